"""rmfsurf for FreeCAD: exact rational sweeps and cone spline surfaces as Part objects.

A pure-Python module over the rmfsurf shared library (ctypes; no compiled extension).
It turns the library's NURBS views -- Cartesian poles, weights, clamped knot vectors --
into ``Part.BSplineCurve``, ``Part.BSplineSurface`` and ``Part.Face`` objects (knots
compressed into distinct values with multiplicities, as FreeCAD wants them), and FreeCAD
edges and faces back into library curves and surfaces.

The library is found through the environment variable RMFSURF_LIBRARY (a path to
librmfsurf.so), next to this file, or on the linker path.

High-level functions, used by the two macros beside this file:

* ``sweep_sketch_along_edge(sketch, edge, method)``: the sketch's profile swept along an
  edge with rotation-minimizing frames (PH cubic rational RMF, or exact rational RMFs by
  Moebius maps or RRMF quintics); one exact rational face per profile edge.
* ``cone_spline_from_face(face, tolerance)``: a developable face approximated by a cone
  spline surface, its exact development and the cutting outline (true arcs and lines).
* ``sweep_wire(wire, profile, holes, corner, radius, ...)``: a ``Part.Wire`` of lines, arcs
  and curves (smooth or with sharp corners, open or closed) and a closed profile (a wire,
  face or edge placed at the wire's start in its normal plane, or a sketch) as a
  ``Part.Solid`` of exact faces (``rmf_wire_sweep``); ``Part.Shell`` for open profiles.

C API conventions (include/rmfsurf.h): every function returns a status (0 = RMF_OK),
rmf_last_error() gives the message; handles are freed by rmf_*_free.
"""

import ctypes
import ctypes.util
import os

import FreeCAD
import Part

# ---------------------------------------------------------------------------------------
# The C API

c_double_p = ctypes.POINTER(ctypes.c_double)


class Vec3(ctypes.Structure):
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double), ("z", ctypes.c_double)]


class NurbsCurveView(ctypes.Structure):
    """RmfNurbsCurve: a borrowed view, valid while its curve lives."""

    _fields_ = [
        ("degree", ctypes.c_uint32),
        ("pole_count", ctypes.c_size_t),
        ("poles", ctypes.POINTER(Vec3)),
        ("weights", c_double_p),
        ("knot_count", ctypes.c_size_t),
        ("knots", c_double_p),
    ]


class NurbsSurfaceView(ctypes.Structure):
    """RmfNurbsSurface: poles indexed i * pole_count_v + j, i along u."""

    _fields_ = [
        ("degree_u", ctypes.c_uint32),
        ("degree_v", ctypes.c_uint32),
        ("pole_count_u", ctypes.c_size_t),
        ("pole_count_v", ctypes.c_size_t),
        ("poles", ctypes.POINTER(Vec3)),
        ("weights", c_double_p),
        ("knot_count_u", ctypes.c_size_t),
        ("knots_u", c_double_p),
        ("knot_count_v", ctypes.c_size_t),
        ("knots_v", c_double_p),
    ]


class Edge(ctypes.Structure):
    """RmfEdge: kind (RMF_EDGE_*), three points, a curve handle for RMF_EDGE_CURVE."""

    _fields_ = [("kind", ctypes.c_uint32), ("points", Vec3 * 3), ("curve", ctypes.c_void_p)]


class WireSweepOptions(ctypes.Structure):
    """RmfWireSweepOptions (initialised by rmf_wire_sweep_options_init)."""

    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("tolerance", ctypes.c_double),
        ("join_tolerance", ctypes.c_double),
        ("corner", ctypes.c_uint32),
        ("corner_radius", ctypes.c_double),
        ("initial_normal", Vec3),
        ("twist", ctypes.c_double),
        ("closure_symmetry", ctypes.c_uint32),
        ("solid", ctypes.c_uint32),
    ]


class ShapeFace(ctypes.Structure):
    """RmfShapeFace: one face of an RmfShape (the surface pointer is borrowed)."""

    _fields_ = [
        ("kind", ctypes.c_uint32),
        ("surface", ctypes.c_void_p),
        ("plane_origin", Vec3),
        ("plane_normal", Vec3),
        ("loop_count", ctypes.c_size_t),
        ("spine_edge", ctypes.c_size_t),
        ("profile_edge", ctypes.c_size_t),
        ("reversed", ctypes.c_uint32),
        ("profile_loop", ctypes.c_size_t),
        ("round_corner", ctypes.c_uint32),
    ]


class SweepReport(ctypes.Structure):
    """RmfSweepReport: the accuracy figures of a wire sweep."""

    _fields_ = [
        ("spine_distance", ctypes.c_double),
        ("rmf_angle_error", ctypes.c_double),
        ("max_parameter_cosine", ctypes.c_double),
        ("singularity_margin", ctypes.c_double),
        ("face_count", ctypes.c_size_t),
        ("corner_turn", ctypes.c_double),
        ("seam_gap", ctypes.c_double),
        ("joint_gap", ctypes.c_double),
    ]


