//! Loose copies moved into the rooms (holes) of placed copies (issue 44
//! item 4, parts in holes).
//!
//! The decoder puts a copy into a hole only when the order brings it after
//! its host; the separation never does, since it moves sheet copies and a
//! hole's room is inside its host's outline. On the flanges (plates with
//! bores, and the discs that fit) the best nest kept 72 of 120 copies on
//! the strip, 32 of them discs, while the 12 diamond bores stayed empty
//! (the placer's candidates never reach into them: [`by_grid`]). Here the placer (bottom-left fill within the
//! room, its guests as obstacles, as the decoder fills holes) is asked,
//! for the strip's copies furthest right first, whether a room of a copy
//! on the strip (or of a copy in a hole) takes them. A copy moved becomes
//! its host's guest: it rides with it ([`super::decoded`]), is cut before
//! the hole and named `in_hole_of` in the nest, as the decoder's guests
//! are. Its place on the strip is left to the exploration to close.
//!
//! Tried for every new best nest, a placer call an evaluation; a room
//! (its host's part, turn and room, and the guests already in it) that
//! refused a part is not asked again for it. The copy placed is checked
//! again by the exact test ([`housed`]).

use std::collections::HashSet;

use super::sample::{Kit, Layout};
use crate::geom::{fmax, Point};
use crate::nest::collide::{overlaps, within, Shape};
use crate::nest::decode::{At, Decoded, HoleBin};
use crate::nest::place::{Bin, Container, Placed, Variant};

/// Candidates the placer tries in a room, as the decoder's in a hole.
const CANDIDATES: usize = 2_000;

/// A room and what it refused: (host's part, its turn and mirror, which
/// room, the guests there relative to the host, the part refused).
pub(super) type Refused = HashSet<Vec<i64>>;

/// Where a loose copy goes: `piece` (index into the layout, and into bin
/// `b`'s copies) into room `room` of the copy at `host`, as `placed`;
/// `bin` the hole bin already open for that room, if any.
pub(super) struct Housing {
    pub(super) piece: usize,
    /// The sheet the room is on.
    sheet: usize,
    host: At,
    room: Shape,
    bin: Option<usize>,
    placed: Placed,
}

/// A room of a copy of bin `b`, where that copy now lies.
struct Room {
    host: At,
    sheet: usize,
    shape: Shape,
    /// The hole bin holding its guests (none: empty).
    bin: Option<usize>,
    /// Room area less its guests'.
    free: f64,
    /// [`Refused`]'s key less the part.
    key: Vec<i64>,
}

/// Millionths of a millimetre, for keys.
fn micro(x: f64) -> i64 {
    (x * 1e6).round() as i64
}

/// The rooms of every copy on bin `b` (on it, or in a hole of one on it).
fn rooms(kit: &Kit, d: &Decoded, b: usize) -> Vec<Room> {
    let mut hosts: Vec<(At, &Placed)> = d.bins[b]
        .placed
        .iter()
        .enumerate()
        .map(|(i, p)| (At::Sheet(b, i), p))
        .collect();
    for (j, h) in d.holes.iter().enumerate() {
        if h.sheet == b {
            hosts.extend(
                h.bin
                    .placed
                    .iter()
                    .enumerate()
                    .map(|(i, p)| (At::Hole(j, i), p)),
            );
        }
    }
    let mut out = Vec::new();
    for (at, p) in hosts {
        let v = &kit.items[p.item].variants[p.variant];
        let shapes: Vec<Shape> = v.holes.iter().map(|r| r.moved(p.t)).collect();
        // Each open hole bin of this host is one of its rooms: the one
        // whose box holds its first guest's centre.
        let mut bins: Vec<Option<usize>> = vec![None; shapes.len()];
        for (j, h) in d.holes.iter().enumerate() {
            let Some(g) = h.bin.placed.first() else {
                continue;
            };
            if h.host != at {
                continue;
            }
            let c = g.shape.bbox().centre();
            let holds = |s: &Shape| {
                let b = s.bbox();
                (b.min.x..=b.max.x).contains(&c.x) && (b.min.y..=b.max.y).contains(&c.y)
            };
            if let Some(r) = shapes.iter().position(holds) {
                bins[r] = Some(j);
            }
        }
        for (r, shape) in shapes.into_iter().enumerate() {
            let guests: &[Placed] = bins[r].map_or(&[], |j| &d.holes[j].bin.placed);
            let area = |q: &Placed| {
                kit.items[q.item].variants[q.variant]
                    .shape
                    .poly
                    .area()
                    .abs()
            };
            let free = shape.poly.area().abs() - guests.iter().map(area).sum::<f64>();
            let mut key = vec![
                p.item as i64,
                v.rotation.to_bits() as i64,
                v.mirror as i64,
                r as i64,
            ];
            for g in guests {
                let rel = g.t.sub(p.t);
                key.extend([g.item as i64, g.variant as i64, micro(rel.x), micro(rel.y)]);
            }
            out.push(Room {
                host: at,
                sheet: b,
                shape,
                bin: bins[r],
                free,
                key,
            });
        }
    }
    out
}

