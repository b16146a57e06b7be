//! The shape set as OpenCascade's B-rep text (`BRepTools::Write`, `CASCADE Topology V1`):
//! records of type codes and numbers, the shortest text that reads back as each double.

use super::{Curve2d, Curve3d, Elementary, Kind, Record, ShapeSet, Surface};
use crate::bezier::{NurbsCurve, NurbsSurface};
use crate::error::Result;
use crate::export::{knot_runs, number, push_counts, push_numbers};
use crate::model::Brep;
use std::fmt::Write;

/// The text of `brep` in OpenCascade's B-rep format (module notes of the parent).
pub fn brep_to_occ(brep: &Brep) -> Result<String> {
    let set = ShapeSet::of(brep)?;
    let mut text = String::from("\nCASCADE Topology V1, (c) Matra-Datavision\nLocations 0\n");
    let _ = writeln!(text, "Curve2ds {}", set.curves_2d.len());
    for curve in &set.curves_2d {
        curve_2d(&mut text, curve);
    }
    let _ = writeln!(text, "Curves {}", set.curves.len());
    for curve in &set.curves {
        match curve {
            Curve3d::Elementary(curve) => elementary(&mut text, curve),
            Curve3d::Nurbs(curve) => bspline(&mut text, curve, 3),
        }
    }
    text.push_str("Polygon3D 0\nPolygonOnTriangulations 0\n");
    let _ = writeln!(text, "Surfaces {}", set.surfaces.len());
    for surface in &set.surfaces {
        match surface {
            Surface::Elementary(surface) => elementary(&mut text, surface),
            Surface::Nurbs(surface) => nurbs_surface(&mut text, surface),
        }
    }
    text.push_str("Triangulations 0\n\n");
    shapes(&mut text, &set);
    Ok(text)
}

/// A 2-D line (code 1) or B-spline (code 7).
fn curve_2d(text: &mut String, curve: &Curve2d) {
    match curve {
        Curve2d::Line { origin, direction } => {
            text.push('1');
            push_numbers(text, [origin.0, origin.1, direction.0, direction.1]);
            text.push('\n');
        }
        Curve2d::Segment { from, to, range } => {
            text.push_str("7 1 0 1 2 2");
            push_numbers(text, [from.0, from.1, 1.0]);
            push_numbers(text, [to.0, to.1, 1.0]);
            text.push('\n');
            push_numbers(text, [range.0]);
            text.push_str(" 2");
            push_numbers(text, [range.1]);
            text.push_str(" 2\n");
        }
        Curve2d::Nurbs(curve) => bspline(text, curve, 2),
    }
}

/// A B-spline curve record (code 7), its poles' first `dimension` coordinates (2 for a
/// curve in a parameter plane, 3 in space).
fn bspline(text: &mut String, curve: &NurbsCurve, dimension: usize) {
    let knots = knot_runs(&curve.knots);
    text.push_str("7 1 0");
    push_counts(
        text,
        [curve.degree, curve.poles.len(), knots.clone().count()],
    );
    for (&p, &w) in curve.poles.iter().zip(&curve.weights) {
        push_numbers(text, p.to_array()[..dimension].iter().copied());
        push_numbers(text, [w]);
    }
    text.push('\n');
    push_knots(text, knots);
}

/// Each distinct knot and its multiplicity, and the end of the line.
fn push_knots(text: &mut String, knots: impl Iterator<Item = (f64, usize)>) {
    for (k, m) in knots {
        push_numbers(text, [k]);
        push_counts(text, [m]);
    }
    text.push('\n');
}

/// A line, circle, plane, cylinder, cone or torus: its code, vectors and numbers.
fn elementary(text: &mut String, record: &Elementary) {
    text.push(char::from(b'0' + record.code));
    for v in &record.vectors {
        push_numbers(text, v.to_array());
    }
    push_numbers(text, record.numbers.iter().copied());
    text.push('\n');
}

/// A B-spline surface record (code 9, v running fastest).
fn nurbs_surface(text: &mut String, s: &NurbsSurface) {
    let (ku, kv) = (knot_runs(&s.knots_u), knot_runs(&s.knots_v));
    text.push_str("9 1 1 0 0");
    push_counts(
        text,
        [
            s.degree_u,
            s.degree_v,
            s.pole_count_u,
            s.pole_count_v,
            ku.clone().count(),
            kv.clone().count(),
        ],
    );
    text.push('\n');
    for row in s
        .poles
        .chunks(s.pole_count_v)
        .zip(s.weights.chunks(s.pole_count_v))
    {
        for (p, w) in row.0.iter().zip(row.1) {
            push_numbers(text, [p.x, p.y, p.z, *w]);
        }
        text.push('\n');
    }
    push_knots(text, ku);
    push_knots(text, kv);
}

/// The `TShapes` table and the root reference: a shape is referred to by its number
/// counted from the last written (1), the root is the last.
fn shapes(text: &mut String, set: &ShapeSet) {
    let n = set.shapes.len();
    let tolerance = number(set.tolerance);
    let _ = writeln!(text, "TShapes {n}");
    for Record { kind, flags, held } in &set.shapes {
        match kind {
            Kind::Vertex(p) => {
                let _ = write!(text, "Ve\n{tolerance}\n{}", number(p.x));
                push_numbers(text, [p.y, p.z]);
                text.push_str("\n0 0\n");
            }
            Kind::Edge {
                curve,
                range,
                on_faces,
            } => {
                let _ = write!(text, "Ed\n {tolerance}");
                match curve {
                    None => text.push_str(" 1 1 1\n"),
                    Some(c) => {
                        text.push_str(" 1 1 0\n1");
                        push_counts(text, [*c, 0]);
                        push_numbers(text, [range.0, range.1]);
                        text.push('\n');
                    }
                }
                for on in on_faces {
                    match on.curves[..] {
                        [forward, reversed, ..] => {
                            text.push('3');
                            push_counts(text, [forward, reversed]);
                            text.push_str(" C0");
                        }
                        [only] => {
                            text.push('2');
                            push_counts(text, [only]);
                        }
                        [] => continue,
                    }
                    push_counts(text, [on.face + 1, 0]);
                    push_numbers(text, [range.0, range.1]);
                    text.push('\n');
                }
                text.push_str("0\n");
            }
            Kind::Wire => text.push_str("Wi\n"),
            Kind::Face { natural, surface } => {
                let _ = writeln!(
                    text,
                    "Fa\n{} {tolerance} {surface} 0",
                    if *natural { 1 } else { 0 }
                );
            }
            Kind::Shell => text.push_str("Sh\n"),
            Kind::Solid => text.push_str("So\n"),
            Kind::Compound => text.push_str("Co\n"),
        }
        let _ = write!(text, "\n{flags}\n");
        for &(reversed, position) in held {
            text.push(if reversed { '-' } else { '+' });
            text.push_str(itoa::Buffer::new().format(n - position));
            text.push_str(" 0 ");
        }
        text.push_str("*\n");
    }
    text.push_str("\n+1 0\n");
}
