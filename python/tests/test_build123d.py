"""rmfsurf.ocp.sweep with build123d from PyPI: a pipe route of lines and arcs and a helix
swept with rotation-minimizing frames into solids that OpenCascade validates
(BRepCheck_Analyzer), with volumes against the closed form π (R² − r²) L, fused with a box
and written to STEP; build123d's own sweep of the same routes for comparison (validity,
volume error, orthogonality of the parameter lines)."""

import math

import pytest

import rmfsurf
import rmfsurf.ocp as rocp
from test_ocp import parameter_cosine

bd = pytest.importorskip("build123d")
from OCP.TopAbs import TopAbs_FACE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Surface  # noqa: E402
from OCP.GeomAbs import GeomAbs_Plane  # noqa: E402
from OCP.TopoDS import TopoDS  # noqa: E402

needs_wire_sweep = pytest.mark.skipif(
    not rmfsurf.shapes._has_wire_sweep(),
    reason="this librmfsurf has no rmf_wire_sweep yet (the wire sweep C API)")

R, HOLE = 3.0, 1.5


def pipe_route():
    return bd.FilletPolyline((0, 0, 0), (60, 0, 0), (60, 40, 0), (60, 40, 30), radius=10)


def helix_route():
    return bd.Wire([bd.Helix(pitch=25, height=50, radius=15)])


def ring(path, hole=True):
    """The profile in the plane normal to the path at its start."""
    plane = bd.Plane(origin=path @ 0, z_dir=path % 0)
    face = bd.Circle(R) - bd.Circle(HOLE) if hole else bd.Circle(R)
    return plane * face.faces()[0]


def lateral_cosine(shape):
    """max |cos| between parameter lines over the non-planar faces."""
    worst, explorer = 0.0, TopExp_Explorer(shape.wrapped, TopAbs_FACE)
    while explorer.More():
        f = TopoDS.Face(explorer.Current())
        if BRepAdaptor_Surface(f).GetType() != GeomAbs_Plane:
            worst = max(worst, parameter_cosine(f))
        explorer.Next()
    return worst


def gk_volume(shape, tolerance=1e-10):
    """OpenCascade's adaptive Gauss-Kronrod volume (BRepGProp.VolumePropertiesGK_s) to
    `tolerance`."""
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps
    props = GProp_GProps()
    BRepGProp.VolumePropertiesGK_s(shape.wrapped, props, tolerance)
    return props.Mass()


def figures(name, solid, expected):
    valid = rocp.is_valid(solid)
    error = abs(solid.volume - expected) / expected
    cosine = lateral_cosine(solid)
    print("\n%-34s valid %-5s volume error %.2e  parameter lines max |cos| %.1e"
          % (name, valid, error, cosine))
    return valid, error, cosine


@needs_wire_sweep
@pytest.mark.parametrize("pipe_frame", ["lightest", "rmf"])
@pytest.mark.parametrize("route, spine_tolerance", [(pipe_route, 1e-12), (helix_route, 1e-4)])
def test_rmfsurf_sweep_is_a_valid_solid_with_the_closed_form_volume(route, spine_tolerance,
                                                                    pipe_frame, tmp_path):
    """A ring along the pipe route and a helix: a valid solid of the closed-form volume,
    fused with and cut from a box, through STEP and back; on the RMF (pipe_frame="rmf",
    and along lines and arcs whatever the frame) its parameter lines are orthogonal."""
    path = route()
    expected = math.pi * (R * R - HOLE * HOLE) * path.length
    pipe = rocp.sweep(path, ring(path), pipe_frame=pipe_frame)
    assert isinstance(pipe, bd.Solid)
    valid, error, cosine = figures("rmfsurf.ocp.sweep, %s, %s" % (route.__name__, pipe_frame),
                                   pipe, expected)
    assert valid
    if route is pipe_route:
        # Lines and arcs are exact cylinders and tori: the closed form to OpenCascade's
        # Gauss-Kronrod accuracy (its default quadrature is off by about 1e-9).
        assert abs(gk_volume(pipe) - expected) <= 1e-12 * expected
    else:
        # A helix is approximated within 1e-4.
        assert error <= 10 * spine_tolerance / R
    if pipe_frame == "rmf" or route is pipe_route:
        assert cosine <= 1e-5
    box = bd.Box(20, 20, 20)
    fused = box + pipe
    assert rocp.is_valid(fused) and box.volume < fused.volume < box.volume + pipe.volume
    cut = box - pipe
    assert rocp.is_valid(cut) and cut.volume < box.volume
    step = tmp_path / "pipe.step"
    bd.export_step(pipe, str(step))
    again = bd.import_step(str(step))
    assert abs(again.volume - pipe.volume) <= 1e-9 * pipe.volume


