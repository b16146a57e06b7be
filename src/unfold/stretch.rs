//! How much a surface that is not developable must stretch to lie flat, measured: a grid of
//! triangles over its parameter domain (the edges of the grid and both diagonals of each
//! cell, at their lengths on the surface) is laid in the plane by least squares — the
//! relative length changes minimized by Levenberg–Marquardt from the surface's first
//! fundamental form at the middle — and the largest relative change left is the stretch.
//! Any unrolling changes some lengths by about as much (a geodesic disc of radius r has
//! circumference 2πr (1 − K r²/6 + …)); the measured value is what this one needs. The
//! normal equations are small and dense (2 unknowns per grid point), solved by Cholesky's
//! method: a linear-algebra crate for this one solve would weigh more than it serves.

use crate::bezier::PiecewiseSurface;
use crate::error::{Error, Result};
use glam::{DVec2, DVec3};

/// Grid cells along each parameter.
const CELLS: usize = 10;
/// Levenberg–Marquardt steps.
const STEPS: usize = 40;

/// The largest relative change of length of a least-squares flattening of `surface`.
pub(crate) fn least_squares_stretch(surface: &PiecewiseSurface) -> Result<f64> {
    let (u0, u1) = surface.domain_u();
    let (v0, v1) = surface.domain_v();
    let n = CELLS + 1;
    let param = |i: usize, j: usize| {
        (
            u0 + (u1 - u0) * i as f64 / CELLS as f64,
            v0 + (v1 - v0) * j as f64 / CELLS as f64,
        )
    };
    let points: Vec<DVec3> = (0..n * n)
        .map(|k| {
            let (u, v) = param(k / n, k % n);
            surface.eval(u, v)
        })
        .collect();
    let mut springs: Vec<(usize, usize, f64)> = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let k = i * n + j;
            let mut spring = |m: usize| {
                let length = points[k].distance(points[m]);
                if length > 1e-12 {
                    springs.push((k, m, length));
                }
            };
            if i + 1 < n {
                spring(k + n);
            }
            if j + 1 < n {
                spring(k + 1);
            }
            if i + 1 < n && j + 1 < n {
                spring(k + n + 1);
            }
            if i + 1 < n && j > 0 {
                spring(k + n - 1);
            }
        }
    }
    let (uc, vc) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
    let [_, su, sv] = surface.eval_d1(uc, vc);
    let (e, f, g) = (su.dot(su), su.dot(sv), sv.dot(sv));
    if !(e > 0.0 && e * g - f * f > 0.0) {
        return Err(Error::no_solution(
            "the surface is singular at the middle of its domain: its stretch is not measured",
        ));
    }
    let (a, b, c) = (e.sqrt(), f / e.sqrt(), ((e * g - f * f) / e).sqrt());
    let mut x: Vec<DVec2> = (0..n * n)
        .map(|k| {
            let (u, v) = param(k / n, k % n);
            let (du, dv) = (u - uc, v - vc);
            DVec2::new(a * du + b * dv, c * dv)
        })
        .collect();
    let mut lambda = 1e-3;
    let mut cost = energy(&x, &springs);
    for _ in 0..STEPS {
        let step = lm_step(&x, &springs, lambda);
        let Some(step) = step else { break };
        let trial: Vec<DVec2> = x.iter().zip(&step).map(|(p, d)| *p + *d).collect();
        let trial_cost = energy(&trial, &springs);
        if trial_cost < cost {
            x = trial;
            cost = trial_cost;
            lambda = (lambda * 0.3).max(1e-12);
        } else {
            lambda *= 10.0;
        }
    }
    Ok(springs
        .iter()
        .map(|&(i, j, l)| ((x[i].distance(x[j]) - l) / l).abs())
        .fold(0.0, f64::max))
}

fn energy(x: &[DVec2], springs: &[(usize, usize, f64)]) -> f64 {
    springs
        .iter()
        .map(|&(i, j, l)| ((x[i].distance(x[j]) - l) / l).powi(2))
        .sum()
}

/// One damped Gauss–Newton step: (JᵀJ + λ diag(JᵀJ) + λ I) δ = −Jᵀr.
fn lm_step(x: &[DVec2], springs: &[(usize, usize, f64)], lambda: f64) -> Option<Vec<DVec2>> {
    let m = 2 * x.len();
    let mut a = vec![0.0; m * m];
    let mut rhs = vec![0.0; m];
    for &(i, j, l) in springs {
        let d = x[i] - x[j];
        let length = d.length().max(1e-300);
        let r = (length - l) / l;
        let grad = d / (length * l);
        let rows = [
            (2 * i, grad.x),
            (2 * i + 1, grad.y),
            (2 * j, -grad.x),
            (2 * j + 1, -grad.y),
        ];
        for &(p, gp) in &rows {
            rhs[p] -= gp * r;
            for &(q, gq) in &rows {
                a[p * m + q] += gp * gq;
            }
        }
    }
    for p in 0..m {
        a[p * m + p] += lambda * (a[p * m + p] + 1.0);
    }
    let delta = cholesky_solve(&mut a, &mut rhs, m)?;
    Some(delta.chunks(2).map(|c| DVec2::new(c[0], c[1])).collect())
}

/// Solves A x = b for symmetric positive definite A (row-major, overwritten).
fn cholesky_solve(a: &mut [f64], b: &mut [f64], m: usize) -> Option<Vec<f64>> {
    for j in 0..m {
        let mut d = a[j * m + j];
        for k in 0..j {
            d -= a[j * m + k] * a[j * m + k];
        }
        if d.is_nan() || d <= 0.0 {
            return None;
        }
        let d = d.sqrt();
        a[j * m + j] = d;
        for i in j + 1..m {
            let mut s = a[i * m + j];
            for k in 0..j {
                s -= a[i * m + k] * a[j * m + k];
            }
            a[i * m + j] = s / d;
        }
    }
    for i in 0..m {
        let mut s = b[i];
        for k in 0..i {
            s -= a[i * m + k] * b[k];
        }
        b[i] = s / a[i * m + i];
    }
    for i in (0..m).rev() {
        let mut s = b[i];
        for k in i + 1..m {
            s -= a[k * m + i] * b[k];
        }
        b[i] = s / a[i * m + i];
    }
    Some(b.to_vec())
}
