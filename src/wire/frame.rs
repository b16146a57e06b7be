//! One rotation-minimizing frame (f₂, f₃) along the whole wire, carried from the start
//! piece by piece:
//!
//! * along a line the RMF is constant;
//! * along a circular arc it keeps its coefficients (a, b) in the Frenet frame,
//!   f₂ = a N + b B with N the principal normal and B the arc's normal (a planar curve has
//!   no torsion, so its Frenet frame is rotation-minimizing). With N = (c − x)/R this frame
//!   is rational of degree 2 with the arc's own weights — the sweep of a rational profile is
//!   then a rational patch of degree (m, 2), an exact torus for a circle;
//! * along any other curve, the PH cubic spline that approximates it within the tolerance
//!   (Mäurer & Jüttler Theorem 10) carries its rational RMF (29) with the biquadratic W of
//!   (36)–(41), exact at the ends, started from the frame that arrives;
//! * at a G1 joint the frame is projected onto the next normal plane (the identity when the
//!   tangents agree: no twist at joints); at a miter it is reflected in the miter plane;
//! * a round profile (circles about the spine, [`super::PipeFrame::Lightest`]) sweeps the
//!   same surface under every frame: along a curve of an open wire, untwisted, it takes the
//!   PH spline's Euler–Rodrigues frame instead (quadratic over quadratic: degree 5 along
//!   the spine instead of the RMF's 9), each cubic's turned to continue the one before.
//!
//! Twist and closure. A caller's `twist` is added as a turn linear in arc length over the
//! whole wire. A closed wire's RMF comes back turned by its holonomy Δ; the smallest turn φ
//! that closes it modulo 2π/k (k the profile's symmetry) is added in the same way, as the
//! closed-spine sweep of [`crate::ph_cubic::rational_rmf`] does — spread over every piece
//! except miter legs, whose frame must stay constant for the miter cut to be exact. On PH
//! pieces the turn enters the Hermite data of W; on lines and arcs the base frame is turned
//! by 2 arctan W with W of the same family fitted to tan(φ(s)/2), so the frames stay
//! rational and exact at every joint.
//!
//! Before anything is built the sweep is checked for folding (Cor. 7): g = 1 − κ c·n > 0
//! everywhere — along arcs g = 1 − h(N)/R with h the profile's support function, along PH
//! pieces the margin of [`crate::ph_cubic::analysis`] — and each miter leg must be longer
//! than the profile's cuts at its ends.

use super::edge::{Chain, Geometry, Joint, JointKind, Piece};
use super::helix::{Follow, Helix, Screw};
use super::law::{law_jet, law_normal, FrameLaw, LawAngle, Unwrapped, LAW_SAMPLES};
use super::profile::{Profile, SupportTable};
use super::scale::{arc_segments, ScaleLaw};
use crate::bezier::{PiecewiseCurve, RationalBezierCurve};
use crate::error::{invalid, Result, ResultExt};
use crate::frames::metrics::angle_about_tangent;
use crate::frames::rational::{RationalFrameSegment, RationalFrames};
use crate::frames::Frame;
use crate::math::{lerp, GaussLegendre};
use crate::math::{normal_plane_unit, orthogonalized, orthonormal_to, signed_angle};
use crate::mesh::grid_parameters;
use crate::model::{Arc, Similarity};
use crate::ph_cubic::accuracy::AngleCheck;
use crate::ph_cubic::analysis::ProfileSurface;
use crate::ph_cubic::approximate::ph_spline_approximate;
use crate::ph_cubic::base_frame::{FrameNumerators, FramePieces};
use crate::ph_cubic::biquadratic::{fit, AngleHermite, Biquadratic};
use crate::ph_cubic::exact_rmf::ExactRmf;
use crate::ph_cubic::frenet::ph_frenet_frames;
use crate::ph_cubic::preimage::euler_rodrigues_frames;
use crate::ph_cubic::rational_rmf::{ph_rational_rmf, RmfOptions};
use crate::ph_cubic::spline::PhSpline;
use crate::spine::{framed_spine, SpineMethod};
use glam::{DVec2, DVec3};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Samples per segment at which twisted lines and arcs are compared with their target.
const ERROR_SAMPLES: usize = 64;

/// Deepest halving of a twisted segment (2⁻¹⁶ of it).
const MAX_HALVINGS: usize = 16;

/// How the frame is set up (normalized coordinates).
#[derive(Clone, Debug)]
pub(crate) struct FrameOptions {
    pub initial_normal: Option<DVec3>,
    /// The frame followed (the RMF, Frenet, a fixed direction), before the twist.
    pub law: FrameLaw,
    /// How curve pieces are made: the PH cubic spline with its rational RMF, or a Möbius or
    /// RRMF spine with its exact rational RMF.
    pub method: SpineMethod,
    pub twist: f64,
    /// Closed wires: k of 2π/k (≥ 1).
    pub closure_symmetry: u32,
    /// PH approximation of curves.
    pub tolerance: f64,
    /// How normalized coordinates map to the caller's.
    pub units: Similarity,
    /// The scale law (its length estimated from the wire's edges), and the profile's
    /// largest distance from the spine, for cutting arcs fine enough for it.
    pub scale: ScaleLaw,
    pub reach: f64,
    /// Curve pieces take their PH spline's Euler–Rodrigues frame
    /// ([`super::PipeFrame::Lightest`] where it applies: a round profile along an open wire,
    /// the RMF untwisted).
    pub lightest: bool,
}

/// A closing turn (radians) at most this is rounding: the frame closes as it is, and the
/// seam's sections differ by at most this angle times the profile's reach (the report's
/// seam gap). A polygon's discrete RMF comes back with no turn at all for many wires (a
/// symmetric one, say), computed as a few ulps.
pub(crate) const CLOSURE_ROUND_OFF: f64 = 1e-9;

/// The frame along one piece.
#[derive(Clone, Debug)]
pub(crate) enum PieceFrame {
    /// An untwisted line: constant.
    Constant { f2: DVec3, f3: DVec3 },
    /// An untwisted arc: f₂ = a N + b B, f₃ = a B − b N.
    Circular { a: f64, b: f64 },
    /// Rational frames along the piece's spine curve (PH pieces, twisted lines and arcs).
    Rational(RationalFrames),
}

/// A piece with its frame.
#[derive(Clone, Debug)]
pub(crate) struct Framed {
    pub piece: Piece,
    /// The curve swept along: the line, the arc, or the PH spline of a curve.
    pub spine: PiecewiseCurve,
    pub frame: PieceFrame,
    pub start: Frame,
    pub end: Frame,
    pub length: f64,
    /// Distance of the PH spline from the curve (0 for lines and arcs).
    pub distance: f64,
    /// A helix swept by its screw motion.
    pub screw: Option<Screw>,
    /// Largest angle between the frames and the exact (twisted) RMF, where it is known
    /// while building (lines and arcs).
    pub angle_error: f64,
    /// Along a curve: the comparison of its frames with the PH spline's exact RMF, prepared
    /// (the angle is measured for the report, on request).
    pub angle_check: Option<AngleCheck>,
    /// Miter planes (point, unit normal) cutting a straight leg at its start and end.
    pub miters: [Option<(DVec3, DVec3)>; 2],
}

/// The framed pieces of a wire.
#[derive(Clone, Debug)]
pub(crate) struct Transport {
    pub pieces: Vec<Framed>,
    pub closed: bool,
    /// Closed wires: the frame after the closing joint is the start frame turned by this
    /// (a multiple of 2π/k up to rounding).
    pub closing_turn: f64,
    /// Largest angle between the frames and the frame law asked for (0 for the RMF).
    pub frame_error: f64,
}

