//! Transition pieces between two closed convex planar curves (square-to-round, rectangle-
//! to-round, round-to-round with offset or inclined planes, obround, any convex curves):
//! the lateral surface of the convex hull of the two curves, the developable that joins
//! them — the classical construction of the sheet-metal layout books (triangulation of a
//! transition piece: flat triangles from straight edges to a point of the other curve,
//! "conical" fans from a corner to an arc, and between two smooth curves the rulings
//! joining points with a common tangent plane; for parallel planes, points with parallel
//! tangents).
//!
//! Every supporting plane H of the hull touches both curves: it contains a supporting line
//! of the bottom curve A (outward normal angle θ in A's plane) and is the plane of that
//! pencil, ν(β) = cos β·d_A(θ) + sin β·n_A, that touches B with B on its inner side —
//! the root of f(β) = max_{x∈B} ν(β)·(x − a) (found by safeguarded Newton; f′ = ν′·(x* − a)
//! at the maximiser x*). Walking θ once around A, the contacts run once around both
//! curves; the Gauss maps of A and B ([`profile`](super::profile)) cut the walk into
//!
//! * a corner P of A against an arc of B: a cone with vertex P (rulings P → B),
//! * an arc of A against a corner Q of B: a cone with vertex Q,
//! * an arc against an arc: a general developable,
//! * a corner against a corner: a crease along PQ (a bend of zero inner radius),
//! * at an edge of A or B: a planar triangle (or, edge against edge, a planar quadrilateral).
//!
//! The planar pieces are exact plane sectors; the cones and general developables are
//! approximated within the tolerance by cone splines [LP] (the cone case of the G1 cone
//! pairs, a common vertex and spherical biarcs (7)–(8), for the corner cones; the general
//! case (5)–(12) between two arcs), G1 everywhere except at creases. Each piece is trimmed
//! exactly: by the planes of the two curves (plane sections) or at the vertex it shares
//! with a curve. The seam, where the flat pattern is cut open, is the middle ruling of the
//! largest planar piece (the classical seam in the middle of a flat side), or the shortest
//! ruling when there is none.

use super::profile::{ConvexProfile, FeatureKind};
use super::thickness::bends_both_ways;
use super::trim::{split_long_pieces, Similarity, Trim, TrimmedSpline};
use crate::bezier::PiecewiseCurve;
use crate::cone_spline::approximate::{fit, FitError};
use crate::cone_spline::developable::{Developable, Ruling};
use crate::cone_spline::{ConePiece, ConeSpline, Element, Motion, Rule};
use crate::error::{invalid, no_solution, Error, Result};
use crate::math::signed_angle;
use glam::DVec3;
use std::f64::consts::TAU;

/// Normal angles closer than this (radians) are one event of the walk.
const MERGE_ANGLE: f64 = 1e-10;
/// Contacts before and after an event closer than this (relative to the curves' size, as
/// the profiles' geometry tolerance) are one point: the same joint of two smooth features,
/// computed on either.
const CONTACT_JUMP: f64 = 1e-9;
/// Samples of the walk used to bracket the events of the top curve.
const WALK_SAMPLES: usize = 720;
/// How often the fit tolerance is halved to bring the edges within the tolerance.
const REFITS: usize = 6;

/// Normals of the two curves' planes closer than this (|n_A × n_B|) are parallel: within
/// the rounding of the normals computed from the curves, so that a transition between
/// parallel planes contacts both curves at the same normal angle, as it should.
const PARALLEL_PLANES: f64 = 1e-13;
/// The smallest height of one curve over the plane of the other, relative to the curves'
/// size (beyond their own distances from their planes): far above the rounding of the
/// heights (a few ε of the coordinates), so that the side of every point is certain.
const MIN_HEIGHT: f64 = 64.0 * f64::EPSILON;
/// Most steps of the support iteration of [`Hull::touch`].
const TOUCH_STEPS: usize = 100;

/// The two curves, oriented: A's normal points towards B, B's away from A; both are
/// traversed counter-clockwise about their normals.
///
/// Heights over A's plane are computed with the curves taken as exactly planar: the height
/// of a point x of B's plane is h₀ + (x − o_B)·τ, τ the part of A's normal in B's plane
/// (0 for parallel planes) — accurate to rounding of the height itself, where the 3-D
/// difference n_A·(x − a) would carry ε of the coordinates, which for a flat transition is
/// most of the height.
pub(crate) struct Hull {
    pub a: ConvexProfile,
    pub b: ConvexProfile,
    /// Height of B's plane origin over A's plane.
    h0: f64,
    /// The part of A's normal in B's plane (3-D, and in B's plane coordinates).
    tilt: DVec3,
    tilt_b: [f64; 2],
}

