//! Which parts the swept kerf frees from the sheet: every point of the
//! outline within the kerf's reach of a cutting move, or else the part
//! sealed off from the sheet on a raster (a notch narrower than the kerf
//! stays with the part; a tab or a missing cut lets the sheet in).
//!
//! The moves come from one flat grid ([`Moves`]), each part's raster and
//! lists reuse one set of buffers, each row's inside is a list of runs
//! looked up only where the sheet reaches, and the parts are shared among
//! the threads. (A map of vectors by 3 mm cell and three fresh rasters a
//! part, each filled inside, took 5.5 s and 1.6 GB on a 61k-contour
//! sheet: issue 17, sheet scale.)

use super::moves::Moves;
use super::{cutting, ATTACHED_MAX};
use crate::contour::{Contour, ContourKind};
use crate::geom::{Along, BBox, Grid, Point};
use crate::par::Threads;
use crate::plan::{CutPlan, PlanInput};

/// Buffers one part's raster check reuses from the last part's.
#[derive(Default)]
struct Scratch {
    /// Per raster cell: [`SWEPT`], [`SEEN`].
    cells: Vec<u8>,
    edges: Vec<(Point, Point)>,
    xs: Vec<f64>,
    /// Runs of cells inside the part, `(first, past last)` column, and
    /// where each row's start in them.
    runs: Vec<(usize, usize)>,
    rows: Vec<usize>,
    stack: Vec<usize>,
    near: Vec<u32>,
    mark: Vec<u32>,
}

const SWEPT: u8 = 1;
const SEEN: u8 = 2;

/// Parts (their outer contours' indices) whose outline some point of which
/// no cutting move reaches, and the points of their outlines (`cell`
/// apart) that none reaches; with `tabs`, the moves over tabs count as
/// cuts. The same answer with any number of `threads`.
pub(super) fn not_freed(
    input: &PlanInput,
    plan: &CutPlan,
    r: f64,
    cell: f64,
    slack: f64,
    tabs: bool,
    threads: Threads,
) -> (Vec<usize>, Vec<Point>) {
    let moves = Moves::new(cutting(plan, tabs), r + slack);
    let outer: Vec<usize> = (input.contours.contours.iter().enumerate())
        .filter(|(_, c)| c.kind == ContourKind::Outer)
        .map(|(k, _)| k)
        .collect();
    // The parts shared among the threads, each range with its own
    // buffers; joined in the parts' order, as one thread finds them.
    let found = crate::par::map_ranges(outer.len(), threads, 64, |range| {
        let mut scratch = Scratch::default();
        let mut out = Vec::new();
        let mut attached = Vec::new();
        for &k in &outer[range] {
            let c = &input.contours.contours[k];
            let b = c.bbox;
            let size = (b.max.x - b.min.x).max(b.max.y - b.min.y);
            // Cells at most 0.4 kerf: a kerf band is then at least five
            // cells wide and seals; a part too big for such a raster (or
            // no kerf) is checked by its outline: every point of it reached.
            let h = (r / 2.5).max(size / 1500.0).max(0.01);
            let free = if h <= r / 2.5 + 1e-12 && r > slack {
                sealed(c, &moves, k as u32, &mut scratch, r, h)
            } else {
                c.segments.iter().all(|s| {
                    let n = ((s.length() / cell).ceil() as usize).clamp(1, 100_000);
                    (0..=n).all(|k| moves.reached(s.point_at(k as f64 / n as f64)))
                })
            };
            if !free {
                out.push(k);
                for s in &c.segments {
                    let n = ((s.length() / cell).ceil() as usize).clamp(1, ATTACHED_MAX);
                    for k in 0..=n {
                        let q = s.point_at(k as f64 / n as f64);
                        if attached.len() < ATTACHED_MAX && !moves.reached(q) {
                            attached.push(q);
                        }
                    }
                }
            }
        }
        (out, attached)
    });
    let mut out = Vec::new();
    let mut attached = Vec::new();
    for (o, a) in found {
        out.extend(o);
        attached.extend(a);
    }
    attached.truncate(ATTACHED_MAX);
    (out, attached)
}

