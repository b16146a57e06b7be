//! How closely rational frames along a PH cubic spline follow its exact RMF (the accuracy of
//! the approximation of §3.4): the angle about the tangent between the frames and the
//! closed-form RMF of [`ExactRmf`] started from the same frame, maximal per spline segment.
//!
//! Frames made with a twist (rational_rmf, item 7) follow the RMF turned by φ·s/S. The
//! comparison takes that off for such frames only, with the φ they were built with
//! ([`Turning::Twisted`]): any other frame is compared with the RMF itself, so that a frame
//! drifting uniformly against the RMF shows its drift (the end turn taken off as a twist
//! for every frame hid it).

use super::exact_rmf::ExactRmf;
use super::spline::PhSpline;
use crate::error::{invalid, Result};
use crate::frames::metrics::angle_about_tangent;
use crate::frames::rational::{RationalFrames, Turning};
use crate::math::minimize_bracketed;
use crate::mesh::grid_parameters;
use std::f64::consts::PI;

/// Samples per frame piece; the largest one is then refined by Brent's method.
const SAMPLES_PER_PIECE: usize = 32;

/// Angles between frames and the exact RMF.
#[derive(Clone, Debug, PartialEq)]
pub struct AngleErrors {
    /// Largest angle (radians) on each segment of the spline.
    pub per_segment: Vec<f64>,
    /// The largest of them.
    pub max: f64,
    /// φ: the twist the frames were built with (`Turning::Twisted`, 0 for other frames),
    /// taken off linearly in arc length.
    pub twist: f64,
}

/// The angle errors of `frames` (rational frames along `spline`, e.g. from
/// `ph_rational_rmf`) against the exact RMF of the PH cubic spline.
pub fn angle_errors(spline: &PhSpline, frames: &RationalFrames) -> Result<AngleErrors> {
    Ok(AngleCheck::new(spline, frames)?.errors())
}

/// The comparison of frames with the exact RMF, checked and prepared (what can refuse:
/// frames of another spline, a spline whose exact RMF cannot be continued across a joint)
/// and measured apart ([`AngleCheck::errors`], which cannot fail): a wire sweep prepares
/// it while building and measures it when its report is asked for.
#[derive(Clone, Debug)]
pub(crate) struct AngleCheck {
    exact: ExactRmf,
    frames: RationalFrames,
    segments: usize,
}

impl AngleCheck {
    pub(crate) fn new(spline: &PhSpline, frames: &RationalFrames) -> Result<Self> {
        let (lo, hi) = spline.domain();
        let fb = frames.breaks();
        if fb[0] != lo || fb[fb.len() - 1] != hi || spline.breaks().iter().any(|b| !fb.contains(b))
        {
            return invalid!("the frames do not belong to the spline: their breakpoints differ");
        }
        Ok(Self {
            exact: ExactRmf::new(spline, frames.frame(lo).f2, 0.0)?,
            frames: frames.clone(),
            segments: spline.segments().len(),
        })
    }

    /// The angles, sampled on every frame piece and refined about the largest one of each
    /// spline segment.
    pub(crate) fn errors(&self) -> AngleErrors {
        let (exact, frames) = (&self.exact, &self.frames);
        let fb = frames.breaks();
        let raw = |t: f64| angle_about_tangent(&exact.frame(t), &frames.frame(t));
        let samples = grid_parameters(fb, SAMPLES_PER_PIECE);
        let unwrapped = unwrap(samples.iter().map(|&t| raw(t)));
        let twist = match frames.turning() {
            Turning::Twisted { total } => total,
            Turning::RotationMinimizing | Turning::Unknown => 0.0,
        };
        let total = exact.total_length();
        let error_near = |t: f64, reference: f64| {
            let turned = reference + wrap(raw(t) - reference);
            turned - twist * exact.arc_length_at(t) / total
        };
        let mut worst = vec![(0.0f64, 0usize); self.segments];
        for (i, (&t, &angle)) in samples.iter().zip(&unwrapped).enumerate() {
            let (k, _) = exact.locate(t);
            let e = (angle - twist * exact.arc_length_at(t) / total).abs();
            if e > worst[k].0 {
                worst[k] = (e, i);
            }
        }
        let per_segment: Vec<f64> = worst
            .iter()
            .map(|&(e, i)| {
                let (a, b) = (
                    samples[i.saturating_sub(1)],
                    samples[(i + 1).min(samples.len() - 1)],
                );
                let refined = minimize_bracketed(|t| -error_near(t, unwrapped[i]).abs(), a, b, 0.0);
                e.max(-refined.value)
            })
            .collect();
        AngleErrors {
            max: per_segment.iter().fold(0.0, |m: f64, &e| m.max(e)),
            per_segment,
            twist,
        }
    }
}

