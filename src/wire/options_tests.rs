//! Frames and scale laws of wire sweeps against closed forms: a frustum's volume, the
//! volume π r² ∫σ² ds of a scaled tube (the sweep's Jacobian is σ²(1 − κσ c·n), whose
//! second term integrates to 0 over a centred circle), profile vertices that run on
//! helices under the Frenet frame and a fixed axis, and the refusals.

use super::tests::{circle, frustum, line, pipe_route, square, square_loop, triangle, volume};
use super::*;
use crate::ph_cubic::ph_spline_hermite;
use crate::spine::SpineMethod;
use std::f64::consts::{FRAC_1_SQRT_2, PI, TAU};

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// A helix about the z axis of radius `radius`, rising `pitch` per turn, `turns` turns from
/// (radius, 0, 0), as a PH spline through 96 samples per turn (within 1e-7 of the helix).
pub(crate) fn helix(radius: f64, pitch: f64, turns: f64) -> Edge {
    let n = (96.0 * turns).ceil() as usize;
    let h = pitch / TAU;
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=n)
        .map(|i| {
            let t = TAU * turns * i as f64 / n as f64;
            (
                DVec3::new(radius * t.cos(), radius * t.sin(), h * t),
                DVec3::new(-radius * t.sin(), radius * t.cos(), h),
            )
        })
        .unzip();
    Edge::Curve(ph_spline_hermite(&points, &tangents).unwrap().into_curve())
}

/// The length of the swept spine (lines, arcs, the PH splines of curves).
fn spine_length(shape: &Shape) -> f64 {
    shape.spine().iter().map(|c| c.arc_length()).sum()
}

/// π r² ∫σ² ds for σ linear from s0 to s1 over length L.
fn scaled_tube_volume(r: f64, length: f64, [s0, s1]: [f64; 2]) -> f64 {
    frustum(r, length, s0, s1)
}

#[test]
fn a_scale_law_along_a_line_is_an_exact_cone_frustum() {
    let options = WireSweep {
        scale: [1.0, 0.5],
        ..WireSweep::default()
    };
    let shape = sweep(
        &[line([0., 0., 0.], [0., 0., 3.])],
        &circle(1.0),
        &[],
        &options,
    )
    .unwrap();
    assert!(shape.is_solid());
    crate::testing::assert_closed_oriented(shape.brep());
    let (r0, r1, l) = (1.0, 0.5, 3.0);
    let exact = PI * l * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
    let v = volume(&shape);
    println!("frustum r 1 → 0.5, L 3: volume {v:.15} against {exact:.15}");
    assert!(relative(v, exact) < 1e-12, "{v} against {exact}");
    for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
        let s = face.surface.as_ref().unwrap();
        assert_eq!(s.patches()[0].degree_v(), 1, "ruled along the line");
        for i in 0..=8 {
            for j in 0..=8 {
                let p = s.eval(i as f64 / 8.0, j as f64 / 8.0);
                let radius = 1.0 - 0.5 * p.z / 3.0;
                assert!((p.truncate().length() - radius).abs() < 1e-14);
            }
        }
    }
    // The caps are the circles of radius 1 and 0.5.
    let caps: Vec<&Face> = shape
        .faces()
        .iter()
        .filter(|f| f.kind == FaceKind::Plane)
        .collect();
    for (cap, (radius, z)) in caps.iter().zip([(1.0, 0.0), (0.5, 3.0)]) {
        for k in 0..=16 {
            let p = cap.loops[0].eval(cap.loops[0].domain().1 * k as f64 / 16.0);
            assert!((p.truncate().length() - radius).abs() < 1e-14, "{p}");
            assert!((p.z - z).abs() < 1e-14, "{p}");
        }
    }
}

#[test]
fn a_scaled_tube_along_lines_arcs_and_curves_encloses_pi_r2_times_the_integral_of_sigma2() {
    for (name, edges, tolerance, exact) in [
        ("pipe route", pipe_route(), 1e-6, false),
        ("helix", vec![helix(3.0, 2.0, 1.5)], 1e-6, true),
    ] {
        for scale in [[1.0, 0.4], [0.5, 1.5]] {
            let options = WireSweep {
                scale,
                tolerance,
                ..WireSweep::default()
            };
            let shape = sweep(&edges, &circle(0.5), &[], &options).unwrap();
            crate::testing::assert_closed_oriented(shape.brep());
            let want = scaled_tube_volume(0.5, spine_length(&shape), scale);
            let v = volume(&shape);
            let error = relative(v, want);
            println!(
                "{name}, scale {scale:?}: volume {v:.12} against {want:.12}, relative {error:.1e}"
            );
            // Exact on lines and PH pieces; on arcs σ is within the tolerance of the law.
            let bound = if exact { 1e-11 } else { 4.0 * tolerance / 0.5 };
            assert!(error < bound, "{name} {scale:?}: {error:e}");
        }
    }
}

