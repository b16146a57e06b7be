//! The fold check of a profile drawn out of the normal plane, in its plane m·c = d (m a
//! unit vector in the frame's coordinates, x along f₂, y along f₃, z along t, m_z > 0).
//! With arc length s along the spine, the frame turning about t at the rate ω and the
//! profile scaled by σ(s), the sweep s = x + σ (c₁t + c₂f₂ + c₃f₃) moves as
//!
//!   ∂s/∂s = t (1 − κσ c⊥·N) + σ c₁ κ N + σω (c₂f₃ − c₃f₂) + σ′ c·F
//!
//! (Frenet–Serret with the RMF's f₂′ = −κ(N·f₂) t, Mäurer & Jüttler (1)). Its component
//! along the moved plane normal M is m_z − κσ c·w + σω (c₂m_y − c₃m_x) + σ′d, |w| ≤ 1, so
//!
//!   g = m_z − κ σ R − |ω| σ R |m⊥| − |σ′ d| > 0
//!
//! (R the profile's reach) keeps every point moving across the profile's plane: the sweep
//! is regular and does not fold. In the normal plane (m = z, d = 0) it is Cor. 7's
//! sufficient bound 1 − κR. κ and ω are sampled along each piece and refined about the
//! largest sample, as the analysis of Cor. 7 along curves does.

use super::edge::Geometry;
use super::frame::{Margins, PieceFrame, Transport};
use super::profile::{Profile, ProfilePlane};
use crate::bezier::PiecewiseCurve;
use crate::error::{invalid, Result};
use crate::math::minimize_bracketed;
use crate::mesh::grid_parameters;

/// Samples per segment of the spine or frames at which κ and ω are taken.
const SAMPLES: usize = 32;

/// The margins g of the module notes, or the refusal naming the piece where g ≤ 0.
/// `reach` is the profile's at its largest scale, `slope` |σ′|, `unit` converts lengths
/// to the caller's units for messages.
pub(crate) fn oblique_margin(
    transport: &Transport,
    profile: &Profile,
    plane: ProfilePlane,
    reach: f64,
    slope: f64,
    unit: f64,
) -> Result<Margins> {
    let m = plane.normal;
    let across = m.x.hypot(m.y);
    let mut least = f64::INFINITY;
    for framed in &transport.pieces {
        let kappa = match &framed.piece.geometry {
            Geometry::Line { .. } => 0.0,
            Geometry::Arc(arc) => 1.0 / arc.radius,
            Geometry::Curve(_) => largest(&framed.spine, framed.spine.breaks(), &|v| {
                let jet = framed.spine.eval_jet(v);
                jet.d1.cross(jet.d2).length() / jet.d1.length().powi(3)
            }),
        };
        let omega = match &framed.frame {
            PieceFrame::Rational(frames) => largest(&framed.spine, frames.breaks(), &|v| {
                let (f2, df2) = frames.f2_with_derivative(v);
                let frame = frames.frame(v);
                debug_assert!(f2.is_finite());
                df2.dot(frame.f3).abs() / framed.spine.eval_jet(v).d1.length()
            }),
            _ => 0.0,
        };
        let g = m.z - kappa * reach - omega * reach * across - slope * plane.offset.abs();
        if g.is_nan() || g <= 0.0 {
            return invalid!(
                "{}: the profile, drawn {:.2}° out of the normal plane, may fold the sweep \
                 there (curvature {:.3e}, the frame turning at {:.3e} rad per length, reach \
                 {:.6}: margin {g:.3e}); draw it closer to the normal plane, nearer the spine \
                 or smaller",
                framed.piece.name(),
                m.z.acos().to_degrees(),
                kappa / unit,
                omega / unit,
                reach * unit
            );
        }
        least = least.min(g);
    }
    Ok(Margins::measured(least.min(1.0), profile.segment_chain()))
}

/// The largest of f over the curve's parameters: sampled on the breaks, refined about the
/// largest sample.
fn largest(curve: &PiecewiseCurve, breaks: &[f64], f: &dyn Fn(f64) -> f64) -> f64 {
    let samples = grid_parameters(breaks, SAMPLES);
    let (i, best) = samples
        .iter()
        .map(|&v| f(v))
        .enumerate()
        .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
    let (lo, hi) = (
        samples[i.saturating_sub(1)],
        samples[(i + 1).min(samples.len() - 1)],
    );
    let (lo, hi) = (lo.max(curve.domain().0), hi.min(curve.domain().1));
    best.max(-minimize_bracketed(|v| -f(v), lo, hi, 0.0).value)
}
