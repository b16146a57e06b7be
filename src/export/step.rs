//! STEP (ISO 10303-21 exchange structure) files of NURBS surfaces and curves, schema
//! AP214 `AUTOMOTIVE_DESIGN` — the entity set OpenCascade (and so FreeCAD) writes and reads
//! for B-spline geometry:
//!
//! * a surface becomes one `ADVANCED_FACE` on a rational B-spline surface (the complex
//!   entity `B_SPLINE_SURFACE_WITH_KNOTS` + `RATIONAL_B_SPLINE_SURFACE`, ISO 10303-42
//!   §4.4.12/§4.4.15) bounded by its four boundary curves, in an `OPEN_SHELL` of a
//!   `SHELL_BASED_SURFACE_MODEL` (`MANIFOLD_SURFACE_SHAPE_REPRESENTATION`);
//! * curves become rational B-spline curves in a `GEOMETRIC_CURVE_SET`
//!   (`GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION`);
//! * a B-rep ([`Brep`]: faces on rational B-spline surfaces and planes, sharing their
//!   edges and vertices, each edge used once in each direction) becomes a
//!   `MANIFOLD_SOLID_BREP` of a `CLOSED_SHELL` (`ADVANCED_BREP_SHAPE_REPRESENTATION`), or
//!   an `OPEN_SHELL` for a sheet. Every edge is written once, as a `SURFACE_CURVE` carrying
//!   its parameter line on each face that uses it (a `SEAM_CURVE` when one face uses it
//!   twice); on a plane the parameter curve is the 2-D B-spline in the plane's axes. A solid
//!   with cavities (a hollow profile swept round a closed wire) is a `BREP_WITH_VOIDS`; an
//!   open shape that falls apart writes one `OPEN_SHELL` per part. Degenerate edges (a side
//!   of a surface collapsed to a point) are left out: STEP loops close in space.
//! * a flat pattern is one `PLANE` face bounded by `LINE` and `CIRCLE` edges.
//!
//! The boundary curves are exact: a clamped NURBS surface's boundary is the NURBS curve of
//! its first/last row or column of poles. Each edge carries its parameter-space line
//! (`SURFACE_CURVE` with a `PCURVE`); where the surface is closed the two coinciding
//! boundaries are one seam edge (`SEAM_CURVE` with both parameter lines), used twice in
//! the loop, as in OpenCascade's own files. Coordinates are written in millimetres with
//! 17 significant digits, so every double round-trips exactly.

use super::knots_and_multiplicities;
use crate::bezier::{NurbsCurve, NurbsSurface};
use crate::error::{invalid, Result};
use crate::math::bounding_diagonal;
use crate::model::{AnalyticCurve, AnalyticSurface, Brep, BrepSurface, PCurve};
use crate::model::{FlatPattern, PatternEdge};
use glam::DVec3;
use std::fmt::Write;

/// Relative distance (to the pole box diagonal) below which two boundary curves or two
/// corners are the same (a closed surface).
const SAME_TOLERANCE: f64 = 1e-9;

/// The entities of one file under construction, numbered from #1.
struct Entities {
    lines: Vec<String>,
}

impl Entities {
    /// Appends an entity and returns its number.
    fn add(&mut self, entity: impl Into<String>) -> usize {
        self.lines.push(entity.into());
        self.lines.len()
    }

    fn point(&mut self, p: DVec3) -> usize {
        self.add(format!(
            "CARTESIAN_POINT('',({},{},{}))",
            real(p.x),
            real(p.y),
            real(p.z)
        ))
    }

    fn point_2d(&mut self, u: f64, v: f64) -> usize {
        self.add(format!("CARTESIAN_POINT('',({},{}))", real(u), real(v)))
    }
}

/// A STEP REAL: the shortest representation that reads back to the same double, always
/// with a decimal point (Part 21 requires one) and an upper-case exponent.
fn real(x: f64) -> String {
    let s = format!("{x:?}").to_uppercase();
    match s.find('E') {
        Some(e) if !s[..e].contains('.') => format!("{}.{}", &s[..e], &s[e..]),
        _ => s,
    }
}

/// The text of a STEP string literal (without the quotes): printable ASCII only (Part 21
/// encodes anything else specially; names here need no more), apostrophes and backslashes
/// doubled.
fn string(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_ascii_graphic() || c == ' ' {
                c
            } else {
                '_'
            }
        })
        .collect::<String>()
        .replace('\\', "\\\\")
        .replace('\'', "''")
}

/// `(a,b,c)` of already formatted items.
fn list(items: impl IntoIterator<Item = String>) -> String {
    format!("({})", items.into_iter().collect::<Vec<_>>().join(","))
}

fn refs(ids: &[usize]) -> String {
    list(ids.iter().map(|id| format!("#{id}")))
}

fn reals(values: &[f64]) -> String {
    list(values.iter().map(|&x| real(x)))
}

