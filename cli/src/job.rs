//! What the input JSON asks for, in the types the constructions take: the input read by
//! serde into the `schema` types (which check every value and bound every list), then the
//! checks that need several fields or the library (one choice of a tagged union, matching
//! counts, valid NURBS), each error naming its field (see `--help` for the schema).

use crate::json::{self, InputError, InputResult, Point2, Vec3};
use crate::schema;
use rmfsurf::glam::DVec3;
use rmfsurf::primitives;
use rmfsurf::{
    cone::Element, sheet::Reference, sheet::Sheet, sheet::SheetOptions, NurbsCurve, NurbsSurface,
    SpineMethod,
};
use std::io::Read;

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
    pub method: SpineMethod,
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

/// How a wire sweep's profile turns about the tangent: a law of the library's, or a guide
/// curve of edges of the wire's kinds (`{"guide": [...]}`).
#[derive(Clone, Debug)]
pub enum WireFrame {
    Law(rmfsurf::wire::SweepFrame),
    Guide(Vec<WireEdge>),
}

/// A sweep along a wire of lines, arcs and NURBS edges (`"spine": {"wire": [...]}`).
#[derive(Clone, Debug)]
pub struct WireJob {
    pub edges: Vec<WireEdge>,
    pub corner: rmfsurf::wire::Corner,
    pub tolerance: f64,
    pub join_tolerance: f64,
    pub initial_normal: Option<DVec3>,
    pub twist: f64,
    pub closure_symmetry: u32,
    /// In the normal plane: x along f₂, y along f₃.
    pub profile: NurbsCurve,
    pub holes: Vec<NurbsCurve>,
    pub solid: bool,
    /// How the profile turns about the tangent (default the RMF).
    pub frame: WireFrame,
    /// How a round profile is swept along curve edges (default the RMF).
    pub pipe_frame: rmfsurf::wire::PipeFrame,
    /// The profile's scale at the wire's start and end (default `[1, 1]`).
    pub scale: [f64; 2],
    /// Knots of the scale law, (fraction of the wire's length, scale) (default none).
    pub scale_knots: Vec<(f64, f64)>,
    /// How curve edges are swept (default ph-rmf; mobius and rrmf carry exact rational
    /// RMFs; frenet is refused by the library, blamed on `sweep.method`).
    pub method: SpineMethod,
    /// The section at the wire's end and its holes (`"end_profile"`, same coordinates as
    /// the profile): the section blends linearly in arc length from the profile to it.
    pub end_profile: Option<(NurbsCurve, Vec<NurbsCurve>)>,
    /// The sections between the profile and the end profile (`"sections"`): (fraction of
    /// the wire's length, profile, holes), the section passing through each.
    pub sections: Vec<(f64, NurbsCurve, Vec<NurbsCurve>)>,
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

impl Job {
    /// Reads the job from the JSON text of `reader`, named `source` in messages.
    pub fn read(reader: impl Read, source: &str) -> InputResult<Self> {
        Self::from_input(json::read::<schema::Input>(reader, source)?)
    }

    fn from_input(input: schema::Input) -> InputResult<Self> {
        let mesh = mesh_options(input.mesh);
        let construction = match (input.sweep, input.cone_spline, input.sheet) {
            (Some(sweep), None, None) if sweep.spine.wire.is_some() => {
                Construction::Wire(wire_job(sweep)?)
            }
            (Some(sweep), None, None) => Construction::Sweep(sweep_job(sweep)?),
            (None, Some(cone), None) => Construction::ConeSpline(cone_job(cone)?),
            (None, None, Some(sheet)) => Construction::Sheet(sheet_job(sheet)?),
            (a, b, c) => {
                return Err(choice(
                    "(top level)",
                    &["sweep", "cone_spline", "sheet"],
                    &[a.is_some(), b.is_some(), c.is_some()],
                ))
            }
        };
        Ok(Self { construction, mesh })
    }
}

/// The error of a tagged union (`{"circle": ...}`) at `path` with the choices `names`
/// of which those marked `given` were given: none, or more than one.
fn choice(path: &str, names: &[&str], given: &[bool]) -> InputError {
    let how = if given.contains(&true) {
        "give only one of"
    } else {
        "needs one of"
    };
    InputError::at(path, format!("{how} {}", names.join(", ")))
}

/// The error of a construction from the input at `path`.
fn at(path: &str) -> impl Fn(rmfsurf::Error) -> InputError + '_ {
    move |e| InputError::at(path, e.message())
}

