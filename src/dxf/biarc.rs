//! Curves → arcs: biarc fitting. A biarc is two tangent-continuous arcs
//! joining two points with given tangents (Bolton 1975, "Biarc curves";
//! the equal-distance joint d1 = d2 of Sabin, as derived in R. Juckett,
//! "Biarc Interpolation", 2010). A parameter span of the curve is replaced
//! by one biarc when every sampled curve point lies within the chord
//! tolerance of it — paper 004's chord criterion (the deviation between the
//! curve and what replaces it, `notes-004-oliveira-1997.md` §2.2) applied to
//! arcs instead of chords — else the span is halved. An arc follows a
//! curve's bending, so an ellipse takes tens of arcs where it took hundreds
//! of lines, and the cut is smooth.

use crate::geom::{dist_to_segment, Point, Segment};

/// Deepest halving of one parameter span.
const MAX_DEPTH: u32 = 24;
/// Curve points checked inside a span (at k/SAMPLES, 0 < k < SAMPLES).
const SAMPLES: usize = 8;
/// The samples must lie within this share of the tolerance: the curve
/// between samples may stray a little further (measured in the tests).
const MARGIN: f64 = 0.8;

/// A parametric plane curve to be fitted.
pub trait Curve {
    fn at(&self, t: f64) -> Point;
    /// The point and, where the curve knows it exactly, its velocity d/dt
    /// (else the fit takes the tangent by a finite difference).
    fn at_with_velocity(&self, t: f64) -> (Point, Option<Point>) {
        (self.at(t), None)
    }
}

impl<F: Fn(f64) -> Point> Curve for F {
    fn at(&self, t: f64) -> Point {
        self(t)
    }
}

/// A span end: parameter, point, and the unit tangent where it is known
/// exactly (computed once, shared by the two halves of a split span).
#[derive(Clone, Copy)]
struct End {
    t: f64,
    p: Point,
    tangent: Option<Point>,
}

fn end<C: Curve + ?Sized>(f: &C, t: f64) -> End {
    let (p, v) = f.at_with_velocity(t);
    End {
        t,
        p,
        tangent: v.and_then(unit),
    }
}

/// `v` scaled to length 1; None for a zero or non-finite vector.
fn unit(v: Point) -> Option<Point> {
    let n = (v.x * v.x + v.y * v.y).sqrt();
    (n.is_finite() && n > 0.0).then(|| v.scale(1.0 / n))
}

/// Appends to `out` arcs (and, where a fit fails at the deepest level,
/// lines) within `tol` of `f` on `[t0, t1]`, starting at `f(t0)`. Stops
/// adding once `out` holds `max` segments.
pub fn fit<C: Curve + ?Sized>(
    f: &C,
    t0: f64,
    t1: f64,
    tol: f64,
    max: usize,
    out: &mut Vec<Segment>,
) {
    span(f, end(f, t0), end(f, t1), tol, max, out, 0);
}

/// Unit tangent at `t` (along increasing parameter), by a one-sided
/// second-order difference towards `toward` (the span's inside: a knot may
/// be a corner). None at a cusp.
fn tangent<C: Curve + ?Sized>(f: &C, (t, a): (f64, Point), toward: f64) -> Option<Point> {
    let h = (toward - t) * 1e-5;
    let (b, c) = (f.at(t + h), f.at(t + 2.0 * h));
    // (−3 f(t) + 4 f(t+h) − f(t+2h)) / 2h, the sign of h folded in.
    unit(b.scale(4.0).sub(a.scale(3.0)).sub(c).scale(h.signum()))
}

fn cross(a: Point, b: Point) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The arc from `a` to `b` leaving `a` along the unit tangent `ta`; None
/// beyond a half turn (a [`Segment`] holds at most 180°).
fn arc_from(a: Point, ta: Point, b: Point) -> Option<Segment> {
    let c = b.sub(a);
    let chord = c.norm();
    if chord == 0.0 {
        return None;
    }
    // The chord turns from the start tangent by θ, half the sweep;
    // bulge = tan(sweep/4) = tan(θ/2) = sin θ / (1 + cos θ), and with ta a
    // unit vector sin θ = ta × c / |c|, cos θ = ta · c / |c|. Exact, and
    // well conditioned wherever the bulge is kept (|θ| ≤ 90°).
    let den = chord + ta.dot(c);
    let bulge = cross(ta, c) / den;
    (den > 0.0 && bulge.is_finite() && bulge.abs() <= 1.0).then_some(Segment { a, b, bulge })
}

/// The biarc from `p0` (unit tangent `t0`) to `p1` (unit tangent `t1`)
/// with equal tangent lengths d: |p0 + d·t0 − (p1 − d·t1)| = 2d, i.e.
/// 2(1 − t0·t1) d² + 2 (v·(t0 + t1)) d − v·v = 0 with v = p1 − p0.
fn biarc(p0: Point, t0: Point, p1: Point, t1: Point) -> Option<[Segment; 2]> {
    let v = p1.sub(p0);
    let t = t0.add(t1);
    let vt = v.dot(t);
    let k = 2.0 * (1.0 - t0.dot(t1));
    let d = if k.abs() < 1e-12 {
        // Parallel tangents: the quadratic is linear.
        let s = v.dot(t1);
        if s.abs() < 1e-300 {
            return None;
        }
        v.dot(v) / (4.0 * s)
    } else {
        (-vt + (vt * vt + k * v.dot(v)).sqrt()) / k
    };
    if !(d.is_finite() && d > 0.0) {
        return None;
    }
    let joint = p0.add(t0.scale(d)).add(p1.sub(t1.scale(d))).scale(0.5);
    let first = arc_from(p0, t0, joint)?;
    // The second arc run backwards leaves p1 along −t1.
    let second = arc_from(p1, t1.scale(-1.0), joint)?;
    Some([first, second.reversed()])
}