fn multiplicities_list(multiplicities: &[usize]) -> String {
    list(multiplicities.iter().map(usize::to_string))
}

/// The complex entity of a rational B-spline curve.
fn curve_entity(out: &mut Entities, curve: &NurbsCurve) -> usize {
    let poles: Vec<usize> = curve.poles.iter().map(|&p| out.point(p)).collect();
    let (knots, multiplicities) = knots_and_multiplicities(&curve.knots);
    out.add(format!(
        "( BOUNDED_CURVE() B_SPLINE_CURVE({},{},.UNSPECIFIED.,.F.,.F.) \
         B_SPLINE_CURVE_WITH_KNOTS({},{},.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() \
         RATIONAL_B_SPLINE_CURVE({}) REPRESENTATION_ITEM('') )",
        curve.degree,
        refs(&poles),
        multiplicities_list(&multiplicities),
        reals(&knots),
        reals(&curve.weights)
    ))
}

/// The complex entity of a rational B-spline surface; control points row by row, a row
/// holding the poles of one u index (ISO 10303-42: `control_points_list[i][j]`, i along u).
fn surface_entity(out: &mut Entities, surface: &NurbsSurface) -> usize {
    let nv = surface.pole_count_v;
    let ids: Vec<usize> = surface.poles.iter().map(|&p| out.point(p)).collect();
    let rows = list(ids.chunks(nv).map(refs));
    let weights = list(surface.weights.chunks(nv).map(reals));
    let (ku, mu) = knots_and_multiplicities(&surface.knots_u);
    let (kv, mv) = knots_and_multiplicities(&surface.knots_v);
    out.add(format!(
        "( BOUNDED_SURFACE() B_SPLINE_SURFACE({},{},{rows},.UNSPECIFIED.,.F.,.F.,.F.) \
         B_SPLINE_SURFACE_WITH_KNOTS({},{},{},{},.UNSPECIFIED.) GEOMETRIC_REPRESENTATION_ITEM() \
         RATIONAL_B_SPLINE_SURFACE({weights}) REPRESENTATION_ITEM('') SURFACE() )",
        surface.degree_u,
        surface.degree_v,
        multiplicities_list(&mu),
        multiplicities_list(&mv),
        reals(&ku),
        reals(&kv)
    ))
}

/// One of the four boundaries of a surface, as the NURBS curve it is.
pub(crate) struct Boundary {
    pub curve: NurbsCurve,
    /// The line in (u, v) the boundary's parameter t maps to: origin + t · direction.
    pub origin: (f64, f64),
    pub direction: (f64, f64),
}

/// The boundaries v = v₀, u = u₁, v = v₁, u = u₀ (counter-clockwise in the parameter plane:
/// the face's loop traverses the first two forwards, the last two backwards).
pub(crate) fn boundaries(s: &NurbsSurface) -> [Boundary; 4] {
    [0, 1, 2, 3].map(|side| {
        let (origin, direction) = s.boundary_line(side);
        Boundary {
            curve: s.boundary_curve(side),
            origin,
            direction,
        }
    })
}

/// Whether two boundary curves are the same curve (same parameterization; homogeneous
/// poles equal up to `tolerance` in position and relative weight).
fn same_curve(a: &NurbsCurve, b: &NurbsCurve, tolerance: f64) -> bool {
    let ratio = b.weights[0] / a.weights[0];
    a.poles
        .iter()
        .zip(&b.poles)
        .all(|(p, q)| p.distance(*q) <= tolerance)
        && a.weights
            .iter()
            .zip(&b.weights)
            .all(|(w, v)| (v - ratio * w).abs() <= SAME_TOLERANCE * v.abs())
}

/// Whether every pole of a curve is the same point (a boundary collapsed to a point).
fn collapsed(c: &NurbsCurve, tolerance: f64) -> bool {
    c.poles.iter().all(|p| p.distance(c.poles[0]) <= tolerance)
}

/// The entities of one face under construction: vertices are shared where boundary curves
/// meet (and where a closed surface's corners coincide).
struct Face<'a> {
    out: &'a mut Entities,
    surface: usize,
    context_2d: usize,
    tolerance: f64,
    vertices: Vec<(DVec3, usize)>,
}

