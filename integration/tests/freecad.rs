//! FreeCAD, headless (`freecadcmd`, Debian package freecad): the command-line tool writes
//! STEP faces and curves, OBJ meshes and the DXF and SVG flat pattern of every example in
//! examples/cli/, and `examples/freecad/check_in_freecad.py` runs inside FreeCAD with the
//! Python package rmfsurf installed as docs/install.md says (the wheel, `pip install
//! --target` into FreeCAD's AdditionalPythonPackages; no environment variable): Part objects
//! from the NURBS views (rmfsurf.freecad), FreeCAD's own Gaussian curvature, STEP written by
//! FreeCAD and read back, the tool's files read by FreeCAD, rmfsurf.freecad's selection
//! entry points and the wire sweep, and the sheet-metal hopper (examples/cli/hopper.json):
//! its STEP solid, DXF and flat STEP face read by FreeCAD, the transition built in FreeCAD,
//! and the comparison with FreeCAD's own mesh unwrapping. The script prints every figure
//! with its limit. The FreeCAD examples of the docs run too. (The macros and the
//! workbench: workbench.rs.)
//!
//! `cargo test -p rmfsurf-integration --test freecad -- --nocapture` shows them.

mod support;

use std::path::Path;
use std::process::Command;
use support::{fresh_dir, python_env, python_wheel, root, run_cli, EXAMPLES, SETUP_HINT};

/// Installs the wheel where FreeCAD 0.20 looks for add-on packages of the user `home`:
/// $HOME/.local/share/FreeCAD/AdditionalPythonPackages (on sys.path when it exists), without
/// dependencies (FreeCAD's Python brings NumPy and cffi's backend), as docs/install.md says.
fn install_for_freecad(home: &Path) {
    let target = home.join(".local/share/FreeCAD/AdditionalPythonPackages");
    let status = Command::new(python_env().join("bin/pip"))
        .args([
            "install",
            "--quiet",
            "--no-deps",
            "--disable-pip-version-check",
            "--target",
        ])
        .arg(&target)
        .arg(python_wheel())
        .status()
        .expect("pip runs");
    assert!(
        status.success(),
        "pip install --target {} failed",
        target.display()
    );
}

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
    run_cli(
        &files,
        "hopper",
        &[
            "-q",
            "-o",
            "hopper.step",
            "-o",
            "hopper.dxf",
            "-o",
            "hopper.flat.step",
        ],
    );
    let work = fresh_dir("freecad_work");
    install_for_freecad(&work);
    let script = root().join("examples/freecad/check_in_freecad.py");
    let out = Command::new("freecadcmd")
        .arg(&script)
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

/// The first Python block after `heading` in `doc`, run in freecadcmd as written (the
/// package installed as docs/install.md says); it must leave a valid shape in `result`.
fn run_docs_example(doc: &str, heading: &str, name: &str) {
    let text = std::fs::read_to_string(root().join(doc)).expect(doc);
    let section = text
        .find(heading)
        .unwrap_or_else(|| panic!("{doc} has {heading:?}"));
    let start = section
        + text[section..]
            .find("```python\n")
            .unwrap_or_else(|| panic!("a Python example under {heading:?} in {doc}"))
        + 10;
    let end = start + text[start..].find("```").expect("the end of the example");
    let dir = fresh_dir(name);
    install_for_freecad(&dir);
    let script = format!(
        "import sys\n{}\nprint('\\n| docs example: valid', result.isValid())\nsys.exit(0 if result.isValid() else 1)\n",
        &text[start..end]
    );
    std::fs::write(dir.join("docs_example.py"), script).unwrap();
    let out = Command::new("freecadcmd")
        .arg("docs_example.py")
        .current_dir(&dir)
        .env("HOME", &dir)
        .output()
        .unwrap_or_else(|e| panic!("cannot run freecadcmd ({e}): {SETUP_HINT}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    report(&stdout).for_each(|line| println!("{line}"));
    assert!(
        out.status.success() && report(&stdout).any(|l| l == "docs example: valid True"),
        "the FreeCAD example of {doc} failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn docs_freecad_examples_run() {
    run_docs_example("docs/install.md", "## FreeCAD", "freecad_docs_install");
    run_docs_example(
        "docs/cad-integration.md",
        "## FreeCAD",
        "freecad_docs_integration",
    );
}
