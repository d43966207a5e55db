//! Do two collision polygons overlap? Boxes first, then crossing edges,
//! then points of one strictly inside the other.
//!
//! Touching is allowed (two parts grown by half the spacing may touch: their
//! outlines are then exactly the spacing apart), so every test is strict by
//! `eps` mm: edges cross only when each one's ends are more than `eps` on
//! either side of the other, and a point is inside only when it is more than
//! `eps` from the boundary. Without crossing edges, two simple polygons
//! overlap only if one holds a point of the other: a vertex, an edge
//! midpoint (edges lying along each other, where no vertex is strictly
//! inside) or the interior point each polygon keeps (one polygon exactly on
//! top of the other).
//!
//! Why our own and not jagua-rs's collision detection engine (the crate
//! issue 16 names; version 1.1, features spp/bpp, builds natively and for
//! wasm32): measured side by side on the same placed polygons and the same
//! queries (a scratch program outside the repo, 2026-11-23, this machine,
//! 10⁵ queries each), this test answered 2.4–5.5× faster on the 7 ESICUP
//! instances (4–9 vertices a part; 0.08–0.14 µs against 0.27–0.73 µs a
//! query for copies moved 2 % from their place) and 11× faster on corpus
//! plates with arcs (48 vertices: 0.11 against 1.17 µs), answering the
//! same in all but 1–3 of 10⁵ touching cases: jagua-rs works in f32
//! (Point(f32, f32)), which at sheet sizes of metres is ~10⁻³ mm, where our
//! spacing guarantee is held to 10⁻⁶ of the tolerance.
//! Made again for the separation (2026-12-02, jagua-rs 1.1.0 with sparrow's
//! defaults: quadtree depth 4, threshold 16; a scratch program outside the
//! repo, both at this crate's release profile, the same f64 polygons (f32
//! for jagua-rs), 9 rounds of ~10⁵ queries alternating, medians): feasible
//! nests of the 7 ESICUP and 6 real-part instances at 20 000 evaluations,
//! each copy moved to 40 samples over the strip and 30 near its place, as
//! the separator's sampler draws them. "Which copies does it overlap"
//! (boxes, diagonals, exact test): jagua-rs took 2.06–10.3× as long, median
//! 2.83× (ESICUP 2.59×; keyboard plates, 336 vertices a copy: 5.3 against
//! 45.4 µs); "does it overlap anything": 1.56–12.7×, median 2.36×; a move
//! (its hazard taken out and put back in the quadtree) 6.3 µs against our
//! 0.06. Of 118 714 overlapping pairs 1 229 differ, every one jagua-rs
//! saying overlap where two copies touch within `eps` (f32, and touching
//! collides there): it would refuse the exact contacts the separator's
//! snap makes. Its quadtree would gain over our box loop with hundreds of
//! copies on one sheet (not measured: the instances have 12–120).

mod bands;
mod cells;
mod core;
mod few;
mod inside;
mod runs;

use std::sync::Arc;

use super::shape::Polygon;
use crate::geom::{fmax, fmin, orient, Affine, BBox, Point};
pub use inside::strictly_inside;
use inside::{holds_a_point_of, shape_holds};
use runs::{edge, Runs, RUNS_FROM};

/// A placed collision polygon with a point well inside it.
#[derive(Clone, Debug)]
pub struct Shape {
    /// The polygon.
    pub poly: Polygon,
    /// A point inside, away from the boundary.
    pub inner: Point,
    /// Circles inside it (many-vertex shapes made [`Shape::with_core`]),
    /// where they lie: `core_at` is how far the shape moved since it was
    /// made (for its `outline` and `cells` too).
    core: Option<Arc<core::Core>>,
    core_at: Point,
    /// Boxes of runs of its edges ([`runs`]).
    runs: Runs,
    /// Its edges bucketed by height, where it was made ([`bands`]).
    outline: Option<Arc<bands::Outline>>,
    /// Its box in cells marked inside, outside or near, where it was made
    /// ([`cells`]), made on first use.
    cells: Option<Arc<cells::Lazy>>,
    /// Its box along the diagonals ([`Diagonals`]).
    diag: Diagonals,
    /// The farthest vertex from its box's centre: the disc round it.
    round: f64,
}

/// The least and greatest `x + y` and `x − y` of a polygon's vertices: with
/// the box, the octagon round it. Two round parts whose boxes meet at a
/// corner are mostly apart along a diagonal, and the exact test of a pair
/// that is clear walks every edge near ([`overlaps`]): on plates with
/// bores and the discs beside them that was most of a separation's time
/// (perf, issue 44).
#[derive(Clone, Copy, Debug)]
struct Diagonals {
    sum: (f64, f64),
    diff: (f64, f64),
}

