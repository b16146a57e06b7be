//! Runs the construction a job asks for with the library's Rust API: the spine and its
//! frames by the chosen method, the sweep; or the cone spline, its surface strip and its
//! development. Failures of the geometry are reported at the input field they come from.

use crate::job::{
    ConeJob, Developable as Input, Method, SheetInput, SheetJob, Spine, SweepJob, WireEdge, WireJob,
};
use crate::json::InputError;
use rmfsurf::glam::DVec3;
use rmfsurf::metrics::nearest_parameter;
use rmfsurf::{
    approximate_developable, check_g1, grid_parameters, hermite_sequence, mobius_approximate,
    mobius_hermite_points, ph_frenet_frames, ph_rational_rmf, ph_spline_approximate,
    ph_spline_hermite, rrmf_spline, sweep, sweep_wire, uniform_parameters, ConeSpline, Developable,
    Edge, FlatPattern, ParametricCurve, PiecewiseCurve, PiecewiseSurface, RationalFrames,
    RmfOptions, Rule, RuledSurface, Shape, ShapeMeasure, SheetPart, TangentSurface, WireSweep,
};

/// Most segments the Möbius and RRMF methods use to reach the tolerance on a NURBS spine
/// (doubled from the NURBS's own segment count).
const MAX_SEGMENTS: usize = 4096;
/// η samples per RRMF segment (then refined by Brent's method).
const ETA_SAMPLES: usize = 64;
/// Points per segment at which the distance of a spine to its input is measured.
const DISTANCE_SAMPLES: usize = 16;

/// A swept surface with its spine and frames.
pub struct SweepOutcome {
    pub spine: PiecewiseCurve,
    pub frames: RationalFrames,
    pub surface: PiecewiseSurface,
    /// For a NURBS spine: the largest measured distance of the spine from it.
    pub spine_distance: Option<f64>,
}

/// A cone spline strip and its development.
pub struct ConeOutcome {
    pub spline: ConeSpline,
    pub surface: PiecewiseSurface,
    pub developed: PiecewiseSurface,
    pub pattern: FlatPattern,
    /// For an approximation: the largest sampled distance from the input surface.
    pub fit_error: Option<f64>,
    pub t_min: f64,
    pub t_max: f64,
}

/// A sheet-metal part and its flat pattern.
pub struct SheetOutcome {
    pub part: SheetPart,
    pub flat: FlatPattern,
}

pub enum Outcome {
    Sweep(SweepOutcome),
    Wire(Shape),
    ConeSpline(ConeOutcome),
    Sheet(SheetOutcome),
}

/// The error of a construction step, at `path`.
fn at(path: &str) -> impl Fn(rmfsurf::Error) -> InputError + '_ {
    move |e| InputError {
        path: path.to_string(),
        message: e.message(),
    }
}

pub fn run_sweep(job: &SweepJob) -> Result<SweepOutcome, InputError> {
    let (spine, frames, spine_distance) = match job.method {
        Method::PhRmf | Method::Frenet => {
            let (spine, distance) = ph_spine(&job.spine, job.tolerance)?;
            let frames = if job.method == Method::PhRmf {
                ph_rational_rmf(&spine, &RmfOptions::rmf(job.initial_normal))
                    .map(|r| r.frames)
                    .map_err(at(blame_normal(job.initial_normal, &spine)))?
            } else {
                ph_frenet_frames(&spine).map_err(at("sweep.method"))?
            };
            (spine, frames, distance)
        }
        Method::Mobius | Method::Rrmf => exact_rmf_spine(job)?,
    };
    let profile = job.profile.to_piecewise().map_err(at("sweep.profile"))?;
    let surface = sweep(&spine, &frames, &profile).map_err(at("sweep"))?;
    Ok(SweepOutcome {
        spine,
        frames,
        surface,
        spine_distance,
    })
}

