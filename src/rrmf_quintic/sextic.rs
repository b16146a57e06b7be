//! The general case of Section 4 for one value of the angular parameter η, eqs. (25)–(38):
//! α₁ ≠ 0, β₁ = μ₁ α₁ (26).
//!
//! With ε = c_i c_f e^{−iφ/2} + s_i s_f e^{iφ/2} (step 4 of the Algorithm), η fixes
//! μ₀ (28) — hence the phase λ of the end coefficients, e^{−iλ} = μ₀ — μ₁ (32) and f₁ (29).
//! The end-derivative ratio ρ (20) is then a positive root of the sextic (35),
//! |δ̄₀δ₂ − δ₁δ̄₂|² − ρ f₁ (|δ₀|² − |δ₁|²)² = 0, whose coefficients (34) come here from the
//! products of the δ's of (31) written as polynomials in ρ — the same expansion the paper
//! does by hand, without transcribing its twenty terms. Every positive root gives the
//! normalized coefficients a_k, b_k of (36)–(38), α_k = γ a_k and β_k = γ b_k. Roots are
//! found without a starting guess (`real_roots_power`) and polished against (33) itself.
//!
//! The exceptional pairs with |δ₀| = |δ₁| (after (32)) are handled too: (30) is then a
//! single real condition on α₁, a line in the complex plane, and |α₁|² = ρ γ² f₁ (29) a
//! circle; their intersections are the solutions.

use super::canonical::CanonicalHermite;
use super::hopf::HopfQuadratics;
use super::polynomial::{
    combine, conjugate, evaluate, multiply, newton_polish, norm_squared, times_rho,
};
use crate::math::{quadratic_roots, real_roots_power, Complex};

/// Relative size of |δ₀|² − |δ₁|² below which (30) is treated as the single real
/// condition of the exceptional case rather than divided by.
const EQUAL_DELTAS: f64 = 1e-8;

/// A candidate solution before scaling by γ: ρ and the a_k, b_k of (37)–(38).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Candidate {
    pub rho: f64,
    pub normalized: HopfQuadratics,
}

/// What η fixes before ρ is known: e^{iφ/2}, μ₀ (28), μ₁ (32) and f₁ (29).
struct EtaTerms {
    half_phi: Complex,
    mu0: Complex,
    mu1: Complex,
    f1: f64,
}

/// s_f e^{iφ/2} − s_i e^{iη}: the denominator of μ₁ (32); it vanishes exactly in the
/// special case α₁ = 0 (s_f = s_i and η = ½φ), handled in `special`.
pub(super) fn mu1_denominator(c: &CanonicalHermite, eta: f64) -> Complex {
    Complex::cis(0.5 * c.phi) * c.sf - Complex::cis(eta) * c.si
}

fn eta_terms(c: &CanonicalHermite, eta: f64) -> EtaTerms {
    let half_phi = Complex::cis(0.5 * c.phi);
    let e = Complex::cis(eta);
    let epsilon = half_phi.conj() * (c.ci * c.cf) + half_phi * (c.si * c.sf);
    let denominator = mu1_denominator(c, eta);
    // |e^{iη} − ε| > 0 for every η because |ε| < 1 for non-planar data (footnote 4).
    let e_minus_epsilon = e - epsilon;
    EtaTerms {
        half_phi,
        mu0: e_minus_epsilon.conj().unit(),
        mu1: (e * c.ci - half_phi.conj() * c.cf) / denominator,
        f1: 0.5 * denominator.norm_sqr() / e_minus_epsilon.abs(),
    }
}

/// The δ's of (31) as polynomials in ρ (ascending powers).
struct Deltas {
    d0: [Complex; 2],
    d1: [Complex; 2],
    d2: [Complex; 3],
}

impl Deltas {
    /// δ₀, δ₁, δ₂ at ρ.
    fn at(&self, rho: f64) -> (Complex, Complex, Complex) {
        (
            evaluate(&self.d0, rho),
            evaluate(&self.d1, rho),
            evaluate(&self.d2, rho),
        )
    }
}

fn deltas(c: &CanonicalHermite, t: &EtaTerms) -> Deltas {
    let h = t.half_phi.conj(); // e^{−iφ/2}
    let (ci, si, cf, sf) = (c.ci, c.si, c.cf, c.sf);
    Deltas {
        d0: [t.mu1 * (3.0 * ci), t.mu0 * h * t.mu1 * (3.0 * cf)],
        d1: [Complex::from(3.0 * si), t.mu0.conj() * h * (3.0 * sf)],
        d2: [
            Complex::from(-6.0 * ci * si),
            -(t.mu1 * (4.0 * t.f1)) - h * (t.mu0.conj() * (ci * sf) + t.mu0 * (cf * si)),
            h * h * (-6.0 * cf * sf),
        ],
    }
}

