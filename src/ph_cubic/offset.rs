//! Offsets of profile surfaces, Proposition 4 of Mäurer & Jüttler: the normal of a profile
//! surface lies in the normal plane of the spine and is the normal of the profile, so the
//! offset at distance d is the profile surface (same spine, same frames) of the planar offset
//! c_d = c + dN of the profile, with N = (ċ₃, −ċ₂)/|ċ| as in (10).
//!
//! c_d is rational exactly when |ċ| is. For a segment c = (X, Y)/h with (A, B) = h²ċ that
//! means A² + B² = S² for a polynomial S, and then c_d = (XS + dhB, YS − dhA)/(hS). Lines,
//! circular arcs and planar PH curves pass; other profiles (an ellipse, a generic cubic) have
//! no rational offset and are refused.

use super::profile::{difference, profile_segments, sum, ProfileSegment};
use crate::bezier::bernstein::{self, from_power, product, restrict, to_power};
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::ResultExt;
use crate::error::{invalid, Error, Result};
use glam::{DVec3, DVec4};

/// Relative size of power-basis coefficients taken as zero when finding the degree of A² + B².
const TRIM: f64 = 1e-11;

/// Largest relative residual of S² − (A² + B²) accepted as a perfect square.
const SQUARE_TOLERANCE: f64 = 1e-9;

/// The offset of a planar profile (x, y; z ignored, 0 in the result) at signed distance
/// `distance` along N = (ẏ, −ẋ)/|ċ| (the right-hand normal, (10)), exact and rational, on the
/// profile's parameter (segments may be split for positive weights).
pub fn offset_profile(profile: &PiecewiseCurve, distance: f64) -> Result<PiecewiseCurve> {
    if !distance.is_finite() {
        return invalid!("distance = {distance} must be finite");
    }
    let mut segments = Vec::new();
    let mut breaks = vec![profile.breaks()[0]];
    for (k, (segment, original)) in profile_segments(profile)
        .iter()
        .zip(profile.segments())
        .enumerate()
    {
        let (a, b) = (profile.breaks()[k], profile.breaks()[k + 1]);
        if let Some(offset) = elementary_offset(original, distance) {
            segments.push(offset);
            breaks.push(b);
            continue;
        }
        let homogeneous =
            offset_segment(segment, distance).with_context(|| format!("profile segment {k}"))?;
        let weights: Vec<f64> = homogeneous.iter().map(|h| h.w).collect();
        let cuts = bernstein::positive_subdivision(&[&weights], 40).ok_or_else(|| {
            Error::invalid_input(format!("profile segment {k} has a singular point (ċ = 0)"))
        })?;
        for w in cuts.windows(2) {
            segments.push(RationalBezierCurve::from_homogeneous(restrict(
                &homogeneous,
                w[0],
                w[1],
            ))?);
            breaks.push(crate::math::lerp(a, b, w[1]));
        }
    }
    PiecewiseCurve::new(segments, breaks)
}

/// The offset of a circular arc (the concentric arc: control points scaled about the centre,
/// weights kept) or of a straight piece (moved along its normal), directly. The general
/// construction below covers both in principle, but its perfect-square test fails for arcs of
/// small angle and unevenly parametrized lines, whose leading power coefficients drop to the
/// rounding.
fn elementary_offset(segment: &RationalBezierCurve, d: f64) -> Option<RationalBezierCurve> {
    let flat: Vec<DVec4> = segment
        .homogeneous()
        .iter()
        .map(|h| DVec4::new(h.x, h.y, 0.0, h.w))
        .collect();
    let curve = RationalBezierCurve::from_homogeneous(flat.clone()).ok()?;
    let poles: Vec<DVec3> = curve.poles().collect();
    let (first, last) = (poles[0], poles[poles.len() - 1]);
    let size = poles
        .iter()
        .fold(0.0f64, |m, p| m.max((*p - first).abs().max_element()));
    if let Some((centre, radius)) = curve.circular_arc(1e-12 * size) {
        // N = (ẏ, −ẋ)/|ċ| points away from the centre when the arc turns left.
        let left = (poles[1] - first).cross(last - poles[1]).z > 0.0;
        let factor = (radius + if left { d } else { -d }) / radius;
        let moved = flat
            .iter()
            .map(|h| ((h.truncate() - centre * h.w) * factor + centre * h.w).extend(h.w))
            .collect();
        return RationalBezierCurve::from_homogeneous(moved).ok();
    }
    let direction = (last - first).normalize_or_zero();
    let straight = direction != DVec3::ZERO
        && poles.windows(2).all(|w| {
            let step = w[1] - w[0];
            step.dot(direction) >= 0.0 && step.cross(direction).length() <= 1e-12 * size
        });
    straight.then(|| curve.similar(1.0, d * DVec3::new(direction.y, -direction.x, 0.0)))
}

