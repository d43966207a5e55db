//! The collision model of a part: a polygon that is never smaller than the
//! part grown by half the spacing, and larger by at most the tolerance.
//!
//! Two parts grown by `spacing / 2` each that do not overlap are at least
//! `spacing` apart (the Minkowski sum with a disc, as in the "offset"
//! treatment of spacing in the nesting literature, e.g. Bennell & Oliveira,
//! "The geometry of nesting problems", EJOR 2008, §2). The growth is done on
//! the true outline with arcs (cavalier_contours, the offset the kerf stage
//! uses), so corners grow round and the error is in one place only: turning
//! arcs into lines.
//!
//! Arcs into lines, conservatively: where the part's inside is inside the
//! arc's circle (a convex arc of a counter-clockwise outline), the lines are
//! the circle's *circumscribed* polygon (tangents meeting at r / cos(θ/2),
//! all outside the circle); where the inside is outside the circle (a
//! concave arc), the lines are chords (inside the circle, so outside the
//! part). Either way the polygon holds the part, and the largest gap between
//! the two, `r (1 / cos(θ/2) − 1)` or `r (1 − cos(θ/2))`, is kept under the
//! tolerance by the step θ.

use cavalier_contours::polyline::{
    PlineCreation, PlineOffsetOptions, PlineSource, PlineSourceMut, Polyline,
};

use crate::geom::{loop_area, BBox, Point, Segment};

/// A closed polygon, counter-clockwise, first vertex not repeated.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    /// Vertices.
    pub pts: Vec<Point>,
    /// Their box.
    pub bbox: BBox,
}

impl Polygon {
    /// A polygon from its vertices (turned counter-clockwise if need be).
    pub fn new(mut pts: Vec<Point>) -> Polygon {
        if pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
        if signed_area(&pts) < 0.0 {
            pts.reverse();
        }
        let mut bbox = BBox::EMPTY;
        for &p in &pts {
            bbox.add(p);
        }
        Polygon { pts, bbox }
    }
    /// The area, mm².
    pub fn area(&self) -> f64 {
        signed_area(&self.pts).abs()
    }
    /// The image under `p → rot·mirror(p) + t`, mirror being x → −x.
    pub fn placed(&self, rot_deg: f64, mirror: bool, t: Point) -> Polygon {
        let (s, c) = rot_deg.to_radians().sin_cos();
        let pts = self
            .pts
            .iter()
            .map(|p| {
                let x = if mirror { -p.x } else { p.x };
                Point::new(c * x - s * p.y + t.x, s * x + c * p.y + t.y)
            })
            .collect();
        Polygon::new(pts)
    }
    /// The same polygon moved by `t`.
    pub fn moved(&self, t: Point) -> Polygon {
        Polygon {
            pts: self.pts.iter().map(|p| p.add(t)).collect(),
            bbox: BBox {
                min: self.bbox.min.add(t),
                max: self.bbox.max.add(t),
            },
        }
    }
}

/// Shoelace area of a vertex loop (> 0 counter-clockwise).
pub fn signed_area(pts: &[Point]) -> f64 {
    let n = pts.len();
    (0..n).map(|i| pts[i].cross(pts[(i + 1) % n])).sum::<f64>() / 2.0
}

/// The collision polygon of a closed outline: the outline grown by `grow`
/// mm (≥ 0), arcs replaced by lines outside the grown outline, within
/// `tol` mm of it. None when the outline has no area.
pub fn collision_polygon(outline: &[Segment], grow: f64, tol: f64) -> Option<Polygon> {
    offset_polygon(outline, -grow.max(0.0), true, tol)
}

/// The room inside a closed outline (a hole a part may sit in, an
/// irregular sheet): the outline shrunk by `shrink` mm (grown when < 0),
/// arcs replaced by lines *inside* the shrunk outline, within `tol` mm of
/// it, so a shape inside the polygon is inside the true room. When the
/// shrunk outline splits, the largest piece (the others are room lost, on
/// the safe side). None when nothing is left.
pub fn room_polygon(outline: &[Segment], shrink: f64, tol: f64) -> Option<Polygon> {
    offset_polygon(outline, shrink, false, tol)
}

