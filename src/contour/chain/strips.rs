//! Chaining a sheet on several threads, with the chains, gaps and
//! warnings of one thread (issue 17: the walks were ~50 of the contours
//! stage's ~104 ms on the 25 MB nest, on one thread).
//!
//! Why it is exact: a walk only ever joins pieces with an end within the
//! tolerance of an end of its chain, so the pieces that can touch, end to
//! end and transitively, form groups no walk leaves; and a group's walks
//! depend on nothing but the group (which of its pieces earlier walks
//! took). So each group walked alone, its starts in the one-thread order,
//! makes the chains one thread makes, and the chains of all groups
//! ordered by their start piece are the one-thread list.
//!
//! How the groups are found cheaply: the sheet is cut into vertical
//! strips, one a thread, at quantiles of the pieces' first ends. A piece
//! with both ends inside one strip, more than twice the tolerance from
//! its borders, touches only pieces whose ends are in that strip. The
//! other pieces (across or near a border), and every piece they reach end
//! to end, are mixed: a breadth-first search from them, through the same
//! end grid the walks use. What is not mixed is walked strip by strip,
//! the mixed pieces on their own; the three (or more) at once.

use super::walk::{Log, Sink, Walked, Walker};
use super::Chain;
use crate::par::Threads;

/// Fewest open pieces chained in strips: below, one thread's walk is
/// well under a millisecond, about what starting the threads costs. (Low
/// enough that tests/threads.rs' sheet, 1,000 plates of four lines among
/// its parts, is chained in strips and compared with one thread.)
pub(super) const FROM: usize = 2048;

/// The label of a piece in no strip's interior, or reached from one.
const MIXED: u8 = u8::MAX;

/// [`Walker::walk`] over all pieces into `out`, walked in strips on the
/// threads and written here in start order (the same chains; see the
/// module's note). Falls back to one walk when most of the sheet is one
/// group (a mesh of lines) or a piece's end is not finite.
pub(super) fn walk(w: &Walker, threads: Threads, out: &mut Vec<Chain>) -> Log {
    let n = w.open.len();
    let all = |out: &mut Vec<Chain>| w.walk(0..n, &mut vec![false; n], out);
    let strips = threads.get().min(usize::from(MIXED));
    let Some(cuts) = cuts(w, strips) else {
        return all(out);
    };
    let mut label = labels(w, &cuts);
    // Every piece a mixed piece reaches end to end is mixed too.
    let mut queue: Vec<usize> = (0..n).filter(|&i| label[i] == MIXED).collect();
    let mut head = 0;
    while head < queue.len() {
        if queue.len() > n / 2 {
            return all(out);
        }
        let i = queue[head];
        head += 1;
        let (a, b) = w.open.ends_of(i, false);
        for p in [a, b] {
            w.touching(p, |j| {
                if label[j] != MIXED {
                    label[j] = MIXED;
                    queue.push(j);
                }
            });
        }
    }
    drop(queue);
    // Strip s's walks, then the mixed pieces' (task `strips`), at once.
    let label = &label;
    let tasks = cuts.len() + 2;
    let parts = crate::par::map_ranges(tasks, threads, 1, |r| {
        r.map(|task| {
            let mine = if task + 1 == tasks { MIXED } else { task as u8 };
            let starts = (0..n).filter(|&i| label[i] == mine);
            let mut walked = Walked::default();
            let log = w.walk(starts, &mut vec![false; n], &mut walked);
            (walked, log)
        })
        .collect::<Vec<_>>()
    });
    let (walked, logs): (Vec<Walked>, Vec<Log>) = parts.into_iter().flatten().unzip();
    write(w, &walked, out);
    merge(logs)
}

/// The chains of `parts` written into `out` in start order: what one
/// walk over all starts writes (each part in start order, no start in
/// two parts).
fn write(w: &Walker, parts: &[Walked], out: &mut Vec<Chain>) {
    let lens: Vec<usize> = parts.iter().map(|p| p.starts.len()).collect();
    in_start_order(
        &lens,
        |p, i| parts[p].starts[i],
        |p, i| {
            let (start, backward, forward, closed) = parts[p].get(i);
            out.chain(&w.open, start, backward, forward, closed);
        },
    );
}

/// Visits the items of several lists, each in start order, as one list
/// in start order: `each(list, item)`, `start(list, item)` being the
/// start piece of its walk (lists of `lens` items).
fn in_start_order(
    lens: &[usize],
    start: impl Fn(usize, usize) -> u32,
    mut each: impl FnMut(usize, usize),
) {
    let mut at = vec![0; lens.len()];
    while let Some(l) = (0..lens.len())
        .filter(|&l| at[l] < lens[l])
        .min_by_key(|&l| start(l, at[l]))
    {
        each(l, at[l]);
        at[l] += 1;
    }
}

/// Each piece's strip: the one whose interior holds both its ends, more
/// than twice the tolerance from the strip's borders (a piece touching it
/// then has its near end in the same strip), or [`MIXED`]. `cuts`
/// ascending: strip s lies between `cuts[s - 1]` and `cuts[s]`.
fn labels(w: &Walker, cuts: &[f64]) -> Vec<u8> {
    let margin = 2.0 * w.t;
    let strip_of = |x: f64| -> Option<u8> {
        let s = cuts.partition_point(|&c| c <= x);
        let low = s == 0 || x - cuts[s - 1] > margin;
        let high = s == cuts.len() || cuts[s] - x > margin;
        (low && high).then_some(s as u8)
    };
    (0..w.open.len())
        .map(|i| {
            let (a, b) = w.open.ends_of(i, false);
            match (strip_of(a.x), strip_of(b.x)) {
                (Some(p), Some(q)) if p == q => p,
                _ => MIXED,
            }
        })
        .collect()
}

/// `strips - 1` cut values at quantiles of the pieces' first ends' x,
/// ascending; None if there is nothing to cut or an end is not finite.
fn cuts(w: &Walker, strips: usize) -> Option<Vec<f64>> {
    let n = w.open.len();
    if strips < 2 || n == 0 {
        return None;
    }
    let mut xs: Vec<f64> = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = w.open.ends_of(i, false);
        if !(a.is_finite() && b.is_finite()) {
            return None;
        }
        xs.push(a.x);
    }
    let mut cuts = Vec::with_capacity(strips - 1);
    for s in 1..strips {
        let k = s * n / strips;
        let (_, x, _) = xs.select_nth_unstable_by(k, f64::total_cmp);
        cuts.push(*x);
    }
    cuts.sort_by(f64::total_cmp);
    Some(cuts)
}

/// The logs of several groups of walks as one in start order.
fn merge(parts: Vec<Log>) -> Log {
    let mut out = Log {
        // The branch count and the first branch point in start order.
        branches: parts.iter().map(|p| p.branches).sum(),
        branch_at: parts
            .iter()
            .filter_map(|p| p.branch_at)
            .min_by_key(|&(start, _)| start),
        gaps: Vec::new(),
    };
    // Gaps, by their walk's start (a walk's own in the order it made them).
    let lens: Vec<usize> = parts.iter().map(|p| p.gaps.len()).collect();
    in_start_order(
        &lens,
        |g, i| parts[g].gaps[i].0,
        |g, i| {
            out.gaps.push(parts[g].gaps[i]);
        },
    );
    out
}

#[cfg(test)]
mod tests;
