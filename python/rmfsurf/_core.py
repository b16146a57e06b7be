"""The C library as Python sees it: the cffi handle, status codes as exceptions, owned
handles freed by the garbage collector, and conversions between NumPy arrays and the C
structs.

The declarations (``ffi``) are generated from the Rust sources by maturin's cbindgen and
cffi (ABI mode), so they match the library the wheel carries; ``lib`` is that library,
loaded from the package directory (no environment variable, no linker path).
"""

from __future__ import annotations

import math
import numbers
import operator
import os
import threading
from collections.abc import Iterable
from typing import Any, Callable, Dict, List, Optional, Tuple, Type

import numpy as np

from ._native import ffi, lib

__all__ = [
    "RmfError",
    "NullPointerError",
    "InvalidInputError",
    "NoSolutionError",
    "NotConvergedError",
    "BufferTooSmallError",
    "InternalError",
    "FileError",
]


class RmfError(Exception):
    """A library call failed.

    Attributes:
        status: the RmfStatus code (e.g. 2 for RMF_ERROR_INVALID_INPUT).
        status_name: its C name, e.g. ``"RMF_ERROR_INVALID_INPUT"``.
        function: the C function that failed, e.g. ``"rmf_sweep_surface"``.
        message: the library's message (``rmf_last_error()``), naming the argument.
    """

    status: int = -1

    def __init__(self, message: str, status: Optional[int] = None, function: str = "") -> None:
        super().__init__(message)
        if status is not None:
            self.status = status
        self.status_name = ffi.string(lib.rmf_status_name(self.status)).decode()
        self.function = function
        self.message = message


class NullPointerError(RmfError, ValueError):
    """RMF_ERROR_NULL_POINTER: a required argument was missing."""

    status = 1


class InvalidInputError(RmfError, ValueError):
    """RMF_ERROR_INVALID_INPUT: NaN/Inf, degenerate vectors, bad counts or knots, a
    parameter outside a domain, ... (the message names the argument)."""

    status = 2


class NoSolutionError(RmfError):
    """RMF_ERROR_NO_SOLUTION: the data admit no construction of that kind."""

    status = 3


class NotConvergedError(RmfError):
    """RMF_ERROR_NOT_CONVERGED: a tolerance was not reached within the iteration limits."""

    status = 4


class BufferTooSmallError(RmfError):
    """RMF_ERROR_BUFFER_TOO_SMALL (the package sizes its buffers, so this means a bug)."""

    status = 5


class InternalError(RmfError):
    """RMF_ERROR_INTERNAL: a caught panic in the library; please report it."""

    status = 6


class FileError(RmfError, OSError):
    """RMF_ERROR_IO: a file could not be written (the message names it and says why)."""

    status = 7


_ERRORS: Dict[int, Type[RmfError]] = {
    cls.status: cls
    for cls in (NullPointerError, InvalidInputError, NoSolutionError, NotConvergedError,
                BufferTooSmallError, InternalError, FileError)
}


def check(status: int, function: str) -> None:
    """Raises the exception of `status` (none for RMF_OK) with the library's message."""
    if status == 0:
        return
    # The library's messages start with the function's name and name the argument.
    message = ffi.string(lib.rmf_last_error()).decode("utf-8", "replace")
    cls = _ERRORS.get(status, RmfError)
    raise cls(message or function, status, function)


def call(function: str, *arguments: Any) -> None:
    """Calls ``lib.<function>(*arguments)`` and raises on a failing status."""
    check(getattr(lib, function)(*arguments), function)


# ---------------------------------------------------------------------------------------
# Owned handles: freed by their rmf_*_free when the Python object is collected.

_live_lock = threading.Lock()
_live: Dict[str, int] = {}
_FREERS: Dict[str, Callable[[Any], None]] = {}


def _freer(kind: str) -> Callable[[Any], None]:
    free = getattr(lib, "rmf_%s_free" % kind)

    def release(pointer: Any) -> None:
        free(pointer)
        with _live_lock:
            _live[kind] -= 1

    return release


