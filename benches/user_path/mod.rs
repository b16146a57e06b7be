//! The path a user takes: NURBS spine in, exact surface out — NURBS data → G1 check and PH
//! spline approximation → rational RMF → profile surface → one NURBS surface, every step
//! timed — beside OpenCascade's BRepOffsetAPI_MakePipeShell (corrected Frenet and Frenet) on
//! the same NURBS data in the same run. Then the breaks (segments against uniform halving,
//! the greedy optimum and the h⁴ bound), poles against OpenCascade's at equal tolerance and
//! at equal orthogonality, and the scaling from 10 to 100,000 segments with memory.
//!
//! Times: the median of several runs with the range (the machine is shared and its timings
//! vary by up to ±40 %); ratios are of medians of the same run.

mod memory;

use super::occ::{Mode, Outcome, Program, Request, Spine, WireEdge};
use super::{measure, Measured, Profile, NORMAL};
use rmfsurf::glam::DVec3;
use rmfsurf::{
    ph::check_g1, ph::rational_rmf as ph_rational_rmf,
    ph::spline_approximate as ph_spline_approximate,
    ph::spline_approximate_with as ph_spline_approximate_with, ph::ApproximationOptions,
    ph::RmfOptions, sweep, wire::sweep as sweep_wire, wire::Edge, wire::WireSweep, NurbsCurve,
    NurbsSurface, ParametricCurve, PiecewiseCurve, PiecewiseSurface, RationalBezierCurve,
};
use std::f64::consts::{FRAC_1_SQRT_2, PI};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Runs of our path per row (the median counts).
const RUNS: usize = 21;
/// Runs of OpenCascade per row on the issue spine (2 per round on the longer spines).
const OCC_RUNS: usize = 12;
/// Rounds of our runs and OpenCascade's in turn.
const ROUNDS: usize = 3;
/// A sweep of OpenCascade still running after this is killed and reported.
const OCC_TIME_LIMIT: Duration = Duration::from_secs(120);
/// The tolerance of the spine approximation (and OpenCascade's default Tol3d).
const TOLERANCE: f64 = 1e-4;

// ---------------------------------------------------------------------------------------
// The inputs

/// A user's spine: NURBS data, and how OpenCascade is given it.
struct Case {
    name: &'static str,
    nurbs: NurbsCurve,
    /// For OpenCascade: a wire of these lines and arcs instead of one B-spline edge.
    wire: Option<Vec<WireEdge>>,
    /// Circle radius and line profile [from, to] along f₂.
    circle: f64,
    line: (f64, f64),
}

impl Case {
    fn spine(&self) -> Spine<'_> {
        match &self.wire {
            Some(edges) => Spine::Wire(edges),
            None => Spine::Nurbs(&self.nurbs),
        }
    }
}

/// The cubic Bézier spine of issue 19, (0,0,0), (10,20,0), (30,−10,20), (40,10,10), as
/// NURBS data.
fn issue_spine() -> Case {
    let poles = vec![
        DVec3::ZERO,
        DVec3::new(10.0, 20.0, 0.0),
        DVec3::new(30.0, -10.0, 20.0),
        DVec3::new(40.0, 10.0, 10.0),
    ];
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    Case {
        name: "issue spine (cubic Bézier)",
        nurbs: NurbsCurve::new(3, poles, None, knots).unwrap(),
        wire: None,
        circle: 2.0,
        line: (0.5, 2.0),
    }
}

/// A C¹ cubic B-spline (double interior knots) of `segments` Hermite pieces of a curve on
/// [0, t_end] given with its derivative: the form CAD systems export analytic curves in.
fn hermite_nurbs(curve: impl Fn(f64) -> (DVec3, DVec3), t_end: f64, segments: usize) -> NurbsCurve {
    let h = t_end / segments as f64;
    let mut poles = vec![curve(0.0).0];
    let mut knots = vec![0.0; 4];
    for k in 0..segments {
        let (a, b) = (k as f64 * h, (k + 1) as f64 * h);
        let ((p0, d0), (p1, d1)) = (curve(a), curve(b));
        poles.push(p0 + d0 * (h / 3.0));
        poles.push(p1 - d1 * (h / 3.0));
        if k + 1 < segments {
            knots.extend([b, b]);
        }
    }
    poles.push(curve(t_end).0);
    knots.extend([t_end; 4]);
    NurbsCurve::new(3, poles, None, knots).unwrap()
}

