//! The scale law of a wire sweep: the profile scaled by σ(s), piecewise linear in arc
//! length s along the whole wire — from σ₀ at its start through given knots to σ₁ at its
//! end — so that the sweep is s(u, v) = x(v) + σ(v) (c₂(u) f₂(v) + c₃(u) f₃(v)) — Mäurer &
//! Jüttler (1) with the profile scaled, still a rational patch when σ is a polynomial in the
//! spine's parameter. The wire is cut at the knots (`split_at_knots`), so that σ is linear
//! along every piece:
//!
//! * on a line σ is linear in its parameter: exact, the ruled patch between two scaled
//!   sections (a cone frustum for a circle);
//! * on a PH piece the arc length is a polynomial (a cubic per PH cubic, Farouki's
//!   hallmark of PH curves), so σ is one too: exact, the degree along the spine raised by 3;
//! * on an arc the rational parameter is not proportional to the angle; σ is taken linear
//!   in the parameter of each rational quadratic segment, exact at its ends, and the arc is
//!   cut into enough segments for that to stay within the tolerance (`arc_segments`).
//!
//! A knot sits at its fraction of the wire's length measured on the given edges (with
//! their round corners); σ is then linear in the swept spine's own arc length between the
//! knots, which lie on piece boundaries.

use super::edge::{Chain, Geometry, Joint, JointKind, Piece};
use crate::bezier::bernstein::restrict;
use crate::bezier::locate;
use crate::bezier::PiecewiseCurve;
use crate::error::Result;
use crate::math::{bisect_root, lerp, GaussLegendre};
use crate::model::Arc;
use crate::ph_cubic::spline::ph_cubics;

/// Samples of an arc segment's parameter at which its angle is compared with a linear one.
const ARC_SAMPLES: usize = 32;

/// Most segments per quarter turn an arc is cut into for a scale law (2⁻¹⁰ of a quarter).
const MAX_ARC_SEGMENTS: usize = 1 << 10;

/// A knot closer than this (relative to the wire's length) to a piece boundary is put on it.
const KNOT_SNAP: f64 = 1e-9;

/// σ along the wire (normalized lengths): linear between knots (arc length, σ), the first
/// at 0, the last at the wire's length.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ScaleLaw {
    knots: Vec<(f64, f64)>,
}

impl ScaleLaw {
    /// The identity law.
    pub(super) fn none() -> Self {
        Self::linear(1.0, 1.0, 1.0)
    }

    /// From `start` to `end` over a wire of `length`.
    pub(super) fn linear(start: f64, end: f64, length: f64) -> Self {
        Self {
            knots: vec![(0.0, start), (length, end)],
        }
    }

    /// From `start` through `values` (piece index starting at the knot, σ) to `end`, on
    /// pieces of `lengths`.
    pub(super) fn on_pieces(
        start: f64,
        values: &[(usize, f64)],
        end: f64,
        lengths: &[f64],
    ) -> Self {
        let at = |piece: usize| lengths[..piece].iter().sum::<f64>();
        let mut knots = vec![(0.0, start)];
        knots.extend(values.iter().map(|&(piece, value)| (at(piece), value)));
        knots.push((at(lengths.len()), end));
        Self { knots }
    }

    pub(super) fn is_constant(&self) -> bool {
        self.knots.iter().all(|k| k.1 == self.knots[0].1)
    }

    /// σ at arc length s.
    pub(super) fn at(&self, s: f64) -> f64 {
        if self.is_constant() {
            return self.knots[0].1;
        }
        let i = self
            .knots
            .partition_point(|k| k.0 <= s)
            .clamp(1, self.knots.len() - 1);
        let ((s0, a), (s1, b)) = (self.knots[i - 1], self.knots[i]);
        if s1 <= s0 {
            return b;
        }
        lerp(a, b, ((s - s0) / (s1 - s0)).clamp(0.0, 1.0))
    }

    /// The largest scale.
    pub(super) fn max(&self) -> f64 {
        self.knots.iter().fold(0.0, |m, k| m.max(k.1))
    }

    /// The largest |dσ/ds|.
    pub(super) fn slope(&self) -> f64 {
        self.knots
            .windows(2)
            .filter(|w| w[1].0 > w[0].0)
            .map(|w| (w[1].1 - w[0].1).abs() / (w[1].0 - w[0].0))
            .fold(0.0, f64::max)
    }
}

