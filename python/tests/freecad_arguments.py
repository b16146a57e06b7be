"""Bad arguments of rmfsurf.freecad (issue 25), run by test_arguments.py in a separate pytest
process with FreeCAD's module directory on sys.path (RMFSURF_FREECAD_LIB): the same classes
and checks as test_arguments.py, and the coverage of the adapter's arguments by their
annotations."""

import functools
import inspect
import math
import os
import sys

import numpy as np
import pytest

sys.path.append(os.environ.get("RMFSURF_FREECAD_LIB", "/usr/lib/freecad-python3/lib"))
FreeCAD = pytest.importorskip("FreeCAD")
Part = pytest.importorskip("Part")

import rmfsurf  # noqa: E402
import rmfsurf.freecad as rfc  # noqa: E402
from arguments import (BEYOND_DOUBLE, MAXIMUM, NON_FINITE, NOT_INTEGERS, NOT_NUMBERS,  # noqa: E402
                       api_arguments, argument, missing_cases, out_of_range, parametrize,
                       refused)
from test_core import helix_data, twisted_cubic  # noqa: E402

V = FreeCAD.Vector


class Inputs:
    """Valid FreeCAD inputs, built when a case first needs them."""

    @functools.cached_property
    def spline(self):
        return rmfsurf.ph_spline_hermite(*helix_data())

    @functools.cached_property
    def line(self):
        return Part.makeLine(V(0, 0, 0), V(10, 0, 0))

    @functools.cached_property
    def wire(self):
        return Part.Wire([Part.makeLine(V(0, 0, 0), V(20, 0, 0)),
                          Part.makeLine(V(20, 0, 0), V(20, 20, 0))])

    @functools.cached_property
    def ring(self):
        return Part.Face(Part.Wire(Part.makeCircle(1.0, V(0, 0, 0), V(1, 0, 0))))

    @functools.cached_property
    def shape(self):
        return rmfsurf.wire_sweep([rmfsurf.Line((0, 0, 0), (10, 0, 0))], rfc.curve(
            Part.makeCircle(1.0, V(0, 0, 0), V(0, 0, 1))))

    @functools.cached_property
    def plane(self):
        return Part.makePlane(10, 4)

    @functools.cached_property
    def plate_face(self):
        return Part.makeBox(4, 3, 1).cut(Part.makeCylinder(0.5, 3, V(2, 1.5, -1))).Faces[0]

    @functools.cached_property
    def pattern(self):
        return rfc.unfold(self.plate_face)

    @functools.cached_property
    def developed(self):
        return rmfsurf.cone_spline_approximate(twisted_cubic(), (0.5, 6.0), 1e-3).develop()

    @functools.cached_property
    def square(self):
        return Part.makePolygon([V(-100, -100, 0), V(100, -100, 0), V(100, 100, 0),
                                 V(-100, 100, 0), V(-100, -100, 0)])

    @functools.cached_property
    def top(self):
        return Part.makeCircle(60.0, V(20, 0, 150), V(0, 0, 1))


IN = Inputs()


INTEGERS = [
    ("freecad.sweep_with_report(closure_symmetry)", 0, MAXIMUM["uint32_t"],
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, closure_symmetry=v)),
    ("freecad.cone_spline_from_face(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rfc.cone_spline_from_face(IN.plane, max_pieces=v)),
]


@pytest.mark.parametrize("case, value", parametrize(INTEGERS, lambda c: out_of_range(c[1], c[2])))
def test_an_integer_out_of_range_is_invalid_input_naming_the_argument_and_range(case, value):
    key, minimum, maximum, call = case
    message = refused(call, value, rmfsurf.InvalidInputError, argument(key))
    assert "%d to %d" % (minimum, maximum) in message, message


@pytest.mark.parametrize("case, value", parametrize(INTEGERS, lambda c: NOT_INTEGERS))
def test_a_non_integer_is_a_type_error_naming_the_argument(case, value):
    refused(case[3], value, TypeError, argument(case[0]))


