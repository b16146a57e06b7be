//! Operations on the PH cubic entry points (Mäurer & Jüttler): Hermite interpolation,
//! splines, approximation of curves and callbacks, rational, twisted, Frenet and exact
//! RMFs, angle errors, and the profile-surface analysis.

use rmfsurf_capi::ph_cubic::*;
use rmfsurf_capi::{RmfCurve, RmfStatus, RmfVec3};
use std::ptr::null_mut;

use super::callback::CallbackCurve;
use super::core::{or_null, parameter};
use super::session::{checked, is_poisoned, poisoned, poisoned_buffer, tracing, Session};

/// The operations of this module.
pub const OPS: &[fn(&mut Session)] = &[
    cubic_hermite,
    spline_hermite,
    spline_hermite,
    spline_approximate,
    rational_rmf,
    rational_rmf,
    twisted_rmf,
    frenet,
    exact_rmf,
    angle_error,
    singularity_margin,
    gaussian_curvature,
    parabolic_points,
    parabolic_curves,
    convex_initial_normal,
    profile_offset,
    profile_offset_by_arcs,
    spline_approximate_with_options,
];

fn cubic_hermite(s: &mut Session) {
    let (p0, t0, p1, t1) = (
        s.input.vec3(),
        s.input.vec3(),
        s.input.vec3(),
        s.input.vec3(),
    );
    if tracing() {
        eprintln!("PH cubic through {p0:?} {t0:?} {p1:?} {t1:?}");
    }
    let (mut a, mut b) = (poisoned(), poisoned());
    let want_other = s.input.flag();
    let other: *mut *mut _ = if want_other { &mut b } else { null_mut() };
    let status = unsafe { rmf_ph_cubic_hermite(p0, t0, p1, t1, &mut a, other) };
    s.made("rmf_ph_cubic_hermite", status, Some(a), None);
    // The other root may not exist: NULL then, even on success.
    if want_other && !b.is_null() {
        s.made("rmf_ph_cubic_hermite", status, Some(b), None);
    }
}

/// Points and tangents for a Hermite spline: drawn freely or from the input's relations.
pub fn hermite_data(s: &mut Session) -> (Vec<RmfVec3>, Vec<RmfVec3>, usize) {
    let n = s.input.len(8);
    let points = s.input.vec3s(n);
    let tangents = s.input.vec3s(n);
    let count = if s.input.byte() == 255 { n + 1 } else { n };
    (points, tangents, count.min(n))
}

fn spline_hermite(s: &mut Session) {
    let (points, tangents, n) = hermite_data(s);
    let mut out = poisoned();
    let status = unsafe {
        rmf_ph_spline_hermite(
            or_null(&mut s.input, &points),
            or_null(&mut s.input, &tangents),
            n,
            &mut out,
        )
    };
    s.made("rmf_ph_spline_hermite", status, Some(out), None);
}

fn spline_approximate(s: &mut Session) {
    let mut source = CallbackCurve::draw(&mut s.input);
    let curve = s.curve();
    let (callback, user) = source.callback_if(s.input.flag());
    let (t_min, t_max, tolerance) = (s.input.f64(), s.input.f64(), s.input.f64());
    if tracing() {
        eprintln!(
            "approximate on [{t_min:e}, {t_max:e}] within {tolerance:e}, callback {}",
            callback.is_some()
        );
    }
    let mut out = poisoned();
    let mut distance = poisoned::<f64>();
    let status = unsafe {
        rmf_ph_spline_approximate(
            curve,
            callback,
            user,
            t_min,
            t_max,
            tolerance,
            &mut out,
            &mut distance,
        )
    };
    if s.made("rmf_ph_spline_approximate", status, Some(out), None) {
        assert!(
            distance.is_finite() && distance >= 0.0,
            "distance {distance}"
        );
    } else {
        assert!(is_poisoned(&distance), "distance written on failure");
    }
}

