//! Chaining at scale (issue 17 item 3): N isolated LINE segments thrown on
//! a sheet (no two touching), and N/4 closed squares of four LINEs each,
//! read and chained; prints µs per segment of the contour stage for each
//! N, so a superlinear step shows as a growing figure:
//! `cargo run --release --example chain_scale -- [MAX_N]` (default 1,000,000).
//! A benchmark, not a test: it asserts nothing.
//!
//! Measured 2026-11-23 on the shared 2-core machine (loaded), contour stage
//! (`contour::extract`: heal, chain, classify), µs per segment:
//!
//! | segments  | isolated | in closed squares |
//! |----------:|---------:|------------------:|
//! |    10,000 |     2.75 |              0.81 |
//! |   100,000 |     5.21 |              1.26 |
//! | 1,000,000 |    11.31 |              3.45 |
//!
//! Not linear yet (issue 17 item 3): at 1M isolated segments 49 % of the
//! time is in `chain::chain` itself (perf), its hot spots two loads — a
//! bucket bound of the end grid and a `used` flag — i.e. memory, not work.
use std::fmt::Write as _;
use std::time::Instant;

/// Small deterministic generator (xorshift64).
struct Rng(u64);
impl Rng {
    fn f(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn line(out: &mut String, a: (f64, f64), b: (f64, f64)) {
    let _ = write!(
        out,
        "0\nLINE\n8\n0\n10\n{:.3}\n20\n{:.3}\n11\n{:.3}\n21\n{:.3}\n",
        a.0, a.1, b.0, b.1
    );
}

/// A DXF of `n` segments: isolated ones (`squares` false) on a 10 mm grid
/// with jitter, or closed 4 mm squares of four lines each.
fn drawing(n: usize, squares: bool) -> String {
    let mut rng = Rng(0x2545_F491_4F6C_DD1D ^ n as u64);
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n");
    let cols = (n as f64).sqrt().ceil() as usize;
    let count = if squares { n / 4 } else { n };
    for k in 0..count {
        let (x, y) = (
            10.0 * (k % cols) as f64 + rng.f(),
            10.0 * (k / cols) as f64 + rng.f(),
        );
        if squares {
            let c = [(x, y), (x + 4.0, y), (x + 4.0, y + 4.0), (x, y + 4.0)];
            for i in 0..4 {
                line(&mut s, c[i], c[(i + 1) % 4]);
            }
        } else {
            let a = rng.f() * std::f64::consts::TAU;
            line(&mut s, (x, y), (x + 5.0 * a.cos(), y + 5.0 * a.sin()));
        }
    }
    s.push_str("0\nENDSEC\n0\nEOF\n");
    s
}

fn main() {
    let max: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let s = kerfcam::Settings::new(1.5, 0.001, 2000.0).expect("settings");
    println!(
        "{:<10} {:>9} {:>9} {:>12} {:>14}",
        "kind", "segments", "contours", "chain ms", "µs per segment"
    );
    let mut n = 10_000;
    while n <= max {
        for squares in [false, true] {
            let text = drawing(n, squares);
            let d = kerfcam::dxf::parse(text.as_bytes(), &s.read).expect("parse");
            let t = Instant::now();
            let c = kerfcam::contour::extract(&d, s.tolerance, s.gap);
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let segs: usize = d.entities.iter().map(|e| e.segments.len()).sum();
            println!(
                "{:<10} {:>9} {:>9} {:>12.1} {:>14.2}",
                if squares { "squares" } else { "isolated" },
                segs,
                c.contours.len(),
                ms,
                1e3 * ms / segs.max(1) as f64
            );
        }
        n *= 10;
    }
}
