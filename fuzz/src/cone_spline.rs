//! Operations on the cone spline entry points (Leopoldseder & Pottmann): Hermite cone
//! pairs, the three approximations and osculating cones, pieces, surfaces, boundaries,
//! bending, development, offsets and the fit reports.

// The deprecated C entry points are fuzzed for as long as they are exported.
#![allow(deprecated)]

use rmfsurf_capi::cone_spline::*;
use rmfsurf_capi::RmfStatus;
use std::ptr::{null, null_mut};

use super::callback::CallbackCurve;
use super::core::{knots, or_null};
use super::session::{checked, is_poisoned, poisoned, poisoned_buffer, Session};

/// The operations of this module.
pub const OPS: &[fn(&mut Session)] = &[
    hermite,
    hermite,
    approximate,
    approximate_ruled,
    approximate_dual,
    osculating,
    pieces,
    surface,
    bounds_and_boundary,
    derived,
    fit_report,
];

/// A region of interest, or NULL.
fn region(s: &mut Session) -> Option<RmfBox> {
    (s.input.below(4) != 0).then(|| RmfBox {
        min: s.input.vec3(),
        max: s.input.vec3(),
    })
}

fn hermite(s: &mut Session) {
    let n = s.input.len(6);
    let elements: Vec<RmfConeElement> = (0..n)
        .map(|_| RmfConeElement {
            point: s.input.vec3(),
            ruling: s.input.vec3(),
            side: s.input.vec3(),
        })
        .collect();
    let (rule, parameter, region) = (s.input.code(), s.input.f64(), region(s));
    let mut out = poisoned();
    let status = unsafe {
        rmf_cone_spline_hermite(
            or_null(&mut s.input, &elements),
            n,
            rule,
            parameter,
            region.as_ref().map_or(null(), |r| r as *const RmfBox),
            &mut out,
        )
    };
    s.made_spline("rmf_cone_spline_hermite", status, out);
}

/// Checks the optional `max_error` out-value of an approximation.
fn fit_made(s: &mut Session, function: &str, status: RmfStatus, out: *mut RmfConeSpline, e: f64) {
    let ok = status == RmfStatus::RmfOk;
    s.made_spline(function, status, out);
    if ok {
        assert!(e.is_finite() && e >= 0.0, "{function}: max_error = {e}");
    } else {
        assert!(is_poisoned(&e), "{function}: max_error written on failure");
    }
}

fn approximate(s: &mut Session) {
    let mut source = CallbackCurve::draw(&mut s.input);
    let curve = s.curve();
    let (callback, user) = source.callback_if(s.input.flag());
    let [t_min, t_max, v_min, v_max, tolerance] = [(); 5].map(|_| s.input.f64());
    let (rule, max_pieces) = (s.input.code(), s.input.work());
    let (mut out, mut e) = (poisoned(), poisoned::<f64>());
    let status = unsafe {
        rmf_cone_spline_approximate(
            curve, callback, user, t_min, t_max, v_min, v_max, tolerance, rule, max_pieces,
            &mut out, &mut e,
        )
    };
    // Checked first: the call below overwrites the last error.
    fit_made(s, "rmf_cone_spline_approximate", status, out, e);
    if callback.is_none() {
        // The curve handle through the options struct: the same status and fit.
        let options = fit_options(tolerance, rule, max_pieces);
        let (mut out2, mut e2) = (poisoned(), poisoned::<f64>());
        let status2 = unsafe {
            rmf_cone_spline_approximate_with_options(
                curve, v_min, v_max, &options, &mut out2, &mut e2,
            )
        };
        same_fit(
            "rmf_cone_spline_approximate_with_options",
            (status, e),
            (status2, out2, e2),
        );
    }
}

/// The options struct of the 0.2 entry points holding the arguments of a 0.1 call.
fn fit_options(tolerance: f64, rule: u32, max_pieces: usize) -> RmfConeApproximationOptions {
    RmfConeApproximationOptions {
        struct_size: std::mem::size_of::<RmfConeApproximationOptions>(),
        tolerance,
        rule,
        max_pieces,
    }
}

