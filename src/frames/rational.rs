//! Frames given exactly as piecewise rational functions: on each segment
//! f₂ = N₂(s)/d(s) and f₃ = N₃(s)/d(s) with vector polynomials N₂, N₃ and one positive
//! scalar polynomial d, all in Bernstein form on the local parameter s ∈ [0, 1].
//!
//! Every RMF construction of the papers ends in this form: the PH-cubic frame (29) with
//! W(v) (Mäurer & Jüttler), the Möbius image (18) of a planar frame (Bartoň, Jüttler &
//! Wang), and the RRMF frame (9) (Farouki, Giannelli & Sestini). The common denominator is
//! what makes the sweep `x + c₂ f₂ + c₃ f₃` a rational tensor-product surface. The tangent
//! is f₂ × f₃, exact because the pair is orthonormal in the normal plane.

use super::metrics::angle_about_tangent;
use super::Frame;
use crate::bezier::bernstein::{self, MAX_DEGREE};
use crate::bezier::{check_breaks, locate, RationalBezierCurve};
use crate::error::{invalid, Result};
use crate::math::{angle_between, normal_plane_unit, reciprocal_length};
use glam::DVec3;

/// Largest distance between unit tangents of consecutive segments at their joint, unless the
/// rounding of the curve's control points allows more ([`g1_tolerance`]).
const G1_TOLERANCE: f64 = 1e-9;

/// The G1 tolerance for frames along `curve`: [`G1_TOLERANCE`], or the direction error of
/// its end legs, 64·ε·|P|/|leg| (differences of control points rounded to ε|P|), where that
/// is larger — a spline of legs 0.18 translated by 1e6 has tangents known to 1.2e-9 only
/// (it was refused as "not G1").
pub(crate) fn g1_tolerance(curve: &crate::bezier::PiecewiseCurve) -> f64 {
    let mut worst = G1_TOLERANCE;
    for segment in curve.segments() {
        let poles: Vec<DVec3> = segment.poles().collect();
        let n = poles.len() - 1;
        if n == 0 {
            continue;
        }
        let size = crate::math::largest_coordinate(poles.iter().copied());
        let leg = crate::math::robust_length(poles[1] - poles[0])
            .min(crate::math::robust_length(poles[n] - poles[n - 1]));
        if leg > 0.0 {
            worst = worst.max(64.0 * f64::EPSILON * size / leg);
        }
    }
    worst
}

/// Which frame vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameVector {
    /// The unit tangent t.
    Tangent,
    /// The first normal-plane vector f₂.
    F2,
    /// f₃ = t × f₂.
    F3,
}

/// One segment: `f₂ = f2 / denominator`, `f₃ = f3 / denominator` (Bernstein coefficients).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalFrameSegment {
    f2: Vec<DVec3>,
    f3: Vec<DVec3>,
    denominator: Vec<f64>,
    /// The tangent's numerator over the same denominator, where the frames carry one of
    /// their own degree (N₂ × N₃ is of twice it over d²).
    tangent: Option<Vec<DVec3>>,
}

impl RationalFrameSegment {
    /// Numerators and denominator of one degree; the denominator's coefficients must be
    /// positive (so the frame vectors are rational Bézier curves with positive weights).
    pub fn new(f2: Vec<DVec3>, f3: Vec<DVec3>, denominator: Vec<f64>) -> Result<Self> {
        let n = denominator.len();
        if n == 0 || n > MAX_DEGREE + 1 || f2.len() != n || f3.len() != n {
            return invalid!(
                "frame numerators and denominator must have one degree in 0..={MAX_DEGREE}"
            );
        }
        if f2.iter().chain(&f3).any(|v| !v.is_finite())
            || denominator.iter().any(|d| !(d.is_finite() && *d > 0.0))
        {
            return invalid!("frame coefficients must be finite with a positive denominator");
        }
        Ok(Self {
            f2,
            f3,
            denominator,
            tangent: None,
        })
    }

    /// The segment with the tangent's numerator `t` over its denominator (finite, of its
    /// degree): frames close to orthonormal whose cross product is of twice the degree.
    pub(crate) fn with_tangent(mut self, t: Vec<DVec3>) -> Result<Self> {
        if t.len() != self.denominator.len() || t.iter().any(|v| !v.is_finite()) {
            return invalid!("a frame's tangent numerator must be finite, of the frame's degree");
        }
        self.tangent = Some(t);
        Ok(self)
    }

