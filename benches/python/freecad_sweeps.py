"""The whole sweep where a FreeCAD user is: FreeCAD's own `makePipeShell` beside
`rmfsurf.freecad.sweep` on the same wires and profiles, in the same run (best of 3).

Run in freecadcmd (scripts/bench installs this checkout's wheel where FreeCAD looks for
add-on packages)."""

import os
import sys

import FreeCAD
import Part

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import rmfsurf.freecad as rfc  # noqa: E402
from timing import best  # noqa: E402

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


main()
