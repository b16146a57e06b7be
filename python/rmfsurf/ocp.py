"""rmfsurf for OpenCascade's Python bindings (OCP), as build123d and CadQuery use them.

OCP objects both ways:

* in: ``TopoDS_Edge``, ``TopoDS_Wire``, ``Geom_BSplineCurve`` (any ``Geom_Curve``) and
  build123d / CadQuery objects (anything with ``.wrapped``) → :class:`rmfsurf.Curve` and
  wire-sweep edges;
* out: :class:`rmfsurf.Curve` → ``Geom_BSplineCurve``, ``TopoDS_Edge``;
  :class:`rmfsurf.Surface` → ``Geom_BSplineSurface``, ``TopoDS_Face``; an
  :class:`rmfsurf.Shape` or :class:`rmfsurf.SheetPart` → ``TopoDS_Solid``, built by the
  kernel from the library's B-rep as it is (no sewing or healing).

:func:`sweep` is the one call build123d and CadQuery users need::

    import build123d as bd, rmfsurf.ocp
    with bd.BuildLine() as route:
        bd.Polyline((0, 0, 0), (40, 0, 0), (40, 30, 10))
    ring = bd.Circle(3)          # in the plane normal to the route at its start
    pipe = rmfsurf.ocp.sweep(route.wire(), ring)   # a build123d Solid
    part = bd.Box(10, 10, 10) + pipe

How the profile is placed: as for build123d's own ``sweep``, the profile lies in the plane
normal to the path at its start and is given where it is in space (a Face, with holes, or a
closed Wire). Its coordinates relative to the path's start point, along the plane's x
direction (f2, the initial normal of the rotation-minimizing frame) and along
tangent × f2 (f3), are the 2-D profile of :func:`rmfsurf.wire_sweep`.

:func:`unfold` unrolls a developable face — a plane, a cylinder, a cone, any face of degree 1
along its rulings, with its holes — into its exact flat pattern::

    import build123d as bd, rmfsurf.ocp
    tube = bd.Cylinder(10, 30) - bd.Cylinder(4, 30, rotation=(90, 0, 0))
    wall = max(tube.faces().filter_by(bd.GeomType.CYLINDER), key=lambda f: f.area)
    pattern = rmfsurf.ocp.unfold(wall)      # .face: a build123d Face in the XY plane, 2 holes
    pattern.write_dxf("wall.dxf")
"""

from __future__ import annotations

import io
import os
from typing import Any, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from .curves import ArrayLike, Curve, NurbsCurve, join_nurbs
from .sheets import FlatEdge, SheetPart
from .shapes import (Arc, CurveEdge, Edge, Line, Shape, SweepFrame, _frame_guide,
                     _drawn_sections, _frame_start_normal, _named, wire_sweep)
from .surfaces import NurbsSurface, Surface
from .unfold import (Brep, BrepEdge, BrepFace, Developability, FlatPattern, UnfoldedBody,
                     UnfoldedFace, checked_k_factor, line_curve, unfold_body, unfold_face)
from .unfold import developability as _developability

from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Curve2d, BRepAdaptor_Surface
from OCP.BRepBuilderAPI import (BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace,
                                BRepBuilderAPI_MakeSolid, BRepBuilderAPI_MakeVertex,
                                BRepBuilderAPI_MakeWire, BRepBuilderAPI_NurbsConvert,
                                BRepBuilderAPI_Sewing)
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepGProp import BRepGProp
from OCP.BRepLib import BRepLib_FindSurface
from OCP.BRepTools import BRepTools, BRepTools_WireExplorer
from OCP.BinTools import BinTools
from OCP.GC import GC_MakeSegment
from OCP.Geom import (Geom_BSplineCurve, Geom_BSplineSurface, Geom_Circle, Geom_Curve,
                      Geom_TrimmedCurve)
from OCP.GeomAbs import GeomAbs_Circle, GeomAbs_Line, GeomAbs_Plane
from OCP.GeomConvert import GeomConvert
from OCP.GProp import GProp_GProps
from OCP.gp import gp_Ax2, gp_Dir, gp_Pln, gp_Pnt, gp_Vec
from OCP.ShapeFix import ShapeFix_Shape

try:  # OCP 7.x: the TColgp/TColStd arrays
    from OCP.TColgp import TColgp_Array1OfPnt, TColgp_Array2OfPnt
    from OCP.TColStd import (TColStd_Array1OfInteger, TColStd_Array1OfReal,
                             TColStd_Array2OfReal)
except ImportError:  # OCP 8: the same NCollection arrays under OCP.collections
    from OCP.collections import Array1_double as TColStd_Array1OfReal
    from OCP.collections import Array1_gp_Pnt as TColgp_Array1OfPnt
    from OCP.collections import Array1_int as TColStd_Array1OfInteger
    from OCP.collections import Array2_double as TColStd_Array2OfReal
    from OCP.collections import Array2_gp_Pnt as TColgp_Array2OfPnt
try:  # OCP 7.x
    from OCP.TopTools import TopTools_IndexedMapOfShape
except ImportError:  # OCP 8
    from OCP.collections import (
        IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as TopTools_IndexedMapOfShape)
from OCP.TopAbs import (TopAbs_COMPOUND, TopAbs_EDGE, TopAbs_FACE, TopAbs_FORWARD,
                        TopAbs_REVERSED, TopAbs_SHELL, TopAbs_SOLID, TopAbs_VERTEX, TopAbs_WIRE)
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopoDS import TopoDS, TopoDS_Shape


def _downcast(kind: str) -> Any:
    """TopoDS::Edge and friends: static methods (Edge_s) in OCP 7, functions of the TopoDS
    namespace in OCP 8."""
    return getattr(TopoDS, kind + "_s", None) or getattr(TopoDS, kind)


_as_edge, _as_wire, _as_face = _downcast("Edge"), _downcast("Wire"), _downcast("Face")
_as_shell, _as_solid = _downcast("Shell"), _downcast("Solid")

_WIRE_LIKE = ("a wire or an edge (build123d/CadQuery Wire or Edge, TopoDS_Wire, TopoDS_Edge "
              "or Geom_BSplineCurve)")
