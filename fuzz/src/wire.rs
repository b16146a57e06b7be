//! Operations on the wire sweep entry points: wires of lines, arcs and pooled curves
//! (mostly connected, sometimes not), profiles (a circle or square of any size, or a pooled
//! curve) with holes, options of every value (a guide frame's edges drawn like the wire's); then the shapes' faces, loops, report, STEP
//! file, texts (STEP, OpenCascade's B-rep) and B-rep model, each checked against the contract (a solid's figures finite and in range, caps with
//! unit normals, borrowed surfaces that evaluate).

use rmfsurf_capi::curve::rmf_nurbs_curve_create;
use rmfsurf_capi::shape::*;
use rmfsurf_capi::surface::{rmf_surface_domain, rmf_surface_eval};
use rmfsurf_capi::wire::*;
use rmfsurf_capi::{RmfBrep, RmfCurve, RmfShape, RmfVec3};
use std::ptr::null_mut;

use super::core::or_null;
use super::session::{checked, is_poisoned, poisoned, status_ok, Session};

/// The operations of this module.
pub const OPS: &[fn(&mut Session)] = &[
    profile_curve,
    wire_sweep,
    wire_sweep,
    wire_sweep,
    shape_faces,
    shape_report,
    shape_step,
    shape_texts,
    shape_brep,
    shape_binary,
];

fn add(a: RmfVec3, b: RmfVec3) -> RmfVec3 {
    RmfVec3 {
        x: a.x + b.x,
        y: a.y + b.y,
        z: a.z + b.z,
    }
}

/// A closed profile in the normal plane: a circle (four quarters) or a square, of a size
/// drawn from the input, added to the curve pool.
fn profile_curve(s: &mut Session) {
    let r = s.input.f64();
    if super::session::tracing() {
        eprintln!("profile curve: size {r}");
    }
    let q = std::f64::consts::FRAC_1_SQRT_2;
    let (poles, weights, knots, degree): (Vec<RmfVec3>, Vec<f64>, Vec<f64>, u32) = if s.input.flag()
    {
        let c = [
            (1., 0.),
            (1., 1.),
            (0., 1.),
            (-1., 1.),
            (-1., 0.),
            (-1., -1.),
            (0., -1.),
            (1., -1.),
            (1., 0.),
        ];
        (
            c.iter()
                .map(|&(x, y)| RmfVec3 {
                    x: r * x,
                    y: r * y,
                    z: 0.0,
                })
                .collect(),
            (0..9).map(|k| if k % 2 == 1 { q } else { 1.0 }).collect(),
            vec![0., 0., 0., 1., 1., 2., 2., 3., 3., 4., 4., 4.],
            2,
        )
    } else {
        let c = [(1., 1.), (-1., 1.), (-1., -1.), (1., -1.), (1., 1.)];
        (
            c.iter()
                .map(|&(x, y)| RmfVec3 {
                    x: r * x,
                    y: r * y,
                    z: 0.0,
                })
                .collect(),
            vec![1.0; 5],
            vec![0., 0., 1., 2., 3., 4., 4.],
            1,
        )
    };
    let mut out = poisoned();
    let status = unsafe {
        rmf_nurbs_curve_create(
            degree,
            poles.as_ptr(),
            weights.as_ptr(),
            poles.len(),
            knots.as_ptr(),
            knots.len(),
            &mut out,
        )
    };
    s.made("rmf_nurbs_curve_create", status, Some(out), None);
}

