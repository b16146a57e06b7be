//! A closed convex planar curve seen through its Gauss map — the classical tool of the
//! transition-piece construction: every supporting line of the curve touches it at a
//! *corner* (a range of outward normals), along an *edge* (one normal, a whole segment) or
//! at a point of a strictly convex *arc* (one normal, one point, monotone along the arc).
//! The features are ordered by their outward normal angle θ, counter-clockwise about the
//! plane normal, and cover θ ∈ [θ₀, θ₀ + 2π) once.
//!
//! Input is any closed planar rational spline (polygons, circles, obrounds, NURBS); lines
//! and circular arcs are recognised so that their support points are exact closed forms.

use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::{invalid, Result};
use crate::math::{bounding_diagonal, power_of_two_inverse, signed_angle};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Relative distance (to the curve's size) within which a curve is closed and planar, and
/// control points are collinear (a straight segment).
const GEOMETRY_TOLERANCE: f64 = 1e-9;
/// Turning angle (radians) below which two segments join smoothly (no corner).
const CORNER_ANGLE: f64 = 1e-9;
/// Largest turning of one smooth feature; longer arcs are split so that the normal angle
/// along each one is far from wrapping. Not π/2 (nor another angle curves are commonly
/// made of: 2π/3, π/3, π/4): an arc exactly at the limit would be split or not by rounding,
/// and with it the walk and the part would change under scaling and translation. Splitting
/// no more than needed also keeps the walk's events few (each one bounds a strip).
const MAX_ARC_TURN: f64 = 1.6;

/// The plane of a profile: origin, unit normal and an in-plane orthonormal basis with
/// x × y = normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Plane {
    pub origin: DVec3,
    pub normal: DVec3,
    pub x: DVec3,
    pub y: DVec3,
}

impl Plane {
    /// The angle of the in-plane direction `v` from x towards y.
    pub(super) fn angle_of(&self, v: DVec3) -> f64 {
        v.dot(self.y).atan2(v.dot(self.x))
    }

    /// The unit in-plane direction at angle `theta`.
    pub(super) fn direction(&self, theta: f64) -> DVec3 {
        theta.cos() * self.x + theta.sin() * self.y
    }

    /// Signed distance of `p` from the plane along the normal.
    pub(super) fn height(&self, p: DVec3) -> f64 {
        (p - self.origin).dot(self.normal)
    }

    fn flipped(&self) -> Self {
        Self {
            origin: self.origin,
            normal: -self.normal,
            x: self.y,
            y: self.x,
        }
    }
}

/// What a supporting line with a given outward normal touches.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum FeatureKind {
    /// A corner: the normal turns over `normals` at a fixed point.
    Corner(DVec3),
    /// A straight edge from the first to the second point (counter-clockwise).
    Edge(DVec3, DVec3),
    /// A strictly convex arc; `circle` is (centre, radius) when it is a circular arc.
    Arc {
        curve: RationalBezierCurve,
        circle: Option<(DVec3, f64)>,
    },
}

/// One feature and the interval of outward normal angles it covers (unwrapped; an edge has
/// `from == to`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Feature {
    pub kind: FeatureKind,
    pub from: f64,
    pub to: f64,
}

/// A closed convex planar curve by its Gauss map.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ConvexProfile {
    pub plane: Plane,
    pub features: Vec<Feature>,
    /// Bounding-box diagonal.
    pub size: f64,
    /// Largest distance of a control point from the plane.
    pub flatness: f64,
}

/// Outward normal angle of a counter-clockwise tangent `t` (the tangent turned by −90°).
fn normal_angle(plane: &Plane, t: DVec3) -> f64 {
    plane.angle_of(t.cross(plane.normal))
}

/// The area vector of the closed polygon through `points` (Newell's method).
fn area_vector(points: &[DVec3]) -> DVec3 {
    let centre = points.iter().copied().sum::<DVec3>() / points.len() as f64;
    (0..points.len())
        .map(|k| (points[k] - centre).cross(points[(k + 1) % points.len()] - centre))
        .sum::<DVec3>()
        * 0.5
}

