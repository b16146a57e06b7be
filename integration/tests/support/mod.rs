//! What the tests that drive external programs share: what capi's tests share (building
//! the shared library, the compilers, compiling and running test programs: the file
//! capi/tests/support/mod.rs, included here, not copied), and the command-line tool, VTK's
//! headers, valgrind, and the Python environment and wheel.
//!
//! Each test binary of this crate includes this module and uses a part of it.
#![allow(dead_code)]

#[path = "../../../capi/tests/support/mod.rs"]
mod common;

pub use common::*;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, MutexGuard, OnceLock};

/// Runs a test program under valgrind (no leaks, no invalid accesses), echoes its output
/// and asserts success.
pub fn run_under_valgrind(exe: &Path) {
    let mut cmd = Command::new("valgrind");
    cmd.args([
        "--quiet",
        "--error-exitcode=99",
        "--leak-check=full",
        "--errors-for-leak-kinds=definite,indirect",
        "--show-leak-kinds=definite,indirect",
    ]);
    cmd.arg(exe);
    run_command(cmd, exe);
}

/// The VTK include directory (/usr/include/vtk-X.Y) and its version suffix.
pub fn vtk() -> (PathBuf, String) {
    let dir = std::fs::read_dir("/usr/include")
        .ok()
        .and_then(|entries| {
            entries
                .filter_map(Result::ok)
                .map(|e| e.path())
                .filter(|p| p.join("vtkCurvatures.h").exists())
                .max()
        })
        .unwrap_or_else(|| panic!("VTK headers (libvtk9-dev) not found: {SETUP_HINT}"));
    let version = dir
        .file_name()
        .and_then(|n| n.to_str())
        .and_then(|n| n.strip_prefix("vtk-"))
        .expect("vtk-X.Y")
        .to_string();
    (dir, version)
}

/// The `-isystem` flag for VTK's headers (they are not -Wpedantic clean: system headers)
/// and the `-l` flags of the VTK `modules` (e.g. "CommonCore").
pub fn vtk_flags(modules: &[&str]) -> (String, Vec<String>) {
    let (dir, version) = vtk();
    let libs = modules
        .iter()
        .map(|m| format!("-lvtk{m}-{version}"))
        .collect();
    (format!("-isystem{}", dir.display()), libs)
}

/// The command-line tool `rmfsurf`, built once (debug profile, beside the library).
pub fn cli() -> PathBuf {
    static CLI: OnceLock<PathBuf> = OnceLock::new();
    CLI.get_or_init(|| {
        let profile_dir = toolchain().lib_dir.parent().expect("target/<profile>");
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let status = Command::new(cargo)
            .args(["build", "--quiet", "-p", "rmfsurf-cli", "--bin", "rmfsurf"])
            .current_dir(root())
            .status()
            .expect("cargo runs");
        assert!(status.success(), "cargo build -p rmfsurf-cli failed");
        let exe = profile_dir.join("rmfsurf");
        assert!(exe.exists(), "{} not built", exe.display());
        exe
    })
    .clone()
}

/// The example inputs of the command-line tool, examples/cli/<name>.json.
pub const EXAMPLES: [&str; 4] = [
    "cone_spline",
    "helix_pipe_mobius",
    "helix_strip_rrmf",
    "nurbs_moulding_ph",
];

/// Runs the tool on examples/cli/<example>.json with the extra arguments `args` (relative
/// paths are in `dir`); asserts success.
pub fn run_cli(dir: &Path, example: &str, args: &[&str]) {
    let input = root().join("examples/cli").join(format!("{example}.json"));
    let out = Command::new(cli())
        .arg(&input)
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the tool runs");
    print!("{example}:\n{}", String::from_utf8_lossy(&out.stdout));
    assert!(
        out.status.success(),
        "rmfsurf {} failed: {}",
        input.display(),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The Python test environment of scripts/python-env (Debian's Python 3.11 with build123d,
/// OCP and pytest from PyPI, kept in target/venv between runs); once.
pub fn python_env() -> PathBuf {
    static VENV: OnceLock<PathBuf> = OnceLock::new();
    VENV.get_or_init(|| {
        let out = Command::new(root().join("scripts/python-env"))
            .output()
            .unwrap_or_else(|e| panic!("cannot run scripts/python-env ({e}): {SETUP_HINT}"));
        eprint!("{}", String::from_utf8_lossy(&out.stderr));
        assert!(
            out.status.success(),
            "scripts/python-env failed: {SETUP_HINT}"
        );
        PathBuf::from(String::from_utf8_lossy(&out.stdout).trim())
    })
    .clone()
}

/// Held while maturin builds the package: every maturin build stages the library in the same
/// target/maturin directory, so two at once remove each other's files.
pub fn maturin_lock() -> MutexGuard<'static, ()> {
    static LOCK: Mutex<()> = Mutex::new(());
    LOCK.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// The Python package's distributions as published (scripts/python-dist): the manylinux
/// wheel, carrying the library, and the sdist.
pub struct Dists {
    pub wheel: PathBuf,
    pub sdist: PathBuf,
}

/// The distributions, built once per test binary into target/dist (the Rust build is
/// cargo's, kept between runs).
pub fn python_dists() -> &'static Dists {
    static DISTS: OnceLock<Dists> = OnceLock::new();
    DISTS.get_or_init(|| {
        let _maturin = maturin_lock();
        let out = Command::new(root().join("scripts/python-dist"))
            .output()
            .unwrap_or_else(|e| panic!("cannot run scripts/python-dist ({e}): {SETUP_HINT}"));
        eprint!("{}", String::from_utf8_lossy(&out.stderr));
        assert!(out.status.success(), "scripts/python-dist failed");
        let stdout = String::from_utf8_lossy(&out.stdout);
        let mut paths = stdout.lines().map(PathBuf::from);
        let (wheel, sdist) = (paths.next(), paths.next());
        Dists {
            wheel: wheel.expect("python-dist prints the wheel"),
            sdist: sdist.expect("python-dist prints the sdist"),
        }
    })
}

/// The manylinux wheel of the Python package (see [`python_dists`]).
pub fn python_wheel() -> PathBuf {
    python_dists().wheel.clone()
}
