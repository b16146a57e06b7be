//! The scale law of a wire sweep: the profile scaled by σ(s) = σ₀ + (σ₁ − σ₀) s/L, linear in
//! arc length s along the whole wire of length L, so that the sweep is
//! s(u, v) = x(v) + σ(v) (c₂(u) f₂(v) + c₃(u) f₃(v)) — Mäurer & Jüttler (1) with the
//! profile scaled, still a rational patch when σ is a polynomial in the spine's parameter:
//!
//! * on a line σ is linear in its parameter: exact, the ruled patch between two scaled
//!   sections (a cone frustum for a circle);
//! * on a PH piece the arc length is a polynomial (a cubic per PH cubic, Farouki's
//!   hallmark of PH curves), so σ is one too: exact, the degree along the spine raised by 3;
//! * on an arc the rational parameter is not proportional to the angle; σ is taken linear
//!   in the parameter of each rational quadratic segment, exact at its ends, and the arc is
//!   cut into enough segments for that to stay within the tolerance (`arc_segments`).

use crate::bezier::bernstein::restrict;
use crate::bezier::locate;
use crate::bezier::PiecewiseCurve;
use crate::error::Result;
use crate::math::lerp;
use crate::ph_cubic::spline::ph_cubics;

/// Samples of an arc segment's parameter at which its angle is compared with a linear one.
const ARC_SAMPLES: usize = 32;

/// Most segments per quarter turn an arc is cut into for a scale law (2⁻¹⁰ of a quarter).
const MAX_ARC_SEGMENTS: usize = 1 << 10;

/// σ along the wire (normalized lengths).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ScaleLaw {
    pub start: f64,
    pub end: f64,
    /// The wire's length.
    pub length: f64,
}

impl ScaleLaw {
    /// The identity law.
    pub fn none() -> Self {
        Self {
            start: 1.0,
            end: 1.0,
            length: 1.0,
        }
    }

    pub fn is_constant(&self) -> bool {
        self.start == self.end
    }

    /// σ at arc length s.
    pub fn at(&self, s: f64) -> f64 {
        if self.is_constant() {
            return self.start;
        }
        lerp(self.start, self.end, (s / self.length).clamp(0.0, 1.0))
    }

    /// The largest scale.
    pub fn max(&self) -> f64 {
        self.start.max(self.end)
    }

    /// |dσ/ds|.
    pub fn slope(&self) -> f64 {
        (self.end - self.start).abs() / self.length
    }
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
    pub fn new(spine: &PiecewiseCurve, kind: SpineKind, s0: f64, law: &ScaleLaw) -> Result<Self> {
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
    pub fn ends(&self) -> (f64, f64) {
        let last = &self.segments[self.segments.len() - 1];
        (self.segments[0][0], last[last.len() - 1])
    }

    /// σ's Bernstein coefficients on [v0, v1], which lies in one segment of the spine.
    pub fn on(&self, v0: f64, v1: f64) -> Vec<f64> {
        let (k, _) = locate(&self.breaks, 0.5 * (v0 + v1));
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        let local = |v: f64| ((v - a) / (b - a)).clamp(0.0, 1.0);
        restrict(&self.segments[k], local(v0), local(v1))
    }
}