/// The curve a piece is swept along: the line or the arc, or the PH spline of a curve
/// with its distance from the curve.
#[derive(Clone, Debug)]
struct Spine {
    curve: PiecewiseCurve,
    ph: Option<PhSpline>,
    /// A Möbius or RRMF spine's exact rational RMF, or a helix's Frenet frames.
    exact: Option<ExactFrames>,
    distance: f64,
    /// A helix swept by its screw motion (module `helix`).
    screw: Option<Screw>,
}

/// The exact rational RMF of a Möbius or RRMF spine (Bartoň, Jüttler & Wang; Farouki,
/// Giannelli & Sestini), from some f₂ at its start, with the arc length along the spine
/// (by Gauss–Legendre quadrature: these spines are not PH).
#[derive(Clone, Debug)]
struct ExactFrames {
    frames: RationalFrames,
    spine: PiecewiseCurve,
    /// The arc length at each of the spine's breaks.
    lengths: Vec<f64>,
    /// The quadrature rule of the arc length, made once.
    rule: GaussLegendre,
}

/// Gauss–Legendre nodes per spine segment for the arc length of exact-RMF spines.
const LENGTH_NODES: usize = 16;

impl ExactFrames {
    fn new(frames: RationalFrames, spine: PiecewiseCurve) -> Self {
        let rule = GaussLegendre::new(LENGTH_NODES);
        let mut lengths = vec![0.0];
        for w in spine.breaks().windows(2) {
            let length = rule.integrate(w[0], w[1], |v| spine.eval_jet(v).d1.length());
            lengths.push(lengths[lengths.len() - 1] + length);
        }
        Self {
            frames,
            spine,
            lengths,
            rule,
        }
    }

    /// The constant angle that turns the frames to start at the unit normal `f2`.
    fn turn_to(&self, f2: DVec3) -> f64 {
        let start = self.frames.frame(self.spine.domain().0);
        signed_angle(start.f2, f2, start.tangent)
    }

    /// The RMF started at the unit normal `f2`: the frames turned by one constant angle.
    fn from(&self, f2: DVec3) -> Result<RationalFrames> {
        let angle = self.turn_to(f2);
        let segments = self
            .frames
            .segments()
            .iter()
            .map(|s| s.rotated(angle))
            .collect();
        RationalFrames::new(segments, self.frames.breaks().to_vec())
    }

    /// f₂ at the end of the RMF started at `f2` (without turning every segment).
    fn end_from(&self, f2: DVec3) -> DVec3 {
        let end = self.frames.frame(self.spine.domain().1);
        end.rotated(self.turn_to(f2)).f2
    }

    /// The arc length from the start to the spine's parameter v.
    fn arc_length_at(&self, v: f64) -> f64 {
        let (k, _) = self.spine.locate(v);
        let a = self.spine.breaks()[k];
        self.lengths[k]
            + self
                .rule
                .integrate(a, v, |t| self.spine.eval_jet(t).d1.length())
    }

    fn length(&self) -> f64 {
        self.lengths[self.lengths.len() - 1]
    }
}

/// The spines of the pieces. Curves are approximated about the wire's centre in the
/// caller's units (the normalized coordinates scaled back by a power of two, exactly: the
/// same decisions at every scale and position), so that what the approximation reports (a
/// tolerance below the rounding, say) is in the caller's units.
fn spines(chain: &Chain, options: &FrameOptions) -> Result<Vec<Spine>> {
    let (tolerance, units) = (options.tolerance, options.units);
    chain
        .pieces
        .iter()
        .map(|piece| {
            let exact = |curve| Spine {
                curve,
                ph: None,
                exact: None,
                distance: 0.0,
                screw: None,
            };
            Ok(match &piece.geometry {
                Geometry::Line { a, b } => exact(line_curve(*a, *b)),
                Geometry::Arc(arc) if !options.scale.is_constant() => {
                    exact(arc.curve_in(arc_segments(
                        arc.segment_count(),
                        arc.angle,
                        arc.radius,
                        &options.scale,
                        options.reach,
                        tolerance,
                    )))
                }
                Geometry::Arc(arc) => exact(arc.curve()),
                Geometry::Curve(c) if options.method != SpineMethod::PhRmf => {
                    exact_spine(piece, c, options.method, tolerance, units)?
                }
                Geometry::Curve(c) => match screw_spine(chain, c, options)? {
                    Some(spine) => spine,
                    None => ph_spine(piece, c, options)?,
                },
            })
        })
        .collect()
}

/// The PH cubic spline of a curve edge within the tolerance (module `ph_cubic::approximate`),
/// or the curve itself where it is one.
fn ph_spine(piece: &Piece, c: &PiecewiseCurve, options: &FrameOptions) -> Result<Spine> {
    let (tolerance, units) = (options.tolerance, options.units);
    let (ph, distance) = match given_ph_spline(c) {
        Some(ph) => (ph, 0.0),
        None => {
            let centred = c.similar(units.scale, DVec3::ZERO);
            let fit = ph_spline_approximate(&centred, c.breaks(), units.length(tolerance))
                .with_context(|| {
                    format!(
                        "edge {} (its coordinates taken about the wire's centre {})",
                        piece.edge, units.origin
                    )
                })?;
            let scale = 1.0 / units.scale;
            (
                fit.spline.similar(scale, DVec3::ZERO)?,
                fit.max_distance * scale,
            )
        }
    };
    Ok(Spine {
        curve: ph.curve().clone(),
        ph: Some(ph),
        exact: None,
        distance,
        screw: None,
    })
}

/// The Möbius or RRMF spine of a curve within `tolerance`, with its exact rational RMF,
/// made in the normalized coordinates (their constructions sample and compare distances:
/// at the unit size they decide alike at every scale and position).
fn exact_spine(
    piece: &Piece,
    curve: &PiecewiseCurve,
    method: SpineMethod,
    tolerance: f64,
    units: Similarity,
) -> Result<Spine> {
    let start = curve.segments()[0].eval_jet(0.0).d1;
    let fit = framed_spine(curve, method, tolerance, orthonormal_to(start.normalize()))
        .with_context(|| {
            format!(
                "edge {} (method {}, tolerance {:e} in the wire's units)",
                piece.edge,
                method.name(),
                units.length(tolerance)
            )
        })?;
    let (spine, frames) = fit.framed.into_parts();
    Ok(Spine {
        curve: spine.clone(),
        ph: None,
        exact: Some(ExactFrames::new(frames, spine)),
        distance: fit.distance,
        screw: None,
    })
}

