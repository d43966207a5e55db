//! Every real SVG of `../shared/corpus-svg` (issue 41): read without an
//! error, through the whole pipeline to a program LinuxCNC's interpreter
//! accepts; the drawing's size against an independent reference
//! (`tests/reference/corpus-svg.json`, svgelements, made by
//! `tests/reference/svg_reference.py`) and the page size against the
//! corpus README's; the same part in DXF and SVG cuts the same; mutated
//! files never panic.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::common;

use kerfcam::dxf::{Drawing, ReadOptions};
use kerfcam::input;
use serde_json::Value;

fn corpus() -> PathBuf {
    common::shared().join("corpus-svg")
}

/// Every SVG of the corpus, by its name relative to the corpus folder.
fn files() -> Vec<(String, PathBuf)> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "svg") {
                out.push(p);
            }
        }
    }
    let mut v = Vec::new();
    walk(&corpus(), &mut v);
    v.sort();
    v.into_iter()
        .map(|p| {
            (
                p.strip_prefix(corpus())
                    .unwrap()
                    .to_string_lossy()
                    .replace('\\', "/"),
                p,
            )
        })
        .collect()
}

fn size(d: &Drawing) -> (f64, f64) {
    let e = d.extent;
    (e.max.x - e.min.x, e.max.y - e.min.y)
}

/// Files whose drawn size rightly differs from svgelements', and why.
const SIZE_DIFFERS: &[(&str, &str)] = &[];

