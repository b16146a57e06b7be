//! Curves as the algorithms see them: a parameter domain and, at each parameter, a point
//! and a derivative. Bézier/NURBS curves implement it, and so does a C callback (`ffi`),
//! so every approximation or sampling algorithm works on either.
//!
//! Algorithms that need higher derivatives (the Darboux vector and torsion of the line of
//! regression of a tangent surface) ask for the jet x, x', x'', x''' ([`ParametricCurve::jet`]):
//! exact for Bézier/NURBS curves, and for a curve that only gives x' by differencing x' with
//! a step controlled by the turning of the tangent ([`differenced_jet`], whose accuracy is
//! stated there).

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

    /// x, x', x'', x''' at `t`. The default differences x' (`differenced_jet`); curves
    /// that know their higher derivatives override it.
    fn jet(&self, t: f64) -> Result<[DVec3; 4]> {
        differenced_jet(self, t)
    }

    /// The curve as Bézier segments, when it is one: algorithms then work on its exact
    /// polynomials (e.g. the roots of the torsion numerator).
    fn as_piecewise(&self) -> Option<&PiecewiseCurve> {
        None
    }

    /// The point and the unit tangent at `t`; fails where the curve is singular.
    fn point_unit_tangent(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let (p, d) = self.point_derivative(t)?;
        // Scaled before squaring: a derivative of 3e-162 has a subnormal square, and d/|d|
        // from it is 0.994 long.
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

    fn jet(&self, t: f64) -> Result<[DVec3; 4]> {
        (**self).jet(t)
    }

    fn as_piecewise(&self) -> Option<&PiecewiseCurve> {
        (**self).as_piecewise()
    }
}

impl ParametricCurve for PiecewiseCurve {
    fn domain(&self) -> (f64, f64) {
        PiecewiseCurve::domain(self)
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        Ok(self.eval_d1(t))
    }

    fn jet(&self, t: f64) -> Result<[DVec3; 4]> {
        Ok(self.eval_jet3(t))
    }

    fn as_piecewise(&self) -> Option<&PiecewiseCurve> {
        Some(self)
    }
}

impl ParametricCurve for crate::ph_cubic::spline::PhSpline {
    fn domain(&self) -> (f64, f64) {
        self.curve().domain()
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        self.curve().point_derivative(t)
    }

    fn jet(&self, t: f64) -> Result<[DVec3; 4]> {
        self.curve().jet(t)
    }

    fn as_piecewise(&self) -> Option<&PiecewiseCurve> {
        Some(self.curve())
    }
}

/// x, x', x'', x''' at t for a curve that gives only x': x'' and x''' are the first and
/// second derivatives of the quartic through the exact x' at five equidistant parameters
/// around t, kept inside the domain. The spacing h is 1e-3 of the domain, divided by 4
/// until the tangent turns by at most 0.05 rad across the five nodes: a step relative to
/// the domain alone is a whole turn of a 1,000-turn helix (whose x' is then the same at
/// all five). The turning is measured from the first node to the last and to an
/// incommensurable one (a golden-section fraction of the way), so that no periodic curve
/// hides it.
///
/// Accuracy: the truncation error is O(h⁴) at the centre of the stencil (O(h³) for x''' at
/// the ends of the domain, where the stencil is one-sided), and rounding contributes
/// ε|x'|/h to x'' and ε|x'|/h² to x'''. With the turning bound this is about 1e-9 relative
/// for x'' and 1e-7 for x''' on a helix (measured in the tests of this module).
pub(crate) fn differenced_jet<C: ParametricCurve + ?Sized>(
    curve: &C,
    t: f64,
) -> Result<[DVec3; 4]> {
    const GOLDEN: f64 = 0.381_966_011_250_105_1;
    const NODES: [f64; 5] = [-2.0, -1.0, 0.0, 1.0, 2.0];
    let (lo, hi) = curve.domain();
    let mut h = 1e-3 * (hi - lo);
    let (x, d1) = curve.point_derivative(t)?;
    let turning = |h: f64| -> Result<f64> {
        let first = t.clamp(lo + 2.0 * h, hi - 2.0 * h) - 2.0 * h;
        // Unit tangents: the angle of derivatives of size 1e200 would overflow.
        let tangent = |s: f64| -> Result<DVec3> {
            let d = curve.point_derivative(first + s * 4.0 * h)?.1;
            Ok(robust_normalize(d).unwrap_or(DVec3::ZERO))
        };
        let (a, m, b) = (tangent(0.0)?, tangent(GOLDEN)?, tangent(1.0)?);
        Ok(crate::math::angle_between(a, m).max(crate::math::angle_between(a, b)))
    };
    while h > 1e-9 * (hi - lo) && turning(h)? > 0.05 {
        h *= 0.25;
    }
    let centre = t.clamp(lo + 2.0 * h, hi - 2.0 * h);
    let at = (t - centre) / h;
    let (mut d2, mut d3) = (DVec3::ZERO, DVec3::ZERO);
    for (j, &xj) in NODES.iter().enumerate() {
        let [w1, w2] = lagrange_derivative_weights(&NODES, j, at);
        let value = curve.point_derivative(centre + xj * h)?.1;
        d2 += value * w1;
        d3 += value * w2;
    }
    Ok([x, d1, d2 / h, d3 / (h * h)])
}

