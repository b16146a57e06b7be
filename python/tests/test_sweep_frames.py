"""The frame and the scale law of wire sweeps through the package and rmfsurf.ocp:
`frame` ("rmf", "frenet", ("fixed", d) / {"fixed": d}), `scale` (start, end) and
`scale_knots` change nothing when left at their defaults; a circle scaled from 1 to 1/2
along a line is the frustum π L (r0² + r0 r1 + r1²)/3 by OpenCascade's integration, and
through knots the chain of frustums; a small triangle swept
along a helix with the Frenet frame has helices of the helix's axis and pitch for edges,
and its solid cuts a thread into a rod. (The last two need the geometry of the frame and
scale law; the bad arguments are in test_arguments.py.)"""

import math

import numpy as np
import pytest

import rmfsurf

bd = pytest.importorskip("build123d")
rocp = pytest.importorskip("rmfsurf.ocp")
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402
from OCP.BRepCheck import BRepCheck_Analyzer  # noqa: E402
from OCP.BRepGProp import BRepGProp  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.TopoDS import TopoDS  # noqa: E402

LINE = [rmfsurf.Line((0, 0, 0), (3, 0, 0))]


def test_the_defaults_are_the_rmf_and_no_scale():
    profile = rmfsurf.circle(1.0)
    plain = rmfsurf.wire_sweep(LINE, profile)
    given = rmfsurf.wire_sweep(LINE, profile, frame="rmf", scale=(1.0, 1.0))
    assert plain.occ_brep() == given.occ_brep()
    assert plain.report() == given.report()
    assert plain.report().frame_error == 0.0


def test_each_form_of_a_frame_is_taken():
    profile = rmfsurf.circle(1.0)
    for frame in ["rmf", "frenet", ("fixed", (0, 0, 1)), {"fixed": [0.0, 1.0, 1.0]},
                  ("fixed", np.array([0.0, 0.0, 2.0]))]:
        shape = rmfsurf.wire_sweep(LINE, profile, frame=frame, scale=[1, 1])
        assert shape.is_solid, frame
        assert 0.0 <= shape.report().frame_error <= 1e-9, frame


def test_an_initial_normal_goes_with_the_rmf_only():
    with pytest.raises(rmfsurf.InvalidInputError, match="initial_normal"):
        rmfsurf.wire_sweep(LINE, rmfsurf.circle(1.0), frame="frenet", initial_normal=(0, 0, 1))


def occ_volume(solid):
    """OpenCascade's volume: BRepGProp's adaptive Gauss-Kronrod integration to 1e-12
    (VolumePropertiesGK_s; VolumeProperties_s with eps 1e-12 stops at 7e-10 relative on
    the cylinder of the same sweep without scale)."""
    props = GProp_GProps()
    BRepGProp.VolumePropertiesGK_s(getattr(solid, "wrapped", solid), props, 1e-12)
    return props.Mass()


def is_valid(shape):
    return BRepCheck_Analyzer(getattr(shape, "wrapped", shape)).IsValid()


@pytest.mark.parametrize("frame", ["rmf", "frenet", ("fixed", (0, 0, 1))])
def test_a_circle_scaled_along_a_line_is_a_frustum(frame):
    r0, r1, length = 1.0, 0.5, 3.0
    path = bd.Line((0, 0, 0), (length, 0, 0))
    profile = bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0)) * bd.Circle(r0)
    solid = rocp.sweep(path, profile, frame=frame, scale=(1.0, r1 / r0))
    exact = math.pi * length * (r0 * r0 + r0 * r1 + r1 * r1) / 3
    volume = occ_volume(solid)
    print("\nfrustum, frame %r: volume %.15f vs %.15f (relative %.1e)"
          % (frame, volume, exact, abs(volume - exact) / exact))
    assert is_valid(solid)
    assert abs(volume - exact) <= 1e-9 * exact


def frustum_chain(r, length, start, knots, end):
    """π r² Σ Lᵢ (aᵢ² + aᵢbᵢ + bᵢ²)/3: the volume of a circle of radius r scaled piecewise
    linearly from `start` through the (fraction, scale) `knots` to `end` along a line."""
    points = [(0.0, start)] + list(knots) + [(1.0, end)]
    return sum(math.pi * r * r * length * (f1 - f0) * (a * a + a * b + b * b) / 3
               for (f0, a), (f1, b) in zip(points, points[1:]))


