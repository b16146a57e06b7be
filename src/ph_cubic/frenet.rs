//! The rational Frenet frame (19) of PH cubics and PH cubic splines: the three Frenet vectors
//! of a PH cubic are quadratic rational functions (they run on circles of the unit sphere).
//! It is what the RMF of (29) is built on, and the comparison frame of the paper's figures
//! (the Frenet sweep is far from a profile surface).

use super::base_frame::{spline_frame_pieces, FrameNumerators};
use super::cubic::PhCubic;
use super::preimage::Preimage;
use super::spline::PhSpline;
use crate::error::{invalid, Result};
use crate::model::FramedCurve;
use glam::DVec3;

/// sin θ below which a cubic counts as straight and gets no Frenet frame. Orthonormal at any
/// bend (see [`frenet_numerators`]), the frame is still only as well defined as its
/// binormal h₀ × h₁ and the twist ρ of (30), both conditioned like ε/sin θ: the RMF built on
/// it is 2e-11 rad from the double-reflection reference at sin θ = 1.6e-4, 3.5e-9 at 1.6e-6;
/// on a line it is undefined (at sin θ = 1e-11 the literal (19) gives vectors of length
/// 1.3). Below it the RMF is built on the carried frame, whose error grows like
/// θ³ (8e-12 rad at 7.9e-5, 8e-9 at 7.9e-4): 1e-4 balances the two.
pub(crate) const NEARLY_STRAIGHT: f64 = 1e-4;

/// The Frenet frame (19) over σ = |A|², computed as the Euler–Rodrigues frame of the cubic's
/// quaternion preimage A turned by the constant angle that takes it to (19) (see
/// [`super::preimage`]: orthonormal to rounding for every bend). The angle is read from the
/// binormal x' × x'' ∝ h₀ × h₁ at v = 0 and h₁ × h₂ at v = 1, weighted by size.
pub(crate) fn frenet_numerators(cubic: &PhCubic) -> FrameNumerators {
    let preimage = Preimage::of(cubic);
    let (e2, e3) = preimage.frame_numerators();
    let [h0, h1, h2] = cubic.legs();
    let (b0, b1) = (h0.cross(h1), h1.cross(h2));
    // b = cos α e₂ + sin α e₃, so n = b × t = sin α e₂ − cos α e₃.
    let (cos, sin) = (b0.dot(e2[0]) + b1.dot(e2[2]), b0.dot(e3[0]) + b1.dot(e3[2]));
    let turn = |a: f64, b: f64| -> Vec<DVec3> {
        e2.iter().zip(&e3).map(|(x, y)| *x * a + *y * b).collect()
    };
    let norm = cos.hypot(sin);
    let (cos, sin) = (cos / norm, sin / norm);
    FrameNumerators {
        e2: turn(sin, -cos),
        e3: turn(cos, sin),
        d: preimage.speed(),
    }
}

