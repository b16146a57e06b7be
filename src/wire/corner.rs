//! Sharp (G0) joints of the spine, resolved as OpenCascade's transition modes do, one
//! mode per sweep:
//!
//! * **round**: the corner is replaced by a circular arc of radius ρ tangent to both edges,
//!   so that the spine becomes G1 and the elbow is an exact torus patch. The arc's centre
//!   is where the two edges' offsets by ρ towards the inside of the corner meet,
//!   x_A(a) + ρ n × t_A(a) = x_B(b) + ρ n × t_B(b) (n the normal of the corner's plane): two
//!   equations in the parameters a, b of the tangent points, solved by Newton's method
//!   (one step for lines, closed form for arcs, a few for curves). Both edges must lie in
//!   the corner's plane near it — a circle tangent to two curves that leave a common plane
//!   does not exist in general. A radius that does not fit (a tangent point beyond the
//!   other end of an edge, or past the tangent point of the neighbouring corner) is
//!   refused with the largest radius that fits every corner.
//! * **miter**: the two legs are cut by the plane through the corner bisecting the
//!   tangents (normal t_in + t_out); the frame is carried across by the reflection in that
//!   plane, which maps the incoming leg onto the outgoing one, so the profile meets itself
//!   in the miter plane and does not turn about the tangent (the discrete RMF of the
//!   double-reflection method). The cut is exact on straight legs (the plane section of a
//!   cylinder along a line is an affine image of the profile); legs that are arcs or curves
//!   are refused.
//!
//! Data given to a few decimals leave slight corners where edges were meant to be tangent;
//! in miter mode those between a line and a curved edge are cut exactly (the line by the
//! curved edge's normal plane, see `JointKind::NearTangent`).
//!
//! Whether the profile fits the corner (Mäurer & Jüttler Cor. 7: ρ above the profile's
//! extent towards the corner's centre; miter legs longer than the profile's cut) is decided
//! with the frame, in `frame`.

use super::edge::{turn_about, Chain, Geometry, Joint, JointKind, Piece};
use crate::error::{invalid, Error, Result};
use crate::model::Arc;
use glam::DVec3;

/// Newton steps for a round corner on curves.
const MAX_NEWTON_STEPS: usize = 100;

/// Bisection steps for the largest radius that fits (relative resolution 2⁻⁵⁰).
const RADIUS_BISECTIONS: usize = 50;

/// The smallest part of an edge (relative to its parameter range) a round corner may leave.
const LEFT_OVER: f64 = 1e-9;

/// How sharp joints are resolved (in normalized coordinates).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum CornerMode {
    Round(f64),
    Miter,
}

/// The chain with its corners resolved. `unit` converts lengths to the caller's units for
/// messages.
pub(crate) fn resolve(
    chain: Chain,
    mode: CornerMode,
    unit: f64,
    profile_radius: f64,
) -> Result<Chain> {
    if !chain.joints.iter().any(|j| j.kind == JointKind::Corner) {
        return Ok(chain);
    }
    match mode {
        CornerMode::Miter => miter(near_tangent(chain, profile_radius)),
        CornerMode::Round(radius) => {
            check_radius_resolved(&chain, radius, unit)?;
            round_or_largest(chain, radius, unit)
        }
    }
}

/// Relative size (to the wire's coordinates) at or below which a corner arc is rounding:
/// its centre and tangent points are not resolved (as coincident Hermite points).
const SMALLEST_RADIUS: f64 = 1e-10;

/// Refuses a corner radius below what the wire's coordinates resolve (a default radius of
/// a tiny profile, 6e-34 at coordinates of 1, gives an arc of NaN control points).
fn check_radius_resolved(chain: &Chain, radius: f64, unit: f64) -> Result<()> {
    let magnitude = chain
        .joints
        .iter()
        .map(|j| j.point.abs().max_element())
        .fold(1.0, f64::max);
    if radius <= SMALLEST_RADIUS * magnitude {
        return invalid!(
            "the corner radius {} is below {} of the wire's coordinates (up to {}): a round \
             corner that small is rounding; give a larger corner_radius, or miter corners",
            crate::error::Num(radius * unit),
            crate::error::Num(SMALLEST_RADIUS),
            crate::error::Num(magnitude * unit)
        );
    }
    Ok(())
}

