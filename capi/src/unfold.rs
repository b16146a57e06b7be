//! Unfolding the caller's own faces (`rmfsurf::unfold::unfold_face`): a developability report for
//! any face of an RmfBrep, and the exact flat pattern of a developable one as an
//! RmfUnfoldedFace — its loops (outline and holes) and bend lines as lines and arcs, its
//! DXF, and the isometry between flat and formed for marks.

use super::boundary::{
    buffer, free_handle, guard, hand_over, hand_text, invalid_arg, options as read_options,
    out_ptr, reference, sized_out, slice, write, write_sized, FfiError, FfiResult, OptionsStruct,
};
use super::brep::RmfBrep;
use super::sheet::{flat_edge, RmfFlatEdge, RMF_FLAT_BEND, RMF_FLAT_CUT};
use super::status::RmfStatus;
use super::types::{RmfVec2, RmfVec3};
use rmfsurf::glam::DVec2;
use rmfsurf::{
    unfold::face_developability, unfold::unfold_body, unfold::unfold_face, unfold::BodyOptions,
    unfold::Developability, unfold::KFactor, unfold::SurfaceKind, unfold::UnfoldOptions,
    unfold::UnfoldedBody, unfold::UnfoldedFace, FlatPattern,
};

/// RmfDevelopability.kind: a plane.
/// \ingroup rmf_unfold
pub const RMF_SURFACE_PLANE: u32 = 0;
/// RmfDevelopability.kind: a circular cylinder.
/// \ingroup rmf_unfold
pub const RMF_SURFACE_CIRCULAR_CYLINDER: u32 = 1;
/// RmfDevelopability.kind: a right circular cone.
/// \ingroup rmf_unfold
pub const RMF_SURFACE_RIGHT_CONE: u32 = 2;
/// RmfDevelopability.kind: a cylinder over any cross-section (parallel rulings).
/// \ingroup rmf_unfold
pub const RMF_SURFACE_GENERAL_CYLINDER: u32 = 3;
/// RmfDevelopability.kind: a cone over any cross-section (rulings through one apex).
/// \ingroup rmf_unfold
pub const RMF_SURFACE_GENERAL_CONE: u32 = 4;
/// RmfDevelopability.kind: the tangent surface of a space curve.
/// \ingroup rmf_unfold
pub const RMF_SURFACE_TANGENT_DEVELOPABLE: u32 = 5;
/// RmfDevelopability.kind: a developable of several of the kinds above joined along
/// rulings, or one whose rulings are not a parameter direction.
/// \ingroup rmf_unfold
pub const RMF_SURFACE_RULED_DEVELOPABLE: u32 = 6;
/// RmfDevelopability.kind: not developable (Gaussian curvature beyond 1e-6 / size²).
/// \ingroup rmf_unfold
pub const RMF_SURFACE_NOT_DEVELOPABLE: u32 = 7;

fn kind_code(kind: SurfaceKind) -> u32 {
    match kind {
        SurfaceKind::Plane => RMF_SURFACE_PLANE,
        SurfaceKind::CircularCylinder => RMF_SURFACE_CIRCULAR_CYLINDER,
        SurfaceKind::RightCone => RMF_SURFACE_RIGHT_CONE,
        SurfaceKind::GeneralCylinder => RMF_SURFACE_GENERAL_CYLINDER,
        SurfaceKind::GeneralCone => RMF_SURFACE_GENERAL_CONE,
        SurfaceKind::TangentDevelopable => RMF_SURFACE_TANGENT_DEVELOPABLE,
        SurfaceKind::RuledDevelopable => RMF_SURFACE_RULED_DEVELOPABLE,
        SurfaceKind::NotDevelopable => RMF_SURFACE_NOT_DEVELOPABLE,
    }
}

/// How developable a face is. Set struct_size to sizeof(RmfDevelopability) before the call.
/// \ingroup rmf_unfold
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfDevelopability {
    /// sizeof(RmfDevelopability), set by the caller.
    pub struct_size: usize,
    /// RMF_SURFACE_*.
    pub kind: u32,
    /// Largest |K|·size² sampled over the face's surface (K the Gaussian curvature, size
    /// the diagonal of its bounding box).
    pub curvature: f64,
    /// For a face that is not developable: the largest relative change of length of a
    /// least-squares flattening of a grid over its surface; 0 for developable faces.
    pub stretch: f64,
    /// rmf_unfold_face only: the largest sampled distance of the cone spline from the face
    /// (0 where the face unrolls in closed form: planes, circular cylinders, right cones).
    pub fit_error: f64,
}

