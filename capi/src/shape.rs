//! `RmfShape`: the result of a wire sweep — a closed solid or a sheet — with its faces as
//! borrowed `RmfSurface` views (lateral faces) and planes with boundary loops (caps), its
//! accuracy report, and its STEP file.

use super::boundary::{
    free_handle, guard, invalid_arg, out_ptr, reference, write, FfiError, FfiResult,
};
use super::curve::RmfCurve;
use super::status::RmfStatus;
use super::surface::RmfSurface;
use super::types::RmfVec3;
use libc::c_char;
use rmfsurf::export::occ_brep::{OccBinary, OccReader};
use rmfsurf::{wire::FaceKind, wire::Shape};
use std::ffi::CStr;
use std::io::Write;
use std::sync::atomic::{AtomicU64, Ordering};

/// What a face of an RmfShape is (values fixed).
/// \ingroup rmf_wire
pub type RmfFaceKind = u32;
/// A lateral face: an exact rational RmfSurface (u along the profile edge, v along the
/// wire).
/// \ingroup rmf_wire
pub const RMF_FACE_SWEPT: RmfFaceKind = 0;
/// A planar cap at an end of an open wire, bounded by profile loops.
/// \ingroup rmf_wire
pub const RMF_FACE_PLANE: RmfFaceKind = 1;

/// A closed solid or a sheet of exact faces (opaque). Made by rmf_wire_sweep, freed with
/// rmf_shape_free. Immutable; may be read from several threads at once.
/// \ingroup rmf_wire
pub struct RmfShape {
    shape: Shape,
    /// The lateral faces' surfaces (None for caps), the views of rmf_shape_face.
    surfaces: Vec<Option<RmfSurface>>,
    /// The caps' loops, the views of rmf_shape_face_loop.
    loops: Vec<Vec<RmfCurve>>,
    /// OpenCascade's B-rep text, made on the first rmf_shape_occ_brep (a caller asks twice:
    /// the size, then the text).
    occ_brep: std::sync::OnceLock<String>,
    /// OpenCascade's binary B-rep, made on the first rmf_shape_occ_binary.
    occ_binary: std::sync::OnceLock<OccBinary>,
}

impl RmfShape {
    pub(crate) fn new(shape: Shape) -> Self {
        let surfaces = shape
            .faces()
            .iter()
            .map(|f| f.surface.clone().map(|s| RmfSurface::new(s, None)))
            .collect();
        let loops = shape
            .faces()
            .iter()
            .map(|f| {
                f.loops
                    .iter()
                    .map(|l| RmfCurve::new(l.clone(), None))
                    .collect()
            })
            .collect();
        Self {
            shape,
            surfaces,
            loops,
            occ_brep: std::sync::OnceLock::new(),
            occ_binary: std::sync::OnceLock::new(),
        }
    }

    pub(crate) fn into_raw(self) -> *mut Self {
        Box::into_raw(Box::new(self))
    }
}

/// One face of an RmfShape (a copy; the pointers are borrowed from the shape).
/// \ingroup rmf_wire
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfShapeFace {
    /// RMF_FACE_SWEPT (a lateral face) or RMF_FACE_PLANE (a cap).
    pub kind: RmfFaceKind,
    /// RMF_FACE_SWEPT: the face's surface, borrowed: valid until the shape is freed (do not
    /// free it). NULL for caps.
    pub surface: *const RmfSurface,
    /// RMF_FACE_PLANE: a point of the cap's plane (the wire's end). Zero for lateral faces.
    pub plane_origin: RmfVec3,
    /// RMF_FACE_PLANE: the cap's unit normal, pointing out of the solid. Zero for lateral
    /// faces.
    pub plane_normal: RmfVec3,
    /// RMF_FACE_PLANE: the number of boundary loops (the first is the outer one; the others
    /// are the holes); rmf_shape_face_loop gives them. 0 for lateral faces (their boundary
    /// is their surface's natural boundary).
    pub loop_count: usize,
    /// RMF_FACE_SWEPT: the index of the wire edge the face lies along (as given to
    /// rmf_wire_sweep) and of the profile edge it sweeps (Bézier segments of the profile,
    /// then of holes[0], holes[1], ...). Caps: the wire edge at that end, and 0.
    pub spine_edge: usize,
    /// RMF_FACE_SWEPT: the profile edge the face sweeps (see spine_edge); 0 for caps.
    pub profile_edge: usize,
    /// 1 if the face's outward normal is −(s_u × s_v) (its surface runs the other way).
    pub reversed: u32,
    /// Added in 0.2: the loop the profile edge belongs to (0 the profile, 1 + h holes[h]).
    pub profile_loop: usize,
    /// Added in 0.2: 1 if the face is the elbow of a round corner after spine_edge.
    pub round_corner: u32,
}

