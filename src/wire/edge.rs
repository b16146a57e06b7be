//! The spine as the user draws it — lines, circular arcs and curves, each in either
//! orientation — turned into one oriented chain of *pieces* joined end to end.
//!
//! * Edges are oriented one after the other: each one is used forwards or backwards so that
//!   it starts where the previous one ends (within the join tolerance); the gap is closed by
//!   moving the start of the later edge onto the end of the earlier one, so consecutive
//!   pieces share their joint exactly. A wire whose end meets its start is closed.
//! * A curve edge is split into pieces of one kind: its Bézier segments that are exactly
//!   straight (collinear control points, monotone) become lines, rational quadratics that
//!   are circular (equal legs, middle weight cos of the half angle, normalized) become
//!   arcs, and the rest stays a curve, to be approximated by a PH cubic spline. Runs of
//!   one kind are merged (collinear lines, arcs of one circle, G1 curve segments).
//! * Every joint between pieces is classified by the angle between the tangents: G1
//!   (smooth), a corner (G0), or a reversal (the wire turns back on itself: refused).
//!
//! Lines and arcs are kept as what they are, so that their sweeps are exact cylinders and
//! tori (see `frame` and `brep`).

use crate::bezier::{CurveJet, PiecewiseCurve, RationalBezierCurve};
use crate::error::{invalid, Result};
use crate::math::{angle_between, robust_normalize, signed_angle};
use crate::model::{Arc, Similarity};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Largest angle between the tangents at a joint that still counts as smooth (G1),
/// radians. Sections on either side then differ by this angle times the profile's size.
pub(crate) const G1_ANGLE: f64 = 1e-9;

/// A joint whose tangents are within this angle of opposite is a reversal (a cusp).
pub(crate) const REVERSAL_ANGLE: f64 = 1e-6;

/// Relative distance (to the segment's size) within which curve data are exactly a line
/// or a circular arc: the rounding of data converted from a CAD system, far below any
/// modelling tolerance.
const EXACT: f64 = 1e-10;

/// What a piece of the spine is.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Geometry {
    /// From `a` to `b` (parameter [0, 1]).
    Line { a: DVec3, b: DVec3 },
    /// Parameter: the angle φ ∈ [0, angle].
    Arc(Arc),
    /// A G1 curve, parameter its own.
    Curve(PiecewiseCurve),
}

impl Geometry {
    pub(super) fn domain(&self) -> (f64, f64) {
        match self {
            Geometry::Line { .. } => (0.0, 1.0),
            Geometry::Arc(arc) => (0.0, arc.angle),
            Geometry::Curve(c) => c.domain(),
        }
    }

    pub(super) fn jet(&self, t: f64) -> CurveJet {
        match self {
            Geometry::Line { a, b } => CurveJet {
                point: *a + t * (*b - *a),
                d1: *b - *a,
                d2: DVec3::ZERO,
            },
            Geometry::Arc(arc) => arc.jet(t),
            Geometry::Curve(c) => c.eval_jet(t),
        }
    }

    pub(super) fn start(&self) -> DVec3 {
        match self {
            Geometry::Line { a, .. } => *a,
            Geometry::Arc(arc) => arc.start,
            Geometry::Curve(c) => c.eval(c.domain().0),
        }
    }

    pub(super) fn end(&self) -> DVec3 {
        match self {
            Geometry::Line { b, .. } => *b,
            Geometry::Arc(arc) => arc.end,
            Geometry::Curve(c) => c.eval(c.domain().1),
        }
    }

    /// The unit tangent at the start (the limit direction where the derivative vanishes).
    pub(super) fn start_tangent(&self) -> DVec3 {
        match self {
            Geometry::Curve(c) => end_direction(&c.segments()[0], false),
            _ => self.unit_tangent(self.domain().0),
        }
    }

    /// The unit tangent at the end.
    pub(super) fn end_tangent(&self) -> DVec3 {
        match self {
            Geometry::Curve(c) => end_direction(&c.segments()[c.segments().len() - 1], true),
            _ => self.unit_tangent(self.domain().1),
        }
    }

