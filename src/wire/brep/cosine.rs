//! The report's parameter-line measure: the largest |cos| between the parameter lines of
//! a lateral face, on the lines u = i/8 — along lines and arcs (degree ≤ 2 in v) bounded
//! over the whole line from the Bernstein coefficients of polynomials in v (convex hull
//! property), along PH pieces sampled (see the notes of the parent module).

use super::*;

/// Samples per patch and direction for the parameter-line measure of the report.
pub(super) const COSINE_SAMPLES: usize = 8;

/// A patch's boundary v = 0 or (`end`) v = 1: its first or last column of control points
/// as a rational curve in u (what the patch is there), taken once for all its points.
pub(super) struct Section<'a> {
    patch: &'a RationalBezierPatch,
    end: bool,
    /// The column, for degrees in u up to MAX_BOUNDED_DEGREE_U (the patch is evaluated
    /// above).
    pub(super) column: Option<[DVec4; MAX_BOUNDED_DEGREE_U + 1]>,
}

impl<'a> Section<'a> {
    pub(super) fn of(patch: &'a RationalBezierPatch, end: bool) -> Self {
        let column = (patch.degree_u() <= MAX_BOUNDED_DEGREE_U).then(|| {
            let nv = patch.degree_v() + 1;
            let j = if end { nv - 1 } else { 0 };
            let mut column = [DVec4::ZERO; MAX_BOUNDED_DEGREE_U + 1];
            for (c, row) in column.iter_mut().zip(patch.homogeneous().chunks_exact(nv)) {
                *c = row[j];
            }
            column
        });
        Self { patch, end, column }
    }

    /// The point at local u.
    pub(super) fn point(&self, u: f64) -> DVec3 {
        let Some(column) = &self.column else {
            return self.patch.eval(u, if self.end { 1.0 } else { 0.0 });
        };
        // Copy only the poles of the profile's usual degrees.
        let degree = self.patch.degree_u();
        let h = match degree {
            1 => casteljau::<2>(column, degree, u),
            2 => casteljau::<3>(column, degree, u),
            3 => casteljau::<4>(column, degree, u),
            _ => casteljau::<{ MAX_BOUNDED_DEGREE_U + 1 }>(column, degree, u),
        };
        crate::bezier::homogeneous::project(h)
    }
}

/// de Casteljau in place on a copy of the first N points (N > `degree`; the points past
/// the degree are not used), as `bernstein::evaluate` does.
pub(super) fn casteljau<const N: usize>(
    points: &[DVec4; MAX_BOUNDED_DEGREE_U + 1],
    degree: usize,
    u: f64,
) -> DVec4 {
    let mut c = [DVec4::ZERO; N];
    c.copy_from_slice(&points[..N]);
    for level in (1..=degree).rev() {
        for i in 0..level {
            c[i] = c[i] * (1.0 - u) + c[i + 1] * u;
        }
    }
    c[0]
}

/// Largest |cos| between the parameter lines of a face, patch by patch (|cos| does not
/// depend on the patch's parameter scale): on the lines u = i/COSINE_SAMPLES (local) of
/// every patch, a bound over the whole line v ∈ [0, 1] for patches of degree ≤
/// [`BOUNDED_DEGREE_V`] along the spine (the lines and arcs, see [`line_cosine_bound`]),
/// the largest of COSINE_SAMPLES + 1 samples on it otherwise.
pub(super) fn max_parameter_cosine(s: &PiecewiseSurface, bases: &mut CosineBases) -> f64 {
    let mut worst = 0.0f64;
    for p in s.patches() {
        let c = match (p.degree_v(), p.degree_u() <= MAX_BOUNDED_DEGREE_U) {
            (1, true) => patch_cosine_bound::<2>(p, bases.of(p.degree_u())),
            (2, true) => patch_cosine_bound::<3>(p, bases.of(p.degree_u())),
            _ => {
                let mut worst = 0.0f64;
                p.grid_partials(COSINE_SAMPLES, |du, dv| {
                    let c = partials_cosine(du, dv);
                    if c.is_finite() {
                        worst = worst.max(c);
                    }
                });
                worst
            }
        };
        worst = worst.max(c);
    }
    worst
}

/// The Bernstein basis with its derivatives at u = k/COSINE_SAMPLES, of the last degree
/// asked for (the profile edges of a sweep mostly share one degree).
pub(super) struct CosineBases {
    degree: usize,
    table: [[[f64; 3]; MAX_BOUNDED_DEGREE_U + 1]; COSINE_SAMPLES + 1],
}