RMF_EDGE_LINE, RMF_EDGE_ARC, RMF_EDGE_CURVE = 0, 1, 2
RMF_CORNER_ROUND, RMF_CORNER_MITER = 0, 1
RMF_FACE_SWEPT, RMF_FACE_PLANE = 0, 1
CORNERS = {"round": RMF_CORNER_ROUND, "miter": RMF_CORNER_MITER}

RMF_CONE_RULE_MIN_VERTEX_DISTANCE = 0
RMF_RRMF_MEASURE_SCALED_ENERGY_RMF = 3
RRMF_ETA_SAMPLES = 64

P = ctypes.c_void_p
PP = ctypes.POINTER(ctypes.c_void_p)
VEC3_P = ctypes.POINTER(Vec3)
SIZE = ctypes.c_size_t

# name: (argument types); every one returns RmfStatus (uint32) unless listed in _VOID.
_SIGNATURES = {
    "rmf_last_error": [],
    "rmf_version": [],
    "rmf_curve_free": [P],
    "rmf_frames_free": [P],
    "rmf_surface_free": [P],
    "rmf_cone_spline_free": [P],
    "rmf_nurbs_curve_create": [ctypes.c_uint32, VEC3_P, c_double_p, SIZE, c_double_p, SIZE, PP],
    "rmf_nurbs_surface_create": [ctypes.c_uint32, ctypes.c_uint32, VEC3_P, c_double_p, SIZE, SIZE,
                                 c_double_p, SIZE, c_double_p, SIZE, PP],
    "rmf_curve_domain": [P, c_double_p, c_double_p],
    "rmf_curve_eval": [P, ctypes.c_double, VEC3_P, VEC3_P],
    "rmf_curve_nurbs": [P, ctypes.POINTER(NurbsCurveView)],
    "rmf_surface_domain": [P, c_double_p, c_double_p, c_double_p, c_double_p],
    "rmf_surface_eval": [P, ctypes.c_double, ctypes.c_double, VEC3_P, VEC3_P, VEC3_P],
    "rmf_surface_nurbs": [P, ctypes.POINTER(NurbsSurfaceView)],
    "rmf_surface_tessellate": [P, ctypes.c_uint32, ctypes.c_uint32, VEC3_P, SIZE,
                               ctypes.POINTER(ctypes.c_uint32), SIZE,
                               ctypes.POINTER(SIZE), ctypes.POINTER(SIZE)],
    "rmf_ph_spline_approximate": [P, P, P, ctypes.c_double, ctypes.c_double, ctypes.c_double,
                                  PP, c_double_p],
    "rmf_ph_spline_hermite": [VEC3_P, VEC3_P, SIZE, PP],
    "rmf_ph_rational_rmf": [P, Vec3, PP],
    "rmf_ph_frenet_frames": [P, PP],
    "rmf_mobius_rrmf_hermite": [VEC3_P, VEC3_P, SIZE, Vec3, PP, PP],
    "rmf_mobius_rrmf_approximate": [P, P, P, ctypes.c_double, ctypes.c_double, SIZE, Vec3, PP, PP],
    "rmf_rrmf_spline_hermite": [VEC3_P, VEC3_P, SIZE, Vec3, ctypes.c_uint32, SIZE, PP, PP],
    "rmf_sweep_surface": [P, P, P, PP],
    "rmf_cone_spline_approximate": [P, P, P, ctypes.c_double, ctypes.c_double, ctypes.c_double,
                                    ctypes.c_double, ctypes.c_double, ctypes.c_uint32, SIZE, PP,
                                    c_double_p],
    "rmf_cone_spline_approximate_ruled": [P, ctypes.c_double, ctypes.c_uint32, SIZE, PP, c_double_p],
    "rmf_cone_spline_surface": [P, ctypes.c_double, ctypes.c_double, PP],
    "rmf_cone_spline_develop": [P, PP],
    "rmf_cone_spline_boundary": [P, ctypes.c_double, PP],
    "rmf_cone_spline_piece_count": [P, ctypes.POINTER(SIZE)],
    "rmf_wire_sweep_options_init": [ctypes.POINTER(WireSweepOptions)],
    "rmf_wire_sweep": [ctypes.POINTER(Edge), SIZE, P, ctypes.POINTER(ctypes.c_void_p), SIZE,
                       ctypes.POINTER(WireSweepOptions), PP],
    "rmf_shape_free": [P],
    "rmf_shape_face_count": [P],
    "rmf_shape_is_solid": [P],
    "rmf_shape_face": [P, SIZE, ctypes.POINTER(ShapeFace)],
    "rmf_shape_face_loop": [P, SIZE, SIZE, PP],
    "rmf_shape_report": [P, ctypes.POINTER(SweepReport)],
    "rmf_shape_write_step": [P, ctypes.c_char_p],
}
_VOID = {"rmf_curve_free", "rmf_frames_free", "rmf_surface_free", "rmf_cone_spline_free",
         "rmf_shape_free"}