    pub(super) fn unit_tangent(&self, t: f64) -> DVec3 {
        match self {
            Geometry::Line { a, b } => (*b - *a).normalize(),
            Geometry::Arc(arc) => arc.tangent(t),
            Geometry::Curve(c) => robust_normalize(c.eval_jet(t).d1).unwrap_or(DVec3::ZERO),
        }
    }

    /// The part on [t0, t1] ⊂ domain, starting at `start` and ending at `end` exactly.
    pub(super) fn trimmed(&self, t0: f64, t1: f64, start: DVec3, end: DVec3) -> Self {
        match self {
            Geometry::Line { .. } => Geometry::Line { a: start, b: end },
            Geometry::Arc(arc) => Geometry::Arc(arc.trimmed(t0, t1, start, end)),
            Geometry::Curve(c) => Geometry::Curve(with_ends(&sub_curve(c, t0, t1), start, end)),
        }
    }

    /// The length (by quadrature for curves).
    pub(super) fn length(&self) -> f64 {
        match self {
            Geometry::Line { a, b } => a.distance(*b),
            Geometry::Arc(arc) => arc.length(),
            Geometry::Curve(c) => c.arc_length(),
        }
    }

    /// Points that span the piece (for sizes and the default frame).
    pub(super) fn hull_points(&self) -> Vec<DVec3> {
        match self {
            Geometry::Line { a, b } => vec![*a, *b],
            Geometry::Arc(arc) => (0..=8)
                .map(|k| arc.point(arc.angle * k as f64 / 8.0))
                .collect(),
            Geometry::Curve(c) => c.segments().iter().flat_map(|s| s.poles()).collect(),
        }
    }

    pub(super) fn kind_name(&self) -> &'static str {
        match self {
            Geometry::Line { .. } => "a line",
            Geometry::Arc(_) => "an arc",
            Geometry::Curve(_) => "a curve",
        }
    }
}

/// The direction of a Bézier segment at its start (`at_end` false) or end: the first
/// control leg that does not vanish (the derivative's direction, or its limit at a
/// singular end).
pub(crate) fn end_direction(segment: &RationalBezierCurve, at_end: bool) -> DVec3 {
    let mut poles: Vec<DVec3> = segment.poles().collect();
    if at_end {
        poles.reverse();
    }
    let size = poles
        .iter()
        .fold(0.0f64, |m, p| m.max(p.distance(poles[0])));
    for p in &poles[1..] {
        if p.distance(poles[0]) > 1e-14 * size {
            let d = robust_normalize(*p - poles[0]).unwrap_or(DVec3::ZERO);
            return if at_end { -d } else { d };
        }
    }
    DVec3::ZERO
}

/// The part of a piecewise curve on [t0, t1] (inside its domain), on its own parameters.
pub(crate) fn sub_curve(curve: &PiecewiseCurve, t0: f64, t1: f64) -> PiecewiseCurve {
    let breaks = curve.breaks();
    let mut segments = Vec::new();
    let mut cuts = vec![t0];
    for k in 0..curve.segments().len() {
        let (a, b) = (breaks[k], breaks[k + 1]);
        if b <= t0 || a >= t1 {
            continue;
        }
        let (lo, hi) = (a.max(t0), b.min(t1));
        let (s0, s1) = ((lo - a) / (b - a), (hi - a) / (b - a));
        let segment = &curve.segments()[k];
        segments.push(if s0 == 0.0 && s1 == 1.0 {
            segment.clone()
        } else {
            segment.restricted(s0, s1)
        });
        cuts.push(hi);
    }
    PiecewiseCurve::new(segments, cuts).expect("a part of a curve")
}

