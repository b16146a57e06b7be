//! Offsets of profiles that have no rational offset, through an arc approximation.
//!
//! The offset c + dN of a planar curve has the unit normal N = (ẏ, −ẋ)/|ċ|. It is rational
//! exactly when |ċ| = √(ẋ² + ẏ²) is, i.e. when ẋ² + ẏ² is the square of a polynomial (the
//! Pythagorean-hodograph condition; for a rational curve, of its numerator, Proposition 4 of
//! Mäurer & Jüttler and [`offset`](super::offset)). For a generic curve (an ellipse, a cubic
//! of a drawing) it is not: the offset is an algebraic curve of higher degree, and no NURBS
//! represents it. The nearest exact answer is the exact offset of a curve close to the
//! profile: here a G¹ chain of circular arcs (biarcs: two arcs with a common tangent through
//! two points with their tangents, Fuhs & Stachel (7)–(8), [`biarc`](crate::cone_spline::biarc)),
//! whose offsets are arcs again, concentric, exactly.
//!
//! Each profile segment is cut into intervals. Each interval is replaced by the equal-leg biarc
//! through its end points and end tangents, and halved until both the profile and its offset
//! are within the tolerance of the biarc and of the biarc's offset. The distances are
//! measured to each arc by its circle, at 17 points of the interval and then at the largest's
//! maximum by Brent's method.

use super::offset::offset_profile;
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::{invalid, Error, Num, Result};
use crate::math::{interior_midpoint, lerp, minimize_bracketed, robust_normalize};
use crate::model::biarc::{biarc, equal_lambda};
use glam::DVec3;

/// Intervals between the samples at which the distances are measured.
const SAMPLES: usize = 16;

/// Halvings of a profile segment's parameter interval before giving up.
const MAX_HALVINGS: usize = 30;

/// How unequal the legs of a biarc's arc may be, at the unit size the fit works at.
const ARC_TOLERANCE: f64 = 1e-12;

/// Most arcs one call makes (the error of a biarc falls with the cube of its length, so this
/// allows tolerances far below any drawing's at the size of the profile).
pub(crate) const MAX_ARCS: usize = 1 << 16;

/// A profile replaced by arcs within a tolerance, and the exact offset of the arcs.
#[derive(Clone, Debug)]
pub struct ArcOffset {
    /// The profile as a G¹ chain of rational quadratic arcs (two per interval, joined at the
    /// interval's middle parameter), on the profile's domain.
    pub arcs: PiecewiseCurve,
    /// The exact offset of `arcs` at the distance (as [`offset_profile`] gives it).
    pub offset: PiecewiseCurve,
    /// The largest distance measured from the profile to `arcs`.
    pub profile_deviation: f64,
    /// The largest distance measured from the profile's true offset to `offset`.
    pub offset_deviation: f64,
}

/// The offset of a planar `profile` (x, y; z ignored) at the signed `distance` along
/// N = (ẏ, −ẋ)/|ċ|, as the exact offset of arcs that stay within `tolerance` of the profile
/// and whose offset stays within `tolerance` of the profile's offset.
pub fn offset_profile_by_arcs(
    profile: &PiecewiseCurve,
    distance: f64,
    tolerance: f64,
) -> Result<ArcOffset> {
    if !distance.is_finite() {
        return invalid!("distance = {} must be finite", Num(distance));
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return invalid!("tolerance = {} must be finite and positive", Num(tolerance));
    }
    // Fitted at unit size about the first pole (lengths of tiny or huge profiles under- or
    // overflow), by a power of two so that the scaling is exact.
    let flat = |p: DVec3| DVec3::new(p.x, p.y, 0.0);
    let poles: Vec<DVec3> = profile
        .segments()
        .iter()
        .flat_map(|s| s.poles())
        .map(flat)
        .collect();
    let origin = poles[0];
    let size = poles
        .iter()
        .fold(0.0f64, |m, p| m.max((*p - origin).abs().max_element()));
    if !(size.is_finite() && size > 0.0) {
        return invalid!("the profile must span a finite, non-zero extent");
    }
    let scale = 2f64.powi(-(size.log2().round() as i32));
    let unit = profile.similar(scale, -origin * scale);
    let fit = fit_arcs(&unit, distance * scale, tolerance * scale)?;
    let back = |c: &PiecewiseCurve| c.similar(1.0 / scale, origin);
    let result = ArcOffset {
        arcs: back(&fit.arcs),
        offset: back(&fit.offset),
        profile_deviation: fit.profile_deviation / scale,
        offset_deviation: fit.offset_deviation / scale,
    };
    // An offset far beyond a profile of large coordinates can leave the range of f64 only
    // on the way back to the caller's units.
    let finite = |c: &PiecewiseCurve| {
        c.segments()
            .iter()
            .all(|s| s.homogeneous().iter().all(|h| h.is_finite()))
    };
    if !(finite(&result.arcs)
        && finite(&result.offset)
        && result.profile_deviation.is_finite()
        && result.offset_deviation.is_finite())
    {
        return invalid!(
            "distance = {} puts the offset beyond the range of a double (the profile's \
             coordinates reach {:.3e})",
            Num(distance),
            origin.abs().max_element() + size
        );
    }
    Ok(result)
}