/// The spine of a curve edge that is a circular helix, swept by its screw motion (module
/// `helix`), where the sweep is the screw motion's image of the profile: one open edge
/// under the Frenet frame or a direction along the helix's axis, untwisted at one scale, or
/// a pipe in its lightest faces. The edge's distance from the helix and, under a frame law,
/// the angle between what the law follows along the edge and the screw motion's frames at
/// the profile's reach take at most three quarters of the tolerance (each at most half), the
/// spline of the screw motion the rest.
fn screw_spine(
    chain: &Chain,
    curve: &PiecewiseCurve,
    options: &FrameOptions,
) -> Result<Option<Spine>> {
    let alone = chain.pieces.len() == 1 && !chain.closed;
    let untwisted = options.twist == 0.0 && options.scale.is_constant();
    let follow = match &options.law {
        FrameLaw::Frenet if untwisted => Some(Follow::Normal),
        FrameLaw::Fixed(d) if untwisted => Some(Follow::Direction(*d)),
        _ => None,
    };
    if !alone || (follow.is_none() && !options.lightest) {
        return Ok(None);
    }
    let (tolerance, reach) = (options.tolerance, options.reach);
    let limit = (0.5 * tolerance / reach.max(f64::MIN_POSITIVE)).min(1e-3);
    let Some(helix) = Helix::fit(curve, 0.5 * tolerance, follow.map(|f| (f, limit))) else {
        return Ok(None);
    };
    let used = helix.off_at(reach);
    if used > 0.75 * tolerance {
        return Ok(None);
    }
    let Some(spine) = helix.spine(curve.domain(), tolerance - used, reach)? else {
        return Ok(None);
    };
    let mut screw = helix.screw();
    screw.normal_angle += spine.frame_error;
    Ok(Some(Spine {
        curve: spine.curve.clone(),
        ph: None,
        exact: Some(ExactFrames::new(spine.frames, spine.curve)),
        distance: spine.distance,
        screw: Some(screw),
    }))
}

/// A curve that is already a PH cubic spline (cubic polynomial segments satisfying (17)).
fn given_ph_spline(curve: &PiecewiseCurve) -> Option<PhSpline> {
    let cubic = |s: &RationalBezierCurve| s.degree() == 3 && s.is_polynomial();
    if !curve.segments().iter().all(cubic) {
        return None;
    }
    PhSpline::new(curve.clone()).ok()
}

pub(crate) fn line_curve(a: DVec3, b: DVec3) -> PiecewiseCurve {
    let line = RationalBezierCurve::polynomial(&[a, b]).expect("finite points");
    PiecewiseCurve::new(vec![line], vec![0.0, 1.0]).expect("one segment")
}

/// The frame carried across a joint: reflected in a miter plane, projected onto the next
/// normal plane.
fn across(joint: &Joint, f2: DVec3) -> DVec3 {
    let carried = match joint.kind {
        JointKind::Miter { normal } => f2 - 2.0 * f2.dot(normal) * normal,
        _ => f2,
    };
    orthogonalized(carried, joint.outgoing).normalize()
}

/// The coefficients (a, b) of f₂ in (N, B) at the start of an arc.
fn arc_coefficients(arc: &Arc, f2: DVec3) -> (f64, f64) {
    let (a, b) = (f2.dot(arc.principal_normal(0.0)), f2.dot(arc.normal));
    let norm = a.hypot(b);
    (a / norm, b / norm)
}

/// f₂ at the end of a piece without twist.
fn carry(piece: &Piece, spine: &Spine, f2: DVec3) -> Result<DVec3> {
    Ok(match (&piece.geometry, &spine.ph) {
        (Geometry::Arc(arc), _) => {
            let (a, b) = arc_coefficients(arc, f2);
            a * arc.principal_normal(arc.angle) + b * arc.normal
        }
        (_, Some(ph)) => {
            let exact =
                ExactRmf::new(ph, f2, 0.0).with_context(|| format!("edge {}", piece.edge))?;
            exact.frame(ph.domain().1).f2
        }
        _ => match &spine.exact {
            Some(exact) => exact.end_from(f2),
            None => f2,
        },
    })
}

/// The default f₂ at the start: the unit normal of the plane through the start tangent
/// and the wire's point farthest from the tangent line (the wire's plane for a planar
/// wire), or any normal of a straight wire.
fn default_normal(chain: &Chain) -> DVec3 {
    let first = &chain.pieces[0].geometry;
    let (p0, t0) = (first.start(), first.start_tangent());
    let size = chain
        .pieces
        .iter()
        .flat_map(|p| p.geometry.hull_points())
        .fold(0.0f64, |m, p| m.max(p.distance(p0)));
    let farthest = chain
        .pieces
        .iter()
        .flat_map(|p| p.geometry.hull_points())
        .map(|p| t0.cross(p - p0))
        .fold(DVec3::ZERO, |best, c| {
            if c.length() > best.length() {
                c
            } else {
                best
            }
        });
    if farthest.length() > 1e-9 * size {
        farthest.normalize()
    } else {
        orthonormal_to(t0)
    }
}

/// The planes cutting each piece at its start and end: miter planes, and the normal planes
/// of curved edges at near-tangent joints (only lines are cut; they may not turn about
/// the tangent).
fn miters(chain: &Chain) -> Vec<[Option<(DVec3, DVec3)>; 2]> {
    let m = chain.pieces.len();
    // A miter cuts both legs; a near-tangent joint only its straight side.
    let plane = |j: &Joint, line_side: bool| match j.kind {
        JointKind::Miter { normal } => Some((j.point, normal)),
        JointKind::NearTangent {
            normal,
            line_before,
        } if line_before == line_side => Some((j.point, normal)),
        _ => None,
    };
    (0..m)
        .map(|i| {
            let before = if i > 0 {
                chain.joints.get(i - 1)
            } else if chain.closed {
                chain.joints.last()
            } else {
                None
            };
            [
                before.and_then(|j| plane(j, false)),
                chain.joints.get(i).and_then(|j| plane(j, true)),
            ]
        })
        .collect()
}

/// The frame along the chain (module notes).
pub(crate) fn transport(chain: &Chain, options: &FrameOptions) -> Result<Transport> {
    let spines = spines(chain, options)?;
    let m = chain.pieces.len();
    let first = &chain.pieces[0].geometry;
    let t0 = first.start_tangent();
    let f2_start = match options.initial_normal {
        Some(n) => normal_plane_unit(n, t0, "initial_normal")?,
        None => law_start(chain, &spines[0], options)?.unwrap_or_else(|| default_normal(chain)),
    };
    let law_turns = law_turns(chain, &spines, options)?;
    let lengths: Vec<f64> = chain
        .pieces
        .iter()
        .zip(&spines)
        .map(|(p, spine)| match (&spine.ph, &spine.exact) {
            // The arc length of a PH spline is a polynomial: exact.
            (Some(ph), _) => ph.cubics().iter().map(|c| c.arc_length()).sum(),
            (_, Some(exact)) => exact.length(),
            _ => p.geometry.length(),
        })
        .collect();
    let miters = miters(chain);
    let twistable: Vec<bool> = miters
        .iter()
        .map(|m| m[0].is_none() && m[1].is_none())
        .collect();
    // Pass 1: the RMF's holonomy of a closed wire.
    let mut total_twist = options.twist;
    if chain.closed {
        let mut f2 = f2_start;
        for (i, ((piece, spine), joint)) in chain
            .pieces
            .iter()
            .zip(&spines)
            .zip(&chain.joints)
            .take(m)
            .enumerate()
        {
            f2 = carry(piece, spine, f2)?;
            f2 = Frame::from_tangent_normal(piece.geometry.end_tangent(), f2)
                .rotated(law_turns[i].turn)
                .f2;
            f2 = across(joint, f2);
        }
        let holonomy = signed_angle(f2_start, f2, t0);
        let period = 2.0 * PI / options.closure_symmetry.max(1) as f64;
        let residual = holonomy + options.twist;
        total_twist = options.twist - residual + period * (residual / period).round();
    }
    let turnable: f64 = lengths
        .iter()
        .zip(&twistable)
        .filter(|(_, &t)| t)
        .map(|(l, _)| l)
        .sum();
    let rate =
        if total_twist == 0.0 || (options.twist == 0.0 && total_twist.abs() <= CLOSURE_ROUND_OFF) {
            0.0
        } else if turnable > 0.0 {
            total_twist / turnable
        } else {
            return invalid!(
            "the frame must turn by {total_twist:.3e} rad (twist and closure) but every edge is a \
             miter leg, whose frame cannot turn; use round corners"
        );
        };
    // Pass 2: the frames.
    let mut pieces = Vec::with_capacity(m);
    let mut f2 = f2_start;
    for i in 0..m {
        let piece = &chain.pieces[i];
        let LawTurn {
            turn: law_turn,
            uniform,
        } = law_turns[i];
        let turn = law_turn + if twistable[i] { rate * lengths[i] } else { 0.0 };
        // Along a curve a law that turns is followed (the twist of a PH spline's RMF that
        // cancels its torsion, as a helix's Frenet frame asks, leaves W no direction).
        let follow = !uniform || (law_turn != 0.0 && matches!(piece.geometry, Geometry::Curve(_)));
        let law = follow.then_some(&options.law);
        let framed = frame_piece(
            piece,
            spines[i].clone(),
            lengths[i],
            f2,
            PieceTurn {
                total: turn,
                law: law.map(|law| (law, turn - law_turn)),
                accuracy: law_accuracy(options),
                lightest: options.lightest,
            },
            miters[i],
        )
        .with_context(|| format!("edge {}", piece.edge))?;
        f2 = framed.end.f2;
        if let Some(joint) = chain.joints.get(i) {
            f2 = across(joint, f2);
        }
        pieces.push(framed);
    }
    let closing_turn = if chain.closed {
        signed_angle(f2_start, f2, t0)
    } else {
        0.0
    };
    Ok(Transport {
        frame_error: frame_error(&pieces, &options.law),
        pieces,
        closed: chain.closed,
        closing_turn,
    })
}

