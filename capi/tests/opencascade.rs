//! The C++ kernel examples, built against OpenCascade from Debian and run:
//! * `examples/occ/occ_kernel.cpp`: Geom_BSplineSurface from rmf_surface_nurbs, BRepCheck
//!   validity, points and derivatives against rmf_surface_eval, GeomLProp_SLProps Gaussian
//!   curvature;
//! * `examples/occ/occ_wire.cpp`: wire sweeps (rmf_wire_sweep) written as STEP and read by
//!   OpenCascade's STEPControl_Reader: one valid Solid (BRepCheck_Analyzer), the volume by
//!   BRepGProp's adaptive integration against the closed form (≤ 1e-9), the parameter lines
//!   of the faces, the corners and the seam; beside BRepOffsetAPI_MakePipeShell (corrected
//!   Frenet and Frenet) on the same wires, measured by the same code.
//!
//! The examples print their figures and fail on any of rmfsurf's.
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

/// What the wire example links in addition: STEP, the sweep (TKOffset) and what they use.
const WIRE_TOOLKITS: [&str; 6] = [
    "TKSTEP",
    "TKXSBase",
    "TKOffset",
    "TKFillet",
    "TKBool",
    "TKShHealing",
];

#[test]
fn opencascade_reads_the_wire_sweeps_as_valid_solids() {
    let include = Path::new("/usr/include/opencascade");
    assert!(
        include.join("STEPControl_Reader.hxx").exists(),
        "OpenCascade's STEP headers (libocct-data-exchange-dev) not found: {SETUP_HINT}"
    );
    let system = format!("-isystem{}", include.display());
    let mut flags = vec!["-std=c++17", system.as_str()];
    flags.extend(STRICT);
    let libs: Vec<String> = WIRE_TOOLKITS
        .iter()
        .chain(&TOOLKITS)
        .map(|t| format!("-l{t}"))
        .collect();
    let exe = build(
        "occ_wire",
        true,
        &["examples/occ/occ_wire.cpp"],
        &flags,
        &libs,
    );
    run(&exe, false);
}

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
