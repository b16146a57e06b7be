//! rmfsurf: exact rational curves, rotation-minimizing frames and surfaces for sweeping
//! and for developable (sheet-metal) surfaces, with a C ABI.
//!
//! The crate is layered; each layer only uses the ones above it:
//!
//! | module | what it computes |
//! | --- | --- |
//! | [`math`] | binomials, validated vectors, polynomial roots, quadrature, 1-D minimization |
//! | [`bezier`] | rational Bézier curves/patches, piecewise assemblies, NURBS conversion |
//! | [`curve`] | the curve interface the algorithms sample (point + tangent at a parameter) |
//! | [`hermite`] | validated G1 Hermite data (points + unit tangents) |
//! | [`frames`] | Frenet frames, the double-reflection RMF (the reference), rational frames, metrics |
//! | [`mesh`] | triangle meshes of surfaces on the patch grid |
//! | [`solid`] | closed, outward-oriented meshes: capped tubes, thickened sheets |
//! | [`mobius`] | Möbius maps, exact images of curves and frames, rational-RMF curves (Bartoň et al.) |
//! | [`sweep`] | sweep surfaces x + c₂ f₂ + c₃ f₃ with exact rational frames |
//! | [`wire`] | sweeps along wires of lines, arcs and curves with corners: closed solids of exact faces |
//! | [`ph_cubic`] | PH cubic splines, their exact and rational RMFs, profile-surface analysis (Mäurer & Jüttler) |
//! | [`rrmf_quintic`] | quintics with exact rational RMFs by G1 Hermite interpolation (Farouki, Giannelli & Sestini) |
//! | [`cone_spline`] | cone spline surfaces: G1 cone pairs, approximation of developables, development, bending, offsets |
//! | [`export`] | STEP, VTK, OBJ, OpenSCAD, SVG and DXF files |
//!
//! The geometry lives in safe Rust and knows nothing of C; the C ABI is the crate
//! `rmfsurf-capi` (directory `capi/`), built on this crate's public API.

pub mod bezier;
pub mod cone_spline;
pub mod curve;
mod error;
pub mod export;
pub mod frames;
pub mod hermite;
pub mod math;
pub mod mesh;
pub mod mobius;
pub mod ph_cubic;
pub mod rrmf_quintic;
pub mod solid;
pub mod sweep;
#[cfg(test)]
mod testing;
pub mod wire;

pub use error::{Error, ErrorKind, Result, ResultExt};
