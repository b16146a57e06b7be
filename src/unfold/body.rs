//! A whole sheet-metal body unfolded: a closed solid of constant thickness made of planes
//! and bends of any developable kind, given as a B-rep.
//!
//! 1. Every face is recognized and developed ([`super::face`]); a face that is not
//!    developable is refused, naming it.
//! 2. The two skins: from a point inside each face, the nearest point of every other face
//!    straight across (along the face's normal) — its partner. Faces that are each other's
//!    partners are skins; their distance is the thickness, which must be the same, to the
//!    tolerance, at every point checked. The other faces are the sheet's cut edges.
//! 3. One side: the skins joined by shared edges to the largest skin face. Each of its
//!    faces is developed on the neutral layer — offset towards the other side by k·t where
//!    it is the bend's inner (concave) side, by (1 − k)·t where it is the outer ([LP]
//!    "Introduction": offsets of cone splines are cone splines; a cylinder's radius, a
//!    cone's apex move), the K-factor k one value or a table by inner bend radius over
//!    thickness.
//! 4. The faces' flat patterns, all seen from the side's outward normal, are placed by
//!    rigid motions so that shared edges coincide (breadth first from the largest face),
//!    and their edges that are not shared are chained by their vertices into the outline
//!    and the holes.
//! 5. Bend lines: the middle ruling of each cylinder or cone, the piece joints of a cone
//!    spline; up where the side is the bend's inner side (the flanges rise towards the
//!    viewer of the pattern), down otherwise. A pattern whose edges cross is refused, with
//!    the point.

use super::develop::Development;
use super::face::{
    check_face, check_finite, clip_to_loops, developed_uses, face_development, loop_area, loops_of,
    mirrored, recognized_surface, report, reversed_loop, FaceLoop, UnfoldOptions,
};
use super::kind::Recognized;
use crate::error::{invalid, Result};
use crate::model::planar::close_loop;
use crate::model::{Brep, BrepSurface, FlatPattern, PatternEdge, Similarity};
use glam::{DVec2, DVec3};
use std::collections::{HashMap, VecDeque};

/// Relative step of the differences for a face's normal in its development.
const NORMAL_STEP: f64 = 1e-6;
/// Largest sine of the angle between the line to a partner point and the normal of a plane,
/// cylinder or cone for the sheet to count as of constant thickness there.
const ACROSS: f64 = 1e-6;
/// Smallest cosine of that angle for a face to be looked at as the one across.
const FACING: f64 = 0.9;
/// Relative distance within which placed vertices and chained edges meet.
const MEET: f64 = 1e-7;

/// The K-factor: the neutral layer lies at k·t from the inner face of each bend.
#[derive(Clone, Debug, PartialEq)]
pub enum KFactor {
    /// One k for every bend, 0 ≤ k ≤ 1.
    Constant(f64),
    /// (inner bend radius / thickness, k) rows, increasing in the ratio; k interpolated
    /// linearly between rows and held beyond the first and last.
    Table(Vec<(f64, f64)>),
}

impl KFactor {
    fn check(&self) -> Result<()> {
        let rows: Vec<(f64, f64)> = match self {
            KFactor::Constant(k) => vec![(0.0, *k)],
            KFactor::Table(rows) => rows.clone(),
        };
        if rows.is_empty() {
            return invalid!("k_factor: the table has no rows");
        }
        for (i, &(ratio, k)) in rows.iter().enumerate() {
            if !(0.0..=1.0).contains(&k) {
                return invalid!("k_factor: row {i} has k = {k}, outside [0, 1]");
            }
            if !(ratio.is_finite() && ratio >= 0.0) {
                return invalid!("k_factor: row {i} has radius / thickness = {ratio}");
            }
            if i > 0 && ratio <= rows[i - 1].0 {
                return invalid!(
                    "k_factor: row {i}'s radius / thickness {ratio} does not increase"
                );
            }
        }
        Ok(())
    }

    /// k at the inner bend radius over thickness `ratio`.
    pub fn at(&self, ratio: f64) -> f64 {
        match self {
            KFactor::Constant(k) => *k,
            KFactor::Table(rows) => {
                let i = rows.partition_point(|r| r.0 <= ratio);
                match i {
                    0 => rows[0].1,
                    i if i == rows.len() => rows[i - 1].1,
                    i => {
                        let ((r0, k0), (r1, k1)) = (rows[i - 1], rows[i]);
                        k0 + (k1 - k0) * (ratio - r0) / (r1 - r0)
                    }
                }
            }
        }
    }
}

/// How a body is unfolded.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyOptions {
    /// The faces' tolerances (see [`UnfoldOptions`]), also the largest variation of the
    /// thickness.
    pub face: UnfoldOptions,
    /// The K-factor.
    pub k_factor: KFactor,
}

/// A bend of the flat pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bend {
    /// The bend line in the flat pattern.
    pub line: PatternEdge,
    /// Whether the bend rises towards the viewer of the pattern (its side is the inner one).
    pub up: bool,
    /// The face of the body it lies on.
    pub face: usize,
    /// The smallest inner bend radius of the face (caller's units).
    pub radius: f64,
    /// The K-factor used for it.
    pub k_factor: f64,
}

