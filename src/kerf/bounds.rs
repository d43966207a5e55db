//! Questions `kerf::offset` asks of every loop, settled without
//! trigonometry where the answer is certain: whether
//! `kerf::invalid_vertices` must look at it at all (one cross product a
//! corner), and whether an offset's area passes the tolerance (bounds on
//! each arc's circular segment instead of its `atan`). A rectangle's outer
//! contour, a round hole: both settled at once.

use cavalier_contours::polyline::{PlineSource, Polyline};

use crate::geom::{Point, Segment};

/// `pl.area().abs() > limit` (the library's area: the shoelace sum plus
/// each arc's circular segment, its sector `4 atan b · r²` less a
/// triangle), without the `atan` where the answer is certain. A circular
/// segment of chord c and sagitta s = |b| c / 2 (|b| <= 1: at most a half
/// circle) holds the triangle on its chord up to its apex (area c s / 2)
/// and lies in the c × s rectangle on its chord, so twice its area is
/// between |b| c² / 2 and |b| c². The library's sum differs from the true
/// one by rounding only: a few ulps of each of its terms, the largest of
/// which are the shoelace products and an arc's sector and triangle
/// (about c² / (4 |b|) each, nearly cancelling for a flat arc). Where the
/// bounds, widened by a million times that rounding, are on one side of
/// the limit, so is the library's area; elsewhere it is computed.
pub(crate) fn area_exceeds(pl: &Polyline<f64>, limit: f64) -> bool {
    let n = pl.vertex_count();
    if !pl.is_closed() || n < 2 {
        return pl.area().abs() > limit;
    }
    // Twice the area: the shoelace sum, the arcs' least and most.
    let (mut twice, mut lo, mut hi, mut size) = (0.0, 0.0, 0.0, 0.0);
    for i in 0..n {
        let (v1, v2) = (pl.at(i), pl.at((i + 1) % n));
        let (p, q) = (v1.x * v2.y, v1.y * v2.x);
        twice += p - q;
        size += p.abs() + q.abs();
        let b = v1.bulge;
        if b.abs() > 1.0 {
            // More than a half circle: the bounds above do not hold.
            return pl.area().abs() > limit;
        }
        if b != 0.0 {
            let c2 = (v2.x - v1.x).powi(2) + (v2.y - v1.y).powi(2);
            let (least, most) = (b.abs() * c2 / 2.0, b.abs() * c2);
            if b > 0.0 {
                (lo, hi) = (lo + least, hi + most);
            } else {
                (lo, hi) = (lo - most, hi - least);
            }
            size += c2 * (1.0 + 1.0 / b.abs());
        }
    }
    let margin = 1e-10 * size;
    let (lo, hi) = (twice + lo - margin, twice + hi + margin);
    let twice_limit = 2.0 * limit;
    if !(lo.is_finite() && hi.is_finite() && twice_limit.is_finite()) {
        return pl.area().abs() > limit;
    }
    if lo > twice_limit || hi < -twice_limit {
        return true;
    }
    if lo >= -twice_limit && hi <= twice_limit {
        return false;
    }
    pl.area().abs() > limit
}

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
        // |u| |v| by one square root (two `hypot` calls were a tenth of
        // the kerf stage): the margins below are a million times either
        // rounding; an overflow or underflow fails the test after and
        // leaves the loop to the full scan.
        let scale = (u.dot(u) * v.dot(v)).sqrt();
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
