//! The C API of PH cubic splines, their rotation-minimizing frames and the analysis of
//! profile surfaces (Mäurer & Jüttler; geometry in `rmfsurf::ph_cubic`). The profile surface
//! itself is made by the generic rmf_sweep_surface.

use super::boundary::{
    buffer, guard, hand_over, invalid_arg, optional_out, out_ptr, reference, sized_out, slice,
    write, write_sized, FfiError, FfiResult, OptionsStruct,
};
use super::curve::RmfCurve;
use super::frames::{framed_curve, rational_frames, RmfFrames};
use super::input::{curve_or_callback, hermite_arrays, RmfCurveCallback};
use super::status::RmfStatus;
use super::types::RmfVec3;
use rmfsurf::validate::{check_in_domain, check_sample_count};
use rmfsurf::{
    ph::angle_errors, ph::check_g1, ph::convex_initial_normal,
    ph::cubic_hermite as ph_cubic_hermite, ph::frenet_frames as ph_frenet_frames,
    ph::offset_profile, ph::offset_profile_by_arcs, ph::rational_rmf as ph_rational_rmf,
    ph::spline_approximate_with as ph_spline_approximate_with,
    ph::spline_from_segments as ph_spline_from_segments, ph::ApproximationOptions, ph::ExactRmf,
    ph::PhCubic, ph::PhSpline, ph::ProfileSurface, ph::RmfOptions, FrameField, FrameKind,
    FramedCurve, HermiteSegment, ParametricCurve, PiecewiseCurve, RationalFrames, ResultExt,
};
use std::ffi::c_void;

/// The G1 Hermite interpolants of Table 1 (Mäurer & Jüttler) with a PH cubic: the cubic
/// Bézier curves from p0 to p1 with end tangents along t0 and t1 whose speed is a
/// polynomial. Both roots of the PH condition (*) are computed; a root is kept only if the
/// cubic leaves p0 along +t0 and arrives at p1 along +t1. Planar data give planar cubics.
///
/// @param[in] p0, p1 End points (finite, distinct).
/// @param[in] t0, t1 End tangents (finite, non-zero; normalized).
/// @param[out] shape_matching Receives the interpolant with the shorter control polygon, the
///             one that follows the shape of the data (Theorem 10); free with
///             rmf_curve_free. For collinear data: the straight segment.
/// @param[out] other May be NULL. Receives the other interpolant, or NULL when the second
///             root reverses a tangent or has a numerical cusp (speed below 1e-8 of its
///             maximum), or the data are collinear; free with rmf_curve_free.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If shape_matching is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a point or tangent is not finite, a tangent is zero, or
///         p0 and p1 coincide (the message names the argument).
/// @return RMF_ERROR_NO_SOLUTION If no PH cubic interpolates the data: (*) has no real root,
///         every root reverses a tangent or has a numerical cusp, or the tangents are
///         parallel with the chord off their line. Nothing is written then.
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_cubic_hermite(
    p0: RmfVec3,
    t0: RmfVec3,
    p1: RmfVec3,
    t1: RmfVec3,
    shape_matching: *mut *mut RmfCurve,
    other: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_ph_cubic_hermite", || {
        let shape_matching = out_ptr(shape_matching, "shape_matching")?;
        let other = optional_out(other, "other")?;
        let data = HermiteSegment::new(p0.into(), t0.into(), p1.into(), t1.into())?;
        let solutions = ph_cubic_hermite(&data)?;
        let single = |c: PhCubic| PiecewiseCurve::new(vec![c.to_bezier()], vec![0.0, 1.0]);
        let first = single(solutions.shape_matching)?;
        let second = match (other, solutions.other) {
            (Some(_), Some(c)) => Some(single(c)?),
            _ => None,
        };
        write(shape_matching, RmfCurve::new(first, None).into_raw());
        if let Some(other) = other {
            let handle = second.map_or(std::ptr::null_mut(), |c| RmfCurve::new(c, None).into_raw());
            write(other, handle);
        }
        Ok(())
    })
}

/// A PH cubic spline through points with tangents (Mäurer & Jüttler §3.2): one
/// shape-matching PH cubic of Table 1 per segment, joined with G1 continuity. Segment i
/// runs on the parameter interval [i, i + 1].
///
/// @param[in] points count points; consecutive points distinct.
/// @param[in] tangents count tangents (finite, non-zero; normalized).
/// @param[in] count Number of points, ≥ 2.
/// @param[out] out Receives the spline (a cubic NURBS with knots of multiplicity 3 at the
///             joints); free with rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If points, tangents or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count < 2, a point or tangent is not finite, a tangent
///         is zero or consecutive points coincide (the message names the index).
/// @return RMF_ERROR_NO_SOLUTION If some segment admits no PH cubic (the message names it);
///         more points in between help.
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_spline_hermite(
    points: *const RmfVec3,
    tangents: *const RmfVec3,
    count: usize,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_ph_spline_hermite", || {
        let out = out_ptr(out, "out")?;
        let spline = ph_spline_from_segments(&hermite_arrays(points, tangents, count)?)?;
        write(out, RmfCurve::new(spline.into_curve(), None).into_raw());
        Ok(())
    })
}

