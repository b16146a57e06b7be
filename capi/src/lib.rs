//! The C API: the only place that knows about C. Everything here is thin: check pointers
//! and counts, convert to core types, call the geometry inside the panic boundary
//! (`boundary::guard`), map `Result` to `RmfStatus`, and write out-pointers last.
//!
//! One module per C type: [`curve`] (`RmfCurve`; the primitive curves in [`primitives`]), [`frames`] (`RmfFrames`), [`surface`]
//! (`RmfSurface`), [`shape`] (`RmfShape`, made by the wire sweeps of [`wire`]), [`sheet`]
//! (`RmfSheetOptions`, sheet-metal parts), [`unfold`] (`RmfUnfoldedFace`, the caller's faces unrolled); [`status`] holds the status codes, last error and
//! version; [`types`]
//! the plain data structs and borrowed views; [`input`] the inputs several capabilities
//! share (Hermite arrays, callback curves). The header `include/rmfsurf.h` is generated
//! from these modules by cbindgen.

// The safety contract of every `unsafe extern "C"` entry point is its C contract, written
// in its doc comment (and the header): each pointer is NULL or valid for the access
// described, handles come from this library and are not used after being freed.
#![allow(clippy::missing_safety_doc)]
// Every public item is documented; its doc comment is also the header's (cbindgen).
#![warn(missing_docs)]

mod boundary;
pub mod brep;
pub mod cone_spline;
pub mod curve;
pub mod frames;
pub mod input;
pub mod mobius;
pub mod ph_cubic;
pub mod primitives;
pub mod rrmf_quintic;
pub mod shape;
pub mod sheet;
pub mod status;
pub mod surface;
pub mod types;
pub mod unfold;
pub mod wire;

pub use brep::RmfBrep;
pub use cone_spline::RmfConeSpline;
pub use curve::RmfCurve;
pub use frames::RmfFrames;
pub use shape::RmfShape;
pub use sheet::{RmfFlatEdge, RmfSheetOptions, RmfSheetReport};
pub use status::RmfStatus;
pub use surface::RmfSurface;
pub use types::{RmfBezierCurve, RmfBezierPatch, RmfNurbsCurve, RmfNurbsSurface, RmfVec2, RmfVec3};
pub use unfold::{
    RmfBend, RmfDevelopability, RmfUnfoldBodyOptions, RmfUnfoldOptions, RmfUnfoldedBody,
    RmfUnfoldedFace,
};
