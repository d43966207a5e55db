//! Faces of lines meeting at branch points.

use super::super::{chain, chain_faces, Chain, FaceLog, Piece, Pieces};
use crate::geom::{Point, Segment};
use crate::par::Threads;

fn pieces(segs: &[Segment]) -> Pieces {
    let mut p = Pieces::default();
    for (i, s) in segs.iter().enumerate() {
        p.push(Piece {
            segments: vec![*s],
            closed: false,
            entities: vec![i],
            measure: None,
        });
    }
    p
}

fn l(a: (f64, f64), b: (f64, f64)) -> Segment {
    Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1))
}

/// Chains `segs` looking for faces: the chains, the warnings' codes, the log.
fn faces(segs: &[Segment]) -> (Vec<Chain>, Vec<&'static str>, FaceLog) {
    let (mut gaps, mut warnings, mut log) = (Vec::new(), Vec::new(), FaceLog::default());
    let chains = chain_faces(
        pieces(segs),
        1e-3,
        &mut gaps,
        &mut warnings,
        Threads::ONE,
        &mut log,
    );
    (chains, warnings.iter().map(|w| w.code).collect(), log)
}

fn closed_areas(chains: &[Chain]) -> Vec<f64> {
    let mut a: Vec<f64> = (chains.iter())
        .filter(|c| c.closed)
        .map(|c| (c.measure.area * 1e6).round() / 1e6)
        .collect();
    a.sort_by(f64::total_cmp);
    a
}

#[test]
fn two_squares_drawn_with_one_line_between_them_are_two_faces() {
    // Seven lines, shuffled and some reversed; three meet at (10,0) and (10,10).
    let segs = [
        l((10.0, 0.0), (10.0, 10.0)),
        l((0.0, 0.0), (10.0, 0.0)),
        l((20.0, 10.0), (10.0, 10.0)),
        l((10.0, 0.0), (20.0, 0.0)),
        l((0.0, 10.0), (0.0, 0.0)),
        l((20.0, 0.0), (20.0, 10.0)),
        l((10.0, 10.0), (0.0, 10.0)),
    ];
    let (chains, warnings, log) = faces(&segs);
    assert_eq!(chains.len(), 2, "{chains:?}");
    assert_eq!(closed_areas(&chains), [100.0, 100.0]);
    for c in &chains {
        assert!(c.shares_edges);
        assert_eq!(c.segments.len(), 4);
        // End to end exactly, and round.
        for k in 0..4 {
            assert_eq!(c.segments[k].b, c.segments[(k + 1) % 4].a);
        }
        // Each face's entities: its own lines and the shared one (entity 0).
        assert_eq!(c.entities.len(), 4);
        assert!(c.entities.contains(&0));
    }
    assert_eq!((log.faces, log.shared_length), (2, 10.0));
    assert!(warnings.is_empty(), "{warnings:?}");
    // Chained by nearest end, the same lines are not two squares.
    let old = chain(pieces(&segs), 1e-3, 1e-3, &mut vec![], &mut vec![]);
    assert_ne!(closed_areas(&old), [100.0, 100.0]);
}

#[test]
fn a_corner_on_the_inside_of_a_line_splits_it_and_a_line_drawn_twice_is_one() {
    // A 20 x 10 rectangle whose top is one line, a divider from its
    // bottom's middle (a branch point) to the top's inside (a T-junction),
    // and the left side drawn twice.
    let segs = [
        l((0.0, 0.0), (10.0, 0.0)),
        l((10.0, 0.0), (20.0, 0.0)),
        l((20.0, 0.0), (20.0, 10.0)),
        l((20.0, 10.0), (0.0, 10.0)),
        l((0.0, 10.0), (0.0, 0.0)),
        l((0.0, 0.0), (0.0, 10.0)),
        l((10.0, 0.0), (10.0, 10.0)),
    ];
    let (chains, _, log) = faces(&segs);
    assert_eq!(closed_areas(&chains), [100.0, 100.0], "{chains:?}");
    assert_eq!(log.shared_length, 10.0);
    assert_eq!(log.duplicates, [Point::new(0.0, 5.0)]);
}

