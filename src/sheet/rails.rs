//! Parts bounded by the input's own boundary: a developable given as a ruled surface
//! between two rails (a NURBS of degree (1, n), [LP] (2)) or as a tangent surface over
//! [t₀, t₁] × [v₀, v₁] ((1): x(t) + v e(t)), approximated by a cone spline ([LP] "G1
//! Hermite elements", [`approximate_developable`](crate::approximate_developable)), and
//! trimmed on every piece between the two rails instead of between two parallel circles.
//!
//! On a piece, the ruling at the arc parameter v is L(v) + ρ e(v); the rail meets it (to
//! within the fit) at the distance ρᵢ(v) of its crossing with the plane through the ruling
//! and the surface normal ([`Rail::crossing`]). ρᵢ is
//! fitted by the cubic Hermite polynomial of its values and slopes at the piece's end
//! rulings — shared with the neighbours, so the boundary is continuous, and tangent
//! continuous to the accuracy of the slopes — and the piece's boundary is the exactly
//! rational curve L(v) + ρᵢ(v) e(v) of degree 2 + 3 (the ruling segments from boundary to
//! boundary: degree (1, 5)). The cone fit takes half the tolerance and the boundaries the
//! other half, so every boundary lies within the tolerance of the input's: a piece whose
//! boundary strays from its rail by more than its half is halved (the surface is unchanged;
//! each half gets its own cubic). A fit that puts a cone vertex on the part (the paper's Ω
//! is the part here) is repeated at a quarter of the fit tolerance.

use super::thickness::{bend_sign, bends_both_ways};
use super::transition::TransitionFit;
use super::trim::{split_piece, Trim, TrimmedSpline};
use crate::cone_spline::approximate::{fit, FitError};
use crate::cone_spline::developable::Developable;
use crate::cone_spline::{ConePiece, ConeSpline, Element, Rule};
use crate::error::{Error, Result};
use crate::math::{minimize_bracketed, secant_refine};
use glam::DVec3;

/// Samples of the rail, per search window, before Brent's method refines the nearest.
const RAIL_SAMPLES: usize = 16;
/// Most secant steps polishing a rail's crossing with a ruling's plane.
const SECANT_STEPS: usize = 30;
/// Samples per piece at which a fitted boundary is measured against its rail.
const CHECK_SAMPLES: usize = 8;
/// Deepest halving of one piece for its boundaries.
const MAX_SPLITS: usize = 12;
/// Step (in the arc parameter) of the one-sided differences for the slopes ρ′.
const SLOPE_STEP: f64 = 1e-4;
/// How often the fit tolerance is quartered when a cone vertex falls on the part.
const REFITS: usize = 3;

/// A rail: the end `side` (0 or 1) of the rulings' region, as a function of the
/// developable's parameter.
struct Rail<'a> {
    surface: &'a dyn Developable,
    side: usize,
    /// How far from a ruling's line the rail may pass where it meets it: the tolerance.
    reach: f64,
}

