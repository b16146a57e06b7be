//! The model layer under the methods: the vocabulary the constructions build and their
//! consumers (sweeps, sheet parts, exporters, the C and Python layers) share.
//!
//! | module | holds |
//! | --- | --- |
//! | `framed` | [`FramedCurve`]: a curve with rational frames adapted to it, what every frame method returns and sweeps and analyses take |

mod framed;

pub(crate) use framed::on_frame_segments;
pub use framed::FramedCurve;
