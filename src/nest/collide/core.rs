//! A quick "surely overlapping" for many-vertex shapes (issue 44): a few
//! circles inside each shape. Two shapes whose circles cut into each other
//! by more than a few `eps` overlap, and the exact test would say so after
//! walking hundreds of edges; the placer's bottom-left candidates are
//! mostly of that kind (a copy put on top of one already placed), and on
//! CAD outlines of 500–1400 vertices the exact test of them was nearly all
//! of the time of a first nest (perf, the real-part instances: 87 % in the
//! crossing search, one finger-jointed panel placed a second).
//!
//! The circles are found as the separator finds its poles (sparrow's
//! idea, Gardeyn & Wauters, EJOR 2025): centres on a grid over the box,
//! each circle as large as the centre's distance to the outline, the
//! largest first, a next one only outside those taken. Only the answer
//! "overlap" is ever taken from them: shapes whose circles do not meet go
//! to the exact test as before, so a nest is the same with or without.

use std::sync::Arc;

use super::seg_dist2;
use crate::geom::{fmax, Point};
use crate::nest::shape::Polygon;

/// Vertices past which a shape gets circles (below, the exact test is a
/// few dozen edge pairs and cheaper than the circles).
pub const CORE_FROM: usize = 24;
/// Most circles per shape: the test costs their product.
const MOST: usize = 8;
/// Grid cells over the box where centres are tried.
const GRID: usize = 24;

/// Circles inside a shape, in the shape's coordinates when it was made.
#[derive(Debug)]
pub struct Core {
    /// Centres and radii (radius = the centre's distance to the outline,
    /// shrunk by a millionth of the shape's size for rounding).
    pub circles: Vec<(Point, f64)>,
}

impl Core {
    /// The circles of `poly`, or None when it has few vertices (or none
    /// fit).
    pub fn of(poly: &Polygon) -> Option<Arc<Core>> {
        if poly.pts.len() <= CORE_FROM {
            return None;
        }
        let b = &poly.bbox;
        let (w, h) = (b.max.x - b.min.x, b.max.y - b.min.y);
        if !(w > 0.0 && h > 0.0) {
            return None;
        }
        let size = fmax(w, h);
        let (sx, sy) = (w / GRID as f64, h / GRID as f64);
        let pts = &poly.pts;
        let n = pts.len();
        let mut cands: Vec<(Point, f64)> = Vec::new();
        for i in 0..GRID {
            for j in 0..GRID {
                let p = Point::new(
                    b.min.x + (i as f64 + 0.5) * sx,
                    b.min.y + (j as f64 + 0.5) * sy,
                );
                if !super::strictly_inside(poly, p, 0.0) {
                    continue;
                }
                let d2 = (0..n)
                    .map(|k| seg_dist2(p, pts[k], pts[(k + 1) % n]))
                    .fold(f64::INFINITY, f64::min);
                let r = d2.sqrt() - size * 1e-6;
                if r > size * 0.02 {
                    cands.push((p, r));
                }
            }
        }
        cands.sort_by(|a, b| b.1.total_cmp(&a.1));
        let mut circles: Vec<(Point, f64)> = Vec::new();
        for (p, r) in cands {
            if circles.len() == MOST {
                break;
            }
            // A next circle mostly outside those taken.
            if circles.iter().all(|&(c, rc)| p.dist(c) > rc) {
                circles.push((p, r));
            }
        }
        (!circles.is_empty()).then(|| Arc::new(Core { circles }))
    }
}

/// True when a circle of `a` (moved by `ta`) and one of `b` (moved by
/// `tb`) cut into each other by more than `4 eps`: then a point lies
/// more than `2 eps` inside both shapes, and they overlap.
pub fn cores_meet(a: &Core, ta: Point, b: &Core, tb: Point, eps: f64) -> bool {
    let d = tb.sub(ta);
    for &(ca, ra) in &a.circles {
        for &(cb, rb) in &b.circles {
            let reach = ra + rb - 4.0 * eps;
            if reach > 0.0 {
                let v = cb.add(d).sub(ca);
                if v.dot(v) < reach * reach {
                    return true;
                }
            }
        }
    }
    false
}