impl Face<'_> {
    fn vertex(&mut self, p: DVec3) -> usize {
        if let Some(&(_, id)) = self
            .vertices
            .iter()
            .find(|(q, _)| q.distance(p) <= self.tolerance)
        {
            return id;
        }
        let point = self.out.point(p);
        let id = self.out.add(format!("VERTEX_POINT('',#{point})"));
        self.vertices.push((p, id));
        id
    }

    /// The boundary's line in the surface's parameter plane.
    fn pcurve(&mut self, side: &Boundary) -> usize {
        let line = PCurve::Line {
            origin: side.origin,
            direction: side.direction,
        };
        pcurve_entity(self.out, self.surface, self.context_2d, &line)
    }

    /// The edge along `side`; with `seam`, the coinciding opposite side, it is a seam
    /// carrying both parameter lines.
    fn edge(&mut self, side: &Boundary, seam: Option<&Boundary>) -> usize {
        let curve = &side.curve;
        let start = self.vertex(curve.poles[0]);
        let end = self.vertex(curve.poles[curve.poles.len() - 1]);
        let geometry = curve_entity(self.out, curve);
        let mut pcurves = vec![self.pcurve(side)];
        if let Some(other) = seam {
            pcurves.push(self.pcurve(other));
        }
        let kind = if seam.is_some() {
            "SEAM_CURVE"
        } else {
            "SURFACE_CURVE"
        };
        let on_surface = self.out.add(format!(
            "{kind}('',#{geometry},{},.PCURVE_S1.)",
            refs(&pcurves)
        ));
        self.out
            .add(format!("EDGE_CURVE('',#{start},#{end},#{on_surface},.T.)"))
    }
}

/// A curve in a surface's parameter plane (a `PCURVE` with its 2-D geometry).
fn pcurve_entity(out: &mut Entities, surface: usize, context_2d: usize, pcurve: &PCurve) -> usize {
    let geometry = match pcurve {
        PCurve::Line { origin, direction } => {
            let origin = out.point_2d(origin.0, origin.1);
            let magnitude = direction.0.hypot(direction.1);
            let direction = out.add(format!(
                "DIRECTION('',({},{}))",
                real(direction.0 / magnitude),
                real(direction.1 / magnitude)
            ));
            let vector = out.add(format!("VECTOR('',#{direction},{})", real(magnitude)));
            out.add(format!("LINE('',#{origin},#{vector})"))
        }
        PCurve::Curve(curve) => curve_entity_2d(out, curve),
    };
    let representation = out.add(format!(
        "DEFINITIONAL_REPRESENTATION('',(#{geometry}),#{context_2d})"
    ));
    out.add(format!("PCURVE('',#{surface},#{representation})"))
}

/// The complex entity of a rational B-spline curve in a parameter plane (x, y of the poles).
fn curve_entity_2d(out: &mut Entities, curve: &NurbsCurve) -> usize {
    let poles: Vec<usize> = curve.poles.iter().map(|p| out.point_2d(p.x, p.y)).collect();
    let (knots, multiplicities) = knots_and_multiplicities(&curve.knots);
    out.add(format!(
        "( BOUNDED_CURVE() B_SPLINE_CURVE({},{},.UNSPECIFIED.,.F.,.F.) \
         B_SPLINE_CURVE_WITH_KNOTS({},{},.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() \
         RATIONAL_B_SPLINE_CURVE({}) REPRESENTATION_ITEM('') )",
        curve.degree,
        refs(&poles),
        multiplicities_list(&multiplicities),
        reals(&knots),
        reals(&curve.weights)
    ))
}

/// Writes the face: surface, vertices, edges (seams shared) and the loop.
fn face_entities(out: &mut Entities, surface: &NurbsSurface, context_2d: usize) -> usize {
    let tolerance =
        SAME_TOLERANCE * bounding_diagonal(surface.poles.iter().copied()).max(f64::MIN_POSITIVE);
    let surface_id = surface_entity(out, surface);
    let sides = boundaries(surface);
    let mut face = Face {
        out,
        surface: surface_id,
        context_2d,
        tolerance,
        vertices: Vec::new(),
    };
    // The two sides of a closed direction coincide: (0, 2) when closed in v, (1, 3) in u.
    let seam_of = |k: usize| {
        let partner = (k + 2) % 4;
        same_curve(&sides[k].curve, &sides[partner].curve, tolerance).then_some(partner)
    };
    let mut edges: [Option<usize>; 4] = [None; 4];
    let mut loop_edges = Vec::new();
    for k in 0..4 {
        if collapsed(&sides[k].curve, tolerance) {
            continue;
        }
        let edge = match edges[k] {
            Some(edge) => edge,
            None => {
                let partner = seam_of(k);
                let edge = face.edge(&sides[k], partner.map(|p| &sides[p]));
                edges[k] = Some(edge);
                if let Some(p) = partner {
                    edges[p] = Some(edge);
                }
                edge
            }
        };
        let forward = if k < 2 { ".T." } else { ".F." };
        loop_edges.push(
            face.out
                .add(format!("ORIENTED_EDGE('',*,*,#{edge},{forward})")),
        );
    }
    let out = face.out;
    let edge_loop = out.add(format!("EDGE_LOOP('',{})", refs(&loop_edges)));
    let bound = out.add(format!("FACE_OUTER_BOUND('',#{edge_loop},.T.)"));
    out.add(format!("ADVANCED_FACE('',(#{bound}),#{surface_id},.T.)"))
}

