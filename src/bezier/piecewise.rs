//! Piecewise rational Bézier curves and surfaces: segments (patches) on consecutive
//! parameter intervals. This is the canonical form of every result of the library; the
//! NURBS form (`nurbs`) is derived from it.

use super::curve::{CurveJet, RationalBezierCurve};
use super::surface::{RationalBezierPatch, SurfaceJet};
use crate::error::Num;
use crate::error::{invalid, Result};
use crate::math::{fraction, reciprocal_length, robust_length, GaussLegendre};
use glam::DVec3;

/// Relative tolerance for parameters that fall just outside a domain by round-off: a
/// parameter up to 1e-12·max(|t_min|, |t_max|, 1) outside is accepted and clamped to the end
/// (the C header documents it with every domain).
pub(super) const DOMAIN_SLACK: f64 = 1e-12;

/// Checks that `breaks` holds `pieces + 1` finite, strictly increasing breakpoints.
pub(crate) fn check_breaks(breaks: &[f64], pieces: usize, name: &str) -> Result<()> {
    if pieces == 0 {
        return invalid!("a piecewise object needs at least one piece");
    }
    if breaks.len() != pieces + 1 {
        return invalid!(
            "{name}: {} pieces need {} breakpoints, got {}",
            pieces,
            pieces + 1,
            breaks.len()
        );
    }
    if breaks.iter().any(|b| !b.is_finite()) || breaks.windows(2).any(|w| w[0] >= w[1]) {
        return invalid!("{name} must be finite and strictly increasing");
    }
    Ok(())
}

/// Index of the interval of `breaks` containing `t` and the local parameter in [0, 1].
/// Parameters outside the domain are clamped; interior breakpoints belong to the interval
/// on their right.
pub(crate) fn locate(breaks: &[f64], t: f64) -> (usize, f64) {
    let last = breaks.len() - 2;
    let k = breaks[1..=last].partition_point(|&b| b <= t);
    (k, fraction(t, breaks[k], breaks[k + 1]).clamp(0.0, 1.0))
}

/// `t` if it lies in `[lo, hi]` (allowing round-off slack), else an error naming `name`.
pub fn check_in_domain(t: f64, (lo, hi): (f64, f64), name: &str) -> Result<f64> {
    let slack = DOMAIN_SLACK * lo.abs().max(hi.abs()).max(1.0);
    if !t.is_finite() || t < lo - slack || t > hi + slack {
        return invalid!(
            "{name} = {} is outside the domain [{}, {}]",
            Num(t),
            Num(lo),
            Num(hi)
        );
    }
    Ok(t.clamp(lo, hi))
}

/// A curve made of rational Bézier segments; segment k lives on `[breaks[k], breaks[k+1]]`.
#[derive(Clone, Debug, PartialEq)]
pub struct PiecewiseCurve {
    segments: Vec<RationalBezierCurve>,
    breaks: Vec<f64>,
}

impl PiecewiseCurve {
    /// The curve of `segments`, segment k on `[breaks[k], breaks[k+1]]`; the breaks must increase strictly, one more than the segments.
    pub fn new(segments: Vec<RationalBezierCurve>, breaks: Vec<f64>) -> Result<Self> {
        check_breaks(&breaks, segments.len(), "breakpoints")?;
        Ok(Self { segments, breaks })
    }

    /// Segments on the integer breakpoints 0, 1, ..., n (the natural parameter of a spline
    /// built segment by segment).
    pub fn with_unit_intervals(segments: Vec<RationalBezierCurve>) -> Result<Self> {
        let breaks = (0..=segments.len()).map(|k| k as f64).collect();
        Self::new(segments, breaks)
    }

