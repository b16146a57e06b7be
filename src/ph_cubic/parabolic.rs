//! The parabolic lines of case 3 of Mäurer & Jüttler §2.3 traced as curves: the zero set of
//! (14), F = ċ₃(u)k₂(v) − ċ₂(u)k₃(v) = 0, where the profile's tangent ċ is parallel to the
//! spine's curvature vector k = (k₂, k₃) in frame coordinates (module notes of
//! [`analysis`](super::analysis)).
//!
//! Every profile segment is cut where it inflects and where its tangent is parallel to an
//! axis, so that on each sub-piece the tangent angle a(u) is monotone and stays within a
//! quadrant. For fixed v, (14) says a(u) ≡ φ(v) mod π (φ the direction of k), so a sub-piece
//! holds at most one root: there the line is the graph of a function u(v), defined exactly
//! where F (with (A, B) = h²ċ in place of ċ) has opposite signs at the sub-piece's two ends.
//! The v where that changes are the roots of F at the ends, found with every sign change of
//! the samples bracketed ([`sampled_roots`]); in between, u(v) is the bracketed root of
//! F(·, v), sampled until the lifted polyline is within the tolerance on the surface. Graphs
//! that meet where one sub-piece hands over to the next (the line running on, or folding
//! back at an inflection) are joined into one polyline.
//!
//! (14) depends only on the direction of k mod π, and k changes sign where the spine
//! inflects (κ = 0): k is used as a unit vector oriented to turn continuously, and where it
//! vanishes the whole line v = const satisfies (14) and is returned as a curve of its own.

use super::analysis::{global, ProfileSurface};
use super::profile::interior_roots;
use crate::bezier::bernstein;
use crate::error::{check_resolution, invalid, Error, Num, Result};
use crate::math::{
    illinois_root, interior_midpoint, minimize_bracketed, robust_length, robust_normalize,
    sampled_roots,
};
use glam::DVec2;
use std::convert::Infallible;

/// Spine samples per frame piece before refinement (as for the singularity margin).
const SAMPLES: usize = 32;

/// The direction of k may turn by at most this between neighbouring samples (cos 30°), so that
/// orienting it by the previous sample cannot be fooled.
const MIN_TURN_COSINE: f64 = 0.866;

/// Halvings of a spine sample interval while resolving the direction of k.
const MAX_DIRECTION_HALVINGS: usize = 30;

/// Most polyline points one call returns.
pub const MAX_PARABOLIC_POINTS: usize = 1 << 20;

/// A trace estimated to need more than [`MAX_PARABOLIC_POINTS`] is refused before it is
/// refined. The estimate, √(d/τ) points for a spine sample interval whose line is d from the
/// chord at its middle (d shrinks with the square of the interval), is what halving reaches
/// on a line of constant curvature; halving makes powers of two, so the trace takes up to
/// twice as many. It overestimates only where the line turns within a small part of an
/// interval, hence the margin.
const ESTIMATE_MARGIN: f64 = 2.0;

/// |k| below this fraction of its largest value on the frame piece counts as k = 0.
const VANISHING_CURVATURE: f64 = 1e-9;

/// A parabolic line of case 3 of §2.3 as a polyline in the parameter plane: points (u, v) on
/// the line, in order; the polyline mapped onto the surface through its parameters stays
/// within the tolerance of the line (checked at the middle of every polyline segment).
#[derive(Clone, Debug, PartialEq)]
pub struct ParabolicCurve {
    /// (profile parameter u, spine parameter v) of each point.
    pub points: Vec<(f64, f64)>,
}

/// A piece of profile segment `segment` on [s0, s1] (local parameters) on which the tangent
/// angle is monotone within a quadrant; (A, B) = h²ċ at both ends.
struct SubPiece {
    segment: usize,
    s0: f64,
    s1: f64,
    ends: [DVec2; 2],
    /// Whether a root at s1 is this piece's: no piece goes on from s1 with the same tangent
    /// (otherwise it is the next piece's root at its s0).
    closed_right: bool,
}

/// The unit curvature direction on one frame piece: samples with their oriented directions.
struct Direction {
    vs: Vec<f64>,
    dirs: Vec<DVec2>,
}

/// The parabolic lines (14) of `surface`, within `tolerance` (a length on the surface).
pub(crate) fn trace(surface: &ProfileSurface<'_>, tolerance: f64) -> Result<Vec<ParabolicCurve>> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return invalid!("tolerance = {} must be finite and positive", Num(tolerance));
    }
    let largest = surface
        .profile()
        .segments()
        .iter()
        .flat_map(|s| s.poles())
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    check_resolution(tolerance, largest, "the profile's")?;
    let graphs = Tracer::new(surface, tolerance).all_graphs()?;
    Ok(join(graphs, surface, tolerance))
}