/// A helix of radius 5 and pitch 3, 10 turns, as a C¹ cubic NURBS with 16 segments per turn.
fn long_helix() -> Case {
    let c = 3.0 / (2.0 * PI);
    let helix = |t: f64| {
        let (s, co) = t.sin_cos();
        (
            DVec3::new(5.0 * co, 5.0 * s, c * t),
            DVec3::new(-5.0 * s, 5.0 * co, c),
        )
    };
    Case {
        name: "helix, 10 turns (C¹ cubic NURBS, 160 segments)",
        nurbs: hermite_nurbs(helix, 20.0 * PI, 160),
        wire: None,
        circle: 0.5,
        line: (0.1, 0.5),
    }
}

/// A pipe route of 100 edges: 51 straight runs of length 3 and 49 bends of radius 1 by 90°,
/// the direction cycling through x, y, z (a staircase that never meets itself). OpenCascade
/// gets the wire of lines and arcs; rmfsurf the same pieces as one G1 NURBS curve (lines
/// raised to degree 2), parameterized by arc length.
fn pipe_route() -> Case {
    let axes = [DVec3::X, DVec3::Y, DVec3::Z];
    let (run, radius) = (3.0, 1.0);
    let mut point = DVec3::ZERO;
    let (mut edges, mut wire) = (Vec::new(), Vec::new());
    for k in 0..51 {
        let (d, next) = (axes[k % 3], axes[(k + 1) % 3]);
        let end = point + run * d;
        edges.push(RationalBezierCurve::polynomial(&[point, end]).unwrap());
        wire.push(WireEdge::Line(point, end));
        point = end;
        if k < 50 {
            let corner = point + radius * d;
            let end = corner + radius * next;
            // The arc's midpoint: the centre plus the radius along the bisector.
            let centre = point + radius * next;
            let middle = centre + radius * (corner - centre).normalize();
            wire.push(WireEdge::Arc(point, middle, end));
            edges.push(
                RationalBezierCurve::from_weighted(
                    &[point, corner, end],
                    &[1.0, FRAC_1_SQRT_2, 1.0],
                )
                .unwrap(),
            );
            point = end;
        }
    }
    let lengths: Vec<f64> = edges
        .iter()
        .map(|e| {
            if e.degree() == 1 {
                run
            } else {
                0.5 * PI * radius
            }
        })
        .collect();
    let mut breaks = vec![0.0];
    for l in &lengths {
        breaks.push(breaks.last().unwrap() + l);
    }
    let raised = edges.iter().map(|e| e.elevated(2 - e.degree())).collect();
    let nurbs = NurbsCurve::from_piecewise(&PiecewiseCurve::new(raised, breaks).unwrap()).unwrap();
    Case {
        name: "pipe route, 100 edges (51 lines, 49 bends)",
        nurbs,
        wire: Some(wire),
        circle: 0.3,
        line: (0.05, 0.3),
    }
}

// ---------------------------------------------------------------------------------------
// Our path, step by step

/// The steps of our path.
const STEPS: [&str; 5] = ["NURBS in", "approximate", "RMF", "sweep", "NURBS out"];

