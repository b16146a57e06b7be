//! Sheet bodies built as a kernel hands them over — the solids of rectangles swept along
//! bent wires (planes and exact cylinders, shared edges, oriented loops) — unfolded and
//! checked against closed forms: the flat area against the neutral length (volume over
//! thickness at k = 0.5), bends up and down, marks, invariance, refusals.

use super::*;
use crate::model::polygon;
use crate::wire::{sweep as sweep_wire, Edge, WireSweep};
use crate::{Brep, ErrorKind, PatternEdge};
use glam::{DVec2, DVec3};
use std::f64::consts::{FRAC_PI_2, PI};

/// A strip of thickness t and width w, its middle surface along `edges` (in the xy plane,
/// starting along +x at the origin): the rectangle [−t/2, t/2] × [0, w] across the wire.
fn strip(edges: &[Edge], t: f64, w: f64, scale: f64, shift: DVec3) -> Brep {
    let edges: Vec<Edge> = edges
        .iter()
        .map(|e| match e {
            Edge::Line { from, to } => Edge::Line {
                from: shift + scale * *from,
                to: shift + scale * *to,
            },
            Edge::Arc {
                start,
                through,
                end,
            } => Edge::Arc {
                start: shift + scale * *start,
                through: shift + scale * *through,
                end: shift + scale * *end,
            },
            Edge::Curve(_) => unreachable!("lines and arcs"),
        })
        .collect();
    let profile = polygon(&[
        DVec3::new(-0.5 * t, 0.0, 0.0) * scale,
        DVec3::new(0.5 * t, 0.0, 0.0) * scale,
        DVec3::new(0.5 * t, w, 0.0) * scale,
        DVec3::new(-0.5 * t, w, 0.0) * scale,
    ])
    .unwrap();
    let options = WireSweep {
        initial_normal: Some(DVec3::Y),
        ..WireSweep::default()
    };
    sweep_wire(&edges, &profile, &[], &options)
        .unwrap()
        .brep()
        .clone()
}

/// Line 10 along x, a quarter turn of radius 3 (to the left), line 10: an L bracket.
fn bracket() -> Vec<Edge> {
    let s = (0.5f64).sqrt();
    vec![
        Edge::Line {
            from: DVec3::ZERO,
            to: DVec3::new(10.0, 0.0, 0.0),
        },
        Edge::Arc {
            start: DVec3::new(10.0, 0.0, 0.0),
            through: DVec3::new(10.0 + 3.0 * s, 3.0 - 3.0 * s, 0.0),
            end: DVec3::new(13.0, 3.0, 0.0),
        },
        Edge::Line {
            from: DVec3::new(13.0, 3.0, 0.0),
            to: DVec3::new(13.0, 13.0, 0.0),
        },
    ]
}

/// Line, a quarter turn left, a quarter turn right, line: a Z bend.
fn z_bend() -> Vec<Edge> {
    let s = (0.5f64).sqrt();
    vec![
        Edge::Line {
            from: DVec3::ZERO,
            to: DVec3::new(6.0, 0.0, 0.0),
        },
        Edge::Arc {
            start: DVec3::new(6.0, 0.0, 0.0),
            through: DVec3::new(6.0 + 2.0 * s, 2.0 - 2.0 * s, 0.0),
            end: DVec3::new(8.0, 2.0, 0.0),
        },
        Edge::Line {
            from: DVec3::new(8.0, 2.0, 0.0),
            to: DVec3::new(8.0, 7.0, 0.0),
        },
        Edge::Arc {
            start: DVec3::new(8.0, 7.0, 0.0),
            through: DVec3::new(10.0 - 2.0 * s, 7.0 + 2.0 * s, 0.0),
            end: DVec3::new(10.0, 9.0, 0.0),
        },
        Edge::Line {
            from: DVec3::new(10.0, 9.0, 0.0),
            to: DVec3::new(16.0, 9.0, 0.0),
        },
    ]
}

fn options(k: f64) -> BodyOptions {
    BodyOptions {
        face: UnfoldOptions::new(1e-6),
        k_factor: KFactor::Constant(k),
    }
}

