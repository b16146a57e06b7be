//! The C API of RRMF quintics (`rmfsurf::rrmf_quintic`): all interpolants for one η, the
//! curve and exact rational RMF of one of them, the η of least shape measure, and G1
//! splines with one continuous rational RMF.

use super::boundary::{
    buffer, guard, invalid_arg, optional_out, out_ptr, reference, sized_out, write, write_sized,
    FfiError, FfiResult, OptionsStruct,
};
use super::curve::RmfCurve;
use super::frames::{write_framed, RmfFrames};
use super::input::hermite_arrays;
use super::status::RmfStatus;
use super::types::RmfVec3;
use rmfsurf::glam::DVec3;
use rmfsurf::{
    rrmf::best_quintic, rrmf::planar_deviation as rrmf_planar_deviation, rrmf::planar_quintic,
    rrmf::quintic_curve, rrmf::quintic_rmf, rrmf::quintics as rrmf_quintics,
    rrmf::quintics_reporting as rrmf_quintics_reporting, rrmf::spline as rrmf_spline,
    rrmf::spline_within as rrmf_spline_within, rrmf::Budget as RrmfBudget, rrmf::CanonicalHermite,
    rrmf::Complex, rrmf::RrmfQuintic, rrmf::ShapeMeasure,
    rrmf::MAX_ETA_SAMPLES as RRMF_MAX_ETA_SAMPLES,
    rrmf::MAX_REFINEMENT_SOLVES as RRMF_MAX_REFINEMENT_SOLVES,
    rrmf::PLANAR_TOLERANCE as RRMF_PLANAR_TOLERANCE, FramedCurve, HermiteSegment,
};

/// One RRMF quintic Hermite interpolant (Farouki, Giannelli & Sestini, Section 4).
///
/// The quintic's hodograph is r'(t) = (|α|² − |β|², 2 Re(α β̄), 2 Im(α β̄)) with the complex
/// quadratics α(t) = Σ α_k B_k(t), β(t) = Σ β_k B_k(t) (Bernstein basis of degree 2), in
/// canonical coordinates: p0 at the origin, p1 − p0 along +x, t0 in the (x, y)-plane with
/// positive y. w(t) = Σ w_k B_k(t) is the polynomial of the RRMF condition (4); the RMF
/// (9) turns the Euler–Rodrigues frame by the angle of w². Complex numbers are stored as
/// (Re, Im) pairs: `alpha[2k]` = Re α_k, `alpha[2k + 1]` = Im α_k.
/// \ingroup rmf_rrmf
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RmfRrmfQuintic {
    /// The angular parameter η of the solution (radians).
    pub eta: f64,
    /// ρ > 0 with ρ² = |r'(1)| / |r'(0)| (eq. (20)).
    pub rho: f64,
    /// Re, Im of alpha_0, alpha_1, alpha_2 (canonical coordinates, alpha_0 real >= 0).
    pub alpha: [f64; 6],
    /// Re, Im of beta_0, beta_1, beta_2.
    pub beta: [f64; 6],
    /// Re, Im of w_0 (= 1), w_1, w_2.
    pub w: [f64; 6],
    /// Arc length L = ∫ σ dt.
    pub arc_length: f64,
    /// Frenet-frame energy E = ∫ (κ² + τ²) ds.
    pub energy_frenet: f64,
    /// RMF energy E_rmf = ∫ κ² ds.
    pub energy_rmf: f64,
}

fn pairs(z: &[Complex; 3]) -> [f64; 6] {
    [z[0].re, z[0].im, z[1].re, z[1].im, z[2].re, z[2].im]
}

impl From<&RrmfQuintic> for RmfRrmfQuintic {
    fn from(q: &RrmfQuintic) -> Self {
        Self {
            eta: q.eta,
            rho: q.rho,
            alpha: pairs(&q.hopf.alpha),
            beta: pairs(&q.hopf.beta),
            w: pairs(&q.w),
            arc_length: q.measures.arc_length,
            energy_frenet: q.measures.energy_frenet,
            energy_rmf: q.measures.energy_rmf,
        }
    }
}

