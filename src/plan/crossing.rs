//! Where a straight move meets a drawn segment, and how near it comes:
//! the geometry the clearance index ([`super::clearance`]) answers with.

use crate::geom::{dist_to_segment, Point, Segment};

/// Exact distance between the line segment `l` and the segment `s` (line
/// or arc): zero where they meet; otherwise the least of the four
/// end-to-other distances and, for an arc, the circle point facing the
/// line when both feet fall inside.
pub fn line_to_segment(l: &Segment, s: &Segment) -> f64 {
    if !crossings(l, s).is_empty() {
        return 0.0;
    }
    let ends = dist_to_segment(l.a, s)
        .min(dist_to_segment(l.b, s))
        .min(dist_to_segment(s.a, l))
        .min(dist_to_segment(s.b, l));
    let Some((c, r)) = s.arc_center() else {
        return ends;
    };
    let d = l.b.sub(l.a);
    let len2 = d.dot(d);
    if len2 <= 0.0 {
        return ends;
    }
    let t = c.sub(l.a).dot(d) / len2;
    if !(0.0..=1.0).contains(&t) {
        return ends;
    }
    let foot = l.a.add(d.scale(t));
    let h = foot.dist(c);
    if h <= r || h == 0.0 {
        // The line meets the circle but not the arc: an end is nearest.
        return ends;
    }
    let toward = c.add(foot.sub(c).scale(r / h));
    let a0 = s.a.sub(c);
    let v = toward.sub(c);
    if crate::geom::angle_in_sweep(a0.y.atan2(a0.x), s.sweep(), v.y.atan2(v.x)) {
        ends.min(h - r)
    } else {
        ends
    }
}

/// Up to two points where a line segment meets a segment ([`crossings`]):
/// held in place, not in a vector (a lead checked against its own
/// contour meets it at its start, and each such meeting was an allocation,
/// two or more per lead on a 137k-contour sheet).
#[derive(Clone, Copy, Debug, Default)]
pub struct Meets {
    pts: [Point; 2],
    n: usize,
}

impl Meets {
    fn push(&mut self, p: Point) {
        if let Some(slot) = self.pts.get_mut(self.n) {
            *slot = p;
            self.n += 1;
        }
    }
    /// How many points.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.n
    }
    /// True when the two do not meet.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }
    /// The points.
    pub fn iter(&self) -> impl Iterator<Item = Point> + '_ {
        self.pts[..self.n].iter().copied()
    }
}

/// Points where the line segment `l` meets segment `s` (line or arc).
pub fn crossings(l: &Segment, s: &Segment) -> Meets {
    let mut out = Meets::default();
    let d = l.b.sub(l.a);
    match s.arc_center() {
        None => {
            let e = s.b.sub(s.a);
            let den = d.cross(e);
            let w = s.a.sub(l.a);
            if den.abs() < 1e-12 * (d.norm() * e.norm()).max(1e-300) {
                // Parallel: touching only if collinear and overlapping.
                if w.cross(d).abs() > 1e-9 * d.norm().max(1.0) {
                    return out;
                }
                let len2 = d.dot(d).max(1e-300);
                let (t0, t1) = (w.dot(d) / len2, s.b.sub(l.a).dot(d) / len2);
                let (lo, hi) = (t0.min(t1).max(0.0), t0.max(t1).min(1.0));
                if lo <= hi {
                    out.push(l.point_at(lo));
                    out.push(l.point_at(hi));
                }
                return out;
            }
            let t = w.cross(e) / den;
            let u = w.cross(d) / den;
            if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
                out.push(l.point_at(t));
            }
            out
        }
        Some((c, r)) => {
            // |a + t d - c|² = r²
            let f = l.a.sub(c);
            let (qa, qb, qc) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - r * r);
            if qa <= 0.0 {
                return out;
            }
            let disc = qb * qb - 4.0 * qa * qc;
            if disc < 0.0 {
                return out;
            }
            let sq = disc.sqrt();
            // The start angle only once a root lies on the line (most
            // segments near a lead miss its circle's chord span).
            let mut start = None;
            for t in [(-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)] {
                if !(0.0..=1.0).contains(&t) {
                    continue;
                }
                let x = l.point_at(t);
                // Inclusive of the arc's ends (a lead touching an arc's end touches it).
                let start = *start.get_or_insert_with(|| {
                    let a0 = s.a.sub(c);
                    a0.y.atan2(a0.x)
                });
                let v = x.sub(c);
                let sweep = s.sweep();
                let ang = v.y.atan2(v.x);
                let d = if sweep >= 0.0 {
                    ang - start
                } else {
                    start - ang
                }
                .rem_euclid(std::f64::consts::TAU);
                if d <= sweep.abs() + 1e-9 || d >= std::f64::consts::TAU - 1e-9 {
                    out.push(x);
                }
            }
            out
        }
    }
}
