//! `RmfSheetPart`, the sheet-metal parts of cone splines: transition pieces between two
//! closed curves, parts between the rails of a ruled developable or of a tangent surface;
//! their sheet (`RmfSheetOptions`), layers and closed solid, the neutral layer's flat pattern
//! for the cutter, and the maps between flat and formed. `rmf_sheet_part_cone_spline` hands
//! the designed surface to the cone spline calls.
//!
//! Before `RmfSheetPart`, a part was an `RmfConeSpline` that refused the part calls at run
//! time when it held no part; those calls (`rmf_cone_spline_transition`, `_part`,
//! `_tangent_part`, `_part_*`, `_flat_*`, `_surface_to_flat`) are deprecated wrappers of the
//! ones here.

use super::boundary::{
    buffer, free_handle, guard, hand_over, invalid_arg, optional_out, out_ptr, reference, slice,
    write, FfiError, FfiResult, OptionsStruct,
};
use super::cone_spline::RmfConeSpline;
use super::curve::RmfCurve;
use super::status::RmfStatus;
use super::surface::RmfSurface;
use super::types::{RmfVec2, RmfVec3};
use rmfsurf::export::{dxf, step, svg};
use rmfsurf::glam::DVec2;
use rmfsurf::PatternEdge;
use rmfsurf::{
    sheet::Layer, sheet::Reference, sheet::Sheet, sheet::SheetOptions, sheet::SheetPart,
    sheet::Side,
};
use std::ffi::c_char;
use std::sync::{Arc, OnceLock};

/// Which face of the sheet the designed surface is (RmfSheetOptions.reference).
/// \ingroup rmf_sheet
pub type RmfSheetReference = u32;
/// The designed surface is the inner face (the concave side of the bends): the sheet lies
/// on the convex side. The default; the only choice for parts with a vertex on an edge
/// (transitions from polygon corners), whose bend radius is 0 there.
/// \ingroup rmf_sheet
pub const RMF_SHEET_REFERENCE_INNER: RmfSheetReference = 0;
/// The designed surface is the neutral layer.
/// \ingroup rmf_sheet
pub const RMF_SHEET_REFERENCE_NEUTRAL: RmfSheetReference = 1;
/// The designed surface is the outer face: the sheet lies towards the bend centres.
/// \ingroup rmf_sheet
pub const RMF_SHEET_REFERENCE_OUTER: RmfSheetReference = 2;

/// A surface of the formed sheet.
/// \ingroup rmf_sheet
pub type RmfSheetLayer = u32;
/// The designed surface (through the input's curves).
/// \ingroup rmf_sheet
pub const RMF_SHEET_LAYER_REFERENCE: RmfSheetLayer = 0;
/// The inner face (concave side).
/// \ingroup rmf_sheet
pub const RMF_SHEET_LAYER_INNER: RmfSheetLayer = 1;
/// The neutral layer, at k·t from the inner face: the one the flat pattern develops.
/// \ingroup rmf_sheet
pub const RMF_SHEET_LAYER_NEUTRAL: RmfSheetLayer = 2;
/// The outer face.
/// \ingroup rmf_sheet
pub const RMF_SHEET_LAYER_OUTER: RmfSheetLayer = 3;

/// Which boundary of a part.
/// \ingroup rmf_sheet
pub type RmfSheetSide = u32;
/// The first boundary: a transition's bottom curve (u = 0 of the layer surfaces).
/// \ingroup rmf_sheet
pub const RMF_SHEET_SIDE_FIRST: RmfSheetSide = 0;
/// The second boundary: a transition's top curve (u = 1).
/// \ingroup rmf_sheet
pub const RMF_SHEET_SIDE_SECOND: RmfSheetSide = 1;

/// What rmf_cone_spline_part_export writes.
/// \ingroup rmf_export
pub type RmfSheetFormat = u32;
/// STEP AP214: the formed part as a closed solid (MANIFOLD_SOLID_BREP) between its inner
/// and outer face, with normal-cut edges.
/// \ingroup rmf_export
pub const RMF_SHEET_FORMAT_STEP_SOLID: RmfSheetFormat = 0;
/// STEP AP214: the flat pattern as one planar face bounded by lines and circles.
/// \ingroup rmf_export
pub const RMF_SHEET_FORMAT_STEP_FLAT: RmfSheetFormat = 1;
/// DXF R12: the flat pattern, LINE and ARC entities, outline on layer CUT, bend lines on
/// layer BEND.
/// \ingroup rmf_export
pub const RMF_SHEET_FORMAT_DXF: RmfSheetFormat = 2;
/// SVG 1.1: the flat pattern in millimetres, bend lines dashed.
/// \ingroup rmf_export
pub const RMF_SHEET_FORMAT_SVG: RmfSheetFormat = 3;
/// OpenCascade's own B-rep text ("CASCADE Topology V1", what BRepTools::Read and FreeCAD's
/// Part.Shape.importBrepFromString read): the formed part as the solid of
/// RMF_SHEET_FORMAT_STEP_SOLID, its faces sharing their edges, built by the kernel as it
/// is (no sewing or healing).
/// \since 0.2
/// \ingroup rmf_export
pub const RMF_SHEET_FORMAT_OCC_BREP: RmfSheetFormat = 4;

