//! The rational adapted frame of one PH cubic that its RMF is measured from and built on,
//! e₂ = E₂/d, e₃ = E₃/d, with the angle function that turns it into the exact RMF:
//!
//! * a cubic that bends: the Frenet frame (19) (quadratic over quadratic) and Ω of (30);
//! * a (nearly) straight cubic, sin θ ≤ [`NEARLY_STRAIGHT`], where the Frenet frame is
//!   undefined or ill-conditioned (see there): the frame carried along by the rotation
//!   taking t₀ = t(0) to t(v) about t₀ × t(v),
//!   R x = x − (t·x)/(1 + t₀·t) (t₀ + t) for x ⊥ t₀, which for t = x'/σ is quartic over
//!   quartic with denominator σ(σ + t₀·x'). Its twist about the tangent, relative to the RMF, is
//!   of third order in the bend (about θ³, below 1e-11 here): it serves as the RMF itself
//!   (angle function 0), and on a straight line it is the constant RMF.

use super::cubic::PhCubic;
use super::frenet::{frenet_numerators, NEARLY_STRAIGHT};
use super::rmf_angle::RmfAngle;
use super::spline::PhSpline;
use crate::bezier::bernstein::{self, add_product, product, restrict};
use crate::error::{Error, Result, ResultExt};
use crate::frames::rational::{frame_at, RationalFrameSegment, RationalFrames};
use crate::frames::Frame;
use crate::math::orthonormal_to;
use glam::DVec3;

/// Halvings allowed to make a denominator's Bernstein coefficients positive.
const MAX_SUBDIVISION_DEPTH: usize = 40;

/// Frame numerators over one denominator, Bernstein coefficients of one degree on a
/// parameter interval mapped to [0, 1]; unlike [`RationalFrameSegment`], the denominator's
/// coefficients may still be negative (it is a positive function).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct FrameNumerators {
    pub e2: Vec<DVec3>,
    pub e3: Vec<DVec3>,
    pub d: Vec<f64>,
}

impl FrameNumerators {
    pub(crate) fn frame(&self, v: f64) -> Frame {
        frame_at(&self.e2, &self.e3, &self.d, v)
    }

    /// The same frame on [v0, v1], reparameterized to [0, 1].
    pub(crate) fn restricted(&self, v0: f64, v1: f64) -> Self {
        Self {
            e2: restrict(&self.e2, v0, v1),
            e3: restrict(&self.e3, v0, v1),
            d: restrict(&self.d, v0, v1),
        }
    }

    /// The frame turned about the tangent by φ(v) = 2 arctan(γ/β), equation (29): with
    /// cos φ = (β² − γ²)/(β² + γ²), sin φ = 2βγ/(β² + γ²) the numerators become
    /// 2βγ E₃ + (β² − γ²) E₂ and (β² − γ²) E₃ − 2βγ E₂ over (β² + γ²) d.
    pub(crate) fn turned(&self, gamma: &[f64; 3], beta: &[f64; 3]) -> Self {
        let mul = |a: f64, b: f64| a * b;
        let (mut bb, mut gg, mut bg) = ([0.0; 5], [0.0; 5], [0.0; 5]);
        add_product(beta, beta, mul, &mut bb);
        add_product(gamma, gamma, mul, &mut gg);
        add_product(beta, gamma, mul, &mut bg);
        let cos_part: [f64; 5] = std::array::from_fn(|k| bb[k] - gg[k]);
        let sin_part = bg.map(|x| 2.0 * x);
        let norm: [f64; 5] = std::array::from_fn(|k| bb[k] + gg[k]);
        let scale = |a: f64, v: DVec3| v * a;
        let turn = |cos_with: &[DVec3], sin_with: &[DVec3], sign: f64| {
            let mut out = vec![DVec3::ZERO; cos_with.len() + 4];
            add_product(&cos_part, cos_with, scale, &mut out);
            add_product(&sin_part.map(|x| sign * x), sin_with, scale, &mut out);
            out
        };
        Self {
            e2: turn(&self.e2, &self.e3, 1.0),
            e3: turn(&self.e3, &self.e2, -1.0),
            d: product(&norm, &self.d, mul),
        }
    }

