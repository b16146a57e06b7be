//! Flat patterns: the developed outline of a part as true lines and circular arcs in the
//! plane z = 0, with its bend lines — what cone splines develop into (Leopoldseder &
//! Pottmann, "Bending sequences and development"), sheet-metal parts are cut from, and the
//! SVG, DXF and STEP writers draw. Shared vocabulary, so that none of them depends on
//! another for it.

use crate::error::Result;
use crate::math::{in_caller_units, robust_length};
use glam::DVec2;

/// One edge of a flat pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PatternEdge {
    /// The straight segment from `from` to `to`.
    Line {
        /// The start point.
        from: DVec2,
        /// The end point.
        to: DVec2,
    },
    /// The circular arc about `center` from `from` through the signed angle `sweep`
    /// (counter-clockwise for positive sweep); `to` is its end point.
    Arc {
        /// The arc's centre.
        center: DVec2,
        /// Its radius.
        radius: f64,
        /// The start point.
        from: DVec2,
        /// The end point.
        to: DVec2,
        /// The signed angle from `from` to `to` about `center` (radians, counter-clockwise positive).
        sweep: f64,
    },
}

impl PatternEdge {
    /// The point the edge starts at.
    pub fn start(&self) -> DVec2 {
        match *self {
            PatternEdge::Line { from, .. } | PatternEdge::Arc { from, .. } => from,
        }
    }

    /// The point the edge ends at.
    pub fn end(&self) -> DVec2 {
        match *self {
            PatternEdge::Line { to, .. } | PatternEdge::Arc { to, .. } => to,
        }
    }

    /// The same edge traversed the other way.
    pub fn reversed(&self) -> Self {
        match *self {
            PatternEdge::Line { from, to } => PatternEdge::Line { from: to, to: from },
            PatternEdge::Arc {
                center,
                radius,
                from,
                to,
                sweep,
            } => PatternEdge::Arc {
                center,
                radius,
                from: to,
                to: from,
                sweep: -sweep,
            },
        }
    }

    /// The edge scaled by `scale` about the origin.
    pub fn scaled(&self, scale: f64) -> Self {
        self.mapped(|p| p * scale, scale, false)
    }

    /// The edge under a similarity `map` of the plane that multiplies lengths by `scale`
    /// and keeps the sense of turning, or reverses it (`mirror`: arcs then sweep the other
    /// way).
    pub(crate) fn mapped(&self, map: impl Fn(DVec2) -> DVec2, scale: f64, mirror: bool) -> Self {
        match *self {
            PatternEdge::Line { from, to } => PatternEdge::Line {
                from: map(from),
                to: map(to),
            },
            PatternEdge::Arc {
                center,
                radius,
                from,
                to,
                sweep,
            } => PatternEdge::Arc {
                center: map(center),
                radius: radius * scale,
                from: map(from),
                to: map(to),
                sweep: if mirror { -sweep } else { sweep },
            },
        }
    }

    /// Distance from `p` to the edge.
    pub fn distance(&self, p: DVec2) -> f64 {
        match *self {
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
                if psi.rem_euclid(std::f64::consts::TAU) <= sweep.abs() {
                    (b.length() - radius).abs()
                } else {
                    p.distance(from).min(p.distance(to))
                }
            }
        }
    }

    /// Arc length.
    pub fn length(&self) -> f64 {
        match *self {
            PatternEdge::Line { from, to } => robust_length((to - from).extend(0.0)),
            PatternEdge::Arc { radius, sweep, .. } => radius * sweep.abs(),
        }
    }
}

/// The cutting outline, its holes and the bend lines of a developed part.
#[derive(Clone, Debug, PartialEq)]
pub struct FlatPattern {
    /// A closed loop: each edge starts where the one before ends; counter-clockwise.
    pub outline: Vec<PatternEdge>,
    /// Holes and cutouts inside the outline, each a closed loop, clockwise.
    pub holes: Vec<Vec<PatternEdge>>,
    /// The rulings between consecutive pieces, from the t₀ side to the t₁ side.
    pub bend_lines: Vec<PatternEdge>,
}

impl FlatPattern {
    /// The area enclosed by the outline less the holes', positive when the outline runs
    /// counter-clockwise and the holes clockwise (Green's theorem: the chords of the
    /// edges, plus the circular segments of the arcs). Summed in
    /// coordinates scaled to the pattern's size (a power of two), so that no product
    /// overflows or underflows; refused when the area itself is outside the range of f64.
    pub fn area(&self) -> Result<f64> {
        let (lo, hi) = self.bounds();
        let size = hi.abs().max(lo.abs()).max_element();
        let scale = if size > 0.0 && size.is_finite() {
            2f64.powi(size.log2().round() as i32)
        } else {
            1.0
        };
        let unit = 0.5
            * self
                .outline
                .iter()
                .chain(self.holes.iter().flatten())
                .map(|e| {
                    let chord = (e.start() / scale).perp_dot(e.end() / scale);
                    match *e {
                        PatternEdge::Line { .. } => chord,
                        PatternEdge::Arc { radius, sweep, .. } => {
                            let r = radius / scale;
                            chord + r * r * (sweep - sweep.sin())
                        }
                    }
                })
                .sum::<f64>();
        in_caller_units(unit, scale, 2, "flat area")
    }

    /// Lower-left and upper-right corners of the box around the outline (arcs included).
    pub fn bounds(&self) -> (DVec2, DVec2) {
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        for edge in &self.outline {
            for p in edge_extremes(edge) {
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        (lo, hi)
    }
}

/// End points of an edge and, for an arc, the points where it reaches ±x or ±y.
fn edge_extremes(edge: &PatternEdge) -> Vec<DVec2> {
    let mut points = vec![edge.start(), edge.end()];
    if let PatternEdge::Arc {
        center,
        radius,
        from,
        sweep,
        ..
    } = *edge
    {
        let a0 = (from - center).to_angle();
        for quarter in 0..4 {
            let direction = quarter as f64 * std::f64::consts::FRAC_PI_2;
            // Angle from the start to this axis direction, in the sense of the sweep.
            let along = ((direction - a0) * sweep.signum()).rem_euclid(std::f64::consts::TAU);
            if along <= sweep.abs() {
                points.push(center + radius * DVec2::from_angle(direction));
            }
        }
    }
    points
}
