//! The B-rep of a wire sweep: its faces, their shared edges and vertices, and how each
//! face is oriented.
//!
//! Faces. For every spine piece and every profile edge one lateral face, the sweep
//! s(u, v) = x(v) + c₂(u) f₂(v) + c₃(u) f₃(v) (Mäurer & Jüttler (1), u along the profile
//! edge, v along the piece) as an exact rational surface:
//! * along an untwisted line, the ruled patch between its two end sections — of degree
//!   (m, 1), a cylinder patch for a circle; a miter plane at an end replaces that section by
//!   its parallel projection along the line onto the plane, c ↦ x + c₂f₂ + c₃f₃ + (c·q) t,
//!   which is linear in c and so keeps the profile's weights;
//! * along an untwisted arc, with the frame of `frame` over the arc's own weights w,
//!   S = h ⊗ (X, w) + C₂ ⊗ (F₂, 0) + C₃ ⊗ (F₃, 0): degree (m, 2), an exact torus patch;
//! * along PH pieces and twisted lines and arcs, the general rational sweep (42) of
//!   [`crate::sweep`].
//!
//! An open wire gets a planar cap at each end, bounded by the profile's loops there.
//!
//! The report's max |cos| between parameter lines is measured when the report is first
//! asked for (a diagnostic the construction does not need: a third of a helix's build), on
//! the surfaces as built, on the lines u = i/8 of every patch: along the lines and arcs
//! (degree ≤ 2 in v) as a bound over the whole line from the Bernstein coefficients of
//! polynomials in v (see `line_cosine_bound`), which costs less than sampling and misses
//! nothing between samples; along PH pieces (degree 9) by 9 samples per line.
//!
//! Topology. Stations k = 0 … M separate the M pieces (a closed wire's station M is station
//! 0, its profile edges turned onto one another by the closing turn). Section edges lie at
//! the stations (one per profile edge), spine edges along the pieces (one per profile
//! vertex, the profile's G0 corners and the start of a smooth closed loop, which is the
//! seam of its faces). In its parameter plane every lateral face runs counter-clockwise
//! along v = v₀, u = u₁, v = v₁, u = u₀; its normal s_u × s_v points out of the solid for an
//! outer loop turning counter-clockwise in (f₂, f₃) and for a hole turning clockwise (else
//! the face is marked reversed). Caps are bounded counter-clockwise about their outward
//! normal (holes clockwise), so every edge is used once in each direction.

use super::blend::{combined, Blends};
use super::clearance::{self_contact, Contact, Tubes};
use super::edge::Geometry;
use super::frame::{arc_numerators, Margins, PieceFrame, Transport, CLOSURE_ROUND_OFF};
use super::profile::{EdgeImage, Profile};
use super::scale::{PieceScale, ScaleLaw, SpineKind};
use crate::bezier::bernstein::{elevate, product};
use crate::bezier::{
    NurbsCurve, NurbsSurface, PiecewiseCurve, PiecewiseSurface, RationalBezierCurve,
    RationalBezierPatch,
};
use crate::error::{invalid, Error, Result};
use crate::frames::metrics::{angle_about_tangent, partials_cosine};
use crate::frames::Frame;
use crate::math::{binomial, GaussLegendre};
use crate::mesh::grid_parameters;
use crate::model::Similarity;
use crate::model::{
    settle_analytic, Brep, BrepBound, BrepEdge, BrepFace, BrepSurface, BrepUse, PCurve,
};
use crate::ph_cubic::accuracy::AngleCheck;
use crate::sweep::{sweep_profile, SweepProfile};
use glam::{DVec3, DVec4};
use std::sync::OnceLock;

mod cosine;
mod merge;
mod topology;

use cosine::{max_parameter_cosine, CosineBases, Section, COSINE_SAMPLES};
use topology::Topology;

/// Gauss–Legendre nodes per patch and direction for [`Shape::volume`].
const VOLUME_NODES: usize = 24;

/// What a face of a [`Shape`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaceKind {
    /// A lateral face: a profile edge swept along a spine piece.
    Swept,
    /// A planar cap at an end of an open wire.
    Plane,
}

/// One face of a [`Shape`].
#[derive(Clone, Debug)]
pub struct Face {
    /// Lateral (swept) face or planar cap.
    pub kind: FaceKind,
    /// [`FaceKind::Swept`]: the exact rational surface (u along the profile edge, v along
    /// the spine).
    pub surface: Option<PiecewiseSurface>,
    /// [`FaceKind::Plane`]: a point of the cap's plane and its unit normal, pointing out of
    /// the solid.
    pub plane: Option<(DVec3, DVec3)>,
    /// [`FaceKind::Plane`]: the boundary loops as closed curves (outer first), counter-
    /// clockwise about the normal (holes clockwise).
    pub loops: Vec<PiecewiseCurve>,
    /// The edge of the wire the face lies along (for caps: the edge at that end).
    pub spine_edge: usize,
    /// The profile edge it sweeps (numbered over all loops, outer loop first).
    pub profile_edge: usize,
    /// 0 for the outer loop, 1 + h for hole h.
    pub profile_loop: usize,
    /// The elbow of a round corner after `spine_edge`.
    pub round_corner: bool,
    /// The face's outward normal is −(s_u × s_v).
    pub reversed: bool,
}

