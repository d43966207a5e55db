//! The chainer's end-point grid (split from chain.rs): end points in flat
//! cells a tolerance disc's look-up reads at most four of.

use crate::geom::Point;
use crate::par::{map_ranges, Threads};

/// Fewest ends a thread takes the box or the buckets of (~10 ns an end).
const CHUNK: usize = 32_768;

/// A box as `[x0, y0, x1, y1]` holding nothing.
const NO_BOX: [f64; 4] = [
    f64::INFINITY,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NEG_INFINITY,
];

/// Box `b` grown to hold box `o` (a point is the box `[x, y, x, y]`),
/// each side on its own: a NaN side of `o` changes nothing.
fn widen(b: [f64; 4], o: [f64; 4]) -> [f64; 4] {
    [
        b[0].min(o[0]),
        b[1].min(o[1]),
        b[2].max(o[2]),
        b[3].max(o[3]),
    ]
}

/// End points in a grid of cells at least 2t wide, stored flat (compressed
/// rows: bucket `b` is `start[b]..start[b + 1]` of `ends`). A point's disc of
/// radius t touches at most 2×2 cells, so a look-up reads up to four buckets;
/// the caller's real distance check rejects what lies farther.
///
/// Two layouts, one look-up:
/// - dense (the usual case): cells sized to the point count over the ends'
///   bounding box, buckets in row-major cell order, so the ends of pieces
///   drawn near each other sit near each other in memory. Chaining walks the
///   pieces in drawing order, and CAD drawings (and the benchmark) are
///   spatially coherent: a look-up mostly reads cache lines a neighbour just
///   read. The earlier hash of 2t cells scattered neighbours across a 60 MB
///   table at 1M segments (issue 17 item 3: 11.3 µs per segment at 1M vs 2.75
///   at 10k, ~70 % of it waiting on memory).
/// - hashed (Teschner et al. 2003, "Optimized Spatial Hashing for Collision
///   Detection of Deformable Objects"): 2t cells hashed to ~2n buckets, used
///   when the ends are so clustered that dense cells would hold many ends
///   each (a few parts far apart on a huge sheet), which would make look-ups
///   quadratic; hashing keeps them O(1) expected whatever the layout.
#[cfg_attr(test, derive(Debug, PartialEq))]
pub(super) struct EndGrid {
    cell: f64,
    /// Origin of the cell indices (dense layout; 0 when hashed).
    x0: f64,
    y0: f64,
    /// Dense layout: cells per row and rows; 0 when hashed.
    pub(super) cols: i64,
    rows: i64,
    /// Hashed layout: log2 of the bucket count over 4.
    bits: u32,
    start: Vec<u32>,
    ends: Vec<(Point, u32)>,
}

impl EndGrid {
    /// Grid of the ends `(point, id)` for look-ups within `t`.
    #[cfg(test)]
    pub(super) fn new(ends: &[(Point, u32)], t: f64) -> Self {
        Self::of(ends.len(), |k| ends[k], t, Threads::ONE)
    }

    /// Grid of the `n` ends `end(0..n)`, each `(point, id)`: read where
    /// they lie (the chainer's pieces), not copied into a list first: at a
    /// million pieces the list, the ends' buckets and a copy of the bucket
    /// starts were 80 MB of fresh pages per chaining (issue 17).
    /// The ends' box and buckets are found on `threads` (the same grid
    /// with any number).
    pub(super) fn of(
        n: usize,
        end: impl Fn(usize) -> (Point, u32) + Copy + Sync,
        t: f64,
        threads: Threads,
    ) -> Self {
        if let Some(g) = Self::dense_of(n, end, t, threads) {
            return g;
        }
        Self::hashed_of(n, end, t, threads)
    }

    /// Smallest cell for radius `t`: a hair over 2t, so the disc's edges stay
    /// strictly inside two columns despite rounding.
    fn min_cell(t: f64) -> f64 {
        2.0 * t.max(1e-9) * (1.0 + 1e-9)
    }

    /// The dense layout, or None when the ends are too clustered for it (or
    /// not all finite).
    #[cfg(test)]
    pub(super) fn dense(ends: &[(Point, u32)], t: f64, threads: Threads) -> Option<Self> {
        Self::dense_of(ends.len(), |k| ends[k], t, threads)
    }

