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
//! Nearly planar data: no threshold. With m the chord's midpoint, e the unit chord and
//! L/2 = ℓ, the sphere's centre is z = m + Y/s with
//!
//! ```text
//!   Y = −ℓ (c₀ t₁ × e + c₁ t₀ × e),   s = det(t₀, t₁, e),   cᵢ = tᵢ·e,
//! ```
//!
//! (the solution of (z − p₀)·t₀ = 0, (z − p₁)·t₁ = 0, (z − m)·e = 0 by Cramer's rule, kept
//! in homogeneous form): Y and s are continuous in the data and s → 0 is the planar limit,
//! where z goes to infinity. A circle of the pencil whose centre lies from m along the unit
//! w ⟂ e puts f at m + w/μ with
//!
//! ```text
//!   μ = s / (Y·w + sgn(Y·w) √((Y·w)² + s²ℓ²)),
//! ```
//!
//! also continuous, 0 in the planar limit. The inversion is taken in the form through p₀
//! (`Inversion::Through`: normal n̂ = v/|v|, curvature κ = μ/|v| with v = −ℓμe − w), whose
//! image formula has no cancellation against the far centre and becomes the reflection in
//! the data's plane as s → 0; the image plane's normal is the image of the sphere's normal at
//! p₀, ∝ −ℓs·e − Y, reflected in n̂. So the map, the planar data and the result move
//! continuously into the planar case (s = 0 exactly: no map at all), and the mapped tangents
//! lie in the plane to rounding.

use super::transform::{Inversion, MobiusMap};
use crate::hermite::HermiteSegment;
use crate::math::{
    angle_between, illinois_root, orthonormal_to, signed_angle, DoubleDouble, DoubleDoubleVec3,
};
use glam::DVec3;

/// Largest asymmetry |a₀ + a₁| / |a₁ − a₀| of the planar data for which the paper's map is
/// kept: its PH cubic then has leg ratios L₁/L₂ = L₂/L₃ within about [0.68, 1.47].
const MAX_ASYMMETRY: f64 = 0.25;

/// Circles of the pencil sampled when looking for the one with the wanted turning.
const PENCIL_SAMPLES: usize = 16;

/// How a segment's data are brought into a plane.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SegmentMap {
    /// Maps the segment's sphere onto the plane (empty for planar data); it is an
    /// involution, so it also maps the planar solution back.
    pub map: MobiusMap,
    /// Unit normal of the plane the data lie in after the map.
    pub plane_normal: DVec3,
    /// The sphere (centre, radius) for non-planar data, when representable (`None` also
    /// where nearly planar data have a centre beyond the range of f64).
    pub sphere: Option<(DVec3, f64)>,
}

/// The sphere of the module notes in homogeneous form: centre m + Y/s.
#[derive(Clone, Copy, Debug)]
struct PencilSphere {
    midpoint: DVec3,
    /// Unit chord e.
    chord: DVec3,
    /// ℓ = |p₁ − p₀| / 2.
    half: f64,
    y: DVec3,
    s: f64,
}

impl PencilSphere {
    fn of(h: &HermiteSegment) -> Self {
        let chord = h.p1 - h.p0;
        let length = chord.length();
        let e = chord / length;
        let half = 0.5 * length;
        // Y and s in double-double: for nearly parallel tangents Y is a tiny difference of
        // its terms (1e-10 of them for a helix sampled at 1e-4), and its direction would be
        // lost in doubles, tilting the sphere off the tangents by 1e-10.
        let (t0, t1, ed) = (
            DoubleDoubleVec3::from(h.t0),
            DoubleDoubleVec3::from(h.t1),
            DoubleDoubleVec3::from(e),
        );
        let y = (t1.cross(ed).scaled(t0.dot(ed)) + t0.cross(ed).scaled(t1.dot(ed)))
            .scaled(DoubleDouble::from(-half))
            .value();
        let s = t0.cross(t1).dot(ed).value();
        Self {
            midpoint: 0.5 * (h.p0 + h.p1),
            chord: e,
            half,
            y,
            s,
        }
    }

