//! `RmfConeSpline`: a cone spline surface — segments of right circular cones, cylinders and
//! planes joined G1 along common rulings (Leopoldseder & Pottmann) — with its pieces, its
//! surface between two bounds along the rulings, its boundary arc splines, bending
//! sequence, development and offsets.

use super::boundary::{
    buffer, free_handle, guard, hand_over, invalid_arg, optional_out, out_ptr, reference, slice,
    write, FfiError, FfiResult, OptionsStruct,
};
use super::curve::RmfCurve;
use super::input::{curve_or_callback, RmfCurveCallback};
use super::status::RmfStatus;
use super::surface::RmfSurface;
use super::types::RmfVec3;
use rmfsurf::glam::DVec4;
use rmfsurf::{
    cone::approximate as approximate_developable, cone::osculating_spline, cone::ConePiece,
    cone::ConeSpline, cone::DualDevelopable, cone::Element, cone::PairCase, cone::PieceKind,
    cone::Region, cone::Rule, cone::RuledSurface, cone::TangentSurface, ParametricCurve,
};
use std::ffi::c_void;

/// A G1 Hermite element: a ruling through `point` with direction `ruling` and the tangent
/// plane spanned by `ruling` and `side`. `side` is normal to `ruling` and points to where the
/// next piece attaches; the normal ruling × side must point to one side of the surface all
/// along a sequence. Directions need not be unit vectors.
/// \ingroup rmf_cone_spline
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfConeElement {
    /// A point on the ruling, where the surface is wanted (decides the nappe of a cone) and
    /// the origin of the distances along the rulings.
    pub point: RmfVec3,
    /// The ruling direction (orientation of the generators).
    pub ruling: RmfVec3,
    /// The side vector in the tangent plane, normal to the ruling.
    pub side: RmfVec3,
}

/// An axis-aligned box min ≤ x ≤ max: the region of interest Ω.
/// \ingroup rmf_cone_spline
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBox {
    /// The corner with the smallest coordinates.
    pub min: RmfVec3,
    /// The corner with the largest coordinates.
    pub max: RmfVec3,
}

/// rule of a cone pair: locally minimal vertex distance (12), the useful root. For
/// intersecting or parallel rulings (cone and cylinder cases): the biarc with equal legs.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_RULE_MIN_VERTEX_DISTANCE: u32 = 0;
/// rule of a cone pair: congruent cones, μ1 = μ2 (cone and cylinder cases: equal legs).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_RULE_CONGRUENT: u32 = 1;
/// rule of a cone pair: the first segment a cylinder (10).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_RULE_CYLINDER_FIRST: u32 = 2;
/// rule of a cone pair: the second segment a cylinder.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_RULE_CYLINDER_SECOND: u32 = 3;
/// rule of a cone pair: the given parameter: μ1 (vertex v1 = a1 + μ1 e1 on the first
/// ruling, a1 where it touches the inscribed sphere or meets the plane π), or λ1 (the first
/// leg of the biarc) in the cone and cylinder cases.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_RULE_GIVEN: u32 = 4;

/// RmfConePiece.kind: a segment of a right circular cone.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_PIECE_CONE: u32 = 0;
/// RmfConePiece.kind: a segment of a cylinder of revolution.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_PIECE_CYLINDER: u32 = 1;
/// RmfConePiece.kind: a plane sector (has a vertex) or a plane strip (parallel rulings).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_PIECE_PLANE: u32 = 2;

/// RmfConePiece.pair_case: general case (skew rulings, inscribed sphere).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_CASE_GENERAL: u32 = 0;
/// RmfConePiece.pair_case: the rulings intersect (common vertex).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_CASE_CONE: u32 = 1;
/// RmfConePiece.pair_case: parallel rulings.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_CASE_CYLINDER: u32 = 2;
/// RmfConePiece.pair_case: constant slope, det(p1, p2, n1 − n2) = 0 (13).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_CASE_CONSTANT_SLOPE: u32 = 3;
/// RmfConePiece.pair_case: equal tangent planes (one plane piece).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_CASE_PLANE: u32 = 4;
/// RmfConePiece.pair_case: not made by a cone pair (osculating cone splines).
/// \ingroup rmf_cone_spline
pub const RMF_CONE_CASE_NONE: u32 = 5;

/// rmf_cone_spline_fit_parameters: the parameters of the selected rulings.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_FIT_ELEMENTS: u32 = 0;
/// rmf_cone_spline_fit_parameters: the parameters of the inflection generators found.
/// \ingroup rmf_cone_spline
pub const RMF_CONE_FIT_INFLECTIONS: u32 = 1;

/// The data of one piece of a cone spline.
/// \ingroup rmf_cone_spline
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfConePiece {
    /// RMF_CONE_PIECE_CONE, RMF_CONE_PIECE_CYLINDER or RMF_CONE_PIECE_PLANE.
    pub kind: u32,
    /// Which case of the paper the cone pair of this piece fell into (RMF_CONE_CASE_*).
    pub pair_case: u32,
    /// 1 if the piece has a vertex (cones and plane sectors), else 0.
    pub has_vertex: u32,
    /// The vertex (valid if has_vertex).
    pub vertex: RmfVec3,
    /// A point on the axis: the vertex, or a point of a cylinder's axis; for a plane strip
    /// the start point.
    pub axis_point: RmfVec3,
    /// Unit axis direction, oriented like the rulings; a plane strip's normal.
    pub axis: RmfVec3,
    /// Half opening angle α between rulings and axis (0 for cylinders, π/2 for planes).
    pub half_angle: f64,
    /// Segment angle φ of the rotation about the axis (0 for plane strips).
    pub segment_angle: f64,
    /// The angle of the developed sector, φ sin α (0 for cylinders and strips).
    pub developed_angle: f64,
    /// Radius of a cylinder (0 otherwise).
    pub radius: f64,
    /// Width of the developed piece along its side for cylinders (r φ) and strips; else 0.
    pub developed_width: f64,
    /// The bounding ruling at the start of the piece: its reference point.
    pub start_point: RmfVec3,
    /// The start ruling's unit direction.
    pub start_ruling: RmfVec3,
    /// The start ruling's unit side vector (in the tangent plane, normal to the ruling).
    pub start_side: RmfVec3,
    /// The bounding ruling at the end of the piece: its reference point.
    pub end_point: RmfVec3,
    /// The end ruling's unit direction.
    pub end_ruling: RmfVec3,
    /// The end ruling's unit side vector.
    pub end_side: RmfVec3,
    /// The piece's patches in the surface (rmf_cone_spline_surface): patch indices
    /// first_patch .. first_patch + patch_count − 1 along v; the piece spans
    /// v ∈ [index, index + 1].
    pub first_patch: usize,
    /// The number of the piece's patches (more than one for segment angles above 120°).
    pub patch_count: usize,
}

