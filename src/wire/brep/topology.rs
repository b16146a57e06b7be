//! The topology of a wire sweep: vertices and edges shared by the faces, with a pcurve on
//! each face, and oriented loops (the notes of the parent module: stations, section and
//! spine edges, the faces' senses).

use super::*;
use crate::math::{robust_length, robust_normalize};
use crate::model::{AnalyticCurve, AnalyticEdge, AnalyticFace, AnalyticSurface, ROUNDING};

/// Vertices and edges shared by the faces (module notes).
pub(super) struct Topology<'a> {
    pub(super) vertices: Vec<DVec3>,
    pub(super) edges: Vec<BrepEdge>,
    /// Section edges [station][loop][edge] (a closed wire has no station M of its own).
    sections: Vec<Vec<Vec<usize>>>,
    /// Spine edges [piece][loop][vertex].
    spines: Vec<Vec<Vec<usize>>>,
    images: Option<&'a Vec<Vec<EdgeImage>>>,
    profile: &'a Profile,
    stations: usize,
}

impl<'a> Topology<'a> {
    pub(super) fn new(
        transport: &Transport,
        profile: &'a Profile,
        nurbs: &[Vec<Vec<NurbsSurface>>],
        images: Option<&'a Vec<Vec<EdgeImage>>>,
    ) -> Self {
        let m = transport.pieces.len();
        let stations = if transport.closed { m } else { m + 1 };
        // Vertices and spine edges per station: the profile's vertices.
        let per_station: usize = profile
            .loops
            .iter()
            .map(|lp| lp.edges.len() + usize::from(!lp.closed))
            .sum();
        let mut t = Topology {
            vertices: Vec::with_capacity(stations * per_station),
            edges: Vec::with_capacity(stations * profile.edge_count() + m * per_station),
            sections: Vec::with_capacity(stations),
            spines: Vec::with_capacity(m),
            images,
            profile,
            stations,
        };
        // Vertices [station][loop][vertex].
        let mut vertex: Vec<Vec<Vec<usize>>> = Vec::with_capacity(stations);
        for k in 0..stations {
            let mut loops = Vec::with_capacity(profile.loops.len());
            for (l, lp) in profile.loops.iter().enumerate() {
                let count = lp.edges.len() + usize::from(!lp.closed);
                let ids = (0..count)
                    .map(|v| {
                        let (face, at_end) = if k < m {
                            (&nurbs[k][l], false)
                        } else {
                            (&nurbs[m - 1][l], true)
                        };
                        let (e, last_u) = if v < lp.edges.len() {
                            (v, false)
                        } else {
                            (v - 1, true)
                        };
                        let s = &face[e];
                        let i = if last_u { s.pole_count_u - 1 } else { 0 };
                        let j = if at_end { s.pole_count_v - 1 } else { 0 };
                        t.vertices.push(s.poles[i * s.pole_count_v + j]);
                        t.vertices.len() - 1
                    })
                    .collect();
                loops.push(ids);
            }
            vertex.push(loops);
        }
        let vertex_at = |k: usize, l: usize, v: usize| -> usize {
            if k < stations {
                return vertex[k][l][v];
            }
            // A closed wire's station M: the image of the vertex at station 0.
            let lp = &profile.loops[l];
            match images {
                Some(images) if v < lp.edges.len() => {
                    let (l2, e2, _) = images[l][v];
                    vertex[0][l2][e2]
                }
                _ => vertex[0][l][v],
            }
        };
        // Section edges.
        for k in 0..stations {
            let mut loops = Vec::with_capacity(profile.loops.len());
            for (l, lp) in profile.loops.iter().enumerate() {
                let n = lp.edges.len();
                let ids = (0..n)
                    .map(|e| {
                        let (s, side) = if k < m {
                            (&nurbs[k][l][e], 0)
                        } else {
                            (&nurbs[m - 1][l][e], 2)
                        };
                        let curve = s.boundary_curve(side);
                        let next = if lp.closed { (e + 1) % n } else { e + 1 };
                        t.edges
                            .push(edge(curve, vertex[k][l][e], vertex[k][l][next]));
                        t.edges.len() - 1
                    })
                    .collect();
                loops.push(ids);
            }
            t.sections.push(loops);
        }
        // Spine edges.
        for (j, faces) in nurbs.iter().enumerate().take(m) {
            let mut loops = Vec::with_capacity(profile.loops.len());
            for (l, lp) in profile.loops.iter().enumerate() {
                let n = lp.edges.len();
                let count = n + usize::from(!lp.closed);
                let ids = (0..count)
                    .map(|v| {
                        let (s, side) = if v < n {
                            (&faces[l][v], 3)
                        } else {
                            (&faces[l][n - 1], 1)
                        };
                        t.edges.push(edge(
                            s.boundary_curve(side),
                            vertex_at(j, l, v),
                            vertex_at(j + 1, l, v),
                        ));
                        t.edges.len() - 1
                    })
                    .collect();
                loops.push(ids);
            }
            t.spines.push(loops);
        }
        t
    }