/// The curve as given, where a piece is one.
fn given(piece: &Piece) -> Option<&PiecewiseCurve> {
    match &piece.geometry {
        Geometry::Curve(c) => Some(c),
        _ => None,
    }
}

/// f₂ at the wire's start as the law asks (`None`: the RMF, or a Frenet frame where the
/// start is straight).
fn law_start(chain: &Chain, spine: &Spine, options: &FrameOptions) -> Result<Option<DVec3>> {
    let piece = &chain.pieces[0];
    let v = spine.curve.domain().0;
    let jet = law_jet(given(piece), &spine.curve, v, v);
    let normal = law_normal(&options.law, &jet);
    if normal.is_none() {
        if let Some(e) = undefined_law(&options.law, piece, jet.point, options.units) {
            return Err(e);
        }
    }
    Ok(normal.map(|n| orthogonalized(n, piece.geometry.start_tangent()).normalize()))
}

/// The refusal where a law that must be defined everywhere on the wire (a fixed direction, a
/// guide) is not, at `at` on `piece`; `None` for a law that may lapse (Frenet).
fn undefined_law(
    law: &FrameLaw,
    piece: &Piece,
    at: DVec3,
    units: Similarity,
) -> Option<crate::error::Error> {
    let message = match law {
        FrameLaw::Fixed(d) => format!(
            "frame: the fixed direction {d} runs along the tangent of {} at {} (it must stay \
             out of the tangent everywhere on the wire)",
            piece.name(),
            units.to_user(at)
        ),
        FrameLaw::Guide(_) => format!(
            "frame: the guide does not run beside the wire at {} of {} (it must cross every \
             normal plane of the wire, away from the wire)",
            units.to_user(at),
            piece.name()
        ),
        _ => return None,
    };
    Some(crate::error::Error::invalid_input(message))
}

/// The RMF along one piece from a given f₂ at its start, at the spine's parameters.
enum PieceRmf<'a> {
    Constant(DVec3),
    Arc {
        arc: &'a Arc,
        a: f64,
        b: f64,
    },
    Exact(ExactRmf),
    /// A Möbius or RRMF spine's exact rational RMF, turned to start at f₂.
    Frames(RationalFrames, &'a ExactFrames),
}

impl PieceRmf<'_> {
    /// (f₂, unit tangent) at the spine's parameter `v`.
    fn at(&self, spine: &PiecewiseCurve, v: f64) -> (DVec3, DVec3) {
        match self {
            PieceRmf::Constant(f2) => (*f2, spine.eval_jet(v).d1.normalize()),
            PieceRmf::Arc { arc, a, b } => circular_at(arc, *a, *b, spine, v),
            PieceRmf::Exact(exact) => {
                let frame = exact.frame(v);
                (frame.f2, frame.tangent)
            }
            PieceRmf::Frames(frames, _) => {
                let frame = frames.frame(v);
                (frame.f2, frame.tangent)
            }
        }
    }
}

/// The arc's frame f₂ = aN + bB at the spine's parameter `v`, with the unit tangent.
fn circular_at(arc: &Arc, a: f64, b: f64, spine: &PiecewiseCurve, v: f64) -> (DVec3, DVec3) {
    let jet = spine.eval_jet(v);
    let n = (arc.center - jet.point) / arc.radius;
    (a * n + b * arc.normal, jet.d1.normalize())
}

/// What a frame law asks of one piece: its turn against the RMF, and whether that turn
/// is linear in arc length (within the law's accuracy: the twist machinery carries it, as
/// on a helix, a planar curve or a line) or must be followed ([`law_frames`]).
#[derive(Clone, Copy, Debug, Default)]
struct LawTurn {
    turn: f64,
    uniform: bool,
}

/// The turn against the RMF over each piece that the frame law asks for (module `law`).
fn law_turns(chain: &Chain, spines: &[Spine], options: &FrameOptions) -> Result<Vec<LawTurn>> {
    let law = &options.law;
    if *law == FrameLaw::Rmf {
        return Ok(vec![
            LawTurn {
                turn: 0.0,
                uniform: true
            };
            chain.pieces.len()
        ]);
    }
    let accuracy = law_accuracy(options);
    chain
        .pieces
        .iter()
        .zip(spines)
        .map(|(piece, spine)| {
            if spine.screw.is_some() {
                // The screw motion's frames, turned to the law at the start, follow it.
                return Ok(LawTurn {
                    turn: 0.0,
                    uniform: true,
                });
            }
            let f2 = orthonormal_to(piece.geometry.start_tangent());
            let (lo, hi) = spine.curve.domain();
            let rmf = match (&piece.geometry, &spine.ph, &spine.exact) {
                (Geometry::Arc(arc), _, _) => {
                    let (a, b) = arc_coefficients(arc, f2);
                    PieceRmf::Arc { arc, a, b }
                }
                (_, Some(ph), _) => PieceRmf::Exact(
                    ExactRmf::new(ph, f2, 0.0).with_context(|| format!("edge {}", piece.edge))?,
                ),
                (_, _, Some(exact)) => PieceRmf::Frames(exact.from(f2)?, exact),
                _ => PieceRmf::Constant(f2),
            };
            let mut angles = Unwrapped::new(law);
            // (arc length, angle) where the law is defined.
            let mut track = Vec::new();
            for v in grid_parameters(spine.curve.breaks(), LAW_SAMPLES) {
                let jet = law_jet(given(piece), &spine.curve, v, v);
                let (r2, t) = rmf.at(&spine.curve, v);
                match law_normal(law, &jet) {
                    Some(n) => {
                        angles.push(r2, n, t);
                        let s = match &rmf {
                            PieceRmf::Exact(exact) => exact.arc_length_at(v),
                            PieceRmf::Frames(_, exact) => exact.arc_length_at(v),
                            _ => piece.geometry.length() * (v - lo) / (hi - lo),
                        };
                        track.extend(angles.last().map(|a| (s, a)));
                    }
                    None => {
                        if let Some(e) = undefined_law(law, piece, jet.point, options.units) {
                            return Err(e);
                        }
                    }
                }
            }
            let turn = angles.change();
            let uniform = match (track.first(), track.last()) {
                (Some(&(s0, a0)), Some(&(s1, a1))) if s1 > s0 => track
                    .iter()
                    .all(|&(s, a)| (a - a0 - (a1 - a0) * (s - s0) / (s1 - s0)).abs() <= accuracy),
                _ => true,
            };
            let turn = if turn.abs() <= CLOSURE_ROUND_OFF {
                0.0
            } else {
                turn
            };
            Ok(LawTurn { turn, uniform })
        })
        .collect()
}

