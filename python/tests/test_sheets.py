"""Sheet-metal parts through the Python API (rmfsurf.transition, SheetPart), checked with the
tests' own arithmetic: the exported edge NURBS evaluated by tests/nurbs.py against the input
circle, the flat outline's closure and area by Green's theorem, marks both ways, the files'
texts, and errors naming the argument. Run by integration/tests/python.rs."""

import math

import numpy as np
import pytest

import rmfsurf
from nurbs import curve_point, surface_point



def square(half=100.0, z=0.0):
    corners = [[-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]]
    return rmfsurf.Curve.from_nurbs(1, corners + [corners[0]], [0, 0, 1, 2, 3, 4, 4])


def circle(centre=(20.0, 0.0, 150.0), radius=60.0):
    return rmfsurf.circle(radius, centre)


@pytest.fixture(scope="module")
def hopper():
    return rmfsurf.transition(square(), circle(), thickness=2.0, k_factor=0.4, tolerance=1e-3)


def test_the_hopper_edges_lie_on_the_input_curves(hopper):
    report = hopper.report()
    assert report.closed and report.pieces == hopper.piece_count > 8
    assert report.edge_distance[0] <= 1e-3 and report.edge_distance[1] <= 1e-3
    assert math.isclose(report.neutral - report.inner, 0.8) and math.isclose(report.outer, 2.0)
    top = hopper.edge("reference", "second").nurbs()
    worst = 0.0
    for t in np.linspace(top.knots[0], top.knots[-1], 2001):
        x, y, z = curve_point(top.degree, top.poles, top.weights, top.knots, t)
        worst = max(worst, math.hypot(math.hypot(x - 20.0, y) - 60.0, z - 150.0))
    assert worst <= 1e-3


def test_the_flat_pattern_is_closed_counter_clockwise_and_as_large_as_formed(hopper):
    edges = hopper.flat_edges()
    cut = [e for e in edges if e.layer == "cut"]
    assert {e.kind for e in cut} == {"line", "arc"}
    for a, b in zip(cut, cut[1:] + cut[:1]):
        assert np.array_equal(a.end, b.start)
    twice = sum(e.start[0] * e.end[1] - e.end[0] * e.start[1]
                + (e.radius ** 2 * (e.sweep - math.sin(e.sweep)) if e.kind == "arc" else 0.0)
                for e in cut)
    assert twice > 0
    # The formed neutral layer's area, measured independently: the triangulated grid of the
    # exported NURBS (chordal, converging as h²), 8 × 6 cells per knot span.
    layer = hopper.layer("neutral").nurbs()
    assert layer.degree_u == 1
    spans = np.unique(layer.knots_v)
    vs = np.concatenate([np.linspace(a, b, 6, endpoint=False) for a, b in zip(spans, spans[1:])] + [spans[-1:]])
    us = np.linspace(0.0, 1.0, 9)
    grid = np.array([[surface_point(layer.degree_u, layer.degree_v, layer.poles, layer.weights,
                                    layer.knots_u, layer.knots_v, u, v) for v in vs] for u in us])
    a, b, c = grid[:-1, :-1], grid[1:, :-1], grid[:-1, 1:]
    d = grid[1:, 1:]
    mesh = 0.5 * (np.linalg.norm(np.cross(b - a, c - a), axis=2) + np.linalg.norm(np.cross(b - d, c - d), axis=2)).sum()
    assert 0.5 * twice == pytest.approx(mesh, rel=2e-3)


def test_marks_go_both_ways(hopper):
    bend = next(e for e in hopper.flat_edges() if e.layer == "bend")
    flat = np.array([bend.start + s * (bend.end - bend.start) for s in (0.2, 0.5, 0.8)])
    points, normals = hopper.flat_to_surface(flat, "outer", normals=True)
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0)
    back = hopper.surface_to_flat(points, "outer", max_distance=1e-9)
    assert np.abs(back - flat).max() < 1e-9
    with pytest.raises(rmfsurf.InvalidInputError, match=r"flat\[1\]"):
        hopper.flat_to_surface([[0.0, 0.0], [1e4, 0.0]])
    with pytest.raises(ValueError, match="points"):
        hopper.flat_to_surface([[0.0, 0.0, 0.0]])


def test_the_files_of_the_part(hopper):
    step = hopper.export("step")
    assert "MANIFOLD_SOLID_BREP" in step and "CLOSED_SHELL" in step
    dxf = hopper.export("dxf")
    assert "\nARC\n" in dxf and "\nBEND\n" in dxf and "POLYLINE" not in dxf
    assert "PLANE(" in hopper.export("flat_step")
    brep = hopper.export("brep")
    assert brep.startswith("\nCASCADE Topology V1, (c) Matra-Datavision\n")
    assert brep.count("\nFa\n") == step.count("ADVANCED_FACE(") and "\nSo\n" in brep
    with pytest.raises(ValueError, match="format"):
        hopper.export("iges")


