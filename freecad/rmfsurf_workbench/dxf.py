"""Flat patterns as DXF R12 (AC1009) files for the cutter, as the library's own writer makes
them (src/export/dxf.rs; the command-line tool's DXF): true LINE and ARC entities, never
polylines or splines, the outline on layer CUT and the bend lines on layer BEND, numbers
written to full double precision. An ARC runs counter-clockwise from its start to its end
angle (degrees) about the z axis.

FreeCAD's own DXF writer rounds coordinates to six significant digits (0.1 µm on a part
of 100 mm, 0.1 mm on one of 100 m): this one keeps the pattern exact.
"""

import math

import Part

CUT_LAYER = "CUT"
BEND_LAYER = "BEND"


def _number(x):
    text = repr(float(x) + 0.0)
    return text[:-2] if text.endswith(".0") else text


def _entity(pairs):
    return "".join("%d\n%s\n" % (code, value) for code, value in pairs)


def _degrees(center, point):
    return math.degrees(math.atan2(point.y - center.y, point.x - center.x)) % 360.0


def edge_entity(edge, layer, name="edge"):
    """One planar edge (z = 0) as a DXF LINE, ARC or CIRCLE entity."""
    curve = edge.Curve
    a, b = edge.valueAt(edge.FirstParameter), edge.valueAt(edge.LastParameter)
    if isinstance(curve, (Part.Line, Part.LineSegment)):
        return _entity([(0, "LINE"), (8, layer), (10, _number(a.x)), (20, _number(a.y)),
                        (30, "0"), (11, _number(b.x)), (21, _number(b.y)), (31, "0")])
    if isinstance(curve, Part.Circle):
        if abs(abs(curve.Axis.z) - 1) > 1e-12:
            raise ValueError("%s: an arc not in the xy-plane" % name)
        c = curve.Center
        head = [(8, layer), (10, _number(c.x)), (20, _number(c.y)), (30, "0"),
                (40, _number(curve.Radius))]
        if edge.isClosed():
            return _entity([(0, "CIRCLE")] + head)
        # The circle's parameter runs counter-clockwise about its axis: a clockwise arc
        # (axis −z) is drawn from its end.
        start, end = (a, b) if curve.Axis.z > 0 else (b, a)
        return _entity([(0, "ARC")] + head + [(50, _number(_degrees(c, start))),
                                              (51, _number(_degrees(c, end)))])
    raise ValueError("%s: a %s, not a line or a circular arc" % (name, type(curve).__name__))


def write_flat_pattern(path, outline, bend_lines):
    """Writes the edges `outline` (layer CUT) and `bend_lines` (layer BEND), all in the
    plane z = 0, as a DXF R12 file."""
    for k, edge in enumerate(list(outline) + list(bend_lines)):
        box = edge.BoundBox
        if max(abs(box.ZMin), abs(box.ZMax)) > 1e-9 * max(1.0, box.DiagonalLength):
            raise ValueError("edge %d: not in the plane z = 0" % k)
    text = _entity([(0, "SECTION"), (2, "HEADER"), (9, "$ACADVER"), (1, "AC1009"),
                    (0, "ENDSEC"), (0, "SECTION"), (2, "ENTITIES")])
    text += "".join(edge_entity(e, CUT_LAYER, "outline edge %d" % k)
                    for k, e in enumerate(outline))
    text += "".join(edge_entity(e, BEND_LAYER, "bend line %d" % k)
                    for k, e in enumerate(bend_lines))
    text += _entity([(0, "ENDSEC"), (0, "EOF")])
    with open(path, "w") as f:
        f.write(text)