@needs_wire_sweep
@pytest.mark.parametrize("route", [pipe_route, helix_route])
def test_build123d_own_sweep_for_comparison(route):
    path = route()
    expected = math.pi * (R * R - HOLE * HOLE) * path.length
    theirs = bd.sweep(ring(path), path, transition=bd.Transition.ROUND)
    figures("build123d.sweep, %s" % route.__name__, theirs, expected)
    ours = rocp.sweep(path, ring(path), pipe_frame="rmf")
    _, our_error, our_cosine = figures("rmfsurf.ocp.sweep, %s" % route.__name__, ours, expected)
    assert our_error <= 1e-4 and our_cosine <= 1e-5


@needs_wire_sweep
def test_a_solid_profile_without_holes_and_miter_corners():
    path = bd.Polyline((0, 0, 0), (40, 0, 0), (40, 30, 0))
    pipe = rocp.sweep(path, ring(path, hole=False), corner="miter")
    assert rocp.is_valid(pipe)
    assert pipe.volume > 0


def free_edges(raw):
    """Edges of the shape used by one face only (ShapeAnalysis_FreeBounds)."""
    from OCP.ShapeAnalysis import ShapeAnalysis_FreeBounds
    from OCP.TopAbs import TopAbs_EDGE as EDGE
    bounds = ShapeAnalysis_FreeBounds(raw)
    count, explorer = 0, TopExp_Explorer(bounds.GetClosedWires(), EDGE)
    while explorer.More():
        count, _ = count + 1, explorer.Next()
    explorer = TopExp_Explorer(bounds.GetOpenWires(), EDGE)
    while explorer.More():
        count, _ = count + 1, explorer.Next()
    return count


@needs_wire_sweep
@pytest.mark.parametrize("corner", ["round", "miter"])
@pytest.mark.parametrize("hole", [False, True])
def test_the_library_hands_over_its_brep_and_opencascade_takes_it_as_built(corner, hole):
    """The shape is read from the library's B-rep text (no sewing, no healing, no volume
    to orient it): valid for BRepCheck_Analyzer as read, every edge shared by two faces,
    the volume positive and the closed form's."""
    path = bd.Polyline((0, 0, 0), (40, 0, 0), (40, 30, 0), (40, 30, 25))
    pipe = rocp.sweep(path, ring(path, hole), corner=corner)
    assert isinstance(pipe, bd.Solid)
    assert rocp.is_valid(pipe)
    assert free_edges(pipe.wrapped) == 0
    assert pipe.volume > 0
    if corner == "round":
        # Lines and round corners: exact cylinders and tori, the closed form exactly.
        expected = math.pi * (R * R - (HOLE * HOLE if hole else 0.0)) * path_length(pipe, path)
        assert abs(gk_volume(pipe) - expected) <= 1e-12 * expected


def surface_kinds(shape):
    """How many faces of the shape lie on each kind of OpenCascade surface."""
    from collections import Counter
    from OCP.GeomAbs import (GeomAbs_BSplineSurface, GeomAbs_Cone, GeomAbs_Cylinder,
                             GeomAbs_Torus)
    names = {GeomAbs_Plane: "plane", GeomAbs_Cylinder: "cylinder", GeomAbs_Torus: "torus",
             GeomAbs_Cone: "cone", GeomAbs_BSplineSurface: "bspline"}
    kinds, explorer = Counter(), TopExp_Explorer(shape.wrapped, TopAbs_FACE)
    while explorer.More():
        kind = BRepAdaptor_Surface(TopoDS.Face(explorer.Current())).GetType()
        kinds[names.get(kind, str(kind))] += 1
        explorer.Next()
    return kinds


