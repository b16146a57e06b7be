//! Faces built the way a kernel hands them over (NURBS surfaces, edges as NURBS curves,
//! loops of edge uses), unrolled and checked against closed forms: areas, outlines, holes,
//! marks both ways, invariance, refusals.

use super::develop::Development;
use super::kind::Recognized;
use super::*;
use crate::math::GaussLegendre;
use crate::model::{arc_through, circle, BrepBound, BrepEdge, BrepFace, BrepUse};
use crate::{Brep, BrepSurface, ErrorKind, NurbsCurve, NurbsSurface, PatternEdge};
use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

fn line(a: DVec3, b: DVec3) -> NurbsCurve {
    NurbsCurve::new(1, vec![a, b], None, vec![0.0, 0.0, 1.0, 1.0]).unwrap()
}

fn nurbs(c: crate::PiecewiseCurve) -> NurbsCurve {
    NurbsCurve::from_piecewise(&c).unwrap()
}

/// A B-rep of one face: its surface, its edges, its loops of (edge, forward) uses.
fn one_face(
    surface: BrepSurface,
    edges: Vec<NurbsCurve>,
    loops: Vec<(Vec<(usize, bool)>, bool)>,
) -> Brep {
    let mut vertices = Vec::new();
    let edges = edges
        .into_iter()
        .map(|curve| {
            let (a, b) = (curve.poles[0], *curve.poles.last().unwrap());
            vertices.extend([a, b]);
            BrepEdge {
                curve,
                start: vertices.len() - 2,
                end: vertices.len() - 1,
                degenerate: false,
                analytic: None,
            }
        })
        .collect();
    let bounds = loops
        .into_iter()
        .map(|(uses, outer)| BrepBound {
            uses: uses
                .into_iter()
                .map(|(edge, forward)| BrepUse {
                    edge,
                    forward,
                    pcurve: None,
                })
                .collect(),
            outer,
        })
        .collect();
    Brep {
        vertices,
        edges,
        faces: vec![BrepFace {
            surface: BrepSurface::Nurbs(surface_of(surface)),
            same_sense: true,
            bounds,
            analytic: None,
        }],
        closed: false,
    }
}

fn surface_of(s: BrepSurface) -> NurbsSurface {
    match s {
        BrepSurface::Nurbs(n) => n,
        BrepSurface::Plane { .. } => unreachable!("the tests hand over NURBS"),
    }
}

/// The ruled surface between two curves of the same degree, knots and weights.
fn ruled(a: &NurbsCurve, b: &NurbsCurve) -> BrepSurface {
    let m = a.poles.len();
    let poles = a.poles.iter().chain(&b.poles).copied().collect();
    let weights = a.weights.iter().chain(&b.weights).copied().collect();
    BrepSurface::Nurbs(
        NurbsSurface::new(
            1,
            a.degree,
            2,
            m,
            poles,
            Some(weights),
            vec![0.0, 0.0, 1.0, 1.0],
            a.knots.clone(),
        )
        .unwrap(),
    )
}

fn area(u: &UnfoldedFace) -> f64 {
    u.pattern().area().unwrap()
}

fn count(edges: &[PatternEdge]) -> (usize, usize) {
    let arcs = edges
        .iter()
        .filter(|e| matches!(e, PatternEdge::Arc { .. }))
        .count();
    (edges.len() - arcs, arcs)
}

