//! Pieces in user units → segments in mm through the element's map.
//! Lines stay lines. An elliptical arc's image under any affine map is an
//! ellipse with the mapped centre and conjugate semi-diameters; when its two
//! semi-axes agree within a tenth of the chord tolerance it is a circle and
//! becomes true arcs (quarters at most), else biarcs by the DXF reader's
//! ELLIPSE code ([`crate::dxf::ellipse::EllipseCurve`]). Béziers are affine
//! invariant: their control points are mapped and the curve fitted with
//! biarcs ([`crate::dxf::biarc`]) within the chord tolerance in mm.

use std::f64::consts::FRAC_PI_2;

use super::path::{Piece, Subpath};
use crate::dxf::biarc::{self, Curve};
use crate::dxf::ellipse::EllipseCurve;
use crate::geom::{Affine, Point, Segment};

/// Parameter spans a Bézier is cut into before fitting: a cubic may loop
/// back to its start (a zero chord the fit cannot take whole) or turn
/// through an inflection; a quarter of it cannot do both.
const BEZIER_SPANS: usize = 4;

/// A quadratic Bézier with its exact velocity.
struct Quad([Point; 3]);

impl Curve for Quad {
    fn at(&self, t: f64) -> Point {
        let [p0, c, p1] = self.0;
        let s = 1.0 - t;
        p0.scale(s * s)
            .add(c.scale(2.0 * s * t))
            .add(p1.scale(t * t))
    }
    fn at_with_velocity(&self, t: f64) -> (Point, Option<Point>) {
        let [p0, c, p1] = self.0;
        let v = c
            .sub(p0)
            .scale(2.0 * (1.0 - t))
            .add(p1.sub(c).scale(2.0 * t));
        (self.at(t), Some(v))
    }
}

/// A cubic Bézier with its exact velocity.
struct Cubic([Point; 4]);

impl Curve for Cubic {
    fn at(&self, t: f64) -> Point {
        let [p0, p1, p2, p3] = self.0;
        let s = 1.0 - t;
        p0.scale(s * s * s)
            .add(p1.scale(3.0 * s * s * t))
            .add(p2.scale(3.0 * s * t * t))
            .add(p3.scale(t * t * t))
    }
    fn at_with_velocity(&self, t: f64) -> (Point, Option<Point>) {
        let [p0, p1, p2, p3] = self.0;
        let s = 1.0 - t;
        let v = (p1.sub(p0).scale(3.0 * s * s))
            .add(p2.sub(p1).scale(6.0 * s * t))
            .add(p3.sub(p2).scale(3.0 * t * t));
        (self.at(t), Some(v))
    }
}

/// The linear part of `m` applied to a vector.
fn linear(m: &Affine, v: Point) -> Point {
    Point::new(m.a * v.x + m.b * v.y, m.d * v.x + m.e * v.y)
}

/// The semi-axes (largest, smallest) of the ellipse with conjugate
/// semi-diameters `u`, `v`: the singular values of the matrix [u v].
pub fn semi_axes(u: Point, v: Point) -> (f64, f64) {
    let (a, b, c, d) = (u.x, v.x, u.y, v.y);
    let s = a * a + b * b + c * c + d * d;
    let det = (a * d - b * c).abs();
    let root = (s * s - 4.0 * det * det).max(0.0).sqrt();
    let s1 = ((s + root) / 2.0).sqrt();
    let s2 = if s1 > 0.0 { det / s1 } else { 0.0 };
    (s1, s2)
}