/// The largest distance of the profile's vertex tracks (the lateral faces' edges u = 0)
/// from the helix of axis z through their start with the given rise per radian.
pub(super) fn off_helix(shape: &Shape, rise: f64) -> f64 {
    let mut worst = 0.0f64;
    for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
        let s = face.surface.as_ref().unwrap();
        let (v0, v1) = s.domain_v();
        let start = s.eval(0.0, v0);
        let (r0, a0) = (start.truncate().length(), start.y.atan2(start.x));
        let mut last = a0;
        let mut turned = 0.0;
        for k in 0..=400 {
            let p = s.eval(0.0, v0 + (v1 - v0) * k as f64 / 400.0);
            let a = p.y.atan2(p.x);
            turned += (a - last + PI).rem_euclid(TAU) - PI;
            last = a;
            let on = DVec3::new(
                r0 * (a0 + turned).cos(),
                r0 * (a0 + turned).sin(),
                start.z + rise * turned,
            );
            worst = worst.max(p.distance(on));
        }
    }
    worst
}

#[test]
fn frenet_and_axis_frames_carry_the_profile_on_helices_and_the_rmf_does_not() {
    let (radius, pitch) = (3.0, 2.0);
    let rise = pitch / TAU;
    let edges = [helix(radius, pitch, 2.0)];
    let triangle = crate::primitives::polygon(&[
        DVec3::new(0.2, 0.0, 0.0),
        DVec3::new(0.6, -0.3, 0.0),
        DVec3::new(0.6, 0.3, 0.0),
    ])
    .unwrap();
    let sweep = |frame| {
        sweep(
            &edges,
            &triangle,
            &[],
            &WireSweep {
                frame,
                tolerance: 1e-6,
                ..WireSweep::default()
            },
        )
        .unwrap()
    };
    let frenet = sweep(SweepFrame::Frenet);
    let axis = sweep(SweepFrame::Fixed(DVec3::Z));
    let rmf = sweep(SweepFrame::Rmf);
    let (on_frenet, on_axis, on_rmf) = (
        off_helix(&frenet, rise),
        off_helix(&axis, rise),
        off_helix(&rmf, rise),
    );
    println!(
        "vertex tracks off their helices: Frenet {on_frenet:.1e}, fixed axis {on_axis:.1e}, RMF \
         {on_rmf:.1e}; frame errors {:.1e} / {:.1e}",
        frenet.report().frame_error,
        axis.report().frame_error
    );
    assert!(on_frenet < 1e-5, "{on_frenet}");
    assert!(on_axis < 1e-5, "{on_axis}");
    assert!(
        on_rmf > 1e-2,
        "the RMF turns against the screw motion: {on_rmf}"
    );
    assert!(frenet.report().frame_error < 1e-4);
    assert!(axis.report().frame_error < 1e-4);
    assert_eq!(rmf.report().frame_error, 0.0);
    // Frenet: f₂ along the principal normal at the start, towards the axis (−x).
    let p = frenet.faces()[0].surface.as_ref().unwrap().eval(0.0, 0.0);
    // (The given spline's normal is the helix's within its 1e-7.)
    assert!(p.distance(DVec3::new(radius - 0.2, 0.0, 0.0)) < 1e-6, "{p}");
    assert!(frenet.is_solid() && axis.is_solid());
    crate::testing::assert_closed_oriented(frenet.brep());
}

#[test]
fn a_fixed_normal_of_a_planar_wire_is_its_rmf() {
    let route = pipe_route();
    let rmf = sweep(&route, &square(0.5), &[], &WireSweep::default()).unwrap();
    let fixed = sweep(
        &route,
        &square(0.5),
        &[],
        &WireSweep {
            frame: SweepFrame::Fixed(DVec3::new(0.0, 0.0, 2.0)),
            ..WireSweep::default()
        },
    )
    .unwrap();
    assert_eq!(fixed.report().frame_error, 0.0);
    for (a, b) in rmf.faces().iter().zip(fixed.faces()) {
        if let (Some(a), Some(b)) = (&a.surface, &b.surface) {
            assert_eq!(a.patches()[0].degree_v(), b.patches()[0].degree_v());
            for i in 0..=4 {
                let (u, v) = (i as f64 / 4.0, 0.3);
                assert!(a.eval(u, v).distance(b.eval(u, v)) < 1e-12);
            }
        }
    }
}

