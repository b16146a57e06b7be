//! `RmfSurface`: a piecewise tensor-product rational Bézier surface (also a NURBS surface),
//! with its NURBS and per-patch views and a tessellator.

use super::boundary::{
    buffer, free_handle, guard, invalid_arg, optional_out, options, out_ptr, reference, to_usize,
    write, FfiError, FfiResult, OptionsStruct,
};
use super::curve::RmfCurve;
use super::frames::{framed_curve, RmfFrames};
use super::input::nurbs_surface;
use super::status::RmfStatus;
use super::types::{piece_views, PieceViews, RmfBezierPatch, RmfNurbsSurface, RmfVec3};
use rmfsurf::validate::check_in_domain;
use rmfsurf::{mesh_size, sweep, tessellate, NurbsSurface, PiecewiseSurface, Result};
use std::sync::{Arc, OnceLock};

/// A piecewise rational tensor-product surface s(u, v) (opaque). Freed with
/// rmf_surface_free. Immutable; may be read from several threads at once.
/// \ingroup rmf_surfaces
pub struct RmfSurface {
    pub(crate) surface: Arc<PiecewiseSurface>,
    /// The caller's NURBS data when created from it: the NURBS view shows it unchanged.
    source: Option<NurbsSurface>,
    /// The NURBS view, built on first request; it fails for discontinuous surfaces (e.g.
    /// a Frenet sweep along a G1 spline), which still have patch views.
    nurbs: OnceLock<Result<NurbsView>>,
    patches: OnceLock<PieceViews>,
}

/// C-layout copy of the NURBS data.
struct NurbsView {
    nurbs: NurbsSurface,
    poles: Vec<RmfVec3>,
}

impl RmfSurface {
    /// A handle for a computed object (`source = None`) or for caller NURBS data.
    pub(crate) fn new(surface: PiecewiseSurface, source: Option<NurbsSurface>) -> Self {
        Self {
            surface: Arc::new(surface),
            source,
            nurbs: OnceLock::new(),
            patches: OnceLock::new(),
        }
    }

    /// Moves the handle to the heap for C; the caller owns it.
    pub(crate) fn into_raw(self) -> *mut Self {
        Box::into_raw(Box::new(self))
    }

    fn nurbs_view(&self) -> FfiResult<&NurbsView> {
        let view = self.nurbs.get_or_init(|| {
            let nurbs = match &self.source {
                Some(n) => n.clone(),
                None => NurbsSurface::from_piecewise(&self.surface)?,
            };
            let poles = nurbs.poles().iter().map(|&p| p.into()).collect();
            Ok(NurbsView { nurbs, poles })
        });
        view.as_ref().map_err(|e| FfiError::Core(e.clone()))
    }

    fn patch_views(&self) -> &PieceViews {
        self.patches
            .get_or_init(|| piece_views(self.surface.patches().iter().map(|p| p.homogeneous())))
    }
}

/// Creates a surface from NURBS data.
///
/// \deprecated Use rmf_nurbs_surface_create_from (the data in one struct that can grow).
/// This function stays, with the same results, for at least one release.
///
/// @param[in] degree_u, degree_v Degrees, each in 1..=64.
/// @param[in] poles pole_count_u * pole_count_v Cartesian poles, index i * pole_count_v + j
///            with i along u.
/// @param[in] weights Weights in the same order (finite, > 0), or NULL for all 1.
/// @param[in] pole_count_u, pole_count_v Pole counts, each ≥ its degree + 1.
/// @param[in] knots_u, knot_count_u Clamped knot vector in u, knot_count_u = pole_count_u + degree_u + 1.
/// @param[in] knots_v, knot_count_v Clamped knot vector in v, likewise.
/// @param[out] out Receives the surface; free with rmf_surface_free. Untouched on failure.
///
/// Degrees and counts are checked against each other before any array is read.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If poles, knots_u, knots_v or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a count, degree, knot, weight or pole is invalid (the
///         message names it).
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
#[deprecated(since = "0.2.0", note = "use rmf_nurbs_surface_create_from")]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_nurbs_surface_create(
    degree_u: u32,
    degree_v: u32,
    poles: *const RmfVec3,
    weights: *const f64,
    pole_count_u: usize,
    pole_count_v: usize,
    knots_u: *const f64,
    knot_count_u: usize,
    knots_v: *const f64,
    knot_count_v: usize,
    out: *mut *mut RmfSurface,
) -> RmfStatus {
    guard("rmf_nurbs_surface_create", || {
        let out = out_ptr(out, "out")?;
        let surface = surface_from_nurbs(
            degree_u,
            degree_v,
            poles,
            weights,
            pole_count_u,
            pole_count_v,
            knots_u,
            knot_count_u,
            knots_v,
            knot_count_v,
        )?;
        write(out, surface.into_raw());
        Ok(())
    })
}

