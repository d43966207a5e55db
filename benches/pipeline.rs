//! `cargo bench --bench pipeline`: time of each stage over the corpus and a
//! generated nest, printed as totals, MB/s and per-stage shares. A benchmark,
//! not a test: nothing here asserts a time. `-- --write-nest OUT.dxf PARTS`
//! writes the nest (scripts/bench-sheet.sh times 20,000 parts beside
//! ezdxf: 2 threads 202 ms, 32.4x its read on 2026-11-28).
//!
//! ## Issue 45 §1: the loss warnings on every run (2026-11-29)
//!
//! `cargo bench --profile ci --bench pipeline -- --warnings` (medians of 7,
//! 2 threads, load 5-6): the 20,000-part nest's pipeline 896-1107 ms, of
//! which parts-closer-than-kerf 41-44 ms and features-narrower-than-kerf
//! 24 ms: +6.6 to +7.8 % over the pipeline without them (the issue's
//! budget 10 %). First cut: 282 + 65 ms, +15 % (the segment index built and
//! asked by every move; every contour's segment pairs boxed); now a cut
//! near no other part's box skips its moves and the index is never built,
//! and round holes are not paired.
//!
//! ## Issue 17, sheet scale: before and after (2026-11-24)
//!
//! The generated nests of `scripts/bench-sheet.sh` (plates 100 × 60 with a
//! round hole, `benches/reader.rs --write-nest`), each stage timed by
//! `cargo run --release --example stages -- --cpu --rounds 3`: CPU time
//! of the process (`/proc/self/schedstat`), best of 3, because the shared
//! 2-core machine ran at load 7 (wall time was 2–3 × CPU time). Before =
//! f05f4a6 (main after the first speed branch), after = branch s7-speed,
//! the two binaries one after the other per file in the same minute.
//! Stages under ~1 ms read 0 at this clock's resolution (the 0.2 MB nest).
//!
//! | nest  | contours | plan ms before → after | G-code ms before → after | total ms before → after |
//! |-------|---------:|-----------------------:|-------------------------:|------------------------:|
//! | 0.2 MB|    1,162 |        55.6 →   56.6   |           3.2 →  (<1)    |          58.7 →   56.6  |
//! | 1 MB  |    5,728 |       123.9 →  112.0   |          12.0 →    8.8   |         152.0 →  135.4  |
//! | 4 MB  |   22,420 |       305.9 →   90.1   |          52.1 →   35.6   |         437.7 →  195.5  |
//! | 11 MB |   61,264 |       782.0 →  286.1   |         154.0 →  104.2   |       1,163.3 →  609.8  |
//! | 25 MB |  137,256 |     1,555.6 →  647.1   |         336.5 →  230.7   |       2,419.7 → 1404.6  |
//!
//! µs per contour, after (before in brackets): flat from 22k to 137k.
//!
//! | nest  | parse | contours | kerf | plan         | G-code     | total        |
//! |-------|------:|---------:|-----:|-------------:|-----------:|-------------:|
//! | 1 MB  |  0.23 |     1.40 | 0.93 | 19.55 (21.6) | 1.54 (2.09)| 23.6 (26.5)  |
//! | 4 MB  |  0.36 |     1.60 | 1.16 |  4.02 (13.6) | 1.59 (2.32)|  8.7 (19.5)  |
//! | 11 MB |  0.45 |     1.89 | 1.24 |  4.67 (12.8) | 1.70 (2.51)| 10.0 (19.0)  |
//! | 25 MB |  0.45 |     2.13 | 1.26 |  4.71 (11.3) | 1.68 (2.45)| 10.2 (17.6)  |
//!
//! (Below 20k contours the plan per contour is higher: the full search's
//! at least 10,000 kicks are a fixed cost, which is what keeps those tours
//! within 2 % of LKH-3.) Whole process on the 25 MB nest, side by side
//! (3 pairs, CPU): after/before 0.60. The 25 MB nest's G-code is 29.3 MB
//! in 231 ms CPU: ~127 MB/s (was 87).
//!
//! What changed: the contour order's short schedule above 20k sites and
//! its allocation-free grids and entry re-choice (src/plan/tsp, table of
//! tour length against time in benches/tsp.rs); the lead/clearance index
//! as one flat array with allocation-free queries (src/plan/clearance.rs);
//! the G-code writer's numbers, comments, templates and arc centres
//! (src/gcode/number.rs, src/gcode/mod.rs; programs byte-identical).
//! Against the budgets for the 25 MB nest (parse 100, contours 80,
//! kerf 50, plan 150, G-code 70 ms) plan and G-code remain over: the plan
//! is now ~60 % tour (two nearest-neighbour constructions, the free local
//! search, the polish) and ~25 % lead-ins (one clearance query and one
//! crossing test a contour, and a Vec of steps per cut); the G-code writer
//! spends most of its time on arcs (each split, its centre searched on the
//! grid, its sweep's atan/tan), not on text.

