//! The exploration's way out of a length it cannot reach: sparrow's pool
//! of failed layouts and its disruption (Gardeyn & Wauters, EJOR 2025,
//! arXiv 2509.13329, the exploration phase), written for this engine.
//!
//! A separation that fails at a length leaves its least-overlapping
//! layout. Trying again from that same layout (what the engine did
//! before) walks back into the same basin: jakobs1, seed 2, made no
//! gain from 17 k to 447 k moves. Here every failed layout goes into a
//! [`Pool`] ordered by its overlap, and the next try starts from one of
//! them, the less overlapping ones chosen more often, with two large
//! copies of different parts swapped ([`swap_large`]): a layout that is
//! neither the best nor the last failure, shaken where it matters.

use super::sample::{Kit, Layout, Piece};
use crate::geom::{fmax, fmin};
use crate::nest::rng::SplitMix;

/// Failed layouts at one length, least overlap first.
pub(super) struct Pool {
    kept: Vec<(f64, Layout)>,
    most: usize,
}

impl Pool {
    /// An empty pool keeping at most `most` layouts (the least
    /// overlapping ones).
    pub(super) fn new(most: usize) -> Pool {
        Pool {
            kept: Vec::with_capacity(most + 1),
            most: most.max(1),
        }
    }

    /// Forgets every layout (a new length is tried).
    pub(super) fn clear(&mut self) {
        self.kept.clear();
    }

    /// The layouts kept (their variants are renumbered with the kit's,
    /// [`Kit::compact`]).
    pub(super) fn layouts_mut(&mut self) -> impl Iterator<Item = &mut Layout> {
        self.kept.iter_mut().map(|(_, l)| l)
    }

    /// Keeps `lay`, which separated down to `overlap`; a layout of equal
    /// overlap goes after the ones already kept.
    pub(super) fn add(&mut self, overlap: f64, lay: &Layout) {
        let at = self.kept.partition_point(|(o, _)| *o <= overlap);
        if at < self.most {
            self.kept.insert(at, (overlap, lay.clone()));
            self.kept.truncate(self.most);
        }
    }

    /// One layout, by rank: the k-th of n with probability about
    /// (√((k+1)/n) − √(k/n)), so the least overlapping is taken most
    /// often and the worst still sometimes (sparrow draws the rank from a
    /// half-normal law; a square of a uniform number does the same job
    /// without a normal sampler). None when empty.
    pub(super) fn pick(&self, rng: &mut SplitMix) -> Option<&Layout> {
        let u = rng.unit();
        let i = ((u * u) * self.kept.len() as f64) as usize;
        self.kept
            .get(i.min(self.kept.len().saturating_sub(1)))
            .map(|(_, l)| l)
    }
}

/// The copies whose part's area is at least that of the copy at the
/// three-quarter mark by area (sparrow's "large" items): the ones whose
/// swap changes the layout's structure.
pub(super) fn large_copies(kit: &Kit, pieces: &[Piece]) -> Vec<usize> {
    let area = |p: &Piece| kit.pen[p.item];
    let mut areas: Vec<f64> = pieces.iter().map(area).collect();
    areas.sort_by(f64::total_cmp);
    let Some(&cutoff) = areas.get(areas.len() * 3 / 4) else {
        return Vec::new();
    };
    (0..pieces.len())
        .filter(|&i| area(&pieces[i]) >= cutoff)
        .collect()
}

/// Swaps two copies of different parts, one of `large` and another of
/// `large` when there is one (else any copy): each goes where
/// the other's box centre was, kept inside the room (same turn). False
/// when every copy is of the same part (nothing to swap).
pub(super) fn swap_large(lay: &mut Layout, large: &[usize], rng: &mut SplitMix) -> bool {
    if large.is_empty() {
        return false;
    }
    let a = large[rng.below(large.len())];
    let item = lay.pieces[a].item;
    let pick = |from: &mut dyn Iterator<Item = usize>, rng: &mut SplitMix| {
        let c: Vec<usize> = from.filter(|&j| lay.pieces[j].item != item).collect();
        (!c.is_empty()).then(|| c[rng.below(c.len())])
    };
    let Some(b) =
        pick(&mut large.iter().copied(), rng).or_else(|| pick(&mut (0..lay.pieces.len()), rng))
    else {
        return false;
    };
    let centre = |p: &Piece| p.shape.bbox().centre();
    let (ca, cb) = (centre(&lay.pieces[a]), centre(&lay.pieces[b]));
    let r = lay.room;
    for (k, to) in [(a, cb), (b, ca)] {
        let bb = *lay.pieces[k].shape.bbox();
        let mut d = to.sub(centre(&lay.pieces[k]));
        // Inside the room: the right and top walls first, so that a copy
        // longer than the room still starts at its left wall.
        d.x = fmax(fmin(d.x, r.x1 - bb.max.x), r.x0 - bb.min.x);
        d.y = fmax(fmin(d.y, r.y1 - bb.max.y), r.y0 - bb.min.y);
        // Fixed sheets: into the sheet it falls on (where it fell when it
        // does not fit there: outside, it will move).
        let d = lay.kept_in_bay(&bb, d).unwrap_or(d);
        let p = &mut lay.pieces[k];
        p.t = p.t.add(d);
        p.shape = p.shape.moved(d);
    }
    true
}
