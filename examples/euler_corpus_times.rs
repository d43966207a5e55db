//! Times the Eulerian order on every corpus file (both modes), to find slow ones.
use kerfcam::plan::{EulerMode, Order};
use std::time::Instant;

fn main() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    let mut files = vec![];
    fn walk(d: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out)
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
                out.push(p)
            }
        }
    }
    walk(&dir, &mut files);
    files.sort();
    for f in files {
        let bytes = std::fs::read(&f).unwrap();
        for mode in [EulerMode::Repeat, EulerMode::Rapid] {
            let mut s = kerfcam::Settings::new(1.5, 0.001, 2000.0).unwrap();
            s = s.map_plan(|p| p.order = Order::Eulerian).unwrap();
            s = s.map_plan(|p| p.euler_mode = mode).unwrap();
            s = s.map_plan(|p| p.cut_open = true).unwrap();
            let t = Instant::now();
            let r = kerfcam::run(&bytes, &s);
            let el = t.elapsed().as_secs_f64();
            let info = r
                .map(|o| {
                    format!(
                        "{} contours, {} cuts",
                        o.contours.contours.len(),
                        o.plan.cuts.len()
                    )
                })
                .unwrap_or_else(|e| format!("{e}"));
            println!("{el:8.3}s {} {} {info}", mode.name(), f.display());
        }
    }
}