unsafe impl OptionsStruct for RmfDevelopability {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

impl RmfDevelopability {
    fn of(report: &Developability, fit_error: f64) -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            kind: kind_code(report.kind),
            curvature: report.curvature,
            stretch: report.stretch,
            fit_error,
        }
    }
}

/// How a face is unrolled. Initialise with rmf_unfold_options_init; the struct only grows
/// at the end.
/// \ingroup rmf_unfold
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfUnfoldOptions {
    /// sizeof(RmfUnfoldOptions), written by rmf_unfold_options_init.
    pub struct_size: usize,
    /// Largest distance of the cone spline from a face that is neither a plane, a circular
    /// cylinder nor a right cone (default 1e-4, caller's units), > 0.
    pub tolerance: f64,
    /// Largest distance of the outline's biarcs from the developed boundary; 0 (the
    /// default) means the tolerance.
    pub flat_tolerance: f64,
    /// Most cone pieces for one face (default 10000), ≥ 2.
    pub max_pieces: usize,
}

impl Default for RmfUnfoldOptions {
    fn default() -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            tolerance: 1e-4,
            flat_tolerance: 0.0,
            max_pieces: rmfsurf::cone::DEFAULT_MAX_PIECES,
        }
    }
}

unsafe impl OptionsStruct for RmfUnfoldOptions {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// Loop `index` of a flat pattern (0 the outline, then the holes) into the caller's buffer.
///
/// # Safety
/// `edges` is NULL or valid for `capacity` edges; `count` is NULL or writable.
unsafe fn hand_loop(
    p: &FlatPattern,
    index: usize,
    edges: *mut RmfFlatEdge,
    capacity: usize,
    count: *mut usize,
) -> FfiResult {
    let count = out_ptr(count, "count")?;
    let edges = buffer(edges, capacity, "edges")?;
    let edges_of = match index {
        0 => &p.outline,
        k if k <= p.holes.len() => &p.holes[k - 1],
        _ => {
            return invalid_arg(format!(
                "index = {index} but the pattern has {} loops",
                1 + p.holes.len()
            ))
        }
    };
    let all: Vec<RmfFlatEdge> = edges_of
        .iter()
        .map(|e| flat_edge(e, RMF_FLAT_CUT))
        .collect();
    hand_over(&all, edges, count, "edges")
}

/// Maps the caller's `count` points of type `In` with `map` into `out` (nothing written on
/// failure; the message names `input_name[i]`).
///
/// # Safety
/// `input` and `out` are NULL or valid for `count` values.
unsafe fn map_points<In: Copy, Out, Mid>(
    input: *const In,
    count: usize,
    out: *mut Out,
    (input_name, out_name): (&'static str, &'static str),
    map: impl Fn(In, &str) -> rmfsurf::Result<Mid>,
) -> FfiResult
where
    Out: From<Mid>,
{
    let input = slice(input, count, input_name)?;
    let out = buffer(out, count, out_name)?;
    let mapped = input
        .iter()
        .enumerate()
        .map(|(i, x)| map(*x, &format!("{input_name}[{i}]")))
        .collect::<rmfsurf::Result<Vec<_>>>()?;
    for (o, m) in out.iter_mut().zip(mapped) {
        *o = m.into();
    }
    Ok(())
}

/// A face unrolled (rmf_unfold_face). Free with rmf_unfolded_face_free.
/// \ingroup rmf_unfold
pub struct RmfUnfoldedFace {
    face: UnfoldedFace,
}

/// Writes the default options and the struct's size.
///
/// @param[out] options Receives the defaults (tolerance 1e-4, flat_tolerance 0 = the
///             tolerance, max_pieces 10000).
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if options is NULL.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfold_options_init(options: *mut RmfUnfoldOptions) -> RmfStatus {
    guard("rmf_unfold_options_init", || {
        let options = out_ptr(options, "options")?;
        write(options, RmfUnfoldOptions::default());
        Ok(())
    })
}

/// How developable face `face` of `brep` is: the kind of its surface (told from its
/// geometry, so a cylinder handed over as a rational B-spline is a circular cylinder), its
/// largest |K|·size², and for a face that is not developable the stretch an unrolling
/// needs, measured.
///
/// @param[in] brep The B-rep (rmf_brep_create, or one the library made).
/// @param[in] face 0 ≤ face < face_count.
/// @param[in,out] out struct_size set by the caller; receives the report (fit_error 0).
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If brep or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If face is out of range, the face has no or several
///         outer loops, a pole is not finite, or out->struct_size is wrong.
/// @return RMF_ERROR_NO_SOLUTION If the surface of a face that is not developable is
///         singular at the middle of its domain (its stretch is not measured).
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_face_developability(
    brep: *const RmfBrep,
    face: usize,
    out: *mut RmfDevelopability,
) -> RmfStatus {
    guard("rmf_face_developability", || {
        let brep = reference(brep, "brep")?;
        let Some(out) = sized_out(out, "out")? else {
            return Err(FfiError::Null("out"));
        };
        let report = face_developability(brep.model(), face)?;
        write_sized(out, &RmfDevelopability::of(&report, 0.0));
        Ok(())
    })
}

/// Unrolls face `face` of `brep` into the plane z = 0, seen from the face's normal side
/// (its outer loop counter-clockwise): planes, circular cylinders and right cones exactly
/// in closed form; every other developable (general cylinders and cones, tangent
/// developables, B-spline developables of degree 1 along their rulings) through its cone
/// spline within `options->tolerance` (Leopoldseder & Pottmann), developed exactly. The
/// face's own loops — outline and holes — are drawn edge by edge: as the line or circular
/// arc the edge develops into where it is one (to 1e-9 of the face's size: rulings,
/// parallel circles, helices and cross-sections of cylinders, lines and circles of planes),
/// as G1 biarcs within the flat tolerance elsewhere. A cylinder or cone going all the way
/// round is cut open along its seam edge. A face that is not developable is refused, the
/// message giving its curvature and the stretch an unrolling would need.
///
/// @param[in] brep The B-rep.
/// @param[in] face 0 ≤ face < face_count.
/// @param[in] options Tolerances, or NULL for the defaults.
/// @param[out] out Receives the unrolled face; free with rmf_unfolded_face_free.
///             Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If brep or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If face is out of range, a loop is not closed or has no
///         edges, the face has no or several outer loops, a pole is not finite, the face is
///         not developable (the message says by how much), a closed general developable
///         or a developable not ruled along a parameter is given, or an option is out of
///         range.
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance needs more than max_pieces pieces or
///         the flat tolerance more biarcs than f64 resolves.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfold_face(
    brep: *const RmfBrep,
    face: usize,
    options: *const RmfUnfoldOptions,
    out: *mut *mut RmfUnfoldedFace,
) -> RmfStatus {
    guard("rmf_unfold_face", || {
        let brep = reference(brep, "brep")?;
        let o = read_options(options, "options")?;
        let out = out_ptr(out, "out")?;
        let unfolded = unfold_face(
            brep.model(),
            face,
            &UnfoldOptions {
                tolerance: o.tolerance,
                flat_tolerance: o.flat_tolerance,
                max_pieces: o.max_pieces,
            },
        )?;
        write(
            out,
            Box::into_raw(Box::new(RmfUnfoldedFace { face: unfolded })),
        );
        Ok(())
    })
}