/// A surface handle from caller NURBS data, checked (both C constructors).
///
/// # Safety
/// The pointers are NULL or valid for the counts given.
#[allow(clippy::too_many_arguments)]
unsafe fn surface_from_nurbs(
    degree_u: u32,
    degree_v: u32,
    poles: *const RmfVec3,
    weights: *const f64,
    pole_count_u: usize,
    pole_count_v: usize,
    knots_u: *const f64,
    knot_count_u: usize,
    knots_v: *const f64,
    knot_count_v: usize,
) -> FfiResult<RmfSurface> {
    let nurbs = nurbs_surface(
        degree_u,
        degree_v,
        poles,
        weights,
        (pole_count_u, pole_count_v),
        (knots_u, knot_count_u),
        (knots_v, knot_count_v),
    )?;
    Ok(RmfSurface::new(nurbs.to_piecewise()?, Some(nurbs)))
}

/// NURBS data of a surface for rmf_nurbs_surface_create_from: the fields of
/// rmf_nurbs_surface_create in one struct. The caller sets struct_size =
/// sizeof(RmfNurbsSurfaceData); the struct only grows at the end.
/// \since 0.2
/// \ingroup rmf_surfaces
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfNurbsSurfaceData {
    /// sizeof(RmfNurbsSurfaceData), set by the caller.
    pub struct_size: usize,
    /// Degree along u, 1..=64.
    pub degree_u: u32,
    /// Degree along v, 1..=64.
    pub degree_v: u32,
    /// Number of poles along u, ≥ degree_u + 1.
    pub pole_count_u: usize,
    /// Number of poles along v, ≥ degree_v + 1.
    pub pole_count_v: usize,
    /// pole_count_u * pole_count_v Cartesian poles, index i * pole_count_v + j with i along u.
    pub poles: *const RmfVec3,
    /// Weights in the same order (finite, > 0), or NULL for all 1.
    pub weights: *const f64,
    /// Number of u knots, pole_count_u + degree_u + 1.
    pub knot_count_u: usize,
    /// Clamped knot vector in u.
    pub knots_u: *const f64,
    /// Number of v knots, pole_count_v + degree_v + 1.
    pub knot_count_v: usize,
    /// Clamped knot vector in v.
    pub knots_v: *const f64,
}

impl Default for RmfNurbsSurfaceData {
    fn default() -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            degree_u: 0,
            degree_v: 0,
            pole_count_u: 0,
            pole_count_v: 0,
            poles: std::ptr::null(),
            weights: std::ptr::null(),
            knot_count_u: 0,
            knots_u: std::ptr::null(),
            knot_count_v: 0,
            knots_v: std::ptr::null(),
        }
    }
}

// SAFETY: repr(C), usize first; numbers and raw pointers (any bit pattern is a value; the
// pointers are checked like arguments before use).
unsafe impl OptionsStruct for RmfNurbsSurfaceData {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
    const SIZE_HINT: &'static str = "set it to sizeof(RmfNurbsSurfaceData)";
}

