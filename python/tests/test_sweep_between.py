"""Sweeps between two profiles through the package and rmfsurf.ocp (intended behaviour of
the geometry, rmf_wire_sweep_between): two concentric circles along a line are the frustum
π L (r0² + r0 r1 + r1²)/3 by OpenCascade's integration; a square face into a circle face,
both drawn at the start of a build123d line, is one valid solid whose volume lies between
the two prisms. Through sections (rmf_wire_sweep_through): three circles along a build123d
line are the chain of two frustums π/3 Σ Lᵢ (aᵢ² + aᵢ aᵢ₊₁ + aᵢ₊₁²) by OpenCascade's
integration; a square through a circle into a triangle is one valid solid. (The bad
arguments are in test_arguments.py.)"""

import math

import pytest

import rmfsurf

bd = pytest.importorskip("build123d")
rocp = pytest.importorskip("rmfsurf.ocp")
from OCP.BRepCheck import BRepCheck_Analyzer  # noqa: E402
from OCP.BRepGProp import BRepGProp  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402
from OCP.TopAbs import TopAbs_SOLID  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402


def occ_volume(solid):
    """OpenCascade's volume: BRepGProp's adaptive Gauss-Kronrod integration to 1e-12."""
    props = GProp_GProps()
    BRepGProp.VolumePropertiesGK_s(getattr(solid, "wrapped", solid), props, 1e-12)
    return props.Mass()


def solids_of(shape):
    raw = getattr(shape, "wrapped", shape)
    explorer, count = TopExp_Explorer(raw, TopAbs_SOLID), 0
    while explorer.More():
        count += 1
        explorer.Next()
    return count


def test_two_concentric_circles_along_a_line_are_the_frustum():
    r0, r1, length = 1.0, 0.5, 3.0
    shape = rmfsurf.wire_sweep([rmfsurf.Line((0, 0, 0), (length, 0, 0))], rmfsurf.circle(r0),
                               end_profile=rmfsurf.circle(r1))
    assert shape.is_solid
    exact = math.pi * length * (r0 * r0 + r0 * r1 + r1 * r1) / 3
    volume = occ_volume(rocp.shape(shape))
    print("\ncircle %g into circle %g along %g: volume %.15f vs the frustum %.15f (relative %.1e)"
          % (r0, r1, length, volume, exact, abs(volume - exact) / exact))
    assert abs(volume - exact) <= 1e-9 * exact
    # With no end profile, the same call is the cylinder; end_holes follow the holes.
    plain = rmfsurf.wire_sweep([rmfsurf.Line((0, 0, 0), (length, 0, 0))], rmfsurf.circle(r0),
                               end_profile=None)
    assert abs(occ_volume(rocp.shape(plain)) - math.pi * length) <= 1e-9 * math.pi * length
    hollow = rmfsurf.wire_sweep([rmfsurf.Line((0, 0, 0), (length, 0, 0))], rmfsurf.circle(r0),
                                rmfsurf.circle(0.5), end_profile=rmfsurf.circle(r1),
                                end_holes=rmfsurf.circle(0.25))
    want = exact - math.pi * length * (0.25 + 0.125 + 0.0625) / 3
    got = occ_volume(rocp.shape(hollow))
    assert abs(got - want) <= 1e-9 * want, (got, want)


def test_ocp_sweeps_a_square_face_into_a_circle_face_along_a_build123d_line():
    """Both faces are drawn at the line's start, in its normal plane (the end profile in the
    start frame's coordinates, carried to the end). OpenCascade's circle is three rational
    120° arcs: the blend cuts it where the square's corners point."""
    length, half, radius = 4.0, 0.5, 0.6
    line = bd.Line((0, 0, 0), (length, 0, 0))
    plane = bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0))
    square = plane * bd.Rectangle(2 * half, 2 * half)
    circle = plane * bd.Circle(radius)
    solid = rocp.sweep(line, square, end_profile=circle)
    raw = getattr(solid, "wrapped", solid)
    assert BRepCheck_Analyzer(raw).IsValid()
    assert solids_of(solid) == 1
    volume = occ_volume(solid)
    square_prism, circle_prism = length * (2 * half) ** 2, length * math.pi * radius ** 2
    print("\nsquare %g into circle %g along a build123d line of %g: volume %.12f between %.6f "
          "and %.6f" % (2 * half, radius, length, volume, square_prism, circle_prism))
    assert square_prism < volume < circle_prism
    # From the line's start to its end, the circle there (|y| up to the radius).
    bounds = solid.bounding_box()
    assert abs(bounds.min.X) < 1e-4 and abs(bounds.max.X - length) < 1e-4, bounds
    assert abs(bounds.max.Y - radius) < 1e-4, bounds


