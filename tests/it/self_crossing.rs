//! Outlines that cross themselves are cut as the region they enclose
//! (issue 45 §2): each figure's repaired contours are checked against the
//! non-zero region of the drawn loop, found here by sampling winding
//! numbers on a grid (independent of the repair's arrangement), and its
//! program against the independent kerf sweep (`common::sweep`).

use crate::common;

use common::sweep::{uncut_edges, worst_reach, Parts, SLACK};
use kerfcam::contour::ContourKind;
use kerfcam::geom::Point;
use kerfcam::Output;

const KERF: f64 = 1.5;

fn dxf(loops: &[Vec<(f64, f64)>]) -> Vec<u8> {
    let mut body = String::new();
    for pts in loops {
        body += &format!("0\nLWPOLYLINE\n8\nGLYPHS\n90\n{}\n70\n1\n", pts.len());
        for (x, y) in pts {
            body += &format!("10\n{x}\n20\n{y}\n");
        }
    }
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n")
        .into_bytes()
}

/// Winding number of a polygon around `p` (Sunday's crossing rule).
fn winding(pts: &[(f64, f64)], p: Point) -> i32 {
    let mut w = 0;
    for i in 0..pts.len() {
        let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
        let side = (b.0 - a.0) * (p.y - a.1) - (p.x - a.0) * (b.1 - a.1);
        if a.1 <= p.y && b.1 > p.y && side > 0.0 {
            w += 1;
        } else if a.1 > p.y && b.1 <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

/// Distance from `p` to the polygon's edges.
fn to_edges(pts: &[(f64, f64)], p: Point) -> f64 {
    (0..pts.len())
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
            common::sweep::seg_dist(p, Point::new(a.0, a.1), Point::new(b.0, b.1))
        })
        .fold(f64::INFINITY, f64::min)
}

/// Inside an odd number of the output's closed contours.
fn in_output(out: &Output, p: Point) -> bool {
    out.contours
        .contours
        .iter()
        .filter(|c| c.is_closed())
        .filter(|c| kerfcam_inside(&c.segments, p))
        .count()
        % 2
        == 1
}

/// Even-odd point test of a loop of lines (the figures are drawn in lines).
fn kerfcam_inside(segs: &[kerfcam::geom::Segment], p: Point) -> bool {
    let mut c = false;
    for s in segs {
        assert_eq!(s.bulge, 0.0, "a repaired line figure has only lines");
        let (a, b) = (s.a, s.b);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            c = !c;
        }
    }
    c
}

/// Runs `pts`, checks the repair and the cut; `pinches`: where the
/// region's parts only touch, the places near which the kerf of one
/// reaches into the other (no cut can part them there: the
/// parts-closer-than-kerf case of issue 45 §1).
fn check(name: &str, pts: &[(f64, f64)], loops: usize, pinches: &[Point]) -> Output {
    let out = kerfcam::run(&dxf(&[pts.to_vec()]), &common::kerf(KERF)).unwrap();
    let codes: Vec<&str> = out.contours.warnings.iter().map(|w| w.code).collect();
    assert!(
        codes.contains(&"self-crossing-repaired"),
        "{name}: {codes:?}"
    );
    assert!(
        !out.kerf.warnings.iter().any(|w| w.code == "self-crossing"),
        "{name}: still refused"
    );
    let closed: Vec<_> = out
        .contours
        .contours
        .iter()
        .filter(|c| c.is_closed())
        .collect();
    assert_eq!(closed.len(), loops, "{name}");
    assert!(
        closed.iter().all(|c| c.layer.as_ref() == "GLYPHS"),
        "{name}"
    );
    // The region: outers minus holes, against the non-zero area sampled.
    let area: f64 = closed
        .iter()
        .map(|c| match c.kind {
            ContourKind::Hole => -c.area.abs(),
            _ => c.area.abs(),
        })
        .sum();
    let (x0, x1) = pts
        .iter()
        .fold((f64::MAX, f64::MIN), |m, p| (m.0.min(p.0), m.1.max(p.0)));
    let (y0, y1) = pts
        .iter()
        .fold((f64::MAX, f64::MIN), |m, p| (m.0.min(p.1), m.1.max(p.1)));
    let step = (x1 - x0).max(y1 - y0) / 400.0;
    let (mut filled, mut wrong) = (0usize, 0usize);
    let mut y = y0 + step / 2.0;
    while y < y1 {
        let mut x = x0 + step / 2.0;
        while x < x1 {
            let p = Point::new(x, y);
            let nonzero = winding(pts, p) != 0;
            filled += usize::from(nonzero);
            if to_edges(pts, p) > 1e-6 && nonzero != in_output(&out, p) {
                wrong += 1;
            }
            x += step;
        }
        y += step;
    }
    let sampled = filled as f64 * step * step;
    assert!(
        (area - sampled).abs() < 0.01 * sampled,
        "{name}: repaired area {area:.3} against {sampled:.3} sampled"
    );
    assert_eq!(wrong, 0, "{name}: samples on the wrong side of the repair");
    // Cut: every drawn edge cut to size, no move into a part but at a pinch.
    let uncut: Vec<_> = uncut_edges(&out.plan, &out.contours, KERF)
        .into_iter()
        .filter(|p| out.kerf.invalid_vertices.iter().all(|v| v.dist(*p) > KERF))
        .collect();
    assert!(
        uncut.is_empty(),
        "{name}: not cut to size at {:?}",
        uncut.first()
    );
    let (depth, at) = worst_reach(&out.plan, &Parts::new(&out.contours), KERF);
    let near_pinch = |p: Point| pinches.iter().any(|q| q.dist(p) < 4.0 * KERF);
    assert!(
        depth <= SLACK || at.is_some_and(|a| near_pinch(a.1)),
        "{name}: {depth} mm into a part at {at:?}"
    );
    assert_eq!(common::rs274_errors(&out.gcode, name), Vec::<String>::new());
    out
}

