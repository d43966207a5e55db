//! Entry-point choice for a fixed visiting sequence.
//!
//! With the order fixed, choosing one candidate per site to minimise the
//! open path is a shortest path through a layered graph (layer i = the
//! candidates of the i-th site), solved exactly by dynamic programming: the
//! "cluster optimisation" step of GTSP heuristics (Fischetti, Salazar, Toth
//! 1997; Karapetyan & Gutin 2012). Work is the sum of products of
//! neighbouring layer sizes, so layers are capped at `SPREAD` well-spread
//! candidates plus the current entry (so the result is never worse); a
//! second pass then tries every candidate of each site between its two
//! fixed neighbours. Stretches with fixed entries between them are
//! independent, so sets of them are re-chosen on the threads
//! ([`optimise_stretches`]), and a big sheet's whole re-choice is made in
//! blocks ([`optimise_blocks`]).

use super::dist;
use super::Inst;
use crate::geom::Point;
use crate::par::Threads;
use std::sync::Mutex;

/// One re-choice's arrays (a stretch's layers), kept from one re-choice to
/// the next: at 137k sites they are ~35 MB, and fresh pages each time (the
/// kernel zeroing them) cost as much as the dynamic programme.
#[derive(Default)]
struct Scratch {
    off: Vec<usize>,
    cand: Vec<usize>,
    lp: Vec<Point>,
    cost: Vec<f64>,
    next: Vec<f64>,
    back: Vec<u32>,
}

/// The re-choices' arrays, one set for each thread at work (which set a
/// stretch gets changes nothing but where its arrays lie).
#[derive(Default)]
pub(super) struct Layers(Mutex<Vec<Scratch>>);

impl Layers {
    /// A set of arrays (the last one put back, or a new one).
    fn take(&self) -> Scratch {
        self.0
            .lock()
            .map(|mut v| v.pop())
            .ok()
            .flatten()
            .unwrap_or_default()
    }
    /// Puts a set back for the next re-choice.
    fn give(&self, s: Scratch) {
        if let Ok(mut v) = self.0.lock() {
            v.push(s);
        }
    }
}

/// Positions a block of [`optimise_blocks`] re-chooses at most: its
/// layers (~250 B a site) stay in a core's cache, and a 137k-site sheet
/// is 17 blocks for the threads to share.
pub(super) const BLOCK: usize = 8192;