#[test]
fn lines_hanging_into_or_between_faces_are_left_open() {
    // Two squares sharing an edge; a line hangs from a corner into the
    // left one, and another joins the right one to a third square.
    let mut segs = vec![
        l((0.0, 0.0), (10.0, 0.0)),
        l((10.0, 0.0), (20.0, 0.0)),
        l((20.0, 0.0), (20.0, 10.0)),
        l((20.0, 10.0), (10.0, 10.0)),
        l((10.0, 10.0), (0.0, 10.0)),
        l((0.0, 10.0), (0.0, 0.0)),
        l((10.0, 0.0), (10.0, 10.0)),
        l((0.0, 0.0), (4.0, 4.0)),
        l((20.0, 10.0), (30.0, 10.0)),
    ];
    for (a, b) in [((30.0, 10.0), (35.0, 10.0)), ((35.0, 10.0), (35.0, 15.0))] {
        segs.push(l(a, b));
    }
    segs.push(l((35.0, 15.0), (30.0, 15.0)));
    segs.push(l((30.0, 15.0), (30.0, 10.0)));
    let (chains, _, log) = faces(&segs);
    assert_eq!(closed_areas(&chains), [25.0, 100.0, 100.0], "{chains:?}");
    let open: Vec<f64> = (chains.iter())
        .filter(|c| !c.closed)
        .map(|c| c.measure.length)
        .collect();
    assert_eq!(open.len(), 2, "{chains:?}");
    assert!(open.contains(&10.0) && open.iter().any(|&x| (x - 32f64.sqrt()).abs() < 1e-9));
    // The small square shares no edge.
    let shares = |area: f64| {
        (chains.iter())
            .find(|c| c.closed && (c.measure.area - area).abs() < 1e-6)
            .unwrap()
            .shares_edges
    };
    assert!(!shares(25.0));
    assert_eq!((log.faces, log.shared_length), (3, 10.0));
}

#[test]
fn a_tree_of_lines_bounds_no_face_and_is_chained_as_before() {
    // A Y and, apart, a square of four lines: no face among the branched.
    let segs = [
        l((0.0, 0.0), (5.0, 5.0)),
        l((5.0, 5.0), (10.0, 0.0)),
        l((5.0, 5.0), (5.0, 12.0)),
        l((20.0, 0.0), (30.0, 0.0)),
        l((30.0, 0.0), (30.0, 10.0)),
        l((30.0, 10.0), (20.0, 10.0)),
        l((20.0, 10.0), (20.0, 0.0)),
    ];
    let (chains, warnings, log) = faces(&segs);
    let mut w = Vec::new();
    let old = chain(pieces(&segs), 1e-3, 1e-3, &mut vec![], &mut w);
    assert_eq!(chains.len(), old.len());
    for (a, b) in chains.iter().zip(&old) {
        assert_eq!(
            (&a.segments, &a.entities, a.closed),
            (&b.segments, &b.entities, b.closed)
        );
    }
    assert_eq!(warnings, ["branch-points"]);
    assert_eq!(log, FaceLog::default());
}

#[test]
fn arcs_leaving_a_corner_along_a_line_are_sorted_by_how_they_turn() {
    // A 10 x 10 square cut by a quarter circle centred on its top left
    // corner, from its bottom left corner (leaving along the bottom
    // line, turning left) to its top right corner.
    let q = (std::f64::consts::PI / 8.0).tan();
    let arc = Segment {
        a: Point::new(0.0, 0.0),
        b: Point::new(10.0, 10.0),
        bulge: q,
    };
    let segs = [
        l((0.0, 0.0), (10.0, 0.0)),
        l((10.0, 0.0), (10.0, 10.0)),
        l((10.0, 10.0), (0.0, 10.0)),
        l((0.0, 10.0), (0.0, 0.0)),
        arc,
    ];
    let (chains, _, log) = faces(&segs);
    let quarter = 25.0 * std::f64::consts::PI;
    let areas = closed_areas(&chains);
    assert_eq!(areas.len(), 2, "{chains:?}");
    assert!((areas[0] - (100.0 - quarter)).abs() < 1e-6, "{areas:?}");
    assert!((areas[1] - quarter).abs() < 1e-6, "{areas:?}");
    assert!((log.shared_length - quarter / 5.0).abs() < 1e-9);
}

#[test]
fn pieces_of_no_length_or_not_finite_do_not_panic() {
    let nan = f64::NAN;
    let segs = [
        l((0.0, 0.0), (10.0, 0.0)),
        l((10.0, 0.0), (10.0, 10.0)),
        l((10.0, 10.0), (0.0, 0.0)),
        l((0.0, 0.0), (0.0, 0.0)),
        l((0.0, 0.0), (nan, 3.0)),
        l((10.0, 0.0), (10.0, 0.0)),
    ];
    let (chains, _, _) = faces(&segs);
    assert!(!chains.is_empty());
}

#[test]
fn squares_each_drawn_with_its_own_lines_touch_but_share_no_line() {
    // Each square's four lines, the common side drawn by both: the faces
    // are the squares, each with its copy; nothing is shared or healed.
    let sq = |x: f64| {
        [
            l((x, 0.0), (x + 10.0, 0.0)),
            l((x + 10.0, 0.0), (x + 10.0, 10.0)),
            l((x + 10.0, 10.0), (x, 10.0)),
            l((x, 10.0), (x, 0.0)),
        ]
    };
    let segs: Vec<Segment> = sq(0.0).into_iter().chain(sq(10.0)).collect();
    let (chains, _, log) = faces(&segs);
    assert_eq!(closed_areas(&chains), [100.0, 100.0], "{chains:?}");
    assert!(chains.iter().all(|c| !c.shares_edges));
    assert_eq!((log.faces, log.shared_length), (2, 0.0));
    assert!(log.duplicates.is_empty());
}
