//! Local search on the visiting sequence: 2-opt, Or-opt and Or-3opt
//! ([`or3`]) driven by a work queue and neighbour lists, then an iterated local search whose kick is a
//! local segment swap (a "double bridge" confined to nearby positions, the
//! usual perturbation of Lin–Kernighan style iterated search, Johnson &
//! McGeoch 1997). Precedence (every site before `Inst::up`) is checked for
//! every move; the chosen entry points stay fixed except for a single site
//! moved by Or-opt, whose entry is re-chosen for its new neighbours.

use std::collections::VecDeque;

mod apply;
mod kicks;
mod moves;
mod neighbours;
mod or3;
mod screen;

pub(super) use kicks::count as kick_count;
pub(super) use neighbours::Neighbours;

use super::cluster;
use super::dist;
use super::{Effort, Inst};
use crate::geom::Point;
use crate::par::Threads;

/// Neighbour-list length: 10 nearest sites by current entry point.
const NEIGHBOURS: usize = 10;
/// A move must gain at least this much (mm): stops float ping-pong.
const EPS: f64 = 1e-7;
/// No site: before the first (the origin) or after the last (the end).
const NONE: usize = usize::MAX;
/// Positions either side of a changed one that [`Path::entries_local`]
/// re-chooses too.
const MARGIN: usize = 4;

/// Distance to an optional point (none: the open end of the path).
fn d(a: Point, b: Option<Point>) -> f64 {
    b.map_or(0.0, |b| dist(a, b))
}

/// The sequence being improved.
pub(super) struct Path<'a> {
    inst: &'a Inst,
    origin: Point,
    /// Visitable sites in visiting order.
    pub seq: Vec<usize>,
    /// Position of each visitable site in `seq`.
    pos: Vec<usize>,
    /// Chosen entry of each site: index into `inst.pts[site]`.
    pub at: Vec<usize>,
    /// The chosen entry's point of each site (`inst.pts[s][at[s]]`), kept
    /// flat: the search reads it for every distance, and the two-level
    /// look-up through `pts` was an eighth of the plan's time (perf, 61k
    /// contours). Set wherever `at` changes ([`Path::sync`] after a
    /// re-choice of all entries).
    cur: Vec<Point>,
    neigh: Neighbours,
    queue: VecDeque<usize>,
    queued: Vec<bool>,
    /// Screen the queue before a local search ([`Path::screen`]): the
    /// short schedule's.
    screen: bool,
    /// Queued sites the screen found no move around, skipped when their
    /// turn comes unless a move changed their neighbourhood meanwhile
    /// (empty: no screen yet).
    idle: Vec<bool>,
    /// Sites whose tour neighbours a move changed since the screen.
    stirred: Vec<bool>,
    /// Current length, kept up to date by every move.
    pub len: f64,
    /// Scratch for `reverse_units`.
    units: Vec<(usize, usize)>,
    /// Positions touched since the last `clean()`: (lowest, highest).
    dirty: (usize, usize),
    /// Scratch of the entry re-choice ([`Path::entries`]).
    layers: cluster::Layers,
    /// Each site's (predecessor, successor) when the entries were last
    /// re-chosen ([`NONE`] at the ends; empty: never).
    pub settled: Vec<(usize, usize)>,
    /// Threads the neighbour lists may be built on.
    threads: Threads,
    /// The short schedule's whole re-choices, in blocks on the threads
    /// ([`cluster::optimise_blocks`]).
    blocks: bool,
}

impl<'a> Path<'a> {
    pub(super) fn new(inst: &'a Inst, origin: Point, seq: Vec<usize>, at: Vec<usize>) -> Self {
        let mut p = Path::unsynced(inst, origin, seq, at);
        p.sync();
        p.len = p.length();
        p
    }

    /// [`Path::new`] without the entry points read or the length summed:
    /// for a path whose entries are re-chosen at once ([`Path::entries`]
    /// does both; twice was two passes over a 137k-site sheet's arrays).
    fn unsynced(inst: &'a Inst, origin: Point, seq: Vec<usize>, at: Vec<usize>) -> Self {
        let n = inst.pts.len();
        let mut p = Path {
            inst,
            origin,
            seq,
            pos: vec![0; n],
            at,
            cur: vec![Point::default(); n],
            neigh: Neighbours::default(),
            queue: VecDeque::new(),
            queued: vec![false; n],
            screen: false,
            idle: Vec::new(),
            stirred: Vec::new(),
            len: 0.0,
            units: Vec::new(),
            dirty: (usize::MAX, 0),
            layers: cluster::Layers::default(),
            settled: Vec::new(),
            threads: Threads::ONE,
            blocks: false,
        };
        for (i, &s) in p.seq.iter().enumerate() {
            p.pos[s] = i;
        }
        p
    }

