//! The committed header `include/rmfsurf.h` must be exactly what the pinned cbindgen
//! generates from the sources. Regenerate it with
//! `RMFSURF_BLESS_HEADER=1 cargo test --test header`.

use std::path::Path;

#[test]
fn committed_header_is_what_cbindgen_generates() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config =
        cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml parses");
    let bindings = cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = root.join("../include/rmfsurf.h");
    if std::env::var_os("RMFSURF_BLESS_HEADER").is_some() {
        std::fs::write(&path, &generated).expect("header written");
        return;
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/rmfsurf.h is stale: regenerate it with `RMFSURF_BLESS_HEADER=1 cargo test --test header` and commit it"
    );
}
