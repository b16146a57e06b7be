//! Osculating cone splines (Section "Osculating cone splines", Figs. 13–15): a sequence of
//! osculating cones Δᵢ of the surface, consecutive ones joined by one cone Δ each — the
//! spatial counterpart of the osculating arc splines of Meek and Walton.
//!
//! * The osculating cone along a ruling has its vertex at the point of regression and its
//!   axis along the Darboux vector d = τe + κn (3). For a tangent surface both come from
//!   the jet x', x'', x''' of the curve (exact for NURBS curves, differenced with a
//!   controlled step for callbacks: [`crate::curve::differenced_jet`]); for the other
//!   developables d is the angular velocity of the frame (e, p, n) of the elements
//!   (central differences of exactly evaluated rulings at steps h and h/2, extrapolated so
//!   that a jump of the frame's second derivative — at a knot, or where a cylindrical
//!   stretch ends and a conical one begins — leaves no error of order h), so that a cone
//!   Γ (axis through the fixed vertex, containing the osculating circle of the spherical
//!   curve) and a cylinder Γ (point of regression at infinity: an osculating cylinder, or
//!   the tangent plane at an inflection generator of a cylinder) come out of the same
//!   formula.
//! * Joining two cones: after translating the vertices to the origin the cones meet the
//!   unit sphere Σ in circles c₁, c₂ with planes Uᵢ and poles Qᵢ. Poles of filling circles
//!   lie on the conic I₁ in the plane V = U₁ + λU₂, λ = ±√((u₁² − u₁₀²)/(u₂² − u₂₀²));
//!   projecting c₁ (a rational quadratic in homogeneous parameters (t₀, t₁)) from Q₁ onto V
//!   and from there from Q₂ onto U₂ pairs the touching points c₁(t), c₂(t). A filling cone
//!   exists where the generators through v₁ and v₂ meet: det(c₁(t), c₂(t), v₁ − v₂) = 0,
//!   the homogeneous quartic (14), solved for all real roots on the whole projective line
//!   (t = 1 : 0 included). Of the candidates only the consistent ones are kept: the
//!   junction generators follow e₁ and precede e₂ in the sense of increasing parameters,
//!   with every segment angle below π/2; the least total angle wins.
//! * Special cases ("Special cases"): a common vertex (Γ a cone) makes (14) vanish
//!   identically, and a one-parameter family of filling cones remains (spherical
//!   osculating arc splines); congruent translated cones (parallel axes, equal opening
//!   angles: a surface of constant slope such as the tangent surface of a helix) have
//!   c₁ = c₂, and the filling cones are their translates with vertex on the conic
//!   Δ₁ ∩ Δ₂. In both families the member with equally long end segments is taken.
//! * An osculating cylinder (or plane) at either end, or cones congruent only to the
//!   accuracy of differenced derivatives (1e-6, not to rounding) without a consistent
//!   filling cone: a segment of each osculating
//!   cone/cylinder at its ruling (turning the tangent plane by a quarter of the turning
//!   between the rulings) and a G1 Hermite cone pair (Section "G1 Hermite elements")
//!   between their inner ends: G1, and osculating at both rulings (a plane: tangent only).
//! * Where no consistent filling cone exists (rulings too far apart), the interval is
//!   halved by the osculating cone at its midpoint, at most [`MAX_SUBDIVISIONS`] times.

use super::developable::Developable;
use super::element::Element;
use super::pair::joins;
use super::pair::{cone_pair, Rule};
use super::piece::{ConePiece, Motion};
use super::spline::ConeSpline;
use crate::error::{invalid, Error, ErrorKind, Result};
use crate::math::{angle_between, interior_midpoint, real_roots_in, robust_length, secant_refine};
use glam::{DMat3, DVec3, DVec4};
use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4, PI};

/// The osculating cone (or cylinder) along one ruling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct OsculatingCone {
    /// The ruling with its tangent plane.
    pub element: Element,
    /// The point of regression; `None` for an osculating cylinder (axis along the ruling)
    /// or, at an inflection generator of a cylinder, the tangent plane (axis its normal).
    pub vertex: Option<DVec3>,
    /// A point on the axis (the vertex, or the cylinder's centre line; the element point
    /// for a plane).
    pub origin: DVec3,
    /// Unit axis direction (the Darboux vector's).
    pub axis: DVec3,
}

impl OsculatingCone {
    #[cfg(test)]
    /// Half angle α (π/2 at an inflection generator, where the cone is the tangent plane).
    pub(crate) fn half_angle(&self) -> f64 {
        self.axis
            .dot(self.element.ruling)
            .abs()
            .clamp(0.0, 1.0)
            .acos()
    }
}

/// The osculating cone of `surface` along the ruling at t: from the jet of the line of
/// regression for a tangent surface, else from the frames of the elements.
pub(crate) fn osculating_cone(surface: &dyn Developable, t: f64) -> Result<OsculatingCone> {
    let el = surface.element(t)?;
    match surface.regression_jet(t) {
        Some(jet) => Ok(darboux_cone(el, jet?)),
        None => frame_cone(surface, el, t),
    }
}

/// The osculating cone with vertex x and axis d = τe + κb (3), from the jet of the line of
/// regression: d ∥ (τ/κ) e + b with τ/κ = det(x', x'', x''') |x'|³ / |x' × x''|³, computed
/// from the derivatives divided by |x'| (τ/κ does not change with the curve's size). The
/// element has already checked the curvature (a tangent plane exists).
fn darboux_cone(el: Element, [x, d1, d2, d3]: [DVec3; 4]) -> OsculatingCone {
    let s = robust_length(d1);
    let (e, u2, u3) = (d1 / s, d2 / s, d3 / s);
    let b = e.cross(u2);
    let ratio = e.dot(u2.cross(u3)) / b.length().powi(3);
    OsculatingCone {
        element: el,
        vertex: Some(x),
        origin: x,
        axis: (ratio * e + b.normalize()).normalize(),
    }
}

