//! PH cubic splines approximating any regular curve (Mäurer & Jüttler §3.2, Theorem 10):
//! G1 Hermite data sampled from the curve, one shape-matching PH cubic of Table 1 per
//! interval, and breaks placed so that every cubic is within the tolerance of the curve with
//! as few cubics as the error law allows.
//!
//! Break placement. By Theorem 10 the distance of the cubic on an interval of length h falls
//! like c·h⁴ (for κ ≠ 0), c varying along the curve. Breaks are therefore placed by marching
//! along each interval of the initial breaks, with the step control of an ODE solver: a trial
//! interval of predicted length h is fitted and measured; with distance e the h⁴ law predicts
//! the length h·(TARGET·tolerance/e)^¼ for a distance of TARGET·tolerance. A trial beyond the
//! tolerance is shortened to that length (three times in a row at most, then halved); a
//! first trial within it but below EXTEND_BELOW·tolerance is extended to it once (to the
//! interval's end if the law puts that within the tolerance, as on a straight line), and the
//! longer of the two within the tolerance is kept. The next segment starts from the kept
//! one's prediction; the last few steps of an interval share what remains equally, each
//! stretched by up to STRETCH before another step is added (no short tail). So every kept
//! cubic is close to the tolerance, the error equidistributed, where halving keeps cubics up
//! to 16 times more accurate than needed; the count is that of the greedy farthest reach on
//! the curves of the benchmark, or one more.
//!
//! Work bounds (constants of [`ApproximationOptions`]). Each trial costs
//! `EVALUATIONS_PER_TRIAL` = 16 curve evaluations (its new end and the distance's interior
//! samples). Per kept segment there are the kept trial, at most one extension and at most
//! three predicted shortenings. The binary logarithm of the trial length rises by at most 4
//! per kept segment ([`MAX_GROWTH`] twice; an extension to the interval's end ends the
//! interval), starts each interval at most at its length, and falls by at least 1 per
//! halving, down to no less than [`MIN_INTERVAL`] of the domain (40 halvings). So there are
//! at most `MAX_TRIALS_PER_SEGMENT` = 9 trials per kept segment plus `TRIALS_PER_INTERVAL` =
//! 43 per interval of the initial breaks, and at most 16·(9·segments + 43·intervals)
//! evaluations plus one per initial break. Callers cap segments and evaluations with
//! [`ApproximationOptions`]; reaching a cap is `NotConverged`.
//!
//! Distance (module `distance`): measured both ways on 16 subintervals, from curve samples
//! to the cubic and from cubic points to the curve, with Newton's method on closest points.

mod distance;

use super::cubic::PhCubic;
use super::hermite::ph_cubic_hermite;
use super::spline::PhSpline;
use crate::bezier::PiecewiseCurve;
#[cfg(test)]
use crate::curve::uniform_parameters;
use crate::curve::ParametricCurve;
#[cfg(test)]
use crate::error::no_solution;
use crate::error::{invalid, Error, Result};
use crate::hermite::HermiteSegment;
use crate::math::{angle_between, largest_coordinate, robust_normalize};
use glam::DVec3;
use std::cell::Cell;

#[cfg(test)]
use distance::distance;
use distance::{measure, SUBINTERVALS};

/// Shortest trial interval, relative to the domain (about 2⁻⁴⁰).
const MIN_INTERVAL: f64 = 1e-12;

/// Largest angle (radians) between the one-sided tangents at a joint of a G1 input curve.
const CORNER_TOLERANCE: f64 = 1e-9;

/// The fraction of the tolerance a predicted step aims at: a margin for the prediction's own
/// error (the c of c·h⁴ changes along the curve).
const TARGET: f64 = 0.95;

/// How far a step predicted for [`TARGET`]·tolerance may be stretched before the h⁴ law
/// predicts the tolerance itself: TARGET^(−1/4).
const STRETCH: f64 = 1.012_906_807_6;

/// A first trial closer than this fraction of the tolerance is extended once (module notes).
const EXTEND_BELOW: f64 = 0.8;

/// Largest factor by which one trial length may exceed the last kept one.
const MAX_GROWTH: f64 = 4.0;

/// Largest factor of a predicted shrink after a rejection.
const FIRST_SHRINK: f64 = 0.97;

/// Rejections in a row shortened as the h⁴ law predicts; later ones at least halve.
const PREDICTED_SHRINKS: usize = 3;

/// Steps of an interval's end shared equally (see `March::trial_end`).
const BALANCED_STEPS: f64 = 5.0;

/// Smallest factor of a predicted shrink (a badly wrong trial does not overshoot below it).
const LEAST_SHRINK: f64 = 0.1;