    fn dense_of(
        n: usize,
        end: impl Fn(usize) -> (Point, u32) + Copy + Sync,
        t: f64,
        threads: Threads,
    ) -> Option<Self> {
        // The box on ranges of ends, then of the ranges' boxes: the same
        // box (a least and a greatest are the same whatever the grouping;
        // `min` and `max` pass over a NaN either way).
        let parts = map_ranges(n, threads, CHUNK, |r| {
            r.fold(NO_BOX, |b, k| {
                let p = end(k).0;
                widen(b, [p.x, p.y, p.x, p.y])
            })
        });
        let [x0, y0, x1, y1] = parts.into_iter().fold(NO_BOX, widen);
        if n == 0 || !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite()) {
            return None;
        }
        let (w, h) = (x1 - x0, y1 - y0);
        if !(w.is_finite() && h.is_finite()) {
            return None;
        }
        // About one end per cell when spread evenly; at most ~4n cells.
        let mut cell = Self::min_cell(t).max((w * h / n as f64).sqrt());
        let cap = 4.0 * n as f64 + 16.0;
        while ((w / cell).floor() + 1.0) * ((h / cell).floor() + 1.0) > cap {
            cell *= 2.0;
        }
        let cols = (w / cell).floor() as i64 + 1;
        let rows = (h / cell).floor() as i64 + 1;
        let mut g = EndGrid {
            cell,
            x0,
            y0,
            cols,
            rows,
            bits: 0,
            // One more bucket than cells: the empty one outside the box.
            start: vec![0; (cols * rows) as usize + 2],
            ends: Vec::new(),
        };
        g.fill(
            n,
            end,
            |g, p| g.bucket(g.cell_of(p.x - g.x0), g.cell_of(p.y - g.y0)),
            threads,
        );
        // Cost of look-ups ~ the sum over ends of their cell's count: too
        // clustered when that is far above n.
        let load: u64 = (0..g.start.len() - 1)
            .map(|b| (g.start[b + 1] - g.start[b]) as u64)
            .map(|k| k * k)
            .sum();
        (load <= 8 * n as u64 + 64).then_some(g)
    }

    #[cfg(test)]
    pub(super) fn hashed(ends: &[(Point, u32)], t: f64, threads: Threads) -> Self {
        Self::hashed_of(ends.len(), |k| ends[k], t, threads)
    }

    fn hashed_of(
        n: usize,
        end: impl Fn(usize) -> (Point, u32) + Copy + Sync,
        t: f64,
        threads: Threads,
    ) -> Self {
        let bits = (n.max(1) * 2).next_power_of_two().trailing_zeros().max(4);
        let mut g = EndGrid {
            cell: Self::min_cell(t),
            x0: 0.0,
            y0: 0.0,
            cols: 0,
            rows: 0,
            bits,
            start: vec![0; (1usize << bits) + 1],
            ends: Vec::new(),
        };
        g.fill(
            n,
            end,
            |g, p| g.bucket(g.cell_of(p.x), g.cell_of(p.y)),
            threads,
        );
        g
    }

    /// Counting sort of the ends into their buckets (`bucket_of` a point's),
    /// stable: counts, running totals (each bucket's end), then the ends
    /// placed from the last, each bucket's end stepping back to its start
    /// (no copy of the starts is needed). Each end's bucket is found once,
    /// on ranges of ends on `threads`, and kept for both passes: the
    /// passes themselves are a count and a placement. The 25 MB nest's
    /// 549k ends, two threads: the contours stage 97.3 -> 91.4 ms (8
    /// alternating pairs, median pair ratio 0.94; the grid was 19-20 ms
    /// on the calling thread alone, the bucket found twice); one thread
    /// the same (105.3 -> 104.8 ms).
    fn fill(
        &mut self,
        n: usize,
        end: impl Fn(usize) -> (Point, u32) + Sync,
        bucket_of: impl Fn(&Self, Point) -> usize + Sync,
        threads: Threads,
    ) {
        let this = &*self;
        let buckets = map_ranges(n, threads, CHUNK, |r| {
            r.map(|k| bucket_of(this, end(k).0) as u32)
                .collect::<Vec<u32>>()
        });
        for &b in buckets.iter().flatten() {
            self.start[b as usize] += 1;
        }
        for b in 1..self.start.len() {
            self.start[b] += self.start[b - 1];
        }
        let mut ends = vec![(Point::new(0.0, 0.0), 0); n];
        let mut k = n;
        for part in buckets.iter().rev() {
            for &b in part.iter().rev() {
                k -= 1;
                let b = b as usize;
                self.start[b] -= 1;
                ends[self.start[b] as usize] = end(k);
            }
        }
        self.ends = ends;
    }

    fn cell_of(&self, v: f64) -> i64 {
        crate::geom::floor(v / self.cell) as i64
    }

    fn bucket(&self, cx: i64, cy: i64) -> usize {
        if self.cols > 0 {
            if cx < 0 || cy < 0 || cx >= self.cols || cy >= self.rows {
                // The empty bucket: nothing lies outside the box.
                return (self.cols * self.rows) as usize;
            }
            return (cy * self.cols + cx) as usize;
        }
        // 2×2 blocks of cells hash to four consecutive buckets: the cells of
        // one look-up often share a block, hence a cache line.
        let h = ((cx >> 1) as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
            ^ ((cy >> 1) as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
        let h = (h ^ (h >> 29)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        let block = (h >> (66 - self.bits)) as usize;
        block << 2 | ((cx & 1) as usize) << 1 | (cy & 1) as usize
    }

    /// Ends stored in the (up to) four cells a disc of radius t around `p`
    /// touches: the cell of `p` and its neighbours on the sides `p` is nearer to.
    pub(super) fn near(&self, p: Point) -> impl Iterator<Item = (Point, u32)> + '_ {
        let (fx, fy) = ((p.x - self.x0) / self.cell, (p.y - self.y0) / self.cell);
        let (cx, cy) = (crate::geom::floor(fx), crate::geom::floor(fy));
        let side = |f: f64, c: f64| if f - c < 0.5 { -1 } else { 1 };
        let (sx, sy) = (side(fx, cx), side(fy, cy));
        let (cx, cy) = (cx as i64, cy as i64);
        let mut buckets = [
            self.bucket(cx, cy),
            self.bucket(cx.saturating_add(sx), cy),
            self.bucket(cx, cy.saturating_add(sy)),
            self.bucket(cx.saturating_add(sx), cy.saturating_add(sy)),
        ];
        // Two cells may share a bucket: read each bucket once, in order
        // (five compare-exchanges sort four; no copy of the standard sort).
        for (i, j) in [(0, 1), (2, 3), (0, 2), (1, 3), (1, 2)] {
            if buckets[i] > buckets[j] {
                buckets.swap(i, j);
            }
        }
        (0..4)
            .filter(move |&i| i == 0 || buckets[i] != buckets[i - 1])
            .flat_map(move |i| {
                let b = buckets[i];
                self.start[b] as usize..self.start[b + 1] as usize
            })
            .map(move |k| self.ends[k])
    }
}
