//! What a CAD user checks before trusting a sweep (Mäurer & Jüttler §2.3): where it is
//! singular, where its Gaussian curvature changes sign, and how to start the frame so that a
//! convex profile gives an everywhere convex (or saddle-shaped) surface.
//!
//! For s = x(v) + c₂(u)f₂(v) + c₃(u)f₃(v) with an adapted frame, f·x' = 0 gives f'·x' = −f·x'',
//! so the part of s_v along the tangent is σg with
//!
//! ```text
//!   g(u, v) = 1 − c(u)·k(v),   k = (k₂, k₃) = (f₂·x'', f₃·x'') / |x'|²  (= κn in frame coordinates).
//! ```
//!
//! For an RMF s_v = σg t exactly (Proposition 1) and g = 1 − κ(c₂cos Ω − c₃sin Ω): the surface
//! is singular where g ≤ 0, condition (9) of Corollary 7, and ‖c‖ < 1/κ_max suffices. The
//! parameter lines being lines of curvature (Proposition 3), (13) becomes
//!
//! ```text
//!   K = −(ċ₂c̈₃ − c̈₂ċ₃) (ċ₃k₂ − ċ₂k₃) / (|ċ|⁴ g),
//! ```
//!
//! zero on the parabolic lines of §2.3: where the profile inflects (case 1), where the spine is
//! straight (case 2, k = 0), and where ċ₃k₂ − ċ₂k₃ = 0, i.e. ċ₃cos Ω + ċ₂sin Ω = 0 (14)
//! (case 3). With a tangent angle a(u) of the profile, K ∝ −a'(u) sin(a(u) + Ω(v)): a
//! convex profile (a monotone, turning by δ) gives K of one sign on the whole patch when a + Ω
//! stays in an interval of length π, which a choice of Ω₀ achieves iff δ + ΔΩ < π
//! (Corollary 9).

use super::base_frame::BaseFrame;
use super::exact_rmf::ExactRmf;
use super::frenet::frenet_numerators;
use super::parabolic::ParabolicCurve;
use super::profile::{critical_points, interior_roots, profile_segments, vanishes, ProfileSegment};
use super::spline::PhSpline;
use crate::bezier::bernstein::{derivative, product};
use crate::bezier::{locate, PiecewiseCurve};
use crate::error::no_solution;
use crate::error::Num;
use crate::error::{invalid, Error, Result};
use crate::frames::metrics::angle_about_tangent;
use crate::frames::rational::{RationalFrames, Turning};
use crate::frames::Frame;
use crate::math::minimize_bracketed;
use crate::mesh::grid_parameters;
use crate::model::FramedCurve;
use glam::{DVec2, DVec3};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Samples per frame piece when scanning along the spine.
const SAMPLES_PER_PIECE: usize = 32;

/// Most frame pieces × profile segments one analysis takes (2¹⁵, e.g. a 1,000-segment spine
/// with a 32-segment profile): the singularity margin scans every pair at 32 samples, about
/// 30 µs a pair, so this bounds a call to about a second (unbounded, one call of a random
/// program runs for over 15 minutes).
pub(crate) const MAX_ANALYSIS_PAIRS: usize = 1 << 15;

/// A sweep of a planar profile along a spine with rational frames, as analysed here.
pub struct ProfileSurface<'a> {
    spine: &'a PiecewiseCurve,
    frames: &'a RationalFrames,
    profile: &'a PiecewiseCurve,
    segments: Vec<ProfileSegment>,
    /// (A, B) = h²ċ of every segment, computed once: the scans along the spine use them at
    /// every sample.
    tangents: Vec<(Vec<f64>, Vec<f64>)>,
}

/// Where a sweep comes closest to being singular (Corollary 7).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SingularityMargin {
    /// min over the surface of g = 1 − κ(c₂cos Ω − c₃sin Ω) (dimensionless; ≤ 0: singular,
    /// the sweep folds over itself).
    pub margin: f64,
    /// Where the minimum is attained (profile parameter u, spine parameter v).
    pub u: f64,
    /// Spine parameter where the minimum is attained.
    pub v: f64,
    /// 1 − κ_max·max‖c‖: positive guarantees regularity (the sufficient condition of §2.3).
    pub bound_margin: f64,
}

/// Parabolic points of a profile surface (§2.3), where K changes sign.
#[derive(Clone, Debug, PartialEq)]
pub struct ParabolicLines {
    /// Case 1: profile inflections, lines u = const.
    pub profile_inflections: Vec<f64>,
    /// Case 1, degenerate: straight profile pieces [u0, u1] (parabolic everywhere).
    pub straight_profile: Vec<(f64, f64)>,
    /// Case 2: straight spine pieces [v0, v1] (parabolic everywhere).
    pub straight_spine: Vec<(f64, f64)>,
    /// Case 3: points (u, v) of the curves (14), at the sampled v.
    pub normal_condition: Vec<(f64, f64)>,
}

