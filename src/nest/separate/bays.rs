//! Fixed sheets shortened as one strip (issue 44 item 3): the sheets laid
//! side by side along x, each a *bay* of the strip that no copy may cross,
//! and the whole strip explored and compressed as a strip is (every other
//! cut in the last bay only, the others in the last two: [`Bays::x0_back`]).
//!
//! The strip's length is then (sheets − 1) × W + the last sheet's used
//! length (plus a constant per sheet for the margins), so shortening it is
//! the objective of a `--sheet` job: fewest sheets, then the shortest last
//! sheet, and the earlier sheets filled to make that possible (their gaps
//! also offered to the last sheet's copies by the placer:
//! [`super::relocate`]). Every copy of every sheet takes part in the
//! separation, as on the strip; a copy pushed across a wall by the cut is
//! outside, and moves like one that overlaps.
//!
//! Measured against the sheet-by-sheet exploration it replaced (the
//! sheets in turn, copies of the last pulled or dropped onto the others:
//! dc2f471), at equal evaluations: the table at the top of
//! scripts/bench-nest-sheets.sh.
//!
//! A bay is the sheet's room (its box less the margin, grown back by half
//! the spacing) moved along x so that the bays touch: bay k starts where
//! bay k − 1 ends. A copy belongs to the bay its box centre is over and
//! must lie inside it; every sampled position is moved into the bay it
//! falls on (so no sample crosses a wall, as none leaves the room).
//!
//! The exact test allows an overlap of its tolerance (10⁻³ of the nest's
//! tolerance): on the panels' sheets (seed 1, 10 000 evaluations) two
//! pairs of long straight edges were left that close, overlapping by
//! 0.004 and 0.02 mm², past check_nest.py's limit (10⁻⁶ of the smaller
//! part's area); the strip of the same run had none. On fixed sheets the
//! tolerance is [`BAYS_EPS`] of that, and those sheets are valid. (The
//! strip's is left as it is: its nests stay the same.)

use super::sample::{Layout, Piece};
use super::{hosts_of, length};
use crate::geom::{fmin, BBox, Point};
use crate::nest::decode::{At, Decoded, Item};
use crate::nest::place::{range_of, Container, Placed};
use crate::nest::rng::SplitMix;

/// The exact test's tolerance on fixed sheets, as a share of the strip's.
pub(super) const BAYS_EPS: f64 = 0.01;

impl Layout {
    /// The room a copy whose box is `b` (where it lies) must keep in: the
    /// bay its centre is over, closed at the room's end; the room on a
    /// strip or a single room.
    pub fn room_of(&self, b: &BBox) -> Container {
        if self.bays.is_empty() {
            return self.room;
        }
        let x = (b.min.x + b.max.x) / 2.0;
        let k = self.bays.partition_point(|c| c.x0 <= x).saturating_sub(1);
        let mut c = self.bays[k];
        c.x1 = fmin(c.x1, self.room.x1);
        c
    }

    /// `t` moved into the bay that a shape with box `b` (untranslated)
    /// at `t` is over; None when it does not fit that bay. On a strip,
    /// `t` as it is.
    pub fn kept_in_bay(&self, b: &BBox, t: Point) -> Option<Point> {
        if self.bays.is_empty() {
            return Some(t);
        }
        let r = self.room_of(&BBox {
            min: b.min.add(t),
            max: b.max.add(t),
        });
        if b.max.x - b.min.x > r.x1 - r.x0 || b.max.y - b.min.y > r.y1 - r.y0 {
            return None;
        }
        let (lo, hi) = range_of(&r, b);
        Some(Point::new(t.x.clamp(lo.x, hi.x), t.y.clamp(lo.y, hi.y)))
    }

    /// The translations keeping a shape with box `b` (untranslated) in
    /// the bay it is over at `t` (the room on a strip).
    pub fn range_at(&self, b: &BBox, t: Point) -> (Point, Point) {
        if self.bays.is_empty() {
            return range_of(&self.room, b);
        }
        let r = self.room_of(&BBox {
            min: b.min.add(t),
            max: b.max.add(t),
        });
        range_of(&r, b)
    }