/// One face of the unfolded side, placed in the pattern.
#[derive(Clone, Debug)]
struct Placed {
    face: usize,
    development: Development,
    mirror: bool,
    /// Pattern point = rotation · (mirrored) development point + shift.
    rotation: DVec2,
    shift: DVec2,
    /// The face's edges in the development (not mirrored), per loop and use.
    groups: Vec<Vec<Vec<PatternEdge>>>,
    /// The face's loops in the development (mirrored), closed up.
    loops: Vec<Vec<PatternEdge>>,
}

/// Coordinates: `raw` of the development, `local` = raw mirrored where the face is seen
/// from behind, pattern = rotation · local + shift.
impl Placed {
    fn mirror(&self, q: DVec2) -> DVec2 {
        if self.mirror {
            DVec2::new(-q.x, q.y)
        } else {
            q
        }
    }

    /// The pattern point of a raw point.
    fn place(&self, raw: DVec2) -> DVec2 {
        self.rotation.rotate(self.mirror(raw)) + self.shift
    }

    /// The local point of a pattern point.
    fn local(&self, q: DVec2) -> DVec2 {
        DVec2::new(self.rotation.x, -self.rotation.y).rotate(q - self.shift)
    }

    fn place_edge(&self, e: &PatternEdge) -> PatternEdge {
        let e = if self.mirror { mirrored(e) } else { *e };
        rigid(&e, self.rotation, self.shift)
    }
}

/// The edge turned by `rotation` (a unit vector: cos, sin) and moved by `shift`.
fn rigid(e: &PatternEdge, rotation: DVec2, shift: DVec2) -> PatternEdge {
    e.mapped(|p| rotation.rotate(p) + shift, 1.0, false)
}

/// A sheet body unfolded: its flat pattern, its bends, its thickness, and the isometry
/// between the flat pattern and the neutral layer.
#[derive(Clone, Debug)]
pub struct UnfoldedBody {
    pattern: FlatPattern,
    bends: Vec<Bend>,
    thickness: f64,
    side: Vec<usize>,
    placed: Vec<Placed>,
    frame: Similarity,
    flat_tolerance: f64,
}

/// What a face of the body is, as far as the unfolding goes (internal units).
struct FaceData {
    shape: Recognized,
    loops: Vec<FaceLoop>,
    development: Development,
    /// The face's loops in its development, closed up (for inside tests).
    flat: Vec<Vec<PatternEdge>>,
    /// Points inside the face, with the face's normal there (from its loops' sense).
    samples: Vec<(DVec3, DVec3)>,
}

/// Whether `q` lies inside the loops (even–odd rule; the outline and its holes).
fn inside(q: DVec2, loops: &[Vec<PatternEdge>]) -> bool {
    let d = DVec2::new(0.8660254037844386, 0.5);
    let crossings = loops
        .iter()
        .flatten()
        .flat_map(|e| super::face::line_crossings(q, d, e))
        .filter(|s| *s > 0.0)
        .count();
    crossings % 2 == 1
}

/// Points inside a face's flat loops: a little inside from the middle of its longest
/// outline edges.
fn interior_points(loops: &[Vec<PatternEdge>], size: f64) -> Vec<DVec2> {
    let Some(outline) = loops.first() else {
        return vec![];
    };
    let ccw = loop_area(outline) > 0.0;
    let mut edges: Vec<&PatternEdge> = outline.iter().collect();
    edges.sort_by(|a, b| b.length().total_cmp(&a.length()));
    let mut out = Vec::new();
    for e in edges.iter().take(6) {
        let (a, b) = (e.start(), e.end());
        let mid = match **e {
            PatternEdge::Line { .. } => 0.5 * (a + b),
            PatternEdge::Arc {
                center,
                radius,
                from,
                sweep,
                ..
            } => center + radius * DVec2::from_angle((from - center).to_angle() + 0.5 * sweep),
        };
        let along = (b - a).normalize_or_zero();
        let left = DVec2::new(-along.y, along.x) * if ccw { 1.0 } else { -1.0 };
        for depth in [0.2, 0.1, 0.05, 1e-2, 1e-3] {
            let q = mid + left * depth * size;
            if inside(q, loops) {
                out.push(q);
                break;
            }
        }
        if out.len() == 3 {
            break;
        }
    }
    out
}

