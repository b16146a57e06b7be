//! Circular helices among a wire's curve edges, swept by their screw motion.
//!
//! A circular helix H(θ) = o + r (cos θ e₁ + sin θ e₂) + c θ a is carried into itself by
//! the screw motion about its axis a, and so is its Frenet frame: a profile swept along it
//! under the Frenet frame (a thread) — or any round profile under any frame (a coil) — is
//! the screw motion's image of the profile. Its rotation is rational: on a span of angle α,
//! cos θ and sin θ are a rational quadratic circle (Piegl & Tiller, *The NURBS Book*,
//! §7.3: weights 1, cos(α/2), 1), whose angle runs as θ(t) = α/2 + 2 arctan(tan(α/4)(2t − 1)).
//! Only the advance c θ(t) along the axis is not rational; it is taken as c q(t), q the
//! quintic with θ's ends and end slopes (so that the spans join C¹) closest to θ in least
//! squares. Every point of the sweep is then off the exact screw sweep along the axis
//! alone, by |c| max|θ − q|, the same for every profile point: measured on the span, and
//! kept within a share of the tolerance by shorter spans. The frames are the helix's Frenet
//! frames, exact: f₂ = N = −(cos θ e₁ + sin θ e₂), f₃ = B, quadratic over the circle's
//! weight.
//!
//! A curve edge is taken for a helix when it lies within a share of the tolerance of the
//! helix fitted to it: the axis from the unit tangents (a helix's make one angle with its
//! axis: their tips lie on a circle in a plane normal to it), centre and radius by a
//! least-squares circle (Kåsa's) in the plane normal to the axis, the advance by least
//! squares in the unwrapped angle; the distance is measured at samples of every segment.
//! Where the frame matters (Frenet), the edge's own principal normal must also be within
//! the law's accuracy of the helix's at every sample.

use crate::bezier::bernstein::{elevate, product};
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::Result;
use crate::frames::rational::{RationalFrameSegment, RationalFrames};
use crate::math::{binomial, solve_refined};
use glam::{DMat3, DVec2, DVec3, DVec4};
use std::f64::consts::FRAC_PI_2;

/// Samples per segment of the edge at which the helix is fitted.
const FIT_SAMPLES: usize = 16;

/// Samples per segment of the edge at which its distance from the helix is measured.
const CHECK_SAMPLES: usize = 64;

/// Degree of the advance q(t) on one span: the sweep's degree along the helix is this plus
/// two (the circle's) plus two (the frames').
const ADVANCE_DEGREE: usize = 5;

/// Largest angle of one span: a quarter turn.
const LARGEST_SPAN: f64 = FRAC_PI_2;

/// Most spans of one helix edge (2¹⁶: far finer than any tolerance needs).
const MAX_SPANS: usize = 1 << 16;

/// Samples of a span at which the advance's error is measured.
const ADVANCE_SAMPLES: usize = 256;

/// A circular helix H(θ) = origin + r (cos θ e₁ + sin θ e₂) + c θ a, θ ∈ [start, end],
/// (e₁, e₂, a) right-handed and θ increasing along the edge; c is signed (negative: a
/// left-handed helix).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Helix {
    origin: DVec3,
    axis: DVec3,
    e1: DVec3,
    e2: DVec3,
    radius: f64,
    advance: f64,
    start: f64,
    end: f64,
    /// Largest distance of the edge's samples from the helix.
    deviation: f64,
    /// Largest angle between the edge's principal normals and the helix's, where measured.
    normal_angle: f64,
}

/// A piece swept by a helix's screw motion: its frames are the helix's Frenet frames
/// (turned by one angle), which the spine's tangent follows within the advance's slope
/// error (they are not adapted to the spine exactly: no rational spine has them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Screw {
    /// Largest angle between the edge's principal normals and the helix's.
    pub normal_angle: f64,
    /// κ = r/(r² + c²), the same all along.
    pub curvature: f64,
    /// The principal normal at the start.
    pub normal: DVec3,
}

/// The spine of a helix edge and its Frenet frames, with its largest distance from the edge.
pub(crate) struct HelixSpine {
    pub curve: PiecewiseCurve,
    pub frames: RationalFrames,
    pub distance: f64,
}

