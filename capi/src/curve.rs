//! `RmfCurve`: a piecewise rational Bézier space curve (also a NURBS curve), with its
//! NURBS and per-segment views — or an analytic curve the caller evaluates in a callback,
//! which the approximations sample (rmf_callback_curve_create).

use super::boundary::{
    buffer, free_handle, guard, invalid_arg, optional_out, out_ptr, reference, write, FfiError,
    FfiResult,
};
use super::input::{callback_curve, nurbs_curve, CallbackCurve, RmfCurveCallback};
use super::status::RmfStatus;
use super::types::{piece_views, PieceViews, RmfBezierCurve, RmfNurbsCurve, RmfVec3};
use libc::c_void;
use rmfsurf::glam::DVec3;
use rmfsurf::ph::PhSpline;
use rmfsurf::validate::check_in_domain;
use rmfsurf::{NurbsCurve, ParametricCurve, PiecewiseCurve, Result};
use std::sync::{Arc, OnceLock};

/// A space curve (opaque): piecewise rational Bézier (also a NURBS curve), or an analytic
/// curve given by a callback. Created by the rmf_* constructors, freed with rmf_curve_free.
/// Immutable; may be read from several threads at once (a callback curve: if its callback
/// may be called from those threads).
/// \ingroup rmf_curves
pub struct RmfCurve {
    geometry: Geometry,
}

enum Geometry {
    Rational(Rational),
    Callback(CallbackCurve),
}

struct Rational {
    curve: Arc<PiecewiseCurve>,
    /// The caller's NURBS data when the curve was created from it: the NURBS view shows it
    /// unchanged.
    source: Option<NurbsCurve>,
    /// The NURBS view, built on first request; it fails for discontinuous curves (e.g. the
    /// Frenet vectors of a G1 spline), which still have segment views.
    nurbs: OnceLock<Result<NurbsView>>,
    segments: OnceLock<PieceViews>,
}

/// C-layout copy of the NURBS data.
struct NurbsView {
    nurbs: NurbsCurve,
    poles: Vec<RmfVec3>,
}

impl RmfCurve {
    /// A handle for a computed object (`source = None`) or for caller NURBS data.
    /// The curve may be shared (an `Arc`) with frames built along it.
    pub(crate) fn new(curve: impl Into<Arc<PiecewiseCurve>>, source: Option<NurbsCurve>) -> Self {
        Self {
            geometry: Geometry::Rational(Rational {
                curve: curve.into(),
                source,
                nurbs: OnceLock::new(),
                segments: OnceLock::new(),
            }),
        }
    }

    /// Moves the handle to the heap for C; the caller owns it.
    pub(crate) fn into_raw(self) -> *mut Self {
        Box::into_raw(Box::new(self))
    }

    /// The rational curve, for the entry points that compute with its Bézier segments; a
    /// callback curve is refused, naming the argument `name`.
    pub(crate) fn rational(&self, name: &str) -> FfiResult<&Arc<PiecewiseCurve>> {
        self.rational_parts(name).map(|r| &r.curve)
    }

    /// The curve as a PH cubic spline, refused (naming `name` and the segment) when it is
    /// not one.
    pub(crate) fn ph_spline(&self, name: &str) -> FfiResult<PhSpline> {
        Ok(PhSpline::new((**self.rational(name)?).clone())?)
    }

    fn rational_parts(&self, name: &str) -> FfiResult<&Rational> {
        match &self.geometry {
            Geometry::Rational(r) => Ok(r),
            Geometry::Callback(_) => invalid_arg(format!(
                "{name} is a callback curve: this needs a rational curve (NURBS data or a \
                 computed curve); approximate it first, e.g. with rmf_ph_spline_approximate"
            )),
        }
    }

    /// The rational curve, if it is one.
    pub(crate) fn as_rational(&self) -> Option<&Arc<PiecewiseCurve>> {
        match &self.geometry {
            Geometry::Rational(r) => Some(&r.curve),
            Geometry::Callback(_) => None,
        }
    }

