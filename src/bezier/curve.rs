//! Rational Bézier curves of any degree on [0, 1], stored in homogeneous coordinates
//! (w·x, w·y, w·z, w). The same type holds rational *vector* functions (frame vectors,
//! whose "points" are directions); a polynomial curve has all weights 1.

use super::bernstein::{self, MAX_DEGREE};
use super::homogeneous::{lift, project, rational_jet, rational_jet3};
use crate::error::{invalid, Result};
use glam::{DVec3, DVec4};

/// Point, first and second derivative of a curve at one parameter.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CurveJet {
    /// x(t).
    pub point: DVec3,
    /// x'(t).
    pub d1: DVec3,
    /// x''(t).
    pub d2: DVec3,
}

/// A rational Bézier curve on [0, 1] in homogeneous form.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBezierCurve {
    points: Vec<DVec4>,
}

impl RationalBezierCurve {
    /// From homogeneous control points (at least one, degree ≤ MAX_DEGREE, all weights
    /// positive and everything finite).
    pub fn from_homogeneous(points: Vec<DVec4>) -> Result<Self> {
        if points.is_empty() || points.len() > MAX_DEGREE + 1 {
            return invalid!(
                "a Bézier curve needs 1 to {} control points, got {}",
                MAX_DEGREE + 1,
                points.len()
            );
        }
        for (i, p) in points.iter().enumerate() {
            if !p.is_finite() || p.w <= 0.0 {
                return invalid!(
                    "control point {i} is not finite or has a non-positive weight ({p})"
                );
            }
        }
        Ok(Self { points })
    }

    /// From Cartesian control points and positive weights.
    pub fn from_weighted(poles: &[DVec3], weights: &[f64]) -> Result<Self> {
        if poles.len() != weights.len() {
            return invalid!("{} poles but {} weights", poles.len(), weights.len());
        }
        Self::from_homogeneous(
            poles
                .iter()
                .zip(weights)
                .map(|(&p, &w)| lift(p, w))
                .collect(),
        )
    }

    /// A polynomial curve (all weights 1).
    pub fn polynomial(poles: &[DVec3]) -> Result<Self> {
        Self::from_homogeneous(poles.iter().map(|&p| p.extend(1.0)).collect())
    }

    /// The polynomial curve Σ cₖ tᵏ on [0, 1] from its power-basis coefficients cₖ.
    pub fn from_power(coefficients: &[DVec3]) -> Result<Self> {
        Self::polynomial(&super::bernstein::from_power(coefficients))
    }

    /// Assembles `numerator / denominator` from Bernstein coefficients of equal degree.
    /// Used for frame vectors given as a vector polynomial over a positive scalar one.
    pub fn from_numerator_denominator(numerator: &[DVec3], denominator: &[f64]) -> Result<Self> {
        if numerator.len() != denominator.len() {
            return invalid!("numerator and denominator degrees differ");
        }
        Self::from_homogeneous(
            numerator
                .iter()
                .zip(denominator)
                .map(|(n, &d)| n.extend(d))
                .collect(),
        )
    }

    /// (centre, radius) when the curve is a circular arc, a rational quadratic with equal
    /// legs (within `tol`) whose inner weight, in standard form, is the cosine of the angle
    /// between leg and chord.
    pub fn circular_arc(&self, tol: f64) -> Option<(DVec3, f64)> {
        if self.degree() != 2 {
            return None;
        }
        let h = &self.points;
        let (p0, p1, p2) = (
            h[0].truncate() / h[0].w,
            h[1].truncate() / h[1].w,
            h[2].truncate() / h[2].w,
        );
        let w = h[1].w / (h[0].w * h[2].w).sqrt();
        let (l0, l1) = ((p1 - p0).length(), (p2 - p1).length());
        let chord = p2 - p0;
        let cos = (p1 - p0).dot(chord) / (l0 * chord.length());
        if (l0 - l1).abs() > tol || (w - cos).abs() > 1e-12 || w <= 0.0 {
            return None;
        }
        let bend = (p1 - p0).cross(chord);
        if bend.length() <= 1e-14 * l0 * chord.length() {
            return None; // a straight piece
        }
        // The centre lies on the normal of the leg at p0, equidistant from p0 and p2.
        let normal = bend.cross(p1 - p0).normalize();
        let s = chord.length_squared() / (2.0 * chord.dot(normal));
        Some((p0 + s * normal, s.abs()))
    }

