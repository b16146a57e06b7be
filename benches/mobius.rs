//! Benchmark of the Möbius construction (Bartoň, Jüttler & Wang) beside double reflection:
//! Hermite construction per segment, and frame evaluation against computing the same number
//! of frames by double reflection on the same curve, with the accuracy of each.
//!
//!   cargo bench --bench mobius

mod support;

use rmfsurf::glam::DVec3;
use rmfsurf::metrics::angle_between;
use rmfsurf::{
    mobius::approximate as mobius_approximate, uniform_parameters, DoubleReflectionRmf,
    ParametricCurve, Result,
};
use support::fastest_of;

struct Helix;

/// A curve with varying curvature and torsion: the paper's map serves every segment.
struct TwistedCubic;

impl ParametricCurve for TwistedCubic {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.5)
    }
    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        Ok((
            DVec3::new(t, t * t - 0.5 * t, 0.5 * t * t * t),
            DVec3::new(1.0, 2.0 * t - 0.5, 1.5 * t * t),
        ))
    }
}

impl ParametricCurve for Helix {
    fn domain(&self) -> (f64, f64) {
        (0.0, 8.0 * std::f64::consts::PI)
    }
    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        Ok((
            DVec3::new(t.cos(), t.sin(), 0.4 * t),
            DVec3::new(-t.sin(), t.cos(), 0.4),
        ))
    }
}

fn main() {
    let seed = DVec3::Z;
    for (name, curve) in [
        ("helix (turning map)", &Helix as &dyn ParametricCurve),
        ("twisted cubic (paper's map)", &TwistedCubic),
    ] {
        let segments = 1000;
        let (t, _) = fastest_of(5, || mobius_approximate(curve, segments, seed).unwrap());
        println!(
            "Hermite construction, {name}, {segments} segments: {:.3} ms ({:.2} µs per segment)",
            t * 1e3,
            t * 1e6 / segments as f64
        );
    }
    let spline = mobius_approximate(&Helix, 1000, seed).unwrap();
    let samples = 100_000;
    let params = uniform_parameters(spline.curve().domain(), samples);
    let start = spline.frames().frame(0.0).f2;
    let (eval, _) = fastest_of(5, || {
        params
            .iter()
            .map(|&t| spline.frames().frame(t).f2.x)
            .sum::<f64>()
    });
    let (reflect, _) = fastest_of(5, || {
        DoubleReflectionRmf::along(&spline.curve(), params.clone(), start).unwrap()
    });
    println!(
        "{samples} frames on the 1000-segment spline: exact rational RMF {:.2} ms ({:.0} ns/frame); \
         double reflection {:.2} ms ({:.0} ns/frame, incl. curve evaluation); ratio {:.2}",
        eval * 1e3,
        eval * 1e9 / samples as f64,
        reflect * 1e3,
        reflect * 1e9 / samples as f64,
        eval / reflect
    );
    // Accuracy on the same curve: double reflection at equal and at 10× the sample count
    // against the exact rational RMF (100× would add ~1e-8 of rounding over 10⁷ steps).
    for factor in [1, 10] {
        let dr_params = uniform_parameters(spline.curve().domain(), factor * samples);
        let dr = DoubleReflectionRmf::along(&spline.curve(), dr_params.clone(), start).unwrap();
        let err = dr_params
            .iter()
            .zip(dr.frames())
            .step_by(97)
            .map(|(&t, f)| angle_between(spline.frames().frame(t).f2, f.f2))
            .fold(0.0, f64::max);
        println!(
            "double reflection with {} samples vs the exact rational RMF: max angle {err:.2e} rad",
            factor * samples
        );
    }
}
