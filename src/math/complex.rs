//! Complex numbers: the Hopf-map model of spatial Pythagorean-hodograph curves writes a
//! hodograph with two complex polynomials α(t), β(t) (Farouki, Giannelli & Sestini,
//! eqs. (2)–(3)), and the RRMF quintic construction works with complex coefficients
//! throughout. Only the operations those algorithms need are here.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// A complex number `re + i·im`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Complex {
    /// The real part.
    pub re: f64,
    /// The imaginary part.
    pub im: f64,
}

impl Complex {
    /// 0.
    pub const ZERO: Complex = Complex::new(0.0, 0.0);
    /// 1.
    pub const ONE: Complex = Complex::new(1.0, 0.0);
    /// The imaginary unit i.
    pub const I: Complex = Complex::new(0.0, 1.0);

    /// re + i·im.
    pub const fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }

    /// `exp(i·angle)`, the unit complex number at that angle.
    pub fn cis(angle: f64) -> Self {
        let (s, c) = angle.sin_cos();
        Self::new(c, s)
    }

    /// The complex conjugate.
    pub fn conj(self) -> Self {
        Self::new(self.re, -self.im)
    }

    /// `|z|²`.
    pub fn norm_sqr(self) -> f64 {
        self.re * self.re + self.im * self.im
    }

    /// `|z|`, without overflow or underflow in the squares.
    pub fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }

    /// The argument in (−π, π].
    pub fn arg(self) -> f64 {
        self.im.atan2(self.re)
    }

    /// `z / |z|`; zero stays zero.
    pub fn unit(self) -> Self {
        let r = self.abs();
        if r == 0.0 {
            self
        } else {
            self / r
        }
    }

    /// Whether both parts are finite.
    pub fn is_finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
}

impl From<f64> for Complex {
    fn from(re: f64) -> Self {
        Self::new(re, 0.0)
    }
}

impl Add for Complex {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self::new(self.re + o.re, self.im + o.im)
    }
}

impl AddAssign for Complex {
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl Sub for Complex {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self::new(self.re - o.re, self.im - o.im)
    }
}

impl Neg for Complex {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.re, -self.im)
    }
}

impl Mul for Complex {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
}

impl Mul<f64> for Complex {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        Self::new(self.re * s, self.im * s)
    }
}

impl Mul<Complex> for f64 {
    type Output = Complex;
    fn mul(self, z: Complex) -> Complex {
        z * self
    }
}

impl Div<f64> for Complex {
    type Output = Self;
    fn div(self, s: f64) -> Self {
        Self::new(self.re / s, self.im / s)
    }
}

impl Div for Complex {
    type Output = Self;
    /// Smith's algorithm: divides by the larger component first, so that quotients of
    /// very large or very small numbers neither overflow nor underflow needlessly.
    fn div(self, o: Self) -> Self {
        if o.re.abs() >= o.im.abs() {
            let r = o.im / o.re;
            let d = o.re + o.im * r;
            Self::new((self.re + self.im * r) / d, (self.im - self.re * r) / d)
        } else {
            let r = o.re / o.im;
            let d = o.re * r + o.im;
            Self::new((self.re * r + self.im) / d, (self.im * r - self.re) / d)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Complex, b: Complex) -> bool {
        (a - b).abs() <= 1e-15 * (1.0 + b.abs())
    }

    #[test]
    fn field_operations() {
        let a = Complex::new(1.5, -2.0);
        let b = Complex::new(-0.25, 3.0);
        assert!(close(a * b, Complex::new(5.625, 5.0)));
        assert!(close((a * b) / b, a));
        assert!(close(
            a / Complex::new(1e-3, 2e3) * Complex::new(1e-3, 2e3),
            a
        ));
        assert!(close(a * a.conj(), Complex::from(a.norm_sqr())));
        assert_eq!(-a + a, Complex::ZERO);
        assert!((Complex::I * Complex::I + Complex::ONE).abs() == 0.0);
    }

    #[test]
    fn polar_form() {
        let z = Complex::cis(2.0) * 3.0;
        assert!((z.abs() - 3.0).abs() < 1e-15);
        assert!((z.arg() - 2.0).abs() < 1e-15);
        assert!((z.unit().abs() - 1.0).abs() < 1e-15);
        assert_eq!(Complex::ZERO.unit(), Complex::ZERO);
        assert!(!Complex::new(f64::NAN, 0.0).is_finite());
    }
}
