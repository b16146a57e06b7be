//! Piecewise-linear scale laws (`scale_knots`) against closed forms: a chain of frustums
//! along a line, π r² ∫σ² ds along a PH helix cut at its knot, the section at a knot of
//! exactly the knot's scale, a closed wire that swells and comes back, the refusals and
//! invariance under scaling and translation.

use super::options_tests::helix;
use super::robustness_tests::check_similar;
use super::tests::{circle, frustum, line, off_circles, pipe_route, square, square_loop, volume};
use super::*;

fn knotted(scale: [f64; 2], knots: &[(f64, f64)]) -> WireSweep {
    WireSweep {
        scale,
        scale_knots: knots.to_vec(),
        ..WireSweep::default()
    }
}

#[test]
fn knots_along_a_line_make_a_chain_of_exact_frustums() {
    let bar = [line([0., 0., 0.], [0., 0., 4.])];
    let options = knotted([1.0, 1.0], &[(0.25, 2.0), (0.75, 0.5)]);
    let shape = sweep(&bar, &circle(0.5), &[], &options).unwrap();
    assert!(shape.is_solid());
    crate::testing::assert_closed_oriented(shape.brep());
    let want =
        frustum(0.5, 1.0, 1.0, 2.0) + frustum(0.5, 2.0, 2.0, 0.5) + frustum(0.5, 1.0, 0.5, 1.0);
    let v = volume(&shape);
    println!("frustums 1 → 2 → 0.5 → 1 along a line of 4: volume {v:.15} against {want:.15}");
    assert!((v - want).abs() < 1e-12 * want, "{v} against {want}");
    // Every section is the circle of radius 0.5 σ(z), σ piecewise linear through the knots.
    let sigma = |z: f64| match z {
        z if z <= 1.0 => 1.0 + z,
        z if z <= 3.0 => 2.0 - 0.75 * (z - 1.0),
        z => 0.5 + 0.5 * (z - 3.0),
    };
    let worst = off_circles(&shape, |z| 0.5 * sigma(z));
    println!("sections off 0.5 σ(z): {worst:.1e}");
    assert!(worst < 1e-14, "{worst}");
    // The law without its knots is a cylinder: the check can fail.
    let plain = sweep(&bar, &circle(0.5), &[], &knotted([1.0, 1.0], &[])).unwrap();
    assert!((volume(&plain) - want).abs() > 0.1);
}

#[test]
fn a_knot_on_a_ph_helix_cuts_it_there_and_is_exact() {
    let (a, b, c) = (0.6, 1.4, 0.8);
    let edges = [helix(3.0, 2.0, 1.5)];
    let options = WireSweep {
        tolerance: 1e-6,
        ..knotted([a, c], &[(0.4, b)])
    };
    let shape = sweep(&edges, &circle(0.3), &[], &options).unwrap();
    crate::testing::assert_closed_oriented(shape.brep());
    let spine = shape.spine();
    assert_eq!(spine.len(), 2, "the helix cut at its knot");
    let (l0, l1) = (spine[0].arc_length(), spine[1].arc_length());
    let want = frustum(0.3, l0, a, b) + frustum(0.3, l1, b, c);
    let v = volume(&shape);
    // The knot at 0.4 of the helix's length: at 0.4 of its angle.
    let phi = 0.4 * 1.5 * std::f64::consts::TAU;
    let knot = DVec3::new(
        3.0 * phi.cos(),
        3.0 * phi.sin(),
        2.0 * phi / std::f64::consts::TAU,
    );
    let at = spine[0].eval(spine[0].domain().1);
    println!(
        "knot on a PH helix: volume {v:.12} against {want:.12}; the cut {:.1e} from the \
         helix's point at 0.4 of its length",
        at.distance(knot)
    );
    assert!((v - want).abs() < 1e-11 * want, "{v} against {want}");
    assert!(at.distance(knot) < 1e-6, "{at}");
}