/// What an approximation reports.
struct Fit {
    max_error: f64,
    parameters: Vec<f64>,
    inflections: Vec<f64>,
    /// `Approximation::vertex_clearance`: the smallest relative clearance of a vertex from
    /// the region of interest.
    vertex_clearance: f64,
}

/// A cone spline surface (opaque). Freed with rmf_cone_spline_free. Immutable; may be read
/// from several threads at once.
/// \ingroup rmf_cone_spline
pub struct RmfConeSpline {
    pub(crate) spline: ConeSpline,
    /// The pair case of each piece (RMF_CONE_CASE_*).
    pub(crate) cases: Vec<u32>,
    fit: Option<Fit>,
    /// A sheet-metal part (rmf_sheet_part_cone_spline, or the deprecated constructors):
    /// `spline` is its designed surface.
    pub(crate) part: Option<std::sync::Arc<crate::sheet::PartHandle>>,
}

impl RmfConeSpline {
    /// The handle of a constructed spline (no fit report, no part), with the pair case of
    /// each piece.
    fn of_spline(spline: ConeSpline, cases: Vec<u32>) -> Self {
        Self {
            spline,
            cases,
            fit: None,
            part: None,
        }
    }

    /// The handle of a sheet-metal part: its designed surface's cone spline and the part.
    pub(crate) fn of_part(part: std::sync::Arc<crate::sheet::PartHandle>) -> rmfsurf::Result<Self> {
        let spline = part.part.cone_spline()?;
        Ok(Self {
            cases: vec![RMF_CONE_CASE_NONE; spline.pieces().len()],
            spline,
            fit: None,
            part: Some(part),
        })
    }

    pub(crate) fn into_raw(self) -> *mut Self {
        Box::into_raw(Box::new(self))
    }

    /// A derived spline (bent, developed, offset) keeps the cases and the fit report, not
    /// the part.
    fn derived(&self, spline: ConeSpline) -> Self {
        Self {
            part: None,
            spline,
            cases: self.cases.clone(),
            fit: self.fit.as_ref().map(|f| Fit {
                max_error: f.max_error,
                parameters: f.parameters.clone(),
                inflections: f.inflections.clone(),
                vertex_clearance: f.vertex_clearance,
            }),
        }
    }
}

fn case_code(case: PairCase) -> u32 {
    match case {
        PairCase::General => RMF_CONE_CASE_GENERAL,
        PairCase::Cone => RMF_CONE_CASE_CONE,
        PairCase::Cylinder => RMF_CONE_CASE_CYLINDER,
        PairCase::ConstantSlope => RMF_CONE_CASE_CONSTANT_SLOPE,
        PairCase::Plane => RMF_CONE_CASE_PLANE,
    }
}

/// The rule from its C code and parameter.
fn rule_from(rule: u32, parameter: f64) -> FfiResult<Rule> {
    Ok(match rule {
        RMF_CONE_RULE_MIN_VERTEX_DISTANCE => Rule::MinimalVertexDistance,
        RMF_CONE_RULE_CONGRUENT => Rule::Congruent,
        RMF_CONE_RULE_CYLINDER_FIRST => Rule::CylinderFirst,
        RMF_CONE_RULE_CYLINDER_SECOND => Rule::CylinderSecond,
        RMF_CONE_RULE_GIVEN if parameter.is_finite() => Rule::Given(parameter),
        RMF_CONE_RULE_GIVEN => {
            return invalid_arg(format!("parameter = {parameter} is not finite"));
        }
        other => {
            return invalid_arg(format!(
                "rule = {other} is not one of the RMF_CONE_RULE_* values"
            ))
        }
    })
}

fn region_from(region: &RmfBox) -> FfiResult<Region> {
    Ok(Region::new(region.min.into(), region.max.into())?)
}

/// Creates the cone spline through G1 Hermite elements: one cone pair (or one plane piece)
/// between consecutive elements, every case of the paper (general, cone, cylinder,
/// constant slope, plane), chosen by `rule`, with no vertex inside `region`. Each pair is
/// solved in coordinates centred and scaled on its two elements: the spline is the same,
/// mapped, for elements scaled by 1e-200 … 1e200 or moved far away (up to the rounding of
/// the moved data, amplified by the inverse of the rulings' angle for close rulings), and
/// rulings 0.001 apart join like any others.
///
/// @param[in] elements count elements (finite; side normal to ruling).
/// @param[in] count Number of elements, ≥ 2.
/// @param[in] rule One of RMF_CONE_RULE_*.
/// @param[in] parameter μ1 or λ1 for RMF_CONE_RULE_GIVEN (finite); ignored otherwise.
/// @param[in] region The region of interest Ω, or NULL for none. Element points must lie in
///            it; solutions with a vertex in it are not used (the useful root, or vertices
///            just outside Ω for the default rule).
/// @param[out] out Receives the spline; free with rmf_cone_spline_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If elements or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If count < 2, a value is not finite, a direction is zero,
///         a side is not normal to its ruling, consecutive rulings are parallel with opposite
///         orientation or coincide, consecutive side vectors are inconsistent (normals to
///         opposite sides), the rule is unknown, or an element point is outside the region.
/// @return RMF_ERROR_NO_SOLUTION If no cone pair of the rule joins two elements
///         consistently, or the region contains every possible vertex.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_hermite(
    elements: *const RmfConeElement,
    count: usize,
    rule: u32,
    parameter: f64,
    region: *const RmfBox,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_hermite", || {
        let out = out_ptr(out, "out")?;
        if elements.is_null() {
            return Err(FfiError::Null("elements"));
        }
        let elements = slice(elements, count, "elements")?
            .iter()
            .enumerate()
            .map(|(i, e)| {
                Element::new(
                    e.point.into(),
                    e.ruling.into(),
                    e.side.into(),
                    &format!("elements[{i}]"),
                )
            })
            .collect::<rmfsurf::Result<Vec<_>>>()?;
        let rule = rule_from(rule, parameter)?;
        let region = if region.is_null() {
            None
        } else {
            Some(region_from(&*region)?)
        };
        let (spline, pairs) = ConeSpline::hermite(&elements, rule, region.as_ref())?;
        let cases = pairs
            .iter()
            .flat_map(|p| p.pieces.iter().map(move |_| case_code(p.case)))
            .collect();
        write(out, RmfConeSpline::of_spline(spline, cases).into_raw());
        Ok(())
    })
}

