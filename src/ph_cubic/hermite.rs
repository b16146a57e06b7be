//! G1 Hermite interpolation with PH cubics: Table 1 of Mäurer & Jüttler, in a form that
//! stays well conditioned for nearly parallel and for opposite end tangents.
//!
//! Table 1 puts the inner control points at b₁ = b₀ + L₁t₀, b₂ = b₃ − L₃t₁. Equal angles
//! θ₁₂ = θ₂₃ force L₁ − L₃ = δ (below), and the dihedral condition of (17) becomes the
//! quadratic (*) of Table 1. Its unknown X is an affine function of s = L₁ + L₃
//! (s = λ₁ − λ₂ − 2X with the λᵢ of step 2), so we solve (*) for s directly: with
//! k = (t₀ + t₁)/2, q = (t₁ − t₀)/2, the chord D = p₁ − p₀ and f = q/|q|,
//!
//! ```text
//!   (4|k|² − 1) s² − 8 (k·D) s + 4|D − (D·f) f|² + ((D·q)² + (D·(t₀ × t₁))²) / |q|⁴ = 0,
//!   δ = L₁ − L₃ = −(D·q) / |q|².
//! ```
//!
//! This avoids the points n₁, n₂ of steps 1–3 (undefined for opposite tangents, and
//! cancelling for nearly parallel ones, which is the normal case of a fine spline), and uses
//! the signed leg lengths where the paper writes |λ₁|, |λ₂| (they agree when λ₁ ≥ 0 ≥ λ₂).
//! A root is kept only if L₁ > 0 and L₃ > 0: otherwise the cubic runs against a given
//! tangent. Of two valid roots the one with the shorter control polygon matches the shape
//! of the data (Theorem 10 (i)); the other is returned as well.

use super::cubic::PhCubic;
use crate::error::no_solution;
use crate::error::{Error, Result};
use crate::hermite::HermiteSegment;
use crate::math::quadratic_roots;
use glam::DVec3;

/// Relative size below which cross products of the data count as zero: tangents parallel,
/// chord along the tangents.
const COLLINEAR: f64 = 1e-12;

/// Relative size of a negative discriminant still taken for a double root (round-off at
/// the boundary between two and no solutions).
const DOUBLE_ROOT: f64 = 1e-13;

/// Smallest min σ / max σ of an interpolant: below it the curve has a numerical cusp, where
/// its tangent (ε/ratio) and any frame on it are decided by rounding; such roots are not
/// returned (they sit at the boundary to reversed tangents).
const SINGULAR_SPEED: f64 = 1e-8;

/// The PH cubics through one segment's G1 Hermite data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhHermiteSolutions {
    /// The interpolant with the shorter control polygon: the one that matches the shape of
    /// the data (for straight data, the uniformly parameterized segment).
    pub shape_matching: PhCubic,
    /// The other root of (*) when it also meets the tangents with the right orientation.
    pub other: Option<PhCubic>,
}

/// Both PH cubics interpolating `data` (Table 1), the shape-matching one first.
///
/// Works for spatial and planar data alike (planar data give planar PH cubics, the
/// Tschirnhausen cubics). Fails with [`ErrorKind::NoSolution`](crate::ErrorKind::NoSolution) when (*) has no real root, when
/// every root reverses an end tangent, or for parallel end tangents with the chord off their
/// line.
pub fn ph_cubic_hermite(data: &HermiteSegment) -> Result<PhHermiteSolutions> {
    // The construction is invariant under scaling: work with a unit chord, so that data of
    // any size (1e-300 … 1e300) neither underflow nor overflow in the squares of (*).
    let scale = data.chord_length();
    let unit_chord = (data.p1 - data.p0) / scale;
    if let Some(line) = straight_interpolant(data, unit_chord)? {
        return Ok(PhHermiteSolutions {
            shape_matching: line,
            other: None,
        });
    }
    let mut cubics = leg_lengths(data, unit_chord)?
        .into_iter()
        .map(|(l1, l3)| interpolant(data, l1 * scale, l3 * scale))
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .flatten()
        .collect::<Vec<_>>();
    cubics.sort_by(|a, b| a.polygon_length().total_cmp(&b.polygon_length()));
    let mut cubics = cubics.into_iter();
    let Some(shape_matching) = cubics.next() else {
        return Err(Error::no_solution(
            "the PH cubics through these data have a (numerical) cusp: their speed falls below \
             1e-8 of its maximum",
        ));
    };
    Ok(PhHermiteSolutions {
        shape_matching,
        other: cubics.next(),
    })
}

