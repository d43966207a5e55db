//! Fewer vertices for the collision model, on the safe side only.
//!
//! A part's collision polygon holds every vertex of its flattened arcs and
//! splines (hundreds on a curved CAD outline), and every collision test,
//! the separator's overlap proxy and the placer pay per vertex. This
//! simplification trades a little area for far fewer vertices, the way
//! jagua-rs and sparrow do before nesting (Gardeyn & Wauters, EJOR 2025,
//! §"polygon simplification"; ideas only): an outline only *grows* (the
//! result holds the input), a room (a hole parts may sit in) only
//! *shrinks* (the result lies in the input), so a nest that is valid for
//! the simplified polygons is valid for the true ones.
//!
//! Two moves, each adding one triangle on the grown side:
//! - **cut a reflex corner**: a vertex turning away from the inside is
//!   dropped, its neighbours joined (the triangle it closed is added);
//! - **extend two edges**: an edge between two convex corners is dropped
//!   and the edges on either side are extended to where they meet (two
//!   vertices become one; the triangle beyond the edge is added).
//!
//! Cheapest move first (the area it adds), while the area added stays
//! within `excess` × the polygon's area ([`EXCESS`]). A move is made only
//! when its new edges cross no other edge (checked against every edge:
//! the result is always a simple polygon) and its new vertex stays inside
//! the input's box (a simplified part is never longer or taller than the
//! part, so a strip's length is not spent on it).
//!
//! Applied to outlines of more than [`MANY_VERTICES`] vertices, grown
//! first by a hundredth of the tolerance ([`nesting_polygon`]); rooms are
//! kept exact, so a disc fits its bore as before. Measured (2026-11-30,
//! scripts/bench-nest.sh): the first version (every outline and room, no
//! margin) gave two invalid `panels` nests (a flush contact 9·10⁻⁵ mm
//! deep) and the round `flanges` parts 2.5 points less; this one was
//! valid on every run and leaves round parts and the ESICUP polygons as
//! they were.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::shape::{collision_polygon, Polygon};
use crate::geom::{orient, BBox, Point, Segment};

/// The area a part's collision polygon may grow by (and a room shrink
/// by), as a fraction of its area: 0.1 %, sparrow's default. Measured
/// (scripts/bench-nest.sh, 2026-11-30): 0.05 %, 0.1 % and 0.5 %.
pub const EXCESS: f64 = 0.001;

/// Outlines of more vertices than this are simplified; fewer are kept as
/// they are (ESICUP's polygons, discs and plates of few arcs).
pub const MANY_VERTICES: usize = 64;

/// The polygon a part is nested on: its collision polygon (the outline
/// grown by `grow`, [`collision_polygon`]); for a many-vertex outline
/// (finger joints, flattened splines) that polygon grown by a further
/// hundredth of the tolerance `tol`, then [`simplified`]. The exact test
/// lets two collision polygons lie flush a few thousandths of the
/// tolerance deep (a 9·10⁻⁵ mm contact along 45 mm was measured, which
/// check_nest.py refuses); the margin keeps such a contact off the parts.
pub fn nesting_polygon(outline: &[Segment], grow: f64, tol: f64) -> Option<Polygon> {
    let poly = collision_polygon(outline, grow, tol)?;
    if poly.pts.len() <= MANY_VERTICES {
        return Some(poly);
    }
    let wide = collision_polygon(outline, grow + tol / 100.0, tol);
    Some(wide.map_or(poly, |g| simplified(&g, Side::Grow, EXCESS)))
}

/// Which way a polygon may change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Only grow: a part's outline (the result holds the input).
    Grow,
    /// Only shrink: a room (the result lies inside the input).
    Shrink,
}

/// `poly` with fewer vertices, grown (or shrunk) by at most `excess` × its
/// area, never self-crossing, inside its box. A polygon with no area, or
/// not finite, comes back as it is.
pub fn simplified(poly: &Polygon, side: Side, excess: f64) -> Polygon {
    let area = poly.area();
    let budget = excess * area;
    if poly.pts.len() <= 4 || !budget.is_finite() || budget <= 0.0 {
        return poly.clone();
    }
    // Worked on with the side that grows on the left: a part's polygon is
    // counter-clockwise (inside on the left); a room's is reversed (the
    // outside of the room on the left), so its room shrinks.
    let mut pts = poly.pts.clone();
    if side == Side::Shrink {
        pts.reverse();
    }
    let mut w = Work::new(pts, poly.bbox);
    w.run(budget);
    Polygon::new(w.into_points())
}

/// A move, keyed by the vertex it starts at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// Drop vertex `v` (a reflex or straight corner).
    Cut,
    /// Drop the edge `v → next(v)`, its neighbours extended to meet.
    Extend,
}

