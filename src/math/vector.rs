//! Validation and normalization of input vectors, with messages naming the argument.
//!
//! Normalization scales by the largest component first, so that vectors near the
//! underflow or overflow range (1e-300, 1e300) are still normalized correctly.

use crate::error::{invalid, Result};
use glam::DVec3;
use std::fmt::Display;

/// Relative size below which a projected vector counts as zero.
const PARALLEL_TOLERANCE: f64 = 1e-12;

/// The length of the diagonal of the axis-aligned box around `points` (a model's size,
/// for relative tolerances); 0 for no points.
pub(crate) fn bounding_diagonal(points: impl IntoIterator<Item = DVec3>) -> f64 {
    let (lo, hi) = points
        .into_iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p), hi.max(p))
        });
    if lo.x > hi.x {
        0.0
    } else {
        // Halved first: hi − lo and its squares stay finite for any finite points.
        2.0 * robust_length(0.5 * hi - 0.5 * lo)
    }
}

/// The largest absolute coordinate of `points` (the rounding of each is ε times it); 0 for
/// no points.
pub(crate) fn largest_coordinate(points: impl IntoIterator<Item = DVec3>) -> f64 {
    points
        .into_iter()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()))
}

/// `v` itself if all its components are finite. The `name` of the argument in the message is
/// any `Display` (e.g. `format_args!("points[{i}]")`), formatted only for a failure: long
/// input arrays are checked without a string per element.
pub fn check_finite(v: DVec3, name: impl Display) -> Result<DVec3> {
    if v.is_finite() {
        Ok(v)
    } else {
        invalid!(
            "{name} has a non-finite component ({}, {}, {})",
            v.x,
            v.y,
            v.z
        )
    }
}

/// Alias of [`check_finite`] for points, for readability at call sites.
pub(crate) fn check_point(p: DVec3, name: impl Display) -> Result<DVec3> {
    check_finite(p, name)
}

/// |v| without overflow or underflow in the squares: for components beyond 1e154 (or
/// below 1e-154) `v.length()` overflows to ∞ (or underflows to 0).
pub fn robust_length(v: DVec3) -> f64 {
    let largest = v.abs().max_element();
    if largest == 0.0 || !largest.is_finite() {
        return largest;
    }
    largest * (v / largest).length()
}

/// `v / |v|` without underflow or overflow in the squares, or `None` for zero, subnormal or
/// non-finite vectors.
pub fn robust_normalize(v: DVec3) -> Option<DVec3> {
    if !v.is_finite() {
        return None;
    }
    let largest = v.abs().max_element();
    if largest == 0.0 || !largest.is_normal() {
        return None;
    }
    let scaled = v / largest;
    Some(scaled / scaled.length())
}

/// The unit vector along `v`; `v` must be finite and non-zero (it need not be unit), and not
/// subnormal (a largest component below f64::MIN_POSITIVE ≈ 2.2e-308, whose direction double
/// precision does not resolve).
pub(crate) fn check_unit_direction(v: DVec3, name: impl Display + Copy) -> Result<DVec3> {
    check_finite(v, name)?;
    match robust_normalize(v) {
        Some(u) => Ok(u),
        None if v == DVec3::ZERO => invalid!("{name} is a zero vector and has no direction"),
        None => invalid!(
            "{name} is subnormal (largest component {}, below 2.2e-308): its direction is not \
             resolved in double precision; scale it",
            crate::error::Num(v.abs().max_element())
        ),
    }
}

/// Projects `n` onto the plane normal to the unit vector `tangent` and normalizes it.
///
/// This is how a caller's `initial_normal` becomes the first frame vector f2.
pub fn normal_plane_unit(n: DVec3, tangent: DVec3, name: &str) -> Result<DVec3> {
    let unit = check_unit_direction(n, name)?;
    let projected = unit - unit.dot(tangent) * tangent;
    if projected.length() < PARALLEL_TOLERANCE {
        return invalid!(
            "{name} is parallel to the curve tangent; it must have a component in the normal plane"
        );
    }
    // A second pass: the first leaves a component along the tangent of relative size
    // ε / |projected|, up to 1e-4 for a normal almost along the tangent.
    Ok(orthogonalized(projected, tangent).normalize())
}

/// `v` minus its component along the unit vector `axis`, projected twice: one Gram–Schmidt
/// pass leaves an error of relative size ε |v| / |result|, which matters when `v` is almost
/// along `axis`; a second pass removes it ("twice is enough").
pub(crate) fn orthogonalized(v: DVec3, axis: DVec3) -> DVec3 {
    let once = v - v.dot(axis) * axis;
    once - once.dot(axis) * axis
}

/// The angle between two non-zero vectors, atan2(|a × b|, a·b): accurate for tiny angles,
/// where acos(a·b / |a||b|) cannot resolve anything below ~1.5e-8.
pub fn angle_between(a: DVec3, b: DVec3) -> f64 {
    let (a, b) = (unit_scaled(a), unit_scaled(b));
    a.cross(b).length().atan2(a.dot(b))
}

