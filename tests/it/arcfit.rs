//! Programs a router takes (issue 43 §5): arc fitting on a drawing of
//! thousands of tiny lines, and G91 incremental output without drift.

use crate::common;
use common::rs274_errors;
use kerfcam::gcode::{emit_post, preset, JobInfo};
use kerfcam::geom::{dist_to_segment, Point, Segment};
use kerfcam::origin::ProgramOrigin;
use kerfcam::plan::{Cut, CutPlan, PlanOptions, Role};
use kerfcam::process::Passes;
use kerfcam::{Output, Settings};

fn gecko() -> std::path::PathBuf {
    common::shared()
        .join("corpus")
        .join("openbuilds-cam")
        .join("GECKO.dxf")
}

fn settings(tol: f64, fit: bool) -> Settings {
    let s = Settings::new(1.5, tol, 2000.0)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .unwrap();
    let plan = PlanOptions {
        fit_arcs: fit,
        ..s.plan().clone()
    };
    s.with_plan(plan).unwrap()
}

/// The largest distance from points of `path` (ends and 8 steps along
/// each move) to the moves of `to`.
fn farthest(path: &[Segment], to: &[Segment]) -> f64 {
    let mut worst = 0.0_f64;
    for s in path {
        for k in 0..=8 {
            let p = s.point_at(k as f64 / 8.0);
            let d = to
                .iter()
                .map(|t| dist_to_segment(p, t))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d);
        }
    }
    worst
}

fn feed_moves(out: &Output) -> usize {
    out.plan.cuts.iter().map(|c| c.steps.len()).sum()
}

fn motion_blocks(g: &str) -> usize {
    g.lines()
        .filter(|l| {
            let l = l.trim_start();
            ["G1 ", "G2 ", "G3 "].iter().any(|w| l.starts_with(w))
        })
        .count()
}

#[test]
fn a_gecko_of_thousands_of_tiny_lines_is_fitted_within_the_tolerance_and_rs274_reads_it() {
    let path = gecko();
    for tol in [0.001, 0.01, 0.05] {
        let plain = common::run(&path, &settings(tol, false)).unwrap();
        let fitted = common::run(&path, &settings(tol, true)).unwrap();
        let fit = fitted.plan.arc_fit.expect("the plan says it was fitted");
        assert_eq!(fit.lines_before + fit.arcs_before, feed_moves(&plain));
        assert_eq!(fit.lines_after + fit.arcs_after, feed_moves(&fitted));
        assert!(plain.plan.arc_fit.is_none());
        let (before, after) = (motion_blocks(&plain.gcode), motion_blocks(&fitted.gcode));
        eprintln!(
            "GECKO tol {tol}: feed moves {} lines + {} arcs -> {} lines + {} arcs; G1/G2/G3 blocks {before} -> {after}; program lines {} -> {}",
            fit.lines_before,
            fit.arcs_before,
            fit.lines_after,
            fit.arcs_after,
            plain.gcode.lines().count(),
            fitted.gcode.lines().count()
        );
        assert!(after < before, "tol {tol}: {before} -> {after}");
        // The same cuts, each within the tolerance of the unfitted one both
        // ways (sampled: + 1e-9 of rounding).
        assert_eq!(plain.plan.cuts.len(), fitted.plan.cuts.len());
        for (a, b) in plain.plan.cuts.iter().zip(&fitted.plan.cuts) {
            assert_eq!(a.pierce, b.pierce);
            assert_eq!(a.end(), b.end());
            let sa: Vec<Segment> = a.steps.iter().map(|s| s.segment).collect();
            let sb: Vec<Segment> = b.steps.iter().map(|s| s.segment).collect();
            let (d1, d2) = (farthest(&sa, &sb), farthest(&sb, &sa));
            assert!(d1 <= tol + 1e-9 && d2 <= tol + 1e-9, "tol {tol}: {d1} {d2}");
        }
        let errors = rs274_errors(&fitted.gcode, &format!("arcfit_gecko_{tol}"));
        assert!(errors.is_empty(), "tol {tol}: {errors:?}");
    }
    // 0.05 mm must save most of the moves of a traced outline.
    let fitted = common::run(&path, &settings(0.05, true)).unwrap();
    let f = fitted.plan.arc_fit.unwrap();
    assert!(
        (f.lines_after + f.arcs_after) * 2 < f.lines_before + f.arcs_before,
        "{f:?}"
    );
}