/// A 0.2 entry point (`function`) gave what the deprecated call it replaces gave: the same
/// status, the same max_error on success (bit for bit: the same code ran), and nothing
/// written on failure. Its spline is freed here.
fn same_fit(
    function: &str,
    (status, e): (RmfStatus, f64),
    (status2, out2, e2): (RmfStatus, *mut RmfConeSpline, f64),
) {
    assert_eq!(
        status2, status,
        "{function} differs from the call it replaces"
    );
    if checked(function, status2, &[is_poisoned(&out2), is_poisoned(&e2)]) {
        assert_eq!(e2.to_bits(), e.to_bits(), "{function}: max_error");
        unsafe { rmf_cone_spline_free(out2) };
    }
}

fn approximate_ruled(s: &mut Session) {
    let surface = s.surface();
    let (tolerance, rule, max_pieces) = (s.input.f64(), s.input.code(), s.input.work());
    let (mut out, mut e) = (poisoned(), poisoned::<f64>());
    let status = unsafe {
        rmf_cone_spline_approximate_ruled(surface, tolerance, rule, max_pieces, &mut out, &mut e)
    };
    fit_made(s, "rmf_cone_spline_approximate_ruled", status, out, e);
}

fn approximate_dual(s: &mut Session) {
    let degree = s.input.code();
    let n = s.input.len(6);
    let planes = s.input.f64s(4 * n);
    let knots = knots(&mut s.input, degree, n);
    let region = region(s);
    let (tolerance, rule, max_pieces) = (s.input.f64(), s.input.code(), s.input.work());
    let (mut out, mut e) = (poisoned(), poisoned::<f64>());
    let planes = or_null(&mut s.input, &planes);
    let region = region.as_ref().map_or(null(), |r| r as *const RmfBox);
    let status = unsafe {
        rmf_cone_spline_approximate_dual(
            degree,
            planes,
            n,
            knots.as_ptr(),
            knots.len(),
            region,
            tolerance,
            rule,
            max_pieces,
            &mut out,
            &mut e,
        )
    };
    // Checked first: the call below overwrites the last error.
    fit_made(s, "rmf_cone_spline_approximate_dual", status, out, e);
    let options = fit_options(tolerance, rule, max_pieces);
    let (mut out2, mut e2) = (poisoned(), poisoned::<f64>());
    let status2 = unsafe {
        rmf_cone_spline_approximate_dual_with_options(
            degree,
            planes,
            n,
            knots.as_ptr(),
            knots.len(),
            region,
            &options,
            &mut out2,
            &mut e2,
        )
    };
    same_fit(
        "rmf_cone_spline_approximate_dual_with_options",
        (status, e),
        (status2, out2, e2),
    );
}

fn osculating(s: &mut Session) {
    let mut source = CallbackCurve::draw(&mut s.input);
    let curve = s.curve();
    let (callback, user) = source.callback_if(s.input.flag());
    let [t_min, t_max, v_min, v_max] = [(); 4].map(|_| s.input.f64());
    let n = s.input.len(8);
    let parameters = s.input.increasing(n);
    let mut out = poisoned();
    let parameters = or_null(&mut s.input, &parameters);
    let status = unsafe {
        rmf_cone_spline_osculating(
            curve, callback, user, t_min, t_max, v_min, v_max, parameters, n, &mut out,
        )
    };
    // Checked first: the call below overwrites the last error.
    s.made_spline("rmf_cone_spline_osculating", status, out);
    if callback.is_none() {
        // The curve handle alone: the same status, nothing written on failure.
        let mut out2 = poisoned();
        let status2 = unsafe {
            rmf_cone_spline_osculating_curve(curve, v_min, v_max, parameters, n, &mut out2)
        };
        assert_eq!(status2, status, "rmf_cone_spline_osculating_curve differs");
        if checked(
            "rmf_cone_spline_osculating_curve",
            status2,
            &[is_poisoned(&out2)],
        ) {
            unsafe { rmf_cone_spline_free(out2) };
        }
    }
}

