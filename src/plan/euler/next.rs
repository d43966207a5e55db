//! Which circuit is cut next ([`super::sequence::order`]): of the groups
//! whose enclosed groups are all cut, the way in that costs the least —
//! the approach from where the torch stopped minus the rapid that starting
//! there saves — ties to the first group and way in; when none is ready (a
//! cycle of "inside" relations, from paths of parts closer than the kerf
//! joining groups of different depths) the deepest groups left.
//!
//! Why not a scan of every group at every step, as before (issue 17, "no
//! stage superlinear"): that was quadratic — the 4 MB nest (22k contours)
//! took 5 s to sequence and the 11 MB one (61k) 40 s. The ready groups'
//! ways in are kept in the rapid tour's grid ([`crate::plan::tsp::Grid`]),
//! each group's added when it becomes ready, and the least one found by a
//! ring search: the same choice, ties included.

use crate::geom::Point;
use crate::plan::tsp::Grid;
use std::collections::BTreeSet;

/// A way into a closed circuit: where the walk starts, the rapid it saves.
#[derive(Clone, Copy, Debug)]
pub(super) struct Entry {
    pub start: Point,
    pub saved: f64,
    pub reversed: bool,
    /// Index in the (possibly reversed) circuit: of the rapid dropped
    /// (`drop`), or of the first step.
    pub k: usize,
    pub drop: bool,
}

/// Ways in per grid cell.
const PER_CELL: f64 = 4.0;

/// What entering at `e` from `at` costs: the approach less the rapid it
/// saves.
fn score(e: &Entry, at: Point) -> f64 {
    at.dist(e.start) - e.saved
}

/// The groups left and how to find the next one.
pub(super) struct Next<'a> {
    entries: &'a [Vec<Entry>],
    depth: &'a [usize],
    /// The groups waiting for each group (one item per `after` link).
    waiting: Vec<Vec<usize>>,
    /// How many groups each group still waits for.
    pending: Vec<usize>,
    done: Vec<bool>,
    /// Groups with a way in that are not cut yet.
    left: usize,
    /// Ready groups not cut yet.
    ready: usize,
    /// Ready groups with no finite way in (not in the grid), by number.
    stray: BTreeSet<usize>,
    /// Ways in with a finite start, group after group: (group, way).
    items: Vec<(u32, u32)>,
    /// Items of group g: `first[g]..first[g + 1]`.
    first: Vec<usize>,
    grid: Grid,
    /// The largest rapid a way in saves.
    slack: f64,
}

impl<'a> Next<'a> {
    /// `entries[g]`: group g's ways in; `after[g]`: the groups to cut
    /// before it (out-of-range and self links ignored); `depth[g]` its
    /// deepest nesting (missing: 0).
    pub(super) fn new(entries: &'a [Vec<Entry>], after: &[Vec<usize>], depth: &'a [usize]) -> Self {
        let n = entries.len();
        let mut waiting = vec![Vec::new(); n];
        let mut pending = vec![0; n];
        for (g, a) in after.iter().enumerate().take(n) {
            for &b in a.iter().filter(|&&b| b < n && b != g) {
                waiting[b].push(g);
                pending[g] += 1;
            }
        }
        let usable = |e: &Entry| e.start.is_finite() && e.saved.is_finite();
        let mut items = Vec::new();
        let mut first = Vec::with_capacity(n + 1);
        let mut points = Vec::new();
        let mut slack: f64 = 0.0;
        for (g, ways) in entries.iter().enumerate() {
            first.push(items.len());
            for (k, e) in ways.iter().enumerate().filter(|(_, e)| usable(e)) {
                items.push((g as u32, k as u32));
                points.push(e.start);
                slack = slack.max(e.saved);
            }
        }
        first.push(items.len());
        let mut next = Next {
            entries,
            depth,
            waiting,
            pending,
            done: vec![false; n],
            left: entries.iter().filter(|w| !w.is_empty()).count(),
            ready: 0,
            stray: BTreeSet::new(),
            items,
            first,
            grid: Grid::new(&points, PER_CELL),
            slack,
        };
        for g in 0..n {
            if next.pending[g] == 0 {
                next.open(g);
            }
        }
        next
    }

    /// Group `g` is ready: its ways in become candidates.
    fn open(&mut self, g: usize) {
        if self.done[g] || self.entries[g].is_empty() {
            return;
        }
        self.ready += 1;
        let (a, b) = (self.first[g], self.first[g + 1]);
        if a == b {
            self.stray.insert(g);
        }
        for id in a..b {
            self.grid.insert_nth(id);
        }
    }

    /// The next group and its way in from `at`, marked cut; None when
    /// every group with a way in is.
    pub(super) fn take(&mut self, at: Point) -> Option<(usize, Entry)> {
        if self.left == 0 {
            return None;
        }
        let (g, e) = if self.ready > 0 {
            let (done, items, entries) = (&self.done, &self.items, self.entries);
            let way = |id: u32| {
                let (g, k) = items[id as usize];
                &entries[g as usize][k as usize]
            };
            let found = self.grid.least(
                at,
                self.slack,
                |id| !done[items[id as usize].0 as usize],
                |id| score(way(id), at),
            );
            match found {
                Some((id, _)) => (items[id as usize].0 as usize, *way(id)),
                // Ready groups with no finite way in; or no score at all
                // (the torch somewhere not finite): then as after a cycle,
                // so that no group is ever left out.
                None => match self.stray.first() {
                    Some(&g) => (g, self.entries[g][0]),
                    None => self.deepest(at)?,
                },
            }
        } else {
            self.deepest(at)?
        };
        self.finish(g);
        Some((g, e))
    }