/// The product structure and the 3-D context (millimetres, radians); returns the numbers of
/// the product's shape and of the context, for the representation.
fn product_and_context(out: &mut Entities, name: &str) -> (usize, usize) {
    let name = string(name);
    let application =
        out.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
    out.add(format!(
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#{application})"
    ));
    let product_context = out.add(format!("PRODUCT_CONTEXT('',#{application},'mechanical')"));
    let product = out.add(format!(
        "PRODUCT('{name}','{name}','',(#{product_context}))"
    ));
    out.add(format!(
        "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#{product}))"
    ));
    let formation = out.add(format!("PRODUCT_DEFINITION_FORMATION('','',#{product})"));
    let definition_context = out.add(format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',#{application},'design')"
    ));
    let definition = out.add(format!(
        "PRODUCT_DEFINITION('design','',#{formation},#{definition_context})"
    ));
    let shape = out.add(format!("PRODUCT_DEFINITION_SHAPE('','',#{definition})"));
    let length = out.add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) )");
    let angle = out.add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )");
    let solid_angle = out.add("( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() )");
    let uncertainty = out.add(format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#{length},'distance_accuracy_value','confusion accuracy')"
    ));
    let context = out.add(format!(
        "( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{uncertainty})) \
         GLOBAL_UNIT_ASSIGNED_CONTEXT((#{length},#{angle},#{solid_angle})) \
         REPRESENTATION_CONTEXT('Context #1','3D Context with UNIT and UNCERTAINTY') )"
    ));
    (shape, context)
}

/// Adds the shape representation `entity` (a format string's result) as the product's
/// shape.
fn represent(out: &mut Entities, shape: usize, entity: String) {
    let representation = out.add(entity);
    out.add(format!(
        "SHAPE_DEFINITION_REPRESENTATION(#{shape},#{representation})"
    ));
}

/// The exchange structure: header and the numbered entities.
fn exchange_structure(entities: &Entities, name: &str) -> String {
    let name = string(name);
    let mut s = String::new();
    s.push_str("ISO-10303-21;\nHEADER;\n");
    s.push_str("FILE_DESCRIPTION(('rmfsurf exact rational geometry'),'2;1');\n");
    let _ = writeln!(
        s,
        "FILE_NAME('{name}','',(''),(''),'rmfsurf {}','rmfsurf','');",
        env!("CARGO_PKG_VERSION")
    );
    s.push_str("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n");
    for (k, line) in entities.lines.iter().enumerate() {
        let _ = writeln!(s, "#{} = {line};", k + 1);
    }
    s.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
    s
}

/// A STEP file holding `surfaces` as faces of one open shell, the product called `name`.
pub fn surfaces_to_step(surfaces: &[&NurbsSurface], name: &str) -> Result<String> {
    if surfaces.is_empty() {
        return invalid!("a STEP file needs at least one surface");
    }
    let mut out = Entities { lines: Vec::new() };
    let (shape, context) = product_and_context(&mut out, name);
    let origin = out.point(DVec3::ZERO);
    let z = out.add("DIRECTION('',(0.,0.,1.))");
    let x = out.add("DIRECTION('',(1.,0.,0.))");
    let placement = out.add(format!("AXIS2_PLACEMENT_3D('',#{origin},#{z},#{x})"));
    let context_2d = out.add(
        "( GEOMETRIC_REPRESENTATION_CONTEXT(2) PARAMETRIC_REPRESENTATION_CONTEXT() \
         REPRESENTATION_CONTEXT('2D SPACE','') )",
    );
    let faces: Vec<usize> = surfaces
        .iter()
        .map(|s| face_entities(&mut out, s, context_2d))
        .collect();
    let shell = out.add(format!("OPEN_SHELL('',{})", refs(&faces)));
    let model = out.add(format!("SHELL_BASED_SURFACE_MODEL('',(#{shell}))"));
    let representation = format!(
        "MANIFOLD_SURFACE_SHAPE_REPRESENTATION('{}',(#{placement},#{model}),#{context})",
        string(name)
    );
    represent(&mut out, shape, representation);
    Ok(exchange_structure(&out, name))
}

fn direction(out: &mut Entities, d: DVec3) -> usize {
    out.add(format!(
        "DIRECTION('',({},{},{}))",
        real(d.x),
        real(d.y),
        real(d.z)
    ))
}

fn flag(value: bool) -> &'static str {
    if value {
        ".T."
    } else {
        ".F."
    }
}

/// An `AXIS2_PLACEMENT_3D` at `origin` with unit `axis` and reference direction `x_axis`.
fn axis_placement(out: &mut Entities, origin: DVec3, axis: DVec3, x_axis: DVec3) -> usize {
    let point = out.point(origin);
    let (axis, reference) = (direction(out, axis), direction(out, x_axis));
    out.add(format!(
        "AXIS2_PLACEMENT_3D('',#{point},#{axis},#{reference})"
    ))
}

