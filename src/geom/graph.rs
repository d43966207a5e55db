//! The edge graph of drawn segments: every segment becomes an edge between
//! snapped vertices; edges drawn twice (by two neighbouring parts, or by
//! two entities) become one. The Eulerian order walks it (paper 003 §3,
//! common-line cutting); the contour stage finds its faces where lines
//! meet at branch points (`contour::chain::faces`).
//!
//! Shared edges are found without comparing all pairs: a vertex that lies on
//! the inside of another segment (a T-junction, or the end of a partial
//! overlap) splits that segment there, so overlapping pieces end up between
//! the same two vertices and are merged when their midpoints coincide. This
//! handles collinear lines and co-circular arcs alike, in either direction.

use crate::cell_lists::CellLists;
use crate::fx::FxMap;

use super::{dist_to_segment, Point, Segment};

/// One edge, between vertices `u` and `v`, drawn from `u` to `v`.
#[derive(Clone, Copy, Debug)]
pub struct Edge {
    /// Geometry from `vertices[u]` to `vertices[v]`.
    pub seg: Segment,
    /// Start vertex.
    pub u: usize,
    /// End vertex.
    pub v: usize,
    /// The first source it was drawn in (a contour, or a piece of one).
    pub contour: usize,
    /// Another source that drew it too (a shared edge).
    pub also: Option<usize>,
}

/// Vertices and merged edges.
#[derive(Default)]
pub struct Graph {
    /// Snapped vertex positions.
    pub vertices: Vec<Point>,
    /// Merged edges.
    pub edges: Vec<Edge>,
    /// Edge ids at each vertex, in the order the edges were made.
    adj: CellLists,
    /// Edges dropped because an equal edge was already there (shared edges).
    pub merged: usize,
}

impl Graph {
    /// Degree of vertex `v`.
    pub fn degree(&self, v: usize) -> usize {
        self.adj.get(v).len()
    }
    /// The ids of the edges at vertex `v`, in the order they were made.
    pub fn edges_at(&self, v: usize) -> &[u32] {
        self.adj.get(v)
    }
    /// Vertices of odd degree, in index order.
    #[cfg(test)]
    pub fn odd_vertices(&self) -> Vec<usize> {
        (0..self.vertices.len())
            .filter(|&v| self.degree(v) % 2 == 1)
            .collect()
    }
}

/// Hash grid of points, cell size `cell`: which vertex is near a point.
/// Each cell's points are a chain in the order they came (its first and
/// last in the map, each point's next in `next`): a vector per cell was
/// an allocation per vertex on a sheet of 100k contours (issue 17).
struct Grid {
    cell: f64,
    cells: FxMap<(i64, i64), (usize, usize)>,
    next: Vec<usize>,
}

impl Grid {
    fn new(cell: f64) -> Self {
        Grid {
            cell,
            cells: FxMap::default(),
            next: Vec::new(),
        }
    }
    fn key(&self, p: Point) -> (i64, i64) {
        // `as` saturates, so a huge coordinate lands in an edge cell, never panics.
        (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        )
    }
    /// Files point `id` (larger than every id filed before) at `p`.
    fn insert(&mut self, p: Point, id: usize) {
        if self.next.len() <= id {
            self.next.resize(id + 1, usize::MAX);
        }
        let k = self.key(p);
        match self.cells.get_mut(&k) {
            Some((_, last)) => {
                self.next[*last] = id;
                *last = id;
            }
            None => {
                self.cells.insert(k, (id, id));
            }
        }
    }
    /// Ids in the cells around `p` (3×3 block).
    fn around(&self, p: Point, out: &mut Vec<usize>) {
        let (x, y) = self.key(p);
        for dx in -1..=1 {
            for dy in -1..=1 {
                let cell = (x.saturating_add(dx), y.saturating_add(dy));
                let mut at = self.cells.get(&cell).map_or(usize::MAX, |c| c.0);
                while at != usize::MAX {
                    out.push(at);
                    at = self.next[at];
                }
            }
        }
    }
    /// Ids in the cells along a segment (sampled every half cell, each with
    /// its 3×3 block, so everything within one cell of the path is seen).
    fn along(&self, s: &Segment, out: &mut Vec<usize>) {
        let n = (s.length() / (0.5 * self.cell)).ceil();
        // At most ~10⁵ samples: a segment longer than that many cells is
        // the drawing's extent over again and its vertices are few.
        let n = if n.is_finite() {
            n.clamp(1.0, 1e5) as usize
        } else {
            1
        };
        out.clear();
        let mut last = None;
        for k in 0..=n {
            let p = s.point_at(k as f64 / n as f64);
            let key = self.key(p);
            if last != Some(key) {
                last = Some(key);
                self.around(p, out);
            }
        }
        crate::sort::sort_indices(out);
        out.dedup();
    }
}

