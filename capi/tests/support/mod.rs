//! What the tests that drive external programs share: building the shared library (and
//! the command-line tool), finding the C/C++ compilers with the `cc` crate, compiling test
//! programs against librmfsurf, running them with their output echoed.
//!
//! Each test binary (`c_suite`, `freecad`, `openscad`, `opencascade`, `vtk_reader`)
//! includes this module and uses a part of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, MutexGuard, OnceLock};

pub const SETUP_HINT: &str =
    "run the README's test command (scripts/test), which installs the Debian packages";

pub struct Toolchain {
    pub cc: PathBuf,
    pub cxx: PathBuf,
    /// Where librmfsurf.so (→ librmfsurf.so.N, the SONAME) and librmfsurf.a are staged
    /// for the test programs, as an installed library would be laid out.
    pub lib_dir: PathBuf,
    /// Where the test programs go.
    pub out_dir: PathBuf,
}

/// The repository root.
pub fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// Builds the C library (cargo test itself only builds the rlib), stages it under its
/// installed names and finds the compilers; once.
pub fn toolchain() -> &'static Toolchain {
    static TOOLCHAIN: OnceLock<Toolchain> = OnceLock::new();
    TOOLCHAIN.get_or_init(|| {
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let status = Command::new(cargo)
            .args(["build", "-p", "rmfsurf-capi", "--lib", "--quiet"])
            .current_dir(root())
            .status()
            .expect("cargo runs");
        assert!(status.success(), "cargo build -p rmfsurf-capi --lib failed");
        // The test binary lives in target/<profile>/deps.
        let exe = std::env::current_exe().expect("test binary path");
        let profile_dir = exe
            .parent()
            .and_then(Path::parent)
            .expect("target/<profile>")
            .to_path_buf();
        let lib_dir = stage_library(&profile_dir);
        let out_dir = profile_dir.join("c_tests");
        std::fs::create_dir_all(&out_dir).expect("output directory");
        let compiler = |cpp: bool| {
            cc::Build::new()
                .cpp(cpp)
                .target(env!("RMFSURF_TARGET"))
                .host(env!("RMFSURF_HOST"))
                .opt_level(1)
                .debug(true)
                .cargo_metadata(false)
                .out_dir(&out_dir)
                .try_get_compiler()
                .expect("a C/C++ compiler (gcc, g++)")
                .path()
                .to_path_buf()
        };
        Toolchain {
            cc: compiler(false),
            cxx: compiler(true),
            lib_dir,
            out_dir,
        }
    })
}

/// Links cargo's librmfsurf_capi.{so,a} in `profile_dir` under the names a C program
/// uses — librmfsurf.so.N (the SONAME the library carries), librmfsurf.so and
/// librmfsurf.a — in `profile_dir`/lib, and returns that directory.
fn stage_library(profile_dir: &Path) -> PathBuf {
    let lib_dir = profile_dir.join("lib");
    std::fs::create_dir_all(&lib_dir).expect("staging directory");
    let soname = format!("librmfsurf.so.{}", env!("RMFSURF_ABI_VERSION"));
    for (link, target) in [
        (soname.as_str(), "../librmfsurf_capi.so"),
        ("librmfsurf.so", soname.as_str()),
        ("librmfsurf.a", "../librmfsurf_capi.a"),
    ] {
        let path = lib_dir.join(link);
        let _ = std::fs::remove_file(&path);
        std::os::unix::fs::symlink(target, &path).expect("symlink in the staging directory");
        assert!(path.exists(), "{} does not resolve", path.display());
    }
    lib_dir
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

/// An empty directory `name` under the test output directory.
pub fn fresh_dir(name: &str) -> PathBuf {
    let dir = toolchain().out_dir.join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("output directory");
    dir
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

pub const STRICT: &[&str] = &["-Wall", "-Wextra", "-Wpedantic", "-Werror"];

/// Compiles `sources` (relative to c_tests/) into `name` with `flags`, linked against
/// librmfsurf and `libs`.
pub fn build(name: &str, cpp: bool, sources: &[&str], flags: &[&str], libs: &[String]) -> PathBuf {
    let tc = toolchain();
    let exe = tc.out_dir.join(name);
    let mut cmd = Command::new(if cpp { &tc.cxx } else { &tc.cc });
    cmd.args(flags)
        .arg("-g")
        .arg("-I")
        .arg(root().join("include"))
        .arg("-I")
        .arg(root().join("c_tests"));
    cmd.args(sources.iter().map(|s| root().join(s)));
    cmd.arg("-o")
        .arg(&exe)
        .arg("-L")
        .arg(&tc.lib_dir)
        .arg("-lrmfsurf");
    cmd.arg(format!("-Wl,-rpath,{}", tc.lib_dir.display()));
    cmd.args(libs).arg("-lm");
    let out = cmd.output().expect("compiler runs");
    assert!(
        out.status.success(),
        "compiling {name} failed:\n{:?}\n{}",
        cmd,
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

/// Runs a test program (optionally under valgrind), echoes its output and asserts success.
pub fn run(exe: &Path, valgrind: bool) {
    let mut cmd = if valgrind {
        let mut c = Command::new("valgrind");
        c.args([
            "--quiet",
            "--error-exitcode=99",
            "--leak-check=full",
            "--errors-for-leak-kinds=definite,indirect",
            "--show-leak-kinds=definite,indirect",
        ]);
        c.arg(exe);
        c
    } else {
        Command::new(exe)
    };
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot run {} ({e}): {SETUP_HINT}", exe.display()));
    print!("{}", String::from_utf8_lossy(&out.stdout));
    eprint!("{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        out.status.success(),
        "{} failed with {}",
        exe.display(),
        out.status
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
        assert!(out.status.success(), "scripts/python-env failed");
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

/// The wheel of the Python package (`pip wheel ./python`, maturin), carrying the library,
/// built once into target/python-wheel; its path.
pub fn python_wheel() -> PathBuf {
    static WHEEL: OnceLock<PathBuf> = OnceLock::new();
    WHEEL
        .get_or_init(|| {
            let dir = root().join("target/python-wheel");
            let _ = std::fs::remove_dir_all(&dir);
            let _maturin = maturin_lock();
            let start = std::time::Instant::now();
            let out = Command::new(python_env().join("bin/pip"))
                .args([
                    "wheel",
                    "--quiet",
                    "--no-deps",
                    "--disable-pip-version-check",
                ])
                .arg(root().join("python"))
                .arg("-w")
                .arg(&dir)
                .output()
                .expect("pip runs");
            assert!(
                out.status.success(),
                "pip wheel ./python failed:\n{}",
                String::from_utf8_lossy(&out.stderr)
            );
            let wheel = std::fs::read_dir(&dir)
                .expect("the wheel directory")
                .filter_map(Result::ok)
                .map(|e| e.path())
                .find(|p| p.extension().is_some_and(|x| x == "whl"))
                .expect("pip wheel wrote a wheel");
            println!(
                "pip wheel ./python: {} in {:.0} s",
                wheel.file_name().unwrap().to_string_lossy(),
                start.elapsed().as_secs_f64()
            );
            wheel
        })
        .clone()
}
