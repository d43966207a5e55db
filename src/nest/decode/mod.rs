//! Decoding: an order of copies (each maybe held to one turn) placed one
//! by one into the sheets' rooms and the holes of copies already placed
//! (part-in-part: a copy tries the holes first, it then takes no sheet
//! room), and the cost of the result.

use super::collide::Shape;
use super::place::{Bin, Container, Placed, Variant};
use super::shape::{collision_polygon, room_polygon};
use super::{NestJob, Sheets};
use crate::geom::path_bbox;

mod trail;

pub(super) use trail::Trail;
use trail::{Log, Rooms};

/// Most candidate positions tried per copy (best first): bounds the work
/// of one placement on crowded sheets.
const MAX_CANDIDATES: usize = 20_000;
/// The same in a hole: a hole is small and mostly full, and every copy
/// tries the holes first.
const HOLE_CANDIDATES: usize = 2_000;

/// A part made ready for placing.
#[derive(Clone)]
pub(super) struct Item {
    pub(super) part: usize,
    pub(super) variants: Vec<Variant>,
}

/// Where a copy sits: a sheet bin or a hole bin, and its index there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum At {
    Sheet(usize, usize),
    Hole(usize, usize),
}

/// A hole of a placed copy, a room of its own (part-in-part).
#[derive(Clone)]
pub(super) struct HoleBin {
    pub(super) bin: Bin,
    /// The sheet it is on.
    pub(super) sheet: usize,
    /// The copy whose hole it is.
    pub(super) host: At,
}

/// One decoded order.
#[derive(Clone)]
pub(super) struct Decoded {
    pub(super) bins: Vec<Bin>,
    pub(super) holes: Vec<HoleBin>,
    pub(super) unplaced: Vec<usize>,
    /// Copies never tried: the budget ran out (or Stop came) while the
    /// first nest was being placed ([`decode_until`]).
    pub(super) stopped: Vec<usize>,
    /// (area not placed, sheets used, length on the last sheet). The area
    /// is in billionths of all copies' area, rounded up (0 only when every
    /// copy is placed): counting copies, a nest that left out one 200 mm
    /// ring tied with one that left out one 35 mm square, and the shorter
    /// (ring-less) nest won. A shop wants the big part cut.
    pub(super) cost: (usize, usize, f64),
    /// The placer's work for this nest ([`Bin::work`], all bins).
    pub(super) work: u64,
    /// Σ (right edge)² on the last sheet: breaks ties of `cost`, so the
    /// search walks plateaus of equal length towards nests packed left.
    pub(super) gravity: f64,
}

impl Decoded {
    /// A nest of nothing: what a margin leaving no room gives, and a
    /// placeholder while a nest is rebuilt in place.
    pub(super) fn empty() -> Decoded {
        Decoded {
            bins: Vec::new(),
            holes: Vec::new(),
            unplaced: Vec::new(),
            stopped: Vec::new(),
            cost: (0, 0, 0.0),
            work: 0,
            gravity: 0.0,
        }
    }
}

pub(super) fn better(a: (usize, usize, f64), b: (usize, usize, f64), eps: f64) -> bool {
    (a.0, a.1) < (b.0, b.1) || ((a.0, a.1) == (b.0, b.1) && a.2 < b.2 - eps)
}

/// The rooms of a copy's holes where it now lies, as hole bins: only
/// holes with room for the smallest copy's polygon.
fn open_holes(
    items: &[Item],
    placed: &Placed,
    at: At,
    sheet: usize,
    smallest: f64,
    holes: &mut Vec<HoleBin>,
) {
    for room in &items[placed.item].variants[placed.variant].holes {
        if room.poly.area() >= smallest {
            holes.push(HoleBin {
                bin: Bin::within(room.moved(placed.t), Container::EVERYWHERE, Vec::new()),
                sheet,
                host: at,
            });
        }
    }
}

/// An order of copies, each maybe held to one turn.
pub(super) type Order = Vec<(usize, Option<usize>)>;

/// The nest of `order` (the tests' constructive nests).
#[cfg(test)]
pub(super) fn decode(
    items: &[Item],
    order: &[(usize, Option<usize>)],
    sheet: &SheetRoom,
    eps: f64,
) -> Decoded {
    decode_until(items, order, sheet, eps, &mut |_, _| true).nest
}