    /// The polynomial degree.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// Homogeneous control points.
    pub fn homogeneous(&self) -> &[DVec4] {
        &self.points
    }

    /// Cartesian control points.
    pub fn poles(&self) -> impl Iterator<Item = DVec3> + '_ {
        self.points.iter().map(|&h| project(h))
    }

    /// Weights of the control points.
    pub fn weights(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|h| h.w)
    }

    /// True when every weight equals the first one (a polynomial curve up to scaling).
    pub fn is_polynomial(&self) -> bool {
        let w0 = self.points[0].w;
        self.points.iter().all(|h| (h.w - w0).abs() <= 1e-15 * w0)
    }

    /// The point at the local parameter t in [0, 1].
    pub fn eval(&self, t: f64) -> DVec3 {
        project(bernstein::evaluate(&self.points, t))
    }

    /// Point and first derivative with respect to the local parameter.
    pub fn eval_d1(&self, t: f64) -> (DVec3, DVec3) {
        let (h, h1) = bernstein::evaluate_d1(&self.points, t);
        let p = project(h);
        (p, (h1.truncate() - h1.w * p) / h.w)
    }

    /// Point and first two derivatives with respect to the local parameter.
    pub fn eval_jet(&self, t: f64) -> CurveJet {
        let jet = bernstein::evaluate_jet(&self.points, t);
        let [point, d1, d2] = rational_jet(jet.value, jet.d1, jet.d2);
        CurveJet { point, d1, d2 }
    }

    /// Point and first three derivatives with respect to the local parameter (x''' from
    /// the jet of the hodograph).
    pub fn eval_jet3(&self, t: f64) -> [DVec3; 4] {
        let h = bernstein::evaluate(&self.points, t);
        let hodograph = bernstein::derivative(&self.points);
        let d = bernstein::evaluate_jet(&hodograph, t);
        rational_jet3(h, d.value, d.d1, d.d2)
    }

    /// Bernstein coefficients on [0, 1] of det(X, X', X'', X''') for the homogeneous curve
    /// X = (w x, w): w⁴ det(x', x'', x'''), the numerator of the torsion (a
    /// polynomial of degree 4n − 6 also for rational curves). Computed as the reciprocal
    /// product of the Plücker coordinates of the lines X ∧ X' and X'' ∧ X''', so that only
    /// Bernstein products appear.
    pub fn torsion_numerator(&self) -> Vec<f64> {
        let d1 = bernstein::derivative(&self.points);
        let d2 = bernstein::derivative(&d1);
        let d3 = bernstein::derivative(&d2);
        let moment = |a: &[DVec4], b: &[DVec4]| {
            bernstein::product(a, b, |x: DVec4, y: DVec4| x.truncate().cross(y.truncate()))
        };
        let direction = |a: &[DVec4], b: &[DVec4]| {
            bernstein::product(a, b, |x: DVec4, y: DVec4| {
                x.w * y.truncate() - y.w * x.truncate()
            })
        };
        let (m1, l1) = (moment(&self.points, &d1), direction(&self.points, &d1));
        let (m2, l2) = (moment(&d2, &d3), direction(&d2, &d3));
        let dot = |x: DVec3, y: DVec3| x.dot(y);
        let mut det = bernstein::product(&m1, &l2, dot);
        bernstein::add_product(&m2, &l1, dot, &mut det);
        det
    }

    /// The same curve in degree `degree + r`.
    pub fn elevated(&self, r: usize) -> Self {
        Self {
            points: bernstein::elevate(&self.points, r),
        }
    }

    /// The same curve with every homogeneous point multiplied by `factor > 0`, which leaves
    /// the geometry and parameterization unchanged and scales all weights.
    pub fn scaled_weights(&self, factor: f64) -> Self {
        Self {
            points: self.points.iter().map(|&h| h * factor).collect(),
        }
    }

    /// The same curve scaled by `scale` about the origin, then moved by `offset`:
    /// (w x, w) becomes (w (scale x + offset), w).
    pub fn similar(&self, scale: f64, offset: DVec3) -> Self {
        Self {
            points: self
                .points
                .iter()
                .map(|&h| (h.truncate() * scale + offset * h.w).extend(h.w))
                .collect(),
        }
    }

    /// The same curve with its start (`at_start`) or end point moved to `point` and the
    /// neighbouring control point moved onto the line through it along `tangent`, weights
    /// kept: the end point and the end tangent's direction become exactly the given ones
    /// (for curves that already have them up to rounding). Also returns the angle by which
    /// the end leg turned.
    pub fn with_pinned_end(&self, at_start: bool, point: DVec3, tangent: DVec3) -> (Self, f64) {
        let n = self.degree();
        let (end, next) = if at_start { (0, 1) } else { (n, n - 1) };
        let mut points = self.points.clone();
        let mut turned = 0.0;
        let end_weight = points[end].w;
        points[end] = lift(point, end_weight);
        if n >= 1 {
            let weight = points[next].w;
            let leg = project(points[next]) - point;
            let along = leg.dot(tangent) * tangent;
            turned = crate::math::angle_between(leg, along);
            points[next] = lift(point + along, weight);
        }
        (Self { points }, turned)
    }

    /// The pieces on [0, t] and [t, 1], each on [0, 1].
    pub fn split(&self, t: f64) -> (Self, Self) {
        let (a, b) = bernstein::split(&self.points, t);
        (Self { points: a }, Self { points: b })
    }

    /// The piece on [t0, t1], reparameterized to [0, 1].
    pub fn restricted(&self, t0: f64, t1: f64) -> Self {
        Self {
            points: bernstein::restrict(&self.points, t0, t1),
        }
    }

    /// The same curve traversed backwards: t ↦ 1 − t (the control points reversed).
    pub fn reversed(&self) -> Self {
        Self {
            points: self.points.iter().rev().copied().collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quarter circle of radius 1 as a rational quadratic.
    fn quarter_circle() -> RationalBezierCurve {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        RationalBezierCurve::from_weighted(
            &[DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
            &[1.0, s, 1.0],
        )
        .unwrap()
    }

    #[test]
    fn evaluates_an_exact_circle() {
        let c = quarter_circle();
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            let jet = c.eval_jet(t);
            assert!((jet.point.length() - 1.0).abs() < 1e-15);
            assert!(
                jet.point.dot(jet.d1).abs() < 1e-14,
                "tangent is perpendicular to the radius"
            );
            // d/dt |p|² = 0 twice: p·p'' + |p'|² = 0.
            assert!((jet.point.dot(jet.d2) + jet.d1.length_squared()).abs() < 1e-13);
        }
    }

    #[test]
    fn elevation_split_and_scaling_keep_the_curve() {
        let c = quarter_circle();
        let e = c.elevated(4);
        let (l, r) = c.split(0.4);
        let s = c.scaled_weights(3.5);
        let sub = c.restricted(0.25, 0.75);
        for i in 0..=8 {
            let t = i as f64 / 8.0;
            assert!((e.eval(t) - c.eval(t)).length() < 1e-15);
            assert!((l.eval(t) - c.eval(0.4 * t)).length() < 1e-15);
            assert!((r.eval(t) - c.eval(0.4 + 0.6 * t)).length() < 1e-15);
            assert!((s.eval(t) - c.eval(t)).length() < 1e-15);
            assert!((sub.eval(t) - c.eval(0.25 + 0.5 * t)).length() < 1e-15);
        }
    }

    #[test]
    fn rejects_bad_weights() {
        assert!(RationalBezierCurve::from_weighted(&[DVec3::X, DVec3::Y], &[1.0, 0.0]).is_err());
        assert!(
            RationalBezierCurve::from_weighted(&[DVec3::X, DVec3::Y], &[1.0, f64::NAN]).is_err()
        );
        assert!(RationalBezierCurve::from_homogeneous(vec![]).is_err());
    }
}
