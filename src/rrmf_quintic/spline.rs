//! G1 RRMF quintic splines (Section 5, Example 3): one RRMF quintic per pair of
//! consecutive Hermite points, each with the η of least shape measure, and one continuous
//! exact rational RMF along the whole spline — each segment's RMF (9) turned by a constant
//! angle about the tangent so that frames agree at the joints (a constant rotation of an
//! RMF is again an RMF).

use super::eta::{best_quintic_within, check_eta_samples, Budget};
use super::frames::{quintic_curve, quintic_rmf};
use super::measures::ShapeMeasure;
use super::solutions::RrmfQuintic;
use crate::bezier::PiecewiseCurve;
use crate::error::{Error, Result};
use crate::frames::rational::RationalFrames;
use crate::hermite::HermiteSegment;
use crate::math::normal_plane_unit;
use glam::DVec3;

/// A spline of RRMF quintics, segment k on [k, k + 1], with its rational RMF.
#[derive(Clone, Debug)]
pub struct RrmfSpline {
    /// The curve, segment k on [k, k + 1].
    pub curve: PiecewiseCurve,
    /// The RMF; its breakpoints refine the curve's where a segment was split for positive
    /// weights.
    pub frames: RationalFrames,
    /// The quintic chosen for each segment.
    pub quintics: Vec<RrmfQuintic>,
}

/// The RRMF quintic spline through validated Hermite `segments`, choosing each segment's η
/// by `measure` from `eta_samples` samples, with f₂ at the start the projection of
/// `initial_normal` onto the normal plane.
pub fn rrmf_spline(
    segments: &[HermiteSegment],
    measure: ShapeMeasure,
    eta_samples: usize,
    initial_normal: DVec3,
) -> Result<RrmfSpline> {
    rrmf_spline_within(
        segments,
        measure,
        eta_samples,
        initial_normal,
        &mut Budget::unlimited(),
    )
}