/// Whether the control points of `c` lie on the line through its end points (within `tol`).
fn is_straight(c: &RationalBezierCurve, tol: f64) -> bool {
    let poles: Vec<DVec3> = c.poles().collect();
    let (a, b) = (poles[0], poles[poles.len() - 1]);
    let d = b - a;
    if d.length() <= tol {
        return false;
    }
    let u = d / d.length();
    poles.iter().all(|&p| (p - a).cross(u).length() <= tol)
}

impl ConvexProfile {
    /// The Gauss-map description of a closed, planar, convex curve; `name` is how the
    /// caller calls it (`bottom`, `top`). Refuses open, non-planar, degenerate and
    /// non-convex curves, saying by how much.
    pub(super) fn new(curve: &PiecewiseCurve, name: &str) -> Result<Self> {
        let segments: Vec<&RationalBezierCurve> = curve.segments().iter().collect();
        let poles: Vec<DVec3> = segments.iter().flat_map(|s| s.poles()).collect();
        let size = bounding_diagonal(poles.iter().copied());
        if !(size.is_finite() && size > 0.0) {
            return invalid!("{name} is a single point (or not finite)");
        }
        let tol = GEOMETRY_TOLERANCE * size;
        let (start, end) = (
            segments[0].eval(0.0),
            segments[segments.len() - 1].eval(1.0),
        );
        if start.distance(end) > tol {
            return invalid!(
                "{name} is not closed: its ends are {:.3e} apart",
                start.distance(end)
            );
        }
        let samples: Vec<DVec3> = segments
            .iter()
            .flat_map(|s| (0..16).map(move |k| s.eval(k as f64 / 16.0)))
            .collect();
        // At unit size (a power of two, exact), where the area's products cannot overflow.
        let unit = power_of_two_inverse(size);
        let area = area_vector(&samples.iter().map(|&p| p * unit).collect::<Vec<_>>());
        let measured = area.length();
        if measured.is_nan() || measured <= 1e-12 * (size * unit).powi(2) {
            return invalid!("{name} encloses no area (its points are collinear)");
        }
        let normal = area.normalize();
        let origin = samples.iter().copied().sum::<DVec3>() / samples.len() as f64;
        let (k, flatness) = poles
            .iter()
            .map(|p| (p - origin).dot(normal).abs())
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, 0.0));
        if flatness > tol {
            return invalid!(
                "{name} is not planar: control point {k} is {flatness:.3e} from the plane of the curve"
            );
        }
        let x = (samples[0] - origin - (samples[0] - origin).dot(normal) * normal).normalize();
        let plane = Plane {
            origin,
            normal,
            x,
            y: normal.cross(x),
        };
        let pieces = split_arcs(&segments, &plane, tol)?;
        let features = gauss_map(&pieces, &plane, tol, name)?;
        Ok(Self {
            plane,
            features,
            size,
            flatness,
        })
    }

    /// The same curve traversed the other way, seen from the other side of its plane.
    pub(super) fn flipped(&self) -> Self {
        let plane = self.plane.flipped();
        // Angles measured in the swapped basis: θ ↦ π/2 − θ reverses their order.
        let mut features: Vec<Feature> = self
            .features
            .iter()
            .rev()
            .map(|f| Feature {
                kind: match &f.kind {
                    FeatureKind::Edge(a, b) => FeatureKind::Edge(*b, *a),
                    FeatureKind::Arc { curve, circle } => FeatureKind::Arc {
                        curve: curve.reversed(),
                        circle: *circle,
                    },
                    corner => corner.clone(),
                },
                from: PI / 2.0 - f.to,
                to: PI / 2.0 - f.from,
            })
            .collect();
        let shift = features[0].from;
        let base = features[0].from.rem_euclid(TAU);
        for f in &mut features {
            f.from += base - shift;
            f.to += base - shift;
        }
        Self {
            plane,
            features,
            size: self.size,
            flatness: self.flatness,
        }
    }

    /// The first normal angle; the features cover [start, start + 2π).
    pub(super) fn start(&self) -> f64 {
        self.features[0].from
    }

    /// `theta` moved into [start, start + 2π).
    pub(super) fn wrap(&self, theta: f64) -> f64 {
        let s = self.start();
        s + (theta - s).rem_euclid(TAU)
    }

    /// The index of the feature whose normal interval contains `theta` (the first one at a
    /// shared end).
    pub(super) fn feature_at(&self, theta: f64) -> usize {
        let t = self.wrap(theta);
        self.features
            .iter()
            .position(|f| t <= f.to)
            .unwrap_or(self.features.len() - 1)
    }

    /// The point of feature `index` where the outward normal angle is `theta` (clamped to
    /// the feature's interval; an edge gives its first point).
    pub(super) fn feature_point(&self, index: usize, theta: f64) -> DVec3 {
        let f = &self.features[index];
        let t = self.wrap_near(theta, f);
        match &f.kind {
            FeatureKind::Corner(p) => *p,
            FeatureKind::Edge(a, _) => *a,
            FeatureKind::Arc { curve, circle } => match circle {
                Some((centre, radius)) => {
                    *centre + *radius * self.plane.direction(t.clamp(f.from, f.to))
                }
                None => arc_point(curve, &self.plane, f.from, t.clamp(f.from, f.to)),
            },
        }
    }

    /// `theta` shifted by a multiple of 2π to lie nearest to the feature's interval.
    fn wrap_near(&self, theta: f64, f: &Feature) -> f64 {
        let mid = 0.5 * (f.from + f.to);
        theta - ((theta - mid) / TAU).round() * TAU
    }

    /// A support point for the outward in-plane normal angle `theta`.
    pub(super) fn support(&self, theta: f64) -> DVec3 {
        self.feature_point(self.feature_at(theta), theta)
    }

    /// A support point for the spatial direction `nu` (its component in the plane; `nu`
    /// must not be normal to the plane).
    pub(super) fn support_3d(&self, nu: DVec3) -> DVec3 {
        let flat = nu - nu.dot(self.plane.normal) * self.plane.normal;
        self.support(self.plane.angle_of(flat))
    }

    /// Distance from a point of the plane to the curve.
    pub(super) fn distance(&self, p: DVec3) -> f64 {
        self.features
            .iter()
            .map(|f| match &f.kind {
                FeatureKind::Corner(c) => c.distance(p),
                FeatureKind::Edge(a, b) => segment_distance(p, *a, *b),
                FeatureKind::Arc { curve, circle } => match circle {
                    Some((c, r)) => {
                        let d = p - *c;
                        let theta = self.wrap_near(self.plane.angle_of(d), f);
                        if (f.from..=f.to).contains(&theta) {
                            (d.length() - r).abs()
                        } else {
                            curve.eval(0.0).distance(p).min(curve.eval(1.0).distance(p))
                        }
                    }
                    None => arc_distance(curve, p),
                },
            })
            .fold(f64::INFINITY, f64::min)
    }
}

