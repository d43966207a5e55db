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
//! (holes) of the copies on every sheet, as the strip's are
//! ([`super::rooms`]): [`super::Improver::house_on_sheets`].

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
        bays.close_empty(&mut work);
        work.room.x1 = super::length(&work);
        let best = std::mem::replace(&mut self.best, Decoded::empty());
        self.best = bays.decoded(best, &work, self.origin_x);
        bays.sort(&mut work);
        self.take_best(work, found)
    }
}

impl super::Improver {
    /// Fixed sheets: a loose copy moved into a room (a hole) of a copy on
    /// any sheet ([`super::rooms::find`]), the last sheet's copies first,
    /// then each earlier sheet's: a copy in a hole takes no sheet room, so
    /// the last sheet shortens or an earlier one frees room for its copies
    /// ([`Self::relocate`]). The strip does this in [`Self::house`]; the
    /// sheets did not, and the flanges' diamond plates kept their bores
    /// empty while their discs took a sheet of their own. When none moves,
    /// nothing is tried again until the best nest changes. Returns false
    /// when `found` cancelled.
    pub(super) fn house_on_sheets(
        &mut self,
        budget: &mut super::Budget,
        found: &mut dyn FnMut(&Decoded, &[Item]) -> bool,
    ) -> bool {
        self.housed = true;
        let Some(bays) = &self.bays else {
            return true;
        };
        let sheets: Vec<usize> = (0..self.best.bins.len()).collect();
        // Where each sheet's copies start in the layout (sheet by sheet).
        let mut first = Vec::with_capacity(sheets.len() + 1);
        first.push(0);
        for bin in &self.best.bins {
            first.push(first.last().copied().unwrap_or(0) + bin.placed.len());
        }
        let mut taken = None;
        for &b in sheets.iter().rev() {
            let mine = Layout {
                pieces: self.lay.pieces[first[b]..first[b + 1]].to_vec(),
                room: self.lay.room,
                bays: Vec::new(),
            };
            let h = super::rooms::find(
                &self.kit,
                &self.best,
                b,
                &sheets,
                &mine,
                &mut self.refused,
                budget,
            );
            if let Some(h) = h {
                taken = Some((b, h));
                break;
            }
        }
        let Some((b, h)) = taken else {
            return true;
        };
        if !super::rooms::housed(&self.best, &h, self.kit.eps) {
            return true;
        }
        let k = first[b] + h.piece;
        let mut best = std::mem::replace(&mut self.best, Decoded::empty());
        super::rooms::house(&mut best, b, h);
        let mut work = self.lay.clone();
        work.pieces.remove(k);
        // A host holds its guests at its turn.
        let hosts = super::hosts_of(&best);
        let at: Vec<(usize, usize)> = best
            .bins
            .iter()
            .enumerate()
            .flat_map(|(s, bin)| (0..bin.placed.len()).map(move |i| (s, i)))
            .collect();
        for (p, &si) in work.pieces.iter_mut().zip(&at) {
            p.turn = !hosts.iter().any(|&(r, n)| r == si && n > 0);
        }
        bays.close_empty(&mut work);
        work.room.x1 = super::length(&work);
        self.best = bays.decoded(best, &work, self.origin_x);
        bays.sort(&mut work);
        self.take_best(work, found)
    }
}
