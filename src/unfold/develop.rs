//! The isometry from a face onto the plane, both ways (internal coordinates).
//!
//! * A plane: its own coordinates.
//! * A circular cylinder of radius R: (R θ, z), θ the angle about the axis, z along it.
//! * A right cone of half angle α: the point at distance ρ from the apex and angle θ about
//!   the axis goes to ρ (cos θ sin α, sin θ sin α) — the sector of angle φ sin α of [LP]
//!   "Bending sequences and development".
//! * Any other developable: its cone spline ([LP] "G1 Hermite elements", fitted between
//!   the surface's rails within half the tolerance, `crate::sheet` rails), each point
//!   developed through the piece, fraction of the motion and distance along the ruling of
//!   its nearest point on the spline (the exact development of the spline, as the marks of
//!   a sheet part).
//!
//! On a cylinder or a cone θ is measured from a cut: a seam of the face, or the middle of
//! the widest angle its boundary leaves free; θ ∈ [0, 2π). A point on the cut itself is at
//! 0 or at 2π, which the caller chooses by continuity along the boundary.

use super::kind::Recognized;
use crate::cone_spline::ConeSpline;
use crate::error::Result;
use crate::sheet::marks::{flat_to_part, part_to_flat, part_to_surface, surface_to_part};
use crate::sheet::trim::TrimmedSpline;
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// Angles within this of the cut are on it.
const ON_CUT: f64 = 1e-9;
/// Points within this of a cone's apex are on the cut too: the apex develops to the same
/// flat point from either side, and its angle is only round-off (a seam's end sample there
/// must not decide on which side of the cut the seam lies).
const AT_APEX: f64 = 1e-9;

/// A face's development (internal coordinates).
#[derive(Clone, Debug)]
pub(crate) enum Development {
    Plane {
        origin: DVec3,
        x: DVec3,
        y: DVec3,
    },
    /// A cylinder (`sin` = None) or a cone about an axis; angles from `x` turned by `cut`.
    Round {
        origin: DVec3,
        axis: DVec3,
        x: DVec3,
        y: DVec3,
        cut: f64,
        radius: f64,
        sin: Option<f64>,
    },
    /// A cone spline's development; `layer` is the offset along the pieces' normals of the
    /// layer developed and formed (0: the spline itself).
    Spline {
        part: TrimmedSpline,
        developed: ConeSpline,
        layer: f64,
    },
}

/// A flat point and whether it lies on the cut (so that 2π·scale may be added or removed).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FlatPoint {
    pub point: DVec2,
    pub on_cut: bool,
}

impl Development {
    /// The development of a plane, a cylinder or a cone with the cut at angle `cut` from
    /// its `x` (unused for planes); `None` for the other kinds.
    pub(super) fn analytic(shape: &Recognized, cut: f64) -> Option<Self> {
        Some(match *shape {
            Recognized::Plane { origin, x, y } => Development::Plane { origin, x, y },
            Recognized::Cylinder {
                origin,
                axis,
                x,
                radius,
            } => Development::Round {
                origin,
                axis,
                x,
                y: axis.cross(x),
                cut,
                radius,
                sin: None,
            },
            Recognized::Cone { apex, axis, x, sin } => Development::Round {
                origin: apex,
                axis,
                x,
                y: axis.cross(x),
                cut,
                radius: 0.0,
                sin: Some(sin),
            },
            _ => return None,
        })
    }

    /// The angle of `p` about the axis of a round face from its `x` (not from the cut).
    pub(super) fn raw_angle(p: DVec3, origin: DVec3, x: DVec3, y: DVec3) -> f64 {
        let d = p - origin;
        d.dot(y).atan2(d.dot(x))
    }

    /// The flat point of `p` (on the face); on a cut, the point at angle 0.
    pub(super) fn flat(&self, p: DVec3) -> FlatPoint {
        match self {
            Development::Plane { origin, x, y } => FlatPoint {
                point: DVec2::new((p - *origin).dot(*x), (p - *origin).dot(*y)),
                on_cut: false,
            },
            Development::Round {
                origin,
                axis,
                x,
                y,
                cut,
                radius,
                sin,
            } => {
                let theta = (Self::raw_angle(p, *origin, *x, *y) - cut).rem_euclid(TAU);
                let at_apex = sin.is_some() && (p - *origin).length() <= AT_APEX;
                let on_cut = theta <= ON_CUT || theta >= TAU - ON_CUT || at_apex;
                let theta = if theta >= TAU - ON_CUT { 0.0 } else { theta };
                let point = match sin {
                    None => DVec2::new(radius * theta, (p - *origin).dot(*axis)),
                    // The foot of p on its ruling: p itself on the cone, its nearest point
                    // off it.
                    Some(s) => {
                        let ruling = Self::ruling(*axis, *x, *y, theta + cut, *s);
                        DVec2::from_angle(theta * s) * (p - *origin).dot(ruling).max(0.0)
                    }
                };
                FlatPoint { point, on_cut }
            }
            Development::Spline {
                part, developed, ..
            } => {
                let (at, _) = surface_to_part(part, 0.0, p);
                FlatPoint {
                    point: part_to_flat(developed.pieces(), at),
                    on_cut: false,
                }
            }
        }
    }

