//! Free rotation in the separator: a copy of a part that may take any
//! angle is not held to the set of turns the placer tries
//! ([`crate::nest::rotations::Rotations::angles_for`]). After the usual
//! samples, a move also tries a few copies turned by random angles
//! (anywhere in the room), then refines the angle of the best position
//! found: turns of ±[`FIRST_TURN`]° about the copy's box centre, halved
//! on failure down to [`LEAST_TURN`]° (sparrow samples orientations the
//! same way when rotations are continuous, Gardeyn & Wauters, EJOR 2025,
//! §4.3). A turned shape is one of the part's own variants rotated
//! rigidly (polygon and poles alike), so it is as conservative as they
//! are; the angle a copy ends at becomes a variant of its own, appended
//! after the allowed ones, and variants no copy uses any more are dropped
//! ([`Kit::compact`]), so memory stays bounded.

use super::overlap::Table;
use super::poles::{Pole, PoleSet};
use super::sample::{Kit, Layout};
use crate::geom::{Affine, Point};
use crate::nest::collide::Shape;
use crate::nest::place::{range_of, Variant};
use crate::nest::rng::SplitMix;

/// Copies turned by a random angle tried per move.
const FREE_SAMPLES: usize = 8;
/// The angle refinement's first and least step, degrees.
const FIRST_TURN: f64 = 4.0;
const LEAST_TURN: f64 = 0.1;
/// Most variants a part may gain between two compactions: past it, its
/// copies keep the angles they have until the next one.
const MOST_GAINED: usize = 128;

/// A part turned: variant `from` rotated by `delta` degrees.
struct Turned {
    from: usize,
    delta: f64,
    shape: Shape,
    poles: PoleSet,
}

impl Kit {
    /// Variant `from` of `item` rotated by `delta` degrees about the origin.
    fn turned(&self, item: usize, from: usize, delta: f64) -> Turned {
        let v = &self.items[item].variants[from];
        let turn = Affine::rotate_deg(delta);
        let shape = v.shape.turned(delta);
        let poles: Vec<Pole> = self.poles[item][from]
            .iter()
            .map(|p| Pole {
                c: turn.apply(p.c),
                r: p.r,
            })
            .collect();
        let poles = PoleSet::new(&poles);
        Turned {
            from,
            delta,
            shape,
            poles,
        }
    }

    /// True when a shape with box `b` fits the room at all.
    fn fits_box(lay: &Layout, b: &crate::geom::BBox) -> bool {
        let r = &lay.room;
        b.max.x - b.min.x <= r.x1 - r.x0 && b.max.y - b.min.y <= r.y1 - r.y0
    }

