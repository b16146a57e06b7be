//! The region of interest Ω (Section "Fundamentals"): an axis-aligned box in which the cone
//! spline must be free of singularities. Vertices inside Ω are not admissible (Figs. 5–6),
//! and a box also yields the widest strip of a cone spline inside it.

use crate::error::{invalid, Result};
use crate::math::check_point;
use glam::DVec3;

/// An axis-aligned box `min ≤ x ≤ max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region {
    /// The corner with the smallest coordinates.
    pub min: DVec3,
    /// The corner with the largest coordinates.
    pub max: DVec3,
}

impl Region {
    /// Validates a box (finite corners, min < max in every coordinate).
    pub fn new(min: DVec3, max: DVec3) -> Result<Self> {
        check_point(min, "region.min")?;
        check_point(max, "region.max")?;
        if !min.cmplt(max).all() {
            return invalid!(
                "region.min = {min} must be less than region.max = {max} in every coordinate"
            );
        }
        Ok(Self { min, max })
    }

    /// Whether `x` lies in the closed box.
    pub fn contains(&self, x: DVec3) -> bool {
        x.cmpge(self.min).all() && x.cmple(self.max).all()
    }

    /// The parameter interval `[t_in, t_out]` of the line `point + t·direction` inside the
    /// box (slab method), or `None` if the line misses it.
    pub fn clip_line(&self, point: DVec3, direction: DVec3) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for k in 0..3 {
            let (p, d) = (point[k], direction[k]);
            if d == 0.0 {
                if p < self.min[k] || p > self.max[k] {
                    return None;
                }
                continue;
            }
            // Saturated: the distance to a face of a box near ±f64::MAX may overflow.
            let (a, b) = (
                saturate((self.min[k] - p) / d),
                saturate((self.max[k] - p) / d),
            );
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        }
        (lo <= hi).then_some((lo, hi))
    }
}

/// `x` clamped to the finite range (NaN stays NaN).
fn saturate(x: f64) -> f64 {
    x.clamp(-f64::MAX, f64::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clips_lines_and_tests_points() {
        let r = Region::new(DVec3::ZERO, DVec3::ONE).unwrap();
        assert!(r.contains(DVec3::splat(0.5)) && !r.contains(DVec3::new(0.5, 0.5, 1.5)));
        let (a, b) = r.clip_line(DVec3::new(-1.0, 0.5, 0.5), DVec3::X).unwrap();
        assert!((a - 1.0).abs() < 1e-15 && (b - 2.0).abs() < 1e-15);
        assert!(r.clip_line(DVec3::new(-1.0, 2.0, 0.5), DVec3::X).is_none());
        assert!(Region::new(DVec3::ONE, DVec3::ZERO).is_err());
    }
}
