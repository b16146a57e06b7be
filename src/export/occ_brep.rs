//! OpenCascade's own B-rep text (`CASCADE Topology V1`, what `BRepTools::Write` writes) of
//! a [`Brep`]: `BRepTools::Read` — and so build123d, CadQuery and FreeCAD's
//! `Part.Shape.importBrepFromString` — builds the shape from it as it is, with no sewing,
//! healing or orientation measured afterwards: shared edges are one edge of the kernel,
//! every edge carries its curve on each B-spline face (`2` records, a `3` record for a
//! seam; on a plane the kernel projects the edge itself), the faces' senses and loops are
//! the model's.
//!
//! The file (OCCT's `BRepTools_ShapeSet`, `GeomTools_*Set`): the geometry tables —
//! 2-D curves, 3-D curves, surfaces, each numbered from 1 in the order written — then the
//! topological shapes, every one after the shapes it holds; a reference to a shape is its
//! orientation and its number counted from the last shape written (the last is 1), and
//! the file ends with the reference to the root. A face that is its whole B-spline surface
//! is marked so (its natural restriction). Curves are written as B-splines (code 7: a
//! pcurve line of the model need not run at unit speed, which a 2-D line would), surfaces
//! as B-splines (code 9, poles with v running fastest) or planes (code 1: origin, normal,
//! x axis, y = normal × x axis) — except the model's analytic forms: planes, cylinders
//! (code 2), cones (code 3) and tori (code 5) for analytic faces, lines (code 1) and circles (code 2) for
//! analytic edges, and on a cylinder or torus each edge's curve a 2-D line (code 1) of unit
//! speed on the edge's length or angle. Numbers are the shortest text that reads back as
//! the same double.

use super::{curve_range, knot_runs, number, push_counts, push_numbers};
use crate::bezier::{NurbsCurve, NurbsSurface};
use crate::error::{invalid, Result};
use crate::model::{AnalyticCurve, AnalyticSurface, Brep, BrepEdge, BrepFace, BrepSurface, PCurve};
use std::fmt::Write;

