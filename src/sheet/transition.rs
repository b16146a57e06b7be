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
use super::trim::{split_long_pieces, Trim, TrimmedSpline};
use crate::bezier::PiecewiseCurve;
use crate::cone_spline::approximate::approximate;
use crate::cone_spline::developable::{Developable, Ruling};
use crate::cone_spline::{ConePiece, ConeSpline, Element, Motion, Rule};
use crate::error::{invalid, no_solution, Error, Result};
use crate::math::signed_angle;
use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, TAU};

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

/// The two curves, oriented: A's normal points towards B, B's away from A; both are
/// traversed counter-clockwise about their normals.
pub(crate) struct Hull {
    pub a: ConvexProfile,
    pub b: ConvexProfile,
}

/// The heights of `q`'s points over the plane of `p` (smallest, largest).
fn height_range(p: &ConvexProfile, q: &ConvexProfile) -> (f64, f64) {
    let n = p.plane.normal;
    if n.cross(q.plane.normal).length() < 1e-12 {
        let h = p.plane.height(q.plane.origin);
        return (h, h);
    }
    (
        p.plane.height(q.support_3d(-n)),
        p.plane.height(q.support_3d(n)),
    )
}

impl Hull {
    pub fn new(bottom: &PiecewiseCurve, top: &PiecewiseCurve) -> Result<Self> {
        let mut a = ConvexProfile::new(bottom, "bottom")?;
        let mut b = ConvexProfile::new(top, "top")?;
        let gap = 1e-6 * a.size.max(b.size);
        let (lo, hi) = height_range(&a, &b);
        if hi < -gap {
            a = a.flipped();
        } else if lo <= gap {
            return invalid!(
                "the curves cross: top reaches {lo:.3e} and {hi:.3e} from the plane of bottom \
                 (each curve must lie strictly on one side of the other's plane)"
            );
        }
        let (lo, hi) = height_range(&b, &a);
        if lo > gap {
            b = b.flipped();
        } else if hi >= -gap {
            return invalid!(
                "the curves cross: bottom reaches {lo:.3e} and {hi:.3e} from the plane of top \
                 (each curve must lie strictly on one side of the other's plane)"
            );
        }
        Ok(Self { a, b })
    }

    /// The outward normal of the supporting plane through A's supporting line with normal
    /// angle `theta` (through its point `p`) that touches B.
    pub fn plane_normal(&self, theta: f64, p: DVec3) -> DVec3 {
        let (d, n) = (self.a.plane.direction(theta), self.a.plane.normal);
        let nu = |beta: f64| beta.cos() * d + beta.sin() * n;
        let (mut lo, mut hi, mut beta) = (-FRAC_PI_2, FRAC_PI_2, 0.0f64);
        for _ in 0..200 {
            let v = nu(beta);
            let x = self.b.support_3d(v) - p;
            let f = v.dot(x);
            if f == 0.0 {
                break;
            }
            let slope = (-beta.sin() * d + beta.cos() * n).dot(x);
            if f > 0.0 {
                hi = beta;
            } else {
                lo = beta;
            }
            let newton = beta - f / slope;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let step = (next - beta).abs();
            beta = next;
            if step <= 1e-16 || hi - lo <= 1e-16 {
                break;
            }
        }
        nu(beta)
    }

    /// B's outward normal angle of the spatial normal `nu`.
    pub fn b_angle(&self, nu: DVec3) -> f64 {
        let n = self.b.plane.normal;
        self.b.plane.angle_of(nu - nu.dot(n) * n)
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
    /// At a point on the ruling (a vertex on the curve).
    Point(DVec3),
    /// At the piece's own vertex (a cone from a corner).
    Vertex,
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
        let nu = self.hull.plane_normal(theta, p);
        let q = self.hull.b.feature_point(self.fb, self.hull.b_angle(nu));
        (p, q, nu)
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
pub struct TransitionFit {
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
            let phi = self.b_angle(self.normal_at(t));
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
                let phi = self.b_angle(self.normal_at(t));
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
            None => self.b.support(self.b_angle(self.normal_at(event.theta))),
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
            let fb = self.b.feature_at(self.b_angle(self.normal_at(mid)));
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
            p.distance(hull.b.support(hull.b_angle(hull.plane_normal(*hi, p))))
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
) -> Result<(Vec<ConePiece>, Vec<[TrimSpec; 2]>, f64)> {
    let mut pieces: Vec<ConePiece> = Vec::new();
    let mut specs: Vec<[TrimSpec; 2]> = Vec::new();
    let mut deviation = 0.0f64;
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
                let fit = approximate(&strip, tolerance, Rule::MinimalVertexDistance, budget)
                    .map_err(|e| e.context("fitting the transition's cones"))?;
                deviation = deviation.max(fit.max_error);
                let spec = match (corner_a, corner_b) {
                    (true, _) => [TrimSpec::Vertex, TrimSpec::Plane],
                    (_, true) => [TrimSpec::Plane, TrimSpec::Vertex],
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
            return Err(Error::not_converged(format!(
                "the transition needs more than max_pieces = {max_pieces} pieces"
            )));
        }
    }
    Ok((pieces, specs, deviation))
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
        TrimSpec::Vertex => match piece.vertex() {
            Some(v) => Ok(Trim::constant(piece.start.parameter_of(v))),
            None => no_solution!("a corner cone of the transition has no vertex"),
        },
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
    if specs
        .iter()
        .any(|s| matches!(s, TrimSpec::Vertex | TrimSpec::Point(_)))
    {
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

/// The transition part between `bottom` and `top` (in the caller's coordinates, which
/// must be of unit size: see [`Similarity`](super::trim::Similarity)), the distance of
/// its surface and edges within `tolerance` of the hull and the curves.
pub(crate) fn transition(
    bottom: &PiecewiseCurve,
    top: &PiecewiseCurve,
    tolerance: f64,
    max_pieces: usize,
) -> Result<(TrimmedSpline, TransitionFit)> {
    let hull = Hull::new(bottom, top)?;
    let walk = hull.segments()?;
    let mut fit_tolerance = 0.5 * tolerance;
    let mut last = None;
    for _ in 0..REFITS {
        let (pieces, specs, deviation) = pieces(&hull, &walk, fit_tolerance, max_pieces)?;
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
            deviation,
            edge_distance: distances,
            fit_tolerance,
        };
        if inside.is_none() && distances.iter().all(|&d| d <= tolerance) {
            return Ok((part, fit));
        }
        last = Some((inside, fit));
        fit_tolerance *= 0.25;
    }
    let (inside, fit) = last.expect("at least one fit");
    Err(Error::not_converged(match inside {
        Some(k) => format!(
            "tolerance = {tolerance:.3e}: the cone fit keeps a vertex on piece {k} of the part"
        ),
        None => format!(
            "tolerance = {tolerance:.3e} not reached: the edges are {:.3e} and {:.3e} from the curves",
            fit.edge_distance[0], fit.edge_distance[1]
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