/// Writes a fitted spline and its deviation.
unsafe fn finish_fit(
    fit: rmfsurf::cone::Approximation,
    out: *mut *mut RmfConeSpline,
    max_error: Option<*mut f64>,
) {
    let cases = vec![RMF_CONE_CASE_NONE; fit.spline.pieces().len()];
    if let Some(p) = max_error {
        write(p, fit.max_error);
    }
    let handle = RmfConeSpline {
        part: None,
        spline: fit.spline,
        cases,
        fit: Some(Fit {
            max_error: fit.max_error,
            parameters: fit.parameters,
            inflections: fit.inflections,
            vertex_clearance: fit.vertex_clearance,
        }),
    };
    write(out, handle.into_raw());
}

/// Checks the common arguments of the approximations.
fn check_fit_arguments(tolerance: f64, max_pieces: usize) -> FfiResult {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return invalid_arg(format!(
            "tolerance = {tolerance} must be finite and positive"
        ));
    }
    if max_pieces < 2 {
        return invalid_arg(format!("max_pieces = {max_pieces} must be at least 2"));
    }
    Ok(())
}

/// Approximates the tangent surface x(t) + v e(t) of a space curve (e = x'/|x'|) over
/// v ∈ [v_min, v_max] by a cone spline: inflection generators (zero torsion) are kept as
/// junctions, further rulings are chosen adaptively until the largest distance from the
/// surface's region to the cone spline is ≤ tolerance.
///
/// \deprecated Use rmf_cone_spline_approximate_with_options (a callback as a curve from
/// rmf_callback_curve_create, the tolerance, rule and piece cap in an options struct that
/// can grow). This function stays, with the same results, for at least one release.
///
/// The curve is `curve` (its whole domain), or `callback` on [t_min, t_max]; exactly one of
/// them. It must be regular with non-zero curvature. The fit runs in coordinates centred
/// and scaled on the surface: the same pieces, mapped, for the curve scaled by 1e-200 …
/// 1e200 or moved by 1e6 of its size. A 1,000-turn helix (radius 1, pitch 0.4, v 0.5 to 2)
/// to 1e-2 takes 16,384 pieces (times: docs/benchmarks.md).
///
/// @param[in] curve A curve (e.g. from rmf_nurbs_curve_create), or NULL.
/// @param[in] callback Point and derivative of an analytic curve, or NULL; called on this
///            thread during the call only; must not unwind or longjmp.
/// @param[in] user Passed to callback.
/// @param[in] t_min, t_max The callback's parameter interval (ignored for curve).
/// @param[in] v_min, v_max The region along the rulings, distances from the curve point:
///            finite, v_min < v_max, 0 ∉ [v_min, v_max] (the curve is the singular edge).
/// @param[in] tolerance Largest allowed distance, > 0.
/// @param[in] rule One of RMF_CONE_RULE_* except RMF_CONE_RULE_GIVEN.
/// @param[in] max_pieces Largest number of pieces, ≥ 2.
/// @param[out] out Receives the spline; free with rmf_cone_spline_free. Its reference
///             point is x(t_min) + (v_min + v_max)/2 e(t_min).
/// @param[out] max_error Receives the largest sampled distance; may be NULL.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If out is NULL, or both curve and callback are.
/// @return RMF_ERROR_INVALID_INPUT For bad numbers, both curve and callback given, or an
///         unknown rule.
/// @return RMF_ERROR_NO_SOLUTION If the curve has zero curvature somewhere (no tangent plane).
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance needs more than max_pieces pieces.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
#[deprecated(since = "0.2.0", note = "use rmf_cone_spline_approximate_with_options")]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_cone_spline_approximate(
    curve: *const RmfCurve,
    callback: RmfCurveCallback,
    user: *mut c_void,
    t_min: f64,
    t_max: f64,
    v_min: f64,
    v_max: f64,
    tolerance: f64,
    rule: u32,
    max_pieces: usize,
    out: *mut *mut RmfConeSpline,
    max_error: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_approximate", || {
        let out = out_ptr(out, "out")?;
        let max_error = optional_out(max_error, "max_error")?;
        let input = curve_or_callback(curve, callback, user, t_min, t_max)?;
        check_fit_arguments(tolerance, max_pieces)?;
        let rule = fit_rule(rule)?;
        approximate_tangent_surface(
            input.as_ref(),
            v_min,
            v_max,
            tolerance,
            rule,
            max_pieces,
            out,
            max_error,
        )
    })
}

/// The tangent-surface approximation both C entry points run.
///
/// # Safety
/// `out` and `max_error` (if given) are valid for writes.
#[allow(clippy::too_many_arguments)]
unsafe fn approximate_tangent_surface(
    curve: &dyn ParametricCurve,
    v_min: f64,
    v_max: f64,
    tolerance: f64,
    rule: Rule,
    max_pieces: usize,
    out: *mut *mut RmfConeSpline,
    max_error: Option<*mut f64>,
) -> FfiResult {
    let surface = TangentSurface::new(curve, v_min, v_max)?;
    finish_fit(
        approximate_developable(&surface, tolerance, rule, max_pieces)?,
        out,
        max_error,
    );
    Ok(())
}

