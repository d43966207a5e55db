//! The separator's move: one overlapping copy taken to the best of a set
//! of sampled positions, the best refined by coordinate descent.
//!
//! As sparrow does it (Gardeyn & Wauters, EJOR 2025, §4.3): samples drawn
//! uniformly over the whole room (any allowed turn of the copy, its box
//! kept inside the room) find a free hole far away; samples near the
//! current position (same turn, within a fraction of the copy's size)
//! find a small shift; the best of each kind is then moved along ±x and
//! ±y with a step that grows on success and halves on failure
//! ([`super::descend`]), and the better of the two kept (sparrow refines
//! several samples; refining the uniform one too gained 1–2.5 points on
//! shapes0 and jakobs2 at equal moves, for ~15 % more time a move). A
//! part free to turn also tries other angles ([`super::turn`]). A
//! position's value is Σ weight × overlap proxy over the copies it
//! overlaps by the exact test; its sum is abandoned once it exceeds the
//! best so far.
//!
//! The room is a rectangle and every position keeps the copy's box inside
//! it, so no position ever leaves the container: sparrow's container-exit
//! term is zero here by construction, not approximated. (A copy turned
//! freely to the room's full length may not fit once the room is
//! shortened: it is moved like an overlapping one, and any position
//! inside beats where it lies.)

use std::cell::RefCell;

use super::overlap::{Near, Table, Walk};
use super::poles::{PoleSet, MAX_POLES};
use crate::geom::{fmax, Point};
use crate::nest::collide::{boxes_overlap, diagonals_apart, overlaps_walked, Shape};
use crate::nest::decode::Item;
use crate::nest::place::{range_of, Container};
use crate::nest::rng::SplitMix;

/// Samples over the whole room per move.
const UNIFORM: usize = 40;
/// Samples near the current position per move.
const FOCUSED: usize = 30;
/// The proxy's decay distance, as a share of the larger copy's size.
const DECAY: f64 = 0.01;
/// Half-width of the focused window, as a share of the copy's size.
const NEAR: f64 = 0.25;
/// Rows of the proxy walked before the exact test is asked.
const PROBE: usize = 2;

/// One copy in the layout being separated.
#[derive(Clone, Debug)]
pub struct Piece {
    /// Index into the items.
    pub item: usize,
    /// Which of its variants.
    pub variant: usize,
    /// Its translation.
    pub t: Point,
    /// Its collision shape there.
    pub shape: Shape,
    /// May take another turn (false for a copy holding others in its
    /// holes: they are not turned with it).
    pub turn: bool,
}

/// The copies of one sheet (or the strip) and the room they must keep in.
#[derive(Clone, Debug)]
pub struct Layout {
    /// The copies.
    pub pieces: Vec<Piece>,
    /// The room (a rectangle; x1 finite: the length tried).
    pub room: Container,
    /// Fixed sheets laid side by side in the room ([`super::bays`]), or
    /// none (a strip or a single room).
    pub bays: Vec<Container>,
}

/// What the separator knows of the parts: their variants and poles.
pub struct Kit {
    /// The parts ready to place; a part turning freely gains variants at
    /// the angles its copies take ([`super::turn`]), after its own.
    pub items: Vec<Item>,
    /// Per item: how many variants are its own (the allowed turns).
    pub base: Vec<usize>,
    /// Per item: may take any angle (free rotation).
    pub free: Vec<bool>,
    /// Poles of every item's every variant.
    pub poles: Vec<Vec<PoleSet>>,
    /// The exact test's tolerance, mm.
    pub eps: f64,
    /// Per item: its size (the larger side of its box), mm.
    pub size: Vec<f64>,
    /// Per item: its weight in a pair's overlap, √(area), mm.
    pub pen: Vec<f64>,
    /// A position's working room: the copy moved there (made anew for
    /// every position tried, its vertices' allocation and copy were a
    /// twentieth of a separation, perf, jakobs2) and the proxy's poles
    /// kept ([`Near`]).
    scratch: RefCell<(Option<Shape>, Near)>,
}

