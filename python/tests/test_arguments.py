"""Bad arguments of every public function of the package and of rmfsurf.ocp (issue 25):
paths, integers for C, numbers, sequences of objects, pairs, boxes and arrays. Each class is
checked on every function that takes it, with the exception docs/python.md promises and a
message naming the argument; a path is never cut at a NUL and nothing is written for a
refused one. test_every_argument_of_the_api_has_its_cases lists the API's arguments by
their annotations, so that a new function without cases fails. rmfsurf.freecad runs the
same checks in FreeCAD's Python (freecad_arguments.py, test_the_freecad_adapter_...).
Run by integration/tests/python.rs."""

import builtins
import functools
import inspect
import math
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import rmfsurf
from arguments import (BEYOND_DOUBLE, MAXIMUM, NON_FINITE, NOT_INTEGERS, NOT_NUMBERS,
                       api_arguments, argument, missing_cases, names, out_of_range, outcome,
                       parametrize, refused)
from test_core import circle, helix_data, twisted_cubic
from test_sheets import circle as top_circle
from test_sheets import square, twisted_cubic_rails

S = math.sqrt(0.5)


def cubic_element(t):
    """The Hermite element of the twisted cubic's tangent surface at t."""
    d1, d2 = np.array([1, 2 * t, 3 * t * t]), np.array([0.0, 2.0, 6 * t])
    ruling = d1 / np.linalg.norm(d1)
    side = d2 - np.dot(d2, ruling) * ruling
    return rmfsurf.ConeElement((t, t * t, t ** 3), ruling, side / np.linalg.norm(side))


class Inputs:
    """Valid inputs, built when a case first needs them."""

    @functools.cached_property
    def spline(self):
        return rmfsurf.ph_spline_hermite(*helix_data())

    @functools.cached_property
    def frames(self):
        return rmfsurf.ph_rational_rmf(self.spline)

    @functools.cached_property
    def profile(self):
        return circle()

    @functools.cached_property
    def surface(self):
        return rmfsurf.sweep_surface(self.spline, self.frames, self.profile)

    @functools.cached_property
    def edges(self):
        return [rmfsurf.Line((0, 0, 0), (10, 0, 0)), rmfsurf.Line((10, 0, 0), (10, 10, 0))]

    @functools.cached_property
    def shape(self):
        return rmfsurf.wire_sweep(self.edges, circle(1.0), corner_radius=2.0)

    @functools.cached_property
    def cone(self):
        return rmfsurf.cone_spline_approximate(twisted_cubic(), (0.5, 6.0), 1e-3)

    @functools.cached_property
    def elements(self):
        return [cubic_element(t) for t in (0.3, 0.5, 0.7)]

    @functools.cached_property
    def rails(self):
        return twisted_cubic_rails()[0]

    @functools.cached_property
    def part(self):
        return rmfsurf.part_between_rails(self.rails, thickness=0.02, tolerance=1e-3)

    @functools.cached_property
    def square(self):
        return square()

    @functools.cached_property
    def top(self):
        return top_circle()

    @functools.cached_property
    def hermite(self):
        """G1 data of one non-planar RRMF segment: p0, t0, p1, t1."""
        p, d = helix_data(3)
        return p[0], d[0], p[1], d[1]

    @functools.cached_property
    def solution(self):
        return rmfsurf.rrmf_quintic_best(*self.hermite)

    @functools.cached_property
    def ocp(self):
        return pytest.importorskip("rmfsurf.ocp")

    @functools.cached_property
    def bd(self):
        return pytest.importorskip("build123d")

    @functools.cached_property
    def route(self):
        return self.bd.Polyline((0, 0, 0), (20, 0, 0), (20, 20, 0))

    @functools.cached_property
    def ring(self):
        bd = self.bd
        return bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0)) * bd.Circle(1.0)

    @functools.cached_property
    def solid(self):
        return self.ocp.shape(self.shape)

    @functools.cached_property
    def brep(self):
        return rmfsurf.Brep.create(SQUARE, SQUARE_EDGES, [SQUARE_FACE])

    @functools.cached_property
    def unfolded(self):
        return rmfsurf.unfold_face(self.brep)

    @functools.cached_property
    def body(self):
        return self.ocp.body_brep(self.bd.Box(4, 3, 1))

    @functools.cached_property
    def unfolded_body(self):
        return rmfsurf.unfold_body(self.body)

    @functools.cached_property
    def plate_face(self):
        return (self.bd.Box(4, 3, 1) - self.bd.Cylinder(0.5, 2)).faces().sort_by(
            self.bd.Axis.Z)[-1]

    @functools.cached_property
    def pattern(self):
        return self.ocp.unfold(self.plate_face)


#: A unit square as plain B-rep data (rmfsurf.Brep.create).
SQUARE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
SQUARE_EDGES = [rmfsurf.BrepEdge(rmfsurf.line_curve(SQUARE[k], SQUARE[(k + 1) % 4]), k,
                                 (k + 1) % 4) for k in range(4)]
SQUARE_FACE = rmfsurf.BrepFace([[(k, True) for k in range(4)]],
                               plane=((0, 0, 0), (0, 0, 1), (1, 0, 0)))

IN = Inputs()
INVERSION = rmfsurf.Inversion((0.0, 0.0, 5.0), 2.0)
DUAL = dict(degree=2, planes=[[0, 1, 0, -0.5], [0, 1, 1, -0.5], [0, 0, 1, -0.5]],
            knots=[0, 0, 0, 1, 1, 1], region=((-3, -3, 1), (3, 3, 2)), tolerance=1e-4)


def dual(**changed):
    return rmfsurf.cone_spline_approximate_dual(**dict(DUAL, **changed))


def helix(t):
    return (math.cos(t), math.sin(t), 0.2 * t), (-math.sin(t), math.cos(t), 0.2)


# ---------------------------------------------------------------------------------------
# Integers for C: (key, minimum, maximum, call).