/// RmfFlatEdge.kind: a straight segment.
/// \ingroup rmf_sheet
pub const RMF_FLAT_EDGE_LINE: u32 = 0;
/// RmfFlatEdge.kind: a circular arc.
/// \ingroup rmf_sheet
pub const RMF_FLAT_EDGE_ARC: u32 = 1;
/// RmfFlatEdge.layer: the cutting outline.
/// \ingroup rmf_sheet
pub const RMF_FLAT_CUT: u32 = 0;
/// RmfFlatEdge.layer: a bend line (a ruling where two pieces meet).
/// \ingroup rmf_sheet
pub const RMF_FLAT_BEND: u32 = 1;

/// How a sheet-metal part is built and cut. Initialise with rmf_sheet_options_init, then
/// change fields; the struct only grows at the end.
/// \ingroup rmf_sheet
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfSheetOptions {
    /// sizeof(RmfSheetOptions), written by rmf_sheet_options_init.
    pub struct_size: usize,
    /// Largest distance of the surface from the designed developable and of the part's
    /// edges from the input's curves (default 1e-4), > 0.
    pub tolerance: f64,
    /// Sheet thickness t (default 1), > 0.
    pub thickness: f64,
    /// K-factor k (default 0.5): the neutral layer lies at k·t from the inner face,
    /// 0 ≤ k ≤ 1 (docs/sheet-metal.md has a table by material and bend ratio).
    pub k_factor: f64,
    /// RMF_SHEET_REFERENCE_* (default RMF_SHEET_REFERENCE_INNER).
    pub reference: RmfSheetReference,
    /// Largest distance of the flat outline's biarcs from the exact developed boundary;
    /// 0 (the default) means the tolerance.
    pub flat_tolerance: f64,
    /// Most cone pieces (default 10000), ≥ 2.
    pub max_pieces: usize,
}

impl Default for RmfSheetOptions {
    fn default() -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            tolerance: 1e-4,
            thickness: 1.0,
            k_factor: 0.5,
            reference: RMF_SHEET_REFERENCE_INNER,
            flat_tolerance: 0.0,
            max_pieces: rmfsurf::cone::DEFAULT_MAX_PIECES,
        }
    }
}

// SAFETY: repr(C) plain data, first field usize; every bit pattern is a valid value.
unsafe impl OptionsStruct for RmfSheetOptions {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// One edge of a flat pattern: a line from `from` to `to`, or an arc about `center` of
/// `radius` from `from` through the signed angle `sweep` (counter-clockwise when positive)
/// to `to`. Coordinates in the caller's units, in the plane of the flat pattern.
/// \ingroup rmf_sheet
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfFlatEdge {
    /// RMF_FLAT_CUT or RMF_FLAT_BEND.
    pub layer: u32,
    /// RMF_FLAT_EDGE_LINE or RMF_FLAT_EDGE_ARC.
    pub kind: u32,
    /// The start point.
    pub from: RmfVec2,
    /// The end point.
    pub to: RmfVec2,
    /// Arcs only (0 for lines): the centre.
    pub center: RmfVec2,
    /// Arcs only (0 for lines): the radius.
    pub radius: f64,
    /// Arcs only (0 for lines): the signed angle from `from` to `to` about `center`,
    /// radians, counter-clockwise when positive.
    pub sweep: f64,
}

/// What the construction of a part measured and chose (caller's units).
/// \ingroup rmf_sheet
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfSheetReport {
    /// Number of cone, cylinder and plane pieces.
    pub pieces: usize,
    /// 1 if the part closes on itself (a transition), 0 for an open part.
    pub closed: u32,
    /// Largest sampled distance of the cone spline from the designed developable.
    pub deviation: f64,
    /// Largest sampled distance of the first and second boundary from the input's curves.
    pub edge_distance: [f64; 2],
    /// The smallest bend radius of the designed surface (0 at a vertex on an edge).
    pub bend_radius: f64,
    /// Distance of the inner layer from the designed surface, along the normal from the
    /// concave to the convex side.
    pub inner: f64,
    /// Distance of the neutral layer from the designed surface, along the same normal.
    pub neutral: f64,
    /// Distance of the outer layer from the designed surface, along the same normal.
    pub outer: f64,
}

fn reference_from(code: RmfSheetReference) -> FfiResult<Reference> {
    Ok(match code {
        RMF_SHEET_REFERENCE_INNER => Reference::Inner,
        RMF_SHEET_REFERENCE_NEUTRAL => Reference::Neutral,
        RMF_SHEET_REFERENCE_OUTER => Reference::Outer,
        other => {
            return invalid_arg(format!(
                "options->reference = {other} is not one of the RMF_SHEET_REFERENCE_* values"
            ))
        }
    })
}

fn layer_from(code: RmfSheetLayer) -> FfiResult<Layer> {
    Ok(match code {
        RMF_SHEET_LAYER_REFERENCE => Layer::Reference,
        RMF_SHEET_LAYER_INNER => Layer::Inner,
        RMF_SHEET_LAYER_NEUTRAL => Layer::Neutral,
        RMF_SHEET_LAYER_OUTER => Layer::Outer,
        other => {
            return invalid_arg(format!(
                "layer = {other} is not one of the RMF_SHEET_LAYER_* values"
            ))
        }
    })
}

/// The core options; messages name the C fields.
unsafe fn options_from(options: *const RmfSheetOptions) -> FfiResult<SheetOptions> {
    let o = super::boundary::options(options, "options")?;
    let sheet = Sheet::new(o.thickness, o.k_factor, reference_from(o.reference)?).map_err(|e| {
        FfiError::Core(rmfsurf::Error::invalid_input(format!(
            "options->{}",
            e.message()
        )))
    })?;
    if !(o.tolerance.is_finite() && o.tolerance > 0.0) {
        return invalid_arg(format!(
            "options->tolerance = {} must be finite and positive",
            o.tolerance
        ));
    }
    if !(o.flat_tolerance.is_finite() && o.flat_tolerance >= 0.0) {
        return invalid_arg(format!(
            "options->flat_tolerance = {} must be finite and ≥ 0 (0: the tolerance)",
            o.flat_tolerance
        ));
    }
    if o.max_pieces < 2 {
        return invalid_arg(format!(
            "options->max_pieces = {} must be at least 2",
            o.max_pieces
        ));
    }
    Ok(SheetOptions {
        tolerance: o.tolerance,
        sheet,
        flat_tolerance: o.flat_tolerance,
        max_pieces: o.max_pieces,
    })
}

/// A sheet-metal part behind its handle, with the texts of its files as made (a caller asks
/// twice: the size, then the text).
pub(crate) struct PartHandle {
    pub(crate) part: SheetPart,
    texts: [OnceLock<String>; 5],
}

impl PartHandle {
    pub(crate) fn new(part: SheetPart) -> Self {
        Self {
            part,
            texts: Default::default(),
        }
    }
}

/// Writes the default options and the struct's size.
///
/// @param[out] options Receives the defaults (tolerance 1e-4, thickness 1, k_factor 0.5,
///             reference inner, flat_tolerance 0 = the tolerance, max_pieces 10000).
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if options is NULL.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_options_init(options: *mut RmfSheetOptions) -> RmfStatus {
    guard("rmf_sheet_options_init", || {
        let options = out_ptr(options, "options")?;
        write(options, RmfSheetOptions::default());
        Ok(())
    })
}

/// A sheet-metal part (opaque): a transition piece, a part between the rails of a ruled
/// developable or of a tangent surface, with its sheet (thickness, K-factor). Made by
/// rmf_sheet_part_transition, rmf_sheet_part_between_rails or rmf_sheet_part_tangent; freed
/// with rmf_sheet_part_free. Immutable; may be read from several threads at once.
/// \since 0.2
/// \ingroup rmf_sheet
pub struct RmfSheetPart {
    handle: Arc<PartHandle>,
}

impl RmfSheetPart {
    fn new(part: SheetPart) -> Self {
        Self {
            handle: Arc::new(PartHandle::new(part)),
        }
    }