    /// Planar data (the sphere is a plane, or the data a line): s = 0, or subnormal, where
    /// it keeps too few bits to place a sphere (a tangent out of the plane by 1e-320 would
    /// give frames 4e-6 from unit length).
    fn is_planar(&self) -> bool {
        self.s.abs() < f64::MIN_POSITIVE
    }

    /// Centre and radius, when representable.
    fn centre_radius(&self) -> Option<(DVec3, f64)> {
        if self.is_planar() {
            return None;
        }
        let offset = self.y / self.s;
        let centre = self.midpoint + offset;
        let radius = offset.length().hypot(self.half);
        (centre.is_finite() && radius.is_finite()).then_some((centre, radius))
    }

    /// The unit normal of the sphere at p₀ (either orientation), continuous into the plane.
    fn normal_at_start(&self) -> DVec3 {
        // Both terms divided by the larger first: for data planar to 1e-300 they are far
        // below 1e-154, where the squares of a plain length underflow to 0.
        let ls = self.half * self.s;
        let k = ls.abs().max(self.y.abs().max_element());
        let n = -(ls / k) * self.chord - self.y / k;
        if k > 0.0 && n.length() > 0.0 {
            n.normalize()
        } else {
            orthonormal_to(self.chord)
        }
    }
}

/// The map used for a segment: the paper's, unless its planar data are S-shaped or nearly so
/// (asymmetry above 1/4: the PH cubic degenerates towards a vanishing leg), in which case the
/// turning map, which is C-shaped and nearly isosceles for any smooth curve sampled finely.
///
/// The paper's map is also given up when its planar data turn by less than half the spatial
/// turn ∠(t₀, t₁): near the symmetric case (every helix segment) its planar turning is
/// near zero — for finely sampled curves at the level of rounding, where the asymmetry is
/// noise (a helix sampled 1e-4 apart had planar data turning by 5e-9 rad, "C-shaped" by
/// chance, against 9e-5 in space). For generic data its turning is close to the spatial one.
pub(crate) fn chosen_segment_map(h: &HermiteSegment) -> SegmentMap {
    let paper = segment_map(h);
    let asymmetry = planar_asymmetry(h, &paper);
    let turns_enough = paper.map.inversions().is_empty()
        || turning(h, &paper).abs() >= 0.5 * angle_between(h.t0, h.t1);
    if asymmetry <= MAX_ASYMMETRY && turns_enough {
        return paper;
    }
    match turning_segment_map(h) {
        Some(turning) if planar_asymmetry(h, &turning) < asymmetry || !turns_enough => turning,
        _ => paper,
    }
}