/// The sub-pieces of every curved profile segment (straight ones are parabolic throughout,
/// case 1, and have no line (14) of their own).
fn sub_pieces(surface: &ProfileSurface<'_>) -> Vec<SubPiece> {
    let mut pieces = Vec::new();
    for (i, (segment, (a, b))) in surface
        .profile_segments()
        .iter()
        .zip(surface.tangents())
        .enumerate()
    {
        if surface.is_straight_profile_segment(i) {
            continue;
        }
        let mut cuts = vec![0.0, 1.0];
        cuts.extend(interior_roots(&segment.normalized().curvature_numerator()));
        for p in [a, b] {
            if !p.iter().all(|&c| c == 0.0) {
                cuts.extend(interior_roots(p));
            }
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|x, y| (*x - *y).abs() <= 1e-12);
        for w in cuts.windows(2) {
            let end = |s: f64| DVec2::new(bernstein::evaluate(a, s), bernstein::evaluate(b, s));
            pieces.push(SubPiece {
                segment: i,
                s0: w[0],
                s1: w[1],
                ends: [end(w[0]), end(w[1])],
                closed_right: true,
            });
        }
    }
    let ub = surface.profile().breaks();
    let at = |p: &SubPiece, s: f64| global(ub, p.segment, s);
    for n in 1..pieces.len() {
        let (left, right) = (&pieces[n - 1], &pieces[n]);
        let (t, next) = (left.ends[1], right.ends[0]);
        let continues = at(left, left.s1) == at(right, right.s0)
            && match (unit(t), unit(next)) {
                (Some(t), Some(next)) => t.dot(next) > 0.0 && t.perp_dot(next).abs() <= 1e-9,
                _ => false,
            };
        pieces[n - 1].closed_right = !continues;
    }
    pieces
}

/// F of the module notes for the tangent (A, B) and the unit direction k̂.
fn condition(tangent: DVec2, k: DVec2) -> f64 {
    tangent.y * k.x - tangent.x * k.y
}

/// F at an end of a sub-piece, 0 where it is at the rounding of its terms (the line (14)
/// running along the end, as for a planar spine, where k̂ is constant).
fn end_condition(tangent: DVec2, k: DVec2) -> f64 {
    let f = condition(tangent, k);
    if f.abs() <= 1e-12 * norm(tangent) {
        0.0
    } else {
        f
    }
}

/// Whether the sub-piece holds a root of F(·, v) given F at its ends: a sign change, or a
/// root at an end that is the piece's own.
fn holds_root(piece: &SubPiece, [f0, f1]: [f64; 2]) -> bool {
    f0 == 0.0 || (f1 == 0.0 && piece.closed_right) || opposite(f0, f1)
}

/// Whether a and b are non-zero of opposite signs (their product underflows at extreme
/// scales).
fn opposite(a: f64, b: f64) -> bool {
    a != 0.0 && b != 0.0 && (a < 0.0) != (b < 0.0)
}

struct Tracer<'s, 'a> {
    surface: &'s ProfileSurface<'a>,
    tolerance: f64,
    points: usize,
}

/// A line of the trace before refinement: done (a line v = const), or a graph at the spine
/// samples of frame piece `directions[frame]` on sub-piece `piece`.
enum Planned {
    Done(ParabolicCurve),
    Coarse {
        frame: usize,
        piece: usize,
        points: Vec<(f64, f64)>,
    },
}

impl<'s, 'a> Tracer<'s, 'a> {
    fn new(surface: &'s ProfileSurface<'a>, tolerance: f64) -> Self {
        Tracer {
            surface,
            tolerance,
            points: 0,
        }
    }

    /// The graphs on every curved sub-piece over every curved frame piece, and the lines
    /// where the spine inflects, not yet joined: first every graph at the spine samples,
    /// then, if the estimate of the points they need is within bounds, refined.
    fn all_graphs(&mut self) -> Result<Vec<ParabolicCurve>> {
        let pieces = sub_pieces(self.surface);
        let fb = self.surface.frames().breaks();
        let mut directions = Vec::new();
        let mut planned = Vec::new();
        for j in 0..fb.len() - 1 {
            if self.surface.frame_piece_is_straight(j) {
                continue;
            }
            let direction = self.direction(j)?;
            for line in self.spine_inflections(j, &direction)? {
                planned.push(Planned::Done(line));
            }
            for (p, piece) in pieces.iter().enumerate() {
                for (v0, v1) in self.runs(j, &direction, piece) {
                    let points = self.coarse(j, &direction, piece, v0, v1);
                    planned.push(Planned::Coarse {
                        frame: directions.len(),
                        piece: p,
                        points,
                    });
                }
            }
            directions.push((j, direction));
        }
        self.check_estimate(&planned, &directions, &pieces)?;
        let mut graphs = Vec::with_capacity(planned.len());
        for line in planned {
            graphs.push(match line {
                Planned::Done(line) => line,
                Planned::Coarse {
                    frame,
                    piece,
                    points,
                } => {
                    let (j, direction) = &directions[frame];
                    self.refined(*j, direction, &pieces[piece], &points)?
                }
            });
        }
        Ok(graphs)
    }