#[test]
fn an_l_bracket_unfolds_to_its_neutral_length() {
    let (t, w) = (1.0, 4.0);
    let brep = strip(&bracket(), t, w, 1.0, DVec3::ZERO);
    for k in [0.5, 0.3, 0.0] {
        let u = unfold_body(&brep, &options(k)).unwrap();
        // Inner radius 3 − t/2; the neutral layer at k·t from it.
        let neutral = 20.0 + FRAC_PI_2 * (3.0 - 0.5 * t + k * t);
        let expected = w * neutral;
        let area = u.pattern().area().unwrap();
        println!(
            "L bracket, k = {k}: thickness {}, flat area {area} (w × neutral length {expected}), {} outline edges, {} bends",
            u.thickness(),
            u.pattern().outline.len(),
            u.bends().len()
        );
        assert!((u.thickness() - t).abs() <= 1e-12);
        assert!(
            (area - expected).abs() <= 1e-9 * expected,
            "area {area} against {expected}"
        );
        assert_eq!(u.bends().len(), 1);
        let b = u.bends()[0];
        assert!((b.radius - (3.0 - 0.5 * t)).abs() <= 1e-12 && b.k_factor == k);
        assert!(
            (b.line.length() - w).abs() <= 1e-9,
            "the bend line runs across the strip"
        );
        assert!(u.pattern().holes.is_empty());
    }
}

#[test]
fn at_k_one_half_the_flat_area_is_the_volume_over_the_thickness() {
    let (t, w) = (0.8, 3.0);
    let brep = strip(&z_bend(), t, w, 1.0, DVec3::ZERO);
    let u = unfold_body(&brep, &options(0.5)).unwrap();
    // The middle surface's length: lines 6 + 5 + 6 and two quarter turns of radius 2.
    let volume = t * w * (17.0 + PI * 2.0);
    let area = u.pattern().area().unwrap();
    println!(
        "Z bend: flat area {area}, volume / thickness {}",
        volume / t
    );
    assert!((area - volume / t).abs() <= 1e-9 * area);
    let ups: Vec<bool> = u.bends().iter().map(|b| b.up).collect();
    assert_eq!(ups.len(), 2);
    assert_ne!(ups[0], ups[1], "a Z bend bends up and down: {ups:?}");
}

#[test]
fn a_k_factor_table_is_read_by_the_bend_radius() {
    let brep = strip(&bracket(), 1.0, 4.0, 1.0, DVec3::ZERO);
    // Inner radius 2.5 over thickness 1: between the rows 2 → 0.4 and 3 → 0.5.
    let table = KFactor::Table(vec![(1.0, 0.3), (2.0, 0.4), (3.0, 0.5)]);
    let u = unfold_body(
        &brep,
        &BodyOptions {
            face: UnfoldOptions::new(1e-6),
            k_factor: table,
        },
    )
    .unwrap();
    assert!((u.bends()[0].k_factor - 0.45).abs() <= 1e-12);
    let expected = 4.0 * (20.0 + FRAC_PI_2 * (2.5 + 0.45));
    assert!((u.pattern().area().unwrap() - expected).abs() <= 1e-9 * expected);
}

#[test]
fn marks_go_flat_to_formed_and_back() {
    let brep = strip(&bracket(), 1.0, 4.0, 1.0, DVec3::ZERO);
    let u = unfold_body(&brep, &options(0.5)).unwrap();
    let (lo, hi) = u.pattern().bounds();
    let mut worst: f64 = 0.0;
    let mut checked = 0;
    for i in 1..10 {
        for j in 1..10 {
            let q = lo + (hi - lo) * DVec2::new(i as f64 / 10.0, j as f64 / 10.0);
            let Ok(x) = u.to_formed(q, "q") else { continue };
            let back = u.to_flat(x, "x").unwrap();
            worst = worst.max(back.distance(q));
            checked += 1;
        }
    }
    println!("marks: {checked} points flat → formed → flat, worst {worst:.1e}");
    assert!(checked >= 20 && worst <= 1e-12);
}

