//! Chaining at scale (issue 17 item 3): N isolated LINE segments thrown on
//! a sheet (no two touching), and N/4 closed squares of four LINEs each,
//! read and chained; prints µs per segment of the contour stage for each
//! N, so a superlinear step shows as a growing figure:
//! `cargo run --release --example chain_scale -- [MAX_N] [--cpu] [--rounds R] [--only isolated|squares]`
//! (default 1,000,000; `--cpu`: the process's CPU time, for a loaded
//! machine; the median of R rounds). A benchmark, not a test: it asserts nothing.
//!
//! Session 12 (2026-11-24 19:17 UTC, load 9 on the 2 cores), isolated
//! segments, CPU µs per segment, main at cfda43a (before) against branch
//! s12-chain (after), 3 alternating pairs, medians (`--rounds 1`: one
//! round a process, 2 pairs, means):
//!
//! | segments  | `--rounds 3` before | after | ratio | `--rounds 1` before | after |
//! |----------:|--------------------:|------:|------:|--------------------:|------:|
//! |    10,000 |                0.80 |  0.80 | 1.00× |                1.22 |  1.00 |
//! |   100,000 |                0.96 |  0.80 | 0.83× |                1.21 |  1.12 |
//! | 1,000,000 |                1.26 |  1.23 | 0.98× |                1.39 |  1.31 |
//!
//! What changed: no `hypot` where an axis settles it (ends more than t
//! apart along an axis do not meet; a line spanning t along an axis is not
//! zero-length), a chain's length summed only once its ends meet (the same
//! additions in the same order), the end grid read from the pieces (no list
//! of ends, no kept buckets, no copy of the bucket starts), the chains
//! split with the larger side left in place, the first chaining's open
//! chains freed before chaining again. Flat from 10k to 100k now; 1M is
//! still 1.5× the 100k figure with three rounds a process, 1.17× with one
//! (as the CLI runs). The gap is fresh pages: at 1M a round takes ~210k
//! page faults (~820 MB first touched: three chainings' 104 MB chain
//! arrays, the 176 MB contour array, the heal's sort buffers), since glibc
//! maps every block over 32 MB afresh and unmaps it on free; at 100k the
//! same blocks are recycled heap from the round before. What is left is
//! memory, not work: fewer or smaller per-chain structs (a `Chain` is
//! 104 B, a `Contour` 176 B plus two small vectors and a layer name).
//!
//! Session 11, measured 2026-11-24 16:14 UTC on the shared 2-core machine (load 6-7),
//! contour stage (`contour::extract`: heal, chain, classify), CPU µs per
//! segment, `--cpu --rounds 3`, main at d40645f (before) and branch
//! s11-chain (after), 3 alternating pairs, medians (10k rounds are 8-16 ms,
//! near the CPU clock's 4 ms tick):
//!
//! | segments  | isolated before | isolated after | ratio | squares before | squares after | ratio |
//! |----------:|----------------:|---------------:|------:|---------------:|--------------:|------:|
//! |    10,000 |            1.59 |           0.80 | 0.50× |           0.40 |        < 0.40 |     - |
//! |   100,000 |            1.68 |           0.92 | 0.55× |           0.32 |          0.19 | 0.59× |
//! | 1,000,000 |            2.46 |           1.28 | 0.52× |           0.51 |          0.30 | 0.59× |
//!
//! What changed: open pieces stored flat and each chain written once
//! (`chain::Pieces`); the second chaining skipped when nothing was healed
//! and no open chain's ends meet (it would give them back unchanged); no
//! `hypot` for ends farther than t along an axis, a chain's length summed
//! only until it passes 2t; the copies found by a radix sort of key hashes
//! instead of a hash map that outgrew the caches; the overlap passes in
//! place, the lines sorted by a radix order of their angle (was a
//! comparison sort through `dyn`).
//!
//! Still not flat from 100k to 1M (1.39×, was 1.46×): what grows is memory,
//! not work. Vectors over glibc's 32 MB mmap threshold are fresh pages on
//! every allocation (kernel page zeroing is ~15 % of the 1M run), and the
//! overlapping-line sort's gather by angle order reads a 40 MB array at
//! random. At 100k both stay in recycled heap and cache.
//!
//! Earlier (2026-11-23, wall clock, load ~2): the end grid's dense cells in
//! drawing order (`chain/grid.rs`) took 1M isolated from 3.94 to 1.75 µs a
//! segment and 100k from 1.65 to 1.28.
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

/// CPU time this process has run (Linux `/proc/self/schedstat`, ns): on
/// a shared machine the wall clock is mostly other processes' turns.
fn cpu_ns() -> u64 {
    std::fs::read_to_string("/proc/self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(0)
}

fn main() {
    // [MAX_N] [--cpu] [--rounds R] [--only isolated|squares]
    let args: Vec<String> = std::env::args().skip(1).collect();
    let flag = |name: &str| args.iter().position(|a| a == name);
    let value = |name: &str| flag(name).and_then(|i| args.get(i + 1));
    let max: usize = args
        .first()
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let cpu = flag("--cpu").is_some();
    let rounds: usize = value("--rounds")
        .and_then(|r| r.parse().ok())
        .unwrap_or(1)
        .max(1);
    let only = value("--only").map(String::as_str);
    let s = kerfcam::Settings::new(1.5, 0.001, 2000.0).expect("settings");
    println!(
        "{:<10} {:>9} {:>9} {:>12} {:>14}",
        "kind",
        "segments",
        "contours",
        if cpu { "chain cpu ms" } else { "chain ms" },
        "µs per segment"
    );
    let mut n = 10_000;
    while n <= max {
        for squares in [false, true] {
            let kind = if squares { "squares" } else { "isolated" };
            if only.is_some_and(|o| o != kind) {
                continue;
            }
            let text = drawing(n, squares);
            let d = kerfcam::dxf::parse(text.as_bytes(), s.read()).expect("parse");
            // The median of the rounds.
            let mut times = Vec::new();
            let mut contours = 0;
            for _ in 0..rounds {
                let (t, c0) = (Instant::now(), cpu_ns());
                let c = kerfcam::contour::extract(&d, s.tolerance(), s.gap());
                times.push(if cpu {
                    (cpu_ns() - c0) as f64 / 1e6
                } else {
                    t.elapsed().as_secs_f64() * 1e3
                });
                contours = c.contours.len();
            }
            times.sort_by(f64::total_cmp);
            let ms = times[times.len() / 2];
            let segs: usize = d.entities.iter().map(|e| e.segments.len()).sum();
            println!(
                "{kind:<10} {segs:>9} {contours:>9} {ms:>12.1} {:>14.2}",
                1e3 * ms / segs.max(1) as f64
            );
        }
        n *= 10;
    }
}