_PROFILE_LIKE = ("a planar profile (build123d/CadQuery Face, Sketch, Wire or Edge (open ones "
                 "for sheets), TopoDS_Face, TopoDS_Wire or TopoDS_Edge)")


def _unwrap(value: Any) -> Any:
    """The OCP object of a build123d/CadQuery object (its .wrapped), else the value."""
    return getattr(value, "wrapped", value)


def _describe(value: Any) -> str:
    cls = type(value)
    module = cls.__module__.split(".")[0]
    return cls.__name__ if module == "builtins" else "%s %s" % (module, cls.__name__)


def _shape_of(value: Any, name: str, kinds: Tuple[Any, ...], what: str) -> TopoDS_Shape:
    raw = _unwrap(value)
    if not isinstance(raw, TopoDS_Shape) or raw.IsNull() or raw.ShapeType() not in kinds:
        raise TypeError("%s: expected %s, got %s" % (name, what, _describe(value)))
    return raw


def _pnt(p: gp_Pnt) -> np.ndarray:
    return np.array(p.Coord())


# ---------------------------------------------------------------------------------------
# Curves both ways


def _bspline_data(curve: Geom_BSplineCurve) -> NurbsCurve:
    n, p = curve.NbPoles(), curve.Degree()
    poles = np.array([curve.Pole(i).Coord() for i in range(1, n + 1)])
    weights = np.array([curve.Weight(i) for i in range(1, n + 1)])
    knots = np.array([curve.Knot(i) for i in range(1, curve.NbKnots() + 1)])
    mults = [curve.Multiplicity(i) for i in range(1, curve.NbKnots() + 1)]
    return NurbsCurve(p, poles, weights, np.repeat(knots, mults))


def _edge_bspline(edge: Any, degree: Optional[int] = None) -> Geom_BSplineCurve:
    """The exact NURBS form of an edge's curve over its range, in the edge's direction,
    raised to `degree` if given."""
    curve = BRep_Tool.Curve_s(edge, 0.0, 0.0)
    if isinstance(curve, tuple):  # bindings that return the range too
        curve = curve[0]
    first, last = BRep_Tool.Range_s(edge)
    if curve is None:
        raise ValueError("an edge without a 3-D curve")
    bspline = GeomConvert.CurveToBSplineCurve_s(Geom_TrimmedCurve(curve, first, last))
    if bspline.IsPeriodic():
        # OpenCascade leaves the end knots of a curve made not periodic unclamped: the
        # segment over the period clamps them.
        a, b = bspline.FirstParameter(), bspline.LastParameter()
        bspline.SetNotPeriodic()
        bspline.Segment(a, b)
    if edge.Orientation() == TopAbs_REVERSED:
        bspline.Reverse()
    if degree is not None and bspline.Degree() < degree:
        bspline.IncreaseDegree(degree)
    return bspline


def curve(value: Any) -> Curve:
    """An :class:`rmfsurf.Curve` from an OCP curve or edge: a ``Geom_BSplineCurve`` (any
    ``Geom_Curve`` with finite bounds), a ``TopoDS_Edge`` (its range, its orientation) or a
    build123d/CadQuery Edge. Exact: lines, circles and B-splines have NURBS forms."""
    raw = _unwrap(value)
    if isinstance(raw, Geom_Curve):
        bspline = GeomConvert.CurveToBSplineCurve_s(raw)
        if bspline.IsPeriodic():
            bspline.SetNotPeriodic()
    elif isinstance(raw, TopoDS_Shape) and not raw.IsNull() and raw.ShapeType() == TopAbs_EDGE:
        bspline = _edge_bspline(_as_edge(raw))
    else:
        raise TypeError("curve: expected an edge or a curve (build123d/CadQuery Edge, "
                        "TopoDS_Edge or Geom_Curve), got %s" % _describe(value))
    d = _bspline_data(bspline)
    return Curve.from_nurbs(d.degree, d.poles, d.knots, d.weights)


def _array1_pnt(points: np.ndarray) -> TColgp_Array1OfPnt:
    a = TColgp_Array1OfPnt(1, len(points))
    for i, p in enumerate(points, 1):
        a.SetValue(i, gp_Pnt(*map(float, p)))
    return a


def _array1_real(values: np.ndarray) -> TColStd_Array1OfReal:
    a = TColStd_Array1OfReal(1, len(values))
    for i, v in enumerate(values, 1):
        a.SetValue(i, float(v))
    return a


def _array1_int(values: np.ndarray) -> TColStd_Array1OfInteger:
    a = TColStd_Array1OfInteger(1, len(values))
    for i, v in enumerate(values, 1):
        a.SetValue(i, int(v))
    return a


def bspline_curve(value: Curve) -> Geom_BSplineCurve:
    """An :class:`rmfsurf.Curve` as a ``Geom_BSplineCurve`` (the same poles, weights and
    knots)."""
    d = _core.instance(value, "curve", Curve, "an rmfsurf.Curve").nurbs()
    knots, mults = d.distinct_knots()
    return Geom_BSplineCurve(_array1_pnt(d.poles), _array1_real(d.weights),
                             _array1_real(knots), _array1_int(mults), d.degree)


def edge(value: Curve) -> Any:
    """An :class:`rmfsurf.Curve` as a ``TopoDS_Edge``."""
    return BRepBuilderAPI_MakeEdge(bspline_curve(value)).Edge()


# ---------------------------------------------------------------------------------------
# Surfaces out


def bspline_surface(value: Surface) -> Geom_BSplineSurface:
    """An :class:`rmfsurf.Surface` as a ``Geom_BSplineSurface`` (rows of poles along u, as
    the library's NURBS view)."""
    d = _core.instance(value, "surface", Surface, "an rmfsurf.Surface").nurbs()
    nu, nv = d.weights.shape
    poles = TColgp_Array2OfPnt(1, nu, 1, nv)
    weights = TColStd_Array2OfReal(1, nu, 1, nv)
    for i in range(nu):
        for j in range(nv):
            poles.SetValue(i + 1, j + 1, gp_Pnt(*map(float, d.poles[i, j])))
            weights.SetValue(i + 1, j + 1, float(d.weights[i, j]))
    ku, mu = np.unique(d.knots_u, return_counts=True)
    kv, mv = np.unique(d.knots_v, return_counts=True)
    return Geom_BSplineSurface(poles, weights, _array1_real(ku), _array1_real(kv),
                               _array1_int(mu), _array1_int(mv), d.degree_u, d.degree_v)