/// Largest angle between the frames built and the law, each piece's offset at its start
/// taken off (module `law`); 0 for the RMF.
fn frame_error(pieces: &[Framed], law: &FrameLaw) -> f64 {
    if *law == FrameLaw::Rmf {
        return 0.0;
    }
    let mut worst = 0.0f64;
    for framed in pieces {
        if let Some(screw) = framed.screw {
            // Measured against what the law follows along the edge where the helix was taken
            // for it.
            worst = worst.max(screw.normal_angle);
            continue;
        }
        let mut angles = Unwrapped::new(law);
        for v in grid_parameters(framed.spine.breaks(), LAW_SAMPLES) {
            let (f2, t) = match (&framed.frame, &framed.piece.geometry) {
                (PieceFrame::Constant { f2, .. }, _) => (*f2, framed.start.tangent),
                (PieceFrame::Circular { a, b }, Geometry::Arc(arc)) => {
                    circular_at(arc, *a, *b, &framed.spine, v)
                }
                (PieceFrame::Rational(frames), _) => {
                    let frame = frames.frame(v);
                    (frame.f2, frame.tangent)
                }
                _ => continue,
            };
            let jet = law_jet(given(&framed.piece), &framed.spine, v, v);
            if let Some(n) = law_normal(law, &jet) {
                angles.push(f2, n, t);
            }
        }
        // A fixed direction is followed from the wire's start on (f₂ starts on it); the
        // Frenet frame keeps the angle it has where its normal was undefined or jumped.
        worst = worst.max(match law {
            FrameLaw::Fixed(_) | FrameLaw::Guide(_) => angles.largest(),
            _ => angles.spread(),
        });
    }
    worst
}

/// How closely a frame law is followed: a quarter of the tolerance at the profile's
/// reach (the profile then lies within it of the law's sweep), between the accuracy of a
/// twist and a milliradian.
fn law_accuracy(options: &FrameOptions) -> f64 {
    (0.25 * options.tolerance / options.reach.max(f64::MIN_POSITIVE)).clamp(TWIST_ACCURACY, 1e-3)
}

/// How a piece's frame turns against the RMF.
#[derive(Clone, Copy)]
struct PieceTurn<'a> {
    /// The whole turn over the piece.
    total: f64,
    /// A frame law other than the RMF, and the part of the turn that is twist and closure
    /// (linear in arc length) on top of it.
    law: Option<(&'a FrameLaw, f64)>,
    /// How closely (radians) the frame follows the law: the tolerance at the profile's
    /// reach.
    accuracy: f64,
    /// Any adapted frame will do (a round profile, untwisted): a PH piece takes its
    /// spline's Euler–Rodrigues frame.
    lightest: bool,
}

/// The frame along one piece starting at f₂, turned by `turn.total` in total: linearly in
/// arc length, or as the frame law asks where it does not turn so (a fixed direction
/// across an arc, either law along a curve; module `law`).
fn frame_piece(
    piece: &Piece,
    spine: Spine,
    length: f64,
    f2: DVec3,
    turn: PieceTurn,
    miters: [Option<(DVec3, DVec3)>; 2],
) -> Result<Framed> {
    let geometry = &piece.geometry;
    let tangent = geometry.start_tangent();
    let f2 = orthogonalized(f2, tangent).normalize();
    let start = Frame::from_tangent_normal(tangent, f2);
    let mut angle_check = None;
    let (followed, accuracy, lightest) = (turn.law, turn.accuracy, turn.lightest);
    let turn = turn.total;
    let (frame, end, angle_error) = match (geometry, followed) {
        (_, Some((law, extra))) => {
            let frames = law_frames(piece, &spine, length, f2, law, extra, accuracy)?;
            let end = frames.frame(spine.curve.domain().1);
            (PieceFrame::Rational(frames), end, 0.0)
        }
        (geometry, _) => match geometry {
            Geometry::Line { .. } if turn == 0.0 => {
                (PieceFrame::Constant { f2, f3: start.f3 }, start, 0.0)
            }
            Geometry::Line { .. } => {
                let base = FrameNumerators {
                    e2: vec![f2; 2],
                    e3: vec![start.f3; 2],
                    d: vec![1.0; 2],
                };
                let frames = turned_frames(
                    spine.curve.breaks(),
                    &[base],
                    &|_, v| turn * v,
                    &|_, _| turn,
                    TWIST_ACCURACY,
                )?;
                let error = max_error(&frames, |v| start.rotated(turn * v));
                let end = frames.frame(1.0);
                (PieceFrame::Rational(frames), end, error)
            }
            Geometry::Arc(arc) => {
                let (a, b) = arc_coefficients(arc, f2);
                let exact = |phi: f64| {
                    let n = arc.principal_normal(phi);
                    Frame::from_tangent_normal(arc.tangent(phi), a * n + b * arc.normal)
                };
                if turn == 0.0 {
                    (PieceFrame::Circular { a, b }, exact(arc.angle), 0.0)
                } else {
                    let (frames, error) = twisted_arc(arc, &spine.curve, a, b, turn)?;
                    let end = frames.frame(1.0);
                    (PieceFrame::Rational(frames), end, error)
                }
            }
            Geometry::Curve(_) if spine.exact.is_some() => {
                let exact = spine.exact.as_ref().expect("an exact-RMF spine");
                let frames = if turn == 0.0 {
                    exact.from(f2)?
                } else {
                    // Twist and closure on the exact RMF: followed as a law would be.
                    law_frames(piece, &spine, length, f2, &FrameLaw::Rmf, turn, accuracy)?
                };
                let end = frames.frame(spine.curve.domain().1);
                (PieceFrame::Rational(frames), end, 0.0)
            }
            Geometry::Curve(_) if lightest && turn == 0.0 => {
                let ph = spine.ph.as_ref().expect("a curve piece has a PH spline");
                let frames = euler_rodrigues_frames(ph, f2)?;
                let end = frames.frame(ph.domain().1);
                (PieceFrame::Rational(frames), end, 0.0)
            }
            Geometry::Curve(_) => {
                let ph = spine.ph.as_ref().expect("a curve piece has a PH spline");
                let options = RmfOptions {
                    twist: turn,
                    ..RmfOptions::rmf(f2)
                };
                let frames = ph_rational_rmf(ph, &options)?.framed.into_parts().1;
                angle_check = Some(AngleCheck::new(ph, &frames)?);
                let end = frames.frame(ph.domain().1);
                (PieceFrame::Rational(frames), end, 0.0)
            }
        },
    };
    let Spine {
        curve: spine,
        distance,
        screw,
        ..
    } = spine;
    Ok(Framed {
        piece: piece.clone(),
        spine,
        frame,
        start,
        end,
        length,
        distance,
        screw,
        angle_error,
        angle_check,
        miters,
    })
}

