//! A router job with two tools (issue 43 §1): the 60 × 40 pocket round
//! an R 8 island with the job's 6 mm end mill (T1), a 12 × 12 pocket
//! inside the profiled square with a 3 mm one (T2) at its own feeds and
//! speed. The program machines T2's work, changes once to T1, then T1's
//! pocket and the profile; each tool's moves swept with its own radius by
//! the independent checker of `common::mill_sweep`; every program read
//! by rs274.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::mill_sweep::{samples, sweep, Cell, Grid};
use kerfcam::{Spec, ToolSpec};

/// The small pocket, inside the PROFILE square (80..110, 0..30).
const SMALL: (f64, f64, f64, f64) = (89.0, 9.0, 101.0, 21.0);

fn dxf(profile: bool) -> Vec<u8> {
    let text = String::from_utf8(common::pocket_island_dxf(profile)).unwrap();
    let (x0, y0, x1, y1) = SMALL;
    let small = format!(
        "0\nLWPOLYLINE\n8\nSMALL\n90\n4\n70\n1\n10\n{x0}\n20\n{y0}\n10\n{x1}\n20\n{y0}\n10\n{x1}\n20\n{y1}\n10\n{x0}\n20\n{y1}\n"
    );
    text.replace("0\nENDSEC\n0\nEOF", &format!("{small}0\nENDSEC\n0\nEOF"))
        .into_bytes()
}

fn spec(post: &str) -> Spec {
    Spec {
        tool_diameter: Some(6.0),
        feed: Some(2000.0),
        depth: Some(3.0),
        pass_depth: 3.0,
        post: Some(post.into()),
        layer_ops: vec![
            ["POCKET".into(), "pocket".into()],
            ["SMALL".into(), "pocket".into()],
            ["PROFILE".into(), "profile".into()],
        ],
        tools: vec![ToolSpec {
            number: 2,
            diameter: 3.0,
            feed: Some(800.0),
            plunge_feed: Some(150.0),
            spindle_rpm: Some(24000.0),
            ..ToolSpec::default()
        }],
        layer_tools: vec![("SMALL".into(), 2)],
        verify: true,
        ..Spec::default()
    }
}

fn in_small(x: f64, y: f64) -> bool {
    (SMALL.0..SMALL.2).contains(&x) && (SMALL.1..SMALL.3).contains(&y)
}

fn in_big(x: f64, y: f64) -> bool {
    (0.0..60.0).contains(&x) && (0.0..40.0).contains(&y) && (x - 30.0).hypot(y - 20.0) > 8.0
}

/// A grid whose pocket is `pocket` (the rest kept), walls by `wall`.
fn grid(pocket: fn(f64, f64) -> bool, wall: fn(f64, f64) -> f64) -> Grid {
    Grid::new(
        (-2.0, -2.0),
        (112.0, 42.0),
        0.2,
        |x, y| {
            if pocket(x, y) {
                Cell::Pocket
            } else {
                Cell::Keep
            }
        },
        wall,
    )
}

