"""rmfsurf for FreeCAD: Part objects both ways, wire sweeps, profile sweeps along an edge
and cone spline surfaces with their flat patterns.

Runs inside FreeCAD (``import FreeCAD, Part`` must work): install the package where
FreeCAD's Python finds it (docs/install.md, "FreeCAD"); the library comes with the package.

* in: ``Part.Edge``/``Part.Wire``/sketches and ``Part.BSplineCurve``/``BSplineSurface``
  (any curve or surface FreeCAD can express as NURBS) → :class:`rmfsurf.Curve`,
  :class:`rmfsurf.Surface`, wire-sweep edges;
* out: ``Part.BSplineCurve``, ``Part.BSplineSurface``, ``Part.Face``, ``Part.Shape``
  (a solid for a closed sweep).

:func:`sweep` is the wire sweep (:func:`sweep_with_report` with its figures, as the
workbench's RmfSweep feature uses it); :func:`transition` the sheet-metal transition piece
between two closed curves (its solid, flat pattern and bend lines as Part shapes);
:func:`unfold` the exact flat pattern of a developable face, its holes kept (planes,
cylinders and cones exactly, any developable through its cone spline)::

    import Part, rmfsurf.freecad
    tube = Part.makeCylinder(10, 30).cut(Part.makeCylinder(3, 30, FreeCAD.Vector(-15, 0, 15),
                                                           FreeCAD.Vector(1, 0, 0)))
    wall = max(tube.Faces, key=lambda f: f.Area)   # the cylinder, two holes in it
    pattern = rmfsurf.freecad.unfold(wall)         # .face: a Part.Face in the XY plane
    pattern.write_dxf("wall.dxf")
"""

from __future__ import annotations

import os
import tempfile
from typing import Any, List, Optional, Sequence, Tuple, Union

import numpy as np

import FreeCAD
import Part

from . import _core
from .cone_splines import ConeSpline, cone_spline_approximate_ruled
from .curves import (ArrayLike, Curve, NurbsCurve, arc, circle, distinct_knots, flat_knots,
                     join_nurbs)
from .frames import SPINE_METHODS, Frames, framed_spine
from .shapes import (Arc, CurveEdge, Edge, Line, Shape, SweepFrame, SweepReport,
                     _drawn_sections, _frame_guide, _frame_start_normal, _named, wire_sweep)
from .sheets import FlatEdge, SheetPart
from .sheets import transition as _transition
from .surfaces import NurbsSurface, Surface, sweep_surface
from .unfold import (Brep, BrepEdge, BrepFace, Developability, FlatPattern, UnfoldedBody,
                     UnfoldedFace, checked_k_factor, line_curve, unfold_body, unfold_face)
from .unfold import developability as _developability

RmfError = _core.RmfError
V = FreeCAD.Vector


def vector(p: ArrayLike) -> Any:
    """A FreeCAD.Vector from a 3-sequence (e.g. a NumPy point)."""
    x, y, z = _core.vector(p, "p")
    return V(float(x), float(y), float(z))


# ---------------------------------------------------------------------------------------
# Curves and surfaces both ways


def _part_curve_data(curve: Any) -> NurbsCurve:
    curve = curve.copy()
    if curve.isPeriodic():
        # FreeCAD 0.20's setNotPeriodic leaves the end knots unclamped (multiplicity 1);
        # the segment over the whole period clamps them.
        a, b = curve.FirstParameter, curve.LastParameter
        curve.setNotPeriodic()
        curve.segment(a, b)
    knots = flat_knots(curve.getKnots(), curve.getMultiplicities())
    return NurbsCurve(curve.Degree, np.array([tuple(p) for p in curve.getPoles()]),
                      np.array(curve.getWeights()), knots)


def _circle_bspline(edge: Any) -> Any:
    """A circular edge as the library's exact circle or arc (rational quadratic spans of at
    most 90°) over the edge's parameter range. OpenCascade's own conversion has 120° spans,
    which FreeCAD's fixed-order Shape.Volume resolves less well (1.1e-9 against 1e-11 on a
    swept ring)."""
    c = edge.Curve
    a, b = edge.FirstParameter, edge.LastParameter
    if edge.isClosed():
        start = edge.valueAt(a) - c.Center
        exact = circle(c.Radius, c.Center, start, c.Axis.cross(start))
    else:
        exact = arc(edge.valueAt(a), edge.valueAt(0.5 * (a + b)), edge.valueAt(b))
    return _part_bspline(exact.nurbs(), (a, b))


def _edge_bspline(edge: Any, placement: Any = None, degree: Optional[int] = None) -> Any:
    """The exact B-spline of an edge over its range, in the edge's direction in its wire,
    moved by `placement`, raised to `degree`. (By the edge's NURBS conversion: in FreeCAD
    0.20, ``Curve.toBSpline`` approximates circles and other conics by polynomial
    B-splines, 7e-8 off on a circle of radius 3, and a conic's ``Curve.toNurbs`` drops its
    placement.)"""
    if isinstance(edge.Curve, Part.Circle):
        curve = _circle_bspline(edge)
    else:
        converted = edge.toNurbs().Edges[0]
        curve = converted.Curve.copy()
        a, b = converted.FirstParameter, converted.LastParameter
        if max(abs(a - curve.FirstParameter), abs(b - curve.LastParameter)) > 1e-12 * (1 + abs(b - a)):
            curve.segment(a, b)
    if edge.Orientation == "Reversed":
        curve.reverse()
    if placement is not None:
        curve.transform(placement.toMatrix())
    if degree is not None and curve.Degree < degree:
        curve.increaseDegree(degree)
    return curve


def curve(value: Any, placement: Any = None) -> Curve:
    """An :class:`rmfsurf.Curve` from a ``Part.Edge`` (its range) or a Part curve
    (``Part.BSplineCurve``, line, circle, ...: its NURBS form), optionally moved by
    `placement` (e.g. the inverse of a sketch's placement)."""
    if isinstance(value, Part.Edge):
        bspline = _edge_bspline(value, placement)
    elif hasattr(value, "toShape"):
        bspline = _edge_bspline(value.toShape())
        if placement is not None:
            bspline.transform(placement.toMatrix())
    else:
        raise TypeError("curve: expected a Part.Edge or a Part curve, got %s"
                        % type(value).__name__)
    d = _part_curve_data(bspline)
    return Curve.from_nurbs(d.degree, d.poles, d.knots, d.weights)


def part_curve(value: Curve) -> Any:
    """An :class:`rmfsurf.Curve` as a ``Part.BSplineCurve`` (knots with multiplicities)."""
    return _part_bspline(_core.instance(value, "curve", Curve, "an rmfsurf.Curve").nurbs())


