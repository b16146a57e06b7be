//! Inputs shared by the capability entry points: arrays of G1 Hermite data, and curves given
//! either as an `RmfCurve` or as a C callback for analytic curves.

use super::boundary::{invalid_arg, slice, to_usize, FfiError, FfiResult};
use super::curve::RmfCurve;
use super::types::{RmfNurbsCurve, RmfNurbsSurface, RmfVec3};
use libc::c_void;
use rmfsurf::glam::DVec3;
use rmfsurf::numeric::{lerp, robust_length};
use rmfsurf::validate::check_nurbs_counts;
use rmfsurf::{
    hermite_sequence, Error, HermiteSegment, Num, NurbsCurve, NurbsSurface, ParametricCurve, Result,
};

/// An analytic curve given by the caller: writes the point and the tangent (the derivative,
/// or any non-zero multiple of it) at parameter t into *point and *tangent. It must not
/// unwind or longjmp; it is called from the calling thread only, during the call it was
/// passed to.
///
/// One rule for every entry point taking a callback: the multiple is found once, from the
/// callback's own points (the speed |x'| by a fourth-order difference at the middle of the
/// domain, and the orientation along increasing t), and divided out, so a tangent 1e80 or
/// 1e-85 times the derivative, or pointing backwards (a negative multiple), gives the same
/// results as the derivative itself; a tangent within 1e-6 of the derivative is taken as
/// it is. Tangents should be a constant multiple (a varying one is only its direction to
/// algorithms that differentiate it, the cone approximations). Subnormal tangents
/// (components below 2.2e-308) are refused: their direction is not resolved in double.
/// \ingroup rmf_curves
pub type RmfCurveCallback = Option<
    unsafe extern "C" fn(t: f64, user: *mut c_void, point: *mut RmfVec3, tangent: *mut RmfVec3),
>;

/// NURBS poles (`count` of them) and their optional weights (NULL: all 1), read from C
/// arrays; the shared input of curves and surfaces.
///
/// # Safety
/// `poles` and, unless NULL, `weights` point to `count` readable values.
pub(crate) unsafe fn poles_and_weights(
    poles: *const RmfVec3,
    weights: *const f64,
    count: usize,
) -> FfiResult<(Vec<DVec3>, Option<Vec<f64>>)> {
    let poles = slice(poles, count, "poles")?
        .iter()
        .map(|&p| p.into())
        .collect();
    let weights = if weights.is_null() {
        None
    } else {
        Some(slice(weights, count, "weights")?.to_vec())
    };
    Ok((poles, weights))
}

/// The Hermite segments of `count` points and tangents from C arrays.
///
/// # Safety
/// `points` and `tangents` must be NULL or point to `count` values each.
pub(crate) unsafe fn hermite_arrays(
    points: *const RmfVec3,
    tangents: *const RmfVec3,
    count: usize,
) -> FfiResult<Vec<HermiteSegment>> {
    if points.is_null() {
        return Err(FfiError::Null("points"));
    }
    if tangents.is_null() {
        return Err(FfiError::Null("tangents"));
    }
    let points: Vec<DVec3> = slice(points, count, "points")?
        .iter()
        .map(|&p| p.into())
        .collect();
    let tangents: Vec<DVec3> = slice(tangents, count, "tangents")?
        .iter()
        .map(|&t| t.into())
        .collect();
    Ok(hermite_sequence(&points, &tangents)?)
}

/// A curve defined by a C callback on `[t_min, t_max]`, its tangents divided by the
/// constant multiple of the derivative they are ([`RmfCurveCallback`]).
pub(crate) struct CallbackCurve {
    callback: unsafe extern "C" fn(f64, *mut c_void, *mut RmfVec3, *mut RmfVec3),
    user: *mut c_void,
    domain: (f64, f64),
    /// The derivative is the callback's tangent times this (±1 when it is the derivative
    /// already, up to its sign).
    factor: f64,
}

