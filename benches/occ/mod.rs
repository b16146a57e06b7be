//! OpenCascade's side of the benchmark: `pipe_shell.cpp` (its input and output formats are
//! documented there), built once with the system's C++ compiler and run as a child process
//! with a time limit, so that a sweep that hangs is reported instead of stopping the table.

use rmfsurf::glam::DVec3;
use rmfsurf::{NurbsCurve, NurbsSurface, PiecewiseCurve};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The spine as OpenCascade is given it.
pub enum Spine<'a> {
    /// One rational Bézier edge per segment (a wire of edges).
    Edges(&'a PiecewiseCurve),
    /// One B-spline edge: the user's NURBS data as they are.
    Nurbs(&'a NurbsCurve),
    /// A wire of lines and circular arcs, as CAD users draw them.
    Wire(&'a [WireEdge]),
}

/// An analytic edge of a wire.
#[derive(Clone, Copy)]
pub enum WireEdge {
    Line(DVec3, DVec3),
    /// Start, a point on the arc, end.
    Arc(DVec3, DVec3, DVec3),
}

/// BRepOffsetAPI_MakePipeShell's trihedron.
#[derive(Clone, Copy, PartialEq)]
pub enum Mode {
    CorrectedFrenet,
    Frenet,
}

impl Mode {
    fn word(self) -> &'static str {
        match self {
            Mode::CorrectedFrenet => "corrected_frenet",
            Mode::Frenet => "frenet",
        }
    }
}

/// One sweep to run.
pub struct Request<'a> {
    pub spine: Spine<'a>,
    /// The profile line of the program's input ("profile circle …" or "profile line …").
    pub profile: String,
    pub mode: Mode,
    /// Tol3d of SetTolerance; 0 keeps OpenCascade's default (1e-4).
    pub tolerance: f64,
    pub repeats: usize,
    /// The child is killed after this long.
    pub time_limit: Duration,
}

/// A finished sweep: the seconds of each build, BRepCheck_Analyzer's verdict, the faces.
pub struct Sweep {
    pub times: Vec<f64>,
    pub valid: bool,
    pub faces: Vec<NurbsSurface>,
}

pub enum Outcome {
    Done(Sweep),
    /// MakePipeShell (or the program) failed; its message.
    Failed(String),
    /// Still running at the time limit (killed).
    TimedOut(Duration),
}

/// The built program.
pub struct Program(PathBuf);

impl Program {
    /// Builds `pipe_shell.cpp` against the system's OpenCascade.
    pub fn build() -> Result<Self, String> {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let out = root.join("target").join("occ_pipe_shell");
        let status = Command::new("c++")
            .args([
                "-O2",
                "-std=c++17",
                "-w",
                "-isystem",
                "/usr/include/opencascade",
            ])
            .arg(root.join("benches/occ/pipe_shell.cpp"))
            .arg("-o")
            .arg(&out)
            .args([
                "-lTKOffset",
                "-lTKFillet",
                "-lTKBool",
                "-lTKBO",
                "-lTKShHealing",
                "-lTKPrim",
                "-lTKTopAlgo",
                "-lTKGeomAlgo",
                "-lTKBRep",
                "-lTKGeomBase",
                "-lTKG3d",
                "-lTKG2d",
                "-lTKMath",
                "-lTKernel",
            ])
            .status()
            .map_err(|e| format!("no C++ compiler ({e})"))?;
        if status.success() {
            Ok(Self(out))
        } else {
            Err("building benches/occ/pipe_shell.cpp failed (OpenCascade dev packages: scripts/bench installs them)".into())
        }
    }

    /// Runs one sweep.
    pub fn sweep(&self, request: &Request) -> Outcome {
        let mut input = spine_input(&request.spine);
        input += &request.profile;
        input += &format!(
            "mode {}\ntolerance {}\nrepeats {}\n",
            request.mode.word(),
            request.tolerance,
            request.repeats
        );
        match self.run(&input, request.time_limit) {
            Ok(Some(text)) => parse_sweep(&text).map_or_else(Outcome::Failed, Outcome::Done),
            Ok(None) => Outcome::TimedOut(request.time_limit),
            Err(e) => Outcome::Failed(e),
        }
    }

    /// BRepCheck_Analyzer on a face made of `surface` (an rmfsurf result): the check the
    /// program applies to its own sweeps.
    pub fn check(&self, surface: &NurbsSurface) -> Result<bool, String> {
        let text = self
            .run(&check_input(surface), Duration::from_secs(60))?
            .ok_or("the check timed out")?;
        let mut words = Words(text.split_whitespace());
        words.skip();
        Ok(words.number()? == 1.0)
    }