/// A wire: mostly connected (each edge starts where the previous one ended, or at a point
/// near it), of lines, arcs through a drawn point, and pooled curves.
fn edges(s: &mut Session) -> Vec<RmfEdge> {
    let n = s.input.len(6);
    let mut at = s.input.vec3();
    (0..n)
        .map(|_| {
            let kind = match s.input.byte() % 8 {
                0..=3 => RMF_EDGE_LINE,
                4..=5 => RMF_EDGE_ARC,
                6 => RMF_EDGE_CURVE,
                _ => s.input.code(),
            };
            let start = if s.input.below(8) == 0 {
                s.input.vec3()
            } else {
                at
            };
            let (through, end) = if s.input.flag() {
                (
                    add(start, s.input.small_vec3()),
                    add(start, s.input.small_vec3()),
                )
            } else {
                (s.input.vec3(), s.input.vec3())
            };
            at = if kind == RMF_EDGE_LINE { through } else { end };
            RmfEdge {
                kind,
                points: [start, through, end],
                curve: s.curve(),
            }
        })
        .collect()
}

fn options(s: &mut Session) -> RmfWireSweepOptions {
    let mut o = poisoned::<RmfWireSweepOptions>();
    unsafe { rmf_wire_sweep_options_init(&mut o) };
    if s.input.flag() {
        o.tolerance = s.input.f64();
    }
    if s.input.flag() {
        o.join_tolerance = s.input.f64();
    }
    o.corner = if s.input.below(4) == 0 {
        s.input.code()
    } else {
        s.input.below(2) as u32
    };
    if s.input.flag() {
        o.corner_radius = s.input.f64();
    }
    if s.input.flag() {
        o.initial_normal = s.input.vec3();
    }
    if s.input.below(4) == 0 {
        o.twist = s.input.f64();
    }
    o.closure_symmetry = s.input.code();
    o.solid = if s.input.below(8) == 0 {
        s.input.code()
    } else {
        s.input.below(2) as u32
    };
    o.frame = if s.input.below(4) == 0 {
        s.input.code()
    } else {
        s.input.below(4) as u32
    };
    if s.input.flag() {
        o.frame_direction = s.input.vec3();
    }
    if s.input.below(4) == 0 {
        o.scale_start = s.input.f64();
    }
    if s.input.below(4) == 0 {
        o.scale_end = s.input.f64();
    }
    o.pipe_frame = if s.input.below(8) == 0 {
        s.input.code()
    } else {
        s.input.below(2) as u32
    };
    if s.input.below(16) == 0 {
        o.struct_size = s.input.work();
    }
    o
}

fn wire_sweep(s: &mut Session) {
    let edges = edges(s);
    let profile = s.curve();
    let holes: Vec<*const RmfCurve> = (0..s.input.len(2)).map(|_| s.curve()).collect();
    let mut options = options(s);
    // A guide frame's edges, drawn like the wire's (NULL sometimes); kept alive to the call.
    let guide = if options.frame == RMF_FRAME_GUIDE {
        self::edges(s)
    } else {
        Vec::new()
    };
    if options.frame == RMF_FRAME_GUIDE {
        options.guide_edges = or_null(&mut s.input, &guide);
        options.guide_edge_count = guide.len();
    }
    let with_options = s.input.below(8) != 0;
    if super::session::tracing() {
        eprintln!(
            "wire sweep: edges {edges:?}, holes {}, options {options:?}, guide {guide:?}",
            holes.len()
        );
    }
    let mut out: *mut RmfShape = poisoned();
    let status = unsafe {
        rmf_wire_sweep(
            or_null(&mut s.input, &edges),
            edges.len(),
            profile,
            or_null(&mut s.input, &holes),
            holes.len(),
            if with_options {
                &options
            } else {
                std::ptr::null()
            },
            &mut out,
        )
    };
    s.made_shape("rmf_wire_sweep", status, out);
}

