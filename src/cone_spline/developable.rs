//! The developable surfaces a cone spline approximates (Section "Fundamentals"), each seen
//! as a one-parameter family of rulings with their tangent planes over a region of
//! interest along the rulings:
//!
//! * the tangent surface of a space curve, (1) with l the curve and e its unit tangent
//!   (a NURBS curve or a caller's callback), region: distances [v₀, v₁] from the curve
//!   point, 0 ∉ [v₀, v₁];
//! * a ruled NURBS surface of degree (1, n), rulings along u (e.g. spanned between two
//!   rails); developability (2) is checked by measuring its own Gaussian curvature;
//! * the dual form (4): a B-spline curve of control planes U(t); rulings U ∩ U̇, the region
//!   a box Ω.
//!
//! From the rulings alone, [`Developable::element`] derives G1 Hermite elements with a side
//! vector pointing towards increasing parameters.
//!
//! Inflection generators (where the osculating cone is a plane, Section "Fundamentals"):
//!
//! * tangent surfaces: the zeros of the torsion numerator det(x', x'', x''') of the line of
//!   regression. For a NURBS curve these are the real roots of the polynomial
//!   det(X, X', X'', X''') = w⁴ det(x', x'', x''') of each Bézier segment (homogeneous X,
//!   so also for rational curves), all of them, double roots included (two roots between
//!   which the determinant stays within its rounding are one double root); for a callback
//!   curve the roots of the
//!   sampled determinant of the differenced jet ([`crate::curve::differenced_jet`]) by
//!   [`crate::math::sampled_roots`];
//! * ruled and dual-form surfaces: the zeros of ṅ · p (the normal stops turning), sampled
//!   on the rulings and found by [`crate::math::sampled_roots`].
//!
//! A root within [`END_FRACTION`] of the domain's length of an end is the end ruling itself,
//! which every algorithm uses anyway: it is not reported as an interior inflection
//! generator. Roots nearer the ends than any sample spacing are kept.

use super::element::Element;
use super::region::Region;
use crate::bezier::bernstein;
use crate::bezier::{NurbsCurve, PiecewiseCurve, PiecewiseSurface};
use crate::curve::{uniform_parameters, ParametricCurve};
use crate::error::no_solution;
use crate::error::{invalid, Error, Result};
use crate::frames::metrics::scaled_gaussian_curvature;
use crate::math::{bounding_diagonal, real_roots_in, sampled_roots};
use glam::{DVec3, DVec4};

/// One ruling of a developable over the region of interest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ruling {
    /// The middle of the region on the ruling.
    pub point: DVec3,
    /// Unit direction, continuous in the parameter.
    pub direction: DVec3,
    /// A normal of the tangent plane (either sign).
    pub normal: DVec3,
    /// The region: signed distances from `point` along the ruling.
    pub range: (f64, f64),
}

/// A developable surface as a family of rulings.
pub trait Developable {
    /// The parameter interval of the rulings.
    fn domain(&self) -> (f64, f64);

    /// The ruling at parameter t.
    fn ruling(&self, t: f64) -> Result<Ruling>;

    /// The G1 element at t: the ruling with its mid-region point and the side vector of the
    /// tangent plane that points to where the rulings of larger parameters lie (seen from
    /// that point: the sign of the ruling's normal velocity).
    fn element(&self, t: f64) -> Result<Element> {
        let r = self.ruling(t)?;
        let q = r.normal.cross(r.direction).normalize();
        let (lo, hi) = self.domain();
        let h = 1e-6 * (hi - lo);
        let (a, b) = ((t - h).max(lo), (t + h).min(hi));
        let nearest = |s: f64| -> Result<DVec3> {
            let n = self.ruling(s)?;
            Ok(n.point + (r.point - n.point).dot(n.direction) * n.direction)
        };
        let motion = (nearest(b)? - nearest(a)?).dot(q);
        if motion.is_nan() || motion == 0.0 {
            return no_solution!(
                "the rulings do not move at t = {t}: the surface is singular there"
            );
        }
        Ok(Element::from_frame(
            r.point,
            r.direction,
            q * motion.signum(),
        ))
    }

    /// The point at signed distance v from the element point along the ruling at t.
    fn point(&self, t: f64, v: f64) -> Result<DVec3> {
        let r = self.ruling(t)?;
        Ok(r.point + v * r.direction)
    }

