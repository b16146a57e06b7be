"""The whole sweep where a build123d user is: build123d's own `sweep` beside
`rmfsurf.ocp.sweep` on the same wires and profiles, in the same run (best of 3), with where
rmfsurf's time goes: reading the user's wire and face (adapter in), the library's sweep, its
binary B-rep, and OpenCascade building the shape from it (`BinTools.Read_s`); then a thread
cut, the boolean downstream of each program's groove.

Run by scripts/bench in the test venv with this checkout's wheel."""

import io
import time

import build123d as bd
from OCP.BinTools import BinTools
from OCP.TopoDS import TopoDS_Shape

import rmfsurf
import rmfsurf.ocp as rocp
from timing import best, best_on_fresh

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
    shape = rmfsurf.wire_sweep(edges, outer, holes, tolerance=TOLERANCE, initial_normal=f2,
                               pipe_frame="lightest")
    library = time.perf_counter()
    data = shape.occ_binary()
    handover = time.perf_counter()
    raw = TopoDS_Shape()
    BinTools.Read_s(raw, io.BytesIO(data))
    kernel = time.perf_counter()
    return [adapter - start, library - adapter, handover - library, kernel - handover]


def main():
    print("build123d %s: the whole call, best of 3, milliseconds" % bd.__version__)
    print("%-42s %10s %10s %7s | %8s %8s %8s %8s" % (
        "case", "build123d", "rmfsurf", "ratio", "adapter", "library", "binary", "kernel"))
    for name, path, face in cases():
        profile = placed(path, face.faces()[0])
        theirs, _ = best(lambda: bd.sweep(profile, path, transition=bd.Transition.ROUND))
        ours, solid = best(lambda: rocp.sweep(path, profile, tolerance=TOLERANCE))
        assert rocp.is_valid(solid), name
        parts = min((stages(path, profile) for _ in range(3)), key=sum)
        print("%-42s %10.1f %10.1f %6.2fx | %8.1f %8.1f %8.1f %8.1f" % (
            name, theirs * 1e3, ours * 1e3, theirs / ours, *(p * 1e3 for p in parts)))
    print("ratio: build123d's time over rmfsurf's (> 1: rmfsurf is faster)")
    downstream()
    thread_cut()


def step_size(shape):
    """Bytes of the shape's STEP file as build123d writes it."""
    import os
    import tempfile
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "shape.step")
        bd.export_step(shape, path)
        return os.path.getsize(path)


def mesh(shape, deflection=0.01):
    """OpenCascade's tessellation of a fresh copy (BRepMesh_IncrementalMesh): triangles."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Copy
    from OCP.BRepMesh import BRepMesh_IncrementalMesh
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopLoc import TopLoc_Location
    from OCP.TopoDS import TopoDS
    copy = BRepBuilderAPI_Copy(shape.wrapped).Shape()
    BRepMesh_IncrementalMesh(copy, deflection, False, 0.5, True)
    triangles, explorer = 0, TopExp_Explorer(copy, TopAbs_FACE)
    while explorer.More():
        mesh = BRep_Tool.Triangulation_s(TopoDS.Face(explorer.Current()), TopLoc_Location())
        triangles += mesh.NbTriangles() if mesh is not None else 0
        explorer.Next()
    return triangles


def downstream():
    """What each program's pipe costs downstream (the same route and profiles as above):
    a boolean (a block less the pipe: a channel through it; with the ring, the core inside
    the hole stays as a second solid), a tessellation (linear deflection 0.01, the copy's
    meshing timed), the size of the STEP file build123d writes."""
    ring = bd.Circle(3) - bd.Circle(1.5)
    route = bd.FilletPolyline((0, 0, 0), (60, 0, 0), (60, 40, 0), (60, 40, 30), radius=10)
    block = bd.Box(70, 20, 20, align=(bd.Align.MIN, bd.Align.CENTER, bd.Align.CENTER))
    print("downstream of the pipe route: milliseconds, best of 3")
    print("%-10s %-10s %6s %10s %6s %10s %10s %10s" % (
        "profile", "sweep by", "faces", "boolean", "valid", "mesh", "triangles", "STEP kB"))
    for name, face in (("circle", bd.Circle(3)), ("ring", ring)):
        profile = placed(route, face.faces()[0])
        for by, make in (
                ("build123d", lambda: bd.sweep(profile, route, transition=bd.Transition.ROUND)),
                ("rmfsurf", lambda: rocp.sweep(route, profile, tolerance=TOLERANCE))):
            solid = make()
            cut_time, cut = best_on_fresh(make, lambda fresh: block - fresh)
            mesh_time, triangles = best(lambda: mesh(solid))
            print("%-10s %-10s %6d %10.1f %6s %10.1f %10d %10.1f" % (
                name, by, len(solid.faces()), cut_time * 1e3,
                rocp.is_valid(cut), mesh_time * 1e3, triangles,
                step_size(solid) / 1e3))


def poles(shape):
    """Faces and B-spline poles of a shape (what downstream work handles)."""
    from OCP.BRep import BRep_Tool
    from OCP.Geom import Geom_BSplineSurface
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    faces, count = 0, 0
    explorer = TopExp_Explorer(shape.wrapped, TopAbs_FACE)
    while explorer.More():
        surface = BRep_Tool.Surface_s(TopoDS.Face(explorer.Current()))
        if isinstance(surface, Geom_BSplineSurface):
            count += surface.NbUPoles() * surface.NbVPoles()
        faces += 1
        explorer.Next()
    return faces, count


def axial(helix, face):
    """`face` in the axial plane through the helix's start (the plane of its axis z and the
    radial direction there), as users draw a thread's profile."""
    start = helix @ 0
    radial = bd.Vector(start.X, start.Y, 0).normalized()
    return bd.Plane(origin=start, x_dir=radial, z_dir=radial.cross(bd.Vector(0, 0, 1))) * face


