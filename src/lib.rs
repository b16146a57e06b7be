//! Exact rational curves, rotation-minimizing frames and surfaces for sweeping and for
//! developable (sheet-metal) design.
//!
//! A sweep's moving frame should follow its spine without spinning about the tangent: the
//! rotation-minimizing frame (RMF). CAD kernels sample it and approximate the surface;
//! this crate gives it as rational functions, and pipes, mouldings and developable sheets as
//! rational Bézier / NURBS data ([`NurbsSurface`]) that CAD kernels take as they are. Four
//! published methods, each in its own part of the API:
//!
//! | module | method | entry points |
//! | --- | --- | --- |
//! | [`ph`] | PH cubic splines and their RMFs, profile surfaces: Mäurer & Jüttler \[MJ\] | [`ph::spline_hermite`], [`ph::spline_approximate`], [`ph::rational_rmf`], [`ph::ExactRmf`], [`ph::ProfileSurface`] |
//! | [`mobius`] | exact rational RMFs by Möbius maps: Bartoň, Jüttler & Wang \[BJW\] | [`mobius::MobiusMap`], [`mobius::hermite`], [`mobius::approximate`] |
//! | [`rrmf`] | quintics with exact rational RMFs: Farouki, Giannelli & Sestini \[FGS\] | [`rrmf::quintics`], [`rrmf::best_quintic`], [`rrmf::spline`] |
//! | [`cone`] | cone spline surfaces, development, bending: Leopoldseder & Pottmann \[LP\] | [`cone::pair`], [`cone::approximate`], [`cone::ConeSpline`] |
//! | [`wire`] | sweeps along wires of lines, arcs and curves into closed solids: \[MJ\] on curve edges, exact cylinders and tori | [`wire::sweep`], [`wire::Edge`], [`wire::WireSweep`], [`wire::Shape`] |
//! | [`sheet`] | sheet-metal parts: transitions, thickness, K-factor flat patterns, marks: \[LP\] and the classical transition layout | [`sheet::SheetPart`], [`sheet::SheetOptions`] |
//! | [`unfold`] | the user's own faces and sheet bodies, unrolled exactly, with a developability report | [`unfold::unfold_face`], [`unfold::unfold_body`] |
//!
//! The vocabulary they share is at the root: curves and surfaces as [`PiecewiseCurve`] and
//! [`PiecewiseSurface`] (rational Bézier pieces) converting to and from [`NurbsCurve`] and
//! [`NurbsSurface`]; frames ([`Frame`], [`RationalFrames`], [`FrameField`]) and curves with
//! them ([`FramedCurve`], made by [`framed_spine`] with any [`SpineMethod`]); the generic
//! rational [`sweep`]; the shapes handed over, [`Brep`] and [`FlatPattern`]. Algorithms that
//! only sample a curve take any [`ParametricCurve`]. The papers are cited in full in
//! `docs/references.md`; module and item docs cite them by equation number. Every fallible
//! function returns [`Result`]; its [`Error`] says what kind of failure ([`ErrorKind`]) and
//! names the offending argument.
//!
//! ```
//! use rmfsurf::prelude::*;
//!
//! // A PH cubic spline through G1 Hermite data on a helix, and its rational RMF.
//! let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=8)
//!     .map(|k| {
//!         let t = k as f64 * 0.5;
//!         (DVec3::new(t.cos(), t.sin(), 0.3 * t), DVec3::new(-t.sin(), t.cos(), 0.3))
//!     })
//!     .unzip();
//! let spine = ph::spline_hermite(&points, &tangents)?;
//! let rmf = ph::rational_rmf(&spine, &ph::RmfOptions::rmf(DVec3::Z))?;
//! assert!(ph::angle_errors(&spine, rmf.framed.frames())?.max < 1e-5);
//! # Ok::<(), rmfsurf::Error>(())
//! ```
//!
//! The geometry lives in safe Rust and knows nothing of C; the C ABI (`librmfsurf`,
//! `include/rmfsurf.h`) is the crate `rmfsurf-capi`, built on this crate's public API.

