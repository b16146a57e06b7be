//! Approximation of a developable surface by a cone spline (Section "G1 Hermite elements"):
//! select rulings of the surface — the inflection generators always, since a cone of
//! revolution has none and their behaviour can only be a junction —, take their G1 elements
//! and join consecutive ones by cone pairs. The remaining rulings are chosen adaptively: an
//! interval whose pair deviates from the surface by more than the tolerance is halved.
//!
//! The region of interest Ω is the band of each ruling ([`Ruling::range`]); no vertex of the
//! spline lies inside it (Figs. 5–6). Each pair is the rule's most useful solution whose
//! vertices keep out of the band swept by the rulings of its interval ([`SweptBand`]), or
//! one with a vertex just outside it; where none is, the interval is halved too.
//!
//! The deviation of a pair is the largest distance from the surface's points over the
//! region (rulings sampled across the interval, points along each ruling) to the pair's
//! pieces extended along their rulings.
//!
//! The fit runs in coordinates centred on the first ruling and scaled by a power of two
//! near the surface's size (tolerance and distances with them), so that it gives the same
//! pieces, mapped, for the surface scaled from 1e-200 to 1e200 or moved far away.

use super::developable::{Developable, Ruling, END_FRACTION};
use super::element::Element;
use super::pair::{cone_pair_in_band, ConePair, Rule};
use super::piece::ConePiece;
use super::region::SweptBand;
use super::spline::ConeSpline;
use crate::error::{Error, Result};
use crate::math::interior_midpoint;
use crate::model::Similarity;
use glam::DVec3;

/// Rulings sampled per interval (plus one) and points per ruling for the deviation.
const RULING_SAMPLES: usize = 12;
const POINT_SAMPLES: usize = 5;

/// The result of [`approximate`].
#[derive(Clone, Debug)]
pub struct Approximation {
    /// The cone spline.
    pub spline: ConeSpline,
    /// The parameters of the selected rulings (the elements), increasing.
    pub parameters: Vec<f64>,
    /// The inflection generators found (a subset of `parameters`).
    pub inflections: Vec<f64>,
    /// The largest sampled distance from the surface to the cone spline.
    pub max_error: f64,
    /// The smallest relative clearance of a vertex from the region of interest
    /// ([`SweptBand::clearance`]: 0 on a ruling's end, positive outside the band, in units
    /// of the band's width); +∞ when no piece has a vertex.
    pub vertex_clearance: f64,
}

/// Largest distance from sampled region points of `surface` on [a, b] to the pieces.
#[cfg(test)]
pub(crate) fn deviation(
    surface: &dyn Developable,
    pieces: &[ConePiece],
    a: f64,
    b: f64,
    rulings: usize,
) -> Result<f64> {
    Ok(deviation_of(
        &sampled_rulings(surface, a, b, rulings)?,
        pieces,
    ))
}

/// The rulings of `surface` at `count + 1` equidistant parameters from a to b.
fn sampled_rulings(surface: &dyn Developable, a: f64, b: f64, count: usize) -> Result<Vec<Ruling>> {
    (0..=count)
        .map(|k| surface.ruling(a + (b - a) * k as f64 / count as f64))
        .collect()
}

