//! libFuzzer entry of the `mobius` target (see `src/lib.rs`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| rmfsurf_fuzz::mobius(data));
