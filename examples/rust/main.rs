use rmfsurf::prelude::*;

fn main() -> rmfsurf::Result<()> {
    // G1 Hermite data: 17 points and unit tangents of the helix (cos t, sin t, 0.3 t).
    let (points, tangents): (Vec<DVec3>, Vec<DVec3>) = (0..=16)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 16.0;
            let point = DVec3::new(t.cos(), t.sin(), 0.3 * t);
            (point, DVec3::new(-t.sin(), t.cos(), 0.3).normalize())
        })
        .unzip();
    let spine = ph::spline_hermite(&points, &tangents)?; // 16 PH cubics, G1 at the joints
    let rmf = ph::rational_rmf(&spine, &ph::RmfOptions::rmf(DVec3::Z))?; // rational, degree 6
    let errors = ph::angle_errors(&spine, rmf.framed.frames())?; // against the closed-form RMF

    // The profile in the normal plane (x -> f2, y -> f3): a quarter circle of radius 0.2.
    let pole = |x, y| DVec3::new(x, y, 0.0);
    let arc = NurbsCurve::new(
        2,
        vec![pole(0.2, 0.0), pole(0.2, 0.2), pole(0.0, 0.2)],
        Some(vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0]),
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    )?;
    let surface = sweep(&rmf.framed, &arc.to_piecewise()?)?;
    let nurbs = NurbsSurface::from_piecewise(&surface)?; // one NURBS, as CAD kernels take it
    println!(
        "RMF within {:.1e} rad of the exact one; NURBS of degree ({}, {}) with {} x {} poles",
        errors.max,
        nurbs.degree_u(),
        nurbs.degree_v(),
        nurbs.pole_count_u(),
        nurbs.pole_count_v()
    );
    Ok(())
}
