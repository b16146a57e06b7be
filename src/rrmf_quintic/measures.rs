//! Shape measures of a quintic, the "shape integrals" by which Section 5 compares the
//! members of the η family (footnote 6; (89) of Farouki, Giannelli, Manni & Sestini 2008):
//!
//! * arc length L = ∫₀¹ σ dt — exact: σ is a quartic, and the integral of a Bernstein
//!   polynomial is the mean of its coefficients;
//! * Frenet-frame energy E = ∫ (κ² + τ²) ds, the squared angular velocity of the Frenet
//!   frame integrated over arc length;
//! * RMF energy E_rmf = ∫ κ² ds, the same for the rotation-minimizing frame (its angular
//!   velocity has no component along the tangent).
//!
//! With r' = H(α, β), κ = |r' × r''| / σ³ and τ = (r' × r'') · r''' / |r' × r''|², so
//! κ² σ = |r' × r''|² / σ⁵ and τ² σ = ((r' × r'') · r''')² σ / |r' × r''|⁴; both are
//! integrated together by composite Gauss–Legendre quadrature.

use super::hopf::HopfQuadratics;
use crate::bezier::bernstein::{derivative, evaluate, to_power};
use crate::math::{real_roots_in, GaussLegendre};
use std::sync::OnceLock;

/// Gauss–Legendre points per piece and pieces of [0, 1]: the integrands are smooth rational
/// functions; for Example 1 the 240 points agree with 40,000 to 5e-15 relative.
const NODES: usize = 10;
const PIECES: usize = 24;

/// L, E and E_rmf of one curve.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShapeMeasures {
    /// Arc length L.
    pub arc_length: f64,
    /// Frenet-frame energy E = ∫ (κ² + τ²) ds.
    pub energy_frenet: f64,
    /// RMF energy E_rmf = ∫ κ² ds.
    pub energy_rmf: f64,
}

/// Which shape measure to minimize when choosing η.
///
/// E and E_rmf of a curve scaled by s are E/s and E_rmf/s, and the η family contains
/// interpolants of unbounded size (γ → ∞ in (39) as f₂ → 0⁺: a closed loop, scaled up,
/// plus the chord), whose energies tend to zero. Minimizing E or E_rmf themselves can
/// therefore return a huge loop; the scaled energies L·E and L·E_rmf — the energies of the
/// curve scaled to unit length — compare shapes, not sizes, and pick fair curves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShapeMeasure {
    /// E_rmf = ∫ κ² ds.
    EnergyRmf,
    /// E = ∫ (κ² + τ²) ds.
    EnergyFrenet,
    /// L = ∫ σ dt.
    ArcLength,
    /// L · E_rmf, invariant under scaling.
    ScaledEnergyRmf,
    /// L · E, invariant under scaling.
    ScaledEnergyFrenet,
}

impl ShapeMeasures {
    /// The measures of the curve scaled by `factor`: L·factor, E/factor, E_rmf/factor.
    pub fn scaled(&self, factor: f64) -> Self {
        Self {
            arc_length: self.arc_length * factor,
            energy_frenet: self.energy_frenet / factor,
            energy_rmf: self.energy_rmf / factor,
        }
    }

    /// The chosen measure's value.
    pub fn get(&self, which: ShapeMeasure) -> f64 {
        match which {
            ShapeMeasure::EnergyRmf => self.energy_rmf,
            ShapeMeasure::EnergyFrenet => self.energy_frenet,
            ShapeMeasure::ArcLength => self.arc_length,
            ShapeMeasure::ScaledEnergyRmf => self.arc_length * self.energy_rmf,
            ShapeMeasure::ScaledEnergyFrenet => self.arc_length * self.energy_frenet,
        }
    }
}

fn rule() -> &'static GaussLegendre {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    RULE.get_or_init(|| GaussLegendre::new(NODES))
}

/// L = ∫₀¹ σ dt, exactly: the mean of the Bernstein coefficients of σ.
pub(crate) fn arc_length(hopf: &HopfQuadratics) -> f64 {
    let speed = hopf.speed();
    speed.iter().sum::<f64>() / speed.len() as f64
}

