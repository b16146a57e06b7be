//! Primitive curves as exact rational Bézier pieces: circles, circular arcs, polylines,
//! polygons and obrounds (slots) — the profiles and wires users draw, in one place for the
//! wire sweeps, the sheet parts, the CLI, C and Python.
//!
//! A circular arc is rational quadratic pieces of at most a quarter turn each, in the
//! standard conic form: end points on the circle, the middle control point where the end
//! tangents meet, of weight cos(θ/2) for a piece of angle θ. Every construction is done
//! about its first point and scaled by a power of two to unit size, so that the same
//! figure at 1e-200 or 1e200, or far from the origin, gives the same pieces, mapped.

use crate::bezier::{CurveJet, PiecewiseCurve, RationalBezierCurve};
use crate::error::{invalid, Result};
use crate::math::{check_finite, power_of_two_scale, robust_normalize, unit_scaled};
use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, TAU};

/// A circular arc: from `start`, counter-clockwise about `normal` by `angle` ∈ (0, 2π),
/// to `end`, on the circle of `radius` about `center` (`e1` points to the start, `e2 =
/// normal × e1`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Arc {
    pub center: DVec3,
    pub radius: f64,
    pub normal: DVec3,
    pub e1: DVec3,
    pub e2: DVec3,
    pub angle: f64,
    pub start: DVec3,
    pub end: DVec3,
}

impl Arc {
    /// The arc from `a` through `b` to `c`.
    pub(crate) fn through(a: DVec3, b: DVec3, c: DVec3) -> Result<Self> {
        let (u, v) = (b - a, c - a);
        let n = u.cross(v);
        let scale = u.length() * v.length();
        if n.length().is_nan() || n.length() <= 1e-12 * scale || (c - b).length() == 0.0 {
            return invalid!(
                "an arc whose three points ({a}, {b}, {c}) are collinear or coincide: they define \
                 no circle"
            );
        }
        let center = a
            + (u.length_squared() * v - v.length_squared() * u).cross(n)
                / (2.0 * n.length_squared());
        let normal = n.normalize();
        let radius = (a - center).length();
        let e1 = (a - center) / radius;
        let e2 = normal.cross(e1);
        let to_c = c - center;
        let angle = to_c.dot(e2).atan2(to_c.dot(e1)).rem_euclid(TAU);
        if !(angle > 0.0 && radius.is_finite()) {
            return invalid!("an arc whose start and end coincide: give a full circle as two arcs");
        }
        Ok(Self {
            center,
            radius,
            normal,
            e1,
            e2,
            angle,
            start: a,
            end: c,
        })
    }

    /// The arc about `center` from `start` to `end` (both at `radius`), counter-clockwise
    /// about `normal` by `angle`.
    pub(crate) fn about(
        center: DVec3,
        radius: f64,
        normal: DVec3,
        start: DVec3,
        end: DVec3,
        angle: f64,
    ) -> Self {
        let e1 = unit_scaled(start - center).normalize();
        Self {
            center,
            radius,
            normal,
            e1,
            e2: normal.cross(e1),
            angle,
            start,
            end,
        }
    }

    /// The point at the angle φ from the start (the ends exactly).
    pub(crate) fn point(&self, phi: f64) -> DVec3 {
        if phi == 0.0 {
            return self.start;
        }
        if phi == self.angle {
            return self.end;
        }
        self.center + self.radius * (phi.cos() * self.e1 + phi.sin() * self.e2)
    }

    /// The unit tangent at φ.
    pub(crate) fn tangent(&self, phi: f64) -> DVec3 {
        -phi.sin() * self.e1 + phi.cos() * self.e2
    }

    /// The principal normal at φ (towards the centre).
    pub(crate) fn principal_normal(&self, phi: f64) -> DVec3 {
        -(phi.cos() * self.e1 + phi.sin() * self.e2)
    }

    pub(crate) fn length(&self) -> f64 {
        self.radius * self.angle
    }

    /// Point and derivatives with respect to φ.
    pub(crate) fn jet(&self, phi: f64) -> CurveJet {
        let radial = phi.cos() * self.e1 + phi.sin() * self.e2;
        CurveJet {
            point: self.point(phi),
            d1: self.radius * self.tangent(phi),
            d2: -self.radius * radial,
        }
    }

    /// Rational quadratic segments of at most a quarter turn each (weights ≥ cos 45°).
    pub(crate) fn segment_count(&self) -> usize {
        ((self.angle / FRAC_PI_2 - 1e-9).ceil() as usize).max(1)
    }

