//! Analytic faces of wire sweeps: a circle swept along untwisted lines and arcs is handed
//! over as the cylinders and tori it is, with lines and circles for edges; faces that meet
//! a non-analytic edge (a miter's ellipse, a PH piece's section) stay NURBS.

use super::tests::{circle, line, pipe_route, square};
use super::*;
use crate::model::{AnalyticCurve, AnalyticSurface, Brep};
use crate::testing::{assert_closed_oriented, assert_similar_breps};
use glam::DVec3;

/// Faces that are (cylinders, tori, planes, cones) among the analytic faces, and the edges
/// that are analytic.
fn census(brep: &Brep) -> ([usize; 4], usize) {
    let mut kinds = [0; 4];
    for face in brep.faces.iter().filter_map(|f| f.analytic.as_ref()) {
        kinds[match face.surface {
            AnalyticSurface::Cylinder { .. } => 0,
            AnalyticSurface::Torus { .. } => 1,
            AnalyticSurface::Plane { .. } => 2,
            AnalyticSurface::Cone { .. } => 3,
        }] += 1;
    }
    let edges = brep.edges.iter().filter(|e| e.analytic.is_some()).count();
    (kinds, edges)
}

#[test]
fn a_circle_along_lines_and_an_arc_sweeps_cylinders_and_tori() {
    let shape = sweep(&pipe_route(), &circle(1.0), &[], &WireSweep::default()).unwrap();
    let brep = shape.brep();
    assert_closed_oriented(brep);
    // Two lines and an arc, four quarter circles joined on each: 2 cylinders, 1 torus; every
    // edge a line (the seams along the lines) or a circle (sections, the seam along the arc).
    assert_eq!(census(brep), ([2, 1, 0, 0], brep.edges.len()));
    assert_eq!(brep.faces.len(), 3 + 2);
    for face in brep.faces.iter().filter_map(|f| f.analytic.as_ref()) {
        match face.surface {
            AnalyticSurface::Cylinder { radius, .. } => assert!((radius - 1.0).abs() < 1e-14),
            AnalyticSurface::Torus { major, minor, .. } => {
                assert!((major - 5.0).abs() < 1e-13 && (minor - 1.0).abs() < 1e-14)
            }
            _ => unreachable!(),
        }
    }
    let circles = brep
        .edges
        .iter()
        .filter(|e| matches!(e.analytic.unwrap().curve, AnalyticCurve::Circle { .. }))
        .count();
    // Sections at 4 stations (4 each) and the seam along the arc.
    assert_eq!(circles, 4 * 4 + 1);
}

#[test]
fn a_ring_along_a_pipe_route_keeps_its_hole_analytic_and_off_centre_circles_sweep_tori() {
    let shape = sweep(
        &pipe_route(),
        &circle(1.0),
        &[circle(0.5)],
        &WireSweep::default(),
    )
    .unwrap();
    assert_closed_oriented(shape.brep());
    assert_eq!(census(shape.brep()).0, [4, 2, 0, 0]);
    // A hole drawn clockwise: its faces' NURBS normals face the other way, and so do their
    // loops on the cylinders and tori (a kernel takes them reversed).
    let clockwise = circle(0.5).reversed();
    let shape = sweep(
        &pipe_route(),
        &circle(1.0),
        &[clockwise],
        &WireSweep::default(),
    )
    .unwrap();
    assert_closed_oriented(shape.brep());
    let faces = &shape.brep().faces;
    let flipped = faces
        .iter()
        .filter(|f| {
            f.analytic
                .as_ref()
                .is_some_and(|a| a.loops_reversed(f.same_sense))
        })
        .count();
    assert_eq!((census(shape.brep()).0, flipped), ([4, 2, 0, 0], 3));
    // A circle off the spine, in the normal plane: still a cylinder along the lines and a
    // torus about the arc's axis (its centre 0.5 off the spine along the arc's normal).
    let off =
        crate::primitives::circle(DVec3::new(0.3, 0.5, 0.0), DVec3::X, DVec3::Y, 1.0).unwrap();
    let shape = sweep(&pipe_route(), &off, &[], &WireSweep::default()).unwrap();
    assert_closed_oriented(shape.brep());
    assert_eq!(census(shape.brep()).0, [2, 1, 0, 0]);
}

#[test]
fn a_polygon_along_lines_sweeps_planes_and_along_an_arc_cones_cylinders_and_annuli() {
    let shape = sweep(&pipe_route(), &square(1.0), &[], &WireSweep::default()).unwrap();
    assert_closed_oriented(shape.brep());
    // The lines' 8 faces are planes; about the arc's axis the square's sides along the
    // axis sweep cylinders, those across it annuli; every edge a line or circle.
    assert_eq!(
        census(shape.brep()),
        ([2, 0, 10, 0], shape.brep().edges.len())
    );
    // A square standing on a corner: its sides sweep cones about the arc's axis.
    let diamond = crate::primitives::polygon(&[
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(-1.0, 0.0, 0.0),
        DVec3::new(0.0, -1.0, 0.0),
    ])
    .unwrap();
    let shape = sweep(&pipe_route(), &diamond, &[], &WireSweep::default()).unwrap();
    assert_closed_oriented(shape.brep());
    assert_eq!(
        census(shape.brep()),
        ([0, 0, 8, 4], shape.brep().edges.len())
    );
    for face in shape
        .brep()
        .faces
        .iter()
        .filter_map(|f| f.analytic.as_ref())
    {
        if let AnalyticSurface::Cone { semi_angle, .. } = face.surface {
            let quarter = std::f64::consts::FRAC_PI_4;
            assert!((semi_angle.abs() - quarter).abs() < 1e-12, "{semi_angle}");
        }
    }
}