#[test]
fn frames_and_scales_that_cannot_be_are_refused_naming_the_option() {
    let bar = [line([0., 0., 0.], [0., 0., 3.])];
    let refused = |edges: &[Edge], options: WireSweep| {
        sweep(edges, &circle(1.0), &[], &options)
            .unwrap_err()
            .message()
    };
    let with = |frame, scale| WireSweep {
        frame,
        scale,
        ..WireSweep::default()
    };
    for s in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let m = refused(&bar, with(SweepFrame::Rmf, [1.0, s]));
        assert!(m.starts_with("scale: the end scale"), "{m}");
        let m = refused(&bar, with(SweepFrame::Rmf, [s, 1.0]));
        assert!(m.starts_with("scale: the start scale"), "{m}");
    }
    let m = refused(&bar, with(SweepFrame::Fixed(DVec3::Z), [1.0, 1.0]));
    assert!(
        m.contains("frame: the fixed direction") && m.contains("tangent"),
        "{m}"
    );
    let m = refused(&bar, with(SweepFrame::Fixed(DVec3::ZERO), [1.0, 1.0]));
    assert!(m.starts_with("frame:"), "{m}");
    let m = refused(
        &bar,
        with(SweepFrame::Fixed(DVec3::new(f64::NAN, 0., 0.)), [1.0, 1.0]),
    );
    assert!(m.starts_with("frame:"), "{m}");
    let m = refused(
        &bar,
        WireSweep {
            initial_normal: Some(DVec3::X),
            ..with(SweepFrame::Frenet, [1.0, 1.0])
        },
    );
    assert!(m.contains("initial_normal"), "{m}");
    // A fixed direction the wire turns into: along the tangent of the second edge.
    let m = refused(
        &[
            line([0., 0., 0.], [5., 0., 0.]),
            line([5., 0., 0.], [5., 0., 5.]),
        ],
        with(SweepFrame::Fixed(DVec3::Z), [1.0, 1.0]),
    );
    assert!(m.contains("tangent of the round corner at the"), "{m}");
    let m = refused(
        &[
            line([0., 0., 0.], [5., 0., 0.]),
            line([5., 0., 0.], [5., 0., 5.]),
        ],
        WireSweep {
            corner: Corner::Miter,
            ..with(SweepFrame::Fixed(DVec3::Z), [1.0, 1.0])
        },
    );
    assert!(m.contains("tangent of edge 1"), "{m}");
    let square_loop = square_loop();
    let m = refused(&square_loop, with(SweepFrame::Rmf, [1.0, 2.0]));
    assert!(m.starts_with("scale: a closed wire"), "{m}");
    // A constant scale closes.
    let shape = sweep(
        &square_loop,
        &circle(1.0),
        &[],
        &with(SweepFrame::Rmf, [1.5, 1.5]),
    )
    .unwrap();
    assert!(shape.is_solid());
}

#[test]
fn a_fixed_direction_across_an_arc_is_followed_within_the_tolerance() {
    for d in [DVec3::new(1.0, 0.0, 1.0), DVec3::new(0.0, 1.0, 0.2)] {
        let shape = sweep(
            &pipe_route(),
            &square(0.5),
            &[],
            &WireSweep {
                frame: SweepFrame::Fixed(d),
                scale: [1.0, 0.5],
                ..WireSweep::default()
            },
        )
        .unwrap();
        crate::testing::assert_closed_oriented(shape.brep());
        let error = shape.report().frame_error;
        println!("fixed {d} along the pipe route: frame error {error:.3e} rad");
        // A quarter of the tolerance 1e-4 at the square's reach √2/2.
        assert!(error > 0.0 && error <= 0.25e-4 / FRAC_1_SQRT_2, "{error}");
    }
}

/// A curve whose torsion is not constant (the twisted cubic (t, t², t³)): the Frenet frame
/// is followed, not just turned linearly, within the tolerance at the profile's reach.
#[test]
fn the_frenet_frame_of_a_curve_of_varying_torsion_is_followed_within_the_tolerance() {
    let cubic = crate::bezier::RationalBezierCurve::polynomial(&[
        DVec3::ZERO,
        DVec3::new(1.0 / 3.0, 0.0, 0.0),
        DVec3::new(2.0 / 3.0, 1.0 / 3.0, 0.0),
        DVec3::new(1.0, 1.0, 1.0),
    ])
    .unwrap();
    let edge = Edge::Curve(PiecewiseCurve::with_unit_intervals(vec![cubic]).unwrap());
    for tolerance in [1e-4, 1e-6] {
        let shape = sweep(
            std::slice::from_ref(&edge),
            &square(0.05),
            &[],
            &WireSweep {
                frame: SweepFrame::Frenet,
                tolerance,
                ..WireSweep::default()
            },
        )
        .unwrap();
        crate::testing::assert_closed_oriented(shape.brep());
        let error = shape.report().frame_error;
        let reach = 0.05 * 2f64.sqrt();
        println!(
            "Frenet along the twisted cubic, tolerance {tolerance:e}: frame error {error:.2e}"
        );
        assert!(error <= 0.25 * tolerance / reach, "{error}");
        // The frame starts on the principal normal: (0, 1, 0) at t = 0.
        let start = shape.faces()[0].surface.as_ref().unwrap().eval(0.0, 0.0);
        assert!(
            start.distance(DVec3::new(0.0, 0.05, 0.05)) < 1e-12,
            "{start}"
        );
    }
}