/// The chain with round corners of `radius`, or the error naming the corner it does not fit.
fn round_or_largest(chain: Chain, radius: f64, unit: f64) -> Result<Chain> {
    match round(&chain, radius)? {
        Ok(rounded) => Ok(rounded),
        Err(joint) => {
            let largest = largest_radius(&chain, radius);
            let j = &chain.joints[joint];
            invalid!(
                "{}: the corner radius {} does not fit the edges beside it (an edge is too \
                     short for the round corners at its ends); the largest radius that fits \
                     every corner is {}",
                j.name,
                radius * unit,
                rounded_down(largest * unit)
            )
        }
    }
}

/// `x` rounded down to 9 significant digits (a radius that still fits).
fn rounded_down(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return x;
    }
    let unit = 10f64.powi(x.log10().floor() as i32 - 8);
    let down = (x / unit).floor() * unit;
    if down > 0.0 && down.is_finite() {
        down
    } else {
        x
    }
}

/// Largest section mismatch ½θ²·r of a near-tangent joint, relative to the wire's size.
const NEAR_TANGENT_GAP: f64 = 1e-9;

/// Miter mode: corners between a line and a curved edge so slight that the line's oblique
/// section by the curved edge's normal plane matches that edge's section (see
/// [`JointKind::NearTangent`]), where a miter (straight legs only) could not be made: data
/// given to a few decimals leave such corners where the edges were meant to be tangent.
/// (Round corners round them, with an exact elbow.)
fn near_tangent(mut chain: Chain, profile_radius: f64) -> Chain {
    let m = chain.pieces.len();
    let size = chain
        .pieces
        .iter()
        .flat_map(|p| p.geometry.hull_points())
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p), hi.max(p))
        });
    let size = (size.1 - size.0).length();
    for (i, joint) in chain.joints.iter_mut().enumerate() {
        if joint.kind != JointKind::Corner {
            continue;
        }
        let theta = joint.angle();
        if 0.5 * theta * theta * profile_radius > NEAR_TANGENT_GAP * size {
            continue;
        }
        let straight = |p: &Piece| matches!(p.geometry, Geometry::Line { .. });
        let (before, after) = (&chain.pieces[i], &chain.pieces[(i + 1) % m]);
        joint.kind = match (straight(before), straight(after)) {
            (true, false) => JointKind::NearTangent {
                normal: joint.outgoing,
                line_before: true,
            },
            (false, true) => JointKind::NearTangent {
                normal: joint.incoming,
                line_before: false,
            },
            _ => continue,
        };
    }
    chain
}

/// Miter joints: both legs must be straight.
fn miter(mut chain: Chain) -> Result<Chain> {
    let m = chain.pieces.len();
    for (i, joint) in chain.joints.iter_mut().enumerate() {
        if joint.kind != JointKind::Corner {
            continue;
        }
        for piece in [&chain.pieces[i], &chain.pieces[(i + 1) % m]] {
            if !matches!(piece.geometry, Geometry::Line { .. }) {
                return invalid!(
                    "{}: a miter corner needs straight legs, but edge {} is {} there (the plane \
                     section of its sweep is not rational); use round corners",
                    joint.name,
                    piece.edge,
                    piece.geometry.kind_name()
                );
            }
        }
        joint.kind = JointKind::Miter {
            normal: (joint.incoming + joint.outgoing).normalize(),
        };
    }
    Ok(chain)
}

/// The part of a piece still free: parameters and end points.
#[derive(Clone, Copy, Debug)]
struct Free {
    lo: f64,
    hi: f64,
    start: DVec3,
    end: DVec3,
}

/// A round corner: the tangent points' parameters on the edges and the arc.
struct Fillet {
    a: f64,
    b: f64,
    arc: Arc,
}

