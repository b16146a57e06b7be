//! NURBS curves and surfaces: validation of input data, conversion to piecewise Bézier
//! form by knot insertion (Boehm's algorithm, Piegl & Tiller, *The NURBS Book*, §5.2), and
//! assembly of piecewise Bézier objects into one clamped NURBS.
//!
//! Assembly joins segments with interior knots of full multiplicity (= degree). Segments
//! are first raised to a common degree; then each segment's homogeneous control points are
//! multiplied by a constant (which changes neither geometry nor parameterization) so that
//! the pole shared by two segments has the same weight on both sides. That is exactly the
//! layout OpenCascade `Geom_BSpline*`, FreeCAD, IGES 126/128 and STEP accept.
//!
//! Range. Every NURBS accepted evaluates to finite values: weights are scaled by a power of
//! two (exactly) so that the largest is 1 before they multiply the poles (all weights 5e-324
//! are the weights 1), parameters are handled by the overflow-free interval arithmetic of
//! `math::interval` (knots ±1e308), and data whose values are not representable are refused
//! with the reason: poles beyond ±1e300 (the homogeneous derivatives would overflow), weights
//! more than 1e300 apart, and segments whose derivatives would exceed 1e300 — a knot span
//! too short for its poles (a domain [0, 5e-324]), the bound p·(w_max/w_min)·|ΔP|/h for the
//! first and its square over |ΔP| for the second derivative.

use super::bernstein::MAX_DEGREE;
use super::curve::RationalBezierCurve;
use super::homogeneous::{lift, project};
use super::piecewise::{PiecewiseCurve, PiecewiseSurface};
use super::surface::RationalBezierPatch;
use crate::error::{invalid, Num, Result};
use crate::math::{fraction, largest_coordinate, reciprocal_length, robust_length};
use glam::{DVec3, DVec4};

/// Relative tolerance for poles that must coincide where segments meet.
const JOINT_TOLERANCE: f64 = 1e-9;

/// Largest coordinate of an accepted pole, weight ratio and derivative bound (module notes).
pub(super) const MAX_VALUE: f64 = 1e300;

/// A NURBS curve with Cartesian poles, positive weights and a clamped knot vector. Made by
/// [`NurbsCurve::new`], which checks the data, or from rational Bézier pieces; read by its
/// accessors.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve {
    /// Polynomial degree p ≥ 1.
    pub(crate) degree: usize,
    /// Cartesian poles, at least p + 1.
    pub(crate) poles: Vec<DVec3>,
    /// One weight per pole, all > 0.
    pub(crate) weights: Vec<f64>,
    /// Clamped, non-decreasing knot vector of poles.len() + p + 1 knots.
    pub(crate) knots: Vec<f64>,
}

/// A NURBS surface; pole (i, j) is stored at `i * pole_count_v + j`, i along u. Made by
/// [`NurbsSurface::new`], which checks the data, or from a grid of patches; read by its
/// accessors.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurface {
    /// Degree along u.
    pub(crate) degree_u: usize,
    /// Degree along v.
    pub(crate) degree_v: usize,
    /// Number of poles along u.
    pub(crate) pole_count_u: usize,
    /// Number of poles along v.
    pub(crate) pole_count_v: usize,
    /// pole_count_u · pole_count_v Cartesian poles, pole (i, j) at `i * pole_count_v + j`.
    pub(crate) poles: Vec<DVec3>,
    /// Weights in the order of the poles, all > 0.
    pub(crate) weights: Vec<f64>,
    /// Clamped knot vector in u, pole_count_u + degree_u + 1 knots.
    pub(crate) knots_u: Vec<f64>,
    /// Clamped knot vector in v, pole_count_v + degree_v + 1 knots.
    pub(crate) knots_v: Vec<f64>,
}

/// Checks degree, pole count and knot count against each other, before any array is read
/// (so that a wrong count is reported instead of reading past the caller's arrays). Names
/// are the C API's arguments with `suffix` ("" or "_u"/"_v").
pub fn check_nurbs_counts(
    degree: usize,
    pole_count: usize,
    knot_count: usize,
    suffix: &str,
) -> Result<()> {
    check_counts(degree, pole_count, knot_count, || {
        [
            format!("degree{suffix}"),
            format!("pole_count{suffix}"),
            format!("knot_count{suffix}"),
        ]
    })
}

/// [`check_nurbs_counts`] with the names of degree, poles and knots where they were given
/// (C's arguments, or the lengths of a Rust caller's vectors), made only for a message.
fn check_counts(
    degree: usize,
    pole_count: usize,
    knot_count: usize,
    names: impl FnOnce() -> [String; 3],
) -> Result<()> {
    if degree == 0 || degree > MAX_DEGREE {
        let [d, _, _] = names();
        return invalid!("{d} = {degree} must lie in 1..={MAX_DEGREE}");
    }
    if pole_count < degree + 1 {
        let [d, p, _] = names();
        return invalid!("{p} = {pole_count} is less than {d} + 1 = {}", degree + 1);
    }
    if pole_count.checked_add(degree + 1) != Some(knot_count) {
        let [d, p, k] = names();
        return invalid!(
            "{k} = {knot_count} but {p} + {d} + 1 = {}",
            pole_count.saturating_add(degree + 1)
        );
    }
    Ok(())
}

/// Checks a clamped knot vector (its length already checked by [`check_nurbs_counts`]).
fn check_knots(degree: usize, knots: &[f64], suffix: &str) -> Result<()> {
    let p = degree;
    if let Some(i) = knots.iter().position(|k| !k.is_finite()) {
        return invalid!("knots{suffix}[{i}] is not finite");
    }
    if let Some(i) = knots.windows(2).position(|w| w[1] < w[0]) {
        return invalid!(
            "knots{suffix} decrease at index {}: {} < {}",
            i + 1,
            knots[i + 1],
            knots[i]
        );
    }
    let n = knots.len();
    if knots[..=p].iter().any(|&k| k != knots[0])
        || knots[n - p - 1..].iter().any(|&k| k != knots[n - 1])
    {
        return invalid!(
            "knots{suffix} must be clamped: the first and last degree + 1 = {} knots must be equal",
            p + 1
        );
    }
    if knots[0] >= knots[n - 1] {
        return invalid!(
            "knots{suffix} span an empty domain [{}, {}]",
            knots[0],
            knots[n - 1]
        );
    }
    // Ends of multiplicity above degree + 1 leave a basis function that is zero everywhere,
    // and the Bézier decomposition, which expects at most degree + 1, would read past its
    // arrays (a run of 5 for degree 3).
    if knots[p + 1] == knots[0] || knots[n - p - 2] == knots[n - 1] {
        return invalid!(
            "knots{suffix}: an end knot has multiplicity above degree + 1 = {}",
            p + 1
        );
    }
    let mut run = 1;
    for i in p + 1..n - p - 1 {
        run = if knots[i] == knots[i - 1] { run + 1 } else { 1 };
        if run > p {
            return invalid!(
                "knots{suffix}: interior knot {} has multiplicity above the degree {p}",
                knots[i]
            );
        }
    }
    Ok(())
}

