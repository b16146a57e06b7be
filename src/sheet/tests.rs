//! The figures of issue 15 on the library's own evaluation (the C/C++, Python and CAD
//! tests repeat them independently): the square-to-round hopper of the command-line
//! example, its edges against the input curves, its flat pattern's area and edge lengths
//! against the formed neutral layer, pieces per tolerance, and marks both ways.

use super::profile::tests::{circle, polygon};
use super::*;
use crate::bezier::PiecewiseCurve;
use crate::math::GaussLegendre;
use crate::model::PatternEdge;
use crate::testing::Stream;
use glam::{DVec2, DVec3};

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
    let area = flat.area().unwrap();
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

/// Whether `p` is inside the closed outline, by the winding number of a dense polygon of
/// it (independent of the library's maps), and its distance from the outline.
fn inside(outline: &[PatternEdge], p: DVec2) -> (bool, f64) {
    let mut polygon = Vec::new();
    for e in outline {
        match *e {
            PatternEdge::Line { from, .. } => polygon.push(from),
            PatternEdge::Arc {
                center,
                from,
                sweep,
                ..
            } => {
                for j in 0..16 {
                    let a = sweep * j as f64 / 16.0;
                    polygon.push(center + DVec2::from_angle(a).rotate(from - center));
                }
            }
        }
    }
    let mut winding = 0.0;
    let mut nearest = f64::INFINITY;
    for k in 0..polygon.len() {
        let (a, b) = (polygon[k] - p, polygon[(k + 1) % polygon.len()] - p);
        winding += a.perp_dot(b).atan2(a.dot(b));
        let d = b - a;
        let s = (-a.dot(d) / d.length_squared()).clamp(0.0, 1.0);
        nearest = nearest.min((a + s * d).length());
    }
    (winding.abs() > std::f64::consts::PI, nearest)
}

#[test]
fn marks_go_from_flat_to_formed_and_back() {
    let (bottom, top) = hopper_curves();
    let part = SheetPart::transition(&bottom, &top, &hopper_options(1e-4)).unwrap();
    let flat = part.flat_pattern().unwrap();
    let (lo, hi) = flat.bounds();
    let size = (hi - lo).length();
    let mut stream = Stream(15);
    let (mut count, mut worst, mut worst_outer, mut worst_geodesic) = (0, 0.0f64, 0.0f64, 0.0f64);
    while count < 1000 {
        let p = lo + (hi - lo) * DVec2::new(stream.next(), stream.next());
        let (is_inside, margin) = inside(&flat.outline, p);
        if !is_inside || margin < 1.0 {
            continue;
        }
        count += 1;
        let (x, n) = part.flat_to_surface(p, Layer::Neutral, "p").unwrap();
        assert!((n.length() - 1.0).abs() < 1e-12);
        let back = part
            .surface_to_flat(x, Layer::Neutral, 1e-9 * size, "x")
            .unwrap();
        worst = worst.max(back.distance(p) / size);
        let (y, _) = part.flat_to_surface(p, Layer::Outer, "p").unwrap();
        let thickness = part.layer_distance(Layer::Outer) - part.layer_distance(Layer::Neutral);
        assert!((y.distance(x) - thickness).abs() < 1e-9 * size);
        let back = part
            .surface_to_flat(y, Layer::Outer, 1e-9 * size, "y")
            .unwrap();
        worst_outer = worst_outer.max(back.distance(p) / size);
        // Geodesics: a segment of length 1 in the flat maps to a curve of length 1 on the
        // layer (polylines of 32 and 64 chords, Richardson-extrapolated).
        let q = p + DVec2::from_angle(stream.next() * 6.3);
        if count % 10 == 0 && inside(&flat.outline, q).0 {
            let polyline = |m: usize| {
                let points: Vec<DVec3> = (0..=m)
                    .map(|j| {
                        part.flat_to_surface(p.lerp(q, j as f64 / m as f64), Layer::Neutral, "s")
                            .unwrap()
                            .0
                    })
                    .collect();
                points.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
            };
            let length = (4.0 * polyline(64) - polyline(32)) / 3.0;
            worst_geodesic = worst_geodesic.max((length - 1.0).abs());
        }
    }
    println!(
        "marks: 1000 flat points, round trip via the neutral layer max {worst:.3e}, via the outer layer {worst_outer:.3e} (relative to the pattern's size {size:.1}); \
         100 flat segments of length 1 on the layer: max length error {worst_geodesic:.3e}"
    );
    assert!(worst <= 1e-12 && worst_outer <= 1e-12);
    assert!(worst_geodesic <= 1e-8);
    // Outside the part, and off the surface: refused, naming the argument.
    let e = part
        .flat_to_surface(hi + DVec2::ONE, Layer::Neutral, "marks[3]")
        .unwrap_err();
    assert!(
        e.message().contains("marks[3]") && e.message().contains("outside"),
        "{e}"
    );
    let (x, n) = part
        .flat_to_surface(0.5 * (lo + hi), Layer::Neutral, "p")
        .unwrap_or((DVec3::ZERO, DVec3::Z));
    let e = part
        .surface_to_flat(x + 0.1 * n, Layer::Neutral, 1e-3, "points[7]")
        .unwrap_err();
    assert!(e.message().contains("points[7]"), "{e}");
}

