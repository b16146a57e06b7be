//! OpenSCAD (Debian package openscad) renders the `.scad` files of the command-line tool:
//! every example's `rmf_solid()` on its own, the same solid through CGAL (a `difference()`
//! with a small cube: CGAL refuses polyhedra that are not closed and consistently
//! oriented), and, for sweeps, `rmf_sweep()` of a 2-D polygon with the RMF transforms.
//! Each run must exit 0, and each STL must be a closed 2-manifold: every edge shared by
//! exactly two triangles, once in each direction (consistent orientation), with positive
//! volume (outward normals) equal to the polyhedron's in the `.scad` file.
//!
//! `cargo test -p rmfsurf-integration --test openscad -- --nocapture` prints the figures.

mod support;

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use support::{fresh_dir, run_cli, EXAMPLES, SETUP_HINT};

type Triangle = [[f64; 3]; 3];

/// Renders `scad` to `stl` with OpenSCAD; asserts exit status 0.
fn render(dir: &Path, scad: &str, stl: &str) {
    let out = Command::new("openscad")
        .args(["-o", stl, scad])
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("cannot run openscad ({e}): {SETUP_HINT}"));
    assert!(
        out.status.success(),
        "openscad -o {stl} {scad} failed ({}):\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The triangles of an ASCII STL, with each vertex's text (OpenSCAD prints a shared
/// vertex identically everywhere, so the text identifies it).
fn read_stl(path: &Path) -> (Vec<Triangle>, Vec<[String; 3]>) {
    let text = std::fs::read_to_string(path).expect("STL written");
    let vertices: Vec<&str> = text
        .lines()
        .filter_map(|l| l.trim().strip_prefix("vertex "))
        .collect();
    assert!(
        !vertices.is_empty() && vertices.len() % 3 == 0,
        "{} holds no triangles",
        path.display()
    );
    let point = |v: &str| {
        let xs: Vec<f64> = v
            .split_whitespace()
            .map(|x| x.parse().expect("a number"))
            .collect();
        [xs[0], xs[1], xs[2]]
    };
    let triangles = vertices
        .chunks(3)
        .map(|t| [point(t[0]), point(t[1]), point(t[2])])
        .collect();
    let keys = vertices
        .chunks(3)
        .map(|t| [t[0].to_string(), t[1].to_string(), t[2].to_string()])
        .collect();
    (triangles, keys)
}

/// Every directed edge used once and its reverse once; returns the number of edges.
fn check_closed_manifold(keys: &[[String; 3]], name: &str) -> usize {
    let mut ids: HashMap<&str, usize> = HashMap::new();
    let mut directed: HashMap<(usize, usize), usize> = HashMap::new();
    for t in keys {
        let corner: Vec<usize> = t
            .iter()
            .map(|v| {
                let next = ids.len();
                *ids.entry(v.as_str()).or_insert(next)
            })
            .collect();
        assert!(
            corner[0] != corner[1] && corner[1] != corner[2] && corner[0] != corner[2],
            "{name}: a degenerate triangle"
        );
        for k in 0..3 {
            *directed
                .entry((corner[k], corner[(k + 1) % 3]))
                .or_default() += 1;
        }
    }
    for (&(a, b), &count) in &directed {
        assert_eq!(
            count, 1,
            "{name}: edge {a} → {b} used {count} times in one direction"
        );
        assert_eq!(
            directed.get(&(b, a)),
            Some(&1),
            "{name}: edge {a} → {b} is not shared by exactly two consistently oriented triangles"
        );
    }
    directed.len() / 2
}

fn stl_volume(triangles: &[Triangle]) -> f64 {
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    triangles
        .iter()
        .map(|[a, b, c]| {
            let n = cross(*b, *c);
            (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6.0
        })
        .sum()
}

/// The volume of `rmf_solid()` from the `.scad` text: `rmf_points()` and `rmf_faces()` as
/// written (faces clockwise from outside, so the signed volume is negated), polygons fanned.
fn polyhedron_volume(scad: &str) -> f64 {
    let block = |start: &str| -> Vec<Vec<f64>> {
        let from = scad.find(start).expect("a block") + start.len();
        scad[from..]
            .lines()
            .skip(1)
            .take_while(|l| l.trim_start().starts_with('['))
            .map(|l| {
                l.trim()
                    .trim_end_matches(',')
                    .trim_matches(|c| c == '[' || c == ']')
                    .split(',')
                    .map(|x| x.trim().parse().expect("a number"))
                    .collect()
            })
            .collect()
    };
    let points = block("function rmf_points() = [");
    let faces = block("function rmf_faces() = [");
    let p = |k: f64| {
        let q = &points[k as usize];
        [q[0], q[1], q[2]]
    };
    let fans: Vec<Triangle> = faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |k| (f[0], f[k], f[k + 1])))
        .map(|(a, b, c)| [p(a), p(b), p(c)])
        .collect();
    -stl_volume(&fans)
}