    /// The program's output for `input`; `None` if it was still running at `limit`.
    fn run(&self, input: &str, limit: Duration) -> Result<Option<String>, String> {
        let mut child = Command::new(&self.0)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| e.to_string())?;
        let mut stdin = child.stdin.take().expect("piped stdin");
        let text = input.to_string();
        // Written from a thread: a large input must not block on a full pipe while the
        // child is not reading yet.
        let writer = std::thread::spawn(move || stdin.write_all(text.as_bytes()));
        let mut stdout = child.stdout.take().expect("piped stdout");
        let reader = std::thread::spawn(move || {
            let mut s = String::new();
            std::io::Read::read_to_string(&mut stdout, &mut s).map(|_| s)
        });
        let start = Instant::now();
        loop {
            match child.try_wait().map_err(|e| e.to_string())? {
                Some(status) => {
                    let _ = writer.join();
                    let out = reader.join().map_err(|_| "reader panicked")?;
                    let out = out.map_err(|e| e.to_string())?;
                    if status.success() {
                        return Ok(Some(out));
                    }
                    let mut err = String::new();
                    if let Some(mut e) = child.stderr.take() {
                        let _ = std::io::Read::read_to_string(&mut e, &mut err);
                    }
                    return Err(err.trim().to_string());
                }
                None if start.elapsed() > limit => {
                    // Only the child this function started.
                    let _ = child.kill();
                    let _ = child.wait();
                    return Ok(None);
                }
                None => std::thread::sleep(Duration::from_millis(5)),
            }
        }
    }
}

fn spine_input(spine: &Spine) -> String {
    match spine {
        Spine::Edges(curve) => {
            let mut input = format!("segments {}\n", curve.segments().len());
            for segment in curve.segments() {
                input += &format!("{}\n", segment.degree());
                for (p, w) in segment.poles().zip(segment.weights()) {
                    input += &format!("{:?} {:?} {:?} {:?}\n", p.x, p.y, p.z, w);
                }
            }
            input
        }
        Spine::Wire(edges) => {
            let p = |v: &DVec3| format!("{:?} {:?} {:?}", v.x, v.y, v.z);
            let mut input = format!("wire {}\n", edges.len());
            for e in edges.iter() {
                input += &match e {
                    WireEdge::Line(a, b) => format!("line {} {}\n", p(a), p(b)),
                    WireEdge::Arc(a, m, b) => format!("arc {} {} {}\n", p(a), p(m), p(b)),
                };
            }
            input
        }
        Spine::Nurbs(nurbs) => {
            let mut input = format!(
                "nurbs {} {} {}\n",
                nurbs.degree(),
                nurbs.poles().len(),
                nurbs.knots().len()
            );
            for k in nurbs.knots() {
                input += &format!("{k:?} ");
            }
            input += "\n";
            for (p, w) in nurbs.poles().iter().zip(nurbs.weights()) {
                input += &format!("{:?} {:?} {:?} {:?}\n", p.x, p.y, p.z, w);
            }
            input
        }
    }
}

fn check_input(s: &NurbsSurface) -> String {
    let mut input = format!(
        "check {} {} {} {}\n",
        s.degree_u(),
        s.degree_v(),
        s.pole_count_u(),
        s.pole_count_v()
    );
    for knots in [s.knots_u(), s.knots_v()] {
        input += &format!("{}", knots.len());
        for k in knots.iter() {
            input += &format!(" {k:?}");
        }
        input += "\n";
    }
    for (p, w) in s.poles().iter().zip(s.weights()) {
        input += &format!("{:?} {:?} {:?} {:?}\n", p.x, p.y, p.z, w);
    }
    input
}

/// The words of the program's output, read as numbers (labels skipped by the caller).
struct Words<'a>(std::str::SplitWhitespace<'a>);

impl Words<'_> {
    fn number(&mut self) -> Result<f64, String> {
        let word = self.0.next().ok_or("truncated OpenCascade output")?;
        word.parse().map_err(|e| format!("{word}: {e}"))
    }

    fn count(&mut self) -> Result<usize, String> {
        Ok(self.number()? as usize)
    }

    fn numbers(&mut self, n: usize) -> Result<Vec<f64>, String> {
        (0..n).map(|_| self.number()).collect()
    }

    fn skip(&mut self) {
        self.0.next();
    }
}

/// Reads a sweep's output (format in pipe_shell.cpp).
fn parse_sweep(text: &str) -> Result<Sweep, String> {
    let mut words = Words(text.split_whitespace());
    words.skip();
    let repeats = words.count()?;
    let times = words
        .numbers(repeats)?
        .into_iter()
        .map(|ms| ms / 1e3)
        .collect();
    words.skip();
    let valid = words.number()? == 1.0;
    words.skip();
    let faces = words.count()?;
    let mut surfaces = Vec::with_capacity(faces);
    for _ in 0..faces {
        let (du, dv, nu, nv) = (
            words.count()?,
            words.count()?,
            words.count()?,
            words.count()?,
        );
        let knot_count = words.count()?;
        let knots_u = words.numbers(knot_count)?;
        let knot_count = words.count()?;
        let knots_v = words.numbers(knot_count)?;
        let homogeneous = words.numbers(4 * nu * nv)?;
        let poles = homogeneous
            .chunks(4)
            .map(|c| DVec3::new(c[0], c[1], c[2]))
            .collect();
        let weights = homogeneous.chunks(4).map(|c| c[3]).collect();
        let surface = NurbsSurface::new(du, dv, nu, nv, poles, Some(weights), knots_u, knots_v)
            .map_err(|e| e.to_string())?;
        surfaces.push(surface);
    }
    Ok(Sweep {
        times,
        valid,
        faces: surfaces,
    })
}