/// The frames a law is followed from along a PH spline: where the law sets f₂ itself
/// (Frenet, a fixed direction), the spline's own rational Frenet frames (degree 2, Farouki's
/// (19): a PH cubic's Frenet frame is rational), each segment turned to continue the
/// previous one from f₂ — the law is then close to them, often a constant turn away (a
/// helix's screw motion, its axis); otherwise (a twist on the RMF) its rational RMF.
fn law_base(ph: &PhSpline, f2: DVec3, law: &FrameLaw) -> Result<RationalFrames> {
    if matches!(law, FrameLaw::Frenet | FrameLaw::Fixed(_)) {
        // A straight segment has no Frenet frame: the RMF serves.
        if let Ok(frenet) = ph_frenet_frames(ph) {
            let frames = frenet.into_parts().1;
            return RationalFrames::chained(
                frames.segments().to_vec(),
                frames.breaks().to_vec(),
                f2,
            );
        }
    }
    Ok(ph_rational_rmf(ph, &RmfOptions::rmf(f2))?
        .framed
        .into_parts()
        .1)
}

/// Rational frames along a piece that follow a frame law: its RMF (exact on an arc, the
/// PH spline's rational RMF on a curve) turned by 2 arctan W fitted to the law's angle
/// against it, plus `extra` (twist and closure) linear in arc length — within
/// [`TWIST_ACCURACY`] of the law, exact at the ends of every piece of W.
fn law_frames(
    piece: &Piece,
    spine: &Spine,
    length: f64,
    f2: DVec3,
    law: &FrameLaw,
    extra: f64,
    accuracy: f64,
) -> Result<RationalFrames> {
    // The RMF as rational frames on the spine's parameter, and the arc length at v.
    let (base, arc_length): (RationalFrames, Box<dyn Fn(f64) -> f64 + '_>) =
        match (&piece.geometry, &spine.ph) {
            (Geometry::Arc(arc), _) => {
                let (a, b) = arc_coefficients(arc, f2);
                let segments = spine
                    .curve
                    .segments()
                    .iter()
                    .map(|s| {
                        let n = arc_numerators(arc, s, a, b);
                        RationalFrameSegment::new(n.e2, n.e3, n.d)
                    })
                    .collect::<Result<Vec<_>>>()?;
                let frames = RationalFrames::new(segments, spine.curve.breaks().to_vec())?;
                let start = arc.start - arc.center;
                let (center, normal, radius) = (arc.center, arc.normal, arc.radius);
                let curve = spine.curve.clone();
                let angle = arc.angle;
                (
                    frames,
                    Box::new(move |v| {
                        let p = curve.eval(v) - center;
                        // Past a half turn signed_angle is negative; at the start, rounding.
                        let phi = signed_angle(start, p, normal);
                        let phi = if phi < -1e-6 { phi + TAU } else { phi.max(0.0) };
                        radius * phi.min(angle)
                    }),
                )
            }
            (Geometry::Line { .. }, _) => {
                let f3 = Frame::from_tangent_normal(piece.geometry.start_tangent(), f2).f3;
                let segments = spine
                    .curve
                    .segments()
                    .iter()
                    .map(|_| RationalFrameSegment::new(vec![f2; 2], vec![f3; 2], vec![1.0; 2]))
                    .collect::<Result<Vec<_>>>()?;
                let frames = RationalFrames::new(segments, spine.curve.breaks().to_vec())?;
                let (lo, hi) = spine.curve.domain();
                (frames, Box::new(move |v| length * (v - lo) / (hi - lo)))
            }
            (_, Some(ph)) => {
                let exact = ExactRmf::new(ph, f2, 0.0)?;
                (
                    law_base(ph, f2, law)?,
                    Box::new(move |v| exact.arc_length_at(v)),
                )
            }
            (_, None) if spine.exact.is_some() => {
                let exact = spine.exact.as_ref().expect("an exact-RMF spine");
                (exact.from(f2)?, Box::new(|v| exact.arc_length_at(v)))
            }
            _ => return invalid!("internal: a frame law on {}", piece.geometry.kind_name()),
        };
    let given = given(piece);
    // The raw angle at v, the law read on the side of `inside`.
    let raw_in = |v: f64, inside: f64| {
        let frame = base.frame(v);
        law_normal(law, &law_jet(given, &spine.curve, v, inside))
            .map(|n| signed_angle(frame.f2, n, frame.tangent))
    };
    let raw = |v: f64| raw_in(v, v);
    let target = LawAngle::new(law, base.breaks(), &raw);
    let breaks = base.breaks().to_vec();
    // The law on segment k, read on its own side of its ends.
    let on = |k: usize, v: f64| {
        let inside = lerp(breaks[k], breaks[k + 1], 0.5);
        target.at(v, &|v| raw_in(v, inside))
    };
    // Where the law's normal jumps at a break (the curve as given is only G1 there), both
    // sides meet at the mean and the jump is spread linearly over each side's segment, so
    // that the frames stay continuous.
    let last = breaks.len() - 2;
    // The law at both ends of each segment, read once.
    let ends: Vec<(f64, f64)> = (0..=last)
        .map(|k| (on(k, breaks[k]), on(k, breaks[k + 1])))
        .collect();
    let joints: Vec<f64> = (0..breaks.len())
        .map(|j| match j {
            0 => ends[0].0,
            j if j > last => ends[last].1,
            j => 0.5 * (ends[j - 1].1 + ends[j].0),
        })
        .collect();
    // Each segment's offsets from the joints at its ends, spread linearly over it.
    let spread: Vec<(f64, f64)> = ends
        .iter()
        .enumerate()
        .map(|(k, &(start, end))| (start - joints[k], end - joints[k + 1]))
        .collect();
    let angle = |k: usize, s: f64| {
        let v = lerp(breaks[k], breaks[k + 1], s);
        let (d0, d1) = spread[k];
        on(k, v) - lerp(d0, d1, s) + extra * arc_length(v) / length
    };
    const STEP: f64 = 1e-3;
    let rate = |k: usize, s: f64| {
        let (s0, s1) = ((s - STEP).max(0.0), (s + STEP).min(1.0));
        (angle(k, s1) - angle(k, s0)) / (s1 - s0)
    };
    let bases: Vec<FrameNumerators> = base
        .segments()
        .iter()
        .map(|s| FrameNumerators {
            e2: s.f2_numerator().to_vec(),
            e3: s.f3_numerator().to_vec(),
            d: s.denominator().to_vec(),
        })
        .collect();
    turned_frames(&breaks, &bases, &angle, &rate, accuracy).map_err(|e| match law.name() {
        // Twist and closure on the RMF: the twist's own message.
        None => e,
        Some(name) => crate::error::Error::invalid_input(format!(
            "frame: the {name} frame cannot be followed along {}: {} (does it jump?)",
            piece.name(),
            e.reason().trim_start_matches("twist: ")
        )),
    })
}

/// Rational frames along an arc (its segments on k/n), the RMF f₂ = aN + bB turned by
/// `turn` linearly in arc length; with the largest angle to that target.
fn twisted_arc(
    arc: &Arc,
    spine: &PiecewiseCurve,
    a: f64,
    b: f64,
    turn: f64,
) -> Result<(RationalFrames, f64)> {
    let n = spine.segments().len();
    let bases: Vec<FrameNumerators> = spine
        .segments()
        .iter()
        .map(|s| arc_numerators(arc, s, a, b))
        .collect();
    let step = arc.angle / n as f64;
    let phi = |k: usize, s: f64| {
        let p = spine.segments()[k].eval(s) - arc.center;
        k as f64 * step + signed_angle(arc.point(k as f64 * step) - arc.center, p, arc.normal)
    };
    let per_angle = turn / arc.angle;
    let angle = |k: usize, s: f64| per_angle * phi(k, s);
    let rate =
        |k: usize, s: f64| per_angle * spine.segments()[k].eval_jet(s).d1.length() / arc.radius;
    let frames = turned_frames(spine.breaks(), &bases, &angle, &rate, TWIST_ACCURACY)?;
    let target = |v: f64| {
        let (k, s) = spine.locate(v);
        let p = phi(k, s);
        let nrm = arc.principal_normal(p);
        Frame::from_tangent_normal(arc.tangent(p), a * nrm + b * arc.normal).rotated(per_angle * p)
    };
    let error = max_error(&frames, target);
    Ok((frames, error))
}

/// The arc's RMF numerators on one of its rational quadratic segments: with the segment's
/// homogeneous points (w P, w), N = (w c − w P)/R, F₂ = aN + b w B, F₃ = a w B − b N, over w.
pub(crate) fn arc_numerators(
    arc: &Arc,
    segment: &RationalBezierCurve,
    a: f64,
    b: f64,
) -> FrameNumerators {
    let h = segment.homogeneous();
    let normals: Vec<DVec3> = h
        .iter()
        .map(|p| (arc.center * p.w - p.truncate()) / arc.radius)
        .collect();
    FrameNumerators {
        e2: normals
            .iter()
            .zip(h)
            .map(|(&nrm, p)| a * nrm + b * p.w * arc.normal)
            .collect(),
        e3: normals
            .iter()
            .zip(h)
            .map(|(&nrm, p)| a * p.w * arc.normal - b * nrm)
            .collect(),
        d: h.iter().map(|p| p.w).collect(),
    }
}

/// Largest angle between the frames and a target frame along [0, 1].
fn max_error(frames: &RationalFrames, target: impl Fn(f64) -> Frame) -> f64 {
    let breaks = frames.breaks();
    let (lo, hi) = (breaks[0], breaks[breaks.len() - 1]);
    let samples = ERROR_SAMPLES * frames.segments().len();
    (0..=samples)
        .map(|i| lo + (hi - lo) * i as f64 / samples as f64)
        .map(|v| angle_about_tangent(&target(v), &frames.frame(v)).abs())
        .fold(0.0, f64::max)
}

/// The base frames of the segments (numerators on [0, 1] each) turned by 2 arctan W ≈ the
/// target `angle(k, s)`, W of the family (37) fitted to the rate `rate(k, s)` (local
/// parameter), on pieces halved until 2 arctan W is within [`TWIST_ACCURACY`] of the target
/// (and turns by at most π/2); exact at the ends of every piece.
fn turned_frames(
    breaks: &[f64],
    bases: &[FrameNumerators],
    angle: &dyn Fn(usize, f64) -> f64,
    rate: &dyn Fn(usize, f64) -> f64,
    accuracy: f64,
) -> Result<RationalFrames> {
    let mut pieces = FramePieces::new(breaks);
    for (k, base) in bases.iter().enumerate() {
        let mut parts = Vec::new();
        let fit = Fit {
            angle: &|s| angle(k, s),
            rate: &|s| rate(k, s),
            accuracy,
        };
        fit_parts(&fit, 0.0, 1.0, 0, &mut parts)?;
        for (v0, v1, w) in parts {
            let (g0, g1) = (angle(k, v0), angle(k, v1));
            // A constant W is a constant turn: the base keeps its degree.
            let constant = w.numerator.iter().all(|&n| n == w.numerator[0])
                && w.denominator.iter().all(|&d| d == w.denominator[0]);
            let (turned, turn) = if constant {
                let w0 = w.numerator[0] / w.denominator[0];
                (base.restricted(v0, v1), 2.0 * w0.atan())
            } else {
                let turned = base.restricted(v0, v1).turned(&w.numerator, &w.denominator);
                (turned, 0.0)
            };
            let mut segments = turned.positive_pieces()?;
            for (_, _, segment) in segments.iter_mut() {
                segment.rotate(0.5 * (g0 + g1) + turn);
            }
            pieces.push_all(k, v0, v1, segments);
        }
    }
    pieces.into_frames()
}

/// Largest angle (radians) between a twisted line's or arc's rational frame and its target.
const TWIST_ACCURACY: f64 = 1e-10;

/// A target angle (local parameter), its rate, and how closely W must follow it.
#[derive(Clone, Copy)]
struct Fit<'a> {
    angle: &'a dyn Fn(f64) -> f64,
    rate: &'a dyn Fn(f64) -> f64,
    accuracy: f64,
}

