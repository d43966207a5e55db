//! Indexes of the containment search ([`super::depth`]): lists stored
//! flat, and a uniform grid of contour boxes.

use super::Contour;
use crate::geom::{BBox, Point};
use crate::par::Threads;

/// Lists stored flat (compressed rows): list `k` is
/// `items[start[k]..start[k + 1]]`. One allocation for all the lists, where a
/// `Vec` per list cost a malloc and a free each (issue 17: 137k cells).
pub(super) struct Lists {
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Lists {
    /// The lists of `n` keys from `(key, item)` pairs, each list in the
    /// order given (one body for both users: the page's wasm stays small).
    #[inline(never)]
    pub(super) fn new(n: usize, pairs: &[(u32, u32)]) -> Lists {
        let mut start = vec![0u32; n + 1];
        for &(k, _) in pairs {
            start[k as usize + 1] += 1;
        }
        for k in 1..=n {
            start[k] += start[k - 1];
        }
        let mut fill = start.clone();
        let mut items = vec![0u32; pairs.len()];
        for &(k, item) in pairs {
            items[fill[k as usize] as usize] = item;
            fill[k as usize] += 1;
        }
        Lists { start, items }
    }
    /// The lists of `parts` one after another (list numbers running on).
    fn concat(mut parts: Vec<Lists>) -> Lists {
        if parts.len() == 1 {
            if let Some(one) = parts.pop() {
                return one;
            }
        }
        let mut start = vec![0u32];
        let mut items = Vec::with_capacity(parts.iter().map(|p| p.items.len()).sum());
        for p in parts {
            let at = items.len() as u32;
            start.extend(p.start[1..].iter().map(|&s| s + at));
            items.extend_from_slice(&p.items);
        }
        Lists { start, items }
    }
    pub(super) fn get(&self, k: usize) -> &[u32] {
        &self.items[self.start[k] as usize..self.start[k + 1] as usize]
    }
}

/// Uniform grid of contour boxes: a contour is registered in every cell its
/// box overlaps, so the possible containers of a point are those of its cell.
pub(super) struct BoxGrid {
    origin: Point,
    cell: f64,
    side: usize,
    cells: Lists,
}

/// Registrations allowed per contour on average before the grid is coarsened
/// (a pile of nested outlines would otherwise fill every cell).
const CELLS_PER_CONTOUR: usize = 8;

impl BoxGrid {
    /// The grid of the boxes of `members`, each cell's contours in the
    /// order of `members`, made on up to `threads` threads (the same grid
    /// with any number).
    pub(super) fn new(contours: &[Contour], members: &[usize], threads: Threads) -> BoxGrid {
        // The members' boxes read once, in order, on the threads: in area
        // order each is a contour far from the last (a cache miss each),
        // and the box count, the extent and the cells read them again.
        let mut parts = crate::par::map_ranges(members.len(), threads, 8192, |r| {
            members[r]
                .iter()
                .map(|&i| contours[i].bbox)
                .collect::<Vec<BBox>>()
        });
        let boxes = match parts.len() {
            1 => parts.pop().unwrap_or_default(),
            _ => parts.concat(),
        };
        let mut ext = BBox::EMPTY;
        for b in &boxes {
            ext.union(b);
        }
        let span = (ext.max.x - ext.min.x).max(ext.max.y - ext.min.y).max(1e-9);
        let mut side = ((members.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        loop {
            let cell = span / side as f64 * (1.0 + 1e-9);
            let mut g = BoxGrid {
                origin: ext.min,
                cell,
                side,
                cells: Lists {
                    start: Vec::new(),
                    items: Vec::new(),
                },
            };
            let total: usize = boxes
                .iter()
                .map(|b| {
                    let ((x0, x1), (y0, y1)) = g.span_of(b);
                    (x1 - x0 + 1) * (y1 - y0 + 1)
                })
                .sum();
            if total <= CELLS_PER_CONTOUR * members.len() || side == 1 {
                g.cells = g.lists(&boxes, members, threads);
                return g;
            }
            side = (side / 2).max(1);
        }
    }

    /// Every cell's list, made in bands of rows on the threads (two bands
    /// a thread: each band reads every box), each band's lists in the
    /// order of `members`, the bands joined in row order: what one band
    /// of all rows gives.
    fn lists(&self, boxes: &[BBox], members: &[usize], threads: Threads) -> Lists {
        let side = self.side;
        let band = side.div_ceil(2 * threads.get());
        let bands = crate::par::map_ranges(side, threads, band, |rows| {
            let mut pairs = Vec::new();
            for (b, &i) in boxes.iter().zip(members) {
                let (y0, y1) = (
                    self.index(b.min.y, self.origin.y).max(rows.start),
                    self.index(b.max.y, self.origin.y).min(rows.end - 1),
                );
                if y0 > y1 {
                    continue;
                }
                let (x0, x1) = (
                    self.index(b.min.x, self.origin.x),
                    self.index(b.max.x, self.origin.x),
                );
                for y in y0..=y1 {
                    let row = (y - rows.start) * side;
                    pairs.extend((x0..=x1).map(|x| ((row + x) as u32, i as u32)));
                }
            }
            Lists::new(rows.len() * side, &pairs)
        });
        Lists::concat(bands)
    }
    fn index(&self, v: f64, o: f64) -> usize {
        (crate::geom::floor((v - o) / self.cell).max(0.0) as usize).min(self.side - 1)
    }
    /// Columns and rows (first and last) of the cells a box overlaps.
    fn span_of(&self, b: &BBox) -> ((usize, usize), (usize, usize)) {
        (
            (
                self.index(b.min.x, self.origin.x),
                self.index(b.max.x, self.origin.x),
            ),
            (
                self.index(b.min.y, self.origin.y),
                self.index(b.max.y, self.origin.y),
            ),
        )
    }
    /// Contours whose boxes may hold `p`.
    pub(super) fn at(&self, p: Point) -> &[u32] {
        self.cells
            .get(self.index(p.y, self.origin.y) * self.side + self.index(p.x, self.origin.x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A contour that is only a box (all the grid reads).
    fn boxed(x: f64, y: f64, w: f64, h: f64) -> Contour {
        let mut bbox = BBox::EMPTY;
        bbox.add(Point::new(x, y));
        bbox.add(Point::new(x + w, y + h));
        Contour {
            segments: Vec::new(),
            kind: super::super::ContourKind::Outer,
            depth: 0,
            parent: None,
            part: None,
            area: w * h,
            length: 2.0 * (w + h),
            bbox,
            layer: "0".into(),
            entities: Vec::new(),
            source: Default::default(),
            block: None,
            group: None,
        }
    }

    #[test]
    fn the_grid_is_the_same_on_any_threads_and_holds_every_overlap_in_order() {
        let mut rnd = crate::test_rng::unit(0x0b0c_5eed);
        // Small parts and a few sheet-wide ones (many cells each).
        let contours: Vec<Contour> = (0..30_000)
            .map(|k| {
                let big = k % 997 == 0;
                let (w, h) = if big {
                    (900.0 * rnd(), 600.0 * rnd())
                } else {
                    (1.0 + 20.0 * rnd(), 1.0 + 20.0 * rnd())
                };
                boxed(1000.0 * rnd(), 700.0 * rnd(), w, h)
            })
            .collect();
        // Members in a scrambled order, some contours left out.
        let members: Vec<usize> = (0..contours.len())
            .map(|k| (k * 7_919) % contours.len())
            .filter(|k| k % 11 != 3)
            .collect();
        let one = BoxGrid::new(&contours, &members, Threads::ONE);
        for t in [2, 3, 8] {
            let g = BoxGrid::new(&contours, &members, Threads::new(t));
            assert_eq!(g.side, one.side);
            assert_eq!(g.cells.start, one.cells.start, "{t} threads");
            assert_eq!(g.cells.items, one.cells.items, "{t} threads");
        }
        // Each cell: exactly the members whose box meets it, in order.
        let side = one.side;
        let mut want = vec![Vec::new(); side * side];
        for &i in &members {
            let ((x0, x1), (y0, y1)) = one.span_of(&contours[i].bbox);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    want[y * side + x].push(i as u32);
                }
            }
        }
        for (c, w) in want.iter().enumerate() {
            assert_eq!(one.cells.get(c), &w[..], "cell {c}");
        }
    }
}
