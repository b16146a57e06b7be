//! The accuracy figures of a construction, measured on its result: for sweeps the spine's
//! distance from its input, the frames' rotation-minimizing defect and orthonormality (and,
//! for PH cubic RMFs, the angle to the exact RMF), the surface's parameter-line
//! orthogonality and, for line profiles, its developability; for cone splines the fit
//! deviation, developability, and the isometry of the development (boundary and ruling
//! lengths, ruling–boundary angles, flatness).

use crate::construct::{ConeOutcome, Outcome, SheetOutcome, SweepOutcome};
use crate::job::{Construction, Job};
use rmfsurf::metrics::{angle_between, orthonormality_error, parameter_line_cosine, rmf_defect};
use rmfsurf::{
    cone::max_scaled_curvature, cone::PieceKind, grid_parameters, ph::angle_errors, ph::PhSpline,
    sheet::Layer, sheet::Side, FrameField, FrameKind, NurbsSurface, PatternEdge, PiecewiseSurface,
    SpineMethod,
};
use serde_json::{json, Map, Value};
use std::sync::Arc;

/// Samples per frame piece (defect, orthonormality) and per patch (surface measures).
const SAMPLES: usize = 32;
const SURFACE_SAMPLES: usize = 8;

/// One figure: a JSON key, a label for people, a value.
pub struct Figure {
    pub key: &'static str,
    pub label: &'static str,
    pub value: Value,
}

fn figure(key: &'static str, label: &'static str, value: impl Into<Value>) -> Figure {
    Figure {
        key,
        label,
        value: value.into(),
    }
}

pub struct Summary {
    pub figures: Vec<Figure>,
}

impl Summary {
    pub fn of(job: &Job, outcome: &Outcome) -> rmfsurf::Result<Self> {
        let figures = match (&job.construction, outcome) {
            (Construction::Sweep(j), Outcome::Sweep(o)) => {
                sweep_figures(j.method, j.profile_is_line, o)?
            }
            (_, Outcome::ConeSpline(o)) => cone_figures(o)?,
            (Construction::Wire(j), Outcome::Wire(shape)) => {
                wire_figures(j.edges.len(), j.method, shape)
            }
            (_, Outcome::Sheet(o)) => sheet_figures(o)?,
            _ => unreachable!("the outcome matches the job"),
        };
        Ok(Self { figures })
    }

    pub fn to_json(&self) -> Value {
        let map: Map<String, Value> = self
            .figures
            .iter()
            .map(|f| (f.key.to_string(), f.value.clone()))
            .collect();
        Value::Object(map)
    }

    pub fn to_text(&self) -> String {
        let width = self
            .figures
            .iter()
            .map(|f| f.label.chars().count())
            .max()
            .unwrap_or(0);
        self.figures
            .iter()
            .map(|f| {
                let value = match &f.value {
                    Value::Number(n) if n.is_f64() => {
                        format!("{:.3e}", n.as_f64().unwrap_or(f64::NAN))
                    }
                    Value::String(s) => s.clone(),
                    other => other.to_string(),
                };
                format!("  {:width$}  {value}\n", f.label)
            })
            .collect()
    }
}

fn method_name(method: SpineMethod) -> &'static str {
    match method {
        SpineMethod::PhRmf => "PH cubic spline, rational RMF (Mäurer & Jüttler)",
        SpineMethod::Frenet => "PH cubic spline, rational Frenet frame (not rotation-minimizing)",
        SpineMethod::Mobius => "exact rational RMF by Möbius maps (Bartoň, Jüttler & Wang)",
        SpineMethod::Rrmf => "RRMF quintics, exact rational RMF (Farouki, Giannelli & Sestini)",
    }
}

/// The NURBS's degrees and poles, or why the patches do not form one NURBS (Frenet frames
/// jump at the joints of a G1 spine).
fn surface_shape(surface: &PiecewiseSurface) -> String {
    match NurbsSurface::from_piecewise(surface) {
        Ok(n) => format!(
            "NURBS of degree ({}, {}), {} × {} poles",
            n.degree_u(),
            n.degree_v(),
            n.pole_count_u(),
            n.pole_count_v()
        ),
        Err(e) => format!(
            "{} rational patches, not one continuous NURBS ({})",
            surface.patches().len(),
            e.message()
        ),
    }
}

