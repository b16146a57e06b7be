//! Small linear systems. The 3 × 3 systems of this crate (sphere centres from tangency
//! conditions, in Möbius maps and cone splines) become nearly singular for short segments or
//! nearby rulings; what the constructions need is a small *residual* — the conditions met to
//! round-off — which iterative refinement restores where the explicit inverse alone loses
//! digits in proportion to the condition number.

use glam::{DMat3, DVec3};

/// The solution of `rows · x = rhs` (`rows` holding the equations' coefficient vectors as
/// rows), refined twice against its residual; `None` for a singular matrix.
pub(crate) fn solve_refined(rows: DMat3, rhs: DVec3) -> Option<DVec3> {
    if rows.determinant() == 0.0 || !rows.is_finite() || !rhs.is_finite() {
        return None;
    }
    let inverse = rows.inverse();
    let mut x = inverse * rhs;
    for _ in 0..2 {
        x += inverse * (rhs - rows * x);
    }
    x.is_finite().then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refinement_leaves_a_round_off_residual_on_nearly_singular_systems() {
        // Three nearly parallel unit rows, as for the sphere touching two nearby tangents.
        let h = 1e-4;
        let rows = DMat3::from_cols(
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, h, 0.0).normalize(),
            DVec3::new(1.0, 0.5 * h, h * h).normalize(),
        )
        .transpose();
        let rhs = DVec3::new(0.0, 0.5 * h * h, 0.3 * h * h);
        let plain = rows.inverse() * rhs;
        let refined = solve_refined(rows, rhs).unwrap();
        let residual = |x: DVec3| (rows * x - rhs).abs().max_element();
        assert!(residual(refined) < 1e-17, "{}", residual(refined));
        assert!(residual(refined) <= residual(plain));
        assert!(solve_refined(DMat3::ZERO, rhs).is_none());
    }
}