/// [`offset_profile_by_arcs`] for a profile of about unit size.
fn fit_arcs(profile: &PiecewiseCurve, distance: f64, tolerance: f64) -> Result<ArcOffset> {
    let mut arcs = Vec::new();
    let mut breaks = vec![profile.breaks()[0]];
    let (mut profile_deviation, mut offset_deviation) = (0.0f64, 0.0f64);
    let b = profile.breaks();
    for (k, segment) in profile.segments().iter().enumerate() {
        let fit = Fit {
            segment,
            distance,
            tolerance,
        };
        let mut pending = vec![(0.0, 1.0, 0)];
        while let Some((s0, s1, depth)) = pending.pop() {
            match fit.biarc(s0, s1)? {
                Some(piece) => {
                    profile_deviation = profile_deviation.max(piece.deviations.0);
                    offset_deviation = offset_deviation.max(piece.deviations.1);
                    let (g0, g1) = (lerp(b[k], b[k + 1], s0), lerp(b[k], b[k + 1], s1));
                    arcs.extend(piece.arcs);
                    breaks.extend([0.5 * (g0 + g1), g1]);
                    if arcs.len() > MAX_ARCS {
                        return Err(Error::not_converged(format!(
                            "more than {MAX_ARCS} arcs are needed for tolerance {}",
                            Num(tolerance)
                        )));
                    }
                }
                None => {
                    let mid = interior_midpoint(s0, s1).filter(|_| depth < MAX_HALVINGS);
                    let Some(mid) = mid else {
                        return Err(Error::not_converged(format!(
                            "profile segment {k}: no arcs within tolerance {} near parameter {}",
                            Num(tolerance),
                            Num(lerp(b[k], b[k + 1], s0))
                        )));
                    };
                    // Right half first: the stack hands out the left half next.
                    pending.push((mid, s1, depth + 1));
                    pending.push((s0, mid, depth + 1));
                }
            }
        }
    }
    let arcs = PiecewiseCurve::new(arcs, breaks)?;
    let offset = offset_profile(&arcs, distance)?;
    Ok(ArcOffset {
        arcs,
        offset,
        profile_deviation,
        offset_deviation,
    })
}

/// One profile segment to be replaced by biarcs.
struct Fit<'a> {
    segment: &'a RationalBezierCurve,
    distance: f64,
    tolerance: f64,
}

/// The two arcs of an interval with the largest distances measured (profile, offset).
struct Piece {
    arcs: [RationalBezierCurve; 2],
    deviations: (f64, f64),
}

/// A circular arc from `start` to `end` (less than a half turn, or a straight piece) in the
/// plane z = 0, by its centre and radius.
struct Arc {
    start: DVec3,
    end: DVec3,
    centre: Option<(DVec3, f64)>,
}

