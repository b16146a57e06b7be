"""The RmfSurf workbench for FreeCAD: parametric features over the rmfsurf library.

* :func:`make_sweep` — **RmfSweep**: a planar profile (a sketch, inner loops are holes) swept
  along a wire of lines, arcs and curves with rotation-minimizing frames: exact cylinders and
  tori on lines and arcs, the PH cubic spline's rational RMF on curves (Mäurer & Jüttler),
  round or mitred corners; a solid with planar caps, or the lateral sheet.
* :func:`make_transition` — **RmfTransition**: the sheet-metal transition piece between two
  closed convex planar curves (the convex-hull developable of Leopoldseder & Pottmann's cone
  splines), formed with a thickness into a solid.
* :func:`make_unfold` — **RmfUnfold**: the exact flat pattern of an RmfTransition's neutral
  layer (K-factor) or of a developable face, with its bend lines; :func:`export_dxf` writes it
  for the cutter.

Each returns the new document object: an ``App::FeaturePython`` (``Part::FeaturePython``)
that keeps links to its inputs and recomputes when they change. Inputs are document objects
or ``(object, sub-element names)`` pairs, as a selection gives them.

The proxy classes live in :mod:`rmfsurf_workbench.sweep`, ``.transition`` and ``.unfold``;
documents store those module paths, so they stay where they are.
"""

import os
import xml.etree.ElementTree as _ElementTree

#: The addon's folder (the one with package.xml).
ADDON_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ICON_DIR = os.path.join(ADDON_DIR, "Resources", "icons")


def _package_version():
    """The version in the addon's package.xml: the library's, which the addon carries."""
    root = _ElementTree.parse(os.path.join(ADDON_DIR, "package.xml")).getroot()
    namespace = root.tag[:root.tag.index("}") + 1] if root.tag.startswith("{") else ""
    return root.find(namespace + "version").text.strip()


__version__ = _package_version()


def icon(name):
    """The path of the SVG icon `name` (without ".svg")."""
    return os.path.join(ICON_DIR, name + ".svg")


def make_sweep(doc, spine, profile, solid=True, corner="round", corner_radius=None,
               tolerance=1e-4):
    """Adds an RmfSweep to `doc`: `profile` swept along `spine`; returns it (recomputed).

    Args:
        doc: the document.
        spine: the wire: an object (its edges, e.g. a sketch or a Part wire), an (object,
            edge names) pair, or a list of those: lines, arcs and curves, end to end.
        profile: a sketch (inner loops are holes), an object with one planar face or closed
            wire, or an (object, ["Face1"]) pair, in the plane normal to the spine at its
            start, where it is in space; its x axis is the frame's initial normal.
        solid: a solid closed by planar caps (else the lateral faces).
        corner: "round" or "miter", how sharp joints of the spine are resolved.
        corner_radius: the rounding radius of round corners (None: 1.5 times the profile's
            largest distance from the spine).
        tolerance: how far the PH cubic spline may be from curve edges of the spine.
    """
    from . import sweep
    return sweep.make_sweep(doc, spine, profile, solid=solid, corner=corner,
                            corner_radius=corner_radius, tolerance=tolerance)


def make_transition(doc, bottom, top, thickness, k_factor=0.5, tolerance=1e-4):
    """Adds an RmfTransition to `doc`: the formed sheet-metal part between the closed convex
    planar curves `bottom` and `top` (objects or (object, edge names) pairs), of sheet
    `thickness`, with the neutral layer at `k_factor` · thickness from the inner side;
    returns it (recomputed)."""
    from . import transition
    return transition.make_transition(doc, bottom, top, thickness, k_factor=k_factor,
                                      tolerance=tolerance)


def make_unfold(doc, feature):
    """Adds an RmfUnfold to `doc`: the flat pattern of `feature` — an RmfTransition (its
    neutral layer) or a developable face, as an (object, ["FaceN"]) pair or an object with
    one face; returns it (recomputed)."""
    from . import unfold
    return unfold.make_unfold(doc, feature)


def export_dxf(unfold_feature, path):
    """Writes an RmfUnfold's flat pattern to the DXF file `path` (R12, LINE and ARC
    entities to full precision): the outline on layer CUT, the bend lines on layer BEND;
    returns the numbers of outline and bend entities."""
    from . import unfold
    return unfold.export_dxf(unfold_feature, path)
