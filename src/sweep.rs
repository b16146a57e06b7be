//! Sweep surfaces with exact rational frames: s(u, v) = x(v) + c₂(u) f₂(v) + c₃(u) f₃(v),
//! equation (1) of Mäurer & Jüttler, with u along the profile and v along the spine.
//!
//! With a rational spine x = X/w (degree n), rational frames f₂ = N₂/d, f₃ = N₃/d (degree m,
//! common denominator) and a rational profile (c₂, c₃) = (C₂, C₃)/h (degree p), the surface
//! is the rational tensor-product patch of degree (p, n + m)
//!
//!   S = h ⊗ (X·d, w·d) + C₂ ⊗ (w·N₂, 0) + C₃ ⊗ (w·N₃, 0)      (homogeneous),
//!
//! i.e. equation (42) of the paper for any rational frame: degree (m', 2n' + 5) for a PH
//! cubic spine with the biquadratic W, and likewise for the exact RMFs of the Möbius and
//! RRMF constructions. The weights h(u)·w(v)·d(v) factor, so the patches join into one NURBS
//! whenever frames and spine are continuous.

use crate::bezier::bernstein::{elevate, product};
use crate::bezier::{PiecewiseCurve, PiecewiseSurface, RationalBezierCurve, RationalBezierPatch};
use crate::error::{invalid, Result};
use crate::frames::rational::{RationalFrameSegment, RationalFrames};
use crate::math::binomial;
use crate::model::{on_frame_segments, FramedCurve};
use glam::{DVec3, DVec4};

/// Most control points of one sweep surface (2²², 128 MiB of homogeneous points): far above
/// any CAD surface, and a bound on the work and memory a single call can ask for (a
/// profile and a spine of 2,048 segments each would ask for 134 million control points,
/// minutes of work in 4 GiB).
pub const MAX_SWEEP_POLES: usize = 1 << 22;

/// The sweep of `profile` (its x → f₂, y → f₃; z ignored) along a curve with its frames:
/// one patch per profile segment and frame segment.
pub fn sweep(framed: &FramedCurve, profile: &PiecewiseCurve) -> Result<PiecewiseSurface> {
    sweep_along(framed.curve(), framed.frames(), profile)
}

/// [`sweep`] of a spine and frames made together (a construction's own pair, not checked
/// again).
pub(crate) fn sweep_along(
    spine: &PiecewiseCurve,
    frames: &RationalFrames,
    profile: &PiecewiseCurve,
) -> Result<PiecewiseSurface> {
    sweep_with(spine, frames, profile, None, false)
}

/// How a construction's own sweep takes its profile: scaled by a law σ(v) (`sigma(v0, v1)`
/// gives σ's Bernstein coefficients on each frame segment [v0, v1]), and with its z along
/// the tangent (`tangential`: a profile drawn out of the normal plane).
#[derive(Clone, Copy, Default)]
pub(crate) struct SweepProfile<'a> {
    pub sigma: Option<&'a dyn Fn(f64, f64) -> Vec<f64>>,
    pub tangential: bool,
}

/// [`sweep_along`] with the profile as `how` says: Mäurer & Jüttler (1) with σ c in place
/// of c, and c₁ t added. The frame factors take σ, the spine's is raised to match; the
/// tangent t = f₂ × f₃ = (N₂ × N₃)/d², so that with it every factor takes one more d:
/// S = h ⊗ (X·d², w·d²)↑ + C₁ ⊗ (σ·w·N₂ × N₃, 0) + C₂ ⊗ (σ·w·d·N₂, 0) + C₃ ⊗ (σ·w·d·N₃, 0).
pub(crate) fn sweep_profile(
    spine: &PiecewiseCurve,
    frames: &RationalFrames,
    profile: &PiecewiseCurve,
    how: SweepProfile,
) -> Result<PiecewiseSurface> {
    sweep_with(spine, frames, profile, how.sigma, how.tangential)
}

