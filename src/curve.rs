//! Curves as the algorithms see them: a parameter domain and, at each parameter, a point
//! and a derivative. Bézier/NURBS curves implement it, and so does a C callback (`ffi`),
//! so every approximation or sampling algorithm works on either.

use crate::bezier::PiecewiseCurve;
use crate::error::{invalid, Result};
use crate::math::{lerp, robust_normalize};
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
        // Scaled before squaring: a derivative of 3e-162 has a subnormal square, and d/|d|
        // was 0.994 long (a property-test finding).
        match robust_normalize(d) {
            Some(tangent) => Ok((p, tangent)),
            None => invalid!("the curve is singular (zero or non-finite derivative) at t = {t}"),
        }
    }
}

impl<C: ParametricCurve + ?Sized> ParametricCurve for &C {
    fn domain(&self) -> (f64, f64) {
        (**self).domain()
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        (**self).point_derivative(t)
    }
}

impl ParametricCurve for PiecewiseCurve {
    fn domain(&self) -> (f64, f64) {
        PiecewiseCurve::domain(self)
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        Ok(self.eval_d1(t))
    }
}

/// The most samples (or segments) a caller may ask a sampling algorithm for: 2²⁴, far
/// beyond any CAD use and far below what would exhaust memory (each sample costs about a
/// hundred bytes). Larger counts are refused, never attempted.
pub const MAX_SAMPLES: usize = 1 << 24;

/// Checks a caller's count of samples or segments named `name`: at least `min`, at most
/// [`MAX_SAMPLES`].
pub fn check_sample_count(count: usize, min: usize, name: &str) -> Result<()> {
    if count < min || count > MAX_SAMPLES {
        return invalid!("{name} = {count} must be between {min} and {MAX_SAMPLES}");
    }
    Ok(())
}

/// `count ≥ 2` parameters spaced uniformly over `domain`, both ends included exactly.
pub fn uniform_parameters((lo, hi): (f64, f64), count: usize) -> Vec<f64> {
    let last = count.max(2) - 1;
    (0..=last)
        .map(|i| {
            if i == last {
                hi
            } else {
                lerp(lo, hi, i as f64 / last as f64)
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Property-test finding: a segment of length 3e-162, whose derivative has a subnormal
    /// square, gave a "unit" tangent of length 0.994.
    #[test]
    fn tiny_derivatives_give_unit_tangents() {
        let tiny = DVec3::new(0.0, 3.125e-162, 0.0);
        let segment = crate::bezier::RationalBezierCurve::polynomial(&[tiny, DVec3::ZERO]).unwrap();
        let line = PiecewiseCurve::with_unit_intervals(vec![segment]).unwrap();
        let (_, tangent) = line.point_unit_tangent(0.5).unwrap();
        assert!((tangent.length() - 1.0).abs() < 1e-15, "{tangent}");
        let subnormal =
            crate::bezier::RationalBezierCurve::polynomial(&[DVec3::Y * 1e-310, DVec3::ZERO]);
        let line = PiecewiseCurve::with_unit_intervals(vec![subnormal.unwrap()]).unwrap();
        assert!(line.point_unit_tangent(0.5).is_err());
    }

    /// Fuzz finding: a sample count of 2³¹ or more was attempted (an allocation of 16 GiB
    /// or a capacity-overflow panic) instead of refused.
    #[test]
    fn sample_counts_are_bounded() {
        assert!(check_sample_count(2, 2, "n").is_ok());
        assert!(check_sample_count(MAX_SAMPLES, 1, "n").is_ok());
        for bad in [0, 1, MAX_SAMPLES + 1, 1 << 31, usize::MAX] {
            let err = check_sample_count(bad, 2, "sample_count").unwrap_err();
            assert!(
                err.message().starts_with(&format!("sample_count = {bad} ")),
                "{err}"
            );
        }
    }
}