impl<'a> ProfileSurface<'a> {
    /// The sweep of `profile` along `spine` with `frames`. The frames must belong to the
    /// spine as for [`sweep`](crate::sweep::sweep) (its breakpoints or a refinement, and its
    /// tangent), and be rotation-minimizing (`Turning::RotationMinimizing`): the formulas
    /// of the module notes hold for an RMF only — for frames turning about the tangent at a
    /// rate ω the surface's s_v has the part ω(c₂f₃ − c₃f₂) across the spine, and g, K and
    /// (14) are other functions (the choice: refuse, rather than answer a question that was
    /// not asked).
    pub fn new(framed: &'a FramedCurve, profile: &'a PiecewiseCurve) -> Result<Self> {
        let (spine, frames) = (framed.curve(), framed.frames());
        match frames.turning() {
            Turning::RotationMinimizing => {}
            Turning::Twisted { total } => {
                return invalid!(
                    "frames are twisted against the rotation-minimizing frame (by {} rad): the \
                     profile-surface analysis (Mäurer & Jüttler §2.3) holds for RMF sweeps only",
                    Num(total)
                )
            }
            Turning::Unknown => {
                return invalid!(
                    "frames are not known to be rotation-minimizing (e.g. Frenet frames): the \
                     profile-surface analysis (Mäurer & Jüttler §2.3) holds for RMF sweeps only; \
                     use the frames of rmf_ph_rational_rmf, rmf_mobius_rrmf_* or rmf_rrmf_*"
                )
            }
        }
        let (pieces, profile_pieces) = (frames.segments().len(), profile.segments().len());
        if pieces.saturating_mul(profile_pieces) > MAX_ANALYSIS_PAIRS {
            return invalid!(
                "{pieces} frame pieces × {profile_pieces} profile segments are more than \
                 {MAX_ANALYSIS_PAIRS} pairs to analyse: split the sweep"
            );
        }
        Ok(Self::of_checked_frames(spine, frames, profile))
    }

    /// The sweep with any frames of the spine (orthonormal, f₁ the tangent), rotation
    /// minimizing or not, for its singularity margin only: s_u lies in the normal plane and
    /// the part of s_v along the tangent is |x′|·g whatever the frames' turn about the
    /// tangent, so g > 0 everywhere still guarantees a regular sweep (g ≤ 0 then no longer
    /// implies a fold: a sufficient test, as the wire sweeps use it).
    ///
    /// The profile's segments need not join (a wire sweep passes every loop's segments at
    /// once); the bound on the work is the caller's, who builds a face per pair anyway.
    pub(crate) fn with_adapted_frames(
        spine: &'a PiecewiseCurve,
        frames: &'a RationalFrames,
        profile: &'a PiecewiseCurve,
    ) -> Result<Self> {
        FramedCurve::check(spine, frames)?;
        Ok(Self::of_checked_frames(spine, frames, profile))
    }

    fn of_checked_frames(
        spine: &'a PiecewiseCurve,
        frames: &'a RationalFrames,
        profile: &'a PiecewiseCurve,
    ) -> Self {
        let segments = profile_segments(profile);
        let tangents = segments
            .iter()
            .map(ProfileSegment::scaled_tangent)
            .collect();
        Self {
            spine,
            frames,
            profile,
            segments,
            tangents,
        }
    }

    /// k(v): the spine's curvature vector in frame coordinates.
    fn curvature_vector(&self, v: f64) -> DVec2 {
        let jet = self.spine.eval_jet(v);
        in_frame(&self.frames.frame(v), jet.d2) / jet.d1.length_squared()
    }

    /// The unit direction of k(v), or `None` where k = 0: from k|x′|², without the division
    /// by |x′|², which under- or overflows at extreme scales.
    fn curvature_direction(&self, v: f64) -> Option<DVec2> {
        let k = in_frame(&self.frames.frame(v), self.spine.eval_jet(v).d2);
        crate::math::robust_normalize(k.extend(0.0)).map(|d| d.truncate())
    }

    /// The profile segment and local parameter of u.
    fn profile_at(&self, u: f64) -> (&ProfileSegment, f64) {
        let (k, s) = locate(self.profile.breaks(), u);
        (&self.segments[k], s)
    }

    /// g(u, v) (module notes): the tangential stretch of the sweep against its spine.
    pub fn stretch(&self, u: f64, v: f64) -> f64 {
        let (segment, s) = self.profile_at(u);
        1.0 - segment.jet(s).point.dot(self.curvature_vector(v))
    }

    /// The Gaussian curvature (13) at (u, v), in the form of the module notes.
    pub fn gaussian_curvature(&self, u: f64, v: f64) -> f64 {
        let (segment, s) = self.profile_at(u);
        let jet = segment.jet(s);
        let k = self.curvature_vector(v);
        let (d1, d2) = (jet.d1, jet.d2);
        let bend = d1.x * d2.y - d2.x * d1.y;
        let normal_part = d1.y * k.x - d1.x * k.y;
        let g = 1.0 - jet.point.dot(k);
        -bend * normal_part / (d1.length_squared().powi(2) * g)
    }

