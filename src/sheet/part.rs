//! [`SheetPart`]: a formed sheet-metal part — its designed surface (a trimmed cone
//! spline), the sheet's inner, neutral and outer layers, the closed solid between inner
//! and outer face with normal-cut edges (what a laser cut of the flat blank gives when
//! formed), the flat pattern of the neutral layer, and the maps between flat and formed.

use super::brep::{EdgeKey, PartFace};
use super::flat::{flat_layout, FlatLayout};
use super::marks::{flat_to_part, part_to_flat, part_to_surface, surface_to_part};
use super::rails::between_rails;
use super::thickness::{layers, Layer, Layers, Sheet};
use super::transition::{transition, TransitionFit};
use super::trim::{collapsed_sides, patch_nurbs, Face, Similarity, TrimmedSpline};
use crate::bezier::{PiecewiseCurve, PiecewiseSurface, RationalBezierCurve, RationalBezierPatch};
use crate::cone_spline::developable::{RuledSurface, TangentSurface};
use crate::cone_spline::{ConePiece, ConeSpline};
use crate::error::{invalid, Result};
use crate::math::in_caller_units;
use crate::model::{Brep, FlatPattern, PatternEdge};
use glam::{DVec2, DVec3};

/// Which boundary curve of a part: the first (u = 0: a transition's bottom, the first rail)
/// or the second.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The first boundary (u = 0).
    First,
    /// The second boundary (u = 1).
    Second,
}

impl Side {
    fn index(self) -> usize {
        match self {
            Side::First => 0,
            Side::Second => 1,
        }
    }
}

/// How a part is built and cut.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SheetOptions {
    /// Largest distance of the surface from the designed developable and of the part's
    /// edges from the input curves (caller's units).
    pub tolerance: f64,
    /// The sheet.
    pub sheet: Sheet,
    /// Largest distance of the flat outline's biarcs from the exact developed boundary;
    /// 0 means `tolerance`.
    pub flat_tolerance: f64,
    /// Most cone pieces.
    pub max_pieces: usize,
}

/// Checks the tolerances of a cone spline fit and its flat pattern: tolerance > 0,
/// flat_tolerance ≥ 0 (0: the tolerance), at least two pieces.
pub(crate) fn check_fit_options(
    tolerance: f64,
    flat_tolerance: f64,
    max_pieces: usize,
) -> Result<()> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return invalid!("tolerance = {tolerance} must be finite and positive");
    }
    if !(flat_tolerance.is_finite() && flat_tolerance >= 0.0) {
        return invalid!(
            "flat_tolerance = {flat_tolerance} must be finite and ≥ 0 (0: the tolerance)"
        );
    }
    if max_pieces < 2 {
        return invalid!("max_pieces = {max_pieces} must be at least 2");
    }
    Ok(())
}

impl SheetOptions {
    fn check(&self) -> Result<()> {
        check_fit_options(self.tolerance, self.flat_tolerance, self.max_pieces)?;
        Sheet::new(
            self.sheet.thickness,
            self.sheet.k_factor,
            self.sheet.reference,
        )
        .map(|_| ())
    }
}

/// What the construction measured (caller's units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PartReport {
    /// Largest sampled distance of the cone spline from the designed developable.
    pub deviation: f64,
    /// Largest sampled distance of the first and second boundary from the input's.
    pub edge_distance: [f64; 2],
    /// The tolerance the cone fit was run with.
    pub fit_tolerance: f64,
}

/// A sheet-metal part: see the module notes.
#[derive(Clone, Debug)]
pub struct SheetPart {
    part: TrimmedSpline,
    frame: Similarity,
    layers: Layers,
    sheet: Sheet,
    /// Internal units.
    flat_tolerance: f64,
    report: PartReport,
    /// The developed neutral layer (internal units).
    developed: ConeSpline,
}

impl SheetPart {
    /// The transition piece between two closed convex planar curves (see
    /// `src/sheet/transition.rs`): `bottom` is the first boundary.
    pub fn transition(
        bottom: &PiecewiseCurve,
        top: &PiecewiseCurve,
        options: &SheetOptions,
    ) -> Result<Self> {
        options.check()?;
        let poles = || {
            bottom
                .segments()
                .iter()
                .chain(top.segments())
                .flat_map(|s| s.poles())
        };
        check_resolution(options.tolerance, poles(), "curves")?;
        let frame = Similarity::fitting(poles());
        let (b, t) = (
            frame.curve_to_internal(bottom)?,
            frame.curve_to_internal(top)?,
        );
        let (part, fit) = transition(
            &b,
            &t,
            options.tolerance / frame.scale,
            options.max_pieces,
            &frame,
        )?;
        Self::new(part, frame, options, fit)
    }

