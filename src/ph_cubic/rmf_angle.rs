//! The exact RMF of a PH cubic relative to its Frenet frame: the angle Ω of (5) in closed
//! form, equations (30)–(31) of Mäurer & Jüttler, with no numerical quadrature.
//!
//! By (6) and (18), Ω' = −τσ = −ρ / q(v), where q = σ/3 = L₁B₀² + L₂cosθ B₁² + L₃B₂² and ρ a
//! constant of the polygon. Writing q = L₁ − 2bv + cv² with b = L₁ − L₂cosθ,
//! c = L₁ − 2L₂cosθ + L₃ and a = √(L₁L₃ − L₂²cos²θ) as in (31),
//!
//! ```text
//!   Ω(v) − Ω(0) = −(ρ/a) · [arctan((cv − b)/a) + arctan(b/a)] = −(ρ/a) · atan2(a v, L₁ − b v),
//! ```
//!
//! the right-hand form being the difference of the two arctangents of (30) without
//! cancellation (its derivative is a / q(v), and its first argument stays positive). With
//! h₀, h₁, h₂ the legs, ρ = det(h₀, h₁, h₂) L₁² / |h₀ × h₁|², the PH-cubic value of τσ·q; its
//! sign is the sign of the torsion (the signed sin ψ of (30)), so both orientations are
//! covered, and ρ = 0 in the planar limit (the RMF is then the Frenet frame turned by a
//! constant). ρ is computed from the polygon orthogonalized against h₀ and h₁, which keeps
//! it accurate for nearly straight polygons (error ≈ ε / sin θ instead of ε / sin²θ).

use super::cubic::PhCubic;
use glam::DVec3;

/// Ω as a function of the segment parameter v ∈ [0, 1], up to its constant Ω(0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RmfAngle {
    /// ρ: Ω' = −ρ / q.
    rho: f64,
    /// a, b, c of (31) and L₁ = q(0).
    a: f64,
    b: f64,
    c: f64,
    l1: f64,
}

impl RmfAngle {
    /// The angle function of a PH cubic that is not a straight line.
    pub(crate) fn of(cubic: &PhCubic) -> Self {
        // Ω depends on the shape only: compute on the normalized cubic (no overflow).
        let cubic = cubic.normalized();
        let [l1, _, l3] = cubic.leg_lengths();
        let m = cubic.speed_middle();
        Self {
            rho: torsion_constant(&cubic),
            a: (l1 * l3 - m * m).max(0.0).sqrt(),
            b: l1 - m,
            c: l1 - 2.0 * m + l3,
            l1,
        }
    }

    /// ρ of the cubic scaled to a longest leg of 1; its sign is that of the torsion, zero for
    /// planar cubics.
    pub(crate) fn torsion_constant(&self) -> f64 {
        self.rho
    }

    /// q(v) = σ(v)/3.
    fn q(&self, v: f64) -> f64 {
        self.l1 - 2.0 * self.b * v + self.c * v * v
    }

    /// Ω'(v) = −τ(v) σ(v).
    pub(crate) fn rate(&self, v: f64) -> f64 {
        -self.rho / self.q(v)
    }

    /// Ω(v) − Ω(0), (30).
    pub(crate) fn increment(&self, v: f64) -> f64 {
        let integral = if self.a > 0.0 {
            (self.a * v).atan2(self.l1 - self.b * v) / self.a
        } else {
            // a → 0: (1/a) atan2(a v, L₁ − b v) → v / (L₁ − b v).
            v / (self.l1 - self.b * v)
        };
        -self.rho * integral
    }

    /// The parameters in (0, 1) where q equals `level` (q is a convex quadratic).
    pub(crate) fn where_q_equals(&self, level: f64) -> Vec<f64> {
        crate::math::quadratic_roots(self.c, -2.0 * self.b, self.l1 - level)
            .into_iter()
            .filter(|&v| v > 0.0 && v < 1.0)
            .collect()
    }
}

