//! One piece of a cone spline: a segment of a right circular cone, of a cylinder of
//! revolution, or of a plane, bounded by two rulings (Fig. 16).
//!
//! Every such segment is swept by its first ruling under one rigid motion: a rotation about
//! the axis (cone, cylinder, plane sector about its vertex) or a translation (plane strip
//! between parallel rulings). Storing the piece as *start element + motion* makes the rest
//! elementary: the end ruling and its tangent plane are the moved start element (so the G1
//! junction of Theorem 1 is a frame equality), the parallel circles are the paths of ruling
//! points, the exact degree (1, 2) patch is a ruling segment times a rational quadratic
//! circular arc, and the development and bending of Section "Bending sequences" only change
//! the half angle α and the segment angle φ with φ sin α fixed.
//!
//! The dual form of a piece (Fig. 1) is its tangent planes as a rational quadratic curve of
//! planes: the tangent planes U₀, U₂ at the bounding rulings in normalized plane
//! coordinates, and the Bézier plane U₁ through both bounding rulings with the weight
//! w₁ = |(u₁₁, u₁₂, u₁₃)| = cos α / cos β, α and β the angles of the axis with U₀ and U₁.
//!
//! The rotation sense is chosen so that the piece leaves its start ruling towards the side
//! vector p at the reference point. On the far nappe of a cone (reference point and inscribed
//! sphere on different sides of the vertex) this is the complementary arc of Figs. 5–6.

use super::element::Element;
use crate::bezier::homogeneous::lift;
use crate::bezier::RationalBezierPatch;
use crate::error::{invalid, Error, Result};
use crate::math::{angle_between, signed_angle};
use glam::{DMat3, DVec3, DVec4};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// |cos| between axis and ruling above which a rotation is a cylinder, and below which it
/// is a plane sector.
const AXIS_TOLERANCE: f64 = 1e-12;

/// Largest angle one degree (1, 2) patch spans; longer pieces are split into equal parts
/// so that every weight cos(φ/2) stays ≥ 1/2.
const MAX_PATCH_ANGLE: f64 = 2.0 * PI / 3.0;

/// The rigid motion that sweeps a piece's first ruling over the piece.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motion {
    /// Rotation by the signed `angle` about the line through `origin` with unit `axis`.
    Rotation {
        /// A point of the axis.
        origin: DVec3,
        /// The unit axis direction.
        axis: DVec3,
        /// The signed rotation angle (radians).
        angle: f64,
    },
    /// Translation by a vector normal to the rulings (a plane strip).
    Translation(DVec3),
}

impl Motion {
    /// The image of the point `x` under the fraction `f ∈ [0, 1]` of the motion.
    pub fn point(&self, x: DVec3, f: f64) -> DVec3 {
        match *self {
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => origin + DMat3::from_axis_angle(axis, f * angle) * (x - origin),
            Motion::Translation(v) => x + f * v,
        }
    }

    /// The image of the direction `d` under the fraction `f` of the motion.
    pub fn vector(&self, d: DVec3, f: f64) -> DVec3 {
        match *self {
            Motion::Rotation { axis, angle, .. } => DMat3::from_axis_angle(axis, f * angle) * d,
            Motion::Translation(_) => d,
        }
    }

    /// The element moved by the fraction `f` of the motion.
    pub fn element(&self, el: &Element, f: f64) -> Element {
        Element::from_frame(
            self.point(el.point, f),
            self.vector(el.ruling, f),
            self.vector(el.side, f),
        )
    }
}

/// What surface a piece is taken from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PieceKind {
    /// A right circular cone (0 < α < π/2).
    Cone,
    /// A cylinder of revolution (α = 0, vertex at infinity).
    Cylinder,
    /// A plane: a sector about a vertex (α = π/2) or a strip between parallel rulings.
    Plane,
}

/// A cone, cylinder or plane segment: its first ruling (with tangent plane and reference
/// point) and the motion that sweeps it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConePiece {
    /// The first ruling, its tangent plane and reference point.
    pub start: Element,
    /// The motion sweeping the first ruling over the piece.
    pub motion: Motion,
}

/// `theta0 ∈ (−π, π]` turned into the sweep in the required sense: (0, 2π) if `positive`,
/// else (−2π, 0).
fn signed_sweep(theta0: f64, positive: bool) -> f64 {
    match (positive, theta0 > 0.0) {
        (true, true) | (false, false) if theta0 != 0.0 => theta0,
        (true, _) => theta0 + TAU,
        (false, _) => theta0 - TAU,
    }
}

