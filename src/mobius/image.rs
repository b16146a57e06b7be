//! Exact images of rational Bézier curves and of rational frames under Möbius maps,
//! computed by polynomial products (Bartoň, Jüttler & Wang, Corollary 1), never by fitting.
//!
//! For an inversion in the sphere (c, r) and a curve x = X/w of degree n, with D = X − c·w:
//!
//!   μ∘x = (c·|D|² + r²·w·D) / |D|²                        (degree 2n),
//!
//! and a frame vector v = V/d along x goes by the normalized differential (12) to
//!
//!   d*μ(v) = (V·|D|² − 2 (V·D) D) / (d·|D|²)                (degree m + 2n).
//!
//! D is divided by a power of two of its size first (|D|² neither overflows nor underflows),
//! and the maps of the Hermite construction, spheres through a point near the data, use
//! D = n̂·w + κ(X − a·w) and the image formula of the `transform` notes (no cancellation
//! against a far centre). A plane reflection acts linearly and keeps degrees. Every inversion reverses
//! orientation, so f₃ is negated to keep f₃ = t × f₂. By Theorem 1 the image of a
//! rotation-minimizing frame is rotation-minimizing on the image curve, so exact rational
//! RMFs map to exact rational RMFs. Images may have positive *functions* with negative
//! Bernstein coefficients as weights: segments are split until every weight is positive.

use super::transform::{Inversion, MobiusMap};
use crate::bezier::bernstein::{positive_subdivision, product, restrict, MAX_DEGREE};
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::{invalid, Result};
use crate::frames::rational::{RationalFrameSegment, RationalFrames, Turning};
use crate::math::largest_coordinate;
use crate::model::FramedCurve;
use glam::{DVec3, DVec4};

/// Halvings allowed per segment when making weights positive (2⁻³⁰ of a segment is far
/// below any distance where the image would still be representable).
const MAX_HALVINGS: usize = 30;

/// Homogeneous Bernstein coefficients of a curve segment, weights of any sign.
type Homogeneous = Vec<DVec4>;

/// A frame segment before its denominator is known to have positive coefficients:
/// f₂ = f2/denominator, f₃ = f3/denominator in Bernstein form, the denominator positive on
/// [0, 1] as a function.
#[derive(Clone, Debug)]
pub(crate) struct RawFrame {
    pub f2: Vec<DVec3>,
    pub f3: Vec<DVec3>,
    pub denominator: Vec<f64>,
}

/// One piece of a mapped segment: its end in the segment's local parameter, the curve, and
/// its frame when one was mapped.
pub(crate) type MappedPiece = (f64, RationalBezierCurve, Option<RationalFrameSegment>);

/// The image of one segment (homogeneous points of any weights) and of its raw frame under
/// `map`, split into pieces with positive weights and denominators. `segment` only names
/// the segment in errors.
pub(crate) fn map_raw_segment(
    map: &MobiusMap,
    points: &[DVec4],
    frame: Option<RawFrame>,
    segment: usize,
) -> Result<Vec<MappedPiece>> {
    let (image, raw) = map_segment(map, points, frame);
    positive_pieces(&image, raw.as_ref(), segment)?
        .windows(2)
        .map(|w| {
            let (s0, s1) = (w[0], w[1]);
            let curve = RationalBezierCurve::from_homogeneous(restrict(&image, s0, s1))?;
            let frame = match &raw {
                Some(f) => Some(RationalFrameSegment::new(
                    restrict(&f.f2, s0, s1),
                    restrict(&f.f3, s0, s1),
                    restrict(&f.denominator, s0, s1),
                )?),
                None => None,
            };
            Ok((s1, curve, frame))
        })
        .collect()
}

