//! Curves with exact rational rotation-minimizing frames by Möbius transformations:
//! M. Bartoň, B. Jüttler and W. Wang, "Construction of rational curves with rational
//! rotation-minimizing frames via Möbius transformations" \[BJW\].
//!
//! | module | computes | paper |
//! | --- | --- | --- |
//! | `transform` | inversions in spheres and planes, their compositions and differentials | §2.2 |
//! | `image` | exact images of rational curves and rational frames, which by Theorem 1 stay rotation-minimizing | Corollary 1 |
//! | `segment_map` | for one segment's Hermite data, the inversion mapping its sphere onto a plane through both points | Section 3.1, step 2 |
//! | `hermite` | G1 Hermite interpolation and approximation of space curves by Möbius images of planar PH cubics, one continuous rational RMF | Section 3.1 |

pub(crate) mod hermite;
pub(crate) mod image;
pub(crate) mod segment_map;
pub(crate) mod transform;

pub use hermite::{
    mobius_approximate as approximate, mobius_hermite as hermite,
    mobius_hermite_points as hermite_points,
};
pub use image::{map_curve, map_framed_curve};
pub use transform::{Inversion, MobiusMap};