    fn into_raw(self) -> *mut Self {
        Box::into_raw(Box::new(self))
    }
}

/// The part behind a handle, or an error naming it.
unsafe fn sheet_part<'a>(part: *const RmfSheetPart) -> FfiResult<&'a PartHandle> {
    Ok(&reference(part, "part")?.handle)
}

/// The part an RmfConeSpline of the deprecated calls holds, or an error naming it.
unsafe fn spline_part<'a>(part: *const RmfConeSpline) -> FfiResult<&'a PartHandle> {
    reference(part, "part")?.part.as_deref().ok_or_else(|| {
        FfiError::Core(rmfsurf::Error::invalid_input(
            "part is not a sheet-metal part (a cone spline holds one when it comes from \
             rmf_sheet_part_cone_spline; an RmfSheetPart takes the rmf_sheet_part_* calls)",
        ))
    })
}

/// Frees a part; NULL is a no-op. Cone splines from rmf_sheet_part_cone_spline stay valid.
///
/// @param[in] part The part, or NULL.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_free(part: *mut RmfSheetPart) {
    free_handle(part);
}

/// The part's designed surface as a cone spline (its pieces, surface strips, bending,
/// development and offsets through the rmf_cone_spline_* calls).
///
/// @param[in] part A part.
/// @param[out] out Receives a new cone spline; free it with rmf_cone_spline_free (it stays
///             valid after the part is freed). Untouched on failure.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_cone_spline(
    part: *const RmfSheetPart,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_sheet_part_cone_spline", || {
        let handle = &reference(part, "part")?.handle;
        let out = out_ptr(out, "out")?;
        write(out, RmfConeSpline::of_part(Arc::clone(handle))?.into_raw());
        Ok(())
    })
}