    /// True when piece `k` lies (partly) outside its room: the room, and
    /// on fixed sheets the bay its centre is over.
    pub fn outside(&self, k: usize, eps: f64) -> bool {
        let b = self.pieces[k].shape.bbox();
        let inside = |r: &Container| {
            b.min.x >= r.x0 - eps
                && b.min.y >= r.y0 - eps
                && b.max.x <= r.x1 + eps
                && b.max.y <= r.y1 + eps
        };
        !inside(&self.room) || (!self.bays.is_empty() && !inside(&self.room_of(b)))
    }

    /// The bay piece `k`'s centre is over (0 on a strip).
    pub(super) fn bay_of(&self, k: usize) -> usize {
        let b = self.pieces[k].shape.bbox();
        let x = (b.min.x + b.max.x) / 2.0;
        self.bays.partition_point(|c| c.x0 <= x).saturating_sub(1)
    }
}

/// The sheets of a nest as bays of one strip: their rooms laid end to
/// end, and how far each is moved along x. None unless every sheet is a
/// box of finite length (a strip and an irregular sheet are shortened as
/// they are).
pub(super) struct Bays {
    rooms: Vec<Container>,
    shift: Vec<f64>,
    /// Every sheet the same box: an empty sheet between two others is
    /// closed by moving the later ones back a sheet.
    same: bool,
}

impl Bays {
    pub(super) fn of(d: &Decoded) -> Option<Bays> {
        if d.bins.is_empty()
            || d.bins.iter().any(|b| {
                !b.container.x1.is_finite() || b.bound.is_some() || !b.obstacles.is_empty()
            })
        {
            return None;
        }
        let mut rooms = Vec::with_capacity(d.bins.len());
        let mut shift = Vec::with_capacity(d.bins.len());
        let x0 = d.bins[0].container.x0;
        let mut at = x0;
        for b in &d.bins {
            let c = b.container;
            let dx = at - c.x0;
            shift.push(dx);
            rooms.push(Container {
                x0: c.x0 + dx,
                y0: c.y0,
                x1: c.x1 + dx,
                y1: c.y1,
            });
            at = c.x1 + dx;
        }
        let c0 = d.bins[0].container;
        let same = d.bins.iter().all(|b| b.container == c0);
        Some(Bays { rooms, shift, same })
    }

    /// The bays, laid end to end along x.
    pub(super) fn rooms(&self) -> &[Container] {
        &self.rooms
    }

    /// Where the bay `back` bays before the one holding x = `len` (the
    /// layout's right end) starts (the first bay's start when there are
    /// fewer).
    ///
    /// A slice cut from an earlier bay slides every later bay's copies
    /// left, and the copies at each wall then cross it: every wall is
    /// disturbed at once, and at 10 000 evaluations the keyboard plates'
    /// last sheet (seeds 2 and 3) was never shortened, at its full length
    /// though its copies needed 85 % of it. Cut from the last bay
    /// (`back` 0), only its copies slide: the strip's exploration on the
    /// last sheet, the earlier sheets open to its copies. The other cuts
    /// go no further back than the bay before it (`back` 1): one wall
    /// crossed, the last sheet's copies pushed into the one before, the
    /// full sheets before that left as they are. Against cuts anywhere
    /// in the strip (every wall crossed), at 10 000 evaluations, eight
    /// instances × seeds 1-4: mean total / strip 1.0486 -> 1.0443, no
    /// sheet more (scripts/bench-nest-sheets.sh).
    pub(super) fn x0_back(&self, len: f64, back: usize) -> f64 {
        let k = self.rooms.partition_point(|c| c.x0 < len).saturating_sub(1);
        self.rooms[k.saturating_sub(back)].x0
    }

    /// Every copy of every sheet, sheet by sheet, in its bay; the room
    /// closed at the last copy's right edge.
    pub(super) fn layout(&self, d: &Decoded) -> Layout {
        let hosts = hosts_of(d);
        let mut pieces = Vec::new();
        for (b, bin) in d.bins.iter().enumerate() {
            let dx = Point::new(self.shift[b], 0.0);
            for (i, p) in bin.placed.iter().enumerate() {
                pieces.push(Piece {
                    item: p.item,
                    variant: p.variant,
                    t: p.t.add(dx),
                    shape: p.shape.moved(dx),
                    turn: !hosts.iter().any(|&(h, n)| h == (b, i) && n > 0),
                });
            }
        }
        let y0 = self
            .rooms
            .iter()
            .map(|r| r.y0)
            .fold(f64::INFINITY, f64::min);
        let y1 = self
            .rooms
            .iter()
            .map(|r| r.y1)
            .fold(f64::NEG_INFINITY, f64::max);
        let mut lay = Layout {
            pieces,
            room: Container {
                x0: self.rooms[0].x0,
                y0,
                x1: f64::INFINITY,
                y1,
            },
            bays: self.rooms.clone(),
        };
        lay.room.x1 = length(&lay);
        lay
    }

