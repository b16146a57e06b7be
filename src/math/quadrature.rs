//! Gauss–Legendre quadrature on [0, 1], nodes computed once by Newton's method on the
//! Legendre polynomial (accurate to round-off for any order used here).

/// An n-point Gauss–Legendre rule on [0, 1] (exact for polynomials of degree 2n − 1).
#[derive(Clone, Debug)]
pub(crate) struct GaussLegendre {
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl GaussLegendre {
    /// The rule with `n ≥ 1` points.
    pub(crate) fn new(n: usize) -> Self {
        let n = n.max(1);
        let mut nodes = vec![0.0; n];
        let mut weights = vec![0.0; n];
        for i in 0..n.div_ceil(2) {
            // Chebyshev-like initial guess for the i-th root of P_n on [-1, 1].
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (p, d) = legendre(n, x);
                dp = d;
                let step = p / d;
                x -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            let (_, d) = legendre(n, x);
            dp = if d != 0.0 { d } else { dp };
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            nodes[i] = 0.5 * (1.0 - x);
            nodes[n - 1 - i] = 0.5 * (1.0 + x);
            weights[i] = 0.5 * w;
            weights[n - 1 - i] = 0.5 * w;
        }
        Self { nodes, weights }
    }

    /// Nodes in (0, 1), ascending.
    pub(crate) fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// Weights, summing to 1.
    pub(crate) fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// ∫ₐᵇ f.
    pub(crate) fn integrate(&self, a: f64, b: f64, mut f: impl FnMut(f64) -> f64) -> f64 {
        let h = b - a;
        self.nodes
            .iter()
            .zip(&self.weights)
            .map(|(&x, &w)| w * f(a + h * x))
            .sum::<f64>()
            * h
    }

    #[cfg(test)]
    /// ∫ₐᵇ f by the rule applied on `pieces` equal subintervals.
    pub(crate) fn integrate_composite(
        &self,
        a: f64,
        b: f64,
        pieces: usize,
        mut f: impl FnMut(f64) -> f64,
    ) -> f64 {
        let pieces = pieces.max(1);
        let h = (b - a) / pieces as f64;
        (0..pieces)
            .map(|k| self.integrate(a + k as f64 * h, a + (k + 1) as f64 * h, &mut f))
            .sum()
    }
}

/// P_n(x) and P_n'(x) by the three-term recurrence.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 2..=n {
        let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
        p0 = p1;
        p1 = p2;
    }
    let p = if n == 0 { 1.0 } else { p1 };
    let d = n as f64 * (x * p - p0) / (x * x - 1.0);
    (p, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_for_polynomials_of_degree_2n_minus_1() {
        let rule = GaussLegendre::new(5);
        let integral = rule.integrate(0.0, 2.0, |x| x.powi(9) - 3.0 * x.powi(4));
        let exact = 2f64.powi(10) / 10.0 - 3.0 * 2f64.powi(5) / 5.0;
        assert!((integral - exact).abs() < 1e-11 * exact.abs());
        assert!((rule.weights().iter().sum::<f64>() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn composite_rule_integrates_smooth_functions() {
        let rule = GaussLegendre::new(8);
        let v = rule.integrate_composite(0.0, std::f64::consts::PI, 4, f64::sin);
        assert!((v - 2.0).abs() < 1e-14);
        assert_eq!(GaussLegendre::new(1).nodes(), &[0.5]);
    }
}
