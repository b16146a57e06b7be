//! What the input JSON asks for, read into typed values. Every value is checked here, and
//! every error names its field (see `--help` for the schema).

use crate::json::{Field, InputResult};
use rmfsurf::glam::DVec3;
use rmfsurf::{Element, NurbsCurve, NurbsSurface, Reference, Sheet, SheetOptions};
use std::f64::consts::FRAC_1_SQRT_2;

/// How the frames along the spine are made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// PH cubic spline, rational approximation of its RMF (Mäurer & Jüttler).
    PhRmf,
    /// PH cubic spline, its rational Frenet frame (for comparison: not rotation-minimizing).
    Frenet,
    /// Degree-6 curves with exact rational RMFs by Möbius maps (Bartoň, Jüttler & Wang).
    Mobius,
    /// RRMF quintics with exact rational RMFs (Farouki, Giannelli & Sestini).
    Rrmf,
}

pub const METHODS: [(&str, Method); 4] = [
    ("ph-rmf", Method::PhRmf),
    ("frenet", Method::Frenet),
    ("mobius", Method::Mobius),
    ("rrmf", Method::Rrmf),
];

/// The spine as given.
#[derive(Clone, Debug)]
pub enum Spine {
    /// A curve to approximate within the tolerance.
    Nurbs(NurbsCurve),
    /// G1 Hermite data to interpolate.
    Hermite {
        points: Vec<DVec3>,
        tangents: Vec<DVec3>,
    },
}

#[derive(Clone, Debug)]
pub struct SweepJob {
    pub spine: Spine,
    pub method: Method,
    pub tolerance: f64,
    pub initial_normal: DVec3,
    /// In the normal plane: x along f₂, y along f₃.
    pub profile: NurbsCurve,
    /// A single straight segment: the sweep is developable.
    pub profile_is_line: bool,
}

/// The developable surface a cone spline approximates (or the elements it interpolates).
#[derive(Clone, Debug)]
pub enum Developable {
    TangentSurface {
        curve: NurbsCurve,
        v_min: f64,
        v_max: f64,
    },
    Ruled(NurbsSurface),
    Elements(Vec<Element>),
}

#[derive(Clone, Debug)]
pub struct ConeJob {
    pub developable: Developable,
    pub tolerance: f64,
    pub max_pieces: usize,
    /// The strip: signed distances along the rulings from the reference points.
    pub t_min: f64,
    pub t_max: f64,
}

/// One edge of a wire spine.
#[derive(Clone, Debug)]
pub enum WireEdge {
    Line {
        from: DVec3,
        to: DVec3,
    },
    Arc {
        start: DVec3,
        through: DVec3,
        end: DVec3,
    },
    Nurbs(NurbsCurve),
}

/// A sweep along a wire of lines, arcs and NURBS edges (`"spine": {"wire": [...]}`).
#[derive(Clone, Debug)]
pub struct WireJob {
    pub edges: Vec<WireEdge>,
    pub corner: rmfsurf::Corner,
    pub tolerance: f64,
    pub join_tolerance: f64,
    pub initial_normal: Option<DVec3>,
    pub twist: f64,
    pub closure_symmetry: u32,
    /// In the normal plane: x along f₂, y along f₃.
    pub profile: NurbsCurve,
    pub holes: Vec<NurbsCurve>,
    pub solid: bool,
}

/// What a sheet-metal part is made from.
#[derive(Clone, Debug)]
pub enum SheetInput {
    /// The transition piece between two closed convex planar curves.
    Transition { bottom: NurbsCurve, top: NurbsCurve },
    /// The part between the two rails of a developable ruled NURBS of degree (1, n).
    Ruled(NurbsSurface),
    /// The part of a tangent surface over its whole curve and [v_min, v_max].
    TangentSurface {
        curve: NurbsCurve,
        v_min: f64,
        v_max: f64,
    },
}

#[derive(Clone, Debug)]
pub struct SheetJob {
    pub input: SheetInput,
    pub options: SheetOptions,
}

#[derive(Clone, Debug)]
pub enum Construction {
    Sweep(SweepJob),
    Wire(WireJob),
    ConeSpline(ConeJob),
    Sheet(SheetJob),
}

/// How the surface is tessellated for meshes and solids.
#[derive(Clone, Copy, Debug)]
pub struct MeshOptions {
    pub u_steps: usize,
    pub v_steps: usize,
    /// For solids of open surfaces (sheets): the sheet thickness.
    pub thickness: Option<f64>,
}

