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

mod support;

use std::path::Path;
use std::process::Command;
use support::{build, fresh_dir, root, run, toolchain, vtk_flags, SETUP_HINT, STRICT};

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

/// Every complete C program of the pages in docs/ (a block with `int main`) compiles and
/// runs, in a scratch directory (the wire sweep example writes pipe.step).
#[test]
fn docs_c_programs_compile_and_run() {
    let mut pages: Vec<_> = std::fs::read_dir(root().join("docs"))
        .expect("docs/")
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    pages.sort();
    let dir = fresh_dir("docs_programs");
    let mut count = 0;
    for page in &pages {
        let text = std::fs::read_to_string(page).expect("a docs page");
        let blocks = text
            .split("```c\n")
            .skip(1)
            .filter_map(|b| b.split("```").next())
            .filter(|b| b.contains("int main("));
        for block in blocks {
            count += 1;
            let name = format!("docs_program_{count}");
            let source = dir.join(format!("{name}.c"));
            std::fs::write(&source, block).expect("example written");
            let mut flags = vec!["-std=c99"];
            flags.extend(STRICT);
            let source = source.to_str().expect("UTF-8 path").to_string();
            let exe = build(&name, false, &[source.as_str()], &flags, &[]);
            let out = Command::new(&exe)
                .current_dir(&dir)
                .output()
                .expect("the example runs");
            print!("{}", String::from_utf8_lossy(&out.stdout));
            assert!(
                out.status.success(),
                "the C program {count} of {} failed: {}",
                page.display(),
                String::from_utf8_lossy(&out.stderr)
            );
        }
    }
    assert!(count >= 3, "the C programs of docs/: {count}");
    assert!(
        dir.join("pipe.step").exists(),
        "the wire sweep example writes pipe.step"
    );
}