/// Scale laws, the Frenet frame and a fixed direction give the same faces at 1e-200 and
/// 1e200 of the unit wire, moved by 300 times their size (the property test spreads this
/// over the whole range).
#[test]
fn frames_and_scale_laws_are_the_same_from_1e_200_to_1e200() {
    use super::robustness_tests::{check_similar, example_pipe};
    let frenet = WireSweep {
        frame: SweepFrame::Frenet,
        scale: [0.5, 1.0],
        ..WireSweep::default()
    };
    let fixed = WireSweep {
        corner: Corner::Round(Some(2.0)),
        frame: SweepFrame::Fixed(DVec3::new(1.0, 0.3, 1.0)),
        scale: [1.0, 0.5],
        ..WireSweep::default()
    };
    for s in [1e-200, 1e-100, 1.0, 1e100, 1e200] {
        let o = DVec3::new(3e2, -1e2, 2e2) * s;
        check_similar(&[helix(3.0, 2.0, 0.5)], &square(0.5), &frenet, s, o);
        check_similar(&example_pipe(), &circle(1.0), &fixed, s, o);
    }
}

/// A circle of radius r about the spine point in the plane through f₂ tilted by `tilt`
/// from the normal plane towards the tangent (profile coordinates: x along f₂, y along f₃,
/// z along t).
fn tilted_circle(r: f64, tilt: f64) -> PiecewiseCurve {
    crate::primitives::circle(
        DVec3::ZERO,
        DVec3::X,
        DVec3::new(0.0, tilt.cos(), tilt.sin()),
        r,
    )
    .unwrap()
}

/// A profile drawn out of the normal plane is carried rigidly: a centred region of area A
/// in a plane whose normal makes the angle α with the tangent sweeps m_z A L = A L cos α
/// (the flux of the moving plane; module `oblique`), along lines, arcs and PH pieces alike.
#[test]
fn a_profile_out_of_the_normal_plane_sweeps_cos_alpha_times_the_volume() {
    for (name, edges) in [
        ("line", vec![line([0., 0., 0.], [0., 0., 4.])]),
        ("pipe route", pipe_route()),
        ("helix", vec![helix(3.0, 2.0, 1.0)]),
    ] {
        for tilt in [0.3, -0.9] {
            let shape = sweep(
                &edges,
                &tilted_circle(0.5, tilt),
                &[],
                &WireSweep::default(),
            )
            .unwrap_or_else(|e| panic!("{name}, tilt {tilt}: {e}"));
            assert!(shape.is_solid());
            crate::testing::assert_closed_oriented(shape.brep());
            let want = tilt.cos() * PI * 0.25 * spine_length(&shape);
            let v = volume(&shape);
            println!("{name}, tilt {tilt}: volume {v:.12} against cos α π r² L {want:.12}");
            assert!(
                relative(v, want) < 1e-11,
                "{name} {tilt}: {v} against {want}"
            );
            // The start cap is the tilted disc itself: its plane's normal is ∓m.
            let cap = shape
                .faces()
                .iter()
                .find(|f| f.kind == FaceKind::Plane)
                .unwrap();
            let (_, n) = cap.plane.unwrap();
            let t0 = match &edges[0] {
                Edge::Line { from, to } => (*to - *from).normalize(),
                _ => shape.spine()[0]
                    .eval_jet(shape.spine()[0].domain().0)
                    .d1
                    .normalize(),
            };
            assert!((n.dot(t0) + tilt.cos()).abs() < 1e-12, "{n}");
        }
    }
}

