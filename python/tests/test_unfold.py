"""Unfolding the user's faces: rmfsurf.ocp.unfold on build123d faces and the core API under
it (rmfsurf.Brep.create, developability, unfold_face). Each figure is checked against an
independent one and printed (pytest -s, `cargo test ... --test python -- --nocapture`):

  a. a plate with a round hole (a Box's top face cut by a Cylinder): kind plane, flat area
     against OpenCascade's area of the face, one hole as an inner wire;
  b. cylinders: a partial one (a Cylinder's wall cut by a Box, < 360°) and a full tube cut
     open along its seam: kind circular_cylinder, area, an outline of lines only;
  c. cones: a frustum, a whole cone to its apex and a cone with a window: kind right_cone,
     area;
  d. a general cylinder (an extruded wavy Spline): area against the spline's length ×
     height within 1e-5 at tolerance 1e-5, bend lines;
  e. a ruled B-spline developable (a general cone between a spline and its scaled copy)
     written to STEP and read back: unfolded, area against the re-read face's within the
     cone spline's fit;
  f. a sphere's face: not developable, with its stretch, and refused naming it;
  g. the DXF read back by this file's own parser: entity counts per layer and the cut
     length against the pattern's;
  h. marks: formed → flat → formed on points of the face;
  i. the plate scaled by 1e-3 and 1e3: areas scale by s²; every face of solids moved and
     turned (faces with a location) unfolds to its area;
  j. whole sheet bodies: an L bracket with a hole (its flat area = volume / thickness at
     k = 0.5, the hole an inner wire, one bend on its DXF layer, k = 0.3 and a table), the
     same through STEP, a conical sheet (a revolved parallelogram), a sheet swept along a
     wavy spline (and through STEP), a Box as a plate, a wedge refused.
Plus the core API on plain data, and the adapter's refusals."""

import math
import os

import numpy as np
import pytest

import rmfsurf

bd = pytest.importorskip("build123d")
rocp = pytest.importorskip("rmfsurf.ocp")
from OCP.BRep import BRep_Tool  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Surface  # noqa: E402
from OCP.BRepClass import BRepClass_FaceClassifier  # noqa: E402
from OCP.BRepCheck import BRepCheck_Analyzer  # noqa: E402
from OCP.BRepGProp import BRepGProp  # noqa: E402
from OCP.BRepTools import BRepTools  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402
from OCP.TopAbs import TopAbs_IN  # noqa: E402
from OCP.gp import gp_Pnt, gp_Pnt2d, gp_Vec  # noqa: E402

GAUSS_X, GAUSS_W = np.polynomial.legendre.leggauss(20)


def rel(a, b):
    return abs(a - b) / abs(b)


def occ_area(face, relative_error=None):
    """OpenCascade's area of a face (BRepGProp; adaptive to `relative_error` if given)."""
    props = GProp_GProps()
    if relative_error is None:
        BRepGProp.SurfaceProperties_s(face.wrapped, props)
    else:
        BRepGProp.SurfaceProperties_s(face.wrapped, props, relative_error)
    return props.Mass()


def spans(values):
    """Consecutive distinct values as intervals."""
    v = sorted(set(values))
    return list(zip(v, v[1:]))


def surface_area(face):
    """The area of an untrimmed B-spline face (bounded by its parameter domain): 20-point
    Gauss-Legendre on every knot span in u and v of |S_u × S_v|."""
    surface = BRep_Tool.Surface_s(face.wrapped)
    u0, u1, v0, v1 = BRepTools.UVBounds_s(face.wrapped)
    us = [u for u in [surface.UKnot(i) for i in range(1, surface.NbUKnots() + 1)]
          if u0 < u < u1] + [u0, u1]
    vs = [v for v in [surface.VKnot(i) for i in range(1, surface.NbVKnots() + 1)]
          if v0 < v < v1] + [v0, v1]
    p, du, dv = gp_Pnt(), gp_Vec(), gp_Vec()
    total = 0.0
    for a, b in spans(us):
        for c, d in spans(vs):
            for x, w in zip(GAUSS_X, GAUSS_W):
                for y, z in zip(GAUSS_X, GAUSS_W):
                    surface.D1(0.5 * (a + b + (b - a) * x), 0.5 * (c + d + (d - c) * y), p,
                               du, dv)
                    total += w * z * du.Crossed(dv).Magnitude() * 0.25 * (b - a) * (d - c)
    return total


