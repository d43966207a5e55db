//! Paper 002's point-list program (Richetti & da Silva, "Programa CN"):
//! one `x;y` row per point, `D` (desliga) on a row moved to with the torch
//! off, `L` (liga) on the first row cut after the torch goes on, a bare `L`
//! for a spot, a bare `D` at the end. The stepper driver only interpolates
//! lines, so arcs and circles are split into n = floor(arc length /
//! resolution) equal pieces (the paper's "resolução", 10 mm in its example).

use crate::geom::Segment;
use crate::plan::CutPlan;

use super::flatten::points;
use super::number::Grid;
use super::post::Post;

/// Writes the point list.
pub(crate) fn write(plan: &CutPlan, post: &Post) -> String {
    let grid = Grid::new(post.decimals).with_trailing_zeros(post.trailing_zeros);
    let k = post.unit_scale();
    let mut out = String::new();
    let mut row = |p: Option<(i64, i64)>, code: &str| {
        if let Some(q) = p {
            out.push_str(&format!("{};{}", grid.fmt(q.0), grid.fmt(q.1)));
            if !code.is_empty() {
                out.push(' ');
            }
        }
        out.push_str(code);
        out.push('\n');
    };
    let mut pos: Option<(i64, i64)> = None;
    for c in &plan.cuts {
        let q = grid.snap(c.pierce.scale(k));
        // Torch off and move; already there: torch off in place.
        row((pos != Some(q)).then_some(q), "D");
        pos = Some(q);
        if c.spot {
            row(None, "L");
            continue;
        }
        let segs: Vec<Segment> = c.steps.iter().map(|s| s.segment).collect();
        let mut code = "L";
        for p in points(&segs, post.segment_length, post.chord) {
            let q = grid.snap(p.scale(k));
            if Some(q) == pos {
                continue;
            }
            row(Some(q), code);
            code = "";
            pos = Some(q);
        }
    }
    row(None, "D");
    out
}