fn sweep_figures(
    method: SpineMethod,
    line: bool,
    o: &SweepOutcome,
) -> rmfsurf::Result<Vec<Figure>> {
    let mut figures = vec![
        figure("method", "method", method_name(method)),
        figure(
            "spine_segments",
            "spine segments",
            o.framed.curve().segments().len(),
        ),
    ];
    if let Some(d) = o.spine_distance {
        figures.push(figure(
            "spine_distance",
            "spine: max distance from the input",
            d,
        ));
    }
    let field = FrameField::new(
        Arc::new(o.framed.curve().clone()),
        FrameKind::Rational(o.framed.frames().clone()),
    )?;
    let (mut defect, mut orthonormality) = (0.0f64, 0.0f64);
    for t in grid_parameters(o.framed.frames().breaks(), SAMPLES) {
        defect = defect.max(rmf_defect(&field, t)?.abs());
        orthonormality = orthonormality.max(orthonormality_error(&field.frame(t)?));
    }
    figures.push(figure(
        "frame_pieces",
        "frame pieces (rational)",
        o.framed.frames().segments().len(),
    ));
    figures.push(figure(
        "rmf_defect",
        "frames: max |f2'·f3|/|x'| (rad per unit length)",
        defect,
    ));
    figures.push(figure(
        "orthonormality",
        "frames: max orthonormality error",
        orthonormality,
    ));
    if method == SpineMethod::PhRmf {
        let spline = PhSpline::new(o.framed.curve().clone())?;
        let angle = angle_errors(&spline, o.framed.frames())?.max;
        figures.push(figure(
            "rmf_angle_error",
            "frames: max angle to the exact RMF (rad)",
            angle,
        ));
    }
    figures.push(figure("surface", "surface", surface_shape(&o.surface)));
    figures.push(figure(
        "orthogonality",
        "surface: max |cos| between parameter lines",
        max_parameter_line_cosine(&o.surface),
    ));
    if line {
        figures.push(figure(
            "developability",
            "surface: max |K|·size² (line profile: developable)",
            max_scaled_curvature(&o.surface),
        ));
    }
    Ok(figures)
}

fn wire_figures(edges: usize, method: SpineMethod, shape: &rmfsurf::wire::Shape) -> Vec<Figure> {
    let r = shape.report();
    let caps = shape
        .faces()
        .iter()
        .filter(|f| f.kind == rmfsurf::wire::FaceKind::Plane)
        .count();
    let mut figures = vec![
        figure(
            "method",
            "method",
            match method {
                SpineMethod::Mobius => {
                    "wire sweep (mobius): lines and arcs exact, curves by Möbius images of planar PH cubics with exact rational RMFs (Bartoň, Jüttler & Wang)"
                }
                SpineMethod::Rrmf => {
                    "wire sweep (rrmf): lines and arcs exact, curves by RRMF quintics with exact rational RMFs (Farouki, Giannelli & Sestini)"
                }
                _ => "wire sweep: lines and arcs exact, curves by PH cubic splines with rational RMFs (Mäurer & Jüttler)",
            },
        ),
        figure("edges", "wire edges", edges),
        figure("spine_pieces", "spine pieces (lines, arcs, elbows, PH splines)", shape.spine().len()),
        figure(
            "faces",
            "faces",
            format!("{} ({} lateral, {caps} planar caps)", r.face_count, r.face_count - caps),
        ),
        figure("solid", "closed solid", shape.is_solid()),
        figure("spine_distance", "spine: max distance of PH splines from curve edges", r.spine_distance),
        figure("rmf_angle_error", "frames: max angle to the exact RMF (rad)", r.rmf_angle_error),
        figure("orthogonality", "surface: max |cos| between parameter lines", r.max_parameter_cosine),
        figure("singularity_margin", "least singularity margin (Cor. 7)", r.singularity_margin),
        figure("corner_turn", "frames: max turn about the tangent across corners (rad)", r.corner_turn),
        figure("frame_error", "frames: max angle to the frame asked for (rad)", r.frame_error),
        figure("seam_gap", "closed wire: seam gap", r.seam_gap),
        figure("joint_gap", "largest gap between sections at joints", r.joint_gap),
    ];
    if let Ok(v) = shape.volume() {
        figures.push(figure(
            "volume",
            "volume (divergence theorem, Gauss–Legendre)",
            v,
        ));
    }
    figures
}