def face(value: Surface, tolerance: float = 1e-7) -> Any:
    """An :class:`rmfsurf.Surface` as a ``TopoDS_Face`` bounded by its parameter domain."""
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    return BRepBuilderAPI_MakeFace(bspline_surface(value), tolerance).Face()


# ---------------------------------------------------------------------------------------
# Wire sweeps


def _ordered_edges(path: Any, name: str = "path") -> List[Any]:
    """The edges of a wire in connection order, each with its orientation in the wire;
    messages name the argument `name`."""
    raw = _shape_of(path, name, (TopAbs_WIRE, TopAbs_EDGE), _WIRE_LIKE)
    if raw.ShapeType() == TopAbs_EDGE:
        return [_as_edge(raw)]
    edges = []
    explorer = BRepTools_WireExplorer(_as_wire(raw))
    while explorer.More():
        edges.append(explorer.Current())
        explorer.Next()
    if not edges:
        raise ValueError("%s: the wire has no edges" % name)
    return edges


def path_edges(path: Any) -> List[Edge]:
    """The wire-sweep edges of an OCP wire or edge (or a build123d/CadQuery one), in order:
    straight edges as :class:`rmfsurf.Line`, circular arcs as :class:`rmfsurf.Arc`, every
    other edge as its exact NURBS curve."""
    return _path_edges(path, "path")


def _path_edges(path: Any, name: str) -> List[Edge]:
    """:func:`path_edges`, messages naming the argument `name`."""
    raw = _unwrap(path)
    if isinstance(raw, Geom_Curve):
        return [CurveEdge(curve(raw))]
    result: List[Edge] = []
    for e in _ordered_edges(path, name):
        adaptor = BRepAdaptor_Curve(e)
        start = _pnt(BRep_Tool.Pnt_s(TopExp.FirstVertex_s(e, True)))
        end = _pnt(BRep_Tool.Pnt_s(TopExp.LastVertex_s(e, True)))
        kind = adaptor.GetType()
        if kind == GeomAbs_Line:
            result.append(Line(start, end))
        elif kind == GeomAbs_Circle and not BRep_Tool.IsClosed_s(e):
            middle = _pnt(adaptor.Value(0.5 * (adaptor.FirstParameter() + adaptor.LastParameter())))
            result.append(Arc(start, middle, end))
        else:
            d = _bspline_data(_edge_bspline(e))
            result.append(CurveEdge(Curve.from_nurbs(d.degree, d.poles, d.knots, d.weights)))
    return result


def _start_frame(path: Any) -> Tuple[np.ndarray, np.ndarray]:
    """The path's start point and unit tangent there (in the wire's direction)."""
    raw = _unwrap(path)
    if isinstance(raw, Geom_Curve):
        bspline = GeomConvert.CurveToBSplineCurve_s(raw)
    else:
        bspline = _edge_bspline(_ordered_edges(path)[0])
    p, v = gp_Pnt(), gp_Vec()
    bspline.D1(bspline.FirstParameter(), p, v)
    t = np.array(v.Coord())
    return _pnt(p), t / np.linalg.norm(t)


def _start_principal_normal(path: Any) -> Optional[np.ndarray]:
    """The path's principal normal at its start (towards the centre of curvature), None
    where it starts straight."""
    raw = _unwrap(path)
    if isinstance(raw, Geom_Curve):
        bspline = GeomConvert.CurveToBSplineCurve_s(raw)
    else:
        bspline = _edge_bspline(_ordered_edges(path)[0])
    p, d1, d2 = gp_Pnt(), gp_Vec(), gp_Vec()
    bspline.D2(bspline.FirstParameter(), p, d1, d2)
    v, a = np.array(d1.Coord()), np.array(d2.Coord())
    t = v / np.linalg.norm(v)
    n = a - np.dot(a, t) * t
    length = np.linalg.norm(n)
    return n / length if length > 1e-12 * np.dot(v, v) else None


def _profile_plane(profile: Any, tolerance: float, origin: np.ndarray, tangent: np.ndarray,
                   name: str = "profile") -> Tuple[Any, List[Any], gp_Pln]:
    """The outer wire, the inner wires and the plane of a planar profile. An open wire or
    an edge (a sheet's profile) that defines no plane of its own — a straight line — is
    taken in the path's normal plane at its start (`origin`, `tangent`) when it lies there."""
    raw = _shape_of(profile, name, (TopAbs_FACE, TopAbs_WIRE, TopAbs_EDGE, TopAbs_COMPOUND),
                    _PROFILE_LIKE)
    if raw.ShapeType() == TopAbs_COMPOUND:  # a build123d sketch such as Circle(3)
        faces = []
        explorer = TopExp_Explorer(raw, TopAbs_FACE)
        while explorer.More():
            faces.append(explorer.Current())
            explorer.Next()
        if len(faces) != 1:
            raise ValueError("%s: a compound (sketch) must hold exactly one face, it "
                             "holds %d" % (name, len(faces)))
        raw = faces[0]
    if raw.ShapeType() == TopAbs_FACE:
        f = _as_face(raw)
        surface = BRepAdaptor_Surface(f)
        if surface.GetType() != GeomAbs_Plane:
            raise ValueError("%s: the face is not planar" % name)
        outer = BRepTools.OuterWire_s(f)
        inner = []
        explorer = TopExp_Explorer(f, TopAbs_WIRE)
        while explorer.More():
            w = _as_wire(explorer.Current())
            if not w.IsSame(outer):
                inner.append(w)
            explorer.Next()
        return outer, inner, surface.Plane()
    if raw.ShapeType() == TopAbs_EDGE:
        raw = BRepBuilderAPI_MakeWire(_as_edge(raw)).Wire()
    wire = _as_wire(raw)
    # An open wire is a sheet's profile: the library refuses it for a solid, naming it.
    finder = BRepLib_FindSurface(wire, tolerance, True)
    if finder.Found():
        plane = BRepAdaptor_Surface(BRepBuilderAPI_MakeFace(finder.Surface(), 1e-7).Face()).Plane()
        return wire, [], plane
    normal_plane = gp_Pln(gp_Pnt(*map(float, origin)), gp_Dir(*map(float, tangent)))
    if BRep_Tool.IsClosed_s(wire):
        raise ValueError("%s: the wire is not planar (within %g)" % (name, tolerance))
    if not _in_plane(wire, normal_plane, tolerance):
        raise ValueError("%s: a straight profile spans no plane of its own; it must lie "
                         "in the path's normal plane at the path's start (within %g)"
                         % (name, tolerance))
    return wire, [], normal_plane