/// Appends `sp`'s segments in mm (through `m`) to `out`, curves within
/// `chord`; stops adding once `out` holds `max`.
pub fn segments(sp: &Subpath, m: &Affine, chord: f64, max: usize, out: &mut Vec<Segment>) {
    for piece in &sp.pieces {
        if out.len() >= max {
            return;
        }
        let from = out.len();
        let (a, b) = match *piece {
            Piece::Line(a, b) => {
                let (a, b) = (m.apply(a), m.apply(b));
                if a != b {
                    out.push(Segment::line(a, b));
                }
                continue;
            }
            Piece::Quad(p) => {
                let q = Quad(p.map(|p| m.apply(p)));
                fit_spans(&q, chord, max, out);
                (q.0[0], q.0[2])
            }
            Piece::Cubic(p) => {
                let c = Cubic(p.map(|p| m.apply(p)));
                fit_spans(&c, chord, max, out);
                (c.0[0], c.0[3])
            }
            Piece::Arc {
                c,
                major,
                minor,
                t0,
                sweep,
                from: a,
                to: b,
            } => {
                let (c, u, v) = (m.apply(c), linear(m, major), linear(m, minor));
                let (a, b) = (m.apply(a), m.apply(b));
                arc(c, u, v, (t0, sweep), chord, max, out);
                (a, b)
            }
        };
        // The curve's ends exactly where the path names them, so pieces
        // join without a gap (the fit's ends are computed, to rounding).
        if out.len() > from {
            out[from].a = a;
            let last = out.len() - 1;
            out[last].b = b;
            if out[last].a == out[last].b {
                out.pop();
            }
            if out.len() > from && out[from].a == out[from].b {
                out.remove(from);
            }
        }
    }
}

fn fit_spans<C: Curve>(f: &C, chord: f64, max: usize, out: &mut Vec<Segment>) {
    for k in 0..BEZIER_SPANS {
        let t0 = k as f64 / BEZIER_SPANS as f64;
        let t1 = (k + 1) as f64 / BEZIER_SPANS as f64;
        biarc::fit(f, t0, t1, chord, max, out);
    }
}

