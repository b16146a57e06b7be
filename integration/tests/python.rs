//! The Python package (python/): its distributions as published (scripts/python-dist), each
//! installed the way users get it beside the tests' requirements
//! (python/tests/requirements.txt: build123d and OCP, pytest), and then its test suite
//! (python/tests) run against the installed copy:
//!
//!  - the manylinux wheel, carrying the library, linked against glibc 2.17's symbols (read
//!    here from the library itself, not only from auditwheel's verdict), installed with no
//!    Rust toolchain on the PATH into the test environment (scripts/python-env: built by
//!    the test command on a fresh machine, kept between runs);
//!  - the sdist, which pip builds in a fresh virtual environment — it fetches maturin,
//!    which builds the library with Rust; `rmfsurf.__version__ == rmf_version()`.
//!
//! pytest runs with RMFSURF_REQUIRE_ALL=1: python/tests/conftest.py then turns every skip
//! (a module `pytest.importorskip` does not find, a `skipif` whose condition holds) into a
//! failure, so a missing build123d, OCP or FreeCAD fails the test instead of passing by.
//!
//! `cargo test -p rmfsurf-integration --test python -- --nocapture` shows pytest's report.

mod support;

use std::path::{Path, PathBuf};
use std::process::Command;
use support::{python_dists, python_env, python_wheel, root, SETUP_HINT};

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

/// Runs python/tests with the Python of `venv` (RMFSURF_REQUIRE_ALL: a skip fails); asserts
/// that they pass.
fn run_python_tests(venv: &Path, path: &str) {
    let out = Command::new(venv.join("bin/python"))
        .args(["-m", "pytest", "-q", "-s", "-rs", "-p", "no:cacheprovider"])
        .current_dir(root().join("python/tests"))
        .env("PATH", path)
        .env("RMFSURF_REPOSITORY", root())
        .env("RMFSURF_REQUIRE_ALL", "1")
        .output()
        .unwrap_or_else(|e| panic!("cannot run pytest ({e}): {SETUP_HINT}"));
    print!("{}", String::from_utf8_lossy(&out.stdout));
    eprint!("{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        out.status.success(),
        "the Python tests failed in {} ({})",
        venv.display(),
        out.status
    );
}

/// The newest GLIBC_x.y symbol version the ELF file `library` needs (objdump -T).
fn newest_glibc_symbol(library: &Path) -> (u32, u32) {
    let out = Command::new("objdump")
        .arg("-T")
        .arg(library)
        .output()
        .unwrap_or_else(|e| panic!("cannot run objdump ({e}): {SETUP_HINT}"));
    assert!(out.status.success(), "objdump -T {}", library.display());
    String::from_utf8_lossy(&out.stdout)
        .split_whitespace()
        .filter_map(|word| word.strip_prefix("(GLIBC_").or(word.strip_prefix("GLIBC_")))
        .filter_map(|v| {
            let mut parts = v.trim_end_matches(')').split('.');
            Some((parts.next()?.parse().ok()?, parts.next()?.parse().ok()?))
        })
        .max()
        .expect("the library uses versioned glibc symbols")
}

#[test]
fn the_wheel_is_manylinux_2_17_and_carries_the_licenses() {
    let wheel = python_wheel();
    let name = wheel.file_name().unwrap().to_string_lossy().into_owned();
    assert!(
        name.ends_with("manylinux_2_17_x86_64.whl"),
        "{name}: not tagged manylinux_2_17_x86_64"
    );
    let dir = root().join("target/python-test/wheel-contents");
    let _ = std::fs::remove_dir_all(&dir);
    let status = Command::new("/usr/bin/python3")
        .args(["-m", "zipfile", "-e"])
        .arg(&wheel)
        .arg(&dir)
        .status()
        .expect("python3 runs");
    assert!(status.success(), "cannot unpack {name}");
    let library = dir.join("rmfsurf/_native/lib_native.so");
    let newest = newest_glibc_symbol(&library);
    println!(
        "{name}: the library's newest glibc symbol is GLIBC_{}.{}",
        newest.0, newest.1
    );
    assert!(
        newest <= (2, 17),
        "{name} needs GLIBC_{}.{}",
        newest.0,
        newest.1
    );
    let info = dir.join(format!("rmfsurf-{}.dist-info", env!("CARGO_PKG_VERSION")));
    let metadata = std::fs::read_to_string(info.join("METADATA")).expect("METADATA");
    assert!(
        metadata.contains("License-Expression: MIT OR Apache-2.0"),
        "{metadata}"
    );
    for license in ["LICENSE-MIT", "LICENSE-APACHE"] {
        let carried = std::fs::read(info.join("licenses").join(license)).expect(license);
        assert_eq!(
            carried,
            std::fs::read(root().join(license)).unwrap(),
            "{license}"
        );
    }
}

/// A fresh virtual environment of Debian's Python 3.11 in target/python-test/`name`.
fn fresh_venv(name: &str) -> PathBuf {
    let venv = root().join("target/python-test").join(name);
    let _ = std::fs::remove_dir_all(&venv);
    let made = Command::new("/usr/bin/python3")
        .args(["-m", "venv"])
        .arg(&venv)
        .status()
        .unwrap_or_else(|e| panic!("cannot run /usr/bin/python3 ({e}): {SETUP_HINT}"));
    assert!(made.success(), "python3 -m venv failed");
    venv
}

/// pip installs `args` into `venv` (PATH as given); asserts success.
fn pip_install(venv: &Path, args: &[&std::ffi::OsStr], path: &str) {
    let out = Command::new(venv.join("bin/pip"))
        .args(["install", "--quiet", "--disable-pip-version-check"])
        .args(args)
        .env("PATH", path)
        .output()
        .expect("pip runs");
    assert!(
        out.status.success(),
        "pip install {args:?} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The tests' own needs (build123d and OCP, pytest: python/tests/requirements.txt).
fn install_test_requirements(venv: &Path, path: &str) {
    let requirements = root().join("python/tests/requirements.txt");
    pip_install(venv, &["-r".as_ref(), requirements.as_os_str()], path);
}

/// The wheel goes into the test environment (scripts/python-env, which the test command
/// builds on a fresh machine and keeps between runs), replacing the copy a run before left.
#[test]
fn wheel_installs_without_rust_and_passes_the_python_tests() {
    let venv = python_env();
    let wheel = python_wheel();
    let path = path_without_rust(&venv);
    pip_install(
        &venv,
        &[
            "--no-deps".as_ref(),
            "--no-index".as_ref(),
            "--force-reinstall".as_ref(),
            wheel.as_os_str(),
        ],
        &path,
    );
    run_python_tests(&venv, &path);
}

#[test]
fn the_sdist_builds_in_a_fresh_environment_and_passes_the_python_tests() {
    let sdist = &python_dists().sdist;
    let venv = fresh_venv("sdist-venv");
    let path = format!(
        "{}:{}",
        venv.join("bin").display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let start = std::time::Instant::now();
    pip_install(&venv, &[sdist.as_os_str()], &path);
    println!(
        "pip install {} (maturin, cffi and NumPy from PyPI, the library built): {:.0} s",
        sdist.file_name().unwrap().to_string_lossy(),
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
    install_test_requirements(&venv, &path);
    run_python_tests(&venv, &path);
}
