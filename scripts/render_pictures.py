"""Renders docs/images/rmfsurf.png (and the wire sweeps' pictures, docs/images/sweep-*.png)
from the demo's output (run by scripts/render-pictures).

    python3 render_pictures.py <demo-output-directory> <png> [<sweep-frames png>
        [<guide-knots png> [<sections png>]]]

Three panels, each drawn from a file the demo writes:
  1. closed_sweep_trefoil.vtp: a square tube swept along a trefoil with the PH cubic
     rational RMF, closed without a seam;
  2. cone_spline.vtp: the cone spline strip fitted to the tangent surface of (t, t², t³),
     its rulings (the piece boundaries) drawn as lines;
  3. cone_spline_development.svg: the strip's exact development, lines and circular arcs.

Needs VTK's Python module (Debian: python3-vtk9) and an X display (xvfb-run).
"""

import math
import re
import sys

import vtk

vtk.vtkMapper.SetResolveCoincidentTopologyToPolygonOffset()  # rulings drawn on the strip

WIDTH, HEIGHT = 1200, 440
RULINGS_EVERY = 8  # the demo tessellates each cone piece with 8 steps along v
CONE_ROWS = 5  # ... and 4 steps along the rulings


def read_vtp(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def shaded(polydata, color, feature_angle=50.0):
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(polydata)
    normals.SetFeatureAngle(feature_angle)
    normals.SplittingOn()
    normals.ConsistencyOn()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(color)
    prop.SetAmbient(0.3)
    prop.SetDiffuse(0.75)
    prop.SetSpecular(0.3)
    prop.SetSpecularPower(30)
    return actor


def lines_actor(points, segments, color, width):
    pts = vtk.vtkPoints()
    cells = vtk.vtkCellArray()
    for a, b in segments:
        ia = pts.InsertNextPoint(points[a] if isinstance(a, int) else a)
        ib = pts.InsertNextPoint(points[b] if isinstance(b, int) else b)
        line = vtk.vtkLine()
        line.GetPointIds().SetId(0, ia)
        line.GetPointIds().SetId(1, ib)
        cells.InsertNextCell(line)
    poly = vtk.vtkPolyData()
    poly.SetPoints(pts)
    poly.SetLines(cells)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(poly)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(color)
    actor.GetProperty().SetLineWidth(width)
    actor.GetProperty().SetLighting(False)
    return actor


def cone_rulings(polydata):
    """The rulings at the piece boundaries: grid point (i, j) is at i * columns + j."""
    columns = polydata.GetNumberOfPoints() // CONE_ROWS
    p = polydata.GetPoints()
    segments = []
    for j in range(0, columns, RULINGS_EVERY):
        segments.append((p.GetPoint(j), p.GetPoint((CONE_ROWS - 1) * columns + j)))
    return segments


def svg_arc_points(x0, y0, r, large, sweep, x1, y1, steps=24):
    """Points of an SVG circular arc (rx = ry = r, no rotation) from (x0, y0) to (x1, y1)."""
    mx, my = (x0 - x1) / 2, (y0 - y1) / 2
    d2 = mx * mx + my * my
    r = max(r, math.sqrt(d2))
    f = math.sqrt(max(r * r - d2, 0.0) / d2) if d2 > 0 else 0.0
    if large == sweep:
        f = -f
    cx = (x0 + x1) / 2 + f * my
    cy = (y0 + y1) / 2 - f * mx
    a0 = math.atan2(y0 - cy, x0 - cx)
    a1 = math.atan2(y1 - cy, x1 - cx)
    da = a1 - a0
    if sweep and da < 0:
        da += 2 * math.pi
    if not sweep and da > 0:
        da -= 2 * math.pi
    return [
        (cx + r * math.cos(a0 + da * k / steps), cy + r * math.sin(a0 + da * k / steps))
        for k in range(1, steps + 1)
    ]


def read_development(path):
    """The outline (a closed polygon, arcs discretized) and the bend lines of the SVG."""
    text = open(path, encoding="utf-8").read()
    d = re.search(r' d="([^"]*)"', text).group(1)
    tokens = d.split()
    outline, k = [], 0
    while k < len(tokens):
        cmd = tokens[k]
        if cmd in ("M", "L"):
            outline.append((float(tokens[k + 1]), float(tokens[k + 2])))
            k += 3
        elif cmd == "A":
            r, large, sweep = float(tokens[k + 1]), int(tokens[k + 4]), int(tokens[k + 5])
            x1, y1 = float(tokens[k + 6]), float(tokens[k + 7])
            x0, y0 = outline[-1]
            outline.extend(svg_arc_points(x0, y0, r, large, sweep, x1, y1))
            k += 8
        elif cmd == "Z":
            k += 1
        else:
            raise ValueError(f"unexpected SVG path command {cmd!r}")
    bends = [
        tuple(float(v) for v in m.groups())
        for m in re.finditer(r'x1="([^"]*)" y1="([^"]*)" x2="([^"]*)" y2="([^"]*)"', text)
    ]
    return outline, bends


def development_actors(path):
    outline, bends = read_development(path)
    # SVG y points down; the pattern is drawn in the xy-plane with y up, in the units of the
    # 3-D strip (the SVG is at 100:1).
    flip = [(x / 100.0, -y / 100.0, 0.0) for x, y in outline]
    pts = vtk.vtkPoints()
    polygon = vtk.vtkPolygon()
    polygon.GetPointIds().SetNumberOfIds(len(flip))
    for i, p in enumerate(flip):
        pts.InsertNextPoint(p)
        polygon.GetPointIds().SetId(i, i)
    cells = vtk.vtkCellArray()
    cells.InsertNextCell(polygon)
    poly = vtk.vtkPolyData()
    poly.SetPoints(pts)
    poly.SetPolys(cells)
    tri = vtk.vtkTriangleFilter()  # the outline is not convex
    tri.SetInputData(poly)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(tri.GetOutputPort())
    fill = vtk.vtkActor()
    fill.SetMapper(mapper)
    fill.GetProperty().SetColor(0.98, 0.80, 0.58)
    fill.GetProperty().SetLighting(False)
    edge = [(flip[i], flip[(i + 1) % len(flip)]) for i in range(len(flip))]
    bend = [((x1 / 100, -y1 / 100, 1e-4), (x2 / 100, -y2 / 100, 1e-4)) for x1, y1, x2, y2 in bends]
    return [
        fill,
        lines_actor(None, bend, (0.55, 0.35, 0.2), 1.0),
        lines_actor(None, edge, (0.25, 0.15, 0.05), 2.0),
    ]


def label(text):
    actor = vtk.vtkTextActor()
    actor.SetInput(text)
    prop = actor.GetTextProperty()
    prop.SetFontSize(16)
    prop.SetColor(0.15, 0.15, 0.2)
    prop.SetJustificationToCentered()
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.SetPosition(0.5, 0.05)
    return actor


def panel(window, x0, x1, actors, caption, view_up, direction, zoom=1.0):
    renderer = vtk.vtkRenderer()
    renderer.SetViewport(x0, 0.0, x1, 1.0)
    renderer.SetBackground(1.0, 1.0, 1.0)
    for a in actors:
        renderer.AddActor(a)
    renderer.AddActor2D(label(caption))
    renderer.UseFXAAOn()
    renderer.TwoSidedLightingOn()  # the cone strip is an open sheet: light both sides
    vtk.vtkLightKit().AddLightsToRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*direction)
    camera.SetViewUp(*view_up)
    renderer.ResetCamera()
    camera.Zoom(zoom)
    # Leave room for the caption.
    camera.SetWindowCenter(0.0, -0.08)
    window.AddRenderer(renderer)
    return renderer