def owned(kind: str, pointer: Any) -> Any:
    """`pointer` (an ``RmfX *`` just written by the library) with its rmf_<kind>_free
    attached: the library object lives exactly as long as the returned cdata."""
    if pointer == ffi.NULL:
        raise InternalError("the library returned RMF_OK and no %s" % kind, 6, "")
    release = _FREERS.get(kind)
    if release is None:
        release = _FREERS[kind] = _freer(kind)
    with _live_lock:
        _live[kind] = _live.get(kind, 0) + 1
    return ffi.gc(pointer, release)


def live_handles() -> Dict[str, int]:
    """How many library objects of each kind ("curve", "frames", "surface", "cone_spline",
    "sheet_part", "shape", ...) Python holds now; for finding leaks."""
    with _live_lock:
        return dict(_live)


def out_pointer(ctype: str) -> Any:
    """A fresh ``ctype **`` for an out-argument, NULL-initialized."""
    return ffi.new(ctype + " **")


# ---------------------------------------------------------------------------------------
# Arguments: every public function converts its arguments here, before the library is
# called. The rules (docs/python.md, "Errors"): a value of the wrong type is a TypeError, a
# value of the right type the library cannot take (out of its C type's range, a path with a
# NUL, a number beyond a double) an InvalidInputError, an array of the wrong shape a
# ValueError; each message starts with the argument's name ("holes[1]: ...").


def _shown(value: Any) -> str:
    """`value` for a message, a huge integer by its size (its digits say nothing)."""
    if isinstance(value, int) and abs(value) >= 10 ** 30:
        return "an integer of %d digits" % len(str(abs(value)))
    return repr(value)


def _refused(name: str, message: str) -> InvalidInputError:
    return InvalidInputError("%s: %s" % (name, message), InvalidInputError.status)


#: The largest value of each C integer type the package passes.
C_INTEGER_MAX: Dict[str, int] = {
    ctype: 2 ** (8 * ffi.sizeof(ctype)) - 1 for ctype in ("uint32_t", "size_t")
}


def integer(value: Any, name: str, ctype: str, minimum: int = 0,
            maximum: Optional[int] = None) -> int:
    """`value` as a Python int for a C `ctype` ("uint32_t" or "size_t"), in
    [minimum, maximum] (maximum: the type's largest value unless given).

    TypeError for what is not an integer (a bool, a float even if whole, a string): C would
    truncate or misread it. InvalidInputError outside the range: cffi would raise a bare
    OverflowError, or a negative count would wrap around to a huge one."""
    if isinstance(value, (bool, np.bool_)):
        raise TypeError("%s: expected an integer, got bool" % name)
    try:
        number = operator.index(value)
    except TypeError:
        raise TypeError("%s: expected an integer, got %s" % (name, type(value).__name__)) from None
    top = C_INTEGER_MAX[ctype] if maximum is None else min(maximum, C_INTEGER_MAX[ctype])
    if not minimum <= number <= top:
        raise _refused(name, "expected an integer from %d to %d (%s), got %s"
                       % (minimum, top, ctype, _shown(number)))
    return number


