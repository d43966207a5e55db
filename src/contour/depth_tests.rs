//! Containment depth tests (split from depth.rs).

use super::*;
use crate::geom::arc_pieces;

#[test]
fn point_in_circle_made_of_two_arcs() {
    let c = arc_pieces(Point::new(0.0, 0.0), 10.0, 0.0, std::f64::consts::TAU);
    assert!(point_in_loop(Point::new(9.9, 0.5), &c));
    assert!(point_in_loop(Point::new(0.0, -9.0), &c));
    assert!(!point_in_loop(Point::new(7.2, 7.2), &c));
    assert!(!point_in_loop(Point::new(-11.0, 0.0), &c));
    let rev: Vec<_> = c.iter().rev().map(Segment::reversed).collect();
    assert!(point_in_loop(Point::new(0.0, 9.5), &rev));
}

#[test]
fn banded_point_test_agrees_with_the_plain_one() {
    // A wavy closed outline of lines and arcs, 400 segments.
    let n = 200;
    let mut segs = Vec::new();
    let pt = |k: usize| {
        let a = k as f64 / n as f64 * std::f64::consts::TAU;
        let r = 50.0 + 8.0 * (7.0 * a).sin();
        Point::new(r * a.cos(), r * a.sin())
    };
    for k in 0..n {
        let (a, b) = (pt(k), pt(k + 1));
        let m = a.add(b).scale(0.5);
        segs.push(Segment {
            a,
            b: m,
            bulge: 0.3,
        });
        segs.push(Segment::line(m, b));
    }
    // And a short loop (its bands kept inline): a slot with round ends.
    let (a, b, c, d) = (
        Point::new(-40.0, -10.0),
        Point::new(40.0, -10.0),
        Point::new(40.0, 10.0),
        Point::new(-40.0, 10.0),
    );
    let slot = vec![
        Segment::line(a, b),
        Segment {
            a: b,
            b: c,
            bulge: 1.0,
        },
        Segment::line(c, d),
        Segment {
            a: d,
            b: a,
            bulge: 1.0,
        },
    ];
    for segs in [&segs, &slot] {
        let l = Loop::new(segs, &crate::geom::path_bbox(segs));
        assert_eq!(
            matches!(l.bands.index, BandIndex::Ranges(..)),
            segs.len() <= INLINE
        );
        let mut x = 12345u64;
        for _ in 0..5000 {
            x = crate::test_rng::Xorshift(x).next();
            let p = Point::new(
                (x % 14_000) as f64 / 100.0 - 70.0,
                ((x >> 20) % 14_000) as f64 / 100.0 - 70.0,
            );
            assert_eq!(l.contains(p), point_in_loop(p, segs), "{p:?}");
            let plain = segs.iter().all(|s| dist_to_segment(p, s) > 0.5);
            assert_eq!(l.clear_of(p, 0.5), plain, "{p:?}");
        }
    }
}
