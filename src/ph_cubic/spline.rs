//! PH cubic splines (Mäurer & Jüttler, §3.2): one shape-matching PH cubic of Table 1 per
//! pair of consecutive G1 Hermite data, joined with G1 continuity; and the way back from a
//! piecewise curve (e.g. a spline handle, or NURBS data) to its PH cubics.

use super::cubic::PhCubic;
use super::hermite::ph_cubic_hermite;
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::ResultExt;
use crate::error::{invalid, Result};
use crate::hermite::{hermite_sequence, HermiteSegment};
use glam::DVec3;

/// A PH cubic spline: a piecewise curve whose every segment is a polynomial cubic (or of
/// lower degree, raised) satisfying the PH condition (17), checked when it is made. Read
/// as a curve through `Deref`; its cubics are kept for the constructions on it.
#[derive(Clone, Debug, PartialEq)]
pub struct PhSpline {
    curve: PiecewiseCurve,
    cubics: Vec<PhCubic>,
}

impl PhSpline {
    /// The PH spline of a piecewise curve, refused (naming the segment) when a segment is not
    /// a polynomial PH cubic.
    pub fn new(curve: PiecewiseCurve) -> Result<Self> {
        let cubics = ph_cubics(&curve)?;
        Ok(Self { curve, cubics })
    }

    /// Consecutive PH cubics on [i, i + 1].
    pub(crate) fn from_cubics(cubics: Vec<PhCubic>) -> Result<Self> {
        let curve =
            PiecewiseCurve::with_unit_intervals(cubics.iter().map(PhCubic::to_bezier).collect())?;
        Ok(Self { curve, cubics })
    }

    /// Consecutive PH cubics on the intervals between `breaks`.
    pub(crate) fn from_cubics_on(cubics: Vec<PhCubic>, breaks: Vec<f64>) -> Result<Self> {
        let curve = PiecewiseCurve::new(cubics.iter().map(PhCubic::to_bezier).collect(), breaks)?;
        Ok(Self { curve, cubics })
    }

    /// The spline as a piecewise curve.
    pub fn curve(&self) -> &PiecewiseCurve {
        &self.curve
    }

    /// Its PH cubics, segment by segment.
    pub fn cubics(&self) -> &[PhCubic] {
        &self.cubics
    }

    /// The piecewise curve.
    pub fn into_curve(self) -> PiecewiseCurve {
        self.curve
    }

    /// The spline scaled by `scale` about the origin, then moved by `offset` (a PH curve
    /// under a similarity is a PH curve).
    pub fn similar(&self, scale: f64, offset: DVec3) -> Result<Self> {
        Self::new(self.curve.similar(scale, offset))
    }
}

impl std::ops::Deref for PhSpline {
    type Target = PiecewiseCurve;

    fn deref(&self) -> &PiecewiseCurve {
        &self.curve
    }
}

/// The PH cubic spline through `points` with unit `tangents` (any non-zero length is
/// normalized): segment i interpolates `points[i]`, `points[i + 1]` on the parameter interval
/// [i, i + 1].
pub fn ph_spline_hermite(points: &[DVec3], tangents: &[DVec3]) -> Result<PhSpline> {
    ph_spline_from_segments(&hermite_sequence(points, tangents)?)
}

/// The PH cubic spline through validated consecutive Hermite segments (see
/// [`ph_spline_hermite`]); errors name the segment and its points.
pub fn ph_spline_from_segments(segments: &[HermiteSegment]) -> Result<PhSpline> {
    let cubics = segments
        .iter()
        .enumerate()
        .map(|(i, s)| {
            ph_cubic_hermite(s)
                .map(|solutions| solutions.shape_matching)
                .with_context(|| format!("segment {i} (points[{i}] to points[{}])", i + 1))
        })
        .collect::<Result<Vec<PhCubic>>>()?;
    PhSpline::from_cubics(cubics)
}

/// The PH cubics of a piecewise curve whose segments are polynomial of degree ≤ 3 (given
/// with equal weights) and PH; lower degrees are raised to 3.
pub fn ph_cubics(curve: &PiecewiseCurve) -> Result<Vec<PhCubic>> {
    curve
        .segments()
        .iter()
        .enumerate()
        .map(|(k, segment)| as_ph_cubic(segment).with_context(|| format!("ph_spline segment {k}")))
        .collect()
}

/// Relative extent (to the largest coordinate) at or below which a segment's control points
/// are rounding of one point: 64 ulps, where its direction is noise (a frame along it was
/// NaN). Segments a little longer keep a direction to the accuracy their rounding allows.
const ROUNDING_EXTENT: f64 = 64.0 * f64::EPSILON;