/// A thread as users draw it: the triangle in the axial plane through the helix's start
/// (which holds the axis and the radial direction: tilted from the normal plane by the
/// helix's lead angle), carried by the Frenet frame: every vertex runs on a helix.
#[test]
fn an_axial_thread_profile_runs_on_helices_under_the_frenet_frame() {
    let (radius, pitch) = (3.0, 1.0);
    let edges = [helix(radius, pitch, 2.0)];
    // At the start f₂ = −x (towards the axis), the tangent t ∝ (0, R, h), f₃ = t × f₂.
    let h = pitch / TAU;
    let t = DVec3::new(0.0, radius, h).normalize();
    let f2 = -DVec3::X;
    let f3 = t.cross(f2);
    // Profile coordinates of a world offset d from the start point: (d·f₂, d·f₃, d·t).
    let local = |d: DVec3| DVec3::new(d.dot(f2), d.dot(f3), d.dot(t));
    let triangle = crate::primitives::polygon(&[
        local(DVec3::new(0.0, 0.0, -0.3)),
        local(DVec3::new(0.0, 0.0, 0.3)),
        local(DVec3::new(0.4, 0.0, 0.0)),
    ])
    .unwrap();
    let shape = sweep(
        &edges,
        &triangle,
        &[],
        &WireSweep {
            frame: SweepFrame::Frenet,
            tolerance: 1e-6,
            ..WireSweep::default()
        },
    )
    .unwrap();
    crate::testing::assert_closed_oriented(shape.brep());
    let off = off_helix(&shape, h);
    println!("axial thread profile: vertex tracks off their helices {off:.1e}");
    assert!(off < 1e-5, "{off}");
    // The start cap is the axial plane y = 0.
    let cap = shape
        .faces()
        .iter()
        .find(|f| f.kind == FaceKind::Plane)
        .unwrap();
    let (o, n) = cap.plane.unwrap();
    assert!(
        o.y.abs() < 1e-12 && (n.y.abs() - 1.0).abs() < 1e-12,
        "{o} {n}"
    );
}

#[test]
fn profiles_out_of_the_normal_plane_that_cannot_be_swept_are_refused() {
    let refused = |edges: &[Edge], profile: &PiecewiseCurve, options: WireSweep| {
        sweep(edges, profile, &[], &options).unwrap_err().message()
    };
    let square_loop = square_loop();
    let m = refused(&square_loop, &tilted_circle(1.0, 0.3), WireSweep::default());
    assert!(
        m.contains("a closed wire takes a profile in its normal plane"),
        "{m}"
    );
    let elbow = [
        line([0., 0., 0.], [10., 0., 0.]),
        line([10., 0., 0.], [10., 10., 0.]),
    ];
    let miter = WireSweep {
        corner: Corner::Miter,
        ..WireSweep::default()
    };
    let m = refused(&elbow, &tilted_circle(1.0, 0.3), miter);
    assert!(
        m.contains("miter cuts take a profile in the wire's normal plane"),
        "{m}"
    );
    let m = refused(&elbow, &tilted_circle(1.0, 1.5705), WireSweep::default());
    assert!(m.contains("contains the wire's start tangent"), "{m}");
    // Steeply tilted along a tight arc: the plane's motion folds the sweep.
    let arc = [Edge::Arc {
        start: DVec3::new(2.0, 0.0, 0.0),
        through: DVec3::new(2f64.sqrt(), 2f64.sqrt(), 0.0),
        end: DVec3::new(0.0, 2.0, 0.0),
    }];
    let m = refused(&arc, &tilted_circle(1.5, 1.2), WireSweep::default());
    assert!(m.contains("may fold the sweep"), "{m}");
    assert!(sweep(&arc, &tilted_circle(0.5, 0.3), &[], &WireSweep::default()).is_ok());
}

/// Profiles out of the normal plane give the same faces at every scale and position.
#[test]
fn profiles_out_of_the_normal_plane_are_the_same_from_1e_200_to_1e200() {
    use super::robustness_tests::check_similar;
    let frenet = WireSweep {
        frame: SweepFrame::Frenet,
        scale: [1.0, 0.7],
        ..WireSweep::default()
    };
    for s in [1e-200, 1e-100, 1.0, 1e100, 1e200] {
        let o = DVec3::new(3e2, -1e2, 2e2) * s;
        check_similar(
            &pipe_route(),
            &tilted_circle(0.5, 0.4),
            &WireSweep::default(),
            s,
            o,
        );
        check_similar(
            &[helix(3.0, 2.0, 0.5)],
            &tilted_circle(0.3, -0.2),
            &frenet,
            s,
            o,
        );
    }
}

/// Between two concentric circles the blend is the scale law: a frustum along a line,
/// π r² ∫σ² ds along lines, arcs and helices.
#[test]
fn a_sweep_between_two_circles_is_the_scaled_tube() {
    for (name, edges, bound) in [
        ("line", vec![line([0., 0., 0.], [0., 0., 3.])], 1e-12),
        ("pipe route", pipe_route(), 4e-6),
        ("helix", vec![helix(3.0, 2.0, 1.0)], 1e-12),
    ] {
        let shape = sweep_between(
            &edges,
            &circle(0.5),
            &[],
            &circle(0.2),
            &[],
            &WireSweep {
                tolerance: 1e-6,
                ..WireSweep::default()
            },
        )
        .unwrap_or_else(|e| panic!("{name}: {e}"));
        crate::testing::assert_closed_oriented(shape.brep());
        let want = scaled_tube_volume(0.5, spine_length(&shape), [1.0, 0.4]);
        let v = volume(&shape);
        println!("circle 0.5 to 0.2 along the {name}: volume {v:.12} against {want:.12}");
        assert!(relative(v, want) < bound, "{name}: {v} against {want}");
    }
}

