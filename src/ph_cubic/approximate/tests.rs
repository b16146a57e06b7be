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
        let a =
            ph_spline_approximate(&Helix, &[0.0, 2.0 * std::f64::consts::PI], tolerance).unwrap();
        assert!(a.max_distance <= tolerance);
        // Independent check on a finer grid of curve points.
        for i in 0..=997 {
            let t = 2.0 * std::f64::consts::PI * i as f64 / 997.0;
            let (p, _) = Helix.point_derivative(t).unwrap();
            let (k, _) = a.spline.locate(t);
            let c: Vec<DVec3> = a.spline.segments()[k].poles().collect();
            let cubic = PhCubic::from_control_points([c[0], c[1], c[2], c[3]]).unwrap();
            let exact =
                crate::bezier::closest::LocalCubic::new(cubic.control_points()).closest_exact(p);
            assert!(exact.distance <= tolerance * 1.01);
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
    let line =
        RationalBezierCurve::polynomial(&[DVec3::new(0.0, 1.0, 1.0), DVec3::new(-1.0, 1.0, 2.0)])
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

/// A helix scaled by `scale` and moved by `offset`: (cos t, sin t, 0.5 t) · scale + offset.
struct Placed {
    scale: f64,
    offset: DVec3,
}

impl ParametricCurve for Placed {
    fn domain(&self) -> (f64, f64) {
        Helix.domain()
    }
    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let (p, d) = Helix.point_derivative(t)?;
        Ok((p * self.scale + self.offset, d * self.scale))
    }
}

/// (t, 0.05 sin 20t, 0.05 cos 20t), t ∈ [0, 1]: three turns of a thin helix around a line.
struct Wiggly;
impl ParametricCurve for Wiggly {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let (s, c) = (20.0 * t).sin_cos();
        Ok((DVec3::new(t, 0.05 * s, 0.05 * c), DVec3::new(1.0, c, -s)))
    }
}

/// The fewest segments the h⁴ law allows (module notes): with e ≈ c(t)·h⁴ on every short
/// interval, a segment within `tolerance` covers at most tolerance^¼ of ∫ c^¼ dt, which
/// 512 uniform segments measure as Σ eₖ^¼.
fn h4_lower_bound(curve: &dyn ParametricCurve, tolerance: f64) -> f64 {
    let fine = ph_spline_uniform(curve, 512).unwrap();
    let sum: f64 = fine.segment_distances.iter().map(|e| e.powf(0.25)).sum();
    sum / tolerance.powf(0.25)
}

#[test]
fn breaks_equidistribute_the_error_near_the_h4_bound() {
    for (name, curve) in [
        ("helix", &Helix as &dyn ParametricCurve),
        ("twisted cubic", &TwistedCubic),
        ("wiggly", &Wiggly),
    ] {
        for tolerance in [1e-4, 1e-6, 1e-8] {
            let (lo, hi) = curve.domain();
            let a = ph_spline_approximate(curve, &[lo, hi], tolerance).unwrap();
            let segments = a.spline.segments().len();
            let bound = h4_lower_bound(curve, tolerance);
            // Halving from the domain needs a power of two of uniform segments on the helix.
            println!(
                "{name} at {tolerance:e}: {segments} segments, h⁴ bound {bound:.1}, \
                 max distance {:.3e}, {} evaluations",
                a.max_distance, a.evaluations
            );
            assert!(a.max_distance <= tolerance);
            assert!(segments as f64 >= bound.floor(), "{segments} < {bound}");
            assert!(
                segments as f64 <= 1.08 * bound.ceil() + 1.0,
                "{name} at {tolerance:e}: {segments} segments against a bound of {bound:.1}"
            );
        }
    }
}

#[test]
fn the_measured_distance_agrees_with_a_dense_exact_one() {
    // Dense: the exact distance from 2,001 curve points to the cubic (quintic roots).
    for (curve, a, b) in [
        (&Helix as &dyn ParametricCurve, 0.3, 1.1),
        (&TwistedCubic, 0.2, 0.7),
        (&Wiggly, 0.1, 0.2),
    ] {
        let (p0, t0) = curve.point_unit_tangent(a).unwrap();
        let (p1, t1) = curve.point_unit_tangent(b).unwrap();
        let data = HermiteSegment::new(p0, t0, p1, t1).unwrap();
        let cubic = ph_cubic_hermite(&data).unwrap().shape_matching;
        let exact = crate::bezier::closest::LocalCubic::new(cubic.control_points());
        let dense = (0..=2000)
            .map(|i| {
                let t = a + (b - a) * i as f64 / 2000.0;
                exact
                    .closest_exact(curve.point_derivative(t).unwrap().0)
                    .distance
            })
            .fold(0.0f64, f64::max);
        let measured = distance(curve, a, b, &cubic).unwrap();
        assert!(
            (measured - dense).abs() <= 0.01 * dense,
            "measured {measured:e}, dense {dense:e}"
        );
    }
}

#[test]
fn work_stays_within_the_documented_bound() {
    for (name, curve, tolerance) in [
        ("helix", &Helix as &dyn ParametricCurve, 1e-9),
        ("twisted cubic", &TwistedCubic, 1e-12),
        ("wiggly", &Wiggly, 1e-15),
    ] {
        let (lo, hi) = curve.domain();
        let a = ph_spline_approximate(curve, &[lo, hi], tolerance).unwrap();
        let segments = a.spline.segments().len();
        let bound = ApproximationOptions::EVALUATIONS_PER_TRIAL
            * (ApproximationOptions::MAX_TRIALS_PER_SEGMENT * segments
                + ApproximationOptions::TRIALS_PER_INTERVAL)
            + 2;
        println!(
            "{name} at {tolerance:e}: {segments} segments, {} evaluations ({:.1} per \
             segment; bound {bound})",
            a.evaluations,
            a.evaluations as f64 / segments as f64
        );
        assert!(a.evaluations <= bound);
        // In practice far fewer: about two trials per segment.
        assert!(a.evaluations <= 3 * ApproximationOptions::EVALUATIONS_PER_TRIAL * segments + 200);
    }
}

