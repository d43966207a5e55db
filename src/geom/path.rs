//! Arcs cut into pieces, and measures of whole paths (area, length, box,
//! distance).

use super::{BBox, Point, Segment};

/// Lines needed for an arc of radius `r` and `sweep` radians so that the
/// chord error `r (1 − cos(θ/2))` stays under `chord` (paper 004's chord
/// formula), at least 1 and at most 4096.
pub fn flatten_count(r: f64, sweep: f64, chord: f64) -> usize {
    if !(r > chord && chord > 0.0) {
        return 1
            .max((sweep / std::f64::consts::FRAC_PI_2).ceil() as usize)
            .min(4096);
    }
    let step = 2.0 * (1.0 - chord / r).acos();
    ((sweep / step).ceil() as usize).clamp(1, 4096)
}

/// `s` as chords end to end: one for a line, [`flatten_count`]'s for an
/// arc within `chord`; the last ends exactly at `s.b`.
pub fn chords(s: &Segment, chord: f64) -> impl Iterator<Item = (Point, Point)> + '_ {
    let n = match s.arc_center() {
        Some((_, r)) => flatten_count(r, s.sweep().abs(), chord),
        None => 1,
    };
    (1..=n).scan(s.a, move |prev, k| {
        let q = if k == n {
            s.b
        } else {
            s.point_at(k as f64 / n as f64)
        };
        Some((std::mem::replace(prev, q), q))
    })
}

/// The points of a path of `segs` end to end, pushed onto `out`: each
/// segment's start, then along an arc the ends of [`chords`] within
/// `chord` but the last (the next segment's start, or the loop's first).
pub fn path_points<'a>(
    segs: impl IntoIterator<Item = &'a Segment>,
    chord: f64,
    out: &mut Vec<Point>,
) {
    for s in segs {
        out.push(s.a);
        if let Some((_, r)) = s.arc_center() {
            let n = flatten_count(r, s.sweep().abs(), chord);
            out.extend((1..n).map(|k| s.point_at(k as f64 / n as f64)));
        }
    }
}

/// True when direction `ang` lies strictly within the sweep that starts at
/// `start` and turns by `sweep` (signed), all in radians.
pub fn angle_in_sweep(start: f64, sweep: f64, ang: f64) -> bool {
    let tau = std::f64::consts::TAU;
    let d = if sweep >= 0.0 {
        (ang - start).rem_euclid(tau)
    } else {
        (start - ang).rem_euclid(tau)
    };
    d > 0.0 && d < sweep.abs()
}

/// Arcs from `center`, radius `r`, starting at angle `start` (radians) and
/// turning by `sweep` (signed, any size), split into pieces of at most 180°.
pub fn arc_pieces(center: Point, r: f64, start: f64, sweep: f64) -> Vec<Segment> {
    let n = (sweep.abs() / std::f64::consts::PI - 1e-9).ceil().max(1.0) as usize;
    let step = sweep / n as f64;
    let at = |ang: f64| Point::new(center.x + r * ang.cos(), center.y + r * ang.sin());
    let bulge = (step / 4.0).tan();
    (0..n)
        .map(|i| Segment {
            a: at(start + step * i as f64),
            b: at(start + step * (i + 1) as f64),
            bulge,
        })
        .collect()
}

/// Splits a bulge segment whose sweep exceeds 180° (|bulge| > 1, as DXF
/// allows) into two halves of equal sweep.
pub fn split_big_bulge(a: Point, b: Point, bulge: f64) -> Vec<Segment> {
    let seg = Segment { a, b, bulge };
    if bulge.abs() <= 1.0 {
        return vec![seg];
    }
    match seg.arc_center() {
        Some((c, r)) => {
            let v = a.sub(c);
            let mut pieces = arc_pieces(c, r, v.y.atan2(v.x), seg.sweep());
            // Keep the exact end points the file gave.
            if let Some(first) = pieces.first_mut() {
                first.a = a;
            }
            if let Some(last) = pieces.last_mut() {
                last.b = b;
            }
            pieces
        }
        None => vec![Segment::line(a, b)],
    }
}

/// Signed area of a closed loop of segments (> 0 counter-clockwise).
pub fn loop_area(segs: &[Segment]) -> f64 {
    segs.iter().map(Segment::area_term).sum()
}

/// Total length of a path.
pub fn path_length(segs: &[Segment]) -> f64 {
    segs.iter().map(Segment::length).sum()
}

/// Bounding box of a path.
pub fn path_bbox(segs: &[Segment]) -> BBox {
    let mut bb = BBox::EMPTY;
    for s in segs {
        bb.union(&s.bbox());
    }
    bb
}

