//! Real roots of low-degree polynomials, without a starting guess.
//!
//! `real_roots_in` isolates the roots of p recursively: the real roots of p' split the
//! interval into pieces on which p is monotone, and each piece with a sign change holds
//! exactly one root, found by safeguarded Newton–bisection. Even-multiplicity roots (where p
//! touches zero without a sign change) are caught at the critical points by comparing
//! |p| with the rounding-error bound of its evaluation. This finds *all* real roots in an
//! interval, which the RRMF sextic (35) and the cone-joining quartic (14) need.
//!
//! `sampled_roots` is the counterpart for a function known only by its values (e.g. the
//! torsion of a curve given by a callback): every sign change between samples is bracketed,
//! and every local minimum of |f| among the samples is searched for a touching (double)
//! root or a pair of roots between two samples.

use super::minimize::minimize_bracketed;

/// Roots of `a x² + b x + c`, ascending, computed without cancellation (the larger root by
/// the usual formula, the smaller from Vieta). Degrades to the linear case when `a == 0`.
pub(crate) fn quadratic_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    if a == 0.0 {
        return if b == 0.0 { Vec::new() } else { vec![-c / b] };
    }
    let discriminant = b * b - 4.0 * a * c;
    if discriminant < 0.0 {
        return Vec::new();
    }
    let q = -0.5 * (b + b.signum() * discriminant.sqrt());
    if q == 0.0 {
        return vec![0.0];
    }
    let (x1, x2) = (q / a, c / q);
    if x1 == x2 {
        vec![x1]
    } else {
        vec![x1.min(x2), x1.max(x2)]
    }
}

/// Horner evaluation of `Σ coeffs[i] xⁱ` with the running bound `Σ |coeffs[i]| |x|ⁱ`,
/// which scales the rounding error of the value.
fn eval_with_bound(coeffs: &[f64], x: f64) -> (f64, f64) {
    let (mut value, mut bound) = (0.0, 0.0);
    for &c in coeffs.iter().rev() {
        value = value * x + c;
        bound = bound * x.abs() + c.abs();
    }
    (value, bound)
}

fn derivative(coeffs: &[f64]) -> Vec<f64> {
    coeffs
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, &c)| i as f64 * c)
        .collect()
}

fn trimmed(coeffs: &[f64]) -> &[f64] {
    let len = coeffs.iter().rposition(|&c| c != 0.0).map_or(0, |i| i + 1);
    &coeffs[..len]
}

/// All real roots of `Σ coeffs[i] xⁱ` (ascending powers), sorted ascending.
///
/// Uses the Cauchy bound `1 + max |aᵢ / aₙ|` as the search interval. The zero polynomial
/// and non-finite coefficients give no roots.
pub(crate) fn real_roots_power(coeffs: &[f64]) -> Vec<f64> {
    let p = trimmed(coeffs);
    if p.len() < 2 || p.iter().any(|c| !c.is_finite()) {
        return Vec::new();
    }
    let lead = p[p.len() - 1].abs();
    let bound = 1.0
        + p[..p.len() - 1]
            .iter()
            .map(|c| c.abs() / lead)
            .fold(0.0, f64::max);
    if !bound.is_finite() {
        return Vec::new();
    }
    real_roots_in(p, -bound, bound)
}