/// The osculating cone from the angular velocity ω of the frame (e, p, n) of the elements
/// and the normal velocity of the ruling (differences of the elements).
///
/// The differences are central (one-sided at the ends of the domain) with steps h and h/2,
/// extrapolated to 2D(h/2) − D(h). That removes the error linear in h, which a central
/// difference has where the second derivative of the frame jumps: at a knot of a cubic
/// B-spline of planes, and in particular at the last ruling of a cylindrical stretch,
/// where e' = 0 but D(h) sees the cone beyond and turns the osculating cylinder into a
/// cone with its vertex some 1/h away.
fn frame_cone(surface: &dyn Developable, el: Element, t: f64) -> Result<OsculatingCone> {
    let (lo, hi) = surface.domain();
    // Normal velocity of the ruling line at the element point.
    let nearest = |x: &Element| x.at(x.parameter_of(el.point));
    let differences = |h: f64| -> Result<[DVec3; 4]> {
        let (a, b) = ((t - h).max(lo), (t + h).min(hi));
        let (ea, eb) = (surface.element(a)?, surface.element(b)?);
        let dt = b - a;
        Ok([
            (eb.ruling - ea.ruling) / dt,
            (eb.side - ea.side) / dt,
            (eb.normal() - ea.normal()) / dt,
            (nearest(&eb) - nearest(&ea)) / dt,
        ])
    };
    let h = 1e-5 * (hi - lo);
    let (coarse, fine) = (differences(h)?, differences(0.5 * h)?);
    let [de, dp, dn, motion] = [0, 1, 2, 3].map(|k| 2.0 * fine[k] - coarse[k]);
    let omega = 0.5 * (el.ruling.cross(de) + el.side.cross(dp) + el.normal().cross(dn));
    let speed = motion.dot(el.side);
    let turning = de.dot(el.side);
    if turning.abs() <= 1e-9 * omega.length().max(1e-300) {
        let spin = omega.dot(el.ruling);
        if spin.abs() <= 1e-12 * speed.abs() {
            // An inflection generator of a cylinder: the osculating cylinder is the plane.
            return Ok(OsculatingCone {
                element: el,
                vertex: None,
                origin: el.point,
                axis: el.normal(),
            });
        }
        // Rotation ω_e about the axis through o = x + ρn moves x with ω_e ρ p.
        return Ok(OsculatingCone {
            element: el,
            vertex: None,
            origin: el.point + speed / spin * el.normal(),
            axis: el.ruling,
        });
    }
    let vertex = el.at(-speed / turning);
    // ω has no p-component for a developable (the Darboux vector τe + κn); dropping the
    // differencing noise keeps the cone exactly tangent to the element's plane.
    Ok(OsculatingCone {
        element: el,
        vertex: Some(vertex),
        origin: vertex,
        axis: (omega - omega.dot(el.side) * el.side).normalize(),
    })
}

/// The Bézier points (homogeneous, (x, y, z, w)) of a quarter of the circle in which the
/// cone with unit axis k through the origin meets the unit sphere, starting at the unit
/// ruling e: any quarter parameterizes the whole circle over the projective line.
fn circle_quarter(k: DVec3, e: DVec3) -> [DVec4; 3] {
    let centre = e.dot(k) * k;
    let end = DMat3::from_axis_angle(k, FRAC_PI_2) * e;
    let corner = centre + (e - centre) + (end - centre);
    [
        e.extend(1.0),
        (corner * FRAC_1_SQRT_2).extend(FRAC_1_SQRT_2),
        end.extend(1.0),
    ]
}

/// Power-basis coefficients (in t = t₁/t₀, t₀ = 1) of the homogeneous quadratic
/// (t₀ − t₁)²B₀ + 2t₁(t₀ − t₁)B₁ + t₁²B₂.
fn power_form(b: &[DVec4; 3]) -> [DVec4; 3] {
    [b[0], 2.0 * (b[1] - b[0]), b[0] - 2.0 * b[1] + b[2]]
}

fn evaluate(b: &[DVec4; 3], t0: f64, t1: f64) -> DVec3 {
    let h = (t0 - t1) * (t0 - t1) * b[0] + 2.0 * t1 * (t0 - t1) * b[1] + t1 * t1 * b[2];
    h.truncate() / h.w
}

/// The real roots (t₀ : t₁) of the homogeneous quartic Σ qₖ t₀^(4−k) t₁ᵏ on the projective
/// line: |t| ≤ 1 from q(t), the rest from the reversed polynomial in s = t₀/t₁.
fn projective_roots(q: &[f64; 5]) -> Vec<(f64, f64)> {
    let mut roots: Vec<(f64, f64)> = real_roots_in(q, -1.0, 1.0)
        .into_iter()
        .map(|t| (1.0, t))
        .collect();
    let reversed: Vec<f64> = q.iter().rev().copied().collect();
    roots.extend(
        real_roots_in(&reversed, -1.0, 1.0)
            .into_iter()
            .filter(|s| s.abs() < 1.0)
            .map(|s| (s, 1.0)),
    );
    roots
}

/// Junction generators (x₁, x₂) as a function of one affine parameter of the projective line.
type Chart<'a> = Box<dyn Fn(f64) -> (DVec3, DVec3) + 'a>;

/// The axis of an osculating cone oriented towards its ruling (k · e ≥ 0).
fn oriented_axis(c: &OsculatingCone) -> DVec3 {
    if c.axis.dot(c.element.ruling) < 0.0 {
        -c.axis
    } else {
        c.axis
    }
}

/// Largest difference of the unit axes and of the cosines of the half angles for which two
/// osculating cones count as congruent translates (constant slope).
const CONGRUENT: f64 = 1e-9;

/// Congruent translates up to 1e-6 (the accuracy of differenced derivatives), but not to
/// rounding (1e-13), where the translated filling cones are exact and only the spacing can
/// make them inconsistent.
fn nearly_congruent(d1: &OsculatingCone, d2: &OsculatingCone) -> bool {
    let (k1, k2) = (oriented_axis(d1), oriented_axis(d2));
    let (c1, c2) = (k1.dot(d1.element.ruling), k2.dot(d2.element.ruling));
    let difference = (k1 - k2).length().max((c1 - c2).abs());
    difference <= 1e-6 && difference > 1e-13
}