/// A `PLANE`, `CYLINDRICAL_SURFACE`, `CONICAL_SURFACE` or `TOROIDAL_SURFACE` (ISO 10303-42);
/// a cone's semi-angle is positive there, so a cone narrowing along its axis is placed on
/// the axis turned round (the same points, u and v both reversed: the same normal).
fn analytic_surface_entity(out: &mut Entities, surface: &AnalyticSurface) -> usize {
    let [origin, axis, x_axis] = surface.axes();
    match *surface {
        AnalyticSurface::Plane { .. } => {
            let frame = axis_placement(out, origin, axis, x_axis);
            out.add(format!("PLANE('',#{frame})"))
        }
        AnalyticSurface::Cylinder { radius, .. } => {
            let frame = axis_placement(out, origin, axis, x_axis);
            out.add(format!("CYLINDRICAL_SURFACE('',#{frame},{})", real(radius)))
        }
        AnalyticSurface::Cone {
            radius, semi_angle, ..
        } => {
            let axis = if semi_angle < 0.0 { -axis } else { axis };
            let frame = axis_placement(out, origin, axis, x_axis);
            out.add(format!(
                "CONICAL_SURFACE('',#{frame},{},{})",
                real(radius),
                real(semi_angle.abs())
            ))
        }
        AnalyticSurface::Torus { major, minor, .. } => {
            let frame = axis_placement(out, origin, axis, x_axis);
            out.add(format!(
                "TOROIDAL_SURFACE('',#{frame},{},{})",
                real(major),
                real(minor)
            ))
        }
    }
}

/// A `LINE` (its point at s = 0 and unit direction) or a `CIRCLE`.
fn analytic_curve_entity(out: &mut Entities, curve: &AnalyticCurve) -> usize {
    match *curve {
        AnalyticCurve::Line { origin, direction } => {
            let point = out.point(origin);
            let along = self::direction(out, direction);
            let vector = out.add(format!("VECTOR('',#{along},1.)"));
            out.add(format!("LINE('',#{point},#{vector})"))
        }
        AnalyticCurve::Circle {
            center,
            axis,
            x_axis,
            radius,
        } => {
            let frame = axis_placement(out, center, axis, x_axis);
            out.add(format!("CIRCLE('',#{frame},{})", real(radius)))
        }
    }
}