/// Component of `v` normal to the unit vector `k`.
fn radial(v: DVec3, k: DVec3) -> DVec3 {
    v - v.dot(k) * k
}

/// Distance from `y` to the line through `p` with unit direction `d`.
fn line_distance(y: DVec3, p: DVec3, d: DVec3) -> f64 {
    (y - p).cross(d).length()
}

impl ConePiece {
    /// The cone with `vertex` (on the start ruling) that touches the start tangent plane
    /// along the start ruling and contains the ruling direction `end_ruling` through the
    /// vertex. Its axis k = cos β e + sin β n lies in the plane of e and n with
    /// k · e = k · e_end, i.e. tan β = (1 − e · e_end) / (n · e_end); n · e_end = 0 gives a
    /// plane sector (β = π/2).
    pub fn cone(vertex: DVec3, start: Element, end_ruling: DVec3) -> Result<Self> {
        let (e, n) = (start.ruling, start.normal());
        let e_end = end_ruling.normalize();
        // 1 − e·e_end = |e − e_end|² / 2 for unit vectors: accurate to rounding for close
        // rulings, where 1 − e·e_end cancels (relative error ε / angle², which the half
        // angle of a cone between rulings 10⁻³ apart would carry as 2e-10).
        let (one_minus_ce, cn) = ((e - e_end).length_squared() / 2.0, n.dot(e_end));
        if one_minus_ce <= 1e-14 || one_minus_ce.is_nan() {
            return invalid!("a cone piece needs two different rulings through its vertex");
        }
        let beta = one_minus_ce.atan2(cn);
        let axis = (beta.cos() * e + beta.sin() * n).normalize();
        let rho = start.parameter_of(vertex);
        let scale = start
            .point
            .abs()
            .max_element()
            .max(vertex.abs().max_element())
            .max(1e-300);
        if rho.abs() <= 1e-12 * scale {
            return Err(Error::no_solution(
                "a cone vertex falls on the reference point of its ruling",
            ));
        }
        // k × e = sin β · p with sin β > 0: a positive rotation moves the reference point
        // towards +p exactly when it lies beyond the vertex, ρ = (vertex − point) · e < 0.
        let theta0 = signed_angle(radial(e, axis), radial(e_end, axis), axis);
        let angle = signed_sweep(theta0, rho < 0.0);
        Ok(Self {
            start,
            motion: Motion::Rotation {
                origin: vertex,
                axis,
                angle,
            },
        })
    }

    /// The cylinder of revolution touching the start tangent plane along the start ruling and
    /// containing the parallel ruling through `end_point` (its normal section is the circle
    /// through the start point tangent to p, radius ρ = |y|² / (2 y · n)); a plane strip
    /// when that ruling lies in the start tangent plane.
    pub fn cylinder(start: Element, end_point: DVec3) -> Result<Self> {
        let (e, p, n) = (start.ruling, start.side, start.normal());
        let y = radial(end_point - start.point, e);
        let (yn, yp, len) = (y.dot(n), y.dot(p), y.length());
        let scale = start
            .point
            .abs()
            .max_element()
            .max(end_point.abs().max_element())
            .max(1e-300);
        if len <= 1e-12 * scale {
            return invalid!("a cylinder piece needs two different parallel rulings");
        }
        if yn.abs() <= 1e-12 * len {
            if yp <= 0.0 {
                return Err(Error::no_solution(
                    "the parallel ruling lies behind the side vector of the plane strip",
                ));
            }
            return Ok(Self {
                start,
                motion: Motion::Translation(y),
            });
        }
        let rho = len * len / (2.0 * yn);
        let origin = start.point + rho * n;
        // e × (x − o) = ρ p: a positive rotation about e moves towards +p iff ρ > 0.
        let theta0 = signed_angle(start.point - origin, start.point + y - origin, e);
        Ok(Self {
            start,
            motion: Motion::Rotation {
                origin,
                axis: e,
                angle: signed_sweep(theta0, rho > 0.0),
            },
        })
    }

    /// The last ruling with its tangent plane and moved reference point.
    pub fn end(&self) -> Element {
        self.motion.element(&self.start, 1.0)
    }

