//! The C++ kernel examples, built against OpenCascade from Debian and run:
//! * `examples/occ/occ_kernel.cpp`: Geom_BSplineSurface from rmf_surface_nurbs, BRepCheck
//!   validity, points and derivatives against rmf_surface_eval, GeomLProp_SLProps Gaussian
//!   curvature;
//! * `examples/occ/occ_wire.cpp`: wire sweeps (rmf_wire_sweep) written as STEP and read by
//!   OpenCascade's STEPControl_Reader, and handed over as OpenCascade's B-rep text
//!   (rmf_shape_occ_brep, BRepTools::Read): one valid Solid (BRepCheck_Analyzer), the volume by
//!   BRepGProp's adaptive integration against the closed form (≤ 1e-9), the parameter lines
//!   of the faces, the corners and the seam; beside BRepOffsetAPI_MakePipeShell (corrected
//!   Frenet and Frenet) on the same wires, measured by the same code.
//!
//! The examples print their figures and fail on any of rmfsurf's.
//!
//! `cargo test -p rmfsurf-integration --test opencascade -- --nocapture` shows them.

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

/// What the wire example links in addition: STEP, the sweep (TKOffset), booleans (TKBO),
/// boxes (TKPrim) and what they use.
const WIRE_TOOLKITS: [&str; 8] = [
    "TKSTEP",
    "TKXSBase",
    "TKOffset",
    "TKFillet",
    "TKBool",
    "TKBO",
    "TKPrim",
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
    run(&exe);
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
    run(&exe);
}

/// OpenCascade's STEP reader (TKSTEP, libocct-data-exchange-dev) on the formed hopper of
/// examples/cli/hopper.json as the command-line tool writes it, and BRepTools::Read on the
/// library's B-rep text of the same part (`SheetPart::to_occ_brep`): one valid closed solid
/// (BRepCheck, no free edges), whose volume (BRepGProp) is t·A(t/2) — the layers of a
/// developable grow linearly in area, A(s) from the library's inner and neutral layers by
/// Gauss–Legendre quadrature.
#[test]
fn opencascade_reads_the_formed_hopper_as_a_valid_closed_solid() {
    use rmfsurf::{
        sheet::Layer, sheet::Reference, sheet::Sheet, sheet::SheetOptions, sheet::SheetPart,
    };
    let dir = support::fresh_dir("occ_hopper");
    support::run_cli(&dir, "hopper", &["-q", "-o", "hopper.step"]);
    let (bottom, top) = hopper_curves();
    let options = SheetOptions {
        tolerance: 1e-4,
        sheet: Sheet::new(2.0, 0.4, Reference::Inner).unwrap(),
        flat_tolerance: 0.0,
        max_pieces: 100_000,
    };
    let part = SheetPart::transition(&bottom, &top, &options).unwrap();
    let (inner, neutral) = (
        part.area(Layer::Inner).unwrap(),
        part.area(Layer::Neutral).unwrap(),
    );
    println!("areas of the inner and neutral layers: {inner:.9}, {neutral:.9}");
    let (t, kt) = (2.0, 0.8);
    let volume = t * (inner + 0.5 * t * (neutral - inner) / kt);
    let include = Path::new("/usr/include/opencascade");
    assert!(
        include.join("STEPControl_Reader.hxx").exists(),
        "OpenCascade's STEP headers (libocct-data-exchange-dev) not found: {SETUP_HINT}"
    );
    let system = format!("-isystem{}", include.display());
    let mut flags = vec!["-std=c++17", system.as_str()];
    flags.extend(STRICT);
    let libs: Vec<String> = ["TKSTEP", "TKSTEPBase", "TKXSBase", "TKShHealing"]
        .iter()
        .chain(TOOLKITS.iter())
        .map(|t| format!("-l{t}"))
        .collect();
    let exe = build(
        "occ_read_solid",
        true,
        &["integration/tests/programs/occ_read_solid.cpp"],
        &flags,
        &libs,
    );
    // The library's B-rep text of the same part, read by BRepTools::Read as it is.
    std::fs::write(dir.join("hopper.brep"), part.to_occ_brep().unwrap()).unwrap();
    for file in ["hopper.step", "hopper.brep"] {
        let out = std::process::Command::new(&exe)
            .arg(dir.join(file))
            .arg(format!("{volume:.12}"))
            .arg("1e-8")
            .output()
            .expect("occ_read_solid runs");
        print!("{}", String::from_utf8_lossy(&out.stdout));
        assert!(
            out.status.success(),
            "OpenCascade does not read {file} as a valid closed solid of the expected \
             volume:\n{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// The curves of examples/cli/hopper.json: the square and the circle (rational quadratics).
fn hopper_curves() -> (rmfsurf::PiecewiseCurve, rmfsurf::PiecewiseCurve) {
    use rmfsurf::glam::DVec3;
    use rmfsurf::{PiecewiseCurve, RationalBezierCurve};
    let c = [
        DVec3::new(-100.0, -100.0, 0.0),
        DVec3::new(100.0, -100.0, 0.0),
        DVec3::new(100.0, 100.0, 0.0),
        DVec3::new(-100.0, 100.0, 0.0),
    ];
    let square = (0..4)
        .map(|k| RationalBezierCurve::polynomial(&[c[k], c[(k + 1) % 4]]).unwrap())
        .collect();
    let at = |k: usize| {
        let a = k as f64 * std::f64::consts::FRAC_PI_2;
        DVec3::new(20.0 + 60.0 * a.cos(), 60.0 * a.sin(), 150.0)
    };
    let centre = DVec3::new(20.0, 0.0, 150.0);
    let circle = (0..4)
        .map(|k| {
            let (p0, p2) = (at(k), at(k + 1));
            RationalBezierCurve::from_weighted(
                &[p0, p0 + p2 - centre, p2],
                &[1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
            )
            .unwrap()
        })
        .collect();
    (
        PiecewiseCurve::with_unit_intervals(square).unwrap(),
        PiecewiseCurve::with_unit_intervals(circle).unwrap(),
    )
}