/// Frees an unrolled face. NULL is a no-op.
///
/// @param[in] face The face to free, or NULL.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_free(face: *mut RmfUnfoldedFace) {
    free_handle(face)
}

/// The report of an unrolled face: kind, curvature, stretch (0), fit error.
///
/// @param[in] face The unrolled face.
/// @param[in,out] out struct_size set by the caller; receives the report.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT for a wrong
///         struct_size.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_report(
    face: *const RmfUnfoldedFace,
    out: *mut RmfDevelopability,
) -> RmfStatus {
    guard("rmf_unfolded_face_report", || {
        let f = &reference(face, "face")?.face;
        let Some(out) = sized_out(out, "out")? else {
            return Err(FfiError::Null("out"));
        };
        write_sized(out, &RmfDevelopability::of(f.report(), f.fit_error()));
        Ok(())
    })
}

/// The number of loops of the flat pattern: 1 (the outline) + the number of holes.
///
/// @param[in] face The unrolled face.
/// @param[out] count Receives the number of loops.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_loop_count(
    face: *const RmfUnfoldedFace,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_face_loop_count", || {
        let f = &reference(face, "face")?.face;
        let count = out_ptr(count, "count")?;
        write(count, 1 + f.pattern().holes.len());
        Ok(())
    })
}