impl Rail<'_> {
    fn at(&self, t: f64) -> Result<DVec3> {
        let r = self.surface.ruling(t)?;
        let v = if self.side == 0 { r.range.0 } else { r.range.1 };
        Ok(r.point + v * r.direction)
    }

    /// The parameter near `guess` (within `window` of it) where the rail meets the line of
    /// the element `el`'s ruling (to within the fit), and the rail's point there.
    ///
    /// The line may meet the rail more than once — the backward extension of a tangent
    /// surface's ruling crosses the surface's other rulings — so every local minimum of the
    /// distance from the line is a candidate, and the one nearest to `guess` among those
    /// within `reach` of the line is the rail's crossing (the parameter moves continuously
    /// along the part). A candidate is polished as the simple root of (x(t) − l)·p, p the
    /// element's side vector (the rail runs across the rulings), to round-off: the point
    /// nearest to the line alone is only known to √ε, too coarse for the slopes ρ′.
    fn crossing(&self, el: &Element, guess: f64, window: f64) -> Result<(f64, DVec3)> {
        let (lo, hi) = self.surface.domain();
        let (a, b) = ((guess - window).max(lo), (guess + window).min(hi));
        let distance = |t: f64| {
            self.at(t)
                .map(|x| (x - el.point).cross(el.ruling).length())
                .unwrap_or(f64::INFINITY)
        };
        let ts: Vec<f64> = (0..=RAIL_SAMPLES)
            .map(|j| a + (b - a) * j as f64 / RAIL_SAMPLES as f64)
            .collect();
        let ds: Vec<f64> = ts.iter().map(|&t| distance(t)).collect();
        let candidates = (0..ts.len()).filter(|&i| {
            (i == 0 || ds[i] <= ds[i - 1]) && (i == RAIL_SAMPLES || ds[i] <= ds[i + 1])
        });
        let polished = candidates.map(|i| {
            let (l, r) = (ts[i.saturating_sub(1)], ts[(i + 1).min(RAIL_SAMPLES)]);
            let m = minimize_bracketed(distance, l, r, 1e-15 * (hi - lo).max(1e-300));
            let nearest = if m.value <= ds[i] { m.x } else { ts[i] };
            // Within the candidate's bracket: the plane meets the rail elsewhere too.
            let across = |t: f64| {
                (l..=r)
                    .contains(&t)
                    .then(|| self.at(t).ok())
                    .flatten()
                    .map(|x| (x - el.point).dot(el.side))
            };
            let t = secant_refine(across, nearest, 1e-6 * (r - l), SECANT_STEPS);
            (t, distance(t))
        });
        let (within, beyond): (Vec<_>, Vec<_>) = polished.partition(|c| c.1 <= self.reach);
        let t = match within
            .iter()
            .min_by(|x, y| (x.0 - guess).abs().total_cmp(&(y.0 - guess).abs()))
        {
            Some(c) => c.0,
            // No crossing: the nearest approach (its boundary will fail the tolerance).
            None => beyond
                .iter()
                .min_by(|x, y| x.1.total_cmp(&y.1))
                .map_or(guess.clamp(lo, hi), |c| c.0),
        };
        Ok((t, self.at(t)?))
    }

    /// Distance from `x` to the rail near the parameter `guess`.
    fn distance(&self, x: DVec3, guess: f64, window: f64) -> f64 {
        let (lo, hi) = self.surface.domain();
        let (a, b) = ((guess - window).max(lo), (guess + window).min(hi));
        let d = |t: f64| self.at(t).map(|y| y.distance(x)).unwrap_or(f64::INFINITY);
        let ts: Vec<f64> = (0..=RAIL_SAMPLES)
            .map(|j| a + (b - a) * j as f64 / RAIL_SAMPLES as f64)
            .collect();
        let best = (0..ts.len())
            .min_by(|&i, &j| d(ts[i]).total_cmp(&d(ts[j])))
            .unwrap_or(0);
        let (l, r) = (ts[best.saturating_sub(1)], ts[(best + 1).min(RAIL_SAMPLES)]);
        minimize_bracketed(d, l, r, 1e-15 * (hi - lo).max(1e-300))
            .value
            .min(d(ts[best]))
    }
}

/// The distance along the ruling of `piece` at the arc parameter v from its reference point
/// to the rail, and the rail's parameter there.
fn rail_distance(
    rail: &Rail,
    piece: &ConePiece,
    v: f64,
    guess: f64,
    window: f64,
) -> Result<(f64, f64)> {
    let f = super::trim::fraction_of_parameter(super::marks::part_angle(piece), v);
    let el = piece.element_at(f);
    let (t, x) = rail.crossing(&el, guess, window)?;
    Ok(((x - el.point).dot(el.ruling), t))
}

/// The cubic Hermite trim of one rail on `piece` from the values at its end rulings.
fn hermite_trim(
    rail: &Rail,
    piece: &ConePiece,
    ends: [(f64, f64); 2],
    window: f64,
) -> Result<Trim> {
    let h = SLOPE_STEP;
    let slope = |v0: f64, sign: f64, value: f64, guess: f64| -> Result<f64> {
        // One-sided three-point difference into the piece.
        let (r1, _) = rail_distance(rail, piece, v0 + sign * h, guess, window)?;
        let (r2, _) = rail_distance(rail, piece, v0 + sign * 2.0 * h, guess, window)?;
        Ok(sign * (-3.0 * value + 4.0 * r1 - r2) / (2.0 * h))
    };
    let (r0, t0) = ends[0];
    let (r1, t1) = ends[1];
    let (d0, d1) = (slope(0.0, 1.0, r0, t0)?, slope(1.0, -1.0, r1, t1)?);
    Ok(Trim::polynomial(vec![r0, r0 + d0 / 3.0, r1 - d1 / 3.0, r1]))
}

/// Largest distance of the fitted boundary of `piece` from its rail.
fn trim_error(
    rail: &Rail,
    piece: &ConePiece,
    trim: &Trim,
    guesses: (f64, f64),
    window: f64,
) -> f64 {
    (1..CHECK_SAMPLES)
        .map(|j| {
            let v = j as f64 / CHECK_SAMPLES as f64;
            let f = super::trim::fraction_of_parameter(super::marks::part_angle(piece), v);
            let x = piece.element_at(f).at(trim.eval(v));
            let guess = guesses.0 + (guesses.1 - guesses.0) * v;
            rail.distance(x, guess, window)
        })
        .fold(0.0, f64::max)
}