/// [`decode`] of `order` from where `parent` stood after the positions
/// the two orders share: the same nest and trail as decoding it whole.
pub(super) fn decode_after(
    items: &[Item],
    order: &[(usize, Option<usize>)],
    sheet: &SheetRoom,
    eps: f64,
    parent: &Trail,
) -> Trail {
    let shared = order
        .iter()
        .zip(&parent.order)
        .take_while(|(a, b)| a == b)
        .count()
        .min(parent.done);
    place_from(
        items,
        order,
        sheet,
        eps,
        parent.rooms_after(shared),
        shared,
        &mut |_, _| true,
    )
}

/// [`decode`], asking `go(k, partial)` before placing the copy at `k` of
/// the order (k ≥ 1; `partial()` is the nest of the copies before it, the
/// rest not placed): false stops there, the copies from `k` on are left
/// out as `stopped`. The first nest of a 200-copy sheet takes seconds; the
/// time budget and Stop must hold during it too, and a nest of the copies
/// placed so far is always a valid nest.
pub(super) fn decode_until(
    items: &[Item],
    order: &[(usize, Option<usize>)],
    sheet: &SheetRoom,
    eps: f64,
    go: &mut dyn FnMut(usize, &dyn Fn() -> Decoded) -> bool,
) -> Trail {
    place_from(items, order, sheet, eps, Rooms::default(), 0, go)
}

/// Places the copies of `order` from position `from` on into `rooms`
/// (where the positions before it left them), as [`decode_until`].
fn place_from(
    items: &[Item],
    order: &[(usize, Option<usize>)],
    sheet: &SheetRoom,
    eps: f64,
    rooms: Rooms,
    from: usize,
    go: &mut dyn FnMut(usize, &dyn Fn() -> Decoded) -> bool,
) -> Trail {
    let Rooms {
        mut bins,
        mut holes,
        mut unplaced,
        mut logs,
    } = rooms;
    let smallest = items
        .iter()
        .map(|it| it.variants[0].shape.poly.area())
        .fold(f64::INFINITY, f64::min);
    let mut stopped = Vec::new();
    for (k, &(it, only)) in order.iter().enumerate().skip(from) {
        if k > 0 {
            let partial = || {
                let rest = order[k..].iter().map(|o| o.0).collect();
                finish(
                    items,
                    order,
                    sheet,
                    bins.clone(),
                    holes.clone(),
                    unplaced.clone(),
                    rest,
                )
            };
            if !go(k, &partial) {
                stopped = order[k..].iter().map(|o| o.0).collect();
                break;
            }
        }
        let v = &items[it].variants;
        let key = (it, only);
        // Holes first: a copy in a hole takes no sheet room.
        let in_hole = holes.iter_mut().zip(&mut logs.holes).position(|(h, log)| {
            log.try_place(&mut h.bin, k, key, |b| {
                b.place_as(it, v, only, eps, HOLE_CANDIDATES)
            })
        });
        let at = match in_hole {
            Some(h) => Some((At::Hole(h, holes[h].bin.placed.len() - 1), holes[h].sheet)),
            None => {
                let mut at = bins.iter_mut().zip(&mut logs.bins).position(|(b, log)| {
                    log.try_place(b, k, key, |b| b.place_as(it, v, only, eps, MAX_CANDIDATES))
                });
                if at.is_none() && bins.len() < sheet.count() {
                    let mut b = sheet.bin(bins.len());
                    if b.place_as(it, v, only, eps, MAX_CANDIDATES) {
                        logs.bins.push(Log {
                            placed: vec![k],
                            work: vec![(k, b.work)],
                            ..Log::born(k)
                        });
                        bins.push(b);
                        at = Some(bins.len() - 1);
                    }
                }
                at.map(|b| (At::Sheet(b, bins[b].placed.len() - 1), b))
            }
        };
        match at {
            Some((a, s)) => {
                let p = match a {
                    At::Sheet(b, i) => bins[b].placed[i].clone(),
                    At::Hole(h, i) => holes[h].bin.placed[i].clone(),
                };
                open_holes(items, &p, a, s, smallest, &mut holes);
                logs.holes.resize_with(holes.len(), || Log::born(k));
            }
            None => {
                unplaced.push(it);
                logs.unplaced.push(k);
            }
        }
    }
    let done = order.len() - stopped.len();
    Trail {
        nest: finish(items, order, sheet, bins, holes, unplaced, stopped),
        order: order.to_vec(),
        done,
        logs,
    }
}

