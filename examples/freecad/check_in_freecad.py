"""Checks rmfsurf inside FreeCAD, headless: run with `freecadcmd check_in_freecad.py`.

Started by the test command (integration/tests/freecad.rs), which installs the Python
package rmfsurf (the wheel, carrying the library) where FreeCAD finds it, runs the rmfsurf
command-line tool on examples/cli/*.json and passes, in the environment:
  RMFSURF_EXAMPLES  examples/cli (the JSON inputs)
  RMFSURF_FILES     the tool's outputs: <example>.step, _curves.step, .obj, cone_spline.dxf/.svg
  RMFSURF_WORK      a scratch directory (FreeCAD's own STEP files)

What is checked, each figure printed with its limit:
  A. Part objects from the NURBS views are valid and agree with rmf_curve_eval and
     rmf_surface_eval; developables have Gaussian curvature ~ 0 by FreeCAD's own
     BSplineSurface.curvature(u, v, "Gauss") (a Frenet strip and a pipe show it can fail);
  B. a STEP file written by FreeCAD re-imports to the same surface;
  C. FreeCAD reads the tool's STEP faces and curves back as the same geometry;
  D. FreeCAD reads the tool's DXF flat pattern: true arcs and lines, isometric to the
     spatial boundary curves (measured by FreeCAD on the tool's curve STEP); and the SVG
     drawing of the same pattern;
  E. FreeCAD's mesh reader reads the tool's OBJ as the library's tessellation;
  F. rmfsurf.freecad's selection entry points (sweep_selection, cone_spline_selection),
     with a selection as the GUI would give it (the macros are wrappers of the RmfSurf
     workbench now, checked by integration/tests/workbench.rs);
  G. rmfsurf.freecad.sweep of a wire into a solid;
  H. sheet metal (examples/cli/hopper.json, a square-to-round hopper): the tool's STEP solid
     is a valid closed solid of the expected volume, its DXF flat pattern (read by FreeCAD)
     encloses the area of the formed neutral layer and its flat STEP face the same; the
     transition built in FreeCAD from a square wire and a circle edge (transition_selection);
     and what a FreeCAD user has today to flatten the same part: the Mesh Design
     workbench's unwrapper (flatmesh, LSCM) and an ideal unfolding of the triangles of
     FreeCAD's mesher, their outline lengths and areas against the exact development.
freecadcmd exits 0 on an exception, so the script exits 1 itself on any failure, and
prints FREECAD CHECKS OK last (report lines start with '| ') when everything passed.
"""

import json
import math
import os
import sys
import traceback

import FreeCAD
import Import
import Mesh
import Part
import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

import rmfsurf  # noqa: E402
import rmfsurf.freecad as rmf  # noqa: E402

V = FreeCAD.Vector
EXAMPLES = os.environ.get("RMFSURF_EXAMPLES", "")
FILES = os.environ.get("RMFSURF_FILES", "")
WORK = os.environ.get("RMFSURF_WORK", "/tmp")
GRID = 21

failures = []


def say(text):
    """Prints one line of the report; the marker sets it apart from FreeCAD's own output
    (banner, progress bars and recompute messages share stdout without newlines)."""
    print("\n| " + text)


def check(name, value, limit, below=True):
    """Records a figure; it passes if value <= limit (or >= limit when below=False)."""
    ok = value <= limit if below else value >= limit
    relation = "<=" if below else ">="
    say("  %-66s %10.3e  (%s %.3g)%s" % (name, value, relation, limit, "" if ok else "  FAILED"))
    if not ok:
        failures.append(name)


def require(name, condition):
    say("  %-66s %s" % (name, "yes" if condition else "NO  FAILED"))
    if not condition:
        failures.append(name)


def example(name):
    with open(os.path.join(EXAMPLES, name + ".json")) as f:
        return json.load(f)


def grid(lo, hi, n=GRID):
    return [lo + (hi - lo) * k / (n - 1) for k in range(n)]


def size_of(points):
    box = FreeCAD.BoundBox()
    for p in points:
        box.add(p)
    return box.DiagonalLength


def surface_samples(library_surface):
    u0, u1, v0, v1 = library_surface.domain
    return [(u, v) for u in grid(u0, u1) for v in grid(v0, v1)]


# ---------------------------------------------------------------------------------------
# The constructions, through the C API, from the same inputs as the tool's examples


def polyline(points):
    n = len(points)
    return rmfsurf.Curve.from_nurbs(1, points, [0.0] + [float(k) for k in range(n)] + [n - 1.0])


def circle(radius):
    r, s = radius, 0.5 ** 0.5
    corners = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    return rmfsurf.Curve.from_nurbs(2, [(r * x, r * y, 0) for x, y in corners],
                                [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4],
                                [s if k % 2 else 1.0 for k in range(9)])


def profile_of(spec):
    if "circle" in spec:
        return circle(spec["circle"]["radius"])
    if "line" in spec:
        return polyline([spec["line"]["from"] + [0], spec["line"]["to"] + [0]])
    corners = [p + [0] for p in spec["polygon"]]
    return polyline(corners + [corners[0]])