/// The curve with its first and last control points moved to `start` and `end` (by at
/// most the join tolerance), keeping their weights.
pub(crate) fn with_ends(curve: &PiecewiseCurve, start: DVec3, end: DVec3) -> PiecewiseCurve {
    let mut segments = curve.segments().to_vec();
    let last = segments.len() - 1;
    let moved = |s: &RationalBezierCurve, index: usize, p: DVec3| {
        let mut h = s.homogeneous().to_vec();
        let w = h[index].w;
        h[index] = (p * w).extend(w);
        RationalBezierCurve::from_homogeneous(h).expect("finite points")
    };
    segments[0] = moved(&segments[0], 0, start);
    let d = segments[last].degree();
    segments[last] = moved(&segments[last], d, end);
    PiecewiseCurve::new(segments, curve.breaks().to_vec()).expect("same breaks")
}

/// One piece of the spine and where it came from.
#[derive(Clone, Debug)]
pub(crate) struct Piece {
    pub geometry: Geometry,
    /// The user's edge it belongs to.
    pub edge: usize,
    /// The elbow of a round corner (after `edge`): the name of the joint it rounds.
    pub corner: Option<String>,
}

impl Piece {
    /// What the piece is called in messages: its edge, or the round corner it makes.
    pub(super) fn name(&self) -> String {
        match &self.corner {
            Some(joint) => format!("the round corner at the {joint}"),
            None => format!("edge {}", self.edge),
        }
    }
}

/// How two consecutive pieces meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum JointKind {
    /// Tangent continuous: the frame is carried across.
    Smooth,
    /// A sharp corner, still to be resolved (`corner`).
    Corner,
    /// A miter: both legs are cut by the plane through the joint with this unit normal
    /// (the bisector of the tangents); the frame is reflected in it.
    Miter { normal: DVec3 },
    /// A corner so slight, between a line and a curved edge, that the line is cut by the
    /// curved edge's normal plane at the joint (unit `normal`; the line is the piece
    /// before the joint when `line_before`) and the frame projected across: the line's
    /// oblique section and the curved edge's normal section differ by ½θ²·r (θ the angle,
    /// r the profile's radius), below a billionth of the wire's size.
    NearTangent { normal: DVec3, line_before: bool },
}

/// The joint after piece i (between pieces i and i + 1, or the last and the first of a
/// closed wire).
#[derive(Clone, Debug)]
pub(crate) struct Joint {
    pub kind: JointKind,
    pub point: DVec3,
    /// Unit tangents at the end of the piece before and the start of the piece after.
    pub incoming: DVec3,
    pub outgoing: DVec3,
    /// "joint between edges 1 and 2", "the corner of edge 3 at t = 0.5": for messages.
    pub name: String,
}

impl Joint {
    pub(super) fn angle(&self) -> f64 {
        angle_between(self.incoming, self.outgoing)
    }

    /// Whether a plane cuts the pieces here (a miter, a near-tangent joint).
    pub(super) fn cuts(&self) -> bool {
        matches!(
            self.kind,
            JointKind::Miter { .. } | JointKind::NearTangent { .. }
        )
    }
}

/// The spine: pieces end to end, the joints between them.
#[derive(Clone, Debug)]
pub(crate) struct Chain {
    pub pieces: Vec<Piece>,
    /// `joints[i]` follows `pieces[i]`; a closed chain has as many joints as pieces (the
    /// last one closes it), an open one one fewer.
    pub joints: Vec<Joint>,
    pub closed: bool,
}

/// An edge as given, in normalized coordinates (see `sweep`).
#[derive(Clone, Debug)]
pub(crate) enum RawEdge {
    Line(DVec3, DVec3),
    Arc(DVec3, DVec3, DVec3),
    Curve(PiecewiseCurve),
}

impl RawEdge {
    fn ends(&self) -> (DVec3, DVec3) {
        match self {
            RawEdge::Line(a, b) => (*a, *b),
            RawEdge::Arc(a, _, c) => (*a, *c),
            RawEdge::Curve(c) => {
                let (lo, hi) = c.domain();
                (c.eval(lo), c.eval(hi))
            }
        }
    }

    fn reversed(&self) -> Self {
        match self {
            RawEdge::Line(a, b) => RawEdge::Line(*b, *a),
            RawEdge::Arc(a, m, c) => RawEdge::Arc(*c, *m, *a),
            RawEdge::Curve(c) => RawEdge::Curve(c.reversed()),
        }
    }

