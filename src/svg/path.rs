//! Path data (SVG 1.1 §8.3, the grammar parsed by `svgtypes`) → subpaths of
//! pieces in user units: lines, cubic and quadratic Béziers and elliptical
//! arcs in centre form (the endpoint-to-centre conversion of SVG 1.1
//! appendix F.6.5, with F.6.6's out-of-range radii scaled up).

use std::f64::consts::{PI, TAU};

use svgtypes::{PathParser, PathSegment};

use crate::geom::Point;

/// A piece of a subpath, in user units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Piece {
    Line(Point, Point),
    Quad([Point; 3]),
    Cubic([Point; 4]),
    /// `c + major·cos t + minor·sin t` for t from `t0` by `sweep` (radians,
    /// signed); `from`/`to` are the exact end points the path names.
    Arc {
        c: Point,
        major: Point,
        minor: Point,
        t0: f64,
        sweep: f64,
        from: Point,
        to: Point,
    },
}

/// Consecutive pieces from a moveto; `closed` by a closepath.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Subpath {
    pub pieces: Vec<Piece>,
    pub closed: bool,
}

/// The path data's subpaths, and the text where reading stopped at an
/// error (SVG 1.1 §F.2: a path is rendered up to the error).
pub fn parse(d: &str) -> (Vec<Subpath>, Option<String>) {
    let mut out: Vec<Subpath> = Vec::new();
    let mut cur = Subpath::default();
    let (mut at, mut start) = (Point::default(), Point::default());
    // The last cubic's or quadratic's second control point, for S and T.
    let (mut last_cubic, mut last_quad): (Option<Point>, Option<Point>) = (None, None);
    let mut error = None;
    let flush = |cur: &mut Subpath, out: &mut Vec<Subpath>| {
        if !cur.pieces.is_empty() {
            out.push(std::mem::take(cur));
        }
        cur.closed = false;
    };
    for seg in PathParser::from(d) {
        let seg = match seg {
            Ok(s) => s,
            Err(e) => {
                error = Some(e.to_string());
                break;
            }
        };
        let abs = seg.is_abs();
        let p = |x: f64, y: f64| {
            if abs {
                Point::new(x, y)
            } else {
                at.add(Point::new(x, y))
            }
        };
        let (mut cubic_ctrl, mut quad_ctrl) = (None, None);
        match seg {
            PathSegment::MoveTo { x, y, .. } => {
                flush(&mut cur, &mut out);
                at = p(x, y);
                start = at;
            }
            PathSegment::LineTo { x, y, .. } => {
                let to = p(x, y);
                cur.pieces.push(Piece::Line(at, to));
                at = to;
            }
            PathSegment::HorizontalLineTo { x, .. } => {
                let to = if abs {
                    Point::new(x, at.y)
                } else {
                    Point::new(at.x + x, at.y)
                };
                cur.pieces.push(Piece::Line(at, to));
                at = to;
            }
            PathSegment::VerticalLineTo { y, .. } => {
                let to = if abs {
                    Point::new(at.x, y)
                } else {
                    Point::new(at.x, at.y + y)
                };
                cur.pieces.push(Piece::Line(at, to));
                at = to;
            }
            PathSegment::CurveTo {
                x1,
                y1,
                x2,
                y2,
                x,
                y,
                ..
            } => {
                let (c1, c2, to) = (p(x1, y1), p(x2, y2), p(x, y));
                cur.pieces.push(Piece::Cubic([at, c1, c2, to]));
                cubic_ctrl = Some(c2);
                at = to;
            }
            PathSegment::SmoothCurveTo { x2, y2, x, y, .. } => {
                // The first control point mirrors the last cubic's second.
                let c1 = last_cubic.map_or(at, |c| at.add(at.sub(c)));
                let (c2, to) = (p(x2, y2), p(x, y));
                cur.pieces.push(Piece::Cubic([at, c1, c2, to]));
                cubic_ctrl = Some(c2);
                at = to;
            }
            PathSegment::Quadratic { x1, y1, x, y, .. } => {
                let (c, to) = (p(x1, y1), p(x, y));
                cur.pieces.push(Piece::Quad([at, c, to]));
                quad_ctrl = Some(c);
                at = to;
            }
            PathSegment::SmoothQuadratic { x, y, .. } => {
                let c = last_quad.map_or(at, |c| at.add(at.sub(c)));
                let to = p(x, y);
                cur.pieces.push(Piece::Quad([at, c, to]));
                quad_ctrl = Some(c);
                at = to;
            }
            PathSegment::EllipticalArc {
                rx,
                ry,
                x_axis_rotation,
                large_arc,
                sweep,
                x,
                y,
                ..
            } => {
                let to = p(x, y);
                cur.pieces
                    .push(arc(at, to, rx, ry, x_axis_rotation, large_arc, sweep));
                at = to;
            }
            PathSegment::ClosePath { .. } => {
                if at != start {
                    cur.pieces.push(Piece::Line(at, start));
                }
                cur.closed = !cur.pieces.is_empty();
                flush(&mut cur, &mut out);
                // A command after Z starts at the subpath's start.
                at = start;
            }
        }
        (last_cubic, last_quad) = (cubic_ctrl, quad_ctrl);
    }
    flush(&mut cur, &mut out);
    (out, error)
}

