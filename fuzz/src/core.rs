//! Operations on the foundation's entry points: NURBS input curves and surfaces, their
//! views, evaluation and tessellation, double-reflection and Frenet frames, sweeps, and the
//! status helpers. Every capability's target mixes these in, so that its results are also
//! read back through every accessor.

// The deprecated C entry points are fuzzed for as long as they are exported.
#![allow(deprecated)]

use rmfsurf_capi::curve::*;
use rmfsurf_capi::frames::*;
use rmfsurf_capi::status::{rmf_status_name, rmf_version};
use rmfsurf_capi::surface::*;
use rmfsurf_capi::types::{RmfBezierCurve, RmfBezierPatch, RmfNurbsCurve, RmfNurbsSurface};
use rmfsurf_capi::RmfVec3;
use std::ptr::{null, null_mut};

use super::input::Input;
use super::session::{
    assert_frame, checked, is_poisoned, poisoned, poisoned_buffer, status_ok, tracing, Session,
};

/// The operations of this module.
pub const OPS: &[fn(&mut Session)] = &[
    nurbs_curve,
    curve_queries,
    curve_copy,
    nurbs_surface,
    surface_queries,
    surface_copy,
    tessellate,
    double_reflection,
    frenet,
    frames_queries,
    frames_vector_curve,
    sweep,
    status_names,
];

/// A weight array: NULL, arbitrary, or positive ordinary weights.
pub fn weights(input: &mut Input, n: usize) -> Option<Vec<f64>> {
    match input.byte() % 4 {
        0 => None,
        1 => Some(input.f64s(n)),
        _ => Some(
            (0..n)
                .map(|_| 0.1 + f64::from(input.byte()) / 64.0)
                .collect(),
        ),
    }
}

/// A knot vector for `poles` poles of `degree`: clamped uniform (valid), or drawn.
pub fn knots(input: &mut Input, degree: u32, poles: usize) -> Vec<f64> {
    let degree = degree as usize;
    if degree > 16 || input.below(3) == 0 {
        let n = input.len(20);
        return input.increasing(n);
    }
    let n = poles + degree + 1;
    let spans = poles.saturating_sub(degree).max(1);
    (0..n)
        .map(|i| (i.saturating_sub(degree).min(spans)) as f64)
        .collect()
}

/// A parameter in `[lo, hi]` (by a fraction), at its ends, or any double.
pub fn parameter(input: &mut Input, lo: f64, hi: f64) -> f64 {
    match input.byte() % 4 {
        0 => input.f64(),
        1 => lo,
        2 => hi,
        _ => lo + (hi - lo) * f64::from(input.byte()) / 255.0,
    }
}

/// A pointer to `data`, or NULL (when the input says so).
pub fn or_null<T>(input: &mut Input, data: &[T]) -> *const T {
    if input.byte() == 255 {
        null()
    } else {
        data.as_ptr()
    }
}

fn nurbs_curve(s: &mut Session) {
    let degree = s.input.code();
    let n = s.input.len(10);
    let poles = s.input.vec3s(n);
    let weights = weights(&mut s.input, n);
    let knots = knots(&mut s.input, degree, n);
    if tracing() {
        eprintln!(
            "nurbs curve: degree {degree}, poles {poles:?}, weights {weights:?}, knots {knots:?}"
        );
    }
    let mut out = poisoned();
    let status = unsafe {
        rmf_nurbs_curve_create(
            degree,
            or_null(&mut s.input, &poles),
            weights.as_ref().map_or(null(), |w| w.as_ptr()),
            n,
            or_null(&mut s.input, &knots),
            knots.len(),
            &mut out,
        )
    };
    s.made("rmf_nurbs_curve_create", status, Some(out), None);
}

/// Reads every entry of a borrowed NURBS curve view (AddressSanitizer checks the bounds).
fn read_curve_view(v: &RmfNurbsCurve) {
    assert!(v.pole_count > v.degree as usize);
    assert_eq!(v.knot_count, v.pole_count + v.degree as usize + 1);
    let poles = unsafe { std::slice::from_raw_parts(v.poles, v.pole_count) };
    let weights = unsafe { std::slice::from_raw_parts(v.weights, v.pole_count) };
    let knots = unsafe { std::slice::from_raw_parts(v.knots, v.knot_count) };
    assert!(weights.iter().all(|w| *w > 0.0), "weights {weights:?}");
    assert!(knots.windows(2).all(|k| k[0] <= k[1]), "knots {knots:?}");
    std::hint::black_box(poles.iter().map(|p| p.x + p.y + p.z).sum::<f64>());
}