def built(name):
    """(spine, frames, surface) of a sweep example, built through the C API."""
    sweep = example(name)["sweep"]
    spine = sweep["spine"]
    normal = sweep.get("initial_normal", [0, 0, 1])
    if sweep["method"] == "mobius":
        curve, frames = rmfsurf.mobius_rrmf_hermite(spine["points"], spine["tangents"], normal)
    elif sweep["method"] == "rrmf":
        curve, frames = rmfsurf.rrmf_spline_hermite(spine["points"], spine["tangents"], normal)
    else:
        n = spine["nurbs"]
        nurbs = rmfsurf.Curve.from_nurbs(n["degree"], n["poles"], n["knots"], n.get("weights"))
        curve, frames = rmf.spine_with_frames(nurbs, sweep["method"], sweep["tolerance"], normal)
    return curve, frames, rmfsurf.sweep_surface(curve, frames, profile_of(sweep["profile"]))


def built_cone_spline():
    cone = example("cone_spline")["cone_spline"]
    tangent = cone["developable"]["tangent_surface"]
    n = tangent["curve"]["nurbs"]
    curve = rmfsurf.Curve.from_nurbs(n["degree"], n["poles"], n["knots"])
    spline = rmfsurf.cone_spline_approximate(curve, (tangent["v_min"], tangent["v_max"]),
                                             cone["tolerance"])
    strip = cone["strip"]
    return spline, strip["t_min"], strip["t_max"]


# ---------------------------------------------------------------------------------------
# A. Part objects from the NURBS views


def max_distance(pairs):
    """max |a − b| over pairs of a FreeCAD.Vector and a point (NumPy or Vector)."""
    return max((a - V(*b)).Length for a, b in pairs)


def check_curve(label, curve):
    part = rmf.part_curve(curve)
    require("%s: spine Part.BSplineCurve edge isValid()" % label, part.toShape().isValid())
    lo, hi = curve.domain
    error = max_distance((part.value(t), curve.eval(t)) for t in grid(lo, hi, 201))
    check("%s: spine, |Part value - rmf_curve_eval|" % label, error, 1e-9)
    return part


def check_surface(label, surface):
    part = rmf.part_surface(surface)
    face = Part.Face(part)
    require("%s: Part.Face of the Part.BSplineSurface isValid()" % label, face.isValid())
    samples = surface_samples(surface)
    error = max_distance((part.value(u, v), surface.eval(u, v)) for u, v in samples)
    check("%s: |Part value - rmf_surface_eval|" % label, error, 1e-9)
    return part


def scaled_gauss(part, surface):
    """max |K|·size² by FreeCAD's own curvature, inside the domain."""
    u0, u1, v0, v1 = surface.domain
    size = size_of([V(*surface.eval(u, v)) for u, v in surface_samples(surface)])
    inner = [(u, v) for u in grid(u0, u1)[1:-1] for v in grid(v0, v1)[1:-1]]
    return max(abs(part.curvature(u, v, "Gauss")) for u, v in inner) * size ** 2


def part_a():
    say("A. Part objects from the NURBS views (rmfsurf.freecad), FreeCAD curvature")
    parts = {}
    for name in ("helix_pipe_mobius", "helix_strip_rrmf", "nurbs_moulding_ph"):
        curve, frames, surface = built(name)
        check_curve(name, curve)
        parts[name] = (surface, check_surface(name, surface))
    # Developable: the same NURBS spine with a line profile (PH cubic rational RMF).
    moulding = example("nurbs_moulding_ph")["sweep"]["spine"]["nurbs"]
    spine = rmfsurf.Curve.from_nurbs(moulding["degree"], moulding["poles"], moulding["knots"])
    line = polyline([(-0.2, 0, 0), (0.2, 0, 0)])
    ph, ph_frames = rmf.spine_with_frames(spine, "ph-rmf", 1e-5)
    parts["ph_strip"] = (rmfsurf.sweep_surface(ph, ph_frames, line), None)
    # Control: one PH cubic with its Frenet frame, not rotation-minimizing: K != 0.
    one = rmfsurf.ph_spline_hermite([(0, 0, 0), (1, 1, 1)], [(1, 0, 0), (0, 1, 0)])
    parts["frenet_strip"] = (rmfsurf.sweep_surface(one, rmfsurf.ph_frenet_frames(one), line), None)
    spline, t_min, t_max = built_cone_spline()
    parts["cone_spline"] = (spline.surface(t_min, t_max), None)
    parts["cone_spline_developed"] = (spline.develop().surface(t_min, t_max), None)
    for name in ("ph_strip", "frenet_strip", "cone_spline", "cone_spline_developed"):
        surface, _ = parts[name]
        parts[name] = (surface, check_surface(name, surface))
    for name in ("helix_strip_rrmf", "ph_strip", "cone_spline", "cone_spline_developed"):
        surface, part = parts[name]
        check("%s: developable, FreeCAD max |K|·size²" % name, scaled_gauss(part, surface), 1e-8)
    for name in ("frenet_strip", "helix_pipe_mobius"):
        surface, part = parts[name]
        check("%s: not developable, FreeCAD max |K|·size² (must be large)" % name,
              scaled_gauss(part, surface), 1e-3, below=False)
    return parts


