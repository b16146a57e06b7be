//! OpenCascade's own B-rep files of a [`Brep`], as text (`CASCADE Topology V1`, what
//! `BRepTools::Write` writes) and in the binary form (`Open CASCADE Topology V3`, what
//! `BinTools::Write` writes): `BRepTools::Read` and `BinTools::Read` — and so build123d,
//! CadQuery and FreeCAD's `Part.Shape.importBrepFromString` and `importBinary` — build the
//! shape from them as it is, with no sewing, healing or orientation measured afterwards:
//! shared edges are one edge of the kernel, every edge carries its curve on each B-spline
//! face (a seam its two curves; on a plane the kernel projects the edge itself), the faces'
//! senses and loops are the model's.
//!
//! Both files hold one shape set (OCCT's `BRepTools_ShapeSet`, `BinTools_ShapeSet`), laid
//! out by `ShapeSet`: the geometry tables — 2-D curves, 3-D curves, surfaces, each numbered
//! from 1 in the order written — then the topological shapes, every one after the shapes it
//! holds; a reference to a shape is its orientation and its number counted from the last
//! shape written (the last is 1), and the file ends with the reference to the root. A face
//! that is its whole B-spline surface is marked so (its natural restriction). Curves are
//! B-splines (a pcurve line of the model need not run at unit speed, which a 2-D line
//! would), surfaces B-splines (poles with v running fastest) or planes (origin, normal, x
//! axis, y = normal × x axis) — except the model's analytic forms: planes, cylinders, cones
//! and tori for analytic faces, lines and circles for analytic edges, and on a cylinder or
//! torus each edge's curve a 2-D line of unit speed on the edge's length or angle.
//!
//! The text (module `text`) writes numbers as the shortest text that reads back as the same
//! double; the binary file (module `binary`) writes them as they are (little-endian IEEE
//! 754), the counts as 32-bit integers, and with each curve on a face its end points in the
//! face's parameter plane (the V2 addition); a kernel reads it several times faster.

mod binary;
mod text;

pub use binary::{brep_to_occ_binary, OccBinary, OccReader};
pub use text::brep_to_occ;

use super::curve_range;
use crate::bezier::{NurbsCurve, NurbsSurface};
use crate::error::{invalid, Result};
use crate::model::{AnalyticCurve, AnalyticSurface, Brep, BrepFace, BrepSurface, PCurve};
use glam::DVec3;

/// A curve of the `Curve2ds` table.
enum Curve2d<'a> {
    /// A 2-D line (on an analytic face): origin + t · direction.
    Line {
        origin: (f64, f64),
        direction: (f64, f64),
    },
    /// A pcurve line of a B-spline face, as the degree-1 B-spline from its point at the
    /// edge's first parameter to that at its last.
    Segment {
        from: (f64, f64),
        to: (f64, f64),
        range: (f64, f64),
    },
    /// A 2-D B-spline (the x, y of its poles).
    Nurbs(&'a NurbsCurve),
}

impl Curve2d<'_> {
    /// The curve's points at the ends of the edge's range (the binary file's UV points).
    fn ends(&self, range: (f64, f64)) -> Result<[(f64, f64); 2]> {
        Ok(match self {
            Curve2d::Line { origin, direction } => [
                line_at(*origin, *direction, range.0),
                line_at(*origin, *direction, range.1),
            ],
            Curve2d::Segment { from, to, .. } => [*from, *to],
            Curve2d::Nurbs(curve) => {
                // A clamped curve on the edge's range starts at its first pole and ends at
                // its last.
                let [p, q] = if curve_range(curve) == range {
                    [curve.poles[0], curve.poles[curve.poles.len() - 1]]
                } else {
                    let pieces = curve.to_piecewise()?;
                    [pieces.eval(range.0), pieces.eval(range.1)]
                };
                [(p.x, p.y), (q.x, q.y)]
            }
        })
    }
}

/// The point of the parameter line origin + t · direction at t.
fn line_at(origin: (f64, f64), direction: (f64, f64), t: f64) -> (f64, f64) {
    (origin.0 + t * direction.0, origin.1 + t * direction.1)
}

/// A line, circle or elementary surface as both files write it: its code, then vectors and
/// numbers.
struct Elementary {
    code: u8,
    vectors: Vec<DVec3>,
    numbers: Vec<f64>,
}

