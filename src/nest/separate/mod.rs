//! Shortening a feasible nest by overlap minimisation: sparrow's
//! exploration and compression (Gardeyn & Wauters, "An open-source
//! heuristic to reboot 2D nesting research", EJOR 2025, arXiv 2509.13329),
//! written for this engine.
//!
//! Exploration: take the best feasible nest, cut a slice out of its length
//! at a random place (the copies right of it slide left, copies now past
//! the end are pushed back in: they overlap), then *separate*: move one
//! overlapping copy at a time to the best of sampled positions
//! ([`sample`]), judging a position by the overlap proxy of [`overlap`]
//! weighted by guided local search, until nothing overlaps by the exact
//! test. Success: the shorter nest is the new best. Failure: the failed
//! layout joins a pool, and the next try at that length starts from one
//! of the pool's layouts with two large copies swapped ([`explore`],
//! sparrow's pool and disruption). After a few tries: back to the best,
//! with half the cut, down to 0.01 % of the
//! length: the small cuts at the end are the compression (sparrow's
//! compression steps decay to 0.001 %; at 0.1 % ours left the last few
//! tenths of a point: measured in scripts/bench-nest.sh). The cut shrinks
//! on failures, not on the clock (as sparrow's phases do): nothing here
//! reads a clock, so a run stopped after E moves is the run given E moves
//! (the page's Stop replays a run to the last evaluation it showed).
//!
//! Only the copies on the last sheet (or the strip) move, in a room that
//! is a rectangle (irregular remnants keep the constructive nest). A copy
//! holding others in its holes carries them along and keeps its turn.
//! A part free to turn takes any angle there ([`turn`]).
//! Feasibility is only ever decided by the exact test with the spacing
//! ([`crate::nest::collide`]), never by the proxy.

mod bays;
pub mod descend;
pub mod explore;
pub mod overlap;
pub mod poles;
mod relocate;
mod rooms;
pub mod sample;
pub mod turn;

use self::explore::Pool;
use self::overlap::Table;
use self::sample::{Kit, Layout, Piece};
use super::decode::{At, Decoded, Item};
use super::rng::SplitMix;
use crate::geom::{fmax, fmin, Point};

/// Passes without a lower total overlap before a strike (until stuck).
const NO_GAIN: usize = 40;
/// Strikes (restarts from the best of this separation) before giving up.
const STRIKES: usize = 3;
/// A run of passes that brings the least overlap below this share of
/// what it was when the run began is no strike: the count starts again
/// (sparrow's strike rule, Gardeyn & Wauters, EJOR 2025). Counting
/// every run as a strike gave up separations that were still converging:
/// jakobs1, seeds 1 and 3, stalled at 86.8–86.9 % of density where this
/// rule reaches 89.1 % (scripts/bench-nest.sh).
const STRIKE_GAIN: f64 = 0.98;
/// Exploration's cut, share of the length, and its least value.
const CUT: f64 = 0.01;
const LEAST_CUT: f64 = 0.0001;
/// Separations tried at one length before going back to the best: the
/// first from the best layout, the others from failed ones of the pool
/// (sparrow's exploration tries one length until it succeeds; here the
/// cut halves after these, as before the pool with 3 tries).
const TRIES: usize = 10;
/// The same on fixed sheets ([`bays`]): a failed try there costs
/// 1 100–4 500 moves, so at 10 000 evaluations ten of them at one length
/// were the rest of the budget, never a halved cut. With three, keyboard
/// plates seed 2 went from 6 sheets to 5 (scripts/bench-nest-sheets.sh).
const SHEET_TRIES: usize = 3;
/// Failed layouts kept at one length ([`explore::Pool`]).
const POOL: usize = 8;
/// Rounds of [`TRIES`] failed at the least cut before the search turns
/// persistent: the cut back to [`CUT`], [`PERSIST_TRIES`] tries a length
/// and [`PERSIST_NO_GAIN`] passes a strike. Measured at equal
/// evaluations (seed 1), persistence from the start gained 1–5 points on
/// jakobs2, marques and fu and lost 1.5–6 on blaz1 and jakobs1, which
/// find their best early with short separations: persistence only once
/// the short ones are stuck keeps both.
const STUCK: usize = 60;
const PERSIST_TRIES: usize = 10;
const PERSIST_NO_GAIN: usize = 200;

