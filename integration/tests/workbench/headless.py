"""The RmfSurf workbench in headless FreeCAD: run with `freecadcmd headless.py`.

Started by integration/tests/workbench.rs after scripts/install-freecad-addon installed the
addon into a fresh user directory ($HOME a scratch directory). In the environment:
  RMFSURF_WORK      a scratch directory (documents, DXF files)
  RMFSURF_VERSION   the library's version (capi/Cargo.toml)
  RMFSURF_MACROS    examples/freecad (the two macros)

What is checked, each figure printed with its limit:
  A. the installed addon: where rmfsurf_workbench and rmfsurf load from, package.xml read
     by FreeCAD's own parser and the Addon Manager's submission rules (date, maintainer's
     e-mail, license files, URLs, icon, a README without HTML, cffi's backend carried),
     the fixed signatures of make_sweep/make_transition/make_unfold;
  B. RmfSweep: a ring sketch (inner loop) swept along a wire of a line, an arc and a line
     (sub-element links), a circle along a sketch with a sharp corner (round, then miter):
     valid solids, volumes against Pappus's A·L; a sketch constraint changed, recomputed;
     twist, sheet; Frame (rmf, frenet, fixed with FrameDirection, guide with a helical
     Guide: the cylinder's volume), ScaleStart/ScaleEnd (a frustum's volume),
     ScaleKnotFractions/ScaleKnotScales (a chain of frustums; older documents get them
     empty), EndProfile (the same frustum from two circles; older documents
     get it empty), Sections/SectionFractions (a chain of frustums through three circles;
     older documents get them empty); Method (ph-rmf, mobius, rrmf: a line and a B-spline, parameter
     lines orthogonal to rounding with the exact RMFs; older documents get the methods);
     the library's refusals mark the feature Invalid with a message;
  C. RmfUnfold of a developable face (a cone frustum): flat area against the closed form,
     bend lines, true arcs; the DXF export read back by this script's own parser (layers,
     outline area by Green's theorem);
  D. RmfTransition + RmfUnfold: the square-to-round hopper, the flat area against the neutral
     layer's (integrated here with FreeCAD's derivatives), the volume against t·(A_in +
     A_out)/2 (exact for a developable: areas are linear in the offset);
  E. persistence: saved, closed, reopened, the shapes cleared and recomputed: the same
     volumes, areas, faces and vertices; a constraint changed after reopening still drives;
  F. the macros, as thin wrappers of make_sweep, make_unfold and make_transition;
  G. any developable face: rmfsurf.freecad.unfold of a cylinder's wall and of a cone's
     wall with a window (flat area against FreeCAD's face.Area, the window an inner wire of
     the flat face, true arcs and lines), a plate with a round hole, a body refused; RmfUnfold
     features on the faces of a Part::Cylinder and a Part::Box (valid, FlatArea against the
     face's area, SurfaceKind, Curvature, PieceCount = BendLineCount + 1), an extruded
     B-spline (a general cylinder: bend lines, fit error), a window's DXF read back.
freecadcmd exits 0 on an exception, so the script exits 1 itself on any failure, and prints
WORKBENCH CHECKS OK last (report lines start with '| ') when everything passed.
"""

import inspect
import math
import os
import sys
import traceback
import types

import FreeCAD
import Part
import Sketcher

V = FreeCAD.Vector
WORK = os.environ.get("RMFSURF_WORK", "/tmp")
PI = math.pi

failures = []

# 8-point Gauss-Legendre nodes and weights on [-1, 1].
GAUSS = [(-0.9602898564975363, 0.1012285362903763), (-0.7966664774136267, 0.2223810344533745),
         (-0.5255324099163290, 0.3137066458778873), (-0.1834346424956498, 0.3626837833783620),
         (0.1834346424956498, 0.3626837833783620), (0.5255324099163290, 0.3137066458778873),
         (0.7966664774136267, 0.2223810344533745), (0.9602898564975363, 0.1012285362903763)]


def say(text):
    print("\n| " + text)


def check(name, value, limit, below=True):
    ok = value <= limit if below else value >= limit
    say("  %-70s %10.3e  (%s %.3g)%s" % (name, value, "<=" if below else ">=", limit,
                                         "" if ok else "  FAILED"))
    if not ok:
        failures.append(name)


def require(name, condition):
    say("  %-70s %s" % (name, "yes" if condition else "NO  FAILED"))
    if not condition:
        failures.append(name)


def rel(a, b):
    return abs(a - b) / abs(b)


# ---------------------------------------------------------------------------------------
# Inputs


Z_TO_X = FreeCAD.Rotation(V(0, 1, 0), 90)  # a sketch's normal along +x (its x along -z)


def circle_sketch(doc, name, placement, radii):
    """A sketch of concentric circles about its origin, each with a radius constraint;
    returns (sketch, [constraint indices])."""
    sketch = doc.addObject("Sketcher::SketchObject", name)
    sketch.Placement = placement
    constraints = []
    for r in radii:
        g = sketch.addGeometry(Part.Circle(V(0, 0, 0), V(0, 0, 1), r))
        sketch.addConstraint(Sketcher.Constraint("Coincident", g, 3, -1, 1))
        constraints.append(sketch.addConstraint(Sketcher.Constraint("Radius", g, r)))
    return sketch, constraints


def set_radius(sketch, constraint, r):
    sketch.setDatum(constraint, FreeCAD.Units.Quantity("%r mm" % r))


def polyline_sketch(doc, name, placement, points):
    sketch = doc.addObject("Sketcher::SketchObject", name)
    sketch.Placement = placement
    for a, b in zip(points, points[1:]):
        sketch.addGeometry(Part.LineSegment(V(*a), V(*b)))
    for g in range(len(points) - 2):
        sketch.addConstraint(Sketcher.Constraint("Coincident", g, 2, g + 1, 1))
    return sketch


def ring_area(radii):
    return PI * (radii[0] ** 2 - sum(r * r for r in radii[1:]))


# ---------------------------------------------------------------------------------------
# A. The installed addon


def part_a():
    say("A. The installed addon")
    import rmfsurf
    import rmfsurf_workbench
    home = os.path.realpath(os.environ["HOME"])
    addon = os.path.realpath(rmfsurf_workbench.ADDON_DIR)
    require("rmfsurf_workbench loads from %s" % addon,
            addon == os.path.realpath(os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "RmfSurf"))
            and addon.startswith(home + os.sep))
    require("rmfsurf (the library) loads from the addon's folder",
            os.path.realpath(rmfsurf.__file__).startswith(addon + os.sep))
    meta = FreeCAD.Metadata(os.path.join(addon, "package.xml"))
    require("package.xml (FreeCAD's parser): name RmfSurf, version %s = the library's %s"
            % (meta.Version, rmfsurf.__version__),
            meta.Name == "RmfSurf" and meta.Version == rmfsurf.__version__
            == os.environ["RMFSURF_VERSION"] == rmfsurf_workbench.__version__)
    licenses = [entry["name"] for entry in meta.License]
    require("package.xml: license %s, FreeCAD >= %s, supports this FreeCAD"
            % (licenses, meta.FreeCADMin),
            licenses == ["MIT", "Apache-2.0"] and meta.FreeCADMin.startswith("0.20")
            and meta.supportsCurrentFreeCAD())
    check_submission_rules(addon, meta)
    workbenches = meta.Content.get("workbench", [])
    require("package.xml: one workbench, class RmfSurfWorkbench, its icon exists",
            len(workbenches) == 1 and workbenches[0].Classname == "RmfSurfWorkbench"
            and os.path.isfile(os.path.join(addon, workbenches[0].Icon))
            and os.path.isfile(os.path.join(addon, meta.Icon)))
    expected = {
        "make_sweep": "(doc, spine, profile, solid=True, corner='round', corner_radius=None, "
                      "tolerance=0.0001)",
        "make_transition": "(doc, bottom, top, thickness, k_factor=0.5, tolerance=0.0001)",
        "make_unfold": "(doc, feature)",
    }
    for name, signature in expected.items():
        actual = str(inspect.signature(getattr(rmfsurf_workbench, name)))
        require("rmfsurf_workbench.%s%s" % (name, actual), actual == signature)


