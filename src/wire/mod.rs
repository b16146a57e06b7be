//! Sweeps along the paths CAD users draw: wires of lines, circular arcs and curves, with
//! smooth and sharp joints, open or closed, giving closed solids (or sheets) whose every
//! face is exact rational geometry.
//!
//! | module | computes |
//! | --- | --- |
//! | `edge` | the wire's edges oriented and joined; lines and arcs recognised in curve data; joints classified (G1, corner, reversal) |
//! | `corner` | sharp joints resolved: round (a tangent circular arc, solved on curves too) or miter (the bisecting plane) |
//! | `profile` | the cross-section's loops split at their corners, their orientation, extent (support function) and symmetry |
//! | `frame` | one RMF along the whole wire: constant on lines, the rational frame of arcs, the PH cubic rational RMF (Mäurer & Jüttler (29), (36)–(41)) on curves; twist, closure, the Cor. 7 margin |
//! | `law` | the Frenet frame, a fixed direction and a guide curve as turns against the RMF (θ' = τ for Frenet; the guide's crossing of each normal plane), unwrapped, their accuracy |
//! | `helix` | a lone circular helix edge under the Frenet frame or its axis direction, or a pipe along it, swept by the helix's screw motion: one smooth spline of the circle for spine and frames |
//! | `blend` | sweeps between two profiles or through sections: the profiles matched loop by loop, over common denominators, the blend as sums of scaled sweeps |
//! | `scale` | the scale law σ piecewise linear in arc length (the wire cut at its knots), as polynomials in each piece's parameter (exact on lines and PH pieces) |
//! | `oblique` | the fold check of a profile drawn in a plane across the wire other than the normal plane |
//! | `brep` | the faces (exact cylinders, tori, sweeps (42)), planar caps, shared edges, orientation; the accuracy report |
//!
//! The work is done in coordinates centred on the wire and scaled by a power of two to its
//! size, so that the result does not depend on where the wire is or how large it is
//! (1e-200 … 1e200), and mapped back exactly at the end.

mod blend;
mod brep;
mod clearance;
mod corner;
mod edge;
mod frame;
mod helix;
mod law;
mod oblique;
mod profile;
mod scale;

pub use brep::{Face, FaceKind, Shape, SweepReport};

use crate::bezier::PiecewiseCurve;
use crate::error::{invalid, Result};
use crate::math::robust_length;
use crate::model::Similarity;
use crate::spine::SpineMethod;
use corner::CornerMode;
use edge::RawEdge;
use frame::FrameOptions;
use glam::DVec3;
use law::FrameLaw;
use profile::Profile;
use scale::ScaleLaw;

/// Most lateral faces one sweep may have (spine pieces × profile edges).
pub const MAX_FACES: usize = 1 << 16;

/// One edge of a wire, in either orientation.
#[derive(Clone, Debug, PartialEq)]
pub enum Edge {
    /// The straight line from `from` to `to`.
    Line {
        /// The start point.
        from: DVec3,
        /// The end point.
        to: DVec3,
    },
    /// The circular arc from `start` through `through` to `end`.
    Arc {
        /// The start point.
        start: DVec3,
        /// A point of the arc between start and end.
        through: DVec3,
        /// The end point.
        end: DVec3,
    },
    /// Any curve on its whole domain (NURBS data, PH, Möbius or RRMF curves, ...). Its
    /// segments that are exactly straight or circular are swept as lines and arcs.
    Curve(PiecewiseCurve),
}

/// How sharp (G0) joints of the wire are resolved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Corner {
    /// A circular arc of this radius tangent to both edges (`None`: 1.5 times the
    /// profile's largest distance from the spine).
    Round(Option<f64>),
    /// Both legs cut by the plane bisecting the corner; straight legs only.
    Miter,
}

