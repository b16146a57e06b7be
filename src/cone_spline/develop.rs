//! Bending and development (Section "Bending sequences and development", Figs. 16–17).
//!
//! A cone segment with half angle α₀ and segment angle φ₀ bends isometrically through the
//! cone segments with αₛ → π/2 and φₛ sin αₛ = φ₀ sin α₀, the distances along the rulings
//! from the vertex unchanged; at sin α = 1 it is the flat sector of angle φ₀ sin α₀. A
//! cylinder segment bends through cylinders with radius r/(1 − s) and angle φ(1 − s) (its
//! arc length r φ kept) into a strip of width r φ. Plane pieces stay as they are.
//!
//! All pieces are bent at once and laid edge to edge: each bent piece starts on the bent
//! end ruling (and tangent plane) of the one before, at the same place along the ruling, so
//! vertex distances, ruling lengths and parallel-circle boundaries are kept — a spatial arc
//! spline boundary becomes a planar arc spline in the development.

use super::element::Element;
use super::piece::{ConePiece, Motion, PieceKind};
use super::spline::ConeSpline;
use crate::error::{invalid, Result};
use crate::math::power_of_two_scale;
use glam::{DMat3, DVec3};
use std::f64::consts::FRAC_PI_2;

/// The piece bent to the stage `s ∈ [0, 1]`, started on the element `start`.
fn bend_piece(piece: &ConePiece, start: Element, s: f64) -> ConePiece {
    let (e, n) = (start.ruling, start.normal());
    let old = &piece.start;
    let motion = match (piece.kind(), piece.motion) {
        (PieceKind::Cone, Motion::Rotation { axis, angle, .. }) => {
            let vertex_at = old.parameter_of(piece.vertex().expect("a cone has a vertex"));
            let alpha0 = piece.half_angle();
            let alpha = alpha0 + s * (FRAC_PI_2 - alpha0);
            // The axis keeps its side: k = cos β e + sin β n with sin β > 0, cos β = ±cos α.
            let forward = axis.dot(old.ruling).signum();
            let bent_axis = forward * alpha.cos() * e + alpha.sin() * n;
            Motion::Rotation {
                origin: start.at(vertex_at),
                axis: bent_axis.normalize(),
                angle: angle * alpha0.sin() / alpha.sin(),
            }
        }
        (PieceKind::Cylinder, Motion::Rotation { origin, angle, .. }) => {
            // Centre at signed distance ρ along n from the ruling; curvature scaled by 1 − s.
            let rho = (origin - old.point).dot(old.normal());
            if s >= 1.0 {
                Motion::Translation(rho.abs() * angle.abs() * start.side)
            } else {
                let axis = if piece.motion_axis_along_ruling() {
                    e
                } else {
                    -e
                };
                Motion::Rotation {
                    origin: start.point + rho / (1.0 - s) * n,
                    axis,
                    angle: angle * (1.0 - s),
                }
            }
        }
        (_, Motion::Rotation { angle, axis, .. }) => {
            // A plane sector: the same rotation about the normal through the vertex.
            let vertex_at = old.parameter_of(piece.vertex().expect("a sector has a vertex"));
            Motion::Rotation {
                origin: start.at(vertex_at),
                axis: axis.dot(old.normal()).signum() * n,
                angle,
            }
        }
        (_, Motion::Translation(v)) => Motion::Translation(v.length() * start.side),
    };
    ConePiece { start, motion }
}

impl ConePiece {
    /// Whether a cylinder's rotation axis points along its rulings (else against them).
    fn motion_axis_along_ruling(&self) -> bool {
        match self.motion {
            Motion::Rotation { axis, .. } => axis.dot(self.start.ruling) > 0.0,
            Motion::Translation(_) => true,
        }
    }

    /// The piece moved by the rigid motion x ↦ R x + shift.
    fn transformed(&self, rotation: DMat3, shift: DVec3) -> Self {
        self.similar(rotation, 1.0, shift)
    }

    /// The piece mapped by the similarity x ↦ scale · R x + shift (R a rotation,
    /// scale > 0): directions and angles are kept, points and translations scaled.
    pub(crate) fn similar(&self, rotation: DMat3, scale: f64, shift: DVec3) -> Self {
        let start = Element::from_frame(
            scale * (rotation * self.start.point) + shift,
            rotation * self.start.ruling,
            rotation * self.start.side,
        );
        let motion = match self.motion {
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => Motion::Rotation {
                origin: scale * (rotation * origin) + shift,
                axis: rotation * axis,
                angle,
            },
            Motion::Translation(v) => Motion::Translation(scale * (rotation * v)),
        };
        Self { start, motion }
    }
}

