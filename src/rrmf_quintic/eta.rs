//! Choosing the free angle η (step 5 of the Algorithm of Section 4, and Section 5).
//!
//! The interpolants form a one-parameter family whose shape depends strongly on η; the
//! paper samples N_η values η = 2πk/N_η and compares the shape integrals. Here the sampled
//! solution of least E_rmf, E or L (the caller's choice) is refined by Brent's method on
//! the bracket of its two neighbouring samples, minimizing over η the least measure of all
//! solutions at η (an η without solutions counts as +∞).
//!
//! The unit of work is one *solve*: the sextic (35) (or the quartic of the special case)
//! for one η, its positive roots, and the verification and measures of each solution. A
//! segment costs N_η solves for the scan plus those of the refinement — at most
//! [`MAX_REFINEMENT_SOLVES`], about 40 in practice — and a [`Budget`] caps the solves of a
//! whole computation, ending it with [`ErrorKind::NotConverged`](crate::ErrorKind) when
//! it is spent.

use super::canonical::CanonicalHermite;
use super::measures::ShapeMeasure;
use super::planar::{is_planar, planar_quintic};
use super::solutions::{solve_reporting, RrmfQuintic};
use crate::error::no_solution;
use crate::error::{invalid, Error, Result};
use crate::hermite::HermiteSegment;
use crate::math::minimize_bracketed;
use std::f64::consts::TAU;

/// Largest N_η accepted (a scan costs one sextic per sample).
pub const MAX_ETA_SAMPLES: usize = 1_000_000;

/// Tolerance in η of the refinement.
const ETA_TOLERANCE: f64 = 1e-9;

/// Most solves of one refinement: Brent's method stops after 500 steps (one solve each),
/// plus its first point and the final solve at the minimum.
pub const MAX_REFINEMENT_SOLVES: usize = 502;

/// A cap on the solves (sextics for one η) of a computation, and how many were spent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    /// Most solves allowed; `usize::MAX` for no cap.
    pub max_solves: usize,
    /// Solves spent so far.
    pub spent: usize,
}

impl Budget {
    /// A budget of `max_solves` solves, none spent.
    pub fn new(max_solves: usize) -> Self {
        Self {
            max_solves,
            spent: 0,
        }
    }

    /// No cap.
    pub fn unlimited() -> Self {
        Self::new(usize::MAX)
    }

    /// Takes one solve from the budget; false (nothing taken) when it is spent.
    fn take(&mut self) -> bool {
        let left = self.spent < self.max_solves;
        if left {
            self.spent += 1;
        }
        left
    }

    /// The error of a spent budget.
    fn spent_error(&self) -> Error {
        Error::not_converged(format!(
            "the work budget of {} solves (sextics for one η) is spent before the best η is found: raise it, or lower eta_samples",
            self.max_solves
        ))
    }
}

/// The chosen interpolant and how many sampled η admit one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BestQuintic {
    /// The interpolant of the best sampled η, refined.
    pub quintic: RrmfQuintic,
    /// Number of the N_η sampled values of η with at least one solution; 0 for the planar
    /// quintic of planar data (no η is sampled).
    pub admissible: usize,
    /// Roots left out over all solves (scan and refinement) for a speed dipping below
    /// `REGULARITY` of its maximum: interpolants with an
    /// RRMF, but near-cusps.
    pub irregular_roots: usize,
}

/// The RRMF quintic interpolant of least `measure`: scan `eta_samples` values of η, then
/// refine the best one. Planar data (`planar`) have no η family (Section 4 does not apply
/// to them, footnote 4); they get the planar PH quintic of least `measure`, which keeps a
/// flat stretch flat, with `admissible` = 0.
pub fn best_quintic(
    data: &HermiteSegment,
    measure: ShapeMeasure,
    eta_samples: usize,
) -> Result<BestQuintic> {
    best_quintic_within(data, measure, eta_samples, &mut Budget::unlimited())
}

/// Checks N_η.
pub(crate) fn check_eta_samples(eta_samples: usize) -> Result<()> {
    if !(1..=MAX_ETA_SAMPLES).contains(&eta_samples) {
        return invalid!("eta_samples = {eta_samples} must be between 1 and {MAX_ETA_SAMPLES}");
    }
    Ok(())
}

