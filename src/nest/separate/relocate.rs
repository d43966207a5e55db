//! Fixed sheets: copies of the last sheet moved into the gaps of earlier
//! ones by the constructive placer (issue 44 item 3, "fewest sheets, then
//! the shortest last sheet, then the best utilisation of the others").
//!
//! The bays' exploration ([`super::bays`]) shortens the sheets as one
//! strip: a copy reaches an earlier sheet only when the separation moves
//! it there, by a sampled position, which seldom lands in a gap barely
//! larger than the copy. The first nests of boxes and keyboard plates left
//! gaps of a whole part on their full sheets (10 000 evaluations, seed 1:
//! four sheets at 1.19 × the strip). Here the placer (bottom-left fill,
//! its touching positions found from the copies' vertices and boxes) is
//! asked, for the copies of the last sheet furthest right, whether an
//! earlier sheet has room: a copy moved is a last sheet no longer (and
//! often shorter), and its room there left for the exploration.
//!
//! Tried once for every new best nest, a placer call an evaluation; what
//! the placer takes is checked again by the exact test ([`super::feasible`]).
//!
//! Then the loose copies, the last sheet's first, offered to the rooms
//! (holes) of the copies on every sheet, as the strip's are:
//! [`super::Improver::house`].

use super::sample::{Kit, Layout};
use crate::nest::decode::{Decoded, Item};
use crate::nest::place::{Bin, Placed};

/// The last sheet's copies tried, those furthest right first: they are
/// the ones whose move shortens the last sheet.
const MOST: usize = 4;
/// Candidates the placer tries, as the decoder's.
const CANDIDATES: usize = 20_000;

/// A copy of the last bay (index into `lay.pieces`) moved by the placer
/// into an earlier bay of `rooms`, when one has room for it: (piece,
/// variant, translation).
pub(super) fn into_earlier(
    kit: &Kit,
    lay: &Layout,
    rooms: &[crate::nest::place::Container],
    budget: &mut super::Budget,
) -> Option<(usize, usize, crate::geom::Point)> {
    let n = lay.pieces.len();
    let bay: Vec<usize> = (0..n).map(|k| lay.bay_of(k)).collect();
    let last = *bay.iter().max()?;
    let area = |k: usize| {
        kit.items[lay.pieces[k].item].variants[0]
            .shape
            .poly
            .area()
            .abs()
    };
    let mut free: Vec<f64> = rooms
        .iter()
        .map(|r| (r.x1 - r.x0) * (r.y1 - r.y0))
        .collect();
    for k in 0..n {
        free[bay[k]] -= area(k);
    }
    let mut mine: Vec<usize> = (0..n).filter(|&k| bay[k] == last).collect();
    let right = |k: usize| lay.pieces[k].shape.bbox().max.x;
    mine.sort_by(|&a, &b| right(b).total_cmp(&right(a)).then(a.cmp(&b)));
    for &k in mine.iter().take(MOST) {
        let p = &lay.pieces[k];
        let item: &Item = &kit.items[p.item];
        // A copy holding others in its holes keeps its turn.
        let (variants, only) = if p.turn {
            (&item.variants[..kit.base[p.item]], None)
        } else {
            (&item.variants[..], Some(p.variant))
        };
        for (j, room) in rooms.iter().enumerate().take(last) {
            if free[j] < area(k) {
                continue;
            }
            if !budget() {
                return None;
            }
            let mut bin = Bin::new(*room);
            bin.placed = (0..n)
                .filter(|&i| bay[i] == j)
                .map(|i| {
                    let q = &lay.pieces[i];
                    Placed {
                        item: q.item,
                        variant: q.variant,
                        t: q.t,
                        shape: q.shape.clone(),
                    }
                })
                .collect();
            bin.right = bin
                .placed
                .iter()
                .map(|q| q.shape.bbox().max.x)
                .fold(room.x0, f64::max);
            if bin.place_as(p.item, variants, only, kit.eps, CANDIDATES) {
                let q = bin.placed.last()?;
                return Some((k, q.variant, q.t));
            }
        }
    }
    None
}

impl super::Improver {
    /// Fixed sheets: a copy of the last sheet moved into an earlier one
    /// ([`into_earlier`]), the nest kept when the exact test agrees; when
    /// none moves, nothing is tried again until the best nest changes.
    /// Returns false when `found` cancelled.
    pub(super) fn relocate(
        &mut self,
        budget: &mut super::Budget,
        found: &mut dyn FnMut(&Decoded, &[Item]) -> bool,
    ) -> bool {
        self.settled = true;
        let Some(bays) = &self.bays else {
            return true;
        };
        let Some((k, v, t)) = into_earlier(&self.kit, &self.lay, bays.rooms(), budget) else {
            return true;
        };
        let mut work = self.lay.clone();
        let p = &mut work.pieces[k];
        p.variant = v;
        p.t = t;
        p.shape = self.kit.items[p.item].variants[v].shape.moved(t);
        if !super::feasible(&self.kit, &work) {
            return true;
        }
        let best = std::mem::replace(&mut self.best, Decoded::empty());
        self.take_moved(work, best, found)
    }
}