/// The heights of `q`'s points over the plane of `p` (smallest, largest), with `q` taken as
/// exactly planar.
fn height_range(p: &ConvexProfile, q: &ConvexProfile) -> (f64, f64) {
    let (h0, tilt) = placement(p, q);
    if tilt == DVec3::ZERO {
        return (h0, h0);
    }
    let at = |x: DVec3| h0 + (x - q.plane.origin).dot(tilt);
    (at(q.support_3d(-tilt)), at(q.support_3d(tilt)))
}

/// h₀ and τ of `q`'s plane over `p`'s (see [`Hull`]).
fn placement(p: &ConvexProfile, q: &ConvexProfile) -> (f64, DVec3) {
    let (n, m) = (p.plane.normal, q.plane.normal);
    let h0 = p.plane.height(q.plane.origin);
    if n.cross(m).length() <= PARALLEL_PLANES {
        return (h0, DVec3::ZERO);
    }
    (h0, n - n.dot(m) * m)
}

impl Hull {
    /// The hull between `bottom` and `top` (internal coordinates); `scale` turns internal
    /// lengths into the caller's for the messages.
    pub(super) fn new(bottom: &PiecewiseCurve, top: &PiecewiseCurve, scale: f64) -> Result<Self> {
        let mut a = ConvexProfile::new(bottom, "bottom")?;
        let mut b = ConvexProfile::new(top, "top")?;
        // The curves' own distances from their planes, and a margin far above the rounding.
        let gap = a.flatness + b.flatness + MIN_HEIGHT * (a.size + b.size);
        let side = |lo: f64, hi: f64, which: &str, other: &str| -> Result<f64> {
            if lo > gap {
                return Ok(1.0);
            }
            if hi < -gap {
                return Ok(-1.0);
            }
            let message = if lo < -gap && hi > gap {
                format!(
                    "the curves cross: {which} reaches {:.3e} and {:.3e} from the plane of {other} \
                     (each curve must lie strictly on one side of the other's plane)",
                    lo * scale,
                    hi * scale
                )
            } else {
                format!(
                    "{which} comes within {:.3e} of the plane of {other} (it reaches {:.3e} to {:.3e} \
                     from it): each curve must lie on one side of the other's plane by more than \
                     {:.3e}, the curves' distances from their own planes and 64 roundings of their size \
                     (the heights below that are rounding)",
                    lo.abs().min(hi.abs()) * scale,
                    lo * scale,
                    hi * scale,
                    gap * scale
                )
            };
            invalid!("{message}")
        };
        let (lo, hi) = height_range(&a, &b);
        if side(lo, hi, "top", "bottom")? < 0.0 {
            a = a.flipped();
        }
        let (lo, hi) = height_range(&b, &a);
        if side(lo, hi, "bottom", "top")? > 0.0 {
            b = b.flipped();
        }
        let (h0, tilt) = placement(&a, &b);
        let tilt_b = [tilt.dot(b.plane.x), tilt.dot(b.plane.y)];
        Ok(Self {
            a,
            b,
            h0,
            tilt,
            tilt_b,
        })
    }

    /// The height over A's plane of a point of B.
    fn height(&self, x: DVec3) -> f64 {
        self.h0 + (x - self.b.plane.origin).dot(self.tilt)
    }

    /// The supporting plane through A's supporting line with normal angle `theta` (through
    /// its point `p`) that touches B: its outward unit normal ν and B's normal angle φ at
    /// the contact.
    ///
    /// The plane is ν ∝ H·d − D·n_A for the point x of B it passes through, D = d·(x − p)
    /// and H = x's height over A's plane: the contact minimises −D/H over B (the plane
    /// rotated about the line until it touches), found by Dinkelbach's iteration — the plane
    /// through the support point of the previous plane — which decreases −D/H at every step
    /// and ends at the minimum (after one step on a corner, superlinearly on an arc). B's
    /// normal angle comes from the in-plane part H·d_B − D·τ_B of ν in B's coordinates,
    /// never from a projection of the unit ν, which for a flat transition (ν nearly n_A)
    /// would cancel to ε / slope.
    pub(super) fn touch(&self, theta: f64, p: DVec3) -> (DVec3, f64) {
        let (d, n) = (self.a.plane.direction(theta), self.a.plane.normal);
        let d_b = [d.dot(self.b.plane.x), d.dot(self.b.plane.y)];
        let angle = |(dd, hh): (f64, f64)| {
            let w = [
                hh * d_b[0] - dd * self.tilt_b[0],
                hh * d_b[1] - dd * self.tilt_b[1],
            ];
            w[1].atan2(w[0])
        };
        let measure = |phi: f64| {
            let x = self.b.support(phi);
            (d.dot(x - p), self.height(x))
        };
        // Start from the vertical plane ν = d.
        let mut phi = d_b[1].atan2(d_b[0]);
        let mut best = measure(phi);
        for _ in 0..TOUCH_STEPS {
            let next_phi = angle(best);
            let next = measure(next_phi);
            // −D'/H' < −D/H, with H, H' > 0.
            if best.0 * next.1 < next.0 * best.1 {
                best = next;
                phi = next_phi;
            } else {
                phi = next_phi;
                break;
            }
        }
        let _ = phi;
        let (dd, hh) = best;
        ((hh * d - dd * n).normalize(), angle(best))
    }