/// Our path once: the seconds of each step, and its results.
fn our_path(
    nurbs: &NurbsCurve,
    profile: &PiecewiseCurve,
    options: &ApproximationOptions,
) -> ([f64; 5], Built) {
    let mut times = [0.0; 5];
    let mut step = |k: usize, start: Instant| times[k] = start.elapsed().as_secs_f64();
    let t = Instant::now();
    // rmf_nurbs_curve_create: validation and Bézier decomposition.
    let data = NurbsCurve::new(
        nurbs.degree(),
        nurbs.poles().to_vec(),
        Some(nurbs.weights().to_vec()),
        nurbs.knots().to_vec(),
    )
    .unwrap();
    let spine = data.to_piecewise().unwrap();
    step(0, t);
    let t = Instant::now();
    // rmf_ph_spline_approximate(_with_options): the G1 check and the approximation.
    check_g1(&spine).unwrap();
    let fit = ph_spline_approximate_with(&spine, spine.breaks(), options).unwrap();
    step(1, t);
    let t = Instant::now();
    let rmf = ph_rational_rmf(&fit.spline, &RmfOptions::rmf(NORMAL)).unwrap();
    step(2, t);
    let t = Instant::now();
    let surface = sweep(&rmf.framed, profile).unwrap();
    step(3, t);
    let t = Instant::now();
    let out = NurbsSurface::from_piecewise(&surface).unwrap();
    step(4, t);
    let built = Built {
        segments: fit.spline.segments().len(),
        max_distance: fit.max_distance,
        start_frame: rmf.framed.frames().frame(fit.spline.domain().0),
        start: fit.spline.eval(fit.spline.domain().0),
        surfaces: vec![surface],
        nurbs: vec![black_box(out)],
    };
    (times, built)
}

/// The route as the wire a user draws, through rmf_wire_sweep (`sweep_wire`): lines and
/// arcs swept exactly (constant frames, cylinders; the arcs' rational frames, tori), the
/// lateral faces only (the line profile is open). The seconds of the sweep and of the
/// faces' NURBS, in the steps' "sweep" and "NURBS out" places; `start` from our NURBS path
/// at the same start (f₂ = `NORMAL` projected, as there).
fn wire_path(edges: &[WireEdge], profile: &PiecewiseCurve, start: &Built) -> ([f64; 5], Built) {
    let mut times = [0.0; 5];
    let t = Instant::now();
    let edges: Vec<Edge> = edges
        .iter()
        .map(|e| match *e {
            WireEdge::Line(from, to) => Edge::Line { from, to },
            WireEdge::Arc(start, through, end) => Edge::Arc {
                start,
                through,
                end,
            },
        })
        .collect();
    let options = WireSweep {
        tolerance: TOLERANCE,
        initial_normal: Some(NORMAL),
        solid: false,
        ..WireSweep::default()
    };
    let shape = sweep_wire(&edges, profile, &[], &options).unwrap();
    times[3] = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let surfaces: Vec<PiecewiseSurface> = shape
        .faces()
        .iter()
        .filter_map(|f| f.surface.clone())
        .collect();
    let nurbs: Vec<NurbsSurface> = surfaces
        .iter()
        .map(|s| NurbsSurface::from_piecewise(s).unwrap())
        .collect();
    times[4] = t.elapsed().as_secs_f64();
    let built = Built {
        segments: shape.spine().iter().map(|c| c.segments().len()).sum(),
        max_distance: shape.report().spine_distance,
        start: start.start,
        start_frame: start.start_frame,
        surfaces,
        nurbs: black_box(nurbs),
    };
    (times, built)
}

/// What our path made: one surface, or a wire sweep's faces.
struct Built {
    /// PH segments (for a wire sweep: spine pieces, lines, arcs and PH segments).
    segments: usize,
    max_distance: f64,
    start: DVec3,
    start_frame: rmfsurf::Frame,
    surfaces: Vec<PiecewiseSurface>,
    nurbs: Vec<NurbsSurface>,
}

impl Built {
    fn poles(&self) -> usize {
        self.nurbs
            .iter()
            .map(|n| n.pole_count_u() * n.pole_count_v())
            .sum()
    }

    /// BRepCheck_Analyzer on a face of each surface.
    fn valid(&self, program: &Program) -> String {
        for n in &self.nurbs {
            match program.check(n) {
                Ok(true) => {}
                Ok(false) => return "INVALID".into(),
                Err(e) => return format!("check failed: {e}"),
            }
        }
        "valid".into()
    }
}

/// Median and range of a sample of seconds.
#[derive(Clone, Copy)]
struct Spread {
    median: f64,
    min: f64,
    max: f64,
}

