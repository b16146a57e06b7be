//! Whether a sweep touches itself away from where its faces meet by construction.
//!
//! The singularity margin (Mäurer & Jüttler Cor. 7, [`super::frame`]) rules out folds near
//! every section; a wire that comes back within the profile's reach of itself (a crossing,
//! a coil wound too tightly) is a global matter, decided here. The lateral patches are
//! numbered by their spine segment along the wire: patches of the same or of consecutive
//! segments meet by construction (shared edges, a section's loops) and are covered by the
//! margin; every other pair must stay farther apart than the gap — the join tolerance,
//! below which a kernel takes two faces for one.
//!
//! Candidate pairs come from boxes about the patches' control points (a rational patch with
//! positive weights lies in the convex hull of its projected control points), swept along
//! x. Each candidate is decided by subdivision: the boxes of the parts bound their distance
//! from below, their corner points (which lie on the surface) from above.
//!
//! Only lateral faces are compared. With one profile along the whole wire, another part of
//! the solid cannot pass through an end cap without crossing the lateral faces beside it:
//! its section in the cap's plane is at least as large as the cap.

use crate::bezier::{PiecewiseSurface, RationalBezierPatch};
use glam::DVec3;

/// Subdivisions one candidate pair may take before it is left undecided.
const PAIR_BUDGET: usize = 40_000;

/// Two points of the sweep closer than the gap, on patches that do not meet by
/// construction.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Contact {
    /// The pieces (indices into the transport) of the two patches.
    pub pieces: (usize, usize),
    /// A point on each (coordinates of the surfaces given).
    pub points: (DVec3, DVec3),
    /// Their distance; `decided` is false when subdivision stopped at its budget with the
    /// distance between `gap` and this (the patches may still be apart).
    pub distance: f64,
    pub decided: bool,
}

/// One lateral patch with its place along the wire.
struct Element<'a> {
    /// The spine segment, numbered along the whole wire.
    position: usize,
    piece: usize,
    patch: &'a RationalBezierPatch,
    lo: DVec3,
    hi: DVec3,
}

/// The first pair of lateral patches (`surfaces[piece][loop][edge]`) that do not meet by
/// construction but come within `gap` of each other, if any. `closed`: the wire's last
/// spine segment is followed by its first.
pub(crate) fn self_contact(
    surfaces: &[Vec<Vec<PiecewiseSurface>>],
    closed: bool,
    gap: f64,
) -> Option<Contact> {
    let mut elements = Vec::new();
    let mut offset = 0;
    for (piece, loops) in surfaces.iter().enumerate() {
        let mut segments = 0;
        for face in loops.iter().flatten() {
            let (nu, nv) = (face.u_breaks().len() - 1, face.v_breaks().len() - 1);
            segments = segments.max(nv);
            for a in 0..nu {
                for b in 0..nv {
                    let patch = face.patch(a, b);
                    let (lo, hi) = control_box(patch);
                    elements.push(Element {
                        position: offset + b,
                        piece,
                        patch,
                        lo,
                        hi,
                    });
                }
            }
        }
        offset += segments;
    }
    let total = offset;
    let meet = |a: usize, b: usize| {
        let d = a.abs_diff(b);
        d <= 1 || (closed && total - d <= 1)
    };
    elements.sort_by(|a, b| a.lo.x.total_cmp(&b.lo.x));
    let mut undecided: Option<Contact> = None;
    for (i, a) in elements.iter().enumerate() {
        for b in elements[i + 1..].iter() {
            if b.lo.x > a.hi.x + gap {
                break;
            }
            if meet(a.position, b.position) || box_distance(a.lo, a.hi, b.lo, b.hi) > gap {
                continue;
            }
            match closest_below(a.patch, b.patch, gap) {
                Verdict::Apart => {}
                Verdict::Touch(pa, pb, distance) => {
                    return Some(Contact {
                        pieces: (a.piece, b.piece),
                        points: (pa, pb),
                        distance,
                        decided: true,
                    })
                }
                Verdict::Undecided(pa, pb, distance) => {
                    undecided = undecided.or(Some(Contact {
                        pieces: (a.piece, b.piece),
                        points: (pa, pb),
                        distance,
                        decided: false,
                    }));
                }
            }
        }
    }
    undecided
}

enum Verdict {
    Apart,
    Touch(DVec3, DVec3, f64),
    Undecided(DVec3, DVec3, f64),
}

/// Whether two patches come within `gap`: subdivision of the larger part while the boxes
/// of the parts are within `gap` and their corners are not.
fn closest_below(a: &RationalBezierPatch, b: &RationalBezierPatch, gap: f64) -> Verdict {
    let mut stack = vec![(a.clone(), b.clone())];
    let mut best = (DVec3::ZERO, DVec3::ZERO, f64::INFINITY);
    let mut budget = PAIR_BUDGET;
    while let Some((p, q)) = stack.pop() {
        let ((plo, phi), (qlo, qhi)) = (control_box(&p), control_box(&q));
        if box_distance(plo, phi, qlo, qhi) > gap {
            continue;
        }
        for x in corners(&p) {
            for y in corners(&q) {
                let d = x.distance(y);
                if d < best.2 {
                    best = (x, y, d);
                }
            }
        }
        if best.2 <= gap {
            return Verdict::Touch(best.0, best.1, best.2);
        }
        if budget == 0 {
            return Verdict::Undecided(best.0, best.1, best.2);
        }
        budget -= 1;
        let (larger, other, first) = if (phi - plo).length() >= (qhi - qlo).length() {
            (p, q, true)
        } else {
            (q, p, false)
        };
        let (left, right) = larger.split(longer_along_u(&larger), 0.5);
        for part in [left, right] {
            stack.push(if first {
                (part, other.clone())
            } else {
                (other.clone(), part)
            });
        }
    }
    Verdict::Apart
}

/// The box about a patch's projected control points.
fn control_box(patch: &RationalBezierPatch) -> (DVec3, DVec3) {
    patch
        .homogeneous()
        .iter()
        .map(|h| h.truncate() / h.w)
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p), hi.max(p))
        })
}

/// The distance between two boxes (0 when they overlap).
fn box_distance(alo: DVec3, ahi: DVec3, blo: DVec3, bhi: DVec3) -> f64 {
    (alo - bhi).max(blo - ahi).max(DVec3::ZERO).length()
}

/// The four corner points of a patch (its corner control points, on the surface).
fn corners(patch: &RationalBezierPatch) -> [DVec3; 4] {
    let (m, n) = (patch.degree_u(), patch.degree_v());
    [(0, 0), (0, n), (m, 0), (m, n)].map(|(i, j)| {
        let h = patch.at(i, j);
        h.truncate() / h.w
    })
}

/// Whether the patch's control net is longer along u than along v (its edges' chords).
fn longer_along_u(patch: &RationalBezierPatch) -> bool {
    let [c00, c0n, cm0, cmn] = corners(patch);
    c00.distance(cm0) + c0n.distance(cmn) >= c00.distance(c0n) + cm0.distance(cmn)
}
