//! The double-reflection rotation-minimizing frame of W. Wang, B. Jüttler, D. Zheng and
//! Y. Liu, "Computation of rotation minimizing frames", ACM TOG 27(1), 2008, Algorithm 1.
//!
//! From a frame (tᵢ, rᵢ) at xᵢ, the reflection R₁ in the plane bisecting xᵢ xᵢ₊₁ followed
//! by the reflection R₂ that takes R₁tᵢ to tᵢ₊₁ gives rᵢ₊₁; the method is fourth-order
//! accurate in the sample spacing and is the reference every rational RMF here is
//! measured against, and the baseline of the benchmarks.

use super::Frame;
use crate::curve::ParametricCurve;
use crate::error::{invalid, Result};
use crate::math::normal_plane_unit;
use glam::DVec3;

/// |t₁ − R₁t₀|² below which the second reflection is replaced by a projection: v₂ is then
/// mostly round-off (after a cusp, R₁ reverses the tangent exactly onto t₁), and reflecting
/// in it would turn f₂ out of the normal plane by ε/|v₂| (ε the round-off of v₂), while the
/// projection onto the normal plane of t₁ differs from the reflection by O(|v₂|²).
const NEARLY_EQUAL_TANGENTS: f64 = 1e-16;

/// One double-reflection step from the frame `from` at `x0` to the point `x1` with unit
/// tangent `t1`. A zero chord skips the first reflection (it is then the identity on the
/// frame); nearly equal tangents replace the second one by a projection (see
/// [`NEARLY_EQUAL_TANGENTS`]).
#[inline]
pub(crate) fn reflect_step(x0: DVec3, from: &Frame, x1: DVec3, t1: DVec3) -> Frame {
    let v1 = x1 - x0;
    let c1 = v1.dot(v1);
    let (r_l, t_l) = if c1 > f64::MIN_POSITIVE {
        let k = 2.0 / c1;
        (
            from.f2 - (k * v1.dot(from.f2)) * v1,
            from.tangent - (k * v1.dot(from.tangent)) * v1,
        )
    } else {
        (from.f2, from.tangent)
    };
    let v2 = t1 - t_l;
    let c2 = v2.dot(v2);
    let r1 = if c2 > NEARLY_EQUAL_TANGENTS {
        r_l - (2.0 / c2 * v2.dot(r_l)) * v2
    } else {
        (r_l - r_l.dot(t1) * t1).normalize()
    };
    Frame::from_tangent_normal(t1, r1)
}

/// Frames sampled by double reflection at increasing parameters of a curve.
#[derive(Clone, Debug)]
pub struct DoubleReflectionRmf {
    params: Vec<f64>,
    points: Vec<DVec3>,
    frames: Vec<Frame>,
}

impl DoubleReflectionRmf {
    /// The RMF sampled at `params` (at least two, strictly increasing, inside the curve's
    /// domain), starting with f₂ = `initial_normal` projected onto the normal plane.
    pub fn along(
        curve: &dyn ParametricCurve,
        params: Vec<f64>,
        initial_normal: DVec3,
    ) -> Result<Self> {
        if params.len() < 2 {
            return invalid!(
                "params.len() = {} but double reflection needs at least 2 samples",
                params.len()
            );
        }
        if params.iter().any(|t| !t.is_finite()) || params.windows(2).any(|w| w[0] >= w[1]) {
            return invalid!("sample parameters must be finite and strictly increasing");
        }
        let mut points = Vec::with_capacity(params.len());
        let mut frames = Vec::with_capacity(params.len());
        for &t in &params {
            let (x, tangent) = curve.point_unit_tangent(t)?;
            let frame = match (frames.last(), points.last()) {
                (Some(prev), Some(&x_prev)) => reflect_step(x_prev, prev, x, tangent),
                _ => Frame::from_tangent_normal(
                    tangent,
                    normal_plane_unit(initial_normal, tangent, "initial_normal")?,
                ),
            };
            points.push(x);
            frames.push(frame);
        }
        Ok(Self {
            params,
            points,
            frames,
        })
    }