/// A tilted plate 4 × 3 with a round hole of radius 0.5, as a bilinear NURBS.
fn plate(scale: f64, shift: DVec3) -> Brep {
    let (x, y) = (DVec3::new(1.0, 0.0, 1.0).normalize(), DVec3::Y);
    let p = |u: f64, v: f64| shift + scale * (u * x + v * y);
    let surface = BrepSurface::Nurbs(
        NurbsSurface::new(
            1,
            1,
            2,
            2,
            vec![p(-1.0, -1.0), p(-1.0, 4.0), p(5.0, -1.0), p(5.0, 4.0)],
            None,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap(),
    );
    let corners = [p(0.0, 0.0), p(4.0, 0.0), p(4.0, 3.0), p(0.0, 3.0)];
    let mut edges: Vec<NurbsCurve> = (0..4)
        .map(|k| line(corners[k], corners[(k + 1) % 4]))
        .collect();
    edges.push(nurbs(circle(p(1.0, 1.0), x, y, 0.5 * scale).unwrap()));
    one_face(
        surface,
        edges,
        vec![
            ((0..4).map(|k| (k, true)).collect(), true),
            (vec![(4, false)], false),
        ],
    )
}

#[test]
fn a_plate_with_a_round_hole_unrolls_to_its_area_with_lines_and_arcs() {
    let u = unfold_face(&plate(1.0, DVec3::ZERO), 0, &UnfoldOptions::new(1e-4)).unwrap();
    assert_eq!(u.report().kind, SurfaceKind::Plane);
    let expected = 12.0 - PI * 0.25;
    println!(
        "plate: area {} (exact {expected}), outline {:?}, hole {:?}",
        area(&u),
        count(&u.pattern().outline),
        count(&u.pattern().holes[0])
    );
    assert!((area(&u) - expected).abs() <= 1e-12 * expected);
    assert_eq!(count(&u.pattern().outline), (4, 0));
    assert_eq!(count(&u.pattern().holes[0]), (0, 2));
}

/// A cylinder patch of radius 2 over θ ∈ [0, 2], z ∈ [0, 3], with a window between the
/// parallel circles z = 1, 2 and the rulings θ = 0.5, 1.5.
fn cylinder_patch(scale: f64, shift: DVec3) -> Brep {
    let at =
        |theta: f64, z: f64| shift + scale * DVec3::new(2.0 * theta.cos(), 2.0 * theta.sin(), z);
    let arc = |t0: f64, t1: f64, z: f64| {
        nurbs(arc_through(at(t0, z), at(0.5 * (t0 + t1), z), at(t1, z)).unwrap())
    };
    let (bottom, top) = (arc(0.0, 2.0, 0.0), arc(0.0, 2.0, 3.0));
    let edges = vec![
        bottom.clone(),
        line(at(2.0, 0.0), at(2.0, 3.0)),
        top.clone(),
        line(at(0.0, 0.0), at(0.0, 3.0)),
        arc(0.5, 1.5, 1.0),
        line(at(1.5, 1.0), at(1.5, 2.0)),
        arc(0.5, 1.5, 2.0),
        line(at(0.5, 1.0), at(0.5, 2.0)),
    ];
    one_face(
        ruled(&bottom, &top),
        edges,
        vec![
            (vec![(0, true), (1, true), (2, false), (3, false)], true),
            (vec![(7, true), (6, true), (5, false), (4, false)], false),
        ],
    )
}

#[test]
fn a_cylinder_patch_with_a_window_unrolls_to_rectangles() {
    let u = unfold_face(
        &cylinder_patch(1.0, DVec3::ZERO),
        0,
        &UnfoldOptions::new(1e-4),
    )
    .unwrap();
    assert_eq!(u.report().kind, SurfaceKind::CircularCylinder);
    println!(
        "cylinder: area {} (exact 10), outline {:?}, hole {:?}",
        area(&u),
        count(&u.pattern().outline),
        count(&u.pattern().holes[0])
    );
    assert!((area(&u) - 10.0).abs() <= 1e-12 * 10.0);
    assert_eq!(count(&u.pattern().outline), (4, 0));
    assert_eq!(count(&u.pattern().holes[0]), (4, 0));
    assert!(u.pattern().bend_lines.is_empty());
}

#[test]
fn a_full_tube_is_cut_open_along_its_seam() {
    let at = |theta: f64, z: f64| DVec3::new(1.5 * theta.cos(), 1.5 * theta.sin(), z);
    let ring = |z: f64| nurbs(circle(DVec3::new(0.0, 0.0, z), DVec3::X, DVec3::Y, 1.5).unwrap());
    let (bottom, top) = (ring(0.0), ring(2.0));
    let brep = one_face(
        ruled(&bottom, &top),
        vec![
            bottom.clone(),
            top.clone(),
            line(at(0.0, 0.0), at(0.0, 2.0)),
        ],
        vec![(vec![(0, true), (2, true), (1, false), (2, false)], true)],
    );
    let u = unfold_face(&brep, 0, &UnfoldOptions::new(1e-4)).unwrap();
    let expected = TAU * 1.5 * 2.0;
    println!(
        "tube: area {} (exact {expected}), outline {:?}",
        area(&u),
        count(&u.pattern().outline)
    );
    assert!((area(&u) - expected).abs() <= 1e-12 * expected);
    assert_eq!(count(&u.pattern().outline), (6, 0));
}

/// A whole cone to its apex, as a kernel hands it over: the base circle, the seam from the
/// base to the apex used both ways, and the apex as a degenerate edge.
#[test]
fn a_whole_cone_is_cut_open_along_its_seam_to_its_apex() {
    let (radius, height) = (5.0f64, 8.0f64);
    let slant = radius.hypot(height);
    let apex = DVec3::new(0.0, 0.0, height);
    // The seam off the x axis: the apex, on the axis, has no angle of its own.
    let (x, y) = (DVec3::new(0.6, 0.8, 0.0), DVec3::new(-0.8, 0.6, 0.0));
    let base = nurbs(circle(DVec3::ZERO, x, y, radius).unwrap());
    // As OpenCascade converts a cone: the circle along u, the rulings along v.
    let surface = NurbsSurface::new(
        base.degree,
        1,
        base.poles.len(),
        2,
        base.poles.iter().flat_map(|&p| [p, apex]).collect(),
        Some(base.weights.iter().flat_map(|&w| [w, w]).collect()),
        base.knots.clone(),
        vec![0.0, 0.0, slant, slant],
    )
    .unwrap();
    // The edges meet a hair off the surface's apex, as a kernel's rounding leaves them:
    // an angle of their own, not the seam's.
    let tip = apex + 1e-13 * y;
    let mut brep = one_face(
        BrepSurface::Nurbs(surface),
        vec![base.clone(), line(radius * x, tip), line(tip, tip)],
        vec![(vec![(2, false), (1, false), (0, true), (1, true)], true)],
    );
    brep.edges[2].degenerate = true;
    let u = unfold_face(&brep, 0, &UnfoldOptions::new(1e-4)).unwrap();
    assert_eq!(u.report().kind, SurfaceKind::RightCone);
    let expected = PI * radius * radius.hypot(height);
    println!(
        "whole cone: area {} (exact {expected}), outline {:?}",
        area(&u),
        count(&u.pattern().outline)
    );
    assert!((area(&u) - expected).abs() <= 1e-12 * expected);
    assert_eq!(count(&u.pattern().outline), (2, 2));
    // The apex develops to one flat point from both sides of the cut: it is on the cut,
    // whatever angle round-off gives it (else a seam's sample there decided the seam's side
    // by a tie, and the seam zigzagged across the cut).
    let cone = Recognized::Cone {
        apex: DVec3::ZERO,
        axis: DVec3::Z,
        x: DVec3::X,
        sin: 0.5,
    };
    let development = Development::analytic(&cone, 1.0).unwrap();
    for p in [DVec3::ZERO, DVec3::new(3e-17, -4e-17, 0.0)] {
        assert!(development.flat(p).on_cut, "the apex {p} is not on the cut");
    }
    assert!(!development.flat(DVec3::new(0.5, 0.0, 1.0)).on_cut);
}

/// A frustum patch of the right cone with apex at the origin, axis z, half angle α
/// (tan α = 0.5), between the heights 1 and 3, over θ ∈ [0, 2.5].
fn cone_patch(scale: f64, shift: DVec3) -> Brep {
    let at = |theta: f64, z: f64| {
        shift + scale * DVec3::new(0.5 * z * theta.cos(), 0.5 * z * theta.sin(), z)
    };
    let arc = |z: f64| nurbs(arc_through(at(0.0, z), at(1.25, z), at(2.5, z)).unwrap());
    let (low, high) = (arc(1.0), arc(3.0));
    let edges = vec![
        low.clone(),
        line(at(2.5, 1.0), at(2.5, 3.0)),
        high.clone(),
        line(at(0.0, 1.0), at(0.0, 3.0)),
    ];
    one_face(
        ruled(&low, &high),
        edges,
        vec![(vec![(0, true), (1, true), (2, false), (3, false)], true)],
    )
}

#[test]
fn a_cone_patch_unrolls_to_an_annular_sector() {
    let u = unfold_face(&cone_patch(1.0, DVec3::ZERO), 0, &UnfoldOptions::new(1e-4)).unwrap();
    assert_eq!(u.report().kind, SurfaceKind::RightCone);
    let sin = 0.5 / 1.25f64.sqrt();
    let (r0, r1) = (1.25f64.sqrt(), 3.0 * 1.25f64.sqrt());
    let expected = 0.5 * 2.5 * sin * (r1 * r1 - r0 * r0);
    println!(
        "cone: area {} (exact {expected}), outline {:?}",
        area(&u),
        count(&u.pattern().outline)
    );
    assert!((area(&u) - expected).abs() <= 1e-12 * expected);
    assert_eq!(count(&u.pattern().outline), (2, 2));
}

#[test]
fn unrolled_faces_scale_and_move_with_the_face() {
    for make in [plate as fn(f64, DVec3) -> Brep, cylinder_patch, cone_patch] {
        let unit = unfold_face(&make(1.0, DVec3::ZERO), 0, &UnfoldOptions::new(1e-4)).unwrap();
        for scale in [1e-200, 1e-3, 1e200] {
            let shift = DVec3::new(3.0, -7.0, 11.0) * scale;
            let moved =
                unfold_face(&make(scale, shift), 0, &UnfoldOptions::new(1e-4 * scale)).unwrap();
            let (a, b) = (unit.pattern(), moved.pattern());
            assert_eq!(a.outline.len(), b.outline.len());
            if scale > 1e-100 && scale < 1e100 {
                let ratio = area(&moved) / area(&unit) / scale / scale;
                assert!(
                    (ratio - 1.0).abs() < 1e-12,
                    "area ratio {ratio} at scale {scale:e}"
                );
            }
            for (e, f) in a.outline.iter().zip(&b.outline) {
                assert!((f.length() / scale - e.length()).abs() <= 1e-12 * e.length().max(1.0));
            }
        }
    }
}

#[test]
fn marks_go_flat_to_formed_and_back_to_round_off() {
    for brep in [
        plate(1.0, DVec3::ZERO),
        cylinder_patch(1.0, DVec3::ZERO),
        cone_patch(1.0, DVec3::ZERO),
    ] {
        let u = unfold_face(&brep, 0, &UnfoldOptions::new(1e-4)).unwrap();
        let surface = match &brep.faces[0].surface {
            BrepSurface::Nurbs(n) => n.to_piecewise().unwrap(),
            _ => unreachable!(),
        };
        let mut worst: f64 = 0.0;
        for (s, t) in [(0.2, 0.3), (0.5, 0.5), (0.8, 0.9), (0.4, 0.15)] {
            let p = surface.eval(s, t);
            let q = u.to_flat(p, "p").unwrap();
            let back = u.to_formed(q, "q").unwrap();
            worst = worst.max(back.distance(p));
        }
        println!("{:?}: flat → formed → flat {worst:.1e}", u.report().kind);
        assert!(worst <= 1e-13);
    }
}

/// A cubic wave y = a sin-like curve, extruded 2 along z: a general cylinder.
fn wave(scale: f64, shift: DVec3) -> Brep {
    let p = |x: f64, y: f64, z: f64| shift + scale * DVec3::new(x, y, z);
    let poles = |z: f64| {
        vec![
            p(0.0, 0.0, z),
            p(1.0, 1.0, z),
            p(2.0, -1.0, z),
            p(3.0, 1.0, z),
            p(4.0, -1.0, z),
            p(5.0, 0.0, z),
        ]
    };
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0];
    let curve = |z: f64| NurbsCurve::new(3, poles(z), None, knots.clone()).unwrap();
    let (low, high) = (curve(0.0), curve(2.0));
    let edges = vec![
        low.clone(),
        line(p(5.0, 0.0, 0.0), p(5.0, 0.0, 2.0)),
        high.clone(),
        line(p(0.0, 0.0, 0.0), p(0.0, 0.0, 2.0)),
    ];
    one_face(
        ruled(&low, &high),
        edges,
        vec![(vec![(0, true), (1, true), (2, false), (3, false)], true)],
    )
}

