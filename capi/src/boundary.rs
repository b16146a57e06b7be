//! The panic boundary and the checks every entry point applies to what C hands it.
//!
//! Each `extern "C"` function body runs inside [`guard`]: it returns `Ok(())` after writing
//! its outputs, or an [`FfiError`]. `guard` catches panics (→ `RMF_ERROR_INTERNAL`), maps
//! errors to status codes and records the message, prefixed with the function name, for
//! `rmf_last_error`. Bodies compute everything first and write out-pointers last, so a
//! failing call writes nothing.

use super::status::{set_last_error, RmfStatus};
use rmfsurf::Error;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Why an entry point failed, before mapping to a status code.
#[derive(Debug)]
pub(crate) enum FfiError {
    /// A required pointer argument was NULL (its name).
    Null(&'static str),
    /// A required pointer in an array's element was NULL (its name with the index, e.g.
    /// `sections[2].profile`).
    NullAt(String),
    /// A caller buffer was too small (message says what is needed).
    BufferTooSmall(String),
    /// The geometry core refused the input.
    Core(Error),
    /// A file or stream could not be written (the message names it and says why).
    Io(String),
}

impl From<Error> for FfiError {
    fn from(e: Error) -> Self {
        FfiError::Core(e)
    }
}

pub(crate) type FfiResult<T = ()> = Result<T, FfiError>;

/// Shorthand for an invalid-input failure detected in the C layer.
pub(crate) fn invalid_arg<T>(message: String) -> FfiResult<T> {
    Err(FfiError::Core(Error::invalid_input(message)))
}

/// Runs an entry point body: catches panics, maps errors to status codes and records the
/// last-error message.
pub(crate) fn guard(function: &str, body: impl FnOnce() -> FfiResult) -> RmfStatus {
    let (status, message) = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => return RmfStatus::RmfOk,
        Ok(Err(FfiError::Null(name))) => {
            (RmfStatus::RmfErrorNullPointer, format!("{name} is NULL"))
        }
        Ok(Err(FfiError::NullAt(name))) => {
            (RmfStatus::RmfErrorNullPointer, format!("{name} is NULL"))
        }
        Ok(Err(FfiError::BufferTooSmall(m))) => (RmfStatus::RmfErrorBufferTooSmall, m),
        Ok(Err(FfiError::Io(m))) => (RmfStatus::RmfErrorIo, m),
        Ok(Err(FfiError::Core(e))) => (RmfStatus::from(&e), e.message()),
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_string());
            (
                RmfStatus::RmfErrorInternal,
                format!("internal error (please report): {what}"),
            )
        }
    };
    set_last_error(&format!("{function}: {message}"));
    status
}

/// Runs a `*_free` body, swallowing any panic (a destructor cannot report failure).
pub(crate) fn guard_free(body: impl FnOnce()) {
    let _ = catch_unwind(AssertUnwindSafe(body));
}

/// Drops a handle created by `Box::into_raw`; NULL is a no-op.
///
/// # Safety
/// `handle` must be NULL or a pointer from `Box::into_raw` not freed before.
pub(crate) unsafe fn free_handle<T>(handle: *mut T) {
    guard_free(|| {
        if !handle.is_null() {
            drop(Box::from_raw(handle));
        }
    })
}

fn check_aligned<T>(p: *const T, name: &'static str) -> FfiResult {
    if (p as usize) % std::mem::align_of::<T>() != 0 {
        return invalid_arg(format!("{name} is not suitably aligned"));
    }
    Ok(())
}

/// A shared reference from a non-NULL, aligned pointer.
///
/// # Safety
/// `p` must be NULL or point to a valid `T` that outlives the call.
pub(crate) unsafe fn reference<'a, T>(p: *const T, name: &'static str) -> FfiResult<&'a T> {
    if p.is_null() {
        return Err(FfiError::Null(name));
    }
    check_aligned(p, name)?;
    Ok(&*p)
}

/// Checks an out-pointer (non-NULL, aligned) without writing it.
pub(crate) fn out_ptr<T>(p: *mut T, name: &'static str) -> FfiResult<*mut T> {
    if p.is_null() {
        return Err(FfiError::Null(name));
    }
    check_aligned(p.cast_const(), name)?;
    Ok(p)
}

