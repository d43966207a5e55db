//! Contour-parallel clearing (paper 004 §5.1 item 5, thesis L667,
//! L573–L580): the walls offset inward again and again, a stepover
//! apart, until nothing is left; cut from the centre outwards, each loop
//! widening what the one before cleared, or from the walls in, the middle
//! holding the stock while the walls are cut. Arcs stay arcs.

use super::region::{Loop, Pocket};
use crate::process::OffsetFrom;

/// The loops at `first`, `first + step`, … inside the walls, level by
/// level in the order `from` says (innermost level first from the
/// centre, the walls' first from the walls); at most `max_levels` levels.
pub fn levels(
    pocket: &Pocket,
    first: f64,
    step: f64,
    from: OffsetFrom,
    max_levels: usize,
) -> Vec<Vec<Loop>> {
    let mut out = Vec::new();
    if step.is_nan() || step <= 0.0 {
        return out;
    }
    for k in 0..max_levels {
        let r = pocket.inset(first + step * k as f64);
        if r.is_empty() {
            break;
        }
        out.push(r.loops);
    }
    if from == OffsetFrom::Centre {
        out.reverse();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{Point, Segment};

    fn circle(r: f64) -> Vec<Segment> {
        let (a, b) = (Point::new(r, 0.0), Point::new(-r, 0.0));
        vec![
            Segment { a, b, bulge: 1.0 },
            Segment {
                a: b,
                b: a,
                bulge: 1.0,
            },
        ]
    }

    #[test]
    fn an_r20_pocket_with_an_r1_tool_at_step_2_is_ten_loops_innermost_first() {
        // Paper 004 §5.3: loops at radii 19, 17, … 1, cut from radius 1 out.
        let p = Pocket::new(&circle(20.0), &[], 0.01);
        let lv = levels(&p, 1.0, 2.0, OffsetFrom::Centre, 100);
        assert_eq!(lv.len(), 10);
        for (k, loops) in lv.iter().enumerate() {
            assert_eq!(loops.len(), 1);
            let want = 1.0 + 2.0 * k as f64;
            let l = &loops[0];
            for s in &l.segments {
                assert!((s.a.dist(Point::new(0.0, 0.0)) - want).abs() < 1e-6, "{k}");
            }
            // Arcs kept: the loop's area is the circle's, not a polygon's.
            let area = std::f64::consts::PI * want * want;
            assert!((l.area() - area).abs() < 1e-6 * area, "{k}");
        }
    }

    #[test]
    fn from_the_walls_the_same_ten_loops_come_outermost_first() {
        // The reverse of paper 004 §5.3's order: radii 19, 17, … 1.
        let p = Pocket::new(&circle(20.0), &[], 0.01);
        let lv = levels(&p, 1.0, 2.0, OffsetFrom::Walls, 100);
        let radii: Vec<f64> = (lv.iter())
            .map(|l| l[0].segments[0].a.dist(Point::new(0.0, 0.0)))
            .collect();
        assert_eq!(radii.len(), 10);
        for (k, r) in radii.iter().enumerate() {
            assert!((r - (19.0 - 2.0 * k as f64)).abs() < 1e-6, "{radii:?}");
        }
    }
}