def _in_plane(wire: Any, plane: gp_Pln, tolerance: float) -> bool:
    """Whether every edge of a wire lies in a plane (9 points of each)."""
    for e in _ordered_edges(wire):
        curve = _edge_bspline(e)
        first, last = curve.FirstParameter(), curve.LastParameter()
        for k in range(9):
            p = curve.Value(first + (last - first) * k / 8)
            if plane.Distance(p) > tolerance:
                return False
    return True


def _wire_curve(wire: Any, origin: np.ndarray, frame: Tuple[np.ndarray, np.ndarray, np.ndarray],
                name: str, tolerance: float) -> Curve:
    """A wire (closed, or open for a sheet) as one curve in the coordinates of `frame`
    (f2, f3, t) about origin."""
    bsplines = [_edge_bspline(e) for e in _ordered_edges(wire)]
    degree = max(b.Degree() for b in bsplines)
    pieces = []
    for b in bsplines:
        if b.Degree() < degree:
            b.IncreaseDegree(degree)
        d = _bspline_data(b)
        pieces.append(NurbsCurve(d.degree, _core.in_frame(d.poles, origin, *frame), d.weights,
                                 d.knots))
    joined = join_nurbs(pieces, name, tolerance)
    return Curve.from_nurbs(joined.degree, joined.poles, joined.knots, joined.weights)


def profile_curves(profile: Any, origin: ArrayLike, tangent: ArrayLike, tolerance: float = 1e-4
                   ) -> Tuple[Curve, List[Curve], np.ndarray]:
    """A planar profile placed in space as the outer curve, hole curves and initial normal
    f2 of :func:`rmfsurf.wire_sweep`, in the frame at the path's start (`origin`,
    `tangent`): x along f2, y along f3, z along the tangent — 0 for a profile in the normal
    plane. f2 is the x direction of the profile's plane (projected onto the normal
    plane)."""
    return _profile_curves(profile, origin, tangent, tolerance)


def _profile_curves(profile: Any, origin: ArrayLike, tangent: ArrayLike, tolerance: float,
                    f2: Optional[np.ndarray] = None, name: str = "profile"
                    ) -> Tuple[Curve, List[Curve], np.ndarray]:
    """:func:`profile_curves`, in the coordinates of the unit normal `f2` (normal to the
    tangent) when given instead of the profile plane's x direction; messages name the
    argument `name`."""
    origin = _core.vector(origin, "origin", finite_only=True)
    t = _core.direction(tangent, "tangent")
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    outer, inner, plane = _profile_plane(profile, tolerance, origin, t, name)
    axis = plane.Position()
    # Any plane across the path, carried rigidly by the frame (the library refuses one that
    # holds the tangent, or that would fold the sweep).
    x = np.array(axis.XDirection().Coord()) if f2 is None else f2
    f2 = x - np.dot(x, t) * t
    if np.linalg.norm(f2) < 0.1:  # the plane's x axis near the tangent: its line across it
        f2 = _core.cross(np.array(axis.Direction().Coord()), t)
    f2 /= np.linalg.norm(f2)
    f3 = _core.cross(t, f2)
    frame = (f2, f3, t)
    outer_curve = _wire_curve(outer, origin, frame, name, tolerance)
    holes = [_wire_curve(w, origin, frame, "%s hole %d" % (name, i), tolerance)
             for i, w in enumerate(inner)]
    return outer_curve, holes, f2


def _cap(loops: List[Curve], origin: np.ndarray, normal: np.ndarray) -> Any:
    """A planar face bounded by closed loop curves (the first the outer one)."""
    plane = gp_Pln(gp_Pnt(*map(float, origin)), gp_Dir(*map(float, normal)))
    wires = [BRepBuilderAPI_MakeWire(edge(c)).Wire() for c in loops]
    maker = BRepBuilderAPI_MakeFace(plane, wires[0], True)
    for w in wires[1:]:
        maker.Add(_as_wire(w.Reversed()))
    return maker.Face()


def _read_binary(data: bytes) -> TopoDS_Shape:
    """The shape of an OpenCascade binary B-rep (for "bintools"), as the kernel reads it."""
    raw = TopoDS_Shape()
    BinTools.Read_s(raw, io.BytesIO(data))
    return raw


def shape(value: Shape, tolerance: float = 1e-6) -> Any:
    """An :class:`rmfsurf.Shape` as OCP, built by OpenCascade from the library's B-rep
    (:meth:`rmfsurf.Shape.occ_binary`, read by ``BinTools.Read_s``): a ``TopoDS_Solid``
    when the shape is a solid, else its shell (a compound of shells when the walls of a
    hollow profile do not meet). Edges are shared and faces oriented as the library made
    them: nothing is sewn or healed. `tolerance` (finite, > 0) is checked and otherwise
    unused: the library's shape needs no sewing."""
    _core.finite(tolerance, "tolerance", positive=True)
    raw = _read_binary(_core.instance(value, "shape", Shape, "an rmfsurf.Shape").occ_binary())
    kind = raw.ShapeType()
    if kind == TopAbs_SOLID:
        return _as_solid(raw)
    if kind == TopAbs_SHELL:
        return _as_shell(raw)
    return raw


