//! The C API of wire sweeps (geometry in `rmfsurf::wire`): a wire of lines, arcs and
//! curves, a planar profile with optional holes, and the options, in; an `RmfShape` (a
//! closed solid or a sheet of exact rational faces) out.

use super::boundary::{
    guard, invalid_arg, options as read_options, out_ptr, reference, slice, write, FfiError,
    OptionsStruct,
};
use super::curve::RmfCurve;
use super::frames::{RMF_SPINE_FRENET, RMF_SPINE_MOBIUS, RMF_SPINE_PH_RMF, RMF_SPINE_RRMF};
use super::shape::RmfShape;
use super::status::RmfStatus;
use super::types::RmfVec3;
use rmfsurf::glam::DVec3;
use rmfsurf::PiecewiseCurve;
use rmfsurf::{
    wire::sweep as sweep_wire, wire::sweep_between as sweep_wire_between,
    wire::sweep_through as sweep_wire_through, wire::Corner, wire::Edge, wire::PipeFrame,
    wire::Section, wire::SweepFrame, wire::WireSweep, wire::MAX_FACES, Error, SpineMethod,
};

/// What an RmfEdge is (values fixed, validated).
/// \ingroup rmf_wire
pub type RmfEdgeKind = u32;
/// A straight line from points[0] to points[1].
/// \ingroup rmf_wire
pub const RMF_EDGE_LINE: RmfEdgeKind = 0;
/// A circular arc from points[0] through points[1] to points[2].
/// \ingroup rmf_wire
pub const RMF_EDGE_ARC: RmfEdgeKind = 1;
/// A curve (any RmfCurve: NURBS data, PH, Möbius or RRMF curves, callbacks approximated
/// first with rmf_ph_spline_approximate, ...) on its whole domain.
/// \ingroup rmf_wire
pub const RMF_EDGE_CURVE: RmfEdgeKind = 2;

/// One edge of a wire, in either orientation. Unused points are ignored; `curve` is read
/// only for RMF_EDGE_CURVE (borrowed for the call; the shape keeps nothing of it).
/// \ingroup rmf_wire
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfEdge {
    /// RMF_EDGE_LINE, RMF_EDGE_ARC or RMF_EDGE_CURVE.
    pub kind: RmfEdgeKind,
    /// A line's start and end (points[0], points[1]); an arc's start, a point on it and
    /// its end.
    pub points: [RmfVec3; 3],
    /// RMF_EDGE_CURVE: the curve, on its whole domain; ignored otherwise.
    pub curve: *const RmfCurve,
}

/// How sharp (G0) joints of a wire are resolved (values fixed, validated).
/// \ingroup rmf_wire
pub type RmfCorner = u32;
/// The corner replaced by a circular arc of corner_radius tangent to both edges (the
/// edges must lie in the plane of the corner near it): an exact torus elbow.
/// \ingroup rmf_wire
pub const RMF_CORNER_ROUND: RmfCorner = 0;
/// Both legs cut by the plane bisecting the corner, the frame reflected in it (the legs
/// must be straight lines).
/// \ingroup rmf_wire
pub const RMF_CORNER_MITER: RmfCorner = 1;

/// How the profile turns about the wire's tangent (before any twist; values fixed,
/// validated).
/// \ingroup rmf_wire
pub type RmfSweepFrame = u32;
/// The rotation-minimizing frame: no turn about the tangent (pipes, mouldings).
/// \ingroup rmf_wire
pub const RMF_FRAME_RMF: RmfSweepFrame = 0;
/// The Frenet frame: f2 along the principal normal at the start, then turning against the
/// RMF by the curve's torsion — the screw motion of a helix, so a thread's edges are
/// helices. Where the curvature vanishes (lines, inflections) or the normal jumps (joints)
/// the frame keeps its angle instead of flipping.
/// \ingroup rmf_wire
pub const RMF_FRAME_FRENET: RmfSweepFrame = 1;
/// f2 along frame_direction projected onto the normal plane: the profile keeps its
/// relation to that direction (OpenCascade's binormal mode). Refused where the direction
/// is along the tangent.
/// \ingroup rmf_wire
pub const RMF_FRAME_FIXED: RmfSweepFrame = 2;
/// f2 towards the guide curve of guide_edges, where it crosses the wire's normal plane (the
/// crossing nearest the wire): the profile turns to follow a second rail (OpenCascade's
/// auxiliary mode). Refused where the guide does not cross a normal plane, or touches the
/// wire.
/// \ingroup rmf_wire
pub const RMF_FRAME_GUIDE: RmfSweepFrame = 3;