/// A PH cubic spline within a distance tolerance of a curve (Mäurer & Jüttler §3.2,
/// Theorem 10): Hermite data sampled from the curve, one PH cubic of Table 1 per interval,
/// breaks placed so that every cubic's sampled two-sided distance to the curve is at most
/// tolerance, with few segments: the distance falls like h⁴ in the interval length h, and
/// each interval is made about as long as that law allows. The spline uses the curve's
/// parameter values as breakpoints (and breaks at every joint of a piecewise curve).
/// rmf_ph_spline_approximate_with_options is the same with caps on the work and a report.
///
/// Give exactly one of curve and callback.
///
/// @param[in] curve A G1 curve (e.g. from rmf_nurbs_curve_create or
///            rmf_callback_curve_create), whole domain; or NULL.
/// @param[in] callback An analytic curve on [t_min, t_max] (see RmfCurveCallback); or NULL.
///            It must be regular (non-zero derivative) and G1.
/// @param[in] user Passed to callback unchanged.
/// @param[in] t_min, t_max The callback's domain (ignored for curve).
/// @param[in] tolerance Largest distance, finite and > 0, in the curve's units.
/// @param[out] out Receives the spline; free with rmf_curve_free. Untouched on failure.
/// @param[out] max_distance May be NULL. Receives the largest measured distance.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If out is NULL, or both curve and callback are.
/// @return RMF_ERROR_INVALID_INPUT If tolerance is not finite and positive, or below what f64
///         resolves at the curve's coordinates (2.2e-16 times the largest coordinate at the
///         domain's ends and breaks), both curve and callback are given, t_min/t_max are not
///         finite with t_min < t_max, the curve has a corner, or the callback gives a
///         non-finite point or a zero tangent.
/// @return RMF_ERROR_NO_SOLUTION If no PH cubic interpolates the curve even on a very short
///         interval (a cusp, or a straight line meeting a corner).
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance is not reached within 100,000 segments,
///         or not above the rounding of the coordinates on the shortest intervals.
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_ph_spline_approximate(
    curve: *const RmfCurve,
    callback: RmfCurveCallback,
    user: *mut c_void,
    t_min: f64,
    t_max: f64,
    tolerance: f64,
    out: *mut *mut RmfCurve,
    max_distance: *mut f64,
) -> RmfStatus {
    guard("rmf_ph_spline_approximate", || {
        let out = out_ptr(out, "out")?;
        let max_distance = optional_out(max_distance, "max_distance")?;
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return invalid_arg(format!(
                "tolerance = {tolerance} must be finite and positive"
            ));
        }
        let source = curve_or_callback(curve, callback, user, t_min, t_max)?;
        let breaks = initial_breaks(curve.as_ref(), source.as_ref())?;
        let result = ph_spline_approximate_with(
            source.as_ref(),
            &breaks,
            &ApproximationOptions::new(tolerance),
        )?;
        write(
            out,
            RmfCurve::new(result.spline.into_curve(), None).into_raw(),
        );
        if let Some(d) = max_distance {
            write(d, result.max_distance);
        }
        Ok(())
    })
}

/// The breaks an approximation must keep: a rational curve's joints (checked G1), else the
/// ends of the domain.
fn initial_breaks(curve: Option<&RmfCurve>, source: &dyn ParametricCurve) -> FfiResult<Vec<f64>> {
    match curve.and_then(RmfCurve::as_rational) {
        Some(piecewise) => {
            check_g1(piecewise)?;
            Ok(piecewise.breaks().to_vec())
        }
        None => {
            let (lo, hi) = source.domain();
            Ok(vec![lo, hi])
        }
    }
}

/// What rmf_ph_spline_approximate_with_options aims at and may spend. Initialise with
/// rmf_ph_approximation_options_init, then set the tolerance.
/// \since 0.2
/// \ingroup rmf_ph_cubic
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RmfPhApproximationOptions {
    /// sizeof(RmfPhApproximationOptions), written by rmf_ph_approximation_options_init.
    pub struct_size: usize,
    /// Largest distance between the spline and the curve, in the curve's units: finite, > 0
    /// and not below the rounding of the curve's coordinates. Default 0, which is refused:
    /// set it.
    pub tolerance: f64,
    /// Most PH segments, 1 … 1,048,576 (2^20). Default 100,000.
    pub max_segments: usize,
    /// Most evaluations of the curve (for a callback curve, callback calls), ≥ 1. Default
    /// SIZE_MAX (no cap beyond max_segments). Each trial interval costs 16; at most 9 trials
    /// per segment plus 43 per segment of the curve (about 1.5 per segment on smooth curves).
    pub max_evaluations: usize,
}

impl Default for RmfPhApproximationOptions {
    fn default() -> Self {
        let defaults = ApproximationOptions::new(0.0);
        Self {
            struct_size: std::mem::size_of::<Self>(),
            tolerance: 0.0,
            max_segments: defaults.max_segments,
            max_evaluations: defaults.max_evaluations,
        }
    }
}