fn check_poles_and_weights(poles: &[DVec3], weights: &[f64]) -> Result<()> {
    if let Some(i) = poles.iter().position(|p| !p.is_finite()) {
        return invalid!("poles[{i}] has a non-finite component");
    }
    if let Some(i) = poles.iter().position(|p| p.abs().max_element() > MAX_VALUE) {
        return invalid!(
            "poles[{i}] has a coordinate beyond ±{}: the curve's derivatives would overflow",
            Num(MAX_VALUE)
        );
    }
    if weights.len() != poles.len() {
        return invalid!("{} weights for {} poles", weights.len(), poles.len());
    }
    if let Some(i) = weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
        return invalid!(
            "weights[{i}] = {} must be finite and positive",
            Num(weights[i])
        );
    }
    let (low, high) = extreme_positions(weights);
    if weights[low] < weights[high] / MAX_VALUE {
        return invalid!(
            "weights[{high}] = {} is more than {} times weights[{low}] = {}: a weight ratio \
             double precision cannot evaluate",
            Num(weights[high]),
            Num(MAX_VALUE),
            Num(weights[low])
        );
    }
    Ok(())
}

/// Indices of the smallest and the largest value.
fn extreme_positions(values: &[f64]) -> (usize, usize) {
    let by = |a: &(usize, &f64), b: &(usize, &f64)| a.1.total_cmp(b.1);
    let low = values.iter().enumerate().min_by(by).map_or(0, |(i, _)| i);
    let high = values.iter().enumerate().max_by(by).map_or(0, |(i, _)| i);
    (low, high)
}

/// The weights scaled by one power of two so that the largest lies in [0.5, 1) (exact).
fn normalized_weights(weights: &[f64]) -> Vec<f64> {
    let largest = weights.iter().fold(0.0f64, |m, &w| m.max(w));
    let exponent = -(largest.log2().floor() as i32) - 1;
    weights
        .iter()
        .map(|&w| times_power_of_two(w, exponent))
        .collect()
}

/// x·2^k, exact, for exponents beyond the range of one power of two (2^1074 for 5e-324).
fn times_power_of_two(x: f64, k: i32) -> f64 {
    let half = k / 2;
    x * 2f64.powi(half) * 2f64.powi(k - half)
}

/// Refuses a segment (of `degree`, on the parameter intervals `spans`) whose first or
/// second derivative could exceed [`MAX_VALUE`] (module notes); `what` names it.
fn check_derivative_range(
    points: &[DVec4],
    degree: usize,
    spans: &[(f64, f64)],
    what: impl std::fmt::Display,
) -> Result<()> {
    let weights: Vec<f64> = points.iter().map(|h| h.w).collect();
    let (low, high) = extreme_positions(&weights);
    let ratio = weights[high] / weights[low];
    let first = project(points[0]);
    let spread = largest_coordinate(points.iter().map(|&h| project(h) - first));
    let p = degree.max(1) as f64;
    for &(a, b) in spans {
        let reciprocal = reciprocal_length(a, b);
        let d1 = p * ratio * spread * reciprocal;
        let d2 = d1 * p * ratio * reciprocal;
        if !(d1 <= MAX_VALUE && d2 <= MAX_VALUE) {
            return invalid!(
                "{what}: its derivatives could exceed {} (knot span [{}, {}], poles {} apart, \
                 weight ratio {}): beyond the range of double precision; use a longer \
                 parameter interval or smaller coordinates",
                Num(MAX_VALUE),
                Num(a),
                Num(b),
                Num(spread),
                Num(ratio)
            );
        }
    }
    Ok(())
}

/// Inserts interior knots until each has multiplicity `degree`, in homogeneous coordinates.
/// `points` is a list of control nets sharing the knot vector (one curve, or every row or
/// column of a surface). Returns the distinct breakpoints; afterwards each net holds
/// `segments * degree + 1` points, segment k using `points[k*degree ..= k*degree + degree]`.
fn decompose(degree: usize, knots: &[f64], nets: &mut [Vec<DVec4>]) -> Vec<f64> {
    for net in nets.iter_mut() {
        *net = decompose_net(degree, knots, net);
    }
    let mut breaks = knots[degree..knots.len() - degree].to_vec();
    breaks.dedup();
    breaks
}

/// The Bézier points of one net, segment by segment in one pass over the knots (Piegl &
/// Tiller, *The NURBS Book*, A5.6): at each breakpoint the knot is inserted up to
/// multiplicity p within the current segment only, so the work is linear in the segments
/// (inserting into the whole net each time was quadratic: 5 s for 10,000 segments).
fn decompose_net(p: usize, knots: &[f64], poles: &[DVec4]) -> Vec<DVec4> {
    let m = knots.len() - 1;
    let mut out = Vec::with_capacity(poles.len() * p);
    let mut current: Vec<DVec4> = poles[..=p].to_vec();
    let mut next = vec![DVec4::ZERO; p + 1];
    let mut alphas = vec![0.0; p];
    let (mut a, mut b) = (p, p + 1);
    while b < m {
        let start = b;
        while b < m && knots[b + 1] == knots[b] {
            b += 1;
        }
        let multiplicity = b - start + 1;
        if multiplicity < p {
            for j in (multiplicity + 1..=p).rev() {
                alphas[j - multiplicity - 1] = fraction(knots[b], knots[a], knots[a + j]);
            }
            let r = p - multiplicity;
            for j in 1..=r {
                let s = multiplicity + j;
                for k in (s..=p).rev() {
                    let alpha = alphas[k - s];
                    current[k] = current[k] * alpha + current[k - 1] * (1.0 - alpha);
                }
                if b < m {
                    // The points the insertion leaves at the start of the next segment.
                    next[r - j] = current[p];
                }
            }
        }
        let first = if out.is_empty() { 0 } else { 1 };
        out.extend_from_slice(&current[first..]);
        if b < m {
            for i in p.saturating_sub(multiplicity)..=p {
                next[i] = poles[b - p + i];
            }
            std::mem::swap(&mut current, &mut next);
            a = b;
            b += 1;
        }
    }
    out
}