    /// The least g over the profile at the spine parameter v, with its u: the largest
    /// c(u)·k(v), at an end of a segment or where (A, B)·k = 0, (A, B) = h²ċ.
    fn least_stretch(&self, v: f64) -> (f64, f64) {
        let k = self.curvature_vector(v);
        let mut best = (f64::INFINITY, 0.0);
        for (i, (segment, (a, b))) in self.segments.iter().zip(&self.tangents).enumerate() {
            let along: Vec<f64> = a.iter().zip(b).map(|(a, b)| a * k.x + b * k.y).collect();
            let candidates = critical_points(&along);
            for s in candidates {
                let g = 1.0 - segment.point(s).dot(k);
                if g < best.0 {
                    best = (g, global(self.profile.breaks(), i, s));
                }
            }
        }
        best
    }

    /// The singularity margin of Corollary 7 with where it is attained, and the cheap bound.
    pub fn singularity_margin(&self) -> SingularityMargin {
        let (margin, u, v) = self.least_margin();
        SingularityMargin {
            margin,
            u,
            v,
            bound_margin: self.bound_margin(),
        }
    }

    /// The sufficient margin 1 − κ_max·max‖c‖ alone (positive: the sweep does not fold),
    /// which costs a curvature per sample instead of a root search per profile segment.
    pub(crate) fn bound_margin(&self) -> f64 {
        self.sampled_bound_margin(self.max_profile_radius())
    }

    /// 1 − κ_max·`reach`, κ_max sampled.
    fn sampled_bound_margin(&self, reach: f64) -> f64 {
        1.0 - self.max_spine_curvature() * reach
    }

    /// Whether the sufficient condition κ_max·max‖c‖ < 1 holds: first with κ_max bounded
    /// from the Bernstein coefficients of a polynomial spine (no evaluation), then as
    /// [`Self::bound_margin`] samples it.
    pub(crate) fn cannot_fold(&self) -> bool {
        let reach = self.max_profile_radius();
        let bounded = curvature_bound(self.spine).is_some_and(|k| k * reach < 1.0);
        bounded || self.sampled_bound_margin(reach) > 0.0
    }

    /// The margin of Corollary 7 alone, (g, u, v) where it is least: g sampled along the
    /// spine and refined about its least sample.
    pub(crate) fn least_margin(&self) -> (f64, f64, f64) {
        let samples = grid_parameters(self.frames.breaks(), SAMPLES_PER_PIECE);
        let (i, _) = samples
            .iter()
            .map(|&v| self.least_stretch(v).0)
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("samples");
        let (lo, hi) = neighbours(&samples, i);
        let refined = minimize_bracketed(|v| self.least_stretch(v).0, lo, hi, 0.0);
        let v = if self.least_stretch(samples[i]).0 <= refined.value {
            samples[i]
        } else {
            refined.x
        };
        let (margin, u) = self.least_stretch(v);
        (margin, u, v)
    }

    /// max ‖c(u)‖.
    fn max_profile_radius(&self) -> f64 {
        self.segments
            .iter()
            .map(ProfileSegment::max_radius)
            .fold(0.0, f64::max)
    }

    /// max κ of the spine, sampled and refined.
    fn max_spine_curvature(&self) -> f64 {
        let curvature = |v: f64| {
            let jet = self.spine.eval_jet(v);
            jet.d1.cross(jet.d2).length() / jet.d1.length().powi(3)
        };
        let samples = grid_parameters(self.frames.breaks(), SAMPLES_PER_PIECE);
        let (i, best) = samples
            .iter()
            .map(|&v| curvature(v))
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .expect("samples");
        let (lo, hi) = neighbours(&samples, i);
        best.max(-minimize_bracketed(|v| -curvature(v), lo, hi, 0.0).value)
    }

    /// The parabolic lines of §2.3, case 3 sampled at `v_samples` ≥ 2 uniform spine
    /// parameters.
    pub fn parabolic_lines(&self, v_samples: usize) -> ParabolicLines {
        let mut lines = ParabolicLines {
            profile_inflections: Vec::new(),
            straight_profile: Vec::new(),
            straight_spine: Vec::new(),
            normal_condition: Vec::new(),
        };
        let ub = self.profile.breaks();
        for (i, segment) in self.segments.iter().enumerate() {
            if self.is_straight_profile_segment(i) {
                lines.straight_profile.push((ub[i], ub[i + 1]));
            } else {
                lines.profile_inflections.extend(
                    interior_roots(&segment.normalized().curvature_numerator())
                        .into_iter()
                        .map(|s| global(ub, i, s)),
                );
            }
        }
        let sb = self.spine.breaks();
        for (k, segment) in self.spine.segments().iter().enumerate() {
            if is_straight(&segment.poles().collect::<Vec<_>>()) {
                lines.straight_spine.push((sb[k], sb[k + 1]));
            }
        }
        let (lo, hi) = self.spine.domain();
        for j in 0..v_samples.max(2) {
            let v = lo + (hi - lo) * j as f64 / (v_samples.max(2) - 1) as f64;
            let Some(k) = self.curvature_direction(v) else {
                continue;
            };
            if lines.straight_spine.iter().any(|&(a, b)| v >= a && v <= b) {
                continue;
            }
            for (i, (a, b)) in self.tangents.iter().enumerate() {
                let condition: Vec<f64> = a.iter().zip(b).map(|(a, b)| b * k.x - a * k.y).collect();
                let size = a.iter().chain(b).fold(0.0f64, |m, c| m.max(c.abs()));
                if vanishes(&condition, size) {
                    continue;
                }
                lines.normal_condition.extend(
                    interior_roots(&condition)
                        .into_iter()
                        .map(|s| (global(ub, i, s), v)),
                );
            }
        }
        lines
    }
}

