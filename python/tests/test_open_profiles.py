"""Open profiles through rmfsurf.ocp: an open edge or wire (an arc, a line, a polyline)
swept with ``solid=False`` is a sheet, valid for OpenCascade, whose area is build123d's own
``Shell.sweep`` of the same section; a line out of the path's normal plane and an open
profile for a solid are refused naming the profile."""

import pytest

bd = pytest.importorskip("build123d")
rocp = pytest.importorskip("rmfsurf.ocp")
import rmfsurf  # noqa: E402
from OCP.BRepCheck import BRepCheck_Analyzer  # noqa: E402

PATH = bd.Wire([bd.Line((0, 0, 0), (0, 0, 10)), bd.Line((0, 0, 10), (0, 6, 18))])

SECTIONS = {
    "arc": bd.Edge.make_circle(2, bd.Plane.XY, start_angle=0, end_angle=120),
    "line": bd.Edge.make_line((-1, 0, 0), (1, 0, 0)),
    "polyline": bd.Wire(bd.Polyline((-1, 0, 0), (0, 1, 0), (1, 0, 0)).edges()),
}


@pytest.mark.parametrize("name", sorted(SECTIONS))
def test_an_open_profile_sweeps_into_a_sheet_of_build123ds_area(name):
    section = SECTIONS[name]
    straight = bd.Wire(bd.Line((0, 0, 0), (0, 0, 10)).edges())
    sheet = rocp.sweep(straight, section, solid=False)
    assert isinstance(sheet, bd.Shell)
    assert BRepCheck_Analyzer(sheet.wrapped).IsValid()
    own = bd.Shell.sweep(section, straight)
    assert abs(sheet.area - own.area) <= 1e-8 * own.area, (sheet.area, own.area)


def test_an_open_profile_along_a_cornered_path_is_one_valid_sheet():
    sheet = rocp.sweep(PATH, SECTIONS["polyline"], solid=False)
    assert BRepCheck_Analyzer(sheet.wrapped).IsValid()
    assert len(sheet.faces()) == 2 * 3  # two profile edges × (line, elbow, line)


def test_an_open_profile_for_a_solid_and_a_line_out_of_the_normal_plane_are_refused():
    with pytest.raises(rmfsurf.InvalidInputError, match="profile: a solid needs a closed profile"):
        rocp.sweep(PATH, SECTIONS["arc"])
    with pytest.raises(ValueError, match="profile: a straight profile spans no plane"):
        rocp.sweep(PATH, bd.Edge.make_line((-1, 0, 0), (1, 0, 1)), solid=False)