fn curve_queries(s: &mut Session) {
    let c = s.curve();
    let (mut lo, mut hi) = (poisoned::<f64>(), poisoned::<f64>());
    let status = unsafe { rmf_curve_domain(c, &mut lo, &mut hi) };
    let (lo, hi) = if checked(
        "rmf_curve_domain",
        status,
        &[is_poisoned(&lo), is_poisoned(&hi)],
    ) {
        assert!(
            lo.is_finite() && hi.is_finite() && lo < hi,
            "domain {lo} {hi}"
        );
        (lo, hi)
    } else {
        (0.0, 1.0)
    };
    let t = parameter(&mut s.input, lo, hi);
    let (mut p, mut d) = (poisoned::<RmfVec3>(), poisoned::<RmfVec3>());
    let want_d = s.input.flag();
    let dp: *mut RmfVec3 = if want_d { &mut d } else { null_mut() };
    let status = unsafe { rmf_curve_eval(c, t, &mut p, dp) };
    checked(
        "rmf_curve_eval",
        status,
        &[is_poisoned(&p), is_poisoned(&d)],
    );
    let mut view = poisoned::<RmfNurbsCurve>();
    let status = unsafe { rmf_curve_nurbs(c, &mut view) };
    if checked("rmf_curve_nurbs", status, &[is_poisoned(&view)]) {
        read_curve_view(&view);
    }
    let mut count = poisoned::<usize>();
    let status = unsafe { rmf_curve_segment_count(c, &mut count) };
    let count = if checked("rmf_curve_segment_count", status, &[is_poisoned(&count)]) {
        count
    } else {
        0
    };
    let index = match s.input.byte() {
        255 => usize::MAX,
        b => usize::from(b) % (count + 1),
    };
    let mut segment = poisoned::<RmfBezierCurve>();
    let status = unsafe { rmf_curve_segment(c, index, &mut segment) };
    if checked("rmf_curve_segment", status, &[is_poisoned(&segment)]) {
        assert!(index < count);
        let n = segment.degree as usize + 1;
        let w = unsafe { std::slice::from_raw_parts(segment.weights, n) };
        let p = unsafe { std::slice::from_raw_parts(segment.poles, n) };
        assert!(w.iter().all(|w| *w > 0.0) && segment.t_start < segment.t_end);
        std::hint::black_box(p.iter().map(|p| p.x).sum::<f64>());
    }
}

fn curve_copy(s: &mut Session) {
    let c = s.curve();
    let (pole_capacity, knot_capacity) = (s.input.work().min(64), s.input.work().min(64));
    let mut poles = poisoned_buffer::<RmfVec3>(pole_capacity);
    let mut weights = poisoned_buffer::<f64>(pole_capacity);
    let mut knots = poisoned_buffer::<f64>(knot_capacity);
    let (mut degree, mut pole_count, mut knot_count) = (poisoned(), poisoned(), poisoned());
    let status = unsafe {
        rmf_curve_nurbs_copy(
            c,
            &mut degree,
            poles.as_mut_ptr(),
            weights.as_mut_ptr(),
            pole_capacity,
            knots.as_mut_ptr(),
            knot_capacity,
            &mut pole_count,
            &mut knot_count,
        )
    };
    let too_small = status == rmfsurf_capi::RmfStatus::RmfErrorBufferTooSmall;
    checked(
        "rmf_curve_nurbs_copy",
        status,
        &[
            is_poisoned(&degree) || too_small,
            poles.iter().all(is_poisoned),
            weights.iter().all(is_poisoned),
            knots.iter().all(is_poisoned),
        ],
    );
}

