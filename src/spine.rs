//! A spine with rational frames along a curve by any of the methods, within a distance
//! tolerance — what a sweep along a user's curve needs, whichever paper's construction makes
//! it:
//!
//! * [`SpineMethod::PhRmf`]: the PH cubic spline within the tolerance (Mäurer & Jüttler
//!   Theorem 10) and its rational approximation of the RMF (29), (36)–(41);
//! * [`SpineMethod::Frenet`]: the same spline with its exact rational Frenet frame (for
//!   comparison, and for screw motions);
//! * [`SpineMethod::Mobius`]: Möbius images of planar PH cubics through samples of the curve
//!   (Bartoň, Jüttler & Wang), exact rational RMFs;
//! * [`SpineMethod::Rrmf`]: RRMF quintics through samples of the curve (Farouki, Giannelli &
//!   Sestini), exact rational RMFs.
//!
//! The two sampled methods interpolate the curve at equally spaced parameters, doubling
//! their number until the sampled distance is within the tolerance.

use crate::bezier::PiecewiseCurve;
use crate::curve::{uniform_parameters, ParametricCurve};
use crate::error::{invalid, Error, ErrorKind, Result};
use crate::frames::compare::nearest_parameter;
use crate::hermite::hermite_sequence;
use crate::math::check_finite;
use crate::mesh::grid_parameters;
use crate::mobius::{approximate as mobius_approximate, hermite_points as mobius_hermite_points};
use crate::model::FramedCurve;
use crate::ph_cubic::approximate::{check_g1, ph_spline_approximate};
use crate::ph_cubic::frenet::ph_frenet_frames;
use crate::ph_cubic::rational_rmf::{ph_rational_rmf, RmfOptions};
use crate::ph_cubic::spline::{ph_spline_hermite, PhSpline};
use crate::rrmf_quintic::{rrmf_spline, ShapeMeasure};
use glam::DVec3;

/// Most segments the sampled methods use to reach the tolerance.
pub const MAX_SPINE_SEGMENTS: usize = 4096;
/// η samples per RRMF segment (then refined by Brent's method).
const ETA_SAMPLES: usize = 64;
/// Points per segment at which a sampled spine's distance to the curve is measured.
const DISTANCE_SAMPLES: usize = 16;

/// How the spine and its frames are made.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SpineMethod {
    /// PH cubic spline, rational approximation of its RMF (the default).
    PhRmf,
    /// PH cubic spline, its exact rational Frenet frame (not an RMF).
    Frenet,
    /// Möbius images of planar PH cubics: exact rational RMFs.
    Mobius,
    /// RRMF quintics: exact rational RMFs.
    Rrmf,
}

impl SpineMethod {
    /// Every method, in the order of their C values.
    pub const ALL: [SpineMethod; 4] = [Self::PhRmf, Self::Frenet, Self::Mobius, Self::Rrmf];

    /// The name users write: `"ph-rmf"`, `"frenet"`, `"mobius"`, `"rrmf"`.
    pub fn name(self) -> &'static str {
        match self {
            Self::PhRmf => "ph-rmf",
            Self::Frenet => "frenet",
            Self::Mobius => "mobius",
            Self::Rrmf => "rrmf",
        }
    }

    /// The method of a name (see [`Self::name`]).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// Whether its frames are rotation-minimizing.
    pub fn is_rmf(self) -> bool {
        self != Self::Frenet
    }
}

/// A spine with its frames and its distance from the curve it follows.
#[derive(Clone, Debug)]
pub struct FramedSpine {
    /// The spine and its frames.
    pub framed: FramedCurve,
    /// The largest distance measured between the spine and the curve (0 through Hermite
    /// data, which the spine interpolates).
    pub distance: f64,
}

/// The spine within `tolerance` of `curve` (G1) with frames by `method`, f₂ at the start
/// the projection of `initial_normal` onto the normal plane (Frenet frames ignore its
/// direction, but it must be finite for every method).
pub fn framed_spine(
    curve: &PiecewiseCurve,
    method: SpineMethod,
    tolerance: f64,
    initial_normal: DVec3,
) -> Result<FramedSpine> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return invalid!("tolerance = {tolerance} must be finite and positive");
    }
    let initial_normal = check_finite(initial_normal, "initial_normal")?;
    check_g1(curve)?;
    match method {
        SpineMethod::PhRmf | SpineMethod::Frenet => {
            let fit = ph_spline_approximate(curve, curve.breaks(), tolerance)?;
            Ok(FramedSpine {
                framed: framed_ph(&fit.spline, method, initial_normal)?,
                distance: fit.max_distance,
            })
        }
        SpineMethod::Mobius | SpineMethod::Rrmf => {
            sampled_spine(curve, method, tolerance, initial_normal)
        }
    }
}