/// A cut of `n` lines round the circle of radius `r` about (cx, cy),
/// from angle 0 (10,000 moves of ~0.03 mm: every end off the grid).
fn circle_plan(n: usize, r: f64, cx: f64, cy: f64) -> CutPlan {
    let at = |k: usize| {
        let t = std::f64::consts::TAU * k as f64 / n as f64 + 0.1234;
        Point::new(cx + r * t.cos(), cy + r * t.sin())
    };
    let segs: Vec<Segment> = (0..n).map(|k| Segment::line(at(k), at(k + 1))).collect();
    CutPlan {
        cuts: vec![Cut::loose(at(0), segs, Role::Contour)],
        ..CutPlan::default()
    }
}

/// Each X/Y move's end, in thousandths, read from the program: G90 and
/// G91 followed as they come (both may be in one program), X and Y words
/// on any motion block, comments skipped.
fn ends(g: &str, scale: f64) -> Vec<(i64, i64)> {
    let (mut rel, mut x, mut y) = (false, 0_i64, 0_i64);
    let mut out = Vec::new();
    for l in g.lines() {
        let l = l.split('(').next().unwrap_or("");
        let mut moved = false;
        for w in l.split_whitespace() {
            let (letter, v) = w.split_at(1);
            match (letter, v) {
                ("G", "90") => rel = false,
                ("G", "91") => rel = true,
                ("X" | "Y", _) => {
                    let n = (v.parse::<f64>().unwrap() * scale).round() as i64;
                    let c = if letter == "X" { &mut x } else { &mut y };
                    *c = if rel { *c + n } else { n };
                    moved = true;
                }
                _ => {}
            }
        }
        if moved {
            out.push((x, y));
        }
    }
    out
}

#[test]
fn ten_thousand_g91_moves_on_a_circle_end_where_g90_ends_to_the_last_decimal() {
    let plan = circle_plan(10_000, 50.0, 123.4567, -76.54321);
    let job = JobInfo::from_process(&kerfcam::process::Process::DEFAULT);
    for decimals in [3, 4] {
        let abs = kerfcam::gcode::Post {
            decimals,
            ..preset("linuxcnc").unwrap()
        };
        let inc = kerfcam::gcode::Post {
            incremental: true,
            ..abs.clone()
        };
        let g90 = emit_post(&plan, &abs, &job).unwrap();
        let g91 = emit_post(&plan, &inc, &job).unwrap();
        assert!(g91.contains("G91"), "{}", &g91[..400]);
        let scale = 10f64.powi(decimals as i32);
        let (a, b) = (ends(&g90, scale), ends(&g91, scale));
        assert!(a.len() > 9_990, "{}", a.len());
        // Every end, not only the last: no increment rounded on its own.
        assert_eq!(a, b);
        let errors = rs274_errors(&g91, &format!("g91_circle_{decimals}"));
        assert!(errors.is_empty(), "{errors:?}");
    }
}

#[test]
fn a_router_profile_in_g91_keeps_its_heights_absolute_and_rs274_reads_it() {
    // A 100 x 50 plate with a hole, cut in 3 passes by the router post in G91.
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n");
    for (a, b) in [
        ((0, 0), (100, 0)),
        ((100, 0), (100, 50)),
        ((100, 50), (0, 50)),
        ((0, 50), (0, 0)),
    ] {
        s += &format!(
            "0\nLINE\n8\nCUT\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
            a.0, a.1, b.0, b.1
        );
    }
    s += "0\nCIRCLE\n8\nCUT\n10\n50\n20\n25\n40\n10\n0\nENDSEC\n0\nEOF\n";
    let post = kerfcam::gcode::Post {
        incremental: true,
        ..preset("linuxcnc-router").unwrap()
    };
    let base = Settings::new(6.0, 0.001, 1500.0)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .and_then(|s| {
            s.with_passes(Passes {
                depth: 10.0,
                pass_depth: 4.0,
            })
        })
        .unwrap();
    let g91 = kerfcam::run(s.as_bytes(), &base.clone().with_post(post).unwrap()).unwrap();
    let g90 = kerfcam::run(
        s.as_bytes(),
        &base.with_post(preset("linuxcnc-router").unwrap()).unwrap(),
    )
    .unwrap();
    let g = &g91.gcode;
    // Every Z word is on an absolute block: G90 is in force when it is read.
    let mut rel = false;
    for l in g.lines() {
        if l.contains("G91") && !l.contains("G91.1") {
            rel = true;
        }
        if l.contains("G90") {
            rel = false;
        }
        assert!(!(rel && l.contains('Z')), "a height in G91: {l}\n{g}");
    }
    assert_eq!(ends(g, 1000.0), ends(&g90.gcode, 1000.0));
    let errors = rs274_errors(g, "g91_router_profile");
    assert!(errors.is_empty(), "{errors:?}\n{g}");
}