def _part_bspline(d: NurbsCurve, bounds: Optional[Tuple[float, float]] = None) -> Any:
    """NURBS data as a ``Part.BSplineCurve``, its parameter mapped linearly onto `bounds`
    if given."""
    knots, mults = distinct_knots(d.knots)
    if bounds is not None:
        k0, k1 = knots[0], knots[-1]
        knots = [bounds[0] + (bounds[1] - bounds[0]) * (k - k0) / (k1 - k0) for k in knots]
        knots[0], knots[-1] = bounds
    result = Part.BSplineCurve()
    result.buildFromPolesMultsKnots([vector(p) for p in d.poles], [int(m) for m in mults],
                                    [float(k) for k in knots], False, d.degree,
                                    [float(w) for w in d.weights])
    return result


def surface(value: Any, rulings_along_v: bool = False) -> Surface:
    """An :class:`rmfsurf.Surface` from a ``Part.BSplineSurface`` (or a Part.Face: its
    NURBS form); `rulings_along_v` swaps u and v."""
    if isinstance(value, Part.Face):
        value = value.toNurbs().Faces[0].Surface
    if not isinstance(value, Part.BSplineSurface):
        raise TypeError("surface: expected a Part.BSplineSurface or a Part.Face, got %s"
                        % type(value).__name__)
    s = value.copy()
    if s.isUPeriodic():
        s.setUNotPeriodic()
    if s.isVPeriodic():
        s.setVNotPeriodic()
    if rulings_along_v:
        s.exchangeUV()
    poles = np.array([[tuple(p) for p in row] for row in s.getPoles()])
    return Surface.from_nurbs(s.UDegree, s.VDegree, poles,
                              flat_knots(s.getUKnots(), s.getUMultiplicities()),
                              flat_knots(s.getVKnots(), s.getVMultiplicities()),
                              np.array(s.getWeights()))


def part_surface(value: Surface) -> Any:
    """An :class:`rmfsurf.Surface` as a ``Part.BSplineSurface`` (pole rows along u)."""
    d = _core.instance(value, "surface", Surface, "an rmfsurf.Surface").nurbs()
    ku, mu = distinct_knots(d.knots_u)
    kv, mv = distinct_knots(d.knots_v)
    result = Part.BSplineSurface()
    result.buildFromPolesMultsKnots(
        [[vector(p) for p in row] for row in d.poles], [int(m) for m in mu],
        [int(m) for m in mv], [float(k) for k in ku], [float(k) for k in kv], False, False,
        d.degree_u, d.degree_v, [[float(w) for w in row] for row in d.weights])
    return result


def part_face(value: Surface) -> Any:
    """An :class:`rmfsurf.Surface` as a ``Part.Face`` bounded by its parameter domain."""
    return Part.Face(part_surface(value))


# ---------------------------------------------------------------------------------------
# Sweeping a sketch along an edge with a chosen frame


METHODS = tuple(SPINE_METHODS)


def spine_with_frames(spine: Curve, method: str = "ph-rmf", tolerance: float = 1e-4,
                      initial_normal: Sequence[float] = (0, 0, 1)) -> Tuple[Curve, Frames]:
    """A spine within `tolerance` of `spine` with rational frames by `method` (one of
    :data:`METHODS`), as :func:`rmfsurf.framed_spine` makes it."""
    spine = _core.instance(spine, "spine", Curve, "an rmfsurf.Curve")
    made, frames, _ = framed_spine(spine, method, tolerance, initial_normal)
    return made, frames


def sweep_sketch_along_edge(sketch: Any, edge: Any, method: str = "ph-rmf",
                            tolerance: float = 1e-4,
                            initial_normal: Sequence[float] = (0, 0, 1)) -> Any:
    """The sketch's edges, in the sketch's own xy coordinates (x along f2, y along f3),
    swept along `edge` with frames by `method`: one exact rational face per sketch edge, as
    a Part.Shell (or a single Part.Face)."""
    spine, frames = spine_with_frames(curve(edge), method, tolerance, initial_normal)
    local = sketch.Placement.inverse()
    faces = [part_face(sweep_surface(spine, frames, curve(e, local)))
             for e in sketch.Shape.Edges]
    if not faces:
        raise ValueError("sketch: %s has no edges to sweep" % sketch.Label)
    return faces[0] if len(faces) == 1 else Part.Shell(faces)


# ---------------------------------------------------------------------------------------
# Wire sweeps


def _shape_of(value: Any, name: str) -> Any:
    """A Part shape from a shape or a document object with one (a sketch, a feature)."""
    if isinstance(value, Part.Shape):
        return value
    shape = getattr(value, "Shape", None)
    if isinstance(shape, Part.Shape):
        return shape
    raise TypeError("%s: expected a Part shape or a document object with one (a sketch), "
                    "got %s" % (name, type(value).__name__))


def _wire_of(value: Any, name: str, what: str) -> Any:
    shape = _shape_of(value, name)
    if isinstance(shape, Part.Edge):
        return Part.Wire([shape])
    if isinstance(shape, Part.Wire):
        return shape
    if shape.ShapeType == "Compound" and len(shape.Wires) == 1 and not shape.Faces:
        return shape.Wires[0]  # a sketch with one wire
    raise TypeError("%s: expected %s, got a %s" % (name, what, shape.ShapeType))


def path_edges(path: Any) -> List[Edge]:
    """The wire-sweep edges of a Part.Wire/Part.Edge/sketch, in order: lines as
    :class:`rmfsurf.Line`, circular arcs as :class:`rmfsurf.Arc`, other edges exactly as
    NURBS."""
    return _path_edges(path, "path")


def _path_edges(path: Any, name: str) -> List[Edge]:
    wire = _wire_of(path, name, "a Part.Wire, a Part.Edge or a sketch with one wire")
    result: List[Edge] = []
    for e in wire.OrderedEdges:
        reverse = e.Orientation == "Reversed"
        a, b = e.FirstParameter, e.LastParameter
        start, end = (e.valueAt(b), e.valueAt(a)) if reverse else (e.valueAt(a), e.valueAt(b))
        if isinstance(e.Curve, (Part.Line, Part.LineSegment)):
            result.append(Line(tuple(start), tuple(end)))
        elif isinstance(e.Curve, Part.Circle) and not e.isClosed():
            result.append(Arc(tuple(start), tuple(e.valueAt(0.5 * (a + b))), tuple(end)))
        else:
            result.append(CurveEdge(curve(e)))
    return result


