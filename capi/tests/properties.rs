//! Property tests (proptest): random valid data must give results with the properties the
//! papers promise, random invalid data a status code — never a panic, never a write.
//!
//! Valid data are G1 Hermite data sampled from random smooth space curves of random size,
//! and random twisted cubics for cone splines. Invalid data take valid data and break one
//! thing: a NaN or infinite coordinate, a zero tangent, a repeated point, a count of 1.

use proptest::prelude::*;
use rmfsurf::glam::DVec3;
use rmfsurf::metrics::{angle_about_tangent, orthonormality_error};
use rmfsurf::{
    ph::cubics as ph_cubics, ph::rational_rmf as ph_rational_rmf,
    ph::spline_hermite as ph_spline_hermite, ph::ExactRmf, ph::RmfOptions, NurbsCurve,
    PiecewiseCurve,
};
use rmfsurf_capi::cone_spline::*;
use rmfsurf_capi::curve::{rmf_curve_eval, rmf_curve_free};
use rmfsurf_capi::mobius::rmf_mobius_rrmf_hermite;
use rmfsurf_capi::ph_cubic::rmf_ph_spline_hermite;
use rmfsurf_capi::rrmf_quintic::rmf_rrmf_spline_hermite;
use rmfsurf_capi::sheet::*;
use rmfsurf_capi::{RmfStatus, RmfVec3};
use std::ffi::c_void;
use std::ptr::null_mut;

/// G1 Hermite data sampled from a random smooth curve (t, a₁ sin(b₁t + c₁), a₂ sin(b₂t + c₂))
/// scaled by s: 2 … 8 samples, parameter steps 0.02 … 0.2 (data a spline would sample).
fn hermite_data() -> impl Strategy<Value = (Vec<DVec3>, Vec<DVec3>)> {
    let wave = (0.1f64..1.5, 0.2f64..1.5, 0.0f64..6.3);
    (2usize..9, 0.02f64..0.2, wave.clone(), wave, 1e-3f64..1e3).prop_map(
        |(n, h, (a1, b1, c1), (a2, b2, c2), scale)| {
            (0..n)
                .map(|i| {
                    let t = h * i as f64;
                    let point = DVec3::new(t, a1 * (b1 * t + c1).sin(), a2 * (b2 * t + c2).sin());
                    let tangent = DVec3::new(
                        1.0,
                        a1 * b1 * (b1 * t + c1).cos(),
                        a2 * b2 * (b2 * t + c2).cos(),
                    );
                    (point * scale, tangent)
                })
                .unzip()
        },
    )
}

fn vec3(v: DVec3) -> RmfVec3 {
    RmfVec3 {
        x: v.x,
        y: v.y,
        z: v.z,
    }
}

/// A rational B-spline evaluated by de Boor's algorithm in homogeneous coordinates — the
/// test's own evaluator, independent of the library's Bézier segments.
fn de_boor(nurbs: &NurbsCurve, t: f64) -> DVec3 {
    let p = nurbs.degree();
    let k = nurbs.knots();
    let n = nurbs.poles().len();
    let span = (p..n).rev().find(|&i| k[i] <= t).unwrap_or(p);
    let mut d: Vec<(DVec3, f64)> = (0..=p)
        .map(|j| {
            let i = span - p + j;
            (nurbs.poles()[i] * nurbs.weights()[i], nurbs.weights()[i])
        })
        .collect();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = span - p + j;
            let alpha = (t - k[i]) / (k[i + p + 1 - r] - k[i]);
            d[j] = (
                d[j - 1].0 * (1.0 - alpha) + d[j].0 * alpha,
                d[j - 1].1 * (1.0 - alpha) + d[j].1 * alpha,
            );
        }
    }
    d[p].0 / d[p].1
}

/// Parameters spread over a spline's domain: every joint and points between.
fn parameters(spline: &PiecewiseCurve) -> Vec<f64> {
    let (lo, hi) = spline.domain();
    (0..=40).map(|i| lo + (hi - lo) * i as f64 / 40.0).collect()
}