// SAFETY: repr(C) plain numbers, usize first.
unsafe impl OptionsStruct for RmfPhApproximationOptions {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// What rmf_ph_spline_approximate_with_options did. The caller sets struct_size =
/// sizeof(RmfPhApproximationReport); the library writes the fields that fit, on success only.
/// \since 0.2
/// \ingroup rmf_ph_cubic
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RmfPhApproximationReport {
    /// sizeof(RmfPhApproximationReport), set by the caller.
    pub struct_size: usize,
    /// Largest measured distance between the spline and the curve.
    pub max_distance: f64,
    /// PH segments of the spline.
    pub segments: usize,
    /// Evaluations of the curve (callback calls for a callback curve).
    pub evaluations: usize,
}

// SAFETY: repr(C) plain numbers, usize first.
unsafe impl OptionsStruct for RmfPhApproximationReport {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// Writes the default options (tolerance 0, to be set; 100,000 segments; no cap on
/// evaluations) and struct_size.
///
/// @param[out] out The options to initialise.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if out is NULL.
/// \since 0.2
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_approximation_options_init(
    out: *mut RmfPhApproximationOptions,
) -> RmfStatus {
    guard("rmf_ph_approximation_options_init", || {
        let out = out_ptr(out, "out")?;
        write(out, RmfPhApproximationOptions::default());
        Ok(())
    })
}

/// rmf_ph_spline_approximate of a curve, with caps on the work and a report of it. The
/// breaks are placed as there; the work is bounded: each trial interval evaluates the curve
/// 16 times, there are at most 9 trials per PH segment plus 43 per segment of a piecewise
/// curve (one for a callback curve), about 1.5 per PH segment on smooth curves (some 25
/// evaluations per segment), and the call ends with
/// RMF_ERROR_NOT_CONVERGED as soon as options->max_segments or options->max_evaluations
/// would be exceeded. Work: about 35 evaluations of the curve per segment (times:
/// docs/benchmarks.md).
///
/// @param[in] curve A G1 curve (NURBS data, a computed curve or a callback curve from
///            rmf_callback_curve_create), whole domain; a piecewise curve breaks at its
///            joints.
/// @param[in] options Tolerance and caps (initialise with rmf_ph_approximation_options_init).
/// @param[out] out Receives the spline; free with rmf_curve_free. Untouched on failure.
/// @param[out] report May be NULL. With struct_size set by the caller, receives the largest
///             measured distance, the segments and the evaluations. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If curve, options or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If options->struct_size or report->struct_size is no size
///         of the struct, the tolerance is not finite and positive or below what f64 resolves
///         at the curve's coordinates (2.2e-16 times the largest coordinate at the domain's
///         ends and joints), max_segments is outside 1 … 2^20, max_evaluations is 0, the
///         curve has a corner, or a callback gives a non-finite point or a zero tangent.
/// @return RMF_ERROR_NO_SOLUTION If no PH cubic interpolates the curve even on a very short
///         interval (a cusp, or a straight line meeting a corner).
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance would need more than max_segments
///         segments or more than max_evaluations evaluations, or is not reached above the
///         rounding of the coordinates on the shortest intervals.
/// \since 0.2
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_spline_approximate_with_options(
    curve: *const RmfCurve,
    options: *const RmfPhApproximationOptions,
    out: *mut *mut RmfCurve,
    report: *mut RmfPhApproximationReport,
) -> RmfStatus {
    guard("rmf_ph_spline_approximate_with_options", || {
        let curve = reference(curve, "curve")?;
        if options.is_null() {
            return Err(FfiError::Null("options"));
        }
        let given = super::boundary::options(options, "options")?;
        let out = out_ptr(out, "out")?;
        let report = sized_out(report, "report")?;
        let limits = ApproximationOptions {
            tolerance: given.tolerance,
            max_segments: given.max_segments,
            max_evaluations: given.max_evaluations,
        };
        limits.check().map_err(|e| e.context("options"))?;
        let source = curve.sampled();
        let breaks = initial_breaks(Some(curve), source.as_ref())?;
        let result = ph_spline_approximate_with(source.as_ref(), &breaks, &limits)?;
        let done = RmfPhApproximationReport {
            struct_size: std::mem::size_of::<RmfPhApproximationReport>(),
            max_distance: result.max_distance,
            segments: result.spline.segments().len(),
            evaluations: result.evaluations,
        };
        write(
            out,
            RmfCurve::new(result.spline.into_curve(), None).into_raw(),
        );
        if let Some(report) = report {
            write_sized(report, &done);
        }
        Ok(())
    })
}

/// The rational approximation of the rotation-minimizing frame of a PH cubic spline
/// (Mäurer & Jüttler §3.3–3.4): on each segment the rational Frenet frame (19) turned by
/// 2 arctan W(v), eq. (29), W the biquadratic rational function (36)–(37) interpolating
/// tan(Ω/2) of the exact RMF angle (30) with its derivative at the segment ends, its free
/// parameter λ minimizing (40). The frames are exact at every joint, continuous and G1,
/// rational of degree 6 (nearly straight segments: the carried frame, degree ≤ 4); segments
/// may be split for positive weights. rmf_frames_vector_curve gives each frame vector as a
/// rational curve; rmf_sweep_surface sweeps profiles with it (degree (m, 9) per segment);
/// rmf_ph_rmf_angle_error measures it against the exact RMF.
///
/// @param[in] ph_spline A PH cubic spline (e.g. from rmf_ph_spline_hermite or
///            rmf_ph_spline_approximate, or NURBS data whose segments are PH cubics), G1.
/// @param[in] initial_normal Projected onto the normal plane at the start and normalized:
///            f2 there; f3 = t × f2.
/// @param[out] out Receives the frames (RMF_FRAMES_RATIONAL); free with rmf_frames_free.
///             They keep their own reference to the spline. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If ph_spline or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a segment is not a PH cubic, the spline is not G1, or
///         initial_normal is not finite, zero or tangent to the spline.
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_rational_rmf(
    ph_spline: *const RmfCurve,
    initial_normal: RmfVec3,
    out: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_ph_rational_rmf", || {
        rational_rmf_into(ph_spline, RmfOptions::rmf(initial_normal.into()), out)
    })
}

