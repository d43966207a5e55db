//! Containment depth of closed contours.
//!
//! Paper 000 takes the largest contour as the outer and all others as holes;
//! a sheet of many parts needs more: a contour's depth is the number of closed
//! contours that contain it. Even depth = outer boundary of a part, odd = hole.
//!
//! Containment is tested with a point of the inner contour that is not on the
//! outer one's boundary, by exact even-odd crossing with arcs: an arc's region
//! is its chord's polygon XOR its circular segment.

use super::{Contour, ContourKind};
use crate::geom::{dist_to_segment, Point, Segment, Tolerance};
use crate::warning::Warning;

/// Even-odd inside test of `p` against a closed loop of lines and arcs.
pub fn point_in_loop(p: Point, segs: &[Segment]) -> bool {
    let mut inside = false;
    for s in segs {
        let (a, b) = (s.a, s.b);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if x > p.x {
                inside = !inside;
            }
        }
        if let Some((c, r)) = s.arc_center() {
            // Inside the circular segment between chord and arc?
            let chord = b.sub(a);
            let mid = s.point_at(0.5);
            let side_p = chord.cross(p.sub(a));
            let side_m = chord.cross(mid.sub(a));
            if p.dist(c) < r && side_p * side_m > 0.0 {
                inside = !inside;
            }
        }
    }
    inside
}

/// A point of `inner` farther than `tol` from `outer`'s boundary, if any.
fn probe(inner: &[Segment], outer: &[Segment], tol: f64) -> Option<Point> {
    let candidates = inner.iter().map(|s| s.point_at(0.5)).chain(inner.iter().map(|s| s.a));
    candidates.take(64).find(|&q| outer.iter().all(|s| dist_to_segment(q, s) > tol))
}

/// Sets depth, parent and kind (outer/hole) of the closed contours.
pub fn classify(contours: &mut [Contour], tol: Tolerance, warnings: &mut Vec<Warning>) {
    let t = tol.mm();
    // Larger first: only a larger contour can contain a smaller one.
    let mut order: Vec<usize> = (0..contours.len()).filter(|&i| contours[i].kind != ContourKind::Open).collect();
    order.sort_by(|&i, &j| contours[j].area.abs().total_cmp(&contours[i].area.abs()).then(i.cmp(&j)));
    let mut depth = vec![0usize; contours.len()];
    let mut parent: Vec<Option<usize>> = vec![None; contours.len()];
    for (rank, &i) in order.iter().enumerate() {
        for &j in &order[..rank] {
            let (ci, cj) = (&contours[i], &contours[j]);
            if !cj.bbox.contains_box(&ci.bbox, t) {
                continue;
            }
            match probe(&ci.segments, &cj.segments, t) {
                Some(q) => {
                    if point_in_loop(q, &cj.segments) {
                        depth[i] += 1;
                        // `order` is by decreasing area: the last container found is the smallest.
                        parent[i] = Some(j);
                    }
                }
                None => {
                    if (ci.area.abs() - cj.area.abs()).abs() <= t * ci.length {
                        warnings.push(Warning::at("contour drawn twice: the copy is cut as a separate contour", ci.start()));
                    }
                }
            }
        }
    }
    for &i in &order {
        contours[i].depth = depth[i];
        contours[i].parent = parent[i];
        contours[i].kind = if depth[i] % 2 == 0 { ContourKind::Outer } else { ContourKind::Hole };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::arc_pieces;

    #[test]
    fn point_in_circle_made_of_two_arcs() {
        let c = arc_pieces(Point::new(0.0, 0.0), 10.0, 0.0, std::f64::consts::TAU);
        assert!(point_in_loop(Point::new(9.9, 0.5), &c));
        assert!(point_in_loop(Point::new(0.0, -9.0), &c));
        assert!(!point_in_loop(Point::new(7.2, 7.2), &c));
        assert!(!point_in_loop(Point::new(-11.0, 0.0), &c));
        let rev: Vec<_> = c.iter().rev().map(Segment::reversed).collect();
        assert!(point_in_loop(Point::new(0.0, 9.5), &rev));
    }
}
