//! VTK's own reader (vtkXMLPolyDataReader, Debian package libvtk9-dev) reads the `.vtp`
//! files the command-line tool writes for every example: the same points (bit for bit),
//! the same triangles as the tool's `.obj` of the same mesh, and unit normals.
//!
//! `cargo test -p rmfsurf-integration --test vtk_reader -- --nocapture` prints the figures.

mod support;

use std::process::Command;
use support::{build, fresh_dir, run_cli, vtk_flags, EXAMPLES, STRICT};

/// Lines starting with `tag ` as vectors of numbers.
fn records(text: &str, tag: &str) -> Vec<Vec<f64>> {
    text.lines()
        .filter_map(|l| l.strip_prefix(tag).and_then(|r| r.strip_prefix(' ')))
        .map(|r| {
            r.split_whitespace()
                .map(|x| x.split("//").next().unwrap().parse().expect("a number"))
                .collect()
        })
        .collect()
}

#[test]
fn vtk_reads_the_tools_vtp_files() {
    let (include, libs) = vtk_flags(&[
        "IOXML",
        "CommonCore",
        "CommonDataModel",
        "CommonExecutionModel",
    ]);
    let mut flags = vec!["-std=c++17", include.as_str()];
    flags.extend(STRICT);
    let reader = build(
        "vtk_read_vtp",
        true,
        &["integration/tests/programs/vtk_read_vtp.cpp"],
        &flags,
        &libs,
    );
    let dir = fresh_dir("vtk_reader");
    for example in EXAMPLES {
        let (vtp, obj) = (format!("{example}.vtp"), format!("{example}.obj"));
        run_cli(&dir, example, &["-q", "-o", &vtp, "-o", &obj]);
        let out = Command::new(&reader)
            .arg(dir.join(&vtp))
            .output()
            .expect("the reader runs");
        assert!(
            out.status.success(),
            "VTK failed on {vtp}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let read = String::from_utf8_lossy(&out.stdout);
        let written = std::fs::read_to_string(dir.join(&obj)).expect("obj written");
        let (points, obj_points) = (records(&read, "v"), records(&written, "v"));
        assert_eq!(
            points, obj_points,
            "{vtp}: VTK's points differ from the mesh's"
        );
        let faces = records(&read, "f");
        let obj_faces: Vec<Vec<f64>> = records(&written, "f")
            .into_iter()
            .map(|f| f.into_iter().map(|k| k - 1.0).collect())
            .collect();
        assert_eq!(
            faces, obj_faces,
            "{vtp}: VTK's triangles differ from the mesh's"
        );
        let normals = records(&read, "n");
        assert_eq!(normals.len(), points.len(), "{vtp}: one normal per point");
        let unit = normals
            .iter()
            .map(|n| ((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() - 1.0).abs())
            .fold(0.0, f64::max);
        println!(
            "{vtp}: VTK read {} points (identical to the .obj), {} triangles (identical), normals unit to {unit:.1e}",
            points.len(),
            faces.len()
        );
        assert!(unit < 1e-15, "{vtp}: normals are not unit: {unit}");
    }
}
