//! Step 2 of the algorithm of Section 3.1 (Bartoň, Jüttler & Wang): for one segment's G1
//! Hermite data, the sphere through both points that touches both tangents, the point f on
//! it farthest from both ends, and the inversion centred at f that maps the sphere onto a
//! plane through both points (normal f − z, z the sphere's centre). The inversion's radius
//! |p₀ − f| = |p₁ − f| makes it fix both end points.
//!
//! The sphere's centre z solves (z − p₀)·t₀ = 0, (z − p₁)·t₁ = 0, (z − m)·(p₁ − p₀) = 0 (m the
//! midpoint). When t₀, t₁ and the chord are (nearly) coplanar the system is singular: the
//! sphere degenerates to a plane and the data are planar — then no map is needed and the
//! planar construction applies directly. The threshold 1e-8 on the normalized determinant
//! balances the two errors: below it the sphere's radius exceeds 1e8 chords and the
//! inversion loses more digits than treating the data as planar costs (≤ 1e-8 rad).

use super::transform::{Inversion, MobiusMap};
use crate::hermite::HermiteSegment;
use crate::math::orthonormal_to;
use glam::{DMat3, DVec3};

/// Below this |det(t₀, t₁, chord/|chord|)| the data count as planar.
const PLANAR_TOLERANCE: f64 = 1e-8;

/// How a segment's data are brought into a plane.
#[derive(Clone, Debug, PartialEq)]
pub struct SegmentMap {
    /// Maps the segment's sphere onto the plane (empty for planar data); it is an
    /// involution, so it also maps the planar solution back.
    pub map: MobiusMap,
    /// Unit normal of the plane the data lie in after the map.
    pub plane_normal: DVec3,
    /// The sphere (centre, radius) for non-planar data.
    pub sphere: Option<(DVec3, f64)>,
}

/// The map of step 2 for one segment.
pub fn segment_map(h: &HermiteSegment) -> SegmentMap {
    let chord = h.p1 - h.p0;
    let unit_chord = chord / chord.length();
    let determinant = DMat3::from_cols(h.t0, h.t1, unit_chord).determinant();
    if determinant.abs() < PLANAR_TOLERANCE {
        return SegmentMap {
            map: MobiusMap::default(),
            plane_normal: planar_normal(h),
            sphere: None,
        };
    }
    // Rows t₀, t₁, chord of the linear system for the centre.
    let rows = DMat3::from_cols(h.t0, h.t1, chord).transpose();
    let midpoint = 0.5 * (h.p0 + h.p1);
    let rhs = DVec3::new(h.p0.dot(h.t0), h.p1.dot(h.t1), midpoint.dot(chord));
    let center = rows.inverse() * rhs;
    let radius = (h.p0 - center).length();
    let f = center - radius * away_direction(h, center, midpoint);
    let map = MobiusMap::new(vec![Inversion::Sphere {
        center: f,
        radius: (h.p0 - f).length(),
    }]);
    SegmentMap {
        map,
        plane_normal: (f - center) / radius,
        sphere: Some((center, radius)),
    }
}

/// Unit direction from the sphere's centre towards the part of the sphere the segment
/// spans: towards the chord's midpoint, or — when the end points are antipodal — the way
/// the tangents lead (a great circle from p₀ to p₁ peaks in direction t₀ − t₁).
fn away_direction(h: &HermiteSegment, center: DVec3, midpoint: DVec3) -> DVec3 {
    let towards_midpoint = midpoint - center;
    if towards_midpoint.length() > 1e-9 * (h.p0 - center).length() {
        return towards_midpoint.normalize();
    }
    let chord = (h.p1 - h.p0).normalize();
    let lead = h.t0 - h.t1;
    let lead = lead - lead.dot(chord) * chord;
    if lead.length() > 1e-9 {
        lead.normalize()
    } else {
        orthonormal_to(chord)
    }
}