/// Trims `piece` between both rails, halving it until both boundaries are within
/// `tolerance`; appends the pieces and trims. `starts` are the rail values (ρ, t) at the
/// piece's first ruling.
// The recursion carries the piece, the searches' starts and window, the tolerance and the
// scale of the messages: one argument more than clippy's default.
#[allow(clippy::too_many_arguments)]
fn trim_piece(
    rails: &[Rail; 2],
    piece: ConePiece,
    starts: [(f64, f64); 2],
    window: f64,
    tolerance: f64,
    scale: f64,
    depth: usize,
    out: &mut Trimmed,
) -> Result<[(f64, f64); 2]> {
    let mut ends = [(0.0, 0.0); 2];
    for (k, rail) in rails.iter().enumerate() {
        ends[k] = rail_distance(rail, &piece, 1.0, starts[k].1, window)?;
    }
    let trims = [0, 1].map(|k| hermite_trim(&rails[k], &piece, [starts[k], ends[k]], window));
    let [a, b] = trims;
    let (a, b) = (a?, b?);
    let error = [0, 1]
        .map(|k| {
            let trim = if k == 0 { &a } else { &b };
            trim_error(&rails[k], &piece, trim, (starts[k].1, ends[k].1), window)
        })
        .into_iter()
        .fold(0.0, f64::max);
    if error <= tolerance {
        out.pieces.push(piece);
        out.trims.push([a, b]);
        out.rail_parameters
            .push([(starts[0].1, ends[0].1), (starts[1].1, ends[1].1)]);
        return Ok(ends);
    }
    if depth >= MAX_SPLITS {
        return Err(Error::not_converged(format!(
            "the part's edges stay {:.3e} from the rails (at most {:.3e}) after {MAX_SPLITS} \
             halvings of a piece",
            error * scale,
            tolerance * scale
        )));
    }
    let [first, second] = <[ConePiece; 2]>::try_from(split_piece(&piece, 2)).expect("two halves");
    let middle = trim_piece(
        rails,
        first,
        starts,
        window,
        tolerance,
        scale,
        depth + 1,
        out,
    )?;
    trim_piece(
        rails,
        second,
        middle,
        window,
        tolerance,
        scale,
        depth + 1,
        out,
    )
}

/// The trimmed pieces, with the rails' parameters at each piece's end rulings.
#[derive(Default)]
struct Trimmed {
    pieces: Vec<ConePiece>,
    trims: Vec<[Trim; 2]>,
    rail_parameters: Vec<[(f64, f64); 2]>,
}

/// Whether a cone vertex lies on the trimmed rulings of its piece (sampled).
fn vertex_on_part(piece: &ConePiece, trims: &[Trim; 2]) -> bool {
    let Some(v) = piece.vertex() else {
        return false;
    };
    if bend_sign(piece) == 0.0 {
        return false;
    }
    let rho = piece.start.parameter_of(v);
    (0..=8).any(|j| {
        let t = j as f64 / 8.0;
        let (r0, r1) = (trims[0].eval(t), trims[1].eval(t));
        let margin = 1e-6 * (r1 - r0).abs();
        rho > r0.min(r1) - margin && rho < r0.max(r1) + margin
    })
}

