//! Step 2 of the algorithm of Section 3.1 (Bartoň, Jüttler & Wang): for one segment's G1
//! Hermite data, the sphere through both points that touches both tangents, a point f on
//! it, and the inversion centred at f that maps the sphere onto a plane through both points
//! (normal f − z, z the sphere's centre). Its radius |p₀ − f| = |p₁ − f| makes it fix both
//! end points, so f is taken on a circle C of the sphere through p₀ and p₁, at the point of
//! C farthest from both: the inversion maps C to the chord's line.
//!
//! * The paper's choice, [`segment_map`]: C is the great circle through p₀ and p₁, so f is
//!   the point of the sphere farthest from both ends.
//! * [`turning_segment_map`], for data the paper's map makes S-shaped or nearly so
//!   ([`chosen_segment_map`] decides). Inversions are
//!   conformal, so the mapped tangents make with the chord the angles a₀, a₁ that t₀, t₁ make
//!   with C at p₀, p₁. Circles of the pencil through p₀, p₁ meet at equal angles at both
//!   points, so moving C turns a₀ and a₁ oppositely: the sum a₀ + a₁ is an invariant of the
//!   data, the turning a₁ − a₀ is free. A planar PH cubic (legs ℓ/r, ℓ, ℓr of equal turns)
//!   needs r² sin a₁ + r sin((a₀ + a₁)/2) + sin a₀ = 0 with r > 0, which has exactly one
//!   solution for C-shaped data (a₀a₁ < 0) and none for S-shaped ones — a PH cubic has no
//!   inflection. Data with a half-turn symmetry about the chord's perpendicular bisector,
//!   every helix segment among them, are S-shaped under the paper's map (f lies on the
//!   symmetry axis, parallel mapped tangents). This map chooses C so that the planar data
//!   turn by as much as the spatial ones, |a₁ − a₀| = ∠(t₀, t₁): C-shaped, nearly isosceles
//!   (the invariant sum is O(h²), the turning O(h)), with planar curvature ≈ the curve's.
//!
//! The sphere's centre z solves (z − p₀)·t₀ = 0, (z − p₁)·t₁ = 0, (z − m)·(p₁ − p₀) = 0 (m the
//! midpoint). When t₀, t₁ and the chord are (nearly) coplanar the system is singular: the
//! sphere degenerates to a plane and the data are planar — then no map is needed. The
//! threshold 1e-8 on the normalized determinant balances the two errors: below it the
//! sphere's radius exceeds 1e8 chords and the inversion loses more digits than treating the
//! data as planar costs (≤ 1e-8 rad).

use super::transform::{Inversion, MobiusMap};
use crate::hermite::HermiteSegment;
use crate::math::{angle_between, bisect_root, orthonormal_to, signed_angle, solve_refined};
use glam::{DMat3, DVec3};

/// Below this |det(t₀, t₁, chord/|chord|)| the data count as planar.
const PLANAR_TOLERANCE: f64 = 1e-8;

/// Largest asymmetry |a₀ + a₁| / |a₁ − a₀| of the planar data for which the paper's map is
/// kept: its PH cubic then has leg ratios L₁/L₂ = L₂/L₃ within about [0.68, 1.47].
const MAX_ASYMMETRY: f64 = 0.25;

/// Circles of the pencil sampled when looking for the one with the wanted turning.
const PENCIL_SAMPLES: usize = 16;

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

/// The sphere through p₀ and p₁ touching t₀ and t₁, or `None` for (nearly) planar data.
///
/// For short segments the system is nearly singular (t₀, t₁ and the chord almost parallel),
/// but what the construction needs is a small *residual* — the tangents touching the sphere
/// to round-off — not an accurate centre. So the system is posed relative to the chord's
/// midpoint m (right-hand sides of the chord's size, no cancellation of absolute
/// coordinates) and the solution refined twice against its residual.
pub fn segment_sphere(h: &HermiteSegment) -> Option<(DVec3, f64)> {
    let chord = h.p1 - h.p0;
    let unit_chord = chord / chord.length();
    let rows = DMat3::from_cols(h.t0, h.t1, unit_chord).transpose();
    if rows.determinant().abs() < PLANAR_TOLERANCE {
        return None;
    }
    // y = z − m: y·t₀ = −(chord·t₀)/2, y·t₁ = (chord·t₁)/2, y·chord = 0.
    let rhs = DVec3::new(-0.5 * chord.dot(h.t0), 0.5 * chord.dot(h.t1), 0.0);
    let y = solve_refined(rows, rhs)?;
    let midpoint = 0.5 * (h.p0 + h.p1);
    Some((midpoint + y, (0.5 * chord + y).length()))
}

