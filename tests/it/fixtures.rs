//! The known answers of `../shared/fixtures/EXPECTED.md`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::{fixture, kerf, run};
use kerfcam::contour::ContourKind;
use kerfcam::geom::{loop_area, Point, Segment};
use kerfcam::kerf::Join;

fn close(a: f64, b: f64, eps: f64) -> bool {
    (a - b).abs() <= eps
}

fn assert_point(p: Point, x: f64, y: f64, eps: f64) {
    assert!(
        close(p.x, x, eps) && close(p.y, y, eps),
        "({}, {}) != ({x}, {y})",
        p.x,
        p.y
    );
}

#[test]
fn figure1_reads_three_entities_and_chains_line_and_arc_into_one_open_contour() {
    let out = run(&fixture("seed000-figure1.dxf"), &kerf(0.0)).unwrap();
    let d = &out.drawing;
    // The fixture's header says $INSUNITS 6 (metres): every value is scaled to mm.
    let u = d.units.unwrap();
    assert_eq!(u.name, "m");
    let k = u.to_mm;
    assert_eq!(d.entities.len(), 3);
    let line = d.entities.iter().find(|e| e.kind == "LINE").unwrap();
    assert_point(line.segments[0].a, -40.0 * k, 50.0 * k, 1e-9);
    assert_point(line.segments[0].b, 40.0 * k, 50.0 * k, 1e-9);
    let arc = d.entities.iter().find(|e| e.kind == "ARC").unwrap();
    assert_point(arc.segments[0].a, -40.0 * k, 50.0 * k, 1e-6);
    assert_point(arc.segments.last().unwrap().b, -50.0 * k, 40.0 * k, 1e-6);
    let sweep: f64 = arc.segments.iter().map(Segment::sweep).sum();
    assert!(close(sweep.to_degrees(), 270.0, 1e-9));
    let circle = d.entities.iter().find(|e| e.kind == "CIRCLE").unwrap();
    assert!(circle.closed);
    let (c, r) = circle.segments[0].arc_center().unwrap();
    assert_point(c, 0.0, 0.0, 1e-9);
    assert!(close(r, 15.0 * k, 1e-9));

    let cs = &out.contours.contours;
    assert_eq!(cs.len(), 2);
    let closed: Vec<_> = cs.iter().filter(|c| c.is_closed()).collect();
    assert_eq!(closed.len(), 1);
    assert!(close(
        closed[0].area.abs(),
        std::f64::consts::PI * (15.0 * k).powi(2),
        1e-3
    ));
    let open = cs.iter().find(|c| c.kind == ContourKind::Open).unwrap();
    assert_eq!(open.entities.len(), 2);
    // (-50,40) → arc → (-40,50) → line → (40,50), in either direction.
    let ends = [open.start(), open.end()];
    let has = |x: f64, y: f64| {
        ends.iter()
            .any(|p| close(p.x, x * k, 1e-6) && close(p.y, y * k, 1e-6))
    };
    assert!(has(-50.0, 40.0) && has(40.0, 50.0), "{ends:?}");
    assert_eq!(out.plan.pierces(), 1, "the open chain is not cut");
}

#[test]
fn plate_has_one_outer_and_six_holes_with_exact_areas() {
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(2.0)).unwrap();
    let cs = &out.contours.contours;
    assert_eq!(cs.len(), 7);
    let outer: Vec<_> = cs.iter().filter(|c| c.kind == ContourKind::Outer).collect();
    let holes: Vec<_> = cs.iter().filter(|c| c.kind == ContourKind::Hole).collect();
    assert_eq!(outer.len(), 1);
    assert_eq!(holes.len(), 6);
    assert_eq!(outer[0].depth, 0);
    assert!(holes
        .iter()
        .all(|h| h.depth == 1 && h.part == outer[0].part));
    let outer_area = 200.0 * 120.0 - (4.0 - std::f64::consts::PI) * 225.0;
    assert!(
        close(outer[0].area.abs(), outer_area, 1e-6),
        "{}",
        outer[0].area
    );
    let mut areas: Vec<f64> = holes.iter().map(|h| h.area.abs()).collect();
    areas.sort_by(f64::total_cmp);
    let circle = std::f64::consts::PI * 36.0;
    let slot = 800.0 + std::f64::consts::PI * 100.0;
    for (got, want) in areas
        .iter()
        .zip([circle, circle, circle, circle, 300.0, slot])
    {
        assert!(close(*got, want, 1e-6), "{got} != {want}");
    }
}

#[test]
fn plate_kerf_paths_grow_the_outer_and_shrink_the_holes_by_half_the_kerf() {
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(2.0)).unwrap();
    let paths = &out.kerf.paths;
    assert_eq!(paths.len(), 7);
    let outer = paths.iter().find(|p| p.kind == ContourKind::Outer).unwrap();
    assert_eq!(outer.segments.iter().filter(|s| s.is_line()).count(), 4);
    let radii: Vec<f64> = outer
        .segments
        .iter()
        .filter_map(|s| s.arc_center().map(|c| c.1))
        .collect();
    assert_eq!(radii.len(), 4);
    assert!(radii.iter().all(|r| close(*r, 16.0, 1e-9)), "{radii:?}");
    // Offset of a convex outline: A + P·d + π d².
    let perimeter = 2.0 * (200.0 + 120.0) - 8.0 * 15.0 + 2.0 * std::f64::consts::PI * 15.0;
    let a0 = 200.0 * 120.0 - (4.0 - std::f64::consts::PI) * 225.0;
    assert!(close(
        loop_area(&outer.segments),
        a0 + perimeter + std::f64::consts::PI,
        1e-6
    ));
    // Circles r 6 → r 5; slot ends r 10 → r 9.
    let mut hole_radii: Vec<f64> = paths
        .iter()
        .filter(|p| p.kind == ContourKind::Hole)
        .flat_map(|p| {
            p.segments
                .iter()
                .filter_map(|s| s.arc_center().map(|c| (c.1 * 1e6).round() / 1e6))
        })
        .collect();
    hole_radii.sort_by(f64::total_cmp);
    hole_radii.dedup();
    assert_eq!(hole_radii, vec![5.0, 9.0]);
}