/// A copy of bin `b` (the copies of `lay`) that a room on one of the
/// bins `on` takes, those furthest right tried first; None when none does
/// or `budget` ran out. Copies holding others are not moved (their guests
/// would have to move into the room too).
pub(super) fn find(
    kit: &Kit,
    d: &Decoded,
    b: usize,
    on: &[usize],
    lay: &Layout,
    refused: &mut Refused,
    budget: &mut super::Budget,
) -> Option<Housing> {
    let rooms: Vec<Room> = on.iter().flat_map(|&s| rooms(kit, d, s)).collect();
    if rooms.is_empty() {
        return None;
    }
    let n = lay.pieces.len();
    let hosting = |k: usize| {
        d.holes
            .iter()
            .any(|h| h.host == At::Sheet(b, k) && !h.bin.placed.is_empty())
    };
    let mut loose: Vec<usize> = (0..n).filter(|&k| !hosting(k)).collect();
    let right = |k: usize| lay.pieces[k].shape.bbox().max.x;
    loose.sort_by(|&a, &c| right(c).total_cmp(&right(a)).then(a.cmp(&c)));
    for k in loose {
        let item = lay.pieces[k].item;
        // Guests keep the part's own turns: variants gained by free turns
        // are dropped when the layouts stop using them.
        let variants = &kit.items[item].variants[..kit.base[item]];
        let area = variants[0].shape.poly.area().abs();
        for room in &rooms {
            // Not into its own rooms, nor where it cannot fit.
            if room.host == At::Sheet(b, k) || room.free < area {
                continue;
            }
            let mut key = room.key.clone();
            key.push(item as i64);
            if refused.contains(&key) {
                continue;
            }
            if !budget() {
                return None;
            }
            let mut bin = Bin::within(room.shape.clone(), Container::EVERYWHERE, Vec::new());
            if let Some(j) = room.bin {
                bin.placed = d.holes[j].bin.placed.clone();
                bin.right = bin
                    .placed
                    .iter()
                    .map(|q| q.shape.bbox().max.x)
                    .fold(bin.right, f64::max);
            }
            let placed = if bin.place_as(item, variants, None, kit.eps, CANDIDATES) {
                bin.placed.pop()
            } else {
                by_grid(&bin, item, variants, kit.eps)
            };
            if let Some(placed) = placed {
                return Some(Housing {
                    piece: k,
                    sheet: room.sheet,
                    host: room.host,
                    room: room.shape.clone(),
                    bin: room.bin,
                    placed,
                });
            }
            refused.insert(key);
        }
    }
    None
}

/// Steps of the grid across the copy's size ([`by_grid`]).
const GRID: f64 = 4.0;

