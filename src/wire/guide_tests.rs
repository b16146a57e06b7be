//! The guide-curve frame against what it must be: a helical guide about a straight wire
//! turns the profile by the helix's screw motion (its vertices on helices); a coaxial
//! helix beside a helix is the Frenet frame turned by π; a guide winding unevenly is
//! followed within the tolerance, measured against the guide's own crossings of each
//! normal plane (found here by bisection, not by the library); the refusals; invariance.

use super::options_tests::{helix, off_helix};
use super::robustness_tests::check_similar;
use super::tests::{circle, line, square};
use super::*;
use crate::bezier::RationalBezierCurve;
use std::f64::consts::TAU;

fn guided(guide: Vec<Edge>, tolerance: f64) -> WireSweep {
    WireSweep {
        frame: SweepFrame::Guide(guide),
        tolerance,
        ..WireSweep::default()
    }
}

/// A triangle with a vertex on f₂ (towards the guide) at 0.5.
fn pointer() -> PiecewiseCurve {
    crate::primitives::polygon(&[
        DVec3::new(0.5, 0.0, 0.0),
        DVec3::new(-0.2, 0.3, 0.0),
        DVec3::new(-0.2, -0.3, 0.0),
    ])
    .unwrap()
}

#[test]
fn a_helical_guide_about_a_straight_wire_turns_the_profile_on_helices() {
    let pitch = 2.0;
    let bar = [line([0., 0., 0.], [0., 0., 4.])];
    let shape = sweep(
        &bar,
        &pointer(),
        &[],
        &guided(vec![helix(2.0, pitch, 2.0)], 1e-6),
    )
    .unwrap();
    let off = off_helix(&shape, pitch / TAU);
    println!(
        "helical guide about a line: vertex tracks off their helices {off:.1e}, frame error \
         {:.1e}",
        shape.report().frame_error
    );
    assert!(off < 1e-6, "{off}");
    // f₂ points at the guide: the vertex (0.5, 0) starts towards (2, 0, 0).
    let start = shape.faces()[0].surface.as_ref().unwrap().eval(0.0, 0.0);
    assert!(start.distance(DVec3::new(0.5, 0.0, 0.0)) < 1e-9, "{start}");
    assert!(shape.is_solid());
    crate::testing::assert_closed_oriented(shape.brep());
    // The RMF of a line does not turn: the check can fail.
    let rmf = sweep(&bar, &pointer(), &[], &WireSweep::default()).unwrap();
    assert!(off_helix(&rmf, pitch / TAU) > 0.1);
}

#[test]
fn a_coaxial_helix_beside_a_helix_is_its_frenet_frame_turned_by_pi() {
    let (radius, pitch) = (3.0, 2.0);
    let edges = [helix(radius, pitch, 1.5)];
    let guide = vec![helix(radius + 1.0, pitch, 1.5)];
    let shape = sweep(&edges, &pointer(), &[], &guided(guide, 1e-6)).unwrap();
    let off = off_helix(&shape, pitch / TAU);
    let error = shape.report().frame_error;
    println!(
        "coaxial helical guide: vertex tracks off their helices {off:.1e}, frame error {error:.1e}"
    );
    assert!(off < 1e-5, "{off}");
    assert!(error < 0.25e-6 / 0.5, "{error}");
    // Outwards, away from the axis (the Frenet normal points in).
    let start = shape.faces()[0].surface.as_ref().unwrap().eval(0.0, 0.0);
    assert!(
        start.distance(DVec3::new(radius + 0.5, 0.0, 0.0)) < 1e-6,
        "{start}"
    );
    crate::testing::assert_closed_oriented(shape.brep());
}

/// The guide (a cubic winding a third of a turn, unevenly) where it crosses the plane
/// z = h: its z rises monotonically, so bisection finds it.
fn crossing(guide: &RationalBezierCurve, h: f64) -> DVec3 {
    let (mut a, mut b) = (0.0, 1.0);
    for _ in 0..80 {
        let m = 0.5 * (a + b);
        if guide.eval(m).z < h {
            a = m;
        } else {
            b = m;
        }
    }
    guide.eval(0.5 * (a + b))
}

