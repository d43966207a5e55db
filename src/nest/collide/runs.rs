//! Boxes of runs of consecutive edges of a many-vertex polygon, so the
//! exact test asks only the edges and vertices near the other shape.
//!
//! Every search of the exact test walks the edges of a shape to keep
//! those reaching a region (the two boxes' overlap, a height band): on
//! round parts of 30–60 vertices (discs and bores at 0.05 mm) the walks
//! were most of a placement's time (perf, issue 44's part-in-hole job: the
//! edge filters 25 %, their crossing and inside tests most of the rest),
//! though a candidate copy mostly meets its neighbour in a sliver. A run's
//! box holds every vertex of its edges, so a run whose box misses the
//! region has no edge or vertex there; the edges of the other runs go
//! through the same exact filter as before, in the same order, so every
//! answer is the same (the boxes are moved with the polygon, by the same
//! addition, and stay the exact boxes of its vertices: rounding is
//! monotonic, so the least of the moved coordinates is the moved least).

use std::ops::Range;

use crate::geom::{fmax, BBox, Point};

/// Vertices past which a polygon gets runs: below, its few edges are
/// walked whole as before (ESICUP's parts have 4–14 vertices).
pub const RUNS_FROM: usize = 16;

/// The boxes of runs of `len` consecutive edges (run k: edges
/// `k·len .. (k+1)·len`, edge i from vertex i to vertex i + 1, the last to
/// vertex 0), in the polygon's coordinates where it lies.
#[derive(Clone, Debug, Default)]
pub struct Runs {
    len: usize,
    boxes: Vec<BBox>,
}

impl Runs {
    /// The runs of a polygon's vertices, about √n edges each (at least
    /// 8): as many runs as edges in one, so the boxes and the edges of the
    /// few runs kept are both about √n to walk. None (no boxes) at
    /// [`RUNS_FROM`] vertices or fewer.
    pub fn of(pts: &[Point]) -> Runs {
        let n = pts.len();
        if n <= RUNS_FROM {
            return Runs::default();
        }
        let len = ((n as f64).sqrt().ceil() as usize).max(8);
        let boxes = (0..n)
            .step_by(len)
            .map(|k| {
                let mut b = BBox::EMPTY;
                for i in k..=(k + len).min(n) {
                    b.add(pts[if i == n { 0 } else { i }]);
                }
                b
            })
            .collect();
        Runs { len, boxes }
    }

    /// Moved by `t` (as the polygon's vertices are: the same boxes).
    pub fn moved(&self, t: Point) -> Runs {
        let mut r = Runs::default();
        r.move_from(self, t);
        r
    }

    /// Becomes `base` moved by `t`, in its own room.
    pub fn move_from(&mut self, base: &Runs, t: Point) {
        self.len = base.len;
        self.boxes.clear();
        self.boxes.extend(base.boxes.iter().map(|b| BBox {
            min: b.min.add(t),
            max: b.max.add(t),
        }));
    }

    /// The box of the run starting at edge `i` (None without runs).
    pub fn box_of(&self, i: usize) -> Option<BBox> {
        (self.len > 0).then(|| self.boxes[i / self.len])
    }

    /// The edges (index ranges, in order) of the runs but those whose box
    /// `far` says is far: all `n` edges at once when there are no runs.
    pub fn edges<F: Fn(&BBox) -> bool>(&self, n: usize, far: F) -> Near<'_, F> {
        Near {
            boxes: &self.boxes,
            k: 0,
            len: self.len,
            n,
            whole: self.boxes.is_empty(),
            far,
        }
    }
}

/// The ranges of [`Runs::edges`] (a plain loop: the hot path).
pub struct Near<'a, F> {
    boxes: &'a [BBox],
    k: usize,
    len: usize,
    n: usize,
    whole: bool,
    far: F,
}

impl<F: Fn(&BBox) -> bool> Iterator for Near<'_, F> {
    type Item = Range<usize>;
    #[inline]
    fn next(&mut self) -> Option<Range<usize>> {
        if self.whole {
            self.whole = false;
            return Some(0..self.n);
        }
        while let Some(b) = self.boxes.get(self.k) {
            let k = self.k;
            self.k += 1;
            if !(self.far)(b) {
                return Some(k * self.len..((k + 1) * self.len).min(self.n));
            }
        }
        None
    }
}

/// True when each point of the box `r` is farther than `eps` from each
/// point of the box `e`, by a margin (a billionth of the coordinates) far
/// above the rounding of the exact test's distances and orientations:
/// what either box holds is then surely more than `eps` apart.
pub fn far_from_box(r: &BBox, e: &BBox, eps: f64) -> bool {
    let size = [
        r.min.x, r.min.y, r.max.x, r.max.y, e.min.x, e.min.y, e.max.x, e.max.y,
    ]
    .iter()
    .fold(1.0f64, |m, v| fmax(m, v.abs()));
    let reach = eps + size * 1e-9;
    r.min.x - e.max.x > reach
        || e.min.x - r.max.x > reach
        || r.min.y - e.max.y > reach
        || e.min.y - r.max.y > reach
}