fn max_parameter_line_cosine(surface: &PiecewiseSurface) -> f64 {
    let vs = grid_parameters(surface.v_breaks(), SURFACE_SAMPLES);
    grid_parameters(surface.u_breaks(), SURFACE_SAMPLES)
        .iter()
        .flat_map(|&u| vs.iter().map(move |&v| (u, v)))
        .map(|(u, v)| parameter_line_cosine(&surface.eval_jet(u, v)))
        .filter(|c| c.is_finite())
        .fold(0.0, f64::max)
}

fn cone_figures(o: &ConeOutcome) -> rmfsurf::Result<Vec<Figure>> {
    let pieces = o.spline.pieces();
    let count = |kind: PieceKind| pieces.iter().filter(|p| p.kind() == kind).count();
    let mut figures = vec![figure(
        "pieces",
        "cone spline pieces",
        format!(
            "{} ({} cones, {} cylinders, {} planes)",
            pieces.len(),
            count(PieceKind::Cone),
            count(PieceKind::Cylinder),
            count(PieceKind::Plane)
        ),
    )];
    if let Some(e) = o.fit_error {
        figures.push(figure(
            "fit_deviation",
            "fit: max distance from the input surface",
            e,
        ));
    }
    figures.push(figure("surface", "surface", surface_shape(&o.surface)));
    figures.push(figure(
        "developability",
        "surface: max |K|·size²",
        max_scaled_curvature(&o.surface),
    ));
    figures.push(figure(
        "boundary_length_error",
        "development: boundary lengths, max relative error",
        boundary_length_error(o)?,
    ));
    figures.push(figure(
        "ruling_length_error",
        "development: ruling lengths, max relative error",
        ruling_length_error(o),
    ));
    figures.push(figure(
        "ruling_angle_error",
        "development: ruling–boundary angles, max error (rad)",
        ruling_angle_error(o),
    ));
    let flatness = o
        .developed
        .patches()
        .iter()
        .flat_map(|p| p.homogeneous().iter().map(|h| (h.z / h.w).abs()))
        .fold(0.0, f64::max);
    figures.push(figure("flatness", "development: max |z|", flatness));
    let (lo, hi) = o.pattern.bounds();
    figures.push(figure(
        "pattern_size",
        "flat pattern: width × height",
        format!(
            "{} × {}",
            length_text(hi.x - lo.x),
            length_text(hi.y - lo.y)
        ),
    ));
    Ok(figures)
}

/// The surface's boundary curves against the pattern's arcs and lines (the outline runs
/// along t_min over the n pieces, then back along t_max).
fn boundary_length_error(o: &ConeOutcome) -> rmfsurf::Result<f64> {
    let n = o.spline.pieces().len();
    let edges = &o.pattern.outline;
    let sides = [(o.t_min, &edges[..n]), (o.t_max, &edges[n + 1..2 * n + 1])];
    let mut worst = 0.0f64;
    for (t, flat) in sides {
        let spatial = o.spline.boundary(t)?.arc_length();
        let developed: f64 = flat.iter().map(PatternEdge::length).sum();
        worst = worst.max((spatial - developed).abs() / spatial);
    }
    Ok(worst)
}

/// Every ruling of the pattern (end rulings and bend lines) against t_max − t_min.
fn ruling_length_error(o: &ConeOutcome) -> f64 {
    let n = o.spline.pieces().len();
    let expected = o.t_max - o.t_min;
    [o.pattern.outline[n], o.pattern.outline[2 * n + 1]]
        .iter()
        .chain(&o.pattern.bend_lines)
        .map(|e| (e.length() - expected).abs() / expected)
        .fold(0.0, f64::max)
}

/// The angle between ruling and boundary at every piece junction and both bounds, on the
/// surface and on its development (v = k is the start of piece k in both).
fn ruling_angle_error(o: &ConeOutcome) -> f64 {
    let angle = |s: &PiecewiseSurface, u: f64, v: f64| {
        let j = s.eval_jet(u, v);
        angle_between(j.du, j.dv)
    };
    (0..=o.spline.pieces().len())
        .flat_map(|k| [(o.t_min, k as f64), (o.t_max, k as f64)])
        .map(|(u, v)| (angle(&o.surface, u, v) - angle(&o.developed, u, v)).abs())
        .fold(0.0, f64::max)
}