/// Asked before each move: false to stop now. Nothing here reads a clock,
/// so the moves made depend on the number of moves allowed only.
pub(super) type Budget<'a> = dyn FnMut() -> bool + 'a;

#[cfg(test)]
/// Shortens `best`'s last sheet for as long as `budget` lasts; `found` is
/// told of every shorter nest (and the items with the variants it uses)
/// and returns false to cancel. `free[i]`: item `i` may take any angle.
/// Returns the best nest and the items, with the variants gained by
/// copies turned freely ([`turn`]) appended after their own.
#[allow(clippy::too_many_arguments)]
pub(super) fn improve(
    items: &[Item],
    free: &[bool],
    best: Decoded,
    origin_x: f64,
    eps: f64,
    rng: &mut SplitMix,
    budget: &mut Budget,
    found: &mut dyn FnMut(&Decoded, &[Item]) -> bool,
) -> (Decoded, Vec<Item>) {
    let mut im = match Improver::new(items, free, best, origin_x, eps) {
        Ok(im) => im,
        Err(best) => return (*best, items.to_vec()),
    };
    while budget() {
        if !im.attempt(rng, budget, found) {
            break;
        }
    }
    im.into_parts()
}

/// Where the exploration stands between two tries ([`improve`] a try at
/// a time): the search holds it while it pauses to exchange its best
/// nest with other searches ([`crate::nest::team`]).
pub(super) struct Improver {
    kit: Kit,
    best: Decoded,
    /// The bin shortened (the last).
    b: usize,
    origin_x: f64,
    /// The best nest's copies of bin `b`.
    lay: Layout,
    large: Vec<usize>,
    pool: Pool,
    cut: f64,
    tries: usize,
    stuck: usize,
    persist: bool,
    work: Layout,
    /// Fixed sheets: every sheet a bay of one strip ([`bays`]); `lay`
    /// holds the copies of all of them.
    bays: Option<bays::Bays>,
    /// The tolerance asked (the kit's may be finer).
    eps: f64,
    /// Fixed sheets: the best nest's last sheet offered its copies to the
    /// earlier ones ([`relocate`]) and none moved.
    settled: bool,
    /// The best nest's loose copies offered to the rooms of placed
    /// copies ([`rooms`]; on fixed sheets, rooms on any sheet) and none
    /// moved.
    housed: bool,
    /// Rooms that refused a part ([`rooms::Refused`]).
    refused: rooms::Refused,
}

impl Improver {
    /// The exploration of `best`; `Err(best)` when its last sheet cannot
    /// be shortened here (an irregular room, obstacles, fewer than two
    /// copies).
    pub(super) fn new(
        items: &[Item],
        free: &[bool],
        best: Decoded,
        origin_x: f64,
        eps: f64,
    ) -> Result<Improver, Box<Decoded>> {
        let Some(b) = best.bins.len().checked_sub(1) else {
            return Err(Box::new(best));
        };
        let bays = bays::Bays::of(&best);
        let copies: usize = best.bins.iter().map(|b| b.placed.len()).sum();
        // One copy is no layout to shorten.
        if copies < 2
            || (bays.is_none()
                && (best.bins[b].bound.is_some() || !best.bins[b].obstacles.is_empty()))
        {
            return Err(Box::new(best));
        }
        // Fixed sheets: overlaps judged 100 times finer (bays.rs, BAYS_EPS).
        let fine = if bays.is_some() {
            eps * bays::BAYS_EPS
        } else {
            eps
        };
        let kit = Kit::new(items, free.to_vec(), fine);
        let lay = match &bays {
            Some(bays) => bays.layout(&best),
            None => layout(&best, b),
        };
        let large = explore::large_copies(&kit, &lay.pieces);
        Ok(Improver {
            kit,
            best,
            b,
            origin_x,
            work: lay.clone(),
            lay,
            large,
            pool: Pool::new(POOL),
            cut: CUT,
            tries: 0,
            stuck: 0,
            persist: false,
            bays,
            eps,
            settled: false,
            housed: false,
            refused: rooms::Refused::new(),
        })
    }