/// The sweep, its profile scaled by `sigma` where one is given, its z along the tangent
/// where `tangential`.
fn sweep_with(
    spine: &PiecewiseCurve,
    frames: &RationalFrames,
    profile: &PiecewiseCurve,
    sigma: Option<&dyn Fn(f64, f64) -> Vec<f64>>,
    tangential: bool,
) -> Result<PiecewiseSurface> {
    let spine = &*on_frame_segments(spine, frames);
    check_sweep_size(spine, frames, profile)?;
    let forms = tangents(frames, tangential);
    let factors: Vec<SpineFactors> = spine
        .segments()
        .iter()
        .zip(frames.segments())
        .zip(frames.breaks().windows(2))
        .zip(&forms)
        .map(|(((segment, frame), v), form)| {
            let factors = SpineFactors::new(segment, frame, form);
            match sigma {
                Some(sigma) => factors.scaled(&sigma(v[0], v[1])),
                None => factors,
            }
        })
        .collect();
    let mut patches = Vec::with_capacity(profile.segments().len() * factors.len());
    for piece in profile.segments() {
        let profile = ProfileFactors::new(piece, tangential);
        for spine in &factors {
            patches.push(sweep_patch(spine, &profile)?);
        }
    }
    PiecewiseSurface::new(patches, profile.breaks().to_vec(), spine.breaks().to_vec())
}

/// The surface's control points, counted before they are made: at most [`MAX_SWEEP_POLES`].
fn check_sweep_size(
    spine: &PiecewiseCurve,
    frames: &RationalFrames,
    profile: &PiecewiseCurve,
) -> Result<()> {
    let along_profile: usize = profile.segments().iter().map(|c| c.degree() + 1).sum();
    let along_spine: usize = spine
        .segments()
        .iter()
        .zip(frames.segments())
        .map(|(x, f)| x.degree() + f.degree() + 1)
        .sum();
    match along_profile.checked_mul(along_spine) {
        Some(poles) if poles <= MAX_SWEEP_POLES => Ok(()),
        _ => invalid!(
            "the sweep would have {along_profile} × {along_spine} control points ({} profile \
             and {} spine segments), more than {MAX_SWEEP_POLES}",
            profile.segments().len(),
            spine.segments().len()
        ),
    }
}

/// The factors in v of every patch along one spine segment (the module equation): X·d,
/// w·N₂ and w·N₃, homogeneous — with the tangent's w·N₂ × N₃ and one more d in each where
/// the profile has a tangential part. They do not depend on the profile piece.
struct SpineFactors {
    along_spine: Vec<DVec4>,
    along_f2: Vec<DVec4>,
    along_f3: Vec<DVec4>,
    along_t: Option<Vec<DVec4>>,
}

impl SpineFactors {
    fn new(spine: &RationalBezierCurve, frame: &RationalFrameSegment, tangent: &Tangent) -> Self {
        let x = spine.homogeneous();
        let spine_weight: Vec<f64> = x.iter().map(|h| h.w).collect();
        let weighted = |numerator: &[DVec3]| {
            product(&spine_weight, numerator, |w: f64, n: DVec3| {
                (n * w).extend(0.0)
            })
        };
        let d = frame.denominator();
        let constant = |c: &[f64]| c.iter().all(|&v| v == c[0]);
        if constant(&spine_weight) && constant(d) && !matches!(tangent, Tangent::OverD2) {
            // A polynomial spine with polynomial frames: the products with the constant
            // weights are scalings, and the surface keeps the spine's degree.
            let (w, d) = (spine_weight[0], d[0]);
            let scaled = |n: &[DVec3]| n.iter().map(|&n| (n * w).extend(0.0)).collect();
            return Self {
                along_spine: x.iter().map(|&h| h * d).collect(),
                along_f2: scaled(frame.f2_numerator()),
                along_f3: scaled(frame.f3_numerator()),
                along_t: match tangent {
                    Tangent::OverD(t) => Some(scaled(t)),
                    _ => None,
                },
            };
        }
        let along_spine = product(x, d, |h: DVec4, d: f64| h * d);
        let (along_f2, along_f3) = (
            weighted(frame.f2_numerator()),
            weighted(frame.f3_numerator()),
        );
        if let Tangent::None = tangent {
            return Self {
                along_spine,
                along_f2,
                along_f3,
                along_t: None,
            };
        }
        let cross = frame_cross(frame);
        if let Tangent::OverD(tangent) = tangent {
            return Self {
                along_spine,
                along_f2,
                along_f3,
                along_t: Some(weighted(tangent)),
            };
        }
        let times_d = |n: &[DVec4]| product(d, n, |d: f64, n: DVec4| n * d);
        Self {
            along_spine: times_d(&along_spine),
            along_f2: times_d(&along_f2),
            along_f3: times_d(&along_f3),
            along_t: Some(weighted(&cross)),
        }
    }
}