#[test]
fn pieces_per_tolerance_on_the_hopper() {
    let (bottom, top) = hopper_curves();
    let mut counts = Vec::new();
    for tolerance in [1e-2, 1e-3, 1e-4, 1e-5] {
        let part = SheetPart::transition(&bottom, &top, &hopper_options(tolerance)).unwrap();
        let r = part.report();
        println!(
            "hopper tolerance {tolerance:.0e}: {:4} pieces, surface deviation {:.3e}, edges {:.3e} / {:.3e}",
            part.piece_count(),
            r.deviation,
            r.edge_distance[0],
            r.edge_distance[1]
        );
        assert!(r.deviation <= tolerance && r.edge_distance.iter().all(|&d| d <= tolerance));
        counts.push(part.piece_count());
    }
    assert!(counts.windows(2).all(|w| w[0] < w[1]));
}

/// The area of a part's flat pattern scaled down by `scale` (at 1e-200 the area itself
/// underflows).
fn flat_area(part: &SheetPart, scale: f64) -> f64 {
    let outline: Vec<PatternEdge> = part
        .flat_pattern()
        .unwrap()
        .outline
        .iter()
        .map(|e| e.scaled(1.0 / scale))
        .collect();
    crate::FlatPattern {
        outline,
        holes: vec![],
        bend_lines: vec![],
    }
    .area()
    .unwrap()
}

#[test]
fn scaled_and_moved_hoppers_are_similar() {
    let (bottom, top) = hopper_curves();
    let reference = SheetPart::transition(&bottom, &top, &hopper_options(1e-3)).unwrap();
    let a0 = flat_area(&reference, 1.0);
    for (scale, shift) in [
        (1e-200, DVec3::ZERO),
        (1e200, DVec3::ZERO),
        (1.0, DVec3::new(1e6, -3e5, 2e6)),
        (1e-3, DVec3::splat(7.0)),
    ] {
        let map = |c: &PiecewiseCurve| {
            PiecewiseCurve::new(
                c.segments()
                    .iter()
                    .map(|s| s.similar(scale, shift))
                    .collect(),
                c.breaks().to_vec(),
            )
            .unwrap()
        };
        let mut options = hopper_options(1e-3 * scale);
        options.sheet = Sheet::new(2.0 * scale, 0.4, Reference::Inner).unwrap();
        let part = SheetPart::transition(&map(&bottom), &map(&top), &options).unwrap();
        assert_eq!(
            part.piece_count(),
            reference.piece_count(),
            "scale {scale:e}"
        );
        let a = flat_area(&part, scale);
        println!("hopper scaled by {scale:e}, moved by {shift}: {} pieces, flat area (scaled back) {a:.12} (relative {:.1e})", part.piece_count(), (a - a0).abs() / a0);
        assert!((a - a0).abs() <= 1e-10 * a0);
        let edge = part.report().edge_distance[1] / scale;
        assert!(
            (edge - reference.report().edge_distance[1]).abs()
                <= 1e-6 * reference.report().edge_distance[1]
        );
    }
}

/// A closed curve of line segments and circular arcs through `points`, where an arc is
/// given by its middle control point and weight.
fn obround(length: f64, radius: f64, z: f64) -> PiecewiseCurve {
    use crate::bezier::homogeneous::lift;
    use crate::bezier::RationalBezierCurve;
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let a = 0.5 * length;
    let p = |x: f64, y: f64| DVec3::new(x, y, z);
    let quarter = |p0: DVec3, p1: DVec3, p2: DVec3| {
        RationalBezierCurve::from_homogeneous(vec![lift(p0, 1.0), lift(p1, s), lift(p2, 1.0)])
            .unwrap()
    };
    let line = |p0: DVec3, p1: DVec3| RationalBezierCurve::polynomial(&[p0, p1]).unwrap();
    let segments = vec![
        line(p(-a, -radius), p(a, -radius)),
        quarter(p(a, -radius), p(a + radius, -radius), p(a + radius, 0.0)),
        quarter(p(a + radius, 0.0), p(a + radius, radius), p(a, radius)),
        line(p(a, radius), p(-a, radius)),
        quarter(p(-a, radius), p(-a - radius, radius), p(-a - radius, 0.0)),
        quarter(p(-a - radius, 0.0), p(-a - radius, -radius), p(-a, -radius)),
    ];
    PiecewiseCurve::with_unit_intervals(segments).unwrap()
}