    /// The curve as the approximations sample it (point and tangent at a parameter).
    pub(crate) fn sampled(&self) -> Box<dyn ParametricCurve + '_> {
        match &self.geometry {
            Geometry::Rational(r) => Box::new(r.curve.as_ref()),
            Geometry::Callback(c) => Box::new(c),
        }
    }

    /// The point and the derivative (a callback curve: the tangent it gives) at `t`, without
    /// allocating.
    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        match &self.geometry {
            Geometry::Rational(r) => r.curve.point_derivative(t),
            Geometry::Callback(c) => c.point_derivative(t),
        }
    }

    fn domain(&self) -> (f64, f64) {
        match &self.geometry {
            Geometry::Rational(r) => r.curve.domain(),
            Geometry::Callback(c) => c.domain(),
        }
    }

    fn nurbs_view(&self) -> FfiResult<&NurbsView> {
        let r = self.rational_parts("curve")?;
        let view = r.nurbs.get_or_init(|| {
            let nurbs = match &r.source {
                Some(n) => n.clone(),
                None => NurbsCurve::from_piecewise(&r.curve)?,
            };
            let poles = nurbs.poles().iter().map(|&p| p.into()).collect();
            Ok(NurbsView { nurbs, poles })
        });
        view.as_ref().map_err(|e| FfiError::Core(e.clone()))
    }

    fn segment_views(&self) -> FfiResult<&PieceViews> {
        let r = self.rational_parts("curve")?;
        Ok(r.segments
            .get_or_init(|| piece_views(r.curve.segments().iter().map(|s| s.homogeneous()))))
    }
}

/// Creates a curve from NURBS data (poles, optional weights, clamped knot vector).
///
/// @param[in] degree Degree p, 1 ≤ p ≤ 64.
/// @param[in] poles pole_count Cartesian poles (finite).
/// @param[in] weights pole_count weights (finite, > 0), or NULL for all weights 1.
/// @param[in] pole_count Number of poles, ≥ degree + 1.
/// @param[in] knots knot_count knots: non-decreasing, clamped (the first and the last
///            knot each of multiplicity exactly degree + 1), interior multiplicities ≤
///            degree, non-empty domain.
/// @param[in] knot_count Must equal pole_count + degree + 1.
/// @param[out] out Receives the new curve; the caller frees it with rmf_curve_free.
///            Untouched on failure.
///
/// Degree and counts are checked against each other before any array is read.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If poles, knots or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a count, degree, knot, weight or pole is invalid (the
///         message names it).
/// @return RMF_ERROR_INTERNAL On an internal error.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_nurbs_curve_create(
    degree: u32,
    poles: *const RmfVec3,
    weights: *const f64,
    pole_count: usize,
    knots: *const f64,
    knot_count: usize,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_nurbs_curve_create", || {
        let out = out_ptr(out, "out")?;
        let nurbs = nurbs_curve(degree, poles, weights, pole_count, knots, knot_count)?;
        let curve = RmfCurve::new(nurbs.to_piecewise()?, Some(nurbs));
        write(out, curve.into_raw());
        Ok(())
    })
}

/// Creates a curve from a callback: an analytic curve on [t_min, t_max] that the
/// approximations sample (rmf_ph_spline_approximate, rmf_mobius_rrmf_approximate, the cone
/// spline fits, wire edges). Entry points that need rational data (NURBS views, segments,
/// sweeps, Möbius images) refuse it with RMF_ERROR_INVALID_INPUT; rmf_curve_eval gives the
/// callback's point and tangent.
///
/// @param[in] callback Writes the point and the tangent (the derivative, or any non-zero
///            multiple of it) at t; see RmfCurveCallback. It is called during the calls that
///            use the curve, from their threads.
/// @param[in] user Passed to the callback unchanged; must stay valid while the curve exists.
/// @param[in] t_min, t_max The domain: finite, t_min < t_max, t_max − t_min finite.
/// @param[out] out Receives the new curve; free it with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If callback or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the domain is invalid.
/// \since 0.2
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_callback_curve_create(
    callback: RmfCurveCallback,
    user: *mut c_void,
    t_min: f64,
    t_max: f64,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_callback_curve_create", || {
        let out = out_ptr(out, "out")?;
        let Some(callback) = callback else {
            return Err(FfiError::Null("callback"));
        };
        let curve = RmfCurve {
            geometry: Geometry::Callback(callback_curve(callback, user, t_min, t_max)?),
        };
        write(out, curve.into_raw());
        Ok(())
    })
}