/// What an approximation aims at and what it may spend.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ApproximationOptions {
    /// Largest distance between the spline and the curve, finite and > 0.
    pub tolerance: f64,
    /// Most PH segments, 1 ..= [`Self::SEGMENT_LIMIT`].
    pub max_segments: usize,
    /// Most curve evaluations (≥ 1); `usize::MAX` for no cap beyond the segment limit.
    pub max_evaluations: usize,
}

impl ApproximationOptions {
    /// Most segments an approximation may have unless the caller allows more.
    pub const MAX_SEGMENTS: usize = 100_000;

    /// The most segments a caller may allow (2²⁰; each costs a few hundred bytes while it
    /// is built, so this bounds one call's memory to about half a gigabyte).
    pub const SEGMENT_LIMIT: usize = 1 << 20;

    /// Curve evaluations of one trial interval: its new end and the interior samples of
    /// the distance.
    pub const EVALUATIONS_PER_TRIAL: usize = SUBINTERVALS;

    /// Most trials per kept segment (module notes): itself, an extension, three predicted
    /// shortenings and four halvings.
    pub const MAX_TRIALS_PER_SEGMENT: usize = 9;

    /// Most trials per interval of the initial breaks beyond
    /// [`Self::MAX_TRIALS_PER_SEGMENT`] per segment: the halvings from the interval's length
    /// down to the shortest trial (2⁻⁴⁰ of the domain), and three predicted shortenings
    /// before a failure.
    pub const TRIALS_PER_INTERVAL: usize = 43;

    /// The tolerance with the default caps: [`Self::MAX_SEGMENTS`] segments, evaluations
    /// uncapped.
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            max_segments: Self::MAX_SEGMENTS,
            max_evaluations: usize::MAX,
        }
    }

    /// Checks the tolerance and the caps (the resolution of the tolerance needs the curve and
    /// is checked by the approximation).
    pub fn check(&self) -> Result<()> {
        let tolerance = self.tolerance;
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return invalid!(
                "tolerance = {tolerance:e} must be finite and positive (in the curve's units)"
            );
        }
        if !(1..=Self::SEGMENT_LIMIT).contains(&self.max_segments) {
            return invalid!(
                "max_segments = {} must be between 1 and {}",
                self.max_segments,
                Self::SEGMENT_LIMIT
            );
        }
        if self.max_evaluations == 0 {
            return invalid!("max_evaluations = 0 must be at least 1");
        }
        Ok(())
    }
}

/// A PH cubic spline approximating a curve, on the curve's own parameter values.
#[derive(Clone, Debug)]
pub struct PhApproximation {
    /// Segment i interpolates the curve's points and tangents at its breakpoints.
    pub spline: PhSpline,
    /// Largest measured distance between the spline and the curve.
    pub max_distance: f64,
    /// The measured distance of each segment.
    pub segment_distances: Vec<f64>,
    /// How many times the curve was evaluated.
    pub evaluations: usize,
}

/// The curve as the approximation sees it: every evaluation counted against the budget, and
/// the largest coordinate seen (the scale at which f64 resolves distances).
struct Sampler<'a> {
    curve: &'a dyn ParametricCurve,
    evaluations: Cell<usize>,
    budget: usize,
    largest: Cell<f64>,
}

impl ParametricCurve for Sampler<'_> {
    fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let count = self.evaluations.get();
        if count >= self.budget {
            return Err(Error::not_converged(format!(
                "the budget of {} curve evaluations is used up at t = {t:e}",
                self.budget
            )));
        }
        self.evaluations.set(count + 1);
        let (p, d) = self.curve.point_derivative(t)?;
        self.largest
            .set(self.largest.get().max(largest_coordinate([p])));
        Ok((p, d))
    }
}

impl<'a> Sampler<'a> {
    fn new(curve: &'a dyn ParametricCurve, budget: usize) -> Self {
        Self {
            curve,
            evaluations: Cell::new(0),
            budget,
            largest: Cell::new(0.0),
        }
    }

    /// Point and unit tangent at a break (errors where the curve is singular).
    fn sample(&self, t: f64) -> Result<Sample> {
        let (point, tangent) = self.point_unit_tangent(t)?;
        Ok(Sample { t, point, tangent })
    }

    /// Point and unit tangent inside an interval; `None` for the tangent where the curve's
    /// derivative vanishes (the distance then uses the chord there).
    fn interior(&self, t: f64) -> Result<(DVec3, Option<DVec3>)> {
        let (p, d) = self.point_derivative(t)?;
        Ok((p, robust_normalize(d)))
    }

