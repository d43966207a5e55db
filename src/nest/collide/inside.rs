//! Points inside a collision polygon, strictly (more than `eps` from its
//! boundary): the second half of the overlap test of [`super`], once no
//! edges cross.

use super::bands::Bands;
use super::cells::Cells;
use super::few::Few;
use super::runs::{edge, far_from_box, RUNS_FROM};
use super::{misses, seg_dist2, Shape};
use crate::geom::{fmax, fmin, BBox, Point};
use crate::nest::shape::Polygon;

/// Past this many vertices or edges near the other shape, the searches
/// below are indexed (ESICUP's parts have 4–14 vertices: never).
const MANY: usize = 64;

/// True when `outer` holds, strictly, a point of `of`'s boundary (its
/// interior point is [`shape_holds`]'s). The boundary is cut at every vertex of `outer`
/// lying on it, so each piece is wholly inside, outside or along `outer`'s
/// boundary (no edges cross properly here), and the middle of each piece is
/// tested: vertices and edge midpoints alone miss two equal U-shapes side
/// by side on a grid, whose every vertex and midpoint lies on the other's
/// boundary (ESICUP shapes0).
pub(super) fn holds_a_point_of(outer: &Shape, of: &Shape, eps: f64) -> bool {
    if outer.poly.pts.len() <= RUNS_FROM {
        holds_a_point_of_few(outer, of, eps)
    } else if let Some(cells) = outer.cells() {
        holds_a_point_of_cells(outer, cells, of, eps)
    } else {
        holds_a_point_of_lists(outer, of, eps)
    }
}

