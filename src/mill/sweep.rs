//! `--verify` for a router's pockets (issue 43 §6; paper 004 §2.6's check
//! by sweeping the tool envelope over a grid): the tool's disc swept along
//! the toolpath the post writes, stamped on a raster of each pocket.
//!
//! - **Gouge**: where a disc below the stock's top reaches what the drawing
//!   keeps (an island, the material round the pocket) by more than the
//!   slack (ten tolerances): counted in mm², with where.
//! - **Left**: what a disc of the tool's radius can reach in the pocket
//!   (the pocket opened by the disc, [`Pocket::reachable`]) that no disc at
//!   the full depth covered, within the slack: in mm², with where. What no
//!   such disc reaches (sharp inside corners, necks narrower than the tool)
//!   is the pocket's own limit, counted apart (`unreachable_mm2`).
//!
//! Each pocket's moves are those between its opening note and the next
//! section's ([`super::PocketSpan`]); a move's disc is stamped as the
//! capsule it sweeps, row by row (the capsule is convex: each row is one
//! run of cells, from its end discs and its sides).

use super::region::Pocket;
use super::{MillMove, Toolpath};
use crate::geom::{chords, flatten_count, path_bbox, BBox, Grid, Point, Segment};

/// The most cells of one pocket's raster; a bigger pocket is swept on
/// coarser cells (each cell then counts whole).
const MAX_CELLS: f64 = 8.0e6;

/// What the swept tool did to the pockets, all pockets together.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Swept {
    /// Material to keep (islands, walls) a disc below the top reached, mm².
    pub gouge_mm2: f64,
    /// Where: a cell of the largest gouged patch.
    pub gouge_at: Option<Point>,
    /// Pocket area the tool's disc can reach but did not clear at full depth, mm².
    pub left_mm2: f64,
    /// Where: a cell of the largest patch left.
    pub left_at: Option<Point>,
    /// Pocket area no disc of the tool's radius can reach, mm².
    pub unreachable_mm2: f64,
    /// The rasters' cell side (the finest of the pockets'), mm.
    pub cell: f64,
}

/// One pocket as drawn (its outline, then its islands) and its moves: the
/// toolpath's notes from `first` (its opening note) up to `end`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PocketSpan {
    /// Outline first, then the islands.
    pub loops: Vec<Vec<Segment>>,
    /// Ordinal of its opening note among the toolpath's notes.
    pub first: usize,
    /// Ordinal of the note after its last move (the next section's).
    pub end: usize,
}

/// Sweeps a disc of radius `r` along `path` over each of `pockets`, cut
/// `depth` deep; `retract` the height the path starts at, `tol` the one
/// tolerance, mm.
pub fn sweep(
    path: &Toolpath,
    pockets: &[PocketSpan],
    r: f64,
    depth: f64,
    retract: f64,
    tol: f64,
) -> Swept {
    let slack = 10.0 * tol.max(1e-6);
    let mut out = Swept::default();
    let mut gouged: Vec<(usize, Point)> = Vec::new();
    let mut left: Vec<(usize, Point)> = Vec::new();
    for p in pockets {
        let Some(s) = sweep_one(path, p, r, depth, retract, slack) else {
            continue;
        };
        let a = s.cell * s.cell;
        out.gouge_mm2 += s.gouged.0 as f64 * a;
        out.left_mm2 += s.left.0 as f64 * a;
        out.unreachable_mm2 += s.unreachable as f64 * a;
        out.cell = if out.cell == 0.0 {
            s.cell
        } else {
            out.cell.min(s.cell)
        };
        gouged.extend(s.gouged.1.map(|at| (s.gouged.2, at)));
        left.extend(s.left.1.map(|at| (s.left.2, at)));
    }
    let largest = |v: &[(usize, Point)]| v.iter().max_by_key(|(n, _)| *n).map(|&(_, p)| p);
    out.gouge_at = largest(&gouged);
    out.left_at = largest(&left);
    out
}

