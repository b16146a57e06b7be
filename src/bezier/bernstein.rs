//! Polynomials in Bernstein form on [0, 1]: evaluation with derivatives, hodographs,
//! products, degree elevation and subdivision.
//!
//! The functions are generic over the coefficient type ([`Coefficient`]: f64, `DVec3`, `Complex`,
//! homogeneous `DVec4`), so that one implementation serves scalar weights, vector numerators
//! of frames and homogeneous control points. The formulas are the standard ones (Farin,
//! *Curves and Surfaces for CAGD*, ch. 5–6); de Casteljau's algorithm keeps evaluation
//! stable (convex combinations only).

use crate::math::{binomial, binomial_row, reciprocal_binomial_row, Complex};
use glam::{DVec3, DVec4};
use std::ops::{Add, Mul, Sub};

/// Highest degree the evaluators accept (they work on stack arrays of this size, so that
/// evaluation never allocates).
pub const MAX_DEGREE: usize = 64;

/// A coefficient of a Bernstein polynomial: anything that forms a real vector space.
pub(crate) trait Coefficient:
    Copy + Default + Add<Output = Self> + Sub<Output = Self> + Mul<f64, Output = Self>
{
}
impl Coefficient for f64 {}
impl Coefficient for DVec3 {}
impl Coefficient for DVec4 {}
impl Coefficient for Complex {}

/// Value, first and second derivative of a Bernstein polynomial at one parameter.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Jet<C> {
    /// p(t)
    pub value: C,
    /// p'(t)
    pub d1: C,
    /// p''(t)
    pub d2: C,
}

fn lerp<C: Coefficient>(a: C, b: C, t: f64) -> C {
    a * (1.0 - t) + b * t
}

/// Degrees up to which the evaluators work on a short stack array (spines, frames and
/// sweeps have degree ≤ 9): zeroing the array of [`MAX_DEGREE`] + 1 coefficients took as
/// long as the evaluation of a cubic.
pub(crate) const SHORT: usize = 10;

/// Degrees up to which they work on a middle-sized array: OpenCascade's B-splines reach
/// degree 25, and its approximations of helices and offsets commonly have degree 8 to 14.
const MEDIUM: usize = 26;

/// `$f::<C, N>(args)` with the smallest stack array N that holds `$n` coefficients.
macro_rules! on_stack {
    ($n:expr, $f:ident($($arg:expr),*)) => {
        if $n <= SHORT {
            $f::<C, SHORT>($($arg),*)
        } else if $n <= MEDIUM {
            $f::<C, MEDIUM>($($arg),*)
        } else {
            $f::<C, { MAX_DEGREE + 1 }>($($arg),*)
        }
    };
}

/// p(t) by de Casteljau's algorithm.
///
/// # Panics
/// If the degree exceeds [`MAX_DEGREE`] (constructors reject such input).
pub(crate) fn evaluate<C: Coefficient>(coeffs: &[C], t: f64) -> C {
    let n = coeffs.len();
    assert!(
        (1..=MAX_DEGREE + 1).contains(&n),
        "Bernstein degree out of range"
    );
    on_stack!(n, de_casteljau(coeffs, t))
}

fn de_casteljau<C: Coefficient, const N: usize>(coeffs: &[C], t: f64) -> C {
    let n = coeffs.len();
    let mut work = [C::default(); N];
    work[..n].copy_from_slice(coeffs);
    for level in (1..n).rev() {
        for i in 0..level {
            work[i] = lerp(work[i], work[i + 1], t);
        }
    }
    work[0]
}

/// p(t), p'(t) and p''(t) by de Casteljau's algorithm, stopping two levels early to read
/// the derivatives off the intermediate points.
pub(crate) fn evaluate_jet<C: Coefficient>(coeffs: &[C], t: f64) -> Jet<C> {
    let n = coeffs.len();
    assert!(
        (1..=MAX_DEGREE + 1).contains(&n),
        "Bernstein degree out of range"
    );
    on_stack!(n, de_casteljau_jet(coeffs, t))
}