INTEGERS = [
    ("developability(face)", 0, MAXIMUM["size_t"], lambda v: rmfsurf.developability(IN.brep, v)),
    ("unfold_face(face)", 0, MAXIMUM["size_t"], lambda v: rmfsurf.unfold_face(IN.brep, v)),
    ("unfold_face(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.unfold_face(IN.brep, max_pieces=v)),
    ("unfold_body(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.unfold_body(IN.body, max_pieces=v)),
    ("Curve.from_nurbs(degree)", 1, MAXIMUM["uint32_t"],
     lambda v: rmfsurf.Curve.from_nurbs(v, [[0, 0, 0], [1, 0, 0], [1, 1, 0]], [0, 0, 0, 1, 1, 1])),
    ("Surface.from_nurbs(degree_u)", 1, MAXIMUM["uint32_t"],
     lambda v: rmfsurf.Surface.from_nurbs(v, 1, np.zeros((2, 2, 3)), [0, 0, 1, 1], [0, 0, 1, 1])),
    ("Surface.from_nurbs(degree_v)", 1, MAXIMUM["uint32_t"],
     lambda v: rmfsurf.Surface.from_nurbs(1, v, np.zeros((2, 2, 3)), [0, 0, 1, 1], [0, 0, 1, 1])),
    ("Surface.tessellate(u_steps)", 1, MAXIMUM["uint32_t"], lambda v: IN.surface.tessellate(v, 2)),
    ("Surface.tessellate(v_steps)", 1, MAXIMUM["uint32_t"], lambda v: IN.surface.tessellate(2, v)),
    ("mobius_rrmf_approximate(segments)", 1, MAXIMUM["size_t"],
     lambda v: rmfsurf.mobius_rrmf_approximate(IN.spline, v)),
    ("rrmf_spline_hermite(eta_samples)", 1, MAXIMUM["size_t"],
     lambda v: rmfsurf.rrmf_spline_hermite(*helix_data(3), eta_samples=v)),
    ("rrmf_quintic_best(eta_samples)", 1, MAXIMUM["size_t"],
     lambda v: rmfsurf.rrmf_quintic_best(*IN.hermite, eta_samples=v)),
    ("ph_rational_rmf(closure_symmetry)", 0, MAXIMUM["uint32_t"],
     lambda v: rmfsurf.ph_rational_rmf(IN.spline, closure_symmetry=v)),
    ("double_reflection_frames(samples)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.double_reflection_frames(IN.spline, samples=v)),
    ("parabolic_points(v_samples)", 2, MAXIMUM["uint32_t"],
     lambda v: rmfsurf.parabolic_points(IN.spline, IN.frames, IN.profile, v)),
    ("cone_spline_approximate(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.cone_spline_approximate(twisted_cubic(), (0.5, 6.0), 1e-3, max_pieces=v)),
    ("cone_spline_approximate_ruled(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.cone_spline_approximate_ruled(IN.rails, 1e-3, max_pieces=v)),
    ("cone_spline_approximate_dual(degree)", 1, MAXIMUM["uint32_t"], lambda v: dual(degree=v)),
    ("cone_spline_approximate_dual(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: dual(max_pieces=v)),
    ("wire_sweep(closure_symmetry)", 0, MAXIMUM["uint32_t"],
     lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), closure_symmetry=v)),
    ("transition(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.transition(IN.square, IN.top, max_pieces=v)),
    ("part_between_rails(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.part_between_rails(IN.rails, max_pieces=v)),
    ("tangent_part(max_pieces)", 2, MAXIMUM["size_t"],
     lambda v: rmfsurf.tangent_part(twisted_cubic(), 0.3, 0.9, max_pieces=v)),
]


@pytest.mark.parametrize("case, value", parametrize(INTEGERS, lambda c: out_of_range(c[1], c[2])))
def test_an_integer_out_of_its_c_range_is_invalid_input_naming_the_argument_and_range(case, value):
    key, minimum, maximum, call = case
    message = refused(call, value, rmfsurf.InvalidInputError, argument(key))
    assert "%d to %d" % (minimum, maximum) in message, message


@pytest.mark.parametrize("case, value", parametrize(INTEGERS, lambda c: NOT_INTEGERS))
def test_a_non_integer_is_a_type_error_naming_the_argument(case, value):
    refused(case[3], value, TypeError, argument(case[0]))


def test_numpy_integers_are_integers():
    points, triangles = IN.surface.tessellate(np.int64(2), np.uint8(1))
    assert triangles.shape[0] == 2 * (2 * 1) * np.prod(IN.surface.patch_count)


# ---------------------------------------------------------------------------------------
# Numbers (C doubles): (key, call).

NUMBERS = [
    ("ph_spline_approximate(tolerance)", lambda v: rmfsurf.ph_spline_approximate(IN.spline, v)),
    ("framed_spine(tolerance)", lambda v: rmfsurf.framed_spine(IN.spline, "ph-rmf", v)),
    ("circle(radius)", lambda v: rmfsurf.circle(v)),
    ("obround(length)", lambda v: rmfsurf.obround(v, 1.0)),
    ("obround(radius)", lambda v: rmfsurf.obround(2.0, v)),
    ("profile_offset(distance)", lambda v: rmfsurf.profile_offset(IN.profile, v)),
    ("profile_offset_by_arcs(distance)",
     lambda v: rmfsurf.profile_offset_by_arcs(IN.profile, v, 1e-4)),
    ("profile_offset_by_arcs(tolerance)",
     lambda v: rmfsurf.profile_offset_by_arcs(IN.profile, 0.1, v)),
    ("rrmf_quintic_solutions(eta)", lambda v: rmfsurf.rrmf_quintic_solutions(*IN.hermite, v)),
    ("mobius_point(maps[0].radius)",
     lambda v: rmfsurf.mobius_point([rmfsurf.Inversion((0, 0, 5), v)], (1, 0, 0))),
    ("ph_rational_rmf(twist)", lambda v: rmfsurf.ph_rational_rmf(IN.spline, twist=v)),
    ("gaussian_curvature(u)",
     lambda v: rmfsurf.gaussian_curvature(IN.spline, IN.frames, IN.profile, v, 1.0)),
    ("gaussian_curvature(v)",
     lambda v: rmfsurf.gaussian_curvature(IN.spline, IN.frames, IN.profile, 1.0, v)),
    ("parabolic_curves(tolerance)",
     lambda v: rmfsurf.parabolic_curves(IN.spline, IN.frames, IN.profile, v)),
    ("wire_sweep(tolerance)", lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), tolerance=v)),
    ("wire_sweep(join_tolerance)",
     lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), join_tolerance=v)),
    ("wire_sweep(corner_radius)",
     lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), corner_radius=v)),
    ("wire_sweep(twist)", lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), twist=v)),
    ("ConeSpline.surface(t_min)", lambda v: IN.cone.surface(v, 0.1)),
    ("ConeSpline.surface(t_max)", lambda v: IN.cone.surface(-0.1, v)),
    ("ConeSpline.boundary(t)", lambda v: IN.cone.boundary(v)),
    ("ConeSpline.bend(s)", lambda v: IN.cone.bend(v)),
    ("ConeSpline.offset(d)", lambda v: IN.cone.offset(v)),
    ("ConeSpline.flat_pattern(t_min)", lambda v: IN.cone.flat_pattern(v, 0.1)),
    ("ConeSpline.flat_pattern(t_max)", lambda v: IN.cone.flat_pattern(-0.1, v)),
    ("cone_spline_hermite(parameter)",
     lambda v: rmfsurf.cone_spline_hermite(IN.elements, rule="given", parameter=v)),
    ("cone_spline_approximate(tolerance)",
     lambda v: rmfsurf.cone_spline_approximate(twisted_cubic(), (0.5, 6.0), v)),
    ("cone_spline_approximate_ruled(tolerance)",
     lambda v: rmfsurf.cone_spline_approximate_ruled(IN.rails, v)),
    ("cone_spline_approximate_dual(tolerance)", lambda v: dual(tolerance=v)),
    ("SheetPart.surface_to_flat(max_distance)",
     lambda v: IN.part.surface_to_flat(IN.part.flat_to_surface([[0.0, 0.0]]), max_distance=v)),
    ("join_nurbs(tolerance)", lambda v: rmfsurf.join_nurbs([IN.profile.nurbs()], tolerance=v)),
]
for _function, _call in [
        ("transition", lambda **o: rmfsurf.transition(IN.square, IN.top, **o)),
        ("part_between_rails", lambda **o: rmfsurf.part_between_rails(IN.rails, **o)),
        ("tangent_part", lambda **o: rmfsurf.tangent_part(twisted_cubic(), 0.3, 0.9, **o))]:
    for _option in ("thickness", "k_factor", "tolerance", "flat_tolerance"):
        NUMBERS.append(("%s(%s)" % (_function, _option),
                        lambda v, c=_call, o=_option: c(**{o: v})))
NUMBERS += [
    ("unfold_face(tolerance)", lambda v: rmfsurf.unfold_face(IN.brep, tolerance=v)),
    ("unfold_face(flat_tolerance)", lambda v: rmfsurf.unfold_face(IN.brep, flat_tolerance=v)),
    ("unfold_body(tolerance)", lambda v: rmfsurf.unfold_body(IN.body, tolerance=v)),
    ("unfold_body(flat_tolerance)", lambda v: rmfsurf.unfold_body(IN.body, flat_tolerance=v)),
    ("ocp.unfold(k_factor)", lambda v: IN.ocp.unfold(IN.plate_face, k_factor=v)),
    ("ocp.unfold(tolerance)", lambda v: IN.ocp.unfold(IN.plate_face, tolerance=v)),
    ("ocp.unfold(flat_tolerance)", lambda v: IN.ocp.unfold(IN.plate_face, flat_tolerance=v)),
    ("tangent_part(v_min)", lambda v: rmfsurf.tangent_part(twisted_cubic(), v, 0.9)),
    ("tangent_part(v_max)", lambda v: rmfsurf.tangent_part(twisted_cubic(), 0.3, v)),
    ("ocp.face(tolerance)", lambda v: IN.ocp.face(IN.surface, v)),
    ("ocp.shape(tolerance)", lambda v: IN.ocp.shape(IN.shape, v)),
    ("ocp.volume(relative_error)", lambda v: IN.ocp.volume(IN.solid, v)),
    ("ocp.sweep(tolerance)", lambda v: IN.ocp.sweep(IN.route, IN.ring, tolerance=v)),
    ("ocp.sweep(corner_radius)", lambda v: IN.ocp.sweep(IN.route, IN.ring, corner_radius=v)),
    ("ocp.profile_curves(tolerance)",
     lambda v: IN.ocp.profile_curves(IN.ring, (0, 0, 0), (1, 0, 0), v)),
]


