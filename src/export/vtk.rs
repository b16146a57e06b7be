//! VTK XML PolyData (`.vtp`, "VTK File Formats", XML formats, PolyData), ASCII: points,
//! polygons and optional point normals. ParaView and VTK's `vtkXMLPolyDataReader` read it.

use super::number;
use glam::DVec3;
use std::fmt::Write;

/// One `DataArray` of 3-vectors.
fn vectors(out: &mut String, name: &str, values: &[DVec3]) {
    let _ = writeln!(
        out,
        "        <DataArray type=\"Float64\" Name=\"{name}\" NumberOfComponents=\"3\" format=\"ascii\">"
    );
    for v in values {
        let _ = writeln!(
            out,
            "          {} {} {}",
            number(v.x),
            number(v.y),
            number(v.z)
        );
    }
    out.push_str("        </DataArray>\n");
}

/// A polygon mesh (`faces` index `points`) as a `.vtp` file, with per-point `normals` if
/// given (same length as `points`).
pub fn mesh_to_vtp<F: AsRef<[u32]>>(
    points: &[DVec3],
    faces: &[F],
    normals: Option<&[DVec3]>,
) -> String {
    let mut out = String::from(
        "<?xml version=\"1.0\"?>\n\
         <VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <PolyData>\n",
    );
    let _ = writeln!(
        out,
        "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"{}\">",
        points.len(),
        faces.len()
    );
    out.push_str("      <Points>\n");
    vectors(&mut out, "Points", points);
    out.push_str("      </Points>\n");
    if let Some(normals) = normals {
        out.push_str("      <PointData Normals=\"Normals\">\n");
        vectors(&mut out, "Normals", normals);
        out.push_str("      </PointData>\n");
    }
    out.push_str("      <Polys>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    let mut offsets = Vec::with_capacity(faces.len());
    let mut end = 0;
    for face in faces {
        let face = face.as_ref();
        let indices: Vec<String> = face.iter().map(u32::to_string).collect();
        let _ = writeln!(out, "          {}", indices.join(" "));
        end += face.len();
        offsets.push(end.to_string());
    }
    out.push_str("        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for chunk in offsets.chunks(16) {
        let _ = writeln!(out, "          {}", chunk.join(" "));
    }
    out.push_str("        </DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_points_normals_and_offsets() {
        let points = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE];
        let faces = [[0u32, 1, 2], [1, 3, 2]];
        let vtp = mesh_to_vtp(&points, &faces, Some(&[DVec3::Z; 4]));
        assert!(vtp.contains("NumberOfPoints=\"4\""));
        assert!(vtp.contains("NumberOfPolys=\"2\""));
        assert!(vtp.contains("          0 1 2\n          1 3 2\n"));
        assert!(vtp.contains("          3 6\n"));
        assert!(vtp.contains("<PointData Normals=\"Normals\">"));
    }
}