/// Shape measure: RMF energy E_rmf = ∫ κ² ds. Note: E_rmf of a curve scaled by s is
/// E_rmf / s, and the family of interpolants contains arbitrarily large loops, so its
/// minimum can be a huge curve; RMF_RRMF_MEASURE_SCALED_ENERGY_RMF compares shapes.
/// \ingroup rmf_rrmf
pub const RMF_RRMF_MEASURE_ENERGY_RMF: u32 = 0;
/// Shape measure: Frenet-frame energy E = ∫ (κ² + τ²) ds (same caveat as E_rmf).
/// \ingroup rmf_rrmf
pub const RMF_RRMF_MEASURE_ENERGY_FRENET: u32 = 1;
/// Shape measure: arc length L.
/// \ingroup rmf_rrmf
pub const RMF_RRMF_MEASURE_ARC_LENGTH: u32 = 2;
/// Shape measure: L · E_rmf, invariant under scaling; picks fair curves (recommended).
/// \ingroup rmf_rrmf
pub const RMF_RRMF_MEASURE_SCALED_ENERGY_RMF: u32 = 3;
/// Shape measure: L · E, invariant under scaling.
/// \ingroup rmf_rrmf
pub const RMF_RRMF_MEASURE_SCALED_ENERGY_FRENET: u32 = 4;

fn shape_measure(measure: u32) -> FfiResult<ShapeMeasure> {
    Ok(match measure {
        RMF_RRMF_MEASURE_ENERGY_RMF => ShapeMeasure::EnergyRmf,
        RMF_RRMF_MEASURE_ENERGY_FRENET => ShapeMeasure::EnergyFrenet,
        RMF_RRMF_MEASURE_ARC_LENGTH => ShapeMeasure::ArcLength,
        RMF_RRMF_MEASURE_SCALED_ENERGY_RMF => ShapeMeasure::ScaledEnergyRmf,
        RMF_RRMF_MEASURE_SCALED_ENERGY_FRENET => ShapeMeasure::ScaledEnergyFrenet,
        other => {
            return invalid_arg(format!(
                "measure = {other} is not one of the RMF_RRMF_MEASURE_* constants (0 to 4)"
            ))
        }
    })
}

fn hermite(p0: RmfVec3, t0: RmfVec3, p1: RmfVec3, t1: RmfVec3) -> FfiResult<HermiteSegment> {
    Ok(HermiteSegment::new(
        p0.into(),
        t0.into(),
        p1.into(),
        t1.into(),
    )?)
}

/// All RRMF quintics interpolating G1 Hermite data for one value of the angular parameter
/// η (the Algorithm of Section 4 of Farouki, Giannelli & Sestini): ρ is every positive root
/// of the sextic (35) (or, when s_f = s_i and η = φ/2, of the quartic of the special case
/// α_1 = 0), and each solution is verified by substitution into the RRMF conditions (7)–(8)
/// (to 1e-10 relative) and the interpolation conditions (end point to 1e-12 of
/// max(|p1 − p0|, L), end tangents to 1e-12 rad). A root whose curve is numerically
/// singular — its speed dipping below 1e-6 of its maximum on [0, 1], where its tangent is
/// determined by rounding errors — is not returned but listed by
/// rmf_rrmf_quintic_irregular_roots; this happens only for nearly degenerate data (a tangent
/// almost along p1 − p0). Where |δ0| = |δ1| (the exceptional case after (32)), (35) has a
/// double root, taken from the quadratic |δ0|² = |δ1|² to full precision.
///
/// ρ far from 1 means one end derivative is much shorter than the other: the first or last
/// leg of the Bézier control polygon is then short, and a tangent computed from the poles
/// alone is accurate only to about 1e-16 |P| / |leg|.
///
/// Capacity: with fewer solutions than exist, RMF_ERROR_BUFFER_TOO_SMALL is returned and
/// only *count is written; capacity 0 with solutions NULL queries the count that way.
///
/// @param[in] p0, p1 End points (finite, distinct).
/// @param[in] t0, t1 End tangents (finite, non-zero; normalized here). The data must not be
///            planar: neither tangent along p1 − p0, and the tangents not coplanar with it.
/// @param[in] eta The angular parameter η (finite, radians; any value, 2π-periodic).
/// @param[out] solutions Buffer for capacity solutions, written in increasing ρ; may be NULL
///             if capacity is 0.
/// @param[in] capacity Capacity of solutions.
/// @param[out] count Receives the number of solutions that exist for this η (possibly 0).
/// @return RMF_OK on success (also when no solution exists for this η: *count = 0).
/// @return RMF_ERROR_NULL_POINTER If count is NULL, or solutions is NULL with capacity > 0.
/// @return RMF_ERROR_INVALID_INPUT If a point or tangent is not finite, a tangent is zero,
///         p0 and p1 coincide, the data are planar or degenerate (θ_i, θ_f or φ a multiple of
///         π), or eta is not finite.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity < *count; then only *count is written.
/// @return RMF_ERROR_INTERNAL On an internal error.
/// \since 0.1
/// \ingroup rmf_rrmf
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_rrmf_quintic_solutions(
    p0: RmfVec3,
    t0: RmfVec3,
    p1: RmfVec3,
    t1: RmfVec3,
    eta: f64,
    solutions: *mut RmfRrmfQuintic,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_rrmf_quintic_solutions", || {
        let count = out_ptr(count, "count")?;
        let solutions = buffer(solutions, capacity, "solutions")?;
        let found = rrmf_quintics(&hermite(p0, t0, p1, t1)?, eta)?;
        write(count, found.len());
        if found.len() > capacity {
            return Err(FfiError::BufferTooSmall(format!(
                "{} solutions exist for eta = {eta}, capacity is {capacity}",
                found.len()
            )));
        }
        for (slot, q) in solutions.iter_mut().zip(&found) {
            *slot = q.into();
        }
        Ok(())
    })
}

