"""Wire sweeps (``rmf_wire_sweep``, ``RmfShape``): a closed planar profile, with holes,
swept along a connected wire of lines, circular arcs and curves, with rotation-minimizing
frames and round or mitred corners; the result is a set of faces — exact rational swept
faces and planar caps bounded by loops — that closes into a solid.

The profile is given in the plane normal to the wire at its start, as 2-D coordinates
(x, y) along (f2, f3) of the frame there (z ignored); the CAD adapters
(:mod:`rmfsurf.ocp`, :mod:`rmfsurf.freecad`) convert a profile placed in space to these
coordinates.
"""

from __future__ import annotations

import collections.abc
import math
import os
import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import _uncleared, call, ffi, lib
from .curves import ArrayLike, Curve, as_curve
from .surfaces import Surface


@dataclass(frozen=True)
class Line:
    """A straight edge from `start` to `end`."""

    start: Sequence[float]
    end: Sequence[float]


@dataclass(frozen=True)
class Arc:
    """A circular arc from `start` through `through` to `end`."""

    start: Sequence[float]
    through: Sequence[float]
    end: Sequence[float]


@dataclass(frozen=True)
class CurveEdge:
    """An edge along a whole :class:`rmfsurf.Curve`."""

    curve: Curve


Edge = Union[Line, Arc, CurveEdge]


def _has_wire_sweep() -> bool:
    return hasattr(lib, "rmf_wire_sweep")


def _require_wire_sweep() -> None:
    if not _has_wire_sweep():
        raise NotImplementedError(
            "this librmfsurf (%s) has no rmf_wire_sweep" % ffi.string(lib.rmf_version()).decode())


def corners() -> dict:
    """The corner options of :func:`wire_sweep`."""
    return {"round": lib.RMF_CORNER_ROUND, "miter": lib.RMF_CORNER_MITER}


#: What `frame` of :func:`wire_sweep` takes: "rmf", "frenet", ("fixed", (x, y, z)),
#: {"fixed": (x, y, z)}, ("guide", edges) or {"guide": edges}.
SweepFrame = Union[str, Tuple[str, Any], Dict[str, Any]]

_FRAME_FORMS = ("'rmf', 'frenet', ('fixed', (x, y, z)), {'fixed': (x, y, z)}, "
                "('guide', edges) or {'guide': edges}")

_FRAME_ARGUMENTS = {"fixed": "a direction (x, y, z)", "guide": "the guide's edges"}


def _frame_codes() -> dict:
    """The frame names of :func:`wire_sweep` ("fixed" takes a direction too, "guide" its
    edges)."""
    return {"rmf": lib.RMF_FRAME_RMF, "frenet": lib.RMF_FRAME_FRENET,
            "fixed": lib.RMF_FRAME_FIXED, "guide": lib.RMF_FRAME_GUIDE}


def _frame_guide(value: Any) -> Optional[Any]:
    """The guide of a guide frame — ("guide", edges) or {"guide": edges} — as given (edges
    of whatever kind the caller takes for its path, for the CAD adapters to convert), None
    for any other frame."""
    if isinstance(value, dict) and list(value) == ["guide"]:
        return value["guide"]
    if isinstance(value, tuple) and len(value) == 2 and _named(value[0], "guide"):
        return value[1]
    return None


