//! Rational RMFs of PH cubic splines, Mäurer & Jüttler §3.3–3.5: on every segment the base
//! frame (the Frenet frame (19)) turned by 2 arctan W(v), equation (29), with W the
//! biquadratic of (36)–(40) approximating w = tan(Ω/2) of (33); the segments are joined
//! continuously from the caller's initial normal (the Ω₀ are chained). Frames are of degree
//! 2(n + 1) = 6, so the sweep (42) of a profile of degree m is a rational surface of degree
//! (m, 9) per segment (`sweep::sweep`).
//!
//! Per segment the target angle is centred, W approximating tan((Ω − Ω_mid)/2) with Ω_mid
//! the mean of its end values: |W| stays ≤ tan(π/8) because a segment whose angle turns by
//! more than π/2 is split (never for the segments of a reasonable spline; (32) bounds the
//! turn by 2π). The sub-pieces, and the pieces into which positive weights split a
//! denominator, refine the spline's breakpoints, which the frames and sweeps allow.
//!
//! Closed spines and twist. The RMF of a closed spine does not close: after one loop it is
//! turned by the holonomy Δ. The frame is therefore turned, on top of the RMF, by φ(s) =
//! φ·s/S, s the arc length (a polynomial for PH curves) and S the total, with
//! φ = twist − Δ reduced modulo 2π/k (k the symmetry order of the profile: a square needs
//! only a quarter turn), so that a closed sweep has no seam; with no closure φ = twist. A
//! uniform twist rate is the smallest one that achieves the closure. The turn enters the
//! Hermite data (34) of W on each segment (Ω' becomes Ω' + (φ/S)σ), so the result is still
//! rational and still exact at every joint; where the rate Ω' + (φ/S)σ changes sign inside a
//! segment, the segment is split there so that each W is monotone.

#[cfg(test)]
use super::base_frame::BaseFrame;
use super::base_frame::FramePieces;
use super::biquadratic::{fit, AngleHermite, BiquadraticFit};
#[cfg(test)]
use super::cubic::PhCubic;
use super::exact_rmf::{ExactRmf, SegmentTarget};
use super::spline::PhSpline;
use crate::bezier::PiecewiseCurve;
use crate::error::ResultExt;
use crate::error::{invalid, Result};
use crate::frames::rational::{g1_tolerance, Turning};
use crate::math::{check_finite, largest_coordinate};
use crate::model::FramedCurve;
use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, PI};

/// Largest turn of the target angle on one W (see the module notes).
const MAX_PIECE_TURN: f64 = FRAC_PI_2;

/// Most pieces of one segment for [`MAX_PIECE_TURN`]: the RMF itself turns by less than 2π
/// on a segment (32), so it needs a few (more where the speed nearly vanishes and the turn
/// concentrates); only an absurd twist needs more.
const MAX_PIECES: usize = 4096;

/// Deepest halving (pieces shorter than 2⁻⁴⁰ of a segment are not split further).
const MAX_HALVINGS: usize = 40;

/// Relative distance between the end and the start of a spine below which it is closed.
const CLOSED_TOLERANCE: f64 = 1e-9;

/// How the frame is set up along the spine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RmfOptions {
    /// Projected onto the normal plane at the start and normalized: f₂ there.
    pub initial_normal: DVec3,
    /// Total turn about the tangent added along the spine, in radians, distributed
    /// linearly in arc length (0 for the RMF).
    pub twist: f64,
    /// For a closed spine: close the frame up to a turn by a multiple of 2π/k, k ≥ 1 the
    /// symmetry order of the profile (1: any profile, 4: a square). `None`: open spine.
    pub closure_symmetry: Option<u32>,
}

impl RmfOptions {
    /// The rotation-minimizing frame, started at `initial_normal`.
    pub fn rmf(initial_normal: DVec3) -> Self {
        Self {
            initial_normal,
            twist: 0.0,
            closure_symmetry: None,
        }
    }
}

/// How one W was chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PieceFit {
    /// Spline segment and the part [v0, v1] of it that the W covers.
    pub segment: usize,
    pub v0: f64,
    pub v1: f64,
    /// The minimizing λ of (37) and Î(λ) of (41); `None` where the target angle is
    /// constant (a planar segment without twist: the frame is the Frenet frame turned).
    pub lambda: Option<f64>,
    pub objective: f64,
}

