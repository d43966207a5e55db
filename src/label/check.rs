//! An independent check of placed labels (not the placer's code): every
//! stroke of a label lies in its part's material — inside the outline,
//! outside every hole — at least `margin` from each of them.
//!
//! The outline is flattened far finer than the placer's (chords within
//! [`FINE`]), and each stroke's distance to each boundary piece is the
//! exact distance between two line segments; a stroke that keeps its
//! distance from every boundary and has one point in the material lies
//! wholly in it.

use crate::geom::{Point, Segment};

/// Chord of the check's flattening, mm: the measured distances are within
/// this of the true ones (a chord lies inside its arc).
pub const FINE: f64 = 1e-3;

fn polyline(segs: &[Segment]) -> Vec<Point> {
    let mut out = Vec::new();
    for s in segs {
        match s.arc_center() {
            Some((_, r)) => {
                let step = 2.0 * (1.0 - (FINE / r).min(1.0)).acos();
                let n = ((s.sweep().abs() / step.max(1e-6)).ceil() as usize).clamp(1, 100_000);
                out.extend((0..n).map(|i| s.point_at(i as f64 / n as f64)));
            }
            None => out.push(s.a),
        }
    }
    out
}

/// Winding number of closed polygon `poly` about `p` (non-zero: inside).
fn winding(poly: &[Point], p: Point) -> i32 {
    let mut w = 0;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
        if a.y <= p.y && b.y > p.y && side > 0.0 {
            w += 1;
        } else if a.y > p.y && b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

fn dist_point_seg(p: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 {
        0.0
    } else {
        (((p.x - a.x) * dx + (p.y - a.y) * dy) / len2).clamp(0.0, 1.0)
    };
    (p.x - a.x - t * dx).hypot(p.y - a.y - t * dy)
}

fn orient(a: Point, b: Point, c: Point) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

/// Exact distance between segments `p`–`q` and `a`–`b`.
fn dist_seg_seg(p: Point, q: Point, a: Point, b: Point) -> f64 {
    let (d1, d2) = (orient(a, b, p), orient(a, b, q));
    let (d3, d4) = (orient(p, q, a), orient(p, q, b));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return 0.0; // proper crossing
    }
    dist_point_seg(p, a, b)
        .min(dist_point_seg(q, a, b))
        .min(dist_point_seg(a, p, q))
        .min(dist_point_seg(b, p, q))
}

/// Least clearance of `strokes` (polylines) from the outline `outer` and
/// the `holes`, mm; negative when a stroke point lies outside the
/// material. The true clearance is at least this less [`FINE`].
pub fn clearance(outer: &[Segment], holes: &[Vec<Segment>], strokes: &[Vec<Point>]) -> f64 {
    let outer = polyline(outer);
    let holes: Vec<Vec<Point>> = holes.iter().map(|h| polyline(h)).collect();
    let mut least = f64::INFINITY;
    for s in strokes {
        let Some(&first) = s.first() else { continue };
        if winding(&outer, first) == 0 || holes.iter().any(|h| winding(h, first) != 0) {
            return -1.0;
        }
        let pieces: Vec<(Point, Point)> = if s.len() == 1 {
            vec![(first, first)]
        } else {
            s.windows(2).map(|w| (w[0], w[1])).collect()
        };
        for poly in std::iter::once(&outer).chain(&holes) {
            for i in 0..poly.len() {
                let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
                for &(p, q) in &pieces {
                    least = least.min(dist_seg_seg(p, q, a, b));
                }
            }
        }
    }
    least
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stroke_outside_or_too_near_is_caught() {
        let p = Point::new;
        let c = [p(0.0, 0.0), p(20.0, 0.0), p(20.0, 10.0), p(0.0, 10.0)];
        let outer: Vec<Segment> = (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4])).collect();
        // A round hole of radius 2 at (15, 5): two half arcs.
        let hole = vec![
            Segment { a: p(13.0, 5.0), b: p(17.0, 5.0), bulge: 1.0 },
            Segment { a: p(17.0, 5.0), b: p(13.0, 5.0), bulge: 1.0 },
        ];
        let holes = [hole];
        // 2 mm from the left edge.
        let ok = clearance(&outer, &holes, &[vec![p(2.0, 5.0), p(8.0, 5.0)]]);
        assert!((ok - 2.0).abs() < FINE, "{ok}");
        // Ending 1 mm from the hole's edge (x = 13).
        let near = clearance(&outer, &holes, &[vec![p(4.0, 5.0), p(12.0, 5.0)]]);
        assert!((near - 1.0).abs() < FINE, "{near}");
        // Across the hole, or outside the part.
        assert_eq!(clearance(&outer, &holes, &[vec![p(2.0, 5.0), p(18.0, 5.0)]]), 0.0);
        assert!(clearance(&outer, &holes, &[vec![p(15.0, 5.0), p(15.5, 5.0)]]) < 0.0);
        assert!(clearance(&outer, &holes, &[vec![p(25.0, 5.0), p(26.0, 5.0)]]) < 0.0);
    }
}
