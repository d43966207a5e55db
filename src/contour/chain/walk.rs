//! The walks that make chains (paper 000, "Chain"): from each unused
//! piece in turn, forward to the nearest unused end within the tolerance
//! of the chain's end, then backward from its first point, until the
//! chain closes or nothing continues it. [`Walker::walk`] walks from the
//! starts it is given, in their order; which pieces are used is the
//! caller's ([`super::strips`] walks the parts of a sheet that cannot
//! touch on separate threads).

use super::grid::EndGrid;
use super::{write_chain, Chain, Length};
use crate::geom::{Point, Segment};

/// A piece joined to a chain, and whether it runs reversed.
pub(super) type Joined = (usize, bool);

/// The open pieces to chain, stored flat ([`super::Pieces`]).
#[derive(Clone, Copy)]
pub(super) struct Open<'p> {
    pub segs: &'p [Segment],
    pub ents: &'p [usize],
    /// Where each piece's segments and entities end.
    pub ends: &'p [(usize, usize)],
}

impl<'p> Open<'p> {
    /// How many pieces.
    pub fn len(&self) -> usize {
        self.ends.len()
    }

    /// Piece `i`'s segments and entities.
    pub fn piece(&self, i: usize) -> (&'p [Segment], &'p [usize]) {
        let (s0, e0) = if i == 0 { (0, 0) } else { self.ends[i - 1] };
        let (s1, e1) = self.ends[i];
        (&self.segs[s0..s1], &self.ents[e0..e1])
    }

    /// A piece's two ends as it lies: `rev` when it runs backwards in the chain.
    pub fn ends_of(&self, i: usize, rev: bool) -> (Point, Point) {
        let segs = self.piece(i).0;
        let (a, b) = (segs[0].a, segs[segs.len() - 1].b);
        if rev {
            (b, a)
        } else {
            (a, b)
        }
    }

    /// End `k` and its id: 2*i = start of piece i, 2*i+1 = its end.
    pub fn end(&self, k: usize) -> (Point, u32) {
        let (a, b) = self.ends_of(k / 2, false);
        (if k.is_multiple_of(2) { a } else { b }, k as u32)
    }
}

/// What walks report besides their chains, in the walks' order.
#[derive(Default)]
pub(super) struct Log {
    /// Joins and closures across more than `report_above`: (the start of
    /// the walk, the point), in the order they were made.
    pub gaps: Vec<(u32, Point)>,
    /// Branch points met (more than one unused end within the tolerance).
    pub branches: usize,
    /// The first branch point: (the start of its walk, the point).
    pub branch_at: Option<(u32, Point)>,
}

/// Where the walks' chains go.
pub(super) trait Sink {
    /// The chain walked from `start`: the pieces joined backward (first
    /// joined first) and forward, each with whether it runs reversed.
    fn chain(
        &mut self,
        open: &Open,
        start: usize,
        backward: &[Joined],
        forward: &[Joined],
        closed: bool,
    );
}

/// Chains written as they are walked.
impl Sink for Vec<Chain> {
    fn chain(
        &mut self,
        open: &Open,
        start: usize,
        backward: &[Joined],
        forward: &[Joined],
        closed: bool,
    ) {
        let piece = |i: usize| open.piece(i);
        self.push(write_chain(&piece, start, backward, forward, closed));
    }
}

/// Chains walked but not written: their pieces, to be written in order
/// later ([`super::strips`]: the walks on worker threads, the chains'
/// vectors allocated by the thread that keeps them, in the order one
/// thread allocates them).
#[derive(Default)]
pub(super) struct Walked {
    pub starts: Vec<u32>,
    pub closed: Vec<bool>,
    /// Each chain's end in `joined`, and where its forward pieces start.
    pub spans: Vec<(usize, usize)>,
    /// Each chain's backward pieces, then its forward ones.
    pub joined: Vec<Joined>,
}

impl Walked {
    /// Chain `i`'s start, backward and forward pieces, and whether it closed.
    pub fn get(&self, i: usize) -> (usize, &[Joined], &[Joined], bool) {
        let from = if i == 0 { 0 } else { self.spans[i - 1].0 };
        let (end, fwd) = self.spans[i];
        (
            self.starts[i] as usize,
            &self.joined[from..fwd],
            &self.joined[fwd..end],
            self.closed[i],
        )
    }
}