# ---------------------------------------------------------------------------------------
# B. STEP written by FreeCAD, read back


def part_b(parts):
    say("B. STEP written by FreeCAD re-imports to the same surface")
    for name, (surface, part) in sorted(parts.items()):
        path = os.path.join(WORK, "freecad_%s.step" % name)
        Part.Face(part).exportStep(path)
        shape = Part.read(path)
        require("%s: FreeCAD STEP re-imports as one valid face" % name,
                len(shape.Faces) == 1 and shape.isValid())
        read = shape.Faces[0].Surface
        error = max_distance((read.value(u, v), surface.eval(u, v)) for u, v in surface_samples(surface))
        check("%s: FreeCAD STEP round trip, |read - rmf_surface_eval|" % name, error, 1e-9)


# ---------------------------------------------------------------------------------------
# C. The tool's STEP files, read by FreeCAD


def part_c(parts):
    say("C. FreeCAD reads the tool's STEP (faces and curves)")
    spline, t_min, t_max = built_cone_spline()
    curves = {name: built(name)[0] for name in ("helix_pipe_mobius", "helix_strip_rrmf", "nurbs_moulding_ph")}
    curves["cone_spline"] = (spline.boundary(t_min), spline.boundary(t_max))
    for name in ("helix_pipe_mobius", "helix_strip_rrmf", "nurbs_moulding_ph", "cone_spline"):
        surface = parts[name][0]
        shape = Part.read(os.path.join(FILES, name + ".step"))
        require("%s.step: one valid face" % name, len(shape.Faces) == 1 and shape.isValid())
        read = shape.Faces[0].Surface
        error = max_distance((read.value(u, v), surface.eval(u, v)) for u, v in surface_samples(surface))
        check("%s.step: |FreeCAD surface - rmf_surface_eval|" % name, error, 1e-9)
        edges = Part.read(os.path.join(FILES, name + "_curves.step")).Edges
        expected = curves[name] if isinstance(curves[name], tuple) else (curves[name],)
        require("%s_curves.step: %d valid edge(s)" % (name, len(expected)),
                len(edges) == len(expected) and all(e.isValid() for e in edges))
        error = 0.0
        for edge, curve in zip(edges, expected):
            lo, hi = curve.domain
            error = max(error, max_distance((edge.Curve.value(t), curve.eval(t)) for t in grid(lo, hi, 201)))
        check("%s_curves.step: |FreeCAD curve - rmf_curve_eval|" % name, error, 1e-9)


# ---------------------------------------------------------------------------------------
# D. The tool's DXF flat pattern


def part_d():
    say("D. FreeCAD reads the tool's DXF and SVG flat pattern")
    spline, t_min, t_max = built_cone_spline()
    pieces = spline.piece_count
    document = FreeCAD.newDocument("dxf")
    Import.readDXF(os.path.join(FILES, "cone_spline.dxf"))
    edges = [e for o in document.Objects if hasattr(o, "Shape") for e in o.Shape.Edges]
    arcs = [e for e in edges if isinstance(e.Curve, Part.Circle)]
    lines = [e for e in edges if isinstance(e.Curve, (Part.Line, Part.LineSegment))]
    require("DXF: %d entities, all true arcs (Part.Circle) or lines" % len(edges),
            len(arcs) + len(lines) == len(edges))
    require("DXF: %d arcs = 2 x %d pieces, %d lines = pieces + 1" % (len(arcs), pieces, len(lines)),
            len(arcs) == 2 * pieces and len(lines) == pieces + 1)
    width = t_max - t_min
    check("DXF: rulings, max |length - (t_max - t_min)|", max(abs(e.Length - width) for e in lines), 1e-12)
    spatial = sum(e.Length for e in Part.read(os.path.join(FILES, "cone_spline_curves.step")).Edges)
    flat = sum(e.Length for e in arcs)
    check("DXF arcs vs STEP boundary curves (both measured by FreeCAD): rel. length error",
          abs(flat - spatial) / spatial, 1e-9)
    dxf_length = sum(e.Length for e in edges)
    FreeCAD.closeDocument(document.Name)
    # The SVG drawing of the same pattern, through FreeCAD's SVG importer (which turns every
    # path segment into a B-spline): as many segments, the same total length.
    import importSVG
    document = FreeCAD.newDocument("svg")
    importSVG.insert(os.path.join(FILES, "cone_spline.svg"), document.Name)
    svg_edges = [e for o in document.Objects if hasattr(o, "Shape") for e in o.Shape.Edges]
    require("SVG: %d path segments = DXF entities" % len(svg_edges), len(svg_edges) == len(edges))
    check("SVG vs DXF, total length (both read by FreeCAD): rel. error",
          abs(sum(e.Length for e in svg_edges) - dxf_length) / dxf_length, 1e-9)
    FreeCAD.closeDocument(document.Name)


# ---------------------------------------------------------------------------------------
# E. The tool's OBJ meshes