/// How a round profile (every loop a circle about the wire in its normal plane: a pipe) is
/// swept along curve edges; its surface is the same either way (values fixed, validated).
/// \ingroup rmf_wire
pub type RmfPipeFrame = u32;
/// The RMF, as every profile: parameter lines orthogonal (lines of curvature), degree 9
/// along the spine on curve edges.
/// \since 0.2
/// \ingroup rmf_wire
pub const RMF_PIPE_FRAME_RMF: RmfPipeFrame = 0;
/// The PH cubic spline's Euler–Rodrigues frame, the lightest exact rational adapted frame:
/// degree 5 along the spine on curve edges, the same surface, its parameter lines not
/// orthogonal. Taken on open wires with the RMF untwisted, method RMF_SPINE_PH_RMF and one
/// profile all along; the RMF elsewhere.
/// \since 0.2
/// \ingroup rmf_wire
pub const RMF_PIPE_FRAME_LIGHTEST: RmfPipeFrame = 1;

/// A section of a sweep through sections (rmf_wire_sweep_through): a profile with its holes
/// at a fraction of the wire's length (all borrowed for the call).
/// \ingroup rmf_wire
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfWireSection {
    /// Where along the wire: a fraction of its length (measured with its round corners), 0
    /// for the first section, 1 for the last, strictly increasing between.
    pub at: f64,
    /// The outer loop, in the frame at its station as rmf_wire_sweep's profile is in the
    /// frame at the start (x along f2, y along f3, z = 0 in the normal plane).
    pub profile: *const RmfCurve,
    /// hole_count inner loops (as many in every section), or NULL when hole_count is 0.
    pub holes: *const *const RmfCurve,
    /// Number of holes.
    pub hole_count: usize,
}

/// Options of rmf_wire_sweep. Initialise with rmf_wire_sweep_options_init, then change
/// fields; the struct only grows at the end.
/// \ingroup rmf_wire
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct RmfWireSweepOptions {
    /// sizeof(RmfWireSweepOptions), set by rmf_wire_sweep_options_init.
    pub struct_size: usize,
    /// Largest distance of the PH cubic spline from a curve edge, absolute (default 1e-4).
    pub tolerance: f64,
    /// Largest gap between consecutive edge ends, relative to the wire's size (the diagonal
    /// of its bounding box); default 1e-7, below 1e-2. Gaps within it are closed by moving
    /// the later edge's start onto the earlier edge's end. Also the relative gap within
    /// which a profile loop counts as closed.
    pub join_tolerance: f64,
    /// Sharp joints: RMF_CORNER_ROUND (default) or RMF_CORNER_MITER.
    pub corner: RmfCorner,
    /// RMF_CORNER_ROUND: the radius (finite, > 0); 0 = 1.5 times the profile's largest
    /// distance from the spine (default).
    pub corner_radius: f64,
    /// f2 at the wire's start, projected onto the normal plane; the zero vector (default)
    /// = the unit normal of the plane through the start tangent and the wire's point
    /// farthest from the tangent line (the wire's plane for a planar wire), or some normal
    /// of a straight wire.
    pub initial_normal: RmfVec3,
    /// Extra turn about the tangent over the whole wire, radians, linear in arc length
    /// (default 0).
    pub twist: f64,
    /// Closed wires: the frame closes modulo 2π/k with the smallest extra turn (k ≥ 1, e.g.
    /// 4 for a square profile); 0 (default) = 1. The turn must map the profile onto itself.
    pub closure_symmetry: u32,
    /// 1 (default): a closed solid (refuses open profiles); 0: the lateral faces only.
    pub solid: u32,
    /// Added in 0.2 (after solid): RMF_FRAME_RMF (default), RMF_FRAME_FRENET,
    /// RMF_FRAME_FIXED or RMF_FRAME_GUIDE. A frame other than RMF_FRAME_RMF sets f2
    /// itself: initial_normal must then be zero.
    pub frame: RmfSweepFrame,
    /// RMF_FRAME_FIXED: the direction f2 follows (finite, not zero, never along the
    /// tangent); ignored otherwise. Default (0, 0, 0).
    pub frame_direction: RmfVec3,
    /// The profile's scale at the wire's start (finite, > 0; default 1), linear in arc
    /// length to scale_end.
    pub scale_start: f64,
    /// The profile's scale at the wire's end (finite, > 0; default 1); equal to scale_start
    /// on a closed wire.
    pub scale_end: f64,
    /// Added in 0.2 (after scale_end): how curve edges are swept — RMF_SPINE_PH_RMF
    /// (default: a PH cubic spline within tolerance and its rational approximation of the
    /// RMF), RMF_SPINE_MOBIUS or RMF_SPINE_RRMF (spines with exact rational RMFs: the
    /// parameter lines orthogonal to rounding). Lines and arcs are exact whatever the
    /// method. RMF_SPINE_FRENET is refused (the Frenet frame is options->frame =
    /// RMF_FRAME_FRENET); RMF_SPINE_MOBIUS and RMF_SPINE_RRMF take no scale law
    /// (scale_start = scale_end).
    pub method: u32,
    /// Added in 0.2 (after method): scale_knot_count knots of the scale law, each two
    /// doubles (fraction, scale): the fraction of the wire's length where the profile has
    /// that scale, the fractions strictly increasing in (0, 1), the scales finite and
    /// positive. The scale then runs from scale_start through every knot to scale_end,
    /// linearly in arc length between them (a chain of frustums along a line). NULL with
    /// scale_knot_count 0 (default): no knots. Borrowed for the call.
    pub scale_knots: *const f64,
    /// Added in 0.2 (with scale_knots): the number of knots, pairs of doubles at scale_knots
    /// (default 0).
    pub scale_knot_count: usize,
    /// Added in 0.2 (after scale_knot_count): RMF_FRAME_GUIDE: guide_edge_count edges of the guide
    /// curve (as `edges` of rmf_wire_sweep: lines, arcs and curves, in any order and
    /// orientation; curves borrowed for the call); ignored otherwise. Default NULL.
    pub guide_edges: *const RmfEdge,
    /// RMF_FRAME_GUIDE: the number of guide_edges (≥ 1); ignored otherwise. Default 0.
    pub guide_edge_count: usize,
    /// Added in 0.2 (after guide_edge_count): how a round profile — every loop a circle
    /// about the wire in its normal plane, a pipe — is swept along curve edges:
    /// RMF_PIPE_FRAME_RMF (default) or RMF_PIPE_FRAME_LIGHTEST (faces of degree 5 along
    /// the spine instead of 9, the same surface). Other profiles ignore it.
    pub pipe_frame: RmfPipeFrame,
}

