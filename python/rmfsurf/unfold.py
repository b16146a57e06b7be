"""Unfolding the caller's own faces (rmf_brep_create, rmf_face_developability,
rmf_unfold_face): a face handed over as plain B-rep data — its NURBS surface or plane, its
edges' NURBS curves, its loops of edge uses — is told how developable it is, and a
developable one is unrolled into its exact flat pattern: the outline and the holes as lines
and circular arcs, the bend lines, the area, the DXF for the cutter, and the isometry
between flat and formed for marks.

Planes, circular cylinders and right cones (recognized from the geometry: a cylinder
converted to a rational B-spline is still a circular cylinder) unroll exactly in closed form;
every other developable of degree 1 along its rulings (general cylinders and cones, tangent
developables, B-spline developables) through its cone spline within the tolerance.

The CAD adapters build the B-rep from their own faces: :func:`rmfsurf.ocp.unfold` (build123d,
CadQuery, OCP) and :func:`rmfsurf.freecad.unfold` (FreeCAD Part faces).

A plate 4 × 3 with a square hole, unrolled (it is a plane: its pattern is itself)::

    import numpy as np, rmfsurf
    from rmfsurf.unfold import BrepEdge, BrepFace, line_curve
    corners = [(0, 0, 0), (4, 0, 0), (4, 3, 0), (0, 3, 0),
               (1, 1, 0), (2, 1, 0), (2, 2, 0), (1, 2, 0)]
    edges = [BrepEdge(line_curve(corners[i], corners[j]), i, j)
             for i, j in [(0, 1), (1, 2), (2, 3), (3, 0), (4, 7), (7, 6), (6, 5), (5, 4)]]
    face = BrepFace([[(0, True), (1, True), (2, True), (3, True)],
                     [(4, True), (5, True), (6, True), (7, True)]],
                    plane=((0, 0, 0), (0, 0, 1), (1, 0, 0)))
    brep = rmfsurf.Brep.create(corners, edges, [face])
    flat = rmfsurf.unfold_face(brep)
    assert flat.report.kind == "plane" and abs(flat.area - 11.0) < 1e-12
"""

from __future__ import annotations

import numbers
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import call, ffi, lib
from .curves import ArrayLike, Curve, NurbsCurve
from .sheets import FlatEdge
from .surfaces import NurbsSurface, Surface

__all__ = ["Bend", "Brep", "FlatPattern", "checked_k_factor", "BrepEdge", "BrepFace", "Developability", "UnfoldedBody",
           "UnfoldedFace", "developability", "line_curve", "unfold_body", "unfold_face",
           "SURFACE_KINDS"]

#: RmfDevelopability.kind by name.
SURFACE_KINDS: Dict[str, int] = {
    "plane": lib.RMF_SURFACE_PLANE,
    "circular_cylinder": lib.RMF_SURFACE_CIRCULAR_CYLINDER,
    "right_cone": lib.RMF_SURFACE_RIGHT_CONE,
    "general_cylinder": lib.RMF_SURFACE_GENERAL_CYLINDER,
    "general_cone": lib.RMF_SURFACE_GENERAL_CONE,
    "tangent_developable": lib.RMF_SURFACE_TANGENT_DEVELOPABLE,
    "ruled_developable": lib.RMF_SURFACE_RULED_DEVELOPABLE,
    "not_developable": lib.RMF_SURFACE_NOT_DEVELOPABLE,
}
_KIND_NAMES = {code: name for name, code in SURFACE_KINDS.items()}


@dataclass(frozen=True)
class Developability:
    """How developable a face is (RmfDevelopability).

    Attributes:
        kind: "plane", "circular_cylinder", "right_cone", "general_cylinder",
            "general_cone", "tangent_developable", "ruled_developable" or
            "not_developable".
        curvature: the largest |K|·size² sampled over the face's surface (K the Gaussian
            curvature, size the diagonal of its bounding box): round-off for developables.
        stretch: for a face that is not developable, the largest relative change of length
            an unrolling needs (measured on a least-squares flattening); 0 for developables.
        fit_error: of an unrolled face, the largest distance of its cone spline from the
            face (0 where it unrolls in closed form: planes, circular cylinders, right
            cones); 0 in :func:`developability`'s answer.
    """

    kind: str
    curvature: float
    stretch: float
    fit_error: float = 0.0

    @property
    def developable(self) -> bool:
        """Whether the face unrolls without stretching."""
        return self.kind != "not_developable"


