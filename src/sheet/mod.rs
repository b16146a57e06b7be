//! Sheet-metal parts from cone spline surfaces (Leopoldseder & Pottmann \[LP\]): parts
//! bounded by the user's own curves, transition pieces between two closed curves, sheet
//! thickness with K-factor flat patterns, and marks carried between flat and formed.
//!
//! | module | what it computes | from |
//! | --- | --- | --- |
//! | `profile` | closed convex planar curves by their Gauss map (corners, edges, arcs) | support functions |
//! | `transition` | the convex-hull developable between two curves: planes, cones, creases | classical transition-piece layout; \[LP\] (5)–(12) |
//! | `trim` | a cone spline trimmed between two boundary curves: rows, layers, cut faces | \[LP\] Fig. 1, "Introduction" (offsets) |
//! | `thickness` | inner, neutral (K-factor) and outer layers; bend sides and radii | \[LP\] "Introduction" |
//! | `flat` | the flat pattern of a layer: lines, arcs and biarcs | \[LP\] "Bending sequences and development", (7)–(8) |
//! | `rails` | parts between the rails of a ruled developable or of a tangent surface | \[LP\] (1), (2); distances along the rulings fitted as cubics |
//! | `marks` | the isometry flat ↔ formed for points | φ sin α = const |
//! | `brep` | the part's solid as a B-rep: faces, shared edges and vertices named by construction | \[LP\] Fig. 1 |
//! | `part` | [`SheetPart`]: the public face of all of the above | |

mod brep;
mod flat;
pub(crate) mod marks;
pub(crate) mod part;
mod profile;
pub(crate) mod rails;
pub(crate) mod thickness;
mod transition;
pub(crate) mod trim;

pub use part::{PartReport, SheetOptions, SheetPart, Side};
pub use thickness::{Layer, Reference, Sheet};

#[cfg(test)]
mod tests;
#[cfg(test)]
mod transition_classes;