/// The wire sweep: the shape, or the failure at the field its message names (an edge or
/// a joint of the wire, the profile, a hole, the corner).
pub fn run_wire(job: &WireJob) -> Result<Shape, InputError> {
    let edges = job
        .edges
        .iter()
        .enumerate()
        .map(|(k, e)| {
            Ok(match e {
                WireEdge::Line { from, to } => Edge::Line {
                    from: *from,
                    to: *to,
                },
                WireEdge::Arc {
                    start,
                    through,
                    end,
                } => Edge::Arc {
                    start: *start,
                    through: *through,
                    end: *end,
                },
                WireEdge::Nurbs(n) => Edge::Curve(n.to_piecewise().map_err(|e| InputError {
                    path: format!("sweep.spine.wire[{k}].nurbs"),
                    message: e.message(),
                })?),
            })
        })
        .collect::<Result<Vec<_>, InputError>>()?;
    let curve = |n: &rmfsurf::NurbsCurve, path: String| {
        n.to_piecewise().map_err(|e| InputError {
            path,
            message: e.message(),
        })
    };
    let profile = curve(&job.profile, "sweep.profile".into())?;
    let holes = job
        .holes
        .iter()
        .enumerate()
        .map(|(k, h)| curve(h, format!("sweep.profile.holes[{k}]")))
        .collect::<Result<Vec<_>, _>>()?;
    let options = WireSweep {
        tolerance: job.tolerance,
        join_tolerance: job.join_tolerance,
        corner: job.corner,
        initial_normal: job.initial_normal,
        twist: job.twist,
        closure_symmetry: job.closure_symmetry,
        solid: job.solid,
    };
    sweep_wire(&edges, &profile, &holes, &options).map_err(|e| InputError {
        path: wire_blame(&e.message()),
        message: e.message(),
    })
}

/// The input field a wire sweep's message is about.
fn wire_blame(message: &str) -> String {
    let number_after = |prefix: &str| {
        message.find(prefix).and_then(|k| {
            message[k + prefix.len()..]
                .split(|c: char| !c.is_ascii_digit())
                .next()
                .and_then(|n| n.parse::<usize>().ok())
        })
    };
    if let Some(k) = number_after("holes[") {
        return format!("sweep.profile.holes[{k}]");
    }
    if message.starts_with("profile") {
        return "sweep.profile".into();
    }
    if message.contains("corner radius") || message.contains("miter corner") {
        return "sweep.corner".into();
    }
    if let Some(k) = number_after(" and ").filter(|_| message.contains("edges ")) {
        return format!("sweep.spine.wire[{k}]");
    }
    if let Some(k) = number_after("edge ") {
        return format!("sweep.spine.wire[{k}]");
    }
    if message.contains("closure_symmetry") {
        return "sweep.closure_symmetry".into();
    }
    "sweep".into()
}

/// Frames fail on the initial normal when it is tangent to the spine at the start.
fn blame_normal(normal: DVec3, spine: &PiecewiseCurve) -> &'static str {
    let tangent = spine.eval_jet(spine.domain().0).d1.normalize_or_zero();
    if normal.cross(tangent).length() <= 1e-9 * normal.length() {
        "sweep.initial_normal"
    } else {
        "sweep.spine"
    }
}

/// The PH cubic spline through the Hermite data, or within `tolerance` of the NURBS.
fn ph_spine(spine: &Spine, tolerance: f64) -> Result<(PiecewiseCurve, Option<f64>), InputError> {
    match spine {
        Spine::Hermite { points, tangents } => Ok((
            ph_spline_hermite(points, tangents).map_err(at("sweep.spine"))?,
            None,
        )),
        Spine::Nurbs(nurbs) => {
            let curve = nurbs.to_piecewise().map_err(at("sweep.spine.nurbs"))?;
            check_g1(&curve).map_err(at("sweep.spine.nurbs"))?;
            let fit = ph_spline_approximate(&curve, curve.breaks(), tolerance)
                .map_err(at("sweep.tolerance"))?;
            Ok((fit.spline, Some(fit.max_distance)))
        }
    }
}

/// A curve with an exact rational RMF (Möbius or RRMF) through the Hermite data, or through
/// samples of the NURBS, doubling the segments until the tolerance is met.
fn exact_rmf_spine(
    job: &SweepJob,
) -> Result<(PiecewiseCurve, RationalFrames, Option<f64>), InputError> {
    let n = job.initial_normal;
    let through = |points: &[DVec3], tangents: &[DVec3]| match job.method {
        Method::Mobius => mobius_hermite_points(points, tangents, n).map(|r| (r.curve, r.frames)),
        _ => hermite_sequence(points, tangents)
            .and_then(|s| rrmf_spline(&s, ShapeMeasure::ScaledEnergyRmf, ETA_SAMPLES, n))
            .map(|r| (r.curve, r.frames)),
    };
    let nurbs = match &job.spine {
        Spine::Hermite { points, tangents } => {
            let (curve, frames) = through(points, tangents).map_err(at("sweep.spine"))?;
            return Ok((curve, frames, None));
        }
        Spine::Nurbs(nurbs) => nurbs.to_piecewise().map_err(at("sweep.spine.nurbs"))?,
    };
    check_g1(&nurbs).map_err(at("sweep.spine.nurbs"))?;
    let mut segments = nurbs.segments().len().max(2);
    loop {
        let params = uniform_parameters(nurbs.domain(), segments + 1);
        let (curve, frames) = if job.method == Method::Mobius {
            mobius_approximate(&nurbs, segments, n).map(|r| (r.curve, r.frames))
        } else {
            samples(&nurbs, &params).and_then(|(p, t)| through(&p, &t))
        }
        .map_err(at("sweep.spine"))?;
        let distance = distance(&curve, &nurbs, &params);
        if distance <= job.tolerance {
            return Ok((curve, frames, Some(distance)));
        }
        if 2 * segments > MAX_SEGMENTS {
            return Err(InputError {
                path: "sweep.tolerance".into(),
                message: format!(
                    "not reached with {segments} segments (distance {distance:.3e}); give a larger tolerance"
                ),
            });
        }
        segments *= 2;
    }
}

