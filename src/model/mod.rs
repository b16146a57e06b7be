//! The model layer under the methods: the vocabulary the constructions build and their
//! consumers (sweeps, sheet parts, exporters, the C and Python layers) share.
//!
//! | module | holds |
//! | --- | --- |
//! | `framed` | [`FramedCurve`]: a curve with rational frames adapted to it, what every frame method returns and sweeps and analyses take |
//! | `topology` | [`Brep`]: vertices, edges shared by faces, loops with pcurves, faces with sense |
//! | `analytic` | the planes, cylinders and tori, lines and circles a B-rep's faces and edges are exactly |
//! | `similarity` | `Similarity`: x ↦ origin + scale·x, how constructions work at unit size |
//! | `primitives` | circles, arcs, polylines, polygons, obrounds as exact rational pieces |
//! | `biarc` | planar and spherical biarcs and polar (Bézier) planes (Leopoldseder & Pottmann, eqs. (7), (8)) |
//! | `planar` | lines, arcs and G1 biarcs drawing a planar curve within a tolerance; closed loops of them |
//! | `pattern` | [`FlatPattern`]: a developed outline of lines and circular arcs with its bend lines |

mod analytic;
pub(crate) mod biarc;
mod framed;
mod pattern;
pub(crate) mod planar;
mod primitives;
mod similarity;
mod topology;

pub(crate) use framed::on_frame_segments;
pub use framed::FramedCurve;
pub use pattern::{FlatPattern, PatternEdge};
pub(crate) use primitives::Arc;
pub use primitives::{arc_through, circle, obround, polygon, polyline};
pub(crate) use similarity::Similarity;

pub(crate) use analytic::{is_centred_arc, settle as settle_analytic, ROUNDING};
pub use analytic::{AnalyticCurve, AnalyticEdge, AnalyticFace, AnalyticSurface};
pub use topology::{Brep, BrepBound, BrepEdge, BrepFace, BrepSurface, BrepUse, PCurve};