/// Largest distance from points of the rulings' regions to the pieces.
fn deviation_of(rulings: &[Ruling], pieces: &[ConePiece]) -> f64 {
    let mut worst = 0.0f64;
    for r in rulings {
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
    worst
}

/// Why [`fit`] stopped short of the tolerance (lengths in the surface's units,
/// parameters the surface's).
#[derive(Debug)]
pub(crate) enum FitError {
    /// More than the allowed pieces would be needed: the deviation on [a, b] when the
    /// halving stopped, and the pieces estimated when it stopped early (the pieces so far
    /// and those this interval needs at the rate its deviation falls).
    Pieces {
        deviation: f64,
        a: f64,
        b: f64,
        estimate: Option<f64>,
    },
    /// The interval [a, b] is too narrow to halve (1e-9 of the domain), its deviation
    /// still above the tolerance.
    Narrow { deviation: f64, a: f64, b: f64 },
    /// No admissible cone pair joins the rulings at a and b, which could not be halved.
    NoPair {
        a: f64,
        b: f64,
        pieces_exhausted: bool,
        reason: String,
    },
    /// The tolerance is below the rounding of the surface's coordinates (up to `largest`).
    Resolution { largest: f64 },
    /// Any other error (of the surface, of its rulings).
    Other(Error),
}

impl From<Error> for FitError {
    fn from(e: Error) -> Self {
        FitError::Other(e)
    }
}

/// The piece limit of cone spline fits and sheet-metal parts when the caller sets none:
/// the fit's time grows with the pieces it makes (some 25 µs each), and a limit is only
/// known to be too small once the fit has used it up.
pub const DEFAULT_MAX_PIECES: usize = 10_000;

/// Fits a cone spline to `surface` within `tolerance` (max distance over the region),
/// with at most `max_pieces` pieces, the pairs chosen by `rule`.
pub fn approximate(
    surface: &dyn Developable,
    tolerance: f64,
    rule: Rule,
    max_pieces: usize,
) -> Result<Approximation> {
    fit(surface, tolerance, rule, max_pieces).map_err(|e| match e {
        FitError::Pieces {
            deviation,
            a,
            b,
            estimate,
        } => Error::not_converged(format!(
            "tolerance = {tolerance:.3e} not reached with at most max_pieces = {max_pieces} \
             pieces (deviation {deviation:.3e} on [{a}, {b}]{})",
            estimate.map_or(String::new(), |n| format!(
                ", where the fit stopped: about {n:.0} pieces would be needed at the rate \
                 the deviation falls"
            ))
        )),
        FitError::Narrow { deviation, a, b } => Error::not_converged(format!(
            "tolerance = {tolerance:.3e} not reached: the deviation is {deviation:.3e} on \
             [{a}, {b}], 1e-9 of the domain, which is not halved further"
        )),
        FitError::NoPair {
            a,
            b,
            pieces_exhausted,
            reason,
        } => Error::not_converged(format!(
            "no cone pair joins the rulings at t = {a} and t = {b} with its vertices \
             outside the region of interest{}: {reason}",
            if pieces_exhausted {
                format!(" (within at most max_pieces = {max_pieces} pieces)")
            } else {
                String::new()
            }
        )),
        FitError::Resolution { largest } => {
            crate::error::below_resolution(tolerance, largest, "the surface's")
        }
        FitError::Other(e) => e,
    })
}

/// [`approximate`] with the reasons it stops apart, for callers that say them in their own
/// terms (a sheet-metal part in the part's units). The tolerance must be above the
/// rounding of the surface's coordinates.
pub(crate) fn fit(
    surface: &dyn Developable,
    tolerance: f64,
    rule: Rule,
    max_pieces: usize,
) -> std::result::Result<Approximation, FitError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(Error::invalid_input(format!(
            "tolerance = {tolerance} must be finite and positive"
        ))
        .into());
    }
    let (lo, hi) = surface.domain();
    let local = Local::of(surface)?;
    if tolerance < f64::EPSILON * local.largest {
        return Err(FitError::Resolution {
            largest: local.largest,
        });
    }
    let scale = local.frame.scale;
    let fit =
        approximate_local(&local, tolerance / scale, rule, max_pieces).map_err(|e| match e {
            FitError::Pieces {
                deviation,
                a,
                b,
                estimate,
            } => FitError::Pieces {
                deviation: deviation * scale,
                a,
                b,
                estimate,
            },
            FitError::Narrow { deviation, a, b } => FitError::Narrow {
                deviation: deviation * scale,
                a,
                b,
            },
            other => other,
        })?;
    let spline = ConeSpline::new(
        fit.spline
            .pieces()
            .iter()
            .map(|p| local.frame.piece_out(p))
            .collect(),
    )?;
    debug_assert_eq!(fit.parameters.first(), Some(&lo));
    debug_assert_eq!(fit.parameters.last(), Some(&hi));
    Ok(Approximation {
        spline,
        max_error: fit.max_error * scale,
        ..fit
    })
}

/// A developable seen in coordinates centred on its first ruling's point and scaled by a
/// power of two near its size (rulings at the ends and the middle of the domain, and the
/// region along them), so that the fit — its tolerance, the pairs, the distances — does
/// not depend on where the surface lies or on its size.
struct Local<'a> {
    surface: &'a dyn Developable,
    frame: Similarity,
    /// The largest coordinate of the region at those rulings (the caller's coordinates).
    largest: f64,
}

impl<'a> Local<'a> {
    fn of(surface: &'a dyn Developable) -> Result<Self> {
        let (lo, hi) = surface.domain();
        let rulings = [lo, 0.5 * (lo + hi), hi].map(|t| surface.ruling(t));
        let first = rulings[0].as_ref().map_err(Clone::clone)?.point;
        let size = rulings
            .iter()
            .flatten()
            .map(|r| {
                crate::math::robust_length(r.point - first)
                    .max(r.range.1.abs())
                    .max(r.range.0.abs())
            })
            .fold(0.0, f64::max);
        let largest = rulings
            .iter()
            .flatten()
            .flat_map(|r| {
                [r.range.0, r.range.1].map(|v| (r.point + v * r.direction).abs().max_element())
            })
            .fold(0.0, f64::max);
        Ok(Self {
            surface,
            frame: Similarity::power_of_two_about(first, size),
            largest,
        })
    }
}

impl Developable for Local<'_> {
    fn domain(&self) -> (f64, f64) {
        self.surface.domain()
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        Ok(self.frame.ruling_in(&self.surface.ruling(t)?))
    }

    fn element(&self, t: f64) -> Result<Element> {
        Ok(self.frame.element_in(&self.surface.element(t)?))
    }

    /// Parameters, the same in local coordinates: the surface's own method.
    fn inflection_generators(&self) -> Result<Vec<f64>> {
        self.surface.inflection_generators()
    }

    fn parallel_generators(&self) -> Result<Vec<f64>> {
        self.surface.parallel_generators()
    }
}

