//! Operations on the RRMF quintic entry points (Farouki, Giannelli & Sestini): solutions
//! for one η, canonical angles, curves with their exact RMF, the best η, and splines.

use rmfsurf_capi::rrmf_quintic::*;
use rmfsurf_capi::{RmfStatus, RmfVec3};

use super::core::or_null;
use super::ph_cubic::hermite_data;
use super::session::{checked, is_poisoned, poisoned, poisoned_buffer, Session};

/// The operations of this module.
pub const OPS: &[fn(&mut Session)] = &[
    solutions_and_curve,
    irregular_roots,
    angles,
    best,
    spline_hermite,
];

/// Two points with tangents.
fn segment(s: &mut Session) -> [RmfVec3; 4] {
    [
        s.input.vec3(),
        s.input.vec3(),
        s.input.vec3(),
        s.input.vec3(),
    ]
}

/// All solutions for one η, then a curve from one of them (as found, perturbed, or drawn).
fn solutions_and_curve(s: &mut Session) {
    let [p0, t0, p1, t1] = segment(s);
    let eta = s.input.f64();
    let capacity = s.input.work().min(16);
    let mut found = poisoned_buffer::<RmfRrmfQuintic>(capacity);
    let mut count = poisoned::<usize>();
    let status = unsafe {
        rmf_rrmf_quintic_solutions(
            p0,
            t0,
            p1,
            t1,
            eta,
            found.as_mut_ptr(),
            capacity,
            &mut count,
        )
    };
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    let ok = checked(
        "rmf_rrmf_quintic_solutions",
        status,
        &[
            found.iter().all(is_poisoned),
            is_poisoned(&count) || too_small,
        ],
    );
    let mut solution = if ok && count > 0 {
        found[s.input.below(count)]
    } else {
        RmfRrmfQuintic::default()
    };
    match s.input.byte() % 4 {
        0 => solution.rho = s.input.f64(),
        1 => solution.eta = s.input.f64(),
        _ => {}
    }
    let normal = s.input.vec3();
    let (mut c, mut f) = (poisoned(), poisoned());
    let data = [p0, t0, p1, t1];
    let [p0, t0, p1, t1] = if s.input.flag() { segment(s) } else { data };
    let status = unsafe {
        rmf_rrmf_quintic_curve(
            p0,
            t0,
            p1,
            t1,
            or_null(&mut s.input, std::slice::from_ref(&solution)),
            normal,
            &mut c,
            &mut f,
        )
    };
    s.made("rmf_rrmf_quintic_curve", status, Some(c), Some(f));
}

/// The near-cusps of one η: positive ρ, speed ratios in (0, 1e-6), nothing written on failure.
fn irregular_roots(s: &mut Session) {
    let [p0, t0, p1, t1] = segment(s);
    let eta = s.input.f64();
    let capacity = s.input.work().min(8);
    let (mut rho, mut ratio) = (
        poisoned_buffer::<f64>(capacity),
        poisoned_buffer::<f64>(capacity),
    );
    let mut count = poisoned::<usize>();
    let status = unsafe {
        rmf_rrmf_quintic_irregular_roots(
            p0,
            t0,
            p1,
            t1,
            eta,
            rho.as_mut_ptr(),
            ratio.as_mut_ptr(),
            capacity,
            &mut count,
        )
    };
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    let untouched = rho.iter().chain(&ratio).all(is_poisoned);
    if checked(
        "rmf_rrmf_quintic_irregular_roots",
        status,
        &[untouched, is_poisoned(&count) || too_small],
    ) {
        for (&r, &q) in rho.iter().zip(&ratio).take(count) {
            assert!(
                r > 0.0 && r.is_finite() && (0.0..1e-6).contains(&q),
                "rho {r}, ratio {q}"
            );
        }
    }
}

fn angles(s: &mut Session) {
    let [p0, t0, p1, t1] = segment(s);
    let mut out = [poisoned::<f64>(); 3];
    let [a, b, c] = &mut out;
    let status = unsafe { rmf_rrmf_quintic_angles(p0, t0, p1, t1, a, b, c) };
    if checked(
        "rmf_rrmf_quintic_angles",
        status,
        &[out.iter().all(is_poisoned)],
    ) {
        assert!(out.iter().all(|a| a.is_finite()), "angles {out:?}");
    }
}

fn best(s: &mut Session) {
    let [p0, t0, p1, t1] = segment(s);
    let (measure, samples) = (s.input.code(), s.input.work());
    let (mut best, mut admissible) = (poisoned::<RmfRrmfQuintic>(), poisoned::<usize>());
    let status = unsafe {
        rmf_rrmf_quintic_best(p0, t0, p1, t1, measure, samples, &mut best, &mut admissible)
    };
    checked(
        "rmf_rrmf_quintic_best",
        status,
        &[is_poisoned(&best), is_poisoned(&admissible)],
    );
}

fn spline_hermite(s: &mut Session) {
    let (points, tangents, n) = hermite_data(s);
    let (normal, measure, samples) = (s.input.vec3(), s.input.code(), s.input.work());
    let (mut c, mut f) = (poisoned(), poisoned());
    let status = unsafe {
        rmf_rrmf_spline_hermite(
            or_null(&mut s.input, &points),
            or_null(&mut s.input, &tangents),
            n,
            normal,
            measure,
            samples,
            &mut c,
            &mut f,
        )
    };
    s.made("rmf_rrmf_spline_hermite", status, Some(c), Some(f));
}