/// rmf_ph_rational_rmf with a twist, and closing the frame of a closed spine. The frame is
/// the RMF turned, in addition, by an angle growing linearly with arc length (exact: the arc
/// length of a PH spline is polynomial), built into the rational W of every segment, so the
/// result stays rational and exact at the joints:
///  - twist: the total turn from start to end, radians (0: none);
///  - closure_symmetry k ≥ 1 (closed spines only): the RMF of a closed spine comes back
///    turned by its holonomy; the smallest additional turn, modulo 2π/k, that closes it is
///    added to twist. k is the symmetry order of the profile (1 for any profile, 4 for a
///    square), so that the closed sweep has no seam. 0: not given; the frame is left
///    open (the RMF with its holonomy). The same meaning as RmfWireSweepOptions's, where a
///    closed wire must close and 0 is taken as 1 (docs/c-api.md, "Parameters").
///
/// @param[in] ph_spline, initial_normal As for rmf_ph_rational_rmf.
/// @param[in] twist Finite.
/// @param[in] closure_symmetry 0 or the symmetry order k ≥ 1.
/// @param[out] out Receives the frames; free with rmf_frames_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If ph_spline or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT As for rmf_ph_rational_rmf; also if twist is not finite
///         or so large that a segment would need more than 4096 rational pieces,
///         or closure_symmetry > 0 for a spline that does not end where it starts with the
///         same tangent.
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_rational_rmf_twisted(
    ph_spline: *const RmfCurve,
    initial_normal: RmfVec3,
    twist: f64,
    closure_symmetry: u32,
    out: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_ph_rational_rmf_twisted", || {
        let options = RmfOptions {
            initial_normal: initial_normal.into(),
            twist,
            closure_symmetry: (closure_symmetry > 0).then_some(closure_symmetry),
        };
        rational_rmf_into(ph_spline, options, out)
    })
}

unsafe fn rational_rmf_into(
    ph_spline: *const RmfCurve,
    options: RmfOptions,
    out: *mut *mut RmfFrames,
) -> FfiResult {
    let spline = reference(ph_spline, "ph_spline")?;
    let out = out_ptr(out, "out")?;
    let rmf = ph_rational_rmf(&spline.ph_spline("ph_spline")?, &options)?;
    write_frames(spline, rmf.framed.into_parts().1, out)
}

/// Writes rational frames along `spline` to `out` as a new handle.
unsafe fn write_frames(
    spline: &RmfCurve,
    frames: RationalFrames,
    out: *mut *mut RmfFrames,
) -> FfiResult {
    let field = FrameField::new(
        spline.rational("ph_spline")?.clone(),
        FrameKind::Rational(frames),
    )?;
    write(out, RmfFrames::into_raw(field));
    Ok(())
}

/// The Frenet frame (t, n, b) of a PH cubic spline as exact rational functions (19) of
/// degree 2, f2 = n, f3 = b (for comparison with the RMF: its sweeps are not profile
/// surfaces). Segments where σ has a negative Bernstein coefficient are split for positive
/// weights. Usable by rmf_sweep_surface (degree (m, 5) per piece).
///
/// @param[in] ph_spline A PH cubic spline.
/// @param[out] out Receives the frames (RMF_FRAMES_RATIONAL); free with rmf_frames_free.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If ph_spline or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a segment is not a PH cubic or is (nearly) straight,
///         sin θ ≤ 1e-4 (no Frenet frame, or none computable to 1e-7).
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_frenet_frames(
    ph_spline: *const RmfCurve,
    out: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_ph_frenet_frames", || {
        let spline = reference(ph_spline, "ph_spline")?;
        let out = out_ptr(out, "out")?;
        write_frames(
            spline,
            ph_frenet_frames(&spline.ph_spline("ph_spline")?)?
                .into_parts()
                .1,
            out,
        )
    })
}

/// The exact rotation-minimizing frame of a PH cubic spline at given parameters, in closed
/// form: the Frenet frame turned by the angle (30)–(31) of Mäurer & Jüttler (no quadrature),
/// the constants chained across the joints from initial_normal. On (nearly) straight
/// segments (sin θ ≤ 1e-3), where the Frenet frame degenerates, the frame carried by the
/// smallest rotation of the tangent is used; it differs from the RMF by about θ³ (below 1e-8
/// rad).
///
/// @param[in] ph_spline A PH cubic spline, G1.
/// @param[in] initial_normal As for rmf_ph_rational_rmf.
/// @param[in] t count parameters in the spline's domain.
/// @param[in] count Number of parameters (0 is allowed: nothing is computed).
/// @param[out] f2 Buffer for count vectors f2.
/// @param[out] f3 May be NULL; else a buffer for count vectors f3 = t × f2.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If ph_spline is NULL, or t or f2 is NULL with count > 0.
/// @return RMF_ERROR_INVALID_INPUT If a segment is not a PH cubic, the spline is not G1,
///         initial_normal is not usable, or a parameter is not finite or outside the domain.
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_exact_rmf_eval(
    ph_spline: *const RmfCurve,
    initial_normal: RmfVec3,
    t: *const f64,
    count: usize,
    f2: *mut RmfVec3,
    f3: *mut RmfVec3,
) -> RmfStatus {
    guard("rmf_ph_exact_rmf_eval", || {
        let spline = reference(ph_spline, "ph_spline")?;
        let params = slice(t, count, "t")?;
        let f2 = buffer(f2, count, "f2")?;
        let f3 = if f3.is_null() {
            None
        } else {
            Some(buffer(f3, count, "f3")?)
        };
        let rmf = ExactRmf::new(&spline.ph_spline("ph_spline")?, initial_normal.into(), 0.0)?;
        let domain = spline.rational("ph_spline")?.domain();
        let frames = params
            .iter()
            .map(|&t| check_in_domain(t, domain, "t").map(|t| rmf.frame(t)))
            .collect::<rmfsurf::Result<Vec<_>>>()?;
        for (dst, f) in f2.iter_mut().zip(&frames) {
            *dst = f.f2.into();
        }
        if let Some(f3) = f3 {
            for (dst, f) in f3.iter_mut().zip(&frames) {
                *dst = f.f3.into();
            }
        }
        Ok(())
    })
}