// Every public item says what it is, and nothing is public that the facade does not show:
// the facade is the book a newcomer reads.
#![warn(missing_docs, unreachable_pub)]

// The methods are public modules: `mobius`, `wire`, `sheet` and `unfold` are their own;
// `ph`, `rrmf` and `cone` (below) choose from the modules that follow their papers
// section by section (`ph_cubic`, `rrmf_quintic`, `cone_spline`).

mod bezier;
mod cone_spline;
mod curve;
mod error;
pub mod export;
mod frames;
mod hermite;
mod math;
mod mesh;
pub mod mobius;
mod model;
mod ph_cubic;
mod rrmf_quintic;
pub mod sheet;
mod solid;
mod spine;
mod sweep;
#[cfg(test)]
mod testing;
pub mod unfold;
pub mod wire;

/// The vector types of every signature (f64 throughout).
pub use glam;

// Errors.
pub use error::{Error, ErrorKind, Num, Result, ResultExt};

// Curves and surfaces: rational Bézier pieces, NURBS, sampled curves, Hermite data.
pub use bezier::{
    CurveJet, NurbsCurve, NurbsSurface, PiecewiseCurve, PiecewiseSurface, RationalBezierCurve,
    RationalBezierPatch, SurfaceJet, MAX_DEGREE,
};
pub use curve::{uniform_parameters, ParametricCurve, MAX_SAMPLES};
pub use hermite::{hermite_sequence, HermiteSegment};

// Frames along curves, spines with frames, and the generic rational sweep.
pub use frames::double_reflection::DoubleReflectionRmf;
pub use frames::rational::{FrameVector, RationalFrames};
pub use frames::{Frame, FrameField, FrameKind};
pub use model::FramedCurve;
pub use spine::{framed_spine, framed_spine_through, FramedSpine, SpineMethod, MAX_SPINE_SEGMENTS};
pub use sweep::{sweep, MAX_SWEEP_POLES};

// The shapes the methods hand over: B-rep models and flat patterns.
pub use model::{
    AnalyticCurve, AnalyticEdge, AnalyticFace, AnalyticSurface, Brep, BrepBound, BrepEdge,
    BrepFace, BrepSurface, BrepUse, FlatPattern, PCurve, PatternEdge,
};

// Meshes of surfaces (for viewers and mesh checks).
pub use mesh::{grid_normals, grid_parameters, mesh_size, tessellate, TriangleMesh};
pub use solid::{closed_mesh, ClosedMesh};

/// PH cubic splines, their rotation-minimizing frames (exactly and as rational functions)
/// and rational profile surfaces: Mäurer & Jüttler \[MJ\].
pub mod ph {
    pub use crate::ph_cubic::accuracy::{angle_errors, AngleErrors};
    pub use crate::ph_cubic::analysis::{
        convex_initial_normal, ConvexStart, ParabolicLines, ProfileSurface, SingularityMargin,
    };
    pub use crate::ph_cubic::approximate::{
        check_g1, ph_spline_approximate as spline_approximate,
        ph_spline_approximate_with as spline_approximate_with, ApproximationOptions,
        PhApproximation,
    };
    pub use crate::ph_cubic::arc_offset::{offset_profile_by_arcs, ArcOffset};
    pub use crate::ph_cubic::cubic::PH_TOLERANCE as TOLERANCE;
    pub use crate::ph_cubic::exact_rmf::ExactRmf;
    pub use crate::ph_cubic::frenet::ph_frenet_frames as frenet_frames;
    pub use crate::ph_cubic::offset::offset_profile;
    pub use crate::ph_cubic::parabolic::{ParabolicCurve, MAX_PARABOLIC_POINTS};
    pub use crate::ph_cubic::rational_rmf::{
        ph_rational_rmf as rational_rmf, RationalRmf, RmfOptions,
    };
    pub use crate::ph_cubic::spline::{ph_spline_from_segments as spline_from_segments, PhSpline};
    pub use crate::ph_cubic::{
        ph_cubic_hermite as cubic_hermite, ph_cubics as cubics,
        ph_spline_hermite as spline_hermite, PhCubic, PhHermiteSolutions,
    };
}