/// A square into a circle along a line: its sections are quadratic in λ, so the volume is
/// Simpson's L (A₀ + 4A½ + A₁)/6 exactly — A½ measured on the faces at mid-length; the
/// caps are the square and the circle, the circle cut where the square's corners point.
#[test]
fn a_square_blends_into_a_circle_corner_to_corner() {
    let edges = [line([0., 0., 0.], [0., 0., 4.])];
    for (start, end) in [(square(0.5), circle(0.6)), (triangle(0.6), square(0.4))] {
        let shape = sweep_between(&edges, &start, &[], &end, &[], &WireSweep::default()).unwrap();
        crate::testing::assert_closed_oriented(shape.brep());
        let area = |z: f64| {
            let mut points = Vec::new();
            for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
                let s = face.surface.as_ref().unwrap();
                let ((u0, u1), (v0, v1)) = (s.domain_u(), s.domain_v());
                for k in 0..400 {
                    let p = s.eval(u0 + (u1 - u0) * k as f64 / 400.0, v0 + (v1 - v0) * z / 4.0);
                    assert!((p.z - z).abs() < 1e-12);
                    points.push(p.truncate());
                }
            }
            // The faces in order around the loop: the polygon's shoelace area.
            let n = points.len();
            0.5 * (0..n)
                .map(|i| points[i].perp_dot(points[(i + 1) % n]))
                .sum::<f64>()
                .abs()
        };
        let (a0, a_mid, a1) = (area(0.0), area(2.0), area(4.0));
        let simpson = 4.0 * (a0 + 4.0 * a_mid + a1) / 6.0;
        let v = volume(&shape);
        println!(
            "blend: areas {a0:.6}, {a_mid:.6}, {a1:.6}; volume {v:.9} against Simpson {simpson:.9}"
        );
        // (The sampled areas are 400-gons: 1e-4 of the circle's.)
        assert!(relative(v, simpson) < 2e-4, "{v} against {simpson}");
        // Corners meet the circle where they point (it is cut there): the sections widen
        // monotonically, none narrows below both ends (a 45° turn gave 0.913 < 1).
        assert!(
            a0.min(a1) <= a_mid && a_mid <= a0.max(a1),
            "{a0} {a_mid} {a1}"
        );
        let caps: Vec<&Face> = shape
            .faces()
            .iter()
            .filter(|f| f.kind == FaceKind::Plane)
            .collect();
        assert_eq!(caps.len(), 2);
    }
}

#[test]
fn sweeps_between_profiles_that_cannot_be_matched_are_refused() {
    let bar = [line([0., 0., 0.], [0., 0., 3.])];
    let refused = |edges: &[Edge], end_holes: &[PiecewiseCurve], options: WireSweep| {
        sweep_between(
            edges,
            &circle(1.0),
            &[circle(0.5)],
            &square(0.8),
            end_holes,
            &options,
        )
        .unwrap_err()
        .message()
    };
    let m = refused(&bar, &[], WireSweep::default());
    assert!(
        m.starts_with("end_profile: it has 0 holes, the profile 1"),
        "{m}"
    );
    let m = refused(
        &bar,
        &[circle(0.2)],
        WireSweep {
            scale: [1.0, 2.0],
            ..WireSweep::default()
        },
    );
    assert!(m.starts_with("scale:"), "{m}");
    let square_loop = square_loop();
    let m = refused(&square_loop, &[circle(0.2)], WireSweep::default());
    assert!(m.starts_with("end_profile: a closed wire"), "{m}");
    // Matched hole to hole: a ring into a square frame.
    let ok = sweep_between(
        &bar,
        &circle(1.0),
        &[circle(0.5)],
        &square(0.8),
        &[square(0.3)],
        &WireSweep::default(),
    )
    .unwrap();
    crate::testing::assert_closed_oriented(ok.brep());
}

