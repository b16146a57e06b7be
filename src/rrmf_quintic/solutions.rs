//! The Algorithm of Section 4 for one value of η: all RRMF quintics interpolating G1
//! Hermite data, each verified by substitution.
//!
//! Steps 1–4 are [`CanonicalHermite`]; steps (a)–(e) are `sextic` (general case) or
//! `special` (α₁ = 0); this module does (f)–(j): f₂ (40) — the x-component of the
//! displacement of the normalized coefficients — must be positive, γ = √(5X / f₂) (39),
//! α_k = γ a_k, β_k = γ b_k (36), and the hodograph (2) is taken back to the original
//! coordinates. Every candidate is then checked against the conditions it must satisfy:
//! the RRMF conditions (7)–(8), the displacement (14)–(15) and the end tangents (16)–(17),
//! and a speed bounded away from zero (a regular curve). A root of the sextic that does not
//! pass (a spurious or inaccurate one, or a numerically singular curve) is dropped.
//!
//! X enters only through γ, and α, β scale with √X: everything computed on the curve (the
//! verification, the shape measures, control points and frames) is computed for a unit
//! chord and scaled (points by X, L by X, E and E_rmf by 1/X), so that chords from 1e-300
//! to 1e300 work alike — products like (7) would otherwise underflow or overflow.

use super::canonical::{CanonicalHermite, Placement};
use super::hopf::{HopfQuadratics, RmfNumerators};
use super::measures::{arc_length, shape_measures, speed_range, ShapeMeasures};
use super::sextic::{self, Candidate};
use super::special;
use crate::bezier::RationalBezierCurve;
use crate::error::{invalid, Result};
use crate::hermite::HermiteSegment;
use crate::math::angle_between;
use crate::math::Complex;
use glam::DVec3;

/// Smallest ratio of the least to the greatest speed σ on [0, 1]. The unit tangent of the
/// curve evaluated from its Bézier data carries an error of about ε σ_max / σ(t): a curve
/// whose speed dips below 1e-6 of its maximum (a near-cusp, or a nearly vanishing end
/// derivative, ρ outside [1e-3, 1e3]) has a tangent known to 1e-10 rad at best there, and
/// as the dip deepens, no tangent at all — frames and sweeps built on it disagree with it.
/// Such roots occur for nearly degenerate data (a tangent almost along the chord); for data
/// in general position none of 4,362 test solutions came near.
pub(crate) const REGULARITY: f64 = 1e-6;
/// Largest relative residual of (7) and (8) a solution may have.
pub(crate) const RRMF_TOLERANCE: f64 = 1e-10;
/// Largest end-point error of a solution, relative to its size max(|p_f − p_i|, L), and
/// end-tangent error in radians. The end point is a sum of hodograph coefficients of the
/// size of the arc length L, so on a curve with wild loops (L ≫ |p_f − p_i|) round-off
/// alone is about 1e-16 L.
pub(crate) const INTERPOLATION_TOLERANCE: f64 = 1e-12;

/// One RRMF quintic interpolating the Hermite data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RrmfQuintic {
    /// The angular parameter η it belongs to.
    pub eta: f64,
    /// ρ = √(|r'(1)| / |r'(0)|) (20).
    pub rho: f64,
    /// α_k, β_k in canonical coordinates (α₀ real and positive).
    pub hopf: HopfQuadratics,
    /// w₀ = 1, w₁, w₂ of the RRMF condition (4).
    pub w: [Complex; 3],
    /// Its arc length and energies.
    pub measures: ShapeMeasures,
    /// From canonical to original coordinates.
    pub placement: Placement,
    /// Whether this is the planar PH quintic of planar data (`planar`): then α, β are real,
    /// the curve lies in the canonical (x, y)-plane, `eta` is 0 and `w` is 1, and the RMF is
    /// the Euler–Rodrigues frame itself — the in-plane normal and the plane's normal.
    pub planar: bool,
    /// The same quintic for the chord (1, 0, 0): α/√X, β/√X.
    pub(super) unit_chord: HopfQuadratics,
    /// X = |p_f − p_i|.
    pub(super) chord: f64,
}

impl RrmfQuintic {
    /// The quintic in original coordinates, as a polynomial Bézier curve on [0, 1].
    pub fn bezier(&self) -> Result<RationalBezierCurve> {
        let points: Vec<DVec3> = self
            .unit_chord
            .control_points(DVec3::ZERO)
            .iter()
            .map(|&p| self.placement.point(p * self.chord))
            .collect();
        RationalBezierCurve::polynomial(&points)
    }

