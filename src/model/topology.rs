//! The boundary representation the constructions build and the exporters and the C layer
//! read: vertices; edges with their 3-D curve, shared by the faces whose loops use them;
//! loops of oriented edge uses, each with the edge's curve in the face's parameter plane;
//! faces on surfaces with their sense. Shared edges are shared by construction (one curve,
//! used by both faces), and orientation is known where the faces are made, never measured
//! afterwards.

use super::analytic::{AnalyticEdge, AnalyticFace};
use crate::bezier::{NurbsCurve, NurbsSurface};
use crate::math::Classes;
use glam::DVec3;

/// A boundary representation: faces on surfaces, bounded by loops of shared edges
/// between shared vertices.
#[derive(Clone, Debug, PartialEq)]
pub struct Brep {
    /// The vertices the edges start and end at.
    pub vertices: Vec<DVec3>,
    /// The edges, each shared by the faces whose loops use it.
    pub edges: Vec<BrepEdge>,
    /// The faces.
    pub faces: Vec<BrepFace>,
    /// The faces bound a solid (a closed shell); otherwise a sheet (an open shell).
    pub closed: bool,
}

/// An edge: its 3-D curve from the vertex `start` (at the curve's first parameter) to `end`.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepEdge {
    /// The 3-D curve, on its own parameter.
    pub curve: NurbsCurve,
    /// Index of the vertex at the curve's first parameter.
    pub start: usize,
    /// Index of the vertex at the curve's last parameter.
    pub end: usize,
    /// A side of a face's surface collapsed to a point (a cone's apex on a boundary): the
    /// curve is that point, `start` = `end`, and the edge is used by one face, whose
    /// parameter curve alone says where it runs. STEP leaves it out of the loops; the
    /// OpenCascade kernel needs it to close the loop in the parameter plane.
    pub degenerate: bool,
    /// The same curve as a line or circle, where it is one and every face using the edge
    /// is analytic or planar (then a writer may write it so; see [`AnalyticFace`]).
    pub analytic: Option<AnalyticEdge>,
}

/// An edge's curve in a face's parameter plane, on the edge curve's parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum PCurve {
    /// origin + t · direction.
    Line {
        /// A point of the line in the face's parameter plane.
        origin: (f64, f64),
        /// Its direction, per unit of the edge curve's parameter.
        direction: (f64, f64),
    },
    /// A 2-D curve (the x, y of its poles).
    Curve(NurbsCurve),
}

/// An edge used by a face's loop, along its curve (`forward`) or against it.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepUse {
    /// Index of the edge in [`Brep::edges`].
    pub edge: usize,
    /// Whether the loop runs along the edge curve (true) or against it.
    pub forward: bool,
    /// The edge's curve in the face's parameter plane, if known (written as a PCURVE; None:
    /// the 3-D curve alone).
    pub pcurve: Option<PCurve>,
}

/// A loop of a face: counter-clockwise in the face's parameter plane (about its normal)
/// for the outer bound, clockwise for holes.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepBound {
    /// The edge uses in the loop's order, each starting where the one before ends.
    pub uses: Vec<BrepUse>,
    /// Whether this is the face's outer bound (else a hole).
    pub outer: bool,
}

/// The surface a face lies on.
#[derive(Clone, Debug, PartialEq)]
pub enum BrepSurface {
    /// A NURBS surface, on its own parameters.
    Nurbs(NurbsSurface),
    /// The plane through `origin` with unit `normal`; parameters along `x_axis` and
    /// `normal × x_axis`.
    Plane {
        /// A point of the plane.
        origin: DVec3,
        /// Its unit normal.
        normal: DVec3,
        /// The unit direction of the first parameter, in the plane.
        x_axis: DVec3,
    },
}

/// A face: its surface, whether the face's normal is the surface's (`same_sense`), its
/// loops.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepFace {
    /// The surface the face lies on.
    pub surface: BrepSurface,
    /// Whether the face's normal is the surface's normal (else its opposite).
    pub same_sense: bool,
    /// The loops: the outer bound and the holes.
    pub bounds: Vec<BrepBound>,
    /// The same face on a plane, cylinder or torus, where its surface is one and every edge
    /// it uses is analytic (planes: any edges).
    pub analytic: Option<AnalyticFace>,
}

/// The geometry's tolerance relative to its largest coordinate (rounding of the model's
/// geometry is some 1e-15 of it), and its floor: OpenCascade's `Precision::Confusion`.
const RELATIVE_TOLERANCE: f64 = 1e-10;
const KERNEL_CONFUSION: f64 = 1e-7;

impl Brep {
    /// The distance within which the model's vertices, edges and faces meet, for a kernel
    /// building it: 1e-10 of its largest coordinate, at least 1e-7 (OpenCascade's
    /// `Precision::Confusion`).
    pub fn tolerance(&self) -> f64 {
        let largest = self
            .vertices
            .iter()
            .chain(self.edges.iter().flat_map(|e| &e.curve.poles))
            .map(|p| p.abs().max_element())
            .fold(0.0, f64::max);
        (RELATIVE_TOLERANCE * largest).max(KERNEL_CONFUSION)
    }

    /// The faces grouped into shells by the edges they share, each shell's faces in the
    /// order of the faces: one shell for a solid; an open shape may fall apart into several
    /// (the outer and the inner walls of a hollow profile).
    pub fn shells(&self) -> Vec<Vec<usize>> {
        let mut classes = Classes::new(self.faces.len());
        let mut first_face: Vec<Option<usize>> = vec![None; self.edges.len()];
        for (f, face) in self.faces.iter().enumerate() {
            for u in face.bounds.iter().flat_map(|b| &b.uses) {
                match first_face.get_mut(u.edge) {
                    Some(Some(g)) => classes.join(*g, f, false),
                    Some(slot) => *slot = Some(f),
                    None => {}
                }
            }
        }
        let mut shell_of_root: Vec<Option<usize>> = vec![None; self.faces.len()];
        let mut shells: Vec<Vec<usize>> = Vec::new();
        for f in 0..self.faces.len() {
            let (root, _) = classes.find(f);
            match shell_of_root[root] {
                Some(s) => shells[s].push(f),
                None => {
                    shell_of_root[root] = Some(shells.len());
                    shells.push(vec![f]);
                }
            }
        }
        shells
    }
}