/// [`approximate`] of a surface in local coordinates.
fn approximate_local(
    surface: &dyn Developable,
    tolerance: f64,
    rule: Rule,
    max_pieces: usize,
) -> std::result::Result<Approximation, FitError> {
    let (lo, hi) = surface.domain();
    let inflections = surface.inflection_generators()?;
    let mut interior: Vec<f64> = inflections.clone();
    interior.extend(surface.parallel_generators()?);
    interior.sort_by(f64::total_cmp);
    interior.dedup_by(|x, y| (*x - *y).abs() <= END_FRACTION * (hi - lo));
    let mut junctions = vec![lo];
    junctions.extend(&interior);
    junctions.push(hi);
    let mut fitting = Fitting {
        surface,
        tolerance,
        rule,
        max_pieces,
        junctions: &junctions,
        estimated: false,
        accepted: Vec::new(),
        pieces: 0,
    };
    for w in junctions.windows(2) {
        fitting.interval(w[0], w[1])?;
    }
    let accepted = fitting.accepted;
    let mut parameters = vec![lo];
    parameters.extend(accepted.iter().map(|x| x.end));
    let max_error = accepted.iter().map(|x| x.error).fold(0.0, f64::max);
    let vertex_clearance = accepted
        .iter()
        .map(|x| x.clearance)
        .fold(f64::INFINITY, f64::min);
    let spline = ConeSpline::new(accepted.into_iter().flat_map(|x| x.pair.pieces).collect())?;
    Ok(Approximation {
        spline,
        parameters,
        inflections,
        max_error,
        vertex_clearance,
    })
}

/// An accepted interval: its end parameter, its pair, the pair's deviation and the
/// clearance of its vertices from the region.
struct Accepted {
    end: f64,
    pair: ConePair,
    error: f64,
    clearance: f64,
}

/// The pair of the interval [a, b] by `rule` with no vertex in the region swept by the
/// rulings, and its deviation.
fn interval_pair(
    surface: &dyn Developable,
    a: f64,
    b: f64,
    rule: Rule,
) -> Result<(ConePair, f64, f64)> {
    let (ea, eb) = (surface.element(a)?, surface.element(b)?);
    let band = SweptBand::new(sampled_rulings(surface, a, b, RULING_SAMPLES)?);
    let pair = cone_pair_in_band(
        &ea,
        &eb,
        rule,
        &band,
        ("the ruling at t_a", "the ruling at t_b"),
    )?;
    let turn: f64 = pair.pieces.iter().map(ConePiece::segment_angle).sum();
    let surface_turn = frame_turn(band.rulings());
    if turn > 2.0 * surface_turn + WINDING_SLACK {
        return Err(Error::no_solution(format!(
            "the only admissible cone pairs turn by {turn:.3} rad where the surface turns by {surface_turn:.3} rad"
        )));
    }
    let error = deviation_of(band.rulings(), &pair.pieces);
    let clearance = band.clearance(&pair.pieces);
    Ok((pair, error, clearance))
}

/// How far (radians) the rotation of a pair's pieces may exceed twice the surface's own.
const WINDING_SLACK: f64 = 0.1;

/// The length of the path of the rulings' frames (ruling, side, normal) in rotations: the
/// sum of the rotation angles between consecutive rulings' frames. The pieces of a pair
/// rotate their frames about fixed axes by their segment angles; a pair that follows the
/// surface rotates by about as much, one that winds round its cones by far more, though
/// every point of the surface may still lie near it (the deviation measures the distance
/// from the surface to the pieces, not back).
fn frame_turn(rulings: &[Ruling]) -> f64 {
    let mut total = 0.0;
    let mut previous: Option<(DVec3, DVec3)> = None;
    for r in rulings {
        let mut n = r.normal.normalize();
        if let Some((_, m)) = previous {
            if n.dot(m) < 0.0 {
                n = -n;
            }
        }
        if let Some((e0, n0)) = previous {
            let (p0, p1) = (n0.cross(e0), n.cross(r.direction));
            // |F₁ − F₀|² = 8 sin²(θ/2) for the rotation by θ between two frames.
            let s = (r.direction - e0).length_squared()
                + (p1 - p0).length_squared()
                + (n - n0).length_squared();
            total += 2.0 * (s / 8.0).sqrt().min(1.0).asin();
        }
        previous = Some((r.direction, n));
    }
    total
}

/// The order of approximation the estimate of the pieces needed assumes at least: the
/// deviation of cone pairs falls as about the third to fourth power of the interval's width
/// (measured by the tests below); the larger order estimates fewer pieces.
const ASSUMED_ORDER: f64 = 4.0;

/// How many times `max_pieces` the estimate must exceed for the fit to give up early.
const ESTIMATE_MARGIN: f64 = 8.0;

/// The part of `max_pieces` (at least [`ESTIMATE_AFTER`] pieces) a fit uses before the
/// pieces it needs are estimated: fits within a small part of their limit never pay for
/// the estimate.
const ESTIMATE_FRACTION: usize = 16;
const ESTIMATE_AFTER: usize = 16;

/// The intervals each junction interval is cut into for the estimate (and each halved once
/// more, to see how fast the deviation falls).
const ESTIMATE_INTERVALS: usize = 16;

