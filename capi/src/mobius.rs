//! C entry points for Möbius transformations and the rational-RMF curves built with them
//! (Bartoň, Jüttler & Wang).

use super::boundary::{guard, invalid_arg, out_ptr, reference, slice, write, FfiError, FfiResult};
use super::curve::RmfCurve;
use super::frames::{framed_of, write_framed, RmfFrames};
use super::input::{curve_or_callback, hermite_arrays, RmfCurveCallback};
use super::status::RmfStatus;
use super::types::RmfVec3;
use libc::c_void;
use rmfsurf::glam::DVec3;
use rmfsurf::{
    mobius::approximate as mobius_approximate, mobius::hermite as mobius_hermite,
    mobius::map_curve, mobius::map_framed_curve, mobius::Inversion, mobius::MobiusMap,
};

/// RmfInversion.kind: inversion in the sphere (center, radius).
/// \ingroup rmf_mobius
pub const RMF_INVERSION_SPHERE: u32 = 0;
/// RmfInversion.kind: reflection in the plane through `center` with normal `normal`.
/// \ingroup rmf_mobius
pub const RMF_INVERSION_PLANE: u32 = 1;

/// One inversion of a Möbius transformation. A Möbius transformation is given as an array
/// of inversions applied first to last (translations and rotations are two reflections).
/// \ingroup rmf_mobius
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfInversion {
    /// RMF_INVERSION_SPHERE or RMF_INVERSION_PLANE.
    pub kind: u32,
    /// Sphere centre, or a point on the plane.
    pub center: RmfVec3,
    /// Sphere radius (> 0); ignored for planes.
    pub radius: f64,
    /// Plane normal (any non-zero length); ignored for spheres.
    pub normal: RmfVec3,
}

/// The core map from a C array of inversions (at least one).
unsafe fn mobius_map(maps: *const RmfInversion, count: usize) -> FfiResult<MobiusMap> {
    if maps.is_null() {
        return Err(FfiError::Null("maps"));
    }
    let maps = slice(maps, count, "maps")?;
    if maps.is_empty() {
        return invalid_arg(
            "count = 0: a Möbius transformation needs at least one inversion".into(),
        );
    }
    let inversions = maps
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let inversion = match m.kind {
                RMF_INVERSION_SPHERE => Inversion::sphere(m.center.into(), m.radius),
                RMF_INVERSION_PLANE => Inversion::plane(m.center.into(), m.normal.into()),
                other => {
                    return invalid_arg(format!(
                        "maps[{i}].kind = {other} is not a known inversion kind"
                    ))
                }
            };
            inversion.map_err(|e| {
                FfiError::Core(rmfsurf::Error::invalid_input(format!(
                    "maps[{i}].{}",
                    e.message()
                )))
            })
        })
        .collect::<FfiResult<Vec<_>>>()?;
    Ok(MobiusMap::new(inversions))
}

fn finite(v: RmfVec3, name: &str) -> FfiResult<DVec3> {
    Ok(rmfsurf::validate::check_finite(v.into(), name)?)
}

/// The image μ(point) of a point under a Möbius transformation. Computed without squares
/// of distances: (1e200, 0, 0) in the unit sphere goes to (1e-200, 0, 0), and images beyond
/// the range of double are refused, never infinite.
///
/// @param[in] maps count inversions, applied first to last.
/// @param[in] count Number of inversions, ≥ 1.
/// @param[in] point A finite point.
/// @param[out] image Receives μ(point). Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If maps or image is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count = 0, an inversion is invalid (radius ≤ 0, zero
///         normal, non-finite), or the image is not finite: the point is sent to infinity (a
///         sphere centre) or beyond ±1.8e308 (e.g. a radius of 1e300 and a point at
///         distance 1 from the centre).
/// \since 0.1
/// \ingroup rmf_mobius
#[no_mangle]
pub unsafe extern "C" fn rmf_mobius_point(
    maps: *const RmfInversion,
    count: usize,
    point: RmfVec3,
    image: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_mobius_point", || {
        let image = out_ptr(image, "image")?;
        let map = mobius_map(maps, count)?;
        let Some(p) = map.apply(finite(point, "point")?) else {
            return invalid_arg(
                "the image of point is at infinity (point is an inversion centre) or beyond \
                 the range of double"
                    .into(),
            );
        };
        write(image, p.into());
        Ok(())
    })
}

