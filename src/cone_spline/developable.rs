//! The developable surfaces a cone spline approximates (Section "Fundamentals"), each seen
//! as a one-parameter family of rulings with their tangent planes over a region of
//! interest along the rulings:
//!
//! * the tangent surface of a space curve, (1) with l the curve and e its unit tangent
//!   (a NURBS curve or a caller's callback), region: distances [v₀, v₁] from the curve
//!   point, 0 ∉ [v₀, v₁];
//! * a ruled NURBS surface of degree (1, n), rulings along u (e.g. spanned between two
//!   rails); developability (2) is checked by measuring its own Gaussian curvature;
//! * the dual form (4): a B-spline curve of control planes U(t); rulings U ∩ U̇, the region
//!   a box Ω.
//!
//! From the rulings alone, [`Developable::element`] derives G1 Hermite elements with a side
//! vector pointing towards increasing parameters, and the generic code below finds the
//! inflection generators (where the osculating cone is a plane: the normal stops turning,
//! ṅ · p changes sign; zero torsion of the line of regression for tangent surfaces).

use super::element::Element;
use super::region::Region;
use crate::bezier::{NurbsCurve, PiecewiseCurve, PiecewiseSurface};
use crate::curve::{uniform_parameters, ParametricCurve};
use crate::error::no_solution;
use crate::error::{invalid, Error, Result};
use crate::frames::metrics::gaussian_curvature;
use glam::{DVec3, DVec4};

/// One ruling of a developable over the region of interest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ruling {
    /// The middle of the region on the ruling.
    pub point: DVec3,
    /// Unit direction, continuous in the parameter.
    pub direction: DVec3,
    /// A normal of the tangent plane (either sign).
    pub normal: DVec3,
    /// The region: signed distances from `point` along the ruling.
    pub range: (f64, f64),
}

/// A developable surface as a family of rulings.
pub trait Developable {
    /// The parameter interval of the rulings.
    fn domain(&self) -> (f64, f64);

    /// The ruling at parameter t.
    fn ruling(&self, t: f64) -> Result<Ruling>;

    /// The G1 element at t: the ruling with its mid-region point and the side vector of the
    /// tangent plane that points to where the rulings of larger parameters lie (seen from
    /// that point: the sign of the ruling's normal velocity).
    fn element(&self, t: f64) -> Result<Element> {
        let r = self.ruling(t)?;
        let q = r.normal.cross(r.direction).normalize();
        let (lo, hi) = self.domain();
        let h = 1e-6 * (hi - lo);
        let (a, b) = ((t - h).max(lo), (t + h).min(hi));
        let nearest = |s: f64| -> Result<DVec3> {
            let n = self.ruling(s)?;
            Ok(n.point + (r.point - n.point).dot(n.direction) * n.direction)
        };
        let motion = (nearest(b)? - nearest(a)?).dot(q);
        if motion.is_nan() || motion == 0.0 {
            return no_solution!(
                "the rulings do not move at t = {t}: the surface is singular there"
            );
        }
        Ok(Element::from_frame(
            r.point,
            r.direction,
            q * motion.signum(),
        ))
    }

    /// The point at signed distance v from the element point along the ruling at t.
    fn point(&self, t: f64, v: f64) -> Result<DVec3> {
        let r = self.ruling(t)?;
        Ok(r.point + v * r.direction)
    }
}

/// Parameters of the inflection generators inside the domain: sign changes of ṅ · p on
/// `samples` uniform rulings, refined by bisection.
pub fn inflection_generators(surface: &dyn Developable, samples: usize) -> Result<Vec<f64>> {
    let (lo, hi) = surface.domain();
    let h = 1e-5 * (hi - lo);
    let turning = |t: f64| -> Result<f64> {
        let el = surface.element(t)?;
        let (a, b) = ((t - h).max(lo), (t + h).min(hi));
        Ok((surface.element(b)?.normal() - surface.element(a)?.normal()).dot(el.side))
    };
    let ts = uniform_parameters((lo, hi), samples.max(3));
    let values = ts.iter().map(|&t| turning(t)).collect::<Result<Vec<_>>>()?;
    let mut roots = Vec::new();
    for k in 0..ts.len() - 1 {
        let (mut a, mut b, fa) = (ts[k], ts[k + 1], values[k]);
        if fa == 0.0 || (fa < 0.0) == (values[k + 1] < 0.0) || values[k + 1] == 0.0 {
            continue;
        }
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            if (turning(m)? < 0.0) == (fa < 0.0) {
                a = m;
            } else {
                b = m;
            }
        }
        let t = 0.5 * (a + b);
        if t - lo > 1e-3 * (hi - lo) && hi - t > 1e-3 * (hi - lo) {
            roots.push(t);
        }
    }
    Ok(roots)
}