#[test]
fn an_unfolded_body_scales_and_moves_with_the_body() {
    let unit = unfold_body(
        &strip(&bracket(), 1.0, 4.0, 1.0, DVec3::ZERO),
        &options(0.5),
    )
    .unwrap();
    for scale in [1e-200, 1e-3, 1e200] {
        let shift = DVec3::new(2.0, -5.0, 7.0) * scale;
        let brep = strip(&bracket(), 1.0, 4.0, scale, shift);
        let moved = unfold_body(
            &brep,
            &BodyOptions {
                face: UnfoldOptions::new(1e-6 * scale),
                k_factor: KFactor::Constant(0.5),
            },
        )
        .unwrap();
        let length = |p: &crate::FlatPattern| p.outline.iter().map(|e| e.length()).sum::<f64>();
        let ratio = length(moved.pattern()) / scale / length(unit.pattern());
        assert!(
            (ratio - 1.0).abs() <= 1e-12,
            "perimeter ratio {ratio} at {scale:e}"
        );
        assert!((moved.thickness() / scale - 1.0).abs() <= 1e-12);
    }
}

#[test]
fn a_sheet_of_varying_thickness_an_open_shell_and_bad_k_factors_are_refused() {
    // A wedge: the strip thickens from 1 to 1.2 across its width.
    let wedge = polygon(&[
        DVec3::new(-0.5, 0.0, 0.0),
        DVec3::new(0.5, 0.0, 0.0),
        DVec3::new(0.6, 4.0, 0.0),
        DVec3::new(-0.6, 4.0, 0.0),
    ])
    .unwrap();
    let line = [Edge::Line {
        from: DVec3::ZERO,
        to: DVec3::new(10.0, 0.0, 0.0),
    }];
    let options_y = WireSweep {
        initial_normal: Some(DVec3::Y),
        ..WireSweep::default()
    };
    let tapered = sweep_wire(&line, &wedge, &[], &options_y)
        .unwrap()
        .brep()
        .clone();
    let e = unfold_body(&tapered, &options(0.5)).unwrap_err();
    println!("wedge: {}", e.message());
    assert!(e.is(ErrorKind::InvalidInput) && e.message().contains("thickness is not constant"));
    let mut open = strip(&bracket(), 1.0, 4.0, 1.0, DVec3::ZERO);
    open.closed = false;
    assert!(unfold_body(&open, &options(0.5))
        .unwrap_err()
        .message()
        .contains("open shell"));
    let good = strip(&bracket(), 1.0, 4.0, 1.0, DVec3::ZERO);
    for (k, says) in [
        (KFactor::Constant(1.5), "outside [0, 1]"),
        (KFactor::Table(vec![]), "no rows"),
        (
            KFactor::Table(vec![(2.0, 0.4), (1.0, 0.3)]),
            "does not increase",
        ),
    ] {
        let o = BodyOptions {
            face: UnfoldOptions::new(1e-6),
            k_factor: k,
        };
        assert!(unfold_body(&good, &o).unwrap_err().message().contains(says));
    }
}

#[test]
fn a_pattern_whose_edges_cross_is_refused_with_the_point() {
    let line = |a: (f64, f64), b: (f64, f64)| PatternEdge::Line {
        from: DVec2::new(a.0, a.1),
        to: DVec2::new(b.0, b.1),
    };
    // A bow tie: its second and fourth edges cross at (1, 0.5).
    let bow = [
        line((0.0, 0.0), (2.0, 0.0)),
        line((2.0, 0.0), (0.0, 1.0)),
        line((0.0, 1.0), (2.0, 1.0)),
        line((2.0, 1.0), (0.0, 0.0)),
    ];
    let frame = crate::model::Similarity {
        origin: DVec3::ZERO,
        scale: 1.0,
    };
    let e = super::body::check_overlap(&bow, &[], frame).unwrap_err();
    assert!(
        e.message().contains("(1.000000, 0.500000)"),
        "{}",
        e.message()
    );
    let square = [
        line((0.0, 0.0), (2.0, 0.0)),
        line((2.0, 0.0), (2.0, 2.0)),
        line((2.0, 2.0), (0.0, 2.0)),
        line((0.0, 2.0), (0.0, 0.0)),
    ];
    assert!(super::body::check_overlap(&square, &[], frame).is_ok());
    // A hole reaching out of the outline.
    let hole = vec![
        line((1.0, 1.0), (1.0, 3.0)),
        line((1.0, 3.0), (1.5, 1.0)),
        line((1.5, 1.0), (1.0, 1.0)),
    ];
    assert!(super::body::check_overlap(&square, &[hole], frame).is_err());
}

