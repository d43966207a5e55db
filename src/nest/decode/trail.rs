//! The decoder's record of how an order was placed, position by position
//! ([`Trail`]): what lets an order that shares its start with one decoded
//! before be decoded from where that one stood ([`super::decode_after`]).

use super::{Decoded, HoleBin, Order};
use crate::nest::place::Bin;

/// (Item, turn held to): what a room refuses.
pub(super) type Key = (usize, Option<usize>);

/// One room's changes (a sheet bin's or a hole's), each with the position
/// in the order whose copy made it: the room as it stood after any
/// earlier position is had back by cutting these lists there
/// ([`Trail::rooms_after`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Log {
    /// The position whose copy opened the room (the first copy on a
    /// sheet, the host of a hole).
    pub(super) born: usize,
    /// The position of each copy placed in it, in order.
    pub(super) placed: Vec<usize>,
    /// What it refused, and at which position: a room only fills up, so
    /// the next copy of that item is not tried there again. Every copy
    /// tried every hole of the sheet before: 200 copies of corpus parts
    /// with 130 holes among them took 50 s of checks inside holes for
    /// one nest.
    pub(super) refused: Vec<(Key, usize)>,
    /// Its work ([`Bin::work`]) after each position it was tried at.
    pub(super) work: Vec<(usize, u64)>,
}

impl Log {
    pub(super) fn born(k: usize) -> Log {
        Log {
            born: k,
            ..Log::default()
        }
    }

    /// Tries the copy at position `k` in `bin` (this log's room) unless
    /// the room refused its item before; true when placed.
    pub(super) fn try_place(
        &mut self,
        bin: &mut Bin,
        k: usize,
        key: Key,
        place: impl FnOnce(&mut Bin) -> bool,
    ) -> bool {
        if self.refused.iter().any(|r| r.0 == key) {
            return false;
        }
        let ok = place(bin);
        self.work.push((k, bin.work));
        if ok {
            self.placed.push(k);
        } else {
            self.refused.push((key, k));
        }
        ok
    }

    /// `bin` (this log's room) as it stood after the positions before
    /// `k`, and its log then.
    fn cut(&self, bin: &Bin, k: usize) -> (Bin, Log) {
        let m = self.placed.partition_point(|&p| p < k);
        let w = self.work.partition_point(|&(p, _)| p < k);
        let r = self.refused.partition_point(|&(_, p)| p < k);
        let work = w.checked_sub(1).map_or(0, |i| self.work[i].1);
        let log = Log {
            born: self.born,
            placed: self.placed[..m].to_vec(),
            refused: self.refused[..r].to_vec(),
            work: self.work[..w].to_vec(),
        };
        (bin.first(m, work), log)
    }
}

/// Every room's log, and the position of each copy not placed.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Logs {
    pub(super) bins: Vec<Log>,
    pub(super) holes: Vec<Log>,
    pub(super) unplaced: Vec<usize>,
}

/// The decoder's rooms after some positions of an order, and their logs.
#[derive(Default)]
pub(super) struct Rooms {
    pub(super) bins: Vec<Bin>,
    pub(super) holes: Vec<HoleBin>,
    pub(super) unplaced: Vec<usize>,
    pub(super) logs: Logs,
}

/// A decoded order and how it was placed, position by position: an order
/// that shares its first k copies with it (the sequence search's swaps,
/// moves and turns at k change nothing before k) places those k the
/// same, so it is decoded from there ([`decode_after`]). Kept: each room's
/// log of positions beside the nest itself, a few numbers a copy.
#[derive(Clone)]
pub(in crate::nest) struct Trail {
    /// The nest.
    pub(in crate::nest) nest: Decoded,
    pub(super) order: Order,
    /// Positions decoded (the first nest may stop before the end).
    pub(super) done: usize,
    pub(super) logs: Logs,
}

impl Trail {
    /// The order decoded.
    pub(in crate::nest) fn order(&self) -> &[(usize, Option<usize>)] {
        &self.order
    }

    /// The rooms as they stood after the first `k` positions (k ≤
    /// `done`): the bins and holes opened by then, each with the copies
    /// placed in it by then.
    pub(super) fn rooms_after(&self, k: usize) -> Rooms {
        let mut rooms = Rooms::default();
        let n = &self.nest;
        for (b, log) in n.bins.iter().zip(&self.logs.bins) {
            if log.born >= k {
                break;
            }
            let (bin, log) = log.cut(b, k);
            rooms.bins.push(bin);
            rooms.logs.bins.push(log);
        }
        for (h, log) in n.holes.iter().zip(&self.logs.holes) {
            if log.born >= k {
                break;
            }
            let (bin, log) = log.cut(&h.bin, k);
            rooms.holes.push(HoleBin {
                bin,
                sheet: h.sheet,
                host: h.host,
            });
            rooms.logs.holes.push(log);
        }
        for (&it, &p) in n.unplaced.iter().zip(&self.logs.unplaced) {
            if p >= k {
                break;
            }
            rooms.unplaced.push(it);
            rooms.logs.unplaced.push(p);
        }
        rooms
    }
}