    /// Splits [0, 1] until the denominator has positive Bernstein coefficients on every
    /// piece (positive weights for CAD), returning the pieces (v0, v1, segment).
    pub(crate) fn positive_pieces(self) -> Result<Vec<(f64, f64, RationalFrameSegment)>> {
        let breaks = bernstein::positive_subdivision(&[&self.d], MAX_SUBDIVISION_DEPTH)
            .ok_or_else(|| {
                Error::invalid_input(
                    "the frame denominator vanishes on the segment (singular PH cubic)",
                )
            })?;
        if breaks == [0.0, 1.0] {
            return Ok(vec![(
                0.0,
                1.0,
                RationalFrameSegment::new(self.e2, self.e3, self.d)?,
            )]);
        }
        breaks
            .windows(2)
            .map(|w| {
                let piece = self.restricted(w[0], w[1]);
                Ok((
                    w[0],
                    w[1],
                    RationalFrameSegment::new(piece.e2, piece.e3, piece.d)?,
                ))
            })
            .collect()
    }
}

/// Frame pieces collected into piecewise rational frames on a refinement of a spline's
/// breakpoints (segment k on `[breaks[k], breaks[k+1]]`, a piece on a part of it).
pub(crate) struct FramePieces<'a> {
    spline_breaks: &'a [f64],
    segments: Vec<RationalFrameSegment>,
    breaks: Vec<f64>,
}

impl<'a> FramePieces<'a> {
    pub(crate) fn new(spline_breaks: &'a [f64]) -> Self {
        Self {
            spline_breaks,
            segments: Vec::new(),
            breaks: vec![spline_breaks[0]],
        }
    }

    /// Global parameter of the local parameter v of segment k; the segment's own
    /// breakpoints are hit exactly (frames must contain the curve's breakpoints).
    fn global(&self, k: usize, v: f64) -> f64 {
        crate::math::lerp(self.spline_breaks[k], self.spline_breaks[k + 1], v)
    }

    /// Appends pieces (p0, p1, frame) on [p0, p1] ⊂ [0, 1] of a part [v0, v1] of segment k.
    pub(crate) fn push_all(
        &mut self,
        k: usize,
        v0: f64,
        v1: f64,
        pieces: Vec<(f64, f64, RationalFrameSegment)>,
    ) {
        for (_, p1, segment) in pieces {
            let v = if p1 == 1.0 { v1 } else { v0 + p1 * (v1 - v0) };
            self.breaks.push(self.global(k, v));
            self.segments.push(segment);
        }
    }

    /// The frames as they are (each piece as computed).
    pub(crate) fn into_frames(self) -> Result<RationalFrames> {
        RationalFrames::new(self.segments, self.breaks)
    }

    /// The frames joined continuously, starting at `initial_normal` (see
    /// [`RationalFrames::chained_within`]), within the G1 tolerance `tolerance` of the
    /// spline.
    pub(crate) fn into_chained_frames(
        self,
        initial_normal: DVec3,
        tolerance: f64,
    ) -> Result<RationalFrames> {
        RationalFrames::chained_within(self.segments, self.breaks, initial_normal, tolerance)
    }
}

/// The frame pieces of a PH cubic spline from `numerators` of each cubic k, split where
/// their denominator has a negative Bernstein coefficient (positive weights for CAD). Each
/// cubic is taken normalized and exactly PH: the frames do not change under translation
/// and scaling, and on the exactly PH cubic of the same data the quaternion formulas hold
/// to rounding (see `exactly_ph`).
pub(crate) fn spline_frame_pieces<'a>(
    spline: &'a PhSpline,
    numerators: impl Fn(usize, &PhCubic) -> Result<FrameNumerators>,
) -> Result<FramePieces<'a>> {
    let mut pieces = FramePieces::new(spline.breaks());
    for (k, cubic) in spline.cubics().iter().enumerate() {
        let cubic = &cubic
            .normalized()
            .exactly_ph()
            .with_context(|| format!("ph_spline segment {k}"))?;
        pieces.push_all(k, 0.0, 1.0, numerators(k, cubic)?.positive_pieces()?);
    }
    Ok(pieces)
}

