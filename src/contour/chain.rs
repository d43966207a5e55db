//! Chaining pieces (see [`super::heal`]) into contours by end-point coincidence (paper 000,
//! "Chain"): take an entity, walk to any unused entity with an end within the
//! tolerance of the current end (reversing it if needed), until the chain
//! comes back to its first point (closed) or nothing continues it (open); then
//! walk backwards from the first point too.
//!
//! End points sit in a hash grid with cells of one tolerance, so each look-up
//! checks the 3×3 cells around a point: O(n) expected, not all pairs.

use std::collections::{HashMap, VecDeque};

use super::heal::Piece;
use crate::geom::{Point, Segment};
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

/// Grid cell of a point.
type Cell = (i64, i64);

struct EndGrid {
    cell: f64,
    map: HashMap<Cell, Vec<u32>>,
}

impl EndGrid {
    fn key(&self, p: Point) -> Cell {
        (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        )
    }
    fn insert(&mut self, p: Point, id: u32) {
        let k = self.key(p);
        self.map.entry(k).or_default().push(id);
    }
    /// Ids stored within one cell of `p` (callers check the real distance).
    fn near(&self, p: Point) -> impl Iterator<Item = u32> + '_ {
        let (cx, cy) = self.key(p);
        (-1..=1)
            .flat_map(move |dx| (-1..=1).map(move |dy| (cx + dx, cy + dy)))
            .flat_map(move |k| self.map.get(&k).into_iter().flatten().copied())
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
    let mut grid = EndGrid {
        cell: t.max(1e-9),
        map: HashMap::new(),
    };
    let end_point = |pieces: &Vec<Option<Piece>>, id: u32| -> Option<Point> {
        let segs = &pieces[(id / 2) as usize].as_ref()?.segments;
        Some(if id.is_multiple_of(2) {
            segs.first()?.a
        } else {
            segs.last()?.b
        })
    };
    for (i, p) in pieces.iter().enumerate() {
        if let Some(p) = p {
            grid.insert(p.segments[0].a, 2 * i as u32);
            grid.insert(p.segments[p.segments.len() - 1].b, 2 * i as u32 + 1);
        }
    }
    let mut used = vec![false; pieces.len()];
    let mut branches = 0usize;
    let mut branch_at = None;

    // Nearest unused end within the tolerance of `p`, and how many there are.
    let find =
        |p: Point, used: &Vec<bool>, pieces: &Vec<Option<Piece>>| -> (Option<(u32, f64)>, usize) {
            let mut best: Option<(f64, u32)> = None;
            let mut n = 0;
            for id in grid.near(p) {
                if used[(id / 2) as usize] {
                    continue;
                }
                let Some(q) = end_point(pieces, id) else {
                    continue;
                };
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
                let (found, n) = find(at, &used, &pieces);
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
        let msg = format!(
            "{branches} branch point(s) where more than two ends meet: contours there were chained by nearest end"
        );
        warnings.push(Warning::maybe_at(msg, branch_at));
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
}
