//! Analytic forms of a B-rep's faces and edges: the plane, cylinder or torus a face's
//! NURBS surface is exactly, the line or circle an edge's curve is — parametrized as
//! OpenCascade's `Geom_*` are (by length and by angle), so that a kernel holding analytic
//! geometry takes the face as the analytic surface it is. Every edge of an analytic face is
//! then an iso-parameter line of its surface: its curve on the face is a line of unit speed
//! in the surface's parameters, found here once for all writers.
//!
//! Circles are read off rational quadratic Bézier arcs: a segment P₀P₁P₂ with weights
//! w₀, w₁, w₂ is a circular arc iff |P₀P₁| = |P₁P₂| and w₁/√(w₀w₂) = cos β, β the angle at
//! P₀ between P₀P₁ and P₀P₂; the arc turns by 2β about the centre P₀ + r n₀,
//! r = |P₀P₁| / tan β, n₀ the unit normal to P₀P₁ towards P₂ (Piegl & Tiller, *The NURBS
//! Book*, §7.3, eq. (7.33) and Fig. 7.16).
//!
//! A construction marks the faces it knows to be analytic (a circle swept along an
//! untwisted line is a cylinder, along an untwisted arc a torus, a line along an arc a
//! cone, cylinder or annulus); [`settle`] keeps a face
//! analytic only where every edge it uses is a line or circle lying along its parameter
//! lines, and an edge analytic only where every face using it is analytic or planar (a
//! kernel projects an edge onto a plane itself), so that every curve on a face is on the
//! parameters of its edge's curve.

use super::topology::{Brep, BrepEdge, BrepFace, BrepSurface, PCurve};
use crate::bezier::{NurbsCurve, RationalBezierCurve};
use crate::math::{power_of_two_inverse, robust_length};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// How far apart two descriptions of the same point may lie, relative to the size of the
/// curve or surface, beyond the rounding of the coordinates.
const RELATIVE: f64 = 1e-10;

/// The rounding of coordinates of magnitude 1, for tolerances of points given in the
/// caller's coordinates (a shape far from the origin carries its offset's rounding).
pub(crate) const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// A line or a circle, on OpenCascade's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnalyticCurve {
    /// origin + s · direction, `direction` a unit vector (s: length).
    Line {
        /// The point at s = 0.
        origin: DVec3,
        /// Unit direction.
        direction: DVec3,
    },
    /// center + radius (cos s · x_axis + sin s · (axis × x_axis)) (s: angle).
    Circle {
        /// The centre.
        center: DVec3,
        /// Unit normal of the circle's plane; the curve turns counter-clockwise about it.
        axis: DVec3,
        /// Unit direction from the centre to the point at s = 0.
        x_axis: DVec3,
        /// The radius.
        radius: f64,
    },
}

/// An edge's curve as a line or circle: from the edge's start vertex at s = 0 to its end
/// vertex at s = `end`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnalyticEdge {
    /// The line or circle.
    pub curve: AnalyticCurve,
    /// The parameter of the end vertex (> 0): the length of a line, the angle of an arc.
    pub end: f64,
}

/// A plane, cylinder, cone or torus, on OpenCascade's parameters (y = axis × x_axis).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnalyticSurface {
    /// origin + u x_axis + v y; its normal `normal`.
    Plane {
        /// A point of the plane.
        origin: DVec3,
        /// Unit normal.
        normal: DVec3,
        /// Unit direction of u.
        x_axis: DVec3,
    },
    /// origin + radius (cos u x_axis + sin u y) + v axis; its normal points away from the
    /// axis.
    Cylinder {
        /// A point of the axis (v = 0).
        origin: DVec3,
        /// Unit direction of the axis.
        axis: DVec3,
        /// Unit direction of u = 0, perpendicular to the axis.
        x_axis: DVec3,
        /// The radius.
        radius: f64,
    },
    /// origin + (radius + v sin α)(cos u x_axis + sin u y) + v cos α axis, α the
    /// semi-angle (|α| < π/2, not 0); v is the length along a ruling, its normal points away
    /// from the axis where radius + v sin α > 0.
    Cone {
        /// The point of the axis at v = 0.
        origin: DVec3,
        /// Unit direction of the axis.
        axis: DVec3,
        /// Unit direction of u = 0, perpendicular to the axis.
        x_axis: DVec3,
        /// The radius at v = 0.
        radius: f64,
        /// The angle α between the rulings and the axis.
        semi_angle: f64,
    },
    /// center + (major + minor cos v)(cos u x_axis + sin u y) + minor sin v axis; its
    /// normal points out of the tube.
    Torus {
        /// The centre.
        center: DVec3,
        /// Unit direction of the axis of revolution.
        axis: DVec3,
        /// Unit direction of u = 0, perpendicular to the axis.
        x_axis: DVec3,
        /// Distance of the tube's centre circle from the axis.
        major: f64,
        /// Radius of the tube (less than `major`).
        minor: f64,
    },
}

