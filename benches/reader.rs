//! `cargo bench --bench reader`: the DXF reader alone (bytes to `Drawing`:
//! every entity built, blocks expanded, splines and ellipses fitted), in MB/s
//! of input, on a generated 25 MB nest (made here in memory, never committed)
//! and on every file of `../shared/corpus`. A benchmark, not a test: nothing
//! here asserts a time. Issue 3's targets: ≥ 150 MB/s native, ≥ 60 MB/s in
//! wasm (Node: `node scripts/bench-wasm.mjs --parse-only`).
//!
//! Each input is read `N` times (default 7); the fastest and the median
//! round are printed, with the process's peak resident memory before and
//! after, so "flat memory" is a number too (the reader keeps one entity's
//! pairs at a time; what grows is the input and the `Drawing` itself).
//!
//! Other uses (after `--`):
//!   `FILE.dxf|DIR [N]`           the same figures for one file or a folder (recursively);
//!   `--write-nest OUT.dxf [MB]`  writes the generated nest (for callgrind or perf on a file).
//!
//! Measured 2026-11-22 on the 2-core machine, idle (release profile, opt-level "s"):
//!   generated nest, 25.0 MB, 343,140 entities: 244–261 MB/s (best), 236 MB/s (median);
//!     peak RSS 26 -> 66 MB, the Drawing itself being ~50 MB of it;
//!   corpus, 55 files, 15.8 MB: 198–211 MB/s (DRAAK.dxf, 1,186 splines, is 40 % of the time).
//!   wasm under Node (bench-wasm.mjs --parse-only, best of 3): nest 205–225 MB/s, corpus
//!   151–166 MB/s; the first round, which pays for compiling the wasm, 193–196 and 60–74 MB/s.
//!   Measured with other builds running on the same 2 cores (previous session): nest 118 MB/s.
use std::path::{Path, PathBuf};
use std::time::Instant;

use kerfcam::dxf;

/// The nest of `scripts/bench-wasm.mjs` (same bytes): rows of 200 plates,
/// each four LINEs on layer `parts` and a CIRCLE on layer `holes`, in mm.
fn nest(bytes_wanted: usize) -> Vec<u8> {
    use std::fmt::Write;
    let mut s = String::with_capacity(bytes_wanted + 1024);
    s += "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
    let mut i = 0;
    while s.len() < bytes_wanted {
        let (x, y) = ((i % 200) as f64 * 110.0, (i / 200) as f64 * 70.0);
        for (a, b) in [
            ((0., 0.), (100., 0.)),
            ((100., 0.), (100., 60.)),
            ((100., 60.), (0., 60.)),
            ((0., 60.), (0., 0.)),
        ] {
            let _ = write!(
                s,
                "0\nLINE\n8\nparts\n10\n{:.6}\n20\n{:.6}\n11\n{:.6}\n21\n{:.6}\n",
                x + a.0,
                y + a.1,
                x + b.0,
                y + b.1
            );
        }
        let _ = write!(
            s,
            "0\nCIRCLE\n8\nholes\n10\n{:.6}\n20\n{:.6}\n40\n10.0\n",
            x + 25.0,
            y + 30.0
        );
        i += 1;
    }
    s += "0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

fn dxf_files(p: &Path, out: &mut Vec<PathBuf>) {
    if p.is_dir() {
        let mut entries: Vec<_> = std::fs::read_dir(p)
            .into_iter()
            .flatten()
            .flatten()
            .map(|e| e.path())
            .collect();
        entries.sort();
        for e in entries {
            dxf_files(&e, out);
        }
    } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
        out.push(p.to_path_buf());
    }
}

/// Peak resident memory of this process so far, in MB (Linux; 0 elsewhere).
fn peak_rss_mb() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(0.0, |kb| kb / 1024.0)
}

/// What a `Drawing`'s entities hold in memory (entity records and their
/// segments): the part of the peak that is the reader's output, not its
/// working memory.
fn drawing_bytes(d: &dxf::Drawing) -> usize {
    use std::mem::size_of;
    d.entities.capacity() * size_of::<dxf::Entity>()
        + d.entities
            .iter()
            .map(|e| e.segments.capacity() * size_of::<kerfcam::geom::Segment>())
            .sum::<usize>()
}

/// Reads every input `rounds` times and prints the fastest and median round.
fn measure(name: &str, inputs: &[Vec<u8>], rounds: usize) {
    let opts = dxf::ReadOptions::DEFAULT;
    let mb = inputs.iter().map(Vec::len).sum::<usize>() as f64 / 1e6;
    let rss_before = peak_rss_mb();
    let (mut entities, mut failed, mut held) = (0, 0, 0);
    let mut secs: Vec<f64> = (0..rounds.max(1))
        .map(|_| {
            let t = Instant::now();
            (entities, failed, held) = (0, 0, 0);
            for bytes in inputs {
                match dxf::parse(bytes, &opts) {
                    Ok(d) => {
                        let d = std::hint::black_box(d);
                        entities += d.entities.len();
                        held = held.max(drawing_bytes(&d));
                    }
                    Err(_) => failed += 1,
                }
            }
            t.elapsed().as_secs_f64()
        })
        .collect();
    secs.sort_by(f64::total_cmp);
    let (best, median) = (secs[0], secs[secs.len() / 2]);
    println!(
        "{name}: {} file(s), {mb:.1} MB, {entities} entities, {failed} unreadable; \
         best {:.1} ms = {:.0} MB/s, median {:.1} ms = {:.0} MB/s ({} rounds); \
         peak RSS {rss_before:.0} -> {:.0} MB (largest Drawing: {:.0} MB)",
        inputs.len(),
        best * 1e3,
        mb / best,
        median * 1e3,
        mb / median,
        secs.len(),
        peak_rss_mb(),
        held as f64 / 1e6,
    );
}

fn main() {
    // `cargo bench` passes `--bench` to harness-less benches; it is not ours.
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    if args.first().map(String::as_str) == Some("--write-nest") {
        let out = args.get(1).expect("--write-nest OUT.dxf [MB]");
        let mb: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(25.0);
        std::fs::write(out, nest((mb * 1e6) as usize)).expect("write the nest");
        return;
    }
    let rounds = |i: usize| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(7);
    if let Some(path) = args.first() {
        let mut files = Vec::new();
        dxf_files(Path::new(path), &mut files);
        let inputs: Vec<Vec<u8>> = files
            .iter()
            .map(|f| std::fs::read(f).expect("read"))
            .collect();
        measure(path, &inputs, rounds(1));
        return;
    }
    measure("generated nest", &[nest(25_000_000)], rounds(99));
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    let mut files = Vec::new();
    dxf_files(&corpus, &mut files);
    let inputs: Vec<Vec<u8>> = files
        .iter()
        .map(|f| std::fs::read(f).expect("read"))
        .collect();
    measure("corpus", &inputs, rounds(99));
}