    /// The smallest distance f64 resolves at the coordinates seen so far.
    fn resolution(&self) -> f64 {
        f64::EPSILON * self.largest.get()
    }
}

/// Point and unit tangent of the curve at a parameter.
#[derive(Clone, Copy, Debug)]
struct Sample {
    t: f64,
    point: DVec3,
    tangent: DVec3,
}

/// A kept segment: its start, its cubic and its measured distance.
struct Kept {
    start: f64,
    cubic: PhCubic,
    distance: f64,
}

/// A PH cubic spline within `tolerance` of `curve`, breaking at least at `initial_breaks`
/// (which must span the curve's domain; e.g. its NURBS knots). The spline's breakpoints are
/// parameter values of the curve. Default caps (see [`ApproximationOptions::new`]).
pub fn ph_spline_approximate(
    curve: &dyn ParametricCurve,
    initial_breaks: &[f64],
    tolerance: f64,
) -> Result<PhApproximation> {
    ph_spline_approximate_with(curve, initial_breaks, &ApproximationOptions::new(tolerance))
}

/// [`ph_spline_approximate`] with the caller's caps on segments and evaluations.
pub fn ph_spline_approximate_with(
    curve: &dyn ParametricCurve,
    initial_breaks: &[f64],
    options: &ApproximationOptions,
) -> Result<PhApproximation> {
    options.check()?;
    let sampler = Sampler::new(curve, options.max_evaluations);
    let starts = initial_breaks
        .iter()
        .map(|&t| sampler.sample(t))
        .collect::<Result<Vec<_>>>()?;
    check_resolution(options.tolerance, &sampler)?;
    let (lo, hi) = curve.domain();
    let mut march = March {
        sampler: &sampler,
        options,
        min_interval: MIN_INTERVAL * (hi - lo),
        kept: Vec::new(),
    };
    let mut step = f64::INFINITY;
    for pair in starts.windows(2) {
        step = march.interval(pair[0], pair[1], step)?;
    }
    let mut breaks: Vec<f64> = march.kept.iter().map(|k| k.start).collect();
    breaks.push(starts[starts.len() - 1].t);
    let segment_distances: Vec<f64> = march.kept.iter().map(|k| k.distance).collect();
    let max_distance = segment_distances.iter().fold(0.0f64, |m, &d| m.max(d));
    let cubics = march.kept.iter().map(|k| k.cubic).collect();
    Ok(PhApproximation {
        spline: PhSpline::from_cubics_on(cubics, breaks)?,
        max_distance,
        segment_distances,
        evaluations: sampler.evaluations.get(),
    })
}

/// A tolerance below the rounding of the curve's coordinates cannot be measured, let alone
/// reached.
fn check_resolution(tolerance: f64, sampler: &Sampler) -> Result<()> {
    crate::error::check_resolution(tolerance, sampler.largest.get(), "the curve's")
}

/// The marching of the module notes.
struct March<'a> {
    sampler: &'a Sampler<'a>,
    options: &'a ApproximationOptions,
    min_interval: f64,
    kept: Vec<Kept>,
}

/// A trial interval within the tolerance.
struct Trial {
    end: Sample,
    cubic: PhCubic,
    distance: f64,
    length: f64,
}

