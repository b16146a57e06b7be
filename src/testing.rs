//! The fixtures the unit tests share: analytic curves with known rotation-minimizing
//! frames, and Hermite data (the RRMF paper's Example 1, pseudo-random and nearly
//! degenerate data) with the checks every RRMF quintic solution must pass.

use crate::bezier::{PiecewiseCurve, PiecewiseSurface};
use crate::curve::{uniform_parameters, ParametricCurve};
use crate::frames::double_reflection::DoubleReflectionRmf;
use crate::frames::frenet::frenet_frame;
use crate::frames::metrics::angle_about_tangent;
use crate::frames::rational::{RationalFrameSegment, RationalFrames};
use crate::frames::Frame;
use crate::hermite::HermiteSegment;
use crate::math::angle_between;
use crate::mobius::hermite::planar_frame;
use crate::model::{
    AnalyticCurve, AnalyticSurface, Brep, BrepSurface, BrepUse, FramedCurve, PCurve,
};
use crate::ph_cubic::PhCubic;
use crate::rrmf_quintic::RrmfQuintic;
use crate::Result;
use glam::DVec3;
use std::collections::HashMap;

/// The circular helix (r cos t, r sin t, h t) on [0, 4π].
pub(crate) struct Helix {
    pub radius: f64,
    pub pitch: f64,
}

impl Helix {
    /// Point and derivative at `t`.
    pub(crate) fn at(&self, t: f64) -> (DVec3, DVec3) {
        let (r, h) = (self.radius, self.pitch);
        (
            DVec3::new(r * t.cos(), r * t.sin(), h * t),
            DVec3::new(-r * t.sin(), r * t.cos(), h),
        )
    }

    fn second_derivative(&self, t: f64) -> DVec3 {
        DVec3::new(-self.radius * t.cos(), -self.radius * t.sin(), 0.0)
    }

    /// The exact RMF: the Frenet frame turned by Ω = −τ σ t (Mäurer & Jüttler, eq. (6);
    /// curvature and torsion are constant).
    pub(crate) fn exact_rmf(&self, t: f64) -> Frame {
        let (d1, d2) = (self.at(t).1, self.second_derivative(t));
        let speed_squared = self.radius * self.radius + self.pitch * self.pitch;
        let torsion = self.pitch / speed_squared;
        frenet_frame(d1, d2)
            .expect("a helix has curvature")
            .rotated(-torsion * speed_squared.sqrt() * t)
    }
}

/// The unit helix (cos t, sin t, pitch·t): point and derivative.
pub(crate) fn helix(t: f64, pitch: f64) -> (DVec3, DVec3) {
    Helix { radius: 1.0, pitch }.at(t)
}

impl ParametricCurve for Helix {
    fn domain(&self) -> (f64, f64) {
        (0.0, 4.0 * std::f64::consts::PI)
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        Ok(self.at(t))
    }
}

/// A planar PH cubic, a Tschirnhausen cubic: legs of lengths 1, q, q² each turning by `turn`
/// (equal angles and L₂² = L₁L₃, condition (17) of Mäurer & Jüttler with ψ = 0).
pub(crate) fn tschirnhausen(turn: f64, q: f64) -> PhCubic {
    let leg = |k: f64| DVec3::new((k * turn).cos(), (k * turn).sin(), 0.0) * q.powf(k);
    let b1 = leg(0.0);
    let b2 = b1 + leg(1.0);
    PhCubic::from_control_points([DVec3::ZERO, b1, b2, b2 + leg(2.0)]).expect("a PH cubic")
}

/// A Tschirnhausen cubic in the xy-plane (legs 1, 2, 4 turning by 30°, moved off the origin)
/// with its rational RMF: f₂ = +z (a constant vector is rotation-minimizing along a planar
/// curve), f₃ = t × z.
pub(crate) fn planar_ph_cubic() -> FramedCurve {
    let shift = DVec3::new(0.2, -0.4, 0.0);
    let cubic = PhCubic::from_control_points(
        tschirnhausen(30f64.to_radians(), 2.0)
            .control_points()
            .map(|p| p + shift),
    )
    .expect("a PH cubic");
    let raw = planar_frame(&cubic, DVec3::Z);
    let frame = RationalFrameSegment::new(raw.f2, raw.f3, raw.denominator).expect("positive speed");
    FramedCurve::new(
        PiecewiseCurve::new(vec![cubic.to_bezier()], vec![0.0, 1.0]).expect("one segment"),
        RationalFrames::new(vec![frame], vec![0.0, 1.0]).expect("one segment"),
    )
    .expect("the cubic's own frames")
}