    /// The rational RMF (9) on [s0, s1] (reparameterized to [0, 1]) in original coordinates;
    /// at t = 0 its f₂ is e₂ of the ERF (5).
    pub fn rmf_on(&self, s0: f64, s1: f64) -> RmfNumerators {
        // The frame does not depend on the scale of α, β. A planar curve's ERF is its RMF
        // (the plane's normal e₃ is constant), so w = 1 there.
        let canonical = if self.planar {
            self.unit_chord
                .restricted(s0, s1)
                .rotated_erf(&[Complex::ONE; 3])
        } else {
            self.unit_chord.rmf_numerators_on(s0, s1)
        };
        let rotate = |v: &[DVec3]| v.iter().map(|&x| self.placement.vector(x)).collect();
        RmfNumerators {
            f2: rotate(&canonical.f2),
            f3: rotate(&canonical.f3),
            denominator: canonical.denominator,
        }
    }
}

/// All RRMF quintics interpolating `data` for the angular parameter `eta`, in increasing
/// ρ. Empty when this η admits none (no positive root of (35), or f₂ ≤ 0 for every root).
pub fn rrmf_quintics(data: &HermiteSegment, eta: f64) -> Result<Vec<RrmfQuintic>> {
    rrmf_quintics_reporting(data, eta).map(|s| s.quintics)
}

/// [`rrmf_quintics`] with the roots it left out for being irregular.
pub fn rrmf_quintics_reporting(data: &HermiteSegment, eta: f64) -> Result<Solutions> {
    if !eta.is_finite() {
        return invalid!("eta = {eta} is not finite");
    }
    Ok(solve_reporting(&CanonicalHermite::new(data)?, eta))
}

/// The RRMF quintics of one η, and the roots that satisfy every condition but regularity.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Solutions {
    /// The solutions, in increasing ρ.
    pub quintics: Vec<RrmfQuintic>,
    /// In increasing ρ, roots whose quintic interpolates the data with an RRMF but whose speed dips below
    /// `REGULARITY` times its maximum (a near-cusp): not returned as solutions, since
    /// their tangent is not known to the accuracy the frames need there.
    pub irregular: Vec<IrregularRoot>,
}

/// A root of (35) left out of the solutions for its speed (`REGULARITY`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IrregularRoot {
    /// Its end-derivative ratio ρ (20).
    pub rho: f64,
    /// Least over greatest speed on [0, 1], below `REGULARITY`.
    pub speed_ratio: f64,
}

/// [`rrmf_quintics`] on data already in canonical form.
#[cfg(test)]
pub(crate) fn solve(c: &CanonicalHermite, eta: f64) -> Vec<RrmfQuintic> {
    solve_reporting(c, eta).quintics
}

/// [`solve`] with the irregular roots.
pub(crate) fn solve_reporting(c: &CanonicalHermite, eta: f64) -> Solutions {
    let candidates = if special::is_special(c, eta) {
        special::candidates(c)
    } else {
        sextic::candidates(c, eta)
    };
    let mut found = Solutions::default();
    for candidate in candidates {
        match complete(c, eta, candidate) {
            Outcome::Solution(q) if !found.quintics.iter().any(|s| same(s, &q)) => {
                found.quintics.push(*q)
            }
            Outcome::Irregular(root) => found.irregular.push(root),
            _ => {}
        }
    }
    found.quintics.sort_by(|a, b| a.rho.total_cmp(&b.rho));
    found.irregular.sort_by(|a, b| a.rho.total_cmp(&b.rho));
    found
}

/// Relative difference of the coefficients of two solutions below which they are one: a
/// root of (35) found both by the exceptional case and as a double root, which a root
/// finder resolves to about √ε only (the first found, the exceptional one, is kept).
const SAME_SOLUTION: f64 = 1e-6;

/// Whether two solutions are one, to [`SAME_SOLUTION`].
fn same(a: &RrmfQuintic, b: &RrmfQuintic) -> bool {
    let coefficients = |q: &RrmfQuintic| {
        let h = &q.unit_chord;
        [h.alpha, h.beta].concat()
    };
    let (x, y) = (coefficients(a), coefficients(b));
    let size = x.iter().chain(&y).map(|z| z.abs()).fold(0.0, f64::max);
    x.iter()
        .zip(&y)
        .all(|(&p, &q)| (p - q).abs() <= SAME_SOLUTION * size)
}