    /// The outward normal of the supporting plane through A's supporting line with normal
    /// angle `theta` (through its point `p`) that touches B.
    pub(super) fn plane_normal(&self, theta: f64, p: DVec3) -> DVec3 {
        self.touch(theta, p).0
    }

    /// B's normal angle at the contact of the supporting plane at A's normal angle `theta`.
    fn b_angle_at(&self, theta: f64) -> f64 {
        self.touch(theta, self.a.support(theta)).1
    }

    /// The supporting plane's normal at A's normal angle `theta`.
    fn normal_at(&self, theta: f64) -> DVec3 {
        self.plane_normal(theta, self.a.support(theta))
    }
}

/// An event of the walk around A: a normal angle where a feature of A or of B begins,
/// with the edges that lie in the supporting plane there.
#[derive(Clone, Debug)]
struct Event {
    theta: f64,
    a_edge: Option<(DVec3, DVec3)>,
    b_edge: Option<(DVec3, DVec3)>,
}

/// One item of the walk, clockwise (outward normals e × p with e from A to B).
#[derive(Clone, Debug)]
enum Segment {
    /// A plane piece from the ruling `from` (A point, B point) to `to`, in the plane with
    /// outward normal `normal`.
    Planar {
        from: (DVec3, DVec3),
        to: (DVec3, DVec3),
        normal: DVec3,
    },
    /// The part of the hull between the normal angles `hi` > `lo` of A, on A's feature
    /// `fa` and B's feature `fb`.
    Strip {
        hi: f64,
        lo: f64,
        fa: usize,
        fb: usize,
    },
}

/// How a piece is trimmed on one side.
#[derive(Clone, Copy, Debug)]
enum TrimSpec {
    /// By the plane of the curve on that side.
    Plane,
    /// At a point on the ruling (a corner of a curve: a vertex on the curve).
    Point(DVec3),
}

/// The hull between A's normal angles `hi` (start) and `lo` as a developable, for the cone
/// spline fit: parameter t = hi − θ.
struct HullStrip<'a> {
    hull: &'a Hull,
    hi: f64,
    lo: f64,
    fa: usize,
    fb: usize,
}

impl HullStrip<'_> {
    fn contacts(&self, t: f64) -> (DVec3, DVec3, DVec3) {
        let theta = self.hi - t;
        let p = self.hull.a.feature_point(self.fa, theta);
        let (nu, phi) = self.hull.touch(theta, p);
        let q = self.hull.b.feature_point(self.fb, phi);
        (p, q, nu)
    }
}

impl HullStrip<'_> {
    /// The smallest sine of the angle between the strip's tangent planes and the planes of
    /// the curves (sampled at 17 rulings).
    fn smallest_edge_sine(&self) -> f64 {
        let (na, nb) = (self.hull.a.plane.normal, self.hull.b.plane.normal);
        (0..=16)
            .map(|j| {
                let nu = self.contacts((self.hi - self.lo) * j as f64 / 16.0).2;
                nu.cross(na).length().min(nu.cross(nb).length())
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The ruling at `t` as its two ends, in the caller's coordinates.
    fn describe(&self, t: f64, frame: &Similarity) -> String {
        let (p, q, _) = self.contacts(t);
        format!("{} – {}", frame.to_user(p), frame.to_user(q))
    }
}

impl Developable for HullStrip<'_> {
    fn domain(&self) -> (f64, f64) {
        (0.0, self.hi - self.lo)
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        let (p, q, nu) = self.contacts(t);
        let d = q - p;
        let length = d.length();
        if length.is_nan() || length <= 0.0 {
            return no_solution!("a ruling of the transition has zero length");
        }
        Ok(Ruling {
            point: 0.5 * (p + q),
            direction: d / length,
            normal: nu,
            range: (-0.5 * length, 0.5 * length),
        })
    }
}

/// The element of the ruling from `a` to `b` in the plane with outward normal `normal`.
fn element(a: DVec3, b: DVec3, normal: DVec3) -> Element {
    let e = (b - a).normalize();
    let n = (normal - normal.dot(e) * e).normalize();
    Element::from_frame(0.5 * (a + b), e, n.cross(e))
}

/// What the transition construction reports besides the part.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TransitionFit {
    /// Largest sampled distance of the cone spline from the hull surface.
    pub deviation: f64,
    /// Largest sampled distance of the part's edges from the bottom and the top curve.
    pub edge_distance: [f64; 2],
    /// The fit tolerance that reached them (the tolerance halved as often as needed).
    pub fit_tolerance: f64,
}