/// Creates a surface from NURBS data given in one struct, as rmf_nurbs_surface_create does.
///
/// @param[in] data The NURBS data, struct_size set to sizeof(RmfNurbsSurfaceData). Degrees
///            and counts are checked against each other before any array is read.
/// @param[out] out Receives the surface; free with rmf_surface_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If data, data->poles, data->knots_u, data->knots_v or out
///         is NULL.
/// @return RMF_ERROR_INVALID_INPUT If data->struct_size is no size of the struct, or a count,
///         degree, knot, weight or pole is invalid (the message names it: "data: ...").
/// \since 0.2
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_nurbs_surface_create_from(
    data: *const RmfNurbsSurfaceData,
    out: *mut *mut RmfSurface,
) -> RmfStatus {
    guard("rmf_nurbs_surface_create_from", || {
        if data.is_null() {
            return Err(FfiError::Null("data"));
        }
        let d = options(data, "data")?;
        let out = out_ptr(out, "out")?;
        let surface = surface_from_nurbs(
            d.degree_u,
            d.degree_v,
            d.poles,
            d.weights,
            d.pole_count_u,
            d.pole_count_v,
            d.knots_u,
            d.knot_count_u,
            d.knots_v,
            d.knot_count_v,
        )
        .map_err(|e| match e {
            FfiError::Null("poles") => FfiError::Null("data->poles"),
            FfiError::Null("knots_u") => FfiError::Null("data->knots_u"),
            FfiError::Null("knots_v") => FfiError::Null("data->knots_v"),
            FfiError::Core(e) => FfiError::Core(e.context("data")),
            other => other,
        })?;
        write(out, surface.into_raw());
        Ok(())
    })
}

/// Frees a surface. NULL is a no-op.
///
/// @param[in] surface The surface to free, or NULL.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_surface_free(surface: *mut RmfSurface) {
    free_handle(surface)
}

/// The parameter domain [u_min, u_max] × [v_min, v_max] of a surface.
///
/// @param[in] surface The surface.
/// @param[out] u_min, u_max Receive the ends of the u domain.
/// @param[out] v_min, v_max Receive the ends of the v domain.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if any argument is NULL.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_surface_domain(
    surface: *const RmfSurface,
    u_min: *mut f64,
    u_max: *mut f64,
    v_min: *mut f64,
    v_max: *mut f64,
) -> RmfStatus {
    guard("rmf_surface_domain", || {
        let surface = reference(surface, "surface")?;
        let outs = [
            out_ptr(u_min, "u_min")?,
            out_ptr(u_max, "u_max")?,
            out_ptr(v_min, "v_min")?,
            out_ptr(v_max, "v_max")?,
        ];
        let ((a, b), (c, d)) = (surface.surface.domain_u(), surface.surface.domain_v());
        for (p, value) in outs.into_iter().zip([a, b, c, d]) {
            write(p, value);
        }
        Ok(())
    })
}

/// Evaluates a surface and its first partial derivatives.
///
/// @param[in] surface The surface.
/// @param[in] u, v Parameters inside the domain.
/// @param[out] point Receives s(u, v).
/// @param[out] du Receives ∂s/∂u; may be NULL.
/// @param[out] dv Receives ∂s/∂v; may be NULL.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If surface or point is NULL.
/// @return RMF_ERROR_INVALID_INPUT If u or v is not finite or outside the domain.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_surface_eval(
    surface: *const RmfSurface,
    u: f64,
    v: f64,
    point: *mut RmfVec3,
    du: *mut RmfVec3,
    dv: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_surface_eval", || {
        let surface = reference(surface, "surface")?;
        let point = out_ptr(point, "point")?;
        let (du, dv) = (optional_out(du, "du")?, optional_out(dv, "dv")?);
        let u = check_in_domain(u, surface.surface.domain_u(), "u")?;
        let v = check_in_domain(v, surface.surface.domain_v(), "v")?;
        let jet = surface.surface.eval_jet(u, v);
        write(point, jet.point.into());
        if let Some(p) = du {
            write(p, jet.du.into());
        }
        if let Some(p) = dv {
            write(p, jet.dv.into());
        }
        Ok(())
    })
}