/// The map used for a segment: the paper's, unless its planar data are S-shaped or nearly so
/// (asymmetry above 1/4: the PH cubic degenerates towards a vanishing leg), in which case the
/// turning map, which is C-shaped and nearly isosceles for any smooth curve sampled finely.
pub fn chosen_segment_map(h: &HermiteSegment) -> SegmentMap {
    let paper = segment_map(h);
    let asymmetry = planar_asymmetry(h, &paper);
    if asymmetry <= MAX_ASYMMETRY {
        return paper;
    }
    match turning_segment_map(h) {
        Some(turning) if planar_asymmetry(h, &turning) < asymmetry => turning,
        _ => paper,
    }
}

/// |a₀ + a₁| / |a₁ − a₀| of the planar data under `m` (0 for isosceles data, ≥ 1 for
/// S-shaped ones; 0 for planar data, which need no map).
pub fn planar_asymmetry(h: &HermiteSegment, m: &SegmentMap) -> f64 {
    if m.sphere.is_none() {
        return 0.0;
    }
    let chord = (h.p1 - h.p0).normalize();
    let (a0, a1) = (
        chord_angle(m, chord, h.p0, h.t0),
        chord_angle(m, chord, h.p1, h.t1),
    );
    (a0 + a1).abs() / (a1 - a0).abs()
}

/// The paper's map: f is the point of the sphere farthest from both end points.
pub fn segment_map(h: &HermiteSegment) -> SegmentMap {
    match segment_sphere(h) {
        None => planar_map(h),
        Some(sphere) => map_through_circle(h, sphere, great_circle_normal(h, sphere.0)),
    }
}

/// The map whose planar data turn by ∠(t₀, t₁) (see the module notes), of the two such
/// circles the one with f farther from the end points; `None` for planar data or when the
/// pencil has no such circle.
pub fn turning_segment_map(h: &HermiteSegment) -> Option<SegmentMap> {
    let sphere = segment_sphere(h)?;
    let chord = (h.p1 - h.p0).normalize();
    let e1 = orthonormal_to(chord);
    let e2 = chord.cross(e1);
    let centre = |g: f64| farthest_on_circle(h, sphere.0, g.cos() * e1 + g.sin() * e2);
    let target = angle_between(h.t0, h.t1);
    let step = std::f64::consts::PI / PENCIL_SAMPLES as f64;
    let mut best: Option<(f64, DVec3)> = None;
    for sign in [1.0, -1.0] {
        let residual = |g: f64| turning_through(h, sphere, centre(g)) - sign * target;
        for k in 0..PENCIL_SAMPLES {
            let (g0, g1) = (k as f64 * step, (k + 1) as f64 * step);
            let (r0, r1) = (residual(g0), residual(g1));
            // A sign change, not a jump of the angles through ±π.
            if r0 * r1 > 0.0 || (r0 - r1).abs() > std::f64::consts::PI {
                continue;
            }
            let Some(root) = bisect_root(residual, g0, g1, 1e-10) else {
                continue;
            };
            let f = centre(root);
            let distance = (f - h.p0).length().min((f - h.p1).length());
            if best.is_none_or(|(d, _)| distance > d) {
                best = Some((distance, f));
            }
        }
    }
    best.map(|(_, f)| map_from_centre(h, sphere, f))
}

/// Signed angle from the chord to the mapped tangent at `p`, about the plane normal.
fn chord_angle(m: &SegmentMap, chord: DVec3, p: DVec3, t: DVec3) -> f64 {
    let image = m.map.normalized_differential(p, t).unwrap_or(t);
    signed_angle(chord, image, m.plane_normal)
}

/// Normal of the plane of the great circle through p₀ and p₁: it contains the chord and the
/// centre — or, for antipodal end points, the chord and the way the tangents lead (a great
/// circle from p₀ to p₁ peaks in direction t₀ − t₁).
fn great_circle_normal(h: &HermiteSegment, center: DVec3) -> DVec3 {
    let chord = (h.p1 - h.p0).normalize();
    let towards_midpoint = 0.5 * (h.p0 + h.p1) - center;
    let radius = (h.p0 - center).length();
    let in_plane = if towards_midpoint.length() > 1e-9 * radius {
        towards_midpoint
    } else {
        h.t0 - h.t1
    };
    let n = chord.cross(in_plane);
    if n.length() > 1e-12 {
        n.normalize()
    } else {
        orthonormal_to(chord)
    }
}

