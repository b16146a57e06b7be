//! The Python package (python/): built and installed the two ways users get it, then its
//! test suite (python/tests, pytest) run against the installed copy.
//!
//!  - `pip install ./python` in a fresh virtual environment builds the library with
//!    maturin (downloaded by pip) and installs it; `import rmfsurf` works and
//!    `rmfsurf.__version__ == rmf_version()`;
//!  - `pip wheel ./python` gives a wheel carrying the library; it is installed into the
//!    test environment (scripts/python-env: build123d and OCP from PyPI) with no Rust
//!    toolchain on the PATH, and pytest runs python/tests there: the API against the tests'
//!    own NURBS evaluator, errors, freed handles, and the OCP adapter with build123d.
//!
//! pytest runs with RMFSURF_REQUIRE_ALL=1: python/tests/conftest.py then turns every skip
//! (a module `pytest.importorskip` does not find, a `skipif` whose condition holds) into a
//! failure, so a missing build123d, OCP or FreeCAD fails the test instead of passing by.
//!
//! `cargo test -p rmfsurf-integration --test python -- --nocapture` shows pytest's report.

mod support;

use std::path::PathBuf;
use std::process::Command;
use support::{maturin_lock, python_env, python_wheel, root, SETUP_HINT};

/// A PATH with the virtual environment and the system's programs but no Rust toolchain.
fn path_without_rust(venv: &std::path::Path) -> String {
    let path = format!("{}:/usr/bin:/bin", venv.join("bin").display());
    for tool in ["cargo", "rustc"] {
        let found = Command::new("sh")
            .arg("-c")
            .arg(format!("command -v {tool}"))
            .env("PATH", &path)
            .output()
            .expect("sh runs");
        assert!(
            !found.status.success(),
            "{tool} is on {path}: the wheel test must run without Rust"
        );
    }
    path
}

#[test]
fn wheel_installs_without_rust_and_passes_the_python_tests() {
    let venv = python_env();
    let wheel = python_wheel();
    let path = path_without_rust(&venv);
    let status = Command::new(venv.join("bin/pip"))
        .args([
            "install",
            "--quiet",
            "--no-deps",
            "--no-index",
            "--force-reinstall",
        ])
        .arg(&wheel)
        .env("PATH", &path)
        .status()
        .expect("pip runs");
    assert!(status.success(), "pip install {} failed", wheel.display());
    let out = Command::new(venv.join("bin/python"))
        .args(["-m", "pytest", "-q", "-s", "-rs", "-p", "no:cacheprovider"])
        .current_dir(root().join("python/tests"))
        .env("PATH", &path)
        .env("RMFSURF_REPOSITORY", root())
        .env("RMFSURF_REQUIRE_ALL", "1")
        .output()
        .unwrap_or_else(|e| panic!("cannot run pytest ({e}): {SETUP_HINT}"));
    print!("{}", String::from_utf8_lossy(&out.stdout));
    eprint!("{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        out.status.success(),
        "the Python tests failed ({})",
        out.status
    );
}

#[test]
fn pip_install_of_the_source_builds_the_library() {
    let venv: PathBuf = root().join("target/python-test/source-venv");
    let _ = std::fs::remove_dir_all(&venv);
    let made = Command::new("/usr/bin/python3")
        .args(["-m", "venv"])
        .arg(&venv)
        .status()
        .unwrap_or_else(|e| panic!("cannot run /usr/bin/python3 ({e}): {SETUP_HINT}"));
    assert!(made.success(), "python3 -m venv failed");
    let maturin = maturin_lock();
    let start = std::time::Instant::now();
    let out = Command::new(venv.join("bin/pip"))
        .args(["install", "--quiet", "--disable-pip-version-check"])
        .arg(root().join("python"))
        .output()
        .expect("pip runs");
    drop(maturin);
    assert!(
        out.status.success(),
        "pip install ./python failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    println!(
        "pip install ./python (maturin, cffi and NumPy from PyPI, the library built): {:.0} s",
        start.elapsed().as_secs_f64()
    );
    let check = "import rmfsurf, sys\n\
                 assert rmfsurf.__version__ == rmfsurf.rmf_version(), rmfsurf.__version__\n\
                 assert rmfsurf.__file__.startswith(sys.prefix), rmfsurf.__file__\n\
                 print('import rmfsurf', rmfsurf.__version__, 'from', rmfsurf.__file__)";
    let out = Command::new(venv.join("bin/python"))
        .args(["-c", check])
        .current_dir(&venv)
        .output()
        .expect("python runs");
    print!("{}", String::from_utf8_lossy(&out.stdout));
    assert!(
        out.status.success(),
        "import rmfsurf failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains(env!("CARGO_PKG_VERSION")));
}