def curve_length(edge):
    """The length of a B-spline edge: 20-point Gauss-Legendre on every knot span."""
    curve = BRep_Tool.Curve_s(edge.wrapped, 0.0, 0.0)
    knots = [curve.Knot(i) for i in range(1, curve.NbKnots() + 1)]
    p, d = gp_Pnt(), gp_Vec()
    total = 0.0
    for a, b in spans(knots):
        for x, w in zip(GAUSS_X, GAUSS_W):
            curve.D1(0.5 * (a + b + (b - a) * x), p, d)
            total += w * d.Magnitude() * 0.5 * (b - a)
    return total


def is_valid(shape):
    return BRepCheck_Analyzer(shape.wrapped).IsValid()


def check_flat_face(pattern, holes):
    """The pattern's face: a valid build123d Face in z = 0, its area the library's, `holes`
    inner wires, lines and circles only."""
    face = pattern.face
    assert isinstance(face, bd.Face), type(face)
    assert is_valid(face)
    box = face.bounding_box()
    assert max(abs(box.min.Z), abs(box.max.Z)) <= 1e-12 * max(1.0, box.diagonal)
    assert len(face.inner_wires()) == holes
    assert {e.geom_type for e in face.edges()} <= {bd.GeomType.LINE, bd.GeomType.CIRCLE}
    assert rel(occ_area(face), pattern.area) <= 1e-9, (occ_area(face), pattern.area)


# ---------------------------------------------------------------------------------------
# Inputs


def plate(scale=1.0):
    """The top face of a 40 × 30 × 2 plate with a round hole of radius 5."""
    part = bd.Box(40, 30, 2) - bd.Pos(4, -3, 0) * bd.Cylinder(5, 10)
    top = part.faces().sort_by(bd.Axis.Z)[-1]
    return top if scale == 1.0 else top.scale(scale)


def cylinder_faces():
    """(a partial cylinder wall: a Cylinder's wall cut by a Box, < 360°; a full tube)."""
    cylinder = bd.Cylinder(6, 20)
    cut = cylinder - bd.Pos(6, 6, 0) * bd.Box(12, 12, 30)
    partial = cut.faces().filter_by(bd.GeomType.CYLINDER)
    assert len(partial) == 1
    return partial[0], cylinder.faces().filter_by(bd.GeomType.CYLINDER)[0]


def cone_faces():
    """(a frustum's lateral face, a whole cone's to its apex, a frustum's with a window
    bounded by two parallel circles and two rulings)."""
    frustum = bd.Cone(10, 4, 20)
    whole = bd.Cone(5, 0, 8)
    sector = bd.Pos(0, 0, -1) * bd.Cylinder(30, 6, arc_size=50, align=bd.Align.MIN)
    windowed = frustum - bd.Rot(0, 0, 100) * sector
    faces = [shape.faces().filter_by(bd.GeomType.CONE) for shape in (frustum, whole, windowed)]
    assert [len(f) for f in faces] == [1, 1, 1]
    return [f[0] for f in faces]


WAVE = [(0, 0, 0), (10, 6, 0), (20, -6, 0), (30, 6, 0), (40, 0, 0)]
WAVE_HEIGHT = 15.0


def wave():
    """A wavy spline extruded along z: a general cylinder."""
    return bd.Face.extrude(bd.Spline(*WAVE), bd.Vector(0, 0, WAVE_HEIGHT))


# ---------------------------------------------------------------------------------------
# a. A plate with a round hole


def test_a_plate_with_a_round_hole_unfolds_to_itself():
    top = plate()
    pattern = rocp.unfold(top)
    area = occ_area(top)
    print("\na. plate: kind %s, flat area %.15g, OpenCascade %.15g, relative %.1e; "
          "%d hole(s), outline %s, hole %s"
          % (pattern.report.kind, pattern.area, area, rel(pattern.area, area),
             len(pattern.unfolded.holes), [e.kind for e in pattern.unfolded.outline],
             [e.kind for e in pattern.unfolded.holes[0]]))
    assert pattern.report.kind == "plane"
    assert rel(pattern.area, area) <= 1e-9
    assert rel(pattern.area, 40 * 30 - math.pi * 25) <= 1e-12
    assert len(pattern.unfolded.holes) == 1
    assert {e.kind for e in pattern.unfolded.holes[0]} == {"arc"}
    assert pattern.bend_lines == [] and pattern.report.fit_error == 0.0
    check_flat_face(pattern, holes=1)


