//! The flat pattern of a part for the cutter: the exact development of one layer ([LP]
//! "Bending sequences and development": each cone piece becomes the plane sector of angle
//! φ sin α about its developed vertex, cylinders and strips parallelograms), with the
//! part's boundary drawn as lines and circular arcs only.
//!
//! A point of piece k at the fraction f of its motion and distance ρ along the ruling
//! develops to the point at the same f and ρ of the developed piece — the angle scaling
//! φ ↦ φ sin α is linear, so fractions correspond, while the rational arc parameters of a
//! piece and of its development do not (their arcs have different angles). A boundary
//! given as ρ(v) over the arc parameter v of the formed piece is therefore drawn at
//! f(v) = θ(v)/φ, θ the angle of the standard rational quadratic arc.
//!
//! What develops into lines and arcs exactly: a constant ρ (a vertex, a parallel circle)
//! into an arc about the developed vertex or a segment of a strip; a plane section of a
//! plane piece into a segment; the rulings into segments. Every other boundary is
//! replaced by G1 biarcs (Fuhs & Stachel, eqs. (7)–(8) of [LP], [`biarc`]) within the flat
//! tolerance. The outline is closed (every edge starts where the one before ends) and
//! counter-clockwise; the bend lines are the rulings where pieces meet.
//!
//! [`biarc`]: crate::cone_spline::biarc

use super::thickness::bend_sign;
use super::trim::{fraction_of_parameter, fraction_rate, TrimKind, TrimmedSpline};
use crate::cone_spline::{ConePiece, Motion};
use crate::error::Result;
use crate::model::planar::{biarcs, close_loop, POINT_LENGTH};
use crate::model::{FlatPattern, PatternEdge};
use glam::{DVec2, DVec3};

/// A developed boundary curve over the formed piece's arc parameter v: point and
/// derivative.
struct Developed<'a> {
    piece: &'a ConePiece,
    /// The formed piece's angle φ (0 for translations), for v ↦ f.
    angle: f64,
    trim: &'a super::trim::Trim,
}

impl Developed<'_> {
    fn at(&self, v: f64) -> (DVec2, DVec2) {
        let f = fraction_of_parameter(self.angle, v);
        let el = self.piece.element_at(f);
        let rho = self.trim.eval(v);
        // d/df of the moved point and ruling: ω × (x − o), ω × e for a rotation ω.
        let (dp, de) = match self.piece.motion {
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => {
                let w = axis * angle;
                (w.cross(el.point - origin), w.cross(el.ruling))
            }
            Motion::Translation(t) => (t, DVec3::ZERO),
        };
        let d =
            (dp + rho * de) * fraction_rate(self.angle, v) + self.trim.derivative(v) * el.ruling;
        ((el.point + rho * el.ruling).truncate(), d.truncate())
    }
}

/// The edges of one developed boundary (trim `side` of piece `k`), in the direction of v.
fn boundary_edges(
    part: &TrimmedSpline,
    developed: &[ConePiece],
    k: usize,
    side: usize,
    tolerance: f64,
    scale: f64,
    out: &mut Vec<PatternEdge>,
) -> Result<()> {
    let formed = &part.pieces()[k];
    let piece = &developed[k];
    let trim = &part.trims[k][side];
    let curve = Developed {
        piece,
        angle: match formed.motion {
            Motion::Rotation { .. } => formed.segment_angle(),
            Motion::Translation(_) => 0.0,
        },
        trim,
    };
    let (a, b) = (curve.at(0.0).0, curve.at(1.0).0);
    match (trim.kind, piece.motion) {
        (
            TrimKind::Constant,
            Motion::Rotation {
                origin,
                axis,
                angle,
            },
        ) => {
            let centre = origin.truncate();
            let radius = (a - centre).length();
            if radius > POINT_LENGTH {
                out.push(PatternEdge::Arc {
                    center: centre,
                    radius,
                    from: a,
                    to: b,
                    sweep: angle * axis.z.signum(),
                });
            }
        }
        (TrimKind::Constant, Motion::Translation(_)) => {
            out.push(PatternEdge::Line { from: a, to: b })
        }
        (TrimKind::Plane, _) if bend_sign(formed) == 0.0 => {
            out.push(PatternEdge::Line { from: a, to: b })
        }
        _ => biarcs(&|v| curve.at(v), 0.0, 1.0, tolerance, scale, out)?,
    }
    Ok(())
}

/// The developed boundaries of a layer, before they are joined into the outline: the
/// first and the second boundary in the direction of the pieces, the first and the last
/// ruling (from the first to the second boundary), the bend lines.
pub(crate) struct FlatLayout {
    pub first: Vec<PatternEdge>,
    pub second: Vec<PatternEdge>,
    pub rulings: [PatternEdge; 2],
    pub bend_lines: Vec<PatternEdge>,
}

impl FlatLayout {
    /// The closed outline: first boundary, last ruling, second boundary backwards, first
    /// ruling backwards; point-like edges dropped, round-off gaps closed, counter-clockwise.
    pub(crate) fn pattern(&self) -> FlatPattern {
        let mut outline = self.first.clone();
        outline.push(self.rulings[1]);
        outline.extend(self.second.iter().rev().map(PatternEdge::reversed));
        outline.push(self.rulings[0].reversed());
        // Internal coordinates are of unit size.
        let mut pattern = FlatPattern {
            outline: close_loop(outline, 1.0),
            holes: vec![],
            bend_lines: self.bend_lines.clone(),
        };
        if pattern.area().is_ok_and(|a| a < 0.0) {
            pattern.outline = pattern
                .outline
                .iter()
                .rev()
                .map(PatternEdge::reversed)
                .collect();
        }
        pattern
    }
}

/// The developed boundaries of the layer at distance `s` along the normals (internal units;
/// `scale` turns them into the caller's for messages).
pub(crate) fn flat_layout(
    part: &TrimmedSpline,
    s: f64,
    tolerance: f64,
    scale: f64,
) -> Result<FlatLayout> {
    let developed = part.spline.offset(s)?.developed()?;
    let pieces = developed.pieces();
    let n = pieces.len();
    let (mut first, mut second) = (Vec::new(), Vec::new());
    for k in 0..n {
        boundary_edges(part, pieces, k, 0, tolerance, scale, &mut first)?;
        boundary_edges(part, pieces, k, 1, tolerance, scale, &mut second)?;
    }
    // Developed ruling of piece k at v = 0 (k = n: the end of the last piece).
    let ruling = |k: usize| {
        let (piece, f, v) = if k < n {
            (k, 0.0, 0.0)
        } else {
            (n - 1, 1.0, 1.0)
        };
        let el = pieces[piece].element_at(f);
        let at = |side: usize| (el.point + part.trims[piece][side].eval(v) * el.ruling).truncate();
        PatternEdge::Line {
            from: at(0),
            to: at(1),
        }
    };
    Ok(FlatLayout {
        first,
        second,
        rulings: [ruling(0), ruling(n)],
        bend_lines: (1..n)
            .map(ruling)
            .filter(|e| e.length() > POINT_LENGTH)
            .collect(),
    })
}
