//! The profile (cross-section) c(u) of a profile surface (1): a planar rational curve in the
//! normal plane of the spine, x ↦ f₂ and y ↦ f₃ (z ignored), written per Bézier segment as
//! c = (X, Y)/h, with the polynomials its analysis needs: h²c' (tangent, Proposition 4) and
//! h³(x'y'' − x''y') (curvature (11), zero at inflections).

use crate::bezier::bernstein::{self, elevate_to, product, to_power};
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::math::{power_of_two_inverse, quadratic_roots, real_roots_in};
use glam::DVec2;

/// One profile segment c = (X, Y)/h on [0, 1]; polynomial segments keep h = 1 (degree 0),
/// which keeps the derived polynomials at their true degrees.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ProfileSegment {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub h: Vec<f64>,
}

/// Point and first two derivatives of the profile at one parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ProfileJet {
    pub point: DVec2,
    pub d1: DVec2,
    pub d2: DVec2,
}

impl ProfileSegment {
    pub(crate) fn of(segment: &RationalBezierCurve) -> Self {
        if segment.is_polynomial() {
            let poles: Vec<_> = segment.poles().collect();
            return Self {
                x: poles.iter().map(|p| p.x).collect(),
                y: poles.iter().map(|p| p.y).collect(),
                h: vec![1.0],
            };
        }
        let hom = segment.homogeneous();
        Self {
            x: hom.iter().map(|p| p.x).collect(),
            y: hom.iter().map(|p| p.y).collect(),
            h: hom.iter().map(|p| p.w).collect(),
        }
    }

    /// c, c', c'' at the local parameter u.
    pub(crate) fn jet(&self, u: f64) -> ProfileJet {
        let (x, y, h) = (
            bernstein::evaluate_jet(&self.x, u),
            bernstein::evaluate_jet(&self.y, u),
            bernstein::evaluate_jet(&self.h, u),
        );
        let point = DVec2::new(x.value, y.value) / h.value;
        let d1 = (DVec2::new(x.d1, y.d1) - h.d1 * point) / h.value;
        let d2 = (DVec2::new(x.d2, y.d2) - 2.0 * h.d1 * d1 - h.d2 * point) / h.value;
        ProfileJet { point, d1, d2 }
    }

    /// c at the local parameter u.
    pub(crate) fn point(&self, u: f64) -> DVec2 {
        let h = bernstein::evaluate(&self.h, u);
        DVec2::new(
            bernstein::evaluate(&self.x, u),
            bernstein::evaluate(&self.y, u),
        ) / h
    }

    /// (A, B) = h²c' = (X'h − Xh', Y'h − Yh').
    pub(crate) fn scaled_tangent(&self) -> (Vec<f64>, Vec<f64>) {
        let dh = bernstein::derivative(&self.h);
        let part = |p: &[f64]| {
            difference(
                &product(&bernstein::derivative(p), &self.h, mul),
                &product(p, &dh, mul),
            )
        };
        (part(&self.x), part(&self.y))
    }

    /// max ‖c‖ on the segment: at its ends or where c·ċ = 0, i.e. X·A + Y·B = 0 with
    /// (A, B) = h²ċ.
    pub(crate) fn max_radius(&self) -> f64 {
        let (a, b) = self.scaled_tangent();
        let radial = sum(&product(&self.x, &a, mul), &product(&self.y, &b, mul));
        critical_points(&radial)
            .into_iter()
            .map(|s| self.point(s).length())
            .fold(0.0, f64::max)
    }

    /// The segment scaled by a power of two that brings its largest coordinate near 1
    /// (exact): polynomials of degree two in the coordinates, as the curvature numerator,
    /// under- or overflow at extreme scales.
    pub(crate) fn normalized(&self) -> Self {
        let size = self
            .x
            .iter()
            .chain(&self.y)
            .fold(0.0f64, |m, c| m.max(c.abs()));
        if size == 0.0 || !size.is_finite() {
            return self.clone();
        }
        let factor = power_of_two_inverse(size);
        Self {
            x: self.x.iter().map(|c| c * factor).collect(),
            y: self.y.iter().map(|c| c * factor).collect(),
            h: self.h.clone(),
        }
    }

    /// h³(x'y'' − x''y') = det[[h, X, Y], [h', X', Y'], [h'', X'', Y'']]: the numerator of the
    /// profile curvature (11).
    pub(crate) fn curvature_numerator(&self) -> Vec<f64> {
        let d = |p: &[f64]| bernstein::derivative(p);
        let (h1, x1, y1) = (d(&self.h), d(&self.x), d(&self.y));
        let (h2, x2, y2) = (d(&h1), d(&x1), d(&y1));
        let minor = |a1: &[f64], b2: &[f64], a2: &[f64], b1: &[f64]| {
            difference(&product(a1, b2, mul), &product(a2, b1, mul))
        };
        let terms = [
            product(&self.h, &minor(&x1, &y2, &x2, &y1), mul),
            product(&self.x, &minor(&h1, &y2, &h2, &y1), mul)
                .into_iter()
                .map(|c| -c)
                .collect(),
            product(&self.y, &minor(&h1, &x2, &h2, &x1), mul),
        ];
        terms.iter().fold(vec![0.0], |acc, t| sum(&acc, t))
    }
}

