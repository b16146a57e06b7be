//! The rational approximation W(v) of w(v) = tan(Ω(v)/2), Mäurer & Jüttler §3.4: the
//! biquadratic Hermite interpolant (36) of the data (34), one member of the family (37),
//! chosen by minimizing the error (40) in the angular velocity on a quadrature (41).
//!
//! Interpolating w and w' at both ends makes the frame (29) exact, with its derivative, at
//! the segment ends, so that consecutive segments join with G1 frames. The family is
//! written here as β = (1 − α, (s₁α + s₀(1 − α)) / (2Δw), α), γ = (w₀β₀, w₀β₁ + s₀β₀/2, w₁β₂),
//! α ∈ (0, 1), Δw = w₁ − w₀ > 0: this is (37) rescaled (λ = 2β₁/β₀ − 2), α ↦ λ maps (0, 1) onto
//! (λ*, ∞) of Lemma 11, so every member is monotone without poles, and it stays valid when
//! an end slope is zero (s₁ = 0 makes (37) degenerate), which happens where a twisted target
//! angle has an extremum. Decreasing data (the other sign of the torsion) are mirrored.

use crate::error::no_solution;
use crate::error::{Error, Result};
use crate::math::{minimize_bracketed, GaussLegendre};
use std::sync::OnceLock;

/// Nodes of the Gauss–Legendre rule for (41): the integrand is a smooth rational function of
/// degree 8/8, integrated to round-off by this many nodes for the data that occur.
const QUADRATURE_NODES: usize = 24;

/// Relative size of a slope of the wrong sign still taken as 0 (round-off at an extremum).
const SLOPE_ROUND_OFF: f64 = 1e-9;

/// Hermite data (34) of w = tan(Ω/2) on [0, 1]: values and derivatives at both ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AngleHermite {
    pub w0: f64,
    pub w1: f64,
    pub s0: f64,
    pub s1: f64,
}

/// W = (γ₀B₀² + γ₁B₁² + γ₂B₂²) / (β₀B₀² + β₁B₁² + β₂B₂²), equation (36).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Biquadratic {
    pub numerator: [f64; 3],
    pub denominator: [f64; 3],
}

impl Biquadratic {
    /// The constant w.
    pub(crate) fn constant(w: f64) -> Self {
        Self {
            numerator: [w; 3],
            denominator: [1.0; 3],
        }
    }

    #[cfg(test)]
    /// The member of (37) with parameter λ, for increasing data (35) with λ > λ* (38).
    pub(crate) fn from_lambda(data: &AngleHermite, lambda: f64) -> Self {
        let AngleHermite { w0, w1, s0, s1 } = *data;
        let beta = [
            s1,
            s1 * (lambda + 2.0) / 2.0,
            (w1 - w0) * (lambda + 2.0) - s0,
        ];
        Self {
            numerator: [
                w0 * beta[0],
                s1 * (w0 * (lambda + 2.0) + s0) / 2.0,
                w1 * beta[2],
            ],
            denominator: beta,
        }
    }

    /// λ of (37) for this member: 2β₁/β₀ − 2.
    pub(crate) fn lambda(&self) -> f64 {
        2.0 * self.denominator[1] / self.denominator[0] - 2.0
    }

    fn parts(&self, v: f64) -> (f64, f64, f64, f64) {
        let u = 1.0 - v;
        let [g0, g1, g2] = self.numerator;
        let [b0, b1, b2] = self.denominator;
        let g = g0 * u * u + 2.0 * g1 * u * v + g2 * v * v;
        let b = b0 * u * u + 2.0 * b1 * u * v + b2 * v * v;
        let dg = 2.0 * ((g1 - g0) * u + (g2 - g1) * v);
        let db = 2.0 * ((b1 - b0) * u + (b2 - b1) * v);
        (g, b, dg, db)
    }

    /// W(v).
    pub(crate) fn eval(&self, v: f64) -> f64 {
        let (g, b, _, _) = self.parts(v);
        g / b
    }

