//! The command line: `rmfsurf [OPTIONS] INPUT.json` (see `--help`). Arguments are taken as
//! `OsString`s, so that file names that are not UTF-8 are written as given.

use crate::output::{Format, EXTENSIONS};
use std::ffi::{OsStr, OsString};
use std::path::PathBuf;

#[derive(Debug, PartialEq)]
pub enum Command {
    Help,
    Version,
    Run(Run),
}

/// Where the JSON comes from.
#[derive(Debug, PartialEq)]
pub enum Input {
    /// `-`
    Stdin,
    File(PathBuf),
}

#[derive(Debug, PartialEq)]
pub struct Run {
    pub input: Input,
    pub outputs: Vec<(PathBuf, Format)>,
    /// STEP file for the curves (spine, or the strip's boundaries).
    pub curves: Option<PathBuf>,
    pub quiet: bool,
}

impl Run {
    /// Every file to write with the option that named it, in the order of the outputs.
    pub fn destinations(&self) -> Vec<(&'static str, PathBuf)> {
        self.outputs
            .iter()
            .map(|(path, _)| ("--output", path.clone()))
            .chain(self.curves.iter().map(|path| ("--curves", path.clone())))
            .collect()
    }
}

/// Whether `arg` looks like an option (`-x`, `--xyz`; `-` alone is standard input).
fn is_option(arg: &OsStr) -> bool {
    arg.as_encoded_bytes().first() == Some(&b'-') && arg != "-"
}

/// Parses the arguments after the program name; the error is a usage message.
pub fn parse(args: impl IntoIterator<Item = OsString>) -> Result<Command, String> {
    let mut args = args.into_iter();
    let mut input = None;
    let mut outputs = Vec::new();
    let mut curves = None;
    let mut quiet = false;
    while let Some(arg) = args.next() {
        let shown = arg.to_string_lossy().into_owned();
        let mut value = || {
            args.next()
                .map(PathBuf::from)
                .ok_or_else(|| format!("{shown} needs a file name"))
        };
        match arg.to_str() {
            Some("-h" | "--help") => return Ok(Command::Help),
            Some("-V" | "--version") => return Ok(Command::Version),
            Some("-q" | "--quiet") => quiet = true,
            Some("-o" | "--output") => {
                let path = value()?;
                let format = Format::of(&path).ok_or_else(|| {
                    format!(
                        "{shown} {}: unknown format; use one of {EXTENSIONS}",
                        path.display()
                    )
                })?;
                outputs.push((path, format));
            }
            Some("--curves") => {
                let path = value()?;
                if Format::of(&path) != Some(Format::Step) {
                    return Err(format!(
                        "--curves {}: curves are written as STEP (.step or .stp)",
                        path.display()
                    ));
                }
                if curves.replace(path).is_some() {
                    return Err("--curves given twice: curves go to one file".into());
                }
            }
            _ if is_option(&arg) => return Err(format!("unknown option {shown}")),
            _ if input.is_some() => return Err(format!("more than one input file ({shown})")),
            _ if arg == "-" => input = Some(Input::Stdin),
            _ => input = Some(Input::File(PathBuf::from(arg))),
        }
    }
    Ok(Command::Run(Run {
        input: input.ok_or("no input file given")?,
        outputs,
        curves,
        quiet,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::ffi::OsStringExt;

    fn parse_str(args: &[&str]) -> Result<Command, String> {
        parse(args.iter().map(OsString::from))
    }

    #[test]
    fn options_and_errors() {
        let Command::Run(run) =
            parse_str(&["in.json", "-o", "a.step", "--output", "b.SCAD", "-q"]).unwrap()
        else {
            panic!("a run")
        };
        assert_eq!(run.input, Input::File("in.json".into()));
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
        assert!(
            parse_str(&["-", "--curves", "a.step", "--curves", "b.step"])
                .unwrap_err()
                .contains("--curves given twice")
        );
        assert!(parse_str(&["a.json", "--frobnicate"])
            .unwrap_err()
            .contains("unknown option"));
        let Command::Run(run) = parse_str(&["-", "-o", "a.step", "--curves", "c.stp"]).unwrap()
        else {
            panic!("a run")
        };
        assert_eq!(run.input, Input::Stdin);
        assert_eq!(
            run.destinations(),
            [("--output", "a.step".into()), ("--curves", "c.stp".into())]
        );
    }

    #[test]
    fn file_names_need_not_be_utf8() {
        let name = OsString::from_vec(b"caf\xe9.step".to_vec());
        let input = OsString::from_vec(b"\xff.json".to_vec());
        let Command::Run(run) = parse([input.clone(), "-o".into(), name.clone()]).unwrap() else {
            panic!("a run")
        };
        assert_eq!(run.input, Input::File(input.into()));
        assert_eq!(run.outputs, [(name.into(), Format::Step)]);
        let option = OsString::from_vec(b"--\xff".to_vec());
        assert!(parse([option])
            .unwrap_err()
            .starts_with("unknown option --"));
    }
}
