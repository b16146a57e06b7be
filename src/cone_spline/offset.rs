//! Offsets (Section "Introduction": "their offsets are of the same type"): every point of a
//! piece moved by d along the surface normal. The normal of a cone of revolution turns with
//! the rotation about the axis, so the offset of a piece is the same motion applied to the
//! offset first ruling: the same axis and half angle, the vertex shifted along the axis, and
//! the G1 junctions kept (the normals agree along shared rulings). Exact — for thickening
//! sheet metal.

use super::spline::ConeSpline;
use crate::error::{invalid, Result};

impl ConeSpline {
    /// The offset at signed distance `d` (towards n = e × p for d > 0).
    pub fn offset(&self, d: f64) -> Result<Self> {
        if !d.is_finite() {
            return invalid!("the offset distance d = {d} is not finite");
        }
        let pieces = self
            .pieces()
            .iter()
            .map(|p| {
                let mut moved = *p;
                moved.start.point += d * p.start.normal();
                moved
            })
            .collect();
        Self::new(pieces)
    }
}
