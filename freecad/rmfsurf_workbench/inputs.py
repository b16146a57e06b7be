"""The features' inputs: what a user selects (objects, or objects with sub-element names)
as link property values, and link values as Part shapes in global coordinates.

A link is kept as FreeCAD keeps it — (object, sub-element names), "" for the whole object —
so FreeCAD's dependency graph recomputes a feature when a linked sketch or edge changes.
"""

import FreeCAD
import Part


def _pairs(value, name):
    """(object, [sub-element names]) pairs from an object, a selection item (``.Object``,
    ``.SubElementNames``), an (object, name or names) pair, or a list of those; [] for the
    whole object."""
    if value is None:
        raise ValueError("%s: nothing given" % name)
    if isinstance(value, FreeCAD.DocumentObject):
        return [(value, [])]
    if hasattr(value, "Object") and hasattr(value, "SubElementNames"):
        return [(value.Object, [s for s in value.SubElementNames if s])]
    if (isinstance(value, tuple) and len(value) == 2
            and isinstance(value[0], FreeCAD.DocumentObject)):
        obj, subs = value
        subs = [subs] if isinstance(subs, str) else list(subs or [])
        return [(obj, [s for s in subs if s])]
    if isinstance(value, (list, tuple)):
        pairs = []
        for k, item in enumerate(value):
            pairs += _pairs(item, "%s[%d]" % (name, k))
        if not pairs:
            raise ValueError("%s: nothing given" % name)
        return pairs
    raise TypeError("%s: expected a document object or an (object, sub-element names) pair, "
                    "got %s" % (name, type(value).__name__))


def link_sub_list(value, name):
    """A value for an App::PropertyLinkSubList: [(object, name), ...], (object, "") for a
    whole object."""
    result = []
    for obj, subs in _pairs(value, name):
        result += [(obj, s) for s in subs] or [(obj, "")]
    return result


def link_sub(value, name):
    """A value for an App::PropertyLinkSub: one object with its sub-element names."""
    pairs = _pairs(value, name)
    objects = {obj.Name for obj, _ in pairs}
    if len(objects) != 1:
        raise ValueError("%s: expected one object, got %d (%s)"
                         % (name, len(objects), ", ".join(sorted(objects))))
    return (pairs[0][0], [s for _, subs in pairs for s in subs])


def linked_objects(value):
    """The objects a link property value points to."""
    if not value:
        return []
    if isinstance(value, tuple) and isinstance(value[0], FreeCAD.DocumentObject):
        return [value[0]]
    return [obj for obj, _ in value]


def shapes(value, name):
    """The Part shapes of a link property value, in global coordinates: the named
    sub-elements, or an object's whole shape."""
    if not value:
        raise ValueError("%s: not set" % name)
    pairs = [value] if isinstance(value[0], FreeCAD.DocumentObject) else list(value)
    result = []
    for obj, subs in pairs:
        subs = [subs] if isinstance(subs, str) else [s for s in subs if s]
        if not subs:
            result.append(_shape(obj, "", name))
        result += [_shape(obj, s, name) for s in subs]
    return result


def _shape(obj, sub, name):
    shape = Part.getShape(obj, sub, needSubElement=bool(sub))
    if shape.isNull():
        what = "%s of %s" % (sub, obj.Label) if sub else obj.Label
        raise ValueError("%s: %s has no shape (is it computed?)" % (name, what))
    return shape


def wire(value, name):
    """The edges of a link property value joined end to end into one Part.Wire."""
    edges = [e for s in shapes(value, name) for e in s.Edges]
    if not edges:
        raise ValueError("%s: the linked objects have no edges" % name)
    groups = Part.sortEdges(edges)
    if len(groups) != 1:
        raise ValueError("%s: its %d edges form %d separate pieces; they must join end to end"
                         % (name, len(edges), len(groups)))
    return Part.Wire(groups[0])


def closed_wire(value, name):
    """A link property value as one closed Part.Wire (a closed edge, edges closing a loop,
    or a sketch of one loop)."""
    result = wire(value, name)
    if not result.isClosed():
        raise ValueError("%s: the wire is not closed" % name)
    return result


def profile(value, name):
    """What :func:`rmfsurf.freecad.sweep_with_report` takes as the profile: a whole linked
    object (a sketch: its x axis is the frame's initial normal), or the linked faces or
    edges as one Part shape."""
    if not value:
        raise ValueError("%s: not set" % name)
    obj, subs = value
    subs = [s for s in subs if s]
    if not subs:
        _shape(obj, "", name)
        return obj
    parts = [_shape(obj, s, name) for s in subs]
    faces = [f for p in parts for f in p.Faces]
    if faces:
        if len(faces) != 1 or len(parts) != 1:
            raise ValueError("%s: expected one face or closed edges, got %s"
                             % (name, ", ".join(subs)))
        return faces[0]
    edges = [e for p in parts for e in p.Edges]
    return Part.Compound([Part.Wire(group) for group in Part.sortEdges(edges)])
