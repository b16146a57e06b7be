//! One PH cubic (Mäurer & Jüttler, §3.1): its control polygon, the characterization (17),
//! the speed σ and the curvature of (18).
//!
//! With the legs h₀ = b₁ − b₀, h₁ = b₂ − b₁, h₂ = b₃ − b₂ the hodograph is
//! x' = 3(h₀B₀² + h₁B₁² + h₂B₂²), and the cubic is PH iff |x'|² = σ² for
//! σ = 3(L₁B₀² + L₂cosθ B₁² + L₃B₂²) (18). Comparing the degree-4 Bernstein coefficients of
//! |x'|² and σ² gives h₀·h₁ = L₁L₂cosθ = … = h₁·h₂ · L₁/L₃ (θ₁₂ = θ₂₃) and
//! 2L₂² + h₀·h₂ = 2(L₂cosθ)² + L₁L₃, which is the dihedral condition of (17). The
//! coefficient form is what [`PhCubic::hodograph_residual`] checks: it stays well
//! conditioned where the angles of (17) do not (nearly straight polygons);
//! [`PhCubic::polygon_condition`] evaluates (17) literally.

use super::hermite::ph_cubic_hermite;
use crate::bezier::bernstein::{self, add_product};
use crate::bezier::RationalBezierCurve;
use crate::error::{invalid, Result};
use crate::hermite::HermiteSegment;
use crate::math::{angle_between, largest_coordinate, robust_length};
use glam::DVec3;

/// Largest relative hodograph residual (see [`PhCubic::hodograph_residual`]) accepted for a
/// curve given as a PH cubic, unless the rounding of its control points allows more (see
/// [`PhCubic::ph_tolerance`]). Control points passed through NURBS data stay near 1e-15; a
/// cubic that is not PH is off by far more.
pub const PH_TOLERANCE: f64 = 1e-9;

/// A hodograph residual at the level of round-off in the polygon itself (below it, a cubic
/// is taken as exactly PH; see [`PhCubic::exactly_ph`]).
const ROUND_OFF_RESIDUAL: f64 = 4.0 * f64::EPSILON;

/// A regular PH cubic on [0, 1] (end legs of non-zero length, |x'| polynomial).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhCubic {
    points: [DVec3; 4],
}

/// The quantities of condition (17): the angles θ₁₂ = ∠(h₀, h₁), θ₂₃ = ∠(h₁, h₂), and cos ψ of
/// the dihedral angle ψ = ∠(h₀ × h₁, h₁ × h₂) beside its PH value 2L₂²/(L₁L₃) − 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonCondition {
    pub theta12: f64,
    pub theta23: f64,
    /// `None` when the polygon is straight (ψ undefined).
    pub cos_psi: Option<f64>,
    pub cos_psi_ph: f64,
}

impl PhCubic {
    /// Validates a cubic Bézier control polygon as a regular PH cubic: finite points, end
    /// legs of non-zero length and a hodograph residual below [`PH_TOLERANCE`].
    pub fn from_control_points(points: [DVec3; 4]) -> Result<Self> {
        if points.iter().any(|p| !p.is_finite()) {
            return invalid!("control points must be finite");
        }
        let cubic = Self { points };
        let [h0, _, h2] = cubic.legs();
        // An end leg below the rounding of the points has no direction (a leg of 0.02
        // beside coordinates of 1e164: its frames would be NaN).
        let rounding = f64::EPSILON * largest_coordinate(points);
        if robust_length(h0) <= rounding || robust_length(h2) <= rounding {
            return invalid!(
                "the first and last legs of a PH cubic must not vanish (singular end): they \
                 must be longer than the rounding of the control points, {rounding:.1e}"
            );
        }
        let residual = cubic.hodograph_residual();
        if residual.is_nan() || residual > cubic.ph_tolerance() {
            return invalid!(
                "the control polygon violates the PH condition (17): relative residual {residual:.1e}"
            );
        }
        Ok(cubic)
    }

    /// A cubic known to be PH by construction (the Hermite interpolant checks its residual).
    pub(crate) fn from_trusted_points(points: [DVec3; 4]) -> Self {
        Self { points }
    }

    /// The four Bézier control points.
    pub fn control_points(&self) -> [DVec3; 4] {
        self.points
    }

    /// h₀, h₁, h₂.
    pub fn legs(&self) -> [DVec3; 3] {
        let b = &self.points;
        [b[1] - b[0], b[2] - b[1], b[3] - b[2]]
    }