/// How rmf_cone_spline_approximate_with_options and
/// rmf_cone_spline_approximate_dual_with_options fit: the tolerance, the rule of the cone
/// pairs and the most pieces. Initialise with rmf_cone_approximation_options_init, then set
/// the tolerance; the struct only grows at the end.
/// \since 0.2
/// \ingroup rmf_cone_spline
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RmfConeApproximationOptions {
    /// sizeof(RmfConeApproximationOptions), written by rmf_cone_approximation_options_init.
    pub struct_size: usize,
    /// Largest allowed distance between the surface's region and the cone spline, in the
    /// input's units, > 0. Default 0, which is refused: set it.
    pub tolerance: f64,
    /// One of RMF_CONE_RULE_* except RMF_CONE_RULE_GIVEN (default
    /// RMF_CONE_RULE_MIN_VERTEX_DISTANCE).
    pub rule: u32,
    /// Most pieces, ≥ 2 (default 10000); more are RMF_ERROR_NOT_CONVERGED.
    pub max_pieces: usize,
}

impl Default for RmfConeApproximationOptions {
    fn default() -> Self {
        Self {
            struct_size: std::mem::size_of::<Self>(),
            tolerance: 0.0,
            rule: RMF_CONE_RULE_MIN_VERTEX_DISTANCE,
            max_pieces: rmfsurf::cone::DEFAULT_MAX_PIECES,
        }
    }
}

// SAFETY: repr(C) plain numbers, usize first.
unsafe impl OptionsStruct for RmfConeApproximationOptions {
    const FIRST_SIZE: usize = std::mem::size_of::<Self>();
}

/// Writes the default cone approximation options (struct_size set, tolerance 0: set it).
///
/// @param[out] out Receives the defaults.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if out is NULL.
/// \since 0.2
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_approximation_options_init(
    out: *mut RmfConeApproximationOptions,
) -> RmfStatus {
    guard("rmf_cone_approximation_options_init", || {
        let out = out_ptr(out, "out")?;
        write(out, RmfConeApproximationOptions::default());
        Ok(())
    })
}

/// The caller's fit options, checked: NULL is refused (the tolerance has no default), and
/// a refused field is named "options: ...".
///
/// # Safety
/// `options` is NULL or points to at least its `struct_size` readable bytes.
unsafe fn fit_options(
    options: *const RmfConeApproximationOptions,
) -> FfiResult<(f64, Rule, usize)> {
    if options.is_null() {
        return Err(FfiError::Null("options"));
    }
    let given = super::boundary::options(options, "options")?;
    let checked = check_fit_arguments(given.tolerance, given.max_pieces)
        .and_then(|()| fit_rule(given.rule))
        .map_err(|e| match e {
            FfiError::Core(e) => FfiError::Core(e.context("options")),
            other => other,
        })?;
    Ok((given.tolerance, checked, given.max_pieces))
}

/// Approximates the tangent surface x(t) + v e(t) of a curve (e = x'/|x'|) over
/// v ∈ [v_min, v_max] by a cone spline, as rmf_cone_spline_approximate does: inflection
/// generators (zero torsion) are kept as junctions, further rulings are chosen adaptively
/// until the largest distance from the surface's region to the cone spline is ≤ the
/// tolerance. The curve must be regular with non-zero curvature.
///
/// @param[in] curve A curve on its whole domain: NURBS data, a computed curve, or an
///            analytic curve from rmf_callback_curve_create.
/// @param[in] v_min, v_max The region along the rulings, distances from the curve point:
///            finite, v_min < v_max, 0 ∉ [v_min, v_max] (the curve is the singular edge).
/// @param[in] options Tolerance, rule and piece cap (initialise with
///            rmf_cone_approximation_options_init, then set the tolerance).
/// @param[out] out Receives the spline; free with rmf_cone_spline_free. Its reference
///             point is x(t_min) + (v_min + v_max)/2 e(t_min), t_min the domain's start.
///             Untouched on failure.
/// @param[out] max_error Receives the largest sampled distance; may be NULL. Untouched on
///             failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If curve, options or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If options->struct_size is no size of the struct, the
///         tolerance is not finite and positive, max_pieces < 2, the rule is unknown or
///         RMF_CONE_RULE_GIVEN (the message names the field: "options: tolerance = ..."),
///         or v_min, v_max are bad.
/// @return RMF_ERROR_NO_SOLUTION If the curve has zero curvature somewhere (no tangent plane).
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance needs more than max_pieces pieces.
/// \since 0.2
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_approximate_with_options(
    curve: *const RmfCurve,
    v_min: f64,
    v_max: f64,
    options: *const RmfConeApproximationOptions,
    out: *mut *mut RmfConeSpline,
    max_error: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_approximate_with_options", || {
        let curve = reference(curve, "curve")?;
        let (tolerance, rule, max_pieces) = fit_options(options)?;
        let out = out_ptr(out, "out")?;
        let max_error = optional_out(max_error, "max_error")?;
        let input = curve.sampled();
        approximate_tangent_surface(
            input.as_ref(),
            v_min,
            v_max,
            tolerance,
            rule,
            max_pieces,
            out,
            max_error,
        )
    })
}

fn fit_rule(rule: u32) -> FfiResult<Rule> {
    if rule == RMF_CONE_RULE_GIVEN {
        return invalid_arg(
            "rule = RMF_CONE_RULE_GIVEN needs one parameter per pair; not for approximation".into(),
        );
    }
    rule_from(rule, 0.0)
}

/// Approximates a developable ruled surface of degree (1, n) — rulings along u, e.g.
/// spanned between two rails — over its whole domain, as rmf_cone_spline_approximate does
/// for tangent surfaces. Developability is checked first: the surface's own Gaussian
/// curvature is measured on a grid.
///
/// @param[in] surface A surface with degree_u = 1 and pole_count_u = 2 (e.g. from
///            rmf_nurbs_surface_create); its parameter v runs along the rails.
/// @param[in] tolerance, rule, max_pieces As for rmf_cone_spline_approximate.
/// @param[out] out Receives the spline; its reference point is the middle of the first ruling.
/// @param[out] max_error Receives the largest sampled distance; may be NULL.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If surface or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the surface is not of degree 1 in u with one span, or
///         is not developable (the message gives its max |K|·size²), or for bad numbers.
/// @return RMF_ERROR_NO_SOLUTION, RMF_ERROR_NOT_CONVERGED As for rmf_cone_spline_approximate.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_approximate_ruled(
    surface: *const RmfSurface,
    tolerance: f64,
    rule: u32,
    max_pieces: usize,
    out: *mut *mut RmfConeSpline,
    max_error: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_approximate_ruled", || {
        let surface = reference(surface, "surface")?;
        let out = out_ptr(out, "out")?;
        let max_error = optional_out(max_error, "max_error")?;
        check_fit_arguments(tolerance, max_pieces)?;
        let rule = fit_rule(rule)?;
        let ruled = RuledSurface::new(surface.surface.as_ref().clone())?;
        finish_fit(
            approximate_developable(&ruled, tolerance, rule, max_pieces)?,
            out,
            max_error,
        );
        Ok(())
    })
}