/// The filling cones of congruent translated cones Δ₁, Δ₂ (axis k, cos α = c; "Special
/// cases"): the translates Δ of Δ₁ whose vertex v lies on the conic Δ₁ ∩ Δ₂. Such a Δ
/// touches Δ₁ along the line v₁v and Δ₂ along v₂v (translates share the tangent planes of
/// parallel generators). With v = v₁ + λg, g = c k + s(cos θ a + sin θ b) the generator of
/// Λ₁ at angle θ and w = v₂ − v₁, v − v₂ on Λ gives the linear equation
/// λ · 2c(c g·w − k·w) = c²|w|² − (k·w)².
fn constant_slope_candidates(
    d1: &OsculatingCone,
    d2: &OsculatingCone,
    scale: f64,
) -> Vec<[ConePiece; 3]> {
    let (Some(v1), Some(v2)) = (d1.vertex, d2.vertex) else {
        return Vec::new();
    };
    let k = oriented_axis(d1);
    let e1 = d1.element.ruling;
    let c = k.dot(e1);
    if c <= 1e-12 {
        return Vec::new(); // planes: the surface is flat here
    }
    let a = (e1 - c * k).normalize();
    let (b, s) = (k.cross(a), (e1 - c * k).length());
    let w = v2 - v1;
    let chart = |x: f64| {
        let (sin, cos) = (PI * x).sin_cos();
        let g = c * k + s * (cos * a + sin * b);
        let lambda =
            (c * c * w.length_squared() - k.dot(w).powi(2)) / (2.0 * c * (c * g.dot(w) - k.dot(w)));
        let y = (v1 + lambda * g - v2).normalize();
        (g, if y.dot(k) < 0.0 { -y } else { y })
    };
    let mut out = Vec::new();
    for sign in [1.0, -1.0] {
        for x in symmetric_parameters(d1, d2, &chart, sign) {
            out.extend(consistent_join(d1, d2, &chart, x, sign, scale, false));
        }
    }
    out
}

/// Pieces Δ₁ (from e₁ to the junction), Δ (the filling cone), Δ₂ (from the junction to e₂)
/// for every real root of (14) on both conics, consistent ones only.
fn joining_candidates(d1: &OsculatingCone, d2: &OsculatingCone) -> Result<Vec<[ConePiece; 3]>> {
    let (Some(v1), Some(v2)) = (d1.vertex, d2.vertex) else {
        return Err(Error::invalid_input(
            "the quartic (14) joins osculating cones, not cylinders",
        ));
    };
    let (k1, k2) = (oriented_axis(d1), oriented_axis(d2));
    let (e1, e2) = (d1.element.ruling, d2.element.ruling);
    let (c1, c2) = (k1.dot(e1), k2.dot(e2));
    let (s1, s2) = ((1.0 - c1 * c1).sqrt(), (1.0 - c2 * c2).sqrt());
    if s1 <= 1e-12 || s2 <= 1e-12 {
        return Err(Error::no_solution(
            "a degenerate osculating cone (half angle 0)",
        ));
    }
    let scale = v1.abs().max_element().max(v2.abs().max_element()).max(1.0);
    if (k1 - k2).length() <= CONGRUENT && (c1 - c2).abs() <= CONGRUENT && !common_vertex(v1, v2) {
        return Ok(constant_slope_candidates(d1, d2, scale));
    }
    let (u1, u2) = (k1.extend(-c1), k2.extend(-c2));
    let (q1, q2) = (k1.extend(c1), k2.extend(c2));
    let arc1 = circle_quarter(k1, e1);
    let mut out = Vec::new();
    for lambda in [s1 / s2, -s1 / s2] {
        let v = u1 + lambda * u2;
        let onto_v = |x: DVec4| v.dot(q1) * x - v.dot(x) * q1;
        let onto_u2 = |x: DVec4| u2.dot(q2) * x - u2.dot(x) * q2;
        let arc2 = arc1.map(|b| onto_u2(onto_v(b)));
        let (p1, p2) = (power_form(&arc1), power_form(&arc2));
        let mut quartic = [0.0; 5];
        for i in 0..3 {
            for j in 0..3 {
                quartic[i + j] += p1[i].truncate().cross(p2[j].truncate()).dot(v1 - v2);
            }
        }
        // A common vertex (the surface is a cone): (14) vanishes identically and the
        // filling cones form a one-parameter family, the spherical osculating arc splines;
        // a symmetric member is taken (see `symmetric_parameters`).
        let roots = if common_vertex(v1, v2) {
            Vec::new()
        } else {
            projective_roots(&quartic)
        };
        // x₂ snapped onto c₂: the two projections lose digits for nearly equal cones.
        let onto_c2 = |y: DVec3| c2 * k2 + s2 * (y - y.dot(k2) * k2).normalize();
        let generators =
            |(t0, t1): (f64, f64)| (evaluate(&arc1, t0, t1), onto_c2(evaluate(&arc2, t0, t1)));
        for sign in [1.0, -1.0] {
            if common_vertex(v1, v2) {
                let chart = |x: f64| generators((1.0, x));
                for x in symmetric_parameters(d1, d2, &chart, sign) {
                    out.extend(consistent_join(d1, d2, &chart, x, sign, scale, false));
                }
            }
            for &(t0, t1) in &roots {
                // The affine chart of the projective line in which the root is finite.
                let (chart, x): (Chart, f64) = if t0.abs() >= t1.abs() {
                    (Box::new(|x: f64| generators((1.0, x))), t1 / t0)
                } else {
                    (Box::new(|x: f64| generators((x, 1.0))), t0 / t1)
                };
                out.extend(consistent_join(
                    d1,
                    d2,
                    chart.as_ref(),
                    x,
                    sign,
                    scale,
                    true,
                ));
            }
        }
    }
    Ok(out)
}