def part_solid(part: SheetPart) -> Any:
    """The formed sheet-metal part as a ``TopoDS_Solid``, built by OpenCascade from the
    library's B-rep (:meth:`rmfsurf.SheetPart.occ_binary`, read by ``BinTools.Read_s``):
    wrap it as ``build123d.Solid(...)`` or ``cadquery.Solid(...)`` to fuse, cut and
    export."""
    part = _core.instance(part, "part", SheetPart, "an rmfsurf.SheetPart")
    return _as_solid(_read_binary(part.occ_binary()))


def closed_solid(sewn: Any) -> Any:
    """A sewn closed shell (or a compound holding one) as a valid ``TopoDS_Solid`` with
    outward normals; ValueError if it does not close."""
    explorer = TopExp_Explorer(sewn, TopAbs_SHELL)
    if not explorer.More():
        raise ValueError("the faces do not sew into a shell")
    solid = BRepBuilderAPI_MakeSolid(_as_shell(explorer.Current())).Solid()
    fix = ShapeFix_Shape(solid)
    fix.Perform()
    fixed = fix.Shape()
    explorer = TopExp_Explorer(fixed, TopAbs_SOLID)
    solid = _as_solid(explorer.Current()) if explorer.More() else solid
    if volume(solid) < 0:
        solid = _as_solid(solid.Reversed())
    return solid


def volume(value: Any, relative_error: float = 1e-9) -> float:
    """The volume of an OCP solid (BRepGProp's adaptive integration to `relative_error`;
    the fixed-order default is off by 1e-4 on the library's degree-(2, 9) faces)."""
    relative_error = _core.finite(relative_error, "relative_error", positive=True)
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(_unwrap(value), props, relative_error)
    return props.Mass()


def is_valid(value: Any) -> bool:
    """OpenCascade's own check of a shape (BRepCheck_Analyzer)."""
    return BRepCheck_Analyzer(_unwrap(value)).IsValid()


def _wrap_like(template: Any, raw: Any) -> Any:
    """`raw` as a build123d/CadQuery Solid when `template` was one of theirs."""
    module = type(template).__module__.split(".")[0]
    if module == "build123d":
        import build123d

        kind = raw.ShapeType()
        if kind == TopAbs_SOLID:
            return build123d.Solid(raw)
        return build123d.Shell(raw) if kind == TopAbs_SHELL else build123d.Compound(raw)
    if module == "cadquery":
        import cadquery

        return cadquery.Shape.cast(raw)
    return raw


def sweep(path: Any, profile: Any, *, solid: bool = True, corner: str = "round",
          corner_radius: Optional[float] = None, tolerance: float = 1e-4,
          frame: SweepFrame = "rmf", scale: Tuple[float, float] = (1.0, 1.0),
          scale_knots: Optional[Sequence[Tuple[float, float]]] = None,
          method: str = "ph-rmf", end_profile: Any = None,
          sections: Optional[Sequence[Tuple[Any, ...]]] = None,
          pipe_frame: str = "lightest") -> Any:
    """Sweeps `profile` along `path` (rmf_wire_sweep), by default with rotation-minimizing
    frames.

    Args:
        path: a build123d/CadQuery Wire or Edge, a TopoDS_Wire/TopoDS_Edge or a
            Geom_BSplineCurve: lines, arcs and curves end to end.
        profile: a planar Face (holes allowed) or closed Wire placed where it is in space
            (as for build123d's sweep): in the plane normal to the path at its start, or
            in any plane across the path (a thread's profile in the axial plane), carried
            rigidly by the frame. An
            open Edge or Wire (an arc, a polyline, a line in that plane) sweeps into a
            sheet (``solid=False``), as build123d's ``Shell.sweep``.
        solid: close the result with planar caps into a solid (else the open shell).
        corner: "round" or "miter" at the path's corners.
        corner_radius: the rounding radius of round corners (None: the library's).
        tolerance: the distance tolerance of the sweep (spine approximation, joints).
        frame: "rmf" (default), "frenet" (as build123d's ``sweep(is_frenet=True)``: along
            a helix the profile's points trace helices, for threads) or ("fixed", (x, y,
            z)) / {"fixed": (x, y, z)} (f2 follows that direction, OpenCascade's binormal
            mode) or ("guide", guide) / {"guide": guide} with a build123d/CadQuery Wire or
            Edge, a TopoDS_Wire/TopoDS_Edge or a Geom_BSplineCurve, converted as `path` is
            (f2 towards where the guide crosses the path's normal plane: the profile
            follows a second rail, OpenCascade's auxiliary mode, as build123d's
            ``sweep(..., binormal=guide)``); see :func:`rmfsurf.wire_sweep`. The profile
            stays where it is placed at the start, except with "frenet" on a path that
            starts straight, where the library chooses f2 there.
        scale: the profile's scale (start, end), linear in arc length: two positive
            numbers ((1, 0.5) tapers a circle along a line into a frustum).
        scale_knots: (fraction, scale) pairs the scale passes through between its start
            and end, at fractions of the path's length strictly increasing in (0, 1)
            (None: none); see :func:`rmfsurf.wire_sweep`.
        method: how the path's curves are swept: "ph-rmf" (default), "mobius" or "rrmf"
            (spines with exact rational RMFs: parameter lines orthogonal to rounding); see
            :func:`rmfsurf.wire_sweep`. Lines and arcs are exact whatever the method.
        end_profile: the section at the path's end (None: `profile` all along), a planar
            Face (as many holes as `profile`) or Wire of the same kind as `profile`, DRAWN
            AT THE PATH'S START, in the plane normal to the path there, like `profile`: it
            is given in the start frame's coordinates and carried to the end by the frame,
            the section blending linearly in arc length from `profile` into it, loop to
            loop, corner to corner (rmf_wire_sweep_between). To taper a circle of radius
            2 into one of radius 1, draw both circles about the path's start. Open paths
            and a constant `scale` only; `profile` must lie in the normal plane too.
        sections: the sections the sweep passes through between `profile` and `end_profile`
            (required with them): ``(at, profile)`` items, `at` the fraction of the path's
            length strictly increasing in (0, 1), each profile a planar Face or Wire of the
            kind of `profile` (as many holes), DRAWN AT THE PATH'S START like `end_profile`,
            in the same placement as `profile`, and carried to its station by the frame; the
            section blends linearly in arc length from each into the next
            (rmf_wire_sweep_through; see :func:`rmfsurf.wire_sweep`). Refusals name
            ``sections[k]``.

        pipe_frame: how a round profile (circles about the path: a pipe) is swept along
            curves: "lightest" (default: the same surface in the lightest exact faces,
            degree 5 along the path instead of 9; along a lone circular helix its screw
            motion, degree 7 with simple knots) or "rmf" (parameter lines orthogonal);
            see :func:`rmfsurf.wire_sweep`.

    Returns:
        A ``TopoDS_Solid`` (or shell) — a build123d ``Solid`` / CadQuery ``Shape`` when
        `path` was a build123d / CadQuery object — to fuse, cut and export.
    """
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    edges = path_edges(path)
    guide = _frame_guide(frame)
    if guide is not None:  # the guide as the path is converted, in the library's edges
        frame = ("guide", _path_edges(guide, "frame"))
    origin, tangent = _start_frame(path)
    start_f2 = _frame_start_normal(frame, tangent, _start_principal_normal(path)
                                   if _named(frame, "frenet") else None, origin)
    outer, holes, f2 = _profile_curves(profile, origin, tangent, tolerance, start_f2)
    end_outer, end_holes = None, []
    if end_profile is not None:
        # In the same coordinates as the profile: the frame (f2, f3, t) at the start.
        end_outer, end_holes, _ = _profile_curves(end_profile, origin, tangent, tolerance, f2,
                                                  "end_profile")
    through = _drawn_sections(sections, lambda face, name: _profile_curves(
        face, origin, tangent, tolerance, f2, name))
    result = wire_sweep(edges, outer, holes, solid=solid, corner=corner,
                        corner_radius=corner_radius, tolerance=tolerance,
                        initial_normal=f2 if _named(frame, "rmf") else None, frame=frame,
                        scale=scale, scale_knots=scale_knots, method=method,
                        end_profile=end_outer,
                        end_holes=end_holes, sections=through, pipe_frame=pipe_frame)
    return _wrap_like(path, shape(result, min(tolerance, 1e-6)))


