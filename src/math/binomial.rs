//! Binomial coefficients as f64, from a Pascal triangle built once, with their reciprocals
//! (Bernstein products and degree elevation divide by them in inner loops).

use std::sync::OnceLock;

/// Largest n for which `binomial(n, k)` is tabulated. Bernstein degrees in this crate stay
/// far below it (the highest, Möbius sweeps, are about 20).
pub(super) const MAX_BINOMIAL_N: usize = 128;

fn table() -> &'static [Vec<f64>] {
    static TABLE: OnceLock<Vec<Vec<f64>>> = OnceLock::new();
    TABLE.get_or_init(pascal_triangle)
}

fn reciprocal_table() -> &'static [Vec<f64>] {
    static TABLE: OnceLock<Vec<Vec<f64>>> = OnceLock::new();
    TABLE.get_or_init(|| {
        table()
            .iter()
            .map(|row| row.iter().map(|c| 1.0 / c).collect())
            .collect()
    })
}

fn pascal_triangle() -> Vec<Vec<f64>> {
    let mut rows: Vec<Vec<f64>> = Vec::with_capacity(MAX_BINOMIAL_N + 1);
    for n in 0..=MAX_BINOMIAL_N {
        let mut row = vec![1.0; n + 1];
        for k in 1..n {
            row[k] = rows[n - 1][k - 1] + rows[n - 1][k];
        }
        rows.push(row);
    }
    rows
}

/// `n choose k`; zero when `k > n`.
///
/// # Panics
/// If `n > MAX_BINOMIAL_N` (degrees are validated long before they get here).
pub(crate) fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    table()[n][k]
}

/// The row `n choose 0..=n`.
///
/// # Panics
/// If `n > MAX_BINOMIAL_N`.
pub(crate) fn binomial_row(n: usize) -> &'static [f64] {
    &table()[n]
}

/// The row `1 / (n choose k)`, k = 0..=n.
///
/// # Panics
/// If `n > MAX_BINOMIAL_N`.
pub(crate) fn reciprocal_binomial_row(n: usize) -> &'static [f64] {
    &reciprocal_table()[n]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_values() {
        assert_eq!(binomial(0, 0), 1.0);
        assert_eq!(binomial(5, 2), 10.0);
        assert_eq!(binomial(9, 4), 126.0);
        assert_eq!(binomial(3, 4), 0.0);
        assert_eq!(binomial(40, 20), 137846528820.0);
        assert_eq!(binomial_row(4), [1.0, 4.0, 6.0, 4.0, 1.0]);
        assert_eq!(reciprocal_binomial_row(4)[2], 1.0 / 6.0);
    }
}