def _sweep_frame(value: Any) -> Tuple[int, Any]:
    """The RmfSweepFrame code of `frame` and, for "fixed", its direction (finite, not
    zero), for "guide" its edges (rmfsurf.Line, Arc or CurveEdge, at least one). TypeError
    for what is no string, pair or dict, or a guide edge of another type; ValueError
    (InvalidInputError for a direction that is zero or not finite, or a guide without
    edges) for an unknown name or a malformed fixed or guide frame; each message names
    `frame`."""
    if isinstance(value, dict):
        if list(value) not in (["fixed"], ["guide"]):
            raise ValueError("frame: a dict frame is {'fixed': (x, y, z)} or {'guide': edges}, "
                             "got keys %s" % ", ".join(repr(k) for k in value))
        items: Any = next(iter(value.items()))
    elif isinstance(value, tuple):
        items = value
    elif isinstance(value, str):
        if value in _FRAME_ARGUMENTS:
            raise ValueError("frame: %r needs %s: (%r, ...) or {%r: ...}"
                             % (value, _FRAME_ARGUMENTS[value], value, value))
        if value not in ("rmf", "frenet"):
            raise ValueError("frame: expected %s, got %r" % (_FRAME_FORMS, value))
        return int(_frame_codes()[value]), None
    else:
        raise TypeError("frame: expected %s, got %s" % (_FRAME_FORMS, type(value).__name__))
    if len(items) != 2 or not (_named(items[0], "fixed") or _named(items[0], "guide")):
        raise ValueError("frame: expected %s, got %r" % (_FRAME_FORMS, value))
    if items[0] == "guide":
        edges = _core.objects(items[1], "frame", (Line, Arc, CurveEdge),
                              "an rmfsurf.Line, Arc or CurveEdge")
        if not edges:
            raise _core._refused("frame", "the guide needs at least one edge")
        return int(lib.RMF_FRAME_GUIDE), edges
    direction = _core.vector(items[1], "frame", finite_only=True)
    if not np.any(direction):
        raise _core._refused("frame", "the fixed direction (0, 0, 0) is zero")
    return int(lib.RMF_FRAME_FIXED), direction


def _scale(value: Any) -> Tuple[float, float]:
    """The profile's scale at the start and the end: two finite positive numbers."""
    start, end = _core.pair(value, "scale")
    for i, s in enumerate((start, end)):
        if not s > 0:
            raise _core._refused("scale[%d]" % i, "%r must be positive" % s)
    return start, end


def _scale_knots(value: Any) -> List[Tuple[float, float]]:
    """The knots of the scale law: (fraction, scale) pairs, the fractions of the wire's
    length strictly increasing in (0, 1), the scales finite and positive. None (or an empty
    sequence) for none. TypeError for what is no sequence of pairs, ValueError for an item
    that is no pair, InvalidInputError for a value out of range; each message names
    `scale_knots` and the item (``scale_knots[1][0]``)."""
    if value is None:
        return []
    if isinstance(value, (str, bytes, dict)) or not isinstance(value, Iterable):
        raise TypeError("scale_knots: expected a sequence of (fraction, scale) pairs, got %s"
                        % type(value).__name__)
    knots: List[Tuple[float, float]] = []
    last = 0.0
    for k, item in enumerate(value):
        name = "scale_knots[%d]" % k
        at, scale = _core.pair(item, name)
        if not (last < at < 1):
            raise _core._refused(name + "[0]", "the fraction of the wire's length %r must lie "
                                 "in (0, 1), after the knot before it (%r)" % (at, last))
        if not scale > 0:
            raise _core._refused(name + "[1]", "the scale %r must be positive" % scale)
        knots.append((at, scale))
        last = at
    return knots


#: How a round profile is swept along curve edges (RMF_PIPE_FRAME_*).
PIPE_FRAMES: Dict[str, int] = {"rmf": 0, "lightest": 1}


def _wire_method(value: Any) -> int:
    """The RMF_SPINE_* code of a wire sweep's `method`: "ph-rmf", "mobius" or "rrmf".
    TypeError for what is no string, ValueError for another name (with a pointer to
    `frame` for "frenet"); each message names `method`."""
    methods = {"ph-rmf": lib.RMF_SPINE_PH_RMF, "mobius": lib.RMF_SPINE_MOBIUS,
               "rrmf": lib.RMF_SPINE_RRMF}
    if isinstance(value, str) and value == "frenet":
        raise ValueError("method: expected one of 'ph-rmf', 'mobius', 'rrmf', got 'frenet' "
                         "(a wire sweep asks for Frenet frames with frame='frenet')")
    return int(_core.choice(value, "method", methods))


def _named(frame: Any, name: str) -> bool:
    """Whether `frame` is the frame called `name` ("rmf", "frenet")."""
    return isinstance(frame, str) and frame == name


