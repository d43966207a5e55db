//! Nearest next over loose items — open contours, marks, spots — each
//! entered at one of a few points (an end, a vertex): the tool goes to the
//! nearest entry point of any item not yet visited.
//!
//! Why a grid (issue 17, "no stage superlinear"): a scan of every item
//! left at every step was quadratic — 20,000 open lines cut with
//! `--cut-open` took 5.1 s, 10,000 marking strokes 1.6 s, where a nested
//! sheet with a part number on each part has tens of thousands. The grid
//! of the rapid tour ([`super::tsp::Grid`], lazy deletion) finds each next
//! one in about constant time.

use super::tsp::Grid;
use crate::geom::Point;

/// Items per grid cell: an item has two to a few entry points.
const PER_CELL: f64 = 4.0;

/// Visits items `0..n` nearest next from `from`. `points` are the entry
/// points and `owners` the item of each (items with no point are not
/// visited). `visit(item)` is called once per item, in order, and returns
/// where the tool is after it. Ties go to the point found first. Items
/// whose every point is non-finite are visited last, in item order:
/// nothing given is dropped.
pub(super) fn visit_nearest(
    points: &[Point],
    owners: &[usize],
    n: usize,
    from: Point,
    mut visit: impl FnMut(usize) -> Point,
) {
    let finite: Vec<u32> = (0..points.len().min(owners.len()))
        .filter(|&i| points[i].is_finite() && owners[i] < n)
        .map(|i| i as u32)
        .collect();
    let at: Vec<Point> = finite.iter().map(|&i| points[i as usize]).collect();
    let mut grid = Grid::new(&at, PER_CELL);
    for k in 0..at.len() {
        grid.insert_nth(k);
    }
    let owner = |k: u32| owners[finite[k as usize] as usize];
    let mut done = vec![false; n];
    let mut here = if from.is_finite() {
        from
    } else {
        Point::default()
    };
    while let Some((k, _)) = grid.nearest(here, |k| at[k as usize], |k| !done[owner(k)]) {
        let item = owner(k);
        done[item] = true;
        here = visit(item);
        if !here.is_finite() {
            here = at[k as usize];
        }
    }
    // Items with points, none of them finite.
    let mut has = vec![false; n];
    for &o in owners.iter().filter(|&&o| o < n) {
        has[o] = true;
    }
    for item in 0..n {
        if has[item] && !done[item] {
            done[item] = true;
            visit(item);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The order by a scan of everything left at each step (the old way),
    /// the reference the grid must agree with where there are no ties.
    fn scanned(points: &[Point], owners: &[usize], n: usize, from: Point) -> Vec<usize> {
        let mut done = vec![false; n];
        let mut here = from;
        let mut out = Vec::new();
        loop {
            let best = (0..points.len())
                .filter(|&i| !done[owners[i]])
                .min_by(|&a, &b| points[a].dist(here).total_cmp(&points[b].dist(here)));
            let Some(i) = best else { break };
            done[owners[i]] = true;
            out.push(owners[i]);
            here = points[i];
        }
        out
    }

    #[test]
    fn agrees_with_a_scan_of_everything_left() {
        let mut f = crate::test_rng::unit(0x9E37_79B9_7F4A_7C15u64);
        for n in [1, 2, 17, 500] {
            let mut points = Vec::new();
            let mut owners = Vec::new();
            for item in 0..n {
                for _ in 0..(1 + item % 3) {
                    points.push(Point::new(f() * 900.0, f() * 400.0));
                    owners.push(item);
                }
            }
            let from = Point::new(-5.0, 3.0);
            let mut got = Vec::new();
            let mut here = from;
            visit_nearest(&points, &owners, n, from, |item| {
                got.push(item);
                // The tool stops where it entered: the item's point
                // nearest where it was.
                here = (0..points.len())
                    .filter(|&i| owners[i] == item)
                    .map(|i| points[i])
                    .min_by(|a, b| a.dist(here).total_cmp(&b.dist(here)))
                    .unwrap_or(here);
                here
            });
            assert_eq!(got, scanned(&points, &owners, n, from), "n {n}");
        }
    }

    #[test]
    fn every_item_with_a_point_is_visited_once_even_non_finite() {
        let points = [
            Point::new(f64::NAN, 0.0),
            Point::new(5.0, 0.0),
            Point::new(1.0, 0.0),
            Point::new(f64::INFINITY, 1.0),
        ];
        // Item 0 has only a NaN point, item 3 none at all, item 4 an
        // infinite one: 1 and 2 first (nearest next), then 0 and 4.
        let owners = [0, 1, 2, 4];
        let mut got = Vec::new();
        visit_nearest(&points, &owners, 5, Point::default(), |i| {
            got.push(i);
            Point::new(f64::NAN, f64::NAN)
        });
        assert_eq!(got, vec![2, 1, 0, 4]);
    }
}
