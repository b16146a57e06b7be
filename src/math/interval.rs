//! Arithmetic on parameter intervals that stays finite for any representable ends: a domain
//! [−1e308, 1e308] has a length that overflows, and one of [0, 5e-324] a length whose
//! reciprocal does. Points of an interval and fractions of it are computed on halved ends
//! when the length is not representable (exact: halving a double only shifts its exponent,
//! apart from subnormals).

/// The point a + (b − a)·s of [a, b] for s ∈ [0, 1], exactly a at s = 0 and b at s = 1.
pub fn lerp(a: f64, b: f64, s: f64) -> f64 {
    if s == 0.0 {
        return a;
    }
    if s == 1.0 {
        return b;
    }
    let length = b - a;
    if length.is_finite() {
        a + length * s
    } else {
        a * (1.0 - s) + b * s
    }
}

/// (t − a) / (b − a), the fraction of [a, b] at t (a < b).
pub(crate) fn fraction(t: f64, a: f64, b: f64) -> f64 {
    let (offset, length) = (t - a, b - a);
    if offset.is_finite() && length.is_finite() {
        offset / length
    } else {
        (0.5 * t - 0.5 * a) / (0.5 * b - 0.5 * a)
    }
}

/// 1 / (b − a): the factor from a local parameter on [0, 1] to the parameter of [a, b]
/// (infinite only for intervals narrower than 1/f64::MAX).
pub(crate) fn reciprocal_length(a: f64, b: f64) -> f64 {
    let length = b - a;
    if length.is_finite() {
        1.0 / length
    } else {
        0.5 / (0.5 * b - 0.5 * a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_widest_and_narrowest_intervals_stay_finite() {
        let (a, b) = (-1e308, 1e308);
        assert_eq!(lerp(a, b, 0.5), 0.0);
        assert_eq!(lerp(a, b, 0.0), a);
        assert_eq!(lerp(a, b, 1.0), b);
        assert_eq!(fraction(0.0, a, b), 0.5);
        assert_eq!(fraction(b, a, b), 1.0);
        assert!((reciprocal_length(a, b) - 5e-309).abs() < 1e-320);
        assert_eq!(fraction(5e-324, 0.0, 5e-324), 1.0);
        assert!(reciprocal_length(0.0, 5e-324).is_infinite());
        assert_eq!(lerp(1.0, 3.0, 0.25), 1.5);
    }
}