    /// The same edge starting at `start` and ending at `end` (moved by the join tolerance).
    fn with_ends(&self, start: DVec3, end: DVec3) -> Self {
        match self {
            RawEdge::Line(..) => RawEdge::Line(start, end),
            RawEdge::Arc(_, m, _) => RawEdge::Arc(start, *m, end),
            RawEdge::Curve(c) => RawEdge::Curve(with_ends(c, start, end)),
        }
    }
}

/// The oriented, connected chain of `edges` (module notes). `tolerance` is the largest gap
/// between consecutive edge ends; `size` the wire's size (for relative tests).
pub(crate) fn chain(
    edges: &[RawEdge],
    tolerance: f64,
    size: f64,
    units: Similarity,
) -> Result<Chain> {
    if edges.is_empty() {
        return invalid!("edges: a wire needs at least one edge");
    }
    for (k, e) in edges.iter().enumerate() {
        check_edge(e, tolerance, units).map_err(|e| e.context(format!("edge {k}")))?;
    }
    let oriented = orient(edges, tolerance, units)?;
    let n = oriented.len();
    let (first, _) = oriented[0].0.ends();
    let (_, last) = oriented[n - 1].0.ends();
    let closed = first.distance(last) <= tolerance;
    // Snap: each edge starts exactly where the previous one ends (a closed wire's last
    // edge ends where the first starts).
    let mut snapped: Vec<RawEdge> = Vec::with_capacity(n);
    for (k, (e, _)) in oriented.iter().enumerate() {
        let (mut s, mut t) = e.ends();
        if k > 0 {
            s = snapped[k - 1].ends().1;
        }
        if closed && k + 1 == n {
            t = if k == 0 { s } else { snapped[0].ends().0 };
        }
        snapped.push(e.with_ends(s, t));
    }
    let mut pieces: Vec<Piece> = Vec::new();
    let mut joints: Vec<Joint> = Vec::new();
    for (k, e) in snapped.iter().enumerate() {
        let (edge_pieces, inner) =
            edge_pieces(e, k, size, oriented[k].1).map_err(|e| e.context(format!("edge {k}")))?;
        if let Some(before) = pieces.last() {
            joints.push(joint(
                &before.geometry,
                &edge_pieces[0].geometry,
                format!("joint between edges {} and {k}", k - 1),
            )?);
        }
        pieces.extend(edge_pieces);
        joints.extend(inner);
    }
    if closed {
        joints.push(joint(
            &pieces[pieces.len() - 1].geometry,
            &pieces[0].geometry,
            if n == 1 {
                "joint where edge 0 closes".to_string()
            } else {
                format!("joint between edges {} and 0", n - 1)
            },
        )?);
    }
    Ok(Chain {
        pieces,
        joints,
        closed,
    })
}

/// Each edge on its own: not of zero length, arcs with a circle.
fn check_edge(edge: &RawEdge, tolerance: f64, units: Similarity) -> Result<()> {
    let p = |q: &DVec3| units.to_user(*q);
    match edge {
        RawEdge::Line(a, b) => {
            if a.distance(*b) <= tolerance {
                return invalid!("a line of zero length (from {} to {})", p(a), p(b));
            }
        }
        RawEdge::Arc(a, m, c) => {
            if a.distance(*c) <= tolerance
                || a.distance(*m) <= tolerance
                || m.distance(*c) <= tolerance
            {
                return invalid!(
                    "an arc whose points coincide ({}, {}, {}): give a full circle as two arcs",
                    p(a),
                    p(m),
                    p(c)
                );
            }
            if Arc::through(*a, *m, *c).is_err() {
                return invalid!(
                    "an arc whose three points ({}, {}, {}) are collinear: they define no circle",
                    p(a),
                    p(m),
                    p(c)
                );
            }
        }
        RawEdge::Curve(c) => {
            let poles: Vec<DVec3> = c.segments().iter().flat_map(|s| s.poles()).collect();
            if poles.iter().all(|q| q.distance(poles[0]) <= tolerance) {
                return invalid!("a curve of zero length (all its poles at {})", p(&poles[0]));
            }
        }
    }
    Ok(())
}

