//! Sweeps between profiles: the section blends from the start profile c₀ to the end
//! profile c₁ as s = x + (1 − λ) c₀·F + λ c₁·F, λ linear in arc length from 0 to 1 (Mäurer
//! & Jüttler (1) with a moving profile) — built from the scale law's machinery (`scale`).
//! Through more sections, the wire is cut at each (`scale::split_at_knots`) and every
//! interval blends its two ends, λ from 0 to 1 along it; every profile is matched to the
//! same edges, so a station's section is one edge shared by the faces on both sides:
//!
//! * the profiles are matched loop by loop: the same number of loops (refused otherwise),
//!   each loop turning the same way; a smooth loop is cut where the other's corners point
//!   (its points nearest them, each loop in its own size and centre: a circle at a square's
//!   diagonals), the edges of the one with fewer split at the middle of their longest until
//!   both have as many, and the end loop's start turned to the joint nearest the start
//!   loop's (ties, as between a regular polygon's sides, to the first, whatever the
//!   rounding); through more sections each is matched to the one before, a cut of that
//!   one made in all before it;
//! * each pair of matched segments is written over one denominator h₀h₁ (c₀ = C₀h₁/h₀h₁,
//!   c₁ = C₁h₀/h₀h₁, degree p₀ + p₁): with equal weights the patch of the blend is the sum
//!   of the patches of c₀ scaled by 1 − λ and of c₁ scaled by λ, less the spine's own term
//!   (the patch of the profile 0 with those weights, scaled by 1): exact rational faces,
//!   exact where the scale law is (lines, PH pieces; arcs within the tolerance).

use super::edge::end_direction;
use super::profile::{Profile, ProfileLoop};
use crate::bezier::bernstein::product;
use crate::bezier::{PiecewiseCurve, PiecewiseSurface, RationalBezierCurve, RationalBezierPatch};
use crate::error::{invalid, Result};
use crate::math::minimize_bracketed;
use glam::{DVec3, DVec4};

/// The start and end profiles matched edge for edge over common denominators, and the
/// zero profile with those weights.
#[derive(Clone, Debug)]
pub(crate) struct Blend {
    pub start: Profile,
    pub end: Profile,
    pub zero: Profile,
}

/// The blends of a sweep through sections: one per interval between consecutive
/// stations, and the first piece of the wire in each interval.
#[derive(Clone, Debug)]
pub(crate) struct Blends {
    pub intervals: Vec<Blend>,
    pub first_piece: Vec<usize>,
}

impl Blends {
    /// The interval that holds piece `j`.
    pub(super) fn interval_of(&self, j: usize) -> usize {
        self.first_piece.partition_point(|&first| first <= j) - 1
    }

    /// The profile at the wire's end.
    pub(super) fn end(&self) -> &Profile {
        &self.intervals[self.intervals.len() - 1].end
    }

    /// Every section: the start and end of each interval.
    pub(super) fn sections(&self) -> impl Iterator<Item = &Profile> {
        self.intervals.iter().flat_map(|b| [&b.start, &b.end])
    }
}

