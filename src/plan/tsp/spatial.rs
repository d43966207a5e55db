//! Site numbers in sheet order (issue 17): above [`super::LARGE`] sites the
//! tour works on sites renumbered along a Hilbert curve through their
//! candidates' centres, and maps its visits back at the end.
//!
//! Why: every per-site array of the search (entry points, candidates,
//! positions, neighbour lists) is read in tour order, and a tour is
//! spatially coherent; site numbers from the drawing are not (the 25 MB
//! nest lists its 68,628 holes first and their plates after them, so each
//! step of the tour jumped 68k sites in every array and most reads of the
//! entry re-choice and the local search were cache misses). Below
//! [`super::LARGE`] sites the arrays fit in cache, and the tours there
//! (those the LKH-3 comparisons measure) keep the drawing's numbers, so
//! their tie-breaks stay what they were.

use super::Sites;
use crate::geom::Point;

/// Bits per axis of the curve: 65,536 cells across the sheet, far below
/// one site's size on any sheet a cutter takes.
const BITS: u32 = 16;

/// Position of cell (x, y) along the Hilbert curve over a 2^BITS square
/// (the classic quadrant-by-quadrant rotation, Hilbert 1891; see
/// Skilling 2004 for the bit form).
fn hilbert(mut x: u32, mut y: u32) -> u64 {
    let n = 1u32 << BITS;
    let mut d = 0u64;
    let mut s = n / 2;
    while s > 0 {
        let rx = u32::from(x & s != 0);
        let ry = u32::from(y & s != 0);
        d += u64::from(s) * u64::from(s) * u64::from((3 * rx) ^ ry);
        // Rotate the quadrant so the curve's sub-square starts where the
        // previous one ended.
        if ry == 0 {
            if rx == 1 {
                x = n - 1 - x;
                y = n - 1 - y;
            }
            std::mem::swap(&mut x, &mut y);
        }
        s /= 2;
    }
    d
}

/// Centre of the finite candidates' box; None without one.
fn centre(candidates: &[Point]) -> Option<Point> {
    let mut it = candidates.iter().filter(|p| p.is_finite());
    let first = *it.next()?;
    let (mut lo, mut hi) = (first, first);
    for p in it {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    Some(lo.add(hi).scale(0.5))
}

/// The sites' indices in Hilbert order of their centres (ties by index;
/// sites without a finite candidate at the curve's start): `order[i]` is the site
/// numbered `i` in the search.
pub(super) fn order(sites: &Sites) -> Vec<usize> {
    let centres: Vec<Option<Point>> = (0..sites.count())
        .map(|i| centre(sites.candidates(i)))
        .collect();
    let (mut lo, mut hi) = (
        Point::new(f64::MAX, f64::MAX),
        Point::new(f64::MIN, f64::MIN),
    );
    for c in centres.iter().flatten() {
        lo = Point::new(lo.x.min(c.x), lo.y.min(c.y));
        hi = Point::new(hi.x.max(c.x), hi.y.max(c.y));
    }
    let side = (hi.x - lo.x).max(hi.y - lo.y);
    let scale = if side > 0.0 && side.is_finite() {
        f64::from((1u32 << BITS) - 1) / side
    } else {
        0.0
    };
    let cell = |v: f64| ((v * scale) as u32).min((1u32 << BITS) - 1);
    // Key: curve position above, site index below (u32: a tour of more
    // than 4 billion sites is not a sheet).
    let mut keys: Vec<u64> = centres
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let h = c.map_or(0, |c| hilbert(cell(c.x - lo.x), cell(c.y - lo.y)));
            (h << 32) | (i as u64 & 0xffff_ffff)
        })
        .collect();
    crate::sort::sort_u64(&mut keys);
    keys.iter().map(|k| (k & 0xffff_ffff) as usize).collect()
}

#[cfg(test)]
mod tests {
    use super::super::Site;
    use super::*;

    #[test]
    fn the_curve_visits_every_cell_once_in_unit_steps() {
        // On the 2^BITS square, neighbours along the curve are neighbouring
        // cells: checked on its first 4,096 positions by inverting a table.
        let m = 64u32;
        let mut at = vec![None; (m * m) as usize];
        for x in 0..m {
            for y in 0..m {
                let d = hilbert(x, y);
                // The first m*m positions of the curve fill an m x m corner.
                if d < u64::from(m * m) {
                    assert!(at[d as usize].is_none());
                    at[d as usize] = Some((x, y));
                }
            }
        }
        let cells: Vec<(u32, u32)> = at.into_iter().map(|c| c.expect("filled")).collect();
        for w in cells.windows(2) {
            let (a, b) = (w[0], w[1]);
            assert_eq!(a.0.abs_diff(b.0) + a.1.abs_diff(b.1), 1, "{a:?} {b:?}");
        }
    }

    #[test]
    fn order_is_a_permutation_in_sheet_order() {
        // Holes listed first, plates after (as the 25 MB nest draws them):
        // in the new order each hole sits next to its plate.
        let mut sites = Vec::new();
        for k in 0..50 {
            let x = (k % 10) as f64 * 100.0;
            let y = (k / 10) as f64 * 100.0;
            sites.push(Site {
                // The plate's centre (x + 45, y + 45).
                candidates: vec![
                    Point::new(x + 35.0, y + 45.0),
                    Point::new(x + 55.0, y + 45.0),
                ],
                parent: Some(50 + k),
            });
        }
        for k in 0..50 {
            let x = (k % 10) as f64 * 100.0;
            let y = (k / 10) as f64 * 100.0;
            sites.push(Site {
                candidates: vec![Point::new(x, y), Point::new(x + 90.0, y + 90.0)],
                parent: None,
            });
        }
        sites.push(Site {
            candidates: vec![Point::new(f64::NAN, 0.0)],
            parent: None,
        });
        let o = order(&Sites::of(&sites));
        let mut seen = o.clone();
        crate::sort::sort_indices(&mut seen);
        assert_eq!(seen, (0..sites.len()).collect::<Vec<_>>());
        let pos = |s: usize| o.iter().position(|&t| t == s).unwrap();
        // No finite candidate: the curve's start, with the sites (0 and 50)
        // centred on its first cell.
        assert_eq!(&o[..3], &[0, 50, 100]);
        for k in 0..50 {
            assert_eq!(pos(k).abs_diff(pos(50 + k)), 1, "hole {k} beside its plate");
        }
    }
}