fn curve_length(c: &NurbsCurve) -> f64 {
    let c = c.to_piecewise().unwrap();
    let (lo, hi) = c.domain();
    GaussLegendre::new(20).integrate_composite(lo, hi, 200, |t| c.eval_d1(t).1.length())
}

#[test]
fn a_wave_unrolls_through_its_cone_spline_to_length_times_height() {
    let brep = wave(1.0, DVec3::ZERO);
    let tolerance = 1e-5;
    let u = unfold_face(&brep, 0, &UnfoldOptions::new(tolerance));
    if let Err(e) = &u {
        println!("{e:?}");
    }
    let u = u.unwrap();
    assert_eq!(u.report().kind, SurfaceKind::GeneralCylinder);
    let length = curve_length(&brep.edges[0].curve);
    let expected = 2.0 * length;
    let error = (area(&u) - expected).abs() / expected;
    println!(
        "wave: area {} (length × height {expected}), relative {error:.1e}, fit {:.1e}, outline {:?}, {} bend lines",
        area(&u),
        u.fit_error(),
        count(&u.pattern().outline),
        u.pattern().bend_lines.len()
    );
    assert!(u.fit_error() <= tolerance);
    // The cone fit moves the boundary by at most the tolerance: area by ~ tolerance × outline.
    assert!(error <= 2.0 * tolerance * (2.0 * length + 4.0) / expected);
    assert!(!u.pattern().bend_lines.is_empty());
    // Bend lines run across the strip, from boundary to boundary: 2 long.
    for b in &u.pattern().bend_lines {
        assert!((b.length() - 2.0).abs() <= 1e-3, "bend line {}", b.length());
    }
    let p = brep.edges[0].curve.to_piecewise().unwrap().eval(1.3) + DVec3::new(0.0, 0.0, 0.7);
    let q = u.to_flat(p, "p").unwrap();
    assert!(u.to_formed(q, "q").unwrap().distance(p) <= 2.0 * tolerance);
}