def _frame_start_normal(frame: Any, tangent: np.ndarray,
                        principal_normal: Optional[np.ndarray],
                        origin: Optional[np.ndarray] = None) -> Optional[np.ndarray]:
    """For the CAD adapters: f2 at the wire's start as the library sets it for `frame`
    (validated), so that a profile placed in space is given in the frame it will be swept
    in — the fixed direction projected onto the normal plane, the principal normal at the
    start for "frenet" (`principal_normal`, None where the wire starts straight), or
    towards the guide's crossing of the normal plane at the start (`origin`) nearest it
    for "guide" (its edges already rmfsurf edges) — and None where the adapter's own f2
    (the profile's x axis) is the initial normal (the RMF) or the library chooses or
    refuses (a Frenet frame on a straight start, a fixed direction along the tangent, a
    guide that does not cross the plane or passes through the start)."""
    code, argument = _sweep_frame(frame)
    if code == lib.RMF_FRAME_GUIDE:
        crossing = None if origin is None else _guide_crossing(argument, origin, tangent)
        if crossing is None:
            return None
        f2 = crossing - origin
        f2 = f2 - np.dot(f2, tangent) * tangent
        length = np.linalg.norm(f2)
        return f2 / length if length > 0 else None
    if code == lib.RMF_FRAME_FIXED:
        d = argument / np.linalg.norm(argument)
        f2 = d - np.dot(d, tangent) * tangent
        length = np.linalg.norm(f2)
        return f2 / length if length > 1e-9 else None
    if code == lib.RMF_FRAME_FRENET:
        return principal_normal
    return None


def _edge_points(edge: Edge, name: str) -> Any:
    """The points of an edge at s in [0, 1] (an array of n parameters: an (n, 3) array),
    from its start to its end: a line's, an arc's (the circle through its three points),
    a curve's over its domain."""
    if isinstance(edge, Line):
        a = _core.vector(edge.start, name + ".start", finite_only=True)
        b = _core.vector(edge.end, name + ".end", finite_only=True)
        return lambda s: a + np.outer(s, b - a)
    if isinstance(edge, Arc):
        a = _core.vector(edge.start, name + ".start", finite_only=True)
        m = _core.vector(edge.through, name + ".through", finite_only=True)
        b = _core.vector(edge.end, name + ".end", finite_only=True)
        ab, ac = m - a, b - a
        n = _core.cross(ab, ac)
        nn = np.dot(n, n)
        if not nn > 0:  # collinear: the library refuses it; its chord here
            return lambda s: a + np.outer(s, b - a)
        centre = a + (np.dot(ac, ac) * _core.cross(n, ab)
                      + np.dot(ab, ab) * _core.cross(ac, n)) / (2 * nn)
        radius = np.linalg.norm(a - centre)
        u = (a - centre) / radius
        v = _core.cross(n / np.sqrt(nn), u)
        w = b - centre
        sweep = math.atan2(np.dot(w, v), np.dot(w, u)) % (2 * math.pi)
        return lambda s: centre + radius * (np.outer(np.cos(sweep * s), u)
                                            + np.outer(np.sin(sweep * s), v))
    c = as_curve(edge.curve, name + ".curve")
    lo, hi = c.domain
    return lambda s: c.eval(lo + (hi - lo) * np.asarray(s, dtype=float))


def _guide_crossing(edges: Sequence[Edge], origin: np.ndarray, tangent: np.ndarray
                    ) -> Optional[np.ndarray]:
    """Where the guide's edges cross the plane through `origin` normal to the unit
    `tangent`, the crossing nearest `origin` (sign changes of the distance from the plane
    at 256 samples per edge, each bisected to rounding); None where they do not cross it."""
    best: Optional[np.ndarray] = None
    samples = np.linspace(0.0, 1.0, 257)
    for i, e in enumerate(edges):
        points = _edge_points(e, "frame[%d]" % i)
        side = (points(samples) - origin) @ tangent
        for k in range(len(samples) - 1):
            if side[k] == 0:
                s = samples[k]
            elif side[k + 1] == 0 or side[k] * side[k + 1] > 0:
                continue
            else:
                lo, hi = samples[k], samples[k + 1]
                for _ in range(60):
                    mid = 0.5 * (lo + hi)
                    if (np.dot(points(np.array([mid]))[0] - origin, tangent) > 0) == \
                            (side[k] > 0):
                        lo = mid
                    else:
                        hi = mid
                s = 0.5 * (lo + hi)
            p = points(np.array([s]))[0]
            if best is None or np.linalg.norm(p - origin) < np.linalg.norm(best - origin):
                best = p
        if side[-1] == 0:
            p = points(np.array([1.0]))[0]
            if best is None or np.linalg.norm(p - origin) < np.linalg.norm(best - origin):
                best = p
    return best


