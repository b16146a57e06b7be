//! Test curves and surfaces shared by the unit tests of the cone spline modules.

use super::developable::{Developable, TangentSurface};
use super::pair::Rule;
use super::spline::ConeSpline;
use crate::bezier::{bernstein, PiecewiseCurve, RationalBezierCurve};
use crate::curve::ParametricCurve;
use crate::error::Result;
use glam::DVec3;

/// The twisted cubic (t, t², t³) on [t0, t1] as one polynomial Bézier segment.
pub fn twisted_cubic(t0: f64, t1: f64) -> PiecewiseCurve {
    let power = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    let full = bernstein::from_power(&power);
    let seg = RationalBezierCurve::polynomial(&full)
        .unwrap()
        .restricted(t0, t1);
    PiecewiseCurve::new(vec![seg], vec![t0, t1]).unwrap()
}

/// The helix (r cos t, r sin t, c t) on [t0, t1] (a curve of constant slope).
pub struct Helix {
    pub radius: f64,
    pub pitch: f64,
    pub domain: (f64, f64),
}

impl ParametricCurve for Helix {
    fn domain(&self) -> (f64, f64) {
        self.domain
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let (s, c) = t.sin_cos();
        Ok((
            DVec3::new(self.radius * c, self.radius * s, self.pitch * t),
            DVec3::new(-self.radius * s, self.radius * c, self.pitch),
        ))
    }
}

/// The tangent surface of `curve` over distances [v0, v1] from the curve.
pub fn tangent_surface(curve: &dyn ParametricCurve, v0: f64, v1: f64) -> TangentSurface<'_> {
    TangentSurface::new(curve, v0, v1).unwrap()
}

/// Cone pairs through the elements at `ts` of the tangent surface of the twisted cubic,
/// region v ∈ [2, 3] (far enough from the curve for the parallel-circle strips).
pub fn cubic_hermite(ts: &[f64]) -> ConeSpline {
    let curve = twisted_cubic(0.2, 1.2);
    let surface = tangent_surface(&curve, 2.0, 3.0);
    let elements: Vec<_> = ts.iter().map(|&t| surface.element(t).unwrap()).collect();
    ConeSpline::hermite(&elements, Rule::MinimalVertexDistance, None)
        .unwrap()
        .0
}

/// Control planes (u₁, u₂, u₃, u₀) of a quadratic dual Bézier curve of planes through the
/// origin: a (quadratic) cone with vertex at the origin around the z axis.
pub fn dual_cone_planes() -> Vec<glam::DVec4> {
    vec![
        glam::DVec4::new(1.0, 0.0, -0.5, 0.0),
        glam::DVec4::new(1.0, 1.0, -0.5, 0.0),
        glam::DVec4::new(0.0, 1.0, -0.5, 0.0),
    ]
}

/// The curve (t, t², t⁴) on [−1, 1], whose torsion vanishes at t = 0 (an inflection
/// generator of its tangent surface).
pub fn zero_torsion_curve() -> PiecewiseCurve {
    let power = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ZERO, DVec3::Z];
    let full = bernstein::from_power(&power);
    let seg = RationalBezierCurve::polynomial(&full)
        .unwrap()
        .restricted(-1.0, 1.0);
    PiecewiseCurve::new(vec![seg], vec![-1.0, 1.0]).unwrap()
}
