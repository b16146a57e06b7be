//! NURBS curves and surfaces: validation of input data, conversion to piecewise Bézier
//! form by knot insertion (Boehm's algorithm, Piegl & Tiller, *The NURBS Book*, §5.2), and
//! assembly of piecewise Bézier objects into one clamped NURBS.
//!
//! Assembly joins segments with interior knots of full multiplicity (= degree). Segments
//! are first raised to a common degree; then each segment's homogeneous control points are
//! multiplied by a constant (which changes neither geometry nor parameterization) so that
//! the pole shared by two segments has the same weight on both sides. That is exactly the
//! layout OpenCascade `Geom_BSpline*`, FreeCAD, IGES 126/128 and STEP accept.

use super::bernstein::MAX_DEGREE;
use super::curve::RationalBezierCurve;
use super::homogeneous::{lift, project};
use super::piecewise::{PiecewiseCurve, PiecewiseSurface};
use super::surface::RationalBezierPatch;
use crate::error::{invalid, Result};
use crate::math::largest_coordinate;
use glam::{DVec3, DVec4};

/// Relative tolerance for poles that must coincide where segments meet.
const JOINT_TOLERANCE: f64 = 1e-9;

/// A NURBS curve with Cartesian poles, positive weights and a clamped knot vector.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve {
    pub degree: usize,
    pub poles: Vec<DVec3>,
    pub weights: Vec<f64>,
    pub knots: Vec<f64>,
}

/// A NURBS surface; pole (i, j) is stored at `i * pole_count_v + j`, i along u.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurface {
    pub degree_u: usize,
    pub degree_v: usize,
    pub pole_count_u: usize,
    pub pole_count_v: usize,
    pub poles: Vec<DVec3>,
    pub weights: Vec<f64>,
    pub knots_u: Vec<f64>,
    pub knots_v: Vec<f64>,
}