/// The roots of the sextic (35) for one η whose quintics interpolate the Hermite data with
/// an RRMF but whose speed dips below 1e-6 of its maximum (near-cusps), which
/// rmf_rrmf_quintic_solutions leaves out: their unit tangent is known to no better than
/// 1e-10 rad there, too little for the exact frames. Empty for data in general position.
///
/// Capacity: as for rmf_rrmf_quintic_solutions (capacity 0 with NULL arrays queries the
/// count).
///
/// @param[in] p0, p1 End points (as for rmf_rrmf_quintic_solutions).
/// @param[in] t0, t1 End tangents (as for rmf_rrmf_quintic_solutions).
/// @param[in] eta The angular parameter η (finite, radians).
/// @param[out] rho Buffer for capacity values of ρ (eq. (20)), increasing; may be NULL if
///             capacity is 0.
/// @param[out] speed_ratio Buffer for capacity ratios of least to greatest speed on [0, 1],
///             one per ρ; may be NULL if capacity is 0.
/// @param[in] capacity Capacity of rho and speed_ratio.
/// @param[out] count Receives the number of such roots for this η (usually 0).
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If count is NULL, or rho or speed_ratio is NULL with
///         capacity > 0.
/// @return RMF_ERROR_INVALID_INPUT As for rmf_rrmf_quintic_solutions.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity < *count; then only *count is written.
/// @return RMF_ERROR_INTERNAL On an internal error.
/// \since 0.2
/// \ingroup rmf_rrmf
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_rrmf_quintic_irregular_roots(
    p0: RmfVec3,
    t0: RmfVec3,
    p1: RmfVec3,
    t1: RmfVec3,
    eta: f64,
    rho: *mut f64,
    speed_ratio: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_rrmf_quintic_irregular_roots", || {
        let count = out_ptr(count, "count")?;
        let rho = buffer(rho, capacity, "rho")?;
        let speed_ratio = buffer(speed_ratio, capacity, "speed_ratio")?;
        let found = rrmf_quintics_reporting(&hermite(p0, t0, p1, t1)?, eta)?.irregular;
        write(count, found.len());
        if found.len() > capacity {
            return Err(FfiError::BufferTooSmall(format!(
                "{} irregular roots exist for eta = {eta}, capacity is {capacity}",
                found.len()
            )));
        }
        for ((r, s), root) in rho.iter_mut().zip(speed_ratio.iter_mut()).zip(&found) {
            (*r, *s) = (root.rho, root.speed_ratio);
        }
        Ok(())
    })
}

