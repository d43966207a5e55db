//! ELLIPSE → arcs (biarcs, [`super::biarc`]) within a chord tolerance
//! (paper 004's chord criterion). ELLIPSE (DXF reference): centre 10/20,
//! major-axis end 11/21 relative to the centre, ratio 40, parameters 41/42,
//! extrusion 210/220/230.

use super::biarc;
use super::curves::{close_up, MAX_LINES};
use super::pairs::Pair;
use crate::geom::{Point, Segment};
use crate::text;
use crate::warning::Text;

/// ELLIPSE → arcs within `tol` (drawing units), in world coordinates (an
/// ELLIPSE's points are WCS; extrusion (0,0,-1) reverses its turn).
pub fn ellipse(pairs: &[Pair], tol: f64) -> Result<(Vec<Segment>, bool), Text> {
    let num = |c: i32| super::entities::num(pairs, c);
    let c = Point::new(num(10).unwrap_or(0.0), num(20).unwrap_or(0.0));
    let major = Point::new(num(11).unwrap_or(0.0), num(21).unwrap_or(0.0));
    let ratio = num(40).unwrap_or(1.0);
    let (t0, mut t1) = (
        num(41).unwrap_or(0.0),
        num(42).unwrap_or(std::f64::consts::TAU),
    );
    // The ellipse lies in the plane of its extrusion N (210/220/230) through
    // its WCS centre; the minor axis is ratio · (N × major) (DXF reference,
    // ELLIPSE). Seen from above (projected onto XY) it is still an ellipse,
    // the image of a circle by an affine map: N = +Z gives (−My, Mx),
    // N = −Z gives (My, −Mx), a tilted N foreshortens it.
    let n = [
        num(210).unwrap_or(0.0),
        num(220).unwrap_or(0.0),
        num(230).unwrap_or(1.0),
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let n = if len.is_finite() && len > 1e-12 {
        n.map(|v| v / len)
    } else {
        [0.0, 0.0, 1.0]
    };
    let mz = num(31).filter(|v| v.is_finite()).unwrap_or(0.0);
    let a = (major.x * major.x + major.y * major.y + mz * mz).sqrt();
    if !(c.is_finite()
        && a.is_finite()
        && a > 0.0
        && ratio.is_finite()
        && ratio > 0.0
        && t0.is_finite()
        && t1.is_finite())
    {
        return Err(text!("centre, axis or ratio is not usable";
                         "centro, eixo ou razão inutilizável"));
    }
    let minor = Point::new(n[1] * mz - n[2] * major.y, n[2] * major.x - n[0] * mz).scale(ratio);
    if !minor.is_finite() {
        return Err(text!("centre, axis or ratio is not usable";
                         "centro, eixo ou razão inutilizável"));
    }
    while t1 <= t0 {
        t1 += std::f64::consts::TAU;
    }
    let full = (t1 - t0 - std::f64::consts::TAU).abs() < 1e-9;
    let f = EllipseCurve { c, major, minor };
    let mut segs = Vec::new();
    let quarters = ((t1 - t0) / std::f64::consts::FRAC_PI_2).ceil().max(1.0) as usize;
    for q in 0..quarters {
        let a0 = t0 + (t1 - t0) * q as f64 / quarters as f64;
        let a1 = t0 + (t1 - t0) * (q + 1) as f64 / quarters as f64;
        biarc::fit(&f, a0, a1, tol, MAX_LINES, &mut segs);
    }
    let closed = full && close_up(&mut segs, true, 0.0);
    Ok((segs, closed))
}

/// c + major·cos t + minor·sin t, with its exact velocity.
pub(crate) struct EllipseCurve {
    pub(crate) c: Point,
    pub(crate) major: Point,
    pub(crate) minor: Point,
}

impl biarc::Curve for EllipseCurve {
    fn at(&self, t: f64) -> Point {
        let (sin, cos) = t.sin_cos();
        self.c.add(self.major.scale(cos)).add(self.minor.scale(sin))
    }
    fn at_with_velocity(&self, t: f64) -> (Point, Option<Point>) {
        let (sin, cos) = t.sin_cos();
        let at = self.c.add(self.major.scale(cos)).add(self.minor.scale(sin));
        (at, Some(self.minor.scale(cos).sub(self.major.scale(sin))))
    }
}
