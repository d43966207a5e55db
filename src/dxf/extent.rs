//! The drawing's extent for the units check, without trigonometry.
//!
//! [`Segment::bbox`] takes an arc's start angle (`atan2`), its sweep
//! (`atan`), a `rem_euclid` per axis and `sin`/`cos` per axis crossing:
//! on a big nest that was 6 % of reading. Here the four axis points come
//! from a table (the same `cos`/`sin` values, computed once), and whether
//! an axis direction lies within the sweep is decided from cross products
//! with the end vectors when the answer is clear by a wide margin. When it
//! is not (an end point on an axis, as every half circle has), the point
//! is added only if that changes nothing, else the exact test of
//! `Segment::bbox` decides. Points are added in the same order with the same
//! operations, so the box is bit for bit the one `Segment::bbox` gives.

use crate::geom::{angle_in_sweep, BBox, Point, Segment};

/// Axis directions 0°, 90°, 180°, 270° as `Segment::bbox` computes them.
pub struct Axes([(f64, f64); 4]);

impl Axes {
    pub fn new() -> Self {
        Axes(std::array::from_fn(|k| {
            let ang = k as f64 * std::f64::consts::FRAC_PI_2;
            (ang.cos(), ang.sin())
        }))
    }
}

/// Unit axis directions (exact), for the cross products.
const DIRS: [(f64, f64); 4] = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)];

/// Inside or outside the sweep, when sure.
fn clear(va: Point, vb: Point, ccw: bool, margin: f64, k: usize) -> Option<bool> {
    let (ux, uy) = DIRS[k];
    // sin of the angle from the start to the axis, and from the axis to the end,
    // both measured in the arc's turning direction (scaled by the vector lengths).
    let (mut s0, mut s1) = (va.x * uy - va.y * ux, ux * vb.y - uy * vb.x);
    if !ccw {
        (s0, s1) = (-s0, -s1);
    }
    let m0 = margin * (va.x.abs() + va.y.abs());
    let m1 = margin * (vb.x.abs() + vb.y.abs());
    if s0 > m0 && s1 > m1 {
        Some(true)
    } else if s0 < -m0 || s1 < -m1 {
        Some(false)
    } else {
        None
    }
}

fn same(a: &BBox, b: &BBox) -> bool {
    let bits = |x: &BBox| [x.min.x, x.min.y, x.max.x, x.max.y].map(f64::to_bits);
    bits(a) == bits(b)
}

/// `s.bbox()`, bit for bit, mostly without trigonometry.
pub fn segment_bbox(s: &Segment, axes: &Axes) -> BBox {
    let mut bb = BBox::EMPTY;
    bb.add(s.a);
    bb.add(s.b);
    let Some((c, r)) = s.arc_center() else {
        return bb;
    };
    // Sweeps over 180° (bulge > 1) are not split by the reader; rare.
    if s.bulge.is_nan() || s.bulge.abs() > 1.0 {
        return s.bbox();
    }
    let (va, vb) = (s.a.sub(c), s.b.sub(c));
    // The angles `Segment::bbox` works with are within a few ulps of these
    // vectors' directions (the centre's rounding over the radius); the
    // margin is many orders above that.
    let scale = c.x.abs() + c.y.abs() + s.a.x.abs() + s.a.y.abs() + r;
    let margin = 1e-9 + 1e-10 * scale / r;
    let mut exact: Option<(f64, f64)> = None;
    for (k, &(cos, sin)) in axes.0.iter().enumerate() {
        let p = Point::new(c.x + r * cos, c.y + r * sin);
        let inside = match clear(va, vb, s.bulge > 0.0, margin, k) {
            Some(v) => v,
            None => {
                let mut with = bb;
                with.add(p);
                if same(&with, &bb) {
                    continue;
                }
                let (start, sweep) = *exact.get_or_insert_with(|| (va.y.atan2(va.x), s.sweep()));
                angle_in_sweep(start, sweep, k as f64 * std::f64::consts::FRAC_PI_2)
            }
        };
        if inside {
            bb.add(p);
        }
    }
    bb
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Xorshift;

    fn check(s: &Segment, axes: &Axes) {
        let (a, b) = (segment_bbox(s, axes), s.bbox());
        assert!(same(&a, &b), "{s:?}: {a:?} vs {b:?}");
    }

    #[test]
    fn matches_segment_bbox_on_random_arcs_and_axis_end_points() {
        let axes = Axes::new();
        let mut st = Xorshift(0x9E37_79B9_7F4A_7C15);
        for i in 0..200_000 {
            let c = Point::new(st.unit() * 2e3 - 1e3, st.unit() * 2e3 - 1e3);
            let r = 10f64.powf(st.unit() * 8.0 - 4.0);
            // Start and end on axes or near them half of the time.
            let snap = |x: f64, st: &mut Xorshift| {
                if i % 2 == 0 {
                    (x * 4.0).round() / 4.0 * std::f64::consts::TAU
                        + (st.unit() - 0.5) * 1e-12 * (i % 4) as f64
                } else {
                    x * std::f64::consts::TAU
                }
            };
            let start = snap(st.unit(), &mut st);
            let sweep = (st.unit() * 2.0 - 1.0) * std::f64::consts::TAU;
            for s in crate::geom::arc_pieces(c, r, start, sweep) {
                check(&s, &axes);
            }
        }
    }

    #[test]
    fn matches_on_circles_lines_and_big_bulges() {
        let axes = Axes::new();
        for s in crate::geom::arc_pieces(Point::new(25.0, 30.0), 10.0, 0.0, std::f64::consts::TAU) {
            check(&s, &axes);
        }
        let (a, b) = (Point::new(0.0, 0.0), Point::new(3.0, -4.0));
        for bulge in [0.0, 1e-13, 1e-9, 0.5, 1.0, -1.0, 2.5, -7.0, f64::NAN] {
            check(&Segment { a, b, bulge }, &axes);
        }
    }
}