@pytest.mark.parametrize("case, value", parametrize(NUMBERS, lambda c: BEYOND_DOUBLE))
def test_a_number_beyond_a_double_is_invalid_input_naming_the_argument(case, value):
    refused(case[1], value, rmfsurf.InvalidInputError, argument(case[0]))


#: The arguments where None means "the library's default".
OPTIONAL = {"wire_sweep(join_tolerance)", "wire_sweep(corner_radius)", "join_nurbs(tolerance)",
            "ocp.sweep(corner_radius)"}


@pytest.mark.parametrize("case, value", parametrize(
    NUMBERS, lambda c: [v for v in NOT_NUMBERS if v is not None or c[0] not in OPTIONAL]))
def test_a_non_number_is_a_type_error_naming_the_argument(case, value):
    refused(case[1], value, TypeError, argument(case[0]))


@pytest.mark.parametrize("case, value", parametrize(NUMBERS, lambda c: NON_FINITE))
def test_nan_and_infinity_are_invalid_input_naming_the_argument(case, value):
    refused(case[1], value, rmfsurf.InvalidInputError, argument(case[0]))


# ---------------------------------------------------------------------------------------
# Paths: (key, call). The library writes where the C string ends, so a NUL must never reach
# it; every accepted form must write exactly the file it names.

#: (key, call, what the written file starts with).
PATHS = [("Shape.write_step(path)", lambda v: IN.shape.write_step(v), b"ISO-10303-21;"),
         ("UnfoldedFace.write_dxf(path)", lambda v: IN.unfolded.write_dxf(v), b"0\nSECTION\n"),
         ("UnfoldedBody.write_dxf(path)", lambda v: IN.unfolded_body.write_dxf(v),
          b"0\nSECTION\n"),
         ("ocp.FlatPattern.write_dxf(path)", lambda v: IN.pattern.write_dxf(v),
          b"0\nSECTION\n")]

NUL_PATHS = ["pipe\0.step", "\0pipe.step", "pipe.step\0", b"pipe\0.step",
             pathlib.Path("pipe\0.step"), pathlib.PurePosixPath("dir\0/pipe.step"), "", b"",
             "pipe\ud800.step"]
NOT_PATHS = [3, None, 2.5, ["pipe.step"], bytearray(b"pipe.step"), ("pipe.step",)]


class PathLike:
    """An os.PathLike that is no pathlib path."""

    def __init__(self, path):
        self.path = path

    def __fspath__(self):
        return self.path


def _listing(directory):
    return sorted(os.listdir(os.fsencode(directory)))


@pytest.mark.parametrize("case, value", parametrize(PATHS, lambda c: NUL_PATHS))
def test_a_path_with_a_nul_or_empty_is_refused_and_nothing_is_written(case, value, tmp_path,
                                                                      monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "dir").mkdir()
    before = _listing(tmp_path), _listing(tmp_path / "dir")
    refused(case[1], value, rmfsurf.InvalidInputError, argument(case[0]))
    assert (_listing(tmp_path), _listing(tmp_path / "dir")) == before


@pytest.mark.parametrize("case, value", parametrize(PATHS, lambda c: NOT_PATHS))
def test_a_non_path_is_a_type_error_and_nothing_is_written(case, value, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    refused(case[1], value, TypeError, argument(case[0]))
    assert _listing(tmp_path) == []


GOOD_PATHS = [
    ("str", lambda d: str(d / "pipe.step"), b"pipe.step"),
    ("bytes", lambda d: os.fsencode(d / "pipe.step"), b"pipe.step"),
    ("relative bytes", lambda d: b"x.step", b"x.step"),
    ("pathlib", lambda d: d / "pipe.step", b"pipe.step"),
    ("os.PathLike", lambda d: PathLike(str(d / "pipe.step")), b"pipe.step"),
    ("os.PathLike of bytes", lambda d: PathLike(os.fsencode(d / "pipe.step")), b"pipe.step"),
    ("bytes not UTF-8", lambda d: os.fsencode(d) + b"/pipe\xff.step", b"pipe\xff.step"),
    ("str escaping bytes not UTF-8", lambda d: str(d) + "/pipe\udcff.step", b"pipe\xff.step"),
    ("str not ASCII", lambda d: str(d / "röhre.step"), "röhre.step".encode()),
]


@pytest.mark.parametrize("case", PATHS, ids=[c[0] for c in PATHS])
@pytest.mark.parametrize("name, make, written", GOOD_PATHS, ids=[g[0] for g in GOOD_PATHS])
def test_str_bytes_and_path_like_write_the_file_they_name(case, name, make, written, tmp_path,
                                                          monkeypatch):
    monkeypatch.chdir(tmp_path)
    case[1](make(tmp_path))
    assert _listing(tmp_path) == [written]
    with open(os.path.join(os.fsencode(tmp_path), written), "rb") as f:
        assert f.read().startswith(case[2])


@pytest.mark.parametrize("case", PATHS, ids=[c[0] for c in PATHS])
def test_a_file_that_cannot_be_written_is_a_file_error_naming_it(case, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(rmfsurf.FileError) as info:
        case[1](tmp_path / "no" / "such" / "pipe.step")
    assert isinstance(info.value, OSError)
    assert info.value.status_name == "RMF_ERROR_IO"
    assert "cannot write" in info.value.message and "pipe.step" in info.value.message
    assert _listing(tmp_path) == []


# ---------------------------------------------------------------------------------------
# Sequences of library objects: (key, call, one valid item). One item alone is a sequence
# of one; anything else that is not a sequence is a TypeError naming the argument, an item
# of another type a TypeError naming its index.

#: A straight open wire of length 3 (sweeps between two profiles).
BAR = [rmfsurf.Line((0, 0, 0), (3, 0, 0))]

OBJECTS = [
    ("Brep.create(edges)", lambda v: rmfsurf.Brep.create(SQUARE, v, []), SQUARE_EDGES[0]),
    ("Brep.create(faces)", lambda v: rmfsurf.Brep.create(SQUARE, SQUARE_EDGES, v), SQUARE_FACE),
    ("wire_sweep(edges)", lambda v: rmfsurf.wire_sweep(v, circle(1.0)),
     rmfsurf.Line((0, 0, 0), (10, 0, 0))),
    ("wire_sweep(holes)", lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), v,
                                                       corner_radius=2.0),
     circle(0.5)),
    ("wire_sweep(end_holes)",
     lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), circle(0.5), end_profile=circle(0.8),
                                  end_holes=v),
     circle(0.4)),
    ("mobius_point(maps)", lambda v: rmfsurf.mobius_point(v, (1, 0, 0)), INVERSION),
    ("mobius_curve(maps)", lambda v: rmfsurf.mobius_curve(IN.spline, v), INVERSION),
    ("mobius_frames(maps)", lambda v: rmfsurf.mobius_frames(IN.frames, v), INVERSION),
    ("cone_spline_hermite(elements)", lambda v: rmfsurf.cone_spline_hermite(v),
     cubic_element(0.3)),
    ("join_nurbs(pieces)", lambda v: rmfsurf.join_nurbs(v), circle().nurbs()),
]


@pytest.mark.parametrize("case", OBJECTS, ids=[c[0] for c in OBJECTS])
def test_one_object_where_a_sequence_is_expected_is_a_sequence_of_one(case):
    key, call, one = case
    alone, listed = outcome(call, one), outcome(call, [one])
    assert alone == listed or (alone != "ok" and listed != "ok" and alone[0] is listed[0]
                               and alone[1] == listed[1]), (alone, listed)
    if alone != "ok":  # e.g. one cone element is too few: the library's error, not a TypeError
        assert alone[0] is not TypeError, alone


@pytest.mark.parametrize("case, value", parametrize(OBJECTS, lambda c: [3, 2.5, "ab", b"ab", None]))
def test_a_non_sequence_is_a_type_error_naming_the_argument(case, value):
    refused(case[1], value, TypeError, argument(case[0]))


FOREIGN_ITEMS = [3, "x", None, INVERSION, rmfsurf.Line((0, 0, 0), (1, 0, 0))]


