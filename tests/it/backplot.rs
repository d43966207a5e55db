//! What is previewed is what is downloaded: every program we emit, re-read by
//! the backplot reader, retraces the plan's geometry to the post's precision
//! (each feed end within a grid step of the plan's path and every plan
//! segment's end reached, arcs with the same centre and direction, every
//! pierce point reached).
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::{fixture, kerf, run};
use kerfcam::gcode::{self, backplot, emit_post, preset, ArcMode, BackplotMove, Units};
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
        for order in Order::ALL {
            let mut s = kerf(k);
            s = s.map_plan(|p| p.order = order).unwrap();
            let out = run(&fixture(file), &s).unwrap();
            let job = s.job();
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

/// Positions visited by a point list (`x;y [L|D]` rows) or knife rows
/// (`z Δx Δy Δθ`, summed from the origin).
fn visited(name: &str, text: &str) -> Vec<Point> {
    let mut at = Point::new(0.0, 0.0);
    let mut out = Vec::new();
    for l in text.lines() {
        let f: Vec<&str> = l.split([' ', ';']).collect();
        match name {
            "point-list" if f.len() >= 2 => {
                at = Point::new(f[0].parse().unwrap(), f[1].parse().unwrap());
                out.push(at);
            }
            "knife-relative" if f.len() == 4 => {
                let d = Point::new(f[1].parse().unwrap(), f[2].parse().unwrap());
                if d != Point::new(0.0, 0.0) {
                    at = at.add(d);
                    out.push(at);
                }
            }
            _ => {}
        }
    }
    out
}

#[test]
fn point_lists_and_knife_rows_retrace_the_plan() {
    for (file, k) in [
        ("seed000-plate-6-holes.dxf", 2.0),
        ("seed002-figure4.dxf", 0.0),
        ("seed003-grid-3x2.dxf", 1.5),
    ] {
        for order in [Order::Contour, Order::Drawing] {
            let mut s = kerf(k);
            s = s.map_plan(|p| p.order = order).unwrap();
            let out = run(&fixture(file), &s).unwrap();
            let job = s.job();
            for name in ["point-list", "knife-relative"] {
                let post = preset(name).unwrap();
                let text = emit_post(&out.plan, &post, &job).unwrap();
                let pts = visited(name, &text);
                let step = 10f64.powi(-(post.decimals as i32));
                // Paper 002's pieces (10 to 20 mm: n = floor(length / 10))
                // lie off the arc by their sagitta; the knife's by the chord.
                let sag = |r: f64| {
                    if post.segment_length > 0.0 {
                        let l = (2.0 * post.segment_length).min(2.0 * r);
                        r - (r * r - l * l / 4.0).max(0.0).sqrt()
                    } else {
                        post.chord
                    }
                };
                let chords: Vec<Segment> =
                    pts.windows(2).map(|w| Segment::line(w[0], w[1])).collect();
                let segs: Vec<Segment> = out
                    .plan
                    .cuts
                    .iter()
                    .flat_map(|c| c.steps.iter().map(|s| s.segment))
                    .collect();
                for p in &pts {
                    let on_path = segs.iter().any(|s| dist_to_segment(*p, s) <= 1.5 * step)
                        || out
                            .plan
                            .cuts
                            .iter()
                            .any(|c| c.pierce.dist(*p) <= 1.5 * step);
                    assert!(on_path, "{file} {name}: {p:?} off the plan");
                }
                for s in &segs {
                    let tol = 1.5 * step + s.arc_center().map_or(0.0, |(_, r)| sag(r));
                    assert!(
                        chords.iter().any(|c| dist_to_segment(s.b, c) <= tol),
                        "{file} {name} {}: {:?} never reached",
                        order.name(),
                        s.b
                    );
                }
            }
        }
    }
}