/// Each edge forwards or backwards so that it starts where the previous one ends.
fn orient(edges: &[RawEdge], tolerance: f64, units: Similarity) -> Result<Vec<(RawEdge, bool)>> {
    let mut oriented: Vec<(RawEdge, bool)> = Vec::with_capacity(edges.len());
    for (k, e) in edges.iter().enumerate() {
        let (s, t) = e.ends();
        let forward = match oriented.last() {
            None => match edges.get(1) {
                // The first edge: whichever end meets the second edge.
                Some(next) => {
                    let (ns, nt) = next.ends();
                    let gap = |p: DVec3| p.distance(ns).min(p.distance(nt));
                    gap(t) <= tolerance || gap(s) > tolerance && gap(t) <= gap(s)
                }
                None => true,
            },
            Some((previous, _)) => {
                let end = previous.ends().1;
                let (gs, gt) = (end.distance(s), end.distance(t));
                if gs > tolerance && gt > tolerance {
                    return invalid!(
                        "edges {} and {k} do not meet: the nearest ends are {:.3e} apart, more \
                         than the join tolerance {:.3e} (edge {} ends at {}, edge {k} runs from \
                         {} to {})",
                        k - 1,
                        units.length(gs.min(gt)),
                        units.length(tolerance),
                        k - 1,
                        units.to_user(end),
                        units.to_user(s),
                        units.to_user(t)
                    );
                }
                gs <= gt
            }
        };
        oriented.push(if forward {
            (e.clone(), false)
        } else {
            (e.reversed(), true)
        });
    }
    if let [(first, _), (second, _), ..] = oriented.as_slice() {
        let gap = first.ends().1.distance(second.ends().0);
        if gap > tolerance {
            return invalid!(
                "edges 0 and 1 do not meet: the nearest ends are {:.3e} apart, more than the \
                 join tolerance {:.3e}",
                units.length(gap),
                units.length(tolerance)
            );
        }
    }
    Ok(oriented)
}

/// The joint between two pieces: smooth, a corner, or refused as a reversal.
fn joint(before: &Geometry, after: &Geometry, name: String) -> Result<Joint> {
    let (incoming, outgoing) = (before.end_tangent(), after.start_tangent());
    if incoming == DVec3::ZERO || outgoing == DVec3::ZERO {
        return invalid!("{name}: a tangent there vanishes (a cusp)");
    }
    let angle = angle_between(incoming, outgoing);
    if angle >= PI - REVERSAL_ANGLE {
        return invalid!(
            "{name}: the wire turns back on itself (the tangents are {:.6}° apart, a 180° \
             reversal): it cannot be swept",
            angle.to_degrees()
        );
    }
    Ok(Joint {
        kind: if angle <= G1_ANGLE {
            JointKind::Smooth
        } else {
            JointKind::Corner
        },
        point: before.end(),
        incoming,
        outgoing,
        name,
    })
}

/// What one Bézier segment of a curve edge is.
enum SegmentKind {
    Line(DVec3, DVec3),
    Arc(Arc),
    Other,
    /// All control points at one point: dropped.
    Degenerate,
}