impl<'a> ProfileSurface<'a> {
    /// The parabolic lines of §2.3, case 3, traced as curves: polylines (u, v) on the zero set
    /// of (14), continued along the spine, whose lift to the surface through their parameters
    /// stays within `tolerance` (a length) of the lines; besides, the lines v = const where
    /// the spine inflects (k = 0 satisfies (14) for every u). Fails with `NotConverged` when
    /// the lines would need more than [`MAX_PARABOLIC_POINTS`](super::parabolic::MAX_PARABOLIC_POINTS)
    /// points.
    pub fn parabolic_curves(&self, tolerance: f64) -> Result<Vec<ParabolicCurve>> {
        super::parabolic::trace(self, tolerance)
    }

    /// The surface point s(u, v) = x(v) + c₂(u)f₂(v) + c₃(u)f₃(v).
    pub fn point(&self, u: f64, v: f64) -> DVec3 {
        let (segment, s) = self.profile_at(u);
        let c = segment.jet(s).point;
        let f = self.frames.frame(v);
        self.spine.eval(v) + c.x * f.f2 + c.y * f.f3
    }

    /// |s(u₁, v) − s(u₂, v)| for any v: |c(u₁) − c(u₂)|, the frames being orthonormal (so
    /// neither the spine nor the frame is evaluated, nor rounded into the difference).
    pub(super) fn separation(&self, u1: f64, u2: f64) -> f64 {
        let point = |u: f64| {
            let (segment, s) = self.profile_at(u);
            segment.jet(s).point
        };
        crate::math::robust_length((point(u1) - point(u2)).extend(0.0))
    }

    pub(super) fn spine(&self) -> &PiecewiseCurve {
        self.spine
    }

    pub(super) fn frames(&self) -> &RationalFrames {
        self.frames
    }

    pub(super) fn profile(&self) -> &PiecewiseCurve {
        self.profile
    }

    pub(super) fn profile_segments(&self) -> &[ProfileSegment] {
        &self.segments
    }

    /// (A, B) = h²ċ of every profile segment.
    pub(super) fn tangents(&self) -> &[(Vec<f64>, Vec<f64>)] {
        &self.tangents
    }

    /// Whether profile segment i is straight (its curvature numerator vanishes).
    pub(super) fn is_straight_profile_segment(&self, i: usize) -> bool {
        let segment = self.segments[i].normalized();
        let numerator = segment.curvature_numerator();
        numerator.iter().all(|&c| c == 0.0) || vanishes(&numerator, segment_scale(&segment))
    }

    /// The spine segment under frame piece j.
    fn spine_segment_of_piece(&self, j: usize) -> usize {
        let fb = self.frames.breaks();
        self.spine.locate(0.5 * (fb[j] + fb[j + 1])).0
    }

    /// Whether the spine is straight under frame piece j (k = 0 there: case 2).
    pub(super) fn frame_piece_is_straight(&self, j: usize) -> bool {
        let k = self.spine_segment_of_piece(j);
        is_straight(&self.spine.segments()[k].poles().collect::<Vec<_>>())
    }

    /// k(v)·|x′|² on frame piece j, from that piece's frame and spine segment also at the
    /// piece's ends (k jumps at a joint of a C¹ spine): the direction of k without the
    /// division by |x′|², which under- or overflows at extreme scales.
    pub(super) fn piece_curvature_direction(&self, j: usize, v: f64) -> DVec2 {
        let (fb, sb) = (self.frames.breaks(), self.spine.breaks());
        let k = self.spine_segment_of_piece(j);
        let local = ((v - sb[k]) / (sb[k + 1] - sb[k])).clamp(0.0, 1.0);
        let d2 = self.spine.segments()[k].eval_jet(local).d2;
        let f =
            self.frames.segments()[j].frame(((v - fb[j]) / (fb[j + 1] - fb[j])).clamp(0.0, 1.0));
        in_frame(&f, d2)
    }
}

/// A vector of the normal plane in the coordinates (f₂, f₃) of a frame.
fn in_frame(f: &Frame, d: DVec3) -> DVec2 {
    DVec2::new(f.f2.dot(d), f.f3.dot(d))
}

/// Global parameter of the local parameter s on interval i of `breaks`.
pub(super) fn global(breaks: &[f64], i: usize, s: f64) -> f64 {
    breaks[i] + s * (breaks[i + 1] - breaks[i])
}

