//! Tests of [`super`]: crossings, and the pierce check against the least distance.

use super::*;

#[test]
fn clear_of_answers_as_the_least_distance_does() {
    // Closed loops of lines, minor and major arcs (a bulge above 1 is
    // where the arc bulges past its chord's circle), scattered; points
    // thrown all over and near the loops, clearances small and large.
    let mut seed = 77u64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut entities = Vec::new();
    for _ in 0..60 {
        let c = Point::new(rnd() * 400.0, rnd() * 300.0);
        let r = 2.0 + rnd() * 20.0;
        let k = 2 + (rnd() * 4.0) as usize;
        let pts: Vec<Point> = (0..k)
            .map(|j| {
                let a = std::f64::consts::TAU * j as f64 / k as f64;
                c.add(Point::new(a.cos(), a.sin()).scale(r))
            })
            .collect();
        let segments: Vec<Segment> = (0..k)
            .map(|j| Segment {
                a: pts[j],
                b: pts[(j + 1) % k],
                bulge: [0.0, 0.3, 1.0, 1.8, -0.2][(rnd() * 5.0) as usize % 5],
            })
            .collect();
        entities.push(crate::dxf::Entity {
            kind: "LWPOLYLINE",
            layer: 0,
            place: crate::dxf::Place::Line(1),
            segments,
            closed: true,
            source: None,
        });
    }
    let d = crate::dxf::Drawing {
        entities,
        ..crate::dxf::Drawing::default()
    };
    let contours = crate::contour::extract(&d, crate::geom::Tolerance(1e-3), 0.05);
    let o = Obstacles::new(&contours, 1e-3);
    let (mut clear, mut near) = (0, 0);
    for _ in 0..4000 {
        let p = Point::new(rnd() * 440.0 - 20.0, rnd() * 340.0 - 20.0);
        let c = [0.5, 1.5, 4.0, 12.0][(rnd() * 4.0) as usize % 4];
        let by_distance = o.distance(p, 2.0 * c + 1.0) >= c;
        assert_eq!(o.clear_of(p, c), by_distance, "{p:?} {c}");
        if by_distance {
            clear += 1;
        } else {
            near += 1;
        }
    }
    assert!(clear > 400 && near > 400, "{clear} clear, {near} near");
}

#[test]
fn line_crossings_with_lines_and_arcs() {
    let l = Segment::line(Point::new(-5.0, 0.0), Point::new(5.0, 0.0));
    let v = Segment::line(Point::new(0.0, -1.0), Point::new(0.0, 1.0));
    assert_eq!(crossings(&l, &v).len(), 1);
    let far = Segment::line(Point::new(7.0, -1.0), Point::new(7.0, 1.0));
    assert!(crossings(&l, &far).is_empty());
    // Upper half circle of radius 3 around the origin: the line y = 0
    // meets it at both ends.
    let arc = Segment {
        a: Point::new(3.0, 0.0),
        b: Point::new(-3.0, 0.0),
        bulge: 1.0,
    };
    assert_eq!(crossings(&l, &arc).len(), 2);
    let above = Segment::line(Point::new(-5.0, 2.0), Point::new(5.0, 2.0));
    assert_eq!(crossings(&above, &arc).len(), 2);
    let below = Segment::line(Point::new(-5.0, -2.0), Point::new(5.0, -2.0));
    assert!(crossings(&below, &arc).is_empty());
}