impl Default for RmfWireSweepOptions {
    fn default() -> Self {
        let d = WireSweep::default();
        Self {
            struct_size: std::mem::size_of::<Self>(),
            tolerance: d.tolerance,
            join_tolerance: d.join_tolerance,
            corner: RMF_CORNER_ROUND,
            corner_radius: 0.0,
            initial_normal: RmfVec3::default(),
            twist: 0.0,
            closure_symmetry: 0,
            solid: 1,
            frame: RMF_FRAME_RMF,
            frame_direction: RmfVec3::default(),
            scale_start: d.scale[0],
            scale_end: d.scale[1],
            method: RMF_SPINE_PH_RMF,
            scale_knots: std::ptr::null(),
            scale_knot_count: 0,
            guide_edges: std::ptr::null(),
            guide_edge_count: 0,
            pipe_frame: RMF_PIPE_FRAME_RMF,
        }
    }
}

// SAFETY: #[repr(C)], first field size_t, every field a number, a u32 code or a raw pointer
// (any bit pattern is a value: codes validated on use, the pointers checked like arguments
// before they are read; guide_edges read only with RMF_FRAME_GUIDE, through `slice`).
unsafe impl OptionsStruct for RmfWireSweepOptions {
    /// The struct up to `solid`, before `frame` was added: a caller built against that
    /// header (or the one before `method`, or before `scale_knots`) gets the defaults of the
    /// fields after it.
    const FIRST_SIZE: usize = std::mem::offset_of!(RmfWireSweepOptions, frame);
}

/// Writes the default options and their struct_size.
///
/// @param[out] options Receives the defaults (see RmfWireSweepOptions).
/// @return RMF_OK, or RMF_ERROR_NULL_POINTER if options is NULL.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_wire_sweep_options_init(
    options: *mut RmfWireSweepOptions,
) -> RmfStatus {
    guard("rmf_wire_sweep_options_init", || {
        let options = out_ptr(options, "options")?;
        write(options, RmfWireSweepOptions::default());
        Ok(())
    })
}

/// The scale law's knots, (fraction, scale) from the doubles at options->scale_knots: the
/// pointer and the count checked here, the values by the geometry (whose `scale_knots[k]:`
/// messages `blame_method` puts on the doubles).
///
/// # Safety
/// `o.scale_knots` must be NULL or point to `2 * o.scale_knot_count` doubles.
unsafe fn scale_knots(o: &RmfWireSweepOptions) -> Result<Vec<(f64, f64)>, FfiError> {
    let count = o.scale_knot_count;
    if count == 0 {
        return Ok(Vec::new());
    }
    if count > MAX_FACES {
        return invalid_arg(format!(
            "options->scale_knot_count = {count}: each knot cuts the wire, and a wire sweep \
             has at most {MAX_FACES} lateral faces"
        ));
    }
    let doubles = slice(o.scale_knots, 2 * count, "options->scale_knots")?;
    Ok(doubles.chunks_exact(2).map(|k| (k[0], k[1])).collect())
}