impl ConeSpline {
    /// The stage `s ∈ [0, 1]` of the bending sequence: s = 0 is this spline, s = 1 the flat
    /// development lying in the tangent plane of the first ruling. The first ruling and its
    /// tangent plane stay fixed.
    pub fn bent(&self, s: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&s) {
            return invalid!("the bending parameter s = {s} must lie in [0, 1]");
        }
        let mut start = self.first();
        let mut pieces = Vec::with_capacity(self.pieces().len());
        for piece in self.pieces() {
            let bent = bend_piece(piece, start, s);
            start = bent.end();
            pieces.push(bent);
        }
        Self::new(pieces)
    }

    /// The exact development: the flat stage of the bending sequence moved into the plane
    /// z = 0 with the first reference point at the origin, e₁ along +x and p₁ along +y (so
    /// n₁ = +z: the development is seen from the side the normals point to).
    pub fn developed(&self) -> Result<Self> {
        let (unit, scale) = self.unit_size()?;
        let flat = unit.developed_unit()?;
        Self::new(
            flat.pieces()
                .iter()
                .map(|p| p.similar(DMat3::IDENTITY, scale, DVec3::ZERO))
                .collect(),
        )
    }

    /// The spline moved to the origin and scaled by a power of two to unit size, with that
    /// scale: the development is the same up to the scale (it starts at the origin), and
    /// computed there none of its products overflow or underflow.
    pub(crate) fn unit_size(&self) -> Result<(Self, f64)> {
        let points = self.pieces().iter().flat_map(|p| {
            let end = p.end().point;
            [p.start.point, end]
        });
        let (lo, hi) = points.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p), hi.max(p))
        });
        let centre = 0.5 * lo + 0.5 * hi;
        let scale = 1.0 / power_of_two_scale(0.5 * hi - 0.5 * lo);
        let pieces = self
            .pieces()
            .iter()
            .map(|p| p.similar(DMat3::IDENTITY, 1.0 / scale, -centre / scale))
            .collect();
        Ok((Self::new(pieces)?, scale))
    }

    /// [`Self::developed`] of a unit-size spline.
    fn developed_unit(&self) -> Result<Self> {
        let flat = self.bent(1.0)?;
        let first = flat.first();
        let rotation = DMat3::from_cols(first.ruling, first.side, first.normal()).transpose();
        let shift = -(rotation * first.point);
        Self::new(
            flat.pieces()
                .iter()
                .map(|p| p.transformed(rotation, shift))
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::super::developable::Developable;
    use super::super::pair::Rule;
    use super::super::test_support::{cubic_hermite, tangent_surface, twisted_cubic, Helix};
    use super::*;

    fn splines() -> Vec<ConeSpline> {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.4,
            domain: (0.0, 7.0),
        };
        let helical = tangent_surface(&helix, 4.0, 5.0);
        let elements: Vec<_> = [0.0, 0.8, 1.6, 2.4]
            .iter()
            .map(|&t| helical.element(t).unwrap())
            .collect();
        let curve = twisted_cubic(0.2, 1.2);
        let cubic = tangent_surface(&curve, 2.0, 3.0);
        let cylinders: Vec<_> = [0.3, 0.5, 0.7, 0.9]
            .iter()
            .map(|&t| cubic.element(t).unwrap())
            .collect();
        vec![
            cubic_hermite(&[0.3, 0.5, 0.7, 0.9]),
            ConeSpline::hermite(&elements, Rule::MinimalVertexDistance, None)
                .unwrap()
                .0,
            ConeSpline::hermite(&cylinders, Rule::CylinderFirst, None)
                .unwrap()
                .0,
        ]
    }

    #[test]
    fn bending_keeps_lengths_and_angles_and_ends_flat() {
        for spline in splines() {
            let (t0, t1) = (-0.25, 0.25);
            let reference = spline.surface(t0, t1).unwrap();
            let unbent = spline.bent(0.0).unwrap().surface(t0, t1).unwrap();
            for k in 0..=40 {
                let v = reference.domain_v().1 * k as f64 / 40.0;
                let gap = (unbent.eval(t1, v) - reference.eval(t1, v)).length();
                // Bending rebuilds each piece on the end frame of the one before: s = 0 reproduces
                // the input up to the round-off of its G1 junctions (~1e-11 rad × lever arms).
                assert!(gap < 1e-9, "{gap:e} at {v}");
            }
            for s in [0.5, 1.0] {
                let bent = spline.bent(s).unwrap();
                let surface = bent.surface(t0, t1).unwrap();
                for t in [t0, t1] {
                    let (a, b) = (
                        spline.boundary(t).unwrap().arc_length(),
                        bent.boundary(t).unwrap().arc_length(),
                    );
                    assert!(
                        (a - b).abs() < 1e-12 * a,
                        "boundary length {a} → {b} at s = {s}"
                    );
                }
                for (k, &v) in reference.v_breaks().iter().enumerate() {
                    let (p, q) = (reference.eval_jet(t0, v), surface.eval_jet(t0, v));
                    let angle =
                        |j: &crate::bezier::SurfaceJet| crate::math::angle_between(j.du, j.dv);
                    assert!((angle(&p) - angle(&q)).abs() < 1e-9, "angle at ruling {k}");
                }
                for (p, q) in spline.pieces().iter().zip(bent.pieces()) {
                    let expected = p.segment_angle() * p.half_angle().sin();
                    if p.kind() == crate::cone_spline::PieceKind::Cone {
                        assert!(
                            (q.segment_angle() * q.half_angle().sin() - expected).abs() < 1e-12
                        );
                    }
                }
            }
            let flat = spline.developed().unwrap();
            let surface = flat.surface(t0, t1).unwrap();
            for patch in surface.patches() {
                assert!(patch
                    .homogeneous()
                    .iter()
                    .all(|h| h.z.abs() < 1e-12 * h.w.abs().max(1.0)));
            }
        }
    }
}
