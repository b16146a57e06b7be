"""RmfUnfold: the exact flat pattern of a sheet-metal part — a planar face bounded by lines
and circular arcs, and the bend lines (the rulings where cone pieces meet) — and its DXF
export for the cutter.

Sources:

* an RmfTransition: the development of its neutral layer (the layer at KFactor · Thickness
  from the inner side), from the library's flat pattern;
* a developable face (an object with one face, or a face of an object), unrolled by the
  library (:func:`rmfsurf.freecad.unfold`, rmf_unfold_face) with its own boundary and its
  holes: planes, circular cylinders and right cones exactly in closed form (told from the
  geometry, B-spline forms included), every other developable of degree 1 along its
  rulings (general cylinders and cones, tangent developables) through its cone spline
  within Tolerance (Leopoldseder & Pottmann), developed exactly, with bend lines where the
  cone pieces meet. SurfaceKind and Curvature say what the face is; a doubly curved face
  is refused with the stretch an unrolling would need;
* a sheet-metal body (an object whose shape is one solid of constant thickness: planes and
  bends of any developable kind), unfolded whole by the library
  (:func:`rmfsurf.freecad.unfold`, rmf_unfold_body): its thickness found, one side
  developed on the neutral layer at KFactor · Thickness from each bend's inner face, its
  faces joined along their bends, holes and cutouts kept, the bend lines up and down.

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
                 "An RmfTransition, a sheet-metal body (an object whose shape is a solid of "
                 "constant thickness), or a developable face (an object with one face, or a "
                 "face of an object)"),
        Property("App::PropertyFloat", "KFactor", "Unfold",
                 "Sheet bodies: the neutral layer lies at KFactor × thickness from the inner "
                 "face of each bend (0 … 1)", default=0.5),
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
                 "(mm; 0 for planes, circular cylinders and right cones, unrolled exactly; "
                 "for a transition its deviation from the designed developable)",
                 output=True),
        Property("App::PropertyString", "SurfaceKind", "Pattern",
                 "What the source is: plane, circular_cylinder, right_cone, "
                 "general_cylinder, general_cone, tangent_developable, ruled_developable "
                 "(a face), or transition", output=True),
        Property("App::PropertyLength", "Thickness", "Pattern",
                 "Sheet bodies: the thickness measured between the skins", output=True),
        Property("App::PropertyFloat", "Curvature", "Pattern",
                 "Developable faces: the largest |K|·size² sampled over the face (K the "
                 "Gaussian curvature, size its diagonal): round-off for a developable",
                 output=True),
    )

    def compute(self, obj):
        made = pattern(obj)
        face = made.face
        if not face.isValid():
            raise ValueError("Source: the flat outline does not bound a valid face")
        shape = Part.Compound([face] + made.bends)
        shape.Placement = obj.Placement  # the pattern may be moved; its DXF is not
        obj.Shape = shape
        self.set_outputs(obj, FlatArea=made.area, PieceCount=made.pieces,
                         BendLineCount=len(made.bends), FitError=made.error,
                         SurfaceKind=made.kind, Curvature=made.curvature,
                         Thickness=made.thickness)


class Pattern:
    """What an RmfUnfold shows: the flat face (holes as inner wires), the bend lines, the
    flat area, the piece count, the fit error, the source's kind and curvature, and the DXF
    text for the cutter."""

    def __init__(self, face, bends, area, pieces, error, kind, curvature, dxf, thickness=0.0):
        self.face, self.bends, self.area, self.pieces = face, bends, area, pieces
        self.error, self.kind, self.curvature, self.dxf = error, kind, curvature, dxf
        self.thickness = thickness


def _transition_source(obj):
    """The RmfTransition an RmfUnfold unrolls, or None for a face source."""
    if not obj.Source:
        raise ValueError("Source: not set")
    source, subs = obj.Source
    subs = [s for s in subs if s]
    return source if is_feature(source, "RmfTransition") and not subs else None


def pattern(obj):
    """The :class:`Pattern` of an RmfUnfold's source."""
    transition = _transition_source(obj)
    if transition is not None:
        from .transition import _library
        part = transition.Proxy.sheet_part(transition)
        face, bends = _library().flat_pattern(part)
        return Pattern(face, bends.Edges, face.Area, part.piece_count,
                       part.report().deviation, "transition", 0.0,
                       lambda: part.export("dxf"))
    source = obj.Source[0]
    shapes = inputs.shapes(obj.Source, "Source")
    if len(shapes) == 1 and shapes[0].Solids:
        return body_pattern(shapes[0], obj.KFactor, obj.Tolerance)
    faces = [f for s in shapes for f in s.Faces]
    if len(faces) != 1:
        raise ValueError("Source: expected an RmfTransition, a sheet body or one developable "
                         "face, got %s with %d faces" % (source.Label, len(faces)))
    return face_pattern(faces[0], obj.Tolerance)


def body_pattern(shape, k_factor, tolerance):
    """The :class:`Pattern` of a sheet-metal body (:func:`rmfsurf.freecad.unfold` of its
    solid): one side on the neutral layer at `k_factor`, its faces joined along their bends,
    the bend lines up and down."""
    import rmfsurf.freecad as rf
    flat = rf.unfold(shape, k_factor=k_factor, tolerance=tolerance)
    return Pattern(flat.face, flat.bend_lines, flat.area, len(flat.bends) + 1, 0.0,
                   "sheet_body", 0.0, flat.unfolded.dxf, flat.thickness)


def face_pattern(face, tolerance):
    """The :class:`Pattern` of a developable face, unrolled by the library with its holes
    (:func:`rmfsurf.freecad.unfold`): one piece and no bend line for planes, circular
    cylinders and right cones, a cone spline's pieces and their bend lines for the rest."""
    import rmfsurf.freecad as rf
    flat = rf.unfold(face, tolerance=tolerance)
    r = flat.report
    return Pattern(flat.face, flat.bend_lines, flat.area, len(flat.bend_lines) + 1,
                   r.fit_error, r.kind, r.curvature, flat.unfolded.dxf)


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
    the DXF file `path`: the outline and the holes on layer CUT, the bend lines on layer
    BEND (a sheet body's on BEND_UP and BEND_DOWN), LINE and ARC entities only, the
    library's own DXF (from the arcs' exact centres and radii): an RmfTransition's of the
    part (the command-line tool's), a face's of its unrolled face (rmf_unfolded_face_dxf),
    a body's of its pattern (rmf_unfolded_body_dxf). Returns the numbers of outline (and
    hole) and bend entities."""
    if not is_feature(unfold, "RmfUnfold"):
        raise TypeError("unfold: expected an RmfUnfold, got %s" % getattr(unfold, "Label", unfold))
    if not unfold.isValid() or unfold.Shape.isNull() or not unfold.Shape.Faces:
        raise ValueError("unfold: %s has no flat pattern (recompute it)" % unfold.Label)
    shape = unfold.Shape.copy()
    shape.Placement = FreeCAD.Placement()
    parts = shape.childShapes()
    outline = [e for w in parts[0].Wires for e in w.Edges]
    bends = [s for s in parts[1:] if s.ShapeType == "Edge"]
    with open(os.fspath(path), "w") as f:
        f.write(pattern(unfold).dxf())
    return len(outline), len(bends)