/// [`holds_a_point_of`] for an `outer` with [`Cells`]: a piece of `of`'s
/// boundary in cells all outside `outer` is not held and one in cells all
/// inside is; the others are cut by the vertices of the cells they cross
/// and their middles tested as in [`holds_a_point_of_lists`], asking
/// `outer`'s edges where they are (its height bands, its runs) rather
/// than copying those near `of` for every pair, as those lists did.
///
/// The same answer: the lists' tests are asked of the same points, and
/// each answers as before. The parity toggles on the same edges (those
/// crossing the point's height are all in the height band, and in the
/// bands or runs asked); the distance asks the same edges (the band's, in
/// the runs not far from the point); the cuts are the same vertices (of
/// the window, within `eps` of the edge: in the cells within `eps` of it).
/// Only where the lists sought vertices by x (more than [`MANY`] in the
/// window) did they leave out a vertex beyond the edge's x range ± eps,
/// which cuts only by rounding: such a vertex is left out the same way.
pub(super) fn holds_a_point_of_cells(outer: &Shape, cells: &Cells, of: &Shape, eps: f64) -> bool {
    let (ob, fb) = (outer.bbox(), of.bbox());
    // (The cells are where `outer` was made: the points asked are taken
    // back by its move.)
    let at = outer.core_at;
    let far = [ob.min, ob.max, fb.min, fb.max]
        .iter()
        .fold(0.0f64, |m, p| fmax(fmax(m, p.x.abs()), p.y.abs()));
    let Some(reach) = cells.reach(eps, at, far) else {
        return holds_a_point_of_lists(outer, of, eps);
    };
    let (ylo, yhi) = (
        fmax(ob.min.y, fb.min.y) - eps,
        fmin(ob.max.y, fb.max.y) + eps,
    );
    let (xlo, xhi) = (fb.min.x - eps, fb.max.x + eps);
    let opts = &outer.poly.pts;
    let m = opts.len();
    let in_band = |(a, b): (Point, Point)| fmax(a.y, b.y) >= ylo && fmin(a.y, b.y) <= yhi;
    let in_window = |v: &Point| v.y >= ylo && v.y <= yhi && v.x >= xlo && v.x <= xhi;
    let band_far = |r: &BBox| r.max.y < ylo || r.min.y > yhi;
    // Whether the lists sought the vertices by x: asked only of a vertex
    // cutting beyond the edge's x range ± eps.
    let by_x = std::cell::OnceCell::new();
    let sought_by_x = || {
        *by_x.get_or_init(|| {
            let window = |r: &BBox| band_far(r) || r.max.x < xlo || r.min.x > xhi;
            let mut n = 0;
            for r in outer.runs.edges(m, window) {
                n += opts[r].iter().filter(|v| in_window(v)).count();
            }
            n > MANY
        })
    };
    let inside = |p: Point| {
        if !well_inside(ob, p, eps) {
            return false;
        }
        let mut inside = false;
        let mut toggle = |(a, b): (Point, Point)| {
            if crosses_ray(a, b, p) {
                inside = !inside;
            }
        };
        let kept = outer
            .outline
            .as_deref()
            .filter(|_| p.y >= ylo && p.y <= yhi)
            .and_then(|o| o.at(p.y, at));
        match kept {
            Some(near) => near.iter().for_each(|&i| toggle(edge(opts, i as usize))),
            // (A run whose box has every vertex above `p` or none
            // toggles nothing.)
            None => outer
                .runs
                .edges(m, |b: &BBox| b.max.y <= p.y || b.min.y > p.y)
                .flatten()
                .map(|i| edge(opts, i))
                .filter(|&e| in_band(e))
                .for_each(toggle),
        }
        inside
            && outer
                .runs
                .edges(m, |b: &BBox| band_far(b) || far_from(b, p, eps))
                .flatten()
                .map(|i| edge(opts, i))
                .all(|(a, b)| !in_band((a, b)) || seg_dist2(p, a, b) > eps * eps)
    };
    // A point in cells all outside (inside) is not (is) held; else asked.
    let holds = |p: Point| {
        let seen = cells.seen_at(p.sub(at), reach);
        !seen.all_out() && (seen.all_in() || inside(p))
    };
    let pts = &of.poly.pts;
    let n = pts.len();
    let mut cuts = Cuts {
        p: Point::default(),
        q: Point::default(),
        d: Point::default(),
        l2: 0.0,
        eps,
        ts: Few::new(),
    };
    let mut near: Few<u32, 16> = Few::new();
    // (A run of `of`'s edges off `outer`'s box, or in cells all outside
    // it, has every edge skipped below.)
    let off_box = |r: &BBox| {
        r.max.x < ob.min.x
            || r.min.x > ob.max.x
            || r.max.y < ob.min.y
            || r.min.y > ob.max.y
            || cells.box_out(r.min.sub(at), r.max.sub(at), reach)
    };
    for i in of.runs.edges(n, off_box).flatten() {
        let (p, q) = edge(pts, i);
        if misses(ob, p, q) {
            continue;
        }
        let d = q.sub(p);
        let l2 = d.dot(d);
        if l2 == 0.0 {
            continue;
        }
        near.clear();
        let seen = cells.seen(p.sub(at), q.sub(at), reach, |c| near.push(c as u32));
        if seen.all_out() {
            continue;
        }
        if seen.all_in() {
            return true;
        }
        (cuts.p, cuts.q, cuts.d, cuts.l2) = (p, q, d, l2);
        cuts.ts.clear();
        cuts.ts.push(0.0);
        cuts.ts.push(1.0);
        let (lo, hi) = (fmin(p.x, q.x) - eps, fmax(p.x, q.x) + eps);
        for &c in near.as_slice() {
            for &k in cells.vertices(c as usize) {
                let v = opts[k as usize];
                if !in_window(&v) {
                    continue;
                }
                if let Some(t) = cuts.cut(v) {
                    if (v.x >= lo && v.x <= hi) || !sought_by_x() {
                        cuts.ts.push(t);
                    }
                }
            }
        }
        if cuts
            .pieces()
            .any(|(w0, w1)| holds(p.add(d.scale((w0 + w1) / 2.0))))
        {
            return true;
        }
    }
    false
}

