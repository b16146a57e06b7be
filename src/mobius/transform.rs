//! Möbius transformations of space (Bartoň, Jüttler & Wang, §2.2): inversions in spheres,
//! eq. (6), and reflections in planes, and their compositions.
//!
//! Each map acts on points, on tangent vectors by its differential dμ (for the unit-sphere
//! inversion, eq. (10)), and on unit vectors by the *normalized* differential d*μ (8),
//! which for an inversion centred at c is the reflection (12)
//! `d*φ_y(v) = v − 2 (v·(y − c)) (y − c) / |y − c|²` — a point-dependent orthogonal map.
//! Theorem 1 is why these matter here: d*μ carries rotation-minimizing frames of a curve to
//! rotation-minimizing frames of its image.
//!
//! Accuracy. An inversion's image of y is evaluated in coordinates centred at its centre and
//! scaled by |y − c| (no overflow or underflow in the squares: (1e200, 0, 0) in the unit
//! sphere goes to 1e-200). The maps of the Hermite construction have centres far from the
//! data (a sphere of radius 1e8 chords for nearly planar data), where c + r²(y − c)/|y − c|²
//! would cancel eight digits; they are given by a point `a` the sphere passes through, its
//! unit normal n̂ there and its signed curvature κ (centre a − n̂/κ), and evaluated as
//!
//! ```text
//!   φ(y) = a + (Δ − 2(n̂·Δ) n̂ − κ|Δ|² n̂) / |n̂ + κΔ|²,   Δ = y − a,
//! ```
//!
//! which has no cancellation, and at κ = 0 is the reflection in the plane through `a`
//! normal to n̂: the family is continuous from spheres to planes.

use crate::error::{invalid, Result};
use crate::math::{check_finite, check_unit_direction, robust_length, robust_normalize};
use glam::DVec3;

/// One inversion: in a sphere, or in a plane (a reflection, which fixes ∞).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Inversion {
    /// y ↦ c + r² (y − c) / |y − c|², eq. (6); c ↔ ∞.
    Sphere {
        /// The centre c.
        center: DVec3,
        /// The radius r > 0.
        radius: f64,
    },
    /// Reflection in the plane through `point` with unit `normal`.
    Plane {
        /// A point of the plane.
        point: DVec3,
        /// Its unit normal.
        normal: DVec3,
    },
    /// The inversion in the sphere through `point` with unit `normal` there and signed
    /// `curvature` κ, i.e. centred at point − normal/κ with radius 1/|κ| (the module notes);
    /// κ = 0 is the reflection in the plane through `point` normal to `normal`. (n̂, κ) and
    /// (−n̂, −κ) are the same map.
    Through {
        /// A point of the sphere (or plane).
        point: DVec3,
        /// The unit normal there.
        normal: DVec3,
        /// The signed curvature κ of the sphere (0: the plane).
        curvature: f64,
    },
}

impl Inversion {
    /// The inversion in the sphere with `center` and `radius > 0`.
    pub fn sphere(center: DVec3, radius: f64) -> Result<Self> {
        let center = check_finite(center, "center")?;
        if !radius.is_finite() || radius <= 0.0 {
            return invalid!("radius = {radius} must be finite and positive");
        }
        Ok(Self::Sphere { center, radius })
    }

    /// The reflection in the plane through `point` with normal `normal` (any length ≠ 0).
    pub fn plane(point: DVec3, normal: DVec3) -> Result<Self> {
        Ok(Self::Plane {
            point: check_finite(point, "point")?,
            normal: check_unit_direction(normal, "normal")?,
        })
    }

    /// The image of `y`, or `None` for the centre of a sphere inversion (it goes to ∞) and
    /// for images beyond the range of f64.
    pub fn apply(&self, y: DVec3) -> Option<DVec3> {
        let image = match *self {
            Self::Sphere { center, radius } => {
                let d = y - center;
                let length = robust_length(d);
                if length == 0.0 {
                    return None;
                }
                // r²/|d| as r·(r/|d|), along the unit d/|d|: no square over- or underflows.
                center + (d / length) * (radius * (radius / length))
            }
            Self::Plane { point, normal } => y - 2.0 * (y - point).dot(normal) * normal,
            Self::Through {
                point,
                normal,
                curvature,
            } => {
                let delta = y - point;
                let axis = normal + curvature * delta;
                let q = axis.length_squared();
                if q == 0.0 {
                    return None;
                }
                let reflected = delta - 2.0 * delta.dot(normal) * normal;
                point + (reflected - curvature * delta.length_squared() * normal) / q
            }
        };
        image.is_finite().then_some(image)
    }

