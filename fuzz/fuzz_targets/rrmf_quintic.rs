//! libFuzzer entry of the `rrmf_quintic` target (see `src/lib.rs`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| rmfsurf_fuzz::rrmf_quintic(data));