/// The Frenet frames (f₂ = n, f₃ = b) of a PH cubic spline as exact rational functions of
/// degree 2, segments split where σ has a negative Bernstein coefficient (θ > 90°) so that
/// all weights are positive. Fails on straight segments, where the frame is undefined.
pub fn ph_frenet_frames(spline: &PhSpline) -> Result<FramedCurve> {
    let pieces = spline_frame_pieces(spline, |k, cubic| {
        if cubic.bend() <= NEARLY_STRAIGHT {
            return invalid!(
                "ph_spline segment {k} is (nearly) straight (sin θ = {:.1e} ≤ {NEARLY_STRAIGHT:e}): its \
                 Frenet frame is undefined or cannot be computed accurately",
                cubic.bend()
            );
        }
        Ok(frenet_numerators(cubic))
    })?;
    Ok(FramedCurve::of_construction(
        spline.curve().clone(),
        pieces.into_frames()?,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::PiecewiseCurve;
    use crate::frames::rational::RationalFrames;

    /// The Frenet frames of a piecewise curve taken for a PH spline.
    fn frenet(curve: &PiecewiseCurve) -> Result<FramedCurve> {
        ph_frenet_frames(&PhSpline::new(curve.clone())?)
    }
    use crate::frames::frenet::frenet_frame;
    use crate::ph_cubic::test_curves::helix_spline;

    #[test]
    fn spline_frames_are_the_frenet_frames() {
        let spline = helix_spline(6, 0.7);
        let frames = ph_frenet_frames(&spline).unwrap();
        for i in 0..=60 {
            let t = 6.0 * i as f64 / 60.0;
            let jet = spline.eval_jet(t);
            let expected = frenet_frame(jet.d1, jet.d2).unwrap();
            let f = frames.frames().frame(t);
            assert!((f.f2 - expected.f2).length() < 1e-13, "t = {t}");
            assert!((f.tangent - expected.tangent).length() < 1e-13, "t = {t}");
        }
    }

    /// Frames at 21 parameters of [0, 1] orthonormal within `tolerance`.
    fn assert_orthonormal(frames: &RationalFrames, tolerance: f64) {
        for i in 0..=20 {
            let f = frames.frame(i as f64 / 20.0);
            let error = crate::frames::metrics::orthonormality_error(&f);
            assert!(error < tolerance, "{error:e}");
        }
    }

    /// A segment of 4e-13 at distance 1 from the origin (its polygon PH only to 1e-3, within
    /// the tolerance its rounding allows) and a PH cubic perturbed by 1e-10 near a straight
    /// line: (19) taken literally puts their Frenet frames 1e-3 and 2e-5 from orthonormal,
    /// and 1e-7 on the exactly PH cubic of their data; from that cubic's quaternion
    /// preimage they are orthonormal to rounding (7e-16).
    #[test]
    fn frames_are_orthonormal_for_polygons_that_are_ph_only_within_tolerance() {
        let tiny = crate::bezier::RationalBezierCurve::polynomial(&[
            DVec3::X,
            DVec3::new(0.9999999999995625, -4.375e-13, -3.125e-14),
        ])
        .unwrap();
        let (b, perturbation) = (2e-3f64, 1e-10);
        let (s, c) = b.sin_cos();
        let exact = crate::ph_cubic::ph_spline_hermite(
            &[DVec3::ZERO, DVec3::new(1.0, 0.3 * b, 0.1 * b)],
            &[DVec3::X, DVec3::new(c, s, 0.2 * s).normalize()],
        )
        .unwrap();
        let mut poles: Vec<DVec3> = exact.segments()[0].poles().collect();
        poles[1].y += perturbation;
        let perturbed = crate::bezier::RationalBezierCurve::polynomial(&poles).unwrap();
        for segment in [tiny, perturbed] {
            let spline = PiecewiseCurve::with_unit_intervals(vec![segment]).unwrap();
            // Both polygons bend by about 1e-3 rad, where (19) taken literally is conditioned
            // like ε/θ²; from the quaternion preimage the frames are orthonormal to rounding.
            assert_orthonormal(frenet(&spline).unwrap().frames(), 1e-14);
        }
    }

    /// A line of 1.1e-13 at distance 1 from the origin, elevated to a cubic, bends by 3e-3
    /// through rounding alone and has no PH interpolant of its end data, so no frame fits
    /// it (its literal "Frenet frames" have vectors of length 0.5): it is refused, or else
    /// its frames are orthonormal.
    #[test]
    fn polygons_without_a_ph_interpolant_of_their_end_data_are_refused() {
        let line = crate::bezier::RationalBezierCurve::from_weighted(
            &[
                DVec3::new(
                    1.0000000000000406,
                    4.0625000000000004e-14,
                    4.0625000000000004e-14,
                ),
                DVec3::new(
                    0.9999999999999313,
                    8.125000000000001e-14,
                    8.125000000000001e-14,
                ),
            ],
            &[1.0000000000000004; 2],
        )
        .unwrap();
        let spline = PiecewiseCurve::with_unit_intervals(vec![line]).unwrap();
        match frenet(&spline) {
            Err(e) => assert!(e.message().contains("no PH cubic interpolates"), "{e}"),
            Ok(frames) => assert_orthonormal(frames.frames(), 1e-14),
        }
    }

    /// A cubic bending by 1e-11 (below [`NEARLY_STRAIGHT`]) has no Frenet frame: (19) taken
    /// literally gives vectors of length 1.3 there.
    #[test]
    fn nearly_straight_segments_are_refused() {
        let data = crate::hermite::HermiteSegment::new(
            DVec3::new(0.9999999999921875, -7.8125e-12, -4.6875e-12),
            DVec3::new(0.9999999999921875, -7.8125e-12, -4.6875e-12),
            DVec3::new(3.0, 0.0, 0.0),
            DVec3::new(1.0000000026484375, -7.8125e-12, 5.78125e-11),
        )
        .unwrap();
        let cubic = crate::ph_cubic::hermite::ph_cubic_hermite(&data)
            .unwrap()
            .shape_matching;
        let spline = PiecewiseCurve::with_unit_intervals(vec![cubic.to_bezier()]).unwrap();
        let e = frenet(&spline).unwrap_err();
        assert!(e.message().contains("(nearly) straight"), "{e}");
    }

    #[test]
    fn straight_segments_have_no_frenet_frame() {
        let line = crate::bezier::RationalBezierCurve::polynomial(&[
            DVec3::ZERO,
            DVec3::X,
            DVec3::X * 2.0,
            DVec3::X * 3.0,
        ])
        .unwrap();
        let spline = PiecewiseCurve::with_unit_intervals(vec![line]).unwrap();
        let e = frenet(&spline).unwrap_err();
        assert!(
            e.message().contains("segment 0 is (nearly) straight"),
            "{e}"
        );
    }
}