/// [`holds_a_point_of`] for an `outer` of any size: its edges and
/// vertices near copied into lists, a stretch per run.
pub(super) fn holds_a_point_of_lists(outer: &Shape, of: &Shape, eps: f64) -> bool {
    let ob = outer.bbox();
    // Every point tested lies on `of`'s boundary and within `outer`'s box
    // (else `inside` says no at once), so only `outer`'s edges and vertices
    // reaching the two boxes' overlap (± eps) can change an answer: they
    // are picked once here, not scanned whole for every piece. Neighbours
    // in a dense nest overlap in a sliver; this was most of the time of a
    // 200-part sheet. The answers are the same as over the whole polygon.
    let fb = of.bbox();
    let (ylo, yhi) = (
        fmax(ob.min.y, fb.min.y) - eps,
        fmin(ob.max.y, fb.max.y) + eps,
    );
    let (xlo, xhi) = (fb.min.x - eps, fb.max.x + eps);
    let opts = &outer.poly.pts;
    let m = opts.len();
    // (Runs whose box misses the band or the window hold no edge or
    // vertex of it: [`super::runs`].)
    // Each run's edges kept are a stretch of `edges` in `stretches`, with
    // the run's box, which the tests of a point below skip when it cannot
    // change their answer.
    let mut edges: Few<(Point, Point), 32> = Few::new();
    let mut stretches: Few<(BBox, usize, usize), 16> = Few::new();
    for r in outer
        .runs
        .edges(m, |r: &BBox| r.max.y < ylo || r.min.y > yhi)
    {
        let from = edges.as_slice().len();
        let b = outer.runs.box_of(r.start).unwrap_or(*ob);
        // (A run within the band: every edge of it.)
        let all = outer
            .runs
            .box_of(r.start)
            .is_some_and(|b| b.min.y >= ylo && b.max.y <= yhi);
        for i in r {
            let (a, b) = edge(opts, i);
            if all || (fmax(a.y, b.y) >= ylo && fmin(a.y, b.y) <= yhi) {
                edges.push((a, b));
            }
        }
        stretches.push((b, from, edges.as_slice().len()));
    }
    let edges = edges.as_slice();
    let stretches = stretches.as_slice();
    // The vertices too, a stretch per run with the box of those kept.
    let mut verts: Few<Point, 32> = Few::new();
    let mut vstretches: Few<(BBox, usize, usize), 16> = Few::new();
    let window = |r: &BBox| r.max.y < ylo || r.min.y > yhi || r.max.x < xlo || r.min.x > xhi;
    for r in outer.runs.edges(m, window) {
        let (from, mut bx) = (verts.as_slice().len(), BBox::EMPTY);
        for v in &opts[r] {
            if v.y >= ylo && v.y <= yhi && v.x >= xlo && v.x <= xhi {
                verts.push(*v);
                bx.add(*v);
            }
        }
        vstretches.push((bx, from, verts.as_slice().len()));
    }
    let vstretches = vstretches.as_slice();
    // Many vertices (CAD outlines, issue 44): in order of x, so each edge
    // below asks only those within its x range ± eps (the others are
    // farther than eps from it and cut nothing: the same cuts, sooner).
    let by_x = verts.as_slice().len() > MANY;
    if by_x {
        verts
            .as_mut_slice()
            .sort_unstable_by(|a, b| a.x.total_cmp(&b.x));
    }
    // And the parity test asks only the edges of the point's height band
    // (the same edges toggle it, in another order): the bands `outer`
    // keeps of all its edges, else those of the edges near.
    let kept = outer.outline.as_deref().filter(|_| edges.len() > MANY);
    let bands = (kept.is_none() && edges.len() > MANY).then(|| Bands::new(edges, ylo, yhi));
    let inside = |p: Point| {
        if !well_inside(ob, p, eps) {
            return false;
        }
        let mut inside = false;
        let mut toggle = |(a, b): (Point, Point)| {
            if crosses_ray(a, b, p) {
                inside = !inside;
            }
        };
        // (Within the band, the edges it may cross are all near ones.)
        let all = kept
            .filter(|_| p.y >= ylo && p.y <= yhi)
            .and_then(|o| o.at(p.y, outer.core_at));
        match (all, bands.as_ref().and_then(|b| b.at(p.y))) {
            (Some(near), _) => near.iter().for_each(|&i| toggle(edge(opts, i as usize))),
            (None, Some(near)) => near.iter().for_each(|&i| toggle(edges[i as usize])),
            // (A stretch whose box has every vertex above `p` or none
            // toggles nothing.)
            (None, None) => stretches
                .iter()
                .filter(|(b, ..)| b.max.y > p.y && b.min.y <= p.y)
                .for_each(|&(_, i, j)| edges[i..j].iter().for_each(|&e| toggle(e))),
        }
        inside
            && stretches
                .iter()
                .filter(|(b, ..)| !far_from(b, p, eps))
                .all(|&(_, i, j)| {
                    edges[i..j]
                        .iter()
                        .all(|&(a, b)| seg_dist2(p, a, b) > eps * eps)
                })
    };
    pieces_inside(ob, of, eps, inside, |cuts| {
        let (p, q) = (cuts.p, cuts.q);
        if by_x {
            let near = verts.as_slice();
            let (lo, hi) = (fmin(p.x, q.x) - eps, fmax(p.x, q.x) + eps);
            let from = near.partition_point(|v| v.x < lo);
            let to = from + near[from..].partition_point(|v| v.x <= hi);
            near[from..to].iter().for_each(|&v| cuts.at(v));
        } else {
            // (A stretch whose box is farther than eps from the edge's
            // holds no vertex that cuts it.)
            let eb = cuts.edge_box();
            for &(bx, i, j) in vstretches {
                if !far_from_box(&bx, &eb, eps) {
                    verts.as_slice()[i..j].iter().for_each(|&v| cuts.at(v));
                }
            }
        }
    })
}