/// Homogeneous control points (XS + dhB, YS − dhA, 0, hS) of one offset segment, in the
/// lowest degree: when h divides S (circular arcs, where S ∝ h) the common factor h is
/// cancelled, c_d = (Xq + dB, Yq − dA)/(hq) with S = qh; then degrees that the products
/// only carry formally are dropped.
fn offset_segment(segment: &ProfileSegment, d: f64) -> Result<Vec<DVec4>> {
    let (a, b) = segment.scaled_tangent();
    let mul = |p: f64, q: f64| p * q;
    let speed_squared = sum(&product(&a, &a, mul), &product(&b, &b, mul));
    let Some(s) = polynomial_sqrt(&speed_squared) else {
        return Err(Error::no_solution(
            "|c'| is not rational (A² + B² is no perfect square): the offset is not a rational \
             curve; only lines, circular arcs and planar PH curves have rational offsets (for \
             others, offset_profile_by_arcs gives the exact offset of arcs within a tolerance)",
        ));
    };
    let (factor, shift) = match exact_quotient(&s, &segment.h) {
        Some(q) => (q, vec![1.0]),
        None => (s, segment.h.clone()),
    };
    let scaled = |p: &[f64]| {
        product(&shift, p, mul)
            .iter()
            .map(|c| c * d)
            .collect::<Vec<_>>()
    };
    let x = sum(&product(&segment.x, &factor, mul), &scaled(&b));
    let y = difference(&product(&segment.y, &factor, mul), &scaled(&a));
    let w = product(&segment.h, &factor, mul);
    let n = x.len().max(y.len()).max(w.len()) - 1;
    let (x, y, w) = (
        bernstein::elevate_to(&x, n),
        bernstein::elevate_to(&y, n),
        bernstein::elevate_to(&w, n),
    );
    let points = (0..=n).map(|i| DVec4::new(x[i], y[i], 0.0, w[i])).collect();
    Ok(lowest_degree(points))
}

/// Drops degrees while the reduction is exact (elevating back reproduces the points).
fn lowest_degree(mut points: Vec<DVec4>) -> Vec<DVec4> {
    let size = points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    while points.len() > 2 {
        let reduced = bernstein::reduce_degree(&points);
        let back = bernstein::elevate(&reduced, 1);
        let exact = back
            .iter()
            .zip(&points)
            .all(|(a, b)| (*a - *b).abs().max_element() <= 1e-13 * size);
        if !exact {
            break;
        }
        points = reduced;
    }
    points
}

/// q with p = q·h exactly (power-basis long division, remainder zero to round-off).
fn exact_quotient(p: &[f64], h: &[f64]) -> Option<Vec<f64>> {
    let trimmed = |c: Vec<f64>| {
        let scale = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let len = c
            .iter()
            .rposition(|x| x.abs() > TRIM * scale)
            .map_or(0, |i| i + 1);
        c[..len].to_vec()
    };
    let (mut rest, divisor) = (trimmed(to_power(p)), trimmed(to_power(h)));
    if divisor.is_empty() || rest.len() < divisor.len() {
        return None;
    }
    let scale = rest.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let lead = divisor[divisor.len() - 1];
    let mut quotient = vec![0.0; rest.len() - divisor.len() + 1];
    for k in (0..quotient.len()).rev() {
        let c = rest[k + divisor.len() - 1] / lead;
        quotient[k] = c;
        for (j, &dj) in divisor.iter().enumerate() {
            rest[k + j] -= c * dj;
        }
    }
    let remainder = rest.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    (remainder <= SQUARE_TOLERANCE * scale).then(|| from_power(&quotient))
}