/// 64 cases per property, or PROPTEST_CASES for longer explorations; the test command fixes
/// the random seed (PROPTEST_RNG_SEED, scripts/test) so that its runs are reproducible.
fn config() -> ProptestConfig {
    let from_environment = ProptestConfig::default();
    let cases = match std::env::var_os("PROPTEST_CASES") {
        Some(_) => from_environment.cases,
        None => 64,
    };
    ProptestConfig {
        cases,
        ..from_environment
    }
}

proptest! {
    #![proptest_config(config())]

    /// PH cubic splines interpolate, their rational RMF is orthonormal and close to the
    /// exact RMF, and their NURBS view evaluates (by de Boor) as the Bézier segments do.
    #[test]
    fn ph_splines_interpolate_with_orthonormal_frames_near_the_rmf(
        (points, tangents) in hermite_data()
    ) {
        // Near an inflection of the planar projection no PH cubic may exist (they have
        // none): RMF_ERROR_NO_SOLUTION is the documented answer, and such data are skipped.
        let spline = match ph_spline_hermite(&points, &tangents) {
            Err(e) if e.is(rmfsurf::ErrorKind::NoSolution) => return Ok(()),
            result => result.unwrap(),
        };
        for (i, (p, t)) in points.iter().zip(&tangents).enumerate() {
            let jet = spline.eval_jet(i as f64);
            prop_assert!((jet.point - *p).length() < 1e-12 * (1.0 + p.length()));
            prop_assert!(jet.d1.normalize().dot(*t) > 1.0 - 1e-12);
        }
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let exact = ExactRmf::new(&spline, DVec3::Z, 0.0).unwrap();
        // Rounding relative to the largest speed grows where the speed dips to
        // r = min σ / max σ (nearly cuspidal interpolants of nearly straight data: 1.7e-11
        // at r = 1.9e-4, from the carried frame).
        let r = ph_cubics(&spline).unwrap().iter().map(|c| c.speed_ratio()).fold(1.0, f64::min);
        for t in parameters(&spline) {
            let frame = rmf.framed.frames().frame(t);
            // Orthonormal to rounding at every bend: the base frames come from the quaternion
            // preimage (a finding of this test: (19) taken literally was 5e-9 from
            // orthonormal at sin θ = 2e-3, its conditioning ε/sin²θ).
            let error = orthonormality_error(&frame);
            prop_assert!(error < 1e-13 / r, "t = {}: {:e} (speed ratio {:e})", t, error, r);
            // Tangents turning up to 0.9 rad per segment: the rational RMF follows the exact
            // one to within 1e-4 rad (1e-6 and below for fine splines, see docs/ph-cubic.md).
            let angle = angle_about_tangent(&exact.frame(t), &frame).abs();
            prop_assert!(angle < 1e-4, "t = {}: {}", t, angle);
        }
        let nurbs = NurbsCurve::from_piecewise(&spline).unwrap();
        for t in parameters(&spline) {
            let (a, b) = (spline.eval(t), de_boor(&nurbs, t));
            prop_assert!((a - b).length() < 1e-12 * (1.0 + a.length()), "t = {}", t);
        }
    }

    /// Cone spline fits of the tangent surface of (t, a t², b t³) develop isometrically:
    /// boundary arc splines keep their lengths in the plane.
    #[test]
    fn developments_are_isometric(a in 0.5f64..2.0, b in 0.5f64..2.0, tolerance in 1e-4f64..1e-2) {
        let coefficients = [a, b];
        let mut spline = null_mut();
        let mut max_error = 0.0;
        #[allow(deprecated)] // the deprecated wrapper gives the same fits
        let status = unsafe {
            rmf_cone_spline_approximate(
                std::ptr::null(), Some(cubic), coefficients.as_ptr() as *mut c_void,
                0.2, 1.2, 0.5, 4.0, tolerance, RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 10_000,
                &mut spline, &mut max_error,
            )
        };
        prop_assert_eq!(status, RmfStatus::RmfOk);
        prop_assert!(max_error <= tolerance);
        let mut flat = null_mut();
        prop_assert_eq!(unsafe { rmf_cone_spline_develop(spline, &mut flat) }, RmfStatus::RmfOk);
        for t in [-0.2, 0.0, 0.3] {
            let (l0, l1) = (boundary_length(spline, t), boundary_length(flat, t));
            prop_assert!((l0 - l1).abs() < 1e-6 * l0, "t = {}: {} vs {}", t, l0, l1);
        }
        unsafe {
            rmf_cone_spline_free(flat);
            rmf_cone_spline_free(spline);
        }
    }

    /// Invalid Hermite data — one coordinate NaN or infinite, a zero tangent, a repeated
    /// point — give RMF_ERROR_INVALID_INPUT from every Hermite entry point, with nothing
    /// written.
    #[test]
    fn invalid_hermite_data_give_a_status_never_a_panic(
        (points, tangents) in hermite_data(),
        index in 0usize..8,
        kind in 0usize..4,
    ) {
        let (mut points, mut tangents): (Vec<RmfVec3>, Vec<RmfVec3>) =
            (points.into_iter().map(vec3).collect(), tangents.into_iter().map(vec3).collect());
        let (n, i) = (points.len(), index % points.len());
        match kind {
            0 => points[i].y = f64::NAN,
            1 => tangents[i].z = f64::NEG_INFINITY,
            2 => tangents[i] = RmfVec3::default(),
            // A point repeated by its successor (or predecessor, for the last one).
            _ => points[if i + 1 < n { i + 1 } else { i - 1 }] = points[i],
        }
        let (p, t) = (points.as_ptr(), tangents.as_ptr());
        let up = vec3(DVec3::Z);
        let sentinel = 0x5EED0 as *mut _;
        let (mut c, mut f) = (sentinel, sentinel as *mut _);
        let s = unsafe { rmf_ph_spline_hermite(p, t, n, &mut c) };
        prop_assert_eq!(s, RmfStatus::RmfErrorInvalidInput);
        prop_assert_eq!(c, sentinel);
        let s = unsafe { rmf_mobius_rrmf_hermite(p, t, n, up, &mut c, &mut f) };
        prop_assert_eq!(s, RmfStatus::RmfErrorInvalidInput);
        prop_assert!(c == sentinel && f == sentinel as *mut _);
        let s = unsafe { rmf_rrmf_spline_hermite(p, t, n, up, 3, 8, &mut c, &mut f) };
        prop_assert_eq!(s, RmfStatus::RmfErrorInvalidInput);
        prop_assert!(c == sentinel && f == sentinel as *mut _);
    }

    /// A transition between a random convex polygon (corners at sorted random angles on a
    /// circle) and a random circle above it is the same part at every scale 1e-200 … 1e200
    /// and translation: the same pieces, edges and flat pattern, scaled; the flat outline
    /// closed, counter-clockwise, and as large as the formed neutral layer is (to the flat
    /// tolerance along the edges).
    #[test]
    fn transitions_are_invariant_under_scaling_and_translation(
        angles in prop::collection::vec(0.0f64..1.0, 3..8),
        (cx, cy, height, radius) in (-0.3f64..0.3, -0.3f64..0.3, 0.5f64..2.0, 0.1f64..0.5),
        exponent in -200i32..=200,
        shift in (-1e3f64..1e3, -1e3f64..1e3, -1e3f64..1e3),
    ) {
        let mut angles: Vec<f64> = angles.iter().map(|a| a * std::f64::consts::TAU).collect();
        angles.sort_by(f64::total_cmp);
        angles.dedup_by(|a, b| (*a - *b).abs() < 0.05);
        // Convex polygons only: every gap below π.
        let gaps = angles.windows(2).map(|w| w[1] - w[0]).chain([angles[0] + std::f64::consts::TAU - angles[angles.len() - 1]]);
        prop_assume!(angles.len() >= 3 && gaps.fold(0.0, f64::max) < 3.0);
        let scale = 10f64.powi(exponent);
        let shift = DVec3::new(shift.0, shift.1, shift.2) * scale;
        let part = |s: f64, t: DVec3| {
            let corners: Vec<DVec3> = angles.iter().map(|a| DVec3::new(a.cos(), a.sin(), 0.0) * s + t).collect();
            sheet_transition(&corners, DVec3::new(cx, cy, height) * s + t, radius * s, 1e-2 * s, 0.01 * s)
        };
        let (a, b) = match (part(1.0, DVec3::ZERO), part(scale, shift)) {
            (Ok(a), Ok(b)) => (a, b),
            (a, b) => return Err(TestCaseError::fail(format!(
                "a transition failed: at scale 1: {:?}; scaled: {:?}", a.err(), b.err()
            ))),
        };
        prop_assert_eq!(a.report.pieces, b.report.pieces);
        for k in 0..2 {
            let (ea, eb) = (a.report.edge_distance[k], b.report.edge_distance[k] / scale);
            // Edges lie on the curves to ~1e-10 of the part's size (rounding of the trims and
            // of the sampled distance), where the two copies may differ; above it, 1e-6.
            prop_assert!(ea <= 1e-2 && (ea - eb).abs() <= 1e-6 * ea + 1e-9, "edge {}: {} vs {}", k, ea, eb);
        }
        let (area_a, area_b) = (outline_area(&a.edges, 1.0), outline_area(&b.edges, scale));
        prop_assert!(area_a > 0.0, "counter-clockwise");
        prop_assert!((area_a - area_b).abs() <= 1e-9 * area_a, "{} vs {}", area_a, area_b);
        let cut: Vec<&RmfFlatEdge> = b.edges.iter().filter(|e| e.layer == RMF_FLAT_CUT).collect();
        for (k, e) in cut.iter().enumerate() {
            prop_assert!(e.to == cut[(k + 1) % cut.len()].from, "closed outline");
        }
    }

    /// Bad sheet numbers — thickness ≤ 0 or not finite, K-factor outside [0, 1], a zero or
    /// negative tolerance — give RMF_ERROR_INVALID_INPUT naming the field, nothing written.
    #[test]
    fn bad_sheet_options_give_a_status_never_a_part(
        which in 0usize..3,
        value in prop_oneof![Just(f64::NAN), Just(f64::INFINITY), -1e300f64..=0.0, 1.0001f64..1e300],
    ) {
        let corners = [DVec3::new(-1.0, -1.0, 0.0), DVec3::new(1.0, -1.0, 0.0), DVec3::new(1.0, 1.0, 0.0), DVec3::new(-1.0, 1.0, 0.0)];
        let (bottom, top) = (polygon_handle(&corners), circle_handle(DVec3::new(0.0, 0.0, 1.0), 0.4));
        let mut options = RmfSheetOptions { tolerance: 1e-2, ..Default::default() };
        let field = match which {
            0 => { options.thickness = value.min(0.0); "options->thickness" }
            1 => { options.k_factor = if value.is_nan() { value } else { value.abs() + 1.0 }; "options->k_factor" }
            _ => { options.tolerance = value.min(0.0); "options->tolerance" }
        };
        let sentinel = 0x5EED0 as *mut RmfSheetPart;
        let mut out = sentinel;
        let status = unsafe { rmf_sheet_part_transition(bottom, top, &options, &mut out) };
        let message = unsafe { std::ffi::CStr::from_ptr(rmfsurf_capi::status::rmf_last_error()) }.to_string_lossy().into_owned();
        unsafe {
            rmf_curve_free(bottom);
            rmf_curve_free(top);
        }
        prop_assert_eq!(status, RmfStatus::RmfErrorInvalidInput);
        prop_assert!(message.contains(field), "{}", message);
        prop_assert_eq!(out, sentinel);
    }

    /// Random bytes run through every capability's fuzz program (the harness of fuzz/,
    /// which checks the C API's contract after every call) without a violation.
    #[test]
    fn random_programs_keep_the_contract(bytes in prop::collection::vec(any::<u8>(), 0..256)) {
        for (_, target) in harness::TARGETS {
            target(&bytes);
        }
    }
}