/// How the profile turns about the wire's tangent (before any twist).
#[derive(Clone, Debug, Default, PartialEq)]
pub enum SweepFrame {
    /// The rotation-minimizing frame: no turn about the tangent (pipes, mouldings).
    #[default]
    Rmf,
    /// The Frenet frame: f₂ along the principal normal at the start, then turning against
    /// the RMF by the curve's torsion — the screw motion of a helix, so a thread's edges are
    /// helices. Where the curvature vanishes (lines, inflections) or the normal jumps
    /// (joints) the frame keeps its angle instead of flipping. An open wire of one curve
    /// edge that is a circular helix is swept by the helix's screw motion itself: faces of
    /// degree 7 along it with simple knots, eight spans a turn.
    Frenet,
    /// f₂ along this direction projected onto the normal plane: the profile keeps its
    /// relation to the axis (OpenCascade's binormal mode). Refused where the direction is
    /// along the tangent. Along a lone circular helix edge with the direction along its
    /// axis, the helix's screw motion, as for [`SweepFrame::Frenet`].
    Fixed(DVec3),
    /// f₂ towards the guide curve of these edges (in any order and orientation), where it
    /// crosses the wire's normal plane (the crossing nearest the wire): the profile turns
    /// to follow a second rail (OpenCascade's auxiliary mode). Refused where the guide does
    /// not cross a normal plane, or touches the wire.
    Guide(Vec<Edge>),
}

/// How a round profile — every loop a circle about the spine in its normal plane, a pipe —
/// is swept along curve edges. Its surface is the same under every frame; the frame sets
/// its parametrization and how heavy its faces are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PipeFrame {
    /// The RMF, as every profile: parameter lines orthogonal (lines of curvature), degree 9
    /// along a PH cubic piece (Mäurer & Jüttler (42)).
    #[default]
    Rmf,
    /// The PH cubic spline's Euler–Rodrigues frame, the lightest exact rational adapted
    /// frame (quadratic over quadratic): degree 5 along a PH cubic piece, the same surface;
    /// its parameter lines are not orthogonal (the report's parameter cosine says how far).
    /// Taken where the sweep allows it — an open wire, the RMF frame law untwisted, the PH
    /// method, one profile all along — and the RMF elsewhere; lines and arcs alike either
    /// way. Along an open wire of one curve edge that is a circular helix, the helix's screw
    /// motion: degree 7 along it with simple knots, eight spans a turn.
    Lightest,
}

/// The options of a wire sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct WireSweep {
    /// Largest distance of the PH cubic spline from a curve edge (absolute; default 1e-4).
    pub tolerance: f64,
    /// Largest gap between consecutive edge ends, relative to the wire's size (its
    /// bounding-box diagonal); default 1e-7. Also the gap within which a profile loop is
    /// closed, relative to the profile's size.
    pub join_tolerance: f64,
    /// How sharp (G0) joints are resolved (default round).
    pub corner: Corner,
    /// f₂ at the wire's start, projected onto the normal plane. `None`: the normal of the
    /// plane through the start tangent and the wire's point farthest from the tangent line
    /// (the wire's plane for planar wires), or any normal for a straight wire.
    pub initial_normal: Option<DVec3>,
    /// Extra turn about the tangent over the whole wire, radians, linear in arc length.
    pub twist: f64,
    /// Closed wires: the frame closes modulo 2π/k (k ≥ 1; 0 is taken as 1).
    pub closure_symmetry: u32,
    /// A closed solid (the profile must be closed); otherwise the lateral faces only.
    pub solid: bool,
    /// How the profile turns about the tangent (default the RMF).
    pub frame: SweepFrame,
    /// The profile's scale at the wire's start and end (default `[1, 1]`), linear in arc
    /// length between (through `scale_knots`); both finite and positive, equal on a
    /// closed wire.
    pub scale: [f64; 2],
    /// Scales the law passes through between its start and end: (fraction of the wire's
    /// length, increasing in (0, 1); scale, finite and positive). σ is piecewise linear in
    /// arc length through them (default none: linear from start to end).
    pub scale_knots: Vec<(f64, f64)>,
    /// How curve edges are swept: [`SpineMethod::PhRmf`] (default: the PH cubic spline and
    /// its rational RMF), [`SpineMethod::Mobius`] or [`SpineMethod::Rrmf`] (spines with
    /// exact rational RMFs: the parameter lines orthogonal to rounding). Lines and arcs are
    /// exact whatever the method.
    pub method: SpineMethod,
    /// How a round profile (a pipe) is swept along curve edges (default the RMF).
    pub pipe_frame: PipeFrame,
}