def number(value: Any, name: str) -> float:
    """`value` as a Python float (a C double). TypeError for what is not a real number;
    InvalidInputError for a finite value beyond the range of a double (10**400), which
    float() would refuse with a bare OverflowError or round to infinity. NaN and ±inf pass:
    the library refuses them where they make no sense, naming the argument."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError("%s: expected a number, got %s" % (name, type(value).__name__))
    try:
        result = float(value)
    except OverflowError:
        result = math.inf
    if math.isinf(result) and value != result:
        raise _refused(name, "%s is beyond the range of a double (about ±1.8e308)"
                       % _shown(value))
    return result


def finite(value: Any, name: str, positive: bool = False, nonnegative: bool = False) -> float:
    """A number the package uses itself (CAD kernel tolerances, ...) rather than passing to
    the library, which would check it: finite, and > 0 if `positive`, >= 0 if
    `nonnegative`."""
    result = number(value, name)
    if not math.isfinite(result) or (positive and not result > 0) or (nonnegative and result < 0):
        raise _refused(name, "%r must be finite%s" % (
            result, " and positive" if positive else " and >= 0" if nonnegative else ""))
    return result


def pair(value: Any, name: str) -> Tuple[float, float]:
    """Two finite numbers, e.g. a parameter interval (t_min, t_max): refused here, as the
    library would name them by its own names (t_min, v_min)."""
    if isinstance(value, (str, bytes)) or not isinstance(value, Iterable):
        raise TypeError("%s: expected a pair of numbers, got %s" % (name, type(value).__name__))
    items = list(value)
    if len(items) != 2:
        raise ValueError("%s: expected a pair of numbers, got %d values" % (name, len(items)))
    return finite(items[0], name + "[0]"), finite(items[1], name + "[1]")


def objects(value: Any, name: str, cls: Any, what: str) -> List[Any]:
    """A sequence of `cls` objects as a list; one `cls` object is a sequence of one. TypeError
    naming the argument for what is not a sequence, and its index for an item of another
    type ("holes[1]: expected an rmfsurf.Curve, got int")."""
    if isinstance(value, cls):
        return [value]
    if isinstance(value, (str, bytes)) or not isinstance(value, Iterable):
        raise TypeError("%s: expected %s or a sequence of them, got %s"
                        % (name, what, type(value).__name__))
    items = list(value)
    for i, item in enumerate(items):
        instance(item, "%s[%d]" % (name, i), cls, what)
    return items


def path(value: Any, name: str) -> bytes:
    """A file name for the library (a C string): str, bytes or os.PathLike, as the bytes the
    operating system gets (os.fsencode: file names that are not UTF-8 survive). Refused with
    InvalidInputError: empty, or with a NUL, which would end the C string early and have
    the file written under a shorter name."""
    try:
        raw = os.fspath(value)
    except TypeError:
        raise TypeError("%s: expected a path (str, bytes or os.PathLike), got %s"
                        % (name, type(value).__name__)) from None
    try:
        encoded = os.fsencode(raw)
    except UnicodeError as e:
        raise _refused(name, "%r cannot be encoded as a file name (%s)" % (raw, e)) from None
    if not encoded:
        raise _refused(name, "the path is empty")
    if b"\0" in encoded:
        raise _refused(name, "%r contains a NUL character, which no file name can hold" % (raw,))
    return encoded


def float_array(value: Any, name: str, what: str, contiguous: bool = True) -> np.ndarray:
    """`value` as a float64 array of any shape (the caller checks it); `what` says what was
    expected."""
    try:
        if contiguous:
            return np.ascontiguousarray(value, dtype=np.float64)
        return np.asarray(value, dtype=np.float64)
    except OverflowError:
        raise _refused(name, "expected %s, got a value beyond the range of a double"
                       % what) from None
    except (TypeError, ValueError) as e:
        # NumPy's ValueError is a string that is no number (a type) or nested sequences of
        # unequal lengths (a shape).
        wrong_type = isinstance(e, TypeError) or "could not convert" in str(e)
        raise (TypeError if wrong_type else ValueError)(
            "%s: expected %s, got %s (%s)" % (name, what, type(value).__name__, e)) from None


def _finite_items(array: np.ndarray, name: str) -> np.ndarray:
    """`array` if every number in it is finite, else InvalidInputError naming the first
    item that is not ("points[2]: [nan, 0.0] is not finite")."""
    bad = ~np.isfinite(array)
    if bad.any():
        i = int(np.argwhere(bad)[0][0])
        raise _refused("%s[%d]" % (name, i), "%s is not finite" % (array[i].tolist(),))
    return array


def rows(value: Any, name: str, width: int, what: str, finite_only: bool = False) -> np.ndarray:
    """`value` as a C-contiguous float64 array of shape (n, width); with `finite_only` (rows
    the library would name by another name, or does not see) NaN and ±inf are refused."""
    array = float_array(value, name, what)
    if array.ndim != 2 or array.shape[1] != width:
        raise ValueError("%s: expected an array of shape (n, %d), got shape %s"
                         % (name, width, array.shape))
    return _finite_items(array, name) if finite_only else array


def points(value: Any, name: str, count: Optional[int] = None, min_count: int = 0) -> np.ndarray:
    """`value` as a C-contiguous float64 array of shape (n, 3); TypeError/ValueError name
    the argument."""
    array = rows(value, name, 3, "an array of 3-D points (shape (n, 3))")
    if count is not None and array.shape[0] != count:
        raise ValueError("%s: expected %d points, got %d" % (name, count, array.shape[0]))
    if array.shape[0] < min_count:
        raise ValueError("%s: expected at least %d points, got %d"
                         % (name, min_count, array.shape[0]))
    return array


def vector(value: Any, name: str, finite_only: bool = False) -> np.ndarray:
    """`value` as a float64 array of shape (3,); with `finite_only` (a vector the package uses
    itself) NaN and ±inf are refused."""
    array = float_array(value, name, "a 3-D vector", contiguous=False)
    if array.shape != (3,):
        raise ValueError("%s: expected a 3-D vector (shape (3,)), got shape %s"
                         % (name, array.shape))
    if finite_only and not np.isfinite(array).all():
        raise _refused(name, "%s has a non-finite component" % (array.tolist(),))
    return array


def direction(value: Any, name: str) -> np.ndarray:
    """A finite non-zero 3-vector, normalized (for a direction the package uses itself)."""
    v = vector(value, name, finite_only=True)
    length = float(np.linalg.norm(v))
    if not length > 0:
        raise _refused(name, "a zero vector has no direction")
    return v / length


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a × b of two 3-vectors, written out (``np.cross`` takes a tenth of a millisecond
    a call, a tenth of a whole pipe sweep in the adapters)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                     a[0] * b[1] - a[1] * b[0]])


def in_frame(points: np.ndarray, origin: np.ndarray, x: np.ndarray, y: np.ndarray,
             z: np.ndarray) -> np.ndarray:
    """Points' coordinates along the orthonormal `x`, `y`, `z` about `origin` (a profile in
    the frame of the sweep's start: x along f2, y along f3, z along the tangent)."""
    local = points - origin
    framed = np.empty((len(local), 3))
    framed[:, 0] = local @ x
    framed[:, 1] = local @ y
    framed[:, 2] = local @ z
    return framed


