//! Circular helices among a wire's curve edges, swept by their screw motion.
//!
//! A circular helix H(θ) = o + r (cos θ e₁ + sin θ e₂) + c θ a is carried into itself by
//! the screw motion about its axis a, and so is its Frenet frame: a profile swept along it
//! under the Frenet frame (a thread) — or any round profile under any frame (a coil) — is
//! the screw motion's image of the profile. Everything along the helix is then linear in
//! (cos θ, sin θ) and θ: the spine, the principal normal N = −(cos θ e₁ + sin θ e₂), the
//! binormal B = (c (sin θ e₁ − cos θ e₂) + r a)/√(r² + c²) and the unit tangent. One
//! polynomial spline of degree 7 on equal spans of θ (at most an eighth of a turn) close to
//! (cos θ, sin θ) — through its ends, the rest by least squares — makes them all, θ itself
//! exact: faces of degree 7 along the helix, C⁶ with simple knots, the parameter
//! proportional to arc length.
//!
//! Not the exact rational rotation: a rational quadratic circle's spans join C¹ only (no
//! piecewise quadratic parametrization of a circle is C²), and a kernel's fixed Gauss rule
//! along an edge, and its surface intersections, read such faces badly (OpenCascade's
//! volume of a 5-turn pipe 0.8 % off, a thread's boolean losing material). Here every
//! profile point is off its exact screw image by at most its distance from the axis times
//! the spline's distance from the unit circle (measured at twice the fitting points), kept
//! within the tolerance's remaining share by more spans, and the frames are within that
//! angle of orthonormal.
//!
//! A curve edge is taken for a helix when it lies within a share of the tolerance of the
//! helix fitted to it: the axis from the unit tangents (a helix's make one angle with its
//! axis: their tips lie on a circle in a plane normal to it), centre and radius by a
//! least-squares circle (Kåsa's) in the plane normal to the axis, the advance by least
//! squares in the unwrapped angle; the distance is measured at samples of every segment.
//! Where a frame law matters (the Frenet frame, a direction along the axis: the Frenet frame
//! turned by a constant), the angle between what the law follows along the edge and the
//! helix's frames so turned, at the profile's reach, shares the tolerance too.

use crate::bezier::{fit_splines, spline_value, PiecewiseCurve};
use crate::error::Result;
use crate::frames::rational::{RationalFrameSegment, RationalFrames};
use crate::math::solve_refined;
use glam::{DMat3, DVec2, DVec3};

/// Samples per segment of the edge at which the helix is fitted.
const FIT_SAMPLES: usize = 16;

/// Samples per segment of the edge at which its distance from the helix is measured.
const CHECK_SAMPLES: usize = 64;

/// Degree of the spline of the circle, and so of the spine, the frames and the faces along
/// the helix.
const DEGREE: usize = 7;

/// Largest angle of one span: an eighth of a turn (the circle within 1.5e-8 of its radius).
const LARGEST_SPAN: f64 = std::f64::consts::FRAC_PI_4;

/// Largest turn between consecutive samples of an edge taken for a helix.
const LARGEST_STEP: f64 = std::f64::consts::FRAC_PI_2;

/// Points of a span at which the circle's spline is fitted.
const FIT_PER_SPAN: usize = 12;

/// Most spans of one helix edge (2¹⁶: far finer than any tolerance needs).
const MAX_SPANS: usize = 1 << 16;

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
    /// Largest angle between what the frames follow along the edge and the helix's frames
    /// turned by `turn`, where measured.
    normal_angle: f64,
    /// The constant turn of the frames from the helix's Frenet frames about the tangent.
    turn: f64,
}

/// A piece swept by a helix's screw motion: its frames are the helix's Frenet frames within
/// the spline's accuracy (close to orthonormal and to adapted, not exactly).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Screw {
    /// Largest angle between what the frame law follows along the edge and the frames' f₂.
    pub normal_angle: f64,
    /// κ = r/(r² + c²), the same all along.
    pub curvature: f64,
    /// The principal normal at the start.
    pub normal: DVec3,
}

/// What a sweep's frames follow along a helix, each the screw motion's image of its start:
/// the principal normal (Frenet), or a direction's projection onto the normal plane (a
/// fixed direction along the helix's axis: the Frenet frame turned by a constant).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Follow {
    Normal,
    Direction(DVec3),
}

/// The spine of a helix edge and its Frenet frames, with its largest distance from the edge.
pub(crate) struct HelixSpine {
    pub curve: PiecewiseCurve,
    pub frames: RationalFrames,
    pub distance: f64,
    /// The largest angle of the frames from the helix's Frenet frames (radians).
    pub frame_error: f64,
}