# ---------------------------------------------------------------------------------------
# Unfolding a face


_FACE_LIKE = ("a face (build123d/CadQuery Face, TopoDS_Face) or a shape holding exactly one "
              "face")


def _one_face(value: Any, name: str = "shape") -> Any:
    """The one face of `value`: a face, or a shape holding exactly one."""
    raw = _unwrap(value)
    if not isinstance(raw, TopoDS_Shape) or raw.IsNull():
        raise TypeError("%s: expected %s, got %s" % (name, _FACE_LIKE, _describe(value)))
    if raw.ShapeType() == TopAbs_FACE:
        return _as_face(raw)
    faces = TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(raw, TopAbs_FACE, faces)
    if faces.Extent() == 0:
        raise ValueError("%s: the %s holds no face; a face is needed" % (name, _describe(value)))
    if faces.Extent() > 1:
        raise ValueError("%s: the %s holds %d faces; whole sheet bodies are not unfolded yet: "
                         "give one face (e.g. one of shape.faces())"
                         % (name, _describe(value), faces.Extent()))
    return _as_face(faces.FindKey(1))


def _surface_nurbs(surface: Geom_BSplineSurface) -> NurbsSurface:
    """A B-spline surface's data with clamped knots (a periodic one as its period)."""
    s = surface
    if s.IsUPeriodic() or s.IsVPeriodic():
        bounds = s.Bounds()
        s = s.Copy()
        if s.IsUPeriodic():
            s.SetUNotPeriodic()
        if s.IsVPeriodic():
            s.SetVNotPeriodic()
        # Made not periodic, the end knots are unclamped: the segment clamps them.
        s.Segment(*bounds)
    nu, nv = s.NbUPoles(), s.NbVPoles()
    poles = np.array([[s.Pole(i, j).Coord() for j in range(1, nv + 1)]
                      for i in range(1, nu + 1)])
    weights = np.array([[s.Weight(i, j) for j in range(1, nv + 1)] for i in range(1, nu + 1)])
    knots_u = np.repeat([s.UKnot(i) for i in range(1, s.NbUKnots() + 1)],
                        [s.UMultiplicity(i) for i in range(1, s.NbUKnots() + 1)])
    knots_v = np.repeat([s.VKnot(i) for i in range(1, s.NbVKnots() + 1)],
                        [s.VMultiplicity(i) for i in range(1, s.NbVKnots() + 1)])
    return NurbsSurface(s.UDegree(), s.VDegree(), poles, weights, knots_u, knots_v)


def _edges_and_vertices(converted: Any) -> Tuple[Any, np.ndarray, List[BrepEdge]]:
    """The edges of a (NURBS-converted) shape once each — a seam or an edge between two
    faces is one edge — with their exact NURBS curves, its vertices, and the edge map."""
    edge_map, vertex_map = TopTools_IndexedMapOfShape(), TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(converted, TopAbs_EDGE, edge_map)
    TopExp.MapShapes_s(converted, TopAbs_VERTEX, vertex_map)
    vertices = [_pnt(BRep_Tool.Pnt_s(_downcast("Vertex")(vertex_map.FindKey(i))))
                for i in range(1, vertex_map.Extent() + 1)]
    edges = []
    for i in range(1, edge_map.Extent() + 1):
        e = _as_edge(edge_map.FindKey(i).Oriented(TopAbs_FORWARD))
        first, last = TopExp.FirstVertex_s(e), TopExp.LastVertex_s(e)
        start, end = vertex_map.FindIndex(first) - 1, vertex_map.FindIndex(last) - 1
        if BRep_Tool.Degenerated_s(e):
            p = _pnt(BRep_Tool.Pnt_s(first))
            edges.append(BrepEdge(line_curve(p, p), start, end, degenerate=True))
        else:
            edges.append(BrepEdge(_bspline_data(_edge_bspline(e)), start, end))
    return edge_map, np.array(vertices).reshape(-1, 3), edges