/// `outline` made counter-clockwise, offset by `inward` mm (cavalier
/// contours: a positive offset goes left of a counter-clockwise loop, i.e.
/// inwards), arcs flattened on the `outside` (or inside) of the result.
fn offset_polygon(outline: &[Segment], inward: f64, outside: bool, tol: f64) -> Option<Polygon> {
    let mut segs = outline.to_vec();
    let area = loop_area(&segs);
    if area == 0.0 || area.is_nan() || !inward.is_finite() {
        return None;
    }
    if area < 0.0 {
        segs = segs.iter().rev().map(Segment::reversed).collect();
    }
    if inward != 0.0 {
        let mut pl = Polyline::with_capacity(segs.len(), true);
        for s in &segs {
            pl.add(s.a.x, s.a.y, s.bulge);
        }
        let pl = pl.remove_repeat_pos(1e-9).unwrap_or(pl);
        let options = PlineOffsetOptions {
            pos_equal_eps: (tol * 1e-3).min(1e-5),
            ..Default::default()
        };
        // An outward offset of a simple loop is one loop; an inward one may
        // split: keep the largest.
        let grown = pl
            .parallel_offset_opt(inward, &options)
            .into_iter()
            .filter(|p| p.area() > 0.0)
            .max_by(|a, b| a.area().abs().total_cmp(&b.area().abs()))?;
        let n = grown.vertex_count();
        segs = (0..n)
            .map(|i| {
                let v = grown.at(i);
                let w = grown.at((i + 1) % n);
                Segment {
                    a: Point::new(v.x, v.y),
                    b: Point::new(w.x, w.y),
                    bulge: v.bulge,
                }
            })
            .collect();
        if loop_area(&segs) < 0.0 {
            segs = segs.iter().rev().map(Segment::reversed).collect();
        }
    }
    let mut pts = Vec::with_capacity(segs.len() * 2);
    for s in &segs {
        pts.push(s.a);
        let Some((c, r)) = s.arc_center() else {
            continue;
        };
        let sweep = s.sweep();
        let a0 = {
            let v = s.a.sub(c);
            v.y.atan2(v.x)
        };
        let at = |ang: f64, rr: f64| Point::new(c.x + rr * ang.cos(), c.y + rr * ang.sin());
        // A counter-clockwise arc (sweep > 0) has the loop's inside on its
        // circle's side. Lines meant to stay outside the loop circumscribe
        // such an arc and chord a clockwise one; lines meant to stay inside
        // do the opposite.
        if (sweep > 0.0) == outside {
            // Circumscribed lines, step θ with r (1/cos(θ/2) − 1) ≤ tol.
            let step = if tol < r {
                2.0 * (r / (r + tol)).acos()
            } else {
                std::f64::consts::FRAC_PI_2
            };
            let n = ((sweep.abs() / step).ceil() as usize).clamp(1, 4096);
            let th = sweep / n as f64;
            let rr = r / (th / 2.0).cos();
            for k in 0..n {
                pts.push(at(a0 + th * (k as f64 + 0.5), rr));
            }
        } else {
            // Chords, step θ with r (1 − cos(θ/2)) ≤ tol.
            let n = crate::geom::flatten_count(r, sweep.abs(), tol);
            let th = sweep / n as f64;
            for k in 1..n {
                pts.push(at(a0 + th * k as f64, r));
            }
        }
    }
    dedup(&mut pts, tol * 1e-3);
    (pts.len() >= 3).then(|| Polygon::new(pts))
}

