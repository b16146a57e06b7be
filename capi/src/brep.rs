//! RmfBrep: a shape's boundary representation for a kernel to build natively — vertices,
//! edges with their 3-D curve, oriented loops of edge uses with each edge's curve in the
//! face's parameter plane, faces with their surface and sense, shells — as counts and
//! borrowed views (the model of `rmfsurf::Brep`). Wire sweeps (rmf_shape_brep) and sheet
//! parts (rmf_sheet_part_brep) hand it out; `include/rmfsurf_occ.hpp` builds an
//! OpenCascade shape from it with BRep_Builder.

use super::boundary::{
    free_handle, guard, invalid_arg, out_ptr, reference, slice, write, FfiError, FfiResult,
};
use super::status::RmfStatus;
use super::types::{RmfNurbsCurve, RmfNurbsSurface, RmfVec2, RmfVec3};
use rmfsurf::export::occ_brep::OccBinary;
use rmfsurf::{
    AnalyticCurve, AnalyticEdge, AnalyticFace, AnalyticSurface, Brep, BrepBound, BrepEdge,
    BrepFace, BrepSurface, BrepUse, PCurve,
};

/// RmfBrepFace.kind: a rational B-spline surface (RmfBrepFace.nurbs).
/// \ingroup rmf_brep
pub const RMF_BREP_SURFACE_NURBS: u32 = 0;
/// RmfBrepFace.kind: a plane (plane_origin, plane_normal, plane_x_axis); its parameters run
/// along plane_x_axis and plane_normal × plane_x_axis.
/// \ingroup rmf_brep
pub const RMF_BREP_SURFACE_PLANE: u32 = 1;

/// RmfBrepUse.pcurve_kind: no curve in the face's parameter plane (on a plane: the kernel
/// projects the edge).
/// \ingroup rmf_brep
pub const RMF_PCURVE_NONE: u32 = 0;
/// RmfBrepUse.pcurve_kind: the line line_origin + t · line_direction, t the edge curve's
/// parameter.
/// \ingroup rmf_brep
pub const RMF_PCURVE_LINE: u32 = 1;
/// RmfBrepUse.pcurve_kind: the 2-D NURBS curve RmfBrepUse.pcurve (x, y of its poles; z is
/// 0), on the edge curve's parameter.
/// \ingroup rmf_brep
pub const RMF_PCURVE_NURBS: u32 = 2;

/// RmfBrepAnalytic.kind: the face or edge is only its NURBS (or plane) view.
/// \ingroup rmf_brep
pub const RMF_ANALYTIC_NONE: u32 = 0;
/// RmfBrepAnalytic.kind of a face: the plane through location with unit normal axis;
/// parameters along x_axis and axis × x_axis.
/// \ingroup rmf_brep
pub const RMF_ANALYTIC_PLANE: u32 = 1;
/// RmfBrepAnalytic.kind of a face: the cylinder location + radius (cos u x + sin u y) + v
/// axis, y = axis × x_axis (OpenCascade's Geom_CylindricalSurface).
/// \ingroup rmf_brep
pub const RMF_ANALYTIC_CYLINDER: u32 = 2;
/// RmfBrepAnalytic.kind of a face: the torus location + (radius + minor_radius cos v)(cos u
/// x + sin u y) + minor_radius sin v axis (OpenCascade's Geom_ToroidalSurface).
/// \ingroup rmf_brep
pub const RMF_ANALYTIC_TORUS: u32 = 3;
/// RmfBrepAnalytic.kind of a face: the cone location + (radius + v sin α)(cos u x + sin u
/// y) + v cos α axis, α = semi_angle, y = axis × x_axis (Geom_ConicalSurface).
/// \ingroup rmf_brep
pub const RMF_ANALYTIC_CONE: u32 = 6;
/// RmfBrepAnalytic.kind of an edge: the line location + s axis (axis a unit vector), s
/// from 0 at the edge's start vertex to end (Geom_Line).
/// \ingroup rmf_brep
pub const RMF_ANALYTIC_LINE: u32 = 4;
/// RmfBrepAnalytic.kind of an edge: the circle location + radius (cos s x + sin s y),
/// y = axis × x_axis, s from 0 at the edge's start vertex to end (Geom_Circle).
/// \ingroup rmf_brep
pub const RMF_ANALYTIC_CIRCLE: u32 = 5;