impl SpineFactors {
    /// The factors with the profile scaled by σ (Bernstein coefficients on the segment).
    fn scaled(self, sigma: &[f64]) -> Self {
        let times = |n: &[DVec4]| product(sigma, n, |s: f64, n: DVec4| n * s);
        Self {
            along_spine: elevate(&self.along_spine, sigma.len() - 1),
            along_f2: times(&self.along_f2),
            along_f3: times(&self.along_f3),
            along_t: self.along_t.as_deref().map(times),
        }
    }
}

/// How the tangent enters a segment's factors: not at all (a profile in the normal plane),
/// as d t over the frames' d (its numerator of their degree), or as N₂ × N₃ = d² t over d².
enum Tangent {
    None,
    OverD(Vec<DVec3>),
    OverD2,
}

fn frame_cross(frame: &RationalFrameSegment) -> Vec<DVec3> {
    product(
        frame.f2_numerator(),
        frame.f3_numerator(),
        |a: DVec3, b: DVec3| a.cross(b),
    )
}

/// The tangent's form on every frame segment: N₂ × N₃ = d² t, and d t is a polynomial
/// wherever d holds the spine's speed (the frames of a PH spline, built on its
/// Euler–Rodrigues or Frenet frame over σ = |x'|), so the tangent goes over d as the
/// normals do, without raising the degree — on every segment, or over d² on all (one form
/// for the whole surface, its patches alike).
fn tangents(frames: &RationalFrames, tangential: bool) -> Vec<Tangent> {
    let n = frames.segments().len();
    if !tangential {
        return (0..n).map(|_| Tangent::None).collect();
    }
    let quotients: Option<Vec<Vec<DVec3>>> = frames
        .segments()
        .iter()
        .map(|f| match f.tangent_numerator() {
            Some(t) => Some(t.to_vec()),
            None => exact_quotient(&frame_cross(f), f.denominator()),
        })
        .collect();
    match quotients {
        Some(q) => q.into_iter().map(Tangent::OverD).collect(),
        None => (0..n).map(|_| Tangent::OverD2).collect(),
    }
}

/// How far the product of a quotient and the denominator may be from the numerator,
/// relative to it: rational frames pinned to their exact end values (to ~1e-11) are
/// divisible to about that; the tangent is then within 1e-10 rad of N₂ × N₃'s.
const QUOTIENT_ROUNDING: f64 = 1e-10;

/// The quotient of two Bernstein polynomials on [0, 1] when the division is exact (to
/// rounding): the product's Bernstein coefficients N_k = Σ_{i+j=k} C(m,i)C(r,j)/C(n,k) d_i q_j
/// solved for q from both ends — from t = 0 for its first half, from t = 1 for the rest,
/// where the denominator (a frame's positive weight) does not vanish — and checked by
/// multiplying back.
fn exact_quotient(numerator: &[DVec3], denominator: &[f64]) -> Option<Vec<DVec3>> {
    let (n, m) = (numerator.len() - 1, denominator.len() - 1);
    if n < m || denominator[0] <= 0.0 || denominator[m] <= 0.0 {
        return None;
    }
    let r = n - m;
    let weight = |i: usize, j: usize| binomial(m, i) * binomial(r, j) / binomial(n, i + j);
    let mut q = vec![DVec3::ZERO; r + 1];
    let half = r / 2;
    for k in 0..=half {
        let known = (1..=k.min(m)).fold(DVec3::ZERO, |acc, i| {
            acc + q[k - i] * (denominator[i] * weight(i, k - i))
        });
        q[k] = (numerator[k] - known) / (denominator[0] * weight(0, k));
    }
    for j in (half + 1..=r).rev() {
        // The coefficient k = j + m involves q_j with d_m, and q_{j'} (j' > j) with d_{i < m}.
        let k = j + m;
        let known = (j + 1..=r.min(k)).fold(DVec3::ZERO, |acc, jj| {
            acc + q[jj] * (denominator[k - jj] * weight(k - jj, jj))
        });
        q[j] = (numerator[k] - known) / (denominator[m] * weight(m, j));
    }
    let back = product(denominator, &q, |d: f64, q: DVec3| q * d);
    let size = numerator.iter().map(|c| c.length()).fold(0.0, f64::max);
    let worst = back
        .iter()
        .zip(numerator)
        .map(|(x, y)| x.distance(*y))
        .fold(0.0, f64::max);
    (worst <= QUOTIENT_ROUNDING * size).then_some(q)
}