/// The angles of G1 Hermite data in the canonical form of Farouki, Giannelli & Sestini
/// (eqs. (11)–(12)): coordinates with p0 at the origin, p1 − p0 along +x and t0 in the
/// (x, y)-plane with positive y, where t0 = (cos θ_i, sin θ_i, 0) and
/// t1 = (cos θ_f, sin θ_f cos φ, sin θ_f sin φ). When θ_f = θ_i, the interpolants at
/// η = φ/2 are those of the special case α_1 = 0.
///
/// @param[in] p0, t0, p1, t1 Hermite data (as for rmf_rrmf_quintic_solutions).
/// @param[out] theta_i Receives θ_i in (0, π).
/// @param[out] theta_f Receives θ_f in (0, π).
/// @param[out] phi Receives φ in (0, 2π), the branch of the paper's examples.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If theta_i, theta_f or phi is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the data are invalid, planar or degenerate (as for
///         rmf_rrmf_quintic_solutions).
/// \since 0.1
/// \ingroup rmf_rrmf
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_rrmf_quintic_angles(
    p0: RmfVec3,
    t0: RmfVec3,
    p1: RmfVec3,
    t1: RmfVec3,
    theta_i: *mut f64,
    theta_f: *mut f64,
    phi: *mut f64,
) -> RmfStatus {
    guard("rmf_rrmf_quintic_angles", || {
        let outs = [
            out_ptr(theta_i, "theta_i")?,
            out_ptr(theta_f, "theta_f")?,
            out_ptr(phi, "phi")?,
        ];
        let c = CanonicalHermite::new(&hermite(p0, t0, p1, t1)?)?;
        for (p, value) in outs.into_iter().zip([c.theta_i, c.theta_f, c.phi]) {
            write(p, value);
        }
        Ok(())
    })
}

/// Relative distance below which a caller's solution is recognized as a recomputed one.
const SAME_SOLUTION: f64 = 1e-9;

/// The solution for the data and solution->eta that `solution` describes.
fn recompute(data: &HermiteSegment, solution: &RmfRrmfQuintic) -> FfiResult<RrmfQuintic> {
    if !(solution.eta.is_finite() && solution.rho.is_finite()) {
        return invalid_arg("solution->eta and solution->rho must be finite".to_string());
    }
    let distance = |q: &RrmfQuintic| {
        let c = RmfRrmfQuintic::from(q);
        let scale = c
            .alpha
            .iter()
            .chain(&c.beta)
            .map(|x| x.abs())
            .fold(c.rho, f64::max);
        let differences = [c.rho - solution.rho]
            .into_iter()
            .chain(c.alpha.iter().zip(&solution.alpha).map(|(a, b)| a - b))
            .chain(c.beta.iter().zip(&solution.beta).map(|(a, b)| a - b));
        differences.map(f64::abs).fold(0.0, f64::max) / scale
    };
    // Planar data have one interpolant per measure, not an η family: the solution is
    // recognized among the planar quintics of every measure.
    let candidates = if rrmf_planar_deviation(data)? <= RRMF_PLANAR_TOLERANCE {
        [
            ShapeMeasure::EnergyRmf,
            ShapeMeasure::ArcLength,
            ShapeMeasure::ScaledEnergyRmf,
        ]
        .into_iter()
        .map(|m| planar_quintic(data, m))
        .collect::<Result<Vec<_>, _>>()?
    } else {
        rrmf_quintics(data, solution.eta)?
    };
    let nearest = candidates
        .into_iter()
        .map(|q| (distance(&q), q))
        .min_by(|a, b| a.0.total_cmp(&b.0));
    match nearest {
        Some((d, q)) if d <= SAME_SOLUTION => Ok(q),
        _ => invalid_arg(format!(
            "solution (eta = {}, rho = {}) is not an interpolant of these p0, t0, p1, t1: pass one \
             returned by rmf_rrmf_quintic_solutions or rmf_rrmf_quintic_best for the same data",
            solution.eta, solution.rho
        )),
    }
}