    /// The arc as rational quadratic Bézier segments on the breakpoints k/n, ends exact.
    pub(crate) fn curve(&self) -> PiecewiseCurve {
        self.curve_in(self.segment_count())
    }

    /// The arc as `n` rational quadratic Bézier segments of equal angle (n ≥ 1) on the
    /// breakpoints k/n, ends exact.
    pub(crate) fn curve_in(&self, n: usize) -> PiecewiseCurve {
        let n = n.max(1);
        let half = 0.5 * self.angle / n as f64;
        let weight = half.cos();
        let segments = (0..n)
            .map(|k| {
                let (a, b) = (2.0 * half * k as f64, 2.0 * half * (k + 1) as f64);
                let (p0, p2) = (
                    self.point(if k == 0 { 0.0 } else { a }),
                    self.point(if k + 1 == n { self.angle } else { b }),
                );
                let m = a + half;
                let p1 =
                    self.center + (self.radius / weight) * (m.cos() * self.e1 + m.sin() * self.e2);
                RationalBezierCurve::from_homogeneous(vec![
                    p0.extend(1.0),
                    (p1 * weight).extend(weight),
                    p2.extend(1.0),
                ])
                .expect("finite arc data")
            })
            .collect();
        let breaks = (0..=n).map(|k| k as f64 / n as f64).collect();
        PiecewiseCurve::new(segments, breaks).expect("increasing breaks")
    }

    /// The part from φ₀ to φ₁, with the given end points (which lie on the circle).
    pub(crate) fn trimmed(&self, phi0: f64, phi1: f64, start: DVec3, end: DVec3) -> Self {
        let mut arc = Self::about(
            self.center,
            self.radius,
            self.normal,
            start,
            end,
            phi1 - phi0,
        );
        if phi0 == 0.0 {
            arc.e1 = self.e1;
            arc.e2 = self.e2;
        }
        arc
    }

    /// Whether two arcs lie on one circle, turning the same way.
    pub(crate) fn same_circle(&self, other: &Arc, tolerance: f64) -> bool {
        self.center.distance(other.center) <= tolerance
            && (self.radius - other.radius).abs() <= tolerance
            && self.normal.dot(other.normal) > 1.0 - 1e-12
    }
}

/// The orthonormal axes of the plane spanned by `x_axis` and `y_axis` (y made orthogonal
/// to x), and their normal x × y.
fn plane_axes(x_axis: DVec3, y_axis: DVec3) -> Result<(DVec3, DVec3, DVec3)> {
    let x = robust_normalize(check_finite(x_axis, "x_axis")?)
        .ok_or_else(|| crate::error::Error::invalid_input("x_axis must not be zero"))?;
    let y = check_finite(y_axis, "y_axis")?;
    let y = robust_normalize(y - y.dot(x) * x)
        .filter(|_| robust_normalize(y).is_some_and(|u| u.cross(x).length() > 1e-12))
        .ok_or_else(|| {
            crate::error::Error::invalid_input(format!(
                "y_axis = {y} must not be zero or parallel to x_axis = {x_axis}"
            ))
        })?;
    Ok((x, y, x.cross(y)))
}

/// Refuses a length that f64 does not resolve beside the coordinates of `centre` (below
/// 1e-10 of them, as consecutive Hermite points): the figure would collapse to a point.
fn resolved(centre: DVec3, length: f64, name: &str) -> Result<()> {
    let largest = centre.abs().max_element();
    if length < 1e-10 * largest {
        return invalid!(
            "{name} = {length:e} is below what f64 resolves beside centre = {centre} \
             (1e-10 of its coordinates)"
        );
    }
    Ok(())
}

/// The arc with its first axis `e1` given (unit, normal to the arc's normal) rather than
/// computed from the start point, which rounding moves at coordinates far above the radius.
fn with_axis(arc: Arc, e1: DVec3) -> Arc {
    let e2 = arc.normal.cross(e1);
    Arc { e1, e2, ..arc }
}

/// A length argument: finite and positive.
fn positive(value: f64, name: &str) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        invalid!("{name} = {value} must be finite and positive")
    }
}

