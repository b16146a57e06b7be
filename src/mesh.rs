//! Triangle meshes of surfaces, for display, OpenSCAD polyhedra and the discrete checks
//! (angle defect) of the test harness.
//!
//! The grid refines every Bézier patch uniformly in its own parameters, so patch
//! boundaries (rulings of cone splines, spine joints of sweeps) are always mesh lines and
//! vertices on shared boundaries are shared.

use crate::bezier::PiecewiseSurface;
use crate::error::{invalid, Result};
use glam::DVec3;

/// Largest vertex count of one tessellation (indices are 32-bit).
pub(crate) const MAX_MESH_POINTS: usize = 50_000_000;

/// An indexed triangle mesh on a (rows × columns) grid of surface points; point (i, j) is
/// at index `i * columns + j`, i along u.
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleMesh {
    /// rows · columns points, point (i, j) at `i * columns + j`.
    pub points: Vec<DVec3>,
    /// Counter-clockwise seen from the side s_u × s_v points to.
    pub triangles: Vec<[u32; 3]>,
    /// Number of grid rows (along u).
    pub rows: usize,
    /// Number of grid columns (along v).
    pub columns: usize,
}

/// Grid parameters: each interval of `breaks` split into `steps` equal parts, shared
/// breakpoints listed once.
pub fn grid_parameters(breaks: &[f64], steps: usize) -> Vec<f64> {
    let mut params = Vec::with_capacity((breaks.len() - 1) * steps + 1);
    for w in breaks.windows(2) {
        params.extend((0..steps).map(|k| crate::math::lerp(w[0], w[1], k as f64 / steps as f64)));
    }
    params.push(breaks[breaks.len() - 1]);
    params
}

/// Numbers of points and triangles of `tessellate(surface, u_steps, v_steps)`.
pub fn mesh_size(
    surface: &PiecewiseSurface,
    u_steps: usize,
    v_steps: usize,
) -> Result<(usize, usize)> {
    if u_steps == 0 || v_steps == 0 {
        return invalid!("u_steps and v_steps must be at least 1 (got {u_steps}, {v_steps})");
    }
    let rows = (surface.u_breaks().len() - 1)
        .checked_mul(u_steps)
        .and_then(|n| n.checked_add(1));
    let columns = (surface.v_breaks().len() - 1)
        .checked_mul(v_steps)
        .and_then(|n| n.checked_add(1));
    match (rows, columns) {
        (Some(r), Some(c)) if r.checked_mul(c).is_some_and(|n| n <= MAX_MESH_POINTS) => Ok((r * c, 2 * (r - 1) * (c - 1))),
        _ => invalid!("a tessellation with u_steps = {u_steps}, v_steps = {v_steps} exceeds {MAX_MESH_POINTS} points"),
    }
}

/// The surface sampled on the refined patch grid, two triangles per grid cell.
pub fn tessellate(
    surface: &PiecewiseSurface,
    u_steps: usize,
    v_steps: usize,
) -> Result<TriangleMesh> {
    mesh_size(surface, u_steps, v_steps)?;
    let us = grid_parameters(surface.u_breaks(), u_steps);
    let vs = grid_parameters(surface.v_breaks(), v_steps);
    let (rows, columns) = (us.len(), vs.len());
    let points = us
        .iter()
        .flat_map(|&u| vs.iter().map(move |&v| surface.eval(u, v)))
        .collect();
    let mut triangles = Vec::with_capacity(2 * (rows - 1) * (columns - 1));
    for i in 0..rows - 1 {
        for j in 0..columns - 1 {
            let index = |a: usize, b: usize| (a * columns + b) as u32;
            let (p00, p10, p11, p01) = (
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            );
            triangles.push([p00, p10, p11]);
            triangles.push([p00, p11, p01]);
        }
    }
    Ok(TriangleMesh {
        points,
        triangles,
        rows,
        columns,
    })
}

/// Unit normals s_u × s_v / |s_u × s_v| at the points of `tessellate(surface, u_steps,
/// v_steps)`, in the same order; zero where the surface is singular.
pub fn grid_normals(surface: &PiecewiseSurface, u_steps: usize, v_steps: usize) -> Vec<DVec3> {
    let vs = grid_parameters(surface.v_breaks(), v_steps);
    grid_parameters(surface.u_breaks(), u_steps)
        .iter()
        .flat_map(|&u| {
            vs.iter().map(move |&v| {
                let jet = surface.eval_jet(u, v);
                jet.du.cross(jet.dv).normalize_or_zero()
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::RationalBezierPatch;
    use glam::DVec4;

    fn unit_square_patches() -> PiecewiseSurface {
        let corners = |x0: f64, x1: f64| {
            vec![
                DVec4::new(x0, 0.0, 0.0, 1.0),
                DVec4::new(x0, 1.0, 0.0, 1.0),
                DVec4::new(x1, 0.0, 0.0, 1.0),
                DVec4::new(x1, 1.0, 0.0, 1.0),
            ]
        };
        let a = RationalBezierPatch::from_homogeneous(1, 1, corners(0.0, 0.5)).unwrap();
        let b = RationalBezierPatch::from_homogeneous(1, 1, corners(0.5, 1.0)).unwrap();
        PiecewiseSurface::new(vec![a, b], vec![0.0, 1.0, 2.0], vec![0.0, 1.0]).unwrap()
    }

    #[test]
    fn grid_shares_patch_boundaries_and_orients_triangles() {
        let s = unit_square_patches();
        let mesh = tessellate(&s, 3, 2).unwrap();
        assert_eq!((mesh.rows, mesh.columns), (7, 3));
        assert_eq!(mesh_size(&s, 3, 2).unwrap(), (21, 24));
        assert_eq!(mesh.triangles.len(), 24);
        // Row 3 is the shared boundary x = 0.5.
        assert!((mesh.points[3 * 3].x - 0.5).abs() < 1e-15);
        // s_u × s_v = +z: every triangle counter-clockwise seen from +z.
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|k| mesh.points[k as usize]);
            assert!((b - a).cross(c - a).z > 0.0);
        }
        let area: f64 = mesh
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|k| mesh.points[k as usize]);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum();
        assert!((area - 1.0).abs() < 1e-14);
        assert!(grid_normals(&s, 3, 2).iter().all(|n| *n == DVec3::Z));
        assert!(tessellate(&s, 0, 2).is_err());
        assert!(mesh_size(&s, usize::MAX, 2).is_err());
    }
}