fn de_casteljau_jet<C: Coefficient, const N: usize>(coeffs: &[C], t: f64) -> Jet<C> {
    let n = coeffs.len();
    let degree = (n - 1) as f64;
    let mut work = [C::default(); N];
    work[..n].copy_from_slice(coeffs);
    for level in (3..n).rev() {
        for i in 0..level {
            work[i] = lerp(work[i], work[i + 1], t);
        }
    }
    match n {
        1 => Jet {
            value: work[0],
            d1: C::default(),
            d2: C::default(),
        },
        2 => Jet {
            value: lerp(work[0], work[1], t),
            d1: (work[1] - work[0]) * degree,
            d2: C::default(),
        },
        _ => {
            let d2 = (work[2] - work[1] * 2.0 + work[0]) * (degree * (degree - 1.0));
            let a = lerp(work[0], work[1], t);
            let b = lerp(work[1], work[2], t);
            Jet {
                value: lerp(a, b, t),
                d1: (b - a) * degree,
                d2,
            }
        }
    }
}

/// p(t) and p'(t) by de Casteljau's algorithm, stopping one level early.
pub(crate) fn evaluate_d1<C: Coefficient>(coeffs: &[C], t: f64) -> (C, C) {
    let n = coeffs.len();
    assert!(
        (1..=MAX_DEGREE + 1).contains(&n),
        "Bernstein degree out of range"
    );
    if n == 4 {
        cubic_d1(coeffs, t)
    } else {
        on_stack!(n, de_casteljau_d1(coeffs, t))
    }
}

/// A cubic and its derivative from the basis directly (the spines' case: a third of de
/// Casteljau's work). Exact at both ends like de Casteljau's algorithm.
fn cubic_d1<C: Coefficient>(c: &[C], t: f64) -> (C, C) {
    let u = 1.0 - t;
    let (uu, ut, tt) = (u * u, u * t, t * t);
    let point = c[0] * (uu * u) + c[1] * (3.0 * uu * t) + c[2] * (3.0 * ut * t) + c[3] * (tt * t);
    let d1 = ((c[1] - c[0]) * uu + (c[2] - c[1]) * (2.0 * ut) + (c[3] - c[2]) * tt) * 3.0;
    (point, d1)
}

fn de_casteljau_d1<C: Coefficient, const N: usize>(coeffs: &[C], t: f64) -> (C, C) {
    let n = coeffs.len();
    if n == 1 {
        return (coeffs[0], C::default());
    }
    let mut work = [C::default(); N];
    work[..n].copy_from_slice(coeffs);
    for level in (2..n).rev() {
        for i in 0..level {
            work[i] = lerp(work[i], work[i + 1], t);
        }
    }
    (
        lerp(work[0], work[1], t),
        (work[1] - work[0]) * (n - 1) as f64,
    )
}

/// The Bernstein basis functions B₀ⁿ(t), …, Bₙⁿ(t), written to `out[0..=n]` by the convex
/// triangle recursion: one pass serves any number of coefficient sets evaluated at `t`.
pub(crate) fn basis(n: usize, t: f64, out: &mut [f64]) {
    assert!(out.len() > n, "basis buffer too small");
    out[0] = 1.0;
    for d in 1..=n {
        out[d] = t * out[d - 1];
        for i in (1..d).rev() {
            out[i] = (1.0 - t) * out[i] + t * out[i - 1];
        }
        out[0] *= 1.0 - t;
    }
}

/// The Bernstein basis functions of degree `n` at `t` with their first and second
/// derivatives, written to `out[0..=n]` as `[B, B', B'']`.
///
/// Uses `B'_i^n = n (B_{i-1}^{n-1} − B_i^{n-1})` and the analogous second difference of the
/// degree n − 2 basis; all basis values come from the convex triangle recursion.
pub(crate) fn basis_jet(n: usize, t: f64, out: &mut [[f64; 3]]) {
    assert!(
        n <= MAX_DEGREE && out.len() > n,
        "Bernstein degree out of range"
    );
    if n < SHORT {
        basis_jet_rows::<SHORT>(n, t, out)
    } else {
        basis_jet_rows::<{ MAX_DEGREE + 1 }>(n, t, out)
    }
}

