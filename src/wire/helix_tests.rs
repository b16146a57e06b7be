//! Sweeps along circular helices against the exact screw sweep: a profile carried by a
//! helix's Frenet frame is the screw motion's image of it, so every point of a thread's
//! faces lies, in the helix's normal plane through it, on the profile placed in that
//! plane's Frenet frame; every point of a pipe is at the profile's radius from the helix;
//! the volume is the profile's area times the helix's length (the first moment of a
//! centred profile integrates to 0). A lone helix edge under the Frenet frame, or a pipe
//! along it, is swept by its screw motion (module `helix`): faces of degree 7 along it with
//! simple knots, eight spans a turn; what the screw motion does not carry takes the PH
//! spline.

use super::options_tests::helix;
use super::tests::{circle, triangle, volume};
use super::*;
use std::f64::consts::TAU;

/// The helix of `helix(radius, pitch, _)`: (R cos θ, R sin θ, h θ), h = pitch/2π.
struct Exact {
    radius: f64,
    rise: f64,
}

impl Exact {
    fn point(&self, theta: f64) -> DVec3 {
        DVec3::new(
            self.radius * theta.cos(),
            self.radius * theta.sin(),
            self.rise * theta,
        )
    }

    fn d1(&self, theta: f64) -> DVec3 {
        DVec3::new(
            -self.radius * theta.sin(),
            self.radius * theta.cos(),
            self.rise,
        )
    }

    fn d2(&self, theta: f64) -> DVec3 {
        DVec3::new(-self.radius * theta.cos(), -self.radius * theta.sin(), 0.0)
    }

    /// The angle whose normal plane holds x (Newton on (x − H(θ))·H′(θ) = 0 from the turn
    /// of the same height: the profile reaches less than half a pitch along the axis).
    fn foot(&self, x: DVec3) -> f64 {
        let around = x.y.atan2(x.x);
        let turns = ((x.z / self.rise - around) / TAU).round();
        let mut theta = around + TAU * turns;
        for _ in 0..50 {
            let d = x - self.point(theta);
            let g = d.dot(self.d1(theta));
            let dg = -self.d1(theta).length_squared() + d.dot(self.d2(theta));
            let step = g / dg;
            theta -= step;
            if step.abs() < 1e-15 {
                break;
            }
        }
        theta
    }

    /// x in the Frenet frame of its normal plane: (along N, along B).
    fn in_normal_plane(&self, x: DVec3) -> (f64, f64) {
        let theta = self.foot(x);
        let t = self.d1(theta).normalize();
        let n = -DVec3::new(theta.cos(), theta.sin(), 0.0);
        let d = x - self.point(theta);
        (d.dot(n), d.dot(t.cross(n)))
    }

    fn length(&self, turns: f64) -> f64 {
        TAU * turns * self.radius.hypot(self.rise)
    }
}

/// The helix the tests sweep along: `helix(3.0, 2.0, _)`.
const THREAD: Exact = Exact {
    radius: 3.0,
    rise: 2.0 / TAU,
};

/// The corners of `triangle(0.5)` (profile coordinates x along f₂, y along f₃) in the
/// normal plane's (along N, along B), the frame placing them as `in_frenet` says.
fn triangle_corners(in_frenet: impl Fn(f64, f64) -> (f64, f64)) -> Vec<(f64, f64)> {
    (0..3)
        .map(|k| {
            let a = TAU * k as f64 / 3.0;
            in_frenet(0.5 * a.cos(), 0.5 * a.sin())
        })
        .collect()
}

/// Points of the lateral faces on a 24 × 400 grid of each.
fn lateral_points(shape: &Shape) -> Vec<DVec3> {
    let mut points = Vec::new();
    for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
        let s = face.surface.as_ref().unwrap();
        let ((u0, u1), (v0, v1)) = (s.domain_u(), s.domain_v());
        for i in 0..=24 {
            for j in 0..=400 {
                let (u, v) = (i as f64 / 24.0, j as f64 / 400.0);
                points.push(s.eval(u0 + (u1 - u0) * u, v0 + (v1 - v0) * v));
            }
        }
    }
    points
}