/// The point of the circle (sphere ∩ plane through p₀ with unit `normal` ⟂ chord) farthest
/// from both end points: where the inversion is centred.
fn farthest_on_circle(h: &HermiteSegment, center: DVec3, normal: DVec3) -> DVec3 {
    let circle_center = center - (center - h.p0).dot(normal) * normal;
    let circle_radius = (h.p0 - circle_center).length();
    let mut away = 0.5 * (h.p0 + h.p1) - circle_center;
    if away.length() <= 1e-9 * circle_radius {
        // The chord is a diameter of the circle: f opposite to where the tangents lead.
        let across = normal.cross((h.p1 - h.p0).normalize());
        away = if across.dot(h.t0 - h.t1) >= 0.0 {
            across
        } else {
            -across
        };
    }
    circle_center - circle_radius * away.normalize()
}

/// The inversion centred at `f` (on the sphere) that fixes both end points.
fn map_from_centre(h: &HermiteSegment, (center, radius): (DVec3, f64), f: DVec3) -> SegmentMap {
    SegmentMap {
        map: MobiusMap::new(vec![Inversion::Sphere {
            center: f,
            radius: (h.p0 - f).length(),
        }]),
        plane_normal: (f - center) / radius,
        sphere: Some((center, radius)),
    }
}

fn map_through_circle(h: &HermiteSegment, sphere: (DVec3, f64), normal: DVec3) -> SegmentMap {
    map_from_centre(h, sphere, farthest_on_circle(h, sphere.0, normal))
}

/// The planar turning a₁ − a₀ of the data under the inversion centred at `f`, computed
/// without building the map (the pencil search evaluates it many times).
fn turning_through(h: &HermiteSegment, (center, radius): (DVec3, f64), f: DVec3) -> f64 {
    let normal = (f - center) / radius;
    let chord = (h.p1 - h.p0).normalize();
    let angle = |p: DVec3, t: DVec3| {
        let y = p - f;
        let image = t - 2.0 * t.dot(y) / y.length_squared() * y;
        signed_angle(chord, image, normal)
    };
    angle(h.p1, h.t1) - angle(h.p0, h.t0)
}