/// [`holds_a_point_of`] when `outer` has at most [`RUNS_FROM`] vertices
/// (no runs): its edges and vertices near marked in
/// masks, not copied. The same edges and vertices as the lists of the
/// general case, which for such an `outer` are one stretch whose box is
/// `outer`'s: every point asked lies strictly within that box, so the
/// stretch is never skipped. The same answer; on ESICUP's 4–14-vertex
/// parts the lists' room and copies were a good part of the test.
pub(super) fn holds_a_point_of_few(outer: &Shape, of: &Shape, eps: f64) -> bool {
    let (ob, fb) = (outer.bbox(), of.bbox());
    let (ylo, yhi) = (
        fmax(ob.min.y, fb.min.y) - eps,
        fmin(ob.max.y, fb.max.y) + eps,
    );
    let (xlo, xhi) = (fb.min.x - eps, fb.max.x + eps);
    let opts = &outer.poly.pts;
    // (One bit an edge, in the height band; one a vertex, in the window.)
    let (mut edges, mut verts, mut vb) = (0u32, 0u32, BBox::EMPTY);
    for (i, v) in opts.iter().enumerate() {
        let (a, b) = edge(opts, i);
        if fmax(a.y, b.y) >= ylo && fmin(a.y, b.y) <= yhi {
            edges |= 1 << i;
        }
        if v.y >= ylo && v.y <= yhi && v.x >= xlo && v.x <= xhi {
            verts |= 1 << i;
            vb.add(*v);
        }
    }
    let bits = |mut m: u32| {
        std::iter::from_fn(move || {
            (m != 0).then(|| {
                let i = m.trailing_zeros() as usize;
                m &= m - 1;
                i
            })
        })
    };
    let inside = |p: Point| {
        if !well_inside(ob, p, eps) {
            return false;
        }
        let mut inside = false;
        for i in bits(edges) {
            let (a, b) = edge(opts, i);
            if crosses_ray(a, b, p) {
                inside = !inside;
            }
        }
        inside
            && bits(edges).all(|i| {
                let (a, b) = edge(opts, i);
                seg_dist2(p, a, b) > eps * eps
            })
    };
    pieces_inside(ob, of, eps, inside, |cuts| {
        if !far_from_box(&vb, &cuts.edge_box(), eps) {
            bits(verts).for_each(|i| cuts.at(opts[i]));
        }
    })
}

/// The cuts of one edge `pq` = `p + t·d` of the boundary tested (t in
/// [0, 1]): where a vertex of the outer polygon lies within `eps` of it.
struct Cuts {
    p: Point,
    q: Point,
    d: Point,
    l2: f64,
    eps: f64,
    ts: Few<f64, 16>,
}

impl Cuts {
    /// Cut at `v` when it lies within `eps` of the edge, inside it.
    #[inline(always)]
    fn at(&mut self, v: Point) {
        if let Some(t) = self.cut(v) {
            self.ts.push(t);
        }
    }
    /// Where `v` cuts the edge, if it does.
    #[inline(always)]
    fn cut(&self, v: Point) -> Option<f64> {
        let t = v.sub(self.p).dot(self.d) / self.l2;
        (t > 0.0 && t < 1.0 && {
            let w = self.p.add(self.d.scale(t)).sub(v);
            w.dot(w) <= self.eps * self.eps
        })
        .then_some(t)
    }
    /// The pieces (from, to) of the edge between its cuts, in order
    /// (empty ones left out).
    fn pieces(&mut self) -> impl Iterator<Item = (f64, f64)> + '_ {
        // (0 and 1 alone are in order: most edges meet no vertex.)
        let ts = &mut self.ts;
        if ts.as_slice().len() > 2 {
            ts.as_mut_slice().sort_by(f64::total_cmp);
        }
        ts.as_slice()
            .windows(2)
            .map(|w| (w[0], w[1]))
            .filter(|(a, b)| b - a > 0.0)
    }
    /// The edge's box.
    fn edge_box(&self) -> BBox {
        let (p, q) = (self.p, self.q);
        BBox {
            min: Point::new(fmin(p.x, q.x), fmin(p.y, q.y)),
            max: Point::new(fmax(p.x, q.x), fmax(p.y, q.y)),
        }
    }
}

