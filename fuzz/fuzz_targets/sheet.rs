//! libFuzzer entry of the `sheet` target (see `src/lib.rs`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| rmfsurf_fuzz::sheet(data));