/// S ≥ 0 on [0, 1] with S² = p (Bernstein coefficients in, of S's own degree out), or `None`
/// when p is not the square of a polynomial without roots in [0, 1].
fn polynomial_sqrt(p: &[f64]) -> Option<Vec<f64>> {
    let power = to_power(p);
    let scale = power.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let degree = power.iter().rposition(|c| c.abs() > TRIM * scale)?;
    if degree % 2 == 1 || power[degree] <= 0.0 {
        return None;
    }
    let n = degree / 2;
    let mut root = vec![0.0; n + 1];
    root[n] = power[degree].sqrt();
    // The coefficient of t^(2n−k) in S² is 2 s_n s_(n−k) + Σ s_i s_(2n−k−i), n − k < i < n.
    for k in 1..=n {
        let mixed: f64 = (n - k + 1..n).map(|i| root[i] * root[degree - k - i]).sum();
        root[n - k] = (power[degree - k] - mixed) / (2.0 * root[n]);
    }
    let square = product(&from_power(&root), &from_power(&root), |a: f64, b: f64| {
        a * b
    });
    let residual = to_power(&square)
        .iter()
        .chain(std::iter::repeat(&0.0))
        .zip(power.iter())
        .map(|(s, q)| (s - q).abs())
        .fold(0.0f64, f64::max);
    if residual > SQUARE_TOLERANCE * scale {
        return None;
    }
    let bernstein_root = from_power(&root);
    let sign = bernstein::evaluate(&bernstein_root, 0.5).signum();
    let positive: Vec<f64> = bernstein_root.iter().map(|c| c * sign).collect();
    let no_root = super::profile::interior_roots(&positive).is_empty()
        && bernstein::evaluate(&positive, 0.0) > 0.0
        && bernstein::evaluate(&positive, 1.0) > 0.0;
    no_root.then_some(positive)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ph_cubic::rational_rmf::{ph_rational_rmf, RmfOptions};
    use crate::ph_cubic::test_curves::helix_spline;
    use crate::sweep::sweep;
    use crate::testing::tschirnhausen;
    use glam::DVec3;

    fn single(segment: RationalBezierCurve) -> PiecewiseCurve {
        PiecewiseCurve::new(vec![segment], vec![0.0, 1.0]).unwrap()
    }

    fn circle_arc() -> PiecewiseCurve {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        single(
            RationalBezierCurve::from_weighted(
                &[
                    DVec3::new(0.5, 0.0, 0.0),
                    DVec3::new(0.5, 0.5, 0.0),
                    DVec3::new(0.0, 0.5, 0.0),
                ],
                &[1.0, s, 1.0],
            )
            .unwrap(),
        )
    }

    #[test]
    fn offsets_of_lines_circles_and_ph_curves_are_exact() {
        let line = single(
            RationalBezierCurve::polynomial(&[
                DVec3::new(0.1, 0.2, 0.0),
                DVec3::new(0.4, -0.2, 0.0),
            ])
            .unwrap(),
        );
        let planar_ph = single(tschirnhausen(std::f64::consts::FRAC_PI_3, 1.0).to_bezier());
        for (profile, degree) in [(line, 1), (circle_arc(), 2), (planar_ph, 5)] {
            for d in [0.05, -0.1] {
                let offset = offset_profile(&profile, d).unwrap();
                assert_eq!(offset.segments()[0].degree(), degree);
                for i in 0..=20 {
                    let u = i as f64 / 20.0;
                    let (c, jet) = (profile.eval(u), profile.eval_jet(u));
                    let n = DVec3::new(jet.d1.y, -jet.d1.x, 0.0).normalize();
                    let p = offset.eval(u);
                    assert!((p - (c + d * n)).length() < 1e-14, "u = {u}, d = {d}");
                }
            }
        }
    }

    #[test]
    fn small_arcs_and_unevenly_parametrized_lines_are_offset_exactly() {
        for angle in [1e-2f64, 1e-4, 1e-7] {
            let half = 0.5 * angle;
            let (r, w) = (3.0, half.cos());
            let at = |a: f64, s: f64| DVec3::new(a.cos(), a.sin(), 0.0) * s;
            let arc = RationalBezierCurve::from_weighted(
                &[at(-half, r), at(0.0, r / w), at(half, r)],
                &[1.0, w, 1.0],
            )
            .unwrap();
            // Counterclockwise: N = (ẏ, −ẋ) points outwards.
            let offset = offset_profile(&single(arc), 0.2).unwrap();
            for i in 0..=10 {
                let p = offset.eval(i as f64 / 10.0);
                assert!(
                    (p.length() - 3.2).abs() < 1e-14,
                    "angle {angle}: {}",
                    p.length()
                );
            }
        }
        let uneven = RationalBezierCurve::polynomial(&[
            DVec3::ZERO,
            DVec3::new(0.1 + 1e-9, 0.0, 0.0),
            DVec3::new(0.2, 0.0, 0.0),
        ])
        .unwrap();
        let offset = offset_profile(&single(uneven), 0.5).unwrap();
        assert!((offset.eval(0.3) - DVec3::new(offset.eval(0.3).x, -0.5, 0.0)).length() < 1e-15);
    }

    #[test]
    fn profiles_without_rational_offsets_are_refused() {
        let ellipse = single(
            RationalBezierCurve::from_weighted(
                &[
                    DVec3::new(2.0, 0.0, 0.0),
                    DVec3::new(2.0, 1.0, 0.0),
                    DVec3::new(0.0, 1.0, 0.0),
                ],
                &[1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
            )
            .unwrap(),
        );
        let e = offset_profile(&ellipse, 0.1).unwrap_err();
        assert!(e.is(crate::ErrorKind::NoSolution) && e.message().contains("profile segment 0"));
        assert!(offset_profile(&circle_arc(), f64::NAN).is_err());
    }

    #[test]
    fn offset_surface_is_the_sweep_of_the_offset_profile() {
        let spine = helix_spline(4, 0.6);
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z)).unwrap();
        let profile = circle_arc();
        let d = 0.07;
        let surface = sweep(&rmf.framed, &profile).unwrap();
        let offset = sweep(&rmf.framed, &offset_profile(&profile, d).unwrap()).unwrap();
        for i in 0..=10 {
            for j in 0..=10 {
                let (u, v) = (i as f64 / 10.0, 4.0 * j as f64 / 10.0);
                let jet = surface.eval_jet(u, v);
                let normal = jet.du.cross(jet.dv).normalize();
                let step = offset.eval(u, v) - jet.point;
                assert!((step.length() - d).abs() < 1e-14);
                let off_normal = step.cross(normal).length() / d;
                assert!(off_normal < 1e-6, "({u}, {v}): {off_normal}");
            }
        }
    }
}
