//! Builds and runs the C/C++ test suite in `c_tests/` against the shared library, with the
//! compilers the `cc` crate finds:
//!
//! * the header compiles on its own as C99 and as C++ with -Wall -Wextra -Wpedantic -Werror;
//! * every `c_tests/abi_*.c` (C99) exercises entry points, under valgrind (no leaks, no
//!   errors) and again built with AddressSanitizer + UndefinedBehaviorSanitizer;
//! * every `c_tests/geometry_*.cpp` checks surfaces independently with the suite's own NURBS
//!   evaluator, OpenMesh and VTK (Debian packages libopenmesh-dev and libvtk9-dev);
//! * the demo and the README's C example build and run.
//!
//! A capability adds its tests as new `abi_<name>.c` / `geometry_<name>.cpp` files; this
//! harness picks them up.
//!
//! The programs print their figures; run `cargo test --test c_suite -- --nocapture` to see
//! them. Missing system packages make the tests fail with a message naming the setup
//! command (README), never skip.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

const SETUP_HINT: &str =
    "run the README's test command (scripts/test), which installs the Debian packages";

struct Toolchain {
    cc: PathBuf,
    cxx: PathBuf,
    /// target/<profile>, where cargo put librmfsurf.so.
    lib_dir: PathBuf,
    /// Where the test programs go.
    out_dir: PathBuf,
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Builds the cdylib (cargo test itself only builds the rlib) and finds the compilers; once.
fn toolchain() -> &'static Toolchain {
    static TOOLCHAIN: OnceLock<Toolchain> = OnceLock::new();
    TOOLCHAIN.get_or_init(|| {
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let status = Command::new(cargo)
            .args(["build", "--lib", "--quiet"])
            .current_dir(root())
            .status()
            .expect("cargo runs");
        assert!(status.success(), "cargo build --lib failed");
        // The test binary lives in target/<profile>/deps.
        let exe = std::env::current_exe().expect("test binary path");
        let lib_dir = exe
            .parent()
            .and_then(Path::parent)
            .expect("target/<profile>")
            .to_path_buf();
        assert!(
            lib_dir.join("librmfsurf.so").exists(),
            "librmfsurf.so not found in {}",
            lib_dir.display()
        );
        let out_dir = lib_dir.join("c_tests");
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

/// The VTK include directory (/usr/include/vtk-X.Y) and its version suffix.
fn vtk() -> (PathBuf, String) {
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

const STRICT: &[&str] = &["-Wall", "-Wextra", "-Wpedantic", "-Werror"];

/// Compiles `sources` (relative to c_tests/) into `name` with `flags`, linked against
/// librmfsurf and `libs`.
fn build(name: &str, cpp: bool, sources: &[&str], flags: &[&str], libs: &[String]) -> PathBuf {
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
fn run(exe: &Path, valgrind: bool) {
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

#[test]
fn header_compiles_alone_as_c99_and_cpp() {
    let mut c_flags = vec!["-std=c99"];
    c_flags.extend(STRICT);
    run(
        &build(
            "header_c99",
            false,
            &["c_tests/header_only.c"],
            &c_flags,
            &[],
        ),
        false,
    );
    for std in ["-std=c++11", "-std=c++17"] {
        let mut cpp_flags = vec!["-x", "c++", std];
        cpp_flags.extend(STRICT);
        run(
            &build(
                &format!("header_cpp{}", &std[8..]),
                true,
                &["c_tests/header_only.c"],
                &cpp_flags,
                &[],
            ),
            false,
        );
    }
}

/// The files in c_tests/ whose names start with `prefix` and end with `suffix`, sorted.
fn suites(prefix: &str, suffix: &str) -> Vec<String> {
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
/// suffix, and runs it under valgrind or not.
fn run_abi_suites(suffix: &str, extra: &[&str], valgrind: bool) {
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
        run(&exe, valgrind);
    }
}

/// Every `c_tests/abi_*.c`: C99 ABI tests, under valgrind (no leaks, no invalid accesses).
#[test]
fn abi_suites_under_valgrind() {
    run_abi_suites("", &[], true);
}

/// Every `c_tests/abi_*.c` again, built with AddressSanitizer (with its leak checker) and
/// UndefinedBehaviorSanitizer; any report fails the run.
#[test]
fn abi_suites_under_address_and_undefined_behavior_sanitizers() {
    let sanitize = [
        "-fsanitize=address,undefined",
        "-fno-sanitize-recover=all",
        "-fno-omit-frame-pointer",
    ];
    run_abi_suites("_asan_ubsan", &sanitize, false);
}

/// Every `c_tests/geometry_*.cpp`: independent checks with OpenMesh and VTK.
#[test]
fn geometry_suites_with_openmesh_and_vtk() {
    assert!(
        Path::new("/usr/include/OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh").exists(),
        "OpenMesh headers (libopenmesh-dev) not found: {SETUP_HINT}"
    );
    let (vtk_dir, version) = vtk();
    // VTK's own headers are not -Wpedantic clean: include them as system headers.
    let vtk_include = format!("-isystem{}", vtk_dir.display());
    let mut flags = vec!["-std=c++17", vtk_include.as_str()];
    flags.extend(STRICT);
    let mut libs: Vec<String> = [
        "CommonCore",
        "CommonDataModel",
        "CommonExecutionModel",
        "FiltersGeneral",
    ]
    .iter()
    .map(|m| format!("-lvtk{m}-{version}"))
    .collect();
    libs.push("-lOpenMeshCore".into());
    for name in suites("geometry_", ".cpp") {
        let source = format!("c_tests/{name}");
        let exe = build(
            name.trim_end_matches(".cpp"),
            true,
            &[source.as_str(), "c_tests/nurbs_eval.c"],
            &flags,
            &libs,
        );
        run(&exe, false);
    }
}

#[test]
fn demo_builds_and_writes_its_files() {
    let mut flags = vec!["-std=c99"];
    flags.extend(STRICT);
    let exe = build("demo", false, &["examples/c/demo.c"], &flags, &[]);
    let dir = toolchain().out_dir.join("demo_output");
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(&exe).arg(&dir).output().expect("demo runs");
    assert!(
        out.status.success(),
        "demo failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let listing: Vec<_> = std::fs::read_dir(&dir)
        .expect("demo output directory")
        .filter_map(Result::ok)
        .collect();
    assert!(listing.len() >= 3, "demo wrote {} files", listing.len());
    for entry in listing {
        assert!(
            entry.metadata().unwrap().len() > 100,
            "{} is (nearly) empty",
            entry.path().display()
        );
    }
}

#[test]
fn readme_c_example_compiles_and_runs() {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let start = readme.find("```c\n").expect("a C example in the README") + 5;
    let end = start + readme[start..].find("```").expect("end of the C example");
    let source = toolchain().out_dir.join("readme_example.c");
    std::fs::write(&source, &readme[start..end]).expect("example written");
    let mut flags = vec!["-std=c99"];
    flags.extend(STRICT);
    let source = source.to_str().expect("UTF-8 path").to_string();
    run(
        &build("readme_example", false, &[source.as_str()], &flags, &[]),
        false,
    );
}