    /// The unit ruling of a cone of half angle α (sin α = `sin`) at angle `angle` from `x`.
    fn ruling(axis: DVec3, x: DVec3, y: DVec3, angle: f64, sin: f64) -> DVec3 {
        let cos = (1.0 - sin * sin).max(0.0).sqrt();
        cos * axis + sin * (angle.cos() * x + angle.sin() * y)
    }

    /// The unit normal at (the foot of) `p` that offsets move along: a plane's x × y, a
    /// cylinder's or cone's away from the axis, a cone spline piece's e × p.
    pub(super) fn normal(&self, p: DVec3) -> DVec3 {
        match self {
            Development::Plane { x, y, .. } => x.cross(*y),
            Development::Round {
                origin,
                axis,
                x,
                y,
                sin,
                ..
            } => {
                let angle = Self::raw_angle(p, *origin, *x, *y);
                let radial = angle.cos() * *x + angle.sin() * *y;
                match sin {
                    None => radial,
                    Some(s) => {
                        let cos = (1.0 - s * s).max(0.0).sqrt();
                        cos * radial - s * *axis
                    }
                }
            }
            Development::Spline { part, .. } => {
                let (at, _) = surface_to_part(part, 0.0, p);
                part_to_surface(part, at, 0.0).1
            }
        }
    }

    /// The development of the surface offset by `s` along [`Self::normal`], taking each
    /// point of this surface (and of its offsets) to the foot of its normal there: a plane
    /// moves (its flat points stay), a cylinder's radius grows by s, a cone's apex moves by −s / sin α along its
    /// axis (its rulings by s cot α), a cone spline's pieces are offset ([LP]
    /// "Introduction").
    pub(super) fn offset(&self, s: f64) -> Result<Self> {
        Ok(match self {
            Development::Plane { origin, x, y } => Development::Plane {
                origin: *origin + s * x.cross(*y),
                x: *x,
                y: *y,
            },
            Development::Round {
                origin,
                axis,
                x,
                y,
                cut,
                radius,
                sin,
            } => Development::Round {
                origin: match sin {
                    None => *origin,
                    Some(sin) => *origin - (s / sin) * *axis,
                },
                axis: *axis,
                x: *x,
                y: *y,
                cut: *cut,
                radius: if sin.is_none() { radius + s } else { 0.0 },
                sin: *sin,
            },
            Development::Spline { part, layer, .. } => Development::Spline {
                part: part.clone(),
                developed: part.spline.offset(layer + s)?.developed()?,
                layer: layer + s,
            },
        })
    }

    /// The flat point at the other end of the cut from `q` (a point at angle 0).
    pub(super) fn across_cut(&self, q: DVec2) -> DVec2 {
        match self {
            Development::Round {
                radius, sin: None, ..
            } => q + DVec2::X * radius * TAU,
            Development::Round { sin: Some(s), .. } => DVec2::from_angle(TAU * s).rotate(q),
            _ => q,
        }
    }

    /// The formed point of the flat point `q`, `None` where the development has no point
    /// (beyond the apex of a cone, outside a cone spline's pieces by more than `slack`).
    pub(super) fn formed(&self, q: DVec2, slack: f64) -> Option<DVec3> {
        match self {
            Development::Plane { origin, x, y } => Some(*origin + q.x * *x + q.y * *y),
            Development::Round {
                origin,
                axis,
                x,
                y,
                cut,
                radius,
                sin,
            } => {
                let (theta, along) = match sin {
                    None => (q.x / radius, q.y),
                    Some(s) => (q.to_angle().rem_euclid(TAU) / s, q.length()),
                };
                let angle = theta + cut;
                Some(match sin {
                    None => {
                        *origin + radius * (angle.cos() * *x + angle.sin() * *y) + along * *axis
                    }
                    Some(s) => *origin + along * Self::ruling(*axis, *x, *y, angle, *s),
                })
            }
            Development::Spline {
                part,
                developed,
                layer,
            } => {
                let at = flat_to_part(part, developed.pieces(), q, slack)?;
                Some(part_to_surface(part, at, *layer).0)
            }
        }
    }
}
