//! Parts that share edges (issue 39 §6): where three or more ends meet (a
//! branch point), chaining by nearest end picks one way on arbitrarily and
//! its loops run round several parts, or none. A nest of panels drawn with
//! their common lines once (Deepnest's merged lines, box-joint nests) is a
//! planar graph, and its parts are the graph's faces.
//!
//! - The pieces that touch end to end (transitively) form groups; a group
//!   with a branch point is drawn into one graph ([`graph::build`]: ends
//!   within the tolerance are one vertex, a vertex on another piece's
//!   inside splits it, a line drawn twice is one edge).
//! - At each vertex the edges leaving it are sorted by the angle of their
//!   tangent there (an arc's, not its chord's), ties by curvature; from
//!   each edge the walk turns to the next edge clockwise at its far end,
//!   which traces the face on the edge's left (the standard half-edge face
//!   walk of a planar map, de Berg et al., *Computational Geometry*, §2.2).
//! - A face walked counter-clockwise with an area (as a loop must have one
//!   to be a part) is bounded: it becomes a closed chain. An edge with the
//!   same face on both sides (a line hanging into a part or joining two) is
//!   no part's edge: it is taken out, the faces walked again, and it is
//!   left open. An edge drawn once with bounded faces on both sides is
//!   shared; drawn by both faces' own lines, each keeps its copy (parts
//!   that touch, as closed outlines that touch: `super::super::heal`).
//! - A group none of whose edges bounds a face (a tree of lines) is
//!   chained by nearest end as before; so is everything without a branch.

use std::collections::HashSet;

use super::walk::Walker;
use super::{Chain, Measure, Pieces};
use crate::geom::graph::{self, Graph};
use crate::geom::{end_tangents, Point, Segment};

/// What the faces made, summed over the chaining passes that look for them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FaceLog {
    /// Bounded faces made closed chains.
    pub faces: usize,
    /// Length of the shared edges, each counted once, mm.
    pub shared_length: f64,
    /// A point on the first shared edge.
    pub shared_at: Option<Point>,
    /// Where a segment drawn twice was kept once.
    pub duplicates: Vec<Point>,
}

/// The faces of the branched groups that have some.
pub(super) struct Found {
    /// Per open piece: drawn into a face's group (not walked).
    pub taken: Vec<bool>,
    /// The bounded faces, counter-clockwise.
    pub loops: Vec<Chain>,
    /// Edges of those groups on no bounded face, one piece each.
    pub leftover: Pieces,
}

/// Union-find over piece numbers.
fn root(up: &mut [u32], mut i: u32) -> u32 {
    while up[i as usize] != i {
        let next = up[up[i as usize] as usize];
        up[i as usize] = next;
        i = next;
    }
    i
}

