//! The parts' boxes in a coarse grid: whether anything of another part
//! lies near a box, answered from a few cells of a few boxes each. On a
//! sheet spaced for the kerf nearly every cutting move is near no other
//! part, and the loss checks ([`super::closeness`]) then need no segment
//! index at all (on the 20,000-part nest, building it was a quarter of
//! their time, its look-ups most of the rest: benches/pipeline.rs
//! `-- --warnings`).

use crate::cell_lists::CellLists;
use crate::contour::Contours;
use crate::geom::BBox;

/// Most cells a box may be filed under; a bigger one is checked by every query.
const MAX_CELLS: i64 = 64;

/// Each part's box, filed by the cells of a grid about one mean part wide.
pub(crate) struct PartBoxes {
    /// Part number (1-based) and box of each part with closed contours.
    boxes: Vec<(usize, BBox)>,
    cell: f64,
    x0: i64,
    y0: i64,
    nx: i64,
    ny: i64,
    lists: CellLists,
    big: Vec<u32>,
}

impl PartBoxes {
    /// The boxes of the parts of `contours` (the union of each part's
    /// closed contours' boxes).
    pub(crate) fn new(contours: &Contours) -> PartBoxes {
        let mut by_part: Vec<Option<BBox>> = Vec::new();
        for c in contours.contours.iter().filter(|c| c.is_closed()) {
            let Some(p) = c.part else { continue };
            if !(c.bbox.min.is_finite() && c.bbox.max.is_finite()) {
                continue;
            }
            if by_part.len() <= p {
                by_part.resize(p + 1, None);
            }
            by_part[p].get_or_insert(BBox::EMPTY).union(&c.bbox);
        }
        let boxes: Vec<(usize, BBox)> = by_part
            .into_iter()
            .enumerate()
            .filter_map(|(p, b)| b.map(|b| (p, b)))
            .collect();
        let mut ext = BBox::EMPTY;
        let mut size = 0.0;
        for (_, b) in &boxes {
            ext.union(b);
            size += (b.max.x - b.min.x) + (b.max.y - b.min.y);
        }
        let n = boxes.len().max(1) as f64;
        let cell = (size / (2.0 * n)).max(1.0);
        let mut g = PartBoxes {
            boxes,
            cell,
            x0: 0,
            y0: 0,
            nx: 1,
            ny: 1,
            lists: CellLists::default(),
            big: Vec::new(),
        };
        if ext.is_empty() {
            return g;
        }
        let (x0, y0, x1, y1) = g.cells(&ext);
        // A drawing whose extent is millions of cells (parts far apart
        // or one huge part) is filed coarser.
        let (w, h) = (x1 - x0 + 1, y1 - y0 + 1);
        if w.saturating_mul(h) > 4 * (n as i64) + 1024 {
            let k = ((w as f64 * h as f64) / (4.0 * n + 1024.0)).sqrt().ceil();
            g.cell *= k.max(1.0);
        }
        let (x0, y0, x1, y1) = g.cells(&ext);
        (g.x0, g.y0, g.nx, g.ny) = (x0, y0, x1 - x0 + 1, y1 - y0 + 1);
        let mut big = Vec::new();
        let lists = CellLists::build((g.nx * g.ny) as usize, |f| {
            big.clear();
            for (i, (_, b)) in g.boxes.iter().enumerate() {
                let (a, c, bx, by) = g.cells(b);
                if (bx - a + 1).saturating_mul(by - c + 1) > MAX_CELLS {
                    big.push(i as u32);
                    continue;
                }
                for y in c..=by {
                    for x in a..=bx {
                        f.push(((y - g.y0) * g.nx + (x - g.x0)) as usize, i as u32);
                    }
                }
            }
        });
        g.lists = lists;
        g.big = big;
        g
    }

    fn cells(&self, b: &BBox) -> (i64, i64, i64, i64) {
        let c = |v: f64| (v / self.cell).floor().clamp(-1e15, 1e15) as i64;
        (c(b.min.x), c(b.min.y), c(b.max.x), c(b.max.y))
    }

