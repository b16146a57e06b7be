//! The installed library, as C and C++ projects find it: `scripts/install PREFIX` into a
//! temporary prefix, then the two consumer projects of examples/consumers/ copied out of
//! the repository and built there — a Makefile with `pkg-config --cflags --libs rmfsurf`
//! and a CMake project with `find_package(rmfsurf 0.2 REQUIRED)` linking `rmfsurf::rmfsurf`
//! and `rmfsurf::rmfsurf_static` — and run. Also checked: the SONAME (readelf), the
//! symlinks, pkg-config's version and static flags, and the CMake version file (0.2 found;
//! 1.0, 0.3 and 0.1 refused).
//!
//! `cargo test -p rmfsurf-integration --test install -- --nocapture` shows the steps.

mod support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;
use support::{root, SETUP_HINT};

const VERSION: &str = env!("CARGO_PKG_VERSION");
const ABI: u32 = rmfsurf_capi::status::RMF_ABI_VERSION;

/// A fresh directory under target/ (outside the source tree, and outside the prefix).
fn scratch(name: &str) -> PathBuf {
    let dir = root().join("target/install-test").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir.canonicalize().expect("scratch directory")
}

fn run(cmd: &mut Command) -> Output {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cmd:?} ({e}): {SETUP_HINT}"));
    print!("{}", String::from_utf8_lossy(&out.stdout));
    out
}