/// Renders `scad` and checks the STL; returns (triangles, edges, volume).
fn rendered_solid(dir: &Path, scad: &str, stl: &str) -> (usize, usize, f64) {
    render(dir, scad, stl);
    let (triangles, keys) = read_stl(&dir.join(stl));
    let edges = check_closed_manifold(&keys, stl);
    let volume = stl_volume(&triangles);
    assert!(
        volume > 0.0,
        "{stl}: negative volume {volume}: the faces point inwards"
    );
    (triangles.len(), edges, volume)
}

/// Writes `<name>.scad` that uses the tool's `scad` and draws `body`, and renders it.
fn render_using(dir: &Path, scad: &str, name: &str, body: &str) -> (usize, usize, f64) {
    let file = format!("{name}.scad");
    std::fs::write(dir.join(&file), format!("use <{scad}>\n{body}\n")).unwrap();
    rendered_solid(dir, &file, &format!("{name}.stl"))
}

#[test]
fn openscad_renders_closed_manifolds() {
    let dir = fresh_dir("openscad");
    for example in EXAMPLES {
        let scad = format!("{example}.scad");
        run_cli(&dir, example, &["-q", "-o", &scad]);
        let (triangles, edges, volume) = rendered_solid(&dir, &scad, &format!("{example}.stl"));
        let written = polyhedron_volume(&std::fs::read_to_string(dir.join(&scad)).unwrap());
        let relative = (volume - written).abs() / written;
        println!(
            "{example}: {triangles} triangles, {edges} edges, each in exactly 2 triangles, consistently oriented; volume {volume:.6} (polyhedron {written:.6}, rel. diff {relative:.1e})"
        );
        // OpenSCAD prints 6 significant digits.
        assert!(
            relative < 1e-4,
            "{example}: STL volume {volume} vs polyhedron {written}"
        );

        // Through CGAL: a small cube cut off at the solid's first point.
        let (triangles, _, cut) = render_using(
            &dir,
            &scad,
            &format!("{example}_csg"),
            "difference() { rmf_solid(); translate(rmf_points()[0]) cube(0.01, center = true); }",
        );
        println!("  CGAL difference with a cube: {triangles} triangles, closed manifold, volume {volume:.9} - {:.3e}", volume - cut);
        assert!(
            cut < volume && cut > volume - 1e-6 - 1e-4 * volume,
            "{example}: volume after the cut {cut} vs {volume}"
        );

        if example.starts_with("cone") {
            continue;
        }
        let (triangles, _, tube) = render_using(
            &dir,
            &scad,
            &format!("{example}_sweep"),
            "rmf_sweep([for (a = [0:30:330]) 0.05 * [cos(a), sin(a)]]);",
        );
        println!("  rmf_sweep of a 12-gon with rmf_transforms(): {triangles} triangles, closed manifold, volume {tube:.6}");
    }
}
