"""The C library as Python sees it: the cffi handle, status codes as exceptions, owned
handles freed by the garbage collector, and conversions between NumPy arrays and the C
structs.

The declarations (``ffi``) are generated from the Rust sources by maturin's cbindgen and
cffi (ABI mode), so they match the library the wheel carries; ``lib`` is that library,
loaded from the package directory (no environment variable, no linker path).
"""

from __future__ import annotations

import threading
from typing import Any, Callable, Dict, Optional, Tuple, Type

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


_ERRORS: Dict[int, Type[RmfError]] = {
    cls.status: cls
    for cls in (NullPointerError, InvalidInputError, NoSolutionError, NotConvergedError,
                BufferTooSmallError, InternalError)
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
    "shape") Python holds now; for finding leaks."""
    with _live_lock:
        return dict(_live)


def out_pointer(ctype: str) -> Any:
    """A fresh ``ctype **`` for an out-argument, NULL-initialized."""
    return ffi.new(ctype + " **")


# ---------------------------------------------------------------------------------------
# Arguments: NumPy in, NumPy out; errors name the argument.


def points(value: Any, name: str, count: Optional[int] = None, min_count: int = 0) -> np.ndarray:
    """`value` as a C-contiguous float64 array of shape (n, 3); TypeError/ValueError name
    the argument."""
    try:
        array = np.ascontiguousarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError("%s: expected an array of 3-D points (shape (n, 3)), got %s (%s)"
                        % (name, type(value).__name__, e)) from None
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError("%s: expected an array of shape (n, 3), got shape %s"
                         % (name, array.shape))
    if count is not None and array.shape[0] != count:
        raise ValueError("%s: expected %d points, got %d" % (name, count, array.shape[0]))
    if array.shape[0] < min_count:
        raise ValueError("%s: expected at least %d points, got %d"
                         % (name, min_count, array.shape[0]))
    return array


def vector(value: Any, name: str) -> np.ndarray:
    """`value` as a float64 array of shape (3,)."""
    try:
        array = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError("%s: expected a 3-D vector, got %s (%s)"
                        % (name, type(value).__name__, e)) from None
    if array.shape != (3,):
        raise ValueError("%s: expected a 3-D vector (shape (3,)), got shape %s"
                         % (name, array.shape))
    return array


def doubles(value: Any, name: str, count: Optional[int] = None) -> np.ndarray:
    """`value` as a C-contiguous 1-D float64 array."""
    try:
        array = np.ascontiguousarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError("%s: expected a sequence of numbers, got %s (%s)"
                        % (name, type(value).__name__, e)) from None
    if array.ndim != 1:
        raise ValueError("%s: expected a 1-D sequence, got shape %s" % (name, array.shape))
    if count is not None and array.shape[0] != count:
        raise ValueError("%s: expected %d values, got %d" % (name, count, array.shape[0]))
    return array


def integer(value: Any, name: str, minimum: int = 0) -> int:
    """`value` as a Python int ≥ minimum (bool refused)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError("%s: expected an integer, got %s" % (name, type(value).__name__))
    if value < minimum:
        raise ValueError("%s: expected an integer >= %d, got %d" % (name, minimum, value))
    return int(value)


def number(value: Any, name: str) -> float:
    """`value` as a Python float (finiteness is the library's to check)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError("%s: expected a number, got %s" % (name, type(value).__name__))
    return float(value)


def vec3(value: Any, name: str) -> Any:
    """A ``RmfVec3`` struct (by value) from a 3-vector."""
    v = vector(value, name)
    return ffi.new("RmfVec3 *", (float(v[0]), float(v[1]), float(v[2])))[0]


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
    scalar = np.ndim(value) == 0
    try:
        array = np.atleast_1d(np.asarray(value, dtype=np.float64))
    except (TypeError, ValueError) as e:
        raise TypeError("%s: expected a number or an array of numbers, got %s (%s)"
                        % (name, type(value).__name__, e)) from None
    if array.ndim != 1:
        raise ValueError("%s: expected a number or a 1-D array, got shape %s"
                         % (name, array.shape))
    return array, scalar


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