fn sheet_figures(o: &SheetOutcome) -> rmfsurf::Result<Vec<Figure>> {
    let part = &o.part;
    let spline = part.cone_spline()?;
    let pieces = spline.pieces();
    let count = |kind: PieceKind| pieces.iter().filter(|p| p.kind() == kind).count();
    let creases = pieces
        .iter()
        .filter(|p| {
            p.kind() == PieceKind::Cylinder && p.radius() <= 1e-12 * p.start.point.length().max(1.0)
        })
        .count();
    let report = part.report();
    let sheet = part.sheet();
    let mut figures = vec![
        figure(
            "part",
            "part",
            if part.is_closed() {
                "transition piece (closed, cut open at its seam in the flat pattern)"
            } else {
                "part between its two boundary curves"
            },
        ),
        figure(
            "pieces",
            "cone spline pieces",
            format!(
                "{} ({} cones, {} cylinders of which {creases} creases, {} planes)",
                pieces.len(),
                count(PieceKind::Cone),
                count(PieceKind::Cylinder),
                count(PieceKind::Plane)
            ),
        ),
        figure(
            "fit_deviation",
            "surface: max distance from the designed developable",
            report.deviation,
        ),
        figure(
            "edge_distance_first",
            "edges: first boundary, max distance from the input",
            report.edge_distance[0],
        ),
        figure(
            "edge_distance_second",
            "edges: second boundary, max distance from the input",
            report.edge_distance[1],
        ),
        figure(
            "sheet",
            "sheet",
            format!(
                "thickness {}, K-factor {}, designed surface = {:?} face",
                number_text(sheet.thickness),
                sheet.k_factor,
                sheet.reference
            ),
        ),
        figure(
            "neutral_layer",
            "neutral layer: distance from the designed surface",
            part.layer_distance(Layer::Neutral),
        ),
        figure(
            "bend_radius",
            "smallest bend radius of the designed surface",
            part.bend_radius(),
        ),
    ];
    let arcs = o
        .flat
        .outline
        .iter()
        .filter(|e| matches!(e, PatternEdge::Arc { .. }))
        .count();
    figures.push(figure(
        "flat_edges",
        "flat pattern: outline edges",
        format!(
            "{} ({arcs} arcs, {} lines), {} bend lines",
            o.flat.outline.len(),
            o.flat.outline.len() - arcs,
            o.flat.bend_lines.len()
        ),
    ));
    let (lo, hi) = o.flat.bounds();
    figures.push(figure(
        "pattern_size",
        "flat pattern: width × height",
        format!(
            "{} × {}",
            length_text(hi.x - lo.x),
            length_text(hi.y - lo.y)
        ),
    ));
    // Areas of parts beyond about 1e154 across (or below 1e-154) are outside the range of
    // f64: those figures are left out, the lengths above still say what was made.
    if let (Ok(flat), Ok(formed)) = (o.flat.area(), part.area(Layer::Neutral)) {
        figures.push(figure("flat_area", "flat pattern: area", flat));
        figures.push(figure("formed_area", "formed neutral layer: area", formed));
        figures.push(figure(
            "area_error",
            "flat against formed area, relative",
            (flat - formed).abs() / formed,
        ));
    }
    let lengths = part.flat_boundary_lengths()?;
    let mut worst = 0.0f64;
    for (k, side) in [Side::First, Side::Second].iter().enumerate() {
        let formed = part.boundary_length(Layer::Neutral, *side)?;
        worst = worst.max((lengths[k] - formed).abs() / formed);
    }
    figures.push(figure(
        "edge_length_error",
        "flat against formed edge lengths, max relative",
        worst,
    ));
    Ok(figures)
}

/// A length with six decimals, or in exponent notation where that would show nothing or
/// hundreds of digits.
fn length_text(x: f64) -> String {
    if (1e-3..1e9).contains(&x.abs()) || x == 0.0 {
        format!("{x:.6}")
    } else {
        format!("{x:.6e}")
    }
}

/// A number as given, or in exponent notation when it is very large or small.
fn number_text(x: f64) -> String {
    if (1e-6..1e9).contains(&x.abs()) || x == 0.0 {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The summary as JSON text, for `-o summary.json`.
pub fn json_text(summary: &Summary) -> String {
    let mut text = serde_json::to_string_pretty(
        &json!({ "rmfsurf": env!("CARGO_PKG_VERSION"), "figures": summary.to_json() }),
    )
    .expect("figures serialize");
    text.push('\n');
    text
}
