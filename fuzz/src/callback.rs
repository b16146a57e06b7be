//! Analytic curves handed to the library as C callbacks: a cubic polynomial with drawn
//! coefficients, which may also misbehave as callers' code does — write NaN, write nothing,
//! or give a zero tangent.

use rmfsurf_capi::input::RmfCurveCallback;
use rmfsurf_capi::RmfVec3;
use std::ffi::c_void;
use std::ptr::null_mut;

use super::input::Input;

/// What a callback curve is: x(t) = Σ c_k t^k, and how it misbehaves.
pub struct CallbackCurve {
    coefficients: [RmfVec3; 4],
    behaviour: u8,
}

impl CallbackCurve {
    pub fn draw(input: &mut Input) -> Self {
        Self {
            coefficients: [input.vec3(), input.vec3(), input.vec3(), input.vec3()],
            behaviour: input.byte() % 8,
        }
    }

    /// The callback and its `user` pointer (valid while `self` lives), or no callback.
    pub fn as_callback(&mut self) -> (RmfCurveCallback, *mut c_void) {
        if self.behaviour == 7 {
            return (None, null_mut());
        }
        (Some(evaluate), (self as *mut Self).cast())
    }

    /// This curve as the callback argument when `used`, else no callback (the entry points
    /// take either a curve handle or a callback).
    pub fn callback_if(&mut self, used: bool) -> (RmfCurveCallback, *mut c_void) {
        if used {
            self.as_callback()
        } else {
            (None, null_mut())
        }
    }
}

unsafe extern "C" fn evaluate(
    t: f64,
    user: *mut c_void,
    point: *mut RmfVec3,
    tangent: *mut RmfVec3,
) {
    let curve = &*(user as *const CallbackCurve);
    let c = &curve.coefficients;
    let poly = |f: fn(&RmfVec3) -> f64| {
        let value = ((f(&c[3]) * t + f(&c[2])) * t + f(&c[1])) * t + f(&c[0]);
        let slope = (3.0 * f(&c[3]) * t + 2.0 * f(&c[2])) * t + f(&c[1]);
        (value, slope)
    };
    let (x, y, z) = (poly(|v| v.x), poly(|v| v.y), poly(|v| v.z));
    match curve.behaviour {
        0 => return, // writes nothing
        1 if t > 0.5 => {
            (*point).x = f64::NAN;
        }
        2 => {
            *tangent = RmfVec3::default(); // zero tangent
        }
        _ => {}
    }
    if curve.behaviour != 1 || t <= 0.5 {
        *point = RmfVec3 {
            x: x.0,
            y: y.0,
            z: z.0,
        };
    }
    if curve.behaviour != 2 {
        *tangent = RmfVec3 {
            x: x.1,
            y: y.1,
            z: z.1,
        };
    }
}