/// The curve and exact rational rotation-minimizing frame of one RRMF quintic interpolant:
/// the quintic as a polynomial Bézier curve of degree 5 on [0, 1] in the caller's
/// coordinates, and its RMF (9) — rational of degree 8, split where needed so that the
/// weights are positive and within a factor 100 of each other on every segment — turned
/// about the tangent so that f2 starts at initial_normal (a constant rotation of an RMF is
/// again an RMF).
///
/// The solution is recomputed from the data and solution->eta and must match *solution
/// (ρ, α, β to 1e-9 relative), so a curve always interpolates the data it is given with.
///
/// @param[in] p0, t0, p1, t1 The Hermite data the solution was computed for.
/// @param[in] solution A solution from rmf_rrmf_quintic_solutions or rmf_rrmf_quintic_best.
/// @param[in] initial_normal Projected onto the normal plane at p0 and normalized to give f2
///            there; f3 = t × f2.
/// @param[out] curve Receives the curve; free with rmf_curve_free. Untouched on failure.
/// @param[out] frames Receives the frames (RMF_FRAMES_RATIONAL, usable by
///             rmf_sweep_surface with this curve); free with rmf_frames_free. Untouched on
///             failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If solution, curve or frames is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the data are invalid (as for rmf_rrmf_quintic_solutions),
///         the solution does not belong to them, or initial_normal is not finite, zero or
///         along t0.
/// @return RMF_ERROR_NO_SOLUTION If the frame cannot be given positive weights (a singular
///         curve; not seen for solutions returned by this library).
/// @return RMF_ERROR_INTERNAL On an internal error.
/// \since 0.1
/// \ingroup rmf_rrmf
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_rrmf_quintic_curve(
    p0: RmfVec3,
    t0: RmfVec3,
    p1: RmfVec3,
    t1: RmfVec3,
    solution: *const RmfRrmfQuintic,
    initial_normal: RmfVec3,
    curve: *mut *mut RmfCurve,
    frames: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_rrmf_quintic_curve", || {
        let solution = reference(solution, "solution")?;
        let (curve, frames) = (out_ptr(curve, "curve")?, out_ptr(frames, "frames")?);
        let q = recompute(&hermite(p0, t0, p1, t1)?, solution)?;
        let rmf = quintic_rmf(&[q], initial_normal.into())?;
        write_framed(FramedCurve::new(quintic_curve(&[q])?, rmf)?, curve, frames)
    })
}

/// The RRMF quintic interpolant of least shape measure: the measure of every solution at
/// eta_samples values η = 2πk / eta_samples is compared, then the best is refined by
/// Brent's method between its neighbouring samples.
///
/// Work: one solve (the sextic (35) for one η, its roots, each solution verified and
/// measured) per sample plus those of the refinement — at most 502, measured 16 to 34 — so
/// eta_samples + 502 solves at most (times: docs/benchmarks.md, `cargo bench --bench
/// rrmf_quintic`). rmf_rrmf_spline_hermite_with_options caps the solves.
///
/// Planar data (chord and tangents coplanar to a sine of 1e-10, scale-free: also a tangent
/// along p1 − p0, or a straight segment), where Section 4 does not apply, get the planar PH
/// quintic (in the plane of the data, real alpha and beta, end speeds |p1 − p0|) of least
/// measure, whose exact RMF is its Euler–Rodrigues frame: then best->eta = 0, best->rho = 1,
/// best->w = (1, 0, 1, 0, 1, 0), the imaginary parts of alpha and beta are 0, and
/// *admissible = 0. A tangent within that tolerance of the plane is projected onto it.
///
/// @param[in] p0, t0, p1, t1 Hermite data (as for rmf_rrmf_quintic_solutions).
/// @param[in] measure RMF_RRMF_MEASURE_ENERGY_RMF, _ENERGY_FRENET, _ARC_LENGTH,
///            _SCALED_ENERGY_RMF (recommended: L · E_rmf) or _SCALED_ENERGY_FRENET.
/// @param[in] eta_samples Number N_η of sampled η, 1 to 1,000,000.
/// @param[out] best Receives the chosen solution (pass it to rmf_rrmf_quintic_curve).
/// @param[out] admissible Receives how many of the sampled η admit at least one solution;
///             may be NULL.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If best is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the data are invalid, measure is unknown or
///         eta_samples is 0 or too large.
/// @return RMF_ERROR_NO_SOLUTION If no sampled η admits an interpolant.
/// @return RMF_ERROR_INTERNAL On an internal error.
/// \since 0.1
/// \ingroup rmf_rrmf
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_rrmf_quintic_best(
    p0: RmfVec3,
    t0: RmfVec3,
    p1: RmfVec3,
    t1: RmfVec3,
    measure: u32,
    eta_samples: usize,
    best: *mut RmfRrmfQuintic,
    admissible: *mut usize,
) -> RmfStatus {
    guard("rmf_rrmf_quintic_best", || {
        let best = out_ptr(best, "best")?;
        let admissible = optional_out(admissible, "admissible")?;
        let measure = shape_measure(measure)?;
        let found = best_quintic(&hermite(p0, t0, p1, t1)?, measure, eta_samples)?;
        write(best, (&found.quintic).into());
        if let Some(a) = admissible {
            write(a, found.admissible);
        }
        Ok(())
    })
}