def thread_cut():
    """A rod less a helical groove (a triangle swept along a helix on the rod's surface):
    the groove by build123d's sweeps (Frenet, and its default corrected Frenet) and by
    rmfsurf's (the RMF, and the Frenet frame whose edges are helices), the triangle in the
    helix's normal plane and in the axial plane as users draw it; then the same boolean
    with each."""
    rod = bd.Cylinder(10, 50, align=(bd.Align.CENTER, bd.Align.CENTER, bd.Align.MIN))
    helix = bd.Wire([bd.Helix(pitch=5, height=40, radius=10, center=(0, 0, 5))])
    shape = bd.RegularPolygon(1.5, 3).faces()[0]
    normal, axial_face = placed(helix, shape), axial(helix, shape)
    grooves = [
        ("build123d sweep (Frenet)", lambda: bd.sweep(normal, helix, is_frenet=True)),
        # Its default frame, close to the RMF: OpenCascade's boolean leaves the rod uncut
        # with this groove as with rmfsurf's RMF groove.
        ("build123d (corrected Frenet)", lambda: bd.sweep(normal, helix)),
        ("rmfsurf.ocp.sweep (RMF)", lambda: rocp.sweep(helix, normal, tolerance=1e-5)),
        ("rmfsurf.ocp.sweep (Frenet)",
         lambda: rocp.sweep(helix, normal, tolerance=1e-5, frame="frenet")),
        ("build123d, axial profile", lambda: bd.sweep(axial_face, helix, is_frenet=True)),
        ("rmfsurf, axial profile",
         lambda: rocp.sweep(helix, axial_face, tolerance=1e-5, frame="frenet")),
    ]
    print("thread cut (rod - 8-turn helical triangle groove), tolerance 1e-5: milliseconds")
    print("%-28s %10s %10s %8s %12s %14s %6s" % (
        "groove by", "groove", "boolean", "valid", "groove faces", "B-spline poles", "ratio"))
    base = None
    for name, make in grooves:
        groove_time, groove = best(make)
        cut_time, cut = best_on_fresh(make, lambda fresh: rod - fresh)
        # A cut that leaves the rod's faces alone did not cut: count it as failed.
        valid = (rocp.is_valid(groove) and rocp.is_valid(cut) and len(cut.solids()) == 1
                 and len(cut.faces()) > len(rod.faces()))
        faces, count = poles(groove)
        base = base or cut_time
        print("%-28s %10.1f %10.1f %8s %12d %14d %5.2fx" % (
            name, groove_time * 1e3, cut_time * 1e3, valid, faces, count, cut_time / base))
    print("ratio: the boolean's time over the boolean with build123d's own groove")


if __name__ == "__main__":
    main()