/// Borrowed NURBS view of a surface: one clamped NURBS with full-multiplicity interior
/// knots at patch boundaries (for a surface made by rmf_nurbs_surface_create: the data given).
///
/// @param[in] surface The surface.
/// @param[out] view Receives pointers owned by the surface: do not free them; valid until
///             rmf_surface_free(surface).
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if the patches do not
///         join into one continuous NURBS (Frenet frame vectors and Frenet sweeps along a G1
///         spline jump at the joints); rmf_surface_patch still gives every piece.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_surface_nurbs(
    surface: *const RmfSurface,
    view: *mut RmfNurbsSurface,
) -> RmfStatus {
    guard("rmf_surface_nurbs", || {
        let surface = reference(surface, "surface")?;
        let view = out_ptr(view, "view")?;
        let v = surface.nurbs_view()?;
        write(view, RmfNurbsSurface::of(&v.nurbs, v.poles.as_ptr()));
        Ok(())
    })
}

/// Copies the NURBS data of a surface (as in rmf_surface_nurbs) into caller buffers.
///
/// \deprecated Use rmf_surface_nurbs_copy_into (the buffers in one struct that can grow,
/// the degrees and counts in an RmfNurbsSurface). This function stays, with the same
/// results, for at least one release.
///
/// Size query: with pole_capacity = knot_capacity_u = knot_capacity_v = 0 (buffers may then
/// be NULL) only the degrees and counts are written and RMF_OK is returned.
///
/// @param[in] surface The surface.
/// @param[out] degree_u, degree_v Receive the degrees.
/// @param[out] poles, weights Buffers for pole_capacity poles and weights (index i * pole_count_v + j).
/// @param[in] pole_capacity Capacity of poles and weights.
/// @param[out] knots_u, knots_v Buffers for knot_capacity_u and knot_capacity_v knots.
/// @param[in] knot_capacity_u Capacity of knots_u.
/// @param[in] knot_capacity_v Capacity of knots_v.
/// @param[out] pole_count_u, pole_count_v, knot_count_u, knot_count_v Receive the counts.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If surface, a degree or a count pointer is NULL, or a
///         buffer is NULL with a non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If a capacity is too small; then only the degrees and
///         counts are written.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
#[deprecated(since = "0.2.0", note = "use rmf_surface_nurbs_copy_into")]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_surface_nurbs_copy(
    surface: *const RmfSurface,
    degree_u: *mut u32,
    degree_v: *mut u32,
    poles: *mut RmfVec3,
    weights: *mut f64,
    pole_capacity: usize,
    knots_u: *mut f64,
    knot_capacity_u: usize,
    knots_v: *mut f64,
    knot_capacity_v: usize,
    pole_count_u: *mut usize,
    pole_count_v: *mut usize,
    knot_count_u: *mut usize,
    knot_count_v: *mut usize,
) -> RmfStatus {
    guard("rmf_surface_nurbs_copy", || {
        let surface = reference(surface, "surface")?;
        let (degree_u, degree_v) = (
            out_ptr(degree_u, "degree_u")?,
            out_ptr(degree_v, "degree_v")?,
        );
        let counts = [
            out_ptr(pole_count_u, "pole_count_u")?,
            out_ptr(pole_count_v, "pole_count_v")?,
            out_ptr(knot_count_u, "knot_count_u")?,
            out_ptr(knot_count_v, "knot_count_v")?,
        ];
        let poles = buffer(poles, pole_capacity, "poles")?;
        let weights = buffer(weights, pole_capacity, "weights")?;
        let knots_u = buffer(knots_u, knot_capacity_u, "knots_u")?;
        let knots_v = buffer(knots_v, knot_capacity_v, "knots_v")?;
        let v = surface.nurbs_view()?;
        let n = &v.nurbs;
        write(degree_u, n.degree_u() as u32);
        write(degree_v, n.degree_v() as u32);
        for (p, value) in counts.into_iter().zip([
            n.pole_count_u(),
            n.pole_count_v(),
            n.knots_u().len(),
            n.knots_v().len(),
        ]) {
            write(p, value);
        }
        if pole_capacity == 0 && knot_capacity_u == 0 && knot_capacity_v == 0 {
            return Ok(());
        }
        copy_nurbs(v, poles, weights, knots_u, knots_v)
    })
}