/// A face's surface as a plane, cylinder or torus, with the face's sense on it and, for a
/// cylinder or torus, each edge use's curve on it.
#[derive(Clone, Debug, PartialEq)]
pub struct AnalyticFace {
    /// The surface.
    pub surface: AnalyticSurface,
    /// Whether the face's normal is this surface's normal (which may be opposite to the
    /// NURBS surface's).
    pub same_sense: bool,
    /// Per loop of the face, per use: the edge's analytic curve in (u, v), on the edge's
    /// parameter s ([`PCurve::Line`], unit speed); empty on a plane, onto which a kernel
    /// projects the edges itself.
    pub pcurves: Vec<Vec<PCurve>>,
}

impl BrepFace {
    /// Whether the face lies on a plane (its own surface, or its analytic form): a kernel
    /// projects its edges onto it, no curve on the face is needed.
    pub fn is_planar(&self) -> bool {
        matches!(self.surface, BrepSurface::Plane { .. })
            || self.analytic.as_ref().is_some_and(|a| a.surface.is_plane())
    }
}

impl AnalyticFace {
    /// Whether the face's loops run the other way on the analytic surface than on its NURBS
    /// surface (their parameters map with opposite orientation, the normals being
    /// opposite): a kernel then takes each loop's uses in reverse order, each against its
    /// direction in the model, to have outer loops counter-clockwise.
    pub fn loops_reversed(&self, face_same_sense: bool) -> bool {
        self.same_sense != face_same_sense
    }
}

impl AnalyticCurve {
    /// The point at parameter `s`.
    pub fn point(&self, s: f64) -> DVec3 {
        match *self {
            AnalyticCurve::Line { origin, direction } => origin + direction * s,
            AnalyticCurve::Circle {
                center,
                axis,
                x_axis,
                radius,
            } => center + (x_axis * s.cos() + axis.cross(x_axis) * s.sin()) * radius,
        }
    }
}

impl AnalyticEdge {
    /// The line or circle `curve` is exactly (to the rounding of its coordinates), from its
    /// first to its last parameter: a degree-1 curve of two poles, or a degree-2 curve of
    /// circular arcs on one circle turning less than a full turn. `None` otherwise.
    pub fn of_curve(curve: &NurbsCurve) -> Option<Self> {
        match curve.degree {
            1 if curve.poles.len() == 2 => {
                let (a, b) = (curve.poles[0], curve.poles[1]);
                let length = robust_length(b - a);
                (length > 0.0 && length.is_finite()).then(|| AnalyticEdge {
                    curve: AnalyticCurve::Line {
                        origin: a,
                        direction: (b - a) / length,
                    },
                    end: length,
                })
            }
            2 => circle_of(curve),
            _ => None,
        }
    }
}

/// The arcs of a degree-2 curve as one circle (module notes).
fn circle_of(curve: &NurbsCurve) -> Option<AnalyticEdge> {
    let pieces = curve.to_piecewise().ok()?;
    let mut arcs = pieces.segments().iter().map(arc_of);
    let first = arcs.next()??;
    let mut angle = first.angle;
    let mut end = first.end;
    for arc in arcs {
        let arc = arc?;
        let tolerance = first.radius * RELATIVE + first.rounding.max(arc.rounding);
        let same = robust_length(arc.center - first.center) <= tolerance
            && (arc.radius - first.radius).abs() <= tolerance
            && arc.axis.dot(first.axis) >= 1.0 - RELATIVE
            && robust_length(arc.start - end) <= tolerance;
        if !same {
            return None;
        }
        angle += arc.angle;
        end = arc.end;
    }
    (angle < TAU - 1e-6).then_some(AnalyticEdge {
        curve: AnalyticCurve::Circle {
            center: first.center,
            axis: first.axis,
            x_axis: first.x_axis,
            radius: first.radius,
        },
        end: angle,
    })
}

/// Whether a segment is an arc of a circle about the origin in the plane z = 0 (its centre
/// and plane to [`RELATIVE`] of its radius plus the rounding of its coordinates): a
/// profile edge no turn about the spine's tangent moves off its circle.
pub(crate) fn is_centred_arc(segment: &RationalBezierCurve) -> bool {
    arc_of(segment).is_some_and(|arc| {
        robust_length(arc.center) <= arc.radius * RELATIVE + arc.rounding
            && arc.axis.z.abs() >= 1.0 - RELATIVE
    })
}

