"""Curves: piecewise rational Bézier space curves (``RmfCurve``), NURBS in and out,
evaluation, and the curve constructions of the library — PH cubic splines (Mäurer &
Jüttler), curves with rational rotation-minimizing frames by Möbius maps (Bartoň, Jüttler
& Wang) and RRMF quintics (Farouki, Giannelli & Sestini), profile offsets.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Callable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import call, ffi, lib

if TYPE_CHECKING:
    from .frames import Frames

ArrayLike = Any
#: An analytic curve for the approximations: ``f(t) -> (point, tangent)``.
CurveFunction = Callable[[float], Tuple[Sequence[float], Sequence[float]]]


@dataclass(frozen=True)
class NurbsCurve:
    """NURBS data in the layout of OpenCascade's Geom_BSplineCurve and STEP: knots listed
    one by one (a clamped vector of ``len(poles) + degree + 1`` values).

    Attributes:
        degree: polynomial degree p ≥ 1.
        poles: (n, 3) Cartesian poles.
        weights: (n,) weights, all > 0.
        knots: (n + p + 1,) clamped, non-decreasing knots.
    """

    degree: int
    poles: np.ndarray
    weights: np.ndarray
    knots: np.ndarray

    def distinct_knots(self) -> Tuple[np.ndarray, np.ndarray]:
        """The knots as distinct values and multiplicities (FreeCAD's and OCC's form)."""
        return distinct_knots(self.knots)


def distinct_knots(knots: ArrayLike) -> Tuple[np.ndarray, np.ndarray]:
    """A flat knot vector as (distinct values, multiplicities)."""
    values, counts = np.unique(_core.doubles(knots, "knots", finite_only=True),
                               return_counts=True)
    return values, counts.astype(np.int64)


def flat_knots(values: ArrayLike, multiplicities: ArrayLike) -> np.ndarray:
    """Distinct knots with multiplicities as one flat knot vector."""
    v = _core.doubles(values, "values", finite_only=True)
    m = _core.integers(multiplicities, "multiplicities")
    if m.shape != v.shape:
        raise ValueError("multiplicities: expected %d values (one per knot value), got %d"
                         % (v.shape[0], m.shape[0]))
    return np.repeat(v, m)


@dataclass(frozen=True)
class BezierSegment:
    """One rational Bézier segment of a curve on [t_start, t_end] (the Bernstein basis runs
    over that interval)."""

    degree: int
    poles: np.ndarray
    weights: np.ndarray
    t_start: float
    t_end: float


class Curve:
    """A piecewise rational Bézier space curve (``RmfCurve``), immutable.

    Make one from NURBS data (:meth:`from_nurbs`) or with the constructions of this module;
    read it back as NURBS (:meth:`nurbs`) or Bézier segments (:meth:`segments`); evaluate it
    with :meth:`eval` (vectorized over parameters). The library object is freed when the
    Python object is collected; a curve borrowed from an :class:`rmfsurf.Shape` keeps the
    shape alive.
    """

    __slots__ = ("_ptr", "_owner", "__weakref__")

    def __init__(self, pointer: Any, owner: Any = None) -> None:
        """Wraps an ``RmfCurve *`` (use the constructors instead)."""
        self._ptr = pointer
        self._owner = owner

    @classmethod
    def _owned(cls, out: Any) -> "Curve":
        return cls(_core.owned("curve", out[0]))

    @classmethod
    def from_nurbs(cls, degree: int, poles: ArrayLike, knots: ArrayLike,
                   weights: Optional[ArrayLike] = None) -> "Curve":
        """A curve from NURBS data.

        Args:
            degree: 1 ≤ p ≤ 64.
            poles: (n, 3) poles, n ≥ p + 1.
            knots: n + p + 1 clamped knots (end multiplicity p + 1, interior ≤ p); use
                :func:`flat_knots` for distinct values with multiplicities.
            weights: n weights > 0, or None for a polynomial curve.
        """
        degree = _core.integer(degree, "degree", "uint32_t", 1)
        p = _core.points(poles, "poles")
        k = _core.doubles(knots, "knots")
        w = None if weights is None else _core.doubles(weights, "weights", p.shape[0])
        out = _core.out_pointer("RmfCurve")
        call("rmf_nurbs_curve_create", degree, _core.vec3_array(p), _core.double_array(w),
             p.shape[0], _core.double_array(k), k.shape[0], out)
        return cls._owned(out)

    @property
    def domain(self) -> Tuple[float, float]:
        """The parameter domain (t_min, t_max)."""
        lo, hi = ffi.new("double *"), ffi.new("double *")
        call("rmf_curve_domain", self._ptr, lo, hi)
        return lo[0], hi[0]

    def eval(self, t: ArrayLike, derivative: bool = False) -> Any:
        """Points x(t) — shape (3,) for a scalar t, (n, 3) for n parameters — and, with
        ``derivative=True``, also x'(t) of the same shape."""
        ts, scalar = _core.parameters(t, "t")
        pts = np.empty((ts.shape[0], 3))
        ders = np.empty((ts.shape[0], 3)) if derivative else None
        p = ffi.new("RmfVec3 *")
        d = ffi.new("RmfVec3 *") if derivative else ffi.NULL
        for i, ti in enumerate(ts):
            call("rmf_curve_eval", self._ptr, float(ti), p, d)
            pts[i] = (p.x, p.y, p.z)
            if ders is not None:
                ders[i] = (d.x, d.y, d.z)
        if scalar:
            return (pts[0], ders[0]) if ders is not None else pts[0]
        return (pts, ders) if ders is not None else pts

    __call__ = eval

    def nurbs(self) -> NurbsCurve:
        """The curve as one clamped NURBS (copies; interior knots of full multiplicity at the
        segment joints). Raises InvalidInputError if the segments do not join
        continuously (then use :meth:`segments`)."""
        view = ffi.new("RmfNurbsCurve *")
        call("rmf_curve_nurbs", self._ptr, view)
        return NurbsCurve(int(view.degree), _core.copy_vec3s(view.poles, view.pole_count),
                          _core.copy_doubles(view.weights, view.pole_count),
                          _core.copy_doubles(view.knots, view.knot_count))

    @property
    def segment_count(self) -> int:
        """The number of rational Bézier segments."""
        n = ffi.new("size_t *")
        call("rmf_curve_segment_count", self._ptr, n)
        return int(n[0])

    def segments(self) -> List[BezierSegment]:
        """Every rational Bézier segment (copies)."""
        result = []
        view = ffi.new("RmfBezierCurve *")
        for i in range(self.segment_count):
            call("rmf_curve_segment", self._ptr, i, view)
            n = view.degree + 1
            result.append(BezierSegment(int(view.degree), _core.copy_vec3s(view.poles, n),
                                        _core.copy_doubles(view.weights, n),
                                        float(view.t_start), float(view.t_end)))
        return result

    def __repr__(self) -> str:
        lo, hi = self.domain
        return "<rmfsurf.Curve %d segments on [%g, %g]>" % (self.segment_count, lo, hi)


