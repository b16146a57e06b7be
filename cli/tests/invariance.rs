//! Every example job of the tool, scaled by 1e-200 … 1e200 and moved by a thousand times
//! its size, gives the same figures: lengths scaled, areas and volumes scaled by the square
//! and cube (left out only where those are outside the range of f64), everything else the
//! same. The whole path is covered: reading, the construction, its measures and the
//! summary.

use serde_json::{Map, Value};
use std::path::{Path, PathBuf};
use std::process::Command;

const TOOL: &str = env!("CARGO_BIN_EXE_rmfsurf");

/// Numbers that are not lengths: degrees, knots, weights, counts, angles, ratios.
const UNSCALED: [&str; 15] = [
    "degree",
    "degree_u",
    "degree_v",
    "knots",
    "knots_u",
    "knots_v",
    "weights",
    "u_steps",
    "v_steps",
    "max_pieces",
    "closure_symmetry",
    "twist",
    "k_factor",
    "join_tolerance",
    "scale",
];

/// Points in space: scaled and moved (directions, such as normals and tangents, are only
/// scaled: a direction of any length is taken).
const POINTS: [&str; 10] = [
    "from", "to", "start", "through", "end", "poles", "points", "center", "point", "polygon",
];

/// How a figure changes with the scale s: as s^power, or not at all (0).
fn power(figure: &str) -> i32 {
    match figure {
        "fit_deviation"
        | "flatness"
        | "bend_radius"
        | "edge_distance_first"
        | "edge_distance_second"
        | "neutral_layer"
        | "spine_distance"
        | "joint_gap"
        | "seam_gap" => 1,
        "flat_area" | "formed_area" => 2,
        "volume" => 3,
        "rmf_defect" => -1,
        _ => 0,
    }
}

/// `value` with lengths scaled by `s` and points (3-D, under a key of POINTS) moved by `o`.
fn mapped(value: &Value, key: &str, s: f64, o: [f64; 3], in_space: bool) -> Value {
    match value {
        Value::Object(map) => Value::Object(
            map.iter()
                .map(|(k, v)| {
                    // Profiles live in the normal plane of the spine: scaled, never moved.
                    let space = in_space && k != "profile" && k != "holes" && k != "strip";
                    (k.clone(), mapped(v, k, s, o, space))
                })
                .collect::<Map<_, _>>(),
        ),
        Value::Array(items) => {
            let point = in_space
                && POINTS.contains(&key)
                && items.len() == 3
                && items.iter().all(Value::is_number);
            Value::Array(
                items
                    .iter()
                    .enumerate()
                    .map(|(k, v)| match (point, v.as_f64()) {
                        (true, Some(x)) => (x * s + o[k] * s).into(),
                        _ => mapped(v, key, s, o, in_space),
                    })
                    .collect(),
            )
        }
        Value::Number(n) if !UNSCALED.contains(&key) => (n.as_f64().unwrap() * s).into(),
        other => other.clone(),
    }
}

fn figures(dir: &Path, job: &Value) -> Result<Map<String, Value>, String> {
    let input = dir.join("job.json");
    std::fs::write(&input, job.to_string()).unwrap();
    let out = Command::new(TOOL)
        .current_dir(dir)
        .args(["job.json", "-o", "figures.json", "-q"])
        .output()
        .unwrap();
    if !out.status.success() {
        return Err(String::from_utf8_lossy(&out.stderr).into_owned());
    }
    let text = std::fs::read_to_string(dir.join("figures.json")).unwrap();
    let value: Value = serde_json::from_str(&text).unwrap();
    Ok(value["figures"].as_object().unwrap().clone())
}

/// Whether `moved` is `unit` at scale `s` (figures of power p scale by s^p).
fn same_figure(name: &str, unit: &Value, moved: Option<&Value>, s: f64) -> Result<(), String> {
    let p = power(name);
    match (unit, moved) {
        (Value::Number(a), Some(Value::Number(b))) => {
            let (a, b) = (a.as_f64().unwrap(), b.as_f64().unwrap());
            let b = b / s.powi(p);
            // Rounding-level figures (gaps, orthonormality) are compared absolutely.
            let slack = 1e-6 * a.abs() + if p == 0 { 1e-8 } else { 1e-6 };
            if (a - b).abs() <= slack {
                Ok(())
            } else {
                Err(format!(
                    "{name}: {a:e} at scale 1, {b:e} at scale {s:e} (scaled back)"
                ))
            }
        }
        // An area or volume beyond f64 is left out of the summary.
        (Value::Number(a), None) if p >= 2 => {
            let exponent = a.as_f64().unwrap().abs().log10() + p as f64 * s.log10();
            if exponent.abs() > 300.0 {
                Ok(())
            } else {
                Err(format!("{name}: missing at scale {s:e}"))
            }
        }
        (Value::String(_), Some(Value::String(_))) if name == "pattern_size" || name == "sheet" => {
            Ok(())
        }
        (a, Some(b)) if a == b => Ok(()),
        (a, b) => Err(format!("{name}: {a} at scale 1, {b:?} at scale {s:e}")),
    }
}

fn examples() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/cli");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_example_gives_the_same_figures_at_any_scale_and_place() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("invariance");
    std::fs::create_dir_all(&dir).unwrap();
    let mut failures = Vec::new();
    for file in examples() {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let job: Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
        let unit = figures(&dir, &job).unwrap_or_else(|e| panic!("{name}: {e}"));
        for (s, o) in [
            (1e-200, [0.0; 3]),
            (1e-100, [1e3, -2e3, 5e2]),
            (1e100, [0.0; 3]),
            (1e180, [0.0; 3]),
            (1e200, [-1e3, 0.0, 1e3]),
            (1.0, [1e3, 1e3, -1e3]),
        ] {
            let moved = mapped(&job, "", s, o, true);
            match figures(&dir, &moved) {
                Err(e) => failures.push(format!("{name} at scale {s:e}: {e}")),
                Ok(f) => {
                    for (k, v) in &unit {
                        // The relative area error goes with the areas.
                        if k == "area_error" && !f.contains_key("flat_area") {
                            continue;
                        }
                        if let Err(e) = same_figure(k, v, f.get(k), s) {
                            failures.push(format!("{name}, offset {o:?}: {e}"));
                        }
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The comparison fails where it should: a figure off by 1e-5 relative, a missing length.
#[test]
fn the_comparison_can_fail() {
    let v = |x: f64| Value::from(x);
    assert!(same_figure(
        "spine_distance",
        &v(1.0),
        Some(&v(2e100 * (1.0 + 1e-5))),
        2e100
    )
    .is_err());
    assert!(same_figure("spine_distance", &v(1.0), None, 2e100).is_err());
    assert!(same_figure("volume", &v(1.0), None, 1e10).is_err());
    assert!(same_figure("volume", &v(1.0), None, 1e200).is_ok());
    assert!(same_figure("orthogonality", &v(2e-7), Some(&v(0.0)), 1e180).is_err());
}