    /// L₁, L₂, L₃ (without over- or underflow in the squares).
    pub fn leg_lengths(&self) -> [f64; 3] {
        self.legs().map(robust_length)
    }

    /// The legs divided by the longest one, and its length: the products of the scalar
    /// quantities below are taken on these, so that cubics of any size (1e-200 … 1e200) have
    /// no square that under- or overflows (a helix ×1e-200 "missed the PH condition by NaN").
    fn unit_legs(&self) -> ([DVec3; 3], f64) {
        let legs = self.legs();
        let longest = legs.iter().fold(0.0f64, |m, &h| m.max(robust_length(h)));
        if longest == 0.0 {
            return (legs, 1.0);
        }
        (legs.map(|h| h / longest), longest)
    }

    /// L₂ cos θ, the middle coefficient of σ/3. Both expressions h₀·h₁/L₁ and h₁·h₂/L₃ give it
    /// for a PH cubic; their mean keeps a rounded polygon symmetric in its two ends.
    pub fn speed_middle(&self) -> f64 {
        let ([h0, h1, h2], scale) = self.unit_legs();
        0.5 * (h0.dot(h1) / h0.length() + h1.dot(h2) / h2.length()) * scale
    }

    /// Bernstein coefficients of the speed σ = |x'| (18): 3(L₁, L₂cosθ, L₃). The middle one
    /// is negative when θ > 90°, so positive weights need a subdivision there.
    pub fn speed(&self) -> [f64; 3] {
        let [l1, _, l3] = self.leg_lengths();
        [3.0 * l1, 3.0 * self.speed_middle(), 3.0 * l3]
    }

    /// Bernstein coefficients of the arc length s(v) = ∫₀ᵛ σ: (0, L₁, L₁ + L₂cosθ,
    /// L₁ + L₂cosθ + L₃) — polynomial, as for every PH curve.
    pub fn arc_length_polynomial(&self) -> [f64; 4] {
        let [l1, _, l3] = self.leg_lengths();
        let m = self.speed_middle();
        [0.0, l1, l1 + m, l1 + m + l3]
    }

    /// The arc length, exact (PH curves have polynomial speed).
    pub fn arc_length(&self) -> f64 {
        self.arc_length_polynomial()[3]
    }

    /// max |coefficient of |x'|² − σ²| / max |coefficient of |x'|²|, in the degree-4 Bernstein
    /// basis: zero exactly for PH cubics (see the module notes).
    pub fn hodograph_residual(&self) -> f64 {
        let (legs, _) = self.unit_legs();
        let [h0, h1, h2] = legs;
        let (l1, l3) = (h0.length(), h2.length());
        let speed = [l1, 0.5 * (h0.dot(h1) / l1 + h1.dot(h2) / l3), l3];
        let (mut squared, mut speed_squared) = ([0.0; 5], [0.0; 5]);
        add_product(&legs, &legs, |a: DVec3, b: DVec3| a.dot(b), &mut squared);
        add_product(&speed, &speed, |a: f64, b: f64| a * b, &mut speed_squared);
        let scale = squared.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let worst = squared
            .iter()
            .zip(&speed_squared)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        worst / scale
    }

    /// The residual accepted for this polygon: [`PH_TOLERANCE`], or more for a short segment
    /// far from the origin, whose legs (differences of rounded points) are only exact to
    /// ε·|b|, which makes |x'|² uncertain by about ε·|b|/L relative.
    pub fn ph_tolerance(&self) -> f64 {
        let coordinates = largest_coordinate(self.points);
        let longest = self.leg_lengths().iter().fold(0.0f64, |m, &l| m.max(l));
        PH_TOLERANCE.max(64.0 * f64::EPSILON * coordinates / longest)
    }

    /// Condition (17) evaluated literally on the control polygon.
    pub fn polygon_condition(&self) -> PolygonCondition {
        let ([h0, h1, h2], _) = self.unit_legs();
        let [l1, l2, l3] = [h0, h1, h2].map(DVec3::length);
        let (n1, n2) = (h0.cross(h1), h1.cross(h2));
        let cos_psi = (n1 != DVec3::ZERO && n2 != DVec3::ZERO)
            .then(|| n1.dot(n2) / (n1.length() * n2.length()));
        PolygonCondition {
            theta12: angle_between(h0, h1),
            theta23: angle_between(h1, h2),
            cos_psi,
            cos_psi_ph: 2.0 * l2 * l2 / (l1 * l3) - 1.0,
        }
    }