def _report(r: Any) -> Developability:
    return Developability(_KIND_NAMES.get(int(r.kind), "kind %d" % r.kind), float(r.curvature),
                          float(r.stretch), float(r.fit_error))


# ---------------------------------------------------------------------------------------
# The caller's B-rep as plain data


def line_curve(start: ArrayLike, end: ArrayLike) -> NurbsCurve:
    """The straight edge from `start` to `end` as NURBS data (degree 1, two poles); with
    ``start == end`` the curve of a degenerate edge (a cone's apex)."""
    a = _core.vector(start, "start", finite_only=True)
    b = _core.vector(end, "end", finite_only=True)
    return NurbsCurve(1, np.array([a, b]), np.ones(2), np.array([0.0, 0.0, 1.0, 1.0]))


@dataclass(frozen=True)
class BrepEdge:
    """An edge of a B-rep handed in: its 3-D curve (NURBS data, :class:`rmfsurf.NurbsCurve`
    with knots listed one by one, or an :class:`rmfsurf.Curve`) from vertex `start` (at the
    curve's first knot) to vertex `end`. A `degenerate` edge is a side of a face collapsed to
    a point (a cone's apex): `start` == `end` and the curve is that point, e.g.
    ``line_curve(apex, apex)``; the unfold skips it."""

    curve: Union[NurbsCurve, Curve]
    start: int
    end: int
    degenerate: bool = False


@dataclass(frozen=True)
class BrepFace:
    """A face of a B-rep handed in.

    Attributes:
        loops: the face's loops, the outer bound first, then the holes; each a sequence of
            edge uses ``(edge index, forward)``, each starting where the one before ends
            (``forward`` False: the loop runs against the edge's curve). A seam (where a
            face closes on itself, a full tube) is one edge used twice, once each way.
        surface: the face's surface as NURBS data (:class:`rmfsurf.NurbsSurface`, poles[i, j]
            with i along u, knots listed one by one) or an :class:`rmfsurf.Surface`; or
        plane: instead of a surface, (origin, unit normal, unit x axis) of a plane.
        same_sense: whether the face's normal (out of a solid) is its surface's.
    """

    loops: Sequence[Sequence[Tuple[int, bool]]]
    surface: Optional[Union[NurbsSurface, Surface]] = None
    plane: Optional[Tuple[ArrayLike, ArrayLike, ArrayLike]] = None
    same_sense: bool = True


def _curve_data(curve: Any, name: str) -> NurbsCurve:
    if isinstance(curve, Curve):
        return curve.nurbs()
    if not isinstance(curve, NurbsCurve):
        raise TypeError("%s: expected an rmfsurf.NurbsCurve or an rmfsurf.Curve, got %s"
                        % (name, type(curve).__name__))
    return curve


def _surface_data(surface: Any, name: str) -> NurbsSurface:
    if isinstance(surface, Surface):
        return surface.nurbs()
    if not isinstance(surface, NurbsSurface):
        raise TypeError("%s: expected an rmfsurf.NurbsSurface or an rmfsurf.Surface, got %s"
                        % (name, type(surface).__name__))
    return surface


def _flag(value: Any, name: str) -> int:
    if isinstance(value, (bool, np.bool_)) or value in (0, 1):
        return 1 if value else 0
    raise TypeError("%s: expected a bool, got %s" % (name, type(value).__name__))