fn face_data(
    brep: &Brep,
    f: usize,
    options: &UnfoldOptions,
    frame: Similarity,
) -> Result<FaceData> {
    let (shape, curvature) = recognized_surface(&brep.faces[f].surface, frame)?;
    let r = report(&shape, curvature)?;
    if !r.kind.is_developable() {
        return invalid!(
            "face {f} is not developable: |K|·size² reaches {:.3e} and an unrolling would stretch it by {:.3e}",
            r.curvature,
            r.stretch
        );
    }
    let loops = loops_of(brep, f, frame)?;
    let (development, _) = face_development(&shape, &loops, options, frame, f)?;
    let tolerance = options.flat() / frame.scale;
    let mut flat = Vec::new();
    for l in &loops {
        let edges = close_loop(
            developed_uses(&development, l, tolerance, frame.scale)?.concat(),
            1.0,
        );
        if l.outer {
            flat.insert(0, edges);
        } else {
            flat.push(edges);
        }
    }
    // Seen from the face's normal side the outline runs counter-clockwise.
    let sense = if loop_area(&flat[0]) >= 0.0 {
        1.0
    } else {
        -1.0
    };
    let size = {
        let (lo, hi) = FlatPattern {
            outline: flat[0].clone(),
            holes: vec![],
            bend_lines: vec![],
        }
        .bounds();
        (hi - lo).length()
    };
    let mut samples = Vec::new();
    for q in interior_points(&flat, size) {
        let h = NORMAL_STEP * size.max(1e-300);
        let at = |d: DVec2| development.formed(q + d, f64::INFINITY);
        let (Some(p), Some(xp), Some(xm), Some(yp), Some(ym)) = (
            at(DVec2::ZERO),
            at(DVec2::X * h),
            at(-DVec2::X * h),
            at(DVec2::Y * h),
            at(-DVec2::Y * h),
        ) else {
            continue;
        };
        let n = (xp - xm).cross(yp - ym).normalize_or_zero() * sense;
        if n != DVec3::ZERO {
            samples.push((p, n));
        }
    }
    if samples.is_empty() {
        return invalid!("face {f}: no point inside it was found to measure the sheet from");
    }
    Ok(FaceData {
        shape,
        loops,
        development,
        flat,
        samples,
    })
}

/// The distance from `p` to its foot on face `g`, the direction to it and the sine of its
/// angle with `n`, if `g` lies across (the foot inside `g`, within 25° of ±`n`).
fn across(p: DVec3, n: DVec3, g: &FaceData, slack: f64) -> Option<(f64, DVec3, f64)> {
    let q = g.development.flat(p).point;
    if !inside(q, &g.flat) {
        // Within the slack of an edge counts as inside (a partner ending where this ends).
        let near = g.flat.iter().flatten().any(|e| e.distance(q) <= slack);
        if !near {
            return None;
        }
    }
    let foot = g.development.formed(q, f64::INFINITY)?;
    let d = foot - p;
    let l = d.length();
    let dir = d / l;
    (l > 0.0 && dir.dot(n).abs() >= FACING).then_some((l, dir, dir.cross(n).length()))
}

/// Unfolds a closed sheet body (see the module notes).
pub fn unfold_body(brep: &Brep, options: &BodyOptions) -> Result<UnfoldedBody> {
    options.face.check()?;
    options.k_factor.check()?;
    if !brep.closed {
        return invalid!("the body is an open shell: a sheet body must be a closed solid");
    }
    if brep.faces.len() < 4 {
        return invalid!(
            "the body has {} faces: a sheet has two skins and its edges",
            brep.faces.len()
        );
    }
    for f in 0..brep.faces.len() {
        check_face(brep, f)?;
        check_finite(brep, f)?;
    }
    check_manifold(brep)?;
    let frame = Similarity::fitting(brep.vertices.iter().copied().chain(
        brep.faces.iter().flat_map(|f| match &f.surface {
            BrepSurface::Nurbs(s) => s.poles.clone(),
            BrepSurface::Plane { .. } => vec![],
        }),
    ));
    let data = (0..brep.faces.len())
        .map(|f| face_data(brep, f, &options.face, frame))
        .collect::<Result<Vec<_>>>()?;
    let tolerance = options.face.tolerance / frame.scale;
    // Partners straight across, from the first sample of each face.
    let partner: Vec<Option<(usize, f64, DVec3)>> = data
        .iter()
        .enumerate()
        .map(|(f, d)| {
            let (p, n) = d.samples[0];
            data.iter()
                .enumerate()
                .filter(|(g, _)| *g != f)
                .filter_map(|(g, e)| across(p, n, e, tolerance).map(|(l, dir, _)| (g, l, dir)))
                .min_by(|a, b| a.1.total_cmp(&b.1))
        })
        .collect();
    let mutual: Vec<bool> = (0..data.len())
        .map(|f| matches!(partner[f], Some((g, _, _)) if matches!(partner[g], Some((h, _, _)) if h == f)))
        .collect();
    // The skins are the largest faces: the thickness is that of the largest pair straight
    // across (a slot's walls or the two side edges of a strip face each other too).
    let area = |f: usize| loop_area(&data[f].flat[0]).abs();
    let Some(largest) = (0..data.len())
        .filter(|&f| mutual[f])
        .max_by(|&a, &b| area(a).total_cmp(&area(b)))
    else {
        return invalid!(
            "no two faces of the body lie straight across from each other: it is not a sheet"
        );
    };
    let thickness = partner[largest].expect("a mutual partner").1;
    let skin: Vec<bool> = (0..data.len())
        .map(|f| mutual[f] && (partner[f].expect("mutual").1 - thickness).abs() <= tolerance)
        .collect();
    check_thickness(&data, &partner, &skin, thickness, tolerance, frame)?;
    let neighbours = face_neighbours(brep);
    let side = one_side(&neighbours, &data, &skin)?;
    let in_side: Vec<bool> = (0..data.len()).map(|f| side.contains(&f)).collect();
    for (f, &s) in skin.iter().enumerate() {
        if s && !in_side[f] && !in_side[partner[f].expect("mutual").0] {
            return invalid!(
                "face {f} is a skin of the sheet but neither it nor its partner (face {}) is joined to the side unfolded: the body falls apart into several sheets",
                partner[f].expect("mutual").0
            );
        }
    }
    let mut placed_faces = Vec::new();
    let mut bends_local = Vec::new();
    for &f in &side {
        let (neutral, bend) = neutral_layer(
            &data[f],
            partner[f].expect("a skin").2,
            thickness,
            &options.k_factor,
            f,
        )?;
        placed_faces.push((f, neutral));
        if let Some(b) = bend {
            bends_local.push(b);
        }
    }
    let flat_tolerance = options.face.flat() / frame.scale;
    let placed = place(
        brep,
        &neighbours,
        &data,
        &placed_faces,
        flat_tolerance,
        frame,
    )?;
    let (outline, holes) = assemble(&neighbours, &data, &placed, &in_side)?;
    let bends = bend_lines(&placed, &bends_local);
    check_overlap(&outline, &holes, frame)?;
    let scale = |e: &PatternEdge| e.scaled(frame.scale);
    Ok(UnfoldedBody {
        pattern: FlatPattern {
            outline: outline.iter().map(scale).collect(),
            holes: holes
                .iter()
                .map(|h| h.iter().map(scale).collect())
                .collect(),
            bend_lines: bends.iter().map(|b| scale(&b.line)).collect(),
        },
        bends: bends
            .into_iter()
            .map(|b| Bend {
                line: scale(&b.line),
                radius: b.radius * frame.scale,
                ..b
            })
            .collect(),
        thickness: thickness * frame.scale,
        side,
        placed,
        frame,
        flat_tolerance,
    })
}