/// One spatial G1 Hermite segment (non-planar, no symmetry): the Möbius tests' data.
pub(crate) fn spatial_hermite_segment() -> HermiteSegment {
    HermiteSegment::new(
        DVec3::new(0.1, 0.0, -0.2),
        DVec3::new(1.0, 0.4, 0.3),
        DVec3::new(1.5, 1.2, 0.4),
        DVec3::new(0.2, 1.0, 0.6),
    )
    .expect("valid data")
}

/// Planar G1 data through three points (a C-shaped arc in the xy-plane).
pub(crate) fn planar_hermite_data() -> ([DVec3; 3], [DVec3; 3]) {
    (
        [
            DVec3::ZERO,
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(4.0, 0.0, 0.0),
        ],
        [
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::X,
            DVec3::new(1.0, -1.0, 0.0),
        ],
    )
}

/// The largest angle about the tangent between `frame(t)` and the double-reflection RMF of
/// `curve` started at `normal`, over `samples` uniform parameters (the double-reflection
/// frames are fourth-order accurate in the sample spacing: the reference of the tests).
pub(crate) fn gap_to_double_reflection(
    curve: &PiecewiseCurve,
    normal: DVec3,
    samples: usize,
    frame: impl Fn(f64) -> Frame,
) -> f64 {
    let params = uniform_parameters(curve.domain(), samples);
    let reference =
        DoubleReflectionRmf::along(curve, params.clone(), normal).expect("a regular curve");
    params
        .iter()
        .zip(reference.frames())
        .map(|(&t, f)| angle_about_tangent(f, &frame(t)).abs())
        .fold(0.0, f64::max)
}

// Hermite data and the checks of RRMF quintic solutions (Farouki, Giannelli & Sestini).

/// Example 1 of the paper.
pub(crate) fn example_1() -> HermiteSegment {
    HermiteSegment::new(
        DVec3::ZERO,
        DVec3::new(1.0, 0.0, 1.0),
        DVec3::ONE,
        DVec3::new(0.0, 1.0, 1.0),
    )
    .unwrap()
}

/// Deterministic pseudo-random vectors with components in [−1, 1) (a linear
/// congruential generator).
pub(crate) fn random_vectors(seed: u64) -> impl FnMut() -> DVec3 {
    let mut stream = Stream(seed);
    move || {
        DVec3::new(
            stream.uniform(-1.0, 1.0),
            stream.uniform(-1.0, 1.0),
            stream.uniform(-1.0, 1.0),
        )
    }
}

/// Pseudo-random Hermite data with chords of very different lengths.
pub(crate) fn random_data(count: usize) -> Vec<HermiteSegment> {
    let mut random = random_vectors(0x2545_f491_4f6c_dd1d);
    let mut vector = |scale: f64| random() * scale;
    (0..count)
        .map(|k| {
            let scale = 10f64.powi(k as i32 % 5 - 2);
            let p0 = vector(scale);
            let p1 = p0 + vector(scale);
            HermiteSegment::new(p0, vector(1.0), p1, vector(1.0)).unwrap()
        })
        .collect()
}

/// Data whose start tangent makes an angle of 10⁻¹ … 10⁻⁹ rad with the chord: close to
/// the degenerate case θ_i = 0, with solutions whose speed dips far below its maximum.
pub(crate) fn near_degenerate_data(count: usize) -> Vec<HermiteSegment> {
    random_data(count)
        .into_iter()
        .enumerate()
        .map(|(k, d)| {
            let chord = (d.p1 - d.p0).normalize();
            let across = crate::math::orthogonalized(d.t0, chord).normalize();
            let t0 = chord + across * 10f64.powi(-(k as i32 % 9) - 1);
            HermiteSegment::new(d.p0, t0, d.p1, d.t1).unwrap()
        })
        .collect()
}

