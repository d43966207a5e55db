//! Paper 000's invalid vertices: the sharp corners on the scrap side that
//! the kerf's rounding cannot reproduce ([`super::offset`] reports them).

use crate::contour::ContourKind;
use crate::geom::{end_tangents, Point, Segment, Tolerance};

/// Turns by less than this (radians) at three vertices in a row, the same
/// way, mark a curve drawn as a polygon (a round hole of short lines), not a
/// designed corner.
const CURVE_SAMPLE_TURN: f64 = std::f64::consts::FRAC_PI_4;

/// Paper 000's invalid vertices of a counter-clockwise contour: scrap-side
/// corners where the kerf's rounding leaves material beyond the tolerance.
pub(super) fn invalid_vertices(
    segs: &[Segment],
    kind: ContourKind,
    half: f64,
    tol: Tolerance,
) -> Vec<Point> {
    // Scrap is to the right of a counter-clockwise outer, to the left inside a hole.
    let scrap_left = kind == ContourKind::Hole;
    let n = segs.len();
    // turn[i]: the turn at the start of segment i.
    let tangents: Vec<(Point, Point)> = segs.iter().map(end_tangents).collect();
    let turn: Vec<f64> = (0..n)
        .map(|i| {
            let (t_in, t_out) = (tangents[(i + n - 1) % n].1, tangents[i].0);
            t_in.cross(t_out).atan2(t_in.dot(t_out))
        })
        .collect();
    let mut found = Vec::new();
    for i in 0..n {
        let next = &segs[i];
        let t = turn[i];
        // A round kerf of radius `half` sitting in a scrap-side corner that turns by δ
        // stays half·(1/cos(δ/2) − 1) from the corner point: that much material is
        // left. The corner is invalid when this exceeds the tolerance, so the
        // tiny turns of a finely segmented curve are not reported.
        let left_behind = if t.abs() >= std::f64::consts::PI - 1e-9 {
            f64::INFINITY
        } else {
            half * (1.0 / (t.abs() / 2.0).cos() - 1.0)
        };
        if left_behind > tol.mm() && (t > 0.0) == scrap_left && !curve_sample(segs, &turn, i, half)
        {
            found.push(next.a);
        }
        if let Some((_, r)) = next.arc_center() {
            if next.is_ccw() == scrap_left && r < half {
                found.push(next.point_at(0.5));
            }
        }
    }
    found
}

/// True when vertex `i` is one sample of a curve drawn as a polygon that
/// the kerf can follow: it and both neighbours turn the same way by less
/// than [`CURVE_SAMPLE_TURN`], and the curve's radius there (a regular
/// polygon's: side / (2 sin(turn / 2))) is at least the kerf's half-width.
/// The kerf then rounds the corner by less than the polygon already departs
/// from its curve, so nothing the drawing meant is lost.
fn curve_sample(segs: &[Segment], turn: &[f64], i: usize, half: f64) -> bool {
    let n = segs.len();
    if n < 3 {
        return false;
    }
    let (a, b, c) = (turn[(i + n - 1) % n], turn[i], turn[(i + 1) % n]);
    let small_same_way =
        |t: f64| t.abs() < CURVE_SAMPLE_TURN && t.signum() == b.signum() && t != 0.0;
    if !(small_same_way(a) && small_same_way(b) && small_same_way(c)) {
        return false;
    }
    let side = segs[(i + n - 1) % n].length().min(segs[i].length());
    let radius = side / (2.0 * (b.abs() / 2.0).sin());
    radius >= half
}