@pytest.mark.parametrize("scale, knots", [((1.0, 1.0), [(0.25, 2.0), (0.75, 0.5)]),
                                          ((0.5, 1.5), [(0.4, 1.0)])])
def test_a_circle_scaled_through_knots_along_a_line_is_a_chain_of_frustums(scale, knots):
    r, length = 1.0, 3.0
    path = bd.Line((0, 0, 0), (length, 0, 0))
    profile = bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0)) * bd.Circle(r)
    solid = rocp.sweep(path, profile, scale=scale, scale_knots=knots)
    exact = frustum_chain(r, length, scale[0], knots, scale[1])
    volume = occ_volume(solid)
    print("\nchain of frustums, scale %r through %r: volume %.15f vs %.15f (relative %.1e)"
          % (scale, knots, volume, exact, abs(volume - exact) / exact))
    assert is_valid(solid)
    assert abs(volume - exact) <= 1e-9 * exact
    # Without the knots the law is linear from start to end: another volume.
    plain = frustum_chain(r, length, scale[0], [], scale[1])
    assert abs(occ_volume(rocp.sweep(path, profile, scale=scale)) - plain) <= 1e-9 * plain
    assert abs(plain - exact) > 0.1


def test_knots_are_taken_as_any_sequence_of_pairs_and_none_is_no_knots():
    profile = rmfsurf.circle(1.0)
    plain = rmfsurf.wire_sweep(LINE, profile).occ_brep()
    assert rmfsurf.wire_sweep(LINE, profile, scale_knots=None).occ_brep() == plain
    assert rmfsurf.wire_sweep(LINE, profile, scale_knots=[]).occ_brep() == plain
    listed = rmfsurf.wire_sweep(LINE, profile, scale_knots=[(0.25, 2.0), (0.75, 0.5)])
    array = rmfsurf.wire_sweep(LINE, profile, scale_knots=np.array([[0.25, 2], [0.75, 0.5]]))
    assert listed.occ_brep() == array.occ_brep() != plain
    # With an exact-RMF method a knot that makes the law non-constant is refused, named.
    with pytest.raises(rmfsurf.InvalidInputError, match=r"scale_knots.*method = 2"):
        rmfsurf.wire_sweep(LINE, profile, scale_knots=[(0.5, 2.0)], method="mobius")


PITCH, HEIGHT, RADIUS = 3.0, 6.0, 5.0
#: The triangle in the normal plane at the helix's start: (radial, along the normal plane's
#: second axis) offsets from the helix; its tip points at the axis.
TRIANGLE = [(0.4, -0.3), (0.4, 0.3), (-0.4, 0.0)]


def helix_and_thread():
    """The helix (axis z through the origin, start (RADIUS, 0, 0)) and the triangle there in
    its normal plane, swept with the Frenet frame."""
    helix = bd.Wire([bd.Helix(pitch=PITCH, height=HEIGHT, radius=RADIUS)])
    start, tangent = np.array(tuple(helix @ 0)), np.array(tuple(helix % 0))
    radial = np.array([start[0], start[1], 0.0]) / np.hypot(start[0], start[1])
    other = np.cross(tangent, radial)
    corners = [tuple(start + a * radial + b * other) for a, b in TRIANGLE]
    triangle = bd.Face(bd.Wire.make_polygon(corners, close=True))
    thread = rocp.sweep(helix, triangle, frame="frenet", tolerance=1e-6)
    return helix, thread, corners


def lateral_edges(shape, path):
    """The edges of `shape` that do not lie in the normal plane at either end of `path`
    (the caps), each sampled at 41 points: the tracks of the profile's corners."""
    caps = [(np.array(tuple(path @ u)), np.array(tuple(path % u))) for u in (0.0, 1.0)]
    tracks, explorer = [], TopExp_Explorer(shape.wrapped, TopAbs_EDGE)
    while explorer.More():
        curve = BRepAdaptor_Curve(TopoDS.Edge(explorer.Current()))
        ts = np.linspace(curve.FirstParameter(), curve.LastParameter(), 41)
        points = np.array([curve.Value(t).Coord() for t in ts])
        if all(np.max(np.abs((points - o) @ n)) > 1e-6 for o, n in caps):
            tracks.append(points)
        explorer.Next()
    return tracks


