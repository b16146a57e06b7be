//! Marks carried between the flat pattern and the formed part — holes, slots, text
//! outlines, fold marks — by the exact isometry of the development, both ways.
//!
//! A point is named on every layer by the same coordinates: the piece k, the fraction f of
//! the piece's motion and the distance ρ along its ruling from the reference point (layers
//! are offsets along the normals with the same motions, [LP] "Introduction"). On the
//! developed piece the same (k, f, ρ) is the point at angle f·φ sin α about the developed
//! vertex ([LP] "Bending sequences and development": φ sin α = const), so the maps are
//! closed forms — rotations and a 2 × 2 solve — and never go through the NURBS parameters
//! (a piece and its development have different rational arcs: equal parameters are not
//! corresponding points).

use super::trim::{offset_piece, parameter_of_fraction, TrimmedSpline};
use crate::cone_spline::{ConePiece, Motion};
use crate::math::signed_angle;
use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

/// Coordinates of a point of a part: piece, fraction of the motion, distance along the
/// ruling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PartPoint {
    pub piece: usize,
    pub f: f64,
    pub rho: f64,
}

/// How far (in length) (f, ρ) lies outside the trimmed piece `k`: 0 inside.
fn outside(part: &TrimmedSpline, k: usize, f: f64, rho: f64, arc_length: f64) -> f64 {
    let along = if f < 0.0 {
        -f * arc_length
    } else if f > 1.0 {
        (f - 1.0) * arc_length
    } else {
        0.0
    };
    let v = parameter_of_fraction(part_angle(&part.pieces()[k]), f.clamp(0.0, 1.0));
    let (r0, r1) = (part.trims[k][0].eval(v), part.trims[k][1].eval(v));
    let across = if rho < r0.min(r1) {
        r0.min(r1) - rho
    } else if rho > r0.max(r1) {
        rho - r0.max(r1)
    } else {
        0.0
    };
    along.max(across)
}

/// The angle a piece's arc parameter is measured against (0 for translations).
pub(crate) fn part_angle(piece: &ConePiece) -> f64 {
    match piece.motion {
        Motion::Rotation { .. } => piece.segment_angle(),
        Motion::Translation(_) => 0.0,
    }
}

/// Candidate (f, ρ) of the planar point `q` on a developed piece (z = 0).
fn developed_coordinates(piece: &ConePiece, q: DVec3) -> Vec<(f64, f64)> {
    let el = piece.start;
    match piece.motion {
        Motion::Translation(t) => {
            // q − l = f t + ρ e with t ⊥ e.
            let d = q - el.point;
            if t.length_squared() == 0.0 {
                return vec![(0.0, d.dot(el.ruling))];
            }
            vec![(d.dot(t) / t.length_squared(), d.dot(el.ruling))]
        }
        Motion::Rotation {
            origin,
            axis,
            angle,
        } => {
            // The rulings pass through the developed vertex o: q − o = (λ₀ + ρ) R(fφ) e₀.
            let lambda0 = (el.point - origin).dot(el.ruling);
            let d = q - origin;
            let r = d.length();
            if r == 0.0 {
                return vec![(0.0, -lambda0)];
            }
            [1.0, -1.0]
                .iter()
                .map(|&nappe| {
                    let psi = signed_angle(el.ruling, nappe * d / r, axis);
                    let along = (psi * angle.signum()).rem_euclid(TAU);
                    // Nearest representative of the angle to the piece's range.
                    let along = if along > angle.abs() + (TAU - angle.abs()) / 2.0 {
                        along - TAU
                    } else {
                        along
                    };
                    (along / angle.abs(), nappe * r - lambda0)
                })
                .collect()
        }
    }
}

