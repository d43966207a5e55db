//! Local search on the visiting sequence: 2-opt, Or-opt and Or-3opt
//! ([`or3`]) driven by a work queue and neighbour lists, then an iterated local search whose kick is a
//! local segment swap (a "double bridge" confined to nearby positions, the
//! usual perturbation of Lin–Kernighan style iterated search, Johnson &
//! McGeoch 1997). Precedence (every site before `Inst::up`) is checked for
//! every move; the chosen entry points stay fixed except for a single site
//! moved by Or-opt, whose entry is re-chosen for its new neighbours.

use std::collections::VecDeque;

mod or3;

use super::cluster;
use super::dist;
use super::grid::Grid;
use super::Inst;
use crate::geom::Point;

/// Neighbour-list length: 10 nearest sites by current entry point.
const NEIGHBOURS: usize = 10;
/// A move must gain at least this much (mm): stops float ping-pong.
const EPS: f64 = 1e-7;
/// Longest block a kick swaps.
const KICK_MAX: usize = 10;

/// Longest stretch `reverse_units` looks at (its gain costs O(length)).
const UNITS_MAX: usize = 1000;
/// Largest family (holes + outer) moved as one block.
const FAMILY_MAX: usize = 12;
/// Or-opt looks for a gap next to a neighbour m of the block's end only
/// while that end is nearer m than this many times what taking the block
/// out saves (neighbours come nearest first): the positive-gain idea of Lin
/// and Kernighan, loosened. At 1× the tours came out 1–2 % longer; at 3×
/// they are as short as with no cut-off (within the kicks' noise) and the
/// local search takes a third of the time (benches/tsp.rs, random nests).
const OR_PRUNE: f64 = 3.0;

/// Which way round Or-opt may put a block back.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Way {
    Forward,
    Reversed,
    Both,
}

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
    /// The chosen entry's point of each site (`inst.pts[s][at[s]].1`), kept
    /// flat: the search reads it for every distance, and the two-level
    /// look-up through `pts` was an eighth of the plan's time (perf, 61k
    /// contours). Set wherever `at` changes ([`Path::sync`] after a
    /// re-choice of all entries).
    cur: Vec<Point>,
    neigh: Vec<Vec<usize>>,
    queue: VecDeque<usize>,
    queued: Vec<bool>,
    /// Current length, kept up to date by every move.
    pub len: f64,
    /// Scratch for `reverse_units`.
    units: Vec<(usize, usize)>,
    /// Positions touched since the last `clean()`: (lowest, highest).
    dirty: (usize, usize),
}

impl<'a> Path<'a> {
    pub(super) fn new(inst: &'a Inst, origin: Point, seq: Vec<usize>, at: Vec<usize>) -> Self {
        let n = inst.pts.len();
        let mut p = Path {
            inst,
            origin,
            seq,
            pos: vec![0; n],
            at,
            cur: vec![Point::default(); n],
            neigh: vec![Vec::new(); n],
            queue: VecDeque::new(),
            queued: vec![false; n],
            len: 0.0,
            units: Vec::new(),
            dirty: (usize::MAX, 0),
        };
        for (i, &s) in p.seq.iter().enumerate() {
            p.pos[s] = i;
        }
        p.sync();
        p.len = p.length();
        p
    }

