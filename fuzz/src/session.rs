//! One fuzz run: a pool of the handles made so far, drawn from by later calls, and the
//! contract every call must keep (checked after each call, whatever the input):
//!
//! * the status is one of the documented codes and never `RMF_ERROR_INTERNAL` (a panic);
//! * a failing call names itself in `rmf_last_error` and leaves every out-pointer as it was
//!   (only the documented counts may be written when a buffer is too small);
//! * a succeeding constructor returns a handle, which later calls use and the end frees;
//! * frames are orthonormal and finite wherever they evaluate.

use rmfsurf_capi::cone_spline::{rmf_cone_spline_free, RmfConeSpline};
use rmfsurf_capi::curve::rmf_curve_free;
use rmfsurf_capi::frames::rmf_frames_free;
use rmfsurf_capi::shape::rmf_shape_free;
use rmfsurf_capi::sheet::{rmf_sheet_part_free, RmfSheetPart};
use rmfsurf_capi::status::rmf_last_error;
use rmfsurf_capi::surface::rmf_surface_free;
use rmfsurf_capi::{RmfCurve, RmfFrames, RmfShape, RmfStatus, RmfSurface, RmfVec3};
use std::ffi::CStr;
use std::mem::{size_of, MaybeUninit};

use super::input::Input;

/// The byte every out-value is filled with before a call: a failing call must leave it.
const POISON: u8 = 0xA5;

/// A value of type `T` whose bytes are all [`POISON`] (for plain C data: numbers, pointers,
/// structs of them).
pub fn poisoned<T: Copy>() -> T {
    let mut value = MaybeUninit::<T>::uninit();
    // SAFETY: every bit pattern is a valid value of the plain C types used here.
    unsafe {
        value
            .as_mut_ptr()
            .cast::<u8>()
            .write_bytes(POISON, size_of::<T>());
        value.assume_init()
    }
}

/// True if `value` still holds the poison of [`poisoned`].
pub fn is_poisoned<T: Copy>(value: &T) -> bool {
    // SAFETY: reading the bytes of a plain value.
    let bytes =
        unsafe { std::slice::from_raw_parts((value as *const T).cast::<u8>(), size_of::<T>()) };
    bytes.iter().all(|&b| b == POISON)
}

/// A buffer of `n` poisoned values.
pub fn poisoned_buffer<T: Copy>(n: usize) -> Vec<T> {
    vec![poisoned(); n]
}

/// The calling thread's last error message.
pub fn last_error() -> String {
    // SAFETY: rmf_last_error never returns NULL; the string lives until the next call.
    unsafe { CStr::from_ptr(rmf_last_error()) }
        .to_string_lossy()
        .into_owned()
}

/// Checks what every call must keep: a documented status other than RMF_ERROR_INTERNAL,
/// and on failure a last-error message that names the function. Returns true on success.
pub fn status_ok(function: &str, status: RmfStatus) -> bool {
    if tracing() {
        eprintln!(
            "{function}: {status:?} {}",
            if status == RmfStatus::RmfOk {
                String::new()
            } else {
                last_error()
            }
        );
    }
    let code = status as u32;
    assert!(code <= 7, "{function}: undocumented status {code}");
    if status == RmfStatus::RmfOk {
        return true;
    }
    let message = last_error();
    assert!(
        status != RmfStatus::RmfErrorInternal,
        "{function} panicked: {message}"
    );
    assert!(
        message.starts_with(&format!("{function}: ")) && message.len() > function.len() + 2,
        "{function} failed ({status:?}) with the message {message:?}"
    );
    false
}

/// Checks a call with out-values: on failure every one of them must still be poisoned.
pub fn checked(function: &str, status: RmfStatus, untouched: &[bool]) -> bool {
    let ok = status_ok(function, status);
    if !ok {
        for (i, &u) in untouched.iter().enumerate() {
            assert!(
                u,
                "{function} failed ({status:?}) but wrote its out-value #{i}"
            );
        }
    }
    ok
}

/// True when RMFSURF_FUZZ_TRACE is set: every call is then printed with its status (to
/// read what a finding does).
pub fn tracing() -> bool {
    static TRACE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *TRACE.get_or_init(|| std::env::var_os("RMFSURF_FUZZ_TRACE").is_some())
}

/// Checks that a frame is finite and orthonormal.
pub fn assert_frame(function: &str, t: RmfVec3, f2: RmfVec3, f3: RmfVec3) {
    let dot = |a: RmfVec3, b: RmfVec3| a.x * b.x + a.y * b.y + a.z * b.z;
    let pairs = [
        (dot(t, t) - 1.0).abs(),
        (dot(f2, f2) - 1.0).abs(),
        (dot(f3, f3) - 1.0).abs(),
        dot(t, f2).abs(),
        dot(t, f3).abs(),
        dot(f2, f3).abs(),
    ];
    assert!(
        pairs.iter().all(|e| *e < 1e-6),
        "{function}: frame not orthonormal: t = {t:?}, f2 = {f2:?}, f3 = {f3:?}"
    );
}