#[derive(Clone, Debug)]
pub struct Job {
    pub construction: Construction,
    pub mesh: MeshOptions,
}

/// Largest tessellation steps per patch accepted from the input.
const MAX_STEPS: usize = 1000;

impl Job {
    pub fn read(root: &Field) -> InputResult<Self> {
        root.only(&["sweep", "cone_spline", "sheet", "mesh"])?;
        let (kind, body) = root.variant_of(&["sweep", "cone_spline", "sheet"], &["mesh"])?;
        let construction = match kind {
            "sweep" if is_wire(&body)? => Construction::Wire(read_wire(&body)?),
            "sweep" => Construction::Sweep(read_sweep(&body)?),
            "sheet" => Construction::Sheet(read_sheet(&body)?),
            _ => Construction::ConeSpline(read_cone(&body)?),
        };
        Ok(Self {
            construction,
            mesh: read_mesh(root)?,
        })
    }
}

fn read_mesh(root: &Field) -> InputResult<MeshOptions> {
    let mut options = MeshOptions {
        u_steps: 8,
        v_steps: 8,
        thickness: None,
    };
    if let Some(mesh) = root.optional("mesh")? {
        mesh.only(&["u_steps", "v_steps", "thickness"])?;
        if let Some(f) = mesh.optional("u_steps")? {
            options.u_steps = f.count(1, MAX_STEPS)?;
        }
        if let Some(f) = mesh.optional("v_steps")? {
            options.v_steps = f.count(1, MAX_STEPS)?;
        }
        options.thickness = mesh
            .optional("thickness")?
            .map(|f| f.positive())
            .transpose()?;
    }
    Ok(options)
}

fn read_sweep(sweep: &Field) -> InputResult<SweepJob> {
    sweep.only(&["spine", "method", "tolerance", "initial_normal", "profile"])?;
    let method = match sweep.optional("method")? {
        None => Method::PhRmf,
        Some(f) => {
            let name = f.string()?;
            match METHODS.iter().find(|(n, _)| *n == name) {
                Some(&(_, m)) => m,
                None => {
                    let names: Vec<&str> = METHODS.iter().map(|(n, _)| *n).collect();
                    return f.error(format!(
                        "unknown method \"{name}\"; expected one of {}",
                        names.join(", ")
                    ));
                }
            }
        }
    };
    let (profile, profile_is_line) = read_profile(&sweep.required("profile")?)?;
    Ok(SweepJob {
        spine: read_spine(&sweep.required("spine")?)?,
        method,
        tolerance: read_tolerance(sweep)?,
        initial_normal: match sweep.optional("initial_normal")? {
            Some(f) => f.vec3()?,
            None => DVec3::Z,
        },
        profile,
        profile_is_line,
    })
}

/// Whether a sweep's spine is a wire (`{"wire": [...]}`).
fn is_wire(sweep: &Field) -> InputResult<bool> {
    match sweep.optional("spine")? {
        Some(spine) => Ok(spine.optional("wire").ok().flatten().is_some()),
        None => Ok(false),
    }
}

fn read_wire(sweep: &Field) -> InputResult<WireJob> {
    sweep.only(&[
        "spine",
        "corner",
        "tolerance",
        "join_tolerance",
        "initial_normal",
        "twist",
        "closure_symmetry",
        "profile",
        "solid",
    ])?;
    let spine = sweep.required("spine")?;
    spine.only(&["wire"])?;
    let edges = spine
        .required("wire")?
        .array()?
        .iter()
        .map(read_wire_edge)
        .collect::<InputResult<Vec<_>>>()?;
    if edges.is_empty() {
        return spine.required("wire")?.error("needs at least one edge");
    }
    let profile_field = sweep.required("profile")?;
    let (kind, body) =
        profile_field.variant_of(&["circle", "line", "polygon", "nurbs"], &["holes"])?;
    let (profile, _) = profile_curve(kind, &body)?;
    let holes = match profile_field.optional("holes")? {
        Some(list) => list
            .array()?
            .iter()
            .map(|hole| {
                let (kind, body) = hole.variant(&["circle", "polygon", "nurbs"])?;
                profile_curve(kind, &body).map(|(c, _)| c)
            })
            .collect::<InputResult<Vec<_>>>()?,
        None => Vec::new(),
    };
    let defaults = rmfsurf::WireSweep::default();
    Ok(WireJob {
        edges,
        corner: match sweep.optional("corner")? {
            Some(f) => read_corner(&f)?,
            None => defaults.corner,
        },
        tolerance: read_tolerance(sweep)?,
        join_tolerance: sweep
            .optional("join_tolerance")?
            .map_or(Ok(defaults.join_tolerance), |f| f.positive())?,
        initial_normal: sweep
            .optional("initial_normal")?
            .map(|f| f.vec3())
            .transpose()?,
        twist: sweep.optional("twist")?.map_or(Ok(0.0), |f| f.number())?,
        closure_symmetry: sweep
            .optional("closure_symmetry")?
            .map_or(Ok(0), |f| f.count(0, 1 << 16).map(|k| k as u32))?,
        profile,
        holes,
        solid: match sweep.optional("solid")? {
            Some(f) => f.boolean()?,
            None => defaults.solid,
        },
    })
}