impl Default for WireSweep {
    fn default() -> Self {
        Self {
            tolerance: 1e-4,
            join_tolerance: 1e-7,
            corner: Corner::Round(None),
            initial_normal: None,
            twist: 0.0,
            closure_symmetry: 0,
            solid: true,
            frame: SweepFrame::Rmf,
            scale: [1.0, 1.0],
            scale_knots: Vec::new(),
            method: SpineMethod::PhRmf,
            pipe_frame: PipeFrame::Rmf,
        }
    }
}

/// The range of wire sizes (bounding-box diagonals) taken: scaled by a power of two to 1,
/// every coordinate stays a normal number.
const MIN_SIZE: f64 = 1e-290;
const MAX_SIZE: f64 = 1e290;

/// The factor of the radius of a default round corner over the profile's radius.
const DEFAULT_RADIUS_FACTOR: f64 = 1.5;

/// The sweep of `profile` (with `holes`; planar curves in the frame at the wire's start,
/// x ↦ f₂, y ↦ f₃, z ↦ t: z = 0 in the normal plane, any other plane across the wire
/// carried rigidly, see `oblique`) along the wire of `edges` (see the module notes).
pub fn sweep(
    edges: &[Edge],
    profile: &PiecewiseCurve,
    holes: &[PiecewiseCurve],
    options: &WireSweep,
) -> Result<Shape> {
    sweep_stations(edges, profile, holes, Stations::none(), options)
}

/// [`sweep`] from `profile` (with `holes`) at the wire's start to `end_profile` (with
/// `end_holes`, as many as `holes`) at its end, blended linearly in arc length (module
/// `blend`): each loop matched to its counterpart, corner to corner. Open wires; both
/// profiles in the normal plane; a constant scale.
pub fn sweep_between(
    edges: &[Edge],
    profile: &PiecewiseCurve,
    holes: &[PiecewiseCurve],
    end_profile: &PiecewiseCurve,
    end_holes: &[PiecewiseCurve],
    options: &WireSweep,
) -> Result<Shape> {
    check_counts(edges.len(), end_profile, end_holes)?;
    let end = Section {
        at: 1.0,
        profile: end_profile,
        holes: end_holes,
    };
    sweep_stations(edges, profile, holes, Stations::end(&end), options)
}

/// A profile a sweep passes through (with its holes), in the frame there as the start
/// profile is in the frame at the start, at `at`: a fraction of the wire's length.
#[derive(Clone, Copy, Debug)]
pub struct Section<'a> {
    /// Where along the wire: 0 at its start, 1 at its end (measured on the given edges, with
    /// their round corners).
    pub at: f64,
    /// The outer loop.
    pub profile: &'a PiecewiseCurve,
    /// The holes, as many in every section.
    pub holes: &'a [PiecewiseCurve],
}

/// [`sweep`] through `sections` (two or more: the first at 0, the last at 1, the
/// fractions between strictly increasing), each blended into the next linearly in arc
/// length (module `blend`): every loop matched to its counterpart in all sections, corner
/// to corner, so that the sections are shared edges. Open wires; every profile in the
/// normal plane; a constant scale.
pub fn sweep_through(edges: &[Edge], sections: &[Section], options: &WireSweep) -> Result<Shape> {
    check_sections(edges.len(), sections)?;
    let first = &sections[0];
    sweep_stations(
        edges,
        first.profile,
        first.holes,
        Stations {
            after: &sections[1..],
            name: "sections",
        },
        options,
    )
}

