//! The table of bad inputs in docs/hardening.md, checked: every row is a call through the C
//! API with one bad argument, the status it must return, and the argument its message must
//! name. The test runs each call and then checks that the table lists the same rows with the
//! same status (so the table cannot drift from the library).

use rmfsurf_capi::cone_spline::*;
use rmfsurf_capi::curve::*;
use rmfsurf_capi::frames::*;
use rmfsurf_capi::mobius::*;
use rmfsurf_capi::ph_cubic::*;
use rmfsurf_capi::rrmf_quintic::*;
use rmfsurf_capi::shape::*;
use rmfsurf_capi::sheet::*;
use rmfsurf_capi::status::{rmf_last_error, rmf_status_name};
use rmfsurf_capi::surface::*;
use rmfsurf_capi::wire::*;
use rmfsurf_capi::{RmfCurve, RmfFrames, RmfShape, RmfStatus, RmfVec2, RmfVec3};
use std::ffi::{c_void, CStr};
use std::ptr::{null, null_mut};

const NAN: f64 = f64::NAN;

fn v(x: f64, y: f64, z: f64) -> RmfVec3 {
    RmfVec3 { x, y, z }
}

/// A valid cubic NURBS curve (the arguments the NURBS rows break one at a time).
struct Nurbs {
    degree: u32,
    poles: Vec<RmfVec3>,
    weights: Vec<f64>,
    knots: Vec<f64>,
}

impl Nurbs {
    fn valid() -> Self {
        Self {
            degree: 3,
            poles: vec![v(0., 0., 0.), v(1., 2., 0.), v(2., -1., 1.), v(3., 0., 2.)],
            weights: vec![1.0; 4],
            knots: vec![0., 0., 0., 0., 1., 1., 1., 1.],
        }
    }

    fn create(&self) -> (RmfStatus, *mut RmfCurve) {
        let mut out = null_mut();
        let status = unsafe {
            rmf_nurbs_curve_create(
                self.degree,
                self.poles.as_ptr(),
                self.weights.as_ptr(),
                self.poles.len(),
                self.knots.as_ptr(),
                self.knots.len(),
                &mut out,
            )
        };
        (status, out)
    }
}

/// Helix Hermite data (valid), 5 points.
fn helix() -> (Vec<RmfVec3>, Vec<RmfVec3>) {
    (0..5)
        .map(|i| {
            let t = 0.7 * i as f64;
            (v(t.cos(), t.sin(), 0.4 * t), v(-t.sin(), t.cos(), 0.4))
        })
        .unzip()
}

/// Valid handles for the rows that need them.
struct Fixtures {
    curve: *mut RmfCurve,
    ph_spline: *mut RmfCurve,
    rmf: *mut RmfFrames,
}

impl Fixtures {
    fn new() -> Self {
        let (points, tangents) = helix();
        let (mut ph_spline, mut rmf) = (null_mut(), null_mut());
        unsafe {
            assert_eq!(
                rmf_ph_spline_hermite(points.as_ptr(), tangents.as_ptr(), 5, &mut ph_spline),
                RmfStatus::RmfOk
            );
            assert_eq!(
                rmf_ph_rational_rmf(ph_spline, v(0., 0., 1.), &mut rmf),
                RmfStatus::RmfOk
            );
        }
        let (status, curve) = Nurbs::valid().create();
        assert_eq!(status, RmfStatus::RmfOk);
        Self {
            curve,
            ph_spline,
            rmf,
        }
    }
}

/// rmf_cone_spline_approximate_with_options on the fixtures' curve with default options at
/// tolerance 1e-3, changed by `edit`; `null_options` passes NULL instead.
fn cone_with(
    f: &Fixtures,
    edit: impl Fn(&mut RmfConeApproximationOptions),
    null_options: bool,
) -> RmfStatus {
    let mut options = std::mem::MaybeUninit::uninit();
    unsafe {
        assert_eq!(
            rmf_cone_approximation_options_init(options.as_mut_ptr()),
            RmfStatus::RmfOk
        );
    }
    let mut options = unsafe { options.assume_init() };
    options.tolerance = 1e-3;
    edit(&mut options);
    let options: *const RmfConeApproximationOptions = if null_options { null() } else { &options };
    let mut out = null_mut();
    unsafe {
        rmf_cone_spline_approximate_with_options(f.curve, 0.5, 1.0, options, &mut out, null_mut())
    }
}

/// rmf_nurbs_surface_create_from on a valid bilinear patch changed by `edit`.
fn surface_from(edit: impl Fn(&mut RmfNurbsSurfaceData)) -> RmfStatus {
    let poles = [v(0., 0., 0.), v(0., 1., 0.), v(1., 0., 0.), v(1., 1., 1.)];
    let knots = [0., 0., 1., 1.];
    let mut data = RmfNurbsSurfaceData {
        struct_size: std::mem::size_of::<RmfNurbsSurfaceData>(),
        degree_u: 1,
        degree_v: 1,
        pole_count_u: 2,
        pole_count_v: 2,
        poles: poles.as_ptr(),
        weights: null(),
        knot_count_u: 4,
        knots_u: knots.as_ptr(),
        knot_count_v: 4,
        knots_v: knots.as_ptr(),
    };
    edit(&mut data);
    let mut out = null_mut();
    let status = unsafe { rmf_nurbs_surface_create_from(&data, &mut out) };
    unsafe { rmf_surface_free(out) };
    status
}

/// rmf_surface_nurbs_copy_into of the saddle as a size query, its buffers changed by
/// `edit`; `null_buffers` passes NULL instead.
fn copy_into(edit: impl Fn(&mut RmfNurbsSurfaceBuffers), null_buffers: bool) -> RmfStatus {
    let surface = saddle_surface();
    let mut buffers = RmfNurbsSurfaceBuffers {
        struct_size: std::mem::size_of::<RmfNurbsSurfaceBuffers>(),
        poles: null_mut(),
        weights: null_mut(),
        pole_capacity: 0,
        knots_u: null_mut(),
        knot_capacity_u: 0,
        knots_v: null_mut(),
        knot_capacity_v: 0,
    };
    edit(&mut buffers);
    let buffers: *const RmfNurbsSurfaceBuffers = if null_buffers { null() } else { &buffers };
    let mut copy = std::mem::MaybeUninit::uninit();
    let status = unsafe { rmf_surface_nurbs_copy_into(surface, buffers, copy.as_mut_ptr()) };
    unsafe { rmf_surface_free(surface) };
    status
}

/// The size query of `rmf_sweep_parabolic_curves` for the fixtures' sweep of their curve.
fn parabolic_curves_count(f: &Fixtures, tolerance: f64) -> RmfStatus {
    let mut count = 0;
    unsafe {
        rmf_sweep_parabolic_curves(
            f.ph_spline,
            f.rmf,
            f.curve,
            tolerance,
            null_mut(),
            0,
            &mut count,
        )
    }
}

/// The size query of `rmf_sweep_parabolic_points` for the fixtures' sweep of `profile`.
fn parabolic_points_count(f: &Fixtures, profile: *mut RmfCurve, v_samples: u32) -> RmfStatus {
    let mut count = 0;
    unsafe {
        rmf_sweep_parabolic_points(
            f.ph_spline,
            f.rmf,
            profile,
            v_samples,
            null_mut(),
            0,
            &mut count,
        )
    }
}

impl Drop for Fixtures {
    fn drop(&mut self) {
        unsafe {
            rmf_frames_free(self.rmf);
            rmf_curve_free(self.ph_spline);
            rmf_curve_free(self.curve);
        }
    }
}

/// rmf_ph_spline_approximate_with_options on the fixtures' curve at 1e-3 with one option
/// edited, and a report whose struct_size is `report_size` (None: no report).
fn approximate_with(
    f: &Fixtures,
    edit: impl Fn(&mut RmfPhApproximationOptions),
    report_size: Option<usize>,
) -> RmfStatus {
    let mut options = std::mem::MaybeUninit::uninit();
    unsafe {
        assert_eq!(
            rmf_ph_approximation_options_init(options.as_mut_ptr()),
            RmfStatus::RmfOk
        );
    }
    let mut options = unsafe { options.assume_init() };
    options.tolerance = 1e-3;
    edit(&mut options);
    let mut report = RmfPhApproximationReport::default();
    let report = match report_size {
        Some(size) => {
            report.struct_size = size;
            &mut report as *mut _
        }
        None => null_mut(),
    };
    let mut out = null_mut();
    unsafe { rmf_ph_spline_approximate_with_options(f.curve, &options, &mut out, report) }
}

/// rmf_rrmf_spline_hermite_with_options on the helix data with one option edited (the
/// normal set first), and a report whose struct_size is `report_size` (None: no report).
fn rrmf_spline_with(
    edit: impl Fn(&mut RmfRrmfSplineOptions),
    report_size: Option<usize>,
) -> RmfStatus {
    let (points, tangents) = helix();
    let mut options = std::mem::MaybeUninit::uninit();
    unsafe {
        assert_eq!(
            rmf_rrmf_spline_options_init(options.as_mut_ptr()),
            RmfStatus::RmfOk
        );
    }
    let mut options = unsafe { options.assume_init() };
    options.eta_samples = 8;
    options.initial_normal = v(0.0, 0.0, 1.0);
    edit(&mut options);
    let mut report = RmfRrmfSplineReport::default();
    let report = match report_size {
        Some(size) => {
            report.struct_size = size;
            &mut report as *mut _
        }
        None => null_mut(),
    };
    let (mut curve, mut frames) = (null_mut(), null_mut());
    let status = unsafe {
        rmf_rrmf_spline_hermite_with_options(
            points.as_ptr(),
            tangents.as_ptr(),
            points.len(),
            &options,
            &mut curve,
            &mut frames,
            report,
        )
    };
    assert!(curve.is_null() && frames.is_null(), "outputs untouched");
    status
}

