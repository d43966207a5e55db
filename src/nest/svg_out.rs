//! The nest as an SVG (issue 41 §5: `kerfcam nest -o NEST.svg`): in mm at
//! true size (width/height in mm, a viewBox in mm), the sheets side by side
//! as [`super::output::to_dxf`] draws them, each sheet an Inkscape layer
//! holding its outline and one group per placed copy, labelled with the
//! part's name and copy. Arcs are written as SVG arcs (exact), so the file
//! reads back into the same loops ([`crate::svg`]).

use std::fmt::Write;

use super::output::{crop_segments, placed_loops, Overlay, SHEET_GAP};
use super::{Nest, NestJob, Sheets};
use crate::geom::{Point, Segment};
use crate::svg::write::{escape, header, path_data, PageMap};

/// The whole nest as an SVG document.
pub fn to_svg(job: &NestJob, nest: &Nest) -> String {
    to_svg_with(job, nest, &[])
}

/// [`to_svg`] with `overlays` over their sheets: on each sheet, a group
/// per layer (class and Inkscape label the layer's name) holding one
/// group per overlay, its name in `data-name`.
pub fn to_svg_with(job: &NestJob, nest: &Nest, overlays: &[Overlay]) -> String {
    let mut offsets = Vec::new();
    let (mut x, mut h) = (0.0, 0.0f64);
    for s in &nest.sheets {
        offsets.push(x);
        x += s.width * (1.0 + SHEET_GAP);
        h = h.max(s.height);
    }
    let w = (x - nest.sheets.last().map_or(0.0, |s| s.width * SHEET_GAP)).max(1.0);
    let h = h.max(1.0);
    let mut out = header(w, h, "kerfcam nest", None);
    for (k, s) in nest.sheets.iter().enumerate() {
        // Every digit: the nest's loops read back bit for bit.
        let map = PageMap {
            dx: offsets[k],
            top: h,
            decimals: None,
        };
        let n = k + 1;
        let _ = writeln!(
            out,
            "<g id=\"sheet-{n}\" inkscape:groupmode=\"layer\" inkscape:label=\"Sheet {n}\">"
        );
        let sheet_paths: Vec<String> = match &job.sheets {
            Sheets::Remnant { outline, no_go } => std::iter::once(outline)
                .chain(no_go)
                .map(|l| path_data(l, &map, true))
                .collect(),
            _ => {
                let c = [
                    (0.0, 0.0),
                    (s.width, 0.0),
                    (s.width, s.height),
                    (0.0, s.height),
                ]
                .map(|(a, b)| Point::new(a, b));
                vec![path_data(&closed(&c), &map, true)]
            }
        };
        for d in sheet_paths {
            let _ = writeln!(
                out,
                "<path class=\"sheet\" d=\"{d}\" fill=\"none\" stroke=\"#808080\"/>"
            );
        }
        let crop = crop_segments(job, nest, k);
        if !crop.is_empty() {
            let d = path_data(&crop, &map, false);
            let _ = writeln!(
                out,
                "<path class=\"remnant-crop\" d=\"{d}\" fill=\"none\" stroke=\"#0000ff\"/>"
            );
        }
        for p in nest.placements.iter().filter(|p| p.sheet == k) {
            let name = escape(&job.parts[p.part].name);
            let copy = p.copy + 1;
            let _ = writeln!(
                out,
                "<g class=\"part\" inkscape:label=\"{name} #{copy}\" data-part=\"{name}\" data-copy=\"{copy}\">"
            );
            for l in placed_loops(job, p) {
                let d = path_data(&l, &map, true);
                let _ = writeln!(out, "<path d=\"{d}\" fill=\"none\" stroke=\"#000000\"/>");
            }
            out.push_str("</g>\n");
        }
        let mut layers: Vec<&str> = Vec::new();
        for o in overlays.iter().filter(|o| o.sheet == k) {
            if !layers.contains(&o.layer) {
                layers.push(o.layer);
            }
        }
        for layer in layers {
            let layer = escape(layer);
            let _ = writeln!(out, "<g class=\"{layer}\" inkscape:label=\"{layer}\">");
            for o in overlays.iter().filter(|o| o.sheet == k && escape(o.layer) == layer) {
                let name = escape(o.name);
                let _ = writeln!(out, "<g data-name=\"{name}\">");
                for path in o.paths.iter().filter(|p| p.len() >= 2) {
                    let mut d = String::new();
                    for (i, q) in path.iter().enumerate() {
                        let (x, y) = map.at(*q);
                        let _ = write!(d, "{}{x} {y}", if i == 0 { "M" } else { " L" });
                    }
                    let _ = writeln!(out, "<path d=\"{d}\" fill=\"none\" stroke=\"#c00000\"/>");
                }
                out.push_str("</g>\n");
            }
            out.push_str("</g>\n");
        }
        out.push_str("</g>\n");
    }
    out.push_str("</svg>\n");
    out
}

/// A closed chain of lines through the points.
fn closed(pts: &[Point]) -> Vec<Segment> {
    (0..pts.len())
        .map(|i| Segment::line(pts[i], pts[(i + 1) % pts.len()]))
        .filter(|s| s.a != s.b)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[cfg(feature = "svg")]
    fn arcs_and_lines_read_back_the_same() {
        // A 20 × 10 slot: two lines and two half circles, counter-clockwise.
        let segs = vec![
            Segment::line(Point::new(5.0, 0.0), Point::new(15.0, 0.0)),
            Segment {
                a: Point::new(15.0, 0.0),
                b: Point::new(15.0, 10.0),
                bulge: 1.0,
            },
            Segment::line(Point::new(15.0, 10.0), Point::new(5.0, 10.0)),
            Segment {
                a: Point::new(5.0, 10.0),
                b: Point::new(5.0, 0.0),
                bulge: 1.0,
            },
        ];
        let map = PageMap {
            dx: 0.0,
            top: 10.0,
            decimals: None,
        };
        let d = path_data(&segs, &map, true);
        let svg = format!(
            "<svg width=\"20mm\" height=\"10mm\" viewBox=\"0 0 20 10\"><path d=\"{d}\"/></svg>"
        );
        let back = crate::svg::parse(svg.as_bytes(), &crate::dxf::ReadOptions::DEFAULT).unwrap();
        let got: Vec<Segment> = crate::svg::all_segments(&back).copied().collect();
        let area = |v: &[Segment]| v.iter().map(Segment::area_term).sum::<f64>();
        assert!(
            (area(&got) - area(&segs)).abs() < 1e-9,
            "{} {}",
            area(&got),
            area(&segs)
        );
        assert!((area(&segs) - (100.0 + std::f64::consts::PI * 25.0)).abs() < 1e-9);
    }
}