#[test]
fn faces_meeting_a_miter_or_a_curve_piece_stay_nurbs() {
    // Miter corners: every cylinder of this route ends on a miter plane (an ellipse).
    let route = [
        line([0., 0., 0.], [10., 0., 0.]),
        line([10., 0., 0.], [10., 10., 0.]),
        line([10., 10., 0.], [10., 10., 10.]),
    ];
    let miter = WireSweep {
        corner: Corner::Miter,
        ..WireSweep::default()
    };
    let shape = sweep(&route, &circle(1.0), &[], &miter).unwrap();
    assert_closed_oriented(shape.brep());
    let (kinds, edges) = census(shape.brep());
    assert_eq!(kinds, [0, 0, 0, 0]);
    assert_eq!(edges, 0);
    // Round corners on the same route: cylinders and the elbows' tori.
    let shape = sweep(&route, &circle(1.0), &[], &WireSweep::default()).unwrap();
    assert_closed_oriented(shape.brep());
    assert_eq!(census(shape.brep()).0, [3, 2, 0, 0]);
    // A line, then a cubic curve: the cylinder shares its end section with a PH face.
    let bend = crate::bezier::RationalBezierCurve::polynomial(&[
        DVec3::new(10.0, 0.0, 0.0),
        DVec3::new(15.0, 0.0, 0.0),
        DVec3::new(20.0, 5.0, 0.0),
        DVec3::new(20.0, 10.0, 0.0),
    ])
    .unwrap();
    let edges = [
        line([0., 0., 0.], [10., 0., 0.]),
        Edge::Curve(PiecewiseCurve::with_unit_intervals(vec![bend]).unwrap()),
    ];
    let shape = sweep(&edges, &circle(1.0), &[], &WireSweep::default()).unwrap();
    assert_closed_oriented(shape.brep());
    assert_eq!(census(shape.brep()), ([0, 0, 0, 0], 0));
}

#[test]
fn twisted_scaled_and_tilted_sweeps_stay_nurbs() {
    let twisted = WireSweep {
        twist: 1.0,
        ..WireSweep::default()
    };
    let shape = sweep(&pipe_route(), &circle(1.0), &[], &twisted).unwrap();
    assert_closed_oriented(shape.brep());
    assert_eq!(census(shape.brep()).0, [0, 0, 0, 0]);
}

#[test]
fn analytic_forms_are_invariant_under_scaling_and_translation() {
    let unit = sweep(
        &pipe_route(),
        &circle(1.0),
        &[circle(0.5)],
        &WireSweep::default(),
    )
    .unwrap();
    for (scale, shift) in [
        (1e-200, DVec3::new(3.0, -2.0, 1.0) * 1e-200),
        (1e200, DVec3::new(-1.0, 4.0, 2.0) * 1e200),
        (2f64.powi(300), DVec3::ZERO),
        (1.0, DVec3::new(3e6, 0.0, 0.0)),
        (1e-3, DVec3::new(0.0, 1e3, 0.0)),
    ] {
        let map = |p: &DVec3| *p * scale + shift;
        let edges: Vec<Edge> = pipe_route()
            .iter()
            .map(|e| match e {
                Edge::Line { from, to } => Edge::Line {
                    from: map(from),
                    to: map(to),
                },
                Edge::Arc {
                    start,
                    through,
                    end,
                } => Edge::Arc {
                    start: map(start),
                    through: map(through),
                    end: map(end),
                },
                Edge::Curve(_) => unreachable!(),
            })
            .collect();
        let shape = sweep(
            &edges,
            &circle(scale),
            &[circle(0.5 * scale)],
            &WireSweep::default(),
        )
        .unwrap();
        assert_similar_breps(unit.brep(), shape.brep(), scale, shift);
        assert_eq!(
            census(shape.brep()),
            census(unit.brep()),
            "scale {scale:e}, shift {shift}"
        );
        let text = shape.to_occ_brep().unwrap();
        assert!(text.contains("\n5 "), "a torus record at scale {scale:e}");
    }
}

#[test]
fn step_files_hold_the_analytic_surfaces_and_curves() {
    let pipe = sweep(&pipe_route(), &circle(1.0), &[], &WireSweep::default()).unwrap();
    let step = pipe.to_step("pipe").unwrap();
    let count = |entity: &str| step.matches(&format!(" = {entity}(")).count();
    assert_eq!(
        (
            count("CYLINDRICAL_SURFACE"),
            count("TOROIDAL_SURFACE"),
            count("PLANE")
        ),
        (2, 1, 2)
    );
    assert!(!step.contains("B_SPLINE_SURFACE") && !step.contains("PCURVE("));
    assert_eq!(count("CIRCLE"), 4 * 4 + 1);
    // A square on a corner about the arc: cones, their semi-angles positive (ISO 10303-42).
    let diamond = crate::primitives::polygon(&[
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(-1.0, 0.0, 0.0),
        DVec3::new(0.0, -1.0, 0.0),
    ])
    .unwrap();
    let duct = sweep(&pipe_route(), &diamond, &[], &WireSweep::default()).unwrap();
    let step = duct.to_step("duct").unwrap();
    let angles: Vec<f64> = step
        .lines()
        .filter(|l| l.contains(" = CONICAL_SURFACE("))
        .map(|l| {
            let inside = l.rsplit(',').next().unwrap().trim_end_matches(");");
            inside.parse().unwrap()
        })
        .collect();
    assert_eq!(angles.len(), 4);
    assert!(
        angles
            .iter()
            .all(|a| (a - std::f64::consts::FRAC_PI_4).abs() < 1e-12),
        "{angles:?}"
    );
}
