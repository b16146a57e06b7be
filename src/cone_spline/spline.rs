//! A cone spline surface: a G1 sequence of cone, cylinder and plane pieces, each starting
//! on the last ruling of the one before, with the same tangent plane there.
//!
//! The reference points are propagated along the chain (each piece starts where the one
//! before moved its reference point), so a signed distance t along the rulings names one
//! parallel-circle arc spline across the whole surface: the bounds of surface patches,
//! the boundary curves that develop into planar arc splines, and the strips of offsets.

use super::element::Element;
use super::pair::{cone_pair, ConePair, Rule};
use super::piece::ConePiece;
use super::region::Region;
use crate::error::no_solution;
use crate::error::{invalid, Result};

/// Tolerance of the G1 check between consecutive pieces (unit vectors; lengths relative).
const CHAIN_TOLERANCE: f64 = 1e-9;

/// A G1 chain of cone pieces.
#[derive(Clone, Debug, PartialEq)]
pub struct ConeSpline {
    pieces: Vec<ConePiece>,
}

impl ConeSpline {
    /// Chains pieces: each must start on the previous end ruling with the same ruling
    /// orientation and tangent plane; its reference point becomes the previous end point.
    pub fn new(pieces: Vec<ConePiece>) -> Result<Self> {
        if pieces.is_empty() {
            return invalid!("a cone spline needs at least one piece");
        }
        let mut chained: Vec<ConePiece> = Vec::with_capacity(pieces.len());
        for (k, piece) in pieces.into_iter().enumerate() {
            let piece = match chained.last() {
                None => piece,
                Some(previous) => {
                    let end = previous.end();
                    let s = &piece.start;
                    let scale = end.point.abs().max_element().max(1.0);
                    // robust_length: the offset of splines of size 1e200 squares to ∞.
                    let off_line =
                        crate::math::robust_length((s.point - end.point).cross(end.ruling));
                    if (s.ruling - end.ruling).length() > CHAIN_TOLERANCE
                        || (s.normal() - end.normal()).length() > CHAIN_TOLERANCE
                        || off_line > CHAIN_TOLERANCE * scale
                    {
                        return no_solution!(
                            "piece {k} does not start on the end ruling and tangent plane of piece {}",
                            k - 1
                        );
                    }
                    ConePiece {
                        start: end,
                        ..piece
                    }
                }
            };
            chained.push(piece);
        }
        Ok(Self { pieces: chained })
    }

    /// G1 Hermite interpolation of a sequence of elements by cone pairs (one pair, or one
    /// plane piece, between consecutive elements), the pairs chosen by `rule` with no
    /// vertex in `region`. Returns the spline and the pairs (case, sphere, biarc, μ).
    pub fn hermite(
        elements: &[Element],
        rule: Rule,
        region: Option<&Region>,
    ) -> Result<(Self, Vec<ConePair>)> {
        if elements.len() < 2 {
            return invalid!(
                "count = {} but a cone spline needs at least 2 elements",
                elements.len()
            );
        }
        if let Some(r) = region {
            if let Some(i) = elements.iter().position(|e| !r.contains(e.point)) {
                return invalid!("elements[{i}].point lies outside the region of interest");
            }
        }
        let pairs = elements
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                let names = (format!("elements[{i}]"), format!("elements[{}]", i + 1));
                cone_pair(&w[0], &w[1], rule, region, (&names.0, &names.1)).map_err(|e| {
                    if e.is(crate::ErrorKind::NoSolution) {
                        e.context(format!("between {} and {}", names.0, names.1))
                    } else {
                        e
                    }
                })
            })
            .collect::<Result<Vec<_>>>()?;
        let spline = Self::new(
            pairs
                .iter()
                .flat_map(|p| p.pieces.iter().copied())
                .collect(),
        )?;
        Ok((spline, pairs))
    }

    pub fn pieces(&self) -> &[ConePiece] {
        &self.pieces
    }

    /// The first element (first ruling, tangent plane and reference point).
    pub fn first(&self) -> Element {
        self.pieces[0].start
    }

    /// Distance from `y` to the surface extended along its rulings (minimum over pieces).
    pub fn distance(&self, y: glam::DVec3) -> f64 {
        self.pieces
            .iter()
            .map(|p| p.distance(y))
            .fold(f64::INFINITY, f64::min)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn chains_reference_points_and_rejects_gaps() {
        let a = Element::new(DVec3::new(1.0, 0.0, 0.0), DVec3::Z, DVec3::Y, "a").unwrap();
        let first = ConePiece::cylinder(a, DVec3::new(0.0, 1.0, 0.0)).unwrap();
        let shifted = first.end().with_point(first.end().point + DVec3::Z * 3.0);
        let second = ConePiece::cylinder(shifted, DVec3::new(-1.0, 0.0, 0.0)).unwrap();
        let spline = ConeSpline::new(vec![first, second]).unwrap();
        assert!((spline.pieces()[1].start.point - DVec3::new(0.0, 1.0, 0.0)).length() < 1e-15);
        let off = ConePiece::cylinder(
            a.with_point(DVec3::new(5.0, 0.0, 0.0)),
            DVec3::new(5.0, 1.0, 0.0),
        )
        .unwrap();
        assert!(ConeSpline::new(vec![first, off]).is_err());
    }
}
