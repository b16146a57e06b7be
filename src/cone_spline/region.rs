//! The region of interest Ω (Section "Fundamentals"), in which the cone spline must be free
//! of singularities: vertices inside Ω are not admissible (Figs. 5–6).
//!
//! Ω is given in one of two ways. For G1 Hermite interpolation it is an axis-aligned box
//! ([`Region`]), which also yields the widest strip of a cone spline inside it. For the
//! approximation of a developable it is the part of the surface the caller asked for: on
//! each ruling the band [`Ruling::range`] of signed distances from [`Ruling::point`] (the
//! distances v₀ … v₁ from the line of regression of a tangent surface, the ruling between
//! the rails of a ruled surface, the ruling clipped by the box of the dual form (4)).
//! [`SweptBand`] is that band swept by the rulings between two selected ones, and measures
//! how far the vertices of the cone pair joining them keep out of it.

use super::developable::Ruling;
use super::piece::ConePiece;
use crate::error::{invalid, Result};
use crate::math::check_point;
use glam::DVec3;

/// How far inside the swept band a vertex may lie, relative to the band's width, and still
/// count as on its boundary: a vertex at a ruling's end is admissible (the corner cones of
/// sheet-metal parts have theirs at a corner of the part), and rounding must not refuse it.
pub(crate) const BOUNDARY_MARGIN: f64 = 1e-9;
/// How far outside the band, relative to its width, a vertex is placed when the rule's own
/// choice lies inside: well beyond [`BOUNDARY_MARGIN`] and the export check of the strip.
pub(crate) const PLACEMENT_MARGIN: f64 = 1e-6;

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

/// The region swept by the rulings of a developable over a parameter interval, from
/// rulings sampled across it (the first and the last at the interval's ends): on each
/// ruling its band `range`.
///
/// A cone pair joins the interval's end rulings, and each of its vertices lies on the end
/// ruling of its own segment: the first segment's on the first ruling, the second's on the
/// last (Fig. 3, vᵢ on eᵢ). A vertex is inside the region when it lies strictly inside the
/// band of that ruling. The junction ruling is not a ruling of the surface (near a line of
/// regression it is a chord of it), so it is not used to judge.
#[derive(Clone, Debug, PartialEq)]
pub struct SweptBand {
    rulings: Vec<Ruling>,
}

impl SweptBand {
    /// The region swept by `rulings` (in increasing parameter, at least one).
    pub fn new(rulings: Vec<Ruling>) -> Self {
        assert!(!rulings.is_empty(), "a swept band needs a ruling");
        Self { rulings }
    }

    /// The sampled rulings.
    pub fn rulings(&self) -> &[Ruling] {
        &self.rulings
    }

    /// The same band with every ruling mapped by `f` (into other coordinates).
    pub(crate) fn map(&self, f: impl Fn(&Ruling) -> Ruling) -> Self {
        Self::new(self.rulings.iter().map(f).collect())
    }

    fn end_ruling(&self, end: bool) -> &Ruling {
        let r = if end {
            self.rulings.last()
        } else {
            self.rulings.first()
        };
        r.expect("a swept band has a ruling")
    }

    /// The smallest relative clearance of the vertices of a pair's pieces (the first starting
    /// on the first ruling, the last ending on the last) from the region: for a vertex at
    /// signed distance s along the end ruling of its piece where the band is [lo, hi],
    /// max(lo − s, s − hi) / (hi − lo) — negative inside, 0 at a ruling's end, positive
    /// outside; +∞ when no piece has a vertex (cylinders, plane strips).
    pub fn clearance(&self, pieces: &[ConePiece]) -> f64 {
        let last = pieces.len().saturating_sub(1);
        pieces
            .iter()
            .enumerate()
            .filter_map(|(k, p)| p.vertex().map(|v| (k, p, v)))
            .flat_map(|(k, p, v)| {
                let first = (k == 0).then(|| self.clearance_on(false, &p.start, v));
                let end = (k == last).then(|| self.clearance_on(true, &p.end(), v));
                first.into_iter().chain(end)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The relative clearance of `v` along the ruling line of `line` (the first or last
    /// ruling, with the piece's reference point) from that ruling's band.
    fn clearance_on(&self, end: bool, line: &super::element::Element, v: DVec3) -> f64 {
        let (lo, hi) = band_on_line(self.end_ruling(end), line.point, line.ruling);
        let s = line.parameter_of(v);
        (lo - s).max(s - hi) / (hi - lo)
    }

    /// Whether no vertex of the pieces lies strictly inside the region (within
    /// `BOUNDARY_MARGIN` of its boundary counts as on it).
    pub fn admits(&self, pieces: &[ConePiece]) -> bool {
        self.clearance(pieces) >= -BOUNDARY_MARGIN
    }

    /// The band on the first (`end` false) or the last ruling (`end` true) as signed
    /// distances along the line `point + s·direction` (`point` on that ruling, `direction`
    /// ± its direction), with the distance by which a vertex is placed outside it.
    pub fn on_ruling(&self, end: bool, point: DVec3, direction: DVec3) -> ((f64, f64), f64) {
        let r = self.end_ruling(end);
        (
            band_on_line(r, point, direction),
            PLACEMENT_MARGIN * (r.range.1 - r.range.0),
        )
    }
}

/// The band of the ruling `r` projected onto the line `point + s·direction`: the interval
/// of s between the projections of its two ends.
fn band_on_line(r: &Ruling, point: DVec3, direction: DVec3) -> (f64, f64) {
    let [a, b] = [r.range.0, r.range.1].map(|v| (r.point + v * r.direction - point).dot(direction));
    (a.min(b), a.max(b))
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