/// The axis of the reflection (12) along a segment, as Bernstein coefficients of the
/// segment's degree, for a sphere inversion (`None` for a plane, whose axis is constant):
/// (X − c·w)/S for a sphere with centre c (S a power of two of the size of X − c·w, so that
/// its square neither overflows nor underflows), n̂·w + κ(X − a·w) for a sphere through a
/// (module notes of `transform`). Either is a positive multiple of y − c at every point.
fn reflection_axis(inv: &Inversion, points: &[DVec4]) -> Option<Vec<DVec3>> {
    match *inv {
        Inversion::Sphere { center, .. } => {
            let d: Vec<DVec3> = points.iter().map(|h| h.truncate() - center * h.w).collect();
            let scale = power_of_two_above(largest_coordinate(d.iter().copied()));
            Some(d.iter().map(|&v| v / scale).collect())
        }
        Inversion::Plane { .. } => None,
        Inversion::Through {
            point,
            normal,
            curvature,
        } => (curvature != 0.0).then(|| {
            points
                .iter()
                .map(|h| normal * h.w + (h.truncate() - point * h.w) * curvature)
                .collect()
        }),
    }
}

/// The power of two at or above `x` (1 for zero), so that dividing by it is exact.
fn power_of_two_above(x: f64) -> f64 {
    if x > 0.0 && x.is_finite() {
        2f64.powi(x.log2().ceil() as i32)
    } else {
        1.0
    }
}

/// |v|² of a vector polynomial, in Bernstein form of twice its degree.
fn square(v: &[DVec3]) -> Vec<f64> {
    product(v, v, |a: DVec3, b: DVec3| a.dot(b))
}

/// The image of a segment under one inversion: for a sphere with centre c, radius r and
/// the axis D/S of [`reflection_axis`], c + r² D/|D|² = (c·|D/S|² + (r²/S)·w·D/S) / |D/S|²;
/// for a sphere through a, the formula of the `transform` module notes; a plane reflects
/// the coefficients (degree kept).
fn invert_points(inv: &Inversion, points: &[DVec4]) -> Homogeneous {
    let weights: Vec<f64> = points.iter().map(|h| h.w).collect();
    match (*inv, reflection_axis(inv, points)) {
        (Inversion::Sphere { center, radius }, Some(axis)) => {
            let d: Vec<DVec3> = points.iter().map(|h| h.truncate() - center * h.w).collect();
            let scale = power_of_two_above(largest_coordinate(d.iter().copied()));
            let factor = radius * (radius / scale);
            let q = square(&axis);
            let wd = product(&weights, &axis, |a: f64, b: DVec3| b * a);
            q.iter()
                .zip(&wd)
                .map(|(&qi, &wdi)| (center * qi + wdi * factor).extend(qi))
                .collect()
        }
        (
            Inversion::Through {
                point,
                normal,
                curvature,
            },
            Some(axis),
        ) => {
            let delta: Vec<DVec3> = points.iter().map(|h| h.truncate() - point * h.w).collect();
            let reflected: Vec<DVec3> = delta
                .iter()
                .map(|&d| d - 2.0 * d.dot(normal) * normal)
                .collect();
            let q = square(&axis);
            let w_reflected = product(&weights, &reflected, |a: f64, b: DVec3| b * a);
            let delta_squared = square(&delta);
            q.iter()
                .zip(&w_reflected)
                .zip(&delta_squared)
                .map(|((&qi, &wr), &dd)| (point * qi + wr - normal * (curvature * dd)).extend(qi))
                .collect()
        }
        (Inversion::Plane { point, normal }, _) | (Inversion::Through { point, normal, .. }, _) => {
            points
                .iter()
                .map(|h| {
                    (h.truncate() - 2.0 * (h.truncate() - point * h.w).dot(normal) * normal)
                        .extend(h.w)
                })
                .collect()
        }
        (Inversion::Sphere { .. }, None) => unreachable!("a sphere has an axis"),
    }
}