    /// Refuses a trace estimated to need more than [`MAX_PARABOLIC_POINTS`] (see
    /// [`ESTIMATE_MARGIN`]).
    fn check_estimate(
        &self,
        planned: &[Planned],
        directions: &[(usize, Direction)],
        pieces: &[SubPiece],
    ) -> Result<()> {
        let mut estimate = 0.0;
        for line in planned {
            let Planned::Coarse {
                frame,
                piece,
                points,
            } = line
            else {
                continue;
            };
            let (j, direction) = &directions[*frame];
            for w in points.windows(2) {
                let Some(v) = interior_midpoint(w[0].1, w[1].1) else {
                    continue;
                };
                let middle = self.root(*j, direction, &pieces[*piece], v);
                let off = self.surface.separation(middle, 0.5 * (w[0].0 + w[1].0));
                estimate += (off / (0.5 * self.tolerance)).sqrt().ceil().max(1.0);
            }
        }
        if estimate > ESTIMATE_MARGIN * MAX_PARABOLIC_POINTS as f64 {
            return Err(self.too_many());
        }
        Ok(())
    }

    /// Samples of the curvature direction on frame piece j, refined until neighbouring
    /// directions differ by less than 30°, oriented to turn continuously.
    fn direction(&self, j: usize) -> Result<Direction> {
        let fb = self.surface.frames().breaks();
        let (va, vb) = (fb[j], fb[j + 1]);
        let raw = |v: f64| self.surface.piece_curvature_direction(j, v);
        let mut vs = vec![va];
        let mut dirs = vec![unit(raw(va)).unwrap_or(DVec2::X)];
        for n in 1..=SAMPLES {
            let target = crate::math::lerp(va, vb, n as f64 / SAMPLES as f64);
            self.resolve(&raw, &mut vs, &mut dirs, target, 0)?;
        }
        Ok(Direction { vs, dirs })
    }

    /// Appends the samples up to `target` to the oriented directions, halving where the
    /// direction turns too fast.
    fn resolve(
        &self,
        raw: &impl Fn(f64) -> DVec2,
        vs: &mut Vec<f64>,
        dirs: &mut Vec<DVec2>,
        target: f64,
        depth: usize,
    ) -> Result<()> {
        let (last_v, last) = (
            *vs.last().expect("a sample"),
            *dirs.last().expect("a sample"),
        );
        let next = unit(raw(target)).map(|d| if d.dot(last) < 0.0 { -d } else { d });
        let smooth = next.is_none_or(|d| d.dot(last) >= MIN_TURN_COSINE);
        if !smooth {
            let Some(mid) =
                interior_midpoint(last_v, target).filter(|_| depth < MAX_DIRECTION_HALVINGS)
            else {
                return Err(Error::not_converged(format!(
                    "the spine's curvature direction turns faster than it can be followed near \
                     v = {}",
                    Num(target)
                )));
            };
            self.resolve(raw, vs, dirs, mid, depth + 1)?;
            return self.resolve(raw, vs, dirs, target, depth + 1);
        }
        vs.push(target);
        dirs.push(next.unwrap_or(last));
        Ok(())
    }

    /// The oriented unit direction of k at v on frame piece j (the previous sample's where
    /// k = 0).
    fn oriented(&self, j: usize, direction: &Direction, v: f64) -> DVec2 {
        let n = direction
            .vs
            .partition_point(|&x| x <= v)
            .clamp(1, direction.vs.len())
            - 1;
        let reference = direction.dirs[n];
        match unit(self.surface.piece_curvature_direction(j, v)) {
            Some(d) if d.dot(reference) < 0.0 => -d,
            Some(d) => d,
            None => reference,
        }
    }

    /// The lines v = const where k vanishes on frame piece j (the spine inflects): the
    /// orientation flips there.
    fn spine_inflections(
        &mut self,
        j: usize,
        direction: &Direction,
    ) -> Result<Vec<ParabolicCurve>> {
        let (vs, dirs) = (&direction.vs, &direction.dirs);
        let raw = |v: f64| self.surface.piece_curvature_direction(j, v);
        let largest = vs.iter().map(|&v| norm(raw(v))).fold(0.0, f64::max);
        let mut lines = Vec::new();
        for n in 0..vs.len() - 1 {
            let (a, b) = (vs[n], vs[n + 1]);
            let along = |v: f64| raw(v).dot(dirs[n]);
            let (fa, fb) = (along(a), along(b));
            if !opposite(fa, fb) {
                continue;
            }
            let Some(v0) =
                illinois_root(along, (a, fa), (b, fb), 1e-15 * (b - a).abs().max(a.abs()))
            else {
                continue;
            };
            let m = minimize_bracketed(|v| norm(raw(v)), a, b, 0.0);
            let at_root = norm(raw(v0));
            let (v0, size) = if m.value < at_root {
                (m.x, m.value)
            } else {
                (v0, at_root)
            };
            if size <= VANISHING_CURVATURE * largest {
                let ub = self.surface.profile().breaks();
                self.count(ub.len())?;
                lines.push(ParabolicCurve {
                    points: ub.iter().map(|&u| (u, v0)).collect(),
                });
            }
        }
        Ok(lines)
    }