fn nurbs_surface(s: &mut Session) {
    let (du, dv) = (s.input.code(), s.input.code());
    let (nu, nv) = (s.input.len(5), s.input.len(5));
    let poles = s.input.vec3s(nu * nv);
    let weights = weights(&mut s.input, nu * nv);
    let (ku, kv) = (knots(&mut s.input, du, nu), knots(&mut s.input, dv, nv));
    let mut out = poisoned();
    let poles = or_null(&mut s.input, &poles);
    let weights = weights.as_ref().map_or(null(), |w| w.as_ptr());
    let status = unsafe {
        rmf_nurbs_surface_create(
            du,
            dv,
            poles,
            weights,
            nu,
            nv,
            ku.as_ptr(),
            ku.len(),
            kv.as_ptr(),
            kv.len(),
            &mut out,
        )
    };
    // Checked first: the call below overwrites the last error.
    s.made_surface("rmf_nurbs_surface_create", status, out);
    // The same data in one struct (no input drawn: the corpus keeps its meaning) must give
    // the same status, and write nothing on failure.
    let data = RmfNurbsSurfaceData {
        struct_size: std::mem::size_of::<RmfNurbsSurfaceData>(),
        degree_u: du,
        degree_v: dv,
        pole_count_u: nu,
        pole_count_v: nv,
        poles,
        weights,
        knot_count_u: ku.len(),
        knots_u: ku.as_ptr(),
        knot_count_v: kv.len(),
        knots_v: kv.as_ptr(),
    };
    let mut from = poisoned();
    let from_status = unsafe { rmf_nurbs_surface_create_from(&data, &mut from) };
    assert_eq!(
        from_status, status,
        "rmf_nurbs_surface_create_from differs from rmf_nurbs_surface_create"
    );
    if checked(
        "rmf_nurbs_surface_create_from",
        from_status,
        &[is_poisoned(&from)],
    ) {
        unsafe { rmf_surface_free(from) };
    }
}

fn surface_queries(s: &mut Session) {
    let surface = s.surface();
    let mut d = [poisoned::<f64>(); 4];
    let [a, b, c, e] = &mut d;
    let status = unsafe { rmf_surface_domain(surface, a, b, c, e) };
    let domain = if checked("rmf_surface_domain", status, &[d.iter().all(is_poisoned)]) {
        assert!(d[0] < d[1] && d[2] < d[3], "domain {d:?}");
        d
    } else {
        [0.0, 1.0, 0.0, 1.0]
    };
    let u = parameter(&mut s.input, domain[0], domain[1]);
    let v = parameter(&mut s.input, domain[2], domain[3]);
    let mut out = [poisoned::<RmfVec3>(); 3];
    let [p, du, dv] = &mut out;
    let status = unsafe { rmf_surface_eval(surface, u, v, p, du, dv) };
    checked("rmf_surface_eval", status, &[out.iter().all(is_poisoned)]);
    let mut view = poisoned::<RmfNurbsSurface>();
    let status = unsafe { rmf_surface_nurbs(surface, &mut view) };
    if checked("rmf_surface_nurbs", status, &[is_poisoned(&view)]) {
        let n = view.pole_count_u * view.pole_count_v;
        let w = unsafe { std::slice::from_raw_parts(view.weights, n) };
        let ku = unsafe { std::slice::from_raw_parts(view.knots_u, view.knot_count_u) };
        let kv = unsafe { std::slice::from_raw_parts(view.knots_v, view.knot_count_v) };
        assert!(w.iter().all(|w| *w > 0.0));
        assert_eq!(ku.len(), view.pole_count_u + view.degree_u as usize + 1);
        assert_eq!(kv.len(), view.pole_count_v + view.degree_v as usize + 1);
        let p = unsafe { std::slice::from_raw_parts(view.poles, n) };
        std::hint::black_box(p.iter().map(|p| p.x).sum::<f64>());
    }
    let (mut cu, mut cv) = (poisoned::<usize>(), poisoned::<usize>());
    let status = unsafe { rmf_surface_patch_count(surface, &mut cu, &mut cv) };
    let (cu, cv) = if checked(
        "rmf_surface_patch_count",
        status,
        &[is_poisoned(&cu), is_poisoned(&cv)],
    ) {
        (cu, cv)
    } else {
        (0, 0)
    };
    let (iu, iv) = (s.input.below(cu + 2), s.input.below(cv + 2));
    let mut patch = poisoned::<RmfBezierPatch>();
    let status = unsafe { rmf_surface_patch(surface, iu, iv, &mut patch) };
    if checked("rmf_surface_patch", status, &[is_poisoned(&patch)]) {
        let n = (patch.degree_u as usize + 1) * (patch.degree_v as usize + 1);
        let w = unsafe { std::slice::from_raw_parts(patch.weights, n) };
        assert!(w.iter().all(|w| *w > 0.0));
    }
}

