//! Fixed sheets to the last one (issue 44 item 3): every sheet shortened
//! in turn, and copies of the last sheet moved into the room that frees
//! on the others.
//!
//! The first nest fills sheets in order (first fit), each packed by the
//! constructive placer; the exploration shortened the last sheet only.
//! Measured against the strip of the same parts at equal evaluations
//! (scripts/bench-nest-sheets.sh), what that leaves is the room the
//! placer could not use on the full sheets. So the exploration takes the
//! sheets in turn ([`TURN`] tries each; the last sheet every other turn,
//! the earlier ones round the others): an earlier sheet shortened by the
//! same cut-and-separate as the strip keeps its copies to the left, and
//! the band it frees at its right end is offered to the copies of the
//! last sheet, rightmost first, by the constructive placer ([`Improver::pull`]).
//! The last sheet loses copies and never gains length; when it loses its
//! last copy the nest has a sheet fewer. A copy holding others in its
//! holes carries them along, at its own turn.

use super::sample::Layout;
use super::{explore, feasible, hosts_of, layout, separate, Improver, CUT, NO_GAIN};
use crate::geom::Point;
use crate::nest::decode::{At, Decoded};
use crate::nest::place::{range_of, Placed};
use crate::nest::rng::SplitMix;

/// Tries on one sheet before the exploration turns to another.
pub(super) const TURN: usize = 10;
/// Candidates of the placer for a copy pulled onto an earlier sheet
/// (the decoder's for a sheet).
const PULL_CANDIDATES: usize = 20_000;

impl Improver {
    /// On fixed sheets, the sheet to shorten next once this one's turn is
    /// over: the last every other turn (twice as long), the earlier ones in
    /// turn between.
    /// Nothing changes for a strip (one sheet).
    pub(super) fn next_turn(&mut self) {
        let last = self.best.bins.len().saturating_sub(1);
        if last == 0 {
            return;
        }
        if self.turn_left > 0 && self.b <= last {
            self.turn_left -= 1;
            return;
        }
        if self.b <= last {
            self.cuts[self.b] = self.cut;
        }
        let next = if self.b >= last {
            let k = self.next_early % last;
            self.next_early += 1;
            k
        } else {
            last
        };
        self.focus(next);
        // The last sheet's length is the objective: twice the tries.
        self.turn_left = if next == last { 2 * TURN - 1 } else { TURN - 1 };
    }

    /// The exploration turned to sheet `k`: its layout, cut and pool.
    pub(super) fn focus(&mut self, k: usize) {
        self.b = k;
        self.cuts.resize(self.best.bins.len().max(k + 1), CUT);
        self.cut = self.cuts[k];
        self.lay = layout(&self.best, k);
        self.large = explore::large_copies(&self.kit, &self.lay.pieces);
        self.work = self.lay.clone();
        self.pool.clear();
        self.tries = 0;
    }

    /// After sheet `self.b` (not the last) was shortened: each copy of
    /// the last sheet, rightmost first, placed on it by the constructive
    /// placer if it finds room (one evaluation each). Returns whether a
    /// copy moved.
    pub(super) fn pull(&mut self, budget: &mut super::Budget) -> bool {
        let k = self.b;
        let last = self.best.bins.len() - 1;
        if k >= last {
            return false;
        }
        let eps = self.kit.eps;
        let mut moved = false;
        let mut by_right: Vec<usize> = (0..self.best.bins[last].placed.len()).collect();
        let right = |d: &Decoded, i: usize| d.bins[last].placed[i].shape.bbox().max.x;
        by_right.sort_by(|&i, &j| {
            right(&self.best, j)
                .total_cmp(&right(&self.best, i))
                .then(i.cmp(&j))
        });
        let roots = hosts_of(&self.best);
        for i in by_right {
            if !budget() {
                break;
            }
            let p = &self.best.bins[last].placed[i];
            // A host keeps its turn (its holes' rooms are of that turn).
            let hosts = roots.iter().any(|&(r, _)| r == (last, i));
            let only = hosts.then_some(p.variant);
            let item = p.item;
            let to = &mut self.best.bins[k];
            if to.place_as(
                item,
                &self.kit.items[item].variants,
                only,
                eps,
                PULL_CANDIDATES,
            ) {
                let q = to.placed.pop().expect("just placed");
                to.right = to.right.max(q.shape.bbox().max.x);
                let from = self.best.bins[last].placed[i].t;
                let mut best = std::mem::replace(&mut self.best, Decoded::empty());
                best = move_copy(best, (last, i), k, q.t.sub(from), q);
                self.best = best;
                moved = true;
                // The indices of the last sheet shifted: stop here, the
                // next shortening pulls again.
                break;
            }
        }
        if moved {
            self.settle_last();
            self.lay = layout(&self.best, k);
        }
        moved
    }

    /// True when the area bound says the last sheet's copies may all fit
    /// in the room the earlier sheets leave (their boxes less the copies'
    /// areas): then dropping it is worth separations ([`Improver::insert`]).
    pub(super) fn may_drop_last(&self) -> bool {
        let bins = &self.best.bins;
        let Some((last, earlier)) = bins.split_last() else {
            return false;
        };
        let area = |b: &crate::nest::place::Bin| -> f64 {
            b.placed.iter().map(|p| p.shape.poly.area().abs()).sum()
        };
        let room: f64 = earlier
            .iter()
            .map(|b| {
                let c = b.container;
                (c.x1 - c.x0) * (c.y1 - c.y0) - area(b)
            })
            .sum();
        !earlier.is_empty() && area(last) <= room
    }

