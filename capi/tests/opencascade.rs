//! The C++ kernel example `examples/occ/occ_kernel.cpp`, built against OpenCascade from
//! Debian (libocct-modeling-algorithms-dev) and run: Geom_BSplineSurface from
//! rmf_surface_nurbs, BRepCheck validity, points and derivatives against rmf_surface_eval,
//! GeomLProp_SLProps Gaussian curvature. The example prints its figures and fails on any.
//!
//! `cargo test --test opencascade -- --nocapture` shows them.

mod support;

use std::path::Path;
use support::{build, run, SETUP_HINT, STRICT};

/// OpenCascade's toolkits the example links, most dependent first.
const TOOLKITS: [&str; 8] = [
    "TKTopAlgo",
    "TKGeomAlgo",
    "TKBRep",
    "TKGeomBase",
    "TKG3d",
    "TKG2d",
    "TKMath",
    "TKernel",
];

#[test]
fn opencascade_kernel_example_builds_and_checks_the_surfaces() {
    let include = Path::new("/usr/include/opencascade");
    assert!(
        include.join("Geom_BSplineSurface.hxx").exists(),
        "OpenCascade headers (libocct-modeling-data-dev) not found: {SETUP_HINT}"
    );
    // OpenCascade's headers are not -Wpedantic clean: include them as system headers.
    let system = format!("-isystem{}", include.display());
    let mut flags = vec!["-std=c++17", system.as_str()];
    flags.extend(STRICT);
    let libs: Vec<String> = TOOLKITS.iter().map(|t| format!("-l{t}")).collect();
    let exe = build(
        "occ_kernel",
        true,
        &["examples/occ/occ_kernel.cpp"],
        &flags,
        &libs,
    );
    run(&exe, false);
}