/// The three pieces for the junction generators x₁ on Δ₁ and x₂ on Δ₂ (the filling cone's
/// last generator oriented by `sign`), without the G1 check at e₂.
fn three_pieces(
    d1: &OsculatingCone,
    d2: &OsculatingCone,
    (x1, x2): (DVec3, DVec3),
    sign: f64,
) -> Option<[ConePiece; 3]> {
    let (v1, v2) = (d1.vertex?, d2.vertex?);
    if !(x1.is_finite() && x2.is_finite()) || (x1 - x2).length() < 1e-9 {
        return None; // a common generator of Λ₁ and Λ₂: no filling cone
    }
    if common_vertex(v1, v2) {
        // The vertex where the two rulings meet, more accurate than either point of
        // regression from differences.
        let (a, b) = (&d1.element, &d2.element);
        let w = a.ruling.cross(b.ruling);
        let v = a.at((b.point - a.point).cross(b.ruling).dot(w) / w.length_squared());
        let first = ConePiece::cone(v, *a, x1).ok()?;
        let filler = ConePiece::cone(v, first.end(), sign * x2).ok()?;
        let last = ConePiece::cone(v, filler.end(), b.ruling).ok()?;
        return Some([first, filler, last]);
    }
    // The filling vertex: where the generators v₁ + a x₁ and v₂ + b x₂ meet (closest point
    // on the first). Its last ruling is drawn through v₂ itself, so that the three pieces
    // chain exactly; what remains of a root's error shows in the tangent plane at e₂.
    let first = ConePiece::cone(v1, d1.element, x1).ok()?;
    let w = x1.cross(x2);
    let v = v1 + (v2 - v1).cross(x2).dot(w) / w.length_squared() * x1;
    let through_v2 = (v2 - v) * (v2 - v).dot(x2).signum();
    let filler = ConePiece::cone(v, first.end(), sign * through_v2).ok()?;
    let last = ConePiece::cone(v2, filler.end(), d2.element.ruling).ok()?;
    Some([first, filler, last])
}

/// The pieces of a root of (14), kept if G1 at e₂ and consistent: every segment angle
/// below π/2, so that the junction generators follow e₁ and precede e₂ without winding
/// round a cone (the other roots give fillers of angle ≈ π on the far nappe). For neighbouring, nearly equal osculating cones the plane V = U₁ + λU₂ and the
/// quartic lose digits to cancellation; since the three pieces chain exactly for every
/// parameter (the filling cone's last ruling is drawn through v₂), the root is polished by
/// secant steps on the one remaining condition, the tangent plane at e₂.
fn consistent_join(
    d1: &OsculatingCone,
    d2: &OsculatingCone,
    generators: &dyn Fn(f64) -> (DVec3, DVec3),
    x0: f64,
    sign: f64,
    scale: f64,
    polish: bool,
) -> Option<[ConePiece; 3]> {
    let target = &d2.element;
    let residual = |x: f64| {
        three_pieces(d1, d2, generators(x), sign).map(|p| p[2].end().tangent_plane_angle(target))
    };
    let polished = if polish {
        let rough = secant_refine(&residual, x0, 1e-9 * x0.abs().max(1.0), 12);
        nearest_best(&residual, rough)
    } else {
        x0
    };
    // Only a correction of the root's round-off: a step far from it would find a G1
    // configuration whose last piece is not the osculating cone Δ₂.
    let x = if (polished - x0).abs() <= 1e-4 * (1.0 + x0.abs()) {
        polished
    } else {
        x0
    };
    let pieces = three_pieces(d1, d2, generators(x), sign)?;
    joins(&pieces[2].end(), target, scale).ok()?;
    pieces
        .iter()
        .all(|p| p.segment_angle() < FRAC_PI_2)
        .then_some(pieces)
}

/// The parameter of least |residual| among `x` and its neighbours within 64 steps of 2⁻⁴⁷
/// relative: the chart parameter is ill-conditioned for neighbouring osculating cones (the
/// residual's slope turns the rounding of one such step into 1e-11 rad, and the rounding
/// of the three pieces makes it noisy at that level), so where the secant stops the best
/// of the nearby floats is taken rather than the first one it lands on.
fn nearest_best(residual: &dyn Fn(f64) -> Option<f64>, x: f64) -> f64 {
    let step = x.abs().max(f64::MIN_POSITIVE) * 2f64.powi(-47);
    (-64..=64)
        .map(|k| x + f64::from(k) * step)
        .filter_map(|y| residual(y).map(|r| (y, r.abs())))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(x, |(y, _)| y)
}

/// Relative distance below which two osculating cones count as sharing their vertex.
const COMMON_VERTEX: f64 = 1e-8;

fn common_vertex(v1: DVec3, v2: DVec3) -> bool {
    (v1 - v2).length()
        <= COMMON_VERTEX * v1.abs().max_element().max(v2.abs().max_element()).max(1.0)
}

/// Parameters (in the chart t₀ = 1, |t| ≤ 1) of the member of the one-parameter family of
/// filling cones for osculating cones with a common vertex: the segments taken from Δ₁ and
/// Δ₂ equally long — or, for mirror-symmetric Δ₁, Δ₂ where they always are, the filling
/// segment as long as both together.
fn symmetric_parameters(
    d1: &OsculatingCone,
    d2: &OsculatingCone,
    generators: &dyn Fn(f64) -> (DVec3, DVec3),
    sign: f64,
) -> Vec<f64> {
    let angles = |x: f64| {
        three_pieces(d1, d2, generators(x), sign)
            .filter(|p| p.iter().all(|q| q.segment_angle() < FRAC_PI_2))
            .map(|p| p.map(|q| q.segment_angle()))
    };
    let equal_ends = |x: f64| angles(x).map(|[a, _, c]| a - c);
    let balanced = |x: f64| angles(x).map(|[a, b, c]| a + c - b);
    let xs: Vec<f64> = (0..=400).map(|k| -1.0 + k as f64 / 200.0).collect();
    let symmetric = xs
        .iter()
        .filter_map(|&x| equal_ends(x))
        .all(|g| g.abs() < 1e-9);
    if symmetric {
        sign_changes(&xs, &balanced)
    } else {
        sign_changes(&xs, &equal_ends)
    }
}

/// The roots of `f` between consecutive samples `xs` where it changes sign (bisection).
fn sign_changes(xs: &[f64], f: &dyn Fn(f64) -> Option<f64>) -> Vec<f64> {
    let mut out = Vec::new();
    for w in xs.windows(2) {
        let (Some(fa), Some(fb)) = (f(w[0]), f(w[1])) else {
            continue;
        };
        if (fa < 0.0) == (fb < 0.0) {
            continue;
        }
        let (mut a, mut b) = (w[0], w[1]);
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            match f(m) {
                Some(fm) if (fm < 0.0) == (fa < 0.0) => a = m,
                Some(_) => b = m,
                None => break,
            }
        }
        out.push(0.5 * (a + b));
    }
    out
}

