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

use crate::geom::{path_measure, BBox, Point, Segment};
use crate::text;
use crate::warning::Warning;

mod grid;
#[cfg(test)]
mod tests;

use grid::EndGrid;

/// A path's signed area (as a loop), length and exact box
/// ([`path_measure`]): found once per chain and carried to the contour, as
/// the loop tests, the duplicate keys and the contour all need them.
#[derive(Clone, Copy, Debug)]
pub struct Measure {
    /// Signed area in mm², as [`crate::geom::loop_area`].
    pub area: f64,
    /// Length in mm.
    pub length: f64,
    /// Exact bounding box.
    pub bbox: BBox,
}

impl Measure {
    /// The measures of `segs` (one body for its three callers: the page's
    /// wasm stays small).
    #[inline(never)]
    pub fn of(segs: &[Segment]) -> Measure {
        let (area, length, bbox) = path_measure(segs);
        Measure { area, length, bbox }
    }
}

/// A piece to chain: a closed entity whole, or one segment of an open one.
#[derive(Clone, Debug)]
pub struct Piece {
    /// Its segments, end to end.
    pub segments: Vec<Segment>,
    /// A closed loop by itself.
    pub closed: bool,
    /// The drawing entities it came from.
    pub entities: Vec<usize>,
    /// Its measures when already known (closed entities).
    pub measure: Option<Measure>,
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
    /// Area, length and box of `segments`.
    pub measure: Measure,
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
    let mut chains = Vec::with_capacity(input.len());
    // Only the open pieces are chained (ids index them, in input order, so
    // ties go as before): a sheet's closed loops pass straight through.
    let mut pieces: Vec<Option<Piece>> = Vec::new();
    for p in input {
        if p.closed {
            let measure = p.measure.unwrap_or_else(|| Measure::of(&p.segments));
            chains.push(Chain {
                segments: p.segments,
                closed: true,
                entities: p.entities,
                measure,
            });
        } else if !p.segments.is_empty() {
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
            // `hypot` is at least either side's length, so an end farther
            // than `t` along an axis is out without it (most of a look-up's
            // ends: the rest of their cells).
            let far = (p.x - q.x).abs() > t || (p.y - q.y).abs() > t;
            if far || used[(id / 2) as usize] {
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
                // Orient so the matched end touches `at` (in place).
                if id.is_multiple_of(2) == backward {
                    next.reverse();
                    for s in &mut next {
                        *s = s.reversed();
                    }
                }
                // Only whether it exceeds 2t matters, and adding lengths
                // (never negative) keeps it there: no more sums once it does.
                if length <= 2.0 * t {
                    length += next.iter().map(Segment::length).sum::<f64>();
                }
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
            measure: Measure::of(&segments),
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