    /// An empty bay between two others closed, when the sheets are all
    /// alike: the copies of the later bays moved back one bay (a sheet
    /// fewer, the same nest on the others).
    pub(super) fn close_empty(&self, lay: &mut Layout) {
        if !self.same {
            return;
        }
        loop {
            let mut used = vec![false; self.rooms.len()];
            for k in 0..lay.pieces.len() {
                used[lay.bay_of(k)] = true;
            }
            let Some(last) = used.iter().rposition(|&u| u) else {
                return;
            };
            let Some(gap) = used[..last].iter().position(|&u| !u) else {
                return;
            };
            let w = self.rooms[gap].x1 - self.rooms[gap].x0;
            let d = Point::new(-w, 0.0);
            for k in 0..lay.pieces.len() {
                if lay.bay_of(k) > gap {
                    let p = &mut lay.pieces[k];
                    p.t = p.t.add(d);
                    p.shape = p.shape.moved(d);
                }
            }
            lay.room.x1 = length(lay);
        }
    }

    /// `lay`'s copies listed sheet by sheet (in their order within each),
    /// as [`Bays::decoded`] lists them on the sheets.
    pub(super) fn sort(&self, lay: &mut Layout) {
        let bays: Vec<usize> = (0..lay.pieces.len()).map(|k| lay.bay_of(k)).collect();
        let mut keyed: Vec<(usize, Piece)> = bays.into_iter().zip(lay.pieces.drain(..)).collect();
        keyed.sort_by_key(|&(bay, _)| bay);
        lay.pieces = keyed.into_iter().map(|(_, p)| p).collect();
    }

    /// `d` with its copies where `lay` (made by [`Bays::layout`] from `d`,
    /// then separated) has them: each on the sheet of its bay, the sheets
    /// past the last used dropped; the copies in their holes moved along.
    /// `lay`'s pieces are `d`'s copies sheet by sheet (as `layout` lists
    /// them), so a nest made here lists them again in that order.
    pub(super) fn decoded(&self, mut d: Decoded, lay: &Layout, origin_x: f64) -> Decoded {
        let hosts = hosts_of(&d);
        let old: Vec<(usize, usize)> = d
            .bins
            .iter()
            .enumerate()
            .flat_map(|(b, bin)| (0..bin.placed.len()).map(move |i| (b, i)))
            .collect();
        let mut placed: Vec<Vec<Placed>> = vec![Vec::new(); self.rooms.len()];
        let mut new = Vec::with_capacity(lay.pieces.len());
        for (k, p) in lay.pieces.iter().enumerate() {
            let bay = lay.bay_of(k);
            let back = Point::new(-self.shift[bay], 0.0);
            let t = p.t.add(back);
            // (A copy past `d`'s own is one that was left out, placed now:
            // no copies in its holes.)
            let (b, i) = old.get(k).copied().unwrap_or((usize::MAX, 0));
            let dt = d
                .bins
                .get(b)
                .map_or(Point::new(0.0, 0.0), |bin| t.sub(bin.placed[i].t));
            for (h, &(root, _)) in hosts.iter().enumerate() {
                if root == (b, i) {
                    let hb = &mut d.holes[h];
                    hb.sheet = bay;
                    for g in &mut hb.bin.placed {
                        g.t = g.t.add(dt);
                        g.shape = g.shape.moved(dt);
                    }
                    if let Some(bound) = &mut hb.bin.bound {
                        *bound = bound.moved(dt);
                    }
                }
            }
            new.push((bay, placed[bay].len()));
            placed[bay].push(Placed {
                item: p.item,
                variant: p.variant,
                t,
                shape: p.shape.moved(back),
            });
        }
        for h in &mut d.holes {
            if let At::Sheet(b, i) = h.host {
                if let Some(k) = old.iter().position(|&o| o == (b, i)) {
                    h.host = At::Sheet(new[k].0, new[k].1);
                }
            }
        }
        let used = placed
            .iter()
            .rposition(|p| !p.is_empty())
            .map_or(0, |k| k + 1);
        d.bins.truncate(used);
        for (bin, copies) in d.bins.iter_mut().zip(placed) {
            bin.right = copies
                .iter()
                .map(|p| p.shape.bbox().max.x)
                .fold(bin.container.x0, f64::max);
            bin.placed = copies;
        }
        d.cost.1 = d.bins.len();
        if let Some(last) = d.bins.last() {
            d.cost.2 = last.right - origin_x;
            d.gravity = last
                .placed
                .iter()
                .map(|p| (p.shape.bbox().max.x - origin_x).powi(2))
                .sum();
        }
        d
    }
}

