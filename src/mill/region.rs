//! A pocket as a region: its outline and the islands standing in it,
//! offset inward with cavalier_contours' shape offset (arcs stay arcs,
//! islands and outline offset together, so where they meet the region
//! splits, paper 004 §2.8 without its self-intersection gap). The
//! tool-centre region at distance r from the walls is where the tool's
//! centre may go: anything inside it never gouges.

use cavalier_contours::polyline::{
    FindIntersectsOptions, PlineCreation, PlineSource, PlineSourceMut, Polyline,
};
use cavalier_contours::shape_algorithms::{Shape, ShapeOffsetOptions};

use crate::contour::point_in_loop;
use crate::geom::{dist_to_segment, loop_area, nearest_param, path_points, Point, Segment};

/// A closed loop of the region's boundary: counter-clockwise around
/// material to clear, clockwise around an island.
#[derive(Clone, Debug)]
pub struct Loop {
    /// Segments end to end (|bulge| ≤ 1).
    pub segments: Vec<Segment>,
    /// The same loop as points (arcs within the chord), closed (first
    /// point not repeated).
    pub points: Vec<Point>,
}

impl Loop {
    fn new(segments: Vec<Segment>, chord: f64) -> Loop {
        let mut points = Vec::with_capacity(segments.len());
        path_points(&segments, chord, &mut points);
        Loop { segments, points }
    }
    /// Signed area (> 0 counter-clockwise).
    pub fn area(&self) -> f64 {
        loop_area(&self.segments)
    }
    /// Edges of the flattened loop.
    pub fn edges(&self) -> impl Iterator<Item = (Point, Point)> + '_ {
        let n = self.points.len();
        (0..n).map(move |i| (self.points[i], self.points[(i + 1) % n]))
    }
    /// Distance from `p` to the loop.
    pub fn dist(&self, p: Point) -> f64 {
        self.segments
            .iter()
            .map(|s| dist_to_segment(p, s))
            .fold(f64::INFINITY, f64::min)
    }
}

/// A region: loops whose even-odd interior is the area.
#[derive(Clone, Debug, Default)]
pub struct Region {
    /// Counter-clockwise outlines and clockwise islands.
    pub loops: Vec<Loop>,
}

fn to_pline(segs: &[Segment], ccw: bool) -> Polyline<f64> {
    let mut pl = Polyline::with_capacity(segs.len(), true);
    let reverse = (loop_area(segs) > 0.0) != ccw;
    if reverse {
        for s in segs.iter().rev() {
            pl.add(s.b.x, s.b.y, -s.bulge);
        }
    } else {
        for s in segs {
            pl.add(s.a.x, s.a.y, s.bulge);
        }
    }
    pl
}

/// The kerf stage's conversion, less the zero-length segments a shape
/// offset may leave.
fn from_pline(pl: &Polyline<f64>) -> Vec<Segment> {
    let mut segs = crate::kerf::from_pline(pl);
    segs.retain(|s| s.a.dist(s.b) > 0.0);
    segs
}

/// A pocket: its outline and islands as drawn.
#[derive(Clone, Debug)]
pub struct Pocket {
    shape: Shape<f64>,
    /// The chord of flattened loops, mm.
    chord: f64,
}

impl Pocket {
    /// The pocket inside `outline`, around `islands` (any direction).
    pub fn new(outline: &[Segment], islands: &[&[Segment]], chord: f64) -> Pocket {
        let mut plines = vec![to_pline(outline, true)];
        plines.extend(islands.iter().map(|i| to_pline(i, false)));
        Pocket {
            shape: Shape::from_plines(plines),
            chord,
        }
    }
    /// The region at distance `d` inside the walls (0: as drawn).
    pub fn inset(&self, d: f64) -> Region {
        let shape = if d == 0.0 {
            self.shape.clone()
        } else {
            self.shape.parallel_offset(d, &ShapeOffsetOptions::new())
        };
        region_of(&shape, self.chord)
    }
    /// The part of the pocket a disc of radius `r` can sweep: the
    /// tool-centre region grown back by `r` (the opening).
    pub fn reachable(&self, r: f64) -> Region {
        let centre = self.shape.parallel_offset(r, &ShapeOffsetOptions::new());
        if centre.ccw_plines.is_empty() {
            return Region::default();
        }
        region_of(
            &centre.parallel_offset(-r, &ShapeOffsetOptions::new()),
            self.chord,
        )
    }
}

