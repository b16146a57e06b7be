//! G1 Hermite data: points with unit tangents, the input of every interpolation scheme of
//! the papers (PH cubics, Möbius images, RRMF quintics). Validated once here, with messages
//! naming the C arguments (`points[i]`, `tangents[i]`, or `p0`, `t0`, `p1`, `t1`).

use crate::error::{invalid, Result};
use crate::math::{check_point, check_unit_direction, robust_length};
use glam::DVec3;
use std::fmt::Display;

/// Relative distance below which consecutive points count as coincident. A curve between
/// points closer than this against their coordinates spans fewer than about 10⁶ ulps: its
/// tangent is decided by rounding (a Möbius segment of 3e-14 at distance 1.7 can get a
/// "tangent" opposite to its derivative). CAD tolerances are far above it (OpenCascade's
/// Precision::Confusion is 1e-7).
const COINCIDENT: f64 = 1e-10;

/// Largest coordinate accepted in Hermite data. The constructions work on a unit chord and
/// scale back, so any size up to here stays finite; beyond it the chord itself (and the
/// control points built along it) can overflow to infinity.
pub(crate) const MAX_COORDINATE: f64 = 1e300;

/// One segment's G1 Hermite data: end points and unit end tangents.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HermiteSegment {
    /// The start point.
    pub p0: DVec3,
    /// The unit tangent at the start.
    pub t0: DVec3,
    /// The end point.
    pub p1: DVec3,
    /// The unit tangent at the end.
    pub t1: DVec3,
}

impl HermiteSegment {
    /// Validates one segment's data (tangents may have any non-zero length; they are
    /// normalized).
    pub fn new(p0: DVec3, t0: DVec3, p1: DVec3, t1: DVec3) -> Result<Self> {
        let segment = Self {
            p0: check_coordinates(p0, "p0")?,
            t0: check_unit_direction(t0, "t0")?,
            p1: check_coordinates(p1, "p1")?,
            t1: check_unit_direction(t1, "t1")?,
        };
        check_distinct(p0, p1, "p0", "p1")?;
        Ok(segment)
    }

    /// |p1 − p0|, without overflow in the squares for coordinates beyond 1e154.
    pub fn chord_length(&self) -> f64 {
        robust_length(self.p1 - self.p0)
    }
}

/// A finite point whose coordinates are within ±[`MAX_COORDINATE`].
fn check_coordinates(p: DVec3, name: impl Display + Copy) -> Result<DVec3> {
    let p = check_point(p, name)?;
    if p.abs().max_element() > MAX_COORDINATE {
        return invalid!("{name} has a coordinate beyond ±{MAX_COORDINATE:e}");
    }
    Ok(p)
}

fn check_distinct(a: DVec3, b: DVec3, name_a: impl Display, name_b: impl Display) -> Result<()> {
    let scale = a
        .abs()
        .max_element()
        .max(b.abs().max_element())
        .max(f64::MIN_POSITIVE);
    if (b - a).abs().max_element() <= COINCIDENT * scale {
        return invalid!("{name_a} and {name_b} coincide; consecutive points must be distinct");
    }
    Ok(())
}

/// The segments between consecutive points of a G1 Hermite sequence (at least two
/// points, as many tangents, consecutive points distinct).
pub fn hermite_sequence(points: &[DVec3], tangents: &[DVec3]) -> Result<Vec<HermiteSegment>> {
    if points.len() < 2 {
        return invalid!(
            "count = {} but Hermite interpolation needs at least 2 points",
            points.len()
        );
    }
    if tangents.len() != points.len() {
        return invalid!("{} points but {} tangents", points.len(), tangents.len());
    }
    let mut checked = Vec::with_capacity(points.len());
    for (i, (&p, &t)) in points.iter().zip(tangents).enumerate() {
        checked.push((
            check_coordinates(p, format_args!("points[{i}]"))?,
            check_unit_direction(t, format_args!("tangents[{i}]"))?,
        ));
    }
    checked
        .windows(2)
        .enumerate()
        .map(|(i, w)| {
            check_distinct(
                w[0].0,
                w[1].0,
                format_args!("points[{i}]"),
                format_args!("points[{}]", i + 1),
            )?;
            Ok(HermiteSegment {
                p0: w[0].0,
                t0: w[0].1,
                p1: w[1].0,
                t1: w[1].1,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points near ±f64::MAX are refused: the PH cubic built on them would have infinite
    /// control points. Coordinates up to [`MAX_COORDINATE`] are accepted.
    #[test]
    fn refuses_coordinates_whose_constructions_would_overflow() {
        let huge = DVec3::new(-6.25e307, 1.0, 0.0);
        let err = HermiteSegment::new(huge, DVec3::X, DVec3::ONE, DVec3::Y).unwrap_err();
        assert!(
            err.message().starts_with("p0 has a coordinate beyond"),
            "{err}"
        );
        let err = hermite_sequence(&[DVec3::ZERO, huge], &[DVec3::X, DVec3::Y]).unwrap_err();
        assert!(err.message().starts_with("points[1]"), "{err}");
        let largest = DVec3::new(MAX_COORDINATE, -MAX_COORDINATE, 0.0);
        assert!(HermiteSegment::new(largest, DVec3::X, -largest, DVec3::Y).is_ok());
    }

    #[test]
    fn validates_and_normalizes() {
        let s = HermiteSegment::new(DVec3::ZERO, DVec3::X * 3.0, DVec3::ONE, DVec3::Y).unwrap();
        assert_eq!(s.t0, DVec3::X);
        assert!((s.chord_length() - 3f64.sqrt()).abs() < 1e-15);
        let e = HermiteSegment::new(DVec3::ONE, DVec3::X, DVec3::ONE, DVec3::Y).unwrap_err();
        assert!(e.message().contains("p0 and p1 coincide"));
        assert!(
            HermiteSegment::new(DVec3::ZERO, DVec3::ZERO, DVec3::ONE, DVec3::Y)
                .unwrap_err()
                .message()
                .contains("t0")
        );
    }

    #[test]
    fn sequences_name_the_offending_item() {
        let points = [DVec3::ZERO, DVec3::X, DVec3::new(2.0, 1.0, 0.0)];
        let tangents = [DVec3::X, DVec3::X, DVec3::new(1.0, f64::NAN, 0.0)];
        assert!(hermite_sequence(&points, &tangents)
            .unwrap_err()
            .message()
            .contains("tangents[2]"));
        let tangents = [DVec3::X; 3];
        assert_eq!(hermite_sequence(&points, &tangents).unwrap().len(), 2);
        assert!(hermite_sequence(&points[..1], &tangents[..1])
            .unwrap_err()
            .message()
            .contains("at least 2"));
        let repeated = [DVec3::ZERO, DVec3::X, DVec3::X];
        assert!(hermite_sequence(&repeated, &tangents)
            .unwrap_err()
            .message()
            .contains("points[1] and points[2]"));
    }
}