impl NurbsCurve {
    /// Polynomial degree p ≥ 1.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Cartesian poles, at least p + 1.
    pub fn poles(&self) -> &[DVec3] {
        &self.poles
    }

    /// One weight per pole, all > 0.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The clamped, non-decreasing knot vector: `poles().len() + degree() + 1` knots.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// Validates NURBS data (`weights = None` means all 1).
    pub fn new(
        degree: usize,
        poles: Vec<DVec3>,
        weights: Option<Vec<f64>>,
        knots: Vec<f64>,
    ) -> Result<Self> {
        check_counts(degree, poles.len(), knots.len(), || {
            ["degree", "poles.len()", "knots.len()"].map(String::from)
        })?;
        let weights = weights.unwrap_or_else(|| vec![1.0; poles.len()]);
        check_poles_and_weights(&poles, &weights)?;
        check_knots(degree, &knots, "")?;
        Ok(Self {
            degree,
            poles,
            weights,
            knots,
        })
    }

    /// The same curve as rational Bézier segments on the distinct knot intervals.
    pub fn to_piecewise(&self) -> Result<PiecewiseCurve> {
        let p = self.degree;
        let mut nets = [self
            .poles
            .iter()
            .zip(normalized_weights(&self.weights))
            .map(|(&x, w)| lift(x, w))
            .collect::<Vec<_>>()];
        let breaks = decompose(p, &self.knots, &mut nets);
        let segments = (0..breaks.len() - 1)
            .map(|k| {
                let points = &nets[0][k * p..=k * p + p];
                let span = (breaks[k], breaks[k + 1]);
                check_derivative_range(points, p, &[span], format_args!("segment {k}"))?;
                RationalBezierCurve::from_homogeneous(points.to_vec())
            })
            .collect::<Result<Vec<_>>>()?;
        PiecewiseCurve::new(segments, breaks)
    }

    /// One clamped NURBS for a piecewise curve (see the module notes).
    pub fn from_piecewise(curve: &PiecewiseCurve) -> Result<Self> {
        let p = curve
            .segments()
            .iter()
            .map(|s| s.degree())
            .max()
            .unwrap_or(1)
            .max(1);
        let scale = coordinate_scale(curve.segments().iter().flat_map(|s| s.poles()));
        let mut homogeneous: Vec<DVec4> = Vec::with_capacity(curve.segments().len() * p + 1);
        for (k, segment) in curve.segments().iter().enumerate() {
            let mut points = segment
                .elevated(p - segment.degree())
                .homogeneous()
                .to_vec();
            if let Some(&shared) = homogeneous.last() {
                let factor = shared.w / points[0].w;
                points.iter_mut().for_each(|h| *h *= factor);
                if !homogeneous_close(shared, points[0], scale) {
                    return invalid!(
                        "segments {} and {} do not meet: the curve is not continuous",
                        k - 1,
                        k
                    );
                }
                homogeneous.extend_from_slice(&points[1..]);
            } else {
                homogeneous.extend_from_slice(&points);
            }
        }
        Ok(Self {
            degree: p,
            poles: homogeneous.iter().map(|&h| project(h)).collect(),
            weights: homogeneous.iter().map(|h| h.w).collect(),
            knots: clamped_knots(curve.breaks(), p),
        })
    }

    /// The curve moved by `dx` along x (a curve in a parameter plane moved along u).
    pub(crate) fn moved_x(mut self, dx: f64) -> Self {
        self.poles.iter_mut().for_each(|p| p.x += dx);
        self
    }

    /// The same curve run the other way on the same parameter range: t ↦ a + b − t.
    pub(crate) fn reversed(&self) -> Self {
        let (a, b) = (self.knots[0], self.knots[self.knots.len() - 1]);
        Self {
            degree: self.degree,
            poles: self.poles.iter().rev().copied().collect(),
            weights: self.weights.iter().rev().copied().collect(),
            knots: self.knots.iter().rev().map(|&t| a + b - t).collect(),
        }
    }
}

impl NurbsSurface {
    /// Degree along u.
    pub fn degree_u(&self) -> usize {
        self.degree_u
    }

    /// Degree along v.
    pub fn degree_v(&self) -> usize {
        self.degree_v
    }

    /// Number of poles along u.
    pub fn pole_count_u(&self) -> usize {
        self.pole_count_u
    }

    /// Number of poles along v.
    pub fn pole_count_v(&self) -> usize {
        self.pole_count_v
    }

    /// `pole_count_u() · pole_count_v()` Cartesian poles, pole (i, j) at
    /// `i * pole_count_v() + j`.
    pub fn poles(&self) -> &[DVec3] {
        &self.poles
    }

    /// Weights in the order of the poles, all > 0.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The clamped knot vector in u: `pole_count_u() + degree_u() + 1` knots.
    pub fn knots_u(&self) -> &[f64] {
        &self.knots_u
    }

