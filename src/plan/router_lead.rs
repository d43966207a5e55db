//! A router profile's lead arcs (issue 43 §3): the end mill comes into
//! the wall along a tangent arc and leaves it along another, on the waste
//! side (outside an outer profile, inside a hole), so the tool never goes
//! down or up against the finished wall, where a plunge leaves a mark.
//! The post cuts both on every depth pass (`gcode::passes`).
//!
//! An arc is kept only where the tool's disc swept along it stays clear
//! of every drawn part (its own and its neighbours) by the distance the
//! profile itself keeps (half the kerf: the tool-centre path's offset).
//! Where it does not, the arc is not cut — never shrunk or turned into
//! something else — and the plan says so: the tool goes straight down
//! onto the contour there, or straight up from it.

use super::clearance::Obstacles;
use crate::geom::{Point, Segment};

/// The quarter-turn arc's bulge (tan of a quarter of 90°).
fn quarter() -> f64 {
    (std::f64::consts::FRAC_PI_2 / 4.0).tan()
}

/// The side normal pointing into the waste for travel direction `t`.
fn waste(t: Point, waste_left: bool) -> Point {
    if waste_left {
        t.perp()
    } else {
        t.perp().scale(-1.0)
    }
}

/// The lead-in: a quarter turn of `radius` on the waste side ending at
/// `start`, arriving along `t` (the first move's direction there).
pub fn arc_in(start: Point, t: Point, waste_left: bool, radius: f64) -> Segment {
    let c = start.add(waste(t, waste_left).scale(radius));
    let a = c.sub(t.scale(radius));
    let b = quarter();
    Segment {
        a,
        b: start,
        bulge: if waste_left { b } else { -b },
    }
}

/// The lead-out: a quarter turn of `radius` on the waste side leaving
/// `end` along `t` (the last move's direction there).
pub fn arc_out(end: Point, t: Point, waste_left: bool, radius: f64) -> Segment {
    let c = end.add(waste(t, waste_left).scale(radius));
    let b = c.add(t.scale(radius));
    let q = quarter();
    Segment {
        a: end,
        b,
        bulge: if waste_left { q } else { -q },
    }
}

/// True when a disc swept along `s` keeps `keep` mm from every drawn
/// contour, within `slack` (the geometry's rounding: the profile's own
/// start keeps exactly `keep`). Sampled at most `slack` apart, so that
/// between samples (distance is 1-Lipschitz) nothing comes nearer than
/// `keep - slack`.
pub fn swept_clear(obstacles: &Obstacles, s: &Segment, keep: f64, slack: f64) -> bool {
    let len = s.length();
    if !len.is_finite() || !s.a.is_finite() || !s.b.is_finite() {
        return false;
    }
    let n = (len / slack).ceil().clamp(1.0, 8192.0) as usize;
    let h = len / n as f64;
    // With h above the slack (a long arc), the samples ask for more.
    let need = keep - slack.max(h) + h / 2.0;
    (0..=n).all(|i| obstacles.clear_of(s.point_at(i as f64 / n as f64), need.max(0.0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_arcs_are_tangent_to_the_path_and_bulge_into_the_waste() {
        // Travel along +X with the waste on the left (+Y).
        let (s, t) = (Point::new(10.0, 0.0), Point::new(1.0, 0.0));
        for left in [true, false] {
            let i = arc_in(s, t, left, 6.0);
            let o = arc_out(s, t, left, 6.0);
            assert!(i.tangent_at(1.0).sub(t).norm() < 1e-9, "in arrives along t");
            assert!(o.tangent_at(0.0).sub(t).norm() < 1e-9, "out leaves along t");
            let side = if left { 1.0 } else { -1.0 };
            assert!(i.point_at(0.5).y * side > 0.0 && o.point_at(0.5).y * side > 0.0);
            // A quarter turn of radius 6: 3π long, ending 6 mm off the path.
            assert!((i.length() - 3.0 * std::f64::consts::PI).abs() < 1e-9);
            assert!((o.b.y.abs() - 6.0).abs() < 1e-9 && (o.b.x - 16.0).abs() < 1e-9);
            assert!((i.a.y.abs() - 6.0).abs() < 1e-9 && (i.a.x - 4.0).abs() < 1e-9);
        }
    }
}