/// The sections a sweep passes through after its start, and what refusals call them.
#[derive(Clone, Copy)]
struct Stations<'a> {
    after: &'a [Section<'a>],
    name: &'static str,
}

impl<'a> Stations<'a> {
    fn none() -> Self {
        Self {
            after: &[],
            name: "",
        }
    }

    fn end(end: &'a Section<'a>) -> Self {
        Self {
            after: std::slice::from_ref(end),
            name: "end_profile",
        }
    }

    /// How a refusal names section k (of the whole list, the start being 0).
    fn name_of(&self, k: usize) -> String {
        match self.name {
            "end_profile" => self.name.to_string(),
            name => format!("{name}[{k}]"),
        }
    }
}

fn sweep_stations(
    edges: &[Edge],
    profile: &PiecewiseCurve,
    holes: &[PiecewiseCurve],
    stations: Stations,
    options: &WireSweep,
) -> Result<Shape> {
    check_options(options)?;
    check_counts(edges.len(), profile, holes)?;
    let points: Vec<DVec3> = edges.iter().flat_map(edge_points).collect();
    if let Some((k, p)) = edges.iter().enumerate().find_map(|(k, e)| {
        edge_points(e)
            .into_iter()
            .find(|p| !p.is_finite())
            .map(|p| (k, p))
    }) {
        return invalid!("edge {k} has a non-finite point {p}");
    }
    if edges.is_empty() {
        return invalid!("edges: a wire needs at least one edge");
    }
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    // The diagonal without overflow or underflow in its squares.
    let size = robust_length(0.5 * hi - 0.5 * lo) * 2.0;
    if !(size > 0.0 && size.is_finite()) {
        return invalid!("edges: the wire has no extent (size {size})");
    }
    if !(MIN_SIZE..=MAX_SIZE).contains(&size) {
        return invalid!(
            "edges: the wire's size {size:e} is outside [{MIN_SIZE:e}, {MAX_SIZE:e}] (its \
             coordinates would not stay normal numbers)"
        );
    }
    let center = 0.5 * lo + 0.5 * hi;
    // A power of two: scaling by it is exact.
    let scale = 2f64.powi(size.log2().round() as i32);
    let unit = |p: DVec3| (p - center) / scale;
    let raw: Vec<RawEdge> = edges
        .iter()
        .map(|e| match e {
            Edge::Line { from, to } => RawEdge::Line(unit(*from), unit(*to)),
            Edge::Arc {
                start,
                through,
                end,
            } => RawEdge::Arc(unit(*start), unit(*through), unit(*end)),
            Edge::Curve(c) => RawEdge::Curve(c.similar(1.0 / scale, -center / scale)),
        })
        .collect();
    // A constant scale is the profile's own; a varying one is the law of module `scale`.
    let constant = constant_scale(options);
    let profile_scale = constant.unwrap_or(1.0) / scale;
    let outer = profile.similar(profile_scale, DVec3::ZERO);
    let holes: Vec<PiecewiseCurve> = holes
        .iter()
        .map(|h| h.similar(profile_scale, DVec3::ZERO))
        .collect();
    for (name, curve) in std::iter::once(("profile".to_string(), &outer)).chain(
        holes
            .iter()
            .enumerate()
            .map(|(k, h)| (format!("holes[{k}]"), h)),
    ) {
        if curve
            .segments()
            .iter()
            .flat_map(|s| s.homogeneous())
            .any(|h| !h.is_finite())
        {
            return invalid!(
                "{name}: its coordinates are out of proportion to the wire's size {size:e} \
                 (or not finite)"
            );
        }
    }
    let size_n = size / scale;
    let units = Similarity {
        scale,
        origin: center,
    };
    let chain = edge::chain(&raw, options.join_tolerance * size_n, size_n, units)?;
    let profile = Profile::new(&outer, &holes, options.solid, options.join_tolerance, scale)?;
    let blend = match stations.after.is_empty() {
        true => None,
        false => Some(matched_sections(
            &profile,
            stations,
            options,
            chain.closed,
            profile_scale,
        )?),
    };
    let profile = blend.as_ref().map_or(profile, |b| b[0].start.clone());
    if options.scale[0] != options.scale[1] && chain.closed {
        return invalid!(
            "scale: a closed wire must end at the scale it starts with, not {} and {}",
            options.scale[0],
            options.scale[1]
        );
    }
    // The law's largest value (a constant scale is the profile's own).
    let largest = match constant {
        Some(_) => 1.0,
        None => scale_values(options).fold(0.0, f64::max),
    };
    if profile.plane.is_some() && chain.closed {
        return invalid!(
            "profile: a closed wire takes a profile in its normal plane at the start (z = 0), \
             which its frame closes onto; this one is drawn out of it"
        );
    }
    // Its largest distance from the spine takes a root search per profile segment: once.
    let end_reach = blend
        .iter()
        .flatten()
        .map(|b| b.end.reach())
        .fold(0.0, f64::max);
    let reach = profile.reach();
    let radius = reach.max(end_reach) * largest;
    let mode = match options.corner {
        Corner::Miter => CornerMode::Miter,
        Corner::Round(Some(r)) => CornerMode::Round(r / scale),
        Corner::Round(None) => CornerMode::Round(DEFAULT_RADIUS_FACTOR * radius),
    };
    let chain = edge::split_arcs(corner::resolve(chain, mode, scale, radius)?);
    // The wire cut at the sections between its ends: the blend is linear along every piece.
    let inner: Vec<f64> = stations
        .after
        .iter()
        .map(|s| s.at)
        .filter(|&at| at < 1.0)
        .collect();
    let (chain, first_piece) = match &blend {
        Some(_) => {
            let (chain, starts) = scale::split_at_knots(chain, &inner)?;
            (chain, [0].into_iter().chain(starts).collect())
        }
        None => (chain, Vec::new()),
    };
    let blend = blend.map(|intervals| blend::Blends {
        intervals,
        first_piece,
    });
    // The wire cut at the scale's knots: σ linear along every piece.
    let (chain, knots) = match constant {
        Some(_) => (chain, Vec::new()),
        None => {
            let fractions: Vec<f64> = options.scale_knots.iter().map(|k| k.0).collect();
            let (chain, starts) = scale::split_at_knots(chain, &fractions)?;
            let values = starts
                .into_iter()
                .zip(options.scale_knots.iter().map(|k| k.1));
            (chain, values.collect())
        }
    };
    let law_on = |lengths: &[f64]| match constant {
        Some(_) => ScaleLaw::none(),
        None => ScaleLaw::on_pieces(options.scale[0], &knots, options.scale[1], lengths),
    };
    let estimated: Vec<f64> = chain.pieces.iter().map(|p| p.geometry.length()).collect();
    let law = law_on(&estimated);
    if profile.plane.is_some() && chain.joints.iter().any(edge::Joint::cuts) {
        return invalid!(
            "profile: miter cuts take a profile in the wire's normal plane (z = 0); this one \
             is drawn out of it: use round corners"
        );
    }
    let faces = chain.pieces.len().saturating_mul(profile.edge_count());
    if faces > MAX_FACES {
        return invalid!(
            "the sweep would have {faces} lateral faces (spine pieces × profile edges), more \
             than {MAX_FACES}"
        );
    }
    let transport = frame::transport(
        &chain,
        &FrameOptions {
            initial_normal: options.initial_normal.filter(|n| *n != DVec3::ZERO),
            law: FrameLaw::new(&options.frame, &|c| c.similar(1.0 / scale, -center / scale))?,
            method: options.method,
            twist: options.twist,
            closure_symmetry: options.closure_symmetry.max(1),
            tolerance: options.tolerance / scale,
            units,
            // Arcs are cut for each interval's λ as for a scale law, |c₁ − c₀| ≤ the
            // reaches: λ up and down from 0 to 1 at every station.
            scale: match &blend {
                Some(b) => {
                    let up_down: Vec<(usize, f64)> = (1..b.intervals.len())
                        .map(|i| (b.first_piece[i], (i % 2) as f64))
                        .collect();
                    let end = (b.intervals.len() % 2) as f64;
                    ScaleLaw::on_pieces(0.0, &up_down, end, &estimated)
                }
                None => law,
            },
            reach: reach + end_reach,
            // A round profile, one all along, sweeps the same surface under every adapted
            // frame; a closed wire's frame must close onto its start (as the RMF's closure
            // turn does), and a twist or another frame law asks for a frame of its own.
            lightest: options.pipe_frame == PipeFrame::Lightest
                && blend.is_none()
                && profile.is_round()
                && !chain.closed
                && options.frame == SweepFrame::Rmf
                && options.twist == 0.0,
        },
    )?;
    let law = law_on(
        &transport
            .pieces
            .iter()
            .map(|p| p.length)
            .collect::<Vec<_>>(),
    );
    // The fold check with the profile at its largest: g = 1 − κσc·n is least there.
    let margins = if let Some(plane) = profile.plane {
        oblique::oblique_margin(
            &transport,
            &profile,
            plane,
            reach * law.max(),
            law.slope(),
            scale,
        )?
    } else if let Some(blend) = &blend {
        // Every section lies between two profiles: g ≥ the least of theirs.
        let mut least = frame::singularity_margin(&transport, &profile, scale)?.least();
        for b in &blend.intervals {
            least = least.min(frame::singularity_margin(&transport, &b.end, scale)?.least());
        }
        frame::Margins::measured(least, profile.segment_chain())
    } else if law.is_constant() {
        frame::singularity_margin(&transport, &profile, scale)?
    } else {
        let k = law.max();
        let largest = Profile::new(
            &outer.similar(k, DVec3::ZERO),
            &holes
                .iter()
                .map(|h| h.similar(k, DVec3::ZERO))
                .collect::<Vec<_>>(),
            options.solid,
            options.join_tolerance,
            scale,
        )?;
        frame::singularity_margin(&transport, &largest, scale)?
    };
    brep::build(
        &transport,
        &profile,
        blend.as_ref(),
        &law,
        options.solid,
        units,
        margins,
        options.join_tolerance * size_n,
    )
}