/// `{"line": {"from", "to"}}`, `{"arc": {"start", "through", "end"}}` or `{"nurbs": {...}}`.
fn read_wire_edge(edge: &Field) -> InputResult<WireEdge> {
    let (kind, body) = edge.variant(&["line", "arc", "nurbs"])?;
    let point = |key: &str| body.required(key)?.vec3();
    Ok(match kind {
        "line" => {
            body.only(&["from", "to"])?;
            WireEdge::Line {
                from: point("from")?,
                to: point("to")?,
            }
        }
        "arc" => {
            body.only(&["start", "through", "end"])?;
            WireEdge::Arc {
                start: point("start")?,
                through: point("through")?,
                end: point("end")?,
            }
        }
        _ => WireEdge::Nurbs(read_nurbs_curve(&body, false)?),
    })
}

/// `{"round": {"radius": r}}` (or `{"round": {}}`, `"round"`: the default radius) or `"miter"`.
fn read_corner(corner: &Field) -> InputResult<rmfsurf::Corner> {
    use rmfsurf::Corner;
    if let Ok(name) = corner.string() {
        return match name {
            "round" => Ok(Corner::Round(None)),
            "miter" => Ok(Corner::Miter),
            other => corner.error(format!(
                "unknown corner \"{other}\"; expected round or miter"
            )),
        };
    }
    let (_, body) = corner.variant(&["round"])?;
    body.only(&["radius"])?;
    Ok(Corner::Round(
        body.optional("radius")?.map(|f| f.positive()).transpose()?,
    ))
}

fn read_tolerance(parent: &Field) -> InputResult<f64> {
    parent
        .optional("tolerance")?
        .map_or(Ok(1e-4), |f| f.positive())
}

fn read_spine(spine: &Field) -> InputResult<Spine> {
    let (kind, body) = spine.variant_of(&["nurbs", "points"], &["tangents"])?;
    if kind == "nurbs" {
        return Ok(Spine::Nurbs(read_nurbs_curve(&body, false)?));
    }
    let points = vectors(&body)?;
    let tangents_field = spine.required("tangents")?;
    let tangents = vectors(&tangents_field)?;
    if tangents.len() != points.len() {
        return tangents_field.error(format!(
            "{} tangents for {} points",
            tangents.len(),
            points.len()
        ));
    }
    Ok(Spine::Hermite { points, tangents })
}

fn vectors(field: &Field) -> InputResult<Vec<DVec3>> {
    field.array()?.iter().map(Field::vec3).collect()
}

/// `{"degree", "poles", "weights" (optional), "knots"}`; `planar`: poles may be [x, y].
fn read_nurbs_curve(nurbs: &Field, planar: bool) -> InputResult<NurbsCurve> {
    nurbs.only(&["degree", "poles", "weights", "knots"])?;
    let degree = nurbs.required("degree")?.count(1, rmfsurf::MAX_DEGREE)?;
    let poles = nurbs
        .required("poles")?
        .array()?
        .iter()
        .map(|f| if planar { f.point_2d() } else { f.vec3() })
        .collect::<InputResult<Vec<_>>>()?;
    let weights = nurbs
        .optional("weights")?
        .map(|f| f.numbers())
        .transpose()?;
    let knots = nurbs.required("knots")?.numbers()?;
    NurbsCurve::new(degree, poles, weights, knots).or_else(|e| nurbs.error(e.message()))
}

