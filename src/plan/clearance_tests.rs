//! Tests of [`super`]: crossings, and the pierce check against the least distance.

use super::*;

#[test]
fn clear_of_answers_as_the_least_distance_does() {
    // Closed loops of lines, minor and major arcs (a bulge above 1 is
    // where the arc bulges past its chord's circle), scattered; points
    // thrown all over and near the loops, clearances small and large.
    let mut rnd = crate::test_rng::unit(77);
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
        entities.push(closed_polyline(segments));
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

/// Random lines and arcs of every turn, both ways (xorshift, fixed seed).
fn random_segments(n: usize, seed: u64) -> Vec<Segment> {
    let mut rnd = crate::test_rng::unit(seed);
    (0..n)
        .map(|_| {
            let a = Point::new(rnd() * 3000.0 - 500.0, rnd() * 1500.0);
            let len = [0.01, 0.5, 3.0, 40.0][(rnd() * 4.0) as usize % 4];
            let b = a.add(Point::new(rnd() - 0.5, rnd() - 0.5).scale(2.0 * len));
            let bulge = [0.0, 1e-6, 0.05, 0.41, 0.99, 1.0, 1.7, 8.0][(rnd() * 8.0) as usize % 8]
                * if rnd() < 0.5 { -1.0 } else { 1.0 };
            Segment { a, b, bulge }
        })
        .collect()
}

#[test]
fn an_index_box_holds_every_point_of_its_segment() {
    // Checked on points placed by `Segment::point_at` (angles, sines and
    // cosines), not by the box's own chord-side test.
    for s in random_segments(3000, 0x2545_F491_4F6C_DD1D) {
        let b = index_box(&s);
        let exact = s.bbox();
        assert!(
            b.min.x <= exact.min.x && b.min.y <= exact.min.y,
            "{s:?} {b:?} {exact:?}"
        );
        assert!(
            b.max.x >= exact.max.x && b.max.y >= exact.max.y,
            "{s:?} {b:?} {exact:?}"
        );
        for k in 0..=256 {
            let p = s.point_at(k as f64 / 256.0);
            assert!(
                (b.min.x..=b.max.x).contains(&p.x) && (b.min.y..=b.max.y).contains(&p.y),
                "{s:?}: {p:?} outside {b:?}"
            );
        }
    }
}

#[test]
fn the_index_answers_as_a_scan_of_every_segment() {
    // Each random segment closed by two lines through a point off its
    // chord, on the side away from its bulge; the scan runs over whatever
    // closed contours come out.
    let segs = random_segments(2000, 0x9E37_79B9_7F4A_7C15);
    let entities = segs
        .iter()
        .map(|s| {
            let away = if s.bulge > 0.0 { -0.3 } else { 0.3 };
            let m = s.a.add(s.b).scale(0.5).add(s.b.sub(s.a).perp().scale(away));
            vec![*s, Segment::line(s.b, m), Segment::line(m, s.a)]
        })
        .map(closed_polyline)
        .collect();
    let d = crate::dxf::Drawing {
        entities,
        ..crate::dxf::Drawing::default()
    };
    let contours = crate::contour::extract(&d, crate::geom::Tolerance(1e-3), 0.05);
    let all: Vec<Segment> = contours
        .contours
        .iter()
        .filter(|c| c.is_closed())
        .flat_map(|c| c.segments.iter().copied())
        .collect();
    assert!(all.len() > 1000, "{} segments indexed", all.len());
    let o = Obstacles::new(&contours, 1e-3);
    let mut rnd = crate::test_rng::unit(12345);
    let mut hits = 0;
    for _ in 0..3000 {
        // Near a segment's end or arc middle, or anywhere.
        let s = all[(rnd() * all.len() as f64) as usize % all.len()];
        let p = match (rnd() * 3.0) as usize {
            0 => s.a.add(Point::new(rnd() - 0.5, rnd() - 0.5).scale(4.0)),
            1 => s.point_at(0.5).add(Point::new(rnd() - 0.5, rnd() - 0.5)),
            _ => Point::new(rnd() * 3200.0 - 600.0, rnd() * 1700.0 - 100.0),
        };
        let reach = [0.3, 2.0, 9.0][(rnd() * 3.0) as usize % 3];
        let scan = all
            .iter()
            .map(|s| crate::geom::dist_to_segment(p, s))
            .fold(f64::INFINITY, f64::min);
        let got = o.distance(p, reach);
        if scan <= reach {
            hits += 1;
            assert_eq!(got, scan, "{p:?} reach {reach}");
        }
        assert_eq!(o.clear_of(p, reach), scan >= reach, "{p:?} {reach}");
        let q = p.add(Point::new(rnd() - 0.5, rnd() - 0.5).scale(2.0 * reach));
        let lead = Segment::line(p, q);
        let clear = all.iter().all(|s| crossings(&lead, s).is_empty());
        assert_eq!(o.line_is_clear(p, q, &[]), clear, "{p:?} {q:?}");
    }
    assert!(hits > 300, "{hits} queries found a segment within reach");
}

/// A closed LWPOLYLINE on layer 0 of the given segments.
fn closed_polyline(segments: Vec<Segment>) -> crate::dxf::Entity {
    crate::dxf::Entity {
        kind: "LWPOLYLINE",
        layer: 0,
        place: crate::dxf::Place::Line(1),
        segments,
        closed: true,
        source: None,
        insert: None,
    }
}
