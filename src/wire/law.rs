//! The frames a wire sweep may follow besides the RMF, written as turns against it.
//!
//! Any frame (t, f₂, f₃) of a curve is its RMF (t, r₂, r₃) turned about the tangent by an
//! angle θ(s). For the Frenet frame θ' is the torsion (Bishop, "There is more than one way
//! to frame a curve", 1975: the RMF's normals turn against the principal normal at the
//! rate τ), so on a helix θ is linear in arc length and the Frenet sweep is the helix's
//! screw motion; for a fixed direction d, f₂ = the projection of d onto the normal plane.
//! The sweep turns its frame on each piece linearly in arc length (the twist machinery of
//! `frame`, rational and exact at every joint) by the change of θ over the piece, measured
//! from samples; how far the result is from the law inside a piece is the report's
//! `frame_error`.
//!
//! Where the law is undefined — the principal normal of a line or at an inflection — no
//! turn is taken: the frame keeps its angle rather than flipping with the normal. The
//! principal normal is defined up to sign across an inflection, so the Frenet angle is
//! followed modulo π, the fixed direction's modulo 2π.

use super::SweepFrame;
use crate::bezier::{CurveJet, PiecewiseCurve};
use crate::math::signed_angle;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Samples per spine segment at which a law is followed and measured.
pub(crate) const LAW_SAMPLES: usize = 16;

/// Curvature (in units of the wire's size, which the sweep works in) below which the
/// principal normal is taken as undefined.
const FLAT: f64 = 1e-6;

/// Sine of the angle to the tangent below which a fixed direction gives no frame.
pub(crate) const ALONG_TANGENT: f64 = 1e-6;

/// The angle the law's f₂ makes with a frame's f₂ about the tangent, unwrapped along a
/// piece (modulo the law's period: π for the Frenet normal, 2π for a fixed direction).
pub(crate) struct Unwrapped {
    period: f64,
    first: Option<f64>,
    last: Option<f64>,
    spread: (f64, f64),
}

impl Unwrapped {
    pub fn new(law: &SweepFrame) -> Self {
        let period = match law {
            SweepFrame::Frenet => PI,
            _ => TAU,
        };
        Self {
            period,
            first: None,
            last: None,
            spread: (0.0, 0.0),
        }
    }

    /// Takes the angle from `frame_f2` to the law's `target` about the tangent `t`.
    pub fn push(&mut self, frame_f2: DVec3, target: DVec3, t: DVec3) {
        let raw = signed_angle(frame_f2, target, t);
        let angle = match self.last {
            None => raw,
            Some(last) => last + wrap(raw - last, self.period),
        };
        let first = *self.first.get_or_insert(angle);
        self.last = Some(angle);
        let off = angle - first;
        self.spread = (self.spread.0.min(off), self.spread.1.max(off));
    }

    /// The last angle taken, unwrapped.
    pub fn last(&self) -> Option<f64> {
        self.last
    }

    /// The change from the first angle to the last (0 with fewer than two).
    pub fn change(&self) -> f64 {
        match (self.first, self.last) {
            (Some(a), Some(b)) => b - a,
            _ => 0.0,
        }
    }

    /// The largest distance of the angles from the first.
    pub fn spread(&self) -> f64 {
        self.spread.0.abs().max(self.spread.1)
    }

    /// The largest angle (the first one in (−π, π], the others unwrapped from it).
    pub fn largest(&self) -> f64 {
        let first = self.first.unwrap_or(0.0);
        (first + self.spread.0)
            .abs()
            .max((first + self.spread.1).abs())
    }
}

/// The f₂ the law asks for at a point of the spine with derivatives `jet`: the principal
/// normal (Frenet; `None` where the curvature vanishes), the fixed direction projected
/// onto the normal plane (`None` along the tangent), `None` for the RMF.
pub(crate) fn law_normal(law: &SweepFrame, jet: &CurveJet) -> Option<DVec3> {
    let t = jet.d1.try_normalize()?;
    match law {
        SweepFrame::Rmf => None,
        SweepFrame::Frenet => {
            let speed = jet.d1.length();
            let binormal = jet.d1.cross(jet.d2);
            if binormal.length() <= FLAT * speed * speed * speed {
                return None;
            }
            Some(binormal.normalize().cross(t))
        }
        SweepFrame::Fixed(d) => {
            let d = d.normalize();
            let p = d - d.dot(t) * t;
            (p.length() > ALONG_TANGENT).then(|| p.normalize())
        }
    }
}

/// The jet at which the law is read at the spine's parameter `v`: the curve as given
/// where the piece is a curve (its normal, not that of the PH spline, whose second
/// derivative jumps at its joints), the spine itself for lines and arcs. At a break the
/// segment is the one holding `inside` (a parameter of the interval being followed), so
/// that a law whose normal jumps there is read on the interval's own side. (Derivatives
/// in the segment's local parameter: the law takes directions and curvature, which do not
/// depend on it.)
pub(crate) fn law_jet(
    given: Option<&PiecewiseCurve>,
    spine: &PiecewiseCurve,
    v: f64,
    inside: f64,
) -> CurveJet {
    let curve = given.unwrap_or(spine);
    let (k, _) = curve.locate(inside);
    let (a, b) = (curve.breaks()[k], curve.breaks()[k + 1]);
    curve.segments()[k].eval_jet(((v - a) / (b - a)).clamp(0.0, 1.0))
}

/// The law's angle against a piece's base frame, zero at the piece's start, as a function
/// of the spine's parameter: the raw angle (defined modulo the law's period) unwrapped
/// against a table sampled along the piece, so that any parameter, in any order, gets the
/// branch continuous with its neighbours. Where the law is undefined, the table's value.
pub(crate) struct LawAngle {
    period: f64,
    params: Vec<f64>,
    angles: Vec<f64>,
    start: f64,
}

impl LawAngle {
    pub fn new(law: &SweepFrame, breaks: &[f64], raw: &dyn Fn(f64) -> Option<f64>) -> Self {
        let period = Unwrapped::new(law).period;
        let mut params = Vec::new();
        let mut angles: Vec<f64> = Vec::new();
        for v in crate::mesh::grid_parameters(breaks, LAW_SAMPLES) {
            let Some(a) = raw(v) else { continue };
            let a = match angles.last() {
                Some(&last) => last + wrap(a - last, period),
                None => a,
            };
            params.push(v);
            angles.push(a);
        }
        let start = angles.first().copied().unwrap_or(0.0);
        Self {
            period,
            params,
            angles,
            start,
        }
    }

    /// The angle at v, 0 at the piece's start.
    pub fn at(&self, v: f64, raw: &dyn Fn(f64) -> Option<f64>) -> f64 {
        if self.params.is_empty() {
            return 0.0;
        }
        let i = self
            .params
            .partition_point(|&p| p <= v)
            .clamp(1, self.params.len());
        let reference = if i == self.params.len() {
            self.angles[i - 1]
        } else {
            let (p0, p1) = (self.params[i - 1], self.params[i]);
            let s = ((v - p0) / (p1 - p0)).clamp(0.0, 1.0);
            crate::math::lerp(self.angles[i - 1], self.angles[i], s)
        };
        let angle = match raw(v) {
            Some(a) => reference + wrap(a - reference, self.period),
            None => reference,
        };
        angle - self.start
    }
}

/// x reduced to (−period/2, period/2].
fn wrap(x: f64, period: f64) -> f64 {
    x - period * (x / period).round()
}