/// Approximates a developable surface in the dual form (4) of the paper: a clamped
/// B-spline curve of planes U(t) = Σ Uᵢ Nᵢ(t), u0 + u1 x + u2 y + u3 z = 0, whose rulings
/// are U ∩ U'. The region of interest is a box; each ruling is used where it crosses it.
///
/// \deprecated Use rmf_cone_spline_approximate_dual_with_options (the tolerance, rule and
/// piece cap in an options struct that can grow). This function stays, with the same
/// results, for at least one release.
///
/// @param[in] degree Degree k ≥ 1 of the B-spline.
/// @param[in] planes plane_count control planes, 4 doubles each: u0, u1, u2, u3.
/// @param[in] plane_count Number of control planes, ≥ degree + 1.
/// @param[in] knots knot_count clamped knots, knot_count = plane_count + degree + 1.
/// @param[in] knot_count Number of knots, plane_count + degree + 1.
/// @param[in] region The region of interest; every ruling must cross it, and it should
///            exclude the line of regression.
/// @param[in] tolerance, rule, max_pieces As for rmf_cone_spline_approximate.
/// @param[out] out Receives the spline; free with rmf_cone_spline_free.
/// @param[out] max_error Receives the largest sampled distance; may be NULL.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If planes, knots, region or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT For bad counts, knots, non-finite planes or numbers.
/// @return RMF_ERROR_NO_SOLUTION If a ruling misses the box or U and U' are parallel.
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance needs more than max_pieces pieces.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
#[deprecated(
    since = "0.2.0",
    note = "use rmf_cone_spline_approximate_dual_with_options"
)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_cone_spline_approximate_dual(
    degree: u32,
    planes: *const f64,
    plane_count: usize,
    knots: *const f64,
    knot_count: usize,
    region: *const RmfBox,
    tolerance: f64,
    rule: u32,
    max_pieces: usize,
    out: *mut *mut RmfConeSpline,
    max_error: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_approximate_dual", || {
        let out = out_ptr(out, "out")?;
        let max_error = optional_out(max_error, "max_error")?;
        let (planes, knots, region) =
            dual_input(degree, planes, plane_count, knots, knot_count, region)?;
        check_fit_arguments(tolerance, max_pieces)?;
        let rule = fit_rule(rule)?;
        let dual = DualDevelopable::new(degree as usize, &planes, knots, region)?;
        finish_fit(
            approximate_developable(&dual, tolerance, rule, max_pieces)?,
            out,
            max_error,
        );
        Ok(())
    })
}

/// The planes (as DVec4 (u1, u2, u3, u0)), knots and region of a dual-form input, checked.
///
/// # Safety
/// The pointers are NULL or valid for the counts given.
unsafe fn dual_input<'a>(
    degree: u32,
    planes: *const f64,
    plane_count: usize,
    knots: *const f64,
    knot_count: usize,
    region: *const RmfBox,
) -> FfiResult<(Vec<DVec4>, &'a [f64], Region)> {
    if planes.is_null() {
        return Err(FfiError::Null("planes"));
    }
    if knots.is_null() {
        return Err(FfiError::Null("knots"));
    }
    let region = region_from(reference(region, "region")?)?;
    rmfsurf::validate::check_nurbs_counts(degree as usize, plane_count, knot_count, "")?;
    let Some(values) = plane_count.checked_mul(4) else {
        return invalid_arg(format!("plane_count = {plane_count} is too large"));
    };
    let planes: Vec<DVec4> = slice(planes, values, "planes")?
        .chunks_exact(4)
        .map(|u| DVec4::new(u[1], u[2], u[3], u[0]))
        .collect();
    let knots = slice(knots, knot_count, "knots")?;
    Ok((planes, knots, region))
}

/// Approximates a developable surface in the dual form (4) of the paper by a cone spline,
/// as rmf_cone_spline_approximate_dual does, with the tolerance, rule and piece cap in an
/// options struct.
///
/// @param[in] degree Degree k ≥ 1 of the B-spline of planes.
/// @param[in] planes plane_count control planes, 4 doubles each: u0, u1, u2, u3.
/// @param[in] plane_count Number of control planes, ≥ degree + 1.
/// @param[in] knots knot_count clamped knots.
/// @param[in] knot_count Number of knots, plane_count + degree + 1.
/// @param[in] region The region of interest; every ruling must cross it, and it should
///            exclude the line of regression.
/// @param[in] options Tolerance, rule and piece cap (initialise with
///            rmf_cone_approximation_options_init, then set the tolerance).
/// @param[out] out Receives the spline; free with rmf_cone_spline_free. Untouched on failure.
/// @param[out] max_error Receives the largest sampled distance; may be NULL.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If planes, knots, region, options or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If options->struct_size is no size of the struct, a field
///         of options is refused (the message names it), or for bad counts, knots,
///         non-finite planes or numbers.
/// @return RMF_ERROR_NO_SOLUTION If a ruling misses the box or U and U' are parallel.
/// @return RMF_ERROR_NOT_CONVERGED If the tolerance needs more than max_pieces pieces.
/// \since 0.2
/// \ingroup rmf_cone_spline
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_cone_spline_approximate_dual_with_options(
    degree: u32,
    planes: *const f64,
    plane_count: usize,
    knots: *const f64,
    knot_count: usize,
    region: *const RmfBox,
    options: *const RmfConeApproximationOptions,
    out: *mut *mut RmfConeSpline,
    max_error: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_approximate_dual_with_options", || {
        let (planes, knots, region) =
            dual_input(degree, planes, plane_count, knots, knot_count, region)?;
        let (tolerance, rule, max_pieces) = fit_options(options)?;
        let out = out_ptr(out, "out")?;
        let max_error = optional_out(max_error, "max_error")?;
        let dual = DualDevelopable::new(degree as usize, &planes, knots, region)?;
        finish_fit(
            approximate_developable(&dual, tolerance, rule, max_pieces)?,
            out,
            max_error,
        );
        Ok(())
    })
}