use std::path::Path;
use std::time::{Duration, Instant};

use kerfcam::{contour, dxf, gcode, kerf, plan, Settings};

#[derive(Default)]
struct Times {
    bytes: usize,
    parse: Duration,
    chain: Duration,
    offset: Duration,
    plan: Duration,
    emit: Duration,
}

fn time_one(bytes: &[u8], settings: &Settings, t: &mut Times) {
    t.bytes += bytes.len();
    let s = Instant::now();
    let Ok(d) = dxf::parse(bytes, settings.read()) else {
        return;
    };
    t.parse += s.elapsed();
    let s = Instant::now();
    let c = contour::extract(&d, settings.tolerance(), settings.gap());
    t.chain += s.elapsed();
    let s = Instant::now();
    let k = kerf::offset(&c, settings.kerf(), settings.tolerance());
    t.offset += s.elapsed();
    let s = Instant::now();
    let p = plan::plan(
        &plan::PlanInput {
            file: kerfcam::plan::FileOrder::of(&d),
            contours: &c,
            kerf: &k,
            tolerance: settings.tolerance().mm(),
            process: settings.process(),
        },
        settings.plan(),
    );
    t.plan += s.elapsed();
    let s = Instant::now();
    let g = gcode::emit(&p, settings.decimals(), &settings.job());
    t.emit += s.elapsed();
    std::hint::black_box(g);
}

fn print(name: &str, t: &Times) {
    let total = t.parse + t.chain + t.offset + t.plan + t.emit;
    let mb = t.bytes as f64 / 1e6;
    println!(
        "{name}: {mb:.1} MB in {:.1} ms = {:.0} MB/s end to end; parse {:.0} MB/s; stages ms: parse {:.1}, chain {:.1}, offset {:.1}, plan {:.1}, G-code {:.1}",
        total.as_secs_f64() * 1e3,
        mb / total.as_secs_f64(),
        mb / t.parse.as_secs_f64(),
        t.parse.as_secs_f64() * 1e3,
        t.chain.as_secs_f64() * 1e3,
        t.offset.as_secs_f64() * 1e3,
        t.plan.as_secs_f64() * 1e3,
        t.emit.as_secs_f64() * 1e3,
    );
}

