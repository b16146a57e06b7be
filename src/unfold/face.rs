//! One face unrolled: its surface recognized ([`super::kind`]), its development chosen
//! ([`super::develop`]), and its own boundary — the outer loop and the holes, edge by edge
//! — drawn in the plane: an edge whose development is a line or a circular arc (a ruling,
//! a parallel circle of a cone, a helix or a cross-section of a cylinder, any line or
//! circle of a plane) as that line or arc, every other as G1 biarcs within the flat
//! tolerance. Bend lines are the rulings where the pieces of a cone spline meet, clipped
//! to the face. The pattern is seen from the face's normal side: its outer loop runs
//! counter-clockwise, as it does about the normal on the face.

use super::develop::{Development, FlatPoint};
use super::kind::{recognize, Recognized, SurfaceKind};
use super::stretch::least_squares_stretch;
use crate::bezier::{PiecewiseCurve, PiecewiseSurface};
use crate::cone_spline::approximate::DEFAULT_MAX_PIECES;
use crate::cone_spline::developable::{max_scaled_curvature, RuledSurface};
use crate::error::{invalid, Error, Result};
use crate::model::planar::{biarcs, close_loop, line_or_arc};
use crate::model::{Brep, BrepSurface, FlatPattern, PatternEdge, Similarity};
use crate::sheet::part::check_fit_options;
use crate::sheet::rails::between_rails;
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// Samples per edge segment for the angles of the cut and for telling lines and arcs.
const EDGE_SAMPLES: usize = 32;
/// Largest distance (relative to the face's size) of an edge's development from a line or
/// arc for it to be drawn as one.
const EXACT: f64 = 1e-9;
/// Largest gap (relative) between consecutive edges of a loop.
const LOOP_GAP: f64 = 1e-7;
/// Relative step of the central differences for the tangents of developed edges.
const TANGENT_STEP: f64 = 1e-6;

/// How a face is unrolled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnfoldOptions {
    /// Largest distance of a cone spline from a face that is neither a plane, a circular
    /// cylinder nor a right cone, and largest |K|·size² … see [`Developability`]; caller's
    /// units.
    pub tolerance: f64,
    /// Largest distance of the outline's biarcs from the developed boundary; 0: the
    /// tolerance.
    pub flat_tolerance: f64,
    /// Most cone pieces for one face.
    pub max_pieces: usize,
}

impl UnfoldOptions {
    /// Options with the given tolerance, the flat tolerance equal to it and the default
    /// number of pieces.
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            flat_tolerance: 0.0,
            max_pieces: DEFAULT_MAX_PIECES,
        }
    }

    pub(super) fn check(&self) -> Result<()> {
        check_fit_options(self.tolerance, self.flat_tolerance, self.max_pieces)
    }

    pub(super) fn flat(&self) -> f64 {
        if self.flat_tolerance > 0.0 {
            self.flat_tolerance
        } else {
            self.tolerance
        }
    }
}

/// How developable a face is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Developability {
    /// The kind of its surface.
    pub kind: SurfaceKind,
    /// The largest |K|·size² sampled over its surface (K the Gaussian curvature, size the
    /// diagonal of the surface's bounding box): 0 for planes, cylinders and cones, round-off
    /// for exact developables.
    pub curvature: f64,
    /// For a face that is not developable, the largest relative change of length of an
    /// unrolling: measured on a least-squares flattening of a grid of triangles over its
    /// surface (edges and diagonals); 0 for developable faces.
    pub stretch: f64,
}

/// A face unrolled: its flat pattern, its report, and the isometry between flat and formed.
#[derive(Clone, Debug)]
pub struct UnfoldedFace {
    pattern: FlatPattern,
    report: Developability,
    fit_error: f64,
    development: Development,
    frame: Similarity,
    /// The pattern is the development mirrored (x ↦ −x), to be seen from the normal side.
    mirror: bool,
    /// Internal units.
    flat_tolerance: f64,
}

