//! rmfsurf's tests that drive external programs, kept out of a plain `cargo test` (this crate
//! is not a default member of the workspace), which needs only Rust and a C compiler:
//!
//! | test | drives |
//! | --- | --- |
//! | `tests/c_suite.rs` | valgrind and AddressSanitizer + UBSan on `c_tests/abi_*.c`; OpenMesh and VTK (`c_tests/geometry_*.cpp`); the demo |
//! | `tests/freecad.rs` | `freecadcmd` reading the tool's files, the Python package inside FreeCAD |
//! | `tests/workbench.rs` | the FreeCAD workbench, headless and in the GUI under Xvfb; the addon tree as the Addon Manager takes it |
//! | `tests/openscad.rs` | `openscad` rendering the tool's `.scad` files |
//! | `tests/opencascade.rs` | OpenCascade's kernel and STEP reader |
//! | `tests/vtk_reader.rs` | VTK's `vtkXMLPolyDataReader` on the tool's `.vtp` files |
//! | `tests/python.rs` | the Python package as published (`scripts/python-dist`: the manylinux wheel, the sdist), each installed, then pytest |
//! | `tests/publish.rs` | the packages' metadata against the crate's (addresses, licenses) |
//! | `tests/docs_site.rs` | `scripts/docs-site`: rustdoc, Doxygen, pdoc and the guide into one site, its links checked |
//! | `tests/install.rs` | `scripts/install` and its consumers: CMake, pkg-config, make |
//!
//! `scripts/setup-debian test` installs what they run, and `scripts/test` runs them after
//! the default tests: `cargo test -p rmfsurf-integration -- --nocapture`. A missing program
//! or library makes a test fail with a message naming that command; none skips.
//!
//! The library has nothing here; the tests share `tests/support`, which includes capi's
//! `tests/support/mod.rs` (building the library, the compilers, running C programs).

#[cfg(test)]
mod tests {
    /// The tests compare the version of what they install (the wheel, the addon, the
    /// pkg-config and CMake files) with this crate's; it must be the library's.
    #[test]
    fn the_integration_crate_has_the_librarys_version() {
        let library = unsafe { std::ffi::CStr::from_ptr(rmfsurf_capi::status::rmf_version()) };
        assert_eq!(
            library.to_str().unwrap(),
            env!("CARGO_PKG_VERSION"),
            "integration/Cargo.toml's version is not the library's (capi/Cargo.toml)"
        );
    }
}
