//! Polishing a root that is already known to round-off of its own formula, by secant steps
//! on a residual that can be evaluated more accurately (e.g. a geometric check), accepting
//! only steps that reduce the residual.

/// Refines the root of `f` near `x0` by at most `iterations` secant steps (first step of
/// size `step`). `f` returns `None` where it cannot be evaluated. Returns the abscissa with
/// the smallest |f| seen; `x0` itself if no step improved it.
pub(crate) fn secant_refine(
    mut f: impl FnMut(f64) -> Option<f64>,
    x0: f64,
    step: f64,
    iterations: usize,
) -> f64 {
    let Some(f0) = f(x0) else { return x0 };
    let (mut best, mut best_f) = (x0, f0.abs());
    let (mut a, mut fa) = (x0, f0);
    let (mut b, mut fb) = match f(x0 + step) {
        Some(v) => (x0 + step, v),
        None => return x0,
    };
    for _ in 0..iterations {
        if fb.abs() < best_f {
            (best, best_f) = (b, fb.abs());
        }
        if best_f == 0.0 || !(fb - fa).is_normal() {
            break;
        }
        let next = b - fb * (b - a) / (fb - fa);
        let Some(value) = f(next) else { break };
        if !value.is_finite() || value.abs() >= best_f {
            break;
        }
        (a, fa, b, fb) = (b, fb, next, value);
    }
    if fb.abs() < best_f {
        best = b;
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polishes_a_rough_root_and_never_worsens() {
        let x = secant_refine(|x| Some(x * x - 2.0), 1.41, 1e-3, 20);
        assert!((x - 2f64.sqrt()).abs() < 1e-15);
        // No root: no step may make the residual worse.
        let x = secant_refine(|x| Some(1.0 + x * x), 0.5, 1e-3, 20);
        assert!(1.0 + x * x <= 1.25);
        assert_eq!(secant_refine(|_| None, 3.0, 1.0, 5), 3.0);
    }
}
