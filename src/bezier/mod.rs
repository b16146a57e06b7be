//! Rational Bézier curves and tensor-product surfaces in homogeneous form, their
//! piecewise (spline) assemblies, and conversion to and from NURBS.
//!
//! Every curve, frame vector and surface the library returns is built from these types:
//! * [`bernstein`]: polynomial algebra in Bernstein form (evaluation, products, elevation),
//! * [`RationalBezierCurve`] and [`RationalBezierPatch`]: one segment or patch,
//! * [`PiecewiseCurve`] and [`PiecewiseSurface`]: segments on consecutive intervals,
//! * [`NurbsCurve`] and [`NurbsSurface`]: the clamped NURBS form CAD systems take.

pub(crate) mod bernstein;
pub(crate) mod closest;
mod curve;
pub(crate) mod homogeneous;
mod nurbs;
mod piecewise;
mod surface;

pub use bernstein::MAX_DEGREE;
pub use curve::{CurveJet, RationalBezierCurve};
pub use nurbs::{check_nurbs_counts, NurbsCurve, NurbsSurface};
pub(crate) use nurbs::{fit_splines, spline_value};
pub(crate) use piecewise::{check_breaks, locate};
pub use piecewise::{check_in_domain, PiecewiseCurve, PiecewiseSurface};
pub use surface::{RationalBezierPatch, SurfaceJet};
