//! Benchmark of cone splines: fitting a cone spline within 1e-4 to the tangent surface of a
//! twisted cubic (a NURBS curve) and of a helix (an analytic curve), and developing it
//! (exact development plus its degree (1, 2) NURBS surface).
//!
//!     cargo bench --bench cone_spline

use rmfsurf::glam::DVec3;
use rmfsurf::{
    cone::approximate as approximate_developable, cone::ConeSpline, cone::Rule,
    cone::TangentSurface, NurbsSurface, ParametricCurve, PiecewiseCurve, RationalBezierCurve,
};
use std::hint::black_box;
use std::time::Instant;

struct Helix;

impl ParametricCurve for Helix {
    fn domain(&self) -> (f64, f64) {
        (0.0, std::f64::consts::PI)
    }

    fn point_derivative(&self, t: f64) -> rmfsurf::Result<(DVec3, DVec3)> {
        let (s, c) = t.sin_cos();
        Ok((DVec3::new(c, s, 0.5 * t), DVec3::new(-s, c, 0.5)))
    }
}

fn twisted_cubic() -> PiecewiseCurve {
    let power = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    let segment = RationalBezierCurve::from_power(&power)
        .unwrap()
        .restricted(0.2, 1.2);
    PiecewiseCurve::new(vec![segment], vec![0.2, 1.2]).unwrap()
}

/// Mean seconds per call of `f` over enough runs to take about half a second.
fn time<T>(mut f: impl FnMut() -> T) -> f64 {
    let start = Instant::now();
    black_box(f());
    let once = start.elapsed().as_secs_f64().max(1e-7);
    let runs = ((0.5 / once) as usize).clamp(3, 10_000);
    let start = Instant::now();
    for _ in 0..runs {
        black_box(f());
    }
    start.elapsed().as_secs_f64() / runs as f64
}

fn develop(spline: &ConeSpline) -> NurbsSurface {
    let flat = spline.developed().unwrap();
    NurbsSurface::from_piecewise(&flat.surface(-0.2, 0.2).unwrap()).unwrap()
}

fn main() {
    let cubic = twisted_cubic();
    let inputs: [(&str, &dyn ParametricCurve); 2] = [
        ("twisted cubic (NURBS)", &cubic),
        ("helix (analytic)", &Helix),
    ];
    println!("cone spline benchmark: tolerance 1e-4, region v in [0.5, 8] from the curve, half a turn of the helix");
    for (name, curve) in inputs {
        let surface = TangentSurface::new(curve, 0.5, 8.0).unwrap();
        let fit =
            approximate_developable(&surface, 1e-4, Rule::MinimalVertexDistance, 100_000).unwrap();
        let fit_time = time(|| {
            approximate_developable(&surface, 1e-4, Rule::MinimalVertexDistance, 100_000).unwrap()
        });
        let develop_time = time(|| develop(&fit.spline));
        println!(
            "  {name:<22} {:>4} pieces (deviation {:.2e}): fit {:>8.3} ms, develop + NURBS {:>8.1} us",
            fit.spline.pieces().len(),
            fit.max_error,
            fit_time * 1e3,
            develop_time * 1e6
        );
    }
}