    /// Entry point of site `s`.
    fn p(&self, s: usize) -> Point {
        self.cur[s]
    }
    /// Re-reads every site's entry point after `at` was changed wholesale.
    pub(super) fn sync(&mut self) {
        for &s in &self.seq {
            self.cur[s] = self.inst.pts[s][self.at[s]];
        }
    }
    /// The point the tool comes from to position `i`.
    fn before(&self, i: usize) -> Point {
        if i == 0 {
            self.origin
        } else {
            self.p(self.seq[i - 1])
        }
    }
    /// The point at position `i`, none past the end.
    fn at_pos(&self, i: usize) -> Option<Point> {
        self.seq.get(i).map(|&s| self.p(s))
    }

    /// Length recomputed from scratch.
    pub(super) fn length(&self) -> f64 {
        let mut here = self.origin;
        let mut len = 0.0;
        for &s in &self.seq {
            len += dist(here, self.p(s));
            here = self.p(s);
        }
        len
    }

    /// Neighbour lists from the current entry points ([`Neighbours::build`]).
    pub(super) fn rebuild_neighbours(&mut self) {
        let pts: Vec<Point> = self.seq.iter().map(|&s| self.p(s)).collect();
        let n = self.inst.pts.len();
        self.neigh.build(&self.seq, &pts, n, self.threads);
    }

    fn push(&mut self, s: usize) {
        if let Some(stirred) = self.stirred.get_mut(s) {
            *stirred = true;
        }
        if !self.queued[s] {
            self.queued[s] = true;
            self.queue.push_back(s);
        }
    }
    fn push_pos(&mut self, i: usize) {
        if let Some(&s) = self.seq.get(i) {
            self.push(s);
        }
    }
    fn touch(&mut self, lo: usize, hi: usize) {
        self.dirty = (self.dirty.0.min(lo), self.dirty.1.max(hi));
        for t in lo..=hi.min(self.seq.len().saturating_sub(1)) {
            self.pos[self.seq[t]] = t;
        }
    }

    /// Runs the queue empty (or out of work budget).
    pub(super) fn local_search(&mut self) {
        if self.screen {
            self.screen();
        }
        let mut budget = 200 * self.seq.len() + 1000;
        while let Some(s) = self.queue.pop_front() {
            self.queued[s] = false;
            if budget == 0 {
                self.queue.clear();
                self.queued.fill(false);
                self.idle.clear();
                self.stirred.clear();
                break;
            }
            if self.idle.get(s) == Some(&true) {
                self.idle[s] = false;
                if self.still(s) {
                    continue;
                }
            }
            budget -= 1;
            if self.improve_site(s) {
                self.push(s);
            }
        }
    }

    /// Re-chooses every entry for the sequence as it is ([`cluster`]).
    fn entries(&mut self) {
        if self.blocks {
            cluster::optimise_blocks(
                &self.layers,
                &mut self.at,
                self.inst,
                self.origin,
                &self.seq,
                MARGIN,
                self.threads,
            );
        } else {
            cluster::optimise_in(
                &self.layers,
                &mut self.at,
                self.inst,
                self.origin,
                &self.seq,
            );
        }
        self.sync();
        self.len = self.length();
        self.settle();
    }

    /// Each site's neighbours in the sequence: (predecessor, successor).
    fn around(&self, i: usize) -> (usize, usize) {
        let pred = if i == 0 { NONE } else { self.seq[i - 1] };
        (pred, self.seq.get(i + 1).copied().unwrap_or(NONE))
    }

    /// Records the neighbours the entries were chosen for.
    fn settle(&mut self) {
        self.settled.resize(self.inst.pts.len(), (NONE, NONE));
        for i in 0..self.seq.len() {
            self.settled[self.seq[i]] = self.around(i);
        }
    }

    /// [`Path::entries`] for the stretches whose sites changed neighbours
    /// since the last re-choice, [`MARGIN`] positions either side, the
    /// entries around them fixed (the whole re-choice if there is no last
    /// one, or if the stretches cover half the sequence). For sheets of tens of
    /// thousands of contours whose tour changed in places: on the 25 MB
    /// nest a whole re-choice was ~30 ms of CPU, four times a tour.
    fn entries_local(&mut self) {
        let n = self.seq.len();
        if self.settled.len() != self.inst.pts.len() {
            return self.entries();
        }
        let mut stretches: Vec<(usize, usize)> = Vec::new();
        for i in 0..n {
            if self.settled[self.seq[i]] == self.around(i) {
                continue;
            }
            let (lo, hi) = (i.saturating_sub(MARGIN), (i + MARGIN).min(n - 1));
            match stretches.last_mut() {
                Some(w) if lo <= w.1 + 1 => w.1 = w.1.max(hi),
                _ => stretches.push((lo, hi)),
            }
        }
        let covered: usize = stretches.iter().map(|w| w.1 + 1 - w.0).sum();
        if covered * 2 > n {
            return self.entries();
        }
        // The stretches are apart (merged when they touch), so each is
        // re-chosen between entries none of them changes: at once on the
        // threads, what one after the other gives.
        cluster::optimise_stretches(
            &self.layers,
            &mut self.at,
            self.inst,
            self.origin,
            &self.seq,
            &stretches,
            self.threads,
        );
        for &w in &stretches {
            for &s in &self.seq[w.0..=w.1] {
                self.cur[s] = self.inst.pts[s][self.at[s]];
            }
        }
        self.len = self.length();
        self.settle();
    }

