//! The command line: `rmfsurf [OPTIONS] INPUT.json` (see `--help`).

use crate::output::{Format, EXTENSIONS};
use std::path::PathBuf;

#[derive(Debug, PartialEq)]
pub enum Command {
    Help,
    Version,
    Run(Run),
}

#[derive(Debug, PartialEq)]
pub struct Run {
    /// The JSON input; `-` reads standard input.
    pub input: String,
    pub outputs: Vec<(PathBuf, Format)>,
    /// STEP file for the curves (spine, or the strip's boundaries).
    pub curves: Option<PathBuf>,
    pub quiet: bool,
}

/// Parses the arguments after the program name; the error is a usage message.
pub fn parse(args: impl IntoIterator<Item = String>) -> Result<Command, String> {
    let mut args = args.into_iter();
    let mut input = None;
    let mut run = Run {
        input: String::new(),
        outputs: Vec::new(),
        curves: None,
        quiet: false,
    };
    while let Some(arg) = args.next() {
        let mut value = |option: &str| {
            args.next()
                .ok_or_else(|| format!("{option} needs a file name"))
        };
        match arg.as_str() {
            "-h" | "--help" => return Ok(Command::Help),
            "-V" | "--version" => return Ok(Command::Version),
            "-q" | "--quiet" => run.quiet = true,
            "-o" | "--output" => {
                let path = PathBuf::from(value(&arg)?);
                let format = Format::of(&path).ok_or_else(|| {
                    format!(
                        "{arg} {}: unknown format; use one of {EXTENSIONS}",
                        path.display()
                    )
                })?;
                run.outputs.push((path, format));
            }
            "--curves" => {
                let path = PathBuf::from(value(&arg)?);
                if Format::of(&path) != Some(Format::Step) {
                    return Err(format!(
                        "--curves {}: curves are written as STEP (.step or .stp)",
                        path.display()
                    ));
                }
                run.curves = Some(path);
            }
            option if option.starts_with('-') && option != "-" => {
                return Err(format!("unknown option {option}"))
            }
            _ if input.is_some() => return Err(format!("more than one input file ({arg})")),
            _ => input = Some(arg),
        }
    }
    run.input = input.ok_or("no input file given")?;
    Ok(Command::Run(run))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_str(args: &[&str]) -> Result<Command, String> {
        parse(args.iter().map(|s| s.to_string()))
    }

    #[test]
    fn options_and_errors() {
        let Command::Run(run) =
            parse_str(&["in.json", "-o", "a.step", "--output", "b.SCAD", "-q"]).unwrap()
        else {
            panic!("a run")
        };
        assert_eq!(run.input, "in.json");
        assert_eq!(run.outputs[1].1, Format::Scad);
        assert!(run.quiet);
        assert_eq!(parse_str(&["-h"]), Ok(Command::Help));
        assert!(parse_str(&["in.json", "-o", "a.xyz"])
            .unwrap_err()
            .contains("unknown format"));
        assert!(parse_str(&["in.json", "-o"])
            .unwrap_err()
            .contains("needs a file name"));
        assert!(parse_str(&[]).unwrap_err().contains("no input"));
        assert!(parse_str(&["a.json", "b.json"])
            .unwrap_err()
            .contains("more than one"));
        assert!(parse_str(&["a.json", "--curves", "c.vtp"])
            .unwrap_err()
            .contains("STEP"));
        assert!(parse_str(&["a.json", "--frobnicate"])
            .unwrap_err()
            .contains("unknown option"));
    }
}