#[test]
fn two_tools_machine_tool_by_tool_with_one_change_each_at_its_feeds_and_radius() {
    let settings = spec("linuxcnc-router").build().unwrap();
    let out = kerfcam::run(&dxf(true), &settings).unwrap();
    let g = &out.gcode;
    assert_eq!(
        common::rs274_errors(g, "milling-tools-linuxcnc"),
        Vec::<String>::new()
    );
    let lines: Vec<&str> = g.lines().collect();
    let at = |s: &str| lines.iter().position(|l| *l == s);
    // The header's tool is the first to work; one change, to the job's.
    let (t2, t1) = (at("T2 M6").unwrap(), at("T1 M6").unwrap());
    assert!(t2 < at("G43 H2").unwrap() && at("G43 H2").unwrap() < at("M3 S24000").unwrap());
    assert!(t1 > t2 && at("G43 H1").unwrap() == t1 + 1);
    assert_eq!(lines.iter().filter(|l| l.contains("M6")).count(), 2);
    assert_eq!(
        lines[t1 - 3],
        "(tool change: T1 6 mm)",
        "{:?}",
        &lines[t1 - 4..t1 + 2]
    );
    // Each tool at its own feeds.
    let (before, after) = (&lines[..t1], &lines[t1..]);
    let has = |ls: &[&str], w: &str| ls.iter().any(|l| l.split_whitespace().any(|x| x == w));
    assert!(has(before, "F800") && has(before, "F150") && !has(before, "F2000"));
    assert!(has(after, "F2000") && has(after, "F300") && !has(after, "F800"));
    // Where each tool cuts below the top: T2 only in the small pocket, T1
    // in the big one then (the profile) round the square, after every
    // pocket (the profile frees the part the small pocket is in).
    let text = |ls: &[&str]| ls.join("\n");
    let cuts = |ls: &[&str]| {
        samples(&text(ls), 0.2)
            .into_iter()
            .filter(|s| s.z < -1e-6)
            .collect::<Vec<_>>()
    };
    let (a, b) = (cuts(before), cuts(after));
    assert!(!a.is_empty() && a.iter().all(|s| in_small(s.x, s.y)));
    let first_profile = b.iter().position(|s| s.x > 70.0).unwrap();
    assert!(b[..first_profile]
        .iter()
        .all(|s| in_big(s.x, s.y) || s.x < 60.0));
    assert!(b[first_profile..]
        .iter()
        .all(|s| !in_big(s.x, s.y) && !in_small(s.x, s.y)));
    // The independent sweep, each tool with its radius, on the milling
    // alone (without the profile): no gouge, its pocket cleared.
    let out2 = kerfcam::run(&dxf(false), &settings).unwrap();
    let lines2: Vec<&str> = out2.gcode.lines().collect();
    let t1 = lines2.iter().position(|l| *l == "T1 M6").unwrap();
    let small_wall = |x: f64, y: f64| {
        (x - SMALL.0)
            .min(SMALL.2 - x)
            .min(y - SMALL.1)
            .min(SMALL.3 - y)
    };
    let big_wall = |x: f64, y: f64| {
        let w = x.min(60.0 - x).min(y).min(40.0 - y);
        w.min((x - 30.0).hypot(y - 20.0) - 8.0)
    };
    let small = grid(in_small, small_wall);
    let big = grid(in_big, big_wall);
    for (name, g, ls, r) in [
        ("T2", &small, &lines2[..t1], 1.5),
        ("T1", &big, &lines2[t1..], 3.0),
    ] {
        let s = sweep(g, &samples(&text(ls), 0.1), r, -3.0, 0.05);
        let pct = 100.0 * s.cleared_mm2 / s.reachable_mm2;
        eprintln!(
            "{name}: cleared {pct:.2} % of {:.0} mm², gouge {:.3} mm²",
            s.reachable_mm2, s.gouge_mm2
        );
        assert_eq!(s.gouge_mm2, 0.0, "{name}: gouge at {:?}", s.gouge_at);
        assert!(pct >= 99.0, "{name}: {pct:.2} %");
        // Planted fault: a disc wider than the tool gouges.
        let wide = sweep(g, &samples(&text(ls), 0.1), r + 0.5, -3.0, 0.05);
        assert!(wide.gouge_mm2 > 0.0, "{name}: the checker misses a gouge");
    }
    // --verify sweeps each tool's pockets with its own radius.
    let own = out.milled.as_ref().unwrap().swept.clone().unwrap();
    assert_eq!((own.gouge_mm2, own.left_mm2), (0.0, 0.0), "{own:?}");
    // The report: each tool's share, in the order they work.
    let report = kerfcam::report::Report::new(&out);
    let tools = &report.plan.tools;
    let rows: Vec<(u32, usize, bool)> = tools
        .iter()
        .map(|t| (t.number, t.pockets, t.profiles))
        .collect();
    assert_eq!(rows, [(2, 1, false), (1, 1, true)]);
    assert_eq!(
        (tools[0].feed, tools[0].plunge_feed, tools[0].spindle_rpm),
        (800.0, 150.0, 24000.0)
    );
    // The time: the program's moves and dwells as written, and the change.
    let post = settings.post().unwrap();
    let program = crate::milling::program_time_s(
        g,
        post.header.len(),
        post.footer.len(),
        out.process.rapid,
        post.safe_height,
    );
    let change = kerfcam::gcode::TOOL_CHANGE_S;
    eprintln!(
        "two tools: program {program:.2} s + change {change} s, estimate {:.2} s; per tool {:?}",
        out.est_time_s,
        tools
            .iter()
            .map(|t| (t.number, t.est_time_s, t.cut_length))
            .collect::<Vec<_>>()
    );
    assert!(
        (out.est_time_s - (program + change)).abs() <= 0.06,
        "{} vs {}",
        out.est_time_s,
        program + change
    );
}

#[test]
fn grbl_pauses_for_the_change_and_a_post_without_one_refuses_two_tools() {
    for post in ["grbl-router", "mach3-router"] {
        let out = kerfcam::run(&dxf(true), &spec(post).build().unwrap()).unwrap();
        let errors = common::rs274_errors(&out.gcode, &format!("milling-tools-{post}"));
        assert!(errors.is_empty(), "{post}: {errors:?}");
        if post == "grbl-router" {
            // GRBL 1.1 has no M6 (its error 20): stopped, raised, paused.
            assert!(!out.gcode.contains("M6"), "{post}");
            let l: Vec<&str> = out.gcode.lines().collect();
            let m0 = l.iter().position(|x| x.starts_with("M0 ")).unwrap();
            assert_eq!(&l[m0 - 3..m0], ["; tool change: T1 6 mm", "G0 Z15", "M5"]);
            assert!(l[m0].contains("tool 1"), "{}", l[m0]);
        } else {
            assert!(out.gcode.contains("T1 M6\nG43 H1"), "{post}");
        }
    }
    // A post of one's own without a tool change: one program per tool.
    let own = r#"{"name": "mine", "header": ["G21 G90", "M3 S{spindle_rpm}"], "pass_z": ["G1 Z{pass_z}"], "pass_retract": ["G0 Z{retract_height}"], "footer": ["M5", "M2"]}"#;
    let mut s = spec("linuxcnc-router");
    s.post = None;
    s.post_json = Some(own.into());
    let e = kerfcam::run(&dxf(true), &s.build().unwrap()).unwrap_err();
    assert!(e.to_string().contains("tool_change"), "{e}");
}

