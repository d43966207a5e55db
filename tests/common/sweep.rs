//! An independent check of torch-on moves against the drawn parts (issue
//! 14), written apart from the planner's own check (`plan::scrap`): the
//! parts are flattened to polygons here, arcs are evaluated from their bulge
//! here, and every feed move is sampled every 0.1 mm; at each sample the kerf
//! disc (radius kerf/2) must not reach into a part's material.

use kerfcam::contour::{ContourKind, Contours};
use kerfcam::geom::{Point, Segment};
use kerfcam::plan::{CutPlan, Role};
use std::collections::HashMap;

/// Chord error of the flattened parts, mm.
const SAGITTA: f64 = 2e-4;
/// Reach into a part allowed for flattening and rounding, mm.
pub const SLACK: f64 = 0.005;
/// Sample spacing along moves, mm.
const STEP: f64 = 0.1;

/// The point at fraction `t` of a bulge segment: centre and angles computed
/// from the bulge (sweep = 4·atan(bulge)).
pub fn bulge_point(s: &Segment, t: f64) -> Point {
    let (a, b) = (s.a, s.b);
    if s.bulge.abs() < 1e-12 {
        return Point::new(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t);
    }
    let sweep = 4.0 * s.bulge.atan();
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let chord = (dx * dx + dy * dy).sqrt();
    let r = chord / (2.0 * (sweep / 2.0).sin()).abs();
    // Centre: from the chord midpoint along the left normal (right for cw).
    let h = r * (sweep / 2.0).cos().abs();
    let (mx, my) = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
    let (nx, ny) = (-dy / chord, dx / chord);
    let side = if (sweep.abs() < std::f64::consts::PI) == (sweep > 0.0) {
        1.0
    } else {
        -1.0
    };
    let (cx, cy) = (mx + side * h * nx, my + side * h * ny);
    let a0 = (a.y - cy).atan2(a.x - cx);
    let ang = a0 + sweep * t;
    Point::new(cx + r * ang.cos(), cy + r * ang.sin())
}

fn seg_len(s: &Segment) -> f64 {
    let n = 64;
    (0..n)
        .map(|k| {
            bulge_point(s, k as f64 / n as f64).dist(bulge_point(s, (k + 1) as f64 / n as f64))
        })
        .sum()
}

/// A segment flattened to points (ends included).
fn flatten(s: &Segment) -> Vec<Point> {
    let sweep = 4.0 * s.bulge.atan();
    let n = if s.bulge.abs() < 1e-12 {
        1
    } else {
        let chord = s.a.dist(s.b);
        let r = chord / (2.0 * (sweep / 2.0).sin()).abs();
        let per = 2.0 * (1.0 - SAGITTA / r).max(-1.0).acos();
        ((sweep.abs() / per.max(1e-6)).ceil() as usize).clamp(1, 100_000)
    };
    (0..=n)
        .map(|k| bulge_point(s, k as f64 / n as f64))
        .collect()
}

/// Distance from `p` to the segment a–b (the tests' own, not the library's).
pub fn seg_dist(p: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.x - a.x) * dx + (p.y - a.y) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.dist(Point::new(a.x + dx * t, a.y + dy * t))
}

/// The drawn parts as polygons, with a grid of their edges.
pub struct Parts {
    polys: Vec<(Vec<Point>, [f64; 4])>,
    edges: Vec<(Point, Point)>,
    grid: HashMap<(i64, i64), Vec<usize>>,
    cell: f64,
}

