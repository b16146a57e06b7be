//! End-to-end checks of wire sweeps: exact geometry on lines and arcs (distance from the
//! spine, orthogonal parameter lines), volumes against closed forms (divergence theorem by
//! Gauss–Legendre quadrature on the faces themselves), a closed and consistently oriented
//! B-rep (every edge used once in each direction), seamless closed wires, refusals.

use super::*;
use crate::bezier::{NurbsCurve, RationalBezierCurve};
use crate::testing::assert_closed_oriented;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// The circle of radius r (four rational quarters), centred.
pub(crate) fn circle(r: f64) -> PiecewiseCurve {
    crate::primitives::circle(DVec3::ZERO, DVec3::X, DVec3::Y, r).unwrap()
}

/// The square of half side a (corners on the axes' diagonals), counter-clockwise.
pub(crate) fn square(a: f64) -> PiecewiseCurve {
    let c = [(a, a), (-a, a), (-a, -a), (a, -a), (a, a)];
    let segments = c
        .windows(2)
        .map(|w| {
            RationalBezierCurve::polynomial(&[
                DVec3::new(w[0].0, w[0].1, 0.0),
                DVec3::new(w[1].0, w[1].1, 0.0),
            ])
            .unwrap()
        })
        .collect();
    PiecewiseCurve::with_unit_intervals(segments).unwrap()
}

pub(crate) fn line(a: [f64; 3], b: [f64; 3]) -> Edge {
    Edge::Line {
        from: DVec3::from(a),
        to: DVec3::from(b),
    }
}

/// A closed square wire of side 10 in the xy plane, corners sharp.
pub(crate) fn square_loop() -> [Edge; 4] {
    [
        line([0., 0., 0.], [10., 0., 0.]),
        line([10., 0., 0.], [10., 10., 0.]),
        line([10., 10., 0.], [0., 10., 0.]),
        line([0., 10., 0.], [0., 0., 0.]),
    ]
}

/// An equilateral triangle with its corners on the circle of radius r, the first on +x.
pub(crate) fn triangle(r: f64) -> PiecewiseCurve {
    let corner = |k: f64| {
        let a = std::f64::consts::TAU * k / 3.0;
        DVec3::new(r * a.cos(), r * a.sin(), 0.0)
    };
    crate::primitives::polygon(&[corner(0.0), corner(1.0), corner(2.0)]).unwrap()
}

/// π r² ∫σ² ds over a length l where σ runs linearly from a to b: a frustum of the circle of
/// radius r scaled from a to b.
pub(crate) fn frustum(r: f64, l: f64, a: f64, b: f64) -> f64 {
    std::f64::consts::PI * r * r * l * (a * a + a * b + b * b) / 3.0
}

/// The largest distance of a sweep's lateral faces (on a 9 × 9 grid) from the circle about
/// the z axis of radius `radius(z)` at their height.
pub(crate) fn off_circles(shape: &Shape, radius: impl Fn(f64) -> f64) -> f64 {
    let mut worst = 0.0f64;
    for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
        let s = face.surface.as_ref().unwrap();
        let ((u0, u1), (v0, v1)) = (s.domain_u(), s.domain_v());
        for i in 0..=8 {
            for j in 0..=8 {
                let p = s.eval(
                    u0 + (u1 - u0) * i as f64 / 8.0,
                    v0 + (v1 - v0) * j as f64 / 8.0,
                );
                worst = worst.max((p.truncate().length() - radius(p.z)).abs());
            }
        }
    }
    worst
}

/// Line – tangent quarter arc (radius 5) – line, as a pipe route.
pub(crate) fn pipe_route() -> Vec<Edge> {
    let s = FRAC_1_SQRT_2;
    vec![
        line([0., 0., 0.], [10., 0., 0.]),
        Edge::Arc {
            start: DVec3::new(10., 0., 0.),
            through: DVec3::new(10. + 5. * s, 5. - 5. * s, 0.),
            end: DVec3::new(15., 5., 0.),
        },
        line([15., 5., 0.], [15., 15., 0.]),
    ]
}