def as_curve(value: Any, name: str) -> Curve:
    """`value` if it is a :class:`Curve`, else a TypeError naming the argument."""
    return _core.instance(value, name, Curve, "an rmfsurf.Curve")


# ---------------------------------------------------------------------------------------
# Analytic curves given as Python functions (RmfCurveCallback).


class _Callback:
    """A Python function f(t) -> (point, tangent) as an RmfCurveCallback. An exception in
    f, or a value of f that is no pair of finite 3-vectors (refused here, naming the
    argument and t, as the library would call it "the callback"), is kept and re-raised
    after the call; the library is given NaN, which it refuses."""

    def __init__(self, function: CurveFunction, name: str) -> None:
        if not callable(function):
            raise TypeError("%s: expected an rmfsurf.Curve or a function t -> (point, "
                            "tangent), got %s" % (name, type(function).__name__))
        self.function = function
        self.name = name
        self.error: Optional[BaseException] = None
        self.c = ffi.callback("RmfCurveCallback", self._call)

    def _call(self, t: float, _user: Any, point: Any, tangent: Any) -> None:
        try:
            if self.error is not None:
                raise self.error
            value = self.function(t)
            try:
                p, d = value
            except (TypeError, ValueError):
                raise TypeError("%s(%r): expected (point, tangent), got %s"
                                % (self.name, t, type(value).__name__)) from None
            point.x, point.y, point.z = _core.vector(p, "%s(%r)[0]" % (self.name, t), True)
            tangent.x, tangent.y, tangent.z = _core.vector(d, "%s(%r)[1]" % (self.name, t), True)
        except BaseException as e:  # never unwind into the library
            if self.error is None:
                self.error = e
            nan = float("nan")
            point.x = point.y = point.z = nan
            tangent.x = tangent.y = tangent.z = nan

    def reraise(self) -> None:
        if self.error is not None:
            raise self.error


