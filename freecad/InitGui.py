# RmfSurf addon, GUI part: FreeCAD runs this file at start-up of the GUI. The workbench's
# commands are registered when it is first activated (Initialize). FreeCAD runs it with
# exec(), whose module-level names a class body cannot see: imports go inside the methods.
import FreeCADGui


class RmfSurfWorkbench(FreeCADGui.Workbench):
    """Parametric sweeps with rotation-minimizing frames, sheet-metal transition pieces and
    their exact flat patterns (rmfsurf)."""

    MenuText = "RmfSurf"
    ToolTip = ("Exact rational sweeps with rotation-minimizing frames, sheet-metal "
               "transition pieces and their flat patterns")

    def __init__(self):
        import rmfsurf_workbench
        self.__class__.Icon = rmfsurf_workbench.icon("RmfSurfWorkbench")

    def Initialize(self):
        from rmfsurf_workbench import commands
        commands.register()
        self.appendToolbar("RmfSurf", list(commands.NAMES))
        self.appendMenu("RmfSurf", list(commands.NAMES))

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(RmfSurfWorkbench())