/// What a candidate turns out to be.
enum Outcome {
    Solution(Box<RrmfQuintic>),
    Irregular(IrregularRoot),
    NotASolution,
}

/// Steps (f)–(h) and the verification: the solution of a candidate, if it is one.
fn complete(c: &CanonicalHermite, eta: f64, candidate: Candidate) -> Outcome {
    // f₂ (40) is the x-displacement of the normalized quintic times 5. (NaN, from a
    // degenerate candidate, is refused too.)
    let f2 = 5.0 * candidate.normalized.displacement().x;
    if f2.is_nan() || f2 <= 0.0 {
        return Outcome::NotASolution;
    }
    // γ of (39) for X = 1.
    let unit_chord = candidate.normalized.scaled((5.0 / f2).sqrt());
    if !satisfies_conditions(c, &unit_chord) {
        return Outcome::NotASolution;
    }
    let speed_ratio = speed_ratio(&unit_chord);
    if !regular(speed_ratio) {
        return Outcome::Irregular(IrregularRoot {
            rho: candidate.rho,
            speed_ratio,
        });
    }
    Outcome::Solution(Box::new(RrmfQuintic {
        eta,
        rho: candidate.rho,
        hopf: unit_chord.scaled(c.x.sqrt()),
        w: unit_chord.w(),
        measures: shape_measures(&unit_chord).scaled(c.x),
        placement: c.placement,
        planar: false,
        unit_chord,
        chord: c.x,
    }))
}

/// Verification by substitution, for the chord (1, 0, 0): (7)–(8), (14)–(15), (16)–(17).
fn satisfies_conditions(c: &CanonicalHermite, unit_chord: &HopfQuadratics) -> bool {
    let (r7, r8) = unit_chord.rrmf_residuals();
    let size = arc_length(unit_chord).max(1.0);
    let end_error = (unit_chord.displacement() - DVec3::X).length() / size;
    let hodograph = unit_chord.hodograph();
    let (ti, tf) = c.tangents();
    let tangent_error = angle_between(hodograph[0], ti).max(angle_between(hodograph[4], tf));
    r7 <= RRMF_TOLERANCE
        && r8 <= RRMF_TOLERANCE
        && end_error <= INTERPOLATION_TOLERANCE
        && tangent_error <= INTERPOLATION_TOLERANCE
}

/// Least over greatest speed σ on [0, 1].
fn speed_ratio(unit_chord: &HopfQuadratics) -> f64 {
    let (slowest, fastest) = speed_range(unit_chord);
    slowest / fastest
}

/// Whether a speed ratio is at least `REGULARITY` (NaN is not).
fn regular(speed_ratio: f64) -> bool {
    speed_ratio >= REGULARITY
}

