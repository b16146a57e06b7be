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

#[cfg(test)]
mod tests {
    use super::super::test_support::cubic_hermite;

    #[test]
    fn offset_points_are_at_distance_d_along_the_normal() {
        let spline = cubic_hermite(&[0.3, 0.6, 0.9]);
        for d in [0.05, -0.08] {
            let offset = spline.offset(d).unwrap();
            let (a, b) = (
                spline.surface(-0.2, 0.2).unwrap(),
                offset.surface(-0.2, 0.2).unwrap(),
            );
            for i in 0..=8 {
                for j in 0..=32 {
                    let (u, v) = (-0.2 + 0.05 * i as f64, 4.0 * j as f64 / 32.0);
                    let jet = a.eval_jet(u, v);
                    let normal = jet.du.cross(jet.dv).normalize();
                    let gap = b.eval(u, v) - jet.point;
                    assert!((gap.length() - d.abs()).abs() < 1e-12);
                    assert!(gap.cross(normal).length() < 1e-12);
                    assert!((spline.distance(b.eval(u, v)) - d.abs()).abs() < 1e-12);
                }
            }
            for (p, q) in spline.pieces().iter().zip(offset.pieces()) {
                assert!((p.half_angle() - q.half_angle()).abs() < 1e-12);
                assert!(p.axis().cross(q.axis()).length() < 1e-12);
            }
        }
        assert!(spline.offset(f64::NAN).is_err());
    }
}