/// The enclosed volume of a solid.
pub(crate) fn volume(shape: &Shape) -> f64 {
    shape.volume().expect("a solid")
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn a_pipe_route_of_lines_and_an_arc_is_an_exact_solid() {
    let options = WireSweep::default();
    let shape = sweep(&pipe_route(), &circle(1.0), &[], &options).unwrap();
    assert!(shape.is_solid());
    assert_eq!(
        shape.faces().len(),
        14,
        "three lateral faces per quarter of the circle and two caps"
    );
    assert_closed_oriented(shape.brep());
    let length = 20.0 + 2.5 * PI;
    let v = volume(&shape);
    println!(
        "line–arc–line pipe, r = 1: volume {v:.15} against π r² L = {:.15}, relative error {:.1e}; \
         max |cos| between parameter lines {:.1e}",
        PI * length,
        relative(v, PI * length),
        shape.report().max_parameter_cosine
    );
    assert!(relative(v, PI * length) < 1e-12);
    assert!(shape.report().max_parameter_cosine < 1e-12);
    assert_eq!(shape.report().spine_distance, 0.0);
    assert!(
        shape.report().joint_gap < 1e-14,
        "{}",
        shape.report().joint_gap
    );
    // Exact: every point of the lateral faces is at distance 1 from the spine.
    let torus = shape.faces()[4].surface.as_ref().unwrap();
    assert_eq!(
        torus.patches()[0].degree_v(),
        2,
        "rational degree 2 along the arc"
    );
    for i in 0..=8 {
        for j in 0..=8 {
            let p = torus.eval(i as f64 / 8.0, j as f64 / 8.0);
            let radial = ((p.truncate() - glam::DVec2::new(10., 5.)).length() - 5.0).hypot(p.z);
            assert!((radial - 1.0).abs() < 1e-14, "{radial}");
        }
    }
    let step = shape.to_step("pipe").unwrap();
    assert!(step.contains("MANIFOLD_SOLID_BREP") && step.contains("CLOSED_SHELL"));
    // One cylinder per line and one torus along the arc (the circle's four quarters joined
    // on each), two caps.
    assert_eq!(step.matches("ADVANCED_FACE(").count(), 5);
    assert!(step.contains("PLANE("));
}

/// The issue's pipe route: its arc is given through a point rounded to 4 decimals, which
/// leaves corners of 1e-5 rad at the arc's ends; both corner modes sweep it: round corners
/// with tiny exact elbows, miters with the lines cut by the arc's normal planes there
/// (near-tangent joints).
#[test]
fn the_issues_rounded_pipe_route_sweeps_with_round_and_miter_corners() {
    let edges = vec![
        line([0., 0., 0.], [10., 0., 0.]),
        Edge::Arc {
            start: DVec3::new(10., 0., 0.),
            through: DVec3::new(13.5355, 1.4645, 0.),
            end: DVec3::new(15., 5., 0.),
        },
        line([15., 5., 0.], [15., 15., 0.]),
    ];
    for corner in [Corner::Miter, Corner::Round(Some(2.0))] {
        let options = WireSweep {
            corner,
            ..WireSweep::default()
        };
        let shape = sweep(&edges, &circle(1.0), &[], &options).unwrap();
        assert_closed_oriented(shape.brep());
        let r = shape.report();
        println!(
            "issue's route, {corner:?}: joint gap {:.1e}, faces {}, max |cos| {:.1e}",
            r.joint_gap, r.face_count, r.max_parameter_cosine
        );
        assert!(r.joint_gap < 1e-9, "{}", r.joint_gap);
        let elbows = if corner == Corner::Miter { 0 } else { 2 };
        assert_eq!(r.face_count, 14 + 4 * elbows, "elbows of round corners");
    }
}

#[test]
fn a_hollow_pipe_has_holes_and_the_volume_of_the_annulus() {
    let shape = sweep(
        &pipe_route(),
        &circle(1.0),
        &[circle(0.8)],
        &WireSweep::default(),
    )
    .unwrap();
    assert_eq!(shape.faces().len(), 26);
    assert_closed_oriented(shape.brep());
    let expected = PI * (1.0 - 0.64) * (20.0 + 2.5 * PI);
    assert!(relative(volume(&shape), expected) < 1e-12);
    // Holes turn clockwise about the cap's outward normal: the cap's loops cancel.
    let cap = shape
        .faces()
        .iter()
        .find(|f| f.kind == FaceKind::Plane)
        .unwrap();
    assert_eq!(cap.loops.len(), 2);
}

/// A polyline with three right angles, each leg 6 long, in 3-D.
fn staircase() -> Vec<Edge> {
    vec![
        line([0., 0., 0.], [6., 0., 0.]),
        line([6., 0., 0.], [6., 6., 0.]),
        line([6., 6., 0.], [6., 6., 6.]),
        line([6., 6., 6.], [0., 6., 6.]),
    ]
}

#[test]
fn round_and_miter_corners_give_solids_with_the_closed_form_volume() {
    let area = 4.0 * 0.25; // square of half side 0.5
    for (corner, expected_length) in [
        (Corner::Miter, 24.0),
        // Each corner cuts 2ρ of straight leg and adds the quarter circle ρπ/2.
        (Corner::Round(Some(1.0)), 24.0 - 3.0 * (2.0 - PI / 2.0)),
    ] {
        let options = WireSweep {
            corner,
            ..WireSweep::default()
        };
        let shape = sweep(&staircase(), &square(0.5), &[], &options).unwrap();
        assert_closed_oriented(shape.brep());
        let v = volume(&shape);
        let turn = shape.report().corner_turn;
        println!(
            "polyline with three 90° corners, {corner:?}: volume {v:.15} against {:.15} \
             (relative {:.1e}), frame turn across the corners {turn:.1e} rad",
            area * expected_length,
            relative(v, area * expected_length)
        );
        assert!(relative(v, area * expected_length) < 1e-12);
        assert!(turn < 1e-12, "{turn}");
    }
}

#[test]
fn a_rounded_rectangle_closes_without_a_seam() {
    let s = FRAC_1_SQRT_2;
    let arc = |c: (f64, f64), a: f64| {
        let p = |t: f64| DVec3::new(c.0 + t.cos(), c.1 + t.sin(), 0.0);
        Edge::Arc {
            start: p(a),
            through: p(a + PI / 4.0),
            end: p(a + PI / 2.0),
        }
    };
    let _ = s;
    let edges = vec![
        line([0., -1., 0.], [4., -1., 0.]),
        arc((4., 0.), -PI / 2.0),
        line([5., 0., 0.], [5., 2., 0.]),
        arc((4., 2.), 0.0),
        line([4., 3., 0.], [0., 3., 0.]),
        arc((0., 2.), PI / 2.0),
        line([-1., 2., 0.], [-1., 0., 0.]),
        arc((0., 0.), PI),
    ];
    let shape = sweep(&edges, &square(0.2), &[], &WireSweep::default()).unwrap();
    assert!(shape.is_solid());
    assert_eq!(shape.faces().len(), 32, "no caps");
    assert_closed_oriented(shape.brep());
    let length = 2.0 * (4.0 + 2.0) + 2.0 * PI;
    let v = volume(&shape);
    let gap = shape.report().seam_gap;
    println!(
        "rounded rectangle, square profile: seam gap {gap:.1e}, volume relative error {:.1e}",
        relative(v, 0.16 * length)
    );
    assert!(gap <= 1e-12);
    assert!(relative(v, 0.16 * length) < 1e-12);
}

/// A ring swept round a closed wire bounds a solid with a cavity: the outer wall and the
/// cavity's wall are two closed shells of one solid, written as such to OpenCascade's text
/// (one `So` of two `Sh`) and to STEP (`BREP_WITH_VOIDS`).
#[test]
fn a_ring_swept_round_a_closed_wire_is_a_solid_with_a_cavity() {
    let edges = vec![
        line([0., 0., 0.], [20., 0., 0.]),
        line([20., 0., 0.], [20., 20., 0.]),
        line([20., 20., 0.], [0., 20., 0.]),
        line([0., 20., 0.], [0., 0., 0.]),
    ];
    let shape = sweep(&edges, &circle(2.0), &[circle(1.0)], &WireSweep::default()).unwrap();
    assert!(shape.is_solid());
    assert_closed_oriented(shape.brep());
    let shells = shape.brep().shells();
    assert_eq!(shells.len(), 2);
    // Each piece's circle is one analytic face of the B-rep: 8 pieces, 2 loops.
    assert_eq!(shells[0].len() + shells[1].len(), 16);
    assert_eq!(shape.brep().faces.len(), 16);
    let r = 3.0; // the corners' radius: 1.5 times the profile's
    let length = 80.0 - 4.0 * (2.0 * r - r * PI / 2.0);
    assert!(relative(volume(&shape), 3.0 * PI * length) < 1e-12);
    let occ = shape.to_occ_brep().unwrap();
    assert_eq!(occ.matches("\nSh\n").count(), 2);
    assert_eq!(occ.matches("\nSo\n").count(), 1);
    let step = shape.to_step("ring").unwrap();
    assert_eq!(step.matches("BREP_WITH_VOIDS(").count(), 1);
    assert_eq!(step.matches("ORIENTED_CLOSED_SHELL(").count(), 1);
    assert_eq!(step.matches("CLOSED_SHELL(").count(), 3);
}

/// A closed, non-planar NURBS (a periodic cubic through a bent loop, made clamped by knot
/// insertion at the seam).
pub(crate) fn closed_nurbs() -> PiecewiseCurve {
    // Uniform cubic B-spline, periodic: poles wrap around.
    let p: Vec<DVec3> = (0..8)
        .map(|k| {
            let a = 2.0 * PI * k as f64 / 8.0;
            DVec3::new(4.0 * a.cos(), 3.0 * a.sin(), 1.5 * (2.0 * a).sin())
        })
        .collect();
    // Each uniform span as a Bézier segment (B-spline to Bézier for uniform cubics).
    let segments = (0..8)
        .map(|k| {
            let (a, b, c, d) = (p[k], p[(k + 1) % 8], p[(k + 2) % 8], p[(k + 3) % 8]);
            RationalBezierCurve::polynomial(&[
                (a + 4.0 * b + c) / 6.0,
                (2.0 * b + c) / 3.0,
                (b + 2.0 * c) / 3.0,
                (b + 4.0 * c + d) / 6.0,
            ])
            .unwrap()
        })
        .collect();
    PiecewiseCurve::with_unit_intervals(segments).unwrap()
}

#[test]
fn a_closed_nurbs_closes_modulo_the_profile_symmetry() {
    let curve = closed_nurbs();
    let _ = NurbsCurve::from_piecewise(&curve).unwrap();
    for k in [1, 4] {
        let options = WireSweep {
            tolerance: 1e-5,
            closure_symmetry: k,
            ..WireSweep::default()
        };
        let shape = sweep(&[Edge::Curve(curve.clone())], &square(0.3), &[], &options).unwrap();
        assert!(shape.is_solid());
        assert_closed_oriented(shape.brep());
        let r = shape.report();
        println!(
            "closed NURBS, square profile, closure modulo 2π/{k}: seam gap {:.1e}, spine within \
             {:.1e}, RMF within {:.1e} rad, max |cos| {:.1e}",
            r.seam_gap, r.spine_distance, r.rmf_angle_error, r.max_parameter_cosine
        );
        assert!(r.seam_gap <= 1e-12, "{}", r.seam_gap);
        assert!(r.spine_distance <= 1e-5);
        // The closure turn (≤ π/k) is a twist: the parameter lines are not orthogonal.
        assert!(r.rmf_angle_error <= 1e-6);
    }
}

#[test]
fn bad_wires_and_profiles_are_refused_naming_the_edge_or_joint() {
    let d = WireSweep::default();
    let message =
        |edges: &[Edge], profile: &PiecewiseCurve, holes: &[PiecewiseCurve], o: &WireSweep| {
            sweep(edges, profile, holes, o).unwrap_err().message()
        };
    let gap = [
        line([0., 0., 0.], [1., 0., 0.]),
        line([1., 0.1, 0.], [2., 0., 0.]),
    ];
    assert!(message(&gap, &circle(0.1), &[], &d).contains("edges 0 and 1 do not meet"));
    let zero = [
        line([0., 0., 0.], [1., 0., 0.]),
        line([1., 0., 0.], [1., 0., 0.]),
    ];
    let m = message(&zero, &circle(0.1), &[], &d);
    assert!(m.contains("edge 1: a line of zero length"), "{m}");
    let back = [
        line([0., 0., 0.], [1., 0., 0.]),
        line([1., 0., 0.], [0.2, 0., 0.]),
    ];
    assert!(message(&back, &circle(0.1), &[], &d).contains("turns back"));
    let open = square(0.5).segments()[..3].to_vec();
    let open = PiecewiseCurve::with_unit_intervals(open).unwrap();
    assert!(message(&staircase(), &open, &[], &d).contains("closed profile"));
    let sheet = WireSweep {
        solid: false,
        ..d.clone()
    };
    let shape = sweep(&staircase(), &open, &[], &sheet).unwrap();
    assert!(!shape.is_solid() && shape.faces().iter().all(|f| f.kind == FaceKind::Swept));
    assert!(message(&staircase(), &open, &[circle(0.1)], &sheet).contains("holes need a closed"));
    let big = WireSweep {
        corner: Corner::Round(Some(4.0)),
        ..d.clone()
    };
    let m = message(&staircase(), &square(0.5), &[], &big);
    assert!(
        m.contains("does not fit")
            && m.contains("the largest radius that fits every corner is 2.99999999"),
        "{m}"
    );
    let small = WireSweep {
        corner: Corner::Round(Some(0.4)),
        ..d.clone()
    };
    let m = message(&staircase(), &square(0.5), &[], &small);
    assert!(
        m.contains("joint between edges 0 and 1")
            && m.contains("smallest radius allowed is 0.7071067"),
        "{m}"
    );
    // The default radius of a profile of 1e-34 at corners of size 1: rounding (an arc of
    // that radius has NaN control points).
    let default = WireSweep {
        corner: Corner::Round(None),
        ..d.clone()
    };
    let m = message(&staircase(), &circle(1e-34), &[], &default);
    assert!(
        m.contains("corner radius") && m.contains("is rounding"),
        "{m}"
    );
    // An arc of radius 5 and a profile reaching 6 towards its centre.
    let m = message(&pipe_route(), &circle(6.0), &[], &d);
    assert!(m.contains("edge 1") && m.contains("at most 4.99999"), "{m}");
    let miter = WireSweep {
        corner: Corner::Miter,
        ..d.clone()
    };
    let m = message(&staircase(), &square(5.0), &[], &miter);
    assert!(m.contains("miter cuts"), "{m}");
}

#[test]
fn results_do_not_depend_on_scale_or_position() {
    let options = WireSweep {
        corner: Corner::Round(Some(1.0)),
        ..WireSweep::default()
    };
    let unit = sweep(&staircase(), &square(0.5), &[], &options).unwrap();
    for (scale, shift) in [
        (1e-200, DVec3::ZERO),
        (1e200, DVec3::ZERO),
        (1.0, DVec3::new(1e6, -3e6, 7.0)),
        (2f64.powi(300), DVec3::ZERO),
    ] {
        let moved: Vec<Edge> = staircase()
            .iter()
            .map(|e| match e {
                Edge::Line { from, to } => Edge::Line {
                    from: *from * scale + shift,
                    to: *to * scale + shift,
                },
                _ => unreachable!(),
            })
            .collect();
        let profile = square(0.5).similar(scale, DVec3::ZERO);
        let o = WireSweep {
            corner: Corner::Round(Some(scale)),
            ..options.clone()
        };
        let shape = sweep(&moved, &profile, &[], &o).unwrap();
        crate::testing::assert_similar_breps(unit.brep(), shape.brep(), scale, shift);
        assert_eq!(shape.faces().len(), unit.faces().len());
        for (a, b) in unit.faces().iter().zip(shape.faces()) {
            let (Some(sa), Some(sb)) = (&a.surface, &b.surface) else {
                continue;
            };
            for u in [0.0, 0.3, 0.7] {
                for v in [0.0, 0.5, 1.0] {
                    let (pa, pb) = (sa.eval(u, v), (sb.eval(u, v) - shift) / scale);
                    assert!(pa.distance(pb) < 1e-9, "scale {scale:e}: {pa} vs {pb}");
                }
            }
        }
    }
}

/// A twist turns the frames along lines and arcs too (rational, the biquadratic W fitted to
/// the linear turn): still a closed solid, the faces meeting at every joint, the frame
/// within 1e-6 rad of the RMF turned linearly in arc length, and the volume unchanged.
#[test]
fn a_twist_turns_the_frame_along_lines_and_arcs_and_keeps_the_solid() {
    let options = WireSweep {
        corner: Corner::Round(Some(1.0)),
        twist: 1.5,
        ..WireSweep::default()
    };
    let shape = sweep(&staircase(), &square(0.5), &[], &options).unwrap();
    assert_closed_oriented(shape.brep());
    let r = shape.report();
    println!(
        "staircase with a twist of 1.5 rad: frames within {:.1e} rad of the twisted RMF, joint gap {:.1e}, \
         max |cos| {:.1e}",
        r.rmf_angle_error, r.joint_gap, r.max_parameter_cosine
    );
    assert!(r.rmf_angle_error < 1e-9, "{}", r.rmf_angle_error);
    assert!(r.joint_gap < 1e-12, "{}", r.joint_gap);
    assert!(
        r.max_parameter_cosine > 1e-3,
        "a twist tilts the parameter lines"
    );
    let length = 24.0 - 3.0 * (2.0 - PI / 2.0);
    assert!(
        relative(volume(&shape), length) < 1e-9,
        "{}",
        volume(&shape)
    );
    // The frame turns by the twist in all: the end section is the untwisted one turned.
    let plain = sweep(
        &staircase(),
        &square(0.5),
        &[],
        &WireSweep {
            twist: 0.0,
            ..options
        },
    )
    .unwrap();
    let end = |s: &Shape| {
        let f = &s.faces()[s.faces().len() - 3 - 3];
        let surface = f.surface.as_ref().unwrap();
        surface.eval(surface.domain_u().0, surface.domain_v().1)
    };
    let centre = DVec3::new(0.0, 6.0, 6.0);
    let (a, b) = (end(&plain) - centre, end(&shape) - centre);
    let turn = a.cross(b).dot(DVec3::X).atan2(a.dot(b));
    assert!((turn.abs() - 1.5).abs() < 1e-9, "{turn}");
}

/// A closed polyline in 3-D: its discrete RMF comes back turned (the holonomy), and the
/// closure spreads the smallest turn over the lines and elbows, rational there.
#[test]
fn a_closed_3d_polyline_closes_by_a_turn_spread_over_lines_and_elbows() {
    let points = [
        [0., 0., 0.],
        [6., 0., 0.],
        [6., 5., 2.],
        [1., 6., 6.],
        [0., 0., 0.],
    ];
    let edges: Vec<Edge> = points.windows(2).map(|w| line(w[0], w[1])).collect();
    let options = WireSweep {
        corner: Corner::Round(Some(1.0)),
        ..WireSweep::default()
    };
    let shape = sweep(&edges, &circle(0.3), &[], &options).unwrap();
    assert!(shape.is_solid());
    assert_closed_oriented(shape.brep());
    let r = shape.report();
    println!(
        "closed 3-D polyline, circle: seam gap {:.1e}, frames within {:.1e} rad of the turned RMF",
        r.seam_gap, r.rmf_angle_error
    );
    assert!(r.seam_gap < 1e-12, "{}", r.seam_gap);
    assert!(r.rmf_angle_error < 1e-9, "{}", r.rmf_angle_error);
    assert!(
        r.max_parameter_cosine > 1e-6,
        "the closure turn tilts the parameter lines"
    );
    // A miter polyline cannot turn at all: refused, unless the turn is a symmetry.
    let miter = WireSweep {
        corner: Corner::Miter,
        ..options
    };
    let e = sweep(&edges, &circle(0.3), &[], &miter).unwrap_err();
    assert!(e.message().contains("every edge is a miter leg"), "{e}");
}

/// A PH cubic spline given as an edge is swept along as it is (distance 0), with its
/// rational RMF.
#[test]
fn a_ph_spline_edge_is_used_as_it_is() {
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=4)
        .map(|i| {
            let t = 0.5 * i as f64;
            (
                DVec3::new(3.0 * t.cos(), 3.0 * t.sin(), t),
                DVec3::new(-3.0 * t.sin(), 3.0 * t.cos(), 1.0),
            )
        })
        .unzip();
    let spline = crate::ph_cubic::ph_spline_hermite(&points, &tangents)
        .unwrap()
        .into_curve();
    let shape = sweep(
        &[Edge::Curve(spline.clone())],
        &circle(0.2),
        &[],
        &WireSweep::default(),
    )
    .unwrap();
    assert_eq!(shape.report().spine_distance, 0.0);
    assert_eq!(shape.spine()[0].segments().len(), spline.segments().len());
    assert!(shape.report().max_parameter_cosine < 1e-5);
}