/// δ̄₀δ₂ − δ₁δ̄₂ = Σ z_k ρ^k (k ≤ 3), the numerator of α₁/γ (after (32)).
fn numerator(d: &Deltas) -> Vec<Complex> {
    let (a, b) = (
        multiply(&conjugate(&d.d0), &d.d2),
        multiply(&d.d1, &conjugate(&d.d2)),
    );
    a.iter().zip(&b).map(|(&x, &y)| x - y).collect()
}

/// The sextic (35) in ρ, ascending coefficients c₀, c₁ − e₀f₁, …, c₆.
fn sextic(d: &Deltas, f1: f64) -> Vec<f64> {
    // |δ₀|² − |δ₁|² = Σ (d₀ₖ − d₁ₖ) ρ^k (k ≤ 2), squared: Σ e_j ρ^j.
    let difference = combine(&norm_squared(&d.d0), &norm_squared(&d.d1), -1.0);
    let e = multiply(&difference, &difference);
    combine(&norm_squared(&numerator(d)), &times_rho(&e, f1), -1.0)
}

/// All candidates of the general case for this η, one or two per positive root of (35),
/// and those of the exceptional case (after (32)) at the positive roots of
/// |δ₀|² − |δ₁|², first. There both terms of (35) vanish to second order, so (35) has a
/// double root, which a root finder reports to only half the digits, or as a complex pair
/// and not at all; the quadratic gives it to full precision. A candidate found both ways
/// is one solution twice; the verification keeps one.
pub(super) fn candidates(c: &CanonicalHermite, eta: f64) -> Vec<Candidate> {
    let terms = eta_terms(c, eta);
    let d = deltas(c, &terms);
    let p = sextic(&d, terms.f1);
    let general = real_roots_power(&p)
        .into_iter()
        .filter(|&rho| rho > 0.0)
        .map(|rho| polish(&d, terms.f1, &p, rho))
        .map(|rho| (rho, alpha1_values(&d, terms.f1, rho)));
    let exceptional = equal_delta_roots(&d)
        .into_iter()
        .map(|rho| (rho, exceptional_alpha1_values(&d, terms.f1, rho)));
    let terms = &terms;
    exceptional
        .chain(general)
        .flat_map(|(rho, values)| {
            values.into_iter().map(move |a1| Candidate {
                rho,
                normalized: coefficients(c, terms, rho, a1),
            })
        })
        .collect()
}

/// The positive roots of |δ₀|² − |δ₁|², a quadratic in ρ.
fn equal_delta_roots(d: &Deltas) -> Vec<f64> {
    let e = combine(&norm_squared(&d.d0), &norm_squared(&d.d1), -1.0);
    quadratic_roots(e[2], e[1], e[0])
        .into_iter()
        .filter(|&rho| rho > 0.0)
        .collect()
}

/// For tests that look for data reaching the exceptional case: each positive root ρ of
/// |δ₀|² − |δ₁|² with the sine of the phase of δ₂ against the line of (30), zero exactly
/// when (35) vanishes there.
#[cfg(test)]
pub(super) fn exceptional_phases(c: &CanonicalHermite, eta: f64) -> Vec<(f64, f64)> {
    let d = deltas(c, &eta_terms(c, eta));
    equal_delta_roots(&d)
        .into_iter()
        .map(|rho| {
            let (d0, d1, d2) = d.at(rho);
            let z = d2 * Complex::cis(-0.5 * (d0.arg() + d1.arg()));
            (rho, z.im / z.abs())
        })
        .collect()
}

/// The solutions of (29)–(30) at a root ρ of |δ₀|² − |δ₁|².
fn exceptional_alpha1_values(d: &Deltas, f1: f64, rho: f64) -> Vec<Complex> {
    let (d0, d1, d2) = d.at(rho);
    line_circle(d0, d1, d2, rho * f1)
}

/// ρ polished by Newton steps on (33) evaluated from the δ's themselves: the expanded
/// coefficients (34) lose the digits that the factors keep.
fn polish(d: &Deltas, f1: f64, sextic: &[f64], rho: f64) -> f64 {
    newton_polish(sextic, rho, |rho| {
        let (d0, d1, d2) = d.at(rho);
        let difference = d0.norm_sqr() - d1.norm_sqr();
        (d0.conj() * d2 - d1 * d2.conj()).norm_sqr() - rho * f1 * difference * difference
    })
}

/// The solutions a₁ = α₁/γ of (30), δ₀ a₁ + δ₁ ā₁ = δ₂, at a root ρ.
fn alpha1_values(d: &Deltas, f1: f64, rho: f64) -> Vec<Complex> {
    let (d0, d1, d2) = d.at(rho);
    let difference = d0.norm_sqr() - d1.norm_sqr();
    if difference.abs() > EQUAL_DELTAS * (d0.norm_sqr() + d1.norm_sqr()) {
        // The general case: a₁ = (δ̄₀δ₂ − δ₁δ̄₂) / (|δ₀|² − |δ₁|²) (after (32)).
        return vec![(d0.conj() * d2 - d1 * d2.conj()) / difference];
    }
    line_circle(d0, d1, d2, rho * f1)
}