/// The full circle of `radius` about `centre` in the plane of `x_axis` and `y_axis`: four
/// quarter arcs on the breakpoints 0, 1, 2, 3, 4, starting at centre + radius·x and turning
/// counter-clockwise about x × y.
pub fn circle(centre: DVec3, x_axis: DVec3, y_axis: DVec3, radius: f64) -> Result<PiecewiseCurve> {
    let centre = check_finite(centre, "centre")?;
    let radius = positive(radius, "radius")?;
    let (x, _, normal) = plane_axes(x_axis, y_axis)?;
    resolved(centre, radius, "radius")?;
    let start = centre + radius * x;
    if !start.is_finite() {
        return invalid!("centre = {centre} and radius = {radius} leave the range of a double");
    }
    Ok(on_unit_intervals(
        with_axis(Arc::about(centre, radius, normal, start, start, TAU), x).curve(),
    ))
}

/// The circular arc from `start` through `through` to `end` (less than a full turn):
/// rational quadratic pieces of at most a quarter turn on [0, 1].
pub fn arc_through(start: DVec3, through: DVec3, end: DVec3) -> Result<PiecewiseCurve> {
    let a = check_finite(start, "start")?;
    let (b, c) = (check_finite(through, "through")?, check_finite(end, "end")?);
    let (u, v) = (b - a, c - a);
    if !(u.is_finite() && v.is_finite()) {
        return invalid!("the arc's points leave the range of a double");
    }
    let s = power_of_two_scale(u.abs().max(v.abs()));
    let local = Arc::through(DVec3::ZERO, u * s, v * s)?;
    let arc = Arc {
        center: a + local.center / s,
        radius: local.radius / s,
        start: a,
        end: c,
        ..local
    };
    Ok(arc.curve())
}

/// Straight segments through `points` (at least two, consecutive points distinct), one
/// unit parameter interval each.
pub fn polyline(points: &[DVec3]) -> Result<PiecewiseCurve> {
    if points.len() < 2 {
        return invalid!(
            "points: a polyline needs at least 2 points, got {}",
            points.len()
        );
    }
    for (k, p) in points.iter().enumerate() {
        check_finite(*p, format!("points[{k}]"))?;
    }
    let segments = points
        .windows(2)
        .enumerate()
        .map(|(k, w)| {
            if w[0] == w[1] {
                return invalid!("points[{k}] and points[{}] coincide ({})", k + 1, w[0]);
            }
            RationalBezierCurve::polynomial(w)
        })
        .collect::<Result<Vec<_>>>()?;
    PiecewiseCurve::with_unit_intervals(segments)
}

/// The closed polygon through `corners` (at least three; the last is joined to the first,
/// which must not be repeated at the end).
pub fn polygon(corners: &[DVec3]) -> Result<PiecewiseCurve> {
    if corners.len() < 3 {
        return invalid!(
            "corners: a polygon needs at least 3 corners, got {}",
            corners.len()
        );
    }
    let mut closed = corners.to_vec();
    closed.push(corners[0]);
    polyline(&closed)
        .map_err(|e| crate::error::Error::invalid_input(e.message().replace("points", "corners")))
}

/// The obround (slot) of the points within `radius` of the segment of `length` centred on
/// `centre` along `x_axis`, in the plane of `x_axis` and `y_axis`: from the bottom of the
/// end at −x, counter-clockwise about x × y, a line, a half circle, a line and a half
/// circle (each half circle two quarter arcs), on unit intervals. A length of 0 is the
/// circle.
pub fn obround(
    centre: DVec3,
    x_axis: DVec3,
    y_axis: DVec3,
    length: f64,
    radius: f64,
) -> Result<PiecewiseCurve> {
    let centre = check_finite(centre, "centre")?;
    let radius = positive(radius, "radius")?;
    if !(length.is_finite() && length >= 0.0) {
        return invalid!("length = {length} must be finite and not negative");
    }
    if length == 0.0 {
        return circle(centre, x_axis, y_axis, radius);
    }
    let (x, y, normal) = plane_axes(x_axis, y_axis)?;
    let h = 0.5 * length;
    let point = |a: f64, b: f64| centre + a * x + b * y;
    let (right, left) = (centre + h * x, centre - h * x);
    let corners = [
        point(h, -radius),
        point(h, radius),
        point(-h, radius),
        point(-h, -radius),
    ];
    if corners.iter().any(|p| !p.is_finite()) {
        return invalid!("centre, length and radius leave the range of a double");
    }
    resolved(centre, radius, "radius")?;
    resolved(centre, h, "length")?;
    let half = |c: DVec3, from: DVec3, to: DVec3| {
        let arc = Arc::about(c, radius, normal, from, to, std::f64::consts::PI);
        with_axis(arc, (from - c) / radius).curve()
    };
    let line = |a: DVec3, b: DVec3| RationalBezierCurve::polynomial(&[a, b]);
    let half = |c: DVec3, from: DVec3, to: DVec3| half(c, from, to).segments().to_vec();
    let mut segments = vec![line(corners[3], corners[0])?];
    segments.extend(half(right, corners[0], corners[1]));
    segments.push(line(corners[1], corners[2])?);
    segments.extend(half(left, corners[2], corners[3]));
    PiecewiseCurve::with_unit_intervals(segments)
}