fn samples(curve: &PiecewiseCurve, params: &[f64]) -> rmfsurf::Result<(Vec<DVec3>, Vec<DVec3>)> {
    let pairs = params
        .iter()
        .map(|&t| curve.point_unit_tangent(t))
        .collect::<rmfsurf::Result<Vec<_>>>()?;
    Ok(pairs.into_iter().unzip())
}

/// Largest distance from points of `approx` to `reference`; segment k of `approx` is
/// compared with the part of `reference` between `params[k]` and `params[k + 1]`.
fn distance(approx: &PiecewiseCurve, reference: &PiecewiseCurve, params: &[f64]) -> f64 {
    let ts = grid_parameters(approx.breaks(), DISTANCE_SAMPLES);
    ts.iter()
        .map(|&t| {
            let (k, _) = approx.locate(t);
            let p = approx.eval(t);
            let v = nearest_parameter(reference, p, params[k], params[k + 1]);
            reference.eval(v).distance(p)
        })
        .fold(0.0, f64::max)
}

/// The cone spline within the job's tolerance of a developable, and the deviation reached.
fn fit(surface: &dyn Developable, job: &ConeJob) -> Result<(ConeSpline, Option<f64>), InputError> {
    let fit = approximate_developable(
        surface,
        job.tolerance,
        Rule::MinimalVertexDistance,
        job.max_pieces,
    )
    .map_err(at("cone_spline.tolerance"))?;
    Ok((fit.spline, Some(fit.max_error)))
}

pub fn run_cone_spline(job: &ConeJob) -> Result<ConeOutcome, InputError> {
    let field = "cone_spline.developable";
    let (spline, fit_error) = match &job.developable {
        Input::Elements(elements) => {
            let (spline, _) = ConeSpline::hermite(elements, Rule::MinimalVertexDistance, None)
                .map_err(at(field))?;
            (spline, None)
        }
        Input::TangentSurface {
            curve,
            v_min,
            v_max,
        } => {
            let curve = curve.to_piecewise().map_err(at(field))?;
            fit(
                &TangentSurface::new(&curve, *v_min, *v_max).map_err(at(field))?,
                job,
            )?
        }
        Input::Ruled(nurbs) => {
            let surface = nurbs
                .to_piecewise()
                .and_then(RuledSurface::new)
                .map_err(at(field))?;
            fit(&surface, job)?
        }
    };
    let (t_min, t_max) = (job.t_min, job.t_max);
    let strip = at("cone_spline.strip");
    Ok(ConeOutcome {
        surface: spline.surface(t_min, t_max).map_err(&strip)?,
        developed: spline
            .developed()
            .and_then(|flat| flat.surface(t_min, t_max))
            .map_err(&strip)?,
        pattern: spline.flat_pattern(t_min, t_max).map_err(&strip)?,
        spline,
        fit_error,
        t_min,
        t_max,
    })
}

/// The sheet-metal part the job asks for, with its flat pattern.
pub fn run_sheet(job: &SheetJob) -> Result<SheetOutcome, InputError> {
    let part = match &job.input {
        SheetInput::Transition { bottom, top } => {
            let field = "sheet.transition";
            let (b, t) = (
                bottom.to_piecewise().map_err(at(field))?,
                top.to_piecewise().map_err(at(field))?,
            );
            SheetPart::transition(&b, &t, &job.options).map_err(at(field))?
        }
        SheetInput::Ruled(nurbs) => {
            let field = "sheet.ruled";
            let surface = nurbs.to_piecewise().map_err(at(field))?;
            SheetPart::between_rails(&surface, &job.options).map_err(at(field))?
        }
        SheetInput::TangentSurface {
            curve,
            v_min,
            v_max,
        } => {
            let field = "sheet.tangent_surface";
            let curve = curve.to_piecewise().map_err(at(field))?;
            SheetPart::tangent_surface(&curve, *v_min, *v_max, &job.options).map_err(at(field))?
        }
    };
    let flat = part.flat_pattern().map_err(at("sheet.flat_tolerance"))?;
    Ok(SheetOutcome { part, flat })
}