/// Re-chooses `at[s]` for every site of `seq`, in the arrays of `layers`;
/// never lengthens the path.
pub(super) fn optimise_in(
    layers: &Layers,
    at: &mut [usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
) {
    let whole = (0, seq.len().saturating_sub(1));
    optimise_stretches(layers, at, inst, origin, seq, &[whole], Threads::ONE);
}

/// Re-chooses the entries of positions `lo..=hi` of `seq` only, the
/// entries around them fixed (the tool comes from the entry at `lo - 1`,
/// or `origin`, and goes on to the one at `hi + 1`): exact for that
/// stretch, and never lengthens the path.
#[cfg(test)]
pub(super) fn optimise_stretch(
    layers: &Layers,
    at: &mut [usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
    stretch: (usize, usize),
) {
    optimise_stretches(layers, at, inst, origin, seq, &[stretch], Threads::ONE);
}

/// Re-chooses the entries of each stretch `(lo, hi)` of positions of
/// `seq`, the entries around it fixed (the tool comes from the entry at
/// `lo - 1`, or `origin`, and goes on to the one at `hi + 1`): exact for
/// the stretch, and never lengthens the path. `stretches` ascending, each
/// ending before the next starts less one (a fixed position between any
/// two); on up to `threads` threads. Each reads only its own sites and the fixed
/// entries around it, so they are re-chosen at once and give what one
/// after the other gives.
pub(super) fn optimise_stretches(
    layers: &Layers,
    at: &mut [usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
    stretches: &[(usize, usize)],
    threads: Threads,
) {
    let n = seq.len();
    let stretches: Vec<(usize, usize)> = stretches
        .iter()
        .map(|&(lo, hi)| (lo, hi.min(n.saturating_sub(1))))
        .filter(|&(lo, hi)| lo <= hi && hi < n)
        .collect();
    let fixed: &[usize] = at;
    let entry = |i: usize| inst.pts[seq[i]][fixed[seq[i]]];
    // Each range of stretches: their choices, position after position.
    let chosen = crate::par::map_ranges(stretches.len(), threads, 1, |r| {
        let mut scratch = layers.take();
        let (mut all, mut out) = (Vec::new(), Vec::new());
        for &(lo, hi) in &stretches[r] {
            let from = if lo == 0 { origin } else { entry(lo - 1) };
            let to = (hi + 1 < n).then(|| entry(hi + 1));
            optimise_between(&mut scratch, fixed, inst, from, &seq[lo..=hi], to, &mut out);
            all.extend_from_slice(&out);
        }
        layers.give(scratch);
        all
    });
    let positions = stretches.iter().flat_map(|&(lo, hi)| lo..=hi);
    for (i, c) in positions.zip(chosen.into_iter().flatten()) {
        at[seq[i]] = c;
    }
}

/// [`optimise_in`] in blocks of [`BLOCK`] positions on the threads, for
/// the short schedule: the position between two blocks keeps its entry
/// while the blocks are re-chosen, then the window of `margin` positions
/// either side of it is re-chosen between the blocks' new entries. The
/// blocks depend on the sequence's length only, so the entries are the
/// same with any number of threads. Never longer; it can differ from one
/// exact pass only near a border (where the best path through it would
/// change entries beyond the window): on the 4/11/25 MB nests and the
/// 60k-site benches not at all (the same tours to the micrometre), and
/// the 25 MB nest's plan stage 242 -> 223 ms on two threads, 405 -> 373
/// on one (10 and 5 alternating pairs): a block's layers stay in cache.
pub(super) fn optimise_blocks(
    layers: &Layers,
    at: &mut [usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
    margin: usize,
    threads: Threads,
) {
    let n = seq.len();
    let margin = margin.min(BLOCK / 2 - 1);
    // Block k: positions after k * BLOCK (from 0 for the first) up to the
    // next multiple; each multiple is a border.
    let blocks: Vec<(usize, usize)> = (0..n.div_ceil(BLOCK))
        .map(|k| (if k == 0 { 0 } else { k * BLOCK + 1 }, (k + 1) * BLOCK - 1))
        .collect();
    optimise_stretches(layers, at, inst, origin, seq, &blocks, threads);
    let windows: Vec<(usize, usize)> = (1..n.div_ceil(BLOCK))
        .map(|k| (k * BLOCK - margin, k * BLOCK + margin))
        .collect();
    optimise_stretches(layers, at, inst, origin, seq, &windows, threads);
}

/// [`optimise_in`] from `origin`, the path going on to `to` after the last
/// site (none: the path ends there): `out[i]` the entry chosen for
/// `seq[i]` (`at` read only for the current entries).
fn optimise_between(
    layers: &mut Scratch,
    at: &[usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
    to: Option<Point>,
    out: &mut Vec<usize>,
) {
    out.clear();
    if seq.is_empty() {
        return;
    }
    let tail = |p: Point| to.map_or(0.0, |t| dist(p, t));
    // Layer i: candidate indices of seq[i], the current entry first, stored
    // flat (`off[i]..off[i + 1]` of `cand` and of their points `lp`): one
    // allocation for all layers instead of four per site, and the inner
    // loop reads the previous layer's points side by side.
    let Scratch {
        off,
        cand,
        lp,
        cost,
        next,
        back,
    } = layers;
    off.clear();
    cand.clear();
    lp.clear();
    // Room made once (at most the sample and the current entry a layer):
    // grown push by push, the first re-choice of a 137k-site sheet copied
    // its arrays a dozen times over (a sixth of its time, perf).
    let most: usize = seq.iter().map(|&s| inst.spread(s).len() + 1).sum();
    off.reserve(seq.len() + 1);
    cand.reserve(most);
    lp.reserve(most);
    off.push(0);
    for &s in seq {
        let pts = &inst.pts[s];
        cand.push(at[s]);
        lp.push(pts[at[s]]);
        for &c in inst.spread(s).iter().filter(|&&c| c != at[s]) {
            cand.push(c);
            lp.push(pts[c]);
        }
        off.push(cand.len());
    }
    let layer = |i: usize| off[i]..off[i + 1];
    cost.clear();
    cost.extend(lp[layer(0)].iter().map(|&p| dist(origin, p)));
    // back[off[i] + k]: best predecessor in layer i - 1 of candidate k of layer i.
    back.clear();
    back.resize(cand.len(), 0);
    for i in 1..seq.len() {
        next.clear();
        let prev = &lp[layer(i - 1)];
        for k in layer(i) {
            let v = lp[k];
            let (mut best, mut arg) = (f64::INFINITY, 0u32);
            for (j, (c, &q)) in cost.iter().zip(prev).enumerate() {
                let t = c + dist(q, v);
                if t < best {
                    best = t;
                    arg = j as u32;
                }
            }
            next.push(best);
            back[k] = arg;
        }
        std::mem::swap(cost, next);
    }
    // Ties keep the current entry (index 0 of each layer).
    let last = layer(seq.len() - 1);
    let mut k = cost
        .iter()
        .zip(&lp[last])
        .map(|(&c, &p)| c + tail(p))
        .enumerate()
        .fold(
            (0, f64::INFINITY),
            |b, (j, c)| if c < b.1 { (j, c) } else { b },
        )
        .0;
    out.resize(seq.len(), 0);
    for i in (0..seq.len()).rev() {
        let r = layer(i);
        let k_here = k.min(r.len() - 1);
        out[i] = cand[r.start + k_here];
        if i > 0 {
            k = back[r.start + k_here] as usize;
        }
    }
    // Every candidate of each site between its fixed neighbours.
    for i in 0..seq.len() {
        let s = seq[i];
        let prev = if i == 0 {
            origin
        } else {
            inst.pts[seq[i - 1]][out[i - 1]]
        };
        let next = seq.get(i + 1).map(|&n| inst.pts[n][out[i + 1]]).or(to);
        let cost = |p: Point| dist(prev, p) + next.map_or(0.0, |n| dist(n, p));
        let mut best = (out[i], cost(inst.pts[s][out[i]]));
        for (c, p) in inst.pts[s].iter().enumerate() {
            let v = cost(*p);
            if v < best.1 {
                best = (c, v);
            }
        }
        out[i] = best.0;
    }
}

#[cfg(test)]
#[path = "cluster_tests.rs"]
mod tests;