/// Loop `index` of the flat pattern (layer RMF_FLAT_CUT): 0 the outline, counter-clockwise;
/// 1 … the holes, clockwise; each closed (every edge starts where the one before ends).
///
/// Size query: with capacity 0 (edges may be NULL) only count is written.
///
/// @param[in] face The unrolled face.
/// @param[in] index 0 ≤ index < rmf_unfolded_face_loop_count.
/// @param[out] edges Buffer for capacity edges.
/// @param[in] capacity Capacity of edges; 0 for a size query.
/// @param[out] count Receives the number of edges.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If face or count is NULL, or edges is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but too small; count is written.
/// @return RMF_ERROR_INVALID_INPUT If index is out of range.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_loop(
    face: *const RmfUnfoldedFace,
    index: usize,
    edges: *mut RmfFlatEdge,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_face_loop", || {
        let p = reference(face, "face")?.face.pattern();
        hand_loop(p, index, edges, capacity, count)
    })
}

/// The bend lines of the flat pattern (layer RMF_FLAT_BEND): the rulings where the pieces
/// of a cone spline meet, clipped to the face; none for planes, circular cylinders and
/// right cones (a face is one bend or none).
///
/// Size query: with capacity 0 (edges may be NULL) only count is written.
///
/// @param[in] face The unrolled face.
/// @param[out] edges Buffer for capacity edges.
/// @param[in] capacity Capacity of edges; 0 for a size query.
/// @param[out] count Receives the number of bend lines.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If face or count is NULL, or edges is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but too small; count is written.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_bend_lines(
    face: *const RmfUnfoldedFace,
    edges: *mut RmfFlatEdge,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_face_bend_lines", || {
        let p = reference(face, "face")?.face.pattern();
        let count = out_ptr(count, "count")?;
        let edges = buffer(edges, capacity, "edges")?;
        let all: Vec<RmfFlatEdge> = p
            .bend_lines
            .iter()
            .map(|e| flat_edge(e, RMF_FLAT_BEND))
            .collect();
        hand_over(&all, edges, count, "edges")
    })
}

/// The flat pattern's area: the outline's less the holes' (exact for lines and arcs).
///
/// @param[in] face The unrolled face.
/// @param[out] area Receives the area.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if the area is
///         outside the range of f64.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_area(
    face: *const RmfUnfoldedFace,
    area: *mut f64,
) -> RmfStatus {
    guard("rmf_unfolded_face_area", || {
        let p = reference(face, "face")?.face.pattern();
        let area = out_ptr(area, "area")?;
        let value = p.area()?;
        write(area, value);
        Ok(())
    })
}

/// The flat pattern as a DXF R12 file: LINE and ARC entities, outline and holes on layer
/// CUT, bend lines on layer BEND.
///
/// Size query: with capacity 0 (text may be NULL) only length is written.
///
/// @param[in] face The unrolled face.
/// @param[out] text Buffer for capacity bytes; receives the text and a terminating NUL.
/// @param[in] capacity Capacity of text; 0 for a size query.
/// @param[out] length Receives the text's length without the NUL.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If face or length is NULL, or text is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but below length + 1.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_dxf(
    face: *const RmfUnfoldedFace,
    text: *mut libc::c_char,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_face_dxf", || {
        let p = reference(face, "face")?.face.pattern();
        let length = out_ptr(length, "length")?;
        let out = buffer(text.cast::<u8>(), capacity, "text")?;
        let dxf = rmfsurf::export::dxf::pattern_to_dxf(p);
        hand_text(&dxf, out, length)
    })
}

/// Marks from the formed face to the flat pattern: each point of the face (holes, slots,
/// text outlines as polylines) to its flat point by the isometry of the development.
///
/// @param[in] face The unrolled face.
/// @param[in] points count points on the face.
/// @param[in] count Number of points (0: nothing to do).
/// @param[out] flat count flat points.
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If face, points or flat is NULL (count > 0).
/// @return RMF_ERROR_INVALID_INPUT If a point is not finite (the message names it).
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_to_flat(
    face: *const RmfUnfoldedFace,
    points: *const RmfVec3,
    count: usize,
    flat: *mut RmfVec2,
) -> RmfStatus {
    guard("rmf_unfolded_face_to_flat", || {
        let f = &reference(face, "face")?.face;
        map_points(
            points,
            count,
            flat,
            ("points", "flat"),
            |p: RmfVec3, name| f.to_flat(p.into(), name),
        )
    })
}