impl March<'_> {
    /// Covers [start, end] with kept segments, trying `step` first (or the whole interval if
    /// shorter); returns the step predicted for what follows.
    fn interval(&mut self, start: Sample, end: Sample, mut step: f64) -> Result<f64> {
        let mut a = start;
        loop {
            let kept = self.segment(&a, &end, step)?;
            if self.kept.len() == self.options.max_segments {
                return Err(Error::not_converged(format!(
                    "the tolerance {:.3e} needs more than max_segments = {} segments (reached \
                     at t = {:e})",
                    self.options.tolerance, self.options.max_segments, a.t
                )));
            }
            self.kept.push(Kept {
                start: a.t,
                cubic: kept.cubic,
                distance: kept.distance,
            });
            step = kept.length * growth(kept.distance, self.options.tolerance);
            if kept.end.t == end.t {
                return Ok(step);
            }
            a = kept.end;
        }
    }

    /// The next segment from `a`, found from the predicted `step` (module notes): a trial
    /// within the tolerance but well below it is extended once, as far as the h⁴ law
    /// predicts (to the interval's end if the law puts it within the tolerance); a trial
    /// beyond it is shortened until one is within.
    fn segment(&self, a: &Sample, end: &Sample, mut step: f64) -> Result<Trial> {
        let tolerance = self.options.tolerance;
        let mut rejections = 0;
        let mut any_cubic = false;
        let mut kept: Option<Trial> = None;
        loop {
            let Some(t) = trial_end(a.t, end.t, step) else {
                return kept.ok_or_else(|| self.give_up(a, a.t + step, None, any_cubic));
            };
            if let Some(trial) = kept.take_if(|k| t <= k.end.t) {
                // The extension would not reach beyond the trial kept (the last steps of an
                // interval are shared equally).
                return Ok(trial);
            }
            let b = if t == end.t {
                *end
            } else {
                self.sampler.sample(t)?
            };
            let length = b.t - a.t;
            let outcome = fit_interval(self.sampler, a, &b)?;
            match outcome {
                Some((cubic, distance)) if distance <= tolerance => {
                    let trial = Trial {
                        end: b,
                        cubic,
                        distance,
                        length,
                    };
                    if kept.is_some() || b.t == end.t || distance >= EXTEND_BELOW * tolerance {
                        return Ok(trial);
                    }
                    let predicted = if distance > 0.0 {
                        length * (TARGET * tolerance / distance).powf(0.25)
                    } else {
                        f64::INFINITY
                    };
                    step = if a.t + predicted >= end.t {
                        end.t - a.t
                    } else {
                        length * growth(distance, tolerance)
                    };
                    kept = Some(trial);
                }
                _ => {
                    if let Some(trial) = kept {
                        return Ok(trial);
                    }
                    rejections += 1;
                    any_cubic |= outcome.is_some();
                    step = length * shrink(outcome.map(|o| o.1), tolerance, rejections);
                    // No float between a and b: a shorter trial would round to the same b
                    // (a step of half an ulp rounds up), and the loop would never end.
                    let mid = a.t + 0.5 * length;
                    if step < self.min_interval || !(mid > a.t && mid < b.t) {
                        return Err(self.give_up(a, b.t, outcome.map(|o| o.1), any_cubic));
                    }
                }
            }
        }
    }

    fn give_up(&self, a: &Sample, b: f64, distance: Option<f64>, any_cubic: bool) -> Error {
        let tolerance = self.options.tolerance;
        match (distance, any_cubic) {
            (Some(distance), _) => Error::not_converged(format!(
                "distance {distance:.3e} > tolerance {tolerance:.3e} near [{:e}, {b:e}] on the \
                 shortest interval (the tolerance is too close to the rounding of the \
                 coordinates, {:.1e}, for this curve)",
                a.t,
                self.sampler.resolution()
            )),
            (None, true) => Error::not_converged(format!(
                "the tolerance {tolerance:.3e} is not reached near t = {:e}: the PH cubics there \
                 are farther from the curve, and on shorter intervals the data admit none \
                 (rounding at coordinates of {:.1e}, or an inflection)",
                a.t,
                self.sampler.largest.get()
            )),
            (None, false) => Error::no_solution(format!(
                "no PH cubic interpolates the curve near [{:e}, {b:e}] even on a short interval \
                 (a corner, cusp or inflection?)",
                a.t
            )),
        }
    }
}

/// The end of the next trial from `a` in [a, end]: `end` when it is within the step
/// (stretched to what the h⁴ law allows up to the tolerance itself, [`STRETCH`]), the equal
/// share of the remainder when a few steps remain ([`BALANCED_STEPS`]: no short tail), else
/// a + `step`. `None` when the step is below the resolution of the parameter.
fn trial_end(a: f64, end: f64, step: f64) -> Option<f64> {
    let remaining = end - a;
    let steps = remaining / step;
    if steps <= STRETCH {
        return Some(end);
    }
    let t = if steps <= BALANCED_STEPS {
        a + remaining / (steps / STRETCH).ceil()
    } else {
        a + step
    };
    (t > a && t < end).then_some(t)
}

/// The factor for the next trial after one within the tolerance at `distance`: the h⁴ law's
/// prediction for [`TARGET`]·tolerance, at most [`MAX_GROWTH`].
fn growth(distance: f64, tolerance: f64) -> f64 {
    if distance > 0.0 {
        (TARGET * tolerance / distance)
            .powf(0.25)
            .clamp(LEAST_SHRINK, MAX_GROWTH)
    } else {
        MAX_GROWTH
    }
}

/// The factor for the next trial after the `rejections`-th in a row, at `distance` (`None`:
/// no PH cubic): the h⁴ law's prediction, at most [`FIRST_SHRINK`] for the first
/// [`PREDICTED_SHRINKS`] and at most a half after that; a half without a cubic.
fn shrink(distance: Option<f64>, tolerance: f64, rejections: usize) -> f64 {
    let most = if rejections <= PREDICTED_SHRINKS {
        FIRST_SHRINK
    } else {
        0.5
    };
    match distance {
        Some(d) if d.is_finite() => (TARGET * tolerance / d)
            .powf(0.25)
            .clamp(LEAST_SHRINK, most),
        _ => 0.5,
    }
}

