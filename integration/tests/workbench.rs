//! The RmfSurf workbench (freecad/) in FreeCAD itself (Debian's FreeCAD 0.20): installed by
//! `scripts/install-freecad-addon` as docs/freecad.md says — with the wheel of the Python
//! package, into a fresh user directory ($HOME a scratch directory) — then
//!
//!  - `integration/tests/workbench/headless.py` in `freecadcmd`: RmfSweep, RmfTransition
//!    and RmfUnfold made with make_sweep/make_transition/make_unfold from sketches and wires,
//!    volumes and areas against closed forms, a sketch constraint changed and recomputed,
//!    the library's refusals as Invalid features, the DXF export read back, the document
//!    saved, reopened and recomputed to the same shapes, the macros;
//!  - `integration/tests/workbench/gui.py` in `freecad` under Xvfb: the workbench
//!    activated, each command run on a selection, the shaded result, a screenshot
//!    (target/.../screenshot.png; the one in docs/images/ is such a screenshot).
//!
//! and the install script's refusals. `cargo test -p rmfsurf-integration --test workbench
//! -- --nocapture` shows every figure.

mod support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use support::{fresh_dir, python_wheel, root, SETUP_HINT};

/// Runs scripts/install-freecad-addon with `HOME` and the extra arguments; its output.
fn install_script(home: &Path, args: &[&std::ffi::OsStr]) -> Output {
    Command::new(root().join("scripts/install-freecad-addon"))
        .args(args)
        .env("HOME", home)
        .output()
        .unwrap_or_else(|e| panic!("cannot run scripts/install-freecad-addon ({e}): {SETUP_HINT}"))
}