def _wire_curve(wire: Any, origin: np.ndarray, frame: Tuple[np.ndarray, np.ndarray, np.ndarray],
                name: str, tolerance: float) -> Curve:
    """A wire (closed, or open for a sheet) as one curve in the coordinates of `frame`
    (f2, f3, t) about `origin`."""
    edges = wire.OrderedEdges
    degree = max(_edge_bspline(e).Degree for e in edges)
    pieces = []
    for e in edges:
        d = _part_curve_data(_edge_bspline(e, degree=degree))
        pieces.append(NurbsCurve(d.degree, _core.in_frame(d.poles, origin, *frame), d.weights,
                                 d.knots))
    joined = join_nurbs(pieces, name, tolerance)
    return Curve.from_nurbs(joined.degree, joined.poles, joined.knots, joined.weights)


def _profile_face(shape: Any, name: str = "profile") -> Any:
    """The one planar region of a profile: a face, a closed wire, or closed wires nested as
    outer loops and holes (a sketch with inner loops: FreeCAD's Bullseye face maker). (An
    open profile is a sheet's, see `_open_profile`.)"""
    if isinstance(shape, Part.Face):
        return shape
    if shape.Faces:
        if len(shape.Faces) != 1:
            raise ValueError("%s: expected one face, got %d" % (name, len(shape.Faces)))
        return shape.Faces[0]
    wires = [shape] if isinstance(shape, Part.Wire) else shape.Wires
    if isinstance(shape, Part.Edge):
        wires = [Part.Wire([shape])]
    if not wires:
        raise TypeError("%s: expected a Part.Face, closed wires or a sketch, got a %s "
                        "without wires" % (name, shape.ShapeType))
    open_wires = [i for i, w in enumerate(wires) if not w.isClosed()]
    if open_wires:
        raise ValueError("%s: wire %d of %d is not closed"
                         % (name, open_wires[0] + 1, len(wires)))
    if len(wires) == 1:
        return Part.Face(wires[0])
    faces = Part.makeFace(wires, "Part::FaceMakerBullseye").Faces
    if len(faces) != 1:
        raise ValueError("%s: its %d closed wires bound %d separate regions; a sweep takes "
                         "one region (with holes)" % (name, len(wires), len(faces)))
    return faces[0]


def _plane_x_axis(plane: Any) -> Any:
    """A Part.Plane's x direction (its u direction): FreeCAD 0.20's Plane has no XAxis."""
    axis = getattr(plane, "XAxis", None)
    return axis if axis is not None else plane.Rotation.multVec(V(1, 0, 0))


def profile_curves(profile: Any, origin: ArrayLike, tangent: ArrayLike, tolerance: float = 1e-4
                   ) -> Tuple[Curve, List[Curve], np.ndarray]:
    """A planar profile (Part.Face with holes, closed Part.Wire, closed wires nested as
    outer loop and holes, or a sketch of them) as the outer curve, holes and initial
    normal f2 (the x direction of the profile's placement, e.g. the sketch's x axis,
    projected onto the normal plane) of :func:`rmfsurf.wire_sweep`, in the frame at the
    wire's start (`origin`, `tangent`): x along f2, y along f3, z along the tangent — 0 for
    a profile in the normal plane."""
    return _profile_curves(profile, origin, tangent, tolerance)


def _profile_curves(profile: Any, origin: ArrayLike, tangent: ArrayLike, tolerance: float,
                    f2: Optional[np.ndarray] = None, name: str = "profile"
                    ) -> Tuple[Curve, List[Curve], np.ndarray]:
    """:func:`profile_curves`, in the coordinates of the unit normal `f2` (normal to the
    tangent) when given instead of the profile's x axis; messages name the argument
    `name`."""
    o = _core.vector(origin, "origin", finite_only=True)
    t = _core.direction(tangent, "tangent")
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    shape = _shape_of(profile, name)
    sheet = _open_profile(shape)
    if sheet is not None:
        outer_wire, hole_wires = sheet, []
        normal, _, plane_x = _open_profile_plane(sheet, o, t, tolerance, name)
    else:
        face = _profile_face(shape, name)
        if not isinstance(face.Surface, Part.Plane):
            raise ValueError("%s: not planar" % name)
        outer_wire = face.OuterWire
        hole_wires = [w for w in face.Wires if not w.isSame(face.OuterWire)]
        normal = np.array(tuple(face.Surface.Axis))
        plane_x = np.array(tuple(_plane_x_axis(face.Surface)))
    # Any plane across the wire, carried rigidly by the frame (the library refuses one that
    # holds the tangent, or that would fold the sweep).
    placement = getattr(profile, "Placement", None) if not isinstance(profile, Part.Shape) else None
    x_axis = placement.Rotation.multVec(V(1, 0, 0)) if placement is not None else None
    x = np.array(tuple(x_axis)) if x_axis is not None else plane_x
    if f2 is not None:
        x = f2
    f2 = x - np.dot(x, t) * t
    if np.linalg.norm(f2) < 0.1:  # the plane's x axis near the tangent: its line across it
        f2 = _core.cross(normal, t)
    f2 /= np.linalg.norm(f2)
    f3 = _core.cross(t, f2)
    frame = (f2, f3, t)
    outer = _wire_curve(outer_wire, o, frame, name, tolerance)
    holes = [_wire_curve(w, o, frame, "%s hole %d" % (name, i), tolerance)
             for i, w in enumerate(hole_wires)]
    return outer, holes, f2


def _open_profile(shape: Any) -> Any:
    """The open wire of a sheet's profile (an open edge or wire), else None."""
    if isinstance(shape, Part.Edge):
        return None if shape.isClosed() else Part.Wire([shape])
    if shape.Faces:
        return None
    wires = [shape] if isinstance(shape, Part.Wire) else shape.Wires
    if len(wires) == 1 and not wires[0].isClosed():
        return wires[0]
    return None


