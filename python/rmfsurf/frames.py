"""Frames along curves (``RmfFrames``): the rational rotation-minimizing frame of PH cubic
splines (Mäurer & Jüttler §3.3–3.4), double-reflection frames, Frenet frames, and the exact
rational RMFs that come with Möbius and RRMF curves (see :mod:`rmfsurf.curves`).
"""

from __future__ import annotations

from typing import Any, Dict, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import call, ffi, lib
from .curves import ArrayLike, Curve, Inversion, _maps, as_curve

KINDS: Dict[int, str] = {
    lib.RMF_FRAMES_RATIONAL: "rational",
    lib.RMF_FRAMES_DOUBLE_REFLECTION: "double_reflection",
    lib.RMF_FRAMES_FRENET: "frenet",
}
#: The methods of :func:`framed_spine`, by the names the tools use.
SPINE_METHODS: Dict[str, int] = {
    "ph-rmf": lib.RMF_SPINE_PH_RMF,
    "frenet": lib.RMF_SPINE_FRENET,
    "mobius": lib.RMF_SPINE_MOBIUS,
    "rrmf": lib.RMF_SPINE_RRMF,
}
VECTORS: Dict[str, int] = {
    "tangent": lib.RMF_FRAME_TANGENT,
    "f2": lib.RMF_FRAME_F2,
    "f3": lib.RMF_FRAME_F3,
}