/// A move in the queue: the cheapest first, then by vertex (deterministic).
#[derive(Clone, Copy, Debug)]
struct Move {
    added: f64,
    v: usize,
    kind: Kind,
    stamp: u32,
}

impl PartialEq for Move {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Move {}
impl PartialOrd for Move {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Move {
    // Reversed: BinaryHeap pops the largest, we want the smallest area.
    fn cmp(&self, o: &Self) -> Ordering {
        o.added
            .total_cmp(&self.added)
            .then(o.v.cmp(&self.v))
            .then((o.kind as u8).cmp(&(self.kind as u8)))
    }
}

/// The polygon as a ring of live vertices, with the moves queued.
struct Work {
    pts: Vec<Point>,
    prev: Vec<usize>,
    next: Vec<usize>,
    alive: Vec<bool>,
    /// Bumped whenever a vertex's neighbourhood changes: older moves of it
    /// are stale.
    stamp: Vec<u32>,
    live: usize,
    bbox: BBox,
    queue: BinaryHeap<Move>,
}

/// Do the closed segments `p0 p1` and `q0 q1` meet (touching counts)?
fn segments_meet(p0: Point, p1: Point, q0: Point, q1: Point) -> bool {
    let (o1, o2) = (orient(p0, p1, q0), orient(p0, p1, q1));
    let (o3, o4) = (orient(q0, q1, p0), orient(q0, q1, p1));
    if o1 == 0.0 && o2 == 0.0 {
        // Collinear: do their boxes overlap?
        let lo = |a: f64, b: f64| a.min(b);
        let hi = |a: f64, b: f64| a.max(b);
        return lo(p0.x, p1.x) <= hi(q0.x, q1.x)
            && lo(q0.x, q1.x) <= hi(p0.x, p1.x)
            && lo(p0.y, p1.y) <= hi(q0.y, q1.y)
            && lo(q0.y, q1.y) <= hi(p0.y, p1.y);
    }
    o1 * o2 <= 0.0 && o3 * o4 <= 0.0
}

/// Two segments `x → y` and `y → z` sharing `y`: does `y → z` fold back
/// along `x → y` (the only way two such segments meet elsewhere)?
fn folds_back(x: Point, y: Point, z: Point) -> bool {
    let (u, v) = (y.sub(x), z.sub(y));
    let straight = u.cross(v).abs() <= 1e-12 * u.norm() * v.norm();
    straight && u.dot(v) < 0.0
}

/// Is `p` strictly inside the triangle `a b c` (either orientation)? A
/// point on its new edge is found by the crossing test instead.
fn in_triangle(p: Point, a: Point, b: Point, c: Point) -> bool {
    let (d1, d2, d3) = (orient(a, b, p), orient(b, c, p), orient(c, a, p));
    (d1 > 0.0 && d2 > 0.0 && d3 > 0.0) || (d1 < 0.0 && d2 < 0.0 && d3 < 0.0)
}

impl Work {
    fn new(pts: Vec<Point>, bbox: BBox) -> Work {
        let n = pts.len();
        let mut w = Work {
            prev: (0..n).map(|i| (i + n - 1) % n).collect(),
            next: (0..n).map(|i| (i + 1) % n).collect(),
            alive: vec![true; n],
            stamp: vec![0; n],
            live: n,
            bbox,
            queue: BinaryHeap::new(),
            pts,
        };
        for v in 0..n {
            w.queue_moves(v);
        }
        w
    }

    fn into_points(self) -> Vec<Point> {
        let start = (0..self.pts.len()).find(|&i| self.alive[i]).unwrap_or(0);
        let mut out = Vec::with_capacity(self.live);
        let mut v = start;
        for _ in 0..self.live {
            out.push(self.pts[v]);
            v = self.next[v];
        }
        out
    }

    /// The point where `a → v` and `c → b` extended meet, beyond `v` and
    /// `b`, for the move Extend at `v` (`a = prev v`, `b = next v`,
    /// `c = next b`).
    fn apex(&self, v: usize) -> Option<Point> {
        let (a, b) = (self.prev[v], self.next[v]);
        let c = self.next[b];
        let (pa, pv, pb, pc) = (self.pts[a], self.pts[v], self.pts[b], self.pts[c]);
        let (d1, d2) = (pv.sub(pa), pb.sub(pc));
        let den = d1.cross(d2);
        if den == 0.0 || !den.is_finite() {
            return None;
        }
        let e = pb.sub(pv);
        let s = e.cross(d2) / den;
        let t = e.cross(d1) / den;
        (s > 0.0 && t > 0.0 && s.is_finite() && t.is_finite()).then(|| pv.add(d1.scale(s)))
    }

