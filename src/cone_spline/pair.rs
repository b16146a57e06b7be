//! G1 cone pairs through two Hermite elements (Sections "The general case" and "Special
//! cases"), every case of the paper:
//!
//! * **general** (skew rulings): the inscribed sphere Σ, centre m from the normal planes (5)
//!   and the bisector plane (6); touching points aᵢ; vertices vᵢ = a₁ + μ₁e₁, a₂ − μ₂e₂ on
//!   the bilinear relation (9), written as the Möbius map (11);
//! * **cone** (intersecting rulings): a common vertex v and a spherical biarc (7)–(8) on a
//!   sphere about v;
//! * **cylinder** (parallel, equally oriented rulings): a planar biarc in a normal section;
//! * **constant slope** (det(p₁, p₂, n₁ − n₂) = 0, (13)): cones with parallel axes normal
//!   to the plane π spanned by p₁, p₂ (or by p₁ and n₁ − n₂ when det(p₁, p₂) = 0), vertices
//!   again by (9) with aᵢ = eᵢ ∩ π;
//! * **plane** (equal tangent planes): one plane sector or strip.
//!
//! The one-parameter family is cut by a [`Rule`]: minimal vertex distance (12) — the
//! default —, congruent cones μ₁ = μ₂, a cylinder as the first (10) or second segment, or
//! a given μ₁. Every candidate is built and checked (G1 at both elements, no vertex in the
//! region Ω, no vertex at a reference point); of the admissible ones the *useful* one is
//! the one with the least total segment angle, which discards the solution that winds
//! round the cone (the wrong root of (12) is not always the larger distance).
//!
//! Conditioning. Each pair is solved in coordinates centred on the first element's point
//! and scaled by a power of two near the elements' distance, so that its tolerances are
//! relative to the data and a pair does not depend on where the data lie or on their size.
//! As the rulings approach, both vertices of (9) tend to the vertex of the osculating cone,
//! 1/dt times the elements' distance away, while C = 2(e₁·e₂ − 1) and A + D of (11)–(12)
//! vanish like dt²: these are formed from e₁ − e₂ (C = −|e₁ − e₂|²), the junction ruling
//! v₂ − v₁ as d − σe₂ + μ₁(e₂ − e₁) with σ = μ₁ + μ₂ the polished unknown, and 1 − cos of a
//! cone's rulings as |e − e'|²/2, so that nothing cancels; 5,000 pairs of helix-tangent-
//! surface rulings 0.001 apart all join (330 did before).

use super::developable::Ruling;
use super::element::{check_consecutive, Element};
use super::piece::ConePiece;
use super::piece::Motion;
use super::region::{Region, SweptBand};
use crate::error::no_solution;
use crate::error::{invalid, Error, Result};
use crate::math::{quadratic_roots, robust_length, secant_refine, solve_refined};
use crate::model::biarc::{biarc, equal_lambda, lambda_through, partner_lambda, Biarc};
use crate::model::Similarity;
use glam::{DMat3, DVec3};

/// |det(p₁, p₂, n₁ − n₂)| below which (13) holds: the constant-slope case.
const CONSTANT_SLOPE_TOLERANCE: f64 = 1e-10;
/// Relative tolerance of the G1 check at the second element.
const JOIN_TOLERANCE: f64 = 1e-10;

/// How a cone pair is chosen from the one-parameter family.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rule {
    /// Locally minimal vertex distance |v₂ − v₁| (12), the useful root. In the cone and
    /// cylinder cases (vertices fixed or at infinity): the biarc with equal legs λ₁ = λ₂.
    MinimalVertexDistance,
    /// Congruent cones, μ₁ = μ₂ in (9). Cone and cylinder cases: λ₁ = λ₂.
    Congruent,
    /// The first segment a cylinder (v₁ at infinity, μ₂ by (10)).
    CylinderFirst,
    /// The second segment a cylinder (v₂ at infinity).
    CylinderSecond,
    /// A given μ₁ (general and constant-slope cases) or λ₁ (cone and cylinder cases).
    Given(f64),
}

/// Which case of the paper a pair falls into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PairCase {
    /// Skew rulings: the cones touch an inscribed sphere.
    General,
    /// The rulings intersect: the cones share a vertex.
    Cone,
    /// Parallel rulings: cylinders.
    Cylinder,
    /// Constant slope, det(p₁, p₂, n₁ − n₂) = 0 (13).
    ConstantSlope,
    /// Equal tangent planes: one plane piece.
    Plane,
}

/// A G1 cone pair (or a single plane piece) from one element to the next.
#[derive(Clone, Debug, PartialEq)]
pub struct ConePair {
    /// Which case of the paper the pair fell into.
    pub case: PairCase,
    /// Two pieces (one for the plane case, or where one segment of the family does not
    /// move); the first starts at the first element.
    pub pieces: Vec<ConePiece>,
    /// The inscribed sphere (centre, radius): general case, and the sphere about the common
    /// vertex in the cone case.
    pub sphere: Option<(DVec3, f64)>,
    /// The biarc along which the pair touches Σ (or meets the normal section / π).
    pub biarc: Option<Biarc>,
    /// The vertex parameters (μ₁, μ₂) of (9); `None` for a vertex at infinity.
    pub mu: Option<VertexParameters>,
}

/// A vertex: a point, or at infinity (the segment is a cylinder).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Apex {
    Finite(DVec3),
    Infinite,
}

/// The cone pair from `a` to `b` chosen by `rule`, free of vertices in `region`.
/// `names` are the caller's names of the two elements, for messages.
///
/// The pair is solved in coordinates centred on the first element's point and scaled by a
/// power of two at or below the elements' distance (a `Similarity`), so that it does not depend on
/// where the data lie or on their size: the tolerances below are relative to that
/// distance, and a scaling by a power of two changes no rounding at all.
pub fn cone_pair(
    a: &Element,
    b: &Element,
    rule: Rule,
    region: Option<&Region>,
    names: (&str, &str),
) -> Result<ConePair> {
    solve_pair(a, b, rule, region.map(|&r| KeepOut::Box(r)), names)
}

/// [`cone_pair`] with no vertex inside the region swept by the rulings `band` of the
/// surface at `a` and `b` (instead of a box): the approximation's pairs. As for a box, the
/// rule's most useful admissible solution is taken, and for the default rule, where both
/// roots of (12) put a vertex inside, one with a vertex just outside the band on either
/// ruling.
pub(crate) fn cone_pair_in_band(
    a: &Element,
    b: &Element,
    rule: Rule,
    band: &SweptBand,
    names: (&str, &str),
) -> Result<ConePair> {
    solve_pair(a, b, rule, Some(KeepOut::Band(band)), names)
}

fn solve_pair(
    a: &Element,
    b: &Element,
    rule: Rule,
    keep_out: Option<KeepOut<'_>>,
    names: (&str, &str),
) -> Result<ConePair> {
    check_consecutive(a, b, names.0, names.1)?;
    if let Rule::Given(x) = rule {
        if !x.is_finite() {
            return invalid!("the given parameter mu1 = {x} is not finite");
        }
    }
    let frame = Similarity::power_of_two_about(a.point, robust_length(b.point - a.point));
    let rule = match rule {
        Rule::Given(x) => Rule::Given(x / frame.scale),
        other => other,
    };
    let omega = keep_out.map(|keep_out| Omega::new(keep_out, frame));
    let pair = local_pair(
        &frame.element_in(a),
        &frame.element_in(b),
        rule,
        omega.as_ref(),
    )?;
    Ok(frame.pair_out(pair))
}

