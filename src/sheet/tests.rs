//! The figures of issue 15 on the library's own evaluation (the C/C++, Python and CAD
//! tests repeat them independently): the square-to-round hopper of the command-line
//! example, its edges against the input curves, its flat pattern's area and edge lengths
//! against the formed neutral layer, pieces per tolerance, and marks both ways.

use super::profile::tests::{circle, polygon};
use super::*;
use crate::bezier::PiecewiseCurve;
use crate::cone_spline::PatternEdge;
use crate::math::GaussLegendre;
use glam::DVec3;

pub(crate) fn hopper_curves() -> (PiecewiseCurve, PiecewiseCurve) {
    let bottom = polygon(&[
        DVec3::new(-100.0, -100.0, 0.0),
        DVec3::new(100.0, -100.0, 0.0),
        DVec3::new(100.0, 100.0, 0.0),
        DVec3::new(-100.0, 100.0, 0.0),
    ]);
    let top = circle(DVec3::new(20.0, 0.0, 150.0), DVec3::X, DVec3::Y, 60.0);
    (bottom, top)
}

pub(crate) fn hopper_options(tolerance: f64) -> SheetOptions {
    SheetOptions {
        tolerance,
        sheet: Sheet::new(2.0, 0.4, Reference::Inner).unwrap(),
        flat_tolerance: 0.0,
        max_pieces: 100_000,
    }
}

/// Arc length of a piecewise curve by Gauss–Legendre quadrature per segment.
fn length(curve: &PiecewiseCurve) -> f64 {
    let g = GaussLegendre::new(24);
    curve
        .segments()
        .iter()
        .map(|s| g.integrate(0.0, 1.0, |t| s.eval_jet(t).d1.length()))
        .sum()
}

fn surface_area(part: &SheetPart, layer: Layer) -> f64 {
    let g = GaussLegendre::new(16);
    part.surface(layer)
        .unwrap()
        .patches()
        .iter()
        .map(|p| {
            g.integrate(0.0, 1.0, |u| {
                g.integrate(0.0, 1.0, |v| {
                    let j = p.eval_jet(u, v);
                    j.du.cross(j.dv).length()
                })
            })
        })
        .sum()
}

#[test]
fn square_to_round_hopper_figures() {
    let (bottom, top) = hopper_curves();
    let part = SheetPart::transition(&bottom, &top, &hopper_options(1e-4)).unwrap();
    let r = part.report();
    println!(
        "hopper 1e-4: {} pieces, surface deviation {:.3e}, bottom edge {:.3e}, top edge {:.3e} (fit tolerance {:.3e})",
        part.piece_count(),
        r.deviation,
        r.edge_distance[0],
        r.edge_distance[1],
        r.fit_tolerance
    );
    assert!(r.edge_distance.iter().all(|&d| d <= 1e-4));
    assert!(part.is_closed());
    let flat = part.flat_pattern().unwrap();
    let n = flat.outline.len();
    for k in 0..n {
        assert_eq!(
            flat.outline[k].end(),
            flat.outline[(k + 1) % n].start(),
            "gap after edge {k}"
        );
    }
    let area = 0.5 * super::flat::signed_area(&flat.outline);
    let formed = surface_area(&part, Layer::Neutral);
    let arcs = flat
        .outline
        .iter()
        .filter(|e| matches!(e, PatternEdge::Arc { .. }))
        .count();
    println!(
        "hopper flat pattern: {n} edges ({arcs} arcs), {} bend lines, area {area:.9} vs formed neutral {formed:.9}: relative {:.3e}",
        flat.bend_lines.len(),
        (area - formed).abs() / formed
    );
    assert!(area > 0.0, "counter-clockwise");
    // The biarcs of the top edge are within the flat tolerance of the exact developed edge:
    // the areas differ by at most tolerance × edge length.
    let top_length = length(&part.boundary(Layer::Neutral, Side::Second).unwrap());
    assert!(
        (area - formed).abs() <= 1e-4 * top_length,
        "area {area} vs {formed}"
    );
    // Edge lengths: the formed neutral boundaries against the flat outline's.
    let layout = part.flat_layout().unwrap();
    let sum =
        |edges: &[PatternEdge]| edges.iter().map(PatternEdge::length).sum::<f64>() * part.scale();
    let bottom_length = length(&part.boundary(Layer::Neutral, Side::First).unwrap());
    let (flat_bottom, flat_top) = (sum(&layout.first), sum(&layout.second));
    let seam = part
        .boundary(Layer::Neutral, Side::First)
        .unwrap()
        .eval(0.0)
        .distance(
            part.boundary(Layer::Neutral, Side::Second)
                .unwrap()
                .eval(0.0),
        );
    let flat_seam =
        [layout.rulings[0].length(), layout.rulings[1].length()].map(|l| l * part.scale());
    let relative = |a: f64, b: f64| (a - b).abs() / b;
    println!(
        "hopper neutral edge lengths, formed vs flat: bottom {bottom_length:.9} vs {flat_bottom:.9} ({:.1e}), top {top_length:.9} vs {flat_top:.9} ({:.1e}), seam {seam:.9} vs {:.9} / {:.9} ({:.1e})",
        relative(flat_bottom, bottom_length),
        relative(flat_top, top_length),
        flat_seam[0],
        flat_seam[1],
        relative(flat_seam[0], seam).max(relative(flat_seam[1], seam))
    );
    assert!(relative(flat_bottom, bottom_length) <= 1e-9);
    assert!(relative(flat_top, top_length) <= 1e-9);
    assert!(relative(flat_seam[0], seam).max(relative(flat_seam[1], seam)) <= 1e-9);
}
