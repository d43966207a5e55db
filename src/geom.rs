//! The geometry every stage speaks: points, and segments that are either a
//! straight line or a circular arc, in millimetres with Y up.
//!
//! A segment is stored the way DXF's LWPOLYLINE (group code 42) and
//! cavalier_contours store it: two end points and a *bulge*
//! `b = tan(sweep / 4)`, positive for a counter-clockwise arc, 0 for a line.
//! Every stage keeps `|b| <= 1` (sweep at most 180°), so no arc is ever a
//! full circle and G2/G3 blocks are never ambiguous.

use serde::Serialize;

/// A point (or vector) in millimetres.
#[derive(Clone, Copy, Debug, PartialEq, Default, Serialize)]
pub struct Point {
    /// X in mm.
    pub x: f64,
    /// Y in mm (up).
    pub y: f64,
}

// Inherent vector helpers rather than operator traits: they read as the formulas they implement.
#[allow(clippy::should_implement_trait)]
impl Point {
    /// A point from its coordinates.
    pub const fn new(x: f64, y: f64) -> Self {
        Point { x, y }
    }
    /// Vector sum.
    pub fn add(self, o: Point) -> Point {
        Point::new(self.x + o.x, self.y + o.y)
    }
    /// Vector difference `self - o`.
    pub fn sub(self, o: Point) -> Point {
        Point::new(self.x - o.x, self.y - o.y)
    }
    /// Scaled vector.
    pub fn scale(self, k: f64) -> Point {
        Point::new(self.x * k, self.y * k)
    }
    /// Dot product.
    pub fn dot(self, o: Point) -> f64 {
        self.x * o.x + self.y * o.y
    }
    /// 2-D cross product (z of the 3-D one): > 0 when `o` turns left of `self`.
    pub fn cross(self, o: Point) -> f64 {
        self.x * o.y - self.y * o.x
    }
    /// Euclidean length.
    pub fn norm(self) -> f64 {
        self.x.hypot(self.y)
    }
    /// Distance to another point.
    pub fn dist(self, o: Point) -> f64 {
        self.sub(o).norm()
    }
    /// Unit vector, or zero for a zero vector.
    pub fn unit(self) -> Point {
        let n = self.norm();
        if n > 0.0 {
            self.scale(1.0 / n)
        } else {
            Point::default()
        }
    }
    /// The vector turned 90° counter-clockwise.
    pub fn perp(self) -> Point {
        Point::new(-self.y, self.x)
    }
    /// True when both coordinates are finite.
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
    /// As `[x, y]`, for reports.
    pub fn xy(self) -> [f64; 2] {
        [self.x, self.y]
    }
}

/// The one geometric tolerance, in mm: two points closer than this are the
/// same point (paper 000 uses 1e-4 mm against a 1e-3 mm NC resolution; our
/// default is the NC resolution itself).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance(pub f64);

impl Tolerance {
    /// 0.001 mm.
    pub const DEFAULT: Tolerance = Tolerance(1e-3);
    /// The distance in mm.
    pub fn mm(self) -> f64 {
        self.0
    }
}

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BBox {
    /// Lower-left corner.
    pub min: Point,
    /// Upper-right corner.
    pub max: Point,
}

impl Default for BBox {
    fn default() -> Self {
        BBox::EMPTY
    }
}

impl BBox {
    /// The empty box (adding any point makes it that point).
    pub const EMPTY: BBox = BBox {
        min: Point::new(f64::INFINITY, f64::INFINITY),
        max: Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
    };
    /// Grows the box to hold `p`.
    pub fn add(&mut self, p: Point) {
        self.min.x = self.min.x.min(p.x);
        self.min.y = self.min.y.min(p.y);
        self.max.x = self.max.x.max(p.x);
        self.max.y = self.max.y.max(p.y);
    }
    /// Grows the box to hold another box.
    pub fn union(&mut self, o: &BBox) {
        if !o.is_empty() {
            self.add(o.min);
            self.add(o.max);
        }
    }
    /// True when nothing was added.
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x
    }
    /// True when `o` lies inside this box grown by `eps`.
    pub fn contains_box(&self, o: &BBox, eps: f64) -> bool {
        o.min.x >= self.min.x - eps
            && o.min.y >= self.min.y - eps
            && o.max.x <= self.max.x + eps
            && o.max.y <= self.max.y + eps
    }
    /// The box of one point.
    pub fn at(p: Point) -> BBox {
        BBox { min: p, max: p }
    }
    /// True when the boxes meet once this one is grown by `eps` (an
    /// empty box meets nothing).
    pub fn overlaps(&self, o: &BBox, eps: f64) -> bool {
        o.max.x >= self.min.x - eps
            && o.min.x <= self.max.x + eps
            && o.max.y >= self.min.y - eps
            && o.min.y <= self.max.y + eps
    }
    /// As `[x0, y0, x1, y1]`, for reports.
    pub fn to_array(&self) -> [f64; 4] {
        [self.min.x, self.min.y, self.max.x, self.max.y]
    }
}

