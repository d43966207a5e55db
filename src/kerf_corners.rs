//! Whether `kerf::invalid_vertices` must look at a loop at all: one cross
//! product a corner (no `atan2`, `sin` or `cos`) settles most loops of a
//! sheet (a rectangle's outer contour, a round hole) as having none.

use crate::geom::{Point, Segment};

/// Directions of travel at a segment's start and end, unnormalised and
/// without trigonometry: an arc's chord turned by ∓ half its sweep (by
/// 2·atan b: cos = (1 − b²)/(1 + b²), sin = 2b/(1 + b²), the common
/// denominator dropped). Within ~1e-15 rad of `geom::end_tangents`.
fn travel(s: &Segment) -> (Point, Point) {
    let c = s.b.sub(s.a);
    if s.is_line() {
        return (c, c);
    }
    let b = s.bulge;
    let (k, m) = (1.0 - b * b, 2.0 * b);
    (
        Point::new(c.x * k + c.y * m, c.y * k - c.x * m),
        Point::new(c.x * k - c.y * m, c.y * k + c.x * m),
    )
}

/// True when `kerf::invalid_vertices` surely finds nothing on this
/// counter-clockwise loop (false: it must look). A corner is invalid only
/// when it turns towards the scrap by more than θ0, where the kerf's
/// rounding half·(1/cos(θ/2) − 1) leaves the tolerance behind; an arc only
/// when it bends towards the scrap with a radius under `half`. Every
/// corner here either turns away from the scrap (by more than 1e-9 of a
/// radian's sine) or by less than θ0·(1 − 1e-6) either way: margins a
/// million times the error of the trigonometric tangents that function
/// measures with, so it decides the same. Arcs bending towards the scrap
/// are measured with its own `arc_center`. A rectangle's outer contour, a
/// round hole: one cross product a corner, no `atan2`, `sin` or `cos`.
#[cfg(test)]
pub(crate) fn no_invalid_vertices(segs: &[Segment], scrap_left: bool, half: f64, tol: f64) -> bool {
    Corners::new(half, tol).none_invalid(segs, scrap_left, half)
}

/// [`no_invalid_vertices`]'s bound on a slight turn, worked out once for
/// the whole job (an `acos` and a `tan` that were a tenth of the kerf
/// stage when taken per contour).
pub(crate) struct Corners {
    /// tan of the largest slight turn; None: always look.
    small: Option<f64>,
}

impl Corners {
    pub(crate) fn new(half: f64, tol: f64) -> Corners {
        let theta0 = 2.0 * (half / (half + tol)).acos();
        // Below 1e-3 rad the function's own 1/cos − 1 is too coarse for the
        // margin (and NaN settings fail here too).
        let small = (!(theta0.is_nan() || theta0 < 1e-3)).then(|| (theta0 * (1.0 - 1e-6)).tan());
        Corners { small }
    }

    /// [`no_invalid_vertices`] with the `half` given to [`Corners::new`].
    pub(crate) fn none_invalid(&self, segs: &[Segment], scrap_left: bool, half: f64) -> bool {
        match self.small {
            Some(small) => none_invalid(segs, scrap_left, half, small),
            None => false,
        }
    }
}

fn none_invalid(segs: &[Segment], scrap_left: bool, half: f64, small: f64) -> bool {
    let mut incoming = match segs.last() {
        Some(s) => travel(s).1,
        None => return true,
    };
    for s in segs {
        let (start, end) = travel(s);
        let (u, v) = (incoming, start);
        let (cr, dt) = (u.cross(v), u.dot(v));
        let scale = u.norm() * v.norm();
        if !(scale > 0.0 && scale.is_finite()) {
            return false;
        }
        let slight = dt > 0.0 && cr.abs() <= small * dt;
        let away = if scrap_left {
            cr < -1e-9 * scale
        } else {
            cr > 1e-9 * scale
        };
        if !(slight || away) {
            return false;
        }
        if !s.is_line() && s.is_ccw() == scrap_left {
            if let Some((_, r)) = s.arc_center() {
                if r < half {
                    return false;
                }
            }
        }
        incoming = end;
    }
    true
}