def test_bad_sheets_and_curves_name_the_argument():
    with pytest.raises(rmfsurf.InvalidInputError, match=r"options->thickness"):
        rmfsurf.transition(square(), circle(), thickness=0.0)
    with pytest.raises(rmfsurf.InvalidInputError, match=r"options->k_factor"):
        rmfsurf.transition(square(), circle(), k_factor=1.5)
    with pytest.raises(rmfsurf.InvalidInputError, match="bend radius"):
        rmfsurf.transition(square(), circle(), tolerance=1e-2, reference="outer")
    dart = rmfsurf.Curve.from_nurbs(1, [[0, 0, 0], [2, 1, 0], [0, 0.5, 0], [-2, 1, 0], [0, 0, 0]],
                                    [0, 0, 1, 2, 3, 4, 4])
    with pytest.raises(rmfsurf.InvalidInputError, match="bottom is not convex"):
        rmfsurf.transition(dart, circle())
    with pytest.raises(TypeError, match="top"):
        rmfsurf.transition(square(), "circle")
    with pytest.raises(ValueError, match="reference"):
        rmfsurf.transition(square(), circle(), reference="middle")


def rail_pole(s, i):
    """Bézier pole i on [0.2, 1.2] of the cubic x + s x′, x = (t, t², t³), by blossoming."""
    u = [1.2] * i + [0.2] * (3 - i)
    m, sym2, prod = sum(u) / 3, (u[0] * u[1] + u[0] * u[2] + u[1] * u[2]) / 3, u[0] * u[1] * u[2]
    return [m + s, sym2 + 2 * s * m, prod + 3 * s * sym2]


def twisted_cubic_rails():
    """The tangent surface of the twisted cubic (t, t², t³) between the rails x + x′/2 and
    x + x′, t in [0.2, 1.2], as a degree (1, 3) NURBS, and the rails densely sampled."""
    pole = rail_pole
    poles = [[pole(s, i) for i in range(4)] for s in (0.5, 1.0)]
    surface = rmfsurf.Surface.from_nurbs(1, 3, poles, [0, 0, 1, 1], [0.2] * 4 + [1.2] * 4)
    ts = np.linspace(0.2, 1.2, 20001)
    rails = [np.stack([ts + s, ts ** 2 + 2 * s * ts, ts ** 3 + 3 * s * ts ** 2], axis=1) for s in (0.5, 1.0)]
    return surface, rails


def polyline_distance(polyline, p):
    """Distance from p to a dense polyline (the two chords at its nearest vertex; a chord of
    the rails sampled every 5e-5 in t sags by less than 1e-9 from the rail)."""
    k = int(np.linalg.norm(polyline - p, axis=1).argmin())
    best = np.linalg.norm(polyline[k] - p)
    for a, b in ((k - 1, k), (k, k + 1)):
        if 0 <= a and b < len(polyline):
            d = polyline[b] - polyline[a]
            s = np.clip(np.dot(p - polyline[a], d) / np.dot(d, d), 0.0, 1.0)
            best = min(best, np.linalg.norm(polyline[a] + s * d - p))
    return best


def test_a_part_between_rails_has_its_edges_on_the_rails():
    surface, rails = twisted_cubic_rails()
    part = rmfsurf.part_between_rails(surface, thickness=0.02, tolerance=1e-4)
    report = part.report()
    assert not report.closed and report.pieces >= 2
    for side, rail in zip(("first", "second"), rails):
        edge = part.edge("reference", side).nurbs()
        points = [np.array(curve_point(edge.degree, edge.poles, edge.weights, edge.knots, t))
                  for t in np.linspace(edge.knots[0], edge.knots[-1], 301)]
        worst = max(polyline_distance(rail, p) for p in points)
        assert worst <= 1e-4
    cut = [e for e in part.flat_edges() if e.layer == "cut"]
    for a, b in zip(cut, cut[1:] + cut[:1]):
        assert np.array_equal(a.end, b.start)
    curve = rmfsurf.Curve.from_nurbs(3, [rail_pole(0.0, i) for i in range(4)], [0.2] * 4 + [1.2] * 4)
    assert rmfsurf.tangent_part(curve, 0.3, 0.9, tolerance=1e-3).report().pieces >= 2
    with pytest.raises(rmfsurf.InvalidInputError, match="contains 0"):
        rmfsurf.tangent_part(curve, -0.3, 0.9)
    with pytest.raises(TypeError, match="surface"):
        rmfsurf.part_between_rails("surface")