/// The checks the issue asks of every returned solution, in original coordinates.
pub(crate) fn check_solution(data: &HermiteSegment, s: &RrmfQuintic) -> (f64, f64, f64, f64) {
    let (r7, r8) = s.hopf.rrmf_residuals();
    assert!(
        r7 <= 1e-10 && r8 <= 1e-10,
        "(7), (8) residuals {r7:e}, {r8:e}"
    );
    assert!(s.rho > 0.0 && s.hopf.alpha[0].im == 0.0 && s.hopf.alpha[0].re > 0.0);
    let curve = s.bezier().unwrap();
    let p: Vec<DVec3> = curve.poles().collect();
    let size = data.chord_length().max(s.measures.arc_length);
    let end = (p[0] - data.p0).length().max((p[5] - data.p1).length()) / size;
    // The curve's derivative r'(0) = R H(α₀, β₀), exact to rounding, and the legs of the
    // control polygon: their direction is only as good as the poles' coordinates allow,
    // ε |P₀| / |P₁ − P₀|, which matters when ρ is far from 1 (a short first or last leg).
    let hodograph = s.hopf.hodograph();
    let at = |k: usize| s.placement.vector(hodograph[k]);
    let tangent = angle_between(at(0), data.t0).max(angle_between(at(4), data.t1));
    let leg =
        |a: DVec3, b: DVec3| 4.0 * f64::EPSILON * a.length().max(b.length()) / (b - a).length();
    let legs = angle_between(p[1] - p[0], data.t0).max(angle_between(p[5] - p[4], data.t1));
    let representable = leg(p[0], p[1]).max(leg(p[4], p[5]));
    assert!(
        end <= 1e-12,
        "end points off by {end:e} (relative to max(chord, L))"
    );
    assert!(tangent <= 1e-12, "end tangents off by {tangent:e} rad");
    assert!(
        legs <= 1e-12 + representable,
        "control legs off by {legs:e} rad"
    );
    // ρ² is the end-derivative ratio (20), and w certifies the RMF: σ = N₀ |w|².
    let ratio = hodograph[4].length() / hodograph[0].length();
    assert!((ratio - s.rho * s.rho).abs() <= 1e-12 * ratio);
    (r7.max(r8), end, tangent, legs)
}

/// A deterministic stream of numbers in [0, 1) (a 64-bit LCG: the tests need no crate).
pub(crate) struct Stream(pub u64);

impl Stream {
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    pub(crate) fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    /// 10^x for x uniform in [lo, hi].
    pub(crate) fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(self.uniform(lo, hi))
    }
}

/// Every edge is used exactly twice, once in each direction once the faces' orientation is
/// applied (a closed, consistently oriented shell), a degenerate edge once, at one vertex;
/// consecutive uses of a loop meet at a vertex; edge curves end at their vertices; every
/// use's parameter curve, mapped by its face's surface, is the edge's curve (sampled, to
/// 1e-9 of the shape's size).
pub(crate) fn assert_closed_oriented(brep: &Brep) {
    let mut uses: HashMap<usize, (usize, usize)> = HashMap::new();
    for face in &brep.faces {
        for u in face.bounds.iter().flat_map(|b| &b.uses) {
            let forward = u.forward == face.same_sense;
            let entry = uses.entry(u.edge).or_default();
            if forward {
                entry.0 += 1;
            } else {
                entry.1 += 1;
            }
        }
    }
    assert_eq!(uses.len(), brep.edges.len(), "every edge is used");
    for (edge, (f, b)) in uses {
        if brep.edges[edge].degenerate {
            assert_eq!(f + b, 1, "degenerate edge {edge}: {f} + {b} uses");
            assert_eq!(brep.edges[edge].start, brep.edges[edge].end);
        } else {
            assert_eq!(
                (f, b),
                (1, 1),
                "edge {edge}: {f} forward, {b} backward uses"
            );
        }
    }
    // Consecutive uses of a loop meet at a vertex.
    for (k, face) in brep.faces.iter().enumerate() {
        for bound in &face.bounds {
            let ends: Vec<(usize, usize)> = bound
                .uses
                .iter()
                .map(|u| {
                    let e = &brep.edges[u.edge];
                    if u.forward {
                        (e.start, e.end)
                    } else {
                        (e.end, e.start)
                    }
                })
                .collect();
            for i in 0..ends.len() {
                let next = ends[(i + 1) % ends.len()];
                assert_eq!(
                    ends[i].1, next.0,
                    "face {k}: the loop is broken after use {i}"
                );
            }
        }
    }
    let size = brep
        .vertices
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    // Edge curves end at their vertices.
    for (k, e) in brep.edges.iter().enumerate() {
        let (first, last) = (e.curve.poles[0], e.curve.poles[e.curve.poles.len() - 1]);
        assert!(
            first.distance(brep.vertices[e.start]) < 1e-9 * size,
            "edge {k} start"
        );
        assert!(
            last.distance(brep.vertices[e.end]) < 1e-9 * size,
            "edge {k} end"
        );
    }
    assert_pcurves_on_edges(brep, size);
    assert_analytic_forms(brep, size);
}