_SIZE = {"rmf_shape_face_count": ctypes.c_size_t, "rmf_shape_is_solid": ctypes.c_uint32}
_STRING = {"rmf_last_error", "rmf_version"}

_library = None


class RmfError(RuntimeError):
    """A library call failed; the message is rmf_last_error()."""


def _find_library():
    candidates = [os.environ.get("RMFSURF_LIBRARY"),
                  os.path.join(os.path.dirname(os.path.abspath(__file__)), "librmfsurf.so"),
                  ctypes.util.find_library("rmfsurf")]
    for path in candidates:
        if path and (os.path.exists(path) or not os.path.dirname(path)):
            return path
    raise RmfError("librmfsurf.so not found: set RMFSURF_LIBRARY to its path "
                   "(cargo build --release puts it in target/release/)")


def library():
    """The shared library with the signatures above declared (loaded once)."""
    global _library
    if _library is None:
        lib = ctypes.CDLL(_find_library())
        for name, arguments in _SIGNATURES.items():
            function = getattr(lib, name)
            function.argtypes = arguments
            function.restype = (None if name in _VOID
                                else ctypes.c_char_p if name in _STRING
                                else _SIZE.get(name, ctypes.c_uint32))
        _library = lib
    return _library


def call(name, *arguments):
    """Calls an rmf_* function; raises RmfError with the library's message on failure."""
    status = getattr(library(), name)(*arguments)
    if status != 0:
        raise RmfError(library().rmf_last_error().decode("utf-8", "replace"))


class Handle:
    """An owned library handle, freed with its rmf_*_free when collected."""

    _free = None

    def __init__(self, pointer):
        self.pointer = pointer

    def __del__(self):
        if self.pointer and _library is not None:
            getattr(_library, self._free)(self.pointer)
            self.pointer = None

    @classmethod
    def made_by(cls, name, *arguments):
        """The handle written to the last argument of rmf_<name>(…, &out)."""
        out = ctypes.c_void_p()
        call(name, *arguments, ctypes.byref(out))
        return cls(out)


def vec3(p):
    return Vec3(float(p[0]), float(p[1]), float(p[2]))


def vector(v):
    return FreeCAD.Vector(v.x, v.y, v.z)


def vec3_array(points):
    return (Vec3 * len(points))(*[vec3(p) for p in points])


def double_array(values):
    return (ctypes.c_double * len(values))(*[float(x) for x in values])


def circle_bspline(edge):
    """A circular edge as a rational quadratic B-spline of spans of at most 90 degrees
    (weights cos of the half span; exact). OpenCascade's own conversion uses 120-degree spans,
    which its fixed-order volume integration (Shape.Volume) resolves less well."""
    import math
    circle = edge.Curve
    a, b = edge.FirstParameter, edge.LastParameter
    n = max(1, int(math.ceil((b - a) / (0.5 * math.pi) - 1e-9)))
    half = 0.5 * (b - a) / n
    center, x = circle.Center, circle.XAxis
    y = circle.Axis.cross(x)
    point = lambda t, r: center + x * (r * math.cos(t)) + y * (r * math.sin(t))  # noqa: E731
    poles, weights = [point(a, circle.Radius)], [1.0]
    for k in range(n):
        t = a + 2 * half * k
        poles += [point(t + half, circle.Radius / math.cos(half)), point(t + 2 * half, circle.Radius)]
        weights += [math.cos(half), 1.0]
    poles[-1] = edge.valueAt(b)
    poles[0] = edge.valueAt(a)
    knots = [a + 2 * half * k for k in range(n)] + [b]
    curve = Part.BSplineCurve()
    curve.buildFromPolesMultsKnots(poles, [3] + [2] * (n - 1) + [3], knots, False, 2, weights)
    return curve


def exact_bspline(edge):
    """The edge's exact NURBS form on the edge's range, clamped: circles by
    circle_bspline, everything else by OpenCascade's NURBS conversion (lines as degree 1;
    Curve.toBSpline would approximate a circle by a polynomial of degree 13)."""
    if isinstance(edge.Curve, Part.Circle):
        return circle_bspline(edge)
    nurbs = edge.toNurbs().Edges[0]
    curve = nurbs.Curve.copy()
    if curve.isPeriodic():
        curve.setNotPeriodic()
    curve.segment(nurbs.FirstParameter, nurbs.LastParameter)
    return curve


def knots_and_multiplicities(knots):
    """A flat clamped knot vector as FreeCAD's distinct knots and multiplicities."""
    distinct, multiplicities = [], []
    for k in knots:
        if distinct and k == distinct[-1]:
            multiplicities[-1] += 1
        else:
            distinct.append(k)
            multiplicities.append(1)
    return distinct, multiplicities


