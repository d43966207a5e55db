//! Cut order: everything inside a contour before the contour itself,
//! nearest-next among siblings.
//!
//! The containment tree (parts → holes → islands → their holes …) is walked
//! depth first with an explicit stack, so a file of thousands of nested
//! contours cannot overflow the (small, in wasm) call stack. Among the
//! children of one contour, the one whose path box is nearest the tool goes
//! next. This is the nearest-neighbour construction; better tours are a
//! later stage's job.

use crate::geom::{path_bbox, BBox, Point};
use crate::kerf::KerfPaths;

/// Squared distance from `p` to a box (0 inside); squared, as only the order matters.
fn box_dist(b: &BBox, p: Point) -> f64 {
    let dx = (b.min.x - p.x).max(0.0).max(p.x - b.max.x);
    let dy = (b.min.y - p.y).max(0.0).max(p.y - b.max.y);
    dx * dx + dy * dy
}

/// Path indices in cutting order.
///
/// `parents[c]` is the smallest closed contour containing contour `c`.
pub fn holes_first_nearest(
    paths: &KerfPaths,
    parents: &[Option<usize>],
    origin: Point,
) -> Vec<usize> {
    let n = parents.len();
    let mut path_of: Vec<Option<usize>> = vec![None; n];
    for (k, p) in paths.paths.iter().enumerate() {
        if p.contour < n {
            path_of[p.contour] = Some(k);
        }
    }
    // Boxes of contours; a contour without a path (a hole that vanished under the kerf)
    // still orders its islands, so it gets the union of theirs.
    let boxes: Vec<BBox> = paths.paths.iter().map(|p| path_bbox(&p.segments)).collect();
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut roots = Vec::new();
    // Only contours that have a path, or hold one, take part.
    let mut relevant = vec![false; n];
    let with_path: Vec<(usize, usize)> = path_of
        .iter()
        .enumerate()
        .filter_map(|(c, k)| k.map(|k| (c, k)))
        .collect();
    for &(c, _) in &with_path {
        let mut x = Some(c);
        while let Some(i) = x {
            if relevant[i] && i != c {
                break;
            }
            relevant[i] = true;
            x = parents[i];
        }
    }
    for c in (0..n).filter(|&c| relevant[c]) {
        match parents[c] {
            Some(p) if p < n => children[p].push(c),
            _ => roots.push(c),
        }
    }
    let mut contour_box = vec![BBox::EMPTY; n];
    for &(c, k) in &with_path {
        let mut x = Some(c);
        while let Some(i) = x {
            contour_box[i].union(&boxes[k]);
            x = parents[i];
        }
    }

    let mut order = Vec::with_capacity(paths.paths.len());
    let mut at = origin;
    // Frame: (contour to cut when its children are done, children left).
    let mut stack: Vec<(Option<usize>, Siblings)> =
        vec![(None, Siblings::new(roots, &contour_box))];
    while let Some((contour, remaining)) = stack.last_mut() {
        let Some(next) = remaining.take_nearest(at, &contour_box) else {
            if let Some(k) = contour.and_then(|c| path_of[c]) {
                order.push(k);
                // The planner pierces at the vertex nearest the tool, and the loop ends there.
                if let Some(v) = paths.paths[k]
                    .segments
                    .iter()
                    .map(|s| s.a)
                    .min_by(|a, b| a.dist(at).total_cmp(&b.dist(at)))
                {
                    at = v;
                }
            }
            stack.pop();
            continue;
        };
        let grandchildren = std::mem::take(&mut children[next]);
        stack.push((Some(next), Siblings::new(grandchildren, &contour_box)));
    }
    order
}

/// Lists longer than this get a grid for the nearest-next search.
const LINEAR_SEARCH_MAX: usize = 64;

/// The contours still to visit among one contour's children.
enum Siblings {
    /// Few: a linear scan.
    Few(Vec<usize>),
    /// Many: boxes in a uniform grid, searched ring by ring around the tool.
    Many(SiblingGrid),
}

struct SiblingGrid {
    origin: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    cells: Vec<Vec<u32>>,
    ids: Vec<usize>,
    taken: Vec<bool>,
    left: usize,
}