@pytest.mark.parametrize("case, bad", parametrize(
    OBJECTS, lambda c: [b for b in FOREIGN_ITEMS if not isinstance(b, type(c[2]))]))
def test_an_item_of_another_type_is_a_type_error_naming_its_index(case, bad):
    key, call, one = case
    message = refused(call, [one, bad], TypeError, argument(key) + "[1]")
    assert type(bad).__name__ in message


# ---------------------------------------------------------------------------------------
# Curves given as Python functions t -> (point, tangent): a value that is not two finite
# 3-vectors is refused naming the argument (the library would name "the callback").

CALLBACKS = [
    ("ph_spline_approximate(curve)", lambda f: rmfsurf.ph_spline_approximate(f, 1e-3, (0, 2))),
    ("mobius_rrmf_approximate(curve)", lambda f: rmfsurf.mobius_rrmf_approximate(f, 4,
                                                                                 domain=(0, 2))),
    ("cone_spline_approximate(curve)",
     lambda f: rmfsurf.cone_spline_approximate(f, (0.5, 2.0), 1e-3, domain=(0, 2))),
    ("cone_spline_osculating(curve)",
     lambda f: rmfsurf.cone_spline_osculating(f, (0.5, 2.0), [0.5, 1.0], domain=(0, 2))),
]


def returning(bad_point=None, bad_value=None):
    """The helix as a function, giving `bad_point` (or `bad_value` whole) from t = 0.5 on."""
    def function(t):
        if t < 0.5:
            return helix(t)
        return bad_value if bad_value is not None else (bad_point, helix(t)[1])
    function.label = "giving %r" % (bad_point if bad_value is None else bad_value,)
    return function


BAD_CALLBACKS = [
    (returning((10 ** 400, 0, 0)), rmfsurf.InvalidInputError),
    (returning((math.nan, 0, 0)), rmfsurf.InvalidInputError),
    (returning((0, math.inf, 0)), rmfsurf.InvalidInputError),
    (returning(("a", 0, 0)), TypeError), (returning((0, 0)), ValueError),
    (returning(bad_value=3.0), TypeError), (returning(bad_value=((0, 0, 0),)), TypeError),
]


@pytest.mark.parametrize("case, bad", parametrize(CALLBACKS, lambda c: BAD_CALLBACKS))
def test_a_curve_function_value_that_is_no_finite_point_names_the_argument(case, bad):
    function, exception = bad
    refused(case[1], function, exception, argument(case[0]))


# ---------------------------------------------------------------------------------------
# Pairs of numbers and boxes: (key, call).

PAIRS = [
    ("ph_spline_approximate(domain)",
     lambda v: rmfsurf.ph_spline_approximate(helix, 1e-3, domain=v)),
    ("mobius_rrmf_approximate(domain)",
     lambda v: rmfsurf.mobius_rrmf_approximate(helix, 4, domain=v)),
    ("cone_spline_approximate(domain)",
     lambda v: rmfsurf.cone_spline_approximate(helix, (0.5, 2.0), 1e-3, domain=v)),
    ("cone_spline_approximate(v_range)",
     lambda v: rmfsurf.cone_spline_approximate(twisted_cubic(), v, 1e-3)),
    ("cone_spline_osculating(domain)",
     lambda v: rmfsurf.cone_spline_osculating(helix, (0.5, 2.0), [0.5, 1.0], domain=v)),
    ("cone_spline_osculating(v_range)",
     lambda v: rmfsurf.cone_spline_osculating(twisted_cubic(), v, [0.3, 0.6])),
    ("wire_sweep(scale)", lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), scale=v)),
    ("ocp.sweep(scale)", lambda v: IN.ocp.sweep(IN.route, IN.ring, scale=v)),
]
BAD_PAIRS = [
    (3.0, TypeError, ""), ("ab", TypeError, ""), ((0.0, 1.0, 2.0), ValueError, ""),
    ((0.0,), ValueError, ""), (("0", 1.0), TypeError, "[0]"), ((0.0, None), TypeError, "[1]"),
    ((10 ** 400, 1.0), rmfsurf.InvalidInputError, "[0]"),
    ((0.0, math.nan), rmfsurf.InvalidInputError, "[1]"),
    ((-math.inf, 1.0), rmfsurf.InvalidInputError, "[0]"),
]


@pytest.mark.parametrize("case, bad", parametrize(PAIRS, lambda c: BAD_PAIRS))
def test_a_bad_pair_names_the_argument_and_the_item(case, bad):
    value, exception, item = bad
    refused(case[1], value, exception, argument(case[0]) + item)


#: Pairs that must be positive too (a profile's scale): (key, call).
POSITIVE_PAIRS = [c for c in PAIRS if argument(c[0]) == "scale"]


@pytest.mark.parametrize("case, bad", parametrize(POSITIVE_PAIRS, lambda c: [
    ((0.0, 1.0), "[0]"), ((1.0, -0.5), "[1]"), ((-1.0, -1.0), "[0]")]))
def test_a_scale_that_is_not_positive_is_invalid_input_naming_the_item(case, bad):
    value, item = bad
    refused(case[1], value, rmfsurf.InvalidInputError, argument(case[0]) + item)


# ---------------------------------------------------------------------------------------
# Knots of a scale law: a sequence of (fraction, scale) pairs, the fractions increasing in
# (0, 1), the scales positive. Not a class of the annotations: (key, call), each with every
# bad value (and the item the message must name after the argument).

KNOTS = [
    ("wire_sweep(scale_knots)",
     lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), scale_knots=v)),
    ("ocp.sweep(scale_knots)", lambda v: IN.ocp.sweep(IN.route, IN.ring, scale_knots=v)),
]
BAD_KNOTS = [
    (0.5, TypeError, ""), ("ab", TypeError, ""), ({0.5: 2.0}, TypeError, ""),
    ([0.5, 2.0], TypeError, "[0]"), ([(0.5,)], ValueError, "[0]"),
    ([(0.25, 2.0), (0.5, 1.0, 3.0)], ValueError, "[1]"), ([("0.5", 2.0)], TypeError, "[0][0]"),
    ([(0.5, None)], TypeError, "[0][1]"), ([(10 ** 400, 2.0)], rmfsurf.InvalidInputError, "[0][0]"),
    ([(math.nan, 2.0)], rmfsurf.InvalidInputError, "[0][0]"),
    ([(1.0, 2.0)], rmfsurf.InvalidInputError, "[0][0]"),
    ([(0.0, 2.0)], rmfsurf.InvalidInputError, "[0][0]"),
    ([(-0.5, 2.0)], rmfsurf.InvalidInputError, "[0][0]"),
    ([(0.5, 2.0), (0.25, 1.0)], rmfsurf.InvalidInputError, "[1][0]"),
    ([(0.5, 2.0), (0.5, 1.0)], rmfsurf.InvalidInputError, "[1][0]"),
    ([(0.5, 0.0)], rmfsurf.InvalidInputError, "[0][1]"),
    ([(0.25, 2.0), (0.5, -1.0)], rmfsurf.InvalidInputError, "[1][1]"),
    ([(0.5, math.nan)], rmfsurf.InvalidInputError, "[0][1]"),
    ([(0.5, math.inf)], rmfsurf.InvalidInputError, "[0][1]"),
]


@pytest.mark.parametrize("case, bad", parametrize(KNOTS, lambda c: BAD_KNOTS))
def test_bad_scale_knots_name_the_argument_and_the_item(case, bad):
    value, exception, item = bad
    refused(case[1], value, exception, argument(case[0]) + item)


# ---------------------------------------------------------------------------------------
# Frames of wire sweeps: "rmf", "frenet", ("fixed", (x, y, z)) or {"fixed": (x, y, z)}.
# Not a class of the annotations: (key, call), each with every bad frame.