class _Arrays:
    """The C arrays of one rmf_brep_create call, kept alive until it returns."""

    def __init__(self) -> None:
        self.alive: List[Any] = []

    def points(self, value: Any, name: str) -> Tuple[int, Any]:
        array = _core.rows(value, name, 3, "an array of 3-D points (shape (n, 3))")
        self.alive.append(array)
        return array.shape[0], _core.vec3_array(array)

    def doubles(self, value: Any, name: str) -> Tuple[int, Any]:
        array = _core.doubles(value, name)
        self.alive.append(array)
        return array.shape[0], _core.double_array(array)

    def nurbs_curve(self, view: Any, curve: Any, name: str) -> None:
        d = _curve_data(curve, name)
        view.degree = _core.integer(d.degree, name + ".degree", "uint32_t", 1)
        view.pole_count, view.poles = self.points(d.poles, name + ".poles")
        weights_count, view.weights = self.doubles(d.weights, name + ".weights")
        view.knot_count, view.knots = self.doubles(d.knots, name + ".knots")
        if weights_count != view.pole_count:
            raise ValueError("%s.weights: expected %d weights (one per pole), got %d"
                             % (name, view.pole_count, weights_count))

    def nurbs_surface(self, view: Any, surface: Any, name: str) -> None:
        d = _surface_data(surface, name)
        poles = _core.float_array(d.poles, name + ".poles", "a grid of 3-D points")
        if poles.ndim != 3 or poles.shape[2] != 3:
            raise ValueError("%s.poles: expected an array of shape (nu, nv, 3), got shape %s"
                             % (name, poles.shape))
        nu, nv = poles.shape[:2]
        weights = _core.float_array(d.weights, name + ".weights", "a grid of weights")
        if weights.shape != (nu, nv):
            raise ValueError("%s.weights: expected shape %s, got %s"
                             % (name, (nu, nv), weights.shape))
        view.degree_u = _core.integer(d.degree_u, name + ".degree_u", "uint32_t", 1)
        view.degree_v = _core.integer(d.degree_v, name + ".degree_v", "uint32_t", 1)
        view.pole_count_u, view.pole_count_v = nu, nv
        _, view.poles = self.points(poles.reshape(nu * nv, 3), name + ".poles")
        _, view.weights = self.doubles(weights.reshape(nu * nv), name + ".weights")
        view.knot_count_u, view.knots_u = self.doubles(d.knots_u, name + ".knots_u")
        view.knot_count_v, view.knots_v = self.doubles(d.knots_v, name + ".knots_v")


def _vec3(view: Any, value: Any, name: str) -> None:
    v = _core.vector(value, name)
    view.x, view.y, view.z = float(v[0]), float(v[1]), float(v[2])


