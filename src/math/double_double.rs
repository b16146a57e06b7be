//! Double-double arithmetic (a value as an unevaluated sum hi + lo of two doubles, about 106
//! bits): for the few quantities whose doubles cancel catastrophically although the data
//! determine them well — the sphere touching two nearly parallel tangents (Möbius maps of
//! densely sampled curves), where Y = c₀ t₁ × e + c₁ t₀ × e is 1e-10 of its terms.
//! Error-free transformations: Knuth's two-sum and the fused-multiply-add two-product.

use glam::DVec3;
use std::ops::{Add, Mul, Neg, Sub};

/// hi + lo with |lo| ≤ ulp(hi)/2.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct DoubleDouble {
    hi: f64,
    lo: f64,
}

impl DoubleDouble {
    /// The value rounded to a double.
    pub(crate) fn value(self) -> f64 {
        self.hi + self.lo
    }
}

impl From<f64> for DoubleDouble {
    fn from(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }
}

/// a + b = s + e exactly.
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let v = s - a;
    (s, (a - (s - v)) + (b - v))
}

/// a·b = p + e exactly.
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Add for DoubleDouble {
    type Output = Self;
    fn add(self, other: Self) -> Self {
        let (s, e) = two_sum(self.hi, other.hi);
        let (hi, lo) = two_sum(s, e + self.lo + other.lo);
        Self { hi, lo }
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    fn neg(self) -> Self {
        Self {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for DoubleDouble {
    type Output = Self;
    fn sub(self, other: Self) -> Self {
        self + -other
    }
}

impl Mul for DoubleDouble {
    type Output = Self;
    fn mul(self, other: Self) -> Self {
        let (p, e) = two_product(self.hi, other.hi);
        let (hi, lo) = two_sum(p, e + self.hi * other.lo + self.lo * other.hi);
        Self { hi, lo }
    }
}

/// A vector of double-doubles.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct DoubleDoubleVec3(pub [DoubleDouble; 3]);

impl DoubleDoubleVec3 {
    pub(crate) fn dot(self, other: Self) -> DoubleDouble {
        let [a, b, c] = self.0;
        let [x, y, z] = other.0;
        a * x + b * y + c * z
    }

    pub(crate) fn cross(self, other: Self) -> Self {
        let [a, b, c] = self.0;
        let [x, y, z] = other.0;
        Self([b * z - c * y, c * x - a * z, a * y - b * x])
    }

    pub(crate) fn scaled(self, k: DoubleDouble) -> Self {
        Self(self.0.map(|c| c * k))
    }

    /// Rounded to doubles.
    pub(crate) fn value(self) -> DVec3 {
        DVec3::from_array(self.0.map(DoubleDouble::value))
    }
}

impl From<DVec3> for DoubleDoubleVec3 {
    fn from(v: DVec3) -> Self {
        Self(v.to_array().map(DoubleDouble::from))
    }
}

impl Add for DoubleDoubleVec3 {
    type Output = Self;
    fn add(self, other: Self) -> Self {
        Self([0, 1, 2].map(|i| self.0[i] + other.0[i]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_what_doubles_cancel() {
        // (1 + 2⁻⁴⁰)² − 1 − 2⁻³⁹ = 2⁻⁸⁰: all of it is lost in doubles.
        let x = DoubleDouble::from(1.0 + 2f64.powi(-40));
        let r = x * x - DoubleDouble::from(1.0) - DoubleDouble::from(2f64.powi(-39));
        assert_eq!(r.value(), 2f64.powi(-80));
        // (1 + 2⁻³⁰, 1, 0)·(1 − 2⁻³⁰, −1, 0) = −2⁻⁶⁰; in doubles the product rounds to 1 − 1 = 0.
        let e = 2f64.powi(-30);
        let a = DoubleDoubleVec3::from(DVec3::new(1.0 + e, 1.0, 0.0));
        let b = DoubleDoubleVec3::from(DVec3::new(1.0 - e, -1.0, 0.0));
        assert_eq!(a.dot(b).value(), -2f64.powi(-60));
        // (x, 1, 0) × (1, x, 0) = (0, 0, x² − 1).
        let x = DoubleDouble::from(1.0 + e);
        let c = DoubleDoubleVec3([x, 1.0.into(), 0.0.into()]).cross(DoubleDoubleVec3([
            1.0.into(),
            x,
            0.0.into(),
        ]));
        assert_eq!(c.0[2].value(), 2.0 * e + e * e);
    }
}