impl Diagonals {
    fn of(pts: &[Point]) -> Diagonals {
        let mut d = Diagonals {
            sum: (f64::INFINITY, f64::NEG_INFINITY),
            diff: (f64::INFINITY, f64::NEG_INFINITY),
        };
        for p in pts {
            let (s, t) = (p.x + p.y, p.x - p.y);
            d.sum = (fmin(d.sum.0, s), fmax(d.sum.1, s));
            d.diff = (fmin(d.diff.0, t), fmax(d.diff.1, t));
        }
        d
    }
    /// Moved by `t` (the vertices moved are rounded otherwise: the test
    /// below leaves a margin for it).
    fn moved(&self, t: Point) -> Diagonals {
        let (s, d) = (t.x + t.y, t.x - t.y);
        Diagonals {
            sum: (self.sum.0 + s, self.sum.1 + s),
            diff: (self.diff.0 + d, self.diff.1 + d),
        }
    }
}

impl Shape {
    /// The shape of a polygon (its interior point found once).
    pub fn new(poly: Polygon) -> Shape {
        let inner = interior_point(&poly);
        let runs = Runs::of(&poly.pts);
        let diag = Diagonals::of(&poly.pts);
        let round = round(&poly);
        let outline = bands::Outline::of(&poly.pts).map(Arc::new);
        let cells = made_cells(&poly);
        Shape {
            poly,
            inner,
            core: None,
            core_at: Point::default(),
            runs,
            outline,
            cells,
            diag,
            round,
        }
    }
    /// [`Shape::new`] with circles inside it when it has many vertices
    /// ([`core`]): the placer's parts, tested against each other at
    /// thousands of positions, most of them overlapping.
    pub fn with_core(poly: Polygon) -> Shape {
        let core = core::Core::of(&poly);
        Shape {
            core,
            ..Shape::new(poly)
        }
    }
    /// Moved by `t`.
    pub fn moved(&self, t: Point) -> Shape {
        Shape {
            poly: self.poly.moved(t),
            inner: self.inner.add(t),
            core: self.core.clone(),
            core_at: self.core_at.add(t),
            runs: self.runs.moved(t),
            outline: self.outline.clone(),
            cells: self.cells.clone(),
            diag: self.diag.moved(t),
            round: self.round,
        }
    }
    /// Becomes `base` moved by `t` (the same shape as `base.moved(t)`), in
    /// its own room: the placer tries thousands of positions a copy, and
    /// their allocation was a tenth of the time (perf, issue 44).
    pub fn move_from(&mut self, base: &Shape, t: Point) {
        self.poly.pts.clear();
        self.poly.pts.extend(base.poly.pts.iter().map(|p| p.add(t)));
        self.poly.bbox = BBox {
            min: base.poly.bbox.min.add(t),
            max: base.poly.bbox.max.add(t),
        };
        self.inner = base.inner.add(t);
        self.core.clone_from(&base.core);
        self.core_at = base.core_at.add(t);
        self.runs.move_from(&base.runs, t);
        self.outline.clone_from(&base.outline);
        self.cells.clone_from(&base.cells);
        self.diag = base.diag.moved(t);
        self.round = base.round;
    }
    /// Turned by `deg` degrees about the origin (counter-clockwise).
    pub fn turned(&self, deg: f64) -> Shape {
        let poly = self.poly.placed(deg, false, Point::default());
        let runs = Runs::of(&poly.pts);
        let diag = Diagonals::of(&poly.pts);
        let round = round(&poly);
        let outline = bands::Outline::of(&poly.pts).map(Arc::new);
        Shape {
            poly,
            inner: Affine::rotate_deg(deg).apply(self.inner),
            core: None,
            core_at: Point::default(),
            runs,
            outline,
            // No cells (nor core): a turn is tried a few times, and cells
            // made for every one cost more than they saved (free turns,
            // brackets and plates, 4 000 evaluations: CPU 1.34 x; made
            // on first use, 0.89 x and 1.08 x of none at 100 and 3 000, one
            // pair each); the lists answer for it, the same.
            cells: None,
            diag,
            round,
        }
    }
    /// Its box.
    pub fn bbox(&self) -> &BBox {
        &self.poly.bbox
    }
    /// Its cells, made now if not yet ([`cells::Lazy`]).
    fn cells(&self) -> Option<&cells::Cells> {
        self.cells.as_deref().and_then(cells::Lazy::get)
    }
}

