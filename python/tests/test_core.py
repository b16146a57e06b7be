"""The Python API over the C library: every figure is checked with the tests' own
arithmetic (tests/nurbs.py evaluates the exported NURBS), not with the library's
evaluators alone. Run by integration/tests/python.rs (pytest, in the environment of
scripts/python-env, against the installed wheel)."""

import gc
import importlib.metadata
import math
import os

import numpy as np
import pytest

import rmfsurf
from nurbs import curve_point, surface_point

S = math.sqrt(0.5)
RADIUS = 0.25


def helix_data(n=9, pitch=0.2):
    a = np.linspace(0.0, 4.0, n)
    points = np.c_[np.cos(a), np.sin(a), pitch * a]
    tangents = np.c_[-np.sin(a), np.cos(a), np.full(n, pitch)]
    return points, tangents


def circle(radius=RADIUS):
    return rmfsurf.circle(radius)


def angle(a, b):
    return math.atan2(np.linalg.norm(np.cross(a, b)), np.dot(a, b))


def test_version_is_the_librarys():
    assert rmfsurf.__version__ == rmfsurf.rmf_version()
    assert importlib.metadata.version("rmfsurf") == rmfsurf.__version__
    major, minor, _ = rmfsurf.__version__.split(".")
    assert (int(major), int(minor)) == (rmfsurf.lib.RMF_VERSION_MAJOR,
                                        rmfsurf.lib.RMF_VERSION_MINOR)


def test_library_is_the_one_in_the_package():
    native = os.path.dirname(rmfsurf._core.__file__)
    assert os.path.exists(os.path.join(native, "_native", "lib_native.so"))
    assert "RMFSURF_LIBRARY" not in os.environ


def test_nurbs_curve_round_trip_and_independent_evaluation():
    c = circle()
    data = c.nurbs()
    assert data.degree == 2 and data.poles.shape == (9, 3)
    values, mults = data.distinct_knots()
    assert list(values) == [0, 1, 2, 3, 4] and list(mults) == [3, 2, 2, 2, 3]
    ts = np.linspace(0, 4, 41)
    ours = np.array([curve_point(data.degree, data.poles, data.weights, data.knots, t)
                     for t in ts])
    theirs = c.eval(ts)
    assert np.abs(ours - theirs).max() <= 1e-14
    assert np.abs(np.linalg.norm(theirs, axis=1) - RADIUS).max() <= 1e-15
    point, derivative = c.eval(0.5, derivative=True)
    assert point.shape == (3,) and abs(np.dot(point, derivative)) <= 1e-15
    assert len(c.segments()) == c.segment_count == 4


def test_ph_rational_rmf_is_rotation_minimizing():
    spline = rmfsurf.ph_spline_hermite(*helix_data())
    frames = rmfsurf.ph_rational_rmf(spline, (0, 0, 1))
    assert frames.kind == "rational"
    reference = rmfsurf.double_reflection_frames(spline, (0, 0, 1), samples=20000)
    ts = np.linspace(*spline.domain, 161)
    t, f2, f3 = frames.eval(ts)
    _, g2, _ = reference.eval(ts)
    assert np.abs(np.einsum("ij,ij->i", f2, t)).max() <= 1e-12
    assert np.abs(np.cross(t, f2) - f3).max() <= 1e-12
    worst = max(angle(a, b) for a, b in zip(f2, g2))
    reported, per_segment = rmfsurf.ph_rmf_angle_error(frames)
    exact2, _ = rmfsurf.ph_exact_rmf(spline, (0, 0, 1), ts)
    exact_worst = max(angle(a, b) for a, b in zip(f2, exact2))
    print("\nPH rational RMF: %.2e rad from double reflection, %.2e from the closed form "
          "(reported %.2e)" % (worst, exact_worst, reported))
    assert worst <= 1e-5 and exact_worst <= 1e-5
    assert exact_worst <= reported * (1 + 1e-6) and per_segment.shape == (8,)
    # A Frenet frame is no RMF: far from the reference on a helix.
    _, n, _ = rmfsurf.frenet_frames(spline).eval(ts)
    assert max(angle(a, b) for a, b in zip(n, g2)) > 0.1