/// The normalized differential d*μ at a point applied to a vector (Bartoň et al. (8), (12)):
/// the image direction of `vector` at μ(point), with the length of `vector`. Applied to a
/// rotation-minimizing vector field along a curve it gives one along the image curve
/// (Theorem 1).
///
/// @param[in] maps count inversions, applied first to last.
/// @param[in] count Number of inversions, ≥ 1.
/// @param[in] point The finite point where the differential is taken.
/// @param[in] vector A finite vector at point.
/// @param[out] image Receives d*μ_point(vector). Untouched on failure.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER (maps, image), or RMF_ERROR_INVALID_INPUT as for
///         rmf_mobius_point, or for a non-finite vector.
/// \since 0.1
/// \ingroup rmf_mobius
#[no_mangle]
pub unsafe extern "C" fn rmf_mobius_vector(
    maps: *const RmfInversion,
    count: usize,
    point: RmfVec3,
    vector: RmfVec3,
    image: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_mobius_vector", || {
        let image = out_ptr(image, "image")?;
        let map = mobius_map(maps, count)?;
        let (p, v) = (finite(point, "point")?, finite(vector, "vector")?);
        let Some(w) = map.normalized_differential(p, v) else {
            return invalid_arg("point is sent to infinity by the transformation".into());
        };
        write(image, w.into());
        Ok(())
    })
}

/// The exact image of a rational curve under a Möbius transformation: a rational curve of
/// degree 2n per sphere inversion (polynomial products, no fitting), with the curve's
/// parameter. Segments are split where needed to keep all weights positive.
///
/// @param[in] curve The curve; it must not pass through an inversion centre.
/// @param[in] maps, count The transformation.
/// @param[out] out Receives the image curve; free with rmf_curve_free.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If curve, maps or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the map is invalid, the curve passes through (or too
///         near) an inversion centre, or the image would have degree above 64 (each sphere
///         inversion doubles the degree).
/// \since 0.1
/// \ingroup rmf_mobius
#[no_mangle]
pub unsafe extern "C" fn rmf_mobius_curve(
    curve: *const RmfCurve,
    maps: *const RmfInversion,
    count: usize,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_mobius_curve", || {
        let curve = reference(curve, "curve")?;
        let out = out_ptr(out, "out")?;
        let map = mobius_map(maps, count)?;
        let image = map_curve(&map, curve.rational("curve")?)?;
        write(out, RmfCurve::new(image, None).into_raw());
        Ok(())
    })
}

/// The exact images of exact rational frames and their curve under a Möbius
/// transformation (Corollary 1): the frame vectors are carried by the normalized
/// differential, so a rotation-minimizing frame stays rotation-minimizing (Theorem 1);
/// f3 is re-oriented so that f3 = t × f2.
///
/// @param[in] frames Exact rational frames (RMF_FRAMES_RATIONAL).
/// @param[in] maps, count The transformation.
/// @param[out] curve_out Receives the image curve; free with rmf_curve_free.
/// @param[out] frames_out Receives the image frames; free with rmf_frames_free.
///             Both are written only on success.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If frames, maps, curve_out or frames_out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the frames are not rational, the map is invalid, the
///         curve passes through an inversion centre, or the image or its frames would have
///         degree above 64 (a sphere inversion takes degree n to 2n, frames of degree m to
///         m + 2n).
/// \since 0.1
/// \ingroup rmf_mobius
#[no_mangle]
pub unsafe extern "C" fn rmf_mobius_frames(
    frames: *const RmfFrames,
    maps: *const RmfInversion,
    count: usize,
    curve_out: *mut *mut RmfCurve,
    frames_out: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_mobius_frames", || {
        let frames = reference(frames, "frames")?;
        let (curve_out, frames_out) = (
            out_ptr(curve_out, "curve_out")?,
            out_ptr(frames_out, "frames_out")?,
        );
        let map = mobius_map(maps, count)?;
        let image = map_framed_curve(&map, &framed_of(frames)?)?;
        write_framed(image, curve_out, frames_out)
    })
}