#[test]
fn plate_reports_the_four_inside_corners_of_the_rectangle_hole_as_invalid() {
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(2.0)).unwrap();
    let mut v: Vec<(i64, i64)> = out
        .kerf
        .invalid_vertices
        .iter()
        .map(|p| ((p.x * 1e6).round() as i64, (p.y * 1e6).round() as i64))
        .collect();
    v.sort();
    let m = 1_000_000;
    assert_eq!(
        v,
        vec![
            (90 * m, 90 * m),
            (90 * m, 105 * m),
            (110 * m, 90 * m),
            (110 * m, 105 * m)
        ]
    );
    // No kerf, nothing to round.
    let zero = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(0.0)).unwrap();
    assert!(zero.kerf.invalid_vertices.is_empty());
}

#[test]
fn plate_cuts_every_hole_before_the_outer_contour() {
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(2.0)).unwrap();
    let kinds: Vec<ContourKind> = out.plan.cuts.iter().map(|c| c.kind).collect();
    assert_eq!(kinds.len(), 7);
    assert_eq!(kinds[6], ContourKind::Outer);
    assert!(kinds[..6].iter().all(|k| *k == ContourKind::Hole));
    assert_eq!(out.plan.pierces(), 7);
}

#[test]
fn p51703_mitred_kerf_gives_the_thesis_compensated_vertices() {
    let s = kerf(3.0).with_join(Join::Miter);
    let out = run(&fixture("seed001-P51703.dxf"), &s).unwrap();
    assert_eq!(out.kerf.paths.len(), 1);
    let path = &out.kerf.paths[0].segments;
    assert!(
        path.iter().all(Segment::is_line),
        "mitre joins leave only lines"
    );
    let expected = [
        (-1.5, -1.5),
        (201.5, -1.5),
        (201.5, 201.5),
        (159.37868, 201.5),
        (-1.5, 40.62132),
    ];
    assert_eq!(path.len(), expected.len());
    for (x, y) in expected {
        assert!(
            path.iter()
                .any(|s| close(s.a.x, x, 1e-5) && close(s.a.y, y, 1e-5)),
            "missing ({x}, {y}) in {path:?}"
        );
    }
    // Placed mirrored on the sheet as in annex H: the thesis' NC coordinates.
    let thesis = [
        (62.12, 251.02),
        (20.0, 251.02),
        (20.0, 48.02),
        (223.0, 48.02),
        (223.0, 90.14),
    ];
    for (x, y) in thesis {
        let hit = path.iter().any(|s| {
            let (xs, ys) = (221.5 - s.a.x, 49.520853 + s.a.y);
            close((xs * 100.0).round() / 100.0, x, 1e-9)
                && close((ys * 100.0).round() / 100.0, y, 1e-9)
        });
        assert!(hit, "thesis point ({x}, {y}) not reproduced");
    }
}

#[test]
fn p51703_round_kerf_puts_arcs_of_half_the_kerf_at_the_convex_corners() {
    let out = run(&fixture("seed001-P51703.dxf"), &kerf(3.0)).unwrap();
    let path = &out.kerf.paths[0].segments;
    let arcs: Vec<(Point, f64)> = path.iter().filter_map(Segment::arc_center).collect();
    assert_eq!(arcs.len(), 5);
    assert!(arcs.iter().all(|(_, r)| close(*r, 1.5, 1e-9)));
    for (x, y) in [
        (0.0, 0.0),
        (200.0, 0.0),
        (200.0, 200.0),
        (160.0, 200.0),
        (0.0, 40.0),
    ] {
        assert!(
            arcs.iter()
                .any(|(c, _)| close(c.x, x, 1e-9) && close(c.y, y, 1e-9)),
            "no join arc at ({x}, {y})"
        );
    }
}

#[test]
fn grid_3x2_has_six_parts_and_cuts_8400_mm_one_contour_at_a_time() {
    let out = run(&fixture("seed003-grid-3x2.dxf"), &kerf(0.0)).unwrap();
    let cs = &out.contours.contours;
    assert_eq!(cs.len(), 6);
    assert!(cs
        .iter()
        .all(|c| c.kind == ContourKind::Outer && c.depth == 0));
    assert!(cs.iter().all(|c| close(c.area.abs(), 120_000.0, 1e-6)));
    assert_eq!(out.plan.pierces(), 6);
    assert!(
        close(out.plan.cut_length(), 8400.0, 1e-6),
        "{}",
        out.plan.cut_length()
    );
}

#[test]
fn every_fixture_program_passes_linuxcnc() {
    for name in [
        "seed000-figure1",
        "seed000-plate-6-holes",
        "seed001-P51703",
        "seed002-figure4",
        "seed003-grid-3x2",
    ] {
        for (k, s) in [
            (0.0, kerf(0.0)),
            (2.0, kerf(2.0)),
            (3.0, kerf(3.0).with_join(Join::Miter)),
        ] {
            let out = run(&fixture(&format!("{name}.dxf")), &s).unwrap();
            let errors = common::rs274_errors(&out.gcode, &format!("fixture-{name}-k{k}"));
            assert!(errors.is_empty(), "{name} kerf {k}: {errors:?}");
        }
    }
}
