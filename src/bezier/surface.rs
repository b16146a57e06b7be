//! Tensor-product rational Bézier patches on [0, 1]², homogeneous control points stored
//! row by row with index `i * (degree_v + 1) + j`, i along u (as in the NURBS views).

use super::bernstein::{self, MAX_DEGREE, SHORT};
use super::homogeneous::{project, rational_partials, HomogeneousPartials};
use crate::error::{invalid, Result};
use glam::{DVec3, DVec4};

/// Point and partial derivatives up to second order.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SurfaceJet {
    /// s(u, v).
    pub point: DVec3,
    /// ∂s/∂u.
    pub du: DVec3,
    /// ∂s/∂v.
    pub dv: DVec3,
    /// ∂²s/∂u².
    pub duu: DVec3,
    /// ∂²s/∂u∂v.
    pub duv: DVec3,
    /// ∂²s/∂v².
    pub dvv: DVec3,
}

/// A rational tensor-product Bézier patch.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBezierPatch {
    degree_u: usize,
    degree_v: usize,
    points: Vec<DVec4>,
}

impl RationalBezierPatch {
    /// From homogeneous control points, row-major with i along u.
    pub fn from_homogeneous(degree_u: usize, degree_v: usize, points: Vec<DVec4>) -> Result<Self> {
        if degree_u > MAX_DEGREE || degree_v > MAX_DEGREE {
            return invalid!(
                "patch degree ({degree_u}, {degree_v}) exceeds the maximum {MAX_DEGREE}"
            );
        }
        if points.len() != (degree_u + 1) * (degree_v + 1) {
            return invalid!(
                "a patch of degree ({degree_u}, {degree_v}) needs {} control points, got {}",
                (degree_u + 1) * (degree_v + 1),
                points.len()
            );
        }
        for (k, p) in points.iter().enumerate() {
            if !p.is_finite() || p.w <= 0.0 {
                return invalid!(
                    "control point {k} is not finite or has a non-positive weight ({p})"
                );
            }
        }
        Ok(Self {
            degree_u,
            degree_v,
            points,
        })
    }

    /// Maps every homogeneous control point through `f` in place, with the checks of
    /// [`Self::from_homogeneous`] on the results (no new control net is allocated).
    pub(crate) fn map_homogeneous(&mut self, f: impl Fn(DVec4) -> DVec4) -> Result<()> {
        for (k, p) in self.points.iter_mut().enumerate() {
            *p = f(*p);
            if !p.is_finite() || p.w <= 0.0 {
                return invalid!(
                    "control point {k} is not finite or has a non-positive weight ({p})"
                );
            }
        }
        Ok(())
    }

    /// The patch `Σ_k a_k(u) ⊗ b_k(v)`: a sum of products of a scalar Bernstein polynomial
    /// in u and a homogeneous one in v, all `a_k` of one degree and all `b_k` of one degree.
    /// This is the shape of every sweep, `x(v) + c₂(u) f₂(v) + c₃(u) f₃(v)`, in homogeneous form.
    pub fn from_outer_products(terms: &[(&[f64], &[DVec4])]) -> Result<Self> {
        let Some(&(a0, b0)) = terms.first() else {
            return invalid!("a patch needs at least one product term");
        };
        let (nu, nv) = (a0.len(), b0.len());
        if terms.iter().any(|(a, b)| a.len() != nu || b.len() != nv) {
            return invalid!("product terms of a patch must share their degrees");
        }
        let mut points = vec![DVec4::ZERO; nu * nv];
        for (a, b) in terms {
            for i in 0..nu {
                for j in 0..nv {
                    points[i * nv + j] += b[j] * a[i];
                }
            }
        }
        Self::from_homogeneous(nu - 1, nv - 1, points)
    }

    /// Degree in u.
    pub fn degree_u(&self) -> usize {
        self.degree_u
    }

    /// Degree in v.
    pub fn degree_v(&self) -> usize {
        self.degree_v
    }

    /// Homogeneous control points, index `i * (degree_v + 1) + j`.
    pub fn homogeneous(&self) -> &[DVec4] {
        &self.points
    }

    /// Homogeneous control point (i, j).
    pub fn at(&self, i: usize, j: usize) -> DVec4 {
        self.points[i * (self.degree_v + 1) + j]
    }

