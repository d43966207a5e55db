//! Distances through the edge graph (Dijkstra), parts of the graph
//! (union-find), and the bridges that join separate parts (paper 003 §3:
//! "the shortest edges linking two pieces, travelled there and back").

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::circuit::Link;
use crate::geom::Point;

/// Total order on finite distances for the heap.
#[derive(Clone, Copy, PartialEq)]
struct Dist(f64);
impl Eq for Dist {}
impl PartialOrd for Dist {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Dist {
    fn cmp(&self, o: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&o.0)
    }
}

/// Undirected weighted graph for shortest paths: `adj[v]` = (link index, other end).
pub struct Net<'a> {
    links: &'a [Link],
    adj: Vec<Vec<(usize, usize)>>,
    weight: Vec<f64>,
}

impl<'a> Net<'a> {
    /// The graph of `links` over `n` vertices, each weighted by its length.
    pub fn new(links: &'a [Link], n: usize) -> Self {
        let mut adj = vec![Vec::new(); n];
        for (i, l) in links.iter().enumerate() {
            if l.u < n && l.v < n && l.u != l.v {
                adj[l.u].push((i, l.v));
                adj[l.v].push((i, l.u));
            }
        }
        let weight = links.iter().map(|l| l.seg.length()).collect();
        Net { links, adj, weight }
    }

    /// Dijkstra from `from`; stops once every vertex in `targets` is
    /// settled. Returns distances (infinite where not reached) and the link
    /// each vertex was reached by.
    pub fn dijkstra(&self, from: usize, targets: &[usize]) -> (Vec<f64>, Vec<Option<usize>>) {
        let n = self.adj.len();
        let mut dist = vec![f64::INFINITY; n];
        let mut via = vec![None; n];
        let mut want = vec![false; n];
        let mut left = 0;
        for &t in targets {
            if t < n && !want[t] {
                want[t] = true;
                left += 1;
            }
        }
        if from >= n {
            return (dist, via);
        }
        dist[from] = 0.0;
        let mut heap = BinaryHeap::from([Reverse((Dist(0.0), from))]);
        let mut done = vec![false; n];
        while let Some(Reverse((Dist(d), v))) = heap.pop() {
            if done[v] {
                continue;
            }
            done[v] = true;
            if want[v] {
                left -= 1;
                if left == 0 {
                    break;
                }
            }
            for &(l, w) in &self.adj[v] {
                let nd = d + self.weight[l];
                if nd < dist[w] {
                    dist[w] = nd;
                    via[w] = Some(l);
                    heap.push(Reverse((Dist(nd), w)));
                }
            }
        }
        (dist, via)
    }

    /// The links of the shortest path from `from` to `to` (any order).
    pub fn path(&self, from: usize, to: usize) -> Vec<usize> {
        let (_, via) = self.dijkstra(from, &[to]);
        let mut out = Vec::new();
        let mut at = to;
        // Each step moves to a vertex settled earlier, so this ends; the
        // bound guards against a corrupt table all the same.
        while at != from && out.len() <= self.links.len() {
            let Some(l) = via.get(at).copied().flatten() else {
                return Vec::new();
            };
            out.push(l);
            let k = &self.links[l];
            at = if k.v == at { k.u } else { k.v };
        }
        out
    }
}

/// Union-find with path halving.
pub struct Parts(Vec<usize>);

impl Parts {
    /// `n` separate vertices.
    pub fn new(n: usize) -> Self {
        Parts((0..n).collect())
    }
    /// Representative of `v`'s part.
    pub fn find(&mut self, mut v: usize) -> usize {
        while self.0[v] != v {
            self.0[v] = self.0[self.0[v]];
            v = self.0[v];
        }
        v
    }
    /// Joins the parts of `a` and `b`; false when already one.
    pub fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        self.0[ra] = rb;
        ra != rb
    }
}