/// Copies a NURBS view into caller buffers, or says how large they must be.
fn copy_nurbs(
    v: &NurbsView,
    poles: &mut [RmfVec3],
    weights: &mut [f64],
    knots_u: &mut [f64],
    knots_v: &mut [f64],
) -> FfiResult {
    let n = &v.nurbs;
    if poles.len() < v.poles.len()
        || weights.len() < v.poles.len()
        || knots_u.len() < n.knots_u().len()
        || knots_v.len() < n.knots_v().len()
    {
        return Err(FfiError::BufferTooSmall(format!(
            "need {} poles, {} u knots and {} v knots",
            v.poles.len(),
            n.knots_u().len(),
            n.knots_v().len()
        )));
    }
    poles[..v.poles.len()].copy_from_slice(&v.poles);
    weights[..v.poles.len()].copy_from_slice(n.weights());
    knots_u[..n.knots_u().len()].copy_from_slice(n.knots_u());
    knots_v[..n.knots_v().len()].copy_from_slice(n.knots_v());
    Ok(())
}

/// Caller buffers for rmf_surface_nurbs_copy_into. The caller sets struct_size =
/// sizeof(RmfNurbsSurfaceBuffers); the struct only grows at the end. A buffer may be NULL
/// when its capacity is 0.
/// \since 0.2
/// \ingroup rmf_surfaces
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfNurbsSurfaceBuffers {
    /// sizeof(RmfNurbsSurfaceBuffers), set by the caller.
    pub struct_size: usize,
    /// Buffer for pole_capacity poles, index i * pole_count_v + j with i along u.
    pub poles: *mut RmfVec3,
    /// Buffer for pole_capacity weights, in the order of the poles.
    pub weights: *mut f64,
    /// Capacity of poles and of weights.
    pub pole_capacity: usize,
    /// Buffer for knot_capacity_u knots along u.
    pub knots_u: *mut f64,
    /// Capacity of knots_u.
    pub knot_capacity_u: usize,
    /// Buffer for knot_capacity_v knots along v.
    pub knots_v: *mut f64,
    /// Capacity of knots_v.
    pub knot_capacity_v: usize,
}

impl Default for RmfNurbsSurfaceBuffers {
    fn default() -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            poles: std::ptr::null_mut(),
            weights: std::ptr::null_mut(),
            pole_capacity: 0,
            knots_u: std::ptr::null_mut(),
            knot_capacity_u: 0,
            knots_v: std::ptr::null_mut(),
            knot_capacity_v: 0,
        }
    }
}

// SAFETY: repr(C), usize first; numbers and raw pointers (any bit pattern is a value; the
// pointers are checked like arguments before use).
unsafe impl OptionsStruct for RmfNurbsSurfaceBuffers {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
    const SIZE_HINT: &'static str = "set it to sizeof(RmfNurbsSurfaceBuffers)";
}

