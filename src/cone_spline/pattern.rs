//! The flat pattern of a cone spline strip, for laser, plasma or water-jet cutting: the
//! exact development (Section "Bending sequences and development") of the strip between
//! two distances t₀ < t₁ along the rulings, as true lines and circular arcs in the plane
//! z = 0.
//!
//! A developed cone is a plane sector about its developed vertex, a developed cylinder or
//! plane strip a parallelogram: the strip's boundary curves (parallel-circle arc splines)
//! become arcs about the sector centres and straight segments, and every ruling stays a
//! straight segment of length t₁ − t₀. The outline is the closed loop
//! lower boundary → last ruling → upper boundary (backwards) → first ruling; the rulings
//! where two pieces meet are the bend lines a brake needs to roll or press the part back.

use super::piece::Motion;
use super::spline::ConeSpline;
use crate::error::{invalid, Result};
use crate::math::{in_caller_units, robust_length};
use glam::{DVec2, DVec3};

/// |normal · z| below 1 − this is not a rotation in the plane (not a development).
const PLANAR_TOLERANCE: f64 = 1e-9;

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
        match *self {
            PatternEdge::Line { from, to } => PatternEdge::Line {
                from: from * scale,
                to: to * scale,
            },
            PatternEdge::Arc {
                center,
                radius,
                from,
                to,
                sweep,
            } => PatternEdge::Arc {
                center: center * scale,
                radius: radius * scale,
                from: from * scale,
                to: to * scale,
                sweep,
            },
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

/// The cutting outline and the bend lines of a developed strip.
#[derive(Clone, Debug, PartialEq)]
pub struct FlatPattern {
    /// A closed loop: each edge starts where the one before ends.
    pub outline: Vec<PatternEdge>,
    /// The rulings between consecutive pieces, from the t₀ side to the t₁ side.
    pub bend_lines: Vec<PatternEdge>,
}

impl FlatPattern {
    /// The area enclosed by the outline, positive when it runs counter-clockwise (Green's
    /// theorem: the chords of its edges, plus the circular segments of its arcs). Summed in
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

impl ConeSpline {
    /// The flat pattern of the strip between the signed distances `t0 < t1` along the
    /// rulings: the spline is developed (its first ruling along +x, the development in
    /// z = 0) and each piece's boundaries become lines and arcs.
    pub fn flat_pattern(&self, t0: f64, t1: f64) -> Result<FlatPattern> {
        self.check_bounds(t0, t1)?;
        // Developed at unit size and scaled back: the lengths of a pattern 1e200 across
        // (or 1e-200) would overflow (or underflow) in the squares of the construction.
        let (unit, scale) = self.unit_size()?;
        let unit = unit.flat_pattern_unit(t0 / scale, t1 / scale)?;
        let scaled = |edges: &[PatternEdge]| edges.iter().map(|e| e.scaled(scale)).collect();
        Ok(FlatPattern {
            outline: scaled(&unit.outline),
            bend_lines: scaled(&unit.bend_lines),
        })
    }

    /// [`Self::flat_pattern`] of a unit-size spline.
    fn flat_pattern_unit(&self, t0: f64, t1: f64) -> Result<FlatPattern> {
        let flat = self.developed()?;
        let mut lower = Vec::with_capacity(flat.pieces().len());
        let mut upper = Vec::with_capacity(flat.pieces().len());
        for piece in flat.pieces() {
            lower.push(path_edge(&piece.motion, piece.start.at(t0))?);
            upper.push(path_edge(&piece.motion, piece.start.at(t1))?);
        }
        let ruling = |k: usize| {
            let el = match k {
                k if k < flat.pieces().len() => flat.pieces()[k].start,
                _ => flat.pieces()[k - 1].end(),
            };
            line(el.at(t0), el.at(t1))
        };
        let n = flat.pieces().len();
        let mut outline = lower;
        outline.push(ruling(n));
        outline.extend(upper.iter().rev().map(PatternEdge::reversed));
        outline.push(ruling(0).reversed());
        Ok(FlatPattern {
            outline,
            bend_lines: (1..n).map(ruling).collect(),
        })
    }
}

fn line(from: DVec3, to: DVec3) -> PatternEdge {
    PatternEdge::Line {
        from: from.truncate(),
        to: to.truncate(),
    }
}

/// The path of the point `y` under a developed piece's motion: a segment for a
/// translation, an arc about the rotation centre (the developed vertex) for a rotation.
fn path_edge(motion: &Motion, y: DVec3) -> Result<PatternEdge> {
    let end = motion.point(y, 1.0);
    match *motion {
        Motion::Translation(_) => Ok(line(y, end)),
        Motion::Rotation {
            origin,
            axis,
            angle,
        } => {
            if axis.z.abs() < 1.0 - PLANAR_TOLERANCE {
                return invalid!(
                    "a developed piece rotates about {axis}, not about the plane's normal"
                );
            }
            let center = origin.truncate();
            Ok(PatternEdge::Arc {
                center,
                radius: (y.truncate() - center).length(),
                from: y.truncate(),
                to: end.truncate(),
                sweep: angle * axis.z.signum(),
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_support::cubic_hermite;
    use super::*;

    #[test]
    fn the_outline_is_closed_and_as_long_as_the_surface_boundary() {
        let spline = cubic_hermite(&[0.3, 0.5, 0.7, 0.9]);
        let (t0, t1) = (-0.3, 0.3);
        let pattern = spline.flat_pattern(t0, t1).unwrap();
        let n = spline.pieces().len();
        assert_eq!(pattern.outline.len(), 2 * n + 2);
        assert_eq!(pattern.bend_lines.len(), n - 1);
        for (k, edge) in pattern.outline.iter().enumerate() {
            let next = &pattern.outline[(k + 1) % pattern.outline.len()];
            assert!(
                edge.end().distance(next.start()) < 1e-13,
                "gap after edge {k}"
            );
        }
        // Arcs: both ends on the circle; the swept angle reproduces the end point.
        for edge in &pattern.outline {
            if let PatternEdge::Arc {
                center,
                radius,
                from,
                to,
                sweep,
            } = *edge
            {
                assert!((from.distance(center) - radius).abs() < 1e-13 * radius.max(1.0));
                let turned = center + DVec2::from_angle(sweep).rotate(from - center);
                assert!(turned.distance(to) < 1e-12);
            }
        }
        // Isometry: the pattern's lower and upper boundaries are as long as the surface's.
        for (t, edges) in [
            (t0, &pattern.outline[..n]),
            (t1, &pattern.outline[n + 1..2 * n + 1]),
        ] {
            let spatial = spline.boundary(t).unwrap().arc_length();
            let flat: f64 = edges.iter().map(PatternEdge::length).sum();
            assert!(
                (spatial - flat).abs() < 1e-12 * spatial,
                "{spatial} vs {flat}"
            );
        }
        for edge in pattern
            .outline
            .iter()
            .filter(|e| matches!(e, PatternEdge::Line { .. }))
        {
            assert!((edge.length() - (t1 - t0)).abs() < 1e-13);
        }
        let (lo, hi) = pattern.bounds();
        assert!(lo.cmplt(hi).all());
        assert!(spline.flat_pattern(0.3, 0.3).is_err());
    }
}
