//! The placer's candidates best first, sorted only as far as they are
//! tried.
//!
//! A candidate's rank is (the length the sheet would use, its right edge,
//! its bottom, then variant and position to make it total). The length
//! used is the larger of its right edge and the sheet's: so the rank
//! follows the right edge (a candidate with the lesser right edge never
//! ranks after one with a greater), and candidates are bucketed by right
//! edge in one linear pass, the buckets gathered and sorted by the full
//! rank a slice at a time as they are reached. Sorting all 20 000
//! candidates of a copy was a sixth of
//! a nest's time (perf, issue 44's part-in-hole job), though the first
//! free one is found before the last; the sequence is the same as the
//! full sort's (the rank is total: equal means the same candidate).

use std::cmp::Ordering;

use crate::geom::Point;

/// A candidate: (length used, right edge, bottom), variant, translation.
pub(super) type Cand = ((f64, f64, f64), usize, Point);

/// The rank: less is better.
pub(super) fn rank(a: &Cand, b: &Cand) -> Ordering {
    let (ka, kb) = (a.0, b.0);
    ka.0.total_cmp(&kb.0)
        .then(ka.1.total_cmp(&kb.1))
        .then(ka.2.total_cmp(&kb.2))
        .then(a.1.cmp(&b.1))
        .then(a.2.x.total_cmp(&b.2.x))
        .then(a.2.y.total_cmp(&b.2.y))
}

/// Candidates per bucket aimed at.
const PER_BUCKET: usize = 8;
/// Candidates in the first slice of buckets taken; each next twice more.
const FIRST_SLICE: usize = 256;

/// The candidates in [`rank`] order, as an iterator.
pub(super) struct BestFirst {
    cands: Vec<Cand>,
    /// Each candidate's bucket.
    bucket: Vec<u32>,
    /// How many candidates each bucket holds.
    count: Vec<usize>,
    /// The slice of buckets being walked, sorted; the next candidate in
    /// it; the first bucket not taken yet; the size of the next slice.
    slice: Vec<Cand>,
    at: usize,
    next: usize,
    want: usize,
}

impl BestFirst {
    /// `cands`, bucketed by right edge (`room`: a spare list whose memory
    /// is reused, [`BestFirst::into_room`]). The buckets are taken a slice
    /// at a time as they are reached (one pass over the candidates a
    /// slice, the slice sorted): a copy placed in its first hundred
    /// candidates moves or sorts none of the others.
    pub fn new(cands: Vec<Cand>, room: Vec<Cand>) -> BestFirst {
        let n = cands.len();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut plain = false;
        for c in &cands {
            let x = c.0 .1;
            // A right edge of ±0 or not finite: one bucket, the full sort
            // (the rank's total order tells −0 from +0, which the larger
            // of two numbers may not; no real copy has one).
            plain |= !x.is_finite() || x == 0.0;
            lo = lo.min(x);
            hi = hi.max(x);
        }
        // Not plain: every x finite, so no NaN here (an empty list: lo = inf > hi).
        let buckets = if plain || hi <= lo {
            1
        } else {
            (n / PER_BUCKET).clamp(1, u32::MAX as usize)
        };
        let scale = buckets as f64 / (hi - lo);
        // Monotonic in the right edge (each step is), so a bucket holds
        // no candidate ranked before one of an earlier bucket.
        let bucket: Vec<u32> = cands
            .iter()
            .map(|c| {
                if buckets == 1 {
                    0
                } else {
                    (((c.0 .1 - lo) * scale) as usize).min(buckets - 1) as u32
                }
            })
            .collect();
        let mut count = vec![0usize; buckets];
        for &k in &bucket {
            count[k as usize] += 1;
        }
        BestFirst {
            cands,
            bucket,
            count,
            slice: room,
            at: 0,
            next: 0,
            want: FIRST_SLICE,
        }
    }

    /// The two lists' memory, emptied, for the next copy's candidates.
    pub fn into_room(mut self) -> (Vec<Cand>, Vec<Cand>) {
        self.cands.clear();
        self.slice.clear();
        (self.cands, self.slice)
    }
}

impl Iterator for BestFirst {
    type Item = Cand;
    fn next(&mut self) -> Option<Cand> {
        while self.at == self.slice.len() {
            let from = self.next;
            if from == self.count.len() {
                return None;
            }
            // Buckets from `from` until they hold `want` candidates.
            let mut held = 0;
            while self.next < self.count.len() && held < self.want {
                held += self.count[self.next];
                self.next += 1;
            }
            let (from, to) = (from as u32, self.next as u32);
            self.slice.clear();
            if from == 0 && to as usize == self.count.len() {
                self.slice.extend_from_slice(&self.cands);
            } else {
                self.slice.extend(
                    self.cands
                        .iter()
                        .zip(&self.bucket)
                        .filter(|(_, &k)| k >= from && k < to)
                        .map(|(c, _)| *c),
                );
            }
            self.slice.sort_unstable_by(rank);
            self.at = 0;
            self.want = self.want.saturating_mul(2);
        }
        let c = self.slice[self.at];
        self.at += 1;
        Some(c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gives_the_full_sort_s_sequence() {
        let mut s = 3u64;
        let mut r = move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for n in [0, 1, 2, 7, 100, 5000] {
            for right_of_sheet in [0.5, 40.0, 120.0] {
                // Right edges on a coarse grid (ties) and anywhere,
                // duplicates, variants and bottoms on a grid.
                let cands: Vec<Cand> = (0..n)
                    .map(|i| {
                        let right = if i % 3 == 0 {
                            (r() * 20.0).floor() * 5.0 + 1.0
                        } else {
                            1.0 + r() * 100.0
                        };
                        let y = (r() * 10.0).floor();
                        let t = Point::new(right - 7.0, y - 2.0);
                        (
                            (right.max(right_of_sheet), right, y),
                            (r() * 4.0) as usize,
                            t,
                        )
                    })
                    .flat_map(|c| [c; 2].into_iter().take(1 + (c.1 == 0) as usize))
                    .collect();
                let mut full = cands.clone();
                full.sort_unstable_by(rank);
                let lazy: Vec<Cand> = BestFirst::new(cands, Vec::new()).collect();
                assert_eq!(lazy, full, "n {n}");
            }
        }
        // A right edge of 0: the full sort.
        let c = vec![((1.0, 0.0, 0.0), 0, Point::default()); 3];
        assert_eq!(BestFirst::new(c.clone(), Vec::new()).collect::<Vec<_>>(), c);
    }
}