def test_sweep_surface_exported_nurbs_is_the_profile_around_the_spine():
    spline = rmfsurf.ph_spline_hermite(*helix_data())
    frames = rmfsurf.ph_rational_rmf(spline, (0, 0, 1))
    surface = rmfsurf.sweep_surface(spline, frames, circle())
    data = surface.nurbs()
    u0, u1, v0, v1 = surface.domain
    worst_eval = worst_radius = worst_normal = 0.0
    for u in np.linspace(u0, u1, 13):
        for v in np.linspace(v0, v1, 17):
            p = surface_point(data.degree_u, data.degree_v, data.poles, data.weights,
                              data.knots_u, data.knots_v, u, v)
            x, dx = spline.eval(v, derivative=True)
            worst_eval = max(worst_eval, np.abs(p - surface.eval(u, v)).max())
            worst_radius = max(worst_radius, abs(np.linalg.norm(p - x) - RADIUS))
            worst_normal = max(worst_normal, abs(np.dot(p - x, dx)) / np.linalg.norm(dx))
    assert worst_eval <= 1e-13
    assert worst_radius <= 1e-13 and worst_normal <= 1e-13
    grid = surface.eval(np.linspace(u0, u1, 5)[:, None], np.linspace(v0, v1, 7)[None, :])
    assert grid.shape == (5, 7, 3)
    points, triangles = surface.tessellate(3, 2)
    nu, nv = surface.patch_count
    assert points.shape == ((3 * nu + 1) * (2 * nv + 1), 3)
    assert triangles.shape == (2 * 6 * nu * nv, 3) and triangles.max() < len(points)
    margin = rmfsurf.singularity_margin(spline, frames, circle())
    # For a circle profile the margin is 1 − r κ_max, κ the spine's curvature, here from
    # central differences of its derivative.
    ts, h = np.linspace(v0 + 1e-3, v1 - 1e-3, 4001), 1e-5
    _, d1 = spline.eval(ts, derivative=True)
    d2 = (spline.eval(ts + h, derivative=True)[1] - spline.eval(ts - h, derivative=True)[1]) / (2 * h)
    kappa = np.linalg.norm(np.cross(d1, d2), axis=1) / np.linalg.norm(d1, axis=1) ** 3
    assert abs(margin.margin - (1 - RADIUS * kappa.max())) <= 1e-5


def test_parabolic_curves_are_where_the_normal_is_across_the_principal_normal():
    spline = rmfsurf.ph_spline_hermite(*helix_data())
    frames = rmfsurf.ph_rational_rmf(spline, (0, 0, 1))
    profile = circle()
    curves = rmfsurf.parabolic_curves(spline, frames, profile, 1e-7)
    assert len(curves) >= 2
    surface = rmfsurf.sweep_surface(spline, frames, profile).nurbs()
    spine = spline.nurbs()
    joints = set(spine.distinct_knots()[0])
    worst, h = 0.0, 1e-4
    args = (surface.degree_u, surface.degree_v, surface.poles, surface.weights,
            surface.knots_u, surface.knots_v)
    for curve in curves:
        assert curve.shape[1] == 5
        for u, v, *point in curve:
            assert np.linalg.norm(surface_point(*args, u, v) - point) <= 1e-12
            # The line jumps with the spine's curvature at a joint; central differences need
            # room inside the domain.
            if any(abs(v - j) < 2 * h for j in joints) or not (2 * h < u < 4 - 2 * h):
                continue
            su = surface_point(*args, u + h, v) - surface_point(*args, u - h, v)
            sv = surface_point(*args, u, v + h) - surface_point(*args, u, v - h)
            c = [curve_point(spine.degree, spine.poles, spine.weights, spine.knots, t)
                 for t in (v - h, v, v + h)]
            tangent, second = c[2] - c[0], c[2] - 2 * c[1] + c[0]
            tangent /= np.linalg.norm(tangent)
            principal = second - tangent * np.dot(tangent, second)
            normal = np.cross(su, sv)
            worst = max(worst, abs(np.dot(normal / np.linalg.norm(normal),
                                          principal / np.linalg.norm(principal))))
    # Central differences (step 1e-4) of the exported NURBS: (14) holds to their error
    # (about 1e-8).
    assert worst <= 1e-6, worst