    /// The part of a developable ruled surface of degree (1, n) — rulings along u — between
    /// its two rails (its boundaries u = u₀ and u = u₁), over its whole v domain: see
    /// `src/sheet/rails.rs`.
    pub fn between_rails(surface: &PiecewiseSurface, options: &SheetOptions) -> Result<Self> {
        options.check()?;
        let poles = || {
            surface
                .patches()
                .iter()
                .flat_map(|p| p.homogeneous().iter().map(|h| h.truncate() / h.w))
        };
        check_resolution(options.tolerance, poles(), "surface's")?;
        let frame = Similarity::fitting(poles());
        let patches = surface
            .patches()
            .iter()
            .map(|p| {
                RationalBezierPatch::from_homogeneous(
                    p.degree_u(),
                    p.degree_v(),
                    p.homogeneous()
                        .iter()
                        .map(|h| ((h.truncate() - frame.origin * h.w) / frame.scale).extend(h.w))
                        .collect(),
                )
            })
            .collect::<Result<Vec<_>>>()?;
        let internal = PiecewiseSurface::new(
            patches,
            surface.u_breaks().to_vec(),
            surface.v_breaks().to_vec(),
        )?;
        let ruled = RuledSurface::new(internal)?;
        let (part, fit) = between_rails(
            &ruled,
            options.tolerance / frame.scale,
            options.max_pieces,
            frame.scale,
        )?;
        Self::new(part, frame, options, fit)
    }

    /// The part of the tangent surface x(t) + v·x′(t)/|x′(t)| of a regular curve over its
    /// whole domain and v ∈ [v_min, v_max] (0 ∉ [v_min, v_max]), between the rails v = v_min
    /// and v = v_max: see `src/sheet/rails.rs`.
    pub fn tangent_surface(
        curve: &PiecewiseCurve,
        v_min: f64,
        v_max: f64,
        options: &SheetOptions,
    ) -> Result<Self> {
        options.check()?;
        // The distances checked in the caller's units (the messages quote them).
        TangentSurface::new(curve, v_min, v_max)?;
        // The frame of the region: the curve and its tangent lines out to the rails.
        let (lo, hi) = curve.domain();
        let points: Vec<DVec3> = (0..=64)
            .flat_map(|j| {
                let jet = curve.eval_jet(lo + (hi - lo) * j as f64 / 64.0);
                let e = jet.d1.normalize_or_zero();
                [jet.point + v_min * e, jet.point + v_max * e]
            })
            .chain(curve.segments().iter().flat_map(|s| s.poles()))
            .collect();
        check_resolution(options.tolerance, points.iter().copied(), "part's")?;
        let frame = Similarity::fitting(points);
        let internal = frame.curve_to_internal(curve)?;
        let tangent = TangentSurface::new(&internal, v_min / frame.scale, v_max / frame.scale)?;
        let (part, fit) = between_rails(
            &tangent,
            options.tolerance / frame.scale,
            options.max_pieces,
            frame.scale,
        )?;
        Self::new(part, frame, options, fit)
    }

    pub(crate) fn new(
        part: TrimmedSpline,
        frame: Similarity,
        options: &SheetOptions,
        fit: TransitionFit,
    ) -> Result<Self> {
        let layers = layers(&part, &options.sheet, frame.scale)?;
        let developed = part
            .spline
            .offset(layers.offset(Layer::Neutral))?
            .developed()?;
        let flat = if options.flat_tolerance > 0.0 {
            options.flat_tolerance
        } else {
            options.tolerance
        };
        Ok(Self {
            report: PartReport {
                deviation: fit.deviation * frame.scale,
                edge_distance: fit.edge_distance.map(|d| d * frame.scale),
                fit_tolerance: fit.fit_tolerance * frame.scale,
            },
            part,
            frame,
            layers,
            sheet: options.sheet,
            flat_tolerance: flat / frame.scale,
            developed,
        })
    }

    /// What the construction measured and chose.
    pub fn report(&self) -> &PartReport {
        &self.report
    }

    /// The sheet: thickness, K-factor, reference face.
    pub fn sheet(&self) -> &Sheet {
        &self.sheet
    }

    /// Whether the part closes on itself (a transition around).
    pub fn is_closed(&self) -> bool {
        self.part.closed
    }

    /// Number of cone, cylinder and plane pieces.
    pub fn piece_count(&self) -> usize {
        self.part.pieces().len()
    }

