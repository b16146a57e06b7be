//! Round profiles swept on the lightest frame ([`PipeFrame::Lightest`]): the same pipe in
//! lighter faces, and the RMF wherever the frame matters or the wire closes.

use super::tests::{circle, closed_nurbs, square, volume};
use super::*;
use crate::math::robust_length;
use crate::testing::assert_closed_oriented;

/// A line into a PH cubic spline on a helix (radius 3, rise 1 per radian), tangent to it:
/// the spline is swept along as it is (distance 0), so its pipe is exactly the circles of
/// radius r about it in its normal planes. Points scaled by `s` and moved by `shift`.
fn line_and_helix(s: f64, shift: DVec3) -> Vec<Edge> {
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=6)
        .map(|i| {
            let t = 0.5 * i as f64;
            (
                DVec3::new(3.0 * t.cos(), 3.0 * t.sin(), t) * s + shift,
                DVec3::new(-3.0 * t.sin(), 3.0 * t.cos(), 1.0),
            )
        })
        .unzip();
    let spline = crate::ph_cubic::ph_spline_hermite(&points, &tangents)
        .unwrap()
        .into_curve();
    let start = DVec3::new(3.0, -3.0, -1.0) * s + shift;
    vec![
        Edge::Line {
            from: start,
            to: points[0],
        },
        Edge::Curve(spline),
    ]
}

fn lightest() -> WireSweep {
    WireSweep {
        pipe_frame: PipeFrame::Lightest,
        ..WireSweep::default()
    }
}

/// The degrees along the spine of the lateral faces along wire edge `edge`.
fn spine_degrees(shape: &Shape, edge: usize) -> Vec<usize> {
    let mut degrees: Vec<usize> = shape
        .faces()
        .iter()
        .filter(|f| f.kind == FaceKind::Swept && f.spine_edge == edge)
        .flat_map(|f| {
            f.surface
                .as_ref()
                .unwrap()
                .patches()
                .iter()
                .map(|p| p.degree_v())
        })
        .collect();
    degrees.dedup();
    degrees
}

/// The largest distance, relative to `r`, of the lateral faces along `edge` (9 × 9 points
/// per patch) from the circle of radius r about the spine in its normal plane at the same
/// parameter: |p − x(v)| − r, and (p − x(v))·t(v).
fn off_the_pipe(shape: &Shape, edge: usize, r: f64) -> f64 {
    let spine = &shape.spine()[edge];
    let mut worst = 0.0f64;
    for face in shape
        .faces()
        .iter()
        .filter(|f| f.kind == FaceKind::Swept && f.spine_edge == edge)
    {
        let s = face.surface.as_ref().unwrap();
        let ((u0, u1), (v0, v1)) = (s.domain_u(), s.domain_v());
        for i in 0..=8 {
            for j in 0..=8 {
                let v = v0 + (v1 - v0) * j as f64 / 8.0;
                let p = s.eval(u0 + (u1 - u0) * i as f64 / 8.0, v);
                let jet = spine.eval_jet(v);
                // In units of r: no square under- or overflows at any scale.
                let d = (p - jet.point) / r;
                let tangent = jet.d1 / robust_length(jet.d1);
                worst = worst
                    .max((d.length() - 1.0).abs())
                    .max(d.dot(tangent).abs());
            }
        }
    }
    worst
}