/// Drops consecutive vertices closer than `eps`.
fn dedup(pts: &mut Vec<Point>, eps: f64) {
    pts.dedup_by(|b, a| a.dist(*b) <= eps);
    while pts.len() > 1 && pts[0].dist(pts[pts.len() - 1]) <= eps {
        pts.pop();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::arc_pieces;
    use std::f64::consts::PI;

    fn circle(r: f64) -> Vec<Segment> {
        arc_pieces(Point::default(), r, 0.0, 2.0 * PI)
    }

    #[test]
    fn a_circle_becomes_a_polygon_around_it_within_the_tolerance() {
        let p = collision_polygon(&circle(50.0), 0.0, 0.1).unwrap();
        for v in &p.pts {
            let d = v.norm();
            assert!((50.0 - 1e-9..=50.1 + 1e-9).contains(&d), "{d}");
        }
        // Every edge stays outside the circle: its midpoint's distance ≥ r.
        for i in 0..p.pts.len() {
            let m = p.pts[i].add(p.pts[(i + 1) % p.pts.len()]).scale(0.5);
            assert!(m.norm() >= 50.0 - 1e-9);
        }
        assert!(p.area() > PI * 2500.0);
    }

    #[test]
    fn a_concave_arc_is_chorded_inside_its_circle() {
        // A 100×100 square with a half-circle bite of r = 20 from the top edge.
        let mut segs = vec![
            Segment::line(Point::new(0.0, 0.0), Point::new(100.0, 0.0)),
            Segment::line(Point::new(100.0, 0.0), Point::new(100.0, 100.0)),
            Segment::line(Point::new(100.0, 100.0), Point::new(70.0, 100.0)),
        ];
        // From (70,100) to (30,100) dipping down to y = 80: clockwise.
        segs.push(Segment {
            a: Point::new(70.0, 100.0),
            b: Point::new(30.0, 100.0),
            bulge: -1.0,
        });
        segs.push(Segment::line(
            Point::new(30.0, 100.0),
            Point::new(0.0, 100.0),
        ));
        segs.push(Segment::line(Point::new(0.0, 100.0), Point::new(0.0, 0.0)));
        let p = collision_polygon(&segs, 0.0, 0.05).unwrap();
        let exact = 10_000.0 - PI * 200.0;
        assert!(
            p.area() >= exact && p.area() < exact + 0.05 * 200.0,
            "{}",
            p.area()
        );
        for v in &p.pts {
            if v.y > 79.0 && v.x > 30.5 && v.x < 69.5 {
                assert!((v.dist(Point::new(50.0, 100.0)) - 20.0).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn growing_a_square_by_two_gives_round_corners_held_from_outside() {
        let sq = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
        let segs: Vec<Segment> = (0..4)
            .map(|i| {
                let (a, b) = (sq[i], sq[(i + 1) % 4]);
                Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1))
            })
            .collect();
        let p = collision_polygon(&segs, 2.0, 0.01).unwrap();
        let exact = 100.0 + 4.0 * 20.0 + PI * 4.0;
        assert!(
            p.area() >= exact && p.area() < exact + 0.01 * 60.0,
            "{}",
            p.area()
        );
        assert!((p.bbox.min.x + 2.0).abs() < 1e-9 && (p.bbox.max.y - 12.0).abs() < 1e-9);
    }

    #[test]
    fn the_room_in_a_round_hole_is_a_polygon_inside_the_shrunk_circle() {
        let p = room_polygon(&circle(50.0), 2.0, 0.1).unwrap();
        for i in 0..p.pts.len() {
            let (a, b) = (p.pts[i], p.pts[(i + 1) % p.pts.len()]);
            assert!(a.norm() <= 48.0 + 1e-9 && a.norm() >= 47.9 - 1e-9);
            assert!(a.add(b).scale(0.5).norm() <= 48.0);
        }
        assert!(p.area() < PI * 48.0 * 48.0);
        // Nothing left of a hole smaller than the shrink.
        assert!(room_polygon(&circle(1.0), 2.0, 0.1).is_none());
    }

    #[test]
    fn placing_turns_mirrors_and_moves() {
        let p = Polygon::new(vec![
            Point::new(0.0, 0.0),
            Point::new(2.0, 0.0),
            Point::new(0.0, 1.0),
        ]);
        let q = p.placed(90.0, false, Point::new(10.0, 0.0));
        assert!((q.bbox.min.x - 9.0).abs() < 1e-12 && (q.bbox.max.y - 2.0).abs() < 1e-12);
        let m = p.placed(0.0, true, Point::default());
        assert!((m.bbox.min.x + 2.0).abs() < 1e-12 && signed_area(&m.pts) > 0.0);
    }
}