/// The analytic forms of a model are its geometry: every analytic edge runs from its start
/// vertex to its end vertex through its curve's points, every analytic face's surface
/// holds its NURBS surface's points with the same normal (times the senses), every curve
/// on an analytic face maps to its edge's analytic curve; an analytic edge is used only by
/// analytic or planar faces, and an analytic cylinder or torus uses only analytic edges.
/// To 1e-9 of `size`, at 9 (9 × 9) parameters.
pub(crate) fn assert_analytic_forms(brep: &Brep, size: f64) {
    let model = Prepared::new(brep);
    let tolerance = 1e-9 * size;
    for (k, edge) in brep.edges.iter().enumerate() {
        let Some(analytic) = edge.analytic else {
            continue;
        };
        let ends = [
            (analytic.curve.point(0.0), edge.start),
            (analytic.curve.point(analytic.end), edge.end),
        ];
        for (p, v) in ends {
            let gap = p.distance(brep.vertices[v]);
            assert!(gap <= tolerance, "edge {k}: {gap:e} from its vertex");
        }
        for j in 0..=8 {
            let (_, p) = model.edge_at(k, j as f64 / 8.0);
            let gap = distance_to_curve(&analytic.curve, p);
            assert!(gap <= tolerance, "edge {k}: {gap:e} off its analytic curve");
        }
    }
    for (k, face) in brep.faces.iter().enumerate() {
        let Some(analytic) = &face.analytic else {
            continue;
        };
        let planar = matches!(analytic.surface, AnalyticSurface::Plane { .. });
        if let Some(surface) = &model.surfaces[k] {
            let ((u0, u1), (v0, v1)) = (surface.domain_u(), surface.domain_v());
            for i in 0..=8 {
                for j in 0..=8 {
                    let (u, v) = (
                        u0 + (u1 - u0) * i as f64 / 8.0,
                        v0 + (v1 - v0) * j as f64 / 8.0,
                    );
                    let jet = surface.eval_jet(u, v);
                    let (a, b) = analytic.surface.parameters(jet.point);
                    let gap = analytic.surface.point(a, b).distance(jet.point);
                    assert!(
                        gap <= tolerance,
                        "face {k}: {gap:e} off its analytic surface"
                    );
                    let normal = jet.du.cross(jet.dv).normalize();
                    let sense = if face.same_sense == analytic.same_sense {
                        1.0
                    } else {
                        -1.0
                    };
                    let turn = normal.dot(analytic.surface.normal(jet.point)) * sense;
                    assert!(turn > 1.0 - 1e-9, "face {k}: normals {turn} apart");
                }
            }
        }
        if planar {
            continue;
        }
        for (b, bound) in face.bounds.iter().enumerate() {
            // Taken as a kernel takes it (reversed where the orientations differ), the
            // loop runs counter-clockwise on the analytic surface (holes clockwise): the
            // signed area of its polygon of line pcurves.
            let reversed = analytic.loops_reversed(face.same_sense);
            let area: f64 = bound
                .uses
                .iter()
                .zip(&analytic.pcurves[b])
                .map(|(u, pcurve)| {
                    let end = brep.edges[u.edge].analytic.map_or(0.0, |a| a.end);
                    let (p, q) = (pcurve_at(pcurve, 0.0), pcurve_at(pcurve, end));
                    let (p, q) = if u.forward { (p, q) } else { (q, p) };
                    0.5 * (p.0 * q.1 - q.0 * p.1)
                })
                .sum();
            let area = if reversed { -area } else { area };
            assert!(
                (area > 0.0) == bound.outer,
                "face {k}: loop {b} turns the wrong way on the analytic surface ({area})"
            );
            for (i, u) in bound.uses.iter().enumerate() {
                let edge = brep.edges[u.edge].analytic;
                let edge =
                    edge.unwrap_or_else(|| panic!("face {k}: edge {} is not analytic", u.edge));
                let pcurve = &analytic.pcurves[b][i];
                for j in 0..=8 {
                    let t = edge.end * j as f64 / 8.0;
                    let (x, y) = pcurve_at(pcurve, t);
                    let gap = analytic.surface.point(x, y).distance(edge.curve.point(t));
                    assert!(
                        gap <= tolerance,
                        "face {k}, edge {}: {gap:e} at {t}",
                        u.edge
                    );
                }
            }
        }
    }
    for (k, face) in brep.faces.iter().enumerate() {
        let planar = matches!(face.surface, BrepSurface::Plane { .. }) || face.analytic.is_some();
        for u in face.bounds.iter().flat_map(|b| &b.uses) {
            if brep.edges[u.edge].analytic.is_some() {
                assert!(planar, "analytic edge {} on the NURBS face {k}", u.edge);
            }
        }
    }
}

