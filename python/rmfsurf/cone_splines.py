"""Cone spline surfaces (``RmfConeSpline``, Leopoldseder & Pottmann): G1 chains of cone,
cylinder and plane pieces through Hermite elements or approximating developable surfaces,
their exact surfaces, isometric bending, offsets, and the exact development into the plane
(the flat pattern of a sheet-metal part, bounded by circular arcs and lines).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import call, ffi, lib
from .curves import ArrayLike, Curve, CurveSource, _curve_handle, _with_callback
from .surfaces import Surface, as_surface

RULES: Dict[str, int] = {
    "min_vertex_distance": lib.RMF_CONE_RULE_MIN_VERTEX_DISTANCE,
    "congruent": lib.RMF_CONE_RULE_CONGRUENT,
    "cylinder_first": lib.RMF_CONE_RULE_CYLINDER_FIRST,
    "cylinder_second": lib.RMF_CONE_RULE_CYLINDER_SECOND,
    "given": lib.RMF_CONE_RULE_GIVEN,
}
_PIECE_KINDS = {lib.RMF_CONE_PIECE_CONE: "cone", lib.RMF_CONE_PIECE_CYLINDER: "cylinder",
                lib.RMF_CONE_PIECE_PLANE: "plane"}
_PAIR_CASES = {lib.RMF_CONE_CASE_GENERAL: "general", lib.RMF_CONE_CASE_CONE: "cone",
               lib.RMF_CONE_CASE_CYLINDER: "cylinder",
               lib.RMF_CONE_CASE_CONSTANT_SLOPE: "constant_slope",
               lib.RMF_CONE_CASE_PLANE: "plane", lib.RMF_CONE_CASE_NONE: "none"}


@dataclass(frozen=True)
class ConeElement:
    """A G1 Hermite element: a ruling through `point` along `ruling`, the tangent plane
    spanned by `ruling` and `side` (normal to the ruling, towards the next piece)."""

    point: Sequence[float]
    ruling: Sequence[float]
    side: Sequence[float]


@dataclass(frozen=True)
class ConePiece:
    """One piece of a cone spline (see RmfConePiece in rmfsurf.h): kind "cone",
    "cylinder" or "plane", the cone pair's case, vertex/axis data, angles, bounding
    rulings, and its patches in the surface."""

    kind: str
    pair_case: str
    vertex: Optional[np.ndarray]
    axis_point: np.ndarray
    axis: np.ndarray
    half_angle: float
    segment_angle: float
    developed_angle: float
    radius: float
    developed_width: float
    start_point: np.ndarray
    start_ruling: np.ndarray
    start_side: np.ndarray
    end_point: np.ndarray
    end_ruling: np.ndarray
    end_side: np.ndarray
    first_patch: int
    patch_count: int


@dataclass(frozen=True)
class FlatPattern:
    """The exact development of a cone spline strip t_min ≤ t ≤ t_max into the plane z = 0:
    `surface` (planar, isometric to the spatial strip), the two boundary curves (exact
    arc splines) and the two end rulings as line segments (start, end)."""

    developed: "ConeSpline"
    surface: Surface
    boundaries: Tuple[Curve, Curve]
    end_rulings: Tuple[Tuple[np.ndarray, np.ndarray], Tuple[np.ndarray, np.ndarray]]


class ConeSpline:
    """A G1 chain of cone, cylinder and plane pieces; freed when collected."""

    __slots__ = ("_ptr", "__weakref__")

    def __init__(self, pointer: Any) -> None:
        self._ptr = pointer

    @classmethod
    def _owned(cls, out: Any) -> "ConeSpline":
        return cls(_core.owned("cone_spline", out[0]))

    def _derived(self, function: str, *arguments: Any) -> "ConeSpline":
        out = _core.out_pointer("RmfConeSpline")
        call(function, self._ptr, *arguments, out)
        return ConeSpline._owned(out)

    @property
    def piece_count(self) -> int:
        n = ffi.new("size_t *")
        call("rmf_cone_spline_piece_count", self._ptr, n)
        return int(n[0])

    def pieces(self) -> List[ConePiece]:
        """The data of every piece."""
        result = []
        p = ffi.new("RmfConePiece *")
        v = _core.from_vec3
        for i in range(self.piece_count):
            call("rmf_cone_spline_piece", self._ptr, i, p)
            result.append(ConePiece(
                _PIECE_KINDS.get(p.kind, "unknown"), _PAIR_CASES.get(p.pair_case, "unknown"),
                v(p.vertex) if p.has_vertex else None, v(p.axis_point), v(p.axis),
                p.half_angle, p.segment_angle, p.developed_angle, p.radius, p.developed_width,
                v(p.start_point), v(p.start_ruling), v(p.start_side), v(p.end_point),
                v(p.end_ruling), v(p.end_side), int(p.first_patch), int(p.patch_count)))
        return result

    def surface(self, t_min: float, t_max: float) -> Surface:
        """The exact surface between signed distances t_min < t_max along the rulings: one
        NURBS of degree (1, 2), u along the rulings, piece k on v ∈ [k, k + 1]."""
        out = _core.out_pointer("RmfSurface")
        call("rmf_cone_spline_surface", self._ptr, _core.number(t_min, "t_min"),
             _core.number(t_max, "t_max"), out)
        return Surface._owned(out)

    def bounds_in_box(self, box: Tuple[ArrayLike, ArrayLike]) -> Tuple[float, float]:
        """The widest (t_min, t_max) whose ruling segments lie in the box (min, max)."""
        lo, hi = ffi.new("double *"), ffi.new("double *")
        call("rmf_cone_spline_bounds_in_box", self._ptr, _core.box(box, "box"), lo, hi)
        return lo[0], hi[0]

    def boundary(self, t: float) -> Curve:
        """The boundary at signed distance t: a G1 spline of exact circular arcs."""
        out = _core.out_pointer("RmfCurve")
        call("rmf_cone_spline_boundary", self._ptr, _core.number(t, "t"), out)
        return Curve._owned(out)

    def bend(self, s: float) -> "ConeSpline":
        """Stage s ∈ [0, 1] of the isometric bending into the plane (s = 1: developed in
        the first tangent plane)."""
        return self._derived("rmf_cone_spline_bend", _core.number(s, "s"))

    def develop(self) -> "ConeSpline":
        """The exact development into the plane z = 0."""
        return self._derived("rmf_cone_spline_develop")

    def offset(self, d: float) -> "ConeSpline":
        """The offset at signed distance d along the normals ruling × side (exact)."""
        return self._derived("rmf_cone_spline_offset", _core.number(d, "d"))

    @property
    def fit_error(self) -> float:
        """The deviation an approximation reached (InvalidInputError for splines not made
        by an approximation)."""
        e = ffi.new("double *")
        call("rmf_cone_spline_fit_error", self._ptr, e)
        return float(e[0])

    def fit_parameters(self, which: str = "elements") -> np.ndarray:
        """The parameters an approximation selected ("elements") or found
        ("inflections")."""
        code = _core.choice(which, "which", {"elements": lib.RMF_CONE_FIT_ELEMENTS,
                                             "inflections": lib.RMF_CONE_FIT_INFLECTIONS})
        count = ffi.new("size_t *")
        call("rmf_cone_spline_fit_parameters", self._ptr, code, ffi.NULL, 0, count)
        values = np.empty(count[0])
        if count[0]:
            call("rmf_cone_spline_fit_parameters", self._ptr, code,
                 _core.double_array(values), count[0], count)
        return values

    def flat_pattern(self, t_min: float, t_max: float) -> FlatPattern:
        """The flat pattern of the strip t_min ≤ t ≤ t_max (see :class:`FlatPattern`)."""
        t_min, t_max = _core.finite(t_min, "t_min"), _core.finite(t_max, "t_max")
        developed = self.develop()
        low, high = developed.boundary(t_min), developed.boundary(t_max)
        a, b = low.domain
        rulings = ((low.eval(a), high.eval(a)), (low.eval(b), high.eval(b)))
        return FlatPattern(developed, developed.surface(t_min, t_max), (low, high), rulings)

    def __repr__(self) -> str:
        return "<rmfsurf.ConeSpline %d pieces>" % self.piece_count


def cone_spline_hermite(elements: Union[ConeElement, Sequence[ConeElement]],
                        rule: str = "min_vertex_distance",
                        parameter: float = 0.0,
                        region: Optional[Tuple[ArrayLike, ArrayLike]] = None) -> ConeSpline:
    """The cone spline through G1 Hermite elements, one cone pair per gap, chosen by
    `rule`, with no vertex inside the box `region` (min, max)."""
    elements = _core.objects(elements, "elements", ConeElement, "an rmfsurf.ConeElement")
    array = ffi.new("RmfConeElement[]", max(len(elements), 1))
    for i, e in enumerate(elements):
        array[i].point = _core.vec3(e.point, "elements[%d].point" % i)
        array[i].ruling = _core.vec3(e.ruling, "elements[%d].ruling" % i)
        array[i].side = _core.vec3(e.side, "elements[%d].side" % i)
    out = _core.out_pointer("RmfConeSpline")
    call("rmf_cone_spline_hermite", array, len(elements), _core.choice(rule, "rule", RULES),
         _core.number(parameter, "parameter"),
         ffi.NULL if region is None else _core.box(region, "region"), out)
    return ConeSpline._owned(out)


def cone_spline_approximate(curve: CurveSource, v_range: Tuple[float, float],
                            tolerance: float, *, rule: str = "min_vertex_distance",
                            max_pieces: int = 10000,
                            domain: Optional[Tuple[float, float]] = None) -> ConeSpline:
    """The tangent surface x(t) + v e(t), v in `v_range` (0 outside it), of a curve (a
    :class:`Curve`, or a function t -> (point, tangent) on `domain`) approximated by a cone
    spline within `tolerance`."""
    source, callback = _curve_handle(curve, domain, "curve")
    v0, v1 = _core.pair(v_range, "v_range")
    options = _fit_options(tolerance, rule, max_pieces)
    out = _core.out_pointer("RmfConeSpline")
    _with_callback(callback, "rmf_cone_spline_approximate_with_options", source, v0, v1, options,
                   out, ffi.NULL)
    return ConeSpline._owned(out)


def _fit_options(tolerance: float, rule: str, max_pieces: int) -> Any:
    """An RmfConeApproximationOptions of these values."""
    options = ffi.new("RmfConeApproximationOptions *")
    call("rmf_cone_approximation_options_init", options)
    options.tolerance = _core.number(tolerance, "tolerance")
    options.rule = _core.choice(rule, "rule", RULES)
    options.max_pieces = _core.integer(max_pieces, "max_pieces", "size_t", 2)
    return options


def cone_spline_approximate_ruled(surface: Surface, tolerance: float, *,
                                  rule: str = "min_vertex_distance",
                                  max_pieces: int = 10000) -> ConeSpline:
    """A developable ruled surface of degree (1, n), rulings along u, approximated by a
    cone spline within `tolerance` (refused if not developable)."""
    out = _core.out_pointer("RmfConeSpline")
    call("rmf_cone_spline_approximate_ruled", as_surface(surface, "surface")._ptr,
         _core.number(tolerance, "tolerance"), _core.choice(rule, "rule", RULES),
         _core.integer(max_pieces, "max_pieces", "size_t", 2), out, ffi.NULL)
    return ConeSpline._owned(out)


def cone_spline_approximate_dual(degree: int, planes: ArrayLike, knots: ArrayLike,
                                 region: Tuple[ArrayLike, ArrayLike], tolerance: float, *,
                                 rule: str = "min_vertex_distance",
                                 max_pieces: int = 10000) -> ConeSpline:
    """A developable in dual form — a B-spline curve of planes (n, 4): u0 + u1 x + u2 y +
    u3 z = 0 — approximated by a cone spline within `tolerance` inside the box `region`."""
    p = _core.rows(planes, "planes", 4, "an array of planes (shape (n, 4))")
    k = _core.doubles(knots, "knots")
    out = _core.out_pointer("RmfConeSpline")
    call("rmf_cone_spline_approximate_dual_with_options",
         _core.integer(degree, "degree", "uint32_t", 1), _core.double_array(p.reshape(-1)),
         p.shape[0], _core.double_array(k), k.shape[0], _core.box(region, "region"),
         _fit_options(tolerance, rule, max_pieces), out, ffi.NULL)
    return ConeSpline._owned(out)


def cone_spline_osculating(curve: CurveSource, v_range: Tuple[float, float],
                           parameters: ArrayLike, *,
                           domain: Optional[Tuple[float, float]] = None) -> ConeSpline:
    """The osculating cone spline of a tangent surface: the osculating cones at the curve
    `parameters`, joined by filling cones."""
    source, callback = _curve_handle(curve, domain, "curve")
    v0, v1 = _core.pair(v_range, "v_range")
    ts = _core.doubles(parameters, "parameters")
    out = _core.out_pointer("RmfConeSpline")
    _with_callback(callback, "rmf_cone_spline_osculating_curve", source, v0, v1,
                   _core.double_array(ts), ts.shape[0], out)
    return ConeSpline._owned(out)