/// ρ = det(h₀, h₁, h₂) / |h₁⊥|², with h₁⊥ the part of h₁ orthogonal to h₀ (|h₀ × h₁| = L₁|h₁⊥|)
/// and det taken on the orthogonalized legs (same value, far less cancellation).
fn torsion_constant(cubic: &PhCubic) -> f64 {
    let [h0, h1, h2] = cubic.legs();
    let reject = |v: DVec3, from: DVec3| v - (v.dot(from) / from.length_squared()) * from;
    let h1p = reject(h1, h0);
    let n2 = h1p.length_squared();
    if n2 == 0.0 {
        return 0.0;
    }
    let h2p = reject(reject(h2, h0), h1p);
    h0.cross(h1p).dot(h2p) / n2
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::frenet::frenet_frame;
    use crate::math::GaussLegendre;
    use crate::ph_cubic::test_curves::{example_cubic, mirrored};
    use crate::testing::tschirnhausen;

    /// τσ from the derivatives of the Bézier curve, for comparison with −Ω'.
    fn torsion_times_speed(c: &PhCubic, v: f64) -> f64 {
        let bez = c.to_bezier();
        let jet = bez.eval_jet(v);
        let third = crate::bezier::bernstein::derivative(&crate::bezier::bernstein::derivative(
            &crate::bezier::bernstein::derivative(&c.control_points()),
        ))[0];
        let cross = jet.d1.cross(jet.d2);
        cross.dot(third) / cross.length_squared() * jet.d1.length()
    }

    #[test]
    fn rate_is_minus_torsion_times_speed_for_both_orientations() {
        for c in [example_cubic(), mirrored(&example_cubic())] {
            let omega = RmfAngle::of(&c);
            for i in 0..=10 {
                let v = i as f64 / 10.0;
                let expected = -torsion_times_speed(&c, v);
                assert!((omega.rate(v) - expected).abs() < 1e-13, "v = {v}");
            }
        }
        // det(h₀, h₁, h₂) = −2 for the example, whose longest leg is 2: ρ = −1 for the
        // normalized cubic, negative torsion; its mirror image has ρ = +1.
        assert!((RmfAngle::of(&example_cubic()).torsion_constant() + 1.0).abs() < 1e-15);
        assert!((RmfAngle::of(&mirrored(&example_cubic())).torsion_constant() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn closed_form_matches_the_integral_of_the_rate() {
        let omega = RmfAngle::of(&example_cubic());
        let rule = GaussLegendre::new(30);
        for v in [0.1, 0.5, 0.9, 1.0] {
            let quadrature = rule.integrate(0.0, v, |t| omega.rate(t));
            assert!((omega.increment(v) - quadrature).abs() < 1e-14, "v = {v}");
        }
    }

    #[test]
    fn frenet_frame_turned_by_omega_is_rotation_minimizing() {
        // f₂ = n cos Ω + b sin Ω must satisfy f₂' · f₃ = 0; checked by finite differences.
        let c = example_cubic();
        let bez = c.to_bezier();
        let omega = RmfAngle::of(&c);
        let frame = |v: f64| {
            let jet = bez.eval_jet(v);
            frenet_frame(jet.d1, jet.d2)
                .unwrap()
                .rotated(omega.increment(v))
        };
        let h = 1e-6;
        for v in [0.2, 0.5, 0.8] {
            let d = (frame(v + h).f2 - frame(v - h).f2) / (2.0 * h);
            assert!(d.dot(frame(v).f3).abs() < 1e-8, "v = {v}");
        }
    }

    #[test]
    fn planar_cubics_have_constant_angle() {
        let c = tschirnhausen(std::f64::consts::FRAC_PI_3, 1.0);
        let omega = RmfAngle::of(&c);
        assert_eq!(omega.torsion_constant(), 0.0);
        assert_eq!(omega.increment(0.7), 0.0);
    }
}