def part_e(parts):
    say("E. FreeCAD's mesh reader reads the tool's OBJ")
    for name in ("helix_pipe_mobius", "helix_strip_rrmf", "nurbs_moulding_ph", "cone_spline"):
        job = example(name)
        steps = job.get("mesh", {})
        points, triangles = parts[name][0].tessellate(steps.get("u_steps", 8), steps.get("v_steps", 8))
        mesh = Mesh.Mesh(os.path.join(FILES, name + ".obj"))
        require("%s.obj: %d points, %d triangles as tessellated" % (name, mesh.CountPoints, mesh.CountFacets),
                mesh.CountPoints == len(points) and mesh.CountFacets == len(triangles))
        # FreeCAD's mesh kernel stores single-precision floats: relative rounding 2^-24
        # per coordinate, so |error| / max |coordinate| stays below sqrt(3)·2^-24 = 1.03e-7.
        error = max((V(p.x, p.y, p.z) - V(*q)).Length / max(abs(q))
                    for p, q in zip(mesh.Points, points))
        check("%s.obj: |FreeCAD mesh point - tessellation| / |point| (float32)" % name, error, 1.04e-7)


# ---------------------------------------------------------------------------------------
# F. The selection entry points


class Selected:
    """What FreeCADGui.Selection.getSelectionEx() gives for one selected object."""

    def __init__(self, obj, names=()):
        self.Object = obj
        self.SubElementNames = list(names)
        self.SubObjects = [obj.Shape.getElement(n) for n in names]


def sweep_inputs(document):
    nurbs = example("nurbs_moulding_ph")["sweep"]["spine"]["nurbs"]
    curve = Part.BSplineCurve()
    knots, multiplicities = rmfsurf.distinct_knots(nurbs["knots"])
    curve.buildFromPolesMultsKnots([V(*p) for p in nurbs["poles"]], [int(m) for m in multiplicities],
                                   [float(k) for k in knots], False, 3)
    spine = document.addObject("Part::Feature", "Spine")
    spine.Shape = curve.toShape()
    sketch = document.addObject("Sketcher::SketchObject", "Profile")
    # The sketch lies anywhere: its own xy coordinates are the profile's.
    sketch.Placement = FreeCAD.Placement(V(5, -3, 2), FreeCAD.Rotation(V(1, 2, 0), 40))
    sketch.addGeometry(Part.Circle(V(0, 0, 0), V(0, 0, 1), 0.2))
    document.recompute()
    return spine, sketch


# 8-point Gauss-Legendre nodes and weights on [-1, 1].
GAUSS = [(-0.9602898564975363, 0.1012285362903763), (-0.7966664774136267, 0.2223810344533745),
         (-0.5255324099163290, 0.3137066458778873), (-0.1834346424956498, 0.3626837833783620),
         (0.1834346424956498, 0.3626837833783620), (0.5255324099163290, 0.3137066458778873),
         (0.7966664774136267, 0.2223810344533745), (0.9602898564975363, 0.1012285362903763)]


def area(face, parts=8):
    """The area of a B-spline face, ∫∫ |s_u × s_v|, by Gauss-Legendre on every knot span
    (split in `parts`), with FreeCAD's own derivatives (Shape.Area integrates too coarsely
    for 1e-9: it is off by about 1e-3 on these rational patches)."""
    surface = face.Surface

    def nodes(knots):
        for a, b in zip(knots, knots[1:]):
            for k in range(parts):
                lo, hi = a + (b - a) * k / parts, a + (b - a) * (k + 1) / parts
                for x, w in GAUSS:
                    yield 0.5 * (lo + hi) + 0.5 * (hi - lo) * x, 0.5 * (hi - lo) * w

    total = 0.0
    for u, wu in nodes(surface.getUKnots()):
        for v, wv in nodes(surface.getVKnots()):
            total += wu * wv * surface.getDN(u, v, 1, 0).cross(surface.getDN(u, v, 0, 1)).Length
    return total


