//! Runs the construction a job asks for with the library's Rust API: the spine and its
//! frames by the chosen method, the sweep; or the cone spline, its surface strip and its
//! development. Failures of the geometry are reported at the input field they come from.

use crate::job::{
    ConeJob, Developable as Input, SheetInput, SheetJob, Spine, SweepJob, WireEdge, WireFrame,
    WireJob,
};
use crate::json::InputError;
use rmfsurf::glam::DVec3;
use rmfsurf::{
    cone::approximate as approximate_developable, cone::ConeSpline, cone::Developable, cone::Rule,
    cone::RuledSurface, cone::TangentSurface, framed_spine, framed_spine_through, ph::check_g1,
    sheet::SheetPart, sweep, wire::sweep as sweep_wire, wire::sweep_between as sweep_wire_between,
    wire::sweep_through as sweep_wire_through, wire::Edge, wire::Section, wire::Shape,
    wire::SweepFrame, wire::WireSweep, Error, FlatPattern, FramedCurve, PiecewiseCurve,
    PiecewiseSurface,
};

/// A swept surface with its spine and frames.
pub struct SweepOutcome {
    pub framed: FramedCurve,
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
    let (framed, spine_distance) = match &job.spine {
        Spine::Hermite { points, tangents } => (
            framed_spine_through(points, tangents, job.method, job.initial_normal)
                .map_err(at(blame_hermite(job, points, tangents)))?,
            None,
        ),
        Spine::Nurbs(nurbs) => {
            let curve = nurbs.to_piecewise().map_err(at("sweep.spine.nurbs"))?;
            check_g1(&curve).map_err(at("sweep.spine.nurbs"))?;
            let spine = framed_spine(&curve, job.method, job.tolerance, job.initial_normal)
                .map_err(at(blame_curve(job, &curve)))?;
            (spine.framed, Some(spine.distance))
        }
    };
    let profile = job.profile.to_piecewise().map_err(at("sweep.profile"))?;
    let surface = sweep(&framed, &profile).map_err(at("sweep"))?;
    Ok(SweepOutcome {
        framed,
        surface,
        spine_distance,
    })
}

/// The wire sweep: the shape, or the failure at the field its message names (an edge or
/// a joint of the wire, the profile, a hole, the corner).
pub fn run_wire(job: &WireJob) -> Result<Shape, InputError> {
    let edges = library_edges(&job.edges, "sweep.spine.wire")?;
    let frame = match &job.frame {
        WireFrame::Law(law) => law.clone(),
        WireFrame::Guide(guide) => SweepFrame::Guide(library_edges(guide, "sweep.frame.guide")?),
    };
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
        frame,
        scale: job.scale,
        scale_knots: job.scale_knots.clone(),
        method: job.method,
        pipe_frame: job.pipe_frame,
    };
    let end = match &job.end_profile {
        Some((end_profile, end_holes)) => Some((
            curve(end_profile, "sweep.end_profile".into())?,
            end_holes
                .iter()
                .enumerate()
                .map(|(k, h)| curve(h, format!("sweep.end_profile.holes[{k}]")))
                .collect::<Result<Vec<_>, _>>()?,
        )),
        None => None,
    };
    let sections = job
        .sections
        .iter()
        .enumerate()
        .map(|(k, (at, profile, holes))| {
            let path = format!("sweep.sections[{k}]");
            Ok((
                *at,
                curve(profile, format!("{path}.profile"))?,
                holes
                    .iter()
                    .enumerate()
                    .map(|(i, h)| curve(h, format!("{path}.holes[{i}]")))
                    .collect::<Result<Vec<_>, _>>()?,
            ))
        })
        .collect::<Result<Vec<_>, InputError>>()?;
    match &end {
        Some((end_profile, end_holes)) if !sections.is_empty() => {
            let all: Vec<Section> = std::iter::once((0.0, &profile, &holes))
                .chain(sections.iter().map(|(at, p, h)| (*at, p, h)))
                .chain(std::iter::once((1.0, end_profile, end_holes)))
                .map(|(at, profile, holes)| Section { at, profile, holes })
                .collect();
            sweep_wire_through(&edges, &all, &options)
                .map_err(|e| Error::new(e.kind(), section_names(&e.message(), sections.len())))
        }
        Some((end_profile, end_holes)) => {
            sweep_wire_between(&edges, &profile, &holes, end_profile, end_holes, &options)
        }
        None => sweep_wire(&edges, &profile, &holes, &options),
    }
    .map_err(|e| {
        let message = e.message();
        let mut path = wire_blame(&message);
        // A law made non-constant by its knots alone (`scale: …` with a constant "scale").
        if path == "sweep.scale" && job.scale[0] == job.scale[1] && !job.scale_knots.is_empty() {
            path = "sweep.scale_knots".into();
        }
        InputError { path, message }
    })
}