/// Collinear data: the straight segment with uniform speed (every cubic on the line with
/// positive end legs is PH; this is the canonical one). Parallel tangents with the chord off
/// their line, or pointing against the chord, admit no PH cubic. `None` for other data.
fn straight_interpolant(data: &HermiteSegment, unit_chord: DVec3) -> Result<Option<PhCubic>> {
    let parallel =
        data.t0.cross(data.t1 - data.t0).length() <= COLLINEAR && data.t0.dot(data.t1) > 0.0;
    if !parallel {
        return Ok(None);
    }
    if unit_chord.cross(data.t0).length() > COLLINEAR {
        return Err(Error::no_solution(
            "the end tangents are parallel but the chord p1 − p0 is not along them: no PH cubic \
             interpolates these data",
        ));
    }
    if unit_chord.dot(data.t0) <= 0.0 {
        return Err(Error::no_solution(
            "the end tangents point against the chord p1 − p0: no PH cubic interpolates these data",
        ));
    }
    let chord = data.p1 - data.p0;
    let b = |i: f64| data.p0 + chord * (i / 3.0);
    Ok(Some(PhCubic::from_trusted_points([
        data.p0,
        b(1.0),
        b(2.0),
        data.p1,
    ])))
}

/// The signed leg lengths (L₁, L₃) of every root of (*) (module notes) with L₁, L₃ > 0, for
/// the data scaled to the unit chord `chord`.
fn leg_lengths(data: &HermiteSegment, chord: DVec3) -> Result<Vec<(f64, f64)>> {
    let (t0, t1) = (data.t0, data.t1);
    let k = 0.5 * (t0 + t1);
    let (q, across) = tangent_difference(t0, t1, chord);
    let q2 = q.length_squared();
    let f = q / q2.sqrt();
    let along_q = chord.dot(q);
    let off_f = chord - chord.dot(f) * f;
    let a = 4.0 * k.length_squared() - 1.0;
    let b = -8.0 * k.dot(chord);
    let c = 4.0 * off_f.length_squared() + (along_q * along_q + across * across) / (q2 * q2);
    let sums = sum_roots(a, b, c);
    if sums.is_empty() {
        return Err(Error::no_solution(
            "the PH condition (*) of Table 1 has no real root for these data: no PH cubic \
             interpolates them (try shorter segments)",
        ));
    }
    let difference = -along_q / q2;
    let valid: Vec<(f64, f64)> = sums
        .iter()
        .map(|&s| (0.5 * (s + difference), 0.5 * (s - difference)))
        .filter(|&(l1, l3)| l1 > 1e-14 && l3 > 1e-14)
        .collect();
    if valid.is_empty() {
        return Err(Error::no_solution(
            "every PH cubic through these data runs against t0 or t1 (reversed end tangent)",
        ));
    }
    Ok(valid)
}