fn segment_distance(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let d = b - a;
    let s = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    p.distance(a + s * d)
}

/// Distance from `p` to a smooth Bézier arc: sampled, then refined by Brent's method.
fn arc_distance(curve: &RationalBezierCurve, p: DVec3) -> f64 {
    let n = 32;
    let best = (0..=n)
        .min_by(|&i, &j| {
            let d = |k: usize| curve.eval(k as f64 / n as f64).distance(p);
            d(i).total_cmp(&d(j))
        })
        .unwrap_or(0);
    let (a, b) = (
        best.saturating_sub(1) as f64 / n as f64,
        (best + 1).min(n) as f64 / n as f64,
    );
    crate::math::minimize_bracketed(|t| curve.eval(t).distance(p), a, b, 1e-14).value
}

/// The point of a smooth convex arc whose outward normal angle is `theta`, the arc's
/// normal angle starting at `from`: safeguarded Newton on the tangent angle, which grows
/// monotonically along a convex arc.
fn arc_point(curve: &RationalBezierCurve, plane: &Plane, from: f64, theta: f64) -> DVec3 {
    let t0 = curve.eval_jet(0.0).d1;
    let target = theta - from;
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    let mut t = 0.5;
    for _ in 0..100 {
        let jet = curve.eval_jet(t);
        let f = signed_angle(t0, jet.d1, plane.normal) - target;
        if f == 0.0 {
            break;
        }
        if f < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        // dθ/dt = (x' × x'')·n / |x'|².
        let slope = jet.d1.cross(jet.d2).dot(plane.normal) / jet.d1.length_squared();
        let newton = t - f / slope;
        let next = if newton > lo && newton < hi && slope > 0.0 {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - t).abs() <= 1e-16 || hi - lo <= 1e-16 {
            t = next;
            break;
        }
        t = next;
    }
    curve.eval(t)
}