/// The cells of a polygon of more than [`cells::CELLS_FROM`] vertices,
/// to be made on first use ([`cells`]: below, the lists of its edges
/// near a neighbour answer sooner).
fn made_cells(p: &Polygon) -> Option<Arc<cells::Lazy>> {
    (p.pts.len() > cells::CELLS_FROM).then(|| Arc::new(cells::Lazy::of(&p.pts)))
}

/// The distance from the centre of `p`'s box to its farthest vertex.
fn round(p: &Polygon) -> f64 {
    let c = p.bbox.centre();
    p.pts.iter().map(|q| q.dist(c)).fold(0.0, f64::max)
}

/// The middle of the widest stretch of a horizontal line through the
/// polygon, at a height halfway between two consecutive vertex heights (so
/// the line meets no vertex and runs along no edge: the middle of a stretch
/// is strictly inside).
fn interior_point(p: &Polygon) -> Point {
    let n = p.pts.len();
    let mut ys: Vec<f64> = p.pts.iter().map(|q| q.y).collect();
    ys.sort_by(f64::total_cmp);
    // Heights equal but for rounding (a turned copy: 5.999999999999999
    // and 6.000000000000001) are one height; else the line halfway
    // between them runs along an edge and its middle is on the boundary.
    let merge = (p.bbox.max.y - p.bbox.min.y) * 1e-6;
    ys.dedup_by(|b, a| *b - *a <= merge);
    let mut best = (0.0, p.pts[0]);
    for y in ys.windows(2).map(|w| (w[0] + w[1]) / 2.0) {
        let mut xs: Vec<f64> = (0..n)
            .filter_map(|i| {
                let (a, b) = (p.pts[i], p.pts[(i + 1) % n]);
                ((a.y > y) != (b.y > y)).then(|| a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y))
            })
            .collect();
        xs.sort_by(f64::total_cmp);
        for w in xs.chunks_exact(2) {
            if w[1] - w[0] > best.0 {
                best = (w[1] - w[0], Point::new((w[0] + w[1]) / 2.0, y));
            }
        }
    }
    best.1
}

/// True when the interiors of `a` and `b` overlap by more than `eps` mm.
pub fn overlaps(a: &Shape, b: &Shape, eps: f64) -> bool {
    boxes_overlap(a.bbox(), b.bbox(), eps) && overlaps_near(a, b, eps)
}

/// [`overlaps`] of two shapes whose boxes overlap ([`boxes_overlap`]
/// asked by the caller, who counts what the exact test costs).
pub fn overlaps_near(a: &Shape, b: &Shape, eps: f64) -> bool {
    !diagonals_apart(a, b, eps) && overlaps_walked(a, b, eps)
}

/// [`overlaps`] past the boxes and the diagonals (both asked by the
/// caller): the cores, then the edges walked.
pub fn overlaps_walked(a: &Shape, b: &Shape, eps: f64) -> bool {
    if let (Some(ca), Some(cb)) = (&a.core, &b.core) {
        if core::cores_meet(ca, a.core_at, cb, b.core_at, eps) {
            return true;
        }
    }
    // Each one's interior point inside the other first: a copy put well
    // into another (the placer's candidates, mostly) is answered before
    // the edges are walked. The same tests as before, in another order.
    shape_holds(a, b.inner, eps)
        || edges_cross(a, b, eps)
        || shape_holds(b, a.inner, eps)
        || holds_a_point_of(b, a, eps)
        || holds_a_point_of(a, b, eps)
}

/// True when `s` lies inside `room` (touching its boundary allowed, by
/// `eps` mm). With no edges crossing properly, `s` is inside, outside or
/// around `room`: around when a point of `room`'s boundary is strictly
/// inside `s`, outside when `s`'s interior point is not inside `room`.
pub fn within(room: &Shape, s: &Shape, eps: f64) -> bool {
    let (r, b) = (room.bbox(), s.bbox());
    if b.min.x < r.min.x - eps
        || b.min.y < r.min.y - eps
        || b.max.x > r.max.x + eps
        || b.max.y > r.max.y + eps
    {
        return false;
    }
    // The disc round `s` inside a circle of the room's core: inside, and
    // the exact test would walk every edge of both to say so (a disc in a
    // round bore: most of a decode of plates with bores, perf, issue 44).
    if let Some(core) = &room.core {
        if core::holds_disc(core, room.core_at, b.centre(), s.round, eps) {
            return true;
        }
    }
    // And a circle of `s`'s core half out of the disc round the room: out
    // (a disc across a bore's rim, the placer's most frequent "no" there).
    if let Some(core) = &s.core {
        if core::sticks_out(core, s.core_at, r.centre(), room.round, eps) {
            return false;
        }
    }
    within_walked(room, s, eps)
}