/// The W of the part [a, b] (the target angle less its mean there, over 2), halved while it
/// turns by more than π/2 or misses the target by more than [`TWIST_ACCURACY`] (sampled).
fn fit_parts(
    fit_to: &Fit,
    a: f64,
    b: f64,
    depth: usize,
    out: &mut Vec<(f64, f64, Biquadratic)>,
) -> Result<()> {
    let Fit {
        angle,
        rate,
        accuracy,
    } = *fit_to;
    let (g0, g1) = (angle(a), angle(b));
    let turns_too_much = (g1 - g0).abs() > FRAC_PI_2;
    // W = tan of a quarter of the turn: past a turn of 2π its ends change sign and the data
    // are no longer monotone, so a long turn is halved before any fit.
    if turns_too_much {
        if depth == MAX_HALVINGS {
            return invalid!(
                "twist: the frame would turn by {:.3e} rad on 2^-{MAX_HALVINGS} of one edge; \
                 at most {:.3e} rad per edge can be carried",
                g1 - g0,
                FRAC_PI_2 * (1u64 << MAX_HALVINGS) as f64
            );
        }
        let m = 0.5 * (a + b);
        fit_parts(fit_to, a, m, depth + 1, out)?;
        return fit_parts(fit_to, m, b, depth + 1, out);
    }
    let mid = 0.5 * (g0 + g1);
    let length = b - a;
    let local = |u: f64| rate(a + u * length) * length;
    let quarter = 0.25 * (g1 - g0);
    let (w0, w1) = (-quarter.tan(), quarter.tan());
    // An end slope against the turn (a target that is flat there, up to rounding, or turns
    // back) is taken as 0: the data stay monotone, and the miss decides on halving.
    let direction = (g1 - g0).signum();
    let slope = |w: f64, r: f64| {
        let s = 0.5 * (1.0 + w * w) * r;
        if g1 == g0 || s * direction < 0.0 {
            0.0
        } else {
            s
        }
    };
    let data = AngleHermite {
        w0,
        w1,
        s0: slope(w0, local(0.0)),
        s1: slope(w1, local(1.0)),
    };
    let w = fit(data, local)?.w;
    let miss = (1..ERROR_SAMPLES)
        .map(|i| i as f64 / ERROR_SAMPLES as f64)
        .map(|u| (2.0 * w.eval(u).atan() + mid - angle(a + u * length)).abs())
        .fold(0.0, f64::max);
    if miss > accuracy && depth < MAX_HALVINGS {
        let m = 0.5 * (a + b);
        fit_parts(fit_to, a, m, depth + 1, out)?;
        return fit_parts(fit_to, m, b, depth + 1, out);
    }
    out.push((a, b, w));
    Ok(())
}