    /// The lateral face (j, l, e): its four sides counter-clockwise in (u, v); `axis` the
    /// spine piece's line or arc where the face is a profile edge swept along it untwisted
    /// and unscaled (then a circle sweeps a cylinder or torus: [`analytic_face`]).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn lateral_face(
        &mut self,
        j: usize,
        l: usize,
        e: usize,
        s: NurbsSurface,
        same_sense: bool,
        axis: Option<SpineAxis>,
        surface: &PiecewiseSurface,
    ) -> BrepFace {
        let analytic = axis.and_then(|axis| {
            let section = self.edges[self.sections[j][l][e]].analytic?;
            analytic_face(axis, &section, surface, same_sense)
        });
        let lp = &self.profile.loops[l];
        let n = lp.edges.len();
        let next = if lp.closed { (e + 1) % n } else { e + 1 };
        let sides = [0, 1, 2, 3].map(|k| s.boundary_line(k));
        let line = |k: usize| {
            let (u, v) = sides[k].0;
            if k % 2 == 1 {
                spine_pcurve(u, &s.knots_v)
            } else {
                PCurve::Line {
                    origin: (u, v),
                    direction: sides[k].1,
                }
            }
        };
        let (top_edge, shift) = if j + 1 < self.stations {
            (self.sections[j + 1][l][e], 0.0)
        } else {
            match self.images {
                Some(images) => {
                    let (l2, e2, shift) = images[l][e];
                    (self.sections[0][l2][e2], shift)
                }
                None => (self.sections[0][l][e], 0.0),
            }
        };
        let top = PCurve::Line {
            origin: (sides[2].0 .0 - shift, sides[2].0 .1),
            direction: sides[2].1,
        };
        let uses = vec![
            BrepUse {
                edge: self.sections[j][l][e],
                forward: true,
                pcurve: Some(line(0)),
            },
            BrepUse {
                edge: self.spines[j][l][next],
                forward: true,
                pcurve: Some(line(1)),
            },
            BrepUse {
                edge: top_edge,
                forward: false,
                pcurve: Some(top),
            },
            BrepUse {
                edge: self.spines[j][l][e],
                forward: false,
                pcurve: Some(line(3)),
            },
        ];
        BrepFace {
            surface: BrepSurface::Nurbs(s),
            same_sense,
            bounds: vec![BrepBound { uses, outer: true }],
            analytic,
        }
    }

    /// The cap at the start (`end` false) or the end of an open wire.
    pub(super) fn cap(
        &mut self,
        end: bool,
        transport: &Transport,
        profile: &Profile,
        placement: Similarity,
        sigma: f64,
    ) -> Result<(Face, BrepFace)> {
        let m = transport.pieces.len();
        let (station, framed) = if end {
            (m, &transport.pieces[m - 1])
        } else {
            (0, &transport.pieces[0])
        };
        let frame = if end { framed.end } else { framed.start };
        let spine_point = if end {
            framed.piece.geometry.end()
        } else {
            framed.piece.geometry.start()
        };
        // The cap lies in the profile's plane m·c = offset carried by the frame (the normal
        // plane: m = z, offset 0), its outward normal ∓m; axes x = f₂ projected onto it,
        // y = normal × x, in the profile's coordinates (x along f₂, y along f₃, z along t).
        let (m, offset) = profile
            .plane
            .map_or((DVec3::Z, 0.0), |p| (p.normal, p.offset));
        let outward = if end { m } else { -m };
        let x_axis = (DVec3::X - m.x * m).normalize();
        let y_axis = outward.cross(x_axis);
        let world = |c: DVec3| frame.f2 * c.x + frame.f3 * c.y + frame.tangent * c.z;
        let normal = world(outward);
        let origin = spine_point + world(m * (offset * sigma));
        let mut bounds = Vec::new();
        let mut loops = Vec::new();
        for (l, lp) in profile.loops.iter().enumerate() {
            let counter_clockwise = lp.area > 0.0;
            // Outer loops run counter-clockwise about the outward normal, holes clockwise;
            // the normal is f₂ × f₃ at the end and its opposite at the start.
            let forward = (l == 0) == (counter_clockwise == end);
            let mut uses: Vec<BrepUse> = lp
                .edges
                .iter()
                .enumerate()
                .map(|(e, edge)| BrepUse {
                    edge: self.sections[station][l][e],
                    forward,
                    pcurve: Some(PCurve::Curve(planar_pcurve(
                        edge,
                        placement.scale * sigma,
                        (x_axis, y_axis),
                    ))),
                })
                .collect();
            if !forward {
                uses.reverse();
            }
            loops.push(loop_curve(&uses, &self.edges)?);
            bounds.push(BrepBound {
                uses,
                outer: l == 0,
            });
        }
        let origin = placement.to_user(origin);
        let face = Face {
            kind: FaceKind::Plane,
            surface: None,
            plane: Some((origin, normal)),
            loops,
            spine_edge: framed.piece.edge,
            profile_edge: 0,
            profile_loop: 0,
            round_corner: false,
            reversed: false,
        };
        let brep = BrepFace {
            surface: BrepSurface::Plane {
                origin,
                normal,
                x_axis: world(x_axis),
            },
            same_sense: true,
            bounds,
            analytic: None,
        };
        Ok((face, brep))
    }
}