/// An edge use of a face's loop: the edge, the vertices it runs from and to, its curve in
/// the loop's direction (internal coordinates), and whether the face uses the edge twice
/// (a seam).
#[derive(Clone, Debug)]
pub(super) struct LoopUse {
    pub edge: usize,
    pub from: usize,
    pub to: usize,
    pub curve: PiecewiseCurve,
    pub seam: bool,
}

/// A loop of a face: its uses (degenerate edges left out) and whether it is the outer one.
#[derive(Clone, Debug)]
pub(super) struct FaceLoop {
    pub uses: Vec<LoopUse>,
    pub outer: bool,
}

pub(super) fn check_face(brep: &Brep, face: usize) -> Result<()> {
    let Some(f) = brep.faces.get(face) else {
        return invalid!("face = {face} is out of range ({} faces)", brep.faces.len());
    };
    let outer = f.bounds.iter().filter(|b| b.outer).count();
    if outer != 1 {
        return invalid!("face {face} has {outer} outer loops (one is needed)");
    }
    for (j, bound) in f.bounds.iter().enumerate() {
        if bound.uses.is_empty() {
            return invalid!("face {face}: loop {j} has no edges");
        }
        if let Some(u) = bound.uses.iter().find(|u| u.edge >= brep.edges.len()) {
            return invalid!(
                "face {face}: loop {j} uses edge {} of {}",
                u.edge,
                brep.edges.len()
            );
        }
    }
    Ok(())
}

pub(super) fn loops_of(brep: &Brep, face: usize, frame: Similarity) -> Result<Vec<FaceLoop>> {
    let f = &brep.faces[face];
    let mut count = vec![0usize; brep.edges.len()];
    for u in f.bounds.iter().flat_map(|b| &b.uses) {
        count[u.edge] += 1;
    }
    let mut loops = Vec::new();
    for (j, bound) in f.bounds.iter().enumerate() {
        let mut uses = Vec::new();
        for u in bound.uses.iter().filter(|u| !brep.edges[u.edge].degenerate) {
            let edge = &brep.edges[u.edge];
            let (used, from, to) = if u.forward {
                (edge.curve.clone(), edge.start, edge.end)
            } else {
                (edge.curve.reversed(), edge.end, edge.start)
            };
            uses.push(LoopUse {
                edge: u.edge,
                from,
                to,
                curve: frame.curve_to_internal(&used.to_piecewise()?)?,
                seam: count[u.edge] > 1,
            });
        }
        if uses.is_empty() {
            return invalid!("face {face}: loop {j} has only degenerate edges");
        }
        for i in 0..uses.len() {
            let c = &uses[i].curve;
            let end = c.eval(c.domain().1);
            let next = &uses[(i + 1) % uses.len()].curve;
            let gap = end.distance(next.eval(next.domain().0));
            if gap.is_nan() || gap > LOOP_GAP {
                return invalid!(
                    "face {face}: loop {j} is not closed: its edge use {i} ends {:.3e} from where the next starts",
                    frame.length(gap)
                );
            }
        }
        loops.push(FaceLoop {
            uses,
            outer: bound.outer,
        });
    }
    Ok(loops)
}

/// Parameters at which an edge is sampled: `EDGE_SAMPLES` per segment.
fn samples(curve: &PiecewiseCurve) -> Vec<f64> {
    let b = curve.breaks();
    let mut ts: Vec<f64> = b
        .windows(2)
        .flat_map(|w| {
            (0..EDGE_SAMPLES).map(move |j| w[0] + (w[1] - w[0]) * j as f64 / EDGE_SAMPLES as f64)
        })
        .collect();
    ts.push(*b.last().expect("a curve has breaks"));
    ts
}