#[test]
fn a_tool_list_that_mills_with_the_jobs_tool_alone_writes_the_one_tool_program() {
    let plain = Spec {
        tools: Vec::new(),
        layer_tools: Vec::new(),
        ..spec("linuxcnc-router")
    };
    let one = kerfcam::run(&dxf(true), &plain.build().unwrap()).unwrap();
    let mut s = spec("linuxcnc-router");
    s.layer_tools = vec![("SMALL".into(), 1)];
    let listed = kerfcam::run(&dxf(true), &s.build().unwrap()).unwrap();
    assert_eq!(listed.gcode, one.gcode);
    assert!(listed.warnings().any(|w| w.code == "tool-unused"));
    assert!(!one.warnings().any(|w| w.code == "tool-unused"));
    // Refused by name: a profile with another tool, a tool the job does
    // not have, a number given twice.
    let field = |f: fn(&mut Spec)| {
        let mut s = spec("linuxcnc-router");
        f(&mut s);
        match s.build() {
            Err(e) => e.field.to_string(),
            Ok(b) => match kerfcam::run(&dxf(true), &b) {
                Err(kerfcam::Error::Settings(e)) => e.field.to_string(),
                other => format!("{:?}", other.map(|_| ())),
            },
        }
    };
    assert_eq!(
        field(|s| s.layer_tools.push(("PROFILE".into(), 2))),
        "layer_tools"
    );
    assert_eq!(
        field(|s| s.layer_tools.push(("SMALL".into(), 5))),
        "layer_tools"
    );
    assert_eq!(field(|s| s.tools[0].number = 1), "tools");
    assert_eq!(field(|s| s.tools[0].stepover = Some(0.0)), "tools");
}

#[test]
fn the_jobs_tool_comes_back_for_the_profile_and_a_job_of_one_listed_tool_has_no_change() {
    // Both pockets with T2: T2 in the header, then the change to T1 for
    // the profile alone, after every pocket.
    let mut s = spec("linuxcnc-router");
    s.layer_tools.push(("POCKET".into(), 2));
    let out = kerfcam::run(&dxf(true), &s.build().unwrap()).unwrap();
    assert_eq!(
        common::rs274_errors(&out.gcode, "milling-tools-profile-after"),
        Vec::<String>::new()
    );
    let lines: Vec<&str> = out.gcode.lines().collect();
    let t1 = lines.iter().position(|l| *l == "T1 M6").unwrap();
    assert!(lines.iter().position(|l| *l == "T2 M6").unwrap() < t1);
    assert!(
        lines[..t1]
            .iter()
            .filter(|l| l.contains("pocket at"))
            .count()
            == 2
    );
    let after = samples(&lines[t1..].join("\n"), 0.5);
    assert!(
        after.iter().filter(|p| p.z < 0.0).all(|p| p.x > 70.0),
        "only the profile after T1"
    );
    let rows: Vec<(u32, usize, bool)> = (kerfcam::report::Report::new(&out).plan.tools.iter())
        .map(|t| (t.number, t.pockets, t.profiles))
        .collect();
    assert_eq!(rows, [(2, 2, false), (1, 0, true)]);
    // No profile: T2 alone, in the header, no change (grbl-router too).
    for post in ["linuxcnc-router", "grbl-router"] {
        let mut s = spec(post);
        s.layer_tools.push(("POCKET".into(), 2));
        let out = kerfcam::run(&dxf(false), &s.build().unwrap()).unwrap();
        assert_eq!(
            common::rs274_errors(&out.gcode, &format!("milling-tools-one-{post}")),
            Vec::<String>::new()
        );
        assert!(!out.gcode.contains("tool change"), "{post}");
        assert!(!out.gcode.contains("M0"), "{post}");
        assert!(
            out.gcode.contains("M3 S24000"),
            "{post}: the header's spindle is T2's"
        );
        assert!(
            out.gcode.contains("; first tool: T2 3 mm")
                || out.gcode.contains("(first tool: T2 3 mm)"),
            "{post}"
        );
    }
}
