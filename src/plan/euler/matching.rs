//! Pairing the odd vertices (paper 003 §4, after Edmonds 1973): a
//! minimum-weight perfect matching makes every vertex even at least cost.
//!
//! Up to [`EXACT_MAX`] odd vertices the matching is exact: the O(n³)
//! primal-dual blossom algorithm of the `integer-blossom` crate, on costs in
//! nanometres. Above that the solver's (2n+1)² table (16 bytes an entry: 16 MB
//! at n = 500, 64 MB at 1000, kept by the crate for reuse) and its cubic time
//! are too much for a browser page (measured by `examples/euler_matching_bench`
//! on a shared 2-core machine: 100 odd vertices 0.006 s, 500 1.6 s, 1000 10.5 s;
//! greedy 2000 0.14 s, 5000 0.8 s), and a greedy nearest-neighbour pairing is
//! used instead (reported as a warning).

use crate::geom::Point;

/// Largest number of odd vertices matched exactly.
pub const EXACT_MAX: usize = 500;

/// Costs are matched as integers in this unit (1e-6 mm): far below any
/// tolerance, so ties are the only thing rounding can change.
const PER_MM: f64 = 1e6;
/// Largest cost handed to the solver (1e9 mm), so sums stay far from overflow.
const MAX_COST: f64 = 1e15;

/// Exact minimum-weight perfect matching on the `n × n` row-major `cost`
/// matrix (mm; only `i < j` is read). Returns `mate`, or None when `n` is odd
/// or the matrix has the wrong size. A non-finite cost counts as the largest.
pub fn exact(cost: &[f64], n: usize) -> Option<Vec<usize>> {
    if n % 2 == 1 || cost.len() != n.checked_mul(n)? {
        return None;
    }
    let ints: Vec<i64> = cost
        .iter()
        .map(|&c| {
            let c = if c.is_finite() { c * PER_MM } else { MAX_COST };
            c.clamp(0.0, MAX_COST).round() as i64
        })
        .collect();
    let mate = integer_blossom::min_weight_perfect_matching(&ints, n);
    // Trust but verify: a matching that is not a perfect involution is refused.
    let valid = mate.len() == n
        && mate
            .iter()
            .enumerate()
            .all(|(i, &j)| j < n && j != i && mate[j] == i);
    valid.then_some(mate)
}

/// Greedy pairing by straight distance: the first unpaired point (by x)
/// takes its nearest unpaired neighbour. O(n²) time, O(n) memory; a
/// heuristic, at most a log factor above the optimum in the worst case.
pub fn greedy(points: &[Point]) -> Vec<usize> {
    let n = points.len();
    let mut order: Vec<usize> = (0..n).collect();
    crate::sort::sort_by(&mut order, |&a, &b| points[a].x.total_cmp(&points[b].x));
    let mut mate = vec![usize::MAX; n];
    for &i in &order {
        if mate[i] != usize::MAX {
            continue;
        }
        let best = (0..n)
            .filter(|&j| j != i && mate[j] == usize::MAX)
            .min_by(|&a, &b| {
                points[i]
                    .dist(points[a])
                    .total_cmp(&points[i].dist(points[b]))
            });
        match best {
            Some(j) => {
                mate[i] = j;
                mate[j] = i;
            }
            // An odd count leaves one vertex alone: it stays its own mate.
            None => mate[i] = i,
        }
    }
    mate
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Total cost of a matching.
    fn total(cost: &[f64], n: usize, mate: &[usize]) -> f64 {
        (0..n)
            .filter_map(|i| {
                let j = *mate.get(i)?;
                (i < j).then(|| cost.get(i * n + j).copied()).flatten()
            })
            .sum()
    }

    /// Every perfect matching of 0..n, by enumeration (n ≤ 10: 945 of them).
    fn brute(cost: &[f64], n: usize) -> f64 {
        fn rec(cost: &[f64], n: usize, used: &mut [bool]) -> f64 {
            let Some(i) = (0..n).find(|&i| !used[i]) else {
                return 0.0;
            };
            used[i] = true;
            let mut best = f64::INFINITY;
            for j in i + 1..n {
                if !used[j] {
                    used[j] = true;
                    best = best.min(cost[i * n + j] + rec(cost, n, used));
                    used[j] = false;
                }
            }
            used[i] = false;
            best
        }
        rec(cost, n, &mut vec![false; n])
    }

    #[test]
    fn exact_matches_brute_force_on_random_point_sets() {
        let mut rng = crate::test_rng::unit(0x9e37_79b9_7f4a_7c15);
        for round in 0..200 {
            let n = 2 * (1 + round % 5);
            let pts: Vec<Point> = (0..n)
                .map(|_| Point::new(100.0 * rng(), 100.0 * rng()))
                .collect();
            let cost: Vec<f64> = (0..n * n).map(|k| pts[k / n].dist(pts[k % n])).collect();
            let mate = exact(&cost, n).unwrap();
            let got = total(&cost, n, &mate);
            let want = brute(&cost, n);
            assert!((got - want).abs() < 1e-5, "n={n}: {got} vs {want}");
            // The greedy pairing is never better than the exact one.
            let g = greedy(&pts);
            assert!(total(&cost, n, &g) >= want - 1e-5);
        }
    }

    #[test]
    fn odd_count_and_bad_sizes_are_refused_not_panicking() {
        assert!(exact(&[0.0; 9], 3).is_none());
        assert!(exact(&[0.0; 3], 2).is_none());
        assert_eq!(exact(&[], 0), Some(vec![]));
        let m = exact(&[0.0, f64::NAN, f64::INFINITY, 0.0], 2).unwrap();
        assert_eq!(m, vec![1, 0]);
        assert_eq!(greedy(&[Point::new(0.0, 0.0)]), vec![0]);
    }
}