    /// x, x', x'', x''' of the line of regression at t, for a tangent surface (whose
    /// osculating cones then follow from the Darboux vector (3) without differencing);
    /// `None` for other developables.
    fn regression_jet(&self, _t: f64) -> Option<Result<[DVec3; 4]>> {
        None
    }

    /// The parameters of the inflection generators inside the domain, increasing (see the
    /// module documentation for the method of each kind of surface). The default samples
    /// the turning ṅ · p of the tangent plane.
    fn inflection_generators(&self) -> Result<Vec<f64>> {
        turning_zeros(self)
    }

    /// The parameters inside the domain where the rulings stop turning in their tangent
    /// plane and turn back (ė · p changes sign): the osculating cone is a cylinder there,
    /// and its vertex passes through infinity from one end of the rulings to the other —
    /// a transition between curves whose curvature radii cross. No cone pair with both
    /// vertices off the rulings follows the surface across such a generator (each vertex
    /// lies beyond the other end), so the approximation makes them junctions, as the
    /// inflection generators. The default samples ė · p.
    fn parallel_generators(&self) -> Result<Vec<f64>> {
        ruling_turning_zeros(self)
    }
}

/// Samples of a turning function for inflection generators (plus the searches between
/// them that [`sampled_roots`] makes).
pub(crate) const INFLECTION_SAMPLES: usize = 400;

/// Roots within this fraction of the domain's length of an end are the end ruling (and
/// sampled roots closer than it to each other one double root).
pub(crate) const END_FRACTION: f64 = 1e-9;

/// A root counts as a touching (double) root where |f| is at most this fraction of the
/// largest sampled |f|: above the differencing noise of the sampled functions (1e-7
/// relative for the differenced x''', less for ṅ · p).
const TOUCH_FRACTION: f64 = 1e-6;

/// The interior roots of the sampled function `f` on the domain `(lo, hi)`.
fn interior_sampled_roots(
    f: &dyn Fn(f64) -> Result<f64>,
    (lo, hi): (f64, f64),
    touch_fraction: f64,
) -> Result<Vec<f64>> {
    let ts = uniform_parameters((lo, hi), INFLECTION_SAMPLES);
    let largest = ts
        .iter()
        .map(|&t| f(t).map(f64::abs))
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .fold(0.0, f64::max);
    let tol = 1e-14 * (hi - lo);
    let mut roots = sampled_roots(f, &ts, touch_fraction * largest, tol)?;
    // A double root whose minimum dips below zero by the noise is bracketed twice.
    roots.dedup_by(|x, y| {
        let close = (*x - *y).abs() <= END_FRACTION * (hi - lo);
        if close {
            *y = 0.5 * (*x + *y);
        }
        close
    });
    Ok(interior((lo, hi), roots))
}

/// The roots that are not an end of the domain ([`END_FRACTION`]).
fn interior((lo, hi): (f64, f64), roots: Vec<f64>) -> Vec<f64> {
    let margin = END_FRACTION * (hi - lo);
    roots
        .into_iter()
        .filter(|&t| t - lo > margin && hi - t > margin)
        .collect()
}

/// Zeros of ṅ · p (the normal's turning towards the side vector) inside the domain.
fn turning_zeros<S: Developable + ?Sized>(surface: &S) -> Result<Vec<f64>> {
    let (lo, hi) = surface.domain();
    let h = 1e-5 * (hi - lo);
    let turning = |t: f64| -> Result<f64> {
        let el = surface.element(t)?;
        let (a, b) = ((t - h).max(lo), (t + h).min(hi));
        Ok((surface.element(b)?.normal() - surface.element(a)?.normal()).dot(el.side))
    };
    interior_sampled_roots(&turning, (lo, hi), TOUCH_FRACTION)
}

/// Zeros of ė · p (the ruling's turning towards the side vector) inside the domain.
fn ruling_turning_zeros<S: Developable + ?Sized>(surface: &S) -> Result<Vec<f64>> {
    let (lo, hi) = surface.domain();
    let h = 1e-5 * (hi - lo);
    let turning = |t: f64| -> Result<f64> {
        let el = surface.element(t)?;
        let (a, b) = ((t - h).max(lo), (t + h).min(hi));
        Ok((surface.ruling(b)?.direction - surface.ruling(a)?.direction).dot(el.side))
    };
    // On a cylinder the rulings never turn: ė · p is round-off everywhere, its sign
    // changes mean nothing, and every osculating cone is a cylinder already.
    let still = uniform_parameters((lo, hi), INFLECTION_SAMPLES)
        .iter()
        .map(|&t| turning(t).map(f64::abs))
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .all(|f| f <= STILL_RULINGS);
    if still {
        return Ok(vec![]);
    }
    // Sign changes only: where the turning touches zero and keeps its sign, the
    // vertex goes out to infinity and comes back on the same side.
    interior_sampled_roots(&turning, (lo, hi), -1.0)
}

