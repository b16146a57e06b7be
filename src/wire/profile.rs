//! The cross-section of a wire sweep: an outer loop and optional holes, planar curves in
//! the normal plane (x ↦ f₂, y ↦ f₃, z = 0), each split into the profile edges that become
//! one lateral face each: at its G0 corners and at the joints of its Bézier segments, so
//! that every face is a single rational patch across the profile. (OpenCascade's
//! fixed-order volume and area integration, which FreeCAD's `Shape.Volume` uses, does not
//! split at knots: a circle swept as one face of four quarters reads 4.5e-3 off in volume,
//! as four faces 1e-11.)
//!
//! Also what the sweep needs to know about the profile: its signed area per loop (which way
//! it turns, so faces are oriented outwards), its extent in a direction (the support
//! function h(d) = max c·d, which decides the singularity margin g = 1 − κ c·n of Mäurer &
//! Jüttler Cor. 7 along arcs, corners and miters), its largest distance from the spine, and
//! whether a turn by 2π/k maps it onto itself (closure of closed wires modulo its
//! symmetry).

use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::{invalid, Result};
use crate::math::bounding_diagonal;
use crate::model::is_centred_arc;
use crate::ph_cubic::profile::{critical_points, ProfileSegment};
use glam::{DVec2, DVec3, DVec4};

/// Relative size (to the profile) of a z coordinate still taken as 0.
const PLANAR: f64 = 1e-9;

/// Samples per Bézier segment of the polygons that decide orientation and containment.
const POLYGON_SAMPLES: usize = 32;

/// One loop of the profile.
#[derive(Clone, Debug)]
pub(crate) struct ProfileLoop {
    /// Consecutive edges, one per Bézier segment.
    pub edges: Vec<PiecewiseCurve>,
    pub closed: bool,
    /// Signed area (closed loops; 0 for open ones): positive when counter-clockwise.
    pub area: f64,
}

/// The outer loop (index 0) and the holes.
#[derive(Clone, Debug)]
pub(crate) struct Profile {
    pub loops: Vec<ProfileLoop>,
    /// A profile drawn out of the normal plane: its plane, in the profile's coordinates
    /// (x along f₂, y along f₃, z along the tangent); `None` in the normal plane (z = 0).
    pub plane: Option<ProfilePlane>,
}

/// The plane m·c = offset of a profile drawn out of the normal plane, m a unit vector with
/// m_z > 0 (towards the tangent; the plane never contains it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ProfilePlane {
    pub normal: DVec3,
    pub offset: f64,
}

/// Least |m_z| of a profile's plane: a plane within 1e-3 rad of containing the tangent
/// would sweep a sheet of no thickness along it.
const MIN_TILT: f64 = 1e-3;

/// Where a turn of the profile sends one of its edges: (loop, edge, parameter shift).
pub(crate) type EdgeImage = (usize, usize, f64);

impl Profile {
    /// The profile of `outer` with `holes`; `solid` needs closed loops. `tolerance` is the
    /// relative distance within which a loop's end meets its start; `unit` converts lengths
    /// to the caller's units for messages.
    pub(super) fn new(
        outer: &PiecewiseCurve,
        holes: &[PiecewiseCurve],
        solid: bool,
        tolerance: f64,
        unit: f64,
    ) -> Result<Self> {
        let plane = profile_plane(std::iter::once(outer).chain(holes), unit)?;
        let mut loops =
            vec![profile_loop(outer, tolerance, plane).map_err(|e| e.context("profile"))?];
        for (k, hole) in holes.iter().enumerate() {
            loops.push(
                profile_loop(hole, tolerance, plane)
                    .map_err(|e| e.context(format!("holes[{k}]")))?,
            );
        }
        let outer = &loops[0];
        if solid && !outer.closed {
            let first = &outer.edges[0];
            let last = &outer.edges[outer.edges.len() - 1];
            return invalid!(
                "profile: a solid needs a closed profile, but it starts at {} and ends at {}",
                first.eval(first.domain().0).truncate() * unit,
                last.eval(last.domain().1).truncate() * unit
            );
        }
        if !holes.is_empty() && !outer.closed {
            return invalid!("profile: holes need a closed outer profile, but the profile is open");
        }
        for (k, hole) in loops[1..].iter().enumerate() {
            if !hole.closed {
                return invalid!("holes[{k}]: a hole must be a closed curve");
            }
        }
        let profile = Self { loops, plane };
        profile.check_nesting()?;
        Ok(profile)
    }