impl Siblings {
    fn new(ids: Vec<usize>, boxes: &[BBox]) -> Siblings {
        if ids.len() <= LINEAR_SEARCH_MAX {
            return Siblings::Few(ids);
        }
        let mut ext = BBox::EMPTY;
        for &c in &ids {
            ext.union(&boxes[c]);
        }
        let (w, h) = (
            (ext.max.x - ext.min.x).max(1e-9),
            (ext.max.y - ext.min.y).max(1e-9),
        );
        // About one box per cell.
        let cell = ((w * h) / ids.len() as f64).sqrt().max(1e-9);
        let nx = ((w / cell).ceil() as usize).clamp(1, 4096);
        let ny = ((h / cell).ceil() as usize).clamp(1, 4096);
        let cell = (w / nx as f64).max(h / ny as f64);
        let mut g = SiblingGrid {
            origin: ext.min,
            cell,
            nx,
            ny,
            cells: vec![Vec::new(); nx * ny],
            taken: vec![false; ids.len()],
            left: ids.len(),
            ids,
        };
        for k in 0..g.ids.len() {
            let b = boxes[g.ids[k]];
            let (x0, y0) = g.cell_of(b.min);
            let (x1, y1) = g.cell_of(b.max);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    g.cells[y * nx + x].push(k as u32);
                }
            }
        }
        Siblings::Many(g)
    }

    /// Removes and returns the contour whose box is nearest `at`.
    fn take_nearest(&mut self, at: Point, boxes: &[BBox]) -> Option<usize> {
        match self {
            Siblings::Few(ids) => {
                // Ties go to the lower contour index, as in the grid.
                let best = (0..ids.len()).min_by(|&i, &j| {
                    box_dist(&boxes[ids[i]], at)
                        .total_cmp(&box_dist(&boxes[ids[j]], at))
                        .then(ids[i].cmp(&ids[j]))
                })?;
                Some(ids.swap_remove(best))
            }
            Siblings::Many(g) => g.take_nearest(at, boxes),
        }
    }
}

impl SiblingGrid {
    fn cell_of(&self, p: Point) -> (usize, usize) {
        let x = ((p.x - self.origin.x) / self.cell)
            .floor()
            .clamp(0.0, (self.nx - 1) as f64) as usize;
        let y = ((p.y - self.origin.y) / self.cell)
            .floor()
            .clamp(0.0, (self.ny - 1) as f64) as usize;
        (x, y)
    }

    fn take_nearest(&mut self, at: Point, boxes: &[BBox]) -> Option<usize> {
        if self.left == 0 {
            return None;
        }
        let (cx, cy) = self.cell_of(at);
        // How far `at` lies outside the grid: every cell is at least that far.
        let outside = {
            let b = BBox {
                min: self.origin,
                max: Point::new(
                    self.origin.x + self.cell * self.nx as f64,
                    self.origin.y + self.cell * self.ny as f64,
                ),
            };
            box_dist(&b, at).sqrt()
        };
        let mut best: Option<(f64, usize)> = None;
        let max_r = self.nx.max(self.ny);
        for r in 0..=max_r {
            // Cells of ring r are at least (r − 1) cells away (plus the way into the grid).
            let bound = (r as f64 - 1.0).max(0.0) * self.cell + outside;
            if best.is_some_and(|(d, _)| d < bound * bound) {
                break;
            }
            let (x0, x1) = (cx as isize - r as isize, cx as isize + r as isize);
            let (y0, y1) = (cy as isize - r as isize, cy as isize + r as isize);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let on_ring = y == y0 || y == y1 || x == x0 || x == x1;
                    if !on_ring || x < 0 || y < 0 || x >= self.nx as isize || y >= self.ny as isize
                    {
                        continue;
                    }
                    for &k in &self.cells[y as usize * self.nx + x as usize] {
                        let k = k as usize;
                        if self.taken[k] {
                            continue;
                        }
                        let d = box_dist(&boxes[self.ids[k]], at);
                        if best.is_none_or(|(bd, bk)| {
                            d < bd || (d == bd && self.ids[k] < self.ids[bk])
                        }) {
                            best = Some((d, k));
                        }
                    }
                }
            }
        }
        let (_, k) = best?;
        self.taken[k] = true;
        self.left -= 1;
        Some(self.ids[k])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_search_visits_in_the_same_order_as_a_linear_scan() {
        let mut x = 0x2545_f491_u64;
        let mut rnd = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % 1_000_000) as f64 / 1000.0
        };
        let boxes: Vec<BBox> = (0..700)
            .map(|_| {
                let (px, py, w, h) = (rnd(), rnd(), rnd() / 50.0, rnd() / 50.0);
                BBox {
                    min: Point::new(px, py),
                    max: Point::new(px + w, py + h),
                }
            })
            .collect();
        let ids: Vec<usize> = (0..boxes.len()).collect();
        let mut grid = Siblings::new(ids.clone(), &boxes);
        assert!(matches!(grid, Siblings::Many(_)));
        let mut linear = Siblings::Few(ids);
        let mut at = Point::new(-50.0, 300.0);
        for _ in 0..boxes.len() {
            let a = grid.take_nearest(at, &boxes).unwrap();
            let b = linear.take_nearest(at, &boxes).unwrap();
            assert_eq!(a, b);
            at = boxes[a].max;
        }
        assert!(grid.take_nearest(at, &boxes).is_none());
    }
}