/// A frame along the segment `points`, carried through one inversion by the reflection
/// (12) in its axis (f₃ negated: an inversion reverses orientation).
fn transport_frame(inv: &Inversion, points: &[DVec4], frame: RawFrame) -> RawFrame {
    match (reflection_axis(inv, points), *inv) {
        (Some(d), _) => {
            let q = square(&d);
            let reflect = |v: &[DVec3], sign: f64| -> Vec<DVec3> {
                let vq = product(v, &q, |a: DVec3, b: f64| a * b);
                let vd = product(v, &d, |a: DVec3, b: DVec3| a.dot(b));
                let vdd = product(&vd, &d, |a: f64, b: DVec3| b * a);
                vq.iter()
                    .zip(&vdd)
                    .map(|(&a, &b)| (a - 2.0 * b) * sign)
                    .collect()
            };
            RawFrame {
                f2: reflect(&frame.f2, 1.0),
                f3: reflect(&frame.f3, -1.0),
                denominator: product(&frame.denominator, &q, |a: f64, b: f64| a * b),
            }
        }
        (None, Inversion::Plane { normal, .. } | Inversion::Through { normal, .. }) => {
            let reflect = |v: &[DVec3], sign: f64| {
                v.iter()
                    .map(|&x| (x - 2.0 * x.dot(normal) * normal) * sign)
                    .collect()
            };
            RawFrame {
                f2: reflect(&frame.f2, 1.0),
                f3: reflect(&frame.f3, -1.0),
                denominator: frame.denominator,
            }
        }
        (None, Inversion::Sphere { .. }) => unreachable!("a sphere has an axis"),
    }
}

/// The image of one segment (and of its frame, if given) under the whole map.
fn map_segment(
    map: &MobiusMap,
    points: &[DVec4],
    frame: Option<RawFrame>,
) -> (Homogeneous, Option<RawFrame>) {
    map.inversions()
        .iter()
        .fold((points.to_vec(), frame), |(pts, frame), inv| {
            let frame = frame.map(|f| transport_frame(inv, &pts, f));
            (invert_points(inv, &pts), frame)
        })
}

/// Local breakpoints on which the image's weights (and frame denominator) are positive.
fn positive_pieces(points: &[DVec4], frame: Option<&RawFrame>, segment: usize) -> Result<Vec<f64>> {
    let weights: Vec<f64> = points.iter().map(|h| h.w).collect();
    let mut polys: Vec<&[f64]> = vec![&weights];
    if let Some(f) = frame {
        polys.push(&f.denominator);
    }
    match positive_subdivision(&polys, MAX_HALVINGS) {
        Some(breaks) => Ok(breaks),
        None => invalid!("segment {segment} passes through (or too near) an inversion centre: its image is unbounded"),
    }
}

/// `a + (b − a)·s`, exactly `a` and `b` at the ends (breakpoints must match exactly).
pub(crate) fn global_parameter(a: f64, b: f64, s: f64) -> f64 {
    crate::math::lerp(a, b, s)
}

/// The image of a piecewise curve under a Möbius map, exactly.
pub fn map_curve(map: &MobiusMap, curve: &PiecewiseCurve) -> Result<PiecewiseCurve> {
    Ok(map_pieces(map, curve, None)?.0)
}

/// The images of a curve and of exact rational frames along it (Corollary 1). The frames
/// may refine the curve's segments; the result shares one segmentation.
pub fn map_framed_curve(map: &MobiusMap, framed: &FramedCurve) -> Result<FramedCurve> {
    let curve = framed.curve_on_frame_segments();
    let (image, frames) = map_pieces(map, &curve, Some(framed.frames()))?;
    Ok(FramedCurve::of_construction(
        image,
        frames.expect("frames were given"),
    ))
}

/// The degrees of the image of a segment of degree `n` (and of frames of degree `m`) stay
/// within [`MAX_DEGREE`]: a sphere inversion takes n to 2n and m to m + 2n (module notes), so
/// a few inversions of a cubic already exceed it (frames of degree 188, past the Bernstein
/// tables).
fn check_image_degrees(map: &MobiusMap, n: usize, m: Option<usize>) -> Result<()> {
    let (mut curve, mut frame) = (n, m);
    for inversion in map.inversions() {
        if inversion.is_sphere() {
            frame = frame.map(|m| m.saturating_add(curve.saturating_mul(2)));
            curve = curve.saturating_mul(2);
        }
    }
    let frame = frame.unwrap_or(0);
    if curve > MAX_DEGREE || frame > MAX_DEGREE {
        return invalid!(
            "the image would have degree {curve} (frames {frame}), above {MAX_DEGREE}: each \
             sphere inversion doubles a curve's degree"
        );
    }
    Ok(())
}

