//! Curves shared by the tests of this module.

use super::cubic::PhCubic;
use super::spline::ph_spline_hermite;
use crate::bezier::PiecewiseCurve;
use glam::DVec3;

/// The PH cubic of Example 2 of the Möbius paper (Bartoň, Jüttler & Wang):
/// x(t) = (3t(1−t)² + 3t²(1−t) + t³, (1−t)³ + 3t(1−t)², 2t³).
pub fn example_cubic() -> PhCubic {
    PhCubic::from_control_points([
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 2.0),
    ])
    .unwrap()
}

/// The mirror image z → −z (opposite torsion).
pub fn mirrored(c: &PhCubic) -> PhCubic {
    let flip = |p: DVec3| DVec3::new(p.x, p.y, -p.z);
    PhCubic::from_control_points(c.control_points().map(flip)).unwrap()
}

/// The helix (cos t, sin t, pitch·t) with its tangent.
pub fn helix(t: f64, pitch: f64) -> (DVec3, DVec3) {
    (
        DVec3::new(t.cos(), t.sin(), pitch * t),
        DVec3::new(-t.sin(), t.cos(), pitch),
    )
}

/// The PH spline through `segments` + 1 samples of the helix with pitch 0.4, spaced by `step`.
pub fn helix_spline(segments: usize, step: f64) -> PiecewiseCurve {
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) =
        (0..=segments).map(|i| helix(step * i as f64, 0.4)).unzip();
    ph_spline_hermite(&points, &tangents).unwrap()
}

/// A planar PH cubic, a Tschirnhausen cubic: legs of lengths 1, q, q² each turning by `turn`
/// (equal angles and L₂² = L₁L₃, condition (17) with ψ = 0).
pub fn tschirnhausen(turn: f64, q: f64) -> PhCubic {
    let leg = |k: f64| DVec3::new((k * turn).cos(), (k * turn).sin(), 0.0) * q.powf(k);
    let b1 = leg(0.0);
    let b2 = b1 + leg(1.0);
    PhCubic::from_control_points([DVec3::ZERO, b1, b2, b2 + leg(2.0)]).unwrap()
}

/// The largest angle about the tangent between `frame(t)` and the double-reflection RMF of
/// `spline` started at `normal`, over `samples` uniform parameters (the double-reflection
/// frames are fourth-order accurate in the sample spacing: the reference of the tests).
pub fn gap_to_double_reflection(
    spline: &PiecewiseCurve,
    normal: DVec3,
    samples: usize,
    frame: impl Fn(f64) -> crate::frames::Frame,
) -> f64 {
    let params = crate::curve::uniform_parameters(spline.domain(), samples);
    let reference = crate::frames::double_reflection::DoubleReflectionRmf::along(
        spline,
        params.clone(),
        normal,
    )
    .unwrap();
    params
        .iter()
        .zip(reference.frames())
        .map(|(&t, f)| crate::frames::metrics::angle_about_tangent(f, &frame(t)).abs())
        .fold(0.0, f64::max)
}