/// The chain with every corner rounded, or the index of a joint whose corner does not fit
/// (`Ok(Err(joint))`). Errors are corners that cannot be rounded at any radius.
fn round(chain: &Chain, radius: f64) -> Result<std::result::Result<Chain, usize>> {
    let m = chain.pieces.len();
    let mut free: Vec<Free> = chain
        .pieces
        .iter()
        .map(|p| {
            let (lo, hi) = p.geometry.domain();
            Free {
                lo,
                hi,
                start: p.geometry.start(),
                end: p.geometry.end(),
            }
        })
        .collect();
    let mut fillets: Vec<Option<Arc>> = vec![None; chain.joints.len()];
    for (j, joint) in chain.joints.iter().enumerate() {
        if joint.kind != JointKind::Corner {
            continue;
        }
        let (i, k) = (j, (j + 1) % m);
        let (a, b) = (&chain.pieces[i], &chain.pieces[k]);
        let Some(f) = fillet(a, free[i], b, free[k], joint, radius)? else {
            return Ok(Err(j));
        };
        let (fa, fb) = (f.arc.start, f.arc.end);
        free[i].hi = f.a;
        free[i].end = fa;
        free[k].lo = f.b;
        free[k].start = fb;
        fillets[j] = Some(f.arc);
    }
    // The trimmed pieces with the arcs between them.
    let mut pieces: Vec<Piece> = Vec::with_capacity(m + fillets.len());
    let mut joints: Vec<Joint> = Vec::new();
    for (i, piece) in chain.pieces.iter().enumerate() {
        let f = free[i];
        let trimmed = Piece {
            geometry: piece.geometry.trimmed(f.lo, f.hi, f.start, f.end),
            ..piece.clone()
        };
        if let Some(previous) = pieces.last() {
            let name = chain.joints[i - 1].name.clone();
            joints.push(smooth(&previous.geometry, &trimmed.geometry, name));
        }
        pieces.push(trimmed);
        if let Some(arc) = fillets.get(i).cloned().flatten() {
            let name = format!("{} (round corner)", chain.joints[i].name);
            let elbow = Piece {
                geometry: Geometry::Arc(arc),
                edge: piece.edge,
                corner: Some(chain.joints[i].name.clone()),
            };
            joints.push(smooth(
                &pieces[pieces.len() - 1].geometry,
                &elbow.geometry,
                name,
            ));
            pieces.push(elbow);
        }
    }
    if chain.closed {
        let name = chain.joints[chain.joints.len() - 1].name.clone();
        joints.push(smooth(
            &pieces[pieces.len() - 1].geometry,
            &pieces[0].geometry,
            name,
        ));
    }
    Ok(Ok(Chain {
        pieces,
        joints,
        closed: chain.closed,
    }))
}

/// A G1 joint between consecutive pieces.
fn smooth(before: &Geometry, after: &Geometry, name: String) -> Joint {
    Joint {
        kind: JointKind::Smooth,
        point: before.end(),
        incoming: before.end_tangent(),
        outgoing: after.start_tangent(),
        name,
    }
}

/// The largest radius ≤ `radius` at which every corner fits (bisection).
fn largest_radius(chain: &Chain, radius: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, radius);
    for _ in 0..RADIUS_BISECTIONS {
        let mid = 0.5 * (lo + hi);
        match round(chain, mid) {
            Ok(Ok(_)) => lo = mid,
            _ => hi = mid,
        }
    }
    lo
}

/// The point of the offset by ρ towards the inside (normal `n × t`) and its derivative.
fn offset(g: &Geometry, t: f64, n: DVec3, radius: f64) -> (DVec3, DVec3) {
    let jet = g.jet(t);
    let speed = jet.d1.length();
    let tangent = jet.d1 / speed;
    let turn = (jet.d2 - tangent * tangent.dot(jet.d2)) / speed;
    (
        jet.point + radius * n.cross(tangent),
        jet.d1 + radius * n.cross(turn),
    )
}