impl Helix {
    /// The helix within `within` of `curve`, whose Frenet frames turned by a constant
    /// follow what `follow` names within its angle where given; `None` where the curve is
    /// not one.
    pub(crate) fn fit(
        curve: &PiecewiseCurve,
        within: f64,
        follow: Option<(Follow, f64)>,
    ) -> Option<Self> {
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
            turn: 0.0,
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
        (helix.deviation, helix.normal_angle, helix.turn) = helix.distance_from(curve, follow)?;
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
        let forward = steps.clone().all(|s| s > 0.0 && s < LARGEST_STEP);
        let backward = steps.clone().all(|s| s < 0.0 && s > -LARGEST_STEP);
        (forward || backward).then_some(angles)
    }

    /// The largest distance of the curve's samples from the helix (from the helix's point
    /// at the sample's angle: a bound on the distance) and, where `follow` is given, the
    /// largest angle between what it follows along the curve and the helix's frames turned
    /// by the constant that makes them agree at the start, with that turn; `None` where the
    /// angle does not advance or the frames differ by more than `follow`'s angle.
    fn distance_from(
        &self,
        curve: &PiecewiseCurve,
        follow: Option<(Follow, f64)>,
    ) -> Option<(f64, f64, f64)> {
        let points = samples(curve, CHECK_SAMPLES);
        let angles = self.unwrapped(points.iter().map(|s| s.0))?;
        let (mut distance, mut angle, mut turn) = (0.0f64, 0.0f64, None);
        for ((p, d1, d2), &theta) in points.iter().zip(&angles) {
            distance = distance.max(p.distance(self.point(theta)));
            let Some((what, limit)) = follow else {
                continue;
            };
            let own = match what {
                Follow::Normal => d1.cross(*d2).cross(*d1),
                Follow::Direction(d) => d - d.dot(*d1) / d1.length_squared() * *d1,
            }
            .try_normalize()?;
            let (normal, binormal) = (self.normal(theta), self.binormal(theta));
            let phi = match (what, turn) {
                (Follow::Normal, _) => 0.0,
                (_, Some(phi)) => phi,
                (_, None) => own.dot(binormal).atan2(own.dot(normal)),
            };
            turn = Some(phi);
            angle = angle.max(own.angle_between(phi.cos() * normal + phi.sin() * binormal));
            if angle > limit {
                return None;
            }
        }
        Some((distance, angle, turn.unwrap_or(0.0)))
    }

    /// How far a profile point at distance `reach` from the edge is from the screw motion's
    /// image of it: the edge's distance from the helix, and the angle between the law's
    /// frames and the helix's (where measured) at that reach.
    pub(crate) fn off_at(&self, reach: f64) -> f64 {
        self.deviation + reach * self.normal_angle
    }

    /// What the sweep needs to know of the screw motion: the angle of the helix's frames to
    /// the law's along the edge (0 where not measured), its curvature and its principal
    /// normal at the start.
    pub(crate) fn screw(&self) -> Screw {
        Screw {
            normal_angle: self.normal_angle,
            curvature: self.radius / (self.radius * self.radius + self.advance * self.advance),
            normal: self.normal(self.start),
        }
    }

    fn point(&self, theta: f64) -> DVec3 {
        self.point_at(unit(theta), theta)
    }

    /// The principal normal at θ: towards the axis.
    fn normal(&self, theta: f64) -> DVec3 {
        -self.radial(unit(theta))
    }

    fn binormal(&self, theta: f64) -> DVec3 {
        self.binormal_at(unit(theta))
    }

    // The helix and its Frenet frame, linear in c = (cos θ, sin θ) (and θ): the same
    // combinations make the spline's coefficients from those of the circle's spline.

    /// c.x e₁ + c.y e₂.
    fn radial(&self, c: DVec2) -> DVec3 {
        c.x * self.e1 + c.y * self.e2
    }

    /// o + r (c.x e₁ + c.y e₂) + c θ a.
    fn point_at(&self, c: DVec2, theta: f64) -> DVec3 {
        self.origin + self.radius * self.radial(c) + self.advance * theta * self.axis
    }

    /// B = (c (sin θ e₁ − cos θ e₂) + r a)/√(r² + c²).
    fn binormal_at(&self, c: DVec2) -> DVec3 {
        let s = self.radius.hypot(self.advance);
        (self.advance * (c.y * self.e1 - c.x * self.e2) + self.radius * self.axis) / s
    }

    /// T = (r (−sin θ e₁ + cos θ e₂) + c a)/√(r² + c²).
    fn tangent_at(&self, c: DVec2) -> DVec3 {
        let s = self.radius.hypot(self.advance);
        (self.radius * (c.x * self.e2 - c.y * self.e1) + self.advance * self.axis) / s
    }