/// A G1 spline of RRMF quintics through points with unit tangents, with one continuous
/// exact rational rotation-minimizing frame along it (Farouki, Giannelli & Sestini,
/// Example 3). Segment k joins points[k] and points[k + 1] on the parameter interval
/// [k, k + 1]; its η is chosen as by rmf_rrmf_quintic_best. Each segment's RMF (9) is
/// turned about the tangent by a constant angle so that the frames agree at the joints.
/// Segments with planar data (flat stretches, straight segments) are planar PH quintics in
/// the plane of their data, with their exact RMF, as in rmf_rrmf_quintic_best; on a straight
/// segment the frame is the constant one carried from the segment before.
///
/// Work: as rmf_rrmf_quintic_best per segment, at most eta_samples + 502 solves (measured:
/// eta_samples + 16 to 34), with no bound on the total but the count of
/// segments: (count − 1) · (eta_samples + 502) solves. rmf_rrmf_spline_hermite_with_options
/// is the same with a cap on the total and a report of the work.
///
/// @param[in] points count points (finite; consecutive points distinct).
/// @param[in] tangents count tangents (finite, non-zero; normalized here).
/// @param[in] count Number of points, ≥ 2.
/// @param[in] initial_normal Projected onto the normal plane at points[0] and normalized to
///            give f2 there; f3 = t × f2.
/// @param[in] measure Shape measure per segment (RMF_RRMF_MEASURE_*).
/// @param[in] eta_samples Number N_η of sampled η per segment, 1 to 1,000,000.
/// @param[out] curve Receives the spline (degree 5, count − 1 segments); free with
///             rmf_curve_free. Untouched on failure.
/// @param[out] frames Receives the rational RMF (RMF_FRAMES_RATIONAL; its segments refine
///             the curve's where the weights had to be made positive and within a factor 100
///             of each other); free with
///             rmf_frames_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If points, tangents, curve or frames is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count < 2, a point or tangent is invalid, consecutive
///         points coincide, measure is unknown, eta_samples is 0 or too large, or initial_normal is
///         not finite, zero or along tangents[0].
/// @return RMF_ERROR_NO_SOLUTION If no sampled η admits an interpolant for some segment (the
///         message names it).
/// @return RMF_ERROR_INTERNAL On an internal error.
/// \since 0.1
/// \ingroup rmf_rrmf
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_rrmf_spline_hermite(
    points: *const RmfVec3,
    tangents: *const RmfVec3,
    count: usize,
    initial_normal: RmfVec3,
    measure: u32,
    eta_samples: usize,
    curve: *mut *mut RmfCurve,
    frames: *mut *mut RmfFrames,
) -> RmfStatus {
    guard("rmf_rrmf_spline_hermite", || {
        let (curve, frames) = (out_ptr(curve, "curve")?, out_ptr(frames, "frames")?);
        let segments = hermite_arrays(points, tangents, count)?;
        let measure = shape_measure(measure)?;
        let spline = rrmf_spline(&segments, measure, eta_samples, initial_normal.into())?;
        write_framed(spline.framed, curve, frames)
    })
}