    /// The area move `kind` at `v` adds, if it is a move that only adds.
    fn added(&self, v: usize, kind: Kind) -> Option<f64> {
        let (a, b) = (self.prev[v], self.next[v]);
        let (pa, pv, pb) = (self.pts[a], self.pts[v], self.pts[b]);
        let turn = orient(pa, pv, pb);
        match kind {
            // A right turn (or none): the triangle a v b lies outside.
            Kind::Cut => (turn <= 0.0).then_some(-turn / 2.0),
            Kind::Extend => {
                let c = self.next[b];
                if turn <= 0.0 || orient(pv, pb, self.pts[c]) <= 0.0 {
                    return None;
                }
                let p = self.apex(v)?;
                // p right of v → b: the triangle v p b lies outside.
                let t = orient(pv, pb, p);
                (t < 0.0).then_some(-t / 2.0)
            }
        }
    }

    fn queue_moves(&mut self, v: usize) {
        if self.live <= 4 {
            return;
        }
        for kind in [Kind::Cut, Kind::Extend] {
            if let Some(added) = self.added(v, kind) {
                self.queue.push(Move {
                    added,
                    v,
                    kind,
                    stamp: self.stamp[v],
                });
            }
        }
    }

    /// Does the chain `from → via → to` (replacing the live chain between
    /// `from` and `to`) keep the polygon simple? `via` is the new vertex,
    /// if any; `gone` the triangle the move adds, whose inside must hold
    /// no other vertex.
    fn keeps_simple(&self, from: usize, via: Option<Point>, to: usize, gone: [Point; 3]) -> bool {
        let (pf, pt) = (self.pts[from], self.pts[to]);
        let mut new_segs: [(Point, Point, Option<usize>, Option<usize>); 2] =
            [(pf, pt, Some(from), Some(to)); 2];
        let count = match via {
            Some(p) => {
                new_segs[0] = (pf, p, Some(from), None);
                new_segs[1] = (p, pt, None, Some(to));
                2
            }
            None => 1,
        };
        // Every live edge outside the replaced chain: to → … → from.
        let mut u = to;
        while u != from {
            let w = self.next[u];
            let (pu, pw) = (self.pts[u], self.pts[w]);
            if u != to && in_triangle(pu, gone[0], gone[1], gone[2]) {
                return false;
            }
            for &(s0, s1, i0, i1) in &new_segs[..count] {
                let bad = match (i0 == Some(w), i1 == Some(u)) {
                    // The edge ends where the new segment starts.
                    (true, false) => folds_back(pu, s0, s1),
                    // The edge starts where the new segment ends.
                    (false, true) => folds_back(s0, s1, pw),
                    // Both ends shared: a two-edge ring, not a polygon.
                    (true, true) => true,
                    (false, false) => segments_meet(s0, s1, pu, pw),
                };
                if bad {
                    return false;
                }
            }
            u = w;
        }
        true
    }

    fn inside_box(&self, p: Point) -> bool {
        let b = &self.bbox;
        p.x >= b.min.x && p.x <= b.max.x && p.y >= b.min.y && p.y <= b.max.y
    }

    /// Makes the cheapest moves while the area added stays within `budget`.
    fn run(&mut self, budget: f64) {
        let mut spent = 0.0;
        while let Some(m) = self.queue.pop() {
            if self.live <= 4 {
                break;
            }
            if !self.alive[m.v] || self.stamp[m.v] != m.stamp || spent + m.added > budget {
                continue;
            }
            let v = m.v;
            let (a, b) = (self.prev[v], self.next[v]);
            let (pa, pv, pb) = (self.pts[a], self.pts[v], self.pts[b]);
            match m.kind {
                Kind::Cut => {
                    if !self.keeps_simple(a, None, b, [pa, pv, pb]) {
                        continue;
                    }
                    self.alive[v] = false;
                    self.next[a] = b;
                    self.prev[b] = a;
                    self.live -= 1;
                    self.touch_around(a);
                }
                Kind::Extend => {
                    let c = self.next[b];
                    let Some(p) = self.apex(v) else { continue };
                    if !self.inside_box(p) || !self.keeps_simple(a, Some(p), c, [pv, p, pb]) {
                        continue;
                    }
                    self.pts[v] = p;
                    self.alive[b] = false;
                    self.next[v] = c;
                    self.prev[c] = v;
                    self.live -= 1;
                    self.touch_around(v);
                }
            }
            spent += m.added;
        }
    }

    /// Stales and queues again the moves of the vertices within two of `v`
    /// (every move that reads a vertex that changed).
    fn touch_around(&mut self, v: usize) {
        let mut u = self.prev[self.prev[v]];
        for _ in 0..5 {
            self.stamp[u] = self.stamp[u].wrapping_add(1);
            self.queue_moves(u);
            u = self.next[u];
        }
    }
}

#[cfg(test)]
#[path = "simplify_tests.rs"]
mod tests;
