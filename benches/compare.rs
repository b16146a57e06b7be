//! The side-by-side benchmark (`scripts/bench`, or `cargo bench --bench compare`): rmfsurf
//! against what CAD users have today, on the same inputs in one run, printed as one table.
//!
//! 0. The user's path (module `user_path`): NURBS spine in → exact surface out, every step
//!    timed, beside OpenCascade's BRepOffsetAPI_MakePipeShell in corrected-Frenet and Frenet
//!    mode on the same NURBS data (the C++ program `benches/occ/pipe_shell.cpp`, run by module
//!    `occ` with a time limit): the spine of issue 19, a 10-turn helix and a 100-edge pipe
//!    route; then the breaks against halving, the greedy optimum and the h⁴ bound, poles
//!    against OpenCascade's by tolerance, and the scaling from NURBS data with memory.
//! 1. Frames: the rational RMF of a PH cubic spline, the exact rational RMFs of Möbius
//!    images and RRMF quintics, each against the double-reflection RMF on the same curve
//!    at the same samples: build time, time per frame, largest angle to a reference RMF
//!    (the closed-form RMF of the PH spline; double reflection at 100× the samples for the
//!    others), and how many double-reflection samples match our error and what they cost.
//! 2. Sweeps from Hermite data: our profile surface against MakePipeShell in corrected-Frenet
//!    mode on the same spine (the PH spline's Bézier edges) and profile; both results
//!    measured here by the same code (max |cos| between parameter lines on a circle pipe,
//!    max |K| on a line profile).
//! 3. Developables: cone spline fit + development against the tolerance.
//! 4. Scaling from Hermite data: PH spline → RMF → sweep for 10 … 100,000 segments, with the
//!    exponent of a least-squares fit of log time against log segments.
//!
//! Times in sections 1–4 are the fastest of several runs; section 0 gives medians with
//! their ranges (the machine may be shared).

mod occ;
mod support;
mod user_path;

use rmfsurf::glam::DVec3;
use rmfsurf::metrics::{angle_about_tangent, gaussian_curvature, parameter_line_cosine};
use rmfsurf::{
    cone::approximate as approximate_developable, cone::ConeSpline, cone::Rule,
    cone::TangentSurface, hermite_sequence, mobius::hermite_points as mobius_hermite_points,
    ph::rational_rmf as ph_rational_rmf, ph::spline_hermite as ph_spline_hermite, ph::ExactRmf,
    ph::RmfOptions, rrmf::spline as rrmf_spline, rrmf::ShapeMeasure, sweep, uniform_parameters,
    DoubleReflectionRmf, Frame, NurbsSurface, ParametricCurve, PiecewiseCurve, PiecewiseSurface,
    RationalBezierCurve, RationalFrames,
};
use support::{timed, REPEATS};

/// Frame samples per spline segment in the frame comparison: a coarse and a fine
/// tessellation of the sweep.
const SAMPLES_PER_SEGMENT: [usize; 2] = [2, 10];
/// The initial normal of every frame.
const NORMAL: DVec3 = DVec3::Z;

fn main() {
    let program = occ::Program::build()
        .map_err(|e| println!("OpenCascade columns skipped: {e}"))
        .ok();
    println!("rmfsurf side by side (sections 0: medians with ranges; 1–4: fastest of {REPEATS} runs; times on this machine)\n");
    user_path::section(program.as_ref());
    if std::env::var_os("RMFSURF_BENCH_USER_PATH_ONLY").is_some() {
        // For profiling the user's path alone (`perf record`).
        return;
    }
    user_path::breaks_section();
    user_path::poles_section(program.as_ref());
    user_path::scaling_section();
    frames_section();
    sweeps_section(program.as_ref());
    developables_section();
    scaling_section();
}

// ---------------------------------------------------------------------------------------
// Timing and data

/// The conical helix ((t/20 + 1) cos t, (t/20 + 1) sin t, 0.3 t) and its derivative.
fn spiral(t: f64) -> (DVec3, DVec3) {
    let r = t / 20.0 + 1.0;
    let (s, c) = t.sin_cos();
    (
        DVec3::new(r * c, r * s, 0.3 * t),
        DVec3::new(c / 20.0 - r * s, s / 20.0 + r * c, 0.3),
    )
}

