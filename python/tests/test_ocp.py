"""rmfsurf.ocp with OpenCascade's Python bindings (OCP from PyPI, as build123d pulls
them): curves and surfaces both ways, checked by OCC's own evaluation; a swept tube closed
into a solid that OCC validates (BRepCheck_Analyzer) and whose volume OCC measures
against the tube formula π r² L."""

import math

import numpy as np
import pytest

import rmfsurf
import rmfsurf.ocp as rocp
from test_core import RADIUS, circle, helix_data

build123d = pytest.importorskip("build123d")
from OCP.BRepAdaptor import BRepAdaptor_Surface  # noqa: E402
from OCP.BRepBuilderAPI import BRepBuilderAPI_Sewing  # noqa: E402
from OCP.gp import gp_Pnt, gp_Vec  # noqa: E402


def test_curves_both_ways():
    c = circle()
    occ = rocp.bspline_curve(c)
    ts = np.linspace(0, 4, 33)
    theirs = np.array([occ.Value(t).Coord() for t in ts])
    assert np.abs(theirs - c.eval(ts)).max() <= 1e-15
    back = rocp.curve(occ)
    assert np.abs(back.eval(ts) - c.eval(ts)).max() <= 1e-15
    # A build123d edge: a line and a reversed arc keep their direction.
    arc = build123d.CenterArc((0, 0, 0), 2.0, 0, 90)
    a = rocp.curve(arc)
    assert np.abs(a.eval(a.domain[0]) - [2, 0, 0]).max() <= 1e-12
    assert np.abs(a.eval(a.domain[1]) - [0, 2, 0]).max() <= 1e-12
    r = rocp.curve(arc.reversed())
    assert np.abs(r.eval(r.domain[0]) - [0, 2, 0]).max() <= 1e-12
    mid = r.eval(0.5 * sum(r.domain))
    assert abs(np.linalg.norm(mid) - 2) <= 1e-12


def test_wrong_types_say_what_was_expected():
    face = build123d.Circle(1).faces()[0]
    with pytest.raises(TypeError, match="path: expected a wire or an edge .*got build123d Face"):
        rocp.sweep(face, face)
    with pytest.raises(TypeError, match="curve: expected an edge or a curve"):
        rocp.curve(face)
    line = build123d.Line((0, 0, 0), (1, 0, 0))
    with pytest.raises(TypeError, match="profile: expected a planar profile .*got str"):
        rocp.sweep(line, "circle")


def tube_solid(frames_of, spline=None):
    """The sweep of a circle along the helix PH spline as an OCC solid: the lateral face
    from the NURBS surface, caps bounded by the end circles."""
    spline = spline or rmfsurf.ph_spline_hermite(*helix_data())
    frames = frames_of(spline)
    surface = rmfsurf.sweep_surface(spline, frames, circle())
    sewing = BRepBuilderAPI_Sewing(1e-6)
    sewing.Add(rocp.face(surface))
    profile = circle().nurbs()
    for v in spline.domain:
        t, f2, f3 = frames.eval(v)
        x = spline.eval(v)
        poles = x + np.outer(profile.poles[:, 0], f2) + np.outer(profile.poles[:, 1], f3)
        loop = rmfsurf.Curve.from_nurbs(2, poles, profile.knots, profile.weights)
        sewing.Add(rocp._cap([loop], x, t))
    sewing.Perform()
    return spline, surface, rocp.closed_solid(sewing.SewedShape())


def arc_length(spline, n=64):
    """∫|x'| by Gauss–Legendre on every segment (the tests' own quadrature)."""
    nodes, weights = np.polynomial.legendre.leggauss(n)
    total = 0.0
    for s in spline.segments():
        a, b = s.t_start, s.t_end
        ts = 0.5 * (b - a) * nodes + 0.5 * (a + b)
        _, d = spline.eval(ts, derivative=True)
        total += 0.5 * (b - a) * np.dot(weights, np.linalg.norm(d, axis=1))
    return total


def test_swept_tube_is_a_valid_solid_with_the_tube_formula_volume():
    spline, surface, solid = tube_solid(lambda s: rmfsurf.ph_rational_rmf(s, (0, 0, 1)))
    assert rocp.is_valid(solid)
    expected = math.pi * RADIUS ** 2 * arc_length(spline)
    error = abs(rocp.volume(solid) - expected) / expected
    print("\nOCC solid of the RMF tube: valid, volume error %.2e against π r² L" % error)
    assert error <= 1e-6
    # OCC evaluates the Geom_BSplineSurface where the library evaluates the surface.
    adaptor = BRepAdaptor_Surface(rocp.face(surface))
    u0, u1, v0, v1 = surface.domain
    worst = 0.0
    for u in np.linspace(u0, u1, 9):
        for v in np.linspace(v0, v1, 9):
            worst = max(worst, np.abs(np.array(adaptor.Value(u, v).Coord())
                                      - surface.eval(u, v)).max())
    assert worst <= 1e-13
    box = build123d.Box(2, 2, 2)
    fused = box + build123d.Solid(solid)
    assert rocp.is_valid(fused) and fused.volume > box.volume


def parameter_cosine(face, n=12):
    """max |cos| of the angle between the parameter lines of an OCC face (OCC's D1)."""
    a = BRepAdaptor_Surface(face)
    worst = 0.0
    for u in np.linspace(a.FirstUParameter(), a.LastUParameter(), n):
        for v in np.linspace(a.FirstVParameter(), a.LastVParameter(), n):
            p, du, dv = gp_Pnt(), gp_Vec(), gp_Vec()
            a.D1(u, v, p, du, dv)
            if du.Magnitude() > 1e-12 and dv.Magnitude() > 1e-12:
                worst = max(worst, abs(du.Dot(dv)) / (du.Magnitude() * dv.Magnitude()))
    return worst


def test_rmf_parameter_lines_are_orthogonal_and_frenet_ones_are_not():
    # RMF: the helix spline (8 segments); Frenet: one PH cubic (Frenet sweeps jump at G1
    # joints and have no single NURBS).
    a = 1.2
    segment, _ = rmfsurf.ph_cubic_hermite((1, 0, 0), (0, 1, 0.2), (math.cos(a), math.sin(a), 0.2 * a),
                                          (-math.sin(a), math.cos(a), 0.2))
    _, rmf_surface, _ = tube_solid(lambda s: rmfsurf.ph_rational_rmf(s, (0, 0, 1)))
    _, frenet_surface, _ = tube_solid(rmfsurf.ph_frenet_frames, segment)
    rmf = parameter_cosine(rocp.face(rmf_surface))
    frenet = parameter_cosine(rocp.face(frenet_surface))
    print("\nparameter lines, max |cos|: RMF %.1e, Frenet %.1e" % (rmf, frenet))
    assert rmf <= 1e-5 and frenet >= 1e-2