impl Elementary {
    /// A line (code 1: origin, direction) or circle (code 2: centre, axis, x and y axes,
    /// radius).
    fn curve(curve: &AnalyticCurve) -> Self {
        match *curve {
            AnalyticCurve::Line { origin, direction } => Self {
                code: 1,
                vectors: vec![origin, direction],
                numbers: Vec::new(),
            },
            AnalyticCurve::Circle {
                center,
                axis,
                x_axis,
                radius,
            } => Self {
                code: 2,
                vectors: vec![center, axis, x_axis, axis.cross(x_axis)],
                numbers: vec![radius],
            },
        }
    }

    /// A plane (code 1: location, normal, x and y axes), cylinder (code 2: the same and the
    /// radius), cone (code 3: the same, the radius at v = 0 and the semi-angle) or torus
    /// (code 5: the same and the major and minor radii).
    fn surface(surface: &AnalyticSurface) -> Self {
        let code = match surface {
            AnalyticSurface::Plane { .. } => 1,
            AnalyticSurface::Cylinder { .. } => 2,
            AnalyticSurface::Cone { .. } => 3,
            AnalyticSurface::Torus { .. } => 5,
        };
        let [origin, axis, x_axis] = surface.axes();
        Self {
            code,
            vectors: vec![origin, axis, x_axis, axis.cross(x_axis)],
            numbers: surface.dimensions(),
        }
    }

    /// A plane of the model (code 1).
    fn plane(origin: DVec3, normal: DVec3, x_axis: DVec3) -> Self {
        Self {
            code: 1,
            vectors: vec![origin, normal, x_axis, normal.cross(x_axis)],
            numbers: Vec::new(),
        }
    }
}

/// A curve of the `Curves` table: one per edge, edge e the (e + 1)-th.
enum Curve3d<'a> {
    Elementary(Elementary),
    Nurbs(&'a NurbsCurve),
}

/// A surface of the `Surfaces` table: one per face, face f the (f + 1)-th.
enum Surface<'a> {
    Elementary(Elementary),
    Nurbs(&'a NurbsSurface),
}

/// An edge on one face: the numbers of its curve(s) in the face's parameter plane — two for
/// a seam, the forward use's first — and the ends of the last of them (the binary file's UV
/// points: of a seam's second curve, as the kernel keeps them).
struct OnFace {
    face: usize,
    curves: Vec<usize>,
    ends: [(f64, f64); 2],
}

/// What a topological shape is, with its own data.
enum Kind {
    Vertex(DVec3),
    Edge {
        /// The number of its 3-D curve; None for a degenerate edge, which the kernel marks so.
        curve: Option<usize>,
        range: (f64, f64),
        on_faces: Vec<OnFace>,
    },
    Wire,
    Face {
        natural: bool,
        surface: usize,
    },
    Shell,
    Solid,
    Compound,
}

/// A shape held by another: reversed or not, and its position in [`ShapeSet::shapes`].
type Held = (bool, usize);

/// A shape's record: its kind, its flags (free, modified, checked, orientable, closed,
/// infinite, convex), the shapes it holds with their orientations.
struct Record {
    kind: Kind,
    flags: &'static str,
    held: Vec<Held>,
}

/// The shape set of a B-rep as OpenCascade writes it (module notes).
struct ShapeSet<'a> {
    tolerance: f64,
    curves_2d: Vec<Curve2d<'a>>,
    curves: Vec<Curve3d<'a>>,
    surfaces: Vec<Surface<'a>>,
    /// Each after the shapes it holds; the last is the root.
    shapes: Vec<Record>,
}

/// Vertex, edge, wire, face, shell flags (free, modified, checked, orientable, closed,
/// infinite, convex): as OpenCascade writes the shapes it makes.
const VERTEX: &str = "0101101";
const EDGE: &str = "0101000";
const WIRE: &str = "0101100";
const FACE: &str = "0101000";
const CLOSED_SHELL: &str = "0101100";
const OPEN_SHELL: &str = "0101000";
/// A root shape is free.
const ROOT: &str = "1101000";
const ROOT_HOLDER: &str = "1100000";