def flat_knots(distinct, multiplicities):
    return [k for k, m in zip(distinct, multiplicities) for _ in range(m)]


# ---------------------------------------------------------------------------------------
# Curves and surfaces of the library, as FreeCAD objects


class Curve(Handle):
    """RmfCurve: a piecewise rational Bezier space curve."""

    _free = "rmf_curve_free"

    @classmethod
    def from_nurbs(cls, degree, poles, knots, weights=None):
        w = double_array(weights) if weights is not None else None
        return cls.made_by("rmf_nurbs_curve_create", degree, vec3_array(poles), w, len(poles),
                           double_array(knots), len(knots))

    @classmethod
    def from_part(cls, curve):
        """A FreeCAD B-spline curve (made non-periodic) as a library curve."""
        curve = curve.copy()
        if curve.isPeriodic():
            curve.setNotPeriodic()
        return cls.from_nurbs(curve.Degree, curve.getPoles(),
                              flat_knots(curve.getKnots(), curve.getMultiplicities()),
                              curve.getWeights())

    @classmethod
    def from_edge(cls, edge, placement=None):
        """The edge's exact NURBS form (a line, circle, B-spline … of FreeCAD), optionally
        moved by `placement` (e.g. the inverse of a sketch's placement)."""
        curve = exact_bspline(edge)
        if placement is not None:
            curve.transform(placement.toMatrix())
        return cls.from_part(curve)

    def domain(self):
        lo, hi = ctypes.c_double(), ctypes.c_double()
        call("rmf_curve_domain", self.pointer, ctypes.byref(lo), ctypes.byref(hi))
        return lo.value, hi.value

    def eval(self, t):
        p = Vec3()
        call("rmf_curve_eval", self.pointer, t, ctypes.byref(p), None)
        return vector(p)

    def nurbs(self):
        view = NurbsCurveView()
        call("rmf_curve_nurbs", self.pointer, ctypes.byref(view))
        return view

    def to_part(self):
        """The curve as a Part.BSplineCurve (poles, weights, knots with multiplicities)."""
        view = self.nurbs()
        n = view.pole_count
        knots, multiplicities = knots_and_multiplicities(view.knots[:view.knot_count])
        curve = Part.BSplineCurve()
        curve.buildFromPolesMultsKnots([vector(view.poles[i]) for i in range(n)], multiplicities,
                                       knots, False, view.degree, view.weights[:n])
        return curve


class Frames(Handle):
    """RmfFrames: an adapted frame along a curve."""

    _free = "rmf_frames_free"


class Surface(Handle):
    """RmfSurface: a piecewise tensor-product rational Bezier surface."""

    _free = "rmf_surface_free"

    @classmethod
    def from_part(cls, surface, rulings_along_v=False):
        """A FreeCAD B-spline surface as a library surface; `rulings_along_v` swaps u and v
        (the library wants the rulings of a developable along u)."""
        surface = surface.copy()
        if surface.isUPeriodic():
            surface.setUNotPeriodic()
        if surface.isVPeriodic():
            surface.setVNotPeriodic()
        if rulings_along_v:
            surface.exchangeUV()
        poles = [p for row in surface.getPoles() for p in row]
        weights = [w for row in surface.getWeights() for w in row]
        ku = flat_knots(surface.getUKnots(), surface.getUMultiplicities())
        kv = flat_knots(surface.getVKnots(), surface.getVMultiplicities())
        return cls.made_by("rmf_nurbs_surface_create", surface.UDegree, surface.VDegree,
                           vec3_array(poles), double_array(weights), surface.NbUPoles,
                           surface.NbVPoles, double_array(ku), len(ku), double_array(kv), len(kv))

    def domain(self):
        d = [ctypes.c_double() for _ in range(4)]
        call("rmf_surface_domain", self.pointer, *[ctypes.byref(x) for x in d])
        return tuple(x.value for x in d)

    def eval(self, u, v):
        p = Vec3()
        call("rmf_surface_eval", self.pointer, u, v, ctypes.byref(p), None, None)
        return vector(p)

    def nurbs(self):
        view = NurbsSurfaceView()
        call("rmf_surface_nurbs", self.pointer, ctypes.byref(view))
        return view

    def to_part(self):
        """The surface as a Part.BSplineSurface (pole rows along u, as FreeCAD indexes)."""
        view = self.nurbs()
        nu, nv = view.pole_count_u, view.pole_count_v
        poles = [[vector(view.poles[i * nv + j]) for j in range(nv)] for i in range(nu)]
        weights = [[view.weights[i * nv + j] for j in range(nv)] for i in range(nu)]
        ku, mu = knots_and_multiplicities(view.knots_u[:view.knot_count_u])
        kv, mv = knots_and_multiplicities(view.knots_v[:view.knot_count_v])
        surface = Part.BSplineSurface()
        surface.buildFromPolesMultsKnots(poles, mu, mv, ku, kv, False, False, view.degree_u,
                                         view.degree_v, weights)
        return surface

    def to_face(self):
        """A Part.Face bounded by the surface's natural bounds."""
        return Part.Face(self.to_part())

    def tessellate(self, u_steps, v_steps):
        """Points and triangles of rmf_surface_tessellate (the mesh of the exporters)."""
        n_points, n_triangles = SIZE(), SIZE()
        call("rmf_surface_tessellate", self.pointer, u_steps, v_steps, None, 0, None, 0,
             ctypes.byref(n_points), ctypes.byref(n_triangles))
        points = (Vec3 * n_points.value)()
        triangles = (ctypes.c_uint32 * (3 * n_triangles.value))()
        call("rmf_surface_tessellate", self.pointer, u_steps, v_steps, points, n_points.value,
             triangles, n_triangles.value, ctypes.byref(n_points), ctypes.byref(n_triangles))
        return ([vector(p) for p in points],
                [tuple(triangles[3 * k:3 * k + 3]) for k in range(n_triangles.value)])


