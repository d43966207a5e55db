//! Parses files N times (for profiling and MB/s):
//! `cargo run --release --example parse_only -- FILE.dxf|DIR [N]`
//! (a directory is read recursively, every `.dxf` in it), or writes the
//! generated nest of the benchmarks (not committed):
//! `cargo run --release --example parse_only -- --write-nest OUT.dxf 25` (MB).
use std::path::{Path, PathBuf};

/// The same nest as `scripts/bench-wasm.mjs`: plates of four LINEs and a CIRCLE.
fn nest(bytes_wanted: usize) -> Vec<u8> {
    let mut s = String::from(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n",
    );
    let mut i = 0;
    while s.len() < bytes_wanted {
        let (x, y) = ((i % 200) as f64 * 110.0, (i / 200) as f64 * 70.0);
        for (a, b) in [
            ((0., 0.), (100., 0.)),
            ((100., 0.), (100., 60.)),
            ((100., 60.), (0., 60.)),
            ((0., 60.), (0., 0.)),
        ] {
            s += &format!(
                "0\nLINE\n8\nparts\n10\n{:.6}\n20\n{:.6}\n11\n{:.6}\n21\n{:.6}\n",
                x + a.0,
                y + a.1,
                x + b.0,
                y + b.1
            );
        }
        s += &format!(
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
        for e in std::fs::read_dir(p).into_iter().flatten().flatten() {
            dxf_files(&e.path(), out);
        }
    } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
        out.push(p.to_path_buf());
    }
}

fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().expect("FILE.dxf | DIR | --write-nest OUT MB");
    if path == "--write-nest" {
        let out = args.next().expect("OUT.dxf");
        let mb: f64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(25.0);
        std::fs::write(out, nest((mb * 1e6) as usize)).expect("write");
        return;
    }
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(1);
    let mut files = Vec::new();
    dxf_files(Path::new(&path), &mut files);
    let inputs: Vec<Vec<u8>> = files
        .iter()
        .map(|f| std::fs::read(f).expect("read"))
        .collect();
    let total: usize = inputs.iter().map(Vec::len).sum();
    let opts = kerfcam::dxf::ReadOptions::DEFAULT;
    let t = std::time::Instant::now();
    let (mut entities, mut failed) = (0, 0);
    for _ in 0..n {
        for bytes in &inputs {
            match kerfcam::dxf::parse(bytes, &opts) {
                Ok(d) => entities += d.entities.len(),
                Err(_) => failed += 1,
            }
        }
    }
    let s = t.elapsed().as_secs_f64() / n as f64;
    println!(
        "{} files, {:.1} MB, {} entities, {} unreadable, {:.1} ms, {:.0} MB/s",
        inputs.len(),
        total as f64 / 1e6,
        entities / n,
        failed / n,
        s * 1e3,
        total as f64 / 1e6 / s
    );
}
