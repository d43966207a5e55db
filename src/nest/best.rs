//! A search's best nest in a form every search of the same job can take
//! ([`Best`]): placements, not the search's own structures (whose turned
//! variants differ from search to search), plain numbers, so that it
//! crosses a thread or a `postMessage` to a web worker unchanged. A search
//! that adopts it rebuilds the decoded nest from it ([`rebuild`]).

use serde::{Deserialize, Serialize};

use super::collide::{boxes_overlap, within, Shape};
use super::decode::{better, finish, At, Decoded, HoleBin, Item, SheetRoom};
use super::place::{Bin, Container, Placed, Variant};
use super::Placement;
use crate::geom::Point;

/// Numbers per copy in [`Best::copies`]: part, copy, sheet, rotation,
/// mirror (0 or 1), x, y, host part, host copy (−1, −1: on the sheet).
pub const PER_COPY: usize = 9;

/// The best nest of one search, as the others adopt it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Best {
    /// Area of the copies not placed, billionths of all copies' (0: all placed).
    pub lost: usize,
    /// Sheets used.
    pub sheets: usize,
    /// Length used on the last sheet (or of the strip), mm.
    pub length: f64,
    /// The placements, [`PER_COPY`] numbers each, in the nest's order.
    pub copies: Vec<f64>,
    /// The part of every copy that found no room.
    pub unplaced: Vec<usize>,
    /// The part of every copy the first nest never reached (budget, Stop).
    pub stopped: Vec<usize>,
}

impl Best {
    /// `d` (whose copies are variants of `items`) as a best nest.
    pub(super) fn of(items: &[Item], d: &Decoded, parts: usize) -> Best {
        let part = |it: &usize| items[*it].part;
        Best::from_placements(
            &super::live::placements(items, d, parts),
            d.cost,
            (
                d.unplaced.iter().map(part).collect(),
                d.stopped.iter().map(part).collect(),
            ),
        )
    }

    /// A nest of these placements and cost (lost, sheets, length), the
    /// parts of its copies left out (no room; not reached).
    pub(super) fn from_placements(
        placements: &[Placement],
        cost: (usize, usize, f64),
        (unplaced, stopped): (Vec<usize>, Vec<usize>),
    ) -> Best {
        let mut copies = Vec::with_capacity(placements.len() * PER_COPY);
        for p in placements {
            let (hp, hc) = p.in_hole_of.map_or((-1.0, -1.0), |(a, b)| (a as f64, b as f64));
            copies.extend([
                p.part as f64,
                p.copy as f64,
                p.sheet as f64,
                p.rotation,
                f64::from(u8::from(p.mirror)),
                p.translation.x,
                p.translation.y,
                hp,
                hc,
            ]);
        }
        Best {
            lost: cost.0,
            sheets: cost.1,
            length: cost.2,
            copies,
            unplaced,
            stopped,
        }
    }

    /// The placements.
    pub fn placements(&self) -> Vec<Placement> {
        self.copies
            .chunks_exact(PER_COPY)
            .map(|c| Placement {
                part: c[0] as usize,
                copy: c[1] as usize,
                sheet: c[2] as usize,
                rotation: c[3],
                mirror: c[4] != 0.0,
                translation: Point::new(c[5], c[6]),
                in_hole_of: (c[7] >= 0.0).then_some((c[7] as usize, c[8] as usize)),
            })
            .collect()
    }

    fn cost(&self) -> (usize, usize, f64) {
        (self.lost, self.sheets, self.length)
    }

    /// True when this nest is better than `other` (fewer copies left out,
    /// fewer sheets, then shorter by more than `eps`, mm).
    pub fn better_than(&self, other: &Best, eps: f64) -> bool {
        better(self.cost(), other.cost(), eps)
    }
}

/// Which of `bests` all the searches adopt: the best, the lowest index
/// among equals (a later one must be better by more than `eps` to win).
pub fn pick(bests: &[&Best], eps: f64) -> usize {
    let mut k = 0;
    for (i, b) in bests.iter().enumerate().skip(1) {
        if b.better_than(bests[k], eps) {
            k = i;
        }
    }
    k
}