class Brep:
    """A B-rep handed to the library (rmf_brep_create): faces with their surfaces, edges
    with their curves, loops of edge uses; freed when collected. Make one with
    :meth:`create`; query it with :func:`developability` and :func:`unfold_face`."""

    __slots__ = ("_ptr", "face_count", "__weakref__")

    def __init__(self, pointer: Any, face_count: int) -> None:
        self._ptr = pointer
        self.face_count = face_count

    @classmethod
    def create(cls, vertices: ArrayLike, edges: Sequence[BrepEdge], faces: Sequence[BrepFace],
               solid: bool = False) -> "Brep":
        """The B-rep of `vertices` ((n, 3) points), `edges` (:class:`BrepEdge`, their curves
        and vertex indices) and `faces` (:class:`BrepFace`, their surfaces or planes and
        their loops of edge uses); `solid` if the faces bound a solid. The library checks the
        counts, the NURBS data and the indices (InvalidInputError naming
        ``edges[e]``, ``faces[f]``, ``uses[k]``: the uses are numbered over all loops of
        all faces in order)."""
        arrays = _Arrays()
        vertex_count, vertex_pointer = arrays.points(_core.points(vertices, "vertices"),
                                                     "vertices")
        edge_list = _core.objects(edges, "edges", BrepEdge, "an rmfsurf.BrepEdge")
        face_list = _core.objects(faces, "faces", BrepFace, "an rmfsurf.BrepFace")
        c_edges = ffi.new("RmfBrepEdge[]", max(1, len(edge_list)))
        for e, edge in enumerate(edge_list):
            name = "edges[%d]" % e
            view = c_edges[e]
            view.start = _core.integer(edge.start, name + ".start", "size_t")
            view.end = _core.integer(edge.end, name + ".end", "size_t")
            view.degenerate = _flag(edge.degenerate, name + ".degenerate")
            arrays.nurbs_curve(view.curve, edge.curve, name + ".curve")
        c_faces = ffi.new("RmfBrepFace[]", max(1, len(face_list)))
        loops: List[Tuple[int, int]] = []
        uses: List[Tuple[int, int]] = []
        for f, face in enumerate(face_list):
            name = "faces[%d]" % f
            view = c_faces[f]
            if (face.surface is None) == (face.plane is None):
                raise ValueError("%s: give either a surface or a plane" % name)
            if face.surface is not None:
                view.kind = lib.RMF_BREP_SURFACE_NURBS
                arrays.nurbs_surface(view.nurbs, face.surface, name + ".surface")
            else:
                try:
                    origin, normal, x_axis = face.plane
                except (TypeError, ValueError):
                    raise TypeError("%s.plane: expected (origin, normal, x_axis)" % name) from None
                view.kind = lib.RMF_BREP_SURFACE_PLANE
                _vec3(view.plane_origin, origin, name + ".plane[0]")
                _vec3(view.plane_normal, normal, name + ".plane[1]")
                _vec3(view.plane_x_axis, x_axis, name + ".plane[2]")
            view.same_sense = _flag(face.same_sense, name + ".same_sense")
            face_loops = list(face.loops)
            if not face_loops:
                raise ValueError("%s.loops: a face needs its outer loop" % name)
            view.loop_count = len(face_loops)
            for j, loop in enumerate(face_loops):
                loop_uses = list(loop)
                loops.append((1 if j == 0 else 0, len(loop_uses)))
                for k, use in enumerate(loop_uses):
                    use_name = "%s.loops[%d][%d]" % (name, j, k)
                    try:
                        edge_index, forward = use
                    except (TypeError, ValueError):
                        raise TypeError("%s: expected (edge index, forward)" % use_name) from None
                    uses.append((_core.integer(edge_index, use_name + "[0]", "size_t"),
                                 _flag(forward, use_name + "[1]")))
        c_loops = ffi.new("RmfBrepLoop[]", max(1, len(loops)))
        for view, (outer, count) in zip(c_loops, loops):
            view.outer, view.use_count = outer, count
        c_uses = ffi.new("RmfBrepUse[]", max(1, len(uses)))
        for view, (edge_index, forward) in zip(c_uses, uses):
            view.edge, view.forward = edge_index, forward
            view.pcurve_kind = lib.RMF_PCURVE_NONE
        data = ffi.new("RmfBrepInput *")
        data.vertex_count, data.vertices = vertex_count, vertex_pointer
        data.edge_count, data.edges = len(edge_list), c_edges
        data.face_count, data.faces = len(face_list), c_faces
        data.loops, data.uses = c_loops, c_uses
        data.solid = _flag(solid, "solid")
        out = _core.out_pointer("RmfBrep")
        call("rmf_brep_create", data, out)
        return cls(_core.owned("brep", out[0]), len(face_list))


def _brep(value: Any) -> Brep:
    return _core.instance(value, "brep", Brep, "an rmfsurf.Brep")


def developability(brep: Brep, face: int = 0) -> Developability:
    """How developable face `face` of `brep` is (rmf_face_developability): the kind of its
    surface, told from its geometry, its largest |K|·size², and for a face that is not
    developable the stretch an unrolling would need, measured."""
    b = _brep(brep)
    out = ffi.new("RmfDevelopability *")
    out.struct_size = ffi.sizeof("RmfDevelopability")
    call("rmf_face_developability", b._ptr, _core.integer(face, "face", "size_t"), out)
    return _report(out)


def _flat_edges(edges: Any) -> List[FlatEdge]:
    xy = lambda p: np.array((p.x, p.y))  # noqa: E731
    return [FlatEdge("cut" if e.layer == lib.RMF_FLAT_CUT else "bend",
                     "arc" if e.kind == lib.RMF_FLAT_EDGE_ARC else "line",
                     xy(getattr(e, "from")), xy(e.to), xy(e.center), float(e.radius),
                     float(e.sweep))
            for e in edges]


def edge_length(edge: FlatEdge) -> float:
    """The length of a flat edge: a line's, or an arc's radius × |sweep|."""
    if edge.kind == "arc":
        return float(edge.radius * abs(edge.sweep))
    return float(np.linalg.norm(edge.end - edge.start))