/// A Hermite call of the PH, Möbius and RRMF splines on broken helix data.
fn ph_spline_with(edit: impl Fn(&mut Vec<RmfVec3>, &mut Vec<RmfVec3>)) -> RmfStatus {
    let (mut points, mut tangents) = helix();
    edit(&mut points, &mut tangents);
    let mut out = null_mut();
    unsafe { rmf_ph_spline_hermite(points.as_ptr(), tangents.as_ptr(), points.len(), &mut out) }
}

unsafe extern "C" fn nan_callback(
    _: f64,
    _: *mut c_void,
    point: *mut RmfVec3,
    tangent: *mut RmfVec3,
) {
    *point = v(NAN, 0.0, 0.0);
    *tangent = v(1.0, 0.0, 0.0);
}

unsafe extern "C" fn twisted_cubic(
    t: f64,
    _: *mut c_void,
    point: *mut RmfVec3,
    tangent: *mut RmfVec3,
) {
    *point = v(t, t * t, t * t * t);
    *tangent = v(1.0, 2.0 * t, 3.0 * t * t);
}

/// A line edge of a wire.
fn line(a: RmfVec3, b: RmfVec3) -> RmfEdge {
    RmfEdge {
        kind: RMF_EDGE_LINE,
        points: [a, b, v(0., 0., 0.)],
        curve: null(),
    }
}

/// Line (10) – tangent quarter arc (radius 5) – line (10).
fn pipe_route() -> Vec<RmfEdge> {
    let s = std::f64::consts::FRAC_1_SQRT_2;
    vec![
        line(v(0., 0., 0.), v(10., 0., 0.)),
        RmfEdge {
            kind: RMF_EDGE_ARC,
            points: [
                v(10., 0., 0.),
                v(10. + 5. * s, 5. - 5. * s, 0.),
                v(15., 5., 0.),
            ],
            curve: null(),
        },
        line(v(15., 5., 0.), v(15., 15., 0.)),
    ]
}

/// A NURBS curve from poles (one Bézier segment, or degree 1 through them).
fn curve(degree: u32, poles: &[RmfVec3]) -> *mut RmfCurve {
    let n = poles.len();
    let knots: Vec<f64> = if degree as usize + 1 == n {
        [vec![0.0; n], vec![1.0; n]].concat()
    } else {
        let mut k = vec![0.0];
        k.extend((0..n).map(|i| i as f64));
        k.push((n - 1) as f64);
        k
    };
    let mut out = null_mut();
    let status = unsafe {
        rmf_nurbs_curve_create(
            degree,
            poles.as_ptr(),
            null(),
            n,
            knots.as_ptr(),
            knots.len(),
            &mut out,
        )
    };
    assert_eq!(status, RmfStatus::RmfOk);
    out
}

/// The circle of radius r (four rational quarters).
fn circle(r: f64) -> *mut RmfCurve {
    circle_curve(v(0.0, 0.0, 0.0), r)
}

/// rmf_wire_sweep of `edges` and `profile` (freed after) with `holes` and options edited by
/// `edit`; the shape, if any, is freed.
fn wire_sweep(
    edges: &[RmfEdge],
    profile: *mut RmfCurve,
    holes: &[*mut RmfCurve],
    edit: impl Fn(&mut RmfWireSweepOptions),
) -> RmfStatus {
    let mut options = std::mem::MaybeUninit::<RmfWireSweepOptions>::uninit();
    // A failure writes nothing: `out` keeps this (never dereferenced) value.
    let sentinel = std::ptr::NonNull::<RmfShape>::dangling().as_ptr();
    let mut out = sentinel;
    unsafe {
        rmf_wire_sweep_options_init(options.as_mut_ptr());
        let mut options = options.assume_init();
        edit(&mut options);
        let holes_c: Vec<*const RmfCurve> = holes.iter().map(|&h| h.cast_const()).collect();
        let status = rmf_wire_sweep(
            edges.as_ptr(),
            edges.len(),
            profile,
            holes_c.as_ptr(),
            holes_c.len(),
            &options,
            &mut out,
        );
        if status == RmfStatus::RmfOk {
            rmf_shape_free(out);
        } else {
            assert_eq!(out, sentinel, "{status:?}: out written on failure");
        }
        rmf_curve_free(profile);
        for &h in holes {
            rmf_curve_free(h);
        }
        status
    }
}

/// A valid knot of the scale law: σ = 2 half way.
static ONE_KNOT: [f64; 2] = [0.5, 2.0];

/// rmf_wire_sweep of a circle of radius 1 along the pipe route with the knots at `knots`
/// (pairs of doubles), the rest the defaults.
fn knotted(knots: &[f64]) -> RmfStatus {
    wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
        o.scale_knots = knots.as_ptr();
        o.scale_knot_count = knots.len() / 2;
    })
}

/// rmf_wire_sweep_between along a line of 3 from the circle of radius 1 with `holes` to
/// `end_profile` with `end_holes` (all freed after; `end_profile` may be NULL), default
/// options; the shape, if any, is freed.
fn wire_sweep_between(
    holes: &[*mut RmfCurve],
    end_profile: *mut RmfCurve,
    end_holes: &[*mut RmfCurve],
) -> RmfStatus {
    let edges = [line(v(0., 0., 0.), v(3., 0., 0.))];
    let profile = circle(1.0);
    let mut out: *mut RmfShape = null_mut();
    let holes_c: Vec<*const RmfCurve> = holes.iter().map(|&h| h.cast_const()).collect();
    let end_holes_c: Vec<*const RmfCurve> = end_holes.iter().map(|&h| h.cast_const()).collect();
    unsafe {
        let status = rmf_wire_sweep_between(
            edges.as_ptr(),
            edges.len(),
            profile,
            holes_c.as_ptr(),
            holes_c.len(),
            end_profile,
            end_holes_c.as_ptr(),
            end_holes_c.len(),
            null(),
            &mut out,
        );
        rmf_shape_free(out);
        for &c in [profile, end_profile].iter().chain(holes).chain(end_holes) {
            rmf_curve_free(c);
        }
        status
    }
}

/// The sections of a sweep through circles of radii 0.5 at 0, 1 at 0.25, 0.3 at 1 (the
/// curves to free after), which a row then breaks.
fn three_circles() -> (Vec<RmfWireSection>, Vec<*mut RmfCurve>) {
    let curves = vec![circle(0.5), circle(1.0), circle(0.3)];
    let sections = [0.0, 0.25, 1.0]
        .iter()
        .zip(&curves)
        .map(|(&at, &c)| RmfWireSection {
            at,
            profile: c,
            holes: null(),
            hole_count: 0,
        })
        .collect();
    (sections, curves)
}

/// rmf_wire_sweep_through along a line of 4 through `section_count` of `sections` (NULL
/// when `sections` is None; the curves freed after), default options; on failure `*out`
/// must keep its sentinel, a shape made is freed.
fn wire_sweep_through(
    sections: Option<&[RmfWireSection]>,
    section_count: usize,
    curves: &[*mut RmfCurve],
) -> RmfStatus {
    let edges = [line(v(0., 0., 0.), v(4., 0., 0.))];
    let sentinel = std::ptr::NonNull::<RmfShape>::dangling().as_ptr();
    let mut out = sentinel;
    unsafe {
        let status = rmf_wire_sweep_through(
            edges.as_ptr(),
            edges.len(),
            sections.map_or(null(), |s| s.as_ptr()),
            section_count,
            null(),
            &mut out,
        );
        if status == RmfStatus::RmfOk {
            rmf_shape_free(out);
        } else {
            assert_eq!(out, sentinel, "{status:?}: out written on failure");
        }
        for &c in curves {
            rmf_curve_free(c);
        }
        status
    }
}

/// A polyline wire through `points` (lines).
fn polyline(points: &[RmfVec3]) -> Vec<RmfEdge> {
    points.windows(2).map(|w| line(w[0], w[1])).collect()
}

/// One row: what is bad, the entry point, the expected status, and a word the message must
/// contain (the argument's name).
struct Row {
    what: &'static str,
    function: &'static str,
    expected: RmfStatus,
    names: &'static str,
    call: fn(&Fixtures) -> RmfStatus,
}

use RmfStatus::{
    RmfErrorBufferTooSmall as TOO_SMALL, RmfErrorInvalidInput as INVALID, RmfErrorIo as IO,
    RmfErrorNoSolution as NO_SOLUTION, RmfErrorNotConverged as NOT_CONVERGED,
    RmfErrorNullPointer as NULL,
};

/// `rmf_cone_spline_approximate` on the tangent surface of the twisted cubic (1e-3, t in
/// [0.2, 1.2], v in [0.5, 6]) with the given rule and piece limit (the deprecated wrapper
/// refuses as it always did).
#[allow(deprecated)]
unsafe fn twisted_cubic_cones(
    rule: u32,
    max_pieces: usize,
    out: *mut *mut RmfConeSpline,
) -> RmfStatus {
    let mut max_error = 0.0;
    rmf_cone_spline_approximate(
        null(),
        Some(twisted_cubic),
        null_mut(),
        0.2,
        1.2,
        0.5,
        6.0,
        1e-3,
        rule,
        max_pieces,
        out,
        &mut max_error,
    )
}