/// Hermite data of `segments` segments of the spiral, parameter step `step`.
fn spiral_data(segments: usize, step: f64) -> (Vec<DVec3>, Vec<DVec3>) {
    (0..=segments).map(|i| spiral(step * i as f64)).unzip()
}

fn ms(seconds: f64) -> String {
    format!("{:.3} ms", seconds * 1e3)
}

fn ns(seconds: f64) -> String {
    format!("{:.0} ns", seconds * 1e9)
}

// ---------------------------------------------------------------------------------------
// 1. Frames

/// One method's curve with its rational frames, and the reference RMF along that curve.
struct FrameCase {
    name: &'static str,
    segments: usize,
    build: f64,
    curve: PiecewiseCurve,
    frames: RationalFrames,
    reference: Reference,
}

/// The RMF a frame is measured against.
enum Reference {
    /// The closed-form RMF of a PH spline (any parameter).
    Exact(Box<ExactRmf>),
    /// Double reflection at 100× the samples of the comparison.
    DoubleReflection,
}

impl FrameCase {
    /// The reference frames at `params` (a uniform grid over the domain).
    fn reference_frames(&self, params: &[f64]) -> Vec<Frame> {
        match &self.reference {
            Reference::Exact(rmf) => params.iter().map(|&t| rmf.frame(t)).collect(),
            Reference::DoubleReflection => {
                let fine = uniform_parameters(self.curve.domain(), 100 * (params.len() - 1) + 1);
                let rmf = DoubleReflectionRmf::along(&self.curve, fine, NORMAL).unwrap();
                rmf.frames().iter().step_by(100).copied().collect()
            }
        }
    }
}

/// The largest angle between corresponding frames.
fn max_angle(a: &[Frame], b: &[Frame]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(a, b)| angle_about_tangent(a, b).abs())
        .fold(0.0, f64::max)
}

fn ph_case(segments: usize) -> FrameCase {
    let (points, tangents) = spiral_data(segments, 0.1);
    let (build, (curve, frames)) = timed(|| {
        let spline = ph_spline_hermite(&points, &tangents).unwrap();
        let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(NORMAL)).unwrap();
        (spline, rmf.framed.into_parts().1)
    });
    let exact = ExactRmf::new(&curve, NORMAL, 0.0).unwrap();
    FrameCase {
        name: "PH cubic, rational RMF (W)",
        segments,
        build,
        curve: curve.into_curve(),
        frames,
        reference: Reference::Exact(Box::new(exact)),
    }
}

fn mobius_case(segments: usize) -> FrameCase {
    let (points, tangents) = spiral_data(segments, 0.1);
    let (build, result) = timed(|| mobius_hermite_points(&points, &tangents, NORMAL).unwrap());
    FrameCase {
        name: "Möbius image, exact RMF",
        segments,
        build,
        curve: result.curve().clone(),
        frames: result.frames().clone(),
        reference: Reference::DoubleReflection,
    }
}

fn rrmf_case(segments: usize) -> FrameCase {
    let (points, tangents) = spiral_data(segments, 0.1);
    let data = hermite_sequence(&points, &tangents).unwrap();
    let (build, spline) =
        timed(|| rrmf_spline(&data, ShapeMeasure::ScaledEnergyRmf, 16, NORMAL).unwrap());
    FrameCase {
        name: "RRMF quintic (N_η 16), exact RMF",
        segments,
        build,
        curve: spline.framed.curve().clone(),
        frames: spline.framed.frames().clone(),
        reference: Reference::DoubleReflection,
    }
}

/// Double reflection with `samples` samples along the case's curve: time and error.
fn double_reflection(case: &FrameCase, samples: usize) -> (f64, f64) {
    let params = uniform_parameters(case.curve.domain(), samples);
    let (time, rmf) =
        timed(|| DoubleReflectionRmf::along(&case.curve, params.clone(), NORMAL).unwrap());
    (
        time,
        max_angle(&case.reference_frames(&params), rmf.frames()),
    )
}