/// The angle from which a round face is measured: a seam's, or the middle of the widest
/// angle its boundary leaves free.
fn cut_angle(loops: &[FaceLoop], origin: DVec3, axis: DVec3, x: DVec3, face: usize) -> Result<f64> {
    let y = axis.cross(x);
    let angle = |p: DVec3| Development::raw_angle(p, origin, x, y);
    let off_axis = |p: DVec3| (p - origin).cross(axis).length() > EXACT;
    for l in loops {
        if let Some(u) = l.uses.iter().find(|u| u.seam) {
            let c = &u.curve;
            let (lo, hi) = c.domain();
            if let Some(p) = [0.5, 0.25, 0.75]
                .map(|f| c.eval(lo + f * (hi - lo)))
                .into_iter()
                .find(|p| off_axis(*p))
            {
                return Ok(angle(p));
            }
        }
    }
    let mut angles: Vec<f64> = loops
        .iter()
        .flat_map(|l| l.uses.iter().map(|u| &u.curve))
        .flat_map(|c| samples(c).into_iter().map(|t| c.eval(t)))
        .filter(|p| off_axis(*p))
        .map(angle)
        .collect();
    angles.sort_by(f64::total_cmp);
    let (Some(&first), Some(&last)) = (angles.first(), angles.last()) else {
        return invalid!("face {face}: its boundary lies on the axis of its surface");
    };
    let (mut gap, mut cut) = (first + TAU - last, last + 0.5 * (first + TAU - last));
    for w in angles.windows(2) {
        if w[1] - w[0] > gap {
            gap = w[1] - w[0];
            cut = 0.5 * (w[0] + w[1]);
        }
    }
    let per_sample = TAU / angles.len() as f64;
    if gap <= 4.0 * per_sample {
        return invalid!(
            "face {face} goes all the way round its axis without a seam edge: it cannot be cut open"
        );
    }
    Ok(cut)
}

/// A use's developed curve: flat points with the cut resolved towards `near` (the flat
/// point a neighbour of the point has).
struct DevelopedUse<'a> {
    development: &'a Development,
    curve: &'a PiecewiseCurve,
    /// For a use lying on the cut: whether it is at the far end (2π).
    across: bool,
    /// The flat points at the use's samples, with the cut resolved.
    resolved: Vec<(f64, DVec2)>,
}

impl DevelopedUse<'_> {
    fn resolve(&self, t: f64, fp: FlatPoint) -> DVec2 {
        if !fp.on_cut {
            return fp.point;
        }
        let across = self.development.across_cut(fp.point);
        let near = self
            .resolved
            .iter()
            .min_by(|a, b| (a.0 - t).abs().total_cmp(&(b.0 - t).abs()));
        match near {
            Some(&(_, q)) if across.distance(q) < fp.point.distance(q) => across,
            Some(_) => fp.point,
            None if self.across => across,
            None => fp.point,
        }
    }

    fn at(&self, t: f64) -> DVec2 {
        self.resolve(t, self.development.flat(self.curve.eval(t)))
    }

    /// Point and derivative (central differences inside the domain).
    fn jet(&self, t: f64) -> (DVec2, DVec2) {
        let (lo, hi) = self.curve.domain();
        let h = TANGENT_STEP * (hi - lo);
        let (a, b) = ((t - h).max(lo), (t + h).min(hi));
        (self.at(t), (self.at(b) - self.at(a)) / (b - a))
    }
}

/// The flat points of a use's samples.
fn sampled_use(development: &Development, curve: &PiecewiseCurve) -> Vec<(f64, FlatPoint)> {
    samples(curve)
        .into_iter()
        .map(|t| (t, development.flat(curve.eval(t))))
        .collect()
}

/// The developed use `curve` from its sampled flat points: those off the cut, or (all on
/// the cut) its side by `before`.
fn develop_use<'a>(
    development: &'a Development,
    curve: &'a PiecewiseCurve,
    flat: &[(f64, FlatPoint)],
    before: Option<DVec2>,
) -> DevelopedUse<'a> {
    let resolved = flat
        .iter()
        .filter(|(_, f)| !f.on_cut)
        .map(|(t, f)| (*t, f.point))
        .collect::<Vec<_>>();
    let across = match (resolved.is_empty(), before) {
        (true, Some(b)) => {
            let start = flat[0].1.point;
            development.across_cut(start).distance(b) < start.distance(b)
        }
        _ => false,
    };
    DevelopedUse {
        development,
        curve,
        across,
        resolved,
    }
}