/// The osculating cone spline of a tangent surface (Section "Osculating cone splines"):
/// the osculating cones along the rulings at `parameters` (vertex on the curve, axis along
/// the Darboux vector τe + κb), consecutive ones joined by a filling cone found from the
/// quartic (14), keeping the consistent solutions. Translated cones (constant slope: a
/// screw flight) are joined by translated cones; osculating cylinders and planes by a
/// segment of each and a Hermite cone pair between them (G1, four pieces per interval).
/// An interval without a consistent filling cone is halved, up to 6 times.
///
/// \deprecated Use rmf_cone_spline_osculating_curve (a callback as a curve from
/// rmf_callback_curve_create). This function stays, with the same results, for at least one
/// release.
///
/// @param[in] curve, callback, user, t_min, t_max The curve, as for rmf_cone_spline_approximate.
/// @param[in] v_min, v_max The region along the rulings, as for rmf_cone_spline_approximate.
/// @param[in] parameters count increasing curve parameters inside the domain.
/// @param[in] count Number of osculating cones, ≥ 2.
/// @param[out] out Receives the spline; free with rmf_cone_spline_free.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If parameters or out is NULL, or both curve and callback are.
/// @return RMF_ERROR_INVALID_INPUT For bad numbers or parameters not increasing.
/// @return RMF_ERROR_NO_SOLUTION If the curve has zero curvature at a parameter (no
///         osculating cone).
/// @return RMF_ERROR_NOT_CONVERGED If two consecutive osculating cones cannot be joined
///         consistently even after 6 halvings of their interval.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
#[deprecated(since = "0.2.0", note = "use rmf_cone_spline_osculating_curve")]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_cone_spline_osculating(
    curve: *const RmfCurve,
    callback: RmfCurveCallback,
    user: *mut c_void,
    t_min: f64,
    t_max: f64,
    v_min: f64,
    v_max: f64,
    parameters: *const f64,
    count: usize,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_osculating", || {
        let out = out_ptr(out, "out")?;
        if parameters.is_null() {
            return Err(FfiError::Null("parameters"));
        }
        let parameters = slice(parameters, count, "parameters")?;
        let input = curve_or_callback(curve, callback, user, t_min, t_max)?;
        osculating(input.as_ref(), v_min, v_max, parameters, out)
    })
}

/// The osculating cone spline both C entry points build.
///
/// # Safety
/// `out` is valid for writes.
unsafe fn osculating(
    curve: &dyn ParametricCurve,
    v_min: f64,
    v_max: f64,
    parameters: &[f64],
    out: *mut *mut RmfConeSpline,
) -> FfiResult {
    let (lo, hi) = curve.domain();
    if let Some(i) = parameters.iter().position(|t| !(lo..=hi).contains(t)) {
        return invalid_arg(format!(
            "parameters[{i}] = {} is outside the domain [{lo}, {hi}]",
            parameters[i]
        ));
    }
    let surface = TangentSurface::new(curve, v_min, v_max)?;
    let spline = osculating_spline(&surface, parameters)?;
    let cases = vec![RMF_CONE_CASE_NONE; spline.pieces().len()];
    write(out, RmfConeSpline::of_spline(spline, cases).into_raw());
    Ok(())
}

/// The osculating cone spline of the tangent surface of a curve, as
/// rmf_cone_spline_osculating builds it, with the curve as one handle (an analytic curve
/// from rmf_callback_curve_create instead of a callback and its interval).
///
/// @param[in] curve A curve on its whole domain (NURBS data, a computed curve or a callback
///            curve).
/// @param[in] v_min, v_max The region along the rulings, as for
///            rmf_cone_spline_approximate_with_options.
/// @param[in] parameters count increasing curve parameters inside the domain.
/// @param[in] count Number of osculating cones, ≥ 2.
/// @param[out] out Receives the spline; free with rmf_cone_spline_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If curve, parameters or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT For bad numbers or parameters not increasing or outside
///         the domain.
/// @return RMF_ERROR_NO_SOLUTION If the curve has zero curvature at a parameter (no
///         osculating cone).
/// @return RMF_ERROR_NOT_CONVERGED If two consecutive osculating cones cannot be joined
///         consistently even after 6 halvings of their interval.
/// \since 0.2
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_osculating_curve(
    curve: *const RmfCurve,
    v_min: f64,
    v_max: f64,
    parameters: *const f64,
    count: usize,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_osculating_curve", || {
        let curve = reference(curve, "curve")?;
        let out = out_ptr(out, "out")?;
        if parameters.is_null() {
            return Err(FfiError::Null("parameters"));
        }
        let parameters = slice(parameters, count, "parameters")?;
        let input = curve.sampled();
        osculating(input.as_ref(), v_min, v_max, parameters, out)
    })
}

/// Frees a cone spline. NULL is a no-op.
///
/// @param[in] spline The spline to free, or NULL.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_free(spline: *mut RmfConeSpline) {
    free_handle(spline)
}

/// The number of pieces of a cone spline.
///
/// @param[in] spline The spline.
/// @param[out] count Receives the number of pieces.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if spline or count is NULL.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_piece_count(
    spline: *const RmfConeSpline,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_cone_spline_piece_count", || {
        let spline = reference(spline, "spline")?;
        let count = out_ptr(count, "count")?;
        write(count, spline.spline.pieces().len());
        Ok(())
    })
}

fn piece_data(piece: &ConePiece, case: u32, first_patch: usize) -> RmfConePiece {
    let (start, end) = (piece.start, piece.end());
    let vertex = piece.vertex();
    let developed_width = match piece.kind() {
        PieceKind::Cylinder => piece.radius() * piece.segment_angle(),
        PieceKind::Plane if vertex.is_none() => (end.point - start.point).length(),
        _ => 0.0,
    };
    RmfConePiece {
        kind: match piece.kind() {
            PieceKind::Cone => RMF_CONE_PIECE_CONE,
            PieceKind::Cylinder => RMF_CONE_PIECE_CYLINDER,
            PieceKind::Plane => RMF_CONE_PIECE_PLANE,
        },
        pair_case: case,
        has_vertex: u32::from(vertex.is_some()),
        vertex: vertex.unwrap_or_default().into(),
        axis_point: piece.axis_point().unwrap_or(start.point).into(),
        axis: piece.axis().into(),
        half_angle: piece.half_angle(),
        segment_angle: piece.segment_angle(),
        developed_angle: if piece.kind() == PieceKind::Cylinder {
            0.0
        } else {
            piece.segment_angle() * piece.half_angle().sin()
        },
        radius: piece.radius(),
        developed_width,
        start_point: start.point.into(),
        start_ruling: start.ruling.into(),
        start_side: start.side.into(),
        end_point: end.point.into(),
        end_ruling: end.ruling.into(),
        end_side: end.side.into(),
        first_patch,
        patch_count: piece.patch_count(),
    }
}

