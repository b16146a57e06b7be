//! Status codes, the thread-local last-error message, and the library version.

use libc::c_char;
use rmfsurf::{Error, ErrorKind};
use std::cell::RefCell;
use std::ffi::CString;

/// Result of every rmf_* function that is not a pure accessor.
///
/// The values are fixed and never reused; new codes are added at the end.
/// \ingroup rmf_foundation
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(clippy::enum_variant_names)]
pub enum RmfStatus {
    /// Success.
    RmfOk = 0,
    /// A required pointer argument was NULL.
    RmfErrorNullPointer = 1,
    /// NaN/Inf, zero or non-normalizable vectors, coincident points, too few items,
    /// malformed counts or knot vectors, parameters outside a domain.
    RmfErrorInvalidInput = 2,
    /// The data admit no interpolant or construction of that kind.
    RmfErrorNoSolution = 3,
    /// A tolerance was not reached within the iteration limits.
    RmfErrorNotConverged = 4,
    /// A caller buffer is too small; the needed size was written where documented.
    RmfErrorBufferTooSmall = 5,
    /// An internal error (a caught panic); please report it.
    RmfErrorInternal = 6,
    /// A file or stream could not be written (the message names the path and says why).
    RmfErrorIo = 7,
}

/// All statuses with their C names, in value order.
const STATUS_NAMES: [(RmfStatus, &str); 8] = [
    (RmfStatus::RmfOk, "RMF_OK\0"),
    (RmfStatus::RmfErrorNullPointer, "RMF_ERROR_NULL_POINTER\0"),
    (RmfStatus::RmfErrorInvalidInput, "RMF_ERROR_INVALID_INPUT\0"),
    (RmfStatus::RmfErrorNoSolution, "RMF_ERROR_NO_SOLUTION\0"),
    (RmfStatus::RmfErrorNotConverged, "RMF_ERROR_NOT_CONVERGED\0"),
    (
        RmfStatus::RmfErrorBufferTooSmall,
        "RMF_ERROR_BUFFER_TOO_SMALL\0",
    ),
    (RmfStatus::RmfErrorInternal, "RMF_ERROR_INTERNAL\0"),
    (RmfStatus::RmfErrorIo, "RMF_ERROR_IO\0"),
];

impl From<&Error> for RmfStatus {
    fn from(e: &Error) -> Self {
        match e.kind() {
            ErrorKind::InvalidInput => RmfStatus::RmfErrorInvalidInput,
            ErrorKind::NoSolution => RmfStatus::RmfErrorNoSolution,
            ErrorKind::NotConverged => RmfStatus::RmfErrorNotConverged,
            // A kind the core gains later is refused input until it has a status of its own.
            _ => RmfStatus::RmfErrorInvalidInput,
        }
    }
}

/// Major version of the library; equals the first number of rmf_version().
/// \ingroup rmf_foundation
pub const RMF_VERSION_MAJOR: u32 = 0;
/// Minor version of the library.
/// \ingroup rmf_foundation
pub const RMF_VERSION_MINOR: u32 = 2;
/// Patch version of the library.
/// \ingroup rmf_foundation
pub const RMF_VERSION_PATCH: u32 = 0;
/// The ABI number: the N of the shared library's SONAME librmfsurf.so.N, raised on every
/// ABI break (0.1.0 had no SONAME; 0.2.0 is ABI 1).
/// \ingroup rmf_foundation
pub const RMF_ABI_VERSION: u32 = 1;

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// Records `message` as the calling thread's last error (interior NULs are replaced).
pub(crate) fn set_last_error(message: &str) {
    let c = CString::new(message.replace('\0', " ")).expect("NULs were replaced");
    LAST_ERROR.with(|cell| *cell.borrow_mut() = c);
}

/// The message of the last failing call on the calling thread.
///
/// @return A NUL-terminated UTF-8 string, never NULL ("" if nothing has failed yet on this
///         thread). Owned by the library: do not free it; it stays valid until the next
///         failing rmf_* call on the same thread.
/// \since 0.1
/// \ingroup rmf_foundation
#[no_mangle]
pub extern "C" fn rmf_last_error() -> *const c_char {
    LAST_ERROR.with(|cell| cell.borrow().as_ptr())
}

/// The library version as "MAJOR.MINOR.PATCH"; agrees with RMF_VERSION_MAJOR/MINOR/PATCH
/// of the header the program was compiled with when the library matches it.
///
/// @return A static NUL-terminated string, never NULL; do not free it.
/// \since 0.1
/// \ingroup rmf_foundation
#[no_mangle]
pub extern "C" fn rmf_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// The C name of a status code, e.g. "RMF_ERROR_INVALID_INPUT".
///
/// @param[in] status Any integer; values that are no RmfStatus give "RMF_UNKNOWN_STATUS".
/// @return A static NUL-terminated string, never NULL; do not free it.
/// \since 0.1
/// \ingroup rmf_foundation
#[no_mangle]
pub extern "C" fn rmf_status_name(status: u32) -> *const c_char {
    let name = STATUS_NAMES
        .iter()
        .find(|(s, _)| *s as u32 == status)
        .map_or("RMF_UNKNOWN_STATUS\0", |(_, n)| n);
    name.as_ptr().cast()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::CStr;

    #[test]
    fn version_constants_match_the_package_version() {
        assert_eq!(
            env!("CARGO_PKG_VERSION_MAJOR").parse::<u32>().unwrap(),
            RMF_VERSION_MAJOR
        );
        assert_eq!(
            env!("CARGO_PKG_VERSION_MINOR").parse::<u32>().unwrap(),
            RMF_VERSION_MINOR
        );
        assert_eq!(
            env!("CARGO_PKG_VERSION_PATCH").parse::<u32>().unwrap(),
            RMF_VERSION_PATCH
        );
        let v = unsafe { CStr::from_ptr(rmf_version()) }.to_str().unwrap();
        assert_eq!(v, env!("CARGO_PKG_VERSION"));
    }

    #[test]
    fn status_names_are_in_value_order() {
        for (i, (status, name)) in STATUS_NAMES.iter().enumerate() {
            assert_eq!(*status as u32, i as u32);
            let c = unsafe { CStr::from_ptr(rmf_status_name(i as u32)) }
                .to_str()
                .unwrap();
            assert_eq!(c, name.trim_end_matches('\0'));
        }
        let unknown = unsafe { CStr::from_ptr(rmf_status_name(999)) };
        assert_eq!(unknown.to_str().unwrap(), "RMF_UNKNOWN_STATUS");
    }

    #[test]
    fn last_error_is_per_thread() {
        set_last_error("main thread");
        std::thread::spawn(|| {
            assert_eq!(unsafe { CStr::from_ptr(rmf_last_error()) }.to_bytes(), b"");
            set_last_error("other");
        })
        .join()
        .unwrap();
        assert_eq!(
            unsafe { CStr::from_ptr(rmf_last_error()) }.to_bytes(),
            b"main thread"
        );
    }
}