/// `{"degree_u", "degree_v", "poles": rows (one per u index) of [x, y, z], "weights" (rows,
/// optional), "knots_u", "knots_v"}`.
fn read_nurbs_surface(nurbs: &Field) -> InputResult<NurbsSurface> {
    nurbs.only(&[
        "degree_u", "degree_v", "poles", "weights", "knots_u", "knots_v",
    ])?;
    let degree = |key: &str| nurbs.required(key)?.count(1, rmfsurf::MAX_DEGREE);
    let rows_field = nurbs.required("poles")?;
    let rows: Vec<Vec<DVec3>> = rows_field
        .array()?
        .iter()
        .map(vectors)
        .collect::<InputResult<_>>()?;
    let columns = rows.first().map_or(0, Vec::len);
    if rows.iter().any(|r| r.len() != columns) {
        return rows_field.error("every row of poles must have the same length");
    }
    let weights = match nurbs.optional("weights")? {
        Some(f) => Some(
            f.array()?
                .iter()
                .map(Field::numbers)
                .collect::<InputResult<Vec<_>>>()?
                .concat(),
        ),
        None => None,
    };
    NurbsSurface::new(
        degree("degree_u")?,
        degree("degree_v")?,
        rows.len(),
        columns,
        rows.concat(),
        weights,
        nurbs.required("knots_u")?.numbers()?,
        nurbs.required("knots_v")?.numbers()?,
    )
    .or_else(|e| nurbs.error(e.message()))
}

/// The profile and whether it is one straight segment.
fn read_profile(profile: &Field) -> InputResult<(NurbsCurve, bool)> {
    let (kind, body) = profile.variant(&["circle", "line", "polygon", "nurbs"])?;
    profile_curve(kind, &body)
}

/// The profile curve of a `{"circle" | "line" | "polygon" | "nurbs": body}` and whether it
/// is one straight segment.
fn profile_curve(kind: &str, body: &Field) -> InputResult<(NurbsCurve, bool)> {
    let curve = match kind {
        "circle" => {
            body.only(&["radius", "center"])?;
            let radius = body.required("radius")?.positive()?;
            let center = body
                .optional("center")?
                .map_or(Ok(DVec3::ZERO), |f| f.point_2d())?;
            circle(center, radius)
        }
        "line" => {
            body.only(&["from", "to"])?;
            let ends = [
                body.required("from")?.point_2d()?,
                body.required("to")?.point_2d()?,
            ];
            polyline(&ends)
        }
        "polygon" => {
            let mut corners = body
                .array()?
                .iter()
                .map(Field::point_2d)
                .collect::<InputResult<Vec<_>>>()?;
            if corners.len() < 3 {
                return body.error(format!("needs at least 3 corners, got {}", corners.len()));
            }
            corners.push(corners[0]);
            polyline(&corners)
        }
        _ => return Ok((read_nurbs_curve(body, true)?, false)),
    };
    let curve = curve.or_else(|e| body.error(e.message()))?;
    Ok((curve, kind == "line"))
}

/// The full circle as a degree-2 NURBS of four quarters (weights 1, 1/√2, 1).
fn circle(center: DVec3, radius: f64) -> rmfsurf::Result<NurbsCurve> {
    let corners = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    let poles = corners
        .iter()
        .map(|&(x, y)| center + radius * DVec3::new(x, y, 0.0))
        .collect();
    let weights = (0..9)
        .map(|k| if k % 2 == 1 { FRAC_1_SQRT_2 } else { 1.0 })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];
    NurbsCurve::new(2, poles, Some(weights), knots)
}

/// Straight segments through `points`, one knot interval each.
fn polyline(points: &[DVec3]) -> rmfsurf::Result<NurbsCurve> {
    let n = points.len();
    let mut knots = vec![0.0];
    knots.extend((0..n).map(|k| k as f64));
    knots.push((n - 1) as f64);
    NurbsCurve::new(1, points.to_vec(), None, knots)
}

fn read_cone(cone: &Field) -> InputResult<ConeJob> {
    cone.only(&["developable", "tolerance", "max_pieces", "strip"])?;
    let developable = cone.required("developable")?;
    let (kind, body) = developable.variant(&["tangent_surface", "ruled", "elements"])?;
    let developable = match kind {
        "tangent_surface" => {
            body.only(&["curve", "v_min", "v_max"])?;
            let curve = body.required("curve")?;
            let (_, nurbs) = curve.variant(&["nurbs"])?;
            Developable::TangentSurface {
                curve: read_nurbs_curve(&nurbs, false)?,
                v_min: body.required("v_min")?.number()?,
                v_max: body.required("v_max")?.number()?,
            }
        }
        "ruled" => {
            let (_, nurbs) = body.variant(&["nurbs"])?;
            Developable::Ruled(read_nurbs_surface(&nurbs)?)
        }
        _ => Developable::Elements(
            body.array()?
                .iter()
                .map(read_element)
                .collect::<InputResult<_>>()?,
        ),
    };
    let strip = cone.required("strip")?;
    strip.only(&["t_min", "t_max"])?;
    let (t_min, t_max) = (
        strip.required("t_min")?.number()?,
        strip.required("t_max")?.number()?,
    );
    if t_min >= t_max {
        return strip.error(format!("t_min = {t_min} must be less than t_max = {t_max}"));
    }
    Ok(ConeJob {
        developable,
        tolerance: read_tolerance(cone)?,
        max_pieces: cone
            .optional("max_pieces")?
            .map_or(Ok(10_000), |f| f.count(2, 1_000_000))?,
        t_min,
        t_max,
    })
}