/// The largest distance, in the helix's normal planes, of the lateral faces' points from
/// the triangle of `corners` (coordinates along N and along B): how far the sweep is from
/// the exact screw sweep of that triangle.
fn off_screw_sweep(shape: &Shape, exact: &Exact, corners: &[(f64, f64)]) -> f64 {
    lateral_points(shape)
        .into_iter()
        .map(|x| {
            let p = exact.in_normal_plane(x);
            (0..corners.len())
                .map(|k| to_segment(p, corners[k], corners[(k + 1) % corners.len()]))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}

/// Distance from p to the segment a–b in the plane.
fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let s = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    (p.0 - a.0 - s * dx).hypot(p.1 - a.1 - s * dy)
}

/// The helix of [`helix`] as cubic Hermite segments through 96 points a turn (not PH:
/// its spine is approximated; within 2e-7 of the helix), from (radius, 0, 0).
fn hermite_helix(radius: f64, pitch: f64, turns: f64) -> Edge {
    let n = (96.0 * turns).ceil() as usize;
    let exact = Exact {
        radius,
        rise: pitch / TAU,
    };
    let step = TAU * turns / n as f64;
    let segments = (0..n)
        .map(|i| {
            let (a, b) = (step * i as f64, step * (i + 1) as f64);
            let (p, q) = (exact.point(a), exact.point(b));
            let (dp, dq) = (exact.d1(a) * step / 3.0, exact.d1(b) * step / 3.0);
            crate::bezier::RationalBezierCurve::polynomial(&[p, p + dp, q - dq, q]).unwrap()
        })
        .collect();
    let breaks = (0..=n).map(|i| i as f64).collect();
    Edge::Curve(PiecewiseCurve::new(segments, breaks).unwrap())
}

/// The poles along the spine of every B-spline face of the model of more than one span
/// along v, where their interior knots there are all simple (the screw motion's faces);
/// `None` if a face has a multiple one (patches joined C⁰: the PH spline's).
fn smooth_faces(shape: &Shape) -> Option<Vec<usize>> {
    let mut poles = Vec::new();
    for face in &shape.brep().faces {
        let crate::model::BrepSurface::Nurbs(s) = &face.surface else {
            continue;
        };
        let knots = s.knots_v();
        let (first, last) = (knots[0], knots[knots.len() - 1]);
        let interior: Vec<f64> = knots
            .iter()
            .copied()
            .filter(|&k| k > first && k < last)
            .collect();
        if interior.is_empty() {
            continue; // one span: along a line or an arc
        }
        if interior.windows(2).any(|w| w[0] == w[1]) {
            return None;
        }
        assert_eq!(s.degree_v(), 7);
        poles.push(s.pole_count_v());
    }
    Some(poles)
}

fn frenet(tolerance: f64) -> WireSweep {
    WireSweep {
        frame: SweepFrame::Frenet,
        tolerance,
        ..WireSweep::default()
    }
}

/// A thread: an equilateral triangle (centred, corners at 0.5) swept along two turns of a
/// helix under its Frenet frame: on the exact screw sweep within the tolerance, the volume
/// area × length.
#[test]
fn a_thread_is_the_screw_sweep_of_its_profile() {
    let exact = THREAD;
    let corners = triangle_corners(|x, y| (x, y));
    for (name, edge, tolerance) in [
        ("PH spline", helix(3.0, 2.0, 2.0), 1e-5),
        ("cubic Hermite", hermite_helix(3.0, 2.0, 2.0), 1e-4),
        ("cubic Hermite", hermite_helix(3.0, 2.0, 2.0), 1e-5),
    ] {
        let shape = sweep(&[edge], &triangle(0.5), &[], &frenet(tolerance)).unwrap();
        assert!(shape.is_solid());
        crate::testing::assert_closed_oriented(shape.brep());
        // Two turns: sixteen spans of degree 7.
        let poles = smooth_faces(&shape).expect("the screw motion's faces");
        assert!(poles.iter().all(|&n| n == 16 + 7), "{poles:?}");
        let off = off_screw_sweep(&shape, &exact, &corners);
        let area = 0.75 * 3f64.sqrt() * 0.25;
        let want = area * exact.length(2.0);
        let v = volume(&shape);
        let error = (v - want).abs() / want;
        println!(
            "{name}, tolerance {tolerance:e}: off the screw sweep {off:.2e}, volume {v:.12} against \
             area × length {want:.12} ({error:.1e}), reported spine distance {:.1e}",
            shape.report().spine_distance
        );
        assert!(off <= tolerance, "{off:e}");
        assert!(shape.report().spine_distance <= tolerance);
        // The Frenet frame carries a centred profile's volume exactly: what is left is the
        // spine's distance from the helix.
        assert!(error < 10.0 * tolerance, "{error:e}");
    }
}

/// A thread under a fixed direction along the helix's axis (OpenCascade's binormal mode):
/// the Frenet frame turned a quarter turn (f₂ the binormal, f₃ = −N), so the screw motion
/// again — its faces lie in each normal plane on the profile placed in that frame; a
/// direction off the axis takes the PH spline.
#[test]
fn a_direction_along_the_axis_is_the_screw_motion_turned_by_a_constant() {
    let exact = THREAD;
    // x along f₂ = B, y along f₃ = −N.
    let corners = triangle_corners(|x, y| (-y, x));
    let fixed = |d: DVec3| WireSweep {
        frame: SweepFrame::Fixed(d),
        tolerance: 1e-5,
        ..WireSweep::default()
    };
    let edges = [hermite_helix(3.0, 2.0, 2.0)];
    let shape = sweep(&edges, &triangle(0.5), &[], &fixed(DVec3::Z)).unwrap();
    crate::testing::assert_closed_oriented(shape.brep());
    assert!(smooth_faces(&shape).is_some());
    let off = off_screw_sweep(&shape, &exact, &corners);
    println!(
        "fixed axis: off the screw sweep {off:.2e}, frame error {:.1e}",
        shape.report().frame_error
    );
    assert!(off <= 1e-5, "{off:e}");
    assert!(shape.report().frame_error < 1e-5);
    let tilted = sweep(
        &edges,
        &triangle(0.5),
        &[],
        &fixed(DVec3::new(0.3, 0.0, 1.0)),
    )
    .unwrap();
    assert!(smooth_faces(&tilted).is_none());
}

/// A pipe along five turns on the lightest frame: every point at the radius from the helix.
#[test]
fn a_pipe_along_a_helix_is_the_tube_about_it() {
    let exact = THREAD;
    let options = WireSweep {
        pipe_frame: PipeFrame::Lightest,
        tolerance: 1e-5,
        ..WireSweep::default()
    };
    let shape = sweep(&[helix(3.0, 2.0, 5.0)], &circle(0.4), &[], &options).unwrap();
    crate::testing::assert_closed_oriented(shape.brep());
    assert!(smooth_faces(&shape).is_some());
    let off = lateral_points(&shape)
        .into_iter()
        .map(|x| {
            let (n, b) = exact.in_normal_plane(x);
            (n.hypot(b) - 0.4).abs()
        })
        .fold(0.0, f64::max);
    let want = std::f64::consts::PI * 0.16 * exact.length(5.0);
    let error = (volume(&shape) - want).abs() / want;
    println!("off the tube {off:.2e}, volume against π r² L {error:.1e}");
    assert!(off <= 1e-5, "{off:e}");
    assert!(error < 1e-7, "{error:e}");
}

/// What the screw motion does not carry takes the PH spline: a conical spiral, a helix
/// under the RMF, a twisted Frenet frame, a scale law, a helix after a line.
#[test]
fn curves_and_frames_the_screw_motion_does_not_carry_take_the_ph_spline() {
    let spiral = {
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=192)
            .map(|i| {
                let t = TAU * 2.0 * i as f64 / 192.0;
                let (r, h) = (3.0 + 0.02 * t, 2.0 / TAU);
                (
                    DVec3::new(r * t.cos(), r * t.sin(), h * t),
                    DVec3::new(
                        0.02 * t.cos() - r * t.sin(),
                        0.02 * t.sin() + r * t.cos(),
                        h,
                    ),
                )
            })
            .unzip();
        let spline = crate::ph_cubic::ph_spline_hermite(&points, &tangents).unwrap();
        Edge::Curve(spline.into_curve())
    };
    let twisted = WireSweep {
        twist: 0.5,
        ..frenet(1e-5)
    };
    let scaled = WireSweep {
        scale: [1.0, 0.8],
        ..frenet(1e-5)
    };
    // Tangent to the helix at its start, (3, 0, 0) along (0, 3, 1/π).
    let lead_in = vec![
        super::tests::line([3.0, -3.0, -1.0 / std::f64::consts::PI], [3.0, 0.0, 0.0]),
        helix(3.0, 2.0, 1.0),
    ];
    let cases: [(&str, Vec<Edge>, WireSweep); 5] = [
        ("conical spiral", vec![spiral], frenet(1e-5)),
        ("RMF", vec![helix(3.0, 2.0, 1.0)], WireSweep::default()),
        ("twisted Frenet", vec![helix(3.0, 2.0, 1.0)], twisted),
        ("scale law", vec![helix(3.0, 2.0, 1.0)], scaled),
        ("after a line", lead_in, frenet(1e-5)),
    ];
    for (name, edges, options) in cases {
        let shape = sweep(&edges, &triangle(0.5), &[], &options).unwrap();
        assert!(smooth_faces(&shape).is_none(), "{name}");
    }
    let screw = sweep(&[helix(3.0, 2.0, 1.0)], &triangle(0.5), &[], &frenet(1e-5)).unwrap();
    assert!(smooth_faces(&screw).is_some());
}