/// [`within`] past the boxes and the core: the edges walked.
fn within_walked(room: &Shape, s: &Shape, eps: f64) -> bool {
    shape_holds(room, s.inner, 0.0) && !edges_cross(room, s, eps) && !holds_a_point_of(s, room, eps)
}

/// True when an edge of `a` and an edge of `b` cross properly (each one's
/// ends more than `eps` mm on either side of the other).
fn edges_cross(a: &Shape, b: &Shape, eps: f64) -> bool {
    // A proper crossing lies in both boxes: only the edges of each that
    // reach into the boxes' overlap can cross. Filtering `b`'s edges once
    // (not once per edge of `a`) made placing many-vertex copies on a full
    // sheet several times faster; the answer is the same.
    if a.poly.pts.len() <= RUNS_FROM && b.poly.pts.len() <= RUNS_FROM {
        edges_cross_few(a, b, eps)
    } else {
        edges_cross_lists(a, b, eps)
    }
}

/// [`edges_cross`] of polygons of any size: the edges near copied into
/// lists, a stretch per run.
fn edges_cross_lists(a: &Shape, b: &Shape, eps: f64) -> bool {
    let w = window(a.bbox(), b.bbox());
    let (x0, y0, x1, y1) = (w.min.x, w.min.y, w.max.x, w.max.y);
    let outside = |p: Point, q: Point| misses(&w, p, q);
    // A run whose box is outside holds only edges outside, one whose box
    // is within only edges not outside ([`runs`]).
    let far = |r: &BBox| r.max.x < x0 || r.min.x > x1 || r.max.y < y0 || r.min.y > y1;
    let within = |r: &BBox| r.min.x >= x0 && r.max.x <= x1 && r.min.y >= y0 && r.max.y <= y1;
    let (pa, pb) = (&a.poly.pts, &b.poly.pts);
    let (na, nb) = (pa.len(), pb.len());
    // `b`'s edges near, a stretch of them per run with a box of their
    // ends: an edge of `a` is asked only against the stretches whose box
    // meets its own (`cross` says no at once to the others' edges).
    let mut near_b: few::Few<(Point, Point), 32> = few::Few::new();
    let mut stretches: few::Few<(BBox, usize, usize), 16> = few::Few::new();
    for r in b.runs.edges(nb, far) {
        let from = near_b.as_slice().len();
        match b.runs.box_of(r.start).filter(within) {
            Some(rb) => {
                r.for_each(|j| near_b.push(edge(pb, j)));
                stretches.push((rb, from, near_b.as_slice().len()));
            }
            None => {
                let mut bx = BBox::EMPTY;
                for j in r {
                    let (p, q) = edge(pb, j);
                    if !outside(p, q) {
                        near_b.push((p, q));
                        bx.add(p);
                        bx.add(q);
                    }
                }
                let to = near_b.as_slice().len();
                if to > from {
                    stretches.push((bx, from, to));
                }
            }
        }
    }
    let (near_b, stretches) = (near_b.as_slice(), stretches.as_slice());
    if near_b.is_empty() {
        return false;
    }
    for r in a.runs.edges(na, far) {
        let all = a.runs.box_of(r.start).is_some_and(|rb| within(&rb));
        for i in r {
            let (a1, a2) = edge(pa, i);
            if !all && outside(a1, a2) {
                continue;
            }
            let (ax0, ax1) = (fmin(a1.x, a2.x), fmax(a1.x, a2.x));
            let (ay0, ay1) = (fmin(a1.y, a2.y), fmax(a1.y, a2.y));
            for &(bx, from, to) in stretches {
                if bx.max.x <= ax0 || bx.min.x >= ax1 || bx.max.y <= ay0 || bx.min.y >= ay1 {
                    continue;
                }
                for &f in &near_b[from..to] {
                    if cross((a1, a2), f, eps) {
                        return true;
                    }
                }
            }
        }
    }
    false
}