/// A point where the closed loops `a` and `b` cross — `b` passes from
/// inside `a` to outside it there, its points `eps` or more from `a` on
/// either side — or None where they only touch (an island standing on
/// its pocket's wall) or stay apart.
pub fn crossing(a: &[Segment], b: &[Segment], eps: f64) -> Option<Point> {
    if a.len() < 2 || b.len() < 2 || !a.iter().chain(b).all(Segment::is_finite) {
        return None;
    }
    let (pa, pb) = (to_pline(a, true), to_pline(b, true));
    let opts = FindIntersectsOptions {
        pos_equal_eps: eps.min(1e-5),
        ..FindIntersectsOptions::new()
    };
    let on_b = crate::kerf::from_pline(&pb);
    let a_dist = |q: Point| {
        a.iter()
            .map(|s| dist_to_segment(q, s))
            .fold(f64::INFINITY, f64::min)
    };
    for x in pa.find_intersects_opt(&pb, &opts).basic_intersects {
        let p = Point::new(x.point.x, x.point.y);
        let j = x.start_index2;
        // Step along b both ways until both points stand clear of a (a
        // shallow crossing needs longer steps).
        for d in [2.0, 8.0, 32.0].map(|k| k * eps) {
            let (q0, q1) = (along(&on_b, j, p, -d), along(&on_b, j, p, d));
            if a_dist(q0) >= eps && a_dist(q1) >= eps {
                if point_in_loop(q0, a) != point_in_loop(q1, a) {
                    return Some(p);
                }
                break;
            }
        }
    }
    None
}

/// The point `d` mm along closed loop `segs` from `p` on its segment `j`
/// (backwards for `d` < 0).
fn along(segs: &[Segment], j: usize, p: Point, d: f64) -> Point {
    let n = segs.len();
    let Some(s) = segs.get(j) else {
        return p;
    };
    let mut k = j;
    let mut left = nearest_param(s, p) * s.length() + d;
    // Each turn moves to a neighbouring segment: a whole round is enough.
    for _ in 0..=2 * n {
        let len = segs[k].length();
        if left < 0.0 {
            k = (k + n - 1) % n;
            left += segs[k].length();
        } else if left > len {
            left -= len;
            k = (k + 1) % n;
        } else {
            return segs[k].point_at(if len > 0.0 { left / len } else { 0.0 });
        }
    }
    p
}

fn region_of(shape: &Shape<f64>, chord: f64) -> Region {
    let loops = (shape.ccw_plines.iter())
        .chain(shape.cw_plines.iter())
        .map(|ip| Loop::new(from_pline(&ip.polyline), chord))
        .filter(|l| l.segments.len() >= 2)
        .collect();
    Region { loops }
}

impl Region {
    /// True when nothing is left.
    pub fn is_empty(&self) -> bool {
        self.loops.is_empty()
    }
    /// Area, mm² (outlines less islands).
    pub fn area(&self) -> f64 {
        self.loops.iter().map(Loop::area).sum()
    }
    /// Even-odd inside test on the flattened loops.
    pub fn contains(&self, p: Point) -> bool {
        let mut inside = false;
        for l in &self.loops {
            for (a, b) in l.edges() {
                if (a.y > p.y) != (b.y > p.y) {
                    let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                    if x > p.x {
                        inside = !inside;
                    }
                }
            }
        }
        inside
    }
    /// Distance from `p` to the nearest wall of the region.
    pub fn wall_dist(&self, p: Point) -> f64 {
        self.loops
            .iter()
            .map(|l| l.dist(p))
            .fold(f64::INFINITY, f64::min)
    }
    /// True when the straight move `a`→`b` stays inside the region (within
    /// `eps` of its walls: a link along a wall is inside).
    pub fn holds_line(&self, a: Point, b: Point, eps: f64) -> bool {
        let n = ((a.dist(b) / (eps * 20.0).max(0.05)).ceil() as usize).clamp(1, 20_000);
        (0..=n).all(|k| {
            let p = a.add(b.sub(a).scale(k as f64 / n as f64));
            self.contains(p) || self.wall_dist(p) <= eps
        })
    }
    /// The way along the wall from `a` to `b` when both lie on the same
    /// loop (within `eps`), the shorter way round, as points (a and b
    /// included); None when they are on different loops.
    pub fn walk(&self, a: Point, b: Point, eps: f64) -> Option<Vec<Point>> {
        let on = |p: Point| -> Option<(usize, usize, f64)> {
            // (loop, edge, distance)
            let mut best: Option<(usize, usize, f64)> = None;
            for (li, l) in self.loops.iter().enumerate() {
                for (ei, (u, v)) in l.edges().enumerate() {
                    let d = dist_to_segment(p, &Segment::line(u, v));
                    if best.is_none_or(|(_, _, bd)| d < bd) {
                        best = Some((li, ei, d));
                    }
                }
            }
            best.filter(|b| b.2 <= eps)
        };
        let (la, ea, _) = on(a)?;
        let (lb, eb, _) = on(b)?;
        if la != lb {
            return None;
        }
        let pts = &self.loops[la].points;
        let n = pts.len();
        if ea == eb {
            return Some(vec![a, b]);
        }
        // Forward: a, points ea+1 … eb, b (edge i runs from point i to i+1).
        let mut fwd = vec![a];
        let mut i = ea;
        while i != eb {
            i = (i + 1) % n;
            fwd.push(pts[i]);
        }
        fwd.push(b);
        // Backward: a, points ea … eb+1, b.
        let mut back = vec![a];
        let mut i = ea;
        loop {
            back.push(pts[i]);
            if i == (eb + 1) % n {
                break;
            }
            i = (i + n - 1) % n;
        }
        back.push(b);
        let len = |v: &[Point]| v.windows(2).map(|w| w[0].dist(w[1])).sum::<f64>();
        Some(if len(&fwd) <= len(&back) { fwd } else { back })
    }
}