impl Helix {
    /// The helix within `within` of `curve`, whose principal normal is within `normal`
    /// radians of the curve's where given; `None` where the curve is not one.
    pub(crate) fn fit(curve: &PiecewiseCurve, within: f64, normal: Option<f64>) -> Option<Self> {
        let fit_points = samples(curve, FIT_SAMPLES);
        let tangents: Option<Vec<DVec3>> = fit_points
            .iter()
            .map(|(_, d1, _)| d1.try_normalize())
            .collect();
        let axis = cone_axis(&tangents?)?;
        let e1 = axis.any_orthonormal_vector();
        let e2 = axis.cross(e1);
        let flat: Vec<DVec2> = fit_points
            .iter()
            .map(|(p, _, _)| DVec2::new(p.dot(e1), p.dot(e2)))
            .collect();
        let (centre, radius) = circle(&flat)?;
        let mut helix = Helix {
            origin: centre.x * e1 + centre.y * e2,
            axis,
            e1,
            e2,
            radius,
            advance: 0.0,
            start: 0.0,
            end: 0.0,
            deviation: 0.0,
            normal_angle: 0.0,
        };
        let mut angles = helix.unwrapped(fit_points.iter().map(|s| s.0))?;
        if angles[angles.len() - 1] < angles[0] {
            // Turning clockwise about a: about −a it turns counter-clockwise.
            helix.axis = -axis;
            helix.e2 = -e2;
            angles.iter_mut().for_each(|a| *a = -*a);
        }
        let heights: Vec<f64> = fit_points.iter().map(|s| s.0.dot(helix.axis)).collect();
        let (z0, advance) = line_fit(&angles, &heights)?;
        helix.origin += z0 * helix.axis;
        helix.advance = advance;
        helix.start = angles[0];
        helix.end = angles[angles.len() - 1];
        (helix.deviation, helix.normal_angle) = helix.distance_from(curve, normal)?;
        (helix.deviation <= within && helix.end > helix.start).then_some(helix)
    }

    /// The angles of points along the helix, unwrapped from the first; `None` unless every
    /// step turns forward by less than a quarter turn, or where a point is on the axis.
    fn unwrapped(&self, points: impl Iterator<Item = DVec3>) -> Option<Vec<f64>> {
        let mut angles: Vec<f64> = Vec::new();
        for p in points {
            let q = p - self.origin;
            let (x, y) = (q.dot(self.e1), q.dot(self.e2));
            if x.hypot(y) == 0.0 {
                return None;
            }
            let raw = y.atan2(x);
            let angle = match angles.last() {
                None => raw,
                Some(&last) => last + wrapped(raw - last),
            };
            angles.push(angle);
        }
        let steps = angles.windows(2).map(|w| w[1] - w[0]);
        let forward = steps.clone().all(|s| s > 0.0 && s < LARGEST_SPAN);
        let backward = steps.clone().all(|s| s < 0.0 && s > -LARGEST_SPAN);
        (forward || backward).then_some(angles)
    }

    /// The largest distance of the curve's samples from the helix (from the helix's point
    /// at the sample's angle: a bound on the distance) and, where `normal` is given, the
    /// largest angle between their principal normals; `None` where the angle does not
    /// advance or the normals differ by more than `normal`.
    fn distance_from(&self, curve: &PiecewiseCurve, normal: Option<f64>) -> Option<(f64, f64)> {
        let points = samples(curve, CHECK_SAMPLES);
        let angles = self.unwrapped(points.iter().map(|s| s.0))?;
        let (mut distance, mut angle) = (0.0f64, 0.0f64);
        for ((p, d1, d2), &theta) in points.iter().zip(&angles) {
            distance = distance.max(p.distance(self.point(theta)));
            if let Some(limit) = normal {
                let own = d1.cross(*d2).cross(*d1).try_normalize()?;
                angle = angle.max(own.angle_between(self.normal(theta)));
                if angle > limit {
                    return None;
                }
            }
        }
        Some((distance, angle))
    }

    /// What the sweep needs to know of the screw motion: the angle of the helix's Frenet
    /// frames to the edge's (0 where not measured), its curvature and its principal normal
    /// at the start.
    pub(crate) fn screw(&self) -> Screw {
        Screw {
            normal_angle: self.normal_angle,
            curvature: self.radius / (self.radius * self.radius + self.advance * self.advance),
            normal: self.normal(self.start),
        }
    }

    fn point(&self, theta: f64) -> DVec3 {
        self.origin
            + self.radius * (theta.cos() * self.e1 + theta.sin() * self.e2)
            + self.advance * theta * self.axis
    }

    /// The principal normal at θ: towards the axis.
    fn normal(&self, theta: f64) -> DVec3 {
        -(theta.cos() * self.e1 + theta.sin() * self.e2)
    }