    /// Piece `k` (free to turn) tried at random angles and its best
    /// position's angle refined; `best` = (cost, variant, translation)
    /// found by the usual samples. Returns the better of the two, a new
    /// variant when a turned copy won.
    pub(super) fn turn_freely(
        &mut self,
        lay: &Layout,
        table: &Table,
        k: usize,
        best: (f64, usize, Point),
        size: f64,
        rng: &mut SplitMix,
    ) -> (f64, usize, Point) {
        let item = lay.pieces[k].item;
        if best.0 <= 0.0 || self.items[item].variants.len() >= self.base[item] + MOST_GAINED {
            return best;
        }
        let (mut c, mut t) = (best.0, best.2);
        let mut cur: Option<Turned> = None;
        for _ in 0..FREE_SAMPLES {
            let from = rng.below(self.base[item]);
            let cand = self.turned(item, from, 360.0 * rng.unit());
            let b = cand.shape.bbox();
            if !Self::fits_box(lay, b) {
                continue;
            }
            let (lo, hi) = range_of(&lay.room, b);
            let tt = Point::new(
                lo.x + rng.unit() * (hi.x - lo.x),
                lo.y + rng.unit() * (hi.y - lo.y),
            );
            let Some(tt) = lay.kept_in_bay(b, tt) else {
                continue;
            };
            let cc = self.cost_as(lay, table, k, &cand.shape, &cand.poles, tt, c);
            if cc < c {
                (c, t, cur) = (cc, tt, Some(cand));
            }
        }
        if let Some(cand) = &cur {
            let range = lay.range_at(cand.shape.bbox(), t);
            let eval =
                |t: Point, u: f64| self.cost_as(lay, table, k, &cand.shape, &cand.poles, t, u);
            (c, t) = self.descend(range, (c, t), size, &eval);
        }
        // The angle refined about the box centre of the best so far.
        let (mut from, mut delta) = cur.as_ref().map_or((best.1, 0.0), |x| (x.from, x.delta));
        let mut step = FIRST_TURN;
        let mut turned = false;
        while c > 0.0 && step >= LEAST_TURN {
            let mut gained = false;
            for sign in [1.0, -1.0] {
                let now = match &cur {
                    Some(x) => x.shape.bbox(),
                    None => self.items[item].variants[best.1].shape.bbox(),
                };
                let mid = now.centre();
                let cand = self.turned(item, from, delta + sign * step);
                let b = cand.shape.bbox();
                if !Self::fits_box(lay, b) {
                    continue;
                }
                let (lo, hi) = range_of(&lay.room, b);
                let keep = t.add(mid).sub(Affine::rotate_deg(sign * step).apply(mid));
                let tt = Point::new(keep.x.clamp(lo.x, hi.x), keep.y.clamp(lo.y, hi.y));
                let Some(tt) = lay.kept_in_bay(b, tt) else {
                    continue;
                };
                let cc = self.cost_as(lay, table, k, &cand.shape, &cand.poles, tt, c);
                if cc < c {
                    (from, delta) = (cand.from, cand.delta);
                    (c, t, cur) = (cc, tt, Some(cand));
                    (gained, turned) = (true, true);
                    break;
                }
            }
            if !gained {
                step /= 2.0;
            }
        }
        let Some(cand) = cur else {
            return best;
        };
        if turned {
            let range = lay.range_at(cand.shape.bbox(), t);
            let eval =
                |t: Point, u: f64| self.cost_as(lay, table, k, &cand.shape, &cand.poles, t, u);
            (c, t) = self.descend(range, (c, t), size, &eval);
        }
        (c, self.adopt(item, cand), t)
    }

    /// `cand` as a new variant of `item`; its index.
    fn adopt(&mut self, item: usize, cand: Turned) -> usize {
        let v = &self.items[item].variants[cand.from];
        let holes = v.holes.iter().map(|h| h.turned(cand.delta)).collect();
        let variant = Variant {
            rotation: (v.rotation + cand.delta).rem_euclid(360.0),
            mirror: v.mirror,
            shape: cand.shape,
            holes,
        };
        self.items[item].variants.push(variant);
        self.poles[item].push(cand.poles);
        self.items[item].variants.len() - 1
    }

    /// Drops the gained variants no copy of `lays` uses, renumbering the
    /// copies that use the others.
    pub(super) fn compact(&mut self, lays: &mut [&mut Layout]) {
        for item in 0..self.items.len() {
            let base = self.base[item];
            let n = self.items[item].variants.len();
            if n == base {
                continue;
            }
            let mut map = vec![usize::MAX; n - base];
            let mut kept = 0;
            for lay in lays.iter() {
                for p in lay
                    .pieces
                    .iter()
                    .filter(|p| p.item == item && p.variant >= base)
                {
                    if map[p.variant - base] == usize::MAX {
                        map[p.variant - base] = 0;
                        kept += 1;
                    }
                }
            }
            if kept == n - base {
                continue;
            }
            let variants = self.items[item].variants.split_off(base);
            let poles = self.poles[item].split_off(base);
            for (i, (v, ps)) in variants.into_iter().zip(poles).enumerate() {
                if map[i] != usize::MAX {
                    map[i] = self.items[item].variants.len();
                    self.items[item].variants.push(v);
                    self.poles[item].push(ps);
                }
            }
            for lay in lays.iter_mut() {
                for p in lay
                    .pieces
                    .iter_mut()
                    .filter(|p| p.item == item && p.variant >= base)
                {
                    p.variant = map[p.variant - base];
                }
            }
        }
    }
}