/// Double-reflection samples that reach `target` along a PH spline (error ∝ n⁻⁴, checked).
fn samples_to_match(case: &FrameCase, start: usize, start_error: f64, target: f64) -> String {
    if !matches!(case.reference, Reference::Exact(_)) {
        return "— (ours is exact)".into();
    }
    let mut n = ((start as f64) * (start_error / target).powf(0.25)).ceil() as usize;
    for _ in 0..6 {
        let (time, error) = double_reflection(case, n);
        if error <= target {
            return format!("{n} samples, {}", ms(time));
        }
        n = n * 5 / 4;
    }
    format!("more than {n}")
}

fn frames_section() {
    println!("1. FRAMES against double reflection (DR) at the same samples, conical helix, 0.1 rad per segment");
    println!(
        "| method | segments | build | samples | per frame (ours) | per frame (DR) | ours / DR | max angle ours | max angle DR | DR / ours | DR samples for our error |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for case in [ph_case(1000), mobius_case(1000), rrmf_case(200)] {
        let ours_error = our_error(&case);
        for per_segment in SAMPLES_PER_SEGMENT {
            frame_row(&case, per_segment, ours_error);
        }
    }
    println!(
        "Reference: the closed-form RMF (30) for the PH spline; double reflection at 100× the samples \
         for the exact methods (whose own error is then the reference's). Our error: anywhere on the \
         curve (20 points per segment); double reflection: at its own samples only. The Möbius curves \
         are spherical on every segment, where double reflection is itself exact (both at round-off).\n"
    );
}

/// Our largest angle to the reference anywhere: on a grid of 20 points per segment that
/// avoids the joints (where the rational RMF of the PH spline is exact).
fn our_error(case: &FrameCase) -> f64 {
    let (lo, hi) = case.curve.domain();
    let n = 20 * case.segments;
    let params: Vec<f64> = (0..n)
        .map(|i| lo + (hi - lo) * (i as f64 + 0.37) / n as f64)
        .collect();
    let ours: Vec<Frame> = params.iter().map(|&t| case.frames.frame(t)).collect();
    match &case.reference {
        Reference::Exact(_) => max_angle(&case.reference_frames(&params), &ours),
        // The reference grid must be uniform: measure on it instead.
        Reference::DoubleReflection => {
            let grid = uniform_parameters((lo, hi), n + 1);
            let ours: Vec<Frame> = grid.iter().map(|&t| case.frames.frame(t)).collect();
            max_angle(&case.reference_frames(&grid), &ours)
        }
    }
}

fn frame_row(case: &FrameCase, per_segment: usize, ours_error: f64) {
    let samples = per_segment * case.segments + 1;
    let params = uniform_parameters(case.curve.domain(), samples);
    let (eval, _) = timed(|| {
        params
            .iter()
            .map(|&t| case.frames.frame(t))
            .collect::<Vec<_>>()
    });
    // Double reflection measured at its own samples, where it is most accurate.
    let (dr_time, dr) = timed(|| DoubleReflectionRmf::along(&case.curve, params.clone(), NORMAL));
    let dr_error = max_angle(&case.reference_frames(&params), dr.unwrap().frames());
    let per = |t: f64| t / samples as f64;
    println!(
        "| {} | {} | {} | {samples} | {} | {} | {:.2} | {:.1e} rad | {:.1e} rad | {:.1} | {} |",
        case.name,
        case.segments,
        ms(case.build),
        ns(per(eval)),
        ns(per(dr_time)),
        eval / dr_time,
        ours_error,
        dr_error,
        dr_error / ours_error,
        samples_to_match(case, samples, dr_error, ours_error),
    );
}

// ---------------------------------------------------------------------------------------
// 2. Sweeps against OpenCascade

/// A surface measured the same way for both libraries: patches of a piecewise surface.
struct Measured {
    poles: usize,
    max_cos: f64,
    max_k: f64,
}