    /// The intervals of v where the line (14) has a graph u(v) on one sub-piece of the
    /// profile over frame piece j: the runs between roots of F at the piece's ends where the
    /// piece holds a root.
    fn runs(&self, j: usize, direction: &Direction, piece: &SubPiece) -> Vec<(f64, f64)> {
        let end_value =
            |e: usize, v: f64| end_condition(piece.ends[e], self.oriented(j, direction, v));
        let (va, vb) = (direction.vs[0], *direction.vs.last().expect("samples"));
        let tol = 1e-15 * (vb - va).abs().max(va.abs().max(vb.abs()));
        let mut splits = vec![va, vb];
        for e in 0..2 {
            let Ok(roots) = sampled_roots(
                |v| Ok::<f64, Infallible>(end_value(e, v)),
                &direction.vs,
                0.0,
                tol,
            );
            splits.extend(roots);
        }
        splits.sort_by(f64::total_cmp);
        splits.dedup_by(|x, y| (*x - *y).abs() <= tol);
        // Runs of intervals holding a root: the root is continuous across their splits.
        let mut runs: Vec<(f64, f64)> = Vec::new();
        for w in splits.windows(2) {
            let Some(mid) = interior_midpoint(w[0], w[1]) else {
                continue;
            };
            if !holds_root(piece, [0, 1].map(|e| end_value(e, mid))) {
                continue;
            }
            match runs.last_mut() {
                Some(run) if run.1 == w[0] => run.1 = w[1],
                _ => runs.push((w[0], w[1])),
            }
        }
        runs
    }

    /// The root of F(·, v) on the sub-piece as a global profile parameter: at an end where F
    /// vanishes there, bracketed inside, or at the end where F is closer to 0 (a graph's
    /// ends, where the root leaves the piece).
    fn root(&self, j: usize, direction: &Direction, piece: &SubPiece, v: f64) -> f64 {
        let k = self.oriented(j, direction, v);
        let (a, b) = &self.surface.tangents()[piece.segment];
        let f = |s: f64| {
            condition(
                DVec2::new(bernstein::evaluate(a, s), bernstein::evaluate(b, s)),
                k,
            )
        };
        let [e0, e1] = [0, 1].map(|e| end_condition(piece.ends[e], k));
        let s = if e0 == 0.0 {
            piece.s0
        } else if e1 == 0.0 {
            piece.s1
        } else if !opposite(e0, e1) {
            if e0.abs() <= e1.abs() {
                piece.s0
            } else {
                piece.s1
            }
        } else {
            illinois_root(f, (piece.s0, e0), (piece.s1, e1), 1e-15).unwrap_or(piece.s0)
        };
        global(self.surface.profile().breaks(), piece.segment, s)
    }

    /// The graph on [v0, v1] at the spine samples inside.
    fn coarse(
        &self,
        j: usize,
        direction: &Direction,
        piece: &SubPiece,
        v0: f64,
        v1: f64,
    ) -> Vec<(f64, f64)> {
        let mut vs = vec![v0];
        vs.extend(direction.vs.iter().copied().filter(|&v| v > v0 && v < v1));
        vs.push(v1);
        vs.into_iter()
            .map(|v| (self.root(j, direction, piece, v), v))
            .collect()
    }

    /// The graph through the `coarse` points, halved where the polyline's middle is farther
    /// than the tolerance from the line.
    fn refined(
        &mut self,
        j: usize,
        direction: &Direction,
        piece: &SubPiece,
        coarse: &[(f64, f64)],
    ) -> Result<ParabolicCurve> {
        let mut points = vec![coarse[0]];
        for w in coarse.windows(2) {
            self.refine(j, direction, piece, w[0], w[1], &mut points, 0)?;
        }
        Ok(ParabolicCurve { points })
    }

    /// Appends the points after `left` up to `right`, halving until the middle is met.
    #[allow(clippy::too_many_arguments)]
    fn refine(
        &mut self,
        j: usize,
        direction: &Direction,
        piece: &SubPiece,
        left: (f64, f64),
        right: (f64, f64),
        points: &mut Vec<(f64, f64)>,
        depth: usize,
    ) -> Result<()> {
        if let Some(v) = interior_midpoint(left.1, right.1) {
            let middle = (self.root(j, direction, piece, v), v);
            let off = self.surface.separation(middle.0, 0.5 * (left.0 + right.0));
            // Half the tolerance at the middle keeps the whole segment within it.
            if off > 0.5 * self.tolerance {
                if depth >= 60 {
                    return Err(Error::not_converged(format!(
                        "the parabolic line near (u, v) = ({}, {}) does not meet the tolerance",
                        Num(middle.0),
                        Num(v)
                    )));
                }
                self.refine(j, direction, piece, left, middle, points, depth + 1)?;
                return self.refine(j, direction, piece, middle, right, points, depth + 1);
            }
        }
        self.count(1)?;
        points.push(right);
        Ok(())
    }

    /// Counts points against [`MAX_PARABOLIC_POINTS`].
    fn count(&mut self, more: usize) -> Result<()> {
        self.points += more;
        if self.points > MAX_PARABOLIC_POINTS {
            return Err(self.too_many());
        }
        Ok(())
    }

    fn too_many(&self) -> Error {
        Error::not_converged(format!(
            "the parabolic lines need more than {MAX_PARABOLIC_POINTS} points at tolerance {}: \
             use a larger tolerance or split the sweep",
            Num(self.tolerance)
        ))
    }
}