#[path = "../../fuzz/src/lib.rs"]
#[allow(dead_code)]
mod harness;

/// The curve (t, a t², b t³) for a C callback, `user` pointing to [a, b].
unsafe extern "C" fn cubic(t: f64, user: *mut c_void, point: *mut RmfVec3, tangent: *mut RmfVec3) {
    let [a, b] = *(user as *const [f64; 2]);
    *point = vec3(DVec3::new(t, a * t * t, b * t * t * t));
    *tangent = vec3(DVec3::new(1.0, 2.0 * a * t, 3.0 * b * t * t));
}

/// The length of the boundary arc spline at distance `t` along the rulings, by a fine
/// polyline on its curve handle.
fn boundary_length(spline: *const RmfConeSpline, t: f64) -> f64 {
    let mut curve = null_mut();
    assert_eq!(
        unsafe { rmf_cone_spline_boundary(spline, t, &mut curve) },
        RmfStatus::RmfOk
    );
    let (mut lo, mut hi) = (0.0, 0.0);
    unsafe { rmfsurf_capi::curve::rmf_curve_domain(curve, &mut lo, &mut hi) };
    let n = 20_000;
    let point = |i: usize| {
        let mut p = RmfVec3::default();
        let s = lo + (hi - lo) * i as f64 / n as f64;
        unsafe { rmf_curve_eval(curve, s.min(hi), &mut p, std::ptr::null_mut()) };
        DVec3::new(p.x, p.y, p.z)
    };
    let length = (0..n).map(|i| (point(i + 1) - point(i)).length()).sum();
    unsafe { rmf_curve_free(curve) };
    length
}