/// One rational quadratic segment as a circular arc.
struct Arc {
    center: DVec3,
    axis: DVec3,
    x_axis: DVec3,
    radius: f64,
    angle: f64,
    start: DVec3,
    end: DVec3,
    /// The rounding of its coordinates.
    rounding: f64,
}

fn arc_of(segment: &RationalBezierCurve) -> Option<Arc> {
    let [h0, h1, h2] = segment.homogeneous() else {
        return None;
    };
    let (w0, w1, w2) = (h0.w, h1.w, h2.w);
    if !(w0 > 0.0 && w1 > 0.0 && w2 > 0.0) {
        return None;
    }
    let (p0, p1, p2) = (h0.truncate() / w0, h1.truncate() / w1, h2.truncate() / w2);
    // At unit size (a power of two, exact): no square under- or overflows.
    let unit = power_of_two_inverse(robust_length(p1 - p0));
    let (leg, next, chord) = ((p1 - p0) * unit, (p2 - p1) * unit, (p2 - p0) * unit);
    let length = leg.length();
    let rounding = ROUNDING * p0.abs().max(p1.abs()).max(p2.abs()).max_element();
    let unequal = (next.length() - length).abs() > length * RELATIVE + rounding * unit;
    if !length.is_finite() || length <= rounding * unit * 1e3 || unequal {
        return None;
    }
    let tangent = leg / length;
    let (cos, sin) = (tangent.dot(chord), tangent.cross(chord).length());
    let beta = sin.atan2(cos);
    let shape = w1 / w0.sqrt() / w2.sqrt();
    let slack = RELATIVE + rounding * unit / length;
    if !(beta > 0.0 && beta < 0.5 * PI) || (shape - beta.cos()).abs() > slack {
        return None;
    }
    let inward = (chord - tangent * tangent.dot(chord)).normalize();
    let radius = length / beta.tan() / unit;
    let center = p0 + inward * radius;
    Some(Arc {
        center,
        axis: tangent.cross(inward),
        x_axis: -inward,
        radius,
        angle: 2.0 * beta,
        start: p0,
        end: p2,
        rounding,
    })
}

impl AnalyticSurface {
    fn is_plane(&self) -> bool {
        matches!(self, AnalyticSurface::Plane { .. })
    }

    /// The point at (u, v).
    pub fn point(&self, u: f64, v: f64) -> DVec3 {
        match *self {
            AnalyticSurface::Plane {
                origin,
                normal,
                x_axis,
            } => origin + x_axis * u + normal.cross(x_axis) * v,
            AnalyticSurface::Cylinder {
                origin,
                axis,
                x_axis,
                radius,
            } => origin + radial(axis, x_axis, u) * radius + axis * v,
            AnalyticSurface::Cone {
                origin,
                axis,
                x_axis,
                radius,
                semi_angle,
            } => {
                origin
                    + radial(axis, x_axis, u) * (radius + v * semi_angle.sin())
                    + axis * (v * semi_angle.cos())
            }
            AnalyticSurface::Torus {
                center,
                axis,
                x_axis,
                major,
                minor,
            } => {
                center
                    + radial(axis, x_axis, u) * (major + minor * v.cos())
                    + axis * (minor * v.sin())
            }
        }
    }

