//! One B-rep face per closed profile loop and spine piece where all of the loop's faces lie
//! on one analytic surface (a circle's arcs along a line: one cylinder; about an arc's
//! axis: one torus), as a kernel's own sweep makes it: the faces are joined across the
//! spine edges between them, which leave the model, and the spine edge at the loop's start
//! becomes the face's seam (used once each way). The joined NURBS view is the faces'
//! patches side by side along u, each face's curves moved along u by where it starts.

use super::*;
use crate::math::robust_length;
use crate::model::{AnalyticSurface, ROUNDING};

/// Relative distance within which two analytic surfaces are the same.
const SAME: f64 = 1e-9;

/// Joins the faces of each group (the lateral faces of one piece and one closed profile
/// loop, in profile order, with their surfaces) that lie on one analytic surface.
pub(super) fn join_analytic_loops(
    brep: &mut Brep,
    groups: &[(Vec<usize>, Vec<&PiecewiseSurface>)],
) {
    let mut dropped = vec![false; brep.edges.len()];
    let mut gone = vec![false; brep.faces.len()];
    for (faces, surfaces) in groups {
        if faces.len() < 2 || !on_one_surface(brep, faces) {
            continue;
        }
        let Some(joined) = joined_face(brep, faces, surfaces) else {
            continue;
        };
        for &f in &faces[..faces.len() - 1] {
            // The right side of each face but the last: a spine edge inside the surface.
            let right = brep.faces[f].bounds[0].uses[1].edge;
            dropped[right] = true;
        }
        brep.faces[faces[0]] = joined;
        faces[1..].iter().for_each(|&f| gone[f] = true);
    }
    if !gone.contains(&true) {
        return;
    }
    let mut index = vec![usize::MAX; brep.edges.len()];
    let mut kept = Vec::with_capacity(brep.edges.len());
    for (e, edge) in std::mem::take(&mut brep.edges).into_iter().enumerate() {
        if !dropped[e] {
            index[e] = kept.len();
            kept.push(edge);
        }
    }
    brep.edges = kept;
    let mut f = 0;
    brep.faces.retain(|_| {
        f += 1;
        !gone[f - 1]
    });
    for u in brep
        .faces
        .iter_mut()
        .flat_map(|face| face.bounds.iter_mut().flat_map(|b| b.uses.iter_mut()))
    {
        u.edge = index[u.edge];
    }
    settle_analytic(brep);
}

/// Whether the faces are analytic on one cylinder or torus, with one sense.
fn on_one_surface(brep: &Brep, faces: &[usize]) -> bool {
    let first = &brep.faces[faces[0]];
    let Some(a) = &first.analytic else {
        return false;
    };
    faces.iter().all(|&f| {
        let face = &brep.faces[f];
        face.same_sense == first.same_sense
            && face.analytic.as_ref().is_some_and(|b| {
                b.same_sense == a.same_sense && same_surface(&a.surface, &b.surface)
            })
    })
}

/// Two cylinders or two tori that are one surface (their placements differ by a turn
/// about the axis).
fn same_surface(a: &AnalyticSurface, b: &AnalyticSurface) -> bool {
    let ([pa, za, _], [pb, zb, _]) = (a.axes(), b.axes());
    let size = match (a, b) {
        (AnalyticSurface::Cylinder { .. }, AnalyticSurface::Cylinder { .. })
        | (AnalyticSurface::Torus { .. }, AnalyticSurface::Torus { .. }) => a.dimensions()[0],
        _ => return false,
    };
    let tolerance = SAME * size + ROUNDING * pa.abs().max_element();
    let offset = pb - pa;
    let along = match a {
        // A cylinder's origin may lie anywhere on its axis.
        AnalyticSurface::Cylinder { .. } => offset - za * offset.dot(za),
        _ => offset,
    };
    za.dot(zb) >= 1.0 - SAME
        && robust_length(along) <= tolerance
        && a.dimensions()
            .iter()
            .zip(b.dimensions())
            .all(|(x, y)| (x - y).abs() <= tolerance)
}

/// The faces joined: their patches side by side along u, the loop bottom edges, the seam
/// up at the end, the top edges back, the seam down at the start.
fn joined_face(brep: &Brep, faces: &[usize], surfaces: &[&PiecewiseSurface]) -> Option<BrepFace> {
    let mut patches = Vec::new();
    let mut breaks_u = vec![0.0];
    let mut offsets = Vec::with_capacity(faces.len());
    for s in surfaces {
        let (lo, _) = s.domain_u();
        let at = breaks_u[breaks_u.len() - 1];
        offsets.push(at - lo);
        breaks_u.extend(s.u_breaks()[1..].iter().map(|b| b - lo + at));
        patches.extend_from_slice(s.patches());
    }
    let joined = PiecewiseSurface::new(patches, breaks_u, surfaces[0].v_breaks().to_vec()).ok()?;
    let nurbs = NurbsSurface::from_piecewise(&joined).ok()?;
    let side = |k: usize, f: usize| -> Option<BrepUse> {
        let u = brep.faces[faces[f]].bounds.first()?.uses.get(k)?.clone();
        Some(shifted(u, offsets[f]))
    };
    let last = faces.len() - 1;
    let mut uses = Vec::with_capacity(2 * faces.len() + 2);
    for f in 0..faces.len() {
        uses.push(side(0, f)?);
    }
    uses.push(side(1, last)?);
    for f in (0..faces.len()).rev() {
        uses.push(side(2, f)?);
    }
    uses.push(side(3, 0)?);
    let first = &brep.faces[faces[0]];
    Some(BrepFace {
        surface: BrepSurface::Nurbs(nurbs),
        same_sense: first.same_sense,
        bounds: vec![BrepBound { uses, outer: true }],
        analytic: first.analytic.clone(),
    })
}

/// A use with its curve moved along u by `offset`.
fn shifted(mut u: BrepUse, offset: f64) -> BrepUse {
    u.pcurve = u.pcurve.map(|p| match p {
        PCurve::Line { origin, direction } => PCurve::Line {
            origin: (origin.0 + offset, origin.1),
            direction,
        },
        PCurve::Curve(c) => PCurve::Curve(c.moved_x(offset)),
    });
    u
}
