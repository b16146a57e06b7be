//! The README's Rust example is `examples/rust/main.rs`, which cargo builds with the tests
//! and clippy lints: this test keeps the two equal, so the README shows code that compiles.

use std::path::Path;

#[test]
fn readme_rust_example_is_examples_rust_main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let marked = readme
        .split("<!-- rust-example -->")
        .nth(1)
        .expect("a '<!-- rust-example -->' marker in the README");
    let start = marked
        .find("```rust\n")
        .expect("a Rust block after the marker")
        + 8;
    let end = start
        + marked[start..]
            .find("```")
            .expect("the end of the Rust block");
    let example =
        std::fs::read_to_string(root.join("examples/rust/main.rs")).expect("examples/rust/main.rs");
    assert_eq!(
        marked[start..end].trim(),
        example.trim(),
        "the README's Rust example differs from examples/rust/main.rs"
    );
}