/// The transition piece between two closed convex planar curves — square-to-round,
/// rectangle-to-round, round-to-round with offset or inclined planes, obround, polygon to
/// polygon, any convex NURBS: the lateral surface of their convex hull, the developable
/// that joins them. Flat triangles from straight edges, cones from corners to arcs
/// (vertex at the corner), creases from corner to corner (bends of zero inner radius), and
/// between two smooth arcs the rulings joining points with a common tangent plane; the
/// cones and general parts as cone splines within the tolerance (Leopoldseder & Pottmann),
/// G1 except at creases, each piece trimmed exactly by the two curves' planes. The sheet
/// (thickness, K-factor) is that of `options`.
///
/// The curves must be closed and planar (to 1e-9 of their size), convex, and each must lie
/// strictly on one side of the other's plane. Corners are where consecutive Bézier
/// segments meet with different tangents (a polygon: degree 1 segments; a circle: rational
/// quadratics).
///
/// @param[in] bottom The first boundary (e.g. from rmf_nurbs_curve_create).
/// @param[in] top The second boundary.
/// @param[in] options The sheet and tolerances, or NULL for the defaults; read during the
///            call only.
/// @param[out] out Receives the part; free with rmf_sheet_part_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If bottom, top or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a curve is not closed, not planar or not convex (the
///         message names it and says by how much), the curves cross each other's planes,
///         or an option is out of range: tolerance ≤ 0, thickness ≤ 0, k_factor outside
///         [0, 1], an unknown reference, or a reference whose inner face would pass a
///         vertex (thickness beyond the smallest bend radius).
/// @return RMF_ERROR_NO_SOLUTION If the hull has a degenerate ruling.
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance needs more than max_pieces pieces.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_transition(
    bottom: *const RmfCurve,
    top: *const RmfCurve,
    options: *const RmfSheetOptions,
    out: *mut *mut RmfSheetPart,
) -> RmfStatus {
    guard("rmf_sheet_part_transition", || {
        let out = out_ptr(out, "out")?;
        write(
            out,
            RmfSheetPart::new(transition(bottom, top, options)?).into_raw(),
        );
        Ok(())
    })
}

/// rmf_sheet_part_transition, handing the part out as an RmfConeSpline (the designed surface's cone spline,
/// holding the part for the rmf_cone_spline_part_* calls); free with rmf_cone_spline_free.
///
/// @param bottom, top, options, out As for rmf_sheet_part_transition.
/// \deprecated Use rmf_sheet_part_transition; rmf_sheet_part_cone_spline gives the cone spline.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_transition")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_transition(
    bottom: *const RmfCurve,
    top: *const RmfCurve,
    options: *const RmfSheetOptions,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_transition", || {
        let out = out_ptr(out, "out")?;
        let part = RmfSheetPart::new(transition(bottom, top, options)?);
        write(out, RmfConeSpline::of_part(part.handle)?.into_raw());
        Ok(())
    })
}

unsafe fn transition(
    bottom: *const RmfCurve,
    top: *const RmfCurve,
    options: *const RmfSheetOptions,
) -> FfiResult<SheetPart> {
    let bottom = reference(bottom, "bottom")?;
    let top = reference(top, "top")?;
    let options = options_from(options)?;
    Ok(SheetPart::transition(
        bottom.rational("bottom")?,
        top.rational("top")?,
        &options,
    )?)
}

/// The part of a developable ruled surface between its two rails: the surface's
/// boundaries u = u₀ and u = u₁ (a NURBS of degree (1, n), rulings along u), over its whole
/// v domain. The developable is approximated by a cone spline (Leopoldseder & Pottmann)
/// within half the tolerance, with no cone vertex on the part, and each piece is trimmed
/// between the rails — the ruling segments run from rail to rail (degree (1, 5) patches),
/// G1 across pieces, each boundary within the tolerance of its rail — not between two
/// parallel circles. The sheet (thickness, K-factor) is that of `options`.
///
/// @param[in] surface A surface with degree_u = 1 and pole_count_u = 2 (e.g. from
///            rmf_nurbs_surface_create); its parameter v runs along the rails. Read during
///            the call only.
/// @param[in] options The sheet and tolerances, or NULL for the defaults; read during the
///            call only.
/// @param[out] out Receives the part; free with rmf_sheet_part_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If surface or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the surface is not of degree 1 in u with one span, is
///         not developable (the message gives its max |K|·size²), or an option is out of
///         range (as for rmf_sheet_part_transition).
/// @return RMF_ERROR_NO_SOLUTION If a ruling of the surface is degenerate.
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance needs more than max_pieces pieces, or
///         the cone fit keeps a vertex on the part.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_between_rails(
    surface: *const RmfSurface,
    options: *const RmfSheetOptions,
    out: *mut *mut RmfSheetPart,
) -> RmfStatus {
    guard("rmf_sheet_part_between_rails", || {
        let out = out_ptr(out, "out")?;
        write(
            out,
            RmfSheetPart::new(between_rails(surface, options)?).into_raw(),
        );
        Ok(())
    })
}

/// rmf_sheet_part_between_rails, handing the part out as an RmfConeSpline (the designed surface's cone spline,
/// holding the part for the rmf_cone_spline_part_* calls); free with rmf_cone_spline_free.
///
/// @param surface, options, out As for rmf_sheet_part_between_rails.
/// \deprecated Use rmf_sheet_part_between_rails; rmf_sheet_part_cone_spline gives the cone spline.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_between_rails")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_part(
    surface: *const RmfSurface,
    options: *const RmfSheetOptions,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_part", || {
        let out = out_ptr(out, "out")?;
        let part = RmfSheetPart::new(between_rails(surface, options)?);
        write(out, RmfConeSpline::of_part(part.handle)?.into_raw());
        Ok(())
    })
}

unsafe fn between_rails(
    surface: *const RmfSurface,
    options: *const RmfSheetOptions,
) -> FfiResult<SheetPart> {
    let surface = reference(surface, "surface")?;
    let options = options_from(options)?;
    Ok(SheetPart::between_rails(surface.surface.as_ref(), &options)
        .map_err(|e| e.context("surface"))?)
}