# ---------------------------------------------------------------------------------------
# b. Cylinders


def test_a_partial_cylinder_and_a_full_tube_unfold_to_rectangles():
    partial, tube = cylinder_faces()
    for name, face, angle in (("partial cylinder (270°)", partial, 1.5 * math.pi),
                              ("full tube, cut at its seam", tube, 2 * math.pi)):
        pattern = rocp.unfold(face)
        area = occ_area(face)
        kinds = [e.kind for e in pattern.unfolded.outline]
        print("\nb. %s: kind %s, flat area %.15g, OpenCascade %.15g, relative %.1e, "
              "closed form %.15g; outline %s"
              % (name, pattern.report.kind, pattern.area, area, rel(pattern.area, area),
                 6 * angle * 20, kinds))
        assert pattern.report.kind == "circular_cylinder"
        assert rel(pattern.area, area) <= 1e-9
        assert rel(pattern.area, 6 * angle * 20) <= 1e-12
        assert set(kinds) == {"line"}
        check_flat_face(pattern, holes=0)


# ---------------------------------------------------------------------------------------
# c. Cones


def test_cones_unfold_to_annular_sectors():
    frustum, whole, windowed = cone_faces()
    slant = math.hypot(6, 20)
    for name, face, exact, holes in (
            ("frustum", frustum, math.pi * (10 + 4) * slant, 0),
            ("whole cone to its apex", whole, math.pi * 5 * math.hypot(5, 8), 0),
            ("frustum with a window", windowed, None, 1)):
        pattern = rocp.unfold(face)
        area = occ_area(face)
        print("\nc. %s: kind %s, flat area %.15g, OpenCascade %.15g, relative %.1e%s; "
              "outline %s, holes %s"
              % (name, pattern.report.kind, pattern.area, area, rel(pattern.area, area),
                 "" if exact is None else ", closed form %.15g" % exact,
                 [e.kind for e in pattern.unfolded.outline],
                 [[e.kind for e in h] for h in pattern.unfolded.holes]))
        assert pattern.report.kind == "right_cone"
        assert rel(pattern.area, area) <= 1e-9
        if exact is not None:
            assert rel(pattern.area, exact) <= 1e-12
        assert len(pattern.unfolded.holes) == holes
        check_flat_face(pattern, holes=holes)
    # The window: two arcs (parallel circles) and two lines (rulings).
    hole = rocp.unfold(windowed).unfolded.holes[0]
    assert sorted(e.kind for e in hole) == ["arc", "arc", "line", "line"]


# ---------------------------------------------------------------------------------------
# d. A general cylinder


def test_an_extruded_spline_unfolds_through_its_cone_spline():
    face = wave()
    pattern = rocp.unfold(face, tolerance=1e-5)
    exact = curve_length(bd.Spline(*WAVE)) * WAVE_HEIGHT
    occ = occ_area(face)
    print("\nd. extruded spline: kind %s, flat area %.12g, length × height %.12g, "
          "relative %.1e (limit 1e-5); fit error %.2e; %d bend lines; OpenCascade's "
          "BRepGProp area %.12g (relative %.1e: its fixed-order rule is off on this "
          "extrusion)"
          % (pattern.report.kind, pattern.area, exact, rel(pattern.area, exact),
             pattern.report.fit_error, len(pattern.bend_lines), occ, rel(occ, exact)))
    assert pattern.report.kind == "general_cylinder"
    assert rel(pattern.area, exact) <= 1e-5
    assert 0 < pattern.report.fit_error <= 1e-5
    assert len(pattern.bend_lines) > 0
    assert all(isinstance(e, bd.Edge) and e.geom_type == bd.GeomType.LINE
               for e in pattern.bend_lines)
    # A cross-section of a cylinder develops into a line: the outline is a rectangle.
    assert [e.kind for e in pattern.unfolded.outline] == ["line"] * 4
    check_flat_face(pattern, holes=0)


# ---------------------------------------------------------------------------------------
# e. A B-spline developable through STEP