def new_window():
    """An off-screen window of the pictures' size."""
    window = vtk.vtkRenderWindow()
    window.SetSize(WIDTH, HEIGHT)
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    return window


def main(demo_dir, png):
    window = new_window()

    tube = read_vtp(f"{demo_dir}/closed_sweep_trefoil.vtp")
    panel(
        window, 0.0, 0.36,
        [shaded(tube, (0.45, 0.64, 0.86))],
        "square tube swept along a trefoil\nPH cubic spline, rational RMF, no seam",
        (0, 0, 1), (1.0, -1.4, 1.3), 1.15,
    )

    cone = read_vtp(f"{demo_dir}/cone_spline.vtp")
    panel(
        window, 0.36, 0.68,
        [shaded(cone, (0.95, 0.62, 0.32), 80.0), lines_actor(None, cone_rulings(cone), (0.4, 0.22, 0.08), 1.5)],
        "cone spline developable: 20 cones\nwithin 3.7e-5 of the tangent surface of (t, t², t³)",
        (0, 0, 1), (-0.7, -0.7, 0.9), 1.25,
    )

    panel(
        window, 0.68, 1.0,
        development_actors(f"{demo_dir}/cone_spline_development.svg"),
        "its exact flat pattern\nlines and circular arcs (SVG, DXF)",
        (0, 1, 0), (0, 0, 1), 1.0,
    )

    write_png(window, png)