impl CosineBases {
    pub(super) fn new() -> Self {
        Self {
            degree: usize::MAX,
            table: [[[0.0; 3]; MAX_BOUNDED_DEGREE_U + 1]; COSINE_SAMPLES + 1],
        }
    }

    pub(super) fn of(
        &mut self,
        degree: usize,
    ) -> &[[[f64; 3]; MAX_BOUNDED_DEGREE_U + 1]; COSINE_SAMPLES + 1] {
        if degree != self.degree {
            for (k, b) in self.table.iter_mut().enumerate() {
                crate::bezier::bernstein::basis_jet(degree, k as f64 / COSINE_SAMPLES as f64, b);
            }
            self.degree = degree;
        }
        &self.table
    }
}

/// Degrees along the spine up to which the parameter lines are bounded, not sampled: 1
/// (the ruled patches of lines) and 2 (the torus patches of arcs).
pub(super) const BOUNDED_DEGREE_V: usize = 2;

/// Profile degrees of the bound (the rows' sums live on the stack).
pub(super) const MAX_BOUNDED_DEGREE_U: usize = 8;

/// Coefficients of the polynomials of [`line_cosine_bound`]: degree ≤ 4·BOUNDED_DEGREE_V.
pub(super) const BOUND_LEN: usize = 4 * BOUNDED_DEGREE_V + 1;

/// [`line_cosine_bound`] on the lines u = i/COSINE_SAMPLES of one patch of NV control
/// points along v (a constant, so that the small loops unroll).
pub(super) fn patch_cosine_bound<const NV: usize>(
    p: &RationalBezierPatch,
    bases: &[[[f64; 3]; MAX_BOUNDED_DEGREE_U + 1]; COSINE_SAMPLES + 1],
) -> f64 {
    let nu = p.degree_u() + 1;
    let mut worst = 0.0f64;
    for basis in bases {
        // The line u = const and its u-derivative: homogeneous Bézier curves in v.
        let (mut s, mut su) = ([DVec4::ZERO; NV], [DVec4::ZERO; NV]);
        for (row, b) in p.homogeneous().chunks_exact(NV).zip(&basis[..nu]) {
            for j in 0..NV {
                s[j] += row[j] * b[0];
                su[j] += row[j] * b[1];
            }
        }
        worst = worst.max(line_cosine_bound::<NV>(&s, &su));
    }
    worst
}