FRAMES = [
    ("wire_sweep(frame)", lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), frame=v)),
    ("ocp.sweep(frame)", lambda v: IN.ocp.sweep(IN.route, IN.ring, frame=v)),
]
BAD_FRAMES = [
    ("binormal", ValueError), ("fixed", ValueError), ("RMF", ValueError),
    (("fixed",), ValueError), (("fixed", (0, 0, 1), 2), ValueError),
    (("frenet", (0, 0, 1)), ValueError), ({"fixd": (0, 0, 1)}, ValueError),
    ({"fixed": (0, 0, 1), "rmf": 1}, ValueError), (("fixed", (0, 1)), ValueError),
    (("fixed", ("a", 0, 1)), TypeError), ({"fixed": (0, 0, 10 ** 400)}, rmfsurf.InvalidInputError),
    (("fixed", (0, 0, 0)), rmfsurf.InvalidInputError),
    (("fixed", (0, math.nan, 1)), rmfsurf.InvalidInputError),
    ({"fixed": (math.inf, 0, 1)}, rmfsurf.InvalidInputError),
    (3, TypeError), (None, TypeError), (["fixed", (0, 0, 1)], TypeError), (b"rmf", TypeError),
]


@pytest.mark.parametrize("case, bad", parametrize(FRAMES, lambda c: BAD_FRAMES))
def test_a_bad_frame_names_the_argument(case, bad):
    value, exception = bad
    refused(case[1], value, exception, argument(case[0]))


# Guide frames: ("guide", edges) / {"guide": edges}, the edges what each function takes as
# its path (rmfsurf edges for wire_sweep, a build123d/OCP wire or edge for ocp.sweep). The
# forms both refuse alike, then each function's own: no edges, an edge of another kind, a
# point that is not finite, a guide along a part of the path only (the library's refusal).
BAD_GUIDE_FORMS = [
    ("guide", ValueError), (("guide",), ValueError), (("guide", [], 2), ValueError),
    ({"guide": [], "fixed": (0, 0, 1)}, ValueError), (("guide", 3), TypeError),
    (("guide", None), TypeError), (("guide", "line"), TypeError), ({"guide": 2.5}, TypeError),
]


@pytest.mark.parametrize("case, bad", parametrize(FRAMES, lambda c: BAD_GUIDE_FORMS))
def test_a_bad_guide_frame_names_the_frame(case, bad):
    value, exception = bad
    refused(case[1], value, exception, argument(case[0]))


#: (key, the guide as a function of the inputs, the exception).
BAD_GUIDES = [
    ("wire_sweep(frame)", lambda: [], rmfsurf.InvalidInputError),
    ("wire_sweep(frame)", lambda: [rmfsurf.Line((0, 5, 0), (0, 5, math.nan))],
     rmfsurf.InvalidInputError),
    ("wire_sweep(frame)", lambda: {"line": ((0, 5, 0), (10, 5, 0))}, TypeError),
    ("wire_sweep(frame)", lambda: [rmfsurf.Line((0, 5, 0), (1, 5, 0))],
     rmfsurf.InvalidInputError),
    ("ocp.sweep(frame)", lambda: [], TypeError),
    ("ocp.sweep(frame)", lambda: rmfsurf.Line((0, 5, 0), (20, 5, 0)), TypeError),
    ("ocp.sweep(frame)", lambda: IN.bd.Line((0, 5, 0), (1, 5, 0)), rmfsurf.InvalidInputError),
]


@pytest.mark.parametrize("key, guide, exception", BAD_GUIDES)
def test_a_bad_guide_names_the_frame(key, guide, exception):
    call = dict(FRAMES)[key]
    for frame in (("guide", guide()), {"guide": guide()}):
        refused(call, frame, exception, argument(key))


def test_a_guide_frame_is_taken_in_both_forms():
    """A guide of two lines (given out of order, one reversed) beside a line of 3: a solid,
    the frame error within a quarter of the tolerance at the profile's reach; the same
    shape in either form."""
    line = [rmfsurf.Line((0, 0, 0), (3, 0, 0))]
    guide = [rmfsurf.Line((3.5, 0, 2), (1.5, 2, 0)), rmfsurf.Line((-0.5, 2, 0), (1.5, 2, 0))]
    shapes = [rmfsurf.wire_sweep(line, circle(1.0), frame=frame)
              for frame in (("guide", guide), {"guide": guide})]
    assert shapes[0].occ_brep() == shapes[1].occ_brep()
    assert shapes[0].is_solid and shapes[0].report().frame_error <= 0.25e-4


# ---------------------------------------------------------------------------------------
# Methods of wire sweeps: "ph-rmf", "mobius" or "rrmf" ("frenet" is the frame's).
# Not a class of the annotations: (key, call), each with every bad method, and a coverage
# check of their own below.

METHODS = [
    ("wire_sweep(method)", lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), method=v)),
    ("ocp.sweep(method)", lambda v: IN.ocp.sweep(IN.route, IN.ring, method=v)),
]
BAD_METHODS = [
    ("frenet", ValueError), ("PH-RMF", ValueError), ("ph_rmf", ValueError),
    ("moebius", ValueError), ("", ValueError), ("rmf", ValueError),
    (None, TypeError), (2, TypeError), (b"mobius", TypeError), (["mobius"], TypeError),
]


@pytest.mark.parametrize("case, bad", parametrize(METHODS, lambda c: BAD_METHODS))
def test_a_bad_method_names_the_argument(case, bad):
    value, exception = bad
    refused(case[1], value, exception, argument(case[0]))


def test_frenet_as_a_wire_method_points_to_the_frame():
    message = refused(METHODS[0][1], "frenet", ValueError, "method")
    assert "frame='frenet'" in message, message


@pytest.mark.parametrize("case", METHODS, ids=[c[0] for c in METHODS])
def test_every_wire_method_is_taken(case):
    for method in ("ph-rmf", "mobius", "rrmf"):
        case[1](method)


def wire_sweep_functions():
    """(name, parameters) of the public functions of rmfsurf and rmfsurf.ocp ("ocp."
    prefixed; the adapter's own, not what it imports)."""
    ocp = pytest.importorskip("rmfsurf.ocp")
    for module, prefix in ((rmfsurf, ""), (ocp, "ocp.")):
        for name in dir(module):
            obj = getattr(module, name)
            if name.startswith("_") or not inspect.isfunction(obj):
                continue
            if getattr(obj, "__module__", "") != module.__name__ and module is ocp:
                continue
            yield prefix + name, inspect.signature(obj).parameters


def test_every_method_of_a_wire_sweep_has_its_cases():
    """Every public function taking both `frame` and `method` (a wire sweep) has METHODS
    cases."""
    required = {"%s(method)" % name for name, parameters in wire_sweep_functions()
                if "frame" in parameters and "method" in parameters}
    assert "wire_sweep(method)" in required and "ocp.sweep(method)" in required, required
    assert required <= {c[0] for c in METHODS}, required - {c[0] for c in METHODS}


# ---------------------------------------------------------------------------------------
# End profiles of wire sweeps (a sweep between two profiles): a curve (rmfsurf.wire_sweep)
# or a planar profile drawn at the path's start (the adapters). Not a class of the
# annotations: (key, call, a valid end profile), each with every bad value, and a coverage
# check of their own below.

END_PROFILES = [
    ("wire_sweep(end_profile)", lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), end_profile=v),
     lambda: circle(0.5)),
    ("ocp.sweep(end_profile)", lambda v: IN.ocp.sweep(IN.route, IN.ring, end_profile=v),
     lambda: IN.bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0)) * IN.bd.Circle(0.5)),
]


def _ring_in_a_tilted_plane():
    """A circle of radius 0.5 about the start in the plane z = x (not the normal plane)."""
    n = circle(0.5).nurbs()
    poles = np.array(n.poles, dtype=float)
    poles[:, 2] = poles[:, 0]
    return rmfsurf.Curve.from_nurbs(n.degree, poles, n.knots, n.weights)


def bad_end_profiles(case):
    """(label, value factory, exception, what the message names) for a case of
    END_PROFILES: no profile (TypeError), a hole the profile has not, a plane across the
    path that is not normal to it (the library's refusals, naming end_profile)."""
    bad = [("int", lambda: 3, TypeError, "end_profile"),
           ("str", lambda: "circle", TypeError, "end_profile"),
           ("list", lambda: [circle(0.5)], TypeError, "end_profile")]
    if case[0].startswith("ocp."):
        plane = lambda z_dir: IN.bd.Plane(origin=(0, 0, 0), z_dir=z_dir)  # noqa: E731
        bad += [("a hole", lambda: plane((1, 0, 0)) * (IN.bd.Circle(0.5) - IN.bd.Circle(0.2)),
                 rmfsurf.InvalidInputError, "end_profile: it has 1 holes, the profile 0"),
                ("tilted", lambda: plane((1, 1, 0)) * IN.bd.Circle(0.5),
                 rmfsurf.InvalidInputError, "end_profile")]
    else:
        bad.append(("tilted", _ring_in_a_tilted_plane, rmfsurf.InvalidInputError,
                    "end_profile"))
    return [pytest.param(case, b, id="%s-%s" % (case[0], b[0])) for b in bad]