/// A random polyline wire: 3 … 6 points, legs of 2 … 6 turning by at most 120° (no
/// reversal), in 3-D.
fn polyline_wire() -> impl Strategy<Value = Vec<DVec3>> {
    let leg = (2.0f64..6.0, -1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0);
    prop::collection::vec(leg, 2..6).prop_filter_map("legs turning by at most 120°", |legs| {
        let mut points = vec![DVec3::ZERO];
        let mut previous: Option<DVec3> = None;
        for (length, x, y, z) in legs {
            let d = DVec3::new(x, y, z).try_normalize()?;
            if previous.is_some_and(|p| p.dot(d) < -0.5 || p.dot(d) > 1.0 - 1e-6) {
                return None;
            }
            points.push(points[points.len() - 1] + d * length);
            previous = Some(d);
        }
        Some(points)
    })
}

/// The circle of radius r about the origin (four rational quarters).
fn circle_profile(r: f64) -> PiecewiseCurve {
    rmfsurf::primitives::circle(DVec3::ZERO, DVec3::X, DVec3::Y, r).unwrap()
}

fn sweep_polyline(points: &[DVec3], r: f64, corner: Corner) -> rmfsurf::Result<Shape> {
    let edges: Vec<Edge> = points
        .windows(2)
        .map(|w| Edge::Line {
            from: w[0],
            to: w[1],
        })
        .collect();
    let options = WireSweep {
        corner,
        ..WireSweep::default()
    };
    sweep_wire(&edges, &circle_profile(r), &[], &options)
}