/// A free position in `bin` (a room) for a copy of `item`, when the
/// placer found none: its candidates lie on the room's box edges and on
/// the guests' levels, so a room whose box corners are far outside it (a
/// diamond bore: the flanges' square plates turned 45°) stayed empty,
/// as it does for the decoder. Positions on a grid of a quarter of the
/// copy's size across the room's box, leftmost then lowest first; the
/// first free one slid left and down while it stays free (a bottom-left
/// fill's rest).
fn by_grid(bin: &Bin, item: usize, variants: &[Variant], eps: f64) -> Option<Placed> {
    let c = bin.container;
    for (vi, v) in variants.iter().enumerate() {
        let vb = *v.shape.bbox();
        let (w, h) = (vb.max.x - vb.min.x, vb.max.y - vb.min.y);
        if w > c.x1 - c.x0 || h > c.y1 - c.y0 {
            continue;
        }
        let step = fmax(w, h) / GRID;
        let (nx, ny) = (
            ((c.x1 - c.x0 - w) / step) as usize,
            ((c.y1 - c.y0 - h) / step) as usize,
        );
        let free = |t: Point| bin.free(&v.shape.moved(t), eps);
        let at = |i: usize, j: usize| {
            Point::new(
                c.x0 - vb.min.x + i as f64 * step,
                c.y0 - vb.min.y + j as f64 * step,
            )
        };
        let Some(mut t) = (0..=nx)
            .flat_map(|i| (0..=ny).map(move |j| (i, j)))
            .map(|(i, j)| at(i, j))
            .find(|&t| free(t))
        else {
            continue;
        };
        let mut d = step / 2.0;
        while d > eps {
            let left = Point::new(t.x - d, t.y);
            let down = Point::new(t.x, t.y - d);
            if free(left) {
                t = left;
            } else if free(down) {
                t = down;
            } else {
                d /= 2.0;
            }
        }
        return Some(Placed {
            item,
            variant: vi,
            t,
            shape: v.shape.moved(t),
        });
    }
    None
}

/// True when `h` is sound by the exact test: the copy within its room
/// and clear of the guests there.
pub(super) fn housed(d: &Decoded, h: &Housing, eps: f64) -> bool {
    let guests: &[Placed] = h.bin.map_or(&[], |j| &d.holes[j].bin.placed);
    within(&h.room, &h.placed.shape, eps)
        && !guests
            .iter()
            .any(|g| overlaps(&g.shape, &h.placed.shape, eps))
}

/// `d` with `h` done: the copy out of bin `b` and into its room's hole
/// bin (opened when the room had none; on the room's sheet), the hole
/// bins it held (empty) closed, every index renumbered.
pub(super) fn house(d: &mut Decoded, b: usize, h: Housing) {
    let k = h.piece;
    let j = match h.bin {
        Some(j) => j,
        None => {
            d.holes.push(HoleBin {
                bin: Bin::within(h.room, Container::EVERYWHERE, Vec::new()),
                sheet: h.sheet,
                host: h.host,
            });
            d.holes.len() - 1
        }
    };
    let bin = &mut d.holes[j].bin;
    bin.right = bin.right.max(h.placed.shape.bbox().max.x);
    bin.placed.push(h.placed);
    d.bins[b].placed.remove(k);
    // The moved copy's own (empty) hole bins close; the others' indices
    // follow.
    let gone = At::Sheet(b, k);
    let mut index = Vec::with_capacity(d.holes.len());
    let mut kept = 0;
    for hb in &d.holes {
        if hb.host == gone {
            index.push(usize::MAX);
        } else {
            index.push(kept);
            kept += 1;
        }
    }
    let holes = std::mem::take(&mut d.holes);
    d.holes = holes
        .into_iter()
        .filter(|hb| hb.host != gone)
        .map(|mut hb| {
            hb.host = match hb.host {
                At::Sheet(s, i) if s == b && i > k => At::Sheet(s, i - 1),
                At::Hole(j, i) => At::Hole(index[j], i),
                at => at,
            };
            hb
        })
        .collect();
}

