//! Measures computed in a construction's own unit-size coordinates, returned in the
//! caller's: a length, area or volume times the scale to its power, refused when that is
//! outside the range of f64 rather than returned as 0 or ∞.

use crate::error::{invalid, Result};

/// `unit` (a measure in coordinates scaled by 1/`scale`) times `scale`^`power`, the same
/// measure in the caller's units; `what` names it in the refusal.
pub(crate) fn in_caller_units(unit: f64, scale: f64, power: i32, what: &str) -> Result<f64> {
    let value = (0..power).fold(unit, |v, _| v * scale);
    if unit != 0.0 && !value.is_normal() {
        return invalid!(
            "the {what} {unit:.6e} × ({scale:e})^{power} is outside the range of f64 (the \
             model is {scale:e} across)"
        );
    }
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_beyond_the_range_of_f64_are_refused() {
        assert_eq!(in_caller_units(2.0, 1e100, 2, "area").unwrap(), 2e200);
        assert_eq!(in_caller_units(0.0, 1e200, 3, "volume").unwrap(), 0.0);
        let big = in_caller_units(2.0, 1e200, 2, "area").unwrap_err();
        assert!(big.message().contains("area 2.000000e0"), "{big}");
        assert!(in_caller_units(2.0, 1e-200, 3, "volume").is_err());
    }
}