/// G1 Hermite interpolation by rational curves with exact rational rotation-minimizing
/// frames (Bartoň, Jüttler & Wang, §3.1): per segment, the sphere through both points
/// touching both tangents is mapped onto a plane by an inversion, a planar PH cubic
/// interpolates the mapped data, and cubic and frame are mapped back — a rational curve of
/// degree 6 on that sphere with an exact rational RMF of degree 8. Planar segments are the
/// planar PH cubics themselves. Segment i runs over the parameters [i, i + 1]; segments may
/// be split further to keep all weights positive. The frames of consecutive segments join
/// continuously (constant rotations), so the whole frame is one exact rational RMF.
///
/// @param[in] points count points; consecutive points distinct.
/// @param[in] tangents count tangents (any non-zero length; normalized).
/// @param[in] count ≥ 2.
/// @param[in] initial_normal Projected onto the normal plane at points[0] and normalized to
///            give f2 there; f3 = t × f2.
/// @param[out] curve Receives the curve; free with rmf_curve_free.
/// @param[out] frames Receives its frames (RMF_FRAMES_RATIONAL); free with rmf_frames_free.
///             Both are written only on success.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If points, tangents, curve or frames is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count < 2, a point or tangent is not finite, a tangent
///         is zero, consecutive points coincide, or initial_normal is zero, not finite or
///         along the first tangent.
/// @return RMF_ERROR_NO_SOLUTION If a segment has no PH cubic interpolant in its plane (e.g.
///         a segment turning by more than half a turn); the message names the segment.
/// \since 0.1
/// \ingroup rmf_mobius
#[no_mangle]
pub unsafe extern "C" fn rmf_mobius_rrmf_hermite(
    points: *const RmfVec3,
    tangents: *const RmfVec3,
    count: usize,
    initial_normal: RmfVec3,
    curve: *mut *mut RmfCurve,
    frames: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_mobius_rrmf_hermite", || {
        let (curve, frames) = (out_ptr(curve, "curve")?, out_ptr(frames, "frames")?);
        let segments = hermite_arrays(points, tangents, count)?;
        let params: Vec<f64> = (0..count).map(|i| i as f64).collect();
        let result = mobius_hermite(&segments, &params, initial_normal.into())?;
        write_framed(result, curve, frames)
    })
}

/// Approximates a curve by `segments` rational curves with exact rational RMFs (the
/// algorithm of rmf_mobius_rrmf_hermite on G1 data sampled at equal parameter steps). The
/// result's joints have the input's parameters, so comparisons pair points by parameter.
/// The Möbius construction converges with order 3 on average and order 4 at the joints in
/// the RMF (Bartoň et al., Example 2).
///
/// @param[in] curve The curve to approximate over its whole domain, or NULL to use callback.
/// @param[in] callback An analytic curve (point and tangent at t), or NULL to use curve.
///            Exactly one of curve and callback must be given.
/// @param[in] user Passed to callback unchanged; may be NULL.
/// @param[in] t_min, t_max The callback's parameter interval (finite, t_min < t_max);
///            ignored for curve.
/// @param[in] segments Number of segments, 1 … 2^24.
/// @param[in] initial_normal As for rmf_mobius_rrmf_hermite.
/// @param[out] curve_out Receives the approximating curve; free with rmf_curve_free.
/// @param[out] frames_out Receives its frames; free with rmf_frames_free. Both are written
///             only on success.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If both curve and callback are NULL, or an out-pointer is NULL.
/// @return RMF_ERROR_INVALID_INPUT If both are given, segments = 0, the interval is invalid,
///         the callback gives a non-finite point or a zero tangent, or initial_normal is
///         invalid.
/// @return RMF_ERROR_NO_SOLUTION If a segment has no interpolant (too few segments).
/// \since 0.1
/// \ingroup rmf_mobius
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_mobius_rrmf_approximate(
    curve: *const RmfCurve,
    callback: RmfCurveCallback,
    user: *mut c_void,
    t_min: f64,
    t_max: f64,
    segments: usize,
    initial_normal: RmfVec3,
    curve_out: *mut *mut RmfCurve,
    frames_out: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_mobius_rrmf_approximate", || {
        let (curve_out, frames_out) = (
            out_ptr(curve_out, "curve_out")?,
            out_ptr(frames_out, "frames_out")?,
        );
        let source = curve_or_callback(curve, callback, user, t_min, t_max)?;
        let result = mobius_approximate(source.as_ref(), segments, initial_normal.into())?;
        write_framed(result, curve_out, frames_out)
    })
}
