//! Parts in holes at spacing 0 (issue 16): the common-line case, where the
//! distances alone cannot tell a copy touching its host's hole from one
//! crossing it. Checked by sampling (`common::sampled`): no point of a
//! copy lies in another's material, independent of the engine.

mod common;

use common::sampled::{nest_faults, Copy};
use kerfcam::geom::{arc_pieces, Point, Segment};
use kerfcam::nest::{self, output, NestJob, NestSettings, Part, Rotations, Sheets};

fn square(x0: f64, y0: f64, side: f64) -> Vec<Segment> {
    let p = [
        (x0, y0),
        (x0 + side, y0),
        (x0 + side, y0 + side),
        (x0, y0 + side),
    ];
    (0..4)
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % 4]);
            Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1))
        })
        .collect()
}

/// A 200 mm ring (a Ø140 hole) and `squares` 35 mm squares on a sheet
/// that holds the ring alone: the squares can only go in its hole.
fn ring_and_squares(squares: usize) -> NestJob {
    let host = Part {
        name: "ring".into(),
        outer: square(0.0, 0.0, 200.0),
        holes: vec![arc_pieces(
            Point::new(100.0, 100.0),
            70.0,
            0.0,
            std::f64::consts::TAU,
        )],
        quantity: 1,
        rotations: Rotations::None,
        mirror: false,
    };
    let small = Part {
        name: "small".into(),
        outer: square(0.0, 0.0, 35.0),
        holes: Vec::new(),
        quantity: squares,
        rotations: Rotations::Steps(8),
        mirror: false,
    };
    NestJob {
        parts: vec![host, small],
        sheets: Sheets::Rect {
            width: 215.0,
            height: 215.0,
            count: 1,
        },
        settings: NestSettings {
            spacing: 0.0,
            margin: 5.0,
            tolerance: 0.05,
            time_s: 1e9,
            seed: 2,
            max_evaluations: Some(20),
        },
    }
}

#[test]
fn at_spacing_zero_copies_in_a_hole_stay_out_of_the_hosts_material() {
    let job = ring_and_squares(6);
    let n = nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
    // The sheet holds the ring alone: every square is in its hole.
    let inside = n
        .placements
        .iter()
        .filter(|p| p.in_hole_of.is_some())
        .count();
    assert!(n.unplaced.is_empty(), "{:?}", n.unplaced);
    assert_eq!(inside, 6);
    let copies: Vec<Copy> = n
        .placements
        .iter()
        .map(|p| Copy::new(&output::placed_loops(&job, p)))
        .collect();
    let faults = nest_faults(&copies, 0.0, 0.01);
    assert!(faults.is_empty(), "{faults:?}");
    // The check sees a square pushed 5 mm across the hole's edge.
    let mut wrong = n.placements.clone();
    let k = wrong.iter().position(|p| p.in_hole_of.is_some()).unwrap();
    let c = Point::new(100.0, 100.0);
    let at = wrong[k].translation;
    let away = at.sub(c).scale(1.0 / at.dist(c).max(1e-9));
    wrong[k].translation = at.add(away.scale(40.0));
    let copies: Vec<Copy> = wrong
        .iter()
        .map(|p| Copy::new(&output::placed_loops(&job, p)))
        .collect();
    assert!(!nest_faults(&copies, 0.0, 0.01).is_empty());
}

#[test]
fn when_not_everything_fits_the_big_part_is_kept_and_small_copies_left_out() {
    // More squares than the hole holds: leaving one square out beats
    // leaving the ring out, though both leave out one copy and the nest
    // without the ring is shorter (the search ranked copies, not area).
    let job = ring_and_squares(12);
    let n = nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
    assert!(
        n.placements.iter().any(|p| p.part == 0),
        "the ring is placed: {:?}",
        n.unplaced
    );
    assert!(
        n.unplaced.iter().all(|u| u.part == "small"),
        "{:?}",
        n.unplaced
    );
    let placed = n.placements.iter().filter(|p| p.part == 1).count();
    let left: usize = n.unplaced.iter().map(|u| u.copies).sum();
    assert_eq!(placed + left, 12);
    assert!(left >= 1 && placed >= 6, "{placed} placed, {left} left");
}