class ConeSpline(Handle):
    """RmfConeSpline: a G1 chain of cone, cylinder and plane pieces."""

    _free = "rmf_cone_spline_free"

    def surface(self, t_min, t_max):
        return Surface.made_by("rmf_cone_spline_surface", self.pointer, t_min, t_max)

    def developed(self):
        return ConeSpline.made_by("rmf_cone_spline_develop", self.pointer)

    def boundary(self, t):
        return Curve.made_by("rmf_cone_spline_boundary", self.pointer, t)

    def piece_count(self):
        n = SIZE()
        call("rmf_cone_spline_piece_count", self.pointer, ctypes.byref(n))
        return n.value


class Shape(Handle):
    """RmfShape: the result of a wire sweep, a closed solid or a sheet of exact faces."""

    _free = "rmf_shape_free"

    def faces(self):
        """The faces as ShapeFace records (lateral faces first, then the caps)."""
        out = []
        for k in range(library().rmf_shape_face_count(self.pointer)):
            face = ShapeFace()
            call("rmf_shape_face", self.pointer, k, ctypes.byref(face))
            out.append(face)
        return out

    def surfaces(self):
        """The lateral faces' surfaces as Part.BSplineSurface (exact, from the NURBS views)."""
        surfaces = []
        for face in self.faces():
            if face.kind == RMF_FACE_SWEPT:
                view = Surface(ctypes.c_void_p(face.surface))
                surfaces.append(view.to_part())
                view.pointer = None  # borrowed from the shape: not freed here
        return surfaces

    def is_solid(self):
        return bool(library().rmf_shape_is_solid(self.pointer))

    def report(self):
        r = SweepReport()
        call("rmf_shape_report", self.pointer, ctypes.byref(r))
        return r

    def write_step(self, path):
        call("rmf_shape_write_step", self.pointer, os.fsencode(path))

    def to_part(self):
        """The shape as FreeCAD reads its STEP file: one Part.Solid (faces sharing their
        edges), or the shell of a sheet."""
        import tempfile
        directory = tempfile.mkdtemp(prefix="rmfsurf-")
        path = os.path.join(directory, "shape.step")
        try:
            self.write_step(path)
            shape = Part.Shape()
            shape.read(path)
        finally:
            if os.path.exists(path):
                os.remove(path)
            os.rmdir(directory)
        if self.is_solid() and shape.Solids:
            return shape.Solids[0]
        return shape.Shells[0] if shape.Shells else shape


# ---------------------------------------------------------------------------------------
# Constructions

METHODS = ("ph-rmf", "mobius", "rrmf", "frenet")


def spine_with_frames(spine, method="ph-rmf", tolerance=1e-4, initial_normal=(0, 0, 1),
                      segments=None):
    """A spine curve with rational frames by `method`, from a library curve `spine`:
    'ph-rmf' (PH cubic spline within `tolerance`, its rational RMF), 'frenet' (the same
    spline's rational Frenet frame), 'mobius' (exact rational RMF, `segments` Hermite
    segments, default 16), 'rrmf' (RRMF quintics through `segments` + 1 samples)."""
    n = vec3(initial_normal)
    if method in ("ph-rmf", "frenet"):
        ph = _ph_approximation(spine, tolerance)
        if method == "ph-rmf":
            return ph, Frames.made_by("rmf_ph_rational_rmf", ph.pointer, n)
        return ph, Frames.made_by("rmf_ph_frenet_frames", ph.pointer)
    segments = segments or 16
    if method == "mobius":
        curve, frames = ctypes.c_void_p(), ctypes.c_void_p()
        call("rmf_mobius_rrmf_approximate", spine.pointer, None, None, 0.0, 0.0, segments, n,
             ctypes.byref(curve), ctypes.byref(frames))
        return Curve(curve), Frames(frames)
    if method == "rrmf":
        lo, hi = spine.domain()
        points, tangents = [], []
        for k in range(segments + 1):
            p, d = Vec3(), Vec3()
            call("rmf_curve_eval", spine.pointer, lo + (hi - lo) * k / segments,
                 ctypes.byref(p), ctypes.byref(d))
            points.append((p.x, p.y, p.z))
            tangents.append((d.x, d.y, d.z))
        return rrmf_spline(points, tangents, initial_normal)
    raise RmfError("unknown method %r; expected one of %s" % (method, ", ".join(METHODS)))