/// The spine through Hermite data (points with tangents of any length) with frames by
/// `method`: the data's PH cubic spline, Möbius curve or RRMF quintic spline.
pub fn framed_spine_through(
    points: &[DVec3],
    tangents: &[DVec3],
    method: SpineMethod,
    initial_normal: DVec3,
) -> Result<FramedCurve> {
    let initial_normal = check_finite(initial_normal, "initial_normal")?;
    match method {
        SpineMethod::PhRmf | SpineMethod::Frenet => framed_ph(
            &ph_spline_hermite(points, tangents)?,
            method,
            initial_normal,
        ),
        SpineMethod::Mobius => mobius_hermite_points(points, tangents, initial_normal),
        SpineMethod::Rrmf => Ok(rrmf_spline(
            &hermite_sequence(points, tangents)?,
            ShapeMeasure::ScaledEnergyRmf,
            ETA_SAMPLES,
            initial_normal,
        )?
        .framed),
    }
}

fn framed_ph(spline: &PhSpline, method: SpineMethod, initial_normal: DVec3) -> Result<FramedCurve> {
    if method == SpineMethod::Frenet {
        return ph_frenet_frames(spline);
    }
    Ok(ph_rational_rmf(spline, &RmfOptions::rmf(initial_normal))?.framed)
}

/// Möbius or RRMF spines through equally spaced samples, doubled until within `tolerance`.
fn sampled_spine(
    curve: &PiecewiseCurve,
    method: SpineMethod,
    tolerance: f64,
    initial_normal: DVec3,
) -> Result<FramedSpine> {
    let mut segments = curve.segments().len().max(2);
    loop {
        let params = uniform_parameters(curve.domain(), segments + 1);
        let framed = if method == SpineMethod::Mobius {
            mobius_approximate(curve, segments, initial_normal)
        } else {
            let (points, tangents) = samples(curve, &params)?;
            framed_spine_through(&points, &tangents, method, initial_normal)
        };
        // Hermite data of one sampling may admit no interpolant of the method (an RRMF
        // quintic needs a suitable η) where finer samples do: only the last word counts.
        let outcome = match framed {
            Ok(framed) => {
                let distance = distance(framed.curve(), curve, &params);
                if distance <= tolerance {
                    return Ok(FramedSpine { framed, distance });
                }
                format!("distance {distance:.3e}")
            }
            Err(e) if e.kind() == ErrorKind::NoSolution => e.to_string(),
            Err(e) => return Err(e),
        };
        if 2 * segments > MAX_SPINE_SEGMENTS {
            return Err(Error::no_solution(format!(
                "tolerance = {tolerance:e} not reached with {segments} {} segments ({outcome}); \
                 give a larger tolerance",
                method.name()
            )));
        }
        segments *= 2;
    }
}

fn samples(curve: &PiecewiseCurve, params: &[f64]) -> Result<(Vec<DVec3>, Vec<DVec3>)> {
    let pairs = params
        .iter()
        .map(|&t| curve.point_unit_tangent(t))
        .collect::<Result<Vec<_>>>()?;
    Ok(pairs.into_iter().unzip())
}

