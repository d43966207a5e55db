//! The geometry every stage speaks: points, and segments that are either a
//! straight line or a circular arc, in millimetres with Y up.
//!
//! A segment is stored the way DXF's LWPOLYLINE (group code 42) and
//! cavalier_contours store it: two end points and a *bulge*
//! `b = tan(sweep / 4)`, positive for a counter-clockwise arc, 0 for a line.
//! Every stage keeps `|b| <= 1` (sweep at most 180°), so no arc is ever a
//! full circle and G2/G3 blocks are never ambiguous.

mod affine;
mod arcfit;
pub(crate) mod graph;
mod grid;
mod path;

pub use affine::{transform_segments, Affine};
pub use arcfit::fit_path;
pub use grid::Grid;
pub use path::{
    angle_in_sweep, arc_pieces, chords, dist_to_segment, end_tangents, flatten_count, loop_area,
    nearest_param, path_bbox, path_length, path_measure, path_points, split_big_bulge,
    SegmentDistance,
};
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
        self.min.x = fmin(self.min.x, p.x);
        self.min.y = fmin(self.min.y, p.y);
        self.max.x = fmax(self.max.x, p.x);
        self.max.y = fmax(self.max.y, p.y);
    }
    /// Grows the box to hold another box.
    pub fn union(&mut self, o: &BBox) {
        if !o.is_empty() {
            self.add(o.min);
            self.add(o.max);
        }
    }
    /// Its middle.
    pub fn centre(&self) -> Point {
        Point::new(
            (self.min.x + self.max.x) / 2.0,
            (self.min.y + self.max.y) / 2.0,
        )
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
    /// This box grown by `d` on every side and by a margin far above the
    /// rounding of points computed on a segment it holds (a nanometre a
    /// kilometre of its coordinates).
    pub fn grown(&self, d: f64) -> BBox {
        let (a, b) = (self.min, self.max);
        let m = d + 1e-9 * (1.0 + a.x.abs().max(a.y.abs()).max(b.x.abs()).max(b.y.abs()));
        BBox {
            min: Point::new(a.x - m, a.y - m),
            max: Point::new(b.x + m, b.y + m),
        }
    }
    /// The box of one point.
    pub fn at(p: Point) -> BBox {
        BBox { min: p, max: p }
    }
    /// Squared distance from `p` to the box (0 inside): never more than
    /// the squared distance to anything in the box, and no square root
    /// (the closeness checks weigh it at every sample before the exact
    /// distance).
    pub fn gap_sq(&self, p: Point) -> f64 {
        let dx = (self.min.x - p.x).max(p.x - self.max.x).max(0.0);
        let dy = (self.min.y - p.y).max(p.y - self.max.y).max(0.0);
        dx * dx + dy * dy
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

/// [`Segment::point_at`] at many parameters of one segment: an arc's
/// centre, radius and angles found once (the kerf check samples every
/// cut a cell apart). Bit for bit the same points.
#[derive(Clone, Copy, Debug)]
pub struct Along {
    a: Point,
    b: Point,
    /// An arc's centre, radius, start angle and sweep.
    arc: Option<(Point, f64, f64, f64)>,
}

impl Along {
    /// Ready to place points along `s`.
    pub fn new(s: &Segment) -> Along {
        let arc = s.arc_center().map(|(c, r)| {
            let a0 = s.a.sub(c);
            (c, r, a0.y.atan2(a0.x), s.sweep())
        });
        Along {
            a: s.a,
            b: s.b,
            arc,
        }
    }

    /// The point at parameter `t` in [0, 1].
    #[inline]
    pub fn at(&self, t: f64) -> Point {
        match self.arc {
            Some((c, r, start, sweep)) => {
                let ang = start + sweep * t;
                Point::new(c.x + r * ang.cos(), c.y + r * ang.sin())
            }
            None => self.a.add(self.b.sub(self.a).scale(t)),
        }
    }
}

/// `(b − a) × (c − a)`: > 0 when `a`, `b`, `c` turn left (counter-clockwise),
/// 0 when they are on one line.
#[inline]
pub fn orient(a: Point, b: Point, c: Point) -> f64 {
    b.sub(a).cross(c.sub(a))
}

/// The smaller of `a` and `b`, neither NaN, without a call: `f64::min`
/// ignores a NaN argument (IEEE minNum), wasm's `f64.min` instruction
/// does not, so in wasm `f64::min` and `f64::max` are calls to
/// compiler-builtins' `fmin` and `fmax`, never inlined: 22 % of the
/// page's nest (`node --cpu-prof`, 100 plates, the box tests of the
/// exact test and the placer). A compare and a select inline everywhere.
/// For the nester's hot loops.
#[inline(always)]
pub(crate) fn fmin(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

/// The larger of `a` and `b`, neither NaN, without a call (see [`fmin`]).
#[inline(always)]
pub(crate) fn fmax(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// `x.ceil()`, bit for bit, without a call (see [`floor`]): `-floor(-x)`.
#[inline]
pub(crate) fn ceil(x: f64) -> f64 {
    -floor(-x)
}

/// `x.floor()`, bit for bit, without a call: the baseline x86-64 target
/// has no rounding instruction (SSE4.1), so `f64::floor` is a libm call,
/// and the grids' look-ups take one per coordinate (issue 17). Below 2^52
/// the truncation to an integer is exact; beyond, `x` is whole already.
#[inline]
pub(crate) fn floor(x: f64) -> f64 {
    if x.abs() < 4_503_599_627_370_496.0 {
        let i = x as i64 as f64;
        if i > x {
            i - 1.0
        } else {
            // -0.0 stays -0.0.
            i.copysign(x)
        }
    } else {
        x.floor()
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
    /// An arc's centre, radius, start angle (of `a` from the centre) and
    /// sweep, radians; None for a line.
    pub(crate) fn arc_angles(&self) -> Option<(Point, f64, f64, f64)> {
        self.arc_center().map(|(c, r)| {
            let a0 = self.a.sub(c);
            (c, r, a0.y.atan2(a0.x), self.sweep())
        })
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
        Along::new(self).at(t)
    }
    /// Unit tangent (direction of travel) at parameter `t`.
    pub fn tangent_at(&self, t: f64) -> Point {
        match self.arc_center() {
            Some((c, _)) => self.travel_across(self.point_at(t).sub(c).unit()),
            None => self.b.sub(self.a).unit(),
        }
    }
    /// An arc's direction of travel where its unit radial is `radial`:
    /// the radial turned a quarter left if it runs counter-clockwise, right
    /// if clockwise.
    pub(crate) fn travel_across(&self, radial: Point) -> Point {
        if self.is_ccw() {
            radial.perp()
        } else {
            radial.perp().scale(-1.0)
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
        self.bbox_of_arc(self.arc_center().map(|(c, r)| (c, r, self.sweep())))
    }
    /// [`Self::bbox`] given the arc's centre, radius and sweep (None for a
    /// line), for callers that already hold them (one `atan` fewer per arc).
    pub(crate) fn bbox_of_arc(&self, arc: Option<(Point, f64, f64)>) -> BBox {
        let mut bb = BBox::EMPTY;
        bb.add(self.a);
        bb.add(self.b);
        if let Some((c, r, sweep)) = arc {
            let start = {
                let v = self.a.sub(c);
                v.y.atan2(v.x)
            };
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
#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn approx(a: f64, b: f64, eps: f64) {
        assert!((a - b).abs() < eps, "{a} != {b}");
    }

    #[test]
    fn a_box_is_never_farther_than_what_it_holds() {
        let b = BBox {
            min: Point::new(0.0, 0.0),
            max: Point::new(4.0, 2.0),
        };
        assert_eq!(b.gap_sq(Point::new(1.0, 1.0)), 0.0);
        assert_eq!(b.gap_sq(Point::new(7.0, 6.0)), 25.0);
        assert_eq!(b.gap_sq(Point::new(-3.0, 1.0)), 9.0);
        // Against the distance to points sampled on the box's edges.
        for k in 0..50 {
            let p = Point::new(-10.0 + 0.41 * k as f64, 8.0 - 0.37 * k as f64);
            let nearest = (0..=400)
                .map(|i| i as f64 / 400.0)
                .flat_map(|t| {
                    [
                        Point::new(4.0 * t, 0.0),
                        Point::new(4.0 * t, 2.0),
                        Point::new(0.0, 2.0 * t),
                        Point::new(4.0, 2.0 * t),
                    ]
                })
                .map(|q| p.dist(q))
                .fold(f64::INFINITY, f64::min);
            let inside = (0.0..=4.0).contains(&p.x) && (0.0..=2.0).contains(&p.y);
            let want = if inside { 0.0 } else { nearest };
            assert!((b.gap_sq(p).sqrt() - want).abs() < 0.02, "{p:?}");
        }
    }

    #[test]
    fn floor_and_ceil_are_f64_floor_and_ceil_bit_for_bit() {
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut cases = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            -1e-300,
            4.5e15,
            -4.5e15,
            9.1e18,
            -9.3e18,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            f64::MIN_POSITIVE,
        ];
        for _ in 0..10_000 {
            x = crate::test_rng::Xorshift(x).next();
            cases.push(f64::from_bits(x));
            cases.push((x >> 11) as f64 / (1u64 << 20) as f64 - 4e9);
        }
        for v in cases {
            assert_eq!(floor(v).to_bits(), v.floor().to_bits(), "{v:e}");
            assert_eq!(ceil(v).to_bits(), v.ceil().to_bits(), "{v:e}");
        }
    }

    #[test]
    fn fmin_and_fmax_are_f64_min_and_max_but_for_nan_and_the_sign_of_zero() {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        let mut cases = vec![
            0.0,
            1.0,
            -1.0,
            1e-300,
            -4.5e15,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for _ in 0..2_000 {
            x = crate::test_rng::Xorshift(x).next();
            let v = f64::from_bits(x);
            cases.push(if v.is_nan() { 0.5 } else { v });
        }
        for (i, &a) in cases.iter().enumerate() {
            for &b in cases.iter().skip(i % 7).step_by(37) {
                assert_eq!(fmin(a, b), a.min(b), "{a:e} {b:e}");
                assert_eq!(fmax(a, b), a.max(b), "{a:e} {b:e}");
            }
        }
        // A box's sides grown from BBox::EMPTY: a NaN point leaves them, as before.
        assert_eq!(fmin(f64::INFINITY, f64::NAN), f64::INFINITY);
        assert_eq!(fmax(f64::NEG_INFINITY, f64::NAN), f64::NEG_INFINITY);
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
}