    /// The cone spline of the designed surface, in the caller's coordinates.
    pub fn cone_spline(&self) -> Result<ConeSpline> {
        ConeSpline::new(
            self.part
                .pieces()
                .iter()
                .map(|p| user_piece(p, &self.frame))
                .collect(),
        )
    }

    /// Distance of `layer` from the designed surface along the unit normal from the concave
    /// to the convex side (caller's units).
    pub fn layer_distance(&self, layer: Layer) -> f64 {
        self.layers.offset(layer) * self.layers.sign * self.frame.scale
    }

    /// The smallest bend radius of the designed surface over the part (caller's units; 0 at
    /// a vertex on its edge or at a crease).
    pub fn bend_radius(&self) -> f64 {
        self.part
            .pieces()
            .iter()
            .zip(&self.part.trims)
            .filter(|(p, _)| super::thickness::bend_sign(p) != 0.0)
            .map(|(p, t)| super::thickness::bend_radius(p, t))
            .fold(f64::INFINITY, f64::min)
            * self.frame.scale
    }

    /// A layer as one surface: u ∈ [0, 1] from the first to the second boundary along the
    /// rulings, v ∈ [k, k + 1] on piece k; degree (1, ·), G1 across the rulings.
    pub fn surface(&self, layer: Layer) -> Result<PiecewiseSurface> {
        let surface = self.part.layer(self.layers.offset(layer))?;
        let patches = surface
            .patches()
            .iter()
            .map(|p| self.user_patch(p))
            .collect();
        PiecewiseSurface::new(
            patches,
            surface.u_breaks().to_vec(),
            surface.v_breaks().to_vec(),
        )
    }

    /// A boundary curve of a layer, v ∈ [k, k + 1] on piece k.
    pub fn boundary(&self, layer: Layer, side: Side) -> Result<PiecewiseCurve> {
        let curve = self
            .part
            .boundary(side.index(), self.layers.offset(layer))?;
        let segments = curve
            .segments()
            .iter()
            .map(|s| {
                RationalBezierCurve::from_homogeneous(
                    s.homogeneous()
                        .iter()
                        .map(|&h| self.frame.homogeneous_to_user(h))
                        .collect(),
                )
            })
            .collect::<Result<Vec<_>>>()?;
        PiecewiseCurve::new(segments, curve.breaks().to_vec())
    }

    /// The area of a layer (caller's units²), by 16-point Gauss–Legendre quadrature on
    /// every patch of the part's unit-size surface; refused when it is outside the range of
    /// f64.
    pub fn area(&self, layer: Layer) -> Result<f64> {
        let g = crate::math::GaussLegendre::new(16);
        let unit: f64 = self
            .part
            .layer(self.layers.offset(layer))?
            .patches()
            .iter()
            .map(|p| {
                g.integrate(0.0, 1.0, |u| {
                    g.integrate(0.0, 1.0, |v| {
                        let j = p.eval_jet(u, v);
                        j.du.cross(j.dv).length()
                    })
                })
            })
            .sum();
        in_caller_units(unit, self.frame.scale, 2, "area")
    }

    /// The length of a boundary curve of a layer, by 24-point Gauss–Legendre quadrature on
    /// every segment of the part's unit-size curve.
    pub fn boundary_length(&self, layer: Layer, side: Side) -> Result<f64> {
        let unit = self
            .part
            .boundary(side.index(), self.layers.offset(layer))?
            .arc_length();
        in_caller_units(unit, self.frame.scale, 1, "boundary length")
    }

    fn user_patch(&self, p: &RationalBezierPatch) -> RationalBezierPatch {
        RationalBezierPatch::from_homogeneous(
            p.degree_u(),
            p.degree_v(),
            p.homogeneous()
                .iter()
                .map(|&h| self.frame.homogeneous_to_user(h))
                .collect(),
        )
        .expect("a similarity keeps the weights")
    }