/// The part of the tangent surface x(t) + v·x′(t)/|x′(t)| of a regular curve over the
/// curve's whole domain, between the rails v = v_min and v = v_max: a cone spline within
/// half the tolerance, trimmed on every piece between the two rails, as rmf_sheet_part_between_rails.
///
/// @param[in] curve A regular rational curve (NURBS data or a computed curve; not a
///            callback curve). Read during the call only.
/// @param[in] v_min, v_max Signed distances along the unit tangent, finite, v_min < v_max,
///            0 outside [v_min, v_max] (the curve itself is the surface's edge of regression).
/// @param[in] options The sheet and tolerances, or NULL for the defaults.
/// @param[out] out Receives the part; free with rmf_sheet_part_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If curve or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If curve is a callback curve, v_min or v_max is not
///         finite, v_min ≥ v_max, [v_min, v_max] contains 0, or an option is out of range.
/// @return RMF_ERROR_NO_SOLUTION If the curve is not regular.
/// @return RMF_ERROR_NOT_CONVERGED As for rmf_sheet_part_between_rails.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_tangent(
    curve: *const RmfCurve,
    v_min: f64,
    v_max: f64,
    options: *const RmfSheetOptions,
    out: *mut *mut RmfSheetPart,
) -> RmfStatus {
    guard("rmf_sheet_part_tangent", || {
        let out = out_ptr(out, "out")?;
        write(
            out,
            RmfSheetPart::new(tangent(curve, v_min, v_max, options)?).into_raw(),
        );
        Ok(())
    })
}

/// rmf_sheet_part_tangent, handing the part out as an RmfConeSpline (the designed surface's cone spline,
/// holding the part for the rmf_cone_spline_part_* calls); free with rmf_cone_spline_free.
///
/// @param curve, v_min, v_max, options, out As for rmf_sheet_part_tangent.
/// \deprecated Use rmf_sheet_part_tangent; rmf_sheet_part_cone_spline gives the cone spline.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_tangent")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_tangent_part(
    curve: *const RmfCurve,
    v_min: f64,
    v_max: f64,
    options: *const RmfSheetOptions,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_tangent_part", || {
        let out = out_ptr(out, "out")?;
        let part = RmfSheetPart::new(tangent(curve, v_min, v_max, options)?);
        write(out, RmfConeSpline::of_part(part.handle)?.into_raw());
        Ok(())
    })
}

unsafe fn tangent(
    curve: *const RmfCurve,
    v_min: f64,
    v_max: f64,
    options: *const RmfSheetOptions,
) -> FfiResult<SheetPart> {
    let curve = reference(curve, "curve")?;
    let options = options_from(options)?;
    Ok(SheetPart::tangent_surface(
        curve.rational("curve")?,
        v_min,
        v_max,
        &options,
    )?)
}

/// What a part's construction measured: pieces, closure, distances of the surface and of
/// the edges from the input, the smallest bend radius, the layers' distances.
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[out] report Receives the report.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_report(
    part: *const RmfSheetPart,
    report: *mut RmfSheetReport,
) -> RmfStatus {
    guard("rmf_sheet_part_report", || {
        write_report(&sheet_part(part)?.part, report)
    })
}

/// rmf_sheet_part_report on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, report As for rmf_sheet_part_report.
/// \deprecated Use rmf_sheet_part_report.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_report")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_part_report(
    part: *const RmfConeSpline,
    report: *mut RmfSheetReport,
) -> RmfStatus {
    guard("rmf_cone_spline_part_report", || {
        write_report(&spline_part(part)?.part, report)
    })
}

unsafe fn write_report(p: &SheetPart, report: *mut RmfSheetReport) -> FfiResult {
    let report = out_ptr(report, "report")?;
    let r = p.report();
    write(
        report,
        RmfSheetReport {
            pieces: p.piece_count(),
            closed: u32::from(p.is_closed()),
            deviation: r.deviation,
            edge_distance: r.edge_distance,
            bend_radius: p.bend_radius(),
            inner: p.layer_distance(Layer::Inner),
            neutral: p.layer_distance(Layer::Neutral),
            outer: p.layer_distance(Layer::Outer),
        },
    );
    Ok(())
}

/// A layer of the formed part as one NURBS surface: u ∈ [0, 1] along the rulings from the
/// first to the second boundary, v ∈ [k, k + 1] on piece k, G1 across the rulings (except
/// at creases); exact rational (degree 1 in u).
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[in] layer RMF_SHEET_LAYER_*.
/// @param[out] out Receives the surface; free with rmf_surface_free.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT for an unknown
///         layer.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_surface(
    part: *const RmfSheetPart,
    layer: RmfSheetLayer,
    out: *mut *mut RmfSurface,
) -> RmfStatus {
    guard("rmf_sheet_part_surface", || {
        write_surface(&sheet_part(part)?.part, layer, out)
    })
}

/// rmf_sheet_part_surface on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, layer, out As for rmf_sheet_part_surface.
/// \deprecated Use rmf_sheet_part_surface.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_surface")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_part_surface(
    part: *const RmfConeSpline,
    layer: RmfSheetLayer,
    out: *mut *mut RmfSurface,
) -> RmfStatus {
    guard("rmf_cone_spline_part_surface", || {
        write_surface(&spline_part(part)?.part, layer, out)
    })
}