fn read_element(field: &Field) -> InputResult<Element> {
    field.only(&["point", "ruling", "side"])?;
    let v = |key: &str| field.required(key)?.vec3();
    Element::new(v("point")?, v("ruling")?, v("side")?, field.path())
        .or_else(|e| field.error(e.message()))
}

/// `{"sheet": {"transition": {"bottom": curve, "top": curve} | "ruled": {"nurbs": ...} |
/// "tangent_surface": {...}, "thickness", "k_factor", "tolerance", "reference",
/// "flat_tolerance", "max_pieces"}}`.
fn read_sheet(sheet: &Field) -> InputResult<SheetJob> {
    let choices = ["transition", "ruled", "tangent_surface"];
    let others = [
        "thickness",
        "k_factor",
        "tolerance",
        "reference",
        "flat_tolerance",
        "max_pieces",
    ];
    let (kind, body) = sheet.variant_of(&choices, &others)?;
    let input = match kind {
        "transition" => {
            body.only(&["bottom", "top"])?;
            SheetInput::Transition {
                bottom: read_closed_curve(&body.required("bottom")?)?,
                top: read_closed_curve(&body.required("top")?)?,
            }
        }
        "ruled" => {
            let (_, nurbs) = body.variant(&["nurbs"])?;
            SheetInput::Ruled(read_nurbs_surface(&nurbs)?)
        }
        _ => {
            body.only(&["curve", "v_min", "v_max"])?;
            let (_, nurbs) = body.required("curve")?.variant(&["nurbs"])?;
            SheetInput::TangentSurface {
                curve: read_nurbs_curve(&nurbs, false)?,
                v_min: body.required("v_min")?.number()?,
                v_max: body.required("v_max")?.number()?,
            }
        }
    };
    let thickness = sheet
        .optional("thickness")?
        .map_or(Ok(1.0), |f| f.positive())?;
    let k_factor = match sheet.optional("k_factor")? {
        None => 0.5,
        Some(f) => {
            let k = f.number()?;
            if !(0.0..=1.0).contains(&k) {
                return f.error(format!(
                    "must lie in [0, 1] (the neutral layer lies within the sheet), got {k}"
                ));
            }
            k
        }
    };
    let reference = match sheet.optional("reference")? {
        None => Reference::Inner,
        Some(f) => match f.string()? {
            "inner" => Reference::Inner,
            "neutral" => Reference::Neutral,
            "outer" => Reference::Outer,
            other => {
                return f.error(format!(
                    "unknown reference \"{other}\"; expected one of inner, neutral, outer"
                ))
            }
        },
    };
    let sheet_values =
        Sheet::new(thickness, k_factor, reference).or_else(|e| sheet.error(e.message()))?;
    Ok(SheetJob {
        input,
        options: SheetOptions {
            tolerance: read_tolerance(sheet)?,
            sheet: sheet_values,
            flat_tolerance: match sheet.optional("flat_tolerance")? {
                None => 0.0,
                Some(f) => f.positive()?,
            },
            max_pieces: sheet
                .optional("max_pieces")?
                .map_or(Ok(100_000), |f| f.count(2, 1_000_000))?,
        },
    })
}