def _ph_approximation(spine, tolerance):
    out = ctypes.c_void_p()
    call("rmf_ph_spline_approximate", spine.pointer, None, None, 0.0, 0.0, tolerance,
         ctypes.byref(out), None)
    return Curve(out)


def mobius_hermite(points, tangents, initial_normal=(0, 0, 1)):
    curve, frames = ctypes.c_void_p(), ctypes.c_void_p()
    call("rmf_mobius_rrmf_hermite", vec3_array(points), vec3_array(tangents), len(points),
         vec3(initial_normal), ctypes.byref(curve), ctypes.byref(frames))
    return Curve(curve), Frames(frames)


def rrmf_spline(points, tangents, initial_normal=(0, 0, 1)):
    curve, frames = ctypes.c_void_p(), ctypes.c_void_p()
    call("rmf_rrmf_spline_hermite", vec3_array(points), vec3_array(tangents), len(points),
         vec3(initial_normal), RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, RRMF_ETA_SAMPLES,
         ctypes.byref(curve), ctypes.byref(frames))
    return Curve(curve), Frames(frames)


def sweep(spine, frames, profile):
    """The profile (a library curve, x along f2, y along f3) swept along the spine."""
    return Surface.made_by("rmf_sweep_surface", spine.pointer, frames.pointer, profile.pointer)


def sweep_sketch_along_edge(sketch, edge, method="ph-rmf", tolerance=1e-4,
                            initial_normal=(0, 0, 1)):
    """The sketch's edges, in the sketch's own xy coordinates, swept along `edge` with
    frames by `method`: one exact rational face per sketch edge, as a Part.Shell (or
    a single Part.Face). The sketch's x axis follows f2, its y axis f3."""
    spine, frames = spine_with_frames(Curve.from_edge(edge), method, tolerance, initial_normal)
    local = sketch.Placement.inverse()
    faces = [sweep(spine, frames, Curve.from_edge(e, local)).to_face() for e in sketch.Shape.Edges]
    if not faces:
        raise RmfError("the sketch %s has no edges to sweep" % sketch.Label)
    return faces[0] if len(faces) == 1 else Part.Shell(faces)


def _wire_edges(wire):
    """The edges of a Part.Wire (or Part.Edge) as RmfEdges, in the wire's order: lines
    and circular arcs as such, every other edge as its exact NURBS form. Returns the array
    and the curve handles it borrows."""
    edges = wire.OrderedEdges if hasattr(wire, "OrderedEdges") else [wire]
    records, handles = [], []
    for edge in edges:
        a, b = edge.FirstParameter, edge.LastParameter
        curve = edge.Curve
        record = Edge()
        if isinstance(curve, (Part.Line, Part.LineSegment)):
            record.kind = RMF_EDGE_LINE
            record.points[0], record.points[1] = vec3(edge.valueAt(a)), vec3(edge.valueAt(b))
        elif isinstance(curve, Part.Circle) and not edge.isClosed():
            record.kind = RMF_EDGE_ARC
            for k, t in enumerate((a, 0.5 * (a + b), b)):
                record.points[k] = vec3(edge.valueAt(t))
        elif isinstance(curve, Part.Circle):
            # A full circle: two half arcs.
            m = 0.5 * (a + b)
            for lo, hi in ((a, m), (m, b)):
                half = Edge()
                half.kind = RMF_EDGE_ARC
                for k, t in enumerate((lo, 0.5 * (lo + hi), hi)):
                    half.points[k] = vec3(edge.valueAt(t))
                records.append(half)
            continue
        else:
            handle = Curve.from_edge(edge)
            handles.append(handle)
            record.kind = RMF_EDGE_CURVE
            record.curve = handle.pointer
        records.append(record)
    return (Edge * len(records))(*records), handles


def _start_frame(wire):
    """The wire's start point and unit tangent (along the first ordered edge)."""
    edges = wire.OrderedEdges if hasattr(wire, "OrderedEdges") else [wire]
    first = edges[0]
    if len(edges) > 1:
        second = edges[1]
        ends = [v.Point for v in second.Vertexes]
        if min((first.valueAt(first.FirstParameter) - e).Length for e in ends) < \
                min((first.valueAt(first.LastParameter) - e).Length for e in ends):
            p = first.valueAt(first.LastParameter)
            return p, -first.tangentAt(first.LastParameter)
    return first.valueAt(first.FirstParameter), first.tangentAt(first.FirstParameter)


