//! PH cubic splines approximating any regular curve (Mäurer & Jüttler §3.2, Theorem 10):
//! G1 Hermite data sampled from the curve, one shape-matching PH cubic of Table 1 per
//! interval, and adaptive subdivision: an interval is halved while its cubic is farther from
//! the curve than the tolerance, or while the data admit no PH cubic. By Theorem 10 the
//! distance falls like h⁴ (for κ ≠ 0), so each halving gains about a factor of 16.
//!
//! The distance between a cubic x and the curve piece p on [a, b] is measured both ways on
//! samples: from points of p to x exactly (the closest points of a cubic are roots of the
//! quintic (x(v) − p)·x'(v)), and from points of x to p by a local minimization near the
//! closest sample (an upper bound of the true distance, so the test errs on the safe side).

use super::cubic::PhCubic;
use super::hermite::ph_cubic_hermite;
use crate::bezier::bernstein::{self, product, to_power};
use crate::bezier::PiecewiseCurve;
#[cfg(test)]
use crate::curve::uniform_parameters;
use crate::curve::ParametricCurve;
#[cfg(test)]
use crate::error::no_solution;
use crate::error::{invalid, Error, Result};
use crate::hermite::HermiteSegment;
use crate::math::angle_between;
use crate::math::{interior_midpoint, minimize_bracketed, real_roots_in};
use glam::DVec3;

/// Samples per interval for the distance, each way.
const DISTANCE_SAMPLES: usize = 16;

/// Most segments an approximation may have before it gives up.
pub const MAX_SEGMENTS: usize = 100_000;

/// Shortest interval, relative to the domain, that is still halved.
const MIN_INTERVAL: f64 = 1e-12;

/// Largest angle (radians) between the one-sided tangents at a joint of a G1 input curve.
const CORNER_TOLERANCE: f64 = 1e-9;

/// A PH cubic spline approximating a curve, on the curve's own parameter values.
#[derive(Clone, Debug)]
pub struct PhApproximation {
    /// Segment i interpolates the curve's points and tangents at its breakpoints.
    pub spline: PiecewiseCurve,
    /// Largest measured distance between the spline and the curve.
    pub max_distance: f64,
}

/// Point and unit tangent of the curve at a parameter.
#[derive(Clone, Copy, Debug)]
struct Sample {
    t: f64,
    point: DVec3,
    tangent: DVec3,
}

fn sample(curve: &dyn ParametricCurve, t: f64) -> Result<Sample> {
    let (point, tangent) = curve.point_unit_tangent(t)?;
    Ok(Sample { t, point, tangent })
}

/// A PH cubic spline within `tolerance` of `curve`, starting from the intervals of
/// `initial_breaks` (which must span the curve's domain; e.g. its NURBS knots) and halving
/// intervals as needed. The spline's breakpoints are parameter values of the curve.
pub fn ph_spline_approximate(
    curve: &dyn ParametricCurve,
    initial_breaks: &[f64],
    tolerance: f64,
) -> Result<PhApproximation> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return invalid!("tolerance = {tolerance} must be finite and positive");
    }
    let (lo, hi) = curve.domain();
    let min_interval = MIN_INTERVAL * (hi - lo);
    let mut accepted: Vec<(Sample, PhCubic, f64)> = Vec::new();
    let mut pending: Vec<(Sample, Sample)> = Vec::new();
    let starts = initial_breaks
        .iter()
        .map(|&t| sample(curve, t))
        .collect::<Result<Vec<_>>>()?;
    pending.extend(starts.windows(2).rev().map(|w| (w[0], w[1])));
    let mut last = starts[starts.len() - 1];
    while let Some((a, b)) = pending.pop() {
        match fit_interval(curve, &a, &b)? {
            Some((cubic, distance)) if distance <= tolerance => {
                accepted.push((a, cubic, distance));
                last = b;
            }
            outcome => {
                let too_fine =
                    b.t - a.t <= min_interval || accepted.len() + pending.len() >= MAX_SEGMENTS;
                let Some(m) = interior_midpoint(a.t, b.t).filter(|_| !too_fine) else {
                    return Err(give_up(&a, &b, outcome, tolerance));
                };
                let mid = sample(curve, m)?;
                pending.push((mid, b));
                pending.push((a, mid));
            }
        }
    }
    let mut breaks: Vec<f64> = accepted.iter().map(|(s, _, _)| s.t).collect();
    breaks.push(last.t);
    let max_distance = accepted.iter().fold(0.0f64, |m, &(_, _, d)| m.max(d));
    let segments = accepted.iter().map(|(_, c, _)| c.to_bezier()).collect();
    Ok(PhApproximation {
        spline: PiecewiseCurve::new(segments, breaks)?,
        max_distance,
    })
}