impl Fit<'_> {
    /// Point and unit tangent of the profile (in the plane z = 0) at the local parameter s.
    fn at(&self, s: f64) -> Result<(DVec3, DVec3)> {
        let (p, d) = self.segment.eval_d1(s);
        let flat = |v: DVec3| DVec3::new(v.x, v.y, 0.0);
        let tangent = robust_normalize(flat(d)).ok_or_else(|| {
            Error::invalid_input(format!(
                "the profile has a singular point (ċ = 0) at local parameter {}",
                Num(s)
            ))
        })?;
        Ok((flat(p), tangent))
    }

    /// The point of the offset at s.
    fn offset_at(&self, s: f64) -> Result<DVec3> {
        let (p, t) = self.at(s)?;
        Ok(p + self.distance * DVec3::new(t.y, -t.x, 0.0))
    }

    /// The biarc of [s0, s1] when it and its offset are within the tolerance.
    fn biarc(&self, s0: f64, s1: f64) -> Result<Option<Piece>> {
        let ((a1, p1), (a2, p2)) = (self.at(s0)?, self.at(s1)?);
        let Some(lambda) = equal_lambda(a1, p1, a2, p2) else {
            return Ok(None);
        };
        let b = biarc(a1, p1, a2, p2, lambda, lambda);
        if !(b.w1 > 0.0 && b.w2 > 0.0) {
            return Ok(None);
        }
        let arc = |a: DVec3, m: DVec3, c: DVec3, w: f64| {
            RationalBezierCurve::from_weighted(&[a, m, c], &[1.0, w, 1.0])
        };
        let arcs = [arc(b.a1, b.b1, b.c, b.w1)?, arc(b.c, b.b2, b.a2, b.w2)?];
        let (Some(first), Some(second)) = (Arc::of(&arcs[0]), Arc::of(&arcs[1])) else {
            return Ok(None);
        };
        let joint_tangent = (b.b2 - b.c).normalize_or_zero();
        let offsets = [
            first.offset(self.distance, p1, joint_tangent),
            second.offset(self.distance, joint_tangent, p2),
        ];
        let near = |s: f64| {
            let (point, _) = self.at(s)?;
            Ok(first.distance(point).min(second.distance(point)))
        };
        let far = |s: f64| {
            let q = self.offset_at(s)?;
            Ok(offsets[0].distance(q).min(offsets[1].distance(q)))
        };
        let near = largest(near, s0, s1)?;
        let far = largest(far, s0, s1)?;
        if near > self.tolerance || far > self.tolerance {
            return Ok(None);
        }
        Ok(Some(Piece {
            arcs,
            deviations: (near, far),
        }))
    }
}

/// The largest value of a distance function on [s0, s1]: its samples, then Brent's method
/// about the largest (the distance of a smooth curve from its biarc has few extrema).
fn largest(f: impl Fn(f64) -> Result<f64>, s0: f64, s1: f64) -> Result<f64> {
    let at = |i: usize| lerp(s0, s1, i as f64 / SAMPLES as f64);
    let values = (0..=SAMPLES)
        .map(|i| f(at(i)))
        .collect::<Result<Vec<f64>>>()?;
    let (i, best) = values
        .iter()
        .copied()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .expect("samples");
    let (a, b) = (at(i.saturating_sub(1)), at((i + 1).min(SAMPLES)));
    let refined = minimize_bracketed(|s| f(s).map_or(f64::INFINITY, |v| -v), a, b, 0.0);
    Ok(best.max(-refined.value))
}

impl Arc {
    /// One arc of a biarc (a rational quadratic at unit size) by its circle
    /// ([`RationalBezierCurve::circular_arc`]), or a straight piece; `None` when it is
    /// neither (rounding broke its equal legs).
    fn of(curve: &RationalBezierCurve) -> Option<Self> {
        let poles: Vec<DVec3> = curve.poles().collect();
        let (start, inner, end) = (poles[0], poles[1], poles[2]);
        if let Some(centre) = curve.circular_arc(ARC_TOLERANCE) {
            return Some(Self {
                start,
                end,
                centre: Some(centre),
            });
        }
        let (leg, chord) = (inner - start, end - start);
        let straight = leg.cross(chord).length() <= 1e-14 * leg.length() * chord.length();
        straight.then_some(Self {
            start,
            end,
            centre: None,
        })
    }