/// A blend gives the same faces at every scale and position.
#[test]
fn sweeps_between_profiles_are_the_same_from_1e_200_to_1e200() {
    let edges = pipe_route();
    let unit = sweep_between(
        &edges,
        &square(0.5),
        &[],
        &circle(0.3),
        &[],
        &WireSweep::default(),
    )
    .unwrap();
    for s in [1e-200, 1e-100, 1e100, 1e200] {
        let o = DVec3::new(3e2, -1e2, 2e2) * s;
        let moved = super::robustness_tests::moved(&edges, s, o);
        let options = WireSweep {
            tolerance: 1e-4 * s,
            ..WireSweep::default()
        };
        let shape = sweep_between(
            &moved,
            &square(0.5).similar(s, DVec3::ZERO),
            &[],
            &circle(0.3).similar(s, DVec3::ZERO),
            &[],
            &options,
        )
        .unwrap();
        assert_eq!(shape.faces().len(), unit.faces().len());
        let rounding = 1.0 + crate::math::robust_length(o) / s;
        for (a, b) in unit.faces().iter().zip(shape.faces()) {
            if let (Some(a), Some(b)) = (&a.surface, &b.surface) {
                for i in 0..=4 {
                    for j in 0..=4 {
                        let (u, v) = (i as f64 / 4.0, j as f64 / 4.0);
                        let (u, v) = (
                            a.domain_u().0 + (a.domain_u().1 - a.domain_u().0) * u,
                            a.domain_v().0 + (a.domain_v().1 - a.domain_v().0) * v,
                        );
                        let (pa, pb) = (a.eval(u, v), (b.eval(u, v) - o) / s);
                        assert!(
                            pa.distance(pb) < 1e-8 * rounding,
                            "{s:e}: {pa} against {pb}"
                        );
                    }
                }
            }
        }
        // (A volume at 1e±100 and beyond is outside f64's range.)
        if let Ok(v) = shape.volume() {
            assert!(relative(v / s / s / s, unit.volume().unwrap()) < 1e-9);
        }
    }
}

/// A profile out of the normal plane adds the tangent to the faces; along a PH spline
/// (whose frames hold its speed in their denominator) it goes over the frames' own
/// denominator, so the faces are no heavier than the normal profile's.
#[test]
fn a_tilted_profile_along_a_ph_spline_keeps_the_faces_degree() {
    let edges = [helix(3.0, 1.0, 1.0)];
    for frame in [SweepFrame::Rmf, SweepFrame::Frenet] {
        let degree = |profile: &PiecewiseCurve| {
            let options = WireSweep {
                frame: frame.clone(),
                tolerance: 1e-5,
                ..WireSweep::default()
            };
            let shape = sweep(&edges, profile, &[], &options).unwrap();
            let surface = shape.faces()[0].surface.as_ref().unwrap();
            surface
                .patches()
                .iter()
                .map(|p| p.degree_v())
                .max()
                .unwrap()
        };
        let (normal, tilted) = (degree(&circle(0.3)), degree(&tilted_circle(0.3, 0.2)));
        println!("{frame:?}: degree along the spine {normal} (normal plane), {tilted} (tilted)");
        assert_eq!(normal, tilted, "{frame:?}");
    }
}

/// The twisted cubic (t, t², t³) on [0, 1] as one cubic Bézier edge.
fn twisted_cubic() -> Edge {
    let cubic = crate::bezier::RationalBezierCurve::polynomial(&[
        DVec3::ZERO,
        DVec3::new(1.0 / 3.0, 0.0, 0.0),
        DVec3::new(2.0 / 3.0, 1.0 / 3.0, 0.0),
        DVec3::new(1.0, 1.0, 1.0),
    ])
    .unwrap();
    Edge::Curve(PiecewiseCurve::with_unit_intervals(vec![cubic]).unwrap())
}

/// The methods of Bartoň–Jüttler–Wang and Farouki–Giannelli–Sestini on wire sweeps: their
/// spines carry exact rational RMFs, so the parameter lines of every face are orthogonal
/// to rounding (Mäurer & Jüttler (43)), where the PH cubic's rational RMF leaves ~1e-8.
#[test]
fn mobius_and_rrmf_wire_sweeps_have_parameter_lines_orthogonal_to_rounding() {
    // A line into the cubic, tangent to it.
    let edges = [line([-1., 0., 0.], [0., 0., 0.]), twisted_cubic()];
    // (RRMF quintic spines through finer samples of this cubic carry curvature spikes of
    // 1e5 at their last segments, which the fold check refuses: 1e-4 for them.)
    let mut cosines = Vec::new();
    for (method, tolerance) in [
        (SpineMethod::PhRmf, 1e-5),
        (SpineMethod::Mobius, 1e-5),
        (SpineMethod::Rrmf, 1e-4),
    ] {
        let options = WireSweep {
            method,
            tolerance,
            ..WireSweep::default()
        };
        let shape = sweep(&edges, &circle(0.05), &[], &options)
            .unwrap_or_else(|e| panic!("{}: {e}", method.name()));
        crate::testing::assert_closed_oriented(shape.brep());
        let report = shape.report();
        let want = PI * 0.05 * 0.05 * spine_length(&shape);
        let v = volume(&shape);
        println!(
            "{}: max |cos| {:.1e}, spine within {:.1e}, volume against π r² L {:.1e}",
            method.name(),
            report.max_parameter_cosine,
            report.spine_distance,
            relative(v, want)
        );
        assert!(report.spine_distance <= tolerance);
        assert!(
            relative(v, want) < 1e-9,
            "{}: {v} against {want}",
            method.name()
        );
        cosines.push(report.max_parameter_cosine);
    }
    assert!(
        cosines[0] > 1e-10,
        "the PH cubic's rational RMF: {}",
        cosines[0]
    );
    assert!(cosines[1] < 1e-12 && cosines[2] < 1e-12, "{cosines:?}");
}