fn succeeds(cmd: &mut Command) -> String {
    let out = run(cmd);
    assert!(
        out.status.success(),
        "{cmd:?} failed ({}):\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// scripts/install into target/install-test/prefix, once for all tests of this file.
fn prefix() -> &'static Path {
    static PREFIX: OnceLock<PathBuf> = OnceLock::new();
    PREFIX.get_or_init(|| {
        let prefix = scratch("prefix");
        succeeds(Command::new(root().join("scripts/install")).arg(&prefix));
        prefix
    })
}

/// The consumer projects, copied out of the repository (nothing may refer back to it).
fn consumers(name: &str) -> PathBuf {
    let dir = scratch(name);
    let src = root().join("examples/consumers");
    succeeds(Command::new("cp").arg("-r").arg(&src).arg(&dir));
    dir.join("consumers")
}

fn pkg_config(args: &[&str]) -> String {
    succeeds(
        Command::new("pkg-config")
            .args(args)
            .arg("rmfsurf")
            .env("PKG_CONFIG_PATH", prefix().join("lib/pkgconfig")),
    )
    .trim()
    .to_string()
}

#[test]
fn installed_files_soname_and_symlinks() {
    let lib = prefix().join("lib");
    let real = format!("librmfsurf.so.{VERSION}");
    let soname = format!("librmfsurf.so.{ABI}");
    let link = |name: &str| {
        std::fs::read_link(lib.join(name))
            .unwrap_or_else(|e| panic!("{name} is no symlink ({e})"))
            .to_string_lossy()
            .into_owned()
    };
    assert_eq!(link("librmfsurf.so"), soname, "librmfsurf.so → SONAME");
    assert_eq!(link(&soname), real, "{soname} → the real file");
    let real_file = std::fs::symlink_metadata(lib.join(&real)).expect("the real library");
    assert!(real_file.file_type().is_file(), "{real} is a file");
    for file in ["librmfsurf.a", "pkgconfig/rmfsurf.pc"] {
        assert!(lib.join(file).is_file(), "{file} installed");
    }
    for file in ["rmfsurfConfig.cmake", "rmfsurfConfigVersion.cmake"] {
        assert!(
            lib.join("cmake/rmfsurf").join(file).is_file(),
            "{file} installed"
        );
    }
    let header = std::fs::read(prefix().join("include/rmfsurf.h")).expect("header installed");
    assert_eq!(
        header,
        std::fs::read(root().join("include/rmfsurf.h")).unwrap(),
        "the installed header is the committed one"
    );
    let builder = std::fs::read(prefix().join("include/rmfsurf_occ.hpp"))
        .expect("the OpenCascade builder installed");
    assert_eq!(
        builder,
        std::fs::read(root().join("include/rmfsurf_occ.hpp")).unwrap(),
        "the installed OpenCascade builder is the committed one"
    );
    let dynamic = succeeds(Command::new("readelf").arg("-d").arg(lib.join(&real)));
    let line = dynamic
        .lines()
        .find(|l| l.contains("(SONAME)"))
        .expect("the library has a SONAME");
    assert!(line.contains(&format!("[{soname}]")), "SONAME: {line}");
    println!("SONAME {soname}, librmfsurf.so → {soname} → {real}");
}

#[test]
fn pkg_config_describes_the_installed_library() {
    assert_eq!(pkg_config(&["--modversion"]), VERSION);
    let include = prefix().join("include");
    let lib = prefix().join("lib");
    assert_eq!(
        pkg_config(&["--cflags"]),
        format!("-I{}", include.display())
    );
    assert_eq!(
        pkg_config(&["--libs"]),
        format!("-L{} -lrmfsurf", lib.display())
    );
    let static_libs = pkg_config(&["--static", "--libs"]);
    for flag in ["-lrmfsurf", "-lm", "-lpthread"] {
        assert!(
            static_libs.split(' ').any(|f| f == flag),
            "pkg-config --static --libs lacks {flag}: {static_libs}"
        );
    }
}

#[test]
fn makefile_project_builds_with_pkg_config_and_runs() {
    let dir = consumers("make");
    let make = dir.join("make");
    succeeds(
        Command::new("make")
            .current_dir(&make)
            .env("PKG_CONFIG_PATH", prefix().join("lib/pkgconfig")),
    );
    let exe = make.join("consumer");
    let needed = succeeds(Command::new("readelf").arg("-d").arg(&exe));
    assert!(
        needed.contains(&format!("[librmfsurf.so.{ABI}]")),
        "the program records the SONAME, not the file name:\n{needed}"
    );
    let out = succeeds(Command::new(&exe).env("LD_LIBRARY_PATH", prefix().join("lib")));
    assert!(out.contains("consumer OK"), "{out}");
}

/// Configures the CMake project asking for `version`; the output of the configure step.
fn cmake_configure(project: &Path, build: &Path, version: &str) -> Output {
    run(Command::new("cmake")
        .arg("-S")
        .arg(project)
        .arg("-B")
        .arg(build)
        .arg(format!("-DCMAKE_PREFIX_PATH={}", prefix().display()))
        .arg(format!("-DRMFSURF_REQUIRED_VERSION={version}")))
}

#[test]
fn cmake_project_finds_the_package_and_links_shared_and_static() {
    let dir = consumers("cmake");
    let project = dir.join("cmake");
    let build = dir.join("build");
    let configured = cmake_configure(&project, &build, "0.2");
    assert!(
        configured.status.success(),
        "find_package(rmfsurf 0.2) failed:\n{}",
        String::from_utf8_lossy(&configured.stderr)
    );
    assert!(
        String::from_utf8_lossy(&configured.stdout)
            .contains(&format!("rmfsurf {VERSION} (ABI {ABI})")),
        "the package reports its version and ABI"
    );
    succeeds(Command::new("cmake").arg("--build").arg(&build));
    let shared = succeeds(
        Command::new("readelf")
            .arg("-d")
            .arg(build.join("consumer")),
    );
    assert!(
        shared.contains(&format!("[librmfsurf.so.{ABI}]")),
        "{shared}"
    );
    let fixed = succeeds(
        Command::new("readelf")
            .arg("-d")
            .arg(build.join("consumer_static")),
    );
    assert!(
        !fixed.contains("librmfsurf"),
        "consumer_static needs no librmfsurf.so:\n{fixed}"
    );
    for exe in ["consumer", "consumer_static"] {
        // The shared one finds the library through the RUNPATH CMake gives build trees.
        let out = succeeds(&mut Command::new(build.join(exe)));
        assert!(out.contains("consumer OK"), "{exe}: {out}");
    }
}

#[test]
fn cmake_version_file_refuses_other_versions() {
    let dir = consumers("cmake_versions");
    let project = dir.join("cmake");
    // 0.x: a request for 0.Y is met only by 0.Y.Z ≥ it; 1.0 by no 0.x.
    for (version, accepted) in [
        ("0.2", true),
        ("0.2.0", true),
        ("1.0", false),
        ("0.3", false),
        ("0.1", false),
    ] {
        let out = cmake_configure(&project, &dir.join(format!("build-{version}")), version);
        let stderr = String::from_utf8_lossy(&out.stderr);
        println!(
            "find_package(rmfsurf {version}): {}",
            if out.status.success() {
                "found"
            } else {
                "refused"
            }
        );
        assert_eq!(
            out.status.success(),
            accepted,
            "find_package(rmfsurf {version}):\n{stderr}"
        );
        if !accepted {
            assert!(
                stderr.contains(&format!("version: {VERSION}")),
                "CMake names the version it refused:\n{stderr}"
            );
        }
    }
}

/// The commands of docs/install.md ("C and C++"), run as written in a scratch directory
/// holding the consumer projects (and `scripts/install`, forwarding to this repository's),
/// with PREFIX a prefix of its own instead of ~/.local.
#[test]
fn docs_install_commands_run() {
    let text = std::fs::read_to_string(root().join("docs/install.md")).expect("docs/install.md");
    let section = text
        .find("## C and C++")
        .expect("docs/install.md has ## C and C++");
    let start = section + text[section..].find("```sh\n").expect("a sh block") + 6;
    let end = start + text[start..].find("```").expect("the end of the block");
    let commands: String = text[start..end]
        .lines()
        .filter(|l| !l.starts_with("PREFIX="))
        .map(|l| format!("{l}\n"))
        .collect();
    let dir = consumers("docs").parent().expect("scratch").to_path_buf();
    std::fs::create_dir_all(dir.join("examples")).unwrap();
    std::fs::rename(dir.join("consumers"), dir.join("examples/consumers")).unwrap();
    std::fs::create_dir_all(dir.join("scripts")).unwrap();
    let forward = format!(
        "#!/bin/sh\nexec {:?} \"$@\"\n",
        root().join("scripts/install").canonicalize().unwrap()
    );
    std::fs::write(dir.join("scripts/install"), forward).unwrap();
    succeeds(
        Command::new("chmod")
            .arg("+x")
            .arg(dir.join("scripts/install")),
    );
    let out = succeeds(
        Command::new("bash")
            .args(["-euo", "pipefail", "-c", &commands])
            .current_dir(&dir)
            .env("PREFIX", scratch("docs-prefix")),
    );
    assert_eq!(
        out.matches("consumer OK").count(),
        3,
        "the Makefile, shared and static CMake consumers ran:\n{out}"
    );
}
