//! The SVG reader's speed beside the DXF reader's on the same parts (issue
//! 41's closing note): N plates, each a rounded rectangle with two round
//! holes and a slot, written as an Inkscape-like SVG (paths with arcs and a
//! cubic, a transform per part, a layer) and as a DXF (LWPOLYLINEs with
//! bulges, CIRCLEs); each read in turn, rounds interleaved, best of each.
//!
//! `cargo run --profile ci --example svg_speed [N]` (default 5000).
//!
//! Measured 2026-11-29 (ci profile, a shared 2-core machine, 5000 plates,
//! 20 000 entities each way): SVG 2.03 MB in 184.8 ms (11.0 MB/s, 27 051
//! parts/s); DXF 2.12 MB in 66.5 ms (31.9 MB/s, 75 242 parts/s): the SVG
//! reader takes 2.78x the DXF reader's time per part.

use std::time::Instant;

use kerfcam::dxf::ReadOptions;

fn svg(n: usize) -> String {
    let mut s = String::from(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" \
         width=\"4000mm\" height=\"4000mm\" viewBox=\"0 0 4000 4000\">\n<g inkscape:groupmode=\"layer\" inkscape:label=\"Cut\">\n",
    );
    for k in 0..n {
        let (x, y) = ((k % 70) as f64 * 55.0, (k / 70) as f64 * 35.0);
        s += &format!(
            "<g transform=\"translate({x} {y})\"><path style=\"fill:none;stroke:#000000;stroke-width:0.1\" \
             d=\"M 5,0 H 45 A 5,5 0 0 1 50,5 V 25 A 5,5 0 0 1 45,30 H 5 A 5,5 0 0 1 0,25 V 5 A 5,5 0 0 1 5,0 Z \
             M 12,15 C 12,18 16,18 16,15 C 16,12 12,12 12,15 Z\"/>\
             <circle cx=\"30\" cy=\"15\" r=\"4\" style=\"fill:none;stroke:#000000\"/>\
             <path d=\"m 38,12 h 4 a 3,3 0 0 1 0,6 h -4 a 3,3 0 0 1 0,-6 z\" style=\"fill:none;stroke:#000000\"/></g>\n"
        );
    }
    s + "</g>\n</svg>\n"
}

fn dxf(n: usize) -> String {
    let mut s = String::from(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n",
    );
    let b = (std::f64::consts::PI / 8.0).tan();
    for k in 0..n {
        let (x, y) = ((k % 70) as f64 * 55.0, (k / 70) as f64 * 35.0);
        let y = 4000.0 - y;
        let pts = [
            (5.0, 0.0, 0.0),
            (45.0, 0.0, -b),
            (50.0, -5.0, 0.0),
            (50.0, -25.0, -b),
            (45.0, -30.0, 0.0),
            (5.0, -30.0, -b),
            (0.0, -25.0, 0.0),
            (0.0, -5.0, -b),
        ];
        s += "0\nLWPOLYLINE\n8\nCut\n90\n8\n70\n1\n";
        for (px, py, bulge) in pts {
            s += &format!("10\n{}\n20\n{}\n", x + px, y + py);
            if bulge != 0.0 {
                s += &format!("42\n{bulge}\n");
            }
        }
        for (cx, cy, r) in [(14.0, -15.0, 2.0), (30.0, -15.0, 4.0)] {
            s += &format!(
                "0\nCIRCLE\n8\nCut\n10\n{}\n20\n{}\n40\n{r}\n",
                x + cx,
                y + cy
            );
        }
        s += &format!(
            "0\nLWPOLYLINE\n8\nCut\n90\n4\n70\n1\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n42\n1\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n42\n1\n",
            x + 38.0, y - 12.0, x + 42.0, y - 12.0, x + 42.0, y - 18.0, x + 38.0, y - 18.0
        );
    }
    s + "0\nENDSEC\n0\nEOF\n"
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5000);
    let (s, d) = (svg(n), dxf(n));
    let opts = ReadOptions::DEFAULT;
    let (mut best_svg, mut best_dxf) = (f64::INFINITY, f64::INFINITY);
    let mut entities = (0, 0);
    for _ in 0..5 {
        let t = Instant::now();
        let a = kerfcam::input::read(s.as_bytes(), &opts).expect("svg");
        best_svg = best_svg.min(t.elapsed().as_secs_f64());
        let t = Instant::now();
        let b = kerfcam::input::read(d.as_bytes(), &opts).expect("dxf");
        best_dxf = best_dxf.min(t.elapsed().as_secs_f64());
        entities = (a.entities.len(), b.entities.len());
    }
    let mb = |len: usize| len as f64 / 1e6;
    println!(
        "{n} plates: SVG {:.2} MB, {} entities; DXF {:.2} MB, {} entities",
        mb(s.len()),
        entities.0,
        mb(d.len()),
        entities.1
    );
    println!(
        "SVG read: {:.1} ms, {:.1} MB/s, {:.0} parts/s",
        best_svg * 1e3,
        mb(s.len()) / best_svg,
        n as f64 / best_svg
    );
    println!(
        "DXF read: {:.1} ms, {:.1} MB/s, {:.0} parts/s",
        best_dxf * 1e3,
        mb(d.len()) / best_dxf,
        n as f64 / best_dxf
    );
    println!("SVG / DXF time per part: {:.2}x", best_svg / best_dxf);
}