/// A pocket's figures: cells gouged and left (count, where, the largest
/// patch's size), cells out of reach, the cell side.
struct One {
    cell: f64,
    gouged: (usize, Option<Point>, usize),
    left: (usize, Option<Point>, usize),
    unreachable: usize,
}

fn sweep_one(
    path: &Toolpath,
    p: &PocketSpan,
    r: f64,
    depth: f64,
    retract: f64,
    slack: f64,
) -> Option<One> {
    let outline = p.loops.first()?;
    let BBox { min: lo, max: hi } = path_bbox(outline);
    if !(lo.x.is_finite() && hi.x.is_finite() && r > 0.0) {
        return None;
    }
    // A band round the outline as wide as the tool: where a gouge into the
    // walls would land.
    let m = r + 2.0 * slack;
    let (w, h) = (hi.x - lo.x + 2.0 * m, hi.y - lo.y + 2.0 * m);
    let mut cell = (r / 8.0).clamp(0.02, 0.25);
    if w * h / (cell * cell) > MAX_CELLS {
        cell = (w * h / MAX_CELLS).sqrt();
    }
    let g = Grid {
        x0: lo.x - m,
        y0: lo.y - m,
        cell,
        nx: (w / cell).ceil() as usize,
        ny: (h / cell).ceil() as usize,
    };
    // Finer than the slack: a cell's class is then within the slack of
    // the exact shapes' (the coverage and the gouge allow that much).
    let chord = (slack / 4.0).min(cell / 8.0);
    let drawn = fill(&g, &p.loops, chord);
    let islands: Vec<&[Segment]> = p.loops[1..].iter().map(Vec::as_slice).collect();
    let reach_region = Pocket::new(outline, &islands, chord).reachable(r);
    let reach_loops: Vec<Vec<Segment>> = (reach_region.loops.iter())
        .map(|l| l.segments.clone())
        .collect();
    let reach = fill(&g, &reach_loops, chord);
    // The discs: below the top (reaching within r − slack), at the full
    // depth (clearing within r + slack).
    let mut below = vec![false; g.nx * g.ny];
    let mut full = vec![false; g.nx * g.ny];
    let bottom = -depth + 1e-6;
    for (a, b, za, zb) in moves_of(path, p, retract, chord) {
        if za.min(zb) < -1e-9 {
            stamp(&g, &mut below, a, b, r - slack);
        }
        if za.max(zb) <= bottom {
            stamp(&g, &mut full, a, b, r + slack);
        }
    }
    let gouge: Vec<bool> = (0..below.len()).map(|i| below[i] && !drawn[i]).collect();
    let left: Vec<bool> = (0..full.len())
        .map(|i| drawn[i] && reach[i] && !full[i])
        .collect();
    let unreachable = (0..drawn.len()).filter(|&i| drawn[i] && !reach[i]).count();
    Some(One {
        cell,
        gouged: patches(&g, &gouge),
        left: patches(&g, &left),
        unreachable,
    })
}

/// The pocket's moves as straight pieces (arcs in chords rising at most
/// `chord`), each with its heights at both ends: vertical moves as
/// a point.
fn moves_of(
    path: &Toolpath,
    p: &PocketSpan,
    retract: f64,
    chord: f64,
) -> Vec<(Point, Point, f64, f64)> {
    let mut out = Vec::new();
    let (mut at, mut z) = (path.start, retract);
    let mut note = 0usize;
    for m in &path.moves {
        let mine = note > p.first && note <= p.end;
        match m {
            MillMove::Note(_) => {
                note += 1;
                continue;
            }
            MillMove::ToolChange(_) => continue,
            MillMove::Rapid(q) => {
                if mine {
                    out.push((at, *q, z, z));
                }
                at = *q;
            }
            MillMove::RapidZ(h) | MillMove::Plunge(h) => {
                if mine {
                    out.push((at, at, z, *h));
                }
                z = *h;
            }
            MillMove::Cut { seg, z: h } => {
                if mine {
                    let n = match seg.arc_center() {
                        Some((_, rad)) => flatten_count(rad, seg.sweep().abs(), chord),
                        None => 1,
                    };
                    let mut prev = seg.a;
                    for k in 1..=n {
                        let t = k as f64 / n as f64;
                        let q = seg.point_at(t);
                        out.push((prev, q, z + (h - z) * (t - 1.0 / n as f64), z + (h - z) * t));
                        prev = q;
                    }
                }
                at = seg.b;
                z = *h;
            }
        }
    }
    out
}