/// The factors in u of every patch across one profile piece: h, C₂, C₃ (and C₁, its z,
/// where the profile has a tangential part).
struct ProfileFactors {
    h: Vec<f64>,
    c2: Vec<f64>,
    c3: Vec<f64>,
    c1: Vec<f64>,
}

impl ProfileFactors {
    fn new(profile: &RationalBezierCurve, tangential: bool) -> Self {
        let c = profile.homogeneous();
        Self {
            h: c.iter().map(|p| p.w).collect(),
            c2: c.iter().map(|p| p.x).collect(),
            c3: c.iter().map(|p| p.y).collect(),
            c1: if tangential {
                c.iter().map(|p| p.z).collect()
            } else {
                Vec::new()
            },
        }
    }
}

/// One patch: profile piece × spine segment (see the module equation).
fn sweep_patch(spine: &SpineFactors, profile: &ProfileFactors) -> Result<RationalBezierPatch> {
    let mut products = vec![
        (&profile.h[..], &spine.along_spine[..]),
        (&profile.c2[..], &spine.along_f2[..]),
        (&profile.c3[..], &spine.along_f3[..]),
    ];
    if let Some(along_t) = &spine.along_t {
        products.push((&profile.c1[..], &along_t[..]));
    }
    RationalBezierPatch::from_outer_products(&products)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::bernstein::restrict;
    use crate::frames::metrics::{gaussian_curvature, parameter_line_cosine};
    use glam::DVec3;

    fn framed(spine: &PiecewiseCurve, frames: &RationalFrames) -> Result<FramedCurve> {
        FramedCurve::new(spine.clone(), frames.clone())
    }

    /// A quarter circle of radius 2 in the xy-plane with its (rational, rotation-minimizing)
    /// frame f₂ = −radial direction, f₃ = +z.
    fn arc_with_frames() -> (PiecewiseCurve, RationalFrames) {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let weights = [1.0, s, 1.0];
        let arc = RationalBezierCurve::from_weighted(
            &[
                DVec3::new(2.0, 0.0, 0.0),
                DVec3::new(2.0, 2.0, 0.0),
                DVec3::new(0.0, 2.0, 0.0),
            ],
            &weights,
        )
        .unwrap();
        let f2 = vec![-DVec3::X, -DVec3::new(1.0, 1.0, 0.0) * s, -DVec3::Y];
        let f3 = weights.iter().map(|&w| DVec3::Z * w).collect();
        let frame = RationalFrameSegment::new(f2, f3, weights.to_vec()).unwrap();
        (
            PiecewiseCurve::new(vec![arc], vec![0.0, 1.0]).unwrap(),
            RationalFrames::new(vec![frame], vec![0.0, 1.0]).unwrap(),
        )
    }

    fn line_profile() -> PiecewiseCurve {
        let line = RationalBezierCurve::polynomial(&[
            DVec3::new(-0.5, 0.3, 0.0),
            DVec3::new(0.5, -0.2, 0.0),
        ])
        .unwrap();
        PiecewiseCurve::new(vec![line], vec![0.0, 1.0]).unwrap()
    }

    #[test]
    fn sweeping_a_circle_around_a_circle_gives_a_torus_with_orthogonal_parameter_lines() {
        let (spine, frames) = arc_with_frames();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let circle = RationalBezierCurve::from_weighted(
            &[
                DVec3::new(0.5, 0.0, 0.0),
                DVec3::new(0.5, 0.5, 0.0),
                DVec3::new(0.0, 0.5, 0.0),
            ],
            &[1.0, s, 1.0],
        )
        .unwrap();
        let profile = PiecewiseCurve::new(vec![circle], vec![0.0, 1.0]).unwrap();
        let torus = sweep(&framed(&spine, &frames).unwrap(), &profile).unwrap();
        assert_eq!(
            (torus.patches()[0].degree_u(), torus.patches()[0].degree_v()),
            (2, 4)
        );
        for i in 0..=8 {
            for j in 0..=8 {
                let (u, v) = (i as f64 / 8.0, j as f64 / 8.0);
                let jet = torus.eval_jet(u, v);
                let p = jet.point;
                // Distance from the spine circle (radius 2 in the xy-plane) is the tube radius.
                let radial = (p.truncate().length() - 2.0).hypot(p.z);
                assert!((radial - 0.5).abs() < 1e-14, "{radial}");
                assert!(parameter_line_cosine(&jet) < 1e-14);
            }
        }
    }

    /// Sweeps are bounded by their control point count, checked before any is made:
    /// 2,048 profile × 2,048 spine segments would be 134 million, minutes of work in 4 GiB.
    #[test]
    fn sweeps_beyond_the_control_point_bound_are_refused() {
        let (spine, frames) = arc_with_frames();
        let pieces = MAX_SWEEP_POLES / 2 / 3 + 1; // poles per spine segment: 2 × (2 + 1)
        let line = line_profile().segments()[0].clone();
        let long = PiecewiseCurve::with_unit_intervals(vec![line; pieces]).unwrap();
        let e = sweep(&framed(&spine, &frames).unwrap(), &long).unwrap_err();
        assert!(e.message().contains("control points"), "{e}");
        assert!(sweep(&framed(&spine, &frames).unwrap(), &line_profile()).is_ok());
    }

    #[test]
    fn sweeping_a_line_gives_a_developable_surface() {
        let (spine, frames) = arc_with_frames();
        let strip = sweep(&framed(&spine, &frames).unwrap(), &line_profile()).unwrap();
        for i in 0..=6 {
            let jet = strip.eval_jet(i as f64 / 6.0, 0.37);
            assert!(gaussian_curvature(&jet).abs() < 1e-13);
            assert!(parameter_line_cosine(&jet) < 1e-14);
        }
    }

    #[test]
    fn frames_may_refine_the_spine() {
        let (spine, frames) = arc_with_frames();
        let seg = &frames.segments()[0];
        let halves: Vec<RationalFrameSegment> = [(0.0, 0.5), (0.5, 1.0)]
            .iter()
            .map(|&(a, b)| {
                RationalFrameSegment::new(
                    restrict(seg.f2_numerator(), a, b),
                    restrict(seg.f3_numerator(), a, b),
                    restrict(seg.denominator(), a, b),
                )
                .unwrap()
            })
            .collect();
        let finer = RationalFrames::new(halves, vec![0.0, 0.5, 1.0]).unwrap();
        let coarse = sweep(&framed(&spine, &frames).unwrap(), &line_profile()).unwrap();
        let fine = sweep(&framed(&spine, &finer).unwrap(), &line_profile()).unwrap();
        assert_eq!(fine.v_breaks(), &[0.0, 0.5, 1.0]);
        for i in 0..=10 {
            let (u, v) = (0.3, i as f64 / 10.0);
            assert!((fine.eval(u, v) - coarse.eval(u, v)).length() < 1e-14);
        }
    }

    #[test]
    fn rejects_frames_of_another_curve() {
        let (spine, frames) = arc_with_frames();
        let other = PiecewiseCurve::new(spine.segments().to_vec(), vec![0.0, 2.0]).unwrap();
        assert!(framed(&other, &frames).is_err());
        let line = RationalBezierCurve::polynomial(&[DVec3::ZERO, DVec3::X]).unwrap();
        let straight = PiecewiseCurve::new(vec![line], vec![0.0, 1.0]).unwrap();
        let e = framed(&straight, &frames).unwrap_err();
        assert!(e.message().contains("tangent"));
    }
}