def _edges(edges: Sequence[Edge], argument: str = "edges", finite_only: bool = False
           ) -> Tuple[Any, int, List[Any]]:
    """An RmfEdge array, its length, and what must stay alive during the call; messages
    name `argument`. With `finite_only` (a guide's edges, which the library would name by
    its own field) points that are not finite are refused here."""
    def vec3(value: Any, name: str) -> Any:
        return _core.vec3(_core.vector(value, name, finite_only), name)

    edges = _core.objects(edges, argument, (Line, Arc, CurveEdge),
                          "an rmfsurf.Line, Arc or CurveEdge")
    array = ffi.new("RmfEdge[]", max(len(edges), 1))
    keep: List[Any] = []
    for i, e in enumerate(edges):
        name = "%s[%d]" % (argument, i)
        item = array[i]
        if isinstance(e, Line):
            item.kind = lib.RMF_EDGE_LINE
            item.points[0] = vec3(e.start, name + ".start")
            item.points[1] = vec3(e.end, name + ".end")
        elif isinstance(e, Arc):
            item.kind = lib.RMF_EDGE_ARC
            item.points[0] = vec3(e.start, name + ".start")
            item.points[1] = vec3(e.through, name + ".through")
            item.points[2] = vec3(e.end, name + ".end")
        elif isinstance(e, CurveEdge):
            item.kind = lib.RMF_EDGE_CURVE
            item.curve = as_curve(e.curve, name + ".curve")._ptr
            keep.append(e.curve)
    return array, len(edges), keep


@dataclass(frozen=True)
class SweepReport:
    """Figures of a wire sweep: the largest distance of the spine from the wire, the RMF
    angle error (radians), the largest |cos| of the angle between parameter lines (0:
    orthogonal, lines of curvature), the singularity margin (> 0: regular), the face
    count, and the frame error: the largest angle (radians) between the frames used and the
    frame asked for (`frame` of :func:`wire_sweep`; 0 for the RMF)."""

    spine_distance: float
    rmf_angle_error: float
    max_parameter_cosine: float
    singularity_margin: float
    face_count: int
    frame_error: float = 0.0


@dataclass(frozen=True)
class ShapeFace:
    """One face of a :class:`Shape`: kind "swept" (its `surface`) or "plane" (a cap in the
    plane through `plane_origin` with `plane_normal`, bounded by `loops`, the first the
    outer one); `spine_edge` and `profile_edge` say where a swept face comes from;
    `reversed` that the face's outward normal is −∂s/∂u × ∂s/∂v (or −plane_normal)."""

    kind: str
    surface: Optional[Surface]
    plane_origin: np.ndarray
    plane_normal: np.ndarray
    loops: List[Curve]
    spine_edge: int
    profile_edge: int
    reversed: bool


