//! Exact rational curves, rotation-minimizing frames and surfaces for sweeping and for
//! developable (sheet-metal) design.
//!
//! A sweep's moving frame should follow its spine without spinning about the tangent: the
//! rotation-minimizing frame (RMF). CAD kernels sample it and approximate the surface;
//! this crate gives it as rational functions, and pipes, mouldings and developable sheets as
//! rational Bézier / NURBS data ([`NurbsSurface`]) that CAD kernels take as they are. Four
//! published methods, each in its own part of the API:
//!
//! | part | method | entry points |
//! | --- | --- | --- |
//! | PH cubic splines and their RMFs, profile surfaces | Mäurer & Jüttler \[MJ\] | [`ph_spline_hermite`], [`ph_spline_approximate`], [`ph_rational_rmf`], [`ExactRmf`], [`sweep`], [`ProfileSurface`] |
//! | exact rational RMFs by Möbius maps | Bartoň, Jüttler & Wang \[BJW\] | [`MobiusMap`], [`mobius_hermite`], [`mobius_approximate`] |
//! | quintics with exact rational RMFs | Farouki, Giannelli & Sestini \[FGS\] | [`rrmf_quintics`], [`best_quintic`], [`rrmf_spline`] |
//! | cone spline surfaces, development, bending | Leopoldseder & Pottmann \[LP\] | [`cone_pair`], [`approximate_developable`], [`ConeSpline`], [`FlatPattern`] |
//! | sweeps along wires of lines, arcs and curves into closed solids | \[MJ\] on curve edges, exact cylinders and tori | [`sweep_wire`], [`Edge`], [`WireSweep`], [`Shape`] |
//! | sheet-metal parts: transitions, thickness, K-factor flat patterns, marks | \[LP\] and the classical transition layout | [`SheetPart`], [`SheetOptions`] |
//!
//! The papers are cited in full in `docs/references.md`; module and item docs cite them by
//! equation number. Curves and surfaces are [`PiecewiseCurve`] and [`PiecewiseSurface`]
//! (rational Bézier pieces) and convert to and from NURBS; algorithms that only sample a
//! curve take any [`ParametricCurve`]. Every fallible function returns [`Result`]; its
//! [`Error`] says what kind of failure ([`ErrorKind`]) and names the offending argument.
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
//! let spine = ph_spline_hermite(&points, &tangents)?;
//! let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(DVec3::Z))?;
//! assert!(angle_errors(&spine, rmf.framed.frames())?.max < 1e-5);
//! # Ok::<(), rmfsurf::Error>(())
//! ```
//!
//! The geometry lives in safe Rust and knows nothing of C; the C ABI (`librmfsurf`,
//! `include/rmfsurf.h`) is the crate `rmfsurf-capi`, built on this crate's public API.

// Every public item says what it is: the facade is the book a newcomer reads.
#![warn(missing_docs)]

mod bezier;
mod cone_spline;
mod curve;
mod error;
pub mod export;
mod frames;
mod hermite;
mod math;
mod mesh;
mod mobius;
mod model;
mod ph_cubic;
mod rrmf_quintic;
mod sheet;
mod solid;
mod spine;
mod sweep;
#[cfg(test)]
mod testing;
mod unfold;
mod wire;

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

// Frames along curves and sweeps with them.
pub use frames::double_reflection::DoubleReflectionRmf;
pub use frames::rational::{FrameVector, RationalFrames};
pub use frames::{Frame, FrameField, FrameKind};
pub use model::{Brep, BrepBound, BrepEdge, BrepFace, BrepSurface, BrepUse, FramedCurve, PCurve};
pub use spine::{framed_spine, framed_spine_through, FramedSpine, SpineMethod, MAX_SPINE_SEGMENTS};
pub use sweep::{sweep, MAX_SWEEP_POLES};