/// The sections after the start in the sweep's coordinates, matched to the start profile
/// and to each other (module `blend`): the blend of each interval between two. What a
/// sweep through sections cannot take is refused here.
fn matched_sections(
    profile: &Profile,
    stations: Stations,
    options: &WireSweep,
    closed: bool,
    profile_scale: f64,
) -> Result<Vec<blend::Blend>> {
    let name = stations.name;
    if closed {
        return invalid!(
            "{name}: a closed wire ends where it starts, with its start profile; give an open \
             wire"
        );
    }
    if constant_scale(options).is_none() {
        return invalid!("scale: with {name} the profiles set the sections; use a constant scale");
    }
    let mut profiles = vec![profile.clone()];
    for (k, section) in stations.after.iter().enumerate() {
        let outer = section.profile.similar(profile_scale, DVec3::ZERO);
        let holes: Vec<PiecewiseCurve> = section
            .holes
            .iter()
            .map(|h| h.similar(profile_scale, DVec3::ZERO))
            .collect();
        let unit = 1.0 / profile_scale;
        let section = Profile::new(&outer, &holes, options.solid, options.join_tolerance, unit)
            .map_err(|e| e.context(stations.name_of(k + 1)))?;
        profiles.push(section);
    }
    blend::matched_sections(&profiles, &|k| stations.name_of(k))
}

