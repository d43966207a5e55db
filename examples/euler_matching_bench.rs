//! Time of the Eulerian order's odd-vertex pairing (paper 003): `n` odd
//! vertices made by n/2 separate short open lines, planned in mode "rapid"
//! (straight distances), so the matching is most of the work. Exact blossom
//! matching up to 500 odd vertices, greedy above. Prints figures and ratios.
//!
//! cargo run --release --example euler_matching_bench
use std::time::Instant;

use kerfcam::plan::{EulerMode, Order};

fn lines_dxf(pairs: usize, seed: &mut u64) -> Vec<u8> {
    let mut r = || {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut d = String::from("0\nSECTION\n2\nENTITIES\n");
    for _ in 0..pairs {
        let (x, y, a) = (2000.0 * r(), 2000.0 * r(), 6.3 * r());
        let (x1, y1) = (x + 5.0 * a.cos(), y + 5.0 * a.sin());
        d += &format!("0\nLINE\n8\n0\n10\n{x:.4}\n20\n{y:.4}\n11\n{x1:.4}\n21\n{y1:.4}\n");
    }
    d += "0\nENDSEC\n0\nEOF\n";
    d.into_bytes()
}

fn main() {
    let mut seed = 0x2545_f491_4f6c_dd1d;
    let mut last: Option<(usize, f64)> = None;
    for n in [100, 250, 500, 1000, 2000, 5000] {
        let dxf = lines_dxf(n / 2, &mut seed);
        let mut s = kerfcam::Settings::new(0.0, 0.001, 2000.0).unwrap();
        s = s.map_plan(|p| p.order = Order::Eulerian).unwrap();
        s = s.map_plan(|p| p.euler_mode = EulerMode::Rapid).unwrap();
        s = s.map_plan(|p| p.cut_open = true).unwrap();
        let t = Instant::now();
        let out = kerfcam::run(&dxf, &s).unwrap();
        let el = t.elapsed().as_secs_f64();
        let greedy = out
            .plan
            .warnings
            .iter()
            .any(|w| w.code == "odd-vertices-greedy");
        let st = out.plan.stats();
        let ratio = last.map_or(String::new(), |(m, t0)| {
            format!(
                "  ×{:.1} time for ×{:.1} vertices",
                el / t0,
                n as f64 / m as f64
            )
        });
        println!(
            "{n:5} odd vertices: {:8.3} s ({}), rapid {:.0} mm, {} pierces{ratio}",
            el,
            if greedy { "greedy" } else { "exact" },
            st.rapid_length,
            st.pierces
        );
        last = Some((n, el));
    }
}
