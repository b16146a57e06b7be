//! Brent's method for a 1-D minimum on a bracket (golden section with parabolic steps).
//! Used to choose free shape parameters, e.g. λ of the rational RMF approximation and η of
//! RRMF quintics.

/// The located minimum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Minimum {
    /// Abscissa of the minimum.
    pub x: f64,
    /// f(x).
    pub value: f64,
    /// Number of evaluations of f.
    pub evaluations: usize,
}

/// Minimizes `f` on `[a, b]` to the absolute tolerance `tol` in x (Brent 1973, `localmin`).
/// Non-finite values of f are treated as +∞, so a caller may return NaN where f is undefined.
pub(crate) fn minimize_bracketed(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    tol: f64,
) -> Minimum {
    const GOLDEN: f64 = 0.381_966_011_250_105_1;
    let mut eval = |x: f64| {
        let v = f(x);
        if v.is_nan() {
            f64::INFINITY
        } else {
            v
        }
    };
    let (mut a, mut b) = (a.min(b), a.max(b));
    let mut x = a + GOLDEN * (b - a);
    let (mut w, mut v) = (x, x);
    let mut fx = eval(x);
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e) = (0.0f64, 0.0f64);
    let mut evaluations = 1;
    for _ in 0..500 {
        let m = 0.5 * (a + b);
        let tol1 = f64::EPSILON.sqrt() * x.abs() + tol / 3.0;
        let tol2 = 2.0 * tol1;
        if (x - m).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let mut golden = true;
        if e.abs() > tol1 {
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            if p.abs() < (0.5 * q * e).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = if x < m { tol1 } else { -tol1 };
                }
                golden = false;
            }
        }
        if golden {
            e = if x < m { b - x } else { a - x };
            d = GOLDEN * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else {
            x + tol1.copysign(d)
        };
        let fu = eval(u);
        evaluations += 1;
        if fu <= fx {
            if u < x {
                b = x;
            } else {
                a = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    Minimum {
        x,
        value: fx,
        evaluations,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_minimum_of_a_smooth_function() {
        let m = minimize_bracketed(|x| (x - 0.3).powi(2) + 1.0, -2.0, 5.0, 1e-10);
        assert!((m.x - 0.3).abs() < 1e-7, "{m:?}");
        assert!((m.value - 1.0).abs() < 1e-14);
        assert!(m.evaluations < 60);
    }

    #[test]
    fn treats_nan_as_infinite() {
        let m = minimize_bracketed(
            |x| if x < 0.0 { f64::NAN } else { (x - 1.0).powi(2) },
            -3.0,
            3.0,
            1e-9,
        );
        assert!((m.x - 1.0).abs() < 1e-6, "{m:?}");
    }
}
