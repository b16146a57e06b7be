//! The quaternion preimage of a PH cubic and its Euler–Rodrigues frame.
//!
//! Every spatial PH cubic has a hodograph x'(v) = A(v) i A*(v) with a linear quaternion
//! polynomial A(v) = A₀(1 − v) + A₁v, and σ = |A|² (the quaternion form of the PH condition
//! (17); Farouki, "Pythagorean-Hodograph Curves", 2008, ch. 22). The Euler–Rodrigues frame
//! (A i A*, A j A*, A k A*)/|A|² is quadratic over quadratic, like (19), and orthonormal by
//! construction: |A q A*| = |A|²|q| holds to rounding of A whatever the cubic's bend.
//!
//! It is what the Frenet frame (19) is computed from: the Frenet frame of a PH cubic is its
//! Euler–Rodrigues frame turned by a constant angle (its twist rate τσ and the frame's,
//! 2(A₀*A₁)ᵢ/σ, are both a constant over σ; a test checks it). Written literally, (19) divides
//! σx'' − σ'x' and x' × x'' by Kσ with σ from the leg lengths, which holds only to the PH
//! residual r of the rounded polygon over sin²θ: 5e-9 from orthonormal at sin θ = 2e-3,
//! against 1e-15 here.

use super::base_frame::{spline_frame_pieces, FrameNumerators};
use super::cubic::PhCubic;
use super::spline::PhSpline;
use crate::error::Result;
use crate::frames::rational::{g1_tolerance, RationalFrames};
use glam::{DQuat, DVec3};

/// The linear quaternion polynomial A with x' = A i A* of a PH cubic.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Preimage {
    a0: DQuat,
    a1: DQuat,
}

const I: DQuat = DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0);
const J: DQuat = DQuat::from_xyzw(0.0, 1.0, 0.0, 0.0);
const K: DQuat = DQuat::from_xyzw(0.0, 0.0, 1.0, 0.0);

fn vector_part(q: DQuat) -> DVec3 {
    DVec3::new(q.x, q.y, q.z)
}

/// A unit quaternion q with q i q* = d for a unit vector d: the rotation about i × d, by its
/// half-angle formula (1 + i·d, i × d)/|…| when d·i ≥ 0, and otherwise the rotation taking i
/// to −d composed with j, which takes i to −i (the formula cancels as d approaches −i).
fn rotating_i_to(d: DVec3) -> DQuat {
    if d.x >= 0.0 {
        DQuat::from_xyzw(0.0, -d.z, d.y, 1.0 + d.x).normalize()
    } else {
        DQuat::from_xyzw(0.0, d.z, -d.y, 1.0 - d.x).normalize() * J
    }
}

/// The unit (c, s) minimizing |c v₁ + s v₂ − target|: the unconstrained least-squares
/// solution turned into an angle, polished by Newton steps on the circle (which keep it a
/// minimum where the least-squares problem is ill-conditioned, on nearly straight cubics).
fn closest_on_circle(v1: DVec3, v2: DVec3, target: DVec3) -> (f64, f64) {
    let (g11, g12, g22) = (v1.dot(v1), v1.dot(v2), v2.dot(v2));
    let (b1, b2) = (v1.dot(target), v2.dot(target));
    let gram = v1.cross(v2).length_squared();
    let objective = |phi: f64| {
        let (s, c) = phi.sin_cos();
        (v1 * c + v2 * s - target).length_squared()
    };
    // The least-squares solution (g₂₂b₁ − g₁₂b₂, g₁₁b₂ − g₁₂b₁)/gram, as an angle.
    let least_squares = (g11 * b2 - g12 * b1).atan2(g22 * b1 - g12 * b2);
    let along_target = b2.atan2(b1);
    let start = if gram > 0.0 && objective(least_squares) <= objective(along_target) {
        least_squares
    } else {
        along_target
    };
    let mut phi = start;
    let mut value = objective(phi);
    for _ in 0..4 {
        let (s, c) = phi.sin_cos();
        let residual = (g11 * c + g12 * s - b1, g12 * c + g22 * s - b2);
        let slope = -s * residual.0 + c * residual.1;
        let curvature =
            -(c * residual.0 + s * residual.1) + g11 * s * s - 2.0 * g12 * s * c + g22 * c * c;
        if curvature <= 0.0 || slope == 0.0 {
            break;
        }
        let next = phi - slope / curvature;
        let next_value = objective(next);
        if next_value > value {
            break;
        }
        (phi, value) = (next, next_value);
    }
    let (s, c) = phi.sin_cos();
    (c, s)
}

