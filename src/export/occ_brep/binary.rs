//! The shape set in OpenCascade's binary B-rep form (`BinTools::Write`, `Open CASCADE
//! Topology V3`): section headers as text, then every number as it is in memory —
//! doubles as little-endian IEEE 754, counts and numbers of curves, surfaces and shapes
//! as 32-bit integers, degrees as 16-bit ones, flags and codes as single bytes
//! (OCCT's `BinTools_ShapeSet`, `BinTools_CurveSet`, `BinTools_Curve2dSet`,
//! `BinTools_SurfaceSet`). Each curve on a face carries its end points in the face's
//! parameter plane (version 2 on); vertices list their point representations from a code
//! (version 3). The file ends with the reference to the root as `BinTools::Read` takes it,
//! or as FreeCAD's `Part.Shape.importBinary` does ([`OccBinary`]).

use super::{Curve2d, Curve3d, Elementary, Kind, Record, ShapeSet, Surface};
use crate::bezier::{NurbsCurve, NurbsSurface};
use crate::error::{invalid, Result};
use crate::export::knot_runs;
use crate::model::{Brep, BrepSurface};
use glam::DVec3;

/// OpenCascade's shape types (`TopAbs_ShapeEnum`).
const COMPOUND: u8 = 0;
const SOLID: u8 = 2;
const SHELL: u8 = 3;
const FACE: u8 = 4;
const WIRE: u8 = 5;
const EDGE: u8 = 6;
const VERTEX: u8 = 7;

/// Which reader a binary B-rep's root reference is written for: the set before it is the
/// same.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OccReader {
    /// OpenCascade's `BinTools::Read` (C++, and build123d and CadQuery through OCP's
    /// `BinTools.Read_s`): the root's orientation (a byte), its number from the last and its
    /// location (32-bit integers).
    BinTools,
    /// FreeCAD's `Part.Shape.importBinary`, as its `exportBinary` writes the root: its
    /// number, location and orientation (32-bit integers).
    FreeCad,
}

/// OpenCascade's binary B-rep of a shape: the shape set, and the root's number in it.
#[derive(Clone, Debug, PartialEq)]
pub struct OccBinary {
    set: Vec<u8>,
    shapes: usize,
}

impl OccBinary {
    /// The shape set: everything but the root reference.
    pub fn set(&self) -> &[u8] {
        &self.set
    }

    /// The reference to the root shape that ends the file, as `reader` takes it.
    pub fn root(&self, reader: OccReader) -> Vec<u8> {
        let mut bytes = Vec::with_capacity(12);
        match reader {
            OccReader::BinTools => {
                bytes.push(0);
                put_int(&mut bytes, 1);
                put_int(&mut bytes, 0);
            }
            OccReader::FreeCad => {
                put_int(&mut bytes, self.shapes);
                put_int(&mut bytes, 0);
                put_int(&mut bytes, 0);
            }
        }
        bytes
    }

    /// The whole file for `reader`.
    pub fn file(&self, reader: OccReader) -> Vec<u8> {
        [&self.set[..], &self.root(reader)].concat()
    }
}

/// The binary B-rep of `brep` (module notes of the parent).
pub fn brep_to_occ_binary(brep: &Brep) -> Result<OccBinary> {
    let set = ShapeSet::of(brep)?;
    if set.shapes.len() > i32::MAX as usize {
        return invalid!(
            "{} shapes are more than the binary format counts",
            set.shapes.len()
        );
    }
    let mut out = Vec::with_capacity(estimated_size(brep));
    out.extend_from_slice(b"\nOpen CASCADE Topology V3 (c)\nLocations 0\n");
    header(&mut out, "Curve2ds", set.curves_2d.len());
    for curve in &set.curves_2d {
        curve_2d(&mut out, curve)?;
    }
    header(&mut out, "Curves", set.curves.len());
    for curve in &set.curves {
        match curve {
            Curve3d::Elementary(curve) => elementary(&mut out, curve),
            Curve3d::Nurbs(curve) => bspline(&mut out, curve, 3)?,
        }
    }
    out.extend_from_slice(b"Polygon3D 0\nPolygonOnTriangulations 0\n");
    header(&mut out, "Surfaces", set.surfaces.len());
    for surface in &set.surfaces {
        match surface {
            Surface::Elementary(surface) => elementary(&mut out, surface),
            Surface::Nurbs(surface) => nurbs_surface(&mut out, surface)?,
        }
    }
    out.extend_from_slice(b"Triangulations 0\n\n");
    shapes(&mut out, &set);
    Ok(OccBinary {
        set: out,
        shapes: set.shapes.len(),
    })
}