    /// The clamped knot vector in v: `pole_count_v() + degree_v() + 1` knots.
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }

    /// Validates NURBS surface data (`weights = None` means all 1).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        degree_u: usize,
        degree_v: usize,
        pole_count_u: usize,
        pole_count_v: usize,
        poles: Vec<DVec3>,
        weights: Option<Vec<f64>>,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
    ) -> Result<Self> {
        // The surface's own arguments, and the lengths of its knot vectors.
        let names = |s: &str| {
            [
                format!("degree{s}"),
                format!("pole_count{s}"),
                format!("knots{s}.len()"),
            ]
        };
        check_counts(degree_u, pole_count_u, knots_u.len(), || names("_u"))?;
        check_counts(degree_v, pole_count_v, knots_v.len(), || names("_v"))?;
        if pole_count_u.checked_mul(pole_count_v) != Some(poles.len()) {
            return invalid!(
                "pole_count_u × pole_count_v = {pole_count_u} × {pole_count_v} but {} poles given",
                poles.len()
            );
        }
        let weights = weights.unwrap_or_else(|| vec![1.0; poles.len()]);
        check_poles_and_weights(&poles, &weights)?;
        check_knots(degree_u, &knots_u, "_u")?;
        check_knots(degree_v, &knots_v, "_v")?;
        Ok(Self {
            degree_u,
            degree_v,
            pole_count_u,
            pole_count_v,
            poles,
            weights,
            knots_u,
            knots_v,
        })
    }

    /// The same surface as a grid of rational Bézier patches.
    pub fn to_piecewise(&self) -> Result<PiecewiseSurface> {
        let (pu, pv) = (self.degree_u, self.degree_v);
        let lifted: Vec<DVec4> = self
            .poles
            .iter()
            .zip(normalized_weights(&self.weights))
            .map(|(&x, w)| lift(x, w))
            .collect();
        // Rows (fixed i) along v first, then the columns of the result along u.
        let mut rows: Vec<Vec<DVec4>> = lifted
            .chunks_exact(self.pole_count_v)
            .map(<[DVec4]>::to_vec)
            .collect();
        let v_breaks = decompose(pv, &self.knots_v, &mut rows);
        let nv = rows[0].len();
        let mut columns: Vec<Vec<DVec4>> = (0..nv)
            .map(|j| rows.iter().map(|r| r[j]).collect())
            .collect();
        let u_breaks = decompose(pu, &self.knots_u, &mut columns);
        let (ku, kv) = (u_breaks.len() - 1, v_breaks.len() - 1);
        let mut patches = Vec::with_capacity(ku * kv);
        for a in 0..ku {
            for b in 0..kv {
                let mut points = Vec::with_capacity((pu + 1) * (pv + 1));
                for i in 0..=pu {
                    for j in 0..=pv {
                        points.push(columns[b * pv + j][a * pu + i]);
                    }
                }
                let spans = [
                    (u_breaks[a], u_breaks[a + 1]),
                    (v_breaks[b], v_breaks[b + 1]),
                ];
                check_derivative_range(
                    &points,
                    pu.max(pv),
                    &spans,
                    format_args!("patch ({a}, {b})"),
                )?;
                patches.push(RationalBezierPatch::from_homogeneous(pu, pv, points)?);
            }
        }
        PiecewiseSurface::new(patches, u_breaks, v_breaks)
    }

    /// One clamped NURBS for a grid of patches (see the module notes). Each patch gets one
    /// weight factor, chosen so that its corner weight matches its neighbour's; the whole
    /// shared boundary must then agree in homogeneous coordinates, which holds for every
    /// surface whose weights factor as w(u)·w(v) per patch (all sweeps and cone splines).
    pub fn from_piecewise(surface: &PiecewiseSurface) -> Result<Self> {
        let (ku, kv) = (surface.u_breaks().len() - 1, surface.v_breaks().len() - 1);
        let pu = surface
            .patches()
            .iter()
            .map(|p| p.degree_u())
            .max()
            .unwrap_or(1)
            .max(1);
        let pv = surface
            .patches()
            .iter()
            .map(|p| p.degree_v())
            .max()
            .unwrap_or(1)
            .max(1);
        let (nu, nv) = (ku * pu + 1, kv * pv + 1);
        let first = surface.patch(0, 0);
        if ku == 1 && kv == 1 && (first.degree_u(), first.degree_v()) == (pu, pv) {
            // One patch: its control net is the NURBS net (no neighbours to join).
            return Ok(Self::of_net(
                surface,
                (pu, pv),
                (nu, nv),
                first.homogeneous(),
            ));
        }
        let scale = coordinate_scale(
            surface
                .patches()
                .iter()
                .flat_map(|p| p.homogeneous().iter().map(|&h| project(h))),
        );
        // Patches are placed a-major: a pole of patch (a, b) is already set by an earlier
        // one exactly on its first row (a > 0: by the patches of row a − 1) or its first
        // column (b > 0: by patch (a, b − 1)).
        let mut net = vec![DVec4::ZERO; nu * nv];
        for a in 0..ku {
            for b in 0..kv {
                let patch = surface.patch(a, b);
                let raised;
                let patch = if (patch.degree_u(), patch.degree_v()) == (pu, pv) {
                    patch
                } else {
                    raised = patch.elevated(pu - patch.degree_u(), pv - patch.degree_v());
                    &raised
                };
                // Match the corner shared with an already placed neighbour.
                let factor = if a > 0 || b > 0 {
                    net[a * pu * nv + b * pv].w / patch.at(0, 0).w
                } else {
                    1.0
                };
                for i in 0..=pu {
                    for j in 0..=pv {
                        let h = patch.at(i, j) * factor;
                        let k = (a * pu + i) * nv + b * pv + j;
                        if !((i == 0 && a > 0) || (j == 0 && b > 0)) {
                            net[k] = h;
                        } else if !homogeneous_close(net[k], h, scale) {
                            return invalid!(
                                "patch ({a}, {b}) does not join its neighbours in homogeneous coordinates"
                            );
                        }
                    }
                }
            }
        }
        Ok(Self::of_net(surface, (pu, pv), (nu, nv), &net))
    }

    /// Boundary `side` of the surface in its parameter plane: v = v₀, u = u₁, v = v₁, u = u₀
    /// for sides 0 to 3 (counter-clockwise: a face's loop traverses the first two forwards,
    /// the last two backwards), as (origin, direction) of the line the boundary curve's
    /// parameter maps to.
    pub(crate) fn boundary_line(&self, side: usize) -> ((f64, f64), (f64, f64)) {
        let s = self;
        let (u0, u1) = (s.knots_u[0], s.knots_u[s.knots_u.len() - 1]);
        let (v0, v1) = (s.knots_v[0], s.knots_v[s.knots_v.len() - 1]);
        match side {
            0 => ((0.0, v0), (1.0, 0.0)),
            1 => ((u1, 0.0), (0.0, 1.0)),
            2 => ((0.0, v1), (1.0, 0.0)),
            _ => ((u0, 0.0), (0.0, 1.0)),
        }
    }
    /// The same surface with every interior knot along v simple, where it is C^{p−1} across
    /// them (a spline's decomposition into patches): each row refitted on the simple knots
    /// by least squares through its ends at p + 1 points a span, and kept only where every
    /// row is the same to 1e-12 of its coefficients at each span's middle; `None` otherwise.
    pub(crate) fn with_simple_knots_v(&self) -> Option<Self> {
        let p = self.degree_v;
        let mut breaks = self.knots_v.clone();
        breaks.dedup();
        let mut knots = vec![breaks[0]; p + 1];
        knots.extend_from_slice(&breaks[1..breaks.len() - 1]);
        knots.extend(std::iter::repeat_n(breaks[breaks.len() - 1], p + 1));
        let n = knots.len() - p - 1;
        let mut params = vec![breaks[0]];
        for w in breaks.windows(2) {
            params.extend((1..=p + 1).map(|k| w[0] + (w[1] - w[0]) * k as f64 / (p + 2) as f64));
        }
        params.push(breaks[breaks.len() - 1]);
        let checks: Vec<f64> = breaks.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        // The basis functions at each point, on the old knots and on the new, for all rows.
        let old = |ts: &[f64]| -> Vec<_> {
            ts.iter()
                .map(|&t| basis_functions(&self.knots_v, p, t))
                .collect()
        };
        let (old_params, old_checks) = (old(&params), old(&checks));
        let new_checks: Vec<_> = checks
            .iter()
            .map(|&t| basis_functions(&knots, p, t))
            .collect();
        let value = |basis: &(usize, Vec<f64>), coefficients: &[DVec4]| -> DVec4 {
            basis
                .1
                .iter()
                .enumerate()
                .map(|(r, &b)| coefficients[basis.0 + r] * b)
                .sum()
        };
        let nv = self.pole_count_v;
        let rows: Vec<Vec<DVec4>> = (0..self.pole_count_u)
            .map(|i| {
                (0..nv)
                    .map(|j| lift(self.poles[i * nv + j], self.weights[i * nv + j]))
                    .collect()
            })
            .collect();
        let values: Vec<Vec<DVec4>> = rows
            .iter()
            .map(|row| old_params.iter().map(|b| value(b, row)).collect())
            .collect();
        let fitted = fit_splines(&knots, p, &params, &values)?;
        let mut poles = Vec::with_capacity(self.pole_count_u * n);
        let mut weights = Vec::with_capacity(self.pole_count_u * n);
        for (row, fitted) in rows.iter().zip(&fitted) {
            let size = row
                .iter()
                .map(|h| h.abs().max_element())
                .fold(0.0, f64::max);
            let off = old_checks
                .iter()
                .zip(&new_checks)
                .map(|(a, b)| (value(b, fitted) - value(a, row)).abs().max_element())
                .fold(0.0, f64::max);
            let same = off <= 1e-12 * size && fitted.iter().all(|h| h.w > 0.0);
            if !same {
                return None;
            }
            poles.extend(fitted.iter().map(|&h| project(h)));
            weights.extend(fitted.iter().map(|h| h.w));
        }
        Some(Self {
            pole_count_v: n,
            poles,
            weights,
            knots_v: knots,
            ..self.clone()
        })
    }

    /// The NURBS curve of boundary `side` (see [`Self::boundary_line`]).
    pub(crate) fn boundary_curve(&self, side: usize) -> NurbsCurve {
        let s = self;
        let (nu, nv) = (s.pole_count_u, s.pole_count_v);
        let column = |j: usize| NurbsCurve {
            degree: s.degree_u,
            poles: (0..nu).map(|i| s.poles[i * nv + j]).collect(),
            weights: (0..nu).map(|i| s.weights[i * nv + j]).collect(),
            knots: s.knots_u.clone(),
        };
        let row = |i: usize| NurbsCurve {
            degree: s.degree_v,
            poles: s.poles[i * nv..(i + 1) * nv].to_vec(),
            weights: s.weights[i * nv..(i + 1) * nv].to_vec(),
            knots: s.knots_v.clone(),
        };
        match side {
            0 => column(0),
            1 => row(nu - 1),
            2 => column(nv - 1),
            _ => row(0),
        }
    }

    /// The NURBS of a joined homogeneous control net of `surface` (u-major, nu × nv), with
    /// the knots of its breaks.
    fn of_net(
        surface: &PiecewiseSurface,
        (pu, pv): (usize, usize),
        (nu, nv): (usize, usize),
        net: &[DVec4],
    ) -> Self {
        Self {
            degree_u: pu,
            degree_v: pv,
            pole_count_u: nu,
            pole_count_v: nv,
            poles: net.iter().map(|&h| project(h)).collect(),
            weights: net.iter().map(|h| h.w).collect(),
            knots_u: clamped_knots(surface.u_breaks(), pu),
            knots_v: clamped_knots(surface.v_breaks(), pv),
        }
    }
}
/// The p + 1 B-spline basis functions of degree p not zero at t on clamped `knots`, and the
/// index of the first (Cox–de Boor; Piegl & Tiller, *The NURBS Book*, A2.2).
pub(crate) fn basis_functions(knots: &[f64], p: usize, t: f64) -> (usize, Vec<f64>) {
    let n = knots.len() - p - 1;
    let span = if t >= knots[n] {
        n - 1
    } else {
        knots.partition_point(|&k| k <= t).max(p + 1) - 1
    };
    let mut values = vec![0.0; p + 1];
    values[0] = 1.0;
    let (mut left, mut right) = (vec![0.0; p + 1], vec![0.0; p + 1]);
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = values[r] / (right[r + 1] + left[j - r]);
            values[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        values[j] = saved;
    }
    (span - p, values)
}

