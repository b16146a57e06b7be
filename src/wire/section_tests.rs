//! Sweeps through sections (`sweep_through`) against closed forms: circles through
//! three radii along a line are a chain of exact frustums; a square → circle → triangle
//! keeps its station's circle as a shared section (its edges on the circle, the faces on
//! both sides meeting there) and its volume is Simpson's rule per interval; the pipe
//! route (arcs within the tolerance); the refusals; invariance under scaling and
//! translation.

use super::tests::{
    circle, frustum, line, off_circles, pipe_route, square, square_loop, triangle, volume,
};
use super::*;

fn at(at: f64, profile: &PiecewiseCurve) -> Section<'_> {
    Section {
        at,
        profile,
        holes: &[],
    }
}

#[test]
fn circles_through_three_radii_along_a_line_are_exact_frustums() {
    let bar = [line([0., 0., 0.], [0., 0., 4.])];
    let (c0, c1, c2) = (circle(0.5), circle(1.0), circle(0.3));
    let sections = [at(0.0, &c0), at(0.25, &c1), at(1.0, &c2)];
    let shape = sweep_through(&bar, &sections, &WireSweep::default()).unwrap();
    assert!(shape.is_solid());
    crate::testing::assert_closed_oriented(shape.brep());
    let want = frustum(1.0, 1.0, 0.5, 1.0) + frustum(1.0, 3.0, 1.0, 0.3);
    let v = volume(&shape);
    println!("circles 0.5 → 1 (at 1/4) → 0.3 along a line of 4: volume {v:.15} against {want:.15}");
    assert!((v - want).abs() < 1e-12 * want, "{v} against {want}");
    // Every point on the circle of its radius, linear in z per interval.
    let radius = |z: f64| {
        if z <= 1.0 {
            0.5 + 0.5 * z
        } else {
            1.0 - 0.7 * (z - 1.0) / 3.0
        }
    };
    let worst = off_circles(&shape, radius);
    assert!(worst < 1e-14, "{worst}");
    // Two sections are sweep_between, bit for bit.
    let two = sweep_through(&bar, &[at(0.0, &c0), at(1.0, &c2)], &WireSweep::default()).unwrap();
    let between = sweep_between(&bar, &c0, &[], &c2, &[], &WireSweep::default()).unwrap();
    assert_eq!(two.faces().len(), between.faces().len());
    for (a, b) in two.faces().iter().zip(between.faces()) {
        if let (Some(a), Some(b)) = (&a.surface, &b.surface) {
            assert_eq!(a.eval(0.3, 0.7), b.eval(0.3, 0.7));
        }
    }
}

/// The shoelace area of the section at height z of a wire along z from 0 to `length` (a
/// 400-gon per face, the faces of one piece in order around the loop).
fn section_area(shape: &Shape, z: f64, length: f64) -> f64 {
    let mut points = Vec::new();
    for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
        let s = face.surface.as_ref().unwrap();
        let ((u0, u1), (v0, v1)) = (s.domain_u(), s.domain_v());
        let (za, zb) = (s.eval(u0, v0).z, s.eval(u0, v1).z);
        // The piece that starts at z, or ends there at the wire's end.
        let holds = (za <= z && z < zb) || (z == length && zb == length);
        if !holds {
            continue;
        }
        let v = v0 + (v1 - v0) * (z - za) / (zb - za);
        for k in 0..400 {
            let p = s.eval(u0 + (u1 - u0) * k as f64 / 400.0, v);
            assert!((p.z - z).abs() < 1e-9 * length, "{} against {z}", p.z);
            points.push(p.truncate());
        }
    }
    let n = points.len();
    0.5 * (0..n)
        .map(|i| points[i].perp_dot(points[(i + 1) % n]))
        .sum::<f64>()
        .abs()
}