/// Marks from the flat pattern to the formed face: each flat point to its point on the
/// face by the isometry of the development.
///
/// @param[in] face The unrolled face.
/// @param[in] flat count points of the flat pattern.
/// @param[in] count Number of points (0: nothing to do).
/// @param[out] points count points on the face.
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If face, flat or points is NULL (count > 0).
/// @return RMF_ERROR_INVALID_INPUT If a point is not finite or has no formed point (beyond
///         a cone spline's pieces); the message names it.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_face_to_formed(
    face: *const RmfUnfoldedFace,
    flat: *const RmfVec2,
    count: usize,
    points: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_unfolded_face_to_formed", || {
        let f = &reference(face, "face")?.face;
        map_points(
            flat,
            count,
            points,
            ("flat", "points"),
            |q: RmfVec2, name| f.to_formed(DVec2::from(q), name),
        )
    })
}

/// How a sheet body is unfolded. Initialise with rmf_unfold_body_options_init; the struct
/// only grows at the end.
/// \ingroup rmf_unfold
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfUnfoldBodyOptions {
    /// sizeof(RmfUnfoldBodyOptions), written by rmf_unfold_body_options_init.
    pub struct_size: usize,
    /// The faces' tolerance (see RmfUnfoldOptions), also the largest variation of the
    /// thickness (default 1e-4), > 0.
    pub tolerance: f64,
    /// Largest distance of the outline's biarcs from the developed boundary; 0 (the
    /// default) means the tolerance.
    pub flat_tolerance: f64,
    /// Most cone pieces for one face (default 10000), ≥ 2.
    pub max_pieces: usize,
    /// The K-factor when k_table_count is 0 (default 0.5), 0 ≤ k ≤ 1: the neutral layer
    /// lies at k·t from the inner face of each bend.
    pub k_factor: f64,
    /// Rows of a K-factor table, or 0 to use k_factor.
    pub k_table_count: usize,
    /// k_table_count rows (x: inner bend radius / thickness, increasing; y: k), k
    /// interpolated linearly between rows and held beyond the ends; read during the call.
    pub k_table: *const RmfVec2,
}

impl Default for RmfUnfoldBodyOptions {
    fn default() -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            tolerance: 1e-4,
            flat_tolerance: 0.0,
            max_pieces: rmfsurf::cone::DEFAULT_MAX_PIECES,
            k_factor: 0.5,
            k_table_count: 0,
            k_table: std::ptr::null(),
        }
    }
}

