//! Convergence of the Möbius construction (Bartoň, Jüttler & Wang, §3.2): A_k (average) and
//! E_k (end point) errors of (23)–(25) for k = 1 … 64 segments,
//!
//! * on the PH cubic (21) of Example 2, against its exact RMF (closed form, Mäurer &
//!   Jüttler (30)); the paper reports order 3 for A_k and 4 for E_k;
//! * on a non-PH curve of our own, a twisted cubic, against double reflection with
//!   200,000 samples;
//! * on a helix, whose data the paper's map makes S-shaped (the fallback map is used).
//!
//! Run `cargo test --test mobius_convergence -- --nocapture` to see the tables.

use rmfsurf::glam::DVec3;
use rmfsurf::metrics::{frame_errors, FrameErrors, ReferenceRmf};
use rmfsurf::{
    mobius::approximate as mobius_approximate, ph::ExactRmf, ph::PhSpline, uniform_parameters,
    DoubleReflectionRmf, FrameField, ParametricCurve, PiecewiseCurve, RationalBezierCurve, Result,
};

const SEGMENTS: [usize; 7] = [1, 2, 4, 8, 16, 32, 64];
const INITIAL_NORMAL: DVec3 = DVec3::new(0.0, 0.0, 1.0);

/// The PH cubic (21): control points (0,1,0), (1,1,0), (1,0,0), (1,0,2).
fn example_2() -> PiecewiseCurve {
    let poles = [
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 2.0),
    ];
    PiecewiseCurve::new(
        vec![RationalBezierCurve::polynomial(&poles).unwrap()],
        vec![0.0, 1.0],
    )
    .unwrap()
}

struct PhReference {
    curve: PiecewiseCurve,
    rmf: ExactRmf,
}

impl ReferenceRmf for PhReference {
    fn curve(&self) -> &dyn ParametricCurve {
        &self.curve
    }
    fn rmf(&self, v: f64) -> Result<DVec3> {
        Ok(self.rmf.frame(v).f2)
    }
}

/// A reference RMF by double reflection on a fine sampling, evaluated by one more
/// reflection step between samples.
struct SampledReference<C: ParametricCurve> {
    curve: C,
    rmf: DoubleReflectionRmf,
}

impl<C: ParametricCurve> ReferenceRmf for SampledReference<C> {
    fn curve(&self) -> &dyn ParametricCurve {
        &self.curve
    }
    fn rmf(&self, v: f64) -> Result<DVec3> {
        let (p, t) = self.curve.point_unit_tangent(v)?;
        Ok(self.rmf.frame_at(v, p, t).f2)
    }
}

impl<C: ParametricCurve> SampledReference<C> {
    fn new(curve: C) -> Self {
        let params = uniform_parameters(curve.domain(), 200_000);
        let rmf = DoubleReflectionRmf::along(&curve, params, INITIAL_NORMAL).unwrap();
        Self { curve, rmf }
    }
}

/// (t, t² − t/2, t³/2) on [0, 1.5]: curvature and torsion both vary; not a PH curve.
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

/// (cos t, sin t, 0.4 t) on [0, 3π].
struct Helix;

impl ParametricCurve for Helix {
    fn domain(&self) -> (f64, f64) {
        (0.0, 3.0 * std::f64::consts::PI)
    }
    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        Ok((
            DVec3::new(t.cos(), t.sin(), 0.4 * t),
            DVec3::new(-t.sin(), t.cos(), 0.4),
        ))
    }
}

/// A_k, E_k for every k, printed as a table with the observed orders between doublings.
fn study(
    name: &str,
    curve: &dyn ParametricCurve,
    reference: &dyn ReferenceRmf,
) -> Vec<FrameErrors> {
    let (lo, hi) = curve.domain();
    println!("\n{name}: Möbius rational-RMF curves vs the reference RMF, (23)-(25)");
    println!(
        "{:>4} {:>12} {:>7} {:>12} {:>7}",
        "k", "A_k", "order", "E_k", "order"
    );
    let mut rows: Vec<FrameErrors> = Vec::new();
    for &k in &SEGMENTS {
        let approx = match mobius_approximate(curve, k, INITIAL_NORMAL) {
            Ok(approx) => approx,
            Err(e) => {
                println!("{k:>4}   no interpolant: {}", e.message());
                continue;
            }
        };
        let field = FrameField::from(approx);
        let errors = frame_errors(&field, reference, 2.0 * (hi - lo) / k as f64).unwrap();
        let order = |a: f64, b: f64| (a / b).log2();
        match rows.last() {
            Some(p) => println!(
                "{k:>4} {:>12.4e} {:>7.2} {:>12.4e} {:>7.2}",
                errors.average,
                order(p.average, errors.average),
                errors.end,
                order(p.end, errors.end)
            ),
            None => println!(
                "{k:>4} {:>12.4e} {:>7} {:>12.4e} {:>7}",
                errors.average, "", errors.end, ""
            ),
        }
        rows.push(errors);
    }
    rows
}

/// The order observed between k = 16 and k = 64 (two doublings; the last rows always exist).
fn fine_order(rows: &[FrameErrors], pick: impl Fn(&FrameErrors) -> f64) -> f64 {
    let n = rows.len();
    (pick(&rows[n - 3]) / pick(&rows[n - 1])).log2() / 2.0
}

/// Runs the study and asserts the fine orders of A_k and E_k.
fn assert_orders(
    name: &str,
    curve: &dyn ParametricCurve,
    reference: &dyn ReferenceRmf,
    average: f64,
    end: f64,
) {
    let rows = study(name, curve, reference);
    let (a, e) = (
        fine_order(&rows, |r| r.average),
        fine_order(&rows, |r| r.end),
    );
    println!("observed orders (k = 16 → 64): A {a:.2}, E {e:.2}; the paper reports 3 and 4 for Example 2");
    assert!(a > average, "A_k order {a}");
    assert!(e > end, "E_k order {e}");
}

#[test]
fn example_2_ph_cubic_against_its_exact_rmf() {
    let curve = example_2();
    let rmf = ExactRmf::new(&PhSpline::new(curve.clone()).unwrap(), INITIAL_NORMAL, 0.0).unwrap();
    let reference = PhReference {
        curve: curve.clone(),
        rmf,
    };
    assert_orders("Example 2, the PH cubic (21)", &curve, &reference, 2.8, 3.8);
}

#[test]
fn a_twisted_cubic_against_fine_double_reflection() {
    let reference = SampledReference::new(TwistedCubic);
    assert_orders(
        "twisted cubic (t, t² − t/2, t³/2), not PH",
        &TwistedCubic,
        &reference,
        2.8,
        3.8,
    );
}

#[test]
fn a_helix_whose_data_need_the_turning_map() {
    let reference = SampledReference::new(Helix);
    assert_orders(
        "helix (cos t, sin t, 0.4 t), S-shaped under the paper's map",
        &Helix,
        &reference,
        2.8,
        3.8,
    );
}
