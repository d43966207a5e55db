//! Posts: golden programs of every preset on every fixture, LinuxCNC's
//! interpreter on every RS274 preset (fixtures and corpus), GRBL's arc rule,
//! paper 002's point list reproduced, safe output.
//! `BLESS=1 cargo test --profile ci --test it posts::` rewrites `tests/golden/posts/`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use std::path::PathBuf;

use common::{fixture, kerf, out_dir, run};
use kerfcam::gcode::{self, backplot, emit_post, preset, BackplotMove, JobInfo, Post};
use kerfcam::kerf::Join;
use kerfcam::plan::Order;
use kerfcam::{Output, Settings};

/// Presets LinuxCNC's interpreter can check (annex H, the point list and
/// the knife rows are not RS274).
const RS274: [&str; 8] = [
    "linuxcnc-plasma",
    "linuxcnc",
    "grbl-laser",
    "grbl-plasma",
    "mach3-plasma",
    "iso6983",
    "knife-gcode",
    "linuxcnc-z",
];

/// `common::rs274_errors`, also taking canonical lines of numbered blocks
/// (`  9 N10    SELECT_PLANE(…)`) as canonical.
fn rs274_errors(program: &str, name: &str) -> Vec<String> {
    common::rs274_errors(program, name)
        .into_iter()
        .filter(|l| {
            let t = l.trim_start();
            let t = t
                .trim_start_matches(|c: char| c.is_ascii_digit())
                .trim_start();
            let n = t.strip_prefix('N').unwrap_or("x");
            let rest = n.trim_start_matches(|c: char| c.is_ascii_digit());
            // Past N99999 rs274 prints no gap: `N100000STRAIGHT_FEED(…)`.
            !(rest.len() < n.len()
                && rest.starts_with(|c: char| c == ' ' || c.is_ascii_uppercase()))
        })
        .collect()
}

fn golden_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/golden/posts")
}

fn cases() -> Vec<(&'static str, &'static str, Settings)> {
    let mut drawing = kerf(0.0);
    drawing = drawing.map_plan(|p| p.order = Order::Drawing).unwrap();
    vec![
        ("plate-6-holes-k2", "seed000-plate-6-holes.dxf", kerf(2.0)),
        ("figure1-k0", "seed000-figure1.dxf", kerf(0.0)),
        (
            "p51703-k3-miter",
            "seed001-P51703.dxf",
            kerf(3.0).with_join(Join::Miter),
        ),
        ("figure4-drawing", "seed002-figure4.dxf", drawing),
        ("grid-3x2-k1.5", "seed003-grid-3x2.dxf", kerf(1.5)),
    ]
}

fn job(s: &Settings) -> JobInfo {
    JobInfo::from_process(&kerfcam::process::Process {
        pierce_delay: 0.5,
        ..*s.process()
    })
}

/// The job for `post`: a router's cuts 6 mm stock in two passes (without
/// a depth its program is refused, see below).
fn job_for(post: &Post, s: &Settings) -> JobInfo {
    let mut job = job(s);
    if gcode::is_router(post) {
        job.process.passes = kerfcam::process::Passes {
            depth: 6.0,
            pass_depth: 3.0,
        };
    }
    job
}

fn program(out: &Output, post: &Post, s: &Settings) -> String {
    emit_post(&out.plan, post, &job_for(post, s)).unwrap()
}

#[test]
fn a_router_post_without_a_depth_is_refused_naming_the_setting() {
    let s = kerf(0.0);
    let out = run(&fixture("seed000-figure1.dxf"), &s).unwrap();
    let mut routers = 0;
    for name in gcode::PRESET_NAMES {
        let post = preset(name).unwrap();
        let r = emit_post(&out.plan, &post, &job(&s));
        if !gcode::is_router(&post) {
            assert!(r.is_ok(), "{name}: {r:?}");
            continue;
        }
        routers += 1;
        let e = r.expect_err(name);
        assert_eq!(e.field, "job.depth", "{name}");
        assert!(e.reason.en.contains("--depth MM"), "{name}: {}", e.reason.en);
        // With a depth: written, every profile cut below the top (Z < 0).
        let text = emit_post(&out.plan, &post, &job_for(&post, &s)).unwrap();
        assert!(text.lines().any(|l| l.starts_with("G1 Z-")), "{name}:\n{text}");
    }
    assert_eq!(routers, 3);
    // Through the pipeline: an error naming --depth, no program.
    let s = kerf(0.0).with_post(preset("grbl-router").unwrap()).unwrap();
    let e = run(&fixture("seed000-figure1.dxf"), &s).expect_err("refused");
    assert!(e.to_string().contains("--depth MM"), "{e}");
}

