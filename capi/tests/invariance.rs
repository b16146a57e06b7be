//! Invariance of the constructions under what must not change their answer (issue 13,
//! items 7 and 8):
//!
//! * scale and translation: every construction of the PH cubic, Möbius and RRMF families,
//!   given data x ↦ s·x + o (s from 1e-200 to 1e200, o up to 1e6 sizes of the data), gives
//!   the curve mapped the same way and the same frames — a property test;
//! * callback tangents: a callback whose tangent is any constant multiple of the derivative
//!   (1e80, 1e-85, negative) gives what the derivative itself gives, in every fit that takes
//!   a callback (PH, Möbius, cone splines).
//!
//! Everything goes through the C API, as a C program would call it.

use proptest::prelude::*;
use rmfsurf::glam::DVec3;
use rmfsurf_capi::cone_spline::*;
use rmfsurf_capi::curve::{rmf_curve_domain, rmf_curve_eval, rmf_curve_free};
use rmfsurf_capi::frames::{rmf_frames_eval, rmf_frames_free};
use rmfsurf_capi::mobius::{rmf_mobius_rrmf_approximate, rmf_mobius_rrmf_hermite};
use rmfsurf_capi::ph_cubic::{
    rmf_ph_rational_rmf, rmf_ph_spline_approximate, rmf_ph_spline_hermite,
};
use rmfsurf_capi::rrmf_quintic::rmf_rrmf_spline_hermite;
use rmfsurf_capi::{RmfCurve, RmfFrames, RmfStatus, RmfVec3};
use std::ffi::c_void;
use std::ptr::{null, null_mut};

fn vec3(v: DVec3) -> RmfVec3 {
    RmfVec3 {
        x: v.x,
        y: v.y,
        z: v.z,
    }
}

fn dvec(v: RmfVec3) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

/// Hermite data on the helix (cos t, sin t, 0.4 t), `count` samples `step` apart, mapped
/// by x ↦ scale·x + offset.
fn helix_data(count: usize, step: f64, scale: f64, offset: DVec3) -> (Vec<RmfVec3>, Vec<RmfVec3>) {
    (0..count)
        .map(|i| {
            let t = step * i as f64;
            let p = DVec3::new(t.cos(), t.sin(), 0.4 * t);
            (
                vec3(p * scale + offset),
                vec3(DVec3::new(-t.sin(), t.cos(), 0.4)),
            )
        })
        .unzip()
}

/// A curve and (optionally) frames made by a construction, freed on drop.
struct Made {
    curve: *mut RmfCurve,
    frames: *mut RmfFrames,
}

impl Drop for Made {
    fn drop(&mut self) {
        unsafe {
            rmf_frames_free(self.frames);
            rmf_curve_free(self.curve);
        }
    }
}

fn domain(curve: *const RmfCurve) -> (f64, f64) {
    let (mut lo, mut hi) = (0.0, 0.0);
    assert_eq!(
        unsafe { rmf_curve_domain(curve, &mut lo, &mut hi) },
        RmfStatus::RmfOk
    );
    (lo, hi)
}

fn point(curve: *const RmfCurve, t: f64) -> DVec3 {
    let mut p = RmfVec3::default();
    assert_eq!(
        unsafe { rmf_curve_eval(curve, t, &mut p, null_mut()) },
        RmfStatus::RmfOk
    );
    dvec(p)
}

fn frame(frames: *const RmfFrames, t: f64) -> [DVec3; 2] {
    let (mut tangent, mut f2, mut f3) = Default::default();
    assert_eq!(
        unsafe { rmf_frames_eval(frames, t, &mut tangent, &mut f2, &mut f3) },
        RmfStatus::RmfOk
    );
    [dvec(f2), dvec(f3)]
}

/// The largest distance of `made` from the reference mapped by x ↦ scale·x + offset,
/// relative to `scale`, and the largest difference of the frames, at parameters spread over
/// the domain (which must be the same).
fn gap(made: &Made, reference: &Made, scale: f64, offset: DVec3) -> (f64, f64) {
    let (lo, hi) = domain(made.curve);
    assert_eq!(
        (lo, hi),
        domain(reference.curve),
        "the same parameter domain"
    );
    let mut worst = (0.0f64, 0.0f64);
    for i in 0..=64 {
        let t = lo + (hi - lo) * i as f64 / 64.0;
        let expected = point(reference.curve, t) * scale + offset;
        // Compared relative to the scale before subtracting (no overflow at 1e200).
        let distance = (point(made.curve, t) / scale - expected / scale).length();
        worst.0 = worst.0.max(distance);
        if !made.frames.is_null() {
            let ([a2, a3], [b2, b3]) = (frame(made.frames, t), frame(reference.frames, t));
            worst.1 = worst.1.max((a2 - b2).length()).max((a3 - b3).length());
        }
    }
    worst
}

