//! The Hopf-map model of a PH quintic and its frames (Section 2, eqs. (2)–(9)).
//!
//! Two complex quadratics α(t), β(t) in Bernstein form (6) give the hodograph
//! r'(t) = H(α, β) = (|α|² − |β|², 2 Re(α β̄), 2 Im(α β̄)) (3), whose length is the
//! polynomial σ = |α|² + |β|² (1). From them come the Euler–Rodrigues frame (5), the
//! complex quadratic w(t) that certifies an RRMF curve, and the rational RMF (9):
//! f₂ + i f₃ = w² (e₂ + i e₃) / |w|², i.e. f₂ = ((a² − b²) e₂ − 2ab e₃)/(a² + b²) and
//! f₃ = (2ab e₂ + (a² − b²) e₃)/(a² + b²) with w = a + i b.
//!
//! Everything is computed exactly in Bernstein form with `bernstein::product`; products
//! of Bernstein polynomials never leave the basis, so no power-form round-off enters.

use crate::bezier::bernstein::{product, restrict};
use crate::math::Complex;
use glam::DVec3;

/// The quadratic Hopf polynomials α(t) = Σ α_k B_k²(t), β(t) = Σ β_k B_k²(t) of (6).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HopfQuadratics {
    pub alpha: [Complex; 3],
    pub beta: [Complex; 3],
}

/// The exact rational RMF (9) of one quintic on an interval: f₂ = `f2` / `denominator`,
/// f₃ = `f3` / `denominator`, all of degree 8 in Bernstein form. The denominator is
/// (a² + b²)(|α|² + |β|²), positive on [0, 1], though its coefficients need not be.
#[derive(Clone, Debug, PartialEq)]
pub struct RmfNumerators {
    pub f2: Vec<DVec3>,
    pub f3: Vec<DVec3>,
    pub denominator: Vec<f64>,
}

/// Coefficient pairs (α_k, β_k), the argument of the bilinear products below.
type Pair = (Complex, Complex);

impl HopfQuadratics {
    fn pairs(&self) -> [Pair; 3] {
        [0, 1, 2].map(|k| (self.alpha[k], self.beta[k]))
    }

    /// α and β restricted to [s0, s1] and reparameterized to [0, 1].
    pub fn restricted(&self, s0: f64, s1: f64) -> Self {
        let piece = |z: &[Complex; 3]| {
            let r = restrict(z, s0, s1);
            [r[0], r[1], r[2]]
        };
        Self {
            alpha: piece(&self.alpha),
            beta: piece(&self.beta),
        }
    }

    /// The same polynomials times a real factor (how (36) scales a_k, b_k by γ).
    pub fn scaled(&self, factor: f64) -> Self {
        Self {
            alpha: self.alpha.map(|z| z * factor),
            beta: self.beta.map(|z| z * factor),
        }
    }

    /// The hodograph H(α, β) of (3): Bernstein coefficients of degree 4.
    pub fn hodograph(&self) -> Vec<DVec3> {
        let p = self.pairs();
        product(&p, &p, |(a1, b1): Pair, (a2, b2): Pair| {
            let ab = a1 * b2.conj();
            DVec3::new(
                (a1 * a2.conj() - b1 * b2.conj()).re,
                2.0 * ab.re,
                2.0 * ab.im,
            )
        })
    }

    /// The parametric speed σ = |α|² + |β|² (1), degree 4.
    pub fn speed(&self) -> Vec<f64> {
        let p = self.pairs();
        product(&p, &p, |(a1, b1): Pair, (a2, b2): Pair| {
            (a1 * a2.conj() + b1 * b2.conj()).re
        })
    }

    /// The Bézier control points (degree 5) of r(t) = start + ∫₀ᵗ H(α, β): integrating
    /// Bernstein coefficients, r_{k+1} = r_k + h_k / 5.
    pub fn control_points(&self, start: DVec3) -> Vec<DVec3> {
        let mut points = vec![start];
        for h in self.hodograph() {
            let last = points[points.len() - 1];
            points.push(last + h / 5.0);
        }
        points
    }