/// How accurate a wire sweep is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepReport {
    /// Largest distance between a curve edge and its PH cubic spline (0 when every edge is a
    /// line or an arc), in the wire's units.
    pub spine_distance: f64,
    /// Largest angle (radians) between the frames used and the exact RMF (plus the twist
    /// and closure turn, linear in arc length); 0 on untwisted lines and arcs, and on curve
    /// pieces a round profile is swept along on the Euler–Rodrigues frame
    /// ([`super::PipeFrame::Lightest`]: no frame changes its surface).
    pub rmf_angle_error: f64,
    /// Largest |cos| of the angle between the parameter lines of the lateral faces (0 on an
    /// exact RMF sweep, Mäurer & Jüttler (43)), measured on every patch on its 9 parameter
    /// lines u = i/8 along the spine: on patches of degree ≤ 2 along the spine (lines and
    /// arcs) a bound over each whole line (Bernstein coefficients of the polynomials of
    /// s_u·s_v, |s_u|², |s_v|²), on the others the largest of 9 samples on each line; miter
    /// legs, ruled between oblique sections, are not orthogonal.
    pub max_parameter_cosine: f64,
    /// The least singularity margin g = 1 − κ c·n over the sweep (Cor. 7; 1 where the spine
    /// is straight), and for miter legs 1 − (length of the cuts)/(length of the leg); > 0.
    pub singularity_margin: f64,
    /// Number of faces of [`Shape::faces`]: one per spine piece and profile edge, and the
    /// caps (the B-rep, [`Shape::brep`], joins a closed loop's faces on one cylinder or
    /// torus into one).
    pub face_count: usize,
    /// Largest turn of the frame about the tangent across a corner, against the minimal
    /// rotation of the tangent there (round corners: across the elbow; miters: across the
    /// miter plane), radians.
    pub corner_turn: f64,
    /// Closed wires: the largest distance between the sections where the wire closes (0
    /// for open wires), in the wire's units.
    pub seam_gap: f64,
    /// Largest angle (radians) between the frames used and the frame asked for
    /// ([`super::SweepFrame`]: the Frenet frame or the fixed direction's, each offset by the
    /// turn it kept where the curvature vanished or the normal jumped), sampled; 0 for the
    /// RMF.
    pub frame_error: f64,
    /// The largest distance between the sections of consecutive pieces at the joints
    /// inside the wire (0 at G1 joints up to rounding; ½θ²·r at near-tangent joints), in
    /// the wire's units.
    pub joint_gap: f64,
}

/// The result of a wire sweep: a closed solid or a sheet.
#[derive(Clone, Debug)]
pub struct Shape {
    faces: Vec<Face>,
    brep: Brep,
    solid: bool,
    /// The figures measured while building, without the parameter-line cosine.
    built: SweepReport,
    /// The whole report, made on first request.
    report: OnceLock<SweepReport>,
    /// The fold check's margins, some measured on request.
    margins: Margins,
    /// The comparisons of the frames along curve pieces with their exact RMFs, measured
    /// on request.
    angle_checks: Vec<AngleCheck>,
    /// The lateral surfaces in the coordinates they were built in, for the report's
    /// parameter-line cosine (measured on request as it would be at build time: the same
    /// figure at every scale and position; the caller's surfaces mapped back carry the
    /// rounding of the placement, which the sampled cosine of a twisted face amplifies to
    /// 1e-9).
    internal: Vec<PiecewiseSurface>,
    spine: Vec<PiecewiseCurve>,
    /// The map from the coordinates the sweep was built in to the caller's.
    placement: Similarity,
}

impl Shape {
    /// The faces: the lateral faces first, then the caps.
    pub fn faces(&self) -> &[Face] {
        &self.faces
    }

    /// Whether the faces bound a closed, consistently oriented solid.
    pub fn is_solid(&self) -> bool {
        self.solid
    }

    /// The accuracy figures of the sweep.
    ///
    /// The largest cosine between parameter lines, the angle between the frames and the
    /// exact RMF along curve pieces, and the singularity margin along curve pieces the
    /// construction knew to be positive from a bound, are measured when the report is
    /// first asked for.
    pub fn report(&self) -> &SweepReport {
        self.report.get_or_init(|| SweepReport {
            max_parameter_cosine: self.max_parameter_cosine(),
            singularity_margin: self.margins.least(),
            rmf_angle_error: self
                .angle_checks
                .iter()
                .map(|check| check.errors().max)
                .fold(self.built.rmf_angle_error, f64::max),
            ..self.built
        })
    }

    /// The report's largest cosine between parameter lines, on the surfaces as built.
    fn max_parameter_cosine(&self) -> f64 {
        let mut bases = CosineBases::new();
        self.internal
            .iter()
            .map(|s| max_parameter_cosine(s, &mut bases))
            .fold(0.0, f64::max)
    }