/// The constructions compared, each from Hermite data (points, tangents).
#[derive(Clone, Copy, Debug)]
enum Construction {
    PhSpline,
    PhRationalRmf,
    Mobius,
    Rrmf,
}

fn construct(kind: Construction, points: &[RmfVec3], tangents: &[RmfVec3]) -> Result<Made, String> {
    let (p, t, n) = (points.as_ptr(), tangents.as_ptr(), points.len());
    let up = vec3(DVec3::new(0.3, -0.2, 1.0));
    let (mut curve, mut frames) = (null_mut(), null_mut());
    let status = unsafe {
        match kind {
            Construction::PhSpline => rmf_ph_spline_hermite(p, t, n, &mut curve),
            Construction::PhRationalRmf => {
                let s = rmf_ph_spline_hermite(p, t, n, &mut curve);
                if s == RmfStatus::RmfOk {
                    rmf_ph_rational_rmf(curve, up, &mut frames)
                } else {
                    s
                }
            }
            Construction::Mobius => rmf_mobius_rrmf_hermite(p, t, n, up, &mut curve, &mut frames),
            Construction::Rrmf => {
                rmf_rrmf_spline_hermite(p, t, n, up, 3, 32, &mut curve, &mut frames)
            }
        }
    };
    let made = Made { curve, frames };
    if status != RmfStatus::RmfOk {
        return Err(format!("{kind:?}: {status:?}: {}", last_error()));
    }
    Ok(made)
}

fn last_error() -> String {
    unsafe { std::ffi::CStr::from_ptr(rmfsurf_capi::status::rmf_last_error()) }
        .to_string_lossy()
        .into_owned()
}

/// 64 cases per property, or PROPTEST_CASES (the test command fixes the seed).
fn config() -> ProptestConfig {
    let from_environment = ProptestConfig::default();
    let cases = match std::env::var_os("PROPTEST_CASES") {
        Some(_) => from_environment.cases,
        None => 64,
    };
    ProptestConfig {
        cases,
        ..from_environment
    }
}

/// The tolerance of a comparison at offset o from data of size s: the data are rounded to
/// ε·(|o| + s), i.e. ε·(1 + |o|/s) relative, and the PH and Möbius constructions amplify
/// that by their conditioning (chords of 0.5, tangents from them): 1e-9 for |o|/s = 1e6.
/// The RRMF quintics choose η as the minimizer of a shape measure, a smooth function of η
/// flat at its minimum: data moved by δ move that minimizer by O(√δ), so the RRMF splines
/// are invariant to O(√(ε·(1 + |o|/s))) — the conditioning of the paper's choice, not of
/// this implementation.
fn tolerance(kind: Construction, offset_ratio: f64) -> f64 {
    let rounding = 1e-11 + 1e3 * f64::EPSILON * offset_ratio;
    match kind {
        Construction::Rrmf => rounding + 0.1 * (f64::EPSILON * (1.0 + offset_ratio)).sqrt(),
        _ => rounding,
    }
}

