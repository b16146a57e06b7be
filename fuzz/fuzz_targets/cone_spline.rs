//! libFuzzer entry of the `cone_spline` target (see `src/lib.rs`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| rmfsurf_fuzz::cone_spline(data));