class UnfoldedFace:
    """A face unrolled into the plane z = 0 (rmf_unfold_face), seen from its normal side;
    freed when collected.

    Attributes:
        outline: the cutting outline, counter-clockwise: a list of :class:`FlatEdge`
            (lines and circular arcs, layer "cut"), each starting where the one before
            ends.
        holes: the holes, each a clockwise list of :class:`FlatEdge`.
        bend_lines: the rulings where the pieces of a cone spline meet, clipped to the face
            (layer "bend"; none for planes, circular cylinders and right cones).
        area: the flat pattern's area (the outline's less the holes', exact for lines and
            arcs).
        report: the :class:`Developability` of the face, with the cone spline's fit error.
    """

    __slots__ = ("_ptr", "outline", "holes", "bend_lines", "area", "report", "__weakref__")

    def __init__(self, pointer: Any) -> None:
        self._ptr = pointer
        r = ffi.new("RmfDevelopability *")
        r.struct_size = ffi.sizeof("RmfDevelopability")
        call("rmf_unfolded_face_report", pointer, r)
        self.report = _report(r)
        n = ffi.new("size_t *")
        call("rmf_unfolded_face_loop_count", pointer, n)
        loops = [self._loop(k) for k in range(n[0])]
        self.outline, self.holes = loops[0], loops[1:]
        call("rmf_unfolded_face_bend_lines", pointer, ffi.NULL, 0, n)
        edges = ffi.new("RmfFlatEdge[]", max(1, n[0]))
        call("rmf_unfolded_face_bend_lines", pointer, edges, max(1, n[0]), n)
        self.bend_lines = _flat_edges(edges[0:n[0]])
        area = ffi.new("double *")
        call("rmf_unfolded_face_area", pointer, area)
        self.area = float(area[0])

    def _loop(self, index: int) -> List[FlatEdge]:
        n = ffi.new("size_t *")
        call("rmf_unfolded_face_loop", self._ptr, index, ffi.NULL, 0, n)
        edges = ffi.new("RmfFlatEdge[]", max(1, n[0]))
        call("rmf_unfolded_face_loop", self._ptr, index, edges, max(1, n[0]), n)
        return _flat_edges(edges[0:n[0]])

    @property
    def cut_length(self) -> float:
        """The length of the outline and the holes: what the cutter travels."""
        return sum(edge_length(e) for loop in [self.outline] + self.holes for e in loop)

    def dxf(self) -> str:
        """The flat pattern as a DXF R12 file's text (rmf_unfolded_face_dxf): LINE and ARC
        entities, the outline and the holes on layer CUT, the bend lines on layer BEND."""
        n = ffi.new("size_t *")
        call("rmf_unfolded_face_dxf", self._ptr, ffi.NULL, 0, n)
        text = ffi.new("char[]", n[0] + 1)
        call("rmf_unfolded_face_dxf", self._ptr, text, n[0] + 1, n)
        return ffi.unpack(text, n[0]).decode("ascii")

    def write_dxf(self, path: Union[str, bytes, "os.PathLike[Any]"]) -> None:
        """Writes :meth:`dxf` to the file `path` (str, bytes or os.PathLike; InvalidInputError
        for a name with a NUL, FileError, an OSError, when the file cannot be written)."""
        _write_text(_core.path(path, "path"), self.dxf(), "write_dxf")

    def to_flat(self, points: ArrayLike) -> np.ndarray:
        """Marks from the formed face to the flat pattern: points (n, 3) on the face to
        their flat points (n, 2), by the isometry of the development (a point on a
        cylinder's or cone's cut goes to the cut's side at angle 0)."""
        p = _core.points(points, "points")
        n = p.shape[0]
        out = np.empty((n, 2))
        call("rmf_unfolded_face_to_flat", self._ptr, _core.vec3_array(p), n,
             ffi.cast("RmfVec2 *", ffi.from_buffer(out)) if n else ffi.NULL)
        return out

    def to_formed(self, points: ArrayLike) -> np.ndarray:
        """Marks from the flat pattern to the formed face: flat points (n, 2) to their
        points (n, 3) on the face."""
        # Finite here: the library calls them "flat".
        q = _core.rows(points, "points", 2, "an array of flat points (shape (n, 2))",
                       finite_only=True)
        n = q.shape[0]
        out = np.empty((n, 3))
        call("rmf_unfolded_face_to_formed", self._ptr,
             ffi.cast("RmfVec2 *", ffi.from_buffer(q)) if n else ffi.NULL, n,
             _core.vec3_array(out))
        return out