/// A pair's local coordinates (centred on the first element's point, scaled by the power of
/// two at or below the elements' distance) carry the cone spline's own objects: rulings,
/// elements, pieces and pairs.
impl Similarity {
    /// A ruling of a developable in these coordinates (its band scaled with them).
    pub(crate) fn ruling_in(&self, r: &Ruling) -> Ruling {
        Ruling {
            point: self.to_internal(r.point),
            range: (r.range.0 / self.scale, r.range.1 / self.scale),
            ..*r
        }
    }

    pub(crate) fn element_in(&self, e: &Element) -> Element {
        Element::from_frame(self.to_internal(e.point), e.ruling, e.side)
    }

    fn element_out(&self, e: &Element) -> Element {
        Element::from_frame(self.to_user(e.point), e.ruling, e.side)
    }

    pub(crate) fn piece_out(&self, p: &ConePiece) -> ConePiece {
        let motion = match p.motion {
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => Motion::Rotation {
                origin: self.to_user(origin),
                axis,
                angle,
            },
            Motion::Translation(v) => Motion::Translation(v * self.scale),
        };
        ConePiece {
            start: self.element_out(&p.start),
            motion,
        }
    }

    fn pair_out(&self, pair: ConePair) -> ConePair {
        let s = self.scale;
        let length = |x: Option<f64>| x.map(|x| x * s);
        ConePair {
            case: pair.case,
            pieces: pair.pieces.iter().map(|p| self.piece_out(p)).collect(),
            sphere: pair.sphere.map(|(m, r)| (self.to_user(m), r * s)),
            biarc: pair.biarc.map(|b| Biarc {
                a1: self.to_user(b.a1),
                b1: self.to_user(b.b1),
                c: self.to_user(b.c),
                b2: self.to_user(b.b2),
                a2: self.to_user(b.a2),
                lambda1: b.lambda1 * s,
                lambda2: b.lambda2 * s,
                ..b
            }),
            mu: pair.mu.map(|(m1, m2)| (length(m1), length(m2))),
        }
    }
}

/// Where the vertices of a pair must not lie, in the caller's coordinates.
#[derive(Clone, Copy, Debug)]
enum KeepOut<'a> {
    /// A box (Hermite interpolation).
    Box(Region),
    /// The region swept by the surface's rulings between the two elements (approximation).
    Band(&'a SweptBand),
}

/// Where the vertices must not lie, seen from the local coordinates of a pair: a box
/// in the caller's coordinates, a band carried into the local ones.
enum LocalKeepOut {
    Box(Region),
    Band(SweptBand),
}

/// The caller's region of interest seen from the local coordinates of a pair.
struct Omega {
    keep_out: LocalKeepOut,
    frame: Similarity,
}

impl Omega {
    fn new(keep_out: KeepOut<'_>, frame: Similarity) -> Self {
        let keep_out = match keep_out {
            KeepOut::Band(band) => LocalKeepOut::Band(band.map(|r| frame.ruling_in(r))),
            KeepOut::Box(region) => LocalKeepOut::Box(region),
        };
        Self { keep_out, frame }
    }

    /// Whether no vertex of the local pieces lies inside the region.
    fn admits(&self, pieces: &[ConePiece]) -> bool {
        match &self.keep_out {
            LocalKeepOut::Box(region) => !pieces
                .iter()
                .filter_map(ConePiece::vertex)
                .any(|v| region.contains(self.frame.to_user(v))),
            LocalKeepOut::Band(band) => band.admits(pieces),
        }
    }

    /// The region on the pair's first (`end` false) or last ruling, along the local line
    /// `point + s·direction` on it, in local distances, with the distance by which a vertex
    /// is placed outside it: for a box its clip ([`Region::clip_line`]) and 1e-6 of its
    /// diagonal.
    fn on_ruling(&self, end: bool, point: DVec3, direction: DVec3) -> Option<((f64, f64), f64)> {
        match &self.keep_out {
            LocalKeepOut::Box(region) => {
                let s = self.frame.scale;
                let margin = 1e-6 * crate::math::robust_length(region.max - region.min) / s;
                region
                    .clip_line(self.frame.to_user(point), direction)
                    .map(|(lo, hi)| ((lo / s, hi / s), margin))
            }
            LocalKeepOut::Band(band) => Some(band.on_ruling(end, point, direction)),
        }
    }
}

/// [`cone_pair`] of checked elements in local coordinates.
fn local_pair(a: &Element, b: &Element, rule: Rule, region: Option<&Omega>) -> Result<ConePair> {
    let (e1, e2) = (a.ruling, b.ruling);
    let w = e1.cross(e2);
    let d = b.point - a.point;
    let scale = a
        .point
        .abs()
        .max_element()
        .max(b.point.abs().max_element())
        .max(d.length())
        .max(1e-300);
    let equal_planes =
        (a.normal() - b.normal()).length() <= 1e-12 && d.dot(a.normal()).abs() <= 1e-12 * scale;
    if w.length() <= 1e-12 {
        return if equal_planes {
            single_plane(ConePiece::cylinder(*a, b.point), b, scale)
        } else {
            cylinder_case(a, b, rule, scale)
        };
    }
    let gap = d.dot(w) / w.length();
    // The rulings meet where their gap is below rounding: rounding of the unit directions
    // moves the lines by ε times the distance to their meeting point, which for close
    // rulings through one vertex (a corner cone) is far larger than the elements' distance.
    let meet = d.cross(e2).dot(w) / w.length_squared();
    if gap.abs() <= 1e-12 * scale.max(meet.abs()) {
        let v = a.at(meet);
        return if equal_planes {
            let piece = ConePiece::cone(v, *a, e2)?;
            if has_vertex_in(std::slice::from_ref(&piece), region) {
                return no_solution!(
                    "the rulings meet{} in the region of interest, in one tangent plane",
                    at_point(v, region)
                );
            }
            single_plane(Ok(piece), b, scale)
        } else {
            cone_case(a, b, v, rule, region, scale)
        };
    }
    let (p1, p2) = (a.side, b.side);
    let slope = p1.dot(p2.cross(a.normal() - b.normal()));
    if slope.abs() <= CONSTANT_SLOPE_TOLERANCE {
        constant_slope_case(a, b, rule, region, scale)
    } else {
        general_case(a, b, rule, region, scale)
    }
}

/// " at v", the local point `v` in the caller's coordinates, where the caller gave them (a
/// box); nothing for a band, whose coordinates are those of an approximation's own frame
/// (its messages name the rulings by their parameters instead).
fn at_point(v: DVec3, region: Option<&Omega>) -> String {
    match region {
        None => String::new(),
        Some(r) => match r.keep_out {
            LocalKeepOut::Box(_) => format!(" at {}", r.frame.to_user(v)),
            LocalKeepOut::Band(_) => String::new(),
        },
    }
}

fn single_plane(piece: Result<ConePiece>, b: &Element, scale: f64) -> Result<ConePair> {
    let piece = piece?;
    joins(&piece.end(), b, scale)?;
    Ok(ConePair {
        case: PairCase::Plane,
        pieces: vec![piece],
        sphere: None,
        biarc: None,
        mu: None,
    })
}

