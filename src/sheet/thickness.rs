//! Sheet thickness and the K-factor. The designed surface is one face of a sheet of
//! thickness t; the others are its exact offsets ([LP] "Introduction": offsets of cone
//! splines are cone splines — same axes and half angles, vertices moved along the axes).
//! Where the sheet bends, the *inner* face is the one on the concave side (towards the
//! axes), and the neutral layer, which keeps its length when the flat blank is formed, lies
//! at k·t from the inner face (0 ≤ k ≤ 1; 0.5 is the mid-surface, sharp bends of soft
//! steel are nearer 0.33 — see docs/sheet-metal.md for a table). The flat pattern is the
//! development of the neutral layer.
//!
//! Distances are measured along m, the unit normal from the concave to the convex side, so
//! that the inner face is at s = s_in and the others at s_in + k·t and s_in + t. A face
//! towards the concave side (s < 0) is regular only nearer than the smallest bend radius —
//! ρ tan α on a cone at distance ρ from its vertex, the radius of a cylinder, 0 at a crease
//! or at a vertex on the part's edge; beyond it the offset passes its vertex (a cusp).

use super::trim::{Trim, TrimmedSpline};
use crate::cone_spline::{ConePiece, PieceKind};
use crate::error::{invalid, Result};

/// Which face of the sheet the designed surface (through the user's curves or rails) is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reference {
    /// The inner face (concave side): the sheet lies on the convex side.
    Inner,
    /// The neutral layer.
    Neutral,
    /// The outer face (convex side): the sheet lies towards the bend centres.
    Outer,
}

/// A surface of the formed sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layer {
    /// The designed surface itself.
    Reference,
    /// The inner face (the concave side of the bends).
    Inner,
    /// The neutral layer, at k·t from the inner face: the one the flat pattern develops.
    Neutral,
    /// The outer face.
    Outer,
}

/// The sheet: thickness t, K-factor k and where the designed surface lies in it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sheet {
    /// Thickness t, > 0.
    pub thickness: f64,
    /// K-factor k, 0 ≤ k ≤ 1: the neutral layer lies at k·t from the inner face.
    pub k_factor: f64,
    /// Which face of the sheet the designed surface is.
    pub reference: Reference,
}

impl Sheet {
    /// Checks the numbers: 0 < t < ∞, 0 ≤ k ≤ 1.
    pub fn new(thickness: f64, k_factor: f64, reference: Reference) -> Result<Self> {
        if !(thickness.is_finite() && thickness > 0.0) {
            return invalid!("thickness = {thickness} must be finite and positive");
        }
        if !(0.0..=1.0).contains(&k_factor) {
            return invalid!("k_factor = {k_factor} must lie in [0, 1] (the neutral layer lies within the sheet)");
        }
        Ok(Self {
            thickness,
            k_factor,
            reference,
        })
    }
}

/// The layers of a part: signed offsets along the pieces' normals n = e × p.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Layers {
    /// +1 when the convex side is +n, −1 when it is −n.
    pub sign: f64,
    /// Offset of the inner face along m (≤ 0 when it lies towards the bend centres).
    pub inner: f64,
    pub thickness: f64,
    pub k_factor: f64,
}

impl Layers {
    /// The offset of `layer` along the normals n.
    pub(crate) fn offset(&self, layer: Layer) -> f64 {
        let along_m = match layer {
            Layer::Reference => return 0.0,
            Layer::Inner => self.inner,
            Layer::Neutral => self.inner + self.k_factor * self.thickness,
            Layer::Outer => self.inner + self.thickness,
        };
        self.sign * along_m
    }
}

/// How a piece bends: +1 when it curves away from its normal n (convex side +n), −1
/// towards it, 0 for planes (the normal's turn across the piece against the side vector;
/// below 1e-9 rad a piece is a plane: sectors built on the round-off of a G1 chain are
/// cones of half angle π/2 − 1e-13).
pub(crate) fn bend_sign(piece: &ConePiece) -> f64 {
    let turn = piece.end().normal().dot(piece.start.side);
    if turn.abs() <= 1e-9 {
        0.0
    } else {
        turn.signum()
    }
}

/// The pieces `k` and `j` of a part that bend to opposite sides, if any.
pub(crate) fn bends_both_ways(pieces: &[ConePiece]) -> Option<(usize, usize)> {
    let signs: Vec<f64> = pieces.iter().map(bend_sign).collect();
    let k = signs.iter().position(|&s| s > 0.0)?;
    let j = signs.iter().position(|&s| s < 0.0)?;
    Some((k, j))
}

/// The smallest bend radius of a piece over the trimmed part (sampled along the piece):
/// distance from the vertex × tan α on a cone, the radius on a cylinder (0 at a crease),
/// infinite on a plane.
pub(crate) fn bend_radius(piece: &ConePiece, trims: &[Trim; 2]) -> f64 {
    match piece.kind() {
        PieceKind::Plane => f64::INFINITY,
        PieceKind::Cylinder => piece.radius(),
        PieceKind::Cone => {
            let Some(v) = piece.vertex() else {
                return f64::INFINITY;
            };
            let rho = piece.start.parameter_of(v);
            let nearest = (0..=32)
                .flat_map(|j| {
                    trims
                        .iter()
                        .map(move |t| (t.eval(j as f64 / 32.0) - rho).abs())
                })
                .fold(f64::INFINITY, f64::min);
            // A vertex within rounding of the trim is on the edge (a corner cone trimmed at
            // its corner): the part is at unit size here, its parameters near 1.
            if nearest <= 16.0 * f64::EPSILON * rho.abs().max(1.0) {
                return 0.0;
            }
            nearest * piece.half_angle().tan()
        }
    }
}

/// The layers of `part` for `sheet`, refusing parts that bend both ways and inner faces
/// beyond the smallest bend radius; `scale` converts internal lengths to the caller's.
pub(crate) fn layers(part: &TrimmedSpline, sheet: &Sheet, scale: f64) -> Result<Layers> {
    let t = sheet.thickness / scale;
    let signs: Vec<f64> = part.pieces().iter().map(bend_sign).collect();
    let first = signs.iter().position(|&s| s > 0.0);
    let other = signs.iter().position(|&s| s < 0.0);
    if let (Some(i), Some(j)) = (first, other) {
        return invalid!(
            "the part bends to both sides of its surface (piece {i} one way, piece {j} the other): \
             its inner side, and the K-factor's neutral layer with it, is not defined; \
             split the part at its inflection rulings"
        );
    }
    let sign = if other.is_some() { -1.0 } else { 1.0 };
    let inner = match sheet.reference {
        Reference::Inner => 0.0,
        Reference::Neutral => -sheet.k_factor * t,
        Reference::Outer => -t,
    };
    if inner < 0.0 {
        let (k, radius) = part
            .pieces()
            .iter()
            .zip(&part.trims)
            .enumerate()
            .filter(|(k, _)| signs[*k] != 0.0)
            .map(|(k, (p, tr))| (k, bend_radius(p, tr)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, f64::INFINITY));
        if -inner >= radius {
            return invalid!(
                "thickness = {} puts the inner face {:.6} towards the bend centres (reference {:?}), \
                 but the smallest bend radius of the part is {:.6} (piece {k}): the inner face would pass \
                 a cone vertex; make the designed surface the inner face or the sheet thinner",
                sheet.thickness,
                -inner * scale,
                sheet.reference,
                radius * scale
            );
        }
    }
    Ok(Layers {
        sign,
        inner,
        thickness: t,
        k_factor: sheet.k_factor,
    })
}