/// The round corner of `radius` at `joint` between `a` (its free part `fa`) and `b`;
/// `None` if it does not fit there.
fn fillet(
    a: &Piece,
    fa: Free,
    b: &Piece,
    fb: Free,
    joint: &Joint,
    radius: f64,
) -> Result<Option<Fillet>> {
    let n = joint.incoming.cross(joint.outgoing).normalize();
    for piece in [a, b] {
        if let Geometry::Arc(arc) = &piece.geometry {
            if arc.normal.cross(n).length() > 1e-9 {
                return Err(not_planar(joint, piece));
            }
        }
    }
    let (ga, gb) = (&a.geometry, &b.geometry);
    let (e1, e2) = (joint.incoming, n.cross(joint.incoming));
    let half = 0.5 * joint.angle();
    let cut = radius * half.tan();
    let mut s = (fa.hi - cut / ga.jet(fa.hi).d1.length()).max(fa.lo);
    let mut t = (fb.lo + cut / gb.jet(fb.lo).d1.length()).min(fb.hi);
    let mut converged = false;
    for _ in 0..MAX_NEWTON_STEPS {
        let (pa, da) = offset(ga, s, n, radius);
        let (pb, db) = offset(gb, t, n, radius);
        let f = pa - pb;
        let scale = 1.0 + radius + pa.length();
        if f.length() <= 1e-13 * scale {
            converged = true;
            break;
        }
        // J (Δs, Δt) = −F in the corner's plane.
        let (j11, j12, j21, j22) = (da.dot(e1), -db.dot(e1), da.dot(e2), -db.dot(e2));
        let det = j11 * j22 - j12 * j21;
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let (f1, f2) = (f.dot(e1), f.dot(e2));
        let ds = -(j22 * f1 - j12 * f2) / det;
        let dt = -(-j21 * f1 + j11 * f2) / det;
        let (s1, t1) = ((s + ds).clamp(fa.lo, fa.hi), (t + dt).clamp(fb.lo, fb.hi));
        if s1 == s && t1 == t {
            break;
        }
        (s, t) = (s1, t1);
    }
    let room = |x: f64, lo: f64, hi: f64| x - lo > LEFT_OVER * (hi - lo);
    // No tangent points on the free parts of the edges (pinned at an end, or no circle of
    // this radius touches both there): the radius does not fit.
    if !converged {
        return Ok(None);
    }
    if !room(s, fa.lo, fa.hi) || !room(fb.hi - t + fb.lo, fb.lo, fb.hi) {
        return Ok(None);
    }
    for (piece, lo, hi) in [(a, s, fa.hi), (b, fb.lo, t)] {
        if let Geometry::Curve(c) = &piece.geometry {
            let part = super::edge::sub_curve(c, lo, hi);
            let extent = piece.geometry.length().max(radius);
            let off_plane = part
                .segments()
                .iter()
                .flat_map(|seg| seg.poles())
                .any(|p| (p - joint.point).dot(n).abs() > 1e-9 * extent);
            if off_plane {
                return Err(not_planar(joint, piece));
            }
        }
    }
    let (ta, tb) = (ga.jet(s).point, gb.jet(t).point);
    let center = 0.5 * (offset(ga, s, n, radius).0 + offset(gb, t, n, radius).0);
    let angle = turn_about(ta - center, tb - center, n);
    Ok(Some(Fillet {
        a: s,
        b: t,
        arc: Arc::about(center, radius, n, ta, tb, angle),
    }))
}

fn not_planar(joint: &Joint, piece: &Piece) -> Error {
    Error::invalid_input(format!(
        "{}: a round corner needs both edges in the plane of the corner near it, but edge {} \
         ({}) leaves that plane (no circular arc is tangent to both); use miter corners or \
         split the edge",
        joint.name,
        piece.edge,
        piece.geometry.kind_name()
    ))
}

#[cfg(test)]
mod tests {
    use super::super::edge::{chain, RawEdge};
    use super::*;
    use crate::model::Similarity;
    use std::f64::consts::FRAC_PI_2;

    const UNIT: Similarity = Similarity {
        scale: 1.0,
        origin: DVec3::ZERO,
    };