/// The data of piece `index`: kind, vertex, axis, half angle α, segment angle φ, the
/// bounding rulings, and where its patches are in the surface.
///
/// @param[in] spline The spline.
/// @param[in] index 0 ≤ index < piece count.
/// @param[out] piece Receives the data (a copy).
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if index is out of range.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_piece(
    spline: *const RmfConeSpline,
    index: usize,
    piece: *mut RmfConePiece,
) -> RmfStatus {
    guard("rmf_cone_spline_piece", || {
        let spline = reference(spline, "spline")?;
        let piece = out_ptr(piece, "piece")?;
        let pieces = spline.spline.pieces();
        if index >= pieces.len() {
            return invalid_arg(format!(
                "index = {index} but the spline has {} pieces",
                pieces.len()
            ));
        }
        let first_patch = pieces[..index].iter().map(ConePiece::patch_count).sum();
        write(
            piece,
            piece_data(&pieces[index], spline.cases[index], first_patch),
        );
        Ok(())
    })
}

/// The exact surface of a cone spline between two signed distances along the rulings,
/// measured from the reference points (the first element's point, carried along the
/// parallel circles): every piece one degree (1, 2) rational Bézier patch (or a few, for
/// segment angles above 120°), u ∈ [t_min, t_max] the distance along the rulings, v ∈
/// [k, k + 1] on piece k. The result is one NURBS surface (rmf_surface_nurbs) of degree
/// (1, 2), G1 across the shared rulings. Its bounds u = t_min, t_max are parallel-circle arc
/// splines (rmf_cone_spline_boundary), orthogonal to the rulings.
///
/// @param[in] spline The spline.
/// @param[in] t_min, t_max Finite, t_min < t_max; the strip must contain no vertex.
/// @param[out] out Receives the surface; free with rmf_surface_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If spline or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the bounds are not finite, not increasing, or the strip
///         contains a vertex (the message names the piece).
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_surface(
    spline: *const RmfConeSpline,
    t_min: f64,
    t_max: f64,
    out: *mut *mut RmfSurface,
) -> RmfStatus {
    guard("rmf_cone_spline_surface", || {
        let spline = reference(spline, "spline")?;
        let out = out_ptr(out, "out")?;
        let surface = spline.spline.surface(t_min, t_max)?;
        write(out, RmfSurface::new(surface, None).into_raw());
        Ok(())
    })
}

/// The bounds for rmf_cone_spline_surface from a region box: the widest strip whose ruling
/// segments all lie in the box (rulings sampled per piece, the extremes refined by Brent's
/// method), and where vertices fall inside that range, its widest part free of them.
///
/// @param[in] spline The spline.
/// @param[in] region The box.
/// @param[out] t_min, t_max Receive the bounds.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If an argument is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the box is not finite or min ≥ max somewhere.
/// @return RMF_ERROR_NO_SOLUTION If some ruling misses the box or no strip fits.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_bounds_in_box(
    spline: *const RmfConeSpline,
    region: *const RmfBox,
    t_min: *mut f64,
    t_max: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_bounds_in_box", || {
        let spline = reference(spline, "spline")?;
        let region = region_from(reference(region, "region")?)?;
        let (t_min, t_max) = (out_ptr(t_min, "t_min")?, out_ptr(t_max, "t_max")?);
        let (a, b) = spline.spline.bounds_in_box(&region)?;
        write(t_min, a);
        write(t_max, b);
        Ok(())
    })
}

/// The boundary curve at signed distance t along the rulings: a G1 spline of circular arcs
/// (the parallel circles; straight lines on plane strips), exact rational quadratics, with
/// the surface's v parameter.
///
/// @param[in] spline The spline.
/// @param[in] t Signed distance along the rulings from the reference points (finite).
/// @param[out] out Receives the curve; free with rmf_curve_free.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if t is not finite.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_boundary(
    spline: *const RmfConeSpline,
    t: f64,
    out: *mut *mut RmfCurve,
) -> RmfStatus {
    guard("rmf_cone_spline_boundary", || {
        let spline = reference(spline, "spline")?;
        let out = out_ptr(out, "out")?;
        let curve = spline.spline.boundary(t)?;
        write(out, RmfCurve::new(curve, None).into_raw());
        Ok(())
    })
}

/// The body of the entry points that make a new spline from one (bending, development,
/// offset): check the pointers, build, write.
///
/// # Safety
/// `spline` must be NULL or a valid handle, `out` NULL or writable.
unsafe fn derive(
    spline: *const RmfConeSpline,
    out: *mut *mut RmfConeSpline,
    make: impl FnOnce(&ConeSpline) -> rmfsurf::Result<ConeSpline>,
) -> FfiResult {
    let spline = reference(spline, "spline")?;
    let out = out_ptr(out, "out")?;
    let made = make(&spline.spline)?;
    write(out, spline.derived(made).into_raw());
    Ok(())
}

/// The stage s of the bending sequence (Fig. 17): every piece bent isometrically at once —
/// a cone's half angle α moves linearly to π/2 with φ sin α kept, a cylinder's curvature
/// scales by 1 − s —, each laid on the end ruling and tangent plane of the one before.
/// Ruling lengths, vertex distances, boundary lengths and angles are kept. The first
/// ruling and its tangent plane stay fixed: s = 0 is the spline itself, s = 1 its flat
/// development in the first tangent plane.
///
/// @param[in] spline The spline.
/// @param[in] s In [0, 1].
/// @param[out] out Receives the bent spline; free with rmf_cone_spline_free.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if s is not in [0, 1].
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_bend(
    spline: *const RmfConeSpline,
    s: f64,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_bend", || {
        derive(spline, out, |c| c.bent(s))
    })
}