/// A boundary representation (see rmf_brep_counts). Free with rmf_brep_free; the views the
/// accessors give are borrowed from it.
/// \ingroup rmf_brep
pub struct RmfBrep {
    counts: RmfBrepCounts,
    vertices: Vec<RmfVec3>,
    edges: Vec<RmfBrepEdge>,
    faces: Vec<RmfBrepFace>,
    loops: Vec<Vec<RmfBrepLoop>>,
    /// [face][loop][use].
    uses: Vec<Vec<Vec<RmfBrepUse>>>,
    shells: Vec<Vec<usize>>,
    /// [face][loop][use] on the analytic faces (empty elsewhere).
    analytic_uses: Vec<Vec<Vec<RmfBrepUse>>>,
    /// What the views point into: the model (weights, knots) and the poles in the C layout.
    /// Neither changes after the views are made (moving the handle moves no buffer).
    model: Brep,
    _poles: Vec<Vec<RmfVec3>>,
    /// OpenCascade's binary B-rep of the model, made on the first rmf_brep_occ_binary.
    occ_binary: std::sync::OnceLock<OccBinary>,
}

impl RmfBrep {
    pub(crate) fn new(brep: Brep) -> Self {
        let mut poles: Vec<Vec<RmfVec3>> = Vec::new();
        let mut keep = |points: &[rmfsurf::glam::DVec3]| -> *const RmfVec3 {
            let c: Vec<RmfVec3> = points.iter().map(|&p| p.into()).collect();
            let at = c.as_ptr();
            poles.push(c);
            at
        };
        let edges = brep
            .edges
            .iter()
            .map(|e| RmfBrepEdge {
                start: e.start,
                end: e.end,
                degenerate: u32::from(e.degenerate),
                curve: RmfNurbsCurve::of(&e.curve, keep(e.curve.poles())),
            })
            .collect();
        let faces = brep.faces.iter().map(|f| face_view(f, &mut keep)).collect();
        let loops = brep
            .faces
            .iter()
            .map(|f| {
                f.bounds
                    .iter()
                    .map(|b| RmfBrepLoop {
                        outer: u32::from(b.outer),
                        use_count: b.uses.len(),
                    })
                    .collect()
            })
            .collect();
        let uses = brep
            .faces
            .iter()
            .map(|f| {
                f.bounds
                    .iter()
                    .map(|b| b.uses.iter().map(|u| use_view(u, &mut keep)).collect())
                    .collect()
            })
            .collect();
        let shells = brep.shells();
        let analytic_uses = brep
            .faces
            .iter()
            .map(|f| match &f.analytic {
                Some(a) => analytic_use_views(f, a),
                None => Vec::new(),
            })
            .collect();
        Self {
            counts: RmfBrepCounts {
                vertex_count: brep.vertices.len(),
                edge_count: brep.edges.len(),
                face_count: brep.faces.len(),
                shell_count: shells.len(),
                solid: u32::from(brep.closed),
                tolerance: brep.tolerance(),
            },
            vertices: brep.vertices.iter().map(|&p| p.into()).collect(),
            edges,
            faces,
            loops,
            uses,
            shells,
            analytic_uses,
            model: brep,
            _poles: poles,
            occ_binary: std::sync::OnceLock::new(),
        }
    }

    pub(crate) fn into_raw(self) -> *mut Self {
        Box::into_raw(Box::new(self))
    }

    /// The model the views describe.
    pub(crate) fn model(&self) -> &Brep {
        &self.model
    }
}

fn face_view(
    face: &BrepFace,
    keep: &mut impl FnMut(&[rmfsurf::glam::DVec3]) -> *const RmfVec3,
) -> RmfBrepFace {
    let zero = RmfVec3::default();
    let (kind, nurbs, [plane_origin, plane_normal, plane_x_axis]) = match &face.surface {
        BrepSurface::Nurbs(s) => (
            RMF_BREP_SURFACE_NURBS,
            RmfNurbsSurface::of(s, keep(s.poles())),
            [zero; 3],
        ),
        BrepSurface::Plane {
            origin,
            normal,
            x_axis,
        } => (
            RMF_BREP_SURFACE_PLANE,
            RmfNurbsSurface::default(),
            [(*origin).into(), (*normal).into(), (*x_axis).into()],
        ),
    };
    RmfBrepFace {
        kind,
        nurbs,
        plane_origin,
        plane_normal,
        plane_x_axis,
        same_sense: u32::from(face.same_sense),
        loop_count: face.bounds.len(),
    }
}