/// The segments, each split until it turns by at most [`MAX_ARC_TURN`]; degenerate
/// (point) segments dropped.
fn split_arcs(
    segments: &[&RationalBezierCurve],
    plane: &Plane,
    tol: f64,
) -> Result<Vec<RationalBezierCurve>> {
    let mut out = Vec::new();
    let mut stack: Vec<(RationalBezierCurve, usize)> =
        segments.iter().rev().map(|s| ((*s).clone(), 0)).collect();
    while let Some((s, depth)) = stack.pop() {
        if bounding_diagonal(s.poles()) <= tol {
            continue;
        }
        let turn = signed_angle(s.eval_jet(0.0).d1, s.eval_jet(1.0).d1, plane.normal).abs();
        let chord_turn =
            |a: f64, b: f64| signed_angle(s.eval_jet(a).d1, s.eval_jet(b).d1, plane.normal).abs();
        let total = chord_turn(0.0, 0.5) + chord_turn(0.5, 1.0);
        if (turn.max(total) > MAX_ARC_TURN) && depth < 20 {
            let (a, b) = s.split(0.5);
            stack.push((b, depth + 1));
            stack.push((a, depth + 1));
        } else {
            out.push(s);
        }
    }
    Ok(out)
}

/// Corners, edges and arcs in counter-clockwise order with unwrapped normal angles;
/// refuses reflex corners, concave arcs and curves that turn more than once.
fn gauss_map(
    pieces: &[RationalBezierCurve],
    plane: &Plane,
    tol: f64,
    name: &str,
) -> Result<Vec<Feature>> {
    let mut features: Vec<Feature> = Vec::new();
    let tangent = |c: &RationalBezierCurve, t: f64| c.eval_jet(t).d1;
    let first_tangent = pieces
        .iter()
        .map(|c| tangent(c, 0.0))
        .next()
        .ok_or_else(|| crate::Error::invalid_input(format!("{name} has no segments")))?;
    let mut theta = normal_angle(plane, first_tangent);
    let n = pieces.len();
    for (k, c) in pieces.iter().enumerate() {
        let (t0, t1) = (tangent(c, 0.0), tangent(c, 1.0));
        if is_straight(c, tol) {
            let (a, b) = (c.eval(0.0), c.eval(1.0));
            match features.last_mut() {
                // No corner since the last edge: collinear edges are one edge.
                Some(Feature {
                    kind: FeatureKind::Edge(_, end),
                    ..
                }) => *end = b,
                _ => features.push(Feature {
                    kind: FeatureKind::Edge(a, b),
                    from: theta,
                    to: theta,
                }),
            }
        } else {
            check_convex_arc(c, plane, name, k)?;
            let turn = signed_angle(t0, t1, plane.normal);
            features.push(Feature {
                kind: FeatureKind::Arc {
                    curve: c.clone(),
                    circle: c.circular_arc(tol),
                },
                from: theta,
                to: theta + turn,
            });
            theta += turn;
        }
        // The turn to the next segment: a corner, or a smooth join.
        let next = &pieces[(k + 1) % n];
        let turn = signed_angle(t1, tangent(next, 0.0), plane.normal);
        if turn < -CORNER_ANGLE {
            return invalid!(
                "{name} is not convex: it turns the other way (by {:.3e} rad) at the end of segment {k}; \
                 a transition piece between two curves is the convex hull surface, which needs convex curves",
                -turn
            );
        }
        if turn > CORNER_ANGLE {
            features.push(Feature {
                kind: FeatureKind::Corner(c.eval(1.0)),
                from: theta,
                to: theta + turn,
            });
            theta += turn;
        }
    }
    let total = theta - features[0].from;
    // A non-finite turn (from a degenerate tangent) is refused too.
    if total.is_nan() || (total - TAU).abs() > 1e-6 {
        return invalid!(
            "{name} is not a simple convex curve: its tangent turns by {:.6} rad in all, not 2π",
            total
        );
    }
    // An edge cut by the start of the curve is one edge.
    let len = features.len();
    if len > 1 {
        if let (FeatureKind::Edge(a, _), FeatureKind::Edge(_, b)) =
            (&features[len - 1].kind, &features[0].kind)
        {
            features[0].kind = FeatureKind::Edge(*a, *b);
            features.pop();
        }
    }
    // Close the cycle exactly.
    let start = features[0].from;
    if let Some(last) = features.last_mut() {
        last.to = start + TAU;
        if matches!(last.kind, FeatureKind::Edge(..)) {
            last.from = last.to;
        }
    }
    Ok(features)
}