impl Preimage {
    /// The preimage of a PH cubic's hodograph 3(h₀B₀ + h₁B₁ + h₂B₂): A₀ i A₀* = 3h₀,
    /// A₁ i A₁* = 3h₂ fix A₀ and A₁ up to a turn e^{iφ} of A₁, and Vec(A₀ i A₁*) = 3h₁ fixes
    /// φ (to the polygon's rounding, in the least-squares sense).
    pub(crate) fn of(cubic: &PhCubic) -> Self {
        let [h0, h1, h2] = cubic.legs();
        let [l1, _, l3] = cubic.leg_lengths();
        let a0 = rotating_i_to(h0 / l1) * (3.0 * l1).sqrt();
        let a1 = rotating_i_to(h2 / l3) * (3.0 * l3).sqrt();
        // With A₁ = Â₁ e^{iφ}: A₀ i e^{−iφ} Â₁* = cos φ A₀ i Â₁* + sin φ A₀ Â₁*.
        let (c, s) = closest_on_circle(
            vector_part(a0 * I * a1.conjugate()),
            vector_part(a0 * a1.conjugate()),
            h1 * 3.0,
        );
        Self {
            a0,
            a1: a1 * DQuat::from_xyzw(s, 0.0, 0.0, c),
        }
    }

    /// Bernstein coefficients of the quadratic A q A* for a pure quaternion q: A₀ q A₀*,
    /// (A₀ q A₁* + A₁ q A₀*)/2 = Vec(A₀ q A₁*), A₁ q A₁*.
    fn sandwich(&self, q: DQuat) -> Vec<DVec3> {
        let (a0, a1) = (self.a0, self.a1);
        vec![
            vector_part(a0 * q * a0.conjugate()),
            vector_part(a0 * q * a1.conjugate()),
            vector_part(a1 * q * a1.conjugate()),
        ]
    }

    /// Bernstein coefficients of σ = |A|²: |A₀|², A₀·A₁, |A₁|².
    pub(crate) fn speed(&self) -> Vec<f64> {
        vec![
            self.a0.length_squared(),
            self.a0.dot(self.a1),
            self.a1.length_squared(),
        ]
    }

    /// The hodograph x' = A i A* (Bernstein coefficients): the tests' check of the preimage.
    #[cfg(test)]
    fn hodograph(&self) -> Vec<DVec3> {
        self.sandwich(I)
    }

    /// Numerators of the normal vectors of the Euler–Rodrigues frame, A j A* and A k A*, over
    /// [`Self::speed`].
    pub(crate) fn frame_numerators(&self) -> (Vec<DVec3>, Vec<DVec3>) {
        (self.sandwich(J), self.sandwich(K))
    }
}