proptest! {
    #![proptest_config(config())]

    /// Issue finding (scale): the helix ×1e-200 gave NO_SOLUTION with "NaN" in its message
    /// (the PH condition), ×1e200 "more than 4096 rational pieces" (the PH frames), and a
    /// translation by 1e6 "not G1" (the PH frames). Every construction of the PH, Möbius and
    /// RRMF families is invariant under x ↦ s·x + o over the representable range.
    #[test]
    fn constructions_are_invariant_under_scaling_and_translation(
        exponent in -200i32..=200,
        mantissa in 1.0f64..10.0,
        offset_ratio in prop::sample::select(vec![0.0, 1.0, 1e3, 1e6]),
        direction in (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0),
        which in 0usize..4,
    ) {
        let kind = [
            Construction::PhSpline,
            Construction::PhRationalRmf,
            Construction::Mobius,
            Construction::Rrmf,
        ][which];
        let scale = mantissa * 10f64.powi(exponent);
        let direction = DVec3::new(direction.0, direction.1, direction.2 + 1e-3).normalize();
        let offset = direction * (offset_ratio * scale);
        let (points, tangents) = helix_data(9, 0.5, 1.0, DVec3::ZERO);
        let reference = construct(kind, &points, &tangents).unwrap();
        let (points, tangents) = helix_data(9, 0.5, scale, offset);
        let made = construct(kind, &points, &tangents);
        prop_assert!(made.is_ok(), "scale {:e}, offset {:e}: {}", scale, offset_ratio * scale,
            made.err().unwrap_or_default());
        let (distance, frames) = gap(&made.unwrap(), &reference, scale, offset);
        let bound = tolerance(kind, offset_ratio);
        prop_assert!(distance <= bound, "{:?} scale {:e} offset {:e}: curve off by {:e} (relative)",
            kind, scale, offset_ratio, distance);
        prop_assert!(frames <= 1e3 * bound, "{:?} scale {:e} offset {:e}: frames off by {:e}",
            kind, scale, offset_ratio, frames);
    }
}

/// The extremes themselves, for every construction (the property test draws among them).
#[test]
fn the_extreme_scales_and_offsets_of_the_issue() {
    for kind in [
        Construction::PhSpline,
        Construction::PhRationalRmf,
        Construction::Mobius,
        Construction::Rrmf,
    ] {
        let (points, tangents) = helix_data(9, 0.5, 1.0, DVec3::ZERO);
        let reference = construct(kind, &points, &tangents).unwrap();
        for scale in [1e-200, 1e-100, 1.0, 1e100, 1e200] {
            for offset_ratio in [0.0, 1e6] {
                let offset = DVec3::new(1.0, -2.0, 3.0).normalize() * (offset_ratio * scale);
                let (points, tangents) = helix_data(9, 0.5, scale, offset);
                let made = construct(kind, &points, &tangents)
                    .unwrap_or_else(|e| panic!("scale {scale:e}, offset {offset_ratio:e}: {e}"));
                let (distance, frames) = gap(&made, &reference, scale, offset);
                println!(
                    "{kind:?} ×{scale:e} + {offset_ratio:e}·size: curve {distance:.1e} (relative), \
                     frames {frames:.1e}"
                );
                let bound = tolerance(kind, offset_ratio);
                assert!(
                    distance <= bound && frames <= 1e3 * bound,
                    "{kind:?} {scale:e} {offset_ratio:e}"
                );
            }
        }
    }
}

/// The twisted cubic (t, t², t³/2) with its tangent multiplied by `*user` (a curve of
/// varying curvature and torsion: its tangent surface is no constant-slope surface).
unsafe extern "C" fn cubic_times(
    t: f64,
    user: *mut c_void,
    point: *mut RmfVec3,
    tangent: *mut RmfVec3,
) {
    let factor = *(user as *const f64);
    *point = vec3(DVec3::new(t, t * t, 0.5 * t * t * t));
    *tangent = vec3(DVec3::new(1.0, 2.0 * t, 1.5 * t * t) * factor);
}

