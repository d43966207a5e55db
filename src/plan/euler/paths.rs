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

/// Most points the bridges are looked for among with an exact minimum
/// spanning tree (an O(P²) Prim, a few tenths of a second at this size).
pub const BRIDGE_POINTS: usize = 6_000;
/// Most points of one part looked at for its bridges.
const POINTS_PER_PART: usize = 64;

/// Straight bridges (vertex pairs) joining the parts of the `used` vertices
/// into one: the minimum spanning tree of the parts under point-to-point
/// distance (Prim over points, two points of one part costing 0). Each part
/// is represented by at most [`POINTS_PER_PART`] of its vertices, evenly
/// spaced, fewer when there are many parts, so that all stay under
/// [`BRIDGE_POINTS`]: a bridge may then be a little longer than the
/// shortest link between two parts. Above [`BRIDGE_POINTS`] parts, each
/// part by one vertex, the parts are chained nearest-first instead.
pub fn bridges(points: &[Point], used: &[usize], part: &mut Parts) -> Vec<(usize, usize)> {
    let mut by_part: std::collections::HashMap<usize, Vec<usize>> = Default::default();
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
    let dist = |a: usize, b: usize| points[reps[a].1].dist(points[reps[b].1]);
    let n = reps.len();
    let mut out = Vec::new();
    if n > BRIDGE_POINTS {
        // Chain: from the part the chain entered, the nearest unjoined part.
        let mut joined = vec![false; parts];
        let mut at = 0;
        loop {
            joined[reps[at].0] = true;
            let best = (0..n)
                .filter(|&j| !joined[reps[j].0])
                .map(|j| (dist(at, j), j))
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let Some((_, j)) = best else {
                break;
            };
            out.push((reps[at].1, reps[j].1));
            at = j;
        }
        return out;
    }
    // Prim: best[j] = cheapest link from the tree to point j.
    let mut in_tree = vec![false; n];
    let mut best = vec![(f64::INFINITY, 0usize); n];
    let mut next = Some(0);
    while let Some(k) = next {
        in_tree[k] = true;
        if best[k].0 > 0.0 && best[k].0.is_finite() {
            out.push((reps[best[k].1].1, reps[k].1));
        }
        next = None;
        let mut low = f64::INFINITY;
        for j in 0..n {
            if in_tree[j] {
                continue;
            }
            let d = if reps[j].0 == reps[k].0 {
                0.0
            } else {
                dist(k, j)
            };
            if d < best[j].0 {
                best[j] = (d, k);
            }
            if next.is_none() || best[j].0 < low {
                low = best[j].0;
                next = Some(j);
            }
        }
    }
    out
}
