//! The refinement of a sampled position: coordinate descent (sparrow's
//! last step of a move, Gardeyn & Wauters, EJOR 2025, §4.3), and the
//! translations that keep a copy inside the room.
//!
//! The descent steps along the diagonals as well as along x and y, as
//! sparrow's does. Round parts need it: a disc wedged between neighbours
//! clears along the line of the centres, which is rarely an axis, and a
//! step along x or y alone runs into the next neighbour, so the copy
//! stayed where it was (a third of the moves on flanges). Measured on
//! flanges with all eight directions at every step (scripts/bench-nest.sh,
//! 40 separations from one layout at 599.6 mm): at a 0.25 % cut every
//! separation succeeded in 84 moves against 38 of 40 in 270; at 0.5 %, 40
//! in 378 against 30 in 978. Eight tries a step cost 15-30 % more time a
//! move, so the diagonals come at every other step; at 60 s that is
//! within noise on flanges and ESICUP (the runs stay at the 1 % cut).

use super::overlap::Table;
use super::sample::{Kit, Layout};
use crate::geom::{fmax, Point};

/// The descent's directions: ±x, ±y, then both diagonals both ways, each
/// of length 1.
const DIRS: [(f64, f64); 8] = {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    [
        (1.0, 0.0),
        (-1.0, 0.0),
        (0.0, 1.0),
        (0.0, -1.0),
        (h, h),
        (-h, -h),
        (h, -h),
        (-h, h),
    ]
};

impl Kit {
    /// Coordinate descent from `best` within `lo`–`hi`: a step along
    /// [`DIRS`] in turn that grows on success and halves after four
    /// failures (as many tries a step as before the diagonals: the axes
    /// at one step, the diagonals at the next); `eval` is the cost at a
    /// translation, given up past its bound.
    pub(super) fn descend(
        &self,
        (lo, hi): (Point, Point),
        mut best: (f64, Point),
        size: f64,
        eval: &dyn Fn(Point, f64) -> f64,
    ) -> (f64, Point) {
        let mut step = 0.05 * size;
        let floor = fmax(1e-4 * size, self.eps * 10.0);
        let mut d = 0;
        let mut fails = 0;
        while best.0 > 0.0 && step > floor {
            let (dx, dy) = DIRS[d];
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
                d = (d + 1) % DIRS.len();
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A cost whose valley runs along the diagonal x = y, falling towards
    /// (0, 0): every step along x or y alone climbs out of the valley.
    fn diagonal_valley(t: Point) -> f64 {
        1.0 + 100.0 * (t.x - t.y).abs() + t.x + t.y
    }

    #[test]
    fn the_descent_follows_a_diagonal_valley() {
        let kit = Kit::new(&[], Vec::new(), 1e-6);
        let eval = |t: Point, _: f64| diagonal_valley(t);
        let start = Point::new(8.0, 8.0);
        let range = (Point::new(0.0, 0.0), Point::new(10.0, 10.0));
        let (c, t) = kit.descend(range, (diagonal_valley(start), start), 10.0, &eval);
        // Along x or y alone it could not leave (8, 8) (cost 17).
        assert!(c < 1.1, "stopped at {t:?}, cost {c}");
        assert!(t.x < 0.05 && t.y < 0.05, "{t:?}");
    }

    #[test]
    fn the_descent_stays_in_its_range_and_never_ends_worse() {
        let kit = Kit::new(&[], Vec::new(), 1e-6);
        // Least at (−3, 12), outside the range: the descent ends at the
        // range's nearest corner, no worse than it began.
        let eval = |t: Point, _: f64| 1.0 + (t.x + 3.0).abs() + (t.y - 12.0).abs();
        let start = Point::new(5.0, 5.0);
        let range = (Point::new(0.0, 0.0), Point::new(10.0, 10.0));
        let c0 = eval(start, f64::INFINITY);
        let (c, t) = kit.descend(range, (c0, start), 10.0, &eval);
        assert!(c <= c0);
        assert!(
            (0.0..=10.0).contains(&t.x) && (0.0..=10.0).contains(&t.y),
            "{t:?}"
        );
        assert!(t.x < 0.05 && t.y > 9.95, "{t:?}");
    }
}