/// The PH cubic spline through `segments` + 1 samples at uniform parameters, with its
/// measured distance to the curve (no adaptivity: for convergence studies).
#[cfg(test)]
pub(crate) fn ph_spline_uniform(
    curve: &dyn ParametricCurve,
    segments: usize,
) -> Result<PhApproximation> {
    let sampler = Sampler::new(curve, usize::MAX);
    let samples = uniform_parameters(curve.domain(), segments + 1)
        .into_iter()
        .map(|t| sampler.sample(t))
        .collect::<Result<Vec<_>>>()?;
    let mut cubics = Vec::with_capacity(segments);
    let mut segment_distances = Vec::with_capacity(segments);
    for w in samples.windows(2) {
        match fit_interval(&sampler, &w[0], &w[1])? {
            Some((cubic, distance)) => {
                cubics.push(cubic);
                segment_distances.push(distance);
            }
            None => {
                return no_solution!(
                    "no PH cubic interpolates the curve on [{}, {}]",
                    w[0].t,
                    w[1].t
                )
            }
        }
    }
    Ok(PhApproximation {
        spline: PhSpline::from_cubics_on(cubics, samples.iter().map(|s| s.t).collect())?,
        max_distance: segment_distances.iter().fold(0.0f64, |m, &d| m.max(d)),
        segment_distances,
        evaluations: sampler.evaluations.get(),
    })
}

/// Checks that a piecewise input curve has no corners (its approximation is G1).
pub fn check_g1(curve: &PiecewiseCurve) -> Result<()> {
    for (k, pair) in curve.segments().windows(2).enumerate() {
        let left = pair[0].eval_jet(1.0).d1;
        let right = pair[1].eval_jet(0.0).d1;
        let angle = angle_between(left, right);

        if angle.is_nan() || angle > CORNER_TOLERANCE {
            return invalid!(
                "curve has a corner at t = {} ({angle:.2e} rad between the tangents): a G1 PH \
                 spline cannot follow it; approximate the pieces on either side separately",
                curve.breaks()[k + 1]
            );
        }
    }
    Ok(())
}

/// The shape-matching PH cubic through the data at a and b with its distance to the curve,
/// or `None` when the data admit no PH cubic (also when the points coincide, as the ends of
/// a closed curve do: the interval is then shortened).
fn fit_interval(sampler: &Sampler, a: &Sample, b: &Sample) -> Result<Option<(PhCubic, f64)>> {
    let Ok(data) = HermiteSegment::new(a.point, a.tangent, b.point, b.tangent) else {
        return Ok(None);
    };
    match ph_cubic_hermite(&data) {
        Ok(solutions) => {
            let cubic = solutions.shape_matching;
            let distance = measure(sampler, a, b, &cubic)?;
            Ok(Some((cubic, distance)))
        }
        Err(e) if e.is(crate::ErrorKind::NoSolution) => Ok(None),
        Err(e) => Err(e),
    }
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod tiny_domain_tests {
    use super::*;

    /// A cubic through the origin's neighbourhood, as a C callback gives it.
    struct Cubic([DVec3; 4], (f64, f64));

    impl ParametricCurve for Cubic {
        fn domain(&self) -> (f64, f64) {
            self.1
        }
        fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
            let c = &self.0;
            let point = ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
            Ok((point, (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1]))
        }
    }

    /// On a domain of 640 ulps where no PH cubic fits, a trial of half an ulp rounds up to
    /// the same one-ulp interval: the trials stop at one ulp, with an error naming the
    /// place, instead of repeating it forever.
    #[test]
    fn trials_stop_at_one_ulp() {
        let c = Cubic(
            [
                DVec3::new(1.6874999999998936, 1.5937500000000435, 2.3125000000001905),
                DVec3::new(9.0625e-14, 0.7071067811865882, 0.7071067811866588),
                DVec3::new(1.5, 1.5000000000001499, 1.5000000000001503),
                DVec3::new(1.5000000000000406, 1.5000000000001905, 1.500000000000191),
            ],
            (7.141778489984131e-1, 7.141778489984844e-1),
        );
        let (lo, hi) = c.1;
        // A refusal naming the place, not a hang.
        let e = ph_spline_approximate(&c, &[lo, hi], 7.141778489985557e-1).unwrap_err();
        assert!(e.message().contains("near"), "{e}");
    }
}