def _open_profile_plane(wire: Any, origin: np.ndarray, tangent: np.ndarray, tolerance: float,
                        name: str = "profile") -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The plane (normal, point, x direction) of an open profile; a straight one spans
    none, and is taken in the wire's normal plane at its start when it lies there (its x
    direction along the line)."""
    plane = wire.findPlane(tolerance)
    if plane is not None:
        return (np.array(tuple(plane.Axis)), np.array(tuple(plane.Position)),
                np.array(tuple(_plane_x_axis(plane))))
    points = np.array([tuple(p) for e in wire.OrderedEdges for p in e.discretize(9)])
    if np.max(np.abs((points - origin) @ tangent)) > tolerance:
        raise ValueError("%s: a straight profile spans no plane of its own; it must lie "
                         "in the wire's normal plane at the wire's start (within %g)"
                         % (name, tolerance))
    return tangent, origin, points[-1] - points[0]


def _from_binary(data: bytes) -> Any:
    """The Part.Shape FreeCAD builds from an OpenCascade binary B-rep (for "freecad"), as it
    is. FreeCAD reads it from a file only: one in memory (/dev/shm), or in the temporary
    directory where /dev/shm is missing, not writable or full."""
    try:
        return _import_binary(data, "/dev/shm")
    except OSError:
        return _import_binary(data, None)


def _import_binary(data: bytes, directory: Optional[str]) -> Any:
    """`data` imported by FreeCAD from a file of its own in `directory` (None: the
    temporary directory), removed after."""
    handle, path = tempfile.mkstemp(prefix="rmfsurf-", suffix=".bin", dir=directory)
    try:
        with os.fdopen(handle, "wb") as file:
            file.write(data)
        built = Part.Shape()
        built.importBinary(path)
        return built
    finally:
        os.unlink(path)


def part_shape(value: Shape, tolerance: float = 1e-6) -> Any:
    """An :class:`rmfsurf.Shape` as a Part.Shape, built by OpenCascade from the library's
    B-rep (:meth:`rmfsurf.Shape.occ_binary`, ``importBinary``): a Part.Solid when
    the shape is a solid, else a Part.Shell (a Part.Compound of shells when the walls of a
    hollow profile do not meet). Edges are shared and faces oriented as the library made
    them: nothing is sewn or healed. `tolerance` (finite, > 0) is checked and otherwise
    unused."""
    _core.finite(tolerance, "tolerance", positive=True)
    shape = _core.instance(value, "shape", Shape, "an rmfsurf.Shape")
    built = _from_binary(shape.occ_binary("freecad"))
    if value.is_solid:
        return built.Solids[0]
    shells = built.Shells
    return shells[0] if len(shells) == 1 else Part.Compound(shells)


def _start_frame(wire: Any) -> Tuple[np.ndarray, np.ndarray]:
    first = _wire_of(wire, "wire", "a Part.Wire, a Part.Edge or a sketch").OrderedEdges[0]
    bspline = _edge_bspline(first)
    a = bspline.FirstParameter
    return np.array(tuple(bspline.value(a))), np.array(tuple(bspline.tangent(a)[0]))


def _start_principal_normal(wire: Any) -> Optional[np.ndarray]:
    """The wire's principal normal at its start (towards the centre of curvature), None
    where it starts straight."""
    first = _wire_of(wire, "wire", "a Part.Wire, a Part.Edge or a sketch").OrderedEdges[0]
    bspline = _edge_bspline(first)
    a = bspline.FirstParameter
    try:
        if not bspline.curvature(a) > 0:
            return None
        n = np.array(tuple(bspline.centerOfCurvature(a))) - np.array(tuple(bspline.value(a)))
    except Part.OCCError:  # no centre of curvature: straight there
        return None
    length = np.linalg.norm(n)
    return n / length if length > 0 and np.isfinite(length) else None


def sweep(wire: Any, profile: Any, *, solid: bool = True, corner: str = "round",
          corner_radius: Optional[float] = None, tolerance: float = 1e-4,
          frame: SweepFrame = "rmf", scale: Tuple[float, float] = (1.0, 1.0),
          scale_knots: Optional[Sequence[Tuple[float, float]]] = None,
          method: str = "ph-rmf", end_profile: Any = None,
          sections: Optional[Sequence[Tuple[Any, ...]]] = None,
          pipe_frame: str = "lightest") -> Any:
    """Sweeps `profile` along `wire` (rmf_wire_sweep), by default with rotation-minimizing
    frames.

    Args:
        wire: a Part.Wire, a Part.Edge or a sketch (one wire): lines, arcs and curves.
        profile: a planar Part.Face (holes allowed), a closed Part.Wire or a sketch (inner
            loops are holes), where it is in space — in the plane normal to the wire at
            its start, or in any plane across the wire (a thread's profile in the axial
            plane), carried rigidly by the frame; its x axis (a sketch's) is the frame's
            initial normal f2. An open edge
            or wire (an arc, a polyline, a line in that plane) sweeps into a sheet
            (``solid=False``).
        solid: close the result with planar caps into a solid.
        corner: "round" or "miter".
        corner_radius: the rounding radius of round corners (None: the library's).
        tolerance: the distance tolerance of the sweep.
        frame: "rmf" (default), "frenet" (as makePipeShell's Frenet mode: along a helix
            the profile's points trace helices, for threads) or ("fixed", (x, y, z)) /
            {"fixed": (x, y, z)} (f2 follows that direction, the binormal mode) or
            ("guide", guide) / {"guide": guide} with a Part.Wire, a Part.Edge or a sketch
            of one wire, converted as `wire` is (f2 towards where the guide crosses the
            wire's normal plane: the profile follows a second rail, makePipeShell's
            auxiliary mode); see :func:`rmfsurf.wire_sweep`. The profile stays where it
            is placed at the start, except with "frenet" on a wire that starts straight,
            where the library chooses f2 there.
        scale: the profile's scale (start, end), linear in arc length: two positive
            numbers ((1, 0.5) tapers a circle along a line into a frustum).
        scale_knots: (fraction, scale) pairs the scale passes through between its start
            and end, at fractions of the wire's length strictly increasing in (0, 1)
            (None: none); see :func:`rmfsurf.wire_sweep`.
        method: how the wire's curves are swept: "ph-rmf" (default), "mobius" or "rrmf"
            (spines with exact rational RMFs: parameter lines orthogonal to rounding); see
            :func:`rmfsurf.wire_sweep`. Lines and arcs are exact whatever the method.
        end_profile: the section at the wire's end (None: `profile` all along), of the
            kinds `profile` takes (as many holes), DRAWN AT THE WIRE'S START, in the plane
            normal to the wire there, like `profile`: it is given in the start frame's
            coordinates and carried to the end by the frame, the section blending
            linearly in arc length from `profile` into it, loop to loop, corner to corner
            (rmf_wire_sweep_between). To taper a circle of radius 2 into one of radius 1,
            draw both circles about the wire's start. Open wires and a constant `scale`
            only; `profile` must lie in the normal plane too.
        sections: the sections the sweep passes through between `profile` and `end_profile`
            (required with them): ``(at, profile)`` items, `at` the fraction of the wire's
            length strictly increasing in (0, 1), each profile of the kinds `profile` takes
            (as many holes), DRAWN AT THE WIRE'S START like `end_profile`, in the same
            placement as `profile`, and carried to its station by the frame; the section
            blends linearly in arc length from each into the next (rmf_wire_sweep_through;
            see :func:`rmfsurf.wire_sweep`). Refusals name ``sections[k]``.

        pipe_frame: how a round profile (circles about the wire: a pipe) is swept along
            curves: "lightest" (default: the same surface in the lightest exact faces,
            degree 5 along the wire instead of 9; along a lone circular helix its screw
            motion, degree 7 with simple knots) or "rmf" (parameter lines orthogonal);
            see :func:`rmfsurf.wire_sweep`.

    Returns:
        A Part.Shape: a Part.Solid (or a Part.Shell with ``solid=False``).
    """
    # The report's figures are measured when asked for (a helix's report costs more than
    # its sweep): not here.
    return _swept(wire, profile, solid=solid, corner=corner, corner_radius=corner_radius,
                  tolerance=tolerance, frame=frame, scale=scale, scale_knots=scale_knots,
                  method=method, end_profile=end_profile, sections=sections,
                  pipe_frame=pipe_frame)[0]


def sweep_with_report(wire: Any, profile: Any, *, solid: bool = True, corner: str = "round",
                      corner_radius: Optional[float] = None, tolerance: float = 1e-4,
                      twist: float = 0.0, closure_symmetry: int = 0,
                      frame: SweepFrame = "rmf", scale: Tuple[float, float] = (1.0, 1.0),
                      scale_knots: Optional[Sequence[Tuple[float, float]]] = None,
                      method: str = "ph-rmf", end_profile: Any = None,
                      sections: Optional[Sequence[Tuple[Any, ...]]] = None,
                      pipe_frame: str = "lightest") -> Tuple[Any, SweepReport]:
    """:func:`sweep` with the wire sweep's `twist` (radians over the whole wire) and
    `closure_symmetry` (closed wires: the frame closes modulo 2π/k; 0 is taken as 1),
    returning the Part.Shape and the library's :class:`rmfsurf.SweepReport` (spine
    distance, RMF angle error, parameter-line orthogonality, singularity margin, face
    count, frame error). `end_profile`, `sections` and `pipe_frame` as for
    :func:`sweep`."""
    shape, result = _swept(wire, profile, solid=solid, corner=corner,
                           corner_radius=corner_radius, tolerance=tolerance, twist=twist,
                           closure_symmetry=closure_symmetry, frame=frame, scale=scale,
                           scale_knots=scale_knots, method=method, end_profile=end_profile,
                           sections=sections, pipe_frame=pipe_frame)
    return shape, result.report()


def _swept(wire: Any, profile: Any, *, solid: bool, corner: str,
           corner_radius: Optional[float], tolerance: float, frame: SweepFrame,
           scale: Tuple[float, float], scale_knots: Optional[Sequence[Tuple[float, float]]],
           method: str, end_profile: Any, sections: Optional[Sequence[Tuple[Any, ...]]],
           pipe_frame: str, twist: float = 0.0, closure_symmetry: int = 0
           ) -> Tuple[Any, Shape]:
    """The Part.Shape of :func:`sweep_with_report`'s sweep and the library's shape."""
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    edges = _path_edges(wire, "wire")
    guide = _frame_guide(frame)
    if guide is not None:  # the guide as the wire is converted, in the library's edges
        frame = ("guide", _path_edges(guide, "frame"))
    origin, tangent = _start_frame(wire)
    principal = _start_principal_normal(wire) if _named(frame, "frenet") else None
    start_f2 = _frame_start_normal(frame, tangent / np.linalg.norm(tangent), principal,
                                   origin)
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
                        initial_normal=f2 if _named(frame, "rmf") else None, twist=twist,
                        closure_symmetry=closure_symmetry, frame=frame, scale=scale,
                        scale_knots=scale_knots, method=method, end_profile=end_outer,
                        end_holes=end_holes, sections=through, pipe_frame=pipe_frame)
    return part_shape(result, min(tolerance, 1e-6)), result


# ---------------------------------------------------------------------------------------
# Cone splines and flat patterns


def cone_spline_from_face(face: Any, tolerance: float = 1e-4, max_pieces: int = 10000
                          ) -> Tuple[ConeSpline, float, float, float]:
    """A developable face (its NURBS form of degree 1 in one direction: the rulings)
    approximated by a cone spline. Returns (spline, t_min, t_max, max_error): the strip
    spans the first ruling's length about its middle."""
    _core.instance(face, "face", Part.Face, "a Part.Face")
    nurbs = face.toNurbs().Faces[0].Surface
    if nurbs.UDegree != 1 and nurbs.VDegree != 1:
        raise ValueError("face: not ruled: its NURBS form has degree (%d, %d), and a "
                         "developable needs degree 1 along its rulings"
                         % (nurbs.UDegree, nurbs.VDegree))
    ruled = surface(nurbs, rulings_along_v=nurbs.UDegree != 1)
    spline = cone_spline_approximate_ruled(ruled, tolerance, max_pieces=max_pieces)
    u0, u1, v0, _ = ruled.domain
    half = 0.5 * float(np.linalg.norm(ruled.eval(u0, v0) - ruled.eval(u1, v0)))
    return spline, -half, half, spline.fit_error


def flat_pattern_edges(developed: ConeSpline, t_min: float, t_max: float) -> List[Any]:
    """The cutting outline of a developed cone spline strip as Part edges: circular arcs
    (or lines) along both boundaries, one per boundary segment, and the two end rulings."""
    _core.instance(developed, "developed", ConeSpline, "an rmfsurf.ConeSpline")
    t_min, t_max = _core.finite(t_min, "t_min"), _core.finite(t_max, "t_max")
    edges = []
    for t in (t_min, t_max):
        boundary = developed.boundary(t)
        breaks = sorted(set(boundary.nurbs().knots))
        for a, b in zip(breaks, breaks[1:]):
            p, m, q = (vector(boundary.eval(s)) for s in (a, 0.5 * (a + b), b))
            line = Part.LineSegment(p, q).toShape()
            if line.distToShape(Part.Vertex(m))[0] < 1e-12 * (1 + p.Length):
                edges.append(line)
            else:
                edges.append(Part.Arc(p, m, q).toShape())
    first, last = developed.boundary(t_min), developed.boundary(t_max)
    for s in first.domain:
        edges.append(Part.LineSegment(vector(first.eval(s)), vector(last.eval(s))).toShape())
    return edges


# ---------------------------------------------------------------------------------------
# Sheet metal: transition pieces


def has_transitions() -> bool:
    """Whether the loaded library has the sheet-metal transitions
    (rmf_sheet_part_transition)."""
    return hasattr(_core.lib, "rmf_sheet_part_transition")


def closed_curve(value: Any, name: str = "curve") -> Curve:
    """A closed edge, wire or face outline (a circle, a polygon, a closed B-spline, ...) as
    one :class:`rmfsurf.Curve`: its edges' exact B-splines in the wire's order, raised to
    one degree and joined at knots of full multiplicity (corners stay corners)."""
    shape = value.OuterWire if hasattr(value, "OuterWire") else value
    if not hasattr(shape, "Edges") or not shape.Edges:
        raise TypeError("%s: expected a closed Part edge or wire, got %s" % (name, type(value).__name__))
    edges = shape.OrderedEdges if hasattr(shape, "OrderedEdges") else shape.Edges
    degree = max(_edge_bspline(e).Degree for e in edges)
    pieces = [_part_curve_data(_edge_bspline(e, degree=degree)) for e in edges]
    return Curve.from_nurbs(*_joined(join_nurbs(pieces, name)))


def _joined(n: NurbsCurve) -> Tuple[int, np.ndarray, np.ndarray, np.ndarray]:
    return n.degree, n.poles, n.knots, n.weights


def transition(bottom: Any, top: Any, thickness: float = 1.0, k_factor: float = 0.5,
               tolerance: float = 1e-4, **options: Any) -> SheetPart:
    """The transition piece between two closed convex planar Part edges or wires (see
    :func:`rmfsurf.transition`, which takes the same keyword options)."""
    return _transition(closed_curve(bottom, "bottom"), closed_curve(top, "top"),
                       thickness=thickness, k_factor=k_factor, tolerance=tolerance, **options)


def part_solid(part: SheetPart) -> Any:
    """The formed part as a ``Part.Solid``, built by OpenCascade from the library's B-rep
    (:meth:`rmfsurf.SheetPart.occ_binary`, ``importBinary``): its faces share their edges
    as the library made them; nothing is sewn or healed."""
    part = _core.instance(part, "part", SheetPart, "an rmfsurf.SheetPart")
    return _from_binary(part.occ_binary("freecad")).Solids[0]


def flat_pattern(part: SheetPart) -> Tuple[Any, Any]:
    """(the flat pattern of the neutral layer as a face in z = 0 bounded by Part lines and
    arcs, the bend lines as a compound of segments)."""
    _core.instance(part, "part", SheetPart, "an rmfsurf.SheetPart")
    outline, bends = [], []
    for e in part.flat_edges():
        a, b = V(e.start[0], e.start[1], 0), V(e.end[0], e.end[1], 0)
        if e.kind == "arc":
            c = V(e.center[0], e.center[1], 0)
            turn = FreeCAD.Rotation(V(0, 0, 1), float(np.degrees(0.5 * e.sweep)))
            shape = Part.Arc(a, c + turn.multVec(a - c), b).toShape()
        else:
            shape = Part.LineSegment(a, b).toShape()
        (outline if e.layer == "cut" else bends).append(shape)
    return Part.Face(Part.Wire(outline)), Part.Compound(bends)


# ---------------------------------------------------------------------------------------
# Unfolding a face


def _one_face(value: Any, name: str = "shape") -> Any:
    """The one face of `value`: a Part.Face, a shape holding exactly one, or a document
    object whose shape is one."""
    shape = _shape_of(value, name)
    if isinstance(shape, Part.Face):
        return shape
    faces = shape.Faces
    if not faces:
        raise ValueError("%s: the %s holds no face; a face is needed" % (name, shape.ShapeType))
    if len(faces) > 1:
        raise ValueError("%s: the %s holds %d faces; whole sheet bodies are not unfolded yet: "
                         "give one face (e.g. shape.Faces[i])"
                         % (name, shape.ShapeType, len(faces)))
    return faces[0]


def _surface_nurbs(surface: Any) -> NurbsSurface:
    """A Part.BSplineSurface's data with clamped knots (a periodic one as its period)."""
    s = surface
    if s.isUPeriodic() or s.isVPeriodic():
        bounds = s.bounds()
        s = s.copy()
        if s.isUPeriodic():
            s.setUNotPeriodic()
        if s.isVPeriodic():
            s.setVNotPeriodic()
        # Made not periodic, the end knots are unclamped: the segment clamps them.
        s.segment(*bounds)
    poles = np.array([[tuple(p) for p in row] for row in s.getPoles()])
    weights = np.array(s.getWeights(), dtype=float)
    return NurbsSurface(s.UDegree, s.VDegree, poles, weights,
                        flat_knots(s.getUKnots(), s.getUMultiplicities()),
                        flat_knots(s.getVKnots(), s.getVMultiplicities()))


def _index_of(shapes: List[Any], shape: Any) -> int:
    """The index of the shape among `shapes` that is the same as `shape` (isSame: the same
    topology whatever the orientation); appended when new."""
    for i, known in enumerate(shapes):
        if known.isSame(shape):
            return i
    shapes.append(shape)
    return len(shapes) - 1


class _Indexed:
    """Vertices and edges of faces indexed once each (isSame: the same topology whatever
    the orientation — a seam, an edge between two faces), with the edges' NURBS curves."""

    def __init__(self) -> None:
        self.vertices: List[Any] = []
        self.edges: List[Any] = []
        self.curves: List[BrepEdge] = []

    def edge(self, e: Any) -> int:
        known = len(self.edges)
        index = _index_of(self.edges, e)
        if index == known:  # a new edge: its curve along its own direction
            start = _index_of(self.vertices, e.firstVertex(False))
            end = _index_of(self.vertices, e.lastVertex(False))
            if e.Degenerated:
                p = np.array(tuple(self.vertices[start].Point))
                self.curves.append(BrepEdge(line_curve(p, p), start, end, degenerate=True))
            else:
                bspline = _edge_bspline(e)
                if e.Orientation == "Reversed":
                    bspline.reverse()
                self.curves.append(BrepEdge(_part_curve_data(bspline), start, end))
        return index

    def points(self) -> np.ndarray:
        return np.array([tuple(v.Point) for v in self.vertices], dtype=float).reshape(-1, 3)

    def loops(self, face: Any, converted: Any) -> List[List[Tuple[int, bool]]]:
        """The face's wires in order (``OrderedEdges``) as loops of edge uses with their
        orientation, the outer wire first: the one bounding the largest region of the face's
        parameter plane (Face.OuterWire takes a hole for it on some faces across a seam)."""
        loops: List[List[Tuple[int, bool]]] = []
        areas: List[float] = []
        for wire in face.Wires:
            uses, uv = [], []
            for e in wire.OrderedEdges:
                uv.append(_pcurve_points(e, converted))
                uses.append((self.edge(e), e.Orientation != "Reversed"))
            loops.append(uses)
            areas.append(abs(_signed_area(uv)))
        if not loops:
            raise ValueError("shape: a face has no wires")
        loops.insert(0, loops.pop(int(np.argmax(areas))))
        return loops


def face_brep(shape: Any) -> Brep:
    """The library's B-rep of one FreeCAD face (:func:`unfold`'s input): its surface (a
    plane as a plane, any other as its NURBS form, ``Face.toNurbs``), its edges once each
    (deduplicated with ``isSame``: a seam is one edge used twice) with their exact NURBS
    curves, and its wires in order (``OrderedEdges``) as loops of edge uses with their
    orientation, the outer wire first."""
    face = _one_face(shape)
    if isinstance(face.Surface, Part.Plane):
        plane = face.Surface
        x = np.array(tuple(_plane_x_axis(plane)))
        y = np.array(tuple(plane.Rotation.multVec(V(0, 1, 0))))
        surface: dict = dict(plane=(np.array(tuple(plane.Position)), _core.cross(x, y), x))
        converted = face
    else:
        converted = face.toNurbs().Faces[0]
        surface = dict(surface=_surface_nurbs(converted.Surface))
    indexed = _Indexed()
    loops = indexed.loops(converted, converted)
    return Brep.create(indexed.points(), indexed.curves,
                       [BrepFace(loops, same_sense=converted.Orientation != "Reversed",
                                 **surface)])


def body_brep(shape: Any) -> Brep:
    """The library's B-rep of a whole FreeCAD solid (:func:`unfold`'s input for a sheet
    body): its faces sharing their edges (indexed once each with ``isSame``), every face
    with its NURBS surface (``Face.toNurbs``) and its loops as in :func:`face_brep`."""
    solid = _shape_of(shape, "shape")
    solids = solid.Solids
    if len(solids) != 1:
        raise ValueError("shape: the %s holds %d solids; a sheet body is one solid"
                         % (solid.ShapeType, len(solids)))
    indexed = _Indexed()
    faces = []
    for face in solids[0].Faces:
        converted = face.toNurbs().Faces[0]
        # The loops are walked on the face itself (its edges are the ones its neighbours
        # share), their parameters read on its NURBS form.
        faces.append(BrepFace(indexed.loops(face, converted),
                              surface=_surface_nurbs(converted.Surface),
                              same_sense=face.Orientation != "Reversed"))
    return Brep.create(indexed.points(), indexed.curves, faces, solid=True)


def _pcurve_points(edge: Any, face: Any, samples: int = 16) -> np.ndarray:
    """Points of an edge's curve in the face's parameter plane, in the edge's direction in
    its wire (a seam's pcurve for that direction)."""
    if isinstance(face.Surface, Part.Plane):  # its parameters: coordinates along its axes
        plane = face.Surface
        x, y = _plane_x_axis(plane), plane.Rotation.multVec(V(0, 1, 0))
        a, b = edge.FirstParameter, edge.LastParameter
        points = np.array([((p - plane.Position).dot(x), (p - plane.Position).dot(y))
                           for p in (edge.valueAt(a + (b - a) * k / samples)
                                     for k in range(samples + 1))])
    else:
        pcurve = face.curveOnSurface(edge)
        if pcurve is not None:
            curve, a, b = pcurve
            uv = [curve.value(a + (b - a) * k / samples) for k in range(samples + 1)]
            points = np.array([(q.x, q.y) for q in uv])
        else:  # no curve on the face stored: the surface's parameters of the edge's points
            a, b = edge.FirstParameter, edge.LastParameter
            points = np.array([face.Surface.parameter(edge.valueAt(a + (b - a) * k / samples))
                               for k in range(samples + 1)])
    return points[::-1] if edge.Orientation == "Reversed" else points


def _signed_area(pieces: List[np.ndarray]) -> float:
    """The signed area of the polygon through the points of the pieces, in order."""
    p = np.concatenate(pieces) if pieces else np.zeros((0, 2))
    if len(p) < 3:
        return 0.0
    q = np.roll(p, -1, axis=0)
    return 0.5 * float(np.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]))