/// The faces of the groups of `w`'s pieces that meet at a branch point,
/// or None when no such group bounds a face. Ends within `t` meet.
pub(super) fn find(w: &Walker, t: f64, log: &mut FaceLog) -> Option<Found> {
    let n = w.open.len();
    let mut up: Vec<u32> = (0..n as u32).collect();
    let mut branched = vec![false; n];
    for (i, branch) in branched.iter_mut().enumerate() {
        let (a, b) = w.open.ends_of(i, false);
        for p in [a, b] {
            // Ends within `t` of this one, itself included.
            let mut ends = 0;
            w.touching(p, |j| {
                ends += 1;
                let (ri, rj) = (root(&mut up, i as u32), root(&mut up, j as u32));
                up[ri.max(rj) as usize] = ri.min(rj);
            });
            *branch |= ends >= 3;
        }
    }
    let mut group_branched = vec![false; n];
    for i in 0..n {
        if branched[i] {
            group_branched[root(&mut up, i as u32) as usize] = true;
        }
    }
    let drawn: Vec<usize> = (0..n)
        .filter(|&i| group_branched[root(&mut up, i as u32) as usize])
        .collect();
    if drawn.is_empty() {
        return None;
    }
    let segments: Vec<(Segment, usize)> = drawn
        .iter()
        .flat_map(|&k| w.open.piece(k).0.iter().map(move |s| (*s, k)))
        .collect();
    let g = graph::build(&segments, t);
    let walked = faces(&g, t);
    // A group is taken when one of its pieces draws an edge of a bounded face.
    let mut group_taken = vec![false; n];
    for (e, edge) in g.edges.iter().enumerate() {
        if walked.on_face(e) {
            for k in std::iter::once(edge.contour).chain(edge.also) {
                group_taken[root(&mut up, k as u32) as usize] = true;
            }
        }
    }
    let taken: Vec<bool> = (0..n)
        .map(|i| group_taken[root(&mut up, i as u32) as usize])
        .collect();
    if !taken.iter().any(|&x| x) {
        return None;
    }
    let entities = |e: usize, out: &mut Vec<usize>, seen: &mut HashSet<usize>| {
        let edge = &g.edges[e];
        for k in std::iter::once(edge.contour).chain(edge.also) {
            out.extend(w.open.piece(k).1.iter().filter(|&&x| seen.insert(x)));
        }
    };
    let mut loops = Vec::new();
    let mut sharing = vec![false; walked.cycles.len()];
    for (e, edge) in g.edges.iter().enumerate() {
        if !taken[edge.contour] {
            continue;
        }
        match (walked.shared(e), edge.also.is_some()) {
            // Drawn once between two faces: one line for both.
            (true, false) => {
                log.shared_length += edge.seg.length();
                log.shared_at = log.shared_at.or(Some(edge.seg.point_at(0.5)));
                sharing[walked.face[2 * e] as usize] = true;
                sharing[walked.face[2 * e + 1] as usize] = true;
            }
            // Drawn by each of the two faces: each keeps its copy, as
            // touching parts drawn closed do (`heal`'s rule).
            (true, true) => {}
            (false, true) => log.duplicates.push(edge.seg.point_at(0.5)),
            (false, false) => {}
        }
    }
    for (c, cycle) in walked.cycles.iter().enumerate() {
        if !walked.bounded[c] {
            continue;
        }
        let segments: Vec<Segment> = cycle.iter().map(|&h| half(&g, h)).collect();
        let mut ents = Vec::new();
        let mut seen = HashSet::new();
        for &h in cycle {
            entities(h as usize / 2, &mut ents, &mut seen);
        }
        log.faces += 1;
        loops.push(Chain {
            measure: Measure::of(&segments),
            segments,
            closed: true,
            entities: ents,
            shares_edges: sharing[c],
        });
    }
    let mut leftover = Pieces::default();
    for (e, edge) in g.edges.iter().enumerate() {
        if taken[edge.contour] && !walked.on_face(e) {
            leftover.open_segments().push(edge.seg);
            let mut ents = Vec::new();
            entities(e, &mut ents, &mut HashSet::new());
            leftover.close_open(&ents);
        }
    }
    Some(Found {
        taken,
        loops,
        leftover,
    })
}

/// Half-edge `h` of `g`: edge `h / 2` as drawn (even) or reversed (odd).
fn half(g: &Graph, h: u32) -> Segment {
    let s = g.edges[h as usize / 2].seg;
    if h.is_multiple_of(2) {
        s
    } else {
        s.reversed()
    }
}

/// The faces of a graph: each half-edge's face, each face's half-edges in
/// walk order, which faces are bounded, and which edges were taken out.
pub(super) struct FaceWalk {
    /// The face on each half-edge's left (`u32::MAX` for an edge taken out).
    pub face: Vec<u32>,
    pub cycles: Vec<Vec<u32>>,
    pub bounded: Vec<bool>,
}

impl FaceWalk {
    /// True when edge `e` bounds a face.
    fn on_face(&self, e: usize) -> bool {
        let side = |h: usize| {
            let f = self.face[h];
            f != u32::MAX && self.bounded[f as usize]
        };
        side(2 * e) || side(2 * e + 1)
    }
    /// True when edge `e` bounds a face on each side (two different ones:
    /// an edge with one face on both sides was taken out).
    fn shared(&self, e: usize) -> bool {
        let side = |h: usize| {
            let f = self.face[h];
            f != u32::MAX && self.bounded[f as usize]
        };
        side(2 * e) && side(2 * e + 1)
    }
}