/// A STEP file holding the B-rep, the product called `name`: a `MANIFOLD_SOLID_BREP` when
/// it is closed, a shell-based surface model otherwise (module notes).
pub fn brep_to_step(brep: &Brep, name: &str) -> Result<String> {
    if brep.faces.is_empty() {
        return invalid!("a STEP file needs at least one face");
    }
    let mut out = Entities { lines: Vec::new() };
    let (shape, context) = product_and_context(&mut out, name);
    let origin = out.point(DVec3::ZERO);
    let z = out.add("DIRECTION('',(0.,0.,1.))");
    let x = out.add("DIRECTION('',(1.,0.,0.))");
    let placement = out.add(format!("AXIS2_PLACEMENT_3D('',#{origin},#{z},#{x})"));
    let context_2d = out.add(
        "( GEOMETRIC_REPRESENTATION_CONTEXT(2) PARAMETRIC_REPRESENTATION_CONTEXT() \
         REPRESENTATION_CONTEXT('2D SPACE','') )",
    );
    let surfaces: Vec<usize> = brep
        .faces
        .iter()
        .map(|f| match (&f.analytic, &f.surface) {
            (Some(analytic), _) => analytic_surface_entity(&mut out, &analytic.surface),
            (None, BrepSurface::Nurbs(s)) => surface_entity(&mut out, s),
            (
                None,
                BrepSurface::Plane {
                    origin,
                    normal,
                    x_axis,
                },
            ) => {
                let frame = axis_placement(&mut out, *origin, *normal, *x_axis);
                out.add(format!("PLANE('',#{frame})"))
            }
        })
        .collect();
    let vertices: Vec<usize> = brep
        .vertices
        .iter()
        .map(|&p| {
            let point = out.point(p);
            out.add(format!("VERTEX_POINT('',#{point})"))
        })
        .collect();
    // The parameter curves of every edge, by the faces that use it.
    let mut pcurves: Vec<Vec<(usize, &PCurve)>> = vec![Vec::new(); brep.edges.len()];
    for (f, face) in brep.faces.iter().enumerate() {
        for u in face.bounds.iter().flat_map(|b| &b.uses) {
            let Some(edge) = pcurves.get_mut(u.edge) else {
                return invalid!("face {f} uses edge {} of {}", u.edge, brep.edges.len());
            };
            // An analytic edge lies on analytic or planar faces only: its 3-D curve alone
            // (the model's pcurves are on its NURBS parameter).
            let analytic = brep.edges[u.edge].analytic.is_some();
            if let (Some(p), false) = (&u.pcurve, analytic) {
                edge.push((f, p));
            }
        }
    }
    let mut edges = Vec::with_capacity(brep.edges.len());
    for (e, edge) in brep.edges.iter().enumerate() {
        let (Some(&start), Some(&end)) = (vertices.get(edge.start), vertices.get(edge.end)) else {
            return invalid!("edge {e} joins vertices that do not exist");
        };
        if edge.degenerate {
            // No entity: its uses are left out of the loops below.
            edges.push(0);
            continue;
        }
        let curve = match &edge.analytic {
            Some(analytic) => analytic_curve_entity(&mut out, &analytic.curve),
            None => curve_entity(&mut out, &edge.curve),
        };
        let on_faces: Vec<usize> = pcurves[e]
            .iter()
            .map(|&(f, p)| pcurve_entity(&mut out, surfaces[f], context_2d, p))
            .collect();
        let seam = pcurves[e].len() == 2 && pcurves[e][0].0 == pcurves[e][1].0;
        let geometry = if on_faces.is_empty() {
            curve
        } else {
            let kind = if seam { "SEAM_CURVE" } else { "SURFACE_CURVE" };
            out.add(format!(
                "{kind}('',#{curve},{},.PCURVE_S1.)",
                refs(&on_faces)
            ))
        };
        edges.push(out.add(format!("EDGE_CURVE('',#{start},#{end},#{geometry},.T.)")));
    }
    // A closed B-rep of several shells is a solid with cavities: the shell reaching
    // farthest bounds it, the others are voids, written (as OpenCascade writes them) as
    // closed shells of the faces turned over, each used the other way round
    // (`ORIENTED_CLOSED_SHELL` .F.): the faces still face out of the material.
    let shells = brep.shells();
    let outer = outermost(brep, &shells);
    let mut turned = vec![false; brep.faces.len()];
    if brep.closed {
        for (s, faces) in shells.iter().enumerate() {
            if s != outer {
                faces.iter().for_each(|&f| turned[f] = true);
            }
        }
    }
    let faces: Vec<usize> = brep
        .faces
        .iter()
        .zip(&surfaces)
        .zip(&turned)
        .map(|((face, &surface), &turned)| {
            let bounds: Vec<usize> = face
                .bounds
                .iter()
                .map(|bound| {
                    let uses: Vec<usize> = bound
                        .uses
                        .iter()
                        .filter(|u| !brep.edges[u.edge].degenerate)
                        .map(|u| {
                            out.add(format!(
                                "ORIENTED_EDGE('',*,*,#{},{})",
                                edges[u.edge],
                                flag(u.forward)
                            ))
                        })
                        .collect();
                    let edge_loop = out.add(format!("EDGE_LOOP('',{})", refs(&uses)));
                    let kind = if bound.outer {
                        "FACE_OUTER_BOUND"
                    } else {
                        "FACE_BOUND"
                    };
                    out.add(format!("{kind}('',#{edge_loop},{})", flag(!turned)))
                })
                .collect();
            let same_sense = face
                .analytic
                .as_ref()
                .map_or(face.same_sense, |a| a.same_sense);
            out.add(format!(
                "ADVANCED_FACE('',{},#{surface},{})",
                refs(&bounds),
                flag(same_sense != turned)
            ))
        })
        .collect();
    let shell_faces = |s: usize| -> Vec<usize> { shells[s].iter().map(|&f| faces[f]).collect() };
    let representation = if brep.closed {
        let shell = out.add(format!("CLOSED_SHELL('',{})", refs(&shell_faces(outer))));
        let voids: Vec<usize> = (0..shells.len())
            .filter(|&s| s != outer)
            .map(|s| {
                let closed = out.add(format!("CLOSED_SHELL('',{})", refs(&shell_faces(s))));
                out.add(format!("ORIENTED_CLOSED_SHELL('',*,#{closed},.F.)"))
            })
            .collect();
        let solid = if voids.is_empty() {
            out.add(format!("MANIFOLD_SOLID_BREP('',#{shell})"))
        } else {
            out.add(format!("BREP_WITH_VOIDS('',#{shell},{})", refs(&voids)))
        };
        format!(
            "ADVANCED_BREP_SHAPE_REPRESENTATION('{}',(#{placement},#{solid}),#{context})",
            string(name)
        )
    } else {
        let open: Vec<usize> = (0..shells.len())
            .map(|s| out.add(format!("OPEN_SHELL('',{})", refs(&shell_faces(s)))))
            .collect();
        let model = out.add(format!("SHELL_BASED_SURFACE_MODEL('',{})", refs(&open)));
        format!(
            "MANIFOLD_SURFACE_SHAPE_REPRESENTATION('{}',(#{placement},#{model}),#{context})",
            string(name)
        )
    };
    represent(&mut out, shape, representation);
    Ok(exchange_structure(&out, name))
}