/// A circle of subnormal radius (6e-313) as the only edge makes the wire's size subnormal,
/// its scale 2⁻¹⁰³⁶ and 1/scale infinite (NaN control points): sizes outside
/// [1e-290, 1e290] are refused.
#[test]
fn wires_of_subnormal_or_huge_size_are_refused() {
    let tiny = circle(1.0).similar(6.25e-313, DVec3::ZERO);
    let e = sweep(
        &[Edge::Curve(tiny)],
        &circle(1e-313),
        &[],
        &WireSweep::default(),
    )
    .unwrap_err();
    assert!(e.message().contains("outside [1e-290, 1e290]"), "{e}");
    let huge = [line([0., 0., 0.], [1e300, 0., 0.])];
    assert!(sweep(&huge, &circle(1e299), &[], &WireSweep::default()).is_err());
    let out_of_proportion = [line([0., 0., 0.], [1e-200, 0., 0.])];
    let e = sweep(
        &out_of_proportion,
        &circle(1e200),
        &[],
        &WireSweep::default(),
    )
    .unwrap_err();
    assert!(
        e.message()
            .contains("profile: its coordinates are out of proportion"),
        "{e}"
    );
}

/// The singularity margin along a curve edge is that of the whole profile, holes and all
/// (Cor. 7: g = 1 − κ h(n), h the profile's extent towards the centre of curvature): an
/// off-centre circle along a planar curve, the reported margin against κ_max of the PH
/// spline swept along, on either side of the spine; past the centre of curvature refused.
#[test]
fn the_singularity_margin_along_a_curve_is_the_whole_profiles() {
    let bend = RationalBezierCurve::polynomial(&[
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(10.0, 0.0, 0.0),
        DVec3::new(20.0, 10.0, 0.0),
        DVec3::new(20.0, 20.0, 0.0),
    ])
    .unwrap();
    let edges = [Edge::Curve(
        PiecewiseCurve::with_unit_intervals(vec![bend]).unwrap(),
    )];
    let options = WireSweep {
        initial_normal: Some(DVec3::Z),
        ..WireSweep::default()
    };
    let (r, d) = (0.3, 0.1);
    let off = |y: f64, radius: f64| {
        crate::primitives::circle(DVec3::new(0.0, y, 0.0), DVec3::X, DVec3::Y, radius).unwrap()
    };
    let toward = |y: f64, holes: &[PiecewiseCurve]| {
        sweep(&edges, &off(y, r), holes, &options).map(|s| {
            let spine = &s.spine()[0];
            let (lo, hi) = spine.domain();
            let kappa = (0..=20_000)
                .map(|i| {
                    let jet = spine.eval_jet(lo + (hi - lo) * i as f64 / 20_000.0);
                    jet.d1.cross(jet.d2).length() / jet.d1.length().powi(3)
                })
                .fold(0.0, f64::max);
            (s.report().singularity_margin, kappa)
        })
    };
    let (a, kappa) = toward(d, &[]).unwrap();
    let (b, _) = toward(-d, &[]).unwrap();
    let (inner, outer) = (a.min(b), a.max(b));
    assert!(
        (inner - (1.0 - kappa * (r + d))).abs() < 1e-6
            && (outer - (1.0 - kappa * (r - d))).abs() < 1e-6,
        "margins {a}, {b}; κ_max {kappa}"
    );
    // A hole reaches less far than the outer loop: the same margin.
    let side = if a < b { d } else { -d };
    let (with_hole, _) = toward(side, &[off(side, 0.1)]).unwrap();
    assert!((with_hole - inner).abs() < 1e-12, "{with_hole} vs {inner}");
    // Far out on the outer side: the bound 1 − κ_max·max‖c‖ < 0 says nothing, the margin
    // is measured while building: g > 1 everywhere, and the report gives at most 1.
    let (far, _) = toward(-side * (1.5 / kappa) / d, &[]).unwrap();
    assert_eq!(far, 1.0);
    // Past the centre of curvature (1/κ_max ≈ {1/kappa}) on the inner side: refused.
    let e = toward(side * (1.2 / kappa) / d, &[]).unwrap_err();
    assert!(
        e.message()
            .contains("edge 0: the profile reaches past the spine's centre"),
        "{e}"
    );
}
