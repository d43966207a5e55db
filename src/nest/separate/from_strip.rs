//! Fixed sheets started from the strip's nest (issue 44 item 3): the
//! strip of the sheets' height nested first, then cut into sheets.
//!
//! The sheets' own first nest fills them in order, first fit, and ends
//! further from what the bays' exploration ([`super::bays`]) reaches than
//! the strip's first nest does from the strip's end (boxes: 7 % against
//! 2 %), and a failed separation costs 1 100–4 500 moves, so the sheets
//! never close that gap at 10 000 evaluations. The strip's nest laid on
//! the bays as it is (the bays end to end are the strip, the same room
//! along y) is feasible but for the copies that cross a wall: those are
//! outside their bay and separated as any overlap is, the room open to
//! the end of the strip's last sheet, or of one sheet more.

use super::bays::{Bays, BAYS_EPS};
use super::sample::Kit;
use super::{feasible, separate, Budget, NO_GAIN};
use crate::nest::decode::{better, Decoded, Item, SheetRoom};
use crate::nest::rng::SplitMix;

/// The strip's nest `strip` (one bin, the sheets' room along y) on the
/// sheets of `sheet`: the sheets it reaches, or one more, with the copies
/// crossing a wall separated into a bay. None when neither separates, or
/// when no cut can beat `beat` (the cost of the sheets' best nest: the
/// cut uses at least the sheets the strip reaches, its last at least the
/// strip's end on it), or the strip is not the sheets' room, or there
/// are not enough sheets. Returns the nest and the items its copies refer
/// to (with the variants gained by free turns). `free[i]`: item `i` may
/// take any angle.
#[allow(clippy::too_many_arguments)]
pub(in crate::nest) fn sheets_from_strip(
    items: &[Item],
    free: &[bool],
    strip: &Decoded,
    sheet: &SheetRoom,
    beat: (usize, usize, f64),
    eps: f64,
    rng: &mut SplitMix,
    budget: &mut Budget,
) -> Option<(Decoded, Vec<Item>)> {
    let [bin] = &strip.bins[..] else {
        return None;
    };
    let (c, s) = (sheet.container, bin.container);
    let same = |a: f64, b: f64| (a - b).abs() <= eps;
    let alike = same(s.x0, c.x0) && same(s.y0, c.y0) && same(s.y1, c.y1);
    if !alike || !strip.stopped.is_empty() || c.x1 - c.x0 <= 0.0 {
        return None;
    }
    let w = c.x1 - c.x0;
    let need = ((bin.right - c.x0) / w).ceil().max(1.0) as usize;
    let least = (
        strip.cost.0,
        need,
        bin.right - (need - 1) as f64 * w - sheet.origin_x,
    );
    if !better(least, beat, eps) {
        return None;
    }
    let mut kit = Kit::new(items, free.to_vec(), eps * BAYS_EPS);
    for m in [need, need + 1] {
        if m > sheet.count() || (strip.cost.0, m) > (beat.0, beat.1) {
            return None;
        }
        let mut d = strip.clone();
        d.bins[0].container = c;
        d.bins.extend((1..m).map(|k| sheet.bin(k)));
        let bays = Bays::of(&d)?;
        let mut lay = bays.layout(&d);
        lay.room.x1 = bays.rooms()[m - 1].x1;
        let (separated, _) = separate(&mut kit, &mut lay, rng, budget, NO_GAIN);
        if separated && feasible(&kit, &lay) {
            bays.close_empty(&mut lay);
            let d = bays.decoded(d, &lay, sheet.origin_x);
            return Some((d, kit.items));
        }
    }
    None
}
