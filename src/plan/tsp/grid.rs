//! A uniform bucket grid over points, for nearest and k-nearest queries.
//!
//! Nests are spread evenly over a sheet, so a grid of about one item per
//! cell answers a nearest query in O(1) expected rings; a k-d tree would
//! buy nothing here and costs more code. Rings are searched outwards
//! until no unseen cell can hold anything nearer than the best found
//! (a cell in ring r + 1 is at least r cell sizes from the query's cell).

use super::dist;
use crate::geom::Point;

/// Cells at most per axis: bounds memory for degenerate (very thin) inputs.
const MAX_AXIS: usize = 4096;

/// A squared distance above the square of `b` times this is certainly
/// above `b` once rooted (rounding is a few ulps): such points are skipped
/// without a square root, and every choice stays the one `dist` makes.
const FAR: f64 = 1.0 + 1e-9;

/// Items (`u32` ids) bucketed by position.
#[derive(Clone)]
pub(crate) struct Grid {
    min: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    /// Cell `c` holds `items[start[c]..start[c] + len[c]]`; its room, up
    /// to `start[c + 1]`, is counted from the points given to [`Grid::new`]
    /// (one array for all cells: a vector per cell was 200k allocations on
    /// a 137k-contour sheet, and scattered).
    start: Vec<u32>,
    len: Vec<u32>,
    items: Vec<u32>,
    /// The cell of each of the points given to [`Grid::new`], for
    /// [`Grid::insert_nth`] (found once: each is two divisions, and every
    /// point of a tour's constructions was placed twice).
    home: Vec<u32>,
    /// Scratch for [`Grid::nearest`]: the cells of one ring (kept, so a
    /// query allocates nothing; 60k queries a tour).
    ring_cells: Vec<usize>,
}

impl Grid {
    /// A grid over `points` (finite) sized for about `per_cell` items a
    /// cell, with room for each of `points` to be inserted once (at its
    /// own position).
    pub(crate) fn new(points: &[Point], per_cell: f64) -> Grid {
        let (mut lo, mut hi) = (
            Point::new(f64::MAX, f64::MAX),
            Point::new(f64::MIN, f64::MIN),
        );
        for p in points {
            lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
        }
        if points.is_empty() {
            lo = Point::default();
            hi = Point::default();
        }
        let (w, h) = ((hi.x - lo.x).max(0.0), (hi.y - lo.y).max(0.0));
        let cells_wanted = (points.len() as f64 / per_cell.max(1e-3)).max(1.0);
        // Square cells; an axis of zero extent still gets one cell.
        let area = (w * h).max(1e-12);
        let mut cell = (area / cells_wanted).sqrt();
        cell = cell.max(w.max(h) / MAX_AXIS as f64).max(1e-9);
        if !cell.is_finite() {
            cell = 1.0;
        }
        let nx = ((w / cell) as usize + 1).min(MAX_AXIS);
        let ny = ((h / cell) as usize + 1).min(MAX_AXIS);
        let mut g = Grid {
            min: lo,
            cell,
            nx,
            ny,
            start: vec![0; nx * ny + 1],
            len: vec![0; nx * ny],
            items: vec![0; points.len()],
            home: Vec::with_capacity(points.len()),
            ring_cells: Vec::new(),
        };
        for p in points {
            let (cx, cy) = g.cell_of(*p);
            let c = cy * nx + cx;
            g.start[c + 1] += 1;
            g.home.push(c as u32);
        }
        for c in 1..g.start.len() {
            g.start[c] += g.start[c - 1];
        }
        g
    }

    /// The cell holding `p`, clamped to the grid.
    fn cell_of(&self, p: Point) -> (usize, usize) {
        let f = |v: f64, n: usize| {
            let c = v / self.cell;
            if c.is_nan() || c <= 0.0 {
                0
            } else {
                (c as usize).min(n - 1)
            }
        };
        (f(p.x - self.min.x, self.nx), f(p.y - self.min.y, self.ny))
    }

    /// Adds item `i` at the `i`-th of the points the grid was made for, in
    /// the cell found for it then (a cell with no room left drops it:
    /// cannot happen, each point being inserted once).
    pub(crate) fn insert_nth(&mut self, i: usize) {
        let Some(&c) = self.home.get(i) else {
            return;
        };
        let c = c as usize;
        let at = (self.start[c] + self.len[c]) as usize;
        if at < self.start[c + 1] as usize {
            self.items[at] = i as u32;
            self.len[c] += 1;
        }
    }

    /// The items of cell `c`.
    fn cell(&self, c: usize) -> &[u32] {
        let a = self.start[c] as usize;
        &self.items[a..a + self.len[c] as usize]
    }