impl super::Improver {
    /// A loose copy moved into a room ([`find`]), the nest kept when the
    /// exact test agrees; when none moves, nothing is tried again until
    /// the best nest changes. On a strip, its copies; on fixed sheets, any
    /// sheet's, the last sheet's first, into a room on any sheet: a copy
    /// in a hole takes no sheet room, so the last sheet shortens or an
    /// earlier one frees room for its copies ([`Self::relocate`]); without
    /// it the flanges' diamond plates kept their bores empty while their
    /// discs took a sheet of their own. Returns false when `found`
    /// cancelled.
    pub(super) fn house(
        &mut self,
        budget: &mut super::Budget,
        found: &mut dyn FnMut(&Decoded, &[crate::nest::decode::Item]) -> bool,
    ) -> bool {
        self.housed = true;
        // The bins whose copies `lay` lists, in its order.
        let sheets: Vec<usize> = match self.bays {
            Some(_) => (0..self.best.bins.len()).collect(),
            None => vec![self.b],
        };
        // Where each one's copies start in the layout.
        let mut first = Vec::with_capacity(sheets.len() + 1);
        first.push(0);
        for &s in &sheets {
            first.push(first.last().copied().unwrap_or(0) + self.best.bins[s].placed.len());
        }
        let mut taken = None;
        for (j, &s) in sheets.iter().enumerate().rev() {
            let mine = Layout {
                pieces: self.lay.pieces[first[j]..first[j + 1]].to_vec(),
                room: self.lay.room,
                bays: Vec::new(),
            };
            let h = find(
                &self.kit,
                &self.best,
                s,
                &sheets,
                &mine,
                &mut self.refused,
                budget,
            );
            if let Some(h) = h {
                taken = Some((j, h));
                break;
            }
        }
        let Some((j, h)) = taken else {
            return true;
        };
        if !housed(&self.best, &h, self.kit.eps) {
            return true;
        }
        let k = first[j] + h.piece;
        let mut best = std::mem::replace(&mut self.best, Decoded::empty());
        house(&mut best, sheets[j], h);
        let mut lay = self.lay.clone();
        lay.pieces.remove(k);
        // A host holds its guests at its turn.
        let hosts = super::hosts_of(&best);
        let at = sheets
            .iter()
            .flat_map(|&s| (0..best.bins[s].placed.len()).map(move |i| (s, i)));
        for (p, si) in lay.pieces.iter_mut().zip(at) {
            p.turn = !hosts.iter().any(|&(r, n)| r == si && n > 0);
        }
        self.take_moved(lay, best, found)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nest::decode::{decode, sheet_room, Item};
    use crate::nest::rng::SplitMix;
    use crate::nest::shape::Polygon;
    use crate::nest::{NestJob, Sheets};

    const PLATE: f64 = 40.0;
    const BORE: f64 = 12.0;
    const DISC: f64 = 5.0;
    /// Vertices of the round polygons.
    const N: usize = 48;

    fn ring(c: Point, r: f64) -> Vec<Point> {
        (0..N)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / N as f64;
                Point::new(c.x + r * a.cos(), c.y + r * a.sin())
            })
            .collect()
    }

    fn variant(outer: Vec<Point>, holes: Vec<Vec<Point>>) -> Variant {
        Variant {
            rotation: 0.0,
            mirror: false,
            shape: Shape::new(Polygon::new(outer)),
            holes: holes
                .into_iter()
                .map(|h| Shape::new(Polygon::new(h)))
                .collect(),
        }
    }

    /// A square plate with a round bore, and a disc that fits in it, on
    /// a strip as high as the plate; the disc first in the order, so the
    /// decoder leaves it on the strip beside the plate (no hole is open
    /// when it comes).
    fn loose_disc() -> (Vec<Item>, Decoded) {
        loose_disc_on(Sheets::Strip { height: PLATE })
    }

    /// [`loose_disc`] on `sheets`.
    fn loose_disc_on(sheets: Sheets) -> (Vec<Item>, Decoded) {
        let square = vec![
            Point::new(0.0, 0.0),
            Point::new(PLATE, 0.0),
            Point::new(PLATE, PLATE),
            Point::new(0.0, PLATE),
        ];
        let centre = Point::new(PLATE / 2.0, PLATE / 2.0);
        let items = vec![
            Item {
                part: 0,
                variants: vec![variant(square, vec![ring(centre, BORE)])],
            },
            Item {
                part: 1,
                variants: vec![variant(ring(Point::new(0.0, 0.0), DISC), Vec::new())],
            },
        ];
        let d = decode(
            &items,
            &[(1, None), (0, None)],
            &sheet_room(&NestJob::touching(Vec::new(), sheets)).unwrap(),
            1e-9,
        );
        (items, d)
    }

    /// Distance from `c` of the farthest vertex of `s`.
    fn reach(s: &Shape, c: Point) -> f64 {
        s.poly.pts.iter().map(|p| p.dist(c)).fold(0.0, f64::max)
    }

    /// `start` after [`super::super::improve`] for 2 000 moves (seed 3,
    /// no free turns).
    fn improved(items: &[Item], start: Decoded) -> Decoded {
        let mut moves = 0u64;
        let mut budget = || {
            moves += 1;
            moves < 2_000
        };
        let (after, _) = super::super::improve(
            items,
            &[false, false],
            start,
            0.0,
            1e-9,
            &mut SplitMix(3),
            &mut budget,
            &mut |_, _| true,
        );
        after
    }

    /// The one hole bin of `d` holding copies, hosted by the first copy
    /// of sheet 0.
    fn the_guests(d: &Decoded) -> &HoleBin {
        let guests: Vec<&HoleBin> = d
            .holes
            .iter()
            .filter(|h| !h.bin.placed.is_empty())
            .collect();
        assert_eq!(guests.len(), 1);
        assert_eq!(guests[0].host, At::Sheet(0, 0));
        guests[0]
    }

    /// Every vertex of `disc` (convex) left of every edge of `plate`'s
    /// bore (convex, counter-clockwise): not the engine's collision test.
    fn assert_in_bore(plate: &Placed, disc: &Placed) {
        let bore = ring(plate.t.add(Point::new(PLATE / 2.0, PLATE / 2.0)), BORE);
        for p in &disc.shape.poly.pts {
            for (i, &a) in bore.iter().enumerate() {
                let b = bore[(i + 1) % N];
                assert!(b.sub(a).cross(p.sub(a)) >= -1e-9, "{p:?} outside the bore");
            }
        }
    }

    #[test]
    fn a_loose_disc_ends_in_the_bore_and_rides_with_its_plate() {
        let (items, start) = loose_disc();
        assert_eq!(start.bins[0].placed.len(), 2, "the disc starts loose");
        assert!(start.holes.iter().all(|h| h.bin.placed.is_empty()));
        assert!(
            start.cost.2 >= PLATE + 2.0 * DISC - 1e-9,
            "{:?}",
            start.cost
        );
        let after = improved(&items, start);
        // One copy on the strip, the plate; the disc its guest.
        assert_eq!(after.bins[0].placed.len(), 1);
        let plate = &after.bins[0].placed[0];
        assert_eq!(plate.item, 0);
        let disc = &the_guests(&after).bin.placed[0];
        assert_eq!(disc.item, 1);
        assert_in_bore(plate, disc);
        // (Its shape is the disc where its translation says.)
        assert!((reach(&disc.shape, disc.t) - DISC).abs() < 1e-9);
        // The plate slid left into the disc's place: shorter than any
        // nest with the disc beside the plate (PLATE + 2 DISC).
        assert!(after.cost.2 < PLATE + 0.5, "{:?}", after.cost);
        // Named as the plate's guest in the nest.
        let placements = crate::nest::live::placements(&items, &after, 2);
        let named: Vec<_> = placements.iter().map(|p| (p.part, p.in_hole_of)).collect();
        assert_eq!(named, vec![(0, None), (1, Some((0, 0)))]);
    }

    #[test]
    fn on_fixed_sheets_a_disc_alone_on_a_sheet_goes_into_the_bore_and_the_sheet_is_gone() {
        // Sheets as large as the plate: the disc (first in the order)
        // takes the first sheet, the plate the second.
        let (items, start) = loose_disc_on(Sheets::Rect {
            width: PLATE,
            height: PLATE,
            count: 2,
        });
        assert_eq!(start.bins.len(), 2);
        assert_eq!(start.bins[0].placed[0].item, 1, "the disc on sheet 1");
        let after = improved(&items, start);
        // One sheet: the plate on it, the disc its guest, on that sheet.
        assert_eq!(after.bins.len(), 1);
        assert_eq!(after.cost.1, 1);
        assert_eq!(after.bins[0].placed.len(), 1);
        assert_eq!(after.bins[0].placed[0].item, 0);
        let guests = the_guests(&after);
        assert_eq!(guests.sheet, 0);
        assert_in_bore(&after.bins[0].placed[0], &guests.bin.placed[0]);
        let placements = crate::nest::live::placements(&items, &after, 2);
        let named: Vec<_> = placements
            .iter()
            .map(|p| (p.part, p.sheet, p.in_hole_of))
            .collect();
        assert_eq!(named, vec![(0, 0, None), (1, 0, Some((0, 0)))]);
    }
}
