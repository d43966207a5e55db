//! Kerf and G-code stages alone, many rounds in one process (a developer's
//! loop: the pipeline's first stages and the plan run once).
//! `cargo run --release --example kerf_gcode_loop -- ROUNDS FILE.dxf`:
//! prints the median and the best CPU ms of each (warm: the second round on
//! reuses pages the first freed).
use std::time::Duration;

fn cpu_time() -> Duration {
    let ns = std::fs::read_to_string("/proc/self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .unwrap_or(0);
    Duration::from_nanos(ns)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rounds: usize = args[0].parse().expect("rounds");
    let s = kerfcam::Settings::new(1.5, 0.001, 2000.0).expect("settings");
    let bytes = std::fs::read(&args[1]).expect("read");
    let d = kerfcam::dxf::parse(&bytes, s.read()).expect("parse");
    let c = kerfcam::contour::extract(&d, s.tolerance(), s.gap());
    let k = kerfcam::kerf::offset(&c, s.kerf(), s.tolerance());
    let p = kerfcam::plan::plan(
        &kerfcam::plan::PlanInput {
            file: kerfcam::plan::FileOrder::of(&d),
            contours: &c,
            kerf: &k,
            tolerance: s.tolerance().mm(),
            kerf_width: s.kerf().width,
        },
        s.plan(),
    );
    let (mut kt, mut gt) = (Vec::new(), Vec::new());
    for _ in 0..rounds {
        let t = cpu_time();
        let k2 = kerfcam::kerf::offset(&c, s.kerf(), s.tolerance());
        let t1 = cpu_time();
        drop(k2);
        let t2 = cpu_time();
        let g = kerfcam::gcode::emit(&p, s.gcode());
        let t3 = cpu_time();
        drop(g);
        kt.push((t1 - t).as_secs_f64() * 1e3);
        gt.push((t3 - t2).as_secs_f64() * 1e3);
    }
    for v in [&mut kt, &mut gt] {
        v.sort_by(f64::total_cmp);
    }
    println!(
        "kerf median {:.1} best {:.1}\tgcode median {:.1} best {:.1}",
        kt[kt.len() / 2],
        kt[0],
        gt[gt.len() / 2],
        gt[0]
    );
}
