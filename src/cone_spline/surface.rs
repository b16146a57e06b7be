//! The point form of a cone spline (Fig. 1): every piece is an exact rational Bézier patch
//! of degree (1, 2) — a ruling segment in u times a rational quadratic parallel-circle arc
//! in v — between two signed distances t₀ < t₁ along the rulings. The patches form a 1 × n
//! grid, u ∈ [t₀, t₁] (u is the distance along the rulings), v ∈ [k, k + 1] on piece k; the
//! shared rulings are patch boundaries with end weights 1, so the grid assembles into one
//! NURBS surface, G1 across the rulings.
//!
//! The bounds may also come from a region box Ω: the widest parallel-circle strip whose
//! rulings stay inside the box.

use super::piece::ConePiece;
use super::region::Region;
use super::spline::ConeSpline;
use crate::bezier::{PiecewiseCurve, PiecewiseSurface, RationalBezierCurve};
use crate::error::{invalid, Error, Result};
use crate::math::minimize_bracketed;

/// Rulings sampled per piece when fitting a strip into a box (then refined by Brent).
const BOX_SAMPLES: usize = 32;

impl ConeSpline {
    /// The v breakpoints: piece k on [k, k + 1], split evenly into its patches.
    fn v_breaks(&self) -> Vec<f64> {
        let mut breaks = vec![0.0];
        for (k, piece) in self.pieces().iter().enumerate() {
            let m = piece.patch_count();
            breaks.extend((1..=m).map(|j| {
                if j == m {
                    (k + 1) as f64
                } else {
                    k as f64 + j as f64 / m as f64
                }
            }));
        }
        breaks
    }

    /// Checks bounds: finite, t₀ < t₁, and no vertex on a ruling segment of the strip.
    fn check_bounds(&self, t0: f64, t1: f64) -> Result<()> {
        if !(t0.is_finite() && t1.is_finite()) || t0 >= t1 {
            return invalid!("t_min = {t0}, t_max = {t1} must be finite with t_min < t_max");
        }
        for (k, piece) in self.pieces().iter().enumerate() {
            if let Some(v) = piece.vertex() {
                let tv = piece.start.parameter_of(v);
                let margin = 1e-9 * (t1 - t0);
                if tv > t0 - margin && tv < t1 + margin {
                    return invalid!(
                        "the strip t_min = {t0} .. t_max = {t1} contains the vertex of piece {k} (at t = {tv}); \
                         a cone spline surface must be free of singularities"
                    );
                }
            }
        }
        Ok(())
    }

    /// The surface between the signed distances `t0 < t1` along the rulings, measured from
    /// the reference points.
    pub fn surface(&self, t0: f64, t1: f64) -> Result<PiecewiseSurface> {
        self.check_bounds(t0, t1)?;
        let patches = self
            .pieces()
            .iter()
            .map(|p| p.patches(t0, t1))
            .collect::<Result<Vec<_>>>()?
            .concat();
        PiecewiseSurface::new(patches, vec![t0, t1], self.v_breaks())
    }

    /// The boundary arc spline at signed distance `t` along the rulings (parallel circles,
    /// straight on plane strips), with the surface's v parameter.
    pub fn boundary(&self, t: f64) -> Result<PiecewiseCurve> {
        if !t.is_finite() {
            return invalid!("t = {t} is not finite");
        }
        let segments = self
            .pieces()
            .iter()
            .flat_map(|p| p.arcs(t))
            .map(|points| RationalBezierCurve::from_homogeneous(points.to_vec()))
            .collect::<Result<Vec<_>>>()?;
        PiecewiseCurve::new(segments, self.v_breaks())
    }

    /// The widest bounds (t₀, t₁) whose strip has every ruling segment inside the box:
    /// the largest entry and the smallest exit parameter over all rulings.
    pub fn bounds_in_box(&self, region: &Region) -> Result<(f64, f64)> {
        let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
        for (k, piece) in self.pieces().iter().enumerate() {
            let (lo, hi) = piece_box_bounds(piece, region).ok_or_else(|| {
                Error::NoSolution(format!("a ruling of piece {k} misses the region box"))
            })?;
            t0 = t0.max(lo);
            t1 = t1.min(hi);
        }
        if t0 >= t1 {
            return Err(Error::NoSolution(format!(
                "no strip of the cone spline lies inside the region box (entry {t0} ≥ exit {t1})"
            )));
        }
        Ok((t0, t1))
    }
}

/// Largest entry and smallest exit of the piece's rulings through the box: sampled, then
/// the extreme sample refined by Brent's method between its neighbours.
fn piece_box_bounds(piece: &ConePiece, region: &Region) -> Option<(f64, f64)> {
    let clip = |f: f64| {
        let el = piece.element_at(f);
        region.clip_line(el.point, el.ruling)
    };
    let fractions: Vec<f64> = (0..=BOX_SAMPLES)
        .map(|j| j as f64 / BOX_SAMPLES as f64)
        .collect();
    let clips = fractions
        .iter()
        .map(|&f| clip(f))
        .collect::<Option<Vec<_>>>()?;
    let refine = |pick: &dyn Fn((f64, f64)) -> f64| {
        let best = (0..clips.len()).max_by(|&i, &j| pick(clips[i]).total_cmp(&pick(clips[j])))?;
        let (a, b) = (
            fractions[best.saturating_sub(1)],
            fractions[(best + 1).min(BOX_SAMPLES)],
        );
        let m = minimize_bracketed(|f| clip(f).map_or(f64::INFINITY, |c| -pick(c)), a, b, 1e-12);
        Some(pick(clips[best]).max(-m.value))
    };
    let lo = refine(&|c: (f64, f64)| c.0)?;
    let hi = -refine(&|c: (f64, f64)| -c.1)?;
    Some((lo, hi))
}