/// The frame a segment's RMF is built on, with the angle that turns it into the RMF.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum BaseFrame {
    /// The Frenet frame (19); the RMF is it turned by Ω (30).
    Frenet {
        numerators: FrameNumerators,
        angle: RmfAngle,
    },
    /// A nearly straight cubic: the carried frame, itself the RMF (module notes).
    Carried { numerators: FrameNumerators },
}

impl BaseFrame {
    /// Fails only for polygons that are PH within rounding but have no PH interpolant of
    /// their end data ([`PhCubic::exactly_ph`]).
    pub(crate) fn of(cubic: &PhCubic) -> Result<Self> {
        let cubic = cubic.normalized().exactly_ph()?;
        Ok(if cubic.bend() > NEARLY_STRAIGHT {
            Self::Frenet {
                numerators: frenet_numerators(&cubic),
                angle: RmfAngle::of(&cubic),
            }
        } else {
            Self::Carried {
                numerators: carried_numerators(&cubic),
            }
        })
    }

    pub(crate) fn numerators(&self) -> &FrameNumerators {
        match self {
            Self::Frenet { numerators, .. } | Self::Carried { numerators } => numerators,
        }
    }

    /// Angle of the RMF against this frame, up to a constant: Ω(v) − Ω(0), or 0.
    pub(crate) fn rmf_increment(&self, v: f64) -> f64 {
        match self {
            Self::Frenet { angle, .. } => angle.increment(v),
            Self::Carried { .. } => 0.0,
        }
    }

    /// d/dv of [`Self::rmf_increment`].
    pub(crate) fn rmf_rate(&self, v: f64) -> f64 {
        match self {
            Self::Frenet { angle, .. } => angle.rate(v),
            Self::Carried { .. } => 0.0,
        }
    }

    /// This frame at v, turned by `angle + rmf_increment(v)`: the exact RMF when `angle`
    /// is the right constant.
    pub(crate) fn rmf_frame(&self, v: f64, angle: f64) -> Frame {
        self.numerators()
            .frame(v)
            .rotated(angle + self.rmf_increment(v))
    }
}

