//! Canonical form of G1 Hermite data (Section 3, eqs. (11)–(13)): coordinates in which the
//! start point is the origin, the displacement Δp = p_f − p_i is (X, 0, 0) and the start
//! tangent lies in the (x, y)-plane, t_i = (cos θ_i, sin θ_i, 0). The end tangent is then
//! t_f = (cos θ_f, sin θ_f cos φ, sin θ_f sin φ), and the construction of Section 4 works
//! with the half-angle values (c_i, s_i) = (cos ½θ_i, sin ½θ_i), (c_f, s_f) likewise (13).
//!
//! The change of coordinates is a rigid motion (translation and rotation, no scaling), so
//! the Hopf coefficients reported in canonical coordinates are those of the paper's
//! examples, and a curve is taken back to the caller's coordinates by [`Placement`].

use crate::error::{invalid, Result};
use crate::hermite::HermiteSegment;
use crate::math::orthogonalized;
use glam::{DMat3, DVec3};

/// |sin| below which θ_i, θ_f or φ count as a multiple of π: the data are planar or
/// degenerate and the construction of Section 4 does not apply (its footnote 4). Such data
/// are planar to `planar::PLANAR_TOLERANCE` (their deviation is at most this |sin|), and
/// `best_quintic` and splines interpolate them with a planar PH quintic.
const DEGENERATE_SINE: f64 = 1e-10;

/// The rigid motion from canonical to original coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// p_i, the canonical origin.
    pub origin: DVec3,
    /// Columns: the canonical x, y and z axes in original coordinates (a rotation).
    pub axes: DMat3,
}

impl Placement {
    /// A canonical point in original coordinates.
    pub fn point(&self, p: DVec3) -> DVec3 {
        self.origin + self.axes * p
    }

    /// A canonical vector (direction, derivative) in original coordinates.
    pub fn vector(&self, v: DVec3) -> DVec3 {
        self.axes * v
    }
}

/// Hermite data in canonical form, with the angles and half-angle values of (11)–(13).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CanonicalHermite {
    /// The similarity from canonical to original coordinates.
    pub placement: Placement,
    /// X = |p_f − p_i| > 0.
    pub x: f64,
    /// Polar angle of t_i from the x-axis, in (0, π).
    pub theta_i: f64,
    /// Polar angle of t_f from the x-axis, in (0, π).
    pub theta_f: f64,
    /// Azimuth φ = φ_f of t_f about the x-axis, in (0, 2π), not π.
    pub phi: f64,
    /// (cos ½θ_i, sin ½θ_i), both positive.
    pub ci: f64,
    /// sin ½θ_i.
    pub si: f64,
    /// (cos ½θ_f, sin ½θ_f), both positive.
    pub cf: f64,
    /// sin ½θ_f.
    pub sf: f64,
}

impl CanonicalHermite {
    /// Canonical form of validated Hermite data; planar or degenerate data (θ_i, θ_f or φ
    /// a multiple of π: a tangent along the chord, or both tangents in one plane with it)
    /// are refused with a message naming the arguments.
    pub fn new(data: &HermiteSegment) -> Result<Self> {
        let (ex, x) = chord_axis(data)?;
        let (theta_i, ey) = polar_angle(data.t0, ex);
        if theta_i.sin() <= DEGENERATE_SINE {
            return invalid!(
                "t0 is parallel to p1 − p0 (θ_i is a multiple of π): degenerate data for an RRMF quintic"
            );
        }
        let ez = ex.cross(ey);
        let local = DVec3::new(data.t1.dot(ex), data.t1.dot(ey), data.t1.dot(ez));
        let theta_f = local.y.hypot(local.z).atan2(local.x);
        if theta_f.sin() <= DEGENERATE_SINE {
            return invalid!(
                "t1 is parallel to p1 − p0 (θ_f is a multiple of π): degenerate data for an RRMF quintic"
            );
        }
        // φ in [0, 2π), the branch of the paper's examples: e^{iφ/2} enters (18)–(19), and the
        // other branch would relabel every solution η as η + π.
        let phi = local
            .z
            .atan2(local.y)
            .rem_euclid(2.0 * std::f64::consts::PI);
        if phi.sin().abs() <= DEGENERATE_SINE {
            return invalid!(
                "p0, p1, t0 and t1 are planar (φ is a multiple of π): the data need a non-planar interpolant"
            );
        }
        let (si, ci) = (0.5 * theta_i).sin_cos();
        let (sf, cf) = (0.5 * theta_f).sin_cos();
        Ok(Self {
            placement: Placement {
                origin: data.p0,
                axes: DMat3::from_cols(ex, ey, ez),
            },
            x,
            theta_i,
            theta_f,
            phi,
            ci,
            si,
            cf,
            sf,
        })
    }