impl Kit {
    /// The separator's view of `items`; `free[i]`: item `i` may take any
    /// angle.
    pub fn new(items: &[Item], free: Vec<bool>, eps: f64) -> Kit {
        let poles = items
            .iter()
            .map(|it| {
                it.variants
                    .iter()
                    .map(|v| PoleSet::new(&super::poles::poles(&v.shape.poly)))
                    .collect()
            })
            .collect();
        let size = items
            .iter()
            .map(|it| {
                let b = it.variants[0].shape.bbox();
                (b.max.x - b.min.x).max(b.max.y - b.min.y)
            })
            .collect();
        let pen = items
            .iter()
            .map(|it| it.variants[0].shape.poly.area().sqrt())
            .collect();
        Kit {
            items: items.to_vec(),
            base: items.iter().map(|it| it.variants.len()).collect(),
            free,
            poles,
            eps,
            size,
            pen,
            scratch: RefCell::new((None, Near::default())),
        }
    }

    /// The overlap of piece `a` with shape `s` (poles `ps`) of `item` at `t`
    /// (0 when the exact test says clear): √proxy × √(√area₁ · √area₂),
    /// the decay 1 % of the larger part's size ([`super::overlap`]); given
    /// up past `limit` (then some value above it).
    ///
    /// The proxy goes first: when two poles overlap deeper than the
    /// tolerance (ten times over), the shapes overlap and the exact test
    /// would only say so again; else the exact test decides, and a clear
    /// pair is exactly 0.
    #[allow(clippy::too_many_arguments)]
    fn pair(
        &self,
        a: &Piece,
        s: &Shape,
        item: usize,
        ps: &PoleSet,
        t: Point,
        limit: f64,
        near: &mut Near,
    ) -> f64 {
        // (Apart along a diagonal: clear by the exact test too, and no
        // pole of one reaches into the other.)
        if !boxes_overlap(a.shape.bbox(), s.bbox(), self.eps)
            || diagonals_apart(&a.shape, s, self.eps)
        {
            return 0.0;
        }
        let decay = DECAY * fmax(self.size[a.item], self.size[item]);
        let scale = (self.pen[a.item] * self.pen[item]).sqrt();
        let raw_limit = if limit.is_finite() {
            (limit / scale).powi(2)
        } else {
            f64::INFINITY
        };
        let mut walk = Walk::new(
            &self.poles[a.item][a.variant],
            a.t,
            ps,
            t,
            decay,
            10.0 * self.eps,
            near,
        );
        walk.rows(PROBE, raw_limit);
        if !walk.deep() && !overlaps_walked(&a.shape, s, self.eps) {
            return 0.0;
        }
        walk.rows(MAX_POLES, raw_limit);
        let raw = walk.value();
        raw.sqrt() * scale
    }

    /// Weighted overlap of piece `k` if it were variant `v` at `t`,
    /// abandoned past `upper`.
    pub fn cost(
        &self,
        lay: &Layout,
        table: &Table,
        k: usize,
        v: usize,
        t: Point,
        upper: f64,
    ) -> f64 {
        let item = lay.pieces[k].item;
        let shape = &self.items[item].variants[v].shape;
        self.cost_as(lay, table, k, shape, &self.poles[item][v], t, upper)
    }