#[test]
fn a_closed_wire_swells_through_its_knots_and_closes() {
    let loop_edges = square_loop();
    let options = knotted([1.0, 1.0], &[(0.3, 1.5), (0.6, 0.7)]);
    let shape = sweep(&loop_edges, &circle(0.5), &[], &options).unwrap();
    assert!(shape.is_solid());
    crate::testing::assert_closed_oriented(shape.brep());
    // Lines and round corners (arcs) have their exact lengths: the knots at 0.3 and 0.6 of
    // the spine's. The curvature term of the Jacobian integrates to 0 over a centred circle;
    // σ is within the tolerance of the law on the corners' arcs.
    let length: f64 = shape.spine().iter().map(|c| c.arc_length()).sum();
    let want = frustum(0.5, 0.3 * length, 1.0, 1.5)
        + frustum(0.5, 0.3 * length, 1.5, 0.7)
        + frustum(0.5, 0.4 * length, 0.7, 1.0);
    let v = volume(&shape);
    let error = (v - want).abs() / want;
    println!("a closed square swelling 1 → 1.5 → 0.7 → 1: volume {v:.12} against {want:.12}, relative {error:.1e}");
    assert!(error < 4.0 * 1e-4 / 0.5, "{error:e}");
    // A scale law along the pipe route (lines and arcs): within the tolerance.
    let route = sweep(
        &pipe_route(),
        &square(0.5),
        &[],
        &knotted([1.0, 0.8], &[(0.5, 1.3)]),
    )
    .unwrap();
    crate::testing::assert_closed_oriented(route.brep());
}

#[test]
fn knots_that_cannot_be_are_refused_naming_the_option() {
    let bar = [line([0., 0., 0.], [0., 0., 4.])];
    let refused = |knots: &[(f64, f64)]| {
        sweep(&bar, &circle(0.5), &[], &knotted([1.0, 1.0], knots))
            .unwrap_err()
            .message()
    };
    for knots in [
        vec![(0.0, 1.0)],
        vec![(1.0, 1.0)],
        vec![(-0.1, 1.0)],
        vec![(f64::NAN, 1.0)],
        vec![(0.5, 1.0), (0.4, 2.0)],
        vec![(0.5, 1.0), (0.5, 2.0)],
    ] {
        let m = refused(&knots);
        assert!(
            m.starts_with("scale_knots[") && m.contains("(0, 1)"),
            "{knots:?}: {m}"
        );
    }
    // Knots that would fall on one piece boundary with an end or each other (the law would
    // jump there: a knot 1e-12 from the end gave the volume of σ running from 5 down to 1).
    for knots in [
        vec![(1.0 - 1e-12, 5.0)],
        vec![(1e-12, 5.0)],
        vec![(0.5, 1.0), (0.5 + 1e-12, 5.0)],
    ] {
        let m = refused(&knots);
        assert!(
            m.starts_with("scale_knots[") && m.contains("by at least 1e-8"),
            "{knots:?}: {m}"
        );
    }
    for value in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let m = refused(&[(0.5, value)]);
        assert!(m.starts_with("scale_knots[0]: the scale"), "{m}");
    }
    // A knot is a scale law: refused with the exact-RMF methods and with an end profile.
    let m = sweep(
        &bar,
        &circle(0.5),
        &[],
        &WireSweep {
            method: crate::spine::SpineMethod::Mobius,
            ..knotted([1.0, 1.0], &[(0.5, 2.0)])
        },
    )
    .unwrap_err()
    .message();
    assert!(m.starts_with("scale:"), "{m}");
    let m = sweep_between(
        &bar,
        &circle(0.5),
        &[],
        &circle(0.3),
        &[],
        &knotted([1.0, 1.0], &[(0.5, 2.0)]),
    )
    .unwrap_err()
    .message();
    assert!(m.starts_with("scale:"), "{m}");
}

#[test]
fn knotted_scale_laws_are_the_same_from_1e_200_to_1e200() {
    let options = knotted([0.5, 1.0], &[(0.3, 1.2), (0.8, 0.7)]);
    for s in [1e-200, 1e-100, 1.0, 1e100, 1e200] {
        let o = DVec3::new(3e2, -1e2, 2e2) * s;
        check_similar(&[helix(3.0, 2.0, 0.5)], &square(0.5), &options, s, o);
        check_similar(&pipe_route(), &circle(0.5), &options, s, o);
    }
}