/// A segment ready for many distance queries: the arc's centre found once,
/// the sweep tested by cross products (arcs here are under a half turn)
/// instead of angles.
struct Near {
    seg: Segment,
    arc: Option<(Point, f64)>,
}

impl Near {
    fn new(seg: Segment) -> Self {
        Near {
            seg,
            arc: seg.arc_center(),
        }
    }
    fn dist(&self, q: Point) -> f64 {
        let s = &self.seg;
        let Some((c, r)) = self.arc else {
            return dist_to_segment(q, s);
        };
        let (v, a, b) = (q.sub(c), s.a.sub(c), s.b.sub(c));
        let (from_a, to_b) = (cross(a, v), cross(v, b));
        let inside = if s.bulge > 0.0 {
            from_a >= 0.0 && to_b >= 0.0
        } else {
            from_a <= 0.0 && to_b <= 0.0
        };
        if inside {
            ((v.x * v.x + v.y * v.y).sqrt() - r).abs()
        } else {
            let (da, db) = (q.sub(s.a), q.sub(s.b));
            (da.x * da.x + da.y * da.y)
                .min(db.x * db.x + db.y * db.y)
                .sqrt()
        }
    }
}

#[allow(clippy::too_many_arguments)]
fn span<C: Curve + ?Sized>(
    f: &C,
    a: End,
    b: End,
    tol: f64,
    max: usize,
    out: &mut Vec<Segment>,
    depth: u32,
) {
    let (t0, p0, t1, p1) = (a.t, a.p, b.t, b.p);
    if depth >= MAX_DEPTH || out.len() >= max {
        if p0 != p1 {
            out.push(Segment::line(p0, p1));
        }
        return;
    }
    let chord = p0.dist(p1);
    let fitted = a
        .tangent
        .or_else(|| tangent(f, (t0, p0), t1))
        .zip(b.tangent.or_else(|| tangent(f, (t1, p1), t0)))
        .and_then(|(ta, tb)| {
            if chord <= tol * 1e-3 {
                return None;
            }
            biarc(p0, ta, p1, tb)
        })
        .filter(|arcs| {
            let near = arcs.map(Near::new);
            // The middle first: a span that does not fit usually fails there.
            [4, 2, 6, 1, 3, 5, 7].iter().all(|&k| {
                let q = f.at(t0 + (t1 - t0) * k as f64 / SAMPLES as f64);
                near[0].dist(q).min(near[1].dist(q)) <= MARGIN * tol
            })
        });
    match fitted {
        Some(arcs) => out.extend(arcs.into_iter().filter(|s| s.a != s.b)),
        // A tiny span (or a cusp) is a line when its chord is within the tolerance.
        None if chord <= tol => {
            if p0 != p1 {
                out.push(Segment::line(p0, p1));
            }
        }
        None => {
            let m = end(f, 0.5 * (t0 + t1));
            span(f, a, m, tol, max, out, depth + 1);
            span(f, m, b, tol, max, out, depth + 1);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_arc_is_fitted_by_one_biarc_on_the_circle() {
        let f = |t: f64| Point::new(10.0 * t.cos(), 10.0 * t.sin());
        let mut out = vec![];
        fit(&f, 0.0, 1.5, 1e-6, 1000, &mut out);
        assert_eq!(out.len(), 2, "{out:?}");
        for s in &out {
            let (c, r) = s.arc_center().unwrap();
            assert!(c.norm() < 1e-6 && (r - 10.0).abs() < 1e-6, "{c:?} {r}");
        }
    }

    #[test]
    fn the_quick_distance_agrees_with_the_general_one() {
        let mut unit = crate::test_rng::unit(0x9e37_79b9_7f4a_7c15);
        let mut r = || unit() * 20.0 - 10.0;
        for _ in 0..2000 {
            let bulge = r() / 10.0;
            let s = Segment {
                a: Point::new(r(), r()),
                b: Point::new(r(), r()),
                bulge,
            };
            let q = Point::new(r(), r());
            let (fast, slow) = (Near::new(s).dist(q), dist_to_segment(q, &s));
            assert!(
                (fast - slow).abs() < 1e-9 * (1.0 + slow),
                "{fast} {slow} {s:?}"
            );
        }
    }

    #[test]
    fn a_straight_span_becomes_straight_pieces() {
        let f = |t: f64| Point::new(t, 2.0 * t);
        let mut out = vec![];
        fit(&f, 0.0, 5.0, 1e-3, 1000, &mut out);
        assert!(!out.is_empty());
        assert!(out.iter().all(|s| s.bulge.abs() < 1e-9));
        assert_eq!(out.last().unwrap().b, Point::new(5.0, 10.0));
    }
}