    /// The point at local parameters (u, v) in [0, 1]².
    pub fn eval(&self, u: f64, v: f64) -> DVec3 {
        if self.degree_u < SHORT {
            self.eval_with::<SHORT>(u, v)
        } else {
            self.eval_with::<{ MAX_DEGREE + 1 }>(u, v)
        }
    }

    /// [`Self::eval`] with a column of N > degree_u points on the stack (zeroing the longest
    /// column cost more than evaluating a patch of the sweeps' degrees).
    fn eval_with<const N: usize>(&self, u: f64, v: f64) -> DVec3 {
        // Evaluate each row in v, then the resulting column in u.
        let mut column = [DVec4::ZERO; N];
        let row_len = self.degree_v + 1;
        for (i, row) in self.points.chunks_exact(row_len).enumerate() {
            column[i] = bernstein::evaluate(row, v);
        }
        project(bernstein::evaluate(&column[..=self.degree_u], u))
    }

    /// Point and partial derivatives up to order two (local parameters).
    pub fn eval_jet(&self, u: f64, v: f64) -> SurfaceJet {
        if self.degree_u < SHORT && self.degree_v < SHORT {
            self.jet_with::<SHORT>(u, v)
        } else {
            self.jet_with::<{ MAX_DEGREE + 1 }>(u, v)
        }
    }

    /// Point and first partial derivatives (local parameters): the rows' sums of
    /// [`Self::eval_jet`] without the second derivatives.
    pub fn eval_d1(&self, u: f64, v: f64) -> [DVec3; 3] {
        if self.degree_u < SHORT && self.degree_v < SHORT {
            self.d1_with::<SHORT>(u, v)
        } else {
            self.d1_with::<{ MAX_DEGREE + 1 }>(u, v)
        }
    }

    fn d1_with<const N: usize>(&self, u: f64, v: f64) -> [DVec3; 3] {
        let mut bu = [[0.0; 3]; N];
        let mut bv = [[0.0; 3]; N];
        bernstein::basis_jet(self.degree_u, u, &mut bu);
        bernstein::basis_jet(self.degree_v, v, &mut bv);
        let (mut s, mut su, mut sv) = (DVec4::ZERO, DVec4::ZERO, DVec4::ZERO);
        for (i, row) in self.points.chunks_exact(self.degree_v + 1).enumerate() {
            let (mut r0, mut r1) = (DVec4::ZERO, DVec4::ZERO);
            for (j, &p) in row.iter().enumerate() {
                r0 += p * bv[j][0];
                r1 += p * bv[j][1];
            }
            let [b, b1, _] = bu[i];
            s += r0 * b;
            su += r0 * b1;
            sv += r1 * b;
        }
        let p = project(s);
        [
            p,
            (su.truncate() - su.w * p) / s.w,
            (sv.truncate() - sv.w * p) / s.w,
        ]
    }

    /// The first partials (s_u, s_v) at the (steps + 1)² local parameters (i/steps, j/steps),
    /// passed to `visit`: the basis at each parameter computed once for the whole row or
    /// column (grids of samples, e.g. the orthogonality of a sweep's parameter lines).
    pub fn grid_partials(&self, steps: usize, mut visit: impl FnMut(DVec3, DVec3)) {
        let (nu, nv) = (self.degree_u + 1, self.degree_v + 1);
        // The bases at the steps + 1 parameters, one after the other.
        let bases = |degree: usize| -> Vec<[f64; 3]> {
            let mut all = vec![[0.0; 3]; (steps + 1) * (degree + 1)];
            for (k, b) in all.chunks_exact_mut(degree + 1).enumerate() {
                bernstein::basis_jet(degree, k as f64 / steps as f64, b);
            }
            all
        };
        let (bu, bv) = (bases(self.degree_u), bases(self.degree_v));
        // Per v: each row's value and v-derivative (homogeneous).
        let mut rows = vec![(DVec4::ZERO, DVec4::ZERO); nu];
        for b in bv.chunks_exact(nv) {
            for (r, row) in rows.iter_mut().zip(self.points.chunks_exact(nv)) {
                *r = row
                    .iter()
                    .zip(b)
                    .fold((DVec4::ZERO, DVec4::ZERO), |(r0, r1), (&p, w)| {
                        (r0 + p * w[0], r1 + p * w[1])
                    });
            }
            for a in bu.chunks_exact(nu) {
                let (mut s, mut su, mut sv) = (DVec4::ZERO, DVec4::ZERO, DVec4::ZERO);
                for ((r0, r1), w) in rows.iter().zip(a) {
                    s += *r0 * w[0];
                    su += *r0 * w[1];
                    sv += *r1 * w[0];
                }
                let p = project(s);
                visit(
                    (su.truncate() - su.w * p) / s.w,
                    (sv.truncate() - sv.w * p) / s.w,
                );
            }
        }
    }