/// The shell reaching farthest: the largest box about the vertices of its faces' edges (the
/// outer shell of a solid with cavities).
fn outermost(brep: &Brep, shells: &[Vec<usize>]) -> usize {
    let diagonal = |faces: &Vec<usize>| {
        bounding_diagonal(faces.iter().flat_map(|&f| {
            brep.faces[f]
                .bounds
                .iter()
                .flat_map(|b| &b.uses)
                .map(|u| brep.vertices[brep.edges[u.edge].start])
        }))
    };
    (0..shells.len())
        .max_by(|&a, &b| diagonal(&shells[a]).total_cmp(&diagonal(&shells[b])))
        .unwrap_or(0)
}

/// A STEP file holding `curves` in one geometric curve set, the product called `name`.
pub fn curves_to_step(curves: &[&NurbsCurve], name: &str) -> Result<String> {
    if curves.is_empty() {
        return invalid!("a STEP file needs at least one curve");
    }
    let mut out = Entities { lines: Vec::new() };
    let (shape, context) = product_and_context(&mut out, name);
    let ids: Vec<usize> = curves.iter().map(|c| curve_entity(&mut out, c)).collect();
    let set = out.add(format!("GEOMETRIC_CURVE_SET('',{})", refs(&ids)));
    let representation = format!(
        "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('{}',(#{set}),#{context})",
        string(name)
    );
    represent(&mut out, shape, representation);
    Ok(exchange_structure(&out, name))
}

/// A STEP file holding a flat pattern as one planar face in z = 0 (`PLANE`, bounded by
/// `LINE` and `CIRCLE` edges, the outline counter-clockwise about +z, the holes inner
/// bounds), the product called `name`. The bend lines are not part of the face (the DXF and SVG files carry them).
pub fn flat_to_step(pattern: &FlatPattern, name: &str) -> Result<String> {
    let outline = &pattern.outline;
    if outline.is_empty() {
        return invalid!("a flat pattern needs at least one edge");
    }
    let mut out = Entities { lines: Vec::new() };
    let (shape, context) = product_and_context(&mut out, name);
    let origin = out.point(DVec3::ZERO);
    let z = out.add("DIRECTION('',(0.,0.,1.))");
    let x = out.add("DIRECTION('',(1.,0.,0.))");
    let placement = out.add(format!("AXIS2_PLACEMENT_3D('',#{origin},#{z},#{x})"));
    let plane = out.add(format!("PLANE('',#{placement})"));
    let edge_loop = flat_loop(&mut out, outline, z, x);
    let bound = out.add(format!("FACE_OUTER_BOUND('',#{edge_loop},.T.)"));
    let mut bounds = vec![bound];
    for hole in pattern.holes.iter().filter(|h| !h.is_empty()) {
        let edge_loop = flat_loop(&mut out, hole, z, x);
        bounds.push(out.add(format!("FACE_BOUND('',#{edge_loop},.T.)")));
    }
    let face = out.add(format!("ADVANCED_FACE('',{},#{plane},.T.)", refs(&bounds)));
    let shell = out.add(format!("OPEN_SHELL('',(#{face}))"));
    let model = out.add(format!("SHELL_BASED_SURFACE_MODEL('',(#{shell}))"));
    let representation = format!(
        "MANIFOLD_SURFACE_SHAPE_REPRESENTATION('{}',(#{placement},#{model}),#{context})",
        string(name)
    );
    represent(&mut out, shape, representation);
    Ok(exchange_structure(&out, name))
}