#[test]
fn a_bow_tie_is_cut_as_two_triangles() {
    check(
        "bow-tie",
        &[(0.0, 0.0), (40.0, 40.0), (40.0, 0.0), (0.0, 40.0)],
        2,
        &[Point::new(20.0, 20.0)],
    );
}

#[test]
fn a_figure_eight_is_cut_as_its_two_lobes() {
    check(
        "figure-8",
        &[
            (0.0, 0.0),
            (30.0, 30.0),
            (60.0, 0.0),
            (30.0, -30.0),
            (0.0, 30.0),
            (-20.0, 0.0),
        ],
        2,
        &[Point::new(10.0, 10.0)],
    );
}

#[test]
fn a_pentagram_is_cut_as_its_star_and_the_even_odd_rule_is_named() {
    let pts: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + k as f64 * 4.0 * std::f64::consts::PI / 5.0;
            (50.0 * a.cos(), 50.0 * a.sin())
        })
        .collect();
    let out = check("pentagram", &pts, 1, &[]);
    let w = out
        .contours
        .warnings
        .iter()
        .find(|w| w.code == "self-crossing-repaired")
        .unwrap();
    assert!(w.message().contains("even-odd"), "{}", w.message());
    assert!(w.text.pt.contains("par-ímpar"), "{}", w.text.pt);
}

#[test]
fn a_glyph_touching_a_bar_is_cut_as_their_union() {
    // A bar and a T drawn as one loop, the T's stem run into the bar
    // across its top edge: the bar's left strip (winding 1), the T with
    // the bar's top (1 and 2) and its right part; the quadrilateral the
    // loop's return cuts off the bar's lower left is winding 0.
    let pts = [
        (0.0, 0.0),
        (40.0, 0.0),
        (40.0, 5.0),
        (0.0, 5.0),
        (0.0, 2.0),
        (18.0, 2.0),
        (18.0, 30.0),
        (10.0, 30.0),
        (10.0, 34.0),
        (30.0, 34.0),
        (30.0, 30.0),
        (22.0, 30.0),
        (22.0, 1.0),
    ];
    check(
        "glyph-bar",
        &pts,
        3,
        &[Point::new(18.0, 5.0), Point::new(22.0, 5.0)],
    );
}

#[test]
fn a_loop_with_a_tiny_twist_at_a_corner_is_cut_whole() {
    // A plate whose last corner overshoots and comes back across its edge.
    let pts = [
        (0.0, 0.0),
        (50.0, 0.0),
        (50.0, 30.0),
        (0.0, 30.0),
        (0.0, -0.3),
        (0.3, 0.2),
    ];
    check("twist", &pts, 1, &[]);
}

