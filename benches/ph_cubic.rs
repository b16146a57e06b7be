//! Benchmark of the PH cubic pipeline (Mäurer & Jüttler) against the double-reflection RMF:
//! a PH cubic spline of 1,000 segments through a conical helix, its rational RMF, a profile
//! surface, and frames at 100,000 parameters; beside it, the double-reflection RMF computing
//! the same 100,000 frames on the same spline. Prints the times, their ratio, and the
//! largest angle of each against the exact (closed-form) RMF.
//!
//! Run with `cargo bench --bench ph_cubic`.

mod support;

use rmfsurf::glam::DVec3;
use rmfsurf::metrics::angle_about_tangent;
use rmfsurf::{
    ph::rational_rmf as ph_rational_rmf, ph::spline_hermite as ph_spline_hermite, ph::ExactRmf,
    ph::RmfOptions, sweep, uniform_parameters, DoubleReflectionRmf, Frame, PiecewiseCurve,
    RationalBezierCurve,
};
use support::{timed, REPEATS};

const SEGMENTS: usize = 1_000;
const FRAMES: usize = 100_000;

/// The conical helix ((t/20 + 1) cos t, (t/20 + 1) sin t, 0.3 t) with its derivative.
fn spiral(t: f64) -> (DVec3, DVec3) {
    let r = t / 20.0 + 1.0;
    (
        DVec3::new(r * t.cos(), r * t.sin(), 0.3 * t),
        DVec3::new(
            t.cos() / 20.0 - r * t.sin(),
            t.sin() / 20.0 + r * t.cos(),
            0.3,
        ),
    )
}

fn max_angle(exact: &ExactRmf, params: &[f64], frames: &[Frame]) -> f64 {
    params
        .iter()
        .zip(frames)
        .map(|(&t, f)| angle_about_tangent(&exact.frame(t), f).abs())
        .fold(0.0, f64::max)
}

fn main() {
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) =
        (0..=SEGMENTS).map(|i| spiral(0.1 * i as f64)).unzip();
    let normal = DVec3::Z;
    let (t_spline, spline) = timed(|| ph_spline_hermite(&points, &tangents).unwrap());
    let (t_rmf, rmf) = timed(|| ph_rational_rmf(&spline, &RmfOptions::rmf(normal)).unwrap());
    let profile = PiecewiseCurve::with_unit_intervals(vec![RationalBezierCurve::polynomial(&[
        DVec3::new(0.3, -0.2, 0.0),
        DVec3::new(0.55, 0.05, 0.0),
        DVec3::new(0.2, 0.3, 0.0),
        DVec3::new(-0.25, 0.25, 0.0),
    ])
    .unwrap()])
    .unwrap();
    let (t_surface, surface) = timed(|| sweep(&rmf.framed, &profile).unwrap());

    let params = uniform_parameters(spline.domain(), FRAMES);
    let (t_eval, rational) = timed(|| {
        params
            .iter()
            .map(|&t| rmf.framed.frames().frame(t))
            .collect::<Vec<_>>()
    });
    let (t_reflection, reflected) =
        timed(|| DoubleReflectionRmf::along(&spline, params.clone(), normal).unwrap());

    let exact = ExactRmf::new(&spline, normal, 0.0).unwrap();
    let e_rational = max_angle(&exact, &params, &rational);
    let e_reflection = max_angle(&exact, &params, reflected.frames());
    let ms = |seconds: f64| seconds * 1e3;

    println!("PH cubic pipeline, {SEGMENTS} segments (conical helix), fastest of {REPEATS} runs:");
    println!("  PH spline (Table 1)            {:9.3} ms", ms(t_spline));
    println!(
        "  rational RMF (W, λ by (40))    {:9.3} ms  ({} frame pieces, degree {})",
        ms(t_rmf),
        rmf.framed.frames().segments().len(),
        rmf.framed.frames().segments()[0].degree()
    );
    println!(
        "  profile surface (42)           {:9.3} ms  ({} patches of degree ({}, {}))",
        ms(t_surface),
        surface.patches().len(),
        surface.patches()[0].degree_u(),
        surface.patches()[0].degree_v()
    );
    println!("{FRAMES} frames on the same spline:");
    println!(
        "  rational RMF, evaluated        {:9.3} ms  max angle to the exact RMF {:.3e} rad",
        ms(t_eval),
        e_rational
    );
    println!(
        "  double reflection, computed    {:9.3} ms  max angle to the exact RMF {:.3e} rad",
        ms(t_reflection),
        e_reflection
    );
    println!(
        "  ratio double reflection / rational evaluation: {:.2}; including the RMF construction: {:.2}",
        ms(t_reflection) / ms(t_eval),
        ms(t_reflection) / (ms(t_eval) + ms(t_rmf))
    );
}
