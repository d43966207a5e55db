//! Euler circuit by Hierholzer's algorithm (paper 003 §4), iterative (no
//! recursion: a drawing may hold 10⁵ edges and a wasm stack is small).
//!
//! At each vertex the walk takes the unused edge whose start turns least from
//! the direction it arrived in: a knife or torch going straight on through a
//! crossing keeps its speed and leaves no corner mark where none was drawn.

use crate::geom::{Point, Segment};

/// One edge of the multigraph walked: a drawn edge, a repeated copy, a
/// bridge or a paired rapid.
#[derive(Clone, Copy, Debug)]
pub struct Link {
    /// Start vertex.
    pub u: usize,
    /// End vertex.
    pub v: usize,
    /// Geometry from `u` to `v`.
    pub seg: Segment,
}

impl Link {
    /// The link's path when travelled from `u` (`forward`) or from `v`.
    pub fn oriented(&self, forward: bool) -> Segment {
        if forward {
            self.seg
        } else {
            self.seg.reversed()
        }
    }
}

/// Euler circuit from `start` over the links reachable from it, as (link
/// index, forward) in travel order. Links not reachable from `start` are left
/// out; the caller walks every component. Assumes every vertex touched has
/// even degree (otherwise the result is a set of trails glued at the start).
#[cfg(test)]
pub fn hierholzer(links: &[Link], n_vertices: usize, start: usize) -> Vec<(usize, bool)> {
    circuits(links, n_vertices, &[start])
        .pop()
        .unwrap_or_default()
}

/// One Euler circuit from each of `starts` that still has an unused link,
/// each over the links left by the ones before (so one start per group of
/// linked edges gives every group's circuit, the adjacency built once).
pub fn circuits(links: &[Link], n_vertices: usize, starts: &[usize]) -> Vec<Vec<(usize, bool)>> {
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); n_vertices];
    for (i, l) in links.iter().enumerate() {
        if l.u < n_vertices && l.v < n_vertices {
            adj[l.u].push(i);
            if l.v != l.u {
                adj[l.v].push(i);
            }
        }
    }
    let mut used = vec![false; links.len()];
    let mut all = Vec::new();
    for &start in starts {
        let c = walk(links, &mut adj, &mut used, start);
        if !c.is_empty() {
            all.push(c);
        }
    }
    all
}

/// Hierholzer's walk from `start` over the unused links.
fn walk(
    links: &[Link],
    adj: &mut [Vec<usize>],
    used: &mut [bool],
    start: usize,
) -> Vec<(usize, bool)> {
    let mut stack: Vec<(usize, Option<(usize, bool)>)> = vec![(start, None)];
    let mut out = Vec::new();
    while let Some(&(at, arrived)) = stack.last() {
        let Some(here) = adj.get_mut(at) else {
            stack.pop();
            continue;
        };
        here.retain(|&l| !used[l]);
        let incoming: Option<Point> = arrived.map(|(l, f)| links[l].oriented(f).tangent_at(1.0));
        // Straight on = largest dot product of the incoming and outgoing tangents.
        let best = here
            .iter()
            .map(|&l| {
                let fwd = links[l].u == at;
                let score = incoming.map_or(0.0, |t| t.dot(links[l].oriented(fwd).tangent_at(0.0)));
                (l, fwd, score)
            })
            .max_by(|a, b| a.2.total_cmp(&b.2));
        match best {
            Some((l, fwd, _)) => {
                used[l] = true;
                let next = if fwd { links[l].v } else { links[l].u };
                stack.push((next, Some((l, fwd))));
            }
            None => {
                stack.pop();
                if let Some(a) = arrived {
                    out.push(a);
                }
            }
        }
    }
    // Edges come off the stack last-first; reversed they form the circuit,
    // each in the direction it was walked.
    out.reverse();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(u: usize, v: usize, p: &[Point]) -> Link {
        Link {
            u,
            v,
            seg: Segment::line(p[u], p[v]),
        }
    }

    #[test]
    fn figure_eight_is_one_continuous_circuit_going_straight_through_the_crossing() {
        // Two squares sharing the corner 0 (an X-crossing of degree 4).
        let p = [
            Point::new(0.0, 0.0),
            Point::new(10.0, 0.0),
            Point::new(10.0, 10.0),
            Point::new(0.0, 10.0),
            Point::new(-10.0, 0.0),
            Point::new(-10.0, -10.0),
            Point::new(0.0, -10.0),
        ];
        let links = [
            line(0, 1, &p),
            line(1, 2, &p),
            line(2, 3, &p),
            line(3, 0, &p),
            line(0, 4, &p),
            line(4, 5, &p),
            line(5, 6, &p),
            line(6, 0, &p),
        ];
        let c = hierholzer(&links, p.len(), 0);
        assert_eq!(c.len(), 8);
        let segs: Vec<Segment> = c.iter().map(|&(l, f)| links[l].oriented(f)).collect();
        assert_eq!(segs[0].a, p[0]);
        assert_eq!(segs[7].b, p[0]);
        for w in segs.windows(2) {
            assert_eq!(w[0].b, w[1].a);
        }
        // The one arrival at the crossing before the end goes straight on
        // (0 is where the squares' sides cross: 3 above, 6 below, 1 right,
        // 4 left): from 3 down to 6, from 6 up to 3, from 1 left to 4, from
        // 4 right to 1 — never a turn.
        let mid: Vec<usize> = (0..7).filter(|&k| segs[k].b == p[0]).collect();
        assert_eq!(
            mid.len(),
            1,
            "the circuit passes the crossing once before the end"
        );
        let (arrive, leave) = (segs[mid[0]], segs[mid[0] + 1]);
        let opposite = [(3, 6), (6, 3), (1, 4), (4, 1)];
        let straight = opposite
            .iter()
            .any(|&(from, to)| arrive.a == p[from] && leave.b == p[to]);
        assert!(
            straight,
            "turned at the crossing: {arrive:?} then {leave:?}"
        );
    }

    #[test]
    fn unreachable_start_gives_an_empty_circuit() {
        assert!(hierholzer(&[], 0, 5).is_empty());
    }
}
