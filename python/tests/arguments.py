"""The checks of bad arguments shared by test_arguments.py (the package and rmfsurf.ocp) and
freecad_arguments.py (rmfsurf.freecad, in FreeCAD's Python): the values of each class, the
check that an exception names the argument, and the list of the public API's arguments by
class, from the annotations, so that a function without cases fails its coverage test.

A case is keyed "function(argument)", e.g. "wire_sweep(closure_symmetry)" or
"Curve.from_nurbs(degree)"; the argument's name is what the message must name."""

import fractions
import inspect
import math
import re

import numpy as np
import pytest

import rmfsurf

UINT32_MAX = 2 ** 32 - 1
SIZE_MAX = 2 ** 64 - 1
MAXIMUM = {"uint32_t": UINT32_MAX, "size_t": SIZE_MAX}


def out_of_range(minimum, maximum):
    """Integers just outside [minimum, maximum], negative ones, and far beyond a size_t."""
    values = {minimum - 1: None, -1: None, maximum + 1: None, 2 ** 64: None, 10 ** 400: None}
    return [v for v in values if not minimum <= v <= maximum]


#: Not integers: C would truncate or misread them, so they are refused by type.
NOT_INTEGERS = [2.5, 3.0, np.float64(3.0), "3", None, True, np.bool_(True), 3 + 0j,
                fractions.Fraction(3)]
#: Finite numbers beyond a double: float() raises OverflowError or rounds them to inf.
BEYOND_DOUBLE = [10 ** 400, -(10 ** 400), fractions.Fraction(10 ** 400, 3)]
if np.isfinite(np.longdouble("1e400")):
    BEYOND_DOUBLE.append(np.longdouble("1e400"))
#: Not real numbers.
NOT_NUMBERS = ["1.0", None, 1j, True, np.bool_(False), [1.0]]
NON_FINITE = [math.nan, math.inf, -math.inf]


def argument(key):
    """The argument of a case key: "wire_sweep(holes)" -> "holes"."""
    return re.fullmatch(r".*\((.*)\)", key).group(1)


def names(message, name):
    """Whether `message` names the argument `name`: "name:", "name = ...", "name[0]",
    "name(0.5)" (a function's value at 0.5), "options->name", as a word of its own (not
    inside "t_min" for "t")."""
    return re.search(r"(^|[\s>.(,])%s(?=$|[\s:=\[,.()])" % re.escape(name), message) is not None


def refused(call, value, exception, name):
    """Calls call(value), expects `exception` and a message naming `name`; returns it."""
    with pytest.raises(exception) as caught:
        call(value)
    message = str(caught.value)
    assert names(message, name), "%r does not name %r" % (message, name)
    return message


def outcome(call, value):
    """What call(value) gives: "ok" or (exception type, message)."""
    try:
        call(value)
    except Exception as e:  # the comparison is the check
        return type(e), str(e)
    return "ok"


def value_id(value):
    if (isinstance(value, tuple) and len(value) >= 2 and isinstance(value[1], type)
            and issubclass(value[1], BaseException)):  # (bad value, expected exception, ...)
        return value_id(value[0])
    text = getattr(value, "label", None) or repr(value)
    return text if len(text) <= 24 else text[:12] + "..." + text[-8:]


def parametrize(cases, values_of):
    """pytest parameters (case, value) for every value of every case."""
    params = []
    for case in cases:
        for value in values_of(case):
            params.append(pytest.param(case, value, id="%s-%s" % (case[0], value_id(value))))
    return params


# ---------------------------------------------------------------------------------------
# The public API's arguments by class, from the annotations.

CLASSES = [
    ("path", re.compile(r".*PathLike.*")),
    ("objects", re.compile(r"Union\[(\w+), Sequence\[\1\]\]|Sequence\[[A-Z]\w*\]")),
    ("pair", re.compile(r"(Optional\[)?Tuple\[float, float\]\]?")),
    ("box", re.compile(r"(Optional\[)?Tuple\[ArrayLike, ArrayLike\]\]?")),
    ("array", re.compile(r"(Optional\[)?(ArrayLike|Sequence\[float\])\]?")),
    ("integer", re.compile(r"(Optional\[)?int\]?")),
    ("number", re.compile(r"(Optional\[)?float\]?")),
]


def _arguments(function, key):
    found = {}
    for p in inspect.signature(function).parameters.values():
        if p.name in ("self", "cls") or p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
            continue
        annotation = p.annotation if isinstance(p.annotation, str) else getattr(
            p.annotation, "__name__", str(p.annotation))
        for cls, pattern in CLASSES:
            if pattern.fullmatch(annotation):
                found["%s(%s)" % (key, p.name)] = cls
                break
    return found


def api_arguments(module, prefix="", own_module=None):
    """{"function(argument)": class} for the public functions and methods defined in
    `module` (or, for the package, its submodules other than the adapters)."""
    found = {}
    for name in dir(module):
        obj = getattr(module, name)
        where = getattr(obj, "__module__", "") or ""
        if name.startswith("_") or not where.startswith("rmfsurf"):
            continue
        if own_module is not None and where != own_module:
            continue
        if own_module is None and where in ("rmfsurf.ocp", "rmfsurf.freecad"):
            continue
        if inspect.isfunction(obj):
            found.update(_arguments(obj, prefix + name))
        elif inspect.isclass(obj):
            for attribute, member in vars(obj).items():
                if attribute.startswith("_"):
                    continue
                if isinstance(member, (classmethod, staticmethod)):
                    member = member.__func__
                if inspect.isfunction(member):
                    found.update(_arguments(member, "%s%s.%s" % (prefix, name, attribute)))
    return found


def missing_cases(required, cases):
    """The arguments of `required` ({key: class}) that no case of their class covers."""
    return sorted("%s: %s" % (key, cls) for key, cls in required.items()
                  if key not in cases.get(cls, ()))
