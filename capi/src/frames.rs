//! `RmfFrames`: an adapted frame (t, f₂, f₃) along a curve, sharing its parameter.

use super::boundary::{
    free_handle, guard, invalid_arg, optional_out, out_ptr, reference, write, FfiResult,
};
use super::curve::RmfCurve;
use super::status::RmfStatus;
use super::types::RmfVec3;
use rmfsurf::validate::{check_in_domain, check_sample_count};
use rmfsurf::{
    framed_spine, uniform_parameters, DoubleReflectionRmf, FrameField, FrameKind, FrameVector,
    FramedCurve, PiecewiseCurve, RationalFrames, Result, ResultExt, SpineMethod,
};

/// Frames along a curve (opaque): exact rational frames, double-reflection samples, or
/// pointwise Frenet frames. Freed with rmf_frames_free. Immutable; may be read from
/// several threads at once. Keeps its own reference to the curve, so the curve handle may
/// be freed first.
/// \ingroup rmf_frames
pub struct RmfFrames {
    pub(crate) field: FrameField,
}

impl RmfFrames {
    /// A heap handle for C; the caller owns it.
    pub(crate) fn into_raw(field: FrameField) -> *mut RmfFrames {
        Box::into_raw(Box::new(Self { field }))
    }
}

/// Frees frames. NULL is a no-op.
///
/// @param[in] frames The frames to free, or NULL.
/// \since 0.1
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_frames_free(frames: *mut RmfFrames) {
    free_handle(frames)
}

/// The parameter domain of the frames (that of their curve).
///
/// @param[in] frames The frames.
/// @param[out] t_min, t_max Receive the domain ends.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if any argument is NULL.
/// \since 0.1
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_frames_domain(
    frames: *const RmfFrames,
    t_min: *mut f64,
    t_max: *mut f64,
) -> RmfStatus {
    guard("rmf_frames_domain", || {
        let frames = reference(frames, "frames")?;
        let (t_min, t_max) = (out_ptr(t_min, "t_min")?, out_ptr(t_max, "t_max")?);
        let (lo, hi) = frames.field.domain();
        write(t_min, lo);
        write(t_max, hi);
        Ok(())
    })
}

/// Evaluates the frame at a curve parameter.
///
/// @param[in] frames The frames.
/// @param[in] t Parameter in the domain of the frames' curve.
/// @param[out] tangent Receives the unit tangent t.
/// @param[out] f2 Receives the first normal-plane vector.
/// @param[out] f3 Receives t × f2.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If any argument is NULL.
/// @return RMF_ERROR_INVALID_INPUT If t is not finite or outside the domain, or the frame is
///         undefined there (Frenet frames where the curvature vanishes; a singular curve).
/// \since 0.1
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_frames_eval(
    frames: *const RmfFrames,
    t: f64,
    tangent: *mut RmfVec3,
    f2: *mut RmfVec3,
    f3: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_frames_eval", || {
        let frames = reference(frames, "frames")?;
        let (tangent, f2, f3) = (
            out_ptr(tangent, "tangent")?,
            out_ptr(f2, "f2")?,
            out_ptr(f3, "f3")?,
        );
        let t = check_in_domain(t, frames.field.domain(), "t")?;
        let frame = frames.field.frame(t)?;
        write(tangent, frame.tangent.into());
        write(f2, frame.f2.into());
        write(f3, frame.f3.into());
        Ok(())
    })
}

/// The double-reflection rotation-minimizing frame (Wang, Jüttler, Zheng & Liu 2008) of any
/// curve: sample_count samples at uniform parameters over the domain; between samples,
/// rmf_frames_eval applies one reflection step from the sample below to the exact point and
/// tangent. This is the reference RMF and benchmark baseline of the library.
///
/// @param[in] curve The curve (regular: non-zero derivative at the samples).
/// @param[in] initial_normal Projected onto the normal plane at the start and normalized to
///            give f2 there; f3 = t × f2.
/// @param[in] sample_count Number of samples, ≥ 2.
/// @param[out] out Receives the frames; free with rmf_frames_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If curve or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If sample_count < 2 or > 2^24, initial_normal is not finite, zero or
///         tangent to the curve, or the curve is singular at a sample.
/// \since 0.1
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_double_reflection_frames(
    curve: *const RmfCurve,
    initial_normal: RmfVec3,
    sample_count: usize,
    out: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_double_reflection_frames", || {
        let curve = reference(curve, "curve")?;
        let out = out_ptr(out, "out")?;
        check_sample_count(sample_count, 2, "sample_count")?;
        let curve = curve.rational("curve")?;
        let params = uniform_parameters(curve.domain(), sample_count);
        let rmf = DoubleReflectionRmf::along(curve.as_ref(), params, initial_normal.into())?;
        let field = FrameField::new(curve.clone(), FrameKind::DoubleReflection(rmf))?;
        write(out, RmfFrames::into_raw(field));
        Ok(())
    })
}