/// Two or more sections, the first at 0 and the last at 1, the fractions strictly
/// increasing; each with no more holes than a sweep can take.
fn check_sections(edge_count: usize, sections: &[Section]) -> Result<()> {
    if sections.len() < 2 {
        return invalid!(
            "sections: a sweep through sections needs two or more (the first at 0, the last \
             at 1), not {}",
            sections.len()
        );
    }
    let last = sections.len() - 1;
    for (k, section) in sections.iter().enumerate() {
        let at = section.at;
        let fits = match k {
            0 => at == 0.0,
            k if k == last => at == 1.0,
            k => station_fits(at, sections[k - 1].at),
        };
        if !fits {
            return invalid!(
                "sections[{k}]: at = {at} must be {}",
                match k {
                    0 => "0 (the first section is at the wire's start)".to_string(),
                    k if k == last => "1 (the last section is at the wire's end)".to_string(),
                    k => format!(
                        "in ({}, 1), after the section before it, by at least \
                         {MIN_STATION_GAP:e} from it and from the wire's end",
                        sections[k - 1].at
                    ),
                }
            );
        }
        check_counts(edge_count, section.profile, section.holes)
            .map_err(|e| e.context(format!("sections[{k}]")))?;
    }
    Ok(())
}

/// Every edge gives at least one lateral face per profile segment: a wire or profile beyond
/// [`MAX_FACES`] is refused from the counts alone, before anything is built.
fn check_counts(edges: usize, profile: &PiecewiseCurve, holes: &[PiecewiseCurve]) -> Result<()> {
    if holes.len() > MAX_FACES {
        return invalid!(
            "holes: {} holes, more than a sweep's {MAX_FACES} lateral faces",
            holes.len()
        );
    }
    let segments = std::iter::once(profile)
        .chain(holes)
        .map(|c| c.segments().len())
        .fold(0usize, usize::saturating_add);
    let faces = edges.saturating_mul(segments);
    if faces > MAX_FACES {
        return invalid!(
            "the sweep would have at least {faces} lateral faces ({edges} edges × {segments} \
             profile segments), more than {MAX_FACES}"
        );
    }
    Ok(())
}