/// `best` made again as a decoded nest of `base`'s items (plus a variant
/// for every angle a copy took by a free turn) and those items; `order`
/// is every copy, for the cost's share of area. None when it names a part,
/// sheet or host that does not exist (it came from a page: never trusted).
pub(super) fn rebuild(
    best: &Best,
    base: &[Item],
    order: &[(usize, Option<usize>)],
    sheet: &SheetRoom,
    eps: f64,
) -> Option<(Decoded, Vec<Item>)> {
    let mut items = base.to_vec();
    let item_of = |part: usize| items.iter().position(|it| it.part == part);
    let item_of: Vec<Option<usize>> = (0..=base.iter().map(|it| it.part).max().unwrap_or(0))
        .map(item_of)
        .collect();
    let item = |part: usize| item_of.get(part).copied().flatten();
    let mut bins: Vec<Bin> = Vec::new();
    let mut holes: Vec<HoleBin> = Vec::new();
    // Per hole bin: its host and which of the host's rooms it is.
    let mut rooms: Vec<(At, usize)> = Vec::new();
    let mut at_of: Vec<((usize, usize), At)> = Vec::new();
    for p in best.placements() {
        let it = item(p.part)?;
        let v = variant(&mut items[it], p.rotation, p.mirror)?;
        let shape = items[it].variants[v].shape.moved(p.translation);
        let placed = Placed {
            item: it,
            variant: v,
            t: p.translation,
            shape,
        };
        let at = match p.in_hole_of {
            None => {
                while bins.len() <= p.sheet {
                    if bins.len() >= sheet.count() {
                        return None;
                    }
                    bins.push(sheet.bin(bins.len()));
                }
                put(&mut bins[p.sheet], placed);
                At::Sheet(p.sheet, bins[p.sheet].placed.len() - 1)
            }
            Some(host) => {
                let h_at = at_of.iter().find(|(k, _)| *k == host)?.1;
                let h = match h_at {
                    At::Sheet(b, i) => &bins[b].placed[i],
                    At::Hole(j, i) => &holes[j].bin.placed[i],
                };
                let h_sheet = match h_at {
                    At::Sheet(b, _) => b,
                    At::Hole(j, _) => holes[j].sheet,
                };
                let of_host: Vec<Shape> = items[h.item].variants[h.variant]
                    .holes
                    .iter()
                    .map(|r| r.moved(h.t))
                    .collect();
                let r = of_host
                    .iter()
                    .position(|r| within(r, &placed.shape, eps))
                    .or_else(|| {
                        of_host
                            .iter()
                            .position(|r| boxes_overlap(r.bbox(), placed.shape.bbox(), eps))
                    })
                    .or((!of_host.is_empty()).then_some(0))?;
                let j = match rooms.iter().position(|&k| k == (h_at, r)) {
                    Some(j) => j,
                    None => {
                        let room = of_host[r].clone();
                        holes.push(HoleBin {
                            bin: Bin::within(room, Container::EVERYWHERE, Vec::new()),
                            sheet: h_sheet,
                            host: h_at,
                        });
                        rooms.push((h_at, r));
                        holes.len() - 1
                    }
                };
                put(&mut holes[j].bin, placed);
                At::Hole(j, holes[j].bin.placed.len() - 1)
            }
        };
        at_of.push(((p.part, p.copy), at));
    }
    let unplaced = best.unplaced.iter().map(|&p| item(p)).collect::<Option<_>>()?;
    let stopped = best.stopped.iter().map(|&p| item(p)).collect::<Option<_>>()?;
    let d = finish(&items, order, sheet, bins, holes, unplaced, stopped);
    Some((d, items))
}

/// A copy put where it was found (no search): the bin's length follows.
fn put(bin: &mut Bin, p: Placed) {
    bin.right = bin.right.max(p.shape.bbox().max.x);
    bin.placed.push(p);
}

/// The variant of `item` turned `rotation`° (after the mirror when
/// `mirror`): one of its own, or one made for it, as a free turn makes
/// them ([`super::separate::turn`]): its first variant of that mirror
/// turned rigidly.
fn variant(item: &mut Item, rotation: f64, mirror: bool) -> Option<usize> {
    if !rotation.is_finite() {
        return None;
    }
    if let Some(v) = item
        .variants
        .iter()
        .position(|v| v.rotation == rotation && v.mirror == mirror)
    {
        return Some(v);
    }
    let from = item.variants.iter().find(|v| v.mirror == mirror)?;
    let delta = rotation - from.rotation;
    let v = Variant {
        rotation,
        mirror,
        shape: from.shape.turned(delta),
        holes: from.holes.iter().map(|h| h.turned(delta)).collect(),
    };
    item.variants.push(v);
    Some(item.variants.len() - 1)
}