/// [`edges_cross`] of two polygons of at most [`RUNS_FROM`] vertices (no
/// runs): `b`'s edges near marked in a mask, not copied. Every filter here and there is
/// implied by [`cross`]'s own test of the two edges' boxes (an edge
/// outside the boxes' overlap misses every box of the other's edges), so
/// both say whether some pair crosses: the same answer.
fn edges_cross_few(a: &Shape, b: &Shape, eps: f64) -> bool {
    let w = window(a.bbox(), b.bbox());
    let outside = |p: Point, q: Point| misses(&w, p, q);
    let (pa, pb) = (&a.poly.pts, &b.poly.pts);
    // (One bit an edge.)
    let mut near = 0u32;
    let mut bx = BBox::EMPTY;
    for j in 0..pb.len() {
        let (p, q) = edge(pb, j);
        if !outside(p, q) {
            near |= 1 << j;
            bx.add(p);
            bx.add(q);
        }
    }
    if near == 0 {
        return false;
    }
    for i in 0..pa.len() {
        let (a1, a2) = edge(pa, i);
        if outside(a1, a2)
            || bx.max.x <= fmin(a1.x, a2.x)
            || bx.min.x >= fmax(a1.x, a2.x)
            || bx.max.y <= fmin(a1.y, a2.y)
            || bx.min.y >= fmax(a1.y, a2.y)
        {
            continue;
        }
        let mut m = near;
        while m != 0 {
            let j = m.trailing_zeros() as usize;
            m &= m - 1;
            if cross((a1, a2), edge(pb, j), eps) {
                return true;
            }
        }
    }
    false
}

/// The overlap of two boxes: a proper crossing of an edge of each shape
/// lies in it ([`edges_cross`]).
fn window(a: &BBox, b: &BBox) -> BBox {
    BBox {
        min: Point::new(fmax(a.min.x, b.min.x), fmax(a.min.y, b.min.y)),
        max: Point::new(fmin(a.max.x, b.max.x), fmin(a.max.y, b.max.y)),
    }
}

/// True when the edge `pq` lies wholly outside the window `w`. Strict: an
/// edge along its side (a vertical edge at b's leftmost x) can still be
/// crossed properly.
#[inline(always)]
fn misses(w: &BBox, p: Point, q: Point) -> bool {
    fmax(p.x, q.x) < w.min.x
        || fmin(p.x, q.x) > w.max.x
        || fmax(p.y, q.y) < w.min.y
        || fmin(p.y, q.y) > w.max.y
}

/// True when edges `a1a2` and `b1b2` cross properly: each one's ends more
/// than `eps` mm on either side of the other (pairs whose boxes do not
/// overlap strictly are answered at once).
#[inline(always)]
fn cross((a1, a2): (Point, Point), (b1, b2): (Point, Point), eps: f64) -> bool {
    let (ax0, ax1) = (fmin(a1.x, a2.x), fmax(a1.x, a2.x));
    let (ay0, ay1) = (fmin(a1.y, a2.y), fmax(a1.y, a2.y));
    if fmax(b1.x, b2.x) <= ax0
        || fmin(b1.x, b2.x) >= ax1
        || fmax(b1.y, b2.y) <= ay0
        || fmin(b1.y, b2.y) >= ay1
    {
        return false;
    }
    let (d1, d2) = (orient(a1, a2, b1), orient(a1, a2, b2));
    let ea = eps * len(a1, a2);
    if !((d1 > ea && d2 < -ea) || (d1 < -ea && d2 > ea)) {
        return false;
    }
    let (d3, d4) = (orient(b1, b2, a1), orient(b1, b2, a2));
    let eb = eps * len(b1, b2);
    (d3 > eb && d4 < -eb) || (d3 < -eb && d4 > eb)
}