/// The text of `brep` in OpenCascade's B-rep format: a solid of one closed shell, or an
/// open shell (a compound of shells when its faces fall apart into parts; module notes).
pub fn brep_to_occ(brep: &Brep) -> Result<String> {
    if brep.faces.is_empty() {
        return invalid!("a shape needs at least one face");
    }
    let tolerance = number(brep.tolerance()).to_string();
    let mut text = String::from("\nCASCADE Topology V1, (c) Matra-Datavision\nLocations 0\n");
    let on_edges = curves_2d(brep, &mut text)?;
    let _ = writeln!(text, "Curves {}", brep.edges.len());
    for edge in &brep.edges {
        match &edge.analytic {
            Some(analytic) => analytic_curve(&mut text, &analytic.curve),
            None => bspline(&mut text, &edge.curve, 3),
        }
    }
    text.push_str("Polygon3D 0\nPolygonOnTriangulations 0\n");
    let _ = writeln!(text, "Surfaces {}", brep.faces.len());
    for face in &brep.faces {
        match &face.analytic {
            Some(analytic) => analytic_surface(&mut text, &analytic.surface),
            None => surface(&mut text, &face.surface),
        }
    }
    text.push_str("Triangulations 0\n\n");
    let mut shapes = Shapes::default();
    let vertices: Vec<usize> = brep
        .vertices
        .iter()
        .map(|p| {
            let mut data = format!("Ve\n{tolerance}\n{}", number(p.x));
            push_numbers(&mut data, [p.y, p.z]);
            data.push_str("\n0 0\n");
            shapes.add(data, "0101101", Vec::new())
        })
        .collect();
    let mut edges = Vec::with_capacity(brep.edges.len());
    for (e, edge) in brep.edges.iter().enumerate() {
        let (Some(&start), Some(&end)) = (vertices.get(edge.start), vertices.get(edge.end)) else {
            return invalid!("edge {e} joins vertices that do not exist");
        };
        let data = edge_data(e, edge, &on_edges[e], &tolerance);
        edges.push(shapes.add(data, "0101000", vec![('+', start), ('-', end)]));
    }
    let mut in_shell = Vec::with_capacity(brep.faces.len());
    for (f, face) in brep.faces.iter().enumerate() {
        let reversed = face
            .analytic
            .as_ref()
            .is_some_and(|a| a.loops_reversed(face.same_sense));
        let wires: Vec<(char, usize)> = face
            .bounds
            .iter()
            .map(|bound| {
                let mut uses: Vec<_> = bound
                    .uses
                    .iter()
                    .map(|u| (if u.forward != reversed { '+' } else { '-' }, edges[u.edge]))
                    .collect();
                if reversed {
                    uses.reverse();
                }
                ('+', shapes.add("Wi\n".into(), "0101100", uses))
            })
            .collect();
        let mut data = String::with_capacity(40);
        data.push_str(if natural_bounds(face) {
            "Fa\n1 "
        } else {
            "Fa\n0 "
        });
        data.push_str(&tolerance);
        push_counts(&mut data, [f + 1, 0]);
        data.push('\n');
        let same_sense = face
            .analytic
            .as_ref()
            .map_or(face.same_sense, |a| a.same_sense);
        let sense = if same_sense { '+' } else { '-' };
        in_shell.push((sense, shapes.add(data, "0101000", wires)));
    }
    // A solid holds its closed shells: one, or the outer shell and the walls of cavities (a
    // hollow profile swept round a closed wire), each with its faces facing out of the
    // material. An open shape is its shell, or a compound of the shells it falls apart into.
    let parts = brep.shells();
    if !brep.closed && parts.len() == 1 {
        shapes.add("Sh\n".into(), "1101000", in_shell);
    } else {
        let flags = if brep.closed { "0101100" } else { "0101000" };
        let shells = parts
            .iter()
            .map(|faces| {
                let held = faces.iter().map(|&f| in_shell[f]).collect();
                ('+', shapes.add("Sh\n".into(), flags, held))
            })
            .collect();
        let holder = if brep.closed { "So\n" } else { "Co\n" };
        shapes.add(holder.into(), "1100000", shells);
    }
    shapes.write(&mut text);
    Ok(text)
}

/// Whether the face is its whole B-spline surface: one loop, every pcurve a line along
/// the boundary of the parameter rectangle. The kernel then takes the rectangle for the
/// face's domain (its natural restriction): integrals over the face, as its volume and
/// area, run over the rectangle instead of along the loop's curves.
fn natural_bounds(face: &BrepFace) -> bool {
    let (BrepSurface::Nurbs(surface), None) = (&face.surface, &face.analytic) else {
        return false;
    };
    let u = [
        surface.knots_u[0],
        surface.knots_u[surface.knots_u.len() - 1],
    ];
    let v = [
        surface.knots_v[0],
        surface.knots_v[surface.knots_v.len() - 1],
    ];
    let [bound] = &face.bounds[..] else {
        return false;
    };
    bound.uses.iter().all(|use_| match &use_.pcurve {
        Some(PCurve::Line { origin, direction }) => {
            (direction.0 == 0.0 && u.contains(&origin.0))
                || (direction.1 == 0.0 && v.contains(&origin.1))
        }
        _ => false,
    })
}

/// An edge on one face: the numbers of its curve(s) in the face's parameter plane — two for
/// a seam, the forward use's first.
struct OnFace {
    face: usize,
    curves: Vec<usize>,
}

