//! Shortening the last sheet's used length (the strip's length) by ruin and
//! recreate.
//!
//! The idea is sparrow's exploration (Gardeyn & Wauters, "An open-source
//! heuristic to reboot 2D nesting research", EJOR 2025, arXiv 2509.13329):
//! once a nest fits in length L, ask for a shorter one, L (1 − r), and
//! repair what no longer fits; on success shrink again, after repeated
//! failures shrink by less (their compression phase uses ever smaller r).
//! Sparrow repairs by letting copies overlap and separating them by guided
//! local search on weighted overlap penalties; we repair without overlap:
//! the copies past the new end, and a few others taken at random, are
//! removed and put back one by one by the bottom-left placer into the
//! shortened sheet (ruin and recreate, Schrimpf et al., J. Comput. Phys.
//! 2000). The same move at the current length, without shrinking, lets the
//! nest change shape so that a later shrink can succeed.

use super::place::{Bin, Variant};
use super::search::SplitMix;

/// Largest shrink step, as a fraction of the used length.
const START_RATIO: f64 = 0.02;
/// Smallest step before starting again from [`START_RATIO`].
const MIN_RATIO: f64 = 0.0005;
/// Failed tries at one step before halving it.
const TRIES_PER_RATIO: u32 = 40;
/// Most copies taken out at random besides those past the end.
const MAX_RUIN: usize = 4;

/// The state of the search between calls (one call = one try).
pub struct Shrink {
    ratio: f64,
    fails: u32,
}

impl Default for Shrink {
    fn default() -> Self {
        Shrink {
            ratio: START_RATIO,
            fails: 0,
        }
    }
}

impl Shrink {
    /// One try on `bin`: returns the changed bin when it worked (it is then
    /// no longer than `bin`), None when not.
    pub fn step<'v>(
        &mut self,
        bin: &Bin,
        variants: &dyn Fn(usize) -> &'v [Variant],
        area: &dyn Fn(usize) -> f64,
        rng: &mut SplitMix,
        eps: f64,
        max_candidates: usize,
    ) -> Option<Bin> {
        let n = bin.placed.len();
        if n == 0 {
            return None;
        }
        let span = bin.right - bin.container.x0;
        // Half the tries shrink, half reshape at the same length.
        let shrinking = rng.below(2) == 0;
        let end = if shrinking {
            bin.right - self.ratio * span
        } else {
            bin.right
        };
        let mut trial = bin.clone();
        trial.container.x1 = trial.container.x1.min(end);
        let mut out: Vec<usize> = Vec::new();
        let mut keep = Vec::with_capacity(n);
        for (i, p) in trial.placed.drain(..).enumerate() {
            if p.shape.bbox().max.x > end + eps {
                out.push(p.item);
            } else {
                keep.push((i, p));
            }
        }
        for _ in 0..1 + rng.below(MAX_RUIN) {
            if keep.is_empty() {
                break;
            }
            // The righter of two random copies (a tournament): copies near
            // the end are the ones whose leaving can shorten the nest.
            let (a, b) = (rng.below(keep.len()), rng.below(keep.len()));
            let right = |k: usize| keep[k].1.shape.bbox().max.x;
            let (_, p) = keep.swap_remove(if right(a) >= right(b) { a } else { b });
            out.push(p.item);
        }
        keep.sort_by_key(|(i, _)| *i);
        trial.placed = keep.into_iter().map(|(_, p)| p).collect();
        trial.right = trial
            .placed
            .iter()
            .map(|p| p.shape.bbox().max.x)
            .fold(trial.container.x0, f64::max);
        // Largest first, with a random neighbour swap now and then.
        out.sort_by(|&a, &b| area(b).total_cmp(&area(a)).then(a.cmp(&b)));
        for k in 1..out.len() {
            if rng.below(3) == 0 {
                out.swap(k - 1, k);
            }
        }
        let ok = out
            .iter()
            .all(|&it| trial.place(it, variants(it), eps, max_candidates));
        let improved = ok && trial.right < bin.right - eps;
        if shrinking {
            if ok {
                self.fails = 0;
            } else {
                self.fails += 1;
                if self.fails >= TRIES_PER_RATIO {
                    self.fails = 0;
                    self.ratio /= 2.0;
                    if self.ratio < MIN_RATIO {
                        self.ratio = START_RATIO;
                    }
                }
            }
        }
        // Keep the sheet's own end for the next tries.
        trial.container.x1 = bin.container.x1;
        (ok && (improved || !shrinking)).then_some(trial)
    }
}
