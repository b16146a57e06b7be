//! Sets the shared library's SONAME to librmfsurf.so.N, N = RMF_ABI_VERSION of
//! src/status.rs (the one place it is written), and passes the target and host triples to
//! the C test harness (tests/c_suite.rs with tests/support), which uses the `cc` crate
//! outside a build script to find the C and C++ compilers. (integration/build.rs passes
//! them to the integration crate's tests, which use the same harness.)
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=src/status.rs");
    let status = std::fs::read_to_string("src/status.rs").expect("src/status.rs");
    let abi = status
        .lines()
        .find_map(|l| l.strip_prefix("pub const RMF_ABI_VERSION: u32 = "))
        .and_then(|rest| rest.strip_suffix(';'))
        .expect("src/status.rs defines RMF_ABI_VERSION");
    let target = std::env::var("TARGET").expect("cargo sets TARGET");
    if target.contains("linux") || target.contains("bsd") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,librmfsurf.so.{abi}");
    }
    for var in ["TARGET", "HOST"] {
        println!(
            "cargo:rustc-env=RMFSURF_{var}={}",
            std::env::var(var).expect("cargo sets TARGET and HOST")
        );
    }
}
