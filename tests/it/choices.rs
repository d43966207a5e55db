//! The operator's choices stay on the loop they were set on (issue 39 §1):
//! start points and tabs kept by the loop's identity and shape, matched
//! again after any change that renumbers contours (layers here), never
//! applied to another loop; and no torch cycle without motion (§3).

use crate::common;

use common::rs274_errors;
use kerfcam::plan::choice::{pick_at, Pick};
use kerfcam::plan::{Role, Tabs};
use kerfcam::{geom::Point, Output, Settings};

const KERF: f64 = 1.0;

/// A square `(x, y, side)` on `layer`, as an LWPOLYLINE.
fn square(layer: &str, x: f64, y: f64, s: f64) -> String {
    format!(
        "0\nLWPOLYLINE\n8\n{layer}\n90\n4\n70\n1\n10\n{x}\n20\n{y}\n10\n{}\n20\n{y}\n10\n{}\n20\n{}\n10\n{x}\n20\n{}\n",
        x + s,
        x + s,
        y + s,
        y + s
    )
}

fn dxf(body: &str) -> Vec<u8> {
    format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n"
    )
    .into_bytes()
}

/// The issue's drawing: A0 on layer A, B1, B2, B3 on layer B, 40 mm
/// squares 20 mm apart in a row.
fn issue_drawing() -> Vec<u8> {
    dxf(&[
        square("A", 0.0, 0.0, 40.0),
        square("B", 60.0, 0.0, 40.0),
        square("B", 120.0, 0.0, 40.0),
        square("B", 180.0, 0.0, 40.0),
    ]
    .concat())
}

fn settings(layers: Option<&[&str]>, starts: &[Pick], tabs: &[Pick]) -> Settings {
    let mut s = Settings::new(KERF, 0.001, 2000.0)
        .unwrap()
        .with_origin(kerfcam::origin::ProgramOrigin::Drawing)
        .unwrap();
    if let Some(l) = layers {
        s = s.with_layers(l.iter().map(|l| l.to_string()).collect());
    }
    let mut plan = s.plan().clone();
    plan.starts = starts.to_vec();
    plan.tabs_at = tabs.to_vec();
    plan.tabs = Tabs {
        count: 0,
        width: 3.0,
        holes: false,
    };
    s.with_plan(plan).unwrap()
}

/// The square whose drawn box starts at `x0`, by geometry.
fn contour_at_x(out: &Output, x0: f64) -> Option<usize> {
    contour_at(out, x0, 0.0)
}

/// The square whose drawn box's lower-left corner is `(x0, y0)`.
fn contour_at(out: &Output, x0: f64, y0: f64) -> Option<usize> {
    out.contours
        .contours
        .iter()
        .position(|c| (c.bbox.min.x - x0).abs() < 1e-6 && (c.bbox.min.y - y0).abs() < 1e-6)
}

/// Where the torch starts cutting contour `c` (its first contour step).
fn loop_start(out: &Output, c: usize) -> Point {
    out.plan
        .cuts
        .iter()
        .flat_map(|cut| &cut.steps)
        .find(|s| s.role == Role::Contour && s.contour == Some(c))
        .map(|s| s.segment.a)
        .unwrap()
}

/// The tab steps of contour `c`.
fn tabs_on(out: &Output, c: usize) -> Vec<(Point, Point)> {
    out.plan
        .cuts
        .iter()
        .flat_map(|cut| &cut.steps)
        .filter(|s| s.role == Role::Tab && s.contour == Some(c))
        .map(|s| (s.segment.a, s.segment.b))
        .collect()
}

fn not_applied(out: &Output) -> Option<String> {
    out.warnings()
        .find(|w| w.code == "choices-not-applied")
        .map(|w| w.text.en.clone())
}

