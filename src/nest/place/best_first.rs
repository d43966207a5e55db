//! The placer's candidates best first, sorted only as far as they are
//! tried.
//!
//! A candidate's rank is (the length the sheet would use, its right edge,
//! its bottom, then variant and position to make it total). The length
//! used is the larger of its right edge and the sheet's: so the rank
//! follows the right edge (a candidate with the lesser right edge never
//! ranks after one with a greater), and candidates are bucketed by right
//! edge in one linear pass, the buckets gathered a slice at a time as
//! they are reached and each bucket sorted by the full rank when it is
//! reached. Sorting all 20 000 candidates of a copy was a sixth of a
//! nest's time (perf, issue 44's part-in-hole job), though the first free
//! one is found before the last; the sequence is the same as the full
//! sort's (the rank is total: equal means the same candidate).

use std::cmp::Ordering;

use crate::geom::{fmax, fmin, Point};

/// A candidate: its rank's three numbers (length used, right edge,
/// bottom) as [`order_bits`], its variant, its translation. The numbers
/// are kept as integers that compare as `f64::total_cmp` does: ranking
/// the candidates (hundreds of thousands a copy on a full sheet) was a
/// third of a decode of the flanges job in `total_cmp` calls (perf).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Cand {
    key: [u64; 3],
    pub(super) variant: usize,
    pub(super) t: Point,
}

impl Cand {
    /// The candidate with these rank numbers.
    pub(super) fn new(used: f64, right: f64, bottom: f64, variant: usize, t: Point) -> Cand {
        Cand {
            key: [order_bits(used), order_bits(right), order_bits(bottom)],
            variant,
            t,
        }
    }

    /// Its right edge.
    fn right(&self) -> f64 {
        from_order_bits(self.key[1])
    }
}

/// `x`'s bits mapped so that the integers compare as `f64::total_cmp`
/// compares the numbers: negative numbers (sign bit set) have every bit
/// flipped, others only the sign bit.
fn order_bits(x: f64) -> u64 {
    let b = x.to_bits();
    // (The sign spread over every bit: all ones when negative.)
    b ^ (((b as i64 >> 63) as u64) | 1 << 63)
}

/// The inverse of [`order_bits`].
fn from_order_bits(u: u64) -> f64 {
    f64::from_bits(u ^ (!((u as i64 >> 63) as u64) | 1 << 63))
}

/// The rank: less is better. Total: equal means the same candidate.
pub(super) fn rank(a: &Cand, b: &Cand) -> Ordering {
    a.key
        .cmp(&b.key)
        .then(a.variant.cmp(&b.variant))
        .then(a.t.x.total_cmp(&b.t.x))
        .then(a.t.y.total_cmp(&b.t.y))
}

/// Candidates per bucket aimed at.
const PER_BUCKET: usize = 8;
/// Candidates in the first slice of buckets taken; each next twice more.
const FIRST_SLICE: usize = 256;

/// The candidates of a copy as made, with the least and greatest right
/// edge among them (so [`BestFirst::new`] need not read them for it), and
/// the lists [`BestFirst`] works in, kept from copy to copy (a new list
/// each copy was page faults).
#[derive(Clone, Debug)]
pub(super) struct Room {
    cands: Vec<Cand>,
    /// Their right edges, apart: the pass that buckets them reads these
    /// 8 bytes a candidate, not 48.
    rights: Vec<f64>,
    lo: f64,
    hi: f64,
    /// A right edge of ±0 or not finite among them.
    plain: bool,
    slice: Vec<Cand>,
    bucket: Vec<u32>,
    count: Vec<usize>,
    starts: Vec<usize>,
    fill: Vec<usize>,
}

impl Default for Room {
    fn default() -> Room {
        Room {
            cands: Vec::new(),
            rights: Vec::new(),
            lo: f64::INFINITY,
            hi: f64::NEG_INFINITY,
            plain: false,
            slice: Vec::new(),
            bucket: Vec::new(),
            count: Vec::new(),
            starts: Vec::new(),
            fill: Vec::new(),
        }
    }
}

impl Room {
    /// One more candidate.
    pub(super) fn push(&mut self, c: Cand) {
        let x = c.right();
        // A right edge of ±0 or not finite: one bucket, the full sort
        // (the rank's total order tells −0 from +0, which the larger
        // of two numbers may not; no real copy has one).
        self.plain |= !x.is_finite() || x == 0.0;
        self.lo = fmin(self.lo, x);
        self.hi = fmax(self.hi, x);
        self.cands.push(c);
        self.rights.push(x);
    }