#[cfg(test)]
/// The PH cubic spline through `segments` + 1 samples at uniform parameters, with its
/// measured distance to the curve (no adaptivity: for convergence studies).
pub fn ph_spline_uniform(curve: &dyn ParametricCurve, segments: usize) -> Result<PhApproximation> {
    let samples = uniform_parameters(curve.domain(), segments + 1)
        .into_iter()
        .map(|t| sample(curve, t))
        .collect::<Result<Vec<_>>>()?;
    let mut cubics = Vec::with_capacity(segments);
    let mut max_distance = 0.0f64;
    for w in samples.windows(2) {
        match fit_interval(curve, &w[0], &w[1])? {
            Some((cubic, distance)) => {
                cubics.push(cubic.to_bezier());
                max_distance = max_distance.max(distance);
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
        spline: PiecewiseCurve::new(cubics, samples.iter().map(|s| s.t).collect())?,
        max_distance,
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
/// a closed curve do: the interval is then halved).
fn fit_interval(
    curve: &dyn ParametricCurve,
    a: &Sample,
    b: &Sample,
) -> Result<Option<(PhCubic, f64)>> {
    let Ok(data) = HermiteSegment::new(a.point, a.tangent, b.point, b.tangent) else {
        return Ok(None);
    };

    match ph_cubic_hermite(&data) {
        Ok(solutions) => {
            let cubic = solutions.shape_matching;
            Ok(Some((cubic, distance(curve, a.t, b.t, &cubic)?)))
        }
        Err(e) if e.is(crate::ErrorKind::NoSolution) => Ok(None),
        Err(e) => Err(e),
    }
}

fn give_up(a: &Sample, b: &Sample, outcome: Option<(PhCubic, f64)>, tolerance: f64) -> Error {
    match outcome {
        None => Error::no_solution(format!(
            "no PH cubic interpolates the curve near [{}, {}] even on a short interval (a corner, \
             cusp or inflection?)",
            a.t, b.t
        )),
        Some((_, distance)) => Error::not_converged(format!(
            "distance {distance:.3e} > tolerance {tolerance:.3e} near [{}, {}] after the limit of \
             {MAX_SEGMENTS} segments or the shortest interval",
            a.t, b.t
        )),
    }
}

/// The two-sided sampled distance between `cubic` and the curve on [a, b] (module notes).
pub fn distance(curve: &dyn ParametricCurve, a: f64, b: f64, cubic: &PhCubic) -> Result<f64> {
    let params: Vec<f64> = (0..=DISTANCE_SAMPLES)
        .map(|j| a + (b - a) * j as f64 / DISTANCE_SAMPLES as f64)
        .collect();
    let points = params
        .iter()
        .map(|&t| curve.point_derivative(t).map(|(p, _)| p))
        .collect::<Result<Vec<DVec3>>>()?;
    let to_cubic = points
        .iter()
        .map(|&p| distance_to_cubic(cubic, p))
        .fold(0.0f64, f64::max);
    let mut to_curve = 0.0f64;
    for j in 1..DISTANCE_SAMPLES {
        let x = cubic.eval(j as f64 / DISTANCE_SAMPLES as f64);
        let nearest = (0..points.len())
            .min_by(|&i, &k| {
                (points[i] - x)
                    .length()
                    .total_cmp(&(points[k] - x).length())
            })
            .expect("samples");
        let (lo, hi) = (
            params[nearest.saturating_sub(1)],
            params[(nearest + 1).min(DISTANCE_SAMPLES)],
        );
        let found = minimize_bracketed(
            |t| {
                curve
                    .point_derivative(t)
                    .map_or(f64::NAN, |(p, _)| (p - x).length())
            },
            lo,
            hi,
            0.0,
        );
        let d = if found.x > lo && found.x < hi {
            normal_distance(curve, found.x, x)?
        } else {
            found.value
        };
        to_curve = to_curve.max(d.min((points[nearest] - x).length()));
    }
    Ok(to_cubic.max(to_curve))
}

/// |x − p(t)| without its part along the tangent at t: near an interior closest point this
/// is the distance with an error of second order in the error of t (Brent's method finds t
/// only to about √ε, which |x − p(t)| would turn into a first-order error).
fn normal_distance(curve: &dyn ParametricCurve, t: f64, x: DVec3) -> Result<f64> {
    let (p, tangent) = curve.point_unit_tangent(t)?;
    let offset = x - p;
    Ok((offset - offset.dot(tangent) * tangent).length())
}

/// Distance from p to a cubic: the closest point is an end or a root in [0, 1] of the
/// quintic (x(v) − p)·x'(v).
fn distance_to_cubic(cubic: &PhCubic, p: DVec3) -> f64 {
    let offset = cubic.control_points().map(|b| b - p);
    let hodograph = bernstein::derivative(&cubic.control_points());
    let quintic = to_power(&product(&offset, &hodograph, |a: DVec3, b: DVec3| a.dot(b)));
    real_roots_in(&quintic, 0.0, 1.0)
        .into_iter()
        .chain([0.0, 1.0])
        .map(|v| (cubic.eval(v) - p).length())
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::RationalBezierCurve;

    /// The helix (cos t, sin t, 0.5 t), t ∈ [0, 2π].
    struct Helix;
    impl ParametricCurve for Helix {
        fn domain(&self) -> (f64, f64) {
            (0.0, 2.0 * std::f64::consts::PI)
        }
        fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
            Ok((
                DVec3::new(t.cos(), t.sin(), 0.5 * t),
                DVec3::new(-t.sin(), t.cos(), 0.5),
            ))
        }
    }

    /// The twisted cubic (t, t², t³), t ∈ [0.2, 1.2]: κ/τ is not constant (not a helix).
    struct TwistedCubic;
    impl ParametricCurve for TwistedCubic {
        fn domain(&self) -> (f64, f64) {
            (0.2, 1.2)
        }
        fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
            Ok((
                DVec3::new(t, t * t, t * t * t),
                DVec3::new(1.0, 2.0 * t, 3.0 * t * t),
            ))
        }
    }

    #[test]
    fn approximation_order_four_of_theorem_10() {
        for (name, curve) in [
            ("helix", &Helix as &dyn ParametricCurve),
            ("twisted cubic", &TwistedCubic),
        ] {
            println!("Theorem 10, {name}: segments, max distance, observed order");
            let mut previous: Option<f64> = None;
            for n in [4, 8, 16, 32, 64] {
                let d = ph_spline_uniform(curve, n).unwrap().max_distance;
                let order = previous.map(|p| (p / d).log2());
                println!(
                    "  {n:3}  {d:.3e}  {}",
                    order.map_or(String::new(), |o| format!("{o:.2}"))
                );
                if let (Some(o), true) = (order, n >= 16) {
                    assert!(o > 3.7 && o < 4.5, "{name}: order {o} at n = {n}");
                }
                previous = Some(d);
            }
        }
    }

    #[test]
    fn adaptive_approximation_meets_the_tolerance() {
        for tolerance in [1e-3, 1e-6, 1e-9] {
            let a = ph_spline_approximate(&Helix, &[0.0, 2.0 * std::f64::consts::PI], tolerance)
                .unwrap();
            assert!(a.max_distance <= tolerance);
            // Independent check on a finer grid of curve points.
            for i in 0..=997 {
                let t = 2.0 * std::f64::consts::PI * i as f64 / 997.0;
                let (p, _) = Helix.point_derivative(t).unwrap();
                let (k, _) = a.spline.locate(t);
                let c: Vec<DVec3> = a.spline.segments()[k].poles().collect();
                let cubic = PhCubic::from_control_points([c[0], c[1], c[2], c[3]]).unwrap();
                assert!(distance_to_cubic(&cubic, p) <= tolerance * 1.01);
            }
            assert_eq!(a.spline.domain(), Helix.domain());
        }
    }

    #[test]
    fn nurbs_input_is_followed_and_corners_are_refused() {
        let arc = RationalBezierCurve::from_weighted(
            &[
                DVec3::X,
                DVec3::new(1.0, 1.0, 0.5),
                DVec3::new(0.0, 1.0, 1.0),
            ],
            &[1.0, 0.7, 1.0],
        )
        .unwrap();
        let line = RationalBezierCurve::polynomial(&[
            DVec3::new(0.0, 1.0, 1.0),
            DVec3::new(-1.0, 1.0, 2.0),
        ])
        .unwrap();
        let smooth = PiecewiseCurve::new(vec![arc.clone()], vec![0.0, 2.0]).unwrap();
        check_g1(&smooth).unwrap();
        let a = ph_spline_approximate(&smooth, smooth.breaks(), 1e-7).unwrap();
        assert!(a.max_distance <= 1e-7);
        let kinked = PiecewiseCurve::new(vec![arc, line], vec![0.0, 1.0, 2.0]).unwrap();
        let e = check_g1(&kinked).unwrap_err();
        assert!(e.message().contains("corner at t = 1"), "{e}");
    }

    #[test]
    fn closed_curves_are_split_where_their_ends_meet() {
        struct Circle;
        impl ParametricCurve for Circle {
            fn domain(&self) -> (f64, f64) {
                (0.0, 2.0 * std::f64::consts::PI)
            }
            fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
                Ok((
                    DVec3::new(t.cos(), t.sin(), 0.1 * (3.0 * t).sin()),
                    DVec3::new(-t.sin(), t.cos(), 0.3 * (3.0 * t).cos()),
                ))
            }
        }
        let a = ph_spline_approximate(&Circle, &[0.0, 2.0 * std::f64::consts::PI], 1e-5).unwrap();
        let (lo, hi) = a.spline.domain();
        assert!((a.spline.eval(hi) - a.spline.eval(lo)).length() < 1e-14);
        assert!(a.max_distance <= 1e-5);
    }

    #[test]
    fn rejects_bad_tolerances_and_reports_failure() {
        for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(ph_spline_approximate(&Helix, &[0.0, 1.0], tol).is_err());
        }
        // A curve with a cusp: (t², t³, 0) around t = 0 has no tangent there.
        struct Cusp;
        impl ParametricCurve for Cusp {
            fn domain(&self) -> (f64, f64) {
                (-1.0, 1.0)
            }
            fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
                Ok((
                    DVec3::new(t * t, t * t * t, 0.0),
                    DVec3::new(2.0 * t, 3.0 * t * t, 0.0),
                ))
            }
        }
        assert!(ph_spline_approximate(&Cusp, &[-1.0, 0.0, 1.0], 1e-6).is_err());
    }
}
