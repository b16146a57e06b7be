//! What kind of surface a face lies on, told from its geometry alone (a kernel converts
//! its cylinders and cones to rational B-splines, a STEP file may carry either): a plane
//! when all poles lie in one; otherwise a developable is ruled ([LP] (2): K = 0), and a
//! surface of degree 1 in one parameter has its rulings along it. Its rulings are
//! parallel on a (general) cylinder, concurrent on a (general) cone — a right circular
//! one when their unit directions from the apex make one angle with an axis, a circular
//! cylinder when its cross-section is a circle —, tangent to a curve of regression on a
//! tangent developable ([LP] (1)), and of several of these kinds on an "other" ruled
//! developable (such as a cone spline). Tests are to [`SHAPE_TOLERANCE`] of the face's
//! size, far below any tolerance a user gives, far above the round-off of exact data.

use crate::bezier::{PiecewiseSurface, RationalBezierPatch};
use crate::cone_spline::developable::DEVELOPABILITY_TOLERANCE;
use crate::error::Result;
use crate::math::solve_refined;
use glam::{DMat3, DVec3};

/// Relative distance within which a surface is taken as a plane, a cylinder or a cone.
pub(crate) const SHAPE_TOLERANCE: f64 = 1e-9;
/// Rulings sampled per Bézier span of a ruled surface.
const RULINGS_PER_SPAN: usize = 8;

/// The kinds of surface a face can lie on, as the developability report names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SurfaceKind {
    /// A plane.
    Plane,
    /// A circular cylinder.
    CircularCylinder,
    /// A right circular cone.
    RightCone,
    /// A cylinder over any cross-section (parallel rulings).
    GeneralCylinder,
    /// A cone over any cross-section (rulings through one apex).
    GeneralCone,
    /// The tangent surface of a space curve.
    TangentDevelopable,
    /// A developable of several of the kinds above joined along rulings.
    RuledDevelopable,
    /// Gaussian curvature beyond the developability tolerance.
    NotDevelopable,
}

impl SurfaceKind {
    /// Whether faces of this kind unroll without stretching.
    pub fn is_developable(self) -> bool {
        self != SurfaceKind::NotDevelopable
    }
}

/// A face's surface as recognized, in internal coordinates.
#[derive(Clone, Debug)]
pub(crate) enum Recognized {
    /// origin + x·u + y·v, x and y orthonormal.
    Plane { origin: DVec3, x: DVec3, y: DVec3 },
    /// Points at `radius` from the line through `origin` along the unit `axis`; `x` a unit
    /// vector normal to the axis.
    Cylinder {
        origin: DVec3,
        axis: DVec3,
        x: DVec3,
        radius: f64,
    },
    /// Rulings from `apex` making the angle α (sin α = `sin`) with the unit `axis`; `x` a
    /// unit vector normal to the axis.
    Cone {
        apex: DVec3,
        axis: DVec3,
        x: DVec3,
        sin: f64,
    },
    /// Any other ruled surface, rulings along u, of the given kind (NotDevelopable when
    /// its curvature exceeds the developability tolerance).
    Ruled {
        surface: PiecewiseSurface,
        kind: SurfaceKind,
    },
    /// A surface that is neither a plane nor ruled along a parameter.
    Other {
        surface: PiecewiseSurface,
        developable: bool,
    },
}

impl Recognized {
    /// The kind the report names.
    pub(super) fn kind(&self) -> SurfaceKind {
        match self {
            Recognized::Plane { .. } => SurfaceKind::Plane,
            Recognized::Cylinder { .. } => SurfaceKind::CircularCylinder,
            Recognized::Cone { .. } => SurfaceKind::RightCone,
            Recognized::Ruled { kind, .. } => *kind,
            Recognized::Other { developable, .. } => {
                if *developable {
                    SurfaceKind::RuledDevelopable
                } else {
                    SurfaceKind::NotDevelopable
                }
            }
        }
    }
}