    /// [`Self::eval_jet`] with basis rows of N > both degrees on the stack.
    fn jet_with<const N: usize>(&self, u: f64, v: f64) -> SurfaceJet {
        let mut bu = [[0.0; 3]; N];
        let mut bv = [[0.0; 3]; N];
        bernstein::basis_jet(self.degree_u, u, &mut bu);
        bernstein::basis_jet(self.degree_v, v, &mut bv);
        let mut h = HomogeneousPartials::default();
        for (i, row) in self.points.chunks_exact(self.degree_v + 1).enumerate() {
            // Row sums in v with the basis and its derivatives.
            let (mut r0, mut r1, mut r2) = (DVec4::ZERO, DVec4::ZERO, DVec4::ZERO);
            for (j, &p) in row.iter().enumerate() {
                r0 += p * bv[j][0];
                r1 += p * bv[j][1];
                r2 += p * bv[j][2];
            }
            let [b, b1, b2] = bu[i];
            h.s += r0 * b;
            h.su += r0 * b1;
            h.suu += r0 * b2;
            h.sv += r1 * b;
            h.suv += r1 * b1;
            h.svv += r2 * b;
        }
        let [point, du, dv, duu, duv, dvv] = rational_partials(&h);
        SurfaceJet {
            point,
            du,
            dv,
            duu,
            duv,
            dvv,
        }
    }

    /// The same patch with degrees raised by (ru, rv).
    pub fn elevated(&self, ru: usize, rv: usize) -> Self {
        let (nu, nv) = (self.degree_u + 1, self.degree_v + 1);
        let rows: Vec<Vec<DVec4>> = self
            .points
            .chunks_exact(nv)
            .map(|row| bernstein::elevate(row, rv))
            .collect();
        let nv2 = nv + rv;
        let mut points = vec![DVec4::ZERO; (nu + ru) * nv2];
        for j in 0..nv2 {
            let column: Vec<DVec4> = rows.iter().map(|row| row[j]).collect();
            for (i, p) in bernstein::elevate(&column, ru).into_iter().enumerate() {
                points[i * nv2 + j] = p;
            }
        }
        Self {
            degree_u: self.degree_u + ru,
            degree_v: self.degree_v + rv,
            points,
        }
    }

    /// The patch split at `t` in u (`along_u`) or in v: the parts on [0, t] and [t, 1],
    /// each reparameterized to [0, 1] (de Casteljau on the homogeneous rows or columns).
    pub fn split(&self, along_u: bool, t: f64) -> (Self, Self) {
        let (nu, nv) = (self.degree_u + 1, self.degree_v + 1);
        let mut left = self.points.clone();
        let mut right = self.points.clone();
        let (lines, length) = if along_u { (nv, nu) } else { (nu, nv) };
        let index = |line: usize, k: usize| {
            if along_u {
                k * nv + line
            } else {
                line * nv + k
            }
        };
        let mut coefficients = Vec::with_capacity(length);
        for line in 0..lines {
            coefficients.clear();
            coefficients.extend((0..length).map(|k| self.points[index(line, k)]));
            let (a, b) = bernstein::split(&coefficients, t);
            for k in 0..length {
                left[index(line, k)] = a[k];
                right[index(line, k)] = b[k];
            }
        }
        let part = |points| Self {
            degree_u: self.degree_u,
            degree_v: self.degree_v,
            points,
        };
        (part(left), part(right))
    }

