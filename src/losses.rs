//! What the program takes from the drawn parts, for the page to mark on
//! the preview before the download (issue 45 §3): the loops the warnings
//! that say a loss ([`crate::warning::Loss`]) name, their outlines as flat
//! numbers, and where a cut comes within half the kerf of another part
//! (the closeness check's cells, [`crate::plan::closeness`]) as squares in
//! the verification heat map's form. Numbers only: the page draws them
//! over the preview as they are.

use std::collections::HashSet;

use crate::source::ContourRef;
use crate::Output;

/// The loops named by the warnings that say a loss.
pub fn loops(out: &Output) -> HashSet<ContourRef> {
    (out.warnings())
        .filter(|w| w.loss().is_some())
        .flat_map(|w| w.loops.iter().copied())
        .collect()
}

/// `[x0, y0, x1, y1, bulge, …]`: the segments of the drawn closed loops
/// [`loops`] names (program coordinates, mm), at most `max` of them.
pub fn outlines(out: &Output, max: usize) -> Vec<f64> {
    let loops = loops(out);
    let mut flat = Vec::new();
    if loops.is_empty() {
        return flat;
    }
    let segments = (out.contours.contours.iter())
        .filter(|c| c.is_closed() && loops.contains(&c.source))
        .flat_map(|c| c.segments.iter())
        .take(max);
    for s in segments {
        flat.extend([s.a.x, s.a.y, s.b.x, s.b.y, s.bulge]);
    }
    flat
}

/// `[side, x, y, depth, …]`: the closeness check's cells binned into at
/// most `max` squares of `side` mm ([`crate::plan::heat::binned`]), each
/// with the deepest reach in it; empty when no cut comes that close.
pub fn closeness_squares(out: &Output, max: usize) -> Vec<f64> {
    let c = &out.closeness;
    let (side, squares) = crate::plan::heat::binned(&c.cells, c.cell, max);
    if squares.is_empty() {
        return Vec::new();
    }
    let mut flat = Vec::with_capacity(1 + 3 * squares.len());
    flat.push(side);
    for (p, d) in squares {
        flat.extend([p.x, p.y, d]);
    }
    flat
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{run, Settings};

    /// Two 40 × 30 squares `gap` mm apart (mm), and a 10 mm square far away.
    fn drawing(gap: f64) -> Vec<u8> {
        let mut s = String::from(
            "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n",
        );
        let mut square = |x0: f64, y0: f64, w: f64, h: f64| {
            s += &format!("0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n{x0}\n20\n{y0}\n10\n{}\n20\n{y0}\n10\n{}\n20\n{}\n10\n{x0}\n20\n{}\n",
                x0 + w, x0 + w, y0 + h, y0 + h);
        };
        square(0.0, 0.0, 40.0, 30.0);
        square(40.0 + gap, 0.0, 40.0, 30.0);
        square(200.0, 0.0, 10.0, 10.0);
        s += "0\nENDSEC\n0\nEOF\n";
        s.into_bytes()
    }

    fn job(gap: f64) -> Output {
        run(&drawing(gap), &Settings::new(1.5, 0.001, 2000.0).unwrap()).unwrap()
    }

    #[test]
    fn the_two_close_parts_are_marked_and_the_far_one_is_not() {
        let j = job(1.0);
        let loops = loops(&j);
        assert_eq!(loops.len(), 2, "{loops:?}");
        let outlines = outlines(&j, usize::MAX);
        // Two squares of four sides, none of them the far square's.
        assert_eq!(outlines.len(), 2 * 4 * 5);
        assert!(outlines.chunks(5).all(|s| s[0] < 100.0 && s[2] < 100.0));
        // The report names the same loops on the warning the page lists.
        let report: serde_json::Value =
            serde_json::from_str(&crate::report::Report::new(&j).to_json()).unwrap();
        let w = (report["warnings"].as_array().unwrap().iter())
            .find(|w| w["code"] == "parts-closer-than-kerf")
            .expect("warned");
        assert_eq!(w["loss"], "cuts-into");
        let named: Vec<u64> = (w["loops"].as_array().unwrap().iter())
            .map(|l| l["part"].as_u64().unwrap())
            .collect();
        assert_eq!(named.len(), 2);
        assert!(named.iter().all(|&p| p > 0));
        // Squares only between the two parts, where the kerf reaches across.
        let heat = closeness_squares(&j, 50_000);
        assert!(heat.len() > 4);
        let side = heat[0];
        for sq in heat[1..].chunks(3) {
            assert!(
                (38.0..=42.0 + side).contains(&sq[0]),
                "square at x {} (side {side})",
                sq[0]
            );
            assert!(sq[2] > 0.0 && sq[2] <= 1.5);
        }
    }

    #[test]
    fn parts_apart_are_not_marked() {
        let j = job(20.0);
        assert!(outlines(&j, usize::MAX).is_empty());
        assert!(closeness_squares(&j, 50_000).is_empty());
        let report = crate::report::Report::new(&j).to_json();
        assert!(!report.contains("\"loss\""), "{report}");
    }
}