#[test]
fn a_square_through_a_circle_into_a_triangle_shares_its_middle_section() {
    let bar = [line([0., 0., 0.], [0., 0., 6.])];
    let (sq, ci, tr) = (square(0.5), circle(0.6), triangle(0.7));
    let sections = [at(0.0, &sq), at(0.5, &ci), at(1.0, &tr)];
    let shape = sweep_through(&bar, &sections, &WireSweep::default()).unwrap();
    assert!(shape.is_solid());
    crate::testing::assert_closed_oriented(shape.brep());
    // The faces' edges at the station lie on the circle (z = 3): the section is the circle.
    let mut off = 0.0f64;
    let mut at_station = 0;
    for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
        let s = face.surface.as_ref().unwrap();
        let ((u0, u1), (v0, v1)) = (s.domain_u(), s.domain_v());
        for v in [v0, v1] {
            if (s.eval(u0, v).z - 3.0).abs() > 1e-12 {
                continue;
            }
            at_station += 1;
            for k in 0..=32 {
                let p = s.eval(u0 + (u1 - u0) * k as f64 / 32.0, v);
                off = off.max((p.truncate().length() - 0.6).abs());
            }
        }
    }
    // Every face of either interval meets the station: as many from each side.
    let lateral = shape
        .faces()
        .iter()
        .filter(|f| f.kind == FaceKind::Swept)
        .count();
    println!(
        "square → circle → triangle: {lateral} lateral faces, {at_station} edges at the \
         station, off the circle {off:.1e}"
    );
    assert_eq!(at_station, lateral, "each face has one end at the station");
    assert!(off < 1e-14, "{off}");
    // Sections quadratic in λ per interval: Simpson per interval.
    let areas: Vec<f64> = [0.0, 1.5, 3.0, 4.5, 6.0]
        .iter()
        .map(|&z| section_area(&shape, z, 6.0))
        .collect();
    let simpson = 3.0 * (areas[0] + 4.0 * areas[1] + areas[2]) / 6.0
        + 3.0 * (areas[2] + 4.0 * areas[3] + areas[4]) / 6.0;
    let v = volume(&shape);
    let error = (v - simpson).abs() / simpson;
    println!(
        "  areas {areas:.6?}; volume {v:.9} against Simpson {simpson:.9}, relative {error:.1e}"
    );
    // (The sampled areas are 400-gons: 1e-4 of the circle's.)
    assert!(error < 2e-4, "{error:e}");
}

#[test]
fn circles_through_four_radii_along_the_pipe_route() {
    let route = pipe_route();
    let c: Vec<PiecewiseCurve> = [0.5, 0.8, 0.4, 0.6].iter().map(|&r| circle(r)).collect();
    let sections = [
        at(0.0, &c[0]),
        at(0.3, &c[1]),
        at(0.6, &c[2]),
        at(1.0, &c[3]),
    ];
    let options = WireSweep {
        tolerance: 1e-6,
        ..WireSweep::default()
    };
    let shape = sweep_through(&route, &sections, &options).unwrap();
    crate::testing::assert_closed_oriented(shape.brep());
    let length: f64 = shape.spine().iter().map(|c| c.arc_length()).sum();
    let want = frustum(1.0, 0.3 * length, 0.5, 0.8)
        + frustum(1.0, 0.3 * length, 0.8, 0.4)
        + frustum(1.0, 0.4 * length, 0.4, 0.6);
    let v = volume(&shape);
    let error = (v - want).abs() / want;
    println!("circles 0.5, 0.8, 0.4, 0.6 along the pipe route: volume {v:.10} against {want:.10}, relative {error:.1e}");
    // Lines exact; on arcs the blend is within the tolerance of linear in arc length.
    assert!(error < 4.0 * 1e-6 / 0.4, "{error:e}");
}