fn mesh_options(mesh: Option<schema::Mesh>) -> MeshOptions {
    let mesh = mesh.unwrap_or(schema::Mesh {
        u_steps: None,
        v_steps: None,
        thickness: None,
    });
    MeshOptions {
        u_steps: mesh.u_steps.map_or(8, |n| n.0),
        v_steps: mesh.v_steps.map_or(8, |n| n.0),
        thickness: mesh.thickness.map(|t| t.0),
    }
}

const ONLY_WIRE: &str = "only for a sweep along a wire (\"spine\": {\"wire\": [...]})";

fn sweep_job(sweep: schema::Sweep) -> InputResult<SweepJob> {
    if let Some(name) = sweep.wire_fields().first() {
        return Err(InputError::at(format!("sweep.{name}"), ONLY_WIRE));
    }
    if sweep.profile.holes.is_some() {
        return Err(InputError::at("sweep.profile.holes", ONLY_WIRE));
    }
    let (profile, profile_is_line) = profile_curve(sweep.profile, "sweep.profile")?;
    Ok(SweepJob {
        spine: curve_spine(sweep.spine)?,
        method: sweep.method.map_or(SpineMethod::PhRmf, |m| m.0),
        tolerance: sweep.tolerance.map_or(DEFAULT_TOLERANCE, |t| t.0),
        initial_normal: sweep.initial_normal.map_or(DVec3::Z, |n| n.0),
        profile,
        profile_is_line,
    })
}

const DEFAULT_TOLERANCE: f64 = 1e-4;

/// A spine that is not a wire: `{"nurbs"}` or `{"points", "tangents"}`.
fn curve_spine(spine: schema::Spine) -> InputResult<Spine> {
    let path = "sweep.spine";
    match (spine.nurbs, spine.points) {
        (Some(nurbs), None) => {
            if spine.tangents.is_some() {
                return Err(InputError::at(
                    "sweep.spine.tangents",
                    "goes with points, not with nurbs",
                ));
            }
            Ok(Spine::Nurbs(nurbs_curve(nurbs, "sweep.spine.nurbs")?))
        }
        (None, Some(points)) => {
            let tangents = spine
                .tangents
                .ok_or_else(|| InputError::at("sweep.spine.tangents", "is missing"))?;
            let (points, tangents) = (vectors(points.into_vec()), vectors(tangents.into_vec()));
            if tangents.len() != points.len() {
                return Err(InputError::at(
                    "sweep.spine.tangents",
                    format!("{} tangents for {} points", tangents.len(), points.len()),
                ));
            }
            Ok(Spine::Hermite { points, tangents })
        }
        (nurbs, points) => Err(choice(
            path,
            &["nurbs", "points", "wire"],
            &[nurbs.is_some(), points.is_some()],
        )),
    }
}

fn vectors<P: Into<DVec3>>(points: Vec<P>) -> Vec<DVec3> {
    points.into_iter().map(Into::into).collect()
}

