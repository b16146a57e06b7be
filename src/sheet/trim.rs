//! A sheet-metal part: a cone spline surface trimmed, on every piece, between two
//! boundary curves that run across its rulings — the part a user designed, bounded by
//! *their* edges, instead of a strip between two parallel circles.
//!
//! On a piece, the point at the arc parameter v ∈ [0, 1] and signed distance ρ along the
//! ruling from the reference point is L(v) + ρ e(v), with L and e the rational quadratic
//! paths of the reference point and of the ruling direction under the piece's motion (one
//! common weight w(v) = (1, cos φ/2, 1)). A boundary is a *trim* ρ(v) = a(v)/b(v), a and b
//! in Bernstein form; the boundary point has the homogeneous form
//!
//!   X(v) = b(v)·L_h(v) + a(v)·E_h(v),   weight b(v)·w(v),
//!
//! of degree 2 + deg a — for a distance fitted as a polynomial (b = 1) of degree q this is
//! the degree (1, 2 + q) of the ruling segments "from boundary to boundary" (the patch is
//! linear in u between the two boundary rows); a plane section is exact (a, b the plane
//! equation along L and e); a vertex is a constant ρ. Every trim is normalised to
//! b(0) = b(1) = 1, so that at the rulings where pieces meet all rows have weight 1: the
//! patches of one layer join in homogeneous coordinates (one NURBS per layer) and the
//! rulings are parametrised affinely (shared STEP edges with straight parameter lines).
//!
//! Offsets keep the trims: a layer at distance s along the normals is the offset cone
//! spline (same motions, reference points moved by s·n, [LP] "Introduction"), and its
//! boundary, the normal projection of the reference boundary, is the same ρ(v) from the
//! moved reference point. The cut faces of the solid (the laser's normal cut) are the
//! ruled strips X(v) + s·n(v) between two layers, again of the same form.

use crate::bezier::bernstein;
use crate::bezier::{
    NurbsSurface, PiecewiseCurve, PiecewiseSurface, RationalBezierCurve, RationalBezierPatch,
};
use crate::cone_spline::{ConePiece, ConeSpline, Motion};
use crate::error::{no_solution, Result};
pub(crate) use crate::model::Similarity;
use glam::{DVec3, DVec4};
use std::f64::consts::PI;

/// Largest angle of one piece (one degree-(1, ·) patch per piece keeps its weights ≥ 1/2).
const MAX_PIECE_ANGLE: f64 = 2.0 * PI / 3.0;

/// What a trim is, for the flat pattern (which boundaries develop into lines and arcs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TrimKind {
    /// A constant distance: a vertex on the reference layer, a parallel circle in general.
    Constant,
    /// The section with a plane (exact).
    Plane,
    /// A fitted distance polynomial.
    Fitted,
}

/// A boundary across a piece's rulings: ρ(v) = a(v)/b(v), b(0) = b(1) = 1.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Trim {
    pub a: Vec<f64>,
    pub b: Vec<f64>,
    pub kind: TrimKind,
}

impl Trim {
    pub(crate) fn constant(rho: f64) -> Self {
        Self {
            a: vec![rho],
            b: vec![1.0],
            kind: TrimKind::Constant,
        }
    }

    /// A polynomial distance (Bernstein coefficients on [0, 1]).
    pub(crate) fn polynomial(coefficients: Vec<f64>) -> Self {
        Self {
            a: coefficients,
            b: vec![1.0],
            kind: TrimKind::Fitted,
        }
    }

    /// The section of `piece` with the plane normal · x = offset; the rulings must cross
    /// it (normal · e ≠ 0 along the piece).
    pub(crate) fn plane(
        piece: &ConePiece,
        normal: DVec3,
        offset: f64,
        length: f64,
    ) -> Result<Self> {
        let (l, e) = generator(piece, length);
        let a: Vec<f64> = l
            .iter()
            .map(|h| offset * h.w - normal.dot(h.truncate()))
            .collect();
        let b: Vec<f64> = e.iter().map(|h| normal.dot(h.truncate())).collect();
        if b.iter().any(|&x| x <= 0.0) {
            return no_solution!("a ruling of the piece does not cross the plane of its boundary");
        }
        Ok(Self::normalised(a, b, TrimKind::Plane))
    }

    /// (g a, g b) with g linear and g(0) = 1/b(0), g(1) = 1/b(1).
    fn normalised(a: Vec<f64>, b: Vec<f64>, kind: TrimKind) -> Self {
        let g = [1.0 / b[0], 1.0 / b[b.len() - 1]];
        Self {
            a: bernstein::product(&a, &g, |x, y| x * y),
            b: bernstein::product(&b, &g, |x, y| x * y),
            kind,
        }
    }