/// sup |cos ∠(s_u, s_v)| over v ∈ [0, 1] on one line u = const of a rational patch, given
/// the line's homogeneous Bézier points S_j (degree n ≤ [`BOUNDED_DEGREE_V`] in v) and
/// those of its u-derivative S_u,j.
///
/// Why it is a bound: with S = (X, W) the homogeneous point, s_u and s_v are positive
/// multiples (1/W²) of U = X_u W − X W_u and V = X_v W − X W_v, so |cos| = |U·V| / (|U| |V|).
/// U, V, U·V, |U|² and |V|² are polynomials in v (degrees 2n, 2n − 1, 4n − 1, 4n, 4n − 2),
/// computed here as Bernstein products (exact but for rounding); a polynomial on [0, 1]
/// lies between its least and largest Bernstein coefficient (convex hull property), so
/// |cos| ≤ max |(U·V)ₖ| / √(min (|U|²)ₖ · min (|V|²)ₖ) for every v, when both minima are
/// positive. On a line or arc swept with its RMF the exact |cos| is 0 and U·V is the
/// round-off of the poles, so the bound is of that order. When a minimum is not positive
/// (a degenerate line, or one the bound cannot separate from 0), the line is sampled at
/// COSINE_SAMPLES + 1 points instead. Computed in floating point like the samples: the
/// bound holds up to the rounding of its own sums (≈ 1e-16 relative to |U|·|V|).
pub(super) fn line_cosine_bound<const NV: usize>(s: &[DVec4; NV], su: &[DVec4; NV]) -> f64 {
    let n = NV - 1;
    // Scaled Bernstein coefficients C(n, j)·a_j, in which a product is the convolution.
    let scaled = |a: &[DVec4], out: &mut [DVec4]| {
        for (j, (o, &x)) in out.iter_mut().zip(a).enumerate() {
            *o = x * binomial(a.len() - 1, j);
        }
    };
    let (mut s_, mut su_, mut sv_) = (
        [DVec4::ZERO; BOUNDED_DEGREE_V + 1],
        [DVec4::ZERO; BOUNDED_DEGREE_V + 1],
        [DVec4::ZERO; BOUNDED_DEGREE_V],
    );
    scaled(s, &mut s_);
    scaled(su, &mut su_);
    // S_v: the hodograph, degree n − 1.
    let mut hodograph = [DVec4::ZERO; BOUNDED_DEGREE_V];
    for j in 0..n {
        hodograph[j] = (s[j + 1] - s[j]) * n as f64;
    }
    scaled(&hodograph[..n], &mut sv_);
    let (s_, su_, sv_) = (&s_[..=n], &su_[..=n], &sv_[..n]);
    // U = X_u W − X W_u (degree 2n) and V = X_v W − X W_v (degree 2n − 1), scaled.
    let mut u = [DVec3::ZERO; BOUND_LEN];
    let mut v = [DVec3::ZERO; BOUND_LEN];
    let minor = |a: DVec4, b: DVec4| a.truncate() * b.w - b.truncate() * a.w;
    convolve(su_, s_, &mut u[..2 * n + 1], minor);
    convolve(sv_, s_, &mut v[..2 * n], minor);
    let (u, v) = (&u[..2 * n + 1], &v[..2 * n]);
    let mut dot = [0.0; BOUND_LEN];
    let mut uu = [0.0; BOUND_LEN];
    let mut vv = [0.0; BOUND_LEN];
    convolve(u, v, &mut dot[..4 * n], DVec3::dot);
    square(u, &mut uu[..4 * n + 1]);
    square(v, &mut vv[..4 * n - 1]);
    // Back to Bernstein coefficients.
    let unscaled = |c: &mut [f64]| {
        let d = c.len() - 1;
        for (k, x) in c.iter_mut().enumerate() {
            *x /= binomial(d, k);
        }
    };
    unscaled(&mut dot[..4 * n]);
    unscaled(&mut uu[..4 * n + 1]);
    unscaled(&mut vv[..4 * n - 1]);
    let largest = dot[..4 * n].iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let least = |c: &[f64]| c.iter().copied().fold(f64::INFINITY, f64::min);
    let (lu, lv) = (least(&uu[..4 * n + 1]), least(&vv[..4 * n - 1]));
    let bound = largest / (lu * lv).sqrt();
    if lu > 0.0 && lv > 0.0 && bound.is_finite() {
        return bound.min(1.0);
    }
    // Sampled: s_u and s_v are positive multiples of U and V (scaled coefficients back).
    let mut u_ = [DVec3::ZERO; BOUND_LEN];
    let mut v_ = [DVec3::ZERO; BOUND_LEN];
    for (k, x) in u.iter().enumerate() {
        u_[k] = *x / binomial(2 * n, k);
    }
    for (k, x) in v.iter().enumerate() {
        v_[k] = *x / binomial(2 * n - 1, k);
    }
    let mut worst = 0.0f64;
    for i in 0..=COSINE_SAMPLES {
        let t = i as f64 / COSINE_SAMPLES as f64;
        let c = partials_cosine(
            crate::bezier::bernstein::evaluate(&u_[..2 * n + 1], t),
            crate::bezier::bernstein::evaluate(&v_[..2 * n], t),
        );
        if c.is_finite() {
            worst = worst.max(c);
        }
    }
    worst
}

/// [`convolve`] of a vector polynomial with itself under the dot product (each pair i < j
/// once, doubled).
pub(super) fn square(a: &[DVec3], out: &mut [f64]) {
    debug_assert_eq!(out.len(), 2 * a.len() - 1);
    out.fill(0.0);
    for (i, x) in a.iter().enumerate() {
        out[2 * i] += x.dot(*x);
        for (j, y) in a.iter().enumerate().skip(i + 1) {
            out[i + j] += 2.0 * x.dot(*y);
        }
    }
}

/// out_k = Σ_{i+j=k} a_i × b_j under the bilinear `times` (the product of two polynomials
/// in scaled Bernstein form, C(m, i)·a_i: C(m+n, k)·c_k of the product's coefficients).
pub(super) fn convolve<A: Copy, B: Copy, C: crate::bezier::bernstein::Coefficient>(
    a: &[A],
    b: &[B],
    out: &mut [C],
    times: impl Fn(A, B) -> C,
) {
    debug_assert_eq!(out.len(), a.len() + b.len() - 1);
    out.fill(C::default());
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            out[i + j] = out[i + j] + times(x, y);
        }
    }
}