/// The halving of a surface's junction intervals until every piece is within the
/// tolerance, the accepted intervals in order of parameter.
struct Fitting<'a> {
    surface: &'a dyn Developable,
    tolerance: f64,
    rule: Rule,
    max_pieces: usize,
    junctions: &'a [f64],
    /// Whether the pieces needed have been estimated (once per fit).
    estimated: bool,
    accepted: Vec<Accepted>,
    /// The pieces of the accepted pairs.
    pieces: usize,
}

impl Fitting<'_> {
    /// Accepts [a, b] with its pair if it is within the tolerance, else halves it (depth
    /// first, so the accepted intervals stay ordered by parameter). An interval whose
    /// rulings no admissible pair joins is halved as well.
    fn interval(&mut self, a: f64, b: f64) -> std::result::Result<(), FitError> {
        let attempt = interval_pair(self.surface, a, b, self.rule);
        if let Ok((pair, error, clearance)) = &attempt {
            if *error <= self.tolerance {
                self.pieces += pair.pieces.len();
                self.accepted.push(Accepted {
                    end: b,
                    pair: pair.clone(),
                    error: *error,
                    clearance: *clearance,
                });
                return Ok(());
            }
        }
        self.refuse_out_of_reach(&attempt, a, b)?;
        let (lo, hi) = self.surface.domain();
        let exhausted = self.pieces + 4 > self.max_pieces;
        let too_fine = exhausted || b - a < 1e-9 * (hi - lo);
        let Some(m) = interior_midpoint(a, b).filter(|_| !too_fine) else {
            return Err(match attempt {
                Ok((_, deviation, _)) if exhausted => FitError::Pieces {
                    deviation,
                    a,
                    b,
                    estimate: None,
                },
                Ok((_, deviation, _)) => FitError::Narrow { deviation, a, b },
                Err(e) => FitError::NoPair {
                    a,
                    b,
                    pieces_exhausted: exhausted,
                    reason: e.message(),
                },
            });
        };
        self.interval(a, m)?;
        self.interval(m, b)
    }

    /// Once the fit has used a part of its limit: refuses when the pieces the whole surface
    /// needs are estimated far beyond the limit (the halving of [a, b] would run into it
    /// after most of the work).
    fn refuse_out_of_reach(
        &mut self,
        attempt: &Result<(ConePair, f64, f64)>,
        a: f64,
        b: f64,
    ) -> std::result::Result<(), FitError> {
        let due = (self.max_pieces / ESTIMATE_FRACTION).max(ESTIMATE_AFTER);
        if self.estimated || self.pieces < due {
            return Ok(());
        }
        self.estimated = true;
        let estimate = self.estimate();
        match attempt {
            Ok((_, deviation, _)) if estimate > ESTIMATE_MARGIN * self.max_pieces as f64 => {
                Err(FitError::Pieces {
                    deviation: *deviation,
                    a,
                    b,
                    estimate: Some(estimate),
                })
            }
            _ => Ok(()),
        }
    }

    /// About how many pieces the fit needs: each junction interval cut into
    /// [`ESTIMATE_INTERVALS`], each of those needing (deviation / tolerance)^(1/order)
    /// intervals of two pieces, the order measured by halving it once but at least
    /// [`ASSUMED_ORDER`] (a fall steeper than asymptotic never overestimates). An
    /// interval without an admissible pair counts as one.
    fn estimate(&self) -> f64 {
        let mut total = 0.0;
        for w in self.junctions.windows(2) {
            let step = (w[1] - w[0]) / ESTIMATE_INTERVALS as f64;
            for k in 0..ESTIMATE_INTERVALS {
                let (a, b) = (w[0] + k as f64 * step, w[0] + (k + 1) as f64 * step);
                total += self.intervals_needed(a, b);
            }
        }
        2.0 * total
    }

    /// The estimate of [`Fitting::estimate`] for one interval.
    fn intervals_needed(&self, a: f64, b: f64) -> f64 {
        let deviation = |a, b| {
            interval_pair(self.surface, a, b, self.rule)
                .ok()
                .map(|(_, deviation, _)| deviation)
        };
        let m = 0.5 * (a + b);
        let Some(whole) = deviation(a, b) else {
            return 1.0;
        };
        let halves = [deviation(a, m), deviation(m, b)];
        let halves: Vec<f64> = halves.into_iter().flatten().collect();
        if halves.len() < 2 {
            return 1.0;
        }
        let worst_half = halves[0].max(halves[1]);
        if worst_half <= self.tolerance {
            return 2.0;
        }
        let order = (whole / worst_half).log2().max(ASSUMED_ORDER);
        2.0 * (worst_half / self.tolerance).powf(1.0 / order)
    }
}

#[cfg(test)]
mod tests {
    use super::super::developable::{DualDevelopable, RuledSurface};
    use super::super::region::Region;
    use super::super::test_support::{
        dual_cone_planes, tangent_surface, twisted_cubic, zero_torsion_curve, Helix,
    };
    use super::*;
    use crate::bezier::{NurbsSurface, RationalBezierPatch};
    use glam::{DVec3, DVec4};

