//! Nest checks by sampling (issues 16, 18), apart from the engine's own
//! collision code: each placed loop becomes points every ~0.5 mm (arcs
//! evaluated from their bulge by [`super::sweep::bulge_point`]), distances
//! are measured point to segment, and insideness by ray crossing.

use super::sweep::{bulge_point, seg_dist2};
use kerfcam::geom::{Point, Segment};

/// A loop as points every ~0.5 mm (at least two per segment).
pub fn sampled(l: &[Segment]) -> Vec<Point> {
    l.iter()
        .flat_map(|s| {
            let n = ((s.a.dist(s.b) / 0.5).ceil() as usize).clamp(1, 400) * 2;
            (0..n).map(move |k| bulge_point(s, k as f64 / n as f64))
        })
        .collect()
}

/// Least distance from any point of `a` to the closed polyline `b`.
pub fn least_distance(a: &[Point], b: &[Point]) -> f64 {
    let (x0, y0, x1, y1) = bounds(b);
    let mut d2 = f64::INFINITY;
    for &p in a {
        // No point of `b` is nearer to `p` than `b`'s box is: a point no
        // nearer to the box than the least distance so far is passed over.
        let bx = (x0 - p.x).max(p.x - x1).max(0.0);
        let by = (y0 - p.y).max(p.y - y1).max(0.0);
        if bx * bx + by * by >= d2 {
            continue;
        }
        for i in 0..b.len() {
            d2 = d2.min(seg_dist2(p, b[i], b[(i + 1) % b.len()]));
        }
    }
    d2.sqrt()
}

/// True when `p` is inside the closed polyline `poly` (ray crossing).
pub fn inside(poly: &[Point], p: Point) -> bool {
    let mut c = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            c = !c;
        }
    }
    c
}

/// Box of points: (min x, min y, max x, max y).
pub fn bounds(pts: &[Point]) -> (f64, f64, f64, f64) {
    pts.iter().fold(
        (
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ),
        |(a, b, c, d), p| (a.min(p.x), b.min(p.y), c.max(p.x), d.max(p.y)),
    )
}

/// One placed copy: its outer loop and its holes, sampled.
pub struct Copy {
    /// The outer loop.
    pub outer: Vec<Point>,
    /// Its holes.
    pub holes: Vec<Vec<Point>>,
}

impl Copy {
    /// From the placed loops (outer first).
    pub fn new(loops: &[Vec<Segment>]) -> Copy {
        Copy {
            outer: sampled(&loops[0]),
            holes: loops[1..].iter().map(|l| sampled(l)).collect(),
        }
    }
    /// True when `p` is in this copy's material (inside the outer, in no hole).
    pub fn holds(&self, p: Point) -> bool {
        inside(&self.outer, p) && !self.holes.iter().any(|h| inside(h, p))
    }
}

/// True when a sampled point of `a`'s outline lies in `b`'s material more
/// than `slack` from its boundary (at spacing 0 the distances alone cannot
/// tell touching from crossing; a copy in a hole crossing the hole's edge
/// is caught here).
fn reaches_into(a: &Copy, b: &Copy, slack: f64) -> bool {
    let (x0, y0, x1, y1) = bounds(&b.outer);
    a.outer.iter().any(|&p| {
        p.x > x0
            && p.x < x1
            && p.y > y0
            && p.y < y1
            && b.holds(p)
            && std::iter::once(&b.outer)
                .chain(&b.holes)
                .all(|l| least_distance(&[p], l) > slack)
    })
}

/// Every pair of copies at least `spacing` apart (less `slack`) and none in
/// another's material; returns what is wrong, empty when all is well.
pub fn nest_faults(copies: &[Copy], spacing: f64, slack: f64) -> Vec<String> {
    let boxes: Vec<_> = copies.iter().map(|c| bounds(&c.outer)).collect();
    let mut faults = Vec::new();
    for i in 0..copies.len() {
        for j in i + 1..copies.len() {
            let (a, b) = (boxes[i], boxes[j]);
            if a.2 + spacing < b.0
                || b.2 + spacing < a.0
                || a.3 + spacing < b.1
                || b.3 + spacing < a.1
            {
                continue;
            }
            let (ci, cj) = (&copies[i], &copies[j]);
            // A copy in another's hole is measured against that hole too.
            let mut d = least_distance(&ci.outer, &cj.outer);
            for h in &cj.holes {
                d = d.min(least_distance(&ci.outer, h));
            }
            for h in &ci.holes {
                d = d.min(least_distance(&cj.outer, h));
            }
            if d < spacing - slack {
                faults.push(format!("copies {i} and {j} are {d:.3} mm apart"));
            }
            if reaches_into(ci, cj, slack) || reaches_into(cj, ci, slack) {
                faults.push(format!("copies {i} and {j} overlap"));
            }
        }
    }
    faults
}
