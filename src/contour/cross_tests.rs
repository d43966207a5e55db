use super::*;

fn poly(pts: &[(f64, f64)]) -> Vec<Segment> {
    let p: Vec<Point> = pts.iter().map(|&(x, y)| Point::new(x, y)).collect();
    (0..p.len())
        .map(|i| Segment::line(p[i], p[(i + 1) % p.len()]))
        .collect()
}

fn repaired(segs: &[Segment]) -> Repair {
    match repair(segs, 1e-5, 1e-3) {
        Outcome::Repaired(r) => r,
        o => panic!("not repaired: {o:?}"),
    }
}

/// Area of the points with non-zero winding, by sampling a grid (the
/// independent measure; the grid's error shrinks with the step).
fn nonzero_area(segs: &[Segment], step: f64) -> f64 {
    let bb = path_bbox(segs);
    let mut n = 0usize;
    let mut y = bb.min.y + step / 2.0;
    while y < bb.max.y {
        let mut x = bb.min.x + step / 2.0;
        while x < bb.max.x {
            if winding(segs, Point::new(x, y)) != 0 {
                n += 1;
            }
            x += step;
        }
        y += step;
    }
    n as f64 * step * step
}

fn total_area(r: &Repair) -> f64 {
    r.loops.iter().map(|l| loop_area(l)).sum()
}

#[test]
fn a_simple_loop_is_left_alone() {
    let square = poly(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]);
    assert!(matches!(repair(&square, 1e-5, 1e-3), Outcome::Simple));
    let c = crate::geom::arc_pieces(Point::new(0.0, 0.0), 5.0, 0.0, std::f64::consts::TAU);
    assert!(matches!(repair(&c, 1e-5, 1e-3), Outcome::Simple));
}

#[test]
fn a_bow_tie_is_two_triangles() {
    let tie = poly(&[(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)]);
    let r = repaired(&tie);
    assert_eq!((r.loops.len(), r.crossings), (2, 1));
    assert!(r.loops.iter().all(|l| loop_area(l) > 0.0));
    assert!((total_area(&r) - 50.0).abs() < 1e-9);
    assert!(r.even_odd_differs.is_none());
}

#[test]
fn a_pentagram_is_its_filled_star_and_the_even_odd_rule_is_named() {
    let pts: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + k as f64 * 4.0 * std::f64::consts::PI / 5.0;
            (10.0 * a.cos(), 10.0 * a.sin())
        })
        .collect();
    let star = poly(&pts);
    let r = repaired(&star);
    assert_eq!((r.loops.len(), r.crossings), (1, 5));
    assert_eq!(r.loops[0].len(), 10);
    let want = nonzero_area(&star, 0.02);
    assert!(
        (total_area(&r) - want).abs() < 0.01 * want,
        "{} {want}",
        total_area(&r)
    );
    let p = r.even_odd_differs.expect("the centre has winding 2");
    assert_eq!(winding(&star, p).abs(), 2);
}

#[test]
fn a_figure_eight_of_arcs_keeps_its_arcs() {
    // Two circles of radius 5 drawn as one loop through a crossing at the
    // origin: the right one counter-clockwise, the left one clockwise.
    let b = 1.0; // half circles
    let o = Point::new(0.0, 0.0);
    let eight = vec![
        Segment {
            a: o,
            b: Point::new(10.0, 0.0),
            bulge: b,
        },
        Segment {
            a: Point::new(10.0, 0.0),
            b: o,
            bulge: b,
        },
        Segment {
            a: o,
            b: Point::new(-10.0, 0.0),
            bulge: -b,
        },
        Segment {
            a: Point::new(-10.0, 0.0),
            b: o,
            bulge: -b,
        },
    ];
    // Touching at one point: two discs, both counter-clockwise now.
    let r = repaired(&eight);
    assert_eq!(r.loops.len(), 2);
    let disc = std::f64::consts::PI * 25.0;
    for l in &r.loops {
        assert!((loop_area(l) - disc).abs() < 1e-9, "{}", loop_area(l));
        assert!(l.iter().all(|s| !s.is_line()));
    }
}

#[test]
fn a_crossed_figure_eight_is_two_lobes() {
    let eight = poly(&[
        (0.0, 0.0),
        (10.0, 10.0),
        (20.0, 0.0),
        (10.0, -10.0),
        (0.0, 10.0),
        (-5.0, 0.0),
    ]);
    let want = nonzero_area(&eight, 0.02);
    let r = repaired(&eight);
    assert!((total_area(&r) - want).abs() < 0.01 * want);
}

#[test]
fn a_loop_drawn_twice_around_has_winding_two_inside() {
    // Around a square twice with a step in: the inner square has winding 2.
    let twice = poly(&[
        (0.0, 0.0),
        (10.0, 0.0),
        (10.0, 10.0),
        (0.0, 10.0),
        (0.0, 1.0),
        (1.0, 1.0),
        (9.0, 1.0),
        (9.0, 9.0),
        (1.0, 9.0),
        (1.0, -1.0),
    ]);
    let want = nonzero_area(&twice, 0.01);
    match repair(&twice, 1e-5, 1e-3) {
        Outcome::Repaired(r) => assert!((total_area(&r) - want).abs() < 0.01 * want),
        o => panic!("{o:?}"),
    }
}