/// q = (t₁ − t₀)/2 and chord·(t₀ × t₁) from the tangents' parts along the unit chord e,
/// cᵢ = tᵢ·e, and across it, uᵢ = tᵢ − cᵢe: q = ((c₁ − c₀)e + u₁ − u₀)/2 with
/// c₁ − c₀ = (|u₀|² − |u₁|²)/(c₀ + c₁), and e·(u₀ × u₁). For nearly parallel tangents (a fine
/// spline) (*) divides these by |q|² and |q|⁴; the literal differences of the unit vectors
/// carry their rounding ε, the sines |uᵢ| carry only ε|uᵢ| (planar data turning by 5e-9 rad
/// had "no real root" of (*), and a cubic whose legs did not turn equally).
fn tangent_difference(t0: DVec3, t1: DVec3, e: DVec3) -> (DVec3, f64) {
    let (c0, c1) = (t0.dot(e), t1.dot(e));
    let (u0, u1) = (t0 - c0 * e, t1 - c1 * e);
    let across = e.dot(u0.cross(u1));
    if c0 + c1 <= 0.5 {
        return (0.5 * (t1 - t0), across);
    }
    let along = (u0.length_squared() - u1.length_squared()) / (c0 + c1);
    (0.5 * (along * e + (u1 - u0)), across)
}

/// Real roots of a s² + b s + c, a double root kept when round-off makes the discriminant
/// slightly negative.
fn sum_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    let roots = quadratic_roots(a, b, c);
    if !roots.is_empty() || a == 0.0 {
        return roots;
    }
    let discriminant = b * b - 4.0 * a * c;
    if discriminant >= -DOUBLE_ROOT * (b * b + (4.0 * a * c).abs()) {
        vec![-b / (2.0 * a)]
    } else {
        Vec::new()
    }
}