/// The exceptional case |δ₀| = |δ₁| = r: with δ₀ = r e^{iA}, δ₁ = r e^{iB} and
/// u = e^{i(A−B)/2}, (30) reads 2r Re(u a₁) e^{i(A+B)/2} = δ₂, a line; (29) is the circle
/// |a₁|² = ρ f₁. Consistency of δ₂'s phase is left to the verification by substitution.
fn line_circle(d0: Complex, d1: Complex, d2: Complex, radius_squared: f64) -> Vec<Complex> {
    let r = 0.5 * (d0.abs() + d1.abs());
    if r == 0.0 {
        return Vec::new();
    }
    let (a, b) = (d0.arg(), d1.arg());
    let u = Complex::cis(0.5 * (a - b));
    let along = (d2 * Complex::cis(-0.5 * (a + b))).re / (2.0 * r);
    let across_squared = radius_squared - along * along;
    if across_squared < 0.0 {
        return Vec::new();
    }
    let across = across_squared.sqrt();
    let mut values = vec![u.conj() * Complex::new(along, across)];
    if across > 0.0 {
        values.push(u.conj() * Complex::new(along, -across));
    }
    values
}

/// a_k, b_k of (37)–(38) for a root ρ and a₁.
fn coefficients(c: &CanonicalHermite, t: &EtaTerms, rho: f64, a1: Complex) -> HopfQuadratics {
    // e^{iλ} = μ̄₀ by (28).
    let end = t.mu0.conj() * rho;
    HopfQuadratics {
        alpha: [Complex::from(c.ci), a1, end * t.half_phi * c.cf],
        beta: [
            Complex::from(c.si),
            t.mu1 * a1,
            end * t.half_phi.conj() * c.sf,
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hermite::HermiteSegment;
    use glam::DVec3;

    fn data() -> CanonicalHermite {
        let d = HermiteSegment::new(
            DVec3::ZERO,
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::ONE,
            DVec3::new(0.0, 1.0, 1.0),
        )
        .unwrap();
        CanonicalHermite::new(&d).unwrap()
    }

    /// The sextic assembled from products agrees with the paper's explicit z₀, z₃ and
    /// d_jk (after (33)) and with (33) evaluated directly.
    #[test]
    fn sextic_matches_the_papers_expansion() {
        let c = data();
        for eta in [0.3, 2.0, 4.325, 5.2] {
            let t = eta_terms(&c, eta);
            let d = deltas(&c, &t);
            let (ci, si, cf, sf) = (c.ci, c.si, c.cf, c.sf);
            let h = t.half_phi; // e^{iφ/2}
            let (mu0, mu1) = (t.mu0, t.mu1);
            let z0 = (Complex::from(si) - mu1.conj() * ci) * (18.0 * ci * si);
            let z3 = mu0.conj() * (h * sf - mu1.conj() * h.conj() * cf) * (18.0 * cf * sf);
            let z = numerator(&d);
            assert!((z[0] - z0).abs() < 1e-12 * z0.abs());
            assert!((z[3] - z3).abs() < 1e-12 * z3.abs());
            let m = mu1.norm_sqr();
            let d0 = [
                9.0 * m * ci * ci,
                9.0 * m * ci * cf * (mu0 * h.conj() + mu0.conj() * h).re,
                9.0 * m * cf * cf,
            ];
            let n0 = norm_squared(&d.d0);
            for k in 0..3 {
                assert!((n0[k] - d0[k]).abs() < 1e-12 * d0[0].abs().max(d0[2].abs()));
            }
            let p = sextic(&d, t.f1);
            for rho in [0.2, 1.0, 3.0] {
                let (a, b, e) = d.at(rho);
                let direct = (a.conj() * e - b * e.conj()).norm_sqr()
                    - rho * t.f1 * (a.norm_sqr() - b.norm_sqr()).powi(2);
                let value: f64 = p.iter().rev().fold(0.0, |acc, &x| acc * rho + x);
                assert!((value - direct).abs() < 1e-11 * direct.abs().max(1.0));
            }
        }
    }

    #[test]
    fn line_circle_solves_the_exceptional_case() {
        let (d0, d1) = (Complex::cis(0.4) * 2.0, Complex::cis(-1.1) * 2.0);
        // δ₂ = δ₀ x + δ₁ x̄ for a chosen x, so the data are consistent.
        let x = Complex::new(0.3, -0.8);
        let d2 = d0 * x + d1 * x.conj();
        let values = line_circle(d0, d1, d2, x.norm_sqr());
        assert_eq!(values.len(), 2);
        assert!(values.iter().any(|&v| (v - x).abs() < 1e-14));
        for v in values {
            assert!((d0 * v + d1 * v.conj() - d2).abs() < 1e-14);
            assert!((v.norm_sqr() - x.norm_sqr()).abs() < 1e-14);
        }
        assert!(
            line_circle(d0, d1, d2, 0.01).is_empty(),
            "circle misses the line"
        );
    }
}