    /// The same patch with every homogeneous point multiplied by `factor > 0`.
    pub fn scaled_weights(&self, factor: f64) -> Self {
        Self {
            degree_u: self.degree_u,
            degree_v: self.degree_v,
            points: self.points.iter().map(|&h| h * factor).collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::homogeneous::lift;

    /// A quarter cylinder x² + y² = 1, u around the axis, v along z ∈ [0, 2].
    fn quarter_cylinder() -> RationalBezierPatch {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let ring = [
            (DVec3::X, 1.0),
            (DVec3::new(1.0, 1.0, 0.0), s),
            (DVec3::Y, 1.0),
        ];
        let mut points = Vec::new();
        for (p, w) in ring {
            points.push(lift(p, w));
            points.push(lift(p + DVec3::Z * 2.0, w));
        }
        RationalBezierPatch::from_homogeneous(2, 1, points).unwrap()
    }

    /// The grid's partials and eval_d1 are those of eval_jet at the same local parameters
    /// (the grid in the order v outer, u inner; a rational patch of degrees (2, 3) with
    /// uneven weights).
    #[test]
    fn grid_partials_match_the_jets() {
        let points: Vec<DVec4> = (0..12)
            .map(|k| {
                let (i, j) = ((k / 4) as f64, (k % 4) as f64);
                let w = 1.0 + 0.3 * ((k * 5) % 3) as f64;
                DVec4::new(i * w, j * w, (i * j).sin() * w, w)
            })
            .collect();
        let patch = RationalBezierPatch::from_homogeneous(2, 3, points).unwrap();
        let mut seen = Vec::new();
        patch.grid_partials(4, |du, dv| seen.push((du, dv)));
        assert_eq!(seen.len(), 25);
        for (k, (du, dv)) in seen.into_iter().enumerate() {
            let (u, v) = ((k % 5) as f64 / 4.0, (k / 5) as f64 / 4.0);
            let jet = patch.eval_jet(u, v);
            assert!((du - jet.du).length() < 1e-13 * jet.du.length(), "{k}");
            assert!((dv - jet.dv).length() < 1e-13 * jet.dv.length(), "{k}");
            let [p, du1, dv1] = patch.eval_d1(u, v);
            assert!(
                (p - jet.point).length() < 1e-13 * (1.0 + jet.point.length()),
                "{k}"
            );
            assert!((du1 - jet.du).length() < 1e-13 * jet.du.length(), "{k}");
            assert!((dv1 - jet.dv).length() < 1e-13 * jet.dv.length(), "{k}");
        }
    }

    #[test]
    fn cylinder_points_and_derivatives() {
        let c = quarter_cylinder();
        let h = 1e-5;
        for &(u, v) in &[(0.2, 0.3), (0.5, 0.9), (0.8, 0.1)] {
            let jet = c.eval_jet(u, v);
            assert!((jet.point - c.eval(u, v)).length() < 1e-15);
            assert!((jet.point.truncate().length() - 1.0).abs() < 1e-15);
            assert!((jet.point.z - 2.0 * v).abs() < 1e-15);
            let fd_u = (c.eval(u + h, v) - c.eval(u - h, v)) / (2.0 * h);
            let fd_v = (c.eval(u, v + h) - c.eval(u, v - h)) / (2.0 * h);
            let fd_uv = (c.eval(u + h, v + h) - c.eval(u + h, v - h) - c.eval(u - h, v + h)
                + c.eval(u - h, v - h))
                / (4.0 * h * h);
            let fd_uu = (c.eval(u + h, v) - 2.0 * c.eval(u, v) + c.eval(u - h, v)) / (h * h);
            assert!((jet.du - fd_u).length() < 1e-8);
            assert!((jet.dv - fd_v).length() < 1e-8);
            assert!((jet.duv - fd_uv).length() < 1e-5);
            assert!((jet.duu - fd_uu).length() < 1e-4);
            assert!(jet.dvv.length() < 1e-14);
        }
    }

    #[test]
    fn elevation_keeps_the_patch() {
        let c = quarter_cylinder();
        let e = c.elevated(2, 3);
        assert_eq!((e.degree_u(), e.degree_v()), (4, 4));
        for &(u, v) in &[(0.0, 0.0), (0.3, 0.6), (1.0, 1.0)] {
            assert!((e.eval(u, v) - c.eval(u, v)).length() < 1e-14);
        }
    }

    #[test]
    fn outer_products_build_a_bilinear_patch() {
        // s(u, v) = (u, v, uv): 1 ⊗ (0, v, 0, 1) + u ⊗ (1, 0, v, 0)
        let one = [1.0, 1.0];
        let u = [0.0, 1.0];
        let b0 = [
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            DVec4::new(0.0, 1.0, 0.0, 1.0),
        ];
        let b1 = [
            DVec4::new(1.0, 0.0, 0.0, 0.0),
            DVec4::new(1.0, 0.0, 1.0, 0.0),
        ];
        let p = RationalBezierPatch::from_outer_products(&[(&one, &b0), (&u, &b1)]).unwrap();
        let q = p.eval(0.25, 0.5);
        assert!((q - DVec3::new(0.25, 0.5, 0.125)).length() < 1e-15);
    }
}