    /// The spine on `domain` (the edge's parameter interval) and the helix's Frenet frames,
    /// with the advance within `budget` along the axis; `None` where that would take more
    /// than [`MAX_SPANS`] spans.
    pub(crate) fn spine(&self, domain: (f64, f64), budget: f64) -> Result<Option<HelixSpine>> {
        let total = self.end - self.start;
        let mut spans = (total / LARGEST_SPAN).ceil().max(1.0) as usize;
        let (q, error) = loop {
            let (q, error) = advance(total / spans as f64);
            if self.advance.abs() * error <= budget {
                break (q, error);
            }
            spans *= 2;
            if spans > MAX_SPANS {
                return Ok(None);
            }
        };
        let alpha = total / spans as f64;
        let mut segments = Vec::with_capacity(spans);
        let mut frames = Vec::with_capacity(spans);
        for j in 0..spans {
            let from = self.start + j as f64 * alpha;
            let (segment, frame) = self.span(from, alpha, &q)?;
            segments.push(segment);
            frames.push(frame);
        }
        let (lo, hi) = domain;
        let breaks: Vec<f64> = (0..=spans)
            .map(|j| match j {
                0 => lo,
                j if j == spans => hi,
                j => lo + (hi - lo) * j as f64 / spans as f64,
            })
            .collect();
        Ok(Some(HelixSpine {
            curve: PiecewiseCurve::new(segments, breaks.clone())?,
            frames: RationalFrames::new(frames, breaks)?,
            distance: self.deviation + self.advance.abs() * error,
        }))
    }

    /// One span from angle `from` on, of angle `alpha`, with the advance `q` (Bernstein
    /// coefficients on [0, 1], from 0 to α): its curve and its Frenet frames.
    fn span(
        &self,
        from: f64,
        alpha: f64,
        q: &[f64],
    ) -> Result<(RationalBezierCurve, RationalFrameSegment)> {
        let half = 0.5 * alpha;
        // (cos θ, sin θ, 1) of the rational quadratic circle, homogeneous.
        let circle = [
            (from.cos(), from.sin(), 1.0),
            ((from + half).cos(), (from + half).sin(), half.cos()),
            ((from + alpha).cos(), (from + alpha).sin(), 1.0),
        ];
        let base = self.origin + self.advance * from * self.axis;
        let radial = |x: f64, y: f64| x * self.e1 + y * self.e2;
        let rotation: Vec<DVec4> = circle
            .iter()
            .map(|&(x, y, w)| (w * base + self.radius * radial(x, y)).extend(w))
            .collect();
        let weights: Vec<f64> = circle.iter().map(|c| c.2).collect();
        let axial = product(q, &weights, |q: f64, w: f64| {
            (self.advance * q * w * self.axis).extend(0.0)
        });
        let homogeneous: Vec<DVec4> = elevate(&rotation, ADVANCE_DEGREE)
            .iter()
            .zip(&axial)
            .map(|(&r, &a)| r + a)
            .collect();
        // T = (r θ' (−sin θ, cos θ) + c θ' a)/(s θ'), s = √(r² + c²); B = T × N.
        let s = self.radius.hypot(self.advance);
        let (along, up) = (self.radius / s, self.advance / s);
        let f2 = circle.iter().map(|&(x, y, _)| -radial(x, y)).collect();
        let f3 = circle
            .iter()
            .map(|&(x, y, w)| -up * radial(-y, x) + along * w * self.axis)
            .collect();
        Ok((
            RationalBezierCurve::from_homogeneous(homogeneous)?,
            RationalFrameSegment::new(f2, f3, weights)?,
        ))
    }
}

/// Points with first and second derivatives at `per` + 1 parameters of every segment.
fn samples(curve: &PiecewiseCurve, per: usize) -> Vec<(DVec3, DVec3, DVec3)> {
    let mut out = Vec::with_capacity(curve.segments().len() * per + 1);
    for (k, segment) in curve.segments().iter().enumerate() {
        let first = if k == 0 { 0 } else { 1 };
        for i in first..=per {
            let jet = segment.eval_jet(i as f64 / per as f64);
            out.push((jet.point, jet.d1, jet.d2));
        }
    }
    out
}

