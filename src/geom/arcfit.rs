//! Arc fitting (issue 43 §5, paper 004 §2.12 and §5.1 item 7): a path of
//! many short moves — a DXF polyline a drawing tool exported as thousands
//! of tiny lines — rewritten as fewer lines and arcs. Paper 004 names
//! "lines swapped for lines and arcs" the main way to shorten a program
//! (L773, L1411) and to spare the axes an acceleration per move (L687).
//!
//! Every piece starts and ends on a vertex of the original path, so the
//! program still passes through the drawing's corners, and every piece is
//! within `tol` of the original both ways: each original vertex and each
//! point of each original move lies within `tol` of the piece, and the
//! piece moves forward along them (no point of it strays from the path
//! between two of them).

use super::{dist_to_segment, Point, Segment};
use std::f64::consts::{PI, TAU};

/// Points of an original arc checked against a candidate piece (an arc
/// of the path is smooth: its distance to a nearby circle or line varies
/// slowly, so 16 steps along it bound the deviation closely).
const ARC_SAMPLES: usize = 16;

/// `segs` (end to end) as fewer pieces within `tol` of it: collinear runs
/// merged into one line, runs on a circle into one arc (at most 180°,
/// the bulge limit every stage keeps). A move that no longer piece
/// covers is returned as it was. Pieces start and end on `segs`' vertices.
pub fn fit_path(segs: &[Segment], tol: f64) -> Vec<Segment> {
    let n = segs.len();
    if n < 2 || tol.is_nan() || tol <= 0.0 {
        return segs.to_vec();
    }
    let mut out = Vec::with_capacity(n / 4 + 1);
    let mut i = 0;
    while i < n {
        // The longest piece from vertex i: lengths doubled while they fit,
        // then halved between the last that fit and the first that did not
        // (O(n log n) checks of O(piece) each, where trying every end was
        // quadratic on a polyline of 10,000 moves).
        let mut good = (i + 1, segs[i]);
        let mut bad = None;
        let mut len = 2;
        while good.0 < n {
            let j = (i + len).min(n);
            match piece(&segs[i..j], tol) {
                Some(p) => good = (j, p),
                None => {
                    bad = Some(j);
                    break;
                }
            }
            len *= 2;
        }
        if let Some(mut hi) = bad {
            while hi - good.0 > 1 {
                let mid = (good.0 + hi) / 2;
                match piece(&segs[i..mid], tol) {
                    Some(p) => good = (mid, p),
                    None => hi = mid,
                }
            }
        }
        out.push(good.1);
        i = good.0;
    }
    out
}

/// One line or arc from the first move's start to the last move's end
/// within `tol` of every move of `run`, or None.
fn piece(run: &[Segment], tol: f64) -> Option<Segment> {
    let (first, last) = (run.first()?, run.last()?);
    if run.len() == 1 {
        return Some(*first);
    }
    // Moves end to end only (the plan's are; a gap ends a run).
    if run.windows(2).any(|w| w[0].b.dist(w[1].a) > tol * 1e-3) {
        return None;
    }
    let (a, b) = (first.a, last.b);
    if let Some(line) = as_line(run, a, b, tol) {
        return Some(line);
    }
    as_arc(run, a, b, tol)
}

/// Points of `s` to check: its ends for a line (the distance to a line or
/// from a point is convex along a line: its extremes are at the ends, or
/// at the foot from a centre, checked apart), samples along an arc.
fn checked_points(s: &Segment, mut f: impl FnMut(Point) -> bool) -> bool {
    if s.is_line() {
        return f(s.a) && f(s.b);
    }
    (0..=ARC_SAMPLES).all(|k| f(s.point_at(k as f64 / ARC_SAMPLES as f64)))
}

/// The chord `a`→`b` when every move of `run` lies within `tol` of it and
/// goes forward along it.
fn as_line(run: &[Segment], a: Point, b: Point, tol: f64) -> Option<Segment> {
    let d = b.sub(a);
    let len = d.norm();
    if len <= tol {
        return None;
    }
    let u = d.scale(1.0 / len);
    let mut along = 0.0_f64;
    let ok = run.iter().all(|s| {
        checked_points(s, |p| {
            let v = p.sub(a);
            let t = v.dot(u);
            // Off the line, past its ends, or back along it: not this line.
            let off = v.cross(u).abs();
            let fwd = t >= along - tol && t >= -tol && t <= len + tol;
            along = along.max(t);
            off <= tol && fwd
        })
    });
    ok.then(|| Segment::line(a, b))
}

/// The arc from `a` to `b` through the run's middle vertex when every move
/// of `run` lies within `tol` of it (radially) and turns forward along it,
/// its sweep at most 180°.
fn as_arc(run: &[Segment], a: Point, b: Point, tol: f64) -> Option<Segment> {
    let m = run[run.len() / 2].a;
    let (c, r) = circle(a, m, b)?;
    let ccw = m.sub(a).cross(b.sub(m)) > 0.0;
    let dir = if ccw { 1.0 } else { -1.0 };
    let ang = |p: Point| {
        let v = p.sub(c);
        v.y.atan2(v.x)
    };
    let a0 = ang(a);
    // Angle turned from `a` in the arc's direction, in (-slack, 2π - slack].
    let slack = tol / r;
    let turned = |p: Point| {
        let t = (dir * (ang(p) - a0)).rem_euclid(TAU);
        if t > TAU - slack {
            t - TAU
        } else {
            t
        }
    };
    let sweep = turned(b);
    if !(sweep > 0.0 && sweep <= PI * (1.0 + 1e-12)) {
        return None;
    }
    let mut along = 0.0_f64;
    let ok = run.iter().all(|s| {
        let points_ok = checked_points(s, |p| {
            let t = turned(p);
            let fwd = t >= along - slack && t <= sweep + slack;
            along = along.max(t);
            (p.dist(c) - r).abs() <= tol && fwd
        });
        // A line's nearest point to the centre lies inside the circle:
        // its sagitta is what a chord of the arc misses by.
        points_ok && (!s.is_line() || r - dist_to_segment(c, s) <= tol)
    });
    let bulge = dir * (sweep.min(PI) / 4.0).tan();
    ok.then_some(Segment { a, b, bulge })
}

/// The circle through three points (centre, radius); None when they are
/// (nearly) on a line.
fn circle(a: Point, m: Point, b: Point) -> Option<(Point, f64)> {
    let (ab, am) = (b.sub(a), m.sub(a));
    let den = 2.0 * am.cross(ab);
    let scale = ab.dot(ab).max(am.dot(am));
    if den.abs() <= 1e-12 * scale {
        return None;
    }
    // Centre relative to `a`: the intersection of the two perpendicular bisectors.
    let (s1, s2) = (am.dot(am), ab.dot(ab));
    let cx = (ab.y * s1 - am.y * s2) / den;
    let cy = (am.x * s2 - ab.x * s1) / den;
    let c = Point::new(a.x + cx, a.y + cy);
    let r = c.dist(a);
    r.is_finite().then_some((c, r))
}

#[cfg(test)]
#[path = "arcfit_tests.rs"]
mod tests;