/// The Frenet frame (t, n, b) of any curve, as f2 = n and f3 = b, evaluated pointwise from
/// the curve's derivatives. Undefined (rmf_frames_eval fails) where the curvature vanishes.
/// For PH cubic splines, rmf_ph_frenet_frames gives the same frame as exact rational
/// functions.
///
/// @param[in] curve The curve.
/// @param[out] out Receives the frames; free with rmf_frames_free.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if curve or out is NULL.
/// \since 0.1
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_frenet_frames(
    curve: *const RmfCurve,
    out: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_frenet_frames", || {
        let curve = reference(curve, "curve")?;
        let out = out_ptr(out, "out")?;
        let field = FrameField::new(curve.rational("curve")?.clone(), FrameKind::Frenet)?;
        write(out, RmfFrames::into_raw(field));
        Ok(())
    })
}

/// rmf_framed_spine: a PH cubic spline within the tolerance with a rational approximation of
/// its RMF (Mäurer & Jüttler).
/// \ingroup rmf_frames
pub const RMF_SPINE_PH_RMF: u32 = 0;
/// rmf_framed_spine: the same PH cubic spline with its exact rational Frenet frame (not an
/// RMF).
/// \ingroup rmf_frames
pub const RMF_SPINE_FRENET: u32 = 1;
/// rmf_framed_spine: Möbius images of planar PH cubics through samples of the curve, exact
/// rational RMFs (Bartoň, Jüttler & Wang).
/// \ingroup rmf_frames
pub const RMF_SPINE_MOBIUS: u32 = 2;
/// rmf_framed_spine: RRMF quintics through samples of the curve, exact rational RMFs
/// (Farouki, Giannelli & Sestini).
/// \ingroup rmf_frames
pub const RMF_SPINE_RRMF: u32 = 3;

/// A spine within `tolerance` of a G1 curve with rational frames by `method` — the one call
/// behind every "sweep along this curve by this method": RMF_SPINE_PH_RMF (default of the
/// tools), RMF_SPINE_FRENET, RMF_SPINE_MOBIUS or RMF_SPINE_RRMF. The two sampled methods
/// interpolate the curve at equally spaced parameters, doubling their number (up to 4096
/// segments) until the sampled distance is within the tolerance.
///
/// @param[in] curve A rational curve (e.g. from rmf_nurbs_curve_create), G1.
/// @param[in] method One of the RMF_SPINE_* values.
/// @param[in] tolerance Largest distance of the spine from the curve (the curve's units).
/// @param[in] initial_normal f2 at the start, projected onto the normal plane (ignored by
///            RMF_SPINE_FRENET).
/// @param[out] spine_out Receives the spine; free with rmf_curve_free.
/// @param[out] frames_out Receives its frames (RMF_FRAMES_RATIONAL); free with
///             rmf_frames_free.
/// @param[out] distance Receives the largest distance measured between spine and curve;
///             may be NULL.
/// @return RMF_OK on success; nothing is written on failure.
/// @return RMF_ERROR_NULL_POINTER If curve, spine_out or frames_out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If method is unknown, tolerance is not finite and
///         positive or below the rounding of the curve's coordinates, the curve has a corner,
///         or initial_normal is zero, not finite or along the start tangent.
/// @return RMF_ERROR_NO_SOLUTION If the tolerance is not reached (4096 segments).
/// \since 0.2
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_framed_spine(
    curve: *const RmfCurve,
    method: u32,
    tolerance: f64,
    initial_normal: RmfVec3,
    spine_out: *mut *mut RmfCurve,
    frames_out: *mut *mut RmfFrames,
    distance: *mut f64,
) -> RmfStatus {
    guard("rmf_framed_spine", || {
        let curve = reference(curve, "curve")?;
        let (spine_out, frames_out) = (
            out_ptr(spine_out, "spine_out")?,
            out_ptr(frames_out, "frames_out")?,
        );
        let distance = optional_out(distance, "distance")?;
        let Some(&method) = SpineMethod::ALL.get(method as usize) else {
            return invalid_arg(format!(
                "method = {method} is not one of the RMF_SPINE_* values (0 to 3)"
            ));
        };
        let spine = framed_spine(
            curve.rational("curve")?,
            method,
            tolerance,
            initial_normal.into(),
        )?;
        if let Some(d) = distance {
            write(d, spine.distance);
        }
        write_framed(spine.framed, spine_out, frames_out)
    })
}

/// rmf_frames_kind: exact piecewise rational frames (usable by rmf_sweep_surface).
/// \ingroup rmf_frames
pub const RMF_FRAMES_RATIONAL: u32 = 0;
/// rmf_frames_kind: double-reflection samples.
/// \ingroup rmf_frames
pub const RMF_FRAMES_DOUBLE_REFLECTION: u32 = 1;
/// rmf_frames_kind: Frenet frames evaluated pointwise.
/// \ingroup rmf_frames
pub const RMF_FRAMES_FRENET: u32 = 2;

