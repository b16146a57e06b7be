//! Test curves and surfaces shared by the unit tests of the cone spline modules.

use super::developable::{Developable, TangentSurface};
use super::pair::Rule;
use super::spline::ConeSpline;
use crate::bezier::{bernstein, PiecewiseCurve, RationalBezierCurve};
use crate::curve::ParametricCurve;
use crate::error::Result;
use glam::DVec3;

/// The twisted cubic (t, t², t³) on [t0, t1] as one polynomial Bézier segment.
pub(crate) fn twisted_cubic(t0: f64, t1: f64) -> PiecewiseCurve {
    let power = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    let full = bernstein::from_power(&power);
    let seg = RationalBezierCurve::polynomial(&full)
        .unwrap()
        .restricted(t0, t1);
    PiecewiseCurve::new(vec![seg], vec![t0, t1]).unwrap()
}

/// The helix (r cos t, r sin t, c t) on [t0, t1] (a curve of constant slope).
pub(crate) struct Helix {
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

    /// The exact jet (a caller who knows the higher derivatives gives them).
    fn jet(&self, t: f64) -> Result<[DVec3; 4]> {
        let (s, c) = t.sin_cos();
        let r = self.radius;
        let (x, d1) = self.point_derivative(t)?;
        Ok([
            x,
            d1,
            DVec3::new(-r * c, -r * s, 0.0),
            DVec3::new(r * s, -r * c, 0.0),
        ])
    }
}

/// A curve seen only through its points and first derivatives, as a C callback gives it:
/// the jet is differenced.
pub(crate) struct OnlyTangents<C>(pub C);

impl<C: ParametricCurve> ParametricCurve for OnlyTangents<C> {
    fn domain(&self) -> (f64, f64) {
        self.0.domain()
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        self.0.point_derivative(t)
    }
}

/// The polynomial curve (t, t², z(t)) on [t0, t1] whose z''' has the given roots (with
/// multiplicity): its torsion numerator det(x', x'', x''') = 2 z''' has exactly these zeros.
pub(crate) fn torsion_zeros_curve(roots: &[f64], t0: f64, t1: f64) -> PiecewiseCurve {
    let mut z3 = vec![1.0];
    for &r in roots {
        let mut next = vec![0.0; z3.len() + 1];
        for (i, &c) in z3.iter().enumerate() {
            next[i + 1] += c;
            next[i] -= r * c;
        }
        z3 = next;
    }
    // z = ∭ z''': tⁱ ↦ tⁱ⁺³ i! / (i + 3)!.
    let mut power = vec![DVec3::ZERO; z3.len() + 3];
    power[1].x = 1.0;
    power[2].y = 1.0;
    for (i, &c) in z3.iter().enumerate() {
        let f = (i + 1) as f64 * (i + 2) as f64 * (i + 3) as f64;
        power[i + 3].z = c / f;
    }
    let full = bernstein::from_power(&power);
    let seg = RationalBezierCurve::polynomial(&full)
        .unwrap()
        .restricted(t0, t1);
    PiecewiseCurve::new(vec![seg], vec![t0, t1]).unwrap()
}

/// The tangent surface of `curve` over distances [v0, v1] from the curve.
pub(crate) fn tangent_surface(curve: &dyn ParametricCurve, v0: f64, v1: f64) -> TangentSurface<'_> {
    TangentSurface::new(curve, v0, v1).unwrap()
}

/// Cone pairs through the elements at `ts` of the tangent surface of the twisted cubic,
/// region v ∈ [2, 3] (far enough from the curve for the parallel-circle strips).
pub(crate) fn cubic_hermite(ts: &[f64]) -> ConeSpline {
    let curve = twisted_cubic(0.2, 1.2);
    let surface = tangent_surface(&curve, 2.0, 3.0);
    let elements: Vec<_> = ts.iter().map(|&t| surface.element(t).unwrap()).collect();
    ConeSpline::hermite(&elements, Rule::MinimalVertexDistance, None)
        .unwrap()
        .0
}

/// Control planes (u₁, u₂, u₃, u₀) of a quadratic dual Bézier curve of planes through the
/// origin: a (quadratic) cone with vertex at the origin around the z axis.
pub(crate) fn dual_cone_planes() -> Vec<glam::DVec4> {
    vec![
        glam::DVec4::new(1.0, 0.0, -0.5, 0.0),
        glam::DVec4::new(1.0, 1.0, -0.5, 0.0),
        glam::DVec4::new(0.0, 1.0, -0.5, 0.0),
    ]
}

/// The curve (t, t², t⁴) on [−1, 1], whose torsion vanishes at t = 0 (an inflection
/// generator of its tangent surface).
pub(crate) fn zero_torsion_curve() -> PiecewiseCurve {
    let power = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ZERO, DVec3::Z];
    let full = bernstein::from_power(&power);
    let seg = RationalBezierCurve::polynomial(&full)
        .unwrap()
        .restricted(-1.0, 1.0);
    PiecewiseCurve::new(vec![seg], vec![-1.0, 1.0]).unwrap()
}