/// Rational frames along a PH cubic spline with how they were made.
#[derive(Clone, Debug)]
pub struct RationalRmf {
    /// The spline with its rational frames.
    pub framed: FramedCurve,
    /// How each segment's rational approximation was fitted.
    pub pieces: Vec<PieceFit>,
    /// The turn φ added to the RMF from start to end (twist and closure), radians.
    pub total_twist: f64,
}

/// The rational (approximate) RMF of a PH cubic spline (every segment a PH cubic, G1
/// joints), with the twist and closure of `options`.
pub fn ph_rational_rmf(spline: &PhSpline, options: &RmfOptions) -> Result<RationalRmf> {
    let initial_normal = check_finite(options.initial_normal, "initial_normal")?;
    let rmf = ExactRmf::new(spline, initial_normal, 0.0)?;
    let total_twist = added_turn(spline, &rmf, options)?;
    let target = if total_twist == 0.0 {
        rmf
    } else {
        ExactRmf::new(spline, initial_normal, total_twist / rmf.total_length())?
    };
    let mut pieces = FramePieces::new(spline.breaks());
    let mut fits = Vec::new();
    for k in 0..target.segment_count() {
        let segment = target.segment_target(k);
        let context = || format!("ph_spline segment {k}");
        for (v0, v1) in monotone_pieces(&segment).with_context(context)? {
            let (numerators, fit) = piece_frame(&segment, v0, v1).with_context(context)?;
            pieces.push_all(k, v0, v1, numerators.positive_pieces()?);
            fits.push(PieceFit {
                segment: k,
                v0,
                v1,
                lambda: fit.map(|f| f.w.lambda()),
                objective: fit.map_or(0.0, |f| f.objective),
            });
        }
    }
    let turning = if total_twist == 0.0 {
        Turning::RotationMinimizing
    } else {
        Turning::Twisted { total: total_twist }
    };
    let frames = pieces
        .into_chained_frames(initial_normal, g1_tolerance(spline))?
        .with_turning(turning);
    Ok(RationalRmf {
        framed: FramedCurve::of_construction(spline.curve().clone(), frames),
        pieces: fits,
        total_twist,
    })
}

/// φ of the module notes: the caller's twist, plus for a closed spine the smallest turn
/// (modulo 2π/k) that cancels the holonomy.
fn added_turn(spline: &PiecewiseCurve, rmf: &ExactRmf, options: &RmfOptions) -> Result<f64> {
    if !options.twist.is_finite() {
        return invalid!("twist = {} must be finite", options.twist);
    }
    let Some(symmetry) = options.closure_symmetry else {
        return Ok(options.twist);
    };
    if symmetry == 0 {
        return invalid!("closure_symmetry must be at least 1 for a closed spine");
    }
    check_closed(spline)?;
    let holonomy = rmf.end_rotation();
    let period = 2.0 * PI / symmetry as f64;
    let correction = -holonomy - period * (-holonomy / period).round();
    Ok(options.twist + correction)
}

/// A closed spine ends where it starts, with the same tangent.
fn check_closed(spline: &PiecewiseCurve) -> Result<()> {
    let (lo, hi) = spline.domain();
    let (start, end) = (spline.eval_jet(lo), spline.eval_jet(hi));
    let size =
        largest_coordinate(spline.segments().iter().flat_map(|s| s.poles())).max(f64::MIN_POSITIVE);
    if (end.point - start.point).length() > CLOSED_TOLERANCE * size {
        return invalid!(
            "closure needs a closed spline, but it ends at {} and starts at {}",
            end.point,
            start.point
        );
    }
    if (end.d1.normalize() - start.d1.normalize()).length() > CLOSED_TOLERANCE {
        return invalid!(
            "closure needs a closed G1 spline, but its end tangent differs from its start tangent"
        );
    }
    Ok(())
}

/// [0, 1] split where the target angle turns back, then halved until no piece turns by
/// more than [`MAX_PIECE_TURN`]. A piece between two turning points is halved as well: with
/// zero slopes at both ends the family (37) shrinks to β₁ = 0, far less flexible.
fn monotone_pieces(segment: &SegmentTarget) -> Result<Vec<(f64, f64)>> {
    let turning = segment.turning_points();
    let mut cuts = vec![0.0];
    for w in turning.windows(2) {
        cuts.extend([w[0], 0.5 * (w[0] + w[1])]);
    }
    cuts.extend(turning.last());
    cuts.push(1.0);
    let mut pieces = Vec::new();
    for w in cuts.windows(2) {
        halve_while_turning(segment, w[0], w[1], 0, &mut pieces)?;
    }
    Ok(pieces)
}

