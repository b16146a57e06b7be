//! Benchmark of RRMF quintics (Farouki, Giannelli & Sestini): `cargo bench --bench rrmf_quintic`.
//!
//! * single G1 Hermite problems: all solutions for one η (the sextic, its roots, the
//!   verification and the shape measures of every solution), and the choice of η;
//! * a 1,000-segment spline along a helix: η per segment, then the exact rational RMF of the
//!   whole spline, with the double-reflection RMF (the library's reference method) of the
//!   same curve beside it — its time, and its distance from the exact frame;
//! * the work of choosing η: solves (sextics for one η) per segment and time per solve,
//!   the figures the header documents for eta_samples and max_evaluations.

use rmfsurf::glam::DVec3;
use rmfsurf::{
    hermite_sequence, rrmf::best_quintic, rrmf::best_quintic_within, rrmf::quintic_curve,
    rrmf::quintic_rmf, rrmf::quintics as rrmf_quintics, rrmf::spline as rrmf_spline,
    rrmf::Budget as RrmfBudget, rrmf::ShapeMeasure, uniform_parameters, DoubleReflectionRmf,
    HermiteSegment,
};
use std::f64::consts::{PI, TAU};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Runs `f` repeatedly for about `budget` and returns the mean time per call.
fn time_per_call(budget: Duration, mut f: impl FnMut()) -> Duration {
    f(); // warm-up
    let start = Instant::now();
    let mut calls = 0u32;
    while start.elapsed() < budget {
        f();
        calls += 1;
    }
    start.elapsed() / calls
}

fn per_second(d: Duration) -> f64 {
    1.0 / d.as_secs_f64()
}

/// Hermite data sampled from the helix (sin t, cos t, t) at t = k h.
fn helix(count: usize, h: f64) -> (Vec<DVec3>, Vec<DVec3>) {
    (0..count)
        .map(|k| {
            let t = k as f64 * h;
            (
                DVec3::new(t.sin(), t.cos(), t),
                DVec3::new(t.cos(), -t.sin(), 1.0),
            )
        })
        .unzip()
}

fn single_problems() {
    let example_1 = HermiteSegment::new(
        DVec3::ZERO,
        DVec3::new(1.0, 0.0, 1.0),
        DVec3::ONE,
        DVec3::new(0.0, 1.0, 1.0),
    )
    .unwrap();
    let budget = Duration::from_millis(700);
    let one = time_per_call(budget, || {
        black_box(rrmf_quintics(black_box(&example_1), 4.325).unwrap());
    });
    println!(
        "rrmf_quintics, Example 1, η = 4.325 (2 solutions): {:.1} µs per call, {:.0} solutions/s",
        one.as_secs_f64() * 1e6,
        2.0 * per_second(one)
    );
    // A sweep over η, where some η have no solution: solutions per second of work.
    let etas: Vec<f64> = (0..360).map(|k| TAU * k as f64 / 360.0).collect();
    let mut found = 0usize;
    let start = Instant::now();
    for &eta in &etas {
        found += black_box(rrmf_quintics(&example_1, eta).unwrap()).len();
    }
    let scan = start.elapsed();
    println!(
        "rrmf_quintics over 360 values of η: {found} solutions in {:.2} ms, {:.0} solutions/s, {:.0} η/s",
        scan.as_secs_f64() * 1e3,
        found as f64 / scan.as_secs_f64(),
        360.0 / scan.as_secs_f64()
    );
    for samples in [32, 128] {
        let best = time_per_call(budget, || {
            black_box(best_quintic(&example_1, ShapeMeasure::ScaledEnergyRmf, samples).unwrap());
        });
        println!(
            "best_quintic (L·E_rmf, N_η = {samples}): {:.2} ms per Hermite problem, {:.0} problems/s",
            best.as_secs_f64() * 1e3,
            per_second(best)
        );
    }
}

