//! Operations on the Möbius entry points (Bartoň, Jüttler & Wang): images of points,
//! vectors, curves and frames under chains of inversions, and curves with exact rational
//! RMFs by Hermite interpolation and by approximation of curves and callbacks.

use rmfsurf_capi::mobius::*;
use rmfsurf_capi::RmfVec3;

use super::callback::CallbackCurve;
use super::core::or_null;
use super::ph_cubic::hermite_data;
use super::session::{checked, is_poisoned, poisoned, tracing, Session};

/// The operations of this module.
pub const OPS: &[fn(&mut Session)] = &[
    point,
    vector,
    curve,
    frames,
    rrmf_hermite,
    rrmf_hermite,
    rrmf_approximate,
];

/// A chain of up to four inversions (spheres, planes, or unknown kinds).
fn maps(s: &mut Session) -> Vec<RmfInversion> {
    let n = s.input.len(4);
    (0..n)
        .map(|_| RmfInversion {
            kind: s.input.code() % 3,
            center: s.input.vec3(),
            radius: s.input.f64(),
            normal: s.input.vec3(),
        })
        .collect()
}

fn point(s: &mut Session) {
    let (maps, p) = (maps(s), s.input.vec3());
    let mut image = poisoned::<RmfVec3>();
    let status =
        unsafe { rmf_mobius_point(or_null(&mut s.input, &maps), maps.len(), p, &mut image) };
    checked("rmf_mobius_point", status, &[is_poisoned(&image)]);
}

fn vector(s: &mut Session) {
    let (maps, p, v) = (maps(s), s.input.vec3(), s.input.vec3());
    let mut image = poisoned::<RmfVec3>();
    let status =
        unsafe { rmf_mobius_vector(or_null(&mut s.input, &maps), maps.len(), p, v, &mut image) };
    checked("rmf_mobius_vector", status, &[is_poisoned(&image)]);
}

fn curve(s: &mut Session) {
    let (c, maps) = (s.curve(), maps(s));
    let mut out = poisoned();
    let status = unsafe { rmf_mobius_curve(c, maps.as_ptr(), maps.len(), &mut out) };
    s.made("rmf_mobius_curve", status, Some(out), None);
}

fn frames(s: &mut Session) {
    let (f, maps) = (s.frames(), maps(s));
    let (mut c, mut out) = (poisoned(), poisoned());
    let status = unsafe { rmf_mobius_frames(f, maps.as_ptr(), maps.len(), &mut c, &mut out) };
    s.made("rmf_mobius_frames", status, Some(c), Some(out));
}

fn rrmf_hermite(s: &mut Session) {
    let (points, tangents, n) = hermite_data(s);
    let normal = s.input.vec3();
    if tracing() {
        eprintln!(
            "Möbius Hermite: points {points:?}, tangents {tangents:?}, n {n}, normal {normal:?}"
        );
    }
    let (mut c, mut f) = (poisoned(), poisoned());
    let status = unsafe {
        rmf_mobius_rrmf_hermite(
            or_null(&mut s.input, &points),
            or_null(&mut s.input, &tangents),
            n,
            normal,
            &mut c,
            &mut f,
        )
    };
    s.made("rmf_mobius_rrmf_hermite", status, Some(c), Some(f));
}

fn rrmf_approximate(s: &mut Session) {
    let mut source = CallbackCurve::draw(&mut s.input);
    let curve = s.curve();
    let (callback, user) = source.callback_if(s.input.flag());
    let (t_min, t_max) = (s.input.f64(), s.input.f64());
    let (segments, normal) = (s.input.work(), s.input.vec3());
    let (mut c, mut f) = (poisoned(), poisoned());
    let status = unsafe {
        rmf_mobius_rrmf_approximate(
            curve, callback, user, t_min, t_max, segments, normal, &mut c, &mut f,
        )
    };
    s.made("rmf_mobius_rrmf_approximate", status, Some(c), Some(f));
}