/// Copies the NURBS data of a surface (as in rmf_surface_nurbs) into the caller's buffers,
/// as rmf_surface_nurbs_copy does, and describes the copy.
///
/// Size query: with all capacities 0 (the buffers may then be NULL) only the degrees and
/// counts are written to `copy` (its pointers NULL) and RMF_OK is returned.
///
/// @param[in] surface The surface.
/// @param[in] buffers The caller's buffers and their capacities, struct_size set.
/// @param[out] copy Receives the degrees and counts, and pointers to the caller's buffers
///             now holding the poles, weights and knots (NULL after a size query).
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If surface, buffers or copy is NULL, or a buffer is NULL
///         with a non-zero capacity (the message names it: buffers->poles, ...).
/// @return RMF_ERROR_INVALID_INPUT If buffers->struct_size is no size of the struct, or the
///         patches do not join into one continuous NURBS (as for rmf_surface_nurbs).
/// @return RMF_ERROR_BUFFER_TOO_SMALL If a capacity is non-zero but too small; then the
///         degrees and counts are written to `copy`, with NULL pointers.
/// \since 0.2
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_surface_nurbs_copy_into(
    surface: *const RmfSurface,
    buffers: *const RmfNurbsSurfaceBuffers,
    copy: *mut RmfNurbsSurface,
) -> RmfStatus {
    guard("rmf_surface_nurbs_copy_into", || {
        let surface = reference(surface, "surface")?;
        if buffers.is_null() {
            return Err(FfiError::Null("buffers"));
        }
        let b = options(buffers, "buffers")?;
        let copy = out_ptr(copy, "copy")?;
        let poles = buffer(b.poles, b.pole_capacity, "buffers->poles")?;
        let weights = buffer(b.weights, b.pole_capacity, "buffers->weights")?;
        let knots_u = buffer(b.knots_u, b.knot_capacity_u, "buffers->knots_u")?;
        let knots_v = buffer(b.knots_v, b.knot_capacity_v, "buffers->knots_v")?;
        let v = surface.nurbs_view()?;
        let n = &v.nurbs;
        let mut described = RmfNurbsSurface {
            degree_u: n.degree_u() as u32,
            degree_v: n.degree_v() as u32,
            pole_count_u: n.pole_count_u(),
            pole_count_v: n.pole_count_v(),
            poles: std::ptr::null(),
            weights: std::ptr::null(),
            knot_count_u: n.knots_u().len(),
            knots_u: std::ptr::null(),
            knot_count_v: n.knots_v().len(),
            knots_v: std::ptr::null(),
        };
        if b.pole_capacity == 0 && b.knot_capacity_u == 0 && b.knot_capacity_v == 0 {
            write(copy, described);
            return Ok(());
        }
        if let Err(e) = copy_nurbs(v, poles, weights, knots_u, knots_v) {
            // As for rmf_surface_nurbs_copy: the counts say how large the buffers must be.
            write(copy, described);
            return Err(e);
        }
        described.poles = b.poles;
        described.weights = b.weights;
        described.knots_u = b.knots_u;
        described.knots_v = b.knots_v;
        write(copy, described);
        Ok(())
    })
}

/// Numbers of Bézier patches of a surface along u and along v.
///
/// @param[in] surface The surface.
/// @param[out] count_u, count_v Receive the numbers of patches along u and v.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if any argument is NULL.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_surface_patch_count(
    surface: *const RmfSurface,
    count_u: *mut usize,
    count_v: *mut usize,
) -> RmfStatus {
    guard("rmf_surface_patch_count", || {
        let surface = reference(surface, "surface")?;
        let (count_u, count_v) = (out_ptr(count_u, "count_u")?, out_ptr(count_v, "count_v")?);
        write(count_u, surface.surface.u_breaks().len() - 1);
        write(count_v, surface.surface.v_breaks().len() - 1);
        Ok(())
    })
}