    /// The tangent's numerator over the denominator, where the segment carries one.
    pub(crate) fn tangent_numerator(&self) -> Option<&[DVec3]> {
        self.tangent.as_deref()
    }

    pub fn degree(&self) -> usize {
        self.denominator.len() - 1
    }

    pub fn f2_numerator(&self) -> &[DVec3] {
        &self.f2
    }

    pub fn f3_numerator(&self) -> &[DVec3] {
        &self.f3
    }

    pub fn denominator(&self) -> &[f64] {
        &self.denominator
    }

    /// The frame at the local parameter `s`.
    pub fn frame(&self, s: f64) -> Frame {
        frame_at(&self.f2, &self.f3, &self.denominator, s)
    }

    /// f₂ and its derivative with respect to the local parameter, by the quotient rule.
    pub fn f2_with_derivative(&self, s: f64) -> (DVec3, DVec3) {
        let n = bernstein::evaluate_jet(&self.f2, s);
        let d = bernstein::evaluate_jet(&self.denominator, s);
        let f2 = n.value / d.value;
        (f2, (n.d1 - d.d1 * f2) / d.value)
    }

    /// The same segment turned by the constant `angle` about the tangent. A constant
    /// rotation of a rotation-minimizing frame is again rotation-minimizing, which is how
    /// spline segments are made to agree at their joints.
    pub fn rotated(&self, angle: f64) -> Self {
        let mut turned = self.clone();
        turned.rotate(angle);
        turned
    }

    /// Turns the frame about the tangent by a constant `angle`, in place.
    pub fn rotate(&mut self, angle: f64) {
        let (s, c) = angle.sin_cos();
        for (a, b) in self.f2.iter_mut().zip(self.f3.iter_mut()) {
            (*a, *b) = (c * *a + s * *b, c * *b - s * *a);
        }
    }

    /// Sets the frame at the start (`at_start`) or the end of the segment to `frame`, keeping
    /// the denominator there: the end coefficients become `frame.f2·d`, `frame.f3·d`.
    pub fn pin_end(&mut self, at_start: bool, frame: &Frame) {
        let i = if at_start { 0 } else { self.degree() };
        let d = self.denominator[i];
        self.f2[i] = frame.f2 * d;
        self.f3[i] = frame.f3 * d;
    }

    /// One frame vector as a rational Bézier curve of vectors (its "points" lie on the unit
    /// sphere). The tangent f₂ × f₃ has numerator N₂ × N₃ over d².
    pub fn vector_curve(&self, which: FrameVector) -> Result<RationalBezierCurve> {
        match which {
            FrameVector::F2 => {
                RationalBezierCurve::from_numerator_denominator(&self.f2, &self.denominator)
            }
            FrameVector::F3 => {
                RationalBezierCurve::from_numerator_denominator(&self.f3, &self.denominator)
            }
            FrameVector::Tangent => {
                let numerator =
                    bernstein::product(&self.f2, &self.f3, |a: DVec3, b: DVec3| a.cross(b));
                let denominator =
                    bernstein::product(&self.denominator, &self.denominator, |a: f64, b: f64| {
                        a * b
                    });
                RationalBezierCurve::from_numerator_denominator(&numerator, &denominator)
            }
        }
    }
}