def _write_text(path: bytes, text: str, function: str) -> None:
    """Writes `text` to `path` (bytes, as _core.path gives it); FileError naming it."""
    try:
        with open(path, "w", encoding="ascii", newline="\n") as f:
            f.write(text)
    except OSError as e:
        raise _core.FileError("%s: cannot write %s: %s"
                              % (function, os.fsdecode(path), e.strerror or e), 7,
                              function) from None


def unfold_face(brep: Brep, face: int = 0, *, tolerance: float = 1e-4,
                flat_tolerance: float = 0.0, max_pieces: int = 10000) -> UnfoldedFace:
    """Unrolls face `face` of `brep` into the plane z = 0 (rmf_unfold_face), seen from the
    face's normal side: planes, circular cylinders and right cones exactly in closed form;
    every other developable of degree 1 along its rulings through its cone spline within
    `tolerance` (caller's units), developed exactly. The outline and the holes are drawn
    edge by edge, as the line or arc an edge develops into where it is one, as G1 biarcs
    within `flat_tolerance` (0: the tolerance) elsewhere. A cylinder or cone all the way
    round is cut open along its seam edge.

    A face that is not developable is refused (InvalidInputError, the message saying "not
    developable", its curvature and the stretch an unrolling would need); so are a loop
    that does not close and options out of range. NotConvergedError if the tolerance needs
    more than `max_pieces` cone pieces.
    """
    b = _brep(brep)
    options = ffi.new("RmfUnfoldOptions *")
    call("rmf_unfold_options_init", options)
    options.tolerance = _core.number(tolerance, "tolerance")
    options.flat_tolerance = _core.number(flat_tolerance, "flat_tolerance")
    options.max_pieces = _core.integer(max_pieces, "max_pieces", "size_t", 2)
    out = _core.out_pointer("RmfUnfoldedFace")
    call("rmf_unfold_face", b._ptr, _core.integer(face, "face", "size_t"), options, out)
    return UnfoldedFace(_core.owned("unfolded_face", out[0]))


@dataclass(frozen=True)
class Bend:
    """A bend of an unfolded sheet body (RmfBend).

    Attributes:
        line: the bend line in the flat pattern (a :class:`FlatEdge`, layer "bend").
        up: True where the bend rises towards the viewer of the pattern (the unfolded side
            is the bend's inner face), False where it goes down.
        face: the index of the body's face the bend lies on.
        radius: the smallest inner bend radius of that face.
        k_factor: the K-factor used for it.
    """

    line: FlatEdge
    up: bool
    face: int
    radius: float
    k_factor: float