    /// The ruling at the fraction `f ∈ [0, 1]` of the piece.
    pub fn element_at(&self, f: f64) -> Element {
        self.motion.element(&self.start, f)
    }

    /// Cone, cylinder or plane: a translation is a plane strip; a rotation is a cylinder when
    /// the ruling is parallel to the axis, a plane sector when normal to it, else a cone.
    pub fn kind(&self) -> PieceKind {
        match self.motion {
            Motion::Translation(_) => PieceKind::Plane,
            Motion::Rotation { axis, .. } => {
                let c = axis.dot(self.start.ruling).abs();
                if c >= 1.0 - AXIS_TOLERANCE {
                    PieceKind::Cylinder
                } else if c <= AXIS_TOLERANCE {
                    PieceKind::Plane
                } else {
                    PieceKind::Cone
                }
            }
        }
    }

    /// The vertex (cones and plane sectors): where the start ruling meets the axis.
    pub fn vertex(&self) -> Option<DVec3> {
        match (self.motion, self.kind()) {
            (Motion::Rotation { origin, axis, .. }, PieceKind::Cone | PieceKind::Plane) => {
                // Where the ruling line meets the axis line, from the components normal to
                // the axis: |e − (e·k)k| = sin α is accurate to rounding, where 1 − (e·k)²
                // of a slender cone loses its digits (relative error ε / sin²α, the vertex
                // of a cone of α = 1e-4 moved by 1e-8 of its distance).
                let (e, w) = (self.start.ruling, self.start.point - origin);
                let (er, wr) = (radial(e, axis), radial(w, axis));
                let t = -wr.dot(er) / er.length_squared();
                Some(self.start.at(t))
            }
            _ => None,
        }
    }

    /// The unit axis direction, oriented like the rulings (k · e ≥ 0); for a plane strip the
    /// plane normal.
    pub fn axis(&self) -> DVec3 {
        match self.motion {
            Motion::Rotation { axis, .. } if axis.dot(self.start.ruling) < 0.0 => -axis,
            Motion::Rotation { axis, .. } => axis,
            Motion::Translation(_) => self.start.normal(),
        }
    }

    /// A point on the axis (the vertex of a cone, the centre line of a cylinder).
    pub fn axis_point(&self) -> Option<DVec3> {
        match self.motion {
            Motion::Rotation { origin, .. } => Some(origin),
            Motion::Translation(_) => None,
        }
    }

    /// Half opening angle α between rulings and axis: 0 for cylinders, π/2 for planes.
    pub fn half_angle(&self) -> f64 {
        match self.kind() {
            PieceKind::Cylinder => 0.0,
            PieceKind::Plane => FRAC_PI_2,
            PieceKind::Cone => {
                // atan2 keeps full precision for slender and for flat cones alike.
                angle_between(self.axis(), self.start.ruling)
            }
        }
    }

    /// Segment angle φ ≥ 0 of the rotation (0 for a plane strip).
    pub fn segment_angle(&self) -> f64 {
        match self.motion {
            Motion::Rotation { angle, .. } => angle.abs(),
            Motion::Translation(_) => 0.0,
        }
    }

    /// Radius of a cylinder (distance of the rulings from the axis); 0 otherwise.
    pub fn radius(&self) -> f64 {
        match (self.kind(), self.motion) {
            (PieceKind::Cylinder, Motion::Rotation { origin, axis, .. }) => {
                radial(self.start.point - origin, axis).length()
            }
            _ => 0.0,
        }
    }

    /// Number of degree (1, 2) patches the piece is drawn with (1 unless φ > 120°).
    pub fn patch_count(&self) -> usize {
        ((self.segment_angle() / MAX_PATCH_ANGLE).ceil() as usize).max(1)
    }

    /// The exact degree (1, 2) rational Bézier patches of the piece between the signed
    /// distances `t0 < t1` along the rulings (from the reference points): u along the
    /// rulings, v along the parallel circles; one patch per [`patch_count`](Self::patch_count).
    pub fn patches(&self, t0: f64, t1: f64) -> Result<Vec<RationalBezierPatch>> {
        self.arcs(t0)
            .into_iter()
            .zip(self.arcs(t1))
            .map(|(lower, upper)| {
                RationalBezierPatch::from_homogeneous(1, 2, [lower, upper].concat())
            })
            .collect()
    }