/// The uses of an analytic face with their curves on the analytic surface (none on a
/// plane), in the order and directions that run outer loops counter-clockwise on it.
fn analytic_use_views(face: &BrepFace, analytic: &AnalyticFace) -> Vec<Vec<RmfBrepUse>> {
    let reversed = analytic.loops_reversed(face.same_sense);
    face.bounds
        .iter()
        .enumerate()
        .map(|(b, bound)| {
            let mut views: Vec<RmfBrepUse> = bound
                .uses
                .iter()
                .enumerate()
                .map(|(k, u)| {
                    let view = BrepUse {
                        edge: u.edge,
                        forward: u.forward != reversed,
                        pcurve: analytic.pcurves.get(b).and_then(|p| p.get(k)).cloned(),
                    };
                    use_view(&view, &mut |_| std::ptr::null())
                })
                .collect();
            if reversed {
                views.reverse();
            }
            views
        })
        .collect()
}

/// The analytic view of a face.
fn analytic_face_view(face: &BrepFace) -> RmfBrepAnalytic {
    let Some(analytic) = &face.analytic else {
        return RmfBrepAnalytic::default();
    };
    let [location, axis, x_axis] = analytic.surface.axes();
    let (kind, radius, minor_radius, semi_angle) = match analytic.surface {
        AnalyticSurface::Plane { .. } => (RMF_ANALYTIC_PLANE, 0.0, 0.0, 0.0),
        AnalyticSurface::Cylinder { radius, .. } => (RMF_ANALYTIC_CYLINDER, radius, 0.0, 0.0),
        AnalyticSurface::Cone {
            radius, semi_angle, ..
        } => (RMF_ANALYTIC_CONE, radius, 0.0, semi_angle),
        AnalyticSurface::Torus { major, minor, .. } => (RMF_ANALYTIC_TORUS, major, minor, 0.0),
    };
    RmfBrepAnalytic {
        kind,
        location: location.into(),
        axis: axis.into(),
        x_axis: x_axis.into(),
        radius,
        minor_radius,
        semi_angle,
        end: 0.0,
        same_sense: u32::from(analytic.same_sense),
    }
}

/// The analytic view of an edge.
fn analytic_edge_view(edge: &BrepEdge) -> RmfBrepAnalytic {
    let Some(AnalyticEdge { curve, end }) = edge.analytic else {
        return RmfBrepAnalytic::default();
    };
    let (kind, location, axis, x_axis, radius) = match curve {
        AnalyticCurve::Line { origin, direction } => (
            RMF_ANALYTIC_LINE,
            origin,
            direction,
            rmfsurf::glam::DVec3::ZERO,
            0.0,
        ),
        AnalyticCurve::Circle {
            center,
            axis,
            x_axis,
            radius,
        } => (RMF_ANALYTIC_CIRCLE, center, axis, x_axis, radius),
    };
    RmfBrepAnalytic {
        kind,
        location: location.into(),
        axis: axis.into(),
        x_axis: x_axis.into(),
        radius,
        minor_radius: 0.0,
        semi_angle: 0.0,
        end,
        same_sense: 1,
    }
}

fn use_view(
    u: &BrepUse,
    keep: &mut impl FnMut(&[rmfsurf::glam::DVec3]) -> *const RmfVec3,
) -> RmfBrepUse {
    let zero = RmfVec2 { x: 0.0, y: 0.0 };
    let (pcurve_kind, line_origin, line_direction, pcurve) = match &u.pcurve {
        None => (RMF_PCURVE_NONE, zero, zero, RmfNurbsCurve::default()),
        Some(PCurve::Line { origin, direction }) => (
            RMF_PCURVE_LINE,
            RmfVec2 {
                x: origin.0,
                y: origin.1,
            },
            RmfVec2 {
                x: direction.0,
                y: direction.1,
            },
            RmfNurbsCurve::default(),
        ),
        Some(PCurve::Curve(c)) => (
            RMF_PCURVE_NURBS,
            zero,
            zero,
            RmfNurbsCurve::of(c, keep(c.poles())),
        ),
    };
    RmfBrepUse {
        edge: u.edge,
        forward: u32::from(u.forward),
        pcurve_kind,
        line_origin,
        line_direction,
        pcurve,
    }
}