    /// A copy of the last sheet (the rightmost more often: rank by u²)
    /// dropped anywhere on sheet `self.b` (an earlier one) and separated
    /// from its new neighbours in the sheet's full room; kept when
    /// nothing overlaps by the exact test. Returns whether it moved.
    pub(super) fn insert(&mut self, rng: &mut SplitMix, budget: &mut super::Budget) -> bool {
        let k = self.b;
        let last = self.best.bins.len() - 1;
        let n = self.best.bins[last].placed.len();
        if k >= last || n == 0 {
            return false;
        }
        let to = &self.best.bins[k];
        if to.bound.is_some() || !to.obstacles.is_empty() {
            return false;
        }
        let right = |i: usize| self.best.bins[last].placed[i].shape.bbox().max.x;
        let mut by_right: Vec<usize> = (0..n).collect();
        by_right.sort_by(|&i, &j| right(j).total_cmp(&right(i)).then(i.cmp(&j)));
        let u = unit(rng);
        let i = by_right[(((u * u) * n as f64) as usize).min(n - 1)];
        let roots = hosts_of(&self.best);
        let hosts = roots.iter().any(|&(r, _)| r == (last, i));
        let mut lay = layout(&self.best, k);
        lay.room = to.container;
        let p = &self.best.bins[last].placed[i];
        let bb = *p.shape.bbox();
        let r = lay.room;
        if bb.max.x - bb.min.x > r.x1 - r.x0 || bb.max.y - bb.min.y > r.y1 - r.y0 {
            return false;
        }
        let (lo, hi) = range_of(&r, &bb);
        let d = Point::new(
            lo.x + unit(rng) * (hi.x - lo.x),
            lo.y + unit(rng) * (hi.y - lo.y),
        );
        let placed = Placed {
            item: p.item,
            variant: p.variant,
            t: p.t.add(d),
            shape: p.shape.moved(d),
        };
        lay.pieces.push(super::sample::Piece {
            item: placed.item,
            variant: placed.variant,
            t: placed.t,
            shape: placed.shape.clone(),
            turn: !hosts,
        });
        let (separated, _) = separate(&mut self.kit, &mut lay, rng, budget, NO_GAIN);
        if !(separated && feasible(&self.kit, &lay)) {
            return false;
        }
        // The copy moved where it was dropped, then the sheet as separated.
        let mut best = std::mem::replace(&mut self.best, Decoded::empty());
        best = move_copy(best, (last, i), k, d, placed);
        self.best = super::decoded(best, k, &lay, self.origin_x);
        self.settle_last();
        self.lay = layout(&self.best, k);
        self.work = self.lay.clone();
        true
    }

    /// The last sheet after it lost copies: its length, or gone; the cost.
    fn settle_last(&mut self) {
        let best = &mut self.best;
        let last = best.bins.len() - 1;
        let l = &mut best.bins[last];
        l.right = l
            .placed
            .iter()
            .map(|p| p.shape.bbox().max.x)
            .fold(l.container.x0, f64::max);
        if l.placed.is_empty() {
            best.bins.pop();
            self.cuts.truncate(best.bins.len());
        }
        let x0 = self.origin_x;
        best.cost.1 = best.bins.len();
        if let Some(l) = best.bins.last() {
            best.cost.2 = l.right - x0;
            best.gravity = l
                .placed
                .iter()
                .map(|p| (p.shape.bbox().max.x - x0).powi(2))
                .sum();
        }
    }

    /// The layouts of the sheets other than the one shortened, for
    /// [`super::sample::Kit::compact`] (variants gained by free turns
    /// there are kept): none for a strip or when no part turns freely.
    pub(super) fn other_layouts(&self) -> Vec<(usize, Layout)> {
        if self.kit.free.iter().any(|&f| f) {
            (0..self.best.bins.len())
                .filter(|&k| k != self.b)
                .map(|k| (k, layout(&self.best, k)))
                .collect()
        } else {
            Vec::new()
        }
    }
}

/// `d` with copy `i` of sheet `b` moved to the end of sheet `k` as `to`
/// (`dt` from where it was, same turn when it hosts others): the rooms
/// of its holes, and the copies in them, go along.
fn move_copy(mut d: Decoded, (b, i): (usize, usize), k: usize, dt: Point, to: Placed) -> Decoded {
    let roots = hosts_of(&d);
    let at = d.bins[k].placed.len();
    for (h, &(root, _)) in d.holes.iter_mut().zip(&roots) {
        if root == (b, i) {
            h.sheet = k;
            for g in &mut h.bin.placed {
                g.t = g.t.add(dt);
                g.shape = g.shape.moved(dt);
            }
            if let Some(bound) = &mut h.bin.bound {
                *bound = bound.moved(dt);
            }
        }
        h.host = match h.host {
            At::Sheet(s, j) if s == b && j == i => At::Sheet(k, at),
            At::Sheet(s, j) if s == b && j > i => At::Sheet(s, j - 1),
            other => other,
        };
    }
    d.bins[b].placed.remove(i);
    d.bins[k].placed.push(to);
    d
}

fn unit(rng: &mut SplitMix) -> f64 {
    (rng.next() >> 11) as f64 / (1u64 << 53) as f64
}
