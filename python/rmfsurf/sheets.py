"""Sheet-metal parts (issue 15 of rmfsurf; Leopoldseder & Pottmann's cone splines): the
transition piece between two closed convex planar curves — square-to-round, round-to-round
with offset or inclined planes, obround, polygon to polygon — with a sheet thickness and a
K-factor: its layers (inner, neutral, outer faces) as exact NURBS, the closed solid between
them, the flat pattern of the neutral layer for the cutter (lines and circular arcs, bend
lines), and the exact isometry between flat and formed for marks (holes, slots, text).

A :class:`SheetPart` is a :class:`rmfsurf.ConeSpline` (its pieces are the designed
surface's, from rmf_sheet_part_cone_spline) with the part's own methods (the
rmf_sheet_part_* calls).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, List, Tuple

import numpy as np

from . import _core
from ._core import call, ffi, lib
from .cone_splines import ConeSpline
from .curves import ArrayLike, Curve, as_curve
from .surfaces import Surface, as_surface

REFERENCES: Dict[str, int] = {
    "inner": lib.RMF_SHEET_REFERENCE_INNER,
    "neutral": lib.RMF_SHEET_REFERENCE_NEUTRAL,
    "outer": lib.RMF_SHEET_REFERENCE_OUTER,
}
LAYERS: Dict[str, int] = {
    "reference": lib.RMF_SHEET_LAYER_REFERENCE,
    "inner": lib.RMF_SHEET_LAYER_INNER,
    "neutral": lib.RMF_SHEET_LAYER_NEUTRAL,
    "outer": lib.RMF_SHEET_LAYER_OUTER,
}
SIDES: Dict[str, int] = {"first": lib.RMF_SHEET_SIDE_FIRST, "second": lib.RMF_SHEET_SIDE_SECOND}
FORMATS: Dict[str, int] = {
    "step": lib.RMF_SHEET_FORMAT_STEP_SOLID,
    "flat_step": lib.RMF_SHEET_FORMAT_STEP_FLAT,
    "dxf": lib.RMF_SHEET_FORMAT_DXF,
    "svg": lib.RMF_SHEET_FORMAT_SVG,
    "brep": lib.RMF_SHEET_FORMAT_OCC_BREP,
}


@dataclass(frozen=True)
class SheetReport:
    """What a part's construction measured (caller's units): pieces, whether it closes on
    itself, the distance of its surface from the designed developable and of its first and
    second edge from the input's curves, the smallest bend radius of the designed surface,
    and the distances of the inner, neutral and outer layer from it (along the normal from
    the concave to the convex side)."""

    pieces: int
    closed: bool
    deviation: float
    edge_distance: Tuple[float, float]
    bend_radius: float
    inner: float
    neutral: float
    outer: float


@dataclass(frozen=True)
class FlatEdge:
    """An edge of a flat pattern: on layer "cut" (the outline) or "bend"; a "line" from
    `start` to `end`, or an "arc" about `center` of `radius` through the signed angle
    `sweep` (counter-clockwise when positive)."""

    layer: str
    kind: str
    start: np.ndarray
    end: np.ndarray
    center: np.ndarray
    radius: float
    sweep: float


class SheetPart(ConeSpline):
    """A sheet-metal part (rmf_sheet_part_transition, rmf_sheet_part_between_rails,
    rmf_sheet_part_tangent) and its designed surface's cone spline; freed when collected."""

    __slots__ = ("_part",)

    @classmethod
    def _made(cls, out: Any) -> "SheetPart":
        """The part an ``RmfSheetPart **`` received, with its cone spline."""
        part = _core.owned("sheet_part", out[0])
        spline = _core.out_pointer("RmfConeSpline")
        call("rmf_sheet_part_cone_spline", part, spline)
        made = cls(_core.owned("cone_spline", spline[0]))
        made._part = part
        return made

    def report(self) -> SheetReport:
        r = ffi.new("RmfSheetReport *")
        call("rmf_sheet_part_report", self._part, r)
        return SheetReport(int(r.pieces), bool(r.closed), r.deviation,
                           (r.edge_distance[0], r.edge_distance[1]), r.bend_radius, r.inner,
                           r.neutral, r.outer)

    def layer(self, layer: str = "neutral") -> Surface:
        """A layer ("reference", "inner", "neutral", "outer") as one NURBS surface: u along
        the rulings from the first to the second edge, piece k on v ∈ [k, k + 1]."""
        out = _core.out_pointer("RmfSurface")
        call("rmf_sheet_part_surface", self._part, _core.choice(layer, "layer", LAYERS), out)
        return Surface._owned(out)

    def edge(self, layer: str = "reference", side: str = "first") -> Curve:
        """An edge of the formed part: the boundary curve `side` ("first": a transition's
        bottom, "second": its top) of `layer`."""
        out = _core.out_pointer("RmfCurve")
        call("rmf_sheet_part_boundary", self._part, _core.choice(layer, "layer", LAYERS),
             _core.choice(side, "side", SIDES), out)
        return Curve._owned(out)

    def flat_edges(self) -> List[FlatEdge]:
        """The flat pattern of the neutral layer: the closed, counter-clockwise outline
        ("cut") of lines and arcs, then the bend lines ("bend")."""
        n = ffi.new("size_t *")
        call("rmf_sheet_part_flat_pattern", self._part, ffi.NULL, 0, n)
        edges = ffi.new("RmfFlatEdge[]", n[0])
        call("rmf_sheet_part_flat_pattern", self._part, edges, n[0], n)
        xy = lambda p: np.array((p.x, p.y))  # noqa: E731
        return [FlatEdge("cut" if e.layer == lib.RMF_FLAT_CUT else "bend",
                         "arc" if e.kind == lib.RMF_FLAT_EDGE_ARC else "line",
                         xy(getattr(e, "from")), xy(e.to), xy(e.center), e.radius, e.sweep)
                for e in edges]

    def flat_to_surface(self, points: ArrayLike, layer: str = "neutral",
                        normals: bool = False) -> Any:
        """Marks from the flat pattern to the formed part: flat points (n, 2) to points
        (n, 3) of `layer` (and, with ``normals=True``, the unit normals there), by the
        exact isometry of the development."""
        flat = _flat_points(points, "points")
        n = flat.shape[0]
        out = np.empty((n, 3))
        out_normals = np.empty((n, 3)) if normals else None
        call("rmf_sheet_part_flat_to_surface", self._part,
             ffi.cast("RmfVec2 *", ffi.from_buffer(flat)) if n else ffi.NULL, n,
             _core.choice(layer, "layer", LAYERS), _core.vec3_array(out),
             _core.vec3_array(out_normals) if normals else ffi.NULL)
        return (out, out_normals) if normals else out

    def surface_to_flat(self, points: ArrayLike, layer: str = "neutral",
                        max_distance: float = 1e-9) -> np.ndarray:
        """Marks from the formed part to the flat pattern: points (n, 3) on `layer` (within
        `max_distance`) to flat points (n, 2)."""
        p = _core.points(points, "points")
        n = p.shape[0]
        out = np.empty((n, 2))
        call("rmf_sheet_part_surface_to_flat", self._part, _core.vec3_array(p), n,
             _core.choice(layer, "layer", LAYERS), _core.number(max_distance, "max_distance"),
             ffi.cast("RmfVec2 *", ffi.from_buffer(out)) if n else ffi.NULL)
        return out

    def export(self, format: str = "step") -> str:
        """The text of a file of the part: "step" (the formed solid), "flat_step" (the flat
        pattern as a planar face), "dxf" or "svg" (the flat pattern), "brep" (the formed
        solid in OpenCascade's own B-rep text, which ``BRepTools.Read`` and FreeCAD's
        ``importBrepFromString`` build as it is)."""
        code = _core.choice(format, "format", FORMATS)
        n = ffi.new("size_t *")
        call("rmf_sheet_part_export", self._part, code, ffi.NULL, 0, n)
        text = ffi.new("char[]", n[0] + 1)
        call("rmf_sheet_part_export", self._part, code, text, n[0] + 1, n)
        return ffi.string(text, n[0]).decode("ascii")


    def occ_binary(self, reader: str = "bintools") -> bytes:
        """The formed solid of ``export("brep")`` in OpenCascade's binary B-rep, which the
        kernel reads several times faster: for ``BinTools.Read_s`` (``reader="bintools"``)
        or FreeCAD's ``Part.Shape().importBinary`` (``"freecad"``)."""
        out = ffi.new("RmfBrep **")
        call("rmf_sheet_part_brep", self._part, out)
        brep = _core.owned("brep", out[0])
        return _core.occ_binary("rmf_brep_occ_binary", brep, reader)