    /// The spine on `domain` (the edge's parameter interval) and the helix's Frenet frames
    /// turned by `turn`, all from one uniform spline of degree [`DEGREE`] close to
    /// (cos θ, sin θ) — spine, normal, binormal and tangent each the same linear combination
    /// of its coefficients as of (cos θ, sin θ), θ itself exact (a line is any spline) —
    /// with `reach` times the circle's error within `budget`; `None` where that would take
    /// more than [`MAX_SPANS`] spans.
    pub(crate) fn spine(
        &self,
        domain: (f64, f64),
        budget: f64,
        reach: f64,
    ) -> Result<Option<HelixSpine>> {
        let total = self.end - self.start;
        // (An edge of whole turns is not a span more for its rounding.)
        let mut spans = (total / LARGEST_SPAN * (1.0 - 1e-9)).ceil().max(1.0) as usize;
        let radius = self.radius + reach;
        let (circle, error) = loop {
            let Some((circle, error)) = circle_spline(self.start, self.end, spans) else {
                return Ok(None);
            };
            if radius * error <= budget {
                break (circle, error);
            }
            spans *= 2;
            if spans > MAX_SPANS {
                return Ok(None);
            }
        };
        let poles = &circle.poles;
        let spine: Vec<DVec3> = poles
            .iter()
            .zip(circle.greville())
            .map(|(&c, theta)| self.point_at(c, theta))
            .collect();
        let (lo, hi) = domain;
        let to_domain = |theta: f64| lo + (hi - lo) * (theta - self.start) / total;
        let knots: Vec<f64> = circle.knots.iter().map(|&t| to_domain(t)).collect();
        let bezier = |poles: Vec<DVec3>| {
            crate::bezier::NurbsCurve::new(DEGREE, poles, None, knots.clone())?.to_piecewise()
        };
        let on_poles = |f: &dyn Fn(DVec2) -> DVec3| bezier(poles.iter().map(|&c| f(c)).collect());
        let curve = bezier(spine)?;
        let f2 = on_poles(&|c| -self.radial(c))?;
        let f3 = on_poles(&|c| self.binormal_at(c))?;
        let tangent = on_poles(&|c| self.tangent_at(c))?;
        let frames = f2
            .segments()
            .iter()
            .zip(f3.segments())
            .zip(tangent.segments())
            .map(|((a, b), t)| {
                let mut frame = RationalFrameSegment::new(
                    a.poles().collect(),
                    b.poles().collect(),
                    vec![1.0; DEGREE + 1],
                )?;
                frame.rotate(self.turn);
                frame.with_tangent(t.poles().collect())
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Some(HelixSpine {
            frames: RationalFrames::new(frames, curve.breaks().to_vec())?,
            curve,
            distance: self.deviation + self.radius * error,
            frame_error: error,
        }))
    }
}

/// A planar spline: degree [`DEGREE`], clamped knots, 2-D poles.
struct PlaneSpline {
    poles: Vec<DVec2>,
    knots: Vec<f64>,
}

impl PlaneSpline {
    /// The Greville abscissae: where the coefficients of the identity sit.
    fn greville(&self) -> Vec<f64> {
        (0..self.poles.len())
            .map(|i| self.knots[i + 1..=i + DEGREE].iter().sum::<f64>() / DEGREE as f64)
            .collect()
    }
}

/// (cos θ, sin θ) on [a, b] by the spline of degree [`DEGREE`] on `spans` equal spans
/// through its ends, the rest by least squares at [`FIT_PER_SPAN`] points a span; and its
/// largest distance from the circle's point of the same θ at twice as many.
fn circle_spline(a: f64, b: f64, spans: usize) -> Option<(PlaneSpline, f64)> {
    let p = DEGREE;
    let mut knots = vec![a; p + 1];
    knots.extend((1..spans).map(|k| a + (b - a) * k as f64 / spans as f64));
    knots.extend(std::iter::repeat_n(b, p + 1));
    let at = |count: usize| (0..=count).map(move |k| a + (b - a) * k as f64 / count as f64);
    let params: Vec<f64> = at(spans * FIT_PER_SPAN).collect();
    let values: Vec<DVec2> = params.iter().map(|&t| unit(t)).collect();
    let poles = fit_splines(&knots, p, &params, &[values])?.pop()?;
    let error = at(2 * spans * FIT_PER_SPAN)
        .map(|t| spline_value(&knots, p, &poles, t).distance(unit(t)))
        .fold(0.0, f64::max);
    Some((PlaneSpline { poles, knots }, error))
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
    c.is_finite().then_some((mean_z - c * mean_a, c))
}

/// (cos θ, sin θ).
fn unit(theta: f64) -> DVec2 {
    DVec2::new(theta.cos(), theta.sin())
}

/// x reduced to (−π, π].
fn wrapped(x: f64) -> f64 {
    x - std::f64::consts::TAU * (x / std::f64::consts::TAU).round()
}