/// The frame N₂/d, N₃/d at `s` from Bernstein coefficients of one degree (the tangent is
/// f₂ × f₃, the pair being orthonormal).
pub(crate) fn frame_at(f2: &[DVec3], f3: &[DVec3], denominator: &[f64], s: f64) -> Frame {
    // One basis evaluation for all seven coefficient sets (3 + 3 + 1), instead of a de
    // Casteljau run per set: frames are evaluated in bulk (meshes, sweeps, benchmarks).
    let n = denominator.len() - 1;
    // At the ends (joints, chaining) the value is the end coefficient, with no rounding.
    let end = if s == 0.0 {
        Some(0)
    } else if s == 1.0 {
        Some(n)
    } else {
        None
    };
    if let Some(i) = end {
        let d = denominator[i];
        let (f2, f3) = (f2[i] / d, f3[i] / d);
        return Frame {
            tangent: f2.cross(f3),
            f2,
            f3,
        };
    }
    let mut basis = [0.0; MAX_DEGREE + 1];
    bernstein::basis(n, s, &mut basis);
    let combine = |c: &[DVec3]| {
        c.iter()
            .zip(&basis)
            .fold(DVec3::ZERO, |a, (&v, &b)| a + v * b)
    };
    let d: f64 = denominator.iter().zip(&basis).map(|(c, b)| c * b).sum();
    let f2 = combine(f2) / d;
    let f3 = combine(f3) / d;

    Frame {
        tangent: f2.cross(f3),
        f2,
        f3,
    }
}

/// The constant turn about the tangent that makes piece `k` of a frame field, starting with
/// the frame `start`, continue the previous piece, which ends with `previous_end` (they must
/// share the tangent: the curve must be G1); for the first piece (`None`), the turn that
/// starts it at `initial_normal` projected onto the normal plane. A constant turn keeps a
/// rotation-minimizing frame rotation-minimizing.
pub(crate) fn joining_turn(
    start: &Frame,
    previous_end: Option<&Frame>,
    initial_normal: DVec3,
    k: usize,
    tolerance: f64,
) -> Result<f64> {
    let target = match previous_end {
        None => normal_plane_unit(initial_normal, start.tangent, "initial_normal")?,
        Some(end) => {
            if (end.tangent - start.tangent).length() > tolerance.max(G1_TOLERANCE) {
                return invalid!(
                    "segments {} and {k} do not share their tangent: the spline is not G1",
                    k - 1
                );
            }
            end.f2
        }
    };
    Ok(angle_about_tangent(
        start,
        &Frame::from_tangent_normal(start.tangent, target),
    ))
}

/// What rational frames are known to be, against the rotation-minimizing frame (RMF) of
/// their curve: set by the construction that made them, so that analyses which hold for an
/// RMF only (the profile-surface analysis of Mäurer & Jüttler §2.3) refuse other frames, and
/// accuracy measures take off a twist only where one was built in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Turning {
    /// A rotation-minimizing frame: exact (Möbius images, RRMF quintics) or the rational
    /// approximation of one (PH cubic splines, §3.4 of Mäurer & Jüttler).
    RotationMinimizing,
    /// The RMF turned in addition by `total` radians from start to end, linearly in arc
    /// length (a twist, or the closure of a closed spine).
    Twisted { total: f64 },
    /// Nothing is known: Frenet frames, frames of unknown origin.
    Unknown,
}

/// Rational frames along a piecewise curve; segment k lives on `[breaks[k], breaks[k+1]]`.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalFrames {
    segments: Vec<RationalFrameSegment>,
    breaks: Vec<f64>,
    turning: Turning,
}

impl RationalFrames {
    /// Frames of unknown turning (`Turning::Unknown`; see [`RationalFrames::with_turning`]).
    pub fn new(segments: Vec<RationalFrameSegment>, breaks: Vec<f64>) -> Result<Self> {
        check_breaks(&breaks, segments.len(), "frame breakpoints")?;
        Ok(Self {
            segments,
            breaks,
            turning: Turning::Unknown,
        })
    }

    /// The same frames, declared to turn as `turning` says (the constructions that know it).
    pub fn with_turning(mut self, turning: Turning) -> Self {
        self.turning = turning;
        self
    }

    /// How the frames turn against the RMF, as far as known.
    pub fn turning(&self) -> Turning {
        self.turning
    }

    /// Joins per-segment rational frames of a G1 spline into one continuous frame field:
    /// segment 0 is turned about the tangent so that f₂ starts at `initial_normal` projected
    /// onto the normal plane, every further segment so that its f₂ starts where the
    /// previous one ended. A constant rotation of a rotation-minimizing frame is again
    /// rotation-minimizing, so the result is an RMF of the spline when the pieces are RMFs of
    /// their segments (Bartoň, Jüttler & Wang §3.1; Farouki, Giannelli & Sestini §5).
    pub fn chained(
        segments: Vec<RationalFrameSegment>,
        breaks: Vec<f64>,
        initial_normal: DVec3,
    ) -> Result<Self> {
        Self::chained_within(segments, breaks, initial_normal, 0.0)
    }