/// Matches profiles at consecutive stations along the wire, every loop to its counterpart
/// in each: the blends between consecutive ones, all with the same edges (a split of one
/// profile's loop is made in every profile's, so that the sections at the stations are
/// shared edges). `name` says what refusals call profile k.
pub(crate) fn matched_sections(
    profiles: &[Profile],
    name: &dyn Fn(usize) -> String,
) -> Result<Vec<Blend>> {
    let first = &profiles[0];
    for (i, other) in profiles.iter().enumerate().skip(1) {
        let name = name(i);
        if first.loops.len() != other.loops.len() {
            return invalid!(
                "{name}: it has {} holes, the profile {}: a sweep between profiles matches \
                 hole to hole",
                other.loops.len() - 1,
                first.loops.len() - 1
            );
        }
        if first.plane.is_some() || other.plane.is_some() {
            return invalid!(
                "{name}: a sweep between profiles takes them in the normal plane (z = 0)"
            );
        }
        for (l, (a, b)) in first.loops.iter().zip(&other.loops).enumerate() {
            if a.closed != b.closed {
                return invalid!(
                    "{name}: {} is {} where the profile's is {}",
                    if l == 0 {
                        "the outer loop".to_string()
                    } else {
                        format!("hole {}", l - 1)
                    },
                    if b.closed { "closed" } else { "open" },
                    if a.closed { "closed" } else { "open" }
                );
            }
        }
    }
    // [interval][loop] → (start, end, zero)
    let n = profiles.len() - 1;
    let mut loops: Vec<(Vec<_>, Vec<_>, Vec<_>)> = vec![(Vec::new(), Vec::new(), Vec::new()); n];
    for l in 0..first.loops.len() {
        let matched = matched_loops(&profiles.iter().map(|p| &p.loops[l]).collect::<Vec<_>>());
        for (interval, (p, q, z)) in loops.iter_mut().zip(matched) {
            interval.0.push(p);
            interval.1.push(q);
            interval.2.push(z);
        }
    }
    let profile = |loops| Profile { loops, plane: None };
    Ok(loops
        .into_iter()
        .map(|(p, q, z)| Blend {
            start: profile(p),
            end: profile(q),
            zero: profile(z),
        })
        .collect())
}

/// The loops of consecutive sections matched (module notes), each turning as the first:
/// for each interval between two, (start, end, zero) with equal edge counts and, edge by
/// edge, equal weights.
fn matched_loops(loops: &[&ProfileLoop]) -> Vec<(ProfileLoop, ProfileLoop, ProfileLoop)> {
    let a = loops[0];
    // The segments of the sections matched so far, index by index.
    let mut chain: Vec<Vec<RationalBezierCurve>> = vec![segments(a)];
    for b in &loops[1..] {
        let mut next = segments(b);
        if a.closed && (a.area > 0.0) != (b.area > 0.0) {
            next = next
                .iter()
                .rev()
                .map(RationalBezierCurve::reversed)
                .collect();
        }
        let last = chain.len() - 1;
        if a.closed {
            // Corners onto a smooth loop: it is cut where they fall, so that they meet
            // points of it, not the middles between its joints (a square onto a circle of
            // quarters).
            match (corners(&chain[last]).is_empty(), corners(&next).is_empty()) {
                (false, true) => {
                    let cuts = corner_cuts(&chain[last], &next);
                    apply_cuts(&mut next, &cuts);
                }
                (true, false) => {
                    let cuts = corner_cuts(&next, &chain[last]);
                    chain.iter_mut().for_each(|s| apply_cuts(s, &cuts));
                }
                _ => {}
            }
        }
        while chain[last].len() < next.len() {
            let cut = [(longest(&chain[last]), 0.5)];
            chain.iter_mut().for_each(|s| apply_cuts(s, &cut));
        }
        while next.len() < chain[last].len() {
            let cut = [(longest(&next), 0.5)];
            apply_cuts(&mut next, &cut);
        }
        if a.closed {
            let shift = nearest_start(&chain[last], &next);
            next.rotate_left(shift);
        }
        chain.push(next);
    }
    let as_loop = |segments: Vec<RationalBezierCurve>, area: f64| ProfileLoop {
        edges: segments
            .into_iter()
            .enumerate()
            .map(|(k, s)| {
                PiecewiseCurve::new(vec![s], vec![k as f64, k as f64 + 1.0]).expect("one segment")
            })
            .collect(),
        closed: a.closed,
        area,
    };
    chain
        .windows(2)
        .zip(loops.windows(2))
        .map(|(pair, given)| {
            let mut triple = (Vec::new(), Vec::new(), Vec::new());
            for (p, q) in pair[0].iter().zip(&pair[1]) {
                let (p, q, z) = common_denominator(p, q);
                triple.0.push(p);
                triple.1.push(q);
                triple.2.push(z);
            }
            let sign = a.area.signum();
            (
                as_loop(triple.0, sign * given[0].area.abs()),
                as_loop(triple.1, sign * given[1].area.abs()),
                as_loop(triple.2, a.area),
            )
        })
        .collect()
}

