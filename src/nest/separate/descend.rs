//! The refinement of a sampled position: coordinate descent (sparrow's
//! last step of a move, Gardeyn & Wauters, EJOR 2025, §4.3), and the
//! translations that keep a copy inside the room.

use super::overlap::Table;
use super::sample::{Kit, Layout};
use crate::geom::Point;

impl Kit {
    /// Coordinate descent from `best` within `lo`–`hi`: ±x, ±y with a
    /// step that grows on success and halves after four failures; `eval`
    /// is the cost at a translation, given up past its bound.
    pub(super) fn descend(
        &self,
        (lo, hi): (Point, Point),
        mut best: (f64, Point),
        size: f64,
        eval: &dyn Fn(Point, f64) -> f64,
    ) -> (f64, Point) {
        let mut step = 0.05 * size;
        let floor = (1e-4 * size).max(self.eps * 10.0);
        let dirs = [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)];
        let mut d = 0;
        let mut fails = 0;
        while best.0 > 0.0 && step > floor {
            let (dx, dy) = dirs[d];
            let t = Point::new(
                (best.1.x + dx * step).clamp(lo.x, hi.x),
                (best.1.y + dy * step).clamp(lo.y, hi.y),
            );
            let c = eval(t, best.0);
            if c < best.0 {
                best = (c, t);
                step *= 1.5;
                fails = 0;
            } else {
                d = (d + 1) % 4;
                fails += 1;
                if fails == 4 {
                    step /= 2.0;
                    fails = 0;
                }
            }
        }
        best
    }

    /// [`Self::descend`] of piece `k` as its variant `best.1`.
    pub(super) fn descend_variant(
        &self,
        lay: &Layout,
        table: &Table,
        k: usize,
        best: (f64, usize, Point),
        size: f64,
    ) -> (f64, usize, Point) {
        let (c, v, t) = best;
        let range = lay.range_at(self.items[lay.pieces[k].item].variants[v].shape.bbox(), t);
        let eval = |t: Point, upper: f64| self.cost(lay, table, k, v, t, upper);
        let (c, t) = self.descend(range, (c, t), size, &eval);
        (c, v, t)
    }
}