/// The exact development of a cone spline into the plane z = 0: each cone piece a sector of
/// angle φ_n = φ sin α about its developed vertex, cylinders and strips rectangles of width
/// r φ, laid edge to edge along the shared rulings; the first reference point at the
/// origin, the first ruling along +x and its side vector along +y. Its surface
/// (rmf_cone_spline_surface with the same bounds) is planar with lines and circular arcs as
/// boundaries, isometric to the spline's.
///
/// @param[in] spline The spline.
/// @param[out] out Receives the development; free with rmf_cone_spline_free.
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if an argument is NULL.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_develop(
    spline: *const RmfConeSpline,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_develop", || {
        derive(spline, out, ConeSpline::developed)
    })
}

/// The offset of a cone spline at signed distance d along the normals ruling × side: again
/// a cone spline (same axes and half angles, shifted vertices), exact.
///
/// @param[in] spline The spline.
/// @param[in] d Signed distance along ruling × side (finite).
/// @param[out] out Receives the offset; free with rmf_cone_spline_free.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if d is not finite.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_offset(
    spline: *const RmfConeSpline,
    d: f64,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    guard("rmf_cone_spline_offset", || {
        derive(spline, out, |c| c.offset(d))
    })
}

/// The deviation an approximation reached (rmf_cone_spline_approximate*; kept by
/// bending, development and offsets).
///
/// @param[in] spline A spline made by rmf_cone_spline_approximate*.
/// @param[out] max_error Receives the largest sampled distance to the input surface.
/// @return RMF_OK, RMF_ERROR_NULL_POINTER, or RMF_ERROR_INVALID_INPUT if the spline was
///         not made by an approximation.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_fit_error(
    spline: *const RmfConeSpline,
    max_error: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_fit_error", || {
        let spline = reference(spline, "spline")?;
        let max_error = out_ptr(max_error, "max_error")?;
        let Some(fit) = &spline.fit else {
            return invalid_arg("the spline was not made by an approximation".into());
        };
        write(max_error, fit.max_error);
        Ok(())
    })
}

/// How far the vertices of a fitted spline keep out of the region of interest Ω, the part
/// of the input surface the approximation was asked for: on each ruling the band of
/// distances v_min … v_max from the curve (rmf_cone_spline_approximate*), the ruling
/// between the rails (rmf_cone_spline_approximate_ruled), or the ruling's segment in the
/// box (rmf_cone_spline_approximate_dual*). The fit keeps every vertex outside Ω.
///
/// The value is relative and has no unit: for each piece with a vertex, measured on the
/// selected ruling (RMF_CONE_FIT_ELEMENTS) on which the vertex lies — the first piece of
/// each cone pair on the pair's first ruling, the last on its last —, the distance of the
/// vertex beyond the nearer end of that ruling's band, divided by the band's length
/// (for a tangent surface v_max − v_min): max(lo − s, s − hi) / (hi − lo) for a vertex at
/// signed distance s along the ruling where the band is [lo, hi]. The smallest over the
/// spline is reported. 0 is a vertex at a band's end (admissible), positive outside the
/// band; it is never below −1e-9 (the rounding margin at the band's ends). +∞ (INFINITY)
/// when no piece has a vertex (only cylinders and plane strips). Kept, like the fit error,
/// by bending, development and offsets (distances along the rulings do not change under
/// bending and development; for an offset it remains the fit's figure).
///
/// @param[in] spline A spline made by rmf_cone_spline_approximate*.
/// @param[out] clearance Receives the smallest relative clearance. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If spline or clearance is NULL.
/// @return RMF_ERROR_INVALID_INPUT If the spline was not made by an approximation
///         (rmf_cone_spline_hermite, the osculating cone splines and sheet-metal parts have
///         no fitted region to measure against).
/// \since 0.2
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_fit_clearance(
    spline: *const RmfConeSpline,
    clearance: *mut f64,
) -> RmfStatus {
    guard("rmf_cone_spline_fit_clearance", || {
        let spline = reference(spline, "spline")?;
        let clearance = out_ptr(clearance, "clearance")?;
        let Some(fit) = &spline.fit else {
            return invalid_arg(
                "the spline was not made by an approximation (rmf_cone_spline_approximate*): \
                 it has no region of interest to measure its vertices against"
                    .into(),
            );
        };
        write(clearance, fit.vertex_clearance);
        Ok(())
    })
}

/// Copies the parameters an approximation selected (RMF_CONE_FIT_ELEMENTS: the rulings
/// joined by cone pairs, increasing) or found (RMF_CONE_FIT_INFLECTIONS: the inflection
/// generators, which are among the elements).
///
/// Size query: with capacity 0 (values may be NULL) only count is written.
///
/// @param[in] spline A spline made by rmf_cone_spline_approximate*.
/// @param[in] which RMF_CONE_FIT_ELEMENTS or RMF_CONE_FIT_INFLECTIONS.
/// @param[out] values Buffer for capacity values.
/// @param[in] capacity Capacity of values; 0 for a size query.
/// @param[out] count Receives the number of values.
/// @return RMF_OK on success or for a size query.
/// @return RMF_ERROR_NULL_POINTER If spline or count is NULL, or values is NULL with a
///         non-zero capacity.
/// @return RMF_ERROR_INVALID_INPUT If which is unknown or the spline was not made by an
///         approximation.
/// @return RMF_ERROR_BUFFER_TOO_SMALL If capacity is non-zero but too small; count is written.
/// \since 0.1
/// \ingroup rmf_cone_spline
#[no_mangle]
pub unsafe extern "C" fn rmf_cone_spline_fit_parameters(
    spline: *const RmfConeSpline,
    which: u32,
    values: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> RmfStatus {
    guard("rmf_cone_spline_fit_parameters", || {
        let spline = reference(spline, "spline")?;
        let count = out_ptr(count, "count")?;
        let values = buffer(values, capacity, "values")?;
        let Some(fit) = &spline.fit else {
            return invalid_arg("the spline was not made by an approximation".into());
        };
        let data = match which {
            RMF_CONE_FIT_ELEMENTS => &fit.parameters,
            RMF_CONE_FIT_INFLECTIONS => &fit.inflections,
            other => return invalid_arg(format!("which = {other} is not an RMF_CONE_FIT_* value")),
        };
        hand_over(data, values, count, "values")
    })
}
