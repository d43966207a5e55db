//! Issue 43's benchmarks for its closing note, measured side by side in
//! one run: `cargo run --profile ci --example milling_bench [CORPUS_DIR]`
//! (CORPUS_DIR defaults to ../shared/corpus).
//!
//! 1. Zig-zag vs contour-parallel on the test pockets (6 mm tool, 6 mm deep
//!    in 2 mm passes, plunge entry, grbl-router): the toolpath's length in
//!    material (cuts + plunges), rapids, the program's estimated time and
//!    its lines — arc fitting off and on.
//! 2. Lines saved by arc fitting on the corpus: every DXF under CORPUS_DIR,
//!    kerf 1.5, tolerance 0.01 mm, feed moves before and after
//!    (`--fit-arcs`); and the milling's on the test pockets.
//!
//! Figures (2026-11-29, branch mill2, `--profile ci`; lengths and times
//! are the plan's, so a loaded machine changes none of them):
//!
//! ```text
//! 1. pockets, 6 mm tool, 6 mm deep in 3 passes, plunge (length in material = cuts + plunges)
//! pocket | strategy | in material mm | rapids mm | time s | lines | lines fitted | mill moves before -> after fitting
//! sign plate | zigzag | 39639.9 | 2499.5 | 1233.3 | 1338 | 1338 | 1222 -> 1222
//! sign plate | offset | 38085.5 | 3305.4 | 1202.7 | 1188 | 1131 | 1012 -> 955
//! sign plate | offset/zigzag | 0.961 |  | 0.975
//! 60x40 + island | zigzag | 2946.0 | 210.4 | 96.5 | 226 | 226 | 186 -> 186
//! 60x40 + island | offset | 2492.7 | 157.4 | 82.1 | 150 | 140 | 116 -> 106
//! 60x40 + island | offset/zigzag | 0.846 |  | 0.851
//! R20 circle | zigzag | 1725.3 | 26.9 | 56.2 | 120 | 120 | 98 -> 98
//! R20 circle | offset | 1387.3 | 37.6 | 46.2 | 93 | 93 | 71 -> 71
//! R20 circle | offset/zigzag | 0.804 |  | 0.822
//! 50x30 + hole | zigzag | 1945.3 | 173.3 | 66.0 | 184 | 178 | 144 -> 138
//! 50x30 + hole | offset | 1494.7 | 395.0 | 57.7 | 196 | 187 | 132 -> 123
//! 50x30 + hole | offset/zigzag | 0.768 |  | 0.874
//! milling moves on the test pockets, both strategies: 2981 -> 2899
//! (drawn as lines, circles and arcs: little to fit; a pocket drawn
//! as a 144-gon fits 1140 -> 186, tests/it/milling_play.rs)
//!
//! 2. arc fitting on the 55 corpus DXFs, kerf 1.5, tolerance 0.01 mm;
//! largest files: file | feed moves before | after | ratio
//! dxf2gcode-plasma/2-test-layers-nested.dxf | 24404 | 223 | 0.009
//! dxf2gcode-plasma/DRAAK.dxf | 22492 | 6319 | 0.281
//! astm-parser/GMH2446F17_INCLALLOWANCE_ASTM.DXF | 20390 | 15370 | 0.754
//! dxf2gcode-plasma/Część1.DXF | 12068 | 240 | 0.020
//! astm-parser/mirrored.DXF | 8784 | 6800 | 0.774
//! astm-parser/GMH2446F17_INCLALLOWANCE_AAMA.DXF | 8357 | 6737 | 0.806
//! visicut/draft1.dxf | 7701 | 7163 | 0.930
//! sofle/SofleKeyboard-drl_map.dxf | 4955 | 3664 | 0.739
//! corpus total: 131631 -> 57520 feed moves (56.3 % saved), 0 file(s) not planned
//! ```

use kerfcam::Spec;
use std::path::{Path, PathBuf};