def developability(shape: Any) -> Developability:
    """How developable a FreeCAD face is (see :func:`rmfsurf.developability`): "plane",
    "circular_cylinder", "right_cone", ..., "not_developable", with its curvature and, for a
    face that is not developable, the stretch an unrolling would need."""
    return _developability(face_brep(shape))


def _flat_part_edge(e: FlatEdge) -> Any:
    """A flat edge as a Part edge in z = 0 from its start to its end: a Part.LineSegment or
    an arc of the exact Part.Circle about its centre."""
    a, b = V(float(e.start[0]), float(e.start[1]), 0), V(float(e.end[0]), float(e.end[1]), 0)
    if e.kind == "line":
        return Part.LineSegment(a, b).toShape()
    circle = Part.Circle(V(float(e.center[0]), float(e.center[1]), 0), V(0, 0, 1),
                         float(e.radius))
    # The circle runs counter-clockwise about +z: a clockwise arc is its reverse.
    first = circle.parameter(a if e.sweep > 0 else b)
    arc = Part.ArcOfCircle(circle, first, first + abs(float(e.sweep))).toShape()
    return arc if e.sweep > 0 else arc.reversed()


def flat_face(unfolded: Union[UnfoldedFace, UnfoldedBody]) -> Any:
    """An unrolled face's or body's flat pattern as a Part.Face in the XY plane (normal
    +z): the outline as its outer wire, the holes as inner wires, exact Part.LineSegment
    lines and Part.Circle arcs."""
    u = _core.instance(unfolded, "unfolded", (UnfoldedFace, UnfoldedBody),
                       "an rmfsurf.UnfoldedFace or UnfoldedBody")
    face = Part.Face(Part.Wire([_flat_part_edge(e) for e in u.outline]))
    if u.holes:
        face = face.cutHoles([Part.Wire([_flat_part_edge(e) for e in hole])
                              for hole in u.holes]) or face
    return face