    /// The best nest and the items its copies refer to.
    pub(super) fn best(&self) -> (&Decoded, &[Item]) {
        (&self.best, &self.kit.items)
    }

    /// The best nest and its items, the exploration ended.
    pub(super) fn into_parts(self) -> (Decoded, Vec<Item>) {
        (self.best, self.kit.items)
    }

    /// The exploration of another best nest, this one's cut and
    /// persistence kept (they tell how far the search has gone, not where).
    pub(super) fn adopt(self, items: &[Item], best: Decoded) -> Result<Improver, Box<Decoded>> {
        let free = self.kit.free.clone();
        let mut im = Improver::new(items, &free, best, self.origin_x, self.eps)?;
        im.cut = self.cut;
        im.stuck = self.stuck;
        im.persist = self.persist;
        im.refused = self.refused;
        Ok(im)
    }

    /// One try at a shorter length (the caller asked `budget` first);
    /// false when `found` cancelled.
    pub(super) fn attempt(
        &mut self,
        rng: &mut SplitMix,
        budget: &mut Budget,
        found: &mut dyn FnMut(&Decoded, &[Item]) -> bool,
    ) -> bool {
        if self.bays.is_some() && !self.best.unplaced.is_empty() {
            return self.place_left_out(rng, budget, found);
        }
        if self.bays.is_some() && !self.settled {
            return self.relocate(budget, found);
        }
        if !self.housed {
            return self.house(budget, found);
        }
        let Improver {
            kit,
            best,
            b,
            lay,
            large,
            pool,
            cut,
            tries,
            stuck,
            persist,
            work,
            bays,
            ..
        } = self;
        let b = *b;
        let len = length(lay);
        let share = *cut;
        // A new length starts from the best layout; a length tried again
        // from a failed one of the pool, shaken (explore.rs).
        if *tries == 0 {
            *work = lay.clone();
        } else if let Some(from) = pool.pick(rng) {
            *work = from.clone();
            explore::swap_large(work, large, rng);
        }
        // Variants gained by free turns that neither the best layout nor
        // the ones tried or kept use any more are dropped (best's copies
        // are lay's).
        let mut lays: Vec<&mut Layout> = vec![&mut *lay, &mut *work];
        lays.extend(pool.layouts_mut());
        kit.compact(&mut lays);
        // (On fixed sheets `lay` lists every sheet's copies in turn.)
        let copies = match bays {
            Some(_) => &mut best.bins[..],
            None => &mut best.bins[b..=b],
        };
        let copies = copies.iter_mut().flat_map(|bin| bin.placed.iter_mut());
        for (p, q) in copies.zip(&lay.pieces) {
            p.variant = q.variant;
        }
        let target = len - share * (len - lay.room.x0);
        // Fixed sheets: every other try (by the draw) cuts the last sheet
        // only, the others the last two; see [`bays::Bays::x0_back`].
        let from = match bays {
            Some(bays) => bays.x0_back(len, rng.below(2)).min(target),
            None => work.room.x0,
        };
        shrink(work, target, from, rng);
        // The separator's word checked once more, pair by pair, by the
        // exact test: the nest kept is never the proxy's.
        let no_gain = if *persist { PERSIST_NO_GAIN } else { NO_GAIN };
        let (separated, least) = separate(kit, work, rng, budget, no_gain);
        if separated && feasible(kit, work) {
            let next = work.clone();
            let d = std::mem::replace(best, Decoded::empty());
            return self.take_moved(next, d, found);
        }
        *tries += 1;
        pool.add(least, work);
        let most = match (*persist, bays.is_some()) {
            (true, _) => PERSIST_TRIES,
            (false, true) => SHEET_TRIES,
            (false, false) => TRIES,
        };
        if *tries >= most {
            *tries = 0;
            pool.clear();
            if *cut <= LEAST_CUT {
                *stuck += 1;
            }
            *cut = (*cut * 0.5).max(LEAST_CUT);
        }
        if !*persist && *stuck >= STUCK {
            *persist = true;
            *cut = CUT;
        }
        true
    }

