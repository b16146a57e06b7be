//! The error type of the geometry core.
//!
//! Each variant carries a message that names the offending argument, so that the C layer
//! can hand it to the caller unchanged (`rmf_last_error`). The C status code of each
//! variant is fixed in `ffi::status`.

use std::fmt;

/// Why a geometric construction failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Error {
    /// NaN/Inf, zero or non-normalizable vectors, coincident points, too few items,
    /// malformed knot vectors, parameters outside a domain.
    InvalidInput(String),
    /// The data admit no interpolant or construction of the requested kind.
    NoSolution(String),
    /// An iteration did not reach its tolerance within its limits.
    NotConverged(String),
}

/// Result of a geometric construction.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// The message, without the kind.
    pub fn message(&self) -> &str {
        match self {
            Error::InvalidInput(m) | Error::NoSolution(m) | Error::NotConverged(m) => m,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self {
            Error::InvalidInput(_) => "invalid input",
            Error::NoSolution(_) => "no solution",
            Error::NotConverged(_) => "not converged",
        };
        write!(f, "{kind}: {}", self.message())
    }
}

impl std::error::Error for Error {}

/// Shorthand for `Err(Error::InvalidInput(..))` with a formatted message.
macro_rules! invalid {
    ($($arg:tt)*) => { Err($crate::Error::InvalidInput(format!($($arg)*))) };
}
pub(crate) use invalid;