/// Planar data need no map; the plane is that of t₀ × t₁, else t₀ × chord, else any plane
/// through the chord (straight-line data lie in every one).
fn planar_map(h: &HermiteSegment) -> SegmentMap {
    let chord = (h.p1 - h.p0).normalize();
    // The end points must lie in the plane (only the tangents are projected into it), so its
    // normal is taken across the chord, from the tangent farther from it; t₀ × t₁ only when
    // both run along the chord. (A fuzz finding: nearly planar data with t₀ ≈ −t₁ took
    // t₀ × t₁, at 0.06 to the chord, and the frames were 2e-6 from orthonormal.)
    let across = [h.t0.cross(chord), h.t1.cross(chord)]
        .into_iter()
        .max_by(|a, b| a.length().total_cmp(&b.length()))
        .expect("two candidates");
    let normal = [across, h.t0.cross(h.t1)]
        .into_iter()
        .find(|n| n.length() > 1e-9)
        .map_or_else(|| orthonormal_to(chord), DVec3::normalize);
    SegmentMap {
        map: MobiusMap::default(),
        plane_normal: normal,
        sphere: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::ParametricCurve;
    use crate::testing::{spatial_hermite_segment, Helix};

    fn inversion_centre(m: &SegmentMap) -> Option<DVec3> {
        match m.map.inversions().first() {
            Some(Inversion::Sphere { center, .. }) => Some(*center),
            _ => None,
        }
    }

    fn helix_segment(a: f64, b: f64) -> HermiteSegment {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.4,
        };
        let (p0, t0) = helix.point_unit_tangent(a).unwrap();
        let (p1, t1) = helix.point_unit_tangent(b).unwrap();
        HermiteSegment::new(p0, t0, p1, t1).unwrap()
    }

    fn check_maps_onto_a_plane_through_both_points(h: &HermiteSegment, m: &SegmentMap) {
        let (center, radius) = m.sphere.expect("non-planar data");
        for (p, t) in [(h.p0, h.t0), (h.p1, h.t1)] {
            assert!(((p - center).length() - radius).abs() < 1e-13 * radius);
            assert!(
                (p - center).dot(t).abs() < 1e-13 * radius,
                "tangent touches the sphere"
            );
            assert!(
                (m.map.apply(p).unwrap() - p).length() < 1e-12,
                "end points are fixed"
            );
            let image = m.map.normalized_differential(p, t).unwrap();
            assert!(
                image.dot(m.plane_normal).abs() < 1e-12,
                "image tangent lies in the plane"
            );
        }
        for k in 0..12 {
            let a = k as f64 * 0.5;
            let q = center + radius * DVec3::new(a.cos() * 0.6, a.sin() * 0.6, 0.8);
            if let Some(image) = m.map.apply(q) {
                assert!((image - h.p0).dot(m.plane_normal).abs() < 1e-10 * (1.0 + image.length()));
            }
        }
    }

    #[test]
    fn the_papers_map_takes_the_point_farthest_from_both_ends() {
        let h = spatial_hermite_segment();
        let m = segment_map(&h);
        check_maps_onto_a_plane_through_both_points(&h, &m);
        let (center, radius) = m.sphere.unwrap();
        let f = inversion_centre(&m).unwrap();
        let far = (f - h.p0).length().min((f - h.p1).length());
        for k in 0..200 {
            let (a, b) = (k as f64 * 0.7, k as f64 * 0.31);
            let q = center + radius * DVec3::new(a.cos() * b.sin(), a.sin() * b.sin(), b.cos());
            assert!((q - h.p0).length().min((q - h.p1).length()) <= far + 1e-12);
        }
    }

    #[test]
    fn a_helix_segment_maps_to_s_shaped_data_under_the_papers_choice() {
        let h = helix_segment(0.0, 1.0);
        let chord = (h.p1 - h.p0).normalize();
        let m = segment_map(&h);
        let (a0, a1) = (
            chord_angle(&m, chord, h.p0, h.t0),
            chord_angle(&m, chord, h.p1, h.t1),
        );
        assert!(
            (a0 - a1).abs() < 1e-12 && a0.abs() > 1e-3,
            "parallel mapped tangents off the chord: {a0} {a1}"
        );
    }

    #[test]
    fn the_angle_sum_is_invariant_and_the_turning_map_makes_data_c_shaped() {
        for h in [
            helix_segment(0.0, 1.0),
            helix_segment(0.3, 2.0),
            spatial_hermite_segment(),
        ] {
            let chord = (h.p1 - h.p0).normalize();
            let paper = segment_map(&h);
            let angles = |m: &SegmentMap| {
                (
                    chord_angle(m, chord, h.p0, h.t0),
                    chord_angle(m, chord, h.p1, h.t1),
                )
            };
            let (p0, p1) = angles(&paper);
            let m = turning_segment_map(&h).expect("a circle with the wanted turning exists");
            check_maps_onto_a_plane_through_both_points(&h, &m);
            let (a0, a1) = angles(&m);
            assert!(
                ((a0 + a1) - (p0 + p1)).abs() < 1e-9,
                "the angle sum is invariant"
            );
            assert!(
                ((a1 - a0).abs() - angle_between(h.t0, h.t1)).abs() < 1e-9,
                "turning as in space"
            );
            assert!(a0 * a1 < 0.0, "C-shaped planar data: {a0} {a1}");
        }
    }

    #[test]
    fn the_papers_map_is_kept_unless_its_planar_data_are_nearly_s_shaped() {
        // A short piece of a curve with varying curvature and torsion: comfortably C-shaped.
        let x = |t: f64| {
            (
                DVec3::new(t, t * t, t * t * t),
                DVec3::new(1.0, 2.0 * t, 3.0 * t * t).normalize(),
            )
        };
        let ((p0, t0), (p1, t1)) = (x(0.5), x(0.7));
        let generic = HermiteSegment::new(p0, t0, p1, t1).unwrap();
        assert!(planar_asymmetry(&generic, &segment_map(&generic)) < 0.25);
        assert_eq!(chosen_segment_map(&generic), segment_map(&generic));
        let helix = helix_segment(0.0, 0.5);
        assert!(
            planar_asymmetry(&helix, &segment_map(&helix)) > 1.0,
            "S-shaped under the paper's map"
        );
        let chosen = chosen_segment_map(&helix);
        assert!(planar_asymmetry(&helix, &chosen) < 0.25);
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
        assert!(turning_segment_map(&straight).is_none());
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
        let f = inversion_centre(&m).unwrap();
        let (center, _) = m.sphere.unwrap();
        assert!(
            (f - center).dot(DVec3::Y) < 0.0,
            "f lies opposite to where the segment goes"
        );
    }
}
