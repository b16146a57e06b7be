//! The documentation site (scripts/docs-site): the guide, the Rust, C and Python APIs in
//! one folder, built as a user would build it; the build fails on a rustdoc or Doxygen
//! warning and on a broken internal link. The link checker is shown to catch a missing file
//! and a missing fragment.
//!
//! `cargo test -p rmfsurf-integration --test docs_site -- --nocapture` prints the counts.

mod support;

use std::process::Command;
use std::sync::Mutex;
use support::{fresh_dir, maturin_lock, python_env, root, SETUP_HINT};

/// Held by each test: both run the test environment's Python, which the site's build
/// reinstalls the package into.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

#[test]
fn the_site_builds_with_every_link_whole() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner());
    let _maturin = maturin_lock();
    let out = Command::new(root().join("scripts/docs-site"))
        .output()
        .unwrap_or_else(|e| panic!("cannot run scripts/docs-site ({e}): {SETUP_HINT}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    print!("{stdout}");
    assert!(
        out.status.success(),
        "scripts/docs-site failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let site = root().join("target/site");
    for page in [
        "index.html",
        "guide.html",
        "wire-sweeps.html",
        "images/rmfsurf.png",
        "rust/rmfsurf/index.html",
        "c/index.html",
        "c/rmfsurf_8h.html",
        "python/rmfsurf.html",
        "python/rmfsurf/ocp.html",
        "python/rmfsurf/freecad.html",
    ] {
        assert!(site.join(page).is_file(), "the site lacks {page}");
    }
    let index = std::fs::read_to_string(site.join("index.html")).unwrap();
    for href in [
        "rust/index.html",
        "c/index.html",
        "python/rmfsurf.html",
        "guide.html",
    ] {
        assert!(
            index.contains(&format!("href=\"{href}\"")),
            "index.html lacks {href}"
        );
    }
}

#[test]
fn the_link_check_finds_a_missing_page_and_a_missing_fragment() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner());
    let site = fresh_dir("docs_site_check");
    std::fs::write(site.join("b.html"), "<h1 id=\"here\">b</h1>").unwrap();
    let check = |page: &str| {
        std::fs::write(site.join("a.html"), page).unwrap();
        Command::new(python_env().join("bin/python"))
            .arg(root().join("scripts/docs_site.py"))
            .arg("--check")
            .arg(&site)
            .output()
            .expect("python runs")
    };
    let whole = check("<a href=\"b.html#here\">b</a> <a href=\"https://example.org/x\">x</a>");
    assert!(whole.status.success(), "{whole:?}");
    for broken in [
        "<a href=\"c.html\">c</a>",
        "<a href=\"b.html#there\">b</a>",
        "<img src=\"i.png\">",
    ] {
        let out = check(broken);
        assert!(
            !out.status.success() && String::from_utf8_lossy(&out.stdout).contains("broken link"),
            "{broken} passed the check: {out:?}"
        );
    }
}