/// max |K|·size² at interior points (u ∈ [0.05, 0.95]: the rows at a vertex are
/// singular), size the bounding-box diagonal.
fn interior_curvature(surface: &crate::bezier::PiecewiseSurface) -> f64 {
    let (mut lo, mut hi, mut k) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0.0f64);
    for p in surface.patches() {
        for i in 0..=6 {
            for j in 0..=6 {
                let jet = p.eval_jet(0.05 + 0.15 * i as f64, j as f64 / 6.0);
                lo = lo.min(jet.point);
                hi = hi.max(jet.point);
                // A crease has no width on the designed surface: no curvature to measure.
                if jet.dv.length() <= 1e-9 * jet.du.length() {
                    continue;
                }
                k = k.max(crate::frames::metrics::gaussian_curvature(&jet).abs());
            }
        }
    }
    k * (hi - lo).length_squared()
}

/// Builds a transition and checks what every one must satisfy; returns the part.
fn check_transition(
    name: &str,
    bottom: &PiecewiseCurve,
    top: &PiecewiseCurve,
    tolerance: f64,
) -> SheetPart {
    let mut options = hopper_options(tolerance);
    options.sheet = Sheet::new(1.5, 0.33, Reference::Inner).unwrap();
    let part =
        SheetPart::transition(bottom, top, &options).unwrap_or_else(|e| panic!("{name}: {e}"));
    let r = part.report();
    let surface = part.surface(Layer::Reference).unwrap();
    let k = interior_curvature(&surface);
    let flat = part.flat_pattern().unwrap();
    let area = flat.area().unwrap();
    let formed = surface_area(&part, Layer::Neutral);
    let creases = part
        .cone_spline()
        .unwrap()
        .pieces()
        .iter()
        .filter(|p| p.kind() == crate::cone_spline::PieceKind::Cylinder && p.radius() < 1e-9)
        .count();
    println!(
        "{name}: {} pieces ({creases} creases), deviation {:.2e}, edges {:.2e} / {:.2e}, max |K|·size² {k:.1e}, flat area {area:.6} vs formed neutral {formed:.6} ({:.1e}), {} outline edges",
        part.piece_count(),
        r.deviation,
        r.edge_distance[0],
        r.edge_distance[1],
        (area - formed).abs() / formed,
        flat.outline.len()
    );
    assert!(r.edge_distance.iter().all(|&d| d <= tolerance), "{name}");
    assert!(k < 1e-9, "{name}: K");
    let top_length = length(&part.boundary(Layer::Neutral, Side::Second).unwrap())
        + length(&part.boundary(Layer::Neutral, Side::First).unwrap());
    assert!(
        (area - formed).abs() <= tolerance * top_length,
        "{name}: area"
    );
    // G1 across the rulings, except at creases.
    let spline = part.cone_spline().unwrap();
    for w in spline.pieces().windows(2) {
        let (a, b) = (w[0].end(), w[1].start);
        assert!(
            a.normal().distance(b.normal()) < 1e-9,
            "{name}: normal jump"
        );
    }
    crate::testing::assert_closed_oriented(&part.brep().unwrap());
    part
}