def _flat_points(value: ArrayLike, name: str) -> np.ndarray:
    # Finite here: the library calls them "flat".
    return _core.rows(value, name, 2, "an array of flat points (shape (n, 2))", finite_only=True)


def _options(thickness: float, k_factor: float, tolerance: float, reference: str,
             flat_tolerance: float, max_pieces: int) -> Any:
    """An RmfSheetOptions from the keyword arguments, each checked by name."""
    options = ffi.new("RmfSheetOptions *")
    call("rmf_sheet_options_init", options)
    options.thickness = _core.number(thickness, "thickness")
    options.k_factor = _core.number(k_factor, "k_factor")
    options.tolerance = _core.number(tolerance, "tolerance")
    options.reference = _core.choice(reference, "reference", REFERENCES)
    options.flat_tolerance = _core.number(flat_tolerance, "flat_tolerance")
    options.max_pieces = _core.integer(max_pieces, "max_pieces", "size_t", 2)
    return options


def transition(bottom: Curve, top: Curve, *, thickness: float = 1.0, k_factor: float = 0.5,
               tolerance: float = 1e-4, reference: str = "inner", flat_tolerance: float = 0.0,
               max_pieces: int = 10000) -> SheetPart:
    """The transition piece between two closed convex planar curves (e.g. a degree-1
    polygon and a circle of rational quadratics; see rmf_sheet_part_transition): the
    convex hull surface of the two, flat triangles, cones from corners, creases and cone
    splines between arcs, each piece trimmed exactly by the curves' planes.

    Args:
        bottom, top: the two curves (the first and second edge of the part).
        thickness: the sheet thickness t > 0.
        k_factor: the neutral layer's distance from the inner face, in t (0 ≤ k ≤ 1).
        tolerance: largest distance of the surface from the hull and of the edges from the
            curves.
        reference: which face of the sheet passes through the curves: "inner" (the
            sheet lies outside, the only choice with polygon corners), "neutral", "outer".
        flat_tolerance: largest distance of the flat outline's biarcs from the exact
            developed edge (0: the tolerance).
        max_pieces: the most cone pieces.
    """
    options = _options(thickness, k_factor, tolerance, reference, flat_tolerance, max_pieces)
    out = _core.out_pointer("RmfSheetPart")
    call("rmf_sheet_part_transition", as_curve(bottom, "bottom")._ptr,
         as_curve(top, "top")._ptr, options, out)
    return SheetPart._made(out)