    /// r(1) − r(0) = ∫₀¹ H(α, β) dt, the left-hand sides of (14)–(15) divided by 5.
    pub fn displacement(&self) -> DVec3 {
        self.hodograph().iter().sum::<DVec3>() / 5.0
    }

    /// The numerators of e₂ and e₃ of the Euler–Rodrigues frame (5) (their denominator is
    /// the speed σ), degree 4.
    fn erf_numerators(&self) -> (Vec<DVec3>, Vec<DVec3>) {
        let p = self.pairs();
        let e2 = product(&p, &p, |(a1, b1): Pair, (a2, b2): Pair| {
            let (aa, bb, ab) = (a1 * a2, b1 * b2, a1 * b2);
            DVec3::new(-2.0 * ab.re, (aa - bb).re, (aa + bb).im)
        });
        let e3 = product(&p, &p, |(a1, b1): Pair, (a2, b2): Pair| {
            let (aa, bb, ab) = (a1 * a2, b1 * b2, a1 * b2);
            DVec3::new(2.0 * ab.im, -(aa - bb).im, (aa + bb).re)
        });
        (e2, e3)
    }

    /// The coefficients of w(t) = w₀ B₀² + w₁ B₁² + w₂ B₂² of Section 2:
    /// w₀ = 1, w₁ = (ᾱ₀α₁ + β̄₀β₁)/(|α₀|² + |β₀|²), w₂ = (ᾱ₁α₂ + β̄₁β₂)/(α₀ᾱ₁ + β₀β̄₁).
    /// The last denominator vanishes only if α₁ = β₁ = 0, which (8) forbids for non-planar
    /// data.
    pub fn w(&self) -> [Complex; 3] {
        let [a0, a1, a2] = self.alpha;
        let [b0, b1, b2] = self.beta;
        let n0 = a0.norm_sqr() + b0.norm_sqr();
        [
            Complex::ONE,
            (a0.conj() * a1 + b0.conj() * b1) / n0,
            (a1.conj() * a2 + b1.conj() * b2) / (a0 * a1.conj() + b0 * b1.conj()),
        ]
    }

    /// The rational RMF (9) on [s0, s1], reparameterized to [0, 1], as numerators over one
    /// denominator of degree 8, computed from α, β and w restricted to the piece: near a dip
    /// of the speed (w almost vanishing) the degree-8 products cancel, and forming them from
    /// the local coefficients keeps the digits that subdividing the products on [0, 1] loses.
    pub fn rmf_numerators_on(&self, s0: f64, s1: f64) -> RmfNumerators {
        let w = restrict(&self.w(), s0, s1);
        self.restricted(s0, s1).rotated_erf(&[w[0], w[1], w[2]])
    }

    /// The ERF (5) turned about the tangent by the angle of w² (the frame (9) for any
    /// complex quadratic w; w = 1 gives the ERF itself).
    pub(crate) fn rotated_erf(&self, w: &[Complex; 3]) -> RmfNumerators {
        // w² = (a² − b²) + i 2ab and |w|² = a² + b², each degree 4.
        let w_squared = product(w, w, |x: Complex, y: Complex| x * y);
        let cos_part: Vec<f64> = w_squared.iter().map(|z| z.re).collect();
        let sin_part: Vec<f64> = w_squared.iter().map(|z| z.im).collect();
        let w_norm = product(w, w, |x: Complex, y: Complex| (x * y.conj()).re);
        let (e2, e3) = self.erf_numerators();
        let times = |s: &[f64], v: &[DVec3]| product(s, v, |s: f64, v: DVec3| v * s);
        let combine = |a: Vec<DVec3>, b: Vec<DVec3>, sign: f64| {
            a.iter().zip(&b).map(|(&x, &y)| x + y * sign).collect()
        };
        RmfNumerators {
            f2: combine(times(&cos_part, &e2), times(&sin_part, &e3), -1.0),
            f3: combine(times(&sin_part, &e2), times(&cos_part, &e3), 1.0),
            denominator: product(&w_norm, &self.speed(), |a: f64, b: f64| a * b),
        }
    }

