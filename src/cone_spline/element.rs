//! G1 Hermite elements (Section "G1 Hermite elements"): a ruling e_i with its tangent plane
//! τ_i, given by a point l_i on the ruling, the unit ruling direction e_i and the unit side
//! vector p_i (in τ_i, normal to e_i, pointing to where the next piece attaches). The
//! normal n_i = e_i × p_i then points to the same side of the surface all along a sequence
//! (Fig. 2).
//!
//! The point l_i also says *where* the surface is wanted on the ruling: it decides which
//! nappe of a cone is used (the test (a − v)·(d − v) > 0 of Figs. 5–6) and is the origin of
//! the distances along the rulings that bound a surface.

use crate::error::{invalid, Result};
use crate::math::{check_point, check_unit_direction};
use glam::DVec3;

/// Largest |cos| between the given side vector and ruling that is accepted as "normal";
/// the side vector is then made exactly normal by projection.
const SIDE_NORMAL_TOLERANCE: f64 = 1e-6;

/// A ruling with its tangent plane: point l, unit direction e, unit side vector p ⊥ e.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Element {
    /// l: a point on the ruling where the surface is wanted.
    pub point: DVec3,
    /// e: unit direction of the ruling (the orientation of the generators).
    pub ruling: DVec3,
    /// p: unit vector in the tangent plane, normal to e, towards the next piece.
    pub side: DVec3,
}

impl Element {
    /// Validates an element; `name` is how the C caller calls it (e.g. `elements[2]`).
    /// Directions may have any non-zero length; `side` must be normal to `ruling` up to
    /// round-off (|cos| ≤ 1e-6) and is then orthogonalized exactly.
    pub fn new(point: DVec3, ruling: DVec3, side: DVec3, name: &str) -> Result<Self> {
        let point = check_point(point, format_args!("{name}.point"))?;
        let e = check_unit_direction(ruling, &format!("{name}.ruling"))?;
        let p = check_unit_direction(side, &format!("{name}.side"))?;
        let cos = p.dot(e);
        if cos.abs() > SIDE_NORMAL_TOLERANCE {
            return invalid!(
                "{name}.side is not normal to {name}.ruling (cos of their angle = {cos:.3e}); \
                 the side vector must lie in the tangent plane, normal to the ruling"
            );
        }
        Ok(Self::from_frame(point, e, (p - cos * e).normalize()))
    }

    /// An element from an already orthonormal pair (e, p).
    pub(crate) fn from_frame(point: DVec3, ruling: DVec3, side: DVec3) -> Self {
        Self {
            point,
            ruling,
            side,
        }
    }

    /// n = e × p, the unit normal of the tangent plane.
    pub fn normal(&self) -> DVec3 {
        self.ruling.cross(self.side)
    }

    /// The point at signed distance `t` from `point` along the ruling.
    pub fn at(&self, t: f64) -> DVec3 {
        self.point + t * self.ruling
    }

    /// The same ruling and tangent plane with another reference point on the ruling.
    #[cfg(test)]
    pub(crate) fn with_point(&self, point: DVec3) -> Self {
        Self { point, ..*self }
    }

    /// The signed angle about `target`'s ruling that turns this normal into `target`'s
    /// (zero only for equal, not for opposite, tangent planes).
    pub fn tangent_plane_angle(&self, target: &Element) -> f64 {
        let (n, m) = (self.normal(), target.normal());
        crate::math::signed_angle(n, m, target.ruling)
    }

    /// Signed parameter of the point of this ruling line nearest to `x`.
    pub fn parameter_of(&self, x: DVec3) -> f64 {
        (x - self.point).dot(self.ruling)
    }
}

/// Checks that two consecutive elements can be joined by a G1 surface whose normals point
/// to one side: rulings not antiparallel-parallel, not the same ruling, and normals
/// n = e × p on the same side (n₁ · n₂ > 0).
pub(crate) fn check_consecutive(
    a: &Element,
    b: &Element,
    name_a: &str,
    name_b: &str,
) -> Result<()> {
    let scale = a
        .point
        .abs()
        .max_element()
        .max(b.point.abs().max_element())
        .max(1.0);
    let parallel = a.ruling.cross(b.ruling).length() <= 1e-12;
    let offset = (b.point - a.point).cross(a.ruling).length();
    if parallel && a.ruling.dot(b.ruling) < 0.0 {
        return invalid!(
            "the rulings of {name_a} and {name_b} are parallel with opposite orientation; \
             the rulings of a sequence must be oriented consistently"
        );
    }
    if parallel && offset <= 1e-12 * scale {
        return invalid!("{name_a} and {name_b} are coincident elements (the same ruling)");
    }
    if a.normal().dot(b.normal()) <= 0.0 {
        return invalid!(
            "inconsistent side vectors: the normals e × p of {name_a} and {name_b} point to \
             opposite sides (each side vector must point to where the next piece attaches)"
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orthogonalizes_the_side_and_names_bad_arguments() {
        let e = Element::new(
            DVec3::ZERO,
            DVec3::Z * 2.0,
            DVec3::new(1.0, 0.0, 1e-9),
            "el",
        )
        .unwrap();
        assert!(e.side.dot(e.ruling).abs() < 1e-16);
        assert!((e.normal() - DVec3::Y).length() < 1e-15);
        let err = Element::new(
            DVec3::ZERO,
            DVec3::Z,
            DVec3::new(1.0, 0.0, 0.1),
            "elements[3]",
        );
        assert!(err.unwrap_err().message().contains("elements[3].side"));
        let err = Element::new(DVec3::new(f64::NAN, 0.0, 0.0), DVec3::Z, DVec3::X, "e");
        assert!(err.unwrap_err().message().contains("e.point"));
        assert!(Element::new(DVec3::ZERO, DVec3::ZERO, DVec3::X, "e").is_err());
    }

    #[test]
    fn rejects_inconsistent_neighbours() {
        let a = Element::new(DVec3::ZERO, DVec3::Z, DVec3::X, "a").unwrap();
        let opposite = Element::new(DVec3::X, -DVec3::Z, DVec3::X, "b").unwrap();
        let m = check_consecutive(&a, &opposite, "a", "b").unwrap_err();
        assert!(m.message().contains("opposite orientation"), "{m}");
        let same = Element::new(DVec3::Z * 3.0, DVec3::Z, DVec3::X, "b").unwrap();
        assert!(check_consecutive(&a, &same, "a", "b")
            .unwrap_err()
            .message()
            .contains("coincident"));
        let flipped = Element::new(DVec3::X, DVec3::Z, -DVec3::X, "b").unwrap();
        assert!(check_consecutive(&a, &flipped, "a", "b")
            .unwrap_err()
            .message()
            .contains("side vectors"));
        let good = Element::new(DVec3::X, DVec3::Z, DVec3::new(1.0, 0.1, 0.0), "b").unwrap();
        assert!(check_consecutive(&a, &good, "a", "b").is_ok());
    }
}