    /// The closed solid between the inner and the outer face, in the caller's units, as a
    /// B-rep built from the construction (`brep` module notes): per piece the two layer
    /// faces and the cut faces along both boundaries (the normal cut of the flat blank),
    /// and for an open part the two end faces; every face's normal ∂u × ∂v points out of
    /// the solid.
    pub fn brep(&self) -> Result<Brep> {
        let (inner, outer) = (
            self.layers.offset(Layer::Inner),
            self.layers.offset(Layer::Outer),
        );
        let (lo, hi) = (inner.min(outer), inner.max(outer));
        let inner_layer = usize::from(inner > outer);
        let sign = self.layers.sign;
        let n = self.piece_count();
        let next = |k: usize| if self.part.closed { (k + 1) % n } else { k + 1 };
        let mut faces = Vec::with_capacity(4 * n + 2);
        for k in 0..n {
            // Layer faces: ∂u × ∂v = n; the solid's outward normal is −m on the inner face
            // and +m on the outer, m = sign·n.
            for (offset, layer, flip) in [
                (inner, inner_layer, sign > 0.0),
                (outer, 1 - inner_layer, sign < 0.0),
            ] {
                let patch = flip_u(self.part.patch(k, Face::Layer(offset)), flip);
                faces.push(self.part_face(&patch, layer_sides(k, next(k), layer, flip))?);
            }
            // Cut faces: ∂u × ∂v ∝ −(to − from)·e; outward −e on the first, +e on the second.
            for (side, from, to) in [(0, lo, hi), (1, hi, lo)] {
                let patch = self.part.patch(k, Face::Cut { side, from, to });
                faces.push(self.part_face(&patch, cut_sides(k, next(k), side))?);
            }
        }
        if !self.part.closed {
            // ∂u × ∂v = −(to − from)·p: outward −p at the first ruling, +p at the last.
            for (ruling, last, from, to) in [(0, false, lo, hi), (n, true, hi, lo)] {
                let patch = self.part.end_patch(last, from, to);
                faces.push(self.part_face(&patch, end_sides(ruling, last))?);
            }
        }
        Ok(super::brep::solid(&faces, next))
    }

    /// The part's solid as a STEP AP214 file (a `MANIFOLD_SOLID_BREP`), the product called
    /// `name`.
    pub fn to_step(&self, name: &str) -> Result<String> {
        crate::export::step::brep_to_step(&self.brep()?, name)
    }

    /// The part's solid in OpenCascade's own B-rep text (`BRepTools::Read`, FreeCAD's
    /// `Part.Shape.importBrepFromString`): the kernel builds it as it is, without sewing.
    pub fn to_occ_brep(&self) -> Result<String> {
        crate::export::occ_brep::brep_to_occ(&self.brep()?)
    }

    /// The part's solid in OpenCascade's binary B-rep (`BinTools::Read`, FreeCAD's
    /// `Part.Shape.importBinary`), which a kernel reads several times faster than the text.
    pub fn to_occ_binary(&self) -> Result<crate::export::occ_brep::OccBinary> {
        crate::export::occ_brep::brep_to_occ_binary(&self.brep()?)
    }

    /// A face of the solid from its patch (internal coordinates) and its named sides.
    fn part_face(
        &self,
        patch: &RationalBezierPatch,
        sides: [(EdgeKey, bool); 4],
    ) -> Result<PartFace> {
        Ok(PartFace {
            surface: patch_nurbs(self.user_patch(patch))?,
            sides,
            collapsed: collapsed_sides(patch),
        })
    }

    /// The flat pattern of the neutral layer for the cutter (caller's units): outline of
    /// lines and arcs, counter-clockwise, and the bend lines.
    pub fn flat_pattern(&self) -> Result<FlatPattern> {
        let flat = self.flat_layout()?.pattern();
        let scale = |e: &PatternEdge| e.scaled(self.frame.scale);
        Ok(FlatPattern {
            outline: flat.outline.iter().map(scale).collect(),
            holes: vec![],
            bend_lines: flat.bend_lines.iter().map(scale).collect(),
        })
    }

    /// The lengths of the flat pattern's first and second boundary (the outline without
    /// the end rulings; caller's units), for comparison with the formed neutral layer's.
    pub fn flat_boundary_lengths(&self) -> Result<[f64; 2]> {
        let layout = self.flat_layout()?;
        let sum = |edges: &[PatternEdge]| {
            edges.iter().map(PatternEdge::length).sum::<f64>() * self.frame.scale
        };
        Ok([sum(&layout.first), sum(&layout.second)])
    }

    /// The developed boundaries of the neutral layer, internal units.
    pub(crate) fn flat_layout(&self) -> Result<FlatLayout> {
        flat_layout(
            &self.part,
            self.layers.offset(Layer::Neutral),
            self.flat_tolerance,
            self.frame.scale,
        )
    }

    /// The scale from internal to the caller's units.
    #[cfg(test)]
    pub(crate) fn scale(&self) -> f64 {
        self.frame.scale
    }