/// Splits segment j at t, for each (j, t) in turn.
fn apply_cuts(segments: &mut Vec<RationalBezierCurve>, cuts: &[(usize, f64)]) {
    for &(j, t) in cuts {
        let (left, right) = segments[j].split(t);
        segments.splice(j..=j, [left, right]);
    }
}

fn segments(lp: &ProfileLoop) -> Vec<RationalBezierCurve> {
    lp.edges
        .iter()
        .flat_map(|e| e.segments().iter().cloned())
        .collect()
}

/// Largest angle between the tangents at a joint that still counts as smooth.
const SMOOTH: f64 = 1e-6;

/// A cut this close to a segment's end (in its parameter) is the joint there.
const AT_JOINT: f64 = 1e-6;

/// Samples per segment of the search for the point of a loop nearest a corner.
const NEAREST_SAMPLES: usize = 64;

/// The joints of a closed loop (joint k starts segment k) where its tangent turns.
fn corners(segments: &[RationalBezierCurve]) -> Vec<usize> {
    let n = segments.len();
    (0..n)
        .filter(|&k| {
            let before = end_direction(&segments[(k + n - 1) % n], true);
            let after = end_direction(&segments[k], false);
            before.angle_between(after) > SMOOTH
        })
        .collect()
}

/// A loop's points about its centre, in units of its size (two loops of different size
/// and place compared alike).
fn normalizer(segments: &[RationalBezierCurve]) -> impl Fn(DVec3) -> DVec3 {
    let starts: Vec<DVec3> = segments.iter().map(|c| c.eval(0.0)).collect();
    let centre = starts.iter().copied().sum::<DVec3>() / starts.len() as f64;
    let size = starts
        .iter()
        .map(|p| p.distance(centre))
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    move |p| (p - centre) / size
}

/// The cuts ([`apply_cuts`], in order) of the smooth loop `smooth` at its points nearest the
/// corners of `cornered` (each loop about its centre and in its size).
fn corner_cuts(
    cornered: &[RationalBezierCurve],
    smooth: &[RationalBezierCurve],
) -> Vec<(usize, f64)> {
    let (from, to) = (normalizer(cornered), normalizer(smooth));
    let mut cuts: Vec<(usize, f64)> = corners(cornered)
        .into_iter()
        .map(|k| {
            let corner = from(cornered[k].eval(0.0));
            let distance = |j: usize, t: f64| to(smooth[j].eval(t)).distance(corner);
            let (j, t) = (0..smooth.len())
                .flat_map(|j| {
                    (0..=NEAREST_SAMPLES).map(move |i| (j, i as f64 / NEAREST_SAMPLES as f64))
                })
                .fold((0, 0.0), |best, c| {
                    if distance(c.0, c.1) < distance(best.0, best.1) {
                        c
                    } else {
                        best
                    }
                });
            let step = 1.0 / NEAREST_SAMPLES as f64;
            let refined = minimize_bracketed(
                |t| distance(j, t),
                (t - step).max(0.0),
                (t + step).min(1.0),
                0.0,
            );
            (j, refined.x)
        })
        // A corner that points at a joint already meets it.
        .filter(|&(_, t)| t > AT_JOINT && t < 1.0 - AT_JOINT)
        .collect();
    // From the last cut back, so that earlier segment indices stay valid; several cuts in
    // one segment from its end back, each in the piece left before it.
    cuts.sort_by(|a, b| b.0.cmp(&a.0).then(b.1.total_cmp(&a.1)));
    cuts.dedup_by(|a, b| a.0 == b.0 && (a.1 - b.1).abs() < 1e-9);
    let mut last: Option<(usize, f64)> = None;
    let mut ops = Vec::with_capacity(cuts.len());
    for (j, t) in cuts {
        // A later cut in the same segment took the part after it: rescale into what is left.
        let t = match last {
            Some((k, t_after)) if k == j => t / t_after,
            _ => t,
        };
        ops.push((j, t));
        last = Some((
            j,
            match last {
                Some((k, t_after)) if k == j => t * t_after,
                _ => t,
            },
        ));
    }
    ops
}

