//! The verification's heat map (issue 20 §9): the very cells the
//! verification's `overcut_mm2` counts, for the preview. A raster too fine
//! to draw (more than `max` cells) is binned into coarser squares, each
//! keeping the deepest depth of the cells it holds: the same cells, drawn
//! bigger, never fewer places.

use std::collections::HashMap;

use crate::geom::Point;

/// `cells` (centres on a grid of side `cell`, with depths) in squares of a
/// side `cell × 2^k`, the smallest that gives at most `max` squares; the
/// side and the squares (centre, deepest depth) in raster order.
pub fn binned(cells: &[(Point, f64)], cell: f64, max: usize) -> (f64, Vec<(Point, f64)>) {
    if cells.is_empty() || !(cell > 0.0 && cell.is_finite()) {
        return (cell, Vec::new());
    }
    let mut side = cell;
    loop {
        let mut bins: HashMap<(i64, i64), f64> = HashMap::new();
        for &(p, d) in cells {
            let k = ((p.x / side).floor() as i64, (p.y / side).floor() as i64);
            let e = bins.entry(k).or_insert(0.0);
            *e = e.max(d);
        }
        // A side past a million cells holds any drawing in a few squares.
        if bins.len() <= max.max(1) || side > cell * 1e6 {
            let mut v: Vec<((i64, i64), f64)> = bins.into_iter().collect();
            crate::sort::sort_cells(&mut v);
            let squares = v
                .into_iter()
                .map(|((i, j), d)| {
                    let c = Point::new((i as f64 + 0.5) * side, (j as f64 + 0.5) * side);
                    (c, d)
                })
                .collect();
            return (side, squares);
        }
        side *= 2.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cell of a 0.1 mm grid (as the verification makes them).
    fn c(i: i64, j: i64, d: f64) -> (Point, f64) {
        (
            Point::new((i as f64 + 0.5) * 0.1, (j as f64 + 0.5) * 0.1),
            d,
        )
    }

    #[test]
    fn few_cells_are_kept_as_they_are() {
        let (side, v) = binned(&[c(5, 0, 0.5), c(0, 0, 0.3)], 0.1, 10);
        assert_eq!(side, 0.1);
        assert_eq!(v.len(), 2);
        assert!((v[0].0.x - 0.05).abs() < 1e-12 && v[0].1 == 0.3);
        assert!((v[1].0.x - 0.55).abs() < 1e-12 && v[1].1 == 0.5);
        assert!(binned(&[], 0.1, 10).1.is_empty());
    }

    #[test]
    fn too_many_are_binned_covering_every_cell_and_keeping_the_depth() {
        let many: Vec<_> = (0..300i64)
            .flat_map(|i| {
                (0..300i64).map(move |j| c(i, j, if (i, j) == (7, 9) { 2.0 } else { 0.1 }))
            })
            .collect();
        let (side, v) = binned(&many, 0.1, 50_000);
        assert!((side - 0.2).abs() < 1e-12, "{side}");
        assert_eq!(v.len(), 150 * 150);
        // Every cell lies in a square (checked by distance, not by the binning's keys).
        for &(p, _) in many.iter().step_by(97) {
            assert!(v
                .iter()
                .any(|&(q, _)| (p.x - q.x).abs() <= side / 2.0 && (p.y - q.y).abs() <= side / 2.0));
        }
        assert_eq!(v.iter().filter(|s| s.1 == 2.0).count(), 1);
        // And a limit of one square: everything in one.
        let (_, one) = binned(&many, 0.1, 1);
        assert_eq!(one.len(), 1);
        assert_eq!(one[0].1, 2.0);
    }
}