fn wire_job(sweep: schema::Sweep) -> InputResult<WireJob> {
    let spine = sweep.spine;
    if let Some((name, _)) = [
        ("nurbs", spine.nurbs.is_some()),
        ("points", spine.points.is_some()),
        ("tangents", spine.tangents.is_some()),
    ]
    .into_iter()
    .find(|(_, given)| *given)
    {
        return Err(InputError::at(
            format!("sweep.spine.{name}"),
            "does not go with wire: give one spine",
        ));
    }
    let edges = spine.wire.map(|w| w.into_vec()).unwrap_or_default();
    if edges.is_empty() {
        return Err(InputError::at(
            "sweep.spine.wire",
            "needs at least one edge",
        ));
    }
    let edges = edges
        .into_iter()
        .enumerate()
        .map(|(k, e)| wire_edge(e, &format!("sweep.spine.wire[{k}]")))
        .collect::<InputResult<Vec<_>>>()?;
    let (profile, holes) = profile_with_holes(sweep.profile, "sweep.profile")?;
    let end_profile = sweep
        .end_profile
        .map(|p| profile_with_holes(p, "sweep.end_profile"))
        .transpose()?;
    let sections = sweep
        .sections
        .map(|s| s.into_vec())
        .unwrap_or_default()
        .into_iter()
        .enumerate()
        .map(|(k, s)| section(s, &format!("sweep.sections[{k}]")))
        .collect::<InputResult<Vec<_>>>()?;
    if !sections.is_empty() && end_profile.is_none() {
        return Err(InputError::at(
            "sweep.sections",
            "need \"end_profile\": the sweep runs from \"profile\" at the start through the \
             sections to \"end_profile\" at the end",
        ));
    }
    let frame = match sweep.frame {
        None => WireFrame::Law(rmfsurf::wire::WireSweep::default().frame),
        Some(schema::FrameName::Law(law)) => WireFrame::Law(law),
        Some(schema::FrameName::Guide(guide)) => {
            if guide.is_empty() {
                return Err(InputError::at(
                    "sweep.frame.guide",
                    "needs at least one edge",
                ));
            }
            WireFrame::Guide(
                guide
                    .into_iter()
                    .enumerate()
                    .map(|(k, e)| wire_edge(e, &format!("sweep.frame.guide[{k}]")))
                    .collect::<InputResult<Vec<_>>>()?,
            )
        }
    };
    let defaults = rmfsurf::wire::WireSweep::default();
    Ok(WireJob {
        edges,
        corner: sweep.corner.map_or(defaults.corner, |c| c.0),
        tolerance: sweep.tolerance.map_or(DEFAULT_TOLERANCE, |t| t.0),
        join_tolerance: sweep
            .join_tolerance
            .map_or(defaults.join_tolerance, |t| t.0),
        initial_normal: sweep.initial_normal.map(|n| n.0),
        twist: sweep.twist.map_or(0.0, |t| t.0),
        closure_symmetry: sweep
            .closure_symmetry
            .map_or(0, |k| u32::try_from(k.0).unwrap_or(u32::MAX)),
        profile,
        holes,
        solid: sweep.solid.map_or(defaults.solid, |s| s.0),
        frame,
        pipe_frame: sweep.pipe_frame.map_or(defaults.pipe_frame, |p| p.0),
        scale: sweep.scale.map_or(defaults.scale, |s| s.0),
        scale_knots: sweep
            .scale_knots
            .map(|k| k.into_vec().into_iter().map(|k| k.0).collect())
            .unwrap_or_default(),
        method: sweep.method.map_or(defaults.method, |m| m.0),
        end_profile,
        sections,
    })
}

/// A section of a sweep through sections at `path`: its fraction, its profile at
/// `path.profile` and its holes at `path.holes[k]` (beside the profile, not in it).
fn section(
    section: schema::SectionIn,
    path: &str,
) -> InputResult<(f64, NurbsCurve, Vec<NurbsCurve>)> {
    if section.profile.holes.is_some() {
        return Err(InputError::at(
            format!("{path}.profile.holes"),
            format!("a section's holes go beside its profile: {path}.holes"),
        ));
    }
    let (profile, _) = profile_with_holes(section.profile, &format!("{path}.profile"))?;
    let holes = section
        .holes
        .map(|h| h.into_vec())
        .unwrap_or_default()
        .into_iter()
        .enumerate()
        .map(|(k, h)| hole_curve(h, &format!("{path}.holes[{k}]")))
        .collect::<InputResult<Vec<_>>>()?;
    Ok((section.at.0, profile, holes))
}

/// A wire sweep's profile (or end profile) at `path` and its holes at `path.holes[k]`.
fn profile_with_holes(
    mut profile: schema::Profile,
    path: &str,
) -> InputResult<(NurbsCurve, Vec<NurbsCurve>)> {
    let holes = profile
        .holes
        .take()
        .map(|h| h.into_vec())
        .unwrap_or_default();
    let (profile, _) = profile_curve(profile, path)?;
    let holes = holes
        .into_iter()
        .enumerate()
        .map(|(k, h)| hole_curve(h, &format!("{path}.holes[{k}]")))
        .collect::<InputResult<Vec<_>>>()?;
    Ok((profile, holes))
}