fn classify(segment: &RationalBezierCurve, size: f64) -> SegmentKind {
    let poles: Vec<DVec3> = segment.poles().collect();
    let (a, b) = (poles[0], poles[poles.len() - 1]);
    let extent = poles.iter().fold(0.0f64, |m, p| m.max(p.distance(a)));
    let tolerance = EXACT * size.max(extent);
    if extent <= EXACT * size {
        return SegmentKind::Degenerate;
    }
    let chord = b - a;
    if chord.length() > tolerance {
        let direction = chord.normalize();
        let along: Vec<f64> = poles.iter().map(|p| (*p - a).dot(direction)).collect();
        let straight = poles
            .iter()
            .all(|p| (*p - a).cross(direction).length() <= tolerance);
        if straight && along.windows(2).all(|w| w[1] >= w[0] - tolerance) {
            return SegmentKind::Line(a, b);
        }
    }
    if segment.degree() == 2 {
        let w: Vec<f64> = segment.weights().collect();
        let (l0, l1) = (poles[1] - a, b - poles[1]);
        let normalized = w[1] / (w[0] * w[2]).sqrt();
        let half_angle = angle_between(l0, chord);
        if (l0.length() - l1.length()).abs() <= EXACT * l0.length().max(l1.length())
            && (normalized - half_angle.cos()).abs() <= EXACT
            && half_angle > 0.0
        {
            if let Ok(arc) = Arc::through(a, segment.eval(0.5), b) {
                return SegmentKind::Arc(arc);
            }
        }
    }
    SegmentKind::Other
}

/// The pieces of one (oriented, snapped) edge and the joints between them.
fn edge_pieces(
    edge: &RawEdge,
    index: usize,
    size: f64,
    reversed: bool,
) -> Result<(Vec<Piece>, Vec<Joint>)> {
    let piece = |geometry| Piece {
        geometry,
        edge: index,
        corner: None,
    };
    let curve = match edge {
        RawEdge::Line(a, b) => return Ok((vec![piece(Geometry::Line { a: *a, b: *b })], vec![])),
        RawEdge::Arc(a, m, c) => {
            return Ok((
                vec![piece(Geometry::Arc(Arc::through(*a, *m, *c)?))],
                vec![],
            ))
        }
        RawEdge::Curve(c) => c,
    };
    let breaks = curve.breaks();
    let (lo, hi) = curve.domain();
    let user_parameter = |t: f64| if reversed { lo + hi - t } else { t };
    // Runs of one kind: (geometry, first segment, last segment + 1).
    let mut runs: Vec<(Geometry, usize, usize)> = Vec::new();
    let mut open: Option<(usize, usize)> = None; // a run of "other" segments
    let close_open = |runs: &mut Vec<(Geometry, usize, usize)>,
                      open: &mut Option<(usize, usize)>| {
        if let Some((a, b)) = open.take() {
            runs.push((
                Geometry::Curve(
                    PiecewiseCurve::new(curve.segments()[a..b].to_vec(), breaks[a..=b].to_vec())
                        .expect("a run of segments"),
                ),
                a,
                b,
            ));
        }
    };
    for (k, segment) in curve.segments().iter().enumerate() {
        let kind = classify(segment, size);
        if matches!(kind, SegmentKind::Degenerate) {
            continue;
        }
        if let SegmentKind::Other = kind {
            if let Some((a, b)) = open {
                let smooth = angle_between(
                    end_direction(&curve.segments()[b - 1], true),
                    end_direction(segment, false),
                ) <= G1_ANGLE;
                if smooth && b == k {
                    open = Some((a, k + 1));
                    continue;
                }
            }
            close_open(&mut runs, &mut open);
            open = Some((k, k + 1));
            continue;
        }
        close_open(&mut runs, &mut open);
        let geometry = match kind {
            SegmentKind::Line(a, b) => Geometry::Line { a, b },
            SegmentKind::Arc(arc) => Geometry::Arc(arc),
            _ => unreachable!("handled above"),
        };
        if let Some((last, _, end)) = runs.last_mut() {
            if let Some(merged) = merge(last, &geometry, size) {
                *last = merged;
                *end = k + 1;
                continue;
            }
        }
        runs.push((geometry, k, k + 1));
    }
    close_open(&mut runs, &mut open);
    if runs.is_empty() {
        return invalid!("a curve of zero length");
    }
    // Consecutive runs must share their joint point exactly (degenerate segments between
    // them were dropped): the later one starts where the earlier one ends.
    for k in 1..runs.len() {
        let end = runs[k - 1].0.end();
        let (lo, hi) = runs[k].0.domain();
        let g = &runs[k].0;
        let moved = g.trimmed(lo, hi, end, g.end());
        runs[k].0 = moved;
    }
    let mut joints = Vec::new();
    for w in runs.windows(2) {
        let t = user_parameter(breaks[w[1].1]);
        joints.push(joint(
            &w[0].0,
            &w[1].0,
            format!("the joint inside edge {index} at t = {t}"),
        )?);
    }
    Ok((runs.into_iter().map(|(g, _, _)| piece(g)).collect(), joints))
}