def off_helices(tracks, radii):
    """How far sampled edge tracks are from helices about the z axis with the helix's pitch:
    (the largest change of the distance from the axis, or its distance from every corner's,
    the largest departure from the rise of pitch / 2π per radian)."""
    worst_radius = worst_pitch = 0.0
    for points in tracks:
        r = np.hypot(points[:, 0], points[:, 1])
        phi = np.unwrap(np.arctan2(points[:, 1], points[:, 0]))
        worst_radius = max(worst_radius, np.ptp(r), min(abs(r[0] - q) for q in radii))
        rise = points[:, 2] - points[0, 2] - PITCH * (phi - phi[0]) / (2 * math.pi)
        worst_pitch = max(worst_pitch, np.max(np.abs(rise)))
    return worst_radius, worst_pitch


def test_a_frenet_sweep_along_a_helix_has_helices_for_edges_and_cuts_a_thread():
    helix, thread, corners = helix_and_thread()
    assert is_valid(thread)
    radii = sorted(np.hypot(c[0], c[1]) for c in corners)
    tracks = lateral_edges(thread, helix)
    assert len(tracks) >= 3
    worst_radius, worst_pitch = off_helices(tracks, radii)
    print("\nFrenet thread along a helix: %d edge tracks, distance from the axis within %.1e, "
          "pitch relation within %.1e" % (len(tracks), worst_radius, worst_pitch))
    assert worst_radius <= 1e-4 and worst_pitch <= 1e-4
    rod = bd.Pos(0, 0, HEIGHT / 2) * bd.Cylinder(RADIUS, HEIGHT - 2)
    cut = rod.cut(thread)
    solids = cut.solids()
    assert len(solids) == 1 and is_valid(solids[0])
    assert solids[0].volume < rod.volume


def straight(points):
    """Whether sampled points lie on one line (a cap's edge, not a track)."""
    chord = points[-1] - points[0]
    if np.linalg.norm(chord) == 0:
        return False
    off = np.cross(points - points[0], chord / np.linalg.norm(chord))
    return np.max(np.linalg.norm(off, axis=1)) < 1e-9


def test_a_thread_profile_drawn_in_the_axial_plane_runs_on_helices_and_cuts_a_thread():
    """The triangle as users draw a thread's profile: in the axial plane (XZ) through the
    helix's start, which the helix crosses at its lead angle; carried rigidly by the Frenet
    frame (src/wire/oblique.rs), its corners trace helices of the helix's axis and pitch."""
    helix = bd.Wire([bd.Helix(pitch=PITCH, height=HEIGHT, radius=RADIUS)])
    start = np.array(tuple(helix @ 0))
    assert abs(start[1]) < 1e-9  # the helix starts in the XZ plane
    corners = [tuple(start + d) for d in [(0.4, 0, -0.3), (0.4, 0, 0.3), (-0.4, 0, 0)]]
    triangle = bd.Face(bd.Wire.make_polygon(corners, close=True))
    thread = rocp.sweep(helix, triangle, frame="frenet", tolerance=1e-6)
    assert is_valid(thread)
    radii = [np.hypot(c[0], c[1]) for c in corners]
    tracks, explorer = [], TopExp_Explorer(thread.wrapped, TopAbs_EDGE)
    while explorer.More():
        curve = BRepAdaptor_Curve(TopoDS.Edge(explorer.Current()))
        ts = np.linspace(curve.FirstParameter(), curve.LastParameter(), 41)
        points = np.array([curve.Value(t).Coord() for t in ts])
        if not straight(points):
            tracks.append(points)
        explorer.Next()
    assert tracks and len(tracks) % 3 == 0  # each corner's track, one edge per spine piece
    worst_radius, worst_pitch = off_helices(tracks, radii)
    print("\naxial thread profile along a helix: distance from the axis within %.1e, pitch "
          "relation within %.1e" % (worst_radius, worst_pitch))
    assert worst_radius <= 1e-4 and worst_pitch <= 1e-4
    rod = bd.Pos(0, 0, HEIGHT / 2) * bd.Cylinder(RADIUS, HEIGHT - 2)
    solids = rod.cut(thread).solids()
    assert len(solids) == 1 and is_valid(solids[0]) and solids[0].volume < rod.volume