class UnfoldedBody:
    """A whole sheet-metal body unfolded (rmf_unfold_body): the flat pattern of its neutral
    layer, seen from the outside of the side unfolded; freed when collected.

    Attributes:
        outline: the cutting outline, counter-clockwise (:class:`FlatEdge` lines and arcs).
        holes: the holes and cutouts, each a clockwise list of :class:`FlatEdge`.
        bends: the :class:`Bend` s: line, up or down, face, inner radius, K-factor.
        bend_lines: the bends' lines (layer "bend").
        thickness: the sheet's thickness, measured between its skins.
        area: the flat area (the outline's less the holes').
    """

    __slots__ = ("_ptr", "outline", "holes", "bends", "bend_lines", "thickness", "area",
                 "__weakref__")

    def __init__(self, pointer: Any) -> None:
        self._ptr = pointer
        n = ffi.new("size_t *")
        call("rmf_unfolded_body_loop_count", pointer, n)
        loops = [self._loop(k) for k in range(n[0])]
        self.outline, self.holes = loops[0], loops[1:]
        call("rmf_unfolded_body_bends", pointer, ffi.NULL, 0, n)
        bends = ffi.new("RmfBend[]", max(1, n[0]))
        call("rmf_unfolded_body_bends", pointer, bends, max(1, n[0]), n)
        lines = _flat_edges([b.line for b in bends[0:n[0]]])
        self.bends = [Bend(line, bool(b.up), int(b.face), float(b.radius), float(b.k_factor))
                      for line, b in zip(lines, bends[0:n[0]])]
        self.bend_lines = lines
        value = ffi.new("double *")
        call("rmf_unfolded_body_thickness", pointer, value)
        self.thickness = float(value[0])
        call("rmf_unfolded_body_area", pointer, value)
        self.area = float(value[0])

    def _loop(self, index: int) -> List[FlatEdge]:
        n = ffi.new("size_t *")
        call("rmf_unfolded_body_loop", self._ptr, index, ffi.NULL, 0, n)
        edges = ffi.new("RmfFlatEdge[]", max(1, n[0]))
        call("rmf_unfolded_body_loop", self._ptr, index, edges, max(1, n[0]), n)
        return _flat_edges(edges[0:n[0]])

    @property
    def cut_length(self) -> float:
        """The length of the outline and the holes: what the cutter travels."""
        return sum(edge_length(e) for loop in [self.outline] + self.holes for e in loop)

    def dxf(self) -> str:
        """The flat pattern as a DXF R12 file's text (rmf_unfolded_body_dxf): LINE and ARC
        entities, outline and holes on layer CUT, bend lines on BEND_UP and BEND_DOWN."""
        n = ffi.new("size_t *")
        call("rmf_unfolded_body_dxf", self._ptr, ffi.NULL, 0, n)
        text = ffi.new("char[]", n[0] + 1)
        call("rmf_unfolded_body_dxf", self._ptr, text, n[0] + 1, n)
        return ffi.unpack(text, n[0]).decode("ascii")

    def write_dxf(self, path: Union[str, bytes, "os.PathLike[Any]"]) -> None:
        """Writes :meth:`dxf` to the file `path` (FileError when it cannot be written)."""
        _write_text(_core.path(path, "path"), self.dxf(), "write_dxf")

    def to_flat(self, points: ArrayLike) -> np.ndarray:
        """Marks from the formed body to the flat pattern: points (n, 3) — on either skin
        or inside the sheet — to the flat points (n, 2) of their feet on the unfolded side."""
        p = _core.points(points, "points")
        n = p.shape[0]
        out = np.empty((n, 2))
        call("rmf_unfolded_body_to_flat", self._ptr, _core.vec3_array(p), n,
             ffi.cast("RmfVec2 *", ffi.from_buffer(out)) if n else ffi.NULL)
        return out

    def to_formed(self, points: ArrayLike) -> np.ndarray:
        """Marks from the flat pattern to the formed body: flat points (n, 2) to their
        points (n, 3) on the neutral layer."""
        q = _core.rows(points, "points", 2, "an array of flat points (shape (n, 2))",
                       finite_only=True)
        n = q.shape[0]
        out = np.empty((n, 3))
        call("rmf_unfolded_body_to_formed", self._ptr,
             ffi.cast("RmfVec2 *", ffi.from_buffer(q)) if n else ffi.NULL, n,
             _core.vec3_array(out))
        return out


KFactorLike = Union[float, Sequence[Tuple[float, float]]]


