//! A shape as a few inscribed circles ("poles"), for measuring how deep
//! two shapes overlap.
//!
//! sparrow (Gardeyn & Wauters, EJOR 2025, arXiv 2509.13329, §4) measures
//! an overlap by the penetration of circles inscribed in the two shapes
//! rather than by the area of their intersection: it is cheap, smooth in
//! the translation and grows with how far one shape must move to clear the
//! other. The circles are found greedily: the first is the shape's *pole of
//! inaccessibility* (the centre of its largest inscribed circle, Garcia-
//! Castellanos & Lombardo 2007), each next one the largest circle inside
//! the shape and outside the circles found so far, until the circles cover
//! most of the area or become small.
//!
//! Here the search is a grid of candidate centres over the shape's box
//! (each keeps its clearance: distance to the outline, less the distance
//! to the circles already taken), the best one refined by a pattern search
//! that halves its step. A circle is never larger than its clearance, so
//! every pole lies inside the shape.

use crate::geom::{fmax, fmin, Point};
use crate::nest::collide::seg_dist2;
use crate::nest::shape::Polygon;

/// A circle inside a shape, in the shape's own (unmoved) coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pole {
    /// Centre.
    pub c: Point,
    /// Radius.
    pub r: f64,
}

/// Most poles per shape: the overlap measure costs poles × poles.
pub const MAX_POLES: usize = 24;
// The proxy marks a row's pairs in a u32 ([`super::overlap`]).
const _: () = assert!(MAX_POLES <= 32);

/// A shape's poles as the overlap proxy walks them ([`super::overlap`]):
/// centres and radii in arrays of their own, so the inner loop reads
/// each as a run, with the box of the centres and the largest radius
/// found once here rather than at every pair of shapes (that was an
/// eighth of a separation's time, jakobs1).
#[derive(Clone, Debug, PartialEq)]
pub struct PoleSet {
    /// How many poles (≤ [`MAX_POLES`]).
    pub n: usize,
    /// Centres' x, y and the radii; past `n`, zeros.
    pub x: [f64; MAX_POLES],
    pub y: [f64; MAX_POLES],
    pub r: [f64; MAX_POLES],
    /// Least and greatest centre (+∞ and −∞ when there is no pole).
    pub lo: Point,
    pub hi: Point,
    /// The largest radius (0 when none).
    pub rmax: f64,
}

impl PoleSet {
    /// The set of `ps` (at most [`MAX_POLES`], largest first as
    /// [`poles`] gives them).
    pub fn new(ps: &[Pole]) -> PoleSet {
        debug_assert!(ps.len() <= MAX_POLES);
        let mut set = PoleSet {
            n: 0,
            x: [0.0; MAX_POLES],
            y: [0.0; MAX_POLES],
            r: [0.0; MAX_POLES],
            lo: Point::new(f64::INFINITY, f64::INFINITY),
            hi: Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
            rmax: 0.0,
        };
        for p in ps.iter().take(MAX_POLES) {
            let i = set.n;
            (set.x[i], set.y[i], set.r[i]) = (p.c.x, p.c.y, p.r);
            set.n += 1;
            set.lo = Point::new(fmin(set.lo.x, p.c.x), fmin(set.lo.y, p.c.y));
            set.hi = Point::new(fmax(set.hi.x, p.c.x), fmax(set.hi.y, p.c.y));
            set.rmax = fmax(set.rmax, p.r);
        }
        set
    }
    /// Pole `i`.
    pub fn pole(&self, i: usize) -> Pole {
        Pole {
            c: Point::new(self.x[i], self.y[i]),
            r: self.r[i],
        }
    }
    /// The poles, in order.
    pub fn iter(&self) -> impl Iterator<Item = Pole> + '_ {
        (0..self.n).map(|i| self.pole(i))
    }
}
/// Stop once the poles cover this share of the area.
const COVER: f64 = 0.92;
/// Stop once a new pole is smaller than this share of the first one.
const SMALLEST: f64 = 0.08;
/// Candidate centres on the grid (about).
const GRID: f64 = 2500.0;

/// The poles of `poly`, largest first; empty only for a shape with no
/// inside.
pub fn poles(poly: &Polygon) -> Vec<Pole> {
    let b = &poly.bbox;
    let (w, h) = (b.max.x - b.min.x, b.max.y - b.min.y);
    if !(w > 0.0 && h > 0.0) || poly.pts.len() < 3 {
        return Vec::new();
    }
    let step = (w * h / GRID).sqrt();
    let (nx, ny) = (
        ((w / step).ceil() as usize).max(1),
        ((h / step).ceil() as usize).max(1),
    );
    let (sx, sy) = (w / nx as f64, h / ny as f64);
    let mut cands: Vec<(Point, f64)> = Vec::with_capacity(nx * ny);
    for i in 0..nx {
        for j in 0..ny {
            let p = Point::new(
                b.min.x + (i as f64 + 0.5) * sx,
                b.min.y + (j as f64 + 0.5) * sy,
            );
            let d = clearance(poly, p, &[]);
            if d > 0.0 {
                cands.push((p, d));
            }
        }
    }
    let area = poly.area();
    let mut out: Vec<Pole> = Vec::new();
    let mut covered = 0.0;
    while out.len() < MAX_POLES && covered < COVER * area {
        let Some(&(p, d)) = cands.iter().max_by(|a, b| a.1.total_cmp(&b.1)) else {
            break;
        };
        if d <= 0.0 {
            break;
        }
        let (c, r) = refine(poly, &out, p, d, fmin(sx, sy));
        if out.first().is_some_and(|f| r < SMALLEST * f.r) {
            break;
        }
        let pole = Pole { c, r };
        out.push(pole);
        covered += std::f64::consts::PI * r * r;
        for cand in &mut cands {
            cand.1 = cand.1.min(cand.0.dist(c) - r);
        }
    }
    out
}