/// Every edge used by exactly two faces, once each way.
fn check_manifold(brep: &Brep) -> Result<()> {
    let mut uses: Vec<Vec<(usize, bool)>> = vec![Vec::new(); brep.edges.len()];
    for (f, face) in brep.faces.iter().enumerate() {
        for u in face.bounds.iter().flat_map(|b| &b.uses) {
            uses[u.edge].push((f, u.forward));
        }
    }
    for (e, u) in uses.iter().enumerate() {
        if brep.edges[e].degenerate || u.is_empty() {
            continue;
        }
        if u.len() != 2 {
            return invalid!(
                "edge {e} is used by {} face sides: a sheet body is a closed manifold solid (each edge between two faces)",
                u.len()
            );
        }
    }
    Ok(())
}

/// Every sample of every skin face at the thickness from its partner, to the tolerance.
fn check_thickness(
    data: &[FaceData],
    partner: &[Option<(usize, f64, DVec3)>],
    skin: &[bool],
    thickness: f64,
    tolerance: f64,
    frame: Similarity,
) -> Result<()> {
    for (f, d) in data.iter().enumerate() {
        if !skin[f] {
            continue;
        }
        let g = partner[f].expect("a skin has a partner").0;
        // The normals of a face developed through its cone spline are the spline's, off the
        // face's by about the fit over a piece: there the distances at the samples decide.
        let angle_limit = match d.shape {
            Recognized::Ruled { .. } => 1.0,
            _ => ACROSS,
        };
        for &(p, n) in &d.samples {
            let measured = data
                .iter()
                .enumerate()
                .filter(|(h, _)| *h != f)
                .filter_map(|(h, e)| across(p, n, e, tolerance).map(|(l, _, sin)| (h, l, sin)))
                .min_by(|a, b| a.1.total_cmp(&b.1));
            match measured {
                Some((_, l, sin)) if (l - thickness).abs() <= tolerance && sin <= angle_limit => {}
                Some((h, l, sin)) => {
                    return invalid!(
                        "the thickness is not constant: face {f} at {} is {:.6} from face {h}, at {:.4}° to its normal (the sheet is {:.6} thick)",
                        frame.to_user(p),
                        l * frame.scale,
                        sin.asin().to_degrees(),
                        thickness * frame.scale
                    )
                }
                None => {
                    return invalid!(
                        "the thickness is not constant: face {f} at {} has no face across it (its partner is face {g}; the sheet is {:.6} thick)",
                        frame.to_user(p),
                        thickness * frame.scale
                    )
                }
            }
        }
    }
    Ok(())
}

