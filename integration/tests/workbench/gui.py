"""The RmfSurf workbench in FreeCAD's GUI: a smoke test, run as `freecad gui.py` under Xvfb
by integration/tests/workbench.rs (the addon installed into a fresh user directory first).

The workbench is activated, and each of its commands runs on a selection made as a user
would (profile sketch, then the spine's edges; a cone's face; two closed curves; the
unfold) through FreeCADGui.runCommand; the DXF export's file dialog is answered by this
script. Checked: the workbench and its toolbar, each command's feature, a wrong selection
reported in the report view without a traceback, the shaded result in the 3D view (an
offscreen render on white: the share of non-white pixels), and a screenshot of the whole
window for the docs.

Environment: RMFSURF_WORK (scratch), RMFSURF_SCREENSHOT (the PNG to write), RMFSURF_RESULT
(the report lines; the last is GUI CHECKS OK when everything passed).
"""

import math
import os
import traceback

import FreeCAD
import FreeCADGui
import Part
import Sketcher
from PySide import QtCore, QtGui

V = FreeCAD.Vector
WORK = os.environ["RMFSURF_WORK"]
lines = []
failures = []


def say(text):
    lines.append(text)
    FreeCAD.Console.PrintMessage("| %s\n" % text)


def require(name, condition):
    say("  %-66s %s" % (name, "yes" if condition else "NO  FAILED"))
    if not condition:
        failures.append(name)


def finish():
    lines.append("GUI CHECKS FAILED: %s" % "; ".join(failures) if failures else "GUI CHECKS OK")
    with open(os.environ["RMFSURF_RESULT"], "w") as f:
        f.write("\n".join(lines) + "\n")
    for name in list(FreeCAD.listDocuments()):
        FreeCAD.closeDocument(name)
    QtGui.QApplication.instance().quit()


def select(*items):
    FreeCADGui.Selection.clearSelection()
    for obj, names in items:
        if names:
            for n in names:
                FreeCADGui.Selection.addSelection(obj, n)
        else:
            FreeCADGui.Selection.addSelection(obj)


def features(doc, kind):
    return [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "Type", "") == kind]


def circle_sketch(doc, name, placement, radii):
    sketch = doc.addObject("Sketcher::SketchObject", name)
    sketch.Placement = placement
    for r in radii:
        g = sketch.addGeometry(Part.Circle(V(0, 0, 0), V(0, 0, 1), r))
        sketch.addConstraint(Sketcher.Constraint("Coincident", g, 3, -1, 1))
        sketch.addConstraint(Sketcher.Constraint("Radius", g, r))
    return sketch


def report_text():
    view = FreeCADGui.getMainWindow().findChild(QtGui.QTextEdit, "Report view")
    return view.toPlainText() if view is not None else ""