/// The accuracy of rational frames along a PH cubic spline (e.g. from rmf_ph_rational_rmf):
/// the largest angle about the tangent between them and the exact RMF (closed form, started
/// from the same frame), per spline segment. Frames made with a twist
/// (rmf_ph_rational_rmf_twisted, also the turn that closes a closed spine) are compared after
/// taking off that twist, linear in arc length; every other frame is compared with the RMF
/// itself, so a frame that drifts against the RMF (e.g. a Frenet frame) reports its drift.
///
/// Size query: with per_segment = NULL and capacity = 0 only segment_count (and max_angle)
/// are written.
///
/// @param[in] frames Rational frames along a PH cubic spline.
/// @param[out] per_segment Buffer for capacity angles (radians), one per spline segment.
/// @param[in] capacity Capacity of per_segment.
/// @param[out] segment_count Receives the number of spline segments.
/// @param[out] max_angle Receives the largest angle (radians).
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If frames, segment_count or max_angle is NULL, or
///         per_segment is NULL with capacity > 0.
/// @return RMF_ERROR_INVALID_INPUT If the frames are not rational or their curve is not a
///         G1 PH cubic spline.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity < the segment count; then only
///         segment_count is written.
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_rmf_angle_error(
    frames: *const RmfFrames,
    per_segment: *mut f64,
    capacity: usize,
    segment_count: *mut usize,
    max_angle: *mut f64,
) -> RmfStatus {
    guard("rmf_ph_rmf_angle_error", || {
        let frames = reference(frames, "frames")?;
        let per_segment = buffer(per_segment, capacity, "per_segment")?;
        let segment_count = out_ptr(segment_count, "segment_count")?;
        let max_angle = out_ptr(max_angle, "max_angle")?;
        let rational = rational_frames(frames)?;
        let spline = PhSpline::new((**frames.field.curve()).clone()).context("frames")?;
        let errors = angle_errors(&spline, rational)?;
        let n = errors.per_segment.len();
        if capacity > 0 && capacity < n {
            write(segment_count, n);
            return Err(FfiError::BufferTooSmall(format!(
                "per_segment needs {n} entries, capacity is {capacity}"
            )));
        }
        per_segment[..capacity.min(n)].copy_from_slice(&errors.per_segment[..capacity.min(n)]);
        write(segment_count, n);
        write(max_angle, errors.max);
        Ok(())
    })
}

/// Where a sweep comes closest to being singular (Corollary 7 of Mäurer & Jüttler).
/// \ingroup rmf_sweeps
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfSingularityMargin {
    /// min of g = 1 − κ(v)·(c(u)·n(v)) over the surface, condition (9): the part of ∂s/∂v
    /// along the spine tangent, relative to the spine's. ≤ 0: the sweep is singular (folds
    /// over itself where the profile reaches the spine's curvature axis).
    pub margin: f64,
    /// Profile parameter where the minimum is attained.
    pub u: f64,
    /// Spine parameter where the minimum is attained.
    pub v: f64,
    /// 1 − κ_max·max‖c‖: > 0 guarantees a regular sweep (the cheap sufficient condition).
    pub bound_margin: f64,
}

/// The singularity margin of the sweep of profile along spine with frames (the inputs of
/// rmf_sweep_surface): condition (9) evaluated exactly over the profile (roots of a
/// polynomial) and scanned and refined along the spine.
///
/// The analyses of §2.3 hold for rotation-minimizing frames only: frames that are not an
/// RMF (Frenet frames, twisted frames, frames of unknown origin) are refused, as are frames
/// of another spine (breakpoints or tangent differ, as for rmf_sweep_surface).
///
/// @param[in] spine, frames, profile As for rmf_sweep_surface; frames from
///            rmf_ph_rational_rmf, rmf_mobius_rrmf_hermite / _approximate, rmf_rrmf_* or
///            rmf_mobius_frames of such frames.
/// @param[out] out Receives the margin.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER if an argument is NULL, or
///         RMF_ERROR_INVALID_INPUT if the frames are not rational frames of the spine (their
///         breakpoints or their tangent differ), are not rotation-minimizing, or frame
///         pieces × profile segments exceed 2^15 (a bound on the work of one call).
/// \since 0.1
/// \ingroup rmf_sweeps
#[no_mangle]
pub unsafe extern "C" fn rmf_sweep_singularity_margin(
    spine: *const RmfCurve,
    frames: *const RmfFrames,
    profile: *const RmfCurve,
    out: *mut RmfSingularityMargin,
) -> RmfStatus {
    guard("rmf_sweep_singularity_margin", || {
        let (framed, profile) = sweep_inputs(spine, frames, profile)?;
        let out = out_ptr(out, "out")?;
        let m = ProfileSurface::new(&framed, profile)?.singularity_margin();
        write(
            out,
            RmfSingularityMargin {
                margin: m.margin,
                u: m.u,
                v: m.v,
                bound_margin: m.bound_margin,
            },
        );
        Ok(())
    })
}