/// Borrowed view of patch (index_u, index_v) of a surface as a rational Bézier patch.
///
/// @param[in] surface The surface.
/// @param[in] index_u 0 ≤ index_u < patch count along u.
/// @param[in] index_v 0 ≤ index_v < patch count along v.
/// @param[out] view Receives pointers owned by the surface (valid until it is freed).
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if an index is out of range.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
pub unsafe extern "C" fn rmf_surface_patch(
    surface: *const RmfSurface,
    index_u: usize,
    index_v: usize,
    view: *mut RmfBezierPatch,
) -> RmfStatus {
    guard("rmf_surface_patch", || {
        let surface = reference(surface, "surface")?;
        let view = out_ptr(view, "view")?;
        let s = &surface.surface;
        let (ku, kv) = (s.u_breaks().len() - 1, s.v_breaks().len() - 1);
        if index_u >= ku || index_v >= kv {
            return invalid_arg(format!(
                "patch ({index_u}, {index_v}) is outside the {ku} × {kv} grid"
            ));
        }
        let (poles, weights) = &surface.patch_views()[index_u * kv + index_v];
        let patch = s.patch(index_u, index_v);
        write(
            view,
            RmfBezierPatch {
                degree_u: patch.degree_u() as u32,
                degree_v: patch.degree_v() as u32,
                poles: poles.as_ptr(),
                weights: weights.as_ptr(),
                u_start: s.u_breaks()[index_u],
                u_end: s.u_breaks()[index_u + 1],
                v_start: s.v_breaks()[index_v],
                v_end: s.v_breaks()[index_v + 1],
            },
        );
        Ok(())
    })
}

/// Tessellates a surface: every Bézier patch is sampled on a (u_steps + 1) × (v_steps + 1)
/// grid of its own parameters (so patch boundaries are mesh lines and shared vertices are
/// shared), two triangles per grid cell, counter-clockwise seen from the side ∂s/∂u × ∂s/∂v
/// points to. Point (i, j) of the global grid is at index i * columns + j, i along u.
///
/// Size query: with point_capacity = triangle_capacity = 0 (points and triangles may then be
/// NULL) only point_count and triangle_count are written and RMF_OK is returned.
///
/// @param[in] surface The surface.
/// @param[in] u_steps, v_steps Subdivisions per patch, each ≥ 1.
/// @param[out] points Buffer for point_capacity points.
/// @param[in] point_capacity Capacity of points (in points).
/// @param[out] triangles Buffer for triangle_capacity triangles of 3 vertex indices each
///             (3 * triangle_capacity uint32_t).
/// @param[in] triangle_capacity Capacity of triangles (in triangles).
/// @param[out] point_count Receives the number of points.
/// @param[out] triangle_count Receives the number of triangles.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If surface or a count pointer is NULL, or a buffer is NULL
///         with a non-zero capacity.
/// @return RMF_ERROR_INVALID_INPUT If u_steps or v_steps is 0 or the mesh would exceed
///         50,000,000 points.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If a capacity is too small; then only the counts are
///         written.
/// \since 0.1
/// \ingroup rmf_surfaces
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_surface_tessellate(
    surface: *const RmfSurface,
    u_steps: u32,
    v_steps: u32,
    points: *mut RmfVec3,
    point_capacity: usize,
    triangles: *mut u32,
    triangle_capacity: usize,
    point_count: *mut usize,
    triangle_count: *mut usize,
) -> RmfStatus {
    guard("rmf_surface_tessellate", || {
        let surface = reference(surface, "surface")?;
        let (point_count, triangle_count) = (
            out_ptr(point_count, "point_count")?,
            out_ptr(triangle_count, "triangle_count")?,
        );
        let points = buffer(points, point_capacity, "points")?;
        let Some(index_capacity) = triangle_capacity.checked_mul(3) else {
            return invalid_arg(format!(
                "triangle_capacity = {triangle_capacity} is too large"
            ));
        };
        let triangles = buffer(triangles, index_capacity, "triangles")?;
        let (u_steps, v_steps) = (to_usize(u_steps), to_usize(v_steps));
        let (n_points, n_triangles) = mesh_size(&surface.surface, u_steps, v_steps)?;
        write(point_count, n_points);
        write(triangle_count, n_triangles);
        if point_capacity == 0 && triangle_capacity == 0 {
            return Ok(());
        }
        if point_capacity < n_points || triangle_capacity < n_triangles {
            return Err(FfiError::BufferTooSmall(format!(
                "need {n_points} points and {n_triangles} triangles"
            )));
        }
        let mesh = tessellate(&surface.surface, u_steps, v_steps)?;
        for (dst, &p) in points.iter_mut().zip(&mesh.points) {
            *dst = p.into();
        }
        for (dst, &index) in triangles.iter_mut().zip(mesh.triangles.iter().flatten()) {
            *dst = index;
        }
        Ok(())
    })
}