    /// Pieces against tolerance; returns the observed order log(n₂/n₁)/log(tol₁/tol₂)
    /// inverted (error ~ h^order) over the whole range.
    fn study(name: &str, surface: &dyn Developable, tolerances: &[f64]) -> f64 {
        let mut counts = Vec::new();
        for &tol in tolerances {
            let fit = approximate(surface, tol, Rule::MinimalVertexDistance, 100_000).unwrap();
            let (lo, hi) = surface.domain();
            let dense = deviation(
                surface,
                fit.spline.pieces(),
                lo,
                hi,
                40 * fit.parameters.len(),
            )
            .unwrap();
            println!(
                "{name}: tolerance {tol:.0e}: {} pieces, max deviation {:.3e} (dense {:.3e})",
                fit.spline.pieces().len(),
                fit.max_error,
                dense
            );
            assert!(
                fit.max_error <= tol && dense <= tol,
                "{name}: deviation {dense:e} > {tol:e}"
            );
            counts.push(fit.spline.pieces().len() as f64);
        }
        let n = tolerances.len() - 1;
        let order = (tolerances[0] / tolerances[n]).ln() / (counts[n] / counts[0]).ln();
        println!("{name}: observed approximation order {order:.2}");
        order
    }

    #[test]
    fn tangent_surfaces_of_a_twisted_cubic_and_a_helix() {
        let curve = twisted_cubic(-0.5, 1.0);
        let order = study(
            "twisted cubic",
            &tangent_surface(&curve, 0.5, 1.0),
            &[1e-2, 1e-3, 1e-4, 1e-5],
        );
        assert!((2.5..4.5).contains(&order), "order {order}");
        let helix = Helix {
            radius: 1.0,
            pitch: 0.5,
            domain: (0.0, std::f64::consts::TAU),
        };
        let order = study(
            "helix",
            &tangent_surface(&helix, 0.5, 1.0),
            &[1e-2, 1e-3, 1e-4, 1e-5],
        );
        assert!((2.5..4.5).contains(&order), "order {order}");
    }

