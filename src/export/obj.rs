//! Wavefront `.obj` (the "Object Files" appendix of the Advanced Visualizer manual):
//! vertices `v`, optional vertex normals `vn`, polygon faces `f` with 1-based indices.

use super::number;
use glam::DVec3;
use std::fmt::Write;

/// A polygon mesh as an `.obj` file, object `name`, with per-point `normals` if given.
pub fn mesh_to_obj<F: AsRef<[u32]>>(
    name: &str,
    points: &[DVec3],
    faces: &[F],
    normals: Option<&[DVec3]>,
) -> String {
    let mut out = format!("# rmfsurf {}\no {name}\n", env!("CARGO_PKG_VERSION"));
    for p in points {
        let _ = writeln!(out, "v {} {} {}", number(p.x), number(p.y), number(p.z));
    }
    for n in normals.unwrap_or_default() {
        let _ = writeln!(out, "vn {} {} {}", number(n.x), number(n.y), number(n.z));
    }
    for face in faces {
        let corners: Vec<String> = face
            .as_ref()
            .iter()
            .map(|&k| match normals {
                Some(_) => format!("{0}//{0}", k + 1),
                None => (k + 1).to_string(),
            })
            .collect();
        let _ = writeln!(out, "f {}", corners.join(" "));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_are_one_based() {
        let obj = mesh_to_obj(
            "t",
            &[DVec3::ZERO, DVec3::X, DVec3::Y],
            &[[0u32, 1, 2]],
            None,
        );
        assert!(
            obj.contains("o t\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            "{obj}"
        );
        let with = mesh_to_obj(
            "t",
            &[DVec3::ZERO; 3],
            &[vec![0u32, 1, 2]],
            Some(&[DVec3::Z; 3]),
        );
        assert!(with.contains("vn 0 0 1\n") && with.contains("f 1//1 2//2 3//3\n"));
    }
}
