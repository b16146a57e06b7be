"""The primitive curves (circle, arc, polyline, polygon, obround), evaluated by this file's
own de Casteljau algorithm on their rational Bézier segments, never by the library."""

import math

import numpy as np
import pytest

import rmfsurf


def points_of(curve, per_segment=32):
    """Points of every segment at `per_segment` + 1 local parameters (homogeneous de
    Casteljau)."""
    out = []
    for seg in curve.segments():
        h = np.c_[seg.poles * seg.weights[:, None], seg.weights]
        for s in np.linspace(0.0, 1.0, per_segment + 1):
            q = h.copy()
            for r in range(1, len(q)):
                q[:-r] = (1 - s) * q[:-r] + s * q[1:len(q) - r + 1]
            out.append(q[0, :3] / q[0, 3])
    return np.array(out)


def test_a_circle_lies_at_its_radius_in_its_plane():
    centre, x, y = np.array([1.0, 2.0, 3.0]), np.array([0.0, 2.0, 0.0]), np.array([0.0, 1.0, 1.0])
    c = rmfsurf.circle(2.5, centre, x, y)
    p = points_of(c)
    assert c.segment_count == 4 and c.domain == (0.0, 4.0)
    assert np.abs(np.linalg.norm(p - centre, axis=1) - 2.5).max() < 1e-13
    assert np.abs((p - centre)[:, 0]).max() < 1e-13  # the plane x = 1
    assert np.allclose(p[0], centre + 2.5 * x / 2.0, atol=1e-15)


def test_an_arc_runs_from_start_through_the_middle_point_to_end():
    a, b, c = (10, 0, 0), (0, 10, 0), (-6, -8, 0)
    p = points_of(rmfsurf.arc(a, b, c), 200)
    assert np.abs(np.linalg.norm(p, axis=1) - 10).max() < 1e-13
    assert np.allclose(p[0], a) and np.allclose(p[-1], c)
    assert np.linalg.norm(p - b, axis=1).min() < 0.2
    assert not np.any((p[:, 0] > 1e-9) & (p[:, 1] < -1e-9)), "the arc stays off the fourth quadrant"


def test_polylines_and_polygons_go_through_their_points():
    corners = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]], dtype=float)
    line, square = rmfsurf.polyline(corners), rmfsurf.polygon(corners)
    assert (line.segment_count, square.segment_count) == (3, 4)
    ends = points_of(square, 1)
    assert np.allclose(ends[::2], corners) and np.allclose(ends[-1], corners[0])


def test_an_obround_lies_at_its_radius_from_its_segment():
    slot = rmfsurf.obround(6.0, 1.5, centre=(0, 0, 5))
    p = points_of(slot)
    along = np.clip(p[:, 0], -3, 3)
    d = np.linalg.norm(p - np.c_[along, np.zeros(len(p)), np.full(len(p), 5.0)], axis=1)
    assert slot.segment_count == 6 and np.abs(d - 1.5).max() < 1e-13


def test_the_check_can_fail():
    p = points_of(rmfsurf.circle(2.6))
    assert np.abs(np.linalg.norm(p, axis=1) - 2.5).max() > 0.09


@pytest.mark.parametrize("call, name", [
    (lambda: rmfsurf.circle(0.0), "radius"),
    (lambda: rmfsurf.circle(1.0, y_axis=(3, 0, 0)), "y_axis"),
    (lambda: rmfsurf.arc((0, 0, 0), (1, 1, 1), (2, 2, 2)), "collinear"),
    (lambda: rmfsurf.polygon([(0, 0, 0), (1, 0, 0), (1, 0, 0)]), "corners[1] and corners[2]"),
    (lambda: rmfsurf.obround(-1.0, 1.0), "length"),
])
def test_bad_primitives_are_refused_naming_the_argument(call, name):
    with pytest.raises(rmfsurf.InvalidInputError) as e:
        call()
    assert name in str(e.value)