/// The cubic b₀, b₀ + L₁t₀, b₃ − L₃t₁, b₃, checked against the PH condition, or `None` when
/// its speed nearly vanishes somewhere (see [`SINGULAR_SPEED`]).
fn interpolant(data: &HermiteSegment, l1: f64, l3: f64) -> Result<Option<PhCubic>> {
    let points = [
        data.p0,
        data.p0 + l1 * data.t0,
        data.p1 - l3 * data.t1,
        data.p1,
    ];
    if points.iter().any(|p| !p.is_finite()) {
        return no_solution!(
            "the interpolant's inner control points overflow (legs {l1:.1e}, {l3:.1e})"
        );
    }
    let cubic = PhCubic::from_trusted_points(points);
    if cubic.speed_ratio() < SINGULAR_SPEED {
        return Ok(None);
    }
    let residual = cubic.hodograph_residual();
    if residual.is_nan() || residual > cubic.ph_tolerance() {
        return no_solution!(
            "the interpolant misses the PH condition (17) by {residual:.1e}: the data are too \
             ill-conditioned for a PH cubic"
        );
    }
    Ok(Some(cubic))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn segment(p0: DVec3, t0: DVec3, p1: DVec3, t1: DVec3) -> HermiteSegment {
        HermiteSegment::new(p0, t0, p1, t1).unwrap()
    }

    /// Table 1 of the paper, step by step (valid for generic data with λ₁ ≥ 0 ≥ λ₂).
    fn table_1(data: &HermiteSegment) -> Vec<[DVec3; 4]> {
        let (b0, b3, t0, t1) = (data.p0, data.p1, data.t0, data.t1);
        let c = t0.dot(t1);
        let m1 = c * t1 - t0;
        let m2 = t1 - c * t0;
        let lambda1 = m1.dot(b3 - b0) / m1.dot(t0);
        let lambda2 = m2.dot(b0 - b3) / m2.dot(t1);
        let n1 = b0 + lambda1 * t0;
        let n2 = b3 + lambda2 * t1;
        let (l1, l2) = (lambda1.abs(), lambda2.abs());
        // (l1 − X)(l2 − X) − 2X²(1 + c) − 2|n1 − n2|²/(1 − c) = 0
        let a = 1.0 - 2.0 * (1.0 + c);
        let b = -(l1 + l2);
        let cc = l1 * l2 - 2.0 * (n1 - n2).length_squared() / (1.0 - c);
        quadratic_roots(a, b, cc)
            .into_iter()
            .map(|x| [b0, n1 - x * t0, n2 + x * t1, b3])
            .collect()
    }

    fn assert_interpolates(c: &PhCubic, data: &HermiteSegment) {
        let b = c.control_points();
        assert_eq!(b[0], data.p0);
        assert_eq!(b[3], data.p1);
        // Control points are rounded in absolute coordinates: legs are exact to ε |b|.
        let [l1, _, l3] = c.leg_lengths();
        let scale = crate::math::largest_coordinate(b).max(1.0);
        assert!(((b[1] - b[0]) - l1 * data.t0).length() < 4.0 * f64::EPSILON * scale);
        assert!(((b[3] - b[2]) - l3 * data.t1).length() < 4.0 * f64::EPSILON * scale);
        assert!(
            c.hodograph_residual() <= c.ph_tolerance(),
            "{}",
            c.hodograph_residual()
        );
        // (17) literally, where it is well conditioned: its angles move by ε|b|/L under the
        // rounding of the points, and ψ is ill-defined for nearly straight polygons.
        let p = c.polygon_condition();
        let angle_tolerance = 1e-13 + 16.0 * f64::EPSILON * scale / l1.min(l3);
        assert!((p.theta12 - p.theta23).abs() < angle_tolerance, "{p:?}");
        // cos ψ = 2L₂²/(L₁L₃) − 1 moves by about ε (L_max/L_min)² with the rounding of the legs.
        let [_, l2, _] = c.leg_lengths();
        let spread = l1.max(l2).max(l3) / l1.min(l2).min(l3);
        if let (Some(cos_psi), true) = (p.cos_psi, c.bend() > 1e-2) {
            let tolerance = 1e-10 + 64.0 * f64::EPSILON * spread * spread;
            assert!((cos_psi - p.cos_psi_ph).abs() < tolerance, "{p:?}");
        }
    }

    #[test]
    fn agrees_with_table_1_on_generic_spatial_data() {
        let data = segment(
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.3, 0.1),
            DVec3::new(2.0, 1.0, 0.4),
            DVec3::new(0.4, 1.0, 0.3),
        );
        let ours = ph_cubic_hermite(&data).unwrap();
        let theirs = table_1(&data);
        assert_eq!(theirs.len(), 2);
        let other = ours.other.expect("two solutions");
        for c in [ours.shape_matching, other] {
            assert_interpolates(&c, &data);
            let b = c.control_points();
            let matched = theirs
                .iter()
                .any(|t| (0..4).all(|i| (t[i] - b[i]).length() < 1e-12));
            assert!(matched, "{b:?} not among Table 1's {theirs:?}");
        }
        assert!(ours.shape_matching.polygon_length() < other.polygon_length());
    }

    #[test]
    fn both_signs_of_torsion_and_planar_data() {
        for z in [0.5, -0.5, 0.0] {
            let data = segment(
                DVec3::ZERO,
                DVec3::new(1.0, 0.0, 0.0),
                DVec3::new(1.0, 1.0, z),
                DVec3::new(0.0, 1.0, 0.0),
            );
            let s = ph_cubic_hermite(&data).unwrap();
            assert_interpolates(&s.shape_matching, &data);
            if z == 0.0 {
                assert!(s.shape_matching.control_points().iter().all(|p| p.z == 0.0));
            }
        }
    }

    #[test]
    fn small_steps_on_a_smooth_curve_give_the_shape_matching_cubic() {
        // Theorem 10 (i): for a short arc of the helix both roots exist; the shape-matching
        // one has legs ≈ h/3, the other ≈ h (expansion (26)).
        let helix = |t: f64| DVec3::new(t.cos(), t.sin(), 0.5 * t);
        let tangent = |t: f64| DVec3::new(-t.sin(), t.cos(), 0.5).normalize();
        let h = 0.01;
        let data = segment(helix(0.0), tangent(0.0), helix(h), tangent(h));
        let s = ph_cubic_hermite(&data).unwrap();
        let chord = data.chord_length();
        let [l1, _, l3] = s.shape_matching.leg_lengths();
        assert!((l1 / chord - 1.0 / 3.0).abs() < 1e-3 && (l3 / chord - 1.0 / 3.0).abs() < 1e-3);
        let [m1, _, m3] = s.other.unwrap().leg_lengths();
        assert!((m1 / chord - 1.0).abs() < 1e-2 && (m3 / chord - 1.0).abs() < 1e-2);
        assert_interpolates(&s.shape_matching, &data);
    }

    #[test]
    fn opposite_tangents_give_a_planar_u_turn() {
        let data = segment(DVec3::ZERO, DVec3::X, DVec3::new(0.5, 2.0, 0.0), -DVec3::X);
        let s = ph_cubic_hermite(&data).unwrap();
        assert_interpolates(&s.shape_matching, &data);
        assert!(s.other.is_none(), "the second root reverses both tangents");
    }

    #[test]
    fn straight_and_degenerate_data() {
        let line = segment(DVec3::ZERO, DVec3::X, DVec3::X * 3.0, DVec3::X);
        let s = ph_cubic_hermite(&line).unwrap();
        assert_eq!(s.shape_matching.control_points()[1], DVec3::X);
        assert_eq!(s.shape_matching.bend(), 0.0);
        let offset = segment(DVec3::ZERO, DVec3::X, DVec3::new(3.0, 1.0, 0.0), DVec3::X);
        let e = ph_cubic_hermite(&offset).unwrap_err();
        assert!(e.is(crate::ErrorKind::NoSolution) && e.message().contains("parallel"));
        let backwards = segment(DVec3::ZERO, DVec3::X, -DVec3::X, DVec3::X);
        assert!(ph_cubic_hermite(&backwards).is_err_and(|e| e.is(crate::ErrorKind::NoSolution)));
        // An S-shape: tangents nearly parallel, chord far off their line.
        let s_shape = segment(
            DVec3::ZERO,
            DVec3::new(1.0, 0.01, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
        );
        let e = ph_cubic_hermite(&s_shape).unwrap_err();
        assert!(e.is(crate::ErrorKind::NoSolution), "{e}");
    }

    #[test]
    fn random_and_nearly_degenerate_data_give_ph_cubics_or_clean_errors() {
        use crate::frames::metrics::orthonormality_error;
        use crate::ph_cubic::rational_rmf::{ph_rational_rmf, RmfOptions};
        use crate::testing::{near_degenerate_data, random_data};
        let (mut solved, mut refused, mut worst_dip) = (0, 0, 1.0f64);
        for data in random_data(2000).iter().chain(&near_degenerate_data(500)) {
            match ph_cubic_hermite(data) {
                Ok(s) => {
                    for c in [Some(s.shape_matching), s.other].into_iter().flatten() {
                        assert_interpolates(&c, data);
                        let spline =
                            crate::ph_cubic::spline::PhSpline::from_cubics(vec![c]).unwrap();
                        let normal = crate::math::orthonormal_to(data.t0);
                        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(normal)).unwrap();
                        // Frames are unit to rounding of the quaternion preimage relative
                        // to the largest speed: about ε/r where the speed dips to
                        // r = min σ / max σ (a nearly cuspidal interpolant). (Taken literally,
                        // (19) divided the PH residual and the rounding of the legs by sin θ.)
                        let speeds: Vec<f64> = (0..=100)
                            .map(|i| c.derivative(i as f64 / 100.0).length())
                            .collect();
                        let r = speeds.iter().fold(f64::INFINITY, |m, &x| m.min(x))
                            / speeds.iter().fold(0.0f64, |m, &x| m.max(x));
                        let bound = 1e-14 / r;
                        for v in [0.0, 0.3, 0.7, 1.0] {
                            let e = orthonormality_error(&rmf.framed.frames().frame(v));
                            assert!(e < bound, "{e:e} > {bound:e}");
                        }
                        worst_dip = worst_dip.min(r);
                        solved += 1;
                    }
                }
                Err(e) if e.is(crate::ErrorKind::NoSolution) => {
                    assert!(!e.message().is_empty());
                    refused += 1;
                }
                Err(e) => panic!("{e}"),
            }
        }
        println!(
            "2,500 random data sets: {solved} PH cubics with rational RMFs, {refused} refused; \
             smallest speed ratio min σ / max σ {worst_dip:.1e}"
        );
        assert!(solved > 1000 && worst_dip >= SINGULAR_SPEED);
    }

    #[test]
    fn nearly_parallel_tangents_stay_accurate() {
        let helix = |t: f64| DVec3::new(t.cos(), t.sin(), 0.5 * t);
        let tangent = |t: f64| DVec3::new(-t.sin(), t.cos(), 0.5).normalize();
        let h = 1e-5;
        let data = segment(helix(1.0), tangent(1.0), helix(1.0 + h), tangent(1.0 + h));
        let s = ph_cubic_hermite(&data).unwrap();
        assert_interpolates(&s.shape_matching, &data);
        let mid = s.shape_matching.eval(0.5);
        // Distance to the helix: the part of mid − helix(t) normal to the helix at the nearest
        // t (insensitive to the error in t, unlike |mid − helix(t)|).
        let t = crate::math::minimize_bracketed(|t| (helix(t) - mid).length(), 1.0, 1.0 + h, 0.0).x;
        let offset = mid - helix(t);
        let normal_part = offset - offset.dot(tangent(t)) * tangent(t);
        assert!(normal_part.length() < 1e-15, "{normal_part}");
    }

    /// Issue finding (Möbius splines of densely sampled curves): planar C-shaped data turning
    /// by 5e-9 rad had "no real root" of (*): t₀ × t₁ of the unit tangents rounds to ε and (*)
    /// divides it by |q|² ≈ 6e-18.
    #[test]
    fn nearly_straight_planar_data_have_their_cubic() {
        // In the xy-plane and in general position (where the unit tangents' rounding, not
        // the cross product, decides below ~1e-8 rad: data turning less are noise).
        let tilt = glam::DQuat::from_axis_angle(DVec3::new(0.3, -0.5, 0.8).normalize(), 0.7);
        for (tilt, (a0, a1)) in [
            (glam::DQuat::IDENTITY, (-2.05e-9, 2.62e-9)),
            (glam::DQuat::IDENTITY, (1e-12, -1.2e-12)),
            (tilt, (-3e-6, 2.5e-6)),
            (tilt, (-4e-5, 4.3e-5)),
        ] {
            let direction = |a: f64| tilt * DVec3::new(a.cos(), a.sin(), 0.0);
            let data = segment(
                tilt * DVec3::new(0.3, -0.2, 0.0),
                direction(a0),
                tilt * DVec3::new(1.3, -0.2, 0.0),
                direction(a1),
            );
            let s = ph_cubic_hermite(&data).unwrap_or_else(|e| panic!("{a0:e} {a1:e}: {e}"));
            let c = s.shape_matching;
            let b = c.control_points();
            assert_eq!((b[0], b[3]), (data.p0, data.p1));
            assert!((b[1] - b[0]).normalize().cross(data.t0).length() < 1e-15);
            assert!((b[3] - b[2]).normalize().cross(data.t1).length() < 1e-15);
            assert!(c.hodograph_residual() <= c.ph_tolerance());
            // No cusp (legs in the ratio the asymmetry asks), and the legs turn equally up to the tangents' rounding: their
            // directions are known to ε, so the turns θ₁₂, θ₂₃ to about ε / θ.
            assert!(c.speed_ratio() > 0.5, "{}", c.speed_ratio());
            let p = c.polygon_condition();
            let turn = (a1 - a0).abs();
            assert!(
                (p.theta12 - p.theta23).abs() < 1e-3 * turn,
                "{a0:e} {a1:e}: {p:?}"
            );
        }
    }
}