/// [`best_quintic`] spending at most what is left of `budget` (and recording what it
/// spends); [`ErrorKind::NotConverged`](crate::ErrorKind) when the budget runs out first.
pub fn best_quintic_within(
    data: &HermiteSegment,
    measure: ShapeMeasure,
    eta_samples: usize,
    budget: &mut Budget,
) -> Result<BestQuintic> {
    check_eta_samples(eta_samples)?;
    if is_planar(data)? {
        return Ok(BestQuintic {
            quintic: planar_quintic(data, measure)?,
            admissible: 0,
            irregular_roots: 0,
        });
    }
    let c = CanonicalHermite::new(data)?;
    let (mut best, mut admissible, mut irregular_roots) = (None::<RrmfQuintic>, 0, 0);
    for k in 0..eta_samples {
        if !budget.take() {
            return Err(budget.spent_error());
        }
        let eta = TAU * k as f64 / eta_samples as f64;
        let found = least_counting(&c, eta, measure, &mut irregular_roots);
        if let Some(q) = found {
            admissible += 1;
            if best.is_none_or(|b| clearly_less(q.measures.get(measure), b.measures.get(measure))) {
                best = Some(q);
            }
        }
    }
    let Some(sampled) = best else {
        return no_solution!(
            "none of the eta_samples = {eta_samples} sampled values of η admits an RRMF quintic interpolant"
        );
    };
    let step = TAU / eta_samples as f64;
    let quintic = refine(&c, sampled, measure, step, budget, &mut irregular_roots)?;
    Ok(BestQuintic {
        quintic,
        admissible,
        irregular_roots,
    })
}

/// The solution of least `measure` for `eta`, adding the irregular roots to `irregular`.
fn least_counting(
    c: &CanonicalHermite,
    eta: f64,
    measure: ShapeMeasure,
    irregular: &mut usize,
) -> Option<RrmfQuintic> {
    let solved = solve_reporting(c, eta);
    *irregular += solved.irregular.len();
    least(&solved.quintics, measure)
}

/// Relative difference of two measures below which they count as equal: symmetric data
/// (a helix) have mirror solutions (ρ and 1/ρ) of one measure, and rounding — a change of
/// scale or a translation of the data — must not swap them.
const SAME_MEASURE: f64 = 1e-9;

/// `a` smaller than `b` by more than rounding.
fn clearly_less(a: f64, b: f64) -> bool {
    a < b - SAME_MEASURE * b.abs()
}

/// The solution of least `measure` among `solutions` (given in increasing ρ); of solutions
/// of the same measure (to [`SAME_MEASURE`]) the one of least ρ.
fn least(solutions: &[RrmfQuintic], measure: ShapeMeasure) -> Option<RrmfQuintic> {
    solutions.iter().copied().fold(None, |best, q| match best {
        Some(b) if !clearly_less(q.measures.get(measure), b.measures.get(measure)) => Some(b),
        _ => Some(q),
    })
}

/// Brent's method on [η − step, η + step] around the sampled best; keeps the sample if the
/// refinement does not improve on it. A budget spent during the refinement is an error
/// (not the sample): the answer must not depend on where the budget ran out.
fn refine(
    c: &CanonicalHermite,
    sampled: RrmfQuintic,
    measure: ShapeMeasure,
    step: f64,
    budget: &mut Budget,
    irregular: &mut usize,
) -> Result<RrmfQuintic> {
    let mut spent = false;
    let mut at = |eta: f64| {
        if !budget.take() {
            spent = true;
            return None;
        }
        least_counting(c, eta.rem_euclid(TAU), measure, irregular)
    };
    let minimum = minimize_bracketed(
        |eta| at(eta).map_or(f64::NAN, |q| q.measures.get(measure)),
        sampled.eta - step,
        sampled.eta + step,
        ETA_TOLERANCE,
    );
    let found = at(minimum.x);
    if spent {
        return Err(budget.spent_error());
    }
    Ok(match found {
        Some(q) if clearly_less(q.measures.get(measure), sampled.measures.get(measure)) => q,
        _ => sampled,
    })
}
#[cfg(test)]
mod tests {
    use super::*;
    use crate::rrmf_quintic::solutions::solve;
    use crate::testing::{check_solution, example_1};
    use glam::DVec3;

