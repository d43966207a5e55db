//! Indexes of the containment search ([`super::depth`]): lists stored
//! flat, and a uniform grid of contour boxes.

use super::Contour;
use crate::geom::Point;

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
    pub(super) fn new(contours: &[Contour], members: &[usize]) -> BoxGrid {
        let mut ext = crate::geom::BBox::EMPTY;
        for &i in members {
            ext.union(&contours[i].bbox);
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
            let total: usize = members
                .iter()
                .map(|&i| {
                    let ((x0, x1), (y0, y1)) = g.span_of(&contours[i].bbox);
                    (x1 - x0 + 1) * (y1 - y0 + 1)
                })
                .sum();
            if total <= CELLS_PER_CONTOUR * members.len() || side == 1 {
                let mut pairs = Vec::with_capacity(total);
                for &i in members {
                    let ((x0, x1), (y0, y1)) = g.span_of(&contours[i].bbox);
                    for y in y0..=y1 {
                        pairs.extend((x0..=x1).map(|x| ((y * side + x) as u32, i as u32)));
                    }
                }
                g.cells = Lists::new(side * side, &pairs);
                return g;
            }
            side = (side / 2).max(1);
        }
    }
    fn index(&self, v: f64, o: f64) -> usize {
        (crate::geom::floor((v - o) / self.cell).max(0.0) as usize).min(self.side - 1)
    }
    /// Columns and rows (first and last) of the cells a box overlaps.
    fn span_of(&self, b: &crate::geom::BBox) -> ((usize, usize), (usize, usize)) {
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