    /// The parallel circle at signed distance `t` along the rulings (the path of the ruling
    /// point at t), as homogeneous control points of one rational quadratic arc per patch.
    pub fn arcs(&self, t: f64) -> Vec<[DVec4; 3]> {
        let m = self.patch_count();
        let part = self.part(1.0 / m as f64);
        (0..m)
            .map(|j| arc_control_points(&part, self.element_at(j as f64 / m as f64).at(t)))
            .collect()
    }

    /// The dual form (Fig. 1): per patch (as [`patches`](Self::patches) splits the piece),
    /// the Bézier planes U₀, w₁U₁, U₂ as plane coordinates (u₁, u₂, u₃, u₀) in glam's
    /// (x, y, z, w) order, a point X on a plane iff `plane.dot(X) = 0`. U₀ and U₂ are the
    /// tangent planes at the patch's bounding rulings with unit normals; U₁ contains both
    /// bounding rulings and carries the weight w₁ = cos α / cos β as the length of its
    /// normal part, so that (1 − s)²U₀ + 2s(1 − s)w₁U₁ + s²U₂ are the tangent planes of the
    /// patch (a plane piece gives its plane three times).
    ///
    /// The tangent-plane normals n(θ) of a rotation about k turn on a circle about k: as a
    /// rational quadratic arc of half angle φ/2 the middle normal is the one at θ = φ/2
    /// with its component normal to k divided by cos(φ/2), at weight cos(φ/2) — weighted,
    /// its axial part times cos(φ/2) and its radial part unchanged. That plane contains
    /// the start ruling, so it passes through the start point.
    pub fn bezier_planes(&self) -> Vec<[DVec4; 3]> {
        let m = self.patch_count();
        let part = self.part(1.0 / m as f64);
        let plane = |n: DVec3, x: DVec3| n.extend(-n.dot(x));
        (0..m)
            .map(|j| {
                let start = self.element_at(j as f64 / m as f64);
                let end = part.element(&start, 1.0);
                let u0 = plane(start.normal(), start.point);
                let u2 = plane(end.normal(), end.point);
                let u1 = match part {
                    Motion::Rotation { axis, angle, .. } => {
                        let middle = DMat3::from_axis_angle(axis, 0.5 * angle) * start.normal();
                        let axial = middle.dot(axis) * axis;
                        plane(middle - axial + (0.5 * angle).cos() * axial, start.point)
                    }
                    Motion::Translation(_) => u0,
                };
                [u0, u1, u2]
            })
            .collect()
    }

    /// The motion restricted to its first fraction `f` (for the sub-patches).
    fn part(&self, f: f64) -> Motion {
        match self.motion {
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => Motion::Rotation {
                origin,
                axis,
                angle: f * angle,
            },
            Motion::Translation(v) => Motion::Translation(f * v),
        }
    }

    /// Distance from `y` to the piece extended along its rulings (the rulings at the
    /// sweep fractions nearest to y's angular position, on either nappe).
    pub fn distance(&self, y: DVec3) -> f64 {
        let el = &self.start;
        match self.motion {
            Motion::Translation(v) => {
                let s = (y - el.point).dot(v) / v.length_squared();
                line_distance(y, el.point + s.clamp(0.0, 1.0) * v, el.ruling)
            }
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => {
                // The reference direction: the ruling's own direction from the vertex (both
                // nappes: ψ and ψ + π), or the ruling's position for a cylinder.
                let cylinder = self.kind() == PieceKind::Cylinder;
                let reference = if cylinder {
                    radial(el.point - origin, axis)
                } else {
                    radial(el.ruling, axis)
                };
                let psi = signed_angle(reference, radial(y - origin, axis), axis);
                let candidates: &[f64] = if cylinder { &[0.0] } else { &[0.0, PI] };
                candidates
                    .iter()
                    .map(|&shift| {
                        let f = sweep_fraction(psi + shift, angle);
                        let r = self.motion.element(el, f);
                        line_distance(y, r.point, r.ruling)
                    })
                    .fold(f64::INFINITY, f64::min)
            }
        }
    }
}

/// The fraction of a rotation by `angle` nearest to the angular position `psi` (clamped to
/// [0, 1], measured in the sense of the rotation).
fn sweep_fraction(psi: f64, angle: f64) -> f64 {
    let along = (psi * angle.signum()).rem_euclid(TAU);
    let span = angle.abs();
    if along <= span {
        along / span.max(1e-300)
    } else if along - span < TAU - along {
        1.0
    } else {
        0.0
    }
}