CurveSource = Union[Curve, CurveFunction]


def _source(curve: CurveSource, domain: Optional[Tuple[float, float]], name: str
            ) -> Tuple[Any, Any, float, float, Optional[_Callback]]:
    """(curve pointer, callback, t_min, t_max, callback object) for the C entry points that
    take either a curve or a callback."""
    if isinstance(curve, Curve):
        if domain is not None:
            raise ValueError("domain: only for a function %s, not an rmfsurf.Curve" % name)
        return curve._ptr, ffi.NULL, 0.0, 0.0, None
    callback = _Callback(curve, name)
    if domain is None:
        raise ValueError("domain: a function %s needs its parameter interval (t_min, t_max)"
                         % name)
    lo, hi = _core.pair(domain, "domain")
    return ffi.NULL, callback.c, lo, hi, callback


def _curve_handle(curve: CurveSource, domain: Optional[Tuple[float, float]], name: str
                  ) -> Tuple[Any, Optional[_Callback]]:
    """(curve pointer, callback object) for the C entry points that take an RmfCurve: the
    Curve's own, or a callback curve (rmf_callback_curve_create) over a function
    t -> (point, tangent) on `domain`, which lives as long as the returned pointer."""
    ptr, cb, lo, hi, callback = _source(curve, domain, name)
    if callback is None:
        return ptr, None
    out = _core.out_pointer("RmfCurve")
    # The library evaluates the function once here: its exception wins, as in the call.
    _with_callback(callback, "rmf_callback_curve_create", cb, ffi.NULL, lo, hi, out)
    return _core.owned("curve", out[0]), callback


def _with_callback(callback: Optional[_Callback], function: str, *arguments: Any) -> None:
    """Calls `function`; an exception raised in the Python callback wins over the status
    the library gave for the NaN it was handed."""
    try:
        call(function, *arguments)
    finally:
        if callback is not None:
            callback.reraise()


# ---------------------------------------------------------------------------------------
# Primitive curves: circles, arcs, polylines, polygons, obrounds (exact rational pieces)


def circle(radius: float, centre: ArrayLike = (0.0, 0.0, 0.0),
           x_axis: ArrayLike = (1.0, 0.0, 0.0), y_axis: ArrayLike = (0.0, 1.0, 0.0)) -> Curve:
    """The full circle of `radius` about `centre` in the plane of `x_axis` and `y_axis`
    (rmf_curve_circle): four rational quadratic quarter arcs on [0, 4], starting at
    centre + radius x_axis / |x_axis|, counter-clockwise about x × y."""
    out = _core.out_pointer("RmfCurve")
    call("rmf_curve_circle", _core.vec3(centre, "centre"), _core.vec3(x_axis, "x_axis"),
         _core.vec3(y_axis, "y_axis"), _core.number(radius, "radius"), out)
    return Curve._owned(out)


def arc(start: ArrayLike, through: ArrayLike, end: ArrayLike) -> Curve:
    """The circular arc from `start` through `through` to `end` (rmf_curve_arc): rational
    quadratic pieces of at most a quarter turn on [0, 1], its ends exactly `start`, `end`."""
    out = _core.out_pointer("RmfCurve")
    call("rmf_curve_arc", _core.vec3(start, "start"), _core.vec3(through, "through"),
         _core.vec3(end, "end"), out)
    return Curve._owned(out)


