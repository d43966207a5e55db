//! Multi-pass depth (issue 20 §8, paper 004: n = ceil(H / d_max),
//! d = H / n): each contour cut n times at decreasing Z, read back from the
//! program text, checked by LinuxCNC's `rs274`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::rs274_errors;
use kerfcam::gcode::{preset, JobInfo};
use kerfcam::origin::ProgramOrigin;
use kerfcam::process::Passes;
use kerfcam::{Output, Settings};

/// A 100 × 50 plate with a 20 mm hole.
fn plate() -> Vec<u8> {
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nCUT\n90\n4\n70\n1\n");
    for (x, y) in [(0, 0), (100, 0), (100, 50), (0, 50)] {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s += "0\nCIRCLE\n8\nCUT\n10\n50\n20\n25\n40\n10\n0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

const TEN_IN_FOURS: Passes = Passes {
    depth: 10.0,
    pass_depth: 4.0,
};

fn settings(post: Option<&str>, passes: Passes) -> Settings {
    let s = Settings::new(1.0, 0.001, 1500.0)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .and_then(|s| s.with_passes(passes))
        .unwrap();
    match post {
        Some(name) => s.with_post(preset(name).unwrap()).unwrap(),
        None => s,
    }
}

fn run(post: Option<&str>, passes: Passes) -> Output {
    kerfcam::run(&plate(), &settings(post, passes)).unwrap()
}

/// Each cut's pass depths in program order: the Z word of the block after
/// each `(pass k of n)` comment, within the text after a `(cut N …)`
/// comment up to the next. Every other plunge in the cut (a knife lifted
/// over a corner) goes back to the depth of the pass it is in: Z never
/// rises between passes.
fn depths_per_cut(g: &str) -> Vec<Vec<String>> {
    let mut cuts: Vec<Vec<String>> = Vec::new();
    let mut after_pass = false;
    let mut deepest = 0.0_f64;
    for l in g.lines() {
        if l.starts_with("(cut ") {
            cuts.push(Vec::new());
            deepest = 0.0;
        } else if l.starts_with("(pass ") {
            after_pass = true;
        } else if let (Some(c), Some(z)) = (cuts.last_mut(), l.strip_prefix("G1 Z-")) {
            let z = z.split(' ').next().unwrap();
            let depth: f64 = z.parse().unwrap();
            if std::mem::take(&mut after_pass) {
                assert!(depth > deepest, "pass deeper than the last: {l}");
                deepest = depth;
                c.push(format!("-{z}"));
            } else {
                assert_eq!(depth, deepest, "a plunge off the pass's depth: {l}");
            }
        }
    }
    cuts
}

#[test]
fn ten_mm_in_four_mm_passes_is_three_passes_on_every_contour() {
    for post in [
        None,
        Some("linuxcnc"),
        Some("linuxcnc-z"),
        Some("knife-gcode"),
    ] {
        let out = run(post, TEN_IN_FOURS);
        let g = &out.gcode;
        let cuts = depths_per_cut(g);
        assert_eq!(cuts.len(), 2, "{post:?}: two contours\n{g}");
        for c in &cuts {
            assert_eq!(c, &["-3.333", "-6.667", "-10"], "{post:?}\n{g}");
        }
        // One pierce and one tool-off per contour: no re-pierce between passes.
        // (The knife also lifts over sharp corners, paper 003: its plunges
        // back to the pass's depth are checked by depths_per_cut.)
        if post != Some("knife-gcode") {
            assert_eq!(
                g.lines().filter(|l| *l == "M3 S1").count(),
                2,
                "{post:?}\n{g}"
            );
            assert_eq!(
                g.lines().filter(|l| *l == "M5").count(),
                2 + usize::from(post == Some("linuxcnc-z")),
                "{post:?}\n{g}"
            );
        }
        // The closed contour is gone round three times: three times the
        // arcs of the hole (two half-circle blocks or more each time).
        let single = run(post, Passes::OFF);
        let feeds = |p: &str| {
            p.lines()
                .filter(|l| l.starts_with("G2") || l.starts_with("G3") || l.starts_with("G1 X"))
                .count()
        };
        assert!(feeds(g) > 2 * feeds(&single.gcode), "{post:?}");
        let errors = rs274_errors(g, &format!("multipass-{}", post.unwrap_or("default")));
        assert!(errors.is_empty(), "{post:?}: rs274: {errors:?}\n{g}");
    }
}

#[test]
fn the_tool_goes_up_once_after_the_last_pass_and_before_any_rapid() {
    let g = run(Some("linuxcnc"), TEN_IN_FOURS).gcode;
    let lines: Vec<&str> = g.lines().collect();
    // Before the first rapid in XY, the tool is at the safe height.
    let first_rapid = lines.iter().position(|l| l.starts_with("G0 X")).unwrap();
    assert!(lines[..first_rapid].contains(&"G0 Z10"), "{g}");
    // Every M5 follows a retract, and no rapid in XY is made below the surface.
    let mut z = 10.0_f64;
    for (i, l) in lines.iter().enumerate() {
        if let Some(v) = l.strip_prefix("G1 Z").or_else(|| l.strip_prefix("G0 Z")) {
            z = v.parse().unwrap();
        }
        if l.starts_with("G0 X") {
            assert!(z > 0.0, "rapid below the surface at line {i}: {l}\n{g}");
        }
        if *l == "M5" {
            assert_eq!(lines[i - 1], "G0 Z10", "{g}");
        }
    }
}

#[test]
fn time_estimates_grow_with_the_passes() {
    let one = run(Some("linuxcnc"), Passes::OFF);
    let three = run(Some("linuxcnc"), TEN_IN_FOURS);
    let t1 = one.plan.est_time_s(&one.process);
    let t3 = three.plan.est_time_s(&three.process);
    let st = one.plan.stats();
    // The contours (not the leads) are cut twice more.
    let extra = 2.0 * 60.0 * (st.cut_length + st.repeated_length) / 1500.0;
    assert!(((t3 - t1) - extra).abs() < 1e-6, "{t1} {t3} {extra}");
    let job = |p: Passes| JobInfo::from_process(settings(None, p).process());
    assert!(
        kerfcam::gcode::est_time_s(&three.plan, &job(TEN_IN_FOURS))
            > kerfcam::gcode::est_time_s(&one.plan, &job(Passes::OFF)) + extra - 1e-6
    );
}

#[test]
fn a_post_without_a_z_word_refuses_multi_pass_naming_itself() {
    for name in ["qtplasmac", "linuxcnc-plasma", "point-list", "grbl-laser"] {
        let err = kerfcam::run(&plate(), &settings(Some(name), TEN_IN_FOURS))
            .err()
            .unwrap_or_else(|| panic!("{name} accepted multi-pass"));
        let msg = err.to_string();
        let post_name = preset(name).unwrap().name;
        assert!(
            msg.contains("pass_z") && msg.contains(&post_name),
            "{name}: {msg}"
        );
        // Without passes the same post writes its program.
        assert!(kerfcam::run(&plate(), &settings(Some(name), Passes::OFF)).is_ok());
    }
}

#[test]
fn half_given_or_bad_depths_are_refused_and_off_changes_nothing() {
    let base = Settings::new(1.0, 0.001, 1500.0).unwrap();
    for (p, field) in [
        (
            Passes {
                depth: 10.0,
                pass_depth: 0.0,
            },
            "pass_depth",
        ),
        (
            Passes {
                depth: 0.0,
                pass_depth: 3.0,
            },
            "depth",
        ),
        (
            Passes {
                depth: -1.0,
                pass_depth: 3.0,
            },
            "depth",
        ),
        (
            Passes {
                depth: 10.0,
                pass_depth: f64::NAN,
            },
            "pass_depth",
        ),
        (
            Passes {
                depth: 1000.0,
                pass_depth: 0.001,
            },
            "pass_depth",
        ),
    ] {
        assert_eq!(
            base.clone().with_passes(p).unwrap_err().field,
            field,
            "{p:?}"
        );
    }
    let off = run(Some("linuxcnc"), Passes::OFF).gcode;
    assert!(!off.contains(" Z") && !off.contains("pass"), "{off}");
}

#[test]
fn an_open_path_is_cut_back_and_forth_one_plunge_per_pass() {
    // A 60 mm line, cut as an open path: no lead, it does not return to its start.
    let bytes = b"0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nCUT\n10\n0\n20\n0\n11\n60\n21\n0\n0\nENDSEC\n0\nEOF\n";
    let s = settings(Some("linuxcnc"), TEN_IN_FOURS);
    let plan = kerfcam::plan::PlanOptions {
        cut_open: true,
        ..s.plan().clone()
    };
    let out = kerfcam::run(bytes, &s.with_plan(plan).unwrap()).unwrap();
    let g = &out.gcode;
    assert_eq!(depths_per_cut(g), [["-3.333", "-6.667", "-10"]], "{g}");
    // The XY the tool reaches at the end of each pass: the far end, back at
    // the start, the far end again.
    let mut ends = Vec::new();
    let mut last = None;
    for l in g.lines() {
        if l.starts_with("(pass ") || l == "G0 Z10" {
            if let Some(x) = last.take() {
                ends.push(x);
            }
        } else if let Some(rest) = l.strip_prefix("G1 X") {
            last = Some(rest.split(' ').next().unwrap().to_string());
        }
    }
    assert_eq!(ends, ["60", "0", "60"], "{g}");
    assert_eq!(g.lines().filter(|l| *l == "M3 S1").count(), 1, "{g}");
    let errors = rs274_errors(g, "multipass-open");
    assert!(errors.is_empty(), "rs274: {errors:?}\n{g}");
}