/// `{"line": {"from", "to"}}`, `{"arc": {"start", "through", "end"}}` or `{"nurbs": {...}}`.
fn wire_edge(edge: schema::Edge, path: &str) -> InputResult<WireEdge> {
    Ok(match (edge.line, edge.arc, edge.nurbs) {
        (Some(line), None, None) => WireEdge::Line {
            from: line.from.0,
            to: line.to.0,
        },
        (None, Some(arc), None) => WireEdge::Arc {
            start: arc.start.0,
            through: arc.through.0,
            end: arc.end.0,
        },
        (None, None, Some(nurbs)) => WireEdge::Nurbs(nurbs_curve(nurbs, &format!("{path}.nurbs"))?),
        (a, b, c) => {
            return Err(choice(
                path,
                &["line", "arc", "nurbs"],
                &[a.is_some(), b.is_some(), c.is_some()],
            ))
        }
    })
}

/// The NURBS curve of `{"degree", "poles", "weights" (optional), "knots"}` at `path`.
fn nurbs_curve<P: Into<DVec3>>(nurbs: schema::Nurbs<P>, path: &str) -> InputResult<NurbsCurve> {
    NurbsCurve::new(
        nurbs.degree.0,
        vectors(nurbs.poles.into_vec()),
        nurbs.weights.map(numbers),
        numbers(nurbs.knots),
    )
    .map_err(at(path))
}

fn numbers<L>(list: json::Bounded<json::Number, L>) -> Vec<f64> {
    list.into_vec().into_iter().map(|x| x.0).collect()
}

/// `{"degree_u", "degree_v", "poles": rows (one per u index) of [x, y, z], "weights" (rows,
/// optional), "knots_u", "knots_v"}` at `path`.
fn nurbs_surface(nurbs: schema::Surface, path: &str) -> InputResult<NurbsSurface> {
    let rows: Vec<Vec<DVec3>> = nurbs
        .poles
        .into_vec()
        .into_iter()
        .map(|row| vectors(row.into_vec()))
        .collect();
    let columns = rows.first().map_or(0, Vec::len);
    if rows.iter().any(|r| r.len() != columns) {
        return Err(InputError::at(
            format!("{path}.poles"),
            "every row of poles must have the same length",
        ));
    }
    let weights = nurbs
        .weights
        .map(|rows| rows.into_vec().into_iter().flat_map(numbers).collect());
    NurbsSurface::new(
        nurbs.degree_u.0,
        nurbs.degree_v.0,
        rows.len(),
        columns,
        rows.concat(),
        weights,
        numbers(nurbs.knots_u),
        numbers(nurbs.knots_v),
    )
    .map_err(at(path))
}

/// The profile curve of `{"circle" | "line" | "polygon" | "nurbs": body}` at `path` and
/// whether it is one straight segment.
fn profile_curve(profile: schema::Profile, path: &str) -> InputResult<(NurbsCurve, bool)> {
    match (profile.circle, profile.line, profile.polygon, profile.nurbs) {
        (Some(c), None, None, None) => Ok((profile_circle(c, &format!("{path}.circle"))?, false)),
        (None, Some(line), None, None) => {
            let path = format!("{path}.line");
            Ok((
                nurbs(primitives::polyline(&[line.from.0, line.to.0])).map_err(at(&path))?,
                true,
            ))
        }
        (None, None, Some(corners), None) => Ok((
            polygon(corners.into_vec(), &format!("{path}.polygon"))?,
            false,
        )),
        (None, None, None, Some(nurbs)) => {
            Ok((nurbs_curve(nurbs, &format!("{path}.nurbs"))?, false))
        }
        (a, b, c, d) => Err(choice(
            path,
            &["circle", "line", "polygon", "nurbs"],
            &[a.is_some(), b.is_some(), c.is_some(), d.is_some()],
        )),
    }
}

