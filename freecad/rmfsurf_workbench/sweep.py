"""RmfSweep: a planar profile swept along a wire with rotation-minimizing frames (or the
Frenet frame, a frame following a fixed direction, or one following a Guide curve; the
profile scaled linearly from ScaleStart to ScaleEnd, through ScaleKnotFractions/
ScaleKnotScales if given, or blended into an EndProfile, through Sections at
SectionFractions if given), by the library's wire sweep (``rmf_wire_sweep``,
``rmf_wire_sweep_between`` with an EndProfile, ``rmf_wire_sweep_through`` with Sections,
through :func:`rmfsurf.freecad.sweep_with_report`).

Lines and circular arcs of the spine give exact cylinders and tori; curve edges are
swept along a spine within the tolerance by the Method: "ph-rmf" (default), a PH cubic
spline with its rational RMF in closed form (Mäurer & Jüttler, eqs. (36)–(41)); "mobius",
Möbius images of planar PH cubics (Bartoň, Jüttler & Wang), or "rrmf", RRMF quintics
(Farouki, Giannelli & Sestini), both with exact rational RMFs, so the parameter lines are
orthogonal to rounding (Orthogonality ~1e-14, ~1e-7 with ph-rmf). One RMF runs across every
joint; sharp joints get round (torus) or mitred corners. Mobius and rrmf take no scale law
(ScaleStart = ScaleEnd, and the same at every knot). A round profile (circles about the
spine) is swept with ph-rmf on the PH spline's Euler-Rodrigues frame by default (PipeFrame
lightest: the same surface in lighter faces), or on the RMF (PipeFrame rmf).

The accuracy figures are the library's report (``rmf_shape_report``), measured on the
result.
"""

import math

from . import inputs
from .feature import Feature, Property
from .view import attach_view, hide

METHODS = ("ph-rmf", "mobius", "rrmf")
CORNERS = ("round", "miter")
FRAMES = ("rmf", "frenet", "fixed", "guide")
PIPE_FRAMES = ("lightest", "rmf")