/// The carried frame of a nearly straight cubic (module notes), started from some unit
/// vector normal to t₀ (the spline's chaining turns it where it belongs).
fn carried_numerators(cubic: &PhCubic) -> FrameNumerators {
    let hodograph = bernstein::derivative(&cubic.control_points());
    let sigma = cubic.speed();
    let t0 = hodograph[0] / sigma[0];
    // P = σ + t₀·x' (positive: the tangent never turns back), D = σP.
    let p: Vec<f64> = sigma
        .iter()
        .zip(&hodograph)
        .map(|(s, h)| s + t0.dot(*h))
        .collect();
    let d = product(&sigma, &p, |a: f64, b: f64| a * b);
    let axis: Vec<DVec3> = sigma
        .iter()
        .zip(&hodograph)
        .map(|(&s, &h)| t0 * s + h)
        .collect();
    let carried = |x: DVec3| -> Vec<DVec3> {
        let along: Vec<f64> = hodograph.iter().map(|h| h.dot(x)).collect();
        let correction = product(&along, &axis, |a: f64, v: DVec3| v * a);
        d.iter()
            .zip(correction)
            .map(|(&di, c)| x * di - c)
            .collect()
    };
    let e2 = orthonormal_to(t0);
    FrameNumerators {
        e2: carried(e2),
        e3: carried(t0.cross(e2)),
        d,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::frenet::frenet_frame;
    use crate::frames::metrics::orthonormality_error;
    use crate::ph_cubic::test_curves::example_cubic;
    use crate::testing::tschirnhausen;

    #[test]
    fn frenet_base_frame_is_the_frenet_frame() {
        let c = example_cubic();
        let base = BaseFrame::of(&c).unwrap();
        assert!(matches!(base, BaseFrame::Frenet { .. }));
        let n = base.numerators();
        assert_eq!(n.d.len(), 3);
        let bez = c.to_bezier();
        for i in 0..=10 {
            let v = i as f64 / 10.0;
            let jet = bez.eval_jet(v);
            let expected = frenet_frame(jet.d1, jet.d2).unwrap();
            let f = n.frame(v);
            assert!((f.f2 - expected.f2).length() < 1e-14, "v = {v}");
            assert!((f.f3 - expected.f3).length() < 1e-14, "v = {v}");
            assert!(orthonormality_error(&f) < 1e-14);
        }
    }

    #[test]
    fn turning_by_a_biquadratic_keeps_the_frame_orthonormal() {
        let n = frenet_numerators(&example_cubic());
        let (gamma, beta) = ([0.1, -0.3, 0.4], [1.0, 0.8, 1.2]);
        let t = n.turned(&gamma, &beta);
        assert_eq!(t.d.len(), 7, "degree 2(n + 1) = 6 for n = 2");
        for v in [0.0, 0.25, 0.6, 1.0] {
            let w = bernstein::evaluate(&gamma, v) / bernstein::evaluate(&beta, v);
            let expected = n.frame(v).rotated(2.0 * w.atan());
            let f = t.frame(v);
            assert!((f.f2 - expected.f2).length() < 1e-14);
            assert!((f.f3 - expected.f3).length() < 1e-14);
        }
    }

    /// The PH cubic through an arc of length 1 at the start of a helix of radius `r` (and the
    /// same pitch), written without cancellation: curvature ≈ 1/(2r).
    pub(crate) fn gentle_helix_cubic(r: f64) -> PhCubic {
        let p = |t: f64| {
            let s = (t / (2.0 * r)).sin();
            DVec3::new(-2.0 * r * s * s, r * (t / r).sin(), t)
        };
        let d = |t: f64| DVec3::new(-(t / r).sin(), (t / r).cos(), 1.0);
        let data = crate::hermite::HermiteSegment::new(p(0.0), d(0.0), p(1.0), d(1.0)).unwrap();
        crate::ph_cubic::ph_cubic_hermite(&data)
            .unwrap()
            .shape_matching
    }

    #[test]
    fn nearly_straight_cubics_carry_their_frame_exactly_adapted() {
        let cubic = gentle_helix_cubic(1e7);
        assert!(cubic.bend() < NEARLY_STRAIGHT);
        let base = BaseFrame::of(&cubic).unwrap();
        assert!(matches!(base, BaseFrame::Carried { .. }));
        for i in 0..=8 {
            let v = i as f64 / 8.0;
            let f = base.numerators().frame(v);
            let t = cubic.derivative(v).normalize();
            assert!((f.tangent - t).length() < 1e-15, "v = {v}");
            assert!(
                orthonormality_error(&f) < 4e-15,
                "{}",
                orthonormality_error(&f)
            );
        }
    }

    #[test]
    fn positive_pieces_split_a_sharp_turn() {
        // Legs 1, 2, 4 turning by 120°: σ = 3(1, −1, 4).
        let c = tschirnhausen(2.0 * std::f64::consts::FRAC_PI_3, 2.0);
        assert!(c.speed()[1] < 0.0);
        let pieces = frenet_numerators(&c).positive_pieces().unwrap();
        assert!(pieces.len() > 1);
        assert_eq!((pieces[0].0, pieces[pieces.len() - 1].1), (0.0, 1.0));
    }
}