def part_f():
    say("F. The selection entry points")
    document = FreeCAD.newDocument("selections")
    spine, sketch = sweep_inputs(document)
    swept = rmf.sweep_selection([Selected(sketch), Selected(spine, ["Edge1"])], document)
    require("sweep_selection: made RmfSweep, one valid face", swept is not None
            and len(swept.Shape.Faces) == 1 and swept.Shape.isValid())
    face, edge = swept.Shape.Faces[0], spine.Shape.Edges[0]
    u0, u1, v0, v1 = face.ParameterRange
    # Every point of the tube lies 0.2 from the spine (which the PH spline follows to 1e-4).
    error = max(abs(edge.distToShape(Part.Vertex(face.Surface.value(u, v)))[0] - 0.2)
                for u in grid(u0, u1, 9) for v in grid(v0, v1, 41)[1:-1])
    check("RmfSweep: ||point - spine| - radius| (spine tolerance 1e-4)", error, 1e-4)
    # Some samples of this spine admit no RRMF quintic at the spacing 1e-4 needs: 1e-2.
    for method, tolerance in (("mobius", 1e-4), ("rrmf", 1e-2)):
        shape = rmf.sweep_selection([Selected(sketch), Selected(spine, ["Edge1"])], document,
                                    method, tolerance)
        require("sweep_selection(%s): one valid face" % method, shape.Shape.isValid())

    # A cone frustum (r = 1 at z = 0, r = 0.5 at z = 2, 270 degrees) as an exact rational
    # B-spline face with its rulings along v, as a STEP import would give it.
    s = 0.5 ** 0.5
    ring = [(1, 0, 1), (1, 1, s), (0, 1, 1), (-1, 1, s), (-1, 0, 1), (-1, -1, s), (0, -1, 1)]
    poles = [[V(x, y, 0), V(0.5 * x, 0.5 * y, 2)] for x, y, _ in ring]
    weights = [[w, w] for _, _, w in ring]
    frustum = Part.BSplineSurface()
    frustum.buildFromPolesMultsKnots(poles, [3, 2, 2, 3], [2, 2], [0, 1, 2, 3], [0, 1], False, False, 2, 1, weights)
    part = document.addObject("Part::Feature", "Frustum")
    part.Shape = Part.Face(frustum)
    document.recompute()
    rmf.cone_spline_selection([Selected(part, ["Face1"])], document)
    cone, flat, outline = (document.getObject(n) for n in ("ConeSpline", "FlatPattern", "CuttingOutline"))
    require("cone_spline_selection: made ConeSpline, FlatPattern, CuttingOutline, all valid",
            None not in (cone, flat, outline) and all(o.Shape.isValid() for o in (cone, flat, outline)))
    slant = (4.0 + 0.25) ** 0.5
    expected_area = 0.75 * 3.141592653589793 * 1.5 * slant
    for label, feature in (("input frustum face", part), ("cone spline face", cone), ("flat pattern face", flat)):
        a = area(feature.Shape.Faces[0])
        check("%s: rel. area error against the frustum's" % label, abs(a - expected_area) / expected_area, 1e-9)
    check("flat pattern: |z| extent", flat.Shape.BoundBox.ZLength, 1e-12)
    surface = cone.Shape.Faces[0].Surface
    u0, u1, v0, v1 = cone.Shape.Faces[0].ParameterRange
    k = max(abs(surface.curvature(u, v, "Gauss")) for u in grid(u0, u1, 7)[1:-1] for v in grid(v0, v1, 31)[1:-1])
    check("cone spline face: FreeCAD max |K|·size²", k * cone.Shape.BoundBox.DiagonalLength ** 2, 1e-8)
    arcs = [e for e in outline.Shape.Edges if isinstance(e.Curve, Part.Circle)]
    arc_length = sum(e.Length for e in arcs)
    check("cutting outline: rel. error of the arcs' length against 3/4 (2 pi 1 + 2 pi 0.5)",
          abs(arc_length - 0.75 * 2 * 3.141592653589793 * 1.5) / arc_length, 1e-9)
    error = max(min(abs(e.Curve.Radius - slant), abs(e.Curve.Radius - 2 * slant)) for e in arcs)
    check("cutting outline: arc radii vs the slant distances from the apex", error, 1e-9)
    FreeCAD.closeDocument(document.Name)


# ---------------------------------------------------------------------------------------
# G. The wire sweep: rmfsurf.freecad.sweep of a Part wire into a Part.Solid