/// A closed polyline through `corners` (degree 1), or the circle about `centre` of radius r
/// in the plane z = centre.z (four rational quadratic quarters).
fn polygon_curve(corners: &[RmfVec3]) -> *mut RmfCurve {
    let mut poles = corners.to_vec();
    poles.push(corners[0]);
    let n = poles.len();
    let mut knots = vec![0.0];
    knots.extend((0..n).map(|k| k as f64));
    knots.push((n - 1) as f64);
    let mut out = null_mut();
    let status = unsafe {
        rmf_nurbs_curve_create(
            1,
            poles.as_ptr(),
            null(),
            n,
            knots.as_ptr(),
            knots.len(),
            &mut out,
        )
    };
    assert_eq!(status, RmfStatus::RmfOk);
    out
}

fn circle_curve(centre: RmfVec3, r: f64) -> *mut RmfCurve {
    let mut out = null_mut();
    let status = unsafe {
        rmfsurf_capi::primitives::rmf_curve_circle(
            centre,
            v(1.0, 0.0, 0.0),
            v(0.0, 1.0, 0.0),
            r,
            &mut out,
        )
    };
    assert_eq!(status, RmfStatus::RmfOk);
    out
}

fn square_curve() -> *mut RmfCurve {
    polygon_curve(&[
        v(-0.5, -0.5, 0.),
        v(0.5, -0.5, 0.),
        v(0.5, 0.5, 0.),
        v(-0.5, 0.5, 0.),
    ])
}

/// `rmf_sheet_part_transition` between `bottom` and `top` (freed here) with the default
/// options at tolerance 1e-2 changed by `edit`; the part is freed.
fn transition_with(
    bottom: *mut RmfCurve,
    top: *mut RmfCurve,
    edit: impl Fn(&mut RmfSheetOptions),
) -> RmfStatus {
    let mut options = RmfSheetOptions::default();
    unsafe { rmf_sheet_options_init(&mut options) };
    options.tolerance = 1e-2;
    edit(&mut options);
    let mut out = null_mut();
    unsafe {
        let status = rmf_sheet_part_transition(bottom, top, &options, &mut out);
        rmf_sheet_part_free(out);
        rmf_curve_free(bottom);
        rmf_curve_free(top);
        status
    }
}

/// The saddle z = xy as a degree (1, 1) surface: ruled, not developable.
fn saddle_surface() -> *mut RmfSurface {
    let poles = [
        v(-1., -1., 1.),
        v(-1., 1., -1.),
        v(1., -1., -1.),
        v(1., 1., 1.),
    ];
    let knots = [0., 0., 1., 1.];
    let mut out = null_mut();
    #[allow(deprecated)] // the deprecated wrapper refuses as it always did
    let status = unsafe {
        rmf_nurbs_surface_create(
            1,
            1,
            poles.as_ptr(),
            null(),
            2,
            2,
            knots.as_ptr(),
            4,
            knots.as_ptr(),
            4,
            &mut out,
        )
    };
    assert_eq!(status, RmfStatus::RmfOk);
    out
}

/// `rmf_sheet_part_tangent` of the circle of radius 1 between `v_min` and `v_max`
/// (default options at tolerance 1e-2); the part, if any, is freed.
fn tangent_part_with(v_min: f64, v_max: f64) -> RmfStatus {
    let circle = circle_curve(v(0., 0., 0.), 1.0);
    let options = RmfSheetOptions {
        tolerance: 1e-2,
        ..Default::default()
    };
    let mut out = null_mut();
    unsafe {
        let status = rmf_sheet_part_tangent(circle, v_min, v_max, &options, &mut out);
        rmf_sheet_part_free(out);
        rmf_curve_free(circle);
        status
    }
}

/// A square-to-round part at tolerance 1e-2, for the rows that need one; `call` gets it,
/// and the part is freed after.
fn with_part(call: impl Fn(*mut RmfSheetPart) -> RmfStatus) -> RmfStatus {
    let (bottom, top) = (square_curve(), circle_curve(v(0.1, 0., 1.), 0.3));
    let options = RmfSheetOptions {
        tolerance: 1e-2,
        ..Default::default()
    };
    let mut part = null_mut();
    unsafe {
        assert_eq!(
            rmf_sheet_part_transition(bottom, top, &options, &mut part),
            RmfStatus::RmfOk
        );
        let status = call(part);
        rmf_sheet_part_free(part);
        rmf_curve_free(bottom);
        rmf_curve_free(top);
        status
    }
}