fn spline_of_1000_segments() {
    let (points, tangents) = helix(1001, PI / 8.0);
    let segments = hermite_sequence(&points, &tangents).unwrap();
    let normal = DVec3::new(-1.0, 0.0, 0.0);
    for samples in [16, 64] {
        let start = Instant::now();
        let spline =
            rrmf_spline(&segments, ShapeMeasure::ScaledEnergyRmf, samples, normal).unwrap();
        let total = start.elapsed();
        println!(
            "rrmf_spline, 1,000 segments, N_η = {samples}: {:.3} s ({:.2} ms per segment, {} frame pieces)",
            total.as_secs_f64(),
            total.as_secs_f64(), // seconds per 1,000 segments = ms per segment
            spline.framed.frames().segments().len()
        );
        black_box(spline);
    }
    // The frames alone, for the quintics chosen above: exact rational RMF vs double reflection.
    let spline = rrmf_spline(&segments, ShapeMeasure::ScaledEnergyRmf, 16, normal).unwrap();
    let quintics = &spline.quintics;
    let curve = quintic_curve(quintics).unwrap();
    let rational = time_per_call(Duration::from_millis(700), || {
        black_box(quintic_rmf(quintics, normal).unwrap());
    });
    println!(
        "exact rational RMF of the 1,000-segment spline: {:.2} ms ({:.2} µs per segment)",
        rational.as_secs_f64() * 1e3,
        rational.as_secs_f64() * 1e3 // ms per 1,000 segments = µs per segment
    );
    let exact = quintic_rmf(quintics, normal).unwrap();
    let start_normal = exact.frame(0.0).f2;
    for per_segment in [4, 16, 64] {
        let params = uniform_parameters(curve.domain(), 1000 * per_segment + 1);
        let dr_time = time_per_call(Duration::from_millis(700), || {
            black_box(DoubleReflectionRmf::along(&curve, params.clone(), start_normal).unwrap());
        });
        let dr = DoubleReflectionRmf::along(&curve, params.clone(), start_normal).unwrap();
        let error = params
            .iter()
            .zip(dr.frames())
            .map(|(&t, f)| (exact.frame(t).f2 - f.f2).length())
            .fold(0.0, f64::max);
        println!(
            "double reflection, {per_segment} samples per segment: {:.2} ms, max |f₂ − exact f₂| = {error:.1e}",
            dr_time.as_secs_f64() * 1e3
        );
    }
    // Frame evaluation at 100,000 parameters.
    let params = uniform_parameters(curve.domain(), 100_001);
    let dr = DoubleReflectionRmf::along(
        &curve,
        uniform_parameters(curve.domain(), 16_001),
        start_normal,
    )
    .unwrap();
    let eval_rational = time_per_call(Duration::from_millis(500), || {
        for &t in &params {
            black_box(exact.frame(t));
        }
    });
    let eval_dr = time_per_call(Duration::from_millis(500), || {
        for &t in &params {
            let jet = curve.eval_jet(t);
            black_box(dr.frame_at(t, jet.point, jet.d1.normalize()));
        }
    });
    println!(
        "frame evaluation: exact rational {:.0} ns, double reflection (16 samples/segment) {:.0} ns per frame",
        eval_rational.as_secs_f64() * 1e9 / 100_001.0,
        eval_dr.as_secs_f64() * 1e9 / 100_001.0
    );
}

/// Solves and time per segment for growing N_η, on Example 1 and on one helix segment.
fn work_per_segment() {
    let example_1 = HermiteSegment::new(
        DVec3::ZERO,
        DVec3::new(1.0, 0.0, 1.0),
        DVec3::ONE,
        DVec3::new(0.0, 1.0, 1.0),
    )
    .unwrap();
    let (points, tangents) = helix(2, PI / 2.0);
    let helix_segment = hermite_sequence(&points, &tangents).unwrap()[0];
    for (name, data) in [
        ("Example 1", example_1),
        ("helix, quarter turn", helix_segment),
    ] {
        for samples in [16, 1_000, 100_000] {
            let mut budget = RrmfBudget::unlimited();
            let start = Instant::now();
            black_box(
                best_quintic_within(&data, ShapeMeasure::ScaledEnergyRmf, samples, &mut budget)
                    .unwrap(),
            );
            let time = start.elapsed().as_secs_f64();
            println!(
                "work, {name}, N_η = {samples}: {} solves ({} refining), {:.3} ms per segment, \
                 {:.1} µs per solve",
                budget.spent,
                budget.spent - samples,
                time * 1e3,
                time * 1e6 / budget.spent as f64
            );
        }
    }
}

fn main() {
    // `cargo bench` passes --bench; `cargo test --benches` runs this once as a smoke test.
    let smoke = std::env::args().all(|a| a != "--bench");
    if smoke {
        let d = HermiteSegment::new(
            DVec3::ZERO,
            DVec3::X + DVec3::Z,
            DVec3::ONE,
            DVec3::Y + DVec3::Z,
        );
        assert_eq!(rrmf_quintics(&d.unwrap(), 5.2).unwrap().len(), 2);
        return;
    }
    work_per_segment();
    single_problems();
    spline_of_1000_segments();
}