unsafe impl OptionsStruct for RmfUnfoldBodyOptions {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// A bend of an unfolded body.
/// \ingroup rmf_unfold
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBend {
    /// The bend line (layer RMF_FLAT_BEND).
    pub line: RmfFlatEdge,
    /// 1 if the bend rises towards the viewer of the pattern (the unfolded side is its
    /// inner side), 0 if it goes down.
    pub up: u32,
    /// The face of the body the bend lies on.
    pub face: usize,
    /// The smallest inner bend radius of that face.
    pub radius: f64,
    /// The K-factor used for it.
    pub k_factor: f64,
}

/// A sheet body unfolded (rmf_unfold_body). Free with rmf_unfolded_body_free.
/// \ingroup rmf_unfold
pub struct RmfUnfoldedBody {
    body: UnfoldedBody,
}

/// Writes the default options and the struct's size.
///
/// @param[out] options Receives the defaults (tolerance 1e-4, flat_tolerance 0 = the
///             tolerance, max_pieces 10000, k_factor 0.5, no table).
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if options is NULL.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfold_body_options_init(
    options: *mut RmfUnfoldBodyOptions,
) -> RmfStatus {
    guard("rmf_unfold_body_options_init", || {
        let options = out_ptr(options, "options")?;
        write(options, RmfUnfoldBodyOptions::default());
        Ok(())
    })
}

/// Unfolds a whole sheet-metal body: a closed solid of constant thickness made of planes
/// and bends of any developable kind (cylinders, cones, general cylinders, B-spline
/// developables). The two skins and the thickness are found straight across the faces;
/// the side joined to the largest skin face is developed on the neutral layer (at k·t from
/// each bend's inner face) and its faces joined along their bends into one flat pattern,
/// seen from that side's outside: outline, holes and cutouts, bend lines up and down. The
/// other faces are the sheet's cut edges.
///
/// @param[in] brep The body (rmf_brep_create with solid = 1, or a library B-rep).
/// @param[in] options Tolerances and K-factor, or NULL for the defaults.
/// @param[out] out Receives the unfolded body; free with rmf_unfolded_body_free.
///             Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If brep or out is NULL, or k_table is NULL with rows.
/// @return RMF_ERROR_INVALID_INPUT If the B-rep is an open shell or not manifold, a face is
///         not developable (named, with its curvature and stretch), the thickness is not
///         constant (the face, the point and the distance), the faces do not close up flat,
///         the flat pattern overlaps itself (the point), or an option is out of range
///         (k outside [0, 1], a table whose ratios do not increase).
/// @return RMF_ERROR_NOT_CONVERGED If a face's cone spline needs more than max_pieces.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfold_body(
    brep: *const RmfBrep,
    options: *const RmfUnfoldBodyOptions,
    out: *mut *mut RmfUnfoldedBody,
) -> RmfStatus {
    guard("rmf_unfold_body", || {
        let brep = reference(brep, "brep")?;
        let o = read_options(options, "options")?;
        let out = out_ptr(out, "out")?;
        let k_factor = if o.k_table_count == 0 {
            KFactor::Constant(o.k_factor)
        } else {
            let rows = slice(o.k_table, o.k_table_count, "options->k_table")?;
            KFactor::Table(rows.iter().map(|r| (r.x, r.y)).collect())
        };
        let body = unfold_body(
            brep.model(),
            &BodyOptions {
                face: UnfoldOptions {
                    tolerance: o.tolerance,
                    flat_tolerance: o.flat_tolerance,
                    max_pieces: o.max_pieces,
                },
                k_factor,
            },
        )?;
        write(out, Box::into_raw(Box::new(RmfUnfoldedBody { body })));
        Ok(())
    })
}

/// Frees an unfolded body. NULL is a no-op.
///
/// @param[in] body The body to free, or NULL.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_free(body: *mut RmfUnfoldedBody) {
    free_handle(body)
}

/// The thickness of the sheet, as measured between its skins.
///
/// @param[in] body The unfolded body.
/// @param[out] thickness Receives the thickness.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_thickness(
    body: *const RmfUnfoldedBody,
    thickness: *mut f64,
) -> RmfStatus {
    guard("rmf_unfolded_body_thickness", || {
        let b = &reference(body, "body")?.body;
        let thickness = out_ptr(thickness, "thickness")?;
        write(thickness, b.thickness());
        Ok(())
    })
}

/// The number of loops of the flat pattern: 1 (the outline) + the number of holes and
/// cutouts.
///
/// @param[in] body The unfolded body.
/// @param[out] count Receives the number of loops.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_loop_count(
    body: *const RmfUnfoldedBody,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_body_loop_count", || {
        let b = &reference(body, "body")?.body;
        let count = out_ptr(count, "count")?;
        write(count, 1 + b.pattern().holes.len());
        Ok(())
    })
}

/// Loop `index` of the body's flat pattern (layer RMF_FLAT_CUT): 0 the outline,
/// counter-clockwise; 1 … the holes and cutouts, clockwise; each closed.
///
/// Size query: with capacity 0 (edges may be NULL) only count is written.
///
/// @param[in] body The unfolded body.
/// @param[in] index 0 ≤ index < rmf_unfolded_body_loop_count.
/// @param[out] edges Buffer for capacity edges.
/// @param[in] capacity Capacity of edges; 0 for a size query.
/// @param[out] count Receives the number of edges.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If body or count is NULL, or edges is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but too small; count is written.
/// @return RMF_ERROR_INVALID_INPUT If index is out of range.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_loop(
    body: *const RmfUnfoldedBody,
    index: usize,
    edges: *mut RmfFlatEdge,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_body_loop", || {
        let p = reference(body, "body")?.body.pattern();
        hand_loop(p, index, edges, capacity, count)
    })
}