/// The sizes of a B-rep and its tolerance.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfBrepCounts {
    /// Number of vertices (rmf_brep_vertex).
    pub vertex_count: usize,
    /// Number of edges (rmf_brep_edge), each shared by the faces whose loops use it.
    pub edge_count: usize,
    /// Number of faces (rmf_brep_face).
    pub face_count: usize,
    /// Number of shells (rmf_brep_shell): 1 for a solid; an open shape may have several
    /// (the two walls of a hollow profile).
    pub shell_count: usize,
    /// 1 if the shell bounds a solid (closed, faces oriented outwards), 0 for a sheet.
    pub solid: u32,
    /// The distance within which vertices, edges and faces meet: 1e-10 of the largest
    /// coordinate, at least 1e-7 (OpenCascade's Precision::Confusion). A kernel's
    /// tolerance for every vertex, edge and face.
    pub tolerance: f64,
}

/// An edge: its 3-D curve from vertex start (at the curve's first knot) to vertex end.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBrepEdge {
    /// Index of the vertex at the curve's first parameter.
    pub start: usize,
    /// Index of the vertex at the curve's last parameter.
    pub end: usize,
    /// 1 for a side of a face collapsed to a point (a cone's apex on a boundary): start ==
    /// end, the curve is that point, the edge is used by one face and only its curve in
    /// that face's parameter plane says where it runs (OpenCascade: a degenerated edge,
    /// without a 3-D curve).
    pub degenerate: u32,
    /// The 3-D curve, borrowed from the B-rep.
    pub curve: RmfNurbsCurve,
}

/// A face: its surface, whether its outward normal is the surface's, its loops.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBrepFace {
    /// RMF_BREP_SURFACE_NURBS or RMF_BREP_SURFACE_PLANE.
    pub kind: u32,
    /// RMF_BREP_SURFACE_NURBS: the surface, borrowed from the B-rep (zero otherwise).
    pub nurbs: RmfNurbsSurface,
    /// RMF_BREP_SURFACE_PLANE: a point of the plane (zero otherwise).
    pub plane_origin: RmfVec3,
    /// RMF_BREP_SURFACE_PLANE: the plane's unit normal, the normal of its parameters.
    pub plane_normal: RmfVec3,
    /// RMF_BREP_SURFACE_PLANE: the unit direction of the first parameter.
    pub plane_x_axis: RmfVec3,
    /// 1 if the face's normal (out of a solid) is the surface's, 0 if its opposite.
    pub same_sense: u32,
    /// Number of loops (rmf_brep_loop): the outer bound and the holes.
    pub loop_count: usize,
}

/// A loop of a face: counter-clockwise in the face's parameter plane (about the surface's
/// normal) for the outer bound, clockwise for holes.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfBrepLoop {
    /// 1 for the face's outer bound, 0 for a hole.
    pub outer: u32,
    /// Number of edge uses (rmf_brep_use), each starting where the one before ends.
    pub use_count: usize,
}

/// An edge used by a loop, along its curve or against it, with its curve in the face's
/// parameter plane. An edge a face uses twice (a seam) has one use each way.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBrepUse {
    /// Index of the edge.
    pub edge: usize,
    /// 1 if the loop runs along the edge's curve, 0 against it.
    pub forward: u32,
    /// RMF_PCURVE_NONE, RMF_PCURVE_LINE or RMF_PCURVE_NURBS.
    pub pcurve_kind: u32,
    /// RMF_PCURVE_LINE: the point (u, v) at the edge curve's parameter 0.
    pub line_origin: RmfVec2,
    /// RMF_PCURVE_LINE: (du, dv) per unit of the edge curve's parameter.
    pub line_direction: RmfVec2,
    /// RMF_PCURVE_NURBS: the curve (x, y of the poles are u, v), borrowed from the B-rep.
    pub pcurve: RmfNurbsCurve,
}