    /// ρ(v).
    pub(crate) fn eval(&self, v: f64) -> f64 {
        bernstein::evaluate(&self.a, v) / bernstein::evaluate(&self.b, v)
    }

    /// ρ′(v).
    pub(crate) fn derivative(&self, v: f64) -> f64 {
        let (a, b) = (
            bernstein::evaluate_jet(&self.a, v),
            bernstein::evaluate_jet(&self.b, v),
        );
        (a.d1 * b.value - a.value * b.d1) / (b.value * b.value)
    }

    /// The degree of the numerator and denominator (written in the same degree).
    fn degree(&self) -> usize {
        self.a.len().max(self.b.len()) - 1
    }
}

/// The homogeneous paths of a piece's reference point, L_h, and of its ruling direction,
/// E_h (w = 0), as degree-2 Bézier control points; `length` is a length of the piece's
/// size, which keeps the difference of the two arcs accurate at any scale.
pub(crate) fn generator(piece: &ConePiece, length: f64) -> ([DVec4; 3], [DVec4; 3]) {
    let l = piece.arcs(0.0)[0];
    let far = piece.arcs(length)[0];
    let e = [0, 1, 2].map(|j| ((far[j] - l[j]) / length).truncate().extend(0.0));
    (l, e)
}

/// The piece with its reference point moved by `s` along the normal (the offset piece).
pub(crate) fn offset_piece(piece: &ConePiece, s: f64) -> ConePiece {
    let mut moved = *piece;
    moved.start.point += s * piece.start.normal();
    moved
}

/// `piece` cut into `m` equal parts (m ≥ 1).
pub(crate) fn split_piece(piece: &ConePiece, m: usize) -> Vec<ConePiece> {
    let motion = match piece.motion {
        Motion::Rotation {
            origin,
            axis,
            angle,
        } => Motion::Rotation {
            origin,
            axis,
            angle: angle / m as f64,
        },
        Motion::Translation(v) => Motion::Translation(v / m as f64),
    };
    (0..m)
        .map(|j| ConePiece {
            start: piece.element_at(j as f64 / m as f64),
            motion,
        })
        .collect()
}

/// The pieces, each longer than [`MAX_PIECE_ANGLE`] cut into equal parts.
pub(crate) fn split_long_pieces(pieces: &[ConePiece]) -> Vec<ConePiece> {
    pieces
        .iter()
        .flat_map(|p| {
            split_piece(
                p,
                (p.segment_angle() / MAX_PIECE_ANGLE).ceil().max(1.0) as usize,
            )
        })
        .collect()
}

/// The distance within which a side of a patch is a point (internal coordinates, where the
/// part is about 1 across): a boundary through a cone's apex, a crease's ruling. Such sides
/// come out of the construction up to some 1e-12 apart once rounding of the input is
/// amplified at an apex (the hopper 3e5 off the origin); a genuine side is orders of
/// magnitude longer, and one this short is within ten times the B-rep's own tolerance.
const COLLAPSED: f64 = 1e-9;

/// Which sides of a patch (internal coordinates) are a point, in the order of
/// `NurbsSurface::boundary_line`: v = 0, u = 1, v = 1, u = 0.
pub(crate) fn collapsed_sides(patch: &RationalBezierPatch) -> [bool; 4] {
    let (nu, nv) = (patch.degree_u() + 1, patch.degree_v() + 1);
    let h = patch.homogeneous();
    let at = |i: usize, j: usize| h[i * nv + j].truncate() / h[i * nv + j].w;
    fn point(mut side: impl Iterator<Item = DVec3>) -> bool {
        let first = side.next().expect("a side has poles");
        side.all(|p| p.distance(first) <= COLLAPSED)
    }
    [
        point((0..nu).map(|i| at(i, 0))),
        point((0..nv).map(|j| at(nu - 1, j))),
        point((0..nu).map(|i| at(i, nv - 1))),
        point((0..nv).map(|j| at(0, j))),
    ]
}

/// The trimmed cone spline of a part, in internal coordinates: pieces (each at most 120°)
/// and their two trims; `closed` when the last ruling is the first (a transition around).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TrimmedSpline {
    pub spline: ConeSpline,
    pub trims: Vec<[Trim; 2]>,
    pub closed: bool,
}

impl TrimmedSpline {
    pub(crate) fn pieces(&self) -> &[ConePiece] {
        self.spline.pieces()
    }

