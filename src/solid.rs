//! Closed, consistently oriented polygon meshes (solids) from surfaces, for OpenSCAD's
//! `polyhedron()`, STL and other formats that need a volume rather than a sheet.
//!
//! A surface bounds a solid in three ways:
//! * closed in u (a closed profile) and open in v: a tube — the seam is welded and both
//!   ends are capped with the profile polygon (planar: it lies in the normal plane);
//! * closed in u and v (a closed profile along a closed spine): welded twice, no caps;
//! * otherwise (a sheet, e.g. a developable strip): it is given a `thickness`, offset by
//!   ± thickness/2 along the unit normal, with side walls along its boundary.
//!
//! The mesh is the patch-grid tessellation of [`crate::mesh`], so shared vertices are
//! shared exactly. Faces are counter-clockwise seen from outside (outward normals); the
//! orientation is decided by the sign of the enclosed volume.

use crate::bezier::PiecewiseSurface;
use crate::error::{invalid, Result};
use crate::math::bounding_diagonal;
use crate::mesh::{grid_normals, tessellate, TriangleMesh};
use glam::DVec3;
use std::collections::HashSet;

/// Relative distance (to the bounding-box diagonal) below which the first and last grid
/// rows or columns coincide, making the surface closed in that direction.
const CLOSURE_TOLERANCE: f64 = 1e-9;

/// A closed polygon mesh; every face counter-clockwise seen from outside.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedMesh {
    /// The vertices.
    pub points: Vec<DVec3>,
    /// The faces as vertex indices, counter-clockwise from outside.
    pub faces: Vec<Vec<u32>>,
}

impl ClosedMesh {
    /// The enclosed volume (divergence theorem over fan-triangulated faces).
    pub fn volume(&self) -> f64 {
        let p = |k: u32| self.points[k as usize];
        self.faces
            .iter()
            .flat_map(|f| (1..f.len() - 1).map(move |k| (f[0], f[k], f[k + 1])))
            .map(|(a, b, c)| p(a).dot(p(b).cross(p(c))) / 6.0)
            .sum()
    }
}

/// Whether the tessellated surface is closed across its first/last row (u) and column (v).
fn closure(mesh: &TriangleMesh) -> (bool, bool) {
    let (rows, cols) = (mesh.rows, mesh.columns);
    let at = |i: usize, j: usize| mesh.points[i * cols + j];
    let tolerance = CLOSURE_TOLERANCE * bounding_diagonal(mesh.points.iter().copied());
    let closed_u = (0..cols).all(|j| at(0, j).distance(at(rows - 1, j)) <= tolerance);
    let closed_v = (0..rows).all(|i| at(i, 0).distance(at(i, cols - 1)) <= tolerance);
    (closed_u, closed_v)
}

/// The solid bounded by `surface` (see the module notes), tessellated with `u_steps` ×
/// `v_steps` cells per patch. `thickness` is needed, and only used, for a surface that is
/// not closed in u.
pub fn closed_mesh(
    surface: &PiecewiseSurface,
    u_steps: usize,
    v_steps: usize,
    thickness: Option<f64>,
) -> Result<ClosedMesh> {
    let mesh = tessellate(surface, u_steps, v_steps)?;
    let (closed_u, closed_v) = closure(&mesh);
    let solid = match (closed_u, thickness) {
        (true, _) => tube(&mesh, closed_v),
        (false, Some(h)) => thickened(surface, &mesh, closed_v, h, (u_steps, v_steps))?,
        (false, None) => {
            return invalid!(
                "the surface is open (its profile is not a closed curve): a solid needs a thickness"
            )
        }
    };
    Ok(outward(solid))
}

/// Grid index (i, j) with welded seams.
struct Welding {
    rows: usize,
    cols: usize,
    closed_u: bool,
    closed_v: bool,
}

impl Welding {
    fn distinct_rows(&self) -> usize {
        self.rows - usize::from(self.closed_u)
    }

    fn distinct_cols(&self) -> usize {
        self.cols - usize::from(self.closed_v)
    }

    fn index(&self, i: usize, j: usize) -> u32 {
        let i = i % self.distinct_rows();
        let j = j % self.distinct_cols();
        (i * self.distinct_cols() + j) as u32
    }