/// The least and the greatest speed σ on [0, 1]: at the ends or where σ' = 0.
pub(crate) fn speed_range(hopf: &HopfQuadratics) -> (f64, f64) {
    let speed = hopf.speed();
    let critical = real_roots_in(&to_power(&derivative(&speed)), 0.0, 1.0);
    [0.0, 1.0]
        .into_iter()
        .chain(critical)
        .map(|t| evaluate(&speed, t))
        .fold((f64::INFINITY, 0.0), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// L, E and E_rmf of the quintic with hodograph H(α, β).
pub(crate) fn shape_measures(hopf: &HopfQuadratics) -> ShapeMeasures {
    // The first three derivatives of r by Horner on the power form of the quartic
    // hodograph: on [0, 1] as accurate as de Casteljau, and much faster in this inner loop.
    let h = to_power(&hopf.hodograph());
    let jet = |t: f64| {
        let d1 = (((h[4] * t + h[3]) * t + h[2]) * t + h[1]) * t + h[0];
        let d2 = ((h[4] * (4.0 * t) + h[3] * 3.0) * t + h[2] * 2.0) * t + h[1];
        let d3 = (h[4] * (12.0 * t) + h[3] * 6.0) * t + h[2] * 2.0;
        (d1, d2, d3)
    };
    // κ²σ and τ²σ at t: the integrands over t of κ² ds and τ² ds.
    let integrands = |t: f64| {
        let (d1, d2, d3) = jet(t);
        let binormal = d1.cross(d2);
        let b2 = binormal.length_squared();
        let sigma = d1.length();
        let kappa2 = b2 / sigma.powi(5);
        let tau2 = if b2 > 0.0 {
            let twist = binormal.dot(d3);
            twist * twist * sigma / (b2 * b2)
        } else {
            f64::INFINITY // no Frenet frame where κ = 0
        };
        (kappa2, tau2)
    };
    let (mut energy_rmf, mut torsion) = (0.0, 0.0);
    let step = 1.0 / PIECES as f64;
    for piece in 0..PIECES {
        for (&x, &w) in rule().nodes().iter().zip(rule().weights()) {
            let (kappa2, tau2) = integrands((piece as f64 + x) * step);
            energy_rmf += w * step * kappa2;
            torsion += w * step * tau2;
        }
    }
    ShapeMeasures {
        arc_length: arc_length(hopf),
        energy_frenet: energy_rmf + torsion,
        energy_rmf,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Complex;

    /// Arbitrary (not RRMF) coefficients: the composite rule against a much finer one.
    #[test]
    fn measures_agree_with_a_much_finer_quadrature() {
        use crate::bezier::bernstein::evaluate_jet;
        let h = HopfQuadratics {
            alpha: [
                Complex::new(1.3, 0.0),
                Complex::new(0.2, 0.9),
                Complex::new(-0.7, 0.4),
            ],
            beta: [
                Complex::new(0.4, 0.1),
                Complex::new(-0.6, 0.5),
                Complex::new(0.3, -0.8),
            ],
        };
        let m = shape_measures(&h);
        let fine = GaussLegendre::new(20);
        let hodograph = h.hodograph();
        let reference = |power: i32| {
            fine.integrate_composite(0.0, 1.0, 400, |t| {
                let j = evaluate_jet(&hodograph, t);
                let s = j.value.length();
                if power == 1 {
                    s
                } else {
                    j.value.cross(j.d1).length_squared() / s.powi(5)
                }
            })
        };
        assert!((m.arc_length - reference(1)).abs() < 1e-13 * m.arc_length);
        assert!((m.energy_rmf - reference(2)).abs() < 1e-10 * m.energy_rmf);
        assert!(m.energy_frenet > m.energy_rmf);
        assert_eq!(m.get(ShapeMeasure::ArcLength), m.arc_length);
    }

    #[test]
    fn speed_range_finds_interior_minima() {
        // α(t) = (1 − 2t)², β(t) = 0.2i t(1 − t): σ = |α|² + |β|² dips to about 0.0025
        // twice near t = ½ (at 1 − 2t = ±0.05), and is 1 at both ends.
        let h = HopfQuadratics {
            alpha: [Complex::ONE, Complex::new(-1.0, 0.0), Complex::ONE],
            beta: [Complex::ZERO, Complex::new(0.0, 0.1), Complex::ZERO],
        };
        let (lo, hi) = speed_range(&h);
        let speed = h.speed();
        let sampled = (0..=100_000)
            .map(|i| evaluate(&speed, i as f64 / 100_000.0))
            .fold(f64::INFINITY, f64::min);
        assert!(
            lo <= sampled && sampled - lo < 1e-12,
            "{lo} vs sampled {sampled}"
        );
        assert!(lo < 0.0025 && (hi - 1.0).abs() < 1e-15);
    }

    #[test]
    fn a_straight_line_has_no_curvature() {
        let one = Complex::ONE;
        let h = HopfQuadratics {
            alpha: [one, one * 2.0, one],
            beta: [Complex::ZERO; 3],
        };
        // α(t) = 1 + 2t − 2t², σ = α², L = ∫ (1 + 4t − 8t³ + 4t⁴) dt = 9/5.
        let m = shape_measures(&h);
        assert!((m.arc_length - 1.8).abs() < 1e-15);
        assert_eq!(m.energy_rmf, 0.0);
        assert!(m.energy_frenet.is_infinite(), "no Frenet frame on a line");
    }
}
