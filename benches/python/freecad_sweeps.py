"""The whole sweep where a FreeCAD user is: FreeCAD's own `makePipeShell` beside
`rmfsurf.freecad.sweep` on the same wires and profiles, in the same run (best of 3); and
the square-to-round transition of the RmfSurf workbench's feature (`rmfsurf.freecad`
`transition` and `part_solid`), with where its time goes, beside FreeCAD's ruled loft of
the same two wires (a surface without thickness: FreeCAD has no developable transition).

Run in freecadcmd (scripts/bench installs this checkout's wheel where FreeCAD looks for
add-on packages)."""

import os
import sys
import time

import FreeCAD
import Part

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import rmfsurf.freecad as rfc  # noqa: E402
from timing import best, best_on_fresh  # noqa: E402

V = FreeCAD.Vector


def polyline(points):
    return Part.Wire([Part.LineSegment(V(*a), V(*b)).toShape() for a, b in zip(points, points[1:])])


def circle_at(wire, radius):
    edge = wire.OrderedEdges[0]
    start, tangent = edge.valueAt(edge.FirstParameter), edge.tangentAt(edge.FirstParameter)
    return Part.Wire([Part.makeCircle(radius, start, tangent)])


def cases():
    route = polyline([(0, 0, 0), (60, 0, 0), (60, 40, 0), (60, 40, 30)])
    yield "pipe route (3 lines, round corners), circle", route, circle_at(route, 3)
    helix = Part.Wire([Part.makeHelix(10, 50, 15)])
    yield "5-turn helix, circle", helix, circle_at(helix, 2)
    zigzag = polyline([(10 * i, 10 * (i % 2), 0) for i in range(101)])
    yield "100-edge polyline, round corners, circle", zigzag, circle_at(zigzag, 1)


def main():
    print("| FreeCAD %s: the whole call, best of 3, milliseconds" % ".".join(FreeCAD.Version()[:3]))
    print("| %-44s %14s %10s %7s" % ("case", "makePipeShell", "rmfsurf", "ratio"))
    for name, wire, profile in cases():
        theirs, shell = best(lambda: wire.makePipeShell([profile], True, False, 2))
        face = Part.Face(profile)
        ours, solid = best(lambda: rfc.sweep(wire, face))
        assert solid.isValid() and shell.isValid(), name
        print("| %-44s %14.1f %10.1f %6.2fx" % (name, theirs * 1e3, ours * 1e3, theirs / ours))
    print("| ratio: FreeCAD's time over rmfsurf's (> 1: rmfsurf is faster)")
    thread()
    transition()


def poles(shape):
    """B-spline poles of a shape's faces (what downstream work handles)."""
    count = 0
    for face in shape.Faces:
        surface = face.Surface
        if isinstance(surface, Part.BSplineSurface):
            count += surface.NbUPoles * surface.NbVPoles
    return count


def thread():
    """A thread's groove as FreeCAD users make it: a triangle in the axial plane through
    the helix's start, swept with the Frenet frame (makePipeShell's isFrenet, rmfsurf's
    frame="frenet"), then cut from a rod."""
    helix = Part.Wire([Part.makeHelix(5, 40, 10)])
    start = helix.OrderedEdges[0].valueAt(helix.OrderedEdges[0].FirstParameter)
    triangle = Part.makePolygon([start + V(0.75, 0, -0.6), start + V(0.75, 0, 0.6),
                                 start + V(-0.6, 0, 0), start + V(0.75, 0, -0.6)])
    rod = Part.makeCylinder(10, 50, V(0, 0, -5))
    print("| thread (rod - 8-turn groove, axial triangle, Frenet), tolerance 1e-5: milliseconds")
    print("| %-28s %8s %9s %6s %8s %7s" % ("groove by", "groove", "boolean", "valid", "poles",
                                            "ratio"))
    base = None
    for name, make in [
            ("makePipeShell (Frenet)", lambda: helix.makePipeShell([triangle], True, True)),
            ("rmfsurf (frame frenet)",
             lambda: rfc.sweep(helix, Part.Face(triangle), frame="frenet", tolerance=1e-5)),
            ("rmfsurf (fixed axis)",
             lambda: rfc.sweep(helix, Part.Face(triangle), frame=("fixed", (0, 0, 1)),
                               tolerance=1e-5))]:
        groove_time, groove = best(make)
        cut_time, cut = best_on_fresh(make, lambda fresh: rod.cut(fresh))
        # A cut that leaves the rod's faces alone did not cut: count it as failed.
        valid = (groove.isValid() and cut.isValid() and len(cut.Solids) == 1
                 and len(cut.Faces) > len(rod.Faces))
        base = base or cut_time
        print("| %-28s %8.1f %9.1f %6s %8d %6.2fx" % (
            name, groove_time * 1e3, cut_time * 1e3, valid, poles(groove), cut_time / base))
    print("| ratio: the boolean's time over the boolean with makePipeShell's groove")


def first_binary(make, runs=3):
    """The best time of a part's binary B-rep for FreeCAD (occ_binary("freecad")), each on
    a part made anew, and the file."""
    times, data = [], None
    for _ in range(runs):
        part = make()
        start = time.perf_counter()
        data = part.occ_binary("freecad")
        times.append(time.perf_counter() - start)
    return min(times), data


def transition():
    square = polyline([(-100, -100, 0), (100, -100, 0), (100, 100, 0), (-100, 100, 0), (-100, -100, 0)])
    circle = Part.Wire([Part.makeCircle(60, V(20, 0, 150), V(0, 0, 1))])
    print("| square-to-round transition, thickness 2: best of 3, milliseconds")
    print("| %-12s %8s %10s %10s %8s %8s %6s" % ("tolerance", "loft", "rmfsurf", "library",
                                                 "binary", "kernel", "faces"))
    for tolerance in (1e-3, 1e-4):
        loft, _ = best(lambda: Part.makeLoft([square, circle], False, True))
        library, _ = best(lambda: rfc.transition(square, circle, 2.0, 0.5, tolerance))
        binary_time, data = first_binary(lambda: rfc.transition(square, circle, 2.0, 0.5, tolerance))

        def build():
            return rfc._from_binary(data).Solids[0]

        kernel, _ = best(build)
        whole, solid = best(lambda: rfc.part_solid(rfc.transition(square, circle, 2.0, 0.5, tolerance)))
        assert solid.isValid() and solid.Volume > 0
        print("| %-12g %8.1f %10.1f %10.1f %8.1f %8.1f %6d" % (
            tolerance, loft * 1e3, whole * 1e3, library * 1e3, binary_time * 1e3, kernel * 1e3,
            len(solid.Faces)))
    print("| loft: Part.makeLoft of the two wires, ruled (a surface: no thickness, no flat "
          "pattern); rmfsurf: the whole call (transition, then part_solid), split into the "
          "library, its binary B-rep and FreeCAD reading it (Part.Shape.importBinary of a "
          "file in /dev/shm)")


main()