/// Joins two osculating cones by the most useful consistent filling cone (three pieces),
/// or, where one is a cylinder or plane, by osculating segments and a Hermite cone pair.
pub(crate) fn join_osculating(d1: &OsculatingCone, d2: &OsculatingCone) -> Result<Vec<ConePiece>> {
    if d1.vertex.is_none() || d2.vertex.is_none() {
        return hermite_join(d1, d2);
    }
    let candidates = joining_candidates(d1, d2)?;
    if candidates.is_empty() && nearly_congruent(d1, d2) {
        // Constant slope seen through differenced derivatives: the translated filling
        // cones miss G1 by the derivatives' error (beyond the join tolerance), and (14)
        // is too ill-conditioned to replace them.
        return hermite_join(d1, d2);
    }
    candidates
        .into_iter()
        .min_by(|a, b| {
            let total = |p: &[ConePiece; 3]| p.iter().map(ConePiece::segment_angle).sum::<f64>();
            total(a).total_cmp(&total(b))
        })
        .map(Vec::from)
        .ok_or_else(|| {
            Error::no_solution(
                "no consistent filling cone joins the two osculating cones (rulings too far apart)",
            )
        })
}

/// A segment of the osculating cone or cylinder `d` at its ruling that turns the tangent
/// plane by `turn` (a rotation about the axis by φ turns the normal by φ|k × n|), capped
/// at π/4: towards larger parameters (`forward`) it starts at the ruling, else it ends
/// there. `None` for a plane, whose tangent plane does not turn.
fn osculating_segment(d: &OsculatingCone, turn: f64, forward: bool) -> Option<ConePiece> {
    let el = d.element;
    let rate = d.axis.cross(el.normal()).length();
    if rate <= 1e-12 || turn <= 0.0 {
        return None;
    }
    let towards_side = d.axis.cross(el.point - d.origin).dot(el.side).signum();
    let angle = towards_side * (turn / rate).min(FRAC_PI_4);
    let motion = |angle: f64| Motion::Rotation {
        origin: d.origin,
        axis: d.axis,
        angle,
    };
    let start = if forward {
        el
    } else {
        motion(-angle).element(&el, 1.0)
    };
    Some(ConePiece {
        start,
        motion: motion(angle),
    })
}

/// Osculating segments at both rulings (a quarter of the tangent plane's turning each) and
/// a G1 cone pair between their inner ends: G1, osculating at the rulings of cones and
/// cylinders, tangent at those of planes.
fn hermite_join(d1: &OsculatingCone, d2: &OsculatingCone) -> Result<Vec<ConePiece>> {
    let turn = 0.25 * angle_between(d1.element.normal(), d2.element.normal());
    let first = osculating_segment(d1, turn, true);
    let last = osculating_segment(d2, turn, false);
    let a = first.map_or(d1.element, |p| p.end());
    let b = last.map_or(d2.element, |p| p.start);
    let pair = cone_pair(&a, &b, Rule::MinimalVertexDistance, None, ("e1", "e2"))?;
    Ok(first.into_iter().chain(pair.pieces).chain(last).collect())
}

/// Halvings of an interval between given osculating cones before joining fails.
pub(crate) const MAX_SUBDIVISIONS: usize = 6;

/// One piece for two consecutive pieces on the same cone (same axis line), else `None`.
fn merged(a: &ConePiece, b: &ConePiece) -> Option<ConePiece> {
    match (a.motion, b.motion) {
        (
            Motion::Rotation {
                origin: o1,
                axis: k1,
                angle: t1,
            },
            Motion::Rotation {
                origin: o2,
                axis: k2,
                angle: t2,
            },
        ) => {
            let scale = o1.abs().max_element().max(1.0);
            let same_line =
                k1.cross(k2).length() <= 1e-9 && (o2 - o1).cross(k1).length() <= 1e-9 * scale;
            let t2 = if k1.dot(k2) < 0.0 { -t2 } else { t2 };
            let one = ConePiece {
                start: a.start,
                motion: Motion::Rotation {
                    origin: o1,
                    axis: k1,
                    angle: t1 + t2,
                },
            };
            // The merged piece must end where b does: axes equal only to 1e-9 (cones from
            // differenced derivatives) would move the far end by more than the chain allows.
            (same_line && t1.signum() == t2.signum() && joins(&one.end(), &b.end(), scale).is_ok())
                .then_some(one)
        }
        _ => None,
    }
}

/// The osculating cone spline through the osculating cones at the parameters `ts`
/// (increasing, at least 2): segments of the osculating cones joined by filling cones.
/// Intervals whose cones cannot be joined are halved by further osculating cones, at most
/// `MAX_SUBDIVISIONS` times (NotConverged beyond).
pub fn osculating_spline(surface: &dyn Developable, ts: &[f64]) -> Result<ConeSpline> {
    osculating_spline_with(surface, ts, MAX_SUBDIVISIONS)
}

fn osculating_spline_with(
    surface: &dyn Developable,
    ts: &[f64],
    subdivisions: usize,
) -> Result<ConeSpline> {
    if ts.len() < 2 || ts.windows(2).any(|w| w[0] >= w[1] || w[0].is_nan()) {
        return invalid!("an osculating cone spline needs at least 2 increasing parameters");
    }
    let cones = ts
        .iter()
        .map(|&t| osculating_cone(surface, t).map(|c| (t, c)))
        .collect::<Result<Vec<_>>>()?;
    let mut pieces: Vec<ConePiece> = Vec::new();
    for w in cones.windows(2) {
        join_interval(surface, w[0], w[1], subdivisions, &mut pieces)?;
    }
    ConeSpline::new(pieces)
}