/// Pattern search from `p` (clearance `d`): the 8 neighbours at `step`,
/// move to a better one, else halve the step.
fn refine(poly: &Polygon, taken: &[Pole], mut p: Point, mut d: f64, step0: f64) -> (Point, f64) {
    let mut step = step0 / 2.0;
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let dirs = [
        (1.0, 0.0),
        (-1.0, 0.0),
        (0.0, 1.0),
        (0.0, -1.0),
        (h, h),
        (-h, h),
        (h, -h),
        (-h, -h),
    ];
    while step > step0 * 1e-3 {
        let best = dirs
            .iter()
            .map(|&(x, y)| {
                let q = Point::new(p.x + x * step, p.y + y * step);
                (q, clearance(poly, q, taken))
            })
            .max_by(|a, b| a.1.total_cmp(&b.1));
        match best {
            Some((q, dq)) if dq > d => {
                p = q;
                d = dq;
            }
            _ => step /= 2.0,
        }
    }
    (p, d)
}

/// How large a circle centred at `p` may be: inside `poly` and outside
/// every pole taken (≤ 0 when `p` is outside or in a pole).
pub fn clearance(poly: &Polygon, p: Point, taken: &[Pole]) -> f64 {
    if !inside(poly, p) {
        return 0.0;
    }
    let pts = &poly.pts;
    let n = pts.len();
    let mut d2 = f64::INFINITY;
    for i in 0..n {
        d2 = d2.min(seg_dist2(p, pts[i], pts[(i + 1) % n]));
    }
    taken
        .iter()
        .fold(d2.sqrt(), |d, q| d.min(p.dist(q.c) - q.r))
}

/// Even-odd test (a point on the boundary has clearance 0 either way).
pub fn inside(poly: &Polygon, p: Point) -> bool {
    let pts = &poly.pts;
    let n = pts.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (pts[i], pts[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) && a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) > p.x {
            inside = !inside;
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn poly(v: &[(f64, f64)]) -> Polygon {
        Polygon::new(v.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    /// Every pole inside the polygon (its centre inside, its circle
    /// clear of every edge, checked by sampling the circle), none
    /// overlapping another, and their area the share asked of the shape.
    fn check(p: &Polygon, least_cover: f64) {
        let ps = poles(p);
        assert!(!ps.is_empty());
        let mut cover = 0.0;
        for (i, q) in ps.iter().enumerate() {
            assert!(inside(p, q.c), "{q:?}");
            for k in 0..64 {
                let a = 2.0 * PI * k as f64 / 64.0;
                let on = Point::new(q.c.x + q.r * 0.999 * a.cos(), q.c.y + q.r * 0.999 * a.sin());
                assert!(inside(p, on), "pole {i} {q:?} leaves the shape at {on:?}");
            }
            for o in &ps[..i] {
                assert!(o.c.dist(q.c) >= o.r + q.r - 1e-9, "{o:?} {q:?}");
            }
            cover += PI * q.r * q.r;
        }
        assert!(ps.len() <= MAX_POLES);
        assert!(
            cover >= least_cover * p.area(),
            "{} poles cover {:.3}",
            ps.len(),
            cover / p.area()
        );
    }

    #[test]
    fn the_first_pole_of_a_square_is_its_inscribed_circle() {
        let sq = poly(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]);
        let ps = poles(&sq);
        assert!(ps[0].c.dist(Point::new(5.0, 5.0)) < 0.01, "{:?}", ps[0]);
        assert!((ps[0].r - 5.0).abs() < 0.01);
        check(&sq, 0.85);
    }

    #[test]
    fn poles_lie_inside_and_cover_most_of_l_u_and_thin_shapes() {
        let l = poly(&[
            (0.0, 0.0),
            (20.0, 0.0),
            (20.0, 10.0),
            (10.0, 10.0),
            (10.0, 20.0),
            (0.0, 20.0),
        ]);
        check(&l, 0.8);
        let u = poly(&[
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 3.0),
            (12.0, 3.0),
            (12.0, 0.0),
            (14.0, 0.0),
            (14.0, 5.0),
            (0.0, 5.0),
        ]);
        check(&u, 0.7);
        // A 50 × 2 bar: a row of circles along it.
        let bar = poly(&[(0.0, 0.0), (50.0, 0.0), (50.0, 2.0), (0.0, 2.0)]);
        check(&bar, 0.7);
        // A triangle.
        check(&poly(&[(0.0, 0.0), (30.0, 0.0), (0.0, 12.0)]), 0.7);
    }

    #[test]
    fn no_inside_no_poles() {
        assert!(poles(&poly(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)])).is_empty());
    }
}