/// Writes the `Curve2ds` table (every use's pcurve, in the order of faces, loops and uses)
/// and returns, per edge, the faces it lies on with their curves' numbers. A use without
/// a pcurve is allowed on a plane only (the kernel projects the edge there).
fn curves_2d(brep: &Brep, text: &mut String) -> Result<Vec<Vec<OnFace>>> {
    let mut table = String::new();
    let mut count = 0;
    let mut on_edges: Vec<Vec<OnFace>> = (0..brep.edges.len()).map(|_| Vec::new()).collect();
    for (f, face) in brep.faces.iter().enumerate() {
        let analytic = face.analytic.as_ref();
        let mut uses: Vec<_> = face
            .bounds
            .iter()
            .enumerate()
            .flat_map(|(b, bound)| bound.uses.iter().enumerate().map(move |(k, u)| (b, k, u)))
            .collect();
        // The forward use of a seam (as written: loops run backwards on an analytic surface
        // of the other orientation) first: its curve is the first of the `3` record.
        let reversed = analytic.is_some_and(|a| a.loops_reversed(face.same_sense));
        // On a plane the kernel projects the edge itself (`BRep_Tool::CurveOnPlane`), as it
        // does for planes it makes.
        let planar = face.is_planar();
        uses.sort_by_key(|(_, _, u)| u.forward == reversed);
        for (b, k, u) in uses {
            let Some(on_faces) = on_edges.get_mut(u.edge) else {
                return invalid!("face {f} uses edge {} of {}", u.edge, brep.edges.len());
            };
            if planar {
                continue;
            }
            let edge = &brep.edges[u.edge];
            match (analytic, &edge.analytic) {
                (Some(a), Some(_)) => {
                    let Some(PCurve::Line { origin, direction }) =
                        a.pcurves.get(b).and_then(|p| p.get(k))
                    else {
                        return invalid!("edge {} has no curve on the analytic face {f}", u.edge);
                    };
                    // A 2-D line (code 1), unit speed on the edge's angle or length.
                    table.push('1');
                    push_numbers(&mut table, [origin.0, origin.1, direction.0, direction.1]);
                    table.push('\n');
                }
                (None, None) => {
                    let Some(pcurve) = &u.pcurve else {
                        return invalid!("edge {} has no curve on face {f}", u.edge);
                    };
                    write_pcurve(&mut table, pcurve, &edge.curve);
                }
                _ => {
                    return invalid!(
                        "edge {} and face {f} are not both analytic or both NURBS",
                        u.edge
                    )
                }
            }
            count += 1;
            match on_faces.iter_mut().find(|o| o.face == f) {
                Some(on) => on.curves.push(count),
                None => on_faces.push(OnFace {
                    face: f,
                    curves: vec![count],
                }),
            }
        }
    }
    let _ = writeln!(text, "Curve2ds {count}");
    text.push_str(&table);
    Ok(on_edges)
}

/// A pcurve as a 2-D B-spline on the edge curve's parameter range.
fn write_pcurve(text: &mut String, pcurve: &PCurve, edge: &NurbsCurve) {
    match pcurve {
        PCurve::Line { origin, direction } => {
            // The degree-1 B-spline from the line's point at the edge's first parameter to
            // that at its last.
            let (first, last) = curve_range(edge);
            let at = |t: f64| [origin.0 + t * direction.0, origin.1 + t * direction.1, 1.0];
            text.push_str("7 1 0 1 2 2");
            push_numbers(text, at(first));
            push_numbers(text, at(last));
            text.push('\n');
            push_numbers(text, [first]);
            text.push_str(" 2");
            push_numbers(text, [last]);
            text.push_str(" 2\n");
        }
        PCurve::Curve(curve) => bspline(text, curve, 2),
    }
}

