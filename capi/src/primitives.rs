//! The C API of the primitive curves users draw — circles, circular arcs, polylines,
//! polygons, obrounds — as `RmfCurve`s of exact rational pieces (geometry in
//! `rmfsurf::primitives`). Each is named after the type it returns: `rmf_curve_<shape>`.

use super::boundary::{guard, out_ptr, slice, write, FfiResult};
use super::curve::RmfCurve;
use super::status::RmfStatus;
use super::types::RmfVec3;
use rmfsurf::glam::DVec3;
use rmfsurf::primitives::{arc_through, circle, obround, polygon, polyline};
use rmfsurf::PiecewiseCurve;

/// Writes a new curve handle to `out`.
unsafe fn hand_over_curve(curve: PiecewiseCurve, out: *mut *mut RmfCurve) -> FfiResult {
    write(out, RmfCurve::new(curve, None).into_raw());
    Ok(())
}

/// The points of a C array as vectors.
unsafe fn points(p: *const RmfVec3, count: usize, name: &'static str) -> FfiResult<Vec<DVec3>> {
    Ok(slice(p, count, name)?.iter().map(|&v| v.into()).collect())
}

/// The full circle of `radius` about `centre` in the plane of `x_axis` and `y_axis`: four
/// rational quadratic quarter arcs on the parameter intervals [0, 1] … [3, 4], starting at
/// centre + radius · x_axis / |x_axis| and turning counter-clockwise about x × y.
///
/// @param[in] centre The centre (finite).
/// @param[in] x_axis Direction to the start point (finite, non-zero).
/// @param[in] y_axis Any vector of the plane not parallel to x_axis (made orthogonal to it).
/// @param[in] radius Finite and > 0.
/// @param[out] out Receives the circle; free with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If an argument is not finite, radius ≤ 0, x_axis is zero
///         or y_axis is zero or parallel to x_axis (the message names the argument).
/// \since 0.2
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_circle(
    centre: RmfVec3,
    x_axis: RmfVec3,
    y_axis: RmfVec3,
    radius: f64,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_curve_circle", || {
        let out = out_ptr(out, "out")?;
        let curve = circle(centre.into(), x_axis.into(), y_axis.into(), radius)?;
        hand_over_curve(curve, out)
    })
}

/// The circular arc from `start` through `through` to `end` (less than a full turn), as
/// rational quadratic pieces of at most a quarter turn on the parameter interval [0, 1];
/// its ends are `start` and `end` exactly.
///
/// @param[in] start, through, end Three finite points, not collinear.
/// @param[out] out Receives the arc; free with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a point is not finite, or the points are collinear or
///         coincide.
/// \since 0.2
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_arc(
    start: RmfVec3,
    through: RmfVec3,
    end: RmfVec3,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_curve_arc", || {
        let out = out_ptr(out, "out")?;
        hand_over_curve(arc_through(start.into(), through.into(), end.into())?, out)
    })
}

/// Straight segments through `count` points, segment i on the parameter interval
/// [i, i + 1].
///
/// @param[in] points count finite points, consecutive points distinct.
/// @param[in] count Number of points, ≥ 2.
/// @param[out] out Receives the polyline; free with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If points or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count < 2, a point is not finite or two consecutive
///         points coincide (the message names their indices).
/// \since 0.2
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_polyline(
    points: *const RmfVec3,
    count: usize,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_curve_polyline", || {
        let out = out_ptr(out, "out")?;
        hand_over_curve(polyline(&self::points(points, count, "points")?)?, out)
    })
}

/// The closed polygon through `count` corners (the last joined to the first, which is not
/// repeated), segment i on the parameter interval [i, i + 1].
///
/// @param[in] corners count finite points, consecutive corners distinct.
/// @param[in] count Number of corners, ≥ 3.
/// @param[out] out Receives the polygon; free with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If corners or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count < 3, a corner is not finite or two consecutive
///         corners coincide (the message names their indices).
/// \since 0.2
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_polygon(
    corners: *const RmfVec3,
    count: usize,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_curve_polygon", || {
        let out = out_ptr(out, "out")?;
        hand_over_curve(polygon(&points(corners, count, "corners")?)?, out)
    })
}

/// The obround (slot): the points at `radius` from the segment of `length` centred on
/// `centre` along `x_axis`, in the plane of `x_axis` and `y_axis`. From the bottom of the
/// end at −x, counter-clockwise about x × y: a line, a half circle (two quarter arcs), a
/// line, a half circle — six pieces on [0, 1] … [5, 6]. A length of 0 gives the circle.
///
/// @param[in] centre The middle of the segment (finite).
/// @param[in] x_axis The segment's direction (finite, non-zero).
/// @param[in] y_axis Any vector of the plane not parallel to x_axis.
/// @param[in] length The distance between the two half circles' centres, finite and ≥ 0.
/// @param[in] radius Finite and > 0 (half the slot's width).
/// @param[out] out Receives the obround; free with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If an argument is not finite, length < 0, radius ≤ 0,
///         x_axis is zero or y_axis is zero or parallel to x_axis.
/// \since 0.2
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_obround(
    centre: RmfVec3,
    x_axis: RmfVec3,
    y_axis: RmfVec3,
    length: f64,
    radius: f64,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_curve_obround", || {
        let out = out_ptr(out, "out")?;
        let curve = obround(centre.into(), x_axis.into(), y_axis.into(), length, radius)?;
        hand_over_curve(curve, out)
    })
}
