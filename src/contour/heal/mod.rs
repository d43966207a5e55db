//! Healing before chaining (paper 001 §11, "filter duplicated entities"):
//! what CAD files get wrong and a cutter must not cut twice.
//!
//! - Zero-length entities and segments (shorter than the tolerance) are dropped.
//! - Closed loops drawn twice (same box, area and length) are kept once.
//! - Parts that share an edge each draw their own copy of it: so edges are
//!   de-duplicated only among what did not close in a first chaining, and
//!   against the edges of the closed loops; there a segment drawn twice, in
//!   either direction, is kept once.
//! - Collinear lines that overlap are merged into one line over their union;
//!   co-circular arcs that overlap likewise into arcs over their union.
//! - Gaps between open ends up to the gap setting are closed later, by a
//!   second chaining pass ([`super::chain`]); they are counted here too.
//!
//! Every fix is counted and located, so the user sees what was changed.

mod overlap;
mod prepare;

use super::chain::{Chain, Measure, Piece, Pieces};
use crate::fx::FxHasher;
use crate::geom::{Point, Segment, Tolerance};
use overlap::{
    drop_duplicate_segments, merge_overlapping_arcs, merge_overlapping_lines, segment_key,
};
use std::hash::{Hash, Hasher};

pub use prepare::{prepare, STAMPED};

/// What healing changed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HealKind {
    /// An entity or segment drawn twice; the copy was dropped.
    Duplicate,
    /// Overlapping collinear lines or co-circular arcs merged.
    Overlap,
    /// A gap between two ends closed.
    Gap,
    /// An entity or segment shorter than the tolerance dropped.
    ZeroLength,
    /// A loop that crossed itself, replaced by its region's outline(s).
    SelfCrossing,
}

impl HealKind {
    /// Name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            HealKind::Duplicate => "duplicate",
            HealKind::Overlap => "overlap",
            HealKind::Gap => "gap",
            HealKind::ZeroLength => "zero_length",
            HealKind::SelfCrossing => "self_crossing",
        }
    }
}

/// Counts and places of every fix.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Healing {
    /// Copies dropped.
    pub duplicates: usize,
    /// Overlaps merged.
    pub overlaps: usize,
    /// Gaps closed.
    pub gaps_closed: usize,
    /// Zero-length entities and segments dropped.
    pub zero_length: usize,
    /// Loops that crossed themselves, repaired.
    pub self_crossings: usize,
    /// Each fix and where.
    pub locations: Vec<(HealKind, Point)>,
}

impl Healing {
    /// Records one fix.
    pub fn add(&mut self, kind: HealKind, at: Point) {
        match kind {
            HealKind::Duplicate => self.duplicates += 1,
            HealKind::Overlap => self.overlaps += 1,
            HealKind::Gap => self.gaps_closed += 1,
            HealKind::ZeroLength => self.zero_length += 1,
            HealKind::SelfCrossing => self.self_crossings += 1,
        }
        self.locations.push((kind, at));
    }
}

fn snap(v: f64, t: f64) -> i64 {
    (v / t).round() as i64
}

/// True for a line whose ends are at least `t` apart along an axis: its
/// length is at least `t` without computing it.
fn spans(s: &Segment, t: f64) -> bool {
    s.is_line() && ((s.b.x - s.a.x).abs() >= t || (s.b.y - s.a.y).abs() >= t)
}

/// One segment of an open entity, by position: no allocation per segment.
#[derive(Clone, Copy, Debug)]
struct Seg {
    s: Segment,
    entity: u32,
    index: u32,
}

/// Key of a closed loop for finding copies: its box, area and length, snapped to the tolerance.
fn loop_key(m: &Measure, t: f64) -> [i64; 6] {
    let bb = m.bbox;
    [
        snap(bb.min.x, t),
        snap(bb.min.y, t),
        snap(bb.max.x, t),
        snap(bb.max.y, t),
        snap(m.area.abs(), t * t.max(1.0)),
        snap(m.length, t),
    ]
}