    /// The curves swept along, in order: the lines, arcs and round-corner elbows exactly,
    /// curve edges as their PH cubic splines.
    pub fn spine(&self) -> &[PiecewiseCurve] {
        &self.spine
    }

    /// The enclosed volume of a solid: ⅓ ∮ x·n dA by 24-point Gauss–Legendre quadrature on
    /// every patch and cap loop segment. The flux is taken about the wire's centre in units
    /// of its size (a power of two), so that it loses nothing to the wire's position and no
    /// square overflows; refused for a sheet, and for a volume outside the range of f64 (a
    /// wire 1e-200 long encloses about 1e-600).
    pub fn volume(&self) -> Result<f64> {
        if !self.solid {
            return invalid!("the shape is a sheet, not a solid: it encloses no volume");
        }
        let Similarity {
            scale,
            origin: offset,
        } = self.placement;
        let local = |p: DVec3| (p - offset) / scale;
        let rule = GaussLegendre::new(VOLUME_NODES);
        let flux: f64 = self
            .faces
            .iter()
            .map(|face| match (&face.surface, face.plane) {
                (Some(s), _) => {
                    let sign = if face.reversed { -1.0 } else { 1.0 };
                    sign * s
                        .patches()
                        .iter()
                        .map(|p| {
                            rule.integrate(0.0, 1.0, |u| {
                                rule.integrate(0.0, 1.0, |v| {
                                    let j = p.eval_jet(u, v);
                                    local(j.point).dot((j.du / scale).cross(j.dv / scale))
                                })
                            })
                        })
                        .sum::<f64>()
                }
                // ∫ x·n dA = (o·n)·area, the area by ½ ∮ ((x − o) × dx)·n over the loops.
                (None, Some((o, n))) => {
                    let area: f64 = face
                        .loops
                        .iter()
                        .flat_map(|l| l.segments())
                        .map(|seg| {
                            rule.integrate(0.0, 1.0, |t| {
                                let j = seg.eval_jet(t);
                                0.5 * ((j.point - o) / scale).cross(j.d1 / scale).dot(n)
                            })
                        })
                        .sum();
                    local(o).dot(n) * area
                }
                _ => 0.0,
            })
            .sum();
        let unit = flux / 3.0;
        let volume = unit * scale * scale * scale;
        if !volume.is_normal() && unit != 0.0 {
            return invalid!(
                "the volume {unit:.6e} × {scale:e}³ is outside the range of f64 (the solid is \
                 {scale:e} across)"
            );
        }
        Ok(volume)
    }

    /// The shape as a STEP AP214 file: a `MANIFOLD_SOLID_BREP` for a solid, an open shell
    /// otherwise; faces share their edges.
    pub fn to_step(&self, name: &str) -> Result<String> {
        crate::export::step::brep_to_step(&self.brep, name)
    }

    /// The shape in OpenCascade's own B-rep text (`BRepTools::Read`, FreeCAD's
    /// `Part.Shape.importBrepFromString`): the kernel builds it as it is, without sewing.
    pub fn to_occ_brep(&self) -> Result<String> {
        crate::export::occ_brep::brep_to_occ(&self.brep)
    }

    /// The shape in OpenCascade's binary B-rep (`BinTools::Read`, FreeCAD's
    /// `Part.Shape.importBinary`): the same shape as [`Self::to_occ_brep`], which a kernel
    /// reads several times faster.
    pub fn to_occ_binary(&self) -> Result<crate::export::occ_brep::OccBinary> {
        crate::export::occ_brep::brep_to_occ_binary(&self.brep)
    }

    /// The shape's boundary representation: vertices, shared edges with their curves on
    /// each face, oriented loops, faces with their senses (what the STEP and OpenCascade
    /// texts are written from). Where all faces of a closed profile loop along a piece lie
    /// on one cylinder or torus (a circle's arcs), they are one face there, with a seam.
    pub fn brep(&self) -> &Brep {
        &self.brep
    }
}

