//! Parse and contour stage only, N times, for `perf record` (issue 17):
//! `cargo run --release --example read_profile -- FILE.dxf [N] [parse]`.
//! A profiling harness, not a test: it prints the sizes and asserts nothing.
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args
        .first()
        .expect("usage: read_profile FILE.dxf [N] [parse]");
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(5);
    let parse_only = args.get(2).map(String::as_str) == Some("parse");
    let s = kerfcam::Settings::new(1.5, 0.001, 2000.0).expect("settings");
    let bytes = std::fs::read(path).expect("read");
    for _ in 0..n {
        let d = kerfcam::dxf::parse(&bytes, s.read()).expect("parse");
        if parse_only {
            println!("{}", d.entities.len());
            continue;
        }
        let c = kerfcam::contour::extract(&d, s.tolerance(), s.gap());
        println!("{} {}", d.entities.len(), c.contours.len());
    }
}