NUMBERS = [
    ("freecad.spine_with_frames(tolerance)", lambda v: rfc.spine_with_frames(IN.spline,
                                                                             tolerance=v)),
    ("freecad.sweep_sketch_along_edge(tolerance)",
     lambda v: rfc.sweep_sketch_along_edge(None, IN.line, tolerance=v)),
    ("freecad.profile_curves(tolerance)",
     lambda v: rfc.profile_curves(IN.ring, (0, 0, 0), (1, 0, 0), v)),
    ("freecad.part_shape(tolerance)", lambda v: rfc.part_shape(IN.shape, v)),
    ("freecad.sweep(tolerance)", lambda v: rfc.sweep(IN.wire, IN.ring, tolerance=v)),
    ("freecad.sweep(corner_radius)", lambda v: rfc.sweep(IN.wire, IN.ring, corner_radius=v)),
    ("freecad.sweep_with_report(tolerance)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, tolerance=v)),
    ("freecad.sweep_with_report(corner_radius)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, corner_radius=v)),
    ("freecad.sweep_with_report(twist)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, twist=v)),
    ("freecad.cone_spline_from_face(tolerance)",
     lambda v: rfc.cone_spline_from_face(IN.plane, v)),
    ("freecad.flat_pattern_edges(t_min)",
     lambda v: rfc.flat_pattern_edges(IN.developed, v, 0.1)),
    ("freecad.flat_pattern_edges(t_max)",
     lambda v: rfc.flat_pattern_edges(IN.developed, -0.1, v)),
    ("freecad.transition(thickness)", lambda v: rfc.transition(IN.square, IN.top, v)),
    ("freecad.transition(k_factor)", lambda v: rfc.transition(IN.square, IN.top, k_factor=v)),
    ("freecad.transition(tolerance)", lambda v: rfc.transition(IN.square, IN.top, tolerance=v)),
    ("freecad.sweep_selection(tolerance)", lambda v: rfc.sweep_selection([], None, tolerance=v)),
    ("freecad.cone_spline_selection(tolerance)",
     lambda v: rfc.cone_spline_selection([], None, tolerance=v)),
    ("freecad.transition_selection(thickness)",
     lambda v: rfc.transition_selection([], None, thickness=v)),
    ("freecad.transition_selection(k_factor)",
     lambda v: rfc.transition_selection([], None, k_factor=v)),
    ("freecad.transition_selection(tolerance)",
     lambda v: rfc.transition_selection([], None, tolerance=v)),
    ("freecad.unfold(k_factor)", lambda v: rfc.unfold(IN.plate_face, k_factor=v)),
    ("freecad.unfold(tolerance)", lambda v: rfc.unfold(IN.plate_face, tolerance=v)),
    ("freecad.unfold(flat_tolerance)", lambda v: rfc.unfold(IN.plate_face, flat_tolerance=v)),
]


@pytest.mark.parametrize("case, value", parametrize(NUMBERS, lambda c: BEYOND_DOUBLE))
def test_a_number_beyond_a_double_is_invalid_input_naming_the_argument(case, value):
    refused(case[1], value, rmfsurf.InvalidInputError, argument(case[0]))


#: The arguments where None means "the library's default".
OPTIONAL = {"freecad.sweep(corner_radius)", "freecad.sweep_with_report(corner_radius)"}


@pytest.mark.parametrize("case, value", parametrize(
    NUMBERS, lambda c: [v for v in NOT_NUMBERS if v is not None or c[0] not in OPTIONAL]))
def test_a_non_number_is_a_type_error_naming_the_argument(case, value):
    refused(case[1], value, TypeError, argument(case[0]))


@pytest.mark.parametrize("case, value", parametrize(NUMBERS, lambda c: NON_FINITE))
def test_nan_and_infinity_are_invalid_input_naming_the_argument(case, value):
    refused(case[1], value, rmfsurf.InvalidInputError, argument(case[0]))


BAD_VECTORS = [((0.0, 1.0), ValueError), ([[0, 0, 1]], ValueError), (("a", 0, 1), TypeError),
               ((0, 0, 10 ** 400), rmfsurf.InvalidInputError)]
ARRAYS = [
    ("freecad.vector(p)", lambda v: rfc.vector(v)),
    ("freecad.spine_with_frames(initial_normal)",
     lambda v: rfc.spine_with_frames(IN.spline, initial_normal=v)),
    ("freecad.sweep_sketch_along_edge(initial_normal)",
     lambda v: rfc.sweep_sketch_along_edge(None, IN.line, initial_normal=v)),
    ("freecad.profile_curves(origin)", lambda v: rfc.profile_curves(IN.ring, v, (1, 0, 0))),
    ("freecad.profile_curves(tangent)", lambda v: rfc.profile_curves(IN.ring, (0, 0, 0), v)),
]


@pytest.mark.parametrize("case, bad", parametrize(ARRAYS, lambda c: BAD_VECTORS))
def test_a_bad_vector_names_the_argument(case, bad):
    value, exception = bad
    refused(case[1], value, exception, argument(case[0]))


def test_non_finite_placements_are_invalid_input():
    for value in ((0, math.nan, 0), (math.inf, 0, 0)):
        refused(lambda v: rfc.profile_curves(IN.ring, v, (1, 0, 0)), value,
                rmfsurf.InvalidInputError, "origin")
    for value in ((0, 0, 0), (math.nan, 0, 0)):
        refused(lambda v: rfc.profile_curves(IN.ring, (0, 0, 0), v), value,
                rmfsurf.InvalidInputError, "tangent")


PAIRS = [
    ("freecad.sweep(scale)", lambda v: rfc.sweep(IN.wire, IN.ring, scale=v)),
    ("freecad.sweep_with_report(scale)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, scale=v)),
]
BAD_PAIRS = [
    (3.0, TypeError, ""), ((0.0, 1.0, 2.0), ValueError, ""), ((1.0,), ValueError, ""),
    (("1", 1.0), TypeError, "[0]"), ((1.0, None), TypeError, "[1]"),
    ((10 ** 400, 1.0), rmfsurf.InvalidInputError, "[0]"),
    ((1.0, math.nan), rmfsurf.InvalidInputError, "[1]"),
    ((0.0, 1.0), rmfsurf.InvalidInputError, "[0]"), ((1.0, -0.5), rmfsurf.InvalidInputError, "[1]"),
]


@pytest.mark.parametrize("case, bad", parametrize(PAIRS, lambda c: BAD_PAIRS))
def test_a_bad_scale_names_the_argument_and_the_item(case, bad):
    value, exception, item = bad
    refused(case[1], value, exception, argument(case[0]) + item)


KNOTS = [
    ("freecad.sweep(scale_knots)", lambda v: rfc.sweep(IN.wire, IN.ring, scale_knots=v)),
    ("freecad.sweep_with_report(scale_knots)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, scale_knots=v)),
]
BAD_KNOTS = [
    (0.5, TypeError, ""), ([0.5, 2.0], TypeError, "[0]"), ([(0.5,)], ValueError, "[0]"),
    ([("0.5", 2.0)], TypeError, "[0][0]"), ([(math.nan, 2.0)], rmfsurf.InvalidInputError, "[0][0]"),
    ([(1.0, 2.0)], rmfsurf.InvalidInputError, "[0][0]"),
    ([(0.5, 2.0), (0.25, 1.0)], rmfsurf.InvalidInputError, "[1][0]"),
    ([(0.5, 0.0)], rmfsurf.InvalidInputError, "[0][1]"),
    ([(0.5, math.nan)], rmfsurf.InvalidInputError, "[0][1]"),
]


@pytest.mark.parametrize("case, bad", parametrize(KNOTS, lambda c: BAD_KNOTS))
def test_bad_scale_knots_name_the_argument_and_the_item(case, bad):
    value, exception, item = bad
    refused(case[1], value, exception, argument(case[0]) + item)


FRAMES = [
    ("freecad.sweep(frame)", lambda v: rfc.sweep(IN.wire, IN.ring, frame=v)),
    ("freecad.sweep_with_report(frame)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, frame=v)),
]
BAD_FRAMES = [
    ("binormal", ValueError), ("fixed", ValueError), (("fixed",), ValueError),
    ({"fixd": (0, 0, 1)}, ValueError), (("fixed", (0, 1)), ValueError),
    (("fixed", (0, 0, 0)), rmfsurf.InvalidInputError),
    ({"fixed": (0, math.nan, 1)}, rmfsurf.InvalidInputError), (3, TypeError), (None, TypeError),
    # Guides: a Part.Wire/Part.Edge/sketch, converted as the wire is.
    ("guide", ValueError), (("guide",), ValueError), (("guide", 3), TypeError),
    ({"guide": None}, TypeError), (("guide", []), TypeError),
    (("guide", rmfsurf.Line((0, 5, 0), (20, 5, 0))), TypeError),
]


@pytest.mark.parametrize("case", FRAMES)
def test_a_guide_beside_part_of_the_wire_is_refused_naming_the_frame(case):
    """The library's refusal of a guide along the first leg's first metre only."""
    for frame in (("guide", Part.makeLine(V(0, 5, 0), V(1, 5, 0))),
                  {"guide": Part.Wire([Part.makeLine(V(0, 5, 0), V(1, 5, 0))])}):
        refused(case[1], frame, rmfsurf.InvalidInputError, argument(case[0]))


@pytest.mark.parametrize("case, bad", parametrize(FRAMES, lambda c: BAD_FRAMES))
def test_a_bad_frame_names_the_argument(case, bad):
    value, exception = bad
    refused(case[1], value, exception, argument(case[0]))


METHODS = [
    ("freecad.sweep(method)", lambda v: rfc.sweep(IN.wire, IN.ring, method=v)),
    ("freecad.sweep_with_report(method)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, method=v)),
]
BAD_METHODS = [
    ("frenet", ValueError), ("PH-RMF", ValueError), ("ph_rmf", ValueError),
    ("moebius", ValueError), ("", ValueError), (None, TypeError), (2, TypeError),
    (b"mobius", TypeError),
]


@pytest.mark.parametrize("case, bad", parametrize(METHODS, lambda c: BAD_METHODS))
def test_a_bad_method_names_the_argument(case, bad):
    value, exception = bad
    refused(case[1], value, exception, argument(case[0]))


def test_every_method_of_a_wire_sweep_has_its_cases():
    """Every function of the adapter taking both `frame` and `method` (a wire sweep) has
    METHODS cases, and takes each method of wire sweeps."""
    required = {"freecad.%s(method)" % name for name in dir(rfc)
                if not name.startswith("_") and inspect.isfunction(getattr(rfc, name))
                and getattr(rfc, name).__module__ == "rmfsurf.freecad"
                and {"frame", "method"} <= set(inspect.signature(getattr(rfc, name)).parameters)}
    assert {"freecad.sweep(method)", "freecad.sweep_with_report(method)"} <= required, required
    assert required <= {c[0] for c in METHODS}, required - {c[0] for c in METHODS}
    for _, call in METHODS:
        for method in ("ph-rmf", "mobius", "rrmf"):
            call(method)


def test_wrong_objects_name_the_argument():
    refused(lambda v: rfc.spine_with_frames(v), IN.line, TypeError, "spine")
    refused(lambda v: rfc.spine_with_frames(IN.spline, v), "ph_rmf", ValueError, "method")
    refused(lambda v: rfc.path_edges(v), 3, TypeError, "path")
    refused(lambda v: rfc.sweep(v, IN.ring), 3, TypeError, "wire")
    refused(lambda v: rfc.cone_spline_from_face(v), IN.line, TypeError, "face")
    refused(lambda v: rfc.flat_pattern_edges(v, -0.1, 0.1), IN.spline, TypeError, "developed")
    refused(lambda v: rfc.part_solid(v), IN.developed, TypeError, "part")
    refused(lambda v: rfc.flat_pattern(v), IN.developed, TypeError, "part")


def test_spine_with_frames_is_the_librarys_framed_spine():
    for method in rfc.METHODS:
        curve, frames = rfc.spine_with_frames(IN.spline, method, 1e-5)
        same, _, distance = rmfsurf.framed_spine(IN.spline, method, 1e-5)
        assert curve.segment_count == same.segment_count, method
        assert distance <= 1e-5, (method, distance)
        assert frames.domain == curve.domain


# End profiles (a sweep between two profiles), drawn at the wire's start like the profile.
END_PROFILES = [
    ("freecad.sweep(end_profile)", lambda v: rfc.sweep(IN.wire, IN.ring, end_profile=v)),
    ("freecad.sweep_with_report(end_profile)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, end_profile=v)),
]


def _end_ring(radius, normal=(1, 0, 0), hole=None):
    """A circle face of `radius` about the wire's start, in the plane of `normal`, with a
    hole of radius `hole`."""
    face = Part.Face(Part.Wire(Part.makeCircle(radius, V(0, 0, 0), V(*normal))))
    if hole is not None:
        face = face.cut(Part.Face(Part.Wire(Part.makeCircle(hole, V(0, 0, 0), V(*normal)))))
    return face


BAD_END_PROFILES = [
    ("int", lambda: 3, TypeError, "end_profile"),
    ("str", lambda: "circle", TypeError, "end_profile"),
    ("a hole", lambda: _end_ring(0.5, hole=0.2), rmfsurf.InvalidInputError,
     "end_profile: it has 1 holes, the profile 0"),
    ("tilted", lambda: _end_ring(0.5, normal=(1, 1, 0)), rmfsurf.InvalidInputError,
     "end_profile"),
]


@pytest.mark.parametrize("case, bad", [
    pytest.param(c, b, id="%s-%s" % (c[0], b[0])) for c in END_PROFILES for b in BAD_END_PROFILES])
def test_a_bad_end_profile_names_the_argument(case, bad):
    _, value, exception, mention = bad
    refused(case[1], value(), exception, mention)


def test_every_end_profile_of_the_adapter_has_its_cases_and_is_taken():
    """Every function of the adapter taking `end_profile` has END_PROFILES cases, each
    taking a smaller circle drawn at the wire's start into a closed solid."""
    required = {"freecad.%s(end_profile)" % name for name in dir(rfc)
                if not name.startswith("_") and inspect.isfunction(getattr(rfc, name))
                and getattr(getattr(rfc, name), "__module__", "") == "rmfsurf.freecad"
                and "end_profile" in inspect.signature(getattr(rfc, name)).parameters}
    assert {"freecad.sweep(end_profile)", "freecad.sweep_with_report(end_profile)"} <= required
    assert required <= {c[0] for c in END_PROFILES}, required - {c[0] for c in END_PROFILES}
    for _, call in END_PROFILES:
        result = call(_end_ring(0.5))
        solid = result[0] if isinstance(result, tuple) else result
        assert solid.isValid() and solid.ShapeType == "Solid"


# Sections (a sweep through sections): (at, profile) items between the profile and the end
# profile, each drawn at the wire's start like it; refusals name sections[k].
SECTIONS = [
    ("freecad.sweep(sections)",
     lambda v: rfc.sweep(IN.wire, IN.ring, end_profile=_end_ring(0.5), sections=v)),
    ("freecad.sweep_with_report(sections)",
     lambda v: rfc.sweep_with_report(IN.wire, IN.ring, end_profile=_end_ring(0.5),
                                     sections=v)),
]

BAD_SECTIONS = [
    ("int", lambda: 3, TypeError, "sections"),
    ("an item of three", lambda: [(0.5, _end_ring(0.8), 1)], TypeError, "sections[0]"),
    ("a profile that is none", lambda: [(0.5, 3)], TypeError, "sections[0]"),
    ("at 1", lambda: [(1.0, _end_ring(0.8))], rmfsurf.InvalidInputError,
     "sections[0].at = 1 must be in (0, 1)"),
    ("out of order", lambda: [(0.5, _end_ring(0.8)), (0.25, _end_ring(0.7))],
     rmfsurf.InvalidInputError, "sections[1].at = 0.25 must be in (0.5, 1)"),
    ("a hole", lambda: [(0.5, _end_ring(0.8, hole=0.2))], rmfsurf.InvalidInputError,
     "sections[0].holes: it has 1 holes, the profile 0"),
    ("tilted", lambda: [(0.5, _end_ring(0.8, normal=(1, 1, 0)))], rmfsurf.InvalidInputError,
     "sections[0]"),
]


@pytest.mark.parametrize("case, bad", [
    pytest.param(c, b, id="%s-%s" % (c[0], b[0])) for c in SECTIONS for b in BAD_SECTIONS])
def test_bad_sections_name_the_argument(case, bad):
    _, value, exception, mention = bad
    refused(case[1], value(), exception, mention)


def test_every_sections_argument_of_the_adapter_has_its_cases_and_is_taken():
    """Every function of the adapter taking `sections` has SECTIONS cases, each taking two
    circles drawn at the wire's start into a closed solid; without an end profile they are
    refused naming `sections`."""
    required = {"freecad.%s(sections)" % name for name in dir(rfc)
                if not name.startswith("_") and inspect.isfunction(getattr(rfc, name))
                and getattr(getattr(rfc, name), "__module__", "") == "rmfsurf.freecad"
                and "sections" in inspect.signature(getattr(rfc, name)).parameters}
    assert {"freecad.sweep(sections)", "freecad.sweep_with_report(sections)"} <= required
    assert required <= {c[0] for c in SECTIONS}, required - {c[0] for c in SECTIONS}
    for _, call in SECTIONS:
        result = call([(0.25, _end_ring(0.8)), (0.5, _end_ring(0.6))])
        solid = result[0] if isinstance(result, tuple) else result
        assert solid.isValid() and solid.ShapeType == "Solid"
    refused(lambda v: rfc.sweep(IN.wire, IN.ring, sections=v), [(0.5, _end_ring(0.8))],
            rmfsurf.InvalidInputError, "sections: need end_profile")


# Paths: (key, call). A name with a NUL or an empty one is refused and nothing is written;
# what is no path is a TypeError; a good one gets the file.

PATHS = [("freecad.FlatPattern.write_dxf(path)", lambda v: IN.pattern.write_dxf(v))]


@pytest.mark.parametrize("case, value", parametrize(
    PATHS, lambda c: ["flat\0.dxf", "\0flat.dxf", b"flat\0.dxf", "", b""]))
def test_a_path_with_a_nul_or_empty_is_refused_and_nothing_is_written(case, value, tmp_path,
                                                                      monkeypatch):
    monkeypatch.chdir(tmp_path)
    refused(case[1], value, rmfsurf.InvalidInputError, argument(case[0]))
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("case, value", parametrize(PATHS, lambda c: [3, None, ["flat.dxf"]]))
def test_a_non_path_is_a_type_error(case, value, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    refused(case[1], value, TypeError, argument(case[0]))
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("case", PATHS, ids=[c[0] for c in PATHS])
def test_a_good_path_gets_the_file_and_a_bad_directory_a_file_error(case, tmp_path):
    case[1](tmp_path / "flat.dxf")
    assert (tmp_path / "flat.dxf").read_text().startswith("0\nSECTION\n")
    with pytest.raises(rmfsurf.FileError) as info:
        case[1](str(tmp_path / "no" / "flat.dxf"))
    assert "cannot write" in str(info.value) and "flat.dxf" in str(info.value)


CASES = {
    "path": {c[0] for c in PATHS},
    "integer": {c[0] for c in INTEGERS},
    "number": {c[0] for c in NUMBERS},
    "array": {c[0] for c in ARRAYS},
    "pair": {c[0] for c in PAIRS},
}


def test_every_argument_of_the_adapter_has_its_cases():
    required = api_arguments(rfc, "freecad.", "rmfsurf.freecad")
    assert len(required) >= 25, required
    assert missing_cases(required, CASES) == []