/// Max |cos ∠(s_u, s_v)| and max |K| at interior points of every patch (12 × 12 each).
fn measure(surfaces: &[PiecewiseSurface], poles: usize) -> Measured {
    let (mut max_cos, mut max_k) = (0.0f64, 0.0f64);
    for surface in surfaces {
        let (us, vs) = (surface.u_breaks(), surface.v_breaks());
        for u in us.windows(2) {
            for v in vs.windows(2) {
                for (i, j) in (0..12).flat_map(|i| (0..12).map(move |j| (i, j))) {
                    let a = u[0] + (u[1] - u[0]) * (i as f64 + 0.5) / 12.0;
                    let b = v[0] + (v[1] - v[0]) * (j as f64 + 0.5) / 12.0;
                    let jet = surface.eval_jet(a, b);
                    max_cos = max_cos.max(parameter_line_cosine(&jet));
                    max_k = max_k.max(gaussian_curvature(&jet).abs());
                }
            }
        }
    }
    Measured {
        poles,
        max_cos,
        max_k,
    }
}

/// The two profiles: a circle of radius r (a pipe, for |cos|) and a line from a to b along
/// f₂ (a developable strip, for K).
#[derive(Clone, Copy)]
enum Profile {
    Circle(f64),
    Line(f64, f64),
}

impl Profile {
    fn name(self) -> String {
        match self {
            Profile::Circle(r) => format!("circle r {r}"),
            Profile::Line(..) => "line along f2".into(),
        }
    }

    /// max |K| where it means something: a line swept by an RMF is developable (K = 0); a
    /// pipe is not.
    fn curvature(self, max_k: f64) -> String {
        match self {
            Profile::Line(..) => format!("{max_k:.1e}"),
            Profile::Circle(_) => "— (pipe)".into(),
        }
    }

    /// The profile in the normal plane (x → f₂, y → f₃), as rmfsurf sweeps it.
    fn curve(self) -> PiecewiseCurve {
        match self {
            Profile::Line(a, b) => {
                PiecewiseCurve::with_unit_intervals(vec![RationalBezierCurve::polynomial(&[
                    DVec3::new(a, 0.0, 0.0),
                    DVec3::new(b, 0.0, 0.0),
                ])
                .unwrap()])
                .unwrap()
            }
            Profile::Circle(r) => {
                // Three arcs of 120°, weights 1, cos 60° = 1/2, 1, the middle pole at 2r
                // on the bisector: 7 poles, the fewest of an exact rational quadratic
                // circle (four quarter arcs take 9).
                let at = |degrees: f64, radius: f64| {
                    let (s, c) = degrees.to_radians().sin_cos();
                    DVec3::new(radius * c, radius * s, 0.0)
                };
                let arc = |k: usize| {
                    let a = 120.0 * k as f64;
                    RationalBezierCurve::from_weighted(
                        &[at(a, r), at(a + 60.0, 2.0 * r), at(a + 120.0, r)],
                        &[1.0, 0.5, 1.0],
                    )
                    .unwrap()
                };
                PiecewiseCurve::with_unit_intervals((0..3).map(arc).collect()).unwrap()
            }
        }
    }

    /// The same profile placed at the spine's start for OpenCascade, in the plane of the
    /// start frame (f₂, f₃).
    fn occ_input(self, start: DVec3, frame: &Frame) -> String {
        let p = |v: DVec3| format!("{:?} {:?} {:?}", v.x, v.y, v.z);
        match self {
            Profile::Line(a, b) => format!(
                "profile line {} {}\n",
                p(start + a * frame.f2),
                p(start + b * frame.f2)
            ),
            Profile::Circle(r) => {
                format!("profile circle {} {} {r:?}\n", p(start), p(frame.tangent))
            }
        }
    }
}

/// rmfsurf: Hermite data → PH spline → rational RMF → profile surface.
fn our_sweep(points: &[DVec3], tangents: &[DVec3], profile: &PiecewiseCurve) -> PiecewiseSurface {
    let spline = ph_spline_hermite(points, tangents).unwrap();
    let rmf = ph_rational_rmf(&spline, &RmfOptions::rmf(NORMAL)).unwrap();
    sweep(&rmf.framed, profile).unwrap()
}