/// What rmf_rrmf_spline_hermite_with_options aims at and may spend. Initialise with
/// rmf_rrmf_spline_options_init, then set initial_normal.
/// \since 0.2
/// \ingroup rmf_rrmf
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RmfRrmfSplineOptions {
    /// sizeof(RmfRrmfSplineOptions), written by rmf_rrmf_spline_options_init.
    pub struct_size: usize,
    /// Shape measure per segment (RMF_RRMF_MEASURE_*). Default
    /// RMF_RRMF_MEASURE_SCALED_ENERGY_RMF.
    pub measure: u32,
    /// Number N_η of sampled η per segment, 1 to 1,000,000. Default 64.
    pub eta_samples: usize,
    /// Projected onto the normal plane at points[0] and normalized to give f2 there: finite,
    /// not zero, not along tangents[0]. Default (0, 0, 0), which is refused: set it.
    pub initial_normal: RmfVec3,
    /// Most solves (the sextic (35) for one η) over the whole spline, ≥ 1: each segment
    /// costs eta_samples plus at most 502 (16 to 34 measured) for the refinement. Default
    /// SIZE_MAX (no cap).
    pub max_evaluations: usize,
}

/// Default N_η of the options.
const DEFAULT_ETA_SAMPLES: usize = 64;

impl Default for RmfRrmfSplineOptions {
    fn default() -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            measure: RMF_RRMF_MEASURE_SCALED_ENERGY_RMF,
            eta_samples: DEFAULT_ETA_SAMPLES,
            initial_normal: RmfVec3::default(),
            max_evaluations: usize::MAX,
        }
    }
}