use rmfsurf::{wire::sweep as sweep_wire, wire::Corner, wire::Edge, wire::Shape, wire::WireSweep};

proptest! {
    #![proptest_config(config())]

    /// Random polylines with round (ρ = 0.3) and miter corners give solids: the spine
    /// pieces connected end to end, the faces meeting at every joint, no turn of the frame
    /// about the tangent across a corner, and the volume π r² L of the closed form (L the
    /// polyline's length, less 2ρ tan(θ/2) − ρθ per round corner).
    #[test]
    fn random_wires_are_connected_solids_without_twist_at_joints(
        points in polyline_wire(), r in 0.02f64..0.15, miter in any::<bool>()
    ) {
        let corner = if miter { Corner::Miter } else { Corner::Round(Some(0.3)) };
        let shape = sweep_polyline(&points, r, corner).unwrap();
        prop_assert!(shape.is_solid());
        let spine = shape.spine();
        for pair in spine.windows(2) {
            let end = pair[0].eval(pair[0].domain().1);
            let start = pair[1].eval(pair[1].domain().0);
            prop_assert!(end.distance(start) <= 1e-12 * (1.0 + end.length()), "{end} vs {start}");
        }
        let report = shape.report();
        prop_assert!(report.joint_gap <= 1e-12, "joint gap {}", report.joint_gap);
        prop_assert!(report.corner_turn <= 1e-12, "turn {}", report.corner_turn);
        let mut length: f64 = points.windows(2).map(|w| w[0].distance(w[1])).sum();
        if !miter {
            for w in points.windows(3) {
                let theta = (w[1] - w[0]).angle_between(w[2] - w[1]);
                length -= 0.3 * (2.0 * (0.5 * theta).tan() - theta);
            }
        }
        let expected = std::f64::consts::PI * r * r * length;
        let v = shape.volume().unwrap();
        prop_assert!((v - expected).abs() <= 1e-9 * expected, "{v} vs {expected}");
    }

    /// The same wire scaled by 10^k (k from −200 to 200) and moved gives the same shape,
    /// scaled and moved: the construction works in coordinates centred and scaled on the
    /// data.
    #[test]
    fn wire_sweeps_do_not_depend_on_scale_or_position(
        points in polyline_wire(), k in -200i32..=200, shift in (-1e3f64..1e3, -1e3f64..1e3, -1e3f64..1e3),
        miter in any::<bool>()
    ) {
        let scale = 10f64.powi(k);
        let offset = DVec3::new(shift.0, shift.1, shift.2) * scale;
        let (corner, scaled_corner) = if miter {
            (Corner::Miter, Corner::Miter)
        } else {
            (Corner::Round(Some(0.3)), Corner::Round(Some(0.3 * scale)))
        };
        let unit = sweep_polyline(&points, 0.1, corner).unwrap();
        let moved: Vec<DVec3> = points.iter().map(|&p| p * scale + offset).collect();
        let edges: Vec<Edge> = moved.windows(2).map(|w| Edge::Line { from: w[0], to: w[1] }).collect();
        let profile = {
            let c = circle_profile(0.1);
            let segments = c.segments().iter().map(|s| s.similar(scale, DVec3::ZERO)).collect();
            PiecewiseCurve::new(segments, c.breaks().to_vec()).unwrap()
        };
        let options = WireSweep { corner: scaled_corner, ..WireSweep::default() };
        let shape = sweep_wire(&edges, &profile, &[], &options).unwrap();
        prop_assert_eq!(unit.faces().len(), shape.faces().len());
        let size = 1.0 + points.iter().map(|p| p.length()).fold(0.0, f64::max);
        for (a, b) in unit.faces().iter().zip(shape.faces()) {
            let (Some(sa), Some(sb)) = (&a.surface, &b.surface) else { continue };
            let (u0, u1) = sa.domain_u();
            let (v0, v1) = sa.domain_v();
            for (u, v) in [(u0, v0), (u1, v1), (0.5 * (u0 + u1), 0.3 * v0 + 0.7 * v1)] {
                let (pa, pb) = (sa.eval(u, v), (sb.eval(u, v) - offset) / scale);
                prop_assert!(pa.distance(pb) <= 1e-9 * size, "scale 1e{k}: {pa} vs {pb}");
            }
        }
        let (ra, rb) = (unit.report(), shape.report());
        prop_assert!((ra.singularity_margin - rb.singularity_margin).abs() <= 1e-9);
    }
}