/// The Euler–Rodrigues frames of a PH cubic spline, joined into one continuous adapted
/// frame starting at `initial_normal`: each cubic's (A j A*, A k A*)/σ turned by the
/// constant that continues the one before — the lightest exact rational adapted frame of a
/// PH cubic (quadratic over quadratic), split where σ has a negative Bernstein coefficient
/// so that all weights are positive. It is no RMF: it turns about the tangent against the
/// RMF by ∫ 2(A₀*A₁)ᵢ/σ dv (module notes).
pub(crate) fn euler_rodrigues_frames(
    spline: &PhSpline,
    initial_normal: DVec3,
) -> Result<RationalFrames> {
    let pieces = spline_frame_pieces(spline, |_, cubic| {
        let preimage = Preimage::of(cubic);
        let (e2, e3) = preimage.frame_numerators();
        Ok(FrameNumerators {
            e2,
            e3,
            d: preimage.speed(),
        })
    })?;
    pieces.into_chained_frames(initial_normal, g1_tolerance(spline.curve()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bezier::bernstein;
    use crate::frames::frenet::frenet_frame;
    use crate::ph_cubic::test_curves::example_cubic;

    /// A PH cubic from a random-looking preimage: x(v) = ∫ A i A*.
    fn cubic_of(a0: DQuat, a1: DQuat) -> PhCubic {
        let h = Preimage { a0, a1 }.hodograph();
        let mut points = [DVec3::new(0.3, -0.2, 0.1); 4];
        for k in 0..3 {
            points[k + 1] = points[k] + h[k] / 3.0;
        }
        PhCubic::from_control_points(points).unwrap()
    }

    #[test]
    fn rotations_take_i_to_every_direction() {
        for d in [
            DVec3::X,
            -DVec3::X,
            DVec3::new(-1.0, 1e-9, 0.0).normalize(),
            DVec3::new(0.3, -0.4, 0.5).normalize(),
            DVec3::new(-0.3, 0.4, -0.5).normalize(),
        ] {
            let q = rotating_i_to(d);
            assert!(
                (vector_part(q * I * q.conjugate()) - d).length() < 1e-15,
                "{d}"
            );
        }
    }

    #[test]
    fn the_preimage_reproduces_the_hodograph_and_speed() {
        let a0 = DQuat::from_xyzw(0.3, -1.1, 0.4, 0.8);
        let a1 = DQuat::from_xyzw(-0.7, 0.2, 1.3, 0.5);
        let nearly = a0 * 1.5 + DQuat::from_xyzw(1e-7, -2e-7, 0.0, 1e-7);
        for cubic in [
            example_cubic(),
            cubic_of(a0, a1),
            cubic_of(a0, a0 * 1.5),
            cubic_of(a0, nearly),
            cubic_of(a0, -a1),
        ] {
            let p = Preimage::of(&cubic);
            let legs = cubic.legs().map(|h| h * 3.0);
            for (a, b) in p.hodograph().iter().zip(legs) {
                assert!((*a - b).length() < 1e-14 * b.length().max(1.0), "{a} {b}");
            }
            for (a, b) in p.speed().iter().zip(cubic.speed()) {
                assert!((a - b).abs() < 1e-14 * b.abs().max(1.0), "{a} {b}");
            }
        }
    }

    /// The fact the Frenet frame is computed from: it is the Euler–Rodrigues frame turned
    /// by one constant angle along the whole cubic.
    #[test]
    fn the_frenet_frame_is_the_euler_rodrigues_frame_turned_by_a_constant() {
        let cubic = cubic_of(
            DQuat::from_xyzw(0.3, -1.1, 0.4, 0.8),
            DQuat::from_xyzw(-0.7, 0.2, 1.3, 0.5),
        );
        let p = Preimage::of(&cubic);
        let (e2, e3) = p.frame_numerators();
        let hodograph = bernstein::derivative(&cubic.control_points());
        let angles: Vec<f64> = (0..=10)
            .map(|i| {
                let v = i as f64 / 10.0;
                let d1 = bernstein::evaluate(&hodograph, v);
                let d2 = bernstein::evaluate(&bernstein::derivative(&hodograph), v);
                let n = frenet_frame(d1, d2).unwrap().f2;
                let (a, b) = (bernstein::evaluate(&e2, v), bernstein::evaluate(&e3, v));
                n.dot(b).atan2(n.dot(a))
            })
            .collect();
        for a in &angles {
            assert!((a - angles[0]).abs() < 1e-12, "{angles:?}");
        }
    }
}
