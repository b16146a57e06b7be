//! Operations on the sheet-metal entry points (issue 15): transitions between two closed
//! curves — drawn polygons and circles in drawn planes (convex or not, crossing or not) or
//! any curve of the pool —, with drawn options (sizes, tolerances, thickness, K-factor,
//! reference); parts between the rails of drawn ruled surfaces (generalised cylinders,
//! developable, or drawn poles, mostly not) and of tangent surfaces of pool curves between
//! drawn distances; then reports, layer surfaces and boundaries, flat patterns, marks both ways
//! and exports of whatever part was made. Each operation takes, as the input draws, an
//! `RmfSheetPart` with the rmf_sheet_part_* calls or an `RmfConeSpline` with the deprecated
//! rmf_cone_spline_* ones (which refuse a spline that holds no part).

// The deprecated C entry points are fuzzed for as long as they are exported.
#![allow(deprecated)]

use rmfsurf_capi::cone_spline::RmfConeSpline;
use rmfsurf_capi::curve::rmf_nurbs_curve_create;
use rmfsurf_capi::sheet::*;
use rmfsurf_capi::surface::rmf_nurbs_surface_create;
use rmfsurf_capi::{RmfStatus, RmfVec2, RmfVec3};
use std::ptr::{null, null_mut};

use super::session::{checked, is_poisoned, poisoned, poisoned_buffer, Session};

/// The operations of this module.
pub const OPS: &[fn(&mut Session)] = &[
    closed_curve,
    closed_curve,
    transition,
    transition,
    ruled_surface,
    part,
    tangent_part,
    part_cone_spline,
    report,
    layer,
    flat_pattern,
    marks,
    export,
    part_brep,
];

/// A part to read: an `RmfSheetPart` or a cone spline (which may hold one), as drawn.
#[derive(Clone, Copy)]
enum Part {
    New(*const RmfSheetPart),
    Old(*const RmfConeSpline),
}

impl Part {
    fn drawn(s: &mut Session) -> Self {
        if s.input.flag() {
            Part::New(s.part())
        } else {
            Part::Old(s.spline())
        }
    }
}

/// Calls the rmf_sheet_part_* function or its deprecated rmf_cone_spline_* wrapper on a
/// drawn part: (the function's name, its status).
macro_rules! on_part {
    ($part:expr, $new:ident, $old:ident $(, $arg:expr)*) => {
        match $part {
            Part::New(p) => (stringify!($new), unsafe { $new(p $(, $arg)*) }),
            Part::Old(p) => (stringify!($old), unsafe { $old(p $(, $arg)*) }),
        }
    };
}

/// Makes a part with the rmf_sheet_part_* constructor or its deprecated wrapper (as the
/// input draws) and adds it to its pool.
macro_rules! make_part {
    ($s:expr, $new:ident, $old:ident $(, $arg:expr)*) => {
        if $s.input.flag() {
            let mut out = poisoned::<*mut RmfSheetPart>();
            let status = unsafe { $new($($arg,)* &mut out) };
            $s.made_part(stringify!($new), status, out);
        } else {
            let mut out = poisoned::<*mut RmfConeSpline>();
            let status = unsafe { $old($($arg,)* &mut out) };
            $s.made_spline(stringify!($old), status, out);
        }
    };
}

fn add(a: RmfVec3, b: RmfVec3, s: f64) -> RmfVec3 {
    RmfVec3 {
        x: a.x + s * b.x,
        y: a.y + s * b.y,
        z: a.z + s * b.z,
    }
}

/// A polygon or a circle in a drawn plane, added to the pool: corners at drawn radii
/// (convex or not), the circle as four rational quadratics.
fn closed_curve(s: &mut Session) {
    let centre = s.input.vec3();
    let (x, y) = (s.input.small_vec3(), s.input.small_vec3());
    let radius = s.input.f64();
    let mut out = poisoned();
    let status = if s.input.flag() {
        let n = 3 + s.input.below(6);
        let mut poles: Vec<RmfVec3> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                let r = if s.input.below(4) == 0 {
                    s.input.f64()
                } else {
                    radius
                };
                add(add(centre, x, r * a.cos()), y, r * a.sin())
            })
            .collect();
        poles.push(poles[0]);
        let mut knots = vec![0.0];
        knots.extend((0..=n).map(|k| k as f64));
        knots.push(n as f64);
        unsafe {
            rmf_nurbs_curve_create(
                1,
                poles.as_ptr(),
                null(),
                n + 1,
                knots.as_ptr(),
                knots.len(),
                &mut out,
            )
        }
    } else {
        let xs = [1., 1., 0., -1., -1., -1., 0., 1., 1.];
        let ys = [0., 1., 1., 1., 0., -1., -1., -1., 0.];
        let poles: Vec<RmfVec3> = (0..9)
            .map(|i| add(add(centre, x, radius * xs[i]), y, radius * ys[i]))
            .collect();
        let weights: Vec<f64> = (0..9)
            .map(|i| if i % 2 == 1 { 0.5f64.sqrt() } else { 1.0 })
            .collect();
        let knots = [0., 0., 0., 1., 1., 2., 2., 3., 3., 4., 4., 4.];
        unsafe {
            rmf_nurbs_curve_create(
                2,
                poles.as_ptr(),
                weights.as_ptr(),
                9,
                knots.as_ptr(),
                12,
                &mut out,
            )
        }
    };
    s.made("rmf_nurbs_curve_create", status, Some(out), None);
}