fn spread(times: &[f64]) -> Spread {
    let mut sorted = times.to_vec();
    sorted.sort_by(f64::total_cmp);
    Spread {
        median: sorted[sorted.len() / 2],
        min: sorted[0],
        max: sorted[sorted.len() - 1],
    }
}

fn ms(seconds: f64) -> String {
    if seconds < 1e-2 {
        format!("{:.3}", seconds * 1e3)
    } else {
        format!("{:.1}", seconds * 1e3)
    }
}

fn with_range(s: Spread) -> String {
    format!("{} ms [{}–{}]", ms(s.median), ms(s.min), ms(s.max))
}

/// OpenCascade's outcome on one case, measured like ours.
struct Theirs {
    /// Seconds of each build, or why there are none.
    time: Result<Vec<f64>, String>,
    poles: String,
    valid: String,
    cos: String,
    k: String,
}

fn theirs(
    program: &Program,
    case: &Case,
    profile: Profile,
    built: &Built,
    mode: Mode,
    tolerance: f64,
    runs: usize,
) -> Theirs {
    let request = Request {
        spine: case.spine(),
        profile: profile.occ_input(built.start, &built.start_frame),
        mode,
        tolerance,
        repeats: runs,
        time_limit: OCC_TIME_LIMIT,
    };
    match program.sweep(&request) {
        Outcome::Done(result) => {
            let poles: usize = result
                .faces
                .iter()
                .map(|f| f.pole_count_u() * f.pole_count_v())
                .sum();
            let pieces: Vec<PiecewiseSurface> = result
                .faces
                .iter()
                .map(|f| f.to_piecewise().unwrap())
                .collect();
            let m = measure(&pieces, poles);
            Theirs {
                time: Ok(result.times),
                poles: format!("{} ({} faces)", m.poles, result.faces.len()),
                valid: if result.valid { "valid" } else { "INVALID" }.into(),
                cos: format!("{:.1e}", m.max_cos),
                k: profile.curvature(m.max_k),
            }
        }
        Outcome::Failed(e) => failed(format!("fails: {e}")),
        Outcome::TimedOut(limit) => {
            failed(format!("no result after {} s (killed)", limit.as_secs()))
        }
    }
}

fn failed(why: String) -> Theirs {
    Theirs {
        time: Err(why),
        poles: "—".into(),
        valid: "—".into(),
        cos: "—".into(),
        k: "—".into(),
    }
}

/// The ratio of their median to ours, or why there is none.
fn ratio(theirs: &Result<Vec<f64>, String>, ours: Spread) -> String {
    match theirs {
        Ok(t) => {
            let t = spread(t);
            format!(
                "**{:.1}×** (fastest {:.1}×)",
                t.median / ours.median,
                t.min / ours.min
            )
        }
        Err(_) => "—".into(),
    }
}

fn time_cell(t: &Result<Vec<f64>, String>) -> String {
    match t {
        Ok(s) => with_range(spread(s)),
        Err(e) => e.clone(),
    }
}