/// A smooth segment is admissible when it turns one way only: (x' × x'')·n ≥ 0 on samples.
fn check_convex_arc(c: &RationalBezierCurve, plane: &Plane, name: &str, k: usize) -> Result<()> {
    for j in 0..=32 {
        let jet = c.eval_jet(j as f64 / 32.0);
        let bend = jet.d1.cross(jet.d2).dot(plane.normal);
        let scale = jet.d1.length() * jet.d2.length();
        if bend < -1e-9 * scale {
            return invalid!(
                "{name} is not convex: segment {k} bends the other way at its parameter {:.3}; \
                 a transition piece between two curves is the convex hull surface, which needs convex curves",
                j as f64 / 32.0
            );
        }
    }
    Ok(())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::bezier::homogeneous::lift;
    use std::f64::consts::FRAC_1_SQRT_2;

    /// A closed polyline through `corners` (one degree-1 segment per side).
    pub(crate) fn polygon(corners: &[DVec3]) -> PiecewiseCurve {
        let n = corners.len();
        let segments = (0..n)
            .map(|k| RationalBezierCurve::polynomial(&[corners[k], corners[(k + 1) % n]]).unwrap())
            .collect();
        PiecewiseCurve::with_unit_intervals(segments).unwrap()
    }

    /// The circle about `centre` in the plane of `x`, `y` (the library's primitive) or, for
    /// axes that are not orthonormal, the ellipse with the conjugate semi-axes `radius`·x and
    /// `radius`·y.
    pub(crate) fn circle(centre: DVec3, x: DVec3, y: DVec3, radius: f64) -> PiecewiseCurve {
        let unit = |v: DVec3| (v.length() - 1.0).abs() <= 1e-15;
        if unit(x) && unit(y) && x.dot(y).abs() <= 1e-15 {
            crate::primitives::circle(centre, x, y, radius).unwrap()
        } else {
            ellipse(centre, x, y, radius)
        }
    }

    /// The ellipse about `centre` with the conjugate semi-axes `radius`·x and `radius`·y, as
    /// four rational quadratic quarters (the affine image of a circle's).
    fn ellipse(centre: DVec3, x: DVec3, y: DVec3, radius: f64) -> PiecewiseCurve {
        let at = |k: i32| {
            let a = k as f64 * PI / 2.0;
            centre + radius * (a.cos() * x + a.sin() * y)
        };
        let segments = (0..4)
            .map(|k| {
                let (p0, p2) = (at(k), at(k + 1));
                let p1 = centre + (p0 - centre) + (p2 - centre);
                RationalBezierCurve::from_homogeneous(vec![
                    lift(p0, 1.0),
                    lift(p1, FRAC_1_SQRT_2),
                    lift(p2, 1.0),
                ])
                .unwrap()
            })
            .collect();
        PiecewiseCurve::with_unit_intervals(segments).unwrap()
    }

    fn square() -> PiecewiseCurve {
        polygon(&[
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(-1.0, 1.0, 0.0),
        ])
    }

    #[test]
    fn a_curve_flat_to_rounding_at_a_size_near_the_top_of_the_range_encloses_no_area() {
        // 1e273 along x, 1e81 along y, 0.4 along z: its area vector's products overflowed
        // to NaN, and the NaN plane led to a panic further on.
        let (a, b) = (
            DVec3::new(1.08e273, -9.5e80, -0.1),
            DVec3::new(1.08e273, -9.5e80, 0.4),
        );
        let curve = polygon(&[a, DVec3::new(0.0, 0.0, 0.0), b]);
        let e = ConvexProfile::new(&curve, "bottom").unwrap_err();
        assert!(
            e.message().contains("bottom encloses no area"),
            "{}",
            e.message()
        );
        // The same triangle at a size in range is a profile.
        let unit = 1e-272;
        assert!(ConvexProfile::new(
            &polygon(&[a * unit, DVec3::ZERO, DVec3::new(0.0, 1.0, 0.0)]),
            "bottom"
        )
        .is_ok());
    }

    #[test]
    fn a_square_has_four_corners_and_four_edges() {
        let p = ConvexProfile::new(&square(), "bottom").unwrap();
        assert_eq!(p.features.len(), 8);
        let corners = p
            .features
            .iter()
            .filter(|f| matches!(f.kind, FeatureKind::Corner(_)))
            .count();
        assert_eq!(corners, 4);
        for f in &p.features {
            if let FeatureKind::Corner(_) = f.kind {
                assert!((f.to - f.from - PI / 2.0).abs() < 1e-12);
            }
        }
        assert!((p.features.last().unwrap().to - p.start() - TAU).abs() < 1e-12);
        // The support of the outward normal (1, 1)/√2 is the corner (1, 1).
        let theta = p.plane.angle_of(DVec3::new(1.0, 1.0, 0.0));
        assert!(p.support(theta).distance(DVec3::new(1.0, 1.0, 0.0)) < 1e-15);
        assert!((p.distance(DVec3::new(0.0, 3.0, 0.0)) - 2.0).abs() < 1e-15);
    }

    #[test]
    fn circles_are_exact_arcs() {
        let c = circle(DVec3::new(1.0, 2.0, 3.0), DVec3::X, DVec3::Y, 2.0);
        let p = ConvexProfile::new(&c, "top").unwrap();
        assert!(p.features.iter().all(|f| matches!(
            f.kind,
            FeatureKind::Arc {
                circle: Some(_),
                ..
            }
        )));
        for k in 0..16 {
            let theta = k as f64 * 0.4;
            let s = p.support(theta);
            let expected = DVec3::new(1.0, 2.0, 3.0) + 2.0 * p.plane.direction(theta);
            assert!(s.distance(expected) < 1e-14, "{theta}: {s} vs {expected}");
        }
        assert!((p.distance(DVec3::new(1.0, 5.0, 3.0)) - 1.0).abs() < 1e-14);
        let f = p.flipped();
        for k in 0..16 {
            let v = DVec3::new((k as f64).cos(), (k as f64).sin(), 0.0);
            assert!(f.support_3d(v).distance(p.support_3d(v)) < 1e-14);
        }
    }

    #[test]
    fn smooth_nurbs_arcs_find_their_support_points() {
        // An ellipse-like closed curve: the circle squashed by 1/2 in y (still rational).
        let c = ellipse(DVec3::ZERO, DVec3::X, DVec3::Y * 0.5, 1.0);
        let p = ConvexProfile::new(&c, "top").unwrap();
        for k in 0..12 {
            let theta = -3.0 + k as f64 * 0.5;
            let s = p.support(theta);
            // Ellipse x²/1 + y²/0.25 = 1: normal (x, 4y) ∥ direction(θ).
            let n = DVec3::new(s.x, 4.0 * s.y, 0.0).normalize();
            assert!(n.distance(p.plane.direction(theta)) < 1e-12, "{theta}");
        }
    }

    #[test]
    fn bad_curves_are_refused_with_the_distance() {
        let open = polygon(&[DVec3::ZERO, DVec3::X, DVec3::ONE]);
        let open = PiecewiseCurve::with_unit_intervals(open.segments()[..2].to_vec()).unwrap();
        let e = ConvexProfile::new(&open, "bottom").unwrap_err();
        assert!(e.message().contains("bottom is not closed"), "{e}");
        let skew = polygon(&[DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.1), DVec3::Y]);
        let e = ConvexProfile::new(&skew, "top").unwrap_err();
        assert!(e.message().contains("top is not planar"), "{e}");
        let dart = polygon(&[
            DVec3::ZERO,
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(0.0, 0.5, 0.0),
            DVec3::new(-2.0, 1.0, 0.0),
        ]);
        let e = ConvexProfile::new(&dart, "bottom").unwrap_err();
        assert!(e.message().contains("not convex"), "{e}");
        let line = polygon(&[DVec3::ZERO, DVec3::X, DVec3::X * 2.0]);
        assert!(ConvexProfile::new(&line, "top").is_err());
    }
}