/// Checks degree, pole count and knot count against each other, before any array is read
/// (so that a wrong count is reported instead of reading past the caller's arrays). Names
/// use the C API's argument names with `suffix` ("" or "_u"/"_v").
pub fn check_nurbs_counts(
    degree: usize,
    pole_count: usize,
    knot_count: usize,
    suffix: &str,
) -> Result<()> {
    if degree == 0 || degree > MAX_DEGREE {
        return invalid!("degree{suffix} = {degree} must lie in 1..={MAX_DEGREE}");
    }
    if pole_count < degree + 1 {
        return invalid!(
            "pole_count{suffix} = {pole_count} is less than degree{suffix} + 1 = {}",
            degree + 1
        );
    }
    if pole_count.checked_add(degree + 1) != Some(knot_count) {
        return invalid!(
            "knot_count{suffix} = {knot_count} but pole_count{suffix} + degree{suffix} + 1 = {}",
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
    // Ends of multiplicity above degree + 1 leave a basis function that is zero everywhere
    // (a property-test finding: a run of 5 for degree 3 overran the Bézier decomposition).
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
    if weights.len() != poles.len() {
        return invalid!("{} weights for {} poles", weights.len(), poles.len());
    }
    if let Some(i) = weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
        return invalid!("weights[{i}] = {} must be finite and positive", weights[i]);
    }
    Ok(())
}

/// Inserts interior knots until each has multiplicity `degree`, in homogeneous coordinates.
/// `points` is a list of control nets sharing the knot vector (one curve, or every row or
/// column of a surface). Returns the distinct breakpoints; afterwards each net holds
/// `segments * degree + 1` points, segment k using `points[k*degree ..= k*degree + degree]`.
fn decompose(degree: usize, knots: &[f64], nets: &mut [Vec<DVec4>]) -> Vec<f64> {
    let p = degree;
    let mut knots = knots.to_vec();
    let mut i = p + 1;
    while i < knots.len() - p - 1 {
        let u = knots[i];
        let multiplicity = knots.iter().filter(|&&k| k == u).count();
        if multiplicity >= p {
            i += multiplicity;
            continue;
        }
        // Span k with knots[k] <= u < knots[k+1]: the last index holding u.
        let k = knots
            .iter()
            .rposition(|&x| x <= u)
            .expect("knot inside the domain");
        for net in nets.iter_mut() {
            let mut inserted = Vec::with_capacity(net.len() + 1);
            for j in 0..=net.len() {
                let q = if j + p <= k {
                    net[j]
                } else if j > k {
                    net[j - 1]
                } else {
                    let alpha = (u - knots[j]) / (knots[j + p] - knots[j]);
                    net[j] * alpha + net[j - 1] * (1.0 - alpha)
                };
                inserted.push(q);
            }
            *net = inserted;
        }
        knots.insert(k + 1, u);
    }
    let mut breaks = knots[p..knots.len() - p].to_vec();
    breaks.dedup();
    breaks
}

impl NurbsCurve {
    /// Validates NURBS data (`weights = None` means all 1).
    pub fn new(
        degree: usize,
        poles: Vec<DVec3>,
        weights: Option<Vec<f64>>,
        knots: Vec<f64>,
    ) -> Result<Self> {
        check_nurbs_counts(degree, poles.len(), knots.len(), "")?;
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
            .zip(&self.weights)
            .map(|(&x, &w)| lift(x, w))
            .collect::<Vec<_>>()];
        let breaks = decompose(p, &self.knots, &mut nets);
        let segments = (0..breaks.len() - 1)
            .map(|k| RationalBezierCurve::from_homogeneous(nets[0][k * p..=k * p + p].to_vec()))
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
}

impl NurbsSurface {
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
        check_nurbs_counts(degree_u, pole_count_u, knots_u.len(), "_u")?;
        check_nurbs_counts(degree_v, pole_count_v, knots_v.len(), "_v")?;
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
            .zip(&self.weights)
            .map(|(&x, &w)| lift(x, w))
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
        let scale = coordinate_scale(
            surface
                .patches()
                .iter()
                .flat_map(|p| p.homogeneous().iter().map(|&h| project(h))),
        );
        let (nu, nv) = (ku * pu + 1, kv * pv + 1);
        let mut net: Vec<Option<DVec4>> = vec![None; nu * nv];
        for a in 0..ku {
            for b in 0..kv {
                let patch = surface.patch(a, b);
                let patch = patch.elevated(pu - patch.degree_u(), pv - patch.degree_v());
                // Match the corner shared with an already placed neighbour.
                let corner = net[a * pu * nv + b * pv];
                let factor = corner.map_or(1.0, |c| c.w / patch.at(0, 0).w);
                for i in 0..=pu {
                    for j in 0..=pv {
                        let h = patch.at(i, j) * factor;
                        let slot = &mut net[(a * pu + i) * nv + b * pv + j];
                        match slot {
                            Some(existing) if !homogeneous_close(*existing, h, scale) => {
                                return invalid!(
                                    "patch ({a}, {b}) does not join its neighbours in homogeneous coordinates"
                                );
                            }
                            Some(_) => {}
                            None => *slot = Some(h),
                        }
                    }
                }
            }
        }
        let net: Vec<DVec4> = net
            .into_iter()
            .map(|h| h.expect("every pole is set"))
            .collect();
        Ok(Self {
            degree_u: pu,
            degree_v: pv,
            pole_count_u: nu,
            pole_count_v: nv,
            poles: net.iter().map(|&h| project(h)).collect(),
            weights: net.iter().map(|h| h.w).collect(),
            knots_u: clamped_knots(surface.u_breaks(), pu),
            knots_v: clamped_knots(surface.v_breaks(), pv),
        })
    }
}

/// The clamped knot vector with full-multiplicity interior knots at `breaks`.
fn clamped_knots(breaks: &[f64], degree: usize) -> Vec<f64> {
    let last = breaks.len() - 1;
    breaks
        .iter()
        .enumerate()
        .flat_map(|(k, &b)| {
            std::iter::repeat_n(
                b,
                if k == 0 || k == last {
                    degree + 1
                } else {
                    degree
                },
            )
        })
        .collect()
}

/// A length scale of a point set, for relative tolerances (at least 1).
fn coordinate_scale(points: impl Iterator<Item = DVec3>) -> f64 {
    largest_coordinate(points).max(1.0)
}

fn homogeneous_close(a: DVec4, b: DVec4, scale: f64) -> bool {
    let weight_ok = (a.w - b.w).abs() <= JOINT_TOLERANCE * a.w.abs().max(b.w.abs());
    weight_ok && (project(a) - project(b)).length() <= JOINT_TOLERANCE * scale
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
        assert!(bad(vec![0.0; 9]).contains("knot_count"));
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
        // Property-test finding: end runs longer than degree + 1 (an index out of range).
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
}