/// The decoded nest of `bins` and `holes` and its cost.
pub(super) fn finish(
    items: &[Item],
    order: &[(usize, Option<usize>)],
    sheet: &SheetRoom,
    bins: Vec<Bin>,
    holes: Vec<HoleBin>,
    unplaced: Vec<usize>,
    stopped: Vec<usize>,
) -> Decoded {
    let x0 = sheet.origin_x;
    let last = bins.last().map_or(0.0, |b| b.right - x0);
    let out: Vec<usize> = unplaced.iter().chain(&stopped).copied().collect();
    let cost = (unplaced_weight(items, order, &out), bins.len(), last);
    let gravity = bins.last().map_or(0.0, |b| {
        b.placed
            .iter()
            .map(|p| (p.shape.bbox().max.x - x0).powi(2))
            .sum()
    });
    let work =
        bins.iter().map(|b| b.work).sum::<u64>() + holes.iter().map(|h| h.bin.work).sum::<u64>();
    Decoded {
        bins,
        holes,
        unplaced,
        stopped,
        work,
        cost,
        gravity,
    }
}

/// The area of the copies not placed, in billionths of all copies' area,
/// rounded up ([`Decoded::cost`]).
fn unplaced_weight(items: &[Item], order: &[(usize, Option<usize>)], unplaced: &[usize]) -> usize {
    if unplaced.is_empty() {
        return 0;
    }
    let area = |it: usize| items[it].variants[0].shape.poly.area().abs();
    let total: f64 = order.iter().map(|&(it, _)| area(it)).sum();
    let lost: f64 = unplaced.iter().map(|&it| area(it)).sum();
    if !(total > 0.0 && lost.is_finite()) {
        return unplaced.len();
    }
    ((lost / total * 1e9).ceil() as usize).max(1)
}

/// Where grown shapes may lie on each sheet. A rectangle or strip: its
/// box less the margin, grown back by half the spacing (the shapes are
/// grown by it). A remnant: its outline shrunk likewise, its no-go zones
/// grown by what the margin asks beyond half the spacing. None when the
/// margin leaves no room.
pub(super) fn sheet_room(job: &NestJob) -> Option<SheetRoom> {
    let s = &job.settings;
    let grow = s.spacing / 2.0;
    let (x0, y0) = (s.margin - grow, s.margin - grow);
    let rect = |width: f64, height: f64| Container {
        x0,
        y0,
        x1: width - s.margin + grow,
        y1: height - s.margin + grow,
    };
    let boxes = |sizes: Vec<(Container, usize)>| SheetRoom {
        container: sizes.first().map_or(rect(0.0, 0.0), |c| c.0),
        sizes,
        bound: None,
        obstacles: Vec::new(),
        origin_x: 0.0,
    };
    Some(match &job.sheets {
        Sheets::Rect {
            width,
            height,
            count,
        } => boxes(vec![(rect(*width, *height), *count)]),
        Sheets::Mixed(v) => boxes(
            v.iter()
                .map(|z| (rect(z.width, z.height), z.count))
                .collect(),
        ),
        Sheets::Strip { height } => boxes(vec![(rect(f64::INFINITY, *height), 1)]),
        Sheets::Remnant { outline, no_go } => {
            let bound = Shape::new(room_polygon(outline, s.margin - grow, s.tolerance)?);
            let obstacles = no_go
                .iter()
                .filter_map(|z| collision_polygon(z, s.margin - grow, s.tolerance))
                .map(Shape::new)
                .collect();
            let b = *bound.bbox();
            let container = Container {
                x0: b.min.x,
                y0: b.min.y,
                x1: b.max.x,
                y1: b.max.y,
            };
            SheetRoom {
                container,
                sizes: vec![(container, 1)],
                bound: Some(bound),
                obstacles,
                origin_x: path_bbox(outline).min.x,
            }
        }
    })
}