/// The normal of the plane of planar data: t₀ × t₁, else t₀ × chord, else any normal of
/// the chord (straight-line data lie in every plane through the chord).
fn planar_normal(h: &HermiteSegment) -> DVec3 {
    let chord = (h.p1 - h.p0).normalize();
    [h.t0.cross(h.t1), h.t0.cross(chord), h.t1.cross(chord)]
        .into_iter()
        .find(|n| n.length() > 1e-9)
        .map_or_else(|| orthonormal_to(chord), DVec3::normalize)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data() -> HermiteSegment {
        HermiteSegment::new(
            DVec3::new(0.1, 0.0, -0.2),
            DVec3::new(1.0, 0.4, 0.3),
            DVec3::new(1.5, 1.2, 0.4),
            DVec3::new(0.2, 1.0, 0.6),
        )
        .unwrap()
    }

    #[test]
    fn the_sphere_touches_both_tangents_and_maps_onto_a_plane_through_both_points() {
        let h = data();
        let m = segment_map(&h);
        let (center, radius) = m.sphere.expect("non-planar data");
        for (p, t) in [(h.p0, h.t0), (h.p1, h.t1)] {
            assert!(((p - center).length() - radius).abs() < 1e-13 * radius);
            assert!(
                (p - center).dot(t).abs() < 1e-13 * radius,
                "tangent touches the sphere"
            );
            assert!(
                (m.map.apply(p).unwrap() - p).length() < 1e-13,
                "end points are fixed"
            );
            let image = m.map.normalized_differential(p, t).unwrap();
            assert!(
                image.dot(m.plane_normal).abs() < 1e-13,
                "image tangent lies in the plane"
            );
        }
        // Other points of the sphere land in the plane through p₀ with the plane normal.
        for k in 0..12 {
            let a = k as f64 * 0.5;
            let q = center + radius * DVec3::new(a.cos() * 0.6, a.sin() * 0.6, 0.8);
            let image = m.map.apply(q).unwrap();
            assert!(
                (image - h.p0).dot(m.plane_normal).abs() < 1e-11,
                "sphere point maps into the plane"
            );
        }
        // f is farther from both ends than any sampled point of the sphere.
        let Inversion::Sphere { center: f, .. } = m.map.inversions()[0] else {
            panic!("sphere map")
        };
        let far = (f - h.p0).length().min((f - h.p1).length());
        for k in 0..200 {
            let (a, b) = (k as f64 * 0.7, k as f64 * 0.31);
            let q = center + radius * DVec3::new(a.cos() * b.sin(), a.sin() * b.sin(), b.cos());
            assert!((q - h.p0).length().min((q - h.p1).length()) <= far + 1e-12);
        }
    }

    #[test]
    fn planar_and_straight_data_need_no_map() {
        let planar = HermiteSegment::new(
            DVec3::ZERO,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::X,
            DVec3::new(1.0, -1.0, 0.0),
        );
        let m = segment_map(&planar.unwrap());
        assert!(m.map.inversions().is_empty() && m.sphere.is_none());
        assert!((m.plane_normal.abs() - DVec3::Z).length() < 1e-15);
        let straight =
            HermiteSegment::new(DVec3::ZERO, DVec3::X, DVec3::X * 2.0, DVec3::X).unwrap();
        let m = segment_map(&straight);
        assert!(m.map.inversions().is_empty() && m.plane_normal.dot(DVec3::X).abs() < 1e-15);
    }

    #[test]
    fn antipodal_end_points_use_the_tangents_to_place_f() {
        // A half great circle of the unit sphere: p₀ = −x, p₁ = +x, leaving along +y.
        let h = HermiteSegment::new(
            -DVec3::X,
            DVec3::new(0.0, 1.0, 0.3),
            DVec3::X,
            DVec3::new(0.0, -1.0, 0.3),
        )
        .unwrap();
        let m = segment_map(&h);
        let Inversion::Sphere { center: f, .. } = m.map.inversions()[0] else {
            panic!("sphere map")
        };
        let (center, _) = m.sphere.unwrap();
        assert!(
            (f - center).dot(DVec3::Y) < 0.0,
            "f lies opposite to where the segment goes"
        );
    }
}