/// The skin faces joined by shared edges to the largest skin face.
fn one_side(
    neighbours: &[Vec<(usize, usize)>],
    data: &[FaceData],
    skin: &[bool],
) -> Result<Vec<usize>> {
    let area = |f: usize| loop_area(&data[f].flat[0]).abs();
    let Some(start) = (0..data.len())
        .filter(|&f| skin[f])
        .max_by(|&a, &b| area(a).total_cmp(&area(b)))
    else {
        return invalid!("the body has no skin faces");
    };
    let mut seen = vec![false; data.len()];
    seen[start] = true;
    let mut order = vec![start];
    let mut queue = VecDeque::from([start]);
    while let Some(f) = queue.pop_front() {
        for &(g, _) in &neighbours[f] {
            if skin[g] && !seen[g] {
                seen[g] = true;
                order.push(g);
                queue.push_back(g);
            }
        }
    }
    Ok(order)
}

/// For each face, its neighbours across edges: (face, edge).
fn face_neighbours(brep: &Brep) -> Vec<Vec<(usize, usize)>> {
    let mut by_edge: HashMap<usize, Vec<usize>> = HashMap::new();
    for (f, face) in brep.faces.iter().enumerate() {
        for u in face.bounds.iter().flat_map(|b| &b.uses) {
            by_edge.entry(u.edge).or_default().push(f);
        }
    }
    let mut out = vec![Vec::new(); brep.faces.len()];
    let mut edges: Vec<_> = by_edge.into_iter().collect();
    edges.sort();
    for (e, faces) in edges {
        if let [a, b] = faces[..] {
            if a != b {
                out[a].push((b, e));
                out[b].push((a, e));
            }
        }
    }
    out
}

/// A bend before placing: the face, whether its side is the inner one, its inner radius
/// and the k used.
#[derive(Clone, Copy, Debug)]
struct LocalBend {
    face: usize,
    up: bool,
    radius: f64,
    k: f64,
}

/// The face's development on the neutral layer and, for a bend, what it is.
fn neutral_layer(
    data: &FaceData,
    toward: DVec3,
    thickness: f64,
    k_factor: &KFactor,
    f: usize,
) -> Result<(Development, Option<LocalBend>)> {
    let (p, _) = data.samples[0];
    let normal = data.development.normal(p);
    let along = toward.dot(normal).signum();
    // Radii of the face along its normal (away from the axis): the side is the bend's
    // inner one when the other side lies further out.
    let (inner, radius) = match &data.shape {
        // Flat regions do not stretch: their layer for marks is the sheet's middle.
        Recognized::Plane { .. } => {
            return Ok((data.development.offset(along * 0.5 * thickness)?, None))
        }
        Recognized::Cylinder { radius, .. } => {
            let inner = along > 0.0;
            (inner, if inner { *radius } else { radius - thickness })
        }
        Recognized::Cone { apex, sin, .. } => {
            // The smallest radius of curvature over the face's samples: ρ tan α.
            let inner = along > 0.0;
            let tan = sin / (1.0 - sin * sin).max(0.0).sqrt();
            let r = data
                .samples
                .iter()
                .map(|(q, _)| q.distance(*apex) * tan)
                .fold(f64::INFINITY, f64::min);
            (inner, if inner { r } else { (r - thickness).max(0.0) })
        }
        _ => {
            let (sign, radius) = spline_bend(&data.development, p)?;
            if sign == 0.0 {
                return Ok((data.development.offset(along * 0.5 * thickness)?, None));
            }
            let inner = along * sign > 0.0;
            (
                inner,
                if inner {
                    radius
                } else {
                    (radius - thickness).max(0.0)
                },
            )
        }
    };
    let k = k_factor.at(radius / thickness);
    if matches!(data.shape, Recognized::Ruled { .. })
        && k != 0.5
        && spline_bends_both_ways(&data.development)
    {
        return invalid!(
            "face {f} bends both ways: its neutral layer at k = {k} differs from bend to bend; split it at its inflection rulings or use k = 0.5"
        );
    }
    let s = if inner {
        k * thickness
    } else {
        (1.0 - k) * thickness
    };
    Ok((
        data.development.offset(along * s)?,
        Some(LocalBend {
            face: f,
            up: inner,
            radius,
            k,
        }),
    ))
}

/// How the cone spline piece at `p` bends (+1 convex towards its normal, −1 away, 0 flat)
/// and the face's smallest bend radius.
fn spline_bend(development: &Development, p: DVec3) -> Result<(f64, f64)> {
    let Development::Spline { part, .. } = development else {
        return Ok((0.0, f64::INFINITY));
    };
    let (at, _) = crate::sheet::marks::surface_to_part(part, 0.0, p);
    let signs: Vec<f64> = part
        .pieces()
        .iter()
        .map(crate::sheet::thickness::bend_sign)
        .collect();
    let sign = if signs[at.piece] != 0.0 {
        signs[at.piece]
    } else {
        signs.iter().copied().find(|s| *s != 0.0).unwrap_or(0.0)
    };
    let radius = part
        .pieces()
        .iter()
        .zip(&part.trims)
        .filter(|(piece, _)| crate::sheet::thickness::bend_sign(piece) != 0.0)
        .map(|(piece, trims)| crate::sheet::thickness::bend_radius(piece, trims))
        .fold(f64::INFINITY, f64::min);
    Ok((sign, radius))
}