/// The room on every sheet: its box, and for an irregular sheet its
/// outline and no-go zones.
pub(super) struct SheetRoom {
    /// The first sheet's box.
    pub(super) container: Container,
    /// Each size's box and how many sheets of it, in the order filled.
    sizes: Vec<(Container, usize)>,
    bound: Option<Shape>,
    obstacles: Vec<Shape>,
    /// Where the sheet starts along x (lengths are measured from here).
    pub(super) origin_x: f64,
}

impl SheetRoom {
    /// How many sheets.
    pub(super) fn count(&self) -> usize {
        self.sizes.iter().map(|s| s.1).sum()
    }

    /// Whether `v` fits on some sheet's box.
    pub(super) fn fits(&self, v: &Variant) -> bool {
        self.sizes.iter().any(|s| s.0.fits(v))
    }

    /// Sheet `k`'s box (past the last: the last's).
    fn container_of(&self, k: usize) -> Container {
        let mut left = k;
        for &(c, n) in &self.sizes {
            if left < n {
                return c;
            }
            left -= n;
        }
        self.sizes.last().map_or(self.container, |s| s.0)
    }

    /// An empty bin for sheet `k`.
    pub(super) fn bin(&self, k: usize) -> Bin {
        let container = self.container_of(k);
        match &self.bound {
            Some(b) => Bin::within(b.clone(), container, self.obstacles.clone()),
            None => {
                let mut bin = Bin::new(container);
                bin.obstacles = self.obstacles.clone();
                bin
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point;
    use crate::nest::shape::Polygon;

    fn poly(pts: &[(f64, f64)]) -> Polygon {
        Polygon::new(pts.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    /// A ring with room for the small squares in its hole, the squares,
    /// an L, a triangle and an irregular heptagon, each at the four right
    /// angles; and an order of all their copies, part by part.
    fn items() -> (Vec<Item>, Order) {
        let ring = poly(&[(0.0, 0.0), (30.0, 0.0), (30.0, 30.0), (0.0, 30.0)]);
        let hole = poly(&[(5.0, 5.0), (25.0, 5.0), (25.0, 25.0), (5.0, 25.0)]);
        let outlines = [
            (ring, vec![hole], 3),
            (
                poly(&[(0.0, 0.0), (8.0, 0.0), (8.0, 8.0), (0.0, 8.0)]),
                vec![],
                6,
            ),
            (
                poly(&[
                    (0.0, 0.0),
                    (20.0, 0.0),
                    (20.0, 4.0),
                    (4.0, 4.0),
                    (4.0, 10.0),
                    (0.0, 10.0),
                ]),
                vec![],
                4,
            ),
            (poly(&[(0.0, 0.0), (17.0, 0.0), (5.0, 13.0)]), vec![], 4),
            (
                poly(&[
                    (0.0, 2.0),
                    (6.0, 0.0),
                    (14.0, 1.0),
                    (16.0, 8.0),
                    (9.0, 9.5),
                    (7.0, 14.0),
                    (1.0, 10.0),
                ]),
                vec![],
                3,
            ),
        ];
        let items = outlines
            .iter()
            .enumerate()
            .map(|(part, (outer, holes, _))| Item {
                part,
                variants: [0.0, 90.0, 180.0, 270.0]
                    .into_iter()
                    .map(|rotation| Variant {
                        rotation,
                        mirror: false,
                        shape: Shape::with_core(outer.placed(rotation, false, Point::default())),
                        holes: holes
                            .iter()
                            .map(|h| Shape::with_core(h.placed(rotation, false, Point::default())))
                            .collect(),
                    })
                    .collect(),
            })
            .collect();
        let order = outlines
            .iter()
            .enumerate()
            .flat_map(|(i, o)| std::iter::repeat_n((i, None), o.2))
            .collect();
        (items, order)
    }

    fn room(sheets: Sheets) -> SheetRoom {
        sheet_room(&NestJob::touching(Vec::new(), sheets)).unwrap()
    }

    /// Everything a nest and its trail are, bit for bit.
    fn fingerprint(t: &Trail) -> String {
        let bin = |b: &Bin| {
            let placed: Vec<_> = b
                .placed
                .iter()
                .map(|p| {
                    let bb = p.shape.bbox();
                    (
                        p.item,
                        p.variant,
                        [p.t.x, p.t.y, bb.min.x, bb.min.y, bb.max.x, bb.max.y].map(f64::to_bits),
                    )
                })
                .collect();
            format!(
                "{:?} {} {} {placed:?}",
                b.container,
                b.right.to_bits(),
                b.work
            )
        };
        let d = &t.nest;
        let bins: Vec<_> = d.bins.iter().map(bin).collect();
        let holes: Vec<_> = d
            .holes
            .iter()
            .map(|h| format!("{} {:?} {}", h.sheet, h.host, bin(&h.bin)))
            .collect();
        format!(
            "{bins:?} {holes:?} {:?} {:?} {} {} {} {} {} {:?} {} {:?}",
            d.unplaced,
            d.stopped,
            d.cost.0,
            d.cost.1,
            d.cost.2.to_bits(),
            d.work,
            d.gravity.to_bits(),
            t.order,
            t.done,
            t.logs,
        )
    }

    /// One of the sequence search's changes, at random.
    fn mutate(o: &mut Order, r: &mut impl FnMut() -> f64) {
        let n = o.len();
        let (i, j) = ((r() * n as f64) as usize, (r() * n as f64) as usize);
        match (r() * 3.0) as usize {
            0 => o[i].1 = [None, Some(0), Some(1), Some(2), Some(3)][(r() * 5.0) as usize],
            1 => o.swap(i, j),
            _ => {
                let x = o.remove(i);
                o.insert(j, x);
            }
        }
    }

    /// Chains of changes, each decoded from the one before's trail (a
    /// trail that was itself decoded from another's), on a strip, on two
    /// fixed sheets too small for all copies, and with holes: the same
    /// nest and trail as decoding the order whole.
    #[test]
    fn a_decode_from_the_shared_prefix_is_the_whole_decode() {
        let (items, order) = items();
        let sheets = [
            Sheets::Strip { height: 40.0 },
            Sheets::Rect {
                width: 70.0,
                height: 40.0,
                count: 2,
            },
        ];
        for (s, sheets) in sheets.into_iter().enumerate() {
            let sheet = room(sheets);
            let mut r = crate::test_rng::unit(11 + s as u64);
            let mut cur = decode_until(&items, &order, &sheet, 1e-9, &mut |_, _| true);
            let (mut shared, mut unplaced, mut in_holes) = (0, 0, 0);
            for _ in 0..60 {
                let mut o = cur.order.clone();
                mutate(&mut o, &mut r);
                let after = decode_after(&items, &o, &sheet, 1e-9, &cur);
                let whole = decode_until(&items, &o, &sheet, 1e-9, &mut |_, _| true);
                assert_eq!(fingerprint(&after), fingerprint(&whole));
                shared += o.iter().zip(&cur.order).take_while(|(a, b)| a == b).count();
                unplaced += after.nest.unplaced.len();
                in_holes += after
                    .nest
                    .holes
                    .iter()
                    .map(|h| h.bin.placed.len())
                    .sum::<usize>();
                // Taken half the time, as the search takes changes no worse.
                if r() < 0.5 {
                    cur = after;
                }
            }
            // The cases meant: prefixes shared, copies in holes, and (on
            // the sheets) copies left out.
            assert!(shared > 60 * 3, "{shared}");
            assert!(in_holes > 0);
            assert_eq!(unplaced > 0, s == 1, "{unplaced}");
        }
    }

    /// A first nest stopped part way (the budget, Stop) gives a trail of
    /// the copies placed: an order decoded after it is the whole decode.
    #[test]
    fn a_decode_after_a_stopped_nest_is_the_whole_decode() {
        let (items, order) = items();
        let sheet = room(Sheets::Strip { height: 40.0 });
        let stopped = decode_until(&items, &order, &sheet, 1e-9, &mut |k, _| k < 9);
        assert_eq!(
            (stopped.done, stopped.nest.stopped.len()),
            (9, order.len() - 9)
        );
        let mut o = order.clone();
        o.swap(12, 15);
        let after = decode_after(&items, &o, &sheet, 1e-9, &stopped);
        let whole = decode_until(&items, &o, &sheet, 1e-9, &mut |_, _| true);
        assert_eq!(fingerprint(&after), fingerprint(&whole));
        assert!(after.nest.stopped.is_empty());
    }
}