fn sweeps_section(program: Option<&occ::Program>) {
    println!("2. SWEEPS FROM HERMITE DATA against OpenCascade BRepOffsetAPI_MakePipeShell, corrected Frenet (same spine and profile)");
    println!("| spine segments | profile | rmfsurf build | OCC build | rmfsurf poles | OCC poles (faces) | max \\|cos\\| rmfsurf | max \\|cos\\| OCC | max \\|K\\| rmfsurf | max \\|K\\| OCC |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for segments in [16, 64] {
        // Half a turn of the spiral per 16 segments: 0.2 rad per segment.
        let (points, tangents) = spiral_data(segments, 3.2 / segments as f64);
        for profile in [Profile::Circle(0.2), Profile::Line(0.1, 0.4)] {
            sweep_row(program, &points, &tangents, profile, segments);
        }
    }
    println!(
        "Build: rmfsurf from Hermite data (PH spline + RMF + surface: not the user's path, which starts \
         from NURBS data, section 0); OpenCascade from the finished spine (the PH spline's Bézier \
         edges). Both surfaces measured here at 12 × 12 points per patch/face.\n"
    );
}

fn sweep_row(
    program: Option<&occ::Program>,
    points: &[DVec3],
    tangents: &[DVec3],
    profile: Profile,
    segments: usize,
) {
    let curve = profile.curve();
    let (build, surface) = timed(|| our_sweep(points, tangents, &curve));
    let nurbs = NurbsSurface::from_piecewise(&surface).unwrap();
    let ours = measure(
        std::slice::from_ref(&surface),
        nurbs.pole_count_u() * nurbs.pole_count_v(),
    );
    let occ = program.map(|program| {
        let spine = ph_spline_hermite(points, tangents).unwrap();
        let rmf = ph_rational_rmf(&spine, &RmfOptions::rmf(NORMAL)).unwrap();
        let request = occ::Request {
            spine: occ::Spine::Edges(&spine),
            profile: profile.occ_input(spine.eval(0.0), &rmf.framed.frames().frame(0.0)),
            mode: occ::Mode::CorrectedFrenet,
            tolerance: 0.0,
            repeats: REPEATS,
            time_limit: std::time::Duration::from_secs(120),
        };
        match program.sweep(&request) {
            occ::Outcome::Done(result) => {
                let faces = &result.faces;
                let poles = faces
                    .iter()
                    .map(|f| f.pole_count_u() * f.pole_count_v())
                    .sum();
                let pieces: Vec<PiecewiseSurface> =
                    faces.iter().map(|f| f.to_piecewise().unwrap()).collect();
                let fastest = result.times.iter().copied().fold(f64::INFINITY, f64::min);
                Ok((fastest, faces.len(), measure(&pieces, poles)))
            }
            occ::Outcome::Failed(e) => Err(e),
            occ::Outcome::TimedOut(limit) => Err(format!("no result after {limit:?}")),
        }
    });
    let (occ_time, occ_poles, occ_cos, occ_k) = match occ {
        Some(Ok((time, faces, m))) => (
            ms(time),
            format!("{} ({faces})", m.poles),
            format!("{:.1e}", m.max_cos),
            profile.curvature(m.max_k),
        ),
        Some(Err(e)) => {
            let e = format!("failed: {}", e.trim());
            (e.clone(), e.clone(), e.clone(), e)
        }
        None => Default::default(),
    };
    println!(
        "| {segments} | {} | {} | {occ_time} | {} | {occ_poles} | {:.1e} | {occ_cos} | {} | {occ_k} |",
        profile.name(),
        ms(build),
        ours.poles,
        ours.max_cos,
        profile.curvature(ours.max_k),
    );
}

// ---------------------------------------------------------------------------------------
// 3. Developables

/// The twisted cubic (t, t², t³) on [0.2, 1.2].
struct TwistedCubic;

impl ParametricCurve for TwistedCubic {
    fn domain(&self) -> (f64, f64) {
        (0.2, 1.2)
    }

    fn point_derivative(&self, t: f64) -> rmfsurf::Result<(DVec3, DVec3)> {
        Ok((
            DVec3::new(t, t * t, t * t * t),
            DVec3::new(1.0, 2.0 * t, 3.0 * t * t),
        ))
    }
}