def part_g():
    say("G. rmfsurf.freecad.sweep: a wire of a line and an arc, a ring profile")
    if not rmfsurf.shapes._has_wire_sweep():
        say("  NOT RUN: this librmfsurf has no rmf_wire_sweep")
        return
    line = Part.LineSegment(V(0, 0, 0), V(20, 0, 0)).toShape()
    arc = Part.ArcOfCircle(Part.Circle(V(20, 10, 0), V(0, 0, 1), 10), -1.5707963267948966, 0).toShape()
    wire = Part.Wire([line, arc])
    outer, inner = Part.makeCircle(2, V(0, 0, 0), V(1, 0, 0)), Part.makeCircle(1, V(0, 0, 0), V(1, 0, 0))
    ring = Part.Face([Part.Wire([outer]), Part.Wire([inner])])
    solid = rmf.sweep(wire, ring)
    require("sweep: a valid Part.Solid", solid.ShapeType == "Solid" and solid.isValid())
    expected = 3.141592653589793 * (4 - 1) * wire.Length
    check("sweep: rel. volume error against pi (R^2 - r^2) L", abs(solid.Volume - expected) / expected, 1e-9)
    box = Part.makeBox(10, 10, 10, V(-5, -5, -5))
    fused = box.fuse(solid)
    require("sweep: fuses with a box into a valid shape", fused.isValid())
    walls = rmf.sweep(wire, ring, solid=False)
    require("sweep, solid=False: the ring's two walls, two valid shells",
            len(walls.Shells) == 2 and walls.isValid())
    # Miter corners on a polyline with a square profile: the volume is A·L exactly.
    poly = Part.makePolygon([V(0, 0, 0), V(6, 0, 0), V(6, 6, 0), V(6, 6, 6)])
    square = Part.Face(Part.makePolygon([V(0, -0.5, -0.5), V(0, 0.5, -0.5), V(0, 0.5, 0.5),
                                         V(0, -0.5, 0.5), V(0, -0.5, -0.5)]))
    mitred = rmf.sweep(poly, square, corner="miter")
    require("sweep, miter corners: a valid Part.Solid", mitred.ShapeType == "Solid" and mitred.isValid())
    check("sweep, miter corners: rel. volume error against A L", abs(mitred.Volume - 18) / 18, 1e-9)
    corner = Part.makeBox(3, 3, 3, V(4.5, -1.5, -1.5))
    parts = [mitred.common(corner), mitred.cut(corner)]
    require("sweep, miter corners: a box's common and cut, valid", all(p.isValid() for p in parts))
    check("sweep, miter corners: the two parts' volumes against the solid's, relative",
          abs(sum(p.Volume for p in parts) - mitred.Volume) / mitred.Volume, 1e-8)
    # A closed wire: a square loop with round corners, the ring swept all the way round.
    loop = Part.makePolygon([V(0, 0, 0), V(20, 0, 0), V(20, 20, 0), V(0, 20, 0), V(0, 0, 0)])
    closed = rmf.sweep(loop, ring)
    require("sweep, closed wire: a valid Part.Solid", closed.ShapeType == "Solid" and closed.isValid())
    r = 1.5 * 2  # the library's corner radius: 1.5 times the profile's
    length = 80 - 4 * (2 * r - r * 3.141592653589793 / 2)
    check("sweep, closed wire: rel. volume error against pi (R^2 - r^2) L",
          abs(closed.Volume - 3.141592653589793 * 3 * length) / (3.141592653589793 * 3 * length), 1e-9)
    # Open profiles sweep into sheets: an arc (its own plane), a line (the wire's normal
    # plane), a polyline; their areas against FreeCAD's own makePipeShell of the same.
    straight = Part.Wire([Part.LineSegment(V(0, 0, 0), V(10, 0, 0)).toShape()])
    for label, profile in [
            ("an arc", Part.ArcOfCircle(Part.Circle(V(0, 0, 0), V(1, 0, 0), 2), 0, 2.0).toShape()),
            ("a line", Part.LineSegment(V(0, -1, 0), V(0, 1, 0)).toShape()),
            ("a polyline", Part.makePolygon([V(0, -1, 0), V(0, 0, 1), V(0, 1, 0)]))]:
        sheet = rmf.sweep(straight, profile, solid=False)
        own = straight.makePipeShell([Part.Wire(profile.Edges)], False, False)
        require("sweep, open profile (%s): a valid sheet" % label, sheet.isValid() and not sheet.Solids)
        check("sweep, open profile (%s): rel. area error against makePipeShell" % label,
              abs(sheet.Area - own.Area) / own.Area, 1e-9)
    try:
        rmf.sweep(straight, Part.LineSegment(V(0, -1, 0), V(1, 1, 0)).toShape(), solid=False)
        require("sweep: a line out of the normal plane is refused", False)
    except ValueError as e:
        require("sweep: a line out of the normal plane is refused naming the profile (%s)" % e,
                str(e).startswith("profile:"))
    # A scale law: a circle from radius 2 to 1 along the line is a frustum.
    frustum = rmf.sweep(straight, Part.Face(Part.Wire([outer])), scale=(1.0, 0.5))
    expected = 3.141592653589793 * 10 * (4 + 2 + 1) / 3
    check("sweep, scale (1, 0.5): rel. volume error against the frustum", abs(frustum.Volume - expected) / expected,
          1e-9)
    try:
        rmf.sweep(ring, ring)
        require("sweep: a Part.Face as the wire is refused", False)
    except TypeError as e:
        require("sweep: a Part.Face as the wire is a TypeError naming 'wire' (%s)" % e, str(e).startswith("wire:"))


# ---------------------------------------------------------------------------------------
# H. Sheet metal


def hopper_curves(document):
    """The hopper of examples/cli/hopper.json as FreeCAD shapes: a square wire, a circle."""
    spec = example("hopper")["sheet"]["transition"]
    square = Part.makePolygon([V(*p) for p in spec["bottom"]["polygon"]] + [V(*spec["bottom"]["polygon"][0])])
    c = spec["top"]["circle"]
    circle = Part.makeCircle(c["radius"], V(*c["center"]), V(*c["normal"]))
    objects = []
    for name, shape in (("Square", square), ("Circle", circle)):
        o = document.addObject("Part::Feature", name)
        o.Shape = shape
        objects.append(o)
    document.recompute()
    return objects


def loop_length_and_area(points):
    """Length and (shoelace) area of a closed planar polygon."""
    n = len(points)
    length = sum(points[k].distanceToPoint(points[(k + 1) % n]) for k in range(n))
    twice = sum(points[k].x * points[(k + 1) % n].y - points[(k + 1) % n].x * points[k].y for k in range(n))
    return length, abs(0.5 * twice)


def hopper_nurbs(spec):
    """The hopper's curves as the command-line tool builds them from the JSON (a degree-1
    polygon, a circle of four rational quadratics), as library curves."""
    corners = spec["bottom"]["polygon"]
    n = len(corners)
    square = rmfsurf.Curve.from_nurbs(1, corners + [corners[0]], [0] + list(range(n + 1)) + [n])
    c = spec["top"]["circle"]
    (cx, cy, cz), r = c["center"], c["radius"]
    xs, ys = [1, 1, 0, -1, -1, -1, 0, 1, 1], [0, 1, 1, 1, 0, -1, -1, -1, 0]
    s = 0.5 ** 0.5
    circle = rmfsurf.Curve.from_nurbs(2, [(cx + r * x, cy + r * y, cz) for x, y in zip(xs, ys)],
                                      [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4], [s if k % 2 else 1 for k in range(9)])
    return square, circle