/// The chain cut where the knots at `fractions` (increasing, in (0, 1)) of its length lie
/// inside a piece; with, for each knot, the index of the piece that starts at it.
pub(crate) fn split_at_knots(chain: Chain, fractions: &[f64]) -> Result<(Chain, Vec<usize>)> {
    let lengths: Vec<f64> = chain.pieces.iter().map(|p| p.geometry.length()).collect();
    let total: f64 = lengths.iter().sum();
    let snap = KNOT_SNAP * total;
    let mut pieces = Vec::with_capacity(chain.pieces.len() + fractions.len());
    let mut joints = Vec::with_capacity(chain.joints.len() + fractions.len());
    let mut starts = Vec::with_capacity(fractions.len());
    let mut knots = fractions.iter().map(|f| f * total).peekable();
    let mut s0 = 0.0;
    for (i, (piece, length)) in chain.pieces.into_iter().zip(&lengths).enumerate() {
        let mut rest = piece;
        let mut offset = 0.0;
        while let Some(&s) = knots.peek() {
            let along = s - s0 - offset;
            if along <= snap {
                // On the boundary where this piece (or its last part) starts.
                starts.push(pieces.len());
                knots.next();
            } else if along < length - offset - snap {
                let (first, second, joint) = split_piece(
                    &rest,
                    along,
                    &format!("the scale knot at {:.6} of the wire's length", s / total),
                )?;
                pieces.push(first);
                joints.push(joint);
                starts.push(pieces.len());
                knots.next();
                offset += along;
                rest = second;
            } else {
                break;
            }
        }
        pieces.push(rest);
        s0 += length;
        if let Some(j) = chain.joints.get(i) {
            joints.push(j.clone());
        }
    }
    // Knots within the snap of the end (not possible for fractions below 1 but rounding).
    starts.extend(knots.map(|_| pieces.len() - 1));
    Ok((
        Chain {
            pieces,
            joints,
            closed: chain.closed,
        },
        starts,
    ))
}

/// `piece` cut at arc length `at` from its start: the two parts and the smooth joint.
fn split_piece(piece: &Piece, at: f64, name: &str) -> Result<(Piece, Piece, Joint)> {
    let (first, second, point, tangent) = match &piece.geometry {
        Geometry::Line { a, b } => {
            let p = a.lerp(*b, at / a.distance(*b));
            (
                Geometry::Line { a: *a, b: p },
                Geometry::Line { a: p, b: *b },
                p,
                (*b - *a).normalize(),
            )
        }
        Geometry::Arc(arc) => {
            let phi = at / arc.radius;
            let p = arc.point(phi);
            let about = |start, end, angle| {
                Geometry::Arc(Arc::about(
                    arc.center, arc.radius, arc.normal, start, end, angle,
                ))
            };
            (
                about(arc.start, p, phi),
                about(p, arc.end, arc.angle - phi),
                p,
                arc.tangent(phi),
            )
        }
        Geometry::Curve(c) => {
            let t = parameter_at_length(c, at);
            let (a, b) = split_curve(c, t)?;
            let p = c.eval(t);
            let tangent = piece.geometry.unit_tangent(t);
            (Geometry::Curve(a), Geometry::Curve(b), p, tangent)
        }
    };
    let part = |geometry| Piece {
        geometry,
        ..piece.clone()
    };
    let joint = Joint {
        kind: JointKind::Smooth,
        point,
        incoming: tangent,
        outgoing: tangent,
        name: name.to_string(),
    };
    Ok((part(first), part(second), joint))
}

/// The parameter of `curve` at arc length `length` from its start.
fn parameter_at_length(curve: &PiecewiseCurve, length: f64) -> f64 {
    let rule = GaussLegendre::new(24);
    let speed = |t: f64| curve.eval_jet(t).d1.length();
    let breaks = curve.breaks();
    // The segment holding it, then the parameter within it.
    let mut before = 0.0;
    for w in breaks.windows(2) {
        let whole = rule.integrate(w[0], w[1], speed);
        if before + whole >= length || w[1] == breaks[breaks.len() - 1] {
            let (a, b) = (w[0], w[1]);
            let target = length - before;
            let f = |t: f64| rule.integrate(a, t, speed) - target;
            return bisect_root(f, a, b, 1e-15 * (b - a).abs().max(1.0)).unwrap_or(b);
        }
        before += whole;
    }
    breaks[breaks.len() - 1]
}

