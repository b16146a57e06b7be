//! Passes the target and host triples to the tests, as capi/build.rs does for capi's: the
//! harness they share (capi/tests/support) uses the `cc` crate outside a build script to
//! find the C and C++ compilers.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    for var in ["TARGET", "HOST"] {
        let triple = std::env::var(var).expect("cargo sets TARGET and HOST");
        println!("cargo:rustc-env=RMFSURF_{var}={triple}");
    }
}
