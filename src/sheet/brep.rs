//! The B-rep of a sheet part's solid, from its construction: per piece of the trimmed cone
//! spline ([LP] Fig. 1) two layer faces and two cut faces, and for an open part the two end
//! faces, every face one rational patch of degree 1 across (see `trim`). Each face's side
//! is named by what it is — a boundary row of a piece on a layer, the cut across the
//! thickness at a ruling on a boundary, a ruling on a layer — and faces naming the same
//! side share one edge, with one curve. Sides collapsed to a point (a boundary through a
//! cone's apex) become degenerate edges of their face, and a face two of whose opposite
//! sides collapse (no area: the cut at a corner of the boundary, a crease on a layer) is
//! left out, its other two sides — then one segment — joined into one edge.

use crate::bezier::{NurbsCurve, NurbsSurface};
use crate::math::Classes;
use crate::model::{Brep, BrepBound, BrepEdge, BrepFace, BrepSurface, BrepUse, PCurve};
use glam::DVec3;
use std::collections::HashMap;

/// A side of the part's faces, by construction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum EdgeKey {
    /// Boundary `side` of piece `piece` on `layer` (0 the lower offset, 1 the upper), from
    /// the piece's first ruling to its last.
    Row {
        piece: usize,
        side: usize,
        layer: usize,
    },
    /// Across the thickness at `ruling` on boundary `side`, from layer 0 to layer 1.
    Thickness { ruling: usize, side: usize },
    /// Ruling `ruling` on `layer`, from the first boundary to the second.
    Ruling { ruling: usize, layer: usize },
}

/// A point of the part: on `ruling`, boundary `side`, `layer`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct VertexKey {
    ruling: usize,
    side: usize,
    layer: usize,
}

impl EdgeKey {
    /// The vertices the side runs between; `next` is the ruling after a piece's first.
    fn ends(self, next: impl Fn(usize) -> usize) -> [VertexKey; 2] {
        let v = |ruling, side, layer| VertexKey {
            ruling,
            side,
            layer,
        };
        match self {
            EdgeKey::Row { piece, side, layer } => {
                [v(piece, side, layer), v(next(piece), side, layer)]
            }
            EdgeKey::Thickness { ruling, side } => [v(ruling, side, 0), v(ruling, side, 1)],
            EdgeKey::Ruling { ruling, layer } => [v(ruling, 0, layer), v(ruling, 1, layer)],
        }
    }
}

/// A face of the part: its surface, normal ∂u × ∂v out of the solid, and its sides in the
/// order of [`NurbsSurface::boundary_line`] (v = 0, u = 1, v = 1, u = 0), each with
/// whether the side's curve runs along the surface's parameter there and whether it is a
/// point.
pub(super) struct PartFace {
    pub surface: NurbsSurface,
    pub sides: [(EdgeKey, bool); 4],
    pub collapsed: [bool; 4],
}

/// The side `s` of a face's surface, run the side's way (`along`: the surface's way).
fn side_curve(face: &PartFace, s: usize) -> NurbsCurve {
    let curve = face.surface.boundary_curve(s);
    if face.sides[s].1 {
        curve
    } else {
        curve.reversed()
    }
}