/// The elliptical arc c + u·cos t + v·sin t, t from t0 by sweep (mm).
fn arc(
    c: Point,
    u: Point,
    v: Point,
    (t0, sweep): (f64, f64),
    chord: f64,
    max: usize,
    out: &mut Vec<Segment>,
) {
    let (s1, s2) = semi_axes(u, v);
    if !(s1.is_finite() && s1 > 0.0) {
        return;
    }
    let quarters = (sweep.abs() / FRAC_PI_2 - 1e-9).ceil().max(1.0) as usize;
    let f = |t: f64| c.add(u.scale(t.cos())).add(v.scale(t.sin()));
    if s1 - s2 <= 0.1 * chord {
        // A circle: t is its angle, turning counter-clockwise (mm, y up)
        // when u × v > 0.
        let turn = if u.cross(v) >= 0.0 { sweep } else { -sweep };
        let bulge = (turn / quarters as f64 / 4.0).tan();
        let mut prev = f(t0);
        for k in 1..=quarters {
            let q = f(t0 + sweep * k as f64 / quarters as f64);
            if out.len() < max && prev != q {
                out.push(Segment {
                    a: prev,
                    b: q,
                    bulge,
                });
            }
            prev = q;
        }
        return;
    }
    // The fit follows increasing parameter: a negative sweep is the
    // ellipse with v reversed, run from −t0 (cos even, sin odd).
    let (e, t0, dt) = if sweep >= 0.0 {
        (
            EllipseCurve {
                c,
                major: u,
                minor: v,
            },
            t0,
            sweep,
        )
    } else {
        (
            EllipseCurve {
                c,
                major: u,
                minor: v.scale(-1.0),
            },
            -t0,
            -sweep,
        )
    };
    for k in 0..quarters {
        let a = t0 + dt * k as f64 / quarters as f64;
        let b = t0 + dt * (k + 1) as f64 / quarters as f64;
        biarc::fit(&e, a, b, chord, max, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::dist_to_segment;
    use crate::svg::path;

    /// The largest distance from the true curve (sampled densely, by its
    /// own formula here, not the fit's) to the nearest segment.
    fn worst(segs: &[Segment], truth: impl Fn(f64) -> Point) -> f64 {
        (0..=2000)
            .map(|k| {
                let p = truth(k as f64 / 2000.0);
                segs.iter()
                    .map(|s| dist_to_segment(p, s))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    }

    fn of(d: &str, m: &Affine, chord: f64) -> Vec<Segment> {
        let (sps, err) = path::parse(d);
        assert!(err.is_none());
        let mut out = vec![];
        for sp in &sps {
            segments(sp, m, chord, usize::MAX, &mut out);
        }
        out
    }

    #[test]
    fn a_cubic_is_fitted_within_the_tolerance_of_the_true_curve() {
        let chord = 0.01;
        let segs = of("M0 0 C 0 40 60 -20 50 30", &Affine::IDENTITY, chord);
        assert!(segs.iter().any(|s| !s.is_line()), "biarcs, not lines");
        let bez = |t: f64| {
            let s = 1.0 - t;
            let x = 3.0 * s * t * t * 60.0 + t * t * t * 50.0;
            let y = 3.0 * s * s * t * 40.0 - 3.0 * s * t * t * 20.0 + t * t * t * 30.0;
            Point::new(x, y)
        };
        let w = worst(&segs, bez);
        assert!(w <= chord, "{w}");
        // Chained end to end from the start to the end.
        assert_eq!(segs[0].a, Point::new(0.0, 0.0));
        assert_eq!(segs.last().unwrap().b, Point::new(50.0, 30.0));
        for p in segs.windows(2) {
            assert_eq!(p[0].b, p[1].a);
        }
    }

    #[test]
    fn a_quadratic_and_a_cubic_that_loops_back_to_its_start() {
        let chord = 0.005;
        let segs = of("M0 0 Q 10 20 20 0", &Affine::IDENTITY, chord);
        let q = |t: f64| Point::new(20.0 * t, 40.0 * t * (1.0 - t));
        assert!(worst(&segs, q) <= chord);
        // Rayforge's tricky arc: ends where it starts.
        let segs = of("M0 0 C 10 10 -10 10 0 0", &Affine::IDENTITY, chord);
        assert!(segs.len() > 2);
        let c = |t: f64| {
            let s = 1.0 - t;
            Point::new(
                3.0 * s * s * t * 10.0 - 3.0 * s * t * t * 10.0,
                3.0 * s * t * 10.0,
            )
        };
        assert!(worst(&segs, c) <= chord);
    }

    #[test]
    fn a_path_arc_is_a_true_arc_under_a_similarity_and_biarcs_under_a_stretch() {
        // Half circle r 10 from (0,0) to (20,0) through (10,-10), flipped
        // to y up by the root's map: through (10, 10).
        let flip = Affine::scale_xy(1.0, -1.0);
        let segs = of("M0 0 A 10 10 0 0 1 20 0", &flip, 0.01);
        assert_eq!(segs.len(), 2);
        for s in &segs {
            let (c, r) = s.arc_center().unwrap();
            assert!(c.dist(Point::new(10.0, 0.0)) < 1e-9 && (r - 10.0).abs() < 1e-9);
        }
        assert!(segs[0].point_at(1.0).dist(Point::new(10.0, 10.0)) < 1e-9);
        assert!(!segs[0].is_ccw(), "left to right over the top is clockwise");
        // Scaled 2 × 1: half an ellipse with semi-axes 20 and 10.
        let m = Affine::scale_xy(2.0, 1.0);
        let segs = of("M0 0 A 10 10 0 0 1 20 0", &m, 0.01);
        let e = |t: f64| {
            let a = std::f64::consts::PI * (1.0 + t);
            Point::new(20.0 + 20.0 * a.cos(), 10.0 * a.sin())
        };
        assert!(worst(&segs, e) <= 0.01);
        assert_eq!(segs.last().unwrap().b, Point::new(40.0, 0.0));
    }

    #[test]
    fn semi_axes_of_a_skewed_circle() {
        // u = (1,0), v = (1,1) (skewX 45 of the unit circle): the
        // singular values of [[1,1],[0,1]] are the golden ratio and its inverse.
        let (s1, s2) = semi_axes(Point::new(1.0, 0.0), Point::new(1.0, 1.0));
        let phi = (1.0 + 5f64.sqrt()) / 2.0;
        assert!((s1 - phi).abs() < 1e-12 && (s2 - 1.0 / phi).abs() < 1e-12);
    }
}