/// An SVG arc from `a` to `b` in centre form (SVG 1.1 F.6.5, F.6.6).
pub fn arc(a: Point, b: Point, rx: f64, ry: f64, phi_deg: f64, large: bool, sweep: bool) -> Piece {
    let (mut rx, mut ry) = (rx.abs(), ry.abs());
    if a == b {
        // F.6.2: an arc to its own start is omitted; kept as a point-line
        // the segment builder drops.
        return Piece::Line(a, b);
    }
    if rx == 0.0 || ry == 0.0 || !(rx.is_finite() && ry.is_finite() && phi_deg.is_finite()) {
        return Piece::Line(a, b);
    }
    let (sin, cos) = phi_deg.to_radians().sin_cos();
    // Step 1: the midpoint difference in the ellipse's axes.
    let h = a.sub(b).scale(0.5);
    let (x1, y1) = (cos * h.x + sin * h.y, -sin * h.x + cos * h.y);
    // F.6.6: radii too small to reach are scaled up until they just do.
    let lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
    if lambda > 1.0 {
        let k = lambda.sqrt();
        rx *= k;
        ry *= k;
    }
    // Step 2: the centre in those axes.
    let (rx2, ry2, x12, y12) = (rx * rx, ry * ry, x1 * x1, y1 * y1);
    let num = (rx2 * ry2 - rx2 * y12 - ry2 * x12).max(0.0);
    let den = rx2 * y12 + ry2 * x12;
    let mut k = if den > 0.0 { (num / den).sqrt() } else { 0.0 };
    if large == sweep {
        k = -k;
    }
    let (cx1, cy1) = (k * rx * y1 / ry, -k * ry * x1 / rx);
    // Step 3: back to user space.
    let mid = a.add(b).scale(0.5);
    let c = Point::new(cos * cx1 - sin * cy1 + mid.x, sin * cx1 + cos * cy1 + mid.y);
    // Step 4: the start angle and the sweep.
    let angle = |ux: f64, uy: f64| uy.atan2(ux);
    let t0 = angle((x1 - cx1) / rx, (y1 - cy1) / ry);
    let t1 = angle((-x1 - cx1) / rx, (-y1 - cy1) / ry);
    let mut dt = t1 - t0;
    if sweep && dt < 0.0 {
        dt += TAU;
    } else if !sweep && dt > 0.0 {
        dt -= TAU;
    }
    // A half turn by rounding may land on the wrong side: keep the flag's turn.
    if dt.abs() > TAU {
        dt = dt.signum() * TAU;
    }
    if dt == 0.0 {
        dt = if sweep { PI } else { -PI };
    }
    Piece::Arc {
        c,
        major: Point::new(cos * rx, sin * rx),
        minor: Point::new(-sin * ry, cos * ry),
        t0,
        sweep: dt,
        from: a,
        to: b,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Point, b: Point) {
        assert!(a.dist(b) < 1e-9, "{a:?} != {b:?}");
    }

    fn arc_point(p: &Piece, t: f64) -> Point {
        let Piece::Arc {
            c, major, minor, ..
        } = p
        else {
            panic!("{p:?}")
        };
        c.add(major.scale(t.cos())).add(minor.scale(t.sin()))
    }

    #[test]
    fn every_command_absolute_and_relative() {
        let (s, err) = parse("M10 10 h5 v5 H10 V10 z m 20 0 l 5 5 L 40 10 Z");
        assert!(err.is_none());
        assert_eq!(s.len(), 2);
        assert!(s[0].closed && s[1].closed);
        assert_eq!(s[0].pieces.len(), 4);
        assert_eq!(
            s[0].pieces[1],
            Piece::Line(Point::new(15.0, 10.0), Point::new(15.0, 15.0))
        );
        // After z the relative m starts from the first subpath's start.
        assert_eq!(
            s[1].pieces[0],
            Piece::Line(Point::new(30.0, 10.0), Point::new(35.0, 15.0))
        );
        assert_eq!(s[1].pieces.len(), 3);
    }

    #[test]
    fn smooth_curves_mirror_the_last_control_point() {
        let (s, _) = parse("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0 Q 25 5 30 0 T 40 0");
        let p = &s[0].pieces;
        assert_eq!(
            p[1],
            Piece::Cubic([
                Point::new(10.0, 0.0),
                Point::new(10.0, -10.0),
                Point::new(20.0, -10.0),
                Point::new(20.0, 0.0)
            ])
        );
        assert_eq!(
            p[3],
            Piece::Quad([
                Point::new(30.0, 0.0),
                Point::new(35.0, -5.0),
                Point::new(40.0, 0.0)
            ])
        );
        // S after a non-cubic: the first control point is the current point.
        let (s, _) = parse("M0 0 L 5 0 S 10 5 10 0");
        assert_eq!(
            s[0].pieces[1],
            Piece::Cubic([
                Point::new(5.0, 0.0),
                Point::new(5.0, 0.0),
                Point::new(10.0, 5.0),
                Point::new(10.0, 0.0)
            ])
        );
    }

    #[test]
    fn a_half_circle_arc_by_hand() {
        // From (0,0) to (20,0), r 10, sweep flag 1: centre (10,0); the
        // positive-angle direction from angle π passes 3π/2, (10,-10)
        // (over the top on a y-down screen, as browsers draw it).
        let p = arc(
            Point::new(0.0, 0.0),
            Point::new(20.0, 0.0),
            10.0,
            10.0,
            0.0,
            false,
            true,
        );
        let Piece::Arc { c, sweep, t0, .. } = p else {
            panic!()
        };
        close(c, Point::new(10.0, 0.0));
        assert!((sweep - PI).abs() < 1e-9 && (t0.abs() - PI).abs() < 1e-9);
        close(arc_point(&p, t0 + sweep / 2.0), Point::new(10.0, -10.0));
        close(arc_point(&p, t0 + sweep), Point::new(20.0, 0.0));
    }

    #[test]
    fn the_large_arc_flag_picks_the_long_way_round() {
        // r 10 from (0,0) to (10,10): small arc 90°, large 270°.
        let small = arc(
            Point::new(0.0, 0.0),
            Point::new(10.0, 10.0),
            10.0,
            10.0,
            0.0,
            false,
            true,
        );
        let large = arc(
            Point::new(0.0, 0.0),
            Point::new(10.0, 10.0),
            10.0,
            10.0,
            0.0,
            true,
            true,
        );
        let sw = |p: Piece| match p {
            Piece::Arc { sweep, .. } => sweep,
            _ => f64::NAN,
        };
        assert!((sw(small) - PI / 2.0).abs() < 1e-9);
        assert!((sw(large) - 1.5 * PI).abs() < 1e-9);
        close(
            arc_point(&large, {
                let Piece::Arc { t0, sweep, .. } = large else {
                    panic!()
                };
                t0 + sweep
            }),
            Point::new(10.0, 10.0),
        );
    }

    #[test]
    fn radii_too_small_are_scaled_up_and_rotation_is_applied() {
        // r 1 cannot reach 20 apart: becomes r 10, a half circle.
        let p = arc(
            Point::new(0.0, 0.0),
            Point::new(20.0, 0.0),
            1.0,
            1.0,
            0.0,
            false,
            false,
        );
        let Piece::Arc {
            c, major, sweep, ..
        } = p
        else {
            panic!()
        };
        close(c, Point::new(10.0, 0.0));
        assert!((major.norm() - 10.0).abs() < 1e-9 && (sweep + PI).abs() < 1e-9);
        // An ellipse 20 × 10 turned 90°: its major axis runs along y.
        let p = arc(
            Point::new(0.0, -20.0),
            Point::new(0.0, 20.0),
            20.0,
            10.0,
            90.0,
            false,
            true,
        );
        let Piece::Arc {
            c, major, minor, ..
        } = p
        else {
            panic!()
        };
        close(c, Point::new(0.0, 0.0));
        close(major, Point::new(0.0, 20.0));
        close(minor, Point::new(-10.0, 0.0));
    }

    #[test]
    fn compact_arc_flags_and_errors() {
        let (s, err) = parse("M10 10 a 25 25 0 1125 25");
        assert!(err.is_none(), "{err:?}");
        assert!(matches!(s[0].pieces[0], Piece::Arc { .. }));
        let (s, err) = parse("M0 0 L 10 0 L 10 X 5");
        assert_eq!(s[0].pieces.len(), 1);
        assert!(err.is_some());
    }
}
