//! The two-sided sampled distance between a PH cubic and the piece of the curve it replaces.
//!
//! The piece [a, b] is cut into [`SUBINTERVALS`] equal parts of the curve's parameter.
//! - Curve to cubic: from each interior sample pⱼ, the distance to the cubic at its closest
//!   point (the "foot" vⱼ), found by Newton's method from the previous feet extrapolated
//!   (`bezier::closest`, exact quintic as the fallback).
//! - Cubic to curve: from the cubic at the middle of each pair of neighbouring feet, the
//!   distance to the curve between the two samples, represented there by its G1 Hermite
//!   cubic (legs of a third of the chord along the sampled unit tangents). By the same h⁴
//!   law as the PH cubic's, that local model is about 16⁴ ≈ 65,000 times closer to the curve
//!   than the PH cubic over the whole piece, so this direction costs no evaluations.
//!
//! Both are distances to points of a curve (the cubic, or the model), never below the
//! distance to it: near the tolerance the test "distance ≤ tolerance" errs on the safe side,
//! up to the model's error.

use super::{Sample, Sampler};
use crate::bezier::closest::LocalCubic;
#[cfg(test)]
use crate::curve::ParametricCurve;
use crate::error::Result;
use crate::math::largest_coordinate;
use crate::ph_cubic::cubic::PhCubic;
use glam::DVec3;

/// Subintervals of a piece: its interior samples and the new end each cost one evaluation.
pub(crate) const SUBINTERVALS: usize = 16;

/// The measured distance between `cubic` and the curve on [a.t, b.t] (module notes).
pub(super) fn measure(sampler: &Sampler, a: &Sample, b: &Sample, cubic: &PhCubic) -> Result<f64> {
    // In coordinates about the cubic's start, in units of its size: no square under- or
    // overflows for curves of any size and place.
    let origin = cubic.control_points()[0];
    let size = largest_coordinate(cubic.control_points().map(|p| p - origin));
    let local = |p: DVec3| (p - origin) / size;
    let x = LocalCubic::new(cubic.control_points().map(local));
    let n = SUBINTERVALS;
    // Samples j = 0 … n (ends included) with their unit tangents (None: singular there).
    let mut points = [DVec3::ZERO; SUBINTERVALS + 1];
    let mut tangents = [None; SUBINTERVALS + 1];
    let mut feet = [0.0; SUBINTERVALS + 1];
    (points[0], tangents[0]) = (local(a.point), Some(a.tangent));
    (points[n], tangents[n]) = (local(b.point), Some(b.tangent));
    feet[n] = 1.0;
    let mut worst = (x.eval(0.0) - points[0])
        .length()
        .max((x.eval(1.0) - points[n]).length());
    for j in 1..n {
        let t = a.t + (b.t - a.t) * (j as f64 / n as f64);
        let (point, tangent) = sampler.interior(t)?;
        (points[j], tangents[j]) = (local(point), tangent);
        let guess = if j == 1 {
            1.0 / n as f64
        } else {
            2.0 * feet[j - 1] - feet[j - 2]
        };
        let foot = x.closest(points[j], guess);
        feet[j] = foot.v;
        worst = worst.max(foot.distance);
    }
    for j in 0..n {
        let model = hermite_model(points[j], tangents[j], points[j + 1], tangents[j + 1]);
        let probe = x.eval(0.5 * (feet[j] + feet[j + 1]));
        // Started from the probe's projection onto the chord: the model is nearly straight.
        let chord = points[j + 1] - points[j];
        let guess = (probe - points[j]).dot(chord) / chord.length_squared();
        worst = worst.max(model.closest(probe, guess).distance);
    }
    Ok(worst * size)
}

/// The curve between two neighbouring samples: the cubic with legs of a third of the chord
/// along the unit tangents (along the chord where a tangent is missing).
fn hermite_model(p0: DVec3, t0: Option<DVec3>, p1: DVec3, t1: Option<DVec3>) -> LocalCubic {
    let chord = p1 - p0;
    let leg = chord.length() / 3.0;
    let along = |t: Option<DVec3>| t.map_or(chord / 3.0, |t| t * leg);
    LocalCubic::new([p0, p0 + along(t0), p1 - along(t1), p1])
}

/// The measured distance between `cubic` and `curve` on [a, b] (module notes).
#[cfg(test)]
pub(crate) fn distance(
    curve: &dyn ParametricCurve,
    a: f64,
    b: f64,
    cubic: &PhCubic,
) -> Result<f64> {
    let sampler = Sampler::new(curve, usize::MAX);
    let (start, end) = (sampler.sample(a)?, sampler.sample(b)?);
    measure(&sampler, &start, &end, cubic)
}
