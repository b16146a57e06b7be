//! Unfolding what the user has: any face of a B-rep — analytic or NURBS, trimmed by its own
//! boundary and holes — with a report of how developable it is, unrolled exactly where it
//! is developable.
//!
//! | module | what it computes | from |
//! | --- | --- | --- |
//! | `kind` | the kind of a face's surface: plane, circular cylinder, right cone, general cylinder or cone, tangent or other ruled developable, not developable | \[LP\] (1), (2) |
//! | `develop` | the isometry face ↔ plane: closed forms for planes, cylinders and cones, the cone spline's development for the rest | \[LP\] "Bending sequences and development" |
//! | `face` | a face's flat pattern: its loops as lines, arcs and biarcs, bend lines, the report | \[LP\] (7)–(8) (biarcs) |
//! | `body` | a whole sheet body: its skins and thickness, the neutral layer at the K-factor, the faces' patterns joined along their bends, bend lines up and down | \[LP\] "Introduction" (offsets) |
//! | `stretch` | how far a face that is not developable must stretch: a least-squares flattening | |

mod body;
mod develop;
mod face;
mod kind;
mod stretch;

pub use body::{unfold_body, Bend, BodyOptions, KFactor, UnfoldedBody};
pub use face::{face_developability, unfold_face, Developability, UnfoldOptions, UnfoldedFace};
pub use kind::SurfaceKind;

#[cfg(test)]
mod body_tests;
#[cfg(test)]
mod tests;