/// The table of the user's path.
pub fn section(program: Option<&Program>) {
    println!(
        "0. THE USER'S PATH: NURBS spine in → exact surface out (rmfsurf: NURBS data → G1 check + PH spline \
         approximation to {TOLERANCE:e} → rational RMF → sweep → one NURBS surface), beside OpenCascade \
         BRepOffsetAPI_MakePipeShell on the same NURBS data, its default Tol3d {TOLERANCE:e}. Median of \
         {RUNS} runs (OpenCascade {OCC_RUNS} on the issue spine, 6 on the others) [range], in {ROUNDS} \
         rounds of ours and theirs in turn; ratios of the medians (and of the fastest runs)."
    );
    println!("| spine | profile | segments (PH; route: spine pieces) | rmfsurf steps: {} (median ms) | rmfsurf total | OCC corrected Frenet | OCC / rmfsurf | OCC Frenet | OCC / rmfsurf |", STEPS.join(" / "));
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    let mut quality = Vec::new();
    for case in [issue_spine(), long_helix(), pipe_route()] {
        for profile in [
            Profile::Circle(case.circle),
            Profile::Line(case.line.0, case.line.1),
        ] {
            let curve = profile.curve();
            let options = ApproximationOptions::new(TOLERANCE);
            let mut steps: Vec<[f64; 5]> = Vec::with_capacity(RUNS);
            let mut built = None;
            let (mut cf, mut fr): (Option<Theirs>, Option<Theirs>) = (None, None);
            // Rounds of ours and theirs in turn, so that a change of the machine's load
            // falls on both.
            for _ in 0..ROUNDS {
                for _ in 0..RUNS / ROUNDS {
                    let (t, b) = match &case.wire {
                        Some(edges) => {
                            let start = built
                                .take()
                                .unwrap_or_else(|| our_path(&case.nurbs, &curve, &options).1);
                            wire_path(edges, &curve, &start)
                        }
                        None => our_path(&case.nurbs, &curve, &options),
                    };
                    steps.push(t);
                    built = Some(b);
                }
                let b = built.as_ref().expect("runs");
                let runs = if case.name.starts_with("issue") {
                    OCC_RUNS / ROUNDS
                } else {
                    2
                };
                for (mode, result) in [(Mode::CorrectedFrenet, &mut cf), (Mode::Frenet, &mut fr)] {
                    *result = Some(match (program, result.take()) {
                        (None, _) => failed("not run".into()),
                        (Some(p), None) => theirs(p, &case, profile, b, mode, 0.0, runs),
                        (Some(p), Some(mut so_far)) => {
                            // A failure or time-out is not repeated.
                            if let Ok(times) = &mut so_far.time {
                                match theirs(p, &case, profile, b, mode, 0.0, runs).time {
                                    Ok(more) => times.extend(more),
                                    Err(e) => so_far.time = Err(e),
                                }
                            }
                            so_far
                        }
                    });
                }
            }
            let (built, cf, fr) = (
                built.expect("runs"),
                cf.expect("rounds"),
                fr.expect("rounds"),
            );
            let totals: Vec<f64> = steps.iter().map(|s| s.iter().sum()).collect();
            let total = spread(&totals);
            let step_median =
                |k: usize| ms(spread(&steps.iter().map(|s| s[k]).collect::<Vec<_>>()).median);
            let per_step = match case.wire {
                Some(_) => format!(
                    "rmf_wire_sweep {} / NURBS out {}",
                    step_median(3),
                    step_median(4)
                ),
                None => (0..5).map(step_median).collect::<Vec<_>>().join(" / "),
            };
            println!(
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                case.name,
                profile.name(),
                built.segments,
                per_step,
                with_range(total),
                time_cell(&cf.time),
                ratio(&cf.time, total),
                time_cell(&fr.time),
                ratio(&fr.time, total),
            );
            let ours = measure(&built.surfaces, built.poles());
            let valid = program.map_or("—".to_string(), |p| built.valid(p));
            quality.push((case.name, profile, built.max_distance, ours, valid, cf, fr));
        }
    }
    println!(
        "Steps: NURBS in = rmf_nurbs_curve_create (validation, Bézier decomposition); approximate = \
         rmf_ph_spline_approximate (G1 check, PH spline); RMF = rmf_ph_rational_rmf; sweep = \
         rmf_sweep_surface; NURBS out = the surface's NURBS view (one clamped NURBS). The route: \
         rmf_wire_sweep on its 100 lines and arcs (exact cylinders and tori, lateral faces), then each \
         face's NURBS. The Rust calls behind each C entry point are timed. OpenCascade: \
         MakePipeShell's Build on the same spine (one B-spline edge; the route as the wire of its 100 \
         analytic lines and arcs) and profile placed at the spine's start; NurbsConvert of its faces is \
         not timed.\n"
    );
    println!("Quality, both surfaces measured by the same code (12 × 12 points per patch/face; validity: BRepCheck_Analyzer on OpenCascade's shape and on a face of our NURBS surface):");
    println!("| spine | profile | spine within | poles rmfsurf / OCC CF / OCC Frenet | valid rmfsurf / CF / Frenet | max \\|cos\\| rmfsurf / CF / Frenet | max \\|K\\| rmfsurf / CF / Frenet |");
    println!("| --- | --- | --- | --- | --- | --- | --- |");
    for (name, profile, distance, ours, valid, cf, fr) in quality {
        println!(
            "| {name} | {} | {distance:.1e} (tolerance {TOLERANCE:e}) | {} / {} / {} | {valid} / {} / {} | {:.1e} / {} / {} | {} / {} / {} |",
            profile.name(),
            ours.poles,
            cf.poles,
            fr.poles,
            cf.valid,
            fr.valid,
            ours.max_cos,
            cf.cos,
            fr.cos,
            profile.curvature(ours.max_k),
            cf.k,
            fr.k,
        );
    }
    println!(
        "OpenCascade's spine is the exact NURBS; ours is the PH spline within the tolerance of it \
         (its measured distance), on which the surface is exact: |cos| and |K| are those of our \
         rational RMF.\n"
    );
}

