//! From homogeneous coordinates (w·x, w·y, w·z, w) to Cartesian points and their
//! derivatives, by the quotient rule applied to p = N / w:
//!
//! p' = (N' − w' p) / w,  p'' = (N'' − 2 w' p' − w'' p) / w,
//! p_uv = (N_uv − w_uv p − w_u p_v − w_v p_u) / w.

use glam::{DVec3, DVec4};

/// Cartesian point of a homogeneous point (w ≠ 0).
pub(crate) fn project(h: DVec4) -> DVec3 {
    h.truncate() / h.w
}

/// Homogeneous point with weight `w` of the Cartesian point `p`.
pub(crate) fn lift(p: DVec3, w: f64) -> DVec4 {
    (p * w).extend(w)
}

/// Point, first and second derivative of a rational curve from the homogeneous ones.
pub(crate) fn rational_jet(h: DVec4, h1: DVec4, h2: DVec4) -> [DVec3; 3] {
    let p = project(h);
    let d1 = (h1.truncate() - h1.w * p) / h.w;
    let d2 = (h2.truncate() - 2.0 * h1.w * d1 - h2.w * p) / h.w;
    [p, d1, d2]
}

/// Cartesian point and first three derivatives of a rational curve from the homogeneous
/// derivatives h, h', h'', h''' (Leibniz' rule on h = w x, solved for x⁽ᵏ⁾).
pub(crate) fn rational_jet3(h: DVec4, h1: DVec4, h2: DVec4, h3: DVec4) -> [DVec3; 4] {
    let [p, d1, d2] = rational_jet(h, h1, h2);
    let d3 = (h3.truncate() - 3.0 * h1.w * d2 - 3.0 * h2.w * d1 - h3.w * p) / h.w;
    [p, d1, d2, d3]
}

/// Homogeneous partial derivatives of a surface at one point, indexed by their orders.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct HomogeneousPartials {
    pub s: DVec4,
    pub su: DVec4,
    pub sv: DVec4,
    pub suu: DVec4,
    pub suv: DVec4,
    pub svv: DVec4,
}

/// Cartesian point and partial derivatives of a surface: `[s, s_u, s_v, s_uu, s_uv, s_vv]`.
pub(crate) fn rational_partials(h: &HomogeneousPartials) -> [DVec3; 6] {
    let w = h.s.w;
    let p = project(h.s);
    let pu = (h.su.truncate() - h.su.w * p) / w;
    let pv = (h.sv.truncate() - h.sv.w * p) / w;
    let puu = (h.suu.truncate() - 2.0 * h.su.w * pu - h.suu.w * p) / w;
    let pvv = (h.svv.truncate() - 2.0 * h.sv.w * pv - h.svv.w * p) / w;
    let puv = (h.suv.truncate() - h.suv.w * p - h.su.w * pv - h.sv.w * pu) / w;
    [p, pu, pv, puu, puv, pvv]
}
