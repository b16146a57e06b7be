//! RRMF quintics and their rational RMF (9) as the library's curve and frame objects.
//!
//! Quintic k of a sequence lives on [k, k + 1]. Its RMF is f₂ = N₂/d, f₃ = N₃/d of degree 8
//! with d = (a² + b²)(|α|² + |β|²) > 0. Each quintic's interval is split into pieces on
//! which d's Bernstein coefficients — the weights of the frame vectors — are positive (CAD
//! systems need positive weights; the coefficients can be negative for a strongly turning
//! quintic, which is the common case) and within a factor `MAX_SPREAD` of each other
//! (extreme weight ratios trouble CAD kernels). Each piece is computed from α, β, w
//! restricted to it (`HopfQuadratics::rmf_numerators_on`): where the speed dips, d ∝ σ²
//! and the degree-8 products cancel, and local coefficients keep the digits. The pieces
//! are joined by constant rotations about the tangent, which keep an RMF rotation-minimizing
//! (`RationalFrames::chained`): the first so that f₂ starts at the caller's normal, every
//! further one so that frames agree at the joints.

use super::hopf::RmfNumerators;
use super::solutions::RrmfQuintic;
use crate::bezier::PiecewiseCurve;
use crate::error::no_solution;
use crate::error::Result;
use crate::frames::rational::{g1_tolerance, RationalFrameSegment, RationalFrames, Turning};
use glam::DVec3;

/// Largest ratio of the frame weights (the RMF denominator's Bernstein coefficients) on one
/// piece.
const MAX_SPREAD: f64 = 100.0;

/// Most halvings of a quintic's interval; a regular quintic needs a few (each halving
/// brings a piece's coefficients closer to the values of d on it).
const MAX_SUBDIVISION_DEPTH: usize = 40;

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
        let mut pieces = Vec::new();
        if !split(quintic, 0.0, 1.0, 0, &mut pieces) {
            return no_solution!(
                "the speed of quintic {k} (almost) vanishes: the curve is numerically singular \
                 and has no rational frame with positive weights"
            );
        }
        for (end, rmf) in pieces {
            segments.push(RationalFrameSegment::new(rmf.f2, rmf.f3, rmf.denominator)?);
            breaks.push(k as f64 + end);
        }
    }
    let tolerance = g1_tolerance(&quintic_curve(quintics)?);
    Ok(
        RationalFrames::chained_within(segments, breaks, initial_normal, tolerance)?
            .with_turning(Turning::RotationMinimizing),
    )
}