/// A line (`bulge == 0`) or a circular arc from `a` to `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// Start point.
    pub a: Point,
    /// End point.
    pub b: Point,
    /// `tan(sweep/4)`: 0 for a line, > 0 counter-clockwise, < 0 clockwise; `|bulge| <= 1`.
    pub bulge: f64,
}

/// Below this |bulge| an arc is treated as a line: the sagitta of a 10 m chord is then under 1e-9 mm.
const LINE_BULGE: f64 = 1e-12;

impl Segment {
    /// A straight line.
    pub fn line(a: Point, b: Point) -> Self {
        Segment { a, b, bulge: 0.0 }
    }
    /// True for a straight line.
    pub fn is_line(&self) -> bool {
        self.bulge.abs() < LINE_BULGE
    }
    /// True for a counter-clockwise arc.
    pub fn is_ccw(&self) -> bool {
        self.bulge > 0.0
    }
    /// Chord length.
    pub fn chord(&self) -> f64 {
        self.a.dist(self.b)
    }
    /// Signed sweep angle in radians (0 for a line).
    pub fn sweep(&self) -> f64 {
        4.0 * self.bulge.atan()
    }
    /// Centre and radius of an arc (None for a line).
    ///
    /// With chord `d` and bulge `b`, the centre sits on the chord's normal at
    /// `h = d (1 - b²) / (4 b)` from its midpoint, on the left for b > 0.
    pub fn arc_center(&self) -> Option<(Point, f64)> {
        if self.is_line() {
            return None;
        }
        let c = self.b.sub(self.a);
        let d = c.norm();
        if d == 0.0 {
            return None;
        }
        let b = self.bulge;
        let mid = self.a.add(c.scale(0.5));
        let h = d * (1.0 - b * b) / (4.0 * b);
        let center = mid.add(c.perp().scale(h / d));
        let r = d * (1.0 + b * b) / (4.0 * b.abs());
        Some((center, r))
    }
    /// Path length.
    pub fn length(&self) -> f64 {
        match self.arc_center() {
            Some((_, r)) => r * self.sweep().abs(),
            None => self.chord(),
        }
    }
    /// The same segment travelled the other way.
    pub fn reversed(&self) -> Segment {
        Segment {
            a: self.b,
            b: self.a,
            bulge: -self.bulge,
        }
    }
    /// Point at parameter `t` in [0, 1] along the segment.
    pub fn point_at(&self, t: f64) -> Point {
        match self.arc_center() {
            Some((c, r)) => {
                let a0 = self.a.sub(c);
                let ang = a0.y.atan2(a0.x) + self.sweep() * t;
                Point::new(c.x + r * ang.cos(), c.y + r * ang.sin())
            }
            None => self.a.add(self.b.sub(self.a).scale(t)),
        }
    }
    /// Unit tangent (direction of travel) at parameter `t`.
    pub fn tangent_at(&self, t: f64) -> Point {
        match self.arc_center() {
            Some((c, _)) => {
                let radial = self.point_at(t).sub(c).unit();
                if self.is_ccw() {
                    radial.perp()
                } else {
                    radial.perp().scale(-1.0)
                }
            }
            None => self.b.sub(self.a).unit(),
        }
    }
    /// This segment's term of the signed area of a closed loop: the shoelace
    /// term of its chord plus, for an arc, the exact circular-segment area
    /// `r²/2 (θ - sin θ)` (paper 000 approximates it with triangles; we do not).
    pub fn area_term(&self) -> f64 {
        let tri = 0.5 * self.a.cross(self.b);
        match self.arc_center() {
            Some((_, r)) => {
                let th = self.sweep();
                tri + 0.5 * r * r * (th - th.sin())
            }
            None => tri,
        }
    }
    /// Exact bounding box (arc extremes included).
    pub fn bbox(&self) -> BBox {
        let mut bb = BBox::EMPTY;
        bb.add(self.a);
        bb.add(self.b);
        if let Some((c, r)) = self.arc_center() {
            let start = {
                let v = self.a.sub(c);
                v.y.atan2(v.x)
            };
            let sweep = self.sweep();
            for k in 0..4 {
                let ang = k as f64 * std::f64::consts::FRAC_PI_2;
                if angle_in_sweep(start, sweep, ang) {
                    bb.add(Point::new(c.x + r * ang.cos(), c.y + r * ang.sin()));
                }
            }
        }
        bb
    }
    /// True when every number is finite.
    pub fn is_finite(&self) -> bool {
        self.a.is_finite() && self.b.is_finite() && self.bulge.is_finite()
    }
}