/// The plane through the poles, if they all lie in one.
pub(crate) fn plane_of(points: &[DVec3]) -> Option<(DVec3, DVec3)> {
    let origin = *points.first()?;
    let far = points.iter().copied().max_by(|a, b| {
        a.distance_squared(origin)
            .total_cmp(&b.distance_squared(origin))
    })?;
    let along = far - origin;
    let normal = points
        .iter()
        .map(|p| along.cross(*p - origin))
        .max_by(|a, b| a.length_squared().total_cmp(&b.length_squared()))?;
    if normal.length() <= SHAPE_TOLERANCE * along.length() {
        return None;
    }
    let normal = normal.normalize();
    let size = along.length();
    points
        .iter()
        .all(|p| (*p - origin).dot(normal).abs() <= SHAPE_TOLERANCE * size)
        .then_some((origin, normal))
}

/// The surface with u and v exchanged.
fn transposed(surface: &PiecewiseSurface) -> Result<PiecewiseSurface> {
    let (nu, nv) = (surface.u_breaks().len() - 1, surface.v_breaks().len() - 1);
    let mut patches = Vec::with_capacity(nu * nv);
    for b in 0..nv {
        for a in 0..nu {
            let p = surface.patch(a, b);
            let (du, dv) = (p.degree_u(), p.degree_v());
            let points = (0..=dv)
                .flat_map(|j| (0..=du).map(move |i| p.at(i, j)))
                .collect();
            patches.push(RationalBezierPatch::from_homogeneous(dv, du, points)?);
        }
    }
    PiecewiseSurface::new(
        patches,
        surface.v_breaks().to_vec(),
        surface.u_breaks().to_vec(),
    )
}

/// Recognizes a NURBS face surface (internal coordinates) whose largest |K|·size² is
/// `curvature`.
pub(crate) fn recognize(surface: &PiecewiseSurface, curvature: f64) -> Result<Recognized> {
    let poles: Vec<DVec3> = surface
        .patches()
        .iter()
        .flat_map(|p| p.homogeneous().iter().map(|h| h.truncate() / h.w))
        .collect();
    if let Some((origin, normal)) = plane_of(&poles) {
        let x = normal.any_orthonormal_vector();
        return Ok(Recognized::Plane {
            origin,
            x,
            y: normal.cross(x),
        });
    }
    let ruled_along = |s: &PiecewiseSurface, u: bool| {
        let (breaks, degree) = if u {
            (
                s.u_breaks().len(),
                s.patches().iter().all(|p| p.degree_u() == 1),
            )
        } else {
            (
                s.v_breaks().len(),
                s.patches().iter().all(|p| p.degree_v() == 1),
            )
        };
        breaks == 2 && degree
    };
    let ruled = if ruled_along(surface, true) {
        Some(surface.clone())
    } else if ruled_along(surface, false) {
        Some(transposed(surface)?)
    } else {
        None
    };
    let developable = curvature <= DEVELOPABILITY_TOLERANCE;
    let Some(ruled) = ruled else {
        return Ok(Recognized::Other {
            surface: surface.clone(),
            developable,
        });
    };
    if !developable {
        return Ok(Recognized::Ruled {
            surface: ruled,
            kind: SurfaceKind::NotDevelopable,
        });
    }
    Ok(ruled_kind(ruled))
}

/// The rulings of a surface ruled along u, sampled per span in v: (first rail point, second).
fn rulings(surface: &PiecewiseSurface, span: Option<usize>) -> Vec<(DVec3, DVec3)> {
    let (u0, u1) = surface.domain_u();
    let breaks = surface.v_breaks();
    let spans = match span {
        Some(k) => k..k + 1,
        None => 0..breaks.len() - 1,
    };
    spans
        .flat_map(|k| {
            (0..=RULINGS_PER_SPAN).map(move |j| {
                breaks[k] + (breaks[k + 1] - breaks[k]) * j as f64 / RULINGS_PER_SPAN as f64
            })
        })
        .map(|v| (surface.eval(u0, v), surface.eval(u1, v)))
        .collect()
}

/// How a set of rulings meets: all parallel, all through one apex, or neither.
enum Meeting {
    Parallel(DVec3),
    Apex(DVec3),
    Neither,
}