/// The segment with the longest control polygon.
fn longest(segments: &[RationalBezierCurve]) -> usize {
    let length = |s: &RationalBezierCurve| {
        let poles: Vec<DVec3> = s.poles().collect();
        poles.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
    };
    let lengths: Vec<f64> = segments.iter().map(length).collect();
    first_near(
        &lengths,
        lengths.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b)),
    )
}

/// Relative difference within which two lengths or costs are taken as equal, so that ties
/// (a regular polygon's sides) go to the first index whatever the rounding: the match
/// does not depend on the profiles' size.
const TIE: f64 = 1e-9;

/// The first index whose value is within [`TIE`] of `best`.
fn first_near(values: &[f64], best: f64) -> usize {
    let slack = TIE * best.abs();
    values
        .iter()
        .position(|&v| (v - best).abs() <= slack)
        .unwrap_or(0)
}

/// The turn of the end loop's segments that puts its starts nearest the start loop's, each
/// loop taken about its centre and in units of its size.
fn nearest_start(s0: &[RationalBezierCurve], s1: &[RationalBezierCurve]) -> usize {
    let normalized = |s: &[RationalBezierCurve]| -> Vec<DVec3> {
        let to = normalizer(s);
        s.iter().map(|c| to(c.eval(0.0))).collect()
    };
    let (a, b) = (normalized(s0), normalized(s1));
    let n = a.len();
    let costs: Vec<f64> = (0..n)
        .map(|r| (0..n).map(|i| a[i].distance(b[(i + r) % n])).sum())
        .collect();
    first_near(&costs, costs.iter().fold(f64::INFINITY, |x, &y| x.min(y)))
}

/// Two segments over the denominator h₀h₁, and the zero segment with it.
fn common_denominator(
    p: &RationalBezierCurve,
    q: &RationalBezierCurve,
) -> (
    RationalBezierCurve,
    RationalBezierCurve,
    RationalBezierCurve,
) {
    let (hp, hq) = (p.homogeneous(), q.homogeneous());
    let wp: Vec<f64> = hp.iter().map(|h| h.w).collect();
    let wq: Vec<f64> = hq.iter().map(|h| h.w).collect();
    let weights = product(&wp, &wq, |a: f64, b: f64| a * b);
    let numerator = |h: &[DVec4], w: &[f64]| -> Vec<DVec3> {
        product(h, w, |h: DVec4, w: f64| h.truncate() * w)
    };
    let build = |points: Vec<DVec3>| {
        RationalBezierCurve::from_homogeneous(
            points
                .iter()
                .zip(&weights)
                .map(|(p, &w)| p.extend(w))
                .collect(),
        )
        .expect("positive weights")
    };
    (
        build(numerator(hp, &wq)),
        build(numerator(hq, &wp)),
        build(vec![DVec3::ZERO; weights.len()]),
    )
}

/// The blend's patch net from the three sweeps (module notes): a + b − zero, point by
/// point in homogeneous coordinates.
pub(crate) fn combined(
    a: &PiecewiseSurface,
    b: &PiecewiseSurface,
    zero: &PiecewiseSurface,
) -> Result<PiecewiseSurface> {
    let patches = a
        .patches()
        .iter()
        .zip(b.patches())
        .zip(zero.patches())
        .map(|((a, b), z)| {
            let points = a
                .homogeneous()
                .iter()
                .zip(b.homogeneous())
                .zip(z.homogeneous())
                .map(|((a, b), z)| *a + *b - *z)
                .collect();
            RationalBezierPatch::from_homogeneous(a.degree_u(), a.degree_v(), points)
        })
        .collect::<Result<Vec<_>>>()?;
    PiecewiseSurface::new(patches, a.u_breaks().to_vec(), a.v_breaks().to_vec())
}
