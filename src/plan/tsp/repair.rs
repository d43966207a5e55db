//! Making a precedence-free order legal (relax and repair).
//!
//! Measured on the bench nests: LKH's tour with precedence ignored, made
//! legal by either repair below, is as short as before (within 0.1 %):
//! holes lie inside their part, so the free optimum visits a part's holes
//! and outer contour together anyway and only their order within the part
//! changes. Local search with precedence checked on every move, on the other
//! hand, stalls 5–10 % above that (no long reversal is legal once parts with
//! holes lie inside it). So the free order is optimised first, then repaired.

use super::Inst;

/// `seq` with each site moved to just after its last descendant.
pub(super) fn defer_parents(inst: &Inst, seq: &[usize]) -> Vec<usize> {
    let n = inst.pts.len();
    let mut waiting: Vec<usize> = inst.kids.iter().map(<[usize]>::len).collect();
    let mut held = vec![false; n];
    let mut out = Vec::with_capacity(seq.len());
    for &s in seq {
        if s >= n || waiting[s] > 0 {
            if s < n {
                held[s] = true;
            }
            continue;
        }
        // Emit s, then every held ancestor it completes.
        let mut x = s;
        loop {
            out.push(x);
            let Some(p) = inst.up[x] else { break };
            waiting[p] = waiting[p].saturating_sub(1);
            if waiting[p] > 0 || !held[p] {
                break;
            }
            held[p] = false;
            x = p;
        }
    }
    out
}

/// `seq` with each site's unvisited descendants pulled forward to just
/// before it (post-order of its subtree, children in `seq` order).
pub(super) fn pull_children(inst: &Inst, seq: &[usize]) -> Vec<usize> {
    let n = inst.pts.len();
    let mut rank = vec![usize::MAX; n];
    for (r, &s) in seq.iter().enumerate() {
        if s < n {
            rank[s] = r;
        }
    }
    let mut seen = vec![false; n];
    let mut out = Vec::with_capacity(seq.len());
    let mut stack: Vec<(usize, bool)> = Vec::new();
    for &s in seq {
        if s >= n || seen[s] {
            continue;
        }
        stack.push((s, false));
        while let Some((x, expanded)) = stack.pop() {
            if seen[x] {
                continue;
            }
            if expanded {
                seen[x] = true;
                out.push(x);
                continue;
            }
            stack.push((x, true));
            let mut kids: Vec<usize> = inst.kids[x].iter().copied().filter(|&k| !seen[k]).collect();
            // Popped in `seq` order: push the latest first.
            crate::sort::sort_by_key(&mut kids, |&k| std::cmp::Reverse(rank[k]));
            stack.extend(kids.into_iter().map(|k| (k, false)));
        }
    }
    out
}

/// The sites of `after` whose predecessor differs from theirs in `before`,
/// with those predecessors: where a repair cut and rejoined the sequence.
pub(super) fn moved(inst: &Inst, before: &[usize], after: &[usize]) -> Vec<usize> {
    const NONE: usize = usize::MAX;
    let n = inst.pts.len();
    let mut pred = vec![NONE; n];
    for w in before.windows(2) {
        if w[1] < n {
            pred[w[1]] = w[0];
        }
    }
    let mut out = Vec::new();
    let mut p = NONE;
    for &x in after {
        if x < n && pred[x] != p {
            out.push(x);
            if p != NONE {
                out.push(p);
            }
        }
        p = x;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::{Inst, Site};
    use super::*;
    use crate::geom::Point;

    fn legal(inst: &Inst, seq: &[usize]) -> bool {
        let mut pos = vec![usize::MAX; inst.pts.len()];
        for (i, &s) in seq.iter().enumerate() {
            pos[s] = i;
        }
        seq.iter()
            .all(|&s| inst.up[s].is_none_or(|u| pos[u] != usize::MAX && pos[u] > pos[s]))
    }

    #[test]
    fn both_repairs_are_legal_permutations() {
        // 0 ← 1 ← 2 (island in hole in part), 3 ← 4, 5 alone.
        let p = Point::new(0.0, 0.0);
        let parents = [None, Some(0), Some(1), None, Some(3), None];
        let sites: Vec<Site> = parents
            .iter()
            .map(|&parent| Site {
                candidates: vec![p],
                parent,
            })
            .collect();
        let inst = Inst::new(&sites);
        let free = [0, 3, 5, 1, 4, 2];
        for seq in [defer_parents(&inst, &free), pull_children(&inst, &free)] {
            assert!(legal(&inst, &seq), "{seq:?}");
            let mut sorted = seq.clone();
            sorted.sort_unstable();
            assert_eq!(sorted, vec![0, 1, 2, 3, 4, 5]);
        }
        assert_eq!(defer_parents(&inst, &free), vec![5, 4, 3, 2, 1, 0]);
        assert_eq!(pull_children(&inst, &free), vec![2, 1, 0, 4, 3, 5]);
        // 5 4 3 2 1 0 against 0 3 5 1 4 2: every join but none is new.
        let deferred = defer_parents(&inst, &free);
        let mut m = moved(&inst, &free, &deferred);
        m.sort_unstable();
        m.dedup();
        assert_eq!(m, vec![0, 1, 2, 3, 4, 5]);
        assert!(moved(&inst, &free, &free).is_empty());
    }
}