def check_submission_rules(addon, meta):
    """What the Addon Manager's submission rules (FreeCAD-addons Documentation/Submission.md
    and the Package_Metadata page) ask of an addon, in the tree as installed: a dated
    version, a maintainer with an e-mail, license files, the repository with its branch, the
    bug tracker and the documentation, an SVG icon of at most 10 KB, a README without HTML,
    and the compiled dependencies the Addon Manager does not install carried along."""
    import datetime
    import re
    import xml.etree.ElementTree as ElementTree
    (date,) = [entry["contents"] for entry in meta.getGenericMetadata("date")]
    day = datetime.date.fromisoformat(date)
    require("package.xml: date %s, a day not after today" % date,
            day <= datetime.date.today())
    require("package.xml: maintainer %s" % meta.Maintainer,
            len(meta.Maintainer) >= 1 and all(
                re.fullmatch(r"[^@\s]+@[^@\s]+\.[a-z]{2,}", m["email"]) for m in meta.Maintainer))
    for entry in meta.License:
        path = os.path.join(addon, entry["file"])
        require("license %s: the file %s is in the addon (%d bytes)"
                % (entry["name"], entry["file"], os.path.getsize(path) if os.path.isfile(path)
                   else 0),
                os.path.isfile(path) and os.path.getsize(path) > 1000)
    urls = {u["type"]: u for u in meta.Urls}
    require("package.xml: urls %s" % sorted(urls),
            {"repository", "bugtracker", "documentation", "readme"} <= set(urls)
            and all(u["location"].startswith("https://") for u in urls.values())
            and urls["repository"].get("branch"))
    icon = os.path.join(addon, meta.Icon)
    root = ElementTree.parse(icon).getroot()
    require("the icon %s: SVG, %d bytes (at most 10 KB)" % (meta.Icon, os.path.getsize(icon)),
            root.tag.endswith("svg") and os.path.getsize(icon) <= 10 * 1024)
    with open(os.path.join(addon, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    tags = re.findall(r"<[A-Za-z!/][^>]*>", readme)
    require("README.md: %d characters, no HTML %s" % (len(readme), tags[:3]),
            len(readme) > 500 and not tags)
    backends = sorted(n for n in os.listdir(addon) if n.startswith("_cffi_backend."))
    pythons = sorted({re.search(r"cpython-(3\d+)", n).group(1) for n in backends}, key=int)
    require("cffi's backend carried for CPython %s, with its license" % pythons,
            pythons == ["38", "39", "310", "311", "312", "313"]
            and os.path.isfile(os.path.join(addon, "LICENSE-cffi")))


# ---------------------------------------------------------------------------------------
# B. RmfSweep


def ring_sweep(doc):
    """A ring (outer radius 3, inner loop 1.5) along a line, a tangent quarter arc (radius
    20) and a line; the spine as three sub-element links of a Part wire."""
    import rmfsurf_workbench as wb
    spine = doc.addObject("Part::Feature", "Spine")
    spine.Shape = Part.Wire([
        Part.LineSegment(V(0, 0, 0), V(40, 0, 0)).toShape(),
        Part.ArcOfCircle(Part.Circle(V(40, 20, 0), V(0, 0, 1), 20), -PI / 2, 0).toShape(),
        Part.LineSegment(V(60, 20, 0), V(60, 60, 0)).toShape()])
    profile, constraints = circle_sketch(doc, "Ring", FreeCAD.Placement(V(0, 0, 0), Z_TO_X),
                                         (3.0, 1.5))
    doc.recompute()
    sweep = wb.make_sweep(doc, (spine, ["Edge1", "Edge2", "Edge3"]), profile)
    return sweep, profile, constraints, 80 + 10 * PI


def check_solid(label, shape, volume):
    require("%s: a valid solid" % label, shape.ShapeType == "Solid" and shape.isValid())
    check("%s: rel. volume error against A·L" % label, rel(shape.Volume, volume), 1e-9)
    check("%s: the same, volume by this script (divergence theorem)" % label,
          rel(divergence_volume(shape), volume), 1e-11)


def divergence_volume(shape, parts=8):
    """V = ∮ (x·a)(n·a) dA — independent of FreeCAD's volume integration: Gauss-Legendre on
    every knot span of the curved faces with FreeCAD's derivatives and oriented normals;
    planar faces bounded by straight edges (polygonal caps, the sides of a polygon swept
    along a line) exactly from their triangles; a direction a in the planes of the other
    planar faces (round caps), so that they count nothing."""
    round_caps = [f.normalAt(*f.ParameterRange[::2]) for f in shape.Faces
                  if isinstance(f.Surface, Part.Plane) and not straight_edged(f)]
    # Without round caps (a closed ring, a polygon along lines) any direction serves.
    a = V(0.3, 0.5, 0.7) if not round_caps else round_caps[0].cross(
        next((n for n in round_caps if n.cross(round_caps[0]).Length > 1e-6), V(0.3, 0.5, 0.7)))
    a.normalize()
    if any(abs(n.dot(a)) > 1e-12 for n in round_caps):
        raise ValueError("no direction lies in every round cap's plane")
    total = 0.0
    for face in shape.Faces:
        surface = face.Surface
        if isinstance(surface, Part.Plane):
            if straight_edged(face):
                total += polygon_flux(face, a)
            continue
        u0, u1, v0, v1 = face.ParameterRange
        for u, wu in gauss_nodes(_breaks(knots_of(surface, 'U'), u0, u1), parts):
            for v, wv in gauss_nodes(_breaks(knots_of(surface, 'V'), v0, v1), parts):
                du, dv = surface.getDN(u, v, 1, 0), surface.getDN(u, v, 0, 1)
                total += wu * wv * surface.value(u, v).dot(a) * face.normalAt(u, v).dot(a) \
                    * du.cross(dv).Length
    return total


def straight_edged(face):
    return all(isinstance(e.Curve, (Part.Line, Part.LineSegment)) for e in face.Edges)


def polygon_flux(face, a):
    """∫ (x·a)(n·a) dA over a planar face bounded by straight edges: its triangles are the
    face exactly, x·a linear on each (the value at its centroid times its area)."""
    n = face.normalAt(*face.ParameterRange[::2])
    points, triangles = face.tessellate(1.0)
    flux = 0.0
    for i, j, k in triangles:
        p, q, r = points[i], points[j], points[k]
        area = 0.5 * (q - p).cross(r - p).Length
        flux += area * ((p + q + r) * (1.0 / 3.0)).dot(a)
    return flux * n.dot(a)


def part_b(doc):
    say("B. RmfSweep")
    import rmfsurf_workbench as wb
    sweep, profile, radius, length = ring_sweep(doc)
    require("RmfSweep: Proxy type RmfSweep, valid, links 3 edges and the sketch",
            sweep.Proxy.Type == "RmfSweep" and sweep.isValid()
            and sweep.Spine[0][1] == ("Edge1", "Edge2", "Edge3") and sweep.Profile[0] is profile)
    check_solid("ring r 3/1.5 along line+arc+line", sweep.Shape, ring_area((3, 1.5)) * length)
    before = sweep.Shape.Volume
    require("FaceCount %d = the solid's faces" % sweep.FaceCount,
            sweep.FaceCount == len(sweep.Shape.Faces) > 0)
    check("SpineDistance (lines and arcs: exact)", sweep.SpineDistance, 1e-12)
    check("RmfDefect (radians)", sweep.RmfDefect, 1e-12)
    check("Orthogonality, max |cos| of the parameter lines", sweep.Orthogonality, 1e-9)
    # Sampled by the library (the profile's extent towards the arc's centre).
    check("SingularityMargin against 1 - 3/20 at the arc", abs(sweep.SingularityMargin - 0.85),
          1e-6)

    set_radius(profile, radius[0], 4.0)
    doc.recompute()
    check_solid("sketch constraint 3 -> 4, recomputed", sweep.Shape, ring_area((4, 1.5)) * length)
    say("  volume %.12g before, %.12g after the constraint change" % (before, sweep.Shape.Volume))

    sweep.Twist = 90
    doc.recompute()
    check_solid("Twist 90°", sweep.Shape, ring_area((4, 1.5)) * length)
    check("Twist 90°: the parameter lines are tilted (Orthogonality)", sweep.Orthogonality,
          1e-3, below=False)
    say("  Twist 90°: RmfDefect %.3g rad against the RMF plus the twist" % sweep.RmfDefect)
    sweep.Twist = 0
    sweep.Solid = False
    doc.recompute()
    require("Solid = False: the lateral faces only (%d), no solid" % len(sweep.Shape.Faces),
            sweep.isValid() and not sweep.Shape.Solids
            and len(sweep.Shape.Faces) == sweep.FaceCount
            and not any(isinstance(f.Surface, Part.Plane) for f in sweep.Shape.Faces))
    check("Solid = False: rel. area error against 2π(4 + 1.5)·L (integrated here)",
          rel(sum(nurbs_area(f) for f in sweep.Shape.Faces), 2 * PI * 5.5 * length), 1e-11)
    sweep.Solid = True
    doc.recompute()

    # The library's refusal: the outer radius beyond the arc's radius (Mäurer & Jüttler
    # Cor. 7) — Invalid with the library's message, the report view without a traceback.
    set_radius(profile, radius[0], 25.0)
    doc.recompute()
    message = sweep.getStatusString()
    require("outer radius 25 > the arc's 20: Invalid, '%s'" % message,
            not sweep.isValid() and "Invalid" in sweep.State and "RmfSweep" in message)
    open_sketch = polyline_sketch(doc, "Open", FreeCAD.Placement(V(0, 0, 0), Z_TO_X),
                                  [(-1, -1, 0), (1, -1, 0), (0, 1, 0)])
    set_radius(profile, radius[0], 4.0)
    sweep.Profile = open_sketch
    doc.recompute()
    require("an open profile with Solid: Invalid, '%s'" % sweep.getStatusString(),
            not sweep.isValid() and "needs a closed profile" in sweep.getStatusString())
    sweep.Solid = False
    doc.recompute()
    require("an open profile with Solid = False: a valid sheet",
            sweep.isValid() and sweep.Shape.isValid() and not sweep.Shape.Solids
            and len(sweep.Shape.Faces) > 0)
    sweep.Solid = True
    sweep.Profile = profile
    doc.removeObject(open_sketch.Name)
    doc.recompute()
    require("profile restored: valid again", sweep.isValid())
    check_solid("restored", sweep.Shape, ring_area((4, 1.5)) * length)

    # Twist on a profile without rotational symmetry: a 4 x 2 rectangle along a line; the
    # end cap turns by the twist.
    line = doc.addObject("Part::Feature", "Line")
    line.Shape = Part.LineSegment(V(0, -40, 0), V(30, -40, 0)).toShape()
    rectangle = polyline_sketch(doc, "Rectangle", FreeCAD.Placement(V(0, -40, 0), Z_TO_X),
                                [(-2, -1, 0), (2, -1, 0), (2, 1, 0), (-2, 1, 0), (-2, -1, 0)])
    rectangle.addConstraint(Sketcher.Constraint("Coincident", 3, 2, 0, 1))
    doc.recompute()
    bar = wb.make_sweep(doc, line, rectangle)

    def cap():
        return next(f for f in bar.Shape.Faces if isinstance(f.Surface, Part.Plane)
                    and abs(f.CenterOfMass.x - 30) < 1e-9).BoundBox

    untwisted = cap()
    bar.Twist = 90
    doc.recompute()
    twisted = cap()
    check_solid("a 4 x 2 rectangle along a line, Twist 90°", bar.Shape, 8 * 30)
    check("Twist 90°: the end cap turned, |extents (y, z) - (4, 2)| (untwisted (2, 4))",
          max(abs(twisted.YLength - 4), abs(twisted.ZLength - 2), abs(untwisted.YLength - 2),
              abs(untwisted.ZLength - 4)), 1e-9)
    doc.removeObject(bar.Name)
    doc.removeObject(rectangle.Name)
    doc.removeObject(line.Name)
    doc.recompute()

    # Frame and scale: the properties and their defaults; a circle of radius 2 scaled to 1
    # along a line of 30 is a frustum (the scale law); the frames on a 4 x 2 rectangle keep
    # its volume; a fixed frame without a direction and a scale of 0 are refused, naming
    # the property.
    require("Frame %r of %s, FrameDirection %s, Guide %r, ScaleStart %r, ScaleEnd %r, "
            "FrameError %r"
            % (sweep.Frame, sweep.getEnumerationsOfProperty("Frame"), tuple(sweep.FrameDirection),
               sweep.Guide, sweep.ScaleStart, sweep.ScaleEnd, sweep.FrameError),
            sweep.Frame == "rmf" and sweep.getEnumerationsOfProperty("Frame")
            == ["rmf", "frenet", "fixed", "guide"] and tuple(sweep.FrameDirection) == (0, 0, 0)
            and sweep.Guide is None and sweep.ScaleStart == 1.0 and sweep.ScaleEnd == 1.0
            and sweep.FrameError == 0.0)
    axis = doc.addObject("Part::Feature", "Axis")
    axis.Shape = Part.LineSegment(V(0, -80, 0), V(30, -80, 0)).toShape()
    cone, _ = circle_sketch(doc, "Cone", FreeCAD.Placement(V(0, -80, 0), Z_TO_X), (2.0,))
    doc.recompute()
    frustum = wb.make_sweep(doc, axis, cone)
    frustum.ScaleEnd = 0.5
    doc.recompute()
    check_solid("a circle r 2 along a line of 30, ScaleEnd 0.5: the frustum", frustum.Shape,
                PI * 30 * (4 + 2 + 1) / 3)
    # Knots of the scale law: none by default (and on a document before them); ScaleEnd back
    # at 1 through the knots (0.25, 2) and (0.75, 0.5): the chain of frustums of lengths 7.5,
    # 15, 7.5 between the scales 1, 2, 0.5, 1; lists of different lengths, a fraction out of
    # (0, 1) and a scale of 0 are refused naming the property; emptied: the cylinder.
    require("ScaleKnotFractions %r, ScaleKnotScales %r of a new RmfSweep: empty"
            % (frustum.ScaleKnotFractions, frustum.ScaleKnotScales),
            list(frustum.ScaleKnotFractions) == [] and list(frustum.ScaleKnotScales) == [])
    frustum.ScaleEnd = 1.0
    frustum.ScaleKnotFractions = [0.25, 0.75]
    frustum.ScaleKnotScales = [2.0, 0.5]
    doc.recompute()
    chain = [(0.0, 1.0), (0.25, 2.0), (0.75, 0.5), (1.0, 1.0)]
    check_solid("a circle r 2 along a line of 30 through the knots 1, 2, 0.5, 1: the frustums",
                frustum.Shape, sum(PI * 4 * 30 * (f1 - f0) * (a * a + a * b + b * b) / 3
                                   for (f0, a), (f1, b) in zip(chain, chain[1:])))
    for fractions, scales, word in (([0.25, 0.75], [2.0], "ScaleKnotScales"),
                                    ([0.25, 1.0], [2.0, 0.5], "ScaleKnotFractions[1]"),
                                    ([0.75, 0.25], [2.0, 0.5], "ScaleKnotFractions[1]"),
                                    ([0.25, 0.75], [2.0, 0.0], "ScaleKnotScales[1]")):
        frustum.ScaleKnotFractions, frustum.ScaleKnotScales = fractions, scales
        doc.recompute()
        message = frustum.getStatusString()
        require("ScaleKnotFractions %r, ScaleKnotScales %r: Invalid, '%s'"
                % (fractions, scales, message), not frustum.isValid() and word in message)
    frustum.ScaleKnotFractions, frustum.ScaleKnotScales = [], []
    for name in ("ScaleKnotFractions", "ScaleKnotScales"):
        frustum.removeProperty(name)
    frustum.Proxy.onDocumentRestored(frustum)
    doc.recompute()
    require("no ScaleKnotFractions/ScaleKnotScales (a document before them): added empty, valid",
            "ScaleKnotScales" in frustum.PropertiesList and not frustum.ScaleKnotFractions
            and frustum.isValid())
    check_solid("no knots, ScaleEnd 1: the cylinder", frustum.Shape, PI * 4 * 30)
    # EndProfile: empty by default (and on a document before it); a circle of radius 1
    # drawn at the start as the end profile, ScaleEnd back at 1: the same frustum, by the
    # blend of the two profiles; a ring (a hole the profile has not) is refused naming
    # EndProfile; emptied again: the cylinder.
    frustum.ScaleEnd = 1.0
    require("EndProfile of a new RmfSweep: empty (%r)" % (frustum.EndProfile,),
            not frustum.EndProfile)
    end_circle, _ = circle_sketch(doc, "EndCircle", FreeCAD.Placement(V(0, -80, 0), Z_TO_X),
                                  (1.0,))
    doc.recompute()
    frustum.EndProfile = (end_circle, [])
    doc.recompute()
    check_solid("a circle r 2 into an EndProfile circle r 1 along a line of 30: the frustum",
                frustum.Shape, PI * 30 * (4 + 2 + 1) / 3)
    # Sections/SectionFractions: empty by default (and on a document before them); a circle
    # of radius 3 drawn at the start as a section at 0.25: the chain of two frustums
    # π/3 Σ Lᵢ (aᵢ² + aᵢ aᵢ₊₁ + aᵢ₊₁²) through radii 2, 3, 1; a fraction missing is refused
    # naming both properties, sections without an EndProfile naming Sections.
    require("Sections %r, SectionFractions %r of a new RmfSweep: empty"
            % (frustum.Sections, frustum.SectionFractions),
            list(frustum.Sections) == [] and list(frustum.SectionFractions) == [])
    mid_circle, _ = circle_sketch(doc, "MidCircle", FreeCAD.Placement(V(0, -80, 0), Z_TO_X),
                                  (3.0,))
    doc.recompute()
    frustum.Sections = [mid_circle]
    frustum.SectionFractions = [0.25]
    doc.recompute()
    chain = [(0.0, 2.0), (0.25, 3.0), (1.0, 1.0)]
    check_solid("a circle r 2 through Sections r 3 at 0.25 into r 1 along 30: the frustums",
                frustum.Shape, sum(PI / 3 * (f1 - f0) * 30 * (a * a + a * b + b * b)
                                   for (f0, a), (f1, b) in zip(chain, chain[1:])))
    for fractions, end, word in (([], end_circle, "Sections, SectionFractions"),
                                 ([1.0], end_circle, "SectionFractions[0]"),
                                 ([0.25], None, "Sections: need an EndProfile")):
        frustum.SectionFractions = fractions
        frustum.EndProfile = (end, []) if end is not None else None
        doc.recompute()
        message = frustum.getStatusString()
        require("SectionFractions %r, EndProfile %s: Invalid, '%s'"
                % (fractions, end and end.Name, message),
                not frustum.isValid() and word in message)
    frustum.EndProfile = (end_circle, [])
    frustum.Sections, frustum.SectionFractions = [], []
    for name in ("Sections", "SectionFractions"):
        frustum.removeProperty(name)
    frustum.Proxy.onDocumentRestored(frustum)
    doc.recompute()
    require("no Sections/SectionFractions (a document before them): added empty, valid",
            "SectionFractions" in frustum.PropertiesList and not frustum.Sections
            and frustum.isValid())
    check_solid("no Sections again: the frustum", frustum.Shape, PI * 30 * (4 + 2 + 1) / 3)
    doc.removeObject(mid_circle.Name)
    end_ring, _ = circle_sketch(doc, "EndRing", FreeCAD.Placement(V(0, -80, 0), Z_TO_X),
                                (1.0, 0.5))
    doc.recompute()
    frustum.EndProfile = (end_ring, [])
    doc.recompute()
    message = frustum.getStatusString()
    require("an EndProfile with a hole the Profile has not: Invalid, '%s'" % message,
            not frustum.isValid() and "end_profile" in message)
    frustum.EndProfile = None
    frustum.removeProperty("EndProfile")
    frustum.Proxy.onDocumentRestored(frustum)
    doc.recompute()
    require("no EndProfile (a document before it): added empty, valid",
            "EndProfile" in frustum.PropertiesList and not frustum.EndProfile
            and frustum.isValid())
    check_solid("EndProfile empty again: the cylinder", frustum.Shape, PI * 4 * 30)
    for name in (end_ring.Name, end_circle.Name):
        doc.removeObject(name)
    block = polyline_sketch(doc, "Block", FreeCAD.Placement(V(0, -80, 0), Z_TO_X),
                            [(-2, -1, 0), (2, -1, 0), (2, 1, 0), (-2, 1, 0), (-2, -1, 0)])
    block.addConstraint(Sketcher.Constraint("Coincident", 3, 2, 0, 1))
    frustum.Profile = block
    frustum.ScaleEnd = 1.0
    for frame, direction in (("frenet", None), ("fixed", V(0, 0, 1)), ("fixed", V(0, 1, 1))):
        frustum.Frame = frame
        if direction is not None:
            frustum.FrameDirection = direction
        doc.recompute()
        check_solid("a 4 x 2 rectangle along a line, Frame %s %s" % (frame, direction or ""),
                    frustum.Shape, 8 * 30)
        check("  its FrameError (radians)", frustum.FrameError, 1e-9)
    for name, value, word in (("FrameDirection", V(0, 0, 0), "FrameDirection"),
                              ("ScaleStart", 0.0, "ScaleStart"), ("ScaleEnd", -1.0, "ScaleEnd")):
        saved = getattr(frustum, name)
        setattr(frustum, name, value)
        doc.recompute()
        message = frustum.getStatusString()
        require("%s = %s: Invalid, '%s'" % (name, value, message),
                not frustum.isValid() and word in message)
        setattr(frustum, name, saved)
    frustum.Frame = "rmf"
    doc.recompute()
    require("Frame rmf again: valid", frustum.isValid())
    # Frame guide: without a Guide refused naming it; with a helix of radius 6 and pitch 10
    # about the axis as the Guide (Part.makeHelix turned from z onto the axis), the circle of
    # radius 2 turns with it and keeps the cylinder's volume π r² L; a Guide beside the
    # axis's first 5 only is the library's refusal, naming the frame; a document before
    # Guide gets it empty.
    frustum.Profile = cone
    frustum.Frame = "guide"
    doc.recompute()
    message = frustum.getStatusString()
    require("Frame guide without a Guide: Invalid, '%s'" % message,
            not frustum.isValid() and "Guide" in message)
    helix = doc.addObject("Part::Feature", "GuideHelix")
    helix_shape = Part.makeHelix(10.0, 30.0, 6.0)
    helix_shape.Placement = FreeCAD.Placement(V(0, -80, 0), FreeCAD.Rotation(V(0, 1, 0), 90))
    helix.Shape = helix_shape
    frustum.Guide = helix
    doc.recompute()
    check_solid("a circle r 2 along a line of 30, Frame guide (a helix r 6 about it)",
                frustum.Shape, PI * 4 * 30)
    check("  its FrameError (radians)", frustum.FrameError, 0.25 * frustum.Tolerance / 2)
    short = doc.addObject("Part::Feature", "ShortGuide")
    short.Shape = Part.makeLine(V(0, -80, 6), V(5, -80, 6))
    frustum.Guide = short
    doc.recompute()
    message = frustum.getStatusString()
    require("a Guide beside the first 5 of the axis only: Invalid, '%s'" % message,
            not frustum.isValid() and "frame" in message and "guide" in message)
    frustum.Guide = None
    frustum.Frame = "rmf"
    frustum.removeProperty("Guide")
    frustum.Proxy.onDocumentRestored(frustum)
    doc.recompute()
    require("no Guide (a document before it): added empty, valid",
            "Guide" in frustum.PropertiesList and frustum.Guide is None and frustum.isValid())
    for name in (frustum.Name, short.Name, helix.Name, block.Name, cone.Name, axis.Name):
        doc.removeObject(name)
    doc.recompute()

    # Method: how curve edges are swept. A circle of radius 0.5 along a line into the
    # twisted cubic 10·(t, t², t³) (an exact B-spline, tangent to the line): ph-rmf leaves
    # its parameter lines off orthogonal by more than 1e-10; mobius and rrmf, spines with
    # exact rational RMFs, give valid solids orthogonal to rounding (< 1e-12); each of the
    # tube's volume π r² L (the divergence theorem on FreeCAD's derivatives). A scale law with mobius is refused naming Method; a document of the
    # workbench whose Method offered ph-rmf only gets the three methods on opening.
    require("Method %r of %s" % (sweep.Method, sweep.getEnumerationsOfProperty("Method")),
            sweep.Method == "ph-rmf"
            and sweep.getEnumerationsOfProperty("Method") == ["ph-rmf", "mobius", "rrmf"])
    o = V(0, -120, 0)
    cubic = Part.BSplineCurve()
    cubic.buildFromPolesMultsKnots([o, o + V(10 / 3, 0, 0), o + V(20 / 3, 10 / 3, 0),
                                    o + V(10, 10, 10)], [4, 4], [0.0, 1.0], False, 3)
    tube_spine = doc.addObject("Part::Feature", "TubeSpine")
    tube_spine.Shape = Part.Wire([Part.LineSegment(o + V(-10, 0, 0), o).toShape(),
                                  cubic.toShape()])
    tube_profile, _ = circle_sketch(doc, "TubeProfile",
                                    FreeCAD.Placement(o + V(-10, 0, 0), Z_TO_X), (0.5,))
    doc.recompute()
    tube = wb.make_sweep(doc, tube_spine, tube_profile)
    tube_volume = PI * 0.25 * tube_spine.Shape.Length
    orthogonality = {}
    for method, tolerance in (("ph-rmf", 1e-4), ("mobius", 1e-4), ("rrmf", 1e-3)):
        tube.Method = method
        tube.Tolerance = tolerance
        doc.recompute()
        orthogonality[method] = tube.Orthogonality
        require("a circle along a line and a B-spline, Method %s: a valid solid" % method,
                tube.isValid() and tube.Shape.ShapeType == "Solid" and tube.Shape.isValid())
        # (FreeCAD's Shape.Volume integrates these faces of high degree to ~4e-4 only.)
        check("  its rel. volume error against π r² L (L of the wire; by this script)",
              rel(divergence_volume(tube.Shape), tube_volume), 1e-5)
        check("  its SpineDistance (mm), within the Tolerance", tube.SpineDistance, tolerance)
        say("  Method %s: Orthogonality %.1e" % (method, tube.Orthogonality))
    check("Method ph-rmf: Orthogonality (the PH spline's rational RMF)",
          orthogonality["ph-rmf"], 1e-10, below=False)
    check("Method mobius: Orthogonality (exact rational RMF)", orthogonality["mobius"], 1e-12)
    check("Method rrmf: Orthogonality (exact rational RMF)", orthogonality["rrmf"], 1e-12)
    # The same tube on the PH spline's Euler-Rodrigues frame (PipeFrame lightest, the
    # default) and on its RMF: B-spline faces of degree 5 and 9 along the spine, the same
    # volume.
    tube.Method = "ph-rmf"
    degrees, volumes = {}, {}
    for pipe_frame in ("lightest", "rmf"):
        tube.PipeFrame = pipe_frame
        doc.recompute()
        degrees[pipe_frame] = {f.Surface.VDegree for f in tube.Shape.Faces
                               if isinstance(f.Surface, Part.BSplineSurface)}
        volumes[pipe_frame] = divergence_volume(tube.Shape)
        say("  PipeFrame %s: degrees along the spine %s, Orthogonality %.1e"
            % (pipe_frame, sorted(degrees[pipe_frame]), tube.Orthogonality))
    require("PipeFrame lightest: degree 5 along the curve; rmf: 9",
            5 in degrees["lightest"] and 9 not in degrees["lightest"] and 9 in degrees["rmf"])
    check("PipeFrame lightest against rmf: rel. volume difference",
          rel(volumes["lightest"], volumes["rmf"]), 1e-9)
    tube.Method = "mobius"
    tube.Tolerance = 1e-4
    tube.ScaleEnd = 0.5
    doc.recompute()
    message = tube.getStatusString()
    require("Method mobius with ScaleEnd 0.5: Invalid, '%s'" % message,
            not tube.isValid() and "Method" in message)
    tube.ScaleEnd = 1.0
    tube.ScaleKnotFractions, tube.ScaleKnotScales = [0.5], [0.8]
    doc.recompute()
    message = tube.getStatusString()
    require("Method mobius with a knot of scale 0.8: Invalid, '%s'" % message,
            not tube.isValid() and "Method" in message and "ScaleKnotScales" in message)
    tube.ScaleKnotFractions, tube.ScaleKnotScales = [], []
    doc.recompute()
    require("ScaleEnd 1 again: valid", tube.isValid())
    # An older document: Method offered ph-rmf only, or had no Method at all.
    tube.Method = ["ph-rmf"]
    tube.Proxy.onDocumentRestored(tube)
    require("an older Method [ph-rmf] restored: %s, value %r"
            % (tube.getEnumerationsOfProperty("Method"), tube.Method),
            tube.getEnumerationsOfProperty("Method") == ["ph-rmf", "mobius", "rrmf"]
            and tube.Method == "ph-rmf")
    tube.removeProperty("Method")
    tube.Proxy.onDocumentRestored(tube)
    doc.recompute()
    require("no Method (a document before it): added, ph-rmf, valid",
            tube.Method == "ph-rmf" and tube.isValid())
    for name in (tube.Name, tube_profile.Name, tube_spine.Name):
        doc.removeObject(name)
    doc.recompute()

    # A closed spine: a rounded rectangle of lines and quarter arcs (radius 5), a circle of
    # radius 1 swept around it into a ring without caps; ClosureSymmetry on it.
    r = 5.0
    edges = []
    for (x0, y0), (x1, y1), centre, a in (((r, 0), (30 - r, 0), (30 - r, r), -PI / 2),
                                          ((30, r), (30, 20 - r), (30 - r, 20 - r), 0.0),
                                          ((30 - r, 20), (r, 20), (r, 20 - r), PI / 2),
                                          ((0, 20 - r), (0, r), (r, r), PI)):
        edges.append(Part.LineSegment(V(x0, y0, -40), V(x1, y1, -40)).toShape())
        edges.append(Part.ArcOfCircle(Part.Circle(V(centre[0], centre[1], -40), V(0, 0, 1), r),
                                      a, a + PI / 2).toShape())
    loop = doc.addObject("Part::Feature", "Loop")
    loop.Shape = Part.Wire(edges)
    disc, _ = circle_sketch(doc, "Disc", FreeCAD.Placement(V(r, 0, -40), Z_TO_X), (1.0,))
    doc.recompute()
    ring = wb.make_sweep(doc, (loop, ["Edge%d" % k for k in range(1, 9)]), disc)
    length = 2 * (30 - 2 * r) + 2 * (20 - 2 * r) + 2 * PI * r
    check_solid("a circle around a closed rounded rectangle (no caps)", ring.Shape, PI * length)
    require("the closed ring: %d faces, none planar (no caps)" % len(ring.Shape.Faces),
            not any(isinstance(f.Surface, Part.Plane) for f in ring.Shape.Faces))
    ring.ClosureSymmetry = 4
    doc.recompute()
    check_solid("the same, ClosureSymmetry 4", ring.Shape, PI * length)
    for name in (ring.Name, disc.Name, loop.Name):
        doc.removeObject(name)
    doc.recompute()

    # A circle along a sketch with a 90° corner: round (radius 8), then miter.
    start = FreeCAD.Placement(V(0, 0, 30), FreeCAD.Rotation())
    corner = polyline_sketch(doc, "Corner", start, [(0, 0, 0), (30, 0, 0), (30, 25, 0)])
    tube, _ = circle_sketch(doc, "Tube", FreeCAD.Placement(V(0, 0, 30), Z_TO_X), (2.0,))
    doc.recompute()
    elbow = wb.make_sweep(doc, corner, tube, corner="round", corner_radius=8)
    rho = 8.0
    check_solid("circle r 2 along a sketch, round corner radius 8", elbow.Shape,
                PI * 4 * (55 - 2 * rho + rho * PI / 2))
    elbow.Corner = "miter"
    doc.recompute()
    check_solid("the same, Corner = miter", elbow.Shape, PI * 4 * 55)
    elbow.Corner = "round"
    doc.recompute()

    for label, call, word in (
            ("corner='bevel'", lambda: wb.make_sweep(doc, corner, tube, corner="bevel"), "corner"),
            ("corner_radius=-1", lambda: wb.make_sweep(doc, corner, tube, corner_radius=-1),
             "corner_radius"),
            ("spine=42", lambda: wb.make_sweep(doc, 42, tube), "spine")):
        try:
            call()
            require("make_sweep(%s) refused" % label, False)
        except (ValueError, TypeError) as e:
            require("make_sweep(%s): %s naming %s (%s)" % (label, type(e).__name__, word, e),
                    str(e).startswith(word + ":"))
    return [sweep, elbow], (profile.Name, radius)


# ---------------------------------------------------------------------------------------
# C. RmfUnfold of a developable face, and the DXF export


def read_dxf(path):
    """The LINE, ARC and CIRCLE entities of a DXF file by layer: this script's own reader
    (group code / value pairs of the ENTITIES section)."""
    with open(path) as f:
        lines = [line.strip() for line in f]
    pairs = list(zip(lines[0::2], lines[1::2]))
    entities, current, in_entities = [], None, False
    for code, value in pairs:
        if code == "2" and value == "ENTITIES":
            in_entities = True
        elif code == "0" and value == "ENDSEC":
            in_entities = False
        if not in_entities:
            continue
        if code == "0":
            current = {"type": value}
            entities.append(current)
        elif current is not None:
            current.setdefault(code, value)
    return [e for e in entities if e["type"] in ("LINE", "ARC", "CIRCLE", "LWPOLYLINE",
                                                 "SPLINE", "POLYLINE")]


def dxf_segments(entity):
    """(start, end, signed area term ½∮(x dy − y dx)) of a LINE or ARC, as drawn."""
    def g(code):
        return float(entity[code])
    if entity["type"] == "LINE":
        a, b = (g("10"), g("20")), (g("11"), g("21"))
        return a, b, 0.5 * (a[0] * b[1] - b[0] * a[1])
    cx, cy, r = g("10"), g("20"), g("40")
    t0, t1 = math.radians(g("50")), math.radians(g("51"))
    if t1 < t0:
        t1 += 2 * PI
    a = (cx + r * math.cos(t0), cy + r * math.sin(t0))
    b = (cx + r * math.cos(t1), cy + r * math.sin(t1))
    term = 0.5 * (r * r * (t1 - t0) + r * (cx * (math.sin(t1) - math.sin(t0))
                                           - cy * (math.cos(t1) - math.cos(t0))))
    return a, b, term


def loop_area(entities, tolerance=1e-6):
    """The area enclosed by LINE and ARC entities chained end to end (Green's theorem; an
    entity walked backwards counts negatively)."""
    pieces = [dxf_segments(e) for e in entities]

    def close(p, q):
        return math.hypot(p[0] - q[0], p[1] - q[1]) < tolerance
    a, end, total = pieces[0]
    start, remaining = a, pieces[1:]
    while remaining:
        for k, (p, q, term) in enumerate(remaining):
            if close(p, end):
                end, total = q, total + term
                break
            if close(q, end):
                end, total = p, total - term
                break
        else:
            raise ValueError("the DXF outline does not close (at %s)" % (end,))
        remaining.pop(k)
    if not close(start, end):
        raise ValueError("the DXF outline does not close")
    return abs(total)


def check_dxf_in_freecad(path, outline):
    """FreeCAD's own DXF importer reads the file: as many edges, true arcs, the same
    length as the outline and bend lines."""
    import Import
    doc = FreeCAD.newDocument("dxf")
    Import.readDXF(path)
    edges = [e for o in doc.Objects if hasattr(o, "Shape") for e in o.Shape.Edges]
    arcs = sum(isinstance(e.Curve, Part.Circle) for e in edges)
    require("FreeCAD's DXF importer: %d edges (%d arcs), all arcs or lines" % (len(edges), arcs),
            all(isinstance(e.Curve, (Part.Circle, Part.Line, Part.LineSegment)) for e in edges)
            and arcs == sum(isinstance(e.Curve, Part.Circle) for e in outline))
    FreeCAD.closeDocument(doc.Name)
    return edges


def frustum_area(r1, r2, height, degrees):
    return degrees / 360.0 * PI * (r1 + r2) * math.hypot(r1 - r2, height)


def part_c(doc):
    say("C. RmfUnfold of a developable face (a cone frustum, 270°), the DXF export")
    import rmfsurf_workbench as wb
    cone = doc.addObject("Part::Cone", "Frustum")
    cone.Radius1, cone.Radius2, cone.Height, cone.Angle = 10, 5, 20, 270
    cone.Placement.Base = V(100, 0, 0)
    doc.recompute()
    lateral = next("Face%d" % (i + 1) for i, f in enumerate(cone.Shape.Faces)
                   if isinstance(f.Surface, Part.Cone))
    unfold = wb.make_unfold(doc, (cone, [lateral]))
    shape = unfold.Shape
    faces = shape.Faces
    require("RmfUnfold of %s: valid, one planar face (|z| extent 0) and %d bend line(s)"
            % (lateral, unfold.BendLineCount),
            unfold.isValid() and len(faces) == 1 and shape.BoundBox.ZLength < 1e-12
            and unfold.BendLineCount == unfold.PieceCount - 1
            == len(shape.childShapes()) - 1)
    require("SurfaceKind %r, Curvature %.1e, FitError %.1e (exact: closed form)"
            % (unfold.SurfaceKind, unfold.Curvature, unfold.FitError),
            unfold.SurfaceKind == "right_cone" and unfold.Curvature < 1e-9
            and unfold.FitError == 0)
    outline = faces[0].Edges
    require("outline: %d edges, all true arcs (Part.Circle) or lines" % len(outline),
            all(isinstance(e.Curve, (Part.Circle, Part.Line, Part.LineSegment)) for e in outline))
    expected = frustum_area(10, 5, 20, 270)
    check("FlatArea against the frustum's (3/4)π(r1 + r2)s", rel(unfold.FlatArea.Value, expected),
          1e-9)
    check("FlatArea against FreeCAD's area of the cone face",
          rel(unfold.FlatArea.Value, cone.Shape.getElement(lateral).Area), 1e-9)
    before = unfold.FlatArea.Value
    cone.Radius2 = 4
    doc.recompute()
    expected = frustum_area(10, 4, 20, 270)
    check("Radius2 5 -> 4, recomputed: FlatArea against the closed form",
          rel(unfold.FlatArea.Value, expected), 1e-9)
    say("  flat area %.12g before, %.12g after" % (before, unfold.FlatArea.Value))

    path = os.path.join(WORK, "frustum.dxf")
    counts = wb.export_dxf(unfold, path)
    entities = read_dxf(path)
    layers = {}
    for e in entities:
        layers.setdefault(e.get("8", "0"), []).append(e)
    require("DXF: layers %s; CUT %d ARC/LINE entities, BEND %d LINEs (%s)"
            % (sorted(layers), len(layers.get("CUT", [])), len(layers.get("BEND", [])), counts),
            set(layers) == ({"CUT", "BEND"} if unfold.BendLineCount else {"CUT"})
            and all(e["type"] in ("ARC", "LINE") for e in layers["CUT"])
            and all(e["type"] == "LINE" for e in layers.get("BEND", []))
            and len(layers["CUT"]) == len(outline)
            and len(layers.get("BEND", [])) == unfold.BendLineCount)
    check("DXF outline area (Green's theorem, this script) against FlatArea",
          rel(loop_area(layers["CUT"]), unfold.FlatArea.Value), 1e-9)
    check_dxf_in_freecad(path, outline)
    try:
        wb.export_dxf(cone, path)
        require("export_dxf of a Part::Cone refused", False)
    except TypeError as e:
        require("export_dxf of a Part::Cone: TypeError naming unfold (%s)" % e,
                str(e).startswith("unfold:"))

    # Not a developable: a sphere face.
    ball = doc.addObject("Part::Sphere", "Ball")
    doc.recompute()
    bad = wb.make_unfold(doc, (ball, ["Face1"]))
    require("RmfUnfold of a sphere: Invalid, '%s'" % bad.getStatusString(),
            not bad.isValid())
    doc.removeObject(bad.Name)
    doc.removeObject(ball.Name)
    doc.recompute()
    return [unfold], cone


# ---------------------------------------------------------------------------------------
# D. RmfTransition and its unfold


def gauss_nodes(breaks, parts):
    """(node, weight) pairs of Gauss-Legendre on each interval between `breaks`, split in
    `parts`."""
    for a, b in zip(breaks, breaks[1:]):
        for k in range(parts):
            lo, hi = a + (b - a) * k / parts, a + (b - a) * (k + 1) / parts
            for x, w in GAUSS:
                yield 0.5 * (lo + hi) + 0.5 * (hi - lo) * x, 0.5 * (hi - lo) * w


def knots_of(surface, direction):
    """A B-spline surface's knots along 'U' or 'V'; none for an analytic surface (a
    cylinder or torus is smooth over the face)."""
    knots = getattr(surface, "get%sKnots" % direction, None)
    return knots() if knots else []


def _breaks(knots, lo, hi):
    return sorted({lo, hi} | {k for k in knots if lo < k < hi})


def nurbs_area(face, parts=4):
    """∫∫ |s_u × s_v| of a B-spline face over its parameter range by Gauss-Legendre on
    every knot span, with FreeCAD's own derivatives."""
    surface = face.Surface
    u0, u1, v0, v1 = face.ParameterRange
    return sum(wu * wv * surface.getDN(u, v, 1, 0).cross(surface.getDN(u, v, 0, 1)).Length
               for u, wu in gauss_nodes(_breaks(knots_of(surface, 'U'), u0, u1), parts)
               for v, wv in gauss_nodes(_breaks(knots_of(surface, 'V'), v0, v1), parts))


def part_d(doc):
    say("D. RmfTransition (the square-to-round hopper) and its RmfUnfold")
    import rmfsurf.freecad as rf
    import rmfsurf_workbench as wb
    if not rf.has_transitions():
        say("  NOT RUN: this librmfsurf has no rmf_sheet_part_transition")
        return [], None
    bottom = polyline_sketch(doc, "Square", FreeCAD.Placement(),
                             [(-100, -100, 0), (100, -100, 0), (100, 100, 0), (-100, 100, 0),
                              (-100, -100, 0)])
    bottom.addConstraint(Sketcher.Constraint("Coincident", 3, 2, 0, 1))
    top, radius = circle_sketch(doc, "Round", FreeCAD.Placement(V(20, 0, 150), FreeCAD.Rotation()),
                                (60.0,))
    doc.recompute()
    hopper = wb.make_transition(doc, bottom, top, thickness=2, k_factor=0.4)
    require("RmfTransition: valid solid, %d faces, %d pieces"
            % (hopper.FaceCount, hopper.PieceCount),
            hopper.isValid() and hopper.Shape.ShapeType == "Solid" and hopper.Shape.isValid())
    check("EdgeDistance against the input curves (tolerance 1e-4)", hopper.EdgeDistance, 1e-4)
    unfold = wb.make_unfold(doc, hopper)
    part = hopper.Proxy.sheet_part(hopper)
    areas = {layer: nurbs_area(rf.part_face(part.layer(layer)))
             for layer in ("inner", "neutral", "outer")}
    require("RmfUnfold of the transition: valid, %d bend lines" % unfold.BendLineCount,
            unfold.isValid() and unfold.BendLineCount > 0)
    check("flat area against the neutral layer's area (integrated by FreeCAD)",
          rel(unfold.FlatArea.Value, areas["neutral"]), 1e-9)
    check("neutral area = inner + 0.4 (outer - inner) (linear in the offset)",
          rel(areas["neutral"], areas["inner"] + 0.4 * (areas["outer"] - areas["inner"])), 1e-9)
    check("volume against t (A_inner + A_outer) / 2",
          rel(hopper.Shape.Volume, 2 * (areas["inner"] + areas["outer"]) / 2), 1e-9)
    before = unfold.FlatArea.Value
    set_radius(top, radius[0], 50.0)
    doc.recompute()
    part = hopper.Proxy.sheet_part(hopper)
    neutral = nurbs_area(rf.part_face(part.layer("neutral")))
    check("top radius 60 -> 50, recomputed: flat area against the neutral layer's",
          rel(unfold.FlatArea.Value, neutral), 1e-9)
    say("  flat area %.12g before, %.12g after" % (before, unfold.FlatArea.Value))
    path = os.path.join(WORK, "hopper.dxf")
    wb.export_dxf(unfold, path)
    entities = read_dxf(path)
    outline = [e for e in entities if e.get("8") == "CUT"]
    bends = [e for e in entities if e.get("8") == "BEND"]
    require("hopper DXF: %d CUT entities (ARC, LINE), %d BEND lines, as the feature's edges"
            % (len(outline), len(bends)),
            len(outline) == len(unfold.Shape.Faces[0].Edges)
            and len(bends) == unfold.BendLineCount
            and all(e["type"] in ("ARC", "LINE") for e in outline))
    check("hopper DXF outline area (this script's reader) against FlatArea",
          rel(loop_area(outline), unfold.FlatArea.Value), 1e-9)
    hopper.KFactor = 1.5
    doc.recompute()
    require("KFactor 1.5: Invalid, '%s'" % hopper.getStatusString(), not hopper.isValid())
    hopper.KFactor = 0.4
    doc.recompute()
    require("KFactor 0.4 again: valid", hopper.isValid() and unfold.isValid())
    return [hopper, unfold], (top, radius)


# ---------------------------------------------------------------------------------------
# E. Persistence


def fingerprint(obj):
    shape = obj.Shape
    return {
        "volume": shape.Volume if shape.Solids else 0.0,
        "area": shape.Area,
        "faces": len(shape.Faces),
        "edges": len(shape.Edges),
        "box": [shape.BoundBox.XMin, shape.BoundBox.YMin, shape.BoundBox.ZMin,
                shape.BoundBox.XMax, shape.BoundBox.YMax, shape.BoundBox.ZMax],
        "vertices": sorted(tuple(round(c, 9) for c in v.Point) for v in shape.Vertexes),
    }


def compare(label, a, b):
    size = max(abs(c) for c in a["box"]) or 1.0
    same = (a["faces"] == b["faces"] and a["edges"] == b["edges"]
            and len(a["vertices"]) == len(b["vertices"]))
    error = max([abs(x - y) / size for x, y in zip(a["box"], b["box"])]
                + [max(abs(p - q) for p, q in zip(u, w)) / size
                   for u, w in zip(a["vertices"], b["vertices"])])
    volume = rel(b["volume"], a["volume"]) if a["volume"] else 0.0
    require("%s: %d faces, %d edges as saved" % (label, b["faces"], b["edges"]), same)
    check("%s: rel. volume and area difference after reopen + recompute" % label,
          max(volume, rel(b["area"], a["area"])), 1e-12)
    check("%s: vertices and bounding box, max difference / size" % label, error, 1e-9)


def part_e(doc, features, drivers):
    say("E. Persistence: save, close, reopen, recompute")
    path = os.path.join(WORK, "workbench.FCStd")
    saved = {f.Name: fingerprint(f) for f in features}
    types_ = {f.Name: f.Proxy.Type for f in features}
    first = features[0].Name
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(path)
    for name, kind in sorted(types_.items()):
        obj = doc.getObject(name)
        require("%s reopened: Proxy %s restored" % (name, kind),
                obj is not None and getattr(obj.Proxy, "Type", None) == kind)
    for name in sorted(saved):
        obj = doc.getObject(name)
        obj.Shape = Part.Shape()  # the saved copy gone: the shape must come from the inputs
        obj.touch()
    doc.recompute()
    for name in sorted(saved):
        obj = doc.getObject(name)
        require("%s recomputed after reopening: valid, not null" % name,
                obj.isValid() and not obj.Shape.isNull())
        compare(name, saved[name], fingerprint(obj))
    if drivers is not None:
        profile, radius = drivers
        set_radius(doc.getObject(profile), radius[0], 3.0)
        doc.recompute()
        sweep = doc.getObject(first)
        check_solid("after reopening, the ring's constraint 4 -> 3 drives the sweep",
                    sweep.Shape, ring_area((3, 1.5)) * (80 + 10 * PI))
    return doc


# ---------------------------------------------------------------------------------------
# F. The macros


class Selected:
    """What FreeCADGui.Selection.getSelectionEx() gives for one selected object."""

    def __init__(self, obj, names=()):
        self.Object = obj
        self.SubElementNames = list(names)
        self.SubObjects = [obj.Shape.getElement(n) for n in names]


def kind_of(obj):
    """The workbench feature type of a document object ("" for others)."""
    return getattr(getattr(obj, "Proxy", None), "Type", "")


def run_macro(path, selection, document):
    gui = types.ModuleType("FreeCADGui")
    gui.Selection = types.SimpleNamespace(getSelectionEx=lambda: selection)
    sys.modules["FreeCADGui"] = gui
    FreeCAD.setActiveDocument(document.Name)
    try:
        with open(path) as f:
            exec(compile(f.read(), path, "exec"), {"__file__": path, "__name__": "__main__"})
    finally:
        del sys.modules["FreeCADGui"]


def part_f(wire_sweeps):
    say("F. The macros (thin wrappers of make_sweep, make_unfold and make_transition)")
    macros = os.environ["RMFSURF_MACROS"]
    doc = FreeCAD.newDocument("macros")
    spine = doc.addObject("Part::Feature", "Spine")
    spine.Shape = Part.Wire([Part.LineSegment(V(0, 0, 0), V(10, 0, 0)).toShape(),
                             Part.LineSegment(V(10, 0, 0), V(10, 10, 0)).toShape()])
    profile, _ = circle_sketch(doc, "Profile", FreeCAD.Placement(V(0, 0, 0), Z_TO_X), (1.0,))
    doc.recompute()
    run_macro(os.path.join(macros, "RmfSweep.FCMacro"),
              [Selected(profile), Selected(spine, ["Edge1", "Edge2"])], doc)
    sweeps = [o for o in doc.Objects if kind_of(o) == "RmfSweep"]
    require("RmfSweep.FCMacro: one parametric RmfSweep%s"
            % (", a valid solid" if wire_sweeps else " (NOT RUN: no rmf_wire_sweep)"),
            len(sweeps) == 1 and (not wire_sweeps or (
                sweeps[0].isValid() and sweeps[0].Shape.ShapeType == "Solid")))
    cone = doc.addObject("Part::Cone", "Cone")
    cone.Angle = 270
    doc.recompute()
    lateral = next("Face%d" % (i + 1) for i, f in enumerate(cone.Shape.Faces)
                   if isinstance(f.Surface, Part.Cone))
    run_macro(os.path.join(macros, "RmfConeSpline.FCMacro"), [Selected(cone, [lateral])], doc)
    unfolds = [o for o in doc.Objects if kind_of(o) == "RmfUnfold"]
    require("RmfConeSpline.FCMacro: one parametric RmfUnfold, valid",
            len(unfolds) == 1 and unfolds[0].isValid())
    import rmfsurf.freecad as rf
    if rf.has_transitions():
        square = polyline_sketch(doc, "Square", FreeCAD.Placement(V(0, 50, 0), FreeCAD.Rotation()),
                                 [(-20, -20, 0), (20, -20, 0), (20, 20, 0), (-20, 20, 0),
                                  (-20, -20, 0)])
        square.addConstraint(Sketcher.Constraint("Coincident", 3, 2, 0, 1))
        round_, _ = circle_sketch(doc, "Round", FreeCAD.Placement(V(5, 50, 30), FreeCAD.Rotation()),
                                  (12.0,))
        doc.recompute()
        run_macro(os.path.join(macros, "RmfTransition.FCMacro"),
                  [Selected(square), Selected(round_)], doc)
        kinds = [kind_of(o) for o in doc.Objects]
        made = [o for o in doc.Objects if kind_of(o) in ("RmfTransition", "RmfUnfold")]
        require("RmfTransition.FCMacro: a parametric RmfTransition and its RmfUnfold, valid",
                kinds.count("RmfTransition") == 1 and kinds.count("RmfUnfold") == 2
                and all(o.isValid() for o in made))
    else:
        say("  RmfTransition.FCMacro: NOT RUN: this librmfsurf has no rmf_sheet_part_transition")
    FreeCAD.closeDocument(doc.Name)


# ---------------------------------------------------------------------------------------
# G. Any developable face: rmfsurf.freecad.unfold and RmfUnfold


def windowed_cone():
    """A frustum (radii 10 and 4, height 20) with a window cut through its wall: between
    the heights 7 and 13 and 40° of turn — two parallel circles and two rulings."""
    cone = Part.makeCone(10, 4, 20)
    window = Part.makeCylinder(30, 6, V(0, 0, 7), V(0, 0, 1), 40)
    window.rotate(V(0, 0, 0), V(0, 0, 1), 120)
    walls = [f for f in cone.cut(window).Faces if isinstance(f.Surface, Part.Cone)]
    assert len(walls) == 1
    return walls[0]


def check_pattern(name, face, pattern, kind, holes):
    """The pattern of `face`: its kind, its area against FreeCAD's face.Area, a valid flat
    face in z = 0 with `holes` inner wires, true arcs and lines only."""
    flat = pattern.face
    inner = [w for w in flat.Wires if not w.isSame(flat.OuterWire)]
    curves = {type(e.Curve).__name__ for e in flat.Edges}
    say("  %s: kind %s, flat area %.15g, FreeCAD's face.Area %.15g; %d inner wire(s); "
        "edges %s" % (name, pattern.report.kind, pattern.area, face.Area, len(inner),
                      sorted(curves)))
    require("%s: kind %s" % (name, kind), pattern.report.kind == kind)
    check("%s: flat area against FreeCAD's face.Area" % name, rel(pattern.area, face.Area),
          1e-9)
    check("%s: the flat face's area against the pattern's" % name,
          rel(flat.Area, pattern.area), 1e-9)
    require("%s: a valid Part.Face in z = 0 with %d inner wire(s), Part.Circle arcs and "
            "lines only" % (name, holes),
            isinstance(flat, Part.Face) and flat.isValid() and len(inner) == holes
            and flat.BoundBox.ZLength < 1e-12 and curves <= {"Circle", "Line", "LineSegment"})


def part_g():
    say("G. Any developable face: rmfsurf.freecad.unfold and RmfUnfold")
    import rmfsurf
    import rmfsurf.freecad as rf
    import rmfsurf_workbench as wb
    cylinder = Part.makeCylinder(3, 10)
    wall = [f for f in cylinder.Faces if isinstance(f.Surface, Part.Cylinder)][0]
    check_pattern("cylinder wall (cut open along its seam)", wall, rf.unfold(wall),
                  "circular_cylinder", 0)
    window = windowed_cone()
    pattern = rf.unfold(window)
    check_pattern("cone wall with a window", window, pattern, "right_cone", 1)
    hole = pattern.unfolded.holes[0]
    require("the window: two arcs (parallel circles) and two lines (rulings): %s"
            % [e.kind for e in hole],
            sorted(e.kind for e in hole) == ["arc", "arc", "line", "line"])
    path = os.path.join(WORK, "window.dxf")
    pattern.write_dxf(path)
    entities = read_dxf(path)
    loops = [pattern.unfolded.outline] + pattern.unfolded.holes
    require("its DXF: %d LINE/ARC entities on layer CUT, one per edge of the outline and "
            "the window" % len(entities),
            len(entities) == sum(len(loop) for loop in loops)
            and all(e.get("8") == "CUT" and e["type"] in ("LINE", "ARC") for e in entities))
    plate = Part.makeBox(40, 30, 2).cut(Part.makeCylinder(5, 10, V(20, 15, -1)))
    top = [f for f in plate.Faces if abs(f.CenterOfMass.z - 2) < 1e-9][0]
    check_pattern("plate with a round hole", top, rf.unfold(top), "plane", 1)
    body = rf.unfold(plate)
    check("the plate as a sheet body: thickness", abs(body.thickness - 2.0), 1e-12)
    check("the plate as a sheet body: flat area against volume / thickness",
          rel(body.area, plate.Volume / 2.0), 1e-9)
    try:
        rf.unfold(Part.makeSphere(5).Faces[0])
        require("a sphere's face refused", False)
    except rmfsurf.InvalidInputError as e:
        require("a sphere's face: InvalidInputError (%s)" % e, "not developable" in str(e))

    doc = FreeCAD.newDocument("faces")
    cyl = doc.addObject("Part::Cylinder", "Cyl")
    cyl.Radius, cyl.Height, cyl.Angle = 4, 10, 300
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 30, 20, 5
    doc.recompute()
    for obj in (cyl, box):
        for i, face in enumerate(obj.Shape.Faces):
            name = "Face%d" % (i + 1)
            kind = {"Cylinder": "circular_cylinder", "Plane": "plane"}[type(face.Surface).__name__]
            unfold = wb.make_unfold(doc, (obj, [name]))
            ok = unfold.isValid()
            say("  RmfUnfold of %s.%s: %s, SurfaceKind %r, FlatArea %.12g, face.Area %.12g, "
                "PieceCount %d, BendLineCount %d, Curvature %.1e"
                % (obj.Name, name, "valid" if ok else "INVALID " + unfold.getStatusString(),
                   unfold.SurfaceKind, unfold.FlatArea.Value, face.Area, unfold.PieceCount,
                   unfold.BendLineCount, unfold.Curvature))
            require("RmfUnfold of %s.%s: valid, SurfaceKind %s, one piece, no bend line"
                    % (obj.Name, name, kind),
                    ok and unfold.SurfaceKind == kind and unfold.PieceCount == 1
                    and unfold.BendLineCount == 0 and unfold.Curvature < 1e-9)
            check("RmfUnfold of %s.%s: FlatArea against face.Area" % (obj.Name, name),
                  rel(unfold.FlatArea.Value, face.Area), 1e-9)
    # A general cylinder: a B-spline wave extruded, unrolled through its cone spline.
    wave = Part.BSplineCurve()
    wave.interpolate([V(0, 0, 0), V(10, 6, 0), V(20, -6, 0), V(30, 6, 0), V(40, 0, 0)])
    sheet = doc.addObject("Part::Feature", "Wave")
    sheet.Shape = wave.toShape().extrude(V(0, 0, 15))
    doc.recompute()
    unfold = wb.make_unfold(doc, sheet)
    unfold.Tolerance = 1e-5
    doc.recompute()
    length = wave.length()
    say("  RmfUnfold of an extruded B-spline: SurfaceKind %r, FlatArea %.12g, length × "
        "height %.12g, PieceCount %d, BendLineCount %d, FitError %.2e"
        % (unfold.SurfaceKind, unfold.FlatArea.Value, 15 * length, unfold.PieceCount,
           unfold.BendLineCount, unfold.FitError))
    require("RmfUnfold of an extruded B-spline: valid, general_cylinder, bend lines, "
            "PieceCount = BendLineCount + 1, 0 < FitError <= Tolerance",
            unfold.isValid() and unfold.SurfaceKind == "general_cylinder"
            and unfold.BendLineCount > 0 and unfold.PieceCount == unfold.BendLineCount + 1
            and 0 < unfold.FitError <= 1e-5)
    check("its FlatArea against the B-spline's length × height", rel(unfold.FlatArea.Value,
                                                                     15 * length), 1e-5)
    path = os.path.join(WORK, "wave.dxf")
    counts = wb.export_dxf(unfold, path)
    layers = {}
    for e in read_dxf(path):
        layers.setdefault(e.get("8"), []).append(e)
    require("its DXF (the library's): CUT %d, BEND %d entities (feature: %s)"
            % (len(layers.get("CUT", [])), len(layers.get("BEND", [])), counts),
            (len(layers.get("CUT", [])), len(layers.get("BEND", []))) == counts
            and counts[1] == unfold.BendLineCount)
    FreeCAD.closeDocument(doc.Name)


# ---------------------------------------------------------------------------------------
# H. A whole sheet body: rmfsurf.freecad.unfold and RmfUnfold


def l_bracket():
    """An L bracket of sheet 1 thick and 4 wide — flanges of 10, a quarter bend of inner
    radius 2.5 — with a round hole of radius 0.8 through its first flange."""
    def arc(centre, radius, a0, a1):
        circle = Part.Circle(V(*centre, 0), V(0, 0, 1), radius)
        return Part.ArcOfCircle(circle, math.radians(a0), math.radians(a1)).toShape()
    edges = [Part.LineSegment(V(0, -0.5, 0), V(10, -0.5, 0)).toShape(),
             arc((10, 3), 3.5, 270, 360),
             Part.LineSegment(V(13.5, 3, 0), V(13.5, 13, 0)).toShape(),
             Part.LineSegment(V(13.5, 13, 0), V(12.5, 13, 0)).toShape(),
             Part.LineSegment(V(12.5, 13, 0), V(12.5, 3, 0)).toShape(),
             arc((10, 3), 2.5, 270, 360),
             Part.LineSegment(V(10, 0.5, 0), V(0, 0.5, 0)).toShape(),
             Part.LineSegment(V(0, 0.5, 0), V(0, -0.5, 0)).toShape()]
    section = Part.Face(Part.Wire(Part.__sortEdges__(edges)))
    solid = section.extrude(V(0, 0, 4))
    return solid.cut(Part.makeCylinder(0.8, 5, V(5, 2.5, 2), V(0, -1, 0)))


def part_h():
    say("H. A whole sheet body: rmfsurf.freecad.unfold and RmfUnfold")
    import rmfsurf_workbench as wb
    import rmfsurf.freecad as rf
    bracket = l_bracket()
    require("the L bracket is a valid solid", bracket.isValid() and len(bracket.Solids) == 1)
    pattern = rf.unfold(bracket, tolerance=1e-6)
    say("  L bracket: thickness %.15g, flat area %.15g, volume / thickness %.15g, %d bends, "
        "%d inner wires" % (pattern.thickness, pattern.area, bracket.Volume / pattern.thickness,
                            len(pattern.bends), len(pattern.face.Wires) - 1))
    check("L bracket: thickness", abs(pattern.thickness - 1.0), 1e-9)
    check("L bracket: flat area against volume / thickness (k = 0.5)",
          rel(pattern.area, bracket.Volume / pattern.thickness), 1e-9)
    require("L bracket: one bend of inner radius 2.5, the hole an inner wire of a valid face",
            len(pattern.bends) == 1 and abs(pattern.bends[0].radius - 2.5) < 1e-9
            and len(pattern.face.Wires) == 2 and pattern.face.isValid())
    expected = 4 * (20 + math.pi / 2 * 2.8) - math.pi * 0.8 ** 2
    check("L bracket at k = 0.3: flat area against 4 (20 + π/2 · 2.8) − π 0.8²",
          rel(rf.unfold(bracket, k_factor=0.3, tolerance=1e-6).area, expected), 1e-9)

    doc = FreeCAD.newDocument("body")
    body = doc.addObject("Part::Feature", "Bracket")
    body.Shape = bracket
    doc.recompute()
    unfold = wb.make_unfold(doc, body)
    unfold.Tolerance, unfold.KFactor = 1e-6, 0.3
    doc.recompute()
    say("  RmfUnfold of the bracket: %s, SurfaceKind %r, Thickness %.12g, FlatArea %.12g, "
        "BendLineCount %d" % ("valid" if unfold.isValid() else "INVALID " + unfold.getStatusString(),
                              unfold.SurfaceKind, unfold.Thickness.Value, unfold.FlatArea.Value,
                              unfold.BendLineCount))
    require("RmfUnfold of the bracket: valid, sheet_body, one bend line",
            unfold.isValid() and unfold.SurfaceKind == "sheet_body" and unfold.BendLineCount == 1)
    check("its FlatArea at KFactor 0.3", rel(unfold.FlatArea.Value, expected), 1e-9)
    path = os.path.join(WORK, "bracket.dxf")
    wb.export_dxf(unfold, path)
    layers = [e.get("8") for e in read_dxf(path)]
    require("its DXF: the bend line on BEND_UP or BEND_DOWN (%s)" % sorted(set(layers)),
            layers.count("BEND_UP") + layers.count("BEND_DOWN") == 1)
    FreeCAD.closeDocument(doc.Name)


def main():
    import rmfsurf
    say("rmfsurf %s in FreeCAD %s, Python %s"
        % (rmfsurf.__version__, ".".join(FreeCAD.Version()[:3]), sys.version.split()[0]))
    import rmfsurf.shapes
    part_a()
    doc = FreeCAD.newDocument("workbench")
    if rmfsurf.shapes._has_wire_sweep():
        sweeps, drivers = part_b(doc)
    else:
        say("B. RmfSweep: NOT RUN: this librmfsurf has no rmf_wire_sweep")
        sweeps, drivers = [], None
    unfolds, _ = part_c(doc)
    transition, _ = part_d(doc)
    part_e(doc, sweeps + unfolds + transition, drivers)
    part_f(rmfsurf.shapes._has_wire_sweep())
    part_g()
    part_h()
    if failures:
        say("WORKBENCH CHECKS FAILED: %s" % "; ".join(failures))
        sys.exit(1)
    say("WORKBENCH CHECKS OK")
    sys.exit(0)


try:
    main()
except SystemExit:
    raise
except BaseException:
    traceback.print_exc()
    sys.exit(1)
