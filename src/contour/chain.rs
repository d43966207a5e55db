//! Chaining pieces (see [`super::heal`]) into contours by end-point coincidence (paper 000,
//! "Chain"): take an entity, walk to any unused entity with an end within the
//! tolerance of the current end (reversing it if needed), until the chain
//! comes back to its first point (closed) or nothing continues it (open); then
//! walk backwards from the first point too.
//!
//! End points sit in a flat grid of cells at least two tolerances wide, laid
//! out in drawing space order (or hashed when clustered), so each look-up
//! checks the 2×2 cells a tolerance disc can touch: O(n) expected.

use std::collections::VecDeque;

use crate::geom::{Point, Segment};
use crate::text;
use crate::warning::Warning;

/// A piece to chain: a closed entity whole, or one segment of an open one.
#[derive(Clone, Debug)]
pub struct Piece {
    /// Its segments, end to end.
    pub segments: Vec<Segment>,
    /// A closed loop by itself.
    pub closed: bool,
    /// The drawing entities it came from.
    pub entities: Vec<usize>,
}

/// A chain of entities, before classification.
#[derive(Clone, Debug)]
pub struct Chain {
    /// Segments end to end (each start equals the previous end exactly).
    pub segments: Vec<Segment>,
    /// True when the last end is the first start.
    pub closed: bool,
    /// Indices of the entities used, in chain order.
    pub entities: Vec<usize>,
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
struct EndGrid {
    cell: f64,
    /// Origin of the cell indices (dense layout; 0 when hashed).
    x0: f64,
    y0: f64,
    /// Dense layout: cells per row and rows; 0 when hashed.
    cols: i64,
    rows: i64,
    /// Hashed layout: log2 of the bucket count over 4.
    bits: u32,
    start: Vec<u32>,
    ends: Vec<(Point, u32)>,
}

impl EndGrid {
    /// Grid of the ends `(point, id)` for look-ups within `t`.
    fn new(ends: &[(Point, u32)], t: f64) -> Self {
        if let Some(g) = Self::dense(ends, t) {
            return g;
        }
        Self::hashed(ends, t)
    }

    /// Smallest cell for radius `t`: a hair over 2t, so the disc's edges stay
    /// strictly inside two columns despite rounding.
    fn min_cell(t: f64) -> f64 {
        2.0 * t.max(1e-9) * (1.0 + 1e-9)
    }

    /// The dense layout, or None when the ends are too clustered for it (or
    /// not all finite).
    fn dense(ends: &[(Point, u32)], t: f64) -> Option<Self> {
        let n = ends.len();
        let (mut x0, mut y0) = (f64::INFINITY, f64::INFINITY);
        let (mut x1, mut y1) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        for &(p, _) in ends {
            x0 = x0.min(p.x);
            y0 = y0.min(p.y);
            x1 = x1.max(p.x);
            y1 = y1.max(p.y);
        }
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
        let buckets: Vec<usize> = ends
            .iter()
            .map(|&(p, _)| g.bucket(g.cell_of(p.x - x0), g.cell_of(p.y - y0)))
            .collect();
        g.fill(ends, &buckets);
        // Cost of look-ups ~ the sum over ends of their cell's count: too
        // clustered when that is far above n.
        let load: u64 = (0..g.start.len() - 1)
            .map(|b| (g.start[b + 1] - g.start[b]) as u64)
            .map(|k| k * k)
            .sum();
        (load <= 8 * n as u64 + 64).then_some(g)
    }

    fn hashed(ends: &[(Point, u32)], t: f64) -> Self {
        let bits = (ends.len().max(1) * 2)
            .next_power_of_two()
            .trailing_zeros()
            .max(4);
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
        let buckets: Vec<usize> = ends
            .iter()
            .map(|&(p, _)| g.bucket(g.cell_of(p.x), g.cell_of(p.y)))
            .collect();
        g.fill(ends, &buckets);
        g
    }

    /// Counting sort of `ends` into their `buckets`.
    fn fill(&mut self, ends: &[(Point, u32)], buckets: &[usize]) {
        for &b in buckets {
            self.start[b + 1] += 1;
        }
        for b in 1..self.start.len() {
            self.start[b] += self.start[b - 1];
        }
        let mut fill = self.start.clone();
        self.ends = vec![(Point::new(0.0, 0.0), 0); ends.len()];
        for (&end, &b) in ends.iter().zip(buckets) {
            let k = fill[b] as usize;
            fill[b] += 1;
            self.ends[k] = end;
        }
    }