/// A closed polygon through `corners` as a curve handle (degree 1).
fn polygon_handle(corners: &[DVec3]) -> *mut rmfsurf_capi::RmfCurve {
    let mut poles: Vec<RmfVec3> = corners.iter().map(|&c| vec3(c)).collect();
    poles.push(poles[0]);
    let n = poles.len();
    let mut knots = vec![0.0];
    knots.extend((0..n).map(|k| k as f64));
    knots.push((n - 1) as f64);
    let mut out = null_mut();
    let status = unsafe {
        rmfsurf_capi::curve::rmf_nurbs_curve_create(
            1,
            poles.as_ptr(),
            std::ptr::null(),
            n,
            knots.as_ptr(),
            knots.len(),
            &mut out,
        )
    };
    assert_eq!(status, RmfStatus::RmfOk);
    out
}

/// The horizontal circle about `centre` of radius `r` (four rational quadratics).
fn circle_handle(centre: DVec3, r: f64) -> *mut rmfsurf_capi::RmfCurve {
    let mut out = null_mut();
    let status = unsafe {
        rmfsurf_capi::primitives::rmf_curve_circle(
            vec3(centre),
            vec3(DVec3::X),
            vec3(DVec3::Y),
            r,
            &mut out,
        )
    };
    assert_eq!(status, RmfStatus::RmfOk);
    out
}