/// True when the kerf swept by `moves` seals part `c` off from the sheet:
/// on a raster of `h` cells over its box (grown by a kerf and two cells),
/// no path of unswept cells leads from the raster's edge into the part.
/// A notch narrower than the kerf (a corner the kerf cannot reproduce)
/// stays with the part; a tab or a missing cut lets the sheet in.
fn sealed(c: &Contour, moves: &Moves, query: u32, s: &mut Scratch, r: f64, h: f64) -> bool {
    let margin = 2.0 * r + 2.0 * h;
    let (x0, y0) = (c.bbox.min.x - margin, c.bbox.min.y - margin);
    let g = Grid {
        x0,
        y0,
        cell: h,
        nx: (((c.bbox.max.x - c.bbox.min.x) + 2.0 * margin) / h).ceil() as usize + 1,
        ny: (((c.bbox.max.y - c.bbox.min.y) + 2.0 * margin) / h).ceil() as usize + 1,
    };
    let (nx, ny) = (g.nx, g.ny);
    let cells = &mut s.cells;
    cells.clear();
    cells.resize(nx * ny, 0);
    let grown = BBox {
        min: Point::new(x0, y0),
        max: Point::new(x0 + nx as f64 * h, y0 + ny as f64 * h),
    };
    moves.near(&grown, &mut s.mark, query, &mut s.near);
    // A disc stamps only cells whose centre lies within `r` of it: one
    // farther than that from the raster's box stamps none.
    let (x1, y1) = (grown.max.x + r, grown.max.y + r);
    let (xa, ya) = (x0 - r, y0 - r);
    for &m in &s.near {
        // Discs at most a cell apart along the move, stamped column by column.
        let seg = moves.moves[m as usize];
        let along = Along::new(seg);
        let n = ((seg.length() / h).ceil() as usize).clamp(1, 1_000_000);
        for k in 0..=n {
            let p = along.at(k as f64 / n as f64);
            if p.x < xa || p.x > x1 || p.y < ya || p.y > y1 {
                continue;
            }
            for i in g.col_from(p.x - r)..g.col_to(p.x + r) {
                let dx = g.centre(i, 0).x - p.x;
                let half = r * r - dx * dx;
                if half < 0.0 {
                    continue;
                }
                let half = half.sqrt();
                for j in g.row_from(p.y - half)..g.row_to(p.y + half) {
                    cells[j * nx + i] |= SWEPT;
                }
            }
        }
    }
    // The part, row by row: even-odd crossings of its outline (arcs as
    // chords within a tenth of a cell).
    let edges = &mut s.edges;
    edges.clear();
    for seg in &c.segments {
        edges.extend(crate::geom::chords(seg, h / 10.0));
    }
    // Each row's runs of cells inside, looked up only for the cells the
    // sheet reaches (filling every inside cell was most of the check).
    let (runs, rows) = (&mut s.runs, &mut s.rows);
    runs.clear();
    rows.clear();
    g.inside_runs(edges, &mut s.xs, |j, lo, hi| {
        while rows.len() <= j {
            rows.push(runs.len());
        }
        runs.push((lo, hi));
    });
    while rows.len() <= ny {
        rows.push(runs.len());
    }
    let inside = |k: usize| {
        let (i, j) = (k % nx, k / nx);
        runs[rows[j]..rows[j + 1]]
            .iter()
            .any(|&(lo, hi)| lo <= i && i < hi)
    };
    // The sheet: every unswept cell reachable from the raster's edge.
    let stack = &mut s.stack;
    stack.clear();
    for i in 0..nx {
        stack.push(i);
        stack.push((ny - 1) * nx + i);
    }
    for j in 0..ny {
        stack.push(j * nx);
        stack.push(j * nx + nx - 1);
    }
    while let Some(k) = stack.pop() {
        if cells[k] & (SEEN | SWEPT) != 0 {
            continue;
        }
        if inside(k) {
            return false;
        }
        cells[k] |= SEEN;
        g.neighbours(k, |q| stack.push(q));
    }
    true
}