/// Candidate (f, ρ) and distance of the spatial point `y` on a formed piece.
fn formed_coordinates(piece: &ConePiece, y: DVec3) -> Vec<(f64, f64)> {
    let el = piece.start;
    match piece.motion {
        Motion::Translation(t) => {
            let d = y - el.point;
            let f = if t.length_squared() == 0.0 {
                0.0
            } else {
                d.dot(t) / t.length_squared()
            };
            vec![(f, d.dot(el.ruling))]
        }
        Motion::Rotation {
            origin,
            axis,
            angle,
        } => {
            let radial = |v: DVec3| v - v.dot(axis) * axis;
            // The reference direction: the ruling's own (cones, both nappes), or the
            // ruling's position about the axis (cylinders).
            let cylinder = el.ruling.cross(axis).length() < 1e-12;
            let (reference, shifts): (DVec3, &[f64]) = if cylinder {
                (radial(el.point - origin), &[0.0])
            } else {
                (radial(el.ruling), &[0.0, PI])
            };
            let target = radial(y - origin);
            if reference.length() == 0.0 || target.length() == 0.0 {
                return vec![(0.0, (y - el.point).dot(el.ruling))];
            }
            let psi = signed_angle(reference, target, axis);
            shifts
                .iter()
                .map(|&shift| {
                    let along = ((psi + shift) * angle.signum()).rem_euclid(TAU);
                    let along = if along > angle.abs() + (TAU - angle.abs()) / 2.0 {
                        along - TAU
                    } else {
                        along
                    };
                    let f = along / angle.abs();
                    let moved = piece.element_at(f);
                    (f, (y - moved.point).dot(moved.ruling))
                })
                .collect()
        }
    }
}

/// Arc length of a piece's motion at distance `rho` (for measuring f outside [0, 1]).
fn arc_length(piece: &ConePiece, rho: f64) -> f64 {
    let a = piece.element_at(0.0).at(rho);
    let b = piece.element_at(1.0).at(rho);
    a.distance(b).max(1e-300)
}

/// The part point at the flat point `q` of the development `developed` (same pieces as
/// the part), accepted up to `slack` outside the trimmed pieces; `None` outside.
pub(crate) fn flat_to_part(
    part: &TrimmedSpline,
    developed: &[ConePiece],
    q: DVec2,
    slack: f64,
) -> Option<PartPoint> {
    let mut best: Option<(f64, PartPoint)> = None;
    for (k, piece) in developed.iter().enumerate() {
        for (f, rho) in developed_coordinates(piece, q.extend(0.0)) {
            let out = outside(part, k, f, rho, arc_length(piece, rho));
            if best.is_none_or(|(b, _)| out < b) {
                best = Some((out, PartPoint { piece: k, f, rho }));
            }
            if out == 0.0 {
                return best.map(|(_, p)| p);
            }
        }
    }
    best.filter(|(out, _)| *out <= slack).map(|(_, p)| p)
}

/// The part point nearest to `y` on the layer at distance `s`, and its distance; the
/// coordinates clamped to the trimmed pieces.
pub(crate) fn surface_to_part(part: &TrimmedSpline, s: f64, y: DVec3) -> (PartPoint, f64) {
    let mut best = (
        PartPoint {
            piece: 0,
            f: 0.0,
            rho: 0.0,
        },
        f64::INFINITY,
    );
    for (k, formed) in part.pieces().iter().enumerate() {
        let piece = offset_piece(formed, s);
        for (f, rho) in formed_coordinates(&piece, y) {
            let f = f.clamp(0.0, 1.0);
            let v = parameter_of_fraction(part_angle(formed), f);
            let (r0, r1) = (part.trims[k][0].eval(v), part.trims[k][1].eval(v));
            let rho = rho.clamp(r0.min(r1), r0.max(r1));
            let d = piece.element_at(f).at(rho).distance(y);
            if d < best.1 {
                best = (PartPoint { piece: k, f, rho }, d);
            }
        }
    }
    best
}

/// The flat point of a part point on the development.
pub(crate) fn part_to_flat(developed: &[ConePiece], p: PartPoint) -> DVec2 {
    developed[p.piece].element_at(p.f).at(p.rho).truncate()
}

/// The spatial point and unit normal n = e × p of a part point on the layer at `s`.
pub(crate) fn part_to_surface(part: &TrimmedSpline, p: PartPoint, s: f64) -> (DVec3, DVec3) {
    let el = offset_piece(&part.pieces()[p.piece], s).element_at(p.f);
    (el.at(p.rho), el.normal())
}