/// Largest relative difference of lengths between a cone spline's strip and its
/// development: per piece, the parallel arcs at three distances and the bounding rulings.
fn isometry_error(spline: &ConeSpline, flat: &ConeSpline) -> f64 {
    let (a, b) = (
        spline.surface(-0.2, 0.2).unwrap(),
        flat.surface(-0.2, 0.2).unwrap(),
    );
    let length = |s: &PiecewiseSurface, from: (f64, f64), to: (f64, f64)| {
        let n = 400;
        (0..n)
            .map(|i| {
                let p = |k: usize| {
                    let f = k as f64 / n as f64;
                    s.eval(from.0 + f * (to.0 - from.0), from.1 + f * (to.1 - from.1))
                };
                (p(i + 1) - p(i)).length()
            })
            .sum::<f64>()
    };
    let (lo, hi) = a.domain_u();
    let mut worst = 0.0f64;
    for v in a.v_breaks().windows(2) {
        let lines = [lo, 0.5 * (lo + hi), hi]
            .map(|u| ((u, v[0]), (u, v[1])))
            .into_iter()
            .chain([v[0], v[1]].map(|v| ((lo, v), (hi, v))));
        for (from, to) in lines {
            let (la, lb) = (length(&a, from, to), length(&b, from, to));
            worst = worst.max((la - lb).abs() / la);
        }
    }
    worst
}

fn developables_section() {
    println!("3. DEVELOPABLES: cone spline fit of the tangent surface of (t, t², t³), t in [0.2, 1.2], strip v in [0.5, 8], and its development");
    println!("| tolerance | pieces | deviation reached | fit | development + NURBS | isometry (rel. length error) |");
    println!("| --- | --- | --- | --- | --- | --- |");
    let surface = TangentSurface::new(&TwistedCubic, 0.5, 8.0).unwrap();
    for tolerance in [1e-2, 1e-3, 1e-4, 1e-5] {
        let fit = |tol| {
            approximate_developable(&surface, tol, Rule::MinimalVertexDistance, 100_000).unwrap()
        };
        let (fit_time, result) = timed(|| fit(tolerance));
        let (develop_time, flat) = timed(|| {
            let flat = result.spline.developed().unwrap();
            let nurbs = NurbsSurface::from_piecewise(&flat.surface(-0.2, 0.2).unwrap()).unwrap();
            (flat, nurbs)
        });
        println!(
            "| {tolerance:.0e} | {} | {:.1e} | {} | {} | {:.1e} |",
            result.spline.pieces().len(),
            result.max_error,
            ms(fit_time),
            ms(develop_time),
            isometry_error(&result.spline, &flat.0),
        );
    }
    println!("Isometry: parallel arcs (3 per piece) and bounding rulings, each measured on the strip t in [−0.2, 0.2] and on its development by 400-point polylines.\n");
}

// ---------------------------------------------------------------------------------------
// 4. Scaling

fn scaling_section() {
    println!("4. SCALING FROM HERMITE DATA: Hermite data → PH spline → rational RMF → profile surface (line profile), conical helix, 0.1 rad per segment");
    println!("| segments | time | per segment |");
    println!("| --- | --- | --- |");
    let profile = Profile::Line(0.1, 0.4).curve();
    let mut samples = Vec::new();
    for segments in [10, 100, 1_000, 10_000, 100_000] {
        let (points, tangents) = spiral_data(segments, 0.1);
        let (time, _) = timed(|| our_sweep(&points, &tangents, &profile));
        println!(
            "| {segments} | {} | {:.2} µs |",
            ms(time),
            time / segments as f64 * 1e6
        );
        samples.push(((segments as f64).ln(), time.ln()));
    }
    println!(
        "Fitted exponent (time ∝ segments^p, least squares on log–log): p = {:.3}",
        fitted_exponent(&samples)
    );
}

/// The slope of a least-squares line through (log n, log time) samples.
fn fitted_exponent(samples: &[(f64, f64)]) -> f64 {
    let n = samples.len() as f64;
    let (mx, my) = samples
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = samples.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    sxy / sxx
}