/// All real roots of `Σ coeffs[i] xⁱ` in the closed interval `[lo, hi]`, sorted ascending.
pub(crate) fn real_roots_in(coeffs: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let p = trimmed(coeffs);
    if p.len() < 2 || lo.is_nan() || hi.is_nan() || lo > hi || p.iter().any(|c| !c.is_finite()) {
        return Vec::new();
    }
    if p.len() == 2 {
        let x = -p[0] / p[1];
        return if (lo..=hi).contains(&x) {
            vec![x]
        } else {
            Vec::new()
        };
    }
    let critical = real_roots_in(&derivative(p), lo, hi);
    let mut knots = Vec::with_capacity(critical.len() + 2);
    knots.push(lo);
    knots.extend(critical.iter().copied().filter(|&c| c > lo && c < hi));
    knots.push(hi);

    let mut roots: Vec<f64> = Vec::new();
    let near_zero = |x: f64| {
        let (value, bound) = eval_with_bound(p, x);
        value.abs() <= 8.0 * p.len() as f64 * f64::EPSILON * bound
    };
    for (i, pair) in knots.windows(2).enumerate() {
        let (a, b) = (pair[0], pair[1]);
        if near_zero(a) && (i == 0 || critical.contains(&a)) {
            roots.push(a);
        }
        let (fa, _) = eval_with_bound(p, a);
        let (fb, _) = eval_with_bound(p, b);
        if fa != 0.0 && fb != 0.0 && (fa < 0.0) != (fb < 0.0) && !near_zero(a) && !near_zero(b) {
            roots.push(solve_bracketed(p, a, b, fa));
        }
    }
    if near_zero(hi) {
        roots.push(hi);
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup_by(|x, y| (*x - *y).abs() <= 1e-13 * x.abs().max(y.abs()).max(1e-300));
    roots
}

/// The root of a polynomial that changes sign on `[a, b]` (`fa = p(a)`), by Newton steps
/// kept inside a shrinking bracket, falling back to bisection.
fn solve_bracketed(p: &[f64], mut a: f64, mut b: f64, fa: f64) -> f64 {
    let dp = derivative(p);
    let negative_at_a = fa < 0.0;
    let mut x = 0.5 * (a + b);
    for _ in 0..200 {
        let (fx, _) = eval_with_bound(p, x);
        if fx == 0.0 {
            return x;
        }
        if (fx < 0.0) == negative_at_a {
            a = x;
        } else {
            b = x;
        }
        let (dfx, _) = eval_with_bound(&dp, x);
        let newton = x - fx / dfx;
        let next = if dfx != 0.0 && newton > a && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if (next - x).abs() <= 2.0 * f64::EPSILON * x.abs()
            || b - a <= 2.0 * f64::EPSILON * a.abs().max(b.abs())
        {
            return next;
        }
        x = next;
    }
    x
}

/// The midpoint of `[a, b]` (a < b) when it lies strictly inside; `None` for an interval of
/// adjacent floats (or one whose midpoint overflows), which halving would return unchanged:
/// adaptive subdivision stops there instead of recursing forever (a cone spline fit halving
/// [1.0001, 1.0001000000000002] would overflow the stack).
pub(crate) fn interior_midpoint(a: f64, b: f64) -> Option<f64> {
    let m = 0.5 * (a + b);
    (m > a && m < b).then_some(m)
}

/// A root of a continuous function with a sign change on `[a, b]` (`f(a)·f(b) ≤ 0`), by
/// bisection to the absolute tolerance `tol`; `None` without a sign change or for NaN values.
pub(crate) fn bisect_root(
    mut f: impl FnMut(f64) -> f64,
    mut a: f64,
    mut b: f64,
    tol: f64,
) -> Option<f64> {
    let (mut fa, fb) = (f(a), f(b));
    if fa.is_nan() || fb.is_nan() || fa * fb > 0.0 {
        return None;
    }
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    while (b - a).abs() > tol {
        let m = 0.5 * (a + b);
        if m == a || m == b {
            break;
        }
        let fm = f(m);
        if fm.is_nan() {
            return None;
        }
        if (fm < 0.0) == (fa < 0.0) {
            (a, fa) = (m, fm);
        } else {
            b = m;
        }
    }
    Some(0.5 * (a + b))
}

/// A root of a continuous function with a sign change between `(a, f(a))` and `(b, f(b))`,
/// by the Illinois variant of regula falsi (superlinear, always bracketed), with a bisection
/// step whenever three steps have not halved the bracket (a jump of f, which has no root,
/// is then closed in as fast as by bisection), to the absolute tolerance `tol` in x; `None`
/// without a sign change or for NaN values.
pub(crate) fn illinois_root(
    mut f: impl FnMut(f64) -> f64,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    tol: f64,
) -> Option<f64> {
    if fa.is_nan() || fb.is_nan() || fa * fb > 0.0 {
        return None;
    }
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    let (mut side, mut steps, mut width) = (0i8, 0, (b - a).abs());
    let mut previous = f64::NAN;
    for _ in 0..400 {
        if (b - a).abs() <= tol {
            break;
        }
        steps += 1;
        let bisect = steps > 3 && (b - a).abs() > 0.5 * width;
        let mut x = if bisect {
            0.5 * (a + b)
        } else {
            (a * fb - b * fa) / (fb - fa)
        };
        if !(x > a.min(b) && x < a.max(b)) {
            x = 0.5 * (a + b);
        }
        if bisect || (b - a).abs() <= 0.5 * width {
            (steps, width) = (0, (b - a).abs());
        }
        // Converged when the steps stall below the tolerance (the far end of the bracket
        // need not move in).
        if (x - previous).abs() <= tol {
            return Some(x);
        }
        previous = x;
        let fx = f(x);
        if fx.is_nan() {
            return None;
        }
        if fx == 0.0 {
            return Some(x);
        }
        if (fx < 0.0) == (fb < 0.0) {
            (b, fb) = (x, fx);
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            (a, fa) = (x, fx);
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    Some(if fa.abs() < fb.abs() { a } else { b })
}

/// The roots of `f` on [ts₀, tsₙ] seen from its values at the increasing samples `ts`:
///
/// * a sample where f is exactly 0;
/// * one root (Illinois) in every interval between samples where f changes sign;
/// * at every sample where |f| has a local minimum among its neighbours without a sign
///   change (the end samples included, against their one neighbour), the minimum of |f| on
///   the neighbouring intervals (Brent): a root where the minimum is at most `touch` (a
///   double root, or a pair closer than the rounding), and two roots where f changes sign
///   at the minimum (a pair of roots between two samples).
///
/// Roots closer than `tol` are merged. Errors of `f` are passed on.
pub(crate) fn sampled_roots<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    ts: &[f64],
    touch: f64,
    tol: f64,
) -> Result<Vec<f64>, E> {
    let values = ts.iter().map(|&t| f(t)).collect::<Result<Vec<_>, E>>()?;
    let mut failure = None;
    let mut g = |t: f64| match f(t) {
        Ok(v) => v,
        Err(e) => {
            failure.get_or_insert(e);
            f64::NAN
        }
    };
    let n = values.len();
    let mut roots: Vec<f64> = (0..n)
        .filter(|&k| values[k] == 0.0)
        .map(|k| ts[k])
        .collect();
    let changes = |a: f64, b: f64| a != 0.0 && b != 0.0 && (a < 0.0) != (b < 0.0);
    for k in 0..n.saturating_sub(1) {
        if changes(values[k], values[k + 1]) {
            roots.extend(illinois_root(
                &mut g,
                (ts[k], values[k]),
                (ts[k + 1], values[k + 1]),
                tol,
            ));
        }
    }
    for k in 0..n {
        let (left, right) = (k.saturating_sub(1), (k + 1).min(n - 1));
        let local_minimum = (left..=right)
            .all(|j| values[j] != 0.0 && !changes(values[j], values[k]))
            && values[left].abs() >= values[k].abs()
            && values[right].abs() >= values[k].abs()
            && left < right;
        if !local_minimum {
            continue;
        }
        let m = minimize_bracketed(|t| g(t).abs(), ts[left], ts[right], tol);
        let at = g(m.x);
        if changes(at, values[k]) {
            let (a, b) = (ts[left], ts[right]);
            roots.extend(illinois_root(&mut g, (a, values[left]), (m.x, at), tol));
            roots.extend(illinois_root(&mut g, (m.x, at), (b, values[right]), tol));
        } else if at.abs() <= touch {
            roots.push(m.x);
        }
    }
    if let Some(e) = failure {
        return Err(e);
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup_by(|x, y| (*x - *y).abs() <= tol);
    Ok(roots)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn from_roots(roots: &[f64]) -> Vec<f64> {
        let mut c = vec![1.0];
        for &r in roots {
            let mut next = vec![0.0; c.len() + 1];
            for (i, &ci) in c.iter().enumerate() {
                next[i + 1] += ci;
                next[i] -= r * ci;
            }
            c = next;
        }
        c
    }

    #[test]
    fn illinois_converges_on_bracketed_roots() {
        let mut calls = 0;
        let root = illinois_root(
            |x| {
                calls += 1;
                x.powi(3) - 2.0
            },
            (0.0, -2.0),
            (2.0, 6.0),
            1e-14,
        )
        .unwrap();
        assert!((root - 2f64.cbrt()).abs() < 1e-14, "{root}");
        assert!(calls < 20, "{calls} evaluations");
        assert!(illinois_root(|x| x, (1.0, 1.0), (2.0, 2.0), 1e-9).is_none());
    }

    #[test]
    fn quadratic_without_cancellation() {
        let r = quadratic_roots(1.0, -1e8, 1.0);
        assert_eq!(r.len(), 2);
        assert!((r[0] - 1e-8).abs() < 1e-22);
        assert!((r[1] - 1e8).abs() < 1e-6);
        assert!(quadratic_roots(1.0, 0.0, 1.0).is_empty());
        assert_eq!(quadratic_roots(0.0, 2.0, -4.0), vec![2.0]);
    }

    #[test]
    fn finds_all_roots_of_a_sextic() {
        let expected = [-3.5, -0.25, 0.001, 0.7, 2.0, 9.0];
        let roots = real_roots_power(&from_roots(&expected));
        assert_eq!(roots.len(), 6, "{roots:?}");
        for (r, e) in roots.iter().zip(expected) {
            assert!((r - e).abs() < 1e-9 * e.abs().max(1.0), "{r} vs {e}");
        }
    }

    #[test]
    fn finds_double_roots_and_skips_complex_ones() {
        // (x - 1)² (x² + 1) (x + 2)
        let mut c = from_roots(&[1.0, 1.0, -2.0]);
        c = {
            let mut next = vec![0.0; c.len() + 2];
            for (i, &ci) in c.iter().enumerate() {
                next[i] += ci;
                next[i + 2] += ci;
            }
            next
        };
        let roots = real_roots_power(&c);
        assert_eq!(roots.len(), 2, "{roots:?}");
        assert!((roots[0] + 2.0).abs() < 1e-12);
        assert!((roots[1] - 1.0).abs() < 1e-7);
    }

    #[test]
    fn bisection_needs_a_sign_change() {
        let r = bisect_root(|x| x * x - 2.0, 0.0, 2.0, 1e-15).unwrap();
        assert!((r - 2f64.sqrt()).abs() < 1e-15);
        assert!(bisect_root(|x| x * x + 1.0, -1.0, 1.0, 1e-12).is_none());
        assert_eq!(bisect_root(|x| x, 0.0, 1.0, 1e-12), Some(0.0));
        assert!(bisect_root(|_| f64::NAN, 0.0, 1.0, 1e-12).is_none());
    }

    #[test]
    fn restricts_to_an_interval() {
        let c = from_roots(&[-1.0, 0.5, 3.0]);
        assert_eq!(real_roots_in(&c, 0.0, 2.0).len(), 1);
        assert!(real_roots_power(&[f64::NAN, 1.0]).is_empty());
        assert!(real_roots_power(&[0.0, 0.0]).is_empty());
    }
}
