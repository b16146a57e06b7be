//! The model layer under the methods: the vocabulary the constructions build and their
//! consumers (sweeps, sheet parts, exporters, the C and Python layers) share.
//!
//! | module | holds |
//! | --- | --- |
//! | `framed` | [`FramedCurve`]: a curve with rational frames adapted to it, what every frame method returns and sweeps and analyses take |
//! | `topology` | [`Brep`]: vertices, edges shared by faces, loops with pcurves, faces with sense |

mod framed;
mod primitives;
mod similarity;
mod topology;

pub(crate) use framed::on_frame_segments;
pub use framed::FramedCurve;
pub(crate) use primitives::Arc;
pub use primitives::{arc_through, circle, obround, polygon, polyline};
pub(crate) use similarity::Similarity;
pub use topology::{Brep, BrepBound, BrepEdge, BrepFace, BrepSurface, BrepUse, PCurve};
