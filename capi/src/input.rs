//! Inputs shared by the capability entry points: arrays of G1 Hermite data, and curves given
//! either as an `RmfCurve` or as a C callback for analytic curves.

use super::boundary::{invalid_arg, slice, FfiError, FfiResult};
use super::curve::RmfCurve;
use super::types::RmfVec3;
use libc::c_void;
use rmfsurf::glam::DVec3;
use rmfsurf::{hermite_sequence, Error, HermiteSegment, ParametricCurve, Result};

/// An analytic curve given by the caller: writes the point and the tangent (the derivative,
/// or any non-zero multiple of it) at parameter t into *point and *tangent. It must not
/// unwind or longjmp; it is called from the calling thread only, during the call it was
/// passed to.
pub type RmfCurveCallback = Option<
    unsafe extern "C" fn(t: f64, user: *mut c_void, point: *mut RmfVec3, tangent: *mut RmfVec3),
>;

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

/// A curve defined by a C callback on `[t_min, t_max]`.
pub(crate) struct CallbackCurve {
    callback: unsafe extern "C" fn(f64, *mut c_void, *mut RmfVec3, *mut RmfVec3),
    user: *mut c_void,
    domain: (f64, f64),
}

impl ParametricCurve for CallbackCurve {
    fn domain(&self) -> (f64, f64) {
        self.domain
    }

    fn point_derivative(&self, t: f64) -> Result<(DVec3, DVec3)> {
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
                "the callback gave a non-finite (or no) point or tangent at t = {t}"
            )));
        }
        Ok((point, tangent))
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
    Ok(CallbackCurve {
        callback,
        user,
        domain: (t_min, t_max),
    })
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
        // Property-test finding: a domain whose length overflows reached the cone splines.
        let wide = unsafe { curve_or_callback(std::ptr::null(), Some(helix), user, -1e308, 1e308) };
        assert!(wide.is_err());
        let quiet =
            unsafe { curve_or_callback(std::ptr::null(), Some(silent), user, 0.0, 1.0) }.unwrap();
        assert!(quiet.point_derivative(0.5).is_err());
        assert!(
            unsafe { curve_or_callback(std::ptr::null(), Some(helix), user, 1.0, 1.0) }.is_err()
        );
        assert!(unsafe { curve_or_callback(std::ptr::null(), None, user, 0.0, 1.0) }.is_err());
    }
}