    /// The values of the welded grid points, from values on the full grid.
    fn points_of<T: Copy>(&self, grid: &[T]) -> Vec<T> {
        (0..self.distinct_rows())
            .flat_map(|i| (0..self.distinct_cols()).map(move |j| (i, j)))
            .map(|(i, j)| grid[i * self.cols + j])
            .collect()
    }

    /// The grid's triangles on the welded indices (orientation as in the mesh).
    fn triangles(&self) -> Vec<Vec<u32>> {
        let mut faces = Vec::with_capacity(2 * (self.rows - 1) * (self.cols - 1));
        for i in 0..self.rows - 1 {
            for j in 0..self.cols - 1 {
                let (p00, p10, p11, p01) = (
                    self.index(i, j),
                    self.index(i + 1, j),
                    self.index(i + 1, j + 1),
                    self.index(i, j + 1),
                );
                faces.push(vec![p00, p10, p11]);
                faces.push(vec![p00, p11, p01]);
            }
        }
        faces
    }
}

/// A tube: the seam in u welded, the ends capped (or welded too when closed in v).
fn tube(mesh: &TriangleMesh, closed_v: bool) -> ClosedMesh {
    let weld = Welding {
        rows: mesh.rows,
        cols: mesh.columns,
        closed_u: true,
        closed_v,
    };
    let mut faces = weld.triangles();
    if !closed_v {
        // The grid triangles run along column 0 as (i → i+1) and along the last column as
        // (i+1 → i): each cap traverses its ring the other way.
        let weld = &weld;
        let ring = |j: usize| (0..weld.distinct_rows()).map(move |i| weld.index(i, j));
        faces.push(ring(0).rev().collect());
        faces.push(ring(mesh.columns - 1).collect());
    }
    ClosedMesh {
        points: weld.points_of(&mesh.points),
        faces,
    }
}

/// A sheet offset by ± thickness/2 along its unit normal, closed by side walls.
fn thickened(
    surface: &PiecewiseSurface,
    mesh: &TriangleMesh,
    closed_v: bool,
    thickness: f64,
    (u_steps, v_steps): (usize, usize),
) -> Result<ClosedMesh> {
    if !(thickness.is_finite() && thickness > 0.0) {
        return invalid!("thickness = {thickness} must be finite and positive");
    }
    let weld = Welding {
        rows: mesh.rows,
        cols: mesh.columns,
        closed_u: false,
        closed_v,
    };
    let all_normals = grid_normals(surface, u_steps, v_steps);
    let normals = weld.points_of(&all_normals);
    if let Some(k) = normals.iter().position(|n| *n == DVec3::ZERO) {
        return invalid!(
            "the surface is singular at grid point {k}: it has no normal to thicken along"
        );
    }
    let middle = weld.points_of(&mesh.points);
    let count = middle.len() as u32;
    let half = 0.5 * thickness;
    let mut points: Vec<DVec3> = middle
        .iter()
        .zip(&normals)
        .map(|(&p, &n)| p + half * n)
        .collect();
    points.extend(middle.iter().zip(&normals).map(|(&p, &n)| p - half * n));
    let top = weld.triangles();
    let mut faces: Vec<Vec<u32>> = Vec::with_capacity(2 * top.len());
    faces.extend(top.iter().cloned());
    faces.extend(
        top.iter()
            .map(|f| f.iter().rev().map(|&k| k + count).collect()),
    );
    // A boundary edge a → b of the top has no reverse b → a there; the bottom has b' → a'.
    // The wall (b, a, a', b') contains both reverses, so the solid is consistently oriented.
    let directed: HashSet<(u32, u32)> = top
        .iter()
        .flat_map(|f| (0..3).map(move |k| (f[k], f[(k + 1) % 3])))
        .collect();
    let mut boundary: Vec<(u32, u32)> = directed
        .iter()
        .copied()
        .filter(|&(a, b)| !directed.contains(&(b, a)))
        .collect();
    boundary.sort_unstable();
    faces.extend(
        boundary
            .into_iter()
            .map(|(a, b)| vec![b, a, a + count, b + count]),
    );
    Ok(ClosedMesh { points, faces })
}