@pytest.mark.parametrize("case, bad", [p for c in END_PROFILES for p in bad_end_profiles(c)])
def test_a_bad_end_profile_names_the_argument(case, bad):
    _, value, exception, mention = bad
    refused(case[1], value(), exception, mention)


def test_an_end_profile_without_the_profiles_holes_is_refused_naming_it():
    refused(lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), circle(0.5), end_profile=v),
            circle(0.8), rmfsurf.InvalidInputError,
            "end_profile: it has 0 holes, the profile 1")


@pytest.mark.parametrize("case", END_PROFILES, ids=[c[0] for c in END_PROFILES])
def test_a_good_end_profile_is_taken(case):
    case[1](case[2]())


def test_end_holes_without_an_end_profile_are_refused_naming_them():
    refused(lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), circle(0.5), end_holes=v),
            circle(0.4), rmfsurf.InvalidInputError, "end_holes")


def test_every_end_profile_of_a_wire_sweep_has_its_cases():
    """Every public function taking `end_profile` has END_PROFILES cases."""
    required = {"%s(end_profile)" % name for name, parameters in wire_sweep_functions()
                if "end_profile" in parameters}
    assert {"wire_sweep(end_profile)", "ocp.sweep(end_profile)"} <= required, required
    assert required <= {c[0] for c in END_PROFILES}, required - {c[0] for c in END_PROFILES}


# Sections (a sweep through sections): (at, profile[, holes]) between the profile and the
# end profile; refusals name sections[k] as the caller counts them.
SECTIONS = [
    ("wire_sweep(sections)",
     lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), end_profile=circle(0.5), sections=v),
     lambda at, r, holes=(): ((at, circle(r), [circle(h) for h in holes]) if holes
                              else (at, circle(r)))),
    ("ocp.sweep(sections)",
     lambda v: IN.ocp.sweep(IN.route, IN.ring, end_profile=_start_face(0.5), sections=v),
     lambda at, r, holes=(): (at, _start_face(r, holes))),
]


def _start_face(radius, holes=()):
    """A circle face of `radius` about the route's start, in its normal plane (with holes of
    the radii `holes`)."""
    plane = IN.bd.Plane(origin=(0, 0, 0), z_dir=(1, 0, 0))
    face = plane * IN.bd.Circle(radius)
    for r in holes:
        face = face - plane * IN.bd.Circle(r)
    return face


def bad_sections(case):
    """(label, value factory, exception, what the message names) for a case of SECTIONS."""
    item = case[2]
    bad = [("int", lambda: 3, TypeError, "sections"),
           ("str", lambda: "circle", TypeError, "sections"),
           ("an item of one", lambda: [(0.5,)], TypeError, "sections[0]"),
           ("a profile that is none", lambda: [(0.5, 3)], TypeError, "sections[0]"),
           ("at 0", lambda: [item(0.0, 0.8)], rmfsurf.InvalidInputError,
            "sections[0].at = 0 must be in (0, 1)"),
           ("at 1", lambda: [item(1.0, 0.8)], rmfsurf.InvalidInputError,
            "sections[0].at = 1 must be in (0, 1)"),
           ("at NaN", lambda: [item(math.nan, 0.8)], rmfsurf.InvalidInputError,
            "sections[0].at = NaN"),
           ("out of order", lambda: [item(0.5, 0.8), item(0.25, 0.7)],
            rmfsurf.InvalidInputError, "sections[1].at = 0.25 must be in (0.5, 1)"),
           ("a hole the profile has not", lambda: [item(0.5, 0.8), item(0.75, 0.7, (0.2,))],
            rmfsurf.InvalidInputError, "sections[1].holes: it has 1 holes, the profile 0")]
    if case[0] == "wire_sweep(sections)":
        bad.append(("holes that are none", lambda: [(0.5, circle(0.8), 3)], TypeError,
                    "sections[0].holes"))
    return [pytest.param(case, b, id="%s-%s" % (case[0], b[0])) for b in bad]


@pytest.mark.parametrize("case, bad", [p for c in SECTIONS for p in bad_sections(c)])
def test_bad_sections_name_the_argument(case, bad):
    _, value, exception, mention = bad
    refused(case[1], value(), exception, mention)


@pytest.mark.parametrize("case", SECTIONS, ids=[c[0] for c in SECTIONS])
def test_good_sections_are_taken_and_need_an_end_profile(case):
    case[1]([case[2](0.25, 0.8), case[2](0.5, 0.6)])
    case[1]([])
    without = (lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), sections=v)) \
        if case[0].startswith("wire_sweep") else (lambda v: IN.ocp.sweep(IN.route, IN.ring,
                                                                         sections=v))
    refused(without, [case[2](0.5, 0.8)], rmfsurf.InvalidInputError,
            "sections: need end_profile")


def test_a_refusal_of_the_end_profile_through_sections_names_it():
    """The library counts the profile and the end profile among the sections: its refusals
    of them name `holes`, `end_profile` and `end_holes` as the caller gave them."""
    refused(lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), end_profile=v,
                                         sections=[(0.5, circle(0.8))]),
            _ring_in_a_tilted_plane(), rmfsurf.InvalidInputError,
            "rmf_wire_sweep_through: end_profile: a sweep between profiles takes them in the "
            "normal plane")
    refused(lambda v: rmfsurf.wire_sweep(BAR, circle(1.0), end_profile=circle(0.5),
                                         end_holes=v, sections=[(0.5, circle(0.8))]),
            circle(0.1), rmfsurf.InvalidInputError, "end_holes: it has 1 holes, the profile 0")


def test_every_sections_argument_of_a_wire_sweep_has_its_cases():
    """Every public function taking `sections` has SECTIONS cases."""
    required = {"%s(sections)" % name for name, parameters in wire_sweep_functions()
                if "sections" in parameters}
    assert {"wire_sweep(sections)", "ocp.sweep(sections)"} <= required, required
    assert required <= {c[0] for c in SECTIONS}, required - {c[0] for c in SECTIONS}


BOXES = [
    ("ConeSpline.bounds_in_box(box)", lambda v: IN.cone.bounds_in_box(v)),
    ("cone_spline_hermite(region)", lambda v: rmfsurf.cone_spline_hermite(IN.elements, region=v)),
    ("cone_spline_approximate_dual(region)", lambda v: dual(region=v)),
]
BAD_BOXES = [
    (3.0, TypeError, ""), (((0, 0, 0),), TypeError, ""), (((0, 0), (1, 1, 1)), ValueError, "[0]"),
    (((0, 0, 0), ("a", 1, 1)), TypeError, "[1]"),
    (((0, 0, 0), (10 ** 400, 1, 1)), rmfsurf.InvalidInputError, "[1]"),
]


@pytest.mark.parametrize("case, bad", parametrize(BOXES, lambda c: BAD_BOXES))
def test_a_bad_box_names_the_argument_and_the_corner(case, bad):
    value, exception, item = bad
    refused(case[1], value, exception, argument(case[0]) + item)


# ---------------------------------------------------------------------------------------
# Arrays: (key, kind, call). Per kind: a value of the wrong shape (ValueError), one with a
# string (TypeError) and one with a number beyond a double (InvalidInputError).