def _is_solid(shape: Any) -> bool:
    try:
        return bool(_shape_of(shape, "shape").Solids)
    except (TypeError, ValueError):
        return False


def unfold(shape: Any, *, k_factor: Any = 0.5, tolerance: float = 1e-4,
           flat_tolerance: float = 0.0) -> FlatPattern:
    """The exact flat pattern of a developable FreeCAD face (rmf_unfold_face) or of a whole
    sheet-metal body (rmf_unfold_body), holes and cutouts kept.

    A face: planes, circular cylinders and right cones (told from the geometry, B-spline
    forms included) exactly; every other developable of degree 1 along its rulings through
    its cone spline within `tolerance`, with bend lines where its pieces meet. A doubly
    curved face is refused (InvalidInputError saying it is not developable).

    A solid: a sheet body of constant thickness made of planes and bends of any developable
    kind. Its skins and thickness are found, one side is developed on the neutral layer at
    `k_factor` and its faces joined along their bends: the outline, the holes and cutouts,
    the bend lines up and down. InvalidInputError naming the face or the point for a face
    that is not developable, a thickness that is not constant, or a pattern that would
    overlap itself.

    Args:
        shape: a Part.Face, a shape holding exactly one face, a solid (a sheet body), or a
            document object whose shape is one of these.
        k_factor: the sheet's K-factor in [0, 1] (ValueError outside), or for a body a table
            of (inner bend radius / thickness, k) rows. One face IS the layer that is
            unrolled, so the K-factor does not change a face's pattern.
        tolerance: the largest distance of the cone spline from a face that is neither a
            plane, a circular cylinder nor a right cone (mm, the document's units); for a
            body also the largest variation of its thickness.
        flat_tolerance: the largest distance of the outline's biarcs from the developed
            boundary where an edge does not develop into a line or an arc (0: the
            tolerance).

    Returns:
        A :class:`FlatPattern`: ``.face`` (a Part.Face in the XY plane with its holes as
        inner wires), ``.bend_lines``, ``.write_dxf(path)``, ``.area``; ``.report`` for a
        face, ``.thickness`` and ``.bends`` for a body.
    """
    tolerance = _core.number(tolerance, "tolerance")
    flat_tolerance = _core.number(flat_tolerance, "flat_tolerance")
    solid = _is_solid(shape)
    k = checked_k_factor(k_factor, table=solid)
    unfolded: Union[UnfoldedFace, UnfoldedBody]
    if solid:
        unfolded = unfold_body(body_brep(shape), k_factor=k, tolerance=tolerance,
                               flat_tolerance=flat_tolerance)
    else:
        unfolded = unfold_face(face_brep(shape), 0, tolerance=tolerance,
                               flat_tolerance=flat_tolerance)
    return FlatPattern(flat_face(unfolded), [_flat_part_edge(e) for e in unfolded.bend_lines],
                       unfolded, k)