def test_a_ruled_developable_read_back_from_step_unfolds(tmp_path):
    # A general cone: a wavy spline at z = -30 and its copy scaled by 0.6 about the apex
    # (the origin), joined by rulings through the apex.
    base = bd.Spline((-20, -10, -30), (-5, 5, -30), (10, -5, -30), (25, 8, -30))
    top = base.scale(0.6)
    ruled = bd.Face.make_surface_from_curves(base, top)
    path = os.path.join(str(tmp_path), "ruled.step")
    bd.export_step(ruled, path)
    read = bd.import_step(path)
    faces = read.faces()
    assert len(faces) == 1
    face = faces[0]
    kind = rocp.developability(face)
    pattern = rocp.unfold(face, tolerance=1e-5)
    area = surface_area(face)
    # The cone spline is within the fit error of the face: the pattern's area moves by at
    # most about fit error × boundary length.
    limit = 2 * pattern.report.fit_error * pattern.unfolded.cut_length / area + 1e-9
    print("\ne. ruled developable read back from STEP: %s, kind %s (curvature %.1e), "
          "flat area %.12g, the face's %.12g (Gauss on its spans), relative %.1e (limit "
          "%.1e: fit error %.1e × cut length %.4g), %d bend lines, OpenCascade %.12g"
          % (os.path.basename(path), pattern.report.kind, kind.curvature, pattern.area,
             area, rel(pattern.area, area), limit, pattern.report.fit_error,
             pattern.unfolded.cut_length, len(pattern.bend_lines), occ_area(face, 1e-10)))
    assert kind.developable and kind.kind == pattern.report.kind
    assert pattern.report.kind == "general_cone"
    assert rel(pattern.area, area) <= limit
    assert len(pattern.bend_lines) > 0
    check_flat_face(pattern, holes=0)


# ---------------------------------------------------------------------------------------
# f. Not developable


def test_a_sphere_face_is_not_developable_and_is_refused():
    ball = bd.Sphere(5).faces()[0]
    report = rocp.developability(ball)
    print("\nf. sphere face: kind %s, |K|·size² %.3g, stretch %.3g"
          % (report.kind, report.curvature, report.stretch))
    assert report.kind == "not_developable" and not report.developable
    assert report.stretch > 0 and report.curvature > 1
    with pytest.raises(rmfsurf.InvalidInputError) as refused:
        rocp.unfold(ball)
    print("   refused: %s" % refused.value)
    assert "not developable" in str(refused.value)
    assert refused.value.function == "rmf_unfold_face"


# ---------------------------------------------------------------------------------------
# g. The DXF read back


def read_dxf(path):
    """The LINE and ARC entities of a DXF file (this file's own reader): dicts of their
    group codes, type and layer."""
    with open(path) as f:
        lines = [line.strip() for line in f]
    entities, current, in_entities = [], None, False
    for code, value in zip(lines[0::2], lines[1::2]):
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
    return [e for e in entities if e["type"] not in ("SECTION",)]


def entity_length(entity):
    g = lambda code: float(entity[code])  # noqa: E731
    if entity["type"] == "LINE":
        return math.hypot(g("11") - g("10"), g("21") - g("20"))
    assert entity["type"] == "ARC", entity
    sweep = (g("51") - g("50")) % 360.0
    return g("40") * math.radians(sweep if sweep > 0 else 360.0)


def test_the_dxf_reads_back_with_the_patterns_entities_and_cut_length(tmp_path):
    for name, face, tolerance in (("plate", plate(), 1e-4),
                                  ("cone with a window", cone_faces()[2], 1e-4),
                                  ("extruded spline", wave(), 1e-5)):
        pattern = rocp.unfold(face, tolerance=tolerance)
        path = tmp_path / ("%s.dxf" % name.replace(" ", "_"))
        pattern.write_dxf(path)
        entities = read_dxf(path)
        layers = {}
        for e in entities:
            layers.setdefault(e.get("8"), []).append(e)
        u = pattern.unfolded
        cut_edges = len(u.outline) + sum(len(h) for h in u.holes)
        cut = sum(entity_length(e) for e in layers.get("CUT", []))
        arcs = sum(e["type"] == "ARC" for e in entities)
        print("\ng. %s DXF: %d CUT entities (%d ARC), %d BEND; cut length %.15g, the "
              "pattern's %.15g, relative %.1e"
              % (name, len(layers.get("CUT", [])), arcs, len(layers.get("BEND", [])), cut,
                 u.cut_length, rel(cut, u.cut_length)))
        assert {e["type"] for e in entities} <= {"LINE", "ARC"}
        assert set(layers) <= {"CUT", "BEND"}
        assert len(layers["CUT"]) == cut_edges
        assert len(layers.get("BEND", [])) == len(u.bend_lines)
        assert arcs == sum(e.kind == "arc" for loop in [u.outline] + u.holes for e in loop)
        assert rel(cut, u.cut_length) <= 1e-9
        with open(path) as f:
            assert f.read() == u.dxf()