/// The sine of the angle within which directions count as parallel (or perpendicular) when
/// a face is taken for a cylinder, torus, cone or plane: the face then lies within 1e-10 of
/// its size of that surface.
const PARALLEL: f64 = 1e-10;

/// An edge of the sweep, with the line or circle its curve is.
fn edge(curve: NurbsCurve, start: usize, end: usize) -> BrepEdge {
    BrepEdge {
        analytic: AnalyticEdge::of_curve(&curve),
        curve,
        start,
        end,
        degenerate: false,
    }
}

/// The line or arc of a spine piece swept untwisted and unscaled, in the caller's
/// coordinates: its unit direction, or its centre, unit normal and angle.
#[derive(Clone, Copy, Debug)]
pub(super) enum SpineAxis {
    Line(DVec3),
    Arc {
        center: DVec3,
        normal: DVec3,
        angle: f64,
    },
}

/// The analytic surface of a lateral face whose profile edge (its `section` at the piece's
/// start) is a circle or a line: a circle in the normal plane of a line sweeps a cylinder,
/// one in a plane through an arc's axis a torus (the frame along an untwisted arc is the
/// arc's rotation); a line along a line sweeps a plane, along an arc a cone, cylinder or
/// annulus ([`revolved_line`]). `None` for other faces (a circle drawn
/// out of the normal plane sweeps an elliptic cylinder), and for tori the kernel would not
/// take as one (the tube reaching the axis, an arc of a whole turn).
fn analytic_face(
    axis: SpineAxis,
    section: &AnalyticEdge,
    surface: &PiecewiseSurface,
    same_sense: bool,
) -> Option<AnalyticFace> {
    let analytic = match (axis, section.curve) {
        (
            SpineAxis::Line(direction),
            AnalyticCurve::Circle {
                center,
                axis,
                x_axis,
                radius,
            },
        ) => {
            (axis.dot(direction).abs() >= 1.0 - PARALLEL).then_some(AnalyticSurface::Cylinder {
                origin: center,
                axis: direction,
                x_axis,
                radius,
            })?
        }
        (
            SpineAxis::Line(direction),
            AnalyticCurve::Line {
                origin,
                direction: along,
            },
        ) => {
            let normal = along.cross(direction);
            (normal.length() > PARALLEL).then_some(AnalyticSurface::Plane {
                origin,
                normal: normal.normalize(),
                x_axis: along,
            })?
        }
        (
            SpineAxis::Arc {
                center: c,
                normal,
                angle,
            },
            AnalyticCurve::Circle {
                center,
                axis,
                radius,
                ..
            },
        ) => {
            let offset = center - c;
            let height = offset.dot(normal);
            let radial = offset - normal * height;
            let major = robust_length(radial);
            // The circle's axis carries the rounding of its coordinates over its radius.
            let slack = PARALLEL + ROUNDING * center.abs().max_element() / radius;
            let meridian = axis.dot(normal).abs() <= slack
                && offset.dot(axis).abs() <= slack * (major + radius);
            (meridian && major > radius * (1.0 + 1e-9) && angle < 1.9 * std::f64::consts::PI)
                .then_some(AnalyticSurface::Torus {
                    center: c + normal * height,
                    axis: normal,
                    x_axis: radial / major,
                    major,
                    minor: radius,
                })?
        }
        (
            SpineAxis::Arc {
                center,
                normal,
                angle,
            },
            AnalyticCurve::Line { origin, direction },
        ) => revolved_line(center, normal, origin, direction, section.end)
            .filter(|_| angle < 1.9 * std::f64::consts::PI)?,
    };
    // The face's sense on the analytic surface: the NURBS normal against the analytic one
    // at the middle of the first patch.
    let jet = surface.patches().first()?.eval_jet(0.5, 0.5);
    let normal = robust_normalize(jet.du)?.cross(robust_normalize(jet.dv)?);
    let along = normal.dot(analytic.normal(jet.point)) > 0.0;
    Some(AnalyticFace {
        surface: analytic,
        same_sense: same_sense == along,
        pcurves: Vec::new(),
    })
}

