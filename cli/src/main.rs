//! `rmfsurf`: the command-line tool. Reads a JSON description of a sweep or a cone spline
//! surface, builds it with the library's exact rational constructions, prints the accuracy
//! figures and writes the requested files (STEP, VTK, OBJ, OpenSCAD, SVG, DXF, JSON).
//!
//! | module | does |
//! | --- | --- |
//! | [`args`] | the command line |
//! | [`json`] | reading JSON with errors that name the field |
//! | [`job`] | the input schema, read into typed values |
//! | [`construct`] | the geometry: spines, frames, sweeps, cone splines, developments |
//! | [`summary`] | the accuracy figures |
//! | [`output`] | formats by extension; all-or-nothing writing |

#![warn(missing_docs)]

mod args;
mod construct;
mod job;
mod json;
mod output;
mod summary;

use args::{Command, Run};
use construct::{run_cone_spline, run_sheet, run_sweep, run_wire, Outcome};
use job::{Construction, Job};
use json::Document;
use std::io::Read;
use std::process::ExitCode;
use summary::Summary;

const HELP: &str = include_str!("help.txt");

/// Exit status for bad input or a failed construction (2 is a bad command line).
const FAILED: u8 = 1;
const USAGE: u8 = 2;

fn main() -> ExitCode {
    match args::parse(std::env::args().skip(1)) {
        Ok(Command::Help) => {
            print!("{HELP}");
            ExitCode::SUCCESS
        }
        Ok(Command::Version) => {
            println!("rmfsurf {}", env!("CARGO_PKG_VERSION"));
            ExitCode::SUCCESS
        }
        Ok(Command::Run(run)) => match execute(&run) {
            Ok(()) => ExitCode::SUCCESS,
            Err(message) => {
                eprintln!("rmfsurf: {message}");
                ExitCode::from(FAILED)
            }
        },
        Err(message) => {
            eprintln!("rmfsurf: {message}\nTry 'rmfsurf --help'.");
            ExitCode::from(USAGE)
        }
    }
}

fn read_input(input: &str) -> Result<String, String> {
    if input == "-" {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| format!("cannot read standard input: {e}"))?;
        Ok(text)
    } else {
        std::fs::read_to_string(input).map_err(|e| format!("cannot read {input}: {e}"))
    }
}

/// Reads, builds, measures, writes.
fn execute(run: &Run) -> Result<(), String> {
    let source = if run.input == "-" {
        "(stdin)"
    } else {
        &run.input
    };
    let document = Document::parse(&read_input(&run.input)?, source).map_err(|e| e.to_string())?;
    let job = Job::read(&document.root()).map_err(|e| e.to_string())?;
    if let Construction::Sweep(_) | Construction::Wire(_) = job.construction {
        if let Some((path, _)) = run.outputs.iter().find(|(_, f)| f.is_pattern()) {
            return Err(format!(
                "--output {}: flat patterns (.svg, .dxf) are made of developments: give a cone_spline or a sheet",
                path.display()
            ));
        }
    }
    let outcome = match &job.construction {
        Construction::Sweep(sweep) => Outcome::Sweep(run_sweep(sweep).map_err(|e| e.to_string())?),
        Construction::Wire(wire) => Outcome::Wire(run_wire(wire).map_err(|e| e.to_string())?),
        Construction::ConeSpline(cone) => {
            Outcome::ConeSpline(run_cone_spline(cone).map_err(|e| e.to_string())?)
        }
        Construction::Sheet(sheet) => Outcome::Sheet(run_sheet(sheet).map_err(|e| e.to_string())?),
    };
    let summary = Summary::of(&job, &outcome).map_err(|e| format!("measuring the result: {e}"))?;
    let mut files = Vec::new();
    for (path, format) in &run.outputs {
        let text = output::render(path, *format, &outcome, &summary, &job.mesh)
            .map_err(|e| format!("--output {}: {e}", path.display()))?;
        files.push((path.clone(), text));
    }
    if let Some(path) = &run.curves {
        let text = output::render_curves(path, &outcome)
            .map_err(|e| format!("--curves {}: {e}", path.display()))?;
        files.push((path.clone(), text));
    }
    output::write_all(&files)?;
    if !run.quiet {
        print!("{}", summary.to_text());
        for (path, _) in &files {
            println!("  wrote {}", path.display());
        }
    }
    Ok(())
}
