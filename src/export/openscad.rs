//! OpenSCAD `.scad` files (OpenSCAD User Manual, "Primitive Solids: polyhedron" and
//! "Transformations: multmatrix"):
//!
//! * `rmf_solid()`: the solid as one `polyhedron()` of `rmf_points()` and `rmf_faces()`,
//!   each face listed clockwise seen from outside, as OpenSCAD requires; the file calls it
//!   at top level;
//! * for sweeps, `rmf_transforms()`: the frames along the spine as 4 × 4 matrices with
//!   columns (f₂, f₃, t, x), which place a 2-D shape drawn in the xy-plane in the normal
//!   plane — the list BOSL2's `sweep(shape, transforms)` takes — and `rmf_sweep(shape)`,
//!   a self-contained sweep of a 2-D polygon with them (capped, outward oriented).
//!
//! Everything is a module or function, so `use <file.scad>` imports it without drawing.

use super::number;
use crate::frames::Frame;
use crate::solid::ClosedMesh;
use glam::DVec3;
use std::fmt::Write;

/// The sweep of a 2-D polygon with the transforms, written in OpenSCAD. The shape is
/// reversed when it is clockwise, so the side faces always point outwards.
const SWEEP_MODULE: &str = r#"
// The signed area of a 2-D polygon (positive when counter-clockwise).
function rmf_area(shape) = 0.5 * [for (i = [0:len(shape) - 1])
    let(a = shape[i], b = shape[(i + 1) % len(shape)]) a[0] * b[1] - a[1] * b[0]] * [for (s = shape) 1];

// The point (x, y) of the xy-plane placed by the 4 x 4 matrix m.
function rmf_place(m, p) = [for (r = [0:2]) m[r][0] * p[0] + m[r][1] * p[1] + m[r][3]];

// Sweeps the 2-D polygon `shape` (x along f2, y along f3) with the rotation-minimizing
// frames of `transforms`; both ends are capped.
module rmf_sweep(shape, transforms = rmf_transforms()) {
    s = rmf_area(shape) < 0 ? [for (i = [len(shape) - 1:-1:0]) shape[i]] : shape;
    n = len(s);
    m = len(transforms);
    points = [for (t = transforms) for (p = s) rmf_place(t, p)];
    sides = [for (k = [0:m - 2]) for (i = [0:n - 1])
        [k * n + i, (k + 1) * n + i, (k + 1) * n + (i + 1) % n, k * n + (i + 1) % n]];
    caps = [[for (i = [0:n - 1]) i], [for (i = [n - 1:-1:0]) (m - 1) * n + i]];
    polyhedron(points = points, faces = concat(sides, caps), convexity = 10);
}
"#;

fn point(p: DVec3) -> String {
    format!("[{}, {}, {}]", number(p.x), number(p.y), number(p.z))
}

/// The matrix [f₂ f₃ t x; 0 0 0 1] in OpenSCAD's row-major nesting.
fn matrix(x: DVec3, f: &Frame) -> String {
    let row = |k: usize| {
        format!(
            "[{}, {}, {}, {}]",
            number(f.f2[k]),
            number(f.f3[k]),
            number(f.tangent[k]),
            number(x[k])
        )
    };
    format!("[{}, {}, {}, [0, 0, 0, 1]]", row(0), row(1), row(2))
}

/// A `.scad` file drawing `solid` (see the module notes); `placements` (spine points with
/// their frames) add `rmf_transforms()` and `rmf_sweep()`.
pub fn solid_to_scad(
    title: &str,
    solid: &ClosedMesh,
    placements: Option<&[(DVec3, Frame)]>,
) -> String {
    let mut out = format!(
        "// {title}\n// Written by rmfsurf {}: a closed polyhedron, exact to the tessellation.\n\n",
        env!("CARGO_PKG_VERSION")
    );
    out.push_str("function rmf_points() = [\n");
    for p in &solid.points {
        let _ = writeln!(out, "  {},", point(*p));
    }
    out.push_str("];\n\nfunction rmf_faces() = [\n");
    for face in &solid.faces {
        // Counter-clockwise from outside in the mesh; OpenSCAD wants clockwise.
        let indices: Vec<String> = face.iter().rev().map(u32::to_string).collect();
        let _ = writeln!(out, "  [{}],", indices.join(", "));
    }
    out.push_str("];\n\nmodule rmf_solid() polyhedron(points = rmf_points(), faces = rmf_faces(), convexity = 10);\n");
    if let Some(placements) = placements {
        out.push_str("\n// The frames along the spine: columns f2, f3, tangent, point.\nfunction rmf_transforms() = [\n");
        for (x, f) in placements {
            let _ = writeln!(out, "  {},", matrix(*x, f));
        }
        out.push_str("];\n");
        out.push_str(SWEEP_MODULE);
    }
    out.push_str("\nrmf_solid();\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_are_reversed_and_transforms_are_row_major() {
        let solid = ClosedMesh {
            points: vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
            faces: vec![vec![0, 2, 1], vec![0, 1, 3], vec![1, 2, 3], vec![0, 3, 2]],
        };
        let frame = Frame::from_tangent_normal(DVec3::Z, DVec3::X);
        let scad = solid_to_scad("t", &solid, Some(&[(DVec3::new(1.0, 2.0, 3.0), frame)]));
        assert!(scad.contains("\n  [1, 2, 0],\n"));
        assert!(scad.contains("[[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]"));
        assert!(scad.contains("module rmf_sweep"));
        assert!(scad.trim_end().ends_with("rmf_solid();"));
        assert!(!solid_to_scad("t", &solid, None).contains("rmf_transforms"));
    }
}