#[test]
fn exact_rmf_methods_take_twists_frames_and_refuse_what_they_cannot() {
    let edges = [twisted_cubic()];
    for method in [SpineMethod::Mobius, SpineMethod::Rrmf] {
        // A twist is followed on the exact RMF; so is the Frenet frame.
        for (frame, twist) in [(SweepFrame::Rmf, 1.0), (SweepFrame::Frenet, 0.0)] {
            let tolerance = 1e-4;
            let options = WireSweep {
                method,
                frame: frame.clone(),
                twist,
                tolerance,
                ..WireSweep::default()
            };
            let shape = sweep(&edges, &square(0.05), &[], &options)
                .unwrap_or_else(|e| panic!("{} {frame:?}: {e}", method.name()));
            crate::testing::assert_closed_oriented(shape.brep());
            let report = shape.report();
            assert!(report.frame_error <= 0.25 * tolerance / (0.05 * 2f64.sqrt()));
            if twist != 0.0 {
                // The end section is the untwisted one turned by the twist about the tangent.
                let plain = sweep(
                    &edges,
                    &square(0.05),
                    &[],
                    &WireSweep {
                        twist: 0.0,
                        ..options
                    },
                )
                .unwrap();
                let corner = |s: &Shape| {
                    let face = s.faces()[0].surface.as_ref().unwrap();
                    face.eval(0.0, face.domain_v().1) - DVec3::ONE
                };
                let (a, b) = (corner(&plain), corner(&shape));
                let angle = a.angle_between(b);
                println!(
                    "{}: the end section turned by {angle:.9} (twist {twist})",
                    method.name()
                );
                assert!((angle - twist).abs() < 1e-9, "{angle}");
            }
        }
        let m = sweep(
            &edges,
            &circle(0.05),
            &[],
            &WireSweep {
                method,
                scale: [1.0, 0.5],
                ..WireSweep::default()
            },
        )
        .unwrap_err()
        .message();
        assert!(
            m.starts_with("scale: a scale law is exact along PH splines"),
            "{m}"
        );
    }
    let m = sweep(
        &edges,
        &circle(0.05),
        &[],
        &WireSweep {
            method: SpineMethod::Frenet,
            ..WireSweep::default()
        },
    )
    .unwrap_err()
    .message();
    assert!(m.starts_with("method: frenet"), "{m}");
}

/// Möbius and RRMF wire sweeps give the same faces at every scale and position.
#[test]
fn exact_rmf_wire_sweeps_are_the_same_from_1e_200_to_1e200() {
    use super::robustness_tests::check_similar;
    for method in [SpineMethod::Mobius, SpineMethod::Rrmf] {
        let options = WireSweep {
            method,
            ..WireSweep::default()
        };
        for s in [1e-200, 1.0, 1e200] {
            let o = DVec3::new(3e2, -1e2, 2e2) * s;
            check_similar(&[twisted_cubic()], &circle(0.05), &options, s, o);
        }
    }
}

/// A closed wire's holonomy is measured by carrying the exact RMF of a Möbius spine round
/// it: the closing turn spread over the wire closes it without a seam.
#[test]
fn a_closed_mobius_wire_closes_without_a_seam() {
    let options = WireSweep {
        method: SpineMethod::Mobius,
        tolerance: 1e-4,
        closure_symmetry: 4,
        ..WireSweep::default()
    };
    let edge = Edge::Curve(super::tests::closed_nurbs());
    let shape = sweep(&[edge], &square(0.3), &[], &options).unwrap();
    crate::testing::assert_closed_oriented(shape.brep());
    let report = shape.report();
    println!("closed Möbius wire: seam gap {:.1e}", report.seam_gap);
    assert!(report.seam_gap <= 1e-12, "{}", report.seam_gap);
}