impl Sink for Walked {
    fn chain(
        &mut self,
        _: &Open,
        start: usize,
        backward: &[Joined],
        forward: &[Joined],
        closed: bool,
    ) {
        self.starts.push(start as u32);
        self.closed.push(closed);
        self.joined.extend_from_slice(backward);
        let fwd = self.joined.len();
        self.joined.extend_from_slice(forward);
        self.spans.push((self.joined.len(), fwd));
    }
}

/// Walks chains through the pieces, their ends in `grid`.
pub(super) struct Walker<'p> {
    pub open: Open<'p>,
    pub grid: &'p EndGrid,
    /// Ends within this distance (mm) join.
    pub t: f64,
    /// Joins and closures across more than this are reported.
    pub report_above: f64,
}

impl Walker<'_> {
    /// Nearest unused end within the tolerance of `p`, and how many there are.
    fn find(&self, p: Point, used: &[bool]) -> (Option<(u32, f64)>, usize) {
        let t = self.t;
        let mut best: Option<(f64, u32)> = None;
        let mut n = 0;
        for (q, id) in self.grid.near(p) {
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
    }

    /// Calls `f` with every piece that has an end within the tolerance of
    /// `p`, used or not: the pieces a walk at `p` could join.
    pub fn touching(&self, p: Point, mut f: impl FnMut(usize)) {
        let t = self.t;
        for (q, id) in self.grid.near(p) {
            let far = (p.x - q.x).abs() > t || (p.y - q.y).abs() > t;
            if !far && p.dist(q) <= t {
                f((id / 2) as usize);
            }
        }
    }

    /// Walks a chain from every start not yet `used`, in order, marking
    /// the pieces it takes; the chains go to `sink`.
    pub fn walk(
        &self,
        starts: impl Iterator<Item = usize>,
        used: &mut [bool],
        sink: &mut impl Sink,
    ) -> Log {
        let (t, report_above) = (self.t, self.report_above);
        let piece = |i: usize| self.open.piece(i);
        let mut out = Log::default();
        // The pieces joined after the first, forward and backward, each with
        // whether it runs reversed: the chain is written once at the end.
        let mut forward: Vec<Joined> = Vec::new();
        let mut backward: Vec<Joined> = Vec::new();
        for start in starts {
            if used[start] {
                continue;
            }
            used[start] = true;
            let tag = start as u32;
            forward.clear();
            backward.clear();
            let (mut head, mut tail) = self.open.ends_of(start, false);
            // The chain's length matters only once its ends meet (a loop must
            // be longer than 2t), so it is summed then, over the pieces in the
            // order they were joined, each added only while the sum is at most
            // 2t: the same additions, in the same order, as summing at every
            // join, without a `hypot` per segment of every chain that never
            // closes (issue 17: a million isolated segments).
            let mut length = Length::default();
            let mut closed = false;
            // Forward, then backward from the first point.
            for back in [false, true] {
                loop {
                    // `hypot` is at least either side's length: ends farther
                    // apart than `t` along an axis do not meet, without it.
                    let near = (head.x - tail.x).abs() <= t && (head.y - tail.y).abs() <= t;
                    if near {
                        let gap = head.dist(tail);
                        if gap <= t
                            && length.settle(&piece, start, &forward, &backward, t) > 2.0 * t
                        {
                            if gap > report_above {
                                out.gaps.push((tag, tail));
                            }
                            closed = true;
                            break;
                        }
                    }
                    let at = if back { head } else { tail };
                    let (found, near) = self.find(at, used);
                    if near > 1 {
                        out.branches += 1;
                        out.branch_at = out.branch_at.or(Some((tag, at)));
                    }
                    let Some((id, d)) = found else { break };
                    if d > report_above {
                        out.gaps.push((tag, at));
                    }
                    let k = (id / 2) as usize;
                    used[k] = true;
                    // Oriented so the matched end touches `at`.
                    let rev = id.is_multiple_of(2) == back;
                    let (a, b) = self.open.ends_of(k, rev);
                    if back {
                        backward.push((k, rev));
                        head = a;
                    } else {
                        forward.push((k, rev));
                        tail = b;
                    }
                }
                if closed {
                    break;
                }
            }
            sink.chain(&self.open, start, &backward, &forward, closed);
        }
        out
    }
}