/// Maps every segment (with its frame, if any), splits where weights are not positive, and
/// reassembles on the refined segmentation.
fn map_pieces(
    map: &MobiusMap,
    curve: &PiecewiseCurve,
    frames: Option<&RationalFrames>,
) -> Result<(PiecewiseCurve, Option<RationalFrames>)> {
    for (k, segment) in curve.segments().iter().enumerate() {
        let frame_degree = frames.map(|f| f.segments()[k].degree());
        check_image_degrees(map, segment.degree(), frame_degree)?;
    }
    let mut segments = Vec::new();
    let mut frame_segments = Vec::new();
    let mut breaks = vec![curve.breaks()[0]];
    for (k, segment) in curve.segments().iter().enumerate() {
        let raw = frames.map(|f| {
            let frame = &f.segments()[k];
            RawFrame {
                f2: frame.f2_numerator().to_vec(),
                f3: frame.f3_numerator().to_vec(),
                denominator: frame.denominator().to_vec(),
            }
        });
        let (a, b) = (curve.breaks()[k], curve.breaks()[k + 1]);
        for (s1, piece, frame) in map_raw_segment(map, segment.homogeneous(), raw, k)? {
            segments.push(piece);
            frame_segments.extend(frame);
            breaks.push(global_parameter(a, b, s1));
        }
    }
    // Theorem 1: the image of an RMF is an RMF; a twist against it is not kept as such
    // (the image's arc length is another).
    let frames = match frames {
        Some(f) => Some(
            RationalFrames::new(frame_segments, breaks.clone())?.with_turning(match f.turning() {
                Turning::RotationMinimizing => Turning::RotationMinimizing,
                _ => Turning::Unknown,
            }),
        ),
        None => None,
    };
    Ok((PiecewiseCurve::new(segments, breaks)?, frames))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::{uniform_parameters, ParametricCurve};
    use crate::frames::double_reflection::DoubleReflectionRmf;
    use crate::frames::metrics::{orthonormality_error, rmf_defect};
    use crate::frames::{FrameField, FrameKind};
    use crate::testing::{gap_to_double_reflection, planar_ph_cubic, Helix};
    use std::sync::Arc;

    fn composite() -> MobiusMap {
        MobiusMap::new(vec![
            Inversion::sphere(DVec3::new(0.5, 3.0, 2.0), 2.5).unwrap(),
            Inversion::plane(DVec3::new(0.0, 0.5, 0.0), DVec3::new(1.0, 2.0, -1.0)).unwrap(),
            Inversion::sphere(DVec3::new(-2.0, 0.0, 1.5), 1.8).unwrap(),
        ])
    }

    /// μ∘x for an analytic curve: points by μ, derivatives by dμ.
    struct Image<'a> {
        map: &'a MobiusMap,
        curve: &'a dyn ParametricCurve,
    }

    impl ParametricCurve for Image<'_> {
        fn domain(&self) -> (f64, f64) {
            self.curve.domain()
        }
        fn point_derivative(&self, t: f64) -> crate::Result<(DVec3, DVec3)> {
            let (p, d) = self.curve.point_derivative(t)?;
            Ok((
                self.map.apply(p).unwrap(),
                self.map.differential(p, d).unwrap(),
            ))
        }
    }

    /// Theorem 1, pointwise: d*μ carries the exact RMF of a helix to the RMF of its image,
    /// which double reflection computes independently on the image curve.
    #[test]
    fn theorem_1_the_image_of_an_rmf_is_the_rmf_of_the_image() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.4,
        };
        let map = composite();
        let image = Image {
            map: &map,
            curve: &helix,
        };
        let transported = |t: f64| {
            let (p, _) = helix.point_derivative(t).unwrap();
            map.normalized_differential(p, helix.exact_rmf(t).f2)
                .unwrap()
        };
        let params = uniform_parameters(helix.domain(), 8000);
        let reference =
            DoubleReflectionRmf::along(&image, params.clone(), transported(0.0)).unwrap();
        let worst = params
            .iter()
            .zip(reference.frames())
            .map(|(&t, f)| (transported(t) - f.f2).length())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-9,
            "transported RMF differs from double reflection by {worst}"
        );
    }

    /// Repeated sphere inversions raise the frames' degree fast (to 188 in a few), past the
    /// tables of the Bernstein products: images beyond the degree bound are refused before
    /// any product.
    #[test]
    fn images_beyond_the_degree_bound_are_refused() {
        let framed = planar_ph_cubic();
        let curve = framed.curve();
        let sphere = Inversion::sphere(DVec3::new(1.0, -2.0, -1.0), 3.0).unwrap();
        // A cubic: 3 → 6 → 12 → 24 → 48; its frames grow faster (m → m + 2n).
        let four = MobiusMap::new(vec![sphere; 4]);
        let e = map_framed_curve(&four, &framed).unwrap_err();
        assert!(e.message().contains("above 64"), "{e}");
        assert!(
            map_curve(&four, curve).is_ok(),
            "the curve alone has degree 48"
        );
        let five = MobiusMap::new(vec![sphere; 5]);
        assert!(map_curve(&five, curve).is_err());
    }

    /// Corollary 1, exactly: the rational image of a rational RMF is a rational RMF of the
    /// rational image curve. Mapped twice, so the second map acts on a non-planar curve.
    #[test]
    fn exact_images_of_rational_rmfs_are_rational_rmfs() {
        let framed = planar_ph_cubic();
        let curve = framed.curve();
        let map = composite();
        let once = map_framed_curve(&map, &framed).unwrap();
        let second = MobiusMap::new(vec![
            Inversion::sphere(DVec3::new(1.0, -2.0, -1.0), 3.0).unwrap()
        ]);
        let (twice, twice_frames) = map_framed_curve(&second, &once).unwrap().into_parts();
        let degree = twice.segments().iter().map(|s| s.degree()).max().unwrap();
        assert_eq!(
            degree, 24,
            "each sphere inversion doubles the degree: 3 → 6 → 12 → 24"
        );
        let full = MobiusMap::new([map.inversions(), second.inversions()].concat());
        let field = FrameField::new(
            Arc::new(twice.clone()),
            FrameKind::Rational(twice_frames.clone()),
        )
        .unwrap();
        let params = uniform_parameters(twice.domain(), 1001);
        let mut worst = [0.0f64; 4];
        for &t in &params {
            let original = curve.eval(t);
            let p = twice.eval(t);
            worst[0] = worst[0].max((p - full.apply(original).unwrap()).length());
            let frame = twice_frames.frame(t);
            let tangent = twice.eval_jet(t).d1.normalize();
            worst[1] = worst[1].max((frame.tangent - tangent).length());
            worst[2] = worst[2].max(rmf_defect(&field, t).unwrap().abs());
            worst[3] = worst[3].max(orthonormality_error(&frame));
        }
        assert!(worst[0] < 1e-12, "image points off by {}", worst[0]);
        assert!(worst[1] < 1e-12, "frame tangent off by {}", worst[1]);
        assert!(worst[2] < 1e-10, "RMF defect {}", worst[2]);
        assert!(worst[3] < 1e-13, "orthonormality {}", worst[3]);
        let drift = gap_to_double_reflection(&twice, twice_frames.frame(0.0).f2, 1001, |t| {
            twice_frames.frame(t)
        });
        assert!(
            drift < 1e-8,
            "exact rational RMF vs double reflection: {drift}"
        );
    }

    #[test]
    fn a_curve_through_an_inversion_centre_is_refused() {
        let framed = planar_ph_cubic();
        let curve = framed.curve().clone();
        let through = MobiusMap::new(vec![Inversion::sphere(curve.eval(0.5), 1.0).unwrap()]);
        let e = map_curve(&through, &curve).unwrap_err();
        assert!(e.message().contains("inversion centre"), "{e}");
        let reflected = map_curve(
            &MobiusMap::new(vec![Inversion::plane(DVec3::ZERO, DVec3::X).unwrap()]),
            &curve,
        )
        .unwrap();
        assert!(
            (reflected.eval(0.3) - curve.eval(0.3) * DVec3::new(-1.0, 1.0, 1.0)).length() < 1e-15
        );
    }
}