/// The edges of a wire (or of a guide) as the library takes them; a NURBS edge that is
/// not a valid curve is reported at `path[k].nurbs`.
fn library_edges(edges: &[WireEdge], path: &str) -> Result<Vec<Edge>, InputError> {
    edges
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
                    path: format!("{path}[{k}].nurbs"),
                    message: e.message(),
                })?),
            })
        })
        .collect()
}

/// A message of a sweep through sections with the library's `sections[k]` (k of the whole
/// list: the start profile 0, the end profile `count + 1`) named as the input names them:
/// `profile`, `sections[k - 1]` (of the `count` intermediate ones), `end_profile`.
fn section_names(message: &str, count: usize) -> String {
    let Some((k, rest)) = message
        .strip_prefix("sections[")
        .and_then(|m| m.split_once("]: "))
        .and_then(|(k, rest)| Some((k.parse::<usize>().ok()?, rest)))
    else {
        return message.to_string();
    };
    let name = match k {
        0 => "profile".to_string(),
        k if k == count + 1 => "end_profile".to_string(),
        k => format!("sections[{}]", k - 1),
    };
    format!("{name}: {rest}")
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
    if message.starts_with("scale_knots[") {
        return match number_after("scale_knots[") {
            Some(k) => format!("sweep.scale_knots[{k}]"),
            None => "sweep.scale_knots".into(),
        };
    }
    if message.starts_with("sections[") {
        let k = number_after("sections[").unwrap_or(0);
        let field = match message.split_once("]: ").map(|(_, rest)| rest) {
            Some(rest) if rest.starts_with("at =") => ".at".to_string(),
            Some(rest) if rest.starts_with("profile") => ".profile".to_string(),
            Some(rest) if rest.starts_with("holes[") => {
                format!(".holes[{}]", number_after("]: holes[").unwrap_or(0))
            }
            _ => String::new(),
        };
        return format!("sweep.sections[{k}]{field}");
    }
    if message.starts_with("sections:") {
        return "sweep.sections".into();
    }
    if message.starts_with("end_profile") {
        return match number_after("holes[") {
            Some(k) => format!("sweep.end_profile.holes[{k}]"),
            None => "sweep.end_profile".into(),
        };
    }
    if let Some(k) = number_after("holes[") {
        return format!("sweep.profile.holes[{k}]");
    }
    if message.starts_with("profile") {
        return "sweep.profile".into();
    }
    for field in ["scale", "frame", "initial_normal", "method"] {
        if message.starts_with(&format!("{field}:")) || message.starts_with(&format!("{field} =")) {
            return format!("sweep.{field}");
        }
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

/// Which field a failed spine through Hermite data is about: the initial normal when it
/// is along the start tangent, the data otherwise.
fn blame_hermite(job: &SweepJob, points: &[DVec3], tangents: &[DVec3]) -> &'static str {
    match (points.first(), tangents.first()) {
        (Some(_), Some(&t)) if along(job.initial_normal, t) => "sweep.initial_normal",
        _ => "sweep.spine",
    }
}

/// Which field a failed spine within the tolerance of a curve is about: the initial normal
/// when it is along the start tangent, the tolerance otherwise.
fn blame_curve(job: &SweepJob, curve: &PiecewiseCurve) -> &'static str {
    let tangent = curve.eval_jet(curve.domain().0).d1;
    if along(job.initial_normal, tangent) {
        "sweep.initial_normal"
    } else {
        "sweep.tolerance"
    }
}

/// Whether `normal` is along the tangent (no component in the normal plane).
fn along(normal: DVec3, tangent: DVec3) -> bool {
    let tangent = tangent.normalize_or_zero();
    normal.cross(tangent).length() <= 1e-9 * normal.length()
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