@needs_wire_sweep
@pytest.mark.parametrize("hole", [False, True])
def test_a_pipe_route_is_handed_over_as_the_cylinders_and_tori_it_is(hole):
    """A circle (or ring) along lines and round corners is exact cylinders and tori:
    OpenCascade reads them as its own analytic surfaces, not B-splines; the solid is valid
    as read, its volume the closed form's, and a boolean with a box is valid and splits the
    volume. With miter corners the cylinders end on ellipses and stay B-splines."""
    import numpy as np
    path = bd.Polyline((0, 0, 0), (40, 0, 0), (40, 30, 0), (40, 30, 25))
    pipe = rocp.sweep(path, ring(path, hole), corner="round")
    kinds = surface_kinds(pipe)
    walls = 2 if hole else 1
    assert kinds["bspline"] == 0 and kinds["plane"] == 2
    assert kinds["cylinder"] > 0 and 2 * kinds["cylinder"] == 3 * kinds["torus"]
    assert kinds["cylinder"] % (3 * walls) == 0
    assert rocp.is_valid(pipe) and free_edges(pipe.wrapped) == 0
    expected = math.pi * (R * R - (HOLE * HOLE if hole else 0.0)) * path_length(pipe, path)
    assert abs(gk_volume(pipe) - expected) <= 1e-12 * expected
    assert abs(pipe.volume - expected) <= 1e-9 * expected
    box = bd.Box(30, 40, 40, align=(bd.Align.MIN, bd.Align.CENTER, bd.Align.CENTER))
    inside, outside = pipe & box, pipe - box
    assert rocp.is_valid(inside) and rocp.is_valid(outside)
    assert np.isclose(inside.volume + outside.volume, pipe.volume, rtol=1e-9)
    assert 0 < inside.volume < pipe.volume
    mitered = rocp.sweep(path, ring(path, hole), corner="miter")
    assert surface_kinds(mitered)["bspline"] > 0 and rocp.is_valid(mitered)


@needs_wire_sweep
def test_a_square_duct_is_handed_over_as_planes_cones_and_cylinders():
    """A square (R across its corners) along lines and round corners: planes along the
    lines; about each corner's axis its sides sweep cones (the square standing on a corner
    there) or cylinders and annuli (upright); turned by 45° one becomes the other.
    OpenCascade reads them as its own surfaces, the solid valid, its volume the profile's
    area times the length of the route (Pappus)."""
    path = bd.Polyline((0, 0, 0), (40, 0, 0), (40, 30, 0), (40, 30, 25))
    plane = bd.Plane(origin=path @ 0, z_dir=path % 0)
    cones = []
    for turn in (0.0, 45.0):
        square = bd.RegularPolygon(R, 4, rotation=turn)
        duct = rocp.sweep(path, plane * square.faces()[0], corner="round")
        kinds = surface_kinds(duct)
        assert kinds["bspline"] == 0 and rocp.is_valid(duct) and free_edges(duct.wrapped) == 0
        assert kinds["cone"] + kinds["cylinder"] + kinds["plane"] == 3 * 4 + 2 * 4 + 2
        cones.append(kinds["cone"])
        expected = 2 * R * R * path_length(duct, path)
        assert abs(gk_volume(duct) - expected) <= 1e-12 * expected
    assert sorted(cones) == [0, 8]


def path_length(pipe, path):
    """The length of the rounded route rmfsurf swept: the polyline's, less 2r − rθ at each
    corner of radius r = 1.5 R (the library's default) and angle θ = π/2."""
    r = 1.5 * R
    return path.length - 2 * (2 * r - r * math.pi / 2)


@needs_wire_sweep
def test_an_open_sweep_of_a_hollow_profile_is_its_two_walls():
    path = pipe_route()
    walls = rocp.sweep(path, ring(path), solid=False)
    assert isinstance(walls, bd.Compound)
    assert len(walls.shells()) == 2 and rocp.is_valid(walls)


