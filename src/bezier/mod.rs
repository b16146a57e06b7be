//! Rational Bézier curves and tensor-product surfaces in homogeneous form, their
//! piecewise (spline) assemblies, and conversion to and from NURBS.
//!
//! Every curve, frame vector and surface the library returns is built from these types:
//! * [`bernstein`]: polynomial algebra in Bernstein form (evaluation, products, elevation),
//! * [`RationalBezierCurve`] and [`RationalBezierPatch`]: one segment or patch,
//! * [`PiecewiseCurve`] and [`PiecewiseSurface`]: segments on consecutive intervals,
//! * [`NurbsCurve`] and [`NurbsSurface`]: the clamped NURBS form CAD systems take.

pub mod bernstein;
pub(crate) mod closest;
mod curve;
pub mod homogeneous;
mod nurbs;
mod piecewise;
mod surface;

pub use bernstein::MAX_DEGREE;
pub use curve::{CurveJet, RationalBezierCurve};
pub use nurbs::{check_nurbs_counts, NurbsCurve, NurbsSurface};
pub use piecewise::{check_breaks, check_in_domain, locate, PiecewiseCurve, PiecewiseSurface};
pub use surface::{RationalBezierPatch, SurfaceJet};
