//! Times what the page's worker does after the pipeline (issue 17 item 4),
//! natively: the report's JSON, the program copied out, the preview of the
//! contours alone and of the whole plan, at the size of the page's canvas.
//!
//! `cargo run --release --example preview_scale -- FILE.dxf [WIDTH HEIGHT [ROUNDS]]`
//! (default 1000 × 700, 3 rounds; the best of the rounds is printed).
//! `PREVIEW_PNG=DIR` saves the two pictures there.
use std::time::Instant;

use kerfcam::plan::CutPlan;
use kerfcam::preview::{self, View};
use kerfcam::report::Report;
use kerfcam::scene::Scene;

fn best<T>(rounds: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut ms = f64::INFINITY;
    let mut out = None;
    for _ in 0..rounds {
        let t = Instant::now();
        let v = f();
        ms = ms.min(t.elapsed().as_secs_f64() * 1e3);
        out = Some(v);
    }
    (ms, out.expect("one round"))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args
        .first()
        .expect("usage: preview_scale FILE.dxf [W H [ROUNDS]]");
    let w: u32 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let h: u32 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(700);
    let rounds: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(3);
    let bytes = std::fs::read(path).expect("read");
    let s = kerfcam::Settings::new(1.5, 0.001, 2000.0).expect("settings");
    let (run_ms, out) = best(1, || kerfcam::run(&bytes, &s).expect("run"));
    println!(
        "{path}: {} contours, pipeline {run_ms:.0} ms",
        out.contours.contours.len()
    );
    let (ms, json) = best(rounds, || Report::new(&out).to_json());
    println!("report json: {ms:.1} ms ({} bytes)", json.len());
    let (ms, _) = best(rounds, || out.gcode.clone().into_bytes());
    println!("program copied: {ms:.1} ms");
    let scene = out.scene();
    let empty = CutPlan::default();
    let drawn = Scene {
        plan: &empty,
        invalid_vertices: &[],
        ..scene
    };
    let (ms, _) = best(rounds, || preview::extent(&scene));
    println!("extent (the page's box): {ms:.1} ms");
    for (name, sc) in [("contours", drawn), ("plan", scene)] {
        let view = View::fit(&preview::extent(&sc), w, h).expect("view");
        let (ms, pixmap) = best(rounds, || preview::render(&sc, &view).expect("render"));
        println!("render {name} {w}x{h}: {ms:.1} ms");
        // PNG writing is in the native build's tiny-skia only.
        #[cfg(not(target_arch = "wasm32"))]
        if let Ok(dir) = std::env::var("PREVIEW_PNG") {
            let file = std::path::Path::new(&dir).join(format!("{name}.png"));
            pixmap.save_png(&file).expect("png");
        }
        #[cfg(target_arch = "wasm32")]
        let _ = pixmap;
    }
}