fn mul(a: f64, b: f64) -> f64 {
    a * b
}

/// a + b in the higher of their degrees.
pub(crate) fn sum(a: &[f64], b: &[f64]) -> Vec<f64> {
    let n = a.len().max(b.len()) - 1;
    elevate_to(a, n)
        .iter()
        .zip(elevate_to(b, n))
        .map(|(x, y)| x + y)
        .collect()
}

/// a − b in the higher of their degrees.
pub(crate) fn difference(a: &[f64], b: &[f64]) -> Vec<f64> {
    sum(a, &b.iter().map(|c| -c).collect::<Vec<_>>())
}

/// The segments of a profile curve.
pub(crate) fn profile_segments(profile: &PiecewiseCurve) -> Vec<ProfileSegment> {
    profile.segments().iter().map(ProfileSegment::of).collect()
}

/// The roots in (0, 1) of a Bernstein polynomial, with both ends (the candidates for an
/// extremum of a function whose derivative's numerator it is).
pub(crate) fn critical_points(p: &[f64]) -> Vec<f64> {
    let mut points = vec![0.0, 1.0];
    if p.iter().any(|&c| c != 0.0) {
        points.extend(interior_roots(p));
    }
    points
}

/// Whether a Bernstein polynomial vanishes identically, relative to `scale`.
pub(crate) fn vanishes(p: &[f64], scale: f64) -> bool {
    p.iter().all(|c| c.abs() <= 1e-12 * scale)
}

/// The roots in the open interval (0, 1) of a Bernstein polynomial that does not vanish
/// identically.
pub(crate) fn interior_roots(p: &[f64]) -> Vec<f64> {
    // Bernstein coefficients of one strict sign bound a polynomial of that sign on [0, 1]
    // (convex hull): no root, and no need to look for one.
    if p.iter().all(|&c| c > 0.0) || p.iter().all(|&c| c < 0.0) {
        return Vec::new();
    }
    let mut power = to_power(p);
    // Leading coefficients at the rounding level of the others are dropped (a rational
    // quadratic's scaled tangent, of degree 2, comes written with degree 3): on [0, 1] they
    // move a root by as little, and a quadratic has its roots in closed form.
    let size = power.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    while power.len() > 1 && power[power.len() - 1].abs() <= 1e-14 * size {
        power.pop();
    }
    let roots = match power[..] {
        // Scaled by a power of two near 1/size (exact): b² − 4ac under- or overflows at
        // extreme scales.
        [c, b, a] => {
            let f = power_of_two_inverse(size);
            quadratic_roots(a * f, b * f, c * f)
        }
        _ => real_roots_in(&power, 0.0, 1.0),
    };
    roots.into_iter().filter(|&u| u > 0.0 && u < 1.0).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn circle_profile_has_constant_curvature_and_the_jet_of_a_circle() {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let arc = RationalBezierCurve::from_weighted(
            &[DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
            &[1.0, s, 1.0],
        )
        .unwrap();
        let p = ProfileSegment::of(&arc);
        let (a, b) = p.scaled_tangent();
        let k = p.curvature_numerator();
        for u in [0.0, 0.3, 0.8] {
            let jet = p.jet(u);
            assert!((jet.point.length() - 1.0).abs() < 1e-15);
            let h = bernstein::evaluate(&p.h, u);
            let tangent = DVec2::new(bernstein::evaluate(&a, u), bernstein::evaluate(&b, u));
            assert!((tangent / (h * h) - jet.d1).length() < 1e-14);
            let curvature = bernstein::evaluate(&k, u) / h.powi(3) / jet.d1.length().powi(3);
            assert!((curvature - 1.0).abs() < 1e-13, "κ = {curvature}");
        }
    }

    #[test]
    fn inflections_of_a_polynomial_profile() {
        // y = x³ − x on [−1, 1], written as a cubic Bézier: one inflection at x = 0 (u = 1/2).
        let cubic = RationalBezierCurve::polynomial(&[
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(-1.0 / 3.0, 4.0 / 3.0, 0.0),
            DVec3::new(1.0 / 3.0, -4.0 / 3.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
        ])
        .unwrap();
        let k = ProfileSegment::of(&cubic).curvature_numerator();
        let roots = interior_roots(&k);
        assert_eq!(roots.len(), 1);
        assert!((roots[0] - 0.5).abs() < 1e-12);
        let line = RationalBezierCurve::polynomial(&[DVec3::ZERO, DVec3::X]).unwrap();
        assert!(vanishes(
            &ProfileSegment::of(&line).curvature_numerator(),
            1.0
        ));
    }
}
