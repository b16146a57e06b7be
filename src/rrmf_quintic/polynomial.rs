//! Polynomials in ρ in power form, `Σ c_k ρ^k` (ascending), with real or complex
//! coefficients: the δ's of (31) are polynomials in ρ of degree ≤ 2, and the sextic (35)
//! is assembled from their products exactly as (34) does by hand, and its roots are polished
//! against the factored form.

use crate::math::Complex;
use std::ops::{Add, Mul};

/// Coefficients of `a · b`.
pub(super) fn multiply<T>(a: &[T], b: &[T]) -> Vec<T>
where
    T: Copy + Default + Add<Output = T> + Mul<Output = T>,
{
    let mut out = vec![T::default(); a.len() + b.len() - 1];
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            out[i + j] = out[i + j] + x * y;
        }
    }
    out
}

/// Coefficients of `a + sign · b` (lengths may differ).
pub(super) fn combine(a: &[f64], b: &[f64], sign: f64) -> Vec<f64> {
    (0..a.len().max(b.len()))
        .map(|k| a.get(k).copied().unwrap_or(0.0) + sign * b.get(k).copied().unwrap_or(0.0))
        .collect()
}

/// Coefficients of `factor · ρ · p(ρ)`.
pub(super) fn times_rho(p: &[f64], factor: f64) -> Vec<f64> {
    std::iter::once(0.0)
        .chain(p.iter().map(|&c| c * factor))
        .collect()
}

/// The polynomial with conjugated coefficients: p̄(ρ) = conj(p(ρ)) for real ρ.
pub(super) fn conjugate(p: &[Complex]) -> Vec<Complex> {
    p.iter().map(|z| z.conj()).collect()
}

/// `|p(ρ)|²` for real ρ, as a real polynomial: p · p̄.
pub(super) fn norm_squared(p: &[Complex]) -> Vec<f64> {
    multiply(p, &conjugate(p)).iter().map(|z| z.re).collect()
}

/// p(ρ) by Horner's rule.
pub(super) fn evaluate(p: &[Complex], rho: f64) -> Complex {
    p.iter().rev().fold(Complex::ZERO, |acc, &c| acc * rho + c)
}

/// A root of the real polynomial `p` polished by Newton steps whose residual comes from
/// `direct`, an evaluation of the same polynomial from its factors (more accurate than
/// Horner on expanded coefficients, which cancel). A step is kept only if it lowers
/// |direct|, so a double root (zero slope) is left alone.
pub(super) fn newton_polish(p: &[f64], mut root: f64, direct: impl Fn(f64) -> f64) -> f64 {
    let slope: Vec<f64> = p
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, &c)| i as f64 * c)
        .collect();
    let mut value = direct(root);
    for _ in 0..3 {
        let derivative = slope.iter().rev().fold(0.0, |acc, &c| acc * root + c);
        let next = root - value / derivative;
        let next_value = direct(next);
        if !(next.is_finite() && next_value.abs() < value.abs()) {
            break;
        }
        (root, value) = (next, next_value);
    }
    root
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_and_norms() {
        let p = [Complex::new(1.0, 2.0), Complex::new(-0.5, 1.0)];
        let rho = 0.7;
        let n = norm_squared(&p);
        let direct = evaluate(&p, rho).norm_sqr();
        let value: f64 = n.iter().rev().fold(0.0, |acc, &c| acc * rho + c);
        assert!((value - direct).abs() < 1e-15);
        assert_eq!(multiply(&[1.0, 1.0], &[1.0, -1.0]), vec![1.0, 0.0, -1.0]);
        assert_eq!(combine(&[1.0, 2.0], &[3.0], -1.0), vec![-2.0, 2.0]);
        assert_eq!(times_rho(&[1.0, 2.0], 3.0), vec![0.0, 3.0, 6.0]);
    }

    #[test]
    fn polishing_improves_a_root_and_respects_double_roots() {
        // (ρ − 0.3)(ρ − 2) = ρ² − 2.3ρ + 0.6
        let p = [0.6, -2.3, 1.0];
        let direct = |r: f64| (r - 0.3) * (r - 2.0);
        assert!((newton_polish(&p, 0.3 + 1e-6, direct) - 0.3).abs() < 1e-15);
        let double = |r: f64| (r - 1.0) * (r - 1.0);
        assert_eq!(newton_polish(&[1.0, -2.0, 1.0], 1.0, double), 1.0);
    }
}
