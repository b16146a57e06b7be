//! G1 RRMF quintic splines (Section 5, Example 3): one RRMF quintic per pair of
//! consecutive Hermite points, each with the η of least shape measure, and one continuous
//! exact rational RMF along the whole spline — each segment's RMF (9) turned by a constant
//! angle about the tangent so that frames agree at the joints (a constant rotation of an
//! RMF is again an RMF).

use super::eta::{best_quintic_within, check_eta_samples, Budget};
use super::frames::{quintic_curve, quintic_rmf};
use super::measures::ShapeMeasure;
use super::solutions::RrmfQuintic;
use crate::error::{Error, Result};
use crate::hermite::HermiteSegment;
use crate::math::normal_plane_unit;
use crate::model::FramedCurve;
use glam::DVec3;

/// A spline of RRMF quintics, segment k on [k, k + 1], with its rational RMF.
#[derive(Clone, Debug)]
pub struct RrmfSpline {
    /// The curve, segment k on [k, k + 1], with its RMF (whose breakpoints refine the
    /// curve's where a segment was split for positive weights).
    pub framed: FramedCurve,
    /// The quintic chosen for each segment.
    pub quintics: Vec<RrmfQuintic>,
    /// Roots left out as near-cusps over all segments ([`BestQuintic::irregular_roots`](super::eta::BestQuintic::irregular_roots)).
    pub irregular_roots: usize,
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
    let best = segments
        .iter()
        .enumerate()
        .map(|(k, data)| {
            best_quintic_within(data, measure, eta_samples, budget).map_err(|e| in_segment(k, e))
        })
        .collect::<Result<Vec<_>>>()?;
    let quintics: Vec<RrmfQuintic> = best.iter().map(|b| b.quintic).collect();
    Ok(RrmfSpline {
        framed: FramedCurve::of_construction(
            quintic_curve(&quintics)?,
            quintic_rmf(&quintics, initial_normal)?,
        ),
        quintics,
        irregular_roots: best.iter().map(|b| b.irregular_roots).sum(),
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
    use crate::testing::check_solution;
    use std::f64::consts::PI;
    use std::sync::Arc;

    /// Example 3: the helix (sin t, cos t, t) sampled at ten equidistant points of
    /// [0, 9π/2], with unit tangents.
    pub(crate) fn helix_data() -> (Vec<DVec3>, Vec<DVec3>) {
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
        assert_eq!(spline.framed.curve().segments().len(), 9);
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
            let jet = spline.framed.curve().eval_jet(k as f64);
            assert!((jet.point - p).length() < 1e-12 * 9.0 * PI);
            assert!(jet.d1.normalize().cross(t).length() < 1e-12);
        }
        // The frames: exact RMF, orthonormal, continuous at every joint and breakpoint.
        let field = FrameField::new(
            Arc::new(spline.framed.curve().clone()),
            FrameKind::Rational(spline.framed.frames().clone()),
        )
        .unwrap();
        let (defect, ortho, tangent) = frame_errors(&field);
        let mut jump = 0.0f64;
        for pair in spline.framed.frames().segments().windows(2) {
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
            spline.framed.frames().segments().len()
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
        // Segment 1: θ_i = 2, θ_f = 3.1, φ = 1.5, data without an RRMF quintic interpolant.
        let points = [DVec3::ZERO, DVec3::X, DVec3::new(2.0, 0.0, 0.0)];
        let (s, c) = 3.1f64.sin_cos();
        let tangents = [
            DVec3::new(1.0, 1.0, 0.5),
            DVec3::new(2f64.cos(), 2f64.sin(), 0.0),
            DVec3::new(c, s * 1.5f64.cos(), s * 1.5f64.sin()),
        ];
        let segments = hermite_sequence(&points, &tangents).unwrap();
        let e = rrmf_spline(&segments, ShapeMeasure::ArcLength, 32, DVec3::Z).unwrap_err();
        assert!(
            e.message().contains("segment 1") && e.message().contains("points[2]"),
            "{e}"
        );
    }

    /// The helix (cos t, sin t, 0.3 t) from `start` with start tangent `tangent`, rigidly
    /// moved: points and unit tangents at t = 0, step, …, (n − 1)·step.
    fn helix_piece(start: DVec3, tangent: DVec3, n: usize, step: f64) -> Vec<(DVec3, DVec3)> {
        let h = |t: f64| DVec3::new(t.cos(), t.sin(), 0.3 * t);
        let dh = |t: f64| DVec3::new(-t.sin(), t.cos(), 0.3).normalize();
        let turn = glam::DQuat::from_rotation_arc(dh(0.0), tangent);
        (0..n)
            .map(|k| {
                let t = k as f64 * step;
                (start + turn * (h(t) - h(0.0)), turn * dh(t))
            })
            .collect()
    }

    /// A unit vector across `t` (not along it).
    fn across(t: DVec3) -> DVec3 {
        crate::math::orthogonalized(DVec3::new(0.3, -0.2, 1.0), t).normalize()
    }

    /// Hermite data with flat stretches between helices: helix, a planar circular arc of
    /// two segments, helix, a straight segment, helix, an S-shaped planar segment (parallel
    /// tangents: φ = 0, where Section 4 finds no quintic even slightly off planar), helix.
    /// Returns the data and which segments are planar.
    pub(crate) fn flat_stretch_data() -> (Vec<DVec3>, Vec<DVec3>, Vec<bool>) {
        let mut data = helix_piece(
            DVec3::ZERO,
            DVec3::new(0.0, 1.0, 0.3).normalize(),
            3,
            0.5 * PI,
        );
        let mut planar = vec![false; 2];
        let (a, ta) = data[data.len() - 1];
        // A circular arc of radius 1.2 in the plane of ta and n, through s = 0.8 and 1.6 rad.
        let n = across(ta);
        let arc = |s: f64| {
            (
                a + (n * (1.0 - s.cos()) + ta * s.sin()) * 1.2,
                ta * s.cos() + n * s.sin(),
            )
        };
        data.extend([arc(0.8), arc(1.6)]);
        planar.extend([true, true]);
        let (b, tb) = data[data.len() - 1];
        data.extend(helix_piece(b, tb, 3, 0.5 * PI).into_iter().skip(1));
        planar.extend([false, false]);
        let (c, tc) = data[data.len() - 1];
        data.push((c + tc * 2.0, tc));
        planar.push(true);
        let (d, td) = data[data.len() - 1];
        data.extend(helix_piece(d, td, 3, 0.5 * PI).into_iter().skip(1));
        planar.extend([false, false]);
        let (e, te) = data[data.len() - 1];
        let chord = (te * 0.5f64.cos() + across(te) * 0.5f64.sin()) * 1.5;
        data.push((e + chord, te));
        planar.push(true);
        let (f, tf) = data[data.len() - 1];
        data.extend(helix_piece(f, tf, 2, 0.5 * PI).into_iter().skip(1));
        planar.push(false);
        let (points, tangents) = data.into_iter().unzip();
        (points, tangents, planar)
    }

    /// Interpolation of the points (to 1e-12 of the data's size) and of the tangents from
    /// both sides of every joint: the max tangent error in radians.
    fn check_interpolation(spline: &RrmfSpline, points: &[DVec3], tangents: &[DVec3]) -> f64 {
        let scale = points
            .iter()
            .map(|p| p.abs().max_element())
            .fold(0.0, f64::max);
        let mut tangent_error = 0.0f64;
        for (k, segment) in spline.framed.curve().segments().iter().enumerate() {
            let poles: Vec<DVec3> = segment.poles().collect();
            assert!(
                crate::math::robust_length(poles[0] - points[k]) <= 1e-12 * scale,
                "segment {k} start"
            );
            assert!(
                crate::math::robust_length(poles[5] - points[k + 1]) <= 1e-12 * scale,
                "segment {k} end"
            );
            // Scaled to unit size before the cross product, which would overflow at 1e200.
            let unit = |v: DVec3| v / v.abs().max_element();
            let start = unit(segment.eval_jet(0.0).d1);
            let end = unit(segment.eval_jet(1.0).d1);
            tangent_error = tangent_error
                .max(crate::math::angle_between(start, tangents[k]))
                .max(crate::math::angle_between(end, tangents[k + 1]));
        }
        assert!(
            tangent_error <= 1e-10,
            "tangents off by {tangent_error:e} rad"
        );
        tangent_error
    }

    /// Interpolation, G1 joints from both sides, and the RMF: |f₂'·f₃| (the frame's angular
    /// velocity about the tangent), orthonormality, agreement with a dense double-reflection
    /// RMF from the same start, and frame continuity at every joint and breakpoint.
    /// Returns (max tangent error at the data, max RMF defect, max |f₂ − f₂(DR)|).
    pub(crate) fn check_spline(
        spline: &RrmfSpline,
        points: &[DVec3],
        tangents: &[DVec3],
    ) -> (f64, f64, f64) {
        let tangent_error = check_interpolation(spline, points, tangents);
        let field = FrameField::new(
            Arc::new(spline.framed.curve().clone()),
            FrameKind::Rational(spline.framed.frames().clone()),
        )
        .unwrap();
        let (defect, ortho, frame_tangent) = frame_errors(&field);
        let mut jump = 0.0f64;
        for pair in spline.framed.frames().segments().windows(2) {
            let (a, b) = (pair[0].frame(1.0), pair[1].frame(0.0));
            jump = jump.max((a.f2 - b.f2).length()).max((a.f3 - b.f3).length());
        }
        let against_dr = distance_from_double_reflection(&field, 20001);
        assert!(defect <= 1e-9, "RMF defect {defect:e}");
        assert!(
            ortho <= 1e-12 && frame_tangent <= 1e-9,
            "{ortho:e} {frame_tangent:e}"
        );
        assert!(jump <= 1e-12, "frames jump by {jump:e} at a joint");
        assert!(
            against_dr < 1e-8,
            "|f₂ − f₂(double reflection)| = {against_dr:e}"
        );
        (tangent_error, defect, against_dr)
    }

    #[test]
    fn flat_stretches_and_straight_segments_keep_one_continuous_rmf() {
        let (points, tangents, planar) = flat_stretch_data();
        let segments = hermite_sequence(&points, &tangents).unwrap();
        let spline = rrmf_spline(&segments, ShapeMeasure::ScaledEnergyRmf, 64, DVec3::Z).unwrap();
        for ((q, data), &flat) in spline.quintics.iter().zip(&segments).zip(&planar) {
            assert_eq!(crate::rrmf_quintic::planar::is_planar(data).unwrap(), flat);
            // A flat stretch stays flat: every pole in the plane of the data (the straight
            // segment: on its line).
            let chord = (data.p1 - data.p0).normalize();
            let (a, b) = (chord.cross(data.t0), chord.cross(data.t1));
            let across = if a.length() >= b.length() { a } else { b };
            for p in q.bezier().unwrap().poles() {
                let off = if across.length() > 1e-14 {
                    (p - data.p0).dot(across.normalize()).abs()
                } else {
                    (p - data.p0).cross(chord).length()
                };
                assert!(!flat || off <= 1e-13 * data.chord_length(), "{off:e}");
            }
            if !q.planar {
                check_solution(data, q);
            }
        }
        let (tangent, defect, dr) = check_spline(&spline, &points, &tangents);
        println!(
            "helix, planar arc (2 segments), helix, straight, helix, S-shaped planar, helix: \
             tangents {tangent:.1e} rad, RMF defect {defect:.1e}, |f₂ − f₂(DR)| {dr:.1e}"
        );
        // The straight segment's frame is constant: the one carried from the helix before.
        let straight = planar.iter().enumerate().filter(|p| *p.1).nth(2).unwrap().0;
        let field = FrameField::new(
            Arc::new(spline.framed.curve().clone()),
            FrameKind::Rational(spline.framed.frames().clone()),
        )
        .unwrap();
        let f = |t: f64| field.frame(t).unwrap().f2;
        let k = straight as f64;
        assert!((f(k) - f(k + 0.5)).length() < 1e-14 && (f(k) - f(k + 1.0)).length() < 1e-14);
    }

    /// The same data scaled by 1e-200 … 1e200 give the same spline, scaled, and the same
    /// frames.
    #[test]
    fn flat_stretches_at_every_scale() {
        let (points, tangents, _) = flat_stretch_data();
        let spline_at = |scale: f64| {
            let scaled: Vec<DVec3> = points.iter().map(|&p| p * scale).collect();
            let segments = hermite_sequence(&scaled, &tangents).unwrap();
            let spline =
                rrmf_spline(&segments, ShapeMeasure::ScaledEnergyRmf, 64, DVec3::Z).unwrap();
            check_interpolation(&spline, &scaled, &tangents);
            spline
        };
        let unit = spline_at(1.0);
        check_spline(&unit, &points, &tangents);
        let size = points.iter().map(|p| p.length()).fold(0.0, f64::max);
        for scale in [1e-200, 1e-100, 1e-10, 1e10, 1e100, 1e200] {
            let s = spline_at(scale);
            let (mut points_off, mut frames_off) = (0.0f64, 0.0f64);
            for i in 0..=2000 {
                let t = i as f64 * (points.len() - 1) as f64 / 2000.0;
                points_off = points_off.max(
                    (s.framed.curve().eval(t) / scale - unit.framed.curve().eval(t)).length()
                        / size,
                );
                frames_off = frames_off.max(
                    (s.framed.frames().frame(t).f2 - unit.framed.frames().frame(t).f2).length(),
                );
            }
            assert!(
                points_off < 1e-12 && frames_off < 1e-10,
                "scale {scale:e}: {points_off:e} {frames_off:e}"
            );
        }
    }
}