fn lw(layer: &str, pts: &[(f64, f64)]) -> String {
    let mut s = format!("0\nLWPOLYLINE\n8\n{layer}\n90\n{}\n70\n1\n", pts.len());
    for (x, y) in pts {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s
}

fn dxf(entities: &str) -> Vec<u8> {
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{entities}0\nENDSEC\n0\nEOF\n").into_bytes()
}

fn circle(layer: &str, x: f64, y: f64, r: f64) -> String {
    format!("0\nCIRCLE\n8\n{layer}\n10\n{x}\n20\n{y}\n40\n{r}\n")
}

/// The test pockets: tests/it/milling.rs's sign plate (a 280 × 130 pocket
/// with an I, an O and its counter, an L and a triangle), the Play tests'
/// 60 × 40 pocket around a round island, paper 004's R 20 circle and its
/// 50 × 30 rectangle around a hole.
fn pockets() -> Vec<(&'static str, Vec<u8>)> {
    let mut sign = lw(
        "POCKET",
        &[(10.0, 10.0), (290.0, 10.0), (290.0, 140.0), (10.0, 140.0)],
    );
    sign += &lw(
        "POCKET",
        &[(40.0, 40.0), (55.0, 40.0), (55.0, 110.0), (40.0, 110.0)],
    );
    sign += &circle("POCKET", 110.0, 75.0, 30.0);
    sign += &circle("POCKET", 110.0, 75.0, 14.0);
    sign += &lw(
        "POCKET",
        &[
            (160.0, 40.0),
            (200.0, 40.0),
            (200.0, 55.0),
            (175.0, 55.0),
            (175.0, 110.0),
            (160.0, 110.0),
        ],
    );
    sign += &lw("POCKET", &[(220.0, 40.0), (270.0, 40.0), (245.0, 110.0)]);
    let mut island = lw(
        "POCKET",
        &[(0.0, 0.0), (60.0, 0.0), (60.0, 40.0), (0.0, 40.0)],
    );
    island += &circle("POCKET", 30.0, 20.0, 8.0);
    let mut rect = lw(
        "POCKET",
        &[(0.0, 0.0), (50.0, 0.0), (50.0, 30.0), (0.0, 30.0)],
    );
    rect += &circle("POCKET", 25.0, 15.0, 5.0);
    vec![
        ("sign plate", dxf(&sign)),
        ("60x40 + island", dxf(&island)),
        ("R20 circle", dxf(&circle("POCKET", 0.0, 0.0, 20.0))),
        ("50x30 + hole", dxf(&rect)),
    ]
}

fn milling(dxf: &[u8], pocket: &str, fit_arcs: bool) -> kerfcam::Output {
    let settings = Spec {
        tool_diameter: Some(6.0),
        depth: Some(6.0),
        pass_depth: 2.0,
        pocket: pocket.into(),
        post: Some("grbl-router".into()),
        tolerance: 0.01,
        fit_arcs,
        layer_ops: vec![["POCKET".into(), "pocket".into()]],
        ..Spec::default()
    }
    .build()
    .expect("settings");
    kerfcam::run(dxf, &settings).expect("milling")
}

fn dxfs(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<PathBuf> = rd.filter_map(|e| e.ok()).map(|e| e.path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            dxfs(&p, out);
        } else if p.extension().is_some_and(|e| e.eq_ignore_ascii_case("dxf")) {
            out.push(p);
        }
    }
}

fn main() {
    println!("1. pockets, 6 mm tool, 6 mm deep in 3 passes, plunge (length in material = cuts + plunges)");
    println!("pocket\tstrategy\tin material mm\trapids mm\ttime s\tlines\tlines fitted\tmill moves before -> after fitting");
    let mut mill_before = 0;
    let mut mill_after = 0;
    for (name, d) in pockets() {
        let mut row = Vec::new();
        for pocket in ["zigzag", "offset"] {
            let plain = milling(&d, pocket, false);
            let fitted = milling(&d, pocket, true);
            let m = plain.milled.as_ref().expect("milled").stats;
            let f = fitted
                .milled
                .as_ref()
                .and_then(|m| m.arc_fit)
                .expect("fitted");
            mill_before += f.lines_before + f.arcs_before;
            mill_after += f.lines_after + f.arcs_after;
            println!(
                "{name}\t{pocket}\t{:.1}\t{:.1}\t{:.1}\t{}\t{}\t{} -> {}",
                m.cut_mm + m.plunge_mm,
                m.rapid_mm,
                plain.est_time_s,
                plain.gcode.lines().count(),
                fitted.gcode.lines().count(),
                f.lines_before + f.arcs_before,
                f.lines_after + f.arcs_after,
            );
            row.push((m.cut_mm + m.plunge_mm, plain.est_time_s));
        }
        println!(
            "{name}\toffset/zigzag\t{:.3}\t\t{:.3}",
            row[1].0 / row[0].0,
            row[1].1 / row[0].1
        );
    }
    println!("milling moves on the test pockets, both strategies: {mill_before} -> {mill_after}");

    let dir = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("../shared/corpus"));
    let mut files = Vec::new();
    dxfs(&dir, &mut files);
    println!();
    println!(
        "2. arc fitting on {} corpus DXFs under {}, kerf 1.5, tolerance 0.01 mm",
        files.len(),
        dir.display()
    );
    println!("file\tfeed moves before\tafter\tratio");
    let settings = Spec {
        kerf: Some(1.5),
        tolerance: 0.01,
        fit_arcs: true,
        ..Spec::default()
    }
    .build()
    .expect("settings");
    let (mut before, mut after, mut failed) = (0usize, 0usize, 0usize);
    for f in &files {
        let Ok(bytes) = std::fs::read(f) else {
            failed += 1;
            continue;
        };
        let Ok(out) = kerfcam::run(&bytes, &settings) else {
            failed += 1;
            continue;
        };
        let Some(a) = out.arc_fit() else { continue };
        let (b, c) = (a.lines_before + a.arcs_before, a.lines_after + a.arcs_after);
        before += b;
        after += c;
        let name = f.strip_prefix(&dir).unwrap_or(f).display();
        println!("{name}\t{b}\t{c}\t{:.3}", c as f64 / b.max(1) as f64);
    }
    println!(
        "corpus total: {before} -> {after} feed moves ({:.1} % saved), {failed} file(s) not planned",
        100.0 * (before - after) as f64 / before.max(1) as f64
    );
}