/// Frees a curve. NULL is a no-op. Views obtained from the curve become invalid; frames and
/// surfaces built from it stay valid (they keep their own reference).
///
/// @param[in] curve The curve to free, or NULL.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_free(curve: *mut RmfCurve) {
    free_handle(curve)
}

/// The parameter domain [t_min, t_max] of a curve.
///
/// @param[in] curve The curve.
/// @param[out] t_min, t_max Receive the domain ends.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if any argument is NULL.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_domain(
    curve: *const RmfCurve,
    t_min: *mut f64,
    t_max: *mut f64,
) -> RmfStatus {
    guard("rmf_curve_domain", || {
        let curve = reference(curve, "curve")?;
        let (t_min, t_max) = (out_ptr(t_min, "t_min")?, out_ptr(t_max, "t_max")?);
        let (lo, hi) = curve.domain();
        write(t_min, lo);
        write(t_max, hi);
        Ok(())
    })
}

/// Evaluates a curve and its first derivative.
///
/// @param[in] curve The curve.
/// @param[in] t Parameter in the curve's domain (see rmf_curve_domain).
/// @param[out] point Receives x(t).
/// @param[out] derivative Receives x'(t) (a callback curve: the tangent its callback gives);
///             may be NULL if not wanted.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If curve or point is NULL.
/// @return RMF_ERROR_INVALID_INPUT If t is not finite or outside the domain, or a callback
///         gives a non-finite value.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_eval(
    curve: *const RmfCurve,
    t: f64,
    point: *mut RmfVec3,
    derivative: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_curve_eval", || {
        let curve = reference(curve, "curve")?;
        let point = out_ptr(point, "point")?;
        let derivative = optional_out(derivative, "derivative")?;
        let t = check_in_domain(t, curve.domain(), "t")?;
        let (p, d1) = curve.point_derivative(t)?;
        write(point, p.into());
        if let Some(d) = derivative {
            write(d, d1.into());
        }
        Ok(())
    })
}

/// Borrowed NURBS view of a curve: one clamped NURBS with full-multiplicity interior knots
/// at segment joints (for a curve made by rmf_nurbs_curve_create: the data given).
///
/// @param[in] curve The curve.
/// @param[out] view Receives pointers into memory owned by the curve: do not free them;
///             valid until rmf_curve_free(curve).
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if the segments do not
///         join into one continuous NURBS (Frenet frame vectors and Frenet sweeps along a G1
///         spline jump at the joints); rmf_curve_segment still gives every piece.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_nurbs(
    curve: *const RmfCurve,
    view: *mut RmfNurbsCurve,
) -> RmfStatus {
    guard("rmf_curve_nurbs", || {
        let curve = reference(curve, "curve")?;
        let view = out_ptr(view, "view")?;
        let v = curve.nurbs_view()?;
        write(view, RmfNurbsCurve::of(&v.nurbs, v.poles.as_ptr()));
        Ok(())
    })
}

