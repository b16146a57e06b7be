//! The command-line tool as a user meets it: `--help` and its examples, every output
//! format, the summary, and bad input — malformed JSON, unknown methods and fields, bad
//! numbers, missing files, unwritable outputs — each with a message naming the field or
//! file, a non-zero exit status, and no output files left behind.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

const TOOL: &str = env!("CARGO_BIN_EXE_rmfsurf");

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/cli")
}

/// A fresh, empty directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn tool(dir: &Path, args: &[&str], stdin: Option<&str>) -> Output {
    let mut child = Command::new(TOOL)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the tool starts");
    // The tool may exit before reading its input (bad options): ignore a broken pipe.
    let _ = child
        .stdin
        .take()
        .unwrap()
        .write_all(stdin.unwrap_or("").as_bytes());
    child.wait_with_output().unwrap()
}

fn files_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

/// Runs the tool on `json` (from standard input), expecting failure with exit status 1, a
/// message containing every one of `expected`, and nothing written.
fn fails_with(name: &str, json: &str, expected: &[&str]) {
    let dir = scratch(name);
    let out = tool(&dir, &["-", "-o", "out.step", "-o", "out.scad"], Some(json));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{name}: {stderr}");
    for e in expected {
        assert!(stderr.contains(e), "{name}: {stderr:?} should say {e:?}");
    }
    assert!(
        files_in(&dir).is_empty(),
        "{name}: wrote {:?}",
        files_in(&dir)
    );
}

const GOOD_SWEEP: &str = r#"{"sweep": {"spine": {"points": [[1,0,0],[0,1,0.5],[-1,0,1]],
    "tangents": [[0,1,0.3],[-1,0,0.3],[0,-1,0.3]]}, "profile": {"circle": {"radius": 0.1}}}}"#;

#[test]
fn help_lists_the_formats_and_its_example_runs() {
    let dir = scratch("help");
    let out = tool(&dir, &["--help"], None);
    assert!(out.status.success());
    let help = String::from_utf8_lossy(&out.stdout);
    for word in [
        ".step",
        ".vtp",
        ".obj",
        ".scad",
        ".svg",
        ".dxf",
        "EXAMPLES",
        "cone_spline",
    ] {
        assert!(help.contains(word), "--help should mention {word}");
    }
    // The first example pipes JSON into the tool: run exactly that.
    let start = help.find("echo '").expect("an echo example") + 6;
    let end = start + help[start..].find("' |").expect("the end of the JSON");
    let json = &help[start..end];
    let out = tool(
        &dir,
        &["-", "-o", "tube.step", "-o", "tube.scad"],
        Some(json),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(files_in(&dir), ["tube.scad", "tube.step"]);
    let version = tool(&dir, &["--version"], None);
    assert!(String::from_utf8_lossy(&version.stdout).starts_with("rmfsurf 0."));
}

#[test]
fn every_format_and_the_summary() {
    let dir = scratch("formats");
    let cone = examples().join("cone_spline.json");
    let outputs = [
        "c.step", "c.stp", "c.vtp", "c.obj", "c.scad", "c.svg", "c.dxf", "c.json",
    ];
    let mut args = vec![cone.to_str().unwrap()];
    for o in &outputs {
        args.extend(["-o", o]);
    }
    args.extend(["--curves", "curves.step"]);
    let out = tool(&dir, &args, None);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = String::from_utf8_lossy(&out.stdout);
    assert!(summary.contains("development: boundary lengths, max relative error"));
    let mut expected: Vec<String> = outputs.iter().map(|s| s.to_string()).collect();
    expected.push("curves.step".into());
    expected.sort();
    assert_eq!(files_in(&dir), expected);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("c.json")).unwrap()).unwrap();
    let figures = &json["figures"];
    for key in [
        "fit_deviation",
        "developability",
        "boundary_length_error",
        "ruling_length_error",
        "ruling_angle_error",
        "flatness",
    ] {
        let value = figures[key]
            .as_f64()
            .unwrap_or_else(|| panic!("figure {key}"));
        assert!(value < 1e-3, "{key} = {value}");
    }
    let dxf = std::fs::read_to_string(dir.join("c.dxf")).unwrap();
    assert!(dxf.contains("\nARC\n") && dxf.contains("\nLINE\n") && !dxf.contains("POLYLINE"));
    let svg = std::fs::read_to_string(dir.join("c.svg")).unwrap();
    assert!(svg.contains(" A ") && svg.contains("mm\""));
    // Sweeps: every method.
    for method in ["ph-rmf", "frenet", "mobius", "rrmf"] {
        let json = GOOD_SWEEP.replace(
            "\"profile\"",
            &format!("\"method\": \"{method}\", \"profile\""),
        );
        let out = tool(&dir, &["-", "-o", "sweep.json"], Some(&json));
        assert!(
            out.status.success(),
            "{method}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let figures: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap())
                .unwrap();
        let defect = figures["figures"]["rmf_defect"].as_f64().unwrap();
        // The Frenet frame turns about the tangent; the exact rational RMFs do not, and the
        // PH cubic one follows the exact RMF (of two 90° segments here) to its accuracy.
        match method {
            "frenet" => assert!(defect > 0.1, "{method}: {defect}"),
            "ph-rmf" => {
                let angle = figures["figures"]["rmf_angle_error"].as_f64().unwrap();
                assert!(defect < 1e-3 && angle < 1e-3, "{method}: {defect}, {angle}");
            }
            _ => assert!(defect < 1e-12, "{method}: {defect}"),
        }
    }
}

#[test]
fn bad_json_is_reported_at_the_field() {
    fails_with(
        "malformed",
        "{\"sweep\": {",
        &["(stdin): malformed JSON", "line 1"],
    );
    fails_with(
        "method",
        &GOOD_SWEEP.replace("\"profile\"", "\"method\": \"spline\", \"profile\""),
        &["sweep.method: unknown method \"spline\"; expected one of ph-rmf, frenet, mobius, rrmf"],
    );
    fails_with(
        "unknown_field",
        &GOOD_SWEEP.replace("\"profile\"", "\"profil\": 1, \"profile\""),
        &["sweep.profil: unknown field"],
    );
    fails_with(
        "radius",
        &GOOD_SWEEP.replace("0.1}", "-0.1}"),
        &["sweep.profile.circle.radius: must be positive, got -0.1"],
    );
    fails_with(
        "point",
        &GOOD_SWEEP.replace("[0,1,0.5]", "[0,\"a\",0.5]"),
        &["sweep.spine.points[1][1]: must be a finite number, got a string"],
    );
    fails_with(
        "tangent_count",
        &GOOD_SWEEP.replace("[-1,0,0.3],", ""),
        &["sweep.spine.tangents: 2 tangents for 3 points"],
    );
    fails_with(
        "knots",
        r#"{"sweep": {"spine": {"nurbs": {"degree": 2, "poles": [[0,0,0],[1,1,0],[2,0,0]],
            "knots": [0, 0, 1, 0.5, 1, 1]}}, "profile": {"circle": {"radius": 0.1}}}}"#,
        &["sweep.spine.nurbs: knots decrease at index 3"],
    );
    fails_with(
        "nothing",
        "{}",
        &["(top level): needs one of sweep, cone_spline"],
    );
    fails_with(
        "strip",
        r#"{"cone_spline": {"developable": {"elements": []}, "strip": {"t_min": 1, "t_max": 0}}}"#,
        &["cone_spline.strip: t_min = 1 must be less than t_max = 0"],
    );
    fails_with(
        "open_profile",
        &GOOD_SWEEP.replace(
            r#"{"circle": {"radius": 0.1}}"#,
            r#"{"line": {"from": [0, -0.1], "to": [0, 0.1]}}"#,
        ),
        &[
            "--output out.scad",
            "needs a thickness (give mesh.thickness)",
        ],
    );
    fails_with(
        "initial_normal",
        &GOOD_SWEEP.replace(
            "\"profile\"",
            "\"initial_normal\": [0, 1, 0.3], \"profile\"",
        ),
        &["sweep.initial_normal"],
    );
}