def polyline(points: ArrayLike) -> Curve:
    """Straight segments through `points` (rmf_curve_polyline), segment i on [i, i + 1]."""
    p = _core.points(points, "points", min_count=2)
    out = _core.out_pointer("RmfCurve")
    call("rmf_curve_polyline", _core.vec3_array(p), p.shape[0], out)
    return Curve._owned(out)


def polygon(corners: ArrayLike) -> Curve:
    """The closed polygon through `corners` (rmf_curve_polygon; the first is not repeated
    at the end), segment i on [i, i + 1]."""
    p = _core.points(corners, "corners", min_count=3)
    out = _core.out_pointer("RmfCurve")
    call("rmf_curve_polygon", _core.vec3_array(p), p.shape[0], out)
    return Curve._owned(out)


def obround(length: float, radius: float, centre: ArrayLike = (0.0, 0.0, 0.0),
            x_axis: ArrayLike = (1.0, 0.0, 0.0), y_axis: ArrayLike = (0.0, 1.0, 0.0)) -> Curve:
    """The obround (slot) of the points at `radius` from the segment of `length` centred on
    `centre` along `x_axis` (rmf_curve_obround): from the bottom of the end at -x a line,
    a half circle, a line, a half circle on [0, 6]; a length of 0 gives the circle."""
    out = _core.out_pointer("RmfCurve")
    call("rmf_curve_obround", _core.vec3(centre, "centre"), _core.vec3(x_axis, "x_axis"),
         _core.vec3(y_axis, "y_axis"), _core.number(length, "length"),
         _core.number(radius, "radius"), out)
    return Curve._owned(out)


# ---------------------------------------------------------------------------------------
# PH cubics (Mäurer & Jüttler)


def ph_cubic_hermite(p0: ArrayLike, t0: ArrayLike, p1: ArrayLike, t1: ArrayLike
                     ) -> Tuple[Curve, Optional[Curve]]:
    """The PH cubic G1 Hermite interpolants of Table 1 (Mäurer & Jüttler): the
    shape-matching one, and the other one or None."""
    shape, other = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfCurve")
    call("rmf_ph_cubic_hermite", _core.vec3(p0, "p0"), _core.vec3(t0, "t0"),
         _core.vec3(p1, "p1"), _core.vec3(t1, "t1"), shape, other)
    second = Curve._owned(other) if other[0] != ffi.NULL else None
    return Curve._owned(shape), second


def ph_spline_hermite(points: ArrayLike, tangents: ArrayLike) -> Curve:
    """A G1 PH cubic spline through `points` with `tangents` (Mäurer & Jüttler §3.2);
    segment i on [i, i + 1]."""
    p = _core.points(points, "points", min_count=2)
    d = _core.points(tangents, "tangents", p.shape[0])
    out = _core.out_pointer("RmfCurve")
    call("rmf_ph_spline_hermite", _core.vec3_array(p), _core.vec3_array(d), p.shape[0], out)
    return Curve._owned(out)


def ph_spline_approximate(curve: CurveSource, tolerance: float,
                          domain: Optional[Tuple[float, float]] = None
                          ) -> Tuple[Curve, float]:
    """A PH cubic spline within `tolerance` of `curve` (a :class:`Curve`, or a function
    t -> (point, tangent) on `domain`), by adaptive halving (Mäurer & Jüttler §3.2).
    Returns the spline and the largest measured distance."""
    ptr, cb, lo, hi, callback = _source(curve, domain, "curve")
    out, distance = _core.out_pointer("RmfCurve"), ffi.new("double *")
    _with_callback(callback, "rmf_ph_spline_approximate", ptr, cb, ffi.NULL, lo, hi,
                   _core.number(tolerance, "tolerance"), out, distance)
    return Curve._owned(out), float(distance[0])


def profile_offset(profile: Curve, distance: float) -> Curve:
    """The exact offset of a planar profile (x, y) at signed `distance` along its
    right-hand normal; sweep it with the same spine and frames for the offset surface
    (Proposition 4 of Mäurer & Jüttler)."""
    out = _core.out_pointer("RmfCurve")
    call("rmf_profile_offset", as_curve(profile, "profile")._ptr,
         _core.number(distance, "distance"), out)
    return Curve._owned(out)