    /// [`Self::cost`] of piece `k` as `shape` (untranslated, poles `ps`).
    #[allow(clippy::too_many_arguments)]
    pub fn cost_as(
        &self,
        lay: &Layout,
        table: &Table,
        k: usize,
        shape: &Shape,
        ps: &PoleSet,
        t: Point,
        upper: f64,
    ) -> f64 {
        let item = lay.pieces[k].item;
        let mut scratch = self.scratch.borrow_mut();
        let (moved, near) = &mut *scratch;
        let s = match moved {
            Some(s) => {
                s.move_from(shape, t);
                s
            }
            None => moved.insert(shape.moved(t)),
        };
        let mut sum = 0.0;
        for (j, p) in lay.pieces.iter().enumerate() {
            // (The box test first, before the division below: four
            // pairs in five end there.)
            if j == k || !boxes_overlap(p.shape.bbox(), s.bbox(), self.eps) {
                continue;
            }
            let w = table.weight(k, j);
            let o = self.pair(p, s, item, ps, t, (upper - sum) / w, near);
            if o > 0.0 {
                sum += w * o;
                if sum >= upper {
                    return sum;
                }
            }
        }
        sum
    }

    /// Fills row `k` of the table with piece `k`'s overlaps as it lies.
    pub fn refresh(&self, lay: &Layout, table: &mut Table, k: usize) {
        let p = &lay.pieces[k];
        let near = &mut self.scratch.borrow_mut().1;
        for (j, q) in lay.pieces.iter().enumerate() {
            if j != k {
                let ps = &self.poles[p.item][p.variant];
                let o = self.pair(q, &p.shape, p.item, ps, p.t, f64::INFINITY, near);
                table.set(k, j, o);
            }
        }
    }

    /// The translations keeping variant `v`'s box inside the room:
    /// (least, most) along x and y (most = least when it does not fit).
    /// True when variant `v` of `item` fits the room at all.
    pub fn fits(&self, room: &Container, item: usize, v: usize) -> bool {
        let b = self.items[item].variants[v].shape.bbox();
        b.max.x - b.min.x <= room.x1 - room.x0 && b.max.y - b.min.y <= room.y1 - room.y0
    }

    /// True when piece `k` lies (partly) outside the room.
    pub fn outside(&self, lay: &Layout, k: usize) -> bool {
        lay.outside(k, self.eps)
    }

    pub(super) fn range(&self, room: &Container, item: usize, v: usize) -> (Point, Point) {
        range_of(room, self.items[item].variants[v].shape.bbox())
    }

    /// The position `best` snapped along x or y so that the copy's box
    /// meets a wall of the room or a box edge of a copy near it, when no
    /// worse (ties: the one further left, then lower). Continuous samples
    /// never land exactly on a contact; nests of parts with straight edges
    /// (ESICUP's jakobs and shapes) are tight only with exact contacts.
    fn snap(
        &self,
        lay: &Layout,
        table: &Table,
        k: usize,
        mut best: (f64, usize, Point),
        size: f64,
    ) -> (f64, usize, Point) {
        let item = lay.pieces[k].item;
        let v = best.1;
        let vb = *self.items[item].variants[v].shape.bbox();
        let here = crate::geom::BBox {
            min: vb.min.add(best.2),
            max: vb.max.add(best.2),
        };
        let r = &lay.room_of(&here);
        let (lo, hi) = range_of(r, &vb);
        let mut xs = vec![r.x0 - vb.min.x, r.x1 - vb.max.x];
        let mut ys = vec![r.y0 - vb.min.y, r.y1 - vb.max.y];
        for (j, p) in lay.pieces.iter().enumerate() {
            let b = p.shape.bbox();
            if j == k
                || b.min.x > here.max.x + size
                || b.max.x < here.min.x - size
                || b.min.y > here.max.y + size
                || b.max.y < here.min.y - size
            {
                continue;
            }
            xs.extend([b.max.x - vb.min.x, b.min.x - vb.max.x]);
            ys.extend([b.max.y - vb.min.y, b.min.y - vb.max.y]);
        }
        let key = |c: f64, t: Point| (c, t.x + t.y);
        let mut cands: Vec<Point> = xs
            .iter()
            .filter(|&&x| x >= lo.x && x <= hi.x)
            .map(|&x| Point::new(x, best.2.y))
            .chain(
                ys.iter()
                    .filter(|&&y| y >= lo.y && y <= hi.y)
                    .map(|&y| Point::new(best.2.x, y)),
            )
            .collect();
        cands.sort_by(|a, b| (a.x + a.y).total_cmp(&(b.x + b.y)));
        for t in cands {
            let c = self.cost(lay, table, k, v, t, best.0 + 1e-12);
            if key(c, t) < key(best.0, best.2) {
                best = (c, v, t);
            }
        }
        best
    }

