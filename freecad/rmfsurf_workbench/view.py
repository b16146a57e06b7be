"""The view providers of the features (GUI only): their icons, and the input sketches shown
as the feature's children in the tree, as Part's own Sweep and Loft do."""

import FreeCAD

from . import icon


class ViewProvider:
    """Proxy of a feature's view provider (Part's shaded display, our icon). Persists as the
    icon name and the link properties whose objects it claims."""

    def __init__(self, vobj, icon_name, claims=()):
        self.icon_name = icon_name
        self.claims = list(claims)
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon(self.icon_name)

    def claimChildren(self):
        from .inputs import linked_objects
        obj = getattr(self, "Object", None)
        if obj is None:
            return []
        children = []
        for name in self.claims:
            for child in linked_objects(getattr(obj, name, None)):
                if child not in children and child.TypeId.startswith("Sketcher::"):
                    children.append(child)
        return children

    def onDelete(self, vobj, subelements):
        for child in self.claimChildren():
            if child.ViewObject is not None:
                child.ViewObject.Visibility = True
        return True

    def updateData(self, obj, prop):
        pass

    def onChanged(self, vobj, prop):
        pass

    def __getstate__(self):
        return {"Icon": self.icon_name, "Claims": self.claims}

    def __setstate__(self, state):
        state = state or {}
        self.icon_name = state.get("Icon", "RmfSurfWorkbench")
        self.claims = list(state.get("Claims", []))

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        self.__setstate__(state)


def attach_view(obj, icon_name, claims=()):
    """Gives a new feature its view provider when the GUI runs."""
    if FreeCAD.GuiUp and obj.ViewObject is not None:
        ViewProvider(obj.ViewObject, icon_name, claims)


def hide(objects):
    """Hides the inputs a new feature consumes (the profile and spine sketches)."""
    if not FreeCAD.GuiUp:
        return
    for obj in objects:
        if obj.ViewObject is not None:
            obj.ViewObject.Visibility = False
