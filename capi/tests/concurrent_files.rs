//! Files written at once: threads writing STEP files to one path each finish a whole file
//! under their own temporary name, and the path ends with one whole file (issue 25, class
//! 5: with one temporary name per process, half of 8 threads failed with "No such file or
//! directory").

use rmfsurf_capi::curve::{rmf_curve_free, rmf_nurbs_curve_create};
use rmfsurf_capi::shape::{rmf_shape_free, rmf_shape_write_step};
use rmfsurf_capi::wire::{
    rmf_wire_sweep, rmf_wire_sweep_options_init, RmfEdge, RmfWireSweepOptions, RMF_EDGE_LINE,
};
use rmfsurf_capi::{RmfCurve, RmfShape, RmfStatus, RmfVec3};
use std::ffi::CString;
use std::ptr::{null, null_mut};

fn v(x: f64, y: f64, z: f64) -> RmfVec3 {
    RmfVec3 { x, y, z }
}

/// A bar along x with a square profile, through the C API.
fn bar() -> *mut RmfShape {
    let poles = [
        v(-1., -1., 0.),
        v(1., -1., 0.),
        v(1., 1., 0.),
        v(-1., 1., 0.),
        v(-1., -1., 0.),
    ];
    let knots = [0., 0., 1., 2., 3., 4., 4.];
    let mut profile: *mut RmfCurve = null_mut();
    let mut options = RmfWireSweepOptions::default();
    let edge = RmfEdge {
        kind: RMF_EDGE_LINE,
        points: [v(0., 0., 0.), v(10., 0., 0.), v(0., 0., 0.)],
        curve: null(),
    };
    let mut shape: *mut RmfShape = null_mut();
    unsafe {
        assert_eq!(
            rmf_nurbs_curve_create(
                1,
                poles.as_ptr(),
                null(),
                5,
                knots.as_ptr(),
                7,
                &mut profile
            ),
            RmfStatus::RmfOk
        );
        assert_eq!(rmf_wire_sweep_options_init(&mut options), RmfStatus::RmfOk);
        assert_eq!(
            rmf_wire_sweep(&edge, 1, profile, null(), 0, &options, &mut shape),
            RmfStatus::RmfOk
        );
        rmf_curve_free(profile);
    }
    shape
}

struct Shared(*mut RmfShape);
unsafe impl Send for Shared {}
unsafe impl Sync for Shared {}

#[test]
fn threads_writing_one_step_path_all_succeed() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("concurrent_step");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = CString::new(dir.join("same.step").to_str().unwrap()).unwrap();
    let shape = Shared(bar());
    let expected = {
        let single = dir.join("single.step");
        let single_c = CString::new(single.to_str().unwrap()).unwrap();
        assert_eq!(
            unsafe { rmf_shape_write_step(shape.0, single_c.as_ptr()) },
            RmfStatus::RmfOk
        );
        std::fs::read_to_string(single)
            .unwrap()
            .replace("single", "same")
    };
    for _round in 0..5 {
        let statuses: Vec<RmfStatus> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..8)
                .map(|_| {
                    let (shape, path) = (&shape, &path);
                    s.spawn(move || unsafe { rmf_shape_write_step(shape.0, path.as_ptr()) })
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        });
        assert!(
            statuses.iter().all(|&s| s == RmfStatus::RmfOk),
            "{statuses:?}"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("same.step")).unwrap(),
            expected
        );
    }
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left.len(), 2, "temporary files left: {left:?}");
    unsafe { rmf_shape_free(shape.0) };
}