    /// On a domain of width 1e-7 at t = 1 no cone pair joins the rulings (cylinder-first
    /// rule) and the halving reaches an interval of adjacent floats, [1.0001,
    /// 1.0001000000000002], whose midpoint is one of its ends: the fit ends there with an
    /// error instead of halving it until the stack overflows.
    #[test]
    fn intervals_too_narrow_to_halve_are_an_error() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.5,
            domain: (1.0001, 1.00010010001),
        };
        for rule in [Rule::CylinderFirst, Rule::MinimalVertexDistance] {
            let surface = tangent_surface(&helix, 0.1, 1.0);
            let e = approximate(&surface, 1.0001, rule, 29).err().unwrap();
            assert!(
                e.message().contains("no cone pair joins the rulings"),
                "{e}"
            );
        }
    }

    #[test]
    fn inflection_generators_become_junctions() {
        let curve = zero_torsion_curve();
        let surface = tangent_surface(&curve, 0.3, 0.8);
        let fit = approximate(&surface, 1e-3, Rule::MinimalVertexDistance, 10_000).unwrap();
        assert_eq!(fit.inflections.len(), 1);
        assert!(fit.inflections[0].abs() < 1e-9, "{:?}", fit.inflections);
        assert!(fit.parameters.contains(&fit.inflections[0]));
        assert!(fit.max_error <= 1e-3);
    }

    #[test]
    fn ruled_nurbs_and_dual_inputs() {
        // The tangent surface of (t, t², t³) between the rails x(t) + x'(t)/2 and x(t) + x'(t),
        // a polynomial NURBS of degree (1, 3) on t ∈ [0.2, 1.2].
        let curve = twisted_cubic(0.2, 1.2);
        let (mut poles, derivative) = (
            Vec::new(),
            crate::bezier::bernstein::derivative(curve.segments()[0].homogeneous()),
        );
        let d: Vec<DVec4> = crate::bezier::bernstein::elevate(&derivative, 1);
        for scale in [0.5, 1.0] {
            for (x, dx) in curve.segments()[0].homogeneous().iter().zip(&d) {
                poles.push((x.truncate() + scale * dx.truncate()).extend(1.0));
            }
        }
        let patch = RationalBezierPatch::from_homogeneous(1, 3, poles).unwrap();
        let pw = crate::bezier::PiecewiseSurface::new(vec![patch], vec![0.0, 1.0], vec![0.2, 1.2])
            .unwrap();
        let nurbs = NurbsSurface::from_piecewise(&pw).unwrap();
        let ruled = RuledSurface::new(nurbs.to_piecewise().unwrap()).unwrap();
        let fit = approximate(&ruled, 1e-4, Rule::MinimalVertexDistance, 10_000).unwrap();
        println!(
            "ruled (1, 3) NURBS: 1e-4 with {} pieces",
            fit.spline.pieces().len()
        );
        assert!(fit.max_error <= 1e-4);

        // Not developable: z = xy, K ≠ 0 is measured and reported.
        let saddle = NurbsSurface::new(
            1,
            1,
            2,
            2,
            vec![
                DVec3::new(-1.0, -1.0, 1.0),
                DVec3::new(-1.0, 1.0, -1.0),
                DVec3::new(1.0, -1.0, -1.0),
                DVec3::ONE,
            ],
            None,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        let cubic = NurbsSurface::new(
            2,
            1,
            3,
            2,
            vec![DVec3::ZERO; 6],
            None,
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        assert!(RuledSurface::new(cubic.to_piecewise().unwrap())
            .err()
            .unwrap()
            .message()
            .contains("degree_u = 1"));
        let err = RuledSurface::new(saddle.to_piecewise().unwrap())
            .err()
            .unwrap();
        assert!(
            err.message().contains("not developable") && err.message().contains("|K|"),
            "{err}"
        );

        // The dual form (4): a quadratic B-spline of planes through the origin (a cone).
        let region = Region::new(DVec3::new(-3.0, -3.0, 1.0), DVec3::new(3.0, 3.0, 2.0)).unwrap();
        let dual = DualDevelopable::new(
            2,
            &dual_cone_planes(),
            &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            region,
        )
        .unwrap();
        let fit = approximate(&dual, 1e-4, Rule::MinimalVertexDistance, 10_000).unwrap();
        println!(
            "dual quadratic cone: 1e-4 with {} pieces",
            fit.spline.pieces().len()
        );
        assert!(fit.max_error <= 1e-4);
        assert!(fit
            .spline
            .pieces()
            .iter()
            .all(|p| p.vertex().is_some_and(|v| v.length() < 1e-9)));
    }

    #[test]
    fn rejects_bad_tolerances() {
        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.5, 1.0);
        for tol in [0.0, -1.0, f64::NAN] {
            assert!(approximate(&surface, tol, Rule::MinimalVertexDistance, 100).is_err());
        }
        let err = approximate(&surface, 1e-9, Rule::MinimalVertexDistance, 8).unwrap_err();
        assert!(err.is(crate::ErrorKind::NotConverged), "{err}");
    }

    /// Issue 13 item 6: the tangent surface of a 1,000-turn helix to 1e-2 ended
    /// NOT_CONVERGED ("no cone pair joins the rulings at t = 2.1764… and 2.1764…": the
    /// pairs of close rulings failed, and the halving went on to the narrowest interval).
    #[test]
    fn a_thousand_turn_helix_converges() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.4,
            domain: (0.0, std::f64::consts::TAU * 1000.0),
        };
        let surface = tangent_surface(&helix, 0.5, 2.0);
        let start = std::time::Instant::now();
        let fit = approximate(&surface, 1e-2, Rule::MinimalVertexDistance, 1_000_000).unwrap();
        println!(
            "1,000-turn helix to 1e-2: {} pieces, max deviation {:.3e}, {:.2} s",
            fit.spline.pieces().len(),
            fit.max_error,
            start.elapsed().as_secs_f64()
        );
        assert!(fit.max_error <= 1e-2);
        // Densely over the first and the last turn (every point against every piece).
        let (lo, hi) = surface.domain();
        for (a, b) in [
            (lo, lo + std::f64::consts::TAU),
            (hi - std::f64::consts::TAU, hi),
        ] {
            let dense = deviation(&surface, fit.spline.pieces(), a, b, 100).unwrap();
            assert!(dense <= 1e-2, "dense deviation {dense:e} on [{a}, {b}]");
        }
    }

    /// The fit as it was before the region was taken into account: the default pair of each
    /// interval whatever its vertices, halved for the tolerance alone. Returns the accepted
    /// intervals with their pairs.
    fn fit_ignoring_the_region(
        surface: &dyn Developable,
        a: f64,
        b: f64,
        tolerance: f64,
        out: &mut Vec<(f64, f64, ConePair)>,
    ) {
        let (ea, eb) = (surface.element(a).unwrap(), surface.element(b).unwrap());
        let pair =
            super::super::pair::cone_pair(&ea, &eb, Rule::MinimalVertexDistance, None, ("a", "b"));
        if let Ok(pair) = pair {
            if deviation(surface, &pair.pieces, a, b, RULING_SAMPLES).unwrap() <= tolerance {
                out.push((a, b, pair));
                return;
            }
        }
        let m = 0.5 * (a + b);
        fit_ignoring_the_region(surface, a, m, tolerance, out);
        fit_ignoring_the_region(surface, m, b, tolerance, out);
    }

    fn clearance_ignoring_the_region(surface: &dyn Developable, tolerance: f64) -> f64 {
        let (lo, hi) = surface.domain();
        let mut out = Vec::new();
        fit_ignoring_the_region(surface, lo, hi, tolerance, &mut out);
        out.iter()
            .map(|(a, b, pair)| {
                let band =
                    SweptBand::new(sampled_rulings(surface, *a, *b, RULING_SAMPLES).unwrap());
                band.clearance(&pair.pieces)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// Issue 12 item 1: the fit ignored the region. On the tangent surface of the twisted
    /// cubic, v ∈ [0.01, 1] (a wide band close to the curve), the default pairs of the old
    /// halving put vertices well inside the band; the fit now keeps every vertex out of it
    /// and reports the smallest clearance.
    #[test]
    fn vertices_keep_out_of_the_region() {
        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.01, 1.0);
        for tol in [1e-2, 1e-3] {
            let old = clearance_ignoring_the_region(&surface, tol);
            let fit = approximate(&surface, tol, Rule::MinimalVertexDistance, 10_000).unwrap();
            println!(
                "v in [0.01, 1], tolerance {tol:e}: smallest vertex clearance {old:.3e} before, {:.3e} now ({} pieces)",
                fit.vertex_clearance,
                fit.spline.pieces().len()
            );
            assert!(old < -0.01, "the old fit had a vertex inside: {old:e}");
            assert!(fit.vertex_clearance >= 0.0, "{}", fit.vertex_clearance);
            assert!(fit.max_error <= tol);
            // Independently of the fit's own report: every vertex against the band of the
            // surface's ruling at the end of its piece that is a selected ruling.
            let mut k = 0;
            for w in fit.parameters.windows(2) {
                let rulings = [surface.ruling(w[0]).unwrap(), surface.ruling(w[1]).unwrap()];
                let band = SweptBand::new(rulings.to_vec());
                let mut pieces = Vec::new();
                while k < fit.spline.pieces().len() {
                    let p = fit.spline.pieces()[k];
                    pieces.push(p);
                    k += 1;
                    if p.end().ruling.dot(rulings[1].direction) > 1.0 - 1e-12 {
                        break;
                    }
                }
                let first = pieces[0];
                if let Some(v) = first.vertex() {
                    let s = (v - rulings[0].point).dot(rulings[0].direction);
                    let (lo, hi) = rulings[0].range;
                    assert!(
                        s <= lo + 1e-9 * (hi - lo) || s >= hi - 1e-9 * (hi - lo),
                        "vertex at {s} in [{lo}, {hi}]"
                    );
                }
                assert!(band.clearance(&pieces) >= 0.0);
            }
        }
    }

    /// Property-style: random twisted cubics scaled and sheared, random bands on either
    /// side of the curve; every fit has every vertex outside the region.
    #[test]
    fn random_tangent_surfaces_have_no_vertex_in_the_region() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut uniform = |lo: f64, hi: f64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            lo + (hi - lo) * (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst = f64::INFINITY;
        for _ in 0..12 {
            let t0 = uniform(-1.0, 0.5);
            let curve = twisted_cubic(t0, t0 + uniform(0.3, 1.2));
            let near = uniform(0.002, 0.2);
            let (v0, v1) = if uniform(0.0, 1.0) < 0.5 {
                (near, near + uniform(0.3, 2.0))
            } else {
                (-near - uniform(0.3, 2.0), -near)
            };
            let surface = tangent_surface(&curve, v0, v1);
            let tol = 10f64.powf(uniform(-3.5, -1.5));
            let fit = approximate(&surface, tol, Rule::MinimalVertexDistance, 100_000)
                .unwrap_or_else(|e| panic!("t0 {t0}, v [{v0}, {v1}], tol {tol:e}: {e}"));
            assert!(
                fit.vertex_clearance >= -super::super::region::BOUNDARY_MARGIN,
                "v [{v0}, {v1}]: {}",
                fit.vertex_clearance
            );
            worst = worst.min(fit.vertex_clearance);
        }
        println!("12 random tangent surfaces: smallest vertex clearance {worst:.3e}");
    }

    /// Figs. 11–12: the vertex polygon of the fit approximates the line of regression,
    /// which the fit never uses. For the tangent surfaces of the twisted cubic (general
    /// case) and of a helix (constant slope) at decreasing tolerances: the largest distance
    /// from a vertex to the curve and from the curve (between the first and the last
    /// vertex's nearest parameters) to the polygon, against the largest ruling spacing h.
    #[test]
    fn the_vertex_polygon_approaches_the_line_of_regression() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.5,
            domain: (0.0, 4.0),
        };
        let cubic = twisted_cubic(-0.5, 1.0);
        let curves: [(&str, &dyn crate::curve::ParametricCurve); 2] =
            [("twisted cubic", &cubic), ("helix", &helix)];
        for (name, curve) in curves {
            let surface = tangent_surface(curve, 0.5, 1.5);
            let (lo, hi) = curve.domain();
            let dense: Vec<(f64, DVec3)> = (0..=20_000)
                .map(|k| {
                    let t = lo + (hi - lo) * k as f64 / 20_000.0;
                    (t, curve.point_derivative(t).unwrap().0)
                })
                .collect();
            let nearest = |v: DVec3| {
                dense
                    .iter()
                    .map(|&(t, x)| ((x - v).length(), t))
                    .min_by(|a, b| a.0.total_cmp(&b.0))
                    .unwrap()
            };
            let mut rows = Vec::new();
            for tol in [1e-2, 1e-3, 1e-4, 1e-5] {
                let fit = approximate(&surface, tol, Rule::MinimalVertexDistance, 100_000).unwrap();
                let vertices: Vec<DVec3> = fit
                    .spline
                    .pieces()
                    .iter()
                    .filter_map(|p| p.vertex())
                    .collect();
                assert!(vertices.len() >= 4, "{name}: {} vertices", vertices.len());
                let to_curve = vertices.iter().map(|&v| nearest(v).0).fold(0.0, f64::max);
                let (t0, t1) = (nearest(vertices[0]).1, nearest(*vertices.last().unwrap()).1);
                let to_polygon = dense
                    .iter()
                    .filter(|(t, _)| (t0..=t1).contains(t))
                    .map(|&(_, x)| {
                        vertices
                            .windows(2)
                            .map(|w| {
                                let d = w[1] - w[0];
                                let s = ((x - w[0]).dot(d) / d.length_squared()).clamp(0.0, 1.0);
                                (x - w[0] - s * d).length()
                            })
                            .fold(f64::INFINITY, f64::min)
                    })
                    .fold(0.0, f64::max);
                let h = fit
                    .parameters
                    .windows(2)
                    .map(|w| w[1] - w[0])
                    .fold(0.0, f64::max);
                println!(
                    "{name}, tolerance {tol:.0e}: {} vertices, spacing {h:.3e}, vertices to the curve {to_curve:.3e}, \
                     curve to the polygon {to_polygon:.3e}",
                    vertices.len()
                );
                rows.push((h, to_curve.max(to_polygon)));
            }
            let (first, last) = (rows[0], rows[rows.len() - 1]);
            let rate = (first.1 / last.1).ln() / (first.0 / last.0).ln();
            println!("{name}: Hausdorff distance ~ h^{rate:.2}");
            assert!(rate > 1.5, "{name}: rate {rate}");
            assert!(
                rows.windows(2).all(|w| w[1].1 <= w[0].1 * (1.0 + 1e-9)),
                "{name}: {rows:?}"
            );
            assert!(last.1 < 1e-2, "{name}: {last:?}");
        }
    }

    /// A tolerance below the rounding of the surface's coordinates (1e-300 on a helix of
    /// radius 25) is refused naming `tolerance` in the caller's units and the size of the
    /// caller's coordinates, never a tolerance rescaled to the fit's own frame (about
    /// 1e-302) nor a failure of the cone construction at that tolerance.
    #[test]
    fn tolerances_below_rounding_are_refused_in_the_callers_units() {
        let helix = Helix {
            radius: 25.0,
            pitch: 0.5,
            domain: (0.0, 1.0),
        };
        let surface = tangent_surface(&helix, 0.1, 1.0);
        let e = approximate(&surface, 1e-300, Rule::MinimalVertexDistance, 100).unwrap_err();
        let message = e.message();
        assert!(e.is(crate::ErrorKind::InvalidInput), "{e}");
        assert!(message.starts_with("tolerance = 1.000e-300 "), "{message}");
        let largest: f64 = message
            .split("up to ")
            .nth(1)
            .and_then(|rest| rest.split(':').next())
            .and_then(|x| x.parse().ok())
            .unwrap_or_else(|| panic!("{message}"));
        assert!((25.0..=30.0).contains(&largest), "{message}");
        assert!(!message.contains("two different rulings"), "{message}");
    }

    /// Running out of pieces quotes `max_pieces` as given (3, not the 2 pieces of one pair).
    #[test]
    fn piece_limits_are_quoted_as_given() {
        let helix = Helix {
            radius: 25.0,
            pitch: 0.5,
            domain: (0.0, 6.0),
        };
        let surface = tangent_surface(&helix, 0.1, 1.0);
        for max_pieces in [3, 4, 7] {
            let e =
                approximate(&surface, 1e-9, Rule::MinimalVertexDistance, max_pieces).unwrap_err();
            let message = e.message();
            assert!(
                message.contains(&format!("max_pieces = {max_pieces} ")),
                "{message}"
            );
            assert!(message.contains("1.000e-9"), "{message}");
        }
    }

    /// A tolerance far beyond what `max_pieces` can reach on a smooth surface is refused
    /// with the estimate once the fit has used a sixteenth of the limit, not after the
    /// limit's worth of pieces; limits the fit reaches are never refused so. (The estimate
    /// assumes the fourth order where this surface shows about 3.3: it is low, about a
    /// third of the pieces needed.)
    #[test]
    fn piece_limits_out_of_reach_are_refused_early_with_an_estimate() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.5,
            domain: (0.0, 6.0),
        };
        let surface = tangent_surface(&helix, 0.1, 1.0);
        let fit = |tolerance, max_pieces| {
            approximate(&surface, tolerance, Rule::MinimalVertexDistance, max_pieces)
        };
        let needed = fit(1e-9, 100_000).unwrap().spline.pieces().len();
        let limit = needed / 64;
        let message = fit(1e-9, limit).unwrap_err().message();
        let estimate: f64 = message
            .split("about ")
            .nth(1)
            .and_then(|rest| rest.split(' ').next())
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("limit {limit}, no estimate: {message}"));
        assert!(
            estimate > ESTIMATE_MARGIN * limit as f64 && estimate < 4.0 * needed as f64,
            "{needed} pieces needed, {estimate} estimated"
        );
        for tolerance in [1e-3, 1e-5, 1e-7, 1e-9] {
            let needed = fit(tolerance, 100_000).unwrap().spline.pieces().len();
            assert!(fit(tolerance, needed).is_ok(), "tolerance {tolerance:e}");
        }
    }
}