#[test]
fn a_start_and_a_tab_stay_on_their_part_when_a_layer_goes_off_and_come_back() {
    let bytes = issue_drawing();
    let all = kerfcam::run(&bytes, &settings(None, &[], &[])).unwrap();
    // The operator's clicks: a start on B1's right edge, a tab on its top.
    let (_, start) = pick_at(&all.contours, Point::new(100.5, 25.0), 2.0).unwrap();
    let (_, tab) = pick_at(&all.contours, Point::new(80.0, 40.5), 2.0).unwrap();
    assert_eq!(start.at, Point::new(100.0, 25.0));
    let check_on_b1 = |out: &Output| {
        let b1 = contour_at_x(out, 60.0).unwrap();
        // Kerf outside: the loop starts on the right edge, kerf/2 out.
        let p = loop_start(out, b1);
        assert!(p.dist(Point::new(100.0 + KERF / 2.0, 25.0)) < 1e-6, "{p:?}");
        let t = tabs_on(out, b1);
        assert_eq!(t.len(), 1, "{t:?}");
        assert!((t[0].0.y - 40.5).abs() < 1e-6 && (t[0].1.y - 40.5).abs() < 1e-6);
        assert!(((t[0].0.x + t[0].1.x) / 2.0 - 80.0).abs() < 1e-6, "{t:?}");
        // B2 and B3 untouched: no tab, and a loop start at a corner of
        // their kerf path (a vertex, where the tour enters), not mid-edge.
        for x0 in [120.0, 180.0] {
            let c = contour_at_x(out, x0).unwrap();
            assert!(tabs_on(out, c).is_empty(), "B at {x0} has a tab");
            let p = loop_start(out, c);
            let path = out.kerf.paths.iter().find(|k| k.contour == c).unwrap();
            assert!(
                path.segments.iter().any(|s| s.a.dist(p) < 1e-9),
                "B at {x0} starts at {p:?}, not at a vertex of its path"
            );
        }
        assert!(not_applied(out).is_none(), "{:?}", not_applied(out));
        assert_eq!(out.gcode.matches("(tab)").count(), 1);
    };
    let both = settings(
        None,
        std::slice::from_ref(&start),
        std::slice::from_ref(&tab),
    );
    let out = kerfcam::run(&bytes, &both).unwrap();
    check_on_b1(&out);
    // Layer A off: every contour renumbered, the choices still on B1.
    let b_only = settings(
        Some(&["B"]),
        std::slice::from_ref(&start),
        std::slice::from_ref(&tab),
    );
    let out = kerfcam::run(&bytes, &b_only).unwrap();
    assert_ne!(contour_at_x(&out, 60.0), contour_at_x(&all, 60.0));
    check_on_b1(&out);
    assert_eq!(
        rs274_errors(&out.gcode, "choices-layer-off"),
        Vec::<String>::new()
    );
    // Layer B off: kept, not applied, named; nothing on A0.
    let a_only = settings(
        Some(&["A"]),
        std::slice::from_ref(&start),
        std::slice::from_ref(&tab),
    );
    let out = kerfcam::run(&bytes, &a_only).unwrap();
    let w = not_applied(&out).expect("a warning naming the choices not applied");
    assert!(w.starts_with("1 start point(s) and 1 tab(s)"), "{w}");
    assert!(w.contains("layer B is not cut now"), "{w}");
    assert!(!out.gcode.contains("(tab)"));
    let a0 = contour_at_x(&out, 0.0).unwrap();
    let path = out.kerf.paths.iter().find(|k| k.contour == a0).unwrap();
    assert!(path
        .segments
        .iter()
        .any(|s| s.a.dist(loop_start(&out, a0)) < 1e-9));
    // Both layers again: back on B1 exactly.
    check_on_b1(&kerfcam::run(&bytes, &both).unwrap());
}

#[test]
fn two_starts_and_two_tabs_on_b1_and_b3_stay_there_with_a_layer_off() {
    let bytes = issue_drawing();
    let all = kerfcam::run(&bytes, &settings(None, &[], &[])).unwrap();
    let pick = |x, y| pick_at(&all.contours, Point::new(x, y), 2.0).unwrap().1;
    let starts = [pick(100.0, 30.0), pick(220.0, 30.0)];
    let tabs = [pick(75.0, 40.0), pick(195.0, 40.0)];
    let out = kerfcam::run(&bytes, &settings(Some(&["B"]), &starts, &tabs)).unwrap();
    assert!(not_applied(&out).is_none());
    for (x0, right) in [(60.0, 100.0), (180.0, 220.0)] {
        let c = contour_at_x(&out, x0).unwrap();
        let p = loop_start(&out, c);
        assert!(p.dist(Point::new(right + KERF / 2.0, 30.0)) < 1e-6, "{p:?}");
        assert_eq!(tabs_on(&out, c).len(), 1);
    }
    let b2 = contour_at_x(&out, 120.0).unwrap();
    assert!(tabs_on(&out, b2).is_empty());
}

#[test]
fn a_start_in_an_order_that_chooses_its_own_entries_is_said() {
    let bytes = issue_drawing();
    let all = kerfcam::run(&bytes, &settings(None, &[], &[])).unwrap();
    let (_, start) = pick_at(&all.contours, Point::new(100.0, 25.25), 2.0).unwrap();
    let s = settings(None, &[start], &[])
        .with_order(kerfcam::plan::Order::Eulerian)
        .unwrap();
    let out = kerfcam::run(&bytes, &s).unwrap();
    let w = not_applied(&out).unwrap();
    assert!(w.contains("chooses its own entries"), "{w}");
    // Where, with the language's decimal mark: a point in English, a
    // comma in Portuguese (its coordinates apart by a semicolon).
    assert!(w.contains("25.25)"), "{w}");
    let pt = &out
        .warnings()
        .find(|w| w.code == "choices-not-applied")
        .unwrap()
        .text
        .pt;
    assert!(pt.contains("; 25,25)"), "{pt}");
}