/// Bytes of the poles and weights, the bulk of the file.
fn estimated_size(brep: &Brep) -> usize {
    let surfaces: usize = brep
        .faces
        .iter()
        .map(|f| match &f.surface {
            BrepSurface::Nurbs(s) => s.poles.len() * 32,
            BrepSurface::Plane { .. } => 100,
        })
        .sum();
    let curves: usize = brep.edges.iter().map(|e| e.curve.poles.len() * 32).sum();
    1024 + surfaces + 2 * curves
}

/// A section's header: its name and count, as text.
fn header(out: &mut Vec<u8>, name: &str, count: usize) {
    out.extend_from_slice(name.as_bytes());
    out.push(b' ');
    out.extend_from_slice(itoa::Buffer::new().format(count).as_bytes());
    out.push(b'\n');
}

fn put_real(out: &mut Vec<u8>, x: f64) {
    out.extend_from_slice(&x.to_le_bytes());
}

fn put_reals(out: &mut Vec<u8>, values: impl IntoIterator<Item = f64>) {
    for x in values {
        put_real(out, x);
    }
}

fn put_vectors(out: &mut Vec<u8>, vectors: impl IntoIterator<Item = DVec3>) {
    for v in vectors {
        put_reals(out, v.to_array());
    }
}

/// A count or number as a 32-bit integer (every one is checked to fit where it is made:
/// the shapes above, poles and knots in [`counts`]).
fn put_int(out: &mut Vec<u8>, n: usize) {
    out.extend_from_slice(&(n as i32).to_le_bytes());
}

fn put_bool(out: &mut Vec<u8>, b: bool) {
    out.push(u8::from(b));
}

/// A degree as the format's 16-bit character.
fn put_degree(out: &mut Vec<u8>, degree: usize) -> Result<()> {
    let Ok(degree) = u16::try_from(degree) else {
        return invalid!("degree {degree} is above the binary format's 65535");
    };
    out.extend_from_slice(&degree.to_le_bytes());
    Ok(())
}

/// Pole and knot counts, refused above what a 32-bit integer holds.
fn counts(poles: usize, knots: usize) -> Result<()> {
    if poles.max(knots) > i32::MAX as usize {
        return invalid!("{poles} poles are more than the binary format counts");
    }
    Ok(())
}

/// A 2-D line (code 1: origin, direction) or B-spline (code 7).
fn curve_2d(out: &mut Vec<u8>, curve: &Curve2d) -> Result<()> {
    match curve {
        Curve2d::Line { origin, direction } => {
            out.push(1);
            put_reals(out, [origin.0, origin.1, direction.0, direction.1]);
        }
        Curve2d::Segment { from, to, range } => {
            // Rational (weights 1, as the text writes it), not periodic, degree 1, 2 poles,
            // 2 knots of multiplicity 2.
            out.extend_from_slice(&[7, 1, 0, 1, 0]);
            put_int(out, 2);
            put_int(out, 2);
            put_reals(out, [from.0, from.1, 1.0, to.0, to.1, 1.0]);
            put_real(out, range.0);
            put_int(out, 2);
            put_real(out, range.1);
            put_int(out, 2);
        }
        Curve2d::Nurbs(curve) => bspline(out, curve, 2)?,
    }
    Ok(())
}

/// A B-spline curve (code 7, rational, not periodic), its poles' first `dimension`
/// coordinates (2 in a parameter plane, 3 in space).
fn bspline(out: &mut Vec<u8>, curve: &NurbsCurve, dimension: usize) -> Result<()> {
    let knots = knot_runs(&curve.knots);
    let runs = knots.clone().count();
    counts(curve.poles.len(), runs)?;
    out.extend_from_slice(&[7, 1, 0]);
    put_degree(out, curve.degree)?;
    put_int(out, curve.poles.len());
    put_int(out, runs);
    for (&p, &w) in curve.poles.iter().zip(&curve.weights) {
        put_reals(out, p.to_array()[..dimension].iter().copied());
        put_real(out, w);
    }
    put_knots(out, knots);
    Ok(())
}