    /// Calls `f` with the index of every cell of ring `r` around (cx, cy)
    /// that lies in the grid. Only those are walked: a query near the end of
    /// a long thin grid (4096 × 1) reaches thousands of rings, almost all of
    /// each outside the grid (a fuzzed drawing of 6 contours spent 1.4 s
    /// walking them).
    fn ring(&self, cx: usize, cy: usize, r: usize, mut f: impl FnMut(usize)) {
        let (nx, ny) = (self.nx as isize, self.ny as isize);
        let (cx, cy, r) = (cx as isize, cy as isize, r as isize);
        if r == 0 {
            f((cy * nx + cx) as usize);
            return;
        }
        let (y0, y1) = (cy - r, cy + r);
        let (x0, x1) = (cx - r, cx + r);
        let (row0, row1) = ((0..ny).contains(&y0), (0..ny).contains(&y1));
        if row0 || row1 {
            for x in x0.max(0)..=x1.min(nx - 1) {
                if row0 {
                    f((y0 * nx + x) as usize);
                }
                if row1 {
                    f((y1 * nx + x) as usize);
                }
            }
        }
        let (col0, col1) = ((0..nx).contains(&x0), (0..nx).contains(&x1));
        if col0 || col1 {
            for y in (y0 + 1).max(0)..=(y1 - 1).min(ny - 1) {
                if col0 {
                    f((y * nx + x0) as usize);
                }
                if col1 {
                    f((y * nx + x1) as usize);
                }
            }
        }
    }

    /// The last ring around (cx, cy) that still holds a cell of the grid.
    fn reach(&self, cx: usize, cy: usize) -> usize {
        cx.max(self.nx - 1 - cx).max(cy).max(self.ny - 1 - cy)
    }

    /// Calls `each` with every live item of `cells`, in cell order; the
    /// items `alive` says are dead are dropped from their cell on the way
    /// (lazy deletion: swap-removed within the cell's room).
    #[inline]
    fn each_live(
        &mut self,
        cells: &[usize],
        alive: impl Fn(u32) -> bool,
        mut each: impl FnMut(u32),
    ) {
        for &c in cells {
            let a = self.start[c] as usize;
            let mut n = self.len[c] as usize;
            let mut t = 0;
            while t < n {
                let id = self.items[a + t];
                if !alive(id) {
                    n -= 1;
                    self.items[a + t] = self.items[a + n];
                    continue;
                }
                each(id);
                t += 1;
            }
            self.len[c] = n as u32;
        }
    }

    /// The live item nearest `q` and its distance; items for which `alive`
    /// is false are dropped from the grid on the way (lazy deletion).
    pub(crate) fn nearest(
        &mut self,
        q: Point,
        at: impl Fn(u32) -> Point,
        alive: impl Fn(u32) -> bool,
    ) -> Option<(u32, f64)> {
        let (cx, cy) = self.cell_of(q);
        let mut best: Option<(u32, f64)> = None;
        let mut idx = std::mem::take(&mut self.ring_cells);
        for r in 0..=self.reach(cx, cy) {
            idx.clear();
            self.ring(cx, cy, r, |c| idx.push(c));
            self.each_live(&idx, &alive, |id| {
                // The squared distance first: a point clearly beyond the
                // best needs no square root (most of them; the margin
                // keeps the choice exactly the one by `dist`).
                let p = at(id);
                let (dx, dy) = (p.x - q.x, p.y - q.y);
                let d2 = dx * dx + dy * dy;
                if best.is_none_or(|(_, b)| d2 <= b * b * FAR) {
                    let d = dist(p, q);
                    if best.is_none_or(|(_, b)| d < b) {
                        best = Some((id, d));
                    }
                }
            });
            if best.is_some_and(|(_, b)| b <= self.scanned_reach(q, cx, cy, r)) {
                break;
            }
        }
        self.ring_cells = idx;
        best
    }

    /// The live item of least `score`, ties to the smaller item, and its
    /// score; dead items dropped on the way as in [`Grid::nearest`].
    /// `score(id)` must be at least the distance from `q` to `at(id)` less
    /// `slack` (a bonus of at most `slack` for entering there): rings are
    /// searched until no unseen item can score as low. A NaN score is never
    /// chosen.
    pub(crate) fn least(
        &mut self,
        q: Point,
        slack: f64,
        alive: impl Fn(u32) -> bool,
        score: impl Fn(u32) -> f64,
    ) -> Option<(u32, f64)> {
        let (cx, cy) = self.cell_of(q);
        let mut best: Option<(u32, f64)> = None;
        let mut idx = std::mem::take(&mut self.ring_cells);
        for r in 0..=self.reach(cx, cy) {
            idx.clear();
            self.ring(cx, cy, r, |c| idx.push(c));
            self.each_live(&idx, &alive, |id| {
                let s = score(id);
                if best.is_none_or(|(b, bs)| s < bs || (s == bs && id < b)) && !s.is_nan() {
                    best = Some((id, s));
                }
            });
            // Strictly below: an unseen item scoring the same might be a
            // smaller one.
            if best.is_some_and(|(_, b)| b < self.scanned_reach(q, cx, cy, r) - slack) {
                break;
            }
        }
        self.ring_cells = idx;
        best
    }