/// Builds the graph of `segments` (each with its contour index); points
/// within `tol` mm are one vertex.
pub fn build(segments: &[(Segment, usize)], tol: f64) -> Graph {
    let tol = if tol.is_finite() && tol > 0.0 {
        tol
    } else {
        1e-6
    };
    let segs: Vec<(Segment, usize)> = segments
        .iter()
        .copied()
        .filter(|(s, _)| s.is_finite() && s.chord() > tol)
        .collect();
    // 1. Snap end points into vertices (cell = tol: a match is in the 3×3 block).
    let mut snap = Grid::new(tol);
    let mut vertices: Vec<Point> = Vec::new();
    let mut near_ids = Vec::new();
    let mut vertex = |p: Point, vertices: &mut Vec<Point>| -> usize {
        near_ids.clear();
        snap.around(p, &mut near_ids);
        if let Some(&i) = near_ids.iter().find(|&&i| vertices[i].dist(p) <= tol) {
            return i;
        }
        vertices.push(p);
        snap.insert(p, vertices.len() - 1);
        vertices.len() - 1
    };
    let ends: Vec<(usize, usize)> = segs
        .iter()
        .map(|(s, _)| (vertex(s.a, &mut vertices), vertex(s.b, &mut vertices)))
        .collect();
    // 2. Split segments at vertices on their inside. Grid cells the size of
    // a median segment hold about one vertex each along a path, however the
    // drawing is spread out (a cell sized from the extent would put a dense
    // part into one cell and make this quadratic).
    let mut chords: Vec<f64> = segs.iter().map(|(s, _)| s.chord()).collect();
    let mid = chords.len() / 2;
    let median = if chords.is_empty() {
        1.0
    } else {
        // The middle of the sorted chords: what select_nth_unstable gives.
        crate::sort::sort_floats(&mut chords);
        chords[mid]
    };
    let cell = median.max(4.0 * tol);
    let mut near = Grid::new(cell);
    for (i, p) in vertices.iter().enumerate() {
        near.insert(*p, i);
    }
    let mut g = Graph {
        vertices,
        ..Graph::default()
    };
    let mut by_ends = SameEnds::default();
    let (mut candidates, mut cuts) = (Vec::new(), Vec::new());
    for (&(seg, contour), &(u, v)) in segs.iter().zip(&ends) {
        near.along(&seg, &mut candidates);
        cuts.clear();
        cuts.extend(
            candidates
                .iter()
                .copied()
                .filter(|&w| w != u && w != v)
                .filter_map(|w| {
                    let p = g.vertices[w];
                    (dist_to_segment(p, &seg) <= tol).then(|| (param(&seg, p), w))
                })
                .filter(|(t, _)| *t > 0.0 && *t < 1.0),
        );
        crate::sort::sort_by(&mut cuts, |a: &(f64, usize), b| a.0.total_cmp(&b.0));
        cuts.dedup_by_key(|c| c.1);
        let mut from = (0.0, u);
        for &to in cuts.iter().chain(&[(1.0, v)]) {
            add_edge(&mut g, &mut by_ends, &seg, from, to, contour, tol);
            from = to;
        }
    }
    let edges = &g.edges;
    g.adj = CellLists::build(g.vertices.len(), |f| {
        for (id, e) in edges.iter().enumerate() {
            f.push(e.u, id as u32);
            f.push(e.v, id as u32);
        }
    });
    g
}

/// The edges between each pair of vertices, in the order they were made:
/// the first under its pair, each one's next in `next` (nearly every
/// pair has one edge: a vector each was a fresh allocation per edge).
#[derive(Default)]
struct SameEnds {
    first: FxMap<(usize, usize), usize>,
    next: Vec<usize>,
}

impl SameEnds {
    /// The edges between `key`'s vertices, in order.
    fn each(&self, key: (usize, usize)) -> impl Iterator<Item = usize> + '_ {
        let mut at = self.first.get(&key).copied();
        std::iter::from_fn(move || {
            let e = at?;
            at = Some(self.next[e]).filter(|&n| n != usize::MAX);
            Some(e)
        })
    }
    /// Files edge `id` (the newest) under `key`, after those there.
    fn push(&mut self, key: (usize, usize), id: usize) {
        if self.next.len() <= id {
            self.next.resize(id + 1, usize::MAX);
        }
        match self.each(key).last() {
            Some(last) => self.next[last] = id,
            None => {
                self.first.insert(key, id);
            }
        }
    }
}

/// Where `p` lies along `s`, 0 at `a` to 1 at `b` (by angle on an arc).
pub fn param(s: &Segment, p: Point) -> f64 {
    match s.arc_center() {
        Some((c, _)) => {
            let a0 = s.a.sub(c);
            let v = p.sub(c);
            let sweep = s.sweep();
            let d = a0.cross(v).atan2(a0.dot(v));
            // Angle from a in the arc's turning sense, in [0, 2π).
            let d = if sweep >= 0.0 { d } else { -d }.rem_euclid(std::f64::consts::TAU);
            d / sweep.abs().max(f64::MIN_POSITIVE)
        }
        None => {
            let d = s.b.sub(s.a);
            p.sub(s.a).dot(d) / d.dot(d).max(f64::MIN_POSITIVE)
        }
    }
}

