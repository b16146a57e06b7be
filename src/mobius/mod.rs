//! Curves with exact rational rotation-minimizing frames by Möbius transformations
//! (M. Bartoň, B. Jüttler, W. Wang, "Construction of rational curves with rational
//! rotation-minimizing frames via Möbius transformations").
//!
//! * [`transform`]: inversions in spheres and planes, compositions, differentials (§2.2);
//! * [`image`]: exact images of rational curves and rational frames (Corollary 1), which by
//!   Theorem 1 keep rotation-minimizing frames rotation-minimizing.

pub mod hermite;
pub mod image;
pub mod segment_map;
pub mod transform;

pub use hermite::{mobius_approximate, mobius_hermite, mobius_hermite_points};
pub use image::{map_curve, map_framed_curve};
pub use transform::{Inversion, MobiusMap};