/// The options as the geometry takes them (validated; the guide's edges read and checked).
///
/// # Safety
/// `o.scale_knots` must be NULL or point to `2 * o.scale_knot_count` doubles; with
/// RMF_FRAME_GUIDE, `o.guide_edges` must be NULL or point to `o.guide_edge_count` edges,
/// each curve NULL or a valid handle.
unsafe fn wire_options(o: &RmfWireSweepOptions) -> Result<WireSweep, FfiError> {
    let corner = match o.corner {
        RMF_CORNER_ROUND if o.corner_radius == 0.0 => Corner::Round(None),
        RMF_CORNER_ROUND => {
            if !(o.corner_radius.is_finite() && o.corner_radius > 0.0) {
                return invalid_arg(format!(
                    "options->corner_radius = {} must be finite and positive (0: the default)",
                    o.corner_radius
                ));
            }
            Corner::Round(Some(o.corner_radius))
        }
        RMF_CORNER_MITER => Corner::Miter,
        other => {
            return invalid_arg(format!(
                "options->corner = {other} is no RmfCorner (RMF_CORNER_ROUND = 0, RMF_CORNER_MITER = 1)"
            ))
        }
    };
    if o.solid > 1 {
        return invalid_arg(format!("options->solid = {} must be 0 or 1", o.solid));
    }
    let frame = match o.frame {
        RMF_FRAME_RMF => SweepFrame::Rmf,
        RMF_FRAME_FRENET => SweepFrame::Frenet,
        RMF_FRAME_FIXED => {
            let d: DVec3 = o.frame_direction.into();
            if !(d.is_finite() && d != DVec3::ZERO) {
                return invalid_arg(format!(
                    "options->frame_direction = {d} must be finite and not zero (the \
                     direction of RMF_FRAME_FIXED)"
                ));
            }
            SweepFrame::Fixed(d)
        }
        RMF_FRAME_GUIDE => {
            if o.guide_edge_count == 0 {
                return invalid_arg(
                    "options->guide_edge_count = 0: RMF_FRAME_GUIDE needs the guide's edges \
                     in options->guide_edges (at least one)"
                        .into(),
                );
            }
            let guide = slice(o.guide_edges, o.guide_edge_count, "options->guide_edges")?;
            SweepFrame::Guide(wire_edges(guide, EdgeArray::Guide)?)
        }
        other => {
            return invalid_arg(format!(
                "options->frame = {other} is no RmfSweepFrame (RMF_FRAME_RMF = 0, \
                 RMF_FRAME_FRENET = 1, RMF_FRAME_FIXED = 2, RMF_FRAME_GUIDE = 3)"
            ))
        }
    };
    for (name, s) in [("scale_start", o.scale_start), ("scale_end", o.scale_end)] {
        if !(s.is_finite() && s > 0.0) {
            return invalid_arg(format!(
                "options->{name} = {s} must be finite and positive (default 1)"
            ));
        }
    }
    let method = match o.method {
        RMF_SPINE_PH_RMF => SpineMethod::PhRmf,
        // Refused by the geometry, whose message `blame_method` puts on options->method.
        RMF_SPINE_FRENET => SpineMethod::Frenet,
        RMF_SPINE_MOBIUS => SpineMethod::Mobius,
        RMF_SPINE_RRMF => SpineMethod::Rrmf,
        other => {
            return invalid_arg(format!(
                "options->method = {other} is no method of a wire sweep (RMF_SPINE_PH_RMF = \
                 0, RMF_SPINE_MOBIUS = 2, RMF_SPINE_RRMF = 3)"
            ))
        }
    };
    let pipe_frame = match o.pipe_frame {
        RMF_PIPE_FRAME_RMF => PipeFrame::Rmf,
        RMF_PIPE_FRAME_LIGHTEST => PipeFrame::Lightest,
        other => {
            return invalid_arg(format!(
                "options->pipe_frame = {other} is no RmfPipeFrame (RMF_PIPE_FRAME_RMF = 0, \
                 RMF_PIPE_FRAME_LIGHTEST = 1)"
            ))
        }
    };
    let normal: DVec3 = o.initial_normal.into();
    if normal != DVec3::ZERO && frame != SweepFrame::Rmf {
        return invalid_arg(format!(
            "options->initial_normal = {normal} goes with RMF_FRAME_RMF only: options->frame \
             = {} sets f2 itself (leave initial_normal zero)",
            o.frame
        ));
    }
    Ok(WireSweep {
        tolerance: o.tolerance,
        join_tolerance: o.join_tolerance,
        corner,
        initial_normal: (normal != DVec3::ZERO).then_some(normal),
        twist: o.twist,
        closure_symmetry: o.closure_symmetry,
        solid: o.solid == 1,
        frame,
        scale: [o.scale_start, o.scale_end],
        scale_knots: scale_knots(o)?,
        method,
        pipe_frame,
    })
}

