//! Chaining pieces (see [`super::heal`]) into contours by end-point coincidence (paper 000,
//! "Chain"): take an entity, walk to any unused entity with an end within the
//! tolerance of the current end (reversing it if needed), until the chain
//! comes back to its first point (closed) or nothing continues it (open); then
//! walk backwards from the first point too.
//!
//! End points sit in a flat spatial hash with cells of two tolerances, so each
//! look-up checks the 2×2 cells a tolerance disc can touch: O(n) expected.

use std::collections::VecDeque;

use super::heal::Piece;
use crate::geom::{Point, Segment};
use crate::text;
use crate::warning::Warning;

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

/// End points in a spatial hash (Teschner et al. 2003, "Optimized Spatial
/// Hashing for Collision Detection of Deformable Objects"): cells of side
/// 2t, each hashed to one of a fixed number of buckets, the buckets stored
/// flat (compressed rows: `start[b]..start[b + 1]` of `ends`). A point's
/// disc of radius t touches at most 2×2 such cells, so a look-up reads four
/// buckets. Hash collisions only add candidates, which the caller's real
/// distance check rejects. No allocation per cell and the points sit beside
/// their ids: a look-up touches a few cache lines, where a map of cells to
/// vectors missed the cache nine times (1M isolated segments took ~12 s).
struct EndGrid {
    cell: f64,
    bits: u32,
    start: Vec<u32>,
    ends: Vec<(Point, u32)>,
}

impl EndGrid {
    /// Grid of the ends `(point, id)` for look-ups within `t`.
    fn new(ends: &[(Point, u32)], t: f64) -> Self {
        // A hair over 2t: the disc's edges stay strictly inside two columns despite rounding.
        let cell = 2.0 * t.max(1e-9) * (1.0 + 1e-9);
        let bits = (ends.len().max(1) * 2)
            .next_power_of_two()
            .trailing_zeros()
            .max(4);
        let mut g = EndGrid {
            cell,
            bits,
            start: vec![0; (1usize << bits) + 1],
            ends: vec![(Point::new(0.0, 0.0), 0); ends.len()],
        };
        let buckets: Vec<usize> = ends
            .iter()
            .map(|&(p, _)| g.bucket(g.cell_of(p.x), g.cell_of(p.y)))
            .collect();
        for &b in &buckets {
            g.start[b + 1] += 1;
        }
        for b in 1..g.start.len() {
            g.start[b] += g.start[b - 1];
        }
        let mut fill = g.start.clone();
        for (&end, &b) in ends.iter().zip(&buckets) {
            let k = fill[b] as usize;
            fill[b] += 1;
            g.ends[k] = end;
        }
        g
    }
    fn cell_of(&self, v: f64) -> i64 {
        (v / self.cell).floor() as i64
    }
    /// 2×2 blocks of cells hash to four consecutive buckets: the cells of
    /// one look-up often share a block, hence a cache line.
    fn bucket(&self, cx: i64, cy: i64) -> usize {
        let h = ((cx >> 1) as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
            ^ ((cy >> 1) as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
        let h = (h ^ (h >> 29)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        let block = (h >> (66 - self.bits)) as usize;
        block << 2 | ((cx & 1) as usize) << 1 | (cy & 1) as usize
    }
    /// Ends stored in the (up to) four cells a disc of radius t around `p`
    /// touches: the cell of `p` and its neighbours on the sides `p` is nearer to.
    fn near(&self, p: Point) -> impl Iterator<Item = (Point, u32)> + '_ {
        let (fx, fy) = (p.x / self.cell, p.y / self.cell);
        let (cx, cy) = (fx.floor(), fy.floor());
        let side = |f: f64, c: f64| if f - c < 0.5 { -1 } else { 1 };
        let (sx, sy) = (side(fx, cx), side(fy, cy));
        let (cx, cy) = (cx as i64, cy as i64);
        let mut buckets = [
            self.bucket(cx, cy),
            self.bucket(cx + sx, cy),
            self.bucket(cx, cy + sy),
            self.bucket(cx + sx, cy + sy),
        ];
        // Two cells may share a bucket: read each bucket once.
        buckets.sort_unstable();
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
            let grid = EndGrid::new(&ends, t);
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
