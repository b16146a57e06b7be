//! What the tests that build C and C++ programs against librmfsurf share: building the
//! shared library, finding the C/C++ compilers with the `cc` crate, compiling test programs
//! against it, running them with their output echoed.
//!
//! Needs only Rust and a C compiler: capi's `c_suite` uses it, and the integration crate's
//! support module (integration/tests/support), which adds what drives the external
//! programs, includes this file — one copy of these functions for both crates.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// What a test that misses a program or a library says: the command that installs them.
pub const SETUP_HINT: &str = "install the Debian packages the tests use with \
     `scripts/setup-debian test` (the README's test command, scripts/test, runs it)";

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
    let soname = format!("librmfsurf.so.{}", rmfsurf_capi::status::RMF_ABI_VERSION);
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

/// An empty directory `name` under the test output directory.
pub fn fresh_dir(name: &str) -> PathBuf {
    let dir = toolchain().out_dir.join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("output directory");
    dir
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

/// Runs a test program, echoes its output and asserts success.
pub fn run(exe: &Path) {
    run_command(Command::new(exe), exe);
}

/// Runs `cmd`, which runs the test program `exe` (itself, or under a checker), echoes its
/// output and asserts success.
pub fn run_command(mut cmd: Command, exe: &Path) {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cmd:?} ({e}): {SETUP_HINT}"));
    print!("{}", String::from_utf8_lossy(&out.stdout));
    eprint!("{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        out.status.success(),
        "{} failed with {}",
        exe.display(),
        out.status
    );
}

/// The files in c_tests/ whose names start with `prefix` and end with `suffix`, sorted.
pub fn suites(prefix: &str, suffix: &str) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("c_tests"))
        .expect("c_tests/")
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.starts_with(prefix) && n.ends_with(suffix))
        .collect();
    names.sort();
    assert!(!names.is_empty(), "no c_tests/{prefix}*{suffix}");
    names
}

/// Builds every `c_tests/abi_*.c` (C99, with -pthread) with `extra` flags under a name
/// suffix, and runs it with `run` (plainly, or under a checker).
pub fn run_abi_suites(suffix: &str, extra: &[&str], run: fn(&Path)) {
    let mut flags = vec!["-std=c99", "-pthread"];
    flags.extend(STRICT);
    flags.extend(extra);
    for name in suites("abi_", ".c") {
        let source = format!("c_tests/{name}");
        let exe_name = format!("{}{suffix}", name.trim_end_matches(".c"));
        let exe = build(
            &exe_name,
            false,
            &[source.as_str(), "c_tests/nurbs_eval.c"],
            &flags,
            &[],
        );
        run(&exe);
    }
}