/// The options-struct form: a curve of the pool (NURBS, computed or callback), options with
/// any tolerance and caps (and now and then a wrong struct_size), and a report that is
/// written on success only.
fn spline_approximate_with_options(s: &mut Session) {
    let curve = s.curve();
    let mut options = RmfPhApproximationOptions::default();
    unsafe { rmf_ph_approximation_options_init(&mut options) };
    options.tolerance = s.input.f64();
    options.max_segments = s.input.work();
    options.max_evaluations = if s.input.flag() {
        s.input.work()
    } else {
        usize::MAX
    };
    if s.input.byte() == 255 {
        options.struct_size = s.input.work();
    }
    let mut report = poisoned::<RmfPhApproximationReport>();
    report.struct_size = if s.input.byte() == 255 {
        s.input.work()
    } else {
        std::mem::size_of::<RmfPhApproximationReport>()
    };
    if tracing() {
        eprintln!("approximate with {options:?}");
    }
    let mut out = poisoned();
    let status =
        unsafe { rmf_ph_spline_approximate_with_options(curve, &options, &mut out, &mut report) };
    if s.made(
        "rmf_ph_spline_approximate_with_options",
        status,
        Some(out),
        None,
    ) {
        assert!(
            report.max_distance >= 0.0 && report.max_distance <= options.tolerance,
            "{report:?}"
        );
        assert!(report.segments >= 1 && report.segments <= options.max_segments);
        assert!(report.evaluations <= options.max_evaluations, "{report:?}");
    } else {
        assert!(
            is_poisoned(&report.max_distance) && is_poisoned(&report.segments),
            "report written on failure"
        );
    }
}

fn rational_rmf(s: &mut Session) {
    let (spline, normal) = (s.curve(), s.input.vec3());
    let mut out = poisoned();
    let status = unsafe { rmf_ph_rational_rmf(spline, normal, &mut out) };
    s.made("rmf_ph_rational_rmf", status, None, Some(out));
}

fn twisted_rmf(s: &mut Session) {
    let (spline, normal, twist, symmetry) =
        (s.curve(), s.input.vec3(), s.input.f64(), s.input.code());
    let mut out = poisoned();
    let status = unsafe { rmf_ph_rational_rmf_twisted(spline, normal, twist, symmetry, &mut out) };
    s.made("rmf_ph_rational_rmf_twisted", status, None, Some(out));
}

fn frenet(s: &mut Session) {
    let spline = s.curve();
    let mut out = poisoned();
    let status = unsafe { rmf_ph_frenet_frames(spline, &mut out) };
    s.made("rmf_ph_frenet_frames", status, None, Some(out));
}

fn exact_rmf(s: &mut Session) {
    let (spline, normal) = (s.curve(), s.input.vec3());
    let n = s.input.len(6);
    let t: Vec<f64> = (0..n).map(|_| parameter(&mut s.input, 0.0, 1.0)).collect();
    if tracing() {
        eprintln!("exact RMF from {normal:?} at {t:?}");
    }
    let mut f2 = poisoned_buffer::<RmfVec3>(n);
    let mut f3 = poisoned_buffer::<RmfVec3>(n);
    let f3_ptr = if s.input.flag() {
        f3.as_mut_ptr()
    } else {
        null_mut()
    };
    let status =
        unsafe { rmf_ph_exact_rmf_eval(spline, normal, t.as_ptr(), n, f2.as_mut_ptr(), f3_ptr) };
    if checked(
        "rmf_ph_exact_rmf_eval",
        status,
        &[f2.iter().all(is_poisoned) && f3.iter().all(is_poisoned)],
    ) {
        for v in &f2 {
            let norm = (v.x * v.x + v.y * v.y + v.z * v.z).sqrt();
            assert!((norm - 1.0).abs() < 1e-6, "f2 = {v:?} is not a unit vector");
        }
    }
}

fn angle_error(s: &mut Session) {
    let frames = s.frames();
    let capacity = s.input.work().min(64);
    let mut per_segment = poisoned_buffer::<f64>(capacity);
    let (mut count, mut max) = (poisoned::<usize>(), poisoned::<f64>());
    let max_ptr: *mut f64 = if s.input.flag() { &mut max } else { null_mut() };
    let status = unsafe {
        rmf_ph_rmf_angle_error(
            frames,
            per_segment.as_mut_ptr(),
            capacity,
            &mut count,
            max_ptr,
        )
    };
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    checked(
        "rmf_ph_rmf_angle_error",
        status,
        &[
            per_segment.iter().all(is_poisoned),
            is_poisoned(&count) || too_small,
            is_poisoned(&max),
        ],
    );
}