    /// d/dv 2 arctan W(v) = 2W' / (1 + W²), the angular velocity of the frame (29).
    pub(crate) fn angle_rate(&self, v: f64) -> f64 {
        let (g, b, dg, db) = self.parts(v);
        // 2 (g'b − gb') / (b² + g²): the same, without forming W.
        2.0 * (dg * b - g * db) / (b * b + g * g)
    }

    fn negated(self) -> Self {
        Self {
            numerator: self.numerator.map(|g| -g),
            denominator: self.denominator,
        }
    }
}

#[cfg(test)]
/// λ* of Lemma 11 (38): members of (37) with λ > λ* are monotone without poles.
pub(crate) fn lambda_star(data: &AngleHermite) -> f64 {
    data.s0 / (data.w1 - data.w0) - 2.0
}

/// The objective (40), ∫₀¹ (d/dv 2 arctan W − Ω')² dv, by the quadrature (41).
pub(crate) fn objective(w: &Biquadratic, rate: impl Fn(f64) -> f64) -> f64 {
    objective_with(quadrature_rule(), w, rate)
}

/// The rule of (41), computed once.
fn quadrature_rule() -> &'static GaussLegendre {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    RULE.get_or_init(|| GaussLegendre::new(QUADRATURE_NODES))
}

fn objective_with(rule: &GaussLegendre, w: &Biquadratic, rate: impl Fn(f64) -> f64) -> f64 {
    rule.integrate(0.0, 1.0, |v| (w.angle_rate(v) - rate(v)).powi(2))
}

/// The chosen W with its value of the objective.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BiquadraticFit {
    pub w: Biquadratic,
    /// Î(λ) of (41) at the minimum.
    pub objective: f64,
}

/// The member of (36)–(37) interpolating `data` that minimizes (40) for the target angular
/// velocity `rate` = Ω'. `data` must be monotone (equal signs of w₁ − w₀, s₀ and s₁, slopes
/// may be 0); constant data give the constant W.
pub(crate) fn fit(data: AngleHermite, rate: impl Fn(f64) -> f64) -> Result<BiquadraticFit> {
    fit_dyn(data, &rate)
}

fn fit_dyn(data: AngleHermite, rate: &dyn Fn(f64) -> f64) -> Result<BiquadraticFit> {
    let delta = data.w1 - data.w0;
    if delta == 0.0 {
        return if data.s0 == 0.0 && data.s1 == 0.0 {
            Ok(BiquadraticFit {
                w: Biquadratic::constant(data.w0),
                objective: objective(&Biquadratic::constant(data.w0), rate),
            })
        } else {
            Err(Error::no_solution(
                "w(0) = w(1) with non-zero slopes: the angle is not monotone on the piece",
            ))
        };
    }
    if delta < 0.0 {
        let mirrored = AngleHermite {
            w0: -data.w0,
            w1: -data.w1,
            s0: -data.s0,
            s1: -data.s1,
        };
        let fit = fit_dyn(mirrored, &|v| -rate(v))?;
        return Ok(BiquadraticFit {
            w: fit.w.negated(),
            objective: fit.objective,
        });
    }
    let (s0, s1) = (
        nonnegative_slope(data.s0, delta)?,
        nonnegative_slope(data.s1, delta)?,
    );
    let family = Family::new(data.w0, data.w1, s0, s1);
    let rule = quadrature_rule();
    // Ω' at the nodes of (41), once: it does not depend on the member.
    let mut target = [0.0; QUADRATURE_NODES];
    for (t, &v) in target.iter_mut().zip(rule.nodes()) {
        *t = rate(v);
    }
    let (x, objective) = gauss_newton(&family, rule, &target).unwrap_or_else(|| {
        let x = scan_and_refine(&family, rule, &target);
        (x, family.objective(rule, &target, logistic(x)))
    });
    Ok(BiquadraticFit {
        w: family.member(logistic(x)),
        objective,
    })
}

