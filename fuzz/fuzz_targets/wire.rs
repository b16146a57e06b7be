//! libFuzzer entry of the `wire` target (see `src/lib.rs`).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| rmfsurf_fuzz::wire(data));