/// Largest |ė · p| (the change of unit ruling directions over the difference step) of
/// rulings that do not turn: round-off of unit vectors.
const STILL_RULINGS: f64 = 1e-13;

/// Every algorithm steps through a developable in fractions of its domain's length, which
/// must therefore be a finite f64 (a domain of length beyond f64::MAX makes the derivative
/// stencil infinite, and `clamp` panics on it).
fn check_domain_length((lo, hi): (f64, f64)) -> Result<()> {
    if (hi - lo).is_finite() {
        Ok(())
    } else {
        invalid!("the parameter domain [{lo}, {hi}] has a length beyond the largest f64")
    }
}

/// The tangent surface x(t) + v e(t) of a regular space curve over v ∈ [v₀, v₁].
pub struct TangentSurface<'a> {
    curve: &'a dyn ParametricCurve,
    distances: (f64, f64),
}

impl<'a> TangentSurface<'a> {
    /// The region must stay off the curve (its edge of regression): 0 ∉ [v₀, v₁].
    pub fn new(curve: &'a dyn ParametricCurve, v_min: f64, v_max: f64) -> Result<Self> {
        if !(v_min.is_finite() && v_max.is_finite()) || v_min >= v_max {
            return invalid!("v_min = {v_min}, v_max = {v_max} must be finite with v_min < v_max");
        }
        check_domain_length(curve.domain())?;
        if v_min <= 0.0 && v_max >= 0.0 {
            return invalid!(
                "v_min = {v_min} .. v_max = {v_max} contains 0: the region must not reach the curve, \
                 the singular edge of its tangent surface"
            );
        }
        Ok(Self {
            curve,
            distances: (v_min, v_max),
        })
    }
}

impl Developable for TangentSurface<'_> {
    fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        let [x, d1, d2, _] = self.curve.jet(t)?;
        // Directions first: |x'| |x''| under- or overflows for curves of size 1e-200 or
        // 1e200 (d1 and d2 scale with the curve).
        let unit = |v: DVec3| crate::math::robust_normalize(v).unwrap_or(DVec3::ZERO);
        let (e, e2) = (unit(d1), unit(d2));
        let binormal = e.cross(e2);
        if binormal.length() <= 1e-10 || binormal.is_nan() {
            return no_solution!(
                "the curve has zero curvature at t = {t}: its tangent surface has no tangent plane there"
            );
        }
        let (v0, v1) = self.distances;
        let mid = 0.5 * (v0 + v1);
        Ok(Ruling {
            point: x + mid * e,
            direction: e,
            normal: binormal.normalize(),
            range: (v0 - mid, v1 - mid),
        })
    }

    fn regression_jet(&self, t: f64) -> Option<Result<[DVec3; 4]>> {
        Some(self.curve.jet(t))
    }

    /// None: the rulings are the curve's tangents, which turn towards the side vector at
    /// the rate κ|x′| ≥ 0 — never back.
    fn parallel_generators(&self) -> Result<Vec<f64>> {
        Ok(Vec::new())
    }

    fn inflection_generators(&self) -> Result<Vec<f64>> {
        let domain = self.curve.domain();
        let roots = match self.curve.as_piecewise() {
            Some(curve) => torsion_roots(curve),
            None => {
                let torsion = |t: f64| -> Result<f64> {
                    let [_, d1, d2, d3] = self.curve.jet(t)?;
                    // Each derivative divided by |x'|: the same zeros and a value free of
                    // the curve's size (the plain determinant underflows at 1e-200).
                    let s = crate::math::robust_length(d1);
                    Ok((d1 / s).dot((d2 / s).cross(d3 / s)))
                };
                return interior_sampled_roots(&torsion, domain, TOUCH_FRACTION);
            }
        };
        Ok(interior(domain, roots))
    }
}