/// Directions of arcs whose support function [`singularity_margin`] keeps.
const REACH_CACHE: usize = 8;

/// The fold check of a sweep (Cor. 7): the least singularity margin where it was measured,
/// and the curve pieces known not to fold from the sufficient bound 1 − κ_max·max‖c‖ > 0,
/// whose margin is measured when asked for ([`Margins::least`]: the report's figure).
#[derive(Clone, Debug)]
pub(crate) struct Margins {
    measured: f64,
    /// The spines and frames of the curve pieces not measured yet.
    deferred: Vec<(PiecewiseCurve, RationalFrames)>,
    /// The profile's segments, as the analysis takes them.
    chain: PiecewiseCurve,
}

impl Margins {
    /// Margins measured while building, the least `least`.
    pub(super) fn measured(least: f64, chain: PiecewiseCurve) -> Self {
        Self {
            measured: least,
            deferred: Vec::new(),
            chain,
        }
    }

    /// The least singularity margin of the sweep.
    pub(super) fn least(&self) -> f64 {
        self.deferred
            .iter()
            .map(|(spine, frames)| {
                ProfileSurface::with_adapted_frames(spine, frames, &self.chain)
                    .expect("checked while building")
                    .least_margin()
                    .0
            })
            .fold(self.measured, f64::min)
    }
}

/// The singularity margin along a helix swept by its screw motion: 1 − κ h, h the
/// profile's reach towards the axis (along the principal normal), the same all along.
fn screw_margin(framed: &Framed, screw: Screw, table: &SupportTable, unit: f64) -> Result<f64> {
    let d = DVec2::new(
        framed.start.f2.dot(screw.normal),
        framed.start.f3.dot(screw.normal),
    );
    let reach = table.support(d);
    let margin = 1.0 - screw.curvature * reach;
    if margin <= 0.0 {
        return invalid!(
            "edge {}: the profile reaches {:.6} towards the helix's axis, past its centre of \
             curvature at {:.6} (singularity margin g = {:.3e}, Mäurer & Jüttler Cor. 7): the \
             sweep would fold",
            framed.piece.edge,
            reach * unit,
            unit / screw.curvature,
            margin
        );
    }
    Ok(margin)
}

/// The fold check of the sweep (Cor. 7; see the module notes): its margins, or the
/// refusal naming the edge or joint where the profile reaches past the centre of
/// curvature. `unit` converts lengths to the caller's units for messages.
pub(crate) fn singularity_margin(
    transport: &Transport,
    profile: &Profile,
    unit: f64,
) -> Result<Margins> {
    let mut least = 1.0f64;
    let mut deferred = Vec::new();
    // The support function in every arc's and miter's direction, from one preparation.
    let table = profile.support_table();
    // Curve pieces scan the whole profile at once: one spine evaluation per sample.
    let chain = profile.segment_chain();
    // Arcs of a wire often share their direction (axis-aligned routes): the support
    // function of the last few directions met, by their exact bits.
    let mut reaches: Vec<([u64; 2], f64)> = Vec::with_capacity(REACH_CACHE);
    for framed in &transport.pieces {
        let piece = &framed.piece;
        let margin = match (&piece.geometry, &framed.frame, framed.screw) {
            (_, _, Some(screw)) => screw_margin(framed, screw, &table, unit)?,
            (Geometry::Line { .. }, PieceFrame::Constant { f2, f3 }, _) => {
                miter_margin(framed, *f2, *f3, &table, unit)?
            }
            (Geometry::Line { .. }, _, _) => 1.0,
            (Geometry::Arc(arc), PieceFrame::Circular { a, b }, _) => {
                let d = DVec2::new(*a, -*b);
                let key = [d.x.to_bits(), d.y.to_bits()];
                let reach = match reaches.iter().find(|(k, _)| *k == key) {
                    Some(&(_, reach)) => reach,
                    None => {
                        let reach = table.support(d);
                        if reaches.len() == REACH_CACHE {
                            reaches.remove(0);
                        }
                        reaches.push((key, reach));
                        reach
                    }
                };
                let margin = 1.0 - reach / arc.radius;
                if margin <= 0.0 {
                    return Err(fold_at_arc(piece, arc.radius, reach, unit));
                }
                margin
            }
            (_, PieceFrame::Rational(frames), _) => {
                let analysis = ProfileSurface::with_adapted_frames(&framed.spine, frames, &chain)
                    .with_context(|| format!("edge {}", piece.edge))?;
                if analysis.cannot_fold() {
                    deferred.push((framed.spine.clone(), frames.clone()));
                    continue;
                }
                let (margin, _, v) = analysis.least_margin();
                if margin <= 0.0 {
                    if let Geometry::Arc(arc) = &piece.geometry {
                        let reach = arc.radius * (1.0 - margin);
                        return Err(fold_at_arc(piece, arc.radius, reach, unit));
                    }
                    return invalid!(
                        "edge {}: the profile reaches past the spine's centre of curvature \
                         near its parameter {:.6} (singularity margin g = {:.3e}, Mäurer & \
                         Jüttler Cor. 7): the sweep would fold; the profile may be at most \
                         {:.6} times as large there",
                        piece.edge,
                        v,
                        margin,
                        1.0 / (1.0 - margin)
                    );
                }
                margin
            }
            _ => 1.0,
        };
        least = least.min(margin);
    }
    Ok(Margins {
        measured: least,
        deferred,
        chain,
    })
}

fn fold_at_arc(piece: &Piece, radius: f64, reach: f64, unit: f64) -> crate::Error {
    crate::Error::invalid_input(match &piece.corner {
        Some(joint) => format!(
            "{joint}: the corner radius {} is smaller than the profile's extent {} towards the \
             corner's centre: the sweep would fold (Mäurer & Jüttler Cor. 7); the smallest \
             radius allowed is {}",
            radius * unit,
            reach * unit,
            reach * unit
        ),
        None => format!(
            "edge {}: the arc's radius {} is smaller than the profile's extent {} towards its \
             centre: the sweep would fold (Mäurer & Jüttler Cor. 7); the profile may reach at \
             most {} towards the centre",
            piece.edge,
            radius * unit,
            reach * unit,
            radius * unit
        ),
    })
}

/// A straight leg cut by miter planes: the length of its shortest ruling over its length
/// (≤ 0: the cuts cross inside the profile).
fn miter_margin(
    framed: &Framed,
    f2: DVec3,
    f3: DVec3,
    table: &SupportTable,
    unit: f64,
) -> Result<f64> {
    let t = framed.start.tangent;
    // The offset along t from a section to the miter plane is c·q, q = −(f₂·m, f₃·m)/(t·m).
    let offset = |plane: Option<(DVec3, DVec3)>| {
        plane.map_or(DVec2::ZERO, |(_, m)| {
            -DVec2::new(f2.dot(m), f3.dot(m)) / t.dot(m)
        })
    };
    let g = offset(framed.miters[1]) - offset(framed.miters[0]);
    if g == DVec2::ZERO {
        return Ok(1.0);
    }
    let shortening = table.support(-g);
    let margin = 1.0 - shortening / framed.length;
    if margin <= 0.0 {
        return invalid!(
            "edge {}: the miter cuts at its ends cross inside the profile: the edge is {} long \
             but its cuts take {}; the profile may be at most {:.6} times as large",
            framed.piece.edge,
            framed.length * unit,
            shortening * unit,
            framed.length / shortening
        );
    }
    Ok(margin)
}
