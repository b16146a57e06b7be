//! The point of a polynomial cubic Bézier curve closest to a given point.
//!
//! The closest point of x(v), v ∈ [0, 1], to p is an end or a root of the quintic
//! g(v) = (x(v) − p)·x'(v). Near a good guess, Newton's method on g (g' = |x'|² + (x − p)·x'')
//! finds it in two or three steps; [`LocalCubic::closest`] uses it, and falls back to all real
//! roots of the quintic (the global answer) whenever Newton leaves its safe ground (a
//! non-convex stretch, no convergence). A Newton answer is a point of the curve, so its
//! distance is never below the true one: a test "distance ≤ tolerance" made with it errs on
//! the safe side.
//!
//! The cubic is held in power form about its first control point, so that points far from
//! the origin lose nothing to cancellation in x(v) − p beyond the rounding of p − b₀.

use super::bernstein::{derivative, product, to_power};
use crate::math::real_roots_in;
use glam::DVec3;

/// Newton steps before the exact fallback.
const NEWTON_STEPS: usize = 12;

/// A Newton step below which the iterate after it has converged: its parameter error is
/// about the square of the step (quadratic convergence), and the distance's error second
/// order in that, far below any rounding.
const CONVERGED_STEP: f64 = 1e-7;

/// A Newton step that moves the point by less than this fraction of its distance (squared)
/// has converged as well: the next iterate's point is off by about the square of the move
/// relative to the cubic's size, a negligible part of the distance.
const CONVERGED_SHIFT: f64 = 1e-6;

/// A polynomial cubic x(v) = b₀ + c₁v + c₂v² + c₃v³ on [0, 1].
#[derive(Clone, Copy, Debug)]
pub(crate) struct LocalCubic {
    bezier: [DVec3; 4],
    c1: DVec3,
    c2: DVec3,
    c3: DVec3,
}

/// Where a cubic comes closest to a point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Closest {
    /// The parameter in [0, 1].
    pub v: f64,
    /// The distance from the point to x(v).
    pub distance: f64,
}

impl LocalCubic {
    /// From the Bézier control points b₀ … b₃.
    pub(crate) fn new(bezier: [DVec3; 4]) -> Self {
        let [b0, b1, b2, b3] = bezier;
        Self {
            bezier,
            c1: 3.0 * (b1 - b0),
            c2: 3.0 * (b2 - 2.0 * b1 + b0),
            c3: b3 - 3.0 * b2 + 3.0 * b1 - b0,
        }
    }

    /// x(v) − b₀.
    fn offset(&self, v: f64) -> DVec3 {
        ((self.c3 * v + self.c2) * v + self.c1) * v
    }

    /// x(v).
    pub(crate) fn eval(&self, v: f64) -> DVec3 {
        self.bezier[0] + self.offset(v)
    }

    /// x(v) − b₀, x'(v), x''(v).
    fn jet(&self, v: f64) -> [DVec3; 3] {
        [
            self.offset(v),
            (3.0 * self.c3 * v + 2.0 * self.c2) * v + self.c1,
            6.0 * self.c3 * v + 2.0 * self.c2,
        ]
    }

    /// The closest point to `p`, by Newton's method from `guess` (module notes).
    pub(crate) fn closest(&self, p: DVec3, guess: f64) -> Closest {
        let q = p - self.bezier[0];
        let mut v = if guess.is_nan() {
            0.5
        } else {
            guess.clamp(0.0, 1.0)
        };
        for _ in 0..NEWTON_STEPS {
            let [x, d1, d2] = self.jet(v);
            let r = x - q;
            let g = r.dot(d1);
            let slope = d1.length_squared() + r.dot(d2);
            // Not locally convex (or NaN): Newton could climb to a maximum.
            if slope.is_nan() || slope <= 0.0 {
                break;
            }
            let next = (v - g / slope).clamp(0.0, 1.0);
            let step = (next - v).abs();
            v = next;
            // At an end with g pointing outwards the end itself is the local minimum.
            // Otherwise the next iterate is off by about the square of this step: its point
            // is then far closer to the true foot than the distance itself.
            if step <= CONVERGED_STEP
                || step * step * d1.length_squared() <= CONVERGED_SHIFT * r.length_squared()
            {
                return Closest {
                    v,
                    distance: (self.offset(v) - q).length(),
                };
            }
        }
        self.closest_exact(p)
    }

    /// The closest point to `p` among the ends and every real root of the quintic.
    pub(crate) fn closest_exact(&self, p: DVec3) -> Closest {
        let b0 = self.bezier[0];
        let q = p - b0;
        let offset = self.bezier.map(|b| (b - b0) - q);
        let hodograph = derivative(&self.bezier);
        let quintic = to_power(&product(&offset, &hodograph, |a: DVec3, b: DVec3| a.dot(b)));
        real_roots_in(&quintic, 0.0, 1.0)
            .into_iter()
            .chain([0.0, 1.0])
            .map(|v| Closest {
                v,
                distance: (self.offset(v) - q).length(),
            })
            .min_by(|a, b| a.distance.total_cmp(&b.distance))
            .expect("the ends are candidates")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wavy() -> LocalCubic {
        LocalCubic::new([
            DVec3::new(1e6, 0.0, 0.0),
            DVec3::new(1e6 + 1.0, 2.0, 0.0),
            DVec3::new(1e6 + 2.0, -1.0, 1.0),
            DVec3::new(1e6 + 3.0, 0.5, 0.2),
        ])
    }

    #[test]
    fn power_form_matches_de_casteljau() {
        let c = wavy();
        for i in 0..=10 {
            let v = i as f64 / 10.0;
            let expected = crate::bezier::bernstein::evaluate(&c.bezier, v);
            assert!((c.eval(v) - expected).length() < 1e-9, "{v}");
        }
    }

    #[test]
    fn newton_agrees_with_the_quintic_and_never_undercuts_it() {
        let c = wavy();
        let mut newton_answers = 0;
        for i in 0..200 {
            let v = i as f64 / 199.0;
            // Points off the curve along a fixed direction, near and far.
            let p = c.eval(v) + DVec3::new(0.1, 0.3, -0.2) * (1.0 + (i % 7) as f64);
            let exact = c.closest_exact(p);
            for guess in [v, 0.5, 0.0] {
                let found = c.closest(p, guess);
                assert!(
                    found.distance >= exact.distance - 1e-9,
                    "{found:?} {exact:?}"
                );
                if (found.distance - exact.distance).abs() <= 1e-9 * exact.distance.max(1.0) {
                    newton_answers += 1;
                }
            }
            // Close to the curve, a close guess gives the global answer.
            let near = c.eval(v) + DVec3::new(1e-4, -2e-4, 1e-4);
            let found = c.closest(near, v);
            let exact = c.closest_exact(near);
            assert!((found.distance - exact.distance).abs() < 1e-12, "{v}");
        }
        assert!(newton_answers > 400, "{newton_answers}");
    }

    #[test]
    fn ends_are_closest_beyond_them() {
        let c = wavy();
        let before = c.eval(0.0) - DVec3::X;
        let found = c.closest(before, 0.3);
        assert_eq!(found.v, 0.0);
        assert!((found.distance - 1.0).abs() < 1e-9);
    }
}