// ---------------------------------------------------------------------------------------
// Breaks

/// The piece of a curve on [a, b].
struct Piece<'a> {
    curve: &'a dyn ParametricCurve,
    domain: (f64, f64),
}

impl ParametricCurve for Piece<'_> {
    fn domain(&self) -> (f64, f64) {
        self.domain
    }

    fn point_derivative(&self, t: f64) -> rmfsurf::Result<(DVec3, DVec3)> {
        self.curve.point_derivative(t)
    }
}

/// Whether one PH cubic of the approximation is within `tolerance` on [a, b] (its first
/// trial is the whole interval).
fn one_segment(curve: &dyn ParametricCurve, a: f64, b: f64, tolerance: f64) -> bool {
    let options = ApproximationOptions {
        max_segments: 1,
        ..ApproximationOptions::new(tolerance)
    };
    let piece = Piece {
        curve,
        domain: (a, b),
    };
    ph_spline_approximate_with(&piece, &[a, b], &options).is_ok()
}

/// Segments of uniform halving from the initial breaks (the approximation before issue 19).
fn halving(curve: &dyn ParametricCurve, a: f64, b: f64, tolerance: f64) -> usize {
    if one_segment(curve, a, b, tolerance) {
        1
    } else {
        let m = 0.5 * (a + b);
        halving(curve, a, m, tolerance) + halving(curve, m, b, tolerance)
    }
}