/// The lateral surface of one framed piece and one profile edge (module notes), in
/// normalized coordinates.
fn lateral(
    framed: &super::frame::Framed,
    edge: &PiecewiseCurve,
    scale: Option<&PieceScale>,
    tangential: bool,
) -> Result<PiecewiseSurface> {
    match (&framed.piece.geometry, &framed.frame) {
        (Geometry::Line { a, b }, PieceFrame::Constant { f2, f3 }) => {
            let t = framed.start.tangent;
            let (sa, sb) = scale.map_or((1.0, 1.0), PieceScale::ends);
            let section = |p: DVec3, miter: Option<(DVec3, DVec3)>, h: DVec4, k: f64| {
                let offset = (*f2 * h.x + *f3 * h.y + t * h.z) * k;
                let mut x = p * h.w + offset;
                if let Some((_, m)) = miter {
                    x -= t * (offset.dot(m) / t.dot(m));
                }
                x.extend(h.w)
            };
            let patches = edge
                .segments()
                .iter()
                .map(|seg| {
                    let mut points = Vec::with_capacity(2 * seg.homogeneous().len());
                    for &h in seg.homogeneous() {
                        points.push(section(*a, framed.miters[0], h, sa));
                        points.push(section(*b, framed.miters[1], h, sb));
                    }
                    RationalBezierPatch::from_homogeneous(seg.degree(), 1, points)
                })
                .collect::<Result<Vec<_>>>()?;
            PiecewiseSurface::new(patches, edge.breaks().to_vec(), vec![0.0, 1.0])
        }
        (Geometry::Arc(arc), PieceFrame::Circular { a, b }) => {
            let spine = &framed.spine;
            let mut patches = Vec::with_capacity(edge.segments().len() * spine.segments().len());
            // The frame of each spine segment, the same for every profile segment.
            let frames: Vec<_> = spine
                .segments()
                .iter()
                .map(|along| arc_numerators(arc, along, *a, *b))
                .collect();
            // The tangent over the arc's weights, T = n × (X − c w)/R (a profile drawn out
            // of the normal plane); with a scale law σ (linear on each segment): X
            // elevated, σF₂, σF₃, σT.
            let tangents = |along: &RationalBezierCurve| -> Vec<DVec3> {
                along
                    .homogeneous()
                    .iter()
                    .map(|x| arc.normal.cross(x.truncate() - arc.center * x.w) / arc.radius)
                    .collect()
            };
            type Factors = (Vec<DVec4>, Vec<DVec3>, Vec<DVec3>, Vec<DVec3>);
            let factors: Vec<Factors> = spine
                .segments()
                .iter()
                .zip(&frames)
                .zip(spine.breaks().windows(2))
                .map(|((along, frame), v)| {
                    let t = if tangential {
                        tangents(along)
                    } else {
                        vec![DVec3::ZERO; along.homogeneous().len()]
                    };
                    match scale {
                        None => (
                            along.homogeneous().to_vec(),
                            frame.e2.clone(),
                            frame.e3.clone(),
                            t,
                        ),
                        Some(scale) => {
                            let sigma = scale.on(v[0], v[1]);
                            let scaled = |n: &[DVec3]| product(&sigma, n, |s: f64, n: DVec3| n * s);
                            (
                                elevate(along.homogeneous(), sigma.len() - 1),
                                scaled(&frame.e2),
                                scaled(&frame.e3),
                                scaled(&t),
                            )
                        }
                    }
                })
                .collect();
            for seg in edge.segments() {
                for (x, e2, e3, e1) in &factors {
                    let mut points = Vec::with_capacity(seg.homogeneous().len() * x.len());
                    for &h in seg.homogeneous() {
                        for (l, xl) in x.iter().enumerate() {
                            points.push(
                                (xl.truncate() * h.w + e2[l] * h.x + e3[l] * h.y + e1[l] * h.z)
                                    .extend(h.w * xl.w),
                            );
                        }
                    }
                    patches.push(RationalBezierPatch::from_homogeneous(
                        seg.degree(),
                        x.len() - 1,
                        points,
                    )?);
                }
            }
            PiecewiseSurface::new(patches, edge.breaks().to_vec(), spine.breaks().to_vec())
        }
        (_, PieceFrame::Rational(frames)) => {
            let sigma = |v0: f64, v1: f64| scale.map_or(vec![1.0], |s| s.on(v0, v1));
            let how = SweepProfile {
                sigma: scale
                    .is_some()
                    .then_some(&sigma as &dyn Fn(f64, f64) -> Vec<f64>),
                tangential,
            };
            sweep_profile(&framed.spine, frames, edge, how)
        }
        _ => invalid!("internal: a frame that does not fit its piece"),
    }
}

/// The spines of the pieces on the v-breaks of their lateral surfaces (none for a leg cut
/// by a miter) and the profile's reach, which bound where the lateral patches lie.
fn tubes(
    transport: &Transport,
    profile: &Profile,
    largest_scale: f64,
    normalized: &[Vec<Vec<PiecewiseSurface>>],
) -> Tubes {
    let reach = largest_scale
        * profile
            .loops
            .iter()
            .flat_map(|lp| &lp.edges)
            .flat_map(|e| e.segments())
            .flat_map(|s| s.poles())
            .fold(0.0f64, |m, p| m.max(p.length()));
    let mut spines = Vec::with_capacity(transport.pieces.len());
    for (framed, loops) in transport.pieces.iter().zip(normalized) {
        let face = loops.iter().flatten().next();
        let spine = match face {
            Some(face) if framed.miters.iter().all(Option::is_none) => {
                framed.spine.refined(face.v_breaks()).ok()
            }
            _ => None,
        };
        spines.push(spine);
    }
    Tubes { spines, reach }
}