/// Adds the piece of `seg` between parameters `from.0` and `to.0` (vertices
/// `from.1`, `to.1`) unless an equal edge is there already.
fn add_edge(
    g: &mut Graph,
    by_ends: &mut SameEnds,
    seg: &Segment,
    from: (f64, usize),
    to: (f64, usize),
    contour: usize,
    tol: f64,
) {
    let (u, v) = (from.1, to.1);
    if u == v {
        return;
    }
    // A piece keeps the arc's turn: its sweep is the parameter span's share.
    let bulge = if seg.is_line() {
        0.0
    } else {
        (seg.sweep() * (to.0 - from.0) / 4.0).tan()
    };
    let piece = Segment {
        a: g.vertices[u],
        b: g.vertices[v],
        bulge,
    };
    let mid = piece.point_at(0.5);
    let key = (u.min(v), u.max(v));
    let same = by_ends
        .each(key)
        .find(|&e| g.edges[e].seg.point_at(0.5).dist(mid) <= tol);
    if let Some(e) = same {
        g.merged += 1;
        let edge = &mut g.edges[e];
        if edge.contour != contour && edge.also.is_none() {
            edge.also = Some(contour);
        }
        return;
    }
    let id = g.edges.len();
    g.edges.push(Edge {
        seg: piece,
        u,
        v,
        contour,
        also: None,
    });
    by_ends.push(key, id);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64, c: usize) -> Vec<(Segment, usize)> {
        let p = [
            Point::new(x0, y0),
            Point::new(x1, y0),
            Point::new(x1, y1),
            Point::new(x0, y1),
        ];
        (0..4)
            .map(|i| (Segment::line(p[i], p[(i + 1) % 4]), c))
            .collect()
    }

    #[test]
    fn two_touching_squares_share_one_edge() {
        let mut s = rect(0.0, 0.0, 10.0, 10.0, 0);
        s.extend(rect(10.0, 0.0, 20.0, 10.0, 1));
        let g = build(&s, 1e-3);
        assert_eq!((g.vertices.len(), g.edges.len(), g.merged), (6, 7, 1));
        assert_eq!(g.odd_vertices().len(), 2);
    }

    #[test]
    fn partial_overlap_is_split_at_each_end() {
        // Second rectangle's left edge x=10, y 5..15 overlaps the first's 0..10.
        let mut s = rect(0.0, 0.0, 10.0, 10.0, 0);
        s.extend(rect(10.0, 5.0, 20.0, 15.0, 1));
        let g = build(&s, 1e-3);
        let total: f64 = g.edges.iter().map(|e| e.seg.length()).sum();
        assert!((total - 75.0).abs() < 1e-9, "{total}");
        assert_eq!(g.merged, 1);
        assert_eq!(g.vertices.len(), 8);
    }

    #[test]
    fn duplicate_arc_in_the_other_direction_is_merged_and_halves_split() {
        let a = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let quarter = Segment {
            a: Point::new(0.0, 10.0),
            b: Point::new(10.0, 0.0),
            bulge: -(std::f64::consts::FRAC_PI_8).tan(),
        };
        let g = build(&[(a, 0), (a.reversed(), 1), (quarter, 2)], 1e-6);
        assert_eq!(g.edges.len(), 2, "{:?}", g.edges);
        let total: f64 = g.edges.iter().map(|e| e.seg.length()).sum();
        assert!((total - 10.0 * std::f64::consts::PI).abs() < 1e-6);
    }

    #[test]
    fn a_grid_gives_each_cell_its_points_in_the_order_they_came() {
        // 200 points over 5 x 5 cells of 1 mm: around() lists the 3 x 3
        // cells column by column, each cell's points by id, as vectors
        // per cell did; the same for the edges between two vertices.
        let mut f = crate::test_rng::unit(0x9E37_79B9_7F4A_7C15u64);
        let pts: Vec<Point> = (0..200).map(|_| Point::new(5.0 * f(), 5.0 * f())).collect();
        let mut grid = Grid::new(1.0);
        for (i, p) in pts.iter().enumerate() {
            grid.insert(*p, i);
        }
        for q in &pts {
            let (cx, cy) = grid.key(*q);
            let mut want = Vec::new();
            for dx in -1..=1 {
                for dy in -1..=1 {
                    want.extend((0..pts.len()).filter(|&i| grid.key(pts[i]) == (cx + dx, cy + dy)));
                }
            }
            let mut got = Vec::new();
            grid.around(*q, &mut got);
            assert_eq!(got, want);
        }
        let mut ends = SameEnds::default();
        for id in 0..50 {
            ends.push((id % 3, 7), id);
        }
        for k in 0..3 {
            let want: Vec<usize> = (0..50).filter(|id| id % 3 == k).collect();
            assert_eq!(ends.each((k, 7)).collect::<Vec<_>>(), want);
        }
        assert_eq!(ends.each((9, 9)).count(), 0);
    }

    #[test]
    fn points_within_tolerance_are_one_vertex() {
        let s = [
            (Segment::line(Point::new(0.0, 0.0), Point::new(5.0, 0.0)), 0),
            (
                Segment::line(Point::new(5.0005, 0.0), Point::new(5.0, 5.0)),
                0,
            ),
        ];
        assert_eq!(build(&s, 1e-3).vertices.len(), 3);
    }
}