unsafe fn write_surface(
    p: &SheetPart,
    layer: RmfSheetLayer,
    out: *mut *mut RmfSurface,
) -> FfiResult {
    let out = out_ptr(out, "out")?;
    let surface = p.surface(layer_from(layer)?)?;
    write(out, RmfSurface::new(surface, None).into_raw());
    Ok(())
}

/// A boundary curve of a layer (the edge of the formed part on that layer), with the
/// surface's v parameter: on the designed surface within the tolerance of the input's
/// curve (exactly in its plane for transitions).
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[in] layer RMF_SHEET_LAYER_*.
/// @param[in] side RMF_SHEET_SIDE_FIRST or RMF_SHEET_SIDE_SECOND.
/// @param[out] out Receives the curve; free with rmf_curve_free.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT for unknown codes.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_boundary(
    part: *const RmfSheetPart,
    layer: RmfSheetLayer,
    side: RmfSheetSide,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_sheet_part_boundary", || {
        write_boundary(&sheet_part(part)?.part, layer, side, out)
    })
}

/// rmf_sheet_part_boundary on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, layer, side, out As for rmf_sheet_part_boundary.
/// \deprecated Use rmf_sheet_part_boundary.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_boundary")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_part_boundary(
    part: *const RmfConeSpline,
    layer: RmfSheetLayer,
    side: RmfSheetSide,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_cone_spline_part_boundary", || {
        write_boundary(&spline_part(part)?.part, layer, side, out)
    })
}

unsafe fn write_boundary(
    p: &SheetPart,
    layer: RmfSheetLayer,
    side: RmfSheetSide,
    out: *mut *mut RmfCurve,
) -> FfiResult {
    let out = out_ptr(out, "out")?;
    let side = match side {
        RMF_SHEET_SIDE_FIRST => Side::First,
        RMF_SHEET_SIDE_SECOND => Side::Second,
        other => {
            return invalid_arg(format!(
                "side = {other} is not one of the RMF_SHEET_SIDE_* values"
            ))
        }
    };
    let curve = p.boundary(layer_from(layer)?, side)?;
    write(out, RmfCurve::new(curve, None).into_raw());
    Ok(())
}

/// The flat pattern of the neutral layer for the cutter: the outline (RMF_FLAT_CUT) as
/// lines and circular arcs only — exact where the development is a line or an arc, G1
/// biarcs within the flat tolerance elsewhere —, closed (each edge starts where the one
/// before ends, the last ends where the first starts) and counter-clockwise, followed by
/// the bend lines (RMF_FLAT_BEND). A closed part (a transition) is cut open along its seam,
/// the middle ruling of its largest planar piece.
///
/// Size query: with capacity 0 (edges may be NULL) only count is written.
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[out] edges Buffer for capacity edges: the outline first, then the bend lines.
/// @param[in] capacity Capacity of edges; 0 for a size query.
/// @param[out] count Receives the number of edges.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If part or count is NULL, or edges is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but too small; count is written.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_flat_pattern(
    part: *const RmfSheetPart,
    edges: *mut RmfFlatEdge,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_sheet_part_flat_pattern", || {
        hand_flat_pattern(&sheet_part(part)?.part, edges, capacity, count)
    })
}

/// rmf_sheet_part_flat_pattern on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, edges, capacity, count As for rmf_sheet_part_flat_pattern.
/// \deprecated Use rmf_sheet_part_flat_pattern.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_flat_pattern")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_flat_pattern(
    part: *const RmfConeSpline,
    edges: *mut RmfFlatEdge,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_cone_spline_flat_pattern", || {
        hand_flat_pattern(&spline_part(part)?.part, edges, capacity, count)
    })
}

unsafe fn hand_flat_pattern(
    p: &SheetPart,
    edges: *mut RmfFlatEdge,
    capacity: usize,
    count: *mut usize,
) -> FfiResult {
    let count = out_ptr(count, "count")?;
    let edges = buffer(edges, capacity, "edges")?;
    let flat = p.flat_pattern()?;
    let all: Vec<RmfFlatEdge> = flat
        .outline
        .iter()
        .map(|e| flat_edge(e, RMF_FLAT_CUT))
        .chain(flat.bend_lines.iter().map(|e| flat_edge(e, RMF_FLAT_BEND)))
        .collect();
    hand_over(&all, edges, count, "edges")
}

/// Marks from the flat pattern to the formed part — holes, slots, text outlines, fold
/// marks, given as points (curves as polylines): each flat point (coordinates of
/// rmf_sheet_part_flat_pattern) to the point of `layer` straight across the sheet from
/// its image on the neutral layer, by the exact isometry of the development (per piece a
/// rotation by f·φ sin α about the developed vertex against f·φ about the axis, not the
/// NURBS parameters), and optionally the unit normal there (from the inner to the outer
/// face).
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[in] flat count points of the flat pattern.
/// @param[in] count Number of points (0: nothing to do).
/// @param[in] layer RMF_SHEET_LAYER_*.
/// @param[out] points count points on the layer.
/// @param[out] normals count unit normals, or NULL.
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If part, flat or points is NULL (count > 0).
/// @return RMF_ERROR_INVALID_INPUT If a point is not finite or lies outside the flat
///         pattern (the message names it: flat[i]), or for an unknown layer.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_flat_to_surface(
    part: *const RmfSheetPart,
    flat: *const RmfVec2,
    count: usize,
    layer: RmfSheetLayer,
    points: *mut RmfVec3,
    normals: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_sheet_part_flat_to_surface", || {
        let p = &sheet_part(part)?.part;
        flat_to_surface(p, flat, count, layer, points, normals)
    })
}