def unfolded_figures(label, faces, exact_length, exact_area, inner_cut):
    """Meshes `faces` (the neutral layer cut in two disks) with FreeCAD's mesher and
    flattens each: an ideal unfolding of the triangles (lengths and areas of the triangles
    kept: the mesh's chordal errors) and FreeCAD's Mesh Design unwrapper (flatmesh, LSCM);
    their outline lengths (without the inner cut, counted twice) and areas against the exact
    development's."""
    import MeshPart
    for deflection in (1.0, 0.1):
        meshes = [MeshPart.meshFromShape(Shape=f, LinearDeflection=deflection, AngularDeflection=0.5) for f in faces]
        triangles, outline, area_sum = 0, 0.0, 0.0
        unwrapped_length, unwrapped_area, unwrapper = 0.0, 0.0, "flatmesh"
        for mesh in meshes:
            points, tris = mesh.Topology
            triangles += len(tris)
            count = {}
            for f in tris:
                for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
                    key = (min(a, b), max(a, b))
                    count[key] = count.get(key, 0) + 1
            outline += sum(points[a].distanceToPoint(points[b]) for (a, b), n in count.items() if n == 1)
            area_sum += mesh.Area
            try:
                import numpy
                import flatmesh
                flat = flatmesh.FaceUnwrapper(numpy.array([[p.x, p.y, p.z] for p in points]),
                                              numpy.array([list(f) for f in tris]))
                flat.findFlatNodes(5, 0.95)
                loops = [loop_length_and_area([V(*node) for node in loop]) for loop in flat.getFlatBoundaryNodes()]
                length, enclosed = max(loops, key=lambda la: la[1])
                unwrapped_length += length
                unwrapped_area += enclosed
            except Exception as e:  # the unwrapper is optional in FreeCAD's builds
                unwrapper = "flatmesh not available (%s)" % e
        outline -= 2 * inner_cut
        unwrapped_length -= 2 * inner_cut
        say("  %s, FreeCAD mesher (LinearDeflection %.1f, %d triangles), ideal unfolding of the triangles: "
            "outline length error %.2e, area error %.2e" % (label, deflection, triangles,
                                                           abs(outline - exact_length) / exact_length,
                                                           abs(area_sum - exact_area) / exact_area))
        if unwrapper == "flatmesh":
            say("  %s, FreeCAD Mesh Design unwrapper (flatmesh, LSCM) of the same mesh: outline length error "
                "%.2e, area error %.2e" % (label, abs(unwrapped_length - exact_length) / exact_length,
                                           abs(unwrapped_area - exact_area) / exact_area))
        else:
            say("  %s: %s" % (label, unwrapper))