/// What a fit from the callback gives: its curve sampled (PH, Möbius) or its cone spline's
/// piece count and error (cone splines).
fn fit_with(factor: f64, fit: usize) -> Result<Vec<f64>, String> {
    let mut factor = factor;
    let user = (&mut factor as *mut f64).cast::<c_void>();
    let callback = Some(cubic_times as unsafe extern "C" fn(_, _, _, _));
    let (mut curve, mut frames, mut spline) = (null_mut(), null_mut(), null_mut());
    let mut error = 0.0;
    #[allow(deprecated)] // the callback entry points: deprecated, still exported, invariant
    let status = unsafe {
        match fit {
            0 => rmf_ph_spline_approximate(
                null(),
                callback,
                user,
                0.2,
                1.2,
                1e-5,
                &mut curve,
                &mut error,
            ),
            1 => rmf_mobius_rrmf_approximate(
                null(),
                callback,
                user,
                0.2,
                1.2,
                24,
                vec3(DVec3::Z),
                &mut curve,
                &mut frames,
            ),
            2 => rmf_cone_spline_approximate(
                null(),
                callback,
                user,
                0.2,
                1.2,
                0.5,
                4.0,
                1e-3,
                RMF_CONE_RULE_MIN_VERTEX_DISTANCE,
                1000,
                &mut spline,
                &mut error,
            ),
            _ => {
                let parameters: Vec<f64> = (0..=20).map(|i| 0.2 + 0.05 * i as f64).collect();
                rmf_cone_spline_osculating(
                    null(),
                    callback,
                    user,
                    0.2,
                    1.2,
                    0.5,
                    4.0,
                    parameters.as_ptr(),
                    parameters.len(),
                    &mut spline,
                )
            }
        }
    };
    if status != RmfStatus::RmfOk {
        return Err(format!("{status:?}: {}", last_error()));
    }
    let made = Made { curve, frames };
    let values = if spline.is_null() {
        let (lo, hi) = domain(made.curve);
        (0..=32)
            .flat_map(|i| point(made.curve, lo + (hi - lo) * i as f64 / 32.0).to_array())
            .collect()
    } else {
        let mut pieces = 0;
        assert_eq!(
            unsafe { rmf_cone_spline_piece_count(spline, &mut pieces) },
            RmfStatus::RmfOk
        );
        unsafe { rmf_cone_spline_free(spline) };
        vec![pieces as f64, error]
    };
    Ok(values)
}

/// Issue finding (callbacks): the header promises a tangent may be "any non-zero multiple"
/// of the derivative, but a factor ≥ 1e80 or ≤ 1e-85 was refused by the cone fits ("the
/// rulings do not move", "zero curvature") and a negative one by the PH and Möbius fits
/// (accepted by the cone fit). One rule at the C boundary now divides the multiple out.
#[test]
fn callback_tangents_may_be_any_constant_multiple() {
    for (fit, name) in ["PH fit", "Möbius fit", "cone fit", "osculating cones"]
        .iter()
        .enumerate()
    {
        let reference = fit_with(1.0, fit).unwrap_or_else(|e| panic!("{name}: {e}"));
        for factor in [1e80, 1e-85, -1.0, -1e80, 3.7, -2.5e-200] {
            let values =
                fit_with(factor, fit).unwrap_or_else(|e| panic!("{name} ×{factor:e}: {e}"));
            if fit == 3 {
                // Accepted for every multiple; its number of pieces is not compared: the
                // osculating construction itself moves by a piece when the exact derivative
                // is multiplied by 1 − 1e-13 (42 → 41 pieces here), an instability of its
                // filling cones (issue 12, items 2–3), not of the multiple divided out.
                continue;
            }
            assert_eq!(values.len(), reference.len(), "{name} ×{factor:e}");
            let worst = values
                .iter()
                .zip(&reference)
                .map(|(a, b)| (a - b).abs() / b.abs().max(1.0))
                .fold(0.0, f64::max);
            assert!(worst < 1e-9, "{name} ×{factor:e}: differs by {worst:e}");
        }
    }
}

/// A cone spline's pieces: vertex (or zeros), end point, end ruling and segment angle.
fn cone_pieces(spline: *const RmfConeSpline) -> Vec<(Option<DVec3>, DVec3, DVec3, f64)> {
    let mut count = 0;
    assert_eq!(
        unsafe { rmf_cone_spline_piece_count(spline, &mut count) },
        RmfStatus::RmfOk
    );
    (0..count)
        .map(|i| {
            let mut p = std::mem::MaybeUninit::<RmfConePiece>::uninit();
            assert_eq!(
                unsafe { rmf_cone_spline_piece(spline, i, p.as_mut_ptr()) },
                RmfStatus::RmfOk
            );
            let p = unsafe { p.assume_init() };
            (
                (p.has_vertex == 1).then(|| dvec(p.vertex)),
                dvec(p.end_point),
                dvec(p.end_ruling),
                p.segment_angle,
            )
        })
        .collect()
}