/// Edge `i` of a polygon of vertices `pts`: from vertex i to the next
/// (the last to the first), without the division of `(i + 1) % n`.
#[inline(always)]
pub fn edge(pts: &[Point], i: usize) -> (Point, Point) {
    (pts[i], *pts.get(i + 1).unwrap_or(&pts[0]))
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::nest::collide::inside::{shape_holds, strictly_inside};
    use crate::nest::collide::{overlaps, within, Shape};
    use crate::nest::shape::Polygon;

    /// A star-shaped polygon of `n` vertices about `c`: radii between
    /// `r` / 3 and `r`, some teeth.
    pub(in crate::nest::collide) fn star(
        rng: &mut impl FnMut() -> f64,
        n: usize,
        r: f64,
        c: Point,
    ) -> Polygon {
        let teeth = rng() < 0.5;
        Polygon::new(
            (0..n)
                .map(|i| {
                    let a = i as f64 / n as f64 * std::f64::consts::TAU;
                    let k = if teeth && i % 4 < 2 { 0.6 } else { 1.0 };
                    let rr = r * k * (0.7 + 0.3 * rng()).max(1.0 / 3.0);
                    Point::new(c.x + rr * a.cos(), c.y + rr * a.sin())
                })
                .collect(),
        )
    }

    /// The shape without runs: every edge walked, as before them.
    fn plain(s: &Shape) -> Shape {
        Shape {
            runs: Runs::default(),
            ..s.clone()
        }
    }

    #[test]
    fn the_exact_test_with_runs_answers_as_the_plain_all_pairs_walk() {
        let mut rng = crate::test_rng::unit(11);
        let (mut overlapping, mut apart, mut inside) = (0, 0, 0);
        for case in 0..3000 {
            let n = 17 + (rng() * 120.0) as usize;
            let m = 5 + (rng() * 130.0) as usize;
            let a = Shape::new(star(&mut rng, n, 20.0, Point::new(1000.0, 500.0)));
            let rb = 5.0 + 20.0 * rng();
            let b0 = Shape::new(star(&mut rng, m, rb, Point::default()));
            // Vertex on vertex (the placer's candidates), or anywhere
            // near, moved in two steps as the separator moves copies.
            let t = if case % 2 == 0 {
                let q = a.poly.pts[(rng() * n as f64) as usize];
                let r = b0.poly.pts[(rng() * m as f64) as usize];
                q.sub(r)
            } else {
                Point::new(1000.0 + 90.0 * (rng() - 0.5), 500.0 + 90.0 * (rng() - 0.5))
            };
            let half = Point::new(t.x * 0.5, t.y * 0.25);
            let b = b0.moved(half).moved(t.sub(half));
            let (pa, pb) = (plain(&a), plain(&b));
            for eps in [0.0, 1e-9, 1e-3, 0.5] {
                let got = overlaps(&a, &b, eps);
                assert_eq!(got, overlaps(&pa, &pb, eps), "case {case} eps {eps}");
                assert_eq!(
                    overlaps(&b, &a, eps),
                    overlaps(&pb, &pa, eps),
                    "case {case}"
                );
                assert_eq!(within(&a, &b, eps), within(&pa, &pb, eps), "case {case}");
                for p in [b.inner, b.poly.pts[0], t] {
                    assert_eq!(shape_holds(&a, p, eps), strictly_inside(&a.poly, p, eps));
                }
                if eps == 1e-9 {
                    overlapping += got as usize;
                    apart += !got as usize;
                    inside += within(&a, &b, eps) as usize;
                }
            }
            let (mut c, d) = (a.clone(), b0.moved(t));
            c.move_from(&b0, t);
            assert_eq!((c.poly, c.inner), (d.poly, d.inner), "case {case}");
            assert_eq!(c.runs.boxes, d.runs.boxes, "case {case}");
        }
        // Both answers came often (and some copies lay wholly inside).
        assert!(
            overlapping > 500 && apart > 500 && inside > 10,
            "{overlapping} {apart} {inside}"
        );
    }

    #[test]
    fn every_edge_is_in_one_run_whose_box_holds_it() {
        for n in [3, 16, 17, 48, 63, 64, 65, 200, 1401] {
            let pts: Vec<Point> = (0..n)
                .map(|i| {
                    let a = i as f64 / n as f64 * std::f64::consts::TAU;
                    Point::new(10.0 * a.cos() + 0.1 * i as f64, 7.0 * a.sin())
                })
                .collect();
            let runs = Runs::of(&pts).moved(Point::new(0.3, -1e3));
            let seen: Vec<usize> = runs.edges(n, |_| false).flatten().collect();
            assert_eq!(seen, (0..n).collect::<Vec<_>>(), "n {n}");
            for (k, b) in runs.boxes.iter().enumerate() {
                for i in k * runs.len..((k + 1) * runs.len).min(n) {
                    let (p, q) = edge(&pts, i);
                    for v in [p, q].map(|v| v.add(Point::new(0.3, -1e3))) {
                        assert!(b.min.x <= v.x && v.x <= b.max.x, "n {n} edge {i}");
                        assert!(b.min.y <= v.y && v.y <= b.max.y, "n {n} edge {i}");
                    }
                }
            }
        }
    }
}