# ---------------------------------------------------------------------------------------
# Selection entry points: they take the Gui selection and the document, so that they run
# (and are tested) without the GUI. They add plain Part::Feature copies; the RmfSurf
# workbench (freecad/ in the repository) adds parametric features instead.


def _selected(selection: Any, want: Any) -> Any:
    for item in selection:
        for name, sub in zip(item.SubElementNames or [""], item.SubObjects or [None]):
            found = want(item.Object, name, sub)
            if found is not None:
                return found
    return None


def sweep_selection(selection: Any, document: Any, method: str = "ph-rmf",
                    tolerance: float = 1e-4) -> Any:
    """Sweeps the selected sketch, in its own xy coordinates, along the selected edge with
    frames by `method` (one face per sketch edge, :func:`sweep_sketch_along_edge`)."""
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    sketch = _selected(selection, lambda o, n, s: o if o.TypeId == "Sketcher::SketchObject" else None)
    edge = _selected(selection, lambda o, n, s: s if n.startswith("Edge") and o is not sketch else None)
    if sketch is None or edge is None:
        raise ValueError("select a profile sketch and an edge of another object (the spine)")
    feature = document.addObject("Part::Feature", "RmfSweep")
    feature.Shape = sweep_sketch_along_edge(sketch, edge, method, tolerance)
    document.recompute()
    return feature