/// Squared distance from `p` to the segment `ab`.
pub(super) fn seg_dist2(p: Point, a: Point, b: Point) -> f64 {
    let d = b.sub(a);
    let l2 = d.dot(d);
    let t = if l2 > 0.0 {
        (p.sub(a).dot(d) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = p.sub(a.add(d.scale(t)));
    q.dot(q)
}

/// Length of `ab` (sqrt, not hypot: this is the inner loop, and the
/// coordinates are far from overflow).
fn len(a: Point, b: Point) -> f64 {
    let d = b.sub(a);
    d.dot(d).sqrt()
}

/// True when `a` and `b` lie apart along a diagonal, by more than `eps`
/// (√2·eps in `x ± y`): a line parts them, so they do not overlap, and
/// the exact test would walk their edges to say so. The margin also
/// covers the rounding of vertices moved (10⁻⁹ of the coordinates, where
/// a move rounds by 10⁻¹⁶ of them): only ever "apart" where the exact
/// test says clear.
pub fn diagonals_apart(a: &Shape, b: &Shape, eps: f64) -> bool {
    let (p, q) = (&a.diag, &b.diag);
    let size = [p.sum, p.diff, q.sum, q.diff]
        .iter()
        .fold(0.0f64, |m, &(lo, hi)| fmax(fmax(m, lo.abs()), hi.abs()));
    let g = 2.0 * eps + 1e-9 * size;
    p.sum.1 < q.sum.0 - g
        || q.sum.1 < p.sum.0 - g
        || p.diff.1 < q.diff.0 - g
        || q.diff.1 < p.diff.0 - g
}

/// True when the boxes overlap by more than `eps` both ways.
pub fn boxes_overlap(a: &BBox, b: &BBox, eps: f64) -> bool {
    a.min.x < b.max.x - eps
        && b.min.x < a.max.x - eps
        && a.min.y < b.max.y - eps
        && b.min.y < a.max.y - eps
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Shape {
        Shape::new(Polygon::new(vec![
            Point::new(x0, y0),
            Point::new(x1, y0),
            Point::new(x1, y1),
            Point::new(x0, y1),
        ]))
    }

    /// A polygon of `n` vertices round `c`, radius `r`, every third
    /// vertex pulled in by `dent` (0: a disc).
    fn ring(n: usize, r: f64, c: Point, dent: f64) -> Polygon {
        Polygon::new(
            (0..n)
                .map(|k| {
                    let a = k as f64 / n as f64 * std::f64::consts::TAU;
                    let rr = if k % 3 == 0 { r * (1.0 - dent) } else { r };
                    Point::new(c.x + rr * a.cos(), c.y + rr * a.sin())
                })
                .collect(),
        )
    }

    #[test]
    fn discs_whose_boxes_meet_at_a_corner_are_apart_along_a_diagonal() {
        let a = Shape::new(ring(48, 10.0, Point::new(0.0, 0.0), 0.0));
        let b = Shape::new(ring(48, 10.0, Point::default(), 0.0));
        // Boxes overlapping by 5 mm both ways, the discs 1.2 mm apart.
        let far = b.moved(Point::new(15.0, 15.0));
        assert!(boxes_overlap(a.bbox(), far.bbox(), 1e-9));
        assert!(diagonals_apart(&a, &far, 1e-9) && !overlaps(&a, &far, 1e-9));
        // 13.5 mm along each axis: 19.1 mm apart, overlapping.
        let near = b.moved(Point::new(13.5, 13.5));
        assert!(!diagonals_apart(&a, &near, 1e-9) && overlaps(&a, &near, 1e-9));
        // Along an axis the boxes part them already; touching is no overlap.
        let side = b.moved(Point::new(20.0, 0.0));
        assert!(!overlaps(&a, &side, 1e-9));
    }

    /// Random dented rings moved near each other: "apart along a
    /// diagonal" only ever where the edges walked say clear, and "a disc
    /// inside the room's core" only where they say inside; both answer
    /// a good share of the cases (else the test proves nothing).
    #[test]
    fn the_quick_answers_agree_with_the_edges_walked() {
        let mut rng = crate::test_rng::unit(7);
        let (mut apart, mut clear, mut held, mut inside) = (0, 0, 0, 0);
        let (mut sticking, mut not_in) = (0, 0);
        for _ in 0..4000 {
            let c = Point::new(1000.0 * rng(), 500.0 * rng());
            let a = Shape::with_core(ring(25 + (rng() * 60.0) as usize, 30.0, c, 0.3 * rng()));
            let rb = 2.0 + 40.0 * rng();
            let b0 = Shape::new(ring(
                5 + (rng() * 60.0) as usize,
                rb,
                Point::default(),
                0.3 * rng(),
            ));
            let t = c.add(Point::new(
                (2.0 * rng() - 1.0) * (32.0 + rb),
                (2.0 * rng() - 1.0) * (32.0 + rb),
            ));
            let b = b0.moved(t);
            for eps in [1e-9, 1e-3] {
                let walked = overlaps_walked(&a, &b, eps);
                if boxes_overlap(a.bbox(), b.bbox(), eps) && diagonals_apart(&a, &b, eps) {
                    assert!(!walked, "apart at {t:?}");
                    apart += 1;
                }
                clear += !walked as usize;
                let core = a.core.as_ref().unwrap();
                let inner = within_walked(&a, &b, eps);
                if core::holds_disc(core, a.core_at, b.bbox().centre(), b.round, eps) {
                    assert!(inner, "held at {t:?}");
                    held += 1;
                }
                inside += inner as usize;
                // The other way: b the room, a's core out of b's disc.
                let out = within_walked(&b, &a, eps);
                if core::sticks_out(core, a.core_at, b.bbox().centre(), b.round, eps) {
                    assert!(!out, "out at {t:?}");
                    sticking += 1;
                }
                not_in += !out as usize;
            }
        }
        assert!(apart > clear / 5, "{apart} apart of {clear} clear");
        assert!(held > inside / 5, "{held} held of {inside} inside");
        assert!(
            sticking > not_in / 5,
            "{sticking} out of {not_in} not within"
        );
    }

    /// A polygon of 4–16 vertices: a star with random radii (turned
    /// copies' rounding), or a staircase on a 1 mm grid (ESICUP's parts,
    /// whose copies touch along whole edges and at vertices).
    fn few_vertices(rng: &mut impl FnMut() -> f64) -> Polygon {
        if rng() < 0.5 {
            let n = 4 + (rng() * 13.0) as usize;
            ring(n, 3.0 + 10.0 * rng(), Point::default(), 0.4 * rng())
        } else {
            // Up the right in steps, back along the top and the left.
            let steps = 1 + (rng() * 6.0) as usize;
            let mut pts = vec![Point::new(0.0, 0.0)];
            let (mut x, mut y) = (0.0, 0.0);
            for _ in 0..steps {
                x += 1.0 + (rng() * 4.0).floor();
                pts.push(Point::new(x, y));
                y += 1.0 + (rng() * 4.0).floor();
                pts.push(Point::new(x, y));
            }
            pts.push(Point::new(0.0, y));
            Polygon::new(pts)
        }
    }

    /// The few-vertex paths of the exact test (masks) answer as the lists
    /// of the general one, on pairs moved vertex onto vertex (the placer's
    /// candidates, mostly touching), by whole millimetres (copies along
    /// each other's edges) or anywhere near.
    #[test]
    fn the_few_vertex_paths_answer_as_the_lists() {
        let mut rng = crate::test_rng::unit(44);
        let (mut crossing, mut holding, mut clear) = (0, 0, 0);
        for case in 0..20_000 {
            let a = Shape::new(few_vertices(&mut rng).moved(Point::new(500.0, 300.0)));
            let b0 = Shape::new(few_vertices(&mut rng));
            let (na, nb) = (a.poly.pts.len(), b0.poly.pts.len());
            let t = match case % 3 {
                0 => a.poly.pts[(rng() * na as f64) as usize]
                    .sub(b0.poly.pts[(rng() * nb as f64) as usize]),
                1 => Point::new(
                    500.0 + (rng() * 24.0 - 12.0).round(),
                    300.0 + (rng() * 24.0 - 12.0).round(),
                ),
                _ => Point::new(500.0 + 30.0 * (rng() - 0.5), 300.0 + 30.0 * (rng() - 0.5)),
            };
            let b = b0.moved(t);
            for eps in [0.0, 1e-9, 1e-3, 0.5] {
                let cross = edges_cross_few(&a, &b, eps);
                assert_eq!(
                    cross,
                    edges_cross_lists(&a, &b, eps),
                    "case {case} eps {eps}"
                );
                assert_eq!(
                    edges_cross_few(&b, &a, eps),
                    edges_cross_lists(&b, &a, eps),
                    "case {case} eps {eps}"
                );
                for (o, f) in [(&a, &b), (&b, &a)] {
                    let held = inside::holds_a_point_of_few(o, f, eps);
                    let listed = inside::holds_a_point_of_lists(o, f, eps);
                    assert_eq!(held, listed, "case {case} eps {eps}");
                    holding += (held && !cross) as usize;
                }
                crossing += cross as usize;
                clear += !overlaps(&a, &b, eps) as usize;
            }
        }
        // Each answer came often.
        assert!(
            crossing > 20_000 && holding > 4000 && clear > 15_000,
            "{crossing} {holding} {clear}"
        );
    }

    #[test]
    fn touching_is_allowed_overlapping_is_not() {
        let a = rect(0.0, 0.0, 10.0, 10.0);
        assert!(!overlaps(&a, &rect(10.0, 0.0, 20.0, 10.0), 1e-9));
        assert!(!overlaps(&a, &rect(10.0, 10.0, 20.0, 20.0), 1e-9));
        assert!(overlaps(&a, &rect(9.0, 0.0, 20.0, 10.0), 1e-9));
        // Same place, edges along each other, one inside the other.
        assert!(overlaps(&a, &rect(0.0, 0.0, 10.0, 10.0), 1e-9));
        assert!(overlaps(&a, &rect(5.0, 0.0, 15.0, 10.0), 1e-9));
        assert!(overlaps(&a, &rect(2.0, 2.0, 3.0, 3.0), 1e-9));
        assert!(overlaps(&rect(2.0, 2.0, 3.0, 3.0), &a, 1e-9));
        // A cross: no vertex inside the other, only crossing edges.
        assert!(overlaps(&rect(-5.0, 4.0, 15.0, 6.0), &a, 1e-9));
    }

    /// A 20 × 20 L with its 10 × 10 notch at the upper right.
    fn l_shape() -> Shape {
        Shape::new(Polygon::new(vec![
            Point::new(0.0, 0.0),
            Point::new(20.0, 0.0),
            Point::new(20.0, 10.0),
            Point::new(10.0, 10.0),
            Point::new(10.0, 20.0),
            Point::new(0.0, 20.0),
        ]))
    }

    #[test]
    fn within_an_l_room_means_inside_it_not_in_its_notch_nor_across() {
        let l = l_shape();
        assert!(within(&l, &rect(1.0, 1.0, 9.0, 9.0), 1e-9));
        // Touching the room's edges from inside.
        assert!(within(&l, &rect(0.0, 0.0, 20.0, 10.0), 1e-9));
        assert!(within(&l, &rect(0.0, 10.0, 10.0, 20.0), 1e-9));
        assert!(!within(&l, &rect(10.0, 10.0, 20.0, 20.0), 1e-9));
        assert!(!within(&l, &rect(5.0, 5.0, 15.0, 15.0), 1e-9));
        assert!(!within(&l, &rect(0.0, 0.0, 20.0, 20.0), 1e-9));
        assert!(!within(&l, &rect(-1.0, 1.0, 5.0, 5.0), 1e-9));
    }

    #[test]
    fn an_l_shape_leaves_its_notch_free() {
        let l = l_shape();
        assert!(!overlaps(&l, &rect(10.0, 10.0, 20.0, 20.0), 1e-9));
        assert!(overlaps(&l, &rect(9.9, 10.0, 20.0, 20.0), 1e-9));
        let moved = rect(0.0, 0.0, 10.0, 10.0).moved(Point::new(10.0, 10.0));
        assert!(!overlaps(&l, &moved, 1e-9));
    }

    #[test]
    fn two_u_shapes_on_a_grid_overlap_although_no_vertex_is_inside() {
        // shapes0's item 0 twice, 2 apart: every vertex and edge midpoint
        // of each lies on the other's boundary, yet the bases overlap.
        let u = |x: f64| {
            Shape::new(Polygon::new(
                [
                    (0.0, 0.0),
                    (2.0, 0.0),
                    (2.0, 3.0),
                    (12.0, 3.0),
                    (12.0, 0.0),
                    (14.0, 0.0),
                    (14.0, 5.0),
                    (0.0, 5.0),
                ]
                .iter()
                .map(|&(a, b)| Point::new(a + x, b))
                .collect(),
            ))
        };
        assert!(overlaps(&u(0.0), &u(2.0), 1e-9));
        assert!(overlaps(&u(2.0), &u(0.0), 1e-9));
        assert!(!overlaps(&u(0.0), &u(14.0), 1e-9));
        // jakobs2: an L exactly on top of another, its box's middle height
        // running along an edge.
        let l = Shape::new(Polygon::new(
            [
                (20.0, 18.0),
                (24.0, 18.0),
                (24.0, 26.0),
                (16.0, 26.0),
                (16.0, 22.0),
                (20.0, 22.0),
            ]
            .iter()
            .map(|&(a, b)| Point::new(a, b))
            .collect(),
        ));
        assert!(overlaps(&l, &l.clone(), 1e-9));
        // The same L turned by 270° as the placer turns it (rounding in
        // the last bits), twice at the same place.
        let turned = l.poly.placed(270.0, false, Point::new(6.0, 46.0));
        let (a, b) = (
            Shape::new(turned.clone()),
            Shape::new(turned.moved(Point::new(1e-15, 0.0))),
        );
        assert!(overlaps(&a, &b, 1e-9));
    }
}
