//! Every repository path the README and `docs/` name exists (the CHANGELOG is history: it
//! names files that have since gone):
//! the relative links `](path)` and the code spans that start with a top-level directory of
//! the repository (`src/wire/brep.rs`, `examples/cli/pipe.json`, ...). A page that names a
//! file which moved or never existed fails here. In a git checkout a path exists when git
//! tracks it (a file, or a directory holding one): a directory that only a local run created
//! (`target`, fuzz artifacts) is absent from a clean clone, so it must not count.

use std::path::{Path, PathBuf};

/// The top-level directories a code span must start with to be read as a path.
const TOP: &[&str] = &[
    "src/",
    "capi/",
    "cli/",
    "c_tests/",
    "examples/",
    "python/",
    "freecad/",
    "integration/",
    "scripts/",
    "docs/",
    "include/",
    "fuzz/",
    "benches/",
    "tests/",
];

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The pages to check: README.md and every docs/*.md.
fn pages() -> Vec<PathBuf> {
    let mut pages = vec![root().join("README.md")];
    let docs = std::fs::read_dir(root().join("docs")).expect("docs/");
    pages.extend(
        docs.map(|e| e.expect("a docs/ entry").path())
            .filter(|p| p.extension().is_some_and(|x| x == "md")),
    );
    pages.sort();
    pages
}

/// The spans between backticks (outside fenced blocks).
fn code_spans(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        out.extend(line.split('`').skip(1).step_by(2));
    }
    out
}

/// The targets of relative markdown links `](target)`, without their anchors.
fn link_targets(text: &str) -> Vec<&str> {
    text.split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .map(|t| t.split('#').next().unwrap_or(""))
        .filter(|t| !t.is_empty() && !t.contains("://") && !t.starts_with("mailto:"))
        .collect()
}

/// A code span read as a repository path: its first word, if it starts with a top-level
/// directory and names one file or directory (no placeholder, glob or option).
fn as_path(span: &str) -> Option<&str> {
    let word = span.split_whitespace().next()?;
    let word = word.split(':').next()?.trim_end_matches([',', '.', ';']);
    let candidate = TOP.iter().any(|t| word.starts_with(t));
    let concrete = !word.contains(['<', '>', '*', '{', '}', '$', '…', '[', '(']);
    (candidate && concrete).then_some(word)
}

/// The files git tracks, relative to the root; `None` outside a git checkout.
fn tracked() -> Option<Vec<String>> {
    let out = std::process::Command::new("git")
        .args(["ls-files", "-z"])
        .current_dir(root())
        .output()
        .ok()?;
    let text = String::from_utf8(out.stdout).ok()?;
    let files: Vec<String> = text
        .split('\0')
        .filter(|f| !f.is_empty())
        .map(String::from)
        .collect();
    (out.status.success() && !files.is_empty()).then_some(files)
}

/// Whether `path` (relative to the root, maybe with a trailing `/`) is in the repository.
fn exists(path: &str, tracked: Option<&[String]>) -> bool {
    let Some(files) = tracked else {
        return root().join(path).exists();
    };
    let path = path.trim_end_matches('/');
    let dir = format!("{path}/");
    files.iter().any(|f| f == path || f.starts_with(&dir))
}

/// The paths a page names that do not exist.
fn missing(page: &Path) -> Vec<String> {
    let tracked = tracked();
    let text = std::fs::read_to_string(page).expect("a page");
    let dir = page.parent().expect("the page's directory");
    let mut missing = Vec::new();
    for target in link_targets(&text) {
        if !dir.join(target).exists() {
            missing.push(format!("link {target}"));
        }
    }
    for path in code_spans(&text).into_iter().filter_map(as_path) {
        if !exists(path, tracked.as_deref()) {
            missing.push(path.to_string());
        }
    }
    missing
}

#[test]
fn every_path_the_readme_and_docs_name_exists() {
    let pages = pages();
    assert!(pages.len() >= 15, "{pages:?}");
    let faults: Vec<String> = pages
        .iter()
        .flat_map(|p| {
            let name = p.strip_prefix(root()).unwrap().display().to_string();
            missing(p).into_iter().map(move |m| format!("{name}: {m}"))
        })
        .collect();
    assert!(
        faults.is_empty(),
        "paths named but absent:\n{}",
        faults.join("\n")
    );
}

#[test]
fn the_check_finds_an_absent_path_and_a_broken_link() {
    let page = std::env::temp_dir().join(format!("rmfsurf-doc-paths-{}.md", std::process::id()));
    std::fs::write(
        &page,
        "Run `src/no_such_module.rs` and `src/lib.rs`; see [x](no_such_page.md).\n\
         ```\nsrc/fenced_is_not_checked.rs\n```\n",
    )
    .unwrap();
    let found = missing(&page);
    std::fs::remove_file(&page).unwrap();
    assert_eq!(found, ["link no_such_page.md", "src/no_such_module.rs"]);
}

#[test]
fn a_directory_only_a_local_run_created_is_absent() {
    let files = ["src/lib.rs".to_string(), "fuzz/run".to_string()];
    assert!(exists("src/lib.rs", Some(&files)));
    assert!(exists("src/", Some(&files)));
    assert!(exists("fuzz/", Some(&files)));
    assert!(!exists("fuzz/artifacts/", Some(&files)));
    assert!(!exists("src/li", Some(&files)));
}