/// Checks an optional out-pointer: NULL means "not wanted".
pub(crate) fn optional_out<T>(p: *mut T, name: &'static str) -> FfiResult<Option<*mut T>> {
    if p.is_null() {
        Ok(None)
    } else {
        out_ptr(p, name).map(Some)
    }
}

/// Writes `value` through an out-pointer checked by [`out_ptr`].
///
/// # Safety
/// `p` must have passed [`out_ptr`] and point to writable memory for a `T`.
pub(crate) unsafe fn write<T>(p: *mut T, value: T) {
    p.write(value);
}

/// Largest element count accepted for any input array (keeps sizes far from overflow).
const MAX_ITEMS: usize = 1 << 40;

/// A slice from a pointer and a count. A count of zero accepts NULL.
///
/// # Safety
/// If `count > 0`, `p` must point to `count` valid `T`s that outlive the call.
pub(crate) unsafe fn slice<'a, T>(
    p: *const T,
    count: usize,
    name: &'static str,
) -> FfiResult<&'a [T]> {
    if count == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(FfiError::Null(name));
    }
    check_aligned(p, name)?;
    if count > MAX_ITEMS
        || count
            .checked_mul(std::mem::size_of::<T>())
            .is_none_or(|b| b > isize::MAX as usize)
    {
        return invalid_arg(format!("{name}: count {count} is too large"));
    }
    Ok(std::slice::from_raw_parts(p, count))
}

/// A mutable slice for a caller buffer of `capacity` elements (NULL allowed when the
/// capacity is zero).
///
/// # Safety
/// If `capacity > 0`, `p` must point to `capacity` writable `T`s.
pub(crate) unsafe fn buffer<'a, T>(
    p: *mut T,
    capacity: usize,
    name: &'static str,
) -> FfiResult<&'a mut [T]> {
    if capacity == 0 {
        return Ok(&mut []);
    }
    if p.is_null() {
        return Err(FfiError::Null(name));
    }
    check_aligned(p.cast_const(), name)?;
    if capacity > MAX_ITEMS
        || capacity
            .checked_mul(std::mem::size_of::<T>())
            .is_none_or(|b| b > isize::MAX as usize)
    {
        return invalid_arg(format!("{name}: capacity {capacity} is too large"));
    }
    Ok(std::slice::from_raw_parts_mut(p, capacity))
}

/// The file in `cell`, made by `make` on the first call (a caller of an export asks twice:
/// the size, then the file); a failure is returned and nothing kept.
pub(crate) fn made_once<T, E>(
    cell: &std::sync::OnceLock<T>,
    make: impl FnOnce() -> Result<T, E>,
) -> Result<&T, E> {
    if let Some(text) = cell.get() {
        return Ok(text);
    }
    let text = make()?;
    Ok(cell.get_or_init(|| text))
}

/// Hands a text to the caller the way every export of the C API does: `length` receives its
/// length without the NUL; with `capacity` 0 (`out` empty) that is all (a size query); a
/// capacity without room for the text and its NUL is refused with BUFFER_TOO_SMALL (the
/// length still written); otherwise the text and a NUL are copied to the front of `out`.
///
/// # Safety
/// `length` must be valid for a write (checked with [`out_ptr`]).
pub(crate) unsafe fn hand_text(text: &str, out: &mut [u8], length: *mut usize) -> FfiResult {
    let bytes = text.as_bytes();
    write(length, bytes.len());
    if out.is_empty() {
        return Ok(());
    }
    if out.len() <= bytes.len() {
        return Err(FfiError::BufferTooSmall(format!(
            "need {} bytes (the text and its NUL), capacity is {}",
            bytes.len() + 1,
            out.len()
        )));
    }
    out[..bytes.len()].copy_from_slice(bytes);
    out[bytes.len()] = 0;
    Ok(())
}

/// Hands a binary file to the caller as every list call hands a list (size query, then
/// BUFFER_TOO_SMALL naming `buffer` below its length): its `set`, then its `root`.
///
/// # Safety
/// `length` must be valid for a write (checked with [`out_ptr`]).
pub(crate) unsafe fn hand_bytes(
    set: &[u8],
    root: &[u8],
    out: &mut [u8],
    length: *mut usize,
) -> FfiResult {
    let n = set.len() + root.len();
    write(length, n);
    if out.is_empty() {
        return Ok(());
    }
    if out.len() < n {
        return Err(FfiError::BufferTooSmall(format!(
            "buffer: need {n} bytes, capacity is {}",
            out.len()
        )));
    }
    out[..set.len()].copy_from_slice(set);
    out[set.len()..n].copy_from_slice(root);
    Ok(())
}