/// rmf_frames_vector_curve: the unit tangent t.
/// \ingroup rmf_frames
pub const RMF_FRAME_TANGENT: u32 = 0;
/// rmf_frames_vector_curve: the first normal-plane vector f2.
/// \ingroup rmf_frames
pub const RMF_FRAME_F2: u32 = 1;
/// rmf_frames_vector_curve: f3 = t × f2.
/// \ingroup rmf_frames
pub const RMF_FRAME_F3: u32 = 2;

/// How frames are represented.
///
/// @param[in] frames The frames.
/// @param[out] kind Receives RMF_FRAMES_RATIONAL, RMF_FRAMES_DOUBLE_REFLECTION or
///             RMF_FRAMES_FRENET.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if frames or kind is NULL.
/// \since 0.1
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_frames_kind(frames: *const RmfFrames, kind: *mut u32) -> RmfStatus {
    guard("rmf_frames_kind", || {
        let frames = reference(frames, "frames")?;
        let kind = out_ptr(kind, "kind")?;
        let value = match frames.field.kind() {
            FrameKind::Rational(_) => RMF_FRAMES_RATIONAL,
            FrameKind::DoubleReflection(_) => RMF_FRAMES_DOUBLE_REFLECTION,
            FrameKind::Frenet => RMF_FRAMES_FRENET,
        };
        write(kind, value);
        Ok(())
    })
}

/// One vector of exact rational frames as a rational curve of vectors: its "points" are the
/// tips of the unit vectors, on the unit sphere, with the frames' parameter (the segments of
/// the frames' curve). f2 and f3 have the degree of the frames; the tangent f2 × f3 twice it.
///
/// @param[in] frames Rational frames (rmf_frames_kind gives RMF_FRAMES_RATIONAL).
/// @param[in] which RMF_FRAME_TANGENT, RMF_FRAME_F2 or RMF_FRAME_F3.
/// @param[out] out Receives the curve; free with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If frames or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If which is not one of the three values or the frames are
///         not rational (double-reflection and pointwise Frenet frames are sampled).
/// \since 0.1
/// \ingroup rmf_frames
#[no_mangle]
pub unsafe extern "C" fn rmf_frames_vector_curve(
    frames: *const RmfFrames,
    which: u32,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_frames_vector_curve", || {
        let frames = reference(frames, "frames")?;
        let out = out_ptr(out, "out")?;
        let which = match which {
            RMF_FRAME_TANGENT => FrameVector::Tangent,
            RMF_FRAME_F2 => FrameVector::F2,
            RMF_FRAME_F3 => FrameVector::F3,
            other => {
                return invalid_arg(format!(
                    "which = {other} is not RMF_FRAME_TANGENT, RMF_FRAME_F2 or RMF_FRAME_F3"
                ))
            }
        };
        let rational = rational_frames(frames)?;
        let segments = rational
            .segments()
            .iter()
            .map(|s| s.vector_curve(which))
            .collect::<Result<Vec<_>>>()?;
        let curve = PiecewiseCurve::new(segments, rational.breaks().to_vec())?;
        write(out, RmfCurve::new(curve, None).into_raw());
        Ok(())
    })
}

/// The exact rational frames behind a handle, or an error naming why there are none.
/// Writes a curve and its frames to two out-pointers (both checked already): two handles
/// sharing the curve.
///
/// # Safety
/// Both out-pointers must be valid for writes.
pub(crate) unsafe fn write_framed(
    framed: FramedCurve,
    curve_out: *mut *mut RmfCurve,
    frames_out: *mut *mut RmfFrames,
) -> FfiResult {
    let (curve, frames) = framed.into_parts();
    let curve = std::sync::Arc::new(curve);
    let field = FrameField::new(curve.clone(), FrameKind::Rational(frames))?;
    write(curve_out, RmfCurve::new(curve, None).into_raw());
    write(frames_out, RmfFrames::into_raw(field));
    Ok(())
}

/// The curve and rational frames of a frames handle.
pub(crate) fn framed_of(frames: &RmfFrames) -> FfiResult<FramedCurve> {
    let curve = (**frames.field.curve()).clone();
    Ok(FramedCurve::new(curve, rational_frames(frames)?.clone())?)
}

/// The spine with its rational frames, checked to belong together (copies of both: the
/// handles stay the caller's).
pub(crate) fn framed_curve(spine: &RmfCurve, frames: &RmfFrames) -> FfiResult<FramedCurve> {
    let curve = (**spine.rational("spine")?).clone();
    Ok(FramedCurve::new(curve, rational_frames(frames)?.clone()).context("spine")?)
}

pub(crate) fn rational_frames(frames: &RmfFrames) -> FfiResult<&RationalFrames> {
    match frames.field.kind() {
        FrameKind::Rational(r) => Ok(r),
        _ => invalid_arg(
            "frames must be exact rational frames; double-reflection and pointwise Frenet frames are sampled".to_string(),
        ),
    }
}
