//! The Frenet–Serret frame (t, n, b) of a curve from x' and x'' (Mäurer & Jüttler, eq. (3)):
//! t = x'/|x'|, b = x' × x'' / |x' × x''|, n = b × t. As an adapted frame, f₂ = n, f₃ = b.

use super::Frame;
use crate::math::orthogonalized;
use glam::DVec3;

/// Relative size of |x' × x''| (against |x'|·|x''|) below which the curvature counts as
/// zero and the Frenet frame as undefined.
const FLAT_TOLERANCE: f64 = 1e-12;

/// The Frenet frame, or `None` where the curve is singular or has zero curvature.
pub(crate) fn frenet_frame(d1: DVec3, d2: DVec3) -> Option<Frame> {
    // The frame does not depend on the lengths of x' and x'': scaled to a largest component
    // of 1 first, tiny (subnormal) or huge derivatives neither underflow nor overflow in the
    // products below.
    let (d1, d2) = (unit_scaled(d1)?, unit_scaled(d2)?);
    let b = d1.cross(d2);
    let b_len = b.length();
    let scale = d1.length() * d2.length();
    if !b_len.is_finite() || b_len <= FLAT_TOLERANCE * scale {
        return None;
    }
    let t = d1.normalize();
    // Rounding leaves x' × x'' off the normal plane by about ε / sin∠(x', x''): 4e-6 at
    // sin∠ = 1e-10. Projected back, the frame is orthonormal to
    // rounding at every angle the tolerance accepts (its direction stays as well
    // conditioned as the data make it).
    let b = orthogonalized(b / b_len, t).normalize();
    Some(Frame {
        tangent: t,
        f2: b.cross(t),
        f3: b,
    })
}

/// `v` divided by its largest absolute component; `None` for zero or non-finite vectors.
fn unit_scaled(v: DVec3) -> Option<DVec3> {
    let largest = v.abs().max_element();
    (largest.is_finite() && largest > 0.0).then(|| v / largest)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frenet_frame_of_a_helix() {
        // x(t) = (cos t, sin t, t): n = (−cos t, −sin t, 0), b = (sin t, −cos t, 1)/√2.
        let t = 0.7f64;
        let d1 = DVec3::new(-t.sin(), t.cos(), 1.0);
        let d2 = DVec3::new(-t.cos(), -t.sin(), 0.0);
        let f = frenet_frame(d1, d2).unwrap();
        assert!((f.f2 - DVec3::new(-t.cos(), -t.sin(), 0.0)).length() < 1e-15);
        assert!((f.f3 - DVec3::new(t.sin(), -t.cos(), 1.0) / 2f64.sqrt()).length() < 1e-15);
        assert!(frenet_frame(DVec3::X, DVec3::X * 3.0).is_none());
    }

    /// Derivatives from subnormal to 1e308 give the frame of their directions or none: they
    /// are scaled to unit size before the cross products (unscaled, a subnormal x' gives a
    /// zero tangent and NaN normals).
    #[test]
    fn tiny_and_huge_derivatives_give_the_same_frame_or_none() {
        let (d1, d2) = (DVec3::new(0.3, -1.0, 0.2), DVec3::new(1.0, 0.5, -0.7));
        let reference = frenet_frame(d1, d2).unwrap();
        for (s1, s2) in [
            (1e-310, 1e-310),
            (1e-312, 1.0),
            (1e300, 1e-300),
            (1e308, 1e308),
        ] {
            let f = frenet_frame(d1 * s1, d2 * s2).unwrap();
            assert!(
                (f.tangent - reference.tangent).length() < 1e-8,
                "{s1} {s2}: {f:?}"
            );
            assert!((f.f2 - reference.f2).length() < 1e-8, "{s1} {s2}: {f:?}");
        }
        assert!(frenet_frame(DVec3::ZERO, d2).is_none());
        assert!(frenet_frame(DVec3::new(f64::NAN, 0.0, 1.0), d2).is_none());
    }

    /// Nearly parallel derivatives (sin∠ from 1e-4 down to the tolerance): the frame is
    /// still orthonormal to rounding.
    #[test]
    fn nearly_flat_points_have_orthonormal_frames() {
        let d1 = DVec3::new(-0.5174, 0.6561, 0.5494);
        let across = DVec3::new(0.6777, -0.0778, 0.7312);
        for e in [1e-4, 1e-7, 1e-10, 2e-12] {
            let f = frenet_frame(d1, d1 * 0.7 + across * e).unwrap();
            let error = crate::frames::metrics::orthonormality_error(&f);
            assert!(error < 1e-15, "sin∠ ≈ {e}: {error:e}");
        }
    }
}