fn spline_bends_both_ways(development: &Development) -> bool {
    match development {
        Development::Spline { part, .. } => {
            crate::sheet::thickness::bends_both_ways(part.pieces()).is_some()
        }
        _ => false,
    }
}

/// A face's neutral flat before placing: its loops' edges per use, its vertices' flat
/// points, whether it is seen from behind.
type LocalFlat = (Vec<Vec<Vec<PatternEdge>>>, HashMap<usize, DVec2>, bool);

/// The side's faces developed on the neutral layer and placed so that shared edges meet.
fn place(
    brep: &Brep,
    neighbours: &[Vec<(usize, usize)>],
    data: &[FaceData],
    faces: &[(usize, Development)],
    tolerance: f64,
    frame: Similarity,
) -> Result<Vec<Placed>> {
    let index: HashMap<usize, usize> = faces
        .iter()
        .enumerate()
        .map(|(i, (f, _))| (*f, i))
        .collect();
    // Each face's neutral flat: its loops per use, and its vertices' flat points.
    let mut local: Vec<LocalFlat> = Vec::new();
    for (f, development) in faces {
        let mut groups = Vec::new();
        let mut vertices = HashMap::new();
        for l in &data[*f].loops {
            let g = developed_uses(development, l, tolerance, frame.scale)?;
            for (u, edges) in l.uses.iter().zip(&g) {
                if let (Some(a), Some(b)) = (edges.first(), edges.last()) {
                    vertices.insert(u.from, a.start());
                    vertices.insert(u.to, b.end());
                }
            }
            groups.push(g);
        }
        // Seen from the face's outward normal: the outer loop counter-clockwise.
        let outer = data[*f]
            .loops
            .iter()
            .position(|l| l.outer)
            .expect("one outer loop");
        let mirror = loop_area(&groups[outer].concat()) < 0.0;
        local.push((groups, vertices, mirror));
    }
    let mut placed: Vec<Option<Placed>> = vec![None; faces.len()];
    let make = |i: usize, rotation: DVec2, shift: DVec2, local: &[LocalFlat]| {
        let (f, development) = &faces[i];
        let (groups, _, mirror) = &local[i];
        Placed {
            face: *f,
            development: development.clone(),
            mirror: *mirror,
            rotation,
            shift,
            groups: groups.clone(),
            loops: groups
                .iter()
                .map(|g| close_loop(g.concat(), 1.0))
                .map(|l| {
                    if *mirror {
                        l.iter().map(mirrored).collect()
                    } else {
                        l
                    }
                })
                .collect(),
        }
    };
    placed[0] = Some(make(0, DVec2::X, DVec2::ZERO, &local));
    let mut queue = VecDeque::from([0usize]);
    while let Some(i) = queue.pop_front() {
        let fi = faces[i].0;
        for &(g, e) in &neighbours[fi] {
            let Some(&j) = index.get(&g) else { continue };
            let edge = &brep.edges[e];
            let at = |k: usize, v: usize| -> Option<DVec2> {
                let (_, vertices, mirror) = &local[k];
                vertices
                    .get(&v)
                    .map(|q| if *mirror { DVec2::new(-q.x, q.y) } else { *q })
            };
            let here = placed[i].as_ref().expect("placed");
            let (Some(a0), Some(a1), Some(b0), Some(b1)) = (
                at(i, edge.start),
                at(i, edge.end),
                at(j, edge.start),
                at(j, edge.end),
            ) else {
                continue;
            };
            let (a0, a1) = (
                here.rotation.rotate(a0) + here.shift,
                here.rotation.rotate(a1) + here.shift,
            );
            if ((a1 - a0).length() - (b1 - b0).length()).abs() > 1e3 * tolerance.max(MEET) {
                return invalid!(
                    "faces {fi} and {g} develop their shared edge {e} to different lengths ({:.6} and {:.6})",
                    (a1 - a0).length() * frame.scale,
                    (b1 - b0).length() * frame.scale
                );
            }
            let rotation = DVec2::from_angle((a1 - a0).to_angle() - (b1 - b0).to_angle());
            let shift = a0 - rotation.rotate(b0);
            match &placed[j] {
                None => {
                    placed[j] = Some(make(j, rotation, shift, &local));
                    queue.push_back(j);
                }
                Some(p) => {
                    let gap = (p.rotation.rotate(b0) + p.shift)
                        .distance(a0)
                        .max((p.rotation.rotate(b1) + p.shift).distance(a1));
                    if gap > 1e3 * tolerance.max(MEET) {
                        return invalid!(
                            "the faces do not close up flat at edge {e} (between faces {fi} and {g}, {:.3e} apart): the sheet goes round and must be cut open",
                            gap * frame.scale
                        );
                    }
                }
            }
        }
    }
    Ok(placed.into_iter().flatten().collect())
}