    /// Queues every site.
    pub(super) fn queue_all(&mut self) {
        for t in 0..self.seq.len() {
            self.push_pos(t);
        }
    }
}

/// What [`improve`] hands on to [`polish`].
pub(super) struct Searched {
    pub seq: Vec<usize>,
    pub at: Vec<usize>,
    /// The neighbour lists.
    pub neigh: Neighbours,
    /// The neighbours each site's entry was last chosen for
    /// ([`Path::settled`]).
    pub settled: Vec<(usize, usize)>,
    /// The entry re-choice's arrays, for the polish to reuse (~35 MB at
    /// 137k sites: fresh ones are pages the kernel zeroes again).
    pub layers: cluster::Layers,
}

/// Full improvement: entries, local search, kicks, entries again. Returns
/// the sequence, the entries and the neighbour lists (for [`polish`]).
/// `neigh`: lists made beforehand ([`Neighbours::of_centres`], the short
/// schedule's), or empty to build them by entry point.
pub(super) fn improve(
    inst: &Inst,
    origin: Point,
    seq: Vec<usize>,
    at: Vec<usize>,
    neigh: Neighbours,
    effort: Effort,
    threads: Threads,
) -> Searched {
    let mut path = Path::unsynced(inst, origin, seq, at);
    path.threads = threads;
    path.screen = effort.short;
    path.blocks = effort.short;
    path.entries();
    if neigh.len() == inst.pts.len() {
        path.neigh = neigh;
    } else {
        path.rebuild_neighbours();
    }
    path.queue_all();
    path.local_search();
    // The kicks' searches are of a few sites each: nothing to screen.
    path.screen = false;
    if !effort.short || effort.kicks > 0 {
        // The kicks' own re-choices are of single moved sites: they start
        // from entries chosen for the order they perturb. (The short
        // schedule without kicks goes straight to the polish, which
        // re-chooses them first: a pass over every site saved, the same
        // tours on the bench nests and the 4/11/25 MB sheets.)
        path.entries();
    }
    if !effort.short {
        // The short schedule keeps the lists: the entries moved within
        // their contours only, and a rebuild is a tenth of its time.
        path.rebuild_neighbours();
    }
    kicks::kicks(&mut path, effort.kicks);
    if !effort.short {
        path.entries();
        // One more local search from every site: worth 0.1–0.5 % on the
        // bench nests, and as long as the first one. (The short schedule
        // leaves the entries to the polish, which re-chooses them first.)
        path.queue_all();
        path.local_search();
        path.entries();
    }
    Searched {
        seq: path.seq,
        at: path.at,
        neigh: path.neigh,
        settled: path.settled,
        layers: path.layers,
    }
}

/// Entries, a local search started at the sites `from`, entries: for a
/// tour that is already good except around those. `neigh`: the lists of
/// an earlier search on the same sites, or empty to build them.
/// `settled`: the neighbours the entries `at` were chosen for in that
/// search ([`Path::settled`]; empty: unknown), so that only the stretches
/// changed since are re-chosen ([`Path::entries_local`]). `layers`: the
/// entry re-choice's arrays of that search (or new ones).
#[allow(clippy::too_many_arguments)]
pub(super) fn polish(
    inst: &Inst,
    origin: Point,
    seq: Vec<usize>,
    at: Vec<usize>,
    neigh: Neighbours,
    settled: Vec<(usize, usize)>,
    layers: cluster::Layers,
    from: &[usize],
    effort: Effort,
    threads: Threads,
) -> (Vec<usize>, Vec<usize>) {
    let mut path = Path::new(inst, origin, seq, at);
    path.threads = threads;
    path.screen = effort.short;
    path.blocks = effort.short;
    path.layers = layers;
    if neigh.len() == inst.pts.len() {
        path.neigh = neigh;
    } else {
        path.rebuild_neighbours();
    }
    path.settled = settled;
    path.entries_local();
    for &s in from {
        path.push(s);
    }
    path.local_search();
    path.entries_local();
    (path.seq, path.at)
}