/// rmf_sheet_part_flat_to_surface on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, flat, count, layer, points, normals As for rmf_sheet_part_flat_to_surface.
/// \deprecated Use rmf_sheet_part_flat_to_surface.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_flat_to_surface")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_flat_to_surface(
    part: *const RmfConeSpline,
    flat: *const RmfVec2,
    count: usize,
    layer: RmfSheetLayer,
    points: *mut RmfVec3,
    normals: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_cone_spline_flat_to_surface", || {
        let p = &spline_part(part)?.part;
        flat_to_surface(p, flat, count, layer, points, normals)
    })
}

unsafe fn flat_to_surface(
    p: &SheetPart,
    flat: *const RmfVec2,
    count: usize,
    layer: RmfSheetLayer,
    points: *mut RmfVec3,
    normals: *mut RmfVec3,
) -> FfiResult {
    let layer = layer_from(layer)?;
    let flat = slice(flat, count, "flat")?;
    let points = buffer(points, count, "points")?;
    let mut normals = match optional_out(normals, "normals")? {
        Some(n) => Some(buffer(n, count, "normals")?),
        None => None,
    };
    let mapped = flat
        .iter()
        .enumerate()
        .map(|(i, q)| p.flat_to_surface(DVec2::from(*q), layer, &format!("flat[{i}]")))
        .collect::<rmfsurf::Result<Vec<_>>>()?;
    for (i, (x, n)) in mapped.into_iter().enumerate() {
        points[i] = x.into();
        if let Some(normals) = normals.as_deref_mut() {
            normals[i] = n.into();
        }
    }
    Ok(())
}

/// Marks from the formed part to the flat pattern: each point on `layer` (within
/// max_distance of it) to the flat pattern's point of the neutral layer straight across
/// the sheet, by the exact isometry of the development.
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[in] points count points on the layer.
/// @param[in] count Number of points (0: nothing to do).
/// @param[in] layer RMF_SHEET_LAYER_*.
/// @param[in] max_distance Largest accepted distance of a point from the layer's part, ≥ 0.
/// @param[out] flat count points of the flat pattern.
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If part, points or flat is NULL (count > 0).
/// @return RMF_ERROR_INVALID_INPUT If a point is not finite or farther than max_distance
///         from the layer's part (the message names it: points[i], and gives the distance),
///         max_distance is negative or not finite, or the layer is unknown.
/// \since 0.2
/// \ingroup rmf_sheet
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_surface_to_flat(
    part: *const RmfSheetPart,
    points: *const RmfVec3,
    count: usize,
    layer: RmfSheetLayer,
    max_distance: f64,
    flat: *mut RmfVec2,
) -> RmfStatus {
    guard("rmf_sheet_part_surface_to_flat", || {
        let p = &sheet_part(part)?.part;
        surface_to_flat(p, points, count, layer, max_distance, flat)
    })
}

/// rmf_sheet_part_surface_to_flat on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, points, count, layer, max_distance, flat As for rmf_sheet_part_surface_to_flat.
/// \deprecated Use rmf_sheet_part_surface_to_flat.
/// \since 0.2
/// \ingroup rmf_sheet
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_surface_to_flat")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_surface_to_flat(
    part: *const RmfConeSpline,
    points: *const RmfVec3,
    count: usize,
    layer: RmfSheetLayer,
    max_distance: f64,
    flat: *mut RmfVec2,
) -> RmfStatus {
    guard("rmf_cone_spline_surface_to_flat", || {
        let p = &spline_part(part)?.part;
        surface_to_flat(p, points, count, layer, max_distance, flat)
    })
}

unsafe fn surface_to_flat(
    p: &SheetPart,
    points: *const RmfVec3,
    count: usize,
    layer: RmfSheetLayer,
    max_distance: f64,
    flat: *mut RmfVec2,
) -> FfiResult {
    let layer = layer_from(layer)?;
    if !(max_distance.is_finite() && max_distance >= 0.0) {
        return invalid_arg(format!(
            "max_distance = {max_distance} must be finite and ≥ 0"
        ));
    }
    let points = slice(points, count, "points")?;
    let flat = buffer(flat, count, "flat")?;
    let mapped = points
        .iter()
        .enumerate()
        .map(|(i, y)| p.surface_to_flat((*y).into(), layer, max_distance, &format!("points[{i}]")))
        .collect::<rmfsurf::Result<Vec<_>>>()?;
    for (i, q) in mapped.into_iter().enumerate() {
        flat[i] = q.into();
    }
    Ok(())
}