/// A hole of a wire sweep's profile: `{"circle" | "polygon" | "nurbs": body}` at `path`.
fn hole_curve(hole: schema::Hole, path: &str) -> InputResult<NurbsCurve> {
    match (hole.circle, hole.polygon, hole.nurbs) {
        (Some(c), None, None) => profile_circle(c, &format!("{path}.circle")),
        (None, Some(corners), None) => polygon(corners.into_vec(), &format!("{path}.polygon")),
        (None, None, Some(nurbs)) => nurbs_curve(nurbs, &format!("{path}.nurbs")),
        (a, b, c) => Err(choice(
            path,
            &["circle", "polygon", "nurbs"],
            &[a.is_some(), b.is_some(), c.is_some()],
        )),
    }
}

/// A primitive as one NURBS curve.
fn nurbs(curve: rmfsurf::Result<rmfsurf::PiecewiseCurve>) -> rmfsurf::Result<NurbsCurve> {
    NurbsCurve::from_piecewise(&curve?)
}

fn profile_circle(c: schema::Circle, path: &str) -> InputResult<NurbsCurve> {
    let centre = c.center.map_or(DVec3::ZERO, |p| p.0);
    nurbs(primitives::circle(centre, DVec3::X, DVec3::Y, c.radius.0)).map_err(at(path))
}

/// The closed polygon through `corners` (at least three) at `path`.
fn polygon<P: Into<DVec3>>(corners: Vec<P>, path: &str) -> InputResult<NurbsCurve> {
    let mut corners = vectors(corners);
    if corners.len() < 3 {
        return Err(InputError::at(
            path,
            format!("needs at least 3 corners, got {}", corners.len()),
        ));
    }
    corners.push(corners[0]);
    nurbs(primitives::polyline(&corners)).map_err(at(path))
}

impl From<Vec3> for DVec3 {
    fn from(v: Vec3) -> DVec3 {
        v.0
    }
}

impl From<Point2> for DVec3 {
    fn from(p: Point2) -> DVec3 {
        p.0
    }
}

fn cone_job(cone: schema::Cone) -> InputResult<ConeJob> {
    let d = cone.developable;
    let path = "cone_spline.developable";
    let developable = match (d.tangent_surface, d.ruled, d.elements) {
        (Some(t), None, None) => Developable::TangentSurface {
            curve: nurbs_curve(
                t.curve.nurbs,
                &format!("{path}.tangent_surface.curve.nurbs"),
            )?,
            v_min: t.v_min.0,
            v_max: t.v_max.0,
        },
        (None, Some(r), None) => {
            Developable::Ruled(nurbs_surface(r.nurbs, &format!("{path}.ruled.nurbs"))?)
        }
        (None, None, Some(elements)) => Developable::Elements(
            elements
                .into_vec()
                .into_iter()
                .enumerate()
                .map(|(k, e)| element(e, &format!("{path}.elements[{k}]")))
                .collect::<InputResult<_>>()?,
        ),
        (a, b, c) => {
            return Err(choice(
                path,
                &["tangent_surface", "ruled", "elements"],
                &[a.is_some(), b.is_some(), c.is_some()],
            ))
        }
    };
    let (t_min, t_max) = (cone.strip.t_min.0, cone.strip.t_max.0);
    if t_min >= t_max {
        return Err(InputError::at(
            "cone_spline.strip",
            format!("t_min = {t_min} must be less than t_max = {t_max}"),
        ));
    }
    Ok(ConeJob {
        developable,
        tolerance: cone.tolerance.map_or(DEFAULT_TOLERANCE, |t| t.0),
        max_pieces: cone
            .max_pieces
            .map_or(rmfsurf::cone::DEFAULT_MAX_PIECES, |n| n.0),
        t_min,
        t_max,
    })
}

fn element(e: schema::Element, path: &str) -> InputResult<Element> {
    Element::new(e.point.0, e.ruling.0, e.side.0, path).map_err(at(path))
}