fn neighbours(samples: &[f64], i: usize) -> (f64, f64) {
    (
        samples[i.saturating_sub(1)],
        samples[(i + 1).min(samples.len() - 1)],
    )
}

/// A size for relative tests on the derived polynomials of a profile segment.
fn segment_scale(segment: &ProfileSegment) -> f64 {
    let m = |p: &[f64]| p.iter().fold(0.0f64, |a, c| a.max(c.abs()));
    let size = m(&segment.x).max(m(&segment.y)).max(1e-300);
    let h = m(&segment.h);
    (size * h).powi(2) * h
}

/// Control points on one line (relative tolerance 1e-12), in coordinates scaled to the
/// points' extent, so that the test does not underflow at extreme scales.
pub(super) fn is_straight(points: &[DVec3]) -> bool {
    let first = points[0];
    let size = points
        .iter()
        .fold(0.0f64, |m, p| m.max((*p - first).abs().max_element()));
    if size == 0.0 {
        return true;
    }
    let scaled: Vec<DVec3> = points.iter().map(|p| (*p - first) / size).collect();
    let axis = scaled[scaled.len() - 1];
    scaled
        .iter()
        .all(|p| p.cross(axis).length() <= 1e-12 * axis.length())
}

/// How to start the frame of a PH spline so that a convex profile sweeps a surface with
/// Gaussian curvature of one sign (Corollary 9).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvexStart {
    /// The initial normal to pass to the RMF construction.
    pub initial_normal: DVec3,
    /// π − δ − ΔΩ > 0: the slack of Corollary 9 (radians).
    pub margin: f64,
    /// δ, the turn of the profile's tangent, and ΔΩ, the spread of the RMF against the
    /// Frenet frame.
    pub profile_turn: f64,
    /// ΔΩ, the spread of the RMF angle against the Frenet frame along the spine (radians).
    pub rmf_spread: f64,
}

/// The initial normal that makes the RMF sweep of a convex `profile` along the PH spline
/// everywhere elliptic (K > 0; `elliptic = false`: hyperbolic, K < 0), Corollary 9: Ω₀ is
/// chosen so that a + Ω stays centred in the half-turn where K has the wanted sign. Fails
/// with `NoSolution` when the profile is not convex, δ + ΔΩ ≥ π, or a spine segment is
/// (nearly) straight (K = 0 there).
pub fn convex_initial_normal(
    spline: &PhSpline,
    profile: &PiecewiseCurve,
    elliptic: bool,
) -> Result<ConvexStart> {
    let (turn, a_start, a_end) = profile_turn(profile)?;
    let cubics = spline.cubics();
    let start = frenet_numerators(&cubics[0]).frame(0.0);
    let rmf = ExactRmf::new(spline, start.f2, 0.0)?;
    let mut arcs = Vec::with_capacity(cubics.len());
    for (k, cubic) in cubics.iter().enumerate() {
        let BaseFrame::Frenet { numerators, angle } = BaseFrame::of(cubic)? else {
            return no_solution!(
                "spine segment {k} is (nearly) straight: the Gaussian curvature vanishes there"
            );
        };
        let t = spline.breaks()[k];
        let omega0 = angle_about_tangent(&numerators.frame(0.0), &rmf.frame(t));
        arcs.push((omega0, angle.increment(1.0)));
    }
    let (spread, spread_start) = covering_arc(&arcs);
    if turn + spread >= PI {
        return no_solution!(
            "the profile turns by δ = {turn:.4} rad and the RMF by ΔΩ = {spread:.4} rad against the \
             Frenet frame: δ + ΔΩ ≥ π, no Ω₀ gives K of one sign (Corollary 9)"
        );
    }
    // K ∝ −a'·sin(a + Ω): centre a + Ω at ∓π/2.
    let direction = (a_end - a_start).signum();
    let target = if elliptic { -direction } else { direction } * FRAC_PI_2;
    let shift = target - (0.5 * (a_start + a_end) + spread_start + 0.5 * spread);
    let initial_normal = start.rotated(shift).f2;
    Ok(ConvexStart {
        initial_normal,
        margin: PI - turn - spread,
        profile_turn: turn,
        rmf_spread: spread,
    })
}

/// δ with the tangent angles at the ends (unwrapped), after checking that the profile is
/// convex: no inflection, and its tangent turning one way throughout.
fn profile_turn(profile: &PiecewiseCurve) -> Result<(f64, f64, f64)> {
    let mut angles: Vec<f64> = Vec::new();
    for (i, segment) in profile_segments(profile).iter().enumerate() {
        let numerator = segment.curvature_numerator();
        if let Some(&s) = interior_roots(&numerator).first() {
            return no_solution!(
                "the profile is not convex: it inflects at u = {}",
                global(profile.breaks(), i, s)
            );
        }
        for j in 0..=16 {
            let d = segment.jet(j as f64 / 16.0).d1;
            let a = d.y.atan2(d.x);
            let a = match angles.last() {
                Some(&previous) => previous + (a - previous - TAU * ((a - previous) / TAU).round()),
                None => a,
            };
            angles.push(a);
        }
    }
    let steps: Vec<f64> = angles.windows(2).map(|w| w[1] - w[0]).collect();
    if steps.iter().any(|&d| d > 1e-12) && steps.iter().any(|&d| d < -1e-12) {
        return Err(Error::no_solution(
            "the profile is not convex: its tangent turns both ways",
        ));
    }
    let (first, last) = (angles[0], angles[angles.len() - 1]);
    Ok(((last - first).abs(), first, last))
}