/// The same segments on the breakpoints 0, 1, …, n.
fn on_unit_intervals(curve: PiecewiseCurve) -> PiecewiseCurve {
    PiecewiseCurve::with_unit_intervals(curve.segments().to_vec()).expect("segments of a curve")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points of `curve` at `n` parameters per segment.
    fn samples(curve: &PiecewiseCurve, n: usize) -> Vec<DVec3> {
        let (lo, hi) = curve.domain();
        let m = n * curve.segments().len();
        (0..=m)
            .map(|k| curve.eval(lo + (hi - lo) * k as f64 / m as f64))
            .collect()
    }

    /// The largest angle between the tangents on either side of the joints.
    fn joint_angle(curve: &PiecewiseCurve) -> f64 {
        curve
            .segments()
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0].eval_jet(1.0).d1, w[1].eval_jet(0.0).d1);
                crate::math::angle_between(a, b)
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn a_circle_is_four_quarter_arcs_at_its_radius_in_its_plane() {
        let (c, x, y) = (
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::Z,
        );
        let circle = circle(c, x, y, 2.5).unwrap();
        assert_eq!(circle.segments().len(), 4);
        assert_eq!(circle.domain(), (0.0, 4.0));
        let normal = x.cross(y).normalize();
        for p in samples(&circle, 16) {
            assert!(((p - c).length() - 2.5).abs() < 1e-14, "{p}");
            assert!((p - c).dot(normal).abs() < 1e-14, "{p}");
        }
        assert_eq!(circle.eval(0.0), circle.eval(4.0));
        assert!((circle.eval(0.0) - (c + 2.5 * x.normalize())).length() < 1e-15);
        // Counter-clockwise about x × y: a quarter on, at y.
        assert!((circle.eval(1.0) - (c + 2.5 * DVec3::Z)).length() < 1e-14);
        assert!(joint_angle(&circle) < 1e-14);
    }

    #[test]
    fn an_arc_passes_through_its_three_points_on_one_circle() {
        let (a, b, c) = (
            DVec3::new(10.0, 0.0, 0.0),
            DVec3::new(0.0, 10.0, 0.0),
            DVec3::new(-6.0, -8.0, 0.0),
        );
        let arc = arc_through(a, b, c).unwrap();
        // 233.13° from a through b to c: three quarter arcs or fewer pieces of ≤ 90°.
        assert_eq!(arc.segments().len(), 3);
        assert_eq!((arc.eval(0.0), arc.eval(1.0)), (a, c));
        let points = samples(&arc, 50);
        assert!(points.iter().all(|p| (p.length() - 10.0).abs() < 1e-13));
        let nearest = points
            .iter()
            .map(|p| p.distance(b))
            .fold(f64::INFINITY, f64::min);
        assert!(nearest < 0.5, "{nearest}");
        assert!(
            points.iter().all(|p| !(p.x > 0.0 && p.y < 0.0)),
            "the arc misses the fourth quadrant"
        );
        assert!(joint_angle(&arc) < 1e-14);
    }

    #[test]
    fn polylines_and_polygons_join_their_points() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0)];
        let line = polyline(&p).unwrap();
        assert_eq!((line.segments().len(), line.domain()), (2, (0.0, 2.0)));
        assert_eq!(line.eval(1.0), DVec3::X);
        let square = polygon(&p).unwrap();
        assert_eq!(square.segments().len(), 3);
        assert_eq!(square.eval(3.0), DVec3::ZERO);
        assert_eq!(square.eval(2.5), DVec3::new(0.5, 0.5, 0.0));
    }

    #[test]
    fn an_obround_is_at_its_radius_from_its_segment() {
        let (c, x, y) = (DVec3::new(0.0, 0.0, 5.0), DVec3::X, DVec3::Y);
        let slot = obround(c, x, y, 6.0, 1.5).unwrap();
        assert_eq!(slot.segments().len(), 6);
        for p in samples(&slot, 16) {
            let along = (p - c).dot(x).clamp(-3.0, 3.0);
            let d = p.distance(c + along * x);
            assert!((d - 1.5).abs() < 1e-14, "{p}: {d}");
        }
        assert!(joint_angle(&slot) < 1e-14);
        assert_eq!(slot.eval(0.0), slot.eval(6.0));
        let round = obround(c, x, y, 0.0, 1.5).unwrap();
        assert_eq!(round.segments().len(), 4);
    }

    #[test]
    fn primitives_are_invariant_under_scaling_and_translation() {
        let (x, y) = (DVec3::new(0.6, 0.8, 0.0), DVec3::new(0.0, 0.0, 1.0));
        let build = |s: f64, o: DVec3| -> Vec<PiecewiseCurve> {
            let p = |v: DVec3| o + s * v;
            vec![
                circle(p(DVec3::new(1.0, 2.0, 3.0)), x, y, 2.0 * s).unwrap(),
                arc_through(p(DVec3::X), p(DVec3::new(0.3, 0.9, 0.2)), p(-DVec3::Y)).unwrap(),
                polygon(&[p(DVec3::ZERO), p(DVec3::X), p(DVec3::Y)]).unwrap(),
                obround(p(DVec3::ONE), x, y, 3.0 * s, 0.5 * s).unwrap(),
            ]
        };
        let unit = build(1.0, DVec3::ZERO);
        for s in [1e-200, 1e-100, 1e100, 1e200] {
            for shift in [DVec3::ZERO, DVec3::new(1e3, -2e3, 5e2)] {
                let o = shift * s;
                for (a, b) in unit.iter().zip(build(s, o)) {
                    assert_eq!(a.segments().len(), b.segments().len());
                    for t in [0.0, 0.37, 1.0, 1.5] {
                        let (pa, pb) = (a.eval(t), (b.eval(t) - o) / s);
                        assert!(
                            pa.distance(pb) < 1e-9 * (1.0 + shift.length()),
                            "{s:e}: {pa} {pb}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn bad_arguments_are_refused_naming_them() {
        let n = f64::NAN;
        let cases: Vec<(Result<PiecewiseCurve>, &str)> = vec![
            (
                circle(DVec3::new(n, 0.0, 0.0), DVec3::X, DVec3::Y, 1.0),
                "centre",
            ),
            (circle(DVec3::ZERO, DVec3::ZERO, DVec3::Y, 1.0), "x_axis"),
            (circle(DVec3::ZERO, DVec3::X, 2.0 * DVec3::X, 1.0), "y_axis"),
            (circle(DVec3::ZERO, DVec3::X, DVec3::Y, 0.0), "radius"),
            (
                circle(DVec3::ZERO, DVec3::X, DVec3::Y, f64::INFINITY),
                "radius",
            ),
            (
                circle(1.7e308 * DVec3::X, DVec3::X, DVec3::Y, 1e308),
                "radius",
            ),
            (
                arc_through(DVec3::ZERO, DVec3::X, 2.0 * DVec3::X),
                "collinear",
            ),
            (
                arc_through(DVec3::ZERO, DVec3::new(n, 1.0, 0.0), DVec3::X),
                "through",
            ),
            (polyline(&[DVec3::ZERO]), "points"),
            (
                polyline(&[DVec3::ZERO, DVec3::X, DVec3::X]),
                "points[1] and points[2]",
            ),
            (polygon(&[DVec3::ZERO, DVec3::X]), "corners"),
            (
                polygon(&[DVec3::ZERO, DVec3::X, DVec3::X]),
                "corners[1] and corners[2]",
            ),
            (
                obround(DVec3::ZERO, DVec3::X, DVec3::Y, -1.0, 1.0),
                "length",
            ),
            (obround(DVec3::ZERO, DVec3::X, DVec3::Y, 1.0, n), "radius"),
            (
                circle(DVec3::new(20.0, 1e300, 150.0), DVec3::Y, DVec3::Z, 60.0),
                "radius",
            ),
            (
                obround(1e20 * DVec3::ONE, DVec3::X, DVec3::Y, 1e5, 1e12),
                "length",
            ),
        ];
        for (k, (result, name)) in cases.into_iter().enumerate() {
            let e = result.expect_err(name);
            assert!(e.message().contains(name), "case {k}: {e}");
        }
    }
}