// PH cubic splines, their RMFs and profile surfaces [MJ].
pub use ph_cubic::accuracy::{angle_errors, AngleErrors};
pub use ph_cubic::analysis::{
    convex_initial_normal, ConvexStart, ParabolicLines, ProfileSurface, SingularityMargin,
};
pub use ph_cubic::approximate::{
    check_g1, ph_spline_approximate, ph_spline_approximate_with, ApproximationOptions,
    PhApproximation,
};
pub use ph_cubic::arc_offset::{offset_profile_by_arcs, ArcOffset};
pub use ph_cubic::cubic::PH_TOLERANCE;
pub use ph_cubic::exact_rmf::ExactRmf;
pub use ph_cubic::frenet::ph_frenet_frames;
pub use ph_cubic::offset::offset_profile;
pub use ph_cubic::parabolic::{ParabolicCurve, MAX_PARABOLIC_POINTS};
pub use ph_cubic::rational_rmf::{ph_rational_rmf, RationalRmf, RmfOptions};
pub use ph_cubic::spline::{ph_spline_from_segments, PhSpline};
pub use ph_cubic::{ph_cubic_hermite, ph_cubics, ph_spline_hermite, PhCubic, PhHermiteSolutions};

// Curves with exact rational RMFs by Möbius transformations [BJW].
pub use mobius::{
    map_curve, map_framed_curve, mobius_approximate, mobius_hermite, mobius_hermite_points,
    Inversion, MobiusMap,
};

// Quintics with exact rational RMFs [FGS].
pub use math::Complex;
pub use rrmf_quintic::canonical::CanonicalHermite;
pub use rrmf_quintic::frames::{quintic_curve, quintic_rmf};
pub use rrmf_quintic::planar::{
    planar_deviation as rrmf_planar_deviation, planar_quintic,
    PLANAR_TOLERANCE as RRMF_PLANAR_TOLERANCE,
};
pub use rrmf_quintic::{
    best_quintic, best_quintic_within, rrmf_quintics, rrmf_quintics_reporting, rrmf_spline,
    rrmf_spline_within, BestQuintic, Budget as RrmfBudget, IrregularRoot, RrmfQuintic,
    RrmfSolutions, RrmfSpline, ShapeMeasure, ShapeMeasures,
    MAX_ETA_SAMPLES as RRMF_MAX_ETA_SAMPLES, MAX_REFINEMENT_SOLVES as RRMF_MAX_REFINEMENT_SOLVES,
};

// Cone spline surfaces: developables, development, bending [LP].
pub use cone_spline::approximate::{approximate as approximate_developable, DEFAULT_MAX_PIECES};
pub use cone_spline::developable::{
    max_scaled_curvature, Developable, DualDevelopable, RuledSurface, Ruling, TangentSurface,
    DEVELOPABILITY_TOLERANCE,
};
pub use cone_spline::osculating::osculating_spline;
pub use cone_spline::{
    cone_pair, Approximation, ConePair, ConePiece, ConeSpline, Element, FlatPattern, Motion,
    PairCase, PatternEdge, PieceKind, Region, Rule, SweptBand,
};

// Sweeps along wires (lines, arcs, curves, corners) into closed solids of exact faces.
pub use wire::{
    sweep_wire, sweep_wire_between, sweep_wire_through, Corner, Edge, Face, FaceKind, Section,
    Shape, SweepFrame, SweepReport, WireSweep, MAX_FACES,
};
// Sheet-metal parts: transition pieces between two curves, thickness and K-factor, the
// neutral layer's flat pattern, marks between flat and formed [LP].
pub use sheet::{Layer, PartReport, Reference, Sheet, SheetOptions, SheetPart, Side};

// Unfolding the user's own faces: developability report, exact flat patterns.
pub use unfold::{
    face_developability, unfold_body, unfold_face, Bend, BodyOptions, Developability, KFactor,
    SurfaceKind, UnfoldOptions, UnfoldedBody, UnfoldedFace,
};

// Meshes of surfaces (for viewers and mesh checks).
pub use mesh::{grid_normals, grid_parameters, mesh_size, tessellate, TriangleMesh};
pub use solid::{closed_mesh, ClosedMesh};

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

/// What most programs need: `use rmfsurf::prelude::*;`.
pub mod prelude {
    pub use crate::{
        angle_errors, approximate_developable, mobius_approximate, mobius_hermite, ph_rational_rmf,
        ph_spline_approximate, ph_spline_hermite, rrmf_spline, sweep, sweep_wire, ConeSpline, Edge,
        Error, ErrorKind, ExactRmf, FrameField, NurbsCurve, NurbsSurface, ParametricCurve,
        PiecewiseCurve, PiecewiseSurface, RationalFrames, Result, ResultExt, RmfOptions, Shape,
        SweepFrame, WireSweep,
    };
    pub use glam::DVec3;
}
