//! Similarities x ↦ origin + scale · x (no rotation): how the constructions move the
//! caller's data to unit size about the origin and their results back. Every construction
//! that must be invariant under scaling (1e-200 … 1e200) and translation computes in the
//! internal coordinates of one of these and maps its answers — points, lengths, curves,
//! surfaces, homogeneous control points — back to the caller's.

use crate::bezier::{PiecewiseCurve, PiecewiseSurface};
use crate::error::Result;
use glam::{DVec3, DVec4};

/// x ↦ origin + scale · x, from internal coordinates to the caller's (scale > 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Similarity {
    pub origin: DVec3,
    pub scale: f64,
}

impl Similarity {
    /// The similarity that maps the unit-size box about the origin onto the bounding box of
    /// `points` (scale the box's largest side; 1 for a single point).
    pub(crate) fn fitting(points: impl IntoIterator<Item = DVec3>) -> Self {
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for p in points {
            lo = lo.min(p);
            hi = hi.max(p);
        }
        let origin = 0.5 * lo + 0.5 * hi;
        // Half-extents first: the diagonal of a box of 1e308 overflows.
        let half = 0.5 * hi - 0.5 * lo;
        let scale = 2.0 * half.abs().max_element();
        Self {
            origin,
            scale: if scale > 0.0 { scale } else { 1.0 },
        }
    }

    /// Centred on `centre`, scaled by the power of two at or below `size` (1 for a zero or
    /// non-finite size; 2^−1022 for a subnormal size, whose power of two is not a normal
    /// number): a change of scale by a power of two changes no rounding.
    pub(crate) fn power_of_two_about(centre: DVec3, size: f64) -> Self {
        let scale = if size.is_finite() && size > 0.0 {
            f64::from_bits(size.to_bits() & 0x7ff0_0000_0000_0000).max(f64::MIN_POSITIVE)
        } else {
            1.0
        };
        Self {
            origin: centre,
            scale,
        }
    }

    /// A point in the caller's coordinates.
    pub(crate) fn to_user(self, x: DVec3) -> DVec3 {
        self.origin + self.scale * x
    }

    /// A point of the caller's in internal coordinates.
    pub(crate) fn to_internal(self, x: DVec3) -> DVec3 {
        (x - self.origin) / self.scale
    }

    /// A length in the caller's units.
    pub(crate) fn length(self, l: f64) -> f64 {
        l * self.scale
    }

    /// A homogeneous point in internal coordinates, mapped to the caller's.
    pub(crate) fn homogeneous_to_user(self, h: DVec4) -> DVec4 {
        (h.truncate() * self.scale + self.origin * h.w).extend(h.w)
    }

    /// A curve in the caller's coordinates.
    pub(crate) fn curve_to_user(self, c: &PiecewiseCurve) -> PiecewiseCurve {
        let segments = c
            .segments()
            .iter()
            .map(|s| s.similar(self.scale, self.origin))
            .collect();
        PiecewiseCurve::new(segments, c.breaks().to_vec()).expect("the same breaks")
    }

    /// A curve of the caller's in internal coordinates.
    pub(crate) fn curve_to_internal(self, c: &PiecewiseCurve) -> Result<PiecewiseCurve> {
        let segments = c
            .segments()
            .iter()
            .map(|s| s.similar(1.0 / self.scale, -self.origin / self.scale))
            .collect();
        PiecewiseCurve::new(segments, c.breaks().to_vec())
    }

    /// A surface in the caller's coordinates (refused if a control point leaves the range
    /// of f64).
    pub(crate) fn surface_to_user(self, mut s: PiecewiseSurface) -> Result<PiecewiseSurface> {
        for p in s.patches_mut() {
            p.map_homogeneous(|h| self.homogeneous_to_user(h))?;
        }
        Ok(s)
    }
}
