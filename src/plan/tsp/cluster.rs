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
//! fixed neighbours.

use super::dist;
use super::Inst;
use crate::geom::Point;

/// The layers' arrays, kept from one re-choice to the next: at 137k sites
/// they are ~35 MB, and fresh pages each time (the kernel zeroing them)
/// cost as much as the dynamic programme.
#[derive(Default)]
pub(super) struct Layers {
    off: Vec<usize>,
    cand: Vec<usize>,
    lp: Vec<Point>,
    cost: Vec<f64>,
    next: Vec<f64>,
    back: Vec<u32>,
}

/// Re-chooses `at[s]` for every site of `seq`, in the arrays of `layers`;
/// never lengthens the path.
pub(super) fn optimise_in(
    layers: &mut Layers,
    at: &mut [usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
) {
    optimise_between(layers, at, inst, origin, seq, None);
}

/// Re-chooses the entries of positions `lo..=hi` of `seq` only, the
/// entries around them fixed (the tool comes from the entry at `lo - 1`,
/// or `origin`, and goes on to the one at `hi + 1`): exact for that
/// stretch, and never lengthens the path.
pub(super) fn optimise_stretch(
    layers: &mut Layers,
    at: &mut [usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
    (lo, hi): (usize, usize),
) {
    let hi = hi.min(seq.len().saturating_sub(1));
    if lo > hi {
        return;
    }
    let entry = |s: usize, at: &[usize]| inst.pts[s][at[s]];
    let from = if lo == 0 {
        origin
    } else {
        entry(seq[lo - 1], at)
    };
    let to = seq.get(hi + 1).map(|&s| entry(s, at));
    optimise_between(layers, at, inst, from, &seq[lo..=hi], to);
}

/// [`optimise_in`] from `origin`, the path going on to `to` after the last
/// site (none: the path ends there).
fn optimise_between(
    layers: &mut Layers,
    at: &mut [usize],
    inst: &Inst,
    origin: Point,
    seq: &[usize],
    to: Option<Point>,
) {
    if seq.is_empty() {
        return;
    }
    let tail = |p: Point| to.map_or(0.0, |t| dist(p, t));
    // Layer i: candidate indices of seq[i], the current entry first, stored
    // flat (`off[i]..off[i + 1]` of `cand` and of their points `lp`): one
    // allocation for all layers instead of four per site, and the inner
    // loop reads the previous layer's points side by side.
    let Layers {
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
    for i in (0..seq.len()).rev() {
        let r = layer(i);
        let k_here = k.min(r.len() - 1);
        at[seq[i]] = cand[r.start + k_here];
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
            inst.pts[seq[i - 1]][at[seq[i - 1]]]
        };
        let next = seq.get(i + 1).map(|&n| inst.pts[n][at[n]]).or(to);
        let cost = |p: Point| dist(prev, p) + next.map_or(0.0, |n| dist(n, p));
        let mut best = (at[s], cost(inst.pts[s][at[s]]));
        for (c, p) in inst.pts[s].iter().enumerate() {
            let v = cost(*p);
            if v < best.1 {
                best = (c, v);
            }
        }
        at[s] = best.0;
    }
}
