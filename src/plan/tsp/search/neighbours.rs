//! The local search's neighbour lists ([`Neighbours`]), filled by
//! `Path::rebuild_neighbours`.

use super::super::grid::Grid;
use super::super::Inst;
use super::NEIGHBOURS;
use crate::geom::Point;
use crate::par::{map_ranges, Threads};
use std::ops::Range;

/// Fewest sites a thread lists the neighbours of (a query is ~0.25 us).
const CHUNK: usize = 8192;

/// Neighbour lists, [`NEIGHBOURS`] + 1 slots a site in one array, nearest
/// first (a vector a site lay wherever the heap had room: a cache miss for
/// nearly every list the local search read on a 137k-contour sheet). Site
/// numbers as `u32`: half the bytes of `usize`, and on a 137k-site sheet
/// the array's fresh pages (12 MB as `usize`, each zeroed by the kernel on
/// first touch) were a third of the lists' build time (perf).
#[derive(Default)]
pub(in super::super) struct Neighbours {
    items: Vec<u32>,
    len: Vec<u8>,
}

/// Slots a site: the k-nearest query asks for one more than
/// [`NEIGHBOURS`] (the site itself skipped).
const SLOTS: usize = NEIGHBOURS + 1;

impl Neighbours {
    /// Empty lists for `n` sites.
    pub(super) fn reset(&mut self, n: usize) {
        self.items.clear();
        self.items.resize(n * SLOTS, 0);
        self.len.clear();
        self.len.resize(n, 0);
    }

    /// How many sites have a list (0 before the first build).
    pub(in super::super) fn len(&self) -> usize {
        self.len.len()
    }

    /// The lists of `seq`'s sites (of `n`), entered at `pts` (by
    /// position): each site's [`NEIGHBOURS`] nearest by entry point. Each
    /// list is its own query: on several threads, ranges of positions each
    /// list theirs and the lists are stored in order (the same lists with
    /// any number of threads; ~35 ms on the 25 MB nest).
    pub(super) fn build(&mut self, seq: &[usize], pts: &[Point], n: usize, threads: Threads) {
        let queries = Queries::new(seq, pts);
        self.reset(n);
        if threads.get() == 1 || seq.len() < 2 * CHUNK {
            self.fill(&queries);
            return;
        }
        let parts = map_ranges(seq.len(), threads, CHUNK, |r| queries.run(r));
        self.store(seq, parts);
    }

    /// Every list of `queries`, on the calling thread.
    fn fill(&mut self, queries: &Queries) {
        let mut found = Vec::with_capacity(SLOTS + 1);
        for (i, &s) in queries.seq.iter().enumerate() {
            queries.query(i, &mut found);
            self.set(
                s,
                found.iter().map(|&(_, k)| queries.seq[k as usize] as u32),
            );
        }
    }

    /// Stores the lists of [`Queries::run`] on consecutive ranges from 0.
    fn store(&mut self, seq: &[usize], parts: Vec<(Vec<u8>, Vec<u32>)>) {
        let mut i = 0;
        for (lens, ids) in parts {
            let mut at = 0;
            for len in lens {
                let len = usize::from(len);
                self.set(seq[i], ids[at..at + len].iter().copied());
                at += len;
                i += 1;
            }
        }
    }

    /// The lists of the short schedule ([`super::super::Effort::short`]):
    /// each visitable site's [`NEIGHBOURS`] nearest by the centre of its
    /// candidates' disc, not by its entry point, on the threads as
    /// [`Neighbours::build`] (the same lists with any number). They
    /// depend on the instance only: made before the first entry
    /// re-choice. Tours against lists by entry point (benches/tsp.rs,
    /// tenth pass): 60k sites -0.42 % grid, +0.13 % random; the 4/11/25
    /// MB sheets -0.11, -0.04, -0.02 %.
    pub(in super::super) fn of_centres(inst: &Inst, threads: Threads) -> Neighbours {
        let pts: Vec<Point> = inst.active.iter().map(|&s| inst.disc[s].0).collect();
        let mut lists = Neighbours::default();
        lists.build(&inst.active, &pts, inst.pts.len(), threads);
        lists
    }

    /// Sets site `s`'s list (at most [`SLOTS`] items).
    pub(super) fn set(&mut self, s: usize, list: impl Iterator<Item = u32>) {
        let base = s * SLOTS;
        let mut k = 0;
        for (slot, x) in self.items[base..base + SLOTS].iter_mut().zip(list) {
            *slot = x;
            k += 1;
        }
        self.len[s] = k as u8;
    }
}

/// One build's k-nearest queries: the points by position and their grid.
struct Queries<'a> {
    seq: &'a [usize],
    pts: &'a [Point],
    grid: Grid,
}

impl<'a> Queries<'a> {
    fn new(seq: &'a [usize], pts: &'a [Point]) -> Queries<'a> {
        // Three points a cell: the 11th nearest then lies ~1.1 cells
        // away, mostly within the first ring around the query's cell, where
        // at two a cell (~1.3 cells) the second ring was scanned too (a grid sheet's lists
        // 35 -> 30 ms on one thread; the same lists, the grid only decides
        // where to look).
        let mut grid = Grid::new(pts, 3.0);
        for i in 0..pts.len() {
            grid.insert_nth(i);
        }
        Queries { seq, pts, grid }
    }

    /// The [`SLOTS`] nearest of position `i` (itself skipped), nearest first.
    fn query(&self, i: usize, found: &mut Vec<(f64, u32)>) {
        self.grid.k_nearest_into(
            self.pts[i],
            SLOTS,
            |k| self.pts[k as usize],
            |k| k as usize == i,
            found,
        );
    }

    /// The lists of positions `r`: each one's length, and the sites of
    /// all of them one after the other.
    fn run(&self, r: Range<usize>) -> (Vec<u8>, Vec<u32>) {
        let mut found = Vec::with_capacity(SLOTS + 1);
        let mut lens = Vec::with_capacity(r.len());
        let mut ids = Vec::with_capacity(r.len() * SLOTS);
        for i in r {
            self.query(i, &mut found);
            lens.push(found.len() as u8);
            ids.extend(found.iter().map(|&(_, k)| self.seq[k as usize] as u32));
        }
        (lens, ids)
    }
}

impl std::ops::Index<usize> for Neighbours {
    type Output = [u32];
    #[inline]
    fn index(&self, s: usize) -> &[u32] {
        let base = s * SLOTS;
        &self.items[base..base + usize::from(self.len[s])]
    }
}