/// The largest difference of two cone splines' pieces, `made` against `reference` mapped by
/// x ↦ scale·x + offset (points relative to the scale); None if the piece counts differ.
fn cone_gap(
    made: *const RmfConeSpline,
    reference: *const RmfConeSpline,
    scale: f64,
    offset: DVec3,
) -> Option<f64> {
    let (a, b) = (cone_pieces(made), cone_pieces(reference));
    if a.len() != b.len() {
        return None;
    }
    let distance = |x: DVec3, y: DVec3| (x / scale - (y * scale + offset) / scale).length();
    let mut gap = 0.0f64;
    for (p, q) in a.iter().zip(&b) {
        match (p.0, q.0) {
            (Some(v), Some(w)) => gap = gap.max(distance(v, w) / (1.0 + (w - q.1).length())),
            (None, None) => {}
            _ => return None,
        }
        gap = gap
            .max(distance(p.1, q.1))
            .max((p.2 - q.2).length())
            .max((p.3 - q.3).abs());
    }
    Some(gap)
}

/// G1 Hermite elements of the tangent surface of the helix (cos t, sin t, 0.4 t), at
/// distance 1 from the curve, `count` rulings `step` apart from t = `start`, mapped by
/// x ↦ scale·x + offset.
fn helix_elements(
    count: usize,
    start: f64,
    step: f64,
    scale: f64,
    offset: DVec3,
) -> Vec<RmfConeElement> {
    (0..count)
        .map(|i| {
            let t = start + step * i as f64;
            let tangent = DVec3::new(-t.sin(), t.cos(), 0.4).normalize();
            let point = DVec3::new(t.cos(), t.sin(), 0.4 * t) + tangent;
            // The rulings move towards the principal normal (−cos t, −sin t, 0).
            let side = DVec3::new(-t.cos(), -t.sin(), 0.0);
            RmfConeElement {
                point: vec3(point * scale + offset),
                ruling: vec3(tangent),
                side: vec3(side),
            }
        })
        .collect()
}

fn cone_hermite(elements: &[RmfConeElement]) -> Result<*mut RmfConeSpline, String> {
    let mut out = null_mut();
    let status = unsafe {
        rmf_cone_spline_hermite(
            elements.as_ptr(),
            elements.len(),
            RMF_CONE_RULE_MIN_VERTEX_DISTANCE,
            0.0,
            null(),
            &mut out,
        )
    };
    if status != RmfStatus::RmfOk {
        return Err(format!("{status:?}: {}", last_error()));
    }
    Ok(out)
}

/// Issue 13 item 6: rmf_cone_spline_hermite failed from scale 1e15 (and pairs of close
/// rulings, 0.001 apart, failed at any scale). The spline through helix elements 0.5 and
/// 0.001 apart, scaled from 1e-200 to 1e200 and moved by up to 1e6 sizes of the data, is
/// the same spline mapped so. Elements 0.001 apart are moved by at most 1e3 sizes: an
/// offset of 1e6 rounds their points to 2e-7 of their distance, other Hermite data (for
/// which a consistent pair need not exist).
#[test]
fn cone_spline_hermite_is_invariant_under_scaling_and_translation() {
    for (step, start, largest_offset) in [(0.5, 0.0, 1e6), (1e-3, 0.004, 1e3), (1e-3, 28.69, 1e3)] {
        let reference = cone_hermite(&helix_elements(9, start, step, 1.0, DVec3::ZERO)).unwrap();
        let mut worst = 0.0f64;
        for exponent in [-200, -100, -15, 0, 14, 15, 16, 100, 200] {
            let scale = 1.3 * 10f64.powi(exponent);
            for offset_ratio in [0.0, 1.0, largest_offset] {
                let offset = DVec3::new(1.0, -2.0, 3.0).normalize() * (offset_ratio * scale);
                let made = cone_hermite(&helix_elements(9, start, step, scale, offset))
                    .unwrap_or_else(|e| {
                        panic!("step {step}, scale {scale:e}, offset {offset_ratio:e}: {e}")
                    });
                let gap = cone_gap(made, reference, scale, offset)
                    .unwrap_or_else(|| panic!("step {step}, scale {scale:e}: other pieces"));
                unsafe { rmf_cone_spline_free(made) };
                // Rounding of the data, ε (1 + |o|/s) relative to their size, relative to
                // the elements' distance, amplified by 1/step for close rulings.
                let rounding = f64::EPSILON * (2.0 + offset_ratio) / step;
                let bound = 1e-12 + 1e2 * rounding / step;
                assert!(
                    gap <= bound,
                    "step {step}, scale {scale:e}, offset {offset_ratio:e}: gap {gap:e} > {bound:e}"
                );
                if offset_ratio == 0.0 {
                    worst = worst.max(gap);
                }
            }
        }
        println!("rmf_cone_spline_hermite, helix elements {step} apart, scales 1.3e-200 … 1.3e200: largest gap {worst:.1e}");
        unsafe { rmf_cone_spline_free(reference) };
    }
}