    /// The homogeneous boundary row of trim `side` of piece `k` on the layer at distance `s`
    /// along the normals (degree 2 + the trim's degree).
    pub(crate) fn row(&self, k: usize, side: usize, s: f64) -> Vec<DVec4> {
        let piece = offset_piece(&self.pieces()[k], s);
        let (l, e) = generator(&piece, 1.0);
        let trim = &self.trims[k][side];
        let degree = trim.degree();
        let (a, b) = (
            bernstein::elevate_to(&trim.a, degree),
            bernstein::elevate_to(&trim.b, degree),
        );
        let mut row = bernstein::product(&b, &l, |x, h: DVec4| h * x);
        bernstein::add_product(&a, &e, |x, h: DVec4| h * x, &mut row);
        row
    }

    /// The patch of piece `k`: a layer between its two trims, or a cut face along one trim
    /// between two layers. Both rows are written in the piece's largest row degree, so that
    /// the faces of a solid share their boundary curves in one representation.
    pub(crate) fn patch(&self, k: usize, face: Face) -> RationalBezierPatch {
        let rows = match face {
            Face::Layer(s) => [self.row(k, 0, s), self.row(k, 1, s)],
            Face::Cut { side, from, to } => [self.row(k, side, from), self.row(k, side, to)],
        };
        let degree = self.trims[k].iter().map(Trim::degree).max().unwrap_or(0) + 2;
        let [r0, r1] = rows.map(|r| bernstein::elevate_to(&r, degree));
        RationalBezierPatch::from_homogeneous(1, degree, [r0, r1].concat())
            .expect("trimmed rows have positive weights")
    }

    /// The end face at the first (`end = false`) or last ruling of an open part, between
    /// the layers `from` and `to`: u along the ruling, v across the thickness.
    pub(crate) fn end_patch(&self, end: bool, from: f64, to: f64) -> RationalBezierPatch {
        let k = if end { self.pieces().len() - 1 } else { 0 };
        let at = |side: usize, s: f64| {
            let row = self.row(k, side, s);
            if end {
                row[row.len() - 1]
            } else {
                row[0]
            }
        };
        RationalBezierPatch::from_homogeneous(
            1,
            1,
            vec![at(0, from), at(0, to), at(1, from), at(1, to)],
        )
        .expect("end faces have weight 1")
    }

    /// The layer at distance `s` as one surface: u ∈ [0, 1] from the first to the second
    /// trim, v ∈ [k, k + 1] on piece k.
    pub(crate) fn layer(&self, s: f64) -> Result<PiecewiseSurface> {
        let n = self.pieces().len();
        let patches: Vec<RationalBezierPatch> =
            (0..n).map(|k| self.patch(k, Face::Layer(s))).collect();
        let degree = patches.iter().map(|p| p.degree_v()).max().unwrap_or(2);
        let patches = patches
            .into_iter()
            .map(|p| {
                let r = degree - p.degree_v();
                p.elevated(0, r)
            })
            .collect();
        PiecewiseSurface::new(patches, vec![0.0, 1.0], (0..=n).map(|k| k as f64).collect())
    }

    /// The boundary curve `side` of the layer at distance `s`, v ∈ [k, k + 1] on piece k.
    pub(crate) fn boundary(&self, side: usize, s: f64) -> Result<PiecewiseCurve> {
        let n = self.pieces().len();
        let segments = (0..n)
            .map(|k| RationalBezierCurve::from_homogeneous(self.row(k, side, s)))
            .collect::<Result<Vec<_>>>()?;
        PiecewiseCurve::new(segments, (0..=n).map(|k| k as f64).collect())
    }
}

/// Which patch of a piece [`TrimmedSpline::patch`] gives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Face {
    /// A layer at a distance along the normals, between the two trims.
    Layer(f64),
    /// The cut face along trim `side` between the layers `from` (u = 0) and `to` (u = 1).
    Cut { side: usize, from: f64, to: f64 },
}

/// The arc parameter v of a piece's rational quadratic arc at the fraction `f` of its
/// angle φ, and back: the standard form from −φ/2 to φ/2 has tan(θ/2) = tan(φ/4)(2v − 1)
/// for the angle θ from the middle. Translations are linear (v = f).
pub(crate) fn fraction_of_parameter(angle: f64, v: f64) -> f64 {
    if angle == 0.0 {
        return v;
    }
    let q = (angle.abs() / 4.0).tan();
    0.5 + 2.0 * (q * (2.0 * v - 1.0)).atan() / angle.abs()
}

pub(crate) fn parameter_of_fraction(angle: f64, f: f64) -> f64 {
    if angle == 0.0 {
        return f;
    }
    let q = (angle.abs() / 4.0).tan();
    0.5 * (1.0 + ((f - 0.5) * angle.abs() / 2.0).tan() / q)
}