    /// Relative residuals of the RRMF conditions (7) and (8): |lhs − rhs| divided by the
    /// sum of the magnitudes of the terms (zero for an exact RRMF quintic).
    pub fn rrmf_residuals(&self) -> (f64, f64) {
        let [a0, a1, a2] = self.alpha;
        let [b0, b1, b2] = self.beta;
        let n0 = a0.norm_sqr() + b0.norm_sqr();
        let n2 = a2.norm_sqr() + b2.norm_sqr();
        let start = a0 * a1.conj() + b0 * b1.conj();
        let end = a1.conj() * a2 + b1.conj() * b2;
        let (lhs7, rhs7) = (n0 * end.norm_sqr(), n2 * start.norm_sqr());
        let (left8, right8) = (a0 * b2 - a2 * b0, a0 * b1 - a1 * b0);
        let lhs8 = left8 * n0;
        let rhs8 = start * right8 * 2.0;
        let scale8 = n0 * ((a0 * b2).abs() + (a2 * b0).abs())
            + 2.0 * start.abs() * ((a0 * b1).abs() + (a1 * b0).abs());
        (
            relative(lhs7 - rhs7, lhs7.abs() + rhs7.abs()),
            relative((lhs8 - rhs8).abs(), scale8),
        )
    }
}

/// `|difference| / scale`, and 0 when both vanish.
fn relative(difference: f64, scale: f64) -> f64 {
    if scale > 0.0 {
        difference.abs() / scale
    } else {
        difference.abs()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::bernstein::{evaluate, evaluate_jet};

    /// Arbitrary (not RRMF) quadratics.
    fn sample() -> HopfQuadratics {
        HopfQuadratics {
            alpha: [
                Complex::new(1.2, 0.0),
                Complex::new(-0.3, 0.7),
                Complex::new(0.4, -0.9),
            ],
            beta: [
                Complex::new(0.5, 0.2),
                Complex::new(0.8, -0.1),
                Complex::new(-0.6, 0.3),
            ],
        }
    }

    #[test]
    fn hodograph_is_pythagorean_and_integrates_to_the_control_points() {
        let h = sample();
        let hodograph = h.hodograph();
        let speed = h.speed();
        let points = h.control_points(DVec3::new(1.0, 2.0, 3.0));
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            let d = evaluate(&hodograph, t);
            assert!((d.length() - evaluate(&speed, t)).abs() < 1e-14);
            let curve = evaluate_jet(&points, t);
            assert!((curve.d1 - d).length() < 1e-13);
        }
        let chord = points[5] - points[0];
        assert!((chord - h.displacement()).length() < 1e-15);
    }

    #[test]
    fn euler_rodrigues_frame_is_orthonormal_and_adapted() {
        let h = sample();
        let (e2, e3) = h.erf_numerators();
        let (hodograph, speed) = (h.hodograph(), h.speed());
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            let s = evaluate(&speed, t);
            let e1 = evaluate(&hodograph, t) / s;
            let (e2, e3) = (evaluate(&e2, t) / s, evaluate(&e3, t) / s);
            assert!((e2.length() - 1.0).abs() < 1e-14 && (e3.length() - 1.0).abs() < 1e-14);
            assert!(e1.dot(e2).abs() < 1e-14 && e2.dot(e3).abs() < 1e-14);
            assert!((e1.cross(e2) - e3).length() < 1e-14, "right-handed");
        }
    }

    #[test]
    fn a_non_rrmf_quintic_has_residuals() {
        let (r7, r8) = sample().rrmf_residuals();
        assert!(r7 > 1e-3 && r8 > 1e-3, "{r7} {r8}");
    }
}