fn put_knots(out: &mut Vec<u8>, knots: impl Iterator<Item = (f64, usize)>) {
    for (k, m) in knots {
        put_real(out, k);
        put_int(out, m);
    }
}

/// A line, circle, plane, cylinder, cone or torus: its code, vectors and numbers.
fn elementary(out: &mut Vec<u8>, record: &Elementary) {
    out.push(record.code);
    put_vectors(out, record.vectors.iter().copied());
    put_reals(out, record.numbers.iter().copied());
}

/// A B-spline surface (code 9: rational both ways, not periodic; poles with v running
/// fastest, each followed by its weight).
fn nurbs_surface(out: &mut Vec<u8>, s: &NurbsSurface) -> Result<()> {
    let (ku, kv) = (knot_runs(&s.knots_u), knot_runs(&s.knots_v));
    let (nu, nv) = (ku.clone().count(), kv.clone().count());
    counts(s.poles.len(), nu.max(nv))?;
    out.extend_from_slice(&[9, 1, 1, 0, 0]);
    put_degree(out, s.degree_u)?;
    put_degree(out, s.degree_v)?;
    for n in [s.pole_count_u, s.pole_count_v, nu, nv] {
        put_int(out, n);
    }
    for (p, &w) in s.poles.iter().zip(&s.weights) {
        put_reals(out, [p.x, p.y, p.z, w]);
    }
    put_knots(out, ku);
    put_knots(out, kv);
    Ok(())
}

/// The `TShapes` table (after the blank line that ends the geometry, as OpenCascade writes
/// it): each shape's type, its data, its flags, the shapes it holds (orientation byte,
/// number from the last, location 0), `*` after them.
fn shapes(out: &mut Vec<u8>, set: &ShapeSet) {
    let n = set.shapes.len();
    header(out, "TShapes", n);
    for Record { kind, flags, held } in &set.shapes {
        match kind {
            Kind::Vertex(p) => {
                out.push(VERTEX);
                put_real(out, set.tolerance);
                put_vectors(out, [*p]);
                // No point representations.
                out.push(0);
            }
            Kind::Edge {
                curve,
                range,
                on_faces,
            } => {
                out.push(EDGE);
                put_real(out, set.tolerance);
                // Same parameter, same range, degenerate.
                out.extend_from_slice(&[1, 1, u8::from(curve.is_none())]);
                if let Some(c) = curve {
                    out.push(1);
                    put_int(out, *c);
                    put_int(out, 0);
                    put_reals(out, [range.0, range.1]);
                }
                for on in on_faces {
                    match on.curves[..] {
                        [forward, reversed, ..] => {
                            out.push(3);
                            put_int(out, forward);
                            put_int(out, reversed);
                            // GeomAbs_C0.
                            out.push(0);
                        }
                        [only] => {
                            out.push(2);
                            put_int(out, only);
                        }
                        [] => continue,
                    }
                    put_int(out, on.face + 1);
                    put_int(out, 0);
                    put_reals(out, [range.0, range.1]);
                    let [(u0, v0), (u1, v1)] = on.ends;
                    put_reals(out, [u0, v0, u1, v1]);
                }
                out.push(0);
            }
            Kind::Wire => out.push(WIRE),
            Kind::Face { natural, surface } => {
                out.push(FACE);
                put_bool(out, *natural);
                put_real(out, set.tolerance);
                put_int(out, *surface);
                put_int(out, 0);
                // No triangulation.
                out.push(0);
            }
            Kind::Shell => out.push(SHELL),
            Kind::Solid => out.push(SOLID),
            Kind::Compound => out.push(COMPOUND),
        }
        out.extend(flags.bytes().map(|b| b - b'0'));
        for &(reversed, position) in held {
            put_bool(out, reversed);
            put_int(out, n - position);
            put_int(out, 0);
        }
        out.push(b'*');
    }
}
