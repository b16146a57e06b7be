//! Flat patterns as DXF R12 (AC1009) files, the DXF every cutting machine's CAM reads
//! (AutoCAD DXF Reference, ENTITIES section): true `LINE` and `ARC` entities, never
//! polylines. The outline and its holes are on layer `CUT`, the bend lines on layer `BEND`. An `ARC` runs
//! counter-clockwise from its start to its end angle (degrees) about the z axis.

use super::number;
use crate::model::{FlatPattern, PatternEdge};
use std::fmt::Write;

/// Group code / value pairs of one entity.
fn entity(out: &mut String, pairs: &[(u16, String)]) {
    for (code, value) in pairs {
        let _ = write!(out, "{code}\n{value}\n");
    }
}

fn edge_entity(out: &mut String, edge: &PatternEdge, layer: &str) {
    let layer = layer.to_string();
    match *edge {
        PatternEdge::Line { from, to } => entity(
            out,
            &[
                (0, "LINE".into()),
                (8, layer),
                (10, number(from.x).to_string()),
                (20, number(from.y).to_string()),
                (30, "0".into()),
                (11, number(to.x).to_string()),
                (21, number(to.y).to_string()),
                (31, "0".into()),
            ],
        ),
        PatternEdge::Arc {
            center,
            radius,
            from,
            to,
            sweep,
        } => {
            // DXF arcs are counter-clockwise: a clockwise arc is drawn from its end.
            let (a, b) = if sweep > 0.0 { (from, to) } else { (to, from) };
            let degrees = |p: glam::DVec2| (p - center).to_angle().to_degrees().rem_euclid(360.0);
            entity(
                out,
                &[
                    (0, "ARC".into()),
                    (8, layer),
                    (10, number(center.x).to_string()),
                    (20, number(center.y).to_string()),
                    (30, "0".into()),
                    (40, number(radius).to_string()),
                    (50, number(degrees(a)).to_string()),
                    (51, number(degrees(b)).to_string()),
                ],
            )
        }
    }
}

/// The flat pattern as a DXF R12 file.
pub fn pattern_to_dxf(pattern: &FlatPattern) -> String {
    let bends: Vec<(&PatternEdge, &str)> = pattern.bend_lines.iter().map(|e| (e, "BEND")).collect();
    dxf(pattern, &bends)
}

/// The flat pattern of a sheet body as a DXF R12 file, its bend lines on the layers
/// `BEND_UP` and `BEND_DOWN` (`up[k]` for bend line k: the flange rises towards the viewer).
pub fn sheet_pattern_to_dxf(pattern: &FlatPattern, up: &[bool]) -> String {
    let bends: Vec<(&PatternEdge, &str)> = pattern
        .bend_lines
        .iter()
        .zip(up)
        .map(|(e, &u)| (e, if u { "BEND_UP" } else { "BEND_DOWN" }))
        .collect();
    dxf(pattern, &bends)
}

fn dxf(pattern: &FlatPattern, bends: &[(&PatternEdge, &str)]) -> String {
    let mut out = String::new();
    entity(
        &mut out,
        &[
            (0, "SECTION".into()),
            (2, "HEADER".into()),
            (9, "$ACADVER".into()),
            (1, "AC1009".into()),
            (0, "ENDSEC".into()),
            (0, "SECTION".into()),
            (2, "ENTITIES".into()),
        ],
    );
    for edge in pattern.outline.iter().chain(pattern.holes.iter().flatten()) {
        edge_entity(&mut out, edge, "CUT");
    }
    for (edge, layer) in bends {
        edge_entity(&mut out, edge, layer);
    }
    entity(&mut out, &[(0, "ENDSEC".into()), (0, "EOF".into())]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use std::f64::consts::PI;

    #[test]
    fn clockwise_arcs_are_written_counter_clockwise() {
        let arc = PatternEdge::Arc {
            center: DVec2::ZERO,
            radius: 2.0,
            from: DVec2::new(0.0, 2.0),
            to: DVec2::new(2.0, 0.0),
            sweep: -PI / 2.0,
        };
        let pattern = FlatPattern {
            outline: vec![arc],
            holes: vec![],
            bend_lines: vec![PatternEdge::Line {
                from: DVec2::ZERO,
                to: DVec2::X,
            }],
        };
        let dxf = pattern_to_dxf(&pattern);
        assert!(
            dxf.contains("0\nARC\n8\nCUT\n10\n0\n20\n0\n30\n0\n40\n2\n50\n0\n51\n90\n"),
            "{dxf}"
        );
        assert!(dxf.contains("0\nLINE\n8\nBEND\n10\n0\n20\n0\n30\n0\n11\n1\n21\n0\n31\n0\n"));
        assert!(dxf.ends_with("0\nENDSEC\n0\nEOF\n"));
        assert!(!dxf.contains("POLYLINE"));
    }
}