# ---------------------------------------------------------------------------------------
# h. Marks both ways


def face_points(face, count=7):
    """Points of a face inside it (its surface at a grid of its parameters, those the face
    classifies as in)."""
    u0, u1, v0, v1 = BRepTools.UVBounds_s(face.wrapped)
    surface = BRepAdaptor_Surface(face.wrapped)
    points = []
    for i in range(1, count + 1):
        for j in range(1, count + 1):
            u, v = u0 + (u1 - u0) * i / (count + 1), v0 + (v1 - v0) * j / (count + 1)
            if BRepClass_FaceClassifier(face.wrapped, gp_Pnt2d(u, v), 1e-9).State() == TopAbs_IN:
                points.append(surface.Value(u, v).Coord())
    return np.array(points)


def test_marks_go_formed_to_flat_and_back():
    partial, tube = cylinder_faces()
    frustum, _, windowed = cone_faces()
    for name, face in (("plate", plate()), ("partial cylinder", partial), ("tube", tube),
                       ("frustum", frustum), ("cone with a window", windowed)):
        u = rocp.unfold(face).unfolded
        points = face_points(face)
        flat = u.to_flat(points)
        back = u.to_formed(flat)
        size = face.bounding_box().diagonal
        worst = float(np.max(np.linalg.norm(back - points, axis=1)))
        print("\nh. %s: %d points formed → flat → formed within %.1e (size %.3g, limit "
              "%.1e)" % (name, len(points), worst, size, 1e-9 * size))
        assert len(points) >= 20
        assert worst <= 1e-9 * size
        # Flat points fall inside the flat face.
        flat_face = rocp.flat_face(u)
        for q in flat:
            state = BRepClass_FaceClassifier(flat_face, gp_Pnt(q[0], q[1], 0.0), 1e-7).State()
            assert state == TopAbs_IN, (name, q)
        if name == "plate":  # a plane's unrolling is a rigid motion: distances stay
            formed = np.linalg.norm(points[:, None] - points[None], axis=2)
            developed = np.linalg.norm(flat[:, None] - flat[None], axis=2)
            assert np.max(np.abs(formed - developed)) <= 1e-12 * size


# ---------------------------------------------------------------------------------------
# i. Scaling


def test_the_plates_area_scales_by_the_square():
    unit = rocp.unfold(plate()).area
    for s in (1e-3, 1e3):
        scaled = rocp.unfold(plate(s), tolerance=1e-4 * s).area
        ratio = scaled / unit / (s * s)
        print("\ni. plate scaled by %g: flat area %.15g, ratio to s² × unit %.17g "
              "(relative %.1e)" % (s, scaled, ratio, abs(ratio - 1)))
        assert abs(ratio - 1) <= 1e-12


def test_every_face_of_moved_and_turned_solids_unfolds_to_its_area():
    """Faces carrying a location (build123d's moved shapes): every face of a cylinder, a
    frustum and the holed plate, moved and turned."""
    where = bd.Location((5, 6, 7), (30, 40, 50))
    worst, kinds = 0.0, set()
    for solid in (bd.Cylinder(3, 10), bd.Cone(10, 4, 20),
                  bd.Box(40, 30, 2) - bd.Pos(4, -3, 0) * bd.Cylinder(5, 10)):
        for face in solid.moved(where).faces():
            pattern = rocp.unfold(face)
            kinds.add(pattern.report.kind)
            worst = max(worst, rel(pattern.area, occ_area(face)))
    print("\ni. every face of three moved and turned solids (%s): flat areas against "
          "OpenCascade's within %.1e" % (", ".join(sorted(kinds)), worst))
    assert kinds == {"plane", "circular_cylinder", "right_cone"}
    assert worst <= 1e-9


# ---------------------------------------------------------------------------------------
# The core API on plain data and the adapter's refusals