class Shape:
    """The result of :func:`wire_sweep`; freed when collected (its faces' surfaces and
    loops keep it alive)."""

    __slots__ = ("_ptr", "__weakref__")

    def __init__(self, pointer: Any) -> None:
        self._ptr = pointer

    @property
    def face_count(self) -> int:
        return int(lib.rmf_shape_face_count(self._ptr))

    @property
    def is_solid(self) -> bool:
        """Whether the faces close into a solid (a closed profile swept with caps)."""
        return bool(lib.rmf_shape_is_solid(self._ptr))

    def faces(self) -> List[ShapeFace]:
        """Every face, with borrowed surfaces and loop curves."""
        result = []
        face = ffi.new("RmfShapeFace *")
        loop = ffi.new("RmfCurve **")
        for i in range(self.face_count):
            call("rmf_shape_face", self._ptr, i, face)
            loops = []
            for k in range(face.loop_count):
                call("rmf_shape_face_loop", self._ptr, i, k, loop)
                loops.append(Curve(ffi.cast("RmfCurve *", loop[0]), self))
            swept = face.kind == lib.RMF_FACE_SWEPT
            surface = Surface(ffi.cast("RmfSurface *", face.surface), self) if swept else None
            result.append(ShapeFace("swept" if swept else "plane", surface,
                                    _core.from_vec3(face.plane_origin),
                                    _core.from_vec3(face.plane_normal), loops,
                                    int(face.spine_edge), int(face.profile_edge),
                                    bool(face.reversed)))
        return result

    def report(self) -> SweepReport:
        """The sweep's accuracy figures; the first call measures those the construction
        did not need (rmf_shape_report)."""
        r = ffi.new("RmfSweepReport *")
        call("rmf_shape_report", self._ptr, r)
        return SweepReport(r.spine_distance, r.rmf_angle_error, r.max_parameter_cosine,
                           r.singularity_margin, int(r.face_count), r.frame_error)

    def volume(self) -> float:
        """The volume the solid encloses, by Gauss–Legendre quadrature on every face patch
        (rmf_shape_volume): closer than OpenCascade's fixed-order rule behind build123d's
        ``volume`` and FreeCAD's ``Shape.Volume``. InvalidInputError for a sheet."""
        out = ffi.new("double *")
        call("rmf_shape_volume", self._ptr, out)
        return float(out[0])

    def write_step(self, path: Union[str, bytes, "os.PathLike[Any]"]) -> None:
        """Writes the shape as a STEP file (exact faces, a closed shell for a solid) at
        `path` (str, bytes or os.PathLike; InvalidInputError for a name with a NUL,
        FileError, an OSError, when the file cannot be written)."""
        call("rmf_shape_write_step", self._ptr, _core.path(path, "path"))

    def occ_brep(self) -> str:
        """The shape in OpenCascade's own B-rep text (``BRepTools.Read_s`` from a
        ``BytesIO``, FreeCAD's ``Part.Shape().importBrepFromString``): the kernel builds
        the solid or shell as it is, shared edges and faces' senses included, with no
        sewing or healing."""
        return self._occ_brep_bytes().decode("ascii")

    def _occ_brep_bytes(self) -> bytes:
        """:meth:`occ_brep` as the bytes a kernel reads, copied once out of the library."""
        n = ffi.new("size_t *")
        call("rmf_shape_occ_brep", self._ptr, ffi.NULL, 0, n)
        text = _uncleared("char[]", n[0] + 1)
        call("rmf_shape_occ_brep", self._ptr, text, n[0] + 1, n)
        return ffi.unpack(text, n[0])

    def occ_binary(self, reader: str = "bintools") -> bytes:
        """The shape in OpenCascade's binary B-rep: the shape of :meth:`occ_brep`, which
        the kernel reads several times faster. ``reader="bintools"``: ``BinTools.Read_s``
        from a ``BytesIO`` (OCP, build123d, CadQuery); ``"freecad"``: a file for FreeCAD's
        ``Part.Shape().importBinary``."""
        return _core.occ_binary("rmf_shape_occ_binary", self._ptr, reader)

    def __repr__(self) -> str:
        return "<rmfsurf.Shape %d faces%s>" % (self.face_count, ", solid" if self.is_solid else "")


def _is_empty(value: Any, name: str) -> bool:
    """Whether a sequence argument has no items (TypeError naming it if it is no sequence)."""
    if isinstance(value, (str, bytes)) or not isinstance(value, collections.abc.Sequence):
        raise TypeError("%s: expected a sequence of (at, profile[, holes]) items, got %s"
                        % (name, type(value).__name__))
    return len(value) == 0