/// Two consecutive pieces of one kind as one: collinear lines, arcs of one circle.
fn merge(first: &Geometry, second: &Geometry, size: f64) -> Option<Geometry> {
    match (first, second) {
        (Geometry::Line { a, b }, Geometry::Line { a: c, b: d }) => {
            let (u, v) = ((*b - *a).normalize(), (*d - *c).normalize());
            (angle_between(u, v) <= G1_ANGLE).then_some(Geometry::Line { a: *a, b: *d })
        }
        (Geometry::Arc(p), Geometry::Arc(q)) => {
            let total = p.angle + q.angle;
            (p.same_circle(q, EXACT * size.max(p.radius)) && total < TAU - 1e-9).then(|| {
                let mut arc = Arc::about(p.center, p.radius, p.normal, p.start, q.end, total);
                arc.e1 = p.e1;
                arc.e2 = p.e2;
                Geometry::Arc(arc)
            })
        }
        _ => None,
    }
}

/// The chain with every arc of more than a quarter turn split into arcs of at most a
/// quarter turn (one rational quadratic each), joined smoothly: every lateral face along an
/// arc is then a single rational span along the spine (OpenCascade's fixed-order volume
/// integration, FreeCAD's `Shape.Volume`, does not split at knots: a half circle as one face
/// of two spans reads 8e-4 off).
pub(crate) fn split_arcs(chain: Chain) -> Chain {
    let mut pieces = Vec::with_capacity(chain.pieces.len());
    let mut joints = Vec::with_capacity(chain.joints.len());
    for (i, piece) in chain.pieces.into_iter().enumerate() {
        if let Geometry::Arc(arc) = &piece.geometry {
            let n = arc.segment_count();
            let step = arc.angle / n as f64;
            let mut start = arc.start;
            for k in 0..n {
                let end = if k + 1 == n {
                    arc.end
                } else {
                    arc.point(step * (k + 1) as f64)
                };
                let part = Arc::about(arc.center, arc.radius, arc.normal, start, end, step);
                if k > 0 {
                    joints.push(Joint {
                        kind: JointKind::Smooth,
                        point: start,
                        incoming: arc.tangent(step * k as f64),
                        outgoing: part.tangent(0.0),
                        name: format!("the middle of edge {}", piece.edge),
                    });
                }
                pieces.push(Piece {
                    geometry: Geometry::Arc(part),
                    ..piece.clone()
                });
                start = end;
            }
        } else {
            pieces.push(piece);
        }
        if let Some(j) = chain.joints.get(i) {
            joints.push(j.clone());
        }
    }
    Chain {
        pieces,
        joints,
        closed: chain.closed,
    }
}

