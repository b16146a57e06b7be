//! The exact RMF of a PH cubic spline, in closed form: on segment k the base frame (the
//! Frenet frame (19)) turned by αₖ + Ω̃ₖ(v), where Ω̃ₖ(v) = Ωₖ(v) − Ωₖ(0) is (30) and the
//! constants αₖ (the Ω₀ of (6)) are chained so that f₂ is continuous across the G1 joints,
//! starting from the caller's initial normal (5), (6).
//!
//! Optionally the frame turns, on top, by a twist proportional to arc length, ω·s — the
//! smallest uniform twist that makes a closed spine's frame close (item 7 of the design),
//! exact because the arc length of a PH curve is a polynomial. `ω = 0` is the RMF itself.

use super::base_frame::BaseFrame;
use super::cubic::PhCubic;
use super::spline::PhSpline;
use crate::bezier::bernstein;
use crate::bezier::locate;
use crate::error::Result;
use crate::error::ResultExt;
use crate::frames::metrics::angle_about_tangent;
use crate::frames::rational::{g1_tolerance, joining_turn};
use crate::frames::Frame;
use glam::DVec3;

/// One segment: its cubic, base frame and the constant αₖ.
#[derive(Clone, Debug)]
struct Segment {
    cubic: PhCubic,
    base: BaseFrame,
    start_angle: f64,
    /// Arc length of the spline before this segment.
    arc_before: f64,
}

/// The exact (optionally twisted) RMF along a PH cubic spline.
#[derive(Clone, Debug)]
pub struct ExactRmf {
    breaks: Vec<f64>,
    segments: Vec<Segment>,
    twist_rate: f64,
}

impl ExactRmf {
    /// The RMF of `spline` with f₂ at the start = `initial_normal` projected onto the normal
    /// plane, turned in addition by `twist_rate` radians per unit arc length.
    pub fn new(spline: &PhSpline, initial_normal: DVec3, twist_rate: f64) -> Result<Self> {
        let mut segments: Vec<Segment> = Vec::with_capacity(spline.segments().len());
        let mut arc_before = 0.0;
        let tolerance = g1_tolerance(spline);
        for (k, &cubic) in spline.cubics().iter().enumerate() {
            let base = BaseFrame::of(&cubic).with_context(|| format!("ph_spline segment {k}"))?;
            let previous_end = segments.last().map(|p| p.frame(1.0, twist_rate));
            let start_angle = joining_turn(
                &base.numerators().frame(0.0),
                previous_end.as_ref(),
                initial_normal,
                k,
                tolerance,
            )
            .context("ph_spline")?;
            segments.push(Segment {
                cubic,
                base,
                start_angle,
                arc_before,
            });
            arc_before += cubic.arc_length();
        }
        Ok(Self {
            breaks: spline.breaks().to_vec(),
            segments,
            twist_rate,
        })
    }

    /// The RMF of a single PH cubic on [0, 1] (e.g. the cubic of Example 2 of the Möbius
    /// paper, as a reference for convergence tables).
    pub fn for_cubic(cubic: &PhCubic, initial_normal: DVec3) -> Result<Self> {
        Self::new(&PhSpline::from_cubics(vec![*cubic])?, initial_normal, 0.0)
    }

    /// The frame at the spline parameter t.
    pub fn frame(&self, t: f64) -> Frame {
        let (k, v) = locate(&self.breaks, t);
        self.segments[k].frame(v, self.twist_rate)
    }

    /// Segment index and local parameter of t.
    pub fn locate(&self, t: f64) -> (usize, f64) {
        locate(&self.breaks, t)
    }

    /// Arc length from the start of the spline to the parameter t.
    pub fn arc_length_at(&self, t: f64) -> f64 {
        let (k, v) = locate(&self.breaks, t);
        let s = &self.segments[k];
        s.arc_before + s.arc_within(v)
    }

    /// The arc length of the whole spline.
    pub fn total_length(&self) -> f64 {
        let last = self.segments.last().expect("a spline has segments");
        last.arc_before + last.cubic.arc_length()
    }

