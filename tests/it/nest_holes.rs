//! Parts in holes at spacing 0 (issue 16): the common-line case, where the
//! distances alone cannot tell a copy touching its host's hole from one
//! crossing it. Checked by sampling (`common::sampled`): no point of a
//! copy lies in another's material, independent of the engine.

use crate::common;

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
            budget_s: None,
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

/// Issue 15 §1: on a cut sheet every contour knows which part, copy and
/// loop it is — the squares inside the ring's hole too, whose containment
/// (a part inside a hole) says nothing about which copy they are.
#[test]
fn every_contour_of_a_cut_sheet_names_its_part_copy_and_loop() {
    let job = ring_and_squares(4);
    let n = nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
    let settings = kerfcam::Settings::new(0.0, 0.001, 1000.0).unwrap();
    let out = kerfcam::nest_cut::cut_sheet(&job, &n, 0, &settings).unwrap();
    let mut expected = Vec::new();
    for p in n.placements.iter().filter(|p| p.sheet == 0) {
        for (k, l) in output::placed_loops(&job, p).iter().enumerate() {
            let (mut lo, mut hi) = (
                Point::new(f64::MAX, f64::MAX),
                Point::new(f64::MIN, f64::MIN),
            );
            for s in l {
                for q in [s.a, s.b] {
                    lo = Point::new(lo.x.min(q.x), lo.y.min(q.y));
                    hi = Point::new(hi.x.max(q.x), hi.y.max(q.y));
                }
            }
            let r = kerfcam::source::ContourRef {
                part: p.part as u32 + 1,
                copy: p.copy as u32,
                contour: k as u32,
            };
            expected.push((r, lo, hi));
        }
    }
    let found: Vec<_> = out.contours.contours.iter().map(|c| c.source).collect();
    let mut want: Vec<_> = expected.iter().map(|e| e.0).collect();
    let mut got = found.clone();
    want.sort();
    got.sort();
    assert_eq!(got, want);
    // Four squares, copies 0..3, and they are in the hole.
    assert_eq!(found.iter().filter(|r| r.part == 2).count(), 4);
    for c in &out.contours.contours {
        let (_, lo, hi) = expected.iter().find(|e| e.0 == c.source).unwrap();
        // The reference points at the very loop placed there (vertex
        // bounds; a circle's arcs may bulge past its ends').
        assert!(
            c.bbox.min.x <= lo.x + 1e-6 && c.bbox.max.x >= hi.x - 1e-6,
            "{:?}: {:?} vs {lo:?}..{hi:?}",
            c.source,
            c.bbox
        );
        assert!(c.bbox.min.y <= lo.y + 1e-6 && c.bbox.max.y >= hi.y - 1e-6);
        assert!(c.bbox.max.x - c.bbox.min.x <= hi.x - lo.x + 30.0);
    }
    // The report carries them.
    let report: serde_json::Value =
        serde_json::from_str(&kerfcam::report::Report::new(&out).to_json()).unwrap();
    assert_eq!(report["contours"][0]["source"]["copy"], found[0].copy);
}