#[test]
fn sections_that_cannot_be_are_refused_naming_them() {
    let bar = [line([0., 0., 0.], [0., 0., 4.])];
    let (c, s) = (circle(0.5), square(0.5));
    let ring_hole = [circle(0.2)];
    let refused = |sections: &[Section]| {
        sweep_through(&bar, sections, &WireSweep::default())
            .unwrap_err()
            .message()
    };
    let m = refused(&[at(0.0, &c)]);
    assert!(
        m.starts_with("sections: a sweep through sections needs two or more"),
        "{m}"
    );
    let m = refused(&[at(0.1, &c), at(1.0, &s)]);
    assert!(m.starts_with("sections[0]: at = 0.1 must be 0"), "{m}");
    let m = refused(&[at(0.0, &c), at(0.9, &s)]);
    assert!(m.starts_with("sections[1]: at = 0.9 must be 1"), "{m}");
    // Also a section so near another, or the end, that both would stand on one boundary.
    for bad in [0.0, 0.5, 1.0, f64::NAN, 0.5 + 1e-12, 1.0 - 1e-12] {
        let m = refused(&[at(0.0, &c), at(0.5, &s), at(bad, &c), at(1.0, &s)]);
        assert!(m.starts_with("sections[2]: at ="), "{bad}: {m}");
    }
    let m = refused(&[at(0.0, &c), at(1e-12, &s), at(1.0, &c)]);
    assert!(
        m.starts_with("sections[1]: at =") && m.contains("1e-8"),
        "{m}"
    );
    let holed = Section {
        at: 0.5,
        profile: &c,
        holes: &ring_hole,
    };
    let m = refused(&[at(0.0, &c), holed, at(1.0, &c)]);
    assert!(m.contains("sections[1]") && m.contains("holes"), "{m}");
    // A closed wire, a scale law.
    let loop_edges = square_loop();
    let m = sweep_through(
        &loop_edges,
        &[at(0.0, &c), at(0.5, &s), at(1.0, &c)],
        &WireSweep::default(),
    )
    .unwrap_err()
    .message();
    assert!(m.starts_with("sections: a closed wire"), "{m}");
    let m = sweep_through(
        &bar,
        &[at(0.0, &c), at(0.5, &s), at(1.0, &c)],
        &WireSweep {
            scale: [1.0, 2.0],
            ..WireSweep::default()
        },
    )
    .unwrap_err()
    .message();
    assert!(m.starts_with("scale: with sections"), "{m}");
}

#[test]
fn sweeps_through_sections_are_the_same_from_1e_200_to_1e200() {
    let route = pipe_route();
    let (a, b, c) = (square(0.5), circle(0.7), triangle(0.6));
    let sections = |s: f64| -> [PiecewiseCurve; 3] {
        [
            a.similar(s, DVec3::ZERO),
            b.similar(s, DVec3::ZERO),
            c.similar(s, DVec3::ZERO),
        ]
    };
    let through = |edges: &[Edge], p: &[PiecewiseCurve; 3], tolerance: f64| {
        sweep_through(
            edges,
            &[at(0.0, &p[0]), at(0.4, &p[1]), at(1.0, &p[2])],
            &WireSweep {
                tolerance,
                ..WireSweep::default()
            },
        )
        .unwrap()
    };
    let unit = through(&route, &sections(1.0), 1e-4);
    for s in [1e-200, 1e-100, 1e100, 1e200] {
        let o = DVec3::new(3e2, -1e2, 2e2) * s;
        let moved = super::robustness_tests::moved(&route, s, o);
        let shape = through(&moved, &sections(s), 1e-4 * s);
        assert_eq!(shape.faces().len(), unit.faces().len());
        let rounding = 1.0 + crate::math::robust_length(o) / s;
        for (fa, fb) in unit.faces().iter().zip(shape.faces()) {
            if let (Some(fa), Some(fb)) = (&fa.surface, &fb.surface) {
                for i in 0..=4 {
                    for j in 0..=4 {
                        let (u0, u1) = fa.domain_u();
                        let (v0, v1) = fa.domain_v();
                        let (u, v) = (
                            u0 + (u1 - u0) * i as f64 / 4.0,
                            v0 + (v1 - v0) * j as f64 / 4.0,
                        );
                        let (pa, pb) = (fa.eval(u, v), (fb.eval(u, v) - o) / s);
                        assert!(
                            pa.distance(pb) < 1e-8 * rounding,
                            "{s:e}: {pa} against {pb}"
                        );
                    }
                }
            }
        }
    }
}