    /// The unit tangents in canonical coordinates, (11) with φ_i = 0 and (12).
    pub fn tangents(&self) -> (DVec3, DVec3) {
        let (si, ci) = self.theta_i.sin_cos();
        let (sf, cf) = self.theta_f.sin_cos();
        let (sp, cp) = self.phi.sin_cos();
        (DVec3::new(ci, si, 0.0), DVec3::new(cf, sf * cp, sf * sp))
    }
}

/// The unit chord direction (p1 − p0)/|p1 − p0| and X = |p1 − p0|, the chord scaled by
/// its largest component first: |p1 − p0| may overflow (or underflow) even though p0 and
/// p1 are finite.
pub(crate) fn chord_axis(data: &HermiteSegment) -> Result<(DVec3, f64)> {
    let chord = data.p1 - data.p0;
    let largest = chord.abs().max_element();
    if !largest.is_finite() {
        return invalid!("p1 − p0 overflows: p0 and p1 are too far apart to be represented");
    }
    Ok((
        (chord / largest).normalize(),
        largest * (chord / largest).length(),
    ))
}

/// The angle θ of the unit vector `t` from the unit axis `ex`, and the unit vector of the
/// (ex, t)-plane perpendicular to `ex` on the side of `t` (arbitrary if t ∥ ex). The
/// double projection keeps the axes orthonormal to rounding however close t is to ex.
fn polar_angle(t: DVec3, ex: DVec3) -> (f64, DVec3) {
    let across = orthogonalized(t, ex);
    let sine = across.length();
    let ey = if sine > 0.0 {
        across / sine
    } else {
        crate::math::orthonormal_to(ex)
    };
    (sine.atan2(t.dot(ex)), ey)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::example_1;

    #[test]
    fn canonical_coordinates_reproduce_the_data() {
        let data = HermiteSegment::new(
            DVec3::new(1.0, -2.0, 0.5),
            DVec3::new(0.3, 1.0, -0.2),
            DVec3::new(2.0, 0.5, 1.5),
            DVec3::new(-0.4, 0.2, 1.0),
        )
        .unwrap();
        let c = CanonicalHermite::new(&data).unwrap();
        let (ti, tf) = c.tangents();
        let p = c.placement;
        assert!((p.point(DVec3::new(c.x, 0.0, 0.0)) - data.p1).length() < 1e-15);
        assert!((p.vector(ti) - data.t0).length() < 1e-15);
        assert!((p.vector(tf) - data.t1).length() < 1e-15);
        assert!((p.axes.determinant() - 1.0).abs() < 1e-15, "a rotation");
        // t0 within 4e-10 rad of the chord: the axes are still orthonormal to rounding.
        let chord = (data.p1 - data.p0).normalize();
        let near = chord + DVec3::new(0.2, -0.3, 0.1) * 1e-9;
        let close = HermiteSegment::new(data.p0, near, data.p1, data.t1);
        let axes = CanonicalHermite::new(&close.unwrap())
            .unwrap()
            .placement
            .axes;
        assert!((axes.transpose() * axes - DMat3::IDENTITY)
            .to_cols_array()
            .iter()
            .all(|e| e.abs() < 1e-15));
        assert!((c.ci.hypot(c.si) - 1.0).abs() < 1e-15 && c.ci > 0.0 && c.si > 0.0);
    }

    #[test]
    fn example_1_angles() {
        // t_i and t_f both make the angle acos(2/√6) with the chord (1, 1, 1).
        let c = CanonicalHermite::new(&example_1()).unwrap();
        let theta = (2.0 / 6f64.sqrt()).acos();
        assert!((c.theta_i - theta).abs() < 1e-15 && (c.theta_f - theta).abs() < 1e-15);
        assert!((c.x - 3f64.sqrt()).abs() < 1e-15);
        assert!((c.phi - 4.0 * std::f64::consts::FRAC_PI_3).abs() < 1e-14);
    }

    #[test]
    fn refuses_planar_and_degenerate_data() {
        let d = |t0: DVec3, t1: DVec3| {
            let data = HermiteSegment::new(DVec3::ZERO, t0, DVec3::X, t1).unwrap();
            CanonicalHermite::new(&data)
                .unwrap_err()
                .message()
                .to_string()
        };
        assert!(d(DVec3::X, DVec3::Y).contains("t0 is parallel"));
        assert!(d(-DVec3::X, DVec3::Y).contains("t0 is parallel"));
        assert!(d(DVec3::Y, DVec3::X * 2.0).contains("t1 is parallel"));
        assert!(d(DVec3::Y, DVec3::new(1.0, -1.0, 0.0)).contains("planar"));
        assert!(d(DVec3::Y, DVec3::new(1.0, 1.0, 1e-13)).contains("planar"));
    }
}