impl Parts {
    /// Every closed contour of `contours`.
    pub fn new(contours: &Contours) -> Parts {
        let cell = 4.0;
        let mut parts = Parts {
            polys: vec![],
            edges: vec![],
            grid: HashMap::new(),
            cell,
        };
        for c in contours
            .contours
            .iter()
            .filter(|c| c.kind != ContourKind::Open)
        {
            let mut pts: Vec<Point> = Vec::new();
            for s in &c.segments {
                let f = flatten(s);
                pts.extend_from_slice(&f[..f.len() - 1]);
            }
            let mut bb = [
                f64::INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NEG_INFINITY,
            ];
            for p in &pts {
                bb = [
                    bb[0].min(p.x),
                    bb[1].min(p.y),
                    bb[2].max(p.x),
                    bb[3].max(p.y),
                ];
            }
            for i in 0..pts.len() {
                let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
                let id = parts.edges.len();
                parts.edges.push((a, b));
                let (x0, y0) = parts.key(Point::new(a.x.min(b.x), a.y.min(b.y)));
                let (x1, y1) = parts.key(Point::new(a.x.max(b.x), a.y.max(b.y)));
                for x in x0..=x1 {
                    for y in y0..=y1 {
                        parts.grid.entry((x, y)).or_default().push(id);
                    }
                }
            }
            parts.polys.push((pts, bb));
        }
        parts
    }
    fn key(&self, p: Point) -> (i64, i64) {
        (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        )
    }
    /// Distance from `p` to the nearest part edge, looked for up to one cell.
    fn distance(&self, p: Point) -> f64 {
        let (x, y) = self.key(p);
        let mut d = self.cell;
        for dx in -1..=1 {
            for dy in -1..=1 {
                for &e in self.grid.get(&(x + dx, y + dy)).map_or(&[][..], |v| &v[..]) {
                    let (a, b) = self.edges[e];
                    d = d.min(seg_dist(p, a, b));
                }
            }
        }
        d
    }
    /// Inside an odd number of contours: in a part's material.
    fn in_material(&self, p: Point) -> bool {
        let mut inside = false;
        for (pts, bb) in &self.polys {
            if p.x < bb[0] || p.x > bb[2] || p.y < bb[1] || p.y > bb[3] {
                continue;
            }
            let mut c = false;
            for i in 0..pts.len() {
                let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
                if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)
                {
                    c = !c;
                }
            }
            inside ^= c;
        }
        inside
    }
}

/// The worst reach into a part of any torch-on move, and where: (depth mm,
/// role, point).
pub fn worst_reach(plan: &CutPlan, parts: &Parts, kerf: f64) -> (f64, Option<(Role, Point)>) {
    let r = kerf / 2.0;
    let mut worst = (0.0, None);
    for c in &plan.cuts {
        for s in &c.steps {
            let n = ((seg_len(&s.segment) / STEP).ceil() as usize).max(1);
            for k in 0..=n {
                let p = bulge_point(&s.segment, k as f64 / n as f64);
                let d = parts.distance(p);
                let depth = if parts.in_material(p) { r + d } else { r - d };
                if depth > worst.0 {
                    worst = (depth, Some((s.role, p)));
                }
            }
        }
    }
    worst
}

/// Points along every drawn closed contour farther than `kerf/2 + SLACK`
/// from all the plan's contour moves: edges not cut to size (none when every
/// part is cut all round at its drawn size).
pub fn uncut_edges(plan: &CutPlan, contours: &Contours, kerf: f64) -> Vec<Point> {
    let r = kerf / 2.0;
    let cell = 4.0;
    let key = |p: Point| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<Point>> = HashMap::new();
    for c in &plan.cuts {
        for s in c
            .steps
            .iter()
            .filter(|s| matches!(s.role, Role::Contour | Role::Repeat))
        {
            let n = ((seg_len(&s.segment) / (STEP / 4.0)).ceil() as usize).max(1);
            for k in 0..=n {
                let p = bulge_point(&s.segment, k as f64 / n as f64);
                grid.entry(key(p)).or_default().push(p);
            }
        }
    }
    let mut out = Vec::new();
    for c in contours
        .contours
        .iter()
        .filter(|c| c.kind != ContourKind::Open)
    {
        for s in &c.segments {
            let n = ((seg_len(s) / 1.0).ceil() as usize).max(1);
            for k in 0..n {
                let p = bulge_point(s, k as f64 / n as f64);
                let (x, y) = key(p);
                let mut d = f64::INFINITY;
                for dx in -1..=1 {
                    for dy in -1..=1 {
                        for q in grid.get(&(x + dx, y + dy)).map_or(&[][..], |v| &v[..]) {
                            d = d.min(p.dist(*q));
                        }
                    }
                }
                // Samples every STEP/4 along the path: the nearest lies within STEP/8.
                if d > r + SLACK + STEP / 8.0 {
                    out.push(p);
                }
            }
        }
    }
    out
}