/// Builds the shape (in the caller's coordinates) from the framed pieces and the profile.
#[allow(clippy::too_many_arguments)]
pub(crate) fn build(
    transport: &Transport,
    profile: &Profile,
    blend: Option<&Blends>,
    law: &ScaleLaw,
    solid: bool,
    placement: Similarity,
    margins: Margins,
    gap: f64,
) -> Result<Shape> {
    let m = transport.pieces.len();
    let scales = piece_scales(transport, law)?;
    let blend_scales = match blend {
        Some(b) => Some(blend_scales(transport, b)?),
        None => None,
    };
    // Lateral surfaces, normalized, [piece][loop][edge].
    let mut normalized: Vec<Vec<Vec<PiecewiseSurface>>> = Vec::with_capacity(m);
    for (j, (framed, scale)) in transport.pieces.iter().zip(&scales).enumerate() {
        let mut loops = Vec::with_capacity(profile.loops.len());
        for (l, lp) in profile.loops.iter().enumerate() {
            let faces = lp
                .edges
                .iter()
                .enumerate()
                .map(|(e, edge)| match (blend, &blend_scales) {
                    (Some(b), Some(laws)) => {
                        let [down, up, ones] = &laws[j];
                        let b = &b.intervals[b.interval_of(j)];
                        combined(
                            &lateral(framed, &b.start.loops[l].edges[e], Some(down), false)?,
                            &lateral(framed, &b.end.loops[l].edges[e], Some(up), false)?,
                            &lateral(framed, &b.zero.loops[l].edges[e], Some(ones), false)?,
                        )
                    }
                    _ => lateral(framed, edge, scale.as_ref(), profile.plane.is_some()),
                })
                .collect::<Result<Vec<_>>>()
                .map_err(|e| e.context(format!("edge {}", framed.piece.edge)))?;
            loops.push(faces);
        }
        normalized.push(loops);
    }
    let tubes = tubes(
        transport,
        blend.map_or(profile, |b| {
            b.sections()
                .fold(profile, |a, c| if c.reach() > a.reach() { c } else { a })
        }),
        law.max(),
        &normalized,
    );
    if let Some(contact) = self_contact(&normalized, &tubes, transport.closed, gap) {
        return Err(self_intersection(&contact, transport, placement, gap));
    }
    let images = closure_images(transport, profile)?;
    let seam_gap = seam_gap(&normalized, profile, images.as_ref()) * placement.scale;
    let joint_gap = joint_gap(&normalized) * placement.scale;
    // In the caller's coordinates.
    let surfaces: Vec<Vec<Vec<PiecewiseSurface>>> = normalized
        .iter()
        .map(|loops| {
            loops
                .iter()
                .map(|faces| {
                    faces
                        .iter()
                        .map(|s| placement.surface_to_user(s.clone()))
                        .collect()
                })
                .collect::<Result<_>>()
        })
        .collect::<Result<_>>()?;
    let nurbs: Vec<Vec<Vec<NurbsSurface>>> = surfaces
        .iter()
        .zip(&transport.pieces)
        .map(|(loops, framed)| {
            loops
                .iter()
                .map(|faces| {
                    faces
                        .iter()
                        .map(|s| face_nurbs(s, framed.screw.is_some()))
                        .collect()
                })
                .collect::<Result<_>>()
        })
        .collect::<Result<_>>()?;
    let mut topology = Topology::new(transport, profile, &nurbs, images.as_ref());
    let face_count = m * profile.edge_count() + 2;
    let mut faces = Vec::with_capacity(face_count);
    let mut brep_faces = Vec::with_capacity(face_count);
    // The surfaces and their NURBS move into the faces.
    for (j, ((framed, nurbs), surfaces)) in
        transport.pieces.iter().zip(nurbs).zip(surfaces).enumerate()
    {
        let mut global_edge = 0;
        for (l, ((lp, nurbs), surfaces)) in
            profile.loops.iter().zip(nurbs).zip(surfaces).enumerate()
        {
            for (e, (n, surface)) in nurbs.into_iter().zip(surfaces).enumerate() {
                let reversed = lp.closed && ((lp.area > 0.0) != (l == 0));
                let axis = spine_axis(
                    framed,
                    scales[j].is_none() && blend.is_none(),
                    profile,
                    placement,
                );
                brep_faces.push(topology.lateral_face(j, l, e, n, !reversed, axis, &surface));
                faces.push(Face {
                    kind: FaceKind::Swept,
                    surface: Some(surface),
                    plane: None,
                    loops: Vec::new(),
                    spine_edge: framed.piece.edge,
                    profile_edge: global_edge,
                    profile_loop: l,
                    round_corner: framed.piece.corner.is_some(),
                    reversed,
                });
                global_edge += 1;
            }
        }
    }
    let capped = !transport.closed && profile.loops[0].closed;
    if capped && solid {
        for end in [false, true] {
            let sigma = match (&scales[if end { m - 1 } else { 0 }], end) {
                (Some(scale), true) => scale.ends().1,
                (Some(scale), false) => scale.ends().0,
                (None, _) => 1.0,
            };
            // A blend ends on its end profile.
            let capped = match (blend, end) {
                (Some(b), true) => b.end(),
                _ => profile,
            };
            let (face, brep_face) = topology.cap(end, transport, capped, placement, sigma)?;
            faces.push(face);
            brep_faces.push(brep_face);
        }
    }
    let closed_shell = solid && profile.loops[0].closed;
    let built = SweepReport {
        spine_distance: transport
            .pieces
            .iter()
            .map(|p| p.distance)
            .fold(0.0, f64::max)
            * placement.scale,
        rmf_angle_error: transport
            .pieces
            .iter()
            .map(|p| p.angle_error)
            .fold(0.0, f64::max),
        // Measured on request (Shape::report).
        max_parameter_cosine: f64::NAN,
        // Measured on request (Shape::report) along curve pieces known not to fold.
        singularity_margin: f64::NAN,
        face_count: faces.len(),
        corner_turn: corner_turn(transport),
        seam_gap,
        joint_gap,
        frame_error: transport.frame_error,
    };
    let mut brep = Brep {
        vertices: topology.vertices,
        edges: topology.edges,
        faces: brep_faces,
        closed: closed_shell,
    };
    settle_analytic(&mut brep);
    // The lateral faces of each piece and closed loop, in the order they were made.
    let mut groups = Vec::new();
    let mut next = 0;
    for _ in 0..m {
        for lp in &profile.loops {
            let range = next..next + lp.edges.len();
            next = range.end;
            if lp.closed {
                let surfaces = faces[range.clone()]
                    .iter()
                    .filter_map(|f| f.surface.as_ref());
                groups.push((range.collect(), surfaces.collect()));
            }
        }
    }
    merge::join_analytic_loops(&mut brep, &groups);
    Ok(Shape {
        faces,
        brep,
        solid: closed_shell,
        built,
        report: OnceLock::new(),
        margins,
        angle_checks: transport
            .pieces
            .iter()
            .filter_map(|p| p.angle_check.clone())
            .collect(),
        internal: normalized.into_iter().flatten().flatten().collect(),
        spine: transport
            .pieces
            .iter()
            .map(|p| placement.curve_to_user(&p.spine))
            .collect(),
        placement,
    })
}