/// A tangent within this relative distance of the estimated derivative is taken as it is.
const DERIVATIVE_MATCH: f64 = 1e-6;

impl CallbackCurve {
    /// The callback on `domain` (finite, of finite length), with the multiple of its
    /// tangents found from its points (see [`RmfCurveCallback`]).
    pub(crate) fn new(
        callback: unsafe extern "C" fn(f64, *mut c_void, *mut RmfVec3, *mut RmfVec3),
        user: *mut c_void,
        domain: (f64, f64),
    ) -> Result<Self> {
        let mut curve = Self {
            callback,
            user,
            domain,
            factor: 1.0,
        };
        curve.factor = curve.derivative_factor()?;
        Ok(curve)
    }

    /// The point and tangent as the callback gives them, checked finite and not subnormal.
    fn raw(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let nan = RmfVec3 {
            x: f64::NAN,
            y: f64::NAN,
            z: f64::NAN,
        };
        let (mut point, mut tangent) = (nan, nan);
        // SAFETY: the caller promised a callback that writes two RmfVec3 and returns.
        unsafe { (self.callback)(t, self.user, &mut point, &mut tangent) };
        let (point, tangent): (DVec3, DVec3) = (point.into(), tangent.into());
        if !point.is_finite() || !tangent.is_finite() {
            return Err(Error::invalid_input(format!(
                "the callback gave a non-finite (or no) point or tangent at t = {}",
                Num(t)
            )));
        }
        let largest = tangent.abs().max_element();
        if largest != 0.0 && !largest.is_normal() {
            return Err(Error::invalid_input(format!(
                "the callback's tangent at t = {} is subnormal (largest component {}, below \
                 2.2e-308): its direction is not resolved in double precision; give a larger \
                 multiple of the derivative",
                Num(t),
                Num(largest)
            )));
        }
        Ok((point, tangent))
    }

    /// The factor from the callback's tangents to the derivative: at the first of a few
    /// parameters where the tangent and the points' difference are usable, the speed from
    /// a fourth-order central difference of the points over the tangent's length, signed by
    /// their orientation.
    fn derivative_factor(&self) -> Result<f64> {
        let (lo, hi) = self.domain;
        for fraction in [0.5, 0.25, 0.75, 0.125, 0.875] {
            let t = lerp(lo, hi, fraction);
            let (_, tangent) = self.raw(t)?;
            let h = (1e-3 * (hi - lo)).max(4.0 * f64::EPSILON * t.abs());
            let points =
                [-2.0, -1.0, 1.0, 2.0].map(|k| self.raw((t + k * h).clamp(lo, hi)).map(|(p, _)| p));
            let [a, b, c, d] = match points {
                [Ok(a), Ok(b), Ok(c), Ok(d)] => [a, b, c, d],
                _ => continue,
            };
            // (−x(t+2h) + 8x(t+h) − 8x(t−h) + x(t−2h)) / 12h, the differences first.
            let difference = (c - b) * (8.0 / 12.0) - (d - a) * (1.0 / 12.0);
            let (length, along) = (robust_length(tangent), robust_length(difference));
            if length == 0.0 || along == 0.0 {
                continue;
            }
            let sign = if tangent.dot(difference) < 0.0 {
                -1.0
            } else {
                1.0
            };
            let speed = along / h;
            let ratio = length / speed;
            if !(ratio.is_finite() && ratio > 0.0) {
                continue;
            }
            if (ratio - 1.0).abs() <= DERIVATIVE_MATCH {
                return Ok(sign);
            }
            return Ok(sign * (speed / length));
        }
        Err(Error::invalid_input(
            "the callback gives zero tangents or constant points at t_min + (0.125 … 0.875)·(t_max − t_min): \
             it describes no regular curve",
        ))
    }
}