    /// [`RationalFrames::chained`] with the G1 tolerance of the curve the frames follow
    /// (see `g1_tolerance`).
    pub fn chained_within(
        segments: Vec<RationalFrameSegment>,
        breaks: Vec<f64>,
        initial_normal: DVec3,
        tolerance: f64,
    ) -> Result<Self> {
        check_breaks(&breaks, segments.len(), "frame breakpoints")?;
        let mut joined: Vec<RationalFrameSegment> = Vec::with_capacity(segments.len());
        for (k, mut segment) in segments.into_iter().enumerate() {
            let previous_end = joined.last().map(|p| p.frame(1.0));
            let angle = joining_turn(
                &segment.frame(0.0),
                previous_end.as_ref(),
                initial_normal,
                k,
                tolerance,
            )?;
            segment.rotate(angle);
            joined.push(segment);
        }
        Ok(Self {
            segments: joined,
            breaks,
            turning: Turning::Unknown,
        })
    }

    /// Joins per-piece RMFs of a G1 curve into one frame field whose frame at every
    /// breakpoint is computed once and shared by the two pieces meeting there, so that they
    /// agree exactly (no tolerance: nothing is compared). `tangents[k]` is the curve's unit
    /// tangent at `breaks[k]` where it is known exactly (the Hermite data at the joints of a
    /// spline), `None` inside a segment, where the tangent of the piece ending there is used.
    /// At each breakpoint the shared frame has that tangent and f₂ = the previous piece's
    /// end f₂ put into its normal plane (`initial_normal` at the start); the next piece is
    /// turned by a constant about its tangent to start with it, and both pieces' end
    /// coefficients are set to it. Also returns the largest angle by which a piece's own end
    /// frame was moved (its tangent against the shared one, or its f₂ about it): the
    /// rounding of the construction, a figure for the tests.
    pub fn joined(
        segments: Vec<RationalFrameSegment>,
        breaks: Vec<f64>,
        tangents: &[Option<DVec3>],
        initial_normal: DVec3,
    ) -> Result<(Self, f64)> {
        check_breaks(&breaks, segments.len(), "frame breakpoints")?;
        if tangents.len() != breaks.len() {
            return invalid!(
                "{} joint tangents for {} frame breakpoints",
                tangents.len(),
                breaks.len()
            );
        }
        let shared = |tangent: DVec3, f2: DVec3, name: &str| -> Result<Frame> {
            Ok(Frame::from_tangent_normal(
                tangent,
                normal_plane_unit(f2, tangent, name)?,
            ))
        };
        let mut correction = 0.0f64;
        let mut joined: Vec<RationalFrameSegment> = Vec::with_capacity(segments.len());
        let mut joint: Option<Frame> = None;
        for (k, mut segment) in segments.into_iter().enumerate() {
            let start = segment.frame(0.0);
            let frame = match joint {
                None => {
                    let tangent = tangents[0].unwrap_or(start.tangent);
                    shared(tangent, initial_normal, "initial_normal")?
                }
                Some(frame) => frame,
            };
            correction = correction.max(angle_between(start.tangent, frame.tangent));
            let turn =
                angle_about_tangent(&start, &Frame::from_tangent_normal(start.tangent, frame.f2));
            segment.rotate(turn);
            segment.pin_end(true, &frame);
            let end = segment.frame(1.0);
            let tangent = tangents[k + 1].unwrap_or(end.tangent);
            let next = shared(tangent, end.f2, "the frame at a joint")?;
            correction = correction
                .max(angle_between(end.tangent, next.tangent))
                .max(angle_between(end.f2, next.f2));
            segment.pin_end(false, &next);
            joined.push(segment);
            joint = Some(next);
        }
        Ok((
            Self {
                segments: joined,
                breaks,
                turning: Turning::Unknown,
            },
            correction,
        ))
    }

    /// The rational frame segments, in parameter order.
    pub fn segments(&self) -> &[RationalFrameSegment] {
        &self.segments
    }