/// The distance of `p` from a line or circle.
fn distance_to_curve(curve: &AnalyticCurve, p: DVec3) -> f64 {
    match *curve {
        AnalyticCurve::Line { origin, direction } => {
            let d = p - origin;
            (d - direction * d.dot(direction)).length()
        }
        AnalyticCurve::Circle {
            center,
            axis,
            radius,
            ..
        } => {
            let d = p - center;
            let height = d.dot(axis);
            let across = (d - axis * height).length() - radius;
            height.hypot(across)
        }
    }
}

/// Every use's parameter curve on a NURBS face, mapped by the surface, is its edge's curve
/// at 9 parameters, to 1e-9 of `size`.
fn assert_pcurves_on_edges(brep: &Brep, size: f64) {
    let model = Prepared::new(brep);
    for (k, face) in brep.faces.iter().enumerate() {
        if let BrepSurface::Plane { .. } = face.surface {
            continue;
        }
        for u in face.bounds.iter().flat_map(|b| &b.uses) {
            for j in 0..=8 {
                let (t, point) = model.edge_at(u.edge, j as f64 / 8.0);
                let pcurve = u.pcurve.as_ref().expect("a pcurve on a NURBS face");
                let (x, y) = pcurve_at(pcurve, t);
                let gap = model.surface_at(k, x, y).distance(point);
                assert!(
                    gap <= 1e-9 * size,
                    "face {k}, edge {}: the pcurve is {gap:e} off the edge at t = {t}",
                    u.edge
                );
            }
        }
    }
}

/// A B-rep's curves and surfaces converted once for the checks that evaluate them.
struct Prepared<'a> {
    brep: &'a Brep,
    curves: Vec<PiecewiseCurve>,
    /// The NURBS faces' surfaces (None for planes).
    surfaces: Vec<Option<PiecewiseSurface>>,
}

impl<'a> Prepared<'a> {
    fn new(brep: &'a Brep) -> Self {
        Self {
            brep,
            curves: brep
                .edges
                .iter()
                .map(|e| e.curve.to_piecewise().expect("a valid curve"))
                .collect(),
            surfaces: brep
                .faces
                .iter()
                .map(|f| match &f.surface {
                    BrepSurface::Nurbs(s) => Some(s.to_piecewise().expect("a valid surface")),
                    BrepSurface::Plane { .. } => None,
                })
                .collect(),
        }
    }

    /// Edge `e` at the fraction `f` of its parameter range: the parameter and the point.
    fn edge_at(&self, e: usize, f: f64) -> (f64, DVec3) {
        let knots = &self.brep.edges[e].curve.knots;
        let (a, b) = (knots[0], knots[knots.len() - 1]);
        let t = a + (b - a) * f;
        (t, self.curves[e].eval(t))
    }

    /// The surface of face `face` at the parameters (x, y).
    fn surface_at(&self, face: usize, x: f64, y: f64) -> DVec3 {
        match (&self.surfaces[face], &self.brep.faces[face].surface) {
            (Some(s), _) => s.eval(x, y),
            (
                None,
                BrepSurface::Plane {
                    origin,
                    normal,
                    x_axis,
                },
            ) => *origin + x * *x_axis + y * normal.cross(*x_axis),
            (None, BrepSurface::Nurbs(_)) => unreachable!("NURBS faces are prepared"),
        }
    }