/// |a₀ + a₁| / |a₁ − a₀| of the planar data under `m` (0 for isosceles data, ≥ 1 for
/// S-shaped ones; 0 for planar data, which need no map).
pub(crate) fn planar_asymmetry(h: &HermiteSegment, m: &SegmentMap) -> f64 {
    if m.map.inversions().is_empty() {
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
pub(crate) fn segment_map(h: &HermiteSegment) -> SegmentMap {
    let sphere = PencilSphere::of(h);
    if sphere.is_planar() {
        return planar_map(h);
    }
    // The great circle through p₀, p₁ and the centre: its centre lies from m along Y.
    // When the chord is a diameter (the centre at m) f lies opposite to where the tangents
    // lead (a great circle from p₀ to p₁ peaks in direction t₀ − t₁).
    let radius = sphere.y.length().hypot(sphere.half * sphere.s.abs());
    if sphere.y.length() > 1e-9 * radius {
        map_towards(h, &sphere, sphere.y.normalize())
    } else {
        map_towards(h, &sphere, across_chord(h, sphere.chord))
    }
}

/// The map whose planar data turn by ∠(t₀, t₁) (see the module notes), of the two such
/// circles the one with f farther from the end points; `None` for planar data or when the
/// pencil has no such circle.
pub(crate) fn turning_segment_map(h: &HermiteSegment) -> Option<SegmentMap> {
    let sphere = PencilSphere::of(h);
    if sphere.is_planar() {
        return None;
    }
    let e1 = orthonormal_to(sphere.chord);
    let e2 = sphere.chord.cross(e1);
    let towards = |g: f64| Towards::new(h, &sphere, g.cos() * e1 + g.sin() * e2);
    let target = angle_between(h.t0, h.t1);
    // Where Y·w = 0 the circle is centred at m and f crosses to its other side: the turning
    // jumps there, so the pencil is sampled on both sides of it and not across.
    let jump = (-sphere.y.dot(e1))
        .atan2(sphere.y.dot(e2))
        .rem_euclid(std::f64::consts::PI);
    let step = std::f64::consts::PI / PENCIL_SAMPLES as f64;
    let mut at: Vec<f64> = (0..=PENCIL_SAMPLES).map(|k| k as f64 * step).collect();
    at.extend(
        [jump - 1e-9, jump + 1e-9]
            .into_iter()
            .filter(|g| (0.0..=std::f64::consts::PI).contains(g)),
    );
    at.sort_by(f64::total_cmp);
    let samples: Vec<(f64, f64)> = at.iter().map(|&g| (g, towards(g).turning(h))).collect();
    let mut best: Option<(f64, f64)> = None;
    for sign in [1.0, -1.0] {
        let residual = |g: f64| towards(g).turning(h) - sign * target;
        for pair in samples.windows(2) {
            let ((g0, t0), (g1, t1)) = (pair[0], pair[1]);
            let (r0, r1) = (t0 - sign * target, t1 - sign * target);
            // A sign change, not a jump of the angles through ±π or of f across the circle.
            if r0 * r1 > 0.0 || (r0 - r1).abs() > std::f64::consts::PI || (g0 < jump && jump < g1) {
                continue;
            }
            let Some(root) = illinois_root(residual, (g0, r0), (g1, r1), 1e-11) else {
                continue;
            };
            if residual(root).abs() > 1e-9 * target.max(1e-3) {
                continue;
            }
            // Farther from the end points: a smaller |κ| (the centre is at distance 1/|κ|).
            // Symmetric data (a helix) have two mirror solutions of equal |κ|: the first
            // found (the turning along +plane normal) is kept unless another is clearly
            // farther, so that rounding (a translation of the data) cannot swap them.
            let closeness = towards(root).curvature.abs();
            if best.is_none_or(|(c, _)| closeness < c * (1.0 - 1e-6)) {
                best = Some((closeness, root));
            }
        }
    }
    best.map(|(_, g)| towards(g).map(&sphere))
}

/// Signed angle from the chord to the mapped tangent at `p`, about the plane normal.
fn chord_angle(m: &SegmentMap, chord: DVec3, p: DVec3, t: DVec3) -> f64 {
    let image = m.map.normalized_differential(p, t).unwrap_or(t);
    signed_angle(chord, image, m.plane_normal)
}

/// The planar turning a₁ − a₀ of the data under `m`.
fn turning(h: &HermiteSegment, m: &SegmentMap) -> f64 {
    let chord = (h.p1 - h.p0).normalize();
    chord_angle(m, chord, h.p1, h.t1) - chord_angle(m, chord, h.p0, h.t0)
}

/// A unit vector across the chord, against the way the tangents lead: where f goes when the
/// circle's centre is the chord's midpoint (every point of the circle is then equally far).
fn across_chord(h: &HermiteSegment, chord: DVec3) -> DVec3 {
    let lead = h.t0 - h.t1;
    let across = lead - lead.dot(chord) * chord;
    if across.length() > 1e-12 {
        -across.normalize()
    } else {
        orthonormal_to(chord)
    }
}

/// The inversion centred at the point f of the sphere on the circle of the pencil whose
/// centre lies from the midpoint along the unit `w` ⟂ chord, farthest from both end points
/// (f = m + w/μ, module notes), in the form through p₀.
fn map_towards(h: &HermiteSegment, sphere: &PencilSphere, w: DVec3) -> SegmentMap {
    Towards::new(h, sphere, w).map(sphere)
}

/// The inversion of [`map_towards`] before it is wrapped in a map: its normal n̂ and
/// curvature κ at p₀ (the form through p₀), and the plane it maps the sphere onto.
struct Towards {
    p0: DVec3,
    normal: DVec3,
    curvature: f64,
    plane_normal: DVec3,
}

impl Towards {
    fn new(h: &HermiteSegment, sphere: &PencilSphere, w: DVec3) -> Self {
        let (s, half) = (sphere.s, sphere.half);
        let yw = sphere.y.dot(w);
        let root = yw.hypot(s * half);
        // Where the circle is centred at m (|Y·w| negligible) f lies against the way the
        // tangents lead: on the side of `across_chord` (μ of the sign of s there).
        let side = if yw.abs() > 1e-9 * root {
            yw.signum()
        } else if across_chord(h, sphere.chord).dot(w) >= 0.0 {
            s.signum()
        } else {
            -s.signum()
        };
        let mu = s / (yw + side * root);
        let v = -half * mu * sphere.chord - w;
        let length = v.length();
        let normal = v / length;
        let n = sphere.normal_at_start();
        Self {
            p0: h.p0,
            normal,
            curvature: mu / length,
            plane_normal: (n - 2.0 * n.dot(normal) * normal).normalize(),
        }
    }

    fn map(&self, sphere: &PencilSphere) -> SegmentMap {
        SegmentMap {
            map: MobiusMap::new(vec![Inversion::Through {
                point: self.p0,
                normal: self.normal,
                curvature: self.curvature,
            }]),
            plane_normal: self.plane_normal,
            sphere: sphere.centre_radius(),
        }
    }

    /// The planar turning a₁ − a₀ of the data under this inversion (the reflections (12)
    /// in n̂ at p₀ and in n̂ + κ(p₁ − p₀) at p₁), without building the map: the pencil search
    /// evaluates it many times.
    fn turning(&self, h: &HermiteSegment) -> f64 {
        let chord = (h.p1 - h.p0).normalize();
        let reflect = |t: DVec3, axis: DVec3| {
            let axis = axis.normalize();
            t - 2.0 * t.dot(axis) * axis
        };
        let image0 = reflect(h.t0, self.normal);
        let image1 = reflect(h.t1, self.normal + self.curvature * (h.p1 - h.p0));
        signed_angle(chord, image1, self.plane_normal)
            - signed_angle(chord, image0, self.plane_normal)
    }
}

/// Planar data need no map; the plane is that of t₀ × t₁, else t₀ × chord, else any plane
/// through the chord (straight-line data lie in every one).
fn planar_map(h: &HermiteSegment) -> SegmentMap {
    let chord = (h.p1 - h.p0).normalize();
    // The end points must lie in the plane (only the tangents are projected into it), so its
    // normal is taken across the chord, from the tangent farther from it; t₀ × t₁ only when
    // both run along the chord. (For nearly planar data with t₀ ≈ −t₁, t₀ × t₁ lies at 0.06
    // to the chord, and frames built on that plane are 2e-6 from orthonormal.)
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
        m.map.inversions().first().and_then(Inversion::center)
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

    /// Issue finding (dense samples): a helix sampled 1e-4 apart has tangents whose
    /// Y = c₀ t₁ × e + c₁ t₀ × e is 1e-10 of its terms; in doubles the sphere missed the
    /// tangents by 2e-10 rad (then more than the G1 tolerance of the joints). In
    /// double-double it touches them to rounding, and the map takes both onto its plane.
    #[test]
    fn nearly_parallel_tangents_touch_the_sphere_to_rounding() {
        for h in [1e-2, 1e-4, 1e-6] {
            let data = helix_segment(0.0021, 0.0021 + h);
            let (origin, scale) = (0.5 * (data.p0 + data.p1), (data.p1 - data.p0).length());
            let local = HermiteSegment {
                p0: (data.p0 - origin) / scale,
                p1: (data.p1 - origin) / scale,
                ..data
            };
            let sphere = PencilSphere::of(&local);
            let n = sphere.normal_at_start();
            assert!(
                local.t0.dot(n).abs() < 1e-15,
                "h = {h}: {:e}",
                local.t0.dot(n)
            );
            let m = chosen_segment_map(&local);
            for (p, t) in [(local.p0, local.t0), (local.p1, local.t1)] {
                let image = m.map.normalized_differential(p, t).unwrap();
                let off = image.dot(m.plane_normal).abs();
                assert!(
                    off < 1e-14,
                    "h = {h}: the image tangent is {off:e} off the plane"
                );
            }
        }
    }
}
