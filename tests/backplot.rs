//! What is previewed is what is downloaded: every program we emit, re-read by
//! the backplot reader, retraces the plan's geometry to the post's precision
//! (each feed end within a grid step of the plan's path and every plan
//! segment's end reached, arcs with the same centre and direction, every
//! pierce point reached).
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::{fixture, kerf, run};
use kerfcam::gcode::{self, backplot, emit_post, preset, ArcMode, BackplotMove, JobInfo, Units};
use kerfcam::geom::{dist_to_segment, Point, Segment};
use kerfcam::plan::{CutPlan, Order};

/// RS274-like presets the reader understands (the point list and knife rows
/// are not G-code).
const GCODE: [&str; 8] = [
    "linuxcnc-plasma",
    "linuxcnc",
    "grbl-laser",
    "grbl-plasma",
    "mach3-plasma",
    "iso6983",
    "annex-h",
    "knife-gcode",
];

fn retrace(plan: &CutPlan, post: &gcode::Post, text: &str) -> Result<(), String> {
    let bp = backplot(text);
    let inch = if post.units == Units::Inch { 25.4 } else { 1.0 };
    let step = 10f64.powi(-(post.decimals as i32)) * inch;
    let linear = post.arcs == ArcMode::Lines || post.knife.is_some();
    let tol = 1.5 * step + if linear { post.chord } else { 0.0 };
    let steps: Vec<Segment> = plan
        .cuts
        .iter()
        .flat_map(|c| c.steps.iter().map(|s| s.segment))
        .collect();
    let feeds: Vec<BackplotMove> = bp
        .moves
        .iter()
        .copied()
        .filter(|m| match m {
            BackplotMove::Rapid { .. } => false,
            BackplotMove::Line { torch, .. } | BackplotMove::Arc { torch, .. } => {
                *torch || post.knife.is_some()
            }
        })
        .collect();
    let mut k = 0usize;
    let mut ends: Vec<Point> = Vec::new();
    for m in &feeds {
        let (to, arc) = match *m {
            BackplotMove::Line { to, .. } => (to, None),
            BackplotMove::Arc {
                to, center, ccw, ..
            } => (to, Some((center, ccw))),
            BackplotMove::Rapid { .. } => continue,
        };
        while k < steps.len() && dist_to_segment(to, &steps[k]) > tol {
            k += 1;
        }
        let Some(s) = steps.get(k) else {
            return Err(format!("feed to {to:?} is off the plan's path"));
        };
        if let Some((c, ccw)) = arc {
            let (pc, _) = s
                .arc_center()
                .ok_or_else(|| format!("arc to {to:?} where the plan has a line"))?;
            if pc.dist(c) > 2.0 * tol.max(step * 3.0) || ccw != s.is_ccw() {
                return Err(format!("arc to {to:?}: centre {c:?} vs {pc:?}, ccw {ccw}"));
            }
        }
        ends.push(to);
    }
    for s in &steps {
        if s.length() > 2.0 * step && !ends.iter().any(|e| e.dist(s.b) <= tol) {
            return Err(format!("plan segment end {:?} never reached", s.b));
        }
    }
    let stops: Vec<Point> = bp
        .moves
        .iter()
        .map(|m| match *m {
            BackplotMove::Rapid { to, .. }
            | BackplotMove::Line { to, .. }
            | BackplotMove::Arc { to, .. } => to,
        })
        .collect();
    for c in &plan.cuts {
        if !stops.iter().any(|p| p.dist(c.pierce) <= tol) {
            return Err(format!("pierce {:?} never reached", c.pierce));
        }
    }
    Ok(())
}

#[test]
fn every_gcode_preset_retraces_the_plan_on_every_fixture_and_order() {
    let files = [
        ("seed000-plate-6-holes.dxf", 2.0),
        ("seed000-figure1.dxf", 0.0),
        ("seed001-P51703.dxf", 3.0),
        ("seed002-figure4.dxf", 0.0),
        ("seed003-grid-3x2.dxf", 1.5),
    ];
    let mut failures = Vec::new();
    for (file, k) in files {
        for order in [Order::Contour, Order::Drawing] {
            let mut s = kerf(k);
            s.plan.order = order;
            let out = run(&fixture(file), &s).unwrap();
            let job = JobInfo::from_options(&s.gcode);
            for name in GCODE {
                let post = preset(name).unwrap();
                let text = emit_post(&out.plan, &post, &job).unwrap();
                if let Err(e) = retrace(&out.plan, &post, &text) {
                    failures.push(format!("{file} {} {name}: {e}", order.name()));
                }
                let bp = backplot(&text);
                // Annex H's cycle lines are the only words it does not know.
                let unknown: Vec<_> = bp
                    .warnings
                    .iter()
                    .filter(|w| !w.message.contains("CYC10"))
                    .collect();
                if !unknown.is_empty() {
                    failures.push(format!("{file} {name}: {unknown:?}"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