/// The part of `surface` (internal coordinates) between its two rails (the ends of its
/// rulings' regions), within `tolerance`.
pub(crate) fn between_rails(
    surface: &dyn Developable,
    tolerance: f64,
    max_pieces: usize,
    scale: f64,
) -> Result<(TrimmedSpline, TransitionFit)> {
    let rails = [0, 1].map(|side| Rail {
        surface,
        side,
        reach: tolerance,
    });
    let (lo, hi) = surface.domain();
    let mut fit_tolerance = 0.5 * tolerance;
    let mut last = String::new();
    for _ in 0..REFITS {
        let user = |x: f64| x * scale;
        let fit = match fit(
            surface,
            fit_tolerance,
            Rule::MinimalVertexDistance,
            max_pieces,
        ) {
            Ok(fit) => fit,
            Err(FitError::Pieces { .. })
            | Err(FitError::NoPair {
                pieces_exhausted: true,
                ..
            }) => {
                return Err(Error::not_converged(format!(
                    "the part needs more than max_pieces = {max_pieces} pieces at the fit \
                     tolerance {:.3e}",
                    user(fit_tolerance)
                )))
            }
            Err(FitError::Narrow { deviation, a, b }) => {
                return Err(Error::not_converged(format!(
                    "the cone fit stays {:.3e} from the surface (fit tolerance {:.3e}) on \
                     [{a}, {b}], which is not halved further",
                    user(deviation),
                    user(fit_tolerance)
                )))
            }
            Err(FitError::NoPair { a, b, reason, .. }) => {
                return Err(Error::not_converged(format!(
                    "no cone pair joins the rulings at t = {a} and t = {b} with its vertices \
                     off the part (fit tolerance {:.3e}): {reason}",
                    user(fit_tolerance)
                )))
            }
            Err(FitError::Resolution { largest }) => {
                let message = format!(
                    "tolerance = {:.3e}{} is below what f64 resolves at the surface's \
                     coordinates (up to {:.3e}: one rounding is {:.3e})",
                    user(tolerance),
                    if fit_tolerance < 0.5 * tolerance {
                        format!(" (the fit tolerance {:.3e})", user(fit_tolerance))
                    } else {
                        String::new()
                    },
                    user(largest),
                    user(f64::EPSILON * largest)
                );
                return Err(if fit_tolerance < 0.5 * tolerance {
                    Error::not_converged(message)
                } else {
                    Error::invalid_input(message)
                });
            }
            Err(FitError::Other(e)) => return Err(e),
        };
        let pieces = super::trim::split_long_pieces(fit.spline.pieces());
        // A rail point moves across a piece by about the domain over the pieces: the
        // searches look a few pieces' worth either way.
        let window = 4.0 * (hi - lo) / pieces.len() as f64;
        let first = pieces[0];
        let mut starts = [(0.0, lo); 2];
        for (k, rail) in rails.iter().enumerate() {
            starts[k] = rail_distance(rail, &first, 0.0, lo, window)?;
        }
        let mut out = Trimmed::default();
        for piece in &pieces {
            starts = trim_piece(
                &rails,
                *piece,
                starts,
                window,
                0.5 * tolerance,
                scale,
                0,
                &mut out,
            )?;
        }
        if out.pieces.len() > max_pieces {
            return Err(Error::not_converged(format!(
                "the part needs more than max_pieces = {max_pieces} pieces at the fit \
                 tolerance {:.3e}",
                user(fit_tolerance)
            )));
        }
        let Trimmed {
            pieces,
            trims,
            rail_parameters,
        } = out;
        if let Some(k) = pieces
            .iter()
            .zip(&trims)
            .position(|(p, t)| vertex_on_part(p, t))
        {
            last = format!("the cone fit puts a vertex on the part (piece {k})");
            fit_tolerance *= 0.25;
            continue;
        }
        // Where the surface has no inflection generator, pieces bending both ways are a
        // fit too coarse somewhere.
        if let (true, Some((k, j))) = (fit.inflections.is_empty(), bends_both_ways(&pieces)) {
            last = format!(
                "the cone fit bends both ways (piece {k} one way, piece {j} the other) \
                 though the surface does not inflect"
            );
            fit_tolerance *= 0.25;
            continue;
        }
        let spline = ConeSpline::new(pieces)?;
        let part = TrimmedSpline {
            spline,
            trims,
            closed: false,
        };
        let edges = [0, 1].map(|k| edge_distance(&rails[k], &part, k, &rail_parameters, window));
        return Ok((
            part,
            TransitionFit {
                deviation: fit.max_error,
                edge_distance: edges,
                fit_tolerance,
            },
        ));
    }
    Err(Error::not_converged(format!(
        "tolerance = {:.3e}: {last} at every fit tolerance down to {:.3e}",
        tolerance * scale,
        4.0 * fit_tolerance * scale
    )))
}

/// Largest sampled distance of the part's boundary `side` from its rail (16 points per
/// piece, each against the rail near the parameters of the piece's end rulings).
fn edge_distance(
    rail: &Rail,
    part: &TrimmedSpline,
    side: usize,
    rail_parameters: &[[(f64, f64); 2]],
    window: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for (k, piece) in part.pieces().iter().enumerate() {
        let (a, b) = rail_parameters[k][side];
        for j in 0..=16 {
            let v = j as f64 / 16.0;
            let f = super::trim::fraction_of_parameter(super::marks::part_angle(piece), v);
            let x = piece.element_at(f).at(part.trims[k][side].eval(v));
            worst = worst.max(rail.distance(x, a + (b - a) * v, window));
        }
    }
    worst
}