    /// The unit normal (∂u × ∂v, normalized) at the point nearest `p`.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let (u, v) = self.parameters(p);
        match *self {
            AnalyticSurface::Plane { normal, .. } => normal,
            AnalyticSurface::Cylinder { axis, x_axis, .. } => radial(axis, x_axis, u),
            AnalyticSurface::Cone {
                axis,
                x_axis,
                semi_angle,
                ..
            } => radial(axis, x_axis, u) * semi_angle.cos() - axis * semi_angle.sin(),
            AnalyticSurface::Torus { axis, x_axis, .. } => {
                radial(axis, x_axis, u) * v.cos() + axis * v.sin()
            }
        }
    }

    /// The parameters (u, v) of the point of the surface nearest `p`, angles in (−π, π].
    pub fn parameters(&self, p: DVec3) -> (f64, f64) {
        match *self {
            AnalyticSurface::Plane {
                origin,
                normal,
                x_axis,
            } => {
                let d = p - origin;
                (d.dot(x_axis), d.dot(normal.cross(x_axis)))
            }
            AnalyticSurface::Cylinder {
                origin,
                axis,
                x_axis,
                ..
            } => {
                let d = p - origin;
                (angle_about(axis, x_axis, d), d.dot(axis))
            }
            AnalyticSurface::Cone {
                origin,
                axis,
                x_axis,
                radius,
                semi_angle,
            } => {
                // The length along the ruling: (ρ − radius, h) projected on (sin α, cos α).
                let (u, out, height) = meridian(p - origin, axis, x_axis, radius);
                (u, out * semi_angle.sin() + height * semi_angle.cos())
            }
            AnalyticSurface::Torus {
                center,
                axis,
                x_axis,
                major,
                ..
            } => {
                let (u, out, height) = meridian(p - center, axis, x_axis, major);
                (u, height.atan2(out))
            }
        }
    }

    /// Which parameters are angles (periodic by 2π).
    fn periodic(&self) -> [bool; 2] {
        match self {
            AnalyticSurface::Plane { .. } => [false, false],
            AnalyticSurface::Cylinder { .. } | AnalyticSurface::Cone { .. } => [true, false],
            AnalyticSurface::Torus { .. } => [true, true],
        }
    }

    /// Its placement as OpenCascade's `gp_Ax3`: the location (origin or centre), the unit
    /// axis (a plane's normal) and the unit x axis.
    pub fn axes(&self) -> [DVec3; 3] {
        match *self {
            AnalyticSurface::Plane {
                origin,
                normal,
                x_axis,
            } => [origin, normal, x_axis],
            AnalyticSurface::Cylinder {
                origin,
                axis,
                x_axis,
                ..
            }
            | AnalyticSurface::Cone {
                origin,
                axis,
                x_axis,
                ..
            } => [origin, axis, x_axis],
            AnalyticSurface::Torus {
                center,
                axis,
                x_axis,
                ..
            } => [center, axis, x_axis],
        }
    }

    /// Its dimensions in OpenCascade's order: none for a plane, the cylinder's radius, the
    /// cone's radius at v = 0 and semi-angle, the torus's major and minor radii.
    pub fn dimensions(&self) -> Vec<f64> {
        match *self {
            AnalyticSurface::Plane { .. } => Vec::new(),
            AnalyticSurface::Cylinder { radius, .. } => vec![radius],
            AnalyticSurface::Cone {
                radius, semi_angle, ..
            } => vec![radius, semi_angle],
            AnalyticSurface::Torus { major, minor, .. } => vec![major, minor],
        }
    }

    /// Its location, whose coordinates' rounding its parameters carry.
    fn location(&self) -> DVec3 {
        self.axes()[0]
    }

    /// The size the surface's lengths are measured against.
    fn size(&self) -> f64 {
        match *self {
            AnalyticSurface::Plane { .. } => 0.0,
            AnalyticSurface::Cylinder { radius, .. } | AnalyticSurface::Cone { radius, .. } => {
                radius
            }
            AnalyticSurface::Torus { major, .. } => major,
        }
    }
}

/// The angle of `d` about `axis` from `x_axis`, its distance from the axis less `radius`,
/// and its height along the axis: where `d` lies in its plane through the axis.
fn meridian(d: DVec3, axis: DVec3, x_axis: DVec3, radius: f64) -> (f64, f64, f64) {
    let height = d.dot(axis);
    let out = robust_length(d - axis * height) - radius;
    (angle_about(axis, x_axis, d), out, height)
}

/// cos u x_axis + sin u (axis × x_axis).
fn radial(axis: DVec3, x_axis: DVec3, u: f64) -> DVec3 {
    x_axis * u.cos() + axis.cross(x_axis) * u.sin()
}

/// The angle of `d` about `axis` from `x_axis`, in (−π, π].
fn angle_about(axis: DVec3, x_axis: DVec3, d: DVec3) -> f64 {
    d.dot(axis.cross(x_axis)).atan2(d.dot(x_axis))
}

/// `a` moved by whole turns to within π of `near`.
fn unwrap(a: f64, near: f64) -> f64 {
    a - TAU * ((a - near) / TAU).round()
}