def run():
    import rmfsurf.freecad as rf
    mw = FreeCADGui.getMainWindow()
    FreeCADGui.activateWorkbench("RmfSurfWorkbench")
    require("the RmfSurf workbench is active",
            FreeCADGui.activeWorkbench().name() == "RmfSurfWorkbench")
    bars = [b for b in mw.findChildren(QtGui.QToolBar) if b.windowTitle() == "RmfSurf"]
    actions = [a.text() for b in bars for a in b.actions() if a.text()]
    require("its toolbar: %s" % ", ".join(actions), len(bars) == 1 and len(actions) == 4)

    doc = FreeCAD.newDocument("RmfSurf")
    spine = doc.addObject("Part::Feature", "Spine")
    spine.Shape = Part.Wire([
        Part.LineSegment(V(0, 0, 0), V(40, 0, 0)).toShape(),
        Part.ArcOfCircle(Part.Circle(V(40, 20, 0), V(0, 0, 1), 20), -math.pi / 2, 0).toShape(),
        Part.LineSegment(V(60, 20, 0), V(60, 60, 0)).toShape()])
    normal_to_x = FreeCAD.Rotation(V(0, 1, 0), 90)
    ring = circle_sketch(doc, "Ring", FreeCAD.Placement(V(0, 0, 0), normal_to_x), (4.0, 2.0))
    cone = doc.addObject("Part::Cone", "Frustum")
    cone.Radius1, cone.Radius2, cone.Height, cone.Angle = 15, 8, 25, 270
    cone.Placement.Base = V(-40, 40, 0)
    doc.recompute()

    select((ring, []), (spine, ["Edge1", "Edge2", "Edge3"]))
    FreeCADGui.runCommand("RmfSurf_Sweep")
    sweeps = features(doc, "RmfSweep")
    import rmfsurf.shapes
    wire_sweeps = rmfsurf.shapes._has_wire_sweep()
    if wire_sweeps:
        require("RmfSurf_Sweep on (sketch, 3 edges): an RmfSweep, a valid solid",
                len(sweeps) == 1 and sweeps[0].isValid() and sweeps[0].Shape.ShapeType == "Solid")
    else:
        say("  RmfSurf_Sweep: NOT RUN: this librmfsurf has no rmf_wire_sweep (not added)")

    lateral = next("Face%d" % (i + 1) for i, f in enumerate(cone.Shape.Faces)
                   if isinstance(f.Surface, Part.Cone))
    select((cone, [lateral]))
    FreeCADGui.runCommand("RmfSurf_Unfold")
    unfolds = features(doc, "RmfUnfold")
    require("RmfSurf_Unfold on the cone's face: a valid RmfUnfold",
            len(unfolds) == 1 and unfolds[0].isValid())
    unfold = unfolds[0]
    unfold.Placement = FreeCAD.Placement(V(-10, 70, 0), FreeCAD.Rotation())
    doc.recompute()

    if rf.has_transitions():
        bottom = doc.addObject("Sketcher::SketchObject", "Square")
        bottom.Placement.Base = V(160, -30, 0)
        corners = [V(-30, -30, 0), V(30, -30, 0), V(30, 30, 0), V(-30, 30, 0)]
        for a, b in zip(corners, corners[1:] + corners[:1]):
            bottom.addGeometry(Part.LineSegment(a, b))
        top = circle_sketch(doc, "Round", FreeCAD.Placement(V(166, -30, 45), FreeCAD.Rotation()),
                            (18.0,))
        doc.recompute()
        select((bottom, []), (top, []))
        FreeCADGui.runCommand("RmfSurf_Transition")
        transitions = features(doc, "RmfTransition")
        require("RmfSurf_Transition on (square, circle): a valid RmfTransition",
                len(transitions) == 1 and transitions[0].isValid())
        # Edited in the property panel's place: a coarser tolerance, fewer pieces.
        pieces = transitions[0].PieceCount
        transitions[0].Tolerance = 0.01
        doc.recompute()
        require("Tolerance 1e-4 -> 1e-2, recomputed: %d -> %d pieces, valid"
                % (pieces, transitions[0].PieceCount),
                transitions[0].isValid() and transitions[0].PieceCount < pieces)
        select((transitions[0], []))
        FreeCADGui.runCommand("RmfSurf_Unfold")
        require("RmfSurf_Unfold on the transition: a second valid RmfUnfold",
                len(features(doc, "RmfUnfold")) == 2 and features(doc, "RmfUnfold")[1].isValid())
        features(doc, "RmfUnfold")[1].Placement.Base = V(150, 90, 0)
        doc.recompute()
    else:
        say("  RmfSurf_Transition: NOT RUN: this librmfsurf has no rmf_sheet_part_transition")

    path = os.path.join(WORK, "gui_export.dxf")
    QtGui.QFileDialog.getSaveFileName = staticmethod(lambda *a, **k: (path, "DXF (*.dxf)"))
    select((unfold, []))
    FreeCADGui.runCommand("RmfSurf_ExportDxf")
    text = open(path).read() if os.path.exists(path) else ""
    require("RmfSurf_ExportDxf: %s written, ARC entities on layer CUT" % os.path.basename(path),
            "\nARC\n8\nCUT\n" in text)

    # A wrong selection: the cone solid as the profile of a sweep.
    select((cone, []), (spine, []))
    FreeCADGui.runCommand("RmfSurf_Sweep")
    for _ in range(5):  # the report view shows messages from the event queue
        QtGui.QApplication.processEvents()
    report = report_text()
    require("a wrong selection: reported ('RmfSweep: not added: ...'), no feature added",
            "RmfSweep: not added: RmfSweep" in report and "profile: expected one face" in report
            and len(features(doc, "RmfSweep")) == len(sweeps))
    require("the report view shows no Python traceback", "Traceback" not in report)

    FreeCADGui.Selection.clearSelection()
    colours = {"RmfSweep": (0.23, 0.51, 0.84), "RmfTransition": (0.55, 0.64, 0.72),
               "RmfUnfold": (0.95, 0.80, 0.55)}
    for kind, colour in colours.items():
        for obj in features(doc, kind):
            obj.ViewObject.ShapeColor = colour
    for dock in mw.findChildren(QtGui.QDockWidget):
        if dock.objectName() in ("Report view", "Python console"):
            dock.hide()
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    render = os.path.join(WORK, "gui_render.png")
    view.saveImage(render, 400, 300, "White")
    image = QtGui.QImage(render)
    white = QtGui.QColor("white").rgb()
    shaded = sum(image.pixel(x, y) != white for x in range(0, image.width(), 2)
                 for y in range(0, image.height(), 2)) / (image.width() * image.height() / 4)
    require("the 3D view shows the results, shaded: %.0f %% of a white render covered"
            % (100 * shaded), shaded > 0.02)
    # The sweep selected, for the picture: the property panel shows its inputs and accuracy
    # figures, and it keeps its colour (the selection colour set to it).
    r, g, b = colours["RmfSweep"]
    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/View").SetUnsigned(
        "SelectionColor", (int(r * 255) << 24) | (int(g * 255) << 16) | (int(b * 255) << 8))
    FreeCADGui.Selection.addSelection((features(doc, "RmfSweep") or [unfold])[0])
    QtCore.QTimer.singleShot(1500, screenshot)


def screenshot():
    try:
        image = QtGui.QApplication.instance().primaryScreen().grabWindow(0)
        path = os.environ["RMFSURF_SCREENSHOT"]
        require("screenshot %s (%dx%d)" % (path, image.width(), image.height()),
                image.save(path) and image.width() >= 800)
    except Exception:
        failures.append("screenshot")
        say(traceback.format_exc())
    finish()


def start():
    try:
        run()
    except Exception:
        failures.append("exception")
        say(traceback.format_exc())
        finish()


QtCore.QTimer.singleShot(500, start)