/// The angle in (−π, π] differing from `a` by a multiple of 2π.
fn wrap(a: f64) -> f64 {
    a - 2.0 * PI * (a / (2.0 * PI)).round()
}

/// Angles made continuous: each differs from the previous by less than π.
fn unwrap(angles: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    for a in angles {
        let next = match out.last() {
            Some(&previous) => previous + wrap(a - previous),
            None => a,
        };
        out.push(next);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ph_cubic::frenet::ph_frenet_frames;
    use crate::ph_cubic::rational_rmf::{ph_rational_rmf, RmfOptions};
    use crate::ph_cubic::test_curves::helix_spline;
    use glam::DVec3;

    #[test]
    fn reports_the_error_of_the_rational_rmf_per_segment() {
        let spline = helix_spline(6, 0.8);
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Y)).unwrap();
        let errors = angle_errors(&spline, rmf.framed.frames()).unwrap();
        assert_eq!(errors.per_segment.len(), 6);
        assert!(errors.twist.abs() < 1e-12);
        // The helix is uniform: every segment has the same error, found to 1e-3 relative.
        let e0 = errors.per_segment[0];
        assert!(e0 > 1e-9 && e0 < 1e-5, "{e0}");
        assert!(errors
            .per_segment
            .iter()
            .all(|e| (e - e0).abs() < 1e-3 * e0));
        // A dense independent scan finds nothing larger.
        let exact = ExactRmf::new(&spline, rmf.framed.frames().frame(0.0).f2, 0.0).unwrap();
        let scan = (0..=60000)
            .map(|i| 6.0 * i as f64 / 60000.0)
            .map(|t| angle_about_tangent(&exact.frame(t), &rmf.framed.frames().frame(t)).abs())
            .fold(0.0, f64::max);
        assert!(scan <= errors.max * (1.0 + 1e-6), "{scan} > {}", errors.max);
        assert!(scan > errors.max * 0.999);
    }

    #[test]
    fn takes_off_a_twist_but_sees_the_frenet_frame_turn() {
        let spline = helix_spline(6, 0.8);
        let options = RmfOptions {
            twist: 1.0,
            ..RmfOptions::rmf(DVec3::Y)
        };
        let twisted = ph_rational_rmf(&spline, &options).unwrap();
        let errors = angle_errors(&spline, twisted.framed.frames()).unwrap();
        assert!((errors.twist - 1.0).abs() < 1e-12);
        // The twist ω·s(v) is not of the arctan form W follows best: 3e-5 rad on this coarse
        // spline (8 segments per turn of the helix), against 5e-6 without twist.
        assert!(errors.max < 1e-4, "{errors:?}");
        // The Frenet frame of a helix turns against its RMF by −∫τ ds: no twist of its own is
        // taken off, so the whole turn is its error.
        let frenet = angle_errors(&spline, ph_frenet_frames(&spline).unwrap().frames()).unwrap();
        assert_eq!(frenet.twist, 0.0);
        assert!(frenet.max > 1.0, "{frenet:?}");
    }

    #[test]
    fn rejects_frames_of_another_curve() {
        let rmf = ph_rational_rmf(&helix_spline(3, 0.8), &RmfOptions::rmf(DVec3::Y)).unwrap();
        assert!(angle_errors(&helix_spline(4, 0.8), rmf.framed.frames()).is_err());
    }

    /// Issue finding (paper gaps): the end turn was taken off as a twist for every frame, so
    /// a frame drifting uniformly against the RMF reported no error. The same twisted frames
    /// with their twist unknown now report it.
    #[test]
    fn a_uniformly_drifting_frame_is_caught() {
        let spline = helix_spline(6, 0.8);
        let options = RmfOptions {
            twist: 0.5,
            ..RmfOptions::rmf(DVec3::Y)
        };
        let twisted = ph_rational_rmf(&spline, &options)
            .unwrap()
            .framed
            .into_parts()
            .1;
        let known = angle_errors(&spline, &twisted).unwrap();
        assert!(known.max < 1e-4, "{known:?}");
        let drifting = twisted.with_turning(Turning::Unknown);
        let caught = angle_errors(&spline, &drifting).unwrap();
        assert!((caught.max - 0.5).abs() < 1e-3, "{caught:?}");
        assert!(
            caught.per_segment.windows(2).all(|w| w[1] > w[0]),
            "the drift grows along the spline: {:?}",
            caught.per_segment
        );
    }
}