/// Keeps the analytic forms a kernel can hold together (module notes) and finds the
/// curves of the analytic faces' edges on them.
pub(crate) fn settle(brep: &mut Brep) {
    loop {
        let mut changed = false;
        for f in 0..brep.faces.len() {
            let Some(analytic) = &brep.faces[f].analytic else {
                continue;
            };
            if analytic.surface.is_plane() {
                continue;
            }
            let surface = analytic.surface;
            let bounds = &brep.faces[f].bounds;
            let pcurves: Option<Vec<Vec<PCurve>>> = bounds
                .iter()
                .map(|b| {
                    let uses: Vec<_> = b.uses.iter().map(|u| (u.edge, u.forward)).collect();
                    loop_pcurves(&surface, &uses, &brep.edges)
                })
                .collect();
            let face = &mut brep.faces[f];
            match pcurves {
                Some(pcurves) => {
                    if let Some(a) = face.analytic.as_mut() {
                        a.pcurves = pcurves;
                    }
                }
                None => {
                    face.analytic = None;
                    changed = true;
                }
            }
        }
        let mut carried = vec![true; brep.edges.len()];
        for face in &brep.faces {
            if matches!(face.surface, BrepSurface::Plane { .. }) || face.analytic.is_some() {
                continue;
            }
            for u in face.bounds.iter().flat_map(|b| &b.uses) {
                if let Some(c) = carried.get_mut(u.edge) {
                    *c = false;
                }
            }
        }
        for (edge, carried) in brep.edges.iter_mut().zip(carried) {
            if !carried && edge.analytic.is_some() {
                edge.analytic = None;
                changed = true;
            }
        }
        if !changed {
            return;
        }
    }
}

/// The curves of a loop's edges on an analytic surface, each an iso-parameter line of unit
/// speed; the loop's points unwrapped by whole turns so that it closes in the parameter
/// plane. `None` where an edge is not analytic or does not run along a parameter line.
fn loop_pcurves(
    surface: &AnalyticSurface,
    uses: &[(usize, bool)],
    edges: &[BrepEdge],
) -> Option<Vec<PCurve>> {
    let periodic = surface.periodic();
    let near = |(u, v): (f64, f64), (nu, nv): (f64, f64)| {
        (
            if periodic[0] { unwrap(u, nu) } else { u },
            if periodic[1] { unwrap(v, nv) } else { v },
        )
    };
    // What 1e-9 of the size and the rounding of the coordinates make of lengths and angles.
    let size = surface.size();
    let length_slack = 1e-9 * size + 4.0 * ROUNDING * surface.location().abs().max_element();
    let slack = |angle: bool| {
        if angle {
            length_slack / size
        } else {
            length_slack
        }
    };
    let mut at: Option<(f64, f64)> = None;
    let mut first = None;
    let mut pcurves = Vec::with_capacity(uses.len());
    for &(e, forward) in uses {
        let edge = edges.get(e)?.analytic?;
        let (s0, s1) = if forward {
            (0.0, edge.end)
        } else {
            (edge.end, 0.0)
        };
        let raw = surface.parameters(edge.curve.point(s0));
        let p0 = at.map_or(raw, |a| near(raw, a));
        let pm = near(surface.parameters(edge.curve.point(0.5 * (s0 + s1))), p0);
        let p1 = near(surface.parameters(edge.curve.point(s1)), pm);
        let line = matches!(edge.curve, AnalyticCurve::Line { .. });
        let rate = |delta: f64, angle: bool| {
            if angle == line {
                // An angle along a line, a length along a circle: constant on these surfaces.
                (delta.abs() <= slack(angle)).then_some(0.0)
            } else {
                snap(delta / (s1 - s0), slack(angle) / (s1 - s0).abs())
            }
        };
        let direction = (
            rate(p1.0 - p0.0, periodic[0])?,
            rate(p1.1 - p0.1, periodic[1])?,
        );
        let origin = (p0.0 - direction.0 * s0, p0.1 - direction.1 * s0);
        // The line must reproduce the edge: checked at its middle, on the surface.
        let middle = 0.5 * (s0 + s1);
        let on_surface = surface.point(
            origin.0 + direction.0 * middle,
            origin.1 + direction.1 * middle,
        );
        if robust_length(on_surface - edge.curve.point(middle)) > 4.0 * length_slack {
            return None;
        }
        first.get_or_insert(p0);
        at = Some((origin.0 + direction.0 * s1, origin.1 + direction.1 * s1));
        pcurves.push(PCurve::Line { origin, direction });
    }
    let (start, end) = (first?, at?);
    // Each edge's end carries its own rounding.
    let closes = |a: f64, b: f64, angle: bool| {
        (a - b).abs() <= uses.len() as f64 * slack(angle) + 1e-12 * a.abs()
    };
    (closes(start.0, end.0, periodic[0]) && closes(start.1, end.1, periodic[1])).then_some(pcurves)
}

/// A parameter's rate along an edge, −1, 0 or 1 (along a parameter line at unit speed) to
/// within `slack`.
fn snap(rate: f64, slack: f64) -> Option<f64> {
    let whole = rate.round();
    ((rate - whole).abs() <= 1e-9 + slack && whole.abs() <= 1.0).then_some(whole + 0.0)
}
