//! The local search's neighbour lists ([`Neighbours`]), filled by
//! `Path::rebuild_neighbours`.

use super::NEIGHBOURS;

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