/// The Gaussian curvature of a profile surface at (u, v) by (13) of Mäurer & Jüttler,
/// K = κ_u · κ_v cos θ: the curvature of the exact profile surface with these frames (for
/// rational RMFs it agrees with the NURBS surface up to the frames' approximation error).
/// Its sign tells elliptic (K > 0) from hyperbolic (K < 0) regions.
///
/// @param[in] spine, frames, profile As for rmf_sweep_singularity_margin (rotation-minimizing
///            frames of the spine).
/// @param[in] u, v Profile and spine parameters inside their domains.
/// @param[out] k Receives K.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER if an argument is NULL, or
///         RMF_ERROR_INVALID_INPUT if u or v is outside its domain, the frames are not
///         rotation-minimizing rational frames of the spine, or frame pieces × profile
///         segments exceed 2^15.
/// \since 0.1
/// \ingroup rmf_sweeps
#[no_mangle]
pub unsafe extern "C" fn rmf_sweep_gaussian_curvature(
    spine: *const RmfCurve,
    frames: *const RmfFrames,
    profile: *const RmfCurve,
    u: f64,
    v: f64,
    k: *mut f64,
) -> RmfStatus {
    guard("rmf_sweep_gaussian_curvature", || {
        let (framed, profile) = sweep_inputs(spine, frames, profile)?;
        let k = out_ptr(k, "k")?;
        let u = check_in_domain(u, profile.domain(), "u")?;
        let v = check_in_domain(v, framed.domain(), "v")?;
        write(
            k,
            ProfileSurface::new(&framed, profile)?.gaussian_curvature(u, v),
        );
        Ok(())
    })
}

/// rmf_sweep_parabolic_points: a profile inflection (K = 0 along u = const), or an end of a
/// straight profile piece (K = 0 on the whole piece).
/// \ingroup rmf_sweeps
pub const RMF_PARABOLIC_PROFILE: u32 = 1;
/// rmf_sweep_parabolic_points: a straight piece of the spine (K = 0 along v = const); the
/// point is given at both ends of the profile.
/// \ingroup rmf_sweeps
pub const RMF_PARABOLIC_SPINE: u32 = 2;
/// rmf_sweep_parabolic_points: a point of the curves (14), where the surface normal is
/// perpendicular to the spine's principal normal.
/// \ingroup rmf_sweeps
pub const RMF_PARABOLIC_NORMAL: u32 = 3;

/// A parabolic point (K = 0) of a profile surface.
/// \ingroup rmf_sweeps
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfParabolicPoint {
    /// Profile parameter.
    pub u: f64,
    /// Spine parameter.
    pub v: f64,
    /// RMF_PARABOLIC_PROFILE, RMF_PARABOLIC_SPINE or RMF_PARABOLIC_NORMAL (cases 1–3 of §2.3).
    pub kind: u32,
}

/// The parabolic points of a profile surface (§2.3 of Mäurer & Jüttler), which separate its
/// elliptic (K > 0) from its hyperbolic (K < 0) parts, sampled on v_samples uniform spine
/// parameters: at each, the profile inflections (case 1), the whole profile where the spine
/// is straight (case 2), and the roots of (14) (case 3), all found as roots of polynomials
/// in u. Points come ordered by v.
///
/// Size query: with points = NULL and capacity = 0 only count is written.
///
/// @param[in] spine, frames, profile As for rmf_sweep_singularity_margin (rotation-minimizing
///            frames of the spine).
/// @param[in] v_samples Number of spine parameters, 2 … 2^24.
/// @param[out] points Buffer for capacity points.
/// @param[in] capacity Capacity of points.
/// @param[out] count Receives the number of points.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If spine, frames, profile or count is NULL, or points is
///         NULL with capacity > 0.
/// @return RMF_ERROR_INVALID_INPUT If v_samples < 2 or v_samples × profile segments > 2^24,
///         the frames are not rotation-minimizing rational frames of the spine, or frame
///         pieces × profile segments exceed 2^15.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity < count; then only count is written.
/// \since 0.1
/// \ingroup rmf_sweeps
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_sweep_parabolic_points(
    spine: *const RmfCurve,
    frames: *const RmfFrames,
    profile: *const RmfCurve,
    v_samples: u32,
    points: *mut RmfParabolicPoint,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_sweep_parabolic_points", || {
        let (framed, profile) = sweep_inputs(spine, frames, profile)?;
        let points = buffer(points, capacity, "points")?;
        let count = out_ptr(count, "count")?;
        check_sample_count(v_samples as usize, 2, "v_samples")?;
        // Each spine sample looks at every profile segment.
        let work = (v_samples as usize).saturating_mul(profile.segments().len());
        check_sample_count(work, 2, "v_samples × profile segments")?;
        let lines = ProfileSurface::new(&framed, profile)?.parabolic_lines(v_samples as usize);
        let found = parabolic_points(
            &lines,
            framed.domain(),
            profile.domain(),
            v_samples as usize,
        );
        hand_over(&found, points, count, "points")
    })
}

/// A vertex of a parabolic line traced by rmf_sweep_parabolic_curves.
/// \ingroup rmf_sweeps
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct RmfParabolicCurvePoint {
    /// Profile parameter.
    pub u: f64,
    /// Spine parameter.
    pub v: f64,
    /// The surface point s(u, v).
    pub point: RmfVec3,
    /// Which curve the vertex belongs to: 0, 1, …; the vertices of one curve are consecutive
    /// and in order along it.
    pub curve: u32,
}