/// The geometry's refusals of the method (`method: …`), of a scale law with it (`scale:
/// …`), of a knot of the law (`scale_knots[k]: …`, put on the double at
/// options->scale_knots that is wrong) and of a guide (`frame: …` with RMF_FRAME_GUIDE) with
/// the fields of the options named; `knots` as read from options->scale_knots.
fn blame_method(e: Error, o: &RmfWireSweepOptions, knots: &[(f64, f64)]) -> Error {
    let fields = if let Some(rest) = e.reason().strip_prefix("method: ") {
        format!("options->method = {}: {rest}", o.method)
    } else if let Some(rest) = e
        .reason()
        .strip_prefix("frame: ")
        .filter(|_| o.frame == RMF_FRAME_GUIDE)
    {
        format!("options->frame = RMF_FRAME_GUIDE, options->guide_edges: {rest}")
    } else if let Some(rest) = e.reason().strip_prefix("scale: ") {
        let knots = match knots.len() {
            0 => String::new(),
            1..=4 => format!(
                ", options->scale_knots = [{}]",
                knots
                    .iter()
                    .map(|(at, s)| format!("({at}, {s})"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            n => format!(", options->scale_knot_count = {n}"),
        };
        format!(
            "options->scale_start = {}, options->scale_end = {}{knots} with options->method = \
             {}: {rest}",
            o.scale_start, o.scale_end, o.method
        )
    } else if let Some((k, rest)) = knot_refusal(e.reason()) {
        // Knot k is the doubles 2k (its fraction) and 2k + 1 (its scale).
        let (index, what) = if rest.starts_with("the scale") {
            (2 * k + 1, "scale")
        } else {
            (2 * k, "fraction")
        };
        format!("options->scale_knots[{index}] (the {what} of knot {k}): {rest}")
    } else {
        return e;
    };
    let contexts: Vec<&str> = e.contexts().collect();
    contexts
        .into_iter()
        .rev()
        .fold(Error::new(e.kind(), fields), |e, c| e.context(c))
}

/// The knot and the rest of a geometry's refusal `scale_knots[k]: rest`.
fn knot_refusal(reason: &str) -> Option<(usize, &str)> {
    let (k, rest) = reason.strip_prefix("scale_knots[")?.split_once("]: ")?;
    Some((k.parse().ok()?, rest))
}

/// Which array of edges is read: the wire's (`edges`) or the guide's
/// (`options->guide_edges`), as the messages name it.
#[derive(Clone, Copy)]
enum EdgeArray {
    Wire,
    Guide,
}

impl EdgeArray {
    fn name(self) -> &'static str {
        match self {
            EdgeArray::Wire => "edges",
            EdgeArray::Guide => "options->guide_edges",
        }
    }

    /// The name of a curve handle in the array (for `reference`).
    fn curve(self) -> &'static str {
        match self {
            EdgeArray::Wire => "edges[].curve",
            EdgeArray::Guide => "options->guide_edges[].curve",
        }
    }
}

/// The edges as the geometry takes them (kinds and points checked, curves borrowed);
/// messages name `array`.
///
/// # Safety
/// Every `curve` of a curve edge must be NULL or a valid handle.
unsafe fn wire_edges(edges: &[RmfEdge], array: EdgeArray) -> Result<Vec<Edge>, FfiError> {
    let name = array.name();
    edges
        .iter()
        .enumerate()
        .map(|(k, e)| {
            let point = |i: usize| -> Result<DVec3, FfiError> {
                let p: DVec3 = e.points[i].into();
                if !p.is_finite() {
                    return invalid_arg(format!("{name}[{k}].points[{i}] = {p} is not finite"));
                }
                Ok(p)
            };
            Ok(match e.kind {
                RMF_EDGE_LINE => Edge::Line {
                    from: point(0)?,
                    to: point(1)?,
                },
                RMF_EDGE_ARC => Edge::Arc {
                    start: point(0)?,
                    through: point(1)?,
                    end: point(2)?,
                },
                RMF_EDGE_CURVE => {
                    if e.curve.is_null() {
                        return invalid_arg(format!(
                            "{name}[{k}].curve is NULL (an RMF_EDGE_CURVE edge)"
                        ));
                    }
                    Edge::Curve(
                        reference(e.curve, array.curve())?
                            .rational(&format!("{name}[{k}].curve"))?
                            .as_ref()
                            .clone(),
                    )
                }
                other => {
                    return invalid_arg(format!(
                        "{name}[{k}].kind = {other} is no RmfEdgeKind (LINE 0, ARC 1, CURVE 2)"
                    ))
                }
            })
        })
        .collect()
}

/// Sweeps a planar profile along a wire of lines, arcs and curves (rmfsurf's wire sweep):
///
/// - the edges may come in either orientation; each must start where the previous one
///   ends (within options->join_tolerance); a wire whose end meets its start is closed;
/// - lines and arcs (also NURBS segments that are exactly straight or circular) are swept
///   exactly: along a line the rotation-minimizing frame (RMF) is constant and a circle
///   gives an exact cylinder patch, along an arc the frame turns with it and the face is
///   rational of degree 2 along the arc (an exact torus patch for a circle). Other curves
///   are approximated by a PH cubic spline within options->tolerance and carry its rational
///   RMF (Mäurer & Jüttler, eqs. (29), (36)–(42)). One RMF runs along the whole wire: it
///   is carried across every joint without a turn about the tangent;
/// - options->frame turns the profile about the tangent by another law than the RMF: the
///   Frenet frame (RMF_FRAME_FRENET: a thread along a helix), a fixed direction
///   (RMF_FRAME_FIXED with options->frame_direction) or a guide curve, a second rail f2
///   points at (RMF_FRAME_GUIDE with options->guide_edges); options->scale_start and
///   options->scale_end scale the profile about the spine, linearly in arc length (a
///   frustum along a line), through the knots at options->scale_knots if any (piecewise
///   linear: a chain of frustums);
/// - options->method sweeps curve edges along spines with exact rational RMFs instead
///   (RMF_SPINE_MOBIUS: Möbius images of planar PH cubics, Bartoň, Jüttler & Wang;
///   RMF_SPINE_RRMF: RRMF quintics, Farouki, Giannelli & Sestini): the parameter lines of
///   their faces are orthogonal to rounding (report's max_parameter_cosine ~1e-14, where
///   the PH cubic's rational RMF leaves ~1e-7);
/// - sharp joints are rounded (a tangent arc, exact torus elbow) or mitred (options->corner);
/// - a closed wire closes without a seam: the RMF's holonomy is cancelled by the smallest
///   turn modulo 2π/closure_symmetry, spread linearly in arc length;
/// - the profile is given in the frame at the wire's start: x along f2, y along f3 and z
///   along the tangent — z = 0 in the normal plane, as usual; a planar profile in any
///   other plane across the wire (a thread's profile in the axial plane) is carried
///   rigidly (not on closed wires or with miter cuts). It is split at its Bézier segment joints:
///   one lateral face per profile segment per line, quarter arc, or curve edge. With
///   options->solid the profile and the holes must be closed, and an open wire gets planar
///   caps: the faces form a closed, outward-oriented solid sharing its edges.
///
/// Refused before anything is built: a profile reaching past the centre of curvature of an
/// arc, corner or curve (Mäurer & Jüttler Cor. 7), miter cuts that cross inside the
/// profile, a corner radius that does not fit the edges; the message names the edge or
/// joint and gives the largest (or smallest) allowed value.
///
/// @param[in] edges edge_count edges (≥ 1), consecutive along the wire.
/// @param[in] edge_count Number of edges.
/// @param[in] profile The outer profile loop (a planar curve in the start frame's
///            coordinates: x along f2, y along f3, z along the tangent; z = 0 in the
///            normal plane).
/// @param[in] holes hole_count inner loops (closed, inside the profile, disjoint), or NULL
///            when hole_count is 0. Need a closed profile.
/// @param[in] hole_count Number of holes.
/// @param[in] options NULL for the defaults, or initialised by rmf_wire_sweep_options_init.
/// @param[out] out Receives the shape; free with rmf_shape_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If edges (with edge_count > 0), profile, a hole, holes
///         (with hole_count > 0), options->scale_knots (with options->scale_knot_count >
///         0) or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT If an edge, the profile, a hole or an option is invalid
///         or the sweep would fold (the message names the edge, joint, loop or option).
/// @return RMF_ERROR_NO_SOLUTION / RMF_ERROR_NOT_CONVERGED If a curve edge admits no PH
///         cubic spline within the tolerance (e.g. a cusp).
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_wire_sweep(
    edges: *const RmfEdge,
    edge_count: usize,
    profile: *const RmfCurve,
    holes: *const *const RmfCurve,
    hole_count: usize,
    options: *const RmfWireSweepOptions,
    out: *mut *mut RmfShape,
) -> RmfStatus {
    guard("rmf_wire_sweep", || {
        let out = out_ptr(out, "out")?;
        let edges = checked_edges(edges, edge_count)?;
        face_bound("hole_count", hole_count)?;
        let edges = wire_edges(edges, EdgeArray::Wire)?;
        let profile = reference(profile, "profile")?;
        let holes = loops(holes, hole_count, "holes")?;
        let raw = read_options(options, "options")?;
        let options = wire_options(&raw)?;
        let shape = sweep_wire(&edges, profile.rational("profile")?, &holes, &options)
            .map_err(|e| blame_method(e, &raw, &options.scale_knots))?;
        write(out, RmfShape::new(shape).into_raw());
        Ok(())
    })
}

/// rmf_wire_sweep from `profile` (with `holes`) at the wire's start to `end_profile` (with
/// `end_holes`) at its end: the section blends linearly in arc length. Each loop is matched
/// to its counterpart (hole to hole, the same turning sense, the loop with fewer edges
/// split at the middle of its longest, corner to the nearest corner), each pair of matched
/// segments written over one denominator: exact rational faces (Mäurer & Jüttler (1) with
/// a moving profile; along arcs within options->tolerance). A circle into a smaller
/// concentric circle is the scale law's sweep.
///
/// @param[in] edges, edge_count, profile, holes, hole_count, options As for rmf_wire_sweep.
/// @param[in] end_profile The outer loop at the wire's end (same coordinates as profile).
/// @param[in] end_holes end_hole_count inner loops (as many as holes), or NULL when 0.
/// @param[in] end_hole_count Number of end holes.
/// @param[out] out Receives the shape; free with rmf_shape_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If edges, a profile, a hole array with a count > 0,
///         options->scale_knots with a count > 0 or out is NULL.
/// @return RMF_ERROR_INVALID_INPUT As for rmf_wire_sweep; also (the message naming
///         end_profile) for a different number of holes, a closed wire, a scale law beside
///         the end profile, a profile out of the normal plane.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn rmf_wire_sweep_between(
    edges: *const RmfEdge,
    edge_count: usize,
    profile: *const RmfCurve,
    holes: *const *const RmfCurve,
    hole_count: usize,
    end_profile: *const RmfCurve,
    end_holes: *const *const RmfCurve,
    end_hole_count: usize,
    options: *const RmfWireSweepOptions,
    out: *mut *mut RmfShape,
) -> RmfStatus {
    guard("rmf_wire_sweep_between", || {
        let out = out_ptr(out, "out")?;
        let edges = checked_edges(edges, edge_count)?;
        face_bound("hole_count", hole_count)?;
        face_bound("end_hole_count", end_hole_count)?;
        let edges = wire_edges(edges, EdgeArray::Wire)?;
        let profile = reference(profile, "profile")?;
        let holes = loops(holes, hole_count, "holes")?;
        let end_profile = reference(end_profile, "end_profile")?;
        let end_holes = loops(end_holes, end_hole_count, "end_holes")?;
        let raw = read_options(options, "options")?;
        let options = wire_options(&raw)?;
        let shape = sweep_wire_between(
            &edges,
            profile.rational("profile")?,
            &holes,
            end_profile.rational("end_profile")?,
            &end_holes,
            &options,
        )
        .map_err(|e| blame_method(e, &raw, &options.scale_knots))?;
        write(out, RmfShape::new(shape).into_raw());
        Ok(())
    })
}

