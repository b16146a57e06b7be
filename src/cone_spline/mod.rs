//! Cone spline surfaces (Leopoldseder & Pottmann, *Approximation of developable surfaces
//! with cone spline surfaces*): developable surfaces made of segments of right circular
//! cones, cylinders of revolution and planes, joined G1 along common rulings.
//!
//! | module | what it computes | paper |
//! | --- | --- | --- |
//! | [`element`] | G1 Hermite elements (ruling, tangent plane, side vector) | "G1 Hermite elements", Fig. 2 |
//! | [`region`] | the region of interest Ω: a box, or the band of each ruling swept over an interval | "Fundamentals", Figs. 5–6 |
//! | [`piece`] | one cone/cylinder/plane segment as a ruling swept by a rotation | Figs. 1, 16 |
//! | [`pair`] | cone pairs through two elements, every case, rules | (5)–(6), (9)–(13), Theorem 1 |
//! | [`spline`] | the G1 chain, Hermite interpolation of element sequences | |
//! | [`surface`] | exact degree (1, 2) patches, boundary arc splines, box bounds | Fig. 1 |
//! | [`developable`] | inputs: tangent surfaces, ruled (1, n) NURBS, dual form; inflection generators | (1), (2), (4) |
//! | [`approximate`] | adaptive approximation within a tolerance, vertices outside Ω | "G1 Hermite elements", Figs. 5–6 |
//! | [`osculating`] | osculating cones and their joining cones | (3), (14), Figs. 13–15 |
//! | [`develop`] | bending sequences and the exact development | φ sin α = const, Figs. 16–17 |
//! | [`offset`] | offsets, again cone splines | "Introduction" |
//! | [`pattern`] | the flat pattern of a strip: lines and circular arcs for cutting | Figs. 16–17 |
//!
//! The biarcs of the pairs (eqs. (7), (8)) and the flat pattern's types live in the model
//! layer (`crate::model`), shared with the PH offsets, the sheet parts and the exporters.

pub(crate) mod approximate;
mod develop;
pub(crate) mod developable;
pub(crate) mod element;
mod offset;
pub(crate) mod osculating;
pub(crate) mod pair;
pub(crate) mod pattern;
pub(crate) mod piece;
pub(crate) mod region;
pub(crate) mod spline;
mod surface;

pub use approximate::Approximation;
pub use element::Element;
pub use pair::{cone_pair, ConePair, PairCase, Rule};
pub use piece::{ConePiece, Motion, PieceKind};
pub use region::{Region, SweptBand};
pub use spline::ConeSpline;

#[cfg(test)]
pub(crate) mod test_support;