/// How accurate a wire sweep is (all figures measured on the result).
/// \ingroup rmf_wire
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfSweepReport {
    /// Largest sampled distance between a curve edge and its PH cubic spline, in the wire's
    /// units (0 when every edge is a line or an arc).
    pub spine_distance: f64,
    /// Largest angle (radians) between the frames used and the exact RMF plus the twist and
    /// closure turn (linear in arc length); 0 on untwisted lines and arcs.
    pub rmf_angle_error: f64,
    /// Largest |cos| of the angle between the parameter lines of the lateral faces: on the
    /// patches of lines and arcs a bound over 9 parameter lines of each (from the Bernstein
    /// coefficients along the spine), on the others sampled (0 for an exact RMF sweep; a
    /// twist or a closure turn tilts them, and miter legs are ruled between oblique
    /// sections).
    pub max_parameter_cosine: f64,
    /// The least singularity margin g = 1 − κ c·n over the sweep (Mäurer & Jüttler Cor. 7;
    /// 1 where the wire is straight), and 1 − cuts/length for miter legs; > 0.
    pub singularity_margin: f64,
    /// Number of faces (rmf_shape_face_count: one per spine piece and profile edge, and the
    /// caps; the B-rep, rmf_shape_brep, joins a closed loop's faces on one cylinder or torus).
    pub face_count: usize,
    /// Added in 0.2: the largest turn of the frame about the tangent across a corner, against
    /// the minimal rotation of the tangent there (round corners: across the elbow; miters:
    /// across the miter plane), radians.
    pub corner_turn: f64,
    /// Added in 0.2: closed wires: the largest distance between the sections where the
    /// wire closes (0 for open wires), in the wire's units.
    pub seam_gap: f64,
    /// Added in 0.2: the largest distance between the sections of consecutive pieces at the
    /// joints inside the wire (rounding at G1 joints; ½θ²·r at near-tangent joints, where a
    /// line meets a curved edge at an angle θ so slight that the line is cut by the curved
    /// edge's normal plane), in the wire's units.
    pub joint_gap: f64,
    /// Added in 0.2 (after joint_gap): the largest angle (radians) between the frames used
    /// and the frame asked for in RmfWireSweepOptions.frame (the Frenet frame or the fixed
    /// direction's, each offset by the turn it kept where the curvature vanished or the
    /// normal jumped), sampled; 0 for RMF_FRAME_RMF.
    pub frame_error: f64,
}

/// Frees a shape; its face surfaces and loop curves become invalid. NULL is a no-op.
///
/// @param[in] shape The shape to free, or NULL.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_free(shape: *mut RmfShape) {
    free_handle(shape)
}

/// The number of faces of a shape (lateral faces first, then the caps); 0 for NULL.
///
/// @param[in] shape The shape, or NULL.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_face_count(shape: *const RmfShape) -> usize {
    if shape.is_null() {
        return 0;
    }
    (*shape).shape.faces().len()
}

/// Whether a shape is a closed, consistently oriented solid (1) or a sheet (0); 0 for NULL.
///
/// @param[in] shape The shape, or NULL.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_is_solid(shape: *const RmfShape) -> u32 {
    if shape.is_null() {
        return 0;
    }
    u32::from((*shape).shape.is_solid())
}

/// Describes face `index` of a shape.
///
/// @param[in] shape The shape.
/// @param[in] index 0 ≤ index < rmf_shape_face_count(shape).
/// @param[out] out Receives the face; its surface pointer is borrowed from the shape.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if index is out of range.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_face(
    shape: *const RmfShape,
    index: usize,
    out: *mut RmfShapeFace,
) -> RmfStatus {
    guard("rmf_shape_face", || {
        let shape = reference(shape, "shape")?;
        let out = out_ptr(out, "out")?;
        let faces = shape.shape.faces();
        let Some(face) = faces.get(index) else {
            return invalid_arg(format!(
                "index = {index} but the shape has {} faces",
                faces.len()
            ));
        };
        let (origin, normal) = face.plane.unwrap_or_default();
        write(
            out,
            RmfShapeFace {
                kind: match face.kind {
                    FaceKind::Swept => RMF_FACE_SWEPT,
                    FaceKind::Plane => RMF_FACE_PLANE,
                },
                surface: shape.surfaces[index]
                    .as_ref()
                    .map_or(std::ptr::null(), |s| s as *const RmfSurface),
                plane_origin: origin.into(),
                plane_normal: normal.into(),
                loop_count: face.loops.len(),
                spine_edge: face.spine_edge,
                profile_edge: face.profile_edge,
                reversed: u32::from(face.reversed),
                profile_loop: face.profile_loop,
                round_corner: u32::from(face.round_corner),
            },
        );
        Ok(())
    })
}