// SAFETY: repr(C) plain numbers, usize first.
unsafe impl OptionsStruct for RmfRrmfSplineOptions {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// What rmf_rrmf_spline_hermite_with_options did. The caller sets struct_size =
/// sizeof(RmfRrmfSplineReport); the library writes the fields that fit, on success only.
/// \since 0.2
/// \ingroup rmf_rrmf
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RmfRrmfSplineReport {
    /// sizeof(RmfRrmfSplineReport), set by the caller.
    pub struct_size: usize,
    /// Solves spent (sextics for one η, scan and refinement, all segments).
    pub evaluations: usize,
    /// Quintic segments of the spline (count − 1).
    pub segments: usize,
    /// Roots left out as near-cusps over all solves (see rmf_rrmf_quintic_irregular_roots).
    pub irregular_roots: usize,
}

// SAFETY: repr(C) plain numbers, usize first.
unsafe impl OptionsStruct for RmfRrmfSplineReport {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// Writes the default options (RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 64 sampled η, no cap on
/// the solves, initial_normal zero — to be set) and struct_size.
///
/// @param[out] out The options to initialise.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if out is NULL.
/// \since 0.2
/// \ingroup rmf_rrmf
#[no_mangle]
pub unsafe extern "C" fn rmf_rrmf_spline_options_init(out: *mut RmfRrmfSplineOptions) -> RmfStatus {
    guard("rmf_rrmf_spline_options_init", || {
        let out = out_ptr(out, "out")?;
        write(out, RmfRrmfSplineOptions::default());
        Ok(())
    })
}

/// The options' fields, each checked with a message naming it, before any work.
fn check_options(given: &RmfRrmfSplineOptions) -> FfiResult<(ShapeMeasure, DVec3)> {
    let Ok(measure) = shape_measure(given.measure) else {
        return invalid_arg(format!(
            "options->measure = {} is not one of the RMF_RRMF_MEASURE_* constants (0 to 4)",
            given.measure
        ));
    };
    if !(1..=RRMF_MAX_ETA_SAMPLES).contains(&given.eta_samples) {
        return invalid_arg(format!(
            "options->eta_samples = {} must be between 1 and {}",
            given.eta_samples, RRMF_MAX_ETA_SAMPLES
        ));
    }
    if given.max_evaluations == 0 {
        return invalid_arg(
            "options->max_evaluations = 0 must be at least 1 (SIZE_MAX for no cap)".to_string(),
        );
    }
    let normal = DVec3::from(given.initial_normal);
    if !normal.is_finite() || normal == DVec3::ZERO {
        return invalid_arg(format!(
            "options->initial_normal = ({}, {}, {}) must be finite and non-zero: set it \
             (rmf_rrmf_spline_options_init leaves it zero)",
            normal.x, normal.y, normal.z
        ));
    }
    Ok((measure, normal))
}

/// rmf_rrmf_spline_hermite with its parameters in an options struct, a cap on the work and a
/// report of it. The spline is the same as rmf_rrmf_spline_hermite's for the same measure,
/// eta_samples and initial_normal. The work is counted in solves (the sextic (35) for one
/// η, its roots, every solution verified and measured): eta_samples per segment for the
/// scan plus at most 502 (measured 16 to 34) for the refinement (times:
/// docs/benchmarks.md). The call ends with
/// RMF_ERROR_NOT_CONVERGED as soon as options->max_evaluations solves are spent before the
/// last segment's η is chosen; it never spends more, and a budget of report->evaluations
/// of an uncapped call gives the same spline.
///
/// @param[in] points count points (finite; consecutive points distinct).
/// @param[in] tangents count tangents (finite, non-zero; normalized here).
/// @param[in] count Number of points, ≥ 2.
/// @param[in] options Measure, eta_samples, initial_normal and the cap (initialise with
///            rmf_rrmf_spline_options_init, then set initial_normal).
/// @param[out] curve Receives the spline (degree 5, count − 1 segments); free with
///             rmf_curve_free. Untouched on failure.
/// @param[out] frames Receives the rational RMF (RMF_FRAMES_RATIONAL), as for
///             rmf_rrmf_spline_hermite; free with rmf_frames_free. Untouched on failure.
/// @param[out] report May be NULL. With struct_size set by the caller, receives the solves
///             spent and the segments. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If points, tangents, options, curve or frames is NULL.
/// @return RMF_ERROR_INVALID_INPUT If options->struct_size or report->struct_size is no size
///         of the struct, options->measure is unknown, options->eta_samples is 0 or above
///         1,000,000, options->max_evaluations is 0, options->initial_normal is not finite,
///         zero or along tangents[0] (the message names the field), or the points and
///         tangents are invalid as for rmf_rrmf_spline_hermite.
/// @return RMF_ERROR_NO_SOLUTION If no sampled η admits an interpolant for some segment (the
///         message names it).
/// @return RMF_ERROR_NOT_CONVERGED If options->max_evaluations solves are spent before every
///         segment's η is chosen (the message names the segment).
/// @return RMF_ERROR_INTERNAL On an internal error.
/// \since 0.2
/// \ingroup rmf_rrmf
#[no_mangle]
pub unsafe extern "C" fn rmf_rrmf_spline_hermite_with_options(
    points: *const RmfVec3,
    tangents: *const RmfVec3,
    count: usize,
    options: *const RmfRrmfSplineOptions,
    curve: *mut *mut RmfCurve,
    frames: *mut *mut RmfFrames,
    report: *mut RmfRrmfSplineReport,
) -> RmfStatus {
    guard("rmf_rrmf_spline_hermite_with_options", || {
        if options.is_null() {
            return Err(FfiError::Null("options"));
        }
        let given = super::boundary::options(options, "options")?;
        let (curve, frames) = (out_ptr(curve, "curve")?, out_ptr(frames, "frames")?);
        let report = sized_out(report, "report")?;
        let (measure, normal) = check_options(&given)?;
        let segments = hermite_arrays(points, tangents, count)?;
        rmfsurf::validate::normal_plane_unit(normal, segments[0].t0, "options->initial_normal")?;
        let mut budget = RrmfBudget::new(given.max_evaluations);
        let spline =
            rrmf_spline_within(&segments, measure, given.eta_samples, normal, &mut budget)?;
        let done = RmfRrmfSplineReport {
            struct_size: std::mem::size_of::<RmfRrmfSplineReport>(),
            evaluations: budget.spent,
            segments: segments.len(),
            irregular_roots: spline.irregular_roots,
        };
        write_framed(spline.framed, curve, frames)?;
        if let Some(report) = report {
            write_sized(report, &done);
        }
        Ok(())
    })
}

/// The bound of the documentation: the refinement's most solves.
const _: () = assert!(RRMF_MAX_REFINEMENT_SOLVES == 502);
