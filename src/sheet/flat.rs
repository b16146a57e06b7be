//! The flat pattern of a part for the cutter: the exact development of one layer ([LP]
//! "Bending sequences and development": each cone piece becomes the plane sector of angle
//! φ sin α about its developed vertex, cylinders and strips parallelograms), with the
//! part's boundary drawn as lines and circular arcs only.
//!
//! A point of piece k at the fraction f of its motion and distance ρ along the ruling
//! develops to the point at the same f and ρ of the developed piece — the angle scaling
//! φ ↦ φ sin α is linear, so fractions correspond, while the rational arc parameters of a
//! piece and of its development do not (their arcs have different angles). A boundary
//! given as ρ(v) over the arc parameter v of the formed piece is therefore drawn at
//! f(v) = θ(v)/φ, θ the angle of the standard rational quadratic arc.
//!
//! What develops into lines and arcs exactly: a constant ρ (a vertex, a parallel circle)
//! into an arc about the developed vertex or a segment of a strip; a plane section of a
//! plane piece into a segment; the rulings into segments. Every other boundary is
//! replaced by G1 biarcs (Fuhs & Stachel, eqs. (7)–(8) of [LP], [`biarc`]) within the flat
//! tolerance. The outline is closed (every edge starts where the one before ends) and
//! counter-clockwise; the bend lines are the rulings where pieces meet.
//!
//! [`biarc`]: crate::cone_spline::biarc

use super::thickness::bend_sign;
use super::trim::{fraction_of_parameter, fraction_rate, TrimKind, TrimmedSpline};
use crate::cone_spline::{ConePiece, Motion};
use crate::error::{Error, Result};
use crate::model::biarc::{biarc, equal_lambda};
use crate::model::{FlatPattern, PatternEdge};
use glam::{DVec2, DVec3};

/// Points per biarc interval at which its distance from the developed boundary is measured.
const BIARC_SAMPLES: usize = 12;
/// Deepest halving of a boundary interval for biarcs.
const MAX_BIARC_DEPTH: usize = 30;
/// Relative length below which an edge is a point (skipped).
const POINT_LENGTH: f64 = 1e-12;

/// A developed boundary curve over the formed piece's arc parameter v: point and
/// derivative.
struct Developed<'a> {
    piece: &'a ConePiece,
    /// The formed piece's angle φ (0 for translations), for v ↦ f.
    angle: f64,
    trim: &'a super::trim::Trim,
}

impl Developed<'_> {
    fn at(&self, v: f64) -> (DVec2, DVec2) {
        let f = fraction_of_parameter(self.angle, v);
        let el = self.piece.element_at(f);
        let rho = self.trim.eval(v);
        // d/df of the moved point and ruling: ω × (x − o), ω × e for a rotation ω.
        let (dp, de) = match self.piece.motion {
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => {
                let w = axis * angle;
                (w.cross(el.point - origin), w.cross(el.ruling))
            }
            Motion::Translation(t) => (t, DVec3::ZERO),
        };
        let d =
            (dp + rho * de) * fraction_rate(self.angle, v) + self.trim.derivative(v) * el.ruling;
        ((el.point + rho * el.ruling).truncate(), d.truncate())
    }
}

fn perp(v: DVec2) -> DVec2 {
    DVec2::new(-v.y, v.x)
}

/// The arc (or line) from `a` with unit tangent `t` to `c`.
fn arc_from(a: DVec2, t: DVec2, c: DVec2) -> PatternEdge {
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

/// Distance from `p` to an edge.
pub(crate) fn edge_distance(edge: &PatternEdge, p: DVec2) -> f64 {
    match *edge {
        PatternEdge::Line { from, to } => {
            let d = to - from;
            let s = ((p - from).dot(d) / d.length_squared()).clamp(0.0, 1.0);
            p.distance(from + s * d)
        }
        PatternEdge::Arc {
            center,
            radius,
            from,
            to,
            sweep,
        } => {
            let (a, b) = (from - center, p - center);
            let psi = a.perp_dot(b).atan2(a.dot(b)) * sweep.signum();
            let along = psi.rem_euclid(std::f64::consts::TAU);
            if along <= sweep.abs() {
                (b.length() - radius).abs()
            } else {
                p.distance(from).min(p.distance(to))
            }
        }
    }
}

/// G1 biarcs through the developed curve on [v0, v1] within `tolerance`, appended to `out`
/// (`scale` turns lengths into the caller's units for the message).
fn biarcs(
    curve: &Developed,
    v0: f64,
    v1: f64,
    tolerance: f64,
    scale: f64,
    depth: usize,
    out: &mut Vec<PatternEdge>,
) -> Result<()> {
    let ((a, ta), (b, tb)) = (curve.at(v0), curve.at(v1));
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
                let p = curve.at(v0 + (v1 - v0) * j as f64 / BIARC_SAMPLES as f64).0;
                edge_distance(&pair[0], p).min(edge_distance(&pair[1], p))
            })
            .fold(0.0, f64::max);
        if error <= tolerance {
            out.extend(pair);
            return Ok(());
        }
    }
    let mid = 0.5 * (v0 + v1);
    if depth >= MAX_BIARC_DEPTH || mid <= v0 || mid >= v1 {
        return Err(Error::not_converged(format!(
            "the flat boundary is not within flat_tolerance = {:.3e} of biarcs after {depth} halvings",
            tolerance * scale
        )));
    }
    biarcs(curve, v0, mid, tolerance, scale, depth + 1, out)?;
    biarcs(curve, mid, v1, tolerance, scale, depth + 1, out)
}