impl super::Improver {
    /// Fixed sheets, copies left out (the first nest found no room for
    /// them on any sheet): one of them dropped anywhere on the sheets and
    /// separated there, the sheets' whole length open; kept when nothing
    /// overlaps by the exact test. Nothing else is tried while copies are
    /// left out: placing them all comes before the shortest last sheet.
    /// Returns false when `found` cancelled.
    pub(super) fn place_left_out(
        &mut self,
        rng: &mut SplitMix,
        budget: &mut super::Budget,
        found: &mut dyn FnMut(&Decoded, &[Item]) -> bool,
    ) -> bool {
        let Some(bays) = &self.bays else {
            return true;
        };
        let n = self.best.unplaced.len();
        let Some(last) = self.best.bins.len().checked_sub(1) else {
            return true;
        };
        if n == 0 {
            return true;
        }
        let j = rng.below(n);
        let item = self.best.unplaced[j];
        let v = rng.below(self.kit.base[item]);
        let mut work = self.lay.clone();
        work.room.x1 = bays.rooms[last].x1;
        let shape = &self.kit.items[item].variants[v].shape;
        let (lo, hi) = range_of(&work.room, shape.bbox());
        let t = Point::new(
            lo.x + rng.unit() * (hi.x - lo.x),
            lo.y + rng.unit() * (hi.y - lo.y),
        );
        let Some(t) = work.kept_in_bay(shape.bbox(), t) else {
            return true;
        };
        work.pieces.push(Piece {
            item,
            variant: v,
            t,
            shape: shape.moved(t),
            turn: true,
        });
        let (separated, _) = super::separate(&mut self.kit, &mut work, rng, budget, super::NO_GAIN);
        if !(separated && super::feasible(&self.kit, &work)) {
            return true;
        }
        let best = std::mem::replace(&mut self.best, Decoded::empty());
        let mut best = bays.decoded(best, &work, self.origin_x);
        best.unplaced.remove(j);
        best.cost.0 = lost(&best, &self.kit.items);
        bays.sort(&mut work);
        work.room.x1 = super::length(&work);
        self.best = best;
        self.large = super::explore::large_copies(&self.kit, &work.pieces);
        self.pool.clear();
        self.tries = 0;
        self.lay = work.clone();
        self.work = work;
        found(&self.best, &self.kit.items)
    }
}

/// The share of all copies' area left out, in billionths, rounded up (as
/// the decoder counts it: 0 only when every copy is placed).
fn lost(d: &Decoded, items: &[Item]) -> usize {
    let out = d.unplaced.len() + d.stopped.len();
    if out == 0 {
        return 0;
    }
    let area = |it: usize| items[it].variants[0].shape.poly.area().abs();
    let placed: f64 = d
        .bins
        .iter()
        .flat_map(|b| &b.placed)
        .chain(d.holes.iter().flat_map(|h| &h.bin.placed))
        .map(|p| area(p.item))
        .sum();
    let lost: f64 = d.unplaced.iter().chain(&d.stopped).map(|&i| area(i)).sum();
    let total = placed + lost;
    if !(total > 0.0 && lost.is_finite()) {
        return out;
    }
    ((lost / total * 1e9).ceil() as usize).max(1)
}