/// df/dv of [`fraction_of_parameter`].
pub(crate) fn fraction_rate(angle: f64, v: f64) -> f64 {
    if angle == 0.0 {
        return 1.0;
    }
    let q = (angle.abs() / 4.0).tan();
    let x = q * (2.0 * v - 1.0);
    4.0 * q / (angle.abs() * (1.0 + x * x))
}

/// Surface area of a patch by Gauss–Legendre quadrature (`n` × `n` nodes).
#[cfg(test)]
pub(crate) fn patch_area(patch: &RationalBezierPatch, n: usize) -> f64 {
    let g = crate::math::GaussLegendre::new(n);
    g.integrate(0.0, 1.0, |u| {
        g.integrate(0.0, 1.0, |v| {
            let j = patch.eval_jet(u, v);
            j.du.cross(j.dv).length()
        })
    })
}

/// One patch as a NURBS surface on [0, 1]².
pub(crate) fn patch_nurbs(patch: RationalBezierPatch) -> Result<NurbsSurface> {
    NurbsSurface::from_piecewise(&PiecewiseSurface::new(
        vec![patch],
        vec![0.0, 1.0],
        vec![0.0, 1.0],
    )?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cone_spline::Element;

    fn cone_piece() -> ConePiece {
        // x² + y² = z², vertex at the origin, from the ruling (1, 0, 1) a quarter turn.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let start = Element::new(
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(s, 0.0, s),
            DVec3::Y,
            "e",
        )
        .unwrap();
        ConePiece::cone(DVec3::ZERO, start, DVec3::new(0.0, s, s)).unwrap()
    }

    #[test]
    fn plane_trims_are_exact_and_rows_join_with_weight_one() {
        let piece = cone_piece();
        let trim = Trim::plane(&piece, DVec3::Z, 3.0, 1.0).unwrap();
        assert_eq!(trim.b[0], 1.0);
        assert!((trim.b[trim.b.len() - 1] - 1.0).abs() < 1e-15);
        let vertex = piece.start.parameter_of(DVec3::ZERO);
        let part = TrimmedSpline {
            spline: ConeSpline::new(vec![piece]).unwrap(),
            trims: vec![[Trim::constant(vertex), trim]],
            closed: false,
        };
        let top = RationalBezierCurve::from_homogeneous(part.row(0, 1, 0.0)).unwrap();
        for j in 0..=20 {
            let p = top.eval(j as f64 / 20.0);
            assert!(
                (p.z - 3.0).abs() < 1e-14 && (p.x.hypot(p.y) - 3.0).abs() < 1e-14,
                "{p}"
            );
        }
        let bottom = part.row(0, 0, 0.0);
        assert!(bottom.iter().all(|h| (h.truncate() / h.w).length() < 1e-15));
        let patch = part.patch(0, Face::Layer(0.0));
        assert_eq!(patch.degree_v(), 5);
        for (i, j) in [(0, 0), (0, 5), (1, 0), (1, 5)] {
            assert!((patch.at(i, j).w - 1.0).abs() < 1e-15);
        }
        // The patch lies on the cone, u along the rulings.
        for (u, v) in [(0.3, 0.2), (0.7, 0.9)] {
            let x = patch.eval(u, v);
            assert!((x.x.hypot(x.y) - x.z).abs() < 1e-14);
        }
        // Area of the cone x² + y² = z² up to z = 3 over a quarter turn: π·3·3√2 / 4.
        let exact = PI * 9.0 * 2f64.sqrt() / 4.0;
        assert!((patch_area(&patch, 24) - exact).abs() < 1e-12 * exact);
    }

    #[test]
    fn angle_fractions_and_arc_parameters_correspond() {
        for angle in [0.3, 1.0, 2.0, -1.5] {
            for v in [0.0, 0.1, 0.5, 0.77, 1.0] {
                let f = fraction_of_parameter(angle, v);
                assert!((parameter_of_fraction(angle, f) - v).abs() < 1e-15);
            }
        }
        // The arc point at v is the rotation by f·φ.
        let piece = cone_piece();
        let arc = RationalBezierCurve::from_homogeneous(piece.arcs(0.0)[0].to_vec()).unwrap();
        for v in [0.1, 0.4, 0.8] {
            let f = fraction_of_parameter(piece.segment_angle(), v);
            assert!(arc.eval(v).distance(piece.element_at(f).point) < 1e-15);
            let (h, angle) = (1e-6, piece.segment_angle());
            let rate = (fraction_of_parameter(angle, v + h) - fraction_of_parameter(angle, v - h))
                / (2.0 * h);
            assert!((rate - fraction_rate(piece.segment_angle(), v)).abs() < 1e-8);
        }
        let split = split_piece(&piece, 3);
        assert_eq!(split.len(), 3);
        assert!(split[2].end().point.distance(piece.end().point) < 1e-15);
    }
}