#[test]
fn a_hyperbolic_paraboloid_is_reported_and_refused_with_its_stretch() {
    let surface = BrepSurface::Nurbs(
        NurbsSurface::new(
            1,
            1,
            2,
            2,
            vec![
                DVec3::ZERO,
                DVec3::new(0.0, 1.0, 0.0),
                DVec3::new(1.0, 0.0, 0.0),
                DVec3::new(1.0, 1.0, 0.4),
            ],
            None,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap(),
    );
    let s = surface_of(surface.clone()).to_piecewise().unwrap();
    let corners = [
        s.eval(0.0, 0.0),
        s.eval(1.0, 0.0),
        s.eval(1.0, 1.0),
        s.eval(0.0, 1.0),
    ];
    let brep = one_face(
        surface,
        (0..4)
            .map(|k| line(corners[k], corners[(k + 1) % 4]))
            .collect(),
        vec![((0..4).map(|k| (k, true)).collect(), true)],
    );
    let report = face_developability(&brep, 0).unwrap();
    println!("hypar: {report:?}");
    assert_eq!(report.kind, SurfaceKind::NotDevelopable);
    assert!(report.curvature > 0.01 && report.stretch > 1e-3 && report.stretch < 0.1);
    let e = unfold_face(&brep, 0, &UnfoldOptions::new(1e-4)).unwrap_err();
    assert!(
        e.is(ErrorKind::InvalidInput) && e.message().contains("not developable"),
        "{}",
        e.message()
    );
    // Flatter, less stretch: the measure follows the curvature.
    let flatter = {
        let mut b = brep.clone();
        if let BrepSurface::Nurbs(n) = &mut b.faces[0].surface {
            n.poles[3].z = 0.1;
        }
        face_developability(&b, 0).unwrap()
    };
    assert!(flatter.stretch < 0.5 * report.stretch, "{flatter:?}");
}

#[test]
fn bad_faces_are_refused_naming_them() {
    let good = plate(1.0, DVec3::ZERO);
    let options = UnfoldOptions::new(1e-4);
    let message = |b: &Brep, face: usize| unfold_face(b, face, &options).unwrap_err().message();
    assert!(message(&good, 1).contains("face = 1"));
    let mut open = good.clone();
    open.faces[0].bounds[0].uses.remove(2);
    assert!(
        message(&open, 0).contains("not closed"),
        "{}",
        message(&open, 0)
    );
    let mut nan = good.clone();
    nan.edges[1].curve.poles[0].x = f64::NAN;
    assert!(message(&nan, 0).contains("edge 1"));
    let mut no_outer = good.clone();
    no_outer.faces[0].bounds[0].outer = false;
    assert!(message(&no_outer, 0).contains("outer"));
    let bad = UnfoldOptions {
        tolerance: -1.0,
        ..options
    };
    assert!(unfold_face(&good, 0, &bad)
        .unwrap_err()
        .message()
        .contains("tolerance"));
    let u = unfold_face(&good, 0, &options).unwrap();
    assert!(u
        .to_flat(DVec3::NAN, "mark")
        .unwrap_err()
        .message()
        .contains("mark"));
    assert!(u.to_formed(DVec2::INFINITY, "q").is_err());
}