/// The flat edges of each use of a loop, in the loop's order (not yet closed up).
pub(super) fn developed_uses(
    development: &Development,
    l: &FaceLoop,
    tolerance: f64,
    scale: f64,
) -> Result<Vec<Vec<PatternEdge>>> {
    let exact = tolerance.min(EXACT);
    // Start at a use off the cut, so that a use on it has a neighbour before it.
    let n = l.uses.len();
    let sampled: Vec<Vec<(f64, FlatPoint)>> = l
        .uses
        .iter()
        .map(|u| sampled_use(development, &u.curve))
        .collect();
    let first = (0..n)
        .find(|&i| sampled[i].iter().any(|(_, f)| !f.on_cut))
        .unwrap_or(0);
    let mut before: Option<DVec2> = None;
    let mut groups = vec![Vec::new(); n];
    for k in 0..n {
        let i = (first + k) % n;
        let curve = &l.uses[i].curve;
        let used = develop_use(development, curve, &sampled[i], before);
        let (lo, hi) = curve.domain();
        // A closed edge (a circle) is drawn in two halves: an arc has two ends.
        let closed = curve.eval(lo).distance(curve.eval(hi)) <= LOOP_GAP;
        let mid = 0.5 * (lo + hi);
        let ranges: &[(f64, f64)] = if closed {
            &[(lo, mid), (mid, hi)]
        } else {
            &[(lo, hi)]
        };
        for &(a, b) in ranges {
            let m = EDGE_SAMPLES * curve.segments().len() / ranges.len();
            let points: Vec<DVec2> = (0..=m)
                .map(|j| used.at(a + (b - a) * j as f64 / m as f64))
                .collect();
            match line_or_arc(&points, exact) {
                Some(edge) => groups[i].push(edge),
                None => biarcs(&|t| used.jet(t), a, b, tolerance, scale, &mut groups[i])?,
            }
            before = points.last().copied();
        }
    }
    Ok(groups)
}

/// The flat edges of one loop, closed up.
fn flat_loop(
    development: &Development,
    l: &FaceLoop,
    tolerance: f64,
    scale: f64,
) -> Result<Vec<PatternEdge>> {
    let groups = developed_uses(development, l, tolerance, scale)?;
    Ok(close_loop(groups.concat(), 1.0))
}

/// The part of the segment from `a` to `b` inside the loops (even–odd rule along its line).
pub(super) fn clip_to_loops(a: DVec2, b: DVec2, loops: &[&[PatternEdge]]) -> Vec<PatternEdge> {
    let d = b - a;
    let mut crossings: Vec<f64> = Vec::new();
    for edge in loops.iter().flat_map(|l| l.iter()) {
        crossings.extend(line_crossings(a, d, edge));
    }
    crossings.sort_by(f64::total_cmp);
    crossings.dedup_by(|x, y| (*x - *y).abs() <= 1e-12);
    crossings
        .chunks_exact(2)
        .filter_map(|w| {
            let (s0, s1) = (w[0].max(0.0), w[1].min(1.0));
            (s1 - s0 > 1e-9).then(|| PatternEdge::Line {
                from: a + s0 * d,
                to: a + s1 * d,
            })
        })
        .collect()
}

/// Parameters s where the line a + s d crosses `edge`.
pub(super) fn line_crossings(a: DVec2, d: DVec2, edge: &PatternEdge) -> Vec<f64> {
    match *edge {
        PatternEdge::Line { from, to } => {
            let e = to - from;
            let den = d.perp_dot(e);
            if den == 0.0 {
                return vec![];
            }
            let s = (from - a).perp_dot(e) / den;
            let r = (from - a).perp_dot(d) / den;
            if (0.0..1.0).contains(&r) {
                vec![s]
            } else {
                vec![]
            }
        }
        PatternEdge::Arc {
            center,
            radius,
            from,
            sweep,
            ..
        } => {
            let f = a - center;
            let (qa, qb, qc) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - radius * radius);
            let disc = qb * qb - 4.0 * qa * qc;
            if disc < 0.0 || qa == 0.0 {
                return vec![];
            }
            let start = (from - center).to_angle();
            [-1.0, 1.0]
                .into_iter()
                .map(|sign| (-qb + sign * disc.sqrt()) / (2.0 * qa))
                .filter(|s| {
                    let p = a + *s * d - center;
                    let along = ((p.to_angle() - start) * sweep.signum()).rem_euclid(TAU);
                    along < sweep.abs()
                })
                .collect()
        }
    }
}

