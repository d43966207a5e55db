//! Which parts the swept kerf frees from the sheet: every point of the
//! outline within the kerf's reach of a cutting move, or else the part
//! sealed off from the sheet on a raster (a notch narrower than the kerf
//! stays with the part; a tab or a missing cut lets the sheet in).

use std::collections::HashMap;

use super::{cutting, ATTACHED_MAX};
use crate::contour::ContourKind;
use crate::geom::{dist_to_segment, BBox, Point, Segment};
use crate::plan::{CutPlan, PlanInput};

/// Parts (their outer contours' indices) whose outline some point of which
/// no cutting move reaches, and the points of their outlines (`cell`
/// apart) that none reaches; with `tabs`, the moves over tabs count as cuts.
pub(super) fn not_freed(
    input: &PlanInput,
    plan: &CutPlan,
    r: f64,
    cell: f64,
    slack: f64,
    tabs: bool,
) -> (Vec<usize>, Vec<Point>) {
    // Cutting moves filed by the cells of a grid their boxes (grown by the
    // reach) cover.
    let reach = r + slack;
    let g = (4.0 * reach).max(1.0);
    let key = |v: f64| (v / g).floor().clamp(-1e12, 1e12) as i64;
    let moves: Vec<&Segment> = cutting(plan, tabs).collect();
    let mut grid: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
    for (m, s) in moves.iter().enumerate() {
        // Filed along the move (a long diagonal's box would cover a whole
        // sheet): the cells within the reach of points half a cell apart.
        let n = ((s.length() / (g / 2.0)).ceil() as usize).clamp(1, 1_000_000);
        let mut last = None;
        for k in 0..=n {
            let p = s.point_at(k as f64 / n as f64);
            // Reach plus the quarter cell to the nearest sample, rounded up.
            let pad = reach + g / 2.0;
            let cells = (
                key(p.x - pad),
                key(p.x + pad),
                key(p.y - pad),
                key(p.y + pad),
            );
            if last == Some(cells) {
                continue;
            }
            last = Some(cells);
            for i in cells.0..=cells.1 {
                for j in cells.2..=cells.3 {
                    let v = grid.entry((i, j)).or_default();
                    if v.last() != Some(&(m as u32)) {
                        v.push(m as u32);
                    }
                }
            }
        }
    }
    let reached = |q: Point| {
        grid.get(&(key(q.x), key(q.y))).is_some_and(|ms| {
            ms.iter()
                .any(|&m| dist_to_segment(q, moves[m as usize]) <= reach)
        })
    };
    let near = |b: &BBox| -> Vec<usize> {
        let mut v: Vec<usize> = Vec::new();
        if (key(b.max.x) - key(b.min.x) + 1).saturating_mul(key(b.max.y) - key(b.min.y) + 1)
            > 4_000_000
        {
            return (0..moves.len()).collect();
        }
        for i in key(b.min.x)..=key(b.max.x) {
            for j in key(b.min.y)..=key(b.max.y) {
                if let Some(ms) = grid.get(&(i, j)) {
                    v.extend(ms.iter().map(|&m| m as usize));
                }
            }
        }
        crate::sort::sort_indices(&mut v);
        v.dedup();
        v
    };
    let mut out = Vec::new();
    let mut attached = Vec::new();
    for (k, c) in input.contours.contours.iter().enumerate() {
        if c.kind != ContourKind::Outer {
            continue;
        }
        let b = c.bbox;
        let size = (b.max.x - b.min.x).max(b.max.y - b.min.y);
        // Cells at most 0.4 kerf: a kerf band is then at least five cells
        // wide and seals; a part too big for such a raster (or no kerf) is
        // checked by its outline: every point of it reached.
        let h = (r / 2.5).max(size / 1500.0).max(0.01);
        let free = if h <= r / 2.5 + 1e-12 && r > slack {
            sealed(c, &moves, &near, r, h)
        } else {
            c.segments.iter().all(|s| {
                let n = ((s.length() / cell).ceil() as usize).clamp(1, 100_000);
                (0..=n).all(|k| reached(s.point_at(k as f64 / n as f64)))
            })
        };
        if !free {
            out.push(k);
            for s in &c.segments {
                let n = ((s.length() / cell).ceil() as usize).clamp(1, ATTACHED_MAX);
                for k in 0..=n {
                    let q = s.point_at(k as f64 / n as f64);
                    if attached.len() < ATTACHED_MAX && !reached(q) {
                        attached.push(q);
                    }
                }
            }
        }
    }
    (out, attached)
}

