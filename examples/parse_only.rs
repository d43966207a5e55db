//! Parses one file N times (for profiling): `cargo run --release --example parse_only -- FILE.dxf 5`.
fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().expect("FILE.dxf");
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(1);
    let bytes = std::fs::read(&path).expect("read");
    let opts = kerfcam::dxf::ReadOptions::DEFAULT;
    let t = std::time::Instant::now();
    let mut segs = 0;
    for _ in 0..n {
        let d = kerfcam::dxf::parse(&bytes, &opts).expect("parse");
        segs += d.entities.len();
    }
    let s = t.elapsed().as_secs_f64() / n as f64;
    println!(
        "{} entities, {:.1} ms, {:.0} MB/s",
        segs / n,
        s * 1e3,
        bytes.len() as f64 / 1e6 / s
    );
}
