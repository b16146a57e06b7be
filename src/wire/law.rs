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
//! For a guide curve, f₂ points from the spine's point to where the guide crosses the normal
//! plane there (the crossing nearest the spine): the profile turns to follow the second
//! rail, as OpenCascade's auxiliary mode and CATIA's guide sweeps do.
//!
//! Where the law is undefined — the principal normal of a line or at an inflection — no
//! turn is taken: the frame keeps its angle rather than flipping with the normal. The
//! principal normal is defined up to sign across an inflection, so the Frenet angle is
//! followed modulo π, the fixed direction's modulo 2π.

use super::{Edge, SweepFrame};
use crate::bezier::bernstein::to_power;
use crate::bezier::{CurveJet, PiecewiseCurve, RationalBezierCurve};
use crate::error::Result;
use crate::math::{real_roots_in, signed_angle};
use crate::model::{arc_through, polyline};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Samples per spine segment at which a law is followed and measured.
pub(crate) const LAW_SAMPLES: usize = 16;

/// Curvature (in units of the wire's size, which the sweep works in) below which the
/// principal normal is taken as undefined.
const FLAT: f64 = 1e-6;

/// Sine of the angle to the tangent below which a fixed direction gives no frame.
pub(crate) const ALONG_TANGENT: f64 = 1e-6;

/// Distance (in units of the wire's size) from the spine within which a guide's point
/// gives no direction.
const GUIDE_CLEARANCE: f64 = 1e-9;

/// How far past a guide segment's ends (in its parameter, and relative to its coefficients)
/// a crossing is taken as at the end.
const GUIDE_END: f64 = 1e-9;

/// A frame law in the sweep's normalized coordinates.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum FrameLaw {
    Rmf,
    Frenet,
    Fixed(DVec3),
    Guide(Guide),
}

impl FrameLaw {
    /// The name of a law other than the RMF, as the options spell it.
    pub(super) fn name(&self) -> Option<&'static str> {
        match self {
            FrameLaw::Rmf => None,
            FrameLaw::Frenet => Some("frenet"),
            FrameLaw::Fixed(_) => Some("fixed"),
            FrameLaw::Guide(_) => Some("guide"),
        }
    }

    /// The law of `frame`, a guide's points mapped by `unit` (a similarity) to the sweep's
    /// coordinates.
    pub(super) fn new(
        frame: &SweepFrame,
        unit: &dyn Fn(&PiecewiseCurve) -> PiecewiseCurve,
    ) -> Result<Self> {
        Ok(match frame {
            SweepFrame::Rmf => FrameLaw::Rmf,
            SweepFrame::Frenet => FrameLaw::Frenet,
            SweepFrame::Fixed(d) => FrameLaw::Fixed(*d),
            SweepFrame::Guide(edges) => FrameLaw::Guide(Guide::new(edges, unit)?),
        })
    }
}

/// A guide curve: its rational Bézier segments, in any order and orientation.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Guide {
    segments: Vec<RationalBezierCurve>,
}

impl Guide {
    fn new(edges: &[Edge], unit: &dyn Fn(&PiecewiseCurve) -> PiecewiseCurve) -> Result<Self> {
        let mut segments = Vec::new();
        for edge in edges {
            let curve = match edge {
                Edge::Line { from, to } => polyline(&[*from, *to])?,
                Edge::Arc {
                    start,
                    through,
                    end,
                } => arc_through(*start, *through, *end)?,
                Edge::Curve(c) => c.clone(),
            };
            segments.extend(unit(&curve).segments().iter().cloned());
        }
        Ok(Self { segments })
    }