#[test]
fn files_and_command_line_errors() {
    let dir = scratch("files");
    let out = tool(&dir, &["missing.json", "-o", "a.step"], None);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read missing.json"));
    // One unwritable output: nothing is written, not even the writable one, and no
    // temporary file stays behind.
    let out = tool(
        &dir,
        &["-", "-o", "good.step", "-o", "no/such/dir/bad.step"],
        Some(GOOD_SWEEP),
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write no/such/dir/bad.step"));
    assert!(files_in(&dir).is_empty(), "left {:?}", files_in(&dir));
    // A flat pattern of a sweep does not exist.
    let out = tool(&dir, &["-", "-o", "a.dxf"], Some(GOOD_SWEEP));
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--output a.dxf: flat patterns"));
    for (args, message) in [
        (vec!["-", "-o", "a.xyz"], "unknown format"),
        (vec![], "no input file given"),
        (vec!["-", "--frobnicate"], "unknown option --frobnicate"),
    ] {
        let out = tool(&dir, &args, Some(GOOD_SWEEP));
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains(message),
            "{args:?}"
        );
    }
    assert!(files_in(&dir).is_empty());
}

#[test]
fn docs_json_example_runs() {
    let docs = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/cad-integration.md"),
    )
    .unwrap();
    let start = docs
        .find("```json\n")
        .expect("a JSON example in docs/cad-integration.md")
        + 8;
    let end = start + docs[start..].find("```").unwrap();
    let dir = scratch("docs");
    let out = tool(
        &dir,
        &["-", "-o", "moulding.step", "-o", "moulding.scad"],
        Some(&docs[start..end]),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(files_in(&dir), ["moulding.scad", "moulding.step"]);
}

/// The issue's input (examples/cli/pipe.json): `rmfsurf pipe.json -o pipe.step` writes the
/// solid, with round corners and with miters; the summary gives its figures.
#[test]
fn wire_sweeps_write_step_solids() {
    let dir = scratch("wire");
    let pipe = examples().join("pipe.json");
    let out = tool(
        &dir,
        &[
            pipe.to_str().unwrap(),
            "-o",
            "pipe.step",
            "-o",
            "pipe.json",
            "--curves",
            "spine.step",
        ],
        None,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = String::from_utf8_lossy(&out.stdout);
    assert!(
        summary.contains("closed solid") && summary.contains("true"),
        "{summary}"
    );
    let step = std::fs::read_to_string(dir.join("pipe.step")).unwrap();
    assert!(step.contains("MANIFOLD_SOLID_BREP") && step.contains("CLOSED_SHELL"));
    let figures: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("pipe.json")).unwrap()).unwrap();
    let f = &figures["figures"];
    assert!(f["spine_distance"].as_f64().unwrap() <= 1e-4);
    assert!(f["joint_gap"].as_f64().unwrap() <= 1e-9);
    assert!(f["orthogonality"].as_f64().unwrap() <= 1e-6);
    let volume = f["volume"].as_f64().unwrap();
    assert!(volume > 40.0 && volume < 60.0, "{volume}");
    let spine = std::fs::read_to_string(dir.join("spine.step")).unwrap();
    assert!(spine.contains("GEOMETRIC_CURVE_SET"));
    let json = std::fs::read_to_string(&pipe).unwrap();
    let miter = json.replace(r#"{"round": {"radius": 2}}"#, r#""miter""#);
    assert_ne!(miter, json);
    let out = tool(&dir, &["-", "-o", "miter.step"], Some(&miter));
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Sheets of open profiles; a mesh of a wire sweep is refused, and nothing is written.
    let sheet = json.replace(
        r#"{"circle": {"radius": 1}, "holes": [{"circle": {"radius": 0.8}}]}"#,
        r#"{"line": {"from": [-1, 0], "to": [1, 0]}}"#,
    );
    let out = tool(
        &dir,
        &["-", "-o", "sheet.step"],
        Some(&sheet.replace("\"solid\": true", "\"solid\": false")),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::read_to_string(dir.join("sheet.step"))
        .unwrap()
        .contains("OPEN_SHELL"));
    let out = tool(&dir, &["-", "-o", "mesh.obj"], Some(&json));
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("STEP solid"));
    assert!(!dir.join("mesh.obj").exists());
}

/// As `fails_with`, for a wire sweep written as STEP.
fn wire_fails_with(name: &str, json: &str, expected: &[&str]) {
    let dir = scratch(name);
    let out = tool(&dir, &["-", "-o", "out.step"], Some(json));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{name}: {stderr}");
    for e in expected {
        assert!(stderr.contains(e), "{name}: {stderr:?} should say {e:?}");
    }
    assert!(
        files_in(&dir).is_empty(),
        "{name}: wrote {:?}",
        files_in(&dir)
    );
}

#[test]
fn bad_wires_are_reported_at_the_field() {
    let json = std::fs::read_to_string(examples().join("pipe.json")).unwrap();
    wire_fails_with(
        "wire_gap",
        &json.replace(
            "[15, 5, 0], \"to\": [15, 15, 0]",
            "[15, 5.5, 0], \"to\": [15, 15, 0]",
        ),
        &[
            "sweep.spine.wire[2]",
            "edges 1 and 2 do not meet",
            "5.000e-1 apart",
        ],
    );
    wire_fails_with(
        "wire_corner",
        &json.replace(r#"{"round": {"radius": 2}}"#, r#""square""#),
        &["sweep.corner: unknown corner \"square\""],
    );
    wire_fails_with(
        "wire_radius",
        &json.replace(r#"{"radius": 2}"#, r#"{"radius": 200}"#),
        &["sweep.corner", "does not fit"],
    );
    wire_fails_with(
        "wire_open_profile",
        &json.replace(
            r#"{"circle": {"radius": 1}, "holes": [{"circle": {"radius": 0.8}}]}"#,
            r#"{"line": {"from": [-1, 0], "to": [1, 0]}}"#,
        ),
        &["sweep.profile", "a solid needs a closed profile"],
    );
    wire_fails_with(
        "wire_hole",
        &json.replace(r#"{"radius": 0.8}"#, r#"{"radius": 1.5}"#),
        &["sweep.profile.holes[0]", "lies outside the profile"],
    );
    wire_fails_with(
        "wire_fold",
        &json.replace(
            r#""circle": {"radius": 1}, "holes": [{"circle": {"radius": 0.8}}]"#,
            r#""circle": {"radius": 6}"#,
        ),
        &["sweep", "would fold"],
    );
    wire_fails_with(
        "wire_edge",
        &json.replace(
            "{\"line\": {\"from\": [0, 0, 0]",
            "{\"spline\": {\"from\": [0, 0, 0]",
        ),
        &["sweep.spine.wire[0].spline: unknown field; expected one of line, arc, nurbs"],
    );
}

/// A circle of radius 1 swept along a straight line of length 3, with `extra` keys in the
/// sweep (e.g. `"frame": "frenet", `).
fn line_job(extra: &str) -> String {
    format!(
        r#"{{"sweep": {{"spine": {{"wire": [{{"line": {{"from": [0, 0, 0], "to": [3, 0, 0]}}}}]}},
            {extra}"profile": {{"circle": {{"radius": 1}}}}}}}}"#
    )
}

/// Runs a job on standard input, writing STEP and the figures; the figures.
fn wire_figures(name: &str, json: &str) -> serde_json::Value {
    let dir = scratch(name);
    let out = tool(&dir, &["-", "-o", "out.step", "-o", "out.json"], Some(json));
    assert!(
        out.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join("out.json")).unwrap();
    serde_json::from_str::<serde_json::Value>(&text).unwrap()["figures"].clone()
}

