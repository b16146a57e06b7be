//! Accuracy of an approximate rotation-minimizing frame against a reference RMF on the
//! curve it approximates, as Bartoň, Jüttler & Wang measure it, eqs. (23)–(25): every
//! point of the approximating curve is compared with the nearest point of the reference
//! curve, u*(u) = argmin_v |x_approx(u) − x(v)| (24), and
//!
//!   δ(u) = |r_approx(u) − r(u*(u))|   (23),   A = ∫ δ(u) du,   E = δ(u_end)   (25).
//!
//! Both frames must start from the same vector (the approximation interpolates the start
//! point and tangent, so the same initial normal gives the same start vector).

use super::FrameField;
use crate::curve::ParametricCurve;
use crate::error::Result;
use crate::math::{bisect_root, minimize_bracketed, GaussLegendre};
use glam::DVec3;

/// Average and end-point errors of (25).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameErrors {
    /// A = ∫ δ(u) du over the approximation's domain, divided by the domain length (the
    /// paper's domain is [0, 1]).
    pub average: f64,
    /// E = δ at the end of the domain.
    pub end: f64,
    /// max δ over the quadrature nodes and the end point.
    pub max: f64,
}

/// The reference: a curve and its RMF vector r(v) (the vector compared with f₂).
pub trait ReferenceRmf {
    /// The curve the reference RMF lives on.
    fn curve(&self) -> &dyn ParametricCurve;
    /// The reference RMF vector r(v) at curve parameter v (the vector compared with f₂).
    fn rmf(&self, v: f64) -> Result<DVec3>;
}

/// The parameter of the point of `curve` nearest to `p`, searched in `[v_lo, v_hi]`
/// (clamped to the domain) — a local projection: the caller brackets it. Brent's method
/// finds the minimum of the distance only to about √ε (it is flat there), so the result is
/// refined as the root of (x(v) − p)·x'(v), to round-off.
pub fn nearest_parameter(curve: &dyn ParametricCurve, p: DVec3, v_lo: f64, v_hi: f64) -> f64 {
    let (lo, hi) = curve.domain();
    let (a, b) = (v_lo.max(lo), v_hi.min(hi));
    let distance = |v: f64| {
        curve
            .point_derivative(v)
            .map_or(f64::NAN, |(x, _)| (x - p).length_squared())
    };
    let rough = minimize_bracketed(distance, a, b, 1e-15 * (hi - lo).max(1.0)).x;
    let slope = |v: f64| {
        curve
            .point_derivative(v)
            .map_or(f64::NAN, |(x, d)| (x - p).dot(d))
    };
    let reach = 1e-6 * (b - a);
    bisect_root(
        slope,
        (rough - reach).max(a),
        (rough + reach).min(b),
        1e-16 * (hi - lo),
    )
    .unwrap_or(rough)
}

/// δ at one parameter: nearest reference point searched within `window` of u (the two
/// curves' parameters correspond up to O(h) when the approximation samples the reference
/// at its own parameters).
fn delta(approx: &FrameField, reference: &dyn ReferenceRmf, u: f64, window: f64) -> Result<f64> {
    let x = approx.curve().eval(u);
    let v = nearest_parameter(reference.curve(), x, u - window, u + window);
    Ok((approx.frame(u)?.f2 - reference.rmf(v)?).length())
}

/// A and E of (25), integrating with an 8-point Gauss–Legendre rule on every segment of the
/// approximation; `window` bounds |u* − u| in the nearest-point search.
pub fn frame_errors(
    approx: &FrameField,
    reference: &dyn ReferenceRmf,
    window: f64,
) -> Result<FrameErrors> {
    let rule = GaussLegendre::new(8);
    let breaks = approx.curve().breaks();
    let (lo, hi) = approx.domain();
    let (mut integral, mut max) = (0.0, 0.0f64);
    for w in breaks.windows(2) {
        let h = w[1] - w[0];
        for (&node, &weight) in rule.nodes().iter().zip(rule.weights()) {
            let d = delta(approx, reference, w[0] + h * node, window)?;
            integral += weight * h * d;
            max = max.max(d);
        }
    }
    let end = delta(approx, reference, hi, window)?;
    Ok(FrameErrors {
        average: integral / (hi - lo),
        end,
        max: max.max(end),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::{NurbsCurve, PiecewiseCurve};
    use crate::curve::uniform_parameters;
    use crate::frames::double_reflection::DoubleReflectionRmf;
    use crate::frames::FrameKind;
    use crate::testing::Helix;
    use std::sync::Arc;

    struct ExactHelix(Helix);

    impl ReferenceRmf for ExactHelix {
        fn curve(&self) -> &dyn ParametricCurve {
            &self.0
        }
        fn rmf(&self, v: f64) -> Result<DVec3> {
            Ok(self.0.exact_rmf(v).f2)
        }
    }

    /// A cubic B-spline through helix points, with double-reflection frames along it: the
    /// measured errors must shrink as the spline and the frames get finer.
    fn spline_errors(pieces: usize) -> FrameErrors {
        let helix = ExactHelix(Helix {
            radius: 1.0,
            pitch: 0.3,
        });
        let (lo, hi) = helix.0.domain();
        // Interpolating poles are not needed: a fine B-spline through curve points is close.
        let params = uniform_parameters((lo, hi), pieces + 3);
        let poles = params
            .iter()
            .map(|&t| helix.0.point_derivative(t).unwrap().0)
            .collect::<Vec<_>>();
        let mut knots = vec![lo; 4];
        knots.extend(
            uniform_parameters((lo, hi), pieces + 1)[1..pieces]
                .iter()
                .copied(),
        );
        knots.extend([hi; 4]);
        let curve = NurbsCurve::new(3, poles, None, knots)
            .unwrap()
            .to_piecewise()
            .unwrap();
        let curve: Arc<PiecewiseCurve> = Arc::new(curve);
        let start = helix.0.exact_rmf(lo).f2;
        let samples = uniform_parameters((lo, hi), 50 * pieces);
        let rmf = DoubleReflectionRmf::along(curve.as_ref(), samples, start).unwrap();
        let field = FrameField::new(curve, FrameKind::DoubleReflection(rmf)).unwrap();
        frame_errors(&field, &helix, (hi - lo) / pieces as f64 * 2.0).unwrap()
    }

    #[test]
    fn errors_are_measured_at_nearest_points_and_shrink_with_refinement() {
        let (coarse, fine) = (spline_errors(16), spline_errors(64));
        assert!(coarse.average > 0.0 && coarse.end > 0.0);
        assert!(fine.average < coarse.average / 4.0, "{coarse:?} → {fine:?}");
        assert!(fine.max >= fine.average && fine.max >= fine.end);
    }

    #[test]
    fn nearest_parameter_projects_onto_the_curve() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.3,
        };
        // Offset along the principal normal (−cos t, −sin t, 0): the foot stays at t = 2.
        let p = helix.point_derivative(2.0).unwrap().0
            + 0.01 * DVec3::new(-(2f64.cos()), -(2f64.sin()), 0.0);
        let v = nearest_parameter(&helix, p, 1.5, 2.5);
        assert!((v - 2.0).abs() < 1e-14, "{v}");
    }
}
