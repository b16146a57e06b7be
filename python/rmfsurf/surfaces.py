"""Surfaces (``RmfSurface``): piecewise rational tensor-product surfaces, NURBS in and out,
evaluation, tessellation, and the sweep of a profile along a spine with exact rational
frames — a profile surface when the frames are rotation-minimizing (Mäurer & Jüttler,
eqs. (1), (42)) — with its analyses (singularity margin, Corollary 7; Gaussian curvature
(13); parabolic points and traced parabolic lines §2.3; convex initial normal, Corollary 9).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, List, Optional, Tuple

import numpy as np

from . import _core
from ._core import call, ffi, lib
from .curves import ArrayLike, Curve, as_curve
from .frames import Frames, as_frames


@dataclass(frozen=True)
class NurbsSurface:
    """NURBS surface data in OpenCascade's layout: poles[i, j], i along u (rows), knots
    listed one by one.

    Attributes:
        degree_u, degree_v: degrees.
        poles: (nu, nv, 3) Cartesian poles.
        weights: (nu, nv) weights > 0.
        knots_u: nu + degree_u + 1 clamped knots; knots_v likewise.
    """

    degree_u: int
    degree_v: int
    poles: np.ndarray
    weights: np.ndarray
    knots_u: np.ndarray
    knots_v: np.ndarray


@dataclass(frozen=True)
class BezierPatch:
    """One rational Bézier patch on [u_start, u_end] × [v_start, v_end]: poles
    (degree_u + 1, degree_v + 1, 3), weights likewise."""

    degree_u: int
    degree_v: int
    poles: np.ndarray
    weights: np.ndarray
    u_start: float
    u_end: float
    v_start: float
    v_end: float


class Surface:
    """A piecewise rational tensor-product surface s(u, v), immutable; freed when
    collected. A surface borrowed from an :class:`rmfsurf.Shape` keeps the shape alive."""

    __slots__ = ("_ptr", "_owner", "__weakref__")

    def __init__(self, pointer: Any, owner: Any = None) -> None:
        self._ptr = pointer
        self._owner = owner

    @classmethod
    def _owned(cls, out: Any) -> "Surface":
        return cls(_core.owned("surface", out[0]))

    @classmethod
    def from_nurbs(cls, degree_u: int, degree_v: int, poles: ArrayLike, knots_u: ArrayLike,
                   knots_v: ArrayLike, weights: Optional[ArrayLike] = None) -> "Surface":
        """A surface from NURBS data: poles (nu, nv, 3), i along u; weights (nu, nv) or None;
        clamped knot vectors of nu + degree_u + 1 and nv + degree_v + 1 knots."""
        du = _core.integer(degree_u, "degree_u", "uint32_t", 1)
        dv = _core.integer(degree_v, "degree_v", "uint32_t", 1)
        grid = _core.float_array(poles, "poles", "an array of shape (nu, nv, 3)")
        if grid.ndim != 3 or grid.shape[2] != 3:
            raise ValueError("poles: expected an array of shape (nu, nv, 3), got shape %s"
                             % (grid.shape,))
        nu, nv = grid.shape[0], grid.shape[1]
        flat = grid.reshape(nu * nv, 3)
        w = None
        if weights is not None:
            w = _core.float_array(weights, "weights", "an array of shape (nu, nv)")
            if w.shape != (nu, nv):
                raise ValueError("weights: expected shape %s, got %s" % ((nu, nv), w.shape))
            w = w.reshape(nu * nv)
        ku = _core.doubles(knots_u, "knots_u")
        kv = _core.doubles(knots_v, "knots_v")
        data = ffi.new("RmfNurbsSurfaceData *")
        data.struct_size = ffi.sizeof("RmfNurbsSurfaceData")
        data.degree_u, data.degree_v, data.pole_count_u, data.pole_count_v = du, dv, nu, nv
        # Views of flat, w, ku and kv, which stay alive through the call.
        data.poles, data.weights = _core.vec3_array(flat), _core.double_array(w)
        data.knots_u, data.knots_v = _core.double_array(ku), _core.double_array(kv)
        data.knot_count_u, data.knot_count_v = ku.shape[0], kv.shape[0]
        out = _core.out_pointer("RmfSurface")
        call("rmf_nurbs_surface_create_from", data, out)
        return cls._owned(out)

    @property
    def domain(self) -> Tuple[float, float, float, float]:
        """(u_min, u_max, v_min, v_max)."""
        d = [ffi.new("double *") for _ in range(4)]
        call("rmf_surface_domain", self._ptr, *d)
        return d[0][0], d[1][0], d[2][0], d[3][0]

    def eval(self, u: ArrayLike, v: ArrayLike, derivatives: bool = False) -> Any:
        """s(u, v), broadcasting u and v against each other: shape (3,) for scalars,
        (..., 3) otherwise; with ``derivatives=True`` also ∂s/∂u and ∂s/∂v."""
        u = _core.float_array(u, "u", "a number or an array of numbers", contiguous=False)
        v = _core.float_array(v, "v", "a number or an array of numbers", contiguous=False)
        try:
            uu, vv = np.broadcast_arrays(u, v)
        except ValueError:
            raise ValueError("u, v: shapes %s and %s do not broadcast against each other"
                             % (u.shape, v.shape)) from None
        shape = uu.shape
        uf, vf = uu.reshape(-1), vv.reshape(-1)
        out = np.empty((3, uf.shape[0], 3))
        p = ffi.new("RmfVec3 *")
        du = ffi.new("RmfVec3 *") if derivatives else ffi.NULL
        dv = ffi.new("RmfVec3 *") if derivatives else ffi.NULL
        for i in range(uf.shape[0]):
            call("rmf_surface_eval", self._ptr, float(uf[i]), float(vf[i]), p, du, dv)
            out[0, i] = (p.x, p.y, p.z)
            if derivatives:
                out[1, i] = (du.x, du.y, du.z)
                out[2, i] = (dv.x, dv.y, dv.z)
        result = out.reshape((3,) + shape + (3,))
        return (result[0], result[1], result[2]) if derivatives else result[0]

    __call__ = eval

    def nurbs(self) -> NurbsSurface:
        """The surface as one clamped NURBS (copies). Raises InvalidInputError if the patches
        do not join continuously (then use :meth:`patches`)."""
        view = ffi.new("RmfNurbsSurface *")
        call("rmf_surface_nurbs", self._ptr, view)
        nu, nv = int(view.pole_count_u), int(view.pole_count_v)
        return NurbsSurface(int(view.degree_u), int(view.degree_v),
                            _core.copy_vec3s(view.poles, nu * nv).reshape(nu, nv, 3),
                            _core.copy_doubles(view.weights, nu * nv).reshape(nu, nv),
                            _core.copy_doubles(view.knots_u, view.knot_count_u),
                            _core.copy_doubles(view.knots_v, view.knot_count_v))

    @property
    def patch_count(self) -> Tuple[int, int]:
        """Numbers of Bézier patches along u and along v."""
        nu, nv = ffi.new("size_t *"), ffi.new("size_t *")
        call("rmf_surface_patch_count", self._ptr, nu, nv)
        return int(nu[0]), int(nv[0])

    def patches(self) -> List[List[BezierPatch]]:
        """Every Bézier patch, [i][j] with i along u (copies)."""
        nu, nv = self.patch_count
        view = ffi.new("RmfBezierPatch *")
        rows = []
        for i in range(nu):
            row = []
            for j in range(nv):
                call("rmf_surface_patch", self._ptr, i, j, view)
                a, b = view.degree_u + 1, view.degree_v + 1
                row.append(BezierPatch(int(view.degree_u), int(view.degree_v),
                                       _core.copy_vec3s(view.poles, a * b).reshape(a, b, 3),
                                       _core.copy_doubles(view.weights, a * b).reshape(a, b),
                                       float(view.u_start), float(view.u_end),
                                       float(view.v_start), float(view.v_end)))
            rows.append(row)
        return rows

    def tessellate(self, u_steps: int = 8, v_steps: int = 8) -> Tuple[np.ndarray, np.ndarray]:
        """A triangle mesh: every patch sampled on (u_steps + 1) × (v_steps + 1) points.
        Returns points (n, 3) and triangles (m, 3) of point indices (uint32),
        counter-clockwise seen from the side ∂s/∂u × ∂s/∂v points to."""
        us = _core.integer(u_steps, "u_steps", "uint32_t", 1)
        vs = _core.integer(v_steps, "v_steps", "uint32_t", 1)
        n_points, n_triangles = ffi.new("size_t *"), ffi.new("size_t *")
        call("rmf_surface_tessellate", self._ptr, us, vs, ffi.NULL, 0, ffi.NULL, 0, n_points,
             n_triangles)
        pts = np.empty((n_points[0], 3))
        tris = np.empty((n_triangles[0], 3), dtype=np.uint32)
        call("rmf_surface_tessellate", self._ptr, us, vs, _core.vec3_array(pts), n_points[0],
             ffi.cast("uint32_t *", ffi.from_buffer(tris)), n_triangles[0], n_points,
             n_triangles)
        return pts, tris

    def __repr__(self) -> str:
        nu, nv = self.patch_count
        return "<rmfsurf.Surface %d x %d patches>" % (nu, nv)


def as_surface(value: Any, name: str) -> Surface:
    return _core.instance(value, name, Surface, "an rmfsurf.Surface")


def sweep_surface(spine: Curve, frames: Frames, profile: Curve) -> Surface:
    """The sweep s(u, v) = x(v) + c2(u) f2(v) + c3(u) f3(v) of a profile (its x along f2,
    y along f3) along a spine with exact rational frames of that spine (Mäurer & Jüttler,
    (1) and (42)); u along the profile, v along the spine."""
    out = _core.out_pointer("RmfSurface")
    call("rmf_sweep_surface", as_curve(spine, "spine")._ptr, as_frames(frames, "frames")._ptr,
         as_curve(profile, "profile")._ptr, out)
    return Surface._owned(out)


@dataclass(frozen=True)
class SingularityMargin:
    """min of g = 1 − κ (c · n) over the sweep (condition (9)): ≤ 0 means singular.
    ``bound_margin`` = 1 − κ_max max|c|, a sufficient condition."""

    margin: float
    u: float
    v: float
    bound_margin: float


def singularity_margin(spine: Curve, frames: Frames, profile: Curve) -> SingularityMargin:
    """How close the sweep comes to being singular (Corollary 7 of Mäurer & Jüttler)."""
    out = ffi.new("RmfSingularityMargin *")
    call("rmf_sweep_singularity_margin", as_curve(spine, "spine")._ptr,
         as_frames(frames, "frames")._ptr, as_curve(profile, "profile")._ptr, out)
    return SingularityMargin(out.margin, out.u, out.v, out.bound_margin)


def gaussian_curvature(spine: Curve, frames: Frames, profile: Curve, u: float, v: float
                       ) -> float:
    """K = κ_u κ_v cos θ at (u, v) by (13) of Mäurer & Jüttler."""
    k = ffi.new("double *")
    call("rmf_sweep_gaussian_curvature", as_curve(spine, "spine")._ptr,
         as_frames(frames, "frames")._ptr, as_curve(profile, "profile")._ptr,
         _core.number(u, "u"), _core.number(v, "v"), k)
    return float(k[0])


PARABOLIC_KINDS = {lib.RMF_PARABOLIC_PROFILE: "profile", lib.RMF_PARABOLIC_SPINE: "spine",
                   lib.RMF_PARABOLIC_NORMAL: "normal"}


def parabolic_points(spine: Curve, frames: Frames, profile: Curve, v_samples: int = 64
                     ) -> List[Tuple[float, float, str]]:
    """The parabolic points (K = 0) on `v_samples` spine parameters as (u, v, kind), kind
    "profile", "spine" or "normal" (cases 1–3 of §2.3 of Mäurer & Jüttler)."""
    args = (as_curve(spine, "spine")._ptr, as_frames(frames, "frames")._ptr,
            as_curve(profile, "profile")._ptr,
            _core.integer(v_samples, "v_samples", "uint32_t", 2))
    count = ffi.new("size_t *")
    call("rmf_sweep_parabolic_points", *args, ffi.NULL, 0, count)
    buffer = ffi.new("RmfParabolicPoint[]", max(count[0], 1))
    call("rmf_sweep_parabolic_points", *args, buffer, count[0], count)
    return [(buffer[i].u, buffer[i].v, PARABOLIC_KINDS.get(buffer[i].kind, "unknown"))
            for i in range(count[0])]


def parabolic_curves(spine: Curve, frames: Frames, profile: Curve, tolerance: float
                     ) -> List[np.ndarray]:
    """The parabolic lines (14) of §2.3 of Mäurer & Jüttler (case 3) traced along the spine:
    one (n, 5) array per curve, rows (u, v, x, y, z) — the parameters and the surface point —
    in order along it; the polyline in (u, v) lifted to the surface is within `tolerance`
    of the line."""
    args = (as_curve(spine, "spine")._ptr, as_frames(frames, "frames")._ptr,
            as_curve(profile, "profile")._ptr, _core.number(tolerance, "tolerance"))
    count = ffi.new("size_t *")
    call("rmf_sweep_parabolic_curves", *args, ffi.NULL, 0, count)
    buffer = ffi.new("RmfParabolicCurvePoint[]", max(count[0], 1))
    call("rmf_sweep_parabolic_curves", *args, buffer, count[0], count)
    rows: List[List[List[float]]] = []
    for i in range(count[0]):
        b = buffer[i]
        if b.curve >= len(rows):
            rows.append([])
        rows[-1].append([b.u, b.v, b.point.x, b.point.y, b.point.z])
    return [np.array(r) for r in rows]


def convex_initial_normal(ph_spline: Curve, profile: Curve, elliptic: bool = True
                          ) -> Tuple[np.ndarray, float]:
    """The initial normal making the RMF sweep of a convex profile everywhere elliptic (or
    hyperbolic), Corollary 9 of Mäurer & Jüttler; and the slack π − δ − ΔΩ."""
    normal, margin = ffi.new("RmfVec3 *"), ffi.new("double *")
    call("rmf_ph_convex_initial_normal", as_curve(ph_spline, "ph_spline")._ptr,
         as_curve(profile, "profile")._ptr, 1 if elliptic else 0, normal, margin)
    return _core.from_vec3(normal), float(margin[0])