/// Along the helix a circle is swept on the Euler–Rodrigues frame: faces of degree 5 along
/// the spine (the RMF's are 9), on the same pipe to rounding, the same volume, a closed
/// oriented B-rep; the line keeps its degree-1 faces. The parameter lines are no longer
/// orthogonal, and the report says so.
#[test]
fn a_pipe_along_a_curve_takes_the_euler_rodrigues_frame_and_is_the_same_pipe() {
    let edges = line_and_helix(1.0, DVec3::ZERO);
    let r = 0.4;
    let rmf = sweep(&edges, &circle(r), &[], &WireSweep::default()).unwrap();
    let light = sweep(&edges, &circle(r), &[], &lightest()).unwrap();
    assert_eq!(spine_degrees(&rmf, 1), [9]);
    assert_eq!(spine_degrees(&light, 1), [5]);
    assert_eq!(spine_degrees(&light, 0), spine_degrees(&rmf, 0));
    let off = off_the_pipe(&light, 1, r);
    assert!(off < 1e-12, "off the pipe by {off:e} of r");
    assert!(off_the_pipe(&rmf, 1, r) < 1e-12);
    let (a, b) = (volume(&light), volume(&rmf));
    assert!((a - b).abs() <= 1e-12 * b, "volumes {a} and {b}");
    assert_closed_oriented(light.brep());
    let poles = |shape: &Shape| -> usize {
        shape
            .brep()
            .faces
            .iter()
            .map(|f| match &f.surface {
                crate::model::BrepSurface::Nurbs(s) => s.poles().len(),
                _ => 0,
            })
            .sum()
    };
    let (cos_light, cos_rmf) = (
        light.report().max_parameter_cosine,
        rmf.report().max_parameter_cosine,
    );
    println!(
        "circle r = {r} along a line and a helical PH spline: poles {} (RMF {}), max |cos| \
         {cos_light:.1e} (RMF {cos_rmf:.1e}), volume {a:.15} (RMF {b:.15})",
        poles(&light),
        poles(&rmf)
    );
    assert!(poles(&light) * 10 < poles(&rmf) * 6);
    assert!(cos_rmf < 1e-5 && cos_light > 1e-3);
    assert_eq!(light.report().rmf_angle_error, 0.0);
}

/// The RMF wherever the frame changes the sweep or the wire must close: a square, a circle
/// off the spine, a twist, a closed wire, the Möbius method — and the RMF pipe frame itself.
#[test]
fn where_the_frame_matters_or_the_wire_closes_the_rmf_stays() {
    let edges = line_and_helix(1.0, DVec3::ZERO);
    let off_centre = circle(0.4).similar(1.0, DVec3::new(0.05, 0.0, 0.0));
    for (name, profile, options) in [
        ("square", square(0.5), lightest()),
        ("circle off the spine", off_centre, lightest()),
        (
            "twisted",
            circle(0.4),
            WireSweep {
                twist: 0.3,
                ..lightest()
            },
        ),
        ("the RMF", circle(0.4), WireSweep::default()),
    ] {
        let shape = sweep(&edges, &profile, &[], &options).unwrap();
        assert_eq!(spine_degrees(&shape, 1), [9], "{name}");
    }
    let closed = sweep(
        &[Edge::Curve(closed_nurbs())],
        &circle(0.1),
        &[],
        &lightest(),
    )
    .unwrap();
    assert!(spine_degrees(&closed, 0).iter().all(|&d| d == 9));
    let mobius = WireSweep {
        method: SpineMethod::Mobius,
        ..lightest()
    };
    let exact = sweep(&edges, &circle(0.4), &[], &mobius).unwrap();
    assert!(exact.report().max_parameter_cosine < 1e-12);
}

/// The same degrees and the same pipe, relative to its size, from 1e-200 to 1e200 and
/// moved by 3e6.
#[test]
fn the_lightest_pipe_is_invariant_under_scaling_and_translation() {
    for (s, shift) in [
        (1e-200, DVec3::ZERO),
        (1e200, DVec3::ZERO),
        (1.0, DVec3::new(3e6, -2e6, 1e6)),
        (2f64.powi(300), DVec3::ZERO),
    ] {
        let r = 0.4 * s;
        let shape = sweep(&line_and_helix(s, shift), &circle(r), &[], &lightest()).unwrap();
        assert_eq!(spine_degrees(&shape, 1), [5], "scale {s:e}");
        let bound = if shift == DVec3::ZERO { 1e-12 } else { 1e-8 };
        let off = off_the_pipe(&shape, 1, r);
        assert!(
            off < bound,
            "scale {s:e}, shift {shift}: off the pipe by {off:e} of r"
        );
    }
}