/// The edge mirrored in the y axis (x ↦ −x).
pub(super) fn mirrored(e: &PatternEdge) -> PatternEdge {
    e.mapped(|p| DVec2::new(-p.x, p.y), 1.0, true)
}

pub(super) fn loop_area(edges: &[PatternEdge]) -> f64 {
    FlatPattern {
        outline: edges.to_vec(),
        holes: vec![],
        bend_lines: vec![],
    }
    .area()
    .unwrap_or(0.0)
}

pub(super) fn reversed_loop(edges: &[PatternEdge]) -> Vec<PatternEdge> {
    edges.iter().rev().map(PatternEdge::reversed).collect()
}

/// The face's surface in internal coordinates, recognized.
pub(super) fn recognized_surface(
    surface: &BrepSurface,
    frame: Similarity,
) -> Result<(Recognized, f64)> {
    match surface {
        BrepSurface::Plane {
            origin,
            normal,
            x_axis,
        } => Ok((
            Recognized::Plane {
                origin: frame.to_internal(*origin),
                x: *x_axis,
                y: normal.cross(*x_axis),
            },
            0.0,
        )),
        BrepSurface::Nurbs(nurbs) => {
            let internal = internal_surface(&nurbs.to_piecewise()?, frame)?;
            let curvature = max_scaled_curvature(&internal);
            Ok((recognize(&internal, curvature)?, curvature))
        }
    }
}

pub(super) fn internal_surface(
    surface: &PiecewiseSurface,
    frame: Similarity,
) -> Result<PiecewiseSurface> {
    let mut s = surface.clone();
    for p in s.patches_mut() {
        p.map_homogeneous(|h| ((h.truncate() - frame.origin * h.w) / frame.scale).extend(h.w))?;
    }
    Ok(s)
}

/// The similarity taking the face to unit size: its surface's poles and its edges'.
pub(super) fn face_frame(brep: &Brep, face: usize) -> Similarity {
    let f = &brep.faces[face];
    let edges = f
        .bounds
        .iter()
        .flat_map(|b| &b.uses)
        .flat_map(|u| brep.edges[u.edge].curve.poles.iter().copied());
    match &f.surface {
        BrepSurface::Nurbs(s) => Similarity::fitting(edges.chain(s.poles.iter().copied())),
        BrepSurface::Plane { .. } => Similarity::fitting(edges),
    }
}

pub(super) fn check_finite(brep: &Brep, face: usize) -> Result<()> {
    let f = &brep.faces[face];
    for u in f.bounds.iter().flat_map(|b| &b.uses) {
        let c = &brep.edges[u.edge].curve;
        if !c.poles.iter().all(|p| p.is_finite()) {
            return invalid!("face {face}: edge {} has a non-finite pole", u.edge);
        }
    }
    match &f.surface {
        BrepSurface::Nurbs(s) if !s.poles.iter().all(|p| p.is_finite()) => {
            invalid!("face {face}: its surface has a non-finite pole")
        }
        BrepSurface::Plane {
            origin,
            normal,
            x_axis,
        } if !(origin.is_finite()
            && (normal.length() - 1.0).abs() < 1e-9
            && (x_axis.length() - 1.0).abs() < 1e-9
            && normal.dot(*x_axis).abs() < 1e-9) =>
        {
            invalid!(
                "face {face}: its plane needs a finite origin and orthonormal normal and x axis"
            )
        }
        _ => Ok(()),
    }
}

/// How developable face `face` of `brep` is (see [`Developability`]).
pub fn face_developability(brep: &Brep, face: usize) -> Result<Developability> {
    check_face(brep, face)?;
    check_finite(brep, face)?;
    let frame = face_frame(brep, face);
    let (shape, curvature) = recognized_surface(&brep.faces[face].surface, frame)?;
    report(&shape, curvature)
}