/// The parabolic lines (14) of a profile surface (§2.3 of Mäurer & Jüttler, case 3: where the
/// surface normal is perpendicular to the spine's principal normal) traced as curves along
/// the spine, as polylines in the parameter plane: the roots of (14) continued from one
/// spine parameter to the next, split where the profile inflects or its tangent is parallel
/// to an axis so that each piece is a graph u(v), and joined again where the pieces meet.
/// The polyline mapped onto the surface through its parameters stays within tolerance of the
/// line (half the tolerance is met at the middle of every polyline segment). Where the spine
/// inflects (k = 0) the whole line v = const satisfies (14) and is a curve of its own. The
/// lines break at a joint of the spine where its curvature jumps (a C¹ spline), and the
/// profile inflections (case 1) and straight pieces (cases 1, 2) are
/// rmf_sweep_parabolic_points's. The frames must be rotation-minimizing: (13) and (14) hold
/// for an RMF; for rational frames that approximate it (rmf_ph_rational_rmf) the lines are
/// the zeros of (14) of the exported surface to the rounding, and K of that surface is small
/// but not 0 on them.
///
/// Size query: with points = NULL and capacity = 0 only count is written.
///
/// @param[in] spine, frames, profile As for rmf_sweep_singularity_margin (rotation-minimizing
///            frames of the spine).
/// @param[in] tolerance Finite positive length on the surface.
/// @param[out] points Buffer for capacity vertices.
/// @param[in] capacity Capacity of points.
/// @param[out] count Receives the number of vertices.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If spine, frames, profile or count is NULL, or points is
///         NULL with capacity > 0.
/// @return RMF_ERROR_INVALID_INPUT If tolerance is not finite and positive or below one
///         rounding of the profile's coordinates, the frames are not rotation-minimizing
///         rational frames of the spine, or frame pieces × profile segments exceed 2^15.
/// @return RMF_ERROR_NOT_CONVERGED If the lines need more than 2^20 vertices at this
///         tolerance (estimated before they are refined, so the refusal is quick), or the
///         spine's curvature direction turns too fast to be followed.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If 0 < capacity < count; then only count is written.
/// \since 0.2
/// \ingroup rmf_sweeps
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_sweep_parabolic_curves(
    spine: *const RmfCurve,
    frames: *const RmfFrames,
    profile: *const RmfCurve,
    tolerance: f64,
    points: *mut RmfParabolicCurvePoint,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_sweep_parabolic_curves", || {
        let (framed, profile) = sweep_inputs(spine, frames, profile)?;
        let points = buffer(points, capacity, "points")?;
        let count = out_ptr(count, "count")?;
        let surface = ProfileSurface::new(&framed, profile)?;
        let mut found = Vec::new();
        for (curve, line) in surface.parabolic_curves(tolerance)?.iter().enumerate() {
            found.extend(line.points.iter().map(|&(u, v)| RmfParabolicCurvePoint {
                u,
                v,
                point: surface.point(u, v).into(),
                curve: curve as u32,
            }));
        }
        hand_over(&found, points, count, "points")
    })
}

/// The parabolic lines as points on the sampled v lines (see rmf_sweep_parabolic_points).
fn parabolic_points(
    lines: &rmfsurf::ph::ParabolicLines,
    (v0, v1): (f64, f64),
    (u0, u1): (f64, f64),
    samples: usize,
) -> Vec<RmfParabolicPoint> {
    let point = |u, v, kind| RmfParabolicPoint { u, v, kind };
    let mut out = Vec::new();
    for j in 0..samples {
        let v = v0 + (v1 - v0) * j as f64 / (samples - 1) as f64;
        out.extend(
            lines
                .profile_inflections
                .iter()
                .map(|&u| point(u, v, RMF_PARABOLIC_PROFILE)),
        );
        for &(a, b) in &lines.straight_profile {
            out.extend([
                point(a, v, RMF_PARABOLIC_PROFILE),
                point(b, v, RMF_PARABOLIC_PROFILE),
            ]);
        }
        if lines.straight_spine.iter().any(|&(a, b)| v >= a && v <= b) {
            out.extend([
                point(u0, v, RMF_PARABOLIC_SPINE),
                point(u1, v, RMF_PARABOLIC_SPINE),
            ]);
        }
    }
    out.extend(
        lines
            .normal_condition
            .iter()
            .map(|&(u, v)| point(u, v, RMF_PARABOLIC_NORMAL)),
    );
    out.sort_by(|a, b| a.v.total_cmp(&b.v).then(a.u.total_cmp(&b.u)));
    out
}

/// The initial normal for rmf_ph_rational_rmf that makes the RMF sweep of a convex profile
/// along a PH spline everywhere elliptic (K > 0) or everywhere hyperbolic (K < 0),
/// Corollary 9 of Mäurer & Jüttler: possible when the profile's tangent turns by δ < π and
/// δ + ΔΩ < π, ΔΩ the spread of the RMF against the Frenet frame along the spine.
///
/// @param[in] ph_spline A G1 PH cubic spline without straight segments.
/// @param[in] profile A convex profile (x → f2, y → f3).
/// @param[in] elliptic Non-zero: K > 0; zero: K < 0.
/// @param[out] initial_normal Receives the initial normal.
/// @param[out] margin May be NULL. Receives π − δ − ΔΩ > 0, the slack (radians).
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If ph_spline, profile or initial_normal is NULL.
/// @return RMF_ERROR_INVALID_INPUT If a segment is not a PH cubic or the spline is not G1.
/// @return RMF_ERROR_NO_SOLUTION If the profile is not convex, δ + ΔΩ ≥ π, or a spine segment
///         is straight (the message says which).
/// \since 0.1
/// \ingroup rmf_ph_cubic
#[no_mangle]
pub unsafe extern "C" fn rmf_ph_convex_initial_normal(
    ph_spline: *const RmfCurve,
    profile: *const RmfCurve,
    elliptic: u32,
    initial_normal: *mut RmfVec3,
    margin: *mut f64,
) -> RmfStatus {
    guard("rmf_ph_convex_initial_normal", || {
        let spline = reference(ph_spline, "ph_spline")?;
        let profile = reference(profile, "profile")?;
        let initial_normal = out_ptr(initial_normal, "initial_normal")?;
        let margin = optional_out(margin, "margin")?;
        let start = convex_initial_normal(
            &spline.ph_spline("ph_spline")?,
            profile.rational("profile")?,
            elliptic != 0,
        )?;
        write(initial_normal, start.initial_normal.into());
        if let Some(m) = margin {
            write(m, start.margin);
        }
        Ok(())
    })
}