#: A triangle in the plane z = 0 with its vertex (0.5, 0, 0) on f2, towards the guide's start
#: (RADIUS, 0, 0): the vertex whose track the guide frame puts on a helix.
POINTER = [(0.5, 0.0, 0.0), (-0.2, 0.3, 0.0), (-0.2, -0.3, 0.0)]


@pytest.mark.parametrize("turn", [0.0, 120.0])
def test_a_helical_guide_about_a_line_puts_the_profile_on_helices(turn):
    """The guide frame through rmfsurf.ocp: a triangle swept up the z axis (a bd.Line of
    HEIGHT) with a bd.Helix of RADIUS and PITCH about it as the guide, both turned by `turn`
    degrees about the axis (so that the profile's plane's x axis is not f2: the adapter
    gives the profile in the frame pointing at the guide). f2 points at the guide's crossing
    of each normal plane z = h, at the angle turn + 2π h / PITCH: the track of the vertex
    on f2, sampled on the solid's own edges (BRepAdaptor_Curve), is the helix (0.5 cos,
    0.5 sin, h) of the guide's pitch; every corner stays at its distance from the axis; the
    solid is valid, of the prism's volume. The RMF of a line does not turn: its vertex
    track is off that helix (the check can fail)."""
    path = bd.Line((0, 0, 0), (0, 0, HEIGHT))
    guide = bd.Rot(0, 0, turn) * bd.Helix(pitch=PITCH, height=HEIGHT, radius=RADIUS)
    phase = math.radians(turn)
    start = np.array(tuple(guide @ 0))
    assert np.linalg.norm(start - RADIUS * np.array([math.cos(phase), math.sin(phase), 0])) < 1e-9
    c, s = math.cos(phase), math.sin(phase)
    triangle = bd.Face(bd.Wire.make_polygon([(c * x - s * y, s * x + c * y, 0.0)
                                             for x, y, _ in POINTER], close=True))

    def vertex_track_off_the_helix(solid):
        tracks = [t for t in lateral_edges(solid, path)
                  if abs(np.hypot(t[0, 0], t[0, 1]) - 0.5) < 1e-9]
        assert tracks
        angle = phase + 2 * math.pi * np.concatenate([t[:, 2] for t in tracks]) / PITCH
        points = np.concatenate(tracks)
        on = np.stack([0.5 * np.cos(angle), 0.5 * np.sin(angle), points[:, 2]], axis=1)
        return np.max(np.linalg.norm(points - on, axis=1)), tracks

    solid = rocp.sweep(path, triangle, frame=("guide", guide), tolerance=1e-6)
    off, tracks = vertex_track_off_the_helix(solid)
    all_tracks = lateral_edges(solid, path)
    radii = [np.hypot(x, y) for x, y, _ in POINTER]
    worst_radius, worst_pitch = off_helices(all_tracks, radii)
    volume, exact = occ_volume(solid), 0.5 * 0.6 * 0.7 * HEIGHT
    print("\ntriangle up a line with a helical guide turned by %g deg: the f2 vertex's track "
          "(%d edges) off the helix of radius 0.5, pitch %g by %.1e; %d corner tracks within "
          "%.1e of their radii, pitch relation within %.1e; volume %.15f vs %.15f (relative "
          "%.1e)" % (turn, len(tracks), PITCH, off, len(all_tracks), worst_radius, worst_pitch,
                     volume, exact, abs(volume - exact) / exact))
    assert is_valid(solid)
    # Within the sweep's tolerance (the screw motion along a line is a twist: exact).
    assert off <= 1e-6 and worst_radius <= 1e-6 and worst_pitch <= 1e-6
    assert abs(volume - exact) <= 1e-9 * exact
    same = rocp.sweep(path, triangle, frame={"guide": bd.Wire([guide])}, tolerance=1e-6)
    assert vertex_track_off_the_helix(same)[0] <= 1e-6
    rmf, _ = vertex_track_off_the_helix(rocp.sweep(path, triangle, tolerance=1e-6))
    assert rmf > 0.1