    /// Moves piece `k` to the best position sampled; returns its new
    /// weighted overlap.
    pub fn move_piece(
        &mut self,
        lay: &mut Layout,
        table: &mut Table,
        k: usize,
        rng: &mut SplitMix,
    ) -> f64 {
        let p = &lay.pieces[k];
        let (item, v0, t0, turn) = (p.item, p.variant, p.t, p.turn);
        let nv = self.base[item];
        let size = {
            let b = p.shape.bbox();
            fmax(b.max.x - b.min.x, b.max.y - b.min.y)
        };
        // A copy too big for the room as it lies (only a copy turned
        // freely, as long as the room, can be) must move: any position
        // inside is better.
        let now = if self.fits(&lay.room, item, v0)
            && (lay.bays.is_empty() || !lay.outside(k, self.eps))
        {
            self.cost(lay, table, k, v0, t0, f64::INFINITY)
        } else {
            f64::INFINITY
        };
        let mut best = (now, v0, t0);
        let here = best;
        // The best uniform sample is kept apart from the best focused one
        // and both are refined (sparrow refines more than one sample).
        let mut far = here;
        for i in 0..UNIFORM + FOCUSED {
            if best.0 <= 0.0 {
                break;
            }
            if i == UNIFORM {
                far = best;
                best = here;
            }
            let (v, t) = if i < UNIFORM {
                let v = if turn { rng.below(nv) } else { v0 };
                let (lo, hi) = self.range(&lay.room, item, v);
                let t = Point::new(
                    lo.x + rng.unit() * (hi.x - lo.x),
                    lo.y + rng.unit() * (hi.y - lo.y),
                );
                (v, t)
            } else {
                let (lo, hi) = self.range(&lay.room, item, v0);
                let r = NEAR * size;
                let t = Point::new(
                    (t0.x + (2.0 * rng.unit() - 1.0) * r).clamp(lo.x, hi.x),
                    (t0.y + (2.0 * rng.unit() - 1.0) * r).clamp(lo.y, hi.y),
                );
                (v0, t)
            };
            if !self.fits(&lay.room, item, v) {
                continue;
            }
            // Fixed sheets: into the sheet it falls on.
            let Some(t) = lay.kept_in_bay(self.items[item].variants[v].shape.bbox(), t) else {
                continue;
            };
            let c = self.cost(lay, table, k, v, t, best.0);
            if c < best.0 {
                best = (c, v, t);
            }
        }
        // (Nothing inside found yet: no position of a variant too big is
        // refined.)
        let mut best = if best.0.is_finite() {
            self.descend_variant(lay, table, k, best, size)
        } else {
            best
        };
        if far.0 > 0.0 && far.0.is_finite() && (far.1, far.2) != (best.1, best.2) && best.0 > 0.0 {
            let other = self.descend_variant(lay, table, k, far, size);
            if other.0 < best.0 {
                best = other;
            }
        } else if far.0 < best.0 {
            best = far;
        }
        let best = if self.free[item] && turn {
            self.turn_freely(lay, table, k, best, size, rng)
        } else {
            best
        };
        let best = if best.0.is_finite() {
            self.snap(lay, table, k, best, size)
        } else {
            best
        };
        let (c, v, t) = best;
        let piece = &mut lay.pieces[k];
        piece.variant = v;
        piece.t = t;
        piece.shape = self.items[item].variants[v].shape.moved(t);
        self.refresh(lay, table, k);
        c
    }
}
