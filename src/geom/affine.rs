//! Affine maps of the plane and segments through them (units scaling, block
//! inserts, OCS mirroring, nest placements).

use super::{flatten_count, Point, Segment};

/// A 2-D affine map `p' = [a b; d e]·p + [c; f]`: units scaling, block
/// inserts (translate, rotate, scale, mirror) and OCS mirroring.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine {
    /// Row 1: x' = a x + b y + c.
    pub a: f64,
    /// See `a`.
    pub b: f64,
    /// See `a`.
    pub c: f64,
    /// Row 2: y' = d x + e y + f.
    pub d: f64,
    /// See `d`.
    pub e: f64,
    /// See `d`.
    pub f: f64,
}

impl Affine {
    /// The identity.
    pub const IDENTITY: Affine = Affine {
        a: 1.0,
        b: 0.0,
        c: 0.0,
        d: 0.0,
        e: 1.0,
        f: 0.0,
    };
    /// Uniform scaling about the origin.
    pub fn scale(k: f64) -> Affine {
        Affine::scale_xy(k, k)
    }
    /// Scaling by `sx`, `sy` about the origin (negative = mirror).
    pub fn scale_xy(sx: f64, sy: f64) -> Affine {
        Affine {
            a: sx,
            b: 0.0,
            c: 0.0,
            d: 0.0,
            e: sy,
            f: 0.0,
        }
    }
    /// Translation.
    pub fn translate(x: f64, y: f64) -> Affine {
        Affine {
            a: 1.0,
            b: 0.0,
            c: x,
            d: 0.0,
            e: 1.0,
            f: y,
        }
    }
    /// Counter-clockwise rotation by `deg` degrees about the origin.
    pub fn rotate_deg(deg: f64) -> Affine {
        let (s, c) = deg.to_radians().sin_cos();
        Affine {
            a: c,
            b: -s,
            c: 0.0,
            d: s,
            e: c,
            f: 0.0,
        }
    }
    /// `self ∘ o`: apply `o` first, then `self`.
    pub fn then_after(&self, o: &Affine) -> Affine {
        Affine {
            a: self.a * o.a + self.b * o.d,
            b: self.a * o.b + self.b * o.e,
            c: self.a * o.c + self.b * o.f + self.c,
            d: self.d * o.a + self.e * o.d,
            e: self.d * o.b + self.e * o.e,
            f: self.d * o.c + self.e * o.f + self.f,
        }
    }
    /// The image of a point.
    pub fn apply(&self, p: Point) -> Point {
        Point::new(
            self.a * p.x + self.b * p.y + self.c,
            self.d * p.x + self.e * p.y + self.f,
        )
    }
    /// Determinant (< 0 mirrors).
    pub fn det(&self) -> f64 {
        self.a * self.e - self.b * self.d
    }
    /// Geometric mean scale factor (lengths grow by about this much).
    pub fn mean_scale(&self) -> f64 {
        self.det().abs().sqrt()
    }
    /// True when circles stay circles: the linear part is a rotation times a
    /// uniform scale, possibly mirrored, to within `rel` relative error.
    pub fn is_similarity(&self, rel: f64) -> bool {
        let c1 = (self.a * self.a + self.d * self.d).sqrt();
        let c2 = (self.b * self.b + self.e * self.e).sqrt();
        let dot = self.a * self.b + self.d * self.e;
        let m = c1.max(c2);
        m > 0.0 && (c1 - c2).abs() <= rel * m && dot.abs() <= rel * m * m
    }
    /// True when every coefficient is finite.
    pub fn is_finite(&self) -> bool {
        [self.a, self.b, self.c, self.d, self.e, self.f]
            .iter()
            .all(|v| v.is_finite())
    }
}

/// Maps segments through an affine map. Arcs stay arcs under a similarity
/// (a mirror flips their turn); under a non-uniform scale they become
/// elliptical and are replaced by lines within `chord` (in output units).
pub fn transform_segments(segs: &[Segment], m: &Affine, chord: f64, out: &mut Vec<Segment>) {
    let similar = m.is_similarity(1e-9);
    let flip = m.det() < 0.0;
    for s in segs {
        if s.is_line() || similar {
            out.push(Segment {
                a: m.apply(s.a),
                b: m.apply(s.b),
                bulge: if flip { -s.bulge } else { s.bulge },
            });
        } else if let Some((_, r)) = s.arc_center() {
            // Sample the arc finely enough that its image is within the chord tolerance.
            let r_out = r * m.a.abs().max(m.b.abs()).max(m.d.abs()).max(m.e.abs()) * 2.0;
            let n = flatten_count(r_out, s.sweep().abs(), chord);
            let mut prev = m.apply(s.a);
            for k in 1..=n {
                let q = if k == n {
                    m.apply(s.b)
                } else {
                    m.apply(s.point_at(k as f64 / n as f64))
                };
                out.push(Segment::line(prev, q));
                prev = q;
            }
        } else {
            out.push(Segment::line(m.apply(s.a), m.apply(s.b)));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mirrored_insert_flips_arc_turn_and_keeps_radius() {
        let s = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let m = Affine::translate(5.0, 5.0).then_after(&Affine::scale_xy(-2.0, 2.0));
        let mut out = vec![];
        transform_segments(&[s], &m, 0.01, &mut out);
        assert_eq!(out.len(), 1);
        assert!(out[0].bulge < 0.0);
        let (c, r) = out[0].arc_center().unwrap();
        assert!((r - 20.0).abs() < 1e-9 && c.dist(Point::new(5.0, 5.0)) < 1e-9);
    }

    #[test]
    fn non_uniform_scale_turns_an_arc_into_lines_within_the_chord_tolerance() {
        let s = Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        };
        let m = Affine::scale_xy(1.0, 0.5);
        let mut out = vec![];
        transform_segments(&[s], &m, 0.01, &mut out);
        assert!(out.len() > 10 && out.iter().all(Segment::is_line));
        for seg in &out {
            let mid = seg.point_at(0.5);
            // On the ellipse x²/100 + y²/25 = 1 within the tolerance.
            let t = (mid.x / 10.0).hypot(mid.y / 5.0);
            assert!((1.0 - t) * 5.0 < 0.011, "{t}");
        }
    }
}