/// The pattern's outline and holes: the placed faces' edges not shared with another face
/// of the side, chained by their vertices.
fn assemble(
    neighbours: &[Vec<(usize, usize)>],
    data: &[FaceData],
    placed: &[Placed],
    in_side: &[bool],
) -> Result<(Vec<PatternEdge>, Vec<Vec<PatternEdge>>)> {
    let mut chains: HashMap<usize, Vec<(usize, Vec<PatternEdge>)>> = HashMap::new();
    for p in placed {
        let shared: Vec<usize> = neighbours[p.face]
            .iter()
            .filter(|(g, _)| in_side[*g])
            .map(|(_, e)| *e)
            .collect();
        for (l, groups) in data[p.face].loops.iter().zip(&p.groups) {
            for (u, edges) in l.uses.iter().zip(groups) {
                if shared.contains(&u.edge) {
                    continue;
                }
                let edges: Vec<PatternEdge> = edges.iter().map(|e| p.place_edge(e)).collect();
                chains.entry(u.from).or_default().push((u.to, edges));
            }
        }
    }
    let mut loops: Vec<Vec<PatternEdge>> = Vec::new();
    while let Some(&start) = chains.keys().min() {
        let mut edges = Vec::new();
        let mut at = start;
        loop {
            let Some(list) = chains.get_mut(&at) else {
                return invalid!("the outline does not close at vertex {at}");
            };
            let (to, e) = list.pop().expect("a chain");
            if list.is_empty() {
                chains.remove(&at);
            }
            edges.extend(e);
            at = to;
            if at == start {
                break;
            }
        }
        loops.push(close_loop(edges, 1.0));
    }
    let outer = (0..loops.len())
        .max_by(|&a, &b| {
            loop_area(&loops[a])
                .abs()
                .total_cmp(&loop_area(&loops[b]).abs())
        })
        .expect("at least one loop");
    let mut outline = loops.swap_remove(outer);
    if loop_area(&outline) < 0.0 {
        outline = reversed_loop(&outline);
    }
    let holes = loops
        .into_iter()
        .map(|h| {
            if loop_area(&h) > 0.0 {
                reversed_loop(&h)
            } else {
                h
            }
        })
        .collect();
    Ok((outline, holes))
}

/// The bend lines: a cylinder's or cone's middle ruling, a cone spline's piece joints.
fn bend_lines(placed: &[Placed], bends: &[LocalBend]) -> Vec<Bend> {
    let mut out = Vec::new();
    for b in bends {
        let Some(p) = placed.iter().find(|p| p.face == b.face) else {
            continue;
        };
        let loops: Vec<&[PatternEdge]> = p.loops.iter().map(Vec::as_slice).collect();
        let lines = match &p.development {
            Development::Spline { .. } => {
                let raw: Vec<Vec<PatternEdge>> = p
                    .loops
                    .iter()
                    .map(|l| {
                        l.iter()
                            .map(|e| if p.mirror { mirrored(e) } else { *e })
                            .collect()
                    })
                    .collect();
                super::face::bend_lines(&p.development, &raw[0], &raw[1..])
                    .iter()
                    .map(|e| if p.mirror { mirrored(e) } else { *e })
                    .collect()
            }
            _ => middle_ruling(p, &loops),
        };
        for line in lines {
            out.push(Bend {
                line: rigid(&line, p.rotation, p.shift),
                up: b.up,
                face: b.face,
                radius: b.radius,
                k_factor: b.k,
            });
        }
    }
    out
}

/// The ruling in the middle of a cylinder or cone face, clipped to it (local, mirrored).
fn middle_ruling(p: &Placed, loops: &[&[PatternEdge]]) -> Vec<PatternEdge> {
    let points: Vec<DVec2> = loops
        .iter()
        .flat_map(|l| l.iter().flat_map(|e| [e.start(), e.end()]))
        .collect();
    let Development::Round { sin, .. } = p.development else {
        return vec![];
    };
    match sin {
        None => {
            let (lo, hi) = points
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), q| {
                    (lo.min(q.x), hi.max(q.x))
                });
            let (ylo, yhi) = points
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), q| {
                    (lo.min(q.y), hi.max(q.y))
                });
            let x = 0.5 * (lo + hi);
            let margin = yhi - ylo;
            clip_to_loops(
                DVec2::new(x, ylo - margin),
                DVec2::new(x, yhi + margin),
                loops,
            )
        }
        Some(_) => {
            let angles: Vec<f64> = points
                .iter()
                .filter(|q| q.length() > 0.0)
                .map(|q| q.to_angle())
                .collect();
            let (lo, hi) = angles
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), a| {
                    (lo.min(*a), hi.max(*a))
                });
            let far = points.iter().map(|q| q.length()).fold(0.0, f64::max);
            let d = DVec2::from_angle(0.5 * (lo + hi));
            clip_to_loops(DVec2::ZERO, d * 2.0 * far, loops)
        }
    }
}