def _sections(sections: Sequence[Any]) -> List[Tuple[float, Curve, List[Curve]]]:
    """The intermediate sections of a sweep through sections: (at, profile[, holes]) items
    as (fraction, curve, holes), each checked for its type and named ``sections[k]``."""
    result = []
    for k, item in enumerate(sections):
        name = "sections[%d]" % k
        if isinstance(item, (str, bytes)) or not isinstance(item, collections.abc.Sequence) \
                or len(item) not in (2, 3):
            raise TypeError("%s: expected (at, profile) or (at, profile, holes), got %r"
                            % (name, item))
        at = _core.number(item[0], name + ".at")
        curve = as_curve(item[1], name + ".profile")
        holes = _core.objects(item[2] if len(item) == 3 else (), name + ".holes", Curve,
                              "an rmfsurf.Curve")
        result.append((at, curve, holes))
    return result


def _drawn_sections(sections: Any, convert: Callable[[Any, str], Any]
                    ) -> Optional[List[Tuple[float, Curve, List[Curve]]]]:
    """The adapters' `sections`: ``(at, profile)`` items whose profiles are drawn at the
    path's start, each converted by ``convert(profile, "sections[k]")`` (the adapter's
    profile conversion in the start frame's coordinates, returning outer, holes, ...) into
    the ``(at, curve, holes)`` items :func:`wire_sweep` takes; None stays None."""
    if sections is None:
        return None
    _is_empty(sections, "sections")
    result = []
    for k, item in enumerate(sections):
        name = "sections[%d]" % k
        if isinstance(item, (str, bytes)) or not isinstance(item, collections.abc.Sequence) \
                or len(item) != 2:
            raise TypeError("%s: expected (at, profile), got %r" % (name, item))
        at = _core.number(item[0], name + ".at")
        outer, holes = convert(item[1], name)[:2]
        result.append((at, outer, holes))
    return result


def _renamed_sections(error: Any, count: int) -> Any:
    """The library's refusal of a sweep through sections with its ``sections[k]`` (k of the
    whole list: 0 the start profile, count + 1 the end profile) named as the caller's
    arguments: ``profile``/``holes``, ``sections[k - 1]``, ``end_profile``/``end_holes``."""
    def name(match: Any) -> str:
        k, field = int(match.group(1)), match.group(2) or ""
        if 1 <= k <= count:
            return "sections[%d]%s" % (k - 1, field)
        start = k == 0
        if field.startswith(".holes"):
            return ("holes" if start else "end_holes") + field[len(".holes"):]
        return "profile" if start else "end_profile"
    message = re.sub(r"\bsections\[(\d+)\]((?:\.at|\.profile|\.holes)(?:\[\d+\])?)?", name,
                     error.message)
    return type(error)(message, error.status, error.function)