/// rmf_wire_sweep through sections: the section passes through each profile of `sections`
/// at its fraction of the wire's length (the first at 0, the last at 1, strictly increasing
/// between), blended linearly in arc length from each into the next. Every loop is matched
/// to its counterpart in all sections (hole to hole, as rmf_wire_sweep_between matches two),
/// so the section at a station is an edge shared by the faces before and after it: exact
/// rational faces (along arcs within options->tolerance). Circles of radii a0, a1, ... at
/// the stations along a line are the chain of frustums of volume
/// pi/3 sum L_i (a_i^2 + a_i a_(i+1) + a_(i+1)^2).
///
/// @param[in] edges, edge_count, options As for rmf_wire_sweep.
/// @param[in] sections section_count sections (≥ 2), each profile in the frame at its
///            station as rmf_wire_sweep's profile is in the frame at the start (x along
///            f2, y along f3, z = 0 in the normal plane), with as many holes as the others.
/// @param[in] section_count Number of sections (≥ 2).
/// @param[out] out Receives the shape; free with rmf_shape_free. Untouched on failure.
/// @return RMF_OK on success.
/// @return RMF_ERROR_NULL_POINTER If edges, sections, a section's profile, its holes with
///         a hole_count > 0, options->scale_knots with a count > 0 or out is NULL (the
///         message naming sections[k].profile, sections[k].holes).
/// @return RMF_ERROR_INVALID_INPUT As for rmf_wire_sweep; also (the message naming
///         section_count, sections[k].at, sections[k].profile or sections[k].holes) for
///         fewer than two sections, fractions not 0, increasing, 1, a NULL hole, a
///         different number of holes, a profile out of the normal plane; and (naming
///         sections) a closed wire, or (naming the options' scale) a scale law.
/// \since 0.2
/// \ingroup rmf_wire
#[no_mangle]
pub unsafe extern "C" fn rmf_wire_sweep_through(
    edges: *const RmfEdge,
    edge_count: usize,
    sections: *const RmfWireSection,
    section_count: usize,
    options: *const RmfWireSweepOptions,
    out: *mut *mut RmfShape,
) -> RmfStatus {
    guard("rmf_wire_sweep_through", || {
        let out = out_ptr(out, "out")?;
        let edges = checked_edges(edges, edge_count)?;
        if section_count < 2 {
            return invalid_arg(format!(
                "section_count = {section_count}: a sweep through sections needs two or more \
                 (the first at 0, the last at 1)"
            ));
        }
        face_bound("section_count", section_count)?;
        let sections = slice(sections, section_count, "sections")?;
        let edges = wire_edges(edges, EdgeArray::Wire)?;
        let loops = sections
            .iter()
            .enumerate()
            .map(|(k, s)| section_loops(s, k))
            .collect::<Result<Vec<_>, _>>()?;
        let sections: Vec<Section> = sections
            .iter()
            .zip(&loops)
            .map(|(s, (profile, holes))| Section {
                at: s.at,
                profile,
                holes,
            })
            .collect();
        let raw = read_options(options, "options")?;
        let options = wire_options(&raw)?;
        let shape = sweep_wire_through(&edges, &sections, &options)
            .map_err(|e| blame_section(blame_method(e, &raw, &options.scale_knots)))?;
        write(out, RmfShape::new(shape).into_raw());
        Ok(())
    })
}

