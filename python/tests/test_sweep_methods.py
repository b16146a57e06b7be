"""The spine method of wire sweeps through the package and rmfsurf.ocp: `method` ("ph-rmf",
the default, "mobius", "rrmf") changes nothing when left at its default or on lines and
arcs; along a build123d path of a line and a B-spline curve (a spline through the twisted
cubic (t, t², t³), tangent to the line) the Möbius and RRMF spines carry exact rational
RMFs, so the library's report gives the parameter lines orthogonal to rounding (< 1e-12)
where the PH cubic spline's rational RMF leaves more than 1e-10, and rmfsurf.ocp.sweep
gives a valid solid of the tube's volume. (The bad arguments are in test_arguments.py.)"""

import math

import numpy as np
import pytest

import rmfsurf

bd = pytest.importorskip("build123d")
rocp = pytest.importorskip("rmfsurf.ocp")
from OCP.BRepCheck import BRepCheck_Analyzer  # noqa: E402
from OCP.BRepGProp import BRepGProp  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402

RADIUS = 0.05
#: The tolerance of each method. RRMF quintics through samples of this B-spline find no
#: interpolant at some segment once the samples are fine (NoSolutionError "none of the
#: eta_samples = 64 sampled values of η admits an RRMF quintic interpolant" from 3e-4 down,
#: at 4096 segments): 1e-3 for them (the spine within 8.2e-4, the volume within 6e-6).
TOLERANCE = {"ph-rmf": 1e-5, "mobius": 1e-5, "rrmf": 1e-3}


def occ_volume(solid):
    """OpenCascade's volume: BRepGProp's adaptive Gauss-Kronrod integration to 1e-12."""
    props = GProp_GProps()
    BRepGProp.VolumePropertiesGK_s(getattr(solid, "wrapped", solid), props, 1e-12)
    return props.Mass()


def is_valid(shape):
    return BRepCheck_Analyzer(getattr(shape, "wrapped", shape)).IsValid()


def path():
    """A line from (-1, 0, 0) to the origin, then a B-spline through samples of the twisted
    cubic (t, t², t³), t in [0, 1], tangent to the line at the origin."""
    ts = np.linspace(0.0, 1.0, 9)
    points = [(t, t * t, t ** 3) for t in ts]
    spline = bd.Spline(*points, tangents=[(1, 0, 0), (1, 2, 3)])
    return bd.Wire([bd.Line((-1, 0, 0), (0, 0, 0)), spline])


def profile():
    return bd.Plane(origin=(-1, 0, 0), z_dir=(1, 0, 0)) * bd.Circle(RADIUS)


def test_the_default_is_ph_rmf_and_lines_are_exact_whatever_the_method():
    line = [rmfsurf.Line((0, 0, 0), (3, 0, 0))]
    circle = rmfsurf.circle(1.0)
    plain = rmfsurf.wire_sweep(line, circle)
    given = rmfsurf.wire_sweep(line, circle, method="ph-rmf")
    assert plain.occ_brep() == given.occ_brep()
    assert plain.report() == given.report()
    for method in ("mobius", "rrmf"):
        other = rmfsurf.wire_sweep(line, circle, method=method)
        assert other.occ_brep() == plain.occ_brep(), method


def test_a_scale_law_and_the_frenet_method_are_refused():
    line = [rmfsurf.Line((0, 0, 0), (3, 0, 0))]
    with pytest.raises(rmfsurf.InvalidInputError, match="scale_start.*method = 2"):
        rmfsurf.wire_sweep(line, rmfsurf.circle(1.0), method="mobius", scale=(1.0, 0.5))
    with pytest.raises(ValueError, match="method: .*frame='frenet'"):
        rmfsurf.wire_sweep(line, rmfsurf.circle(1.0), method="frenet")


def test_exact_rmf_methods_sweep_a_line_and_spline_with_orthogonal_parameter_lines():
    wire = path()
    edges = rocp.path_edges(wire)
    assert [type(e).__name__ for e in edges] == ["Line", "CurveEdge"]
    length = wire.length
    cosines, volumes = {}, {}
    for method, tolerance in TOLERANCE.items():
        report = rmfsurf.wire_sweep(edges, rmfsurf.circle(RADIUS), method=method,
                                    tolerance=tolerance).report()
        solid = rocp.sweep(wire, profile(), method=method, tolerance=tolerance)
        cosines[method] = report.max_parameter_cosine
        volumes[method] = occ_volume(solid)
        tube = math.pi * RADIUS ** 2 * length
        print("\n%s: max |cos| %.1e, spine within %.1e, volume %.15f (against pi r^2 L of "
              "the path %.1e)" % (method, report.max_parameter_cosine, report.spine_distance,
                                 volumes[method], abs(volumes[method] - tube) / tube))
        assert is_valid(solid), method
        assert report.spine_distance <= tolerance, method
        assert abs(volumes[method] - tube) <= 1e-5 * tube, method
    assert cosines["ph-rmf"] > 1e-10, cosines
    assert cosines["mobius"] < 1e-12, cosines
    assert cosines["rrmf"] < 1e-12, cosines
    # The same tube: the spines are within 1e-5 of the same curve.
    assert abs(volumes["mobius"] - volumes["ph-rmf"]) <= 1e-6 * volumes["ph-rmf"], volumes