def frustum_chain(length, stations):
    """π/3 Σ Lᵢ (aᵢ² + aᵢ aᵢ₊₁ + aᵢ₊₁²) of circles of radii a at fractions f of `length`."""
    return sum(math.pi / 3 * (f1 - f0) * length * (a * a + a * b + b * b)
               for (f0, a), (f1, b) in zip(stations, stations[1:]))


def test_three_circles_through_a_build123d_line_are_the_chain_of_frustums():
    """Radii 0.5 at 0, 1 at 0.25 and 0.3 at 1 along a line of 4, every circle drawn at the
    line's start (ocp.sweep's convention); rmfsurf.wire_sweep with the same circles as
    Curves gives the same volume."""
    length, stations = 4.0, [(0.0, 0.5), (0.25, 1.0), (1.0, 0.3)]
    line = bd.Line((0, 0, 0), (length, 0, 0))
    plane = bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0))
    circle = lambda r: plane * bd.Circle(r)  # noqa: E731
    solid = rocp.sweep(line, circle(0.5), end_profile=circle(0.3),
                       sections=[(0.25, circle(1.0))])
    raw = getattr(solid, "wrapped", solid)
    assert BRepCheck_Analyzer(raw).IsValid()
    assert solids_of(solid) == 1
    exact = frustum_chain(length, stations)
    volume = occ_volume(solid)
    print("\ncircles 0.5 at 0, 1 at 0.25, 0.3 at 1 through a build123d line of 4: volume %.15f "
          "vs the frustums %.15f (relative %.1e)" % (volume, exact, abs(volume - exact) / exact))
    assert abs(volume - exact) <= 1e-9 * exact
    shape = rmfsurf.wire_sweep([rmfsurf.Line((0, 0, 0), (length, 0, 0))], rmfsurf.circle(0.5),
                               end_profile=rmfsurf.circle(0.3),
                               sections=[(0.25, rmfsurf.circle(1.0))])
    assert shape.is_solid
    volume = occ_volume(rocp.shape(shape))
    assert abs(volume - exact) <= 1e-9 * exact, (volume, exact)
    # Without the middle section: one frustum, another volume.
    straight = occ_volume(rocp.shape(rmfsurf.wire_sweep(
        [rmfsurf.Line((0, 0, 0), (length, 0, 0))], rmfsurf.circle(0.5),
        end_profile=rmfsurf.circle(0.3), sections=[])))
    assert abs(straight - frustum_chain(length, [(0.0, 0.5), (1.0, 0.3)])) <= 1e-9 * straight
    assert abs(straight - exact) > 0.1 * exact


def test_ocp_sweeps_a_square_through_a_circle_into_a_triangle():
    """A square (side 1) at 0, a circle (radius 0.6) at 0.5, a triangle at 1, all faces
    drawn at a build123d line's start: one valid solid from the line's start to its end."""
    length = 4.0
    line = bd.Line((0, 0, 0), (length, 0, 0))
    plane = bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0))
    square = plane * bd.Rectangle(1.0, 1.0)
    circle = plane * bd.Circle(0.6)
    triangle = plane * bd.RegularPolygon(0.7, 3)
    solid = rocp.sweep(line, square, end_profile=triangle, sections=[(0.5, circle)])
    raw = getattr(solid, "wrapped", solid)
    assert BRepCheck_Analyzer(raw).IsValid()
    assert solids_of(solid) == 1
    volume = occ_volume(solid)
    faces = len(solid.faces())
    print("\nsquare 1 through circle 0.6 into triangle 0.7 along a build123d line of 4: %d faces, "
          "volume %.12f" % (faces, volume))
    assert volume > 0
    bounds = solid.bounding_box()
    assert abs(bounds.min.X) < 1e-4 and abs(bounds.max.X - length) < 1e-4, bounds