    /// How many candidates.
    pub(super) fn len(&self) -> usize {
        self.cands.len()
    }
}

/// The first `limit` candidates in [`rank`] order, as an iterator.
pub(super) struct BestFirst {
    cands: Vec<Cand>,
    /// (Memory only: [`Room`]'s right edges, read.)
    rights: Vec<f64>,
    /// Each candidate's bucket.
    bucket: Vec<u32>,
    /// How many candidates each bucket holds.
    count: Vec<usize>,
    /// The slice of buckets being walked, bucket after bucket; where each
    /// of its buckets starts in it (and its end), and the memory to fill
    /// it with.
    slice: Vec<Cand>,
    starts: Vec<usize>,
    fill: Vec<usize>,
    /// The slice is sorted up to `sorted`, its buckets before `sorted_in`;
    /// the next candidate is at `at`; the first bucket not taken yet; the
    /// size of the next slice; how many candidates may still be given.
    sorted: usize,
    sorted_in: usize,
    at: usize,
    next: usize,
    want: usize,
    left: usize,
}

impl BestFirst {
    /// `room`'s candidates, bucketed by right edge in one linear pass. The
    /// buckets are taken a slice at a time as they are reached (one pass
    /// over the buckets' numbers a slice, the slice laid out bucket after
    /// bucket), and each bucket (a few candidates) sorted when it is
    /// reached: a copy placed in its first hundred candidates moves or
    /// sorts none of the others. Past `limit` candidates given, none: the
    /// sequence of selecting the best `limit` and sorting them, without
    /// the selection. Selecting and sorting were a third of a decode of
    /// the flanges job (perf).
    pub fn new(room: Room, limit: usize) -> BestFirst {
        let Room {
            cands,
            mut rights,
            lo,
            hi,
            plain,
            slice,
            mut bucket,
            mut count,
            starts,
            fill,
        } = room;
        let n = cands.len();
        // Not plain: every x finite, so no NaN here (an empty list: lo = inf > hi).
        let buckets = if plain || hi <= lo {
            1
        } else {
            (n / PER_BUCKET).clamp(1, u32::MAX as usize)
        };
        let scale = buckets as f64 / (hi - lo);
        // Monotonic in the right edge (each step is), so a bucket holds
        // no candidate ranked before one of an earlier bucket: a lesser
        // right edge never ranks after a greater (the length used is the
        // larger of the right edge and the sheet's).
        bucket.clear();
        count.clear();
        count.resize(buckets, 0);
        if buckets == 1 {
            // (One slice, all of them: the buckets' numbers unread.)
            count[0] = n;
        } else {
            bucket.extend(rights.iter().map(|&x| {
                let k = (((x - lo) * scale) as usize).min(buckets - 1);
                count[k] += 1;
                k as u32
            }));
        }
        rights.clear();
        BestFirst {
            cands,
            rights,
            bucket,
            count,
            slice,
            starts,
            fill,
            sorted: 0,
            sorted_in: 0,
            at: 0,
            next: 0,
            want: FIRST_SLICE,
            left: limit,
        }
    }

    /// The lists' memory, emptied, for the next copy's candidates.
    pub fn into_room(mut self) -> Room {
        self.cands.clear();
        self.slice.clear();
        self.bucket.clear();
        self.count.clear();
        self.starts.clear();
        self.fill.clear();
        Room {
            cands: self.cands,
            rights: self.rights,
            slice: self.slice,
            bucket: self.bucket,
            count: self.count,
            starts: self.starts,
            fill: self.fill,
            ..Room::default()
        }
    }