/// The spline of degree p on clamped `knots` with `coefficients`, at t.
pub(crate) fn spline_value<T: SplineValue>(
    knots: &[f64],
    p: usize,
    coefficients: &[T],
    t: f64,
) -> T {
    let (first, values) = basis_functions(knots, p, t);
    values
        .iter()
        .enumerate()
        .fold(T::default(), |sum, (r, &b)| {
            sum + coefficients[first + r] * b
        })
}

/// What a spline's coefficients may be: vectors of f64.
pub(crate) trait SplineValue:
    Copy
    + Default
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<f64, Output = Self>
    + std::ops::Div<f64, Output = Self>
{
}

impl<T> SplineValue for T where
    T: Copy
        + Default
        + std::ops::Add<Output = T>
        + std::ops::Sub<Output = T>
        + std::ops::Mul<f64, Output = T>
        + std::ops::Div<f64, Output = T>
{
}

/// For each of `rows`, the spline of degree p on clamped `knots` through the row's values
/// at the first and last of `params` (the knots' ends), closest to them at the others in
/// least squares: its coefficients (the normal equations, banded, by one Cholesky
/// factorization for all rows); `None` where the points do not determine it.
pub(crate) fn fit_splines<T: SplineValue>(
    knots: &[f64],
    p: usize,
    params: &[f64],
    rows: &[Vec<T>],
) -> Option<Vec<Vec<T>>> {
    let n = knots.len() - p - 1;
    // The interior coefficients 1 … n − 2; the matrix's band: column j − p … j + p of row j.
    let m = n.checked_sub(2)?;
    let bases: Vec<(usize, Vec<f64>)> = params
        .iter()
        .map(|&t| basis_functions(knots, p, t))
        .collect();
    let mut matrix = vec![vec![0.0; m]; m];
    for (start, b) in &bases {
        for (r, &wr) in b.iter().enumerate() {
            let i = start + r;
            if i == 0 || i == n - 1 {
                continue;
            }
            for (c, &wc) in b.iter().enumerate() {
                let j = start + c;
                if j != 0 && j != n - 1 {
                    matrix[i - 1][j - 1] += wr * wc;
                }
            }
        }
    }
    let factor = cholesky(matrix, p)?;
    rows.iter()
        .map(|values| {
            let (first, last) = (values[0], values[values.len() - 1]);
            let mut rhs = vec![T::default(); m];
            for ((start, b), &value) in bases.iter().zip(values) {
                let mut target = value;
                for (r, &w) in b.iter().enumerate() {
                    match start + r {
                        0 => target = target - first * w,
                        i if i == n - 1 => target = target - last * w,
                        _ => {}
                    }
                }
                for (r, &w) in b.iter().enumerate() {
                    let i = start + r;
                    if i != 0 && i != n - 1 {
                        rhs[i - 1] = rhs[i - 1] + target * w;
                    }
                }
            }
            let mut coefficients = vec![first];
            coefficients.extend(cholesky_solve(&factor, p, rhs));
            coefficients.push(last);
            Some(coefficients)
        })
        .collect()
}