impl Hull {
    /// The events of the walk around A, sorted and merged, in [θ₀, θ₀ + 2π).
    fn events(&self) -> Result<Vec<Event>> {
        let a = &self.a;
        let start = a.start();
        let mut events: Vec<Event> = a
            .features
            .iter()
            .map(|f| Event {
                theta: a.wrap(f.from),
                a_edge: match f.kind {
                    FeatureKind::Edge(p, q) => Some((p, q)),
                    _ => None,
                },
                b_edge: None,
            })
            .collect();
        // B's contact angle along the walk, unwrapped; it must advance once around B.
        let thetas: Vec<f64> = (0..=WALK_SAMPLES)
            .map(|j| start + TAU * j as f64 / WALK_SAMPLES as f64)
            .collect();
        let mut phis: Vec<f64> = Vec::with_capacity(thetas.len());
        for &t in &thetas {
            let phi = self.b_angle_at(t);
            let phi = match phis.last() {
                None => phi,
                Some(&last) => phi - ((phi - last) / TAU).round() * TAU,
            };
            phis.push(phi);
        }
        let advance = phis[phis.len() - 1] - phis[0];
        if (advance - TAU).abs() > 1e-6 || phis.windows(2).any(|w| w[1] < w[0] - 1e-9) {
            return no_solution!(
                "the supporting planes do not walk once around the top curve (they turn by {advance:.6} rad)"
            );
        }
        for g in &self.b.features {
            let target = phis[0] + (g.from - phis[0]).rem_euclid(TAU);
            let j = phis
                .windows(2)
                .position(|w| w[0] <= target && target <= w[1])
                .unwrap_or(0);
            let phi_at = |t: f64| {
                let phi = self.b_angle_at(t);
                phi - ((phi - phis[j]) / TAU).round() * TAU
            };
            let (mut lo, mut hi) = (thetas[j], thetas[j + 1]);
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if phi_at(mid) < target {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            events.push(Event {
                theta: a.wrap(0.5 * (lo + hi)),
                a_edge: None,
                b_edge: match g.kind {
                    FeatureKind::Edge(p, q) => Some((p, q)),
                    _ => None,
                },
            });
        }
        events.sort_by(|x, y| x.theta.total_cmp(&y.theta));
        let mut merged: Vec<Event> = Vec::new();
        for e in events {
            match merged.last_mut() {
                Some(last) if e.theta - last.theta < MERGE_ANGLE => {
                    last.a_edge = last.a_edge.or(e.a_edge);
                    last.b_edge = last.b_edge.or(e.b_edge);
                }
                _ => merged.push(e),
            }
        }
        if merged.len() > 1 {
            let last = merged[merged.len() - 1].clone();
            if merged[0].theta + TAU - last.theta < MERGE_ANGLE {
                merged[0].a_edge = merged[0].a_edge.or(last.a_edge);
                merged[0].b_edge = merged[0].b_edge.or(last.b_edge);
                merged.pop();
            }
        }
        Ok(merged)
    }

    /// The contacts on A and B just above (`after = false`) or below an event, walking
    /// clockwise: edges are crossed from their counter-clockwise end to the other.
    fn contacts_at(&self, event: &Event, after: bool) -> (DVec3, DVec3) {
        let a = match event.a_edge {
            Some((p, q)) => {
                if after {
                    p
                } else {
                    q
                }
            }
            None => self.a.support(event.theta),
        };
        let b = match event.b_edge {
            Some((p, q)) => {
                if after {
                    p
                } else {
                    q
                }
            }
            None => self.b.support(self.b_angle_at(event.theta)),
        };
        (a, b)
    }

    /// The walk, clockwise, as segments, rotated to start at the seam.
    fn segments(&self) -> Result<Vec<Segment>> {
        let events = self.events()?;
        let m = events.len();
        let mut walk = Vec::new();
        for k in (0..m).rev() {
            let (lo, hi) = (
                events[k].theta,
                if k + 1 < m {
                    events[k + 1].theta
                } else {
                    events[0].theta + TAU
                },
            );
            let mid = 0.5 * (lo + hi);
            let fa = self.a.feature_at(mid);
            let fb = self.b.feature_at(self.b_angle_at(mid));
            walk.push(Segment::Strip { hi, lo, fa, fb });
            let (before, after) = (
                self.contacts_at(&events[k], false),
                self.contacts_at(&events[k], true),
            );
            let jump = CONTACT_JUMP * self.a.size.max(self.b.size);
            if before.0.distance(after.0) > jump || before.1.distance(after.1) > jump {
                walk.push(Segment::Planar {
                    from: before,
                    to: after,
                    normal: self.normal_at(events[k].theta),
                });
            }
        }
        Ok(start_at_seam(walk, self))
    }
}

/// Area of a planar segment's quadrilateral (or triangle).
fn planar_area(from: (DVec3, DVec3), to: (DVec3, DVec3)) -> f64 {
    0.5 * (to.1 - from.0).cross(to.0 - from.1).length()
}

/// The point where the ray `origin + t·direction` meets the line through `p` and `q`
/// (all in one plane with normal `n`).
fn meet(origin: DVec3, direction: DVec3, p: DVec3, q: DVec3, n: DVec3) -> DVec3 {
    let t = (p - origin).cross(q - p).dot(n) / direction.cross(q - p).dot(n);
    origin + t * direction
}

/// The middle ruling of a planar segment: through the middle of its A side (or its A
/// point), along the sector's rulings.
fn middle_ruling(from: (DVec3, DVec3), to: (DVec3, DVec3), n: DVec3) -> (DVec3, DVec3) {
    let mid_a = 0.5 * (from.0 + to.0);
    if from.0 == to.0 {
        return (from.0, 0.5 * (from.1 + to.1));
    }
    if from.1 == to.1 {
        return (mid_a, from.1);
    }
    let (d0, d1) = (from.1 - from.0, to.1 - to.0);
    let direction = if d0.cross(d1).length() <= 1e-12 * d0.length() * d1.length() {
        d0
    } else {
        // The sector's vertex: where the two rulings' lines meet.
        let vertex = meet(from.0, d0, to.0, to.1, n);
        mid_a - vertex
    };
    (mid_a, meet(mid_a, direction, from.1, to.1, n))
}

/// Rotates the walk to begin at the seam: the middle ruling of the largest planar piece
/// (split there), or else the event with the shortest ruling.
fn start_at_seam(walk: Vec<Segment>, hull: &Hull) -> Vec<Segment> {
    let largest = walk
        .iter()
        .enumerate()
        .filter_map(|(k, s)| match s {
            Segment::Planar { from, to, .. } => Some((k, planar_area(*from, *to))),
            _ => None,
        })
        .max_by(|x, y| x.1.total_cmp(&y.1));
    if let Some((k, _)) = largest {
        let Segment::Planar { from, to, normal } = walk[k].clone() else {
            unreachable!("a planar segment")
        };
        let mid = middle_ruling(from, to, normal);
        let mut out = vec![Segment::Planar {
            from: mid,
            to,
            normal,
        }];
        out.extend(walk[k + 1..].iter().cloned());
        out.extend(walk[..k].iter().cloned());
        out.push(Segment::Planar {
            from,
            to: mid,
            normal,
        });
        return out;
    }
    // No planar piece: start at the strip boundary with the shortest ruling.
    let length = |s: &Segment| match s {
        Segment::Strip { hi, .. } => {
            let p = hull.a.support(*hi);
            p.distance(hull.b.support(hull.touch(*hi, p).1))
        }
        Segment::Planar { .. } => f64::INFINITY,
    };
    let k = (0..walk.len())
        .min_by(|&i, &j| length(&walk[i]).total_cmp(&length(&walk[j])))
        .unwrap_or(0);
    let mut out = walk[k..].to_vec();
    out.extend(walk[..k].iter().cloned());
    out
}

/// The pieces and trim specifications of the walk, joined G1 (creases excepted), with the
/// largest fit deviation.
fn pieces(
    hull: &Hull,
    walk: &[Segment],
    tolerance: f64,
    max_pieces: usize,
    frame: &Similarity,
    goal: f64,
    first: bool,
) -> Result<Fitted> {
    let too_many = || {
        Error::not_converged(format!(
            "the transition needs more than max_pieces = {max_pieces} pieces at the fit \
             tolerance {:.3e}",
            tolerance * frame.scale
        ))
    };
    let mut pieces: Vec<ConePiece> = Vec::new();
    let mut specs: Vec<[TrimSpec; 2]> = Vec::new();
    let mut deviation = 0.0f64;
    let mut finest = tolerance;
    for segment in walk {
        let previous = pieces.last().map(ConePiece::end);
        match segment {
            Segment::Planar { from, to, normal } => {
                let start = previous.unwrap_or_else(|| element(from.0, from.1, *normal));
                let (piece, spec) = planar_piece(start, *from, *to)?;
                pieces.push(piece);
                specs.push(spec);
            }
            Segment::Strip { hi, lo, fa, fb } => {
                let strip = HullStrip {
                    hull,
                    hi: *hi,
                    lo: *lo,
                    fa: *fa,
                    fb: *fb,
                };
                let corner_a = matches!(hull.a.features[*fa].kind, FeatureKind::Corner(_));
                let corner_b = matches!(hull.b.features[*fb].kind, FeatureKind::Corner(_));
                if corner_a && corner_b {
                    let (p, q, _) = strip.contacts(0.0);
                    let start = previous.unwrap_or_else(|| element(p, q, hull.normal_at(*hi)));
                    let end_normal = strip.contacts(*hi - *lo).2;
                    let angle = signed_angle(start.normal(), end_normal, start.ruling);
                    pieces.push(ConePiece {
                        start,
                        motion: Motion::Rotation {
                            origin: p,
                            axis: start.ruling,
                            angle,
                        },
                    });
                    specs.push([TrimSpec::Point(p), TrimSpec::Point(q)]);
                    continue;
                }
                let budget = max_pieces.saturating_sub(pieces.len()).max(2);
                // A deviation δ of the surface moves its section with a curve's plane by
                // δ / sin γ within the surface, γ the angle between surface and plane: the
                // fit is asked for the tolerance times the smallest sin γ of the strip, so
                // that the edges of a flat transition (γ small) stay within it too.
                let sine = strip.smallest_edge_sine().min(1.0);
                let tolerance = tolerance * sine;
                finest = finest.min(tolerance);
                let fit = match fit(&strip, tolerance, Rule::MinimalVertexDistance, budget) {
                    Ok(fit) => fit,
                    Err(FitError::Resolution { largest }) => {
                        let rounding = f64::EPSILON * largest;
                        let message = format!(
                            "tolerance = {:.3e}{} is below what f64 resolves at the edges of \
                             this transition: its surface meets the plane of a curve at an \
                             angle of {:.3e} rad (between the rulings {} and {}), where one \
                             rounding of the coordinates ({:.3e}) moves the edge by {:.3e}",
                            goal * frame.scale,
                            if first {
                                String::new()
                            } else {
                                format!(" (the fit tolerance {:.3e})", tolerance * frame.scale)
                            },
                            sine.asin(),
                            strip.describe(0.0, frame),
                            strip.describe(*hi - *lo, frame),
                            rounding * frame.scale,
                            rounding / sine * frame.scale
                        );
                        return Err(if first {
                            Error::invalid_input(message)
                        } else {
                            Error::not_converged(message)
                        });
                    }
                    Err(FitError::Pieces { .. })
                    | Err(FitError::NoPair {
                        pieces_exhausted: true,
                        ..
                    }) => return Err(too_many()),
                    Err(FitError::Narrow { deviation, a, b }) => {
                        return Err(Error::not_converged(format!(
                            "the cone fit stays {:.3e} from the hull (fit tolerance {:.3e}) \
                             between the rulings {} and {}",
                            deviation * frame.scale,
                            tolerance * frame.scale,
                            strip.describe(a, frame),
                            strip.describe(b, frame)
                        )))
                    }
                    Err(FitError::NoPair { a, b, reason, .. }) => {
                        return Err(Error::not_converged(format!(
                            "no cone pair follows the hull between the rulings {} and {} \
                             (fit tolerance {:.3e}): {reason}",
                            strip.describe(a, frame),
                            strip.describe(b, frame),
                            tolerance * frame.scale
                        )))
                    }
                    Err(FitError::Other(e)) => return Err(e),
                };
                deviation = deviation.max(fit.max_error);
                // A corner cone is trimmed at the corner itself, not at its fitted vertex:
                // the rulings of a tall or flat transition meet at small angles, where
                // their meeting point is known to fewer digits than the corner.
                let (p, q, _) = strip.contacts(0.0);
                let spec = match (corner_a, corner_b) {
                    (true, _) => [TrimSpec::Point(p), TrimSpec::Plane],
                    (_, true) => [TrimSpec::Plane, TrimSpec::Point(q)],
                    _ => [TrimSpec::Plane, TrimSpec::Plane],
                };
                // Chained as ConeSpline::new will (each piece from the end of the one
                // before), so that the pieces built on these ends stay as built.
                for p in fit.spline.pieces() {
                    let mut piece = *p;
                    if let Some(previous) = pieces.last() {
                        piece.start = previous.end();
                    }
                    pieces.push(piece);
                    specs.push(spec);
                }
            }
        }
        if pieces.len() > max_pieces {
            return Err(too_many());
        }
    }
    Ok(Fitted {
        pieces,
        specs,
        deviation,
        finest,
    })
}

/// The pieces of a walk, their trim specifications, the largest fit deviation and the
/// smallest fit tolerance of a strip.
struct Fitted {
    pieces: Vec<ConePiece>,
    specs: Vec<[TrimSpec; 2]>,
    deviation: f64,
    finest: f64,
}

/// The plane sector about `vertex` from the ruling of `start` to the ruling direction
/// `end` (projected into the start's tangent plane): a rotation about the plane's normal.
fn sector(start: Element, vertex: DVec3, end: DVec3) -> ConePiece {
    let n = start.normal();
    let e1 = (end - end.dot(n) * n).normalize();
    ConePiece {
        start,
        motion: Motion::Rotation {
            origin: vertex,
            axis: n,
            angle: signed_angle(start.ruling, e1, n),
        },
    }
}

/// The plane sector (or strip) from the ruling of `start` to the ruling `to`.
fn planar_piece(
    start: Element,
    from: (DVec3, DVec3),
    to: (DVec3, DVec3),
) -> Result<(ConePiece, [TrimSpec; 2])> {
    let end_ruling = to.1 - to.0;
    if from.0 == to.0 {
        return Ok((
            sector(start, from.0, end_ruling),
            [TrimSpec::Point(from.0), TrimSpec::Plane],
        ));
    }
    if from.1 == to.1 {
        return Ok((
            sector(start, from.1, end_ruling),
            [TrimSpec::Plane, TrimSpec::Point(from.1)],
        ));
    }
    let d0 = start.ruling;
    let piece = if d0.cross(end_ruling.normalize()).length() <= 1e-12 {
        ConePiece::cylinder(start, to.0)?
    } else {
        sector(
            start,
            meet(from.0, d0, to.0, to.1, start.normal()),
            end_ruling,
        )
    };
    Ok((piece, [TrimSpec::Plane, TrimSpec::Plane]))
}

/// The trim of `piece` on `side` (0: bottom plane, 1: top plane) by `spec`.
fn trim(hull: &Hull, piece: &ConePiece, side: usize, spec: TrimSpec) -> Result<Trim> {
    match spec {
        TrimSpec::Point(p) => Ok(Trim::constant(piece.start.parameter_of(p))),
        TrimSpec::Plane => {
            let plane = if side == 0 {
                &hull.a.plane
            } else {
                &hull.b.plane
            };
            // B's normal points away from A: the rulings (A → B) cross both planes forwards.
            let normal = plane.normal;
            Trim::plane(piece, normal, normal.dot(plane.origin), 1.0)
        }
    }
}

/// Whether a piece's vertex lies on its trimmed rulings (where it is not the designed
/// corner point): sampled along the piece.
fn vertex_inside(piece: &ConePiece, trims: &[Trim; 2], specs: &[TrimSpec; 2]) -> bool {
    let Some(v) = piece.vertex() else {
        return false;
    };
    if specs.iter().any(|s| matches!(s, TrimSpec::Point(_))) {
        return false;
    }
    let rho = piece.start.parameter_of(v);
    (0..=16).any(|j| {
        let t = j as f64 / 16.0;
        let (r0, r1) = (trims[0].eval(t), trims[1].eval(t));
        let margin = 1e-6 * (r1 - r0).abs();
        rho > r0.min(r1) - margin && rho < r0.max(r1) + margin
    })
}

/// Largest sampled distance of the part's boundary `side` from the curve on that side.
fn edge_distance(hull: &Hull, part: &TrimmedSpline, side: usize) -> Result<f64> {
    let profile = if side == 0 { &hull.a } else { &hull.b };
    let curve = part.boundary(side, 0.0)?;
    let mut worst = 0.0f64;
    for segment in curve.segments() {
        for j in 0..=16 {
            worst = worst.max(profile.distance(segment.eval(j as f64 / 16.0)));
        }
    }
    Ok(worst)
}

/// Why a fit of the part was not accepted.
enum Refused {
    Vertex(usize),
    Bends(usize, usize),
    Edges([f64; 2]),
}

/// The transition part between `bottom` and `top` (in internal coordinates: the caller's
/// mapped by `frame`), the distance of its surface and edges within `tolerance` of the hull
/// and the curves; messages quote lengths and points in the caller's units.
pub(crate) fn transition(
    bottom: &PiecewiseCurve,
    top: &PiecewiseCurve,
    tolerance: f64,
    max_pieces: usize,
    frame: &Similarity,
) -> Result<(TrimmedSpline, TransitionFit)> {
    let scale = frame.scale;
    let hull = Hull::new(bottom, top, scale)?;
    let walk = hull.segments()?;
    let mut fit_tolerance = 0.5 * tolerance;
    let mut last = None;
    for refit in 0..REFITS {
        let Fitted {
            pieces,
            specs,
            deviation,
            finest,
        } = pieces(
            &hull,
            &walk,
            fit_tolerance,
            max_pieces,
            frame,
            tolerance,
            refit == 0,
        )?;
        let chain = ConeSpline::new(pieces.clone())?;
        // Split pieces beyond 120°, each keeping its trim specification.
        let mut split = Vec::new();
        let mut split_specs = Vec::new();
        for (p, s) in chain.pieces().iter().zip(&specs) {
            for q in split_long_pieces(std::slice::from_ref(p)) {
                split.push(q);
                split_specs.push(*s);
            }
        }
        let spline = ConeSpline::new(split)?;
        let fit = TransitionFit {
            deviation,
            edge_distance: [f64::NAN; 2],
            fit_tolerance: finest,
        };
        // The hull is convex: a fit whose pieces bend both ways is too coarse somewhere.
        if let Some((k, j)) = bends_both_ways(spline.pieces()) {
            last = Some((Refused::Bends(k, j), fit));
            fit_tolerance *= 0.25;
            continue;
        }
        let trims = spline
            .pieces()
            .iter()
            .zip(&split_specs)
            .map(|(p, s)| Ok([trim(&hull, p, 0, s[0])?, trim(&hull, p, 1, s[1])?]))
            .collect::<Result<Vec<_>>>()?;
        let inside = spline
            .pieces()
            .iter()
            .zip(&trims)
            .zip(&split_specs)
            .position(|((p, t), s)| vertex_inside(p, t, s));
        let part = TrimmedSpline {
            spline,
            trims,
            closed: true,
        };
        let distances = [
            edge_distance(&hull, &part, 0)?,
            edge_distance(&hull, &part, 1)?,
        ];
        let fit = TransitionFit {
            edge_distance: distances,
            ..fit
        };
        match inside {
            Some(k) => last = Some((Refused::Vertex(k), fit)),
            None if distances.iter().all(|&d| d <= tolerance) => return Ok((part, fit)),
            None => last = Some((Refused::Edges(distances), fit)),
        }
        fit_tolerance *= 0.25;
    }
    let (refused, fit) = last.expect("at least one fit");
    let finest = fit.fit_tolerance * scale;
    let tolerance = tolerance * scale;
    Err(Error::not_converged(match refused {
        Refused::Vertex(k) => format!(
            "tolerance = {tolerance:.3e}: the cone fit keeps a vertex on piece {k} of the part \
             at every fit tolerance down to {finest:.3e}"
        ),
        Refused::Bends(k, j) => format!(
            "tolerance = {tolerance:.3e}: the cone fit bends both ways (piece {k} one way, \
             piece {j} the other) at every fit tolerance down to {finest:.3e}, though a \
             transition's surface is convex"
        ),
        Refused::Edges([a, b]) => format!(
            "tolerance = {tolerance:.3e} not reached: the edges are {:.3e} and {:.3e} from \
             the curves at the fit tolerance {finest:.3e}",
            a * scale,
            b * scale
        ),
    }))
}

#[cfg(test)]
mod tests {
    use super::super::profile::tests::{circle, polygon};
    use super::*;
    use crate::cone_spline::PieceKind;