/// The axis of the cone of unit tangents: the normal of the plane their tips lie in, the
/// null direction of their scatter (the largest cross product of its rows); `None` where
/// the tips do not spread in a plane (a line's).
fn cone_axis(tangents: &[DVec3]) -> Option<DVec3> {
    let mean = tangents.iter().sum::<DVec3>() / tangents.len() as f64;
    let mut scatter = DMat3::ZERO;
    for t in tangents {
        let d = *t - mean;
        scatter += DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    let rows = [scatter.row(0), scatter.row(1), scatter.row(2)];
    let candidates = [
        rows[0].cross(rows[1]),
        rows[1].cross(rows[2]),
        rows[2].cross(rows[0]),
    ];
    let best = candidates
        .into_iter()
        .max_by(|a, b| a.length_squared().total_cmp(&b.length_squared()))?;
    let trace = scatter.x_axis.x + scatter.y_axis.y + scatter.z_axis.z;
    (best.length() > 1e-12 * trace * trace).then(|| best.normalize())
}

/// The least-squares circle through planar points (Kåsa: x² + y² + D x + E y + F = 0,
/// linear in D, E, F), about their mean; its centre and radius.
fn circle(points: &[DVec2]) -> Option<(DVec2, f64)> {
    let mean = points.iter().sum::<DVec2>() / points.len() as f64;
    let (mut normal, mut rhs) = (DMat3::ZERO, DVec3::ZERO);
    for p in points {
        let d = *p - mean;
        let row = DVec3::new(d.x, d.y, 1.0);
        normal += DMat3::from_cols(row * row.x, row * row.y, row * row.z);
        rhs -= row * d.length_squared();
    }
    let x = solve_refined(normal, rhs)?;
    let centre = DVec2::new(-0.5 * x.x, -0.5 * x.y);
    let radius = (centre.length_squared() - x.z).sqrt();
    (radius.is_finite() && radius > 0.0).then_some((mean + centre, radius))
}

/// z = z₀ + c θ by least squares: (z₀, c).
fn line_fit(angles: &[f64], heights: &[f64]) -> Option<(f64, f64)> {
    let n = angles.len() as f64;
    let mean_a = angles.iter().sum::<f64>() / n;
    let mean_z = heights.iter().sum::<f64>() / n;
    let (mut saa, mut saz) = (0.0, 0.0);
    for (a, z) in angles.iter().zip(heights) {
        saa += (a - mean_a) * (a - mean_a);
        saz += (a - mean_a) * (z - mean_z);
    }
    let c = saz / saa;
    c.is_finite().then(|| (mean_z - c * mean_a, c))
}

/// x reduced to (−π, π].
fn wrapped(x: f64) -> f64 {
    x - std::f64::consts::TAU * (x / std::f64::consts::TAU).round()
}

/// The advance on a span of angle α: the Bernstein coefficients of q (degree
/// [`ADVANCE_DEGREE`]) with θ's ends and end slopes, odd about the span's middle, the rest
/// by least squares; and max |θ − q| (radians) at [`ADVANCE_SAMPLES`] points.
fn advance(alpha: f64) -> (Vec<f64>, f64) {
    let k = (0.25 * alpha).tan();
    let theta = |t: f64| 0.5 * alpha + 2.0 * (k * (2.0 * t - 1.0)).atan();
    let m = ADVANCE_DEGREE;
    let slope = 4.0 * k / (1.0 + k * k);
    // Fixed: b₀ = 0, b₁ = θ'(0)/m and their mirrors b_{m−i} = α − b_i; free: b₂ (= α − b₃).
    let mut b = vec![0.0; m + 1];
    b[1] = slope / m as f64;
    b[m] = alpha;
    b[m - 1] = alpha - b[1];
    let basis = |t: f64, i: usize| {
        binomial(m, i) * t.powi(i as i32) * (1.0 - t).powi((m - i) as i32)
    };
    let fixed = |t: f64, b: &[f64]| -> f64 {
        b.iter().enumerate().map(|(i, &c)| c * basis(t, i)).sum()
    };
    // q(t) = fixed(t) + b₂ (B₂(t) − B₃(t)) + α B₃(t): least squares in b₂.
    let (mut gg, mut gr) = (0.0, 0.0);
    for i in 0..=ADVANCE_SAMPLES {
        let t = i as f64 / ADVANCE_SAMPLES as f64;
        let g = basis(t, 2) - basis(t, 3);
        let r = fixed(t, &b) + alpha * basis(t, 3) - theta(t);
        gg += g * g;
        gr += g * r;
    }
    b[2] = -gr / gg;
    b[3] = alpha - b[2];
    let error = (0..=ADVANCE_SAMPLES)
        .map(|i| i as f64 / ADVANCE_SAMPLES as f64)
        .map(|t| (fixed(t, &b) - theta(t)).abs())
        .fold(0.0, f64::max);
    (b, error)
}