def square_hole_plate():
    corners = [(0, 0, 0), (4, 0, 0), (4, 3, 0), (0, 3, 0),
               (1, 1, 0), (2, 1, 0), (2, 2, 0), (1, 2, 0)]
    line = rmfsurf.line_curve
    edges = [rmfsurf.BrepEdge(line(corners[i], corners[j]), i, j)
             for i, j in [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4)]]
    face = rmfsurf.BrepFace([[(0, True), (1, True), (2, True), (3, True)],
                             [(7, False), (6, False), (5, False), (4, False)]],
                            plane=((0, 0, 0), (0, 0, 1), (1, 0, 0)))
    return rmfsurf.Brep.create(corners, edges, [face])


def test_the_core_api_unfolds_plain_data():
    brep = square_hole_plate()
    report = rmfsurf.developability(brep)
    u = rmfsurf.unfold_face(brep, 0)
    print("\ncore: %s; area %.15g (exact 11); outline %d lines, hole %d lines"
          % (report, u.area, len(u.outline), len(u.holes[0])))
    assert report.kind == "plane" and report.curvature == 0 and report.stretch == 0
    assert u.report.kind == "plane" and abs(u.area - 11.0) <= 1e-14
    assert [e.kind for e in u.outline] == ["line"] * 4 and len(u.holes) == 1
    assert all(e.layer == "cut" for e in u.outline + u.holes[0])
    # The outline counter-clockwise, the hole clockwise.
    signed = lambda loop: sum(e.start[0] * e.end[1] - e.end[0] * e.start[1]  # noqa: E731
                              for e in loop) / 2
    assert signed(u.outline) > 0 > signed(u.holes[0])
    assert u.cut_length == pytest.approx(18.0, rel=1e-15)
    text = u.dxf()
    assert text.startswith("0\nSECTION\n") and text.rstrip().endswith("EOF")
    q = u.to_flat([[1.5, 0.5, 0.0]])
    assert q.shape == (1, 2) and np.allclose(u.to_formed(q), [[1.5, 0.5, 0.0]], rtol=0, atol=1e-15)
    assert rmfsurf.live_handles().get("brep", 0) >= 1


def test_the_core_api_refuses_bad_data_with_the_librarys_message():
    brep = square_hole_plate()
    with pytest.raises(rmfsurf.InvalidInputError) as e:
        rmfsurf.unfold_face(brep, 3)
    assert "face = 3 is out of range" in str(e.value)
    with pytest.raises(rmfsurf.InvalidInputError) as e:
        rmfsurf.Brep.create([(0, 0, 0)], [rmfsurf.BrepEdge(
            rmfsurf.line_curve((0, 0, 0), (1, 0, 0)), 0, 5)],
            [rmfsurf.BrepFace([[(0, True)]], plane=((0, 0, 0), (0, 0, 1), (1, 0, 0)))])
    assert str(e.value).startswith("rmf_brep_create: edges[0].end = 5")
    # A loop that does not close.
    edges = [rmfsurf.BrepEdge(rmfsurf.line_curve((0, 0, 0), (1, 0, 0)), 0, 1),
             rmfsurf.BrepEdge(rmfsurf.line_curve((1, 0, 0), (1, 1, 0)), 1, 2)]
    open_loop = rmfsurf.Brep.create([(0, 0, 0), (1, 0, 0), (1, 1, 0)], edges, [
        rmfsurf.BrepFace([[(0, True), (1, True)]], plane=((0, 0, 0), (0, 0, 1), (1, 0, 0)))])
    with pytest.raises(rmfsurf.InvalidInputError) as e:
        rmfsurf.unfold_face(open_loop)
    assert "is not closed" in str(e.value)
    with pytest.raises(rmfsurf.InvalidInputError) as e:
        rmfsurf.unfold_face(brep, tolerance=0.0)
    assert "tolerance" in str(e.value)


def test_the_adapter_refuses_bad_shapes_and_k_factors():
    # Two faces that are not a solid: neither one face nor a sheet body.
    shell = bd.Compound(children=list(bd.Box(1, 2, 3).faces()[:2]))
    with pytest.raises(ValueError) as e:
        rocp.unfold(shell)
    print("\nrefusals: %s" % e.value)
    assert "holds 2 faces" in str(e.value)
    for k in (-0.1, 1.5):
        with pytest.raises(ValueError) as e:
            rocp.unfold(plate(), k_factor=k)
        assert str(e.value).startswith("k_factor:")
    with pytest.raises(TypeError):
        rocp.unfold(3)
    # The K-factor does not change one face's pattern.
    assert rocp.unfold(plate(), k_factor=0.0).area == rocp.unfold(plate(), k_factor=1.0).area