#[test]
fn a_zigzag_of_many_bends_unfolds_to_its_neutral_length() {
    // 40 quarter turns alternating left and right, joined by lines of 2: 4 · 81 + 2 faces.
    let s = (0.5f64).sqrt();
    let mut edges = Vec::new();
    let mut at = DVec3::ZERO;
    let mut dir = DVec3::X;
    let mut length = 0.0;
    for k in 0..40 {
        let next = at + 2.0 * dir;
        edges.push(Edge::Line { from: at, to: next });
        at = next;
        let left = if k % 2 == 0 {
            DVec3::Z.cross(dir)
        } else {
            -DVec3::Z.cross(dir)
        };
        let centre = at + 1.5 * left;
        let end = centre + 1.5 * dir;
        let through = centre + 1.5 * (s * dir - s * left);
        edges.push(Edge::Arc {
            start: at,
            through,
            end,
        });
        at = end;
        dir = left;
        length += 2.0 + 1.5 * FRAC_PI_2;
    }
    edges.push(Edge::Line {
        from: at,
        to: at + 2.0 * dir,
    });
    length += 2.0;
    let brep = strip(&edges, 0.5, 3.0, 1.0, DVec3::ZERO);
    let start = std::time::Instant::now();
    let u = unfold_body(&brep, &options(0.5)).unwrap();
    let area = u.pattern().area().unwrap();
    println!(
        "zigzag: {} faces, {} bends, flat area {area} (w × length {}), {:.0} ms (unoptimized test build)",
        brep.faces.len(),
        u.bends().len(),
        3.0 * length,
        start.elapsed().as_secs_f64() * 1e3
    );
    assert_eq!(u.bends().len(), 40);
    assert!((area - 3.0 * length).abs() <= 1e-9 * area);
    let ups = u.bends().iter().filter(|b| b.up).count();
    assert_eq!(ups, 20, "half the bends up, half down");
}

#[test]
fn a_sheet_along_a_wave_unfolds_through_its_cone_splines() {
    // A cubic wave with an inflection, the strip 0.5 thick and 3 high along it: its skins
    // are exact offsets of the sweep's PH spine, general cylinders of degree (1, n).
    let wave = crate::RationalBezierCurve::from_power(&[
        DVec3::ZERO,
        DVec3::new(10.0, 9.0, 0.0),
        DVec3::new(0.0, -27.0, 0.0),
        DVec3::new(0.0, 18.0, 0.0),
    ])
    .unwrap();
    let curve = crate::PiecewiseCurve::new(vec![wave], vec![0.0, 1.0]).unwrap();
    let profile = polygon(&[
        DVec3::new(-0.25, 0.0, 0.0),
        DVec3::new(0.25, 0.0, 0.0),
        DVec3::new(0.25, 3.0, 0.0),
        DVec3::new(-0.25, 3.0, 0.0),
    ])
    .unwrap();
    let sweep = WireSweep {
        initial_normal: Some(DVec3::Z.cross(DVec3::new(10.0, 9.0, 0.0)).normalize()),
        tolerance: 1e-6,
        ..WireSweep::default()
    };
    let shape = sweep_wire(&[Edge::Curve(curve)], &profile, &[], &sweep).unwrap();
    let brep = shape.brep().clone();
    let u = unfold_body(
        &brep,
        &BodyOptions {
            face: UnfoldOptions::new(1e-5),
            k_factor: KFactor::Constant(0.5),
        },
    )
    .unwrap();
    // At k = 0.5 the neutral layer is the spine's surface: the flat area is the volume
    // over the thickness (K = 0: no t³ term).
    let volume = shape.volume().unwrap();
    let area = u.pattern().area().unwrap();
    println!(
        "wave sheet: thickness {}, flat area {area}, volume / thickness {} ({:.1e}), {} bend lines",
        u.thickness(),
        volume / 0.5,
        (area - volume / 0.5).abs() / area,
        u.pattern().bend_lines.len()
    );
    assert!((u.thickness() - 0.5).abs() <= 1e-5);
    assert!((area - volume / 0.5).abs() <= 1e-5 * area);
}