/// [`rrmf_spline`] spending at most `budget` solves over all segments (N_η plus the
/// refinement's, about 40, per segment); [`ErrorKind::NotConverged`](crate::ErrorKind),
/// naming the segment, when it is spent. `budget.spent` tells what was used.
pub fn rrmf_spline_within(
    segments: &[HermiteSegment],
    measure: ShapeMeasure,
    eta_samples: usize,
    initial_normal: DVec3,
    budget: &mut Budget,
) -> Result<RrmfSpline> {
    check_eta_samples(eta_samples)?;
    // A bad normal is refused before any work is spent.
    if let Some(first) = segments.first() {
        normal_plane_unit(initial_normal, first.t0, "initial_normal")?;
    }
    let quintics = segments
        .iter()
        .enumerate()
        .map(|(k, data)| {
            best_quintic_within(data, measure, eta_samples, budget)
                .map(|best| best.quintic)
                .map_err(|e| in_segment(k, e))
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(RrmfSpline {
        curve: quintic_curve(&quintics)?,
        frames: quintic_rmf(&quintics, initial_normal)?,
        quintics,
    })
}

/// The error of segment k, saying which points it joins (the segment's own messages name
/// its data p0, t0, p1, t1).
fn in_segment(k: usize, e: Error) -> Error {
    let context = format!(
        "segment {k} (p0, t0 = points[{k}], tangents[{k}]; p1, t1 = points[{}], tangents[{}])",
        k + 1,
        k + 1
    );
    e.context(context)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::frames::{FrameField, FrameKind};
    use crate::hermite::hermite_sequence;
    use crate::rrmf_quintic::frames::tests::{distance_from_double_reflection, frame_errors};
    use crate::rrmf_quintic::solutions::tests::check_solution;
    use std::f64::consts::PI;
    use std::sync::Arc;

    /// Example 3: the helix (sin t, cos t, t) sampled at ten equidistant points of
    /// [0, 9π/2], with unit tangents.
    pub fn helix_data() -> (Vec<DVec3>, Vec<DVec3>) {
        (0..10)
            .map(|k| {
                let t = k as f64 * PI / 2.0;
                (
                    DVec3::new(t.sin(), t.cos(), t),
                    DVec3::new(t.cos(), -t.sin(), 1.0).normalize(),
                )
            })
            .unzip()
    }

    #[test]
    fn example_3_helix_spline_with_one_continuous_rmf() {
        let (points, tangents) = helix_data();
        let segments = hermite_sequence(&points, &tangents).unwrap();
        let normal = DVec3::new(-1.0, 0.0, 0.0);
        let spline = rrmf_spline(&segments, ShapeMeasure::ScaledEnergyRmf, 64, normal).unwrap();
        assert_eq!(spline.curve.segments().len(), 9);
        for (k, q) in spline.quintics.iter().enumerate() {
            check_solution(&segments[k], q);
            println!(
                "segment {k}: η = {:.4}, ρ = {:.4}, L = {:.4}, E = {:.4}, E_rmf = {:.4}",
                q.eta,
                q.rho,
                q.measures.arc_length,
                q.measures.energy_frenet,
                q.measures.energy_rmf
            );
        }
        // Interpolation and G1 joints in the spline's own parameter.
        for (k, (&p, &t)) in points.iter().zip(&tangents).enumerate() {
            let jet = spline.curve.eval_jet(k as f64);
            assert!((jet.point - p).length() < 1e-12 * 9.0 * PI);
            assert!(jet.d1.normalize().cross(t).length() < 1e-12);
        }
        // The frames: exact RMF, orthonormal, continuous at every joint and breakpoint.
        let field = FrameField::new(
            Arc::new(spline.curve.clone()),
            FrameKind::Rational(spline.frames.clone()),
        )
        .unwrap();
        let (defect, ortho, tangent) = frame_errors(&field);
        let mut jump = 0.0f64;
        for pair in spline.frames.segments().windows(2) {
            let (a, b) = (pair[0].frame(1.0), pair[1].frame(0.0));
            jump = jump.max((a.f2 - b.f2).length()).max((a.f3 - b.f3).length());
        }
        let against_dr = distance_from_double_reflection(&field, 9001);
        let length: f64 = spline.quintics.iter().map(|q| q.measures.arc_length).sum();
        println!(
            "Example 3: L = {length:.4} (helix {:.4}), {} frame pieces; max RMF defect {defect:.1e}, \
             orthonormality {ortho:.1e}, frame jump at joints {jump:.1e}, \
             |f₂ − f₂(double reflection)| {against_dr:.1e}",
            9.0 * PI / 2.0 * 2f64.sqrt(),
            spline.frames.segments().len()
        );
        assert!(defect <= 1e-9 && ortho <= 1e-12 && tangent <= 1e-12);
        assert!(jump <= 1e-12 && against_dr < 1e-8);
        let start_normal = (normal - normal.dot(tangents[0]) * tangents[0]).normalize();
        assert!((field.frame(0.0).unwrap().f2 - start_normal).length() < 1e-15);
    }

    /// The budget caps the solves of the whole spline: with exactly what an uncapped run
    /// spends the result is the same, one solve less is NotConverged naming the segment
    /// where it ran out.
    #[test]
    fn the_budget_caps_the_work_of_the_whole_spline() {
        let (points, tangents) = helix_data();
        let segments = hermite_sequence(&points, &tangents).unwrap();
        let normal = DVec3::new(-1.0, 0.0, 0.0);
        let measure = ShapeMeasure::ScaledEnergyRmf;
        let mut free = Budget::unlimited();
        let spline = rrmf_spline_within(&segments, measure, 16, normal, &mut free).unwrap();
        let per_segment = free.spent as f64 / segments.len() as f64;
        println!(
            "{} solves for {} segments at N_η = 16 ({per_segment:.1} per segment)",
            free.spent,
            segments.len()
        );
        assert!(free.spent >= 16 * segments.len());
        assert!(free.spent <= (16 + crate::rrmf_quintic::eta::MAX_REFINEMENT_SOLVES) * 9);
        let mut exact = Budget::new(free.spent);
        let same = rrmf_spline_within(&segments, measure, 16, normal, &mut exact).unwrap();
        assert_eq!(same.quintics, spline.quintics);
        assert_eq!(exact.spent, free.spent);
        for max in [free.spent - 1, 100, 1, 0] {
            let mut short = Budget::new(max);
            let e = rrmf_spline_within(&segments, measure, 16, normal, &mut short).unwrap_err();
            assert!(e.is(crate::ErrorKind::NotConverged), "{e}");
            assert!(
                e.message().contains("budget") && e.message().contains("segment"),
                "{e}"
            );
            assert!(short.spent <= max);
        }
        let mut short = Budget::new(free.spent - 1);
        let e = rrmf_spline_within(&segments, measure, 16, normal, &mut short).unwrap_err();
        assert!(e.message().contains("segment 8"), "{e}");
    }

    #[test]
    fn names_the_segment_that_fails() {
        let points = [DVec3::ZERO, DVec3::X, DVec3::new(2.0, 0.0, 0.0)];
        let tangents = [
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::X,
        ];
        let segments = hermite_sequence(&points, &tangents).unwrap();
        let e = rrmf_spline(&segments, ShapeMeasure::ArcLength, 32, DVec3::Z).unwrap_err();
        assert!(
            e.message().contains("segment 1") && e.message().contains("points[2]"),
            "{e}"
        );
    }
}