/// Every algorithm steps through a developable in fractions of its domain's length, which
/// must therefore be a finite f64 (a property-test finding: a domain of length beyond
/// f64::MAX made the derivative stencil infinite and panicked).
fn check_domain_length((lo, hi): (f64, f64)) -> Result<()> {
    if (hi - lo).is_finite() {
        Ok(())
    } else {
        invalid!("the parameter domain [{lo}, {hi}] has a length beyond the largest f64")
    }
}

/// The tangent surface x(t) + v e(t) of a regular space curve over v ∈ [v₀, v₁].
pub struct TangentSurface<'a> {
    curve: &'a dyn ParametricCurve,
    distances: (f64, f64),
}

impl<'a> TangentSurface<'a> {
    /// The region must stay off the curve (its edge of regression): 0 ∉ [v₀, v₁].
    pub fn new(curve: &'a dyn ParametricCurve, v_min: f64, v_max: f64) -> Result<Self> {
        if !(v_min.is_finite() && v_max.is_finite()) || v_min >= v_max {
            return invalid!("v_min = {v_min}, v_max = {v_max} must be finite with v_min < v_max");
        }
        check_domain_length(curve.domain())?;
        if v_min <= 0.0 && v_max >= 0.0 {
            return invalid!(
                "v_min = {v_min} .. v_max = {v_max} contains 0: the region must not reach the curve, \
                 the singular edge of its tangent surface"
            );
        }
        Ok(Self {
            curve,
            distances: (v_min, v_max),
        })
    }

    /// x, x' and x'' at t: x'' as the derivative of the quartic through the exact x' at
    /// five equidistant parameters around t, kept inside the domain (fourth order, error
    /// ~1e-12 relative, also at the ends of the domain). The spacing is 1e-3 of the domain,
    /// divided by 4 until the tangent turns by at most 0.05 rad across the five: a step
    /// relative to the domain alone is a whole turn of a 1,000-turn helix (whose x' is then
    /// the same at all five, x'' zero). The turning is measured from the first node to the
    /// last and to an incommensurable one (a golden-section fraction of the way), so that no
    /// periodic curve hides it.
    pub fn derivatives(&self, t: f64) -> Result<[DVec3; 3]> {
        const GOLDEN: f64 = 0.381_966_011_250_105_1;
        let (lo, hi) = self.curve.domain();
        let mut h = 1e-3 * (hi - lo);
        let (x, d1) = self.curve.point_derivative(t)?;
        let turning = |h: f64| -> Result<f64> {
            let first = t.clamp(lo + 2.0 * h, hi - 2.0 * h) - 2.0 * h;
            // Unit tangents: the angle of derivatives of size 1e200 would overflow.
            let tangent = |s: f64| -> Result<DVec3> {
                let d = self.curve.point_derivative(first + s * 4.0 * h)?.1;
                Ok(crate::math::robust_normalize(d).unwrap_or(DVec3::ZERO))
            };
            let (a, m, b) = (tangent(0.0)?, tangent(GOLDEN)?, tangent(1.0)?);
            let angle = crate::math::angle_between;
            Ok(angle(a, m).max(angle(a, b)))
        };
        while h > 1e-9 * (hi - lo) && turning(h)? > 0.05 {
            h *= 0.25;
        }
        let centre = t.clamp(lo + 2.0 * h, hi - 2.0 * h);
        let nodes = [-2.0, -1.0, 0.0, 1.0, 2.0];
        let at = (t - centre) / h;
        let mut d2 = DVec3::ZERO;
        for (j, &xj) in nodes.iter().enumerate() {
            // Derivative of the Lagrange basis polynomial of node j at `at`.
            let others = || {
                nodes
                    .iter()
                    .enumerate()
                    .filter(move |&(k, _)| k != j)
                    .map(|(_, &xk)| xk)
            };
            let denominator: f64 = others().map(|xk| xj - xk).product();
            let derivative: f64 = others()
                .map(|skip| {
                    others()
                        .filter(|&xk| xk != skip)
                        .map(|xk| at - xk)
                        .product::<f64>()
                })
                .sum();
            d2 += self.curve.point_derivative(centre + xj * h)?.1 * (derivative / denominator);
        }
        Ok([x, d1, d2 / h])
    }
}

