//! RRMF quintics and their rational RMF (9) as the library's curve and frame objects.
//!
//! Quintic k of a sequence lives on [k, k + 1]. Its RMF is f₂ = N₂/d, f₃ = N₃/d of degree 8
//! with d = (a² + b²)(|α|² + |β|²) > 0; d's Bernstein coefficients can be negative for a
//! strongly turning quintic, so each quintic's interval is split until they are all
//! positive (`bernstein::positive_subdivision`) — CAD systems need positive weights. The
//! pieces are then joined by constant rotations about the tangent, which keep an RMF
//! rotation-minimizing (`RationalFrames::chained`): the first so that f₂ starts at the
//! caller's normal, every further one so that frames agree at the joints.

use super::solutions::RrmfQuintic;
use crate::bezier::bernstein::{positive_subdivision, restrict};
use crate::bezier::PiecewiseCurve;
use crate::error::{Error, Result};
use crate::frames::rational::{RationalFrameSegment, RationalFrames};
use glam::DVec3;

/// Most halvings of a quintic's interval to make the RMF denominator's coefficients
/// positive; d is bounded away from zero on a regular quintic, so far fewer are needed.
const MAX_SUBDIVISION_DEPTH: usize = 30;

/// The quintics as one curve, quintic k on [k, k + 1].
pub fn quintic_curve(quintics: &[RrmfQuintic]) -> Result<PiecewiseCurve> {
    let segments = quintics
        .iter()
        .map(RrmfQuintic::bezier)
        .collect::<Result<Vec<_>>>()?;
    PiecewiseCurve::with_unit_intervals(segments)
}

