//! Curves as the algorithms see them: a parameter domain and, at each parameter, a point
//! and a derivative. Bézier/NURBS curves implement it, and so does a C callback (`ffi`),
//! so every approximation or sampling algorithm works on either.

use crate::bezier::PiecewiseCurve;
use crate::error::{invalid, Result};
use glam::DVec3;

/// A regular parametric space curve.
pub trait ParametricCurve {
    /// The parameter interval `(t_min, t_max)`, `t_min < t_max`.
    fn domain(&self) -> (f64, f64);

    /// The point and first derivative at `t` (inside the domain).
    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)>;

    /// The point and the unit tangent at `t`; fails where the curve is singular.
    fn point_unit_tangent(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let (p, d) = self.point_derivative(t)?;
        let length = d.length();
        if !length.is_finite() || length <= 0.0 {
            return invalid!("the curve is singular (zero or non-finite derivative) at t = {t}");
        }
        Ok((p, d / length))
    }
}

impl ParametricCurve for PiecewiseCurve {
    fn domain(&self) -> (f64, f64) {
        PiecewiseCurve::domain(self)
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let jet = self.eval_jet(t);
        Ok((jet.point, jet.d1))
    }
}

/// `count ≥ 2` parameters spaced uniformly over `domain`, both ends included exactly.
pub fn uniform_parameters((lo, hi): (f64, f64), count: usize) -> Vec<f64> {
    let last = count.max(2) - 1;
    (0..=last)
        .map(|i| {
            if i == last {
                hi
            } else {
                lo + (hi - lo) * i as f64 / last as f64
            }
        })
        .collect()
}