impl Developable for TangentSurface<'_> {
    fn domain(&self) -> (f64, f64) {
        self.curve.domain()
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        let [x, d1, d2] = self.derivatives(t)?;
        // Directions first: |x'| |x''| under- or overflows for curves of size 1e-200 or
        // 1e200 (d1 and d2 scale with the curve).
        let unit = |v: DVec3| crate::math::robust_normalize(v).unwrap_or(DVec3::ZERO);
        let (e, e2) = (unit(d1), unit(d2));
        let binormal = e.cross(e2);
        if binormal.length() <= 1e-10 || binormal.is_nan() {
            return no_solution!(
                "the curve has zero curvature at t = {t}: its tangent surface has no tangent plane there"
            );
        }
        let (v0, v1) = self.distances;
        let mid = 0.5 * (v0 + v1);
        Ok(Ruling {
            point: x + mid * e,
            direction: e,
            normal: binormal.normalize(),
            range: (v0 - mid, v1 - mid),
        })
    }
}

/// A ruled NURBS surface of degree (1, n) with rulings along u, checked to be developable.
pub struct RuledSurface {
    surface: PiecewiseSurface,
}

/// Largest |K|·size² accepted as developable (size: bounding-box diagonal).
pub const DEVELOPABILITY_TOLERANCE: f64 = 1e-6;

impl RuledSurface {
    /// A degree (1, n) surface with one interval in u (a NURBS with degree_u = 1 and
    /// pole_count_u = 2), whose measured |K|·size² does not exceed
    /// [`DEVELOPABILITY_TOLERANCE`].
    pub fn new(surface: PiecewiseSurface) -> Result<Self> {
        let linear = surface.patches().iter().all(|p| p.degree_u() == 1);
        if !linear || surface.u_breaks().len() != 2 {
            return invalid!(
                "a developable ruled surface needs degree_u = 1 and pole_count_u = 2 (rulings along u)"
            );
        }
        check_domain_length(surface.domain_v())?;
        let k = max_scaled_curvature(&surface);
        if k > DEVELOPABILITY_TOLERANCE || k.is_nan() {
            return invalid!(
                "the surface is not developable: its Gaussian curvature reaches |K|·size² = {k:.3e} \
                 (size = bounding-box diagonal; at most {DEVELOPABILITY_TOLERANCE:.0e} is accepted)"
            );
        }
        Ok(Self { surface })
    }
}

/// max |K|·size² over a grid of 9 × 8 points per patch.
pub fn max_scaled_curvature(surface: &PiecewiseSurface) -> f64 {
    let us = uniform_parameters(surface.domain_u(), 9);
    let vs: Vec<f64> = surface
        .v_breaks()
        .windows(2)
        .flat_map(|w| (0..8).map(move |j| w[0] + (w[1] - w[0]) * (j as f64 + 0.5) / 8.0))
        .collect();
    let (mut lo, mut hi, mut k) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0.0f64);
    for &u in &us {
        for &v in &vs {
            let jet = surface.eval_jet(u, v);
            lo = lo.min(jet.point);
            hi = hi.max(jet.point);
            k = k.max(gaussian_curvature(&jet).abs());
        }
    }
    k * (hi - lo).length_squared()
}