    /// Every edge with its loop and index in the loop.
    pub(super) fn edges(&self) -> impl Iterator<Item = (usize, usize, &PiecewiseCurve)> {
        self.loops
            .iter()
            .enumerate()
            .flat_map(|(l, lp)| lp.edges.iter().enumerate().map(move |(e, c)| (l, e, c)))
    }

    pub(super) fn edge_count(&self) -> usize {
        self.loops.iter().map(|l| l.edges.len()).sum()
    }

    /// h(d) = max over the profile of c·d.
    #[cfg(test)]
    pub(super) fn support(&self, d: DVec2) -> f64 {
        self.support_table().support(d)
    }

    /// The segments prepared for [`SupportTable::support`] in many directions.
    pub(super) fn support_table(&self) -> SupportTable {
        SupportTable {
            segments: self
                .segments()
                .map(|segment| {
                    let (a, b) = segment.scaled_tangent();
                    (segment, a, b)
                })
                .collect(),
        }
    }

    /// The profile's largest distance from the spine: max ‖c‖ in the normal plane; out of
    /// it a bound, the farthest control point (the curves lie in their hulls).
    pub(super) fn reach(&self) -> f64 {
        match self.plane {
            None => self.radius(),
            Some(_) => self
                .loops
                .iter()
                .flat_map(|l| &l.edges)
                .flat_map(|e| e.segments())
                .flat_map(|s| s.poles())
                .map(|p| p.length())
                .fold(0.0, f64::max),
        }
    }

    /// max ‖c‖ of the profile's projection onto the normal plane.
    pub(super) fn radius(&self) -> f64 {
        self.segments()
            .map(|segment| segment.max_radius())
            .fold(0.0, f64::max)
    }

    /// Every segment of every loop one after another on unit intervals: the profile as an
    /// analysis that takes it segment by segment sees it (consecutive segments of different
    /// loops do not join).
    pub(super) fn segment_chain(&self) -> PiecewiseCurve {
        let segments = self
            .loops
            .iter()
            .flat_map(|l| &l.edges)
            .flat_map(|e| e.segments().iter().cloned())
            .collect();
        PiecewiseCurve::with_unit_intervals(segments).expect("a profile has segments")
    }

    fn segments(&self) -> impl Iterator<Item = ProfileSegment> + '_ {
        self.loops
            .iter()
            .flat_map(|l| &l.edges)
            .flat_map(|e| e.segments())
            .map(ProfileSegment::of)
    }

    /// The size of the profile (its bounding-box diagonal).
    pub(super) fn size(&self) -> f64 {
        bounding_diagonal(
            self.loops
                .iter()
                .flat_map(|l| &l.edges)
                .flat_map(|e| e.segments())
                .flat_map(|s| s.poles()),
        )
    }

    /// Whether every loop is a closed circle about the spine (the origin) in the normal
    /// plane: a profile that no turn of the frame about the tangent moves, whose sweep is
    /// the same surface under every frame (a pipe).
    pub(super) fn is_round(&self) -> bool {
        self.plane.is_none()
            && self.loops.iter().all(|lp| {
                lp.closed
                    && lp.edges.iter().all(|edge| match edge.segments() {
                        [segment] => is_centred_arc(segment),
                        _ => false,
                    })
            })
    }

    /// Where the turn by `angle` (counter-clockwise in the profile plane) sends every edge,
    /// if it maps the profile onto itself edge by edge, each edge onto one with the same
    /// parameterization (up to a shift); `None` otherwise. Loop 0 must go to loop 0.
    pub(super) fn symmetry(&self, angle: f64) -> Option<Vec<Vec<EdgeImage>>> {
        let tolerance = 1e-9 * self.size();
        let (s, c) = angle.sin_cos();
        let turn = |h: DVec4| DVec4::new(c * h.x - s * h.y, s * h.x + c * h.y, 0.0, h.w);
        let mut images = Vec::with_capacity(self.loops.len());
        for (l, lp) in self.loops.iter().enumerate() {
            let mut loop_images = Vec::with_capacity(lp.edges.len());
            for edge in &lp.edges {
                let turned: Vec<Vec<DVec4>> = edge
                    .segments()
                    .iter()
                    .map(|seg| seg.homogeneous().iter().map(|&h| turn(h)).collect())
                    .collect();
                let image = self.edges().find(|&(l2, _, other)| {
                    (l == 0) == (l2 == 0) && same_edge(&turned, edge, other, tolerance)
                })?;
                let shift = image.2.breaks()[0] - edge.breaks()[0];
                loop_images.push((image.0, image.1, shift));
            }
            images.push(loop_images);
        }
        Some(images)
    }

    /// Holes lie inside the outer loop, outside each other, and no loops cross (checked on
    /// dense polygons).
    fn check_nesting(&self) -> Result<()> {
        let polygons: Vec<Vec<DVec2>> = self.loops.iter().map(polygon).collect();
        for (a, pa) in polygons.iter().enumerate() {
            for (b, pb) in polygons.iter().enumerate().skip(a + 1) {
                if polygons_cross(pa, pb) {
                    return invalid!("{} and {} cross each other", loop_name(a), loop_name(b));
                }
            }
        }
        for (k, hole) in polygons.iter().enumerate().skip(1) {
            if winding(&polygons[0], hole[0]) == 0 {
                return invalid!("{} lies outside the profile", loop_name(k));
            }
            for (j, other) in polygons.iter().enumerate().skip(1) {
                if j != k && winding(other, hole[0]) != 0 {
                    return invalid!("{} lies inside {}", loop_name(k), loop_name(j));
                }
            }
        }
        Ok(())
    }
}

