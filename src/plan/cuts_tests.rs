//! Tests of `cuts`.

use super::*;

#[test]
fn a_loop_split_at_a_clicked_point_keeps_its_length_and_closes() {
    let c = Point::new(0.0, 0.0);
    let segs = vec![
        Segment {
            a: Point::new(10.0, 0.0),
            b: Point::new(-10.0, 0.0),
            bulge: 1.0,
        },
        Segment {
            a: Point::new(-10.0, 0.0),
            b: Point::new(10.0, 0.0),
            bulge: 1.0,
        },
    ];
    let click = Point::new(0.0, 12.0);
    let out = split_loop_at(&segs, click);
    assert_eq!(out.len(), 3);
    assert!(out[0].a.dist(Point::new(0.0, 10.0)) < 1e-9);
    assert!(out[2].b.dist(out[0].a) < 1e-9);
    let total: f64 = out.iter().map(Segment::length).sum();
    assert!((total - 20.0 * std::f64::consts::PI).abs() < 1e-9);
    for w in out.windows(2) {
        assert!(w[0].b.dist(w[1].a) < 1e-9);
    }
    let _ = c;
}