@needs_wire_sweep
def test_a_face_turned_inside_out_in_the_text_is_found_invalid():
    """The validity check above can fail: the same text with one face's sense flipped."""
    from OCP.BRep import BRep_Builder
    from OCP.BRepTools import BRepTools
    from OCP.TopoDS import TopoDS_Shape
    import io
    pipe = rmfsurf.wire_sweep([rmfsurf.Line((0, 0, 0), (10, 0, 0))], rmfsurf.circle(1.0))
    text = pipe.occ_brep()
    head, shell = text.rsplit("\nSh\n", 1)
    flipped = shell.replace("+", "\x00", 1).replace("-", "+", 1).replace("\x00", "-", 1)
    for candidate, valid in [(text, True), (head + "\nSh\n" + flipped, False)]:
        raw = TopoDS_Shape()
        BRepTools.Read_s(raw, io.BytesIO(candidate.encode()), BRep_Builder())
        assert rocp.is_valid(raw) == valid


def read_text_and_binary(text, data):
    """The shapes OpenCascade reads from a B-rep text (BRepTools) and a binary B-rep
    (BinTools)."""
    from OCP.BRep import BRep_Builder
    from OCP.BRepTools import BRepTools
    from OCP.BinTools import BinTools
    from OCP.TopoDS import TopoDS_Shape
    import io
    by_text, by_binary = TopoDS_Shape(), TopoDS_Shape()
    BRepTools.Read_s(by_text, io.BytesIO(text.encode()), BRep_Builder())
    BinTools.Read_s(by_binary, io.BytesIO(data))
    return by_text, by_binary


def census(shape):
    """Kinds and counts of the shape's sub-shapes and its faces' surface types."""
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_SHELL, TopAbs_VERTEX
    counts = []
    for kind in (TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE, TopAbs_SHELL):
        explorer, n = TopExp_Explorer(shape, kind), 0
        while explorer.More():
            n += 1
            explorer.Next()
        counts.append(n)
    types, explorer = [], TopExp_Explorer(shape, TopAbs_FACE)
    while explorer.More():
        types.append(str(BRepAdaptor_Surface(TopoDS.Face(explorer.Current())).GetType()))
        explorer.Next()
    return shape.ShapeType(), counts, types


@needs_wire_sweep
def test_the_binary_b_rep_is_the_text_s_shape_read_without_parsing():
    """Shape.occ_binary() and SheetPart.occ_binary(), read by BinTools: the shape of the
    B-rep text — the same kinds and counts of vertices, edges, faces and shells, the same
    surface types, valid as read, the same volume to 1e-12 — for a pipe route of a circle
    (cylinders, tori), the open walls of a ring (a compound of two shells), a square duct
    with miter corners (planes and B-splines), a helix and a transition. A vertex moved
    in the binary file is read as moved (the check can fail)."""
    import struct
    from OCP.TopAbs import TopAbs_SOLID
    route = pipe_route()
    square = bd.Plane(origin=route @ 0, z_dir=route % 0) * bd.Rectangle(3, 2).faces()[0]
    corners = [[-100, -100, 0], [100, -100, 0], [100, 100, 0], [-100, 100, 0]]
    bottom = rmfsurf.Curve.from_nurbs(1, corners + [corners[0]], [0, 0, 1, 2, 3, 4, 4])
    part = rmfsurf.transition(bottom, rmfsurf.circle(60.0, (20.0, 0.0, 150.0)), thickness=2.0,
                              tolerance=1e-3)
    helix = helix_route()

    def library_sweep(path, profile, **options):
        origin, tangent = rocp._start_frame(path)
        outer, holes, f2 = rocp.profile_curves(profile, origin, tangent, 1e-4)
        return rmfsurf.wire_sweep(rocp.path_edges(path), outer, holes, tolerance=1e-4,
                                  initial_normal=f2, **options)

    sources = [library_sweep(route, ring(route, hole=False)),
               library_sweep(route, ring(route), solid=False),
               library_sweep(route, square, corner="miter"),
               library_sweep(helix, ring(helix, hole=False)),
               part]
    for source in sources:
        text, data = source.export("brep") if source is part else source.occ_brep(), \
            source.occ_binary()
        by_text, by_binary = read_text_and_binary(text, data)
        assert census(by_binary) == census(by_text)
        assert rocp.is_valid(by_binary) and rocp.is_valid(by_text)
        if by_text.ShapeType() == TopAbs_SOLID:
            volume = gk_volume(bd.Solid(by_text))
            assert abs(gk_volume(bd.Solid(by_binary)) - volume) <= 1e-12 * volume
    # The FreeCAD reader's file: the same set, its own root (three integers).
    freecad = part.occ_binary("freecad")
    assert freecad[:len(data) - 9] == data[:-9] and len(freecad) == len(data) + 3
    with pytest.raises(ValueError, match="reader"):
        part.occ_binary("step")
    # The first vertex's x moved by 1 in the TShapes table: the shape is no longer valid.
    pipe = sources[0]
    text, data = pipe.occ_brep(), pipe.occ_binary()
    table = data.index(b"\nTShapes ")
    record = data.index(b"\x07", table + 9)
    moved = data[:record + 9] + struct.pack("<d", struct.unpack("<d", data[record + 9:record + 17])[0] + 1.0) \
        + data[record + 17:]
    assert rocp.is_valid(read_text_and_binary(text, data)[1])
    assert not rocp.is_valid(read_text_and_binary(text, moved)[1])