/// The outer loop and the holes of section k, each curve borrowed; messages name
/// `sections[k].profile`, `sections[k].holes`.
///
/// # Safety
/// `section.profile` must be NULL or a valid handle; `section.holes` NULL or pointing to
/// `section.hole_count` pointers, each NULL or a valid handle.
unsafe fn section_loops(
    section: &RmfWireSection,
    k: usize,
) -> Result<(PiecewiseCurve, Vec<PiecewiseCurve>), FfiError> {
    if section.profile.is_null() {
        return Err(FfiError::NullAt(format!("sections[{k}].profile")));
    }
    let profile = reference(section.profile, "sections[].profile")?
        .rational(&format!("sections[{k}].profile"))?
        .as_ref()
        .clone();
    face_bound(&format!("sections[{k}].hole_count"), section.hole_count)?;
    if section.hole_count > 0 && section.holes.is_null() {
        return Err(FfiError::NullAt(format!("sections[{k}].holes")));
    }
    let holes = slice(section.holes, section.hole_count, "sections[].holes")?;
    let holes = curves(holes, &format!("sections[{k}].holes"), "sections[].holes[]")?;
    Ok((profile, holes))
}

/// The core's refusals of section k (`sections[k]: …`) on the field of the RmfWireSection
/// they are about: `sections[k].at`, `sections[k].holes` (a different number, or a hole's
/// own refusal) or `sections[k].profile`.
fn blame_section(e: Error) -> Error {
    let message = e.message();
    let Some((k, rest)) = message
        .strip_prefix("sections[")
        .and_then(|m| m.split_once("]: "))
        .filter(|(k, _)| k.parse::<usize>().is_ok())
    else {
        return e;
    };
    let fields = if let Some(at) = rest.strip_prefix("at = ") {
        format!("sections[{k}].at = {at}")
    } else if let Some(hole) = rest.strip_prefix("holes[") {
        format!("sections[{k}].holes[{hole}")
    } else if let Some(profile) = rest.strip_prefix("profile: ") {
        format!("sections[{k}].profile: {profile}")
    } else if rest.contains("hole") {
        format!("sections[{k}].holes: {rest}")
    } else {
        format!("sections[{k}].profile: {rest}")
    };
    Error::new(e.kind(), fields)
}