/// Appends the pieces joining the osculating cones at a and b, halving the interval while
/// no consistent filling cone exists (at most `depth` times).
fn join_interval(
    surface: &dyn Developable,
    (ta, a): (f64, OsculatingCone),
    (tb, b): (f64, OsculatingCone),
    depth: usize,
    out: &mut Vec<ConePiece>,
) -> Result<()> {
    // From the ruling and tangent plane where the spline so far ends (a's to the join
    // tolerance), so that the junction errors do not add up along the chain; the
    // reference point stays a's (its foot on that ruling).
    let mut a = a;
    if let Some(last) = out.last() {
        let end = last.end();
        let foot = end.at(end.parameter_of(a.element.point));
        a.element = Element::from_frame(foot, end.ruling, end.side);
    }
    match join_osculating(&a, &b) {
        Ok(joined) => {
            append(out, joined);
            Ok(())
        }
        Err(e) if e.is(ErrorKind::NoSolution) => {
            let Some(tm) = interior_midpoint(ta, tb).filter(|_| depth > 0) else {
                return Err(Error::not_converged(format!(
                    "the osculating cones at t = {ta} and t = {tb} cannot be joined after \
                     {MAX_SUBDIVISIONS} halvings of the given interval: {}",
                    e.message()
                )));
            };
            let m = (tm, osculating_cone(surface, tm)?);
            join_interval(surface, (ta, a), m, depth - 1, out)?;
            join_interval(surface, m, (tb, b), depth - 1, out)
        }
        Err(e) => Err(e),
    }
}

/// Appends pieces, merging the first with the last one so far where they lie on the same
/// cone (the osculating segments on either side of a ruling).
fn append(out: &mut Vec<ConePiece>, pieces: Vec<ConePiece>) {
    let mut pieces = pieces.into_iter();
    if let Some(first) = pieces.next() {
        match out.last().and_then(|previous| merged(previous, &first)) {
            Some(one) => *out.last_mut().expect("checked") = one,
            None => out.push(first),
        }
    }
    out.extend(pieces);
}

#[cfg(test)]
mod tests {
    use super::super::approximate::deviation;
    use super::super::developable::DualDevelopable;
    use super::super::test_support::{
        dual_cone_planes, tangent_surface, twisted_cubic, Helix, OnlyTangents,
    };
    use super::*;
    use crate::cone_spline::pair::Rule;
    use crate::curve::{uniform_parameters, ParametricCurve};