/// The G1 check at the second element: same ruling line, direction and tangent plane.
pub(crate) fn joins(end: &Element, b: &Element, scale: f64) -> Result<()> {
    let off_line = (b.point - end.point).cross(end.ruling).length();
    if (end.ruling - b.ruling).length() > JOIN_TOLERANCE
        || (end.normal() - b.normal()).length() > JOIN_TOLERANCE
        || off_line > JOIN_TOLERANCE * scale
    {
        return Err(Error::no_solution(
            "the pair does not reach the second element with its ruling orientation and side",
        ));
    }
    Ok(())
}

/// Both segments from their vertices: the junction ruling joins v₁ and v₂ (or is parallel
/// to the ruling of a segment whose vertex is at infinity), with the orientation `sign`.
/// By construction the second segment ends on the ruling of `b` with its direction; only
/// its tangent plane there remains to be checked. For two finite vertices `junction` is
/// v₂ − v₁ computed without cancellation ([`VertexFamily::junction`]), and v₂ = v₁ +
/// `junction`.
fn pair_from_apexes(
    a: &Element,
    b: &Element,
    v1: Apex,
    v2: Apex,
    junction: Option<DVec3>,
    sign: f64,
    scale: f64,
) -> Result<[ConePiece; 2]> {
    let (through, direction) = match (v1, v2, junction) {
        (Apex::Finite(p), Apex::Finite(_), Some(j)) => (p, j),
        (Apex::Finite(p), Apex::Finite(q), None) => (p, q - p),
        (Apex::Infinite, Apex::Finite(q), _) => (q, a.ruling),
        (Apex::Finite(p), Apex::Infinite, _) => (p, b.ruling),
        (Apex::Infinite, Apex::Infinite, _) => {
            return Err(Error::no_solution("both vertices at infinity"))
        }
    };
    if direction.length() <= 1e-12 * scale {
        return Err(Error::no_solution("the two vertices coincide"));
    }
    let first = match v1 {
        Apex::Finite(p) => ConePiece::cone(p, *a, sign * direction),
        Apex::Infinite => ConePiece::cylinder(*a, through),
    }?;
    let second = match (v1, v2) {
        (Apex::Finite(p), Apex::Finite(_)) => ConePiece::cone(p + direction, first.end(), b.ruling),
        (_, Apex::Finite(q)) => ConePiece::cone(q, first.end(), b.ruling),
        (_, Apex::Infinite) => ConePiece::cylinder(first.end(), b.point),
    }?;
    Ok([first, second])
}

/// The signed angle about e₂ between the pair's end tangent plane and that of `b`.
fn plane_residual(pieces: &[ConePiece; 2], b: &Element) -> f64 {
    pieces[1].end().tangent_plane_angle(b)
}

/// The pair of a family member, G1 at `b` to round-off: the vertex family (9) is
/// ill-conditioned where the inscribed sphere is huge (nearly constant slope) and where the
/// rulings approach (the two vertices tend to the vertex of the osculating cone, far from
/// the elements compared with their distance |v₂ − v₁|), so one parameter is polished by
/// secant steps on the tangent-plane residual at `b` before the G1 check: for two finite
/// vertices the vertex distance σ = μ₁ + μ₂ with μ₁ fixed — the junction ruling
/// d − σe₂ + μ₁(e₂ − e₁) is then accurate to rounding of the data, however close the
/// rulings —, else the finite one of μ₂, μ₁.
fn family_member(
    a: &Element,
    b: &Element,
    family: &VertexFamily,
    mu: VertexParameters,
    sign: f64,
    scale: f64,
) -> Result<(Vec<ConePiece>, VertexParameters)> {
    let (pieces, mu) = match mu {
        (Some(mu1), Some(mu2)) => {
            let build = |sigma: f64| {
                let (v1, v2) = family.apexes((Some(mu1), Some(sigma - mu1)));
                let junction = family.junction(mu1, sigma);
                pair_from_apexes(a, b, v1, v2, Some(junction), sign, scale)
            };
            let residual = |x: f64| build(x).ok().map(|p| plane_residual(&p, b));
            let sigma0 = mu1 + mu2;
            let sigma = secant_refine(residual, sigma0, 1e-7 * sigma0.abs().max(scale), 8);
            (build(sigma)?, (Some(mu1), Some(sigma - mu1)))
        }
        _ => {
            let build = |mu: VertexParameters| {
                let (v1, v2) = family.apexes(mu);
                pair_from_apexes(a, b, v1, v2, None, sign, scale)
            };
            let with = |x: f64| {
                if mu.1.is_some() {
                    (mu.0, Some(x))
                } else {
                    (Some(x), None)
                }
            };
            match mu.1.or(mu.0) {
                Some(x0) => {
                    let residual = |x: f64| build(with(x)).ok().map(|p| plane_residual(&p, b));
                    let x = secant_refine(residual, x0, 1e-7 * x0.abs().max(scale), 8);
                    (build(with(x))?, with(x))
                }
                None => (build(mu)?, mu),
            }
        }
    };
    joins(&pieces[1].end(), b, scale)?;
    // A segment that does not move (the family member where one cone alone joins the
    // elements) is left out rather than kept as an empty patch.
    Ok((
        pieces.into_iter().filter(|p| !is_empty(p, scale)).collect(),
        mu,
    ))
}

/// Whether a piece does not move its ruling at all (to round-off).
fn is_empty(piece: &ConePiece, scale: f64) -> bool {
    let end = piece.end();
    (end.point - piece.start.point).length() <= 1e-13 * scale
        && (end.ruling - piece.start.ruling).length() <= 1e-13
}

/// The total segment angle of a candidate (smaller is more useful).
fn total_angle(pieces: &[ConePiece]) -> f64 {
    pieces.iter().map(ConePiece::segment_angle).sum()
}

fn has_vertex_in(pieces: &[ConePiece], region: Option<&Omega>) -> bool {
    region.is_some_and(|r| !r.admits(pieces))
}

/// Vertex parameters (μ₁, μ₂); `None` is a vertex at infinity.
pub(crate) type VertexParameters = (Option<f64>, Option<f64>);

/// The vertex family of (9): v₁ = a₁ + μ₁e₁, v₂ = a₂ − μ₂e₂, μ₂ = (Aμ₁ + B)/(Cμ₁ + D) (11).
///
/// As the rulings approach, C and A + D vanish quadratically in their angle while A and
/// D do not; they are computed from e₁ − e₂ (C = 2(e₁·e₂ − 1) = −|e₁ − e₂|² for unit
/// vectors, A + D = 2 d·(e₁ − e₂)), which keeps their relative accuracy, instead of from
/// the cancelling differences of nearly equal numbers.
struct VertexFamily {
    a1: DVec3,
    a2: DVec3,
    e1: DVec3,
    e2: DVec3,
    coefficients: [f64; 4],
    /// A + D.
    a_plus_d: f64,
}

impl VertexFamily {
    fn new(a1: DVec3, e1: DVec3, a2: DVec3, e2: DVec3) -> Self {
        let d = a2 - a1;
        let de = e1 - e2;
        let coefficients = [
            2.0 * d.dot(e1),
            -d.length_squared(),
            -de.length_squared(),
            -2.0 * d.dot(e2),
        ];
        Self {
            a1,
            a2,
            e1,
            e2,
            coefficients,
            a_plus_d: 2.0 * d.dot(de),
        }
    }

    /// μ₂ for μ₁ by (11); `None` at the pole (v₂ at infinity).
    fn mu2(&self, mu1: f64) -> Option<f64> {
        let [a, b, c, d] = self.coefficients;
        let (num, den) = (a * mu1 + b, c * mu1 + d);
        (den.abs() > 1e-14 * num.abs().max(1e-300)).then(|| num / den)
    }