def profile_offset_by_arcs(profile: Curve, distance: float, tolerance: float
                           ) -> Tuple[Curve, Curve, float]:
    """The offset of any planar profile (x, y) at signed `distance`, exactly, through arcs:
    the profile replaced by a G1 chain of circular arcs within `tolerance` of it (and of its
    offset), and the arcs offset exactly. For profiles `profile_offset` refuses: a general
    curve's offset is not rational. Returns (offset, arcs, largest distance measured)."""
    out, arcs = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfCurve")
    deviation = ffi.new("double *")
    call("rmf_profile_offset_by_arcs", as_curve(profile, "profile")._ptr,
         _core.number(distance, "distance"), _core.number(tolerance, "tolerance"), out, arcs,
         deviation)
    return Curve._owned(out), Curve._owned(arcs), float(deviation[0])


# ---------------------------------------------------------------------------------------
# Curves with exact rational RMFs: Möbius maps (Bartoň, Jüttler & Wang), RRMF quintics
# (Farouki, Giannelli & Sestini).


def _curve_and_frames(curve_out: Any, frames_out: Any) -> Tuple[Curve, "Frames"]:
    from .frames import Frames

    return Curve._owned(curve_out), Frames._owned(frames_out)


def mobius_rrmf_hermite(points: ArrayLike, tangents: ArrayLike,
                        initial_normal: ArrayLike = (0.0, 0.0, 1.0)) -> Tuple[Curve, "Frames"]:
    """G1 Hermite interpolation by rational curves with exact rational RMFs (Bartoň,
    Jüttler & Wang §3.1). Returns the curve and its frames."""
    p = _core.points(points, "points", min_count=2)
    d = _core.points(tangents, "tangents", p.shape[0])
    c, f = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfFrames")
    call("rmf_mobius_rrmf_hermite", _core.vec3_array(p), _core.vec3_array(d), p.shape[0],
         _core.vec3(initial_normal, "initial_normal"), c, f)
    return _curve_and_frames(c, f)


def mobius_rrmf_approximate(curve: CurveSource, segments: int,
                            initial_normal: ArrayLike = (0.0, 0.0, 1.0),
                            domain: Optional[Tuple[float, float]] = None
                            ) -> Tuple[Curve, "Frames"]:
    """`curve` approximated by `segments` rational curves with exact rational RMFs."""
    ptr, cb, lo, hi, callback = _source(curve, domain, "curve")
    c, f = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfFrames")
    _with_callback(callback, "rmf_mobius_rrmf_approximate", ptr, cb, ffi.NULL, lo, hi,
                   _core.integer(segments, "segments", "size_t", 1),
                   _core.vec3(initial_normal, "initial_normal"), c, f)
    return _curve_and_frames(c, f)


#: Shape measures of the RRMF quintic family (rmf_rrmf_quintic_best).
RRMF_MEASURES = {
    "energy_rmf": lib.RMF_RRMF_MEASURE_ENERGY_RMF,
    "energy_frenet": lib.RMF_RRMF_MEASURE_ENERGY_FRENET,
    "arc_length": lib.RMF_RRMF_MEASURE_ARC_LENGTH,
    "scaled_energy_rmf": lib.RMF_RRMF_MEASURE_SCALED_ENERGY_RMF,
    "scaled_energy_frenet": lib.RMF_RRMF_MEASURE_SCALED_ENERGY_FRENET,
}


def rrmf_spline_hermite(points: ArrayLike, tangents: ArrayLike,
                        initial_normal: ArrayLike = (0.0, 0.0, 1.0), *,
                        measure: str = "scaled_energy_rmf", eta_samples: int = 64
                        ) -> Tuple[Curve, "Frames"]:
    """A G1 spline of RRMF quintics with one exact rational RMF (Farouki, Giannelli &
    Sestini, Example 3); each segment's η by least `measure` over `eta_samples` values."""
    p = _core.points(points, "points", min_count=2)
    d = _core.points(tangents, "tangents", p.shape[0])
    c, f = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfFrames")
    call("rmf_rrmf_spline_hermite", _core.vec3_array(p), _core.vec3_array(d), p.shape[0],
         _core.vec3(initial_normal, "initial_normal"),
         _core.choice(measure, "measure", RRMF_MEASURES),
         _core.integer(eta_samples, "eta_samples", "size_t", 1), c, f)
    return _curve_and_frames(c, f)


