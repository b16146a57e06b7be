//! The parts of the C/C++ test suite in `c_tests/` that need more than a C compiler, built
//! against the shared library with the compilers the `cc` crate finds:
//!
//! * every `c_tests/abi_*.c` (C99) under valgrind (no leaks, no errors) and again built with
//!   AddressSanitizer + UndefinedBehaviorSanitizer;
//! * every `c_tests/geometry_*.cpp` checks surfaces independently with the suite's own NURBS
//!   evaluator, OpenMesh and VTK (Debian packages libopenmesh-dev and libvtk9-dev);
//! * the demo builds and writes its files.
//!
//! The rest — the header alone as C99 and C++, the `abi_*.c` run as they are, the README's
//! and docs' C programs — is capi's `c_suite` (capi/tests/c_suite.rs), run by a plain
//! `cargo test`. A capability adds its tests as new `abi_<name>.c` / `geometry_<name>.cpp`
//! files; both harnesses pick them up.
//!
//! The programs print their figures; run `cargo test -p rmfsurf-integration --test c_suite
//! -- --nocapture` to see them. Missing system packages make the tests fail with a message
//! naming the setup command (`scripts/setup-debian test`), never skip.

mod support;

use std::path::Path;
use std::process::Command;
use support::{
    build, run, run_abi_suites, run_under_valgrind, suites, toolchain, vtk_flags, SETUP_HINT,
    STRICT,
};

/// Every `c_tests/abi_*.c`: C99 ABI tests, under valgrind (no leaks, no invalid accesses).
#[test]
fn abi_suites_under_valgrind() {
    run_abi_suites("", &[], run_under_valgrind);
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
    run_abi_suites("_asan_ubsan", &sanitize, run);
}

/// Every `c_tests/geometry_*.cpp`: independent checks with OpenMesh and VTK.
#[test]
fn geometry_suites_with_openmesh_and_vtk() {
    assert!(
        Path::new("/usr/include/OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh").exists(),
        "OpenMesh headers (libopenmesh-dev) not found: {SETUP_HINT}"
    );
    let (vtk_include, mut libs) = vtk_flags(&[
        "CommonCore",
        "CommonDataModel",
        "CommonExecutionModel",
        "FiltersGeneral",
    ]);
    let mut flags = vec!["-std=c++17", vtk_include.as_str()];
    flags.extend(STRICT);
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
        run(&exe);
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
