//! Wire sweeps against OpenCascade's `BRepOffsetAPI_MakePipeShell` (FreeCAD's Part Sweep),
//! the same wires in one run (`cargo bench --bench wire`, part of `scripts/bench`): a pipe
//! route of lines and an arc, the same with a NURBS edge, a 3-D polyline with round and
//! with miter corners, a closed rounded rectangle, a closed NURBS. rmfsurf's solid is written
//! as STEP and read back by OpenCascade; all three sweeps (rmfsurf, corrected Frenet,
//! Frenet) are measured by the same OpenCascade code (`benches/occ/wire_pipe_shell.cpp`):
//! validity, volume error against the closed form (or against rmfsurf's), max |cos| between
//! parameter lines, B-spline poles, and the build time (the fastest of several; rmfsurf from
//! the edges to the finished B-rep).

mod support;

use rmfsurf::glam::DVec3;
use rmfsurf::{wire::sweep as sweep_wire, wire::Corner, wire::Edge, wire::Shape, wire::WireSweep};
use rmfsurf::{NurbsCurve, PiecewiseCurve, RationalBezierCurve};
use std::f64::consts::{FRAC_1_SQRT_2, PI};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use support::timed;

/// One wire of the table.
struct Case {
    name: &'static str,
    edges: Vec<Edge>,
    /// A circle of this radius, or a square of this half side.
    circle: bool,
    size: f64,
    corner: Corner,
    closure: u32,
    /// The closed-form volume (None: compared with rmfsurf's).
    exact: Option<f64>,
}

fn line(a: [f64; 3], b: [f64; 3]) -> Edge {
    Edge::Line {
        from: DVec3::from(a),
        to: DVec3::from(b),
    }
}

fn arc(a: DVec3, m: DVec3, b: DVec3) -> Edge {
    Edge::Arc {
        start: a,
        through: m,
        end: b,
    }
}

fn nurbs(degree: usize, poles: Vec<DVec3>, knots: Vec<f64>) -> Edge {
    Edge::Curve(
        NurbsCurve::new(degree, poles, None, knots)
            .unwrap()
            .to_piecewise()
            .unwrap(),
    )
}

fn cases() -> Vec<Case> {
    let s = FRAC_1_SQRT_2;
    let route = vec![
        line([0., 0., 0.], [10., 0., 0.]),
        arc(
            DVec3::new(10., 0., 0.),
            DVec3::new(10. + 5. * s, 5. - 5. * s, 0.),
            DVec3::new(15., 5., 0.),
        ),
        line([15., 5., 0.], [15., 15., 0.]),
    ];
    let mut with_nurbs = route.clone();
    with_nurbs.push(nurbs(
        3,
        vec![
            DVec3::new(15., 15., 0.),
            DVec3::new(15., 20., 0.),
            DVec3::new(20., 25., 5.),
            DVec3::new(25., 25., 5.),
        ],
        vec![0., 0., 0., 0., 1., 1., 1., 1.],
    ));
    let stairs = vec![
        line([0., 0., 0.], [6., 0., 0.]),
        line([6., 0., 0.], [6., 6., 0.]),
        line([6., 6., 0.], [6., 6., 6.]),
        line([6., 6., 6.], [0., 6., 6.]),
    ];
    let quarter = |c: (f64, f64), a: f64| {
        let p = |t: f64| DVec3::new(c.0 + t.cos(), c.1 + t.sin(), 0.0);
        arc(p(a), p(a + PI / 4.0), p(a + PI / 2.0))
    };
    let rounded = vec![
        line([0., -1., 0.], [4., -1., 0.]),
        quarter((4., 0.), -PI / 2.0),
        line([5., 0., 0.], [5., 2., 0.]),
        quarter((4., 2.), 0.0),
        line([4., 3., 0.], [0., 3., 0.]),
        quarter((0., 2.), PI / 2.0),
        line([-1., 2., 0.], [-1., 0., 0.]),
        quarter((0., 0.), PI),
    ];
    vec![
        Case {
            name: "line-arc-line, circle r = 1",
            edges: route,
            circle: true,
            size: 1.0,
            corner: Corner::Round(None),
            closure: 0,
            exact: Some(PI * (20.0 + 2.5 * PI)),
        },
        Case {
            name: "line-arc-line-NURBS, circle r = 1",
            edges: with_nurbs,
            circle: true,
            size: 1.0,
            corner: Corner::Round(None),
            closure: 0,
            exact: None,
        },
        Case {
            name: "polyline, round corners r = 1, square",
            edges: stairs.clone(),
            circle: false,
            size: 0.5,
            corner: Corner::Round(Some(1.0)),
            closure: 0,
            exact: Some(24.0 - 3.0 * (2.0 - PI / 2.0)),
        },
        Case {
            name: "polyline, miter corners, square",
            edges: stairs,
            circle: false,
            size: 0.5,
            corner: Corner::Miter,
            closure: 0,
            exact: Some(24.0),
        },
        Case {
            name: "rounded rectangle (closed), square",
            edges: rounded,
            circle: false,
            size: 0.2,
            corner: Corner::Round(None),
            closure: 1,
            exact: Some(0.16 * (12.0 + 2.0 * PI)),
        },
        Case {
            name: "closed NURBS, square",
            edges: vec![closed_nurbs()],
            circle: false,
            size: 0.3,
            corner: Corner::Round(None),
            closure: 4,
            exact: None,
        },
    ]
}