def part_h():
    say("H. Sheet metal: the square-to-round hopper (examples/cli/hopper.json)")
    spec = example("hopper")["sheet"]
    t, k, tol = spec["thickness"], spec["k_factor"], spec["tolerance"]
    # The tool's part, rebuilt here from the same curves through the glue.
    square_curve, circle_curve = hopper_nurbs(spec["transition"])
    part = rmfsurf.transition(square_curve, circle_curve, thickness=t, k_factor=k, tolerance=tol)
    # The exact areas of the layers, by quadrature on FreeCAD's own B-spline faces.
    inner = area(rmf.part_face(part.layer("inner")), 2)
    neutral_face = rmf.part_face(part.layer("neutral"))
    neutral = area(neutral_face, 2)
    # Offsets of a developable grow linearly in area: A(s) = A(0) + s (A(kt) - A(0)) / kt,
    # and the sheet's volume is t A(t/2).
    volume = t * (inner + 0.5 * t * (neutral - inner) / (k * t))
    solid = Part.read(os.path.join(FILES, "hopper.step"))
    shells = solid.Shells
    require("hopper.step: one solid, %d faces, valid, closed shell" % len(solid.Faces),
            len(solid.Solids) == 1 and solid.isValid() and len(shells) == 1 and shells[0].isClosed())
    check("hopper.step: FreeCAD's solid volume against t·A(t/2), relative", abs(solid.Volume - volume) / volume, 1e-8)
    # The DXF flat pattern read by FreeCAD: lines and arcs, one closed outline, bend lines.
    flat_face, bends = rmf.flat_pattern(part)
    outline = flat_face.OuterWire.Edges
    dxf_doc = FreeCAD.newDocument("hopper_dxf")
    Import.readDXF(os.path.join(FILES, "hopper.dxf"))
    edges = [e for o in dxf_doc.Objects if hasattr(o, "Shape") for e in o.Shape.Edges]
    arcs = [e for e in edges if isinstance(e.Curve, Part.Circle)]
    lines = [e for e in edges if isinstance(e.Curve, (Part.Line, Part.LineSegment))]
    require("hopper.dxf: %d entities, all true arcs (%d) or lines (%d)" % (len(edges), len(arcs), len(lines)),
            len(arcs) + len(lines) == len(edges))
    bend_ends = [(b.Vertexes[0].Point, b.Vertexes[-1].Point) for b in bends.Edges]

    def is_bend(e):
        # Classification only (FreeCAD's DXF reader rounds some coordinates in the 1e-7th).
        a, b = e.Vertexes[0].Point, e.Vertexes[-1].Point
        return not isinstance(e.Curve, Part.Circle) and any(
            max(a.distanceToPoint(p), b.distanceToPoint(q)) < 1e-6
            or max(a.distanceToPoint(q), b.distanceToPoint(p)) < 1e-6 for p, q in bend_ends)

    cut = [e for e in edges if not is_bend(e)]
    require("hopper.dxf: %d outline entities and %d bend lines" % (len(cut), len(edges) - len(cut)),
            len(cut) == len(outline) and len(edges) - len(cut) == len(bend_ends))
    dxf_face = Part.Face(Part.Wire(Part.__sortEdges__(cut)))
    check("hopper.dxf read by FreeCAD: face area against the formed neutral layer's, relative",
          abs(dxf_face.Area - neutral) / neutral, 1e-8)
    flat_step = Part.read(os.path.join(FILES, "hopper.flat.step"))
    check("hopper.flat.step: planar face area against the formed neutral layer's, relative",
          abs(flat_step.Faces[0].Area - neutral) / neutral, 1e-8)
    FreeCAD.closeDocument(dxf_doc.Name)
    # Built in FreeCAD from its own shapes: a square wire and a circle edge, directly and by
    # the selection entry point (as a selection gives them, at a tolerance of 1e-3).
    document = FreeCAD.newDocument("sheet")
    square, circle = hopper_curves(document)
    own = rmf.transition(square.Shape, circle.Shape.Edges[0], t, k, tol)
    limit = tol * neutral / volume
    own_solid = rmf.part_solid(own)
    check("transition of FreeCAD's square and circle: volume against the tool's, relative",
          abs(own_solid.Volume - solid.Volume) / solid.Volume, limit)
    # A box over y < -37 (off the symmetry plane, which holds the seam ruling).
    box = Part.makeBox(400, 400, 400, V(-200, -437, -200))
    parts = [own_solid.common(box), own_solid.cut(box)]
    require("transition: a box's common and cut, valid", all(p.isValid() for p in parts))
    check("transition: the two parts' volumes against the solid's, relative",
          abs(sum(p.Volume for p in parts) - own_solid.Volume) / own_solid.Volume, 1e-8)
    rmf.transition_selection([Selected(square), Selected(circle, ["Edge1"])], document, t, k, 1e-3)
    made = [document.getObject(n) for n in ("Transition", "FlatPattern", "BendLines")]
    require("transition_selection: made Transition, FlatPattern, BendLines, all valid",
            None not in made and all(o.Shape.isValid() for o in made))
    if None not in made:
        check("transition_selection (tolerance 1e-3): volume against the tool's, relative",
              abs(made[0].Shape.Volume - solid.Volume) / solid.Volume, 1e-3 * neutral / volume)
        check("transition_selection: flat pattern |z| extent", made[1].Shape.BoundBox.ZLength, 1e-12)
    FreeCAD.closeDocument(document.Name)
    # What a FreeCAD user has today to flatten the same part: triangulate the formed neutral
    # layer with FreeCAD's mesher and unfold it. (SheetMetal unfolds planes and cylinders
    # only; CurvesWB is no Debian package.) The layer is cut in two disks at its middle
    # ruling (an unwrapper needs disks; the seam is the other cut).
    exact_length = sum(e.Length for e in outline)
    exact_area = flat_face.Area
    say("  exact development (rmfsurf): %d lines and arcs, outline length %.6f, area %.6f; "
        "against the formed neutral layer %.2e" % (len(outline), exact_length, exact_area,
                                                   abs(exact_area - neutral) / neutral))
    surface = neutral_face.Surface
    u0, u1, v0, v1 = surface.bounds()
    middle = 0.5 * (v0 + v1)
    first, second = surface.copy(), surface.copy()
    first.segment(u0, u1, v0, middle)
    second.segment(u0, u1, middle, v1)
    inner_cut = surface.value(u0, middle).distanceToPoint(surface.value(u1, middle))
    unfolded_figures("hopper", [Part.Face(first), Part.Face(second)], exact_length, exact_area, inner_cut)


def main():
    say("rmfsurf %s (%s) in FreeCAD %s, Python %s" % (rmfsurf.__version__, os.path.dirname(rmfsurf.__file__),
                                                   ".".join(FreeCAD.Version()[:3]), sys.version.split()[0]))
    parts = part_a()
    part_b(parts)
    part_c(parts)
    part_d()
    part_e(parts)
    part_f()
    part_g()
    part_h()
    if failures:
        say("FREECAD CHECKS FAILED: %s" % "; ".join(failures))
        sys.exit(1)
    say("FREECAD CHECKS OK")
    sys.exit(0)


try:
    main()
except SystemExit:
    raise
except BaseException:
    traceback.print_exc()
    sys.exit(1)