/// The edges, their count checked first: each edge gives at least one lateral face, so a
/// count beyond the face bound is refused before any edge is read.
///
/// # Safety
/// `edges` must be NULL or point to `edge_count` edges.
unsafe fn checked_edges<'a>(
    edges: *const RmfEdge,
    edge_count: usize,
) -> Result<&'a [RmfEdge], FfiError> {
    if edge_count == 0 {
        return invalid_arg("edge_count = 0: a wire needs at least one edge".into());
    }
    face_bound("edge_count", edge_count)?;
    slice(edges, edge_count, "edges")
}

/// Each edge and each hole gives at least one lateral face: counts beyond the face bound
/// are refused before anything is read.
fn face_bound(name: &str, count: usize) -> Result<(), FfiError> {
    if count > MAX_FACES {
        return invalid_arg(format!(
            "{name} = {count}: a wire sweep has at most {MAX_FACES} lateral faces, one or more \
             per edge and per profile segment"
        ));
    }
    Ok(())
}

/// A profile's holes (`name`: "holes" or "end_holes"), each closed curve borrowed.
///
/// # Safety
/// `holes` must be NULL or point to `count` pointers, each NULL or a valid handle.
unsafe fn loops(
    holes: *const *const RmfCurve,
    count: usize,
    name: &'static str,
) -> Result<Vec<PiecewiseCurve>, FfiError> {
    let element = if name == "holes" {
        "holes[]"
    } else {
        "end_holes[]"
    };
    curves(slice(holes, count, name)?, name, element)
}

/// The curves of an array of holes, messages naming `name[k]` (`element` for a handle's
/// alignment).
///
/// # Safety
/// Each pointer must be NULL or a valid handle.
unsafe fn curves(
    holes: &[*const RmfCurve],
    name: &str,
    element: &'static str,
) -> Result<Vec<PiecewiseCurve>, FfiError> {
    holes
        .iter()
        .enumerate()
        .map(|(k, &h)| {
            if h.is_null() {
                return invalid_arg(format!("{name}[{k}] is NULL"));
            }
            Ok(reference(h, element)?
                .rational(&format!("{name}[{k}]"))?
                .as_ref()
                .clone())
        })
        .collect()
}