/// Most points the bridges are looked for among: parts are represented by
/// fewer of their vertices when there are many.
pub const BRIDGE_POINTS: usize = 6_000;
/// Most points of one part looked at for its bridges.
const POINTS_PER_PART: usize = 64;
/// Candidate bridges kept per point: its nearest points of other parts.
const NEAREST: usize = 8;

/// Straight bridges (vertex pairs) joining parts of the `used` vertices, as
/// a minimum spanning forest (Kruskal) over candidate pairs: each point's
/// [`NEAREST`] points of other parts within `max_len`, shortest first, each
/// kept only when `ok(a, b)` (the bridge runs through scrap). Parts that no
/// acceptable bridge reaches stay apart. Each part is represented by at most
/// [`POINTS_PER_PART`] of its vertices, evenly spaced, fewer when there are
/// many parts, so that all stay under [`BRIDGE_POINTS`]: a bridge may then
/// be a little longer than the shortest link between two parts.
pub fn bridges(
    points: &[Point],
    used: &[usize],
    part: &mut Parts,
    max_len: f64,
    ok: &mut dyn FnMut(usize, usize) -> bool,
) -> Vec<(usize, usize)> {
    if max_len.is_nan() || max_len <= 0.0 {
        return Vec::new();
    }
    let mut by_part: crate::fx::FxMap<usize, Vec<usize>> = Default::default();
    let mut order = Vec::new();
    for &v in used {
        let r = part.find(v);
        let e = by_part.entry(r).or_default();
        if e.is_empty() {
            order.push(r);
        }
        e.push(v);
    }
    let parts = order.len();
    if parts < 2 {
        return Vec::new();
    }
    let per = (BRIDGE_POINTS / parts).clamp(1, POINTS_PER_PART);
    let mut reps: Vec<(usize, usize)> = Vec::new(); // (part number, vertex)
    for (k, r) in order.iter().enumerate() {
        let vs = by_part.get(r).map_or(&[][..], |v| &v[..]);
        let step = vs.len().div_ceil(per).max(1);
        reps.extend(vs.iter().step_by(step).map(|&v| (k, v)));
    }
    let at = |i: usize| points[reps[i].1];
    // Points in cells of the longest bridge: a point's candidates are in
    // its 3×3 block.
    let cell = if max_len.is_finite() {
        max_len
    } else {
        f64::MAX
    };
    let key = |p: Point| {
        (
            (p.x / cell).floor().clamp(-1e15, 1e15) as i64,
            (p.y / cell).floor().clamp(-1e15, 1e15) as i64,
        )
    };
    let mut grid: crate::fx::FxMap<(i64, i64), Vec<usize>> = Default::default();
    for i in 0..reps.len() {
        grid.entry(key(at(i))).or_default().push(i);
    }
    let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
    let mut near: Vec<(f64, usize)> = Vec::new();
    for i in 0..reps.len() {
        near.clear();
        let (x, y) = key(at(i));
        for dx in -1..=1_i64 {
            for dy in -1..=1_i64 {
                let Some(ids) = grid.get(&(x.saturating_add(dx), y.saturating_add(dy))) else {
                    continue;
                };
                for &j in ids {
                    let d = at(i).dist(at(j));
                    if reps[j].0 != reps[i].0 && d <= max_len {
                        near.push((d, j));
                    }
                }
            }
        }
        if near.len() > NEAREST {
            near.select_nth_unstable_by(NEAREST, |a, b| a.0.total_cmp(&b.0));
            near.truncate(NEAREST);
        }
        pairs.extend(near.iter().map(|&(d, j)| (d, i, j)));
    }
    crate::sort::sort_by(&mut pairs, |a, b| a.0.total_cmp(&b.0));
    let mut joined = Parts::new(parts);
    let mut out = Vec::new();
    for (_, i, j) in pairs {
        let (pi, pj) = (reps[i].0, reps[j].0);
        if joined.find(pi) == joined.find(pj) {
            continue;
        }
        let (a, b) = (reps[i].1, reps[j].1);
        if ok(a, b) {
            joined.union(pi, pj);
            part.union(a, b);
            out.push((a, b));
        }
    }
    out
}
