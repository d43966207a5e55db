//! A nest as the page draws it: placements as flat numbers, each part's
//! outline and holes and the sheet's outline and no-go zones as SVG path
//! data (y up).

use crate::geom::{path_bbox, Segment};
use crate::nest::{Part, Placement, Sheets};

/// Numbers per copy in the flat placements: part, copy, sheet, rotation,
/// mirror, x, y.
pub(super) const PER_COPY: usize = 7;

/// Placements as the page reads them, 7 numbers each.
pub(super) fn flat_placements(ps: &[Placement]) -> Vec<f64> {
    let mut out = Vec::with_capacity(ps.len() * PER_COPY);
    for p in ps {
        out.extend([
            p.part as f64,
            p.copy as f64,
            p.sheet as f64,
            p.rotation,
            if p.mirror { 1.0 } else { 0.0 },
            p.translation.x,
            p.translation.y,
        ]);
    }
    out
}

/// One closed loop as SVG path data, y up: lines as L, arcs as A (the
/// bulge gives the sweep: counter-clockwise is SVG's positive sweep in
/// y-up coordinates).
fn loop_path(segs: &[Segment], out: &mut String) {
    use std::fmt::Write;
    let Some(first) = segs.first() else { return };
    let _ = write!(out, "M{} {}", first.a.x, first.a.y);
    for s in segs {
        match s.arc_center() {
            Some((_, r)) if !s.is_line() => {
                let large = u8::from(s.bulge.abs() > 1.0);
                let sweep = u8::from(s.bulge > 0.0);
                let _ = write!(out, "A{r} {r} 0 {large} {sweep} {} {}", s.b.x, s.b.y);
            }
            _ => {
                let _ = write!(out, "L{} {}", s.b.x, s.b.y);
            }
        }
    }
    out.push('Z');
}

/// A part's outline and holes as one SVG path (y up).
pub(super) fn part_path(p: &Part) -> String {
    let mut d = String::new();
    for l in std::iter::once(&p.outer).chain(&p.holes) {
        loop_path(l, &mut d);
    }
    d
}

/// `[{name, d}]`: each part's outline and holes as one SVG path.
pub(super) fn outlines_json(parts: &[Part]) -> String {
    let v: Vec<_> = parts
        .iter()
        .map(|p| serde_json::json!({ "name": p.name, "d": part_path(p) }))
        .collect();
    serde_json::Value::Array(v).to_string()
}

/// The sheet as the page draws it: `{kind: rect | remnant, path, box: [x0, y0, x1, y1]}`, its
/// outline and no-go zones as one SVG path (y up); null for a strip and a
/// list of sizes.
pub(super) fn sheet_shape(sheets: &Sheets) -> serde_json::Value {
    let kind = if matches!(sheets, Sheets::Rect { .. }) {
        "rect"
    } else {
        "remnant"
    };
    let (outline, no_go): (Vec<Segment>, &[Vec<Segment>]) = match sheets {
        Sheets::Rect { width, height, .. } => {
            let c = [(0.0, 0.0), (*width, 0.0), (*width, *height), (0.0, *height)]
                .map(|(x, y)| crate::geom::Point::new(x, y));
            (
                (0..4)
                    .map(|i| Segment::line(c[i], c[(i + 1) % 4]))
                    .collect(),
                &[],
            )
        }
        Sheets::Strip { .. } => return serde_json::Value::Null,
        // Sizes differ from sheet to sheet: the page draws each at its
        // own W × H (the nest's sheets say them), at 0, 0.
        Sheets::Mixed(_) => return serde_json::Value::Null,
        Sheets::Remnant { outline, no_go } => (outline.clone(), no_go),
    };
    let mut d = String::new();
    for l in std::iter::once(&outline).chain(no_go) {
        loop_path(l, &mut d);
    }
    let b = path_bbox(&outline);
    serde_json::json!({ "kind": kind, "path": d, "box": [b.min.x, b.min.y, b.max.x, b.max.y] })
}