/// The margin of [`holds_disc`] and [`sticks_out`]: `2 eps`, and the
/// rounding of the points moved (10⁻⁹ of the coordinates, where a move
/// rounds by 10⁻¹⁶ of them).
fn disc_slack(at: Point, c: Point, r: f64, eps: f64) -> f64 {
    2.0 * eps + 1e-9 * (c.x.abs() + c.y.abs() + at.x.abs() + at.y.abs() + r)
}

/// True when the disc at `c` of radius `r` lies inside a circle of
/// `core` (moved by `at`), more than `2 eps` from its rim: then inside the
/// shape ([`disc_slack`]).
pub fn holds_disc(core: &Core, at: Point, c: Point, r: f64, eps: f64) -> bool {
    let slack = disc_slack(at, c, r, eps);
    core.circles.iter().any(|&(cc, rc)| {
        let reach = rc - r - slack;
        reach > 0.0 && cc.add(at).dist(c) < reach
    })
}

/// True when a circle of `core` (moved by `at`) reaches past the disc at
/// `c` of radius `r` by more than half its own radius and `2 eps`: then a
/// disc inside the shape lies out of that disc, so the shape is not
/// within anything that disc holds.
pub fn sticks_out(core: &Core, at: Point, c: Point, r: f64, eps: f64) -> bool {
    let slack = disc_slack(at, c, r, eps);
    core.circles
        .iter()
        .any(|&(cc, rc)| cc.add(at).dist(c) + 0.5 * rc > r + slack)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nest::collide::{overlaps, Shape};

    /// A disc of `n` vertices, radius `r`, centre `c`.
    fn disc(n: usize, r: f64, c: Point) -> Polygon {
        Polygon::new(
            (0..n)
                .map(|k| {
                    let a = k as f64 / n as f64 * std::f64::consts::TAU;
                    Point::new(c.x + r * a.cos(), c.y + r * a.sin())
                })
                .collect(),
        )
    }

    #[test]
    fn circles_lie_inside_and_meeting_circles_mean_overlap() {
        // A toothed plate (a comb) and a disc: every circle inside its
        // shape, and whenever the circles say overlap the exact test
        // (independent of them) says so too, over a grid of offsets.
        let mut comb = vec![Point::new(0.0, 0.0), Point::new(60.0, 0.0)];
        for k in (0..12).rev() {
            let x = k as f64 * 5.0;
            comb.extend([
                Point::new(x + 5.0, 20.0),
                Point::new(x + 2.5, 20.0),
                Point::new(x + 2.5, 14.0),
                Point::new(x, 14.0),
            ]);
        }
        let comb = Polygon::new(comb);
        let d = disc(60, 7.0, Point::new(0.0, 0.0));
        let (ca, cb) = (Core::of(&comb).expect("comb"), Core::of(&d).expect("disc"));
        for (poly, core) in [(&comb, &ca), (&d, &cb)] {
            for &(c, r) in &core.circles {
                assert!(crate::nest::collide::strictly_inside(poly, c, 0.0));
                let n = poly.pts.len();
                for k in 0..n {
                    assert!(seg_dist2(c, poly.pts[k], poly.pts[(k + 1) % n]).sqrt() >= r);
                }
            }
        }
        let (sa, sb) = (Shape::new(comb.clone()), Shape::new(d.clone()));
        let mut said = 0;
        for i in -10..=80 {
            for j in -10..=35 {
                let t = Point::new(i as f64, j as f64);
                if cores_meet(&ca, Point::default(), &cb, t, 1e-6) {
                    said += 1;
                    assert!(overlaps(&sa, &sb.moved(t), 1e-6), "{t:?}");
                }
            }
        }
        assert!(said > 100, "{said}");
    }

    #[test]
    fn few_vertices_get_no_circles() {
        assert!(Core::of(&disc(CORE_FROM, 5.0, Point::default())).is_none());
        assert!(Core::of(&disc(CORE_FROM + 1, 5.0, Point::default())).is_some());
    }
}