#[test]
fn every_corpus_svg_reads_and_cuts_to_a_program_linuxcnc_accepts() {
    let files = files();
    assert!(
        files.len() >= 50,
        "corpus-svg not found beside the project: {}",
        files.len()
    );
    let reference: BTreeMap<String, Value> =
        serde_json::from_str(include_str!("../reference/corpus-svg.json")).unwrap();
    let (mut failures, mut table) = (Vec::new(), Vec::new());
    table.push(
        "| file | entities | layers | size mm | reference mm | pierces | warnings |".to_owned(),
    );
    table.push("|---|---|---|---|---|---|---|".to_owned());
    for (name, path) in &files {
        let bytes = std::fs::read(path).unwrap();
        let d = match input::read(&bytes, &ReadOptions::DEFAULT) {
            Ok(d) => d,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        let (w, h) = size(&d);
        let r = &reference[name.as_str()];
        let want = r["size_mm"]
            .as_array()
            .map(|a| (a[0].as_f64().unwrap(), a[1].as_f64().unwrap()));
        if let Some((rw, rh)) = want {
            let off = |a: f64, b: f64| (a - b).abs() > 1e-3 * b.max(1.0);
            if (off(w, rw) || off(h, rh)) && !SIZE_DIFFERS.iter().any(|(n, _)| n == name) {
                failures.push(format!(
                    "{name}: size {w:.4} × {h:.4} mm, svgelements {rw} × {rh}"
                ));
            }
        } else if !d.entities.is_empty() {
            failures.push(format!(
                "{name}: {} entities where svgelements finds no shape",
                d.entities.len()
            ));
        }
        let layers: Vec<&str> = d.layers.iter().map(|l| l.name.as_str()).collect();
        let (pierces, warnings) = if d.entities.is_empty() {
            (
                0,
                d.warnings
                    .iter()
                    .map(|w| w.code)
                    .collect::<Vec<_>>()
                    .join(" "),
            )
        } else {
            match kerfcam::run(&bytes, &common::kerf(0.2)) {
                Ok(out) => {
                    let safe: String = name
                        .chars()
                        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
                        .collect();
                    let errors = common::rs274_errors(&out.gcode, &format!("svg-{safe}"));
                    if !errors.is_empty() {
                        failures.push(format!(
                            "{name}: rs274: {:?}",
                            &errors[..errors.len().min(3)]
                        ));
                    }
                    let codes: std::collections::BTreeSet<&str> =
                        d.warnings.iter().map(|w| w.code).collect();
                    (
                        out.plan.pierces(),
                        codes.into_iter().collect::<Vec<_>>().join(" "),
                    )
                }
                Err(e) => {
                    failures.push(format!("{name}: pipeline: {e}"));
                    continue;
                }
            }
        };
        table.push(format!(
            "| {name} | {} | {} | {w:.2} × {h:.2} | {} | {pierces} | {warnings} |",
            d.entities.len(),
            layers.len(),
            want.map_or("-".into(), |(a, b)| format!("{a:.2} × {b:.2}")),
        ));
    }
    println!("{}", table.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The README's "overall size (mm)" column: the page per the SVG/CSS rules.
fn readme_sizes() -> BTreeMap<String, (f64, f64)> {
    let text = std::fs::read_to_string(corpus().join("README.md")).unwrap();
    let mut out = BTreeMap::new();
    for line in text.lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let (Some(name), Some(size)) = (cells.get(1), cells.get(6)) else {
            continue;
        };
        let name = name.trim_matches('`').to_owned();
        // "500.0 × 200.0. *intended …*": the two numbers around the first ×.
        let Some((w, rest)) = size.split_once(" × ") else {
            continue;
        };
        let h: String = rest
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect();
        if let (Ok(w), Ok(h)) = (
            w.trim().parse::<f64>(),
            h.trim_end_matches('.').parse::<f64>(),
        ) {
            out.insert(name, (w, h));
        }
    }
    out
}

#[test]
fn page_sizes_match_the_corpus_readme() {
    let sizes = readme_sizes();
    assert!(sizes.len() >= 50, "{}", sizes.len());
    let mut bad = Vec::new();
    for (name, path) in files() {
        let Some(&(w, h)) = sizes.get(&name) else {
            continue;
        };
        let bytes = std::fs::read(&path).unwrap();
        match kerfcam::svg::page_size(&bytes, None) {
            // The README rounds to 0.1 mm.
            Some((pw, ph)) if (pw - w).abs() <= 0.051 && (ph - h).abs() <= 0.051 => {}
            other => bad.push(format!("{name}: {other:?}, README {w} × {h}")),
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_unit_switch_reads_illustrator_px_at_72_per_inch() {
    // Illustrator CS5's A4 artboard in px: 210 × 297 mm at 72 px per inch.
    let bytes = std::fs::read(corpus().join("visicut/illustrator15.svg")).unwrap();
    let px72 = kerfcam::dxf::Units::from_name("px72");
    let (w, h) = kerfcam::svg::page_size(&bytes, px72).unwrap();
    assert!(
        (w - 210.0).abs() < 0.01 && (h - 297.0).abs() < 0.01,
        "{w} × {h}"
    );
    let d96 = input::read(&bytes, &ReadOptions::DEFAULT).unwrap();
    assert_eq!(d96.units_source, "assumed");
    assert!(d96.warnings.iter().any(|w| w.code == "units-assumed"));
    let opts = ReadOptions {
        units: px72,
        ..ReadOptions::DEFAULT
    };
    let d72 = input::read(&bytes, &opts).unwrap();
    let (a, b) = (size(&d96), size(&d72));
    assert!((b.0 / a.0 - 96.0 / 72.0).abs() < 1e-9, "{a:?} {b:?}");
}

#[test]
fn the_same_part_in_dxf_and_svg_cuts_the_same() {
    // A 60 × 40 plate with a 10 mm hole at (20, 20) and a slot, in both formats.
    let dxf = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n\
        0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n60\n20\n0\n10\n60\n20\n40\n10\n0\n20\n40\n\
        0\nCIRCLE\n8\n0\n10\n20\n20\n20\n40\n5\n\
        0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n35\n20\n15\n42\n-1\n10\n35\n20\n25\n10\n50\n20\n25\n42\n-1\n10\n50\n20\n15\n\
        0\nENDSEC\n0\nEOF\n";
    // y down from a 40 mm page top: y_svg = 40 − y.
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="40mm" viewBox="0 0 60 40">
        <path d="M0 40 H60 V0 H0 Z" fill="none" stroke="black"/>
        <circle cx="20" cy="20" r="5"/>
        <path d="M35 25 A5 5 0 0 1 35 15 H50 A5 5 0 0 1 50 25 Z"/></svg>"#;
    let s = common::kerf(1.5);
    let a = kerfcam::run(dxf.as_bytes(), &s).unwrap();
    let b = kerfcam::run(svg.as_bytes(), &s).unwrap();
    assert_eq!(a.plan.pierces(), b.plan.pierces());
    assert_eq!(a.contours.contours.len(), b.contours.contours.len());
    let area = |o: &kerfcam::Output| {
        let mut v: Vec<f64> = o.contours.contours.iter().map(|c| c.area.abs()).collect();
        v.sort_by(f64::total_cmp);
        v
    };
    for (x, y) in area(&a).iter().zip(area(&b)) {
        assert!((x - y).abs() < 1e-6, "{x} {y}");
    }
    let (sa, sb) = (a.plan.stats(), b.plan.stats());
    assert!(
        (sa.cut_length - sb.cut_length).abs() < 1e-6,
        "{} {}",
        sa.cut_length,
        sb.cut_length
    );
    let errors = common::rs274_errors(&b.gcode, "svg-same-part");
    assert!(errors.is_empty(), "{errors:?}");
}

/// A small deterministic generator (xorshift64*).
struct Rng(u64);
impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }
}

/// Mutations that reach the grammars: numbers, commands, flags, units.
const TOKENS: &[&str] = &[
    "1e308",
    "-1e308",
    "NaN",
    "inf",
    "0",
    "-0",
    "1e-320",
    "A",
    "a 0 0 0 1 1",
    "Z",
    "z",
    "C",
    "Q",
    "T",
    "S",
    "M",
    "<use href='#a'/>",
    "<g id='a'><use href='#a'/></g>",
    "viewBox='0 0 0 0'",
    "mm",
    "%",
    "transform='scale(0)'",
    "transform='matrix(1e300 0 0 1e300 0 0)'",
    "<![CDATA[",
    "&amp;",
    "&bad;",
    "\"",
    "'",
    "<",
    ">",
    "/>",
];

#[test]
fn mutated_corpus_files_and_random_bytes_never_panic() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let sources: Vec<Vec<u8>> = files()
        .iter()
        .map(|(_, p)| std::fs::read(p).unwrap())
        .filter(|b| b.len() < 40_000)
        .collect();
    let opts = ReadOptions::DEFAULT;
    let mut read = 0;
    for round in 0..1500 {
        let mut b = sources[rng.below(sources.len())].clone();
        for _ in 0..1 + rng.below(6) {
            let at = rng.below(b.len());
            match rng.below(4) {
                0 => b[at] = rng.next_u64() as u8,
                1 => {
                    let t = TOKENS[rng.below(TOKENS.len())].as_bytes();
                    b.splice(at..at, t.iter().copied());
                }
                2 => {
                    let end = (at + rng.below(64)).min(b.len());
                    b.drain(at..end);
                }
                _ => {
                    // A copy of a stretch elsewhere (repeated elements, deeper nesting).
                    let end = (at + rng.below(200)).min(b.len());
                    let piece: Vec<u8> = b[at..end].to_vec();
                    let to = rng.below(b.len());
                    b.splice(to..to, piece);
                }
            }
        }
        if let Ok(d) = input::read(&b, &opts) {
            read += 1;
            // The next stage takes what the reader gives.
            if round % 10 == 0 {
                let _ = kerfcam::contour::extract(&d, kerfcam::geom::Tolerance::DEFAULT, 0.01);
            }
        }
    }
    for _ in 0..300 {
        let n = rng.below(300);
        let mut b: Vec<u8> = (0..n).map(|_| rng.next_u64() as u8).collect();
        b.insert(0, b'<');
        let _ = input::read(&b, &opts);
    }
    // Most mutations break the XML (a clear error); enough still parse to reach the grammars.
    assert!(read > 200, "mutations that still parse: {read}");
}