/// `v` scaled by a power of two to components near 1 (zero and non-finite vectors as they
/// are): the same direction, exactly, with products that neither overflow nor underflow,
/// for formulas that do not depend on the length.
pub(crate) fn unit_scaled(v: DVec3) -> DVec3 {
    v * power_of_two_scale(v)
}

/// 2⁻ᵏ with 2ᵏ nearest the largest component of `v` (1 for zero or non-finite vectors):
/// multiplying by it is exact and brings the components near 1.
pub(crate) fn power_of_two_scale(v: DVec3) -> f64 {
    power_of_two_inverse(v.abs().max_element())
}

/// 2⁻ᵏ with 2ᵏ nearest |x| (1 for zero or non-finite x), k kept within ±1023 so that the
/// factor is a finite, non-zero power of two (for subnormal |x| the factor 2¹⁰²³ still
/// brings it to normal numbers): multiplying by it is exact.
pub(crate) fn power_of_two_inverse(x: f64) -> f64 {
    let x = x.abs();
    if x > 0.0 && x.is_finite() {
        2f64.powi((-x.log2().round()).clamp(-1023.0, 1023.0) as i32)
    } else {
        1.0
    }
}

/// The signed angle about the unit `axis` that turns `a` into `b` (both normal to the
/// axis), in (−π, π]: atan2(axis·(a × b), a·b).
pub(crate) fn signed_angle(a: DVec3, b: DVec3, axis: DVec3) -> f64 {
    let (a, b) = (unit_scaled(a), unit_scaled(b));
    axis.dot(a.cross(b)).atan2(a.dot(b))
}

/// Some unit vector perpendicular to the unit vector `t` (a stable choice: the cross
/// product with the coordinate axis least aligned with `t`).
pub(crate) fn orthonormal_to(t: DVec3) -> DVec3 {
    let a = t.abs();
    let axis = if a.x <= a.y && a.x <= a.z {
        DVec3::X
    } else if a.y <= a.z {
        DVec3::Y
    } else {
        DVec3::Z
    };
    t.cross(axis).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalizes_tiny_and_huge_vectors() {
        let tiny = check_unit_direction(DVec3::new(1e-300, 1e-300, 0.0), "t").unwrap();
        assert!((tiny.length() - 1.0).abs() < 1e-15);
        let huge = check_unit_direction(DVec3::new(1e300, -1e300, 1e300), "t").unwrap();
        assert!((huge.length() - 1.0).abs() < 1e-15);
    }

    /// Issue finding: a subnormal tangent was reported as "a zero vector".
    #[test]
    fn subnormal_vectors_are_named_as_such() {
        let e = check_unit_direction(DVec3::new(1e-310, 0.0, 0.0), "tangents[1]").unwrap_err();
        assert!(
            e.message()
                .starts_with("tangents[1] is subnormal (largest component 1e-310"),
            "{e}"
        );
        assert!(check_unit_direction(DVec3::new(3e-308, 0.0, 0.0), "t").is_ok());
    }

    #[test]
    fn rejects_zero_and_nan_with_the_argument_name() {
        let e = check_unit_direction(DVec3::ZERO, "tangents[2]").unwrap_err();
        assert!(e.message().contains("tangents[2]"));
        assert!(check_unit_direction(DVec3::new(f64::NAN, 0.0, 1.0), "t").is_err());
        assert!(check_unit_direction(DVec3::new(f64::INFINITY, 0.0, 1.0), "t").is_err());
    }

    #[test]
    fn angles_are_accurate_near_zero() {
        let a = DVec3::X;
        let b = DVec3::new(1.0, 1e-12, 0.0);
        assert!((angle_between(a, b) - 1e-12).abs() < 1e-24);
        assert!((angle_between(a, -a) - std::f64::consts::PI).abs() < 1e-15);
    }

    #[test]
    fn projects_into_the_normal_plane() {
        let t = DVec3::new(0.0, 0.0, 1.0);
        let n = normal_plane_unit(DVec3::new(1.0, 0.0, 5.0), t, "initial_normal").unwrap();
        assert!((n - DVec3::X).length() < 1e-15);
        assert!(normal_plane_unit(DVec3::new(0.0, 0.0, 2.0), t, "initial_normal").is_err());
        // A normal within 1e-11 of the tangent still gives f2 ⟂ t to rounding (one
        // projection alone left 6e-6).
        let t = DVec3::new(0.6, 0.8, 0.0);
        let n = normal_plane_unit(t + DVec3::new(0.3, -0.1, 0.7) * 1e-11, t, "n").unwrap();
        assert!(n.dot(t).abs() < 1e-16, "{}", n.dot(t));
        let p = orthonormal_to(DVec3::new(0.6, 0.8, 0.0));
        assert!(p.dot(DVec3::new(0.6, 0.8, 0.0)).abs() < 1e-15 && (p.length() - 1.0).abs() < 1e-15);
    }
}
