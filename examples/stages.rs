//! Times each stage on one file: `cargo run --release --example stages -- FILE.dxf`.
use std::time::Instant;
fn main() {
    let path = std::env::args().nth(1).expect("FILE.dxf");
    let bytes = std::fs::read(&path).expect("read");
    let s = kerfcam::Settings::new(1.5, 0.001, 2000.0).expect("settings");
    let t = Instant::now();
    let d = kerfcam::dxf::parse(&bytes, &s.read).expect("parse");
    let t1 = t.elapsed();
    let c = kerfcam::contour::extract(&d, s.tolerance, s.gap);
    let t2 = t.elapsed();
    let k = kerfcam::kerf::offset(&c, s.kerf, s.tolerance);
    let t3 = t.elapsed();
    let p = kerfcam::plan::plan(
        &kerfcam::plan::PlanInput {
            drawing: &d,
            contours: &c,
            kerf: &k,
            tolerance: s.tolerance.mm(),
            kerf_width: s.kerf.width,
        },
        &s.plan,
    );
    let t4 = t.elapsed();
    let g = kerfcam::gcode::emit(&p, &s.gcode);
    let t5 = t.elapsed();
    let segs: usize = d.entities.iter().map(|e| e.segments.len()).sum();
    println!(
        "{} segments, {} contours, {} bytes of G-code; ms: parse {:.1}, contours {:.1}, kerf {:.1}, plan {:.1}, G-code {:.1}",
        segs,
        c.contours.len(),
        g.len(),
        t1.as_secs_f64() * 1e3,
        (t2 - t1).as_secs_f64() * 1e3,
        (t3 - t2).as_secs_f64() * 1e3,
        (t4 - t3).as_secs_f64() * 1e3,
        (t5 - t4).as_secs_f64() * 1e3
    );
}
