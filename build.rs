//! Passes the target and host triples to the test harness (`tests/c_suite.rs`), which uses
//! the `cc` crate outside a build script to find the C and C++ compilers.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    for var in ["TARGET", "HOST"] {
        println!(
            "cargo:rustc-env=RMFSURF_{var}={}",
            std::env::var(var).expect("cargo sets TARGET and HOST")
        );
    }
}
