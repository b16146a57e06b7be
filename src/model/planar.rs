//! Planar curves drawn for the cutter: true lines and circular arcs where a curve is one,
//! G1 biarcs (Fuhs & Stachel; Leopoldseder & Pottmann, eqs. (7)–(8)) within a tolerance
//! elsewhere, and closed loops of them. The flat patterns of the sheet parts and of the
//! user's unfolded faces are drawn with these.

use super::biarc::{biarc, equal_lambda};
use super::PatternEdge;
use crate::error::{Error, Result};
use glam::DVec2;

/// Points per biarc interval at which its distance from the curve is measured.
const BIARC_SAMPLES: usize = 12;
/// Deepest halving of an interval for biarcs.
const MAX_BIARC_DEPTH: usize = 30;
/// Relative length below which an edge is a point (skipped).
pub(crate) const POINT_LENGTH: f64 = 1e-12;

/// A planar curve over an interval of its parameter: point and derivative.
pub(crate) type PlanarCurve<'a> = dyn Fn(f64) -> (DVec2, DVec2) + 'a;

fn perp(v: DVec2) -> DVec2 {
    DVec2::new(-v.y, v.x)
}

/// The arc (or line) from `a` with unit tangent `t` to `c`.
pub(crate) fn arc_from(a: DVec2, t: DVec2, c: DVec2) -> PatternEdge {
    let d = c - a;
    let sweep = 2.0 * t.perp_dot(d).atan2(t.dot(d));
    if sweep.abs() <= 1e-12 {
        return PatternEdge::Line { from: a, to: c };
    }
    let radius = d.length() / (2.0 * (0.5 * sweep).sin().abs());
    let centre = a + radius * sweep.signum() * perp(t);
    PatternEdge::Arc {
        center: centre,
        radius,
        from: a,
        to: c,
        sweep,
    }
}

/// G1 biarcs through `curve` on [t0, t1] within `tolerance`, appended to `out` (`scale`
/// turns lengths into the caller's units for the message).
pub(crate) fn biarcs(
    curve: &PlanarCurve,
    t0: f64,
    t1: f64,
    tolerance: f64,
    scale: f64,
    out: &mut Vec<PatternEdge>,
) -> Result<()> {
    biarcs_to_depth(curve, t0, t1, tolerance, scale, 0, out)
}

fn biarcs_to_depth(
    curve: &PlanarCurve,
    t0: f64,
    t1: f64,
    tolerance: f64,
    scale: f64,
    depth: usize,
    out: &mut Vec<PatternEdge>,
) -> Result<()> {
    let ((a, ta), (b, tb)) = (curve(t0), curve(t1));
    let lift = |p: DVec2| p.extend(0.0);
    let attempt = (ta.length() > 0.0 && tb.length() > 0.0)
        .then(|| equal_lambda(lift(a), lift(ta.normalize()), lift(b), lift(tb.normalize())))
        .flatten()
        .map(|lambda| {
            let arc = biarc(
                lift(a),
                lift(ta.normalize()),
                lift(b),
                lift(tb.normalize()),
                lambda,
                lambda,
            );
            let c = arc.c.truncate();
            let first = arc_from(a, ta.normalize(), c);
            // The second arc, traversed backwards from b against its tangent.
            let second = arc_from(b, -tb.normalize(), c).reversed();
            [first, second]
        });
    if let Some(pair) = attempt {
        let error = (1..BIARC_SAMPLES)
            .map(|j| {
                let p = curve(t0 + (t1 - t0) * j as f64 / BIARC_SAMPLES as f64).0;
                pair[0].distance(p).min(pair[1].distance(p))
            })
            .fold(0.0, f64::max);
        if error <= tolerance {
            out.extend(pair);
            return Ok(());
        }
    }
    let mid = 0.5 * (t0 + t1);
    if depth >= MAX_BIARC_DEPTH || mid <= t0 || mid >= t1 {
        return Err(Error::not_converged(format!(
            "the flat boundary is not within flat_tolerance = {:.3e} of biarcs after {depth} halvings",
            tolerance * scale
        )));
    }
    biarcs_to_depth(curve, t0, mid, tolerance, scale, depth + 1, out)?;
    biarcs_to_depth(curve, mid, t1, tolerance, scale, depth + 1, out)
}

