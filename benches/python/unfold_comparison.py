"""Unfolding side by side in FreeCAD (run by scripts/bench with freecadcmd): the same faces
unrolled by FreeCAD's own mesh unwrapper (flatmesh.FaceUnwrapper on the face's
triangulation at a deflection of 0.01 mm, as MeshPart's "Unwrap mesh" command does: the
triangles flattened by least squares; its "Unwrap face" command unwraps the untrimmed
surface, holes and trims ignored) and by rmfsurf.freecad.unfold,
each pattern's area and outline length against the formed face's (exact where the face is
analytic: the closed forms below; a B-spline extrusion's: its curve's length × height).
Prints one table row per face; the figures go to docs/unfold.md.

    freecadcmd benches/python/unfold_comparison.py
"""

import math
import sys
import time

import numpy as np

import FreeCAD
import Part
import flatmesh

import rmfsurf.freecad as rf

V = FreeCAD.Vector


def windowed_cone():
    """A frustum (radii 10 and 4, height 20) with a window between the heights 7 and 13
    and 40° of turn: two parallel circles and two rulings."""
    cone = Part.makeCone(10, 4, 20)
    window = Part.makeCylinder(30, 6, V(0, 0, 7), V(0, 0, 1), 40)
    window.rotate(V(0, 0, 0), V(0, 0, 1), 120)
    return [f for f in cone.cut(window).Faces if isinstance(f.Surface, Part.Cone)][0]


def drilled_tube():
    """A tube of radius 6 and height 30 with a radial hole of radius 2: the hole's edge is
    a space curve (the intersection of two cylinders)."""
    tube = Part.makeCylinder(6, 30)
    hole = Part.makeCylinder(2, 20, V(-10, 0, 15), V(1, 0, 0))
    walls = [f for f in tube.cut(hole).Faces if isinstance(f.Surface, Part.Cylinder)]
    return max(walls, key=lambda f: f.Area)


def wave():
    curve = Part.BSplineCurve()
    curve.interpolate([V(0, 0, 0), V(10, 6, 0), V(20, -6, 0), V(30, 6, 0), V(40, 0, 0)])
    return curve.toShape().extrude(V(0, 0, 15)).Faces[0], 15 * curve.length()


def unwrapper(face, deflection=0.01):
    """FreeCAD's mesh unwrapper on `face`'s triangulation: (seconds, triangles, flat area,
    boundary length)."""
    start = time.perf_counter()
    points, triangles = face.tessellate(deflection)
    u = flatmesh.FaceUnwrapper(np.array([tuple(p) for p in points], dtype=float),
                               np.array(triangles, dtype=np.int64))
    u.findFlatNodes(5, 0.95)
    seconds = time.perf_counter() - start
    nodes, tris = np.asarray(u.ze_nodes), np.asarray(u.tris)
    a, b, c = nodes[tris[:, 0]], nodes[tris[:, 1]], nodes[tris[:, 2]]
    area = 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                        - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])).sum()
    length = 0.0
    for loop in u.getFlatBoundaryNodes():
        p = np.asarray(loop)[:, :2]
        length += np.linalg.norm(np.diff(np.vstack([p, p[:1]]), axis=0), axis=1).sum()
    return seconds, len(tris), area, length


def ours(face):
    start = time.perf_counter()
    pattern = rf.unfold(face, tolerance=1e-5, flat_tolerance=1e-6)
    seconds = time.perf_counter() - start
    return seconds, pattern


def main():
    cone = windowed_cone()
    # A frustum's lateral area π (r₁ + r₂) s, s its slant; the window: 40° of the band
    # between the heights 7 and 13.
    radius = lambda h: 10 - 6 * h / 20  # noqa: E731
    band = lambda h0, h1: math.pi * (radius(h0) + radius(h1)) * math.hypot(6 * (h1 - h0) / 20, h1 - h0)  # noqa: E731
    cone_area = band(0, 20) - band(7, 13) * 40 / 360
    tube = drilled_tube()
    # The hole's footprint on each wall: ∫ 2√(4 − y²) / √(1 − y²/36) dy over |y| ≤ 2, with
    # y = 2 sin φ: ∫ 8 cos²φ / √(1 − sin²φ / 9) dφ over |φ| ≤ π/2 (smooth: Gauss–Legendre).
    x, w = np.polynomial.legendre.leggauss(40)
    phi = 0.5 * math.pi * x
    footprint = 0.5 * math.pi * np.sum(w * 8 * np.cos(phi) ** 2 / np.sqrt(1 - np.sin(phi) ** 2 / 9))
    tube_area = 2 * math.pi * 6 * 30 - 2 * footprint
    wave_face, wave_area = wave()
    rows = [("cone frustum with a window", cone, cone_area),
            ("tube with a radial hole through both walls", tube, tube_area),
            ("extruded B-spline wave", wave_face, wave_area)]
    print("| face | FreeCAD mesh unwrapper: triangles, area error, outline length error, time "
          "| rmfsurf.freecad.unfold: edges, area error, outline length error, time |")
    print("| --- | --- | --- |")
    for name, face, area in rows:
        boundary = sum(e.Length for e in face.Edges if not e.isSeam(face) and not e.Degenerated)
        seam = sum(e.Length for e in face.Edges if e.isSeam(face))
        t0, triangles, flat_area, flat_length = unwrapper(face)
        t1, pattern = ours(face)
        cut = pattern.unfolded.cut_length
        # A cut-open face's outline runs along its seam twice.
        length = boundary + 2 * seam
        print("| %s | %d, %.1e, %.1e, %.0f ms | %d, %.1e, %.1e, %.0f ms |"
              % (name, triangles, abs(flat_area - area) / area, abs(flat_length - length) / length,
                 1e3 * t0, len(pattern.unfolded.outline) + sum(map(len, pattern.unfolded.holes)),
                 abs(pattern.area - area) / area, abs(cut - length) / length, 1e3 * t1))
    sys.stdout.flush()


main()