impl ParametricCurve for CallbackCurve {
    fn domain(&self) -> (f64, f64) {
        self.domain
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
        let (point, tangent) = self.raw(t)?;
        let derivative = tangent * self.factor;
        if !derivative.is_finite() {
            return Err(Error::invalid_input(format!(
                "the callback's tangent at t = {} is {} times the one at the middle of the \
                 domain: beyond the range of double as a derivative",
                Num(t),
                Num(robust_length(tangent) / (1.0 / self.factor.abs()))
            )));
        }
        Ok((point, derivative))
    }
}

// SAFETY: the C contract of rmf_callback_curve_create: a callback curve may be used from the
// threads its callback may be called from; the library calls it only during calls that use
// the curve.
unsafe impl Send for CallbackCurve {}
unsafe impl Sync for CallbackCurve {}

/// A callback curve on `[t_min, t_max]` (finite, t_min < t_max, of finite length).
pub(crate) fn callback_curve(
    callback: unsafe extern "C" fn(f64, *mut c_void, *mut RmfVec3, *mut RmfVec3),
    user: *mut c_void,
    t_min: f64,
    t_max: f64,
) -> FfiResult<CallbackCurve> {
    if !(t_max - t_min).is_finite() || t_min >= t_max {
        return invalid_arg(format!(
            "t_min = {t_min}, t_max = {t_max} must be finite with t_min < t_max and \
             t_max − t_min finite"
        ));
    }
    Ok(CallbackCurve::new(callback, user, (t_min, t_max))?)
}

/// The curve to approximate: exactly one of `curve` (its whole domain; a rational or a
/// callback curve) and `callback` (on `[t_min, t_max]`) must be given.
///
/// # Safety
/// `curve` must be NULL or a valid handle; `callback` and `user` as documented for
/// [`RmfCurveCallback`].
pub(crate) unsafe fn curve_or_callback<'a>(
    curve: *const RmfCurve,
    callback: RmfCurveCallback,
    user: *mut c_void,
    t_min: f64,
    t_max: f64,
) -> FfiResult<Box<dyn ParametricCurve + 'a>> {
    match (curve.is_null(), callback) {
        (false, None) => Ok((*curve).sampled()),
        (true, Some(callback)) => Ok(Box::new(callback_curve(callback, user, t_min, t_max)?)),
        (true, None) => Err(FfiError::Null("curve and callback")),
        (false, Some(_)) => invalid_arg("give either curve or callback, not both".to_string()),
    }
}

/// A NURBS surface from caller arrays, every count checked before an array is read.
///
/// # Safety
/// The pointers are NULL or valid for the counts given.
pub(crate) unsafe fn nurbs_surface(
    degree_u: u32,
    degree_v: u32,
    poles: *const RmfVec3,
    weights: *const f64,
    (pole_count_u, pole_count_v): (usize, usize),
    (knots_u, knot_count_u): (*const f64, usize),
    (knots_v, knot_count_v): (*const f64, usize),
) -> FfiResult<NurbsSurface> {
    for (p, name) in [
        (poles.cast::<u8>(), "poles"),
        (knots_u.cast(), "knots_u"),
        (knots_v.cast(), "knots_v"),
    ] {
        if p.is_null() {
            return Err(FfiError::Null(name));
        }
    }
    check_nurbs_counts(to_usize(degree_u), pole_count_u, knot_count_u, "_u")?;
    check_nurbs_counts(to_usize(degree_v), pole_count_v, knot_count_v, "_v")?;
    let Some(count) = pole_count_u.checked_mul(pole_count_v) else {
        return invalid_arg(format!(
            "pole_count_u × pole_count_v = {pole_count_u} × {pole_count_v} overflows"
        ));
    };
    let (poles, weights) = poles_and_weights(poles, weights, count)?;
    let knots_u = slice(knots_u, knot_count_u, "knots_u")?.to_vec();
    let knots_v = slice(knots_v, knot_count_v, "knots_v")?.to_vec();
    Ok(NurbsSurface::new(
        to_usize(degree_u),
        to_usize(degree_v),
        pole_count_u,
        pole_count_v,
        poles,
        weights,
        knots_u,
        knots_v,
    )?)
}