/// A sheet of `n` plates 100 × 60 with a round hole and a rectangular hole each, as LINE/CIRCLE entities.
fn nest(n: usize) -> Vec<u8> {
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n");
    let cols = (n as f64).sqrt().ceil() as usize;
    for i in 0..n {
        let (x, y) = ((i % cols) as f64 * 110.0, (i / cols) as f64 * 70.0);
        let line = |s: &mut String, a: (f64, f64), b: (f64, f64)| {
            *s += &format!(
                "0\nLINE\n8\nparts\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
                a.0, a.1, b.0, b.1
            );
        };
        for (a, b) in [
            ((0., 0.), (100., 0.)),
            ((100., 60.), (100., 0.)),
            ((100., 60.), (0., 60.)),
            ((0., 0.), (0., 60.)),
        ] {
            line(&mut s, (x + a.0, y + a.1), (x + b.0, y + b.1));
        }
        for (a, b) in [
            ((60., 20.), (80., 20.)),
            ((80., 20.), (80., 40.)),
            ((80., 40.), (60., 40.)),
            ((60., 40.), (60., 20.)),
        ] {
            line(&mut s, (x + a.0, y + a.1), (x + b.0, y + b.1));
        }
        s += &format!(
            "0\nCIRCLE\n8\nparts\n10\n{}\n20\n{}\n40\n10\n",
            x + 25.0,
            y + 30.0
        );
    }
    s += "0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

fn main() {
    // `--write-nest OUT.dxf PARTS`: the nest of PARTS plates, for
    // scripts/bench-sheet.sh (issue 17 was measured on 20,000 of them).
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--write-nest") {
        let out = args.get(1).expect("--write-nest OUT.dxf PARTS");
        let parts = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(20_000);
        std::fs::write(out, nest(parts)).expect("write the nest");
        return;
    }
    let settings = Settings::new(1.5, 0.001, 2000.0).expect("settings");
    if args.first().map(String::as_str) == Some("--warnings") {
        warnings_share(&settings);
        return;
    }
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    let mut files = Vec::new();
    let mut stack = vec![corpus];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
                files.push(std::fs::read(&p).unwrap_or_default());
            }
        }
    }
    let rounds = 5;
    let mut t = Times::default();
    for _ in 0..rounds {
        for f in &files {
            time_one(f, &settings, &mut t);
        }
    }
    print(&format!("corpus ({} files) x{rounds}", files.len()), &t);
    for n in [1000, 5000] {
        let bytes = nest(n);
        let mut t = Times::default();
        time_one(&bytes, &settings, &mut t);
        print(&format!("nest of {n} parts ({} contours)", 3 * n), &t);
    }
    warnings_share(&settings);
}

/// Issue 45 §1: what the two loss warnings that run on every pipeline
/// (parts closer than the kerf, features narrower than it) add to it on
/// the 20,000-part nest: the whole pipeline (which runs them) and the two
/// checks alone on the same plan, in turns, medians of 7.
fn warnings_share(settings: &Settings) {
    let bytes = nest(20_000);
    let d = dxf::parse(&bytes, settings.read()).expect("the nest reads");
    let c = contour::extract(&d, settings.tolerance(), settings.gap());
    let k = kerf::offset(&c, settings.kerf(), settings.tolerance());
    let input = plan::PlanInput {
        file: kerfcam::plan::FileOrder::of(&d),
        contours: &c,
        kerf: &k,
        tolerance: settings.tolerance().mm(),
        process: settings.process(),
    };
    let p = plan::plan(&input, settings.plan());
    let (mut whole, mut close, mut narrow) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..7 {
        let s = Instant::now();
        std::hint::black_box(kerfcam::run(&bytes, settings).expect("the nest runs"));
        whole.push(s.elapsed().as_secs_f64() * 1e3);
        let s = Instant::now();
        std::hint::black_box(plan::closeness::closeness(&input, &p, settings.threads()));
        close.push(s.elapsed().as_secs_f64() * 1e3);
        let s = Instant::now();
        std::hint::black_box(plan::narrow::narrow(&input, settings.threads()));
        narrow.push(s.elapsed().as_secs_f64() * 1e3);
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (w, c, n) = (median(&mut whole), median(&mut close), median(&mut narrow));
    println!(
        "nest of 20000 parts: pipeline {w:.1} ms with the loss warnings, of which parts closer than the kerf {c:.1} ms and features narrower than it {n:.1} ms: +{:.1} % over the pipeline without them",
        100.0 * (c + n) / (w - c - n)
    );
}