    fn cell_of(&self, v: f64) -> i64 {
        (v / self.cell).floor() as i64
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
    fn near(&self, p: Point) -> impl Iterator<Item = (Point, u32)> + '_ {
        let (fx, fy) = ((p.x - self.x0) / self.cell, (p.y - self.y0) / self.cell);
        let (cx, cy) = (fx.floor(), fy.floor());
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

/// Chains pieces whose ends are within `t` mm. Closed pieces (circles,
/// closed polylines) are contours by themselves. Every join or closure
/// across more than `report_above` mm is pushed to `gaps` (the second,
/// gap-closing pass reports what it bridged).
pub fn chain(
    input: Vec<Piece>,
    t: f64,
    report_above: f64,
    gaps: &mut Vec<Point>,
    warnings: &mut Vec<Warning>,
) -> Vec<Chain> {
    let mut chains = Vec::new();
    let mut pieces: Vec<Option<Piece>> = Vec::with_capacity(input.len());
    for p in input {
        if p.closed {
            chains.push(Chain {
                segments: p.segments,
                closed: true,
                entities: p.entities,
            });
            pieces.push(None);
        } else if p.segments.is_empty() {
            pieces.push(None);
        } else {
            pieces.push(Some(p));
        }
    }

    // End ids: 2*i = start of piece i, 2*i+1 = its end.
    let mut ends = Vec::with_capacity(2 * pieces.len());
    for (i, p) in pieces.iter().enumerate() {
        if let Some(p) = p {
            ends.push((p.segments[0].a, 2 * i as u32));
            ends.push((p.segments[p.segments.len() - 1].b, 2 * i as u32 + 1));
        }
    }
    let grid = EndGrid::new(&ends, t);
    drop(ends);
    let mut used = vec![false; pieces.len()];
    let mut branches = 0usize;
    let mut branch_at = None;

    // Nearest unused end within the tolerance of `p`, and how many there are.
    let find = |p: Point, used: &Vec<bool>| -> (Option<(u32, f64)>, usize) {
        let mut best: Option<(f64, u32)> = None;
        let mut n = 0;
        for (q, id) in grid.near(p) {
            if used[(id / 2) as usize] {
                continue;
            }
            let d = p.dist(q);
            if d <= t {
                n += 1;
                if best.is_none_or(|(bd, bid)| d < bd || (d == bd && id < bid)) {
                    best = Some((d, id));
                }
            }
        }
        (best.map(|b| (b.1, b.0)), n)
    };

    for start in 0..pieces.len() {
        if used[start] {
            continue;
        }
        // A used piece is never looked at again: move it out rather than clone it.
        let Some(first) = pieces[start].take() else {
            continue;
        };
        used[start] = true;
        // Deques: a chain grows at both ends in O(1) per piece.
        let mut segs: VecDeque<Segment> = first.segments.into();
        let mut ents: VecDeque<usize> = first.entities.into();
        let mut length: f64 = segs.iter().map(Segment::length).sum();
        let mut closed = false;
        // Forward, then backward from the first point.
        for backward in [false, true] {
            loop {
                let (head, tail) = (segs[0].a, segs[segs.len() - 1].b);
                let gap = head.dist(tail);
                if gap <= t && length > 2.0 * t {
                    if gap > report_above {
                        gaps.push(tail);
                    }
                    closed = true;
                    break;
                }
                let at = if backward { head } else { tail };
                let (found, n) = find(at, &used);
                if n > 1 {
                    branches += 1;
                    branch_at = branch_at.or(Some(at));
                }
                let Some((id, d)) = found else { break };
                if d > report_above {
                    gaps.push(at);
                }
                let k = (id / 2) as usize;
                used[k] = true;
                let Some(piece) = pieces[k].take() else {
                    break;
                };
                let mut next = piece.segments;
                // Orient so the matched end touches `at`.
                if id.is_multiple_of(2) == backward {
                    next = next.iter().rev().map(Segment::reversed).collect();
                }
                length += next.iter().map(Segment::length).sum::<f64>();
                if backward {
                    if let Some(last) = next.last_mut() {
                        last.b = at;
                    }
                    for s in next.into_iter().rev() {
                        segs.push_front(s);
                    }
                    for e in piece.entities.into_iter().rev() {
                        ents.push_front(e);
                    }
                } else {
                    next[0].a = at;
                    segs.extend(next);
                    ents.extend(piece.entities);
                }
            }
            if closed {
                break;
            }
        }
        let mut segments: Vec<Segment> = segs.into();
        if closed {
            let first = segments[0].a;
            if let Some(last) = segments.last_mut() {
                last.b = first;
            }
        }
        let mut entities: Vec<usize> = ents.into();
        entities.dedup();
        chains.push(Chain {
            segments,
            closed,
            entities,
        });
    }
    if branches > 0 {
        warnings.push(Warning::maybe_at(
            "branch-points",
            text!("{branches} branch point(s) where more than two ends meet: contours there were chained by nearest end";
                  "{branches} ponto(s) de ramificação onde mais de duas pontas se encontram: os contornos ali foram encadeados pela ponta mais próxima"),
            branch_at,
        ));
    }
    chains
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line_entity(a: (f64, f64), b: (f64, f64)) -> Piece {
        Piece {
            segments: vec![Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1))],
            closed: false,
            entities: vec![0],
        }
    }