/// [`basis_jet`] with rows of N ≥ n + 1 entries on the stack.
fn basis_jet_rows<const N: usize>(n: usize, t: f64, out: &mut [[f64; 3]]) {
    // Basis rows of degree n − 2 and n − 1 (all zero when that degree is negative).
    let mut below = [[0.0; N]; 2];
    let mut row = [0.0; N];
    row[0] = 1.0;
    for d in 0..=n {
        if d > 0 {
            row[d] = t * row[d - 1];
            for i in (1..d).rev() {
                row[i] = (1.0 - t) * row[i] + t * row[i - 1];
            }
            row[0] *= 1.0 - t;
        }
        if d + 2 == n {
            below[0] = row;
        }
        if d + 1 == n {
            below[1] = row;
        }
    }
    // Index i − k into a row, zero outside it.
    let shifted = |r: &[f64; N], i: usize, k: usize| if i >= k { r[i - k] } else { 0.0 };
    let nf = n as f64;
    for i in 0..=n {
        let d1 = nf * (shifted(&below[1], i, 1) - below[1][i]);
        let d2 = nf
            * (nf - 1.0)
            * (shifted(&below[0], i, 2) - 2.0 * shifted(&below[0], i, 1) + below[0][i]);
        out[i] = [row[i], d1, d2];
    }
}

/// Coefficients of p' (degree n − 1); a constant gives the zero polynomial of degree 0.
pub(crate) fn derivative<C: Coefficient>(coeffs: &[C]) -> Vec<C> {
    let n = coeffs.len() - 1;
    if n == 0 {
        return vec![C::default()];
    }
    coeffs
        .windows(2)
        .map(|w| (w[1] - w[0]) * n as f64)
        .collect()
}

/// Coefficients of `a·b` (degree m + n) for any bilinear product `mul` (scalar × vector,
/// dot, cross, ...): `c_k = Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) · mul(a_i, b_j)`.
pub(crate) fn product<A: Copy, B: Copy, C: Coefficient>(
    a: &[A],
    b: &[B],
    mul: impl Fn(A, B) -> C,
) -> Vec<C> {
    let mut out = vec![C::default(); a.len() + b.len() - 1];
    add_product(a, b, mul, &mut out);
    out
}

/// Adds the coefficients of `a·b` (see [`product`]) to `out[..=m + n]`: sums of products
/// without intermediate vectors, and products into buffers on the stack.
pub(crate) fn add_product<A: Copy, B: Copy, C: Coefficient>(
    a: &[A],
    b: &[B],
    mul: impl Fn(A, B) -> C,
    out: &mut [C],
) {
    let (m, n) = (a.len() - 1, b.len() - 1);
    let (row_a, row_b) = (binomial_row(m), binomial_row(n));
    let reciprocals = reciprocal_binomial_row(m + n);
    for (i, &ai) in a.iter().enumerate() {
        for (j, &bj) in b.iter().enumerate() {
            // scale ≤ 1 before it meets the coefficients: no overflow for huge ones
            let scale = row_a[i] * row_b[j] * reciprocals[i + j];
            out[i + j] = out[i + j] + mul(ai, bj) * scale;
        }
    }
}

/// The same polynomial written in degree n + r.
pub(crate) fn elevate<C: Coefficient>(coeffs: &[C], r: usize) -> Vec<C> {
    let n = coeffs.len() - 1;
    if r == 0 {
        return coeffs.to_vec();
    }
    let (row_n, row_r) = (binomial_row(n), binomial_row(r));
    let reciprocals = reciprocal_binomial_row(n + r);
    (0..=n + r)
        .map(|k| {
            let lo = k.saturating_sub(r);
            let hi = k.min(n);
            (lo..=hi).fold(C::default(), |acc, j| {
                acc + coeffs[j] * (row_n[j] * row_r[k - j] * reciprocals[k])
            })
        })
        .collect()
}