#[test]
fn transitions_between_all_kinds_of_convex_curves() {
    let rectangle = |w: f64, h: f64, z: f64| {
        polygon(&[
            DVec3::new(-w, -h, z),
            DVec3::new(w, -h, z),
            DVec3::new(w, h, z),
            DVec3::new(-w, h, z),
        ])
    };
    check_transition(
        "rectangle-to-round",
        &rectangle(150.0, 80.0, 0.0),
        &circle(DVec3::new(0.0, 10.0, 120.0), DVec3::X, DVec3::Y, 50.0),
        1e-3,
    );
    check_transition(
        "round-to-round, offset",
        &circle(DVec3::ZERO, DVec3::X, DVec3::Y, 100.0),
        &circle(DVec3::new(40.0, 20.0, 150.0), DVec3::X, DVec3::Y, 50.0),
        1e-3,
    );
    let tilt = DVec3::new(1.0, 0.0, 0.4).normalize();
    check_transition(
        "round-to-round, inclined",
        &circle(DVec3::ZERO, DVec3::X, DVec3::Y, 100.0),
        &circle(DVec3::new(0.0, 0.0, 200.0), tilt, DVec3::Y, 60.0),
        1e-3,
    );
    check_transition(
        "obround-to-round",
        &obround(200.0, 60.0, 0.0),
        &circle(DVec3::new(0.0, 0.0, 100.0), DVec3::X, DVec3::Y, 50.0),
        1e-3,
    );
    let part = check_transition(
        "rectangle-to-rectangle",
        &rectangle(100.0, 60.0, 0.0),
        &rectangle(40.0, 30.0, 80.0),
        1e-3,
    );
    // Four trapezoids (one split at the seam) and four creases.
    assert_eq!(part.piece_count(), 9);
    check_transition(
        "ellipse (NURBS) to round",
        &circle(DVec3::ZERO, DVec3::X * 1.5, DVec3::Y, 80.0),
        &circle(DVec3::new(10.0, 0.0, 100.0), DVec3::X, DVec3::Y, 40.0),
        1e-3,
    );
    check_transition(
        "square-to-round, inclined top",
        &rectangle(100.0, 100.0, 0.0),
        &circle(
            DVec3::new(0.0, 0.0, 150.0),
            DVec3::new(1.0, 0.0, -0.3).normalize(),
            DVec3::Y,
            60.0,
        ),
        1e-3,
    );
}

#[test]
fn bad_transitions_and_sheets_are_refused_naming_the_argument() {
    let (bottom, top) = hopper_curves();
    let try_with = |b: &PiecewiseCurve, t: &PiecewiseCurve, o: SheetOptions| {
        SheetPart::transition(b, t, &o).unwrap_err().message()
    };
    let o = hopper_options(1e-3);
    let below = circle(
        DVec3::new(0.0, 0.0, -20.0),
        DVec3::X,
        DVec3::new(0.0, 0.6, 0.8),
        60.0,
    );
    assert!(try_with(&bottom, &below, o).contains("the curves cross"));
    let dart = polygon(&[
        DVec3::ZERO,
        DVec3::new(2.0, 1.0, 0.0),
        DVec3::new(0.0, 0.5, 0.0),
        DVec3::new(-2.0, 1.0, 0.0),
    ]);
    assert!(try_with(&dart, &top, o).contains("bottom is not convex"));
    let open = PiecewiseCurve::with_unit_intervals(bottom.segments()[..3].to_vec()).unwrap();
    let m = try_with(&open, &top, o);
    assert!(
        m.contains("bottom is not closed") && m.contains("apart"),
        "{m}"
    );
    for (t, k, what) in [
        (0.0, 0.4, "thickness"),
        (-1.0, 0.4, "thickness"),
        (f64::NAN, 0.4, "thickness"),
        (2.0, 1.5, "k_factor"),
        (2.0, -0.1, "k_factor"),
    ] {
        let mut o = hopper_options(1e-3);
        o.sheet.thickness = t;
        o.sheet.k_factor = k;
        assert!(try_with(&bottom, &top, o).contains(what), "{what}");
    }
    let mut o = hopper_options(1e-3);
    o.tolerance = 0.0;
    assert!(try_with(&bottom, &top, o).contains("tolerance"));
    // The designed surface as the outer face: the inner face would pass the corner cones'
    // vertices (bend radius 0 at the corners).
    let mut o = hopper_options(1e-3);
    o.sheet.reference = Reference::Outer;
    let m = try_with(&bottom, &top, o);
    assert!(
        m.contains("thickness = 2") && m.contains("bend radius"),
        "{m}"
    );
}

/// The ruled example of the cone spline fit (cone_spline::approximate's tests): the
/// tangent surface of the twisted cubic (t, t², t³) between the rails x + x′/2 and x + x′,
/// t ∈ [0.2, 1.2], as a polynomial NURBS of degree (1, 3), scaled by `scale` and moved by
/// `shift`.
fn twisted_cubic_ruled(scale: f64, shift: DVec3) -> crate::PiecewiseSurface {
    use crate::bezier::bernstein;
    let curve = crate::cone_spline::test_support::twisted_cubic(0.2, 1.2);
    let segment = &curve.segments()[0];
    let d: Vec<glam::DVec4> = bernstein::elevate(&bernstein::derivative(segment.homogeneous()), 1);
    let mut poles = Vec::new();
    for s in [0.5, 1.0] {
        for (x, dx) in segment.homogeneous().iter().zip(&d) {
            poles.push((scale * (x.truncate() + s * dx.truncate()) + shift).extend(1.0));
        }
    }
    let patch = crate::RationalBezierPatch::from_homogeneous(1, 3, poles).unwrap();
    crate::PiecewiseSurface::new(vec![patch], vec![0.0, 1.0], vec![0.2, 1.2]).unwrap()
}

