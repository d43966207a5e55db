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

/// Re-chooses `at[s]` for every site of `seq`; never lengthens the path.
pub(super) fn optimise(at: &mut [usize], inst: &Inst, origin: Point, seq: &[usize]) {
    if seq.is_empty() {
        return;
    }
    // layers[i]: candidate indices of seq[i]; the current entry first.
    let layers: Vec<Vec<usize>> = seq
        .iter()
        .map(|&s| {
            let mut l = vec![at[s]];
            l.extend(inst.spread[s].iter().copied().filter(|&c| c != at[s]));
            l
        })
        .collect();
    let pt = |i: usize, k: usize| inst.pts[seq[i]][layers[i][k]].1;
    let mut cost: Vec<f64> = (0..layers[0].len())
        .map(|k| dist(origin, pt(0, k)))
        .collect();
    // back[i][k]: best predecessor in layer i - 1 of candidate k of layer i.
    let mut back: Vec<Vec<u32>> = vec![Vec::new(); seq.len()];
    for i in 1..seq.len() {
        let mut next = Vec::with_capacity(layers[i].len());
        let mut from = Vec::with_capacity(layers[i].len());
        for k in 0..layers[i].len() {
            let v = pt(i, k);
            let (mut best, mut arg) = (f64::INFINITY, 0u32);
            for (j, c) in cost.iter().enumerate() {
                let t = c + dist(pt(i - 1, j), v);
                if t < best {
                    best = t;
                    arg = j as u32;
                }
            }
            next.push(best);
            from.push(arg);
        }
        cost = next;
        back[i] = from;
    }
    // Ties keep the current entry (index 0 of each layer).
    let mut k = cost
        .iter()
        .enumerate()
        .fold(
            (0, f64::INFINITY),
            |b, (j, &c)| if c < b.1 { (j, c) } else { b },
        )
        .0;
    for i in (0..seq.len()).rev() {
        at[seq[i]] = layers[i][k];
        if i > 0 {
            k = back[i].get(k).map_or(0, |&b| b as usize);
        }
    }
    // Every candidate of each site between its fixed neighbours.
    for i in 0..seq.len() {
        let s = seq[i];
        let prev = if i == 0 {
            origin
        } else {
            inst.pts[seq[i - 1]][at[seq[i - 1]]].1
        };
        let next = seq.get(i + 1).map(|&n| inst.pts[n][at[n]].1);
        let cost = |p: Point| dist(prev, p) + next.map_or(0.0, |n| dist(n, p));
        let mut best = (at[s], cost(inst.pts[s][at[s]].1));
        for (c, (_, p)) in inst.pts[s].iter().enumerate() {
            let v = cost(*p);
            if v < best.1 {
                best = (c, v);
            }
        }
        at[s] = best.0;
    }
}