    fn polyline(points: &[[f64; 3]]) -> Chain {
        let edges: Vec<RawEdge> = points
            .windows(2)
            .map(|w| RawEdge::Line(DVec3::from(w[0]), DVec3::from(w[1])))
            .collect();
        chain(&edges, 1e-9, 10.0, UNIT).unwrap()
    }

    #[test]
    fn a_right_angle_gets_a_quarter_circle_tangent_to_both_legs() {
        let c = polyline(&[[0., 0., 0.], [4., 0., 0.], [4., 4., 0.]]);
        let r = resolve(c, CornerMode::Round(1.0), 1.0, 0.1).unwrap();
        assert_eq!(r.pieces.len(), 3);
        let Geometry::Arc(arc) = &r.pieces[1].geometry else {
            panic!("an elbow")
        };
        assert!((arc.center - DVec3::new(3., 1., 0.)).length() < 1e-14);
        assert!((arc.angle - FRAC_PI_2).abs() < 1e-14);
        assert!(r
            .joints
            .iter()
            .all(|j| j.kind == JointKind::Smooth && j.angle() < 1e-14));
        assert_eq!(r.pieces[0].geometry.end(), arc.start);
    }

    #[test]
    fn a_radius_too_large_is_refused_with_the_largest_that_fits() {
        // Legs of 4 and 2 with two right angles: the middle leg holds 2 × ρ, so ρ ≤ 1.
        let c = polyline(&[[0., 0., 0.], [4., 0., 0.], [4., 2., 0.], [0., 2., 0.]]);
        let e = resolve(c.clone(), CornerMode::Round(1.5), 1.0, 0.1).unwrap_err();
        assert!(e.message().contains("does not fit"), "{e}");
        let largest: f64 = e.message().rsplit(' ').next().unwrap().parse().unwrap();
        assert!(largest <= 1.0 && largest > 1.0 - 1e-8, "{e}");
        assert!(resolve(c, CornerMode::Round(0.99), 1.0, 0.1).is_ok());
    }

    #[test]
    fn a_line_and_an_arc_get_a_tangent_round_corner() {
        // A line heading south-east into the top of a circle of radius 2 about the origin,
        // which it leaves clockwise heading east: a 45° corner turning left, so the
        // elbow touches the big circle from outside.
        let edges = [
            RawEdge::Line(DVec3::new(-2., 4., 0.), DVec3::new(0., 2., 0.)),
            RawEdge::Arc(
                DVec3::new(0., 2., 0.),
                DVec3::new(2f64.sqrt(), 2f64.sqrt(), 0.),
                DVec3::new(2., 0., 0.),
            ),
        ];
        let c = chain(&edges, 1e-9, 5.0, UNIT).unwrap();
        assert_eq!(c.joints[0].kind, JointKind::Corner);
        let r = resolve(c, CornerMode::Round(0.5), 1.0, 0.1).unwrap();
        let Geometry::Arc(elbow) = &r.pieces[1].geometry else {
            panic!("an elbow")
        };
        let Geometry::Arc(rest) = &r.pieces[2].geometry else {
            panic!("the arc")
        };
        assert!((elbow.center.distance(rest.center) - 2.5).abs() < 1e-12);
        let direction = DVec3::new(1., -1., 0.).normalize();
        let to_line = (elbow.center - DVec3::new(0., 2., 0.))
            .cross(direction)
            .length();
        assert!(
            (to_line - 0.5).abs() < 1e-12,
            "tangent to the line: {to_line}"
        );
        assert!(r.joints.iter().all(|j| j.angle() < 1e-12));
    }

    #[test]
    fn miters_need_straight_legs() {
        let c = polyline(&[[0., 0., 0.], [4., 0., 0.], [4., 4., 0.]]);
        let m = resolve(c, CornerMode::Miter, 1.0, 0.1).unwrap();
        let JointKind::Miter { normal } = m.joints[0].kind else {
            panic!("a miter")
        };
        assert!((normal - DVec3::new(1., 1., 0.).normalize()).length() < 1e-15);
    }
}
