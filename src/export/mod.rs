//! Files for CAD, mesh and cutting tools, written from the library's exact geometry. Each
//! writer returns the file's text; writing it to disk (atomically) is the caller's job.
//!
//! | module | format | holds | read back in the tests by |
//! | --- | --- | --- | --- |
//! | [`step`] | STEP AP214 (ISO 10303-21) | rational B-spline surfaces as faces, curves | FreeCAD (OpenCascade's reader) |
//! | [`occ_brep`] | OpenCascade's B-rep text (`CASCADE Topology V1`) and binary B-rep (`Open CASCADE Topology V3`) | a B-rep solid or shell as the kernel holds it | OpenCascade's `BRepTools::Read` and `BRepCheck_Analyzer` (Python tests) |
//! | [`vtk`] | VTK XML PolyData `.vtp` | triangle meshes with normals | VTK's `vtkXMLPolyDataReader` |
//! | [`obj`] | Wavefront `.obj` | polygon meshes with normals | FreeCAD's mesh reader |
//! | [`openscad`] | OpenSCAD `.scad` | closed `polyhedron()` solids, RMF transforms for sweeps | OpenSCAD (renders to STL) |
//! | [`svg`] | SVG 1.1 | flat patterns: true arcs and lines, in millimetres | — (a drawing) |
//! | [`dxf`] | DXF R12 (AC1009) | flat patterns: `LINE` and `ARC` entities | FreeCAD's DXF reader |
//!
//! Numbers are written in their shortest round-trip representation (Ryu), so every
//! coordinate reads back as the same double.

use crate::bezier::NurbsCurve;

pub mod dxf;
pub mod obj;
pub mod occ_brep;
pub mod openscad;
pub mod step;
pub mod svg;
pub mod vtk;

/// The shortest decimal text that reads back as `x` (`1`, `0.1`, `1e-7`; −0 as `0`),
/// written where it is formatted: no allocation per number (the files hold a great many).
/// Fractions by Ryu (the `ryu` crate: some 3× faster than the standard library's
/// formatting, which the B-rep texts of large parts spend most of their time in).
fn number(x: f64) -> Number {
    Number(x + 0.0)
}

/// A number formatted by [`number`].
#[derive(Clone, Copy)]
struct Number(f64);

impl Number {
    /// The text, handed to `f`: whole numbers below 1e16 as integers (exact below 2⁵³, and
    /// every whole double up to 1e16 fits an i64), everything else in Ryu's shortest
    /// round-trip form.
    fn with_text<R>(self, f: impl FnOnce(&str) -> R) -> R {
        if self.0.fract() == 0.0 && self.0.abs() < 1e16 {
            f(itoa::Buffer::new().format(self.0 as i64))
        } else {
            f(ryu::Buffer::new().format(self.0))
        }
    }
}

impl std::fmt::Display for Number {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.with_text(|text| f.write_str(text))
    }
}

/// Appends a space and each of `values` as [`number`] writes it: the writers' inner loops,
/// without the formatting machinery, which costs them more than the digits themselves.
fn push_numbers(text: &mut String, values: impl IntoIterator<Item = f64>) {
    for x in values {
        text.push(' ');
        number(x).with_text(|digits| text.push_str(digits));
    }
}

/// Appends a space and each of `counts` (integers of the writers' records).
fn push_counts(text: &mut String, counts: impl IntoIterator<Item = usize>) {
    for n in counts {
        text.push(' ');
        text.push_str(itoa::Buffer::new().format(n));
    }
}

/// A clamped NURBS curve's parameter range.
pub(crate) fn curve_range(curve: &NurbsCurve) -> (f64, f64) {
    (curve.knots[0], curve.knots[curve.knots.len() - 1])
}

/// Distinct knots and their multiplicities, in order.
fn knot_runs(knots: &[f64]) -> impl Iterator<Item = (f64, usize)> + Clone + '_ {
    knots.chunk_by(|a, b| a == b).map(|run| (run[0], run.len()))
}

/// Distinct knots and their multiplicities.
fn knots_and_multiplicities(knots: &[f64]) -> (Vec<f64>, Vec<usize>) {
    knot_runs(knots).unzip()
}

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn numbers_round_trip() {
        for x in [0.0, 1.0, -2.5, 1e-7, 1.5e300, 0.1, std::f64::consts::PI] {
            assert_eq!(number(x).to_string().parse::<f64>().unwrap(), x);
        }
        assert_eq!(number(2.0).to_string(), "2");
        assert_eq!(number(-0.0).to_string(), "0");
    }

    /// The text reads back as the same double, with no more significant digits than Rust's
    /// own shortest form and no `.0` after a whole number, for whole numbers on both sides
    /// of 1e16, fractions and any bit pattern.
    #[test]
    fn numbers_are_the_shortest_form_without_a_trailing_point_zero() {
        // Significant digits: those of the mantissa without leading and trailing zeros.
        let digits = |s: &str| {
            let mantissa = s.split(['e', 'E']).next().unwrap_or("");
            let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
            digits.trim_matches('0').len()
        };
        let check = |x: f64| {
            let text = number(x).to_string();
            let back: f64 = text.parse().unwrap();
            assert!(
                back == x + 0.0 || (x.is_nan() && back.is_nan()),
                "{x:e}: {text}"
            );
            assert!(!text.ends_with(".0"), "{x:e}: {text}");
            let shortest = format!("{:?}", x + 0.0);
            assert!(
                digits(&text) <= digits(&shortest),
                "{x:e}: {text} against {shortest}"
            );
        };
        let mut bits = 0x9E37_79B9_7F4A_7C15u64;
        let mut values = vec![
            1e15,
            1e16,
            9_999_999_999_999_998.0,
            -123.0,
            4.5e15,
            f64::NAN,
        ];
        values.extend([
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN_POSITIVE,
        ]);
        for _ in 0..20_000 {
            bits ^= bits << 13;
            bits ^= bits >> 7;
            bits ^= bits << 17;
            values.push(f64::from_bits(bits));
            values.push((bits >> 11) as f64);
            values.push(((bits >> 40) as f64) * 0.25);
        }
        for x in values {
            check(x);
        }
    }
}