/// |k| without under- or overflow (the curvature numerators scale with the square of the
/// spine's size).
fn norm(k: DVec2) -> f64 {
    robust_length(k.extend(0.0))
}

fn unit(k: DVec2) -> Option<DVec2> {
    robust_normalize(k.extend(0.0)).map(|d| d.truncate())
}

/// The graphs joined where their ends meet: at the same v, at the same u (a hand-over
/// between sub-pieces or frame pieces) or within the tolerance on the surface (the small
/// jump of k at a joint of a C¹ spine).
fn join(
    mut graphs: Vec<ParabolicCurve>,
    surface: &ProfileSurface<'_>,
    tolerance: f64,
) -> Vec<ParabolicCurve> {
    let (u0, u1) = surface.profile().domain();
    let (v0, v1) = surface.spine().domain();
    let (eu, ev) = (1e-9 * (u1 - u0), 1e-9 * (v1 - v0));
    let meets = |a: (f64, f64), b: (f64, f64)| {
        (a.1 - b.1).abs() <= ev
            && ((a.0 - b.0).abs() <= eu
                || robust_length(surface.point(a.0, a.1) - surface.point(b.0, b.1)) <= tolerance)
    };
    // Ends sorted by v: a match lies among the neighbours within ev.
    let mut ends: Vec<(f64, usize, bool)> = Vec::with_capacity(2 * graphs.len());
    for (i, g) in graphs.iter().enumerate() {
        ends.push((g.points[0].1, i, false));
        ends.push((g.points[g.points.len() - 1].1, i, true));
    }
    ends.sort_by(|a, b| a.0.total_cmp(&b.0));
    let end_point = |g: &ParabolicCurve, last: bool| {
        if last {
            g.points[g.points.len() - 1]
        } else {
            g.points[0]
        }
    };
    let mut partner: Vec<[Option<(usize, bool)>; 2]> = vec![[None, None]; graphs.len()];
    for (n, &(v, i, last)) in ends.iter().enumerate() {
        if partner[i][last as usize].is_some() {
            continue;
        }
        for &(w, k, other) in &ends[n + 1..] {
            if w - v > ev {
                break;
            }
            if k == i || partner[k][other as usize].is_some() {
                continue;
            }
            if meets(end_point(&graphs[i], last), end_point(&graphs[k], other)) {
                partner[i][last as usize] = Some((k, other));
                partner[k][other as usize] = Some((i, last));
                break;
            }
        }
    }
    let mut used = vec![false; graphs.len()];
    let mut curves = Vec::new();
    // Open chains first (from a free end), then closed loops.
    let starts: Vec<usize> = (0..graphs.len())
        .filter(|&i| partner[i][0].is_none() || partner[i][1].is_none())
        .chain(0..graphs.len())
        .collect();
    for start in starts {
        if used[start] {
            continue;
        }
        let mut points: Vec<(f64, f64)> = Vec::new();
        // Walk out of the free end (the first end when both or neither are free).
        let (mut i, mut forward) = (
            start,
            partner[start][0].is_none() || partner[start][1].is_some(),
        );
        loop {
            used[i] = true;
            let mut piece = std::mem::take(&mut graphs[i].points);
            if !forward {
                piece.reverse();
            }
            let skip = usize::from(!points.is_empty());
            points.extend(piece.into_iter().skip(skip));
            match partner[i][forward as usize] {
                Some((k, entered_at_last)) if !used[k] => {
                    (i, forward) = (k, !entered_at_last);
                }
                Some(_) => {
                    // A closed loop: end where it started.
                    if let Some(&first) = points.first() {
                        points.push(first);
                    }
                    break;
                }
                None => break,
            }
        }
        curves.push(ParabolicCurve { points });
    }
    curves
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::bernstein::product;
    use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
    use crate::frames::metrics::gaussian_curvature;
    use crate::frames::rational::{RationalFrameSegment, RationalFrames, Turning};
    use crate::model::FramedCurve;
    use crate::ph_cubic::rational_rmf::{ph_rational_rmf, RmfOptions};
    use crate::ph_cubic::spline::PhSpline;
    use crate::ph_cubic::test_curves::{helix_spline, s_profile};
    use crate::sweep::sweep;
    use glam::DVec3;

    /// A circle of `radius` about `centre` from four quarter arcs, starting at the angle
    /// `start`: u ∈ [0, 4], angle start + uπ/2.
    fn circle(radius: f64, centre: DVec3, start: f64) -> PiecewiseCurve {
        let (sin, cos) = start.sin_cos();
        let (x, y) = (DVec3::new(cos, sin, 0.0), DVec3::new(-sin, cos, 0.0));
        crate::primitives::circle(centre, x, y, radius).unwrap()
    }

    /// The Gaussian curvature of the exported sweep at (u, v) (its own fundamental forms).
    fn exported_curvature(surface: &crate::bezier::PiecewiseSurface, u: f64, v: f64) -> f64 {
        gaussian_curvature(&surface.eval_jet(u, v))
    }

    /// Every vertex, on the exported surface: (14) in its geometric form, the surface normal
    /// perpendicular to the spine's principal normal, and K changing sign across the polyline.
    /// Returns the largest |n·p| and the largest |K| at a vertex relative to the largest |K|
    /// on the surface (not 0 where the frames only approximate the RMF, for which (13) and
    /// (14) hold).
    fn check_vertices(
        curves: &[ParabolicCurve],
        surface: &crate::bezier::PiecewiseSurface,
        (u0, u1): (f64, f64),
        spine: &PiecewiseCurve,
    ) -> (f64, f64) {
        let (v0, v1) = spine.domain();
        // K jumps at a joint of a C¹ spine, and so does the line: vertices there are one
        // side's.
        let at_joint = |v: f64| spine.breaks().iter().any(|&b| (b - v).abs() < 1e-12);
        let mut largest: f64 = 0.0;
        for i in 0..=40 {
            for j in 0..=40 {
                let (u, v) = (
                    u0 + (u1 - u0) * i as f64 / 40.0,
                    v0 + (v1 - v0) * j as f64 / 40.0,
                );
                largest = largest.max(exported_curvature(surface, u, v).abs());
            }
        }
        let mut normal: f64 = 0.0;
        let mut worst: f64 = 0.0;
        for curve in curves {
            let p = &curve.points;
            for n in 0..p.len() {
                let (u, v) = p[n];
                if at_joint(v) {
                    continue;
                }
                worst = worst.max(exported_curvature(surface, u, v).abs() / largest);
                let jet = surface.eval_jet(u, v);
                let spine_jet = spine.eval_jet(v);
                let t = spine_jet.d1.normalize();
                let principal = (spine_jet.d2 - t * t.dot(spine_jet.d2)).normalize();
                // A line v = const is where the spine inflects: no principal normal there.
                if !p.iter().all(|q| q.1 == p[0].1) {
                    normal = normal.max(jet.du.cross(jet.dv).normalize().dot(principal).abs());
                }
                let (a, b) = (p[n.saturating_sub(1)], p[(n + 1).min(p.len() - 1)]);
                let (du, dv) = ((b.0 - a.0) / (u1 - u0), (b.1 - a.1) / (v1 - v0));
                let length = du.hypot(dv);
                let (nu, nv) = (
                    -dv / length * 1e-4 * (u1 - u0),
                    du / length * 1e-4 * (v1 - v0),
                );
                let inside = |u: f64, v: f64| u > u0 && u < u1 && v > v0 && v < v1;
                if inside(u + nu, v + nv) && inside(u - nu, v - nv) {
                    let (k1, k2) = (
                        exported_curvature(surface, u + nu, v + nv),
                        exported_curvature(surface, u - nu, v - nv),
                    );
                    // Where the line meets a profile inflection (K = 0 along u = const, case
                    // 1) K stays at the rounding on both sides.
                    let flat = k1.abs().max(k2.abs()) < 1e-8 * largest;
                    assert!(
                        flat || k1 * k2 < 0.0,
                        "K = {k1}, {k2} on both sides of ({u}, {v})"
                    );
                }
            }
        }
        (normal, worst)
    }

    /// The crossings of the polylines with the line v = const, as u.
    fn crossings(curves: &[ParabolicCurve], v: f64) -> Vec<f64> {
        let mut us = Vec::new();
        for curve in curves {
            for w in curve.points.windows(2) {
                let (a, b) = (w[0], w[1]);
                let (lo, hi) = (a.1.min(b.1), a.1.max(b.1));
                if v >= lo && v < hi {
                    us.push(a.0 + (b.0 - a.0) * (v - a.1) / (b.1 - a.1));
                }
            }
        }
        us.sort_by(f64::total_cmp);
        us
    }

    #[test]
    fn parabolic_lines_are_traced_along_a_helix_within_the_tolerance() {
        let spine = helix_spline(8, 0.6);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = circle(0.2, DVec3::new(0.05, -0.03, 0.0), 0.3);
        let analysis = ProfileSurface::new(&rmf.framed, &profile).unwrap();
        let tolerance = 1e-8;
        let curves = analysis.parabolic_curves(tolerance).unwrap();
        let points: usize = curves.iter().map(|c| c.points.len()).sum();
        let surface = sweep(&rmf.framed, &profile).unwrap();
        let (normal, worst) = check_vertices(&curves, &surface, profile.domain(), &spine);
        println!(
            "{} curves, {points} points; at the vertices |n·p| ≤ {normal:.1e}, |K| ≤ {worst:.1e} \
             of max |K|",
            curves.len()
        );
        assert!(normal < 1e-10, "{normal}");
        // The rational frames approximate the RMF: K of the exported surface is not exactly
        // 0 on (14), but close.
        assert!(worst < 1e-4, "{worst}");
        // Two lines winding around the tube, cut at every joint of the C¹ spine (k jumps
        // there, and so do the lines): two curves over each spine segment.
        let sb = spine.breaks();
        assert_eq!(curves.len(), 2 * (sb.len() - 1), "{curves:?}");
        for c in &curves {
            let (first, last) = (c.points[0].1, c.points[c.points.len() - 1].1);
            let (lo, hi) = (first.min(last), first.max(last));
            assert!(sb
                .windows(2)
                .any(|w| (w[0] - lo).abs() < 1e-12 && (w[1] - hi).abs() < 1e-12));
        }
        let (v0, v1) = spine.domain();
        // Beside the roots of the sampled analysis at 101 spine parameters, one crossing each,
        // within the tolerance on the surface.
        let lines = analysis.parabolic_lines(101);
        let mut farthest: f64 = 0.0;
        for j in 1..100 {
            let v = v0 + (v1 - v0) * j as f64 / 100.0;
            let sampled: Vec<f64> = lines
                .normal_condition
                .iter()
                .filter(|p| (p.1 - v).abs() < 1e-12)
                .map(|p| p.0)
                .collect();
            let traced = crossings(&curves, v);
            assert_eq!(
                sampled.len(),
                traced.len(),
                "at v = {v}: {sampled:?} vs {traced:?}"
            );
            for (a, b) in sampled.iter().zip(&traced) {
                farthest = farthest.max((analysis.point(*a, v) - analysis.point(*b, v)).length());
            }
        }
        println!(
            "farthest sampled root from the polylines: {farthest:.1e} (tolerance {tolerance:.0e})"
        );
        assert!(farthest <= tolerance, "{farthest}");
    }

    #[test]
    fn parabolic_lines_of_an_s_shaped_profile_fold_at_its_inflection() {
        let spine = helix_spline(12, 0.35);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = s_profile();
        let analysis = ProfileSurface::new(&rmf.framed, &profile).unwrap();
        let curves = analysis.parabolic_curves(1e-7).unwrap();
        let surface = sweep(&rmf.framed, &profile).unwrap();
        let (normal, worst) = check_vertices(&curves, &surface, profile.domain(), &spine);
        assert!(normal < 1e-10 && worst < 1e-4, "{normal}, {worst}");
        // Every sampled root lies on a traced line.
        let (v0, v1) = spine.domain();
        let lines = analysis.parabolic_lines(61);
        for j in 1..60 {
            let v = v0 + (v1 - v0) * j as f64 / 60.0;
            let sampled = lines
                .normal_condition
                .iter()
                .filter(|p| (p.1 - v).abs() < 1e-12)
                .count();
            assert_eq!(sampled, crossings(&curves, v).len(), "at v = {v}");
        }
    }

    /// The planar PH quintic with hodograph (a² − b², 2ab) for quadratics a, b, its
    /// rotation-minimizing frames (the normal of the plane, f₃ = z) and its inflections.
    fn planar_quintic(a: [f64; 3], b: [f64; 3]) -> FramedCurve {
        let mul = |p: f64, q: f64| p * q;
        let (aa, bb, ab) = (
            product(&a, &a, mul),
            product(&b, &b, mul),
            product(&a, &b, mul),
        );
        let hodograph: Vec<DVec3> = (0..5)
            .map(|i| DVec3::new(aa[i] - bb[i], 2.0 * ab[i], 0.0))
            .collect();
        let mut poles = vec![DVec3::ZERO];
        for h in &hodograph {
            let last = *poles.last().unwrap();
            poles.push(last + *h / 5.0);
        }
        let curve = RationalBezierCurve::polynomial(&poles).unwrap();
        let spine = PiecewiseCurve::new(vec![curve], vec![0.0, 1.0]).unwrap();
        let sigma: Vec<f64> = (0..5).map(|i| aa[i] + bb[i]).collect();
        let f2 = (0..5)
            .map(|i| DVec3::new(-2.0 * ab[i], aa[i] - bb[i], 0.0))
            .collect();
        let f3 = sigma.iter().map(|&s| DVec3::Z * s).collect();
        let segment = RationalFrameSegment::new(f2, f3, sigma).unwrap();
        let frames = RationalFrames::new(vec![segment], vec![0.0, 1.0])
            .unwrap()
            .with_turning(Turning::RotationMinimizing);
        FramedCurve::new(spine, frames).unwrap()
    }

    #[test]
    fn a_planar_spine_gives_lines_of_constant_u_and_its_inflection_a_line_of_constant_v() {
        // a = 1 − 2t + ..., b: a·b' − a'·b has one root in (0, 1): one inflection.
        let framed = planar_quintic([1.0, 0.4, 0.8], [-0.5, 0.3, 0.6]);
        let spine = framed.curve();
        let profile = circle(0.05, DVec3::ZERO, 0.25);
        let analysis = ProfileSurface::new(&framed, &profile).unwrap();
        let curves = analysis.parabolic_curves(1e-8).unwrap();
        let surface = sweep(&framed, &profile).unwrap();
        let (normal, worst) = check_vertices(&curves, &surface, profile.domain(), spine);
        // The exact RMF of a planar curve: K vanishes on the lines to the rounding.
        assert!(normal < 1e-10 && worst < 1e-9, "{normal}, {worst}");
        // k ∥ f₂ in the plane: (14) is ċ ∥ f₂, at the profile's points at angles π/2 and 3π/2
        // (x = 0), each for every v; and v = const at the inflection.
        let x = |u: f64| profile.eval(u).x;
        let expected = [(0.0, 2.0), (2.0, 4.0)]
            .map(|(a, b)| crate::math::bisect_root(x, a, b, 1e-15).unwrap());
        let along_u: Vec<&ParabolicCurve> = curves
            .iter()
            .filter(|c| c.points[0].1 != c.points[1].1)
            .collect();
        assert_eq!(along_u.len(), 2, "{curves:?}");
        for (c, u) in along_u.iter().zip(expected) {
            assert!(
                c.points.iter().all(|p| (p.0 - u).abs() < 1e-9),
                "{c:?} vs u = {u}"
            );
        }
        let inflections: Vec<f64> = curves
            .iter()
            .filter(|c| c.points[0].1 == c.points[1].1)
            .map(|c| c.points[0].1)
            .collect();
        assert_eq!(inflections.len(), 1, "{curves:?}");
        // The inflection, independently: the root of the cross product of x' and x''.
        let cross = |v: f64| {
            let jet = spine.eval_jet(v);
            jet.d1.cross(jet.d2).z
        };
        let v = crate::math::bisect_root(cross, 0.0, 1.0, 1e-15).unwrap();
        assert!(
            (inflections[0] - v).abs() < 1e-9,
            "{} vs {v}",
            inflections[0]
        );
    }

    #[test]
    fn parabolic_curves_are_invariant_under_scaling_and_translation() {
        let spine = helix_spline(4, 0.6);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = circle(0.2, DVec3::ZERO, 0.3);
        let reference = ProfileSurface::new(&rmf.framed, &profile)
            .unwrap()
            .parabolic_curves(1e-7)
            .unwrap();
        for (scale, shift) in [
            (1e-200, DVec3::ZERO),
            (1e200, DVec3::ZERO),
            (1.0, DVec3::splat(1e3)),
        ] {
            let map = |c: &PiecewiseCurve, shift: DVec3| {
                let segments = c
                    .segments()
                    .iter()
                    .map(|s| {
                        let moved = s
                            .homogeneous()
                            .iter()
                            .map(|h| (h.truncate() * scale + shift * h.w).extend(h.w));
                        RationalBezierCurve::from_homogeneous(moved.collect()).unwrap()
                    })
                    .collect();
                PiecewiseCurve::new(segments, c.breaks().to_vec()).unwrap()
            };
            let (spine, profile) = (map(&spine, shift), map(&profile, DVec3::ZERO));
            let spine = PhSpline::new(spine).unwrap();
            let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
            let curves = ProfileSurface::new(&rmf.framed, &profile)
                .unwrap()
                .parabolic_curves(1e-7 * scale)
                .unwrap();
            assert_eq!(curves.len(), reference.len(), "scale {scale:e}");
            for (c, r) in curves.iter().zip(&reference) {
                let (p, q) = (c.points[c.points.len() / 2], r.points[r.points.len() / 2]);
                assert!(c.points.len().abs_diff(r.points.len()) <= r.points.len() / 10);
                assert!(
                    (c.points[0].0 - r.points[0].0).abs() < 1e-8,
                    "scale {scale:e}"
                );
                assert!(p.1 >= 0.0 && q.1 >= 0.0);
            }
        }
    }

    #[test]
    fn tolerances_below_the_profiles_rounding_are_refused_at_every_scale() {
        for scale in [1e-200, 1.0, 1e200] {
            let spine = helix_spline(2, 0.6);
            let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
            let profile = circle(0.2 * scale, DVec3::ZERO, 0.0);
            let analysis = ProfileSurface::new(&rmf.framed, &profile).unwrap();
            // One rounding of the profile's coordinates (up to 0.2√2·scale) is 6.3e-17·scale.
            let e = analysis.parabolic_curves(4e-17 * scale).unwrap_err();
            assert_eq!(e.kind(), crate::ErrorKind::InvalidInput, "{e}");
            assert!(
                e.message()
                    .contains("below what f64 resolves at the profile's"),
                "{e}"
            );
            assert!(analysis.parabolic_curves(1e-7 * scale).is_ok());
        }
    }

    #[test]
    fn a_trace_far_beyond_the_point_bound_is_refused_before_it_is_refined() {
        let spine = helix_spline(2, 0.6);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = circle(0.2, DVec3::ZERO, 0.0);
        let analysis = ProfileSurface::new(&rmf.framed, &profile).unwrap();
        // Resolvable (a few roundings), but the lines need about 3·10⁶ points at it (4·10⁵ at
        // 1e-13, where the estimate is 3·10⁵).
        let mut tracer = Tracer::new(&analysis, 1e-15);
        let e = tracer.all_graphs().unwrap_err();
        assert_eq!(e.kind(), crate::ErrorKind::NotConverged, "{e}");
        assert!(e.message().contains("more than 1048576 points"), "{e}");
        assert_eq!(tracer.points, 0, "points refined before the refusal");
    }

    #[test]
    fn bad_tolerances_are_refused() {
        let spine = helix_spline(2, 0.6);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = circle(0.2, DVec3::ZERO, 0.0);
        let analysis = ProfileSurface::new(&rmf.framed, &profile).unwrap();
        for t in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = analysis.parabolic_curves(t).unwrap_err();
            assert!(e.to_string().contains("tolerance"), "{e}");
        }
    }
}