/// True when `inside` holds the middle of a piece of `of`'s boundary
/// (within the outer box `ob`), its edges cut where `cut` says.
fn pieces_inside(
    ob: &BBox,
    of: &Shape,
    eps: f64,
    inside: impl Fn(Point) -> bool,
    mut cut: impl FnMut(&mut Cuts),
) -> bool {
    let pts = &of.poly.pts;
    let n = pts.len();
    let mut cuts = Cuts {
        p: Point::default(),
        q: Point::default(),
        d: Point::default(),
        l2: 0.0,
        eps,
        ts: Few::new(),
    };
    let far = |r: &BBox| {
        r.max.x < ob.min.x || r.min.x > ob.max.x || r.max.y < ob.min.y || r.min.y > ob.max.y
    };
    for i in of.runs.edges(n, far).flatten() {
        let (p, q) = edge(pts, i);
        if misses(ob, p, q) {
            continue;
        }
        let d = q.sub(p);
        let l2 = d.dot(d);
        if l2 == 0.0 {
            continue;
        }
        (cuts.p, cuts.q, cuts.d, cuts.l2) = (p, q, d, l2);
        cuts.ts.clear();
        cuts.ts.push(0.0);
        cuts.ts.push(1.0);
        cut(&mut cuts);
        if cuts
            .pieces()
            .any(|(a, b)| inside(p.add(d.scale((a + b) / 2.0))))
        {
            return true;
        }
    }
    false
}

/// True when `p` is inside `poly` and more than `eps` from its boundary.
pub fn strictly_inside(poly: &Polygon, p: Point, eps: f64) -> bool {
    let bb = &poly.bbox;
    if !well_inside(bb, p, eps) {
        return false;
    }
    let pts = &poly.pts;
    let n = pts.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = edge(pts, i);
        if crosses_ray(a, b, p) {
            inside = !inside;
        }
    }
    inside
        && (0..n).all(|i| {
            let (a, b) = edge(pts, i);
            seg_dist2(p, a, b) > eps * eps
        })
}

/// True when `p` lies more than `eps` inside the box `b`: a point of the
/// box's rim or outside it is in no polygon strictly.
#[inline(always)]
fn well_inside(b: &BBox, p: Point, eps: f64) -> bool {
    p.x > b.min.x + eps && p.x < b.max.x - eps && p.y > b.min.y + eps && p.y < b.max.y - eps
}

/// True when the edge `ab` crosses the ray from `p` towards +x: the
/// parity test's toggle, half-open in y (a vertex at `p`'s height counts
/// as below it, so a ray through a vertex is crossed once or not at all).
#[inline(always)]
fn crosses_ray(a: Point, b: Point, p: Point) -> bool {
    (a.y > p.y) != (b.y > p.y) && a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) > p.x
}

/// True when every point of the box `r` is farther than `eps` from `p`
/// by a margin (a billionth of the coordinates) far above the rounding
/// of [`seg_dist2`]: the distance of an edge in it is then surely more
/// than `eps`.
fn far_from(r: &BBox, p: Point, eps: f64) -> bool {
    let size = [r.min.x, r.min.y, r.max.x, r.max.y, p.x, p.y]
        .iter()
        .fold(1.0f64, |m, v| fmax(m, v.abs()));
    let reach = eps + size * 1e-9;
    r.min.x - p.x > reach || p.x - r.max.x > reach || r.min.y - p.y > reach || p.y - r.max.y > reach
}

/// [`strictly_inside`] of a shape's polygon, asking only the runs of
/// edges that can change the answer ([`super::runs`]): the parity only
/// those whose box spans `p`'s height (every vertex of another is above
/// `p`, or none is: no edge of it is crossed), the distance only those
/// whose box comes within `eps` of `p` with a margin far above the
/// rounding of the distance (a billionth of the coordinates), which the
/// others' edges are then surely farther than. The same answer.
pub(super) fn shape_holds(shape: &Shape, p: Point, eps: f64) -> bool {
    let bb = shape.bbox();
    if !well_inside(bb, p, eps) {
        return false;
    }
    let pts = &shape.poly.pts;
    let n = pts.len();
    let mut inside = false;
    for r in shape
        .runs
        .edges(n, |r: &BBox| r.max.y <= p.y || r.min.y > p.y)
    {
        for i in r {
            let (a, b) = edge(pts, i);
            if crosses_ray(a, b, p) {
                inside = !inside;
            }
        }
    }
    if !inside {
        return false;
    }
    for r in shape.runs.edges(n, |r: &BBox| far_from(r, p, eps)) {
        for i in r {
            let (a, b) = edge(pts, i);
            if seg_dist2(p, a, b) > eps * eps {
                continue;
            }
            return false;
        }
    }
    true
}