/// α = 1/(1 + e⁻ˣ): every real x gives a member of the family, monotone without poles.
fn logistic(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

/// The members of (37) for increasing data with non-negative slopes, written in α ∈ (0, 1)
/// (module notes): β and γ are affine in α, β = β⁰ + αβ¹, γ = γ⁰ + αγ¹.
struct Family {
    beta: [[f64; 3]; 2],
    gamma: [[f64; 3]; 2],
}

impl Family {
    fn new(w0: f64, w1: f64, s0: f64, s1: f64) -> Self {
        let delta = w1 - w0;
        let (b1_0, b1_1) = (s0 / (2.0 * delta), (s1 - s0) / (2.0 * delta));
        Self {
            beta: [[1.0, b1_0, 0.0], [-1.0, b1_1, 1.0]],
            gamma: [
                [w0, w0 * b1_0 + 0.5 * s0, 0.0],
                [-w0, w0 * b1_1 - 0.5 * s0, w1],
            ],
        }
    }

    fn member(&self, alpha: f64) -> Biquadratic {
        let at = |c: &[[f64; 3]; 2]| [0, 1, 2].map(|k| c[0][k] + alpha * c[1][k]);
        Biquadratic {
            numerator: at(&self.gamma),
            denominator: at(&self.beta),
        }
    }

    /// Î(α) of (41) against the target rates at the rule's nodes.
    fn objective(&self, rule: &GaussLegendre, target: &[f64], alpha: f64) -> f64 {
        let w = self.member(alpha);
        rule.nodes()
            .iter()
            .zip(rule.weights())
            .zip(target)
            .map(|((&v, &weight), &r)| weight * (w.angle_rate(v) - r).powi(2))
            .sum()
    }

    /// g, b, g′, b′ of the members at each node of the rule, as affine functions of α:
    /// (value at α = 0, coefficient of α), computed once for all Gauss–Newton steps.
    fn node_parts(&self, rule: &GaussLegendre) -> [[(f64, f64); 4]; QUADRATURE_NODES] {
        let base = self.member(0.0);
        let slope = Biquadratic {
            numerator: self.gamma[1],
            denominator: self.beta[1],
        };
        let mut parts = [[(0.0, 0.0); 4]; QUADRATURE_NODES];
        for (p, &v) in parts.iter_mut().zip(rule.nodes()) {
            let (g, b, dg, db) = base.parts(v);
            let (g_a, b_a, dg_a, db_a) = slope.parts(v);
            *p = [(g, g_a), (b, b_a), (dg, dg_a), (db, db_a)];
        }
        parts
    }

    /// The residuals' weighted sums Σ wᵢ eᵢ Jᵢ, Σ wᵢ Jᵢ² and Σ wᵢ eᵢ² (= Î), eᵢ = R(vᵢ) − Ω'(vᵢ),
    /// Jᵢ = ∂R/∂α for R = 2(g'b − gb')/(b² + g²), the angular velocity of (29); `parts` from
    /// [`Self::node_parts`].
    fn gradient_terms(
        parts: &[[(f64, f64); 4]; QUADRATURE_NODES],
        rule: &GaussLegendre,
        target: &[f64],
        alpha: f64,
    ) -> (f64, f64, f64) {
        let (mut ej, mut jj, mut ee) = (0.0, 0.0, 0.0);
        for ((p, &weight), &r) in parts.iter().zip(rule.weights()).zip(target) {
            let [g, b, dg, db] = p.map(|(at0, slope)| at0 + alpha * slope);
            let [g_a, b_a, dg_a, db_a] = p.map(|(_, slope)| slope);
            let (n, den) = (dg * b - g * db, b * b + g * g);
            let n_a = dg_a * b + dg * b_a - g_a * db - g * db_a;
            let den_a = 2.0 * (b * b_a + g * g_a);
            let inverse = 1.0 / den;
            let rate = 2.0 * n * inverse;
            let jacobian = 2.0 * (n_a * den - n * den_a) * (inverse * inverse);
            ej += weight * (rate - r) * jacobian;
            jj += weight * jacobian * jacobian;
            ee += weight * (rate - r) * (rate - r);
        }
        (ej, jj, ee)
    }
}

/// Minimizes Î of (41) by Gauss–Newton steps in x (α = logistic(x)) from the symmetric
/// member α = 1/2: the residuals are small (W follows Ω' closely), so a few steps reach the
/// minimum. Returns x with Î there; `None` if the steps do not settle (then
/// [`scan_and_refine`] is used).
fn gauss_newton(family: &Family, rule: &GaussLegendre, target: &[f64]) -> Option<(f64, f64)> {
    const STEPS: usize = 12;
    const SETTLED: f64 = 1e-10;
    let parts = family.node_parts(rule);
    let mut x = 0.0f64;
    for _ in 0..STEPS {
        let alpha = logistic(x);
        let (ej, jj, objective) = Family::gradient_terms(&parts, rule, target, alpha);
        // dα/dx = α(1 − α).
        let dx = -ej / (jj * alpha * (1.0 - alpha));
        if !dx.is_finite() {
            return None;
        }
        if dx.abs() < SETTLED {
            // x is within SETTLED of the minimum, and Î at x is known.
            return (x.abs() < 30.0).then_some((x, objective));
        }
        x += dx.clamp(-2.0, 2.0);
    }
    None
}

/// The robust search: a coarse scan over x finds the basin, Brent's method the minimum.
fn scan_and_refine(family: &Family, rule: &GaussLegendre, target: &[f64]) -> f64 {
    let cost = |x: f64| family.objective(rule, target, logistic(x));
    let (best, _) = (-15..=15)
        .map(|i| (i as f64, cost(i as f64)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("a non-empty scan");
    minimize_bracketed(cost, best - 1.0, best + 1.0, 1e-10).x
}

/// A slope of monotone data on a piece, with round-off below zero taken as 0.
fn nonnegative_slope(s: f64, delta: f64) -> Result<f64> {
    if s >= 0.0 {
        Ok(s)
    } else if s >= -SLOPE_ROUND_OFF * delta {
        Ok(0.0)
    } else {
        no_solution!(
            "slope {s:e} against the direction of the angle: it is not monotone on the piece"
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// w = tan(Ω/2) for Ω = k·2 arctan((cv − b)/a) shifted to start at 0, as in (33).
    fn target(k: f64) -> (impl Fn(f64) -> f64, impl Fn(f64) -> f64) {
        let (a, b, c) = (0.8, 0.3, 1.1);
        let omega = move |v: f64| 2.0 * k * (((c * v - b) / a).atan() - (-b / a).atan());
        let rate = move |v: f64| 2.0 * k * (c / a) / (1.0 + ((c * v - b) / a).powi(2));
        (omega, rate)
    }

    fn hermite(omega: &impl Fn(f64) -> f64, rate: &impl Fn(f64) -> f64) -> AngleHermite {
        let w = |v: f64| (omega(v) / 2.0).tan();
        let s = |v: f64| 0.5 * (1.0 + w(v).powi(2)) * rate(v);
        AngleHermite {
            w0: w(0.0),
            w1: w(1.0),
            s0: s(0.0),
            s1: s(1.0),
        }
    }

    #[test]
    fn every_member_interpolates_and_the_paper_family_agrees() {
        let (omega, rate) = target(0.6);
        let data = hermite(&omega, &rate);
        let fit = fit(data, &rate).unwrap();
        let w = fit.w;
        let h = 1e-6;
        assert!((w.eval(0.0) - data.w0).abs() < 1e-15);
        assert!((w.eval(1.0) - data.w1).abs() < 1e-15);
        assert!(((w.eval(h) - w.eval(0.0)) / h - data.s0).abs() < 1e-5);
        assert!(((w.eval(1.0) - w.eval(1.0 - h)) / h - data.s1).abs() < 1e-5);
        // The same member from (37) with its λ.
        let lambda = w.lambda();
        assert!(lambda > lambda_star(&data));
        let paper = Biquadratic::from_lambda(&data, lambda);
        for v in [0.1, 0.5, 0.9] {
            assert!((paper.eval(v) - w.eval(v)).abs() < 1e-13);
        }
    }

    #[test]
    fn the_chosen_member_minimizes_the_objective_and_tracks_the_angle() {
        let (omega, rate) = target(0.6);
        let data = hermite(&omega, &rate);
        let best = fit(data, &rate).unwrap();
        let lambda = best.w.lambda();
        for d in [-0.05, 0.05] {
            let other = Biquadratic::from_lambda(&data, lambda + d);
            assert!(objective(&other, &rate) > best.objective);
        }
        assert!((objective(&best.w, &rate) - best.objective).abs() < 1e-15);
        // The angle is followed to about 1e-3 of its turn of 1.37 rad by one W.
        let worst = (0..=100)
            .map(|i| i as f64 / 100.0)
            .map(|v| (2.0 * best.w.eval(v).atan() - omega(v)).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1.5e-3 * omega(1.0), "{worst}");
    }

    #[test]
    fn the_chosen_angle_does_not_depend_on_the_offset_of_w() {
        // tan(x + c) is a Möbius function of tan x: the family (37) for the shifted data is the
        // shifted family, so the optimum is the same angle function (with another λ).
        let (omega, rate) = target(0.6);
        let a = fit(hermite(&omega, &rate), &rate).unwrap();
        let shifted = move |v: f64| omega(v) - 0.7;
        let b = fit(hermite(&shifted, &rate), &rate).unwrap();
        assert!((a.objective - b.objective).abs() < 1e-12 * a.objective.max(1e-300) + 1e-18);
        assert!((a.w.lambda() - b.w.lambda()).abs() > 1e-3);
        for v in [0.2, 0.5, 0.8] {
            let (x, y) = (2.0 * a.w.eval(v).atan(), 2.0 * b.w.eval(v).atan() + 0.7);
            assert!((x - y).abs() < 1e-7, "v = {v}: {x} vs {y}");
        }
    }

    #[test]
    fn decreasing_data_and_zero_slopes() {
        let (omega, rate) = target(-0.6);
        let data = hermite(&omega, &rate);
        assert!(data.w1 < data.w0);
        let f = fit(data, &rate).unwrap();
        assert!((f.w.eval(1.0) - data.w1).abs() < 1e-15);
        let (up, _) = target(0.6);
        let mirrored = fit(hermite(&up, &target(0.6).1), target(0.6).1).unwrap();
        assert!((f.objective - mirrored.objective).abs() < 1e-15);
        // An extremum at the end: s₁ = 0 (degenerate in (37)) still interpolates.
        let flat_end = AngleHermite {
            w0: 0.0,
            w1: 0.5,
            s0: 1.0,
            s1: 0.0,
        };
        let f = fit(flat_end, |v| 2.0 * (1.0 - v)).unwrap();
        assert!((f.w.eval(1.0) - 0.5).abs() < 1e-15);
        let h = 1e-6;
        assert!(((f.w.eval(1.0) - f.w.eval(1.0 - h)) / h).abs() < 1e-5);
        assert!(f.w.denominator.iter().all(|&b| b >= 0.0));
    }

    #[test]
    fn constant_and_non_monotone_data() {
        let f = fit(
            AngleHermite {
                w0: 0.2,
                w1: 0.2,
                s0: 0.0,
                s1: 0.0,
            },
            |_| 0.0,
        )
        .unwrap();
        assert!((f.w.eval(0.4) - 0.2).abs() < 1e-16);
        let bump = AngleHermite {
            w0: 0.0,
            w1: 0.1,
            s0: -1.0,
            s1: 1.0,
        };
        assert!(fit(bump, |_| 0.0).is_err());
    }
}