@needs_wire_sweep
def test_a_pipe_along_a_curve_is_handed_over_in_the_lightest_faces():
    """rocp.sweep sweeps a circle along a curve on the PH spline's Euler-Rodrigues frame
    by default (pipe_frame="lightest"): along a conical spiral B-spline faces of degree 5
    along the path against the RMF's 9, 0.56 of the poles, the same valid solid
    (OpenCascade's volume to 1e-9); along a circular helix the helix's screw motion,
    degree 7 with simple knots, under a tenth of the RMF's poles; a pipe_frame that is
    neither is refused naming it."""
    from OCP.BRep import BRep_Tool

    def spline_faces(solid):
        faces, explorer = [], TopExp_Explorer(solid.wrapped, TopAbs_FACE)
        while explorer.More():
            surface = BRep_Tool.Surface_s(TopoDS.Face(explorer.Current()))
            if surface.DynamicType().Name() == "Geom_BSplineSurface":
                inner = {surface.VMultiplicity(i) for i in range(2, surface.NbVKnots())}
                faces.append((surface.VDegree(), surface.NbUPoles() * surface.NbVPoles(),
                              inner))
            explorer.Next()
        return faces

    spiral = bd.Wire([bd.Helix(pitch=25, height=25, radius=15, cone_angle=10)])
    light = rocp.sweep(spiral, ring(spiral, hole=False))
    rmf = rocp.sweep(spiral, ring(spiral, hole=False), pipe_frame="rmf")
    assert {d for d, _, _ in spline_faces(light)} == {5}
    assert {d for d, _, _ in spline_faces(rmf)} == {9}
    poles = [sum(n for _, n, _ in spline_faces(s)) for s in (light, rmf)]
    assert poles[0] < 0.6 * poles[1], poles
    assert rocp.is_valid(light) and rocp.is_valid(rmf)
    assert abs(gk_volume(light) - gk_volume(rmf)) <= 1e-9 * gk_volume(rmf)
    helix = helix_route()
    screw = spline_faces(rocp.sweep(helix, ring(helix, hole=False)))
    rmf = spline_faces(rocp.sweep(helix, ring(helix, hole=False), pipe_frame="rmf"))
    assert {(d, frozenset(inner)) for d, _, inner in screw} == {(7, frozenset({1}))}
    assert sum(n for _, n, _ in screw) < 0.1 * sum(n for _, n, _ in rmf)
    with pytest.raises(ValueError, match="pipe_frame"):
        rocp.sweep(helix, ring(helix, hole=False), pipe_frame="frenet")