/// The edge's record: its 3-D curve (number `e + 1`; none for a degenerate edge, which
/// the kernel marks so) and its curves on the faces.
fn edge_data(e: usize, edge: &BrepEdge, on_faces: &[OnFace], tolerance: &str) -> String {
    let (first, last) = edge
        .analytic
        .map_or_else(|| curve_range(&edge.curve), |a| (0.0, a.end));
    let mut data = String::with_capacity(160);
    data.push_str("Ed\n ");
    data.push_str(tolerance);
    if edge.degenerate {
        data.push_str(" 1 1 1\n");
    } else {
        data.push_str(" 1 1 0\n1");
        push_counts(&mut data, [e + 1, 0]);
        push_numbers(&mut data, [first, last]);
        data.push('\n');
    }
    for on in on_faces {
        match on.curves[..] {
            [forward, reversed, ..] => {
                data.push('3');
                push_counts(&mut data, [forward, reversed]);
                data.push_str(" C0");
            }
            [only] => {
                data.push('2');
                push_counts(&mut data, [only]);
            }
            [] => continue,
        }
        push_counts(&mut data, [on.face + 1, 0]);
        push_numbers(&mut data, [first, last]);
        data.push('\n');
    }
    data.push_str("0\n");
    data
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

/// A surface record: a B-spline (code 9, v running fastest) or a plane (code 1).
fn surface(text: &mut String, surface: &BrepSurface) {
    match surface {
        BrepSurface::Nurbs(s) => nurbs_surface(text, s),
        BrepSurface::Plane {
            origin,
            normal,
            x_axis,
        } => {
            let y_axis = normal.cross(*x_axis);
            text.push('1');
            for v in [*origin, *normal, *x_axis, y_axis] {
                push_numbers(text, v.to_array());
            }
            text.push('\n');
        }
    }
}

/// A line (code 1: origin, direction) or circle (code 2: centre, axis, x and y axes,
/// radius).
fn analytic_curve(text: &mut String, curve: &AnalyticCurve) {
    match *curve {
        AnalyticCurve::Line { origin, direction } => {
            text.push('1');
            for v in [origin, direction] {
                push_numbers(text, v.to_array());
            }
        }
        AnalyticCurve::Circle {
            center,
            axis,
            x_axis,
            radius,
        } => {
            text.push('2');
            for v in [center, axis, x_axis, axis.cross(x_axis)] {
                push_numbers(text, v.to_array());
            }
            push_numbers(text, [radius]);
        }
    }
    text.push('\n');
}

/// A plane (code 1: location, normal, x and y axes), cylinder (code 2: the same and the
/// radius), cone (code 3: the same, the radius at v = 0 and the semi-angle) or torus (code
/// 5: the same and the major and minor radii).
fn analytic_surface(text: &mut String, surface: &AnalyticSurface) {
    text.push(match surface {
        AnalyticSurface::Plane { .. } => '1',
        AnalyticSurface::Cylinder { .. } => '2',
        AnalyticSurface::Cone { .. } => '3',
        AnalyticSurface::Torus { .. } => '5',
    });
    let [origin, axis, x_axis] = surface.axes();
    for v in [origin, axis, x_axis, axis.cross(x_axis)] {
        push_numbers(text, v.to_array());
    }
    push_numbers(text, surface.dimensions());
    text.push('\n');
}

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

/// A shape held by another: its orientation (`+`, `-`) and its position in [`Shapes`].
type Held = (char, usize);

/// A shape's record: its type and data, its flags, the shapes it holds.
struct Record {
    data: String,
    flags: &'static str,
    held: Vec<Held>,
}

/// The topological shapes in the order written (each after the shapes it holds).
#[derive(Default)]
struct Shapes {
    records: Vec<Record>,
}

impl Shapes {
    /// Adds a shape — its type and data, its flags (free, modified, checked, orientable,
    /// closed, infinite, convex), the shapes it holds with their orientations — and
    /// returns its position (from 0).
    fn add(&mut self, data: String, flags: &'static str, held: Vec<Held>) -> usize {
        self.records.push(Record { data, flags, held });
        self.records.len() - 1
    }

    /// The `TShapes` table and the root reference: a shape is referred to by its number
    /// counted from the last written (1), the root is the last.
    fn write(&self, text: &mut String) {
        let n = self.records.len();
        let _ = writeln!(text, "TShapes {n}");
        for Record { data, flags, held } in &self.records {
            text.push_str(data);
            let _ = write!(text, "\n{flags}\n");
            for (orientation, position) in held {
                text.push(*orientation);
                text.push_str(itoa::Buffer::new().format(n - position));
                text.push_str(" 0 ");
            }
            text.push_str("*\n");
        }
        text.push_str("\n+1 0\n");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::tests::{circle, pipe_route, square};
    use crate::wire::{sweep as sweep_wire, WireSweep};

    /// The `TShapes` records: each one's type and the numbers it refers to.
    fn records(text: &str) -> Vec<(String, Vec<usize>)> {
        let table = text.split("TShapes ").nth(1).expect("a TShapes table");
        let mut lines = table.lines();
        let n: usize = lines.next().unwrap().trim().parse().unwrap();
        let mut out = Vec::new();
        let mut kind = None;
        for line in lines {
            match line.get(..2) {
                Some(k @ ("Ve" | "Ed" | "Wi" | "Fa" | "Sh" | "So" | "Co")) if kind.is_none() => {
                    kind = Some(k.to_string())
                }
                _ if line.ends_with('*') => {
                    let refs = line
                        .split_whitespace()
                        .filter(|t| t.starts_with(['+', '-']))
                        .map(|t| t[1..].parse().unwrap())
                        .collect();
                    out.push((kind.take().unwrap(), refs));
                }
                _ => {}
            }
        }
        assert_eq!(out.len(), n);
        out
    }

    /// Every reference is to a shape written before (numbered from the last, 1), the last
    /// shape is the root, and the counts are the model's.
    fn check_order_and_counts(brep: &Brep, text: &str, root: &str) {
        let shapes = records(text);
        let n = shapes.len();
        for (i, (kind, refs)) in shapes.iter().enumerate() {
            for &k in refs {
                assert!(k >= 1 && n - k < i, "record {i} ({kind}) refers to {k}");
            }
        }
        assert_eq!(shapes.last().unwrap().0, root);
        assert!(text.trim_end().ends_with("+1 0"));
        let count = |kind: &str| shapes.iter().filter(|(k, _)| k == kind).count();
        assert_eq!(count("Ve"), brep.vertices.len());
        assert_eq!(count("Ed"), brep.edges.len());
        assert_eq!(count("Fa"), brep.faces.len());
    }

    #[test]
    fn a_pipe_is_a_solid_whose_shapes_follow_the_shapes_they_hold() {
        let shape = sweep_wire(&pipe_route(), &circle(1.0), &[], &WireSweep::default()).unwrap();
        let text = shape.to_occ_brep().unwrap();
        check_order_and_counts(shape.brep(), &text, "So");
        if let Ok(path) = std::env::var("RMFSURF_DUMP_OCC") {
            std::fs::write(path, &text).unwrap();
        }
        // Every edge of a B-spline face has its curve on that face.
        for (e, edge_record) in text.split("\nEd\n").skip(1).enumerate() {
            let on_faces = edge_record
                .lines()
                .take_while(|l| *l != "0")
                .filter(|l| l.starts_with("2 ") || l.starts_with("3 "))
                .count();
            assert!(on_faces >= 1, "edge {e} has no curve on a face");
        }
    }

    #[test]
    fn an_open_hollow_sweep_is_a_compound_of_its_two_walls() {
        let sheet = WireSweep {
            solid: false,
            ..WireSweep::default()
        };
        let shape = sweep_wire(&pipe_route(), &square(1.0), &[circle(0.5)], &sheet).unwrap();
        let text = shape.to_occ_brep().unwrap();
        check_order_and_counts(shape.brep(), &text, "Co");
        let shells = records(&text).iter().filter(|(k, _)| k == "Sh").count();
        assert_eq!(shells, 2);
    }
}