/// Boundary loop `loop` of a planar cap: a closed 3-D curve, counter-clockwise about the
/// cap's outward normal for the outer loop (index 0), clockwise for holes.
///
/// @param[in] shape The shape.
/// @param[in] face A face of kind RMF_FACE_PLANE.
/// @param[in] loop 0 ≤ loop < the face's loop_count.
/// @param[out] out Receives the curve, borrowed: valid until the shape is freed (do not free it).
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if face or loop is out
///         of range (lateral faces have no loops).
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_face_loop(
    shape: *const RmfShape,
    face: usize,
    r#loop: usize,
    out: *mut *const RmfCurve,
) -> RmfStatus {
    guard("rmf_shape_face_loop", || {
        let shape = reference(shape, "shape")?;
        let out = out_ptr(out, "out")?;
        let Some(loops) = shape.loops.get(face) else {
            return invalid_arg(format!(
                "face = {face} but the shape has {} faces",
                shape.loops.len()
            ));
        };
        let Some(curve) = loops.get(r#loop) else {
            return invalid_arg(format!(
                "loop = {} but face {face} has {} loops",
                r#loop,
                loops.len()
            ));
        };
        write(out, curve as *const RmfCurve);
        Ok(())
    })
}

/// The accuracy figures of a wire sweep (see RmfSweepReport). The first call on a shape
/// measures the figures the construction did not need (the largest cosine between
/// parameter lines; along curve pieces the frames' angle to the exact RMF and, where a
/// bound already ruled out a fold, the least singularity margin); later calls return them.
///
/// @param[in] shape A shape made by rmf_wire_sweep.
/// @param[out] out Receives the report.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if shape or out is NULL.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_report(
    shape: *const RmfShape,
    out: *mut RmfSweepReport,
) -> RmfStatus {
    guard("rmf_shape_report", || {
        let shape = reference(shape, "shape")?;
        let out = out_ptr(out, "out")?;
        let r = shape.shape.report();
        write(
            out,
            RmfSweepReport {
                spine_distance: r.spine_distance,
                rmf_angle_error: r.rmf_angle_error,
                max_parameter_cosine: r.max_parameter_cosine,
                singularity_margin: r.singularity_margin,
                face_count: r.face_count,
                corner_turn: r.corner_turn,
                seam_gap: r.seam_gap,
                joint_gap: r.joint_gap,
                frame_error: r.frame_error,
            },
        );
        Ok(())
    })
}

/// The volume a solid encloses: ⅓ ∮ x·n dA over its faces, by 24-point Gauss–Legendre
/// quadrature on every rational patch and cap loop segment, about the wire's centre (so
/// that nothing is lost to its position) — far closer than OpenCascade's fixed-order
/// `BRepGProp::VolumeProperties` (at most 61 points along a whole face's edge), which
/// FreeCAD's `Shape.Volume` and build123d's `volume` use.
///
/// @param[in] shape A shape made by rmf_wire_sweep.
/// @param[out] out Receives the volume (untouched on failure).
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If shape or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the shape is a sheet (it encloses no volume), or the
/// volume is outside the range of a double (a wire 1e-200 long encloses about 1e-600).
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_volume(shape: *const RmfShape, out: *mut f64) -> RmfStatus {
    guard("rmf_shape_volume", || {
        let shape = reference(shape, "shape")?;
        let out = out_ptr(out, "out")?;
        let volume = shape.shape.volume()?;
        write(out, volume);
        Ok(())
    })
}