def _profile_loop(shape, to_local):
    """One closed (or open) loop of edges as a single library NURBS curve in the normal
    plane's coordinates: each edge's exact NURBS form, oriented along the loop, mapped by
    `to_local` (a FreeCAD Matrix), raised to a common degree and joined with C0 knots."""
    edges = shape.OrderedEdges if hasattr(shape, "OrderedEdges") else shape.Edges
    pieces = []
    for edge in edges:
        b = exact_bspline(edge)
        if edge.Orientation == "Reversed":
            b.reverse()
        b.transform(to_local)
        pieces.append(b)
    # Each piece must start where the previous one ends: reverse those given backwards.
    if len(pieces) > 1:
        ends = (pieces[1].StartPoint, pieces[1].EndPoint)
        if min((pieces[0].StartPoint - e).Length for e in ends) < min((pieces[0].EndPoint - e).Length for e in ends):
            pieces[0].reverse()
    for k in range(1, len(pieces)):
        previous_end = pieces[k - 1].EndPoint
        if (pieces[k].EndPoint - previous_end).Length < (pieces[k].StartPoint - previous_end).Length:
            pieces[k].reverse()
    degree = max(p.Degree for p in pieces)
    for p in pieces:
        if p.Degree < degree:
            p.increaseDegree(degree)
    poles, weights, knots = [], [], []
    for p in pieces:
        flat = flat_knots(p.getKnots(), p.getMultiplicities())
        w = p.getWeights()
        if not poles:
            poles, weights, knots = list(p.getPoles()), list(w), flat
            continue
        # Join: the shared pole once, the second piece's weights scaled to match it, its
        # knots shifted to continue, the joint knot of multiplicity `degree` (C0).
        scale = weights[-1] / w[0]
        shift = knots[-1] - flat[0]
        poles += list(p.getPoles())[1:]
        weights += [x * scale for x in w[1:]]
        knots = knots[:-1] + [k + shift for k in flat[degree + 1:]]
    return Curve.from_nurbs(degree, [(q.x, q.y, q.z) for q in poles], knots, weights)


def sweep_wire(wire, profile, holes=(), corner="round", radius=0.0, tolerance=1e-4, solid=True,
               twist=0.0, closure_symmetry=0, initial_normal=None, join_tolerance=1e-7):
    """The profile swept along a Part.Wire of lines, arcs and curves (rmf_wire_sweep), as an
    rmfsurf Shape; ``.to_part()`` gives the Part.Solid.

    `profile` and `holes` are closed wires (or faces, edges) placed at the wire's start in
    its normal plane, as FreeCAD's own sweep takes them, or sketches (their x axis along
    f2). `corner`: "round" (a tangent arc of `radius`; 0: 1.5 times the profile's radius)
    or "miter". `initial_normal`: f2 at the start (default: the profile sketch's x axis, or
    the library's default for a placed profile)."""
    origin, tangent = _start_frame(wire)
    tangent.normalize()
    sketch = getattr(profile, "TypeId", "") == "Sketcher::SketchObject"
    if initial_normal is None:
        if sketch:
            initial_normal = profile.Placement.Rotation.multVec(FreeCAD.Vector(1, 0, 0))
        else:
            up = FreeCAD.Vector(0, 0, 1) if abs(tangent.z) < 0.9 else FreeCAD.Vector(1, 0, 0)
            initial_normal = up - tangent * up.dot(tangent)
    f2 = FreeCAD.Vector(initial_normal)
    f2 = (f2 - tangent * f2.dot(tangent)).normalize()
    f3 = tangent.cross(f2)

    def local(shape):
        if getattr(shape, "TypeId", "") == "Sketcher::SketchObject":
            return _profile_loop(shape.Shape, shape.Placement.inverse().toMatrix())
        m = FreeCAD.Matrix(f2.x, f2.y, f2.z, -f2.dot(origin), f3.x, f3.y, f3.z, -f3.dot(origin),
                           tangent.x, tangent.y, tangent.z, -tangent.dot(origin), 0, 0, 0, 1)
        if hasattr(shape, "OuterWire"):
            shape = shape.OuterWire
        return _profile_loop(shape, m)

    outer = local(profile)
    inner = [local(h) for h in holes]
    edges, handles = _wire_edges(wire)
    options = WireSweepOptions()
    call("rmf_wire_sweep_options_init", ctypes.byref(options))
    options.tolerance = tolerance
    options.join_tolerance = join_tolerance
    if corner not in CORNERS:
        raise RmfError("corner must be one of %s, not %r" % (", ".join(CORNERS), corner))
    options.corner = CORNERS[corner]
    options.corner_radius = radius
    options.initial_normal = vec3(f2)
    options.twist = twist
    options.closure_symmetry = closure_symmetry
    options.solid = 1 if solid else 0
    hole_array = (ctypes.c_void_p * max(1, len(inner)))(*[h.pointer.value for h in inner])
    out = ctypes.c_void_p()
    call("rmf_wire_sweep", edges, len(edges), outer.pointer, hole_array, len(inner), ctypes.byref(options),
         ctypes.byref(out))
    del handles  # the library copied what it needs
    return Shape(out)