@dataclass(frozen=True)
class RrmfQuintic:
    """One RRMF quintic Hermite interpolant (Farouki, Giannelli & Sestini §4), canonical
    coordinates; complex coefficients as Python complex numbers."""

    eta: float
    rho: float
    alpha: Tuple[complex, ...]
    beta: Tuple[complex, ...]
    w: Tuple[complex, ...]
    arc_length: float
    energy_frenet: float
    energy_rmf: float
    _c: Any = None

    @classmethod
    def _from_c(cls, s: Any) -> "RrmfQuintic":
        def pairs(a: Any) -> Tuple[complex, ...]:
            return tuple(complex(a[2 * k], a[2 * k + 1]) for k in range(3))

        copy = ffi.new("RmfRrmfQuintic *", s)
        return cls(float(s.eta), float(s.rho), pairs(s.alpha), pairs(s.beta), pairs(s.w),
                   float(s.arc_length), float(s.energy_frenet), float(s.energy_rmf), copy)


def rrmf_quintic_solutions(p0: ArrayLike, t0: ArrayLike, p1: ArrayLike, t1: ArrayLike,
                           eta: float) -> List[RrmfQuintic]:
    """All RRMF quintics interpolating the G1 data for one η (possibly none)."""
    args = (_core.vec3(p0, "p0"), _core.vec3(t0, "t0"), _core.vec3(p1, "p1"),
            _core.vec3(t1, "t1"), _core.number(eta, "eta"))
    count = ffi.new("size_t *")
    call("rmf_rrmf_quintic_solutions", *args, ffi.NULL, 0, count)
    if count[0] == 0:
        return []
    buffer = ffi.new("RmfRrmfQuintic[]", count[0])
    call("rmf_rrmf_quintic_solutions", *args, buffer, count[0], count)
    return [RrmfQuintic._from_c(buffer[i]) for i in range(count[0])]


def rrmf_quintic_best(p0: ArrayLike, t0: ArrayLike, p1: ArrayLike, t1: ArrayLike, *,
                      measure: str = "scaled_energy_rmf", eta_samples: int = 64
                      ) -> RrmfQuintic:
    """The RRMF quintic interpolant of least shape `measure`."""
    best, admissible = ffi.new("RmfRrmfQuintic *"), ffi.new("size_t *")
    call("rmf_rrmf_quintic_best", _core.vec3(p0, "p0"), _core.vec3(t0, "t0"),
         _core.vec3(p1, "p1"), _core.vec3(t1, "t1"),
         _core.choice(measure, "measure", RRMF_MEASURES),
         _core.integer(eta_samples, "eta_samples", "size_t", 1), best, admissible)
    return RrmfQuintic._from_c(best[0])


def rrmf_quintic_curve(p0: ArrayLike, t0: ArrayLike, p1: ArrayLike, t1: ArrayLike,
                       solution: RrmfQuintic, initial_normal: ArrayLike = (0.0, 0.0, 1.0)
                       ) -> Tuple[Curve, "Frames"]:
    """The quintic of `solution` (for the same data) and its exact rational RMF."""
    _core.instance(solution, "solution", RrmfQuintic, "an rmfsurf.RrmfQuintic")
    c, f = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfFrames")
    call("rmf_rrmf_quintic_curve", _core.vec3(p0, "p0"), _core.vec3(t0, "t0"),
         _core.vec3(p1, "p1"), _core.vec3(t1, "t1"), solution._c,
         _core.vec3(initial_normal, "initial_normal"), c, f)
    return _curve_and_frames(c, f)


# ---------------------------------------------------------------------------------------
# Möbius transformations