    /// Entry point of site `s`.
    fn p(&self, s: usize) -> Point {
        self.cur[s]
    }
    /// Re-reads every site's entry point after `at` was changed wholesale.
    pub(super) fn sync(&mut self) {
        for &s in &self.seq {
            self.cur[s] = self.inst.pts[s][self.at[s]].1;
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

    /// Neighbour lists from the current entry points.
    pub(super) fn rebuild_neighbours(&mut self) {
        let pts: Vec<Point> = self.seq.iter().map(|&s| self.p(s)).collect();
        let mut grid = Grid::new(&pts, 2.0);
        for (i, q) in pts.iter().enumerate() {
            grid.insert(*q, i as u32);
        }
        for (i, &s) in self.seq.iter().enumerate() {
            let near = grid.k_nearest(
                pts[i],
                NEIGHBOURS + 1,
                |k| pts[k as usize],
                |k| k as usize == i,
            );
            self.neigh[s] = near.into_iter().map(|k| self.seq[k as usize]).collect();
        }
    }

    fn push(&mut self, s: usize) {
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

    /// Reverses positions i..=j if that is legal and gains; true if done.
    fn try_reverse(&mut self, i: usize, j: usize) -> bool {
        if i >= j || j >= self.seq.len() {
            return false;
        }
        let (a, b) = (self.before(i), self.at_pos(j + 1));
        let (f, l) = (self.p(self.seq[i]), self.p(self.seq[j]));
        let delta = dist(a, l) + d(f, b) - dist(a, f) - d(l, b);
        if delta > -EPS {
            return false;
        }
        let inside = |t: usize| t >= i && t <= j;
        let legal = self.seq[i..=j]
            .iter()
            .all(|&s| self.inst.up[s].is_none_or(|u| !inside(self.pos[u])));
        if !legal {
            return self.reverse_units(i, j);
        }
        self.seq[i..=j].reverse();
        self.touch(i, j);
        self.len += delta;
        for t in [i.wrapping_sub(1), i, j, j + 1] {
            self.push_pos(t);
        }
        true
    }

    /// 2-opt at the level of families: reverses the order of the units of
    /// positions i..=j — a unit being a run of holes followed by their outer
    /// contour, or a single site — each unit kept in its own order, so the
    /// holes still come first. Plain 2-opt can never reverse a stretch holding
    /// a whole part with holes, which is nearly every long stretch of a nest.
    /// Legal only if the stretch splits into such units exactly and no unit's
    /// last site has its parent inside; gains are computed over every unit
    /// boundary (a unit is entered and left at different points). True if done.
    fn reverse_units(&mut self, i: usize, j: usize) -> bool {
        if j + 1 - i > UNITS_MAX {
            return false;
        }
        let mut units = std::mem::take(&mut self.units);
        units.clear();
        let done = self.split_units(i, j, &mut units) && self.apply_units(i, j, &units);
        self.units = units;
        done
    }

    /// Splits i..=j into units (see `reverse_units`); false if it cannot.
    fn split_units(&self, i: usize, j: usize, units: &mut Vec<(usize, usize)>) -> bool {
        let up = &self.inst.up;
        let mut t = i;
        while t <= j {
            let end = match up[self.seq[t]] {
                Some(u) if self.pos[u] > t && self.pos[u] <= j => {
                    let e = self.pos[u];
                    if !self.seq[t..e].iter().all(|&k| up[k] == Some(u)) {
                        return false;
                    }
                    e
                }
                _ => t,
            };
            if up[self.seq[end]].is_some_and(|u| self.pos[u] <= j) {
                return false;
            }
            units.push((t, end));
            t = end + 1;
        }
        units.len() >= 2
    }

    /// Reverses the units if that gains.
    fn apply_units(&mut self, i: usize, j: usize, units: &[(usize, usize)]) -> bool {
        let entry = |u: &(usize, usize)| self.p(self.seq[u.0]);
        let exit = |u: &(usize, usize)| self.p(self.seq[u.1]);
        let (Some(first), Some(last)) = (units.first(), units.last()) else {
            return false;
        };
        let (a, b) = (self.before(i), self.at_pos(j + 1));
        let mut old = dist(a, entry(first)) + d(exit(last), b);
        let mut new = dist(a, entry(last)) + d(exit(first), b);
        for w in units.windows(2) {
            old += dist(exit(&w[0]), entry(&w[1]));
            new += dist(exit(&w[1]), entry(&w[0]));
        }
        let delta = new - old;
        if delta > -EPS {
            return false;
        }
        let mut out = Vec::with_capacity(j + 1 - i);
        for &(x, y) in units.iter().rev() {
            out.extend_from_slice(&self.seq[x..=y]);
        }
        self.seq[i..=j].copy_from_slice(&out);
        self.touch(i, j);
        self.len += delta;
        for t in [i.wrapping_sub(1), i, j, j + 1] {
            self.push_pos(t);
        }
        true
    }

    /// Moves positions i..=j to the gap before position `g` (0..=n, not in
    /// i..=j+1), either way round, if legal and gaining; true if done.
    fn try_move(&mut self, i: usize, j: usize, g: usize, removed: f64, way: Way) -> bool {
        let n = self.seq.len();
        if j >= n || g > n || (g >= i && g <= j + 1) {
            return false;
        }
        let (f, l) = (self.seq[i], self.seq[j]);
        let (a, b) = (self.before(g), self.at_pos(g));
        let base = d(a, b);
        // Best way in: forward, reversed, and for one site every entry.
        let mut best: Option<(f64, bool, usize)> = None;
        if i == j {
            // Every candidate lies within `radius` of `centre`: a lower bound
            // on the cost of the best one, to skip hopeless gaps cheaply.
            let (c, r) = self.inst.disc[f];
            let lower = dist(a, c) + b.map_or(-r, |b| dist(c, b) - r) - r - base;
            if lower - removed > -EPS {
                return false;
            }
            let spread = &self.inst.spread[f];
            for c in spread.iter().copied().chain([self.at[f]]) {
                let v = self.inst.pts[f][c].1;
                let add = dist(a, v) + d(v, b) - base;
                if best.is_none_or(|(x, _, _)| add < x) {
                    best = Some((add, false, c));
                }
            }
        } else {
            if way != Way::Reversed {
                let fwd = dist(a, self.p(f)) + d(self.p(l), b) - base;
                best = Some((fwd, false, self.at[f]));
            }
            if way != Way::Forward {
                let rev = dist(a, self.p(l)) + d(self.p(f), b) - base;
                if best.is_none_or(|(x, _, _)| rev < x)
                    && rev - removed < -EPS
                    && self.reversible(i, j)
                {
                    best = Some((rev, true, self.at[f]));
                }
            }
        }
        let Some((add, rev, entry)) = best else {
            return false;
        };
        let delta = add - removed;
        if delta > -EPS {
            return false;
        }
        let up = &self.inst.up;
        let legal = if g < i {
            // Sites in g..i end up after the block: none may be a child.
            self.seq[i..=j].iter().all(|&s| {
                self.inst.kids[s]
                    .iter()
                    .all(|&k| self.pos[k] < g || self.pos[k] >= i)
            })
        } else {
            // Sites in j+1..g end up before the block: none may be a parent.
            self.seq[i..=j]
                .iter()
                .all(|&s| up[s].is_none_or(|u| self.pos[u] <= j || self.pos[u] >= g))
        };
        if !legal {
            return false;
        }
        let len = j - i + 1;
        let (lo, hi, at) = if g < i {
            self.seq[g..=j].rotate_right(len);
            (g, j, g)
        } else {
            self.seq[i..g].rotate_left(len);
            (i, g - 1, g - len)
        };
        if rev {
            self.seq[at..at + len].reverse();
        }
        self.at[f] = entry;
        self.cur[f] = self.inst.pts[f][entry].1;
        self.touch(lo, hi);
        self.len += delta;
        for t in [
            i.wrapping_sub(1),
            i,
            at.wrapping_sub(1),
            at,
            at + len - 1,
            at + len,
        ] {
            self.push_pos(t);
        }
        // The block's old successor, now joined to its old predecessor.
        if g < i {
            self.push_pos(j + 1);
        }
        true
    }

    /// True if positions i..=j hold no site together with its parent.
    fn reversible(&self, i: usize, j: usize) -> bool {
        self.seq[i..=j]
            .iter()
            .all(|&s| self.inst.up[s].is_none_or(|u| self.pos[u] < i || self.pos[u] > j))
    }

    /// Tries the moves around site `s`; true on the first gain.
    fn improve_site(&mut self, s: usize) -> bool {
        let n = self.seq.len();
        let p = self.pos[s];
        // 2-opt: every reversal that creates an edge s–c with c near s.
        // Positive-gain rule (Lin & Kernighan 1973): the new edge s–c must
        // be shorter than an edge of s it replaces; neighbours come nearest first.
        let here = self.p(s);
        let longest = dist(self.before(p), here).max(d(here, self.at_pos(p + 1)));
        for k in 0..self.neigh[s].len() {
            let c = self.neigh[s][k];
            if dist(here, self.p(c)) >= longest {
                break;
            }
            let q = self.pos[c];
            let done = if q > p {
                self.try_reverse(p + 1, q) || (p + 1 < q && self.try_reverse(p, q - 1))
            } else {
                self.try_reverse(q + 1, p) || (q + 1 < p && p > 0 && self.try_reverse(q, p - 1))
            };
            if done {
                return true;
            }
        }
        if self.try_reverse(0, p) || self.try_reverse(p + 1, n.saturating_sub(1)) {
            return true;
        }
        if self.try_reverse(p, n.saturating_sub(1)) {
            return true;
        }
        // Or-opt: blocks of 1–3 sites starting or ending at s, and the
        // whole family ending at s (its holes, then s), so a part with its
        // holes can move as one.
        let kids = self.inst.kids[s].len();
        let family = (kids > 0
            && kids < FAMILY_MAX
            && p >= kids
            && self.seq[p - kids..p]
                .iter()
                .all(|&k| self.inst.up[k] == Some(s)))
        .then(|| (p - kids, p));
        let blocks = [
            Some((p, p)),
            Some((p, p + 1)),
            Some((p, p + 2)),
            Some((p.wrapping_sub(1), p)),
            Some((p.wrapping_sub(2), p)),
            family.filter(|&(i, _)| i + 2 < p),
        ];
        for (i, j) in blocks.into_iter().flatten() {
            if i > j || j >= n {
                continue;
            }
            let (f, l) = (self.seq[i], self.seq[j]);
            let (pp, nn) = (self.before(i), self.at_pos(j + 1));
            let removed = dist(pp, self.p(f)) + d(self.p(l), nn) - d(pp, nn);
            if self.try_move(i, j, 0, removed, Way::Both)
                || self.try_move(i, j, n, removed, Way::Both)
            {
                return true;
            }
            // The block's first site next to a neighbour m: after m as it
            // is, or before m reversed (a single site: both gaps, any entry).
            for k in 0..self.neigh[f].len() {
                let m = self.neigh[f][k];
                if dist(self.p(f), self.p(m)) >= OR_PRUNE * removed {
                    break;
                }
                let q = self.pos[m];
                if self.try_move(i, j, q + 1, removed, Way::Forward)
                    || self.try_move(i, j, q, removed, Way::Reversed)
                {
                    return true;
                }
            }
            if i == j {
                continue;
            }
            for k in 0..self.neigh[l].len() {
                let m = self.neigh[l][k];
                if dist(self.p(l), self.p(m)) >= OR_PRUNE * removed {
                    break;
                }
                let q = self.pos[m];
                if self.try_move(i, j, q, removed, Way::Forward)
                    || self.try_move(i, j, q + 1, removed, Way::Reversed)
                {
                    return true;
                }
            }
        }
        self.try_or3(s)
    }

    /// Runs the queue empty (or out of work budget).
    pub(super) fn local_search(&mut self) {
        let mut budget = 200 * self.seq.len() + 1000;
        while let Some(s) = self.queue.pop_front() {
            self.queued[s] = false;
            if budget == 0 {
                self.queue.clear();
                self.queued.fill(false);
                break;
            }
            budget -= 1;
            if self.improve_site(s) {
                self.push(s);
            }
        }
    }

    /// Queues every site.
    pub(super) fn queue_all(&mut self) {
        for t in 0..self.seq.len() {
            self.push_pos(t);
        }
    }
}

/// Small deterministic generator (xorshift64*): same input, same tour.
struct Rng(u64);
impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let r = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        ((r >> 33) % n.max(1) as u64) as usize
    }
}

/// Iterated local search: swap two short adjacent blocks, re-optimise
/// around them, keep the result only if shorter.
fn kicks(path: &mut Path, iterations: usize) {
    let n = path.seq.len();
    if n < 8 {
        return;
    }
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut best_seq = path.seq.clone();
    let mut best_at = path.at.clone();
    let mut best_len = path.len;
    for _ in 0..iterations {
        path.dirty = (usize::MAX, 0);
        let l1 = 1 + rng.below(KICK_MAX.min(n / 4));
        let l2 = 1 + rng.below(KICK_MAX.min(n / 4));
        let p = rng.below(n - l1 - l2 + 1);
        let (b, c, e) = (p, p + l1, p + l1 + l2);
        // C moves before B: illegal if a site of B has its parent in C.
        let legal = path.seq[b..c]
            .iter()
            .all(|&s| path.inst.up[s].is_none_or(|u| path.pos[u] < c || path.pos[u] >= e));
        if !legal {
            continue;
        }
        let pt = |path: &Path, i: usize| path.at_pos(i);
        let before = path.before(b);
        let (fb, lb) = (path.p(path.seq[b]), path.p(path.seq[c - 1]));
        let (fc, lc) = (path.p(path.seq[c]), path.p(path.seq[e - 1]));
        let next = pt(path, e);
        let old = dist(before, fb) + dist(lb, fc) + d(lc, next);
        let new = dist(before, fc) + dist(lc, fb) + d(lb, next);
        path.seq[b..e].rotate_left(l1);
        path.touch(b, e - 1);
        path.len += new - old;
        for t in [b.wrapping_sub(1), b, b + l2 - 1, b + l2, e - 1, e] {
            path.push_pos(t);
        }
        path.local_search();
        let (lo, hi) = path.dirty;
        if lo > hi {
            continue;
        }
        let hi = hi.min(n - 1);
        if path.len < best_len - EPS {
            best_len = path.len;
            best_seq[lo..=hi].copy_from_slice(&path.seq[lo..=hi]);
            for &s in &path.seq[lo..=hi] {
                best_at[s] = path.at[s];
            }
        } else {
            path.seq[lo..=hi].copy_from_slice(&best_seq[lo..=hi]);
            for t in lo..=hi {
                let s = path.seq[t];
                path.at[s] = best_at[s];
                path.cur[s] = path.inst.pts[s][best_at[s]].1;
                path.pos[s] = t;
            }
            path.len = best_len;
        }
    }
}

/// Kicks in all: fixed work, so the result is reproducible. A kick costs
/// 5–10 µs on hundreds of sites and ~15 µs on 60k (its local search stays
/// local; the copy-back of what it touched grows a little). Up to
/// [`KICKS_UNTIL`] sites [`KICKS_PER_SITE`] a site, at least [`KICKS_MIN`]
/// and at most [`KICKS`]: 10,000 on a 100-part nest (33 a site: within
/// 0.1 % of LKH-3 there, 2.5 % above with one a site), 30,000 on 5,000
/// parts (15k sites, 0.3 s in all: 1.9 % above LKH-3, 3.1 % with 10,000).
/// Above, on sheets of tens of thousands of contours, [`KICKS_LARGE`]
/// (~150 ms at 60k; 30,000 gained 0.6 % there for 0.3 s). Measured in
/// benches/tsp.rs. 30 a site (tried first) made a 1,162-contour nest plan
/// in 350 ms instead of 50.
const KICKS: usize = 30_000;
/// Fewest kicks (small instances).
const KICKS_MIN: usize = 10_000;
/// Kicks a site between [`KICKS_MIN`] and [`KICKS`].
const KICKS_PER_SITE: usize = 2;
/// Largest instance that gets [`KICKS`]; larger ones get [`KICKS_LARGE`].
const KICKS_UNTIL: usize = 20_000;
/// Kicks above [`KICKS_UNTIL`] sites.
const KICKS_LARGE: usize = 10_000;

/// Full improvement: entries, local search, kicks, entries again.
pub(super) fn improve(
    inst: &Inst,
    origin: Point,
    seq: Vec<usize>,
    at: Vec<usize>,
) -> (Vec<usize>, Vec<usize>) {
    let mut path = Path::new(inst, origin, seq, at);
    cluster::optimise(&mut path.at, inst, origin, &path.seq);
    path.sync();
    path.len = path.length();
    path.rebuild_neighbours();
    path.queue_all();
    path.local_search();
    cluster::optimise(&mut path.at, inst, origin, &path.seq);
    path.sync();
    path.len = path.length();
    path.rebuild_neighbours();
    let n = path.seq.len();
    let iterations = if n <= KICKS_UNTIL {
        (KICKS_PER_SITE * n).clamp(KICKS_MIN, KICKS)
    } else {
        KICKS_LARGE
    };
    kicks(&mut path, iterations);
    polish_path(&mut path);
    (path.seq, path.at)
}

/// Entries, a local search started at the sites `from`, entries: for a
/// tour that is already good except around those.
pub(super) fn polish(
    inst: &Inst,
    origin: Point,
    seq: Vec<usize>,
    at: Vec<usize>,
    from: &[usize],
) -> (Vec<usize>, Vec<usize>) {
    let mut path = Path::new(inst, origin, seq, at);
    path.rebuild_neighbours();
    cluster::optimise(&mut path.at, inst, origin, &path.seq);
    path.sync();
    path.len = path.length();
    for &s in from {
        path.push(s);
    }
    path.local_search();
    cluster::optimise(&mut path.at, inst, origin, &path.seq);
    path.sync();
    path.len = path.length();
    (path.seq, path.at)
}

/// Entries, one local search from every site, entries.
fn polish_path(path: &mut Path) {
    let (inst, origin) = (path.inst, path.origin);
    cluster::optimise(&mut path.at, inst, origin, &path.seq);
    path.sync();
    path.len = path.length();
    path.queue_all();
    path.local_search();
    cluster::optimise(&mut path.at, inst, origin, &path.seq);
    path.sync();
    path.len = path.length();
}