    /// The next slice of buckets laid out in `slice`; false when none is left.
    fn take_slice(&mut self) -> bool {
        let from = self.next;
        if from == self.count.len() {
            return false;
        }
        // Buckets from `from` until they hold `want` candidates.
        let mut held = 0;
        self.starts.clear();
        self.starts.push(0);
        while self.next < self.count.len() && held < self.want {
            held += self.count[self.next];
            self.next += 1;
            self.starts.push(held);
        }
        let (from, to) = (from as u32, self.next as u32);
        self.slice.clear();
        if self.count.len() == 1 {
            self.slice.extend_from_slice(&self.cands);
        } else {
            // Each candidate at the next free place of its bucket (the
            // slice is small: its writes stay in the cache).
            self.slice.resize(held, self.cands[0]);
            self.fill.clear();
            self.fill.extend_from_slice(&self.starts);
            for (c, &k) in self.cands.iter().zip(&self.bucket) {
                if k >= from && k < to {
                    let f = &mut self.fill[(k - from) as usize];
                    self.slice[*f] = *c;
                    *f += 1;
                }
            }
        }
        self.at = 0;
        self.sorted = 0;
        self.sorted_in = 0;
        self.want = self.want.saturating_mul(2);
        true
    }
}

impl Iterator for BestFirst {
    type Item = Cand;
    fn next(&mut self) -> Option<Cand> {
        if self.left == 0 {
            return None;
        }
        while self.at == self.sorted {
            if self.sorted_in + 1 < self.starts.len() {
                // The next bucket of the slice, sorted.
                let (i, j) = (self.starts[self.sorted_in], self.starts[self.sorted_in + 1]);
                self.slice[i..j].sort_unstable_by(rank);
                self.sorted = j;
                self.sorted_in += 1;
            } else if !self.take_slice() {
                return None;
            }
        }
        let c = self.slice[self.at];
        self.at += 1;
        self.left -= 1;
        Some(c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rank as it was written on the numbers, `total_cmp` field by
    /// field: the integers must order the candidates the same.
    fn rank_of_numbers(a: &Cand, b: &Cand) -> Ordering {
        let f = |c: &Cand| c.key.map(from_order_bits);
        let (ka, kb) = (f(a), f(b));
        ka[0]
            .total_cmp(&kb[0])
            .then(ka[1].total_cmp(&kb[1]))
            .then(ka[2].total_cmp(&kb[2]))
            .then(a.variant.cmp(&b.variant))
            .then(a.t.x.total_cmp(&b.t.x))
            .then(a.t.y.total_cmp(&b.t.y))
    }

    fn room(cands: Vec<Cand>) -> Room {
        let mut room = Room::default();
        cands.into_iter().for_each(|c| room.push(c));
        room
    }

    #[test]
    fn order_bits_compare_as_total_cmp() {
        let xs = [
            f64::NEG_INFINITY,
            -1e300,
            -2.5,
            -f64::MIN_POSITIVE,
            -0.0,
            0.0,
            f64::MIN_POSITIVE,
            1e-300,
            0.1,
            2.5,
            1e300,
            f64::INFINITY,
            f64::NAN,
            -f64::NAN,
        ];
        for a in xs {
            assert_eq!(from_order_bits(order_bits(a)).to_bits(), a.to_bits());
            for b in xs {
                assert_eq!(
                    order_bits(a).cmp(&order_bits(b)),
                    a.total_cmp(&b),
                    "{a} {b}"
                );
            }
        }
    }

    #[test]
    fn gives_the_full_sort_s_sequence_up_to_the_limit() {
        let mut r = crate::test_rng::unit(3);
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
                        let v = (r() * 4.0) as usize;
                        Cand::new(right.max(right_of_sheet), right, y, v, t)
                    })
                    .flat_map(|c| [c; 2].into_iter().take(1 + (c.variant == 0) as usize))
                    .collect();
                let mut full = cands.clone();
                full.sort_unstable_by(rank_of_numbers);
                for limit in [0, 1, 300, n / 2, n, 2 * n + 1] {
                    // As the placer did: the best `limit` selected, then sorted.
                    let mut kept = cands.clone();
                    if kept.len() > limit {
                        kept.select_nth_unstable_by(limit, rank_of_numbers);
                        kept.truncate(limit);
                    }
                    kept.sort_unstable_by(rank_of_numbers);
                    assert_eq!(kept, full[..limit.min(full.len())]);
                    let lazy: Vec<Cand> = BestFirst::new(room(cands.clone()), limit).collect();
                    assert_eq!(lazy, kept, "n {n} limit {limit}");
                }
            }
        }
        // A right edge of 0: the full sort.
        let c = vec![Cand::new(1.0, 0.0, 0.0, 0, Point::default()); 3];
        let all: Vec<Cand> = BestFirst::new(room(c.clone()), 10).collect();
        assert_eq!(all, c);
    }
}