/// The edges of one developed boundary (trim `side` of piece `k`), in the direction of v.
fn boundary_edges(
    part: &TrimmedSpline,
    developed: &[ConePiece],
    k: usize,
    side: usize,
    tolerance: f64,
    scale: f64,
    out: &mut Vec<PatternEdge>,
) -> Result<()> {
    let formed = &part.pieces()[k];
    let piece = &developed[k];
    let trim = &part.trims[k][side];
    let curve = Developed {
        piece,
        angle: match formed.motion {
            Motion::Rotation { .. } => formed.segment_angle(),
            Motion::Translation(_) => 0.0,
        },
        trim,
    };
    let (a, b) = (curve.at(0.0).0, curve.at(1.0).0);
    match (trim.kind, piece.motion) {
        (
            TrimKind::Constant,
            Motion::Rotation {
                origin,
                axis,
                angle,
            },
        ) => {
            let centre = origin.truncate();
            let radius = (a - centre).length();
            if radius > POINT_LENGTH {
                out.push(PatternEdge::Arc {
                    center: centre,
                    radius,
                    from: a,
                    to: b,
                    sweep: angle * axis.z.signum(),
                });
            }
        }
        (TrimKind::Constant, Motion::Translation(_)) => {
            out.push(PatternEdge::Line { from: a, to: b })
        }
        (TrimKind::Plane, _) if bend_sign(formed) == 0.0 => {
            out.push(PatternEdge::Line { from: a, to: b })
        }
        _ => biarcs(&curve, 0.0, 1.0, tolerance, scale, 0, out)?,
    }
    Ok(())
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

/// The developed boundaries of a layer, before they are joined into the outline: the
/// first and the second boundary in the direction of the pieces, the first and the last
/// ruling (from the first to the second boundary), the bend lines.
pub(crate) struct FlatLayout {
    pub first: Vec<PatternEdge>,
    pub second: Vec<PatternEdge>,
    pub rulings: [PatternEdge; 2],
    pub bend_lines: Vec<PatternEdge>,
}

impl FlatLayout {
    /// The closed outline: first boundary, last ruling, second boundary backwards, first
    /// ruling backwards; point-like edges dropped, round-off gaps closed, counter-clockwise.
    pub fn pattern(&self) -> FlatPattern {
        let mut outline = self.first.clone();
        outline.push(self.rulings[1]);
        outline.extend(self.second.iter().rev().map(PatternEdge::reversed));
        outline.push(self.rulings[0].reversed());
        // Internal coordinates are of unit size.
        let mut pattern = FlatPattern {
            outline: close_loop(outline, 1.0),
            bend_lines: self.bend_lines.clone(),
        };
        if pattern.area().is_ok_and(|a| a < 0.0) {
            pattern.outline = pattern
                .outline
                .iter()
                .rev()
                .map(PatternEdge::reversed)
                .collect();
        }
        pattern
    }
}

/// The developed boundaries of the layer at distance `s` along the normals (internal units;
/// `scale` turns them into the caller's for messages).
pub(crate) fn flat_layout(
    part: &TrimmedSpline,
    s: f64,
    tolerance: f64,
    scale: f64,
) -> Result<FlatLayout> {
    let developed = part.spline.offset(s)?.developed()?;
    let pieces = developed.pieces();
    let n = pieces.len();
    let (mut first, mut second) = (Vec::new(), Vec::new());
    for k in 0..n {
        boundary_edges(part, pieces, k, 0, tolerance, scale, &mut first)?;
        boundary_edges(part, pieces, k, 1, tolerance, scale, &mut second)?;
    }
    // Developed ruling of piece k at v = 0 (k = n: the end of the last piece).
    let ruling = |k: usize| {
        let (piece, f, v) = if k < n {
            (k, 0.0, 0.0)
        } else {
            (n - 1, 1.0, 1.0)
        };
        let el = pieces[piece].element_at(f);
        let at = |side: usize| (el.point + part.trims[piece][side].eval(v) * el.ruling).truncate();
        PatternEdge::Line {
            from: at(0),
            to: at(1),
        }
    };
    Ok(FlatLayout {
        first,
        second,
        rulings: [ruling(0), ruling(n)],
        bend_lines: (1..n)
            .map(ruling)
            .filter(|e| e.length() > POINT_LENGTH)
            .collect(),
    })
}

/// Drops point-like edges and closes the round-off gaps between the others (a vertex
/// computed on two pieces differs by ~1e-12): where a line meets an arc the joint is the
/// arc's end point, between arcs the first arc's, and every arc is redrawn through its
/// joints, so that its DXF form (centre, radius, angles) gives the same end points.
fn close_loop(edges: Vec<PatternEdge>, size: f64) -> Vec<PatternEdge> {
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
