//! A short list kept on the stack: the exact test builds a few lists
//! (edges and vertices near the other shape, cuts along an edge) for
//! every pair of shapes it is asked about, mostly of a handful of
//! entries; on the heap, their allocation and release were a tenth of
//! the test's time (perf, jakobs1). Past `N` entries the list moves to
//! the heap, so a shape of any size is still answered.

/// Up to `N` entries inline, then on the heap; one contiguous slice
/// either way.
pub(super) struct Few<T: Copy + Default, const N: usize> {
    inline: [T; N],
    len: usize,
    /// Every entry once there were more than `N` (empty before).
    heap: Vec<T>,
}

impl<T: Copy + Default, const N: usize> Few<T, N> {
    /// Empty.
    #[inline]
    pub fn new() -> Self {
        Few {
            inline: [T::default(); N],
            len: 0,
            heap: Vec::new(),
        }
    }
    /// The entries of `it`, in order.
    #[cfg(test)]
    pub fn of(it: impl Iterator<Item = T>) -> Self {
        let mut f = Few::new();
        for v in it {
            f.push(v);
        }
        f
    }
    /// Adds `v` at the end.
    #[inline]
    pub fn push(&mut self, v: T) {
        // (`len` stays at `N` once the entries are on the heap.)
        if self.len < N {
            self.inline[self.len] = v;
            self.len += 1;
        } else {
            if self.heap.is_empty() {
                self.heap.extend_from_slice(&self.inline[..self.len]);
            }
            self.heap.push(v);
        }
    }
    /// Empties the list.
    #[inline]
    pub fn clear(&mut self) {
        self.len = 0;
        self.heap.clear();
    }
    /// The entries.
    #[inline]
    pub fn as_slice(&self) -> &[T] {
        if self.heap.is_empty() {
            &self.inline[..self.len]
        } else {
            &self.heap
        }
    }
    /// The entries, to sort in place.
    #[inline]
    pub fn as_mut_slice(&mut self) -> &mut [T] {
        if self.heap.is_empty() {
            &mut self.inline[..self.len]
        } else {
            &mut self.heap
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Few;

    #[test]
    fn keeps_every_entry_in_order_past_its_inline_room() {
        for n in [0, 1, 3, 4, 5, 40] {
            let mut f: Few<u32, 4> = Few::of(0..n);
            assert_eq!(f.as_slice(), (0..n).collect::<Vec<_>>().as_slice());
            f.as_mut_slice().reverse();
            assert_eq!(f.as_slice(), (0..n).rev().collect::<Vec<_>>().as_slice());
            f.clear();
            assert!(f.as_slice().is_empty());
            f.push(7);
            assert_eq!(f.as_slice(), &[7]);
        }
    }
}