/// Copies the NURBS data of a curve (as in rmf_curve_nurbs) into caller buffers.
///
/// Size query: with pole_capacity = knot_capacity = 0 (poles, weights, knots may then be
/// NULL) only degree, pole_count and knot_count are written and RMF_OK is returned.
///
/// @param[in] curve The curve.
/// @param[out] degree Receives the degree.
/// @param[out] poles Buffer for pole_capacity poles.
/// @param[out] weights Buffer for pole_capacity weights.
/// @param[in] pole_capacity Capacity of poles and weights.
/// @param[out] knots Buffer for knot_capacity knots.
/// @param[in] knot_capacity Capacity of knots.
/// @param[out] pole_count Receives the number of poles.
/// @param[out] knot_count Receives the number of knots.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If curve, degree, pole_count or knot_count is NULL, or a
///         buffer is NULL with a non-zero capacity.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If a capacity is non-zero but too small; then only
///         degree, pole_count and knot_count are written.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_curve_nurbs_copy(
    curve: *const RmfCurve,
    degree: *mut u32,
    poles: *mut RmfVec3,
    weights: *mut f64,
    pole_capacity: usize,
    knots: *mut f64,
    knot_capacity: usize,
    pole_count: *mut usize,
    knot_count: *mut usize,
) -> RmfStatus {
    guard("rmf_curve_nurbs_copy", || {
        let curve = reference(curve, "curve")?;
        let (degree, pole_count, knot_count) = (
            out_ptr(degree, "degree")?,
            out_ptr(pole_count, "pole_count")?,
            out_ptr(knot_count, "knot_count")?,
        );
        let poles = buffer(poles, pole_capacity, "poles")?;
        let weights = buffer(weights, pole_capacity, "weights")?;
        let knots = buffer(knots, knot_capacity, "knots")?;
        let v = curve.nurbs_view()?;
        write(degree, v.nurbs.degree() as u32);
        write(pole_count, v.poles.len());
        write(knot_count, v.nurbs.knots().len());
        if pole_capacity == 0 && knot_capacity == 0 {
            return Ok(());
        }
        if pole_capacity < v.poles.len() || knot_capacity < v.nurbs.knots().len() {
            return Err(FfiError::BufferTooSmall(format!(
                "need {} poles and {} knots, capacities are {pole_capacity} and {knot_capacity}",
                v.poles.len(),
                v.nurbs.knots().len()
            )));
        }
        poles[..v.poles.len()].copy_from_slice(&v.poles);
        weights[..v.poles.len()].copy_from_slice(v.nurbs.weights());
        knots[..v.nurbs.knots().len()].copy_from_slice(v.nurbs.knots());
        Ok(())
    })
}

/// Number of rational Bézier segments of a curve.
///
/// @param[in] curve The curve.
/// @param[out] count Receives the number of segments.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if curve or count is NULL.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_segment_count(
    curve: *const RmfCurve,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_curve_segment_count", || {
        let curve = reference(curve, "curve")?;
        let count = out_ptr(count, "count")?;
        write(count, curve.rational("curve")?.segments().len());
        Ok(())
    })
}

/// Borrowed view of segment `index` of a curve as a rational Bézier curve.
///
/// @param[in] curve The curve.
/// @param[in] index 0 ≤ index < segment count.
/// @param[out] view Receives pointers owned by the curve (valid until it is freed).
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if index is out of range.
/// \since 0.1
/// \ingroup rmf_curves
#[no_mangle]
pub unsafe extern "C" fn rmf_curve_segment(
    curve: *const RmfCurve,
    index: usize,
    view: *mut RmfBezierCurve,
) -> RmfStatus {
    guard("rmf_curve_segment", || {
        let curve = reference(curve, "curve")?;
        let view = out_ptr(view, "view")?;
        let segments = curve.segment_views()?;
        let Some((poles, weights)) = segments.get(index) else {
            return super::boundary::invalid_arg(format!(
                "index = {index} but the curve has {} segments",
                segments.len()
            ));
        };
        let breaks = curve.rational("curve")?.breaks();
        write(
            view,
            RmfBezierCurve {
                degree: (poles.len() - 1) as u32,
                poles: poles.as_ptr(),
                weights: weights.as_ptr(),
                t_start: breaks[index],
                t_end: breaks[index + 1],
            },
        );
        Ok(())
    })
}