fn loop_name(k: usize) -> String {
    if k == 0 {
        "the profile".to_string()
    } else {
        format!("holes[{}]", k - 1)
    }
}

/// Whether `turned` (homogeneous segments of `edge` turned) is `other`, segment by segment
/// with the same interval lengths.
fn same_edge(
    turned: &[Vec<DVec4>],
    edge: &PiecewiseCurve,
    other: &PiecewiseCurve,
    tolerance: f64,
) -> bool {
    if other.segments().len() != turned.len() {
        return false;
    }
    let lengths =
        |c: &PiecewiseCurve| -> Vec<f64> { c.breaks().windows(2).map(|w| w[1] - w[0]).collect() };
    let same_lengths = lengths(edge)
        .iter()
        .zip(lengths(other))
        .all(|(a, b)| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()));
    same_lengths
        && turned.iter().zip(other.segments()).all(|(t, o)| {
            let o = o.homogeneous();
            if o.len() != t.len() {
                return false;
            }
            let ratio = o[0].w / t[0].w;
            t.iter().zip(o).all(|(a, b)| {
                (a.truncate() / a.w).distance(b.truncate() / b.w) <= tolerance
                    && (b.w - ratio * a.w).abs() <= 1e-9 * b.w
            })
        })
}

/// The plane of a profile's loops: `None` when they lie in the normal plane (z = 0 within
/// rounding), else the one plane they all lie in, which must not contain the tangent.
fn profile_plane<'a>(
    curves: impl Iterator<Item = &'a PiecewiseCurve>,
    unit: f64,
) -> Result<Option<ProfilePlane>> {
    let poles: Vec<DVec3> = curves
        .flat_map(|c| c.segments())
        .flat_map(|s| s.poles())
        .collect();
    if poles.iter().any(|p| !p.is_finite()) {
        return Ok(None); // refused by the loop, which names it
    }
    let size = bounding_diagonal(poles.iter().copied());
    if size.is_nan() || size <= 0.0 || poles.iter().all(|p| p.z.abs() <= PLANAR * size) {
        return Ok(None);
    }
    // Three poles spanning the largest triangle give the plane; a straight profile lies in
    // the plane through it nearest to the normal plane.
    let p0 = poles[0];
    let p1 = poles.iter().copied().fold(p0, |far, p| {
        if p.distance(p0) > far.distance(p0) {
            p
        } else {
            far
        }
    });
    let chord = (p1 - p0).normalize();
    let off_line = |p: DVec3| (p - p0).cross(chord);
    let p2 = poles.iter().copied().fold(p0, |far, p| {
        if off_line(p).length() > off_line(far).length() {
            p
        } else {
            far
        }
    });
    let mut normal = if off_line(p2).length() > PLANAR * size {
        (p1 - p0).cross(p2 - p0).normalize()
    } else {
        (DVec3::Z - DVec3::Z.dot(chord) * chord).normalize()
    };
    if normal.z < 0.0 {
        normal = -normal;
    }
    if let Some((k, p)) = poles
        .iter()
        .enumerate()
        .find(|(_, p)| (**p - p0).dot(normal).abs() > PLANAR * size)
    {
        return invalid!(
            "profile: pole {k} {} lies {:.3e} off the plane of the others: a profile is planar",
            *p * unit,
            (*p - p0).dot(normal).abs() * unit
        );
    }
    if normal.z.is_nan() || normal.z <= MIN_TILT {
        return invalid!(
            "profile: its plane contains the wire's start tangent (within {:.3e} rad): it \
             would sweep no volume; draw it across the wire",
            normal.z.asin()
        );
    }
    Ok(Some(ProfilePlane {
        normal,
        offset: p0.dot(normal),
    }))
}