fn surface_copy(s: &mut Session) {
    let surface = s.surface();
    let pc = s.input.work().min(400);
    let (kcu, kcv) = (s.input.work().min(64), s.input.work().min(64));
    let mut poles = poisoned_buffer::<RmfVec3>(pc);
    let mut weights = poisoned_buffer::<f64>(pc);
    let (mut ku, mut kv) = (poisoned_buffer::<f64>(kcu), poisoned_buffer::<f64>(kcv));
    let (mut du, mut dv) = (poisoned(), poisoned());
    let mut counts = [poisoned::<usize>(); 4];
    let [a, b, c, d] = &mut counts;
    let status = unsafe {
        rmf_surface_nurbs_copy(
            surface,
            &mut du,
            &mut dv,
            poles.as_mut_ptr(),
            weights.as_mut_ptr(),
            pc,
            ku.as_mut_ptr(),
            kcu,
            kv.as_mut_ptr(),
            kcv,
            a,
            b,
            c,
            d,
        )
    };
    let too_small = status == rmfsurf_capi::RmfStatus::RmfErrorBufferTooSmall;
    let copied = checked(
        "rmf_surface_nurbs_copy",
        status,
        &[
            (is_poisoned(&du) && is_poisoned(&dv)) || too_small,
            poles.iter().all(is_poisoned) && weights.iter().all(is_poisoned),
            ku.iter().all(is_poisoned) && kv.iter().all(is_poisoned),
        ],
    );
    // The same capacities through rmf_surface_nurbs_copy_into (no input drawn): the same
    // status, and on success the same degrees, counts and data.
    let mut poles2 = poisoned_buffer::<RmfVec3>(pc);
    let mut weights2 = poisoned_buffer::<f64>(pc);
    let (mut ku2, mut kv2) = (poisoned_buffer::<f64>(kcu), poisoned_buffer::<f64>(kcv));
    let buffers = RmfNurbsSurfaceBuffers {
        struct_size: std::mem::size_of::<RmfNurbsSurfaceBuffers>(),
        poles: poles2.as_mut_ptr(),
        weights: weights2.as_mut_ptr(),
        pole_capacity: pc,
        knots_u: ku2.as_mut_ptr(),
        knot_capacity_u: kcu,
        knots_v: kv2.as_mut_ptr(),
        knot_capacity_v: kcv,
    };
    let mut copy = poisoned::<RmfNurbsSurface>();
    let into = unsafe { rmf_surface_nurbs_copy_into(surface, &buffers, &mut copy) };
    assert_eq!(
        into, status,
        "rmf_surface_nurbs_copy_into differs from rmf_surface_nurbs_copy"
    );
    checked(
        "rmf_surface_nurbs_copy_into",
        into,
        &[
            is_poisoned(&copy) || too_small,
            poles2.iter().all(is_poisoned) && weights2.iter().all(is_poisoned),
            ku2.iter().all(is_poisoned) && kv2.iter().all(is_poisoned),
        ],
    );
    if copied || too_small {
        assert_eq!(
            (copy.degree_u, copy.degree_v),
            (du, dv),
            "rmf_surface_nurbs_copy_into: degrees"
        );
        assert_eq!(
            [
                copy.pole_count_u,
                copy.pole_count_v,
                copy.knot_count_u,
                copy.knot_count_v
            ],
            counts,
            "rmf_surface_nurbs_copy_into: counts"
        );
    }
    if copied {
        let same = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits());
        let p = |v: &[RmfVec3]| v.iter().flat_map(|p| [p.x, p.y, p.z]).collect::<Vec<f64>>();
        assert!(
            same(&p(&poles), &p(&poles2))
                && same(&weights, &weights2)
                && same(&ku, &ku2)
                && same(&kv, &kv2),
            "rmf_surface_nurbs_copy_into copied other data than rmf_surface_nurbs_copy"
        );
    }
}