/// Where an edge leaves a vertex, for sorting round it: the angle of its
/// tangent there (quantised: a total order; edges leaving within 1e-9 rad
/// are told apart by curvature), then its signed curvature (an edge that
/// turns left lies counter-clockwise of one that goes straight on).
fn leaving(s: &Segment) -> (i64, f64) {
    let (t0, _) = end_tangents(s);
    let angle = t0.y.atan2(t0.x);
    let q = if angle.is_finite() {
        (angle * 1e9).round() as i64
    } else {
        0
    };
    let curvature = match s.arc_center() {
        Some((_, r)) if r > 0.0 => s.bulge.signum() / r,
        _ => 0.0,
    };
    (q, curvature)
}

/// Walks the faces of `g`, taking out edges with one face on both sides
/// until none is left; a face is bounded when it runs counter-clockwise
/// round an area of more than `t` times its length (`contour::extract`'s
/// rule for a loop).
pub(super) fn faces(g: &Graph, t: f64) -> FaceWalk {
    let m = g.edges.len();
    let nv = g.vertices.len();
    let mut alive = vec![true; m];
    loop {
        // Each vertex's leaving half-edges, sorted counter-clockwise.
        let mut around: Vec<Vec<u32>> = vec![Vec::new(); nv];
        for (e, edge) in g.edges.iter().enumerate() {
            if alive[e] {
                around[edge.u].push(2 * e as u32);
                around[edge.v].push(2 * e as u32 + 1);
            }
        }
        let mut pos = vec![0u32; 2 * m];
        for list in &mut around {
            let mut keyed: Vec<((i64, f64), u32)> =
                list.iter().map(|&h| (leaving(&half(g, h)), h)).collect();
            keyed.sort_by(|a, b| {
                (a.0 .0.cmp(&b.0 .0))
                    .then(a.0 .1.total_cmp(&b.0 .1))
                    .then(a.1.cmp(&b.1))
            });
            *list = keyed.into_iter().map(|(_, h)| h).collect();
            for (i, &h) in list.iter().enumerate() {
                pos[h as usize] = i as u32;
            }
        }
        let head = |h: u32| {
            let e = &g.edges[h as usize / 2];
            if h.is_multiple_of(2) {
                e.v
            } else {
                e.u
            }
        };
        // The next half-edge round the face on `h`'s left: at its head,
        // the one clockwise of its twin.
        let next = |h: u32| {
            let list = &around[head(h)];
            let i = pos[(h ^ 1) as usize] as usize;
            list[(i + list.len() - 1) % list.len()]
        };
        let mut face = vec![u32::MAX; 2 * m];
        let mut cycles: Vec<Vec<u32>> = Vec::new();
        for start in 0..2 * m as u32 {
            if !alive[start as usize / 2] || face[start as usize] != u32::MAX {
                continue;
            }
            let id = cycles.len() as u32;
            let mut cycle = Vec::new();
            let mut h = start;
            // Every half-edge has one successor and one predecessor, so the
            // walk comes back to its start; the bound only guards it.
            while face[h as usize] == u32::MAX && cycle.len() <= 2 * m {
                face[h as usize] = id;
                cycle.push(h);
                h = next(h);
            }
            cycles.push(cycle);
        }
        let mut out = false;
        for e in 0..m {
            if alive[e] && face[2 * e] == face[2 * e + 1] {
                alive[e] = false;
                out = true;
            }
        }
        if out {
            continue;
        }
        let bounded = cycles
            .iter()
            .map(|c| {
                let (mut area, mut length) = (0.0, 0.0);
                for &h in c {
                    let s = half(g, h);
                    area += s.area_term();
                    length += s.length();
                }
                area > t * length
            })
            .collect();
        return FaceWalk {
            face,
            cycles,
            bounded,
        };
    }
}

#[cfg(test)]
mod tests;