/// A closed loop of lines and arcs in z = 0 as an `EDGE_LOOP` (`z`, `x`: the plane's
/// directions); returns its id.
fn flat_loop(out: &mut Entities, edges: &[PatternEdge], z: usize, x: usize) -> usize {
    let lift = |p: glam::DVec2| p.extend(0.0);
    let vertices: Vec<usize> = edges
        .iter()
        .map(|e| {
            let point = out.point(lift(e.start()));
            out.add(format!("VERTEX_POINT('',#{point})"))
        })
        .collect();
    let mut loop_edges = Vec::new();
    for (k, edge) in edges.iter().enumerate() {
        let (start, end) = (vertices[k], vertices[(k + 1) % vertices.len()]);
        let (geometry, same) = match *edge {
            PatternEdge::Line { from, to } => {
                let d = to - from;
                let p = out.point(lift(from));
                let direction = out.add(format!(
                    "DIRECTION('',({},{},0.))",
                    real(d.x / d.length()),
                    real(d.y / d.length())
                ));
                let vector = out.add(format!("VECTOR('',#{direction},{})", real(d.length())));
                (out.add(format!("LINE('',#{p},#{vector})")), true)
            }
            PatternEdge::Arc {
                center,
                radius,
                sweep,
                ..
            } => {
                let c = out.point(lift(center));
                let axis = out.add(format!("AXIS2_PLACEMENT_3D('',#{c},#{z},#{x})"));
                // A CIRCLE runs counter-clockwise about +z: clockwise arcs run against it.
                (
                    out.add(format!("CIRCLE('',#{axis},{})", real(radius))),
                    sweep > 0.0,
                )
            }
        };
        let flag = if same { ".T." } else { ".F." };
        let e = out.add(format!("EDGE_CURVE('',#{start},#{end},#{geometry},{flag})"));
        loop_edges.push(out.add(format!("ORIENTED_EDGE('',*,*,#{e},.T.)")));
    }
    out.add(format!("EDGE_LOOP('',{})", refs(&loop_edges)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quarter cylinder (closed in neither direction) and a full one (closed in u).
    fn cylinder(full: bool) -> NurbsSurface {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let mut ring = vec![
            (DVec3::X, 1.0),
            (DVec3::new(1.0, 1.0, 0.0), s),
            (DVec3::Y, 1.0),
        ];
        let mut knots_u = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        if full {
            ring.extend([
                (DVec3::new(-1.0, 1.0, 0.0), s),
                (-DVec3::X, 1.0),
                (DVec3::new(-1.0, -1.0, 0.0), s),
                (-DVec3::Y, 1.0),
                (DVec3::new(1.0, -1.0, 0.0), s),
                (DVec3::X, 1.0),
            ]);
            knots_u = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];
        }
        let (mut poles, mut weights) = (Vec::new(), Vec::new());
        for (p, w) in &ring {
            for z in [0.0, 2.0] {
                poles.push(*p + DVec3::Z * z);
                weights.push(*w);
            }
        }
        let n = ring.len();
        NurbsSurface::new(
            2,
            1,
            n,
            2,
            poles,
            Some(weights),
            knots_u,
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap()
    }

    #[test]
    fn reals_have_a_decimal_point_and_round_trip() {
        for x in [
            0.0,
            1.0,
            -2.5,
            1e-7,
            1.5e300,
            0.1,
            std::f64::consts::PI,
            -3e-310,
        ] {
            let s = real(x);
            assert!(s.contains('.'), "{s}");
            assert_eq!(s.parse::<f64>().unwrap(), x, "{s}");
        }
        assert_eq!(real(1e-7), "1.E-7");
        assert_eq!(string("it's a\\b, ü"), "it''s a\\\\b, _");
        assert_eq!(
            knots_and_multiplicities(&[0.0, 0.0, 0.5, 1.0, 1.0]).1,
            vec![2, 1, 2]
        );
    }

    #[test]
    fn an_open_surface_has_four_edges_and_a_closed_one_a_seam() {
        let open = surfaces_to_step(&[&cylinder(false)], "quarter").unwrap();
        assert_eq!(open.matches("EDGE_CURVE(").count(), 4);
        assert_eq!(open.matches("ORIENTED_EDGE(").count(), 4);
        assert_eq!(open.matches("VERTEX_POINT(").count(), 4);
        assert!(!open.contains("SEAM_CURVE"));
        assert!(open.contains("RATIONAL_B_SPLINE_SURFACE(((1.0,1.0),(0.7071067811865476,0.7071067811865476),(1.0,1.0)))"));
        let closed = surfaces_to_step(&[&cylinder(true)], "tube").unwrap();
        assert_eq!(closed.matches("EDGE_CURVE(").count(), 3);
        assert_eq!(closed.matches("ORIENTED_EDGE(").count(), 4);
        assert_eq!(closed.matches("SEAM_CURVE(").count(), 1);
        assert_eq!(closed.matches("VERTEX_POINT(").count(), 2);
        // Every reference points at an entity that exists.
        let count = closed.matches("\n#").count();
        for (k, _) in closed.match_indices('#') {
            let digits: String = closed[k + 1..]
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            if let Ok(id) = digits.parse::<usize>() {
                assert!(id >= 1 && id <= count, "#{id} of {count}");
            }
        }
        assert!(surfaces_to_step(&[], "none").is_err());
    }

    #[test]
    fn curves_go_into_a_curve_set() {
        let c = NurbsCurve::new(
            2,
            vec![DVec3::ZERO, DVec3::X, DVec3::ONE],
            Some(vec![1.0, 0.5, 1.0]),
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        )
        .unwrap();
        let step = curves_to_step(&[&c, &c], "spine").unwrap();
        assert!(step.contains("GEOMETRIC_CURVE_SET('',(#"));
        assert_eq!(
            step.matches("RATIONAL_B_SPLINE_CURVE((1.0,0.5,1.0))")
                .count(),
            2
        );
        assert!(step.contains("B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.0,1.0),.UNSPECIFIED.)"));
    }
}
