//! `rmfsurf`: the command-line tool. Reads a JSON description of a sweep or a cone spline
//! surface, builds it with the library's exact rational constructions, prints the accuracy
//! figures and writes the requested files (STEP, VTK, OBJ, OpenSCAD, SVG, DXF, JSON).
//!
//! | module | does |
//! | --- | --- |
//! | [`args`] | the command line |
//! | [`json`] | reading JSON, bounded, with errors that name the field |
//! | [`schema`] | the input as serde reads it |
//! | [`job`] | the input checked and in the constructions' types |
//! | [`construct`] | the geometry: spines, frames, sweeps, cone splines, developments |
//! | [`summary`] | the accuracy figures |
//! | [`output`] | the files, by extension, rendered to memory |
//! | [`write`] | writing them all or nothing |
//!
//! Exit status: 0 when everything was written (the files, and the summary unless `-q`),
//! 1 for bad input, a failed construction or a file or the summary that could not be
//! written (then no file is left), 2 for a bad command line, 3 for an internal error.

#![warn(missing_docs)]

mod args;
mod construct;
mod job;
mod json;
mod output;
mod schema;
mod summary;
mod write;

use args::{Command, Input, Run};
use construct::{run_cone_spline, run_sheet, run_sweep, run_wire, Outcome};
use job::{Construction, Job};
use std::io::{self, Write};
use std::process::ExitCode;
use summary::Summary;

const HELP: &str = include_str!("help.txt");

/// Exit status for bad input, a failed construction or an output not written.
const FAILED: u8 = 1;
/// A bad command line.
const USAGE: u8 = 2;
/// A panic: a bug, caught so that it is reported like any failure (and never leaves files).
const INTERNAL: u8 = 3;

fn main() -> ExitCode {
    let status = match args::parse(std::env::args_os().skip(1)) {
        Ok(Command::Help) => print(HELP),
        Ok(Command::Version) => print(&format!("rmfsurf {}\n", env!("CARGO_PKG_VERSION"))),
        Ok(Command::Run(run)) => match std::panic::catch_unwind(|| execute(&run)) {
            Ok(result) => result,
            Err(_) => Err((
                INTERNAL,
                "internal error (the message above); please report it with the input".into(),
            )),
        },
        Err(message) => Err((USAGE, format!("{message}\nTry 'rmfsurf --help'."))),
    };
    match status {
        Ok(()) => ExitCode::SUCCESS,
        Err((code, message)) => {
            // Nothing is left to tell if standard error fails too.
            let _ = writeln!(io::stderr().lock(), "rmfsurf: {message}");
            ExitCode::from(code)
        }
    }
}

/// Writes `text` to standard output and flushes it: a full disk or a closed pipe is an
/// error, not a panic (as it would be with `print!`).
fn print(text: &str) -> Result<(), (u8, String)> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| (FAILED, format!("cannot write to standard output: {e}")))
}

/// Reads the job, from standard input or a file.
fn read_job(input: &Input) -> Result<Job, String> {
    match input {
        Input::Stdin => Job::read(io::stdin().lock(), "(stdin)"),
        Input::File(path) => {
            let file = std::fs::File::open(path)
                .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
            Job::read(file, &path.display().to_string())
        }
    }
    .map_err(|e| e.to_string())
}

/// Checks the destinations, reads, builds, measures, writes.
fn execute(run: &Run) -> Result<(), (u8, String)> {
    let failed = |message: String| (FAILED, message);
    let targets = write::check(run.destinations()).map_err(failed)?;
    let job = read_job(&run.input).map_err(failed)?;
    let outcome = build(run, &job).map_err(failed)?;
    let summary =
        Summary::of(&job, &outcome).map_err(|e| failed(format!("measuring the result: {e}")))?;
    let mut files = Vec::with_capacity(targets.len());
    for (path, format) in &run.outputs {
        let text = output::render(path, *format, &outcome, &summary, &job.mesh)
            .map_err(|e| failed(format!("--output {}: {e}", path.display())))?;
        files.push(text);
    }
    if let Some(path) = &run.curves {
        let text = output::render_curves(path, &outcome)
            .map_err(|e| failed(format!("--curves {}: {e}", path.display())))?;
        files.push(text);
    }
    let files: Vec<_> = targets.into_iter().zip(files).collect();
    let written = write::write_all(&files).map_err(failed)?;
    if !run.quiet {
        let mut text = summary.to_text();
        for (target, _) in &files {
            text.push_str(&format!("  wrote {}\n", target.shown.display()));
        }
        // The summary is one of the outputs: without it, no file is kept either.
        if let Err((_, e)) = print(&text) {
            return Err(failed(match written.undo() {
                Ok(()) => format!("{e}; no file was written"),
                Err(undo) => format!("{e}; {undo}"),
            }));
        }
    }
    written.keep();
    Ok(())
}

/// The construction the job asks for.
fn build(run: &Run, job: &Job) -> Result<Outcome, String> {
    if let Construction::Sweep(_) | Construction::Wire(_) = job.construction {
        if let Some((path, _)) = run.outputs.iter().find(|(_, f)| f.is_pattern()) {
            return Err(format!(
                "--output {}: flat patterns (.svg, .dxf) are made of developments: give a cone_spline or a sheet",
                path.display()
            ));
        }
    }
    Ok(match &job.construction {
        Construction::Sweep(sweep) => Outcome::Sweep(run_sweep(sweep).map_err(|e| e.to_string())?),
        Construction::Wire(wire) => Outcome::Wire(run_wire(wire).map_err(|e| e.to_string())?),
        Construction::ConeSpline(cone) => {
            Outcome::ConeSpline(run_cone_spline(cone).map_err(|e| e.to_string())?)
        }
        Construction::Sheet(sheet) => Outcome::Sheet(run_sheet(sheet).map_err(|e| e.to_string())?),
    })
}