    /// True when the box of a part other than `own` (any part when
    /// `None`) overlaps `b`.
    pub(crate) fn others_near(&self, b: &BBox, own: Option<usize>) -> bool {
        let hit = |i: u32| {
            let (p, pb) = &self.boxes[i as usize];
            Some(*p) != own && pb.overlaps(b, 0.0)
        };
        if self.big.iter().any(|&i| hit(i)) {
            return true;
        }
        let (a, c, bx, by) = self.cells(b);
        let (xa, xb) = (a.max(self.x0), bx.min(self.x0 + self.nx - 1));
        let (ya, yb) = (c.max(self.y0), by.min(self.y0 + self.ny - 1));
        if (xb - xa + 1).saturating_mul(yb - ya + 1) > MAX_CELLS * 16 {
            return self.boxes.iter().enumerate().any(|(i, _)| hit(i as u32));
        }
        (ya..=yb).any(|y| {
            (xa..=xb).any(|x| {
                self.lists
                    .get(((y - self.y0) * self.nx + (x - self.x0)) as usize)
                    .iter()
                    .any(|&i| hit(i))
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;
    use crate::test_dxf;

    fn drawing(rects: &[(f64, f64, f64, f64)]) -> Contours {
        let body: String = rects
            .iter()
            .map(|&(x, y, w, h)| test_dxf::rect(x, y, w, h))
            .collect();
        let s = crate::Settings::new(1.5, 0.001, 2000.0).unwrap();
        crate::run(&test_dxf::file(&body), &s).unwrap().contours
    }

    fn bx(x0: f64, y0: f64, x1: f64, y1: f64) -> BBox {
        BBox {
            min: Point::new(x0, y0),
            max: Point::new(x1, y1),
        }
    }

    #[test]
    fn a_box_near_another_part_is_seen_and_its_own_part_is_not() {
        // A grid of 10 x 10 plates 10 mm wide, 5 mm apart, and one long
        // plate under them (filed as a big box).
        let mut rects: Vec<(f64, f64, f64, f64)> = (0..100)
            .map(|i| {
                (
                    (i % 10) as f64 * 15.0,
                    30.0 + (i / 10) as f64 * 15.0,
                    10.0,
                    10.0,
                )
            })
            .collect();
        rects.push((0.0, 0.0, 2000.0, 5.0));
        let contours = drawing(&rects);
        let g = PartBoxes::new(&contours);
        assert_eq!(g.boxes.len(), 101);
        // Around plate (3, 4)'s box: only itself.
        let (x, y) = (45.0, 90.0);
        let own = contours
            .contours
            .iter()
            .find(|c| (c.bbox.min.x - x).abs() < 1e-9 && (c.bbox.min.y - y).abs() < 1e-9)
            .and_then(|c| c.part);
        let around = bx(x - 0.75, y - 0.75, x + 10.75, y + 10.75);
        assert!(!g.others_near(&around, own));
        assert!(g.others_near(&around, None));
        // Reaching 4.5 mm right: still clear; 5.5 mm: the neighbour.
        assert!(!g.others_near(&bx(x, y, x + 14.5, y + 10.0), own));
        assert!(g.others_near(&bx(x, y, x + 15.5, y + 10.0), own));
        // Down to the long plate, and far away nothing.
        assert!(g.others_near(&bx(1500.0, 4.0, 1501.0, 6.0), None));
        assert!(!g.others_near(&bx(1500.0, 100.0, 1501.0, 101.0), None));
        // Brute force over many boxes.
        for k in 0..400 {
            let (x, y) = ((k * 37 % 170) as f64 - 10.0, (k * 53 % 200) as f64 - 10.0);
            let b = bx(x, y, x + (k % 7) as f64, y + (k % 5) as f64);
            let want = g.boxes.iter().any(|(_, pb)| pb.overlaps(&b, 0.0));
            assert_eq!(g.others_near(&b, None), want, "{b:?}");
        }
    }
}