impl<'a> ShapeSet<'a> {
    /// The shape set of `brep`: a solid of one closed shell, or an open shell (a compound of
    /// shells when its faces fall apart into parts).
    fn of(brep: &'a Brep) -> Result<Self> {
        if brep.faces.is_empty() {
            return invalid!("a shape needs at least one face");
        }
        let (curves_2d, on_edges) = curves_2d(brep)?;
        let curves = brep
            .edges
            .iter()
            .map(|edge| match &edge.analytic {
                Some(analytic) => Curve3d::Elementary(Elementary::curve(&analytic.curve)),
                None => Curve3d::Nurbs(&edge.curve),
            })
            .collect();
        let surfaces = brep
            .faces
            .iter()
            .map(|face| match (&face.analytic, &face.surface) {
                (Some(analytic), _) => Surface::Elementary(Elementary::surface(&analytic.surface)),
                (None, BrepSurface::Nurbs(surface)) => Surface::Nurbs(surface),
                (
                    None,
                    &BrepSurface::Plane {
                        origin,
                        normal,
                        x_axis,
                    },
                ) => Surface::Elementary(Elementary::plane(origin, normal, x_axis)),
            })
            .collect();
        let mut set = Self {
            tolerance: brep.tolerance(),
            curves_2d,
            curves,
            surfaces,
            shapes: Vec::new(),
        };
        set.add_shapes(brep, on_edges)?;
        Ok(set)
    }

    /// Adds a shape and returns its position (from 0).
    fn add(&mut self, kind: Kind, flags: &'static str, held: Vec<Held>) -> usize {
        self.shapes.push(Record { kind, flags, held });
        self.shapes.len() - 1
    }