/// One loop: planar, snapped shut if its ends meet, split at its corners. In the normal
/// plane (`plane` `None`) its z is rounding and is made 0.
fn profile_loop(
    curve: &PiecewiseCurve,
    tolerance: f64,
    plane: Option<ProfilePlane>,
) -> Result<ProfileLoop> {
    let poles: Vec<DVec3> = curve.segments().iter().flat_map(|s| s.poles()).collect();
    if poles.iter().any(|p| !p.is_finite()) {
        return invalid!("has a non-finite pole");
    }
    let size = bounding_diagonal(poles.iter().map(|p| p.truncate().extend(0.0)));
    if size.is_nan() || size <= 0.0 {
        return invalid!("is a single point: it has no extent");
    }
    let flat: Vec<RationalBezierCurve> = curve
        .segments()
        .iter()
        .map(|s| {
            let h = s
                .homogeneous()
                .iter()
                .map(|h| match plane {
                    None => DVec4::new(h.x, h.y, 0.0, h.w),
                    Some(_) => *h,
                })
                .collect();
            RationalBezierCurve::from_homogeneous(h).expect("the same weights")
        })
        .collect();
    let (lo, hi) = curve.domain();
    let mut flat = PiecewiseCurve::new(flat, curve.breaks().to_vec())?;
    let (start, end) = (flat.eval(lo), flat.eval(hi));
    let closed = start.distance(end) <= tolerance * size;
    if closed {
        flat = super::edge::with_ends(&flat, start, start);
    }
    let edges = split(&flat);
    let area = if closed {
        signed_area(&polygon_of(&edges))
    } else {
        0.0
    };
    if closed && (area.is_nan() || area.abs() <= 1e-12 * size * size) {
        return invalid!("encloses no area");
    }
    Ok(ProfileLoop {
        edges,
        closed,
        area,
    })
}

/// One edge per Bézier segment, on the curve's own parameters.
fn split(curve: &PiecewiseCurve) -> Vec<PiecewiseCurve> {
    let breaks = curve.breaks();
    curve
        .segments()
        .iter()
        .enumerate()
        .map(|(k, s)| {
            PiecewiseCurve::new(vec![s.clone()], breaks[k..=k + 1].to_vec()).expect("a segment")
        })
        .collect()
}

/// A dense polygon through a closed loop (its edges in order).
fn polygon(lp: &ProfileLoop) -> Vec<DVec2> {
    polygon_of(&lp.edges)
}

fn polygon_of(edges: &[PiecewiseCurve]) -> Vec<DVec2> {
    edges
        .iter()
        .flat_map(|e| e.segments())
        .flat_map(|s| (0..POLYGON_SAMPLES).map(move |i| s.eval(i as f64 / POLYGON_SAMPLES as f64)))
        .map(|p| p.truncate())
        .collect()
}

fn signed_area(points: &[DVec2]) -> f64 {
    let n = points.len();
    0.5 * (0..n)
        .map(|i| points[i].perp_dot(points[(i + 1) % n]))
        .sum::<f64>()
}