    /// Up to `k` items nearest `q`, nearest first, skipping those `skip` names.
    #[cfg(test)]
    pub(super) fn k_nearest(
        &self,
        q: Point,
        k: usize,
        at: impl Fn(u32) -> Point,
        skip: impl Fn(u32) -> bool,
    ) -> Vec<u32> {
        let mut found = Vec::with_capacity(k + 1);
        self.k_nearest_into(q, k, at, skip, &mut found);
        found.into_iter().map(|(_, id)| id).collect()
    }

    /// [`Grid::k_nearest`] into `found` as (squared distance, item),
    /// nearest first: the buffer is reused from query to query (no
    /// allocation each).
    pub(super) fn k_nearest_into(
        &self,
        q: Point,
        k: usize,
        at: impl Fn(u32) -> Point,
        skip: impl Fn(u32) -> bool,
        found: &mut Vec<(f64, u32)>,
    ) {
        let (cx, cy) = self.cell_of(q);
        found.clear();
        if k == 0 {
            return;
        }
        for r in 0..=self.reach(cx, cy) {
            self.ring(cx, cy, r, |c| {
                for &id in self.cell(c) {
                    if skip(id) {
                        continue;
                    }
                    // Ranked by squared distance: the same order as by
                    // distance without a square root a point (a tenth of
                    // the lists' time on a 60k-site sheet), and a tie only
                    // where the points are equally far.
                    let p = at(id);
                    let (dx, dy) = (p.x - q.x, p.y - q.y);
                    let d = dx * dx + dy * dy;
                    // Into place after every item no farther (so the first
                    // met wins a tie), the farthest dropped when full: an
                    // insertion step instead of a search, insert and
                    // truncate, which moved the tail twice (a tenth of a
                    // 60k-site tour went to these queries).
                    let mut i = found.len();
                    if i == k {
                        if found[k - 1].0 <= d {
                            continue;
                        }
                        i -= 1;
                    } else {
                        found.push((d, id));
                    }
                    while i > 0 && found[i - 1].0 > d {
                        found[i] = found[i - 1];
                        i -= 1;
                    }
                    found[i] = (d, id);
                }
            });
            if found.len() == k && found[k - 1].0 <= self.scanned_reach(q, cx, cy, r).powi(2) {
                break;
            }
        }
    }

    /// How far from `q` every cell outside rings 0..=r around (cx, cy)
    /// lies, at least: the distance from `q` to the nearest side of that
    /// block beyond which the grid still has cells, less a rounding margin
    /// (points are binned by division, the sides found by multiplication).
    /// At least `r` cells, and often nearly `r + 1`: a k-nearest query with
    /// only `r` cells counted scanned a ring more about every other time
    /// (the 11 nearest of one item a cell reach past ring 1 at once).
    /// Only where the query stops, never which items it keeps: those
    /// beyond are at least this far, and the search keeps the nearest it
    /// met first on ties, so stopping before them changes nothing.
    fn scanned_reach(&self, q: Point, cx: usize, cy: usize, r: usize) -> f64 {
        let c = self.cell;
        let side = |lo_cells: bool, lo_edge: f64, hi_cells: bool, hi_edge: f64, v: f64| {
            let lo = if lo_cells { v - lo_edge } else { f64::INFINITY };
            let hi = if hi_cells { hi_edge - v } else { f64::INFINITY };
            lo.min(hi)
        };
        let x = side(
            cx > r,
            self.min.x + (cx - r.min(cx)) as f64 * c,
            cx + r + 1 < self.nx,
            self.min.x + (cx + r + 1) as f64 * c,
            q.x,
        );
        let y = side(
            cy > r,
            self.min.y + (cy - r.min(cy)) as f64 * c,
            cy + r + 1 < self.ny,
            self.min.y + (cy + r + 1) as f64 * c,
            q.y,
        );
        let margin = 1e-9 * (1.0 + q.x.abs() + q.y.abs() + self.min.x.abs() + self.min.y.abs())
            + 1e-9 * c * (r + 1) as f64;
        // Never less than the ring count itself gave.
        (x.min(y) - margin).max(r as f64 * c)
    }
}

#[cfg(test)]
#[path = "grid_tests.rs"]
mod tests;
