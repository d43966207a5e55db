//! Times each stage on files: `cargo run --release --example stages -- [--cpu] [--rounds N] [--threads N] FILE.dxf...`.
//!
//! One tab-separated row per file, the best of N rounds per stage (the
//! machines are shared and noisy; the best is the least disturbed):
//! `file, bytes, segments, contours, parse_ms, contours_ms, kerf_ms, plan_ms,
//! gcode_ms, total_ms, gcode_bytes`. `scripts/bench-sheet.sh` reads it.
//! `STAGES_GCODE=FILE` writes the (last) program there; `STAGES_TOUR=1`
//! prints the tour's lengths (nearest neighbour, improved) to stderr.
//! `--threads N`: the stages' threads (default: the machine's cores; the
//! program is the same with any).
//! `--cpu`: the calling thread's CPU time (Linux `/proc/self/schedstat`,
//! ns) instead of the wall clock — the workers' is not in it, so use it
//! with `--threads 1` (the process's total is `/usr/bin/time`'s user +
//! sys), for a machine so loaded that wall time is
//! mostly waiting (load 7 on 2 cores while the figures of issue 17 were
//! taken).
use std::time::{Duration, Instant};

/// CPU time the calling thread has run, from the scheduler's own account.
fn cpu_time() -> Duration {
    let ns = std::fs::read_to_string("/proc/self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .unwrap_or(0);
    Duration::from_nanos(ns)
}

/// A clock: the wall clock, or CPU time.
struct Clock(Option<Instant>, Duration);
impl Clock {
    fn start(cpu: bool) -> Clock {
        if cpu {
            Clock(None, cpu_time())
        } else {
            Clock(Some(Instant::now()), Duration::ZERO)
        }
    }
    fn elapsed(&self) -> Duration {
        match self.0 {
            Some(t) => t.elapsed(),
            None => cpu_time().saturating_sub(self.1),
        }
    }
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let cpu = args.first().map(String::as_str) == Some("--cpu");
    if cpu {
        args.remove(0);
    }
    let mut rounds = 1usize;
    if args.first().map(String::as_str) == Some("--rounds") {
        rounds = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1).max(1);
        args.drain(..2.min(args.len()));
    }
    let mut threads = kerfcam::par::Threads::available();
    if args.first().map(String::as_str) == Some("--threads") {
        let n = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1);
        threads = kerfcam::par::Threads::new(n);
        args.drain(..2.min(args.len()));
    }
    assert!(
        !args.is_empty(),
        "usage: stages [--cpu] [--rounds N] [--threads N] FILE.dxf..."
    );
    let s = kerfcam::Settings::new(1.5, 0.001, 2000.0)
        .expect("settings")
        .with_threads(threads);
    for path in &args {
        let bytes = std::fs::read(path).expect("read");
        let mut best = [f64::INFINITY; 5];
        let mut sizes = (0, 0, 0);
        for _ in 0..rounds {
            let t = Clock::start(cpu);
            let d = kerfcam::dxf::parse(&bytes, s.read()).expect("parse");
            let t1 = t.elapsed();
            let c = kerfcam::contour::extract_with(&d, s.tolerance(), s.gap(), s.threads());
            let t2 = t.elapsed();
            let k = kerfcam::kerf::offset(&c, s.kerf(), s.tolerance());
            let t3 = t.elapsed();
            let p = kerfcam::plan::plan(
                &kerfcam::plan::PlanInput {
                    file: kerfcam::plan::FileOrder::of(&d),
                    contours: &c,
                    kerf: &k,
                    tolerance: s.tolerance().mm(),
                    process: s.process(),
                },
                s.plan(),
            );
            let t4 = t.elapsed();
            let g = kerfcam::gcode::emit(&p, s.decimals(), &s.job());
            let t5 = t.elapsed();
            if let (Some(t), Some(_)) = (p.tour, std::env::var_os("STAGES_TOUR")) {
                // The tour's lengths, to compare two builds' tours.
                eprintln!(
                    "{path}\ttour nn {:.3}\timproved {:.3}",
                    t.nearest_neighbour, t.improved
                );
            }
            if let Some(out) = std::env::var_os("STAGES_GCODE") {
                // The program itself, to compare two builds byte for byte.
                std::fs::write(out, &g).expect("write the program");
            }
            let ms = |a: Duration, b: Duration| b.saturating_sub(a).as_secs_f64() * 1e3;
            let zero = Duration::ZERO;
            let now = [ms(zero, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t4, t5)];
            for (b, n) in best.iter_mut().zip(now) {
                *b = b.min(n);
            }
            let segs: usize = d.entities.iter().map(|e| e.segments.len()).sum();
            sizes = (segs, c.contours.len(), g.len());
        }
        let total: f64 = best.iter().sum();
        println!(
            "{path}\t{}\t{}\t{}\t{:.1}\t{:.1}\t{:.1}\t{:.1}\t{:.1}\t{total:.1}\t{}",
            bytes.len(),
            sizes.0,
            sizes.1,
            best[0],
            best[1],
            best[2],
            best[3],
            best[4],
            sizes.2
        );
    }
}