fn rows() -> Vec<Row> {
    vec![
        Row {
            what: "NULL handle",
            function: "rmf_curve_eval",
            expected: NULL,
            names: "curve",
            call: |_| unsafe { rmf_curve_eval(null(), 0.5, &mut v(0., 0., 0.), null_mut()) },
        },
        Row {
            what: "NULL out-pointer",
            function: "rmf_ph_spline_hermite",
            expected: NULL,
            names: "out",
            call: |_| {
                let (p, t) = helix();
                unsafe { rmf_ph_spline_hermite(p.as_ptr(), t.as_ptr(), 5, null_mut()) }
            },
        },
        Row {
            what: "parameter NaN",
            function: "rmf_curve_eval",
            expected: INVALID,
            names: "t",
            call: |f| unsafe { rmf_curve_eval(f.curve, NAN, &mut v(0., 0., 0.), null_mut()) },
        },
        Row {
            what: "parameter outside the domain",
            function: "rmf_frames_eval",
            expected: INVALID,
            names: "t",
            call: |f| {
                let (mut a, mut b, mut c) = (v(0., 0., 0.), v(0., 0., 0.), v(0., 0., 0.));
                unsafe { rmf_frames_eval(f.rmf, 1e6, &mut a, &mut b, &mut c) }
            },
        },
        Row {
            what: "NURBS pole ±Inf",
            function: "rmf_nurbs_curve_create",
            expected: INVALID,
            names: "poles[2]",
            call: |_| {
                let mut n = Nurbs::valid();
                n.poles[2].y = f64::INFINITY;
                n.create().0
            },
        },
        Row {
            what: "NURBS weight 0 or negative",
            function: "rmf_nurbs_curve_create",
            expected: INVALID,
            names: "weights[1]",
            call: |_| {
                let mut n = Nurbs::valid();
                n.weights[1] = -0.5;
                n.create().0
            },
        },
        Row {
            what: "NURBS knot NaN",
            function: "rmf_nurbs_curve_create",
            expected: INVALID,
            names: "knots[5]",
            call: |_| {
                let mut n = Nurbs::valid();
                n.knots[5] = NAN;
                n.create().0
            },
        },
        Row {
            what: "NURBS knots not clamped",
            function: "rmf_nurbs_curve_create",
            expected: INVALID,
            names: "knots",
            call: |_| {
                let mut n = Nurbs::valid();
                n.knots[0] = -1.0;
                n.create().0
            },
        },
        Row {
            what: "NURBS degree ≥ pole count",
            function: "rmf_nurbs_curve_create",
            expected: INVALID,
            names: "degree",
            call: |_| {
                let mut n = Nurbs::valid();
                n.degree = 4;
                n.knots.push(1.0);
                n.knots.insert(0, 0.0);
                n.create().0
            },
        },
        Row {
            what: "NURBS degree 2³²−1",
            function: "rmf_nurbs_curve_create",
            expected: INVALID,
            names: "degree",
            call: |_| {
                let mut n = Nurbs::valid();
                n.degree = u32::MAX;
                n.create().0
            },
        },
        Row {
            what: "sample count 1 or above 2²⁴",
            function: "rmf_double_reflection_frames",
            expected: INVALID,
            names: "sample_count",
            call: |f| {
                let mut out = null_mut();
                unsafe {
                    rmf_double_reflection_frames(f.curve, v(0., 0., 1.), usize::MAX, &mut out)
                }
            },
        },
        Row {
            what: "initial normal along the tangent",
            function: "rmf_ph_rational_rmf",
            expected: INVALID,
            names: "initial_normal",
            call: |f| {
                let mut out = null_mut();
                unsafe { rmf_ph_rational_rmf(f.ph_spline, v(0., 1., 0.4), &mut out) }
            },
        },
        Row {
            what: "initial normal zero or NaN",
            function: "rmf_ph_rational_rmf",
            expected: INVALID,
            names: "initial_normal",
            call: |f| {
                let mut out = null_mut();
                unsafe { rmf_ph_rational_rmf(f.ph_spline, v(0., 0., 0.), &mut out) }
            },
        },
        Row {
            what: "frames of another curve",
            function: "rmf_sweep_surface",
            expected: INVALID,
            names: "frames",
            call: |f| {
                let mut out = null_mut();
                unsafe { rmf_sweep_surface(f.curve, f.rmf, f.curve, &mut out) }
            },
        },
        Row {
            what: "buffer too small",
            function: "rmf_surface_tessellate",
            expected: TOO_SMALL,
            names: "need",
            call: |f| {
                let (mut surface, mut np, mut nt) = (null_mut(), 0, 0);
                let mut points = [v(0., 0., 0.); 4];
                let mut triangles = [0u32; 3];
                unsafe {
                    rmf_sweep_surface(f.ph_spline, f.rmf, f.curve, &mut surface);
                    let status = rmf_surface_tessellate(
                        surface,
                        4,
                        4,
                        points.as_mut_ptr(),
                        4,
                        triangles.as_mut_ptr(),
                        1,
                        &mut np,
                        &mut nt,
                    );
                    rmf_surface_free(surface);
                    status
                }
            },
        },
        Row {
            what: "Hermite points coincide",
            function: "rmf_ph_spline_hermite",
            expected: INVALID,
            names: "points[1] and points[2]",
            call: |_| ph_spline_with(|p, _| p[2] = p[1]),
        },
        Row {
            what: "Hermite tangent zero",
            function: "rmf_ph_spline_hermite",
            expected: INVALID,
            names: "tangents[3]",
            call: |_| ph_spline_with(|_, t| t[3] = v(0., 0., 0.)),
        },
        Row {
            what: "Hermite coordinate beyond ±1e300",
            function: "rmf_ph_spline_hermite",
            expected: INVALID,
            names: "points[4]",
            call: |_| ph_spline_with(|p, _| p[4].x = 1e308),
        },
        Row {
            what: "Hermite point subnormal distance apart",
            function: "rmf_ph_spline_hermite",
            expected: INVALID,
            names: "coincide",
            call: |_| ph_spline_with(|p, _| p[1] = v(p[0].x + 5e-324, p[0].y, p[0].z)),
        },
        Row {
            what: "one point only",
            function: "rmf_ph_spline_hermite",
            expected: INVALID,
            names: "count",
            call: |_| {
                ph_spline_with(|p, t| {
                    p.truncate(1);
                    t.truncate(1);
                })
            },
        },
        Row {
            what: "tangents antiparallel along the chord",
            function: "rmf_ph_cubic_hermite",
            expected: NO_SOLUTION,
            names: "",
            call: |_| {
                let mut out = null_mut();
                unsafe {
                    rmf_ph_cubic_hermite(
                        v(0., 0., 0.),
                        v(1., 0., 0.),
                        v(1., 0., 0.),
                        v(-1., 0., 0.),
                        &mut out,
                        null_mut(),
                    )
                }
            },
        },
        Row {
            what: "parallel tangents off the chord",
            function: "rmf_ph_cubic_hermite",
            expected: NO_SOLUTION,
            names: "",
            call: |_| {
                let mut out = null_mut();
                unsafe {
                    rmf_ph_cubic_hermite(
                        v(0., 0., 0.),
                        v(1., 0., 0.),
                        v(1., 1., 0.),
                        v(1., 0., 0.),
                        &mut out,
                        null_mut(),
                    )
                }
            },
        },
        Row {
            what: "a curve that is not a PH spline",
            function: "rmf_ph_rational_rmf",
            expected: INVALID,
            names: "ph_spline",
            call: |f| {
                let mut out = null_mut();
                unsafe { rmf_ph_rational_rmf(f.curve, v(0., 0., 1.), &mut out) }
            },
        },
        Row {
            what: "tolerance 0, negative or NaN",
            function: "rmf_ph_spline_approximate",
            expected: INVALID,
            names: "tolerance",
            call: |f| {
                let (mut out, mut d) = (null_mut(), 0.0);
                unsafe {
                    rmf_ph_spline_approximate(
                        f.curve,
                        None,
                        null_mut(),
                        0.,
                        1.,
                        -1e-3,
                        &mut out,
                        &mut d,
                    )
                }
            },
        },
        Row {
            what: "callback writes NaN",
            function: "rmf_ph_spline_approximate",
            expected: INVALID,
            names: "callback",
            call: |_| {
                let (mut out, mut d) = (null_mut(), 0.0);
                unsafe {
                    rmf_ph_spline_approximate(
                        null(),
                        Some(nan_callback),
                        null_mut(),
                        0.,
                        1.,
                        1e-3,
                        &mut out,
                        &mut d,
                    )
                }
            },
        },
        Row {
            what: "both a curve and a callback",
            function: "rmf_ph_spline_approximate",
            expected: INVALID,
            names: "either",
            call: |f| {
                let (mut out, mut d) = (null_mut(), 0.0);
                unsafe {
                    rmf_ph_spline_approximate(
                        f.curve,
                        Some(twisted_cubic),
                        null_mut(),
                        0.,
                        1.,
                        1e-3,
                        &mut out,
                        &mut d,
                    )
                }
            },
        },
        Row {
            what: "tolerance below the rounding of the coordinates",
            function: "rmf_ph_spline_approximate",
            expected: INVALID,
            names: "tolerance",
            call: |f| {
                let mut out = null_mut();
                unsafe {
                    rmf_ph_spline_approximate(
                        f.curve,
                        None,
                        null_mut(),
                        0.,
                        1.,
                        4e-320,
                        &mut out,
                        null_mut(),
                    )
                }
            },
        },
        Row {
            what: "approximation options NULL",
            function: "rmf_ph_spline_approximate_with_options",
            expected: NULL,
            names: "options",
            call: |f| {
                let mut out = null_mut();
                unsafe {
                    rmf_ph_spline_approximate_with_options(f.curve, null(), &mut out, null_mut())
                }
            },
        },
        Row {
            what: "approximation options not initialised",
            function: "rmf_ph_spline_approximate_with_options",
            expected: INVALID,
            names: "options->struct_size",
            call: |f| approximate_with(f, |o| o.struct_size = 0, None),
        },
        Row {
            what: "approximation tolerance left at its default 0",
            function: "rmf_ph_spline_approximate_with_options",
            expected: INVALID,
            names: "options: tolerance",
            call: |f| approximate_with(f, |o| o.tolerance = 0.0, None),
        },
        Row {
            what: "max_segments 0 or above 2²⁰",
            function: "rmf_ph_spline_approximate_with_options",
            expected: INVALID,
            names: "options: max_segments",
            call: |f| approximate_with(f, |o| o.max_segments = (1 << 20) + 1, None),
        },
        Row {
            what: "max_evaluations 0",
            function: "rmf_ph_spline_approximate_with_options",
            expected: INVALID,
            names: "options: max_evaluations",
            call: |f| approximate_with(f, |o| o.max_evaluations = 0, None),
        },
        Row {
            what: "report struct_size not set",
            function: "rmf_ph_spline_approximate_with_options",
            expected: INVALID,
            names: "report->struct_size",
            call: |f| approximate_with(f, |_| {}, Some(0)),
        },
        Row {
            what: "twist NaN",
            function: "rmf_ph_rational_rmf_twisted",
            expected: INVALID,
            names: "twist",
            call: |f| {
                let mut out = null_mut();
                unsafe { rmf_ph_rational_rmf_twisted(f.ph_spline, v(0., 0., 1.), NAN, 0, &mut out) }
            },
        },
        Row {
            what: "closure asked of an open spine",
            function: "rmf_ph_rational_rmf_twisted",
            expected: INVALID,
            names: "closed",
            call: |f| {
                let mut out = null_mut();
                unsafe { rmf_ph_rational_rmf_twisted(f.ph_spline, v(0., 0., 1.), 0.0, 4, &mut out) }
            },
        },
        Row {
            what: "v_samples 2³²−1",
            function: "rmf_sweep_parabolic_points",
            expected: INVALID,
            names: "v_samples",
            call: |f| parabolic_points_count(f, f.curve, u32::MAX),
        },
        Row {
            what: "v_samples 2²⁴ along a 4-segment profile",
            function: "rmf_sweep_parabolic_points",
            expected: INVALID,
            names: "v_samples × profile segments",
            call: |f| parabolic_points_count(f, f.ph_spline, 1 << 24),
        },
        Row {
            what: "arc offset tolerance NaN",
            function: "rmf_profile_offset_by_arcs",
            expected: INVALID,
            names: "tolerance",
            call: |f| {
                let mut out = null_mut();
                unsafe {
                    rmf_profile_offset_by_arcs(f.curve, 0.1, NAN, &mut out, null_mut(), null_mut())
                }
            },
        },
        Row {
            what: "arc offset distance ∞",
            function: "rmf_profile_offset_by_arcs",
            expected: INVALID,
            names: "distance",
            call: |f| {
                let mut out = null_mut();
                unsafe {
                    rmf_profile_offset_by_arcs(
                        f.curve,
                        f64::INFINITY,
                        1e-3,
                        &mut out,
                        null_mut(),
                        null_mut(),
                    )
                }
            },
        },
        Row {
            what: "parabolic line tolerance 0",
            function: "rmf_sweep_parabolic_curves",
            expected: INVALID,
            names: "tolerance",
            call: |f| parabolic_curves_count(f, 0.0),
        },
        Row {
            what: "parabolic line tolerance NaN",
            function: "rmf_sweep_parabolic_curves",
            expected: INVALID,
            names: "tolerance",
            call: |f| parabolic_curves_count(f, NAN),
        },
        Row {
            what: "parabolic line tolerance 1e-300",
            function: "rmf_sweep_parabolic_curves",
            expected: INVALID,
            names: "tolerance",
            call: |f| parabolic_curves_count(f, 1e-300),
        },
        Row {
            what: "parabolic line tolerance 1e-14",
            function: "rmf_sweep_parabolic_curves",
            expected: NOT_CONVERGED,
            names: "tolerance",
            call: |f| parabolic_curves_count(f, 1e-14),
        },
        Row {
            what: "Möbius segments above 2²⁴",
            function: "rmf_mobius_rrmf_approximate",
            expected: INVALID,
            names: "segments",
            call: |f| {
                let (mut c, mut fr) = (null_mut(), null_mut());
                unsafe {
                    rmf_mobius_rrmf_approximate(
                        f.curve,
                        None,
                        null_mut(),
                        0.,
                        1.,
                        1 << 40,
                        v(0., 0., 1.),
                        &mut c,
                        &mut fr,
                    )
                }
            },
        },
        Row {
            what: "inversion radius 0",
            function: "rmf_mobius_point",
            expected: INVALID,
            names: "radius",
            call: |_| {
                let map = RmfInversion {
                    kind: RMF_INVERSION_SPHERE,
                    center: v(0., 0., 0.),
                    radius: 0.0,
                    normal: v(0., 0., 1.),
                };
                unsafe { rmf_mobius_point(&map, 1, v(1., 0., 0.), &mut v(0., 0., 0.)) }
            },
        },
        Row {
            what: "point at the inversion centre",
            function: "rmf_mobius_point",
            expected: INVALID,
            names: "centre",
            call: |_| {
                let map = RmfInversion {
                    kind: RMF_INVERSION_SPHERE,
                    center: v(1., 2., 3.),
                    radius: 1.0,
                    normal: v(0., 0., 1.),
                };
                unsafe { rmf_mobius_point(&map, 1, v(1., 2., 3.), &mut v(0., 0., 0.)) }
            },
        },
        Row {
            what: "unknown inversion kind",
            function: "rmf_mobius_point",
            expected: INVALID,
            names: "kind",
            call: |_| {
                let map = RmfInversion {
                    kind: 7,
                    center: v(0., 0., 0.),
                    radius: 1.0,
                    normal: v(0., 0., 1.),
                };
                unsafe { rmf_mobius_point(&map, 1, v(1., 0., 0.), &mut v(0., 0., 0.)) }
            },
        },
        Row {
            what: "planar Hermite data (RRMF)",
            function: "rmf_rrmf_quintic_solutions",
            expected: INVALID,
            names: "planar",
            call: |_| {
                let mut count = 0;
                unsafe {
                    rmf_rrmf_quintic_solutions(
                        v(0., 0., 0.),
                        v(1., 0., 0.),
                        v(1., 1., 0.),
                        v(0., 1., 0.),
                        1.0,
                        null_mut(),
                        0,
                        &mut count,
                    )
                }
            },
        },
        Row {
            what: "η NaN",
            function: "rmf_rrmf_quintic_solutions",
            expected: INVALID,
            names: "eta",
            call: |_| {
                let mut count = 0;
                unsafe {
                    rmf_rrmf_quintic_solutions(
                        v(0., 0., 0.),
                        v(1., 0., 1.),
                        v(1., 1., 1.),
                        v(0., 1., 1.),
                        NAN,
                        null_mut(),
                        0,
                        &mut count,
                    )
                }
            },
        },
        Row {
            what: "solutions buffer too small",
            function: "rmf_rrmf_quintic_solutions",
            expected: TOO_SMALL,
            names: "capacity",
            call: |_| {
                let mut count = 0;
                let mut one = [RmfRrmfQuintic::default(); 1];
                unsafe {
                    rmf_rrmf_quintic_solutions(
                        v(0., 0., 0.),
                        v(1., 0., 1.),
                        v(1., 1., 1.),
                        v(0., 1., 1.),
                        4.325,
                        one.as_mut_ptr(),
                        1,
                        &mut count,
                    )
                }
            },
        },
        Row {
            what: "irregular-root buffers NULL with a capacity",
            function: "rmf_rrmf_quintic_irregular_roots",
            expected: NULL,
            names: "rho",
            call: |_| {
                let mut count = 0;
                unsafe {
                    rmf_rrmf_quintic_irregular_roots(
                        v(0., 0., 0.),
                        v(1., 1e-3, 0.),
                        v(1., 0., 0.),
                        v(0., 1., 1.),
                        1.0,
                        null_mut(),
                        null_mut(),
                        2,
                        &mut count,
                    )
                }
            },
        },
        Row {
            what: "irregular-root buffers too small",
            function: "rmf_rrmf_quintic_irregular_roots",
            expected: TOO_SMALL,
            names: "capacity",
            call: |_| {
                let mut count = 0;
                let (mut rho, mut ratio) = ([0.0; 1], [0.0; 1]);
                unsafe {
                    rmf_rrmf_quintic_irregular_roots(
                        v(0., 0., 0.),
                        v(1., 1e-3, 0.),
                        v(1., 0., 0.),
                        v(0., 1., 1.),
                        1.0,
                        rho.as_mut_ptr(),
                        ratio.as_mut_ptr(),
                        0,
                        &mut count,
                    )
                }
            },
        },
        Row {
            what: "η samples 0 or above 10⁶",
            function: "rmf_rrmf_quintic_best",
            expected: INVALID,
            names: "eta_samples",
            call: |_| {
                let (mut best, mut n) = (RmfRrmfQuintic::default(), 0);
                unsafe {
                    rmf_rrmf_quintic_best(
                        v(0., 0., 0.),
                        v(1., 0., 1.),
                        v(1., 1., 1.),
                        v(0., 1., 1.),
                        RMF_RRMF_MEASURE_SCALED_ENERGY_RMF,
                        usize::MAX,
                        &mut best,
                        &mut n,
                    )
                }
            },
        },
        Row {
            what: "unknown shape measure",
            function: "rmf_rrmf_quintic_best",
            expected: INVALID,
            names: "measure",
            call: |_| {
                let (mut best, mut n) = (RmfRrmfQuintic::default(), 0);
                unsafe {
                    rmf_rrmf_quintic_best(
                        v(0., 0., 0.),
                        v(1., 0., 1.),
                        v(1., 1., 1.),
                        v(0., 1., 1.),
                        99,
                        16,
                        &mut best,
                        &mut n,
                    )
                }
            },
        },
        Row {
            what: "RRMF spline options NULL",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: NULL,
            names: "options",
            call: |_| {
                let (points, tangents) = helix();
                let (mut curve, mut frames) = (null_mut(), null_mut());
                unsafe {
                    rmf_rrmf_spline_hermite_with_options(
                        points.as_ptr(),
                        tangents.as_ptr(),
                        points.len(),
                        null(),
                        &mut curve,
                        &mut frames,
                        null_mut(),
                    )
                }
            },
        },
        Row {
            what: "RRMF spline options not initialised",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: INVALID,
            names: "options->struct_size",
            call: |_| rrmf_spline_with(|o| o.struct_size = 8, None),
        },
        Row {
            what: "RRMF spline options: unknown measure",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: INVALID,
            names: "options->measure",
            call: |_| rrmf_spline_with(|o| o.measure = 5, None),
        },
        Row {
            what: "RRMF spline options: η samples 0",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: INVALID,
            names: "options->eta_samples",
            call: |_| rrmf_spline_with(|o| o.eta_samples = 0, None),
        },
        Row {
            what: "RRMF spline options: initial normal left zero",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: INVALID,
            names: "options->initial_normal",
            call: |_| rrmf_spline_with(|o| o.initial_normal = v(0.0, 0.0, 0.0), None),
        },
        Row {
            what: "RRMF spline options: initial normal along the tangent",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: INVALID,
            names: "options->initial_normal",
            call: |_| rrmf_spline_with(|o| o.initial_normal = v(0.0, 2.0, 0.8), None),
        },
        Row {
            what: "RRMF spline options: max_evaluations 0",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: INVALID,
            names: "options->max_evaluations",
            call: |_| rrmf_spline_with(|o| o.max_evaluations = 0, None),
        },
        Row {
            what: "RRMF spline work budget spent",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: RmfStatus::RmfErrorNotConverged,
            names: "budget",
            call: |_| rrmf_spline_with(|o| o.max_evaluations = 20, None),
        },
        Row {
            what: "RRMF spline report struct_size not set",
            function: "rmf_rrmf_spline_hermite_with_options",
            expected: INVALID,
            names: "report->struct_size",
            call: |_| rrmf_spline_with(|_| {}, Some(0)),
        },
        Row {
            what: "a solution of other data",
            function: "rmf_rrmf_quintic_curve",
            expected: INVALID,
            names: "solution",
            call: |_| {
                let wrong = RmfRrmfQuintic {
                    eta: 1.0,
                    rho: 0.5,
                    ..Default::default()
                };
                let (mut c, mut f) = (null_mut(), null_mut());
                unsafe {
                    rmf_rrmf_quintic_curve(
                        v(0., 0., 0.),
                        v(1., 0., 1.),
                        v(1., 1., 1.),
                        v(0., 1., 1.),
                        &wrong,
                        v(0., 0., 1.),
                        &mut c,
                        &mut f,
                    )
                }
            },
        },
        Row {
            what: "cone element with side along the ruling",
            function: "rmf_cone_spline_hermite",
            expected: INVALID,
            names: "side",
            call: |_| {
                let e = RmfConeElement {
                    point: v(0., 0., 0.),
                    ruling: v(0., 0., 1.),
                    side: v(0., 0., 2.),
                };
                let second = RmfConeElement {
                    point: v(1., 0., 0.),
                    ..e
                };
                let mut out = null_mut();
                unsafe {
                    rmf_cone_spline_hermite(
                        [e, second].as_ptr(),
                        2,
                        RMF_CONE_RULE_MIN_VERTEX_DISTANCE,
                        0.0,
                        null(),
                        &mut out,
                    )
                }
            },
        },
        Row {
            what: "unknown cone rule",
            function: "rmf_cone_spline_approximate",
            expected: INVALID,
            names: "rule",
            call: |_| {
                let mut out = null_mut();
                unsafe { twisted_cubic_cones(99, 100, &mut out) }
            },
        },
        Row {
            what: "max_pieces 1",
            function: "rmf_cone_spline_approximate",
            expected: INVALID,
            names: "max_pieces",
            call: |_| {
                let mut out = null_mut();
                unsafe { twisted_cubic_cones(0, 1, &mut out) }
            },
        },
        Row {
            what: "strip through a cone vertex",
            function: "rmf_cone_spline_surface",
            expected: INVALID,
            names: "vertex",
            call: |_| {
                let (mut spline, mut surface) = (null_mut(), null_mut());
                unsafe {
                    twisted_cubic_cones(0, 1000, &mut spline);
                    let status = rmf_cone_spline_surface(spline, -100.0, 100.0, &mut surface);
                    rmf_cone_spline_free(spline);
                    status
                }
            },
        },
        Row {
            what: "disconnected wire edges",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "edges 1 and 2 do not meet: the nearest ends are 5.000e-1 apart",
            call: |_| {
                let mut e = pipe_route();
                e[2].points[0].y = 5.5;
                wire_sweep(&e, circle(1.0), &[], |_| {})
            },
        },
        Row {
            what: "zero-length wire edge",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "edge 2: a line of zero length",
            call: |_| {
                let mut e = pipe_route();
                e[2].points[1] = e[2].points[0];
                wire_sweep(&e, circle(1.0), &[], |_| {})
            },
        },
        Row {
            what: "wire edge with a cusp",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "edge 0",
            call: |_| {
                let cusp = curve(
                    3,
                    &[v(0., 0., 0.), v(1., 1., 0.), v(0., 1., 0.), v(1., 0., 0.)],
                );
                let e = [RmfEdge {
                    kind: RMF_EDGE_CURVE,
                    points: [v(0., 0., 0.); 3],
                    curve: cusp,
                }];
                let status = wire_sweep(&e, circle(0.01), &[], |_| {});
                unsafe { rmf_curve_free(cusp) };
                status
            },
        },
        Row {
            what: "180° reversal at a joint",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "joint between edges 0 and 1: the wire turns back on itself",
            call: |_| {
                let e = polyline(&[v(0., 0., 0.), v(10., 0., 0.), v(5., 0., 0.)]);
                wire_sweep(&e, circle(1.0), &[], |_| {})
            },
        },
        Row {
            what: "open profile for a solid",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "profile: a solid needs a closed profile",
            call: |_| {
                let open = curve(1, &[v(-1., 0., 0.), v(1., 0., 0.), v(1., 1., 0.)]);
                wire_sweep(&pipe_route(), open, &[], |_| {})
            },
        },
        Row {
            what: "open profile with holes",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "holes need a closed outer profile",
            call: |_| {
                let open = curve(1, &[v(-1., 0., 0.), v(1., 0., 0.), v(1., 1., 0.)]);
                wire_sweep(&pipe_route(), open, &[circle(0.1)], |o| o.solid = 0)
            },
        },
        Row {
            what: "corner radius that does not fit",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "the largest radius that fits every corner is 0.99999",
            call: |_| {
                let e = polyline(&[v(0., 0., 0.), v(4., 0., 0.), v(4., 2., 0.), v(0., 2., 0.)]);
                wire_sweep(&e, circle(0.1), &[], |o| o.corner_radius = 1.5)
            },
        },
        Row {
            what: "corner radius below the profile's extent",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "the smallest radius allowed is 0.5",
            call: |_| {
                let e = polyline(&[v(0., 0., 0.), v(4., 0., 0.), v(4., 4., 0.)]);
                wire_sweep(&e, circle(0.5), &[], |o| o.corner_radius = 0.2)
            },
        },
        Row {
            what: "profile reaching past an arc's centre",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "edge 1: the arc's radius 4.99999",
            call: |_| wire_sweep(&pipe_route(), circle(6.0), &[], |_| {}),
        },
        Row {
            what: "miter corner on an arc",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "a miter corner needs straight legs",
            call: |_| {
                let e = [
                    line(v(-2., 4., 0.), v(0., 2., 0.)),
                    RmfEdge {
                        kind: RMF_EDGE_ARC,
                        points: [
                            v(0., 2., 0.),
                            v(2f64.sqrt(), 2f64.sqrt(), 0.),
                            v(2., 0., 0.),
                        ],
                        curve: null(),
                    },
                ];
                wire_sweep(&e, circle(0.1), &[], |o| o.corner = RMF_CORNER_MITER)
            },
        },
        Row {
            what: "unknown edge kind",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "edges[1].kind = 7",
            call: |_| {
                let mut e = pipe_route();
                e[1].kind = 7;
                wire_sweep(&e, circle(1.0), &[], |_| {})
            },
        },
        Row {
            what: "options not initialised",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->struct_size = 0",
            call: |_| wire_sweep(&pipe_route(), circle(1.0), &[], |o| o.struct_size = 0),
        },
        Row {
            what: "wire of more edges than faces allowed",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "edge_count = 65537: a wire sweep has at most 65536 lateral faces",
            call: |_| {
                let points: Vec<RmfVec3> = (0..=65_537).map(|k| v(k as f64, 0., 0.)).collect();
                wire_sweep(&polyline(&points), circle(0.1), &[], |_| {})
            },
        },
        Row {
            what: "wire crossing itself within the profile",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "the sweep intersects itself: the faces along edge 0 and along edge 3",
            call: |_| {
                let e = polyline(&[
                    v(0., 0., 0.),
                    v(10., 0., 0.),
                    v(10., 10., 0.),
                    v(5., 10., 1.),
                    v(5., -5., 1.),
                ]);
                wire_sweep(&e, circle(1.0), &[], |_| {})
            },
        },
        Row {
            what: "twist beyond what an edge carries",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "twist: the frame would turn by",
            call: |_| {
                let e = polyline(&[v(0., 0., 0.), v(10., 0., 0.)]);
                wire_sweep(&e, circle(1.0), &[], |o| o.twist = 1e6)
            },
        },
        Row {
            what: "unknown sweep frame",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->frame = 7 is no RmfSweepFrame",
            call: |_| wire_sweep(&pipe_route(), circle(1.0), &[], |o| o.frame = 7),
        },
        Row {
            what: "fixed frame without a direction",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->frame_direction = [0, 0, 0] must be finite and not zero",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.frame = RMF_FRAME_FIXED
                })
            },
        },
        Row {
            what: "guide frame without guide edges",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->guide_edge_count = 0: RMF_FRAME_GUIDE needs the guide's edges in \
                    options->guide_edges",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.frame = RMF_FRAME_GUIDE
                })
            },
        },
        Row {
            what: "guide frame with NULL guide edges",
            function: "rmf_wire_sweep",
            expected: NULL,
            names: "options->guide_edges is NULL",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.frame = RMF_FRAME_GUIDE;
                    o.guide_edge_count = 1;
                })
            },
        },
        Row {
            what: "guide edge not finite",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->guide_edges[0].points[1] = [0, NaN, 10] is not finite",
            call: |_| {
                let guide = [line(v(0., 3., 0.), v(0., NAN, 10.))];
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.frame = RMF_FRAME_GUIDE;
                    o.guide_edges = guide.as_ptr();
                    o.guide_edge_count = guide.len();
                })
            },
        },
        Row {
            what: "initial normal with a Frenet frame",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->initial_normal = [0, 0, 1] goes with RMF_FRAME_RMF only",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.frame = RMF_FRAME_FRENET;
                    o.initial_normal = v(0., 0., 1.);
                })
            },
        },
        Row {
            what: "profile scale not positive",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_end = 0 must be finite and positive",
            call: |_| wire_sweep(&pipe_route(), circle(1.0), &[], |o| o.scale_end = 0.0),
        },
        Row {
            what: "unknown wire sweep method",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->method = 7 is no method of a wire sweep",
            call: |_| wire_sweep(&pipe_route(), circle(1.0), &[], |o| o.method = 7),
        },
        Row {
            what: "Frenet spine method on a wire",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->method = 1: frenet makes Frenet frames",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.method = RMF_SPINE_FRENET
                })
            },
        },
        Row {
            what: "scale law with an exact-RMF method",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_start = 1, options->scale_end = 0.5 with options->method = 2",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.method = RMF_SPINE_MOBIUS;
                    o.scale_end = 0.5;
                })
            },
        },
        Row {
            what: "scale knots NULL with a count",
            function: "rmf_wire_sweep",
            expected: NULL,
            names: "options->scale_knots is NULL",
            call: |_| wire_sweep(&pipe_route(), circle(1.0), &[], |o| o.scale_knot_count = 2),
        },
        Row {
            what: "more scale knots than faces allowed",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_knot_count = 65537: each knot cuts the wire",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.scale_knots = ONE_KNOT.as_ptr();
                    o.scale_knot_count = 65_537;
                })
            },
        },
        Row {
            what: "scale knot fraction out of (0, 1)",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_knots[0] (the fraction of knot 0): its fraction of the wire's \
                    length 1.5 must lie in (0, 1)",
            call: |_| knotted(&[1.5, 2.0]),
        },
        Row {
            what: "scale knot fractions not increasing",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_knots[2] (the fraction of knot 1): its fraction of the wire's \
                    length 0.25 must lie in (0, 1), after the knot before it (0.5)",
            call: |_| knotted(&[0.5, 2.0, 0.25, 1.0]),
        },
        Row {
            what: "scale knot scale not positive",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_knots[3] (the scale of knot 1): the scale 0 must be finite and \
                    positive",
            call: |_| knotted(&[0.25, 2.0, 0.5, 0.0]),
        },
        Row {
            what: "scale knot scale NaN",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_knots[1] (the scale of knot 0): the scale NaN must be finite",
            call: |_| knotted(&[0.5, NAN]),
        },
        Row {
            what: "scale knots with an exact-RMF method",
            function: "rmf_wire_sweep",
            expected: INVALID,
            names: "options->scale_start = 1, options->scale_end = 1, options->scale_knots = \
                    [(0.5, 2)] with options->method = 3",
            call: |_| {
                wire_sweep(&pipe_route(), circle(1.0), &[], |o| {
                    o.method = RMF_SPINE_RRMF;
                    o.scale_knots = ONE_KNOT.as_ptr();
                    o.scale_knot_count = 1;
                })
            },
        },
        Row {
            what: "sweep between two profiles: end profile NULL",
            function: "rmf_wire_sweep_between",
            expected: NULL,
            names: "end_profile",
            call: |_| wire_sweep_between(&[circle(0.5)], null_mut(), &[]),
        },
        Row {
            what: "sweep between two profiles: a different number of holes",
            function: "rmf_wire_sweep_between",
            expected: INVALID,
            names: "end_profile: it has 0 holes, the profile 1",
            call: |_| wire_sweep_between(&[circle(0.5)], circle(0.8), &[]),
        },
        Row {
            what: "sweep through sections: sections NULL with a count",
            function: "rmf_wire_sweep_through",
            expected: NULL,
            names: "sections is NULL",
            call: |_| {
                let (_, curves) = three_circles();
                wire_sweep_through(None, 3, &curves)
            },
        },
        Row {
            what: "sweep through sections: one section",
            function: "rmf_wire_sweep_through",
            expected: INVALID,
            names: "section_count = 1: a sweep through sections needs two or more",
            call: |_| {
                let (sections, curves) = three_circles();
                wire_sweep_through(Some(&sections), 1, &curves)
            },
        },
        Row {
            what: "sweep through sections: fractions out of order",
            function: "rmf_wire_sweep_through",
            expected: INVALID,
            names: "sections[2].at = 0.2 must be in (0.5, 1)",
            call: |_| {
                let (mut sections, mut curves) = three_circles();
                let extra = circle(0.8);
                curves.push(extra);
                sections[1].at = 0.5;
                sections.insert(
                    2,
                    RmfWireSection {
                        at: 0.2,
                        profile: extra,
                        holes: null(),
                        hole_count: 0,
                    },
                );
                wire_sweep_through(Some(&sections), 4, &curves)
            },
        },
        Row {
            what: "sweep through sections: a section's profile NULL",
            function: "rmf_wire_sweep_through",
            expected: NULL,
            names: "sections[1].profile is NULL",
            call: |_| {
                let (mut sections, curves) = three_circles();
                sections[1].profile = null();
                wire_sweep_through(Some(&sections), 3, &curves)
            },
        },
        Row {
            what: "sweep through sections: a different number of holes",
            function: "rmf_wire_sweep_through",
            expected: INVALID,
            names: "sections[1].holes: it has 1 holes, the profile 0",
            call: |_| {
                let (mut sections, mut curves) = three_circles();
                let hole = circle(0.2);
                curves.push(hole);
                let holes = [hole.cast_const()];
                sections[1].holes = holes.as_ptr();
                sections[1].hole_count = 1;
                wire_sweep_through(Some(&sections), 3, &curves)
            },
        },
        Row {
            what: "face index out of range",
            function: "rmf_shape_face",
            expected: INVALID,
            names: "index = 99 but the shape has 14 faces",
            call: |_| unsafe {
                let (e, profile) = (pipe_route(), circle(1.0));
                let mut shape = null_mut();
                rmf_wire_sweep(e.as_ptr(), 3, profile, null(), 0, null(), &mut shape);
                let mut face = std::mem::MaybeUninit::uninit();
                let status = rmf_shape_face(shape, 99, face.as_mut_ptr());
                rmf_shape_free(shape);
                rmf_curve_free(profile);
                status
            },
        },
        Row {
            what: "STEP path in a missing directory",
            function: "rmf_shape_write_step",
            expected: IO,
            names: "cannot write no/such/dir/pipe.step",
            call: |_| unsafe {
                let (e, profile) = (pipe_route(), circle(1.0));
                let mut shape = null_mut();
                rmf_wire_sweep(e.as_ptr(), 3, profile, null(), 0, null(), &mut shape);
                let status = rmf_shape_write_step(shape, c"no/such/dir/pipe.step".as_ptr());
                rmf_shape_free(shape);
                rmf_curve_free(profile);
                status
            },
        },
        Row {
            what: "transition curve not closed",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "bottom is not closed",
            call: |_| {
                let poles = [v(0., 0., 0.), v(1., 0., 0.), v(1., 1., 0.)];
                let knots = [0., 0., 1., 2., 2.];
                let mut open = null_mut();
                unsafe {
                    rmf_nurbs_curve_create(
                        1,
                        poles.as_ptr(),
                        null(),
                        3,
                        knots.as_ptr(),
                        5,
                        &mut open,
                    )
                };
                transition_with(open, circle_curve(v(0.1, 0., 1.), 0.3), |_| {})
            },
        },
        Row {
            what: "transition curve not planar",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "top is not planar",
            call: |_| {
                let skew =
                    polygon_curve(&[v(0., 0., 1.), v(1., 0., 1.), v(1., 1., 1.2), v(0., 1., 1.)]);
                transition_with(square_curve(), skew, |_| {})
            },
        },
        Row {
            what: "transition curve not convex",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "bottom is not convex",
            call: |_| {
                let dart =
                    polygon_curve(&[v(0., 0., 0.), v(2., 1., 0.), v(0., 0.5, 0.), v(-2., 1., 0.)]);
                transition_with(dart, circle_curve(v(0.1, 0., 1.), 0.3), |_| {})
            },
        },
        Row {
            what: "transition curves that cross",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "the curves cross",
            call: |_| {
                let tilted = polygon_curve(&[
                    v(-1., -1., -0.5),
                    v(1., -1., 0.5),
                    v(1., 1., 0.5),
                    v(-1., 1., -0.5),
                ]);
                transition_with(square_curve(), tilted, |_| {})
            },
        },
        Row {
            what: "thickness 0",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "options->thickness",
            call: |_| {
                transition_with(square_curve(), circle_curve(v(0.1, 0., 1.), 0.3), |o| {
                    o.thickness = 0.0
                })
            },
        },
        Row {
            what: "K-factor outside [0, 1]",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "options->k_factor",
            call: |_| {
                transition_with(square_curve(), circle_curve(v(0.1, 0., 1.), 0.3), |o| {
                    o.k_factor = 1.5
                })
            },
        },
        Row {
            what: "thickness beyond the smallest bend radius",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "bend radius",
            call: |_| {
                transition_with(square_curve(), circle_curve(v(0.1, 0., 1.), 0.3), |o| {
                    o.reference = RMF_SHEET_REFERENCE_OUTER
                })
            },
        },
        Row {
            what: "sheet options of unknown size",
            function: "rmf_sheet_part_transition",
            expected: INVALID,
            names: "options->struct_size",
            call: |_| {
                transition_with(square_curve(), circle_curve(v(0.1, 0., 1.), 0.3), |o| {
                    o.struct_size = 8
                })
            },
        },
        Row {
            what: "flat mark outside the part",
            function: "rmf_sheet_part_flat_to_surface",
            expected: INVALID,
            names: "flat[1]",
            call: |_| {
                with_part(|part| {
                    let flat = [RmfVec2 { x: 0.1, y: 0.0 }, RmfVec2 { x: 1e3, y: 0.0 }];
                    let mut points = [v(0., 0., 0.); 2];
                    unsafe {
                        rmf_sheet_part_flat_to_surface(
                            part,
                            flat.as_ptr(),
                            2,
                            RMF_SHEET_LAYER_NEUTRAL,
                            points.as_mut_ptr(),
                            null_mut(),
                        )
                    }
                })
            },
        },
        Row {
            what: "formed mark off the part",
            function: "rmf_sheet_part_surface_to_flat",
            expected: INVALID,
            names: "points[0]",
            call: |_| {
                with_part(|part| {
                    let points = [v(5., 5., 5.)];
                    let mut flat = [RmfVec2 { x: 0., y: 0. }];
                    unsafe {
                        rmf_sheet_part_surface_to_flat(
                            part,
                            points.as_ptr(),
                            1,
                            RMF_SHEET_LAYER_OUTER,
                            1e-6,
                            flat.as_mut_ptr(),
                        )
                    }
                })
            },
        },
        Row {
            what: "flat pattern buffer too small",
            function: "rmf_sheet_part_flat_pattern",
            expected: TOO_SMALL,
            names: "need",
            call: |_| {
                with_part(|part| {
                    let mut edges = [RmfFlatEdge::default(); 2];
                    let mut count = 0;
                    unsafe { rmf_sheet_part_flat_pattern(part, edges.as_mut_ptr(), 2, &mut count) }
                })
            },
        },
        Row {
            what: "ruled part of a surface that is not developable",
            function: "rmf_sheet_part_between_rails",
            expected: INVALID,
            names: "surface: the surface is not developable",
            call: |_| {
                let saddle = saddle_surface();
                let mut out = null_mut();
                unsafe {
                    let status = rmf_sheet_part_between_rails(saddle, null(), &mut out);
                    rmf_sheet_part_free(out);
                    rmf_surface_free(saddle);
                    status
                }
            },
        },
        Row {
            what: "ruled part of a NULL surface",
            function: "rmf_sheet_part_between_rails",
            expected: NULL,
            names: "surface",
            call: |_| {
                let mut out = null_mut();
                unsafe { rmf_sheet_part_between_rails(null(), null(), &mut out) }
            },
        },
        Row {
            what: "tangent part through the edge of regression",
            function: "rmf_sheet_part_tangent",
            expected: INVALID,
            names: "contains 0",
            call: |_| tangent_part_with(-0.5, 0.5),
        },
        Row {
            what: "tangent part with v_min ≥ v_max",
            function: "rmf_sheet_part_tangent",
            expected: INVALID,
            names: "v_min",
            call: |_| tangent_part_with(0.5, 0.2),
        },
        Row {
            what: "cone spline that is not a part",
            function: "rmf_cone_spline_part_report",
            expected: INVALID,
            names: "not a sheet-metal part",
            call: |_| {
                let mut spline = null_mut();
                let mut report = RmfSheetReport::default();
                unsafe {
                    twisted_cubic_cones(0, 1000, &mut spline);
                    #[allow(deprecated)] // the deprecated wrapper of a part held by a cone spline
                    let status = rmf_cone_spline_part_report(spline, &mut report);
                    rmf_cone_spline_free(spline);
                    status
                }
            },
        },
        Row {
            what: "fit clearance of no spline",
            function: "rmf_cone_spline_fit_clearance",
            expected: NULL,
            names: "spline",
            call: |_| {
                let mut clearance = 0.0;
                unsafe { rmf_cone_spline_fit_clearance(null(), &mut clearance) }
            },
        },
        Row {
            what: "fit clearance without an out-pointer",
            function: "rmf_cone_spline_fit_clearance",
            expected: NULL,
            names: "clearance",
            call: |_| {
                let mut spline = null_mut();
                unsafe {
                    twisted_cubic_cones(0, 1000, &mut spline);
                    let status = rmf_cone_spline_fit_clearance(spline, null_mut());
                    rmf_cone_spline_free(spline);
                    status
                }
            },
        },
        Row {
            what: "fit clearance of a spline that is not a fit",
            function: "rmf_cone_spline_fit_clearance",
            expected: INVALID,
            names: "not made by an approximation",
            call: |_| {
                // Rulings through the origin: a cone pair with their common vertex.
                let e = RmfConeElement {
                    point: v(1., 0., 1.),
                    ruling: v(1., 0., 1.),
                    side: v(0., 1., 0.),
                };
                let second = RmfConeElement {
                    point: v(0., 1., 1.),
                    ruling: v(0., 1., 1.),
                    side: v(-1., 0., 0.),
                };
                let (mut spline, mut clearance) = (null_mut(), 0.0);
                unsafe {
                    let made = rmf_cone_spline_hermite(
                        [e, second].as_ptr(),
                        2,
                        RMF_CONE_RULE_MIN_VERTEX_DISTANCE,
                        0.0,
                        null(),
                        &mut spline,
                    );
                    assert_eq!(made, RmfStatus::RmfOk, "{}", last_error());
                    let status = rmf_cone_spline_fit_clearance(spline, &mut clearance);
                    rmf_cone_spline_free(spline);
                    status
                }
            },
        },
        Row {
            what: "cone approximation options NULL",
            function: "rmf_cone_spline_approximate_with_options",
            expected: NULL,
            names: "options",
            call: |f| cone_with(f, |_| {}, true),
        },
        Row {
            what: "cone approximation options not initialised",
            function: "rmf_cone_spline_approximate_with_options",
            expected: INVALID,
            names: "options->struct_size",
            call: |f| cone_with(f, |o| o.struct_size = 0, false),
        },
        Row {
            what: "cone approximation tolerance left at its default 0",
            function: "rmf_cone_spline_approximate_with_options",
            expected: INVALID,
            names: "options: tolerance",
            call: |f| cone_with(f, |o| o.tolerance = 0.0, false),
        },
        Row {
            what: "cone approximation rule RMF_CONE_RULE_GIVEN",
            function: "rmf_cone_spline_approximate_with_options",
            expected: INVALID,
            names: "options: rule",
            call: |f| cone_with(f, |o| o.rule = RMF_CONE_RULE_GIVEN, false),
        },
        Row {
            what: "osculating cones of no curve",
            function: "rmf_cone_spline_osculating_curve",
            expected: NULL,
            names: "curve",
            call: |_| {
                let parameters = [0.2, 0.5];
                let mut out = null_mut();
                unsafe {
                    rmf_cone_spline_osculating_curve(
                        null(),
                        0.5,
                        1.0,
                        parameters.as_ptr(),
                        2,
                        &mut out,
                    )
                }
            },
        },
        Row {
            what: "surface data NULL",
            function: "rmf_nurbs_surface_create_from",
            expected: NULL,
            names: "data",
            call: |_| {
                let mut out = null_mut();
                unsafe { rmf_nurbs_surface_create_from(null(), &mut out) }
            },
        },
        Row {
            what: "surface data struct_size not set",
            function: "rmf_nurbs_surface_create_from",
            expected: INVALID,
            names: "data->struct_size",
            call: |_| surface_from(|d| d.struct_size = 0),
        },
        Row {
            what: "surface data knot count off",
            function: "rmf_nurbs_surface_create_from",
            expected: INVALID,
            names: "data: knot_count_v",
            call: |_| surface_from(|d| d.knot_count_v = 3),
        },
        Row {
            what: "surface copy buffers NULL",
            function: "rmf_surface_nurbs_copy_into",
            expected: NULL,
            names: "buffers",
            call: |_| copy_into(|_| {}, true),
        },
        Row {
            what: "surface copy buffers struct_size not set",
            function: "rmf_surface_nurbs_copy_into",
            expected: INVALID,
            names: "buffers->struct_size",
            call: |_| copy_into(|b| b.struct_size = 0, false),
        },
    ]
}