def test_the_librarys_volume_is_opencascades_adaptive_volume():
    """Shape.volume() (rmf_shape_volume) of a pipe along a helix, the library's shape that
    rocp.sweep hands over, agrees with OpenCascade's adaptive Gauss-Kronrod volume of the
    solid built from it to 1e-9, and with pi r^2 L to 1e-5 (the PH spline is within 1e-4 of
    the helix of radius 15: its length within 7e-6); a sheet has no volume."""
    helix = helix_route()
    edges = rocp.path_edges(helix)
    shape = rmfsurf.wire_sweep(edges, rmfsurf.circle(R), tolerance=1e-4,
                               pipe_frame="lightest")
    solid = bd.Solid(rocp.shape(shape))
    length = 2 * math.hypot(2 * math.pi * 15, 25)
    exact = math.pi * R * R * length
    print("\nhelix pipe: library volume %.12f, OpenCascade adaptive %.12f, pi r^2 L %.12f"
          % (shape.volume(), gk_volume(solid), exact))
    assert abs(shape.volume() - gk_volume(solid)) <= 1e-9 * exact
    assert abs(shape.volume() - exact) <= 1e-5 * exact
    sheet = rmfsurf.wire_sweep(edges, rmfsurf.circle(R), solid=False)
    with pytest.raises(rmfsurf.InvalidInputError, match="sheet"):
        sheet.volume()


def test_a_threads_groove_is_its_screw_motion_which_the_kernel_reads_exactly():
    """A thread's groove — a triangle swept under the Frenet frame along an 8-turn helix
    made by build123d — is the helix's screw motion: B-spline faces of degree 7 along it
    with simple knots, fewer poles than build123d's own groove. OpenCascade's fixed-order
    volume (build123d's ``volume``) is area x length to 1e-6 (4.5e-8 measured; the PH
    spline's faces were read 2.8e-6 off), and rod - groove is valid and removes what
    build123d's own Frenet groove removes to 1e-5 (1.7e-6 measured)."""
    from OCP.BRep import BRep_Tool
    from OCP.Geom import Geom_BSplineSurface
    helix = bd.Wire([bd.Helix(pitch=5, height=40, radius=10, center=(0, 0, 5))])
    plane = bd.Plane(origin=helix @ 0, z_dir=helix % 0)
    triangle = plane * bd.RegularPolygon(1.5, 3).faces()[0]
    groove = rocp.sweep(helix, triangle, tolerance=1e-5, frame="frenet")
    theirs = bd.sweep(triangle, helix, is_frenet=True)
    poles = {"ours": 0, "theirs": 0}
    for name, shape in (("ours", groove), ("theirs", theirs)):
        for face in shape.faces():
            surface = BRep_Tool.Surface_s(face.wrapped)
            if not isinstance(surface, Geom_BSplineSurface):
                continue
            poles[name] += surface.NbUPoles() * surface.NbVPoles()
            if name == "ours":
                inner = [surface.VMultiplicity(i) for i in range(2, surface.NbVKnots())]
                assert surface.VDegree() == 7 and set(inner) == {1}, inner
    area = 0.75 * math.sqrt(3) * 1.5 ** 2
    exact = area * 8 * math.hypot(2 * math.pi * 10, 5)
    rod = bd.Cylinder(10, 50, align=(bd.Align.CENTER, bd.Align.CENTER, bd.Align.MIN))
    cut, reference = rod - groove, rod - theirs
    removed, expected = rod.volume - gk_volume(cut), rod.volume - gk_volume(reference)
    print("\nthread groove: poles %(ours)d (build123d's %(theirs)d)" % poles,
          "fixed-order volume off area x length by %.1e," % (groove.volume / exact - 1),
          "removed %.6f against build123d's %.6f" % (removed, expected))
    assert poles["ours"] < poles["theirs"]
    assert abs(groove.volume - exact) <= 1e-6 * exact
    assert rocp.is_valid(cut) and len(cut.solids()) == 1
    assert abs(removed - expected) <= 1e-5 * expected


def surface_area(surface, tolerance=1e-10):
    """OpenCascade's area of a library surface: one face per knot span of the
    Geom_BSplineSurface (BRepGProp.SurfaceProperties_s integrates a face across C0 knots
    with 4e-4 error on the transition below)."""
    import numpy as np
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps
    geometry, total = rocp.bspline_surface(surface), 0.0
    nurbs = surface.nurbs()
    us, vs = np.unique(nurbs.knots_u), np.unique(nurbs.knots_v)
    for u0, u1 in zip(us, us[1:]):
        for v0, v1 in zip(vs, vs[1:]):
            props = GProp_GProps()
            face = BRepBuilderAPI_MakeFace(geometry, u0, u1, v0, v1, 1e-7).Face()
            BRepGProp.SurfaceProperties_s(face, props, tolerance)
            total += props.Mass()
    return total