/// Random rows of squares on three layers, picks on random edges, random
/// layer subsets: each pick applies to its own square only, checked by
/// geometry (where each loop's cut starts), not by the planner's matching.
#[test]
fn kept_choices_apply_only_to_their_own_loop_under_random_layer_subsets() {
    let mut seed = 0x5eed_c401_u64;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let layers = ["L0", "L1", "L2"];
    for round in 0..12 {
        let n = 4 + (rnd() * 8.0) as usize;
        let squares: Vec<(usize, f64, f64, f64)> = (0..n)
            .map(|i| {
                let side = 10.0 + (rnd() * 30.0).round();
                let layer = (rnd() * 3.0) as usize;
                (layer, (i % 4) as f64 * 60.0, (i / 4) as f64 * 60.0, side)
            })
            .collect();
        let body: String = squares
            .iter()
            .map(|&(l, x, y, s)| square(layers[l], x, y, s))
            .collect();
        let bytes = dxf(&body);
        let all = kerfcam::run(&bytes, &settings(None, &[], &[])).unwrap();
        // A start on the right edge of some squares, at a random height.
        let mut picks: Vec<(usize, Pick)> = Vec::new();
        for (k, &(_, x, y, s)) in squares.iter().enumerate() {
            if rnd() < 0.5 {
                let h = y + s * (0.2 + 0.6 * rnd());
                let (_, p) = pick_at(&all.contours, Point::new(x + s, h), 0.5).unwrap();
                picks.push((k, p));
            }
        }
        let starts: Vec<Pick> = picks.iter().map(|(_, p)| p.clone()).collect();
        for subset in 1..8usize {
            let on: Vec<&str> = (0..3)
                .filter(|b| subset & (1 << b) != 0)
                .map(|b| layers[b])
                .collect();
            let out = kerfcam::run(&bytes, &settings(Some(&on), &starts, &[])).unwrap();
            let mut gone = 0;
            for (k, &(l, x, y, _)) in squares.iter().enumerate() {
                let Some(c) = contour_at(&out, x, y).filter(|_| subset & (1 << l) != 0) else {
                    gone += picks.iter().filter(|(j, _)| *j == k).count();
                    continue;
                };
                let p = loop_start(&out, c);
                match picks.iter().find(|(j, _)| *j == k) {
                    Some((_, pick)) => {
                        let want = Point::new(pick.at.x + KERF / 2.0, pick.at.y);
                        assert!(
                            p.dist(want) < 1e-6,
                            "round {round} subset {subset} square {k}: {p:?}, want {want:?}"
                        );
                    }
                    None => {
                        let path = out.kerf.paths.iter().find(|q| q.contour == c).unwrap();
                        assert!(
                            path.segments.iter().any(|s| s.a.dist(p) < 1e-9),
                            "round {round} subset {subset}: square {k}, never picked, starts mid-edge at {p:?}"
                        );
                    }
                }
            }
            match not_applied(&out) {
                None => assert_eq!(gone, 0, "round {round} subset {subset}"),
                Some(w) => assert!(
                    w.starts_with(&format!("{gone} start point(s)")),
                    "round {round} subset {subset}: {w}"
                ),
            }
        }
    }
}

/// A tab over a corner of B1 is one crossing: the torch is off once and on
/// once, with the contour cut before and after it.
#[test]
fn a_tab_over_a_corner_is_one_crossing_with_motion_around_it() {
    let bytes = issue_drawing();
    let all = kerfcam::run(&bytes, &settings(None, &[], &[])).unwrap();
    // On B1's top-right corner.
    let (_, tab) = pick_at(&all.contours, Point::new(100.0, 40.0), 1.0).unwrap();
    let out = kerfcam::run(&bytes, &settings(None, &[], &[tab])).unwrap();
    let b1 = contour_at_x(&out, 60.0).unwrap();
    let t = tabs_on(&out, b1);
    assert_eq!(t.len(), 1, "one tab step over the corner: {t:?}");
    assert_eq!(out.gcode.matches("(tab)").count(), 1);
    assert_eq!(out.plan.stats().tabs, 1);
    // The program is checked for torch cycles without motion by
    // common::rs274_output, as every program the tests check.
    assert_eq!(
        rs274_errors(&out.gcode, "choices-corner-tab"),
        Vec::<String>::new()
    );
}

#[test]
fn the_cli_takes_start_and_tab_points_and_refuses_a_point_on_nothing() {
    let dir = common::out_dir();
    let file = dir.join("choices-cli.dxf");
    std::fs::write(&file, issue_drawing()).unwrap();
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
            .arg(&file)
            .args([
                "--kerf",
                "1",
                "--program-origin",
                "drawing",
                "--layers",
                "B",
            ])
            .args(args)
            .output()
            .unwrap()
    };
    let ok = run(&["--start", "100.3,25", "--tab-at", "80,40.2"]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let g = String::from_utf8(ok.stdout).unwrap();
    assert_eq!(g.matches("(tab)").count(), 1);
    // The loop starts where asked: the first feed after B1's pierce.
    assert!(g.contains("X100.5 Y25"), "{g}");
    let bad = run(&["--start", "20,20"]);
    assert!(!bad.status.success());
    let e = String::from_utf8_lossy(&bad.stderr);
    assert!(e.contains("--start 20,20: no cut loop"), "{e}");
}
