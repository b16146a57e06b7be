//! Benchmark of unfolding: a sheet body of 326 faces (a strip 0.5 thick and 3 wide bent 40
//! times, alternately up and down — the solid of a rectangle swept along the zigzag, exact
//! planes and cylinders as a kernel hands them over) unfolded whole, and one of its bend
//! faces alone. The input is the B-rep model (the library's own sweep made it; building
//! it is not timed). No program installed here unfolds such a body (FreeCAD's SheetMetal
//! workbench is not part of FreeCAD 0.20, OpenCascade has no unfolding), so the row stands
//! alone.
//!
//!     cargo bench --bench unfold

#[path = "support/mod.rs"]
mod support;

use rmfsurf::glam::DVec3;
use rmfsurf::primitives::polygon;
use rmfsurf::{
    unfold::unfold_body, unfold::unfold_face, unfold::BodyOptions, unfold::KFactor,
    unfold::UnfoldOptions, wire::sweep as sweep_wire, wire::Edge, wire::WireSweep,
};

/// `bends` quarter turns of radius 1.5, alternately left and right, joined by lines of 2.
fn zigzag(bends: usize) -> Vec<Edge> {
    let s = 0.5f64.sqrt();
    let (mut at, mut dir) = (DVec3::ZERO, DVec3::X);
    let mut edges = Vec::new();
    for k in 0..bends {
        let next = at + 2.0 * dir;
        edges.push(Edge::Line { from: at, to: next });
        at = next;
        let side = DVec3::Z.cross(dir) * if k % 2 == 0 { 1.0 } else { -1.0 };
        let centre = at + 1.5 * side;
        let end = centre + 1.5 * dir;
        edges.push(Edge::Arc {
            start: at,
            through: centre + 1.5 * (s * dir - s * side),
            end,
        });
        at = end;
        dir = side;
    }
    edges.push(Edge::Line {
        from: at,
        to: at + 2.0 * dir,
    });
    edges
}

fn main() {
    let profile = polygon(&[
        DVec3::new(-0.25, 0.0, 0.0),
        DVec3::new(0.25, 0.0, 0.0),
        DVec3::new(0.25, 3.0, 0.0),
        DVec3::new(-0.25, 3.0, 0.0),
    ])
    .unwrap();
    let options = WireSweep {
        initial_normal: Some(DVec3::Y),
        ..WireSweep::default()
    };
    let brep = sweep_wire(&zigzag(40), &profile, &[], &options)
        .unwrap()
        .brep()
        .clone();
    let body_options = BodyOptions {
        face: UnfoldOptions::new(1e-6),
        k_factor: KFactor::Constant(0.4),
    };
    let (body, unfolded) = support::timed(|| unfold_body(&brep, &body_options).unwrap());
    let bend = unfolded.bends()[0].face;
    let (face, _) = support::timed(|| unfold_face(&brep, bend, &UnfoldOptions::new(1e-6)).unwrap());
    println!(
        "unfold benchmark (from the B-rep model; fastest of {} runs)",
        support::REPEATS
    );
    println!("| input | faces | bends | time |");
    println!("| --- | --- | --- | --- |");
    println!(
        "| zigzag strip, whole body | {} | {} | {:.1} ms |",
        brep.faces.len(),
        unfolded.bends().len(),
        body * 1e3
    );
    println!("| one of its bend faces | 1 | | {:.3} ms |", face * 1e3);
}