    /// μ₁ for μ₂ by the inverse of (11); `None` for v₁ at infinity.
    fn mu1(&self, mu2: f64) -> Option<f64> {
        let [a, b, c, d] = self.coefficients;
        let (num, den) = (d * mu2 - b, a - c * mu2);
        (den.abs() > 1e-14 * num.abs().max(1e-300)).then(|| num / den)
    }

    /// The (μ₁, μ₂) the rule asks for (two for the quadratic rules).
    fn candidates(&self, rule: Rule) -> Vec<VertexParameters> {
        let [a, b, c, d] = self.coefficients;
        let with_partner = |mu1: f64| (Some(mu1), self.mu2(mu1));
        match rule {
            // (12): C²μ₁² + 2CDμ₁ + AD + D² − BC = 0, with AD + D² = D(A + D).
            Rule::MinimalVertexDistance => {
                quadratic_roots(c * c, 2.0 * c * d, d * self.a_plus_d - b * c)
                    .into_iter()
                    .map(with_partner)
                    .collect()
            }
            // μ₁ = μ₂ = μ in (11): Cμ² + (D − A)μ − B = 0.
            Rule::Congruent => quadratic_roots(c, d - a, -b)
                .into_iter()
                .map(|mu| (Some(mu), Some(mu)))
                .collect(),
            // (10): μ₁ → ∞ gives μ₂ = A / C.
            Rule::CylinderFirst => vec![(None, (c != 0.0).then(|| a / c))],
            Rule::CylinderSecond => vec![((c != 0.0).then(|| -d / c), None)],
            Rule::Given(mu1) => vec![with_partner(mu1)],
        }
    }

    /// Vertices just outside the region on either ruling, for when the rule's own choice
    /// puts a vertex inside it.
    fn boundary_candidates(&self, region: &Omega) -> Vec<VertexParameters> {
        let mut out = self.candidates(Rule::CylinderFirst);
        out.extend(self.candidates(Rule::CylinderSecond));
        if let Some(((lo, hi), margin)) = region.on_ruling(false, self.a1, self.e1) {
            for mu1 in [lo - margin, hi + margin] {
                out.push((Some(mu1), self.mu2(mu1)));
            }
        }
        if let Some(((lo, hi), margin)) = region.on_ruling(true, self.a2, -self.e2) {
            for mu2 in [lo - margin, hi + margin] {
                out.push((self.mu1(mu2), Some(mu2)));
            }
        }
        out
    }

    /// v₂ − v₁ = d − μ₂e₂ − μ₁e₁ for μ₂ = σ − μ₁, as d − σe₂ + μ₁(e₂ − e₁): every term is of
    /// the size of the result when the rulings are close (μ₁ ≈ −μ₂ large, e₂ − e₁ small),
    /// where the difference of the vertices would cancel.
    fn junction(&self, mu1: f64, sigma: f64) -> DVec3 {
        (self.a2 - self.a1) - sigma * self.e2 + mu1 * (self.e2 - self.e1)
    }

    fn apexes(&self, (mu1, mu2): VertexParameters) -> (Apex, Apex) {
        (
            mu1.map_or(Apex::Infinite, |m| Apex::Finite(self.a1 + m * self.e1)),
            mu2.map_or(Apex::Infinite, |m| Apex::Finite(self.a2 - m * self.e2)),
        )
    }
}

/// The most useful admissible pair of the candidates, with its (μ₁, μ₂).
fn best_pair(
    a: &Element,
    b: &Element,
    family: &VertexFamily,
    candidates: Vec<VertexParameters>,
    region: Option<&Omega>,
    scale: f64,
) -> Option<(Vec<ConePiece>, VertexParameters)> {
    candidates
        .into_iter()
        .flat_map(|mu| [1.0, -1.0].map(|sign| (mu, sign)))
        .filter_map(|(mu, sign)| {
            let (pieces, mu) = family_member(a, b, family, mu, sign, scale).ok()?;
            (!has_vertex_in(&pieces, region)).then_some((pieces, mu))
        })
        .min_by(|x, y| total_angle(&x.0).total_cmp(&total_angle(&y.0)))
}

/// Solves a family case (general or constant slope) by the rule, falling back (for the
/// default rule) to vertices just outside the region.
fn family_pair(
    a: &Element,
    b: &Element,
    family: &VertexFamily,
    rule: Rule,
    region: Option<&Omega>,
    scale: f64,
) -> Result<(Vec<ConePiece>, VertexParameters)> {
    if let Some(found) = best_pair(a, b, family, family.candidates(rule), region, scale) {
        return Ok(found);
    }
    if let (Some(r), Rule::MinimalVertexDistance) = (region, rule) {
        if let Some(found) = best_pair(a, b, family, family.boundary_candidates(r), region, scale) {
            return Ok(found);
        }
        return Err(Error::no_solution(
            "the region of interest contains every admissible vertex of the cone pairs",
        ));
    }
    no_solution!(
        "no cone pair of the rule {rule:?} joins the elements consistently{}",
        if region.is_some() {
            " with its vertices outside the region"
        } else {
            ""
        }
    )
}

/// The spherical (or planar) biarc of a finished pair: the junction point c where the
/// junction ruling touches Σ / meets the plane, and λᵢ through c.
fn biarc_through(a1: DVec3, a2: DVec3, a: &Element, b: &Element, c: DVec3) -> Biarc {
    let l1 = lambda_through(a1, a.side, c);
    let l2 = lambda_through(a2, -b.side, c);
    biarc(a1, a.side, a2, b.side, l1, l2)
}

fn general_case(
    a: &Element,
    b: &Element,
    rule: Rule,
    region: Option<&Omega>,
    scale: f64,
) -> Result<ConePair> {
    let (n1, n2) = (a.normal(), b.normal());
    // m: the normal planes (5) and the bisector plane (6), relative to the first element's
    // point (right-hand sides of the elements' distance, no cancellation of coordinates)
    // and solved with refinement: nearby elements make the system nearly singular.
    let rows = DMat3::from_cols(a.side, b.side, n1 - n2).transpose();
    let offset = b.point - a.point;
    let rhs = DVec3::new(0.0, b.side.dot(offset), -offset.dot(n2));
    let Some(y) = solve_refined(rows, rhs) else {
        return Err(Error::no_solution(
            "the inscribed sphere of the two elements is undefined (parallel normal planes)",
        ));
    };
    let m = a.point + y;
    let radius = (m - a.point).dot(n1);
    let a1 = a.at(a.parameter_of(m));
    let a2 = b.at(b.parameter_of(m));
    let family = VertexFamily::new(a1, a.ruling, a2, b.ruling);
    let (pieces, mu) = family_pair(a, b, &family, rule, region, scale)?;
    // The junction ruling touches Σ at the foot of m on it.
    let j = pieces[0].end();
    let c = j.at(j.parameter_of(m));
    Ok(ConePair {
        case: PairCase::General,
        biarc: Some(biarc_through(a1, a2, a, b, c)),
        pieces,
        sphere: Some((m, radius.abs())),
        mu: Some(mu),
    })
}