/// The handles a run made, by type; freed when the run ends.
#[derive(Default)]
pub struct Pool {
    pub curves: Vec<*mut RmfCurve>,
    pub frames: Vec<*mut RmfFrames>,
    pub surfaces: Vec<*mut RmfSurface>,
    pub splines: Vec<*mut RmfConeSpline>,
    pub parts: Vec<*mut RmfSheetPart>,
    pub shapes: Vec<*mut RmfShape>,
}

impl Drop for Pool {
    fn drop(&mut self) {
        // SAFETY: every pointer came from the library and is freed once.
        unsafe {
            self.curves.drain(..).for_each(|h| rmf_curve_free(h));
            self.frames.drain(..).for_each(|h| rmf_frames_free(h));
            self.surfaces.drain(..).for_each(|h| rmf_surface_free(h));
            self.splines.drain(..).for_each(|h| rmf_cone_spline_free(h));
            self.parts.drain(..).for_each(|h| rmf_sheet_part_free(h));
            self.shapes.drain(..).for_each(|h| rmf_shape_free(h));
        }
    }
}

/// A fuzz run: the input and the handles made from it.
pub struct Session<'a> {
    pub input: Input<'a>,
    pub pool: Pool,
}

/// Picks a handle from a pool, or NULL (when the pool is empty or the input says so).
fn pick<T>(input: &mut Input, pool: &[*mut T]) -> *mut T {
    let b = input.byte();
    if pool.is_empty() || b == 255 {
        std::ptr::null_mut()
    } else {
        pool[usize::from(b) % pool.len()]
    }
}

/// Adds a handle returned through an out-pointer to a pool: after success it must be a new
/// non-NULL handle; after failure it must be untouched (or NULL).
fn adopt<T>(function: &str, ok: bool, handle: *mut T, pool: &mut Vec<*mut T>) {
    if ok {
        assert!(
            !handle.is_null() && !is_poisoned(&handle),
            "{function} succeeded without a handle"
        );
        pool.push(handle);
    } else {
        assert!(
            handle.is_null() || is_poisoned(&handle),
            "{function} failed but wrote a handle"
        );
    }
}

impl<'a> Session<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Self {
            input: Input::new(bytes),
            pool: Pool::default(),
        }
    }

    pub fn curve(&mut self) -> *const RmfCurve {
        pick(&mut self.input, &self.pool.curves)
    }

    pub fn frames(&mut self) -> *const RmfFrames {
        pick(&mut self.input, &self.pool.frames)
    }

    pub fn surface(&mut self) -> *const RmfSurface {
        pick(&mut self.input, &self.pool.surfaces)
    }

    pub fn spline(&mut self) -> *const RmfConeSpline {
        pick(&mut self.input, &self.pool.splines)
    }

    pub fn part(&mut self) -> *const RmfSheetPart {
        pick(&mut self.input, &self.pool.parts)
    }

    pub fn shape(&mut self) -> *const RmfShape {
        pick(&mut self.input, &self.pool.shapes)
    }

    /// Checks a constructor's status and adopts its handles (curve and/or frames).
    pub fn made(
        &mut self,
        function: &str,
        status: RmfStatus,
        curve: Option<*mut RmfCurve>,
        frames: Option<*mut RmfFrames>,
    ) -> bool {
        let ok = status_ok(function, status);
        if let Some(c) = curve {
            adopt(function, ok, c, &mut self.pool.curves);
        }
        if let Some(f) = frames {
            adopt(function, ok, f, &mut self.pool.frames);
        }
        ok
    }

    pub fn made_surface(&mut self, function: &str, status: RmfStatus, s: *mut RmfSurface) {
        let ok = status_ok(function, status);
        adopt(function, ok, s, &mut self.pool.surfaces);
    }

    pub fn made_spline(&mut self, function: &str, status: RmfStatus, s: *mut RmfConeSpline) {
        let ok = status_ok(function, status);
        adopt(function, ok, s, &mut self.pool.splines);
    }

    pub fn made_part(&mut self, function: &str, status: RmfStatus, p: *mut RmfSheetPart) {
        let ok = status_ok(function, status);
        adopt(function, ok, p, &mut self.pool.parts);
    }

    pub fn made_shape(&mut self, function: &str, status: RmfStatus, s: *mut RmfShape) {
        let ok = status_ok(function, status);
        adopt(function, ok, s, &mut self.pool.shapes);
    }

    /// Runs operations chosen by the input from `ops` until the input is used up (at most
    /// `max_ops`, which bounds the time of one run).
    pub fn run(mut self, ops: &[fn(&mut Session)], max_ops: usize) {
        for _ in 0..max_ops {
            if self.input.is_empty() {
                break;
            }
            let op = ops[self.input.below(ops.len())];
            op(&mut self);
        }
    }
}