/// A 2-D affine map `p' = [a b; d e]·p + [c; f]`: units scaling, block
/// inserts (translate, rotate, scale, mirror) and OCS mirroring.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine {
    /// Row 1: x' = a x + b y + c.
    pub a: f64,
    /// See `a`.
    pub b: f64,
    /// See `a`.
    pub c: f64,
    /// Row 2: y' = d x + e y + f.
    pub d: f64,
    /// See `d`.
    pub e: f64,
    /// See `d`.
    pub f: f64,
}

impl Affine {
    /// The identity.
    pub const IDENTITY: Affine = Affine {
        a: 1.0,
        b: 0.0,
        c: 0.0,
        d: 0.0,
        e: 1.0,
        f: 0.0,
    };
    /// Uniform scaling about the origin.
    pub fn scale(k: f64) -> Affine {
        Affine::scale_xy(k, k)
    }
    /// Scaling by `sx`, `sy` about the origin (negative = mirror).
    pub fn scale_xy(sx: f64, sy: f64) -> Affine {
        Affine {
            a: sx,
            b: 0.0,
            c: 0.0,
            d: 0.0,
            e: sy,
            f: 0.0,
        }
    }
    /// Translation.
    pub fn translate(x: f64, y: f64) -> Affine {
        Affine {
            a: 1.0,
            b: 0.0,
            c: x,
            d: 0.0,
            e: 1.0,
            f: y,
        }
    }
    /// Counter-clockwise rotation by `deg` degrees about the origin.
    pub fn rotate_deg(deg: f64) -> Affine {
        let (s, c) = deg.to_radians().sin_cos();
        Affine {
            a: c,
            b: -s,
            c: 0.0,
            d: s,
            e: c,
            f: 0.0,
        }
    }
    /// `self ∘ o`: apply `o` first, then `self`.
    pub fn then_after(&self, o: &Affine) -> Affine {
        Affine {
            a: self.a * o.a + self.b * o.d,
            b: self.a * o.b + self.b * o.e,
            c: self.a * o.c + self.b * o.f + self.c,
            d: self.d * o.a + self.e * o.d,
            e: self.d * o.b + self.e * o.e,
            f: self.d * o.c + self.e * o.f + self.f,
        }
    }
    /// The image of a point.
    pub fn apply(&self, p: Point) -> Point {
        Point::new(
            self.a * p.x + self.b * p.y + self.c,
            self.d * p.x + self.e * p.y + self.f,
        )
    }
    /// Determinant (< 0 mirrors).
    pub fn det(&self) -> f64 {
        self.a * self.e - self.b * self.d
    }
    /// Geometric mean scale factor (lengths grow by about this much).
    pub fn mean_scale(&self) -> f64 {
        self.det().abs().sqrt()
    }
    /// True when circles stay circles: the linear part is a rotation times a
    /// uniform scale, possibly mirrored, to within `rel` relative error.
    pub fn is_similarity(&self, rel: f64) -> bool {
        let c1 = (self.a * self.a + self.d * self.d).sqrt();
        let c2 = (self.b * self.b + self.e * self.e).sqrt();
        let dot = self.a * self.b + self.d * self.e;
        let m = c1.max(c2);
        m > 0.0 && (c1 - c2).abs() <= rel * m && dot.abs() <= rel * m * m
    }
    /// True when every coefficient is finite.
    pub fn is_finite(&self) -> bool {
        [self.a, self.b, self.c, self.d, self.e, self.f]
            .iter()
            .all(|v| v.is_finite())
    }
}