fn check_options(options: &WireSweep) -> Result<()> {
    if !(options.tolerance.is_finite() && options.tolerance > 0.0) {
        return invalid!(
            "tolerance = {} must be finite and positive",
            options.tolerance
        );
    }
    if !(options.join_tolerance.is_finite()
        && options.join_tolerance > 0.0
        && options.join_tolerance < 1e-2)
    {
        return invalid!(
            "join_tolerance = {} must be positive and below 1e-2 (it is relative to the wire's size)",
            options.join_tolerance
        );
    }
    if let Corner::Round(Some(r)) = options.corner {
        if !(r.is_finite() && r > 0.0) {
            return invalid!("corner_radius = {r} must be finite and positive");
        }
    }
    if !options.twist.is_finite() {
        return invalid!("twist = {} must be finite", options.twist);
    }
    if let Some(n) = options.initial_normal {
        if !n.is_finite() {
            return invalid!("initial_normal = {n} must be finite");
        }
        if n != DVec3::ZERO && options.frame != SweepFrame::Rmf {
            return invalid!(
                "initial_normal = {n} is for the rmf frame; the {} frame sets f2 itself",
                frame_name(&options.frame)
            );
        }
    }
    match &options.frame {
        SweepFrame::Fixed(d) if !(d.is_finite() && *d != DVec3::ZERO) => {
            return invalid!("frame: the fixed direction {d} must be finite and not zero");
        }
        SweepFrame::Guide(edges) => check_guide(edges)?,
        _ => {}
    }
    for (name, s) in ["start", "end"].iter().zip(options.scale) {
        if !(s.is_finite() && s > 0.0) {
            return invalid!("scale: the {name} scale {s} must be finite and positive");
        }
    }
    check_scale_knots(&options.scale_knots)?;
    if options.method == SpineMethod::Frenet {
        return invalid!(
            "method: frenet makes Frenet frames, which a wire sweep asks for with its frame \
             option; the methods of wire sweeps are ph-rmf, mobius and rrmf"
        );
    }
    if options.method != SpineMethod::PhRmf && constant_scale(options).is_none() {
        return invalid!(
            "scale: a scale law is exact along PH splines, whose arc length is a polynomial; \
             with method {} use a constant scale, or method ph-rmf",
            options.method.name()
        );
    }
    Ok(())
}