    /// The guide's point in the plane through `point` normal to the unit `t` that is
    /// nearest `point`: the real roots of t·(g(w) − point), a polynomial in the Bernstein
    /// basis for each (homogeneous) segment, whose coefficients of one sign rule it out.
    pub(super) fn point_in_plane(&self, point: DVec3, t: DVec3) -> Option<DVec3> {
        let level = t.dot(point);
        let mut nearest: Option<(f64, DVec3)> = None;
        for segment in &self.segments {
            let c: Vec<f64> = segment
                .homogeneous()
                .iter()
                .map(|h| t.dot(h.truncate()) - level * h.w)
                .collect();
            // A guide that ends in the wire's end plane (one as long as the wire) crosses
            // it at its end, which rounding may move out of [0, 1]: taken within a margin.
            let margin = GUIDE_END * c.iter().fold(level.abs(), |m, x| m.max(x.abs()));
            if c.iter().all(|&x| x > margin) || c.iter().all(|&x| x < -margin) {
                continue;
            }
            for w in real_roots_in(&to_power(&c), -GUIDE_END, 1.0 + GUIDE_END) {
                let q = segment.eval(w.clamp(0.0, 1.0));
                let d = q.distance(point);
                if nearest.is_none_or(|(best, _)| d < best) {
                    nearest = Some((d, q));
                }
            }
        }
        nearest.map(|(_, q)| q)
    }
}

/// The angle the law's f₂ makes with a frame's f₂ about the tangent, unwrapped along a
/// piece (modulo the law's period: π for the Frenet normal, 2π for a fixed direction).
pub(crate) struct Unwrapped {
    period: f64,
    first: Option<f64>,
    last: Option<f64>,
    spread: (f64, f64),
}

impl Unwrapped {
    pub(super) fn new(law: &FrameLaw) -> Self {
        let period = match law {
            FrameLaw::Frenet => PI,
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
    pub(super) fn push(&mut self, frame_f2: DVec3, target: DVec3, t: DVec3) {
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
    pub(super) fn last(&self) -> Option<f64> {
        self.last
    }

    /// The change from the first angle to the last (0 with fewer than two).
    pub(super) fn change(&self) -> f64 {
        match (self.first, self.last) {
            (Some(a), Some(b)) => b - a,
            _ => 0.0,
        }
    }

    /// The largest distance of the angles from the first.
    pub(super) fn spread(&self) -> f64 {
        self.spread.0.abs().max(self.spread.1)
    }

    /// The largest angle (the first one in (−π, π], the others unwrapped from it).
    pub(super) fn largest(&self) -> f64 {
        let first = self.first.unwrap_or(0.0);
        (first + self.spread.0)
            .abs()
            .max((first + self.spread.1).abs())
    }
}

/// The f₂ the law asks for at a point of the spine with derivatives `jet`: the principal
/// normal (Frenet; `None` where the curvature vanishes), the fixed direction projected
/// onto the normal plane (`None` along the tangent), towards the guide in the normal plane
/// (`None` where the guide does not cross it, or touches the spine), `None` for the RMF.
pub(crate) fn law_normal(law: &FrameLaw, jet: &CurveJet) -> Option<DVec3> {
    let t = jet.d1.try_normalize()?;
    match law {
        FrameLaw::Rmf => None,
        FrameLaw::Frenet => {
            let speed = jet.d1.length();
            let binormal = jet.d1.cross(jet.d2);
            if binormal.length() <= FLAT * speed * speed * speed {
                return None;
            }
            Some(binormal.normalize().cross(t))
        }
        FrameLaw::Fixed(d) => {
            let d = d.normalize();
            let p = d - d.dot(t) * t;
            (p.length() > ALONG_TANGENT).then(|| p.normalize())
        }
        FrameLaw::Guide(guide) => {
            let to = guide.point_in_plane(jet.point, t)? - jet.point;
            let across = to - to.dot(t) * t;
            (across.length() > GUIDE_CLEARANCE).then(|| across.normalize())
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
    pub(super) fn new(law: &FrameLaw, breaks: &[f64], raw: &dyn Fn(f64) -> Option<f64>) -> Self {
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
    pub(super) fn at(&self, v: f64, raw: &dyn Fn(f64) -> Option<f64>) -> f64 {
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