/// Hands a list to the caller the way every list call of the C API does: `count` receives
/// its length; with `capacity` 0 (`out` empty) that is all (a size query); a smaller
/// non-zero capacity is refused with BUFFER_TOO_SMALL, naming `name`; otherwise the list is
/// copied to the front of `out`.
///
/// # Safety
/// `count` must be writable.
pub(crate) unsafe fn hand_over<T: Copy>(
    list: &[T],
    out: &mut [T],
    count: *mut usize,
    name: &str,
) -> FfiResult {
    write(count, list.len());
    if out.is_empty() {
        return Ok(());
    }
    if out.len() < list.len() {
        return Err(FfiError::BufferTooSmall(format!(
            "{name} needs {} entries, capacity is {}",
            list.len(),
            out.len()
        )));
    }
    out[..list.len()].copy_from_slice(list);
    Ok(())
}

/// An options (or report) struct of the C API. Its first field is `size_t struct_size`, which
/// the caller's `rmf_*_options_init` (or the caller, for a report) set to the size of the
/// struct *it* was compiled with: a program built against an older header passes a shorter
/// struct, and the fields it does not know keep their defaults (or are not written). Structs
/// only grow at the end.
///
/// # Safety
/// Implementors are `#[repr(C)]` plain data whose first field is a `usize` and for which
/// any bit pattern of their fields is a valid value (numbers, vectors, `u32` codes).
pub(crate) unsafe trait OptionsStruct: Copy + Default {
    /// The size of the first published version of the struct.
    const FIRST_SIZE: usize;
    /// How a caller sets `struct_size` right (the end of the message refusing it).
    const SIZE_HINT: &'static str = "initialise it with its rmf_*_options_init function";
}

/// The caller's options, or the defaults where `options` is NULL.
///
/// # Safety
/// `options` must be NULL or point to at least `struct_size` readable bytes.
pub(crate) unsafe fn options<T: OptionsStruct>(
    options: *const T,
    name: &'static str,
) -> FfiResult<T> {
    let mut value = T::default();
    if options.is_null() {
        return Ok(value);
    }
    check_aligned(options, name)?;
    let size = options.cast::<usize>().read();
    if size < T::FIRST_SIZE || size > std::mem::size_of::<T>() {
        return invalid_arg(format!(
            "{name}->struct_size = {size} is no size of this struct ({} to {} bytes): {}",
            T::FIRST_SIZE,
            std::mem::size_of::<T>(),
            T::SIZE_HINT
        ));
    }
    std::ptr::copy_nonoverlapping(
        options.cast::<u8>(),
        (&mut value as *mut T).cast::<u8>(),
        size,
    );
    Ok(value)
}

/// A caller's struct that the library fills (a report), checked before any work: NULL means
/// "not wanted"; otherwise its `struct_size`, set by the caller to the size of the struct it
/// was compiled with, must be a size of the struct. Returns the pointer and that size.
///
/// # Safety
/// `p` must be NULL or point to at least `struct_size` writable bytes.
pub(crate) unsafe fn sized_out<T: OptionsStruct>(
    p: *mut T,
    name: &'static str,
) -> FfiResult<Option<(*mut T, usize)>> {
    let Some(p) = optional_out(p, name)? else {
        return Ok(None);
    };
    let size = p.cast::<usize>().read();
    if size < T::FIRST_SIZE || size > std::mem::size_of::<T>() {
        return invalid_arg(format!(
            "{name}->struct_size = {size} is no size of this struct ({} to {} bytes): set it \
             to sizeof the struct",
            T::FIRST_SIZE,
            std::mem::size_of::<T>()
        ));
    }
    Ok(Some((p, size)))
}