#[test]
fn a_hole_that_crosses_itself_stays_a_hole_and_no_repair_keeps_it_uncut() {
    let plate = vec![(-60.0, -60.0), (60.0, -60.0), (60.0, 60.0), (-60.0, 60.0)];
    // Lopsided: a symmetric bow tie's signed area is 0, and unrepaired it is open.
    let tie = vec![(-20.0, -20.0), (20.0, 20.0), (20.0, -20.0), (-20.0, 40.0)];
    let bytes = dxf(&[plate, tie]);
    let out = kerfcam::run(&bytes, &common::kerf(KERF)).unwrap();
    let holes = out
        .contours
        .contours
        .iter()
        .filter(|c| c.kind == ContourKind::Hole);
    assert_eq!(holes.count(), 2);
    assert_eq!(out.contours.healing.self_crossings, 1);
    let strict = kerfcam::run(&bytes, &common::kerf(KERF).with_repair(false)).unwrap();
    assert!(strict
        .kerf
        .warnings
        .iter()
        .any(|w| w.code == "self-crossing"));
    assert_eq!(strict.contours.healing.self_crossings, 0);
}

#[test]
fn a_drawing_without_crossings_is_not_changed() {
    let plate = vec![(0.0, 0.0), (60.0, 0.0), (60.0, 40.0), (0.0, 40.0)];
    let hole = vec![(10.0, 10.0), (20.0, 10.0), (20.0, 20.0), (10.0, 20.0)];
    let bytes = dxf(&[plate, hole]);
    let a = kerfcam::run(&bytes, &common::kerf(KERF)).unwrap();
    let b = kerfcam::run(&bytes, &common::kerf(KERF).with_repair(false)).unwrap();
    assert_eq!(a.gcode, b.gcode);
    assert!(!a
        .contours
        .warnings
        .iter()
        .any(|w| w.code.starts_with("self-crossing")));
}

/// Parts of a run (the plan's count).
fn parts(out: &Output) -> usize {
    out.contours
        .contours
        .iter()
        .filter_map(|c| c.part)
        .collect::<std::collections::BTreeSet<_>>()
        .len()
}

#[test]
fn outlines_that_only_touch_or_retrace_themselves_are_never_split_into_more_parts() {
    // Two squares through one corner (touching there, crossing nowhere),
    // and a garment's internal line drawn out straight and back in bumps
    // meeting it at its vertices (GMH2446F17's layer 8): each one loop
    // drawn, each left one loop, as without the repair, and said.
    let touching = vec![
        (0.0, 0.0),
        (10.0, 0.0),
        (10.0, 10.0),
        (20.0, 10.0),
        (20.0, 20.0),
        (10.0, 20.0),
        (10.0, 10.0),
        (0.0, 10.0),
    ];
    let lenses = vec![
        (40.0, 0.0),
        (50.0, 0.0),
        (60.0, 0.0),
        (70.0, 0.0),
        (65.0, 1.0),
        (60.0, 0.0),
        (55.0, 1.0),
        (50.0, 0.0),
        (45.0, 1.0),
    ];
    let bytes = dxf(&[touching, lenses]);
    let repaired = kerfcam::run(&bytes, &common::kerf(KERF)).unwrap();
    let strict = kerfcam::run(&bytes, &common::kerf(KERF).with_repair(false)).unwrap();
    assert_eq!(parts(&repaired), parts(&strict));
    assert_eq!(
        repaired.contours.contours.len(),
        strict.contours.contours.len()
    );
    assert_eq!(repaired.gcode, strict.gcode);
    // One warning of the kind, naming both places.
    let kept = repaired
        .contours
        .warnings
        .iter()
        .find(|w| w.code == "self-touching-kept")
        .expect("said");
    assert_eq!(kept.count, 2, "{kept:?}");
    assert!(kept.message().contains("(10.000, 10.000), (50.000, 0.000)"));
    assert!(kept.text.pt.contains("sem reparo"), "{}", kept.text.pt);
    assert_eq!(repaired.contours.healing.self_crossings, 0);
}

#[test]
fn a_plate_with_a_slit_drawn_there_and_back_is_cut_as_one_part_and_said() {
    // The slit (a zero-width spike) cannot be kerf-compensated: the plate
    // is cut whole without it, and the warning says the line was not cut.
    let plate = vec![
        (0.0, 0.0),
        (40.0, 0.0),
        (40.0, 30.0),
        (20.0, 30.0),
        (20.0, 10.0),
        (20.0, 30.0),
        (0.0, 30.0),
    ];
    let out = kerfcam::run(&dxf(&[plate]), &common::kerf(KERF)).unwrap();
    assert_eq!(parts(&out), 1);
    let w = out
        .contours
        .warnings
        .iter()
        .find(|w| w.code == "self-crossing-repaired")
        .expect("said");
    assert!(w.message().contains("not cut"), "{}", w.message());
    let outer = out
        .contours
        .contours
        .iter()
        .find(|c| c.is_closed())
        .unwrap();
    assert!((outer.area.abs() - 1200.0).abs() < 1e-6, "{}", outer.area);
    assert_eq!(out.plan.pierces(), 1);
}
