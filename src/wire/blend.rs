//! Sweeps between two profiles: the section blends from the start profile c₀ to the end
//! profile c₁ as s = x + (1 − λ) c₀·F + λ c₁·F, λ linear in arc length from 0 to 1 (Mäurer
//! & Jüttler (1) with a moving profile) — built from the scale law's machinery (`scale`):
//!
//! * the profiles are matched loop by loop: the same number of loops (refused otherwise),
//!   each loop turning the same way; a smooth loop is cut where the other's corners point
//!   (its points nearest them, each loop in its own size and centre: a circle at a square's
//!   diagonals), the edges of the one with fewer split at the middle of their longest until
//!   both have as many, and the end loop's start turned to the joint nearest the start
//!   loop's;
//! * each pair of matched segments is written over one denominator h₀h₁ (c₀ = C₀h₁/h₀h₁,
//!   c₁ = C₁h₀/h₀h₁, degree p₀ + p₁): with equal weights the patch of the blend is the sum
//!   of the patches of c₀ scaled by 1 − λ and of c₁ scaled by λ, less the spine's own term
//!   (the patch of the profile 0 with those weights, scaled by 1): exact rational faces,
//!   exact where the scale law is (lines, PH pieces; arcs within the tolerance).

use super::edge::{end_direction, reversed};
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

/// Matches the end profile to the start profile (module notes).
pub(crate) fn matched(start: &Profile, end: &Profile) -> Result<Blend> {
    if start.loops.len() != end.loops.len() {
        return invalid!(
            "end_profile: it has {} holes, the profile {}: a sweep between two profiles \
             matches hole to hole",
            end.loops.len() - 1,
            start.loops.len() - 1
        );
    }
    if start.plane.is_some() || end.plane.is_some() {
        return invalid!(
            "end_profile: a sweep between two profiles takes both in the normal plane (z = 0)"
        );
    }
    let mut loops = (Vec::new(), Vec::new(), Vec::new());
    for (l, (a, b)) in start.loops.iter().zip(&end.loops).enumerate() {
        if a.closed != b.closed {
            return invalid!(
                "end_profile: {} is {} where the profile's is {}",
                if l == 0 {
                    "the outer loop".to_string()
                } else {
                    format!("hole {}", l - 1)
                },
                if b.closed { "closed" } else { "open" },
                if a.closed { "closed" } else { "open" }
            );
        }
        let (p, q, z) = matched_loop(a, b);
        loops.0.push(p);
        loops.1.push(q);
        loops.2.push(z);
    }
    Ok(Blend {
        start: Profile {
            loops: loops.0,
            plane: None,
        },
        end: Profile {
            loops: loops.1,
            plane: None,
        },
        zero: Profile {
            loops: loops.2,
            plane: None,
        },
    })
}

/// One pair of loops matched: (start, end, zero) with equal edge counts and, edge by edge,
/// equal weights.
fn matched_loop(a: &ProfileLoop, b: &ProfileLoop) -> (ProfileLoop, ProfileLoop, ProfileLoop) {
    let mut s0 = segments(a);
    let mut s1 = segments(b);
    if a.closed && (a.area > 0.0) != (b.area > 0.0) {
        s1 = s1.iter().rev().map(reversed_segment).collect();
    }
    if a.closed {
        // Corners onto a smooth loop: it is cut where they fall, so that they meet points
        // of it, not the middles between its joints (a square onto a circle of quarters).
        match (corners(&s0).is_empty(), corners(&s1).is_empty()) {
            (false, true) => cut_at_corners_of(&s0, &mut s1),
            (true, false) => cut_at_corners_of(&s1, &mut s0),
            _ => {}
        }
    }
    while s0.len() < s1.len() {
        split_longest(&mut s0);
    }
    while s1.len() < s0.len() {
        split_longest(&mut s1);
    }
    if a.closed {
        let shift = nearest_start(&s0, &s1);
        s1.rotate_left(shift);
    }
    let mut triple = (Vec::new(), Vec::new(), Vec::new());
    for (p, q) in s0.iter().zip(&s1) {
        let (p, q, z) = common_denominator(p, q);
        triple.0.push(p);
        triple.1.push(q);
        triple.2.push(z);
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
    (
        as_loop(triple.0, a.area),
        as_loop(triple.1, a.area.signum() * b.area.abs()),
        as_loop(triple.2, a.area),
    )
}

fn segments(lp: &ProfileLoop) -> Vec<RationalBezierCurve> {
    lp.edges
        .iter()
        .flat_map(|e| e.segments().iter().cloned())
        .collect()
}

fn reversed_segment(s: &RationalBezierCurve) -> RationalBezierCurve {
    let curve = PiecewiseCurve::new(vec![s.clone()], vec![0.0, 1.0]).expect("one segment");
    reversed(&curve).segments()[0].clone()
}

/// Largest angle between the tangents at a joint that still counts as smooth.
const SMOOTH: f64 = 1e-6;

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

/// Cuts the smooth loop `smooth` at its points nearest the corners of `cornered` (each
/// loop about its centre and in its size).
fn cut_at_corners_of(cornered: &[RationalBezierCurve], smooth: &mut Vec<RationalBezierCurve>) {
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
        .filter(|&(_, t)| t > 1e-9 && t < 1.0 - 1e-9)
        .collect();
    // From the last cut back, so that earlier segment indices stay valid; several cuts in
    // one segment from its end back, each in the piece left before it.
    cuts.sort_by(|a, b| b.0.cmp(&a.0).then(b.1.total_cmp(&a.1)));
    cuts.dedup_by(|a, b| a.0 == b.0 && (a.1 - b.1).abs() < 1e-9);
    let mut last: Option<(usize, f64)> = None;
    for (j, t) in cuts {
        // A later cut in the same segment took the part after it: rescale into what is left.
        let t = match last {
            Some((k, t_after)) if k == j => t / t_after,
            _ => t,
        };
        let (left, right) = smooth[j].split(t);
        smooth.splice(j..=j, [left, right]);
        last = Some((
            j,
            match last {
                Some((k, t_after)) if k == j => t * t_after,
                _ => t,
            },
        ));
    }
}

/// Splits the segment with the longest control polygon at its middle.
fn split_longest(segments: &mut Vec<RationalBezierCurve>) {
    let length = |s: &RationalBezierCurve| {
        let poles: Vec<DVec3> = s.poles().collect();
        poles.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
    };
    let (k, _) = segments
        .iter()
        .enumerate()
        .map(|(k, s)| (k, length(s)))
        .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
    let (left, right) = segments[k].split(0.5);
    segments.splice(k..=k, [left, right]);
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
    (0..n)
        .map(|r| {
            let cost: f64 = (0..n).map(|i| a[i].distance(b[(i + r) % n])).sum();
            (r, cost)
        })
        .fold((0, f64::INFINITY), |x, y| if y.1 < x.1 { y } else { x })
        .0
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