fn pieces(s: &mut Session) {
    let spline = s.spline();
    let mut count = poisoned::<usize>();
    let status = unsafe { rmf_cone_spline_piece_count(spline, &mut count) };
    let count = if checked(
        "rmf_cone_spline_piece_count",
        status,
        &[is_poisoned(&count)],
    ) {
        count
    } else {
        0
    };
    let index = s.input.below(count + 2);
    let mut piece = poisoned::<RmfConePiece>();
    let status = unsafe { rmf_cone_spline_piece(spline, index, &mut piece) };
    if checked("rmf_cone_spline_piece", status, &[is_poisoned(&piece)]) {
        assert!(index < count && piece.kind <= RMF_CONE_PIECE_PLANE);
    }
}

fn surface(s: &mut Session) {
    let (spline, t_min, t_max) = (s.spline(), s.input.f64(), s.input.f64());
    let mut out = poisoned();
    let status = unsafe { rmf_cone_spline_surface(spline, t_min, t_max, &mut out) };
    s.made_surface("rmf_cone_spline_surface", status, out);
}

fn bounds_and_boundary(s: &mut Session) {
    let (spline, region) = (s.spline(), region(s));
    let (mut lo, mut hi) = (poisoned::<f64>(), poisoned::<f64>());
    let status = unsafe {
        rmf_cone_spline_bounds_in_box(
            spline,
            region.as_ref().map_or(null(), |r| r as *const RmfBox),
            &mut lo,
            &mut hi,
        )
    };
    checked(
        "rmf_cone_spline_bounds_in_box",
        status,
        &[is_poisoned(&lo), is_poisoned(&hi)],
    );
    let t = s.input.f64();
    let mut out = poisoned();
    let status = unsafe { rmf_cone_spline_boundary(spline, t, &mut out) };
    s.made("rmf_cone_spline_boundary", status, Some(out), None);
}

fn derived(s: &mut Session) {
    let spline = s.spline();
    let value = s.input.f64();
    let mut out = poisoned();
    let (function, status) = match s.input.byte() % 3 {
        0 => ("rmf_cone_spline_bend", unsafe {
            rmf_cone_spline_bend(spline, value, &mut out)
        }),
        1 => ("rmf_cone_spline_develop", unsafe {
            rmf_cone_spline_develop(spline, &mut out)
        }),
        _ => ("rmf_cone_spline_offset", unsafe {
            rmf_cone_spline_offset(spline, value, &mut out)
        }),
    };
    s.made_spline(function, status, out);
}

fn fit_report(s: &mut Session) {
    let spline = s.spline();
    let mut e = poisoned::<f64>();
    let status = unsafe { rmf_cone_spline_fit_error(spline, &mut e) };
    checked("rmf_cone_spline_fit_error", status, &[is_poisoned(&e)]);
    let mut c = poisoned::<f64>();
    let status = unsafe { rmf_cone_spline_fit_clearance(spline, &mut c) };
    if checked("rmf_cone_spline_fit_clearance", status, &[is_poisoned(&c)]) {
        // The fit keeps every vertex outside the region, up to the rounding margin.
        assert!(
            c >= -1e-9,
            "rmf_cone_spline_fit_clearance: a vertex inside the region: {c}"
        );
    }
    let (which, capacity) = (s.input.code(), s.input.work().min(64));
    let mut values = poisoned_buffer::<f64>(capacity);
    let mut count = poisoned::<usize>();
    let values_ptr = if capacity == 0 && s.input.flag() {
        null_mut()
    } else {
        values.as_mut_ptr()
    };
    let status =
        unsafe { rmf_cone_spline_fit_parameters(spline, which, values_ptr, capacity, &mut count) };
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    checked(
        "rmf_cone_spline_fit_parameters",
        status,
        &[
            values.iter().all(is_poisoned),
            is_poisoned(&count) || too_small,
        ],
    );
}