fn tessellate(s: &mut Session) {
    let surface = s.surface();
    let (us, vs) = (s.input.code(), s.input.code());
    let (pc, tc) = (s.input.work().min(1024), s.input.work().min(4096));
    let mut points = poisoned_buffer::<RmfVec3>(pc);
    // triangle_capacity counts triangles, of 3 indices each
    let mut triangles = poisoned_buffer::<u32>(3 * tc);
    let (mut np, mut nt) = (poisoned::<usize>(), poisoned::<usize>());
    let status = unsafe {
        rmf_surface_tessellate(
            surface,
            us,
            vs,
            points.as_mut_ptr(),
            pc,
            triangles.as_mut_ptr(),
            tc,
            &mut np,
            &mut nt,
        )
    };
    if checked(
        "rmf_surface_tessellate",
        status,
        &[
            points.iter().all(is_poisoned),
            triangles.iter().all(is_poisoned),
        ],
    ) && pc > 0
    {
        let used = &triangles[..(3 * nt).min(3 * tc)];
        assert!(
            used.iter().all(|&i| (i as usize) < np),
            "triangle index out of range"
        );
    }
}

fn double_reflection(s: &mut Session) {
    let c = s.curve();
    let normal = s.input.vec3();
    let samples = s.input.work();
    if tracing() {
        eprintln!("double reflection: normal {normal:?}, {samples} samples");
    }
    let mut out = poisoned();
    let status = unsafe { rmf_double_reflection_frames(c, normal, samples, &mut out) };
    s.made("rmf_double_reflection_frames", status, None, Some(out));
}

fn frenet(s: &mut Session) {
    let c = s.curve();
    let mut out = poisoned();
    let status = unsafe { rmf_frenet_frames(c, &mut out) };
    s.made("rmf_frenet_frames", status, None, Some(out));
}

/// Evaluates frames at `t` and checks they are orthonormal when the call succeeds.
fn eval_frames(frames: *const rmfsurf_capi::RmfFrames, t: f64) {
    let mut out = [poisoned::<RmfVec3>(); 3];
    let [a, b, c] = &mut out;
    let status = unsafe { rmf_frames_eval(frames, t, a, b, c) };
    if checked("rmf_frames_eval", status, &[out.iter().all(is_poisoned)]) {
        assert_frame("rmf_frames_eval", out[0], out[1], out[2]);
    }
}

fn frames_queries(s: &mut Session) {
    let f = s.frames();
    let (mut lo, mut hi) = (poisoned::<f64>(), poisoned::<f64>());
    let status = unsafe { rmf_frames_domain(f, &mut lo, &mut hi) };
    let (lo, hi) = if checked(
        "rmf_frames_domain",
        status,
        &[is_poisoned(&lo), is_poisoned(&hi)],
    ) {
        (lo, hi)
    } else {
        (0.0, 1.0)
    };
    for _ in 0..1 + s.input.below(4) {
        let t = parameter(&mut s.input, lo, hi);
        if tracing() {
            eprintln!("frames at t = {t:e} in [{lo:e}, {hi:e}]");
        }
        eval_frames(f, t);
    }
    let mut kind = poisoned::<u32>();
    let status = unsafe { rmf_frames_kind(f, &mut kind) };
    if checked("rmf_frames_kind", status, &[is_poisoned(&kind)]) {
        assert!(kind <= RMF_FRAMES_FRENET);
    }
}

fn frames_vector_curve(s: &mut Session) {
    let f = s.frames();
    let which = s.input.code();
    let mut out = poisoned();
    let status = unsafe { rmf_frames_vector_curve(f, which, &mut out) };
    s.made("rmf_frames_vector_curve", status, Some(out), None);
}

fn sweep(s: &mut Session) {
    let (spine, frames, profile) = (s.curve(), s.frames(), s.curve());
    let mut out = poisoned();
    let status = unsafe { rmf_sweep_surface(spine, frames, profile, &mut out) };
    s.made_surface("rmf_sweep_surface", status, out);
}

fn status_names(s: &mut Session) {
    let code = s.input.code();
    let name = unsafe { std::ffi::CStr::from_ptr(rmf_status_name(code)) };
    assert!(!name.to_bytes().is_empty());
    let version = unsafe { std::ffi::CStr::from_ptr(rmf_version()) };
    assert!(version.to_bytes().starts_with(b"0."));
    // A failure with a NULL argument, to exercise the last-error path.
    let status = unsafe { rmf_curve_domain(null(), null_mut(), null_mut()) };
    assert!(!status_ok("rmf_curve_domain", status));
}