    /// sin θ, θ = ∠(h₀, h₁): how far the polygon bends (0 for a straight line).
    pub fn bend(&self) -> f64 {
        let ([h0, h1, _], _) = self.unit_legs();
        let (l1, l2) = (h0.length(), h1.length());
        if l2 == 0.0 {
            return 0.0;
        }
        h0.cross(h1).length() / (l1 * l2)
    }

    /// min σ / max σ on [0, 1]. σ/3 = L₁ − 2bv + cv² is convex (c = L₁ − 2L₂cos θ + L₃ > 0), so
    /// its maximum is at an end and its minimum at an end or at the vertex, where it is
    /// (L₁L₃ − L₂²cos²θ)/c (the a²/c of (31)). For L₂cos θ ≥ 0 the value there is taken from
    /// the Bernstein form L₁(1 − v)² + 2L₂cos θ v(1 − v) + L₃v² instead, a sum of positive
    /// terms: for nearly straight polygons the literal formula is 0/0 (a cubic turning by
    /// 2e-9 rad had a "cusp"), while σ is then nearly constant and any v near the vertex
    /// gives its least value.
    pub fn speed_ratio(&self) -> f64 {
        let [l1, _, l3] = self.leg_lengths();
        let m = self.speed_middle();
        let (b, c) = (l1 - m, l1 - 2.0 * m + l3);
        let vertex = b / c;
        let least = if vertex > 0.0 && vertex < 1.0 {
            if m >= 0.0 {
                let u = 1.0 - vertex;
                l1 * u * u + 2.0 * m * vertex * u + l3 * vertex * vertex
            } else {
                (l1 * l3 - m * m).max(0.0) / c
            }
        } else {
            l1.min(l3)
        };
        least / l1.max(l3)
    }

    /// Curvature κ(v) = 6L₂|sin θ| / σ(v)² (18).
    pub fn curvature(&self, v: f64) -> f64 {
        let unit = self.normalized();
        let ([h0, h1, _], scale) = self.unit_legs();
        let sigma = bernstein::evaluate(&unit.speed(), v);
        6.0 * h0.cross(h1).length() / h0.length() / (sigma * sigma) / scale
    }

    /// The cubic as a polynomial Bézier curve.
    pub fn to_bezier(&self) -> RationalBezierCurve {
        RationalBezierCurve::polynomial(&self.points).expect("finite control points")
    }

    /// Point at v.
    pub fn eval(&self, v: f64) -> DVec3 {
        bernstein::evaluate(&self.points, v)
    }

    /// First derivative x'(v).
    pub fn derivative(&self, v: f64) -> DVec3 {
        bernstein::evaluate(&self.legs(), v) * 3.0
    }

    /// The same cubic moved to b₀ = 0 and scaled to a longest leg of 1: frames, angles and
    /// curvature ratios do not change, and the products that compute them neither underflow
    /// nor overflow for curves of any size.
    pub fn normalized(&self) -> Self {
        // Robustly: legs beyond 1e154 would overflow in |h|² (and the frames be NaN).
        let longest = self
            .legs()
            .iter()
            .fold(0.0f64, |m, &h| m.max(robust_length(h)));
        let origin = self.points[0];
        Self {
            points: self.points.map(|p| (p - origin) / longest),
        }
    }

