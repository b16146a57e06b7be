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
use crate::error::no_solution;
use crate::error::{invalid, Error, Result};
use crate::math::minimize_bracketed;

/// Rulings sampled per piece when fitting a strip into a box (then refined by Brent).
const BOX_SAMPLES: usize = 32;
/// Relative distance (of the strip's width) within which a vertex counts as on the strip:
/// its patches would degenerate there.
const VERTEX_MARGIN: f64 = 1e-9;
/// The distance, relative to the strip's width, by which [`ConeSpline::bounds_in_box`] keeps
/// its bounds away from a vertex: well beyond [`VERTEX_MARGIN`], so that the strip it
/// returns passes [`ConeSpline::surface`]'s check.
const BOX_VERTEX_MARGIN: f64 = 1e-6;

/// `b − a` for `a ≤ b` without overflow: the width of bounds that may each be near ±f64::MAX
/// (b − a of a region box of ±1e308 is infinite, and t_min with it), as half the width
/// doubled when it fits.
fn width(a: f64, b: f64) -> f64 {
    let half = 0.5 * b - 0.5 * a;
    if half <= 0.5 * f64::MAX {
        2.0 * half
    } else {
        f64::MAX
    }
}

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
    pub(super) fn check_bounds(&self, t0: f64, t1: f64) -> Result<()> {
        if !(t0.is_finite() && t1.is_finite()) || t0 >= t1 {
            return invalid!("t_min = {t0}, t_max = {t1} must be finite with t_min < t_max");
        }
        for (k, piece) in self.pieces().iter().enumerate() {
            if let Some(v) = piece.vertex() {
                let tv = piece.start.parameter_of(v);
                let margin = VERTEX_MARGIN * width(t0, t1);
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

    /// The widest bounds (t₀, t₁) whose strip has every ruling segment inside the box (the
    /// largest entry and the smallest exit parameter over all rulings) and no vertex
    /// (where vertices split that range, its widest vertex-free part).
    pub fn bounds_in_box(&self, region: &Region) -> Result<(f64, f64)> {
        let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
        for (k, piece) in self.pieces().iter().enumerate() {
            let (lo, hi) = piece_box_bounds(piece, region).ok_or_else(|| {
                Error::no_solution(format!("a ruling of piece {k} misses the region box"))
            })?;
            t0 = t0.max(lo);
            t1 = t1.min(hi);
        }
        if t0 >= t1 || !t0.is_finite() || !t1.is_finite() {
            return no_solution!(
                "no strip of the cone spline lies inside the region box (entry {t0:.6e}, exit {t1:.6e})"
            );
        }
        // Vertices inside split the strip: keep the widest part free of them.
        let mut cuts: Vec<f64> = self
            .pieces()
            .iter()
            .filter_map(|p| p.vertex().map(|v| p.start.parameter_of(v)))
            .filter(|&t| t > t0 && t < t1)
            .collect();
        cuts.sort_by(f64::total_cmp);
        let mut ends = vec![t0];
        ends.extend(cuts);
        ends.push(t1);
        let margin = BOX_VERTEX_MARGIN * width(t0, t1);
        let (a, b) = ends
            .windows(2)
            .map(|w| (w[0], w[1]))
            .max_by(|x, y| width(x.0, x.1).total_cmp(&width(y.0, y.1)))
            .expect("at least one interval");
        let (a, b) = (
            if a > t0 { a + margin } else { a },
            if b < t1 { b - margin } else { b },
        );
        if a >= b || a.is_nan() || b.is_nan() {
            return no_solution!(
                "the vertices of the cone spline leave no strip inside the region box"
            );
        }
        let representable = self
            .pieces()
            .iter()
            .all(|p| p.start.at(a).is_finite() && p.start.at(b).is_finite());
        if !representable {
            return no_solution!(
                "the region box is so large that its strip reaches points beyond the largest f64"
            );
        }
        Ok((a, b))
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
    // Four ulps inside: a point at the exact clip distance can round one ulp out of the box.
    let slack = 4.0 * f64::EPSILON * lo.abs().max(hi.abs());
    Some((lo + slack, hi - slack))
}

#[cfg(test)]
mod tests {
    use super::super::test_support::cubic_hermite;
    use super::*;
    use crate::bezier::NurbsSurface;
    use crate::frames::metrics::gaussian_curvature;
    use glam::DVec3;

    fn cubic_spline() -> ConeSpline {
        cubic_hermite(&[0.3, 0.5, 0.7, 0.9])
    }

    #[test]
    fn patches_are_developable_and_g1_across_rulings() {
        let spline = cubic_spline();
        let surface = spline.surface(-0.3, 0.3).unwrap();
        assert_eq!(surface.patches().len(), 6);
        for patch in surface.patches() {
            assert_eq!((patch.degree_u(), patch.degree_v()), (1, 2));
            for (u, v) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.8)] {
                let k = gaussian_curvature(&patch.eval_jet(u, v));
                assert!(k.abs() < 1e-9, "K = {k}");
            }
        }
        let normal = |p: &crate::bezier::RationalBezierPatch, u: f64, v: f64| {
            let j = p.eval_jet(u, v);
            j.du.cross(j.dv).normalize()
        };
        for w in surface.patches().windows(2) {
            for u in [0.0, 0.5, 1.0] {
                assert!((w[0].eval(u, 1.0) - w[1].eval(u, 0.0)).length() < 1e-13);
                let (a, b) = (normal(&w[0], u, 1.0), normal(&w[1], u, 0.0));
                let gap = crate::math::angle_between(a, b);
                assert!(gap < 1e-9, "normal jump {gap:e}");
            }
        }
        let nurbs = NurbsSurface::from_piecewise(&surface).unwrap();
        assert_eq!(
            (
                nurbs.degree_u,
                nurbs.degree_v,
                nurbs.pole_count_u,
                nurbs.pole_count_v
            ),
            (1, 2, 2, 13)
        );
        // The boundary arc spline is the surface's edge u = t_min.
        let edge = spline.boundary(-0.3).unwrap();
        for k in 0..=24 {
            let v = 6.0 * k as f64 / 24.0;
            assert!((edge.eval(v) - surface.eval(-0.3, v)).length() < 1e-13);
        }
    }

    #[test]
    fn strips_avoid_vertices_and_fit_boxes() {
        let spline = cubic_spline();
        let piece = spline.pieces()[1];
        let tv = piece.start.parameter_of(piece.vertex().unwrap());
        let err = spline.surface(tv - 0.1, tv + 0.1).unwrap_err();
        assert!(err.message().contains("vertex of piece"), "{err}");
        assert!(spline.surface(0.3, 0.3).is_err());
        let first = spline.first();
        let region = Region::new(
            first.point - DVec3::splat(1.0),
            first.point + DVec3::new(0.5, 1.5, 1.5),
        )
        .unwrap();
        let (t0, t1) = spline.bounds_in_box(&region).unwrap();
        assert!(t0 < t1);
        let surface = spline.surface(t0, t1).unwrap();
        let grow = Region::new(
            region.min - DVec3::splat(1e-9),
            region.max + DVec3::splat(1e-9),
        )
        .unwrap();
        for i in 0..=10 {
            for j in 0..=60 {
                let x = surface.eval(t0 + (t1 - t0) * i as f64 / 10.0, 6.0 * j as f64 / 60.0);
                assert!(grow.contains(x), "{x} leaves the box");
            }
        }
        let vertex = spline.pieces()[0].vertex().unwrap();
        let around = Region::new(vertex - DVec3::splat(0.5), vertex + DVec3::splat(0.5)).unwrap();
        let (a, b) = spline.bounds_in_box(&around).unwrap();
        assert!(spline.surface(a, b).is_ok());
        let tiny = Region::new(DVec3::splat(50.0), DVec3::splat(51.0)).unwrap();
        assert!(spline.bounds_in_box(&tiny).is_err());
    }

    /// Bounds in a region box of ±1e308 are finite and ordered: the strip's width, which
    /// overflows as b − a (t_min = +inf > t_max), is half the width doubled; a box of
    /// ±f64::MAX is refused.
    #[test]
    fn bounds_in_a_box_of_1e308_are_finite_and_ordered() {
        let spline = cubic_spline();
        for size in [1e300, 1e307, 1e308, f64::MAX] {
            let region = Region::new(DVec3::splat(-size), DVec3::splat(size)).unwrap();
            let (t0, t1) = match spline.bounds_in_box(&region) {
                Err(e) if size == f64::MAX => {
                    assert!(e.message().contains("largest f64"), "{e}");
                    continue;
                }
                other => other.unwrap(),
            };
            assert!(
                t0.is_finite() && t1.is_finite() && t0 < t1,
                "{size:e}: {t0:e} {t1:e}"
            );
            // The strip lies in the box and is free of vertices.
            spline.check_bounds(t0, t1).unwrap();
            for piece in spline.pieces() {
                for f in [0.0, 0.5, 1.0] {
                    let el = piece.element_at(f);
                    for t in [t0, t1] {
                        let x = el.at(t);
                        assert!(x.is_finite() && region.contains(x), "{size:e}: {x}");
                    }
                }
            }
        }
    }
}