    /// The direction from the centre towards `y` (the axis of the reflection (12)), any
    /// length; the normal for a plane.
    fn axis(&self, y: DVec3) -> DVec3 {
        match *self {
            Self::Sphere { center, .. } => y - center,
            Self::Plane { normal, .. } => normal,
            Self::Through {
                point,
                normal,
                curvature,
            } => normal + curvature * (y - point),
        }
    }

    /// The differential dφ_y(v): r² (|d|² v − 2 (v·d) d) / |d|⁴ with d = y − c, eq. (10)
    /// scaled to radius r, i.e. (r/|d|)² times the reflection (12); a plane reflection is its
    /// own differential.
    pub fn differential(&self, y: DVec3, v: DVec3) -> DVec3 {
        let stretch = match *self {
            Self::Sphere { center, radius } => {
                let ratio = radius / robust_length(y - center);
                ratio * ratio
            }
            Self::Plane { .. } => 1.0,
            Self::Through { .. } => 1.0 / self.axis(y).length_squared(),
        };
        self.normalized_differential(y, v) * stretch
    }

    /// The normalized differential d*φ_y(v), eq. (12): length-preserving.
    pub fn normalized_differential(&self, y: DVec3, v: DVec3) -> DVec3 {
        let axis = match robust_normalize(self.axis(y)) {
            Some(unit) => unit,
            None => return v,
        };
        v - 2.0 * v.dot(axis) * axis
    }

    /// The centre of a sphere inversion (`None` for planes).
    pub fn center(&self) -> Option<DVec3> {
        match *self {
            Self::Sphere { center, .. } => Some(center),
            Self::Plane { .. } => None,
            Self::Through {
                point,
                normal,
                curvature,
            } => (curvature != 0.0).then(|| point - normal / curvature),
        }
    }

    /// True for an inversion in a sphere (which doubles the degree of a rational curve).
    pub fn is_sphere(&self) -> bool {
        match *self {
            Self::Sphere { .. } => true,
            Self::Plane { .. } => false,
            Self::Through { curvature, .. } => curvature != 0.0,
        }
    }
}

/// A composition of inversions, applied first to last. Every Möbius transformation of
/// space is one; translations and rotations are compositions of two plane reflections.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MobiusMap {
    inversions: Vec<Inversion>,
}

impl MobiusMap {
    /// The map applying `inversions` first to last.
    pub fn new(inversions: Vec<Inversion>) -> Self {
        Self { inversions }
    }

    /// The inversions, applied first to last.
    pub fn inversions(&self) -> &[Inversion] {
        &self.inversions
    }

    /// The inverse map: the same inversions in reverse order (each is an involution).
    pub fn inverse(&self) -> Self {
        Self {
            inversions: self.inversions.iter().rev().copied().collect(),
        }
    }

    /// True for an odd number of inversions: the map reverses orientation, so a frame
    /// (t, f₂, f₃) is carried to a left-handed one and f₃ must be negated.
    pub fn reverses_orientation(&self) -> bool {
        self.inversions.len() % 2 == 1
    }

    /// μ(y), or `None` if some inversion sends the point to ∞.
    pub fn apply(&self, y: DVec3) -> Option<DVec3> {
        self.inversions.iter().try_fold(y, |p, inv| inv.apply(p))
    }

    /// dμ_y(v), by the chain rule through the intermediate points.
    pub fn differential(&self, y: DVec3, v: DVec3) -> Option<DVec3> {
        self.push_forward(y, v, Inversion::differential)
    }

    /// d*μ_y(v), eq. (8): the normalized differentials composed.
    pub fn normalized_differential(&self, y: DVec3, v: DVec3) -> Option<DVec3> {
        self.push_forward(y, v, Inversion::normalized_differential)
    }

