//! libFuzzer entry of the `ph_cubic` target (see `src/lib.rs`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| rmfsurf_fuzz::ph_cubic(data));