BAD_ARRAYS = {
    "points": [([0.0, 0.0, 1.0], ValueError), ([[0, 0], [1, 1]], ValueError),
               ([[0, 0, 0], [1, 1]], ValueError),
               ([["a", 0, 0], [1, 0, 0]], TypeError),
               ([[10 ** 400, 0, 0], [1, 0, 0]], rmfsurf.InvalidInputError)],
    "flat points": [([[0.0, 0.0, 0.0]], ValueError), ([["a", 0.0]], TypeError),
                    ([[10 ** 400, 0.0]], rmfsurf.InvalidInputError)],
    "planes": [([[0, 1, 0]], ValueError), ([["a", 1, 0, 0]], TypeError),
               ([[10 ** 400, 1, 0, 0]], rmfsurf.InvalidInputError)],
    "weights": [([[1.0, 1.0]], ValueError), ([["a", 1.0], [1.0, 1.0]], TypeError),
                ([[10 ** 400, 1.0], [1.0, 1.0]], rmfsurf.InvalidInputError)],
    "grid": [([[0, 0, 0]], ValueError), ([[["a", 0, 0]]], TypeError),
             ([[[10 ** 400, 0, 0]]], rmfsurf.InvalidInputError)],
    "vector": [((0.0, 1.0), ValueError), ([[0, 0, 1]], ValueError), (("a", 0, 1), TypeError),
               ((0, 0, 10 ** 400), rmfsurf.InvalidInputError)],
    "numbers": [([[0.0, 1.0]], ValueError), (["a", 1.0], TypeError),
                ([0.0, 10 ** 400], rmfsurf.InvalidInputError)],
    "parameters": [("a", TypeError), ([0.5, 10 ** 400], rmfsurf.InvalidInputError),
                   (10 ** 400, rmfsurf.InvalidInputError)],
    "integers": [([[1, 2]], ValueError), ([1.5, 2.0], TypeError),
                 ([1, -2], rmfsurf.InvalidInputError)],
}
P, D = helix_data(3)
H = dict(p0=P[0], t0=D[0], p1=P[1], t1=D[1])


ARRAYS = [
    ("Brep.create(vertices)", "points", lambda v: rmfsurf.Brep.create(v, [], [])),
    ("UnfoldedFace.to_flat(points)", "points", lambda v: IN.unfolded.to_flat(v)),
    ("UnfoldedFace.to_formed(points)", "flat points", lambda v: IN.unfolded.to_formed(v)),
    ("UnfoldedBody.to_flat(points)", "points", lambda v: IN.unfolded_body.to_flat(v)),
    ("UnfoldedBody.to_formed(points)", "flat points", lambda v: IN.unfolded_body.to_formed(v)),
    ("line_curve(start)", "vector", lambda v: rmfsurf.line_curve(v, (1, 0, 0))),
    ("line_curve(end)", "vector", lambda v: rmfsurf.line_curve((1, 0, 0), v)),
    ("Curve.from_nurbs(poles)", "points", lambda v: rmfsurf.Curve.from_nurbs(1, v, [0, 0, 1, 1])),
    ("Curve.from_nurbs(knots)", "numbers",
     lambda v: rmfsurf.Curve.from_nurbs(1, [[0, 0, 0], [1, 0, 0]], v)),
    ("Curve.from_nurbs(weights)", "numbers",
     lambda v: rmfsurf.Curve.from_nurbs(1, [[0, 0, 0], [1, 0, 0]], [0, 0, 1, 1], v)),
    ("Curve.eval(t)", "parameters", lambda v: IN.profile.eval(v)),
    ("Frames.eval(t)", "parameters", lambda v: IN.frames.eval(v)),
    ("Surface.eval(u)", "parameters", lambda v: IN.surface.eval(v, 0.5)),
    ("Surface.eval(v)", "parameters", lambda v: IN.surface.eval(0.5, v)),
    ("Surface.from_nurbs(poles)", "grid",
     lambda v: rmfsurf.Surface.from_nurbs(1, 1, v, [0, 0, 1, 1], [0, 0, 1, 1])),
    ("Surface.from_nurbs(weights)", "weights",
     lambda v: rmfsurf.Surface.from_nurbs(1, 1, np.zeros((2, 2, 3)), [0, 0, 1, 1], [0, 0, 1, 1],
                                          v)),
    ("Surface.from_nurbs(knots_u)", "numbers",
     lambda v: rmfsurf.Surface.from_nurbs(1, 1, np.zeros((2, 2, 3)), v, [0, 0, 1, 1])),
    ("Surface.from_nurbs(knots_v)", "numbers",
     lambda v: rmfsurf.Surface.from_nurbs(1, 1, np.zeros((2, 2, 3)), [0, 0, 1, 1], v)),
    ("distinct_knots(knots)", "numbers", lambda v: rmfsurf.distinct_knots(v)),
    ("flat_knots(values)", "numbers", lambda v: rmfsurf.flat_knots(v, [2, 2])),
    ("flat_knots(multiplicities)", "integers", lambda v: rmfsurf.flat_knots([0, 1], v)),
    ("ph_spline_hermite(points)", "points", lambda v: rmfsurf.ph_spline_hermite(v, D[:2])),
    ("ph_spline_hermite(tangents)", "points", lambda v: rmfsurf.ph_spline_hermite(P[:2], v)),
    ("mobius_rrmf_hermite(points)", "points", lambda v: rmfsurf.mobius_rrmf_hermite(v, D[:2])),
    ("mobius_rrmf_hermite(tangents)", "points", lambda v: rmfsurf.mobius_rrmf_hermite(P[:2], v)),
    ("mobius_rrmf_hermite(initial_normal)", "vector",
     lambda v: rmfsurf.mobius_rrmf_hermite(P, D, v)),
    ("mobius_rrmf_approximate(initial_normal)", "vector",
     lambda v: rmfsurf.mobius_rrmf_approximate(IN.spline, 4, v)),
    ("rrmf_spline_hermite(points)", "points", lambda v: rmfsurf.rrmf_spline_hermite(v, D[:2])),
    ("rrmf_spline_hermite(tangents)", "points", lambda v: rmfsurf.rrmf_spline_hermite(P[:2], v)),
    ("rrmf_spline_hermite(initial_normal)", "vector",
     lambda v: rmfsurf.rrmf_spline_hermite(P, D, v)),
    ("rrmf_quintic_curve(initial_normal)", "vector",
     lambda v: rmfsurf.rrmf_quintic_curve(*IN.hermite, IN.solution, v)),
    ("mobius_point(point)", "vector", lambda v: rmfsurf.mobius_point(INVERSION, v)),
    ("ph_rational_rmf(initial_normal)", "vector", lambda v: rmfsurf.ph_rational_rmf(IN.spline, v)),
    ("double_reflection_frames(initial_normal)", "vector",
     lambda v: rmfsurf.double_reflection_frames(IN.spline, v)),
    ("ph_exact_rmf(initial_normal)", "vector",
     lambda v: rmfsurf.ph_exact_rmf(IN.spline, v, [0.5])),
    ("ph_exact_rmf(t)", "parameters", lambda v: rmfsurf.ph_exact_rmf(IN.spline, (0, 0, 1), v)),
    ("wire_sweep(initial_normal)", "vector",
     lambda v: rmfsurf.wire_sweep(IN.edges, circle(1.0), initial_normal=v)),
    ("circle(centre)", "vector", lambda v: rmfsurf.circle(1.0, v)),
    ("circle(x_axis)", "vector", lambda v: rmfsurf.circle(1.0, x_axis=v)),
    ("circle(y_axis)", "vector", lambda v: rmfsurf.circle(1.0, y_axis=v)),
    ("arc(start)", "vector", lambda v: rmfsurf.arc(v, (0, 1, 0), (-1, 0, 0))),
    ("arc(through)", "vector", lambda v: rmfsurf.arc((1, 0, 0), v, (-1, 0, 0))),
    ("arc(end)", "vector", lambda v: rmfsurf.arc((1, 0, 0), (0, 1, 0), v)),
    ("obround(centre)", "vector", lambda v: rmfsurf.obround(2.0, 1.0, v)),
    ("obround(x_axis)", "vector", lambda v: rmfsurf.obround(2.0, 1.0, x_axis=v)),
    ("obround(y_axis)", "vector", lambda v: rmfsurf.obround(2.0, 1.0, y_axis=v)),
    ("polyline(points)", "points", lambda v: rmfsurf.polyline(v)),
    ("polygon(corners)", "points", lambda v: rmfsurf.polygon(list(v) + [(0, 5, 0)])),
    ("framed_spine(initial_normal)", "vector",
     lambda v: rmfsurf.framed_spine(IN.spline, "frenet", initial_normal=v)),
    ("cone_spline_approximate_dual(planes)", "planes", lambda v: dual(planes=v)),
    ("cone_spline_approximate_dual(knots)", "numbers", lambda v: dual(knots=v)),
    ("cone_spline_osculating(parameters)", "numbers",
     lambda v: rmfsurf.cone_spline_osculating(twisted_cubic(), (0.5, 6.0), v)),
    ("SheetPart.flat_to_surface(points)", "flat points", lambda v: IN.part.flat_to_surface(v)),
    ("SheetPart.surface_to_flat(points)", "points", lambda v: IN.part.surface_to_flat(v)),
    ("ocp.profile_curves(origin)", "vector",
     lambda v: IN.ocp.profile_curves(IN.ring, v, (1, 0, 0))),
    ("ocp.profile_curves(tangent)", "vector",
     lambda v: IN.ocp.profile_curves(IN.ring, (0, 0, 0), v)),
]
HERMITE = {
    "ph_cubic_hermite": lambda **h: rmfsurf.ph_cubic_hermite(**h),
    "rrmf_quintic_solutions": lambda **h: rmfsurf.rrmf_quintic_solutions(eta=1.0, **h),
    "rrmf_quintic_best": lambda **h: rmfsurf.rrmf_quintic_best(**h),
    "rrmf_quintic_curve": lambda **h: rmfsurf.rrmf_quintic_curve(solution=IN.solution, **h),
}
for _function, _call in HERMITE.items():
    for _name in ("p0", "t0", "p1", "t1"):
        ARRAYS.append(("%s(%s)" % (_function, _name), "vector",
                       lambda v, c=_call, n=_name: c(**dict(H, **{n: v}))))


