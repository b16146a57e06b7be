//! PH cubic fixtures shared by the tests of this module (the generic ones are in
//! `crate::testing`).

use super::cubic::PhCubic;
use super::spline::{ph_spline_hermite, PhSpline};
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::testing::helix;
use glam::DVec3;

/// The PH cubic of Example 2 of the Möbius paper (Bartoň, Jüttler & Wang):
/// x(t) = (3t(1−t)² + 3t²(1−t) + t³, (1−t)³ + 3t(1−t)², 2t³).
pub(crate) fn example_cubic() -> PhCubic {
    PhCubic::from_control_points([
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 2.0),
    ])
    .unwrap()
}

/// The mirror image z → −z (opposite torsion).
pub(crate) fn mirrored(c: &PhCubic) -> PhCubic {
    let flip = |p: DVec3| DVec3::new(p.x, p.y, -p.z);
    PhCubic::from_control_points(c.control_points().map(flip)).unwrap()
}

/// The PH spline through `segments` + 1 samples of the helix with pitch 0.4, spaced by `step`.
pub(crate) fn helix_spline(segments: usize, step: f64) -> PhSpline {
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) =
        (0..=segments).map(|i| helix(step * i as f64, 0.4)).unzip();
    ph_spline_hermite(&points, &tangents).unwrap()
}

/// An S-shaped cubic profile on [0, 1] with one inflection, at u = 1/2.
pub(crate) fn s_profile() -> PiecewiseCurve {
    let cubic = RationalBezierCurve::polynomial(&[
        DVec3::new(-0.3, 0.0, 0.0),
        DVec3::new(-0.1, 0.4, 0.0),
        DVec3::new(0.1, -0.4, 0.0),
        DVec3::new(0.3, 0.0, 0.0),
    ])
    .unwrap();
    PiecewiseCurve::new(vec![cubic], vec![0.0, 1.0]).unwrap()
}