fn constant_slope_case(
    a: &Element,
    b: &Element,
    rule: Rule,
    region: Option<&Omega>,
    scale: f64,
) -> Result<ConePair> {
    let (p1, p2) = (a.side, b.side);
    let mut normal = p1.cross(p2);
    if normal.length() <= 1e-12 {
        // det(p₁, p₂) = 0: π is spanned by p₁ and n₁ − n₂.
        normal = p1.cross(a.normal() - b.normal());
    }
    let normal = normal.normalize();
    let meet = |el: &Element| -> Result<DVec3> {
        let s = el.ruling.dot(normal);
        if s.abs() <= 1e-12 {
            return Err(Error::no_solution(
                "a ruling is parallel to the plane π of the constant-slope case",
            ));
        }
        Ok(el.at((a.point - el.point).dot(normal) / s))
    };
    let (a1, a2) = (meet(a)?, meet(b)?);
    let family = VertexFamily::new(a1, a.ruling, a2, b.ruling);
    let (pieces, mu) = family_pair(a, b, &family, rule, region, scale)?;
    let j = pieces[0].end();
    let c = j.at((a1 - j.point).dot(normal) / j.ruling.dot(normal));
    Ok(ConePair {
        case: PairCase::ConstantSlope,
        biarc: Some(biarc_through(a1, a2, a, b, c)),
        pieces,
        sphere: None,
        mu: Some(mu),
    })
}

/// λ₁, λ₂ of the rule for the cone and cylinder cases.
fn biarc_lambdas(a1: DVec3, p1: DVec3, a2: DVec3, p2: DVec3, rule: Rule) -> Result<(f64, f64)> {
    let lambda1 = match rule {
        Rule::Given(l) => l,
        _ => equal_lambda(a1, p1, a2, p2)
            .ok_or_else(|| Error::no_solution("no biarc with equal positive legs"))?,
    };
    let lambda2 = partner_lambda(a1, p1, a2, p2, lambda1).ok_or_else(|| {
        Error::no_solution(match rule {
            Rule::Given(_) => "the given lambda1 gives no second arc".to_string(),
            _ => "the equal-legged biarc has no second arc".to_string(),
        })
    })?;
    if (lambda1 + lambda2).abs() <= 1e-14 * (lambda1.abs() + lambda2.abs()) {
        return Err(Error::no_solution(
            "the biarc degenerates (lambda1 + lambda2 = 0)",
        ));
    }
    Ok((lambda1, lambda2))
}

fn cone_case(
    a: &Element,
    b: &Element,
    v: DVec3,
    rule: Rule,
    region: Option<&Omega>,
    scale: f64,
) -> Result<ConePair> {
    if matches!(rule, Rule::CylinderFirst | Rule::CylinderSecond) {
        return Err(Error::no_solution(
            "the rulings intersect: every cone pair has their common vertex, none is a cylinder",
        ));
    }
    let (s1, s2) = (a.parameter_of(v), b.parameter_of(v));
    if s1 == 0.0 || s2 == 0.0 || (s1 < 0.0) != (s2 < 0.0) {
        return Err(Error::no_solution(
            "the element points lie at or on different sides of the common vertex of the rulings",
        ));
    }
    // The nappe of the reference points: aᵢ = v + σ R eᵢ on the sphere about v.
    let sigma = if s1 < 0.0 { 1.0 } else { -1.0 };
    let radius = (a.point - v).length();
    let (a1, a2) = (v + sigma * radius * a.ruling, v + sigma * radius * b.ruling);
    let (l1, l2) = biarc_lambdas(a1, a.side, a2, b.side, rule)?;
    let arcs = biarc(a1, a.side, a2, b.side, l1, l2);
    let junction = sigma * (arcs.c - v);
    let first = ConePiece::cone(v, *a, junction)?;
    let second = ConePiece::cone(v, first.end(), b.ruling)?;
    if has_vertex_in(&[first, second], region) {
        return no_solution!(
            "the region of interest contains every possible vertex: the rulings meet{}",
            at_point(v, region)
        );
    }
    joins(&second.end(), b, scale)?;
    Ok(ConePair {
        case: PairCase::Cone,
        pieces: vec![first, second],
        sphere: Some((v, radius)),
        biarc: Some(arcs),
        mu: None,
    })
}

fn cylinder_case(a: &Element, b: &Element, rule: Rule, scale: f64) -> Result<ConePair> {
    let a1 = a.point;
    let a2 = b.point - (b.point - a.point).dot(a.ruling) * a.ruling;
    let (l1, l2) = biarc_lambdas(a1, a.side, a2, b.side, rule)?;
    let arcs = biarc(a1, a.side, a2, b.side, l1, l2);
    let first = ConePiece::cylinder(*a, arcs.c)?;
    let second = ConePiece::cylinder(first.end(), b.point)?;
    joins(&second.end(), b, scale)?;
    Ok(ConePair {
        case: PairCase::Cylinder,
        pieces: vec![first, second],
        sphere: None,
        biarc: Some(arcs),
        mu: None,
    })
}

#[cfg(test)]
mod tests {
    use super::super::developable::Developable;
    use super::super::piece::PieceKind;
    use super::super::test_support::{tangent_surface, twisted_cubic, Helix};
    use super::*;
    use crate::curve::ParametricCurve;
    use crate::model::biarc::polar_plane;
    use glam::DVec4;
    use std::f64::consts::PI;

    fn solve(a: &Element, b: &Element, rule: Rule, region: Option<&Region>) -> Result<ConePair> {
        cone_pair(a, b, rule, region, ("a", "b"))
    }

    /// Elements of the oblique cone from the vertex `p` over the circle of radius 0.1 about
    /// (0, 0.15, 0.25) at angles `phi`: the ruling p → q(φ) with its tangent plane, the point
    /// at the ruling's middle (as a transition's corner strip has them).
    fn corner_cone_element(p: DVec3, phi: f64) -> Element {
        let q = DVec3::new(0.1 * phi.cos(), 0.15 + 0.1 * phi.sin(), 0.25);
        let dq = DVec3::new(-phi.sin(), phi.cos(), 0.0);
        let e = (q - p).normalize();
        let n = e.cross(dq).normalize();
        Element::from_frame(0.5 * (p + q), e, n.cross(e))
    }

    #[test]
    fn close_rulings_through_one_vertex_are_a_cone_pair() {
        let p = DVec3::new(-0.5, 0.3, -0.13);
        for dphi in [1e-3, 1e-4] {
            for phi in [0.3, 1.57, 2.9] {
                let (a, b) = (
                    corner_cone_element(p, phi),
                    corner_cone_element(p, phi + dphi),
                );
                let pair = solve(&a, &b, Rule::MinimalVertexDistance, None)
                    .unwrap_or_else(|e| panic!("dφ = {dphi:e} at {phi}: {e}"));
                assert_eq!(pair.case, PairCase::Cone, "dφ = {dphi:e} at {phi}");
                let v = pair.pieces[0].vertex().unwrap();
                assert!(v.distance(p) <= 1e-9, "dφ = {dphi:e}: vertex {v} for {p}");
            }
        }
    }

    fn on_plane(plane: DVec4, x: DVec3) -> f64 {
        plane.dot(x.extend(1.0)) / plane.truncate().length()
    }

