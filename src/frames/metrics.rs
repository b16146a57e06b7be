//! Measures that decide whether a frame is rotation-minimizing and whether a sweep has
//! the properties an RMF sweep must have (Mäurer & Jüttler, Section 2 and eq. (43)):
//!
//! * RMF defect `(df₂/dt · f₃) / |x'|`: the frame's angular velocity about the tangent per
//!   unit arc length; zero exactly for an RMF (Bartoň, Jüttler & Wang, eq. (1)).
//! * The angle about the tangent between two frames (error of an approximate RMF).
//! * Orthonormality error of a frame.
//! * `O(u, v) = cos ∠(s_u, s_v)` (43): zero on a profile surface (Proposition 3).
//! * Gaussian curvature `K = (LN − M²)/(EG − F²)`: zero on developable surfaces
//!   (Proposition 2 for line profiles; cone splines).

use super::{Frame, FrameField, FrameKind};
use crate::bezier::SurfaceJet;
use crate::error::Result;
use crate::math::{power_of_two_scale, robust_length, signed_angle, unit_scaled};
use glam::DVec3;

/// The RMF defect at `t`: `(df₂/dt · f₃) / |x'(t)|` (radians per unit length).
///
/// Exact for rational frames (quotient rule on the Bernstein data). For sampled or
/// pointwise frames the derivative is a central difference, which is only as accurate as
/// the step allows (≈1e-7 relative).
pub fn rmf_defect(field: &FrameField, t: f64) -> Result<f64> {
    let speed = robust_length(field.curve().eval_jet(t).d1);
    let rate = match field.kind() {
        FrameKind::Rational(r) => {
            let (_, d) = r.f2_with_derivative(t);
            d.dot(r.frame(t).f3)
        }
        _ => {
            let (lo, hi) = field.domain();
            let h = 1e-6 * (hi - lo);
            let (a, b) = ((t - h).max(lo), (t + h).min(hi));
            let d = (field.frame(b)?.f2 - field.frame(a)?.f2) / (b - a);
            d.dot(field.frame(t)?.f3)
        }
    };
    Ok(rate / speed)
}

/// Signed angle about `a.tangent` that turns `a.f2` into `b.f2` (frames on one tangent).
pub fn angle_about_tangent(a: &Frame, b: &Frame) -> f64 {
    signed_angle(a.f2, b.f2, a.tangent)
}

/// Largest deviation of the frame from orthonormality: `max |fᵢ·fⱼ − δᵢⱼ|`.
pub fn orthonormality_error(f: &Frame) -> f64 {
    let v = [f.tangent, f.f2, f.f3];
    let mut worst = 0.0f64;
    for i in 0..3 {
        for j in i..3 {
            let target = if i == j { 1.0 } else { 0.0 };
            worst = worst.max((v[i].dot(v[j]) - target).abs());
        }
    }
    worst
}

/// `|cos ∠(s_u, s_v)|`, the orthogonality measure O(u, v) of (43).
pub fn parameter_line_cosine(jet: &SurfaceJet) -> f64 {
    partials_cosine(jet.du, jet.dv)
}

/// `|cos ∠(s_u, s_v)|` from the first partials alone.
pub(crate) fn partials_cosine(du: DVec3, dv: DVec3) -> f64 {
    let (du, dv) = (unit_scaled(du), unit_scaled(dv));
    du.dot(dv).abs() / (du.length() * dv.length())
}

/// Gaussian curvature from the first and second fundamental forms.
pub fn gaussian_curvature(jet: &SurfaceJet) -> f64 {
    scaled_gaussian_curvature(jet, 1.0)
}

/// K·length², the Gaussian curvature in units of `length` (a size of the surface): the
/// jet is scaled by a power of two first, so that neither the fundamental forms nor K
/// overflow or underflow where K·length² is a moderate number (surfaces of size 1e-200 or
/// 1e200, whose K is 1e400 or 1e-400).
pub fn scaled_gaussian_curvature(jet: &SurfaceJet, length: f64) -> f64 {
    let c = power_of_two_scale(jet.du.abs().max(jet.dv.abs()));
    let (du, dv) = (jet.du * c, jet.dv * c);
    let normal = du.cross(dv);
    let area2 = normal.length_squared();
    let n = normal / area2.sqrt();
    let (l, m, nn) = (
        (jet.duu * c).dot(n),
        (jet.duv * c).dot(n),
        (jet.dvv * c).dot(n),
    );
    let scaled_length = length * c;
    (l * nn - m * m) / area2 * scaled_length * scaled_length
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::RationalBezierPatch;
    use glam::{DVec3, DVec4};

    #[test]
    fn curvature_of_a_hyperbolic_paraboloid_and_of_a_plane() {
        // s(u, v) = (u, v, uv): K = −1 / (1 + u² + v²)².
        let pts = vec![
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            DVec4::new(0.0, 1.0, 0.0, 1.0),
            DVec4::new(1.0, 0.0, 0.0, 1.0),
            DVec4::new(1.0, 1.0, 1.0, 1.0),
        ];
        let patch = RationalBezierPatch::from_homogeneous(1, 1, pts).unwrap();
        let jet = patch.eval_jet(0.5, 0.25);
        let expected = -1.0 / (1.0f64 + 0.25 + 0.0625).powi(2);
        assert!((gaussian_curvature(&jet) - expected).abs() < 1e-14);
        let cos = 0.25 * 0.5 / ((1.0f64 + 0.0625).sqrt() * (1.0f64 + 0.25).sqrt());
        assert!((parameter_line_cosine(&jet) - cos).abs() < 1e-15);
    }

    #[test]
    fn frame_measures() {
        let a = Frame::from_tangent_normal(DVec3::Z, DVec3::X);
        let b = a.rotated(-0.7);
        assert!((angle_about_tangent(&a, &b) + 0.7).abs() < 1e-15);
        assert!(orthonormality_error(&b) < 1e-15);
        let bad = Frame {
            tangent: DVec3::Z,
            f2: DVec3::X * 1.1,
            f3: DVec3::Y,
        };
        assert!((orthonormality_error(&bad) - 0.21).abs() < 1e-12);
    }
}