/// The winding number of the closed polygon around p.
fn winding(polygon: &[DVec2], p: DVec2) -> i32 {
    let n = polygon.len();
    let mut w = 0;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        let side = (b - a).perp_dot(p - a);
        if a.y <= p.y && b.y > p.y && side > 0.0 {
            w += 1;
        } else if a.y > p.y && b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

/// Whether two closed polygons have crossing sides.
fn polygons_cross(a: &[DVec2], b: &[DVec2]) -> bool {
    let sides = |p: &[DVec2]| -> Vec<(DVec2, DVec2)> {
        (0..p.len()).map(|i| (p[i], p[(i + 1) % p.len()])).collect()
    };
    let (sa, sb) = (sides(a), sides(b));
    sa.iter().any(|&(p, q)| {
        sb.iter().any(|&(r, s)| {
            let d1 = (q - p).perp_dot(r - p);
            let d2 = (q - p).perp_dot(s - p);
            let d3 = (s - r).perp_dot(p - r);
            let d4 = (s - r).perp_dot(q - r);
            d1 * d2 <= 0.0 && d3 * d4 <= 0.0
        })
    })
}

/// The profile's segments with their scaled tangents (A, B) = h²ċ, for its support
/// function in many directions.
pub(crate) struct SupportTable {
    segments: Vec<(ProfileSegment, Vec<f64>, Vec<f64>)>,
}

impl SupportTable {
    /// h(d) = max over the profile of c·d: at a segment's ends or where ċ·d = 0.
    pub(super) fn support(&self, d: DVec2) -> f64 {
        self.segments
            .iter()
            .map(|(segment, a, b)| {
                let along: Vec<f64> = a.iter().zip(b).map(|(a, b)| a * d.x + b * d.y).collect();
                critical_points(&along)
                    .into_iter()
                    .map(|s| segment.point(s).dot(d))
                    .fold(f64::NEG_INFINITY, f64::max)
            })
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::tests::circle;

    fn polyline(points: &[(f64, f64)]) -> PiecewiseCurve {
        let points: Vec<DVec3> = points.iter().map(|p| DVec3::new(p.0, p.1, 0.0)).collect();
        crate::primitives::polyline(&points).unwrap()
    }

    #[test]
    fn a_square_has_four_edges_and_quarter_turn_symmetry() {
        let square = polyline(&[(1., 1.), (-1., 1.), (-1., -1.), (1., -1.), (1., 1.)]);
        let profile = Profile::new(&square, &[], true, 1e-9, 1.0).unwrap();
        let lp = &profile.loops[0];
        assert_eq!(lp.edges.len(), 4);
        assert!(lp.closed && (lp.area - 4.0).abs() < 1e-12);
        assert!((profile.support(DVec2::X) - 1.0).abs() < 1e-15);
        assert!((profile.radius() - 2f64.sqrt()).abs() < 1e-15);
        let quarter = profile.symmetry(std::f64::consts::FRAC_PI_2).unwrap();
        assert_eq!(
            quarter[0].iter().map(|i| i.1).collect::<Vec<_>>(),
            [1, 2, 3, 0]
        );
        assert!(profile.symmetry(0.3).is_none());
    }

    #[test]
    fn a_circle_is_four_edges_and_holes_are_loops() {
        let profile = Profile::new(&circle(1.0), &[circle(0.5)], true, 1e-9, 1.0).unwrap();
        assert_eq!(profile.loops[0].edges.len(), 4);
        assert_eq!(profile.loops[1].edges[2].breaks(), &[2.0, 3.0]);
        assert!((profile.radius() - 1.0).abs() < 1e-15);
        assert!((profile.support(DVec2::new(0.6, 0.8)) - 1.0).abs() < 1e-12);
        assert!(profile.loops[1].area > 0.0);
        // A quarter turn maps the quarters onto one another.
        let images = profile.symmetry(std::f64::consts::FRAC_PI_2).unwrap();
        assert_eq!(
            images[1].iter().map(|i| i.1).collect::<Vec<_>>(),
            [1, 2, 3, 0]
        );
    }

    #[test]
    fn bad_profiles_are_refused() {
        let open = polyline(&[(0., 0.), (1., 0.), (1., 1.)]);
        let e = Profile::new(&open, &[], true, 1e-9, 1.0).unwrap_err();
        assert!(e.message().contains("closed profile"), "{e}");
        assert!(Profile::new(&open, &[], false, 1e-9, 1.0).is_ok());
        let e = Profile::new(&open, &[circle(0.1)], false, 1e-9, 1.0).unwrap_err();
        assert!(e.message().contains("holes need a closed"), "{e}");
        let e = Profile::new(&circle(1.0), &[circle(2.0)], true, 1e-9, 1.0).unwrap_err();
        assert!(
            e.message().contains("cross") || e.message().contains("outside"),
            "{e}"
        );
        let lifted = PiecewiseCurve::with_unit_intervals(vec![RationalBezierCurve::polynomial(&[
            DVec3::ZERO,
            DVec3::new(1.0, 0.0, 0.5),
        ])
        .unwrap()])
        .unwrap();
        // A straight profile out of the normal plane lies in the plane through it nearest
        // to the normal plane; a lifted polygon in its own plane.
        let plane = Profile::new(&lifted, &[], false, 1e-9, 1.0)
            .unwrap()
            .plane
            .unwrap();
        assert!((plane.normal - DVec3::new(-0.5, 0.0, 1.0).normalize()).length() < 1e-15);
        let upright = crate::primitives::polyline(&[
            DVec3::ZERO,
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 1.0),
        ])
        .unwrap();
        let e = Profile::new(&upright, &[], false, 1e-9, 1.0).unwrap_err();
        assert!(
            e.message().contains("contains the wire's start tangent"),
            "{e}"
        );
        let skew = crate::primitives::polyline(&[
            DVec3::ZERO,
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(0.0, 1.0, 0.3),
        ])
        .unwrap();
        let e = Profile::new(&skew, &[], false, 1e-9, 1.0).unwrap_err();
        assert!(e.message().contains("off the plane"), "{e}");
    }
}
