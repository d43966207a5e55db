//! `cargo bench --bench pipeline`: time of each stage over the corpus and a
//! generated nest, printed as totals, MB/s and per-stage shares. A benchmark,
//! not a test: nothing here asserts a time.

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
    let Ok(d) = dxf::parse(bytes, &settings.read) else {
        return;
    };
    t.parse += s.elapsed();
    let s = Instant::now();
    let c = contour::extract(&d, settings.tolerance, settings.gap);
    t.chain += s.elapsed();
    let s = Instant::now();
    let k = kerf::offset(&c, settings.kerf, settings.tolerance);
    t.offset += s.elapsed();
    let s = Instant::now();
    let p = plan::plan(
        &plan::PlanInput {
            drawing: &d,
            contours: &c,
            kerf: &k,
            tolerance: settings.tolerance.mm(),
            kerf_width: settings.kerf.width,
        },
        &settings.plan,
    );
    t.plan += s.elapsed();
    let s = Instant::now();
    let g = gcode::emit(&p, &settings.gcode);
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
    let settings = Settings::new(1.5, 0.001, 2000.0).expect("settings");
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
}