/// All real roots of the torsion numerator of a piecewise rational curve: per segment the
/// roots in [0, 1] of its polynomial det(X, X', X'', X'''), mapped to the global parameter;
/// a root at a break counts once. A segment whose determinant vanishes identically (a
/// planar segment) has no isolated roots and contributes none.
fn torsion_roots(curve: &PiecewiseCurve) -> Vec<f64> {
    let breaks = curve.breaks();
    let mut roots: Vec<f64> = Vec::new();
    for (k, segment) in curve.segments().iter().enumerate() {
        let numerator = segment.torsion_numerator();
        let power = bernstein::to_power(&numerator);
        let (a, b) = (breaks[k], breaks[k + 1]);
        roots.extend(
            touching_pairs_merged(&numerator, real_roots_in(&power, 0.0, 1.0))
                .into_iter()
                .map(|s| polished(&numerator, s))
                .map(|s| crate::math::lerp(a, b, s)),
        );
    }
    let (lo, hi) = curve.domain();
    roots.dedup_by(|x, y| (*x - *y).abs() <= 1e-14 * (hi - lo));
    roots
}

/// A simple root from the power form (ill-conditioned for the degree 4n − 6) polished on
/// the Bernstein form (stable de Casteljau evaluation), by Illinois steps in a bracket of
/// ±1e-6 around it; a root without a sign change there (a double root) stays.
fn polished(b: &[f64], s: f64) -> f64 {
    let f = |x: f64| bernstein::evaluate(b, x);
    let (lo, hi) = ((s - 1e-6).max(0.0), (s + 1e-6).min(1.0));
    crate::math::illinois_root(f, (lo, f(lo)), (hi, f(hi)), 1e-16).unwrap_or(s)
}

/// |det| relative to its largest Bernstein coefficient below which it is rounding: the
/// products of the determinant round its coefficients, and a double root comes out as two
/// simple roots about 1e-6 apart (or none).
const TORSION_ROUNDING: f64 = 1e-12;

/// Consecutive roots between which the polynomial (Bernstein coefficients `b`) stays within
/// its rounding are one double root (their midpoint): a touching zero split by rounding.
fn touching_pairs_merged(b: &[f64], roots: Vec<f64>) -> Vec<f64> {
    let rounding = TORSION_ROUNDING * b.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let mut out: Vec<f64> = Vec::with_capacity(roots.len());
    let mut merged_last = false;
    for r in roots {
        if let Some(&previous) = out.last() {
            let mid = 0.5 * (previous + r);
            if !merged_last && bernstein::evaluate(b, mid).abs() <= rounding {
                *out.last_mut().expect("checked") = mid;
                merged_last = true;
                continue;
            }
        }
        out.push(r);
        merged_last = false;
    }
    out
}

/// A ruled NURBS surface of degree (1, n) with rulings along u, checked to be developable.
pub struct RuledSurface {
    surface: PiecewiseSurface,
}

/// Largest |K|·size² accepted as developable (size: bounding-box diagonal).
pub const DEVELOPABILITY_TOLERANCE: f64 = 1e-6;

impl RuledSurface {
    /// A degree (1, n) surface with one interval in u (a NURBS with degree_u = 1 and
    /// pole_count_u = 2), whose measured |K|·size² does not exceed
    /// [`DEVELOPABILITY_TOLERANCE`].
    pub fn new(surface: PiecewiseSurface) -> Result<Self> {
        let linear = surface.patches().iter().all(|p| p.degree_u() == 1);
        if !linear || surface.u_breaks().len() != 2 {
            return invalid!(
                "a developable ruled surface needs degree_u = 1 and pole_count_u = 2 (rulings along u)"
            );
        }
        check_domain_length(surface.domain_v())?;
        let k = max_scaled_curvature(&surface);
        if k > DEVELOPABILITY_TOLERANCE || k.is_nan() {
            return invalid!(
                "the surface is not developable: its Gaussian curvature reaches |K|·size² = {k:.3e} \
                 (size = bounding-box diagonal; at most {DEVELOPABILITY_TOLERANCE:.0e} is accepted)"
            );
        }
        Ok(Self { surface })
    }
}

