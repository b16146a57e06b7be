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
//! Before two patches are subdivided, their spine segments are. Every point of a lateral
//! patch is a section point x(v) + c₁f₂ + c₂f₃ with orthonormal frames normal to the
//! tangent t(v), |c| ≤ R (the profile's reach). Hence two tests, each deciding every pair of
//! patches of the two segments at once:
//! - tubes: the patch lies within R of its spine segment, so segments farther apart than
//!   2R + gap keep their patches apart (a thin profile along a spine that doubles back);
//! - slabs: along a direction d, the section point's offset from x(v) is at most
//!   R·sin∠(d, t(v)), and t(v) lies in the cone of the differences of the segment's control
//!   points; projected on d (the chord between the segments' middles), the two segments'
//!   ranges widened so must be more than the gap apart (sections along a short straight or
//!   gently bent spine, a wide profile, many turns of twist). The same test runs on the
//!   parts of the patches while they are subdivided, with the parts of their spine segments.
//!
//! Patch parts whose boxes overlap may still be apart along the line between the centres of
//! their control nets (the convex hull of the control points holds the patch). Pairs left
//! after all that are subdivided, within a budget per pair and one for the whole check.
//!
//! A leg cut by a miter reaches beyond its segment and is always compared patch by patch.
//!
//! Only lateral faces are compared. With one profile along the whole wire, another part of
//! the solid cannot pass through an end cap without crossing the lateral faces beside it:
//! its section in the cap's plane is at least as large as the cap.

use crate::bezier::{PiecewiseCurve, PiecewiseSurface, RationalBezierCurve, RationalBezierPatch};
use glam::DVec3;
use std::collections::HashMap;

/// Subdivisions one candidate pair may take before it is left undecided.
const PAIR_BUDGET: usize = 40_000;

/// Subdivisions the whole check may take (pairs of patches and of spine segments); pairs met
/// after it is spent are left undecided.
const CALL_BUDGET: usize = 250_000;

/// Subdivisions one pair of spine segments may take before it is left to the patches.
const SPINE_BUDGET: usize = 200;

/// What bounds the lateral patches of each piece: its spine on the surfaces' v-breaks (one
/// segment per patch row; `None` for a leg cut by a miter) and the profile's reach.
pub(crate) struct Tubes {
    pub spines: Vec<Option<PiecewiseCurve>>,
    pub reach: f64,
}

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
    /// The spine segment the patch lies within the reach of, unless cut by a miter.
    spine: Option<&'a RationalBezierCurve>,
    lo: DVec3,
    hi: DVec3,
}