/// `curve` cut at parameter `t` inside its domain.
fn split_curve(curve: &PiecewiseCurve, t: f64) -> Result<(PiecewiseCurve, PiecewiseCurve)> {
    let breaks = curve.breaks();
    let k = breaks.partition_point(|&b| b < t);
    let refined = if breaks[k] == t {
        curve.clone()
    } else {
        let mut with_t = breaks.to_vec();
        with_t.insert(k, t);
        curve.refined(&with_t)?
    };
    let (segments, breaks) = (refined.segments(), refined.breaks());
    Ok((
        PiecewiseCurve::new(segments[..k].to_vec(), breaks[..=k].to_vec())?,
        PiecewiseCurve::new(segments[k..].to_vec(), breaks[k..].to_vec())?,
    ))
}

/// The rational quadratic segments an arc of radius `radius` and angle `angle` is cut
/// into (at least `segments`, doubled) so that σ linear in each segment's parameter is
/// within `tolerance` of the law at the profile's `reach`.
pub(crate) fn arc_segments(
    segments: usize,
    angle: f64,
    radius: f64,
    law: &ScaleLaw,
    reach: f64,
    tolerance: f64,
) -> usize {
    let mut n = segments;
    while n < segments * MAX_ARC_SEGMENTS {
        let theta = angle / n as f64;
        let error = parameter_angle_deviation(theta) * radius * law.slope() * reach;
        if error <= tolerance {
            break;
        }
        n *= 2;
    }
    n
}

/// The largest |φ(t) − θt| over a rational quadratic arc segment of angle θ with its
/// symmetric weights, whose parameter is the stereographic one: φ(t) = θ/2 +
/// 2 arctan(tan(θ/4)(2t − 1)).
fn parameter_angle_deviation(theta: f64) -> f64 {
    let k = (0.25 * theta).tan();
    (0..=ARC_SAMPLES)
        .map(|i| i as f64 / ARC_SAMPLES as f64)
        .map(|t| (0.5 * theta + 2.0 * (k * (2.0 * t - 1.0)).atan() - theta * t).abs())
        .fold(0.0, f64::max)
}

/// The law on one piece: σ's Bernstein coefficients on each segment of the piece's spine.
#[derive(Clone, Debug)]
pub(crate) struct PieceScale {
    breaks: Vec<f64>,
    segments: Vec<Vec<f64>>,
}

/// How a piece's spine is parameterized, for its scale.
pub(crate) enum SpineKind {
    /// A line of this length.
    Line(f64),
    /// An arc of this radius and angle, its segments of equal angle.
    Arc { radius: f64, angle: f64 },
    /// A PH cubic spline.
    Ph,
}

impl PieceScale {
    /// σ on the piece whose spine starts at arc length `s0` of the wire.
    pub(super) fn new(
        spine: &PiecewiseCurve,
        kind: SpineKind,
        s0: f64,
        law: &ScaleLaw,
    ) -> Result<Self> {
        let n = spine.segments().len();
        let segments = match kind {
            SpineKind::Line(length) => vec![vec![law.at(s0), law.at(s0 + length)]],
            SpineKind::Arc { radius, angle } => (0..n)
                .map(|k| {
                    let s = |j: usize| s0 + radius * angle * j as f64 / n as f64;
                    vec![law.at(s(k)), law.at(s(k + 1))]
                })
                .collect(),
            SpineKind::Ph => {
                let mut s = s0;
                ph_cubics(spine)?
                    .iter()
                    .map(|cubic| {
                        let lengths = cubic.arc_length_polynomial();
                        let coefficients = lengths.iter().map(|l| law.at(s + l)).collect();
                        s += lengths[3];
                        coefficients
                    })
                    .collect()
            }
        };
        Ok(Self {
            breaks: spine.breaks().to_vec(),
            segments,
        })
    }

    /// σ at the piece's start and end.
    pub(super) fn ends(&self) -> (f64, f64) {
        let last = &self.segments[self.segments.len() - 1];
        (self.segments[0][0], last[last.len() - 1])
    }

    /// σ's Bernstein coefficients on [v0, v1], which lies in one segment of the spine.
    pub(super) fn on(&self, v0: f64, v1: f64) -> Vec<f64> {
        let (k, _) = locate(&self.breaks, 0.5 * (v0 + v1));
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        let local = |v: f64| ((v - a) / (b - a)).clamp(0.0, 1.0);
        restrict(&self.segments[k], local(v0), local(v1))
    }
}