/// The helix (cos t, sin t, 0.4 t) mapped by x ↦ scale·x + offset, `user` = [scale, ox, oy, oz].
unsafe extern "C" fn helix_mapped(
    t: f64,
    user: *mut c_void,
    point: *mut RmfVec3,
    tangent: *mut RmfVec3,
) {
    let m = &*(user as *const [f64; 4]);
    let p = DVec3::new(t.cos(), t.sin(), 0.4 * t);
    *point = vec3(p * m[0] + DVec3::new(m[1], m[2], m[3]));
    *tangent = vec3(DVec3::new(-t.sin(), t.cos(), 0.4) * m[0]);
}

fn cone_fit(
    scale: f64,
    offset: DVec3,
    turns: f64,
    tolerance: f64,
    max_pieces: usize,
) -> Result<(*mut RmfConeSpline, f64), String> {
    let mut user = [scale, offset.x, offset.y, offset.z];
    let (mut out, mut error) = (null_mut(), 0.0);
    #[allow(deprecated)] // the callback entry point: deprecated, still exported, invariant
    let status = unsafe {
        rmf_cone_spline_approximate(
            null(),
            Some(helix_mapped),
            (&mut user as *mut [f64; 4]).cast(),
            0.0,
            std::f64::consts::TAU * turns,
            0.5 * scale,
            2.0 * scale,
            tolerance * scale,
            RMF_CONE_RULE_MIN_VERTEX_DISTANCE,
            max_pieces,
            &mut out,
            &mut error,
        )
    };
    if status != RmfStatus::RmfOk {
        return Err(format!("{status:?}: {}", last_error()));
    }
    Ok((out, error))
}

/// Issue 13 item 6: the cone fit failed from scale 1e14. The fit of the helix's tangent
/// surface to 1e-3, scaled from 1e-200 to 1e200 and moved by 1 and 1e6 sizes, has the same
/// pieces mapped so and the same error relative to the scale.
#[test]
fn cone_spline_fit_is_invariant_under_scaling_and_translation() {
    let (reference, error) = cone_fit(1.0, DVec3::ZERO, 2.0, 1e-3, 10_000).unwrap();
    let pieces = cone_pieces(reference).len();
    let mut worst = 0.0f64;
    for exponent in [-200, -100, -15, 0, 14, 15, 100, 200] {
        let scale = 1.3 * 10f64.powi(exponent);
        for offset_ratio in [0.0, 1.0, 1e6] {
            let offset = DVec3::new(1.0, -2.0, 3.0).normalize() * (offset_ratio * scale);
            let (made, e) = cone_fit(scale, offset, 2.0, 1e-3, 10_000)
                .unwrap_or_else(|m| panic!("scale {scale:e}, offset {offset_ratio:e}: {m}"));
            let gap = cone_gap(made, reference, scale, offset);
            unsafe { rmf_cone_spline_free(made) };
            let gap = gap.unwrap_or_else(|| {
                panic!("scale {scale:e}, offset {offset_ratio:e}: not {pieces} pieces")
            });
            let bound = 1e-9 + 1e3 * f64::EPSILON * offset_ratio * 10.0;
            assert!(
                gap <= bound,
                "scale {scale:e}, offset {offset_ratio:e}: gap {gap:e}"
            );
            assert!(
                (e / scale - error).abs() <= 1e-3 * error,
                "scale {scale:e}: error {e:e}"
            );
            if offset_ratio == 0.0 {
                worst = worst.max(gap);
            }
        }
    }
    println!("rmf_cone_spline_approximate, helix of 2 turns to 1e-3 ({pieces} pieces), scales 1.3e-200 … 1.3e200: largest gap {worst:.1e}");
    unsafe { rmf_cone_spline_free(reference) };
}