/// The solid bounded by `faces`; `next` gives the ruling after a piece's first (the first
/// again after the last of a closed part).
pub(super) fn solid(faces: &[PartFace], next: impl Fn(usize) -> usize) -> Brep {
    let mut ids: HashMap<EdgeKey, usize> = HashMap::new();
    let mut keys: Vec<EdgeKey> = Vec::new();
    let mut classes = Classes::default();
    let mut side_ids = Vec::with_capacity(faces.len());
    for face in faces {
        side_ids.push(face.sides.map(|(key, _)| {
            *ids.entry(key).or_insert_with(|| {
                keys.push(key);
                classes.add()
            })
        }));
    }
    // Faces without area: their two other sides are one segment, run the same way.
    let mut kept = vec![true; faces.len()];
    for (f, face) in faces.iter().enumerate() {
        let points = face.collapsed;
        for (a, b) in [(0, 2), (1, 3)] {
            let (c, d) = ((a + 1) % 4, (b + 1) % 4);
            if points[c] && points[d] {
                kept[f] = false;
                if !(points[a] && points[b]) {
                    let reversed = face.sides[a].1 != face.sides[b].1;
                    classes.join(side_ids[f][a], side_ids[f][b], reversed);
                }
            }
        }
    }
    // Vertices: the ends of sides of one class are one; a collapsed side's ends are one.
    let mut vertex_ids: HashMap<VertexKey, usize> = HashMap::new();
    let mut points = Classes::default();
    let mut vertex = |key: VertexKey, points: &mut Classes| {
        *vertex_ids.entry(key).or_insert_with(|| points.add())
    };
    for (k, &key) in keys.iter().enumerate() {
        let [a, b] = key.ends(&next).map(|v| vertex(v, &mut points));
        let (root, against) = classes.find(k);
        let [ra, rb] = keys[root].ends(&next).map(|v| vertex(v, &mut points));
        let (ra, rb) = if against { (rb, ra) } else { (ra, rb) };
        points.join(a, ra, false);
        points.join(b, rb, false);
    }
    for face in faces {
        for s in (0..4).filter(|&s| face.collapsed[s]) {
            let [a, b] = face.sides[s].0.ends(&next).map(|v| vertex(v, &mut points));
            points.join(a, b, false);
        }
    }
    let mut brep = Brep {
        vertices: Vec::new(),
        edges: Vec::new(),
        faces: Vec::with_capacity(faces.len()),
        closed: true,
    };
    let mut vertex_of: HashMap<usize, usize> = HashMap::new();
    let mut place = |key: VertexKey, at: DVec3, brep: &mut Brep| {
        let (root, _) = points.find(vertex_ids[&key]);
        *vertex_of.entry(root).or_insert_with(|| {
            brep.vertices.push(at);
            brep.vertices.len() - 1
        })
    };
    // Per class: its edge and whether the edge runs against the class's root.
    let mut edge_of: HashMap<usize, (usize, bool)> = HashMap::new();
    for (f, face) in faces.iter().enumerate().filter(|&(f, _)| kept[f]) {
        let mut uses = Vec::with_capacity(4);
        for (s, &side) in side_ids[f].iter().enumerate() {
            let (key, along) = face.sides[s];
            let curve = side_curve(face, s);
            let [start, end] = key.ends(&next);
            let (start, end) = (
                place(start, curve.poles[0], &mut brep),
                place(end, curve.poles[curve.poles.len() - 1], &mut brep),
            );
            // A collapsed side is its face's own degenerate edge; the others share their
            // class's edge, made by the first face to come to it, running its way.
            let (root, against_root) = classes.find(side);
            let degenerate = face.collapsed[s];
            let shared = if degenerate {
                None
            } else {
                edge_of.get(&root).copied()
            };
            let (edge, against) = match shared {
                Some((edge, edge_against_root)) => (edge, edge_against_root != against_root),
                None => {
                    brep.edges.push(BrepEdge {
                        curve,
                        start,
                        end,
                        degenerate,
                        analytic: None,
                    });
                    let edge = brep.edges.len() - 1;
                    if !degenerate {
                        edge_of.insert(root, (edge, against_root));
                    }
                    (edge, false)
                }
            };
            // The loop runs counter-clockwise: sides 0 and 1 along the surface's parameter.
            let with_parameter = along != against;
            let (a, b) = crate::export::curve_range(&brep.edges[edge].curve);
            let (origin, direction) = face.surface.boundary_line(s);
            let pcurve = if with_parameter {
                PCurve::Line { origin, direction }
            } else {
                PCurve::Line {
                    origin: (
                        origin.0 + (a + b) * direction.0,
                        origin.1 + (a + b) * direction.1,
                    ),
                    direction: (-direction.0, -direction.1),
                }
            };
            uses.push(BrepUse {
                edge,
                forward: with_parameter == (s < 2),
                pcurve: Some(pcurve),
            });
        }
        brep.faces.push(BrepFace {
            surface: BrepSurface::Nurbs(face.surface.clone()),
            same_sense: true,
            bounds: vec![BrepBound { uses, outer: true }],
            analytic: None,
        });
    }
    brep
}