def test_an_ellipse_is_offset_exactly_through_arcs():
    w = S
    ellipse = rmfsurf.Curve.from_nurbs(2, [[2, 0, 0], [2, 1, 0], [0, 1, 0]], [0, 0, 0, 1, 1, 1],
                                       [1, w, 1])
    with pytest.raises(rmfsurf.NoSolutionError):
        rmfsurf.profile_offset(ellipse, 0.1)
    offset, arcs, deviation = rmfsurf.profile_offset_by_arcs(ellipse, 0.1, 1e-5)
    assert 0 < deviation <= 1e-5
    data = offset.nurbs()
    assert data.degree == 2
    def true_offset(t):
        n = math.hypot(math.cos(t), 2 * math.sin(t))
        return np.array([2 * math.cos(t) + 0.1 * math.cos(t) / n,
                         math.sin(t) + 0.2 * math.sin(t) / n, 0.0])

    worst = 0.0
    for t in np.linspace(data.knots[0], data.knots[-1], 101):
        q = curve_point(data.degree, data.poles, data.weights, data.knots, t)
        # The closest point of the true offset: a scan, then a ternary search about the best.
        grid = np.linspace(0, math.pi / 2, 2001)
        best = min(grid, key=lambda a: np.linalg.norm(true_offset(a) - q))
        lo, hi = max(0.0, best - math.pi / 4000), min(math.pi / 2, best + math.pi / 4000)
        for _ in range(100):
            a, b = lo + (hi - lo) / 3, hi - (hi - lo) / 3
            if np.linalg.norm(true_offset(a) - q) < np.linalg.norm(true_offset(b) - q):
                hi = b
            else:
                lo = a
        worst = max(worst, np.linalg.norm(true_offset(0.5 * (lo + hi)) - q))
    assert worst <= 1e-5, worst


def test_mobius_and_rrmf_frames_are_rotation_minimizing():
    points, tangents = helix_data(5)
    for name, (curve, frames) in [
            ("Möbius", rmfsurf.mobius_rrmf_hermite(points, tangents, (0, 0, 1))),
            ("RRMF quintic", rmfsurf.rrmf_spline_hermite(points, tangents, (0, 0, 1)))]:
        lo, hi = curve.domain
        h = 1e-5
        ts = np.linspace(lo + 2 * h, hi - 2 * h, 401)
        _, x1 = curve.eval(ts, derivative=True)
        t, f2, f3 = frames.eval(ts)
        # An RMF turns f2 only along t: d f2/dt · f3 = 0 (central differences), relative
        # to the speed.
        _, a, _ = frames.eval(ts + h)
        _, b, _ = frames.eval(ts - h)
        rate = np.einsum("ij,ij->i", (a - b) / (2 * h), f3) / np.linalg.norm(x1, axis=1)
        twist = np.abs(rate).max()
        assert np.abs(curve.eval([lo, hi]) - points[[0, -1]]).max() <= 1e-12
        print("\n%s: |f2' . f3| <= %.1e" % (name, twist))
        assert twist <= 1e-6, name


