//! Biarcs: two circular arcs joined with a common tangent, interpolating two points with
//! tangent directions (Fuhs & Stachel; eqs. (7)–(8)). On the inscribed sphere Σ they are the
//! spherical biarcs along which a cone pair touches Σ (general and cone case); in a plane
//! they are the planar biarcs of the cylinder and constant-slope cases (Fig. 10).
//!
//! With b₁ = a₁ + λ₁p₁ and b₂ = a₂ − λ₂p₂ the legs of each arc are equal, which gives the
//! bilinear relation (7) between λ₁ and λ₂, the junction point (8), and the inner weights
//! |wᵢ| = |(bᵢ − aᵢ)·(c − aᵢ)| / (|bᵢ − aᵢ||c − aᵢ|), negative for λᵢ < 0 (the
//! complementary arc). The Bézier planes of a cone segment are the polar planes of these
//! Bézier points with respect to Σ.

use glam::DVec3;
#[cfg(test)]
use glam::DVec4;

/// A biarc a₁, b₁, c, b₂, a₂ with the weights of b₁ and b₂ (end weights 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Biarc {
    pub a1: DVec3,
    pub b1: DVec3,
    pub c: DVec3,
    pub b2: DVec3,
    pub a2: DVec3,
    pub w1: f64,
    pub w2: f64,
    pub lambda1: f64,
    pub lambda2: f64,
}

/// λ₂ for a given λ₁ by (7), or `None` where the relation has a pole (λ₂ = ∞).
pub(crate) fn partner_lambda(
    a1: DVec3,
    p1: DVec3,
    a2: DVec3,
    p2: DVec3,
    lambda1: f64,
) -> Option<f64> {
    let d = a2 - a1;
    let denominator = 2.0 * d.dot(p2) - 2.0 * lambda1 * (p1.dot(p2) - 1.0);
    let numerator = d.length_squared() - 2.0 * lambda1 * d.dot(p1);
    (denominator.abs() > 1e-14 * numerator.abs().max(1e-300)).then(|| numerator / denominator)
}

/// The positive λ with λ₁ = λ₂ = λ in (7) (the biarc with equal tangent lengths):
/// |d|² − 2λ d·(p₁ + p₂) + 2λ²(p₁·p₂ − 1) = 0, whose roots have opposite signs.
pub(crate) fn equal_lambda(a1: DVec3, p1: DVec3, a2: DVec3, p2: DVec3) -> Option<f64> {
    let d = a2 - a1;
    crate::math::quadratic_roots(
        2.0 * (p1.dot(p2) - 1.0),
        -2.0 * d.dot(p1 + p2),
        d.length_squared(),
    )
    .into_iter()
    .filter(|&l| l > 0.0 && l.is_finite())
    .fold(None, |best: Option<f64>, l| {
        Some(best.map_or(l, |b| b.min(l)))
    })
}

/// The biarc for λ₁, λ₂ satisfying (7): junction point (8) and signed weights.
pub(crate) fn biarc(
    a1: DVec3,
    p1: DVec3,
    a2: DVec3,
    p2: DVec3,
    lambda1: f64,
    lambda2: f64,
) -> Biarc {
    let (b1, b2) = (a1 + lambda1 * p1, a2 - lambda2 * p2);
    let c = (lambda2 * b1 + lambda1 * b2) / (lambda1 + lambda2);
    let weight = |a: DVec3, b: DVec3, lambda: f64| {
        let (u, v) = (b - a, c - a);
        let w = u.dot(v).abs() / (u.length() * v.length());
        if lambda > 0.0 {
            w
        } else {
            -w
        }
    };
    Biarc {
        a1,
        b1,
        c,
        b2,
        a2,
        w1: weight(a1, b1, lambda1),
        w2: weight(a2, b2, lambda2),
        lambda1,
        lambda2,
    }
}

/// λ of the arc from `a` (tangent `p`) through the junction `c`: the leg length for which
/// |a + λp − c| = |λ|, λ = |c − a|² / (2 (c − a)·p).
pub(crate) fn lambda_through(a: DVec3, p: DVec3, c: DVec3) -> f64 {
    (c - a).length_squared() / (2.0 * (c - a).dot(p))
}

#[cfg(test)]
/// The polar plane of the homogeneous point `y` (xyz = y₀·y, w = y₀) with respect to the
/// sphere (x − m)² = r², as plane coordinates (u₁, u₂, u₃, u₀) in glam's (x, y, z, w) order,
/// so that a homogeneous point X lies on it iff `plane.dot(X) = 0`:
/// (x − x₀m)·(y − y₀m) = r² x₀ y₀.
pub(crate) fn polar_plane(y: DVec4, centre: DVec3, radius: f64) -> DVec4 {
    let q = y.truncate() - y.w * centre;
    q.extend(-centre.dot(q) - radius * radius * y.w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::RationalBezierCurve;

    #[test]
    fn planar_biarc_arcs_are_circles_with_a_common_tangent() {
        let (a1, p1) = (DVec3::ZERO, DVec3::X);
        let (a2, p2) = (DVec3::new(2.0, 1.0, 0.0), DVec3::new(0.6, 0.8, 0.0));
        let l = equal_lambda(a1, p1, a2, p2).unwrap();
        let l2 = partner_lambda(a1, p1, a2, p2, l).unwrap();
        assert!((l - l2).abs() < 1e-12);
        let b = biarc(a1, p1, a2, p2, l, l2);
        assert!(((b.b1 - b.a1).length() - (b.c - b.b1).length()).abs() < 1e-12);
        assert!(((b.b2 - b.c).length() - (b.a2 - b.b2).length()).abs() < 1e-12);
        let arc =
            RationalBezierCurve::from_weighted(&[b.a1, b.b1, b.c], &[1.0, b.w1, 1.0]).unwrap();
        // A circle: equidistant from the centre on the normal of p1 at a1.
        let centre = a1 + DVec3::Y * lambda_through(a1, DVec3::Y, b.c);
        let r = (a1 - centre).length();
        for k in 0..=8 {
            assert!(((arc.eval(k as f64 / 8.0) - centre).length() - r).abs() < 1e-12);
        }
        assert!((lambda_through(a1, p1, b.c) - l).abs() < 1e-12);
    }

    #[test]
    fn polar_plane_of_a_point_on_the_sphere_is_its_tangent_plane() {
        let (m, r) = (DVec3::new(1.0, 2.0, 3.0), 2.0);
        let a = m + DVec3::new(0.0, 0.0, r);
        let plane = polar_plane(a.extend(1.0), m, r);
        // The tangent plane z = 5 contains a and a + X, and has normal Z.
        assert!(plane.dot(a.extend(1.0)).abs() < 1e-14);
        assert!(plane.dot((a + DVec3::X).extend(1.0)).abs() < 1e-14);
        assert!(plane.truncate().normalize().dot(DVec3::Z) > 1.0 - 1e-15);
    }
}