def cone_spline_selection(selection: Any, document: Any, tolerance: float = 1e-4) -> List[Any]:
    """The selected developable face as a cone spline surface, its development (a flat
    face in the xy-plane) and its cutting outline."""
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    face = _selected(selection, lambda o, n, s: s if n.startswith("Face") else None)
    if face is None:
        raise ValueError("select one developable face")
    spline, t_min, t_max, error = cone_spline_from_face(face, tolerance)
    developed = spline.develop()
    features = []
    for name, shape in (("ConeSpline", part_face(spline.surface(t_min, t_max))),
                        ("FlatPattern", part_face(developed.surface(t_min, t_max))),
                        ("CuttingOutline",
                         Part.Compound(flat_pattern_edges(developed, t_min, t_max)))):
        feature = document.addObject("Part::Feature", name)
        feature.Shape = shape
        features.append(feature)
    document.recompute()
    FreeCAD.Console.PrintMessage("rmfsurf: %d cone pieces within %.3g of the face\n"
                                 % (spline.piece_count, error))
    return features


def transition_selection(selection: Any, document: Any, thickness: float = 1.0,
                         k_factor: float = 0.5, tolerance: float = 1e-4) -> List[Any]:
    """The transition piece between the two selected closed edges or
    wires (or objects whose shape is one): the formed solid, the flat pattern of the
    neutral layer (a face in the xy-plane; export it as DXF for the cutter) and its bend
    lines."""
    thickness = _core.finite(thickness, "thickness", positive=True)
    k_factor = _core.finite(k_factor, "k_factor")
    tolerance = _core.finite(tolerance, "tolerance", positive=True)
    shapes = []
    for item in selection:
        subs = [s for s in (item.SubObjects or []) if s is not None]
        shapes.extend(subs if subs else [item.Object.Shape])
    closed = [s for s in shapes if s.isClosed() or (s.Wires and s.Wires[0].isClosed())]
    if len(closed) != 2:
        raise ValueError("select two closed edges or wires (e.g. a square and a circle in parallel planes)")
    part = transition(closed[0], closed[1], thickness, k_factor, tolerance)
    face, bends = flat_pattern(part)
    features = []
    for name, shape in (("Transition", part_solid(part)), ("FlatPattern", face), ("BendLines", bends)):
        feature = document.addObject("Part::Feature", name)
        feature.Shape = shape
        features.append(feature)
    document.recompute()
    r = part.report()
    FreeCAD.Console.PrintMessage("rmfsurf: transition of %d pieces, edges within %.3g / %.3g of the curves\n"
                                 % (r.pieces, r.edge_distance[0], r.edge_distance[1]))
    return features