/// The sweep surface s(u, v) = x(v) + c2(u) f2(v) + c3(u) f3(v) of a profile along a spine
/// with exact rational frames (Mäurer & Jüttler, eqs. (1) and (42)): a rational
/// tensor-product surface, u along the profile (the profile's parameter), v along the spine
/// (the spine's parameter). Patch (a, b) is profile segment a × spine segment b, of degree
/// (profile degree, spine degree + frame degree). With a rotation-minimizing frame this is a
/// profile surface: parameter lines are lines of curvature, and a straight profile gives a
/// developable surface.
///
/// @param[in] spine The spine curve; must be the curve of `frames` (same segments).
/// @param[in] frames Exact rational frames along the spine (RMF_FRAMES_RATIONAL).
/// @param[in] profile The profile in the normal plane: its x maps to f2, its y to f3, z is
///            ignored (e.g. from rmf_nurbs_curve_create).
/// @param[out] out Receives the surface; free with rmf_surface_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If an argument is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the frames are not rational or do not belong to the
///         spine, or the surface would have more than 2^22 (4,194,304) control points.
/// \since 0.1
/// \ingroup rmf_sweeps
#[no_mangle]
pub unsafe extern "C" fn rmf_sweep_surface(
    spine: *const RmfCurve,
    frames: *const RmfFrames,
    profile: *const RmfCurve,
    out: *mut *mut RmfSurface,
) -> RmfStatus {
    guard("rmf_sweep_surface", || {
        let spine = reference(spine, "spine")?;
        let frames = reference(frames, "frames")?;
        let profile = reference(profile, "profile")?;
        let out = out_ptr(out, "out")?;
        let surface = sweep(&framed_curve(spine, frames)?, profile.rational("profile")?)?;
        write(out, RmfSurface::new(surface, None).into_raw());
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rmfsurf::glam::DVec4;
    use rmfsurf::RationalBezierPatch;

    /// Two bilinear patches that do not meet: no single NURBS, but each patch has a view.
    fn torn() -> RmfSurface {
        let square = |x0: f64, lift: f64| {
            let corners = [(x0, 0.0), (x0, 1.0), (x0 + 1.0, 0.0), (x0 + 1.0, 1.0)];
            let points = corners
                .iter()
                .map(|&(x, y)| DVec4::new(x, y, lift, 1.0))
                .collect();
            RationalBezierPatch::from_homogeneous(1, 1, points).unwrap()
        };
        let surface = PiecewiseSurface::new(
            vec![square(0.0, 0.0), square(1.0, 0.5)],
            vec![0.0, 1.0, 2.0],
            vec![0.0, 1.0],
        )
        .unwrap();
        RmfSurface::new(surface, None)
    }

    #[test]
    fn a_discontinuous_surface_has_patch_views_but_no_nurbs_view() {
        let surface = torn();
        let mut patch = std::mem::MaybeUninit::<RmfBezierPatch>::uninit();
        let status = unsafe { rmf_surface_patch(&surface, 1, 0, patch.as_mut_ptr()) };
        assert_eq!(status, RmfStatus::RmfOk);
        let patch = unsafe { patch.assume_init() };
        assert_eq!(unsafe { (*patch.poles).z }, 0.5);
        let mut view = std::mem::MaybeUninit::<RmfNurbsSurface>::uninit();
        let status = unsafe { rmf_surface_nurbs(&surface, view.as_mut_ptr()) };
        assert_eq!(status, RmfStatus::RmfErrorInvalidInput);
    }
}
