"""RmfTransition: the sheet-metal transition piece between two closed convex planar curves
(square-to-round, rectangle-to-round, round-to-round with offset or inclined planes, ...),
formed with a sheet thickness into a solid.

The surface is the convex-hull developable of the two curves — planar triangles and quads
from straight edges and corners, right circular cones between a corner and an arc, general
strips fitted by cone pairs (Leopoldseder & Pottmann, eqs. (5)–(12)) — trimmed exactly by
the curves' planes, with exact offsets for the inner and outer layers (the library's
``rmf_sheet_part_transition`` through :func:`rmfsurf.freecad.transition`). The neutral
layer lies at KFactor · Thickness from the inner side; RmfUnfold develops it.
"""

from . import inputs
from .feature import Feature, Property
from .view import attach_view, hide


def _library():
    """rmfsurf.freecad, refusing when the loaded library has no sheet-metal transitions."""
    import rmfsurf
    import rmfsurf.freecad as rf
    if not rf.has_transitions():
        raise NotImplementedError("this rmfsurf (%s) has no sheet-metal transitions "
                                  "(rmf_sheet_part_transition)" % rmfsurf.__version__)
    return rf


class TransitionFeature(Feature):
    TYPE = "RmfTransition"
    PROPERTIES = (
        Property("App::PropertyLinkSub", "Bottom", "Transition",
                 "The first closed convex planar curve: a closed edge, edges closing a loop, "
                 "or a sketch of one loop"),
        Property("App::PropertyLinkSub", "Top", "Transition",
                 "The second closed convex planar curve"),
        Property("App::PropertyLength", "Thickness", "Transition", "Sheet thickness",
                 default=1.0),
        Property("App::PropertyFloat", "KFactor", "Transition",
                 "Neutral layer at KFactor × Thickness from the inner side, 0 ≤ k ≤ 1 "
                 "(0.5: the middle; about 0.33–0.45 for tight bends in steel)", default=0.5),
        Property("App::PropertyFloat", "Tolerance", "Transition",
                 "Largest distance of the part's surface and edges from the designed "
                 "developable and the input curves (mm)", default=1e-4),
        Property("App::PropertyFloat", "Deviation", "Accuracy",
                 "Largest distance of the cone spline from the designed developable (mm)",
                 output=True),
        Property("App::PropertyFloat", "EdgeDistance", "Accuracy",
                 "Largest distance of the part's bottom and top edges from the input curves "
                 "(mm)", output=True),
        Property("App::PropertyFloat", "BendRadius", "Accuracy",
                 "Smallest bend radius of the designed surface (mm; 0 at a crease)",
                 output=True),
        Property("App::PropertyInteger", "PieceCount", "Accuracy",
                 "Number of cone, cylinder and plane pieces", output=True),
        Property("App::PropertyInteger", "FaceCount", "Accuracy",
                 "Number of faces of the solid", output=True),
    )

    def __init__(self, obj):
        super().__init__(obj)
        self._part = None

    def __setstate__(self, state):
        super().__setstate__(state)
        self._part = None

    def compute(self, obj):
        self._part = None
        part = self.build(obj)
        solid = _library().part_solid(part)
        report = part.report()
        obj.Shape = solid
        self._part = part
        self.set_outputs(obj, Deviation=report.deviation,
                         EdgeDistance=max(report.edge_distance),
                         BendRadius=report.bend_radius, PieceCount=report.pieces,
                         FaceCount=len(solid.Faces))

    @staticmethod
    def build(obj):
        """The library's sheet-metal part from the feature's inputs."""
        rf = _library()
        return rf.transition(inputs.closed_wire(obj.Bottom, "Bottom"),
                             inputs.closed_wire(obj.Top, "Top"),
                             thickness=obj.Thickness.Value, k_factor=obj.KFactor,
                             tolerance=obj.Tolerance)

    def sheet_part(self, obj):
        """The library part of the last successful recompute, or built anew (after a
        document is opened the proxy holds none)."""
        if getattr(self, "_part", None) is None:
            self._part = self.build(obj)
        return self._part


def make_transition(doc, bottom, top, thickness, k_factor=0.5, tolerance=1e-4):
    """See :func:`rmfsurf_workbench.make_transition`."""
    if not thickness > 0:
        raise ValueError("thickness: expected a thickness > 0, got %r" % thickness)
    if not 0 <= k_factor <= 1:
        raise ValueError("k_factor: expected 0 <= k_factor <= 1, got %r" % k_factor)
    bottom_link = inputs.link_sub(bottom, "bottom")
    top_link = inputs.link_sub(top, "top")
    obj = doc.addObject("Part::FeaturePython", "RmfTransition")
    TransitionFeature(obj)
    obj.Bottom = bottom_link
    obj.Top = top_link
    obj.Thickness = float(thickness)
    obj.KFactor = float(k_factor)
    obj.Tolerance = float(tolerance)
    attach_view(obj, "RmfTransition", claims=("Bottom", "Top"))
    hide(inputs.linked_objects(obj.Bottom) + inputs.linked_objects(obj.Top))
    doc.recompute()
    return obj
