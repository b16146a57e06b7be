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
}
_VOID = {"rmf_curve_free", "rmf_frames_free", "rmf_surface_free", "rmf_cone_spline_free"}
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
                                else ctypes.c_char_p if name in _STRING else ctypes.c_uint32)
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
        curve = edge.Curve.toBSpline(edge.FirstParameter, edge.LastParameter)
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