/// Eight uniform spans of a periodic cubic B-spline through a bent loop, as Bézier segments.
fn closed_nurbs() -> Edge {
    let c: Vec<DVec3> = (0..8)
        .map(|k| {
            let a = 2.0 * PI * k as f64 / 8.0;
            DVec3::new(4.0 * a.cos(), 3.0 * a.sin(), 1.5 * (2.0 * a).sin())
        })
        .collect();
    let segments = (0..8)
        .map(|k| {
            let (a, b, d, e) = (c[k], c[(k + 1) % 8], c[(k + 2) % 8], c[(k + 3) % 8]);
            RationalBezierCurve::polynomial(&[
                (a + 4.0 * b + d) / 6.0,
                (2.0 * b + d) / 3.0,
                (b + 2.0 * d) / 3.0,
                (b + 4.0 * d + e) / 6.0,
            ])
            .unwrap()
        })
        .collect();
    Edge::Curve(PiecewiseCurve::with_unit_intervals(segments).unwrap())
}

fn profile(case: &Case) -> PiecewiseCurve {
    let a = case.size;
    if case.circle {
        let c = [
            (1., 0.),
            (1., 1.),
            (0., 1.),
            (-1., 1.),
            (-1., 0.),
            (-1., -1.),
            (0., -1.),
            (1., -1.),
            (1., 0.),
        ];
        let poles = c
            .iter()
            .map(|&(x, y)| DVec3::new(a * x, a * y, 0.0))
            .collect();
        let weights = (0..9)
            .map(|k| if k % 2 == 1 { FRAC_1_SQRT_2 } else { 1.0 })
            .collect();
        let knots = vec![0., 0., 0., 1., 1., 2., 2., 3., 3., 4., 4., 4.];
        return NurbsCurve::new(2, poles, Some(weights), knots)
            .unwrap()
            .to_piecewise()
            .unwrap();
    }
    let c = [(a, a), (-a, a), (-a, -a), (a, -a), (a, a)];
    let segments = c
        .windows(2)
        .map(|w| {
            RationalBezierCurve::polynomial(&[
                DVec3::new(w[0].0, w[0].1, 0.),
                DVec3::new(w[1].0, w[1].1, 0.),
            ])
            .unwrap()
        })
        .collect();
    PiecewiseCurve::with_unit_intervals(segments).unwrap()
}

/// The wire for the C++ driver (format in wire_pipe_shell.cpp).
fn describe(case: &Case, shape: &Shape, step: &Path) -> String {
    let p = |v: DVec3| format!("{} {} {}", v.x, v.y, v.z);
    let mut text = format!("edges {}\n", case.edges.len());
    for e in &case.edges {
        match e {
            Edge::Line { from, to } => text += &format!("line {} {}\n", p(*from), p(*to)),
            Edge::Arc {
                start,
                through,
                end,
            } => text += &format!("arc {} {} {}\n", p(*start), p(*through), p(*end)),
            Edge::Curve(c) => {
                let n = NurbsCurve::from_piecewise(c).unwrap();
                text += &format!("nurbs {} {}", n.degree(), n.poles().len());
                for (q, w) in n.poles().iter().zip(n.weights()) {
                    text += &format!(" {} {w}", p(*q));
                }
                text += &format!(" {}", n.knots().len());
                for k in n.knots() {
                    text += &format!(" {k}");
                }
                text += "\n";
            }
        }
    }
    let spine = &shape.spine()[0];
    let (lo, _) = spine.domain();
    let jet = spine.eval_jet(lo);
    text += &format!(
        "profile {} {}\n",
        if case.circle { "circle" } else { "square" },
        case.size
    );
    text += &format!(
        "frame {} {} {}\n",
        p(jet.point),
        p(jet.d1.normalize()),
        p(DVec3::Z)
    );
    text += &format!(
        "corner {}\n",
        if case.corner == Corner::Miter {
            "miter"
        } else {
            "round"
        }
    );
    text += &format!("repeats {}\n", support::REPEATS);
    text += &format!("ours {}\n", step.display());
    text
}