    /// The point of a use's edge at the fraction `f` of its parameter range, and that of
    /// its curve in the face's parameter plane there, mapped by the face's surface.
    fn use_points(&self, face: usize, use_: &BrepUse, f: f64) -> (DVec3, Option<DVec3>) {
        let (t, point) = self.edge_at(use_.edge, f);
        let on_face = use_.pcurve.as_ref().map(|p| {
            let (x, y) = pcurve_at(p, t);
            self.surface_at(face, x, y)
        });
        (point, on_face)
    }
}

/// A parameter curve at the edge curve's parameter t.
fn pcurve_at(pcurve: &PCurve, t: f64) -> (f64, f64) {
    match pcurve {
        PCurve::Line { origin, direction } => {
            (origin.0 + t * direction.0, origin.1 + t * direction.1)
        }
        PCurve::Curve(c) => {
            let p = c.to_piecewise().expect("a valid pcurve").eval(t);
            (p.x, p.y)
        }
    }
}

/// `moved` is `unit` scaled by `scale` about the origin and then moved by `shift`: the same
/// topology (vertices, edges, loops, uses, senses) and, mapped back, the same vertices, edge
/// curves and curves on the faces at 9 parameters each, to 1e-9 of the unit model's size.
pub(crate) fn assert_similar_breps(unit: &Brep, moved: &Brep, scale: f64, shift: DVec3) {
    let back = |p: DVec3| (p - shift) / scale;
    let size = unit
        .vertices
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    let near = |a: DVec3, b: DVec3, what: &str| {
        assert!(
            a.distance(back(b)) <= 1e-9 * size,
            "scale {scale:e}, shift {shift}: {what}: {a} vs {}",
            back(b)
        );
    };
    assert_eq!(unit.closed, moved.closed);
    assert_eq!(unit.vertices.len(), moved.vertices.len());
    for (k, (a, b)) in unit.vertices.iter().zip(&moved.vertices).enumerate() {
        near(*a, *b, &format!("vertex {k}"));
    }
    assert_eq!(unit.edges.len(), moved.edges.len());
    for (k, (a, b)) in unit.edges.iter().zip(&moved.edges).enumerate() {
        assert_eq!(
            (a.start, a.end, a.degenerate),
            (b.start, b.end, b.degenerate)
        );
        assert_eq!(a.curve.degree, b.curve.degree, "edge {k}");
        assert_eq!(
            a.analytic.is_some(),
            b.analytic.is_some(),
            "edge {k}: analytic"
        );
    }
    assert_eq!(unit.faces.len(), moved.faces.len());
    let prepared = (Prepared::new(unit), Prepared::new(moved));
    for (k, (a, b)) in unit.faces.iter().zip(&moved.faces).enumerate() {
        assert_eq!(a.same_sense, b.same_sense, "face {k}");
        let kind = |f: &crate::model::BrepFace| {
            f.analytic
                .as_ref()
                .map(|a| (std::mem::discriminant(&a.surface), a.same_sense))
        };
        assert_eq!(kind(a), kind(b), "face {k}: analytic");
        assert_eq!(a.bounds.len(), b.bounds.len(), "face {k}");
        for (p, q) in a.bounds.iter().zip(&b.bounds) {
            assert_eq!(p.outer, q.outer, "face {k}");
            assert_eq!(p.uses.len(), q.uses.len(), "face {k}");
            for (u, v) in p.uses.iter().zip(&q.uses) {
                assert_eq!((u.edge, u.forward), (v.edge, v.forward), "face {k}");
                assert_eq!(u.pcurve.is_some(), v.pcurve.is_some(), "face {k}");
                for j in 0..=8 {
                    let f = j as f64 / 8.0;
                    let (pa, sa) = prepared.0.use_points(k, u, f);
                    let (pb, sb) = prepared.1.use_points(k, v, f);
                    near(pa, pb, &format!("edge {} at {f}", u.edge));
                    if let (Some(sa), Some(sb)) = (sa, sb) {
                        near(sa, sb, &format!("face {k}, edge {} at {f}", u.edge));
                    }
                }
            }
        }
    }
}
