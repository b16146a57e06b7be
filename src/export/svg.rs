//! Flat patterns as SVG 1.1 drawings (SVG 1.1, §8.3 path data, §F.6 elliptical arcs), at
//! true scale: one user unit is one millimetre. The outline is one closed path of `L` and
//! `A` (circular arc) commands, the bend lines are dashed paths. SVG's y axis points down,
//! so y is negated (the pattern is seen from the side its normals point to).

use super::number;
use crate::model::{FlatPattern, PatternEdge};
use glam::DVec2;
use std::f64::consts::PI;
use std::fmt::Write;

/// Margin around the pattern, millimetres.
const MARGIN: f64 = 5.0;

fn xy(p: DVec2) -> String {
    format!("{} {}", number(p.x), number(-p.y))
}

/// The path commands that draw `edge` from its start.
fn command(edge: &PatternEdge) -> String {
    match *edge {
        PatternEdge::Line { to, .. } => format!("L {}", xy(to)),
        PatternEdge::Arc {
            radius, to, sweep, ..
        } => {
            let large = u8::from(sweep.abs() > PI);
            // Counter-clockwise in the pattern is clockwise on the y-down canvas: flag 1.
            let clockwise_on_canvas = u8::from(sweep > 0.0);
            let r = number(radius);
            format!("A {r} {r} 0 {large} {clockwise_on_canvas} {}", xy(to))
        }
    }
}

fn path(edges: &[PatternEdge], close: bool) -> String {
    let mut d = format!("M {}", xy(edges[0].start()));
    for edge in edges {
        d.push(' ');
        d.push_str(&command(edge));
    }
    if close {
        d.push_str(" Z");
    }
    d
}

/// The flat pattern as an SVG document titled `title`.
pub fn pattern_to_svg(title: &str, pattern: &FlatPattern) -> String {
    let (lo, hi) = pattern.bounds();
    let (width, height) = (hi.x - lo.x + 2.0 * MARGIN, hi.y - lo.y + 2.0 * MARGIN);
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"{} {} {w} {h}\">",
        number(lo.x - MARGIN),
        number(-hi.y - MARGIN),
        w = number(width),
        h = number(height)
    );
    let _ = writeln!(out, "  <title>{}</title>", escape(title));
    let _ = writeln!(
        out,
        "  <path id=\"outline\" fill=\"none\" stroke=\"black\" stroke-width=\"0.2\" d=\"{}\"/>",
        path(&pattern.outline, true)
    );
    for (k, hole) in pattern.holes.iter().enumerate() {
        let _ = writeln!(
            out,
            "  <path id=\"hole{k}\" fill=\"none\" stroke=\"black\" stroke-width=\"0.2\" d=\"{}\"/>",
            path(hole, true)
        );
    }
    for (k, bend) in pattern.bend_lines.iter().enumerate() {
        let _ = writeln!(
            out,
            "  <path id=\"bend{k}\" fill=\"none\" stroke=\"red\" stroke-width=\"0.1\" stroke-dasharray=\"1 1\" d=\"{}\"/>",
            path(std::slice::from_ref(bend), false)
        );
    }
    out.push_str("</svg>\n");
    out
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arcs_keep_their_sense_on_the_flipped_canvas() {
        let quarter = PatternEdge::Arc {
            center: DVec2::ZERO,
            radius: 2.0,
            from: DVec2::new(2.0, 0.0),
            to: DVec2::new(0.0, 2.0),
            sweep: PI / 2.0,
        };
        assert_eq!(command(&quarter), "A 2 2 0 0 1 0 -2");
        assert_eq!(command(&quarter.reversed()), "A 2 2 0 0 0 2 0");
        let pattern = FlatPattern {
            outline: vec![
                quarter,
                PatternEdge::Line {
                    from: DVec2::new(0.0, 2.0),
                    to: DVec2::ZERO,
                },
                PatternEdge::Line {
                    from: DVec2::ZERO,
                    to: DVec2::new(2.0, 0.0),
                },
            ],
            holes: vec![],
            bend_lines: vec![],
        };
        let svg = pattern_to_svg("a & b", &pattern);
        assert!(
            svg.contains("d=\"M 2 0 A 2 2 0 0 1 0 -2 L 0 0 L 2 0 Z\""),
            "{svg}"
        );
        assert!(svg.contains("viewBox=\"-5 -7 12 12\""), "{svg}");
        assert!(svg.contains("<title>a &amp; b</title>"));
    }
}