fn singularity_margin(s: &mut Session) {
    let (spine, frames, profile) = (s.curve(), s.frames(), s.curve());
    let mut out = poisoned::<RmfSingularityMargin>();
    let status = unsafe { rmf_sweep_singularity_margin(spine, frames, profile, &mut out) };
    checked("rmf_sweep_singularity_margin", status, &[is_poisoned(&out)]);
}

fn gaussian_curvature(s: &mut Session) {
    let (spine, frames, profile) = (s.curve(), s.frames(), s.curve());
    let (u, v) = (
        parameter(&mut s.input, 0.0, 1.0),
        parameter(&mut s.input, 0.0, 1.0),
    );
    let mut k = poisoned::<f64>();
    let status = unsafe { rmf_sweep_gaussian_curvature(spine, frames, profile, u, v, &mut k) };
    checked("rmf_sweep_gaussian_curvature", status, &[is_poisoned(&k)]);
}

fn parabolic_points(s: &mut Session) {
    let (spine, frames, profile) = (s.curve(), s.frames(), s.curve());
    let samples = u32::try_from(s.input.work()).unwrap_or(u32::MAX);
    let capacity = s.input.work().min(256);
    let mut points = poisoned_buffer::<RmfParabolicPoint>(capacity);
    let mut count = poisoned::<usize>();
    let status = unsafe {
        rmf_sweep_parabolic_points(
            spine,
            frames,
            profile,
            samples,
            points.as_mut_ptr(),
            capacity,
            &mut count,
        )
    };
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    checked(
        "rmf_sweep_parabolic_points",
        status,
        &[
            points.iter().all(is_poisoned),
            is_poisoned(&count) || too_small,
        ],
    );
}

/// The traced parabolic lines at any tolerance (tiny ones run into the vertex bound).
fn parabolic_curves(s: &mut Session) {
    let (spine, frames, profile) = (s.curve(), s.frames(), s.curve());
    let tolerance = s.input.f64();
    let capacity = s.input.work().min(256);
    let mut points = poisoned_buffer::<RmfParabolicCurvePoint>(capacity);
    let mut count = poisoned::<usize>();
    let status = unsafe {
        rmf_sweep_parabolic_curves(
            spine,
            frames,
            profile,
            tolerance,
            points.as_mut_ptr(),
            capacity,
            &mut count,
        )
    };
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    checked(
        "rmf_sweep_parabolic_curves",
        status,
        &[
            points.iter().all(is_poisoned),
            is_poisoned(&count) || too_small,
        ],
    );
}

fn convex_initial_normal(s: &mut Session) {
    let (spline, profile, elliptic) = (s.curve(), s.curve(), s.input.code());
    let (mut normal, mut margin) = (poisoned::<RmfVec3>(), poisoned::<f64>());
    let margin_ptr: *mut f64 = if s.input.flag() {
        &mut margin
    } else {
        null_mut()
    };
    let status =
        unsafe { rmf_ph_convex_initial_normal(spline, profile, elliptic, &mut normal, margin_ptr) };
    checked(
        "rmf_ph_convex_initial_normal",
        status,
        &[is_poisoned(&normal), is_poisoned(&margin)],
    );
}

fn profile_offset_by_arcs(s: &mut Session) {
    let (profile, distance, tolerance) = (s.curve(), s.input.f64(), s.input.f64());
    let (mut out, mut arcs, mut deviation) = (poisoned(), poisoned(), poisoned::<f64>());
    let arcs_ptr: *mut *mut RmfCurve = if s.input.flag() {
        &mut arcs
    } else {
        null_mut()
    };
    let status = unsafe {
        rmf_profile_offset_by_arcs(
            profile,
            distance,
            tolerance,
            &mut out,
            arcs_ptr,
            &mut deviation,
        )
    };
    if s.made("rmf_profile_offset_by_arcs", status, Some(out), None) {
        assert!(
            deviation <= tolerance,
            "deviation {deviation} above tolerance {tolerance}"
        );
    }
    if !arcs_ptr.is_null() {
        s.made("rmf_profile_offset_by_arcs", status, Some(arcs), None);
    }
}

fn profile_offset(s: &mut Session) {
    let (profile, distance) = (s.curve(), s.input.f64());
    let mut out = poisoned();
    let status = unsafe { rmf_profile_offset(profile, distance, &mut out) };
    s.made("rmf_profile_offset", status, Some(out), None);
}
