//! FreeCAD, headless (`freecadcmd`, Debian package freecad): the command-line tool writes
//! STEP faces and curves, OBJ meshes and the DXF and SVG flat pattern of every example in
//! examples/cli/, and `examples/freecad/check_in_freecad.py` runs inside FreeCAD against the
//! shared library through the pure-Python glue: Part objects from the NURBS views, FreeCAD's
//! own Gaussian curvature, STEP written by FreeCAD and read back, the tool's files read by
//! FreeCAD, both macros, and wire sweeps (Part.Wire in, Part.Solid out, beside FreeCAD's own
//! makePipeShell; the tool's pipe.step). The script prints every figure with its limit.
//!
//! `cargo test --test freecad -- --nocapture` shows them.

mod support;

use std::process::Command;
use support::{fresh_dir, root, run_cli, toolchain, EXAMPLES, SETUP_HINT};

/// The script's report lines (marked "| "), without FreeCAD's banner and progress output.
fn report(stdout: &str) -> impl Iterator<Item = &str> {
    stdout
        .lines()
        .filter_map(|line| line.find("| ").map(|k| &line[k + 2..]))
}

#[test]
fn freecad_reads_our_files_and_builds_exact_part_objects() {
    let files = fresh_dir("freecad_files");
    for example in EXAMPLES {
        let step = format!("{example}.step");
        let obj = format!("{example}.obj");
        let curves = format!("{example}_curves.step");
        run_cli(
            &files,
            example,
            &["-q", "-o", &step, "-o", &obj, "--curves", &curves],
        );
    }
    run_cli(
        &files,
        "cone_spline",
        &["-q", "-o", "cone_spline.dxf", "-o", "cone_spline.svg"],
    );
    // The issue's wire sweep input: its STEP solid.
    run_cli(&files, "pipe", &["-q", "-o", "pipe.step"]);
    let work = fresh_dir("freecad_work");
    let script = root().join("examples/freecad/check_in_freecad.py");
    let out = Command::new("freecadcmd")
        .arg(&script)
        .env("RMFSURF_LIBRARY", toolchain().lib_dir.join("librmfsurf.so"))
        .env("RMFSURF_EXAMPLES", root().join("examples/cli"))
        .env("RMFSURF_FILES", &files)
        .env("RMFSURF_WORK", &work)
        // FreeCAD keeps its settings under $HOME: each run gets its own, untouched by the
        // user's (and by the other test running at the same time).
        .env("HOME", &work)
        .output()
        .unwrap_or_else(|e| panic!("cannot run freecadcmd ({e}): {SETUP_HINT}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    report(&stdout).for_each(|line| println!("{line}"));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && report(&stdout).any(|l| l == "FREECAD CHECKS OK"),
        "the FreeCAD checks failed ({}):\n{stdout}\n{stderr}",
        out.status
    );
}

/// The README's FreeCAD console example, run as written (with the glue on the path).
#[test]
fn readme_freecad_example_runs() {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let start = readme
        .find("```python\n")
        .expect("a Python example in the README")
        + 10;
    let end = start + readme[start..].find("```").expect("the end of the example");
    let dir = fresh_dir("freecad_readme");
    let script = format!(
        "import sys\nsys.path.insert(0, {:?})\n{}\nprint('\\n| README example: valid face', tube.isValid())\nsys.exit(0 if tube.isValid() else 1)\n",
        root().join("examples/freecad").display().to_string(),
        &readme[start..end]
    );
    std::fs::write(dir.join("readme_example.py"), script).unwrap();
    let out = Command::new("freecadcmd")
        .arg("readme_example.py")
        .current_dir(&dir)
        .env("RMFSURF_LIBRARY", toolchain().lib_dir.join("librmfsurf.so"))
        .env("HOME", &dir)
        .output()
        .unwrap_or_else(|e| panic!("cannot run freecadcmd ({e}): {SETUP_HINT}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    report(&stdout).for_each(|line| println!("{line}"));
    assert!(
        out.status.success() && report(&stdout).any(|l| l == "README example: valid face True"),
        "the README's FreeCAD example failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        dir.join("tube.step").exists(),
        "the example writes tube.step"
    );
}
