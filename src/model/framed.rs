//! A curve with rational frames adapted to it: (x(t), f₂(t), f₃(t)) with f₂ × f₃ the unit
//! tangent of x, the frames' breakpoints those of the curve or a refinement of them (a frame
//! may split a segment to keep its weights positive). Every rational frame construction of
//! the papers returns one — the PH-cubic RMF of Mäurer & Jüttler (29), the Möbius images of
//! Bartoň, Jüttler & Wang, the RRMF quintics of Farouki, Giannelli & Sestini — and sweeps
//! (Mäurer & Jüttler (1), (42)) and the profile-surface analyses take one, so the pairing is
//! checked once, where the pair is made.

use crate::bezier::PiecewiseCurve;
use crate::error::{invalid, Result};
use crate::frames::rational::RationalFrames;
use crate::frames::Frame;
use crate::math::robust_normalize;
use glam::DVec3;

/// Relative tolerance for the frames' tangent against the curve's.
const TANGENT_TOLERANCE: f64 = 1e-8;

/// A curve with rational frames adapted to it (see the module notes).
#[derive(Clone, Debug, PartialEq)]
pub struct FramedCurve {
    curve: PiecewiseCurve,
    frames: RationalFrames,
}

impl FramedCurve {
    /// `frames` along `curve`: refused when their breakpoints do not refine the curve's, or
    /// their tangent f₂ × f₃ is not the curve's (checked at both ends and the middle of every
    /// segment) — frames built on another curve.
    pub fn new(curve: PiecewiseCurve, frames: RationalFrames) -> Result<Self> {
        Self::check(&curve, &frames)?;
        Ok(Self { curve, frames })
    }

    /// The check of [`Self::new`], for pairs held apart.
    pub(crate) fn check(curve: &PiecewiseCurve, frames: &RationalFrames) -> Result<()> {
        if curve.breaks() == frames.breaks() {
            return check_tangents(curve, frames);
        }
        let refined = curve.refined(frames.breaks()).map_err(|_| {
            crate::Error::invalid_input(
                "frames do not belong to the curve: their parameter breakpoints differ",
            )
        })?;
        check_tangents(&refined, frames)
    }

    /// A pair a construction made together (the frames built on this very curve), without
    /// the check of [`Self::new`].
    pub(crate) fn of_construction(curve: PiecewiseCurve, frames: RationalFrames) -> Self {
        Self { curve, frames }
    }

    /// The curve.
    pub fn curve(&self) -> &PiecewiseCurve {
        &self.curve
    }

    /// The frames.
    pub fn frames(&self) -> &RationalFrames {
        &self.frames
    }

    /// The curve and the frames.
    pub fn into_parts(self) -> (PiecewiseCurve, RationalFrames) {
        (self.curve, self.frames)
    }

    /// The parameter domain.
    pub fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    /// The point and the frame at `t`.
    pub fn eval(&self, t: f64) -> (DVec3, Frame) {
        (self.curve.eval(t), self.frames.frame(t))
    }

    /// The curve split at the frames' breakpoints, so that segment k of the curve carries
    /// segment k of the frames.
    pub(crate) fn curve_on_frame_segments(&self) -> std::borrow::Cow<'_, PiecewiseCurve> {
        on_frame_segments(&self.curve, &self.frames)
    }
}

impl From<FramedCurve> for crate::frames::FrameField {
    /// The frames as a frame field along the curve (the general type that also holds
    /// sampled and pointwise frames).
    fn from(framed: FramedCurve) -> Self {
        let (curve, frames) = framed.into_parts();
        Self::new(
            std::sync::Arc::new(curve),
            crate::frames::FrameKind::Rational(frames),
        )
        .expect("a framed curve's frames belong to it")
    }
}

/// `curve` split at the breakpoints of `frames` made on it (which refine its own).
pub(crate) fn on_frame_segments<'a>(
    curve: &'a PiecewiseCurve,
    frames: &RationalFrames,
) -> std::borrow::Cow<'a, PiecewiseCurve> {
    if curve.breaks() == frames.breaks() {
        std::borrow::Cow::Borrowed(curve)
    } else {
        std::borrow::Cow::Owned(
            curve
                .refined(frames.breaks())
                .expect("frames refine the curve's breakpoints"),
        )
    }
}

/// The frames' tangent is the curve's on every segment (same breakpoints).
fn check_tangents(curve: &PiecewiseCurve, frames: &RationalFrames) -> Result<()> {
    for (k, (segment, frame)) in curve.segments().iter().zip(frames.segments()).enumerate() {
        for s in [0.0, 0.5, 1.0] {
            let d = robust_normalize(segment.eval_jet(s).d1);
            let tangent = frame.frame(s).tangent;
            if d.is_none_or(|d| (d - tangent).length() > TANGENT_TOLERANCE) {
                return invalid!(
                    "frames do not belong to the curve: their tangent differs on segment {k}"
                );
            }
        }
    }
    Ok(())
}