/// The lower factor L (L Lᵀ = a) of a symmetric positive definite matrix of band width p;
/// `None` where it is not positive definite.
fn cholesky(mut a: Vec<Vec<f64>>, p: usize) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    for j in 0..n {
        let from = j.saturating_sub(p);
        let d = a[j][j] - (from..j).map(|k| a[j][k] * a[j][k]).sum::<f64>();
        if d.is_nan() || d <= 0.0 {
            return None;
        }
        a[j][j] = d.sqrt();
        for i in j + 1..n.min(j + p + 1) {
            let from = i.saturating_sub(p);
            a[i][j] = (a[i][j] - (from..j).map(|k| a[i][k] * a[j][k]).sum::<f64>()) / a[j][j];
        }
    }
    Some(a)
}

/// x with L Lᵀ x = b, L from [`cholesky`] of band width p.
fn cholesky_solve<T: SplineValue>(l: &[Vec<f64>], p: usize, b: Vec<T>) -> Vec<T> {
    let n = b.len();
    let mut y = vec![T::default(); n];
    for i in 0..n {
        let s = (i.saturating_sub(p)..i).fold(b[i], |s, k| s - y[k] * l[i][k]);
        y[i] = s / l[i][i];
    }
    let mut x = vec![T::default(); n];
    for i in (0..n).rev() {
        let s = (i + 1..n.min(i + p + 1)).fold(y[i], |s, k| s - x[k] * l[k][i]);
        x[i] = s / l[i][i];
    }
    x
}

/// The clamped knot vector with full-multiplicity interior knots at `breaks`.
fn clamped_knots(breaks: &[f64], degree: usize) -> Vec<f64> {
    let last = breaks.len() - 1;
    let mut knots = Vec::with_capacity(breaks.len() * degree + 2);
    for (k, &b) in breaks.iter().enumerate() {
        let multiplicity = if k == 0 || k == last {
            degree + 1
        } else {
            degree
        };
        knots.extend(std::iter::repeat_n(b, multiplicity));
    }
    knots
}

/// A length scale of a point set, for relative tolerances: its largest coordinate, so that
/// a join is judged alike at every scale.
fn coordinate_scale(points: impl Iterator<Item = DVec3>) -> f64 {
    largest_coordinate(points).max(f64::MIN_POSITIVE)
}

