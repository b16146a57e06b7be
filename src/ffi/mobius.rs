//! C entry points for Möbius transformations and the rational-RMF curves built with them
//! (Bartoň, Jüttler & Wang).

use super::boundary::{guard, invalid_arg, out_ptr, reference, slice, write, FfiError, FfiResult};
use super::curve::RmfCurve;
use super::frames::{rational_frames, RmfFrames};
use super::status::RmfStatus;
use super::types::RmfVec3;
use crate::frames::{FrameField, FrameKind};
use crate::mobius::{map_curve, map_framed_curve, Inversion, MobiusMap};
use glam::DVec3;
use std::sync::Arc;

/// RmfInversion.kind: inversion in the sphere (center, radius).
pub const RMF_INVERSION_SPHERE: u32 = 0;
/// RmfInversion.kind: reflection in the plane through `center` with normal `normal`.
pub const RMF_INVERSION_PLANE: u32 = 1;

/// One inversion of a Möbius transformation. A Möbius transformation is given as an array
/// of inversions applied first to last (translations and rotations are two reflections).
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
                FfiError::Core(crate::Error::InvalidInput(format!(
                    "maps[{i}].{}",
                    e.message()
                )))
            })
        })
        .collect::<FfiResult<Vec<_>>>()?;
    Ok(MobiusMap::new(inversions))
}

fn finite(v: RmfVec3, name: &str) -> FfiResult<DVec3> {
    Ok(crate::math::check_finite(v.into(), name)?)
}

/// The image μ(point) of a point under a Möbius transformation.
///
/// @param[in] maps count inversions, applied first to last.
/// @param[in] point A finite point.
/// @param[out] image Receives μ(point). Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If maps or image is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count = 0, an inversion is invalid (radius ≤ 0, zero
///         normal, non-finite), or the point is sent to infinity (a sphere centre).
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
            return invalid_arg("point is an inversion centre: its image is at infinity".into());
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
/// @param[out] image Receives d*μ_point(vector). Untouched on failure.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER (maps, image), or RMF_ERROR_INVALID_INPUT as for
///         rmf_mobius_point, or for a non-finite vector.
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
/// @return RMF_ERROR_INVALID_INPUT If the map is invalid or the curve passes through (or too
///         near) an inversion centre.
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
        let image = map_curve(&map, &curve.curve)?;
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
/// @return RMF_ERROR_INVALID_INPUT If the frames are not rational, the map is invalid, or the
///         curve passes through an inversion centre.
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
        let (image, image_frames) =
            map_framed_curve(&map, frames.field.curve(), rational_frames(frames)?)?;
        let image = Arc::new(image);
        let field = FrameField::new(image.clone(), FrameKind::Rational(image_frames))?;
        write(curve_out, RmfCurve::new(image, None).into_raw());
        write(frames_out, RmfFrames::into_raw(field));
        Ok(())
    })
}