/// First and second derivatives at `at` of the Lagrange basis polynomial of node j.
fn lagrange_derivative_weights(nodes: &[f64], j: usize, at: f64) -> [f64; 2] {
    // Power coefficients of Π_{k≠j} (u − x_k) / (x_j − x_k).
    let mut basis = vec![1.0];
    for (_, &xk) in nodes.iter().enumerate().filter(|&(k, _)| k != j) {
        let scale = 1.0 / (nodes[j] - xk);
        let mut next = vec![0.0; basis.len() + 1];
        for (i, &c) in basis.iter().enumerate() {
            next[i + 1] += c * scale;
            next[i] -= c * xk * scale;
        }
        basis = next;
    }
    let derivative = |c: &[f64]| -> Vec<f64> {
        c.iter()
            .enumerate()
            .skip(1)
            .map(|(i, &a)| a * i as f64)
            .collect()
    };
    let horner = |c: &[f64]| c.iter().rev().fold(0.0, |acc, &a| acc * at + a);
    let first = derivative(&basis);
    [horner(&first), horner(&derivative(&first))]
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

    /// The helix (cos t, sin t, 0.5 t) known only by x and x'.
    struct Helix(f64, f64);

    impl ParametricCurve for Helix {
        fn domain(&self) -> (f64, f64) {
            (self.0, self.1)
        }

        fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
            let (s, c) = t.sin_cos();
            Ok((DVec3::new(c, s, 0.5 * t), DVec3::new(-s, c, 0.5)))
        }
    }

    /// The differenced x'' and x''' of a helix of three turns against the exact ones, in
    /// the middle and at the ends of the domain (one-sided stencils), and the exact jet of
    /// a cubic NURBS.
    #[test]
    fn jets_exact_and_differenced() {
        let helix = Helix(0.0, 6.0 * std::f64::consts::PI);
        let (mut e2, mut e3) = (0.0f64, 0.0f64);
        for t in uniform_parameters(helix.domain(), 41) {
            let [_, _, d2, d3] = helix.jet(t).unwrap();
            let (s, c) = t.sin_cos();
            e2 = e2.max((d2 - DVec3::new(-c, -s, 0.0)).length());
            e3 = e3.max((d3 - DVec3::new(s, -c, 0.0)).length());
        }
        println!("differenced jet of a helix: |Δx''| ≤ {e2:.2e}, |Δx'''| ≤ {e3:.2e}");
        assert!(e2 < 1e-8 && e3 < 1e-6, "{e2} {e3}");
        let power = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        let poles = crate::bezier::bernstein::from_power(&power);
        let seg = crate::bezier::RationalBezierCurve::polynomial(&poles).unwrap();
        let cubic = PiecewiseCurve::new(vec![seg.restricted(-1.0, 2.0)], vec![-1.0, 2.0]).unwrap();
        let t = 0.7;
        let [x, d1, d2, d3] = cubic.jet(t).unwrap();
        let exact = [
            DVec3::new(t, t * t, t * t * t),
            DVec3::new(1.0, 2.0 * t, 3.0 * t * t),
            DVec3::new(0.0, 2.0, 6.0 * t),
            DVec3::new(0.0, 0.0, 6.0),
        ];
        for (a, b) in [x, d1, d2, d3].iter().zip(exact) {
            assert!((*a - b).length() < 1e-13, "{a} vs {b}");
        }
    }

    /// A segment of length 3e-162, whose derivative has a subnormal square, has a unit
    /// tangent (d/|d| unscaled is 0.994 long); a subnormal derivative is singular.
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

    /// Sample counts are bounded by [`MAX_SAMPLES`]: 2³¹ or more would be an allocation of
    /// 16 GiB or a capacity-overflow panic.
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
