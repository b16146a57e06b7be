//! The special case α₁ = 0 of Section 4 (after (25)): when s_f e^{iφ/2} = s_i e^{iη}
//! — s_f = s_i and η = ½φ, or s_f = −s_i and η = ½φ + π — condition (25) forces α₁ = 0
//! and (26) does not apply.
//!
//! Then (24) reads ρ γ² e^{iλ} K = 2 c_i s_i |β₁|² with K = c_i s_f e^{−iφ/2} − c_f s_i
//! e^{iφ/2}, so e^{iλ} = K̄/|K| · sign(c_i s_i) and |β₁|² = ρ γ² k, k = |K| / (2|c_i s_i|):
//! the paper's λ = ½π or 3⁄2π with k = |sin ½φ| (s_f = s_i), and λ = 0 or π with
//! k = |cos ½φ| (s_f = −s_i). With α₁ = 0 the displacement condition (15) is linear in
//! β̄₁: b̄₁ (a₀ + a₂) = −(2a₀b̄₀ + ⅓(a₀b̄₂ + a₂b̄₀) + 2a₂b̄₂) =: P(ρ), with a_k, b_k = α_k/γ,
//! β_k/γ as in (36). Both sides are polynomials in ρ, and |β₁|² = ρ γ² k becomes the quartic
//! |P(ρ)|² − k ρ |a₀ + a₂(ρ)|² = 0, whose positive roots give the solutions; γ follows
//! from (39)–(40) as in the general case.

use super::canonical::CanonicalHermite;
use super::hopf::HopfQuadratics;
use super::polynomial::{combine, evaluate, newton_polish, norm_squared, times_rho};
use super::sextic::{mu1_denominator, Candidate};
use crate::math::{real_roots_power, Complex};

/// |s_f e^{iφ/2} − s_i e^{iη}| / (s_i + s_f) below which η is the special value.
const SPECIAL_ETA: f64 = 1e-12;

/// Whether η is (to rounding) the special value of the α₁ = 0 case for these data.
pub(super) fn is_special(c: &CanonicalHermite, eta: f64) -> bool {
    mu1_denominator(c, eta).abs() <= SPECIAL_ETA * (c.si + c.sf)
}

/// All candidates with α₁ = 0, one per positive root of the quartic.
pub(super) fn candidates(c: &CanonicalHermite) -> Vec<Candidate> {
    let half_phi = Complex::cis(0.5 * c.phi);
    let k_factor = half_phi.conj() * (c.ci * c.sf) - half_phi * (c.cf * c.si);
    let lambda = k_factor.conj().unit() * (c.ci * c.si).signum(); // e^{iλ}
    let k = k_factor.abs() / (2.0 * (c.ci * c.si).abs());
    // a₂ = ρ c_f e^{i(λ+φ/2)} and b₂ = ρ s_f e^{i(λ−φ/2)}, written per unit ρ.
    let a2 = lambda * half_phi * c.cf;
    let b2 = lambda * half_phi.conj() * c.sf;
    let (a0, b0) = (Complex::from(c.ci), Complex::from(c.si));
    // a₀ + a₂(ρ) and P(ρ), polynomials in ρ.
    let a0_plus_a2 = [a0, a2];
    let p = [
        -(a0 * b0.conj() * 2.0),
        -(a0 * b2.conj() + a2 * b0.conj()) / 3.0,
        -(a2 * b2.conj() * 2.0),
    ];
    let quartic = combine(
        &norm_squared(&p),
        &times_rho(&norm_squared(&a0_plus_a2), k),
        -1.0,
    );
    let direct =
        |rho: f64| evaluate(&p, rho).norm_sqr() - k * rho * evaluate(&a0_plus_a2, rho).norm_sqr();
    real_roots_power(&quartic)
        .into_iter()
        .filter(|&rho| rho > 0.0)
        .map(|rho| newton_polish(&quartic, rho, direct))
        .filter_map(|rho| {
            let denominator = evaluate(&a0_plus_a2, rho);
            (denominator.abs() > 0.0).then(|| Candidate {
                rho,
                normalized: HopfQuadratics {
                    alpha: [a0, Complex::ZERO, a2 * rho],
                    beta: [b0, (evaluate(&p, rho) / denominator).conj(), b2 * rho],
                },
            })
        })
        .collect()
}