/// Appends the pieces of [s0, s1] (their right ends and frames) to `out`, halving until the
/// denominator's coefficients are positive and within `MAX_SPREAD`; false if that takes
/// more than `MAX_SUBDIVISION_DEPTH` halvings.
fn split(
    q: &RrmfQuintic,
    s0: f64,
    s1: f64,
    depth: usize,
    out: &mut Vec<(f64, RmfNumerators)>,
) -> bool {
    let rmf = q.rmf_on(s0, s1);
    let d = &rmf.denominator;
    let (lo, hi) = d.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &x| {
        (lo.min(x), hi.max(x))
    });
    if lo > 0.0 && hi <= MAX_SPREAD * lo {
        out.push((s1, rmf));
        return true;
    }
    if depth == MAX_SUBDIVISION_DEPTH {
        return false;
    }
    let mid = 0.5 * (s0 + s1);
    split(q, s0, mid, depth + 1, out) && split(q, mid, s1, depth + 1, out)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::curve::{uniform_parameters, ParametricCurve};
    use crate::frames::double_reflection::DoubleReflectionRmf;
    use crate::frames::metrics::{orthonormality_error, rmf_defect};
    use crate::frames::{FrameField, FrameKind};
    use crate::hermite::HermiteSegment;
    use crate::math::Complex;
    use crate::rrmf_quintic::measures::speed_range;
    use crate::rrmf_quintic::solutions::rrmf_quintics;
    use crate::testing::{
        check_solution, example_1, near_degenerate_data, random_data, random_vectors,
    };
    use std::sync::Arc;

    /// Max RMF defect |f₂' · f₃| / |x'| and orthonormality error at 1,000 parameters, and
    /// the max distance of the frame's tangent from the curve's.
    pub(crate) fn frame_errors(field: &FrameField) -> (f64, f64, f64) {
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

    /// Every solution of general and of nearly degenerate data (whose solutions include
    /// near-cusps, the speed dipping to 1e-6 of its maximum) gets an exact, orthonormal
    /// frame: |f₂' · f₃| ≤ 1e-9 per unit parameter at 1,000 parameters, adapted to the curve.
    #[test]
    fn the_rational_rmf_is_exact_orthonormal_and_starts_at_the_normal() {
        let normal = DVec3::new(0.2, 1.0, -0.4);
        let (mut worst, mut count, mut split, mut dips) = ([0.0f64; 4], 0, 0, 0);
        let mut data = random_data(40);
        data.extend(near_degenerate_data(60));
        data.push(example_1());
        for d in &data {
            for k in 0..12 {
                for q in rrmf_quintics(d, 0.1 + 0.5 * k as f64).unwrap() {
                    let f = field(&[q], normal);
                    let (defect, ortho, tangent) = frame_errors(&f);
                    let per_parameter = defect_per_parameter(&f);
                    assert!(per_parameter <= 1e-9, "RMF defect {per_parameter:e}");
                    assert!(ortho <= 1e-12, "orthonormality {ortho:e}");
                    assert!(
                        tangent <= 1e-9,
                        "frame tangent off the curve's by {tangent:e}"
                    );
                    let start = f.frame(0.0).unwrap();
                    let expected = (normal - normal.dot(d.t0) * d.t0).normalize();
                    assert!((start.f2 - expected).length() < 1e-14);
                    for (w, value) in worst
                        .iter_mut()
                        .zip([per_parameter, defect, ortho, tangent])
                    {
                        *w = w.max(value);
                    }
                    count += 1;
                    if let FrameKind::Rational(r) = f.kind() {
                        split += usize::from(r.breaks().len() > 2);
                    }
                    let (slowest, fastest) = speed_range(&q.hopf);
                    dips += usize::from(slowest < 1e-3 * fastest);
                }
            }
        }
        println!(
            "{count} quintics ({split} split into pieces, {dips} with the speed dipping below 1e-3 \
             of its maximum): max RMF defect |f₂'·f₃| {:.1e} per unit parameter ({:.1e} per unit \
             length), orthonormality {:.1e}, frame tangent vs curve tangent {:.1e}",
            worst[0], worst[1], worst[2], worst[3]
        );
        assert!(
            count > 1000 && split > 0 && dips > 50,
            "{count} quintics, {split} split, {dips} dips"
        );
    }

    /// Max |f₂' · f₃| (per unit parameter) at 1,000 parameters.
    fn defect_per_parameter(field: &FrameField) -> f64 {
        uniform_parameters(field.domain(), 1000)
            .into_iter()
            .map(|t| {
                let speed = field.curve().eval_jet(t).d1.length();
                (rmf_defect(field, t).unwrap() * speed).abs()
            })
            .fold(0.0, f64::max)
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
    pub(crate) fn distance_from_double_reflection(field: &FrameField, samples: usize) -> f64 {
        let params = uniform_parameters(field.domain(), samples);
        let start = field.frame(field.domain().0).unwrap().f2;
        let dr = DoubleReflectionRmf::along(field.curve().as_ref(), params.clone(), start).unwrap();
        params
            .iter()
            .zip(dr.frames())
            .map(|(&t, g)| (field.frame(t).unwrap().f2 - g.f2).length())
            .fold(0.0, f64::max)
    }

    /// The values of η in [−π, π] at which pseudo-random data reach the exceptional case
    /// |δ₀| = |δ₁| of (30) with (35) satisfied, each with its ρ: sign changes of the phase
    /// condition along η (2,000 steps), refined by bisection.
    fn exceptional_cases(data: &HermiteSegment) -> Vec<(f64, f64)> {
        use crate::math::bisect_root;
        use crate::rrmf_quintic::canonical::CanonicalHermite;
        use crate::rrmf_quintic::sextic::exceptional_phases;
        let c = CanonicalHermite::new(data).unwrap();
        let phase = |eta: f64, k: usize| exceptional_phases(&c, eta).get(k).copied();
        let etas = uniform_parameters((-std::f64::consts::PI, std::f64::consts::PI), 2001);
        let mut found = Vec::new();
        for pair in etas.windows(2) {
            for k in 0..2 {
                let (Some((r0, g0)), Some((r1, g1))) = (phase(pair[0], k), phase(pair[1], k))
                else {
                    continue;
                };
                // The same root on both sides (not a swap of roots) changing sign.
                if (g0 < 0.0) != (g1 < 0.0) && (r1 - r0).abs() < 0.1 * r0 {
                    let g = |eta: f64| phase(eta, k).map_or(f64::NAN, |p| p.1);
                    if let Some(eta) = bisect_root(g, pair[0], pair[1], 1e-15) {
                        if let Some((rho, _)) = phase(eta, k).filter(|p| p.1.abs() < 1e-12) {
                            found.push((eta, rho));
                        }
                    }
                }
            }
        }
        found
    }

    /// Hermite data that reach the exceptional case |δ₀| = |δ₁| of (30) (after (32)): there
    /// (35) has a double root ρ*, and the solutions at ρ* exist for that η alone (none within
    /// 1e-3 of ρ* at η ± 1e-7). Every one returned is a true interpolant with an exact RMF
    /// that agrees with double reflection, none is returned twice, and most cases have one.
    #[test]
    fn data_reaching_equal_deltas_get_their_solutions() {
        let (mut cases, mut solved, mut solutions, mut worst) = (0, 0, 0, 0.0f64);
        for d in random_data(40) {
            for (eta, rho) in exceptional_cases(&d) {
                let near = |eta: f64| {
                    rrmf_quintics(&d, eta)
                        .unwrap()
                        .into_iter()
                        .filter(|q| (q.rho - rho).abs() < 1e-3 * rho)
                        .collect::<Vec<_>>()
                };
                let at = near(eta);
                assert!(near(eta - 1e-7).is_empty() && near(eta + 1e-7).is_empty());
                for (k, q) in at.iter().enumerate() {
                    check_solution(&d, q);
                    let alone = field(&[*q], DVec3::Z);
                    worst = worst.max(distance_from_double_reflection(&alone, 2000));
                    for other in &at[..k] {
                        let apart = (q.hopf.alpha[1] - other.hopf.alpha[1]).abs();
                        assert!(apart > 1e-6 * q.hopf.alpha[1].abs(), "a solution twice");
                    }
                }
                cases += 1;
                solved += usize::from(!at.is_empty());
                solutions += at.len();
            }
        }
        println!(
            "equal deltas: {solved} of {cases} cases solved, {solutions} solutions; \
             |f₂ − double reflection| ≤ {worst:.1e}"
        );
        assert!(cases >= 40, "only {cases} exceptional cases reached");
        assert!(
            solved >= 20,
            "only {solved} of {cases} exceptional cases solved"
        );
        assert!(worst < 1e-9, "{worst:e}");
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

    /// Pseudo-random data of every scale from 1e-150 to 1e150, many nearly degenerate (a
    /// tangent almost along the chord or the data almost planar), with η up to 1e6: no
    /// panic, and every returned solution has its exact frame.
    #[test]
    fn fuzzed_data_give_solutions_with_frames_or_clean_errors() {
        let mut vector = random_vectors(777);
        let (mut solutions, mut refused) = (0, 0);
        for i in 0..4000 {
            let closeness = 10f64.powi(-(i % 16));
            let scale = 10f64.powi(i % 7 * 50 - 150);
            let (p0, mut t0, chord, mut t1) =
                (vector() * scale, vector(), vector() * scale, vector());
            match i % 4 {
                0 => t0 = chord.normalize() + t0 * closeness,
                1 => {
                    let n = chord.cross(t0).normalize();
                    t1 = t1 - n * t1.dot(n) + n * closeness;
                }
                2 => t1 = t0 + t1 * closeness,
                _ => {}
            }
            let e = vector();
            let eta = [e.x * 1e6, e.y * 1e-300, e.z * 7.0][i as usize % 3];
            let Ok(data) = HermiteSegment::new(p0, t0, p0 + chord, t1) else {
                refused += 1;
                continue;
            };
            match rrmf_quintics(&data, eta) {
                Ok(found) => {
                    for q in found {
                        quintic_rmf(&[q], vector()).unwrap();
                        quintic_curve(&[q]).unwrap();
                        solutions += 1;
                    }
                }
                Err(_) => refused += 1,
            }
        }
        println!("4,000 fuzzed data sets: {solutions} solutions with frames, {refused} refused");
        assert!(solutions > 1000);
    }
}