/// A NURBS curve from caller arrays, every count checked before an array is read.
///
/// # Safety
/// The pointers are NULL or valid for the counts given.
pub(crate) unsafe fn nurbs_curve(
    degree: u32,
    poles: *const RmfVec3,
    weights: *const f64,
    pole_count: usize,
    knots: *const f64,
    knot_count: usize,
) -> FfiResult<NurbsCurve> {
    if poles.is_null() {
        return Err(FfiError::Null("poles"));
    }
    if knots.is_null() {
        return Err(FfiError::Null("knots"));
    }
    check_nurbs_counts(to_usize(degree), pole_count, knot_count, "")?;
    let (poles, weights) = poles_and_weights(poles, weights, pole_count)?;
    let knots = slice(knots, knot_count, "knots")?.to_vec();
    Ok(NurbsCurve::new(to_usize(degree), poles, weights, knots)?)
}

impl RmfNurbsCurve {
    /// The curve this view describes (the caller's arrays, checked).
    ///
    /// # Safety
    /// The view's pointers are NULL or valid for its counts.
    pub(crate) unsafe fn read(&self) -> FfiResult<NurbsCurve> {
        nurbs_curve(
            self.degree,
            self.poles,
            self.weights,
            self.pole_count,
            self.knots,
            self.knot_count,
        )
    }
}

impl RmfNurbsSurface {
    /// The surface this view describes (the caller's arrays, checked).
    ///
    /// # Safety
    /// The view's pointers are NULL or valid for its counts.
    pub(crate) unsafe fn read(&self) -> FfiResult<NurbsSurface> {
        nurbs_surface(
            self.degree_u,
            self.degree_v,
            self.poles,
            self.weights,
            (self.pole_count_u, self.pole_count_v),
            (self.knots_u, self.knot_count_u),
            (self.knots_v, self.knot_count_v),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    unsafe extern "C" fn helix(
        t: f64,
        user: *mut c_void,
        point: *mut RmfVec3,
        tangent: *mut RmfVec3,
    ) {
        let pitch = *(user as *const f64);
        *point = RmfVec3 {
            x: t.cos(),
            y: t.sin(),
            z: pitch * t,
        };
        *tangent = RmfVec3 {
            x: -t.sin(),
            y: t.cos(),
            z: pitch,
        };
    }

    unsafe extern "C" fn silent(_: f64, _: *mut c_void, _: *mut RmfVec3, _: *mut RmfVec3) {}

    #[test]
    fn callback_curves_are_sampled_and_checked() {
        let mut pitch = 0.5f64;
        let user = (&mut pitch as *mut f64).cast();
        let curve =
            unsafe { curve_or_callback(std::ptr::null(), Some(helix), user, 0.0, 3.0) }.unwrap();
        assert_eq!(curve.domain(), (0.0, 3.0));
        let (p, t) = curve.point_unit_tangent(1.0).unwrap();
        assert!((p - DVec3::new(1f64.cos(), 1f64.sin(), 0.5)).length() < 1e-15);
        assert!((t.length() - 1.0).abs() < 1e-15);
        // A domain whose length overflows is refused here, before it reaches the cone
        // splines (which step in fractions of its length).
        let wide = unsafe { curve_or_callback(std::ptr::null(), Some(helix), user, -1e308, 1e308) };
        assert!(wide.is_err());
        // A callback that writes nothing is refused when its multiple is sought.
        let quiet = unsafe { curve_or_callback(std::ptr::null(), Some(silent), user, 0.0, 1.0) };
        assert!(quiet.is_err());
        assert!(
            unsafe { curve_or_callback(std::ptr::null(), Some(helix), user, 1.0, 1.0) }.is_err()
        );
        assert!(unsafe { curve_or_callback(std::ptr::null(), None, user, 0.0, 1.0) }.is_err());
    }
}