    /// `lay`, its copies moved outside a separation (into an earlier
    /// sheet, [`relocate`], or into a room, [`rooms`]), with `best` (the
    /// nest they were moved in) decoded from it and taken
    /// ([`Self::take_best`]): on fixed sheets a sheet emptied between two
    /// others closed and the copies listed sheet by sheet; the room closed
    /// at the used length.
    fn take_moved(
        &mut self,
        mut lay: Layout,
        best: Decoded,
        found: &mut dyn FnMut(&Decoded, &[Item]) -> bool,
    ) -> bool {
        if let Some(bays) = &self.bays {
            bays.close_empty(&mut lay);
        }
        lay.room.x1 = length(&lay);
        self.best = match &self.bays {
            Some(bays) => {
                let d = bays.decoded(best, &lay, self.origin_x);
                bays.sort(&mut lay);
                d
            }
            None => decoded(best, self.b, &lay, self.origin_x),
        };
        self.take_best(lay, found)
    }

    /// `lay` as the best layout, the new `best` already decoded from it:
    /// a separation that succeeded, or copies that changed places or order
    /// outside one (a copy moved into an earlier sheet, [`relocate`], or
    /// into a room, [`rooms`]). The search at that length starts afresh
    /// and every move is offered again. Returns what `found` says of the
    /// new best.
    fn take_best(&mut self, lay: Layout, found: &mut dyn FnMut(&Decoded, &[Item]) -> bool) -> bool {
        self.large = explore::large_copies(&self.kit, &lay.pieces);
        self.pool.clear();
        self.tries = 0;
        self.settled = false;
        self.housed = false;
        self.work = lay.clone();
        self.lay = lay;
        found(&self.best, &self.kit.items)
    }
}

/// The copies of bin `b` as a layout, its room closed at its used length.
fn layout(d: &Decoded, b: usize) -> Layout {
    let bin = &d.bins[b];
    let hosts = hosts_of(d);
    let pieces = bin
        .placed
        .iter()
        .enumerate()
        .map(|(i, p)| Piece {
            item: p.item,
            variant: p.variant,
            t: p.t,
            shape: p.shape.clone(),
            turn: !hosts.iter().any(|&(h, n)| h == (b, i) && n > 0),
        })
        .collect();
    let mut room = bin.container;
    room.x1 = fmin(room.x1, bin.right);
    Layout {
        pieces,
        room,
        bays: Vec::new(),
    }
}

/// For every hole bin, the sheet copy it is (maybe through other holes)
/// in, and how many copies it holds.
fn hosts_of(d: &Decoded) -> Vec<((usize, usize), usize)> {
    let mut root: Vec<(usize, usize)> = Vec::with_capacity(d.holes.len());
    for h in &d.holes {
        let r = match h.host {
            At::Sheet(b, i) => (b, i),
            At::Hole(j, _) => root[j],
        };
        root.push(r);
    }
    root.into_iter()
        .zip(d.holes.iter().map(|h| h.bin.placed.len()))
        .collect()
}

/// The right edge of the rightmost copy (the room's left when empty).
fn length(lay: &Layout) -> f64 {
    lay.pieces
        .iter()
        .map(|p| p.shape.bbox().max.x)
        .fold(lay.room.x0, f64::max)
}

/// Closes the room at `target`: a slice is cut at a random x between
/// `from` and `target`, copies right of it slide left by the slice, any
/// still past the end is pushed back in.
fn shrink(lay: &mut Layout, target: f64, from: f64, rng: &mut SplitMix) {
    let len = length(lay);
    let cut = len - target;
    let x = from + rng.unit() * (target - from);
    lay.room.x1 = target;
    for p in &mut lay.pieces {
        let b = *p.shape.bbox();
        let mut dx = if (b.min.x + b.max.x) / 2.0 > x {
            -cut
        } else {
            0.0
        };
        dx = dx.min(target - (b.max.x + dx)).min(0.0);
        dx = fmax(dx, lay.room.x0 - b.min.x);
        if dx != 0.0 {
            p.t.x += dx;
            p.shape = p.shape.moved(Point::new(dx, 0.0));
        }
    }
}