/// Homogeneous control points of the path of `y` under `motion` as a rational quadratic:
/// y, the corner point at weight cos(φ/2), the moved point.
fn arc_control_points(motion: &Motion, y: DVec3) -> [DVec4; 3] {
    let end = motion.point(y, 1.0);
    match *motion {
        Motion::Rotation {
            origin,
            axis,
            angle,
        } => {
            let centre = origin + (y - origin).dot(axis) * axis;
            let w = (0.5 * angle).cos();
            let corner = centre + DMat3::from_axis_angle(axis, 0.5 * angle) * (y - centre) / w;
            [lift(y, 1.0), lift(corner, w), lift(end, 1.0)]
        }
        Motion::Translation(_) => [lift(y, 1.0), lift(0.5 * (y + end), 1.0), lift(end, 1.0)],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn element(point: DVec3, e: DVec3, p: DVec3) -> Element {
        Element::new(point, e, p, "el").unwrap()
    }

    #[test]
    fn cone_through_two_rulings_touches_the_start_plane() {
        // Cone x² + y² = z², vertex at the origin, rulings (1,0,1)/√2 and (0,1,1)/√2.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let start = element(DVec3::new(1.0, 0.0, 1.0), DVec3::new(s, 0.0, s), DVec3::Y);
        let piece = ConePiece::cone(DVec3::ZERO, start, DVec3::new(0.0, s, s)).unwrap();
        assert_eq!(piece.kind(), PieceKind::Cone);
        assert!((piece.axis() - DVec3::Z).length() < 1e-15);
        assert!((piece.half_angle() - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!((piece.segment_angle() - FRAC_PI_2).abs() < 1e-15);
        let end = piece.end();
        assert!((end.point - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-15);
        assert!((end.side - DVec3::new(-1.0, 0.0, 0.0)).length() < 1e-15);
        assert!(piece.vertex().unwrap().length() < 1e-15);
        // On the far nappe the same rulings are joined the other way round (Figs. 5–6).
        let far = ConePiece::cone(
            DVec3::ZERO,
            start.with_point(-start.point),
            DVec3::new(0.0, s, s),
        );
        assert!((far.unwrap().segment_angle() - 1.5 * PI).abs() < 1e-14);
        for patch in piece.patches(-0.5, 2.0).unwrap() {
            for (u, v) in [(0.0, 0.3), (0.5, 0.5), (1.0, 0.9)] {
                let x = patch.eval(u, v);
                assert!((x.x * x.x + x.y * x.y - x.z * x.z).abs() < 1e-14, "{x}");
            }
        }
        assert!(piece.distance(DVec3::new(0.6, 0.6, 0.6 * 2f64.sqrt() + 0.1)) < 0.1);
    }

    #[test]
    fn cylinders_and_strips() {
        let start = element(DVec3::new(1.0, 0.0, 0.0), DVec3::Z, DVec3::Y);
        let piece = ConePiece::cylinder(start, DVec3::new(-1.0, 0.0, 5.0)).unwrap();
        assert_eq!(piece.kind(), PieceKind::Cylinder);
        assert!((piece.radius() - 1.0).abs() < 1e-15);
        assert!((piece.segment_angle() - PI).abs() < 1e-15);
        assert_eq!(piece.patch_count(), 2);
        assert!((piece.end().side + DVec3::Y).length() < 1e-15);
        assert!((piece.distance(DVec3::new(0.0, 2.0, 3.0)) - 1.0).abs() < 1e-15);
        let strip = ConePiece::cylinder(start, DVec3::new(1.0, 2.0, 0.0)).unwrap();
        assert_eq!(strip.kind(), PieceKind::Plane);
        assert!(ConePiece::cylinder(start, DVec3::new(1.0, -2.0, 0.0)).is_err());
    }

    /// The largest departure of the curve of planes (1 − s)²U₀ + 2s(1 − s)U₁ + s²U₂ of
    /// one patch (fractions f0 … f1 of the piece) from the piece's tangent planes: at each
    /// s, the plane's unit normal against the normal of the piece's ruling at the same
    /// angle about the axis, and the distance of that ruling's points from the plane.
    fn tangency_residual(piece: &ConePiece, planes: [DVec4; 3], f0: f64, f1: f64) -> f64 {
        let Motion::Rotation { axis, angle, .. } = piece.motion else {
            return 0.0;
        };
        let n0 = radial(piece.element_at(f0).normal(), axis);
        let mut worst = 0.0f64;
        for k in 0..=16 {
            let s = k as f64 / 16.0;
            let [u0, u1, u2] = planes;
            let u = (1.0 - s) * (1.0 - s) * u0 + 2.0 * s * (1.0 - s) * u1 + s * s * u2;
            let (n, offset) = (u.truncate().normalize(), u.w / u.truncate().length());
            let theta = signed_angle(n0, radial(n, axis), axis);
            let f = f0 + theta / angle;
            assert!(
                (f0 - 1e-9..=f1 + 1e-9).contains(&f),
                "s = {s}: f = {f} not in [{f0}, {f1}]"
            );
            let el = piece.element_at(f);
            worst = worst
                .max((n - el.normal()).length())
                .max((n.dot(el.at(-1.0)) + offset).abs())
                .max((n.dot(el.at(2.0)) + offset).abs());
        }
        worst
    }

    /// Fig. 1: the dual form of cone and cylinder pieces. The weighted Bézier planes give
    /// the tangent planes of the piece, U₁ contains both bounding rulings, and its weight
    /// is cos α / cos β with α, β the angles of the axis with U₀ and with the plane through
    /// the two rulings (computed here from the rulings, not from the planes).
    #[test]
    fn bezier_planes_are_the_tangent_planes_with_weight_cos_alpha_over_cos_beta() {
        let mut pieces = super::super::test_support::cubic_hermite(&[0.3, 0.5, 0.7, 0.9])
            .pieces()
            .to_vec();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let start = element(DVec3::new(1.0, 0.0, 1.0), DVec3::new(s, 0.0, s), DVec3::Y);
        let cone = |start: Element| ConePiece::cone(DVec3::ZERO, start, DVec3::new(0.0, s, s));
        pieces.push(cone(start).unwrap());
        // 3π/2 on the far nappe: two patches.
        pieces.push(cone(start.with_point(-start.point)).unwrap());
        let axial = element(DVec3::new(1.0, 0.0, 0.0), DVec3::Z, DVec3::Y);
        pieces.push(ConePiece::cylinder(axial, DVec3::new(-1.0, 0.0, 5.0)).unwrap());
        let (mut weight, mut tangency, mut rulings) = (0.0f64, 0.0f64, 0.0f64);
        for piece in &pieces {
            let planes = piece.bezier_planes();
            let m = piece.patch_count();
            assert_eq!(planes.len(), m);
            for (j, &[u0, u1, u2]) in planes.iter().enumerate() {
                let (f0, f1) = (j as f64 / m as f64, (j + 1) as f64 / m as f64);
                let (a, b) = (piece.element_at(f0), piece.element_at(f1));
                assert!((u0.truncate().length() - 1.0).abs() < 1e-15);
                assert!((u2.truncate().length() - 1.0).abs() < 1e-15);
                let w = u1.truncate().length();
                for x in [a.at(-1.0), a.at(2.0), b.at(-1.0), b.at(2.0)] {
                    rulings = rulings.max(u1.dot(x.extend(1.0)).abs() / w);
                }
                let k = piece.axis();
                let through = match piece.kind() {
                    PieceKind::Cone => a.ruling.cross(b.ruling),
                    _ => a.ruling.cross(b.point - a.point),
                }
                .normalize();
                let alpha = k.dot(a.normal()).abs().asin();
                let beta = k.dot(through).abs().asin();
                weight = weight.max((w - alpha.cos() / beta.cos()).abs());
                tangency = tangency.max(tangency_residual(piece, [u0, u1, u2], f0, f1));
                // A weight off by 1% is not the tangent planes.
                let off = tangency_residual(piece, [u0, 1.01 * u1, u2], f0, f1);
                assert!(off > 1e-7, "a perturbed weight passes: {off:e}");
            }
        }
        println!(
            "Bézier planes of {} pieces: weight − cos α / cos β {weight:.1e}, tangency {tangency:.1e}, \
             U1 off the rulings {rulings:.1e}",
            pieces.len()
        );
        assert!(weight < 1e-12 && tangency < 1e-12 && rulings < 1e-12);
    }
}
