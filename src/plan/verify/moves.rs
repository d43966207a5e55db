//! The cutting moves filed by the cells of one flat grid ([`CellLists`]):
//! which moves reach a point, and which may reach a box. The cells are
//! about a move's share of the sheet (never under four reaches), so a part's
//! box meets a few of them and the grid holds a few cells per move.

use crate::cell_lists::CellLists;
use crate::geom::{dist_to_segment, BBox, Point, Segment};

/// Most cells of the moves' grid per move, plus [`CELLS_FREE`].
const CELLS_PER_MOVE: usize = 4;
const CELLS_FREE: usize = 4096;

/// The cutting moves, filed by the cells of a grid that lie within the
/// kerf's reach of them.
pub(super) struct Moves<'a> {
    pub(super) moves: Vec<&'a Segment>,
    /// Each move's box grown by the reach (and a margin far above rounding).
    boxes: Vec<BBox>,
    reach: f64,
    /// The grid's lower left corner, its cell side and size.
    origin: Point,
    g: f64,
    nx: usize,
    ny: usize,
    lists: CellLists,
}

impl<'a> Moves<'a> {
    /// The cutting moves `moves`, reaching `reach` mm. A move not finite
    /// is left out: its samples are not finite and reach nothing.
    pub(super) fn new(moves: impl Iterator<Item = &'a Segment>, reach: f64) -> Moves<'a> {
        let moves: Vec<&Segment> = moves.filter(|s| s.is_finite()).collect();
        let boxes: Vec<BBox> = moves.iter().map(|s| s.bbox().grown(reach)).collect();
        let mut ext = BBox::EMPTY;
        for b in &boxes {
            ext.union(b);
        }
        let (w, h) = match ext.is_empty() {
            true => (0.0, 0.0),
            false => (ext.max.x - ext.min.x, ext.max.y - ext.min.y),
        };
        // Cells of at least four reaches (a sample's cells are then few),
        // about one move's share of the sheet each, and never more than
        // a few per move.
        let most = CELLS_PER_MOVE * moves.len() + CELLS_FREE;
        let mut g = (4.0 * reach)
            .max(1.0)
            .max((w * h / moves.len().max(1) as f64).sqrt());
        // Counted in floating point: a drawing kilometres wide (or wider
        // than any integer) only widens the cells.
        let size = |g: f64| (((w + g) / g).ceil() + 2.0, ((h + g) / g).ceil() + 2.0);
        while size(g).0 * size(g).1 > most as f64 && g < f64::MAX / 4.0 {
            g *= 2.0;
        }
        let (nx, ny) = (size(g).0 as usize, size(g).1 as usize);
        let (nx, ny) = (nx.clamp(3, most), ny.clamp(3, most));
        // Every sample's cells lie on the grid: the moves' boxes grown by
        // the half cell a sample's cells reach past the reach.
        let origin = Point::new(ext.min.x - g, ext.min.y - g);
        let mut out = Moves {
            moves,
            boxes,
            reach,
            origin,
            g,
            nx,
            ny,
            lists: CellLists::default(),
        };
        out.lists = out.file();
        out
    }

    /// Files each move under the cells within `reach + g / 2` of points
    /// half a cell apart along it: a point within the reach of a move lies
    /// within `reach + g / 4` of one of them, so its cell lists the move.
    /// (Filed along the move: a long diagonal's box would cover a sheet.)
    fn file(&self) -> CellLists {
        let pad = self.reach + self.g / 2.0;
        let mut last = vec![u32::MAX; self.nx * self.ny];
        CellLists::build(self.nx * self.ny, |f| {
            last.fill(u32::MAX);
            for (m, s) in self.moves.iter().enumerate() {
                let n = ((s.length() / (self.g / 2.0)).ceil() as usize).clamp(1, 1_000_000);
                let mut seen = None;
                for k in 0..=n {
                    let p = s.point_at(k as f64 / n as f64);
                    let (lo, hi) = (
                        self.cell(p.x - pad, p.y - pad),
                        self.cell(p.x + pad, p.y + pad),
                    );
                    if seen == Some((lo, hi)) {
                        continue;
                    }
                    seen = Some((lo, hi));
                    for j in lo.1..=hi.1 {
                        for i in lo.0..=hi.0 {
                            let c = j * self.nx + i;
                            if last[c] != m as u32 {
                                last[c] = m as u32;
                                f.push(c, m as u32);
                            }
                        }
                    }
                }
            }
        })
    }

    /// The cell of a point, clamped to the grid.
    fn cell(&self, x: f64, y: f64) -> (usize, usize) {
        let f = |v: f64, n: usize| ((v / self.g).floor().max(0.0) as usize).min(n - 1);
        (f(x - self.origin.x, self.nx), f(y - self.origin.y, self.ny))
    }

    /// True when some move comes within the reach of `q`.
    pub(super) fn reached(&self, q: Point) -> bool {
        let (x, y) = (
            (q.x - self.origin.x) / self.g,
            (q.y - self.origin.y) / self.g,
        );
        if !(x >= 0.0 && y >= 0.0 && x < self.nx as f64 && y < self.ny as f64) {
            return false;
        }
        let c = y as usize * self.nx + x as usize;
        self.lists.get(c).iter().any(|&m| {
            let b = &self.boxes[m as usize];
            b.overlaps(&BBox::at(q), 0.0)
                && dist_to_segment(q, self.moves[m as usize]) <= self.reach
        })
    }

    /// Into `out`, once each, every move that may come within the reach
    /// of a point of `b`; `mark` holds a number per move, the latest
    /// query's for those already taken.
    pub(super) fn near(&self, b: &BBox, mark: &mut Vec<u32>, query: u32, out: &mut Vec<u32>) {
        out.clear();
        mark.resize(self.moves.len(), u32::MAX);
        let (lo, hi) = (self.cell(b.min.x, b.min.y), self.cell(b.max.x, b.max.y));
        for j in lo.1..=hi.1 {
            for i in lo.0..=hi.0 {
                for &m in self.lists.get(j * self.nx + i) {
                    if mark[m as usize] != query && self.boxes[m as usize].overlaps(b, 0.0) {
                        mark[m as usize] = query;
                        out.push(m);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    //! The moves' grid against every move: the same "reached", and no
    //! move that can reach a box missing from its look-up.
    use super::*;

    /// Random moves over a 400 × 300 mm sheet: short and long lines (a few
    /// across the sheet) and arcs of every sweep, points within twice the
    /// reach of them and points anywhere.
    fn moves_and_points(seed: u64, reach: f64) -> (Vec<Segment>, Vec<Point>) {
        let mut f = crate::test_rng::unit(seed);
        let mut moves = Vec::new();
        for i in 0..300 {
            let a = Point::new(400.0 * f(), 300.0 * f());
            let len = if i % 50 == 0 { 500.0 } else { 40.0 * f() };
            let t = std::f64::consts::TAU * f();
            let b = Point::new(a.x + len * t.cos(), a.y + len * t.sin());
            let bulge = if i % 3 == 0 { 2.0 * f() - 1.0 } else { 0.0 };
            moves.push(Segment { a, b, bulge });
        }
        let mut points = Vec::new();
        for s in &moves {
            for _ in 0..20 {
                let p = s.point_at(f());
                let t = std::f64::consts::TAU * f();
                let d = 2.0 * reach * f();
                points.push(Point::new(p.x + d * t.cos(), p.y + d * t.sin()));
            }
        }
        for _ in 0..2000 {
            points.push(Point::new(-50.0 + 500.0 * f(), -50.0 + 400.0 * f()));
        }
        (moves, points)
    }

    #[test]
    fn reached_is_some_move_within_the_reach() {
        for (seed, reach) in [(7u64, 0.76), (11, 0.01), (13, 2.5)] {
            let (moves, points) = moves_and_points(0x9E37_79B9_7F4A_7C15 ^ seed, reach);
            let index = Moves::new(moves.iter(), reach);
            let (mut yes, mut no) = (0, 0);
            for q in points {
                let want = moves.iter().any(|s| dist_to_segment(q, s) <= reach);
                assert_eq!(index.reached(q), want, "reach {reach} at {q:?}");
                if want {
                    yes += 1;
                } else {
                    no += 1;
                }
            }
            assert!(yes > 1000 && no > 2000, "{yes} reached, {no} not");
        }
    }

    #[test]
    fn near_lists_every_move_that_reaches_the_box() {
        let reach = 0.76;
        let (moves, points) = moves_and_points(0xD1B5_4A32_D192_ED03, reach);
        let index = Moves::new(moves.iter(), reach);
        let (mut mark, mut out) = (Vec::new(), Vec::new());
        for (query, q) in points.iter().step_by(7).enumerate() {
            // Boxes from a few mm to a part's size.
            let (w, h) = (
                1.0 + (query % 40) as f64 * 2.0,
                1.0 + (query % 17) as f64 * 3.0,
            );
            let b = BBox {
                min: Point::new(q.x - w, q.y - h),
                max: Point::new(q.x + w, q.y + h),
            };
            index.near(&b, &mut mark, query as u32, &mut out);
            let mut listed = out.clone();
            listed.sort_unstable();
            listed.dedup();
            assert_eq!(listed.len(), out.len(), "a move listed twice");
            // Every move within the reach of a point of the box (its corners,
            // its centre, and the moves' own points inside it).
            for (m, s) in moves.iter().enumerate() {
                let mut probes = vec![b.min, b.max, *q, Point::new(b.min.x, b.max.y)];
                probes.extend((0..=64).map(|k| s.point_at(k as f64 / 64.0)).filter(|p| {
                    p.x >= b.min.x && p.x <= b.max.x && p.y >= b.min.y && p.y <= b.max.y
                }));
                if probes.iter().any(|&p| dist_to_segment(p, s) <= reach) {
                    assert!(out.contains(&(m as u32)), "move {m} near {b:?} not listed");
                }
            }
        }
    }
}
