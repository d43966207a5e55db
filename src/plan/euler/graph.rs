//! The edge graph of the Eulerian order (paper 003 §3): every drawn segment of
//! the selected contours becomes an edge between snapped vertices; edges that
//! two neighbouring parts share (common-line cutting) become one edge.
//!
//! Shared edges are found without comparing all pairs: a vertex that lies on
//! the inside of another segment (a T-junction, or the end of a partial
//! overlap) splits that segment there, so overlapping pieces end up between
//! the same two vertices and are merged when their midpoints coincide. This
//! handles collinear lines and co-circular arcs alike, in either direction.

use crate::fx::FxMap;

use crate::geom::{dist_to_segment, Point, Segment};

/// One edge, between vertices `u` and `v`, drawn from `u` to `v`.
#[derive(Clone, Copy, Debug)]
pub struct Edge {
    /// Geometry from `vertices[u]` to `vertices[v]`.
    pub seg: Segment,
    /// Start vertex.
    pub u: usize,
    /// End vertex.
    pub v: usize,
    /// The first contour it was drawn in.
    pub contour: usize,
    /// Another contour that drew it too (a shared edge).
    pub also: Option<usize>,
}

/// Vertices and merged edges.
#[derive(Clone, Debug, Default)]
pub struct Graph {
    /// Snapped vertex positions.
    pub vertices: Vec<Point>,
    /// Merged edges.
    pub edges: Vec<Edge>,
    /// Edge ids at each vertex.
    pub adj: Vec<Vec<usize>>,
    /// Edges dropped because an equal edge was already there (shared edges).
    pub merged: usize,
}

impl Graph {
    /// Degree of vertex `v`.
    pub fn degree(&self, v: usize) -> usize {
        self.adj.get(v).map_or(0, Vec::len)
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
struct Grid {
    cell: f64,
    cells: FxMap<(i64, i64), Vec<usize>>,
}

impl Grid {
    fn new(cell: f64) -> Self {
        Grid {
            cell,
            cells: FxMap::default(),
        }
    }
    fn key(&self, p: Point) -> (i64, i64) {
        // `as` saturates, so a huge coordinate lands in an edge cell, never panics.
        (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        )
    }
    fn insert(&mut self, p: Point, id: usize) {
        let k = self.key(p);
        self.cells.entry(k).or_default().push(id);
    }
    /// Ids in the cells around `p` (3×3 block).
    fn around(&self, p: Point, out: &mut Vec<usize>) {
        let (x, y) = self.key(p);
        for dx in -1..=1 {
            for dy in -1..=1 {
                if let Some(ids) = self
                    .cells
                    .get(&(x.saturating_add(dx), y.saturating_add(dy)))
                {
                    out.extend_from_slice(ids);
                }
            }
        }
    }
    /// Ids in the cells along a segment (sampled every half cell, each with
    /// its 3×3 block, so everything within one cell of the path is seen).
    fn along(&self, s: &Segment) -> Vec<usize> {
        let n = (s.length() / (0.5 * self.cell)).ceil();
        // At most ~10⁵ samples: a segment longer than that many cells is
        // the drawing's extent over again and its vertices are few.
        let n = if n.is_finite() {
            n.clamp(1.0, 1e5) as usize
        } else {
            1
        };
        let mut out = Vec::new();
        let mut last = None;
        for k in 0..=n {
            let p = s.point_at(k as f64 / n as f64);
            let key = self.key(p);
            if last != Some(key) {
                last = Some(key);
                self.around(p, &mut out);
            }
        }
        crate::sort::sort_indices(&mut out);
        out.dedup();
        out
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
        adj: vec![Vec::new(); vertices.len()],
        vertices,
        ..Graph::default()
    };
    let mut by_ends: FxMap<(usize, usize), Vec<usize>> = FxMap::default();
    for (&(seg, contour), &(u, v)) in segs.iter().zip(&ends) {
        let candidates = near.along(&seg);
        let mut cuts: Vec<(f64, usize)> = candidates
            .into_iter()
            .filter(|&w| w != u && w != v)
            .filter_map(|w| {
                let p = g.vertices[w];
                (dist_to_segment(p, &seg) <= tol).then(|| (param(&seg, p), w))
            })
            .filter(|(t, _)| *t > 0.0 && *t < 1.0)
            .collect();
        crate::sort::sort_by(&mut cuts, |a, b| a.0.total_cmp(&b.0));
        cuts.dedup_by_key(|c| c.1);
        let mut from = (0.0, u);
        for to in cuts.into_iter().chain([(1.0, v)]) {
            add_edge(&mut g, &mut by_ends, &seg, from, to, contour, tol);
            from = to;
        }
    }
    g
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
    by_ends: &mut FxMap<(usize, usize), Vec<usize>>,
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
    let same = by_ends.get(&key).and_then(|ids| {
        ids.iter()
            .copied()
            .find(|&e| g.edges[e].seg.point_at(0.5).dist(mid) <= tol)
    });
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
    g.adj[u].push(id);
    g.adj[v].push(id);
    by_ends.entry(key).or_default().push(id);
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