/// For each key, whether an earlier one is equal: found by sorting the
/// keys' hashes (a linear radix sort) and comparing keys within runs of
/// equal hashes, in input order (the sort is stable), rather than through
/// a hash map of every loop of a sheet (issue 17: the map's inserts and its
/// fresh pages were a tenth of the stage). Loops' keys here, segments' in
/// [`overlap`]. The hashes are folded to 32 bits: the radix sort then
/// makes four passes instead of eight (~4.6 ms of the 25 MB nest's 137k
/// loops before; the contours stage 108.8 -> 103.9 ms, 8 alternating
/// pairs on two threads, median pair ratio 0.97), and a run of equal
/// hashes is still read in input order comparing keys, so which key is a
/// copy does not depend on the hash at all.
fn copies<K: Hash + PartialEq>(n: usize, key: impl Fn(usize) -> K) -> Vec<bool> {
    let hashes: Vec<u64> = (0..n)
        .map(|k| {
            let mut h = FxHasher::default();
            key(k).hash(&mut h);
            let h = h.finish();
            (h ^ (h >> 32)) & 0xffff_ffff
        })
        .collect();
    let order = crate::sort::radix_order(&hashes);
    let mut copy = vec![false; n];
    // Distinct keys met so far in a run (one, unless hashes collide).
    let mut distinct: Vec<K> = Vec::new();
    let mut i = 0;
    while i < order.len() {
        let h = hashes[order[i]];
        let n = order[i..].iter().take_while(|&&k| hashes[k] == h).count();
        if n > 1 {
            distinct.clear();
            for &k in &order[i..i + n] {
                let key = key(k);
                if distinct.contains(&key) {
                    copy[k] = true;
                } else {
                    distinct.push(key);
                }
            }
        }
        i += n;
    }
    copy
}

/// Closed loops drawn twice (by the same or by other entities) are kept once.
pub fn drop_duplicate_loops(loops: &mut Vec<Chain>, tol: Tolerance, healing: &mut Healing) {
    let t = tol.mm().max(1e-9);
    let copy = copies(loops.len(), |k| loop_key(&loops[k].measure, t));
    let mut k = 0;
    loops.retain(|c| {
        let copy = copy[k];
        k += 1;
        if copy {
            healing.add(
                HealKind::Duplicate,
                c.segments.first().map_or(Point::default(), |s| s.a),
            );
        }
        !copy
    });
}

/// Second step, on what did not close: a segment that repeats another (or
/// an edge of a closed loop) is dropped, overlapping collinear lines and
/// co-circular arcs are merged; the rest goes back to chaining in runs.
/// None when nothing was dropped or merged (every chain would come back
/// whole, as one run).
pub fn heal_open(
    open: &[Chain],
    closed: &[Chain],
    tol: Tolerance,
    healing: &mut Healing,
) -> Option<Pieces> {
    let t = tol.mm().max(1e-9);
    let mut pieces = Pieces::default();
    let mut segs: Vec<Seg> = Vec::new();
    for (i, c) in open.iter().enumerate() {
        // A zero-area "loop" is opened up: its segments are healed like any other.
        segs.extend(c.segments.iter().enumerate().map(|(k, s)| Seg {
            s: *s,
            entity: i as u32,
            index: k as u32,
        }));
    }
    if segs.is_empty() {
        return None;
    }
    let total = segs.len();
    // Only a closed edge whose two ends lie near the open segments can
    // share a key with one of them (a key snaps each end to the tolerance):
    // the others are not hashed (a nested sheet: 400k closed edges, no open).
    let mut near = crate::geom::BBox::EMPTY;
    for g in &segs {
        near.add(g.s.a);
        near.add(g.s.b);
    }
    let inside = |p: Point| near.contains_box(&crate::geom::BBox::at(p), 2.0 * t);
    let mut earlier = Vec::new();
    for c in closed {
        for s in &c.segments {
            if inside(s.a) && inside(s.b) {
                earlier.push(segment_key(s, t));
            }
        }
    }
    let segs = drop_duplicate_segments(segs, t, earlier, healing);
    let segs = merge_overlapping_lines(segs, t, healing, &mut pieces);
    let segs = merge_overlapping_arcs(segs, t, healing, &mut pieces);
    if pieces.is_empty() && segs.len() == total {
        return None;
    }
    // What is left of each chain, in runs: a run breaks where a segment was
    // taken out as a copy or into a merge. The survivors are marked at their
    // place in `open` (chain by chain, segment by segment: the order a sort
    // by (chain, index) gives) and read back in that order.
    let mut first = Vec::with_capacity(open.len() + 1);
    first.push(0usize);
    for c in open {
        first.push(first[first.len() - 1] + c.segments.len());
    }
    let mut kept = vec![false; total];
    for g in &segs {
        kept[first[g.entity as usize] + g.index as usize] = true;
    }
    for (chain, c) in open.iter().enumerate() {
        let kept = &kept[first[chain]..first[chain + 1]];
        let mut k = 0;
        while k < kept.len() {
            if !kept[k] {
                k += 1;
                continue;
            }
            let m = kept[k..]
                .iter()
                .position(|&x| !x)
                .map_or(kept.len(), |n| k + n);
            pieces.open_segments().extend_from_slice(&c.segments[k..m]);
            pieces.close_open(&c.entities);
            k = m;
        }
    }
    Some(pieces)
}
#[cfg(test)]
mod tests;