/// Writes a shape as a STEP AP214 file: a solid as a MANIFOLD_SOLID_BREP (a closed shell of
/// ADVANCED_FACEs on rational B-spline surfaces and planes, sharing edges and vertices),
/// a sheet as an open shell. FreeCAD and OpenCascade read it as one valid Solid. The file
/// is written under a temporary name beside `path` and renamed: on failure nothing is
/// written at `path`.
///
/// @param[in] shape The shape.
/// @param[in] path The file's path (NUL-terminated; its stem names the product).
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If shape or path is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the shape cannot be written as STEP.
/// @return RMF_ERROR_IO If the file cannot be written (the message names it and says why).
/// \since 0.2
/// \ingroup rmf_export
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_write_step(
    shape: *const RmfShape,
    path: *const c_char,
) -> RmfStatus {
    guard("rmf_shape_write_step", || {
        let shape = reference(shape, "shape")?;
        if path.is_null() {
            return Err(FfiError::Null("path"));
        }
        use std::os::unix::ffi::OsStrExt;
        let path =
            std::path::Path::new(std::ffi::OsStr::from_bytes(CStr::from_ptr(path).to_bytes()));
        let name = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("rmfsurf");
        let text = shape.shape.to_step(name)?;
        write_atomically(path, text.as_bytes())
            .map_err(|e| FfiError::Io(format!("cannot write {}: {e}", path.display())))
    })
}

/// The STEP AP214 text of a shape, as rmf_shape_write_step writes it, into a caller buffer:
/// for a caller that writes the file or stream itself, or hands the text to a reader
/// (OpenCascade's STEPControl_Reader reads a stream).
///
/// Size query: with capacity 0 (buffer may be NULL) only length is written. Otherwise the
/// text and a terminating NUL are written if capacity ≥ length + 1.
///
/// @param[in] shape The shape.
/// @param[in] name The product's name (NUL-terminated UTF-8), or NULL for "rmfsurf".
/// @param[out] buffer capacity bytes for the text and its NUL.
/// @param[in] capacity Size of buffer in bytes; 0 for a size query.
/// @param[out] length Receives the length of the text (without the NUL).
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If shape or length is NULL, or buffer is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity ≤ length; length is written.
/// @return RMF_ERROR_INVALID_INPUT If name is not UTF-8.
/// \since 0.2
/// \ingroup rmf_export
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_step(
    shape: *const RmfShape,
    name: *const c_char,
    buffer: *mut c_char,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_shape_step", || {
        let shape = reference(shape, "shape")?;
        let length = out_ptr(length, "length")?;
        let out = crate::boundary::buffer(buffer.cast::<u8>(), capacity, "buffer")?;
        let name = if name.is_null() {
            "rmfsurf"
        } else {
            match CStr::from_ptr(name).to_str() {
                Ok(name) => name,
                Err(e) => return invalid_arg(format!("name is not UTF-8: {e}")),
            }
        };
        let text = shape.shape.to_step(name)?;
        crate::boundary::hand_text(&text, out, length)
    })
}

/// The shape in OpenCascade's own B-rep text (`CASCADE Topology V1`, what
/// `BRepTools::Write` writes) into a caller buffer: `BRepTools::Read` (C++, or OCP's
/// `BRepTools.Read_s` from a `BytesIO`) and FreeCAD's `Part.Shape.importBrepFromString`
/// build the solid or shell from it as it is — shared edges, their curves on every face,
/// the faces' senses — with no sewing or healing.
///
/// Size query: with capacity 0 (buffer may be NULL) only length is written. Otherwise the
/// text and a terminating NUL are written if capacity ≥ length + 1.
///
/// @param[in] shape The shape.
/// @param[out] buffer capacity bytes for the text and its NUL.
/// @param[in] capacity Size of buffer in bytes; 0 for a size query.
/// @param[out] length Receives the length of the text (without the NUL).
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If shape or length is NULL, or buffer is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity ≤ length; length is written.
/// \since 0.2
/// \ingroup rmf_export
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_occ_brep(
    shape: *const RmfShape,
    buffer: *mut c_char,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_shape_occ_brep", || {
        let shape = reference(shape, "shape")?;
        let length = out_ptr(length, "length")?;
        let out = crate::boundary::buffer(buffer.cast::<u8>(), capacity, "buffer")?;
        let text = crate::boundary::made_once(&shape.occ_brep, || shape.shape.to_occ_brep())?;
        crate::boundary::hand_text(text, out, length)
    })
}

/// Which program reads a binary B-rep (rmf_shape_occ_binary, rmf_brep_occ_binary): the
/// file ends with the reference to its root shape as that program takes it.
/// \ingroup rmf_export
pub type RmfOccReader = u32;
/// OpenCascade's BinTools::Read (C++; build123d and CadQuery through OCP's
/// BinTools.Read_s from a BytesIO).
/// \since 0.2
/// \ingroup rmf_export
pub const RMF_OCC_READER_BINTOOLS: RmfOccReader = 0;
/// FreeCAD's Part.Shape.importBinary (a file, as Part.Shape.exportBinary writes it).
/// \since 0.2
/// \ingroup rmf_export
pub const RMF_OCC_READER_FREECAD: RmfOccReader = 1;