fn meeting(lines: &[(DVec3, DVec3)]) -> Meeting {
    let directions: Vec<DVec3> = lines.iter().map(|(a, b)| (*b - *a).normalize()).collect();
    let d0 = directions[0];
    if directions
        .iter()
        .all(|d| d.cross(d0).length() <= SHAPE_TOLERANCE)
    {
        return Meeting::Parallel(d0);
    }
    // The point nearest to all lines: Σ (I − d dᵀ) x = Σ (I − d dᵀ) a.
    let mut m = DMat3::ZERO;
    let mut rhs = DVec3::ZERO;
    for ((a, _), d) in lines.iter().zip(&directions) {
        let projector = DMat3::IDENTITY - DMat3::from_cols(*d * d.x, *d * d.y, *d * d.z);
        m += projector;
        rhs += projector * *a;
    }
    let Some(apex) = solve_refined(m.transpose(), rhs) else {
        return Meeting::Neither;
    };
    let off_line = |(a, d): (&DVec3, &DVec3)| (apex - *a).cross(*d).length();
    let worst = lines
        .iter()
        .map(|(a, _)| a)
        .zip(&directions)
        .map(off_line)
        .fold(0.0, f64::max);
    if apex.is_finite() && worst <= SHAPE_TOLERANCE * (1.0 + apex.length()) {
        Meeting::Apex(apex)
    } else {
        Meeting::Neither
    }
}

/// The kind of a developable surface ruled along u.
fn ruled_kind(surface: PiecewiseSurface) -> Recognized {
    let lines = rulings(&surface, None);
    match meeting(&lines) {
        Meeting::Parallel(axis) => circular_cylinder(&lines, axis).unwrap_or(Recognized::Ruled {
            surface,
            kind: SurfaceKind::GeneralCylinder,
        }),
        Meeting::Apex(apex) => right_cone(&lines, apex).unwrap_or(Recognized::Ruled {
            surface,
            kind: SurfaceKind::GeneralCone,
        }),
        Meeting::Neither => {
            let spans = surface.v_breaks().len() - 1;
            let mixed = (0..spans)
                .any(|k| !matches!(meeting(&rulings(&surface, Some(k))), Meeting::Neither));
            let kind = if mixed {
                SurfaceKind::RuledDevelopable
            } else {
                SurfaceKind::TangentDevelopable
            };
            Recognized::Ruled { surface, kind }
        }
    }
}

/// The circle through three points (centre, radius), `None` when they are collinear.
fn circle_through(a: DVec3, b: DVec3, c: DVec3) -> Option<(DVec3, f64)> {
    let (u, v) = (b - a, c - a);
    let n = u.cross(v);
    if n.length_squared() <= 1e-300 {
        return None;
    }
    let centre = a
        + (v.length_squared() * n.cross(u) + u.length_squared() * v.cross(n))
            / (2.0 * n.length_squared());
    Some((centre, centre.distance(a)))
}

fn circular_cylinder(lines: &[(DVec3, DVec3)], axis: DVec3) -> Option<Recognized> {
    let across = |p: DVec3| p - p.dot(axis) * axis;
    let points: Vec<DVec3> = lines
        .iter()
        .flat_map(|(a, b)| [across(*a), across(*b)])
        .collect();
    // Thirds, not ends: a closed surface's first and last rulings coincide.
    let n = lines.len();
    let (first, second, third) = (lines[0].0, lines[n / 3].0, lines[2 * n / 3].0);
    let (centre, radius) = circle_through(across(first), across(second), across(third))?;
    let round = points
        .iter()
        .all(|p| (p.distance(centre) - radius).abs() <= SHAPE_TOLERANCE);
    round.then(|| Recognized::Cylinder {
        origin: centre,
        axis,
        x: (across(first) - centre).normalize(),
        radius,
    })
}

fn right_cone(lines: &[(DVec3, DVec3)], apex: DVec3) -> Option<Recognized> {
    // Unit directions from the apex towards each ruling's far end.
    let tips: Vec<DVec3> = lines
        .iter()
        .map(|(a, b)| {
            let far = if a.distance(apex) > b.distance(apex) {
                *a
            } else {
                *b
            };
            (far - apex).normalize()
        })
        .collect();
    let n = tips.len();
    let (e0, e1, e2) = (tips[0], tips[n / 3], tips[2 * n / 3]);
    let (centre, _) = circle_through(e0, e1, e2)?;
    let axis = centre.normalize();
    let cos = e0.dot(axis);
    let round = tips
        .iter()
        .all(|e| (e.dot(axis) - cos).abs() <= SHAPE_TOLERANCE);
    let sin = e0.cross(axis).length();
    (round && sin > SHAPE_TOLERANCE).then(|| Recognized::Cone {
        apex,
        axis,
        x: (e0 - cos * axis).normalize(),
        sin,
    })
}