def test_callback_curves_and_their_errors():
    def helix(t):
        return (math.cos(t), math.sin(t), 0.2 * t), (-math.sin(t), math.cos(t), 0.2)

    spline, distance = rmfsurf.ph_spline_approximate(helix, 1e-6, domain=(0.0, 4.0))
    assert distance <= 1e-6
    # The distance is geometric (the spline's parameter is not the callback's): from each
    # helix point to its nearest spline point, found by golden-section search around the
    # nearest of dense samples.
    lo, hi = spline.domain
    grid = np.linspace(lo, hi, 4001)
    samples = spline.eval(grid)
    worst = 0.0
    for t in np.linspace(0.013, 3.987, 57):  # off the spline's breakpoints
        p = np.array(helix(t)[0])
        k = int(np.argmin(np.linalg.norm(samples - p, axis=1)))
        a, b = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
        g = (math.sqrt(5) - 1) / 2
        for _ in range(80):
            c, d = b - g * (b - a), a + g * (b - a)
            fc, fd = (np.linalg.norm(spline.eval([u])[0] - p) for u in (c, d))
            a, b = (a, d) if fc < fd else (c, b)
        worst = max(worst, np.linalg.norm(spline.eval([0.5 * (a + b)])[0] - p))
    assert 0.0 < worst <= distance * (1 + 1e-6), (worst, distance)

    def broken(t):
        raise KeyError("the user's bug")

    with pytest.raises(KeyError, match="the user's bug"):
        rmfsurf.ph_spline_approximate(broken, 1e-6, domain=(0.0, 4.0))
    with pytest.raises(ValueError, match="domain"):
        rmfsurf.ph_spline_approximate(helix, 1e-6)


def twisted_cubic():
    """(t, t², t³) for t in [0.2, 1.2] as a cubic Bézier curve (examples/cli/cone_spline)."""
    poles = [[0.2, 0.04, 0.008], [0.2 + 1 / 3, 0.04 + 0.4 / 3, 0.008 + 0.12 / 3],
             [1.2 - 1 / 3, 1.44 - 2.4 / 3, 1.728 - 4.32 / 3], [1.2, 1.44, 1.728]]
    return rmfsurf.Curve.from_nurbs(3, poles, [0, 0, 0, 0, 1, 1, 1, 1])


def test_cone_spline_flat_pattern_is_isometric():
    spline = rmfsurf.cone_spline_approximate(twisted_cubic(), (0.5, 6.0), 1e-4)
    assert spline.fit_error <= 1e-4 and spline.piece_count >= 2
    assert {p.kind for p in spline.pieces()} <= {"cone", "cylinder", "plane"}
    t_min, t_max = -0.3, 0.3
    pattern = spline.flat_pattern(t_min, t_max)
    u0, u1, v0, v1 = pattern.surface.domain
    flat = pattern.surface.eval(np.linspace(u0, u1, 5)[:, None],
                                np.linspace(v0, v1, 50)[None, :])
    assert np.abs(flat[..., 2]).max() <= 1e-12

    def length(curve):
        p = curve.eval(np.linspace(*curve.domain, 4001))
        return np.linalg.norm(np.diff(p, axis=0), axis=1).sum()

    for t, developed in zip((t_min, t_max), pattern.boundaries):
        spatial = length(spline.boundary(t))
        assert abs(length(developed) - spatial) <= 1e-6 * spatial
    (a, b), _ = pattern.end_rulings
    assert abs(np.linalg.norm(b - a) - (t_max - t_min)) <= 1e-12