/// A path's signed loop area, length and box in one pass: each exactly as
/// [`loop_area`], [`path_length`] and [`path_bbox`] give it (the same terms
/// summed in the same order), with one centre and one sweep per arc instead
/// of one per measure (issue 17: the contour stage measured each loop five
/// times over).
pub fn path_measure(segs: &[Segment]) -> (f64, f64, BBox) {
    // -0.0: where `Iterator::sum` of f64 starts.
    let (mut area, mut length, mut bb) = (-0.0, -0.0, BBox::EMPTY);
    for s in segs {
        let tri = 0.5 * s.a.cross(s.b);
        match s.arc_center() {
            Some((c, r)) => {
                let th = s.sweep();
                area += tri + 0.5 * r * r * (th - th.sin());
                length += r * th.abs();
                bb.union(&s.bbox_of_arc(Some((c, r, th))));
            }
            None => {
                area += tri;
                length += s.chord();
                bb.union(&s.bbox_of_arc(None));
            }
        }
    }
    (area, length, bb)
}

/// Unit tangents at the start and at the end of `s`: exactly
/// `(s.tangent_at(0.0), s.tangent_at(1.0))` (the same operations), with one
/// centre, start angle and sweep for both ends instead of one per call.
pub fn end_tangents(s: &Segment) -> (Point, Point) {
    match s.arc_center() {
        Some((c, r)) => {
            let a0 = s.a.sub(c);
            let (start, sweep) = (a0.y.atan2(a0.x), s.sweep());
            let tangent = |t: f64| {
                let ang = start + sweep * t;
                let at = Point::new(c.x + r * ang.cos(), c.y + r * ang.sin());
                s.travel_across(at.sub(c).unit())
            };
            (tangent(0.0), tangent(1.0))
        }
        None => {
            let d = s.b.sub(s.a).unit();
            (d, d)
        }
    }
}

/// Parameter of the point of `s` nearest `p`.
pub fn nearest_param(s: &Segment, p: Point) -> f64 {
    match s.arc_center() {
        None => {
            let d = s.b.sub(s.a);
            let len2 = d.dot(d);
            if len2 <= 0.0 {
                0.0
            } else {
                (p.sub(s.a).dot(d) / len2).clamp(0.0, 1.0)
            }
        }
        Some((c, _)) => {
            let a0 = s.a.sub(c);
            let v = p.sub(c);
            let sweep = s.sweep();
            let mut d = v.y.atan2(v.x) - a0.y.atan2(a0.x);
            // Bring the angle into the sweep's direction, in [0, 2π).
            d = if sweep >= 0.0 { d } else { -d }.rem_euclid(std::f64::consts::TAU);
            let t = d / sweep.abs().max(1e-12);
            if t <= 1.0 {
                t
            } else if p.dist(s.a) < p.dist(s.b) {
                0.0
            } else {
                1.0
            }
        }
    }
}

/// Distance from `p` to the segment.
pub fn dist_to_segment(p: Point, s: &Segment) -> f64 {
    SegmentDistance::new(s).to(p)
}

/// [`dist_to_segment`] from many points to one segment: an arc's centre,
/// radius and angles found once (the kerf check asks it at every sample of
/// a sheet's cuts). Bit for bit the same distances.
#[derive(Clone, Copy, Debug)]
pub struct SegmentDistance {
    a: Point,
    b: Point,
    /// An arc's centre, radius, start angle and sweep.
    arc: Option<(Point, f64, f64, f64)>,
}

impl SegmentDistance {
    /// Ready to measure from points to `s`.
    pub fn new(s: &Segment) -> SegmentDistance {
        SegmentDistance {
            a: s.a,
            b: s.b,
            arc: s.arc_angles(),
        }
    }

    /// For a straight segment, the square of [`Self::to`]'s distance
    /// from the same differences without its `hypot` (a few units in the
    /// last place apart: a filter that skips what is surely farther than a
    /// reach, not a distance); for an arc 0, which skips nothing.
    #[inline]
    pub fn to_sq_about(&self, p: Point) -> f64 {
        if self.arc.is_some() {
            return 0.0;
        }
        let d = self.b.sub(self.a);
        let len2 = d.dot(d);
        let v = if len2 == 0.0 {
            p.sub(self.a)
        } else {
            let t = (p.sub(self.a).dot(d) / len2).clamp(0.0, 1.0);
            p.sub(self.a.add(d.scale(t)))
        };
        v.dot(v)
    }