fn halve_while_turning(
    segment: &SegmentTarget,
    a: f64,
    b: f64,
    depth: usize,
    out: &mut Vec<(f64, f64)>,
) -> Result<()> {
    if (segment.angle(b) - segment.angle(a)).abs() <= MAX_PIECE_TURN || depth == MAX_HALVINGS {
        out.push((a, b));
        return Ok(());
    }
    if out.len() >= MAX_PIECES {
        return invalid!(
            "the frame would need more than {MAX_PIECES} rational pieces on this segment to turn              by at most π/2 on each: the twist is too large for this spline"
        );
    }
    let mid = 0.5 * (a + b);
    halve_while_turning(segment, a, mid, depth + 1, out)?;
    halve_while_turning(segment, mid, b, depth + 1, out)
}

/// The frame numerators on the part [v0, v1] of a segment: its base frame turned by
/// 2 arctan W (29), W fitted to the centred target angle; the base frame itself where the
/// target is constant. Also the fit, if any.
fn piece_frame(
    segment: &SegmentTarget,
    v0: f64,
    v1: f64,
) -> Result<(super::base_frame::FrameNumerators, Option<BiquadraticFit>)> {
    // The base numerators on the piece, borrowed when the piece is the whole segment.
    let base = segment.base().numerators();
    let restricted = (v0 != 0.0 || v1 != 1.0).then(|| base.restricted(v0, v1));
    let numerators = restricted.as_ref().unwrap_or(base);
    let (g0, g1) = (segment.angle(v0), segment.angle(v1));
    let length = v1 - v0;
    let rate = |u: f64| segment.rate(v0 + u * length) * length;
    if g0 == g1 && rate(0.0) == 0.0 && rate(1.0) == 0.0 {
        return Ok((restricted.unwrap_or_else(|| base.clone()), None));
    }
    let half_turn = 0.25 * (g1 - g0);
    let (w0, w1) = (-half_turn.tan(), half_turn.tan());
    let slope = |w: f64, r: f64| 0.5 * (1.0 + w * w) * r;
    let data = AngleHermite {
        w0,
        w1,
        s0: slope(w0, rate(0.0)),
        s1: slope(w1, rate(1.0)),
    };
    let fitted = fit(data, rate)?;
    let turned = numerators.turned(&fitted.w.numerator, &fitted.w.denominator);
    Ok((turned, Some(fitted)))
}