/// Sheet options with drawn fields (or NULL for the defaults).
fn options(s: &mut Session) -> Option<RmfSheetOptions> {
    if s.input.below(4) == 0 {
        return None;
    }
    let mut o = RmfSheetOptions::default();
    unsafe { rmf_sheet_options_init(&mut o) };
    if s.input.below(8) == 0 {
        o.struct_size = s.input.work();
    }
    // Mostly coarse tolerances: the fit's cost grows as tolerance^(-1/3).
    o.tolerance = if s.input.flag() {
        1e-2 * (1.0 + s.input.below(9) as f64)
    } else {
        s.input.f64()
    };
    if s.input.flag() {
        o.thickness = s.input.f64();
    }
    if s.input.flag() {
        o.k_factor = s.input.f64();
    }
    if s.input.flag() {
        o.reference = s.input.code();
    }
    if s.input.flag() {
        o.flat_tolerance = s.input.f64();
    }
    o.max_pieces = s.input.work().min(400);
    Some(o)
}

fn transition(s: &mut Session) {
    let (bottom, top) = (s.curve(), s.curve());
    let o = options(s);
    let o = o.as_ref().map_or(null(), |o| o as *const RmfSheetOptions);
    make_part!(
        s,
        rmf_sheet_part_transition,
        rmf_cone_spline_transition,
        bottom,
        top,
        o
    );
}

/// A degree (1, 3) surface, added to the pool: a drawn cubic and its translate by a drawn
/// vector (a generalised cylinder, developable), or eight drawn poles.
fn ruled_surface(s: &mut Session) {
    let first: Vec<RmfVec3> = (0..4).map(|_| s.input.vec3()).collect();
    let second: Vec<RmfVec3> = if s.input.flag() {
        let d = s.input.small_vec3();
        first.iter().map(|&p| add(p, d, 1.0)).collect()
    } else {
        (0..4).map(|_| s.input.vec3()).collect()
    };
    let poles = [first, second].concat();
    let (knots_u, knots_v) = ([0., 0., 1., 1.], [0., 0., 0., 0., 1., 1., 1., 1.]);
    let mut out = poisoned();
    let status = unsafe {
        rmf_nurbs_surface_create(
            1,
            3,
            poles.as_ptr(),
            null(),
            2,
            4,
            knots_u.as_ptr(),
            4,
            knots_v.as_ptr(),
            8,
            &mut out,
        )
    };
    s.made_surface("rmf_nurbs_surface_create", status, out);
}

fn part(s: &mut Session) {
    let surface = s.surface();
    let o = options(s);
    let o = o.as_ref().map_or(null(), |o| o as *const RmfSheetOptions);
    make_part!(
        s,
        rmf_sheet_part_between_rails,
        rmf_cone_spline_part,
        surface,
        o
    );
}

fn tangent_part(s: &mut Session) {
    let curve = s.curve();
    let (v_min, v_max) = (s.input.f64(), s.input.f64());
    let o = options(s);
    let o = o.as_ref().map_or(null(), |o| o as *const RmfSheetOptions);
    make_part!(
        s,
        rmf_sheet_part_tangent,
        rmf_cone_spline_tangent_part,
        curve,
        v_min,
        v_max,
        o
    );
}

/// A part's designed surface as a cone spline, added to the cone spline pool (where the
/// deprecated part calls find the part it holds).
fn part_cone_spline(s: &mut Session) {
    let part = s.part();
    let mut out = poisoned::<*mut RmfConeSpline>();
    let status = unsafe { rmf_sheet_part_cone_spline(part, &mut out) };
    s.made_spline("rmf_sheet_part_cone_spline", status, out);
}

fn report(s: &mut Session) {
    let part = Part::drawn(s);
    let mut r = poisoned::<RmfSheetReport>();
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_report,
        rmf_cone_spline_part_report,
        &mut r
    );
    if checked(name, status, &[is_poisoned(&r)]) {
        assert!(
            r.pieces > 0 && r.deviation >= 0.0 && r.edge_distance.iter().all(|d| d.is_finite())
        );
        assert!(
            r.inner <= r.neutral && r.neutral <= r.outer,
            "layers in order"
        );
    }
}