    /// No group is ready: the least way in among the deepest groups left
    /// (a scan; only after a cycle).
    fn deepest(&self, at: Point) -> Option<(usize, Entry)> {
        let n = self.entries.len();
        let depth = |g: usize| self.depth.get(g).copied().unwrap_or(0);
        let live = |g: &usize| !self.done[*g] && !self.entries[*g].is_empty();
        let deepest = (0..n).filter(live).map(depth).max()?;
        let mut best: Option<(f64, usize, Entry)> = None;
        for g in (0..n).filter(live).filter(|&g| depth(g) == deepest) {
            for e in &self.entries[g] {
                let s = score(e, at);
                if best.as_ref().is_none_or(|b| s < b.0) {
                    best = Some((s, g, *e));
                }
            }
        }
        best.map(|(_, g, e)| (g, e))
    }

    /// Marks `g` cut and opens the groups that waited only for it.
    fn finish(&mut self, g: usize) {
        if self.pending[g] == 0 {
            self.ready -= 1;
        }
        self.done[g] = true;
        self.left -= 1;
        self.stray.remove(&g);
        // Read once: g is cut for good.
        for h in std::mem::take(&mut self.waiting[g]) {
            self.pending[h] -= 1;
            if self.pending[h] == 0 {
                self.open(h);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The choice by a scan of every group at every step (how the order
    /// was made before): the reference, ties included.
    fn scanned(
        entries: &[Vec<Entry>],
        after: &[Vec<usize>],
        depth: &[usize],
    ) -> Vec<(usize, usize)> {
        let n = entries.len();
        let mut done = vec![false; n];
        let mut at = Point::new(0.0, 0.0);
        let mut out = Vec::new();
        loop {
            let ready = |g: usize| {
                !done[g]
                    && !entries[g].is_empty()
                    && after
                        .get(g)
                        .is_none_or(|a| a.iter().all(|&b| b >= n || b == g || done[b]))
            };
            let any_ready = (0..n).any(ready);
            let deepest = (0..n)
                .filter(|&g| !done[g] && !entries[g].is_empty())
                .map(|g| depth.get(g).copied().unwrap_or(0))
                .max()
                .unwrap_or(0);
            let fallback = |g: usize| !done[g] && depth.get(g).copied().unwrap_or(0) == deepest;
            let mut best: Option<(f64, usize, usize)> = None;
            for g in (0..n).filter(|&g| if any_ready { ready(g) } else { fallback(g) }) {
                for (k, e) in entries[g].iter().enumerate() {
                    let score = at.dist(e.start) - e.saved;
                    if best.is_none_or(|b| score < b.0) {
                        best = Some((score, g, k));
                    }
                }
            }
            let Some((_, g, k)) = best else { break };
            done[g] = true;
            at = entries[g][k].start;
            out.push((g, k));
        }
        out
    }

    fn way(x: f64, y: f64, saved: f64, k: usize) -> Entry {
        Entry {
            start: Point::new(x, y),
            saved,
            reversed: false,
            k,
            drop: saved > 0.0,
        }
    }

    #[test]
    fn the_same_choices_as_a_scan_ties_and_cycles_included() {
        let mut f = crate::test_rng::unit(0x2545_F491_4F6C_DD1Du64);
        for (n, grid) in [
            (1, false),
            (30, true),
            (300, true),
            (300, false),
            (2000, true),
        ] {
            // On a grid of whole millimetres many ways in are equally far.
            let at = |f: &mut dyn FnMut() -> f64| {
                let (a, b) = (f() * 400.0, f() * 200.0);
                if grid {
                    (a.round(), b.round())
                } else {
                    (a, b)
                }
            };
            let mut entries = Vec::new();
            let mut after = Vec::new();
            let mut depth = Vec::new();
            for g in 0..n {
                let ways = (f() * 5.0) as usize; // some groups have none
                let mut w = Vec::new();
                for k in 0..ways {
                    let (a, b) = at(&mut f);
                    let saved = if f() < 0.3 { (f() * 40.0).round() } else { 0.0 };
                    w.push(way(a, b, saved, k));
                }
                entries.push(w);
                // Links to earlier groups mostly, a few later ones (cycles),
                // some out of range or to itself.
                let mut a = Vec::new();
                for _ in 0..(f() * 3.0) as usize {
                    let t = f();
                    a.push(if t < 0.8 && g > 0 {
                        (f() * g as f64) as usize
                    } else if t < 0.9 {
                        (f() * n as f64) as usize
                    } else if t < 0.95 {
                        g
                    } else {
                        n + 3
                    });
                }
                after.push(a);
                depth.push((f() * 3.0) as usize);
            }
            let want = scanned(&entries, &after, &depth);
            let mut next = Next::new(&entries, &after, &depth);
            let mut got = Vec::new();
            let mut here = Point::new(0.0, 0.0);
            while let Some((g, e)) = next.take(here) {
                got.push((g, e.k));
                here = e.start;
            }
            assert_eq!(got, want, "n {n} grid {grid}");
        }
    }

    #[test]
    fn every_group_is_taken_even_from_nowhere() {
        let entries = vec![
            vec![way(1.0, 1.0, 0.0, 0)],
            vec![way(5.0, 1.0, 2.0, 0), way(f64::NAN, 0.0, 0.0, 1)],
            vec![way(f64::INFINITY, 0.0, 0.0, 0)],
        ];
        let after = vec![vec![], vec![0], vec![]];
        let mut next = Next::new(&entries, &after, &[]);
        let mut got = Vec::new();
        while let Some((g, _)) = next.take(Point::new(f64::NAN, 0.0)) {
            got.push(g);
        }
        got.sort_unstable();
        assert_eq!(got, vec![0, 1, 2]);
    }
}
