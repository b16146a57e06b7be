"""What the three features share: their properties, how a failure is reported, and how the
proxies persist.

A feature holds its inputs (links and numbers) and nothing else: its proxy carries only its
type name, so a saved document recomputes from the inputs after reopening. A failure of the
library, or an input it cannot use, leaves the feature Invalid (red in the tree, the message
as its status) with one line in the report view — not a Python traceback.
"""

import sys
import traceback

import FreeCAD

# Property status bits of DocumentObject.addProperty (App::PropertyType): read-only in the
# property editor, and an output that does not touch the feature when written.
_READ_ONLY = 1
_OUTPUT = 8

_UNSET = object()


class FeatureError(Exception):
    """A feature could not be computed; the message names the feature and the input.

    FreeCAD 0.20 formats an exception leaving ``execute`` with its traceback (for the report
    view) before it marks the feature Invalid. The traceback is formatted with
    ``sys.tracebacklimit``: this exception sets it to 0 while it is being raised and restores
    it when FreeCAD lets go of it, so the report view shows only the message.
    """

    def __init__(self, message):
        super().__init__(message)
        self._saved_limit = getattr(sys, "tracebacklimit", _UNSET)
        sys.tracebacklimit = 0

    def __del__(self):
        if self._saved_limit is _UNSET:
            if hasattr(sys, "tracebacklimit"):
                del sys.tracebacklimit
        else:
            sys.tracebacklimit = self._saved_limit


FeatureError.__module__ = "rmfsurf_workbench"

# What users cause (bad inputs, refusals of the library); anything else is a bug of the
# workbench, reported the same way but with the traceback in FreeCAD's log.
_INPUT_ERRORS = (ValueError, TypeError, ArithmeticError, NotImplementedError)


def _input_errors():
    errors = _INPUT_ERRORS + (ImportError,)  # ImportError: the library is not installed
    try:
        import Part
        import rmfsurf
    except ImportError:
        return errors
    return errors + (rmfsurf.RmfError, Part.OCCError)


class Property:
    """One property of a feature: type, name, group, tooltip, default; `output` ones are
    read-only results (accuracy figures, counts)."""

    def __init__(self, kind, name, group, doc, default=None, output=False, enum=None):
        self.kind, self.name, self.group, self.doc = kind, name, group, doc
        self.default, self.output, self.enum = default, output, enum

    def add(self, obj):
        if self.name in obj.PropertiesList:
            self.update_enumeration(obj)
            return
        obj.addProperty(self.kind, self.name, self.group, self.doc,
                        _READ_ONLY | _OUTPUT if self.output else 0)
        if self.enum is not None:
            setattr(obj, self.name, list(self.enum))
        if self.default is not None:
            setattr(obj, self.name, self.default)


    def update_enumeration(self, obj):
        """An enumeration saved by an older workbench gets the choices offered since; its
        value is kept where it is still offered, else the first choice (the default)."""
        if self.enum is None or obj.getEnumerationsOfProperty(self.name) == list(self.enum):
            return
        value = getattr(obj, self.name)
        setattr(obj, self.name, list(self.enum))
        setattr(obj, self.name, value if value in self.enum else self.enum[0])


class Feature:
    """Base of the feature proxies: adds the properties, computes the shape in
    :meth:`compute` (overridden), reports failures, persists as its type name."""

    TYPE = ""
    PROPERTIES = ()

    def __init__(self, obj):
        self.Type = self.TYPE
        obj.Proxy = self
        self.add_properties(obj)

    def add_properties(self, obj):
        for p in self.PROPERTIES:
            p.add(obj)

    def onDocumentRestored(self, obj):
        # Documents of an older workbench get the properties added since, with defaults.
        self.add_properties(obj)

    def execute(self, obj):
        label = obj.Label
        if not label.startswith(self.TYPE):
            label = "%s (%s)" % (label, self.TYPE)
        try:
            self.compute(obj)
        except _input_errors() as e:
            raise FeatureError("%s: %s" % (label, message_of(e))) from None
        except Exception as e:  # a bug: the message here, the traceback in the log
            FreeCAD.Console.PrintLog(traceback.format_exc())
            raise FeatureError("%s: internal error (%s: %s); please report it, the traceback "
                               "is in FreeCAD's log" % (label, type(e).__name__, e)) from None

    def compute(self, obj):
        raise NotImplementedError

    def set_outputs(self, obj, **values):
        for name, value in values.items():
            setattr(obj, name, value)

    # FreeCAD 0.20 stores a proxy with __getstate__/__setstate__, 0.21 and later with
    # dumps/loads: only the type name, the inputs are the feature's properties.
    def __getstate__(self):
        return {"Type": self.TYPE}

    def __setstate__(self, state):
        self.Type = (state or {}).get("Type", self.TYPE)

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        self.__setstate__(state)


def message_of(error):
    """An exception's message as a user reads it (the library's names the argument)."""
    text = str(error).strip()
    return text or type(error).__name__


def is_feature(obj, type_name):
    """Whether `obj` is a feature of this workbench of `type_name` ("RmfTransition", ...)."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == type_name