def cone_spline_from_face(face, tolerance=1e-4, max_pieces=10000):
    """A developable face (its NURBS form must be of degree 1 in one direction: the
    rulings) approximated by a cone spline. Returns (spline, t_min, t_max, max_error): the
    strip spans the first ruling's length about its middle."""
    surface = face.toNurbs().Faces[0].Surface
    if surface.UDegree != 1 and surface.VDegree != 1:
        raise RmfError("the face is not ruled: its NURBS form has degree (%d, %d), and a "
                       "developable needs degree 1 along its rulings"
                       % (surface.UDegree, surface.VDegree))
    rulings_along_v = surface.UDegree != 1
    ruled = Surface.from_part(surface, rulings_along_v)
    spline, error = ctypes.c_void_p(), ctypes.c_double()
    call("rmf_cone_spline_approximate_ruled", ruled.pointer, tolerance,
         RMF_CONE_RULE_MIN_VERTEX_DISTANCE, max_pieces, ctypes.byref(spline), ctypes.byref(error))
    u0, u1, v0, _ = ruled.domain()
    half = 0.5 * ruled.eval(u0, v0).distanceToPoint(ruled.eval(u1, v0))
    return ConeSpline(spline), -half, half, error.value


def flat_pattern_edges(developed, t_min, t_max):
    """The cutting outline of a developed cone spline strip as FreeCAD edges: circular arcs
    (or lines) along both boundaries, one per boundary segment, and the two end rulings."""
    edges = []
    for t in (t_min, t_max):
        boundary = developed.boundary(t)
        view = boundary.nurbs()
        breaks = sorted(set(view.knots[:view.knot_count]))
        for a, b in zip(breaks, breaks[1:]):
            p, m, q = (boundary.eval(s) for s in (a, 0.5 * (a + b), b))
            if Part.LineSegment(p, q).toShape().distToShape(Part.Vertex(m))[0] < 1e-12 * (1 + p.Length):
                edges.append(Part.LineSegment(p, q).toShape())
            else:
                edges.append(Part.Arc(p, m, q).toShape())
    first, last = developed.boundary(t_min), developed.boundary(t_max)
    lo, hi = first.domain()
    for s in (lo, hi):
        edges.append(Part.LineSegment(first.eval(s), last.eval(s)).toShape())
    return edges


# ---------------------------------------------------------------------------------------
# The macros' entry points: they take the Gui selection and the document, so that they
# can be run (and tested) without the GUI.


def _selected(selection, want):
    for item in selection:
        for name, sub in zip(item.SubElementNames or [""], item.SubObjects or [None]):
            found = want(item.Object, name, sub)
            if found is not None:
                return found
    return None


def sweep_selection(selection, document, method="ph-rmf", tolerance=1e-4):
    """Macro RmfSweep: sweeps the selected sketch along the selected edge."""
    sketch = _selected(selection, lambda o, n, s: o if o.TypeId == "Sketcher::SketchObject" else None)
    edge = _selected(selection, lambda o, n, s: s if n.startswith("Edge") and o is not sketch else None)
    if sketch is None or edge is None:
        raise RmfError("select a profile sketch and an edge of another object (the spine)")
    shape = sweep_sketch_along_edge(sketch, edge, method, tolerance)
    feature = document.addObject("Part::Feature", "RmfSweep")
    feature.Shape = shape
    document.recompute()
    return feature


def cone_spline_selection(selection, document, tolerance=1e-4):
    """Macro RmfConeSpline: the selected developable face as a cone spline surface, its
    development (a flat face in the xy-plane) and its cutting outline."""
    face = _selected(selection, lambda o, n, s: s if n.startswith("Face") else None)
    if face is None:
        raise RmfError("select one developable face")
    spline, t_min, t_max, error = cone_spline_from_face(face, tolerance)
    developed = spline.developed()
    features = []
    for name, shape in (("ConeSpline", spline.surface(t_min, t_max).to_face()),
                        ("FlatPattern", developed.surface(t_min, t_max).to_face()),
                        ("CuttingOutline", Part.Compound(flat_pattern_edges(developed, t_min, t_max)))):
        feature = document.addObject("Part::Feature", name)
        feature.Shape = shape
        features.append(feature)
    document.recompute()
    FreeCAD.Console.PrintMessage("rmfsurf: %d cone pieces within %.3g of the face\n"
                                 % (spline.piece_count(), error))
    return features