/// True when no two copies overlap by the exact test and all are in the room.
fn feasible(kit: &Kit, lay: &Layout) -> bool {
    let e = kit.eps;
    lay.pieces.iter().enumerate().all(|(i, p)| {
        !lay.outside(i, e)
            && lay.pieces[i + 1..]
                .iter()
                .all(|q| !crate::nest::collide::overlaps(&p.shape, &q.shape, e))
    })
}

/// Separates `lay` in place: (true, 0) when nothing overlaps any more
/// (then `lay` is feasible), else false with `lay` the least-overlapping
/// layout seen and its total overlap (the pool's rank); a run ends after `no_gain_most` passes without a lower total overlap,
/// and [`STRIKES`] runs in a row that cut it by less than 2 % end the
/// separation.
pub(super) fn separate(
    kit: &mut Kit,
    lay: &mut Layout,
    rng: &mut SplitMix,
    budget: &mut Budget,
    no_gain_most: usize,
) -> (bool, f64) {
    let n = lay.pieces.len();
    let mut table = Table::new(n);
    for k in 0..n {
        kit.refresh(lay, &mut table, k);
    }
    let mut best = (table.total(), lay.clone());
    if best.0 <= 0.0 && !(0..n).any(|k| kit.outside(lay, k)) {
        return (true, 0.0);
    }
    let mut order: Vec<usize> = Vec::with_capacity(n);
    let mut strikes = 0;
    while strikes < STRIKES {
        let at_start = best.0;
        let mut no_gain = 0;
        while no_gain < no_gain_most {
            order.clear();
            order.extend((0..n).filter(|&k| table.colliding(k) || kit.outside(lay, k)));
            for i in (1..order.len()).rev() {
                order.swap(i, rng.below(i + 1));
            }
            for &k in &order {
                if !budget() {
                    *lay = best.1;
                    return (false, best.0);
                }
                if table.colliding(k) || kit.outside(lay, k) {
                    kit.move_piece(lay, &mut table, k, rng);
                }
            }
            let total = table.total();
            if total <= 0.0 && !(0..n).any(|k| kit.outside(lay, k)) {
                return (true, 0.0);
            }
            if total < best.0 {
                best = (total, lay.clone());
                no_gain = 0;
            } else {
                no_gain += 1;
            }
            table.update_weights();
        }
        // A strike unless the run cut the least overlap by a share; then
        // back to the least overlap seen, weights kept.
        strikes = strikes_after(strikes, at_start, best.0);
        *lay = best.1.clone();
        for k in 0..n {
            kit.refresh(lay, &mut table, k);
        }
    }
    (false, best.0)
}

/// The strikes after a run of passes that took the least overlap from
/// `at_start` to `least`: none when it fell by [`STRIKE_GAIN`]'s share,
/// one more otherwise.
fn strikes_after(strikes: usize, at_start: f64, least: f64) -> usize {
    if least < STRIKE_GAIN * at_start {
        0
    } else {
        strikes + 1
    }
}

/// `d` with bin `b`'s copies where `lay` has them; the copies in their
/// holes moved along.
fn decoded(mut d: Decoded, b: usize, lay: &Layout, origin_x: f64) -> Decoded {
    let hosts = hosts_of(&d);
    for (i, p) in lay.pieces.iter().enumerate() {
        let old = &mut d.bins[b].placed[i];
        let dt = p.t.sub(old.t);
        old.variant = p.variant;
        old.t = p.t;
        old.shape = p.shape.clone();
        for (h, &(root, _)) in hosts.iter().enumerate() {
            if root == (b, i) {
                let bin = &mut d.holes[h].bin;
                for g in &mut bin.placed {
                    g.t = g.t.add(dt);
                    g.shape = g.shape.moved(dt);
                }
                if let Some(bound) = &mut bin.bound {
                    *bound = bound.moved(dt);
                }
            }
        }
    }
    let last = b + 1 == d.bins.len();
    let bin = &mut d.bins[b];
    bin.right = length(lay);
    if last {
        d.cost.2 = bin.right - origin_x;
        d.gravity = bin
            .placed
            .iter()
            .map(|p| (p.shape.bbox().max.x - origin_x).powi(2))
            .sum();
    }
    d
}

#[cfg(test)]
mod tests;