/// A lateral face as one NURBS: along a screw piece (one spline along the helix, module
/// `helix`) with simple knots along the spine where the patches join that smoothly.
fn face_nurbs(surface: &PiecewiseSurface, screw: bool) -> Result<NurbsSurface> {
    let nurbs = NurbsSurface::from_piecewise(surface)?;
    if screw {
        return Ok(nurbs.with_simple_knots_v().unwrap_or(nurbs));
    }
    Ok(nurbs)
}

/// The line or arc a piece sweeps its profile along untwisted (its frame constant along a
/// line, the arc's rotation along an arc), unscaled and in the normal plane: what makes a
/// lateral face analytic ([`topology::SpineAxis`]).
fn spine_axis(
    framed: &super::frame::Framed,
    unscaled: bool,
    profile: &Profile,
    placement: Similarity,
) -> Option<topology::SpineAxis> {
    if !unscaled || profile.plane.is_some() {
        return None;
    }
    match (&framed.piece.geometry, &framed.frame) {
        (Geometry::Line { a, b }, PieceFrame::Constant { .. }) => {
            Some(topology::SpineAxis::Line((*b - *a).normalize()))
        }
        (Geometry::Arc(arc), PieceFrame::Circular { .. }) => Some(topology::SpineAxis::Arc {
            center: placement.to_user(arc.center),
            normal: arc.normal,
            angle: arc.angle,
        }),
        _ => None,
    }
}

/// A blend's laws on each piece: 1 − λ, λ and 1 (for the spine's own term), λ linear in
/// arc length from 0 at the start of the piece's interval to 1 at its end.
fn blend_scales(transport: &Transport, blends: &Blends) -> Result<Vec<[PieceScale; 3]>> {
    let lengths: Vec<f64> = transport.pieces.iter().map(|p| p.length).collect();
    let mut s0 = 0.0;
    transport
        .pieces
        .iter()
        .enumerate()
        .map(|(j, framed)| {
            let i = blends.interval_of(j);
            let first = blends.first_piece[i];
            let last = blends
                .first_piece
                .get(i + 1)
                .copied()
                .unwrap_or(lengths.len());
            let law = |start, end| ScaleLaw::on_pieces(start, &[], end, &lengths[first..last]);
            let (down, up, ones) = (law(1.0, 0.0), law(0.0, 1.0), law(1.0, 1.0));
            // Arc length from the interval's start.
            let s = s0 - lengths[..first].iter().sum::<f64>();
            let scale = |law: &ScaleLaw| PieceScale::new(&framed.spine, spine_kind(framed), s, law);
            let laws = [scale(&down)?, scale(&up)?, scale(&ones)?];
            s0 += framed.length;
            Ok(laws)
        })
        .collect()
}