/// The text of a file of the part: the formed solid or the flat pattern as STEP, the flat
/// pattern as DXF or SVG, the formed solid in OpenCascade's B-rep text
/// (RMF_SHEET_FORMAT_*), exactly as the command-line tool writes it.
///
/// Size query: with capacity 0 (buffer may be NULL) only length is written. Otherwise the
/// text and a terminating NUL are written if capacity ≥ length + 1.
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[in] format RMF_SHEET_FORMAT_*.
/// @param[out] buffer capacity bytes for the text and its NUL.
/// @param[in] capacity Size of buffer in bytes; 0 for a size query.
/// @param[out] length Receives the length of the text (without the NUL).
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If part or length is NULL, or buffer is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity ≤ length; length is written.
/// @return RMF_ERROR_INVALID_INPUT For an unknown format.
/// \since 0.2
/// \ingroup rmf_export
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_export(
    part: *const RmfSheetPart,
    format: RmfSheetFormat,
    buffer: *mut c_char,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_sheet_part_export", || {
        export(sheet_part(part)?, format, buffer, capacity, length)
    })
}

/// rmf_sheet_part_export on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, format, buffer, capacity, length As for rmf_sheet_part_export.
/// \deprecated Use rmf_sheet_part_export.
/// \since 0.2
/// \ingroup rmf_export
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_export")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_part_export(
    part: *const RmfConeSpline,
    format: RmfSheetFormat,
    buffer: *mut c_char,
    capacity: usize,
    length: *mut usize,
) -> RmfStatus {
    guard("rmf_cone_spline_part_export", || {
        export(spline_part(part)?, format, buffer, capacity, length)
    })
}

unsafe fn export(
    handle: &PartHandle,
    format: RmfSheetFormat,
    text_buffer: *mut c_char,
    capacity: usize,
    length: *mut usize,
) -> FfiResult {
    let length = out_ptr(length, "length")?;
    let out = buffer(text_buffer.cast::<u8>(), capacity, "buffer")?;
    let Some(cell) = handle.texts.get(format as usize) else {
        return invalid_arg(format!(
            "format = {format} is not one of the RMF_SHEET_FORMAT_* values"
        ));
    };
    let p = &handle.part;
    let text = crate::boundary::made_once(cell, || {
        Ok(match format {
            RMF_SHEET_FORMAT_STEP_SOLID => p.to_step("rmfsurf part")?,
            RMF_SHEET_FORMAT_OCC_BREP => p.to_occ_brep()?,
            RMF_SHEET_FORMAT_STEP_FLAT => {
                step::flat_to_step(&p.flat_pattern()?, "rmfsurf flat pattern")?
            }
            RMF_SHEET_FORMAT_DXF => dxf::pattern_to_dxf(&p.flat_pattern()?),
            RMF_SHEET_FORMAT_SVG => svg::pattern_to_svg("rmfsurf flat pattern", &p.flat_pattern()?),
            other => {
                return invalid_arg(format!(
                    "format = {other} is not one of the RMF_SHEET_FORMAT_* values"
                ))
            }
        })
    })?;
    crate::boundary::hand_text(text, out, length)
}

/// The boundary representation of a sheet-metal part's formed solid (the solid of
/// RMF_SHEET_FORMAT_STEP_SOLID and RMF_SHEET_FORMAT_OCC_BREP).
///
/// @param[in] part A part (rmf_sheet_part_transition, _between_rails or _tangent).
/// @param[out] out Receives a new B-rep; free it with rmf_brep_free.
/// @return RMF_OK or RMF_ERROR_NULL_POINTER.
/// \since 0.2
/// \ingroup rmf_brep
#[no_mangle]
pub unsafe extern "C" fn rmf_sheet_part_brep(
    part: *const RmfSheetPart,
    out: *mut *mut crate::brep::RmfBrep,
) -> RmfStatus {
    guard("rmf_sheet_part_brep", || {
        write_brep(&sheet_part(part)?.part, out)
    })
}

/// rmf_sheet_part_brep on the part an RmfConeSpline holds (made by rmf_cone_spline_transition,
/// _part or _tangent_part); RMF_ERROR_INVALID_INPUT for a cone spline that is no part.
///
/// @param part, out As for rmf_sheet_part_brep.
/// \deprecated Use rmf_sheet_part_brep.
/// \since 0.2
/// \ingroup rmf_brep
#[deprecated(since = "0.2.0", note = "use rmf_sheet_part_brep")]
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_part_brep(
    part: *const RmfConeSpline,
    out: *mut *mut crate::brep::RmfBrep,
) -> RmfStatus {
    guard("rmf_cone_spline_part_brep", || {
        write_brep(&spline_part(part)?.part, out)
    })
}

unsafe fn write_brep(p: &SheetPart, out: *mut *mut crate::brep::RmfBrep) -> FfiResult {
    let out = out_ptr(out, "out")?;
    write(out, crate::brep::RmfBrep::new(p.brep()?).into_raw());
    Ok(())
}

pub(crate) fn flat_edge(edge: &PatternEdge, layer: u32) -> RmfFlatEdge {
    match *edge {
        PatternEdge::Line { from, to } => RmfFlatEdge {
            layer,
            kind: RMF_FLAT_EDGE_LINE,
            from: from.into(),
            to: to.into(),
            ..Default::default()
        },
        PatternEdge::Arc {
            center,
            radius,
            from,
            to,
            sweep,
        } => RmfFlatEdge {
            layer,
            kind: RMF_FLAT_EDGE_ARC,
            from: from.into(),
            to: to.into(),
            center: center.into(),
            radius,
            sweep,
        },
    }
}