/// The analytic form of a face (plane, cylinder, cone, torus) or an edge (line, circle), on
/// OpenCascade's parameters. A kernel holding analytic geometry builds such a face on the
/// analytic surface, with the analytic curve of every edge it uses (each is analytic:
/// rmf_brep_edge_analytic) and each use's curve from rmf_brep_analytic_use; an analytic
/// edge is used only by analytic or planar faces. The NURBS views describe the same
/// geometry and stay consistent among themselves.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfBrepAnalytic {
    /// RMF_ANALYTIC_NONE, or RMF_ANALYTIC_PLANE, _CYLINDER, _CONE, _TORUS (faces),
    /// RMF_ANALYTIC_LINE, _CIRCLE (edges).
    pub kind: u32,
    /// The plane's point, the cylinder's or cone's point on the axis at v = 0, the torus's
    /// or the circle's centre, the line's point at s = 0.
    pub location: RmfVec3,
    /// The unit normal of the plane or circle, the unit axis of the cylinder or torus, the
    /// unit direction of the line.
    pub axis: RmfVec3,
    /// The unit direction of the first parameter (u = 0 or s = 0), perpendicular to axis
    /// (zero for a line).
    pub x_axis: RmfVec3,
    /// The radius of the cylinder or circle, the cone's radius at v = 0, the torus's major
    /// radius (distance of the tube's centre from the axis).
    pub radius: f64,
    /// The torus's minor radius (the tube's).
    pub minor_radius: f64,
    /// The cone's semi-angle α between its rulings and its axis (|α| < π/2, radians).
    pub semi_angle: f64,
    /// Edges: the parameter of the end vertex (the line's length, the arc's angle).
    pub end: f64,
    /// Faces: 1 if the face's normal (out of a solid) is the analytic surface's, 0 if its
    /// opposite (it may differ from RmfBrepFace.same_sense).
    pub same_sense: u32,
}

/// A shell: the faces it holds.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBrepShell {
    /// Number of faces.
    pub face_count: usize,
    /// face_count face indices, borrowed from the B-rep.
    pub faces: *const usize,
}

/// Frees a B-rep; its views become invalid. NULL is a no-op.
///
/// @param[in] brep The B-rep to free, or NULL.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_free(brep: *mut RmfBrep) {
    free_handle(brep)
}

/// The B-rep in OpenCascade's binary B-rep ("Open CASCADE Topology V3", what
/// BinTools::Write writes) into a caller buffer, as rmf_shape_occ_binary writes a shape's:
/// a solid of its closed shell, or its open shell (a compound of the shells it falls apart
/// into), built by the kernel as it is. The way to hand a sheet-metal part's solid
/// (rmf_sheet_part_brep) or a B-rep of rmf_brep_create to OpenCascade or FreeCAD.
///
/// Size query: with capacity 0 (buffer may be NULL) only length is written. Otherwise the
/// file is written if capacity ≥ length.
///
/// @param[in] brep The B-rep.
/// @param[in] reader RMF_OCC_READER_*.
/// @param[out] buffer capacity bytes for the file.
/// @param[in] capacity Size of buffer in bytes; 0 for a size query.
/// @param[out] length Receives the length of the file in bytes.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If brep or length is NULL, or buffer is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_INVALID_INPUT If reader is not an RMF_OCC_READER_* value, or the
///         B-rep has no face.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity < length; length is written.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_occ_binary(
    brep: *const RmfBrep,
    reader: crate::shape::RmfOccReader,
    buffer: *mut u8,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_brep_occ_binary", || {
        let b = reference(brep, "brep")?;
        let make = || rmfsurf::export::occ_brep::brep_to_occ_binary(&b.model);
        crate::shape::hand_occ_binary(&b.occ_binary, make, reader, buffer, capacity, length)
    })
}

/// The sizes of a B-rep, whether it is a solid, and its tolerance.
///
/// @param[in] brep The B-rep.
/// @param[out] out Receives the counts.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_counts(
    brep: *const RmfBrep,
    out: *mut RmfBrepCounts,
) -> RmfStatus {
    guard("rmf_brep_counts", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        write(out, b.counts);
        Ok(())
    })
}

/// The element `index` of `items` (`what` and `name` for the message).
fn item<'a, T>(items: &'a [T], index: usize, name: &str, what: &str) -> FfiResult<&'a T> {
    match items.get(index) {
        Some(item) => Ok(item),
        None => invalid_arg(format!(
            "{name} = {index} but the B-rep has {} {what}",
            items.len()
        )),
    }
}

/// Vertex `index` of a B-rep.
///
/// @param[in] brep The B-rep.
/// @param[in] index 0 ≤ index < vertex_count.
/// @param[out] out Receives the point.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_vertex(
    brep: *const RmfBrep,
    index: usize,
    out: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_brep_vertex", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        write(out, *item(&b.vertices, index, "index", "vertices")?);
        Ok(())
    })
}