struct Transition {
    report: RmfSheetReport,
    edges: Vec<RmfFlatEdge>,
}

/// A transition through the C API (polygon to circle) with its report and flat pattern.
fn sheet_transition(
    corners: &[DVec3],
    centre: DVec3,
    radius: f64,
    tolerance: f64,
    thickness: f64,
) -> Result<Transition, String> {
    let (bottom, top) = (polygon_handle(corners), circle_handle(centre, radius));
    let options = RmfSheetOptions {
        tolerance,
        thickness,
        ..Default::default()
    };
    let mut part = null_mut();
    let status = unsafe { rmf_sheet_part_transition(bottom, top, &options, &mut part) };
    unsafe {
        rmf_curve_free(bottom);
        rmf_curve_free(top);
    }
    if status != RmfStatus::RmfOk {
        let message = unsafe { std::ffi::CStr::from_ptr(rmfsurf_capi::status::rmf_last_error()) };
        return Err(format!("{status:?}: {}", message.to_string_lossy()));
    }
    let mut report = RmfSheetReport::default();
    let mut count = 0;
    unsafe {
        assert_eq!(rmf_sheet_part_report(part, &mut report), RmfStatus::RmfOk);
        assert_eq!(
            rmf_sheet_part_flat_pattern(part, null_mut(), 0, &mut count),
            RmfStatus::RmfOk
        );
    }
    let mut edges = vec![RmfFlatEdge::default(); count];
    unsafe {
        assert_eq!(
            rmf_sheet_part_flat_pattern(part, edges.as_mut_ptr(), count, &mut count),
            RmfStatus::RmfOk
        );
        rmf_sheet_part_free(part);
    }
    Ok(Transition { report, edges })
}

/// The area enclosed by the outline (the RMF_FLAT_CUT edges) divided by scale² (Green's
/// theorem on the scaled-down edges, which keeps 1e±200 in range).
fn outline_area(edges: &[RmfFlatEdge], scale: f64) -> f64 {
    edges
        .iter()
        .filter(|e| e.layer == RMF_FLAT_CUT)
        .map(|e| {
            let (a, b) = (
                (e.from.x / scale, e.from.y / scale),
                (e.to.x / scale, e.to.y / scale),
            );
            let chord = a.0 * b.1 - b.0 * a.1;
            if e.kind == RMF_FLAT_EDGE_ARC {
                let r = e.radius / scale;
                chord + r * r * (e.sweep - e.sweep.sin())
            } else {
                chord
            }
        })
        .sum::<f64>()
        * 0.5
}