fn last_error() -> String {
    unsafe { CStr::from_ptr(rmf_last_error()) }
        .to_string_lossy()
        .into_owned()
}

fn status_name(status: RmfStatus) -> String {
    unsafe { CStr::from_ptr(rmf_status_name(status as u32)) }
        .to_string_lossy()
        .into_owned()
}

/// The method of wire sweeps defaults to the PH cubic spline's rational RMF, and each
/// method of a wire sweep is taken on the pipe route (lines and an arc: exact whatever
/// the method).
#[test]
fn wire_sweep_method_defaults_to_ph_rmf() {
    let mut options = std::mem::MaybeUninit::<RmfWireSweepOptions>::uninit();
    let options = unsafe {
        assert_eq!(
            rmf_wire_sweep_options_init(options.as_mut_ptr()),
            RmfStatus::RmfOk
        );
        options.assume_init()
    };
    assert_eq!(options.method, RMF_SPINE_PH_RMF);
    for method in [RMF_SPINE_PH_RMF, RMF_SPINE_MOBIUS, RMF_SPINE_RRMF] {
        let status = wire_sweep(&pipe_route(), circle(1.0), &[], |o| o.method = method);
        assert_eq!(
            status,
            RmfStatus::RmfOk,
            "method {method}: {}",
            last_error()
        );
    }
}