/// The reader behind an RMF_OCC_READER_* value.
pub(crate) fn occ_reader(reader: RmfOccReader) -> FfiResult<OccReader> {
    match reader {
        RMF_OCC_READER_BINTOOLS => Ok(OccReader::BinTools),
        RMF_OCC_READER_FREECAD => Ok(OccReader::FreeCad),
        other => invalid_arg(format!(
            "reader = {other} is not one of the RMF_OCC_READER_* values"
        )),
    }
}

/// The shape in OpenCascade's binary B-rep ("Open CASCADE Topology V3", what
/// BinTools::Write writes) into a caller buffer: the shape of rmf_shape_occ_brep — shared
/// edges, their curves on every face, the faces' senses — which the kernel reads several
/// times faster than the text (the numbers as they are in memory, no parsing). The file
/// ends with the root as `reader` takes it (RMF_OCC_READER_BINTOOLS: BinTools::Read;
/// RMF_OCC_READER_FREECAD: FreeCAD's Part.Shape.importBinary).
///
/// Size query: with capacity 0 (buffer may be NULL) only length is written. Otherwise the
/// file is written if capacity ≥ length.
///
/// @param[in] shape The shape.
/// @param[in] reader RMF_OCC_READER_*.
/// @param[out] buffer capacity bytes for the file.
/// @param[in] capacity Size of buffer in bytes; 0 for a size query.
/// @param[out] length Receives the length of the file in bytes.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If shape or length is NULL, or buffer is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_INVALID_INPUT If reader is not an RMF_OCC_READER_* value.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity < length; length is written.
/// \since 0.2
/// \ingroup rmf_export
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_occ_binary(
    shape: *const RmfShape,
    reader: RmfOccReader,
    buffer: *mut u8,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_shape_occ_binary", || {
        let shape = reference(shape, "shape")?;
        hand_occ_binary(
            &shape.occ_binary,
            || shape.shape.to_occ_binary(),
            reader,
            buffer,
            capacity,
            length,
        )
    })
}

/// A binary B-rep into a caller buffer, made by `make` into `cell` on the first call
/// (rmf_shape_occ_binary, rmf_brep_occ_binary: `length`, `reader`, then `buffer` checked).
///
/// # Safety
/// `buffer` and `length` as the calls document them.
pub(crate) unsafe fn hand_occ_binary(
    cell: &std::sync::OnceLock<OccBinary>,
    make: impl FnOnce() -> rmfsurf::Result<OccBinary>,
    reader: RmfOccReader,
    buffer: *mut u8,
    capacity: usize,
    length: *mut usize,
) -> FfiResult {
    let length = out_ptr(length, "length")?;
    let reader = occ_reader(reader)?;
    let out = crate::boundary::buffer(buffer, capacity, "buffer")?;
    let file = crate::boundary::made_once(cell, make)?;
    crate::boundary::hand_bytes(file.set(), &file.root(reader), out, length)
}

/// Writes `bytes` beside `path` under a temporary name, then renames it to `path`. The
/// temporary name is the process's and a call's own (a counter), created exclusively: threads
/// and processes writing the same path at once each finish their file, and the last rename
/// wins with a whole file.
fn write_atomically(path: &std::path::Path, bytes: &[u8]) -> std::io::Result<()> {
    static CALLS: AtomicU64 = AtomicU64::new(0);
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("shape");
    // A name left by an earlier process of the same id is skipped, never overwritten.
    let (temp, file) = loop {
        let call = CALLS.fetch_add(1, Ordering::Relaxed);
        let temp =
            path.with_file_name(format!(".{name}.rmfsurf-{}-{call}.tmp", std::process::id()));
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temp)
        {
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
            Ok(file) => break (temp, file),
        }
    };
    let mut file = file;
    let result = file
        .write_all(bytes)
        .and_then(|()| file.sync_all())
        .and_then(|()| std::fs::rename(&temp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&temp);
    }
    result
}

/// The boundary representation of a wire sweep's shape (its solid or sheet), as the STEP
/// and OpenCascade texts write it.
///
/// @param[in] shape The shape.
/// @param[out] out Receives a new B-rep; free it with rmf_brep_free.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_shape_brep(
    shape: *const RmfShape,
    out: *mut *mut crate::brep::RmfBrep,
) -> RmfStatus {
    guard("rmf_shape_brep", || {
        let shape = reference(shape, "shape")?;
        let out = out_ptr(out, "out")?;
        write(
            out,
            crate::brep::RmfBrep::new(shape.shape.brep().clone()).into_raw(),
        );
        Ok(())
    })
}
