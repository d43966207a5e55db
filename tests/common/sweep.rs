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
    seg_dist2(p, a, b).sqrt()
}

/// Squared distance from `p` to the segment `ab` (no square root: the
/// sampled nest check's inner loop takes the least of millions).
pub fn seg_dist2(p: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.x - a.x) * dx + (p.y - a.y) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (ex, ey) = (p.x - (a.x + dx * t), p.y - (a.y + dy * t));
    ex * ex + ey * ey
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

/// What the kerf swept along the plan's cutting moves takes from one part,
/// found here on a raster of `cell` mm (issue 39 §6: the independent check
/// of `--verify`'s loss part by part).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Loss {
    /// Area taken, mm²: raster cells whose centre lies in the part and
    /// within kerf/2 of a cutting move.
    pub area: f64,
    /// Deepest reach of the disc past the part's drawn edge, mm.
    pub depth: f64,
}

/// A closed contour flattened: its part, polygon, box and whether an outer.
type Poly = (Option<usize>, Vec<Point>, [f64; 4], bool);

/// The loss of every part (by part number, 1-based; index 0 unused) to the
/// cutting moves of `plan` (every role but marks and tabs) with a kerf of
/// `kerf`. The moves are flattened to chords here and the parts are the
/// closed contours flattened to polygons, even-odd, as [`Parts`] reads them.
pub fn loss_by_part(plan: &CutPlan, contours: &Contours, kerf: f64, cell: f64) -> Vec<Loss> {
    let r = kerf / 2.0;
    let polys: Vec<Poly> = contours
        .contours
        .iter()
        .filter(|c| c.kind != ContourKind::Open)
        .map(|c| {
            let mut pts: Vec<Point> = Vec::new();
            for s in &c.segments {
                let f = flatten(s);
                pts.extend_from_slice(&f[..f.len() - 1]);
            }
            let mut bb = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
            for p in &pts {
                bb = [
                    bb[0].min(p.x),
                    bb[1].min(p.y),
                    bb[2].max(p.x),
                    bb[3].max(p.y),
                ];
            }
            (c.part, pts, bb, c.kind == ContourKind::Outer)
        })
        .collect();
    let inside = |pts: &[Point], p: Point| {
        let mut c = false;
        for i in 0..pts.len() {
            let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
            if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
                c = !c;
            }
        }
        c
    };
    // The part whose material holds `p`: the smallest polygon round it,
    // when an odd number are.
    let part_at = |p: Point| {
        let mut odd = false;
        let mut best: Option<(f64, Option<usize>)> = None;
        for (part, pts, bb, _) in &polys {
            if p.x < bb[0] || p.x > bb[2] || p.y < bb[1] || p.y > bb[3] || !inside(pts, p) {
                continue;
            }
            odd = !odd;
            let size = (bb[2] - bb[0]) * (bb[3] - bb[1]);
            if best.is_none_or(|(s, _)| size < s) {
                best = Some((size, *part));
            }
        }
        if odd {
            best.and_then(|b| b.1)
        } else {
            None
        }
    };
    // The moves as chords at most 0.05 mm off the arc, filed by 2 mm cells.
    let g = 2.0_f64.max(2.0 * r);
    let key = |p: Point| ((p.x / g).floor() as i64, (p.y / g).floor() as i64);
    let mut chords: Vec<(Point, Point)> = Vec::new();
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    for s in plan
        .cuts
        .iter()
        .flat_map(|c| c.steps.iter())
        .filter(|s| !matches!(s.role, Role::Mark | Role::Tab))
    {
        let n = ((seg_len(&s.segment) / 0.05).ceil() as usize).max(1);
        for k in 0..n {
            let a = bulge_point(&s.segment, k as f64 / n as f64);
            let b = bulge_point(&s.segment, (k + 1) as f64 / n as f64);
            let id = chords.len();
            chords.push((a, b));
            let (x0, y0) = key(Point::new(a.x.min(b.x), a.y.min(b.y)));
            let (x1, y1) = key(Point::new(a.x.max(b.x), a.y.max(b.y)));
            for x in x0..=x1 {
                for y in y0..=y1 {
                    grid.entry((x, y)).or_default().push(id);
                }
            }
        }
    }
    let n = polys.iter().filter_map(|p| p.0).max().unwrap_or(0);
    let mut out = vec![Loss::default(); n + 1];
    // Area: every raster cell of every grid cell that holds a move (the
    // cells a disc can reach lie in those or their neighbours), each
    // tested against the moves of its 3 x 3 grid cells.
    let mut cells: Vec<(i64, i64)> = grid.keys().copied().collect();
    let mut reach: Vec<(i64, i64)> = Vec::new();
    for &(x, y) in &cells {
        for dx in -1..=1 {
            for dy in -1..=1 {
                reach.push((x + dx, y + dy));
            }
        }
    }
    reach.sort();
    reach.dedup();
    cells.clear();
    let per = (g / cell).round() as i64;
    let h = g / per as f64;
    for (x, y) in reach {
        let mut near: Vec<usize> = Vec::new();
        for dx in -1..=1 {
            for dy in -1..=1 {
                near.extend(grid.get(&(x + dx, y + dy)).map_or(&[][..], |v| &v[..]));
            }
        }
        if near.is_empty() {
            continue;
        }
        for i in 0..per {
            for j in 0..per {
                let p = Point::new(
                    x as f64 * g + (i as f64 + 0.5) * h,
                    y as f64 * g + (j as f64 + 0.5) * h,
                );
                if near
                    .iter()
                    .any(|&k| seg_dist(p, chords[k].0, chords[k].1) <= r)
                {
                    if let Some(part) = part_at(p) {
                        out[part].area += h * h;
                    }
                }
            }
        }
    }
    // Depth: each chord's start against each part's own edges (its outline
    // and its holes'): past them into its material, or short of them.
    for (part, loss) in out.iter_mut().enumerate().skip(1) {
        let own: Vec<&Poly> = polys.iter().filter(|p| p.0 == Some(part)).collect();
        let Some((_, _, bb, _)) = own.iter().find(|p| p.3) else {
            continue;
        };
        let grown = [bb[0] - r, bb[1] - r, bb[2] + r, bb[3] + r];
        for &(a, _) in &chords {
            if a.x < grown[0] || a.x > grown[2] || a.y < grown[1] || a.y > grown[3] {
                continue;
            }
            let d = (own.iter())
                .flat_map(|p| (0..p.1.len()).map(|i| seg_dist(a, p.1[i], p.1[(i + 1) % p.1.len()])))
                .fold(f64::INFINITY, f64::min);
            let depth = if part_at(a) == Some(part) {
                r + d
            } else {
                r - d
            };
            loss.depth = loss.depth.max(depth);
        }
    }
    out
}