/// Edge `index` of a B-rep.
///
/// @param[in] brep The B-rep.
/// @param[in] index 0 ≤ index < edge_count.
/// @param[out] out Receives the edge; its curve is borrowed from the B-rep.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_edge(
    brep: *const RmfBrep,
    index: usize,
    out: *mut RmfBrepEdge,
) -> RmfStatus {
    guard("rmf_brep_edge", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        write(out, *item(&b.edges, index, "index", "edges")?);
        Ok(())
    })
}

/// Face `index` of a B-rep.
///
/// @param[in] brep The B-rep.
/// @param[in] index 0 ≤ index < face_count.
/// @param[out] out Receives the face; a NURBS surface is borrowed from the B-rep.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_face(
    brep: *const RmfBrep,
    index: usize,
    out: *mut RmfBrepFace,
) -> RmfStatus {
    guard("rmf_brep_face", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        write(out, *item(&b.faces, index, "index", "faces")?);
        Ok(())
    })
}

/// Loop `index` of face `face`.
///
/// @param[in] brep The B-rep.
/// @param[in] face 0 ≤ face < face_count.
/// @param[in] index 0 ≤ index < the face's loop_count.
/// @param[out] out Receives the loop.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming face or index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_loop(
    brep: *const RmfBrep,
    face: usize,
    index: usize,
    out: *mut RmfBrepLoop,
) -> RmfStatus {
    guard("rmf_brep_loop", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        let loops = item(&b.loops, face, "face", "faces")?;
        write(out, *item(loops, index, "index", "loops on that face")?);
        Ok(())
    })
}

/// Edge use `index` of loop `loop` of face `face`.
///
/// @param[in] brep The B-rep.
/// @param[in] face 0 ≤ face < face_count.
/// @param[in] loop 0 ≤ loop < the face's loop_count.
/// @param[in] index 0 ≤ index < the loop's use_count.
/// @param[out] out Receives the use; a NURBS pcurve is borrowed from the B-rep.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming face, loop or
///         index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_use(
    brep: *const RmfBrep,
    face: usize,
    r#loop: usize,
    index: usize,
    out: *mut RmfBrepUse,
) -> RmfStatus {
    guard("rmf_brep_use", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        let loops = item(&b.uses, face, "face", "faces")?;
        let uses = item(loops, r#loop, "loop", "loops on that face")?;
        write(out, *item(uses, index, "index", "uses in that loop")?);
        Ok(())
    })
}

/// The analytic form of face `index` (a plane, cylinder, cone or torus), or kind
/// RMF_ANALYTIC_NONE.
///
/// @param[in] brep The B-rep.
/// @param[in] index 0 ≤ index < face_count.
/// @param[out] out Receives the analytic form.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_face_analytic(
    brep: *const RmfBrep,
    index: usize,
    out: *mut RmfBrepAnalytic,
) -> RmfStatus {
    guard("rmf_brep_face_analytic", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        let face = item(&b.model().faces, index, "index", "faces")?;
        write(out, analytic_face_view(face));
        Ok(())
    })
}

/// The analytic form of edge `index` (a line or circle), or kind RMF_ANALYTIC_NONE.
///
/// @param[in] brep The B-rep.
/// @param[in] index 0 ≤ index < edge_count.
/// @param[out] out Receives the analytic form.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_edge_analytic(
    brep: *const RmfBrep,
    index: usize,
    out: *mut RmfBrepAnalytic,
) -> RmfStatus {
    guard("rmf_brep_edge_analytic", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        let edge = item(&b.model().edges, index, "index", "edges")?;
        write(out, analytic_edge_view(edge));
        Ok(())
    })
}