    /// Rotation about the tangent from the frame at the start to the frame at the end (for a
    /// closed spine with ω = 0: the holonomy of its RMF), in (−π, π].
    pub fn end_rotation(&self) -> f64 {
        let (lo, hi) = (self.breaks[0], self.breaks[self.breaks.len() - 1]);
        angle_about_tangent(&self.frame(lo), &self.frame(hi))
    }

    /// The base frame of segment k and the angle function g(v) the frame is turned by
    /// relative to it, up to its constant: Ω̃(v) + ω·s(v) with derivative g'.
    pub(crate) fn segment_target(&self, k: usize) -> SegmentTarget<'_> {
        SegmentTarget {
            segment: &self.segments[k],
            twist_rate: self.twist_rate,
        }
    }

    /// Number of PH cubic segments.
    pub fn segment_count(&self) -> usize {
        self.segments.len()
    }
}

impl Segment {
    fn arc_within(&self, v: f64) -> f64 {
        bernstein::evaluate(&self.cubic.arc_length_polynomial(), v)
    }

    fn frame(&self, v: f64, twist_rate: f64) -> Frame {
        // Without twist the arc length is not needed (it may overflow for a huge cubic).
        let twist = if twist_rate == 0.0 {
            0.0
        } else {
            twist_rate * self.arc_within(v)
        };
        self.base.rmf_frame(v, self.start_angle + twist)
    }
}

/// What the rational frame of one segment has to follow: its base frame turned by g(v).
pub(crate) struct SegmentTarget<'a> {
    segment: &'a Segment,
    twist_rate: f64,
}