pub(super) fn report(shape: &Recognized, curvature: f64) -> Result<Developability> {
    let kind = shape.kind();
    let stretch = match shape {
        Recognized::Ruled { surface, .. } | Recognized::Other { surface, .. }
            if !kind.is_developable() =>
        {
            least_squares_stretch(surface)?
        }
        _ => 0.0,
    };
    Ok(Developability {
        kind,
        curvature,
        stretch,
    })
}

/// Face `face` of `brep` unrolled into the plane (see the module notes): planes, circular
/// cylinders and right cones exactly, every other developable through its cone spline
/// within `options.tolerance`; a face that is not developable is refused with its
/// curvature and the stretch an unrolling would need.
pub fn unfold_face(brep: &Brep, face: usize, options: &UnfoldOptions) -> Result<UnfoldedFace> {
    options.check()?;
    check_face(brep, face)?;
    check_finite(brep, face)?;
    let frame = face_frame(brep, face);
    let (shape, curvature) = recognized_surface(&brep.faces[face].surface, frame)?;
    let report = report(&shape, curvature)?;
    if !report.kind.is_developable() {
        return invalid!(
            "face {face} is not developable: |K|·size² reaches {:.3e} and an unrolling would stretch it by {:.3e} (relative)",
            report.curvature,
            report.stretch
        );
    }
    let loops = loops_of(brep, face, frame)?;
    let (development, fit_error) = face_development(&shape, &loops, options, frame, face)?;
    let flat_tolerance = options.flat() / frame.scale;
    let mut outline = Vec::new();
    let mut holes = Vec::new();
    for l in &loops {
        let edges = flat_loop(&development, l, flat_tolerance, frame.scale)
            .map_err(|e| e.context(format!("face {face}")))?;
        if l.outer {
            outline = edges;
        } else {
            holes.push(edges);
        }
    }
    let bend_lines = bend_lines(&development, &outline, &holes);
    let mirror = loop_area(&outline) < 0.0;
    let orient = |edges: Vec<PatternEdge>| -> Vec<PatternEdge> {
        if mirror {
            edges.iter().map(mirrored).collect()
        } else {
            edges
        }
    };
    let outline = orient(outline);
    let holes: Vec<Vec<PatternEdge>> = holes
        .into_iter()
        .map(orient)
        .map(|h| {
            if loop_area(&h) > 0.0 {
                reversed_loop(&h)
            } else {
                h
            }
        })
        .collect();
    let scale = |e: &PatternEdge| e.scaled(frame.scale);
    let pattern = FlatPattern {
        outline: outline.iter().map(scale).collect(),
        holes: holes
            .iter()
            .map(|h| h.iter().map(scale).collect())
            .collect(),
        bend_lines: orient(bend_lines).iter().map(scale).collect(),
    };
    Ok(UnfoldedFace {
        pattern,
        report,
        fit_error: fit_error * frame.scale,
        development,
        frame,
        mirror,
        flat_tolerance,
    })
}

/// The development of a recognized face (internal units) and the cone spline's fit error.
pub(super) fn face_development(
    shape: &Recognized,
    loops: &[FaceLoop],
    options: &UnfoldOptions,
    frame: Similarity,
    face: usize,
) -> Result<(Development, f64)> {
    let tolerance = options.tolerance / frame.scale;
    Ok(match shape {
        Recognized::Plane { .. } => (Development::analytic(shape, 0.0).expect("a plane"), 0.0),
        Recognized::Cylinder {
            origin, axis, x, ..
        } => {
            let cut = cut_angle(loops, *origin, *axis, *x, face)?;
            (Development::analytic(shape, cut).expect("a cylinder"), 0.0)
        }
        Recognized::Cone { apex, axis, x, .. } => {
            let cut = cut_angle(loops, *apex, *axis, *x, face)?;
            (Development::analytic(shape, cut).expect("a cone"), 0.0)
        }
        Recognized::Ruled { surface, .. } => {
            spline_development(surface, tolerance, options, frame, face)?
        }
        Recognized::Other { .. } => {
            return invalid!(
                "face {face}: a developable whose rulings are not along a parameter of its surface \
                 (degree 1 in u or in v) is not supported"
            )
        }
    })
}