    /// The parameters of the samples, increasing.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// The frames at the samples.
    pub fn frames(&self) -> &[Frame] {
        &self.frames
    }

    /// The frame at parameter `t`, where the curve has `point` and unit `tangent`: one
    /// reflection step from the last sample at or before `t`.
    pub fn frame_at(&self, t: f64, point: DVec3, tangent: DVec3) -> Frame {
        let k = self.params.partition_point(|&p| p <= t).saturating_sub(1);
        reflect_step(self.points[k], &self.frames[k], point, tangent)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::uniform_parameters;
    use crate::testing::Helix;

    /// Across a cusp (a polyline going back on itself) the first reflection reverses the
    /// tangent onto t₁ up to round-off; reflecting in that round-off would leave f₂ 5e-6
    /// out of the normal plane, so the second reflection is replaced by a projection onto
    /// it and the frame stays orthonormal.
    #[test]
    fn a_reversed_tangent_keeps_the_frame_orthonormal() {
        for d in [
            DVec3::new(1.0, 2.875e-5, 2.875e-5),
            DVec3::new(0.3, -0.7, 0.2),
            DVec3::new(1.0, 1e-9, 0.0),
        ] {
            let t0 = d.normalize();
            let f2 = t0.any_orthonormal_vector();
            let from = Frame::from_tangent_normal(t0, f2);
            let x0 = DVec3::new(1.0000146875, 2.875e-5, 2.875e-5);
            let step = reflect_step(x0, &from, x0 + 9.2 * t0, -t0);
            assert!(step.f2.dot(step.tangent).abs() < 1e-15, "{d}: {step:?}");
            assert!((step.f2.length() - 1.0).abs() < 1e-15, "{d}: {step:?}");
        }
    }

    const HELIX: Helix = Helix {
        radius: 2.0,
        pitch: 0.5,
    };

    fn max_error(samples: usize) -> f64 {
        let params = uniform_parameters(HELIX.domain(), samples);
        let rmf =
            DoubleReflectionRmf::along(&HELIX, params.clone(), HELIX.exact_rmf(0.0).f2).unwrap();
        params
            .iter()
            .zip(rmf.frames())
            .map(|(&t, f)| (f.f2 - HELIX.exact_rmf(t).f2).length())
            .fold(0.0, f64::max)
    }

    #[test]
    fn converges_to_the_exact_rmf_of_a_helix_with_order_four() {
        let (e1, e2) = (max_error(100), max_error(200));
        assert!(e2 < 1e-6, "error {e2}");
        let order = (e1 / e2).log2();
        assert!(order > 3.8, "observed order {order}");
    }

    #[test]
    fn frames_between_samples_follow_the_exact_rmf() {
        let params = uniform_parameters(HELIX.domain(), 200);
        let rmf = DoubleReflectionRmf::along(&HELIX, params, HELIX.exact_rmf(0.0).f2).unwrap();
        let (x, t) = HELIX.point_unit_tangent(1.234).unwrap();
        let f = rmf.frame_at(1.234, x, t);
        assert!(f.f2.dot(t).abs() < 1e-14 && (f.f2.length() - 1.0).abs() < 1e-14);
        assert!((f.f2 - HELIX.exact_rmf(1.234).f2).length() < 1e-6);
    }

    #[test]
    fn rejects_too_few_samples_and_a_tangential_normal() {
        assert!(DoubleReflectionRmf::along(&HELIX, vec![0.0], DVec3::Z).is_err());
        let (_, t0) = HELIX.point_unit_tangent(0.0).unwrap();
        let e = DoubleReflectionRmf::along(&HELIX, vec![0.0, 1.0], t0).unwrap_err();
        assert!(e.message().contains("initial_normal"));
    }
}