fn occ_program() -> Result<PathBuf, String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = root.join("target").join("occ_wire_pipe_shell");
    let status = Command::new("c++")
        .args([
            "-O2",
            "-std=c++17",
            "-w",
            "-isystem",
            "/usr/include/opencascade",
        ])
        .arg(root.join("benches/occ/wire_pipe_shell.cpp"))
        .arg("-o")
        .arg(&out)
        .args([
            "-lTKSTEP",
            "-lTKXSBase",
            "-lTKOffset",
            "-lTKFillet",
            "-lTKBool",
            "-lTKBO",
            "-lTKShHealing",
            "-lTKPrim",
            "-lTKTopAlgo",
            "-lTKGeomAlgo",
            "-lTKBRep",
            "-lTKGeomBase",
            "-lTKG3d",
            "-lTKG2d",
            "-lTKMath",
            "-lTKernel",
        ])
        .status()
        .map_err(|e| format!("no C++ compiler ({e})"))?;
    if status.success() {
        Ok(out)
    } else {
        Err("building benches/occ/wire_pipe_shell.cpp failed (OpenCascade dev packages: scripts/bench installs them)".into())
    }
}

fn main() {
    println!("Wire sweeps against OpenCascade BRepOffsetAPI_MakePipeShell (FreeCAD's Part Sweep), made solid");
    println!("(fastest of {} builds; rmfsurf's solid read back by OpenCascade's STEP reader; all measured by the same OpenCascade code)\n", support::REPEATS);
    let program = match occ_program() {
        Ok(p) => p,
        Err(e) => {
            println!("skipped: {e}");
            return;
        }
    };
    println!("| wire | sweep | valid solid | volume error | max \\|cos\\| | B-spline poles (faces, analytic faces) | build time |");
    println!("| --- | --- | --- | --- | --- | --- | --- |");
    let dir = std::env::temp_dir().join(format!("rmfsurf-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for case in cases() {
        let options = WireSweep {
            corner: case.corner,
            initial_normal: Some(DVec3::Z),
            closure_symmetry: case.closure,
            tolerance: 1e-5,
            ..WireSweep::default()
        };
        let profile = profile(&case);
        let (ours_time, shape) =
            timed(|| sweep_wire(&case.edges, &profile, &[], &options).unwrap());
        let step = dir.join("shape.step");
        std::fs::write(&step, shape.to_step("bench").unwrap()).unwrap();
        let mut child = Command::new(&program)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        child
            .stdin
            .take()
            .unwrap()
            .write_all(describe(&case, &shape, &step).as_bytes())
            .unwrap();
        let out = child.wait_with_output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        let exact = case.exact.unwrap_or_else(|| shape.volume().unwrap());
        for line in text.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            let field = |key: &str| {
                words
                    .iter()
                    .position(|w| *w == key)
                    .map(|i| words[i + 1])
                    .unwrap_or("")
            };
            let number = |key: &str| field(key).parse::<f64>().unwrap_or(f64::NAN);
            let (name, time) = match words[0] {
                "rmfsurf" => ("rmfsurf", ours_time * 1e3),
                "corrected_frenet" => ("MakePipeShell, corrected Frenet", number("ms")),
                _ => ("MakePipeShell, Frenet", number("ms")),
            };
            if field("built") != "1" {
                let reason = line.split("failure ").nth(1).unwrap_or("");
                println!("| {} | {name} | failed: {reason} | | | | |", case.name);
                continue;
            }
            let faces = words
                .iter()
                .position(|w| *w == "faces")
                .map(|i| (words[i + 1], words[i + 2]))
                .unwrap_or(("", ""));
            println!(
                "| {} | {name} | {} | {:.1e} | {:.1e} | {} ({}, {}) | {:.3} ms |",
                case.name,
                if field("valid") == "1" && field("solids") == "1" {
                    "yes"
                } else {
                    "NO"
                },
                (number("volume") - exact).abs() / exact,
                number("cos"),
                field("poles"),
                faces.0,
                faces.1,
                time
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    println!("\nVolume error against the closed form (for the NURBS wires: against rmfsurf's own volume, marked by 0 in its row).");
}
