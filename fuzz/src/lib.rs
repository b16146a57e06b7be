//! The fuzz harness of rmfsurf: every C entry point driven with arbitrary doubles.
//!
//! A fuzz input is a program: its bytes choose the next operation (an entry point with
//! arguments drawn by [`input::Input`]: NaN, ±Inf, subnormals, 1e±300, near-duplicate
//! points, collinear, antiparallel and nearly parallel tangents, degenerate NURBS), and the
//! handles made so far are the arguments of later operations — a spline made by one call
//! gets frames from the next, a sweep, a tessellation, a NURBS copy. After every call the
//! contract of the C API is checked ([`session`]); any violation, panic or memory error is a
//! finding.
//!
//! Each target mixes one capability's operations with the foundation's ([`core`]). The
//! same functions run under libFuzzer (`fuzz_targets/`, with cargo-fuzz) and, on a stable
//! toolchain without instrumentation, over the committed corpus in the test command
//! (`tests/fuzz_corpus.rs` of the main crate).

pub mod brep;
pub mod callback;
pub mod cone_spline;
pub mod core;
pub mod input;
pub mod mobius;
pub mod ph_cubic;
pub mod rrmf_quintic;
pub mod session;
pub mod sheet;
pub mod wire;

use session::Session;

/// Operations per run: bounds the time one input can take.
const MAX_OPS: usize = 24;

/// Runs `input` as a program over `ops` (a capability's operations) and the foundation's.
fn run(input: &[u8], ops: &[fn(&mut Session)]) {
    let all: Vec<fn(&mut Session)> = ops.iter().chain(core::OPS).copied().collect();
    Session::new(input).run(&all, MAX_OPS);
}

/// A fuzz target: runs one input.
pub type Target = fn(&[u8]);

/// The targets by name: the name of the fuzz target and of its corpus directory.
pub const TARGETS: &[(&str, Target)] = &[
    ("foundation", foundation),
    ("ph_cubic", ph_cubic),
    ("mobius", mobius),
    ("rrmf_quintic", rrmf_quintic),
    ("cone_spline", cone_spline),
    ("wire", wire),
    ("sheet", sheet),
];

/// NURBS curves and surfaces, views, evaluation, tessellation, frames, sweeps.
pub fn foundation(input: &[u8]) {
    run(input, &[])
}

pub fn ph_cubic(input: &[u8]) {
    run(input, ph_cubic::OPS)
}

pub fn mobius(input: &[u8]) {
    run(input, mobius::OPS)
}

pub fn rrmf_quintic(input: &[u8]) {
    run(input, rrmf_quintic::OPS)
}

pub fn cone_spline(input: &[u8]) {
    run(input, cone_spline::OPS)
}

/// Wire sweeps, with the PH splines and NURBS curves they take as edges and profiles.
pub fn wire(input: &[u8]) {
    let ops: Vec<fn(&mut Session)> = wire::OPS.iter().chain(ph_cubic::OPS).copied().collect();
    run(input, &ops)
}

/// Sheet-metal parts: transitions, layers, flat patterns, marks, exports.
pub fn sheet(input: &[u8]) {
    run(input, sheet::OPS)
}