/// Installs the addon for the user `home` as docs/freecad.md says, with the tests' wheel.
fn install(home: &Path) {
    let wheel = python_wheel();
    let out = install_script(home, &["--wheel".as_ref(), wheel.as_os_str()]);
    print!("{}", String::from_utf8_lossy(&out.stdout));
    assert!(
        out.status.success(),
        "scripts/install-freecad-addon failed:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The report lines (marked "| ") of a FreeCAD script's output.
fn report(stdout: &str) -> impl Iterator<Item = &str> {
    stdout
        .lines()
        .filter_map(|line| line.find("| ").map(|k| &line[k + 2..]))
}

#[test]
fn package_xml_carries_the_library_version() {
    let xml = std::fs::read_to_string(root().join("freecad/package.xml")).expect("package.xml");
    let version = xml
        .split("<version>")
        .nth(1)
        .and_then(|rest| rest.split("</version>").next())
        .expect("package.xml has a <version>");
    assert_eq!(
        version,
        env!("CARGO_PKG_VERSION"),
        "freecad/package.xml's version is not the library's (capi/Cargo.toml)"
    );
    for needed in [
        "<license file=\"LICENSE-MIT\">MIT</license>",
        "<license file=\"LICENSE-APACHE\">Apache-2.0</license>",
        "<classname>RmfSurfWorkbench</classname>",
        "<freecadmin>0.20.0</freecadmin>",
        "<icon>Resources/icons/RmfSurfWorkbench.svg</icon>",
    ] {
        assert!(xml.contains(needed), "package.xml lacks {needed}");
    }
}

#[test]
fn workbench_features_in_freecadcmd() {
    let home = fresh_dir("workbench_headless");
    install(&home);
    let work = home.join("work");
    std::fs::create_dir_all(&work).unwrap();
    let start = std::time::Instant::now();
    let out = Command::new("freecadcmd")
        .arg(root().join("integration/tests/workbench/headless.py"))
        .env("HOME", &home)
        .env("RMFSURF_WORK", &work)
        .env("RMFSURF_VERSION", env!("CARGO_PKG_VERSION"))
        .env("RMFSURF_MACROS", root().join("examples/freecad"))
        .output()
        .unwrap_or_else(|e| panic!("cannot run freecadcmd ({e}): {SETUP_HINT}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    report(&stdout).for_each(|line| println!("{line}"));
    println!("headless checks: {:.0} s", start.elapsed().as_secs_f64());
    assert!(
        out.status.success() && report(&stdout).any(|l| l == "WORKBENCH CHECKS OK"),
        "the workbench checks failed ({}):\n{stdout}\n{stderr}",
        out.status
    );
    // Failing features report one line each; a Python traceback would be a bug.
    assert!(
        !stdout.contains("Traceback") && !stderr.contains("Traceback"),
        "a traceback in FreeCAD's output:\n{stdout}\n{stderr}"
    );
}

#[test]
fn workbench_commands_in_the_gui_under_xvfb() {
    let home = fresh_dir("workbench_gui");
    install(&home);
    let work = home.join("work");
    std::fs::create_dir_all(&work).unwrap();
    let screenshot = home.join("screenshot.png");
    let result = home.join("result.txt");
    let start = std::time::Instant::now();
    let out = Command::new("timeout")
        .args([
            "600",
            "xvfb-run",
            "-a",
            "-s",
            "-screen 0 1440x900x24",
            "freecad",
        ])
        .arg(root().join("integration/tests/workbench/gui.py"))
        .env("HOME", &home)
        // FreeCAD's start page is a Chromium view, which refuses to run as root with its
        // sandbox (the test command may run as root).
        .env("QTWEBENGINE_DISABLE_SANDBOX", "1")
        .env("RMFSURF_WORK", &work)
        .env("RMFSURF_SCREENSHOT", &screenshot)
        .env("RMFSURF_RESULT", &result)
        .output()
        .unwrap_or_else(|e| panic!("cannot run xvfb-run freecad ({e}): {SETUP_HINT}"));
    // timeout's status when it cannot run xvfb-run, or xvfb-run when it cannot run freecad.
    assert!(
        out.status.code() != Some(127),
        "xvfb-run or freecad not found ({}): {SETUP_HINT}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines = std::fs::read_to_string(&result).unwrap_or_default();
    print!("{lines}");
    println!(
        "GUI smoke test: {:.0} s, screenshot {}",
        start.elapsed().as_secs_f64(),
        screenshot.display()
    );
    assert!(
        out.status.success() && lines.lines().any(|l| l == "GUI CHECKS OK"),
        "the GUI smoke test failed ({}):\n{lines}\n{}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(screenshot.exists(), "no screenshot");
}

/// A copy of the tests' wheel under another platform tag.
fn wheel_tagged(dir: &Path, platform: &str) -> PathBuf {
    let wheel = python_wheel();
    let name = wheel.file_name().unwrap().to_string_lossy().to_string();
    let stem = name
        .rsplit_once('-')
        .expect("name-version-py-abi-platform.whl")
        .0;
    let copy = dir.join(format!("{stem}-{platform}.whl"));
    std::fs::copy(&wheel, &copy).expect("copy of the wheel");
    copy
}

/// `--into HOME/tree` with the tests' wheel: the tree an Addon Manager repository holds.
fn write_tree(home: &Path) -> PathBuf {
    let tree = home.join("tree");
    let wheel = python_wheel();
    let out = install_script(
        home,
        &[
            "--wheel".as_ref(),
            wheel.as_os_str(),
            "--into".as_ref(),
            tree.as_os_str(),
        ],
    );
    assert!(out.status.success(), "--into failed: {out:?}");
    tree
}

#[test]
fn install_script_writes_the_addon_tree_and_refuses_what_it_must() {
    let home = fresh_dir("workbench_install");
    let tree = write_tree(&home);
    let wheel = python_wheel();
    for path in [
        "package.xml",
        "Init.py",
        "InitGui.py",
        "Resources/icons/RmfSweep.svg",
        "rmfsurf_workbench/__init__.py",
        "rmfsurf/__init__.py",
        "rmfsurf/_native/lib_native.so",
        "README.md",
        "LICENSE-MIT",
        "LICENSE-APACHE",
        "LICENSE-cffi",
    ] {
        assert!(tree.join(path).exists(), "the addon tree lacks {path}");
    }
    // A folder of that name that is not the addon stays untouched.
    let other = home.join(".local/share/FreeCAD/Mod/RmfSurf");
    std::fs::create_dir_all(&other).unwrap();
    std::fs::write(other.join("mine.txt"), "a user's file").unwrap();
    let out = install_script(&home, &["--wheel".as_ref(), wheel.as_os_str()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        !out.status.success() && stdout.contains("is not the RmfSurf addon"),
        "installing over a foreign folder was not refused: {stdout}"
    );
    assert!(
        other.join("mine.txt").exists(),
        "the foreign folder was touched"
    );
    // A wheel for another platform is refused before anything is written.
    let foreign = wheel_tagged(&home, "macosx_11_0_arm64");
    let target = home.join("elsewhere");
    let out = install_script(
        &home,
        &[
            "--wheel".as_ref(),
            foreign.as_os_str(),
            "--into".as_ref(),
            target.as_os_str(),
        ],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        !out.status.success() && stdout.contains("is built for macosx_11_0_arm64"),
        "a macOS wheel was not refused: {stdout}"
    );
    assert!(
        !target.exists(),
        "a refused install wrote {}",
        target.display()
    );
}

/// The first Python block under "## Scripting" of the Markdown `text`, run in freecadcmd as
/// written for the user `home` (the addon installed); it must leave a valid shape in
/// `result`. FreeCAD's output.
fn run_scripting_example(text: &str, home: &Path, page: &str) -> String {
    let section = text
        .find("## Scripting")
        .unwrap_or_else(|| panic!("{page} has ## Scripting"));
    let start = section
        + text[section..]
            .find("```python\n")
            .unwrap_or_else(|| panic!("a Python example under ## Scripting of {page}"))
        + 10;
    let end = start + text[start..].find("```").expect("the end of the example");
    let script = format!(
        "import sys\n{}\nprint('\\n| example: valid', result.isValid())\nsys.exit(0 if result.isValid() else 1)\n",
        &text[start..end]
    );
    std::fs::write(home.join("example.py"), script).unwrap();
    let out = Command::new("freecadcmd")
        .arg("example.py")
        .current_dir(home)
        .env("HOME", home)
        .output()
        .unwrap_or_else(|e| panic!("cannot run freecadcmd ({e}): {SETUP_HINT}"));
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    report(&stdout).for_each(|line| println!("{page}: {line}"));
    assert!(
        out.status.success() && report(&stdout).any(|l| l == "example: valid True"),
        "the example of {page} failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

/// The first Python block under "## Scripting" in docs/freecad.md, run in freecadcmd as
/// written (the addon installed as the page says).
#[test]
fn docs_freecad_example_runs() {
    let text = std::fs::read_to_string(root().join("docs/freecad.md")).expect("docs/freecad.md");
    let home = fresh_dir("workbench_docs");
    install(&home);
    run_scripting_example(&text, &home, "docs/freecad.md");
    assert!(
        home.join("hood.dxf").exists(),
        "docs/freecad.md's example wrote no hood.dxf"
    );
}

/// The tree `--into` writes is what a registered repository holds: copied as it is into
/// FreeCAD's Mod folder (what the Addon Manager does with a clone), the workbench and the
/// library load and the addon README's example runs. Its cffi backend loads without the
/// system's cffi (a Python without site-packages) and opens the library.
#[test]
fn the_addon_tree_copied_into_mod_runs_its_readme_example() {
    let home = fresh_dir("workbench_tree");
    let tree = write_tree(&home);
    let mod_dir = home.join(".local/share/FreeCAD/Mod");
    std::fs::create_dir_all(&mod_dir).unwrap();
    let copied = Command::new("cp")
        .arg("-r")
        .arg(&tree)
        .arg(mod_dir.join("RmfSurf"))
        .status()
        .expect("cp runs");
    assert!(copied.success(), "cp -r of the addon tree failed");
    let readme = std::fs::read_to_string(tree.join("README.md")).expect("the tree's README.md");
    run_scripting_example(&readme, &home, "the addon's README.md");
    let backend = "import sys\n\
                   sys.path.insert(0, sys.argv[1])\n\
                   sys.path.insert(0, sys.argv[1] + '/rmfsurf')\n\
                   import _cffi_backend, _native\n\
                   assert _cffi_backend.__file__.startswith(sys.argv[1]), _cffi_backend.__file__\n\
                   print(_cffi_backend.__file__, _native.ffi.string(_native.lib.rmf_version()).decode())";
    let out = Command::new("/usr/bin/python3")
        .args(["-S", "-c", backend])
        .arg(&tree)
        .output()
        .expect("python3 runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    println!("the bundled cffi backend: {stdout}");
    assert!(
        out.status.success() && stdout.trim().ends_with(env!("CARGO_PKG_VERSION")),
        "the addon's cffi backend does not load the library: {stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