/// The surface a profile line sweeps about an arc's axis: in a plane through the axis (the
/// normal plane of an untwisted arc), a cone, or a cylinder where it runs along the axis, an
/// annulus where it runs across it. `None` for a line out of such a plane or reaching the
/// axis.
fn revolved_line(
    center: DVec3,
    normal: DVec3,
    origin: DVec3,
    direction: DVec3,
    length: f64,
) -> Option<AnalyticSurface> {
    let offset = origin - center;
    let height = offset.dot(normal);
    let radial = offset - normal * height;
    let rho = robust_length(radial);
    if rho.is_nan() || rho <= 0.0 {
        return None;
    }
    let out = radial / rho;
    // The line's points carry the rounding of their coordinates over its length.
    let slack = PARALLEL + ROUNDING * origin.abs().max_element() / length;
    let (d_rho, d_h) = (direction.dot(out), direction.dot(normal));
    let in_meridian = direction.dot(normal.cross(out)).abs() <= slack;
    if !in_meridian || rho + d_rho * length <= 0.0 {
        return None;
    }
    let base = center + normal * height;
    Some(if d_h.abs() <= slack {
        AnalyticSurface::Plane {
            origin,
            normal,
            x_axis: out,
        }
    } else if d_rho.abs() <= slack {
        AnalyticSurface::Cylinder {
            origin: base,
            axis: normal,
            x_axis: out,
            radius: rho,
        }
    } else {
        // Rulings up the axis: |α| < π/2.
        let (s_rho, s_h) = if d_h > 0.0 {
            (d_rho, d_h)
        } else {
            (-d_rho, -d_h)
        };
        AnalyticSurface::Cone {
            origin: base,
            axis: normal,
            x_axis: out,
            radius: rho,
            semi_angle: s_rho.atan2(s_h),
        }
    })
}

/// The parameter line u = const of a spine edge: a `LINE`, or for a face of several spans
/// along the spine the same line as a degree-1 B-spline with knots at the spans, so that
/// OpenCascade's adaptive integration (BRepGProp with a tolerance) splits there.
pub(super) fn spine_pcurve(u: f64, knots_v: &[f64]) -> PCurve {
    // One span (the clamped ends only): a line, without building the breaks.
    if knots_v.windows(2).filter(|w| w[0] != w[1]).count() == 1 {
        return PCurve::Line {
            origin: (u, 0.0),
            direction: (0.0, 1.0),
        };
    }
    let mut breaks = knots_v.to_vec();
    breaks.dedup();
    let mut knots = vec![breaks[0]];
    knots.extend_from_slice(&breaks);
    knots.push(breaks[breaks.len() - 1]);
    let poles = breaks.iter().map(|&v| DVec3::new(u, v, 0.0)).collect();
    PCurve::Curve(NurbsCurve::new(1, poles, None, knots).expect("increasing breaks"))
}

/// A profile edge as a curve in the cap's plane coordinates (`axes`, in the profile's
/// coordinates: in the normal plane x along f₂ and y along the normal × f₂, f₃ at the
/// end, −f₃ at the start), in the caller's units.
pub(super) fn planar_pcurve(
    edge: &PiecewiseCurve,
    scale: f64,
    (x, y): (DVec3, DVec3),
) -> NurbsCurve {
    let segments = edge
        .segments()
        .iter()
        .map(|s| {
            let h = s
                .homogeneous()
                .iter()
                .map(|h| {
                    let c = h.truncate() * scale;
                    DVec4::new(c.dot(x), c.dot(y), 0.0, h.w)
                })
                .collect();
            RationalBezierCurve::from_homogeneous(h).expect("finite")
        })
        .collect();
    let curve = PiecewiseCurve::new(segments, edge.breaks().to_vec()).expect("same breaks");
    NurbsCurve::from_piecewise(&curve).expect("a continuous profile edge")
}

/// The closed 3-D curve of a cap's bound: its edges' curves in the order and direction of
/// the uses.
pub(super) fn loop_curve(uses: &[BrepUse], edges: &[BrepEdge]) -> Result<PiecewiseCurve> {
    let mut segments: Vec<RationalBezierCurve> = Vec::new();
    let mut breaks = vec![0.0];
    for u in uses {
        let piece = edges[u.edge].curve.to_piecewise()?;
        let piece = if u.forward { piece } else { piece.reversed() };
        let (lo, _) = piece.domain();
        let offset = breaks[breaks.len() - 1] - lo;
        segments.extend_from_slice(piece.segments());
        breaks.extend(piece.breaks()[1..].iter().map(|b| b + offset));
    }
    PiecewiseCurve::new(segments, breaks)
}