/// The mesh with every face reversed if it encloses a negative volume.
fn outward(mut solid: ClosedMesh) -> ClosedMesh {
    if solid.volume() < 0.0 {
        solid.faces.iter_mut().for_each(|f| f.reverse());
    }
    solid
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
    use crate::frames::rational::{RationalFrameSegment, RationalFrames};
    use crate::mesh::grid_parameters;
    use crate::model::FramedCurve;
    use crate::sweep::sweep;
    use std::collections::HashMap;

    /// Every edge of every face used exactly once in each direction: a closed, consistently
    /// oriented 2-manifold surface (the check an STL from OpenSCAD gets, too).
    pub(crate) fn assert_closed_manifold(faces: &[Vec<u32>]) {
        let mut uses: HashMap<(u32, u32), usize> = HashMap::new();
        for f in faces {
            for k in 0..f.len() {
                *uses.entry((f[k], f[(k + 1) % f.len()])).or_default() += 1;
            }
        }
        for (&(a, b), &n) in &uses {
            assert_eq!(n, 1, "edge {a} → {b} used {n} times in one direction");
            assert_eq!(uses.get(&(b, a)), Some(&1), "edge {a} → {b} has no partner");
        }
    }

    /// A straight spine along z of length 2 with the constant frame (x, y).
    fn straight() -> FramedCurve {
        let line = RationalBezierCurve::polynomial(&[DVec3::ZERO, DVec3::Z * 2.0]).unwrap();
        let frame = RationalFrameSegment::new(
            vec![DVec3::X, DVec3::X],
            vec![DVec3::Y, DVec3::Y],
            vec![1.0, 1.0],
        )
        .unwrap();
        FramedCurve::new(
            PiecewiseCurve::new(vec![line], vec![0.0, 1.0]).unwrap(),
            RationalFrames::new(vec![frame], vec![0.0, 1.0]).unwrap(),
        )
        .unwrap()
    }

    /// The unit circle (four rational quadratic quarters) or, `open`, three of them.
    fn circle(open: bool) -> PiecewiseCurve {
        let full = crate::primitives::circle(DVec3::ZERO, DVec3::X, DVec3::Y, 1.0).unwrap();
        let quarters = if open { 3 } else { 4 };
        PiecewiseCurve::with_unit_intervals(full.segments()[..quarters].to_vec()).unwrap()
    }

    /// Σ ½ sin Δθ over the polygon through the profile's grid points (the area of the
    /// polygon of radius 1 drawn by the tessellation; its angles are not uniform).
    fn unit_polygon_area(profile: &PiecewiseCurve, steps: usize) -> f64 {
        let angles: Vec<f64> = grid_parameters(profile.breaks(), steps)
            .iter()
            .map(|&u| profile.eval(u).truncate().to_angle())
            .collect();
        angles
            .windows(2)
            .map(|w| 0.5 * (w[1] - w[0]).rem_euclid(std::f64::consts::TAU).sin())
            .sum()
    }

    #[test]
    fn a_closed_profile_gives_a_capped_tube() {
        let framed = straight();
        let profile = circle(false);
        let surface = sweep(&framed, &profile).unwrap();
        let solid = closed_mesh(&surface, 16, 1, None).unwrap();
        assert_closed_manifold(&solid.faces);
        let expected = 2.0 * unit_polygon_area(&profile, 16);
        assert!(
            (expected - std::f64::consts::TAU).abs() < 0.05,
            "{expected}"
        );
        assert!(
            (solid.volume() - expected).abs() < 1e-12,
            "{}",
            solid.volume()
        );
    }

    #[test]
    fn an_open_profile_needs_a_thickness() {
        let framed = straight();
        let profile = circle(true);
        let surface = sweep(&framed, &profile).unwrap();
        let e = closed_mesh(&surface, 8, 2, None).unwrap_err();
        assert!(e.message().contains("thickness"), "{e}");
        assert!(closed_mesh(&surface, 8, 2, Some(-1.0)).is_err());
        let solid = closed_mesh(&surface, 8, 2, Some(0.1)).unwrap();
        assert_closed_manifold(&solid.faces);
        // The normals are radial: three quarters of a polygonal annulus 0.95 .. 1.05, height 2.
        let expected = 2.0 * (1.05f64.powi(2) - 0.95f64.powi(2)) * unit_polygon_area(&profile, 8);
        assert!(
            (solid.volume() - expected).abs() < 1e-12,
            "{}",
            solid.volume()
        );
    }
}
