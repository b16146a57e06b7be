//! Builds and runs the C test suite in `c_tests/` against the shared library, with the
//! compilers the `cc` crate finds — all that needs only Rust and a C compiler:
//!
//! * the header compiles on its own as C99 and as C++ with -Wall -Wextra -Wpedantic -Werror;
//! * every `c_tests/abi_*.c` (C99) exercises entry points, run as it is;
//! * the README's C example and the C programs of docs/ build and run.
//!
//! The same `abi_*.c` under valgrind and under AddressSanitizer + UndefinedBehaviorSanitizer,
//! the `c_tests/geometry_*.cpp` checks with OpenMesh and VTK, and the demo are the
//! integration crate's (integration/tests/c_suite.rs). A capability adds its tests as new
//! `abi_<name>.c` / `geometry_<name>.cpp` files; both harnesses pick them up.
//!
//! The programs print their figures; run `cargo test -p rmfsurf-capi --test c_suite --
//! --nocapture` to see them.

mod support;

use std::process::Command;
use support::{build, fresh_dir, root, run, run_abi_suites, toolchain, STRICT};

#[test]
fn header_compiles_alone_as_c99_and_cpp() {
    let mut c_flags = vec!["-std=c99"];
    c_flags.extend(STRICT);
    run(&build(
        "header_c99",
        false,
        &["c_tests/header_only.c"],
        &c_flags,
        &[],
    ));
    for std in ["-std=c++11", "-std=c++17"] {
        let mut cpp_flags = vec!["-x", "c++", std];
        cpp_flags.extend(STRICT);
        run(&build(
            &format!("header_cpp{}", &std[8..]),
            true,
            &["c_tests/header_only.c"],
            &cpp_flags,
            &[],
        ));
    }
}

/// The deprecated functions are deprecated for the compiler: calling one warns with the
/// note naming its replacement, in C and in C++, unless the includer defines
/// RMF_DEPRECATED itself (as the suites that test the old wrappers do).
#[test]
fn calling_a_deprecated_function_warns_with_its_replacement() {
    let source = toolchain().out_dir.join("deprecated_call.c");
    std::fs::write(
        &source,
        "#include \"rmfsurf.h\"\n\
         int call(void) {\n\
             RmfSurface *s = 0;\n\
             return (int)rmf_nurbs_surface_create(1, 1, 0, 0, 2, 2, 0, 4, 0, 4, &s);\n\
         }\n",
    )
    .unwrap();
    let include = format!("-I{}", root().join("include").display());
    for (compiler, language) in [(&toolchain().cc, "c"), (&toolchain().cxx, "c++")] {
        let compile = |extra: &[&str]| {
            Command::new(compiler)
                .args([
                    "-x",
                    language,
                    "-c",
                    "-Werror=deprecated-declarations",
                    "-o",
                ])
                .arg(toolchain().out_dir.join("deprecated_call.o"))
                .arg(&include)
                .args(extra)
                .arg(&source)
                .output()
                .expect("the compiler runs")
        };
        let warned = compile(&[]);
        let message = String::from_utf8_lossy(&warned.stderr);
        assert!(
            !warned.status.success() && message.contains("use rmf_nurbs_surface_create_from"),
            "{language}: calling rmf_nurbs_surface_create did not warn: {message}"
        );
        let silenced = compile(&["-DRMF_DEPRECATED(note)="]);
        assert!(
            silenced.status.success(),
            "{language}: with RMF_DEPRECATED defined: {}",
            String::from_utf8_lossy(&silenced.stderr)
        );
    }
}

/// Every `c_tests/abi_*.c`: C99 ABI tests, built against the library and run as they are
/// (under valgrind and the sanitizers too by the integration crate's c_suite).
#[test]
fn abi_suites() {
    run_abi_suites("", &[], run);
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
    run(&build(
        "readme_example",
        false,
        &[source.as_str()],
        &flags,
        &[],
    ));
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