    /// The breakpoints, one more than the segments.
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// Segment, local parameter and 1 / segment length at the global parameter `t`.
    fn locate(&self, t: f64) -> (usize, f64, f64) {
        let (k, s) = locate(&self.breaks, t);
        (k, s, reciprocal_length(self.breaks[k], self.breaks[k + 1]))
    }

    /// The frame at the global parameter `t` (clamped to the domain).
    pub fn frame(&self, t: f64) -> Frame {
        let (k, s, _) = self.locate(t);
        self.segments[k].frame(s)
    }

    /// f₂ and df₂/dt (global parameter).
    pub fn f2_with_derivative(&self, t: f64) -> (DVec3, DVec3) {
        let (k, s, scale) = self.locate(t);
        let (f2, d) = self.segments[k].f2_with_derivative(s);
        (f2, d * scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The frame of the circle (cos φ, sin φ, 0) with f₂ = −radius direction and f₃ = Z,
    /// on a quarter arc: rational quadratic, weights (1, 1/√2, 1).
    fn circle_segment() -> RationalFrameSegment {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let w = vec![1.0, s, 1.0];
        let f2 = vec![-DVec3::X, -DVec3::new(1.0, 1.0, 0.0) * s, -DVec3::Y];
        let f3 = w.iter().map(|&wi| DVec3::Z * wi).collect();
        RationalFrameSegment::new(f2, f3, w).unwrap()
    }

    #[test]
    fn frame_is_orthonormal_and_rotation_keeps_the_tangent() {
        let seg = circle_segment();
        for i in 0..=10 {
            let f = seg.frame(i as f64 / 10.0);
            assert!((f.f2.length() - 1.0).abs() < 1e-15 && f.f2.dot(f.f3).abs() < 1e-15);
            let g = seg.rotated(0.4).frame(i as f64 / 10.0);
            assert!((g.tangent - f.tangent).length() < 1e-15);
            assert!((g.f2 - f.rotated(0.4).f2).length() < 1e-15);
        }
        let tangent = seg.vector_curve(FrameVector::Tangent).unwrap();
        assert!((tangent.eval(0.3) - seg.frame(0.3).tangent).length() < 1e-15);
    }

    #[test]
    fn derivative_matches_finite_differences() {
        let frames = RationalFrames::new(vec![circle_segment()], vec![0.0, 2.0]).unwrap();
        let h = 1e-6;
        let (_, d) = frames.f2_with_derivative(0.8);
        let fd = (frames.frame(0.8 + h).f2 - frames.frame(0.8 - h).f2) / (2.0 * h);
        assert!((d - fd).length() < 1e-8);
    }

    #[test]
    fn chaining_makes_frames_continuous_and_starts_at_the_initial_normal() {
        // Two quarter arcs of one circle, the second with a frame turned by 1 rad.
        let first = circle_segment();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let w = vec![1.0, s, 1.0];
        let f2 = vec![-DVec3::Y, -DVec3::new(-1.0, 1.0, 0.0) * s, DVec3::X];
        let f3 = w.iter().map(|&wi| DVec3::Z * wi).collect();
        let second = RationalFrameSegment::new(f2, f3, w).unwrap().rotated(1.0);
        let seed = DVec3::new(0.3, 0.0, 1.0);
        let chained =
            RationalFrames::chained(vec![first.clone(), second], vec![0.0, 1.0, 2.0], seed)
                .unwrap();
        let start = chained.frame(0.0);
        // The start tangent is +y, so the seed already lies in the normal plane.
        assert!((start.f2 - seed.normalize()).length() < 1e-15);
        let (before, after) = (
            chained.segments()[0].frame(1.0),
            chained.segments()[1].frame(0.0),
        );
        assert!((before.f2 - after.f2).length() < 1e-14);
        assert!((before.f3 - after.f3).length() < 1e-14);
        // A spline that is not G1 is refused.
        let kinked = RationalFrames::chained(vec![first.clone(), first], vec![0.0, 1.0, 2.0], seed);
        assert!(kinked.unwrap_err().message().contains("G1"));
    }

    #[test]
    fn rejects_non_positive_denominators() {
        let e = RationalFrameSegment::new(vec![DVec3::X; 2], vec![DVec3::Y; 2], vec![1.0, -1.0]);
        assert!(e.is_err());
    }
}