#[cfg(test)]
/// The paper's setting for one PH cubic (§3.4, Figures 5 and 6): W approximating
/// tan(Ω(v)/2) on all of [0, 1], with Ω(0) = `omega0` against the Frenet frame (π/2 starts f₂
/// at the binormal, as in Figure 5). The frame does not depend on `omega0` (turning w maps
/// the family (37) onto itself), λ does. Fails for a (nearly) straight cubic, which has no
/// Frenet frame to start from, and when Ω reaches ±π (w has a pole).
pub(crate) fn cubic_rmf_fit(cubic: &PhCubic, omega0: f64) -> Result<BiquadraticFit> {
    let BaseFrame::Frenet { angle, .. } = BaseFrame::of(cubic)? else {
        return invalid!("the cubic is (nearly) straight: its Frenet frame is undefined");
    };
    let omega = |v: f64| omega0 + angle.increment(v);
    if !(omega(0.0).abs() < PI && omega(1.0).abs() < PI) {
        return invalid!(
            "Ω runs from {} to {}: tan(Ω/2) has a pole; choose omega0 in (−π, π) accordingly",
            omega(0.0),
            omega(1.0)
        );
    }
    let w = |v: f64| (0.5 * omega(v)).tan();
    let slope = |v: f64| 0.5 * (1.0 + w(v).powi(2)) * angle.rate(v);
    let data = AngleHermite {
        w0: w(0.0),
        w1: w(1.0),
        s0: slope(0.0),
        s1: slope(1.0),
    };
    fit(data, |v| angle.rate(v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::metrics::{angle_about_tangent, orthonormality_error};
    use crate::ph_cubic::ph_spline_hermite;
    use crate::ph_cubic::test_curves::helix_spline;
    use crate::testing::{gap_to_double_reflection, helix};

    fn max_error(spline: &PiecewiseCurve, rmf: &RationalRmf, exact: &ExactRmf) -> f64 {
        let (lo, hi) = spline.domain();
        (0..=2000)
            .map(|i| lo + (hi - lo) * i as f64 / 2000.0)
            .map(|t| angle_about_tangent(&exact.frame(t), &rmf.framed.frames().frame(t)).abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn approximates_the_exact_rmf_with_order_five() {
        let error = |n: usize| {
            let spline = helix_spline(n, 4.8 / n as f64);
            let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
            max_error(
                &spline,
                &rmf,
                &ExactRmf::new(&spline, DVec3::Z, 0.0).unwrap(),
            )
        };
        let (coarse, fine) = (error(8), error(16));
        assert!(fine < 1e-7, "{fine}");
        assert!((coarse / fine).log2() > 4.5, "{coarse} → {fine}");
    }

    /// Bends between 1e-6 and 5e-4 per segment (a helix of radius 200 sampled at chords of
    /// 0.2): Frenet base frames from (19) taken literally are off by ε/sin²θ (enough for the
    /// RMF to be "not G1", and 5e-9 from orthonormal at sin θ = 2e-3), and the carried frame
    /// drifts 8e-9 rad from the RMF at 8e-4. With the Frenet frame from the quaternion
    /// preimage and the carried frame only below sin θ = 1e-4, every radius and pitch gives
    /// frames orthonormal to rounding and within 1e-10 rad of the double-reflection RMF.
    #[test]
    fn gently_bending_splines_have_accurate_frames() {
        for radius in [5.0, 40.0, 200.0, 2e3, 2e4, 2e5] {
            for pitch in [0.3, 3.0] {
                let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=8)
                    .map(|i| {
                        let (t, a) = (0.2 * i as f64, 0.2 * i as f64 / radius);
                        (
                            DVec3::new(radius * a.sin(), radius * (1.0 - a.cos()), pitch * t),
                            DVec3::new(a.cos(), a.sin(), pitch),
                        )
                    })
                    .unzip();
                let spline = ph_spline_hermite(&points, &tangents).unwrap();
                let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
                for t in [0.0, 0.5, 3.3, 8.0] {
                    let error = orthonormality_error(&rmf.framed.frames().frame(t));
                    assert!(error < 1e-14, "radius {radius}, pitch {pitch}: {error:e}");
                }
                // Frenet side: ε/sin θ; carried side: θ³ (`frenet::NEARLY_STRAIGHT`).
                let gap = gap_to_double_reflection(&spline, DVec3::Z, 8001, |t| {
                    rmf.framed.frames().frame(t)
                });
                assert!(gap < 1e-10, "radius {radius}, pitch {pitch}: {gap:e}");
            }
        }
    }

    #[test]
    fn frames_are_orthonormal_of_degree_six_and_exact_at_joints() {
        let spline = helix_spline(8, 0.6);
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let exact = ExactRmf::new(&spline, DVec3::Z, 0.0).unwrap();
        assert!(rmf
            .framed
            .frames()
            .segments()
            .iter()
            .all(|s| s.degree() == 6));
        for t in [0.0, 0.5, 3.0, 7.9] {
            assert!(orthonormality_error(&rmf.framed.frames().frame(t)) < 1e-14);
        }
        // Exact at every joint.
        for k in 0..=8 {
            let t = k as f64;
            let a = angle_about_tangent(&exact.frame(t), &rmf.framed.frames().frame(t));
            assert!(a.abs() < 1e-13, "joint {k}: {a}");
        }
    }

    #[test]
    fn frames_turn_exactly_like_the_rmf_at_the_joints() {
        // W interpolates w and w' at both ends (34): at every joint, on both sides, the frame
        // has the RMF's value and no turn about the tangent (f₂'·f₃ = 0), while inside a
        // segment it turns a little. With the G1 spline this makes sweeps G1 (Proposition 5).
        let spline = helix_spline(4, 0.8);
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
        // The turn f₂'·f₃ relative to how fast the frame moves: the larger of |f₂'| and
        // |f₃'|, which the curvature keeps from 0 (|f₂'| alone vanishes where f₂ is the
        // binormal, as at the start of this helix with the initial normal on its axis).
        let turn = |piece: usize, s: f64| {
            let p = &rmf.framed.frames().segments()[piece];
            let (_, d2) = p.f2_with_derivative(s);
            let (_, d3) = p.rotated(std::f64::consts::FRAC_PI_2).f2_with_derivative(s);
            d2.dot(p.frame(s).f3).abs() / d2.length().max(d3.length())
        };
        let pieces = rmf.framed.frames().segments().len();
        for piece in 0..pieces {
            assert!(
                turn(piece, 0.0) < 1e-12 && turn(piece, 1.0) < 1e-12,
                "piece {piece}: {:e} {:e}",
                turn(piece, 0.0),
                turn(piece, 1.0)
            );
        }
        assert!((0..pieces).any(|p| turn(p, 0.3) > 1e-9));
    }

    #[test]
    fn sharp_turns_and_both_torsion_signs_keep_positive_weights() {
        // A coarse spline of a helix with opposite pitch: fewer, sharper segments.
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=4)
            .map(|i| {
                let (p, t) = helix(1.4 * i as f64, -0.3);
                (p, t)
            })
            .unzip();
        let spline = ph_spline_hermite(&points, &tangents).unwrap();
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::X)).unwrap();
        assert!(rmf
            .framed
            .frames()
            .segments()
            .iter()
            .all(|s| s.denominator().iter().all(|&d| d > 0.0)));
        let exact = ExactRmf::new(&spline, DVec3::X, 0.0).unwrap();
        assert!(max_error(&spline, &rmf, &exact) < 1e-4);
    }

    #[test]
    fn straight_and_nearly_straight_segments_carry_the_frame() {
        // (t, s³, s³/2) with s = max(t − 1, 0): a straight start, then a curve leaving it with
        // zero curvature (nearly straight segments), sampled every 0.25.
        let curve = |t: f64| {
            let s = (t - 1.0).max(0.0);
            (
                DVec3::new(t, s.powi(3), 0.5 * s.powi(3)),
                DVec3::new(1.0, 3.0 * s * s, 1.5 * s * s),
            )
        };
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) =
            (0..=12).map(|i| curve(0.25 * i as f64)).unzip();
        let spline = ph_spline_hermite(&points, &tangents).unwrap();
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Y)).unwrap();
        let worst =
            gap_to_double_reflection(&spline, DVec3::Y, 20001, |t| rmf.framed.frames().frame(t));
        assert!(worst < 1e-8, "{worst}");
        // On the straight part (spline parameters [0, 4]) the frame does not move at all.
        for t in [0.5, 2.0, 3.9] {
            assert!(
                (rmf.framed.frames().frame(t).f2 - DVec3::Y).length() < 1e-15,
                "t = {t}"
            );
        }
        let bends: Vec<f64> = crate::ph_cubic::ph_cubics(&spline)
            .unwrap()
            .iter()
            .map(|c| c.bend())
            .collect();
        assert!(bends[..4].iter().all(|&b| b == 0.0) && bends[4] > 0.0);
        // A gentle helix (radius of curvature 2e6): every segment nearly straight (carried
        // frames), still the RMF.
        let r = 1e6;
        let gentle = |t: f64| {
            let s = (t / (2.0 * r)).sin();
            (
                DVec3::new(-2.0 * r * s * s, r * (t / r).sin(), t),
                DVec3::new(-(t / r).sin(), (t / r).cos(), 1.0),
            )
        };
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) =
            (0..=4).map(|i| gentle(i as f64)).unzip();
        let spline = ph_spline_hermite(&points, &tangents).unwrap();
        let cubics = crate::ph_cubic::ph_cubics(&spline).unwrap();
        assert!(cubics
            .iter()
            .all(|c| c.bend() > 0.0 && c.bend() < super::super::frenet::NEARLY_STRAIGHT));
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::X)).unwrap();
        let worst =
            gap_to_double_reflection(&spline, DVec3::X, 4001, |t| rmf.framed.frames().frame(t));
        assert!(worst < 1e-12, "{worst}");
    }

    #[test]
    fn any_scale_gives_the_same_frames() {
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) =
            (0..=6).map(|i| helix(0.5 * i as f64, 0.4)).unzip();
        let unit = ph_rational_rmf(
            &ph_spline_hermite(&points, &tangents).unwrap(),
            &RmfOptions::rmf(DVec3::Z),
        )
        .unwrap();
        // Powers of two scale exactly: the frames must agree to round-off. Decimal scales
        // round the data (relative ε); λ, found by Brent's method to about √ε, then moves
        // and with it W inside a segment, by up to about 1e-12 (never at the joints).
        for (scale, tolerance) in [
            (2f64.powi(-500), 1e-15),
            (2f64.powi(500), 1e-15),
            (1e-150, 1e-11),
            (1e150, 1e-11),
        ] {
            let scaled: Vec<DVec3> = points.iter().map(|&p| p * scale).collect();
            let spline = ph_spline_hermite(&scaled, &tangents).unwrap();
            let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
            for i in 0..=60 {
                let t = 0.1 * i as f64;
                let (a, b) = (unit.framed.frames().frame(t), rmf.framed.frames().frame(t));
                assert!(
                    (a.f2 - b.f2).length() < tolerance,
                    "scale {scale:e}, t = {t}: {:e}",
                    (a.f2 - b.f2).length()
                );
            }
        }
    }

    #[test]
    fn planar_splines_get_the_exact_rmf() {
        let (points, tangents) = crate::testing::planar_hermite_data();
        let spline = ph_spline_hermite(&points, &tangents).unwrap();
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
        assert!(rmf.pieces.iter().all(|p| p.lambda.is_none()));
        for i in 0..=20 {
            let f = rmf.framed.frames().frame(0.1 * i as f64);
            assert!((f.f2 - DVec3::Z).length() < 1e-14 || (f.f2 + DVec3::Z).length() < 1e-14);
        }
    }

    #[test]
    fn closed_spines_close_with_the_smallest_turn() {
        // A trefoil knot, (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t): its RMF comes back
        // turned by about −2.22 rad.
        let n = 24;
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=n)
            .map(|i| {
                let t = if i == n {
                    0.0
                } else {
                    2.0 * PI * i as f64 / n as f64
                };
                (
                    DVec3::new(
                        t.sin() + 2.0 * (2.0 * t).sin(),
                        t.cos() - 2.0 * (2.0 * t).cos(),
                        -(3.0 * t).sin(),
                    ),
                    DVec3::new(
                        t.cos() + 4.0 * (2.0 * t).cos(),
                        -t.sin() + 4.0 * (2.0 * t).sin(),
                        -3.0 * (3.0 * t).cos(),
                    ),
                )
            })
            .unzip();
        let spline = ph_spline_hermite(&points, &tangents).unwrap();
        let holonomy = ExactRmf::new(&spline, DVec3::Z, 0.0)
            .unwrap()
            .end_rotation();
        assert!((holonomy + 2.22).abs() < 0.01, "{holonomy}");
        for k in [1u32, 4] {
            let options = RmfOptions {
                closure_symmetry: Some(k),
                ..RmfOptions::rmf(DVec3::Z)
            };
            let rmf = ph_rational_rmf(&spline, &options).unwrap();
            let (start, end) = (
                rmf.framed.frames().frame(0.0),
                rmf.framed.frames().frame(n as f64),
            );
            let gap = angle_about_tangent(&start, &end);
            let period = 2.0 * PI / k as f64;
            let off = gap - period * (gap / period).round();
            assert!(off.abs() < 1e-12, "k = {k}: {gap}");
            assert!(rmf.total_twist.abs() <= period / 2.0 + 1e-12);
        }
        // With a caller twist of one full turn the frame closes after turning once more.
        let options = RmfOptions {
            twist: 2.0 * PI,
            closure_symmetry: Some(1),
            ..RmfOptions::rmf(DVec3::Z)
        };
        let rmf = ph_rational_rmf(&spline, &options).unwrap();
        assert!((rmf.total_twist - 2.0 * PI + holonomy).abs() < 1e-9);
        let exact = ExactRmf::new(
            &spline,
            DVec3::Z,
            rmf.total_twist
                / ExactRmf::new(&spline, DVec3::Z, 0.0)
                    .unwrap()
                    .total_length(),
        )
        .unwrap();
        // Where the twist rate crosses the torsion, a W runs into a turning point of the
        // angle with zero slope; those pieces are followed less closely (2e-5 rad here, against
        // 2e-6 for the untwisted RMF of the same spline).
        let e = max_error(&spline, &rmf, &exact);
        assert!(e < 1e-4, "{e}");
    }

    #[test]
    fn twist_against_the_torsion_splits_segments_at_turning_points() {
        let spline = helix_spline(3, 1.0);
        // The RMF of the helix turns against its Frenet frame at −τ = −0.4/1.16 rad per unit
        // length; a twist at the rate τ cancels it on average, and reverses it where the
        // torsion of the PH cubics dips below τ.
        let length = ExactRmf::new(&spline, DVec3::Z, 0.0)
            .unwrap()
            .total_length();
        let options = RmfOptions {
            twist: 0.4 / 1.16 * length,
            ..RmfOptions::rmf(DVec3::Z)
        };
        let rmf = ph_rational_rmf(&spline, &options).unwrap();
        assert!(rmf.pieces.len() > 3, "turning points split the segments");
        let exact = ExactRmf::new(&spline, DVec3::Z, options.twist / length).unwrap();
        let e = max_error(&spline, &rmf, &exact);
        assert!(e < 1e-5, "{e}");
    }

    #[test]
    fn one_cubic_in_the_setting_of_the_paper() {
        // The example cubic's RMF turns by 2.22 rad against its Frenet frame.
        let c = crate::ph_cubic::test_curves::example_cubic();
        let a = cubic_rmf_fit(&c, -0.5).unwrap();
        let b = cubic_rmf_fit(&c, 0.0).unwrap();
        assert!(a.objective < 1e-2 && (a.objective - b.objective).abs() < 1e-9 * a.objective);
        assert!((a.w.lambda() - b.w.lambda()).abs() > 1e-3);
        assert!((a.w.eval(0.0) - (-0.25f64).tan()).abs() < 1e-15);
        assert!(cubic_rmf_fit(&c, FRAC_PI_2).is_err(), "Ω would pass π");
    }

    #[test]
    fn rejects_bad_options() {
        let spline = helix_spline(3, 0.5);
        let open = RmfOptions {
            closure_symmetry: Some(1),
            ..RmfOptions::rmf(DVec3::Z)
        };
        let e = ph_rational_rmf(&spline, &open).unwrap_err();
        assert!(e.message().contains("closed"), "{e}");
        let nan = RmfOptions {
            twist: f64::NAN,
            ..RmfOptions::rmf(DVec3::Z)
        };
        assert!(ph_rational_rmf(&spline, &nan).is_err());
        let (_, t0) = helix(0.0, 0.4);
        let e = ph_rational_rmf(&spline, &RmfOptions::rmf(t0)).unwrap_err();
        assert!(e.message().contains("initial_normal"));
        let absurd = RmfOptions {
            twist: 1e9,
            ..RmfOptions::rmf(DVec3::Z)
        };
        let e = ph_rational_rmf(&spline, &absurd).unwrap_err();
        assert!(e.message().contains("twist is too large"), "{e}");
    }

    /// Issue finding (translation): a helix spline of legs 0.18 moved by (1e6, −2e6, 3e6) was
    /// refused as "not G1" — its tangents, differences of control points rounded to ε·4e6,
    /// are known to 1e-9 only, the G1 tolerance of the joints. The tolerance now follows the
    /// rounding of the control points.
    #[test]
    fn a_spline_far_from_the_origin_is_g1_to_its_rounding() {
        let offset = DVec3::new(1e6, -2e6, 3e6);
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..9)
            .map(|i| {
                let (p, t) = crate::testing::helix(0.5 * i as f64, 0.4);
                (p + offset, t)
            })
            .unzip();
        let spline = crate::ph_cubic::ph_spline_hermite(&points, &tangents).unwrap();
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let near = helix_spline(8, 0.5);
        let reference = ph_rational_rmf(&near, &RmfOptions::rmf(DVec3::Z)).unwrap();
        for i in 0..=80 {
            let t = 0.1 * i as f64;
            let (a, b) = (
                rmf.framed.frames().frame(t),
                reference.framed.frames().frame(t),
            );
            assert!(
                (a.f2 - b.f2).length() < 1e-8,
                "t = {t}: {:e}",
                (a.f2 - b.f2).length()
            );
        }
    }
}