/// Maps segments through an affine map. Arcs stay arcs under a similarity
/// (a mirror flips their turn); under a non-uniform scale they become
/// elliptical and are replaced by lines within `chord` (in output units).
pub fn transform_segments(segs: &[Segment], m: &Affine, chord: f64, out: &mut Vec<Segment>) {
    let similar = m.is_similarity(1e-9);
    let flip = m.det() < 0.0;
    for s in segs {
        if s.is_line() || similar {
            out.push(Segment {
                a: m.apply(s.a),
                b: m.apply(s.b),
                bulge: if flip { -s.bulge } else { s.bulge },
            });
        } else if let Some((_, r)) = s.arc_center() {
            // Sample the arc finely enough that its image is within the chord tolerance.
            let r_out = r * m.a.abs().max(m.b.abs()).max(m.d.abs()).max(m.e.abs()) * 2.0;
            let n = flatten_count(r_out, s.sweep().abs(), chord);
            let mut prev = m.apply(s.a);
            for k in 1..=n {
                let q = if k == n {
                    m.apply(s.b)
                } else {
                    m.apply(s.point_at(k as f64 / n as f64))
                };
                out.push(Segment::line(prev, q));
                prev = q;
            }
        } else {
            out.push(Segment::line(m.apply(s.a), m.apply(s.b)));
        }
    }
}

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

/// Distance from `p` to the segment.
pub fn dist_to_segment(p: Point, s: &Segment) -> f64 {
    match s.arc_center() {
        Some((c, r)) => {
            let v = p.sub(c);
            let a0 = s.a.sub(c);
            if angle_in_sweep(a0.y.atan2(a0.x), s.sweep(), v.y.atan2(v.x)) {
                (v.norm() - r).abs()
            } else {
                p.dist(s.a).min(p.dist(s.b))
            }
        }
        None => {
            let d = s.b.sub(s.a);
            let len2 = d.dot(d);
            if len2 == 0.0 {
                return p.dist(s.a);
            }
            let t = (p.sub(s.a).dot(d) / len2).clamp(0.0, 1.0);
            p.dist(s.a.add(d.scale(t)))
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
    fn half_circle_bulge_one_has_centre_at_chord_midpoint() {
        let s = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let (c, r) = s.arc_center().unwrap();
        approx(c.x, 0.0, 1e-12);
        approx(c.y, 0.0, 1e-12);
        approx(r, 10.0, 1e-12);
        approx(s.length(), PI * 10.0, 1e-9);
        // The CCW half from (10,0) to (-10,0) passes through (0,10).
        approx(s.point_at(0.5).y, 10.0, 1e-9);
        approx(s.bbox().max.y, 10.0, 1e-9);
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
    fn mirrored_insert_flips_arc_turn_and_keeps_radius() {
        let s = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let m = Affine::translate(5.0, 5.0).then_after(&Affine::scale_xy(-2.0, 2.0));
        let mut out = vec![];
        transform_segments(&[s], &m, 0.01, &mut out);
        assert_eq!(out.len(), 1);
        assert!(out[0].bulge < 0.0);
        let (c, r) = out[0].arc_center().unwrap();
        assert!((r - 20.0).abs() < 1e-9 && c.dist(Point::new(5.0, 5.0)) < 1e-9);
    }

    #[test]
    fn non_uniform_scale_turns_an_arc_into_lines_within_the_chord_tolerance() {
        let s = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let m = Affine::scale_xy(1.0, 0.5);
        let mut out = vec![];
        transform_segments(&[s], &m, 0.01, &mut out);
        assert!(out.len() > 10 && out.iter().all(Segment::is_line));
        for seg in &out {
            let mid = seg.point_at(0.5);
            // On the ellipse x²/100 + y²/25 = 1 within the tolerance.
            let t = (mid.x / 10.0).hypot(mid.y / 5.0);
            assert!((1.0 - t) * 5.0 < 0.011, "{t}");
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