def wire_sweep(edges: Union[Edge, Sequence[Edge]], profile: Curve,
               holes: Union[Curve, Sequence[Curve]] = (), *,
               solid: bool = True, corner: str = "round",
               corner_radius: Optional[float] = None, tolerance: float = 1e-4,
               join_tolerance: Optional[float] = None,
               initial_normal: Optional[ArrayLike] = None, twist: float = 0.0,
               closure_symmetry: int = 0, frame: SweepFrame = "rmf",
               scale: Tuple[float, float] = (1.0, 1.0),
               scale_knots: Optional[Sequence[Tuple[float, float]]] = None,
               method: str = "ph-rmf", end_profile: Optional[Curve] = None,
               end_holes: Union[Curve, Sequence[Curve]] = (),
               sections: Optional[Sequence[Tuple[Any, ...]]] = None,
               pipe_frame: str = "rmf") -> Shape:
    """Sweeps a closed profile (with `holes`) along a connected wire of `edges`.

    Args:
        edges: :class:`Line`, :class:`Arc` and :class:`CurveEdge` items, end to end (or
            one of them).
        profile: closed (or, for a sheet, open) planar curve in the frame at the wire's
            start: x along f2, y along f3, z along the tangent (z = 0 in the normal plane;
            any other plane across the wire is carried rigidly).
        holes: closed curves inside the profile, same coordinates (or one curve).
        solid: close the shape with planar caps (needs a closed profile).
        corner: "round" (the profile swept around the corner) or "miter".
        corner_radius: the rounding radius of "round" corners (None: the library's).
        tolerance: distance tolerance of the spine approximation.
        join_tolerance: how far consecutive edges may be apart (None: the library's).
        initial_normal: f2 at the start (None: the library's choice).
        twist: extra turn of the frame from start to end, radians.
        closure_symmetry: for a closed wire, the profile's symmetry order k ≥ 1 so that
            the frame closes modulo 2π/k without a seam; 0 is taken as 1 (ignored for an
            open wire; docs/c-api.md, "Parameters").
        frame: how the profile turns about the tangent: "rmf" (the rotation-minimizing
            frame, the default), "frenet" (f2 along the principal normal at the start, then
            turning with the torsion: along a helix the profile's points trace helices, as
            a thread needs), ("fixed", (x, y, z)) / {"fixed": (x, y, z)} (f2 along that
            direction projected onto the normal plane) or ("guide", edges) / {"guide":
            edges} (f2 towards where the guide curve of these edges — :class:`Line`,
            :class:`Arc` and :class:`CurveEdge` items as `edges`, in any order and
            orientation — crosses the normal plane, the crossing nearest the wire: the
            profile turns to follow a second rail, OpenCascade's auxiliary mode; refused
            where the guide does not cross a normal plane, or touches the wire). A frame
            other than "rmf" sets f2 itself: `initial_normal` must then be None.
        scale: the profile's scale (start, end) about the spine, linear in arc length
            between: two finite positive numbers, equal on a closed wire ((1, 0.5) makes a
            circle along a line a frustum).
        scale_knots: scales the law passes through between its start and end: (fraction,
            scale) pairs, the fraction of the wire's length strictly increasing in (0, 1),
            the scale finite and positive (None, the default: none). σ runs from scale[0]
            through every knot to scale[1], linear in arc length between them
            (``scale=(1, 1), scale_knots=[(0.25, 2), (0.75, 0.5)]`` makes a circle along a
            line a chain of three frustums).
        method: how curve edges are swept: "ph-rmf" (the default: a PH cubic spline within
            `tolerance` and its rational approximation of the RMF), "mobius" (Möbius images
            of planar PH cubics) or "rrmf" (RRMF quintics) — spines with exact rational
            RMFs, so the parameter lines of their faces are orthogonal to rounding
            (``report().max_parameter_cosine`` ~1e-14, ~1e-7 with "ph-rmf"). Lines and
            arcs are exact whatever the method. "mobius" and "rrmf" take a constant
            `scale` only (no knots of other scales).
        end_profile: the section at the wire's end (None: the profile all along), in the
            profile's coordinates (x along f2, y along f3 of the frame, z = 0): the section
            blends linearly in arc length from `profile` to it, loop to loop and corner to
            corner (rmf_wire_sweep_between; a circle into a smaller concentric circle is
            the frustum of `scale`). Open wires only, with a constant `scale` (and
            `scale_knots`), both profiles in the normal plane.
        end_holes: the end profile's holes (or one curve), as many as `holes`, matched in
            order; only with `end_profile`.
        sections: the sections the sweep passes through between `profile` (at 0) and
            `end_profile` (at 1, required with them): ``(at, profile)`` or ``(at, profile,
            holes)`` items, `at` the fraction of the wire's length strictly increasing in
            (0, 1), each profile an rmfsurf.Curve in the frame at its station as `profile`
            is in the frame at the start (x along f2, y along f3, z = 0), with as many holes
            (one curve or a sequence) as `holes`. The section blends linearly in arc length
            from each into the next, every loop matched to its counterpart in all of them
            (rmf_wire_sweep_through): circles of radii 0.5, 1, 0.3 at 0, 0.25, 1 along a
            line are a chain of two frustums. Refusals name ``sections[k]`` (k counting
            these items) or the field, e.g. ``sections[0].at``.
        pipe_frame: how a round profile — every loop a circle about the wire in its
            normal plane, a pipe — is swept along curve edges: "rmf" (the default, as
            every profile: parameter lines orthogonal) or "lightest" (the PH spline's
            Euler–Rodrigues frame: the same surface in faces of degree 5 along the wire
            instead of 9, its parameter lines not orthogonal; on open wires with the RMF
            untwisted, "ph-rmf" and no `end_profile`, the RMF elsewhere). Other profiles
            ignore it.
    """
    _require_wire_sweep()
    array, count, keep = _edges(edges)
    prof = as_curve(profile, "profile")
    hole_list = _core.objects(holes, "holes", Curve, "an rmfsurf.Curve")
    hole_array = ffi.new("RmfCurve *[]", [h._ptr for h in hole_list] or [ffi.NULL])
    options = ffi.new("RmfWireSweepOptions *")
    call("rmf_wire_sweep_options_init", options)
    options.tolerance = _core.number(tolerance, "tolerance")
    if join_tolerance is not None:
        options.join_tolerance = _core.number(join_tolerance, "join_tolerance")
    options.corner = _core.choice(corner, "corner", corners())
    if corner_radius is not None:
        options.corner_radius = _core.number(corner_radius, "corner_radius")
    if initial_normal is not None:
        options.initial_normal = _core.vec3(initial_normal, "initial_normal")
    options.twist = _core.number(twist, "twist")
    options.closure_symmetry = _core.integer(closure_symmetry, "closure_symmetry", "uint32_t")
    options.solid = 1 if solid else 0
    options.frame, argument = _sweep_frame(frame)
    guide_array = None
    if options.frame == lib.RMF_FRAME_FIXED:
        options.frame_direction = _core.vec3(argument, "frame")
    elif options.frame == lib.RMF_FRAME_GUIDE:
        guide_array, options.guide_edge_count, guide_keep = _edges(argument, "frame", True)
        options.guide_edges = guide_array
        keep += guide_keep
    options.scale_start, options.scale_end = _scale(scale)
    knots = _scale_knots(scale_knots)
    # Kept alive until the call: the options borrow the doubles.
    knot_doubles = ffi.new("double[]", [x for knot in knots for x in knot] or [0.0])
    if knots:
        options.scale_knots = knot_doubles
        options.scale_knot_count = len(knots)
    options.method = _wire_method(method)
    options.pipe_frame = _core.choice(pipe_frame, "pipe_frame", PIPE_FRAMES)
    out = ffi.new("RmfShape **")
    if sections is not None and not _is_empty(sections, "sections"):
        if end_profile is None:
            raise _core._refused("sections", "need end_profile: the sweep runs from profile "
                                 "at the start through the sections to end_profile at the "
                                 "end")
        end = as_curve(end_profile, "end_profile")
        end_list = _core.objects(end_holes, "end_holes", Curve, "an rmfsurf.Curve")
        stations = ([(0.0, prof, hole_list)] + _sections(sections)
                    + [(1.0, end, end_list)])
        arrays = [ffi.new("RmfCurve *[]", [h._ptr for h in holes] or [ffi.NULL])
                  for _, _, holes in stations]
        c_sections = ffi.new("RmfWireSection[]", len(stations))
        for c, (at, curve, holes), hole_array_k in zip(c_sections, stations, arrays):
            c.at, c.profile, c.holes, c.hole_count = at, curve._ptr, hole_array_k, len(holes)
        try:
            call("rmf_wire_sweep_through", array, count, c_sections, len(stations), options,
                 out)
        except _core.RmfError as error:
            raise _renamed_sections(error, len(stations) - 2) from None
        del stations, arrays, c_sections
    elif end_profile is None:
        if _core.objects(end_holes, "end_holes", Curve, "an rmfsurf.Curve"):
            raise _core._refused("end_holes", "holes of the end profile need end_profile")
        call("rmf_wire_sweep", array, count, prof._ptr, hole_array, len(hole_list), options,
             out)
    else:
        end = as_curve(end_profile, "end_profile")
        end_list = _core.objects(end_holes, "end_holes", Curve, "an rmfsurf.Curve")
        end_array = ffi.new("RmfCurve *[]", [h._ptr for h in end_list] or [ffi.NULL])
        call("rmf_wire_sweep_between", array, count, prof._ptr, hole_array, len(hole_list),
             end._ptr, end_array, len(end_list), options, out)
    del keep, knot_doubles, guide_array
    return Shape(_core.owned("shape", out[0]))
