//! Approximation of a developable surface by a cone spline (Section "G1 Hermite elements"):
//! select rulings of the surface — the inflection generators always, since a cone of
//! revolution has none and their behaviour can only be a junction —, take their G1 elements
//! and join consecutive ones by cone pairs. The remaining rulings are chosen adaptively: an
//! interval whose pair deviates from the surface by more than the tolerance is halved.
//!
//! The deviation of a pair is the largest distance from the surface's points over the
//! region (rulings sampled across the interval, points along each ruling) to the pair's
//! pieces extended along their rulings.

use super::developable::{inflection_generators, Developable};
use super::pair::{cone_pair, ConePair, Rule};
use super::piece::ConePiece;
use super::spline::ConeSpline;
use crate::error::{invalid, Error, Result};

/// Rulings sampled per interval (plus one) and points per ruling for the deviation.
const RULING_SAMPLES: usize = 12;
const POINT_SAMPLES: usize = 5;
/// Uniform rulings scanned for inflection generators.
const INFLECTION_SAMPLES: usize = 400;

/// The result of [`approximate`].
#[derive(Clone, Debug)]
pub struct Approximation {
    pub spline: ConeSpline,
    /// The parameters of the selected rulings (the elements), increasing.
    pub parameters: Vec<f64>,
    /// The inflection generators found (a subset of `parameters`).
    pub inflections: Vec<f64>,
    /// The largest sampled distance from the surface to the cone spline.
    pub max_error: f64,
}

/// Largest distance from sampled region points of `surface` on [a, b] to the pieces.
pub fn deviation(
    surface: &dyn Developable,
    pieces: &[ConePiece],
    a: f64,
    b: f64,
    rulings: usize,
) -> Result<f64> {
    let mut worst = 0.0f64;
    for k in 0..=rulings {
        let t = a + (b - a) * k as f64 / rulings as f64;
        let r = surface.ruling(t)?;
        for j in 0..POINT_SAMPLES {
            let v = r.range.0 + (r.range.1 - r.range.0) * j as f64 / (POINT_SAMPLES - 1) as f64;
            let y = r.point + v * r.direction;
            let d = pieces
                .iter()
                .map(|p| p.distance(y))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d);
        }
    }
    Ok(worst)
}

/// Fits a cone spline to `surface` within `tolerance` (max distance over the region),
/// with at most `max_pieces` pieces, the pairs chosen by `rule`.
pub fn approximate(
    surface: &dyn Developable,
    tolerance: f64,
    rule: Rule,
    max_pieces: usize,
) -> Result<Approximation> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return invalid!("tolerance = {tolerance} must be finite and positive");
    }
    let (lo, hi) = surface.domain();
    let inflections = inflection_generators(surface, INFLECTION_SAMPLES)?;
    let mut junctions = vec![lo];
    junctions.extend(&inflections);
    junctions.push(hi);
    let mut accepted: Vec<(f64, ConePair, f64)> = Vec::new();
    for w in junctions.windows(2) {
        fit_interval(
            surface,
            w[0],
            w[1],
            tolerance,
            rule,
            max_pieces,
            &mut accepted,
        )?;
    }
    let mut parameters = vec![lo];
    parameters.extend(accepted.iter().map(|(b, _, _)| *b));
    let max_error = accepted.iter().map(|(_, _, e)| *e).fold(0.0, f64::max);
    let spline = ConeSpline::new(
        accepted
            .into_iter()
            .flat_map(|(_, p, _)| p.pieces)
            .collect(),
    )?;
    Ok(Approximation {
        spline,
        parameters,
        inflections,
        max_error,
    })
}

/// Accepts [a, b] with its pair if it is within the tolerance, else halves it (depth
/// first, so `out` stays ordered by parameter).
fn fit_interval(
    surface: &dyn Developable,
    a: f64,
    b: f64,
    tolerance: f64,
    rule: Rule,
    max_pieces: usize,
    out: &mut Vec<(f64, ConePair, f64)>,
) -> Result<()> {
    let (ea, eb) = (surface.element(a)?, surface.element(b)?);
    let attempt = cone_pair(
        &ea,
        &eb,
        rule,
        None,
        ("the ruling at t_a", "the ruling at t_b"),
    )
    .and_then(|pair| {
        Ok((
            deviation(surface, &pair.pieces, a, b, RULING_SAMPLES)?,
            pair,
        ))
    });
    if let Ok((error, pair)) = &attempt {
        if *error <= tolerance {
            out.push((b, pair.clone(), *error));
            return Ok(());
        }
    }
    let pieces_so_far: usize = out.iter().map(|(_, p, _)| p.pieces.len()).sum();
    let (lo, hi) = surface.domain();
    if pieces_so_far + 4 > max_pieces || b - a < 1e-9 * (hi - lo) {
        return Err(Error::NotConverged(match attempt {
            Ok((error, _)) => format!(
                "tolerance {tolerance:.3e} not reached with at most {max_pieces} pieces \
                 (deviation {error:.3e} on [{a}, {b}])"
            ),
            Err(e) => format!(
                "no cone pair joins the rulings at t = {a} and t = {b}: {}",
                e.message()
            ),
        }));
    }
    let m = 0.5 * (a + b);
    fit_interval(surface, a, m, tolerance, rule, max_pieces, out)?;
    fit_interval(surface, m, b, tolerance, rule, max_pieces, out)
}
