//! Quintic space curves with rational rotation-minimizing frames (RRMF quintics) by G1
//! Hermite interpolation: R. T. Farouki, C. Giannelli and A. Sestini, "Geometric design
//! using space curves with rational rotation-minimizing frames" (reference [3] of
//! docs/references.md).
//!
//! A spatial PH quintic is given by two complex quadratics α(t), β(t) through the Hopf map
//! (2)–(3); it has a rational RMF (9) of degree 8 exactly when its coefficients satisfy
//! (7)–(8). Interpolating end points and unit tangents leaves a one-parameter family of
//! such quintics, parameterized by an angle η; for each η the end-derivative ratio ρ is a
//! positive root of a sextic (35). The modules follow the paper:
//!
//! | module | computes | equations |
//! | --- | --- | --- |
//! | [`canonical`] | canonical Hermite data, θ_i, θ_f, φ, c_i, s_i, c_f, s_f | (11)–(13) |
//! | [`hopf`] | hodograph, control points, ERF, w(t), rational RMF, RRMF residuals | (2)–(9) |
//! | `sextic` | μ₀, μ₁, f₁, δ₀, δ₁, δ₂, the sextic and its roots, a_k, b_k | (25)–(38) |
//! | `special` | the special case α₁ = 0 (s_f = ±s_i with the matching η) | after (25) |
//! | [`solutions`] | f₂, γ, α_k, β_k, verification: the Algorithm of Section 4 | (36)–(40) |
//! | [`measures`] | arc length L, energies E and E_rmf | footnote 6 |
//! | [`frames`] | the RMF (9) as exact rational frames with positive weights | (9) |
//! | [`planar`] | planar data: the planar PH quintic and its RMF (ERF = RMF) | (2)–(5), footnote 4 |
//! | [`eta`] | the η of least E_rmf, E or L: scan, then Brent refinement | Section 5 |
//! | [`spline`] | G1 RRMF quintic splines with one continuous rational RMF | Example 3 |

pub(crate) mod canonical;
pub(crate) mod eta;
pub(crate) mod frames;
pub(crate) mod hopf;
pub(crate) mod measures;
pub(crate) mod planar;
mod polynomial;
mod sextic;
pub(crate) mod solutions;
mod special;
pub(crate) mod spline;

pub use eta::{
    best_quintic, best_quintic_within, BestQuintic, Budget, MAX_ETA_SAMPLES, MAX_REFINEMENT_SOLVES,
};
pub use measures::{ShapeMeasure, ShapeMeasures};
pub use solutions::{
    rrmf_quintics, rrmf_quintics_reporting, IrregularRoot, RrmfQuintic, Solutions as RrmfSolutions,
};
pub use spline::{rrmf_spline, rrmf_spline_within, RrmfSpline};
