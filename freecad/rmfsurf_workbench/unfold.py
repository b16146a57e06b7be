"""RmfUnfold: the exact flat pattern of a sheet-metal part — a planar face bounded by lines
and circular arcs, and the bend lines (the rulings where cone pieces meet) — and its DXF
export for the cutter.

Sources:

* an RmfTransition: the development of its neutral layer (the layer at KFactor · Thickness
  from the inner side), from the library's flat pattern;
* a developable face (ruled, degree 1 along its rulings: cones, cylinders, tangent surfaces
  and planes as B-spline or analytic faces): approximated within Tolerance by a cone spline
  (Leopoldseder & Pottmann, eqs. (5)–(12)) and developed exactly, piece by piece (their
  eqs. (7)–(8)); the pattern is the strip between the cone spline's boundaries through the
  face's first ruling (:func:`rmfsurf.freecad.cone_spline_from_face`).

The outline's arcs are exact circular arcs (``Part.Circle``), so the DXF has ARC and LINE
entities only. The pattern lies in the plane z = 0; the feature's Placement moves it in the
document, not in the DXF.
"""

import os

import FreeCAD
import Part

from . import inputs
from .feature import Feature, Property, is_feature
from .view import attach_view


class UnfoldFeature(Feature):
    TYPE = "RmfUnfold"
    PROPERTIES = (
        Property("App::PropertyLinkSub", "Source", "Unfold",
                 "An RmfTransition, or a developable face (an object with one face, or a "
                 "face of an object)"),
        Property("App::PropertyFloat", "Tolerance", "Unfold",
                 "Developable faces: the largest distance of the cone spline from the face "
                 "(mm); an RmfTransition has its own", default=1e-4),
        Property("App::PropertyArea", "FlatArea", "Pattern",
                 "Area of the flat pattern", output=True),
        Property("App::PropertyInteger", "PieceCount", "Pattern",
                 "Number of cone, cylinder and plane pieces", output=True),
        Property("App::PropertyInteger", "BendLineCount", "Pattern",
                 "Number of bend lines", output=True),
        Property("App::PropertyFloat", "FitError", "Pattern",
                 "Developable faces: largest distance of the cone spline from the face "
                 "(mm; for a transition its deviation from the designed developable)",
                 output=True),
    )

    def compute(self, obj):
        outline, bends, pieces, error = pattern(obj)
        face = Part.Face(Part.Wire(Part.__sortEdges__(outline)))
        if not face.isValid():
            raise ValueError("Source: the flat outline does not bound a valid face")
        shape = Part.Compound([face] + bends)
        shape.Placement = obj.Placement  # the pattern may be moved; its DXF is not
        obj.Shape = shape
        self.set_outputs(obj, FlatArea=face.Area, PieceCount=pieces,
                         BendLineCount=len(bends), FitError=error)


def pattern(obj):
    """(outline edges, bend line edges, piece count, fit error) of an RmfUnfold's source."""
    if not obj.Source:
        raise ValueError("Source: not set")
    source, subs = obj.Source
    subs = [s for s in subs if s]
    if is_feature(source, "RmfTransition") and not subs:
        from .transition import _library
        part = source.Proxy.sheet_part(source)
        face, bends = _library().flat_pattern(part)
        return face.Edges, bends.Edges, part.piece_count, part.report().deviation
    faces = [f for s in inputs.shapes(obj.Source, "Source") for f in s.Faces]
    if len(faces) != 1:
        raise ValueError("Source: expected an RmfTransition or one developable face, got %s "
                         "with %d faces" % (source.Label, len(faces)))
    return face_pattern(faces[0], obj.Tolerance)


def face_pattern(face, tolerance):
    """The flat pattern of a developable face through its cone spline (module notes)."""
    import rmfsurf.freecad as rf
    spline, t_min, t_max, error = rf.cone_spline_from_face(face, tolerance)
    developed = spline.develop()
    outline = rf.flat_pattern_edges(developed, t_min, t_max)
    low, high = developed.boundary(t_min), developed.boundary(t_max)
    first, last = low.domain
    # Piece k of the strip spans boundary parameters [k, k + 1]: the bend lines are the
    # rulings at the inner integers.
    bends = [Part.LineSegment(rf.vector(low.eval(k)), rf.vector(high.eval(k))).toShape()
             for k in range(int(round(first)) + 1, int(round(last)))]
    return outline, bends, spline.piece_count, error


def make_unfold(doc, feature):
    """See :func:`rmfsurf_workbench.make_unfold`."""
    source = inputs.link_sub(feature, "feature")
    obj = doc.addObject("Part::FeaturePython", "RmfUnfold")
    UnfoldFeature(obj)
    obj.Source = source
    attach_view(obj, "RmfUnfold")
    doc.recompute()
    return obj


def export_dxf(unfold, path):
    """Writes `unfold`'s flat pattern, in its own plane (without the feature's Placement), to
    the DXF file `path`: the outline on layer CUT, the bend lines on layer BEND, LINE and
    ARC entities only. An RmfTransition's pattern is the library's own DXF of the part (the
    command-line tool's, from the arcs' exact centres and radii); a face's is written by
    :mod:`rmfsurf_workbench.dxf` from the feature's edges. Returns the numbers of outline
    and bend entities."""
    from .dxf import write_flat_pattern
    if not is_feature(unfold, "RmfUnfold"):
        raise TypeError("unfold: expected an RmfUnfold, got %s" % getattr(unfold, "Label", unfold))
    if not unfold.isValid() or unfold.Shape.isNull() or not unfold.Shape.Faces:
        raise ValueError("unfold: %s has no flat pattern (recompute it)" % unfold.Label)
    shape = unfold.Shape.copy()
    shape.Placement = FreeCAD.Placement()
    parts = shape.childShapes()
    outline = [e for w in parts[0].Wires for e in w.Edges]
    bends = [s for s in parts[1:] if s.ShapeType == "Edge"]
    source, subs = unfold.Source
    if is_feature(source, "RmfTransition") and not [s for s in subs if s]:
        with open(os.fspath(path), "w") as f:
            f.write(source.Proxy.sheet_part(source).export("dxf"))
    else:
        write_flat_pattern(os.fspath(path), outline, bends)
    return len(outline), len(bends)
