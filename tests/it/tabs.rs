//! Tabs (issue 20 §6, paper 001's "travas"): N stretches of W mm of
//! material left on each part's outline, read back from the program text
//! (the backplot), not from the plan that placed them; every program
//! through LinuxCNC's `rs274`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::{rs274_errors, rs274_qtplasmac};
use kerfcam::gcode::{backplot, preset};
use kerfcam::geom::{Point, Segment};
use kerfcam::origin::ProgramOrigin;
use kerfcam::plan::Tabs;
use kerfcam::{Output, Settings};

const KERF: f64 = 1.5;
const W: f64 = 3.0;

/// A 100 × 50 plate with a 20 mm hole, and a 40 mm disc at (200, 25).
fn drawing() -> Vec<u8> {
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nCUT\n90\n4\n70\n1\n");
    for (x, y) in [(0, 0), (100, 0), (100, 50), (0, 50)] {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s += "0\nCIRCLE\n8\nCUT\n10\n50\n20\n25\n40\n10\n";
    s += "0\nCIRCLE\n8\nCUT\n10\n200\n20\n25\n40\n20\n0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

fn settings(post: Option<&str>, n: usize) -> Settings {
    let mut s = Settings::new(KERF, 0.001, 1500.0)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .unwrap()
        .with_verify(true);
    if let Some(p) = post {
        s = s.with_post(preset(p).unwrap()).unwrap();
    }
    let mut plan = s.plan().clone();
    plan.tabs = Tabs {
        count: n,
        width: W,
        holes: false,
    };
    s.with_plan(plan).unwrap()
}

fn run(post: Option<&str>, n: usize) -> Output {
    kerfcam::run(&drawing(), &settings(post, n)).unwrap()
}

/// The torch-on moves of a program, as it reads back.
fn torch_on(gcode: &str) -> Vec<Segment> {
    backplot(gcode)
        .moves
        .iter()
        .filter(|m| m.torch() == Some(true))
        .flat_map(|m| m.segments())
        .collect()
}

/// Points along the torch-on moves at most 0.01 mm apart, filed by 1 mm
/// cells: "within r of a move" within 0.005 mm.
fn samples(cuts: &[Segment]) -> std::collections::HashMap<(i64, i64), Vec<Point>> {
    let mut grid: std::collections::HashMap<(i64, i64), Vec<Point>> = Default::default();
    for s in cuts {
        let n = ((s.length() / 0.01).ceil() as usize).max(1);
        for k in 0..=n {
            let p = s.point_at(k as f64 / n as f64);
            grid.entry((p.x.floor() as i64, p.y.floor() as i64))
                .or_default()
                .push(p);
        }
    }
    grid
}

/// The stretches of a closed centre line (points `step` apart) that no
/// torch-on move comes within half the kerf of: (start index, length mm).
fn uncut(line: &[Point], cuts: &[Segment], step: f64) -> Vec<(usize, f64)> {
    let r = KERF / 2.0 + 0.006;
    let grid = samples(cuts);
    let near = |p: &Point| {
        let (i, j) = (p.x.floor() as i64, p.y.floor() as i64);
        (i - 1..=i + 1).any(|a| {
            (j - 1..=j + 1).any(|b| {
                grid.get(&(a, b))
                    .is_some_and(|v| v.iter().any(|q| q.dist(*p) <= r))
            })
        })
    };
    let hit: Vec<bool> = line.iter().map(near).collect();
    // Start from a cut point so a run does not wrap round.
    let Some(first) = hit.iter().position(|h| *h) else {
        return vec![(0, line.len() as f64 * step)];
    };
    let mut runs = Vec::new();
    let mut start = None;
    for k in 0..=line.len() {
        let i = (first + k) % line.len();
        match (hit[i], start) {
            (false, None) => start = Some(i),
            (true, Some(s)) => {
                let n = (i + line.len() - s) % line.len();
                runs.push((s, n as f64 * step));
                start = None;
            }
            _ => {}
        }
    }
    runs
}

/// The kerf centre line round the 100 × 50 plate's straight edges (the
/// corners' arcs left out: no tab may be there anyway).
fn plate_line(step: f64) -> Vec<Point> {
    let r = KERF / 2.0;
    let mut v = Vec::new();
    let edges: [((f64, f64), (f64, f64)); 4] = [
        ((0.0, -r), (100.0, -r)),
        ((100.0 + r, 0.0), (100.0 + r, 50.0)),
        ((100.0, 50.0 + r), (0.0, 50.0 + r)),
        ((-r, 50.0), (-r, 0.0)),
    ];
    for ((x0, y0), (x1, y1)) in edges {
        let len = (x1 - x0).hypot(y1 - y0);
        let n = (len / step).round() as usize;
        for k in 0..n {
            let t = k as f64 / n as f64;
            v.push(Point::new(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t));
        }
    }
    v
}

fn circle_line(cx: f64, cy: f64, rad: f64, step: f64) -> Vec<Point> {
    let n = (std::f64::consts::TAU * rad / step).round() as usize;
    (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            Point::new(cx + rad * a.cos(), cy + rad * a.sin())
        })
        .collect()
}

#[test]
fn tabs_leave_n_gaps_of_w_on_each_outer_contour_read_back_from_the_program() {
    let step = 0.01;
    for post in [
        None,
        Some("qtplasmac"),
        Some("linuxcnc-z"),
        Some("linuxcnc-plasma"),
    ] {
        let name = post.unwrap_or("linuxcnc");
        for n in [1, 2, 3] {
            let out = run(post, n);
            let cuts = torch_on(&out.gcode);
            // The plate: n bridges of W, each on a straight edge clear of
            // its corners (1.5 mm and more) and of the lead-in's end.
            let line = plate_line(step);
            let gaps = uncut(&line, &cuts, step);
            assert_eq!(gaps.len(), n, "{name} n={n}: plate gaps {gaps:?}");
            for &(i, len) in &gaps {
                assert!((len - W).abs() < 0.05, "{name} n={n}: gap {len} mm");
                let p = line[i];
                let corner = [(0.0, 0.0), (100.0, 0.0), (100.0, 50.0), (0.0, 50.0)]
                    .iter()
                    .map(|&(x, y)| p.dist(Point::new(x, y)))
                    .fold(f64::INFINITY, f64::min);
                assert!(corner > 1.5, "{name}: a tab {corner} mm from a corner");
            }
            // The disc: no straight edge, tabs on its arc.
            let disc = circle_line(200.0, 25.0, 20.0 + KERF / 2.0, step);
            let gaps = uncut(&disc, &cuts, step);
            assert_eq!(gaps.len(), n, "{name} n={n}: disc gaps {gaps:?}");
            for &(_, len) in &gaps {
                assert!((len - W).abs() < 0.05, "{name} n={n}: disc gap {len} mm");
            }
            // Holes keep no tab by default.
            let hole = circle_line(50.0, 25.0, 10.0 - KERF / 2.0, step);
            assert!(
                uncut(&hole, &cuts, step).is_empty(),
                "{name}: a tab in the hole"
            );
            let file = format!("tabs-{name}-{n}");
            let errors = if name == "qtplasmac" {
                rs274_qtplasmac(&out.gcode, &file)
            } else {
                rs274_errors(&out.gcode, &file)
            };
            assert!(errors.is_empty(), "{name} n={n}: rs274 {errors:?}");
            let st = out.plan.stats();
            assert_eq!(st.tabs, 2 * n, "{name}");
            // Each tab a restart: pierces are the contours plus the tabs.
            assert_eq!(st.pierces, 3 + 2 * n, "{name}");
        }
    }
}

#[test]
fn tabs_stay_clear_of_the_lead_in_and_the_overcut() {
    let mut s = settings(None, 4);
    let mut plan = s.plan().clone();
    plan.leads.overcut = 6.0;
    s = s.with_plan(plan).unwrap();
    let out = kerfcam::run(&drawing(), &s).unwrap();
    let step = 0.01;
    let cuts = torch_on(&out.gcode);
    // Where the plate's lead-in reaches its contour: the end of the first
    // torch-on move of the plate's cut (read from the program).
    let b = backplot(&out.gcode);
    let line = plate_line(step);
    let mut joins = Vec::new();
    let mut was_on = false;
    for m in &b.moves {
        let on = m.torch() == Some(true);
        if on && !was_on {
            // A lead-in starts off the contour (a restart after a tab on it).
            let seg = m.segments()[0];
            let off = line
                .iter()
                .map(|p| p.dist(seg.a))
                .fold(f64::INFINITY, f64::min);
            if off > 1.0 {
                joins.push(seg.b);
            }
        }
        was_on = on;
    }
    let gaps = uncut(&line, &cuts, step);
    assert_eq!(gaps.len(), 4, "{gaps:?}");
    for &(i, len) in &gaps {
        let mid = line[(i + (len / 2.0 / step) as usize) % line.len()];
        // The lead-in's end on the plate and the 6 mm overcut after it.
        let lead = joins
            .iter()
            .filter(|j| j.x > -2.0 && j.x < 102.0 && j.y > -2.0 && j.y < 52.0)
            .map(|j| j.dist(mid))
            .fold(f64::INFINITY, f64::min);
        assert!(lead > 6.0 + W / 2.0, "a tab {lead} mm from a lead-in");
    }
}

#[test]
fn off_by_default_and_the_verification_counts_parts_held_by_tabs() {
    let delay = |n| {
        kerfcam::run(
            &drawing(),
            &settings(None, n).with_pierce_delay(0.5).unwrap(),
        )
        .unwrap()
    };
    let plain = run(None, 0);
    assert!(!plain.gcode.contains("(tab)"));
    let v = plain.verification.unwrap();
    assert_eq!((v.parts_not_freed, v.parts_held_by_tabs), (0, 0), "{v:?}");
    let tabbed = run(None, 2);
    let v = tabbed.verification.clone().unwrap();
    assert_eq!(
        v.parts_not_freed, 0,
        "held by tabs is not 'not freed': {v:?}"
    );
    assert_eq!(v.parts_held_by_tabs, 2, "{v:?}");
    assert_eq!(v.overcut_mm2, 0.0, "{v:?}");
    // The time estimate counts the restarts; the report lists tabs by part.
    let t = |o: &Output| o.plan.stats().est_time_s(&o.process);
    let (a, b) = (delay(0), delay(2));
    let st = b.plan.stats();
    // Each tab: its stretch at the rapid speed instead of the feed, and a
    // pierce delay.
    let want = 4.0 * 0.5 + st.tab_length * (60.0 / b.process.rapid - 60.0 / b.process.feed);
    assert!(
        (t(&b) - t(&a) - want).abs() < 1e-6,
        "{} {} {want}",
        t(&b),
        t(&a)
    );
    assert!((st.tab_length - 4.0 * (W + KERF)).abs() < 1e-6, "{st:?}");
    let json = kerfcam::report::Report::new(&tabbed).to_json();
    assert!(json.contains(r#""tabs":4"#), "{json}");
    assert!(
        json.contains(r#""tabs_per_part":[{"part":1,"tabs":2},{"part":2,"tabs":2}]"#),
        "{json}"
    );
    assert!(json.contains(r#""parts_held_by_tabs":2"#), "{json}");
}

#[test]
fn a_post_with_tab_templates_keeps_moving_over_the_tab() {
    let mut post = preset("linuxcnc").unwrap();
    post.tab_off = vec!["M62 P3".into()];
    post.tab_on = vec!["M63 P3".into()];
    let s = settings(None, 1).with_post(post).unwrap();
    let out = kerfcam::run(&drawing(), &s).unwrap();
    let g = &out.gcode;
    assert_eq!(g.matches("M62 P3").count(), 2, "{g}");
    // The move after the torch goes off is a feed move, not a rapid.
    let after: Vec<&str> = g
        .lines()
        .skip_while(|l| *l != "M62 P3")
        .skip(1)
        .take(1)
        .collect();
    assert!(
        after[0].starts_with("G1") || after[0].starts_with("G2") || after[0].starts_with("G3"),
        "{after:?}"
    );
    assert_eq!(rs274_errors(g, "tabs-synchronised"), Vec::<String>::new());
    // One template without the other is refused, naming the field.
    let mut half = preset("linuxcnc").unwrap();
    half.tab_off = vec!["M62 P3".into()];
    assert_eq!(half.validate().unwrap_err().field, "tab_on");
}

#[test]
fn depth_passes_lift_over_each_tab_in_each_pass() {
    let s = settings(None, 1)
        .with_passes(kerfcam::process::Passes {
            depth: 6.0,
            pass_depth: 3.0,
        })
        .unwrap();
    let out = kerfcam::run(&drawing(), &s).unwrap();
    let g = &out.gcode;
    // Two outer contours × two passes: a retract and a plunge per tab.
    let tabs = g.matches("(tab)").count();
    assert_eq!(tabs, 4, "{g}");
    let errors = rs274_errors(g, "tabs-passes");
    assert!(errors.is_empty(), "{errors:?}");
    for block in g.split("(tab)").skip(1) {
        let lines: Vec<&str> = block.lines().skip(1).take(5).collect();
        assert_eq!(lines[0], "M5", "{lines:?}");
        assert!(lines[1].starts_with("G0 Z"), "{lines:?}");
        assert!(lines.iter().any(|l| l.starts_with("G1 Z-")), "{lines:?}");
    }
}

#[test]
fn row_formats_refuse_tabs_naming_the_post() {
    for name in ["point-list", "knife-relative"] {
        let s = settings(None, 1).with_post(preset(name).unwrap()).unwrap();
        match kerfcam::run(&drawing(), &s) {
            Err(e) => assert!(e.to_string().contains("tabs"), "{name}: {e}"),
            Ok(_) => panic!("{name}: tabs written by a post that cannot stop the torch"),
        }
        // Without tabs the same post writes its program.
        let s = settings(None, 0).with_post(preset(name).unwrap()).unwrap();
        assert!(kerfcam::run(&drawing(), &s).is_ok());
    }
}

#[test]
fn a_tab_placed_by_a_click_leaves_its_gap_where_clicked() {
    let mut s = settings(None, 0);
    let mut plan = s.plan().clone();
    // The top edge at x = 30 (a click lands on the drawn line, not the
    // kerf path), twice (the second is the same tab), and the disc's top.
    // Points near the loops, as `--tab-at X,Y` gives them.
    let near = |x, y| kerfcam::plan::choice::Pick::near(Point::new(x, y), 1.0);
    plan.tabs_at = vec![near(30.0, 50.2), near(30.5, 50.0), near(200.0, 45.0)];
    s = s.with_plan(plan).unwrap();
    let out = kerfcam::run(&drawing(), &s).unwrap();
    let cuts = torch_on(&out.gcode);
    let step = 0.01;
    let line = plate_line(step);
    let gaps = uncut(&line, &cuts, step);
    assert_eq!(gaps.len(), 1, "{gaps:?}");
    let (at, len) = gaps[0];
    assert!((len - W).abs() < 0.05, "{gaps:?}");
    // Centred on the click: the gap runs along the top edge (x falling).
    let centre = line[at].x - len / 2.0;
    assert!(
        (line[at].y - (50.0 + KERF / 2.0)).abs() < 1e-9 && (centre - 30.0).abs() < 0.05,
        "{centre}"
    );
    let disc_gaps = uncut(
        &circle_line(200.0, 25.0, 20.0 + KERF / 2.0, step),
        &cuts,
        step,
    );
    assert_eq!(disc_gaps.len(), 1, "{disc_gaps:?}");
    assert!((disc_gaps[0].1 - W).abs() < 0.05, "{disc_gaps:?}");
    assert_eq!(out.verification.as_ref().unwrap().parts_held_by_tabs, 2);
    assert_eq!(
        rs274_errors(&out.gcode, "tabs-clicked"),
        Vec::<String>::new()
    );
    // With the controller's compensation: refused, as automatic tabs are.
    let mut plan = s.plan().clone();
    plan.controller_comp = true;
    assert_eq!(s.clone().with_plan(plan).unwrap_err().field, "tabs");
}