/// Whether the speed stays above `REGULARITY` times its maximum on [0, 1].
pub(super) fn is_regular(unit_chord: &HopfQuadratics) -> bool {
    regular(speed_ratio(unit_chord))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{check_solution, example_1, near_degenerate_data, random_data};

    /// `value` rounds to `printed`, given with `decimals` decimals.
    fn agrees(value: f64, printed: f64, decimals: i32) -> bool {
        (value - printed).abs() <= 0.5 * 10f64.powi(-decimals)
    }

    fn assert_coefficients(z: &[Complex; 3], printed: [(f64, f64); 3], what: &str) {
        for (k, (&z, (re, im))) in z.iter().zip(printed).enumerate() {
            assert!(
                agrees(z.re, re, 4) && agrees(z.im, im, 4),
                "{what}_{k} = {z:?}, the paper prints {re} + {im}i"
            );
        }
    }

    /// What the paper prints for one curve of Example 1: η, ρ, α_k, β_k, w_k (4 decimals),
    /// and L, E, E_rmf with their numbers of decimals.
    struct Printed {
        eta: f64,
        rho: f64,
        alpha: [(f64, f64); 3],
        beta: [(f64, f64); 3],
        w: [(f64, f64); 3],
        measures: [(f64, i32); 3],
    }

    fn reproduces(p: Printed) {
        let all = rrmf_quintics(&example_1(), p.eta).unwrap();
        let rhos: Vec<f64> = all.iter().map(|s| s.rho).collect();
        println!("Example 1, η = {}: ρ = {rhos:?}", p.eta);
        let s = all.into_iter().find(|s| agrees(s.rho, p.rho, 4));
        let s = s.unwrap_or_else(|| panic!("no solution with ρ = {} at η = {}", p.rho, p.eta));
        println!("{s:#?}");
        assert_coefficients(&s.hopf.alpha, p.alpha, "α");
        assert_coefficients(&s.hopf.beta, p.beta, "β");
        assert_coefficients(&s.w, p.w, "w");
        let m = s.measures;
        let computed = [m.arc_length, m.energy_frenet, m.energy_rmf];
        for ((value, (printed, decimals)), name) in
            computed.iter().zip(p.measures).zip(["L", "E", "E_rmf"])
        {
            assert!(
                agrees(*value, printed, decimals),
                "{name} = {value}, the paper prints {printed}"
            );
        }
    }

    #[test]
    fn example_1_left_curve_eta_5_2() {
        reproduces(Printed {
            eta: 5.2,
            rho: 1.9158,
            alpha: [(1.4194, 0.0), (-0.7920, 0.4058), (-0.9158, 2.5605)],
            beta: [(0.4512, 0.0), (1.1392, 0.7361), (-0.5593, -0.6590)],
            w: [(1.0, 0.0), (-0.2751, 0.4094), (1.1863, 1.5044)],
            measures: [(2.3259, 4), (44.509, 3), (22.856, 3)],
        });
    }

    #[test]
    fn example_1_right_curve_eta_4_325() {
        reproduces(Printed {
            eta: 4.325,
            rho: 0.9652,
            alpha: [(1.5363, 0.0), (1.1372, 0.4334), (0.7595, 1.2735)],
            beta: [(0.4883, 0.0), (-0.0461, -0.2865), (-0.4712, 0.0067)],
            w: [(1.0, 0.0), (0.6637, 0.2024), (0.6024, 0.7542)],
            measures: [(1.9070, 4), (5.7495, 4), (1.4641, 4)],
        });
    }

    /// Nearly degenerate data have roots whose quintic interpolates with an RRMF but dips
    /// below `REGULARITY` in speed: they are reported, not returned, and data in general
    /// position have none.
    #[test]
    fn near_cusps_are_reported_not_returned() {
        let count = |data: &[HermiteSegment]| {
            let (mut irregular, mut solutions) = (0, 0);
            for d in data {
                for k in 0..36 {
                    let found = rrmf_quintics_reporting(d, 0.1745 * k as f64).unwrap();
                    for root in &found.irregular {
                        assert!(root.rho > 0.0 && root.speed_ratio < REGULARITY, "{root:?}");
                        assert!(found.quintics.iter().all(|q| q.rho != root.rho));
                    }
                    irregular += found.irregular.len();
                    solutions += found.quintics.len();
                }
            }
            (irregular, solutions)
        };
        let (near, near_solutions) = count(&near_degenerate_data(60));
        let (general, general_solutions) = count(&random_data(60));
        println!("near-degenerate: {near} irregular roots, {near_solutions} solutions; general: {general}, {general_solutions}");
        assert!(near > 0, "no near-cusp reported");
        assert_eq!(general, 0, "near-cusps of data in general position");
    }

    #[test]
    fn every_solution_interpolates_and_is_rrmf() {
        let (mut count, mut worst) = (0, [0.0f64; 5]);
        let data = random_data(200);
        for d in &data {
            for k in 0..48 {
                for s in rrmf_quintics(d, TAU_F * k as f64 / 48.0).unwrap() {
                    let (r, e, t, legs) = check_solution(d, &s);
                    let chord_relative =
                        (s.bezier().unwrap().eval(1.0) - d.p1).length() / d.chord_length();
                    worst[0] = worst[0].max(r);
                    worst[1] = worst[1].max(e);
                    worst[2] = worst[2].max(t);
                    if s.measures.arc_length <= 10.0 * d.chord_length() {
                        worst[3] = worst[3].max(chord_relative);
                    }
                    if (0.1..=10.0).contains(&s.rho) {
                        worst[4] = worst[4].max(legs);
                    }
                    count += 1;
                }
            }
        }
        println!(
            "{count} solutions of {} data sets × 48 η: max RRMF residual {:.1e}, end point {:.1e} \
             (relative to max(chord, L); {:.1e} relative to the chord where L ≤ 10 chords), \
             end tangents {:.1e} rad (control legs {:.1e} rad where 0.1 ≤ ρ ≤ 10)",
            data.len(),
            worst[0],
            worst[1],
            worst[3],
            worst[2],
            worst[4]
        );
        assert!(
            count > 4000,
            "only {count} solutions: the test would prove little"
        );
    }

    const TAU_F: f64 = std::f64::consts::TAU;

    /// Data with θ_f = θ_i: at η = ½φ the special case α₁ = 0 applies, and the general
    /// solutions at nearby η tend to its solutions.
    #[test]
    fn special_case_alpha1_zero_is_solved_and_continuous() {
        let (theta, phi) = (0.3f64, 1.5f64);
        let data = HermiteSegment::new(
            DVec3::ZERO,
            DVec3::new(theta.cos(), theta.sin(), 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(
                theta.cos(),
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
            ),
        )
        .unwrap();
        let special = rrmf_quintics(&data, 0.5 * phi).unwrap();
        assert_eq!(special.len(), 2);
        for s in &special {
            check_solution(&data, s);
            assert_eq!(s.hopf.alpha[1], Complex::ZERO);
            // |β₁|² = ρ γ² |sin ½φ| and λ = ½π: α₂ ∝ e^{i(π + φ)/2}.
            let gamma2 = s.hopf.alpha[0].norm_sqr() + s.hopf.beta[0].norm_sqr();
            let b1 = s.hopf.beta[1].norm_sqr();
            assert!((b1 - s.rho * gamma2 * (0.5 * phi).sin()).abs() < 1e-12 * b1);
            let phase = s.hopf.alpha[2].arg() - 0.5 * (std::f64::consts::PI + phi);
            assert!(phase.sin().abs() < 1e-12 && phase.cos() > 0.0);
        }
        for offset in [1e-3, -1e-6, 1e-9] {
            let near = rrmf_quintics(&data, 0.5 * phi + offset).unwrap();
            assert_eq!(near.len(), 2);
            for (a, b) in near.iter().zip(&special) {
                check_solution(&data, a);
                assert!(
                    (a.rho - b.rho).abs() < 20.0 * offset.abs() * b.rho,
                    "{offset}"
                );
                assert!(a.hopf.alpha[1].abs() < 20.0 * offset.abs() * b.hopf.beta[1].abs());
            }
        }
    }

    #[test]
    fn refuses_a_non_finite_eta_and_planar_data() {
        assert!(rrmf_quintics(&example_1(), f64::NAN)
            .unwrap_err()
            .message()
            .contains("eta"));
        let planar =
            HermiteSegment::new(DVec3::ZERO, DVec3::Y, DVec3::X, DVec3::new(1.0, -1.0, 0.0))
                .unwrap();
        assert!(rrmf_quintics(&planar, 1.0).is_err());
    }

    /// Chords from 1e-300 to 1e300 give the same solutions, scaled: α, β by √X, L by X,
    /// E and E_rmf by 1/X, and the curve by X.
    #[test]
    fn any_representable_scale_works() {
        let unit = rrmf_quintics(&example_1(), 4.325).unwrap();
        for scale in [1e-300, 1e-150, 1e-20, 1e20, 1e150, 1e300] {
            let d = example_1();
            let scaled = HermiteSegment::new(d.p0, d.t0, d.p1 * scale, d.t1).unwrap();
            let found = rrmf_quintics(&scaled, 4.325).unwrap();
            assert_eq!(found.len(), unit.len(), "scale {scale:e}");
            for (q, u) in found.iter().zip(&unit) {
                let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
                assert!(
                    close(q.rho, u.rho),
                    "scale {scale:e}: ρ {} vs {}",
                    q.rho,
                    u.rho
                );
                assert!(close(q.hopf.alpha[2].re / scale.sqrt(), u.hopf.alpha[2].re));
                assert!(close(q.measures.arc_length / scale, u.measures.arc_length));
                assert!(close(q.measures.energy_rmf * scale, u.measures.energy_rmf));
                assert!(close(
                    q.measures.energy_frenet * scale,
                    u.measures.energy_frenet
                ));
                let end = q.bezier().unwrap().eval(1.0);
                assert!(
                    (end / scale - DVec3::ONE).length() < 1e-12,
                    "scale {scale:e}"
                );
            }
        }
        let huge = HermiteSegment::new(
            DVec3::splat(-1e308),
            DVec3::X,
            DVec3::splat(1e308),
            DVec3::Y,
        );
        // Refused when validated: beyond ±1e300 the chord itself may overflow.
        let e = huge.unwrap_err();
        assert!(e.message().contains("beyond"), "{e}");
    }
}