/// Refuses a pattern whose edges cross (other than neighbours at their common point).
pub(super) fn check_overlap(
    outline: &[PatternEdge],
    holes: &[Vec<PatternEdge>],
    frame: Similarity,
) -> Result<()> {
    let mut all: Vec<(usize, usize, &PatternEdge)> =
        outline.iter().enumerate().map(|(i, e)| (0, i, e)).collect();
    for (h, hole) in holes.iter().enumerate() {
        all.extend(hole.iter().enumerate().map(|(i, e)| (h + 1, i, e)));
    }
    let len = |l: usize| {
        if l == 0 {
            outline.len()
        } else {
            holes[l - 1].len()
        }
    };
    for a in 0..all.len() {
        for b in a + 1..all.len() {
            let ((la, ia, ea), (lb, ib, eb)) = (all[a], all[b]);
            let neighbours = la == lb && ((ia + 1) % len(la) == ib || (ib + 1) % len(lb) == ia);
            if neighbours {
                continue;
            }
            if let Some(x) = crossing(ea, eb) {
                return invalid!(
                    "the flat pattern overlaps itself: its edges cross at ({:.6}, {:.6})",
                    x.x * frame.scale,
                    x.y * frame.scale
                );
            }
        }
    }
    Ok(())
}

/// A point where two edges cross, if they do.
fn crossing(a: &PatternEdge, b: &PatternEdge) -> Option<DVec2> {
    let (p, q) = (a.start(), a.end());
    // b against the segment's line, then on the segment, then a's own extent.
    let on_a = |x: DVec2| a.distance(x) <= 1e-12;
    match (a, b) {
        (PatternEdge::Line { .. }, _) => super::face::line_crossings(p, q - p, b)
            .into_iter()
            .filter(|s| *s > 1e-12 && *s < 1.0 - 1e-12)
            .map(|s| p + s * (q - p))
            .next(),
        (_, PatternEdge::Line { .. }) => crossing(b, a),
        (
            PatternEdge::Arc {
                center: c0,
                radius: r0,
                ..
            },
            PatternEdge::Arc {
                center: c1,
                radius: r1,
                ..
            },
        ) => {
            let d = c1 - c0;
            let l = d.length();
            if l == 0.0 || l > r0 + r1 || l < (r0 - r1).abs() {
                return None;
            }
            let x = (l * l + r0 * r0 - r1 * r1) / (2.0 * l);
            let h = (r0 * r0 - x * x).max(0.0).sqrt();
            let base = *c0 + d * (x / l);
            let perp = DVec2::new(-d.y, d.x) / l;
            [base + perp * h, base - perp * h].into_iter().find(|x| {
                on_a(*x)
                    && b.distance(*x) <= 1e-12
                    && [a.start(), a.end(), b.start(), b.end()]
                        .iter()
                        .all(|e| e.distance(*x) > 1e-9)
            })
        }
    }
}

impl UnfoldedBody {
    /// The flat pattern of the neutral layer: outline counter-clockwise, holes clockwise,
    /// bend lines (caller's units, plane z = 0), seen from the unfolded side's outside.
    pub fn pattern(&self) -> &FlatPattern {
        &self.pattern
    }

    /// The bends: line, up or down, face, inner radius, K-factor.
    pub fn bends(&self) -> &[Bend] {
        &self.bends
    }

    /// The sheet's thickness as measured (caller's units).
    pub fn thickness(&self) -> f64 {
        self.thickness
    }

    /// The faces of the side unfolded, in the order they were placed.
    pub fn side(&self) -> &[usize] {
        &self.side
    }

    /// The flat point of the body's point `p` (on either skin or inside the sheet): its
    /// foot on the nearest face of the unfolded side, developed on the neutral layer.
    pub fn to_flat(&self, p: DVec3, name: &str) -> Result<DVec2> {
        if !p.is_finite() {
            return invalid!("{name} = {p} is not finite");
        }
        let x = self.frame.to_internal(p);
        let best = self
            .placed
            .iter()
            .filter_map(|f| {
                let raw = f.development.flat(x).point;
                let foot = f.development.formed(raw, f64::INFINITY)?;
                let outside: f64 = if inside(f.mirror(raw), &f.loops) {
                    0.0
                } else {
                    1.0
                };
                Some((outside, foot.distance(x), f.place(raw)))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        match best {
            Some((_, _, q)) => Ok(q * self.frame.scale),
            None => invalid!("{name} = {p} is on no face of the unfolded side"),
        }
    }

    /// The point of the neutral layer at the flat pattern's point `q` (in flat regions,
    /// which do not stretch, the sheet's middle).
    pub fn to_formed(&self, q: DVec2, name: &str) -> Result<DVec3> {
        if !q.is_finite() {
            return invalid!("{name} = {q} is not finite");
        }
        let pattern = q / self.frame.scale;
        let slack = self.flat_tolerance;
        for f in &self.placed {
            let local = f.local(pattern);
            let near = inside(local, &f.loops)
                || f.loops.iter().flatten().any(|e| e.distance(local) <= slack);
            if near {
                if let Some(x) = f.development.formed(f.mirror(local), slack) {
                    return Ok(self.frame.to_user(x));
                }
            }
        }
        invalid!("{name} = {q} lies outside the flat pattern")
    }
}
