//! Files for CAD, mesh and cutting tools, written from the library's exact geometry. Each
//! writer returns the file's text; writing it to disk (atomically) is the caller's job.
//!
//! | module | format | holds | read back in the tests by |
//! | --- | --- | --- | --- |
//! | [`step`] | STEP AP214 (ISO 10303-21) | rational B-spline surfaces as faces, curves | FreeCAD (OpenCascade's reader) |
//! | [`occ_brep`] | OpenCascade's B-rep text (`CASCADE Topology V1`) | a B-rep solid or shell as the kernel holds it | OpenCascade's `BRepTools::Read` and `BRepCheck_Analyzer` (Python tests) |
//! | [`vtk`] | VTK XML PolyData `.vtp` | triangle meshes with normals | VTK's `vtkXMLPolyDataReader` |
//! | [`obj`] | Wavefront `.obj` | polygon meshes with normals | FreeCAD's mesh reader |
//! | [`openscad`] | OpenSCAD `.scad` | closed `polyhedron()` solids, RMF transforms for sweeps | OpenSCAD (renders to STL) |
//! | [`svg`] | SVG 1.1 | flat patterns: true arcs and lines, in millimetres | — (a drawing) |
//! | [`dxf`] | DXF R12 (AC1009) | flat patterns: `LINE` and `ARC` entities | FreeCAD's DXF reader |
//!
//! Numbers are written with Rust's shortest round-trip representation, so every coordinate
//! reads back as the same double.

pub mod dxf;
pub mod obj;
pub mod occ_brep;
pub mod openscad;
pub mod step;
pub mod svg;
pub mod vtk;

/// The shortest decimal text that reads back as `x` (`1`, `0.1`, `1e-7`; −0 as `0`).
fn number(x: f64) -> String {
    let s = format!("{:?}", x + 0.0);
    s.strip_suffix(".0").map_or(s.clone(), str::to_string)
}

/// Distinct knots and their multiplicities.
fn knots_and_multiplicities(knots: &[f64]) -> (Vec<f64>, Vec<usize>) {
    let mut distinct: Vec<f64> = Vec::new();
    let mut multiplicities: Vec<usize> = Vec::new();
    for &k in knots {
        if distinct.last() == Some(&k) {
            *multiplicities.last_mut().expect("a knot before") += 1;
        } else {
            distinct.push(k);
            multiplicities.push(1);
        }
    }
    (distinct, multiplicities)
}

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn numbers_round_trip() {
        for x in [0.0, 1.0, -2.5, 1e-7, 1.5e300, 0.1, std::f64::consts::PI] {
            assert_eq!(number(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(number(2.0), "2");
    }
}