impl SegmentTarget<'_> {
    pub(crate) fn base(&self) -> &BaseFrame {
        &self.segment.base
    }

    /// g(v) − g(0) = Ω̃(v) + ω·s(v).
    pub(crate) fn angle(&self, v: f64) -> f64 {
        self.segment.base.rmf_increment(v) + self.twist_rate * self.segment.arc_within(v)
    }

    /// g'(v) = Ω'(v) + ω·σ(v).
    pub(crate) fn rate(&self, v: f64) -> f64 {
        let rmf_rate = self.segment.base.rmf_rate(v);
        if self.twist_rate == 0.0 {
            // the RMF itself: no speed to evaluate (this runs at every quadrature node)
            return rmf_rate;
        }
        rmf_rate + self.twist_rate * bernstein::evaluate(&self.segment.cubic.speed(), v)
    }

    /// The parameters in (0, 1) where g' = 0 (the angle turns back), in increasing order.
    ///
    /// Ω' = −ρ/q with ρ and q = σ/3 of the cubic scaled to a longest leg of 1, while the
    /// twist term is ω·σ = 3ωℓq for the cubic's longest leg ℓ: g' = 0 where q = √(ρ/(3ωℓ)),
    /// when ρ/ω > 0.
    pub(crate) fn turning_points(&self) -> Vec<f64> {
        let (omega, base) = (self.twist_rate, &self.segment.base);
        let longest = self
            .segment
            .cubic
            .leg_lengths()
            .iter()
            .fold(0.0f64, |m, &l| m.max(l));
        match base {
            BaseFrame::Frenet { angle, .. } if omega != 0.0 => {
                let level = angle.torsion_constant() / (3.0 * omega * longest);
                if level > 0.0 {
                    angle.where_q_equals(level.sqrt())
                } else {
                    Vec::new()
                }
            }
            _ => Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::PiecewiseCurve;
    use crate::ph_cubic::test_curves::helix_spline;
    use crate::testing::gap_to_double_reflection;

    /// A cubic with a chord of 4e153 has finite unit exact RMF frames: it is normalized
    /// without squaring its legs, which overflow beyond 1e154 (NaN frames).
    #[test]
    fn huge_cubics_have_finite_unit_frames() {
        let data = crate::hermite::HermiteSegment::new(
            DVec3::X,
            DVec3::new(0.99999609375, 1.96875e-6, -9.375e-8),
            DVec3::new(-4.0625e153, 0.0, 0.0),
            DVec3::splat(-2.03125),
        )
        .unwrap();
        let cubic = crate::ph_cubic::hermite::ph_cubic_hermite(&data)
            .unwrap()
            .shape_matching;
        let spline = PhSpline::from_cubics(vec![cubic]).unwrap();
        let normal = DVec3::new(1.89e307, 1.27e307, 1.27e307);
        let exact = ExactRmf::new(&spline, normal, 0.0).unwrap();
        for t in [0.0, 0.5, 1.0] {
            let f = exact.frame(t);
            assert!((f.f2.length() - 1.0).abs() < 1e-12, "t = {t}: {f:?}");
            assert!(f.f2.dot(f.tangent).abs() < 1e-12, "t = {t}: {f:?}");
        }
    }

    #[test]
    fn agrees_with_the_double_reflection_rmf() {
        let spline = helix_spline(8, 0.6);
        let normal = DVec3::new(0.3, -0.2, 1.0);
        let exact = ExactRmf::new(&spline, normal, 0.0).unwrap();
        let worst = gap_to_double_reflection(&spline, normal, 4001, |t| exact.frame(t));
        assert!(worst < 1e-9, "{worst}");
    }

    #[test]
    fn rmf_of_one_cubic_agrees_with_double_reflection() {
        let cubic = crate::ph_cubic::test_curves::example_cubic();
        let exact = ExactRmf::for_cubic(&cubic, DVec3::Z).unwrap();
        let spline = PiecewiseCurve::new(vec![cubic.to_bezier()], vec![0.0, 1.0]).unwrap();
        let worst = gap_to_double_reflection(&spline, DVec3::Z, 4001, |t| exact.frame(t));
        assert!(worst < 1e-10, "{worst}");
    }

    #[test]
    fn is_continuous_across_joints_and_starts_at_the_normal() {
        let spline = helix_spline(5, 0.9);
        let exact = ExactRmf::new(&spline, DVec3::Z, 0.0).unwrap();
        let start = exact.frame(0.0);
        assert!(start.f2.cross(DVec3::Z).dot(start.tangent).abs() < 1e-15);
        for k in 1..5 {
            let t = k as f64;
            let before = exact.segments[k - 1].frame(1.0, 0.0);
            let after = exact.frame(t);
            assert!((before.f2 - after.f2).length() < 1e-14, "joint {k}");
        }
    }

    #[test]
    fn twist_adds_a_rotation_linear_in_arc_length() {
        let spline = helix_spline(4, 0.8);
        let plain = ExactRmf::new(&spline, DVec3::Z, 0.0).unwrap();
        let twisted = ExactRmf::new(&spline, DVec3::Z, 0.25).unwrap();
        for t in [0.0, 0.7, 2.0, 3.3, 4.0] {
            let angle = angle_about_tangent(&plain.frame(t), &twisted.frame(t));
            let expected = 0.25 * plain.arc_length_at(t);
            assert!((angle - expected).abs() < 1e-13, "t = {t}");
        }
        let rule = crate::math::GaussLegendre::new(20);
        let length: f64 = (0..4)
            .map(|k| rule.integrate(k as f64, k as f64 + 1.0, |t| spline.eval_jet(t).d1.length()))
            .sum();
        assert!((plain.total_length() - length).abs() < 1e-13);
    }

    #[test]
    fn rejects_a_spline_with_a_kink() {
        let a = crate::bezier::RationalBezierCurve::polynomial(&[
            DVec3::ZERO,
            DVec3::X,
            DVec3::X * 2.0,
            DVec3::X * 3.0,
        ])
        .unwrap();
        let b = crate::bezier::RationalBezierCurve::polynomial(&[
            DVec3::X * 3.0,
            DVec3::new(3.0, 1.0, 0.0),
            DVec3::new(3.0, 2.0, 0.0),
            DVec3::new(3.0, 3.0, 0.0),
        ])
        .unwrap();
        let kinked = PiecewiseCurve::with_unit_intervals(vec![a, b]).unwrap();
        let e = PhSpline::new(kinked)
            .and_then(|s| ExactRmf::new(&s, DVec3::Z, 0.0))
            .unwrap_err();
        assert!(e.message().contains("not G1"), "{e}");
    }
}