/// Least distance, as a fraction of the wire's length, of a scale knot or a section from
/// the wire's ends and from the one before it: ten times the distance within which the wire
/// is cut at a piece boundary instead (`scale::split_at_knots`), so that no two of them, nor
/// one and an end, fall on the same boundary (which would make the law jump there).
const MIN_STATION_GAP: f64 = 1e-8;

/// Whether `at` lies in (0, 1) at least [`MIN_STATION_GAP`] after `before` and before 1.
fn station_fits(at: f64, before: f64) -> bool {
    at - before >= MIN_STATION_GAP && 1.0 - at >= MIN_STATION_GAP
}

/// The scale's knots: fractions increasing in (0, 1), values finite and positive.
fn check_scale_knots(knots: &[(f64, f64)]) -> Result<()> {
    let mut last = 0.0;
    for (k, &(at, value)) in knots.iter().enumerate() {
        if !station_fits(at, last) {
            return invalid!(
                "scale_knots[{k}]: its fraction of the wire's length {at} must lie in (0, 1), \
                 after the knot before it ({last}), by at least {MIN_STATION_GAP:e} from it \
                 and from the ends"
            );
        }
        if !(value.is_finite() && value > 0.0) {
            return invalid!("scale_knots[{k}]: the scale {value} must be finite and positive");
        }
        last = at;
    }
    Ok(())
}

/// Every value the scale law takes at its start, knots and end.
fn scale_values(options: &WireSweep) -> impl Iterator<Item = f64> + '_ {
    let knots = options.scale_knots.iter().map(|k| k.1);
    std::iter::once(options.scale[0])
        .chain(knots)
        .chain(std::iter::once(options.scale[1]))
}

/// The scale when it is the same along the whole wire.
fn constant_scale(options: &WireSweep) -> Option<f64> {
    let first = options.scale[0];
    scale_values(options).all(|s| s == first).then_some(first)
}

/// The frame's name as the CLI and Python spell it.
fn frame_name(frame: &SweepFrame) -> &'static str {
    match frame {
        SweepFrame::Rmf => "rmf",
        SweepFrame::Frenet => "frenet",
        SweepFrame::Fixed(_) => "fixed",
        SweepFrame::Guide(_) => "guide",
    }
}

/// A guide's edges: at least one, every point finite.
fn check_guide(edges: &[Edge]) -> Result<()> {
    if edges.is_empty() {
        return invalid!("frame: the guide needs at least one edge");
    }
    for (k, edge) in edges.iter().enumerate() {
        if let Some(p) = edge_points(edge).into_iter().find(|p| !p.is_finite()) {
            return invalid!("frame: edge {k} of the guide has a non-finite point {p}");
        }
    }
    Ok(())
}

/// The points that span an edge (for the wire's size and centre).
fn edge_points(edge: &Edge) -> Vec<DVec3> {
    match edge {
        Edge::Line { from, to } => vec![*from, *to],
        Edge::Arc {
            start,
            through,
            end,
        } => vec![*start, *through, *end],
        Edge::Curve(c) => c.segments().iter().flat_map(|s| s.poles()).collect(),
    }
}

#[cfg(test)]
mod analytic_tests;
#[cfg(test)]
mod guide_tests;
#[cfg(test)]
mod helix_tests;
#[cfg(test)]
mod options_tests;
#[cfg(test)]
mod pipe_tests;
#[cfg(test)]
mod robustness_tests;
#[cfg(test)]
mod scale_knot_tests;
#[cfg(test)]
mod section_tests;
#[cfg(test)]
pub(crate) mod tests;