    /// Canonical data with tangent angles θ_i, θ_f and azimuth φ, chord 1.
    fn data(theta_i: f64, theta_f: f64, phi: f64) -> HermiteSegment {
        let t0 = DVec3::new(theta_i.cos(), theta_i.sin(), 0.0);
        let (s, c) = theta_f.sin_cos();
        let t1 = DVec3::new(c, s * phi.cos(), s * phi.sin());
        HermiteSegment::new(DVec3::ZERO, t0, DVec3::X, t1).unwrap()
    }

    const ALL: [ShapeMeasure; 5] = [
        ShapeMeasure::EnergyRmf,
        ShapeMeasure::EnergyFrenet,
        ShapeMeasure::ArcLength,
        ShapeMeasure::ScaledEnergyRmf,
        ShapeMeasure::ScaledEnergyFrenet,
    ];

    /// The result beats every sample and is a local minimum in η.
    #[test]
    fn the_best_beats_every_sample_and_is_a_local_minimum() {
        let d = example_1();
        let c = CanonicalHermite::new(&d).unwrap();
        for measure in ALL {
            let best = best_quintic(&d, measure, 90).unwrap();
            let q = best.quintic;
            check_solution(&d, &q);
            let value = q.measures.get(measure);
            let mut admissible = 0;
            for k in 0..90 {
                let sampled = least(&solve(&c, TAU * k as f64 / 90.0), measure);
                if let Some(s) = sampled {
                    admissible += 1;
                    assert!(
                        value <= s.measures.get(measure),
                        "{measure:?}: sample {k} is better"
                    );
                }
            }
            assert_eq!(admissible, best.admissible);
            for offset in [-1e-4, 1e-4] {
                if let Some(s) = least(&solve(&c, q.eta + offset), measure) {
                    assert!(
                        value <= s.measures.get(measure) * (1.0 + 1e-9),
                        "{measure:?}"
                    );
                }
            }
            println!(
                "Example 1, least {measure:?}: η = {:.4}, ρ = {:.4}, L = {:.4}, E = {:.4}, E_rmf = {:.4} \
                 ({} of 90 sampled η admit solutions)",
                q.eta, q.rho, q.measures.arc_length, q.measures.energy_frenet, q.measures.energy_rmf,
                best.admissible
            );
        }
    }

    /// L·E_rmf picks the fair interpolant of Example 1 the paper shows on the right of its
    /// Figure 1 (η = 4.325, L = 1.9070).
    #[test]
    fn the_scaled_rmf_energy_finds_the_papers_fair_curve() {
        let q = best_quintic(&example_1(), ShapeMeasure::ScaledEnergyRmf, 90)
            .unwrap()
            .quintic;
        assert!((q.eta - 4.325).abs() < 0.01, "η = {}", q.eta);
        assert!((q.measures.arc_length - 1.907).abs() < 0.01);
    }

    /// On these data the raw energies lead to a loop thousands of chords long (the
    /// documented pitfall), the scaled one to a fair curve.
    #[test]
    fn raw_energies_prefer_huge_loops_scaled_ones_do_not() {
        let d = data(0.3, 1.5, 1.5);
        let raw = best_quintic(&d, ShapeMeasure::EnergyRmf, 360)
            .unwrap()
            .quintic;
        let scaled = best_quintic(&d, ShapeMeasure::ScaledEnergyRmf, 360)
            .unwrap()
            .quintic;
        println!(
            "raw E_rmf: L = {:.1}, E_rmf = {:.2e}; L·E_rmf: L = {:.3}, E_rmf = {:.3}",
            raw.measures.arc_length,
            raw.measures.energy_rmf,
            scaled.measures.arc_length,
            scaled.measures.energy_rmf
        );
        assert!(raw.measures.arc_length > 1000.0);
        assert!(scaled.measures.arc_length < 1.5);
    }

    #[test]
    fn refuses_zero_samples_and_reports_data_without_interpolants() {
        let e = best_quintic(&example_1(), ShapeMeasure::ArcLength, 0).unwrap_err();
        assert!(e.is(crate::ErrorKind::InvalidInput) && e.message().contains("eta_samples"));
        let none = best_quintic(&data(2.0, 3.1, 1.5), ShapeMeasure::ArcLength, 360).unwrap_err();
        assert!(none.is(crate::ErrorKind::NoSolution), "{none}");
    }
}
