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
use crate::model::{FlatPattern, PatternEdge};
use glam::DVec3;

/// |normal · z| below 1 − this is not a rotation in the plane (not a development).
const PLANAR_TOLERANCE: f64 = 1e-9;

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
            holes: vec![],
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
            holes: vec![],
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
    use glam::DVec2;

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