/// True when the kerf swept by `moves` seals part `c` off from the sheet:
/// on a raster of `h` cells over its box (grown by a kerf and two cells),
/// no path of unswept cells leads from the raster's edge into the part.
/// A notch narrower than the kerf (a corner the kerf cannot reproduce)
/// stays with the part; a tab or a missing cut lets the sheet in.
fn sealed(
    c: &crate::contour::Contour,
    moves: &[&Segment],
    near: &dyn Fn(&BBox) -> Vec<usize>,
    r: f64,
    h: f64,
) -> bool {
    let margin = 2.0 * r + 2.0 * h;
    let (x0, y0) = (c.bbox.min.x - margin, c.bbox.min.y - margin);
    let nx = (((c.bbox.max.x - c.bbox.min.x) + 2.0 * margin) / h).ceil() as usize + 1;
    let ny = (((c.bbox.max.y - c.bbox.min.y) + 2.0 * margin) / h).ceil() as usize + 1;
    let centre =
        |i: usize, j: usize| Point::new(x0 + (i as f64 + 0.5) * h, y0 + (j as f64 + 0.5) * h);
    let mut swept = vec![false; nx * ny];
    let grown = BBox {
        min: Point::new(x0, y0),
        max: Point::new(x0 + nx as f64 * h, y0 + ny as f64 * h),
    };
    for m in near(&grown) {
        // Discs at most a cell apart along the move, stamped column by column.
        let s = moves[m];
        let n = ((s.length() / h).ceil() as usize).clamp(1, 1_000_000);
        for k in 0..=n {
            let p = s.point_at(k as f64 / n as f64);
            let lo_i = ((p.x - r - x0) / h - 0.5).ceil().max(0.0) as usize;
            let hi_i = (((p.x + r - x0) / h - 0.5).floor() + 1.0).max(0.0) as usize;
            for i in lo_i..hi_i.min(nx) {
                let dx = x0 + (i as f64 + 0.5) * h - p.x;
                let half = r * r - dx * dx;
                if half < 0.0 {
                    continue;
                }
                let half = half.sqrt();
                let lo_j = ((p.y - half - y0) / h - 0.5).ceil().max(0.0) as usize;
                let hi_j = (((p.y + half - y0) / h - 0.5).floor() + 1.0).max(0.0) as usize;
                for j in lo_j..hi_j.min(ny) {
                    swept[j * nx + i] = true;
                }
            }
        }
    }
    // The part, row by row: even-odd crossings of its outline (arcs as
    // chords within a tenth of a cell).
    let mut edges: Vec<(Point, Point)> = Vec::new();
    for s in &c.segments {
        match s.arc_center() {
            Some((_, rad)) => {
                let n = crate::geom::flatten_count(rad, s.sweep().abs(), h / 10.0).max(1);
                let mut a = s.a;
                for k in 1..=n {
                    let b = if k == n {
                        s.b
                    } else {
                        s.point_at(k as f64 / n as f64)
                    };
                    edges.push((a, b));
                    a = b;
                }
            }
            None => edges.push((s.a, s.b)),
        }
    }
    let mut inside = vec![false; nx * ny];
    let mut xs: Vec<f64> = Vec::new();
    for j in 0..ny {
        let y = centre(0, j).y;
        xs.clear();
        for (a, b) in &edges {
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
            }
        }
        crate::sort::sort_floats(&mut xs);
        for pair in xs.chunks(2) {
            if let [xa, xb] = pair {
                let lo = ((xa - x0) / h - 0.5).ceil().max(0.0) as usize;
                let hi = (((xb - x0) / h - 0.5).floor() + 1.0).max(0.0) as usize;
                for i in lo..hi.min(nx) {
                    inside[j * nx + i] = true;
                }
            }
        }
    }
    // The sheet: every unswept cell reachable from the raster's edge.
    let mut seen = vec![false; nx * ny];
    let mut stack: Vec<usize> = Vec::new();
    for i in 0..nx {
        stack.push(i);
        stack.push((ny - 1) * nx + i);
    }
    for j in 0..ny {
        stack.push(j * nx);
        stack.push(j * nx + nx - 1);
    }
    while let Some(k) = stack.pop() {
        if seen[k] || swept[k] {
            continue;
        }
        if inside[k] {
            return false;
        }
        seen[k] = true;
        let (i, j) = (k % nx, k / nx);
        if i > 0 {
            stack.push(k - 1);
        }
        if i + 1 < nx {
            stack.push(k + 1);
        }
        if j > 0 {
            stack.push(k - nx);
        }
        if j + 1 < ny {
            stack.push(k + nx);
        }
    }
    true
}