/// The vertices (u, v) of `rmf_sweep_parabolic_curves` of a circular-arc profile of radius
/// 0.3·scale swept along the PH spline through `points`, at tolerance 1e-7·scale.
fn parabolic_vertices(
    points: &[RmfVec3],
    tangents: &[RmfVec3],
    scale: f64,
) -> Vec<(f64, f64, u32)> {
    use rmfsurf_capi::curve::rmf_nurbs_curve_create;
    use rmfsurf_capi::ph_cubic::{rmf_sweep_parabolic_curves, RmfParabolicCurvePoint};
    let r = 0.3 * scale;
    let arc = [
        vec3(DVec3::new(r, 0.0, 0.0)),
        vec3(DVec3::new(r, r, 0.0)),
        vec3(DVec3::new(0.0, r, 0.0)),
    ];
    let (weights, knots) = (
        [1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
        [0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    );
    let (mut spline, mut frames, mut profile) = (null_mut(), null_mut(), null_mut());
    unsafe {
        assert_eq!(
            rmf_ph_spline_hermite(
                points.as_ptr(),
                tangents.as_ptr(),
                points.len(),
                &mut spline
            ),
            RmfStatus::RmfOk
        );
        assert_eq!(
            rmf_ph_rational_rmf(spline, vec3(DVec3::Z), &mut frames),
            RmfStatus::RmfOk
        );
        assert_eq!(
            rmf_nurbs_curve_create(
                2,
                arc.as_ptr(),
                weights.as_ptr(),
                3,
                knots.as_ptr(),
                6,
                &mut profile
            ),
            RmfStatus::RmfOk
        );
        let mut count = 0;
        let status = rmf_sweep_parabolic_curves(
            spline,
            frames,
            profile,
            1e-7 * scale,
            null_mut(),
            0,
            &mut count,
        );
        assert_eq!(status, RmfStatus::RmfOk, "{}", last_error());
        let mut out = vec![RmfParabolicCurvePoint::default(); count];
        assert_eq!(
            rmf_sweep_parabolic_curves(
                spline,
                frames,
                profile,
                1e-7 * scale,
                out.as_mut_ptr(),
                count,
                &mut count
            ),
            RmfStatus::RmfOk
        );
        rmf_frames_free(frames);
        rmf_curve_free(spline);
        rmf_curve_free(profile);
        out.iter().map(|p| (p.u, p.v, p.curve)).collect()
    }
}

#[test]
fn parabolic_curves_are_invariant_under_scaling_and_translation() {
    let (points, tangents) = helix_data(9, 0.5, 1.0, DVec3::ZERO);
    let reference = parabolic_vertices(&points, &tangents, 1.0);
    assert!(!reference.is_empty());
    for scale in [1e-200, 1e200, 1.0] {
        for offset_ratio in [0.0, 1e3] {
            let offset = DVec3::new(1.0, -2.0, 3.0).normalize() * (offset_ratio * scale);
            let (points, tangents) = helix_data(9, 0.5, scale, offset);
            let got = parabolic_vertices(&points, &tangents, scale);
            let curves = |v: &[(f64, f64, u32)]| v.last().map_or(0, |p| p.2 + 1);
            assert_eq!(
                curves(&got),
                curves(&reference),
                "×{scale:e} + {offset_ratio:e}"
            );
            // The same lines: every vertex of the reference lies on the polyline at its v.
            let mut worst: f64 = 0.0;
            for &(u, v, c) in &reference {
                let line: Vec<&(f64, f64, u32)> = got.iter().filter(|p| p.2 == c).collect();
                let at = line.windows(2).find(|w| (w[0].1 - v) * (w[1].1 - v) <= 0.0);
                let Some(w) = at else {
                    // Past an end of the line (where it leaves the profile): the ends move
                    // with the rounding of the data, a few ulps of the offset.
                    let end = [line[0], line[line.len() - 1]]
                        .into_iter()
                        .min_by(|a, b| (a.1 - v).abs().total_cmp(&(b.1 - v).abs()))
                        .unwrap();
                    assert!(
                        (end.1 - v).abs() < 1e-8,
                        "×{scale:e}: curve {c} misses v = {v}"
                    );
                    worst = worst.max((end.0 - u).abs());
                    continue;
                };
                let s = if w[1].1 == w[0].1 {
                    0.0
                } else {
                    (v - w[0].1) / (w[1].1 - w[0].1)
                };
                worst = worst.max((w[0].0 + s * (w[1].0 - w[0].0) - u).abs());
            }
            println!("parabolic curves ×{scale:e} + {offset_ratio:e}·size: u within {worst:.1e}");
            assert!(worst < 1e-9, "×{scale:e} + {offset_ratio:e}: {worst}");
        }
    }
}