/// max |K|·size² over a grid of 9 × 8 points per patch.
pub fn max_scaled_curvature(surface: &PiecewiseSurface) -> f64 {
    let us = uniform_parameters(surface.domain_u(), 9);
    let vs: Vec<f64> = surface
        .v_breaks()
        .windows(2)
        .flat_map(|w| (0..8).map(move |j| w[0] + (w[1] - w[0]) * (j as f64 + 0.5) / 8.0))
        .collect();
    let jets: Vec<_> = us
        .iter()
        .flat_map(|&u| vs.iter().map(move |&v| surface.eval_jet(u, v)))
        .collect();
    let size = bounding_diagonal(jets.iter().map(|j| j.point));
    jets.iter()
        .map(|jet| scaled_gaussian_curvature(jet, size).abs())
        .fold(0.0, f64::max)
}

impl Developable for RuledSurface {
    fn domain(&self) -> (f64, f64) {
        self.surface.domain_v()
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        let (u0, u1) = self.surface.domain_u();
        let (a, b) = (self.surface.eval(u0, t), self.surface.eval(u1, t));
        let half = 0.5 * (b - a).length();
        if half.is_nan() || half == 0.0 {
            return no_solution!("the ruling at v = {t} has zero length");
        }
        let jet = self.surface.eval_jet(0.5 * (u0 + u1), t);
        Ok(Ruling {
            point: 0.5 * (a + b),
            direction: (b - a).normalize(),
            normal: jet.du.cross(jet.dv),
            range: (-half, half),
        })
    }
}

/// The dual form (4): a B-spline curve of planes U(t) = (u₀(t), u(t)), u₀ + u·x = 0, with
/// the region of interest a box.
pub struct DualDevelopable {
    normals: PiecewiseCurve,
    offsets: PiecewiseCurve,
    region: Region,
}

impl DualDevelopable {
    /// `planes` are (u₁, u₂, u₃, u₀) in glam's (x, y, z, w) order; `knots` clamped.
    pub fn new(degree: usize, planes: &[DVec4], knots: &[f64], region: Region) -> Result<Self> {
        if let Some(i) = planes.iter().position(|u| !u.is_finite()) {
            return invalid!("planes[{i}] has a non-finite coordinate");
        }
        let normals = planes.iter().map(|u| u.truncate()).collect();
        let offsets = planes.iter().map(|u| DVec3::new(u.w, 0.0, 0.0)).collect();
        let curve = |poles| NurbsCurve::new(degree, poles, None, knots.to_vec())?.to_piecewise();
        let normals = curve(normals)?;
        check_domain_length(normals.domain())?;
        Ok(Self {
            normals,
            offsets: curve(offsets)?,
            region,
        })
    }
}