/// `"frame"` ("rmf", "frenet", {"fixed": [x, y, z]}) and `"scale"` ([start, end]) are read
/// on wire sweeps, reported as the frame error, and refused with the field named: unknown
/// names, a fixed direction of two numbers or zero, a scale of one number or a negative
/// one, either key on a sweep along a curve, an initial normal with a frame that sets f2.
#[test]
fn wire_sweep_frames_and_scales_are_read_and_refused_at_the_field() {
    for (k, frame) in [r#""rmf""#, r#""frenet""#, r#"{"fixed": [0, 0, 1]}"#]
        .iter()
        .enumerate()
    {
        let f = wire_figures(
            &format!("wire_frame_{k}"),
            &line_job(&format!(r#""frame": {frame}, "scale": [1, 1], "#)),
        );
        let error = f["frame_error"].as_f64().unwrap();
        assert!((0.0..=1e-9).contains(&error), "{frame}: {error}");
        let volume = f["volume"].as_f64().unwrap();
        let cylinder = 3.0 * std::f64::consts::PI;
        assert!(
            (volume - cylinder).abs() <= 1e-9 * cylinder,
            "{frame}: {volume}"
        );
    }
    let cases = [
        (
            r#""frame": "binormal", "#,
            "sweep.frame: unknown frame \"binormal\"; expected rmf, frenet, {\"fixed\": [x, y, z]} \
             or {\"guide\": [edges]}",
        ),
        (
            r#""frame": {"fixed": [0, 1]}, "#,
            "sweep.frame.fixed: must be [x, y, z], got 2 numbers",
        ),
        (
            r#""frame": {"fixed": [0, 0, 0]}, "#,
            "sweep.frame.fixed: must not be zero",
        ),
        (
            r#""frame": {"fixd": [0, 0, 1]}, "#,
            "sweep.frame.fixd: unknown field",
        ),
        (r#""frame": 3, "#, "sweep.frame"),
        (
            r#""scale": [0.5], "#,
            "sweep.scale: must be [start, end], got 1 number",
        ),
        (
            r#""scale": [1, 0.5, 2], "#,
            "sweep.scale: must be [start, end], got 3 numbers",
        ),
        (
            r#""scale": [1, -0.5], "#,
            "sweep.scale[1]: must be positive, got -0.5",
        ),
        (r#""scale": 0.5, "#, "sweep.scale"),
        (
            r#""frame": "frenet", "initial_normal": [0, 0, 1], "#,
            "sweep.initial_normal: ",
        ),
    ];
    for (k, (extra, expected)) in cases.iter().enumerate() {
        wire_fails_with(
            &format!("wire_frame_bad_{k}"),
            &line_job(extra),
            &[expected],
        );
    }
    for (k, key) in [r#""frame": "frenet", "#, r#""scale": [1, 0.5], "#]
        .iter()
        .enumerate()
    {
        let name = &key[1..6];
        fails_with(
            &format!("curve_frame_{k}"),
            &GOOD_SWEEP.replace("\"profile\"", &format!("{key}\"profile\"")),
            &[&format!("sweep.{name}: only for a sweep along a wire")],
        );
    }
}

/// The helix of radius 2 about the x axis, (h t, 2 cos t, 2 sin t) with h = pitch / 2π for
/// t in [0, 2π turns], as a C¹ cubic NURBS edge: one Bézier per quarter turn, its inner
/// poles along the helix's tangents at a third of the span (Hermite interpolation).
fn helix_guide_edge(pitch: f64, turns: f64) -> String {
    let h = pitch / std::f64::consts::TAU;
    let n = (4.0 * turns).ceil() as usize;
    let span = std::f64::consts::TAU * turns / n as f64;
    let point = |t: f64| [h * t, 2.0 * t.cos(), 2.0 * t.sin()];
    let tangent = |t: f64| [h, -2.0 * t.sin(), 2.0 * t.cos()];
    let mut poles = vec![point(0.0)];
    for i in 0..n {
        let (a, b) = (span * i as f64, span * (i + 1) as f64);
        let (pa, ta, pb, tb) = (point(a), tangent(a), point(b), tangent(b));
        poles.push(std::array::from_fn(|j| pa[j] + ta[j] * span / 3.0));
        poles.push(std::array::from_fn(|j| pb[j] - tb[j] * span / 3.0));
        poles.push(pb);
    }
    let mut knots = vec![0.0; 4];
    for i in 1..n {
        knots.extend([i as f64; 3]);
    }
    knots.extend([n as f64; 4]);
    let poles: Vec<String> = poles
        .iter()
        .map(|p| format!("[{:?}, {:?}, {:?}]", p[0], p[1], p[2]))
        .collect();
    let knots: Vec<String> = knots.iter().map(|k| format!("{k:?}")).collect();
    format!(
        r#"{{"nurbs": {{"degree": 3, "poles": [{}], "knots": [{}]}}}}"#,
        poles.join(", "),
        knots.join(", ")
    )
}

/// `"pipe_frame"`: a circle of radius 0.5 along a 2-turn helix (a NURBS edge) is the same
/// pipe on the RMF (the default, degree 9 along the spine) and on the lightest frame
/// (degree 5), volumes within 1e-9 of each other; an unknown name, and the key on a sweep
/// along a curve, are refused naming `sweep.pipe_frame`.
#[test]
fn the_pipe_frame_is_read_and_refused_at_the_field() {
    let job = |extra: &str| {
        format!(
            r#"{{"sweep": {{"spine": {{"wire": [{}]}}, {extra}"profile": {{"circle": {{"radius": 0.5}}}}}}}}"#,
            helix_guide_edge(3.0, 2.0)
        )
    };
    let mut volumes = Vec::new();
    for (name, extra, degree) in [
        ("pipe_frame_default", "", 9),
        ("pipe_frame_rmf", r#""pipe_frame": "rmf", "#, 9),
        ("pipe_frame_lightest", r#""pipe_frame": "lightest", "#, 5),
    ] {
        let f = wire_figures(name, &job(extra));
        volumes.push(f["volume"].as_f64().unwrap());
        let step = std::fs::read_to_string(
            Path::new(env!("CARGO_TARGET_TMPDIR"))
                .join(name)
                .join("out.step"),
        )
        .unwrap();
        let along = format!("B_SPLINE_SURFACE(2,{degree},");
        assert!(
            step.contains(&along),
            "{name}: no face of degree (2, {degree})"
        );
        let other = if degree == 9 { 5 } else { 9 };
        let not = format!("B_SPLINE_SURFACE(2,{other},");
        assert!(
            !step.contains(&not),
            "{name}: a face of degree (2, {other})"
        );
    }
    for v in &volumes[1..] {
        assert!((v - volumes[0]).abs() <= 1e-9 * volumes[0], "{volumes:?}");
    }
    wire_fails_with(
        "pipe_frame_bad",
        &job(r#""pipe_frame": "light", "#),
        &["sweep.pipe_frame: unknown pipe frame \"light\"; expected one of rmf, lightest"],
    );
    fails_with(
        "curve_pipe_frame",
        &GOOD_SWEEP.replace("\"profile\"", "\"pipe_frame\": \"lightest\", \"profile\""),
        &["sweep.pipe_frame: only for a sweep along a wire"],
    );
}

/// `"frame": {"guide": [edges]}` (edges of the form of "wire"'s): a circle of radius 1
/// along a line of 3 with a helical guide about it (radius 2, pitch 2) turns with the guide
/// but keeps the cylinder's volume π r² L (to 1e-9), the frame followed within the
/// tolerance; a guide that does not run beside the wire, an empty guide, an edge of no
/// known kind and a guide beside a fixed direction are refused naming `sweep.frame`.
#[test]
fn a_guide_curve_frame_is_read_and_refused_at_the_field() {
    let guide = helix_guide_edge(2.0, 1.5);
    let f = wire_figures(
        "wire_guide",
        &line_job(&format!(
            r#""frame": {{"guide": [{guide}]}}, "tolerance": 1e-6, "#
        )),
    );
    let volume = f["volume"].as_f64().unwrap();
    let cylinder = 3.0 * std::f64::consts::PI;
    let error = f["frame_error"].as_f64().unwrap();
    println!(
        "circle r 1 along a line of 3, helical guide: volume {volume:.15} vs pi r^2 L \
         {cylinder:.15} (relative {:.1e}), frame error {error:.1e} rad",
        (volume - cylinder).abs() / cylinder
    );
    assert!(
        (volume - cylinder).abs() <= 1e-9 * cylinder,
        "volume {volume}, cylinder {cylinder}"
    );
    assert!((0.0..=0.25e-6).contains(&error), "{error}");
    assert_eq!(f["solid"], serde_json::json!(true));
    let cases = [
        (
            r#""frame": {"guide": [{"line": {"from": [0, 2, 0], "to": [1, 2, 0]}}]}, "#.to_string(),
            "sweep.frame: frame: the guide does not run beside the wire",
        ),
        (
            r#""frame": {"guide": []}, "#.to_string(),
            "sweep.frame.guide: needs at least one edge",
        ),
        (
            r#""frame": {"guide": [{"spline": {"from": [0, 2, 0], "to": [3, 2, 0]}}]}, "#
                .to_string(),
            "sweep.frame.guide[0].spline: unknown field",
        ),
        (
            r#""frame": {"guide": [{"line": {"from": [0, 2, 0], "to": [3, 2, 0]}}],
                         "fixed": [0, 0, 1]}, "#
                .to_string(),
            "sweep.frame",
        ),
        (
            format!(r#""frame": {{"guide": [{guide}]}}, "initial_normal": [0, 0, 1], "#),
            "sweep.initial_normal: ",
        ),
    ];
    for (k, (extra, expected)) in cases.iter().enumerate() {
        wire_fails_with(
            &format!("wire_guide_bad_{k}"),
            &line_job(extra),
            &[expected],
        );
    }
}

/// A circle of radius 0.05 along a line into the twisted cubic (t, t², t³) as a NURBS edge
/// tangent to it, with `extra` keys in the sweep.
fn cubic_job(extra: &str) -> String {
    format!(
        r#"{{"sweep": {{"spine": {{"wire": [
              {{"line": {{"from": [-1, 0, 0], "to": [0, 0, 0]}}}},
              {{"nurbs": {{"degree": 3, "poles": [[0, 0, 0], [0.3333333333333333, 0, 0],
                [0.6666666666666666, 0.3333333333333333, 0], [1, 1, 1]],
                "knots": [0, 0, 0, 0, 1, 1, 1, 1]}}}}]}},
            {extra}"profile": {{"circle": {{"radius": 0.05}}}}}}}}"#
    )
}

/// `"method"` ("ph-rmf", "mobius", "rrmf") is read on wire sweeps: lines are exact whatever
/// the method (the cylinder's volume to 1e-9); on a NURBS edge the Möbius and RRMF spines
/// carry exact rational RMFs, so the summary's max |cos| between parameter lines is at
/// rounding (< 1e-12), where the PH cubic's rational RMF leaves more than 1e-10. Refused at
/// the field: "frenet" (the library's message: the Frenet frame is "frame"'s), a scale law
/// with mobius, an unknown name.
#[test]
fn wire_sweep_methods_are_read_and_refused_at_the_field() {
    for (k, method) in ["ph-rmf", "mobius", "rrmf"].iter().enumerate() {
        let f = wire_figures(
            &format!("wire_method_{k}"),
            &line_job(&format!(r#""method": "{method}", "#)),
        );
        let volume = f["volume"].as_f64().unwrap();
        let cylinder = 3.0 * std::f64::consts::PI;
        assert!(
            (volume - cylinder).abs() <= 1e-9 * cylinder,
            "{method}: {volume}"
        );
        assert_eq!(f["solid"], serde_json::json!(true), "{method}");
    }
    let mut cosines = Vec::new();
    for (k, (method, tolerance)) in [("ph-rmf", 1e-5), ("mobius", 1e-5), ("rrmf", 1e-4)]
        .iter()
        .enumerate()
    {
        let f = wire_figures(
            &format!("wire_method_cubic_{k}"),
            &cubic_job(&format!(
                r#""method": "{method}", "tolerance": {tolerance}, "#
            )),
        );
        let cosine = f["orthogonality"].as_f64().unwrap();
        let distance = f["spine_distance"].as_f64().unwrap();
        println!("{method}: max |cos| {cosine:.1e}, spine within {distance:.1e}");
        assert!(distance <= *tolerance, "{method}: {distance}");
        assert_eq!(f["solid"], serde_json::json!(true), "{method}");
        if *method != "ph-rmf" {
            let label = f["method"].as_str().unwrap();
            assert!(label.contains(&format!("({method})")), "{label}");
        }
        cosines.push(cosine);
    }
    assert!(cosines[0] > 1e-10, "ph-rmf: {}", cosines[0]);
    assert!(cosines[1] < 1e-12, "mobius: {}", cosines[1]);
    assert!(cosines[2] < 1e-12, "rrmf: {}", cosines[2]);
    let cases = [
        (
            r#""method": "frenet", "#,
            "sweep.method: method: frenet makes Frenet frames, which a wire sweep asks for \
             with its frame option",
        ),
        (
            r#""method": "mobius", "scale": [1, 0.5], "#,
            "sweep.scale: scale: a scale law is exact along PH splines",
        ),
        (
            r#""method": "spline", "#,
            "sweep.method: unknown method \"spline\"; expected one of ph-rmf, frenet, mobius, rrmf",
        ),
        (r#""method": 2, "#, "sweep.method"),
    ];
    for (k, (extra, expected)) in cases.iter().enumerate() {
        wire_fails_with(
            &format!("wire_method_bad_{k}"),
            &line_job(extra),
            &[expected],
        );
    }
}

/// The scale law (intended behaviour of the geometry): a circle of radius 1 scaled from 1
/// to ½ along a line of length 3 is the frustum of volume π L (r₀² + r₀r₁ + r₁²)/3.
#[test]
fn a_scaled_circle_along_a_line_is_a_frustum() {
    for frame in [r#""rmf""#, r#""frenet""#, r#"{"fixed": [0, 1, 1]}"#] {
        let f = wire_figures(
            "wire_frustum",
            &line_job(&format!(r#""frame": {frame}, "scale": [1, 0.5], "#)),
        );
        let (r0, r1, length) = (1.0, 0.5, 3.0);
        let exact = std::f64::consts::PI * length * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
        let volume = f["volume"].as_f64().unwrap();
        assert!(
            (volume - exact).abs() <= 1e-9 * exact,
            "{frame}: volume {volume}, frustum {exact}"
        );
    }
}

/// The knots of the scale law (intended behaviour of the geometry): a circle of radius 1
/// along a line of length 3, `"scale": [1, 1]` through the knots `[0.25, 2]` and `[0.75, 0.5]`,
/// is the chain of frustums of lengths 0.75, 1.5, 0.75 between the scales 1, 2, 0.5, 1, of
/// volume π Σ Lᵢ (aᵢ² + aᵢbᵢ + bᵢ²)/3 (the summary's volume); without the knots the
/// cylinder, so the check can fail.
#[test]
fn scale_knots_make_a_chain_of_frustums() {
    let chain = |start: f64, knots: &[(f64, f64)], end: f64| {
        let mut points = vec![(0.0, start)];
        points.extend_from_slice(knots);
        points.push((1.0, end));
        points
            .windows(2)
            .map(|w| {
                let (length, a, b) = (3.0 * (w[1].0 - w[0].0), w[0].1, w[1].1);
                std::f64::consts::PI * length * (a * a + a * b + b * b) / 3.0
            })
            .sum::<f64>()
    };
    for (k, (extra, exact)) in [
        (
            r#""scale": [1, 1], "scale_knots": [[0.25, 2], [0.75, 0.5]], "#,
            chain(1.0, &[(0.25, 2.0), (0.75, 0.5)], 1.0),
        ),
        (
            r#""scale_knots": [[0.4, 1.5]], "scale": [0.5, 1], "#,
            chain(0.5, &[(0.4, 1.5)], 1.0),
        ),
    ]
    .into_iter()
    .enumerate()
    {
        let f = wire_figures(&format!("wire_knots_{k}"), &line_job(extra));
        let volume = f["volume"].as_f64().unwrap();
        println!("{extra}: volume {volume:.15}, chain of frustums {exact:.15}");
        assert!(
            (volume - exact).abs() <= 1e-9 * exact,
            "{extra}: volume {volume}, frustums {exact}"
        );
        assert_eq!(f["solid"], serde_json::json!(true), "{extra}");
        let cylinder = 3.0 * std::f64::consts::PI;
        assert!((exact - cylinder).abs() > 0.1, "{extra}: {exact}");
    }
}

/// `"scale_knots"` refused at the field: a fraction out of (0, 1), fractions not
/// increasing (the library's message), a scale not positive, a knot of one or three
/// numbers, no array, knots with an exact-RMF method (the law made non-constant by its knots
/// alone), the key on a sweep along a curve.
#[test]
fn scale_knots_are_refused_at_the_field() {
    let cases = [
        (
            r#""scale_knots": [[1.5, 2]], "#,
            "sweep.scale_knots[0][0]: must lie in (0, 1) (a fraction of the wire's length), got 1.5",
        ),
        (
            r#""scale_knots": [[0.5, 2], [0.25, 1]], "#,
            "sweep.scale_knots[1]: scale_knots[1]: its fraction of the wire's length 0.25 must \
             lie in (0, 1), after the knot before it (0.5)",
        ),
        (
            r#""scale_knots": [[0.5, -1]], "#,
            "sweep.scale_knots[0][1]: must be positive, got -1",
        ),
        (
            r#""scale_knots": [[0.5]], "#,
            "sweep.scale_knots[0]: must be [fraction, scale], got 1 number",
        ),
        (
            r#""scale_knots": [[0.5, 2, 3]], "#,
            "sweep.scale_knots[0]: must be [fraction, scale], got 3 numbers",
        ),
        (r#""scale_knots": 0.5, "#, "sweep.scale_knots"),
        (
            r#""method": "mobius", "scale_knots": [[0.5, 2]], "#,
            "sweep.scale_knots: scale: a scale law is exact along PH splines",
        ),
    ];
    for (k, (extra, expected)) in cases.iter().enumerate() {
        wire_fails_with(
            &format!("wire_knots_bad_{k}"),
            &line_job(extra),
            &[expected],
        );
    }
    fails_with(
        "curve_knots",
        &GOOD_SWEEP.replace("\"profile\"", r#""scale_knots": [[0.5, 2]], "profile""#),
        &["sweep.scale_knots: only for a sweep along a wire"],
    );
}

/// The fixed input of issue 15 (examples/cli/hopper.json): the formed solid as STEP, the
/// neutral layer's flat pattern as DXF, SVG and a planar STEP face, the figures as JSON.
#[test]
fn sheet_metal_hopper_writes_its_solid_and_flat_pattern() {
    let dir = scratch("hopper");
    let hopper = examples().join("hopper.json");
    let out = tool(
        &dir,
        &[
            hopper.to_str().unwrap(),
            "-o",
            "hopper.step",
            "-o",
            "hopper.dxf",
            "-o",
            "hopper.svg",
            "-o",
            "hopper.flat.step",
            "-o",
            "hopper.json",
            "--curves",
            "edges.step",
        ],
        None,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = String::from_utf8_lossy(&out.stdout);
    println!("{summary}");
    assert_eq!(
        files_in(&dir),
        [
            "edges.step",
            "hopper.dxf",
            "hopper.flat.step",
            "hopper.json",
            "hopper.step",
            "hopper.svg"
        ]
    );
    let step = std::fs::read_to_string(dir.join("hopper.step")).unwrap();
    assert!(step.contains("MANIFOLD_SOLID_BREP") && step.contains("CLOSED_SHELL"));
    let flat = std::fs::read_to_string(dir.join("hopper.flat.step")).unwrap();
    assert!(flat.contains("PLANE(") && flat.contains("CIRCLE(") && !flat.contains("B_SPLINE"));
    let dxf = std::fs::read_to_string(dir.join("hopper.dxf")).unwrap();
    assert!(dxf.contains("\nARC\n") && dxf.contains("\nBEND\n") && !dxf.contains("POLYLINE"));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("hopper.json")).unwrap()).unwrap();
    let figures = &json["figures"];
    let figure = |key: &str| {
        figures[key]
            .as_f64()
            .unwrap_or_else(|| panic!("figure {key}"))
    };
    assert!(figure("edge_distance_first") <= 1e-4 && figure("edge_distance_second") <= 1e-4);
    assert!(figure("fit_deviation") <= 1e-4);
    assert!(
        figure("area_error") <= 1e-9,
        "area {}",
        figure("area_error")
    );
    assert!(figure("edge_length_error") <= 1e-9);
    assert!(
        (figure("neutral_layer") - 0.8).abs() < 1e-12,
        "k t = 0.4 × 2"
    );
    // Bad sheets are refused at their field, nothing written.
    for (json, expected) in [
        (
            r#"{"sheet": {"transition": {"bottom": {"polygon": [[0,0,0],[1,0,0],[1,1,0]]}, "top": {"circle": {"center": [0,0,1], "normal": [0,0,1], "radius": 0.2}}}, "k_factor": 1.5}}"#,
            &["sheet.k_factor: must lie in [0, 1]"][..],
        ),
        (
            r#"{"sheet": {"transition": {"bottom": {"polygon": [[0,0,0],[1,0,0],[1,1,0]]}, "top": {"circle": {"center": [0,0,1], "normal": [0,0,1], "radius": 0.2}}}, "thickness": -2}}"#,
            &["sheet.thickness: must be positive"],
        ),
        (
            r#"{"sheet": {"transition": {"bottom": {"polygon": [[0,0,0],[2,1,0],[0,0.5,0],[-2,1,0]]}, "top": {"circle": {"center": [0,0,1], "normal": [0,0,1], "radius": 0.2}}}}}"#,
            &["sheet.transition", "bottom is not convex"],
        ),
        (
            r#"{"sheet": {"transition": {"bottom": {"polygon": [[0,0,0],[1,0,0],[1,1,0]]}, "top": {"circle": {"center": [0.5,0.3,0], "normal": [1,0,0], "radius": 0.2}}}}}"#,
            &["sheet.transition", "the curves cross"],
        ),
        (
            r#"{"sheet": {"transition": {"bottom": {"polygon": [[0,0,0],[1,0,0],[1,1,0]]}, "top": {"circle": {"center": [0,0,1], "normal": [0,0,1], "radius": 0.2}}}, "reference": "outer", "thickness": 0.1}}"#,
            &["bend radius"],
        ),
    ] {
        fails_with("bad_sheet", json, expected);
    }
}

#[test]
fn sheet_metal_part_between_the_rails_of_a_ruled_developable() {
    let dir = scratch("ruled_part");
    let input = examples().join("ruled_part.json");
    let out = tool(
        &dir,
        &[
            input.to_str().unwrap(),
            "-o",
            "ruled.step",
            "-o",
            "ruled.dxf",
            "-o",
            "ruled.json",
        ],
        None,
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    println!("{}", String::from_utf8_lossy(&out.stdout));
    assert_eq!(files_in(&dir), ["ruled.dxf", "ruled.json", "ruled.step"]);
    let step = std::fs::read_to_string(dir.join("ruled.step")).unwrap();
    assert!(step.contains("MANIFOLD_SOLID_BREP") && step.contains("CLOSED_SHELL"));
    let dxf = std::fs::read_to_string(dir.join("ruled.dxf")).unwrap();
    assert!(dxf.contains("\nARC\n") && !dxf.contains("POLYLINE"));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("ruled.json")).unwrap()).unwrap();
    let figure = |key: &str| {
        json["figures"][key]
            .as_f64()
            .unwrap_or_else(|| panic!("figure {key}"))
    };
    assert!(figure("edge_distance_first") <= 1e-4 && figure("edge_distance_second") <= 1e-4);
    assert!(
        figure("area_error") <= 1e-9,
        "area {}",
        figure("area_error")
    );
    assert!(figure("edge_length_error") <= 1e-9);
    // A ruled surface that is not developable (the saddle z = xy) is refused at its field.
    fails_with(
        "bad_ruled_part",
        r#"{"sheet": {"ruled": {"nurbs": {"degree_u": 1, "degree_v": 1, "poles": [[[-1,-1,1],[-1,1,-1]],[[1,-1,-1],[1,1,1]]], "knots_u": [0,0,1,1], "knots_v": [0,0,1,1]}}}}"#,
        &["sheet.ruled", "not developable"],
    );
}

/// Runs the tool with arguments that need not be UTF-8, `stdin` as its input and `stdout`
/// as its standard output (standard error is captured).
fn tool_os(
    dir: &Path,
    args: &[std::ffi::OsString],
    stdin: Stdio,
    stdout: Stdio,
    stderr: Stdio,
) -> Output {
    Command::new(TOOL)
        .args(args)
        .current_dir(dir)
        .stdin(stdin)
        .stdout(stdout)
        .stderr(stderr)
        .output()
        .expect("the tool runs")
}

fn os(args: &[&str]) -> Vec<std::ffi::OsString> {
    args.iter().map(Into::into).collect()
}

/// GOOD_SWEEP as a file in `dir`, for runs whose standard input is not a pipe.
fn good_sweep_in(dir: &Path) -> PathBuf {
    let path = dir.join("sweep.input");
    std::fs::write(&path, GOOD_SWEEP).unwrap();
    path
}

fn dev_full() -> Stdio {
    Stdio::from(
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap(),
    )
}

#[test]
fn a_directory_among_the_outputs_writes_nothing() {
    let dir = scratch("output_directory");
    std::fs::create_dir(dir.join("dir.step")).unwrap();
    for (args, message) in [
        (
            vec!["-", "-o", "good.step", "-o", "dir.step", "-o", "good.json"],
            "cannot write dir.step: it is a directory",
        ),
        (
            vec!["-", "-o", "good.step", "--curves", "dir.step"],
            "cannot write dir.step: it is a directory",
        ),
        (
            vec!["-", "-o", "good.step", "-o", "new.step/"],
            "cannot write new.step/: the name is a directory's",
        ),
        (
            vec!["-", "-o", "good.step", "-o", "good.json/x.step"],
            "cannot write good.json/x.step: No such file or directory",
        ),
    ] {
        let out = tool(&dir, &args, Some(GOOD_SWEEP));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains(message), "{args:?}: {stderr}");
        assert_eq!(files_in(&dir), ["dir.step"], "{args:?}");
    }
    assert!(files_in(&dir.join("dir.step")).is_empty());
}

#[test]
fn duplicate_outputs_are_refused_before_anything_is_written() {
    let dir = scratch("output_duplicates");
    std::fs::create_dir(dir.join("sub")).unwrap();
    std::fs::write(dir.join("old.step"), "old").unwrap();
    for args in [
        vec!["-", "-o", "same.step", "-o", "same.step"],
        vec!["-", "-o", "a.step", "-o", "b.json", "-o", "./a.step"],
        vec!["-", "-o", "c.step", "--curves", "c.step"],
        vec!["-", "-o", "sub/../d.step", "-o", "d.step"],
        vec!["-", "-o", "old.step", "-o", "sub/../old.step"],
    ] {
        let out = tool(&dir, &args, Some(GOOD_SWEEP));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(
            stderr.contains("are the same file: give each output once"),
            "{args:?}: {stderr}"
        );
        assert_eq!(files_in(&dir), ["old.step", "sub"], "{args:?}");
    }
    assert_eq!(
        std::fs::read_to_string(dir.join("old.step")).unwrap(),
        "old"
    );
}

#[test]
fn file_names_need_not_be_utf8() {
    use std::os::unix::ffi::OsStringExt;
    let dir = scratch("non_utf8");
    let input = good_sweep_in(&dir);
    let name = std::ffi::OsString::from_vec(b"caf\xe9.step".to_vec());
    let curves = std::ffi::OsString::from_vec(b"\xff\xfe.stp".to_vec());
    let args = vec![
        input.clone().into_os_string(),
        "-o".into(),
        name.clone(),
        "--curves".into(),
        curves.clone(),
    ];
    let out = tool_os(&dir, &args, Stdio::null(), Stdio::piped(), Stdio::piped());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let step = std::fs::read_to_string(dir.join(&name)).unwrap();
    assert!(step.contains("B_SPLINE_SURFACE"));
    assert!(dir.join(&curves).exists());
    let missing = std::ffi::OsString::from_vec(b"no\xff.json".to_vec());
    let out = tool_os(
        &dir,
        &[missing, "-o".into(), "x.step".into()],
        Stdio::null(),
        Stdio::piped(),
        Stdio::piped(),
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read no\u{fffd}.json"));
    let out = tool_os(
        &dir,
        &[
            input.into_os_string(),
            "-o".into(),
            std::ffi::OsString::from_vec(b"x.\xff".to_vec()),
        ],
        Stdio::null(),
        Stdio::piped(),
        Stdio::piped(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown format"));
}

/// A full disk or a closed pipe on standard output is reported, and the files of the run
/// are taken back (an existing one restored): the summary is one of the outputs.
#[test]
fn a_full_or_closed_standard_output_is_an_error() {
    let dir = scratch("stdout_full");
    let input = good_sweep_in(&dir);
    std::fs::write(dir.join("old.step"), "old").unwrap();
    let args = os(&[input.to_str().unwrap(), "-o", "new.step", "-o", "old.step"]);
    let out = tool_os(&dir, &args, Stdio::null(), dev_full(), Stdio::piped());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("cannot write to standard output: No space left on device")
            && stderr.contains("no file was written"),
        "{stderr}"
    );
    assert_eq!(files_in(&dir), ["old.step", "sweep.input"]);
    assert_eq!(
        std::fs::read_to_string(dir.join("old.step")).unwrap(),
        "old"
    );
    // A pipe whose reader has gone: `true` exits without reading.
    let mut reader = Command::new("true").stdin(Stdio::piped()).spawn().unwrap();
    let closed = Stdio::from(reader.stdin.take().unwrap());
    reader.wait().unwrap();
    let out = tool_os(&dir, &args, Stdio::null(), closed, Stdio::piped());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("Broken pipe"), "{stderr}");
    assert_eq!(files_in(&dir), ["old.step", "sweep.input"]);
    // With -q nothing goes to standard output.
    let mut quiet = args.clone();
    quiet.push("-q".into());
    let out = tool_os(&dir, &quiet, Stdio::null(), dev_full(), Stdio::piped());
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(files_in(&dir), ["new.step", "old.step", "sweep.input"]);
    // --help, --version; and a full standard error with an error to report.
    for args in [os(&["--help"]), os(&["-V"])] {
        let out = tool_os(&dir, &args, Stdio::null(), dev_full(), Stdio::piped());
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write to standard output"));
    }
    let out = tool_os(
        &dir,
        &os(&["missing.json"]),
        Stdio::null(),
        Stdio::piped(),
        dev_full(),
    );
    assert_eq!(out.status.code(), Some(1));
}

/// Every input example with one value or key changed per variant: each leaf in turn
/// replaced by a value of another kind or an extreme one, and objects given an unknown key
/// or missing one.
fn mutations(json: &str) -> Vec<String> {
    use serde_json::{json, Value};
    const LEAVES: [&str; 12] = [
        "null",
        "\"x\"",
        "-1",
        "0",
        "1e300",
        "-1e-320",
        "18446744073709551616",
        "true",
        "[]",
        "{}",
        "[1, 2, 3, 4]",
        "[[[[[[[[1]]]]]]]]",
    ];
    fn walk(value: &mut Value, visit: &mut dyn FnMut(&mut Value)) {
        visit(value);
        match value {
            Value::Array(items) => items.iter_mut().for_each(|v| walk(v, visit)),
            Value::Object(map) => map.values_mut().for_each(|v| walk(v, visit)),
            _ => {}
        }
    }
    let root: Value = serde_json::from_str(json).unwrap();
    let mut count = 0;
    walk(&mut root.clone(), &mut |_| count += 1);
    let mut variants = Vec::new();
    for target in 0..count {
        let mut doc = root.clone();
        let mut k = 0;
        walk(&mut doc, &mut |v| {
            if k == target {
                *v = match v {
                    Value::Object(map) if target % 2 == 0 => {
                        map.insert("unknown".into(), json!(1));
                        v.clone()
                    }
                    Value::Object(map) => {
                        let first = map.keys().next().cloned();
                        if let Some(key) = first {
                            map.remove(&key);
                        }
                        v.clone()
                    }
                    _ => serde_json::from_str(LEAVES[target % LEAVES.len()]).unwrap(),
                };
            }
            k += 1;
        });
        variants.push(doc.to_string());
    }
    variants
}

/// Bad command lines, inputs and outputs of every kind: the tool reports them (exit status
/// 1 or 2) or succeeds, and never panics (exit status 101, or 3 for a caught panic).
#[test]
fn no_input_makes_the_tool_panic() {
    use std::os::unix::ffi::OsStringExt;
    let dir = scratch("no_panic");
    std::fs::create_dir(dir.join("sub.step")).unwrap();
    let input = good_sweep_in(&dir);
    let input = input.to_str().unwrap();
    let long = format!("{}.step", "n".repeat(300));
    let bytes = |b: &[u8]| std::ffi::OsString::from_vec(b.to_vec());
    let mut command_lines: Vec<Vec<std::ffi::OsString>> = [
        &[][..],
        &["-"],
        &["--"],
        &["-o"],
        &["--curves"],
        &["-", "-o", ""],
        &["-", "-o", "/"],
        &["-", "-o", "."],
        &["-", "-o", ".."],
        &["-", "-o", ".step"],
        &["-", "-o", "a.step/"],
        &["-", "-o", "a.step/."],
        &["-", "-o", "sub.step"],
        &["-", "-o", "sub.step/a.step/b.step"],
        &["-", "-o", "/dev/null"],
        &["-", "-o", "/proc/x.step"],
        &["-", "-o", &long],
        &["-", "-o", "a.step", "-o", "a.step"],
        &["-", "--curves", "a.step", "--curves", "b.step"],
        &["-", "--curves", "a.obj"],
        &["-", "-q", "-q"],
        &["-h", "junk"],
        &["a.json", "b.json"],
        &["-", "-"],
        &[".", "-o", "a.step"],
        &["/dev/null", "-o", "a.step"],
        &["/dev/zero", "-o", "a.step"],
        &["sub.step"],
        &[input, "-o", "a.dxf"],
        &[input, "-o", "a.flat.step"],
        &[
            input, "-o", "a.step", "-o", "a.vtp", "-o", "a.obj", "-o", "a.scad", "-o", "a.json",
        ],
    ]
    .iter()
    .map(|args| os(args))
    .collect();
    command_lines.push(vec![bytes(b"\xff")]);
    command_lines.push(vec![bytes(b"-\xff")]);
    command_lines.push(vec![input.into(), "-o".into(), bytes(b"\xff.step")]);
    command_lines.push(vec![input.into(), "-o".into(), bytes(b"\xff/a.step")]);
    let check = |what: &dyn std::fmt::Debug, out: &Output| {
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            matches!(out.status.code(), Some(0..=2)) && !stderr.contains("panicked"),
            "{what:?}: {:?} {stderr}",
            out.status
        );
    };
    for args in &command_lines {
        let out = tool_os(&dir, args, Stdio::null(), Stdio::piped(), Stdio::piped());
        check(args, &out);
        let out = tool_os(&dir, args, Stdio::null(), dev_full(), dev_full());
        check(args, &out);
    }
    // Standard input that is a directory, empty, or not JSON.
    for (what, stdin) in [
        (
            "a directory",
            Stdio::from(std::fs::File::open(&dir).unwrap()),
        ),
        ("empty", Stdio::null()),
        (
            "endless",
            Stdio::from(std::fs::File::open("/dev/zero").unwrap()),
        ),
        (
            "a binary file",
            Stdio::from(std::fs::File::open(TOOL).unwrap()),
        ),
    ] {
        let args = os(&["-", "-o", "a.step"]);
        let out = tool_os(&dir, &args, stdin, Stdio::piped(), Stdio::piped());
        check(&what, &out);
        assert_eq!(out.status.code(), Some(1), "{what}");
    }
    // Bad JSON of every kind.
    let mut documents: Vec<String> = [
        "",
        " ",
        "null",
        "[]",
        "{}",
        "\u{feff}{}",
        "{\"sweep\": null}",
        "{\"sweep\": {}}",
        "{\"sweep\": 1e999}",
        "\"\\ud800\"",
        "{\"a\": 1, \"a\": 2}",
        "{\"sweep\": {\"spine\": {\"wire\": []}}}",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    documents.push(format!("{}1{}", "[".repeat(100_000), "]".repeat(100_000)));
    documents.push(format!(
        "{}{}",
        "{\"sweep\": ".repeat(10_000),
        "}".repeat(10_000)
    ));
    for name in [
        "pipe.json",
        "cone_spline.json",
        "hopper.json",
        "ruled_part.json",
    ] {
        documents.extend(mutations(
            &std::fs::read_to_string(examples().join(name)).unwrap(),
        ));
    }
    documents.extend(mutations(GOOD_SWEEP));
    for json in &documents {
        let out = tool(&dir, &["-", "-o", "m.step", "-o", "m.json"], Some(json));
        check(&json.chars().take(300).collect::<String>(), &out);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The input is read through a counter that stops at 64 MiB, and lists stop at their bound:
/// neither an oversized input nor an overlong list is held in memory before it is refused.
#[test]
fn oversized_inputs_and_lists_are_refused_while_reading() {
    let mut json = String::from("{\"sweep\": ");
    json.push_str(&" ".repeat(64 << 20));
    json.push('}');
    fails_with(
        "oversized",
        &json,
        &["(stdin): the input is larger than 67108864 bytes (64 MiB), the limit of the tool"],
    );
    let edge = r#"{"line": {"from": [0, 0, 0], "to": [1, 0, 0]}}"#;
    let sweep = |spine: &str, profile: &str| {
        format!(r#"{{"sweep": {{"spine": {spine}, "profile": {profile}}}}}"#)
    };
    wire_fails_with(
        "too_many_edges",
        &sweep(
            &format!(r#"{{"wire": [{}]}}"#, vec![edge; 65_537].join(", ")),
            r#"{"circle": {"radius": 0.1}}"#,
        ),
        &[
            "sweep.spine.wire: has more than 65536 edges: a wire sweep has at most \
             rmfsurf::wire::MAX_FACES lateral faces, one or more per edge",
        ],
    );
    wire_fails_with(
        "too_many_holes",
        &sweep(
            &format!(r#"{{"wire": [{edge}]}}"#),
            &format!(
                r#"{{"circle": {{"radius": 1}}, "holes": [{}]}}"#,
                vec![r#"{"circle": {"radius": 0.1}}"#; 65_537].join(", ")
            ),
        ),
        &[
            "sweep.profile.holes: has more than 65536 holes",
            "rmfsurf::wire::MAX_FACES",
        ],
    );
    fails_with(
        "too_many_rows",
        r#"{"cone_spline": {"developable": {"ruled": {"nurbs": {"degree_u": 1, "degree_v": 1,
            "poles": [[[0,0,0],[1,0,0]], [[0,1,0],[1,1,0]], [[0,2,0],[1,2,0]]]}}},
            "strip": {"t_min": 0, "t_max": 1}}}"#,
        &["cone_spline.developable.ruled.nurbs.poles: has more than 2 rows: a developable ruled surface"],
    );
    // At the bound the list is read, and the library refuses the sweep by its face count.
    let chain: Vec<String> = (0..65_536)
        .map(|i| {
            format!(
                r#"{{"line": {{"from": [{i}, 0, 0], "to": [{}, 0, 0]}}}}"#,
                i + 1
            )
        })
        .collect();
    wire_fails_with(
        "edges_at_the_bound",
        &sweep(
            &format!(r#"{{"wire": [{}]}}"#, chain.join(", ")),
            r#"{"circle": {"radius": 0.1}}"#,
        ),
        &["lateral faces", "more than 65536"],
    );
}

/// `"sections"` with `"end_profile"` on wire sweeps: circles of radii 0.5 at 0 (the
/// profile), 1 at 0.25 (a section) and 0.3 at 1 (the end profile) along a line of 4 are the
/// chain of two frustums π/3 Σ Lᵢ (aᵢ² + aᵢ aᵢ₊₁ + aᵢ₊₁²) (the summary's volume to 1e-9);
/// refused naming `sections`: without an end profile, a fraction out of (0, 1), fractions
/// out of order, a hole the profile has not, the key on a sweep along a curve.
#[test]
fn wire_sweeps_through_sections_are_read_and_refused_at_the_field() {
    let job = |sections: &str, end: &str| {
        format!(
            r#"{{"sweep": {{"spine": {{"wire": [{{"line": {{"from": [0, 0, 0], "to": [4, 0, 0]}}}}]}},
            "profile": {{"circle": {{"radius": 0.5}}}}, {end}"sections": [{sections}]}}}}"#
        )
    };
    let end = r#""end_profile": {"circle": {"radius": 0.3}}, "#;
    let f = wire_figures(
        "wire_through_circles",
        &job(r#"{"at": 0.25, "profile": {"circle": {"radius": 1}}}"#, end),
    );
    let volume = f["volume"].as_f64().unwrap();
    let chain = [(0.0, 0.5), (0.25, 1.0), (1.0, 0.3)];
    let frustums: f64 = chain
        .windows(2)
        .map(|w| {
            let ((f0, a), (f1, b)) = (w[0], w[1]);
            std::f64::consts::PI / 3.0 * (f1 - f0) * 4.0 * (a * a + a * b + b * b)
        })
        .sum();
    println!(
        "circles 0.5 at 0, 1 at 0.25, 0.3 at 1 along a line of 4: volume {volume:.12} against \
         {frustums:.12}"
    );
    assert!(
        (volume - frustums).abs() <= 1e-9 * frustums,
        "{volume} against {frustums}"
    );
    assert_eq!(f["solid"], serde_json::json!(true));
    let one = r#"{"at": 0.25, "profile": {"circle": {"radius": 1}}}"#;
    let cases = [
        (job(one, ""), "sweep.sections: need \"end_profile\""),
        (
            job(r#"{"at": 1, "profile": {"circle": {"radius": 1}}}"#, end),
            "sweep.sections[0].at: must lie in (0, 1)",
        ),
        (
            job(
                &format!(r#"{one}, {{"at": 0.2, "profile": {{"circle": {{"radius": 1}}}}}}"#),
                end,
            ),
            "sweep.sections[1].at: sections[1]: at = 0.2 must be in (0.25, 1)",
        ),
        (
            job(
                r#"{"at": 0.25, "profile": {"circle": {"radius": 1}}, "holes": [{"circle": {"radius": 0.1}}]}"#,
                end,
            ),
            "sweep.sections[0]: sections[0]: it has 1 holes, the profile 0",
        ),
        (
            job(
                r#"{"at": 0.25, "profile": {"circle": {"radius": 1}, "holes": [{"circle": {"radius": 0.1}}]}}"#,
                end,
            ),
            "sweep.sections[0].profile.holes: a section's holes go beside its profile",
        ),
    ];
    for (k, (json, expected)) in cases.iter().enumerate() {
        wire_fails_with(&format!("wire_through_bad_{k}"), json, &[expected]);
    }
    fails_with(
        "curve_sections",
        &GOOD_SWEEP.replace("\"profile\"", &format!(r#""sections": [{one}], "profile""#)),
        &["sweep.sections: only for a sweep along a wire"],
    );
}

/// `"end_profile"` (the form of `"profile"`, its holes too) on wire sweeps: a circle of
/// radius 1 into one of radius 0.5 along a line of 3 is the frustum π L (r0² + r0 r1 +
/// r1²)/3 (the summary's volume to 1e-9), a square into a circle a closed solid; refused at
/// the field: a different number of holes and a bad radius (`sweep.end_profile`), a scale
/// law beside it (`sweep.scale`), the key on a sweep along a curve (only for a wire).
#[test]
fn wire_sweeps_between_two_profiles_are_read_and_refused_at_the_field() {
    let f = wire_figures(
        "wire_between_circles",
        &line_job(r#""end_profile": {"circle": {"radius": 0.5}}, "#),
    );
    let volume = f["volume"].as_f64().unwrap();
    let (r0, r1, length) = (1.0, 0.5, 3.0);
    let frustum = std::f64::consts::PI * length * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
    println!(
        "circle 1 into circle 0.5 along a line of 3: volume {volume:.12} against {frustum:.12}"
    );
    assert!(
        (volume - frustum).abs() <= 1e-9 * frustum,
        "{volume} against {frustum}"
    );
    assert_eq!(f["solid"], serde_json::json!(true));
    let f = wire_figures(
        "wire_between_square_circle",
        &line_job(
            r#""end_profile": {"polygon": [[0.5, 0.5], [-0.5, 0.5], [-0.5, -0.5], [0.5, -0.5]]}, "#,
        ),
    );
    assert_eq!(f["solid"], serde_json::json!(true));
    let volume = f["volume"].as_f64().unwrap();
    assert!(
        volume > 3.0 && volume < 3.0 * std::f64::consts::PI,
        "between the square's prism and the circle's: {volume}"
    );
    let cases = [
        (
            r#""end_profile": {"circle": {"radius": 0.5}, "holes": [{"circle": {"radius": 0.1}}]}, "#,
            "sweep.end_profile: end_profile: it has 1 holes, the profile 0",
        ),
        (
            r#""end_profile": {"circle": {"radius": -0.5}}, "#,
            "sweep.end_profile.circle.radius",
        ),
        (
            r#""end_profile": {"circle": {"radius": 0.5}}, "scale": [1, 0.5], "#,
            "sweep.scale: scale: with end_profile",
        ),
    ];
    for (k, (extra, expected)) in cases.iter().enumerate() {
        wire_fails_with(
            &format!("wire_between_bad_{k}"),
            &line_job(extra),
            &[expected],
        );
    }
    fails_with(
        "curve_end_profile",
        &GOOD_SWEEP.replace(
            "\"profile\"",
            r#""end_profile": {"circle": {"radius": 0.05}}, "profile""#,
        ),
        &["sweep.end_profile: only for a sweep along a wire"],
    );
}