    /// The topological shapes, each after those it holds, the root last.
    fn add_shapes(&mut self, brep: &Brep, on_edges: Vec<Vec<OnFace>>) -> Result<()> {
        let vertices: Vec<usize> = brep
            .vertices
            .iter()
            .map(|&p| self.add(Kind::Vertex(p), VERTEX, Vec::new()))
            .collect();
        let mut edges = Vec::with_capacity(brep.edges.len());
        for ((e, edge), on_faces) in brep.edges.iter().enumerate().zip(on_edges) {
            let (Some(&start), Some(&end)) = (vertices.get(edge.start), vertices.get(edge.end))
            else {
                return invalid!("edge {e} joins vertices that do not exist");
            };
            let range = edge
                .analytic
                .map_or_else(|| curve_range(&edge.curve), |a| (0.0, a.end));
            let kind = Kind::Edge {
                curve: (!edge.degenerate).then_some(e + 1),
                range,
                on_faces,
            };
            edges.push(self.add(kind, EDGE, vec![(false, start), (true, end)]));
        }
        let mut in_shell = Vec::with_capacity(brep.faces.len());
        for (f, face) in brep.faces.iter().enumerate() {
            let reversed = face
                .analytic
                .as_ref()
                .is_some_and(|a| a.loops_reversed(face.same_sense));
            let wires: Vec<Held> = face
                .bounds
                .iter()
                .map(|bound| {
                    let mut uses: Vec<Held> = bound
                        .uses
                        .iter()
                        .map(|u| (u.forward == reversed, edges[u.edge]))
                        .collect();
                    if reversed {
                        uses.reverse();
                    }
                    (false, self.add(Kind::Wire, WIRE, uses))
                })
                .collect();
            let same_sense = face
                .analytic
                .as_ref()
                .map_or(face.same_sense, |a| a.same_sense);
            let kind = Kind::Face {
                natural: natural_bounds(face),
                surface: f + 1,
            };
            in_shell.push((!same_sense, self.add(kind, FACE, wires)));
        }
        // A solid holds its closed shells: one, or the outer shell and the walls of cavities
        // (a hollow profile swept round a closed wire), each with its faces facing out of the
        // material. An open shape is its shell, or a compound of the shells it falls apart
        // into.
        let parts = brep.shells();
        if !brep.closed && parts.len() == 1 {
            self.add(Kind::Shell, ROOT, in_shell);
        } else {
            let flags = if brep.closed {
                CLOSED_SHELL
            } else {
                OPEN_SHELL
            };
            let shells = parts
                .iter()
                .map(|faces| {
                    let held = faces.iter().map(|&f| in_shell[f]).collect();
                    (false, self.add(Kind::Shell, flags, held))
                })
                .collect();
            let holder = if brep.closed {
                Kind::Solid
            } else {
                Kind::Compound
            };
            self.add(holder, ROOT_HOLDER, shells);
        }
        Ok(())
    }
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

/// The `Curve2ds` table (every use's pcurve, in the order of faces, loops and uses) and,
/// per edge, the faces it lies on with their curves' numbers. A use without a pcurve is
/// allowed on a plane only (the kernel projects the edge there).
fn curves_2d(brep: &Brep) -> Result<(Vec<Curve2d<'_>>, Vec<Vec<OnFace>>)> {
    let mut table = Vec::new();
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
        // of the other orientation) first: its curve is the first of the seam's two.
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
            let (curve, range) = match (analytic, &edge.analytic) {
                (Some(a), Some(e)) => {
                    let Some(&PCurve::Line { origin, direction }) =
                        a.pcurves.get(b).and_then(|p| p.get(k))
                    else {
                        return invalid!("edge {} has no curve on the analytic face {f}", u.edge);
                    };
                    (Curve2d::Line { origin, direction }, (0.0, e.end))
                }
                (None, None) => {
                    let range = curve_range(&edge.curve);
                    let curve = match &u.pcurve {
                        &Some(PCurve::Line { origin, direction }) => Curve2d::Segment {
                            from: line_at(origin, direction, range.0),
                            to: line_at(origin, direction, range.1),
                            range,
                        },
                        Some(PCurve::Curve(curve)) => Curve2d::Nurbs(curve),
                        None => return invalid!("edge {} has no curve on face {f}", u.edge),
                    };
                    (curve, range)
                }
                _ => {
                    return invalid!(
                        "edge {} and face {f} are not both analytic or both NURBS",
                        u.edge
                    )
                }
            };
            let ends = curve.ends(range)?;
            table.push(curve);
            let number = table.len();
            match on_faces.iter_mut().find(|o| o.face == f) {
                Some(on) => {
                    on.curves.push(number);
                    on.ends = ends;
                }
                None => on_faces.push(OnFace {
                    face: f,
                    curves: vec![number],
                    ends,
                }),
            }
        }
    }
    Ok((table, on_edges))
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
            std::fs::write(&path, &text).unwrap();
            let binary = shape.to_occ_binary().unwrap();
            std::fs::write(format!("{path}.bin"), binary.file(OccReader::BinTools)).unwrap();
            std::fs::write(format!("{path}.fcbin"), binary.file(OccReader::FreeCad)).unwrap();
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

    /// The count in the header `name` of a file (text or binary).
    fn section(file: &[u8], name: &str) -> usize {
        let key = format!("{name} ");
        let at = file
            .windows(key.len())
            .position(|w| w == key.as_bytes())
            .unwrap_or_else(|| panic!("no {name} section"));
        let digits: String = file[at + key.len()..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .map(|&b| char::from(b))
            .collect();
        digits.parse().unwrap()
    }

    /// The binary file holds the text's set: the version line, the same counts of 2-D
    /// curves, curves, surfaces and shapes, and ends with the root as each reader takes it.
    #[test]
    fn the_binary_file_holds_the_text_s_shape_set() {
        let hollow = WireSweep {
            solid: false,
            ..WireSweep::default()
        };
        for (shape, root) in [
            (
                sweep_wire(&pipe_route(), &circle(1.0), &[], &WireSweep::default()).unwrap(),
                "So",
            ),
            (
                sweep_wire(&pipe_route(), &square(1.0), &[circle(0.5)], &hollow).unwrap(),
                "Co",
            ),
        ] {
            let text = shape.to_occ_brep().unwrap();
            let binary = shape.to_occ_binary().unwrap();
            let bintools = binary.file(OccReader::BinTools);
            let freecad = binary.file(OccReader::FreeCad);
            assert!(bintools.starts_with(b"\nOpen CASCADE Topology V3 (c)\nLocations 0\n"));
            for name in ["Curve2ds", "Curves", "Surfaces", "TShapes"] {
                assert_eq!(
                    section(&bintools, name),
                    section(text.as_bytes(), name),
                    "{name}"
                );
            }
            let n = section(&bintools, "TShapes");
            assert_eq!(n, records(&text).len());
            assert_eq!(records(&text).last().unwrap().0, root);
            let set = binary.set();
            assert_eq!(bintools[..set.len()], *set);
            assert_eq!(bintools[set.len()..], [0, 1, 0, 0, 0, 0, 0, 0, 0]);
            let mut freecad_root = (n as i32).to_le_bytes().to_vec();
            freecad_root.extend([0; 8]);
            assert_eq!(freecad[set.len()..], freecad_root[..]);
            // The last shape record ends its list of held shapes.
            assert_eq!(set.last(), Some(&b'*'));
        }
    }
}