/// The same polynomial written in degree `degree ≥ n`.
pub(crate) fn elevate_to<C: Coefficient>(coeffs: &[C], degree: usize) -> Vec<C> {
    elevate(coeffs, degree + 1 - coeffs.len())
}

/// The polynomial of degree n − 1 whose elevation gives `coeffs` (degree n ≥ 1), computed
/// from both ends (the first half by the forward recursion of the elevation formula, the
/// second by the backward one). Exact when p has degree < n — e.g. a product whose top
/// power coefficient cancels — and otherwise no approximation of any quality: check by
/// elevating back.
pub(crate) fn reduce_degree<C: Coefficient>(coeffs: &[C]) -> Vec<C> {
    let n = coeffs.len() - 1;
    assert!(n >= 1, "a constant cannot be reduced");
    let nf = n as f64;
    let mut out = vec![C::default(); n];
    let half = (n - 1) / 2;
    out[0] = coeffs[0];
    for i in 1..=half {
        out[i] = (coeffs[i] * nf - out[i - 1] * i as f64) * (1.0 / (n - i) as f64);
    }
    out[n - 1] = coeffs[n];
    for i in (half + 2..n).rev() {
        out[i - 1] = (coeffs[i] * nf - out[i] * (n - i) as f64) * (1.0 / i as f64);
    }
    out
}

/// Subdivision at `t`: coefficients of p on [0, t] and on [t, 1], each reparameterized to
/// [0, 1].
pub(crate) fn split<C: Coefficient>(coeffs: &[C], t: f64) -> (Vec<C>, Vec<C>) {
    let n = coeffs.len();
    let mut work = coeffs.to_vec();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![C::default(); n];
    for level in (0..n).rev() {
        left.push(work[0]);
        right[level] = work[level];
        for i in 0..level {
            work[i] = lerp(work[i], work[i + 1], t);
        }
    }
    (left, right)
}

/// Coefficients of p restricted to [t0, t1] and reparameterized to [0, 1].
pub(crate) fn restrict<C: Coefficient>(coeffs: &[C], t0: f64, t1: f64) -> Vec<C> {
    if t1 == 1.0 {
        return split(coeffs, t0).1;
    }
    let (left, _) = split(coeffs, t1);
    split(&left, t0 / t1).1
}

/// Local breakpoints `0 = s₀ < s₁ < … < s_k = 1` such that on every interval each of the
/// given polynomials has only positive Bernstein coefficients (interval bisection; the
/// coefficients of a piece converge to the function's values as the piece shrinks, so a
/// polynomial positive on [0, 1] needs finitely many halvings).
///
/// This is how rational results get the positive weights CAD systems require: the natural
/// denominators here (PH speed σ, |α|² + |β|², Möbius weights) are positive functions whose
/// coefficients need not be. Returns `None` when some piece still has a non-positive
/// coefficient after `max_depth` halvings (the polynomial has, or nearly has, a root).
pub(crate) fn positive_subdivision(polynomials: &[&[f64]], max_depth: usize) -> Option<Vec<f64>> {
    fn visit(
        polys: &[Vec<f64>],
        lo: f64,
        hi: f64,
        depth: usize,
        max_depth: usize,
        out: &mut Vec<f64>,
    ) -> bool {
        if polys.iter().all(|p| p.iter().all(|&c| c > 0.0)) {
            out.push(hi);
            return true;
        }
        if depth == max_depth || polys.iter().any(|p| p[0] <= 0.0 || p[p.len() - 1] <= 0.0) {
            return false;
        }
        let (left, right): (Vec<_>, Vec<_>) = polys.iter().map(|p| split(p, 0.5)).unzip();
        let mid = 0.5 * (lo + hi);
        visit(&left, lo, mid, depth + 1, max_depth, out)
            && visit(&right, mid, hi, depth + 1, max_depth, out)
    }
    let polys: Vec<Vec<f64>> = polynomials.iter().map(|p| p.to_vec()).collect();
    let mut breaks = vec![0.0];
    visit(&polys, 0.0, 1.0, 0, max_depth, &mut breaks).then_some(breaks)
}