    #[test]
    fn osculating_cones_follow_the_darboux_vector() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.5,
            domain: (0.0, 6.0),
        };
        let surface = tangent_surface(&helix, 0.5, 1.0);
        let cone = osculating_cone(&surface, 2.0).unwrap();
        let (x, _) = helix.point_derivative(2.0).unwrap();
        assert!((cone.vertex.unwrap() - x).length() < 1e-15);
        assert!(cone.axis.cross(DVec3::Z).length() < 1e-15, "{}", cone.axis);
        // cos α = τ/|d| with κ = r/(r² + c²), τ = c/(r² + c²): tan α = r / c.
        assert!((cone.half_angle() - (1.0f64 / 0.5).atan()).abs() < 1e-14);
        // The same helix as a callback: the differenced jet.
        let callback = OnlyTangents(helix);
        let surface = tangent_surface(&callback, 0.5, 1.0);
        let cone = osculating_cone(&surface, 2.0).unwrap();
        let error = cone.axis.cross(DVec3::Z).length();
        println!("callback helix: axis error {error:.2e}");
        assert!(error < 1e-7, "{error}");

        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.5, 1.0);
        let t = 0.7f64;
        let cone = osculating_cone(&surface, t).unwrap();
        let (d1, d2, d3) = (
            DVec3::new(1.0, 2.0 * t, 3.0 * t * t),
            DVec3::new(0.0, 2.0, 6.0 * t),
            DVec3::new(0.0, 0.0, 6.0),
        );
        let b = d1.cross(d2);
        let (kappa, tau) = (
            b.length() / d1.length().powi(3),
            b.dot(d3) / b.length_squared(),
        );
        let darboux = tau * d1.normalize() + kappa * b.normalize();
        assert!(cone.axis.cross(darboux.normalize()).length() < 1e-14, "(3)");
        assert!((cone.vertex.unwrap() - DVec3::new(t, t * t, t * t * t)).length() < 1e-15);
    }

    /// A screw flight: the tangent surface of the helix r = 1, pitch 0.5 over three turns.
    /// Its osculating cones are congruent translates; the filling cones are translates too
    /// (vertex on Δ₁ ∩ Δ₂), so every piece has the axis z and tan α = r / c = 2.
    #[test]
    fn screw_flights_are_joined_by_translated_cones() {
        let helix = Helix {
            radius: 1.0,
            pitch: 0.5,
            domain: (0.0, 6.0 * PI),
        };
        let surface = tangent_surface(&helix, 0.5, 1.5);
        let mut previous = f64::INFINITY;
        for cones in [25, 49, 97] {
            let ts = uniform_parameters(helix.domain, cones);
            let spline = osculating_spline(&surface, &ts).unwrap();
            for p in spline.pieces() {
                assert!(p.axis().cross(DVec3::Z).length() < 1e-10, "{}", p.axis());
                assert!((p.half_angle() - 2f64.atan()).abs() < 1e-10);
            }
            let pieces = spline.pieces().len();
            let error = deviation(&surface, spline.pieces(), 0.0, 6.0 * PI, 2400).unwrap();
            println!("screw flight: {cones} cones, {pieces} pieces, max deviation {error:.3e}");
            // 2n − 1: the osculating segments on either side of each eᵢ merge.
            assert_eq!(pieces, 2 * cones - 1);
            assert!(error < if cones == 25 { 1e-3 } else { previous / 8.0 });
            previous = error;
        }
        // Quarter turns apart no filling cone is consistent: the midpoints are inserted,
        // which gives the spline of eighth turns.
        let spline = osculating_spline(&surface, &uniform_parameters(helix.domain, 13));
        assert_eq!(spline.unwrap().pieces().len(), 49);
        // The helix as a callback: differenced derivatives, congruent to 1e-11 only; where
        // the translated filling cones miss G1 (near the ends, one-sided differences) the
        // osculating segments and a Hermite pair join.
        let callback = OnlyTangents(helix);
        let surface = tangent_surface(&callback, 0.5, 1.5);
        let spline = osculating_spline(&surface, &uniform_parameters((0.0, 6.0 * PI), 25)).unwrap();
        let error = deviation(&surface, spline.pieces(), 0.0, 6.0 * PI, 2400).unwrap();
        println!(
            "callback screw flight: 25 cones, {} pieces, max deviation {error:.3e}",
            spline.pieces().len()
        );
        assert!(error < 1e-3, "{error}");
    }

    /// A general cylinder (dual form, planes parallel to z): its osculating cylinders are
    /// joined by osculating segments and Hermite cone pairs. The first piece osculates: its
    /// distance from the surface grows with the cube of the parameter (a tangent cylinder
    /// with another radius: the square).
    #[test]
    fn osculating_cylinders_are_joined() {
        let region =
            crate::cone_spline::Region::new(DVec3::new(-3.0, -3.0, 0.0), DVec3::new(3.0, 3.0, 1.0))
                .unwrap();
        let planes = [
            DVec4::new(1.0, 0.0, 0.0, -1.0),
            DVec4::new(1.0, 1.0, 0.0, -1.5),
            DVec4::new(0.0, 1.0, 0.0, -1.0),
        ];
        let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        let cylinder = DualDevelopable::new(2, &planes, &knots, region).unwrap();
        let cone = osculating_cone(&cylinder, 0.3).unwrap();
        assert!(cone.vertex.is_none() && cone.axis.cross(DVec3::Z).length() < 1e-12);
        let spline = osculating_spline(&cylinder, &uniform_parameters((0.0, 1.0), 4)).unwrap();
        let error = deviation(&cylinder, spline.pieces(), 0.0, 1.0, 400).unwrap();
        println!(
            "osculating, general cylinder: 4 cylinders, {} pieces, max deviation {error:.3e}",
            spline.pieces().len()
        );
        assert!(error < 1e-3, "{error}");
        let first = spline.pieces()[0];
        assert_eq!(first.kind(), crate::cone_spline::PieceKind::Cylinder);
        let gap = |t: f64| first.distance(cylinder.ruling(t).unwrap().point);
        let ratio = gap(0.02) / gap(0.01);
        println!("contact: gap(0.02) / gap(0.01) = {ratio:.3}");
        assert!((7.0..9.0).contains(&ratio), "{ratio}");
    }

    /// Osculating cones too far apart are joined through the osculating cones at interval
    /// midpoints; without halvings the same data fail as not converged.
    #[test]
    fn widely_spaced_cones_are_subdivided() {
        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.5, 1.0);
        let far = uniform_parameters((0.2, 1.2), 3);
        let spline = osculating_spline(&surface, &far).unwrap();
        let error = deviation(&surface, spline.pieces(), 0.2, 1.2, 400).unwrap();
        println!(
            "osculating, 3 cones: {} pieces, max deviation {error:.3e}",
            spline.pieces().len()
        );
        assert!(spline.pieces().len() > 6 && error < 1e-2, "{error}");
        let refused = osculating_spline_with(&surface, &far, 0).unwrap_err();
        assert!(refused.is(ErrorKind::NotConverged), "{refused}");
    }

    /// A developable that is a general cylinder on t ∈ [0, 1] and a cone-like surface on
    /// [1, 2]: the dual form of a cubic B-spline of planes (knots 0⁴ 1 2⁴) whose first four
    /// control planes are vertical and whose fifth is tilted. The span [0, 1] has only
    /// vertical planes (rulings along z: osculating cylinders); on (1, 2] the fifth plane's
    /// weight (t − 1)³ tilts them, and the point of regression comes in from infinity
    /// (distance ∝ 1/(t − 1)). The planes are C² across t = 1, so the surface is smooth
    /// there and the osculating elements change from cylinders to cones continuously.
    /// The region is the box 6 × 6 × 1 above z = 0; the line of regression runs below it.
    fn cylinder_then_cone() -> (DualDevelopable, crate::cone_spline::Region) {
        let region =
            crate::cone_spline::Region::new(DVec3::new(-3.0, -3.0, 0.0), DVec3::new(3.0, 3.0, 1.0))
                .unwrap();
        let plane = |theta: f64, tilt: f64| {
            let (s, c) = f64::sin_cos(theta);
            DVec4::new(c, s, tilt, -1.0)
        };
        let planes = [
            plane(0.0, 0.0),
            plane(0.4, 0.0),
            plane(0.8, 0.0),
            plane(1.2, 0.0),
            plane(1.6, -0.6),
        ];
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0, 2.0];
        (
            DualDevelopable::new(3, &planes, &knots, region).unwrap(),
            region,
        )
    }

    /// The velocity of the point `x` under the motion of `piece` (per unit sweep fraction).
    fn velocity(piece: &ConePiece, x: DVec3) -> DVec3 {
        match piece.motion {
            Motion::Rotation {
                origin,
                axis,
                angle,
            } => angle * axis.cross(x - origin),
            Motion::Translation(v) => v,
        }
    }

    /// The largest defects of G1 continuity between consecutive pieces, measured on the
    /// pieces' own surfaces rather than on the stored side vectors: the distance of the
    /// end ruling of piece k (its start swept by its motion) from the start ruling of piece
    /// k + 1 at the points `offsets` along it, and the angle between the tangent planes
    /// there, each from its own piece's motion (ruling × the velocity of the point).
    fn g1_defects(pieces: &[ConePiece], offsets: &[f64]) -> (f64, f64) {
        let (mut gap, mut angle) = (0.0f64, 0.0f64);
        for w in pieces.windows(2) {
            let (a, b) = (w[0].end(), w[1].start);
            gap = gap.max((a.ruling - b.ruling).length());
            for &u in offsets {
                let x = a.at(u);
                gap = gap.max((x - b.point).cross(b.ruling).length());
                let oriented = |n: DVec3| {
                    let n = n.normalize();
                    if n.dot(a.normal()) < 0.0 {
                        -n
                    } else {
                        n
                    }
                };
                let na = oriented(a.ruling.cross(velocity(&w[0], x)));
                let nb = oriented(b.ruling.cross(velocity(&w[1], x)));
                let between = angle_between(na, nb);
                assert!(
                    between.is_finite(),
                    "a piece without a tangent plane at {x}"
                );
                angle = angle.max(between);
            }
        }
        (gap, angle)
    }

    /// A developable that is cylindrical on one stretch and conical on the next: its
    /// osculating elements are cylinders on [0, 1] and cones on (1, 2], so the spline mixes
    /// both joins (osculating segments and a Hermite pair next to a cylinder, filling cones
    /// between cones). G1 is measured on the pieces' own surfaces; the deviation from the
    /// surface over its region falls with the third power of the spacing. Odd counts put an
    /// element on t = 1, the last cylinder (which central differences alone saw as a cone
    /// with its vertex 1.4e4 away, and which then could not be joined from 33 elements on);
    /// even counts straddle it.
    #[test]
    fn mixed_cylinders_and_cones_are_joined_g1() {
        let (surface, region) = cylinder_then_cone();
        assert!(osculating_cone(&surface, 1.0).unwrap().vertex.is_none());
        for t in [1.01, 1.5, 2.0] {
            let vertex = osculating_cone(&surface, t).unwrap().vertex.unwrap();
            assert!(
                !region.contains(vertex),
                "the line of regression avoids the region"
            );
        }
        let offsets = [-0.5, 0.0, 0.5];
        let mut odd = Vec::new();
        for cones in [9, 17, 33, 65, 16, 32, 64] {
            let ts = uniform_parameters((0.0, 2.0), cones);
            let spline = osculating_spline(&surface, &ts).unwrap();
            let cylinders = ts
                .iter()
                .filter(|&&t| osculating_cone(&surface, t).unwrap().vertex.is_none())
                .count();
            let kinds = |kind| spline.pieces().iter().filter(|p| p.kind() == kind).count();
            let (gap, angle) = g1_defects(spline.pieces(), &offsets);
            let error = deviation(&surface, spline.pieces(), 0.0, 2.0, 1600).unwrap();
            println!(
                "cylinder then cone: {cones} elements ({cylinders} cylinders), {} pieces \
                 ({} cylinders, {} cones), G1 gap {gap:.1e}, angle {angle:.1e} rad, \
                 max deviation {error:.3e}",
                spline.pieces().len(),
                kinds(crate::cone_spline::PieceKind::Cylinder),
                kinds(crate::cone_spline::PieceKind::Cone),
            );
            assert!(cylinders > 0 && cylinders < cones, "{cylinders} of {cones}");
            assert!(kinds(crate::cone_spline::PieceKind::Cylinder) > 0);
            assert!(kinds(crate::cone_spline::PieceKind::Cone) > 0);
            assert!(
                gap <= 1e-12 && angle <= 1e-10,
                "G1: gap {gap:e}, angle {angle:e}"
            );
            assert!(error <= 1e-3, "{error}");
            if cones % 2 == 1 {
                odd.push((cones, error));
            }
        }
        for w in odd.windows(2) {
            let spacing = (w[1].0 - 1) as f64 / (w[0].0 - 1) as f64;
            let order = (w[0].1 / w[1].1).ln() / spacing.ln();
            println!(
                "cylinder then cone: {} → {} elements, order {order:.2}",
                w[0].0, w[1].0
            );
            assert!(order >= 2.5, "order {order}");
        }
        // The check can fail: the axis of one cone piece turned about its start ruling by
        // 1e-8 rad breaks G1.
        let ts = uniform_parameters((0.0, 2.0), 17);
        let mut pieces = osculating_spline(&surface, &ts).unwrap().pieces().to_vec();
        let k = (pieces.len() / 2..pieces.len())
            .find(|&k| pieces[k].kind() == crate::cone_spline::PieceKind::Cone)
            .unwrap();
        let turn = DMat3::from_axis_angle(pieces[k].start.ruling, 1e-8);
        if let Motion::Rotation { axis, .. } = &mut pieces[k].motion {
            *axis = turn * *axis;
        }
        let (gap, angle) = g1_defects(&pieces, &offsets);
        println!("perturbed piece {k}: gap {gap:.1e}, angle {angle:.1e} rad");
        assert!(gap > 1e-12 || angle > 1e-10);
    }

    #[test]
    fn osculating_cone_splines_against_hermite_pairs() {
        let curve = twisted_cubic(0.2, 1.2);
        let surface = tangent_surface(&curve, 0.5, 1.0);
        let mut previous = f64::INFINITY;
        for cones in [8, 11, 16, 21] {
            let ts = uniform_parameters((0.2, 1.2), cones);
            let spline = osculating_spline(&surface, &ts).unwrap();
            // 2n − 1 pieces when the osculating segments on either side of eᵢ merge into one.
            let pieces = spline.pieces().len();
            assert!(
                (2 * cones - 1..=3 * cones - 2).contains(&pieces),
                "{pieces} pieces"
            );
            let error = deviation(&surface, spline.pieces(), 0.2, 1.2, 400).unwrap();
            let hermite = |elements: usize| {
                let ts = uniform_parameters((0.2, 1.2), elements);
                let els: Vec<_> = ts.iter().map(|&t| surface.element(t).unwrap()).collect();
                let (spline, _) =
                    ConeSpline::hermite(&els, Rule::MinimalVertexDistance, None).unwrap();
                (
                    spline.pieces().len(),
                    deviation(&surface, spline.pieces(), 0.2, 1.2, 400).unwrap(),
                )
            };
            let (below, above) = (hermite(pieces / 2), hermite(pieces / 2 + 1));
            println!(
                "osculating: {cones} cones, {pieces} pieces, max deviation {error:.3e}; \
                 Hermite cone pairs: {} pieces {:.3e}, {} pieces {:.3e}",
                below.0, below.1, above.0, above.1
            );
            assert!(error < previous, "the error decreases with more cones");
            previous = error;
        }
        // A cone Γ (the dual quadratic cone): every osculating cone has Γ's vertex, and a
        // spherical osculating arc spline joins them.
        let region =
            crate::cone_spline::Region::new(DVec3::new(-3.0, -3.0, 1.0), DVec3::new(3.0, 3.0, 2.0))
                .unwrap();
        let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        let cone = DualDevelopable::new(2, &dual_cone_planes(), &knots, region).unwrap();
        let vertex = osculating_cone(&cone, 0.5).unwrap().vertex.unwrap();
        assert!(
            vertex.length() < 1e-8,
            "the osculating cone of a cone has its vertex: {vertex}"
        );
        let spherical = osculating_spline(&cone, &uniform_parameters((0.0, 1.0), 6)).unwrap();
        let error = deviation(&cone, spherical.pieces(), 0.0, 1.0, 400).unwrap();
        println!(
            "osculating, cone Γ: 6 cones, {} pieces, max deviation {error:.3e}",
            spherical.pieces().len()
        );
        assert!(spherical
            .pieces()
            .iter()
            .all(|p| p.vertex().unwrap().length() < 1e-7));
        assert!(error < 1e-3);
    }
}