@dataclass(frozen=True)
class Inversion:
    """One inversion of a Möbius transformation: in a sphere (center, radius), or, with a
    `normal`, a reflection in the plane through `center`."""

    center: Sequence[float]
    radius: float = 1.0
    normal: Optional[Sequence[float]] = None

    def _fill(self, item: Any, i: int) -> None:
        plane = self.normal is not None
        item.kind = lib.RMF_INVERSION_PLANE if plane else lib.RMF_INVERSION_SPHERE
        item.center = _core.vec3(self.center, "maps[%d].center" % i)
        item.radius = _core.number(self.radius, "maps[%d].radius" % i)
        item.normal = _core.vec3(self.normal if plane else (0, 0, 1), "maps[%d].normal" % i)


def _maps(maps: Union[Inversion, Sequence[Inversion]]) -> Tuple[Any, int]:
    items = _core.objects(maps, "maps", Inversion, "an rmfsurf.Inversion")
    array = ffi.new("RmfInversion[]", max(len(items), 1))
    for i, m in enumerate(items):
        m._fill(array[i], i)
    return array, len(items)


def mobius_point(maps: Union[Inversion, Sequence[Inversion]], point: ArrayLike) -> np.ndarray:
    """The image of a point under the Möbius transformation `maps` (applied in order)."""
    array, n = _maps(maps)
    image = ffi.new("RmfVec3 *")
    call("rmf_mobius_point", array, n, _core.vec3(point, "point"), image)
    return _core.from_vec3(image)


def mobius_curve(curve: Curve, maps: Union[Inversion, Sequence[Inversion]]) -> Curve:
    """The exact image of a rational curve under a Möbius transformation."""
    array, n = _maps(maps)
    out = _core.out_pointer("RmfCurve")
    call("rmf_mobius_curve", as_curve(curve, "curve")._ptr, array, n, out)
    return Curve._owned(out)


# ---------------------------------------------------------------------------------------
# Joining the edges of a CAD wire into one curve


def join_nurbs(pieces: Union[NurbsCurve, Sequence[NurbsCurve]], name: str = "pieces",
               tolerance: Optional[float] = None) -> NurbsCurve:
    """NURBS pieces of one degree, each ending where the next starts, as one NURBS: piece k
    on the parameters [k, k + 1], joined by knots of multiplicity p (C0: every piece stays
    exactly what it was). A piece's weights are scaled (which leaves a rational curve
    unchanged) so that its first weight equals the last weight of the piece before.
    Consecutive pieces may be `tolerance` apart (default 1e-9 of the coordinates' size);
    the joint is then where the earlier piece ends. CAD adapters raise the pieces to a
    common degree with their kernel first."""
    pieces = _core.objects(pieces, name, NurbsCurve, "an rmfsurf.NurbsCurve")
    if tolerance is not None:
        tolerance = _core.finite(tolerance, "tolerance", nonnegative=True)
    if not pieces:
        raise ValueError("%s: nothing to join" % name)
    p = pieces[0].degree
    poles, weights, knots = [pieces[0].poles[:1]], [pieces[0].weights[:1]], [np.zeros(p + 1)]
    for k, piece in enumerate(pieces):
        if piece.degree != p:
            raise ValueError("%s[%d]: degree %d, expected %d (raise the degrees first)"
                             % (name, k, piece.degree, p))
        w = piece.weights * (weights[-1][-1] / piece.weights[0])
        gap = np.linalg.norm(piece.poles[0] - poles[-1][-1])
        size = max(np.abs(piece.poles).max(), np.abs(poles[-1]).max(), 1.0)
        if gap > (1e-9 * size if tolerance is None else tolerance):
            raise ValueError("%s[%d] starts %.3g away from where %s[%d] ends"
                             % (name, k, gap, name, k - 1))
        lo, hi = piece.knots[0], piece.knots[-1]
        inner = (piece.knots[p + 1:-(p + 1)] - lo) / (hi - lo) + k
        poles.append(piece.poles[1:])
        weights.append(w[1:])
        knots.append(np.concatenate([inner, np.full(p, k + 1.0)]))
    knots.append([float(len(pieces))])
    return NurbsCurve(p, np.concatenate(poles), np.concatenate(weights),
                      np.concatenate(knots))