/// Largest distance from points of `spine` to `curve`, which the spine interpolates at
/// `params`. A spine segment may be a part of one sampled interval (a construction can
/// split an interval): each is compared with the part of `curve` between the samples
/// nearest its ends, widened by one interval on either side.
fn distance(spine: &PiecewiseCurve, curve: &PiecewiseCurve, params: &[f64]) -> f64 {
    let samples: Vec<DVec3> = params.iter().map(|&t| curve.eval(t)).collect();
    let nearest_sample = |p: DVec3| {
        (0..samples.len())
            .min_by(|&i, &j| samples[i].distance(p).total_cmp(&samples[j].distance(p)))
            .unwrap_or(0)
    };
    let last = params.len() - 1;
    let windows: Vec<(f64, f64)> = spine
        .segments()
        .iter()
        .map(|s| {
            let (a, b) = (nearest_sample(s.eval(0.0)), nearest_sample(s.eval(1.0)));
            let (lo, hi) = (a.min(b), a.max(b));
            (params[lo.saturating_sub(1)], params[(hi + 1).min(last)])
        })
        .collect();
    grid_parameters(spine.breaks(), DISTANCE_SAMPLES)
        .iter()
        .map(|&t| {
            let (k, _) = spine.locate(t);
            let p = spine.eval(t);
            let (lo, hi) = windows[k.min(windows.len() - 1)];
            let v = nearest_parameter(curve, p, lo, hi);
            curve.eval(v).distance(p)
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::RationalBezierCurve;
    use crate::ph_cubic::accuracy::angle_errors;

    fn cubic() -> PiecewiseCurve {
        PiecewiseCurve::with_unit_intervals(vec![RationalBezierCurve::polynomial(&[
            DVec3::ZERO,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(2.0, -1.0, 1.0),
            DVec3::new(3.0, 0.0, 2.0),
        ])
        .unwrap()])
        .unwrap()
    }

    /// The cubic B-spline of `examples/cli/nurbs_moulding_ph.json`: the sampled methods'
    /// spines have more segments than sampled intervals here (the Möbius construction
    /// splits some), and each is measured against its own part of the curve.
    #[test]
    fn spines_with_more_segments_than_samples_are_measured_against_their_part() {
        let p = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
        let poles = vec![
            p(0.0, 0.0, 0.0),
            p(1.0, 1.0, 0.0),
            p(2.0, -1.0, 1.0),
            p(3.0, 0.0, 2.0),
            p(4.0, 2.0, 1.5),
            p(5.0, 0.0, 1.0),
        ];
        let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0];
        let curve = crate::bezier::NurbsCurve::new(3, poles, None, knots)
            .unwrap()
            .to_piecewise()
            .unwrap();
        for (method, tolerance) in [
            (SpineMethod::PhRmf, 1e-4),
            (SpineMethod::Frenet, 1e-4),
            (SpineMethod::Mobius, 1e-4),
            (SpineMethod::Rrmf, 1e-2),
        ] {
            let spine = framed_spine(&curve, method, tolerance, DVec3::Z).unwrap();
            assert!(
                spine.distance <= tolerance,
                "{method:?}: {}",
                spine.distance
            );
        }
        // Some samples of this curve admit no RRMF quintic at any spacing tried: a finer
        // tolerance is refused, naming it.
        match framed_spine(&curve, SpineMethod::Rrmf, 1e-4, DVec3::Z) {
            Ok(spine) => assert!(spine.distance <= 1e-4),
            Err(e) => assert!(e.message().contains("tolerance = 1e-4"), "{e}"),
        }
    }

    #[test]
    fn a_non_finite_initial_normal_is_refused_by_every_method() {
        let (p, d) = ([DVec3::ZERO, DVec3::X], [DVec3::X, DVec3::Y]);
        for method in SpineMethod::ALL {
            for n in [
                DVec3::new(f64::NAN, 0.0, 1.0),
                DVec3::new(0.0, f64::INFINITY, 0.0),
            ] {
                let e = framed_spine(&cubic(), method, 1e-4, n).unwrap_err();
                assert!(e.message().contains("initial_normal"), "{method:?}: {e}");
                let e = framed_spine_through(&p, &d, method, n).unwrap_err();
                assert!(e.message().contains("initial_normal"), "{method:?}: {e}");
            }
        }
    }

    #[test]
    fn every_method_reaches_the_tolerance_with_frames_of_the_spine() {
        for method in SpineMethod::ALL {
            let spine = framed_spine(&cubic(), method, 1e-4, DVec3::Z).unwrap();
            assert!(spine.distance <= 1e-4, "{method:?}: {}", spine.distance);
            let (lo, hi) = spine.framed.domain();
            for i in 0..=20 {
                let t = lo + (hi - lo) * i as f64 / 20.0;
                let (_, frame) = spine.framed.eval(t);
                let tangent = spine.framed.curve().eval_jet(t).d1.normalize();
                assert!((frame.tangent - tangent).length() < 1e-8, "{method:?}");
            }
            assert_eq!(SpineMethod::from_name(method.name()), Some(method));
        }
    }

    #[test]
    fn the_ph_rmf_frames_follow_the_exact_rmf() {
        let spine = framed_spine(&cubic(), SpineMethod::PhRmf, 1e-5, DVec3::Z).unwrap();
        let ph = PhSpline::new(spine.framed.curve().clone()).unwrap();
        assert!(angle_errors(&ph, spine.framed.frames()).unwrap().max < 1e-6);
    }

    #[test]
    fn a_tolerance_out_of_reach_is_refused_naming_it() {
        let e = framed_spine(&cubic(), SpineMethod::Mobius, 1e-300, DVec3::Z).unwrap_err();
        assert!(e.message().contains("tolerance = 1e-300"), "{e}");
        let e = framed_spine(&cubic(), SpineMethod::Rrmf, 0.0, DVec3::Z).unwrap_err();
        assert!(e.message().contains("tolerance = 0"), "{e}");
    }
}
