"""The workbench's commands (GUI only): each takes the selection, adds its feature in one
undoable transaction and recomputes. A selection that does not fit, or a feature that
fails, is reported in the report view; nothing raises into the GUI.

* RmfSurf_Sweep: select the profile (a sketch, a planar face or closed edges) first, then
  the spine's edges or objects (Ctrl+click).
* RmfSurf_Transition: select the bottom curve, then the top curve (closed edges or sketches).
* RmfSurf_Unfold: select an RmfTransition or a developable face.
* RmfSurf_ExportDxf: select an RmfUnfold; asks for the file.

A feature that fails on the selection is not added (the transaction is undone).
"""

import traceback

import FreeCAD
import FreeCADGui

from . import icon
from .feature import is_feature, message_of

NAMES = ("RmfSurf_Sweep", "RmfSurf_Transition", "RmfSurf_Unfold", "RmfSurf_ExportDxf")


def _report(title, error):
    if not isinstance(error, (ValueError, TypeError, NotImplementedError, ImportError)):
        FreeCAD.Console.PrintLog(traceback.format_exc())
    FreeCAD.Console.PrintError("%s: %s\n" % (title, message_of(error)))


def _selection():
    return FreeCADGui.Selection.getSelectionEx()


class _Command:
    """A command: its resources, when it is active, and what it does (``run``)."""

    ICON = ""
    MENU = ""
    TIP = ""

    def GetResources(self):
        return {"Pixmap": icon(self.ICON), "MenuText": self.MENU, "ToolTip": self.TIP}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and self.fits(_selection())

    def fits(self, selection):
        return bool(selection)

    def Activated(self):
        doc = FreeCAD.ActiveDocument
        doc.openTransaction(self.MENU)
        try:
            result = self.run(doc, _selection())
        except Exception as e:  # the report view, not a traceback in the GUI
            doc.abortTransaction()
            _report(self.MENU, e)
            return
        if result is not None and not result.isValid():
            # The feature failed on this selection: not added (its message is reported).
            message = result.getStatusString()
            doc.abortTransaction()
            FreeCAD.Console.PrintError("%s: not added: %s\n" % (self.MENU, message))
            return
        doc.commitTransaction()
        if result is not None:
            FreeCADGui.Selection.clearSelection()
            FreeCADGui.Selection.addSelection(result)


class Sweep(_Command):
    ICON, MENU = "RmfSweep", "RmfSweep"
    TIP = ("Sweeps a profile along a wire with rotation-minimizing frames: exact rational "
           "faces, round or mitred corners, a solid. Select the profile sketch first, then "
           "the spine's edges.")

    def fits(self, selection):
        return len(selection) >= 2 or (len(selection) == 1
                                       and len(selection[0].SubElementNames) >= 2)

    def run(self, doc, selection):
        from . import make_sweep
        profile, spine = _first_and_rest(selection)
        return make_sweep(doc, spine, profile)


class Transition(_Command):
    ICON, MENU = "RmfTransition", "RmfTransition"
    TIP = ("The sheet-metal transition piece between two closed convex curves (square to "
           "round, ...), with thickness. Select the bottom curve, then the top curve.")

    def fits(self, selection):
        return len(selection) == 2 or (len(selection) == 1
                                       and len(selection[0].SubElementNames) == 2)

    def run(self, doc, selection):
        from . import make_transition
        bottom, top = _first_and_rest(selection)
        return make_transition(doc, bottom, top, thickness=1.0)


class Unfold(_Command):
    ICON, MENU = "RmfUnfold", "RmfUnfold"
    TIP = ("The exact flat pattern, with bend lines, of an RmfTransition (its neutral "
           "layer) or of a developable face.")

    def fits(self, selection):
        return len(selection) == 1

    def run(self, doc, selection):
        from . import make_unfold
        item = selection[0]
        names = [n for n in item.SubElementNames if n]
        return make_unfold(doc, (item.Object, names) if names else item.Object)


class ExportDxf(_Command):
    ICON, MENU = "RmfExportDxf", "Export flat pattern to DXF"
    TIP = "Writes the selected RmfUnfold's flat pattern as DXF: outline and bend lines on " \
          "their own layers, lines and true arcs only."

    def fits(self, selection):
        return len(selection) == 1 and is_feature(selection[0].Object, "RmfUnfold")

    def run(self, doc, selection):
        from PySide import QtGui
        from . import export_dxf
        unfold = selection[0].Object
        path, _ = QtGui.QFileDialog.getSaveFileName(
            FreeCADGui.getMainWindow(), "Export flat pattern", unfold.Label + ".dxf",
            "DXF (*.dxf)")
        if path:
            outline, bends = export_dxf(unfold, path)
            FreeCAD.Console.PrintMessage("RmfSurf: %s written: %d outline and %d bend "
                                         "entities\n" % (path, outline, bends))
        return None


def _first_and_rest(selection):
    """(first selected item, the rest) as (object, sub-element names) pairs: a selection of
    several sub-elements of one object splits after the first of them."""
    pairs = [(s.Object, [n for n in s.SubElementNames if n]) for s in selection]
    if len(pairs) == 1:
        obj, names = pairs[0]
        return (obj, names[:1]), (obj, names[1:])
    first, rest = pairs[0], pairs[1:]
    return (first[0], first[1]) if first[1] else first[0], \
        [(obj, names) if names else obj for obj, names in rest]


def register():
    for name, command in zip(NAMES, (Sweep(), Transition(), Unfold(), ExportDxf())):
        FreeCADGui.addCommand(name, command)