/// Writes the fields of `value` after `struct_size` that fit in the caller's `size` bytes
/// (a struct of an older header gets the fields it knows).
///
/// # Safety
/// `p` and `size` must come from [`sized_out`].
pub(crate) unsafe fn write_sized<T: OptionsStruct>((p, size): (*mut T, usize), value: &T) {
    let skip = std::mem::size_of::<usize>();
    std::ptr::copy_nonoverlapping(
        (value as *const T).cast::<u8>().add(skip),
        p.cast::<u8>().add(skip),
        size - skip,
    );
}

/// `value` as usize from a C `uint32_t` degree or count (always fits on supported targets).
pub(crate) fn to_usize(value: u32) -> usize {
    value as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::status::rmf_last_error;
    use std::ffi::CStr;

    fn last_error() -> String {
        unsafe { CStr::from_ptr(rmf_last_error()) }
            .to_string_lossy()
            .into_owned()
    }

    #[test]
    fn panics_become_internal_errors_with_a_message() {
        // The panics below are deliberate: keep the default hook from printing them.
        let hook = std::panic::take_hook();
        std::panic::set_hook(Box::new(|_| {}));
        let status = guard("rmf_test_entry", || panic!("deliberate test panic"));
        guard_free(|| panic!("a panicking destructor is swallowed"));
        std::panic::set_hook(hook);
        assert_eq!(status, RmfStatus::RmfErrorInternal);
        let message = last_error();
        assert!(
            message.starts_with("rmf_test_entry: internal error"),
            "{message}"
        );
        assert!(message.contains("deliberate test panic"));
    }

    #[test]
    fn errors_map_to_their_status_codes() {
        assert_eq!(
            guard("f", || Err(FfiError::Null("curve"))),
            RmfStatus::RmfErrorNullPointer
        );
        assert_eq!(last_error(), "f: curve is NULL");
        let no_solution = guard("f", || Err(Error::no_solution("no real root").into()));
        assert_eq!(no_solution, RmfStatus::RmfErrorNoSolution);
        let not_converged = guard("f", || Err(Error::not_converged("slow").into()));
        assert_eq!(not_converged, RmfStatus::RmfErrorNotConverged);
        assert_eq!(
            guard("f", || Err(FfiError::BufferTooSmall("need 3".into()))),
            RmfStatus::RmfErrorBufferTooSmall
        );
        assert_eq!(guard("f", || Ok(())), RmfStatus::RmfOk);
        assert_eq!(
            last_error(),
            "f: need 3",
            "success leaves the last error alone"
        );
    }

    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq)]
    struct Grown {
        struct_size: usize,
        old: f64,
        new: f64,
    }
    impl Default for Grown {
        fn default() -> Self {
            Grown {
                struct_size: std::mem::size_of::<Grown>(),
                old: 1.0,
                new: 2.0,
            }
        }
    }
    unsafe impl OptionsStruct for Grown {
        const FIRST_SIZE: usize = 16;
    }

    #[test]
    fn options_of_an_older_header_keep_the_new_fields_default() {
        let given = Grown {
            struct_size: 16,
            old: 5.0,
            new: 99.0,
        };
        let read = unsafe { options(&given, "options") }.unwrap();
        assert_eq!((read.old, read.new), (5.0, 2.0));
        let full = Grown {
            struct_size: 24,
            ..given
        };
        assert_eq!(unsafe { options(&full, "options") }.unwrap().new, 99.0);
        assert_eq!(
            unsafe { options::<Grown>(std::ptr::null(), "o") }.unwrap(),
            Grown::default()
        );
        for bad in [0, 8, 32] {
            let wrong = Grown {
                struct_size: bad,
                ..given
            };
            assert!(unsafe { options(&wrong, "options") }.is_err());
        }
    }

    #[test]
    fn slices_reject_null_misaligned_and_huge_inputs() {
        let data = [1.0f64, 2.0];
        unsafe {
            assert_eq!(slice(data.as_ptr(), 2, "x").unwrap(), &data);
            assert!(slice::<f64>(std::ptr::null(), 0, "x").unwrap().is_empty());
            assert!(matches!(
                slice::<f64>(std::ptr::null(), 1, "x"),
                Err(FfiError::Null("x"))
            ));
            let misaligned = (data.as_ptr() as *const u8).add(1) as *const f64;
            assert!(slice(misaligned, 1, "x").is_err());
            assert!(slice(data.as_ptr(), usize::MAX / 4, "x").is_err());
        }
    }
}