/// The bends of the body's flat pattern: line, up or down, face, inner radius, K-factor.
///
/// Size query: with capacity 0 (bends may be NULL) only count is written.
///
/// @param[in] body The unfolded body.
/// @param[out] bends Buffer for capacity bends.
/// @param[in] capacity Capacity of bends; 0 for a size query.
/// @param[out] count Receives the number of bends.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If body or count is NULL, or bends is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but too small; count is written.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_bends(
    body: *const RmfUnfoldedBody,
    bends: *mut RmfBend,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_body_bends", || {
        let b = &reference(body, "body")?.body;
        let count = out_ptr(count, "count")?;
        let bends = buffer(bends, capacity, "bends")?;
        let all: Vec<RmfBend> = b
            .bends()
            .iter()
            .map(|bend| RmfBend {
                line: flat_edge(&bend.line, RMF_FLAT_BEND),
                up: u32::from(bend.up),
                face: bend.face,
                radius: bend.radius,
                k_factor: bend.k_factor,
            })
            .collect();
        hand_over(&all, bends, count, "bends")
    })
}

/// The body's flat area: the outline's less the holes'.
///
/// @param[in] body The unfolded body.
/// @param[out] area Receives the area.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if the area is
///         outside the range of f64.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_area(
    body: *const RmfUnfoldedBody,
    area: *mut f64,
) -> RmfStatus {
    guard("rmf_unfolded_body_area", || {
        let p = reference(body, "body")?.body.pattern();
        let area = out_ptr(area, "area")?;
        let value = p.area()?;
        write(area, value);
        Ok(())
    })
}

/// The body's flat pattern as a DXF R12 file: LINE and ARC entities, outline and holes on
/// layer CUT, bend lines on BEND_UP and BEND_DOWN.
///
/// Size query: with capacity 0 (text may be NULL) only length is written.
///
/// @param[in] body The unfolded body.
/// @param[out] text Buffer for capacity bytes; receives the text and a terminating NUL.
/// @param[in] capacity Capacity of text; 0 for a size query.
/// @param[out] length Receives the text's length without the NUL.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If body or length is NULL, or text is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but below length + 1.
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_dxf(
    body: *const RmfUnfoldedBody,
    text: *mut libc::c_char,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_unfolded_body_dxf", || {
        let b = &reference(body, "body")?.body;
        let length = out_ptr(length, "length")?;
        let out = buffer(text.cast::<u8>(), capacity, "text")?;
        let up: Vec<bool> = b.bends().iter().map(|bend| bend.up).collect();
        let dxf = rmfsurf::export::dxf::sheet_pattern_to_dxf(b.pattern(), &up);
        hand_text(&dxf, out, length)
    })
}

/// Marks from the formed body to the flat pattern: each point (on a skin or inside the
/// sheet) to the flat point of its foot on the nearest face of the unfolded side.
///
/// @param[in] body The unfolded body.
/// @param[in] points count points.
/// @param[in] count Number of points (0: nothing to do).
/// @param[out] flat count flat points.
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If body, points or flat is NULL (count > 0).
/// @return RMF_ERROR_INVALID_INPUT If a point is not finite (the message names it).
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_to_flat(
    body: *const RmfUnfoldedBody,
    points: *const RmfVec3,
    count: usize,
    flat: *mut RmfVec2,
) -> RmfStatus {
    guard("rmf_unfolded_body_to_flat", || {
        let b = &reference(body, "body")?.body;
        map_points(
            points,
            count,
            flat,
            ("points", "flat"),
            |p: RmfVec3, name| b.to_flat(p.into(), name),
        )
    })
}

/// Marks from the flat pattern to the formed body: each flat point to its point on the
/// neutral layer.
///
/// @param[in] body The unfolded body.
/// @param[in] flat count flat points.
/// @param[in] count Number of points (0: nothing to do).
/// @param[out] points count points of the neutral layer.
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If body, flat or points is NULL (count > 0).
/// @return RMF_ERROR_INVALID_INPUT If a point is not finite or lies outside the pattern
///         (the message names it).
/// \since 0.2
/// \ingroup rmf_unfold
#[no_mangle]
pub unsafe extern "C" fn rmf_unfolded_body_to_formed(
    body: *const RmfUnfoldedBody,
    flat: *const RmfVec2,
    count: usize,
    points: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_unfolded_body_to_formed", || {
        let b = &reference(body, "body")?.body;
        map_points(
            flat,
            count,
            points,
            ("flat", "points"),
            |q: RmfVec2, name| b.to_formed(DVec2::from(q), name),
        )
    })
}