/// Edge use `index` of loop `loop` of an analytic face, with its curve on the analytic
/// surface: RMF_PCURVE_LINE on the edge's analytic parameter (a parameter line of unit
/// speed) on a cylinder, cone or torus, RMF_PCURVE_NONE on a plane. The uses run the loop
/// counter-clockwise on the analytic surface (holes clockwise): where its parameters have
/// the other orientation than the NURBS surface's, in the reverse order of rmf_brep_use,
/// each against its direction there.
///
/// @param[in] brep The B-rep.
/// @param[in] face 0 ≤ face < face_count, a face whose rmf_brep_face_analytic kind is not
///            RMF_ANALYTIC_NONE.
/// @param[in] loop 0 ≤ loop < the face's loop_count.
/// @param[in] index 0 ≤ index < the loop's use_count.
/// @param[out] out Receives the use.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming face, loop or
///         index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_analytic_use(
    brep: *const RmfBrep,
    face: usize,
    r#loop: usize,
    index: usize,
    out: *mut RmfBrepUse,
) -> RmfStatus {
    guard("rmf_brep_analytic_use", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        let loops = item(&b.analytic_uses, face, "face", "faces")?;
        if loops.is_empty() {
            return invalid_arg(format!("face = {face} is not analytic"));
        }
        let uses = item(loops, r#loop, "loop", "loops on that face")?;
        write(out, *item(uses, index, "index", "uses in that loop")?);
        Ok(())
    })
}

/// Shell `index` of a B-rep: the faces it holds.
///
/// @param[in] brep The B-rep.
/// @param[in] index 0 ≤ index < shell_count.
/// @param[out] out Receives the shell; its face indices are borrowed from the B-rep.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT naming index.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_shell(
    brep: *const RmfBrep,
    index: usize,
    out: *mut RmfBrepShell,
) -> RmfStatus {
    guard("rmf_brep_shell", || {
        let b = reference(brep, "brep")?;
        let out = out_ptr(out, "out")?;
        let shell = item(&b.shells, index, "index", "shells")?;
        write(
            out,
            RmfBrepShell {
                face_count: shell.len(),
                faces: shell.as_ptr(),
            },
        );
        Ok(())
    })
}

/// A B-rep handed in by the caller (rmf_brep_create): the same views the library hands out,
/// in arrays. Face f's loops are the next `faces[f].loop_count` entries of `loops` (faces in
/// order), loop l's uses the next `loops[l].use_count` entries of `uses`. Every pointer in
/// the views is the caller's and is read during the call only.
/// \ingroup rmf_brep
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBrepInput {
    /// Number of vertices.
    pub vertex_count: usize,
    /// The vertices.
    pub vertices: *const RmfVec3,
    /// Number of edges.
    pub edge_count: usize,
    /// The edges (start, end, degenerate, the 3-D curve).
    pub edges: *const RmfBrepEdge,
    /// Number of faces.
    pub face_count: usize,
    /// The faces (kind, surface or plane, sense, loop_count).
    pub faces: *const RmfBrepFace,
    /// The loops of all faces, face after face (outer flag, use_count).
    pub loops: *const RmfBrepLoop,
    /// The edge uses of all loops, loop after loop (edge, forward, optional pcurve).
    pub uses: *const RmfBrepUse,
    /// 1 if the faces bound a solid, 0 for a sheet.
    pub solid: u32,
}

/// Makes a B-rep from the caller's data: a face or a body from another kernel (an
/// OpenCascade shape's faces with their B-spline surfaces and edge curves, a STEP file's),
/// for the analyses that take one (rmf_unfold_face, rmf_face_developability). Checked
/// here: counts, NURBS data, finite vertices, vertex and edge indices in range; the
/// analyses check what they rely on (closed loops, orthonormal plane axes).
///
/// @param[in] input The arrays (see RmfBrepInput); read during the call only.
/// @param[out] out Receives the B-rep; free with rmf_brep_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If input or out is NULL, or an array or a view's pointer
///         is NULL with a non-zero count.
/// @return RMF_ERROR_INVALID_INPUT If a count, an index or a NURBS is malformed, or an
///         unknown kind is given (the message names it: faces[f], edges[e], uses[k]).
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_brep_create(
    input: *const RmfBrepInput,
    out: *mut *mut RmfBrep,
) -> RmfStatus {
    guard("rmf_brep_create", || {
        let input = reference(input, "input")?;
        let out = out_ptr(out, "out")?;
        let brep = read_brep(input)?;
        write(out, RmfBrep::new(brep).into_raw());
        Ok(())
    })
}