    /// The point (and unit normal, from the concave to the convex side) on `layer` of the
    /// flat pattern's point `q`; `name` is the caller's name of `q` for the message when it
    /// lies outside the part (beyond the flat tolerance).
    pub fn flat_to_surface(&self, q: DVec2, layer: Layer, name: &str) -> Result<(DVec3, DVec3)> {
        if !q.is_finite() {
            return invalid!("{name} = {q} is not finite");
        }
        let local = q / self.frame.scale;
        let Some(p) = flat_to_part(
            &self.part,
            self.developed.pieces(),
            local,
            self.flat_tolerance,
        ) else {
            return invalid!("{name} = {q} lies outside the flat pattern of the part");
        };
        let (x, n) = part_to_surface(&self.part, p, self.layers.offset(layer));
        Ok((self.frame.to_user(x), n * self.layers.sign))
    }

    /// The flat pattern's point of the point `y` on `layer` (the point straight across the
    /// sheet on the neutral layer, developed); refused when `y` is farther than
    /// `max_distance` from the layer's part.
    pub fn surface_to_flat(
        &self,
        y: DVec3,
        layer: Layer,
        max_distance: f64,
        name: &str,
    ) -> Result<DVec2> {
        if !y.is_finite() {
            return invalid!("{name} = {y} is not finite");
        }
        let local = self.frame.to_internal(y);
        let (p, distance) = surface_to_part(&self.part, self.layers.offset(layer), local);
        let distance = distance * self.frame.scale;
        if distance.is_nan() || distance > max_distance {
            return invalid!(
                "{name} = {y} is {distance:.3e} from the part's {layer:?} layer (max_distance = {max_distance:.3e})"
            );
        }
        Ok(part_to_flat(self.developed.pieces(), p) * self.frame.scale)
    }
}

/// The sides of the layer face of piece `k` (first ruling `k`, last `next`) on `layer`, u
/// from the first boundary to the second, or back when `flip`.
fn layer_sides(k: usize, next: usize, layer: usize, flip: bool) -> [(EdgeKey, bool); 4] {
    let ruling = |ruling| (EdgeKey::Ruling { ruling, layer }, !flip);
    let row = |side| {
        (
            EdgeKey::Row {
                piece: k,
                side,
                layer,
            },
            true,
        )
    };
    let (first, second) = if flip {
        (row(0), row(1))
    } else {
        (row(1), row(0))
    };
    [ruling(k), first, ruling(next), second]
}

/// The sides of the cut face of piece `k` along boundary `side`: u from layer 0 to layer 1
/// on the first boundary, back on the second.
fn cut_sides(k: usize, next: usize, side: usize) -> [(EdgeKey, bool); 4] {
    let up = side == 0;
    let across = |ruling| (EdgeKey::Thickness { ruling, side }, up);
    let row = |layer| {
        (
            EdgeKey::Row {
                piece: k,
                side,
                layer,
            },
            true,
        )
    };
    [
        across(k),
        row(usize::from(up)),
        across(next),
        row(usize::from(!up)),
    ]
}

/// The sides of the end face at `ruling` (the first, or the `last`): u from the first
/// boundary to the second, v from layer 0 to layer 1 at the first ruling and back at the
/// last.
fn end_sides(ruling: usize, last: bool) -> [(EdgeKey, bool); 4] {
    let along = |layer| (EdgeKey::Ruling { ruling, layer }, true);
    let across = |side| (EdgeKey::Thickness { ruling, side }, !last);
    let (from, to) = if last { (1, 0) } else { (0, 1) };
    [along(from), across(1), along(to), across(0)]
}

/// `patch` with u reversed (its two rows swapped) when `flip`.
fn flip_u(patch: RationalBezierPatch, flip: bool) -> RationalBezierPatch {
    if !flip {
        return patch;
    }
    let n = patch.degree_v() + 1;
    let h = patch.homogeneous();
    RationalBezierPatch::from_homogeneous(1, patch.degree_v(), [&h[n..], &h[..n]].concat())
        .expect("the same points")
}

/// Refuses a tolerance below the rounding of the input's coordinates `points` (`whose` names
/// them in the message: "curves", …).
fn check_resolution(
    tolerance: f64,
    points: impl IntoIterator<Item = DVec3>,
    whose: &str,
) -> Result<()> {
    let largest = points
        .into_iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    let whose = if whose == "curves" {
        "the curves'".to_string()
    } else {
        format!("the {whose}")
    };
    crate::error::check_resolution(tolerance, largest, &whose)
}

/// A piece in the caller's coordinates.
fn user_piece(p: &ConePiece, frame: &Similarity) -> ConePiece {
    p.similar(glam::DMat3::IDENTITY, frame.scale, frame.origin)
}