fn layer(s: &mut Session) {
    let (part, code) = (Part::drawn(s), s.input.code());
    let mut surface = poisoned();
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_surface,
        rmf_cone_spline_part_surface,
        code,
        &mut surface
    );
    s.made_surface(name, status, surface);
    let side = s.input.code();
    let mut curve = poisoned();
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_boundary,
        rmf_cone_spline_part_boundary,
        code,
        side,
        &mut curve
    );
    s.made(name, status, Some(curve), None);
}

fn flat_pattern(s: &mut Session) {
    let part = Part::drawn(s);
    let capacity = s.input.work().min(4096);
    let mut edges = poisoned_buffer::<RmfFlatEdge>(capacity);
    let mut count = poisoned::<usize>();
    let pointer = if capacity == 0 && s.input.flag() {
        null_mut()
    } else {
        edges.as_mut_ptr()
    };
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_flat_pattern,
        rmf_cone_spline_flat_pattern,
        pointer,
        capacity,
        &mut count
    );
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    if checked(
        name,
        status,
        &[
            edges.iter().all(is_poisoned),
            is_poisoned(&count) || too_small,
        ],
    ) && capacity >= count
    {
        let cut: Vec<&RmfFlatEdge> = edges[..count]
            .iter()
            .filter(|e| e.layer == RMF_FLAT_CUT)
            .collect();
        for (k, e) in cut.iter().enumerate() {
            let next = cut[(k + 1) % cut.len()];
            assert!(e.to == next.from, "the outline is closed");
            assert!(e.from.x.is_finite() && e.from.y.is_finite() && e.radius.is_finite());
        }
    }
}

fn marks(s: &mut Session) {
    let (part, n, code) = (Part::drawn(s), s.input.len(6), s.input.code());
    let flat: Vec<RmfVec2> = (0..n)
        .map(|_| RmfVec2 {
            x: s.input.f64(),
            y: s.input.f64(),
        })
        .collect();
    let mut points = poisoned_buffer::<RmfVec3>(n);
    let mut normals = poisoned_buffer::<RmfVec3>(n);
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_flat_to_surface,
        rmf_cone_spline_flat_to_surface,
        flat.as_ptr(),
        n,
        code,
        points.as_mut_ptr(),
        normals.as_mut_ptr()
    );
    let ok = checked(
        name,
        status,
        &[
            points.iter().all(is_poisoned),
            normals.iter().all(is_poisoned),
        ],
    );
    let targets: Vec<RmfVec3> = if ok {
        points
    } else {
        (0..n).map(|_| s.input.vec3()).collect()
    };
    let max_distance = s.input.f64();
    let mut back = poisoned_buffer::<RmfVec2>(n);
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_surface_to_flat,
        rmf_cone_spline_surface_to_flat,
        targets.as_ptr(),
        n,
        code,
        max_distance,
        back.as_mut_ptr()
    );
    if checked(name, status, &[back.iter().all(is_poisoned)]) {
        assert!(back.iter().all(|p| p.x.is_finite() && p.y.is_finite()));
    }
}

fn export(s: &mut Session) {
    let (part, format) = (Part::drawn(s), s.input.code());
    let mut length = poisoned::<usize>();
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_export,
        rmf_cone_spline_part_export,
        format,
        null_mut(),
        0,
        &mut length
    );
    if !checked(name, status, &[is_poisoned(&length)]) {
        return;
    }
    let capacity = if s.input.flag() {
        length + 1
    } else {
        s.input.below(length + 2)
    };
    let mut text = poisoned_buffer::<u8>(capacity);
    let mut written = poisoned::<usize>();
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_export,
        rmf_cone_spline_part_export,
        format,
        text.as_mut_ptr().cast(),
        capacity,
        &mut written
    );
    let too_small = status == RmfStatus::RmfErrorBufferTooSmall;
    if checked(
        name,
        status,
        &[
            text.iter().all(is_poisoned) || capacity == 0,
            is_poisoned(&written) || too_small,
        ],
    ) && capacity > 0
    {
        assert_eq!(written, length);
        assert_eq!(text[length], 0, "NUL-terminated");
    }
}

/// The B-rep model of the part's solid (rmf_sheet_part_brep), walked and freed
/// (`brep::walk`); a cone spline that is not a part is refused unwritten.
fn part_brep(s: &mut Session) {
    let part = Part::drawn(s);
    let mut brep = poisoned::<*mut rmfsurf_capi::RmfBrep>();
    let (name, status) = on_part!(
        part,
        rmf_sheet_part_brep,
        rmf_cone_spline_part_brep,
        &mut brep
    );
    if checked(name, status, &[is_poisoned(&brep)]) {
        super::brep::walk(brep);
    }
}
