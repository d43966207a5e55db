//! Chaining pieces (see [`super::heal`]) into contours by end-point coincidence (paper 000,
//! "Chain"): take an entity, walk to any unused entity with an end within the
//! tolerance of the current end (reversing it if needed), until the chain
//! comes back to its first point (closed) or nothing continues it (open); then
//! walk backwards from the first point too.
//!
//! End points sit in a flat grid of cells at least two tolerances wide, laid
//! out in drawing space order (or hashed when clustered), so each look-up
//! checks the 2×2 cells a tolerance disc can touch: O(n) expected.

use crate::geom::{path_measure, BBox, Point, Segment};
use crate::text;
use crate::warning::Warning;

mod faces;
mod grid;
mod strips;
#[cfg(test)]
mod tests;
mod walk;

use crate::par::Threads;
pub use faces::FaceLog;
use grid::EndGrid;
use walk::{Open, Walker};

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

/// Pieces to chain: the closed ones already contours by themselves, the
/// open ones stored flat (their segments and entities in two arrays, a
/// range of each per piece): a sheet's 300k lines were two small vectors
/// each, allocated, moved and freed again as chains grew (issue 17).
#[derive(Default)]
pub struct Pieces {
    /// Closed pieces as chains, in input order.
    closed: Vec<Chain>,
    /// Open pieces' segments, piece after piece.
    segs: Vec<Segment>,
    /// Open pieces' entities, piece after piece.
    ents: Vec<usize>,
    /// Where each open piece's segments and entities end in `segs`, `ents`.
    ends: Vec<(usize, usize)>,
}

impl Pieces {
    /// Room for `n` pieces of one segment.
    pub fn with_capacity(n: usize) -> Pieces {
        Pieces {
            closed: Vec::new(),
            segs: Vec::with_capacity(n),
            ents: Vec::with_capacity(n),
            ends: Vec::with_capacity(n),
        }
    }
    /// Adds a piece (an open one with no segment is left out).
    pub fn push(&mut self, p: Piece) {
        if p.closed {
            self.push_closed(p.segments, p.entities, p.measure);
        } else {
            self.segs.extend_from_slice(&p.segments);
            self.close_open(&p.entities);
        }
    }
    /// Adds a closed piece, measured here unless `measure` is given.
    pub fn push_closed(&mut self, segs: Vec<Segment>, ents: Vec<usize>, measure: Option<Measure>) {
        let measure = measure.unwrap_or_else(|| Measure::of(&segs));
        self.closed.push(Chain {
            segments: segs,
            closed: true,
            entities: ents,
            measure,
            shares_edges: false,
        });
    }
    /// Drops the closed pieces marked in `copy` (one mark per closed piece, in order).
    pub fn drop_closed(&mut self, copy: &[bool]) {
        let mut k = 0;
        self.closed.retain(|_| {
            k += 1;
            !copy[k - 1]
        });
    }
    /// The open piece being written: its segments so far.
    pub fn open_segments(&mut self) -> &mut Vec<Segment> {
        &mut self.segs
    }
    /// Ends the open piece whose segments were just added to
    /// [`Self::open_segments`] (none added: no piece).
    pub fn close_open(&mut self, entities: &[usize]) {
        let from = self.ends.last().map_or(0, |e| e.0);
        if self.segs.len() > from {
            self.ents.extend_from_slice(entities);
            self.ends.push((self.segs.len(), self.ents.len()));
        }
    }
    /// Appends `other`'s pieces after these (closed after closed, open
    /// after open): what pushing its pieces here one by one would give.
    pub fn append(&mut self, other: Pieces) {
        let (segs, ents) = (self.segs.len(), self.ents.len());
        self.closed.extend(other.closed);
        self.segs.extend_from_slice(&other.segs);
        self.ents.extend_from_slice(&other.ents);
        self.ends
            .extend(other.ends.iter().map(|&(s, e)| (s + segs, e + ents)));
    }
    /// True when it holds no piece.
    pub fn is_empty(&self) -> bool {
        self.closed.is_empty() && self.ends.is_empty()
    }
    /// Number of open pieces.
    fn open_len(&self) -> usize {
        self.ends.len()
    }
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
    /// A face of lines meeting at branch points that shares an edge with
    /// another ([`faces`]).
    pub shares_edges: bool,
}

/// Chains pieces whose ends are within `t` mm. Closed pieces (circles,
/// closed polylines) are contours by themselves, first, in input order.
/// Every join or closure across more than `report_above` mm is pushed to
/// `gaps` (the second, gap-closing pass reports what it bridged).
#[cfg(test)]
pub fn chain(
    input: Pieces,
    t: f64,
    report_above: f64,
    gaps: &mut Vec<Point>,
    warnings: &mut Vec<Warning>,
) -> Vec<Chain> {
    chain_on(input, t, report_above, gaps, warnings, Threads::ONE)
}

/// Chains pieces whose ends are within `t` mm (as the test-only `chain`
/// does) on up to `threads` threads: the same chains, gaps and warnings
/// with any number ([`strips`]).
pub fn chain_on(
    input: Pieces,
    t: f64,
    report_above: f64,
    gaps: &mut Vec<Point>,
    warnings: &mut Vec<Warning>,
    threads: Threads,
) -> Vec<Chain> {
    chain_with(input, t, report_above, gaps, warnings, threads, None)
}

/// [`chain_on`], except that where pieces meet at a branch point and bound
/// faces, the faces are the chains ([`faces`]; what they made goes to
/// `log`). Without a branch point the chains are [`chain_on`]'s: the walk
/// is the same, and faces are looked for only once it met a branch.
pub fn chain_faces(
    input: Pieces,
    t: f64,
    gaps: &mut Vec<Point>,
    warnings: &mut Vec<Warning>,
    threads: Threads,
    log: &mut FaceLog,
) -> Vec<Chain> {
    chain_with(input, t, t, gaps, warnings, threads, Some(log))
}