class Frames:
    """An adapted frame (t, f2, f3) along a curve, f3 = t × f2. Keeps its own reference to
    its curve. Freed when collected."""

    __slots__ = ("_ptr", "__weakref__")

    def __init__(self, pointer: Any) -> None:
        self._ptr = pointer

    @classmethod
    def _owned(cls, out: Any) -> "Frames":
        return cls(_core.owned("frames", out[0]))

    @property
    def domain(self) -> Tuple[float, float]:
        """The parameter domain of the frames' curve."""
        lo, hi = ffi.new("double *"), ffi.new("double *")
        call("rmf_frames_domain", self._ptr, lo, hi)
        return lo[0], hi[0]

    @property
    def kind(self) -> str:
        """"rational" (exact rational frames, sweepable), "double_reflection" or "frenet"."""
        k = ffi.new("uint32_t *")
        call("rmf_frames_kind", self._ptr, k)
        return KINDS.get(int(k[0]), "unknown")

    def eval(self, t: ArrayLike) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(tangent, f2, f3) at t: each of shape (3,) for a scalar t, (n, 3) for n."""
        ts, scalar = _core.parameters(t, "t")
        out = np.empty((3, ts.shape[0], 3))
        v = [ffi.new("RmfVec3 *") for _ in range(3)]
        for i, ti in enumerate(ts):
            call("rmf_frames_eval", self._ptr, float(ti), v[0], v[1], v[2])
            for k in range(3):
                out[k, i] = (v[k].x, v[k].y, v[k].z)
        if scalar:
            return out[0, 0], out[1, 0], out[2, 0]
        return out[0], out[1], out[2]

    __call__ = eval

    def vector_curve(self, which: str) -> Curve:
        """One frame vector ("tangent", "f2" or "f3") of rational frames as a rational curve
        on the unit sphere."""
        out = _core.out_pointer("RmfCurve")
        call("rmf_frames_vector_curve", self._ptr, _core.choice(which, "which", VECTORS), out)
        return Curve._owned(out)

    def __repr__(self) -> str:
        lo, hi = self.domain
        return "<rmfsurf.Frames %s on [%g, %g]>" % (self.kind, lo, hi)


def as_frames(value: Any, name: str) -> Frames:
    return _core.instance(value, name, Frames, "rmfsurf.Frames")


def ph_rational_rmf(ph_spline: Curve, initial_normal: ArrayLike = (0.0, 0.0, 1.0), *,
                    twist: float = 0.0, closure_symmetry: int = 0) -> Frames:
    """The rational approximation of the RMF of a PH cubic spline (Mäurer & Jüttler
    §3.3–3.4), exact at the joints, degree 6. `twist` adds a turn linear in arc length
    (radians from start to end); `closure_symmetry` k ≥ 1 closes the frame of a closed
    spine modulo 2π/k (k = the profile's symmetry order); 0 leaves the RMF's holonomy
    (docs/c-api.md, "Parameters")."""
    spline = as_curve(ph_spline, "ph_spline")
    normal = _core.vec3(initial_normal, "initial_normal")
    turn = _core.number(twist, "twist")
    symmetry = _core.integer(closure_symmetry, "closure_symmetry", "uint32_t")
    out = _core.out_pointer("RmfFrames")
    if turn == 0.0 and symmetry == 0:
        call("rmf_ph_rational_rmf", spline._ptr, normal, out)
    else:
        call("rmf_ph_rational_rmf_twisted", spline._ptr, normal, turn, symmetry, out)
    return Frames._owned(out)


def framed_spine(curve: Curve, method: str = "ph-rmf", tolerance: float = 1e-4,
                 initial_normal: ArrayLike = (0.0, 0.0, 1.0)) -> Tuple[Curve, Frames, float]:
    """A spine within `tolerance` of a G1 rational `curve` with rational frames by `method`
    (rmf_framed_spine): "ph-rmf" (PH cubic spline, rational RMF), "frenet" (its exact
    rational Frenet frame), "mobius" or "rrmf" (exact rational RMFs through samples of the
    curve, doubled until within the tolerance). Returns (spine, frames, distance), distance
    the largest one measured between spine and curve."""
    source = as_curve(curve, "curve")
    code = _core.choice(method, "method", SPINE_METHODS)
    spine, frames = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfFrames")
    distance = ffi.new("double *")
    call("rmf_framed_spine", source._ptr, code, _core.number(tolerance, "tolerance"),
         _core.vec3(initial_normal, "initial_normal"), spine, frames, distance)
    return Curve._owned(spine), Frames._owned(frames), float(distance[0])


def ph_frenet_frames(ph_spline: Curve) -> Frames:
    """The Frenet frame of a PH cubic spline as exact rational functions (for comparison:
    its sweeps are not profile surfaces)."""
    out = _core.out_pointer("RmfFrames")
    call("rmf_ph_frenet_frames", as_curve(ph_spline, "ph_spline")._ptr, out)
    return Frames._owned(out)


def double_reflection_frames(curve: Curve, initial_normal: ArrayLike = (0.0, 0.0, 1.0),
                             samples: int = 1000) -> Frames:
    """The double-reflection RMF (Wang, Jüttler, Zheng & Liu) of any curve, `samples`
    uniform samples: the library's reference RMF."""
    out = _core.out_pointer("RmfFrames")
    call("rmf_double_reflection_frames", as_curve(curve, "curve")._ptr,
         _core.vec3(initial_normal, "initial_normal"),
         _core.integer(samples, "samples", "size_t", 2), out)
    return Frames._owned(out)


def frenet_frames(curve: Curve) -> Frames:
    """The Frenet frame of any curve, evaluated pointwise (f2 = n, f3 = b)."""
    out = _core.out_pointer("RmfFrames")
    call("rmf_frenet_frames", as_curve(curve, "curve")._ptr, out)
    return Frames._owned(out)


def mobius_frames(frames: Frames, maps: Union[Inversion, Sequence[Inversion]]
                  ) -> Tuple[Curve, Frames]:
    """The images of rational frames and their curve under a Möbius transformation: an RMF
    goes to an RMF (Bartoň, Jüttler & Wang, Theorem 1)."""
    array, n = _maps(maps)
    c, f = _core.out_pointer("RmfCurve"), _core.out_pointer("RmfFrames")
    call("rmf_mobius_frames", as_frames(frames, "frames")._ptr, array, n, c, f)
    return Curve._owned(c), Frames._owned(f)


def ph_exact_rmf(ph_spline: Curve, initial_normal: ArrayLike, t: ArrayLike
                 ) -> Tuple[np.ndarray, np.ndarray]:
    """The exact RMF of a PH cubic spline at parameters t, in closed form (30)–(31) of
    Mäurer & Jüttler: (f2, f3), each (n, 3)."""
    ts, _ = _core.parameters(t, "t")
    f2, f3 = np.empty((ts.shape[0], 3)), np.empty((ts.shape[0], 3))
    call("rmf_ph_exact_rmf_eval", as_curve(ph_spline, "ph_spline")._ptr,
         _core.vec3(initial_normal, "initial_normal"), _core.double_array(ts), ts.shape[0],
         _core.vec3_array(f2), _core.vec3_array(f3))
    return f2, f3


def ph_rmf_angle_error(frames: Frames) -> Tuple[float, np.ndarray]:
    """The largest angle between rational frames along a PH spline and its exact RMF, and
    the largest per spline segment (radians)."""
    f = as_frames(frames, "frames")
    count, worst = ffi.new("size_t *"), ffi.new("double *")
    call("rmf_ph_rmf_angle_error", f._ptr, ffi.NULL, 0, count, worst)
    per_segment = np.empty(count[0])
    call("rmf_ph_rmf_angle_error", f._ptr, _core.double_array(per_segment), count[0], count,
         worst)
    return float(worst[0]), per_segment