/// The first pair of lateral patches (`surfaces[piece][loop][edge]`) that do not meet by
/// construction but come within `gap` of each other, if any. `closed`: the wire's last
/// spine segment is followed by its first.
pub(crate) fn self_contact(
    surfaces: &[Vec<Vec<PiecewiseSurface>>],
    tubes: &Tubes,
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
                    let spine = tubes.spines[piece]
                        .as_ref()
                        .filter(|c| c.segments().len() == nv)
                        .map(|c| &c.segments()[b])
                        .filter(|c| sections_reach(patch, c, tubes.reach));
                    elements.push(Element {
                        position: offset + b,
                        piece,
                        patch,
                        spine,
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
    let tube_gap = 2.0 * tubes.reach + gap;
    let mut spines_apart: HashMap<(usize, usize), bool> = HashMap::new();
    let mut undecided: Option<Contact> = None;
    let mut budget = CALL_BUDGET;
    for (i, a) in elements.iter().enumerate() {
        for b in elements[i + 1..].iter() {
            if b.lo.x > a.hi.x + gap {
                break;
            }
            if meet(a.position, b.position) || box_distance(a.lo, a.hi, b.lo, b.hi) > gap {
                continue;
            }
            if let (Some(sa), Some(sb)) = (a.spine, b.spine) {
                let key = (a.position.min(b.position), a.position.max(b.position));
                let apart = *spines_apart.entry(key).or_insert_with(|| {
                    slabs_apart(sa, sb, tubes.reach, gap)
                        || curves_apart(sa, sb, tube_gap, &mut budget)
                });
                if apart {
                    continue;
                }
            }
            let part = |e: &Element| Part::new(e.patch.clone(), e.spine.cloned(), tubes.reach);
            let mut allowance = PAIR_BUDGET.min(budget);
            let verdict = closest(part(a), part(b), gap, &mut allowance);
            budget -= PAIR_BUDGET.min(budget) - allowance;
            match verdict {
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

/// A patch, or part of one, with the part of the spine segment it is swept along (when the
/// tests on spines hold for it).
/// What pairwise subdivision needs of a piece of geometry: a box about it, points on it
/// (corners or ends), its two halves, and any test proving two pieces apart beyond their
/// boxes.
trait Subdivided<const N: usize>: Sized + Clone {
    fn bounds(&self) -> (DVec3, DVec3);
    fn samples(&self) -> [DVec3; N];
    fn halves(self) -> [Self; 2];
    fn proven_apart(&self, _other: &Self, _gap: f64) -> bool {
        false
    }
}

/// A patch, or part of one, with the part of the spine segment it is swept along (when the
/// tests on spines hold for it) and the profile's reach.
#[derive(Clone)]
struct Part {
    patch: RationalBezierPatch,
    /// The patch's projected control points, for its box and the separation test.
    points: Vec<DVec3>,
    spine: Option<RationalBezierCurve>,
    reach: f64,
}

impl Part {
    fn new(patch: RationalBezierPatch, spine: Option<RationalBezierCurve>, reach: f64) -> Self {
        Part {
            points: projected(&patch),
            patch,
            spine,
            reach,
        }
    }
}

impl Subdivided<4> for Part {
    fn bounds(&self) -> (DVec3, DVec3) {
        points_box(self.points.iter().copied())
    }

    fn samples(&self) -> [DVec3; 4] {
        corners(&self.patch)
    }

    /// Along u the sections are cut (the spine part stays), along v the spine part is cut
    /// with them.
    fn halves(self) -> [Part; 2] {
        let along_u = longer_along_u(&self.patch);
        let (left, right) = self.patch.split(along_u, 0.5);
        let spines = match (&self.spine, along_u) {
            (Some(spine), true) => (Some(spine.clone()), Some(spine.clone())),
            (Some(spine), false) => {
                let (a, b) = spine.split(0.5);
                (Some(a), Some(b))
            }
            (None, _) => (None, None),
        };
        let reach = self.reach;
        let part = |patch: RationalBezierPatch, spine: Option<RationalBezierCurve>| {
            let spine = spine.filter(|c| sections_reach(&patch, c, reach));
            Part::new(patch, spine, reach)
        };
        [part(left, spines.0), part(right, spines.1)]
    }

    fn proven_apart(&self, other: &Self, gap: f64) -> bool {
        if let (Some(a), Some(b)) = (&self.spine, &other.spine) {
            if slabs_apart(a, b, self.reach, gap) {
                return true;
            }
        }
        let (p, q) = (&self.points, &other.points);
        let centre = |points: &[DVec3]| points.iter().sum::<DVec3>() / points.len() as f64;
        (centre(q) - centre(p))
            .try_normalize()
            .is_some_and(|d| separated_along(p, q, d, gap))
    }
}

impl Subdivided<2> for RationalBezierCurve {
    fn bounds(&self) -> (DVec3, DVec3) {
        points_box(self.poles())
    }

    fn samples(&self) -> [DVec3; 2] {
        [self.eval(0.0), self.eval(1.0)]
    }

    fn halves(self) -> [Self; 2] {
        let (left, right) = self.split(0.5);
        [left, right]
    }
}

/// Whether two pieces come within `gap`: subdivision of the larger part while the boxes of
/// the parts are within `gap`, they are not proven apart otherwise and no two of their
/// sample points are within `gap`; undecided when `budget` subdivisions (counted down) are
/// spent.
fn closest<const N: usize, T: Subdivided<N>>(a: T, b: T, gap: f64, budget: &mut usize) -> Verdict {
    let mut stack = vec![(a, b)];
    let mut best = (DVec3::ZERO, DVec3::ZERO, f64::INFINITY);
    while let Some((p, q)) = stack.pop() {
        let ((plo, phi), (qlo, qhi)) = (p.bounds(), q.bounds());
        if box_distance(plo, phi, qlo, qhi) > gap || p.proven_apart(&q, gap) {
            continue;
        }
        for x in p.samples() {
            for y in q.samples() {
                let d = x.distance(y);
                if d < best.2 {
                    best = (x, y, d);
                }
            }
        }
        if best.2 <= gap {
            return Verdict::Touch(best.0, best.1, best.2);
        }
        if *budget == 0 {
            return Verdict::Undecided(best.0, best.1, best.2);
        }
        *budget -= 1;
        let (larger, other, first) = if (phi - plo).length() >= (qhi - qlo).length() {
            (p, q, true)
        } else {
            (q, p, false)
        };
        for part in larger.halves() {
            stack.push(if first {
                (part, other.clone())
            } else {
                (other.clone(), part)
            });
        }
    }
    Verdict::Apart
}

/// Whether two curves are proven farther apart than `distance`; false when they come within
/// it or their budget (at most `budget`, which is counted down) runs out.
fn curves_apart(
    a: &RationalBezierCurve,
    b: &RationalBezierCurve,
    distance: f64,
    budget: &mut usize,
) -> bool {
    let mut allowance = SPINE_BUDGET.min(*budget);
    let verdict = closest(a.clone(), b.clone(), distance, &mut allowance);
    *budget -= SPINE_BUDGET.min(*budget) - allowance;
    matches!(verdict, Verdict::Apart)
}

/// Whether the patch's corners lie within `reach` of the segment's ends at their own v (the
/// patch is swept along this segment): the tests on spines hold only then.
fn sections_reach(patch: &RationalBezierPatch, spine: &RationalBezierCurve, reach: f64) -> bool {
    let [u0v0, u0v1, u1v0, u1v1] = corners(patch);
    let (s0, s1) = (spine.eval(0.0), spine.eval(1.0));
    let slack = reach * (1.0 + 1e-9) + 1e-12 * s0.abs().max(s1.abs()).max_element();
    [(u0v0, s0), (u1v0, s0), (u0v1, s1), (u1v1, s1)]
        .iter()
        .all(|(x, s)| x.distance(*s) <= slack)
}

/// Whether the sections along two spine segments are more than `gap` apart along the
/// chord between the segments' middles (module notes).
fn slabs_apart(a: &RationalBezierCurve, b: &RationalBezierCurve, reach: f64, gap: f64) -> bool {
    let Some(d) = (b.eval(0.5) - a.eval(0.5)).try_normalize() else {
        return false;
    };
    let range = |c: &RationalBezierCurve| {
        let (lo, hi) = range_along(c.poles(), d);
        let widening = reach * sine_bound(c, d);
        (lo - widening, hi + widening)
    };
    let ((alo, ahi), (blo, bhi)) = (range(a), range(b));
    blo - ahi > gap || alo - bhi > gap
}

/// A bound on sin∠(±d, t) over the curve's tangents t: they lie in the cone of the
/// differences of its control points (positive weights); while the cone keeps within 90° of
/// d or of −d (a segment runs either way along the chord) its largest angle to that line is
/// at a generator, otherwise 1.
fn sine_bound(curve: &RationalBezierCurve, d: DVec3) -> f64 {
    let poles: Vec<DVec3> = curve.poles().collect();
    let mut sine: f64 = 0.0;
    let mut side = 0.0;
    for (k, p) in poles.iter().enumerate() {
        for q in &poles[k + 1..] {
            let Some(w) = (*q - *p).try_normalize() else {
                continue;
            };
            let along = w.dot(d);
            if side == 0.0 {
                side = along.signum();
            }
            if along * side <= 0.0 {
                return 1.0;
            }
            sine = sine.max(w.cross(d).length());
        }
    }
    sine.min(1.0)
}

/// A patch's projected control points (their convex hull holds the patch).
fn projected(patch: &RationalBezierPatch) -> Vec<DVec3> {
    patch
        .homogeneous()
        .iter()
        .map(|h| h.truncate() / h.w)
        .collect()
}

/// Whether the points' ranges along the unit direction `d` are more than `gap` apart.
fn separated_along(p: &[DVec3], q: &[DVec3], d: DVec3, gap: f64) -> bool {
    let ((plo, phi), (qlo, qhi)) = (
        range_along(p.iter().copied(), d),
        range_along(q.iter().copied(), d),
    );
    qlo - phi > gap || plo - qhi > gap
}

/// The range of the points' coordinates along `d`.
fn range_along(points: impl Iterator<Item = DVec3>, d: DVec3) -> (f64, f64) {
    points
        .map(|x| x.dot(d))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        })
}

/// The box about a patch's projected control points.
fn control_box(patch: &RationalBezierPatch) -> (DVec3, DVec3) {
    points_box(projected(patch).into_iter())
}

/// The box about points.
fn points_box(points: impl Iterator<Item = DVec3>) -> (DVec3, DVec3) {
    points.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn segment(a: DVec3, b: DVec3) -> RationalBezierCurve {
        RationalBezierCurve::polynomial(&[a, (a + b) * 0.5, b]).unwrap()
    }

    #[test]
    fn sections_of_a_straight_spine_are_apart_by_the_segments_between() {
        let (a, b) = (
            segment(DVec3::ZERO, DVec3::X),
            segment(DVec3::X * 1.5, DVec3::X * 2.5),
        );
        // However wide the profile: the normal sections are 0.5 apart.
        assert!(slabs_apart(&a, &b, 100.0, 0.49));
        assert!(!slabs_apart(&a, &b, 100.0, 0.51));
        assert!(!curves_apart(
            &a,
            &b,
            2.0 * 100.0 + 0.49,
            &mut CALL_BUDGET.clone()
        ));
        assert!(curves_apart(&a, &b, 0.49, &mut CALL_BUDGET.clone()));
    }

    #[test]
    fn sections_of_a_bent_spine_are_widened_by_the_turn_of_the_tangent() {
        // The second segment turns by 60°: its sections lean towards the first one by up to
        // reach·sin 60° along the chord.
        let a = segment(DVec3::ZERO, DVec3::X);
        let turn = DVec3::new(0.5, 3f64.sqrt() / 2.0, 0.0);
        let b = segment(DVec3::X * 2.0, DVec3::X * 2.0 + turn);
        assert!(slabs_apart(&a, &b, 0.5, 0.1));
        assert!(!slabs_apart(&a, &b, 2.0, 0.1));
        // A segment turning back on itself: the tangents leave the half-space, no bound.
        let back =
            RationalBezierCurve::polynomial(&[DVec3::X * 3.0, DVec3::X * 4.0, DVec3::X * 3.5])
                .unwrap();
        assert_eq!(sine_bound(&back, DVec3::X), 1.0);
    }

    #[test]
    fn sections_are_apart_whichever_way_the_chord_runs() {
        // Two segments of an arc of radius 5, 0.26 apart along it, sections of reach 0.09:
        // decided in either order (the chord from the later to the earlier runs against the
        // tangents).
        let arc = |t: f64| DVec3::new(5.0 * t.sin(), 5.0 * (1.0 - t.cos()), 0.0);
        let piece = |t: f64| segment(arc(t), arc(t + 0.005));
        let (early, late) = (piece(0.0), piece(0.057));
        assert!(slabs_apart(&early, &late, 0.09, 1e-7));
        assert!(slabs_apart(&late, &early, 0.09, 1e-7));
        assert_eq!(sine_bound(&early, DVec3::X), sine_bound(&early, -DVec3::X));
    }

    /// A flat patch of degree (1, 1) with the given corners (u along the first two).
    fn quad(corners: [DVec3; 4]) -> Part {
        let points = corners.iter().map(|c| c.extend(1.0)).collect();
        Part::new(
            RationalBezierPatch::from_homogeneous(1, 1, points).unwrap(),
            None,
            0.0,
        )
    }

    #[test]
    fn patches_whose_boxes_overlap_are_apart_along_the_line_between_them() {
        // Two strips along the diagonal x = y, 0.1 apart across it: their boxes overlap.
        let strip = |offset: f64| {
            let across = DVec3::new(1.0, -1.0, 0.0) * offset;
            quad([
                across,
                across + DVec3::Z,
                across + DVec3::new(1.0, 1.0, 0.0),
                across + DVec3::new(1.0, 1.0, 1.0),
            ])
        };
        let (a, b) = (strip(0.0), strip(0.1 / 2f64.sqrt()));
        let ((alo, ahi), (blo, bhi)) = (a.bounds(), b.bounds());
        assert_eq!(box_distance(alo, ahi, blo, bhi), 0.0);
        assert!(a.proven_apart(&b, 0.099));
        assert!(!a.proven_apart(&b, 0.101));
        let mut budget = CALL_BUDGET;
        assert!(matches!(closest(a, b, 0.099, &mut budget), Verdict::Apart));
        assert_eq!(budget, CALL_BUDGET, "decided without subdivision");
    }

    #[test]
    fn pairs_met_after_the_budget_is_spent_are_undecided() {
        // Two diagonal segments 1e-3 apart, a gap just below it: their boxes overlap, only
        // subdivision decides.
        let shift = DVec3::Y * 1e-3 * 2f64.sqrt();
        let diagonal = DVec3::new(1.0, 1.0, 0.0);
        let (a, b) = (
            segment(DVec3::ZERO, diagonal),
            segment(shift, diagonal + shift),
        );
        let mut budget = CALL_BUDGET;
        assert!(matches!(
            closest(a.clone(), b.clone(), 0.9e-3, &mut budget),
            Verdict::Apart
        ));
        assert!(budget < CALL_BUDGET);
        let mut spent = 0;
        assert!(matches!(
            closest(a, b, 0.9e-3, &mut spent),
            Verdict::Undecided(..)
        ));
    }
}