/// The offset of a planar profile at signed distance along its right-hand normal
/// (y', −x')/|c'| (the surface normal (10) of the sweep), exact and rational. By
/// Proposition 4 of Mäurer & Jüttler the offset of a profile surface is the profile surface
/// of the offset profile: sweep the result with the same spine and frames. Lines, circular
/// arcs and planar PH curves have rational offsets; other profiles are refused.
///
/// @param[in] profile The profile (x, y; z ignored, 0 in the result).
/// @param[in] distance Finite signed distance.
/// @param[out] out Receives the offset profile on the profile's parameter; free with
///             rmf_curve_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If profile or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If distance is not finite or the profile has a singular
///         point.
/// @return RMF_ERROR_NO_SOLUTION If a profile segment has no rational offset (the message
///         names it): rmf_profile_offset_by_arcs gives the exact offset of arcs within a
///         tolerance of it.
/// \since 0.1
/// \ingroup rmf_sweeps
#[no_mangle]
pub unsafe extern "C" fn rmf_profile_offset(
    profile: *const RmfCurve,
    distance: f64,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_profile_offset", || {
        let profile = reference(profile, "profile")?;
        let out = out_ptr(out, "out")?;
        let offset = offset_profile(profile.rational("profile")?, distance)?;
        write(out, RmfCurve::new(offset, None).into_raw());
        Ok(())
    })
}

/// The offset of any planar profile, exactly, through arcs: the profile is replaced by a G1
/// chain of circular arcs (biarcs, two rational quadratic arcs per interval) within tolerance,
/// refined until the profile's true offset is within tolerance of the arcs' offset too, and
/// the arcs are offset exactly (concentric arcs). For profiles that rmf_profile_offset
/// refuses: the offset of a general rational curve is not rational (its unit normal divides
/// by |c'| = √(x'² + y'²), a polynomial only for PH curves), so no NURBS is its exact offset;
/// this is the exact offset of a NURBS within tolerance of the profile. Sweep the result with
/// the same spine and frames for the offset surface (Proposition 4 of Mäurer & Jüttler).
///
/// @param[in] profile The profile (x, y; z ignored, 0 in the results), without singular
///            points.
/// @param[in] distance Finite signed distance along (y', −x')/|c'|.
/// @param[in] tolerance Finite positive length: the largest distance of the arcs from the
///            profile and of their offset from the profile's offset (measured on each
///            interval at 17 points and at the largest one's maximum).
/// @param[out] offset Receives the offset of the arcs; free with rmf_curve_free.
/// @param[out] arcs May be NULL. Receives the arcs, on the profile's domain; free with
///             rmf_curve_free.
/// @param[out] deviation May be NULL. Receives the largest distance measured (profile to
///             arcs, or true offset to offset).
/// @return RMF_OK on success; out-pointers are untouched on failure.
/// @return RMF_ERROR_NULL_POINTER If profile or offset is NULL.
/// @return RMF_ERROR_INVALID_INPUT If distance or tolerance is not finite (tolerance not
///         positive), or the profile has a singular point.
/// @return RMF_ERROR_NOT_CONVERGED If an interval halved 30 times still misses the tolerance.
/// \since 0.2
/// \ingroup rmf_sweeps
#[no_mangle]
pub unsafe extern "C" fn rmf_profile_offset_by_arcs(
    profile: *const RmfCurve,
    distance: f64,
    tolerance: f64,
    offset: *mut *mut RmfCurve,
    arcs: *mut *mut RmfCurve,
    deviation: *mut f64,
) -> RmfStatus {
    guard("rmf_profile_offset_by_arcs", || {
        let profile = reference(profile, "profile")?;
        let offset = out_ptr(offset, "offset")?;
        let arcs = optional_out(arcs, "arcs")?;
        let deviation = optional_out(deviation, "deviation")?;
        let result = offset_profile_by_arcs(profile.rational("profile")?, distance, tolerance)?;
        write(offset, RmfCurve::new(result.offset, None).into_raw());
        if let Some(arcs) = arcs {
            write(arcs, RmfCurve::new(result.arcs, None).into_raw());
        }
        if let Some(deviation) = deviation {
            write(
                deviation,
                result.profile_deviation.max(result.offset_deviation),
            );
        }
        Ok(())
    })
}

/// The three inputs of a sweep, with rational frames.
unsafe fn sweep_inputs<'a>(
    spine: *const RmfCurve,
    frames: *const RmfFrames,
    profile: *const RmfCurve,
) -> FfiResult<(FramedCurve, &'a PiecewiseCurve)> {
    let spine = reference(spine, "spine")?;
    let frames = reference(frames, "frames")?;
    let profile = reference(profile, "profile")?;
    Ok((framed_curve(spine, frames)?, profile.rational("profile")?))
}