    /// The PH cubic through this polygon's end points and end tangents (the interpolant of
    /// Table 1 nearest to it) when its hodograph residual is above round-off; itself
    /// otherwise.
    ///
    /// The frames (19), (29) and the angle (30) assume the PH identity |x'| = σ exactly.
    /// Taken literally, (19) turns a residual r into an orthonormality error of about
    /// r / sin²θ (2e-5 for r = 1e-9 at θ = 2e-3); computed from the quaternion
    /// preimage (x' = A i A*) the frames are orthonormal anyway, but adapted to the PH
    /// cubic nearest the polygon, whose hodograph differs from it by about r. So a polygon accepted
    /// within [`PH_TOLERANCE`] (data read from files, or rounded far from the origin) gets its
    /// frames from the exact PH cubic of its own Hermite data, which it matches at both ends
    /// and within r inside. When no PH cubic interpolates those data (a segment so short
    /// against its distance from the origin that rounding reverses a leg, where the literal
    /// frames have vectors of length 0.5) no frame fits the polygon, and it is refused.
    pub fn exactly_ph(&self) -> Result<Self> {
        let residual = self.hodograph_residual();
        if residual <= ROUND_OFF_RESIDUAL {
            return Ok(*self);
        }
        let [p0, _, _, p3] = self.points;
        let [h0, _, h2] = self.legs();
        let interpolants = HermiteSegment::new(p0, h0, p3, h2).and_then(|d| ph_cubic_hermite(&d));
        let Ok(solutions) = interpolants else {
            return invalid!(
                "the control polygon is PH only within rounding (relative residual \
                 {residual:.1e}) and no PH cubic interpolates its end points and tangents: \
                 its frames cannot be computed orthonormal"
            );
        };
        let distance = |c: &PhCubic| {
            c.points
                .iter()
                .zip(&self.points)
                .fold(0.0f64, |m, (a, b)| m.max(robust_length(*a - *b)))
        };
        Ok(std::iter::once(solutions.shape_matching)
            .chain(solutions.other)
            .min_by(|a, b| distance(a).total_cmp(&distance(b)))
            .unwrap_or(*self))
    }

    /// Sum of the leg lengths, the criterion of Table 1 for the shape-matching interpolant.
    pub fn polygon_length(&self) -> f64 {
        self.leg_lengths().iter().sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ph_cubic::test_curves::example_cubic;

    #[test]
    fn speed_is_the_length_of_the_derivative() {
        let c = example_cubic();
        let sigma = c.speed();
        for i in 0..=20 {
            let v = i as f64 / 20.0;
            let speed = bernstein::evaluate(&sigma, v);
            assert!((c.derivative(v).length() - speed).abs() < 1e-14, "v = {v}");
        }
        // L1 = L2 = 1, L3 = 2, L2 cos θ = 0: arc length L1 + L2 cos θ + L3 = 3.
        assert!((c.arc_length() - 3.0).abs() < 1e-15);
        // σ/3 = (1 − v)² + 2v² is least at v = 1/3 (2/3) and largest at v = 1 (2).
        assert!((c.speed_ratio() - 1.0 / 3.0).abs() < 1e-15);
        assert!(c.hodograph_residual() < 1e-15);
    }

    /// A quadratic NURBS with a pole at 1e164 taken as a PH spline: its last leg, 0.02, is
    /// below the rounding of the points, so the end is singular (its frames would be NaN).
    #[test]
    fn end_legs_below_the_rounding_of_the_points_are_singular() {
        let far = DVec3::new(1.0, 0.0, 1.1517219314030583e164);
        let points = [far, far / 3.0, DVec3::new(0.0, 0.0208, 0.0), DVec3::ZERO];
        let e = PhCubic::from_control_points(points).unwrap_err();
        assert!(e.message().contains("singular end"), "{e}");
        // The same shape near the origin is a regular (straight) PH cubic.
        let near = DVec3::new(1.0, 0.0, 3.0);
        let points = [near, near * (2.0 / 3.0), near / 3.0, DVec3::ZERO];
        assert!(PhCubic::from_control_points(points).is_ok());
    }

    #[test]
    fn condition_17_holds_literally() {
        let p = example_cubic().polygon_condition();
        assert!((p.theta12 - p.theta23).abs() < 1e-15);
        assert!((p.cos_psi.unwrap() - p.cos_psi_ph).abs() < 1e-15);
    }

    #[test]
    fn curvature_matches_the_derivatives() {
        let c = example_cubic();
        let bez = c.to_bezier();
        for v in [0.0, 0.3, 0.8, 1.0] {
            let jet = bez.eval_jet(v);
            let kappa = jet.d1.cross(jet.d2).length() / jet.d1.length().powi(3);
            assert!((c.curvature(v) - kappa).abs() < 1e-13 * kappa, "v = {v}");
        }
    }

    #[test]
    fn rejects_cubics_that_are_not_ph() {
        let e = PhCubic::from_control_points([
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(3.0, 1.0, 1.0),
        ])
        .unwrap_err();
        assert!(e.message().contains("(17)"), "{e}");
        let singular = [DVec3::ZERO, DVec3::ZERO, DVec3::X, DVec3::Y];
        assert!(PhCubic::from_control_points(singular).is_err());
        let nan = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::splat(f64::NAN)];
        assert!(PhCubic::from_control_points(nan).is_err());
    }
}