#[test]
fn a_guide_winding_unevenly_beside_a_line_is_followed_within_the_tolerance() {
    let cubic = RationalBezierCurve::polynomial(&[
        DVec3::new(1.5, 0.0, 0.0),
        DVec3::new(1.5, 0.3, 2.0),
        DVec3::new(0.2, 1.6, 2.4),
        DVec3::new(-1.0, 1.0, 3.0),
    ])
    .unwrap();
    let guide = vec![Edge::Curve(
        PiecewiseCurve::with_unit_intervals(vec![cubic.clone()]).unwrap(),
    )];
    let bar = [line([0., 0., 0.], [0., 0., 3.])];
    for tolerance in [1e-4, 1e-6] {
        let shape = sweep(&bar, &pointer(), &[], &guided(guide.clone(), tolerance)).unwrap();
        crate::testing::assert_closed_oriented(shape.brep());
        // The face swept by the vertex on f₂: its points against the guide's direction.
        let mut worst = 0.0f64;
        for face in shape.faces().iter().filter(|f| f.kind == FaceKind::Swept) {
            let s = face.surface.as_ref().unwrap();
            let (v0, v1) = s.domain_v();
            let p0 = s.eval(0.0, v0);
            if (p0.truncate().length() - 0.5).abs() > 1e-9 {
                continue;
            }
            for k in 0..=300 {
                let p = s.eval(0.0, v0 + (v1 - v0) * k as f64 / 300.0);
                let g = crossing(&cubic, p.z);
                let expected = g.truncate().normalize() * 0.5;
                worst = worst.max(p.truncate().distance(expected));
            }
        }
        let reported = shape.report().frame_error;
        println!(
            "uneven guide, tolerance {tolerance:e}: vertex off the guide's direction {worst:.2e} \
             (bound {tolerance:e}), frame error {reported:.2e} rad"
        );
        assert!(worst > 0.0 && worst <= tolerance, "{worst}");
        assert!(reported <= 0.25 * tolerance / 0.5, "{reported}");
    }
}

#[test]
fn guides_that_do_not_run_beside_the_wire_are_refused_naming_the_option() {
    let bar = [line([0., 0., 0.], [0., 0., 3.])];
    let refused = |options: WireSweep| {
        sweep(&bar, &circle(0.2), &[], &options)
            .unwrap_err()
            .message()
    };
    // Along only the first third of the wire.
    let m = refused(guided(vec![line([1., 0., 0.], [1., 0., 1.])], 1e-4));
    assert!(
        m.contains("frame: the guide does not run beside the wire"),
        "{m}"
    );
    // The wire itself.
    let m = refused(guided(bar.to_vec(), 1e-4));
    assert!(
        m.contains("frame: the guide does not run beside the wire"),
        "{m}"
    );
    // A guide whose nearest crossing jumps to the other side halfway up.
    let m = refused(guided(
        vec![
            line([1., 0., 0.], [1., 0., 1.5]),
            line([-0.5, 0., 1.5], [-0.5, 0., 3.]),
        ],
        1e-4,
    ));
    assert!(
        m.contains("frame: the guide frame cannot be followed along edge 0"),
        "{m}"
    );
    let m = refused(guided(vec![], 1e-4));
    assert!(
        m.starts_with("frame: the guide needs at least one edge"),
        "{m}"
    );
    let m = refused(guided(vec![line([1., 0., f64::NAN], [1., 0., 3.])], 1e-4));
    assert!(
        m.starts_with("frame: edge 0 of the guide has a non-finite point"),
        "{m}"
    );
    let m = refused(WireSweep {
        initial_normal: Some(DVec3::X),
        ..guided(vec![line([1., 0., 0.], [1., 0., 3.])], 1e-4)
    });
    assert!(m.contains("initial_normal") && m.contains("guide"), "{m}");
}

/// The guide moves and scales with the wire: the same faces from 1e-200 to 1e200.
#[test]
fn guided_sweeps_are_the_same_from_1e_200_to_1e200() {
    let options = guided(vec![helix(4.0, 2.0, 0.5)], 1e-4);
    let bar = guided(
        vec![Edge::Arc {
            start: DVec3::new(1.0, 0.0, 0.0),
            through: DVec3::new(0.0, 1.0, 1.5),
            end: DVec3::new(-1.0, 0.0, 3.0),
        }],
        1e-4,
    );
    for s in [1e-200, 1e-100, 1.0, 1e100, 1e200] {
        let o = DVec3::new(3e2, -1e2, 2e2) * s;
        check_similar(&[helix(3.0, 2.0, 0.5)], &square(0.5), &options, s, o);
        check_similar(
            &[line([0., 0., 0.], [0., 0., 3.])],
            &circle(0.3),
            &bar,
            s,
            o,
        );
    }
}