def _face_loops(face: Any, edge_map: Any) -> List[List[Tuple[int, bool]]]:
    """A face's wires in order as loops of edge uses with their orientation
    (BRepTools_WireExplorer on the face), the outer wire first: the one bounding the
    largest region of the face's parameter plane (BRepTools.OuterWire and
    ShapeAnalysis.OuterWire, by boxes and by a classifier, each take a hole for it on some
    faces across a seam)."""
    loops: List[List[Tuple[int, bool]]] = []
    areas: List[float] = []
    explorer = TopExp_Explorer(face, TopAbs_WIRE)
    while explorer.More():
        wire = _as_wire(explorer.Current())
        uses, uv = [], []
        walk = BRepTools_WireExplorer(wire, face)
        while walk.More():
            e = walk.Current()
            uses.append((edge_map.FindIndex(e) - 1, e.Orientation() != TopAbs_REVERSED))
            uv.append(_pcurve_points(e, face))
            walk.Next()
        loops.append(uses)
        areas.append(abs(_signed_area(uv)))
        explorer.Next()
    if not loops:
        raise ValueError("shape: a face has no wires")
    loops.insert(0, loops.pop(int(np.argmax(areas))))
    return loops


def _nurbs_surface_of(face: Any) -> NurbsSurface:
    bspline = BRep_Tool.Surface_s(face)
    if not isinstance(bspline, Geom_BSplineSurface):
        bspline = Geom_BSplineSurface.DownCast(bspline)
    return _surface_nurbs(bspline)


def face_brep(shape: Any) -> Brep:
    """The library's B-rep of one face (:func:`unfold`'s input; `shape` as there): its
    surface (a plane as a plane, any other as its NURBS form by
    BRepBuilderAPI_NurbsConvert), its edges once each (TopTools_IndexedMapOfShape: a seam is
    one edge used twice) with their exact NURBS curves, its wires in order as loops of edge
    uses with their orientation (BRepTools_WireExplorer on the face), the outer wire
    first."""
    face = _one_face(shape)
    adaptor = BRepAdaptor_Surface(face)
    converted = _as_face(BRepBuilderAPI_NurbsConvert(face, True).Shape())
    if adaptor.GetType() == GeomAbs_Plane:
        position = adaptor.Plane().Position()
        x = np.array(position.XDirection().Coord())
        normal = _core.cross(x, np.array(position.YDirection().Coord()))  # the parameters'
        surface: dict = dict(plane=(np.array(position.Location().Coord()), normal, x))
    else:
        surface = dict(surface=_nurbs_surface_of(converted))
    edge_map, vertices, edges = _edges_and_vertices(converted)
    same_sense = converted.Orientation() == TopAbs_FORWARD
    return Brep.create(vertices, edges,
                       [BrepFace(_face_loops(converted, edge_map), same_sense=same_sense,
                                 **surface)])


def body_brep(shape: Any) -> Brep:
    """The library's B-rep of a whole solid (:func:`unfold`'s input for a sheet body): the
    solid converted by BRepBuilderAPI_NurbsConvert as one shape, so that the faces share
    their edges; every face with its NURBS surface and its loops as in :func:`face_brep`."""
    raw = _unwrap(shape)
    if not isinstance(raw, TopoDS_Shape) or raw.IsNull():
        raise TypeError("shape: expected a solid, got %s" % _describe(shape))
    solids = TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(raw, TopAbs_SOLID, solids)
    if solids.Extent() != 1:
        raise ValueError("shape: the %s holds %d solids; a sheet body is one solid"
                         % (_describe(shape), solids.Extent()))
    converted = BRepBuilderAPI_NurbsConvert(solids.FindKey(1), True).Shape()
    edge_map, vertices, edges = _edges_and_vertices(converted)
    faces = []
    explorer = TopExp_Explorer(converted, TopAbs_FACE)
    while explorer.More():
        face = _as_face(explorer.Current())
        faces.append(BrepFace(_face_loops(face, edge_map), surface=_nurbs_surface_of(face),
                              same_sense=face.Orientation() == TopAbs_FORWARD))
        explorer.Next()
    return Brep.create(vertices, edges, faces, solid=True)


def _pcurve_points(edge: Any, face: Any, samples: int = 16) -> np.ndarray:
    """Points of an edge's curve in the face's parameter plane, in the edge's direction in
    its wire (a seam's pcurve for that direction)."""
    curve = BRepAdaptor_Curve2d(edge, face)
    a, b = curve.FirstParameter(), curve.LastParameter()
    points = np.array([curve.Value(a + (b - a) * k / samples).Coord()
                       for k in range(samples + 1)])
    return points[::-1] if edge.Orientation() == TopAbs_REVERSED else points


def _signed_area(pieces: List[np.ndarray]) -> float:
    """The signed area of the polygon through the points of the pieces, in order."""
    p = np.concatenate(pieces) if pieces else np.zeros((0, 2))
    if len(p) < 3:
        return 0.0
    q = np.roll(p, -1, axis=0)
    return 0.5 * float(np.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]))


def developability(shape: Any) -> Developability:
    """How developable a face is (see :func:`rmfsurf.developability`; `shape` as for
    :func:`unfold`): "plane", "circular_cylinder", "right_cone", ..., "not_developable",
    with its curvature and, for a face that is not developable, the stretch an unrolling
    would need."""
    return _developability(face_brep(shape))


def _flat_vertex(p: np.ndarray) -> Any:
    return BRepBuilderAPI_MakeVertex(gp_Pnt(float(p[0]), float(p[1]), 0.0)).Vertex()