fn spline_development(
    surface: &PiecewiseSurface,
    tolerance: f64,
    options: &UnfoldOptions,
    frame: Similarity,
    face: usize,
) -> Result<(Development, f64)> {
    let (u0, u1) = surface.domain_u();
    let (v0, v1) = surface.domain_v();
    let closed = surface.eval(u0, v0).distance(surface.eval(u0, v1)) <= EXACT
        && surface.eval(u1, v0).distance(surface.eval(u1, v1)) <= EXACT;
    if closed {
        return invalid!(
            "face {face}: a developable closed around (its first and last ruling the same) is \
             supported as a circular cylinder or a right cone only; split it into two faces"
        );
    }
    let ruled =
        RuledSurface::new(surface.clone()).map_err(|e| e.context(format!("face {face}")))?;
    let (part, fit) = between_rails(&ruled, tolerance, options.max_pieces, frame.scale)
        .map_err(|e| e.context(format!("face {face}")))?;
    let developed = part.spline.developed()?;
    Ok((
        Development::Spline {
            part,
            developed,
            layer: 0.0,
        },
        fit.deviation,
    ))
}

/// The rulings where the pieces of a cone spline development meet, clipped to the face.
pub(super) fn bend_lines(
    development: &Development,
    outline: &[PatternEdge],
    holes: &[Vec<PatternEdge>],
) -> Vec<PatternEdge> {
    let Development::Spline {
        part, developed, ..
    } = development
    else {
        return vec![];
    };
    let mut loops: Vec<&[PatternEdge]> = vec![outline];
    loops.extend(holes.iter().map(Vec::as_slice));
    let mut out = Vec::new();
    for k in 1..developed.pieces().len() {
        let el = developed.pieces()[k].element_at(0.0);
        let at = |side: usize| (el.point + part.trims[k][side].eval(0.0) * el.ruling).truncate();
        let (a, b) = (at(0), at(1));
        // A little beyond the rails: the face's boundary may run along them.
        let d = (b - a) * 1e-6;
        out.extend(clip_to_loops(a - d, b + d, &loops));
    }
    out
}

impl UnfoldedFace {
    /// The flat pattern: outline counter-clockwise, holes clockwise, the bend lines (caller's
    /// units, in the plane z = 0).
    pub fn pattern(&self) -> &FlatPattern {
        &self.pattern
    }

    /// How developable the face is.
    pub fn report(&self) -> &Developability {
        &self.report
    }

    /// Largest sampled distance of the cone spline from the face (0 where the face is
    /// unrolled exactly).
    pub fn fit_error(&self) -> f64 {
        self.fit_error
    }

    fn to_pattern(&self, q: DVec2) -> DVec2 {
        let q = if self.mirror {
            DVec2::new(-q.x, q.y)
        } else {
            q
        };
        q * self.frame.scale
    }

    /// The flat point of the face's point `p` (`name`: the caller's name for messages). A
    /// point on a cylinder's or cone's cut is put on the cut's side at angle 0.
    pub fn to_flat(&self, p: DVec3, name: &str) -> Result<DVec2> {
        if !p.is_finite() {
            return invalid!("{name} = {p} is not finite");
        }
        let q = self.development.flat(self.frame.to_internal(p)).point;
        Ok(self.to_pattern(q))
    }

    /// The formed point of the flat pattern's point `q`.
    pub fn to_formed(&self, q: DVec2, name: &str) -> Result<DVec3> {
        if !q.is_finite() {
            return invalid!("{name} = {q} is not finite");
        }
        let local = q / self.frame.scale;
        let local = if self.mirror {
            DVec2::new(-local.x, local.y)
        } else {
            local
        };
        match self.development.formed(local, self.flat_tolerance) {
            Some(x) => Ok(self.frame.to_user(x)),
            None => Err(Error::invalid_input(format!(
                "{name} = {q} lies outside the developed face"
            ))),
        }
    }
}