/// Distance from `x` to the curve `c` over [a, b] (a dense scan, then golden sections
/// about the nearest sample): independent of the library's searches.
fn curve_distance(c: impl Fn(f64) -> DVec3, (a, b): (f64, f64), x: DVec3) -> f64 {
    let n = 2000;
    let t = |i: usize| a + (b - a) * i as f64 / n as f64;
    let d = |s: f64| c(s).distance(x);
    let best = (0..=n)
        .min_by(|&i, &j| d(t(i)).total_cmp(&d(t(j))))
        .unwrap();
    let (mut lo, mut hi) = (t(best.max(1) - 1), t((best + 1).min(n)));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if d(x1) < d(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    d(0.5 * (lo + hi)).min(d(t(best)))
}

/// Largest distance of the part's boundaries (reference layer, 17 points per piece) from
/// the rails `rail(side, t)` over `domain`.
fn boundary_against_rails(
    part: &SheetPart,
    rail: &impl Fn(usize, f64) -> DVec3,
    domain: (f64, f64),
) -> [f64; 2] {
    let mut worst = [0.0f64; 2];
    for (k, side) in [Side::First, Side::Second].into_iter().enumerate() {
        let edge = part.boundary(Layer::Reference, side).unwrap();
        for s in edge.segments() {
            for j in 0..=16 {
                let x = s.eval(j as f64 / 16.0);
                worst[k] = worst[k].max(curve_distance(|t| rail(k, t), domain, x));
            }
        }
    }
    worst
}

/// The smallest distance of a cone vertex from the part's ruling segments (the patches of
/// the reference layer at u ∈ [0, 1], 33 rulings per piece), relative to `size`: every
/// ruling of a cone passes through its vertex, so the vertex is on the part exactly when
/// it lies inside one of these segments.
fn vertex_clearance(part: &SheetPart, size: f64) -> f64 {
    let spline = part.cone_spline().unwrap();
    let surface = part.surface(Layer::Reference).unwrap();
    let mut clearance = f64::INFINITY;
    for (piece, patch) in spline.pieces().iter().zip(surface.patches()) {
        let Some(vertex) = piece.vertex() else {
            continue;
        };
        for j in 0..=32 {
            let v = j as f64 / 32.0;
            let (a, b) = (patch.eval(0.0, v), patch.eval(1.0, v));
            let d = b - a;
            let s = ((vertex - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
            clearance = clearance.min(vertex.distance(a + s * d) / size);
        }
    }
    clearance
}

fn rails_options(tolerance: f64, flat_tolerance: f64) -> SheetOptions {
    SheetOptions {
        tolerance,
        sheet: Sheet::new(0.02, 0.5, Reference::Inner).unwrap(),
        flat_tolerance,
        max_pieces: 100_000,
    }
}

/// Relative differences of the flat pattern's area and boundary lengths from the formed
/// neutral layer's (library quadrature of the NURBS on both sides).
fn flat_against_formed(part: &SheetPart) -> (f64, f64) {
    let flat = part.flat_pattern().unwrap();
    let n = flat.outline.len();
    for k in 0..n {
        assert_eq!(flat.outline[k].end(), flat.outline[(k + 1) % n].start());
    }
    let (formed, area) = (surface_area(part, Layer::Neutral), flat.area().unwrap());
    assert!(area > 0.0, "counter-clockwise");
    let lengths = part.flat_boundary_lengths().unwrap();
    let formed_lengths =
        [Side::First, Side::Second].map(|s| length(&part.boundary(Layer::Neutral, s).unwrap()));
    let length_error = (0..2)
        .map(|k| (lengths[k] - formed_lengths[k]).abs() / formed_lengths[k])
        .fold(0.0, f64::max);
    ((area - formed).abs() / formed, length_error)
}

#[test]
fn parts_between_the_rails_of_a_ruled_developable() {
    let surface = twisted_cubic_ruled(1.0, DVec3::ZERO);
    // The input's own boundary curves, u = 0 and u = 1.
    let rail = |side: usize, t: f64| surface.eval(side as f64, t);
    let domain = (0.2, 1.2);
    let size = 5.0;
    let mut counts = Vec::new();
    for tolerance in [1e-3, 1e-4, 1e-5] {
        let part =
            SheetPart::between_rails(&surface, &rails_options(tolerance, 1e-9 * size)).unwrap();
        let r = part.report();
        let worst = boundary_against_rails(&part, &rail, domain);
        let (area_error, length_error) = flat_against_formed(&part);
        let clearance = vertex_clearance(&part, size);
        println!(
            "ruled part between rails, tolerance {tolerance:.0e}: {} pieces, surface deviation {:.3e}, edges against the rails {:.3e} / {:.3e} \
             (library {:.3e} / {:.3e}); flat area vs formed neutral {area_error:.1e}, edge lengths {length_error:.1e}; vertices {clearance:.2e}·size from the part",
            part.piece_count(),
            r.deviation,
            worst[0],
            worst[1],
            r.edge_distance[0],
            r.edge_distance[1],
        );
        assert!(worst.iter().all(|&w| w <= tolerance), "{worst:?}");
        assert!(r.deviation <= tolerance);
        assert!(area_error <= 1e-9, "{area_error}");
        assert!(length_error <= 1e-9, "{length_error}");
        assert!(clearance > 1e-6, "{clearance}");
        // G1 across the pieces; the part starts on the input's first ruling.
        let spline = part.cone_spline().unwrap();
        for w in spline.pieces().windows(2) {
            assert!(w[0].end().normal().distance(w[1].start.normal()) < 1e-9);
        }
        for (side, t) in [(Side::First, 0), (Side::Second, 1)] {
            let start = part.boundary(Layer::Reference, side).unwrap().eval(0.0);
            assert!(start.distance(rail(t, 0.2)) <= tolerance, "{start}");
        }
        // The measurement catches a rail off by ten tolerances.
        let moved = |side: usize, t: f64| rail(side, t) + DVec3::Z * (10.0 * tolerance);
        let off = boundary_against_rails(&part, &moved, domain);
        assert!(off.iter().all(|&w| w > 5.0 * tolerance), "{off:?}");
        counts.push(part.piece_count());
    }
    assert!(counts.windows(2).all(|w| w[0] <= w[1]), "{counts:?}");
    // The area check catches a flat outline drawn with coarse biarcs (flat tolerance 1e-3).
    let coarse = SheetPart::between_rails(&surface, &rails_options(1e-3, 1e-3)).unwrap();
    let (area_error, length_error) = flat_against_formed(&coarse);
    println!("coarse flat tolerance 1e-3: area {area_error:.1e}, lengths {length_error:.1e}");
    assert!(area_error > 1e-9 && length_error > 1e-9);
    // The vertex check catches a vertex on the part: the hopper's corner cones have theirs
    // at the square's corners, on its bottom edge.
    let (bottom, top) = hopper_curves();
    let hopper = SheetPart::transition(&bottom, &top, &hopper_options(1e-3)).unwrap();
    let on_edge = vertex_clearance(&hopper, 400.0);
    assert!(on_edge < 1e-9, "{on_edge}");
}

#[test]
fn parts_between_rails_are_similar_under_scaling_and_translation() {
    let reference = SheetPart::between_rails(
        &twisted_cubic_ruled(1.0, DVec3::ZERO),
        &rails_options(1e-4, 1e-9),
    )
    .unwrap();
    let area0 = reference.flat_pattern().unwrap().area().unwrap();
    let edge0 = reference.report().edge_distance;
    for (scale, shift) in [
        (1e-200, DVec3::ZERO),
        (1e200, DVec3::ZERO),
        (1.0, DVec3::new(1e6, -3e5, 2e6)),
        (1e-3, DVec3::splat(7.0)),
    ] {
        let surface = twisted_cubic_ruled(scale, shift * scale);
        let mut options = rails_options(1e-4 * scale, 1e-9 * scale);
        options.sheet = Sheet::new(0.02 * scale, 0.5, Reference::Inner).unwrap();
        let part = SheetPart::between_rails(&surface, &options).unwrap();
        let area = flat_area(&part, scale);
        let edges = part.report().edge_distance.map(|d| d / scale);
        let start = part
            .boundary(Layer::Reference, Side::First)
            .unwrap()
            .eval(0.0);
        println!(
            "rails scaled by {scale:e}, moved by {shift}·scale: {} pieces (reference {}), flat area {:.1e} relative, edges {:.3e} / {:.3e}",
            part.piece_count(),
            reference.piece_count(),
            (area - area0).abs() / area0,
            edges[0],
            edges[1]
        );
        assert_eq!(part.piece_count(), reference.piece_count());
        assert!((area - area0).abs() <= 1e-10 * area0);
        for k in 0..2 {
            assert!((edges[k] - edge0[k]).abs() <= 1e-6 * edge0[k].max(1e-12));
        }
        // Compared in the input's own size ((1e200)² overflows).
        let expected = surface_start() + shift;
        assert!(
            (start / scale).distance(expected) <= 1e-4,
            "{start} vs {expected}"
        );
    }
}

/// The first rail's start on the unscaled input, x(0.2) + x′(0.2)/2.
fn surface_start() -> DVec3 {
    let t = 0.2;
    DVec3::new(t, t * t, t * t * t) + 0.5 * DVec3::new(1.0, 2.0 * t, 3.0 * t * t)
}

#[test]
fn parts_of_a_tangent_surface_between_two_distances() {
    let curve = crate::cone_spline::test_support::twisted_cubic(0.2, 1.2);
    let (v_min, v_max) = (0.3, 0.9);
    // The rails from the curve's own derivative: x(t) + v x′(t)/|x′(t)|.
    let rail = |side: usize, t: f64| {
        let jet = curve.eval_jet(t);
        jet.point + [v_min, v_max][side] * jet.d1.normalize()
    };
    let tolerance = 1e-4;
    let part =
        SheetPart::tangent_surface(&curve, v_min, v_max, &rails_options(tolerance, 1e-9)).unwrap();
    let r = part.report();
    let worst = boundary_against_rails(&part, &rail, (0.2, 1.2));
    let (area_error, length_error) = flat_against_formed(&part);
    let clearance = vertex_clearance(&part, 3.0);
    println!(
        "tangent surface of the twisted cubic, v in [0.3, 0.9]: {} pieces, deviation {:.3e}, edges against the rails {:.3e} / {:.3e} (library {:.3e} / {:.3e}); \
         flat area {area_error:.1e}, lengths {length_error:.1e}; vertices {clearance:.2e}·size from the part",
        part.piece_count(),
        r.deviation,
        worst[0],
        worst[1],
        r.edge_distance[0],
        r.edge_distance[1]
    );
    assert!(worst.iter().all(|&d| d <= tolerance), "{worst:?}");
    assert!(r.deviation <= tolerance);
    assert!(area_error <= 1e-9 && length_error <= 1e-9);
    assert!(clearance > 1e-6);
    // The curve itself (v = 0) is the tangent surface's edge of regression: refused.
    let e =
        SheetPart::tangent_surface(&curve, -0.3, 0.9, &rails_options(tolerance, 0.0)).unwrap_err();
    assert!(e.message().contains("contains 0"), "{e}");
    let e =
        SheetPart::tangent_surface(&curve, 0.9, 0.3, &rails_options(tolerance, 0.0)).unwrap_err();
    assert!(e.message().contains("v_min"), "{e}");
}

/// Polygon-to-circle transitions (a circle of four exact quarter arcs, each turning by π/2
/// up to rounding) are the same part — pieces and flat area — at every scale and at
/// offsets up to 1e3 times their size (beyond ~1e4 the input's rounding exceeds the
/// curves' convexity and planarity tolerances of 1e-9).
#[test]
fn polygon_to_circle_transitions_are_the_same_part_at_every_scale() {
    let cases: [(&[f64], [f64; 4]); 3] = [
        (
            &[1.4138192855026037, 2.812644272322218, 5.715071603918129],
            [
                0.10198870864154413,
                -0.18403485341710007,
                1.8152147772691047,
                0.1430999847997217,
            ],
        ),
        (
            &[
                0.6167634768841023,
                3.204034352659418,
                3.4166874238882077,
                3.6077790130348104,
                4.384088273620114,
                4.444028350579497,
                5.396036268084197,
            ],
            [
                0.2828667266147222,
                -0.2250294404975664,
                1.7913098033465844,
                0.21428333497388974,
            ],
        ),
        (
            &[
                0.17022799757433765,
                1.9198502059355156,
                4.393430130014077,
                4.968843842836862,
            ],
            [
                0.0779749186053515,
                0.017324794416909428,
                0.8610205348846299,
                0.23291614679063027,
            ],
        ),
    ];
    for (angles, [cx, cy, height, radius]) in cases {
        let part = |s: f64, t: DVec3| {
            let corners: Vec<DVec3> = angles
                .iter()
                .map(|a| DVec3::new(a.cos(), a.sin(), 0.0) * s + t)
                .collect();
            let top = circle(
                DVec3::new(cx, cy, height) * s + t,
                DVec3::X,
                DVec3::Y,
                radius * s,
            );
            let options = SheetOptions {
                tolerance: 1e-2 * s,
                sheet: Sheet::new(0.01 * s, 0.5, Reference::Inner).unwrap(),
                flat_tolerance: 0.0,
                max_pieces: 100_000,
            };
            SheetPart::transition(&polygon(&corners), &top, &options).unwrap()
        };
        let reference = part(1.0, DVec3::ZERO);
        let a0 = flat_area(&reference, 1.0);
        for (s, t) in [
            (1e-200, DVec3::ZERO),
            (1e-14, DVec3::new(3.0, -7.0, 1.0) * 1e-14),
            (1e33, DVec3::new(-412.0, 873.0, 95.0) * 1e33),
            (1.0, DVec3::new(1e3, 0.0, -1e3)),
            (1e200, DVec3::ZERO),
        ] {
            let p = part(s, t);
            assert_eq!(
                p.piece_count(),
                reference.piece_count(),
                "scale {s:e}, shift {t}"
            );
            let a = flat_area(&p, s);
            assert!(
                (a - a0).abs() <= 1e-9 * a0,
                "scale {s:e}, shift {t}: {a} vs {a0}"
            );
        }
    }
}

#[test]
fn the_hoppers_solid_is_built_from_its_construction() {
    let (bottom, top) = hopper_curves();
    let part = SheetPart::transition(&bottom, &top, &hopper_options(1e-4)).unwrap();
    let brep = part.brep().unwrap();
    crate::testing::assert_closed_oriented(&brep);
    assert!(brep.closed);
    // Four faces a piece; the cuts at the square's corners have no area (both rows are
    // the corner) and are left out. Rows through the apex of a cone or of a plane sector
    // are degenerate edges: at a corner of the square or on the circle on the inner
    // (designed) layer, the sheet's thickness (2) from there on the outer.
    let n = part.piece_count();
    assert!(
        brep.faces.len() < 4 * n && brep.faces.len() >= 4 * n - 8,
        "{}",
        brep.faces.len()
    );
    let degenerate = brep.edges.iter().filter(|e| e.degenerate).count();
    assert!(degenerate >= 8, "{degenerate}");
    for e in brep.edges.iter().filter(|e| e.degenerate) {
        let p = brep.vertices[e.start];
        let corner = DVec3::new(100.0f64.copysign(p.x), 100.0f64.copysign(p.y), 0.0);
        let circle = ((p.x - 20.0).hypot(p.y) - 60.0).hypot(p.z - 150.0);
        let near = p.distance(corner).min(circle);
        assert!(near < 2.0 + 1e-9, "a degenerate edge at {p}");
    }
    // Sides named alike are one edge: every other edge is shared by two faces, so
    // edges = (sides of the faces − degenerate sides) / 2 + degenerate sides.
    let sides = 4 * brep.faces.len();
    assert_eq!(brep.edges.len(), (sides - degenerate) / 2 + degenerate);
    // The STEP and OpenCascade texts write this model.
    let step = part.to_step("hopper").unwrap();
    assert!(step.contains("MANIFOLD_SOLID_BREP"));
    assert_eq!(step.matches("ADVANCED_FACE(").count(), brep.faces.len());
    assert_eq!(
        step.matches("EDGE_CURVE(").count(),
        brep.edges.len() - degenerate
    );
    let occ = part.to_occ_brep().unwrap();
    assert_eq!(occ.matches("\nFa\n").count(), brep.faces.len());
    let flags: Vec<&str> = occ
        .split("\nEd\n")
        .skip(1)
        .map(|record| record.lines().next().unwrap().trim_start())
        .collect();
    assert_eq!(flags.len(), brep.edges.len());
    let marked = flags.iter().filter(|f| f.ends_with(" 1 1 1")).count();
    assert_eq!(marked, degenerate);
}

/// The hopper's B-rep scaled by 1e-200 and 1e200 and moved far off is the same model: the
/// same vertices, edges, loops and senses, its points the scaled and moved ones.
#[test]
fn the_hoppers_brep_is_invariant_under_scaling_and_translation() {
    let (bottom, top) = hopper_curves();
    let unit = SheetPart::transition(&bottom, &top, &hopper_options(1e-3))
        .unwrap()
        .brep()
        .unwrap();
    for (scale, shift) in [
        (1e-200, DVec3::ZERO),
        (1e200, DVec3::ZERO),
        (1.0, DVec3::new(1e5, -3e5, 2e4)),
    ] {
        let options = SheetOptions {
            tolerance: 1e-3 * scale,
            sheet: Sheet::new(2.0 * scale, 0.4, Reference::Inner).unwrap(),
            ..hopper_options(1e-3)
        };
        let part = SheetPart::transition(
            &bottom.similar(scale, shift),
            &top.similar(scale, shift),
            &options,
        )
        .unwrap();
        crate::testing::assert_similar_breps(&unit, &part.brep().unwrap(), scale, shift);
    }
}
