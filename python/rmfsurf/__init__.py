"""rmfsurf: exact rational curves, rotation-minimizing frames and surfaces for sweeping and
sheet-metal design, over the C library librmfsurf (bundled in this package).

The four methods of the library:

* PH cubic splines and their rational rotation-minimizing frame (Mäurer & Jüttler):
  :func:`ph_spline_hermite`, :func:`ph_spline_approximate`, :func:`ph_rational_rmf`;
* curves with exact rational RMFs by Möbius maps (Bartoň, Jüttler & Wang):
  :func:`mobius_rrmf_hermite`, :func:`mobius_rrmf_approximate`;
* RRMF quintics (Farouki, Giannelli & Sestini): :func:`rrmf_spline_hermite`, ...;
* cone spline surfaces and their flat patterns (Leopoldseder & Pottmann):
  :func:`cone_spline_approximate`, :meth:`ConeSpline.flat_pattern`, ...;
  sheet-metal parts of them: :func:`transition` (square-to-round and every convex
  transition piece, with thickness and K-factor), :class:`SheetPart` (layers, solid, flat
  pattern for the cutter, marks between flat and formed);
* unfolding the caller's own faces (:mod:`rmfsurf.unfold`): :meth:`Brep.create` from plain
  B-rep data, :func:`developability` (how developable a face is), :func:`unfold_face` (its
  exact flat pattern with holes, bend lines, DXF and marks) and :func:`unfold_body` (a whole
  sheet-metal body on its neutral layer, bends up and down)

and what is made of them: :func:`sweep_surface` (a profile along a spine with exact rational
frames) and :func:`wire_sweep` (a profile along a wire of lines, arcs and curves, closed into a
solid). Arrays go in and come out as NumPy arrays; failures raise :class:`RmfError` (one
subclass per status); library objects are freed by the garbage collector.

CAD adapters: :mod:`rmfsurf.ocp` (OpenCascade's Python bindings, as used by build123d and
CadQuery) and :mod:`rmfsurf.freecad` (FreeCAD's Part objects).
"""

from ._core import (BufferTooSmallError, FileError, InternalError, InvalidInputError,
                    NoSolutionError, NotConvergedError, NullPointerError, RmfError, ffi, lib,
                    live_handles)
from .cone_splines import (ConeElement, ConePiece, ConeSpline, FlatPattern,
                           cone_spline_approximate, cone_spline_approximate_dual,
                           cone_spline_approximate_ruled, cone_spline_hermite,
                           cone_spline_osculating)
from .curves import (BezierSegment, Curve, Inversion, NurbsCurve, RrmfQuintic, arc, circle,
                     distinct_knots, obround, polygon, polyline,
                     flat_knots, join_nurbs, mobius_curve, mobius_point, mobius_rrmf_approximate,
                     mobius_rrmf_hermite, ph_cubic_hermite, ph_spline_approximate,
                     ph_spline_hermite, profile_offset, profile_offset_by_arcs, rrmf_quintic_best,
                     rrmf_quintic_curve, rrmf_quintic_solutions, rrmf_spline_hermite)
from .frames import (SPINE_METHODS, Frames, double_reflection_frames, framed_spine,
                     frenet_frames, mobius_frames, ph_exact_rmf, ph_frenet_frames,
                     ph_rational_rmf, ph_rmf_angle_error)
from .shapes import Arc, CurveEdge, Line, Shape, ShapeFace, SweepReport, wire_sweep
from .sheets import FlatEdge, SheetPart, SheetReport, part_between_rails, tangent_part, transition
from .unfold import (Bend, Brep, BrepEdge, BrepFace, Developability, UnfoldedBody, UnfoldedFace,
                     developability, line_curve, unfold_body, unfold_face)
from .surfaces import (BezierPatch, NurbsSurface, SingularityMargin, Surface,
                       convex_initial_normal, gaussian_curvature, parabolic_curves,
                       parabolic_points, singularity_margin, sweep_surface)


def rmf_version() -> str:
    """The version of the loaded librmfsurf, rmf_version()."""
    return ffi.string(lib.rmf_version()).decode()


#: The package version: that of the library it carries.
__version__ = rmf_version()
#: The library's ABI number (the N of librmfsurf.so.N).
ABI_VERSION: int = lib.RMF_ABI_VERSION

__all__ = [name for name in dir() if not name.startswith("_") and name not in ("ffi", "lib")]