    #[test]
    fn shuffled_reversed_square_chains_into_one_closed_contour() {
        let es = vec![
            line_entity((10.0, 10.0), (10.0, 0.0)),
            line_entity((0.0, 0.0), (10.0, 0.0)),
            line_entity((0.0, 10.0), (0.0005, 0.0)),
            line_entity((0.0, 10.0), (10.0, 10.0)),
        ];
        let mut w = vec![];
        let chains = chain(es, 1e-3, 1e-3, &mut vec![], &mut w);
        assert_eq!(chains.len(), 1);
        assert!(chains[0].closed);
        assert_eq!(chains[0].segments.len(), 4);
        for pair in chains[0].segments.windows(2) {
            assert_eq!(pair[0].b, pair[1].a);
        }
        assert!(w.is_empty(), "{w:?}");
    }

    #[test]
    fn a_gap_larger_than_the_tolerance_leaves_an_open_chain() {
        let es = vec![
            line_entity((0.0, 0.0), (10.0, 0.0)),
            line_entity((10.01, 0.0), (20.0, 0.0)),
        ];
        let chains = chain(es, 1e-3, 1e-3, &mut vec![], &mut vec![]);
        assert_eq!(chains.len(), 2);
        assert!(chains.iter().all(|c| !c.closed));
    }

    #[test]
    fn chain_started_mid_way_extends_backwards() {
        let es = vec![
            line_entity((10.0, 0.0), (20.0, 0.0)),
            line_entity((0.0, 0.0), (10.0, 0.0)),
            line_entity((20.0, 0.0), (30.0, 0.0)),
        ];
        let chains = chain(es, 1e-3, 1e-3, &mut vec![], &mut vec![]);
        assert_eq!(chains.len(), 1);
        assert_eq!(chains[0].segments[0].a, Point::new(0.0, 0.0));
        assert_eq!(chains[0].segments[2].b, Point::new(30.0, 0.0));
    }

    #[test]
    fn the_grid_finds_every_end_within_the_tolerance_as_brute_force_does() {
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut rnd = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        for t in [1e-3, 0.37, 5.0] {
            let ends: Vec<(Point, u32)> = (0..2000)
                .map(|i| (Point::new(rnd() * 40.0 * t, rnd() * 40.0 * t), i))
                .collect();
            let dense = EndGrid::dense(&ends, t).expect("evenly spread ends: dense");
            assert!(dense.cols > 0);
            let hashed = EndGrid::hashed(&ends, t);
            for grid in [&dense, &hashed] {
                for _ in 0..2000 {
                    let p = Point::new(rnd() * 40.0 * t, rnd() * 40.0 * t);
                    let mut want: Vec<u32> = ends
                        .iter()
                        .filter(|(q, _)| p.dist(*q) <= t)
                        .map(|e| e.1)
                        .collect();
                    let mut got: Vec<u32> = grid
                        .near(p)
                        .filter(|(q, _)| p.dist(*q) <= t)
                        .map(|e| e.1)
                        .collect();
                    want.sort_unstable();
                    got.sort_unstable();
                    assert_eq!(got, want, "t {t} at {p:?}");
                }
                // Exactly t away along an axis, on both sides.
                for &(q, id) in &ends[..200] {
                    for (dx, dy) in [(t, 0.0), (-t, 0.0), (0.0, t), (0.0, -t)] {
                        let p = Point::new(q.x + dx, q.y + dy);
                        if p.dist(q) <= t {
                            assert!(grid.near(p).any(|e| e.1 == id), "t {t} at {p:?}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn clustered_ends_fall_back_to_the_hash_and_are_still_all_found() {
        // 2000 ends within 1 mm at the origin and one 1 km away: dense cells
        // sized to the box would put nearly all ends in one cell.
        let t = 1e-3;
        let mut ends: Vec<(Point, u32)> = (0..2000u32)
            .map(|i| {
                (
                    Point::new((i % 50) as f64 * 0.02, (i / 50) as f64 * 0.02),
                    i,
                )
            })
            .collect();
        ends.push((Point::new(1e6, 1e6), 2000));
        assert!(EndGrid::dense(&ends, t).is_none());
        let grid = EndGrid::new(&ends, t);
        assert_eq!(grid.cols, 0);
        for &(q, id) in &ends {
            let p = Point::new(q.x + 0.7 * t, q.y - 0.7 * t);
            let got: Vec<u32> = grid
                .near(p)
                .filter(|(e, _)| p.dist(*e) <= t)
                .map(|e| e.1)
                .collect();
            assert_eq!(got, vec![id]);
        }
    }
}