def bracket(hole=True):
    """An L bracket of sheet 1 thick and 4 wide: flanges of 10 joined by a quarter bend of
    inner radius 2.5, a round hole of radius 0.8 through the first flange."""
    with bd.BuildSketch() as section:
        with bd.BuildLine():
            bd.Polyline((0, -0.5), (10, -0.5))
            bd.CenterArc((10, 3), 3.5, 270, 90)
            bd.Polyline((13.5, 3), (13.5, 13), (12.5, 13), (12.5, 3))
            bd.CenterArc((10, 3), 2.5, 0, -90)
            bd.Polyline((10, 0.5), (0, 0.5), (0, -0.5))
        bd.make_face()
    part = bd.extrude(section.sketch, amount=4)
    if hole:
        part = part - bd.Pos(5, 0, 2) * bd.Rot(90, 0, 0) * bd.Cylinder(0.8, 5)
    return part


def occ_volume(shape):
    """OpenCascade's volume of a solid, adaptive to 1e-9 relative (its fixed-order default
    is 2e-3 off on the B-spline skins of a swept sheet)."""
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape.wrapped, props, 1e-9)
    return props.Mass()


def test_an_l_bracket_with_a_hole_unfolds_to_its_volume_over_its_thickness(tmp_path):
    part = bracket()
    volume = occ_volume(part)
    pattern = rocp.unfold(part, tolerance=1e-6)
    print("\nL bracket: thickness %.15g, flat area %.15g, volume / thickness %.15g (%.1e), "
          "%d bends, %d holes" % (pattern.thickness, pattern.area, volume, rel(pattern.area, volume),
                                   len(pattern.bends), len(pattern.unfolded.holes)))
    assert abs(pattern.thickness - 1.0) <= 1e-9
    assert rel(pattern.area, volume / pattern.thickness) <= 1e-9
    assert len(pattern.bends) == 1 and len(pattern.unfolded.holes) == 1
    bend = pattern.bends[0]
    assert abs(bend.radius - 2.5) <= 1e-9 and bend.k_factor == 0.5
    assert isinstance(pattern.face, bd.Face) and is_valid(pattern.face)
    assert len(pattern.face.inner_wires()) == 1
    assert rel(pattern.face.area, pattern.area) <= 1e-9
    # At k = 0.3 the neutral layer lies 0.3 from the inner face: the bend's flat length
    # is π/2 · 2.8 instead of π/2 · 3.
    at_k = rocp.unfold(part, k_factor=0.3, tolerance=1e-6)
    expected = 4 * (20 + math.pi / 2 * 2.8) - math.pi * 0.8 ** 2
    print("L bracket at k = 0.3: flat area %.15g (%.15g, %.1e)" % (at_k.area, expected,
                                                                   rel(at_k.area, expected)))
    assert rel(at_k.area, expected) <= 1e-9
    table = rocp.unfold(part, k_factor=[(1.0, 0.3), (3.0, 0.5)], tolerance=1e-6)
    assert abs(table.bends[0].k_factor - 0.45) <= 1e-12
    path = tmp_path / "bracket.dxf"
    pattern.write_dxf(path)
    layers = [e["8"] for e in read_dxf(path)]
    assert layers.count("BEND_UP") + layers.count("BEND_DOWN") == 1
    cut = sum(entity_length(e) for e in read_dxf(path) if e["8"] == "CUT")
    assert rel(cut, pattern.unfolded.cut_length) <= 1e-9
    # Marks: a point of the flange's outer skin, flat and back on the neutral layer; one of
    # the other flange, the same; the hole's centre is in no part of the sheet.
    for skin, neutral in [([3.0, -0.5, 1.0], [3.0, 0.0, 1.0]), ([13.5, 8.0, 3.0], [13.0, 8.0, 3.0])]:
        formed = pattern.unfolded.to_formed(pattern.unfolded.to_flat([skin]))
        assert np.linalg.norm(formed[0] - neutral) <= 1e-9, (skin, formed)
    with pytest.raises(rmfsurf.InvalidInputError):
        pattern.unfolded.to_formed(pattern.unfolded.to_flat([[5.0, -0.5, 2.0]]))


def test_an_l_bracket_read_back_from_step_unfolds_alike(tmp_path):
    path = str(tmp_path / "bracket.step")
    part = bracket()
    bd.export_step(part, path)
    again = bd.import_step(path)
    area = rocp.unfold(again, tolerance=1e-6).area
    print("\nL bracket through STEP: flat area %.15g (%.1e from before)"
          % (area, rel(area, rocp.unfold(part, tolerance=1e-6).area)))
    assert rel(area, rocp.unfold(part, tolerance=1e-6).area) <= 1e-9