/// The signed turn about `axis` from `a` to `b` in [0, 2π).
pub(crate) fn turn_about(a: DVec3, b: DVec3, axis: DVec3) -> f64 {
    signed_angle(a, b, axis).rem_euclid(TAU)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    const UNIT: Similarity = Similarity {
        scale: 1.0,
        origin: DVec3::ZERO,
    };

    fn line(a: [f64; 3], b: [f64; 3]) -> RawEdge {
        RawEdge::Line(DVec3::from(a), DVec3::from(b))
    }

    #[test]
    fn an_arc_through_three_points_has_its_circle() {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let arc = Arc::through(DVec3::X, DVec3::new(s, s, 0.0), DVec3::Y).unwrap();
        assert!(arc.center.length() < 1e-15 && (arc.radius - 1.0).abs() < 1e-15);
        assert!((arc.angle - FRAC_PI_2).abs() < 1e-15);
        assert!((arc.normal - DVec3::Z).length() < 1e-15);
        let c = arc.curve();
        for i in 0..=10 {
            let p = c.eval(i as f64 / 10.0);
            assert!((p.length() - 1.0).abs() < 1e-15);
        }
        // Three quarters: three segments, the other way round.
        let back = Arc::through(DVec3::Y, DVec3::new(-s, -s, 0.0), DVec3::X).unwrap();
        assert_eq!(back.segment_count(), 3);
        assert!((back.angle - 1.5 * PI).abs() < 1e-14);
        assert!(Arc::through(DVec3::ZERO, DVec3::X, DVec3::X * 2.0).is_err());
    }

    #[test]
    fn edges_are_oriented_and_joined() {
        // The second line is given backwards, the third forwards.
        let edges = [
            line([0., 0., 0.], [1., 0., 0.]),
            line([1., 1., 0.], [1., 1e-9, 0.]),
            line([1., 1., 0.], [0., 1., 0.]),
        ];
        let chain = chain(&edges, 1e-7, 2.0, UNIT).unwrap();
        assert!(!chain.closed);
        assert_eq!(chain.pieces.len(), 3);
        assert_eq!(chain.joints.len(), 2);
        assert!(chain.joints.iter().all(|j| j.kind == JointKind::Corner));
        // Snapped: the second starts where the first ends.
        assert_eq!(chain.pieces[1].geometry.start(), DVec3::X);
        let gap = [
            line([0., 0., 0.], [1., 0., 0.]),
            line([1., 1e-3, 0.], [2., 0., 0.]),
        ];
        let e = super::chain(&gap, 1e-7, 2.0, UNIT).unwrap_err();
        assert!(e.message().contains("edges 0 and 1 do not meet"), "{e}");
        assert!(e.message().contains("1.000e-3"), "{e}");
    }

    #[test]
    fn reversals_and_zero_length_edges_are_refused() {
        let back = [
            line([0., 0., 0.], [1., 0., 0.]),
            line([1., 0., 0.], [0.5, 0., 0.]),
        ];
        let e = chain(&back, 1e-7, 1.0, UNIT).unwrap_err();
        assert!(e.message().contains("turns back"), "{e}");
        let zero = [line([0., 0., 0.], [0., 0., 0.])];
        let e = chain(&zero, 1e-7, 1.0, UNIT).unwrap_err();
        assert!(
            e.message().contains("edge 0") && e.message().contains("zero length"),
            "{e}"
        );
    }

    #[test]
    fn nurbs_lines_and_arcs_are_recognised() {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let quarter = RationalBezierCurve::from_weighted(
            &[DVec3::X, DVec3::new(1., 1., 0.), DVec3::Y],
            &[1.0, s, 1.0],
        )
        .unwrap();
        let straight = RationalBezierCurve::polynomial(&[
            DVec3::Y,
            DVec3::new(-0.5, 1.0, 0.0),
            DVec3::new(-1.0, 1.0, 0.0),
        ])
        .unwrap();
        let bent = RationalBezierCurve::polynomial(&[
            DVec3::new(-1.0, 1.0, 0.0),
            DVec3::new(-2.0, 1.0, 0.0),
            DVec3::new(-3.0, 2.0, 1.0),
            DVec3::new(-3.0, 3.0, 1.0),
        ])
        .unwrap();
        let curve = PiecewiseCurve::with_unit_intervals(vec![quarter, straight, bent]).unwrap();
        let chain = chain(&[RawEdge::Curve(curve)], 1e-7, 4.0, UNIT).unwrap();
        let kinds: Vec<&str> = chain
            .pieces
            .iter()
            .map(|p| p.geometry.kind_name())
            .collect();
        assert_eq!(kinds, ["an arc", "a line", "a curve"]);
        // The quarter ends along −x, as the line runs and the curve starts: all G1.
        assert!(chain.joints.iter().all(|j| j.kind == JointKind::Smooth));
        assert_eq!(chain.joints.len(), 2);
    }
}