def doubles(value: Any, name: str, count: Optional[int] = None,
            finite_only: bool = False) -> np.ndarray:
    """`value` as a C-contiguous 1-D float64 array (finite numbers only with
    `finite_only`)."""
    array = float_array(value, name, "a sequence of numbers")
    if array.ndim != 1:
        raise ValueError("%s: expected a 1-D sequence, got shape %s" % (name, array.shape))
    if count is not None and array.shape[0] != count:
        raise ValueError("%s: expected %d values, got %d" % (name, count, array.shape[0]))
    return _finite_items(array, name) if finite_only else array


def integers(value: Any, name: str, minimum: int = 0) -> np.ndarray:
    """`value` as a 1-D int64 array of integers >= minimum (floats refused, not truncated)."""
    array = np.asarray(value)
    if array.ndim != 1:
        raise ValueError("%s: expected a 1-D sequence of integers, got shape %s"
                         % (name, array.shape))
    if array.size and array.dtype.kind not in "iu":
        raise TypeError("%s: expected integers, got %s" % (name, array.dtype))
    for i, v in enumerate(array):
        if v < minimum or v > np.iinfo(np.int64).max:
            raise _refused("%s[%d]" % (name, i), "expected an integer >= %d, got %d"
                           % (minimum, v))
    return array.astype(np.int64)


def vec3(value: Any, name: str) -> Any:
    """A ``RmfVec3`` struct (by value) from a 3-vector."""
    v = vector(value, name)
    return ffi.new("RmfVec3 *", (float(v[0]), float(v[1]), float(v[2])))[0]