/// How a piece's spine is parameterized, for a scale law on it.
fn spine_kind(framed: &super::frame::Framed) -> SpineKind {
    match &framed.piece.geometry {
        Geometry::Line { .. } => SpineKind::Line(framed.length),
        Geometry::Arc(arc) => SpineKind::Arc {
            radius: arc.radius,
            angle: arc.angle,
        },
        Geometry::Curve(_) => SpineKind::Ph,
    }
}

/// The scale law on each piece (`None` everywhere for a constant one).
fn piece_scales(transport: &Transport, law: &ScaleLaw) -> Result<Vec<Option<PieceScale>>> {
    let mut s0 = 0.0;
    transport
        .pieces
        .iter()
        .map(|framed| {
            if law.is_constant() {
                return Ok(None);
            }
            let scale = PieceScale::new(&framed.spine, spine_kind(framed), s0, law)?;
            s0 += framed.length;
            Ok(Some(scale))
        })
        .collect()
}

/// The refusal of a sweep that touches itself, in the caller's units.
fn self_intersection(
    contact: &Contact,
    transport: &Transport,
    placement: Similarity,
    gap: f64,
) -> Error {
    let name = |piece: usize| transport.pieces[piece].piece.name();
    let (a, b) = contact.pieces;
    let (near, distance) = (
        placement.to_user(contact.points.0),
        contact.distance * placement.scale,
    );
    let gap = gap * placement.scale;
    let message = if contact.decided {
        format!(
            "the sweep intersects itself: the faces along {} and along {} come within \
             {distance:.3e} of each other near {near} (the join tolerance is {gap:.3e}), so \
             the solid would not be valid; keep the wire's parts farther apart than the \
             profile reaches, or use a smaller profile",
            name(a),
            name(b)
        )
    } else {
        format!(
            "the sweep may intersect itself: the faces along {} and along {} come within \
             {distance:.3e} of each other near {near}, and could not be shown to stay \
             farther apart than the join tolerance {gap:.3e}",
            name(a),
            name(b)
        )
    };
    if contact.decided {
        Error::invalid_input(message)
    } else {
        Error::not_converged(message)
    }
}

/// A closed wire's closing turn as a map of the profile's edges onto themselves (the
/// identity for an open wire: `None`).
fn closure_images(transport: &Transport, profile: &Profile) -> Result<Option<Vec<Vec<EdgeImage>>>> {
    if !transport.closed {
        return Ok(None);
    }
    let turn = transport.closing_turn;
    let identity = turn.abs() <= CLOSURE_ROUND_OFF;
    let images = if identity {
        Some(
            profile
                .loops
                .iter()
                .enumerate()
                .map(|(l, lp)| (0..lp.edges.len()).map(|e| (l, e, 0.0)).collect())
                .collect(),
        )
    } else {
        profile.symmetry(turn)
    };
    let Some(images) = images else {
        return invalid!(
            "closure_symmetry: the frame closes turned by {:.6} rad (a multiple of 2π/k), but \
             that turn does not map the profile onto itself edge by edge (each edge onto one \
             with the same parameterization); use closure_symmetry = 1 or a symmetric profile",
            turn
        );
    };
    for (l, lp) in profile.loops.iter().enumerate() {
        if !lp.closed
            && images[l]
                .iter()
                .enumerate()
                .any(|(e, &(l2, e2, _))| l2 != l || e2 != e)
        {
            return invalid!(
                "closure_symmetry: an open profile closes only without a turn, but the frame \
                 closes turned by {turn:.6} rad"
            );
        }
    }
    Ok(Some(images))
}

/// Largest distance between the sections where a closed wire closes.
fn seam_gap(
    surfaces: &[Vec<Vec<PiecewiseSurface>>],
    profile: &Profile,
    images: Option<&Vec<Vec<EdgeImage>>>,
) -> f64 {
    let Some(images) = images else { return 0.0 };
    let last = surfaces.len() - 1;
    let mut gap = 0.0f64;
    for (l, lp) in profile.loops.iter().enumerate() {
        for e in 0..lp.edges.len() {
            let (l2, e2, shift) = images[l][e];
            let (end, start) = (&surfaces[last][l][e], &surfaces[0][l2][e2]);
            let v1 = end.domain_v().1;
            let v0 = start.domain_v().0;
            for u in grid_parameters(end.u_breaks(), COSINE_SAMPLES) {
                gap = gap.max(end.eval(u, v1).distance(start.eval(u + shift, v0)));
            }
        }
    }
    gap
}

