//! Replays the committed fuzz corpus through the fuzz harness, on a stable toolchain and
//! without libFuzzer: every input in `fuzz/corpus/<target>/` (the interesting inputs the
//! fuzzers kept) and in `fuzz/regressions/<target>/` (each input that once broke the
//! contract, named after the finding) runs through the same function the fuzz target calls,
//! which checks the C API's contract after every call (`fuzz/src/session.rs`).

#[path = "../../fuzz/src/lib.rs"]
#[allow(dead_code)]
mod harness;

use std::path::{Path, PathBuf};

fn inputs(kind: &str, target: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../fuzz")
        .join(kind)
        .join(target);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|entries| entries.filter_map(|e| Some(e.ok()?.path())).collect())
        .unwrap_or_default();
    files.sort();
    files
}

/// Runs every input of `kind` for every target; returns how many ran.
fn replay(kind: &str) -> usize {
    let mut total = 0;
    for (target, run) in harness::TARGETS {
        let files = inputs(kind, target);
        for file in &files {
            let data = std::fs::read(file).expect("corpus file");
            if let Err(panic) = std::panic::catch_unwind(|| run(&data)) {
                std::panic::resume_unwind(Box::new(format!(
                    "{} broke the contract: {:?}",
                    file.display(),
                    panic
                        .downcast_ref::<String>()
                        .cloned()
                        .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                )));
            }
        }
        println!("fuzz {kind}: {target}: {} inputs", files.len());
        total += files.len();
    }
    total
}

#[test]
fn the_committed_corpus_keeps_the_contract() {
    for (target, _) in harness::TARGETS {
        assert!(
            !inputs("corpus", target).is_empty(),
            "fuzz/corpus/{target}/ is empty"
        );
    }
    replay("corpus");
}

#[test]
fn every_former_finding_keeps_the_contract() {
    assert!(replay("regressions") > 0, "no regression inputs found");
}