    fn square(half: f64, z: f64) -> PiecewiseCurve {
        polygon(&[
            DVec3::new(-half, -half, z),
            DVec3::new(half, -half, z),
            DVec3::new(half, half, z),
            DVec3::new(-half, half, z),
        ])
    }

    #[test]
    fn square_to_round_walks_four_triangles_and_four_corner_cones() {
        let hull = Hull::new(
            &square(1.0, 0.0),
            &circle(DVec3::new(0.2, 0.0, 1.5), DVec3::X, DVec3::Y, 0.6),
            1.0,
        )
        .unwrap();
        let walk = hull.segments().unwrap();
        let planar = walk
            .iter()
            .filter(|s| matches!(s, Segment::Planar { .. }))
            .count();
        // Four triangles, one of them split at the seam.
        assert_eq!(planar, 5);
        let (part, fit) = transition(
            &square(1.0, 0.0),
            &circle(DVec3::new(0.2, 0.0, 1.5), DVec3::X, DVec3::Y, 0.6),
            1e-5,
            10_000,
            &Similarity {
                origin: DVec3::ZERO,
                scale: 1.0,
            },
        )
        .unwrap();
        println!(
            "square-to-round: {} pieces, deviation {:.3e}, edges {:.3e} / {:.3e}",
            part.pieces().len(),
            fit.deviation,
            fit.edge_distance[0],
            fit.edge_distance[1]
        );
        assert!(fit.edge_distance.iter().all(|&d| d <= 1e-5));
        let last = part.pieces().last().unwrap().end();
        let first = part.pieces()[0].start;
        assert!(last.ruling.distance(first.ruling) < 1e-9);
        assert!(part.pieces().iter().any(|p| p.kind() == PieceKind::Cone));
    }
}