@pytest.mark.parametrize("case, bad", parametrize(ARRAYS, lambda c: BAD_ARRAYS[c[1]]))
def test_a_bad_array_names_the_argument(case, bad):
    value, exception = bad
    refused(case[2], value, exception, argument(case[0]))


NAN = math.nan
#: An array of the right shape with a NaN or an infinity, per kind and where a case needs
#: another count.
NON_FINITE_ARRAYS = {
    "points": [[NAN, 0, 0], [1, 0, 0]], "flat points": [[0.0, 0.0], [math.inf, 0.0]],
    "planes": [[0, 1, 0, -0.5], [0, 1, NAN, -0.5], [0, 0, 1, -0.5]],
    "grid": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, NAN, 0]]], "weights": [[1, 1], [1, NAN]],
    "vector": (NAN, 0, 1), "numbers": [0, 0, NAN, 1, 1], "parameters": [0.5, NAN],
    "integers": [1, 1],
    "Curve.from_nurbs(knots)": [0, 0, math.inf, 1], "Curve.from_nurbs(weights)": [1, NAN],
    "Surface.from_nurbs(knots_u)": [0, 0, NAN, 1], "Surface.from_nurbs(knots_v)": [0, 0, NAN, 1],
    "cone_spline_approximate_dual(knots)": [0, 0, 0, NAN, 1, 1],
    "cone_spline_osculating(parameters)": [0.3, NAN],
}


@pytest.mark.parametrize("case", [c for c in ARRAYS if c[1] != "integers"],
                         ids=[c[0] for c in ARRAYS if c[1] != "integers"])
def test_an_array_with_nan_or_infinity_is_invalid_input_naming_the_argument(case):
    key, kind, call = case
    refused(call, NON_FINITE_ARRAYS.get(key, NON_FINITE_ARRAYS[kind]),
            rmfsurf.InvalidInputError, argument(key))


def test_ocp_non_finite_placements_are_invalid_input():
    for value in ((0, math.nan, 0), (math.inf, 0, 0)):
        refused(lambda v: IN.ocp.profile_curves(IN.ring, v, (1, 0, 0)), value,
                rmfsurf.InvalidInputError, "origin")
    for value in ((0, 0, 0), (math.nan, 0, 0)):
        refused(lambda v: IN.ocp.profile_curves(IN.ring, (0, 0, 0), v), value,
                rmfsurf.InvalidInputError, "tangent")


# ---------------------------------------------------------------------------------------
# Coverage: every argument of these classes in the API has its cases.

CASES = {
    "integer": {c[0] for c in INTEGERS},
    "number": {c[0] for c in NUMBERS},
    "path": {c[0] for c in PATHS},
    "objects": {c[0] for c in OBJECTS},
    "pair": {c[0] for c in PAIRS},
    "box": {c[0] for c in BOXES},
    "array": {c[0] for c in ARRAYS},
}


def test_every_argument_of_the_api_has_its_cases():
    required = api_arguments(rmfsurf)
    ocp = pytest.importorskip("rmfsurf.ocp")
    required.update(api_arguments(ocp, "ocp.", "rmfsurf.ocp"))
    assert len(required) >= 100, required
    # Cases of an argument the annotations do not name (an option struct's field, ...).
    required = {k: c for k, c in required.items() if not k.startswith("rmfsurf.")}
    assert missing_cases(required, CASES) == []


def test_the_message_check_can_fail():
    assert names("rmf_x: t = NaN is outside", "t")
    assert names("holes[1]: expected an rmfsurf.Curve", "holes[1]")
    assert names("rmf_x: options->twist = NaN", "twist")
    assert names("curve(0.5)[0]: (nan, 0, 0) has a non-finite component", "curve")
    assert not names("rmf_x: t_min = NaN", "t")
    assert not names("rmf_x: the tolerance of it", "tol")


# ---------------------------------------------------------------------------------------
# The table of docs/hardening.md, "The Python package": every row run as written.

REPOSITORY = os.environ.get("RMFSURF_REPOSITORY",
                            os.path.join(os.path.dirname(__file__), "..", ".."))


def hardening_rows():
    with open(os.path.join(REPOSITORY, "docs", "hardening.md"), encoding="utf-8") as f:
        text = f.read()
    section = text.split("\n## The Python package\n", 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if len(cells) == 4 and cells[1].startswith("`"):
            rows.append(pytest.param(cells[1].strip("`"), cells[2], cells[3], id=cells[0]))
    return rows


def test_the_python_table_of_docs_hardening_md_has_rows():
    assert len(hardening_rows()) >= 15


@pytest.mark.parametrize("call, exception, message", hardening_rows())
def test_the_python_rows_of_docs_hardening_md_are_what_the_package_raises(
        call, exception, message, tmp_path, monkeypatch):
    if "rmfsurf.ocp" in call:
        pytest.importorskip("rmfsurf.ocp")
    monkeypatch.chdir(tmp_path)
    namespace = dict(rmfsurf=rmfsurf, np=np, math=math, nan=math.nan, shape=IN.shape,
                     spline=IN.spline, curve=IN.profile, cubic=twisted_cubic(), helix=helix,
                     edges=IN.edges, profile=circle(1.0))
    expected = getattr(rmfsurf, exception, None) or getattr(builtins, exception)
    with pytest.raises(expected) as caught:
        eval(call, namespace)
    assert type(caught.value) is expected
    text = str(caught.value)
    if "…" in message:
        assert text.startswith(message.split("…")[0]), (text, message)
    else:
        assert text == message
    assert os.listdir(tmp_path) == []


# ---------------------------------------------------------------------------------------
# rmfsurf.freecad in FreeCAD's Python (Debian's FreeCAD module directory, the interpreter of
# this environment): a separate process, since FreeCAD's OpenCascade and OCP's must not
# share one.

FREECAD_LIB = "/usr/lib/freecad-python3/lib"


@pytest.mark.skipif(not os.path.exists(os.path.join(FREECAD_LIB, "FreeCAD.so")),
                    reason="FreeCAD (Debian package freecad) is not installed")
def test_the_freecad_adapter_refuses_bad_arguments_in_freecads_python():
    here = os.path.dirname(os.path.abspath(__file__))
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
         os.path.join(here, "freecad_arguments.py")],
        cwd=here, capture_output=True, text=True, timeout=1800,
        env=dict(os.environ, RMFSURF_FREECAD_LIB=FREECAD_LIB))
    tail = run.stdout[-3000:] + run.stderr[-3000:]
    print("\nrmfsurf.freecad bad arguments:", run.stdout.strip().splitlines()[-1:])
    assert run.returncode == 0, tail
    assert " passed" in run.stdout and " skipped" not in run.stdout, tail