/// A guide frame's bad guides (NULL, a count of 0, a point that is not finite) leave the
/// out-pointer as it was; a good guide on the same call writes it (the check can fail).
#[test]
fn bad_guides_write_nothing() {
    let sentinel = 0x5e5e_usize as *mut RmfShape;
    let edges = [line(v(0., 0., 0.), v(0., 0., 4.))];
    let good = [line(v(2., 0., 0.), v(2., 0., 4.))];
    let not_finite = [line(v(2., 0., 0.), v(2., NAN, 4.))];
    let cases: [(*const RmfEdge, usize, RmfStatus, &str); 4] = [
        (null(), 1, NULL, "options->guide_edges is NULL"),
        (good.as_ptr(), 0, INVALID, "options->guide_edge_count = 0"),
        (null(), 0, INVALID, "options->guide_edges"),
        (
            not_finite.as_ptr(),
            1,
            INVALID,
            "options->guide_edges[0].points[1] = [2, NaN, 4] is not finite",
        ),
    ];
    let profile = circle(0.5);
    for (guide, count, expected, names) in
        cases
            .into_iter()
            .chain([(good.as_ptr(), 1, RmfStatus::RmfOk, "")])
    {
        let mut options = RmfWireSweepOptions::default();
        unsafe { rmf_wire_sweep_options_init(&mut options) };
        options.frame = RMF_FRAME_GUIDE;
        options.guide_edges = guide;
        options.guide_edge_count = count;
        let mut out = sentinel;
        let status = unsafe {
            rmf_wire_sweep(
                edges.as_ptr(),
                edges.len(),
                profile,
                null(),
                0,
                &options,
                &mut out,
            )
        };
        let message = last_error();
        assert_eq!(status, expected, "{names}: {message}");
        if expected == RmfStatus::RmfOk {
            assert!(!out.is_null() && out != sentinel, "a shape is written");
            unsafe { rmf_shape_free(out) };
        } else {
            assert!(message.contains(names), "{message}");
            assert_eq!(out, sentinel, "{names}: nothing written");
        }
    }
    unsafe { rmf_curve_free(profile) };
}