def _flat_curve(e: FlatEdge) -> Tuple[Any, float, float]:
    """A flat edge's exact curve in the plane z = 0 and its parameter range, from its start
    to its end: a segment, or the arc of a Geom_Circle about the exact centre."""
    if e.kind == "line":
        segment = GC_MakeSegment(gp_Pnt(float(e.start[0]), float(e.start[1]), 0.0),
                                 gp_Pnt(float(e.end[0]), float(e.end[1]), 0.0)).Value()
        return segment, segment.FirstParameter(), segment.LastParameter()
    # About +z for a counter-clockwise arc, about −z for a clockwise one, x along +x: the
    # circle's parameter runs from the start to the end.
    turn = 1.0 if e.sweep > 0 else -1.0
    axis = gp_Ax2(gp_Pnt(float(e.center[0]), float(e.center[1]), 0.0), gp_Dir(0.0, 0.0, turn),
                  gp_Dir(1.0, 0.0, 0.0))
    circle = Geom_Circle(axis, float(e.radius))
    d = e.start - e.center
    start = turn * float(np.arctan2(d[1], d[0]))
    return circle, start, start + abs(float(e.sweep))


def _flat_wire(loop: List[FlatEdge]) -> Any:
    """A closed loop of flat edges as a wire, consecutive edges sharing their vertex."""
    vertices = [_flat_vertex(e.start) for e in loop]
    maker = BRepBuilderAPI_MakeWire()
    for k, e in enumerate(loop):
        curve, a, b = _flat_curve(e)
        maker.Add(BRepBuilderAPI_MakeEdge(curve, vertices[k], vertices[(k + 1) % len(loop)],
                                          a, b).Edge())
    return maker.Wire()


def _flat_edge(e: FlatEdge) -> Any:
    curve, a, b = _flat_curve(e)
    return BRepBuilderAPI_MakeEdge(curve, a, b).Edge()


def flat_face(unfolded: UnfoldedFace) -> Any:
    """An unrolled face's flat pattern as a ``TopoDS_Face`` in the plane z = 0 (normal +z):
    its outline as the outer wire, its holes as inner wires, of exact lines and circular
    arcs."""
    u = _core.instance(unfolded, "unfolded", (UnfoldedFace, UnfoldedBody),
                       "an rmfsurf.UnfoldedFace or UnfoldedBody")
    maker = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)),
                                    _flat_wire(u.outline), True)
    for hole in u.holes:  # clockwise: inner wires as they are
        maker.Add(_flat_wire(hole))
    return maker.Face()


def _wrap_pattern_like(template: Any, raw: Any) -> Any:
    """A face or an edge as a build123d/CadQuery one when `template` was one of theirs."""
    module = type(template).__module__.split(".")[0]
    if module == "build123d":
        import build123d

        return build123d.Face(raw) if raw.ShapeType() == TopAbs_FACE else build123d.Edge(raw)
    if module == "cadquery":
        import cadquery

        return cadquery.Shape.cast(raw)
    return raw


def _holds_solid(shape: Any) -> bool:
    raw = _unwrap(shape)
    if not isinstance(raw, TopoDS_Shape) or raw.IsNull():
        return False
    solids = TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(raw, TopAbs_SOLID, solids)
    return solids.Extent() > 0


def unfold(shape: Any, *, k_factor: Any = 0.5, tolerance: float = 1e-4,
           flat_tolerance: float = 0.0) -> FlatPattern:
    """The exact flat pattern of a developable face (rmf_unfold_face) or of a whole
    sheet-metal body (rmf_unfold_body), holes and cutouts kept.

    A face: planes, circular cylinders and right cones (a cylinder converted to a B-spline,
    or read back from STEP, included: the kind is told from the geometry) unroll exactly;
    every other developable of degree 1 along its rulings (general cylinders and cones — an
    extruded spline —, tangent developables, ruled B-spline developables) through its
    cone spline within `tolerance`, with bend lines where its pieces meet. A doubly curved
    face is refused: InvalidInputError saying it is not developable, with its curvature and
    the stretch an unrolling would need.

    A solid: a sheet body of constant thickness made of planes and bends of any
    developable kind. Its skins and thickness are found, one side is developed on the
    neutral layer at `k_factor` and its faces joined along their bends: the outline, the
    holes and cutouts (one across a bend included), the bend lines up and down.
    InvalidInputError naming the face or the point for a face that is not developable, a
    thickness that is not constant, or a pattern that would overlap itself.

    Args:
        shape: a build123d/CadQuery Face or TopoDS_Face, a shape holding exactly one face,
            or a solid (a sheet body).
        k_factor: the sheet's K-factor in [0, 1] (ValueError outside), or for a body a
            table of (inner bend radius / thickness, k) rows. One face IS the layer that is
            unrolled, so the K-factor does not change a face's pattern.
        tolerance: the largest distance of the cone spline from a face that is neither a
            plane, a circular cylinder nor a right cone (caller's units); for a body also
            the largest variation of its thickness.
        flat_tolerance: the largest distance of the outline's biarcs from the developed
            boundary where an edge does not develop into a line or an arc (0: the
            tolerance).

    Returns:
        A :class:`FlatPattern`: ``.face`` in the XY plane (a build123d Face for build123d
        input), ``.bend_lines``, ``.write_dxf(path)``, ``.area``; ``.report`` for a face,
        ``.thickness`` and ``.bends`` for a body.
    """
    tolerance = _core.number(tolerance, "tolerance")
    flat_tolerance = _core.number(flat_tolerance, "flat_tolerance")
    solid = _holds_solid(shape)
    k = checked_k_factor(k_factor, table=solid)
    unfolded: Union[UnfoldedFace, UnfoldedBody]
    if solid:
        unfolded = unfold_body(body_brep(shape), k_factor=k, tolerance=tolerance,
                               flat_tolerance=flat_tolerance)
    else:
        unfolded = unfold_face(face_brep(shape), 0, tolerance=tolerance,
                               flat_tolerance=flat_tolerance)
    flat = _wrap_pattern_like(shape, flat_face(unfolded))
    bends = [_wrap_pattern_like(shape, _flat_edge(e)) for e in unfolded.bend_lines]
    return FlatPattern(flat, bends, unfolded, k)