impl Developable for DualDevelopable {
    fn domain(&self) -> (f64, f64) {
        self.normals.domain()
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        let (n, o) = (self.normals.eval_jet(t), self.offsets.eval_jet(t));
        let (u, du, u0, du0) = (n.point, n.d1, o.point.x, o.d1.x);
        let d = u.cross(du);
        if d.length() <= 1e-12 * u.length() * du.length() || d.is_nan() {
            return no_solution!(
                "U(t) and U'(t) are parallel at t = {t}: no ruling (the planes do not turn)"
            );
        }
        // The point of U ∩ U̇ in the span of u and u̇: a u + b u̇ with u·x = −u₀, u̇·x = −u̇₀.
        let (g11, g12, g22) = (u.dot(u), u.dot(du), du.dot(du));
        let det = g11 * g22 - g12 * g12;
        let a = (-u0 * g22 + du0 * g12) / det;
        let b = (-du0 * g11 + u0 * g12) / det;
        let x = a * u + b * du;
        let e = d.normalize();
        let (lo, hi) = self.region.clip_line(x, e).ok_or_else(|| {
            Error::no_solution(format!("the ruling at t = {t} misses the region box"))
        })?;
        let mid = 0.5 * (lo + hi);
        Ok(Ruling {
            point: x + mid * e,
            direction: e,
            normal: u,
            range: (lo - mid, hi - mid),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{torsion_zeros_curve, OnlyTangents};
    use super::*;

    /// Torsion zeros 0.4 (double), 0.7 and 1 − 5e-5 (inside the old 1e-3 margin): all
    /// found, exactly from the NURBS polynomial and from the sampled differenced jet.
    #[test]
    fn inflection_generators_are_the_torsion_zeros() {
        let near_end = 1.0 - 5e-5;
        let exact = [0.4, 0.7, near_end];
        let curve = torsion_zeros_curve(&[0.4, 0.4, 0.7, near_end], 0.0, 1.0);
        let nurbs = TangentSurface::new(&curve, 0.5, 1.0).unwrap();
        let found = nurbs.inflection_generators().unwrap();
        println!("NURBS: {found:?}");
        assert_eq!(found.len(), 3, "{found:?}");
        for (r, x) in found.iter().zip(exact) {
            assert!((r - x).abs() < 1e-7, "{r} vs {x}");
        }
        assert!((found[1] - 0.7).abs() < 1e-8 && (found[2] - near_end).abs() < 1e-8);
        let callback = OnlyTangents(curve.clone());
        let sampled = TangentSurface::new(&callback, 0.5, 1.0).unwrap();
        let found = sampled.inflection_generators().unwrap();
        println!("callback: {found:?}");
        assert_eq!(found.len(), 3, "{found:?}");
        for (r, x) in found.iter().zip(exact) {
            assert!((r - x).abs() < 1e-5, "{r} vs {x}");
        }
        // A zero at an end is the end ruling, not an interior inflection generator; one
        // 1e-6 inside is kept.
        let curve = torsion_zeros_curve(&[0.0, 0.5, 1.0 - 1e-6], 0.0, 1.0);
        let found = TangentSurface::new(&curve, 0.5, 1.0)
            .unwrap()
            .inflection_generators()
            .unwrap();
        assert_eq!(found.len(), 2, "{found:?}");
        assert!((found[0] - 0.5).abs() < 1e-8 && (found[1] - (1.0 - 1e-6)).abs() < 1e-8);
    }

    /// A pair of torsion zeros closer than the sample spacing (1/399) is found by the
    /// search at the local minimum of |det| (a sign scan sees no change).
    #[test]
    fn close_pairs_of_torsion_zeros_are_found_from_samples() {
        let (a, b) = (0.3001, 0.3008);
        let curve = torsion_zeros_curve(&[a, b], 0.0, 1.0);
        let callback = OnlyTangents(curve);
        let found = TangentSurface::new(&callback, 0.5, 1.0)
            .unwrap()
            .inflection_generators()
            .unwrap();
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(
            (found[0] - a).abs() < 1e-7 && (found[1] - b).abs() < 1e-7,
            "{found:?}"
        );
    }

    /// The torsion numerator of a rational segment (Plücker product of homogeneous
    /// derivatives) against w⁴ det(x', x'', x''') from the Cartesian jet (quotient rule).
    #[test]
    fn rational_torsion_numerator_matches_the_jet() {
        let points = vec![
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            DVec4::new(2.0, 0.0, 1.0, 2.0),
            DVec4::new(1.0, 3.0, 0.0, 0.5),
            DVec4::new(0.0, 1.0, 2.0, 1.0),
            DVec4::new(1.5, 1.0, 0.5, 1.5),
        ];
        let segment = crate::bezier::RationalBezierCurve::from_homogeneous(points.clone()).unwrap();
        let numerator = segment.torsion_numerator();
        for s in [0.0, 0.2, 0.5, 0.9, 1.0] {
            let [_, d1, d2, d3] = segment.eval_jet3(s);
            let w = bernstein::evaluate(&points, s).w;
            let cartesian = w.powi(4) * d1.dot(d2.cross(d3));
            let homogeneous = bernstein::evaluate(&numerator, s);
            assert!(
                (cartesian - homogeneous).abs() <= 1e-12 * cartesian.abs().max(1.0),
                "{s}: {cartesian} vs {homogeneous}"
            );
        }
    }

    /// A line on a domain whose length overflows.
    struct WideLine;

    impl ParametricCurve for WideLine {
        fn domain(&self) -> (f64, f64) {
            (-1e308, 1e308)
        }

        fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
            Ok((DVec3::X * t, DVec3::X))
        }
    }

    #[test]
    fn domains_whose_length_overflows_are_refused() {
        let e = TangentSurface::new(&WideLine, 0.5, 1.0).err().unwrap();
        assert!(e.message().contains("beyond the largest f64"), "{e}");
        let planes = [DVec4::X, DVec4::Y, DVec4::Z];
        let knots = [-1e308, -1e308, -1e308, 1e308, 1e308, 1e308];
        let region = Region::new(DVec3::splat(-1.0), DVec3::ONE).unwrap();
        let e = DualDevelopable::new(2, &planes, &knots, region)
            .err()
            .unwrap();
        assert!(e.message().contains("beyond the largest f64"), "{e}");
    }
}