/// The model from the caller's arrays (see rmf_brep_create).
///
/// # Safety
/// The arrays and the views' pointers are NULL or valid for their counts.
unsafe fn read_brep(input: &RmfBrepInput) -> FfiResult<Brep> {
    let vertices: Vec<rmfsurf::glam::DVec3> =
        slice(input.vertices, input.vertex_count, "vertices")?
            .iter()
            .map(|&v| v.into())
            .collect();
    if let Some(i) = vertices.iter().position(|v| !v.is_finite()) {
        return invalid_arg(format!("vertices[{i}] is not finite"));
    }
    let mut edges = Vec::new();
    for (e, edge) in slice(input.edges, input.edge_count, "edges")?
        .iter()
        .enumerate()
    {
        let curve = edge
            .curve
            .read()
            .map_err(|err| named(err, format!("edges[{e}].curve")))?;
        for (end, name) in [(edge.start, "start"), (edge.end, "end")] {
            if end >= vertices.len() {
                return invalid_arg(format!(
                    "edges[{e}].{name} = {end} but there are {} vertices",
                    vertices.len()
                ));
            }
        }
        edges.push(BrepEdge {
            curve,
            start: edge.start,
            end: edge.end,
            degenerate: edge.degenerate != 0,
            analytic: None,
        });
    }
    let faces = slice(input.faces, input.face_count, "faces")?;
    let loop_count = faces
        .iter()
        .try_fold(0usize, |n, f| n.checked_add(f.loop_count));
    let Some(loop_count) = loop_count else {
        return invalid_arg("faces: the loop counts overflow".into());
    };
    let loops = slice(input.loops, loop_count, "loops")?;
    let use_count = loops
        .iter()
        .try_fold(0usize, |n, l| n.checked_add(l.use_count));
    let Some(use_count) = use_count else {
        return invalid_arg("loops: the use counts overflow".into());
    };
    let uses = slice(input.uses, use_count, "uses")?;
    let (mut next_loop, mut next_use) = (0, 0);
    let mut model_faces = Vec::new();
    for (f, face) in faces.iter().enumerate() {
        let surface = match face.kind {
            RMF_BREP_SURFACE_NURBS => BrepSurface::Nurbs(
                face.nurbs
                    .read()
                    .map_err(|err| named(err, format!("faces[{f}].nurbs")))?,
            ),
            RMF_BREP_SURFACE_PLANE => BrepSurface::Plane {
                origin: face.plane_origin.into(),
                normal: face.plane_normal.into(),
                x_axis: face.plane_x_axis.into(),
            },
            kind => {
                return invalid_arg(format!("faces[{f}].kind = {kind} is no RMF_BREP_SURFACE_*"))
            }
        };
        let mut bounds = Vec::new();
        for l in &loops[next_loop..next_loop + face.loop_count] {
            let mut model_uses = Vec::new();
            for (k, u) in uses[next_use..next_use + l.use_count].iter().enumerate() {
                let k = next_use + k;
                if u.edge >= edges.len() {
                    return invalid_arg(format!(
                        "uses[{k}].edge = {} but there are {} edges",
                        u.edge,
                        edges.len()
                    ));
                }
                model_uses.push(BrepUse {
                    edge: u.edge,
                    forward: u.forward != 0,
                    pcurve: read_pcurve(u, k)?,
                });
            }
            next_use += l.use_count;
            bounds.push(BrepBound {
                uses: model_uses,
                outer: l.outer != 0,
            });
        }
        next_loop += face.loop_count;
        model_faces.push(BrepFace {
            surface,
            same_sense: face.same_sense != 0,
            bounds,
            analytic: None,
        });
    }
    Ok(Brep {
        vertices,
        edges,
        faces: model_faces,
        closed: input.solid != 0,
    })
}

/// A use's curve in its face's parameter plane.
unsafe fn read_pcurve(u: &RmfBrepUse, k: usize) -> FfiResult<Option<PCurve>> {
    Ok(match u.pcurve_kind {
        RMF_PCURVE_NONE => None,
        RMF_PCURVE_LINE => Some(PCurve::Line {
            origin: (u.line_origin.x, u.line_origin.y),
            direction: (u.line_direction.x, u.line_direction.y),
        }),
        RMF_PCURVE_NURBS => Some(PCurve::Curve(
            u.pcurve
                .read()
                .map_err(|err| named(err, format!("uses[{k}].pcurve")))?,
        )),
        kind => return invalid_arg(format!("uses[{k}].pcurve_kind = {kind} is no RMF_PCURVE_*")),
    })
}

/// The error with the view's name in front.
fn named(err: FfiError, name: String) -> FfiError {
    match err {
        FfiError::Null(what) => FfiError::NullAt(format!("{name}.{what}")),
        FfiError::Core(e) => FfiError::Core(e.context(name)),
        other => other,
    }
}