fn shape_faces(s: &mut Session) {
    let shape = s.shape();
    let count = unsafe { rmf_shape_face_count(shape) };
    assert!(shape.is_null() || count > 0, "a shape without faces");
    let solid = unsafe { rmf_shape_is_solid(shape) };
    assert!(solid <= 1);
    let index = if s.input.flag() {
        s.input.work()
    } else {
        s.input.below(count.max(1))
    };
    let mut face = poisoned::<RmfShapeFace>();
    let status = unsafe { rmf_shape_face(shape, index, &mut face) };
    if !checked("rmf_shape_face", status, &[is_poisoned(&face)]) {
        return;
    }
    assert!(index < count);
    match face.kind {
        RMF_FACE_SWEPT => {
            assert!(!face.surface.is_null() && face.loop_count == 0);
            let (mut u0, mut u1, mut v0, mut v1) = (0.0, 0.0, 0.0, 0.0);
            let mut p = poisoned::<RmfVec3>();
            unsafe {
                assert!(status_ok(
                    "rmf_surface_domain",
                    rmf_surface_domain(face.surface, &mut u0, &mut u1, &mut v0, &mut v1)
                ));
                let status = rmf_surface_eval(
                    face.surface,
                    0.5 * (u0 + u1),
                    0.5 * (v0 + v1),
                    &mut p,
                    null_mut(),
                    null_mut(),
                );
                assert!(status_ok("rmf_surface_eval", status));
            }
            assert!(
                p.x.is_finite() && p.y.is_finite() && p.z.is_finite(),
                "a face point {p:?}"
            );
        }
        RMF_FACE_PLANE => {
            assert!(face.surface.is_null() && face.loop_count >= 1);
            let n = face.plane_normal;
            assert!(
                ((n.x * n.x + n.y * n.y + n.z * n.z).sqrt() - 1.0).abs() < 1e-9,
                "cap normal {n:?}"
            );
            let l = s.input.below(face.loop_count + 1);
            let mut c = poisoned::<*const RmfCurve>();
            let status = unsafe { rmf_shape_face_loop(shape, index, l, &mut c) };
            if checked("rmf_shape_face_loop", status, &[is_poisoned(&c)]) {
                assert!(!c.is_null() && l < face.loop_count);
            }
        }
        other => panic!("rmf_shape_face: kind {other}"),
    }
}

fn shape_report(s: &mut Session) {
    let shape = s.shape();
    let mut r = poisoned::<RmfSweepReport>();
    let status = unsafe { rmf_shape_report(shape, &mut r) };
    if !checked("rmf_shape_report", status, &[is_poisoned(&r)]) {
        return;
    }
    for (name, x) in [
        ("spine_distance", r.spine_distance),
        ("rmf_angle_error", r.rmf_angle_error),
        ("max_parameter_cosine", r.max_parameter_cosine),
        ("corner_turn", r.corner_turn),
        ("seam_gap", r.seam_gap),
        ("joint_gap", r.joint_gap),
    ] {
        assert!(x.is_finite() && x >= 0.0, "report: {name} = {x}");
    }
    assert!(r.max_parameter_cosine <= 1.0 + 1e-12);
    assert!(
        r.singularity_margin > 0.0 && r.singularity_margin <= 1.0 + 1e-12,
        "margin {}",
        r.singularity_margin
    );
    assert_eq!(r.face_count, unsafe { rmf_shape_face_count(shape) });
    // A solid encloses a positive volume (or one outside a double's range, refused); a
    // sheet none.
    let mut volume = poisoned::<f64>();
    let status = unsafe { rmf_shape_volume(shape, &mut volume) };
    if checked("rmf_shape_volume", status, &[is_poisoned(&volume)]) {
        assert_eq!(unsafe { rmf_shape_is_solid(shape) }, 1, "a sheet's volume");
        assert!(volume.is_finite() && volume > 0.0, "volume {volume}");
    }
}

