//! The hot path allocates nothing: evaluating frames, curves and surfaces — through the C API
//! and through the Rust API — is counted by a global allocator that records every allocation
//! made on the calling thread, and the count must not move while 10,000 evaluations run.
//! (Construction allocates, of course; it happens before counting starts.)

use rmfsurf::glam::DVec3;
use rmfsurf::{
    ph::rational_rmf as ph_rational_rmf, ph::spline_approximate as ph_spline_approximate,
    ph::spline_hermite as ph_spline_hermite, ph::RmfOptions, sweep, ParametricCurve,
};
use rmfsurf_capi::curve::{rmf_curve_eval, rmf_curve_free, rmf_nurbs_curve_create};
use rmfsurf_capi::frames::{rmf_double_reflection_frames, rmf_frames_eval, rmf_frames_free};
use rmfsurf_capi::mobius::rmf_mobius_rrmf_hermite;
use rmfsurf_capi::ph_cubic::{rmf_ph_rational_rmf, rmf_ph_spline_hermite};
use rmfsurf_capi::surface::{rmf_surface_eval, rmf_surface_free, rmf_sweep_surface};
use rmfsurf_capi::{RmfCurve, RmfFrames, RmfStatus, RmfSurface, RmfVec3};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::ptr::null_mut;

/// The system allocator, counting allocations per thread (other test threads do not count).
struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|a| a.set(a.get() + 1));
        System.alloc(layout)
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.with(|a| a.set(a.get() + 1));
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Allocations made on this thread while `f` runs.
fn allocations_during(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    f();
    ALLOCATIONS.with(Cell::get) - before
}

const EVALUATIONS: usize = 10_000;

/// Helix data: 9 points with tangents.
fn helix() -> (Vec<RmfVec3>, Vec<RmfVec3>) {
    (0..9)
        .map(|i| {
            let t = 0.6 * i as f64;
            let (s, c) = t.sin_cos();
            (
                RmfVec3 {
                    x: c,
                    y: s,
                    z: 0.4 * t,
                },
                RmfVec3 {
                    x: -s,
                    y: c,
                    z: 0.4,
                },
            )
        })
        .unzip()
}

/// Parameters spread over [0, 8] (the helix splines' domain).
fn parameter(i: usize) -> f64 {
    8.0 * i as f64 / (EVALUATIONS - 1) as f64
}

#[test]
fn c_api_evaluation_does_not_allocate() {
    let (points, tangents) = helix();
    let up = RmfVec3 {
        x: 0.0,
        y: 0.0,
        z: 1.0,
    };
    let (mut spine, mut rmf, mut profile, mut surface): (
        *mut RmfCurve,
        *mut RmfFrames,
        *mut RmfCurve,
        *mut RmfSurface,
    ) = (null_mut(), null_mut(), null_mut(), null_mut());
    let (mut mobius_curve, mut mobius_frames, mut reflected) = (null_mut(), null_mut(), null_mut());
    let line = [
        RmfVec3 {
            x: 0.1,
            y: 0.0,
            z: 0.0,
        },
        RmfVec3 {
            x: 0.3,
            y: 0.1,
            z: 0.0,
        },
    ];
    let knots = [0.0, 0.0, 1.0, 1.0];
    unsafe {
        let ok = [
            rmf_ph_spline_hermite(points.as_ptr(), tangents.as_ptr(), 9, &mut spine),
            rmf_ph_rational_rmf(spine, up, &mut rmf),
            rmf_nurbs_curve_create(
                1,
                line.as_ptr(),
                std::ptr::null(),
                2,
                knots.as_ptr(),
                4,
                &mut profile,
            ),
            rmf_sweep_surface(spine, rmf, profile, &mut surface),
            rmf_mobius_rrmf_hermite(
                points.as_ptr(),
                tangents.as_ptr(),
                9,
                up,
                &mut mobius_curve,
                &mut mobius_frames,
            ),
            rmf_double_reflection_frames(spine, up, 400, &mut reflected),
        ];
        assert!(ok.iter().all(|&s| s == RmfStatus::RmfOk), "{ok:?}");
    }
    let (mut p, mut d, mut t, mut f2, mut f3) = Default::default();
    let mut du = RmfVec3::default();
    // Warm up: a handle may build a view on first use (not on the evaluation path).
    unsafe { rmf_frames_eval(rmf, 0.5, &mut t, &mut f2, &mut f3) };
    let count = allocations_during(|| {
        for i in 0..EVALUATIONS {
            let s = parameter(i);
            unsafe {
                rmf_curve_eval(spine, s, &mut p, &mut d);
                rmf_frames_eval(rmf, s, &mut t, &mut f2, &mut f3);
                rmf_frames_eval(mobius_frames, s, &mut t, &mut f2, &mut f3);
                rmf_frames_eval(reflected, s, &mut t, &mut f2, &mut f3);
                rmf_surface_eval(surface, 0.5, s, &mut p, &mut du, &mut d);
            }
        }
    });
    assert_eq!(
        count, 0,
        "allocations in {EVALUATIONS} rounds of evaluations"
    );
    // The count is live: a failing call (whose message is formatted) does allocate.
    let failing = allocations_during(|| unsafe {
        rmf_curve_eval(spine, f64::NAN, &mut p, &mut d);
    });
    assert!(failing > 0);
    unsafe {
        rmf_surface_free(surface);
        rmf_curve_free(profile);
        rmf_frames_free(rmf);
        rmf_frames_free(reflected);
        rmf_frames_free(mobius_frames);
        rmf_curve_free(mobius_curve);
        rmf_curve_free(spine);
    }
}

#[test]
fn rust_api_evaluation_does_not_allocate() {
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = helix()
        .0
        .iter()
        .zip(helix().1)
        .map(|(p, t)| (DVec3::new(p.x, p.y, p.z), DVec3::new(t.x, t.y, t.z)))
        .unzip();
    let spline = ph_spline_hermite(&points, &tangents).unwrap();
    let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(DVec3::Z)).unwrap();
    let profile = rmfsurf::PiecewiseCurve::with_unit_intervals(vec![
        rmfsurf::RationalBezierCurve::polynomial(&[DVec3::X * 0.1, DVec3::Y * 0.2]).unwrap(),
    ])
    .unwrap();
    let surface = sweep(&rmf.framed, &profile).unwrap();
    // The user's path: a curve sampled as the approximation samples it, and its PH spline.
    let approximated = ph_spline_approximate(&spline, spline.breaks(), 1e-6).unwrap();
    let mut sink = 0.0;
    let count = allocations_during(|| {
        for i in 0..EVALUATIONS {
            let s = parameter(i);
            sink += rmf.framed.frames().frame(s).f2.x;
            sink += spline.eval_jet(s).d2.y;
            sink += surface.eval_jet(0.3, s).duv.z;
            sink += ParametricCurve::point_derivative(&spline, s).unwrap().1.x;
            sink += approximated.spline.eval_jet(s).d1.z;
        }
    });
    assert!(sink.is_finite());
    assert_eq!(
        count, 0,
        "allocations in {EVALUATIONS} rounds of evaluations"
    );
}