impl Developable for RuledSurface {
    fn domain(&self) -> (f64, f64) {
        self.surface.domain_v()
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        let (u0, u1) = self.surface.domain_u();
        let (a, b) = (self.surface.eval(u0, t), self.surface.eval(u1, t));
        let half = 0.5 * (b - a).length();
        if half.is_nan() || half == 0.0 {
            return no_solution!("the ruling at v = {t} has zero length");
        }
        let jet = self.surface.eval_jet(0.5 * (u0 + u1), t);
        Ok(Ruling {
            point: 0.5 * (a + b),
            direction: (b - a).normalize(),
            normal: jet.du.cross(jet.dv),
            range: (-half, half),
        })
    }
}

/// The dual form (4): a B-spline curve of planes U(t) = (u₀(t), u(t)), u₀ + u·x = 0, with
/// the region of interest a box.
pub struct DualDevelopable {
    normals: PiecewiseCurve,
    offsets: PiecewiseCurve,
    region: Region,
}

impl DualDevelopable {
    /// `planes` are (u₁, u₂, u₃, u₀) in glam's (x, y, z, w) order; `knots` clamped.
    pub fn new(degree: usize, planes: &[DVec4], knots: &[f64], region: Region) -> Result<Self> {
        if let Some(i) = planes.iter().position(|u| !u.is_finite()) {
            return invalid!("planes[{i}] has a non-finite coordinate");
        }
        let normals = planes.iter().map(|u| u.truncate()).collect();
        let offsets = planes.iter().map(|u| DVec3::new(u.w, 0.0, 0.0)).collect();
        let curve = |poles| NurbsCurve::new(degree, poles, None, knots.to_vec())?.to_piecewise();
        let normals = curve(normals)?;
        check_domain_length(normals.domain())?;
        Ok(Self {
            normals,
            offsets: curve(offsets)?,
            region,
        })
    }
}

impl Developable for DualDevelopable {
    fn domain(&self) -> (f64, f64) {
        self.normals.domain()
    }

    fn ruling(&self, t: f64) -> Result<Ruling> {
        let (n, o) = (self.normals.eval_jet(t), self.offsets.eval_jet(t));
        let (u, du, u0, du0) = (n.point, n.d1, o.point.x, o.d1.x);
        let d = u.cross(du);
        if d.length() <= 1e-12 * u.length() * du.length() || d.is_nan() {
            return no_solution!(
                "U(t) and U'(t) are parallel at t = {t}: no ruling (the planes do not turn)"
            );
        }
        // The point of U ∩ U̇ in the span of u and u̇: a u + b u̇ with u·x = −u₀, u̇·x = −u̇₀.
        let (g11, g12, g22) = (u.dot(u), u.dot(du), du.dot(du));
        let det = g11 * g22 - g12 * g12;
        let a = (-u0 * g22 + du0 * g12) / det;
        let b = (-du0 * g11 + u0 * g12) / det;
        let x = a * u + b * du;
        let e = d.normalize();
        let (lo, hi) = self.region.clip_line(x, e).ok_or_else(|| {
            Error::no_solution(format!("the ruling at t = {t} misses the region box"))
        })?;
        let mid = 0.5 * (lo + hi);
        Ok(Ruling {
            point: x + mid * e,
            direction: e,
            normal: u,
            range: (lo - mid, hi - mid),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A line on a domain whose length overflows.
    struct WideLine;

    impl ParametricCurve for WideLine {
        fn domain(&self) -> (f64, f64) {
            (-1e308, 1e308)
        }

        fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
            Ok((DVec3::X * t, DVec3::X))
        }
    }

    #[test]
    fn domains_whose_length_overflows_are_refused() {
        let e = TangentSurface::new(&WideLine, 0.5, 1.0).err().unwrap();
        assert!(e.message().contains("beyond the largest f64"), "{e}");
        let planes = [DVec4::X, DVec4::Y, DVec4::Z];
        let knots = [-1e308, -1e308, -1e308, 1e308, 1e308, 1e308];
        let region = Region::new(DVec3::splat(-1.0), DVec3::ONE).unwrap();
        let e = DualDevelopable::new(2, &planes, &knots, region)
            .err()
            .unwrap();
        assert!(e.message().contains("beyond the largest f64"), "{e}");
    }
}
