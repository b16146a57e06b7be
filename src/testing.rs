//! Analytic curves with known rotation-minimizing frames, shared by the unit tests.

use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::curve::ParametricCurve;
use crate::frames::frenet::frenet_frame;
use crate::frames::rational::{RationalFrameSegment, RationalFrames};
use crate::frames::Frame;
use crate::Result;
use glam::DVec3;

/// The circular helix (r cos t, r sin t, h t) on [0, 4π].
pub struct Helix {
    pub radius: f64,
    pub pitch: f64,
}

impl Helix {
    pub fn derivatives(&self, t: f64) -> (DVec3, DVec3) {
        let (r, h) = (self.radius, self.pitch);
        (
            DVec3::new(-r * t.sin(), r * t.cos(), h),
            DVec3::new(-r * t.cos(), -r * t.sin(), 0.0),
        )
    }

    /// The exact RMF: the Frenet frame turned by Ω = −τ σ t (Mäurer & Jüttler, eq. (6);
    /// curvature and torsion are constant).
    pub fn exact_rmf(&self, t: f64) -> Frame {
        let (d1, d2) = self.derivatives(t);
        let speed_squared = self.radius * self.radius + self.pitch * self.pitch;
        let torsion = self.pitch / speed_squared;
        frenet_frame(d1, d2)
            .expect("a helix has curvature")
            .rotated(-torsion * speed_squared.sqrt() * t)
    }
}

impl ParametricCurve for Helix {
    fn domain(&self) -> (f64, f64) {
        (0.0, 4.0 * std::f64::consts::PI)
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let p = DVec3::new(self.radius * t.cos(), self.radius * t.sin(), self.pitch * t);
        Ok((p, self.derivatives(t).0))
    }
}

/// A planar PH cubic in the xy-plane (control legs of lengths 1, 2, 4 turning by 30° each:
/// equal angles and L₂² = L₁L₃, the planar case of (17)) with its rational RMF: f₂ = +z
/// (a constant vector is rotation-minimizing along a planar curve), f₃ = t × z.
pub fn planar_ph_cubic() -> (PiecewiseCurve, RationalFrames) {
    let dir = |deg: f64| DVec3::new(deg.to_radians().cos(), deg.to_radians().sin(), 0.0);
    let b0 = DVec3::new(0.2, -0.4, 0.0);
    let b1 = b0 + dir(0.0);
    let b2 = b1 + 2.0 * dir(30.0);
    let b3 = b2 + 4.0 * dir(60.0);
    let curve = RationalBezierCurve::polynomial(&[b0, b1, b2, b3]).expect("valid cubic");
    // Hodograph 3(Δb₁, Δb₂, Δb₃) and speed σ = 3(L₁, L₂ cos θ, L₃), eq. (18).
    let legs = [b1 - b0, b2 - b1, b3 - b2];
    let speed = [3.0, 6.0 * 30f64.to_radians().cos(), 12.0];
    let f2 = speed.iter().map(|&s| DVec3::Z * s).collect();
    let f3 = legs.iter().map(|&l| (3.0 * l).cross(DVec3::Z)).collect();
    let frame = RationalFrameSegment::new(f2, f3, speed.to_vec()).expect("positive speed");
    (
        PiecewiseCurve::new(vec![curve], vec![0.0, 1.0]).expect("one segment"),
        RationalFrames::new(vec![frame], vec![0.0, 1.0]).expect("one segment"),
    )
}