    fn push_forward(
        &self,
        y: DVec3,
        v: DVec3,
        step: impl Fn(&Inversion, DVec3, DVec3) -> DVec3,
    ) -> Option<DVec3> {
        let mut point = y;
        let mut vector = v;
        for inv in &self.inversions {
            vector = step(inv, point, vector);
            point = inv.apply(point)?;
        }
        Some(vector)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn composite() -> MobiusMap {
        MobiusMap::new(vec![
            Inversion::sphere(DVec3::new(0.3, -1.0, 2.0), 1.5).unwrap(),
            Inversion::plane(DVec3::new(0.0, 0.5, 0.0), DVec3::new(1.0, 2.0, -1.0)).unwrap(),
            Inversion::sphere(DVec3::new(-2.0, 0.0, 0.5), 0.8).unwrap(),
        ])
    }

    #[test]
    fn inversions_are_involutions_and_the_inverse_undoes_the_map() {
        let map = composite();
        let y = DVec3::new(0.7, 0.2, -0.4);
        for inv in map.inversions() {
            let back = inv.apply(inv.apply(y).unwrap()).unwrap();
            assert!((back - y).length() < 1e-14);
        }
        let there = map.apply(y).unwrap();
        assert!((map.inverse().apply(there).unwrap() - y).length() < 1e-13);
        let center = DVec3::new(0.3, -1.0, 2.0);
        assert!(
            map.apply(center).is_none(),
            "the first centre goes to infinity"
        );
    }

    #[test]
    fn differential_matches_finite_differences_and_normalizes_to_an_isometry() {
        let map = composite();
        let (y, v) = (DVec3::new(0.7, 0.2, -0.4), DVec3::new(0.3, -0.8, 0.5));
        let h = 1e-6;
        let fd = (map.apply(y + h * v).unwrap() - map.apply(y - h * v).unwrap()) / (2.0 * h);
        let d = map.differential(y, v).unwrap();
        assert!((d - fd).length() < 1e-7 * d.length(), "{d} vs {fd}");
        let n = map.normalized_differential(y, v).unwrap();
        assert!((n.length() - v.length()).abs() < 1e-15);
        assert!(
            (n.normalize() - d.normalize()).length() < 1e-13,
            "d*μ is dμ rescaled"
        );
        // Conformal: angles between vectors are kept.
        let w = DVec3::new(-0.1, 0.4, 0.9);
        let nw = map.normalized_differential(y, w).unwrap();
        assert!((n.dot(nw) - v.dot(w)).abs() < 1e-14);
    }

    #[test]
    fn rejects_bad_spheres_and_planes() {
        assert!(Inversion::sphere(DVec3::ZERO, 0.0).is_err());
        assert!(Inversion::sphere(DVec3::ZERO, f64::NAN).is_err());
        assert!(Inversion::sphere(DVec3::new(f64::INFINITY, 0.0, 0.0), 1.0).is_err());
        assert!(Inversion::plane(DVec3::ZERO, DVec3::ZERO)
            .unwrap_err()
            .message()
            .contains("normal"));
    }

    /// Issue finding: (1e200, 0, 0) inverted in the unit sphere gave (0, 0, 0) (the square
    /// 1e400 overflowed), a sphere of radius 1e300 gave (inf, NaN, NaN). Images are now
    /// computed without squares: exact where representable, `None` where they are not.
    #[test]
    fn images_neither_underflow_nor_overflow_in_squares() {
        let unit = Inversion::sphere(DVec3::ZERO, 1.0).unwrap();
        let image = unit.apply(DVec3::new(1e200, 0.0, 0.0)).unwrap();
        assert!(
            (image.x - 1e-200).abs() < 1e-215 && image.y == 0.0,
            "{image}"
        );
        let tiny = unit.apply(DVec3::new(0.0, -3e-200, 4e-200)).unwrap();
        assert!(
            (tiny / 1e199 - DVec3::new(0.0, -1.2, 1.6)).length() < 1e-15,
            "{tiny}"
        );
        let huge = Inversion::sphere(DVec3::new(1.0, 2.0, 3.0), 1e300).unwrap();
        assert_eq!(
            huge.apply(DVec3::new(2.0, 2.0, 3.0)),
            None,
            "1e600 is not a double"
        );
        let far = huge.apply(DVec3::new(1.0, 2.0, 3.0 + 1e300)).unwrap();
        assert!((far / 1e300 - DVec3::Z).length() < 1e-15, "{far}");
        let d = unit.differential(DVec3::new(1e200, 0.0, 0.0), DVec3::Y);
        assert!((d.y - 1e-400f64.max(0.0)).abs() <= f64::MIN_POSITIVE && d.is_finite());
        let n = unit.normalized_differential(DVec3::new(1e200, 0.0, 0.0), DVec3::X);
        assert_eq!(n, -DVec3::X);
    }
}