    /// The same curve on a finer segmentation: `breaks` must contain every breakpoint of
    /// this curve (and nothing outside its domain); segments are restricted accordingly.
    pub fn refined(&self, breaks: &[f64]) -> Result<Self> {
        check_breaks(
            breaks,
            breaks.len().saturating_sub(1).max(1),
            "refined breakpoints",
        )?;
        if breaks[0] != self.breaks[0]
            || breaks[breaks.len() - 1] != self.breaks[self.breaks.len() - 1]
        {
            return invalid!("refined breakpoints must span the curve's domain exactly");
        }
        if self.breaks.iter().any(|b| !breaks.contains(b)) {
            return invalid!("refined breakpoints must contain the curve's breakpoints");
        }
        let segments = breaks
            .windows(2)
            .map(|w| {
                let (k, _) = self.locate(0.5 * (w[0] + w[1]));
                let (a, b) = (self.breaks[k], self.breaks[k + 1]);
                let (s0, s1) = (fraction(w[0], a, b), fraction(w[1], a, b));
                if s0 == 0.0 && s1 == 1.0 {
                    self.segments[k].clone()
                } else {
                    self.segments[k].restricted(s0, s1)
                }
            })
            .collect();
        Ok(Self {
            segments,
            breaks: breaks.to_vec(),
        })
    }

    /// The rational Bézier segments, in parameter order.
    pub fn segments(&self) -> &[RationalBezierCurve] {
        &self.segments
    }

    /// The breakpoints, one more than the segments.
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// The same curve traversed backwards, on the same domain: t ↦ lo + hi − t.
    pub fn reversed(&self) -> Self {
        let (lo, hi) = self.domain();
        let segments = self.segments.iter().rev().map(|s| s.reversed()).collect();
        let mut breaks: Vec<f64> = self.breaks.iter().rev().map(|&t| lo + hi - t).collect();
        // The ends exactly, whatever lo + hi − t rounds to.
        breaks[0] = lo;
        *breaks.last_mut().expect("two breaks or more") = hi;
        Self { segments, breaks }
    }

    /// The parameter domain `(first break, last break)`.
    pub fn domain(&self) -> (f64, f64) {
        (self.breaks[0], self.breaks[self.breaks.len() - 1])
    }

    /// Segment index and local parameter of a global parameter (clamped to the domain).
    pub fn locate(&self, t: f64) -> (usize, f64) {
        locate(&self.breaks, t)
    }

    /// The point at the global parameter `t` (clamped to the domain).
    pub fn eval(&self, t: f64) -> DVec3 {
        let (k, s) = self.locate(t);
        self.segments[k].eval(s)
    }

    /// The arc length, by 24-point Gauss–Legendre quadrature on every segment (exact to
    /// round-off for the smooth speeds of rational segments of moderate degree).
    pub fn arc_length(&self) -> f64 {
        let rule = GaussLegendre::new(24);
        self.breaks
            .windows(2)
            .map(|w| rule.integrate(w[0], w[1], |t| robust_length(self.eval_jet(t).d1)))
            .sum()
    }

    /// The same curve scaled by `scale` about the origin, then moved by `offset` (segment by
    /// segment, [`RationalBezierCurve::similar`]).
    pub fn similar(&self, scale: f64, offset: DVec3) -> Self {
        Self {
            segments: self
                .segments
                .iter()
                .map(|s| s.similar(scale, offset))
                .collect(),
            breaks: self.breaks.clone(),
        }
    }

    /// Point and first derivative with respect to the global parameter.
    pub fn eval_d1(&self, t: f64) -> (DVec3, DVec3) {
        let (k, s) = self.locate(t);
        let (point, d1) = self.segments[k].eval_d1(s);
        (point, d1 * (1.0 / (self.breaks[k + 1] - self.breaks[k])))
    }

    /// Point and derivatives with respect to the global parameter.
    pub fn eval_jet(&self, t: f64) -> CurveJet {
        let (k, s) = self.locate(t);
        let scale = reciprocal_length(self.breaks[k], self.breaks[k + 1]);
        let jet = self.segments[k].eval_jet(s);
        CurveJet {
            point: jet.point,
            d1: jet.d1 * scale,
            d2: jet.d2 * (scale * scale),
        }
    }

