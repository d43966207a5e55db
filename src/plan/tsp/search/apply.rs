//! Applying the moves [`Path::find`] returns: the sequence rearranged,
//! positions and length kept up to date, and the sites whose tour
//! neighbours changed queued for the local search.

use super::moves::Move;
use super::Path;

impl Path<'_> {
    /// Tries the moves around site `s` and applies the first gain; true
    /// if one was found.
    pub(super) fn improve_site(&mut self, s: usize) -> bool {
        let mut units = std::mem::take(&mut self.units);
        let found = self.find(s, &mut units);
        self.units = units;
        match found {
            Some(m) => {
                self.apply(m);
                true
            }
            None => false,
        }
    }

    /// Applies a move [`Path::find`] returned for the path as it is (a
    /// [`Move::Units`] with its units still in `self.units`), and queues
    /// the sites whose tour neighbours it changed.
    pub(super) fn apply(&mut self, m: Move) {
        match m {
            Move::Reverse { i, j, delta } => {
                self.seq[i..=j].reverse();
                self.touch(i, j);
                self.len += delta;
                for t in [i.wrapping_sub(1), i, j, j + 1] {
                    self.push_pos(t);
                }
            }
            Move::Units { i, j, delta } => {
                let mut out = Vec::with_capacity(j + 1 - i);
                for &(x, y) in self.units.iter().rev() {
                    out.extend_from_slice(&self.seq[x..=y]);
                }
                self.seq[i..=j].copy_from_slice(&out);
                self.touch(i, j);
                self.len += delta;
                for t in [i.wrapping_sub(1), i, j, j + 1] {
                    self.push_pos(t);
                }
            }
            Move::Shift {
                i,
                j,
                g,
                rev,
                entry,
                delta,
            } => {
                let f = self.seq[i];
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
                self.cur[f] = self.inst.pts[f][entry];
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
            }
            Move::Exchange { i, j, k, delta } => {
                self.seq[i..=k].rotate_left(j + 1 - i);
                self.touch(i, k);
                self.len += delta;
                let c_len = k - j;
                for t in [i.wrapping_sub(1), i, i + c_len - 1, i + c_len, k, k + 1] {
                    self.push_pos(t);
                }
            }
        }
    }
}
