//! Timing shared by the benchmarks: the fastest of several runs (the machine may be shared,
//! and the fastest run is the one least disturbed).

// Each benchmark compiles this module on its own and uses part of it.
#![allow(dead_code)]

use std::hint::black_box;
use std::time::Instant;

/// Runs of each timed step; the fastest counts.
pub const REPEATS: usize = 5;

/// Seconds of the fastest of `runs` runs of `f`, with its last result.
pub fn fastest_of<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut result = None;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let r = black_box(f());
        best = best.min(start.elapsed().as_secs_f64());
        result = Some(r);
    }
    (best, result.expect("at least one run"))
}

/// [`fastest_of`] with [`REPEATS`] runs.
pub fn timed<T>(f: impl FnMut() -> T) -> (f64, T) {
    fastest_of(REPEATS, f)
}