class SweepFeature(Feature):
    TYPE = "RmfSweep"
    PROPERTIES = (
        Property("App::PropertyLinkSubList", "Spine", "Sweep",
                 "The wire: edges, wires or sketches of lines, arcs and curves, end to end"),
        Property("App::PropertyLinkSub", "Profile", "Sweep",
                 "A sketch (inner loops are holes), a planar face or closed edges, in the "
                 "plane normal to the spine at its start; its x axis is the frame's initial "
                 "normal"),
        Property("App::PropertyLinkSub", "EndProfile", "Sweep",
                 "Optional: the section at the spine's end, of the kinds Profile takes (as "
                 "many holes), drawn at the spine's START in the plane normal to it there, "
                 "like Profile: the section blends linearly in arc length from Profile into "
                 "it, loop to loop, corner to corner (open spines, ScaleStart = ScaleEnd). "
                 "Empty: Profile all along"),
        Property("App::PropertyLinkList", "Sections", "Sweep",
                 "Optional, with EndProfile: the sections the sweep passes through between "
                 "Profile and EndProfile, of the kinds Profile takes (as many holes), each "
                 "drawn at the spine's START like EndProfile, at the fraction of the spine's "
                 "length of the same place in SectionFractions; the section blends linearly "
                 "in arc length from each into the next. Empty: none"),
        Property("App::PropertyFloatList", "SectionFractions", "Sweep",
                 "Where the Sections are: fractions of the spine's length, strictly "
                 "increasing in (0, 1), one per section (as many)"),
        Property("App::PropertyEnumeration", "Method", "Sweep",
                 "How curve edges are swept: ph-rmf, the PH cubic spline with its rational "
                 "RMF; mobius or rrmf, spines with exact rational RMFs (parameter lines "
                 "orthogonal to rounding; no scale law). Lines and arcs are exact whatever "
                 "the method", enum=METHODS),
        Property("App::PropertyEnumeration", "PipeFrame", "Sweep",
                 "How a round profile (circles about the spine: a pipe) is swept along curve "
                 "edges with ph-rmf: lightest, the PH spline's Euler-Rodrigues frame (the same "
                 "surface in faces of degree 5 along the spine instead of 9; Orthogonality "
                 "then measures how far its parameter lines are from the RMF's); rmf, the RMF "
                 "as every profile", enum=PIPE_FRAMES),
        Property("App::PropertyEnumeration", "Corner", "Sweep",
                 "Sharp joints of the spine: round (a torus elbow) or miter", enum=CORNERS),
        Property("App::PropertyLength", "CornerRadius", "Sweep",
                 "Radius of round corners; 0: 1.5 times the profile's largest distance from "
                 "the spine", default=0.0),
        Property("App::PropertyFloat", "Tolerance", "Sweep",
                 "Largest distance of the PH cubic spline from curve edges (mm)",
                 default=1e-4),
        Property("App::PropertyBool", "Solid", "Sweep",
                 "Close the sweep with planar caps into a solid (else the lateral faces)",
                 default=True),
        Property("App::PropertyAngle", "Twist", "Sweep",
                 "Extra turn of the frame about the tangent over the whole spine, linear in "
                 "arc length", default=0.0),
        Property("App::PropertyInteger", "ClosureSymmetry", "Sweep",
                 "Closed spines: the frame closes modulo 360°/k, k the profile's rotational "
                 "symmetry (e.g. 4 for a square); 0: closes exactly", default=0),
        Property("App::PropertyEnumeration", "Frame", "Sweep",
                 "How the profile turns about the tangent: rmf (rotation-minimizing), frenet "
                 "(with the spine's torsion: threads along helices), fixed (its x axis "
                 "follows FrameDirection) or guide (its x axis points at the Guide curve, a "
                 "second rail)", enum=FRAMES),
        Property("App::PropertyVector", "FrameDirection", "Sweep",
                 "Frame fixed: the direction the profile's x axis follows (projected onto "
                 "the normal plane; not zero, never along the spine)"),
        Property("App::PropertyLink", "Guide", "Sweep",
                 "Frame guide: an object whose shape is the guide curve (edges joined end "
                 "to end, beside the spine all along): the profile's x axis points where it "
                 "crosses the spine's normal plane, the crossing nearest the spine"),
        Property("App::PropertyFloat", "ScaleStart", "Sweep",
                 "The profile's scale at the spine's start (> 0), linear in arc length to "
                 "ScaleEnd", default=1.0),
        Property("App::PropertyFloat", "ScaleEnd", "Sweep",
                 "The profile's scale at the spine's end (> 0; equal to ScaleStart on a "
                 "closed spine)", default=1.0),
        Property("App::PropertyFloatList", "ScaleKnotFractions", "Sweep",
                 "Knots of the scale law: fractions of the spine's length, strictly "
                 "increasing in (0, 1), where the profile has the scale of the same place "
                 "in ScaleKnotScales; the scale runs from ScaleStart through them to "
                 "ScaleEnd, linear in arc length between (empty: none)"),
        Property("App::PropertyFloatList", "ScaleKnotScales", "Sweep",
                 "The profile's scale (> 0) at each of ScaleKnotFractions (as many)"),
        Property("App::PropertyFloat", "SpineDistance", "Accuracy",
                 "Largest distance of the PH cubic spline from the curve edges (mm; 0 on "
                 "lines and arcs)", output=True),
        Property("App::PropertyFloat", "RmfDefect", "Accuracy",
                 "Largest angle between the frames used and the exact RMF plus twist "
                 "(radians)", output=True),
        Property("App::PropertyFloat", "Orthogonality", "Accuracy",
                 "Largest |cos| of the angle between the lateral faces' parameter lines (0: "
                 "orthogonal, lines of curvature)", output=True),
        Property("App::PropertyFloat", "SingularityMargin", "Accuracy",
                 "Least 1 - κ·(profile distance) over the sweep (> 0: no self-intersection "
                 "at the spine's curvature, Mäurer & Jüttler Cor. 7)", output=True),
        Property("App::PropertyInteger", "FaceCount", "Accuracy",
                 "Number of faces of the result", output=True),
        Property("App::PropertyFloat", "FrameError", "Accuracy",
                 "Largest angle between the frames used and the frame asked for (radians; "
                 "0 for rmf)", output=True),
    )

    def compute(self, obj):
        from rmfsurf.freecad import sweep_with_report
        if obj.Method not in METHODS:
            raise ValueError("Method: %r is not offered by the wire sweep" % obj.Method)
        knots = scale_knots(obj)
        if obj.Method != "ph-rmf" and any(s != obj.ScaleStart for s in
                                          [obj.ScaleEnd] + [k[1] for k in knots]):
            raise ValueError("Method: %s takes a constant scale (ScaleStart %r, ScaleEnd %r, "
                             "ScaleKnotScales %r); a scale law needs ph-rmf"
                             % (obj.Method, obj.ScaleStart, obj.ScaleEnd,
                                [k[1] for k in knots]))
        if obj.ClosureSymmetry < 0:
            raise ValueError("ClosureSymmetry: must be 0 or a symmetry order k >= 1, got %d"
                             % obj.ClosureSymmetry)
        frame = obj.Frame
        if frame == "fixed":
            frame = ("fixed", tuple(obj.FrameDirection))
            if not any(frame[1]):
                raise ValueError("FrameDirection: Frame fixed needs a direction, not (0, 0, 0)")
        elif frame == "guide":
            if obj.Guide is None:
                raise ValueError("Guide: Frame guide needs a Guide, an object whose shape "
                                 "is the guide curve")
            frame = ("guide", inputs.wire((obj.Guide, []), "Guide"))
        for name in ("ScaleStart", "ScaleEnd"):
            value = getattr(obj, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError("%s: the profile's scale must be positive, got %r"
                                 % (name, value))
        radius = obj.CornerRadius.Value
        end_profile = (inputs.profile(obj.EndProfile, "EndProfile") if obj.EndProfile
                       else None)
        through = sections(obj)
        shape, report = sweep_with_report(
            inputs.wire(obj.Spine, "Spine"), inputs.profile(obj.Profile, "Profile"),
            solid=obj.Solid, corner=obj.Corner, corner_radius=radius if radius > 0 else None,
            tolerance=obj.Tolerance, twist=math.radians(obj.Twist.Value),
            closure_symmetry=obj.ClosureSymmetry, frame=frame,
            scale=(obj.ScaleStart, obj.ScaleEnd), scale_knots=knots, method=obj.Method,
            end_profile=end_profile, sections=through, pipe_frame=obj.PipeFrame)
        obj.Shape = shape
        self.set_outputs(obj, SpineDistance=report.spine_distance,
                         RmfDefect=report.rmf_angle_error,
                         Orthogonality=report.max_parameter_cosine,
                         SingularityMargin=report.singularity_margin,
                         FaceCount=len(shape.Faces), FrameError=report.frame_error)


def sections(obj):
    """The sections between Profile and EndProfile, (fraction, profile) pairs from
    SectionFractions and Sections: as many of each, the fractions strictly increasing in
    (0, 1), and an EndProfile; None without sections; ValueError naming the property
    otherwise."""
    fractions, links = list(obj.SectionFractions), list(obj.Sections)
    if len(fractions) != len(links):
        raise ValueError("Sections, SectionFractions: a section is a profile and a fraction, "
                         "but there are %d sections and %d fractions"
                         % (len(links), len(fractions)))
    if not links:
        return None
    if not obj.EndProfile:
        raise ValueError("Sections: need an EndProfile, the section at the spine's end (the "
                         "sweep runs from Profile through the Sections to EndProfile)")
    last = 0.0
    for k, at in enumerate(fractions):
        if not last < at < 1:
            raise ValueError("SectionFractions[%d]: the fraction of the spine's length %r "
                             "must lie in (0, 1), after the one before it (%r)"
                             % (k, at, last))
        last = at
    return [(at, inputs.profile((link, []), "Sections[%d]" % k))
            for k, (at, link) in enumerate(zip(fractions, links))]


def scale_knots(obj):
    """The knots of the scale law, (fraction, scale) pairs from ScaleKnotFractions and
    ScaleKnotScales: as many of each, the fractions strictly increasing in (0, 1), the scales
    finite and positive; ValueError naming the property otherwise."""
    fractions, scales = list(obj.ScaleKnotFractions), list(obj.ScaleKnotScales)
    if len(fractions) != len(scales):
        raise ValueError("ScaleKnotFractions, ScaleKnotScales: a knot is a fraction and a "
                         "scale, but there are %d fractions and %d scales"
                         % (len(fractions), len(scales)))
    last = 0.0
    for k, (at, scale) in enumerate(zip(fractions, scales)):
        if not last < at < 1:
            raise ValueError("ScaleKnotFractions[%d]: the fraction of the spine's length %r "
                             "must lie in (0, 1), after the one before it (%r)"
                             % (k, at, last))
        if not (math.isfinite(scale) and scale > 0):
            raise ValueError("ScaleKnotScales[%d]: the profile's scale must be positive, got %r"
                             % (k, scale))
        last = at
    return list(zip(fractions, scales))


def make_sweep(doc, spine, profile, solid=True, corner="round", corner_radius=None,
               tolerance=1e-4):
    """See :func:`rmfsurf_workbench.make_sweep`."""
    if corner not in CORNERS:
        raise ValueError("corner: expected one of %s, got %r" % (", ".join(CORNERS), corner))
    if corner_radius is not None and not corner_radius > 0:
        raise ValueError("corner_radius: expected a radius > 0 or None, got %r" % corner_radius)
    spine_links = inputs.link_sub_list(spine, "spine")
    profile_link = inputs.link_sub(profile, "profile")
    obj = doc.addObject("Part::FeaturePython", "RmfSweep")
    SweepFeature(obj)
    obj.Spine = spine_links
    obj.Profile = profile_link
    obj.Solid = bool(solid)
    obj.Corner = corner
    obj.CornerRadius = corner_radius or 0.0
    obj.Tolerance = float(tolerance)
    attach_view(obj, "RmfSweep", claims=("Profile", "Spine"))
    hide(inputs.linked_objects(obj.Spine) + inputs.linked_objects(obj.Profile))
    doc.recompute()
    return obj