    /// The arc's offset at `distance` along (t_y, −t_x): concentric, or the moved segment.
    fn offset(&self, distance: f64, tangent: DVec3, end_tangent: DVec3) -> Self {
        let shift = |t: DVec3| distance * DVec3::new(t.y, -t.x, 0.0);
        let (start, end) = (self.start + shift(tangent), self.end + shift(end_tangent));
        let centre = self
            .centre
            .map(|(m, _)| (m, 0.5 * ((start - m).length() + (end - m).length())));
        Self { start, end, centre }
    }

    /// The distance of p from the arc: to its circle where p lies in the arc's sector, else to
    /// the nearer end.
    fn distance(&self, p: DVec3) -> f64 {
        let ends = (p - self.start).length().min((p - self.end).length());
        match self.centre {
            Some((m, radius)) => {
                let (a, b, q) = (self.start - m, self.end - m, p - m);
                let turn = a.x * b.y - a.y * b.x;
                let inside = (a.x * q.y - a.y * q.x) * turn >= 0.0
                    && (q.x * b.y - q.y * b.x) * turn >= 0.0
                    && q.dot(a + b) >= 0.0;
                if inside {
                    (q.length() - radius).abs()
                } else {
                    ends
                }
            }
            None => {
                let d = self.end - self.start;
                let t = ((p - self.start).dot(d) / d.length_squared()).clamp(0.0, 1.0);
                (p - (self.start + t * d)).length()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::minimize_bracketed;

    /// A quarter of the ellipse (2 cos θ, sin θ) about `centre`, as a rational quadratic (an
    /// affine image of a circular arc: no rational offset).
    fn quarter_ellipse(scale: f64, centre: DVec3) -> PiecewiseCurve {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let poles = [
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ]
        .map(|p| p * scale + centre);
        let arc = RationalBezierCurve::from_weighted(&poles, &[1.0, w, 1.0]).unwrap();
        PiecewiseCurve::new(vec![arc], vec![0.0, 1.0]).unwrap()
    }

    /// The ellipse's true offset at θ: (2 cos θ, sin θ) + d (cos θ, 2 sin θ)/|·|, the
    /// right-hand normal of the quarter's direction of travel (θ from 0 to π/2).
    fn true_offset(theta: f64, d: f64) -> DVec3 {
        let (s, c) = theta.sin_cos();
        let n = DVec3::new(c, 2.0 * s, 0.0).normalize();
        DVec3::new(2.0 * c, s, 0.0) + d * n
    }

    /// The distance of p from a curve by a dense scan and Brent's method around the best.
    fn distance_to(p: DVec3, f: impl Fn(f64) -> DVec3, (lo, hi): (f64, f64)) -> f64 {
        let n = 400;
        let at = |i: usize| lerp(lo, hi, i as f64 / n as f64);
        let best = (0..=n)
            .min_by(|&i, &j| (f(at(i)) - p).length().total_cmp(&(f(at(j)) - p).length()))
            .unwrap();
        let (a, b) = (at(best.saturating_sub(1)), at((best + 1).min(n)));
        minimize_bracketed(|t| (f(t) - p).length(), a, b, 1e-14).value
    }

    /// The largest distance both ways between the computed offset and the true offset.
    fn two_sided_error(result: &ArcOffset, d: f64) -> f64 {
        let (lo, hi) = result.offset.domain();
        let mut worst: f64 = 0.0;
        for i in 0..=1000 {
            let t = lerp(lo, hi, i as f64 / 1000.0);
            let q = result.offset.eval(t);
            worst = worst.max(distance_to(q, |th| true_offset(th, d), (0.0, FRAC_PI_2)));
            let th = FRAC_PI_2 * i as f64 / 1000.0;
            let p = true_offset(th, d);
            worst = worst.max(distance_to(p, |t| result.offset.eval(t), (lo, hi)));
        }
        worst
    }

    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn an_ellipse_is_offset_exactly_through_arcs_within_the_tolerance() {
        for d in [0.1, -0.3, 0.5] {
            let mut previous = 0;
            for tolerance in [1e-3, 1e-5, 1e-7] {
                let result =
                    offset_profile_by_arcs(&quarter_ellipse(1.0, DVec3::ZERO), d, tolerance)
                        .unwrap();
                let error = two_sided_error(&result, d);
                let arcs = result.arcs.segments().len();
                println!(
                    "d = {d}, tolerance {tolerance:e}: {arcs} arcs, offset {} segments, \
                     measured {:.1e} / {:.1e}, two-sided error {error:.1e}",
                    result.offset.segments().len(),
                    result.profile_deviation,
                    result.offset_deviation
                );
                assert!(
                    error <= tolerance,
                    "d = {d}, tolerance {tolerance}: {error}"
                );
                assert!(
                    result.offset_deviation <= tolerance && result.profile_deviation <= tolerance
                );
                assert!(arcs > previous);
                previous = arcs;
                // Every arc and every offset piece is circular, and the chain is G¹.
                for seg in result
                    .arcs
                    .segments()
                    .iter()
                    .chain(result.offset.segments())
                {
                    assert!(seg.circular_arc(1e-12).is_some(), "{seg:?}");
                }
                let b = result.offset.breaks();
                for k in 1..b.len() - 1 {
                    let (_, left) = result.offset.segments()[k - 1].eval_d1(1.0);
                    let (_, right) = result.offset.segments()[k].eval_d1(0.0);
                    let angle = left.normalize().dot(right.normalize());
                    assert!(angle > 1.0 - 1e-12, "G¹ at break {k}: {angle}");
                }
            }
        }
    }

    #[test]
    fn arc_offsets_are_invariant_under_scaling_and_translation() {
        let reference =
            offset_profile_by_arcs(&quarter_ellipse(1.0, DVec3::ZERO), 0.1, 1e-5).unwrap();
        for (scale, shift) in [
            (1e-200, DVec3::ZERO),
            (1e200, DVec3::ZERO),
            (1.0, DVec3::splat(1e4)),
        ] {
            let profile = quarter_ellipse(scale, shift);
            let result = offset_profile_by_arcs(&profile, 0.1 * scale, 1e-5 * scale).unwrap();
            assert_eq!(
                result.arcs.segments().len(),
                reference.arcs.segments().len(),
                "{scale:e}"
            );
            for i in 0..=20 {
                let t = i as f64 / 20.0;
                let expected = reference.offset.eval(t) * scale + DVec3::new(shift.x, shift.y, 0.0);
                let got = result.offset.eval(t);
                assert!(
                    crate::math::robust_length(got - expected)
                        <= 1e-9 * scale.max(shift.length() * 1e-3),
                    "{scale:e}: {got} vs {expected}"
                );
            }
        }
    }

    #[test]
    fn an_offset_beyond_the_range_of_a_double_is_refused() {
        // A profile of 1e300 at x = 1.5e308 offset by 1e308: fitted at unit size about
        // its first pole, it overflows only on the way back.
        let profile = quarter_ellipse(1e300, DVec3::new(1.5e308, 0.0, 0.0));
        let e = offset_profile_by_arcs(&profile, 1e308, 1e300).unwrap_err();
        assert!(e.to_string().contains("distance"), "{e}");
        assert!(e.to_string().contains("beyond the range"), "{e}");
    }

    #[test]
    fn bad_arguments_are_refused() {
        let profile = quarter_ellipse(1.0, DVec3::ZERO);
        for (d, t, name) in [
            (f64::NAN, 1e-3, "distance"),
            (0.1, 0.0, "tolerance"),
            (0.1, f64::NAN, "tolerance"),
        ] {
            let e = offset_profile_by_arcs(&profile, d, t).unwrap_err();
            assert!(e.to_string().contains(name), "{e}");
        }
        // A cusp: ċ = 0 at the end.
        let cusp = RationalBezierCurve::polynomial(&[
            DVec3::ZERO,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
        ])
        .unwrap();
        let cusp = PiecewiseCurve::new(vec![cusp], vec![0.0, 1.0]).unwrap();
        let e = offset_profile_by_arcs(&cusp, 0.1, 1e-3).unwrap_err();
        assert!(e.to_string().contains("singular"), "{e}");
    }
}