/// A closed planar curve in space: `{"polygon": [[x, y, z], ...]}`, `{"circle": {"center",
/// "normal", "radius"}}`, `{"obround": {"center", "normal", "direction", "length",
/// "radius"}}` or `{"nurbs": {...}}`.
fn read_closed_curve(field: &Field) -> InputResult<NurbsCurve> {
    let (kind, body) = field.variant(&["polygon", "circle", "obround", "nurbs"])?;
    let curve = match kind {
        "polygon" => {
            let mut corners = vectors(&body)?;
            if corners.len() < 3 {
                return body.error(format!("needs at least 3 corners, got {}", corners.len()));
            }
            corners.push(corners[0]);
            polyline(&corners)
        }
        "circle" => {
            body.only(&["center", "normal", "radius"])?;
            let (center, normal) = (body.required("center")?.vec3()?, plane_normal(&body)?);
            let radius = body.required("radius")?.positive()?;
            let x = orthonormal_to(normal);
            space_circle(center, x, normal.cross(x), radius)
        }
        "obround" => {
            body.only(&["center", "normal", "direction", "length", "radius"])?;
            let (center, normal) = (body.required("center")?.vec3()?, plane_normal(&body)?);
            let direction_field = body.required("direction")?;
            let d = direction_field.vec3()?;
            let x = d - d.dot(normal) * normal;
            if x.length().is_nan() || x.length() <= 1e-12 * d.length() {
                return direction_field.error("must not be parallel to the normal");
            }
            let x = x.normalize();
            let length = body.required("length")?.positive()?;
            let radius = body.required("radius")?.positive()?;
            obround(center, x, normal.cross(x), length, radius)
        }
        _ => return read_nurbs_curve(&body, false),
    };
    curve.or_else(|e| body.error(e.message()))
}

/// A unit vector normal to the unit vector `n` (crossed with the axis least along it).
fn orthonormal_to(n: DVec3) -> DVec3 {
    let a = n.abs();
    let axis = if a.x <= a.y && a.x <= a.z {
        DVec3::X
    } else if a.y <= a.z {
        DVec3::Y
    } else {
        DVec3::Z
    };
    n.cross(axis).normalize()
}

fn plane_normal(body: &Field) -> InputResult<DVec3> {
    let field = body.required("normal")?;
    let n = field.vec3()?;
    if n.length().is_nan() || n.length() <= 0.0 {
        return field.error("must not be zero");
    }
    Ok(n.normalize())
}

/// The circle about `center` in the plane spanned by the orthonormal `x`, `y`: four
/// rational quadratic quarters.
fn space_circle(center: DVec3, x: DVec3, y: DVec3, radius: f64) -> rmfsurf::Result<NurbsCurve> {
    let corners = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    let poles = corners
        .iter()
        .map(|&(a, b)| center + radius * (a * x + b * y))
        .collect();
    let weights = (0..9)
        .map(|k| if k % 2 == 1 { FRAC_1_SQRT_2 } else { 1.0 })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];
    NurbsCurve::new(2, poles, Some(weights), knots)
}

/// Two half circles of `radius` about centres `length` apart along `x`, joined by lines:
/// degree 2, the lines elevated.
fn obround(
    center: DVec3,
    x: DVec3,
    y: DVec3,
    length: f64,
    radius: f64,
) -> rmfsurf::Result<NurbsCurve> {
    let a = 0.5 * length;
    let p = |u: f64, v: f64| center + u * x + v * y;
    let s = FRAC_1_SQRT_2;
    // (pole, weight) of each Bézier segment of degree 2, end points shared.
    let segments = [
        [
            (p(-a, -radius), 1.0),
            (p(0.0, -radius), 1.0),
            (p(a, -radius), 1.0),
        ],
        [
            (p(a, -radius), 1.0),
            (p(a + radius, -radius), s),
            (p(a + radius, 0.0), 1.0),
        ],
        [
            (p(a + radius, 0.0), 1.0),
            (p(a + radius, radius), s),
            (p(a, radius), 1.0),
        ],
        [
            (p(a, radius), 1.0),
            (p(0.0, radius), 1.0),
            (p(-a, radius), 1.0),
        ],
        [
            (p(-a, radius), 1.0),
            (p(-a - radius, radius), s),
            (p(-a - radius, 0.0), 1.0),
        ],
        [
            (p(-a - radius, 0.0), 1.0),
            (p(-a - radius, -radius), s),
            (p(-a, -radius), 1.0),
        ],
    ];
    let mut poles = vec![segments[0][0].0];
    let mut weights = vec![1.0];
    let mut knots = vec![0.0, 0.0, 0.0];
    for (k, seg) in segments.iter().enumerate() {
        for &(q, w) in &seg[1..] {
            poles.push(q);
            weights.push(w);
        }
        knots.extend([(k + 1) as f64; 2]);
    }
    knots.push(segments.len() as f64);
    NurbsCurve::new(2, poles, Some(weights), knots)
}
