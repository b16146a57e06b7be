"""The whole sweep where a build123d user is: build123d's own `sweep` beside
`rmfsurf.ocp.sweep` on the same wires and profiles, in the same run (best of 3), with where
rmfsurf's time goes: reading the user's wire and face (adapter in), the library's sweep, its
B-rep text, and OpenCascade building the shape from it (`BRepTools.Read_s`).

Run by scripts/bench in the test venv with this checkout's wheel."""

import io
import time

import build123d as bd
from OCP.BRep import BRep_Builder
from OCP.BRepTools import BRepTools
from OCP.TopoDS import TopoDS_Shape

import rmfsurf
import rmfsurf.ocp as rocp
from timing import best

TOLERANCE = 1e-4


def placed(path, face):
    """`face` in the plane normal to `path` at its start."""
    return bd.Plane(origin=path @ 0, z_dir=path % 0) * face


def cases():
    ring = bd.Circle(3) - bd.Circle(1.5)
    route = bd.FilletPolyline((0, 0, 0), (60, 0, 0), (60, 40, 0), (60, 40, 30), radius=10)
    yield "pipe route (line, arc, line, arc, line), circle", route, bd.Circle(3)
    yield "pipe route (line, arc, line, arc, line), ring", route, ring
    yield ("5-turn helix, circle",
           bd.Wire([bd.Helix(pitch=10, height=50, radius=15)]), bd.Circle(2))
    yield ("100-edge polyline, round corners, circle",
           bd.Polyline(*[(10 * i, 10 * (i % 2), 0) for i in range(101)]), bd.Circle(1))


def stages(path, profile):
    """rmfsurf.ocp.sweep's steps, timed one by one."""
    start = time.perf_counter()
    edges = rocp.path_edges(path)
    origin, tangent = rocp._start_frame(path)
    outer, holes, f2 = rocp.profile_curves(profile, origin, tangent, TOLERANCE)
    adapter = time.perf_counter()
    shape = rmfsurf.wire_sweep(edges, outer, holes, tolerance=TOLERANCE, initial_normal=f2)
    library = time.perf_counter()
    text = shape.occ_brep().encode("ascii")
    handover = time.perf_counter()
    raw = TopoDS_Shape()
    BRepTools.Read_s(raw, io.BytesIO(text), BRep_Builder())
    kernel = time.perf_counter()
    return [adapter - start, library - adapter, handover - library, kernel - handover]


def main():
    print("build123d %s: the whole call, best of 3, milliseconds" % bd.__version__)
    print("%-42s %10s %10s %7s | %8s %8s %8s %8s" % (
        "case", "build123d", "rmfsurf", "ratio", "adapter", "library", "text", "kernel"))
    for name, path, face in cases():
        profile = placed(path, face.faces()[0])
        theirs, _ = best(lambda: bd.sweep(profile, path, transition=bd.Transition.ROUND))
        ours, solid = best(lambda: rocp.sweep(path, profile, tolerance=TOLERANCE))
        assert rocp.is_valid(solid), name
        parts = min((stages(path, profile) for _ in range(3)), key=sum)
        print("%-42s %10.1f %10.1f %6.2fx | %8.1f %8.1f %8.1f %8.1f" % (
            name, theirs * 1e3, ours * 1e3, theirs / ours, *(p * 1e3 for p in parts)))
    print("ratio: build123d's time over rmfsurf's (> 1: rmfsurf is faster)")


if __name__ == "__main__":
    main()