#[test]
fn every_bad_input_gets_its_status_and_a_message_naming_it() {
    let fixtures = Fixtures::new();
    for row in rows() {
        let status = (row.call)(&fixtures);
        let message = last_error();
        println!("{}: {} {message}", row.what, status_name(status));
        assert_eq!(status, row.expected, "{}: {message}", row.what);
        assert!(
            message.starts_with(&format!("{}: ", row.function)),
            "{}: {message}",
            row.what
        );
        assert!(message.contains(row.names), "{}: {message}", row.what);
    }
}

#[test]
fn the_docs_list_every_row_with_its_status() {
    let docs =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/hardening.md"))
            .unwrap();
    let table = docs
        .split("## Bad inputs")
        .nth(1)
        .expect("a '## Bad inputs' section in docs/hardening.md");
    let lines: Vec<&str> = table.lines().take_while(|l| !l.starts_with("##")).collect();
    for row in rows() {
        let line = lines
            .iter()
            .find(|l| l.starts_with(&format!("| {} |", row.what)))
            .unwrap_or_else(|| panic!("docs/hardening.md: no row for '{}'", row.what));
        assert!(
            line.contains(&format!("`{}`", row.function))
                && line.contains(&status_name(row.expected)),
            "docs/hardening.md row for '{}' should name `{}` and {}: {line}",
            row.what,
            row.function,
            status_name(row.expected)
        );
    }
}