/// `{"sheet": {"transition": {"bottom": curve, "top": curve} | "ruled": {"nurbs": ...} |
/// "tangent_surface": {...}, "thickness", "k_factor", "tolerance", "reference",
/// "flat_tolerance", "max_pieces"}}`.
fn sheet_job(sheet: schema::Sheet) -> InputResult<SheetJob> {
    let input = match (sheet.transition, sheet.ruled, sheet.tangent_surface) {
        (Some(t), None, None) => SheetInput::Transition {
            bottom: closed_curve(t.bottom, "sheet.transition.bottom")?,
            top: closed_curve(t.top, "sheet.transition.top")?,
        },
        (None, Some(r), None) => SheetInput::Ruled(nurbs_surface(r.nurbs, "sheet.ruled.nurbs")?),
        (None, None, Some(t)) => SheetInput::TangentSurface {
            curve: nurbs_curve(t.curve.nurbs, "sheet.tangent_surface.curve.nurbs")?,
            v_min: t.v_min.0,
            v_max: t.v_max.0,
        },
        (a, b, c) => {
            return Err(choice(
                "sheet",
                &["transition", "ruled", "tangent_surface"],
                &[a.is_some(), b.is_some(), c.is_some()],
            ))
        }
    };
    let k_factor = sheet.k_factor.map_or(0.5, |k| k.0);
    if !(0.0..=1.0).contains(&k_factor) {
        return Err(InputError::at(
            "sheet.k_factor",
            format!("must lie in [0, 1] (the neutral layer lies within the sheet), got {k_factor}"),
        ));
    }
    let sheet_values = Sheet::new(
        sheet.thickness.map_or(1.0, |t| t.0),
        k_factor,
        sheet.reference.map_or(Reference::Inner, |r| r.0),
    )
    .map_err(at("sheet"))?;
    Ok(SheetJob {
        input,
        options: SheetOptions {
            tolerance: sheet.tolerance.map_or(DEFAULT_TOLERANCE, |t| t.0),
            sheet: sheet_values,
            flat_tolerance: sheet.flat_tolerance.map_or(0.0, |t| t.0),
            max_pieces: sheet
                .max_pieces
                .map_or(rmfsurf::cone::DEFAULT_MAX_PIECES, |n| n.0),
        },
    })
}

/// A closed planar curve in space at `path`: `{"polygon": [[x, y, z], ...]}`,
/// `{"circle": {"center", "normal", "radius"}}`, `{"obround": {"center", "normal",
/// "direction", "length", "radius"}}` or `{"nurbs": {...}}`.
fn closed_curve(curve: schema::ClosedCurve, path: &str) -> InputResult<NurbsCurve> {
    match (curve.polygon, curve.circle, curve.obround, curve.nurbs) {
        (Some(corners), None, None, None) => {
            polygon(corners.into_vec(), &format!("{path}.polygon"))
        }
        (None, Some(c), None, None) => {
            let path = format!("{path}.circle");
            let normal = plane_normal(c.normal.0, &path)?;
            let x = orthonormal_to(normal);
            nurbs(primitives::circle(
                c.center.0,
                x,
                normal.cross(x),
                c.radius.0,
            ))
            .map_err(at(&path))
        }
        (None, None, Some(o), None) => {
            let path = format!("{path}.obround");
            let normal = plane_normal(o.normal.0, &path)?;
            let d = rmfsurf::numeric::robust_normalize(o.direction.0).unwrap_or(normal);
            let x = d - d.dot(normal) * normal;
            if x.length().is_nan() || x.length() <= 1e-12 {
                return Err(InputError::at(
                    format!("{path}.direction"),
                    "must not be parallel to the normal",
                ));
            }
            let x = x.normalize();
            nurbs(primitives::obround(
                o.center.0,
                x,
                normal.cross(x),
                o.length.0,
                o.radius.0,
            ))
            .map_err(at(&path))
        }
        (None, None, None, Some(nurbs)) => nurbs_curve(nurbs, &format!("{path}.nurbs")),
        (a, b, c, d) => Err(choice(
            path,
            &["polygon", "circle", "obround", "nurbs"],
            &[a.is_some(), b.is_some(), c.is_some(), d.is_some()],
        )),
    }
}

fn plane_normal(n: DVec3, path: &str) -> InputResult<DVec3> {
    // Any length: a normal is a direction.
    rmfsurf::numeric::robust_normalize(n)
        .ok_or_else(|| InputError::at(format!("{path}.normal"), "must not be zero"))
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
