//! PH cubic splines, their rotation-minimizing frames (exactly and as rational functions) and
//! rational profile surfaces, after C. Mäurer and B. Jüttler, "Rational approximation of
//! rotation minimizing frames using Pythagorean-hodograph cubics" (equation numbers below are
//! the paper's).
//!
//! | module | computes | paper |
//! | --- | --- | --- |
//! | [`cubic`] | one PH cubic: condition (17), speed, arc length, curvature | (17), (18) |
//! | [`hermite`] | both PH cubics through G1 Hermite data | Table 1 |
//! | [`spline`] | PH cubic splines through Hermite data; PH cubics of a spline | §3.2 |
//! | [`approximate`] | PH cubic splines approximating any curve to a tolerance | Theorem 10 |
//! | [`preimage`] | the quaternion form x' = A i A* and the Euler–Rodrigues frame | (17) |
//! | [`frenet`] | the rational Frenet frame | (19) |
//! | [`rmf_angle`] | the exact RMF angle against the Frenet frame, closed form | (30), (31) |
//! | [`base_frame`] | the frame each segment's RMF is built on; frame numerators | (29) |
//! | [`exact_rmf`] | the exact RMF of a PH cubic spline, chained over its segments | (5), (30) |
//! | [`biquadratic`] | the rational W(v) approximating tan(Ω/2) | (34)–(41), Lemma 11 |
//! | [`rational_rmf`] | rational RMFs of splines, with twist and closure of closed spines | (29), (42) |
//! | [`accuracy`] | angle between rational frames and the exact RMF | §3.4 |
//! | [`analysis`] | singularities, parabolic lines, curvature sign, convexity of profile surfaces | (9), (13), (14), Cor. 7, 9 |
//! | [`parabolic`] | the parabolic lines (14) traced as curves along the spine | (14), §2.3 |
//! | [`profile`] | the planar profile c(u): tangent and curvature polynomials | (1), (11) |
//! | [`arc_offset`] | offsets of other profiles: exact offsets of a biarc approximation | (7)–(8) of Fuhs & Stachel |
//! | [`offset`] | offsets of profile surfaces as profile surfaces of offset profiles | Proposition 4 |

//!
//! The profile surface itself, (42), is the generic rational sweep of [`crate::sweep`].

pub(crate) mod accuracy;
pub(crate) mod analysis;
pub(crate) mod approximate;
pub(crate) mod arc_offset;
pub(crate) mod base_frame;
pub(crate) mod biquadratic;
pub(crate) mod cubic;
pub(crate) mod exact_rmf;
pub(crate) mod frenet;
pub(crate) mod hermite;
pub(crate) mod offset;
pub(crate) mod parabolic;
pub(crate) mod preimage;
pub(crate) mod profile;

pub(crate) mod rational_rmf;
pub(crate) mod rmf_angle;
pub(crate) mod spline;
#[cfg(test)]
pub(crate) mod test_curves;

pub use cubic::PhCubic;
pub use hermite::{ph_cubic_hermite, PhHermiteSolutions};
pub use spline::{ph_cubics, ph_spline_hermite};