/// Cells whose centre is inside `loops` by the even-odd rule (arcs
/// within `chord`).
fn fill(g: &Grid, loops: &[Vec<Segment>], chord: f64) -> Vec<bool> {
    let mut edges: Vec<(Point, Point)> = Vec::new();
    for l in loops {
        for s in l {
            edges.extend(chords(s, chord));
        }
    }
    let mut out = vec![false; g.nx * g.ny];
    g.inside_runs(&edges, &mut Vec::new(), |j, lo, hi| {
        out[j * g.nx + lo..j * g.nx + hi].fill(true);
    });
    out
}

/// Marks the cells whose centre is within `rho` of the piece `a`–`b` (the
/// capsule it sweeps): per row, the run between the leftmost and rightmost
/// of its end discs' and its sides' crossings.
fn stamp(g: &Grid, cells: &mut [bool], a: Point, b: Point, rho: f64) {
    if rho <= 0.0 || !(a.is_finite() && b.is_finite()) {
        return;
    }
    let d = b.sub(a);
    let len = d.norm();
    let n = if len > 0.0 {
        Point::new(-d.y / len, d.x / len).scale(rho)
    } else {
        Point::new(0.0, 0.0)
    };
    let (ylo, yhi) = (a.y.min(b.y) - rho, a.y.max(b.y) + rho);
    for j in g.row_from(ylo)..g.row_to(yhi) {
        let y = g.centre(0, j).y;
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for e in [a, b] {
            let dy = y - e.y;
            if dy.abs() <= rho {
                let w = (rho * rho - dy * dy).sqrt();
                lo = lo.min(e.x - w);
                hi = hi.max(e.x + w);
            }
        }
        if len > 0.0 && d.y != 0.0 {
            // The sides: the piece offset by ±rho, crossing the row
            // within its length.
            for side in [n, n.scale(-1.0)] {
                let t = (y - a.y - side.y) / d.y;
                if (0.0..=1.0).contains(&t) {
                    let x = a.x + side.x + d.x * t;
                    lo = lo.min(x);
                    hi = hi.max(x);
                }
            }
        }
        if lo > hi {
            continue;
        }
        for i in g.col_from(lo)..g.col_to(hi) {
            cells[j * g.nx + i] = true;
        }
    }
}

/// How many cells are set, where the largest 4-connected patch of them is
/// (its cell nearest its centroid), and that patch's size.
fn patches(g: &Grid, set: &[bool]) -> (usize, Option<Point>, usize) {
    let total = set.iter().filter(|&&s| s).count();
    if total == 0 {
        return (0, None, 0);
    }
    let mut seen = vec![false; set.len()];
    let mut best: (usize, Option<Point>) = (0, None);
    let mut stack = Vec::new();
    let mut patch = Vec::new();
    for start in 0..set.len() {
        if !set[start] || seen[start] {
            continue;
        }
        seen[start] = true;
        stack.push(start);
        patch.clear();
        while let Some(k) = stack.pop() {
            patch.push(k);
            g.neighbours(k, |q| {
                if set[q] && !seen[q] {
                    seen[q] = true;
                    stack.push(q);
                }
            });
        }
        if patch.len() > best.0 {
            let c = |k: usize| g.centre(k % g.nx, k / g.nx);
            let sum = patch.iter().fold(Point::new(0.0, 0.0), |s, &k| s.add(c(k)));
            let mid = sum.scale(1.0 / patch.len() as f64);
            let at = (patch.iter())
                .map(|&k| c(k))
                .min_by(|p, q| p.dist(mid).total_cmp(&q.dist(mid)));
            best = (patch.len(), at);
        }
    }
    (total, best.1, best.0)
}

#[cfg(test)]
#[path = "sweep_tests.rs"]
mod tests;
