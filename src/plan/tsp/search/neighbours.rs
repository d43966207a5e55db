//! The local search's neighbour lists ([`Neighbours`]), filled by
//! `Path::rebuild_neighbours`.

use super::super::grid::Grid;
use super::NEIGHBOURS;
use crate::geom::Point;
use crate::par::{map_ranges, Threads};

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
        let mut grid = Grid::new(pts, 2.0);
        for i in 0..pts.len() {
            grid.insert_nth(i);
        }
        let grid = &grid;
        let query = |i: usize, found: &mut Vec<(f64, u32)>| {
            grid.k_nearest_into(
                pts[i],
                NEIGHBOURS + 1,
                |k| pts[k as usize],
                |k| k as usize == i,
                found,
            );
        };
        let mut found = Vec::with_capacity(NEIGHBOURS + 2);
        self.reset(n);
        if threads.get() == 1 || seq.len() < 2 * CHUNK {
            for (i, &s) in seq.iter().enumerate() {
                query(i, &mut found);
                self.set(s, found.iter().map(|&(_, k)| seq[k as usize] as u32));
            }
            return;
        }
        let parts = map_ranges(seq.len(), threads, CHUNK, |r| {
            let mut found = Vec::with_capacity(NEIGHBOURS + 2);
            let mut lens = Vec::with_capacity(r.len());
            let mut ids = Vec::with_capacity(r.len() * (NEIGHBOURS + 1));
            for i in r {
                query(i, &mut found);
                lens.push(found.len());
                ids.extend(found.iter().map(|&(_, k)| seq[k as usize] as u32));
            }
            (lens, ids)
        });
        let mut i = 0;
        for (lens, ids) in parts {
            let mut at = 0;
            for len in lens {
                self.set(seq[i], ids[at..at + len].iter().copied());
                at += len;
                i += 1;
            }
        }
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

impl std::ops::Index<usize> for Neighbours {
    type Output = [u32];
    #[inline]
    fn index(&self, s: usize) -> &[u32] {
        let base = s * SLOTS;
        &self.items[base..base + usize::from(self.len[s])]
    }
}