/// Segments of the greedy farthest reach (each break as far as one cubic within the
/// tolerance reaches, found by bisection): the fewest any placement can have when every
/// subinterval of an interval within the tolerance is within it too.
fn greedy(curve: &dyn ParametricCurve, breaks: &[f64], tolerance: f64) -> usize {
    let mut count = 0;
    for w in breaks.windows(2) {
        let mut a = w[0];
        loop {
            count += 1;
            if one_segment(curve, a, w[1], tolerance) {
                break;
            }
            let (mut lo, mut hi) = (a, w[1]);
            while hi - lo > 1e-9 * (w[1] - w[0]) {
                let m = 0.5 * (lo + hi);
                if one_segment(curve, a, m, tolerance) {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            a = lo;
        }
    }
    count
}

/// The h⁴ bound: with e ≈ c(t)·h⁴ on short intervals (Theorem 10), a segment within the
/// tolerance covers at most tolerance^¼ of ∫ c^¼ dt, so no placement has fewer than
/// ∫ c^¼ dt / tolerance^¼ segments; ∫ c^¼ dt = Σ eₖ^¼ over the segments of a far finer
/// approximation (10⁴ times the tolerance: ten times the segments).
fn h4_bound(curve: &PiecewiseCurve, tolerance: f64) -> f64 {
    let fine = ph_spline_approximate(curve, curve.breaks(), tolerance * 1e-4).unwrap();
    fine.segment_distances
        .iter()
        .map(|e| e.powf(0.25))
        .sum::<f64>()
        / tolerance.powf(0.25)
}

pub fn breaks_section() {
    println!("0b. BREAKS: PH segments for the tolerance — ours (step control on the h⁴ law), uniform halving (before), the greedy farthest reach (optimal when feasibility is nested), and the h⁴ lower bound");
    println!("| spine | tolerance | ours | halving | greedy | h⁴ bound | ours / bound | kept distances / tolerance (min–max) | evaluations |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for case in [issue_spine(), long_helix(), pipe_route()] {
        let spine = case.nurbs.to_piecewise().unwrap();
        for tolerance in [1e-2, 1e-3, 1e-4, 1e-6] {
            let ours = ph_spline_approximate(&spine, spine.breaks(), tolerance).unwrap();
            let halved: usize = spine
                .breaks()
                .windows(2)
                .map(|w| halving(&spine, w[0], w[1], tolerance))
                .sum();
            let best = greedy(&spine, spine.breaks(), tolerance);
            let bound = h4_bound(&spine, tolerance);
            let (lo, hi) = ours
                .segment_distances
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(lo, hi), &e| {
                    (lo.min(e), hi.max(e))
                });
            let n = ours.spline.segments().len();
            println!(
                "| {} | {tolerance:.0e} | {n} | {halved} | {best} | {bound:.1} | {:.2} | {:.2}–{:.2} | {} |",
                case.name,
                n as f64 / bound,
                lo / tolerance,
                hi / tolerance,
                ours.evaluations,
            );
        }
    }
    println!(
        "The h⁴ bound holds in the limit of small segments; at coarse tolerances a segment may do \
         better than c·h⁴ and the greedy count falls below it. Straight runs take one segment each \
         whatever their length (e = 0), so the route's bound counts its bends.\n"
    );
}

// ---------------------------------------------------------------------------------------
// Poles

pub fn poles_section(program: Option<&Program>) {
    println!("0c. POLES on the issue spine, circle r 2: rmfsurf at its tolerance (spine distance) against OpenCascade corrected Frenet at the same Tol3d");
    println!("| tolerance | rmfsurf segments (h⁴ bound) | rmfsurf poles | fewest poles of the construction | rmfsurf max \\|cos\\| | OCC poles (faces) | OCC max \\|cos\\| | OCC valid | poles rmfsurf / OCC | fewest / OCC |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    let case = issue_spine();
    let spine = case.nurbs.to_piecewise().unwrap();
    let profile = Profile::Circle(case.circle);
    let curve = profile.curve();
    for tolerance in [1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8] {
        let (_, built) = our_path(&case.nurbs, &curve, &ApproximationOptions::new(tolerance));
        let poles = built.poles();
        // ∫ c^¼ dt once, from an approximation at 1e-10 (h4_bound at 1e-6).
        let bound = h4_bound(&spine, 1e-6) * (1e-6 / tolerance).powf(0.25);
        // (9·segments + 1) poles along the spine, one per pole of the profile around it.
        let fewest = (9 * bound.ceil() as usize + 1) * built.nurbs[0].pole_count_u();
        let ours: Measured = measure(&built.surfaces, poles);
        let occ = program.map_or_else(
            || failed("not run".into()),
            |p| {
                theirs(
                    p,
                    &case,
                    profile,
                    &built,
                    Mode::CorrectedFrenet,
                    tolerance,
                    1,
                )
            },
        );
        let theirs = occ
            .poles
            .split_whitespace()
            .next()
            .and_then(|w| w.parse::<f64>().ok());
        let ratio = |n: usize| theirs.map_or("—".into(), |t| format!("{:.2}", n as f64 / t));
        println!(
            "| {tolerance:.0e} | {} ({bound:.1}) | {poles} | {fewest} | {:.1e} | {} | {} | {} | {} | {} |",
            built.segments,
            ours.max_cos,
            occ.poles,
            occ.cos,
            occ.valid,
            ratio(poles),
            ratio(fewest),
        );
    }
    println!(
        "The exact profile surface (42) of a PH cubic under its rational RMF (frames of degree 6) has \
         degree 9 along the spine: 9 poles per piece (a PH segment, split where the RMF angle turns \
         by more than π/2), times the circle's 7 poles (three rational arcs of 120°), so (9·pieces + \
         1) × 7 poles. No placement of breaks has fewer segments than the h⁴ bound (section 0b), so \
         no exact sweep of this construction has fewer poles than the 'fewest' column. OpenCascade \
         approximates the sweep by one B-spline surface of its own degree and knots within Tol3d, \
         and its orthogonality stays at its best value (|cos| ≈ 2e-2) at every Tol3d.\n"
    );
}

// ---------------------------------------------------------------------------------------
// Scaling

/// The conical helix ((t/20 + 1) cos t, (t/20 + 1) sin t, 0.3 t) with its derivative.
fn spiral(t: f64) -> (DVec3, DVec3) {
    let r = t / 20.0 + 1.0;
    let (s, c) = t.sin_cos();
    (
        DVec3::new(r * c, r * s, 0.3 * t),
        DVec3::new(c / 20.0 - r * s, s / 20.0 + r * c, 0.3),
    )
}

/// Sizes of the scaling table (NURBS segments).
const SCALING_SIZES: [usize; 7] = [10, 100, 1_000, 3_000, 10_000, 30_000, 100_000];

/// Runs per size of the scaling table; the fastest counts (the machine is shared: a slower
/// run is another process's time, not the build's).
const SCALING_RUNS: usize = 5;

pub fn scaling_section() {
    println!("0d. SCALING of the user's path: the conical helix as a C¹ cubic NURBS of n segments (0.1 rad each), tolerance {TOLERANCE:e}, line profile; fastest of {SCALING_RUNS} runs (median beside it); memory by a counting allocator");
    println!("| NURBS segments | PH segments | time (fastest) | median | per PH segment (fastest) | approximation evaluations per PH segment | peak memory per segment | result per segment |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- |");
    let profile = Profile::Line(0.1, 0.4).curve();
    // rmf_ph_spline_approximate_with_options with the most segments a caller may allow.
    let options = ApproximationOptions {
        max_segments: ApproximationOptions::SEGMENT_LIMIT,
        ..ApproximationOptions::new(TOLERANCE)
    };
    let mut samples = Vec::new();
    for n in SCALING_SIZES {
        let nurbs = hermite_nurbs(spiral, 0.1 * n as f64, n);
        let mut totals = Vec::new();
        let mut segments = 0;
        for _ in 0..SCALING_RUNS {
            let (times, built) = our_path(&nurbs, &profile, &options);
            totals.push(times.iter().sum::<f64>());
            segments = built.segments;
        }
        let (peak, kept) = memory::measure(|| our_path(&nurbs, &profile, &options).1);
        // The work of the approximation, independent of the machine's load.
        let spine = nurbs.to_piecewise().unwrap();
        let evaluations = ph_spline_approximate_with(&spine, spine.breaks(), &options)
            .unwrap()
            .evaluations;
        let time = spread(&totals);
        println!(
            "| {n} | {segments} | {} ms | {} ms | {:.2} µs | {:.1} | {:.0} B | {:.0} B |",
            ms(time.min),
            ms(time.median),
            time.min / segments as f64 * 1e6,
            evaluations as f64 / segments as f64,
            peak as f64 / segments as f64,
            kept as f64 / segments as f64,
        );
        samples.push((n, (segments as f64).ln(), time.min.ln()));
    }
    let fit = |from: usize| {
        let s: Vec<(f64, f64)> = samples
            .iter()
            .filter(|(n, ..)| *n >= from)
            .map(|&(_, x, y)| (x, y))
            .collect();
        super::fitted_exponent(&s)
    };
    println!(
        "Fitted exponent of the fastest runs (time ∝ segments^p, least squares on log–log): p = {:.3} \
         on all sizes, {:.3} on 1,000 segments and more, {:.3} on 10,000 and more. Result: the spline, \
         frames, piecewise surface and NURBS surface kept; peak: the most allocated at once during the \
         build. No allocation per evaluation: capi/tests/no_allocation.rs.\n",
        fit(0),
        fit(1_000),
        fit(10_000),
    );
}