def part_between_rails(surface: Surface, *, thickness: float = 1.0, k_factor: float = 0.5,
                       tolerance: float = 1e-4, reference: str = "inner",
                       flat_tolerance: float = 0.0, max_pieces: int = 10000) -> SheetPart:
    """The part of a developable ruled surface between its two rails (see
    rmf_sheet_part_between_rails): `surface` has degree 1 and two poles in u (rulings along u,
    e.g. ``Surface.from_nurbs`` of two rails), v along the rails. The result is a cone
    spline within half the tolerance, no cone vertex on the part, trimmed on every piece
    between the rails, each edge within the tolerance of its rail. Keyword arguments as
    for :func:`transition`.
    """
    options = _options(thickness, k_factor, tolerance, reference, flat_tolerance, max_pieces)
    out = _core.out_pointer("RmfSheetPart")
    call("rmf_sheet_part_between_rails", as_surface(surface, "surface")._ptr, options, out)
    return SheetPart._made(out)


def tangent_part(curve: Curve, v_min: float, v_max: float, *, thickness: float = 1.0,
                 k_factor: float = 0.5, tolerance: float = 1e-4, reference: str = "inner",
                 flat_tolerance: float = 0.0, max_pieces: int = 10000) -> SheetPart:
    """The part of the tangent surface x(t) + v·x′(t)/|x′(t)| of a regular curve between
    the rails v = v_min and v = v_max (0 outside [v_min, v_max]; see
    rmf_sheet_part_tangent). Keyword arguments as for :func:`transition`.
    """
    options = _options(thickness, k_factor, tolerance, reference, flat_tolerance, max_pieces)
    out = _core.out_pointer("RmfSheetPart")
    call("rmf_sheet_part_tangent", as_curve(curve, "curve")._ptr,
         _core.number(v_min, "v_min"), _core.number(v_max, "v_max"), options, out)
    return SheetPart._made(out)