fn shape_step(s: &mut Session) {
    let shape = s.shape();
    let dir = std::env::temp_dir().join(format!("rmfsurf-fuzz-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let path = dir.join("shape.step");
    let c_path = std::ffi::CString::new(path.to_string_lossy().into_owned()).expect("no NUL");
    let status = unsafe { rmf_shape_write_step(shape, c_path.as_ptr()) };
    let written = path.exists();
    if status_ok("rmf_shape_write_step", status) {
        assert!(written, "rmf_shape_write_step succeeded without the file");
    } else {
        assert!(!written, "rmf_shape_write_step failed but wrote the file");
    }
    let _ = std::fs::remove_file(&path);
    let _ = std::fs::remove_dir(&dir);
}

/// The STEP and OpenCascade B-rep texts of a shape: a size query, then the text into a
/// buffer of exactly that size, NUL-terminated; the B-rep text from its version line to
/// the root reference.
fn shape_texts(s: &mut Session) {
    let shape = s.shape();
    type Text = unsafe extern "C" fn(
        *const RmfShape,
        *mut std::ffi::c_char,
        usize,
        *mut usize,
    ) -> rmfsurf_capi::RmfStatus;
    unsafe extern "C" fn step(
        shape: *const RmfShape,
        buffer: *mut std::ffi::c_char,
        capacity: usize,
        length: *mut usize,
    ) -> rmfsurf_capi::RmfStatus {
        rmf_shape_step(shape, std::ptr::null(), buffer, capacity, length)
    }
    let calls: [(&str, Text); 2] = [
        ("rmf_shape_step", step),
        ("rmf_shape_occ_brep", rmf_shape_occ_brep),
    ];
    for (name, call) in calls {
        let mut length = poisoned::<usize>();
        let status = unsafe { call(shape, null_mut(), 0, &mut length) };
        if !checked(name, status, &[is_poisoned(&length)]) {
            continue;
        }
        let mut buffer = vec![0xAAu8; length + 1];
        let mut again = 0usize;
        let status = unsafe { call(shape, buffer.as_mut_ptr().cast(), length + 1, &mut again) };
        assert!(
            status_ok(name, status),
            "{name}: the size it gave is not enough"
        );
        assert_eq!(again, length, "{name}: the length changed");
        assert_eq!(buffer[length], 0, "{name}: no NUL");
        let text = std::str::from_utf8(&buffer[..length]).expect("UTF-8 text");
        assert!(!text.contains('\0'), "{name}: a NUL inside the text");
        if name == "rmf_shape_occ_brep" {
            assert!(text.starts_with("\nCASCADE Topology V1, (c) Matra-Datavision\n"));
            assert!(text.ends_with("\n+1 0\n"));
            assert!(
                !text.contains("NaN") && !text.contains("inf"),
                "a number out of range"
            );
        }
    }
}

/// The binary B-rep of a shape for both readers: a size query, then the file into a buffer
/// of exactly that size; the same set before either root, the version line first.
fn shape_binary(s: &mut Session) {
    let shape = s.shape();
    let mut files = Vec::new();
    for reader in [RMF_OCC_READER_BINTOOLS, RMF_OCC_READER_FREECAD] {
        let name = "rmf_shape_occ_binary";
        let mut length = poisoned::<usize>();
        let status = unsafe { rmf_shape_occ_binary(shape, reader, null_mut(), 0, &mut length) };
        if !checked(name, status, &[is_poisoned(&length)]) {
            return;
        }
        let mut buffer = vec![0xAAu8; length];
        let mut again = 0usize;
        let status =
            unsafe { rmf_shape_occ_binary(shape, reader, buffer.as_mut_ptr(), length, &mut again) };
        assert!(
            status_ok(name, status),
            "{name}: the size it gave is not enough"
        );
        assert_eq!(again, length, "{name}: the length changed");
        assert!(buffer.starts_with(b"\nOpen CASCADE Topology V3 (c)\n"));
        files.push(buffer);
    }
    let (bintools, freecad) = (&files[0], &files[1]);
    assert_eq!(freecad.len(), bintools.len() + 3, "the two roots");
    assert_eq!(
        bintools[..bintools.len() - 9],
        freecad[..freecad.len() - 12]
    );
}

/// The B-rep model of a shape (rmf_shape_brep), walked and freed (`brep::walk`).
fn shape_brep(s: &mut Session) {
    let shape = s.shape();
    let mut brep = poisoned::<*mut RmfBrep>();
    let status = unsafe { rmf_shape_brep(shape, &mut brep) };
    if checked("rmf_shape_brep", status, &[is_poisoned(&brep)]) {
        super::brep::walk(brep);
    }
}
