//! Shared numerical building blocks: binomial coefficients, complex numbers, validated vectors,
//! classes of joined items (union–find),
//! robust polynomial root finding, secant polishing of roots, Gauss–Legendre quadrature and
//! 1-D minimization.
//!
//! Every geometric module takes these from here rather than writing its own.

mod binomial;
mod classes;
mod complex;
mod double_double;
mod interval;
mod linear;
mod minimize;
mod quadrature;
mod roots;
mod secant;
mod units;
mod vector;

pub(crate) use binomial::{binomial, binomial_row, reciprocal_binomial_row};
pub(crate) use classes::Classes;
pub use complex::Complex;
pub(crate) use double_double::{DoubleDouble, DoubleDoubleVec3};
pub use interval::lerp;
pub(crate) use interval::{fraction, reciprocal_length};
pub(crate) use linear::solve_refined;
pub(crate) use minimize::minimize_bracketed;
pub(crate) use quadrature::GaussLegendre;
pub(crate) use roots::{
    bisect_root, illinois_root, interior_midpoint, quadratic_roots, real_roots_in,
    real_roots_power, sampled_roots,
};
pub(crate) use secant::secant_refine;
pub(crate) use units::in_caller_units;
pub use vector::{angle_between, check_finite, normal_plane_unit, robust_length, robust_normalize};
pub(crate) use vector::{
    bounding_diagonal, check_point, check_unit_direction, largest_coordinate, orthogonalized,
    orthonormal_to, power_of_two_inverse, power_of_two_scale, signed_angle, unit_scaled,
};
