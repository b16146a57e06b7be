//! Plain data exchanged with C: vectors and borrowed views of NURBS and Bézier data.

use rmfsurf::glam::{DVec3, DVec4};

/// C-layout copies of Bézier pieces (segments or patches): Cartesian poles and weights of
/// each, the arrays behind `RmfBezierCurve` and `RmfBezierPatch` views.
pub(crate) type PieceViews = Vec<(Vec<RmfVec3>, Vec<f64>)>;

/// Piece views from the homogeneous control points of each piece.
pub(crate) fn piece_views<'a>(pieces: impl Iterator<Item = &'a [DVec4]>) -> PieceViews {
    pieces
        .map(|points| {
            let poles = points
                .iter()
                .map(|&h| (h.truncate() / h.w).into())
                .collect();
            (poles, points.iter().map(|h| h.w).collect())
        })
        .collect()
}

/// A point or vector in 3-space.
/// \ingroup rmf_foundation
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RmfVec3 {
    /// The x coordinate.
    pub x: f64,
    /// The y coordinate.
    pub y: f64,
    /// The z coordinate.
    pub z: f64,
}

impl From<DVec3> for RmfVec3 {
    fn from(v: DVec3) -> Self {
        Self {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    }
}

impl From<RmfVec3> for DVec3 {
    fn from(v: RmfVec3) -> Self {
        DVec3::new(v.x, v.y, v.z)
    }
}

/// A point or vector in a plane (a flat pattern's coordinates).
/// \ingroup rmf_sheet
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RmfVec2 {
    /// The x coordinate.
    pub x: f64,
    /// The y coordinate.
    pub y: f64,
}

impl From<rmfsurf::glam::DVec2> for RmfVec2 {
    fn from(v: rmfsurf::glam::DVec2) -> Self {
        Self { x: v.x, y: v.y }
    }
}

impl From<RmfVec2> for rmfsurf::glam::DVec2 {
    fn from(v: RmfVec2) -> Self {
        rmfsurf::glam::DVec2::new(v.x, v.y)
    }
}

/// Borrowed view of a NURBS curve, the layout of OpenCascade Geom_BSplineCurve, FreeCAD
/// Part.BSplineCurve, IGES 126 and STEP (with knots listed one by one, not with
/// multiplicities).
///
/// The arrays are owned by the curve handle: do not free them; they stay valid until the
/// handle is freed.
/// \ingroup rmf_curves
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfNurbsCurve {
    /// Polynomial degree p ≥ 1.
    pub degree: u32,
    /// Number of poles n ≥ p + 1.
    pub pole_count: usize,
    /// pole_count Cartesian poles.
    pub poles: *const RmfVec3,
    /// pole_count weights, all > 0.
    pub weights: *const f64,
    /// pole_count + degree + 1.
    pub knot_count: usize,
    /// Clamped, non-decreasing knot vector; curves built by the library have interior knots
    /// of full multiplicity p at segment joints.
    pub knots: *const f64,
}

impl RmfNurbsCurve {
    /// The view of `curve` whose poles, in the C layout, are at `poles` (owned beside it).
    pub(crate) fn of(curve: &rmfsurf::NurbsCurve, poles: *const RmfVec3) -> Self {
        Self {
            degree: curve.degree() as u32,
            pole_count: curve.poles().len(),
            poles,
            weights: curve.weights().as_ptr(),
            knot_count: curve.knots().len(),
            knots: curve.knots().as_ptr(),
        }
    }
}

/// The empty view: no poles, null pointers (a field for a kind of geometry a struct does
/// not hold).
impl Default for RmfNurbsCurve {
    fn default() -> Self {
        Self {
            degree: 0,
            pole_count: 0,
            poles: std::ptr::null(),
            weights: std::ptr::null(),
            knot_count: 0,
            knots: std::ptr::null(),
        }
    }
}

/// Borrowed view of a NURBS surface. Pole (i, j) is at index `i * pole_count_v + j`, i along
/// u; the arrays are owned by the surface handle (do not free; valid until it is freed).
/// \ingroup rmf_surfaces
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfNurbsSurface {
    /// Degree along u.
    pub degree_u: u32,
    /// Degree along v.
    pub degree_v: u32,
    /// Number of poles along u.
    pub pole_count_u: usize,
    /// Number of poles along v.
    pub pole_count_v: usize,
    /// pole_count_u * pole_count_v Cartesian poles, index i * pole_count_v + j.
    pub poles: *const RmfVec3,
    /// Weights in the same order, all > 0.
    pub weights: *const f64,
    /// pole_count_u + degree_u + 1.
    pub knot_count_u: usize,
    /// knot_count_u clamped knots along u.
    pub knots_u: *const f64,
    /// pole_count_v + degree_v + 1.
    pub knot_count_v: usize,
    /// knot_count_v clamped knots along v.
    pub knots_v: *const f64,
}

impl RmfNurbsSurface {
    /// The view of `surface` whose poles, in the C layout, are at `poles` (owned beside it).
    pub(crate) fn of(surface: &rmfsurf::NurbsSurface, poles: *const RmfVec3) -> Self {
        Self {
            degree_u: surface.degree_u() as u32,
            degree_v: surface.degree_v() as u32,
            pole_count_u: surface.pole_count_u(),
            pole_count_v: surface.pole_count_v(),
            poles,
            weights: surface.weights().as_ptr(),
            knot_count_u: surface.knots_u().len(),
            knots_u: surface.knots_u().as_ptr(),
            knot_count_v: surface.knots_v().len(),
            knots_v: surface.knots_v().as_ptr(),
        }
    }
}

/// The empty view: no poles, null pointers.
impl Default for RmfNurbsSurface {
    fn default() -> Self {
        Self {
            degree_u: 0,
            degree_v: 0,
            pole_count_u: 0,
            pole_count_v: 0,
            poles: std::ptr::null(),
            weights: std::ptr::null(),
            knot_count_u: 0,
            knots_u: std::ptr::null(),
            knot_count_v: 0,
            knots_v: std::ptr::null(),
        }
    }
}

/// Borrowed view of one rational Bézier segment of a curve: degree + 1 poles and weights
/// for the parameter interval [t_start, t_end] of the curve (the Bernstein basis runs over
/// that interval). Owned by the curve handle.
/// \ingroup rmf_curves
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBezierCurve {
    /// Polynomial degree.
    pub degree: u32,
    /// degree + 1 Cartesian poles.
    pub poles: *const RmfVec3,
    /// degree + 1 weights, all > 0.
    pub weights: *const f64,
    /// Start of the segment's interval in the curve's parameter.
    pub t_start: f64,
    /// End of the segment's interval.
    pub t_end: f64,
}

/// Borrowed view of one rational tensor-product Bézier patch of a surface:
/// (degree_u + 1) * (degree_v + 1) poles, index `i * (degree_v + 1) + j`, on
/// [u_start, u_end] × [v_start, v_end]. Owned by the surface handle.
/// \ingroup rmf_surfaces
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfBezierPatch {
    /// Degree along u.
    pub degree_u: u32,
    /// Degree along v.
    pub degree_v: u32,
    /// (degree_u + 1) * (degree_v + 1) Cartesian poles, index i * (degree_v + 1) + j.
    pub poles: *const RmfVec3,
    /// Weights in the same order, all > 0.
    pub weights: *const f64,
    /// Start of the patch's u interval in the surface's parameter.
    pub u_start: f64,
    /// End of the u interval.
    pub u_end: f64,
    /// Start of the patch's v interval.
    pub v_start: f64,
    /// End of the v interval.
    pub v_end: f64,
}