    /// Point and first three derivatives with respect to the global parameter.
    pub fn eval_jet3(&self, t: f64) -> [DVec3; 4] {
        let (k, s) = self.locate(t);
        let scale = reciprocal_length(self.breaks[k], self.breaks[k + 1]);
        let [point, d1, d2, d3] = self.segments[k].eval_jet3(s);
        [
            point,
            d1 * scale,
            d2 * (scale * scale),
            d3 * (scale * scale * scale),
        ]
    }
}

/// A surface made of a grid of rational Bézier patches; patch (a, b) lives on
/// `[u_breaks[a], u_breaks[a+1]] × [v_breaks[b], v_breaks[b+1]]` and is stored at index
/// `a * (number of v intervals) + b`.
#[derive(Clone, Debug, PartialEq)]
pub struct PiecewiseSurface {
    patches: Vec<RationalBezierPatch>,
    u_breaks: Vec<f64>,
    v_breaks: Vec<f64>,
}

impl PiecewiseSurface {
    /// The surface of a grid of `patches` (index `a * (v_breaks.len() - 1) + b`); the breaks must increase strictly.
    pub fn new(
        patches: Vec<RationalBezierPatch>,
        u_breaks: Vec<f64>,
        v_breaks: Vec<f64>,
    ) -> Result<Self> {
        if u_breaks.len() < 2 || v_breaks.len() < 2 {
            return invalid!("a surface needs at least two breakpoints in u and in v");
        }
        let (ku, kv) = (u_breaks.len() - 1, v_breaks.len() - 1);
        if patches.len() != ku * kv {
            return invalid!(
                "a {ku} × {kv} grid of patches needs {} patches, got {}",
                ku * kv,
                patches.len()
            );
        }
        check_breaks(&u_breaks, ku, "u breakpoints")?;
        check_breaks(&v_breaks, kv, "v breakpoints")?;
        Ok(Self {
            patches,
            u_breaks,
            v_breaks,
        })
    }

    /// The patches, mutable (their grid and breaks stay).
    pub(crate) fn patches_mut(&mut self) -> &mut [RationalBezierPatch] {
        &mut self.patches
    }

    /// The patches, index `a * (number of v intervals) + b`.
    pub fn patches(&self) -> &[RationalBezierPatch] {
        &self.patches
    }

    /// Patch (a, b): a-th interval in u, b-th in v.
    pub fn patch(&self, a: usize, b: usize) -> &RationalBezierPatch {
        &self.patches[a * (self.v_breaks.len() - 1) + b]
    }

    /// The breakpoints in u.
    pub fn u_breaks(&self) -> &[f64] {
        &self.u_breaks
    }

    /// The breakpoints in v.
    pub fn v_breaks(&self) -> &[f64] {
        &self.v_breaks
    }

    /// The parameter domain in u.
    pub fn domain_u(&self) -> (f64, f64) {
        (self.u_breaks[0], self.u_breaks[self.u_breaks.len() - 1])
    }

    /// The parameter domain in v.
    pub fn domain_v(&self) -> (f64, f64) {
        (self.v_breaks[0], self.v_breaks[self.v_breaks.len() - 1])
    }

    /// The point at global parameters (u, v) (clamped to the domain).
    pub fn eval(&self, u: f64, v: f64) -> DVec3 {
        let (a, s) = locate(&self.u_breaks, u);
        let (b, t) = locate(&self.v_breaks, v);
        self.patch(a, b).eval(s, t)
    }

    /// Point and first partial derivatives with respect to the global parameters.
    pub fn eval_d1(&self, u: f64, v: f64) -> [DVec3; 3] {
        let (a, s) = locate(&self.u_breaks, u);
        let (b, t) = locate(&self.v_breaks, v);
        let su = reciprocal_length(self.u_breaks[a], self.u_breaks[a + 1]);
        let sv = reciprocal_length(self.v_breaks[b], self.v_breaks[b + 1]);
        let [p, du, dv] = self.patch(a, b).eval_d1(s, t);
        [p, du * su, dv * sv]
    }