fn homogeneous_close(a: DVec4, b: DVec4, scale: f64) -> bool {
    let weight_ok = (a.w - b.w).abs() <= JOINT_TOLERANCE * a.w.abs().max(b.w.abs());
    weight_ok && robust_length(project(a) - project(b)) <= JOINT_TOLERANCE * scale
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rational de Boor evaluation, independent of the Bézier path (Piegl & Tiller A4.1).
    fn de_boor(c: &NurbsCurve, t: f64) -> DVec3 {
        let p = c.degree;
        let n = c.poles.len();
        let k = if t >= c.knots[n] {
            n - 1
        } else {
            c.knots.iter().rposition(|&x| x <= t).unwrap()
        };
        let mut d: Vec<DVec4> = (0..=p)
            .map(|j| lift(c.poles[j + k - p], c.weights[j + k - p]))
            .collect();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = j + k - p;
                let alpha = (t - c.knots[i]) / (c.knots[i + p + 1 - r] - c.knots[i]);
                d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
            }
        }
        project(d[p])
    }

    fn sample_curve() -> NurbsCurve {
        let poles = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 2.0, 0.5),
            DVec3::new(2.0, -1.0, 1.0),
            DVec3::new(3.0, 1.0, -0.5),
            DVec3::new(4.0, 0.0, 2.0),
            DVec3::new(5.0, 2.0, 1.0),
        ];
        let weights = Some(vec![1.0, 0.5, 2.0, 1.0, 0.7, 1.0]);
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.3, 1.2, 1.2, 1.2, 1.2];
        NurbsCurve::new(3, poles, weights, knots).unwrap()
    }

    #[test]
    fn decomposition_matches_de_boor() {
        let c = sample_curve();
        let pw = c.to_piecewise().unwrap();
        assert_eq!(pw.breaks(), &[0.0, 0.3, 1.2]);
        for i in 0..=60 {
            let t = 1.2 * i as f64 / 60.0;
            assert!((pw.eval(t) - de_boor(&c, t)).length() < 1e-13, "t = {t}");
        }
    }

    /// Single, double and full interior knots, degrees 1 to 5, uneven spacing: every
    /// segment's Bézier points (one pass over the knots) against de Boor's algorithm.
    #[test]
    fn decomposition_of_every_multiplicity_matches_de_boor() {
        for degree in 1..=5usize {
            let mut knots = vec![0.0; degree + 1];
            let mut t = 0.0;
            for k in 0..12 {
                t += 0.2 + 0.13 * (k % 5) as f64;
                let multiplicity = 1 + k % degree;
                knots.extend(std::iter::repeat_n(t, multiplicity));
            }
            t += 0.5;
            knots.extend(std::iter::repeat_n(t, degree + 1));
            let n = knots.len() - degree - 1;
            let poles = (0..n)
                .map(|i| {
                    let x = i as f64;
                    DVec3::new(x, (0.7 * x).sin() * 3.0, (0.3 * x).cos())
                })
                .collect();
            let weights = (0..n).map(|i| 1.0 + 0.5 * ((i * 7) % 3) as f64).collect();
            let c = NurbsCurve::new(degree, poles, Some(weights), knots).unwrap();
            let pw = c.to_piecewise().unwrap();
            assert_eq!(pw.segments().len(), 12 + 1, "degree {degree}");
            for i in 0..=600 {
                let u = t * i as f64 / 600.0;
                let e = (pw.eval(u) - de_boor(&c, u)).length();
                assert!(e < 1e-12, "degree {degree}, t = {u}: {e:e}");
            }
        }
    }

    /// A spline surface of degree (2, 4) with simple knots along v, decomposed into patches
    /// (full-multiplicity knots): its simple knots come back, the same coefficients to
    /// rounding; a surface with a corner along v (a knot of full multiplicity in the
    /// original) keeps its knots.
    #[test]
    fn a_decomposed_spline_surface_gets_its_simple_knots_back() {
        let (nu, nv) = (3, 9);
        let knots_v = vec![
            0.0, 0.0, 0.0, 0.0, 0.0, 0.7, 1.1, 1.5, 2.6, 3.0, 3.0, 3.0, 3.0, 3.0,
        ];
        let poles: Vec<DVec3> = (0..nu * nv)
            .map(|k| {
                let (i, j) = ((k / nv) as f64, (k % nv) as f64);
                DVec3::new(j, i + 0.3 * (1.7 * j).sin(), (0.5 * j + i).cos())
            })
            .collect();
        let weights: Vec<f64> = (0..nu * nv).map(|k| [1.0, 0.8, 1.0][k / nv]).collect();
        let knots_u = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        let smooth =
            NurbsSurface::new(2, 4, nu, nv, poles, Some(weights), knots_u, knots_v).unwrap();
        let decomposed = NurbsSurface::from_piecewise(&smooth.to_piecewise().unwrap()).unwrap();
        assert_eq!(decomposed.pole_count_v, 4 * 5 + 1);
        let back = decomposed.with_simple_knots_v().unwrap();
        assert_eq!(back.knots_v, smooth.knots_v);
        for (a, b) in back.poles.iter().zip(&smooth.poles) {
            assert!(a.distance(*b) < 1e-12, "{a} {b}");
        }
        // The weights up to one factor (the decomposition normalizes them).
        let factor = back.weights[0] / smooth.weights[0];
        for (a, b) in back.weights.iter().zip(&smooth.weights) {
            assert!((a - factor * b).abs() < 1e-12 * a, "{a} {b}");
        }
        let mut cornered = decomposed.clone();
        cornered.poles[4 + 1] += DVec3::new(0.0, 0.0, 1e-6);
        assert!(cornered.with_simple_knots_v().is_none());
    }

    #[test]
    fn assembly_round_trips_with_full_multiplicity_knots() {
        let c = sample_curve();
        let pw = c.to_piecewise().unwrap();
        // Scale the second segment's weights: assembly must undo it at the joint.
        let segs = vec![
            pw.segments()[0].clone(),
            pw.segments()[1].scaled_weights(7.0),
        ];
        let pw = PiecewiseCurve::new(segs, pw.breaks().to_vec()).unwrap();
        let back = NurbsCurve::from_piecewise(&pw).unwrap();
        assert_eq!(
            back.knots,
            vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.3, 0.3, 1.2, 1.2, 1.2, 1.2]
        );
        assert_eq!(back.poles.len(), 7);
        for i in 0..=40 {
            let t = 1.2 * i as f64 / 40.0;
            assert!((de_boor(&back, t) - pw.eval(t)).length() < 1e-13);
        }
    }

    #[test]
    fn rejects_malformed_knot_vectors_naming_the_argument() {
        let c = sample_curve();
        let bad = |knots: Vec<f64>| {
            NurbsCurve::new(3, c.poles.clone(), None, knots)
                .unwrap_err()
                .message()
                .to_string()
        };
        // A Rust caller passed vectors; the C layer's counts keep their C names.
        assert!(bad(vec![0.0; 9]).starts_with("knots.len() = 9 but poles.len() + degree + 1 = 10"));
        let c_names = check_nurbs_counts(3, 6, 9, "_v").unwrap_err();
        assert!(c_names
            .message()
            .starts_with("knot_count_v = 9 but pole_count_v + degree_v + 1 = 10"));
        assert!(bad(vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.4, 1.0, 1.0, 1.0, 1.0]).contains("decrease"));
        assert!(bad(vec![0.0, 0.0, 0.0, 0.1, 0.5, 0.6, 1.0, 1.0, 1.0, 1.0]).contains("clamped"));
        assert!(bad(vec![0.0; 10]).contains("empty"));
        assert!(
            bad(vec![0.0, 0.0, 0.0, 0.0, f64::NAN, 0.5, 1.0, 1.0, 1.0, 1.0]).contains("knots[4]")
        );
        let four = vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
        let e = NurbsCurve::new(
            3,
            [c.poles.clone(), vec![DVec3::ONE, DVec3::ONE]].concat(),
            None,
            four,
        )
        .unwrap_err();
        assert!(e.message().contains("multiplicity"));
        // End runs longer than degree + 1 (the decomposition would index out of range).
        let six = [c.poles.clone(), vec![DVec3::ONE]].concat();
        for knots in [
            vec![0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0, 1.0],
            vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0],
        ] {
            let e = NurbsCurve::new(3, six.clone(), None, knots).unwrap_err();
            assert!(e.message().contains("end knot has multiplicity"), "{e}");
        }
        let e = NurbsCurve::new(
            3,
            c.poles.clone(),
            Some(vec![1.0, 1.0, -1.0, 1.0, 1.0, 1.0]),
            c.knots.clone(),
        );
        assert!(e.unwrap_err().message().contains("weights[2]"));
        let e = NurbsCurve::new(0, c.poles.clone(), None, c.knots.clone());
        assert!(e.unwrap_err().message().contains("degree"));
    }

    #[test]
    fn surface_decomposition_and_assembly() {
        // Degree (2, 1) cylinder-like surface with an interior knot in u.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let ring = [
            (DVec3::X, 1.0),
            (DVec3::new(1.0, 1.0, 0.0), s),
            (DVec3::Y, 1.0),
            (DVec3::new(-1.0, 1.0, 0.0), s),
            (DVec3::new(-1.0, 0.0, 0.0), 1.0),
        ];
        let mut poles = Vec::new();
        let mut weights = Vec::new();
        for (p, w) in ring {
            for z in [0.0, 1.0, 3.0] {
                poles.push(p + DVec3::Z * z);
                weights.push(w);
            }
        }
        let knots_u = vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0];
        let knots_v = vec![0.0, 0.0, 0.4, 1.0, 1.0];
        let nurbs = NurbsSurface::new(2, 1, 5, 3, poles, Some(weights), knots_u, knots_v).unwrap();
        let pw = nurbs.to_piecewise().unwrap();
        assert_eq!((pw.u_breaks().len(), pw.v_breaks().len()), (3, 3));
        for i in 0..=10 {
            for j in 0..=10 {
                let (u, v) = (i as f64 / 10.0, j as f64 / 10.0);
                let p = pw.eval(u, v);
                assert!((p.truncate().length() - 1.0).abs() < 1e-14);
                assert!(p.y >= -1e-15);
            }
        }
        let back = NurbsSurface::from_piecewise(&pw).unwrap();
        assert_eq!((back.pole_count_u, back.pole_count_v), (5, 3));
        let again = back.to_piecewise().unwrap();
        for i in 0..=7 {
            let (u, v) = (i as f64 / 7.0, 1.0 - i as f64 / 7.0);
            assert!((again.eval(u, v) - pw.eval(u, v)).length() < 1e-14);
        }
    }

    /// Issue finding (overflowing NURBS): knots ±1e308 evaluated to the first pole or NaN,
    /// all weights 5e-324 to Inf/NaN. Both are the curve of knots [0, 1] and weights 1.
    #[test]
    fn extreme_knots_and_weights_evaluate_like_their_normalized_curve() {
        let poles = vec![
            DVec3::ZERO,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(2.0, 0.0, 1.0),
            DVec3::new(3.0, 1.0, 0.0),
        ];
        let unit = |k: f64| vec![k, k, k, k];
        let reference = NurbsCurve::new(3, poles.clone(), None, [unit(0.0), unit(1.0)].concat())
            .unwrap()
            .to_piecewise()
            .unwrap();
        let wide = NurbsCurve::new(3, poles.clone(), None, [unit(-1e308), unit(1e308)].concat())
            .unwrap()
            .to_piecewise()
            .unwrap();
        let light = NurbsCurve::new(
            3,
            poles.clone(),
            Some(vec![5e-324; 4]),
            [unit(0.0), unit(1.0)].concat(),
        )
        .unwrap()
        .to_piecewise()
        .unwrap();
        for i in 0..=8 {
            let s = i as f64 / 8.0;
            let expected = reference.eval_jet(s);
            let t = crate::math::lerp(-1e308, 1e308, s);
            let jet = wide.eval_jet(t);
            assert!(
                (jet.point - expected.point).length() < 1e-15,
                "{s}: {}",
                jet.point
            );
            // d/dt = d/ds / 2e308.
            assert!((jet.d1 * 1e308 * 2.0 - expected.d1).length() < 1e-14 * expected.d1.length());
            assert!(jet.d2.is_finite());
            let jet = light.eval_jet(s);
            assert!((jet.point - expected.point).length() < 1e-15);
            assert!((jet.d1 - expected.d1).length() < 1e-14 && jet.d2.is_finite());
        }
        assert!((wide.eval(0.0) - DVec3::new(1.5, 0.5, 0.375)).length() < 1e-15);
    }

    /// Issue finding (overflowing NURBS): data whose evaluation overflows — a weight of
    /// 1e308 among weights 1 (NaN derivatives), poles at ±1e308 (infinite derivatives), a
    /// domain [0, 5e-324] (an infinite derivative) — are refused at creation, saying why.
    #[test]
    fn data_whose_evaluation_would_overflow_are_refused_with_the_reason() {
        let poles = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE];
        let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let message = |poles: Vec<DVec3>, weights: Option<Vec<f64>>, knots: Vec<f64>| {
            NurbsCurve::new(3, poles, weights, knots)
                .and_then(|c| c.to_piecewise())
                .unwrap_err()
                .message()
        };
        let heavy = message(
            poles.clone(),
            Some(vec![1.0, 1e308, 1.0, 1.0]),
            knots.clone(),
        );
        assert!(
            heavy.contains("weights[1] = 1e308") && heavy.contains("1e300"),
            "{heavy}"
        );
        let far = vec![DVec3::ZERO, DVec3::X * 1e308, -DVec3::X * 1e308, DVec3::ONE];
        let far = message(far, None, knots.clone());
        assert!(
            far.starts_with("poles[1] has a coordinate beyond ±1e300"),
            "{far}"
        );
        let short = [vec![0.0; 4], vec![5e-324; 4]].concat();
        let short = message(poles.clone(), None, short);
        assert!(
            short.starts_with("segment 0: its derivatives could exceed 1e300")
                && short.contains("5e-324"),
            "{short}"
        );
        // Within range: a span of 1e-150 has derivatives of 1e150 and 1e300 at most.
        let tiny = [vec![0.0; 4], vec![1e-140; 4]].concat();
        let c = NurbsCurve::new(3, poles, None, tiny)
            .unwrap()
            .to_piecewise()
            .unwrap();
        let jet = c.eval_jet(5e-141);
        assert!(jet.d1.is_finite() && jet.d2.is_finite());
    }

    /// Surfaces likewise: knots ±1e308 in u and subnormal weights evaluate like the
    /// normalized surface; a patch whose derivatives overflow is refused.
    #[test]
    fn extreme_surfaces_evaluate_or_are_refused() {
        let poles: Vec<DVec3> = (0..4)
            .flat_map(|i| (0..2).map(move |j| DVec3::new(i as f64, j as f64, (i * j) as f64)))
            .collect();
        let make = |knots_u: Vec<f64>, weights: Option<Vec<f64>>| {
            NurbsSurface::new(
                3,
                1,
                4,
                2,
                poles.clone(),
                weights,
                knots_u,
                vec![0.0, 0.0, 1.0, 1.0],
            )
            .and_then(|s| s.to_piecewise())
        };
        let unit = [vec![0.0; 4], vec![1.0; 4]].concat();
        let reference = make(unit.clone(), None).unwrap();
        let wide = make(
            [vec![-1e308; 4], vec![1e308; 4]].concat(),
            Some(vec![1e-320; 8]),
        )
        .unwrap();
        for (s, v) in [(0.0, 0.0), (0.3, 0.7), (1.0, 0.5)] {
            let jet = wide.eval_jet(crate::math::lerp(-1e308, 1e308, s), v);
            let expected = reference.eval_jet(s, v);
            assert!((jet.point - expected.point).length() < 1e-14);
            assert!((jet.dv - expected.dv).length() < 1e-13 && jet.du.is_finite());
            assert!(jet.duu.is_finite() && jet.duv.is_finite() && jet.dvv.is_finite());
        }
        let e = make([vec![0.0; 4], vec![5e-324; 4]].concat(), None).unwrap_err();
        assert!(
            e.message().starts_with("patch (0, 0): its derivatives"),
            "{e}"
        );
    }
}