def test_errors_are_exceptions_per_status_naming_the_argument():
    p, d = helix_data()
    with pytest.raises(rmfsurf.InvalidInputError) as e:
        rmfsurf.ph_spline_hermite(p * np.nan, d)
    assert e.value.status == 2 and e.value.status_name == "RMF_ERROR_INVALID_INPUT"
    assert "points[0]" in str(e.value) and e.value.function == "rmf_ph_spline_hermite"
    assert isinstance(e.value, ValueError) and isinstance(e.value, rmfsurf.RmfError)
    # Tangents parallel, the chord off their line: no PH cubic.
    with pytest.raises(rmfsurf.NoSolutionError) as e:
        rmfsurf.ph_cubic_hermite((0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 0, 0))
    assert e.value.status == 3 and "RMF_ERROR_NO_SOLUTION" == e.value.status_name
    with pytest.raises(rmfsurf.NotConvergedError) as e:
        rmfsurf.cone_spline_approximate(twisted_cubic(), (0.5, 6.0), 1e-12, max_pieces=2)
    assert e.value.status == 4
    with pytest.raises(rmfsurf.InvalidInputError, match="t"):
        circle().eval(7.0)
    for cls in (rmfsurf.NullPointerError, rmfsurf.InvalidInputError, rmfsurf.NoSolutionError,
                rmfsurf.NotConvergedError, rmfsurf.BufferTooSmallError, rmfsurf.InternalError):
        assert issubclass(cls, rmfsurf.RmfError)
        assert cls("x").status_name == rmfsurf.ffi.string(
            rmfsurf.lib.rmf_status_name(cls.status)).decode()


def test_wrong_types_say_what_was_expected():
    spline = rmfsurf.ph_spline_hermite(*helix_data())
    frames = rmfsurf.ph_rational_rmf(spline)
    with pytest.raises(TypeError, match="profile: expected an rmfsurf.Curve, got str"):
        rmfsurf.sweep_surface(spline, frames, "circle")
    with pytest.raises(TypeError, match="frames: expected rmfsurf.Frames, got Curve"):
        rmfsurf.sweep_surface(spline, spline, circle())
    with pytest.raises(ValueError, match=r"points: expected an array of shape \(n, 3\)"):
        rmfsurf.ph_spline_hermite([[0, 0], [1, 1]], [[1, 0], [1, 0]])
    with pytest.raises(ValueError, match="tangents: expected 9 points, got 2"):
        rmfsurf.ph_spline_hermite(helix_data()[0], [[1, 0, 0], [1, 0, 0]])
    with pytest.raises(TypeError, match="degree: expected an integer, got float"):
        rmfsurf.Curve.from_nurbs(2.0, [[0, 0, 0]] * 3, [0, 0, 0, 1, 1, 1])
    with pytest.raises(ValueError, match="measure: expected one of"):
        rmfsurf.rrmf_spline_hermite(*helix_data(3), measure="shortest")


def _rss():
    """The resident memory, after glibc hands its free pages back (malloc_trim): memory
    freed by earlier tests would otherwise be reused unseen by the leak below."""
    import ctypes
    ctypes.CDLL("libc.so.6").malloc_trim(0)
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _cycle(points, tangents, profile):
    spline = rmfsurf.ph_spline_hermite(points, tangents)
    frames = rmfsurf.ph_rational_rmf(spline)
    return rmfsurf.sweep_surface(spline, frames, profile)


def test_handles_are_freed_by_python():
    points, tangents = helix_data()
    profile = circle()
    gc.collect()
    before = rmfsurf.live_handles()
    for _ in range(50):
        _cycle(points, tangents, profile)
    gc.collect()
    assert rmfsurf.live_handles() == before
    # Memory: 2,000 sweeps freed by Python against 2,000 whose handles are dropped without
    # rmf_*_free (the control shows the measurement sees a leak of this size).
    _cycle(points, tangents, profile)
    start = _rss()
    for _ in range(2000):
        _cycle(points, tangents, profile)
    gc.collect()
    freed = _rss() - start
    start = _rss()
    ffi = rmfsurf.ffi
    for _ in range(2000):
        s = _cycle(points, tangents, profile)
        ffi.gc(s._ptr, None)  # detach the destructor: a leak, on purpose
    leaked = _rss() - start
    print("\nRSS growth over 2,000 sweeps: %.1f MB freed by Python, %.1f MB leaked (control)"
          % (freed / 1e6, leaked / 1e6))
    assert leaked >= 20e6
    assert freed <= leaked / 10