    /// Point and partial derivatives up to second order with respect to the global parameters.
    pub fn eval_jet(&self, u: f64, v: f64) -> SurfaceJet {
        let (a, s) = locate(&self.u_breaks, u);
        let (b, t) = locate(&self.v_breaks, v);
        let su = reciprocal_length(self.u_breaks[a], self.u_breaks[a + 1]);
        let sv = reciprocal_length(self.v_breaks[b], self.v_breaks[b + 1]);
        let j = self.patch(a, b).eval_jet(s, t);
        SurfaceJet {
            point: j.point,
            du: j.du * su,
            dv: j.dv * sv,
            duu: j.duu * (su * su),
            duv: j.duv * (su * sv),
            dvv: j.dvv * (sv * sv),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: DVec3, b: DVec3) -> RationalBezierCurve {
        RationalBezierCurve::polynomial(&[a, b]).unwrap()
    }

    #[test]
    fn locates_segments_and_scales_derivatives() {
        let c = PiecewiseCurve::new(
            vec![
                line(DVec3::ZERO, DVec3::X),
                line(DVec3::X, DVec3::new(1.0, 2.0, 0.0)),
            ],
            vec![0.0, 0.5, 2.5],
        )
        .unwrap();
        assert_eq!(c.locate(0.5), (1, 0.0));
        assert_eq!(c.locate(2.5), (1, 1.0));
        assert_eq!(c.locate(-1.0), (0, 0.0));
        assert!((c.eval(1.5) - DVec3::new(1.0, 1.0, 0.0)).length() < 1e-15);
        assert!((c.eval_jet(0.25).d1 - DVec3::new(2.0, 0.0, 0.0)).length() < 1e-15);
        assert!((c.eval_jet(2.0).d1 - DVec3::new(0.0, 1.0, 0.0)).length() < 1e-15);
    }

    #[test]
    fn refinement_keeps_the_curve() {
        let c = PiecewiseCurve::new(
            vec![
                line(DVec3::ZERO, DVec3::X),
                line(DVec3::X, DVec3::new(1.0, 2.0, 0.0)),
            ],
            vec![0.0, 0.5, 2.5],
        )
        .unwrap();
        let r = c.refined(&[0.0, 0.25, 0.5, 1.0, 2.5]).unwrap();
        assert_eq!(r.segments().len(), 4);
        for i in 0..=50 {
            let t = 2.5 * i as f64 / 50.0;
            assert!((r.eval(t) - c.eval(t)).length() < 1e-15);
            assert!((r.eval_jet(t).d1 - c.eval_jet(t).d1).length() < 1e-14);
        }
        assert!(
            c.refined(&[0.0, 1.0, 2.5]).is_err(),
            "must keep the breakpoint 0.5"
        );
        assert!(c.refined(&[0.0, 0.5, 3.0]).is_err(), "must keep the domain");
    }

    #[test]
    fn rejects_bad_breakpoints() {
        let seg = || line(DVec3::ZERO, DVec3::X);
        assert!(PiecewiseCurve::new(vec![seg(), seg()], vec![0.0, 1.0]).is_err());
        assert!(PiecewiseCurve::new(vec![seg()], vec![1.0, 1.0]).is_err());
        assert!(PiecewiseCurve::new(vec![seg()], vec![0.0, f64::NAN]).is_err());
        assert!(PiecewiseCurve::new(vec![], vec![0.0]).is_err());
        assert!(check_in_domain(1.0 + 1e-14, (0.0, 1.0), "t").is_ok());
        assert!(check_in_domain(1.1, (0.0, 1.0), "t").is_err());
        assert!(check_in_domain(f64::NAN, (0.0, 1.0), "t").is_err());
    }
}