/// Bernstein coefficients of degree n of the polynomial `Σ power[i] tⁱ` (n = power.len() − 1):
/// `b_k = Σ_{i≤k} C(k,i)/C(n,i) · a_i`.
pub(crate) fn from_power<C: Coefficient>(power: &[C]) -> Vec<C> {
    let n = power.len() - 1;
    (0..=n)
        .map(|k| {
            (0..=k).fold(C::default(), |acc, i| {
                acc + power[i] * (binomial(k, i) / binomial(n, i))
            })
        })
        .collect()
}

/// Power-basis coefficients `a_i` (p = Σ a_i tⁱ) of a Bernstein polynomial:
/// `a_i = C(n,i) Σ_{k≤i} (−1)^{i−k} C(i,k) b_k`.
pub(crate) fn to_power<C: Coefficient>(coeffs: &[C]) -> Vec<C> {
    let n = coeffs.len() - 1;
    (0..=n)
        .map(|i| {
            let sum = (0..=i).fold(C::default(), |acc, k| {
                let sign = if (i - k) % 2 == 0 { 1.0 } else { -1.0 };
                acc + coeffs[k] * (sign * binomial(i, k))
            });
            sum * binomial(n, i)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn power_eval(a: &[f64], t: f64) -> f64 {
        a.iter().rev().fold(0.0, |acc, &c| acc * t + c)
    }

    const P: [f64; 5] = [1.0, -2.0, 0.5, 3.0, -1.0];

    #[test]
    fn jet_matches_finite_differences() {
        let t = 0.37;
        let jet = evaluate_jet(&P, t);
        assert!((jet.value - evaluate(&P, t)).abs() < 1e-15);
        let h = 1e-5;
        let fd1 = (evaluate(&P, t + h) - evaluate(&P, t - h)) / (2.0 * h);
        let fd2 = (evaluate(&P, t + h) - 2.0 * evaluate(&P, t) + evaluate(&P, t - h)) / (h * h);
        assert!((jet.d1 - fd1).abs() < 1e-8);
        assert!((jet.d2 - fd2).abs() < 1e-4);
        let d = derivative(&P);
        assert!((evaluate(&d, t) - jet.d1).abs() < 1e-13);
        assert!((evaluate(&derivative(&d), t) - jet.d2).abs() < 1e-12);
    }

    #[test]
    fn basis_jet_reproduces_polynomial_jet() {
        for n in 0..7 {
            let coeffs: Vec<f64> = (0..=n).map(|i| (i as f64 * 1.7).sin()).collect();
            let mut basis = [[0.0; 3]; MAX_DEGREE + 1];
            basis_jet(n, 0.63, &mut basis);
            let jet = evaluate_jet(&coeffs, 0.63);
            let sum = |k: usize| (0..=n).map(|i| basis[i][k] * coeffs[i]).sum::<f64>();
            assert!((sum(0) - jet.value).abs() < 1e-14, "n = {n}");
            assert!((sum(1) - jet.d1).abs() < 1e-12, "n = {n}");
            assert!((sum(2) - jet.d2).abs() < 1e-11, "n = {n}");
        }
    }

    #[test]
    fn every_stack_size_evaluates_as_the_basis_sums() {
        // Degrees on both sides of each array size the evaluators pick.
        for n in [0, 3, 8, 9, 10, 11, 24, 25, 26, 27, 40, MAX_DEGREE] {
            let coeffs: Vec<f64> = (0..=n).map(|i| (i as f64 * 0.9).cos()).collect();
            let mut basis = [[0.0; 3]; MAX_DEGREE + 1];
            for t in [0.0, 0.29, 0.5, 0.83, 1.0] {
                basis_jet(n, t, &mut basis);
                let sum = |k: usize| (0..=n).map(|i| basis[i][k] * coeffs[i]).sum::<f64>();
                let scale = (n * n).max(1) as f64;
                let (value, d1) = evaluate_d1(&coeffs, t);
                let jet = evaluate_jet(&coeffs, t);
                assert!((evaluate(&coeffs, t) - sum(0)).abs() < 1e-13, "n = {n}");
                assert!((value - sum(0)).abs() < 1e-13, "n = {n}");
                assert!((d1 - sum(1)).abs() < 1e-13 * scale, "n = {n}");
                assert!((jet.value - sum(0)).abs() < 1e-13, "n = {n}");
                assert!((jet.d1 - sum(1)).abs() < 1e-13 * scale, "n = {n}");
                assert!((jet.d2 - sum(2)).abs() < 1e-12 * scale * scale, "n = {n}");
            }
        }
    }

    #[test]
    fn subdivides_until_coefficients_are_positive() {
        // 3 (1, cos θ, 1): the speed of a PH cubic with a sharp turn, positive on [0, 1]
        // with a negative middle coefficient.
        let speed = [3.0, -1.5, 3.0];
        let breaks = positive_subdivision(&[&speed, &[1.0, 1.0]], 20).unwrap();
        assert!(breaks.len() > 2 && breaks[0] == 0.0 && *breaks.last().unwrap() == 1.0);
        for w in breaks.windows(2) {
            assert!(restrict(&speed, w[0], w[1]).iter().all(|&c| c > 0.0));
        }
        assert_eq!(
            positive_subdivision(&[&[1.0, 2.0, 1.0]], 20).unwrap(),
            vec![0.0, 1.0]
        );
        // (1 − 2t)² touches zero at t = 1/2: no positive subdivision exists.
        assert!(positive_subdivision(&[&[1.0, -1.0, 1.0]], 30).is_none());
    }

    #[test]
    fn basis_reproduces_evaluation() {
        let mut b = [0.0; 8];
        for &t in &[0.0, 0.3, 0.77, 1.0] {
            basis(4, t, &mut b);
            let sum: f64 = P.iter().zip(&b).map(|(c, w)| c * w).sum();
            assert!((sum - evaluate(&P, t)).abs() < 1e-15);
            assert!((b[..5].iter().sum::<f64>() - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn reduction_undoes_elevation() {
        for r in 1..4 {
            let e = elevate(&P, r);
            let mut back = e.clone();
            for _ in 0..r {
                back = reduce_degree(&back);
            }
            assert_eq!(back.len(), P.len());
            assert!(
                back.iter().zip(&P).all(|(a, b)| (a - b).abs() < 1e-12),
                "{back:?}"
            );
        }
        assert_eq!(reduce_degree(&[2.0, 2.0]), vec![2.0]);
    }

    #[test]
    fn product_elevation_split_and_power_conversion() {
        let q = [2.0, 0.0, 1.0];
        let pq = product(&P, &q, |a, b| a * b);
        let e = elevate(&P, 3);
        let (l, r) = split(&P, 0.3);
        let sub = restrict(&P, 0.2, 0.7);
        let power = to_power(&P);
        assert_eq!(from_power(&power).len(), P.len());
        for &t in &[0.0, 0.1, 0.5, 0.9, 1.0] {
            let p = evaluate(&P, t);
            assert!((evaluate(&pq, t) - p * evaluate(&q, t)).abs() < 1e-13);
            assert!((evaluate(&e, t) - p).abs() < 1e-14);
            assert!((evaluate(&l, t) - evaluate(&P, 0.3 * t)).abs() < 1e-14);
            assert!((evaluate(&r, t) - evaluate(&P, 0.3 + 0.7 * t)).abs() < 1e-14);
            assert!((evaluate(&sub, t) - evaluate(&P, 0.2 + 0.5 * t)).abs() < 1e-13);
            assert!((power_eval(&power, t) - p).abs() < 1e-13);
            assert!((evaluate(&from_power(&power), t) - p).abs() < 1e-13);
        }
    }
}