def sweep_frames(demo_dir, png):
    """docs/images/sweep-frames.png: the demo's section 9."""
    window = new_window()
    panel(
        window, 0.0, 0.33,
        [shaded(read_vtp(f"{demo_dir}/thread_frenet.vtp"), (0.80, 0.62, 0.30), 40.0)],
        "a thread ridge along a helix, Frenet frame:\nits edges are helices (screw motion)",
        (0, 0, 1), (1.0, -1.6, 0.5), 1.1,
    )
    panel(
        window, 0.33, 0.66,
        [shaded(read_vtp(f"{demo_dir}/thread_rmf.vtp"), (0.55, 0.55, 0.60), 40.0)],
        "the same ridge with the RMF:\nit turns against the screw motion",
        (0, 0, 1), (1.0, -1.6, 0.5), 1.1,
    )
    panel(
        window, 0.66, 1.0,
        [shaded(read_vtp(f"{demo_dir}/pipe_tapered.vtp"), (0.45, 0.64, 0.86))],
        "scale law from 1 to 0.4 along line, arc, line:\nexact on lines, arcs within the tolerance",
        (0, 1, 0), (0.3, -0.5, 1.0), 1.1,
    )
    write_png(window, png)


def guide_and_knots(demo_dir, png):
    """docs/images/sweep-guide-knots.png: the demo's section 9, its guide and scale knots."""
    window = new_window()
    guide = read_vtp(f"{demo_dir}/bar_guide.vtp")
    points = [guide.GetPoint(k) for k in range(guide.GetNumberOfPoints())]
    helix = lines_actor(points, [(k, k + 1) for k in range(len(points) - 1)], (0.25, 0.35, 0.7), 2.5)
    panel(
        window, 0.0, 0.5,
        [shaded(read_vtp(f"{demo_dir}/bar_guided.vtp"), (0.80, 0.62, 0.30), 40.0), helix],
        "a flat bar up a line, its width turned to point at\na helical guide (blue): frame \"guide\"",
        (0, 0, 1), (1.0, -1.4, 0.7), 0.85,
    )
    panel(
        window, 0.5, 1.0,
        [shaded(read_vtp(f"{demo_dir}/baluster.vtp"), (0.45, 0.64, 0.86), 40.0)],
        "a baluster: a circle through scales 1, 1.6, 0.6, 1.3, 1\n(scale_knots): a chain of exact frustums",
        (0, 0, 1), (1.0, -1.4, 0.7), 0.85,
    )
    write_png(window, png)


def sections_and_sheet(demo_dir, png):
    """docs/images/sweep-sections.png: the demo's section 9, a sweep through sections and a
    sheet from an open profile."""
    window = new_window()
    panel(
        window, 0.0, 0.5,
        [shaded(read_vtp(f"{demo_dir}/pipe_sections.vtp"), (0.45, 0.64, 0.86), 40.0)],
        "the pipe route through a square, a circle half way\nand a triangle (sections): one solid, shared sections",
        (0, 0, 1), (0.5, -1.0, 0.9), 1.05,
    )
    panel(
        window, 0.5, 1.0,
        [shaded(read_vtp(f"{demo_dir}/gutter.vtp"), (0.80, 0.62, 0.30), 40.0)],
        "an open half circle along the same route:\na sheet (solid off), exact cylinders and torus",
        (0, 0, 1), (0.5, -1.0, 0.9), 1.05,
    )
    write_png(window, png)


def write_png(window, png):
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetCompressionLevel(9)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
    if len(sys.argv) > 3:
        sweep_frames(sys.argv[1], sys.argv[3])
    if len(sys.argv) > 4:
        guide_and_knots(sys.argv[1], sys.argv[4])
    if len(sys.argv) > 5:
        sections_and_sheet(sys.argv[1], sys.argv[5])