    /// Distance from `p` to the segment.
    #[inline]
    pub fn to(&self, p: Point) -> f64 {
        match self.arc {
            Some((c, r, start, sweep)) => {
                let v = p.sub(c);
                if angle_in_sweep(start, sweep, v.y.atan2(v.x)) {
                    (v.norm() - r).abs()
                } else {
                    p.dist(self.a).min(p.dist(self.b))
                }
            }
            None => {
                let d = self.b.sub(self.a);
                let len2 = d.dot(d);
                if len2 == 0.0 {
                    return p.dist(self.a);
                }
                let t = (p.sub(self.a).dot(d) / len2).clamp(0.0, 1.0);
                p.dist(self.a.add(d.scale(t)))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn approx(a: f64, b: f64, eps: f64) {
        assert!((a - b).abs() < eps, "{a} != {b}");
    }

    #[test]
    fn circle_area_is_exact_with_two_half_arcs() {
        let c = Point::new(3.0, -2.0);
        let segs = arc_pieces(c, 6.0, 0.3, 2.0 * PI);
        assert_eq!(segs.len(), 2);
        approx(loop_area(&segs), PI * 36.0, 1e-9);
        let rev: Vec<_> = segs.iter().rev().map(Segment::reversed).collect();
        approx(loop_area(&rev), -PI * 36.0, 1e-9);
        approx(path_length(&segs), 12.0 * PI, 1e-9);
    }

    #[test]
    fn big_bulge_is_split_into_arcs_of_at_most_half_a_turn() {
        // 270° arc: bulge = tan(270°/4).
        let b = (1.5 * PI / 4.0).tan();
        let pieces = split_big_bulge(Point::new(1.0, 0.0), Point::new(0.0, -1.0), b);
        assert_eq!(pieces.len(), 2);
        assert!(pieces.iter().all(|p| p.bulge.abs() <= 1.0));
        approx(path_length(&pieces), 1.5 * PI, 1e-9);
    }

    #[test]
    fn path_measure_and_end_tangents_are_bit_for_bit_the_plain_ones() {
        // Lines and arcs of every turn, both ways, and a degenerate arc.
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            x = crate::test_rng::Xorshift(x).next();
            (x % 20_000) as f64 / 100.0 - 100.0
        };
        for len in [0, 1, 2, 5, 40] {
            let mut segs: Vec<Segment> = (0..len)
                .map(|k| Segment {
                    a: Point::new(next(), next()),
                    b: Point::new(next(), next()),
                    bulge: if k % 3 == 0 { 0.0 } else { next() / 100.0 },
                })
                .collect();
            if len > 3 {
                segs[3].b = segs[3].a;
            }
            for s in &segs {
                let (t0, t1) = end_tangents(s);
                assert_eq!((t0, t1), (s.tangent_at(0.0), s.tangent_at(1.0)), "{s:?}");
            }
            let (area, length, bb) = path_measure(&segs);
            assert_eq!(area.to_bits(), loop_area(&segs).to_bits());
            assert_eq!(length.to_bits(), path_length(&segs).to_bits());
            assert_eq!(bb, path_bbox(&segs));
        }
    }

    #[test]
    fn the_squared_filter_is_the_distance_squared_on_lines_and_nothing_on_arcs() {
        // Checked against the plain formula: foot of the perpendicular,
        // clamped to the ends, by the point's own distances to them.
        let mut f = crate::test_rng::unit(0xD1B5_4A32_D192_ED03u64);
        let mut at = |scale: f64| Point::new(scale * (f() - 0.5), scale * (f() - 0.5));
        for k in 0..20_000 {
            let scale = [1e-3, 1.0, 2500.0, 1e5][k % 4];
            let (a, p) = (at(scale), at(scale));
            let b = if k % 97 == 0 { a } else { at(scale) };
            let line = Segment { a, b, bulge: 0.0 };
            let got = SegmentDistance::new(&line).to_sq_about(p);
            let (ab, ap) = (b.sub(a), p.sub(a));
            let t = if ab.dot(ab) == 0.0 { 0.0 } else { ap.dot(ab) / ab.dot(ab) };
            let want = if t <= 0.0 {
                ap.x.hypot(ap.y)
            } else if t >= 1.0 {
                (p.x - b.x).hypot(p.y - b.y)
            } else {
                ap.cross(ab).abs() / ab.x.hypot(ab.y)
            };
            let d = dist_to_segment(p, &line);
            assert!((got - d * d).abs() <= 1e-12 * d * d + 1e-300, "{got} vs {d}²");
            assert!((got.sqrt() - want).abs() <= 1e-9 * (scale + want), "{got} vs {want}²");
            // (An arc whose ends meet is measured as a point.)
            let arc = Segment { a, b, bulge: 0.4 };
            if a != b {
                assert_eq!(SegmentDistance::new(&arc).to_sq_about(p), 0.0);
            }
        }
    }

    #[test]
    fn distance_to_arc_outside_its_sweep_is_to_the_nearest_end() {
        let s = Segment {
            a: Point::new(1.0, 0.0),
            b: Point::new(-1.0, 0.0),
            bulge: 1.0,
        };
        approx(dist_to_segment(Point::new(0.0, 2.0), &s), 1.0, 1e-12);
        approx(
            dist_to_segment(Point::new(0.0, -2.0), &s),
            5f64.sqrt(),
            1e-12,
        );
    }
}