def box(value: Any, name: str) -> Any:
    """An ``RmfBox *`` from (min corner, max corner)."""
    try:
        lo, hi = value
    except (TypeError, ValueError):
        raise TypeError("%s: expected (min corner, max corner), got %s"
                        % (name, type(value).__name__)) from None
    return ffi.new("RmfBox *", (vec3(lo, name + "[0]"), vec3(hi, name + "[1]")))


def vec3_array(array: np.ndarray) -> Any:
    """A ``RmfVec3 *`` viewing an (n, 3) float64 array (keep `array` alive during the
    call); NULL for no points."""
    if array.shape[0] == 0:
        return ffi.NULL
    return ffi.cast("RmfVec3 *", ffi.from_buffer(array))


def double_array(array: Optional[np.ndarray]) -> Any:
    """A ``double *`` viewing a float64 array, NULL for None or an empty array."""
    if array is None or array.shape[0] == 0:
        return ffi.NULL
    return ffi.cast("double *", ffi.from_buffer(array))


def from_vec3(v: Any) -> np.ndarray:
    """A NumPy vector from a ``RmfVec3``."""
    return np.array((v.x, v.y, v.z))


def copy_vec3s(pointer: Any, count: int) -> np.ndarray:
    """A copy of `count` ``RmfVec3`` at `pointer` as an (n, 3) array."""
    if count == 0:
        return np.zeros((0, 3))
    raw = ffi.buffer(pointer, count * ffi.sizeof("RmfVec3"))
    return np.frombuffer(raw, dtype=np.float64).reshape(count, 3).copy()


def copy_doubles(pointer: Any, count: int) -> np.ndarray:
    """A copy of `count` doubles at `pointer`."""
    if count == 0:
        return np.zeros(0)
    return np.frombuffer(ffi.buffer(pointer, count * 8), dtype=np.float64).copy()


def parameters(value: Any, name: str) -> Tuple[np.ndarray, bool]:
    """Parameters for vectorized evaluation: a flat float64 array and whether `value` was
    a scalar (then the caller returns one result instead of an array of them)."""
    array = float_array(value, name, "a number or an array of numbers", contiguous=False)
    scalar = array.ndim == 0
    array = np.atleast_1d(array)
    if array.ndim != 1:
        raise ValueError("%s: expected a number or a 1-D array, got shape %s"
                         % (name, array.shape))
    return array, scalar


#: The programs an OpenCascade binary B-rep is written for (RMF_OCC_READER_*): the file ends
#: with the root shape as that program reads it.
OCC_READERS: Dict[str, int] = {"bintools": 0, "freecad": 1}

# Buffers the library fills whole: not cleared first (a helix's B-rep text is over 1 MB).
_uncleared = ffi.new_allocator(should_clear_after_alloc=False)


def occ_binary(function: str, handle: Any, reader: str) -> bytes:
    """The binary B-rep a C `function` (rmf_shape_occ_binary, rmf_brep_occ_binary) writes
    of `handle` for `reader` ("bintools" or "freecad"), copied once out of the library."""
    code = choice(reader, "reader", OCC_READERS)
    n = ffi.new("size_t *")
    call(function, handle, code, ffi.NULL, 0, n)
    data = _uncleared("uint8_t[]", n[0])
    call(function, handle, code, data, n[0], n)
    return ffi.buffer(data, n[0])[:]


def choice(value: Any, name: str, options: Dict[str, int]) -> int:
    """The integer of an option given by name (e.g. corner="round")."""
    if not isinstance(value, str):
        raise TypeError("%s: expected one of %s, got %s"
                        % (name, ", ".join(repr(k) for k in options), type(value).__name__))
    try:
        return options[value]
    except KeyError:
        raise ValueError("%s: expected one of %s, got %r"
                         % (name, ", ".join(repr(k) for k in options), value)) from None


def instance(value: Any, name: str, cls: Type[Any], what: str) -> Any:
    """`value` if it is a `cls`, else a TypeError naming the argument and what it wants."""
    if not isinstance(value, cls):
        raise TypeError("%s: expected %s, got %s" % (name, what, type(value).__name__))
    return value