/// Largest distance between the end section of each piece and the start section of the
/// next (the same profile edge, the same parameter), at COSINE_SAMPLES + 1 local
/// parameters of every profile segment.
fn joint_gap(surfaces: &[Vec<Vec<PiecewiseSurface>>]) -> f64 {
    let mut gap = 0.0f64;
    for pair in surfaces.windows(2) {
        for (before, after) in pair[0].iter().flatten().zip(pair[1].iter().flatten()) {
            let (v1, v0) = (before.domain_v().1, after.domain_v().0);
            if before.u_breaks() != after.u_breaks() {
                for u in grid_parameters(before.u_breaks(), COSINE_SAMPLES) {
                    gap = gap.max(before.eval(u, v1).distance(after.eval(u, v0)));
                }
                continue;
            }
            let (last, segments) = (before.v_breaks().len() - 2, before.u_breaks().len() - 1);
            for a in 0..segments {
                let (end, start) = (
                    Section::of(before.patch(a, last), true),
                    Section::of(after.patch(a, 0), false),
                );
                // Equal columns give equal points (up to the sign of zeros): distance 0.
                if end.column.is_some() && end.column == start.column {
                    continue;
                }
                // The last segment's end too (the next segment's start elsewhere).
                let steps = COSINE_SAMPLES + usize::from(a + 1 == segments);
                for k in 0..steps {
                    let u = k as f64 / COSINE_SAMPLES as f64;
                    gap = gap.max(end.point(u).distance(start.point(u)));
                }
            }
        }
    }
    gap
}

/// v turned about the unit axis by θ (Rodrigues).
fn rotate(v: DVec3, axis: DVec3, theta: f64) -> DVec3 {
    let (s, c) = theta.sin_cos();
    v * c + axis.cross(v) * s + axis * axis.dot(v) * (1.0 - c)
}

/// The frame turned by the minimal rotation taking its tangent to `tangent`.
fn minimal_rotation(frame: &Frame, tangent: DVec3) -> DVec3 {
    let axis = frame.tangent.cross(tangent);
    if axis.length() == 0.0 {
        return frame.f2;
    }
    let theta = axis.length().atan2(frame.tangent.dot(tangent));
    rotate(frame.f2, axis.normalize(), theta)
}

/// Largest turn about the tangent across corners (see [`SweepReport::corner_turn`]).
fn corner_turn(transport: &Transport) -> f64 {
    let pieces = &transport.pieces;
    let m = pieces.len();
    let turn = |before: &Frame, after: &Frame| {
        let carried =
            Frame::from_tangent_normal(after.tangent, minimal_rotation(before, after.tangent));
        angle_about_tangent(&carried, after).abs()
    };
    let mut worst = 0.0f64;
    for (i, p) in pieces.iter().enumerate() {
        if p.piece.corner.is_some() {
            // Across the elbow: the arc's RMF is the rotation about its axis by its angle.
            if let Geometry::Arc(arc) = &p.piece.geometry {
                let carried = rotate(p.start.f2, arc.normal, arc.angle);
                let carried = Frame::from_tangent_normal(p.end.tangent, carried);
                worst = worst.max(angle_about_tangent(&carried, &p.end).abs());
            }
        }
        if p.miters[1].is_some() {
            let next = &pieces[(i + 1) % m];
            worst = worst.max(turn(&p.end, &next.start));
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::cosine::patch_cosine_bound;
    use super::*;

    /// The largest sampled |cos| on a fine grid of a patch.
    fn sampled(p: &RationalBezierPatch, steps: usize) -> f64 {
        let mut worst = 0.0f64;
        p.grid_partials(steps, |du, dv| worst = worst.max(partials_cosine(du, dv)));
        worst
    }

    #[test]
    fn the_cosine_bound_is_above_every_sample_and_close_to_them() {
        // Deterministic pseudo-random patches of degrees (1..=3, 1..=2), positive weights.
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for trial in 0..200 {
            let (du, dv) = (1 + trial % 3, 1 + (trial / 3) % 2);
            let points = (0..=du)
                .flat_map(|i| (0..=dv).map(move |j| (i, j)))
                .map(|(i, j)| {
                    let w = 0.5 + next();
                    let p = DVec3::new(i as f64, j as f64, 0.0)
                        + 0.3 * DVec3::new(next(), next(), next());
                    (p * w).extend(w)
                })
                .collect();
            let patch = RationalBezierPatch::from_homogeneous(du, dv, points).unwrap();
            let mut bases = CosineBases::new();
            let bases = bases.of(du);
            let bound = if dv == 1 {
                patch_cosine_bound::<2>(&patch, bases)
            } else {
                patch_cosine_bound::<3>(&patch, bases)
            };
            // Finer than the bound's lines along u would miss nothing on them: compare on
            // those lines, densely along v.
            let mut on_lines = 0.0f64;
            for k in 0..=COSINE_SAMPLES {
                let u = k as f64 / COSINE_SAMPLES as f64;
                for i in 0..=200 {
                    let j = patch.eval_jet(u, i as f64 / 200.0);
                    on_lines = on_lines.max(partials_cosine(j.du, j.dv));
                }
            }
            assert!(
                bound >= on_lines * (1.0 - 1e-12),
                "trial {trial}: bound {bound} below a sample {on_lines}"
            );
            assert!(bound <= 1.0);
            // Of the samples' order (the convex hull bound is not far from the maximum).
            assert!(
                bound <= (20.0 * on_lines).max(sampled(&patch, 8)) + 1e-12,
                "trial {trial}: bound {bound} far above {on_lines}"
            );
        }
    }
}