#[test]
fn budgets_end_in_not_converged() {
    let domain = [0.0, 2.0 * std::f64::consts::PI];
    let full = ph_spline_approximate(&Helix, &domain, 1e-8).unwrap();
    let capped = |max_segments, max_evaluations| {
        let options = ApproximationOptions {
            max_segments,
            max_evaluations,
            ..ApproximationOptions::new(1e-8)
        };
        ph_spline_approximate_with(&Helix, &domain, &options)
    };
    let e = capped(ApproximationOptions::MAX_SEGMENTS, full.evaluations / 2).unwrap_err();
    assert!(e.is(crate::ErrorKind::NotConverged), "{e}");
    assert!(e.message().contains("budget of"), "{e}");
    let segments = full.spline.segments().len();
    let e = capped(segments - 1, usize::MAX).unwrap_err();
    assert!(e.is(crate::ErrorKind::NotConverged), "{e}");
    assert!(e.message().contains("max_segments"), "{e}");
    // Exactly enough of both reproduces the full result.
    let exact = capped(segments, full.evaluations).unwrap();
    assert_eq!(exact.spline, full.spline);
    assert_eq!(exact.evaluations, full.evaluations);
    for (max_segments, max_evaluations) in
        [(0, 1), (ApproximationOptions::SEGMENT_LIMIT + 1, 1), (1, 0)]
    {
        let e = capped(max_segments, max_evaluations).unwrap_err();
        assert!(e.is(crate::ErrorKind::InvalidInput), "{e}");
    }
}

/// An unreachable tolerance is not a corner, cusp or inflection (NoSolution): below the
/// rounding of the coordinates (4e-320, 1e-300, 5e-16) it is refused as invalid; above it,
/// but beyond what the PH fits can resolve there, it is NotConverged.
#[test]
fn unreachable_tolerances_are_not_mistaken_for_inflections() {
    let domain = [0.0, 2.0 * std::f64::consts::PI];
    for tolerance in [4e-320, 1e-300, 5e-16] {
        let e = ph_spline_approximate(&Helix, &domain, tolerance).unwrap_err();
        assert!(e.is(crate::ErrorKind::InvalidInput), "{e}");
        assert!(e.message().contains("below what f64 resolves"), "{e}");
    }
    // Just above the rounding the fits are decided by it: they reach the tolerance or end
    // NotConverged, never with a verdict on the curve's shape.
    let far = Placed {
        scale: 1.0,
        offset: DVec3::new(1e6, 0.0, 0.0),
    };
    for (curve, resolution) in [
        (&far as &dyn ParametricCurve, f64::EPSILON * (1e6 + 1.0)),
        (&Wiggly, f64::EPSILON),
    ] {
        for factor in [1.01, 1.5, 2.0, 4.0, 16.0] {
            let tolerance = factor * resolution;
            let (lo, hi) = curve.domain();
            match ph_spline_approximate(curve, &[lo, hi], tolerance) {
                Ok(a) => {
                    println!(
                        "{factor} × rounding: {} segments",
                        a.spline.segments().len()
                    );
                    assert!(a.max_distance <= tolerance);
                }
                Err(e) => {
                    println!("{factor} × rounding: {e}");
                    assert!(e.is(crate::ErrorKind::NotConverged), "{e}");
                }
            }
        }
    }
}

/// The marching and the distance are invariant under scaling and translation. (Beyond
/// 1e±150 the Hermite fit of Table 1 itself fails today: its PH residual squares the legs,
/// which under- or overflow; reliability issue, item 8.)
#[test]
fn scaling_and_translation_leave_the_breaks() {
    let domain = [0.0, 2.0 * std::f64::consts::PI];
    let reference = ph_spline_approximate(&Helix, &domain, 1e-6).unwrap();
    for (scale, offset) in [
        (1e-140, DVec3::ZERO),
        (1e-100, DVec3::ZERO),
        (1e100, DVec3::ZERO),
        (1e140, DVec3::ZERO),
        (1.0, DVec3::new(1e6, -1e6, 1e6)),
    ] {
        let placed = Placed { scale, offset };
        let a = ph_spline_approximate(&placed, &domain, 1e-6 * scale).unwrap();
        assert_eq!(
            a.spline.segments().len(),
            reference.spline.segments().len(),
            "scale {scale:e}, offset {offset}"
        );
        // Translated, the coordinates round at 2e-10, 2e-4 of the tolerance: the predicted
        // steps (a fourth root) move by about 5e-5 of themselves.
        let shift = if offset == DVec3::ZERO { 1e-9 } else { 1e-4 };
        let moved = a
            .spline
            .breaks()
            .iter()
            .zip(reference.spline.breaks())
            .map(|(b, r)| (b - r).abs())
            .fold(0.0f64, f64::max);
        println!("scale {scale:e}, offset {offset}: breaks moved by {moved:.1e}");
        assert!(moved < shift, "scale {scale:e}, offset {offset}: {moved:e}");
        assert!(a.max_distance <= 1e-6 * scale);
        assert!((a.max_distance / scale - reference.max_distance).abs() < 1e-3 * 1e-6);
    }
}