def test_a_box_is_a_plate_and_a_wedge_is_refused():
    plate_body = rocp.unfold(bd.Box(20, 30, 1))
    assert abs(plate_body.thickness - 1.0) <= 1e-12 and rel(plate_body.area, 600.0) <= 1e-12
    assert not plate_body.bends
    wedge = bd.extrude(bd.Polygon((0, 0), (10, 0), (10, 1.2), (0, 1.0), align=None), amount=5)
    with pytest.raises(rmfsurf.InvalidInputError) as e:
        rocp.unfold(wedge)
    print("\nwedge: %s" % e.value)
    assert "thickness is not constant" in str(e.value)


def test_an_ocp_face_gives_an_ocp_pattern():
    top = plate()
    pattern = rocp.unfold(top.wrapped)
    from OCP.TopoDS import TopoDS_Face
    assert isinstance(pattern.face, TopoDS_Face)
    assert rel(pattern.area, occ_area(top)) <= 1e-9


def conical_sheet():
    """A conical sheet 1 thick: the parallelogram across the cone's generator from (10, 0) to
    (6, 12) revolved 270° about z — inner and outer skins coaxial cones of one half angle."""
    a, b = np.array([10.0, 0.0]), np.array([6.0, 12.0])
    d = (b - a) / np.linalg.norm(b - a)
    n = np.array([d[1], -d[0]])  # away from the axis
    corners = [a, a + n, b + n, b]
    with bd.BuildSketch(bd.Plane.XZ) as section:
        bd.Polygon(*[tuple(p) for p in corners], align=None)
    return bd.revolve(section.sketch, bd.Axis.Z, 270)


def test_a_conical_sheet_body_unfolds_to_its_volume_over_its_thickness():
    part = conical_sheet()
    pattern = rocp.unfold(part, tolerance=1e-6)
    volume = occ_volume(part)
    print("\nconical sheet: thickness %.15g, flat area %.15g, volume / thickness %.15g (%.1e), "
          "%d bends (%s)" % (pattern.thickness, pattern.area, volume / pattern.thickness,
                             rel(pattern.area, volume / pattern.thickness), len(pattern.bends),
                             ["up" if b.up else "down" for b in pattern.bends]))
    assert abs(pattern.thickness - 1.0) <= 1e-9
    assert rel(pattern.area, volume) <= 1e-9
    assert len(pattern.bends) == 1 and is_valid(pattern.face)



def test_a_sheet_swept_along_a_wavy_spline_unfolds_through_its_cone_splines(tmp_path):
    # A strip 0.5 thick and 3 high swept along a wavy spline by rmfsurf.ocp.sweep: its skins
    # are general cylinders (exact offsets of the sweep's spine), handed back through
    # OpenCascade and STEP.
    path = bd.Spline((0, 0, 0), (10, 6, 0), (20, -6, 0), (30, 6, 0), (40, 0, 0))
    start, tangent = path @ 0, path % 0
    plane = bd.Plane(origin=start, x_dir=bd.Vector(0, 0, 1).cross(tangent), z_dir=tangent)
    profile = plane * bd.Rectangle(0.5, 3, align=(bd.Align.CENTER, bd.Align.MIN))
    part = rocp.sweep(path, profile.face(), tolerance=1e-6)
    pattern = rocp.unfold(part, tolerance=1e-5)
    volume = occ_volume(part)
    print("\nwave sheet (swept): thickness %.9g, flat area %.9g, volume / thickness %.9g "
          "(%.1e), %d bend lines" % (pattern.thickness, pattern.area, volume / 0.5,
                                     rel(pattern.area, volume / 0.5), len(pattern.bend_lines)))
    assert abs(pattern.thickness - 0.5) <= 1e-5
    assert rel(pattern.area, volume / 0.5) <= 1e-5
    step = str(tmp_path / "wave.step")
    bd.export_step(part, step)
    again = rocp.unfold(bd.import_step(step), tolerance=1e-5)
    print("wave sheet through STEP: flat area %.9g (%.1e from before)"
          % (again.area, rel(again.area, pattern.area)))
    assert rel(again.area, pattern.area) <= 1e-6