/// A thread and a pipe along a helix are the same from 1e-200 to 1e200 of the unit wire,
/// moved by 300 times its size.
#[test]
fn helix_sweeps_are_the_same_from_1e_200_to_1e200() {
    use super::robustness_tests::check_similar;
    let pipe = WireSweep {
        pipe_frame: PipeFrame::Lightest,
        ..WireSweep::default()
    };
    for s in [1e-200, 1e-100, 1.0, 1e100, 1e200] {
        let o = DVec3::new(3e2, -1e2, 2e2) * s;
        check_similar(&[helix(3.0, 2.0, 1.5)], &triangle(0.5), &frenet(1e-5), s, o);
        check_similar(&[helix(3.0, 2.0, 1.5)], &circle(0.4), &pipe, s, o);
    }
}

/// A profile reaching past the helix's centre of curvature (1/κ = (r² + c²)/r ≈ 3.54 here,
/// half a turn of pitch 8) towards its axis folds the sweep: refused, naming the edge.
#[test]
fn a_profile_past_the_helixs_centre_of_curvature_is_refused() {
    let edges = [helix(3.0, 8.0, 0.5)];
    assert!(sweep(&edges, &triangle(3.4), &[], &frenet(1e-4)).is_ok());
    let e = sweep(&edges, &triangle(3.7), &[], &frenet(1e-4)).unwrap_err();
    println!("{e}");
    assert!(e.to_string().contains("edge 0"), "{e}");
    assert!(e.to_string().contains("fold"), "{e}");
}
