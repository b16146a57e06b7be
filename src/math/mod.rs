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

pub use binomial::{binomial, binomial_row, reciprocal_binomial_row};
pub(crate) use classes::Classes;
pub use complex::Complex;
pub use double_double::{DoubleDouble, DoubleDoubleVec3};
pub use interval::{fraction, lerp, reciprocal_length};
pub use linear::solve_refined;
pub use minimize::minimize_bracketed;
pub use quadrature::GaussLegendre;
pub use roots::{
    bisect_root, illinois_root, interior_midpoint, quadratic_roots, real_roots_in,
    real_roots_power, sampled_roots,
};
pub use secant::secant_refine;
pub use units::in_caller_units;
pub use vector::{
    angle_between, bounding_diagonal, check_finite, check_point, check_unit_direction,
    largest_coordinate, normal_plane_unit, orthogonalized, orthonormal_to, power_of_two_inverse,
    power_of_two_scale, robust_length, robust_normalize, signed_angle, unit_scaled,
};