/// Quintic space curves with exact rational rotation-minimizing frames (RRMF quintics) by
/// G1 Hermite interpolation, and splines of them: Farouki, Giannelli & Sestini \[FGS\].
pub mod rrmf {
    pub use crate::math::Complex;
    pub use crate::rrmf_quintic::canonical::CanonicalHermite;
    pub use crate::rrmf_quintic::frames::{quintic_curve, quintic_rmf};
    pub use crate::rrmf_quintic::planar::{planar_deviation, planar_quintic, PLANAR_TOLERANCE};
    pub use crate::rrmf_quintic::{
        best_quintic, best_quintic_within, rrmf_quintics as quintics,
        rrmf_quintics_reporting as quintics_reporting, rrmf_spline as spline,
        rrmf_spline_within as spline_within, BestQuintic, Budget, IrregularRoot, RrmfQuintic,
        RrmfSolutions as Solutions, RrmfSpline, ShapeMeasure, ShapeMeasures, MAX_ETA_SAMPLES,
        MAX_REFINEMENT_SOLVES,
    };
}

/// Cone spline surfaces: developables approximated by cones, cylinders and planes joined G1
/// along rulings, their exact development and bending: Leopoldseder & Pottmann \[LP\].
pub mod cone {
    pub use crate::cone_spline::approximate::{approximate, DEFAULT_MAX_PIECES};
    pub use crate::cone_spline::developable::{
        max_scaled_curvature, Developable, DualDevelopable, RuledSurface, Ruling, TangentSurface,
        DEVELOPABILITY_TOLERANCE,
    };
    pub use crate::cone_spline::osculating::osculating_spline;
    pub use crate::cone_spline::{
        cone_pair as pair, Approximation, ConePair, ConePiece, ConeSpline, Element, Motion,
        PairCase, PieceKind, Region, Rule, SweptBand,
    };
}

/// The curves users draw, as exact rational Bézier pieces: circles, circular arcs,
/// polylines, polygons and obrounds (slots).
pub mod primitives {
    pub use crate::model::{arc_through, circle, obround, polygon, polyline};
}

/// Measures of frames and surfaces: how far frames are from rotation-minimizing, from each
/// other and from orthonormal, the angle between parameter lines, Gaussian curvature.
pub mod metrics {
    pub use crate::frames::compare::{frame_errors, nearest_parameter, FrameErrors, ReferenceRmf};
    pub use crate::frames::metrics::{
        angle_about_tangent, gaussian_curvature, orthonormality_error, parameter_line_cosine,
        rmf_defect, scaled_gaussian_curvature,
    };
    pub use crate::math::angle_between;
}

/// The checks the constructors apply to their arguments, for layers (such as the C API)
/// that validate raw input before building anything.
pub mod validate {
    pub use crate::bezier::{check_in_domain, check_nurbs_counts};
    pub use crate::curve::check_sample_count;
    pub use crate::math::{check_finite, normal_plane_unit};
}

/// Overflow-free arithmetic the C layer shares with the geometry: points of a parameter
/// interval of any width, lengths of vectors of any size.
pub mod numeric {
    pub use crate::math::{lerp, robust_length, robust_normalize};
}

/// What most programs need: `use rmfsurf::prelude::*;` — the vocabulary types and the
/// method modules, so that calls read `ph::spline_hermite(…)`, `wire::sweep(…)`.
pub mod prelude {
    pub use crate::cone::ConeSpline;
    pub use crate::ph::{ExactRmf, RmfOptions};
    pub use crate::wire::{Edge, PipeFrame, Shape, SweepFrame, WireSweep};
    pub use crate::{cone, mobius, ph, rrmf, sheet, unfold, wire};
    pub use crate::{
        framed_spine, sweep, Error, ErrorKind, FrameField, FramedCurve, NurbsCurve, NurbsSurface,
        ParametricCurve, PiecewiseCurve, PiecewiseSurface, RationalFrames, Result, ResultExt,
        SpineMethod,
    };
    pub use glam::DVec3;
}