#[test]
fn a_loop_back_over_itself_encloses_nothing() {
    // A triangle walked there and back along a detour that crosses.
    let flat = poly(&[(0.0, 0.0), (10.0, 0.0), (0.0, 0.0001), (10.0, 0.0001)]);
    assert!(!matches!(repair(&flat, 1e-5, 1e-3), Outcome::Repaired(_)));
}

#[test]
fn huge_and_broken_coordinates_do_not_panic() {
    let big = poly(&[(0.0, 0.0), (1e15, 1e15), (1e15, 0.0), (0.0, 1e15)]);
    let _ = repair(&big, 1e-5, 1e-3);
    let nan = poly(&[(0.0, 0.0), (f64::NAN, 1.0), (1.0, 0.0), (0.0, 1.0)]);
    assert!(matches!(repair(&nan, 1e-5, 1e-3), Outcome::Simple));
    let dot = poly(&[(0.0, 0.0), (0.0, 0.0), (0.0, 0.0), (0.0, 0.0)]);
    let _ = repair(&dot, 1e-5, 1e-3);
}

#[test]
fn two_squares_touching_at_a_corner_are_left_as_drawn() {
    // One loop through (10, 10) twice, both squares counter-clockwise:
    // it touches itself there and crosses nowhere.
    let eight = poly(&[
        (0.0, 0.0),
        (10.0, 0.0),
        (10.0, 10.0),
        (20.0, 10.0),
        (20.0, 20.0),
        (10.0, 20.0),
        (10.0, 10.0),
        (0.0, 10.0),
    ]);
    match repair(&eight, 1e-5, 1e-3) {
        Outcome::Touching { at, places, lobes } => {
            assert_eq!((places, lobes), (1, 2));
            assert!(at.dist(Point::new(10.0, 10.0)) < 1e-9);
        }
        o => panic!("{o:?}"),
    }
}

#[test]
fn a_line_drawn_out_and_back_through_the_same_points_is_left_as_drawn() {
    // A garment's internal line: out straight, back in three bumps meeting
    // it at its vertices (the lenses all wind the same way).
    let lenses = poly(&[
        (0.0, 0.0),
        (10.0, 0.0),
        (20.0, 0.0),
        (30.0, 0.0),
        (25.0, 1.0),
        (20.0, 0.0),
        (15.0, 1.0),
        (10.0, 0.0),
        (5.0, 1.0),
    ]);
    assert!(
        matches!(
            repair(&lenses, 1e-5, 1e-3),
            Outcome::Touching { lobes: 3, .. }
        ),
        "{:?}",
        repair(&lenses, 1e-5, 1e-3)
    );
}

#[test]
fn a_spike_drawn_there_and_back_is_dropped_and_the_part_kept_whole() {
    // A square with a zero-width slit drawn into it from its top edge.
    let spiked = poly(&[
        (0.0, 0.0),
        (10.0, 0.0),
        (10.0, 10.0),
        (5.0, 10.0),
        (5.0, 4.0),
        (5.0, 10.0),
        (0.0, 10.0),
    ]);
    let r = repaired(&spiked);
    assert!(r.touch_only);
    assert_eq!(r.loops.len(), 1);
    assert!((total_area(&r) - 100.0).abs() < 1e-9, "{}", total_area(&r));
    assert!(repaired(&spiked).loops[0]
        .iter()
        .all(|s| s.a.dist(Point::new(5.0, 4.0)) > 1.0));
}

#[test]
fn a_hole_pinched_to_its_outline_is_one_part_with_a_hole() {
    // Around the plate, then clockwise around a window from its corner.
    let pinched = poly(&[
        (0.0, 0.0),
        (20.0, 0.0),
        (20.0, 20.0),
        (10.0, 20.0),
        (5.0, 15.0),
        (15.0, 15.0),
        (15.0, 5.0),
        (5.0, 5.0),
        (5.0, 15.0),
        (10.0, 20.0),
        (0.0, 20.0),
    ]);
    let r = repaired(&pinched);
    assert!(r.touch_only);
    assert_eq!(outers(&r.loops), 1);
    assert!((total_area(&r) - 300.0).abs() < 1e-9, "{}", total_area(&r));
}

#[test]
fn a_crossing_is_never_taken_for_a_touch() {
    for pts in [
        vec![(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)],
        vec![
            (0.0, 0.0),
            (50.0, 0.0),
            (50.0, 30.0),
            (0.0, 30.0),
            (0.0, -0.3),
            (0.3, 0.2),
        ],
    ] {
        assert!(!repaired(&poly(&pts)).touch_only, "{pts:?}");
    }
}