def test_a_transition_is_handed_over_as_a_solid_opencascade_takes_as_built():
    """A square-to-round transition from the library's B-rep text: valid as read, no free
    edge, and — the part being developable and cut along the normals — its volume the
    thickness times the area of the middle layer (OpenCascade's own integrals on both);
    booleans with a box are valid and partition it."""
    t = 2.0
    corners = [[-100, -100, 0], [100, -100, 0], [100, 100, 0], [-100, 100, 0]]
    bottom = rmfsurf.Curve.from_nurbs(1, corners + [corners[0]], [0, 0, 1, 2, 3, 4, 4])
    top = rmfsurf.circle(60.0, (20.0, 0.0, 150.0))
    part = rmfsurf.transition(bottom, top, thickness=t, k_factor=0.5, tolerance=1e-3)
    solid = bd.Solid(rocp.part_solid(part))
    assert rocp.is_valid(solid)
    assert free_edges(solid.wrapped) == 0
    middle = surface_area(part.layer("neutral"))
    volume = gk_volume(solid)
    assert abs(volume - t * middle) <= 1e-9 * volume
    # A box over y < −37 (off the symmetry plane, which holds the part's seam ruling): the
    # part inside and the rest, both valid, together the whole (OpenCascade integrates the
    # trimmed faces of the parts to about 1e-9).
    box = bd.Pos(0, -237, 0) * bd.Box(400, 400, 400)
    inside, rest = solid & box, solid - box
    assert rocp.is_valid(inside) and rocp.is_valid(rest)
    parts = gk_volume(inside) + gk_volume(rest)
    assert gk_volume(inside) > 0.1 * volume and abs(parts - volume) <= 1e-8 * volume


def test_a_profile_across_the_path_is_carried_rigidly_and_one_along_it_refused():
    path = pipe_route()
    # A disc in a plane at 45° to the path's start tangent (x): carried rigidly, it sweeps
    # cos 45° times the normal disc's volume (module src/wire/oblique.rs).
    tilted = bd.Plane(origin=path @ 0, z_dir=(1, 1, 0)) * bd.Circle(R)
    solid = rocp.sweep(path, tilted)
    assert rocp.is_valid(solid)
    expected = math.cos(math.pi / 4) * math.pi * R * R * path.length
    assert abs(gk_volume(solid) - expected) <= 1e-9 * expected
    along = bd.Plane(origin=path @ 0, z_dir=(0, 1, 0)) * bd.Circle(R)
    with pytest.raises(rmfsurf.InvalidInputError, match="contains the wire's start tangent"):
        rocp.sweep(path, along)


def self_intersects(shape):
    """OpenCascade's own verdict: BOPAlgo_ArgumentAnalyzer with its self-interference
    check on."""
    from OCP.BOPAlgo import BOPAlgo_ArgumentAnalyzer
    analyzer = BOPAlgo_ArgumentAnalyzer()
    analyzer.SetShape1(shape.wrapped)
    analyzer.SelfInterMode = True
    analyzer.Perform()
    return analyzer.HasFaulty()


def crossing_route(height):
    """Along x, up y, then back across the first leg `height` above it."""
    return bd.Polyline((0, 0, 0), (60, 0, 0), (60, 60, 0), (30, 60, height),
                       (30, -30, height))


@needs_wire_sweep
def test_a_route_crossing_itself_within_the_profile_is_refused():
    path = crossing_route(4.0)
    # The tubes of radius 3 overlap: OpenCascade's analyzer sees it in build123d's own sweep
    # (the check can fail), and rmfsurf refuses to make the solid.
    assert self_intersects(bd.sweep(ring(path, hole=False), path, transition=bd.Transition.ROUND))
    with pytest.raises(rmfsurf.InvalidInputError, match="intersects itself"):
        rocp.sweep(path, ring(path, hole=False))
    # 0.5 above the reach of the profile: a valid solid OpenCascade finds no fault in.
    path = crossing_route(6.5)
    pipe = rocp.sweep(path, ring(path, hole=False))
    assert rocp.is_valid(pipe)
    assert not self_intersects(pipe)
