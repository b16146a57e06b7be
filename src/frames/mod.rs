//! Adapted frames along curves: (t, f₂, f₃) with t the unit tangent and f₃ = t × f₂.
//!
//! * [`frenet`]: the Frenet frame (t, n, b) of any curve from its first two derivatives;
//! * [`double_reflection`]: the double-reflection RMF of Wang, Jüttler, Zheng & Liu (2008),
//!   the reference every rational RMF in this project is measured against;
//! * [`rational`]: frames given exactly as piecewise rational functions (all RMF
//!   constructions of the papers end here);
//! * [`compare`]: errors of an approximate RMF against a reference RMF at nearest points;
//! * [`metrics`]: rotation-minimizing defect, angles between frames, orthonormality, and
//!   the surface measures (parameter-line angle, Gaussian curvature) used to verify sweeps.

pub(crate) mod compare;
pub(crate) mod double_reflection;
pub(crate) mod frenet;
pub(crate) mod metrics;
pub(crate) mod rational;

use crate::bezier::PiecewiseCurve;
use crate::curve::ParametricCurve;
use crate::error::{invalid, Result};
use double_reflection::DoubleReflectionRmf;
use glam::DVec3;
use rational::RationalFrames;
use std::sync::Arc;

/// An orthonormal adapted frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Unit tangent of the curve.
    pub tangent: DVec3,
    /// First normal-plane vector.
    pub f2: DVec3,
    /// `tangent × f2`.
    pub f3: DVec3,
}

impl Frame {
    /// The frame with tangent `t` and first normal vector `f2` (both unit, orthogonal).
    pub fn from_tangent_normal(tangent: DVec3, f2: DVec3) -> Self {
        Self {
            tangent,
            f2,
            f3: tangent.cross(f2),
        }
    }

    /// The frame turned by `angle` about its tangent (f₂ towards f₃ for positive angles).
    pub fn rotated(&self, angle: f64) -> Self {
        let (s, c) = angle.sin_cos();
        Self {
            tangent: self.tangent,
            f2: c * self.f2 + s * self.f3,
            f3: c * self.f3 - s * self.f2,
        }
    }
}

/// How the frames of a [`FrameField`] are represented.
#[derive(Clone, Debug)]
pub enum FrameKind {
    /// Exact piecewise rational functions (PH-cubic RMF approximation, Möbius, RRMF,
    /// rational Frenet frames of PH curves).
    Rational(RationalFrames),
    /// Double-reflection samples; between samples, one reflection step from the sample
    /// below to the exact point and tangent of the curve.
    DoubleReflection(DoubleReflectionRmf),
    /// The Frenet frame of the curve, evaluated pointwise (undefined where κ = 0).
    Frenet,
}

/// A frame along a curve, sharing the curve's parameter. This is what `RmfFrames` holds.
#[derive(Clone, Debug)]
pub struct FrameField {
    curve: Arc<PiecewiseCurve>,
    kind: FrameKind,
}

impl FrameField {
    /// Frames of `kind` along `curve`. Rational frames use the curve's breakpoints or a
    /// refinement of them (a frame may split a segment to keep its weights positive).
    pub fn new(curve: Arc<PiecewiseCurve>, kind: FrameKind) -> Result<Self> {
        if let FrameKind::Rational(r) = &kind {
            let (fb, cb) = (r.breaks(), curve.breaks());
            let same_domain = fb[0] == cb[0] && fb[fb.len() - 1] == cb[cb.len() - 1];
            if !same_domain || cb.iter().any(|b| !fb.contains(b)) {
                return invalid!(
                    "rational frames must use their curve's breakpoints (or a refinement of them)"
                );
            }
        }
        Ok(Self { curve, kind })
    }

    /// The curve the frames are taken along.
    pub fn curve(&self) -> &Arc<PiecewiseCurve> {
        &self.curve
    }

    /// How the frames are made.
    pub fn kind(&self) -> &FrameKind {
        &self.kind
    }

    /// The parameter domain (that of the curve).
    pub fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    /// The frame at `t` (inside the domain).
    pub fn frame(&self, t: f64) -> Result<Frame> {
        match &self.kind {
            FrameKind::Rational(r) => Ok(r.frame(t)),
            FrameKind::DoubleReflection(d) => {
                let (point, tangent) = self.curve.point_unit_tangent(t)?;
                Ok(d.frame_at(t, point, tangent))
            }
            FrameKind::Frenet => {
                let jet = self.curve.eval_jet(t);
                frenet::frenet_frame(jet.d1, jet.d2).ok_or_else(|| {
                    crate::Error::invalid_input(format!(
                        "the Frenet frame is undefined at t = {t} (zero curvature)"
                    ))
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_keeps_the_frame_orthonormal() {
        let f = Frame::from_tangent_normal(DVec3::Z, DVec3::X).rotated(0.3);
        assert!((f.f2 - DVec3::new(0.3f64.cos(), 0.3f64.sin(), 0.0)).length() < 1e-15);
        assert!((f.tangent.cross(f.f2) - f.f3).length() < 1e-15);
    }
}