/// The exact RMF (9) along the quintics (quintic k on [k, k + 1]), continuous across the
/// joints, with f₂ at the start the projection of `initial_normal` onto the normal plane.
pub fn quintic_rmf(quintics: &[RrmfQuintic], initial_normal: DVec3) -> Result<RationalFrames> {
    let mut segments = Vec::new();
    let mut breaks = vec![0.0];
    for (k, quintic) in quintics.iter().enumerate() {
        let rmf = quintic.rmf();
        let local = positive_subdivision(&[&rmf.denominator], MAX_SUBDIVISION_DEPTH)
            .ok_or_else(|| {
                Error::NoSolution(format!(
                    "the RMF denominator of quintic {k} (almost) vanishes: the curve is (nearly) singular"
                ))
            })?;
        for w in local.windows(2) {
            let piece = |v: &[DVec3]| restrict(v, w[0], w[1]);
            segments.push(RationalFrameSegment::new(
                piece(&rmf.f2),
                piece(&rmf.f3),
                restrict(&rmf.denominator, w[0], w[1]),
            )?);
            breaks.push(k as f64 + w[1]);
        }
    }
    RationalFrames::chained(segments, breaks, initial_normal)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::curve::{uniform_parameters, ParametricCurve};
    use crate::frames::double_reflection::DoubleReflectionRmf;
    use crate::frames::metrics::{orthonormality_error, rmf_defect};
    use crate::frames::{FrameField, FrameKind};
    use crate::math::Complex;
    use crate::rrmf_quintic::solutions::rrmf_quintics;
    use crate::rrmf_quintic::solutions::tests::{example_1, random_data};
    use std::sync::Arc;

    /// Max RMF defect |f₂' · f₃| / |x'| and orthonormality error at 1,000 parameters, and
    /// the max distance of the frame's tangent from the curve's.
    pub fn frame_errors(field: &FrameField) -> (f64, f64, f64) {
        let mut worst = (0.0f64, 0.0f64, 0.0f64);
        for t in uniform_parameters(field.domain(), 1000) {
            let frame = field.frame(t).unwrap();
            let (_, tangent) = field.curve().point_unit_tangent(t).unwrap();
            worst.0 = worst.0.max(rmf_defect(field, t).unwrap().abs());
            worst.1 = worst.1.max(orthonormality_error(&frame));
            worst.2 = worst.2.max((frame.tangent - tangent).length());
        }
        worst
    }

    fn field(quintics: &[RrmfQuintic], normal: DVec3) -> FrameField {
        let curve = Arc::new(quintic_curve(quintics).unwrap());
        let frames = quintic_rmf(quintics, normal).unwrap();
        FrameField::new(curve, FrameKind::Rational(frames)).unwrap()
    }

    #[test]
    fn the_rational_rmf_is_exact_orthonormal_and_starts_at_the_normal() {
        let normal = DVec3::new(0.2, 1.0, -0.4);
        let (mut worst, mut count, mut split) = ((0.0f64, 0.0f64, 0.0f64), 0, 0);
        let mut data = random_data(30);
        data.push(example_1());
        for d in &data {
            for eta in [0.4, 1.7, 3.0, 4.325, 5.2] {
                for q in rrmf_quintics(d, eta).unwrap() {
                    let f = field(&[q], normal);
                    let (defect, ortho, tangent) = frame_errors(&f);
                    assert!(defect <= 1e-9, "RMF defect {defect:e}");
                    assert!(ortho <= 1e-12, "orthonormality {ortho:e}");
                    assert!(
                        tangent <= 1e-12,
                        "frame tangent off the curve's by {tangent:e}"
                    );
                    let start = f.frame(0.0).unwrap();
                    let expected = (normal - normal.dot(d.t0) * d.t0).normalize();
                    assert!((start.f2 - expected).length() < 1e-14);
                    worst = (
                        worst.0.max(defect),
                        worst.1.max(ortho),
                        worst.2.max(tangent),
                    );
                    count += 1;
                    if let FrameKind::Rational(r) = f.kind() {
                        split += usize::from(r.breaks().len() > 2);
                    }
                }
            }
        }
        println!(
            "{count} quintics ({split} split for positive weights): max RMF defect {:.1e}, \
             orthonormality {:.1e}, tangent {:.1e}",
            worst.0, worst.1, worst.2
        );
        assert!(count > 50 && split > 0, "{count} quintics, {split} split");
    }

    /// The Euler–Rodrigues frame (w = 1 in (9)) of the same curve is not rotation-minimizing
    /// (Section 2): the defect measure does see the difference.
    #[test]
    fn the_erf_of_an_rrmf_quintic_is_not_an_rmf() {
        let q = rrmf_quintics(&example_1(), 4.325).unwrap()[0];
        let erf = q.hopf.rotated_erf(&[Complex::ONE; 3]);
        assert!(erf.denominator.iter().all(|&d| d > 0.0));
        let erf_segment = RationalFrameSegment::new(
            erf.f2.iter().map(|&v| q.placement.vector(v)).collect(),
            erf.f3.iter().map(|&v| q.placement.vector(v)).collect(),
            erf.denominator.clone(),
        )
        .unwrap();
        let curve = Arc::new(quintic_curve(&[q]).unwrap());
        let frames = RationalFrames::new(vec![erf_segment], vec![0.0, 1.0]).unwrap();
        let erf_field = FrameField::new(curve, FrameKind::Rational(frames)).unwrap();
        let (defect, ortho, _) = frame_errors(&erf_field);
        let (rmf_defect, _, _) = frame_errors(&field(&[q], DVec3::Z));
        println!("Example 1, η = 4.325: max defect ERF {defect:.3}, RMF (9) {rmf_defect:.1e}");
        assert!(defect > 0.1 && ortho < 1e-12);
        assert!(rmf_defect < 1e-12);
    }

    /// Max |f₂ − f₂(double reflection)| at `samples` parameters: an independent RMF of the
    /// same curve from the same start.
    pub fn distance_from_double_reflection(field: &FrameField, samples: usize) -> f64 {
        let params = uniform_parameters(field.domain(), samples);
        let start = field.frame(field.domain().0).unwrap().f2;
        let dr = DoubleReflectionRmf::along(field.curve().as_ref(), params.clone(), start).unwrap();
        params
            .iter()
            .zip(dr.frames())
            .map(|(&t, g)| (field.frame(t).unwrap().f2 - g.f2).length())
            .fold(0.0, f64::max)
    }

    #[test]
    fn agrees_with_double_reflection() {
        for eta in [4.325, 5.2] {
            let q = rrmf_quintics(&example_1(), eta).unwrap();
            let worst = distance_from_double_reflection(&field(&q[1..], DVec3::Z), 4000);
            println!(
                "Example 1, η = {eta}: |f₂ − f₂(double reflection, 4,000 samples)| ≤ {worst:.1e}"
            );
            assert!(worst < 1e-9, "{worst:e}");
        }
    }
}