#[test]
fn every_preset_matches_its_golden_file_on_every_fixture() {
    let bless = std::env::var("BLESS").as_deref() == Ok("1");
    let mut changed = Vec::new();
    for (case, file, settings) in cases() {
        let out = run(&fixture(file), &settings).unwrap();
        for name in gcode::PRESET_NAMES {
            let post = preset(name).unwrap();
            let text = program(&out, &post, &settings);
            let path = golden_dir().join(format!("{case}.{name}.txt"));
            if bless {
                std::fs::create_dir_all(golden_dir()).unwrap();
                std::fs::write(&path, &text).unwrap();
                continue;
            }
            if std::fs::read_to_string(&path).unwrap_or_default() != text {
                std::fs::write(out_dir().join(format!("{case}.{name}.txt")), &text).unwrap();
                changed.push(format!("{case}.{name}"));
            }
        }
    }
    assert!(changed.is_empty(), "differ (new in tests/out): {changed:?}");
}

#[test]
fn rs274_accepts_every_rs274_preset_on_the_fixtures() {
    let mut failures = Vec::new();
    for (case, file, settings) in cases() {
        let out = run(&fixture(file), &settings).unwrap();
        for name in RS274 {
            let text = program(&out, &preset(name).unwrap(), &settings);
            let errors = rs274_errors(&text, &format!("posts-{case}-{name}"));
            if !errors.is_empty() {
                failures.push(format!(
                    "{case} {name}: {:?}",
                    &errors[..errors.len().min(3)]
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn rs274_accepts_every_rs274_preset_on_the_corpus() {
    let mut failures = Vec::new();
    let settings = common::corpus_settings();
    for common::CorpusRun { name, out, .. } in common::corpus_runs() {
        let Ok(out) = out else {
            continue;
        };
        let safe: String = name
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        // The plain LinuxCNC program is checked by tests/it/corpus.rs.
        for name in RS274.iter().filter(|n| **n != "linuxcnc") {
            let text = program(out, &preset(name).unwrap(), &settings);
            let errors = rs274_errors(&text, &format!("posts-corpus-{safe}-{name}"));
            if !errors.is_empty() {
                failures.push(format!(
                    "{safe} {name}: {:?}",
                    &errors[..errors.len().min(3)]
                ));
            }
            assert!(grbl_arc_errors(&text).is_empty(), "{safe} {name}");
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// GRBL's arc check (gcode.c, "Arc definition error"): error 33 when the
/// start and end radii differ by more than 0.005 mm and, either by more than
/// 0.5 mm, or by more than 0.1 % of the radius.
fn grbl_arc_errors(text: &str) -> Vec<String> {
    backplot(text)
        .moves
        .iter()
        .filter_map(|m| match *m {
            BackplotMove::Arc {
                from, to, center, ..
            } => {
                let r = from.dist(center);
                let dr = (to.dist(center) - r).abs();
                (dr > 0.005 && (dr > 0.5 || dr > 0.001 * r))
                    .then(|| format!("arc {from:?}→{to:?} radii differ by {dr}"))
            }
            _ => None,
        })
        .collect()
}

#[test]
fn grbl_programs_keep_grbls_arc_rule() {
    for (case, file, settings) in cases() {
        let out = run(&fixture(file), &settings).unwrap();
        for name in ["grbl-laser", "grbl-plasma"] {
            let text = program(&out, &preset(name).unwrap(), &settings);
            assert!(
                text.lines()
                    .all(|l| !l.contains("G41") && !l.contains("G42")),
                "{case} {name}: no cutter compensation on GRBL"
            );
            let e = grbl_arc_errors(&text);
            assert!(e.is_empty(), "{case} {name}: {e:?}");
        }
    }
}

#[test]
fn seed002_point_list_is_the_papers_table() {
    let mut s = kerf(0.0);
    s = s.map_plan(|p| p.order = Order::Drawing).unwrap();
    let out = run(&fixture("seed002-figure4.dxf"), &s).unwrap();
    let text = program(&out, &preset("point-list").unwrap(), &s);
    // ../shared/fixtures/EXPECTED.md, rows 1–30.
    let want = "\
100;150 D
100;200 L
104.39;210.61
115;215
125.61;210.61
130;200
132.91;190.43
138.38;182.05
145.98;175.54
155.1;171.41
165;170
174.9;171.41
184.02;175.54
191.62;182.05
197.09;190.43
200;200
196.49;209.64
187.6;214.77
177.5;212.99
170.9;205.13
170.9;194.87
177.5;187.01
187.6;185.23
196.49;190.36
200;200
200;150 D
L
165;150 D
115;150 L
D
";
    assert_eq!(text, want);
}

#[test]
fn every_gcode_program_ends_torch_off_then_program_end() {
    for (case, file, settings) in cases() {
        let out = run(&fixture(file), &settings).unwrap();
        for name in RS274.iter().chain(&["annex-h"]) {
            let post = preset(name).unwrap();
            let text = program(&out, &post, &settings);
            // Last line whose block (framing stripped) ends with `w`.
            let last = |w: &str| {
                text.lines()
                    .collect::<Vec<_>>()
                    .iter()
                    .rposition(|l| l.trim_end().trim_end_matches('$').ends_with(w))
            };
            // The last fixed word (a Z post retracts to `{safe_height}` after M5).
            let off = post
                .torch_off
                .iter()
                .rev()
                .find(|t| !t.contains('{'))
                .unwrap();
            let on = post
                .torch_on
                .iter()
                .rev()
                .find(|t| !t.contains('{'))
                .unwrap();
            let end = ["M2", "M30", "M02"]
                .iter()
                .filter_map(|w| last(w))
                .max()
                .unwrap();
            assert!(last(off) > last(on), "{case} {name}: torch left on");
            assert!(
                end > last(off).unwrap(),
                "{case} {name}: no end after torch off"
            );
        }
    }
}

#[test]
fn an_inch_post_with_r_arcs_and_absolute_centres_is_accepted() {
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &kerf(2.0)).unwrap();
    for (arcs, units) in [
        (gcode::ArcMode::R, gcode::Units::Mm),
        (gcode::ArcMode::IjAbsolute, gcode::Units::Mm),
        (gcode::ArcMode::IjIncremental, gcode::Units::Inch),
        (gcode::ArcMode::Lines, gcode::Units::Inch),
    ] {
        let unit_word = if units == gcode::Units::Inch {
            "G20"
        } else {
            "G21"
        };
        let ij = if arcs == gcode::ArcMode::IjAbsolute {
            "G90.1"
        } else {
            "G91.1"
        };
        let post = Post {
            arcs,
            units,
            decimals: 4,
            max_arc_sweep_deg: 90.0,
            header: vec![format!("{unit_word} G90 G17 G40 {ij}"), "F{feed}".into()],
            ..Post::default()
        };
        let text = emit_post(&out.plan, &post, &job(&kerf(2.0))).unwrap();
        let errors = rs274_errors(&text, &format!("posts-{arcs:?}-{units:?}"));
        assert!(errors.is_empty(), "{arcs:?} {units:?}: {errors:?}");
    }
}

#[test]
fn a_bad_post_file_names_its_field() {
    let e = Post::from_json(r#"{"header": ["G21", "F{speed}"]}"#).unwrap_err();
    assert_eq!(e.field, "header[1]");
    let e = Post::from_json(r#"{"decimals": "three"}"#).unwrap_err();
    assert_eq!(e.field, "json");
}

#[test]
fn time_estimate_uses_the_jobs_rapid_speed() {
    let s = kerf(2.0);
    let out = run(&fixture("seed000-plate-6-holes.dxf"), &s).unwrap();
    let at = |rapid: f64| job(&s.clone().with_rapid(rapid).unwrap());
    let (a, b) = (
        gcode::est_time_s(&out.plan, &at(1000.0)),
        gcode::est_time_s(&out.plan, &at(100_000.0)),
    );
    let st = out.plan.stats();
    let want = 60.0 * st.rapid_length * (1.0 / 1000.0 - 1.0 / 100_000.0);
    assert!((a - b - want).abs() < 1e-6, "{a} {b} {want}");
}

#[test]
fn no_dxf_text_reaches_any_program() {
    // The same square on a layer named "0" and on a layer whose name tries to
    // close a comment and end the program: every post writes the same text.
    let dxf = |layer: &str| {
        let mut s = String::from("0\nSECTION\n2\nENTITIES\n");
        for (a, b) in [
            ((0, 0), (10, 0)),
            ((10, 0), (10, 10)),
            ((10, 10), (0, 10)),
            ((0, 10), (0, 0)),
        ] {
            s += &format!(
                "0\nLINE\n8\n{layer}\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
                a.0, a.1, b.0, b.1
            );
        }
        s + "0\nPOINT\n8\n" + layer + "\n10\n5\n20\n5\n0\nENDSEC\n0\nEOF\n"
    };
    let s = kerf(1.0);
    let plain = kerfcam::run(dxf("0").as_bytes(), &s).unwrap();
    let evil = kerfcam::run(dxf("A)M30($%#;G0 X0").as_bytes(), &s).unwrap();
    for name in gcode::PRESET_NAMES {
        let post = preset(name).unwrap();
        assert_eq!(
            program(&plain, &post, &s),
            program(&evil, &post, &s),
            "{name}"
        );
    }
}