/// The line or circular arc from the first to the last of `points` (samples of a curve in
/// order) when every sample lies within `tolerance` of it; `None` otherwise.
pub(crate) fn line_or_arc(points: &[DVec2], tolerance: f64) -> Option<PatternEdge> {
    let (&a, &b) = (points.first()?, points.last()?);
    let line = PatternEdge::Line { from: a, to: b };
    let within = |edge: &PatternEdge| points.iter().all(|&p| edge.distance(p) <= tolerance);
    if a.distance(b) > 0.0 && within(&line) {
        return Some(line);
    }
    let m = points[points.len() / 2];
    let arc = arc_through_three(a, m, b)?;
    within(&arc).then_some(arc)
}

/// The circular arc from `a` through `m` to `b`; `None` when the three are collinear or
/// the arc closes (a = b).
fn arc_through_three(a: DVec2, m: DVec2, b: DVec2) -> Option<PatternEdge> {
    let (u, v) = (m - a, b - a);
    let det = 2.0 * u.perp_dot(v);
    if det.abs() <= 1e-300 || a.distance(b) == 0.0 {
        return None;
    }
    let offset = (v.length_squared() * perp(u) - u.length_squared() * perp(v)) / det;
    let center = a + offset;
    let angle = |p: DVec2| (p - center).to_angle();
    let turn =
        |from: f64, to: f64, sense: f64| ((to - from) * sense).rem_euclid(std::f64::consts::TAU);
    // a, m, b counter-clockwise on the circle: the triangle is.
    let sense = if u.perp_dot(v) > 0.0 { 1.0 } else { -1.0 };
    let sweep = sense * turn(angle(a), angle(b), sense);
    Some(PatternEdge::Arc {
        center,
        radius: offset.length(),
        from: a,
        to: b,
        sweep,
    })
}

/// The edge between the points `from` and `to`: a line, or the arc of the same sweep
/// through both (centre and radius recomputed, so that both ends lie on its circle).
fn between(edge: PatternEdge, from: DVec2, to: DVec2) -> PatternEdge {
    match edge {
        PatternEdge::Line { .. } => PatternEdge::Line { from, to },
        PatternEdge::Arc { sweep, .. } => {
            let d = to - from;
            let half = 0.5 * d.length();
            PatternEdge::Arc {
                center: from + 0.5 * d + perp(d / d.length()) * (half / (0.5 * sweep).tan()),
                radius: half / (0.5 * sweep).sin().abs(),
                from,
                to,
                sweep,
            }
        }
    }
}

/// Drops point-like edges and closes the round-off gaps between the others (a vertex
/// computed on two pieces differs by ~1e-12): where a line meets an arc the joint is the
/// arc's end point, between arcs the first arc's, and every arc is redrawn through its
/// joints, so that its DXF form (centre, radius, angles) gives the same end points.
pub(crate) fn close_loop(edges: Vec<PatternEdge>, size: f64) -> Vec<PatternEdge> {
    let kept: Vec<PatternEdge> = edges
        .into_iter()
        .filter(|e| e.length() > POINT_LENGTH * size)
        .collect();
    let m = kept.len();
    let joints: Vec<DVec2> = (0..m)
        .map(|k| {
            let (before, after) = (&kept[(k + m - 1) % m], &kept[k]);
            match (before, after) {
                (PatternEdge::Line { .. }, PatternEdge::Arc { from, .. }) => *from,
                _ => before.end(),
            }
        })
        .collect();
    (0..m)
        .map(|k| between(kept[k], joints[k], joints[(k + 1) % m]))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_points_of_a_circle_give_its_arc_either_way_round() {
        let p = |a: f64| DVec2::new(2.0 + 3.0 * a.cos(), -1.0 + 3.0 * a.sin());
        for (a0, a1) in [(0.2, 2.9), (2.9, 0.2), (-0.5, 4.0), (4.0, -0.5)] {
            let points: Vec<DVec2> = (0..=20)
                .map(|k| p(a0 + (a1 - a0) * k as f64 / 20.0))
                .collect();
            let Some(PatternEdge::Arc {
                center,
                radius,
                sweep,
                ..
            }) = line_or_arc(&points, 1e-12)
            else {
                panic!("no arc for {a0} .. {a1}");
            };
            assert!(center.distance(DVec2::new(2.0, -1.0)) < 1e-12 && (radius - 3.0).abs() < 1e-12);
            assert!(
                (sweep - (a1 - a0)).abs() < 1e-12,
                "sweep {sweep} for {a0} .. {a1}"
            );
        }
        let wavy: Vec<DVec2> = (0..=20)
            .map(|k| p(k as f64 * 0.1) + DVec2::Y * 1e-6 * (k as f64).sin())
            .collect();
        assert!(line_or_arc(&wavy, 1e-9).is_none());
    }
}
