//! The error type of the geometry core: a kind, a message, and the context it was raised in.
//!
//! The message names the offending argument in the terms of the Rust API ("tangent 3",
//! "weights"); callers add context from the outside in ("segment 2", "spine") with
//! [`Error::context`] or [`ResultExt::context`], and [`Display`](fmt::Display) prints the
//! chain outermost first: `segment 2: tangent 3 is zero`. The C layer maps the kind to a
//! status code; nothing here knows about C.

use std::fmt;

/// What went wrong, independent of the message.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// NaN/Inf, zero or non-normalizable vectors, coincident points, too few items,
    /// malformed knot vectors, parameters outside a domain.
    InvalidInput,
    /// The data admit no interpolant or construction of the requested kind.
    NoSolution,
    /// An iteration did not reach its tolerance within its limits (or its work budget).
    NotConverged,
}

impl ErrorKind {
    fn describe(self) -> &'static str {
        match self {
            ErrorKind::InvalidInput => "invalid input",
            ErrorKind::NoSolution => "no solution",
            ErrorKind::NotConverged => "not converged",
        }
    }
}

/// Why a geometric construction failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    kind: ErrorKind,
    message: String,
    /// Outermost first.
    context: Vec<String>,
}

/// Result of a geometric construction.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// An error of `kind` with `message`.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Error {
            kind,
            message: message.into(),
            context: Vec::new(),
        }
    }

    /// An [`ErrorKind::InvalidInput`] error.
    pub fn invalid_input(message: impl Into<String>) -> Self {
        Self::new(ErrorKind::InvalidInput, message)
    }

    /// An [`ErrorKind::NoSolution`] error.
    pub fn no_solution(message: impl Into<String>) -> Self {
        Self::new(ErrorKind::NoSolution, message)
    }

    /// An [`ErrorKind::NotConverged`] error.
    pub fn not_converged(message: impl Into<String>) -> Self {
        Self::new(ErrorKind::NotConverged, message)
    }

    /// The kind of failure.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// Whether this is an error of `kind`.
    pub fn is(&self, kind: ErrorKind) -> bool {
        self.kind == kind
    }

    /// The innermost message, without context.
    pub fn reason(&self) -> &str {
        &self.message
    }

    /// The contexts, outermost first.
    pub fn contexts(&self) -> impl Iterator<Item = &str> {
        self.context.iter().map(String::as_str)
    }

    /// The same error, raised inside `context` (e.g. "segment 3").
    pub fn context(mut self, context: impl Into<String>) -> Self {
        self.context.insert(0, context.into());
        self
    }

    /// The message with its contexts, outermost first: `segment 3: tangent 1 is zero`.
    pub fn message(&self) -> String {
        let mut out = String::new();
        for c in &self.context {
            out.push_str(c);
            out.push_str(": ");
        }
        out.push_str(&self.message);
        out
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.kind.describe(), self.message())
    }
}

impl std::error::Error for Error {}

/// Context for the errors of a [`Result`].
pub trait ResultExt<T> {
    /// Adds `context` to the error, if any.
    fn context(self, context: impl Into<String>) -> Result<T>;
    /// Adds the context `f()` to the error, if any (computed only on failure).
    fn with_context<C: Into<String>>(self, f: impl FnOnce() -> C) -> Result<T>;
}

impl<T> ResultExt<T> for Result<T> {
    fn context(self, context: impl Into<String>) -> Result<T> {
        self.map_err(|e| e.context(context))
    }

    fn with_context<C: Into<String>>(self, f: impl FnOnce() -> C) -> Result<T> {
        self.map_err(|e| e.context(f()))
    }
}

/// `Err(Error::invalid_input(format!(..)))`.
macro_rules! invalid {
    ($($arg:tt)*) => { Err($crate::Error::invalid_input(format!($($arg)*))) };
}
/// `Err(Error::no_solution(format!(..)))`.
macro_rules! no_solution {
    ($($arg:tt)*) => { Err($crate::Error::no_solution(format!($($arg)*))) };
}
pub(crate) use {invalid, no_solution};

/// Refuses a tolerance below one rounding of coordinates up to `largest`, which no
/// construction can measure, let alone reach; `whose` completes "at … coordinates" ("the
/// curve's", "the profile's").
pub(crate) fn check_resolution(tolerance: f64, largest: f64, whose: &str) -> Result<()> {
    let rounding = f64::EPSILON * largest;
    if tolerance < rounding {
        return Err(below_resolution(tolerance, largest, whose));
    }
    Ok(())
}

/// The refusal of [`check_resolution`].
pub(crate) fn below_resolution(tolerance: f64, largest: f64, whose: &str) -> Error {
    Error::invalid_input(format!(
        "tolerance = {tolerance:.3e} is below what f64 resolves at {whose} coordinates \
         (up to {largest:.3e}: one rounding is {:.3e})",
        f64::EPSILON * largest
    ))
}

/// A number as messages print it: at most six significant digits, in plain form between
/// 1e-4 and 1e6 and as `1.5e-200` outside (Rust's `{}` writes 1e200 with 200 digits). The
/// one formatter of numbers in messages, of the geometry and of the C layer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !x.is_finite() || x == 0.0 {
            return write!(f, "{x}");
        }
        let magnitude = x.abs();
        if (1e-4..1e6).contains(&magnitude) {
            // Six significant digits, trailing zeros dropped.
            let decimals = (5 - magnitude.log10().floor() as i32).max(0) as usize;
            let text = format!("{x:.decimals$}");
            let text = if text.contains('.') {
                text.trim_end_matches('0').trim_end_matches('.')
            } else {
                &text
            };
            write!(f, "{text}")
        } else {
            let shortest = format!("{x:e}");
            let digits = shortest
                .split('e')
                .next()
                .unwrap_or("")
                .trim_start_matches('-');
            if digits.chars().filter(char::is_ascii_digit).count() <= 6 {
                return write!(f, "{shortest}");
            }
            let text = format!("{x:.5e}");
            let (mantissa, exponent) = text.split_once('e').expect("exponent form");
            let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
            write!(f, "{mantissa}e{exponent}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_print_short() {
        let cases = [
            (1e200, "1e200"),
            (-2.5e-320, "-2.5e-320"),
            (0.1, "0.1"),
            (2.176412345678, "2.17641"),
            (123456.7, "123457"),
            (0.5, "0.5"),
            (0.0, "0"),
            (1e-5, "1e-5"),
            (4e-320, "4e-320"),
            (f64::NAN, "NaN"),
        ];
        for (x, expected) in cases {
            assert_eq!(Num(x).to_string(), expected, "{x:e}");
        }
    }

    #[test]
    fn context_reads_outermost_first() {
        let e: Result<()> = Err(Error::no_solution("no real root"));
        let e = e.context("segment 3").context("spine").unwrap_err();
        assert_eq!(e.message(), "spine: segment 3: no real root");
        assert_eq!(e.to_string(), "no solution: spine: segment 3: no real root");
        assert_eq!(e.reason(), "no real root");
        assert!(e.is(ErrorKind::NoSolution));
        assert_eq!(e.contexts().collect::<Vec<_>>(), ["spine", "segment 3"]);
    }
}