fn as_ph_cubic(segment: &RationalBezierCurve) -> Result<PhCubic> {
    if segment.degree() > 3 || !segment.is_polynomial() {
        return invalid!(
            "is not a polynomial cubic (degree {}, {}): not a PH cubic",
            segment.degree(),
            if segment.is_polynomial() {
                "polynomial"
            } else {
                "rational"
            }
        );
    }
    let poles: Vec<DVec3> = segment.elevated(3 - segment.degree()).poles().collect();
    // The largest coordinate range (no squares: they underflow for tiny segments).
    let extent = poles
        .iter()
        .map(|p| (*p - poles[0]).abs().max_element())
        .fold(0.0, f64::max);
    let magnitude = poles
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    if extent <= ROUNDING_EXTENT * magnitude || extent.is_nan() {
        return invalid!(
            "is degenerate: its control points span {}, within the rounding of their \
             coordinates (up to {}); a segment must span more than {} of them",
            crate::error::Num(extent),
            crate::error::Num(magnitude),
            crate::error::Num(ROUNDING_EXTENT)
        );
    }
    PhCubic::from_control_points([poles[0], poles[1], poles[2], poles[3]])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn helix(t: f64) -> (DVec3, DVec3) {
        (
            DVec3::new(t.cos(), t.sin(), 0.4 * t),
            DVec3::new(-t.sin(), t.cos(), 0.4),
        )
    }

    #[test]
    fn segments_within_the_rounding_of_their_coordinates_are_refused() {
        // A line 3.6e-15 long at distance 6.8: its direction is rounding, and the exact RMF
        // along it would be NaN.
        let line = RationalBezierCurve::polynomial(&[
            DVec3::new(4.25e-144, -6.8, 0.0),
            DVec3::new(1.87e-143, -6.799999999999996, 0.0),
        ])
        .unwrap();
        let spline = PiecewiseCurve::with_unit_intervals(vec![line]).unwrap();
        let e = ph_cubics(&spline).unwrap_err();
        assert!(e.message().contains("is degenerate"), "{e}");
        let short =
            RationalBezierCurve::polynomial(&[DVec3::ZERO, DVec3::new(1e-300, 0.0, 0.0)]).unwrap();
        assert!(ph_cubics(&PiecewiseCurve::with_unit_intervals(vec![short]).unwrap()).is_ok());
    }

    #[test]
    fn interpolates_g1_data_and_validates_back() {
        let (points, tangents): (Vec<DVec3>, Vec<DVec3>) =
            (0..=8).map(|i| helix(0.5 * i as f64)).unzip();
        let spline = ph_spline_hermite(&points, &tangents).unwrap();
        assert_eq!(spline.domain(), (0.0, 8.0));
        for (i, (p, t)) in points.iter().zip(&tangents).enumerate() {
            let jet = spline.eval_jet(i as f64);
            assert!((jet.point - *p).length() < 1e-14);
            assert!((jet.d1.normalize() - t.normalize()).length() < 1e-12);
        }
        let cubics = ph_cubics(&spline).unwrap();
        assert_eq!(cubics.len(), 8);
    }

    #[test]
    fn names_the_failing_segment() {
        let points = [DVec3::ZERO, DVec3::X, DVec3::new(2.0, 1.0, 0.0)];
        let tangents = [DVec3::X, DVec3::X, DVec3::X];
        let e = ph_spline_hermite(&points, &tangents).unwrap_err();
        assert!(e.is(crate::ErrorKind::NoSolution));
        assert!(
            e.message().contains("segment 1 (points[1] to points[2])"),
            "{e}"
        );
    }

    #[test]
    fn rejects_curves_that_are_not_ph_splines() {
        let line = RationalBezierCurve::polynomial(&[DVec3::ZERO, DVec3::X]).unwrap();
        let bent = RationalBezierCurve::polynomial(&[
            DVec3::X,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(2.0, 1.0, 1.0),
        ])
        .unwrap();
        let ok = PiecewiseCurve::with_unit_intervals(vec![line.clone()]).unwrap();
        assert_eq!(ph_cubics(&ok).unwrap()[0].bend(), 0.0);
        let mixed = PiecewiseCurve::with_unit_intervals(vec![line, bent]).unwrap();
        let e = ph_cubics(&mixed).unwrap_err();
        assert!(e.message().contains("ph_spline segment 1"), "{e}");
    }
}