/// The shortest arc of the circle containing arcs [s, s + d] (d of either sign): its length
/// and start angle.
fn covering_arc(arcs: &[(f64, f64)]) -> (f64, f64) {
    let mut intervals: Vec<(f64, f64)> = arcs
        .iter()
        .map(|&(s, d)| {
            let lo = (s + d.min(0.0)).rem_euclid(TAU);
            (lo, lo + d.abs())
        })
        .collect();
    intervals.sort_by(|a, b| a.0.total_cmp(&b.0));
    // The largest gap between the end of the covered part so far and the next start,
    // going once around the circle.
    let mut reach = intervals[0].1;
    let mut best_gap = (0.0, intervals[0].0);
    for &(lo, hi) in &intervals[1..] {
        if lo - reach > best_gap.0 {
            best_gap = (lo - reach, lo);
        }
        reach = reach.max(hi);
    }
    let wrap = intervals[0].0 + TAU - reach;
    if wrap > best_gap.0 {
        best_gap = (wrap, intervals[0].0);
    }
    let (gap, start) = best_gap;
    ((TAU - gap).max(0.0), start)
}

/// An upper bound on the curvature |r′ × r″|/|r′|³ of a spine of polynomial segments: on
/// each, the largest coefficient of r′ × r″ over the smallest of |r′|² to the power 3/2 (the
/// Bernstein coefficients bound a polynomial from both sides); `None` for a rational
/// segment or one whose |r′|² has a coefficient ≤ 0.
fn curvature_bound(spine: &PiecewiseCurve) -> Option<f64> {
    let mut largest = 0.0f64;
    for segment in spine.segments() {
        if !segment.is_polynomial() || segment.degree() < 2 {
            return None;
        }
        let poles: Vec<DVec3> = segment.poles().collect();
        let d1 = derivative(&poles);
        let d2 = derivative(&d1);
        let cross = product(&d1, &d2, |a: DVec3, b: DVec3| a.cross(b));
        let speed = product(&d1, &d1, |a: DVec3, b: DVec3| a.dot(b));
        let slowest = speed.iter().copied().fold(f64::INFINITY, f64::min);
        if slowest.is_nan() || slowest <= 0.0 {
            return None;
        }
        let bend = cross.iter().map(|c| c.length()).fold(0.0, f64::max);
        largest = largest.max(bend / (slowest * slowest.sqrt()));
    }
    largest.is_finite().then_some(largest)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::RationalBezierCurve;
    use crate::frames::metrics::gaussian_curvature;
    use crate::ph_cubic::rational_rmf::{ph_rational_rmf, RmfOptions};
    use crate::ph_cubic::test_curves::{helix_spline, s_profile};
    use crate::sweep::sweep;

    fn arc_profile(radius: f64, center: DVec3) -> PiecewiseCurve {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let arc = RationalBezierCurve::from_weighted(
            &[
                center + DVec3::X * radius,
                center + DVec3::new(radius, radius, 0.0),
                center + DVec3::Y * radius,
            ],
            &[1.0, s, 1.0],
        )
        .unwrap();
        PiecewiseCurve::new(vec![arc], vec![0.0, 1.0]).unwrap()
    }

    #[test]
    fn the_curvature_bound_holds_the_sampled_curvature_and_decides_the_fold_check() {
        let spine = helix_spline(16, 0.15);
        let curve = spine.curve();
        let bound = curvature_bound(curve).unwrap();
        let (lo, hi) = curve.domain();
        let sampled = (0..=4000)
            .map(|i| curve.eval_jet(lo + (hi - lo) * i as f64 / 4000.0))
            .map(|j| j.d1.cross(j.d2).length() / j.d1.length().powi(3))
            .fold(0.0, f64::max);
        assert!(
            bound >= sampled && bound <= 1.5 * sampled,
            "{bound} vs {sampled}"
        );
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        // Within the bound's reach the check needs no sample; beyond the curvature radius
        // neither bound holds.
        let (near, far) = (
            arc_profile(0.6 / bound, DVec3::ZERO),
            arc_profile(1.2 / sampled, DVec3::ZERO),
        );
        assert!(ProfileSurface::new(&rmf.framed, &near)
            .unwrap()
            .cannot_fold());
        assert!(!ProfileSurface::new(&rmf.framed, &far)
            .unwrap()
            .cannot_fold());
        // A rational spine gets no bound (the sampled one serves).
        let arc = arc_profile(1.0, DVec3::ZERO);
        assert_eq!(curvature_bound(&arc), None);
    }

    #[test]
    fn analyses_beyond_the_pair_bound_are_refused() {
        let spine = helix_spline(2, 0.15);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let pieces = rmf.framed.frames().segments().len();
        let profile = arc_profile(0.3, DVec3::ZERO);
        let arc = profile.segments()[0].clone();
        let many = MAX_ANALYSIS_PAIRS / pieces + 1;
        let long = PiecewiseCurve::with_unit_intervals(vec![arc; many]).unwrap();
        let e = ProfileSurface::new(&rmf.framed, &long).err().unwrap();
        assert!(e.message().contains("pairs to analyse"), "{e}");
        assert!(ProfileSurface::new(&rmf.framed, &profile).is_ok());
    }

    #[test]
    fn curvature_formula_agrees_with_the_swept_surface() {
        let spine = helix_spline(16, 0.15);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = arc_profile(0.3, DVec3::new(0.1, -0.2, 0.0));
        let analysis = ProfileSurface::new(&rmf.framed, &profile).unwrap();
        let surface = sweep(&rmf.framed, &profile).unwrap();
        for &(u, v) in &[(0.2, 0.3), (0.5, 1.7), (0.9, 3.6), (0.4, 11.1)] {
            let jet = surface.eval_jet(u, v);
            let k = gaussian_curvature(&jet);
            // (13) is K of the exact profile surface; the rational sweep's K differs through
            // the error in the frame's angular velocity (2e-4 relative at the step 0.6, 2e-6
            // at 0.15).
            assert!(
                (analysis.gaussian_curvature(u, v) - k).abs() < 1e-5 * k.abs().max(1.0),
                "{u} {v}: {} vs {k}",
                analysis.gaussian_curvature(u, v)
            );
            let spine_jet = spine.eval_jet(v);
            let g = jet.dv.dot(spine_jet.d1) / spine_jet.d1.length_squared();
            assert!((analysis.stretch(u, v) - g).abs() < 1e-9);
        }
    }

    #[test]
    fn singularity_margin_finds_the_curvature_axis() {
        // Helix of curvature 1/1.16: a profile point at distance 1.16 along n reaches the axis.
        let spine = helix_spline(4, 0.6);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let small_profile = arc_profile(0.3, DVec3::ZERO);
        let small = ProfileSurface::new(&rmf.framed, &small_profile).unwrap();

        let m = small.singularity_margin();
        assert!(
            m.margin > 0.5 && m.bound_margin > 0.0 && m.bound_margin <= m.margin,
            "{m:?}"
        );
        let big_profile = arc_profile(2.0, DVec3::ZERO);
        let big = ProfileSurface::new(&rmf.framed, &big_profile).unwrap();
        let m = big.singularity_margin();
        assert!(m.margin < 0.0 && m.bound_margin < 0.0, "{m:?}");
        // The reported point is where the sweep's s_v has the smallest tangential part.
        let surface = sweep(&rmf.framed, &big_profile).unwrap();
        let scan = (0..=40)
            .flat_map(|i| (0..=40).map(move |j| (i as f64 / 40.0, 4.0 * j as f64 / 40.0)))
            .map(|(u, v)| {
                let d = spine.eval_jet(v).d1;
                surface.eval_jet(u, v).dv.dot(d) / d.length_squared()
            })
            .fold(f64::INFINITY, f64::min);
        assert!(
            m.margin <= scan + 1e-9 && m.margin > scan - 0.01,
            "{} vs {scan}",
            m.margin
        );
    }

    #[test]
    fn sampled_parabolic_lines_are_invariant_under_scaling() {
        let spine = helix_spline(4, 0.6);
        let profile = s_profile();
        let lines = |scale: f64| {
            let spine = spine.similar(scale, DVec3::ZERO).unwrap();
            let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
            let profile = profile.similar(scale, DVec3::ZERO);
            ProfileSurface::new(&rmf.framed, &profile)
                .unwrap()
                .parabolic_lines(9)
        };
        let reference = lines(1.0);
        assert!(!reference.normal_condition.is_empty());
        for scale in [1e-200, 1e200] {
            let scaled = lines(scale);
            assert_eq!(
                scaled.normal_condition.len(),
                reference.normal_condition.len()
            );
            for (a, b) in scaled
                .normal_condition
                .iter()
                .zip(&reference.normal_condition)
            {
                assert!(
                    (a.0 - b.0).abs() < 1e-9 && a.1 == b.1,
                    "scale {scale:e}: {a:?} vs {b:?}"
                );
            }
            assert_eq!(scaled.profile_inflections.len(), 1);
        }
    }

    #[test]
    fn parabolic_lines_are_where_the_curvature_changes_sign() {
        let spine = helix_spline(4, 0.6);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        // An S-shaped cubic profile: one inflection at u = 1/2, curves (14) besides.
        let profile = s_profile();
        let analysis = ProfileSurface::new(&rmf.framed, &profile).unwrap();
        let lines = analysis.parabolic_lines(9);
        assert_eq!(lines.profile_inflections.len(), 1);
        assert!((lines.profile_inflections[0] - 0.5).abs() < 1e-12);
        assert!(!lines.normal_condition.is_empty());
        for &(u, v) in lines.normal_condition.iter().chain(
            lines
                .profile_inflections
                .iter()
                .map(|u| (*u, 1.3))
                .collect::<Vec<_>>()
                .iter(),
        ) {
            let (before, after) = (
                analysis.gaussian_curvature(u - 1e-4, v),
                analysis.gaussian_curvature(u + 1e-4, v),
            );
            assert!(before * after < 0.0, "K changes sign across ({u}, {v})");
        }
        assert!(lines.straight_spine.is_empty() && lines.straight_profile.is_empty());
    }

    #[test]
    fn corollary_9_makes_a_convex_patch_elliptic_or_hyperbolic() {
        let spine = helix_spline(2, 0.5);
        let profile = arc_profile(0.2, DVec3::ZERO);
        for elliptic in [true, false] {
            let start = convex_initial_normal(&spine, &profile, elliptic).unwrap();
            assert!((start.profile_turn - FRAC_PI_2).abs() < 1e-12);
            assert!(start.margin > 0.0);
            let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(start.initial_normal)).unwrap();
            let surface = sweep(&rmf.framed, &profile).unwrap();
            for i in 0..=20 {
                for j in 0..=20 {
                    let k = gaussian_curvature(
                        &surface.eval_jet(i as f64 / 20.0, 2.0 * j as f64 / 20.0),
                    );
                    assert!(if elliptic { k > 0.0 } else { k < 0.0 }, "K = {k}");
                }
            }
        }
        // A profile turning by more than π cannot be helped.
        let half = RationalBezierCurve::from_weighted(
            &[
                DVec3::X,
                DVec3::new(1.0, 2.0, 0.0),
                DVec3::new(-1.0, 2.0, 0.0),
                -DVec3::X,
            ],
            &[1.0, 1.0 / 3.0, 1.0 / 3.0, 1.0],
        )
        .unwrap();
        let wide = PiecewiseCurve::new(vec![half], vec![0.0, 1.0]).unwrap();
        assert!(convex_initial_normal(&spine, &wide, true)
            .is_err_and(|e| e.is(crate::ErrorKind::NoSolution)));
    }

    #[test]
    fn covering_arcs_on_the_circle() {
        let (len, start) = covering_arc(&[(0.1, 0.2), (0.5, -0.1)]);
        assert!((len - 0.4).abs() < 1e-15 && (start - 0.1).abs() < 1e-15);

        let (len, start) = covering_arc(&[(6.2, 0.2), (0.3, 0.1)]);
        assert!((len - (0.4 + TAU - 6.2)).abs() < 1e-12 && (start - 6.2).abs() < 1e-12);
    }

    /// Issue finding: the three analyses accepted frames built on another spine with the
    /// same breakpoints and answered (rmf_sweep_surface refuses them: "tangent differs").
    #[test]
    fn frames_of_another_spine_are_refused() {
        let spine = helix_spline(4, 0.6);
        let other = helix_spline(4, 0.5);
        assert_eq!(spine.breaks(), other.breaks());
        let rmf = ph_rational_rmf(&other, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = arc_profile(0.3, DVec3::ZERO);
        let e = FramedCurve::new(spine.curve().clone(), rmf.framed.frames().clone()).unwrap_err();
        assert!(e.message().contains("tangent differs"), "{e}");
        // The analysis of a spine with frames held apart checks them too.
        let e = ProfileSurface::with_adapted_frames(&spine, rmf.framed.frames(), &profile)
            .err()
            .unwrap();
        assert!(e.message().contains("tangent differs"), "{e}");
    }

    /// Issue finding (paper gaps): the analyses assume an RMF but answered for Frenet and
    /// twisted frames, with values that hold only for an RMF sweep. They refuse them.
    #[test]
    fn frames_that_are_not_rotation_minimizing_are_refused() {
        let spine = helix_spline(4, 0.6);
        let profile = arc_profile(0.3, DVec3::ZERO);
        let frenet = crate::ph_cubic::frenet::ph_frenet_frames(&spine).unwrap();
        let e = ProfileSurface::new(&frenet, &profile).err().unwrap();
        assert!(
            e.message().contains("not known to be rotation-minimizing"),
            "{e}"
        );
        let options = RmfOptions {
            twist: 0.3,
            ..RmfOptions::rmf(DVec3::Z)
        };
        let twisted = ph_rational_rmf(&spine, &options).unwrap();
        let e = ProfileSurface::new(&twisted.framed, &profile)
            .err()
            .unwrap();
        assert!(
            e.message().contains("twisted") && e.message().contains("0.3 rad"),
            "{e}"
        );
        // The RMF of the same spine is analysed; the Frenet sweep's curvature is not (13).
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        assert!(ProfileSurface::new(&rmf.framed, &profile).is_ok());
    }
}