    #[test]
    fn general_case_inscribed_sphere_biarc_and_polar_planes() {
        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.5, 1.5);
        let (a, b) = (surface.element(0.4).unwrap(), surface.element(0.6).unwrap());
        let pair = solve(&a, &b, Rule::MinimalVertexDistance, None).unwrap();
        assert_eq!(pair.case, PairCase::General);
        let (m, r) = pair.sphere.unwrap();
        // Σ touches both tangent planes at points of the rulings.
        for el in [&a, &b] {
            let foot = el.at(el.parameter_of(m));
            assert!(((m - foot).length() - r).abs() < 1e-12 * r.max(1.0));
            assert!((m - foot).cross(el.normal()).length() < 1e-10);
        }
        // Vertex distance |v₂ − v₁| = |μ₁ + μ₂| and locally minimal along (9).
        let (mu1, mu2) = match pair.mu.unwrap() {
            (Some(x), Some(y)) => (x, y),
            other => panic!("finite vertices expected, got {other:?}"),
        };
        let [first, second] = [pair.pieces[0], pair.pieces[1]];
        let (v1, v2) = (first.vertex().unwrap(), second.vertex().unwrap());
        assert!(((v2 - v1).length() - (mu1 + mu2).abs()).abs() < 1e-9);
        let arcs = pair.biarc.unwrap();
        let family = VertexFamily::new(arcs.a1, a.ruling, arcs.a2, b.ruling);
        let distance = |x: f64| (x + family.mu2(x).unwrap()).abs();
        let h = 1e-4 * mu1.abs().max(1.0);
        assert!(distance(mu1) <= distance(mu1 + h) && distance(mu1) <= distance(mu1 - h));
        // Polar planes of the biarc's Bézier points: the tangent planes at the bounding
        // rulings and the Bézier plane through both rulings (Fig. 1).
        let j = first.end();
        let plane_a = polar_plane(arcs.a1.extend(1.0), m, r);
        let plane_c = polar_plane(arcs.c.extend(1.0), m, r);
        let plane_b = polar_plane((arcs.b1 * arcs.w1).extend(arcs.w1), m, r);
        for t in [-1.0, 2.0] {
            assert!(on_plane(plane_a, a.at(t)).abs() < 1e-9);
            assert!(on_plane(plane_c, j.at(t)).abs() < 1e-9);
            assert!(on_plane(plane_b, a.at(t)).abs() < 1e-9);
            assert!(on_plane(plane_b, j.at(t)).abs() < 1e-9);
        }
        // The first cone's axis passes through m (it touches Σ).
        let k = first.axis();
        assert!((m - v1).cross(k).length() < 1e-9 * (m - v1).length());
        assert!(first.segment_angle() < 1.0 && second.segment_angle() < 1.0);
    }

    #[test]
    fn rules_pick_congruent_cylinder_and_given_solutions() {
        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.5, 1.5);
        let (a, b) = (surface.element(0.5).unwrap(), surface.element(0.8).unwrap());
        let congruent = solve(&a, &b, Rule::Congruent, None).unwrap();
        let (x, y) = (
            congruent.pieces[0].half_angle(),
            congruent.pieces[1].half_angle(),
        );
        assert!(
            (x - y).abs() < 1e-9,
            "congruent cones have equal half angles: {x} {y}"
        );
        let cylinder = solve(&a, &b, Rule::CylinderFirst, None).unwrap();
        assert_eq!(cylinder.pieces[0].kind(), PieceKind::Cylinder);
        assert_eq!(cylinder.pieces[1].kind(), PieceKind::Cone);
        let second = solve(&a, &b, Rule::CylinderSecond, None).unwrap();
        assert_eq!(second.pieces[1].kind(), PieceKind::Cylinder);
        let best = solve(&a, &b, Rule::MinimalVertexDistance, None).unwrap();
        let (mu1, _) = best.mu.unwrap();
        let given = solve(&a, &b, Rule::Given(mu1.unwrap() * 1.1), None).unwrap();
        let arcs = given.biarc.unwrap();
        let v1 = given.pieces[0].vertex().unwrap();
        assert!((v1 - (arcs.a1 + mu1.unwrap() * 1.1 * a.ruling)).length() < 1e-9);
    }

    fn assert_vertical_axes(pair: &ConePair) {
        for piece in &pair.pieces {
            let k = piece.axis();
            assert!(k.cross(DVec3::Z).length() < 1e-9, "axis {k}");
        }
    }

    #[test]
    fn constant_slope_case_has_parallel_axes() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.5,
            domain: (0.0, 6.0),
        };
        let surface = tangent_surface(&helix, 1.0, 2.0);
        let (a, b) = (surface.element(1.0).unwrap(), surface.element(1.6).unwrap());
        let pair = solve(&a, &b, Rule::MinimalVertexDistance, None).unwrap();
        assert_eq!(pair.case, PairCase::ConstantSlope);
        assert_vertical_axes(&pair);
        // Minimal vertex distance gives congruent cones here.
        assert!((pair.pieces[0].half_angle() - pair.pieces[1].half_angle()).abs() < 1e-9);
        // det(p₁, p₂) = 0: half a turn apart the principal normals are antiparallel, π is
        // spanned by p₁ and n₁ − n₂ (still horizontal).
        let (a, b) = (
            surface.element(1.0).unwrap(),
            surface.element(1.0 + PI).unwrap(),
        );
        assert!(a.side.cross(b.side).length() < 1e-9);
        let pair = solve(&a, &b, Rule::MinimalVertexDistance, None).unwrap();
        assert_eq!(pair.case, PairCase::ConstantSlope);
        assert_vertical_axes(&pair);
    }

    #[test]
    fn cone_cylinder_and_plane_cases() {
        // Rulings of the elliptic cone x²/4 + y² = z² through the origin.
        let ruling = |s: f64| DVec3::new(2.0 * s.cos(), s.sin(), 1.0);
        let side = |s: f64| DVec3::new(-2.0 * s.sin(), s.cos(), 0.0);
        let element = |s: f64, scale: f64| {
            let side = side(s) - side(s).dot(ruling(s).normalize()) * ruling(s).normalize();
            Element::new(scale * ruling(s), ruling(s), side, "el").unwrap()
        };
        let pair = solve(
            &element(0.2, 2.0),
            &element(0.7, 1.5),
            Rule::MinimalVertexDistance,
            None,
        )
        .unwrap();
        assert_eq!(pair.case, PairCase::Cone);
        for piece in &pair.pieces {
            assert!(piece.vertex().unwrap().length() < 1e-12);
        }
        // The far nappe: points behind the vertex, the side vectors reversed with them.
        let far = |s: f64| {
            let el = element(s, 1.0);
            Element::new(-el.point, el.ruling, el.side, "el").unwrap()
        };
        let pair = solve(&far(0.7), &far(0.2), Rule::MinimalVertexDistance, None).unwrap();
        assert!(pair.pieces.iter().all(|p| p.segment_angle() < 1.0));
        // A region around the common vertex contains every possible vertex.
        let region = Region::new(DVec3::splat(-0.1), DVec3::splat(0.1)).unwrap();
        let big = Region::new(DVec3::splat(-5.0), DVec3::splat(5.0)).unwrap();
        let err = solve(
            &element(0.2, 2.0),
            &element(0.7, 1.5),
            Rule::MinimalVertexDistance,
            Some(&big),
        )
        .unwrap_err();
        assert!(err.message().contains("every possible vertex"), "{err}");
        assert!(solve(
            &element(0.2, 2.0),
            &element(0.7, 1.5),
            Rule::MinimalVertexDistance,
            Some(&region)
        )
        .is_err());
        assert!(solve(
            &element(0.2, 2.0),
            &element(0.7, 1.5),
            Rule::CylinderFirst,
            None
        )
        .is_err());

        // Parallel rulings of the elliptic cylinder x²/4 + y² = 1.
        let el = |s: f64| {
            Element::new(
                DVec3::new(2.0 * s.cos(), s.sin(), 0.3 * s),
                DVec3::Z,
                side(s),
                "el",
            )
            .unwrap()
        };
        let pair = solve(&el(0.1), &el(0.9), Rule::MinimalVertexDistance, None).unwrap();
        assert_eq!(pair.case, PairCase::Cylinder);
        assert!(pair.pieces.iter().all(|p| p.kind() == PieceKind::Cylinder));

        // Equal tangent planes: one plane sector, one strip.
        let a = Element::new(DVec3::ZERO + DVec3::Y, DVec3::Y, DVec3::X, "a").unwrap();
        let b = Element::new(
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            "b",
        )
        .unwrap();
        let pair = solve(&a, &b, Rule::MinimalVertexDistance, None).unwrap();
        assert_eq!((pair.case, pair.pieces.len()), (PairCase::Plane, 1));
        assert!((pair.pieces[0].segment_angle() - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
        let c = Element::new(DVec3::new(2.0, 5.0, 0.0), DVec3::Y, DVec3::X, "c").unwrap();
        let pair = solve(&a, &c, Rule::MinimalVertexDistance, None).unwrap();
        assert_eq!(pair.pieces[0].kind(), PieceKind::Plane);
    }

    #[test]
    fn regions_exclude_vertices() {
        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.5, 1.5);
        let (a, b) = (surface.element(0.4).unwrap(), surface.element(0.7).unwrap());
        let free = solve(&a, &b, Rule::MinimalVertexDistance, None).unwrap();
        let v = free.pieces[0].vertex().unwrap();
        // A box around the default vertex but not the element points.
        let region = Region::new(v - DVec3::splat(0.02), v + DVec3::splat(0.02)).unwrap();
        let moved = solve(&a, &b, Rule::MinimalVertexDistance, Some(&region)).unwrap();
        for piece in &moved.pieces {
            assert!(piece.vertex().is_none_or(|v| !region.contains(v)));
        }
        assert!(moved.pieces[1].end().ruling.dot(b.ruling) > 1.0 - 1e-9);
        let given = solve(
            &a,
            &b,
            Rule::Given(free.mu.unwrap().0.unwrap()),
            Some(&region),
        );
        assert!(given.unwrap_err().message().contains("outside the region"));
    }

    /// The tangent surface of the helix (cos t, sin t, t/2), distances 1 to 2 from the curve:
    /// a constant-slope surface whose osculating cone at t has its vertex at the curve point.
    fn helix_surface() -> (Helix, f64, f64) {
        (
            Helix {
                radius: 1.0,
                pitch: 0.5,
                domain: (-1.0, 40.0),
            },
            1.0,
            2.0,
        )
    }

    /// Issue 13 item 6: rulings 0.001 apart (3,544 of 5,000 such pairs were NO_SOLUTION):
    /// every pair joins, G1 at the second element to the tolerance of the check, its
    /// vertices near the osculating cone's (the curve point, their limit as the rulings
    /// approach) and the pair within the Hermite error O(dt³) of the surface.
    #[test]
    fn close_rulings_of_a_helix_tangent_surface_join() {
        let (helix, v0, v1) = helix_surface();
        let surface = tangent_surface(&helix, v0, v1);
        let dt = 1e-3;
        let (mut join, mut vertex, mut deviation) = (0.0f64, 0.0f64, 0.0f64);
        for k in 0..5000 {
            let t = 0.004 + 0.006 * k as f64;
            let (a, b) = (
                surface.element(t).unwrap(),
                surface.element(t + dt).unwrap(),
            );
            let pair = solve(&a, &b, Rule::MinimalVertexDistance, None)
                .unwrap_or_else(|e| panic!("t = {t}: {e}"));
            assert_eq!(pair.case, PairCase::ConstantSlope, "t = {t}");
            let end = pair.pieces.last().unwrap().end();
            join = join
                .max((end.ruling - b.ruling).length())
                .max((end.normal() - b.normal()).length())
                .max((b.point - end.point).cross(end.ruling).length());
            let apex = helix.point_derivative(t + dt / 2.0).unwrap().0;
            for piece in &pair.pieces {
                vertex = vertex.max((piece.vertex().unwrap() - apex).length());
            }
            deviation = deviation.max(
                super::super::approximate::deviation(&surface, &pair.pieces, t, t + dt, 4).unwrap(),
            );
        }
        println!(
            "5,000 helix pairs at dt = 1e-3: G1 at the second element {join:.1e}, vertices \
             {vertex:.1e} from the curve point, deviation from the surface {deviation:.1e}"
        );
        assert!(join <= JOIN_TOLERANCE);
        assert!(vertex <= 10.0 * dt, "vertex {vertex:e}");
        assert!(deviation <= 10.0 * dt.powi(3), "deviation {deviation:e}");
    }

    /// The pair of `a`, `b` moved by x ↦ s·x + o against the pair itself moved so: the
    /// largest difference of vertices, end points, end rulings, end normals and segment
    /// angles (lengths relative to s), and that of the half angles.
    fn moved_pair_gap(a: &Element, b: &Element, s: f64, o: DVec3) -> Result<(f64, f64)> {
        let moved = |e: &Element| Element::from_frame(e.point * s + o, e.ruling, e.side);
        let reference = solve(a, b, Rule::MinimalVertexDistance, None)?;
        let pair = solve(&moved(a), &moved(b), Rule::MinimalVertexDistance, None)?;
        assert_eq!(pair.case, reference.case);
        assert_eq!(pair.pieces.len(), reference.pieces.len());
        // Compared relative to the scale before subtracting (no overflow at 1e200).
        let distance = |x: DVec3, y: DVec3| (x / s - (y * s + o) / s).length();
        let (mut gap, mut half) = (0.0f64, 0.0f64);
        for (p, q) in pair.pieces.iter().zip(&reference.pieces) {
            if let (Some(v), Some(w)) = (p.vertex(), q.vertex()) {
                gap = gap.max(distance(v, w));
            }
            let (e, f) = (p.end(), q.end());
            gap = gap
                .max(distance(e.point, f.point))
                .max((e.ruling - f.ruling).length())
                .max((e.normal() - f.normal()).length())
                .max((p.segment_angle() - q.segment_angle()).abs());
            half = half.max((p.half_angle() - q.half_angle()).abs());
        }
        Ok((gap, half))
    }

    /// Issue 13 item 6: a pair at t ≈ 28.69 failed and succeeded once moved by −8.607 in z.
    /// The pair is the same up to the translation, and up to scaling from 1e-200 to 1e200
    /// with offsets of 1e6 times the data's size.
    #[test]
    fn pairs_are_invariant_under_translation_and_scaling() {
        let (helix, v0, v1) = helix_surface();
        let surface = tangent_surface(&helix, v0, v1);
        let (a, b) = (
            surface.element(28.69).unwrap(),
            surface.element(28.691).unwrap(),
        );
        let (shifted, _) = moved_pair_gap(&a, &b, 1.0, DVec3::new(0.0, 0.0, -8.607)).unwrap();
        println!("t = 28.69 pair moved by -8.607 in z: {shifted:.1e}");
        assert!(shifted <= 1e-9, "{shifted:e}");
        let (mut worst, mut worst_half) = (0.0f64, 0.0f64);
        // Close rulings of the issue, and a wide pair.
        for (t, dt) in [(0.004, 1e-3), (28.69, 1e-3), (3.0, 0.3)] {
            let (a, b) = (
                surface.element(t).unwrap(),
                surface.element(t + dt).unwrap(),
            );
            for exponent in [-200, -100, -15, 0, 14, 15, 100, 200] {
                let s = 1.7 * 10f64.powi(exponent);
                for ratio in [0.0, 1e6] {
                    let o = DVec3::new(1.0, -2.0, 3.0).normalize() * (ratio * s * 30.0);
                    let (gap, half) = moved_pair_gap(&a, &b, s, o)
                        .unwrap_or_else(|e| panic!("t = {t}, scale {s:e}, offset {ratio:e}: {e}"));
                    // The data are rounded to ε·(30 + |o|/s); relative to the distance of
                    // the element points that rounding is ρ, and close rulings amplify ρ by
                    // 1/dt (the vertices lie 1/dt times that distance away).
                    let distance = (b.point - a.point).length();
                    let rho = f64::EPSILON * 30.0 * (1.0 + ratio) / distance;
                    let bound = 1e2 * rho / dt;
                    assert!(
                        gap <= bound,
                        "t = {t}, scale {s:e}, offset {ratio:e}: {gap:e}"
                    );
                    assert!(
                        half <= bound,
                        "t = {t}, scale {s:e}, offset {ratio:e}: half angle {half:e}"
                    );
                    if ratio == 0.0 {
                        worst = worst.max(gap);
                        worst_half = worst_half.max(half);
                    }
                }
            }
        }
        println!(
            "pairs scaled by 1.7e-200 … 1.7e200: largest gap {worst:.1e}, half angles {worst_half:.1e}"
        );
    }

    /// The closest points of the lines p + s·d and q + u·e.
    fn closest_points(p: DVec3, d: DVec3, q: DVec3, e: DVec3) -> (DVec3, DVec3) {
        let w = p - q;
        let (a, b, c, dd, ee) = (d.dot(d), d.dot(e), e.dot(e), d.dot(w), e.dot(w));
        let den = a * c - b * b;
        let (s, u) = ((b * ee - c * dd) / den, (a * ee - b * dd) / den);
        (p + s * d, q + u * e)
    }

    /// Theorem 1, checked on random G1 elements in general position with the library's
    /// pairs of the one-parameter family (Rule::Given μ₁) and geometry computed here: the
    /// cones of every member touch one sphere Σ (centre: where the two axes meet, the same
    /// for all members); the junction rulings touch Σ at points of one circle; they are
    /// rulings of one hyperboloid of revolution Φ about the line through m normal to that
    /// circle (equal distance R from the axis and equal q = ((p − m) × e)·N / (e·N)), and
    /// e₁, e₂ are rulings of the other regulus (distance R, −q); the junction tangent
    /// planes are the tangent planes of Σ at the touching points.
    #[test]
    fn theorem_1_sphere_hyperboloid_and_junction_circle() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut uniform = |lo: f64, hi: f64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            lo + (hi - lo) * (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut cases, mut worst) = (0, [0.0f64; 6]);
        while cases < 20 {
            let mut unit = || {
                DVec3::new(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0)).normalize()
            };
            let (e1, e2, q1, q2) = (unit(), unit(), unit(), unit());
            let p1 = (q1 - q1.dot(e1) * e1).normalize();
            let p2 = (q2 - q2.dot(e2) * e2).normalize();
            let x2 = DVec3::new(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0));
            let (Ok(a), Ok(b)) = (
                Element::new(DVec3::ZERO, e1, p1, "a"),
                Element::new(x2, e2, p2, "b"),
            ) else {
                continue;
            };
            let Ok(best) = solve(&a, &b, Rule::MinimalVertexDistance, None) else {
                continue;
            };
            if best.case != PairCase::General {
                continue;
            }
            let mu = best.mu.unwrap().0.unwrap();
            let members: Vec<ConePair> = [0.5, 0.8, 1.0, 1.3, 2.0, -0.7, 3.0]
                .iter()
                .filter_map(|&f| solve(&a, &b, Rule::Given(mu * f), None).ok())
                .filter(|p| p.pieces.len() == 2 && p.pieces.iter().all(|q| q.vertex().is_some()))
                .collect();
            if members.len() < 5 {
                continue;
            }
            cases += 1;
            let size = x2.length().max(1.0);
            // Σ: where the axes of the two cones meet, and its radius from the first plane.
            let centre = |pair: &ConePair| {
                let [c1, c2] = [pair.pieces[0], pair.pieces[1]];
                let (x, y) = closest_points(
                    c1.vertex().unwrap(),
                    c1.axis(),
                    c2.vertex().unwrap(),
                    c2.axis(),
                );
                ((x - y).length(), 0.5 * (x + y))
            };
            let (_, m) = centre(&members[0]);
            let r = (m - a.point).dot(a.normal()).abs();
            let mut touching = Vec::new();
            for pair in &members {
                let (gap, mi) = centre(pair);
                worst[0] = worst[0].max(gap / size).max((mi - m).length() / size);
                let j = pair.pieces[0].end();
                for plane in [a, b, j] {
                    worst[0] = worst[0]
                        .max(((m - plane.point).dot(plane.normal()).abs() - r).abs() / size);
                }
                // The junction ruling touches Σ at c, with the tangent plane of Σ there.
                let c = j.at(j.parameter_of(m));
                worst[1] = worst[1].max(((c - m).length() - r).abs() / size);
                worst[2] = worst[2].max((c - m).normalize().cross(j.normal()).length());
                touching.push((c, j));
            }
            // The circle: the plane of three touching points, the others in it.
            let (c0, c1, c2) = (touching[0].0, touching[1].0, touching[2].0);
            let n = (c1 - c0).cross(c2 - c0).normalize();
            for (c, _) in &touching {
                worst[3] = worst[3].max((*c - c0).dot(n).abs() / size);
            }
            // Φ about the line through m along n.
            let invariant = |point: DVec3, e: DVec3| {
                let (x, y) = closest_points(m, n, point, e);
                ((x - y).length(), (point - m).cross(e).dot(n) / e.dot(n))
            };
            let (radius, q) = invariant(touching[0].1.point, touching[0].1.ruling);
            for (_, j) in &touching {
                let (d, qj) = invariant(j.point, j.ruling);
                worst[4] = worst[4]
                    .max((d - radius).abs() / size)
                    .max((qj - q).abs() / size);
            }
            for el in [a, b] {
                let (d, qe) = invariant(el.point, el.ruling);
                worst[5] = worst[5]
                    .max((d - radius).abs() / size)
                    .max((qe + q).abs() / size);
            }
            // A line that is not a junction ruling is not a ruling of Φ: the test can fail.
            let j = touching[0].1;
            let tilted = DMat3::from_axis_angle(j.ruling.cross(n).normalize(), 1e-3) * j.ruling;
            let (d, qt) = invariant(j.point, tilted);
            assert!((d - radius).abs().max((qt - q).abs()) > 1e-6 * size);
        }
        println!(
            "Theorem 1 on {cases} random element pairs: common sphere {:.1e}, junctions touching Σ {:.1e}, \
             junction planes tangent to Σ {:.1e}, touching points coplanar {:.1e}, junctions on Φ {:.1e}, \
             e1, e2 on the other regulus {:.1e}",
            worst[0], worst[1], worst[2], worst[3], worst[4], worst[5]
        );
        assert!(worst.iter().all(|&w| w < 1e-7), "{worst:?}");
    }
}