fn chain_with(
    input: Pieces,
    t: f64,
    report_above: f64,
    gaps: &mut Vec<Point>,
    warnings: &mut Vec<Warning>,
    threads: Threads,
    faces: Option<&mut FaceLog>,
) -> Vec<Chain> {
    let n = input.open_len();
    let closed = input.closed.len();
    let mut chains = input.closed;
    let open = Open {
        segs: &input.segs,
        ents: &input.ents,
        ends: &input.ends,
    };
    let grid = EndGrid::of(2 * n, |k| open.end(k), t, threads);
    let walker = Walker {
        open,
        grid: &grid,
        t,
        report_above,
    };
    chains.reserve(n);
    let mut log = if threads.get() > 1 && n >= strips::FROM {
        strips::walk(&walker, threads, &mut chains)
    } else {
        walker.walk(0..n, &mut vec![false; n], &mut chains)
    };
    let found = match faces {
        Some(faces_log) if log.branches > 0 => faces::find(&walker, t, faces_log),
        _ => None,
    };
    if let Some(found) = found {
        // The other pieces walked again without the faces' groups: no end
        // of theirs is within `t` of those groups' ends, so each walk joins
        // what it joined before (as [`strips`] walks groups apart).
        chains.truncate(closed);
        let mut used = found.taken;
        log = walker.walk(0..n, &mut used, &mut chains);
        chains.extend(found.loops);
        chains.extend(chain_on(
            found.leftover,
            t,
            report_above,
            gaps,
            warnings,
            Threads::ONE,
        ));
    }
    gaps.extend(log.gaps.iter().map(|&(_, p)| p));
    let branches = log.branches;
    if branches > 0 {
        warnings.push(Warning::maybe_at(
            "branch-points",
            text!("{branches} branch point(s) where more than two ends meet: contours there were chained by nearest end";
                  "{branches} ponto(s) de ramificação onde mais de duas pontas se encontram: os contornos ali foram encadeados pela ponta mais próxima"),
            log.branch_at.map(|(_, p)| p),
        ));
    }
    chains
}

/// A chain's length as far as the loop test needs it: the first piece's,
/// then each joined piece's (forward ones, then backward ones, the order
/// they were joined in) while the sum is at most 2t; no more sums once it
/// passes (adding lengths, never negative, keeps it there).
#[derive(Default)]
pub(super) struct Length {
    sum: f64,
    /// Pieces counted: none yet, or the first and this many joined.
    counted: Option<usize>,
}

impl Length {
    pub(super) fn settle<'p>(
        &mut self,
        piece: &impl Fn(usize) -> (&'p [Segment], &'p [usize]),
        start: usize,
        forward: &[(usize, bool)],
        backward: &[(usize, bool)],
        t: f64,
    ) -> f64 {
        let mut c = match self.counted {
            Some(c) => c,
            None => {
                self.sum = piece(start).0.iter().map(Segment::length).sum();
                0
            }
        };
        while c < forward.len() + backward.len() {
            let (k, rev) = match forward.get(c) {
                Some(&f) => f,
                None => backward[c - forward.len()],
            };
            if self.sum <= 2.0 * t {
                let segs = piece(k).0;
                self.sum += if rev {
                    segs.iter()
                        .rev()
                        .map(|s| s.reversed().length())
                        .sum::<f64>()
                } else {
                    segs.iter().map(Segment::length).sum::<f64>()
                };
            }
            c += 1;
        }
        self.counted = Some(c);
        self.sum
    }
}

/// A chain's segments and entities: the backward pieces (last joined
/// first), the first piece, the forward pieces; each joined piece's near
/// end moved onto its neighbour's far end (which no join moves), and a
/// closed chain's last end onto its first.
pub(super) fn write_chain<'p>(
    piece: &impl Fn(usize) -> (&'p [Segment], &'p [usize]),
    start: usize,
    backward: &[(usize, bool)],
    forward: &[(usize, bool)],
    closed: bool,
) -> Chain {
    let order = backward
        .iter()
        .rev()
        .copied()
        .chain(std::iter::once((start, false)))
        .chain(forward.iter().copied());
    let (mut n_segs, mut n_ents) = (0, 0);
    for (k, _) in order.clone() {
        let (s, e) = piece(k);
        n_segs += s.len();
        n_ents += e.len();
    }
    let mut segments: Vec<Segment> = Vec::with_capacity(n_segs);
    let mut entities: Vec<usize> = Vec::with_capacity(n_ents);
    let joined_back = backward.len();
    for (rank, (k, rev)) in order.enumerate() {
        let (s, e) = piece(k);
        let at = segments.len();
        if rev {
            segments.extend(s.iter().rev().map(Segment::reversed));
        } else {
            segments.extend_from_slice(s);
        }
        entities.extend_from_slice(e);
        if rank < joined_back {
            // A backward piece: it ends where the next one (joined before it) starts,
            // which is written after it: fixed below.
        } else if rank > joined_back {
            // A forward piece starts where the previous one ends.
            segments[at].a = segments[at - 1].b;
        }
    }
    // Backward pieces end where the next piece starts.
    let mut at = 0;
    for (k, _) in backward.iter().rev() {
        at += piece(*k).0.len();
        segments[at - 1].b = segments[at].a;
    }
    if closed {
        let first = segments[0].a;
        if let Some(last) = segments.last_mut() {
            last.b = first;
        }
    }
    entities.dedup();
    Chain {
        measure: Measure::of(&segments),
        segments,
        closed,
        entities,
        shares_edges: false,
    }
}