def unfold_body(brep: Brep, *, k_factor: KFactorLike = 0.5, tolerance: float = 1e-4,
                flat_tolerance: float = 0.0, max_pieces: int = 10000) -> UnfoldedBody:
    """Unfolds a whole sheet-metal body (rmf_unfold_body): a closed solid of constant
    thickness made of planes and bends of any developable kind. The skins and the
    thickness are found straight across the faces; the side joined to the largest skin face
    is developed on the neutral layer — at k·t from each bend's inner face — and its faces
    are joined along their bends into one flat pattern with its holes and cutouts and the
    bend lines up and down.

    Args:
        brep: the body (:meth:`Brep.create` with ``solid=True``; the adapters'
            ``body_brep``).
        k_factor: one K-factor in [0, 1], or a table of (inner bend radius / thickness, k)
            rows, the ratios increasing, interpolated linearly.
        tolerance: the faces' tolerance and the largest variation of the thickness.
        flat_tolerance: the largest distance of biarcs from developed edges (0: tolerance).
        max_pieces: most cone pieces for one face.

    InvalidInputError, naming the face or the point, for an open shell, a face that is not
    developable, a thickness that is not constant, faces that do not close up flat, or a
    pattern that would overlap itself.
    """
    b = _brep(brep)
    options = ffi.new("RmfUnfoldBodyOptions *")
    call("rmf_unfold_body_options_init", options)
    options.tolerance = _core.number(tolerance, "tolerance")
    options.flat_tolerance = _core.number(flat_tolerance, "flat_tolerance")
    options.max_pieces = _core.integer(max_pieces, "max_pieces", "size_t", 2)
    table = None
    if isinstance(k_factor, (int, float, np.floating, np.integer)) and not isinstance(k_factor, bool):
        options.k_factor = _core.number(k_factor, "k_factor")
    else:
        rows = _core.rows(k_factor, "k_factor", 2,
                          "a K-factor or a table of (radius / thickness, k) rows",
                          finite_only=True)
        table = ffi.new("RmfVec2[]", max(1, len(rows)))
        for view, (ratio, k) in zip(table, rows):
            view.x, view.y = float(ratio), float(k)
        options.k_table_count, options.k_table = len(rows), table
    out = _core.out_pointer("RmfUnfoldedBody")
    call("rmf_unfold_body", b._ptr, options, out)
    return UnfoldedBody(_core.owned("unfolded_body", out[0]))


def checked_k_factor(k_factor: Any, table: bool = False) -> Any:
    """`k_factor` checked: a number in [0, 1] (ValueError outside), or — where `table` — a
    table of rows as :func:`unfold_body` takes it (checked there)."""
    if table and not isinstance(k_factor, numbers.Real):
        return k_factor
    k = _core.finite(k_factor, "k_factor")
    if not 0.0 <= k <= 1.0:
        raise _core._refused("k_factor", "%r is outside [0, 1]" % k)
    return k


class FlatPattern:
    """The flat pattern of one face or of a whole sheet body, as the CAD adapters return it
    (:func:`rmfsurf.ocp.unfold`, :func:`rmfsurf.freecad.unfold`).

    Attributes:
        face: the pattern as a face of the caller's kernel in the XY plane (normal +z, seen
            from the formed face's normal side, or from the outside of the body's side
            unfolded): the outline as its outer wire, the holes as inner wires, exact lines
            and circular arcs (a build123d or CadQuery Face for their input, a
            ``TopoDS_Face`` for OCP, a ``Part.Face`` in FreeCAD).
        bend_lines: the bend lines as the kernel's edges in the XY plane; none for planes,
            circular cylinders and right cones.
        report: a face's :class:`Developability` (kind, curvature, stretch, fit_error);
            None for a body.
        thickness: a body's thickness, measured between its skins; None for a face.
        bends: a body's :class:`Bend` s (line, up or down, face, inner radius, K-factor);
            empty for a face.
        area: the flat area (the library's, exact for lines and arcs).
        unfolded: the library's :class:`UnfoldedFace` or :class:`UnfoldedBody`: its flat
            edges, DXF text and marks between flat and formed (``to_flat``, ``to_formed``).
        k_factor: the K-factor asked for.
    """

    __slots__ = ("face", "bend_lines", "report", "area", "unfolded", "k_factor", "thickness",
                 "bends")

    def __init__(self, face: Any, bend_lines: List[Any],
                 unfolded: Union[UnfoldedFace, UnfoldedBody], k_factor: Any) -> None:
        self.face, self.bend_lines, self.unfolded = face, bend_lines, unfolded
        body = isinstance(unfolded, UnfoldedBody)
        self.report: Optional[Developability] = None if body else unfolded.report
        self.thickness: Optional[float] = unfolded.thickness if body else None
        self.bends: List[Bend] = list(unfolded.bends) if body else []
        self.area: float = unfolded.area
        self.k_factor = k_factor

    def write_dxf(self, path: Union[str, bytes, "os.PathLike[Any]"]) -> None:
        """Writes the library's DXF R12 of the pattern to `path` (LINE and ARC entities, the
        outline and holes on layer CUT, a face's bend lines on layer BEND, a body's on
        BEND_UP and BEND_DOWN; str, bytes or os.PathLike; FileError when the file cannot be
        written)."""
        self.unfolded.write_dxf(path)
