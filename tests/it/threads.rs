//! The stages on several threads give exactly what one thread gives
//! (issue 17, src/par.rs): the drawing, contours, kerf paths, plan,
//! warnings, report and program of a sheet big enough to be split among
//! threads, and of every shared drawing, compared with one thread's.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use std::fmt::Write;

use common::{corpus_files, shared};
use kerfcam::par::Threads;
use kerfcam::plan::Order;
use kerfcam::report::Report;
use kerfcam::{Output, Settings};

/// A sheet of `n` parts in rows of 60, drawn the ways a nest comes: plates
/// of four LINEs or one closed LWPOLYLINE with a rounded corner, round and
/// square holes (sharp scrap-side corners: invalid vertices), an island in
/// a hole, and now and then a circle drawn twice, a zero-length line and
/// an open arc (healing and open-contour warnings spread over the sheet, so
/// every thread's range has some).
fn sheet(n: usize) -> Vec<u8> {
    let mut s = String::from("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n");
    s += "0\nSECTION\n2\nENTITIES\n";
    for i in 0..n {
        let (x, y) = ((i % 60) as f64 * 110.0, (i / 60) as f64 * 70.0);
        if i % 3 == 0 {
            for (a, b) in [
                ((0., 0.), (100., 0.)),
                ((100., 0.), (100., 60.)),
                ((100., 60.), (0., 60.)),
                ((0., 60.), (0., 0.)),
            ] {
                let _ = write!(
                    s,
                    "0\nLINE\n8\nparts\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
                    x + a.0,
                    y + a.1,
                    x + b.0,
                    y + b.1
                );
            }
        } else {
            // A closed LWPOLYLINE, its last corner rounded by a bulge.
            let _ = write!(
                s,
                "0\nLWPOLYLINE\n8\nparts\n90\n5\n70\n1\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n42\n0.4142135623730951\n10\n{}\n20\n{}\n",
                x,
                y,
                x + 100.0,
                y,
                x + 100.0,
                y + 50.0,
                x + 90.0,
                y + 60.0,
                x,
                y + 60.0
            );
        }
        let _ = write!(
            s,
            "0\nCIRCLE\n8\nholes\n10\n{}\n20\n{}\n40\n10.0\n",
            x + 25.0,
            y + 30.0
        );
        // A square hole with an island in it.
        let _ = write!(
            s,
            "0\nLWPOLYLINE\n8\nholes\n90\n4\n70\n1\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n",
            x + 50.0,
            y + 10.0,
            x + 90.0,
            y + 10.0,
            x + 90.0,
            y + 50.0,
            x + 50.0,
            y + 50.0
        );
        let _ = write!(
            s,
            "0\nCIRCLE\n8\nparts\n10\n{}\n20\n{}\n40\n8.0\n",
            x + 70.0,
            y + 30.0
        );
        if i % 97 == 5 {
            let _ = write!(
                s,
                "0\nCIRCLE\n8\nholes\n10\n{}\n20\n{}\n40\n10.0\n",
                x + 25.0,
                y + 30.0
            );
        }
        if i % 89 == 7 {
            let _ = write!(s, "0\nLINE\n8\nparts\n10\n{x}\n20\n{y}\n11\n{x}\n21\n{y}\n");
        }
        if i % 101 == 9 {
            let _ = write!(
                s,
                "0\nARC\n8\nparts\n10\n{}\n20\n{}\n40\n4.0\n50\n0\n51\n90\n",
                x + 104.0,
                y + 65.0
            );
        }
    }
    s += "0\nENDSEC\n0\nEOF\n";
    s.into_bytes()
}

/// Everything a run gives, as text: the drawing, contours, kerf paths and
/// plan (Debug), the report and the program.
fn everything(out: &Output) -> Vec<(&'static str, String)> {
    vec![
        ("drawing", format!("{:?}", out.drawing)),
        ("contours", format!("{:?}", out.contours)),
        ("kerf", format!("{:?}", out.kerf)),
        ("plan", format!("{:?}", out.plan)),
        ("report", Report::new(out).to_json()),
        ("program", out.gcode.clone()),
    ]
}

/// A run's everything (`Ok`) or its error's text (`Err`).
type Outcome = Result<Vec<(&'static str, String)>, String>;

fn outcome(bytes: &[u8], settings: &Settings, threads: Threads) -> Outcome {
    kerfcam::run(bytes, &settings.clone().with_threads(threads))
        .map(|out| everything(&out))
        .map_err(|e| e.to_string())
}

/// Runs `bytes` with each of `threads` and names what differs from one
/// thread's run (made once: issue 40, it was most of this file's time).
fn differences(name: &str, bytes: &[u8], settings: &Settings, threads: &[usize]) -> Vec<String> {
    let one = outcome(bytes, settings, Threads::ONE);
    let mut diffs = Vec::new();
    for &n in threads {
        match (&one, outcome(bytes, settings, Threads::new(n))) {
            (Ok(a), Ok(b)) => diffs.extend(
                a.iter()
                    .zip(&b)
                    .filter(|(x, y)| x.1 != y.1)
                    .map(|(x, _)| format!("{name}: the {} differs with {n} threads", x.0)),
            ),
            (Err(a), Err(b)) if *a == b => {}
            (a, b) => diffs.push(format!(
                "{name}: one thread {:?}, {n} threads {:?}",
                a.as_ref().err(),
                b.err()
            )),
        }
    }
    diffs
}

fn settings(order: Order) -> Settings {
    Settings::new(1.5, 0.001, 2000.0)
        .and_then(|s| s.with_order(order))
        .unwrap()
}

#[test]
fn a_sheet_split_among_threads_gives_what_one_thread_gives() {
    let bytes = sheet(3000);
    let mut diffs = Vec::new();
    for order in [Order::Contour, Order::Chained] {
        diffs.extend(differences(
            &format!("sheet, {order:?} order"),
            &bytes,
            &settings(order),
            &[2, 3, 8],
        ));
    }
    assert!(diffs.is_empty(), "{diffs:#?}");
}

#[test]
fn the_sheet_is_big_enough_to_be_split() {
    // Each stage splits only work of a few thousand items (src/par.rs
    // callers); the sheet above must reach that, or its test proves nothing.
    let out = kerfcam::run(&sheet(3000), &settings(Order::Contour)).unwrap();
    assert!(out.drawing.entities.len() >= 12_000);
    assert!(out.contours.contours.len() >= 12_000);
    assert!(out.kerf.paths.len() >= 12_000, "{}", out.kerf.paths.len());
    let codes: Vec<&str> = out.warnings().map(|w| w.code).collect();
    for code in ["invalid-vertices", "healed", "open-contour"] {
        assert!(codes.contains(&code), "no {code} warning: {codes:?}");
    }
}

#[test]
fn every_shared_drawing_gives_the_same_with_threads() {
    let mut files = corpus_files();
    if let Ok(rd) = std::fs::read_dir(shared().join("fixtures")) {
        let mut f: Vec<_> = rd
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")))
            .collect();
        f.sort();
        files.extend(f);
    }
    assert!(
        files.len() >= 50,
        "shared drawings not found: {}",
        files.len()
    );
    let mut diffs = Vec::new();
    for f in &files {
        let bytes = std::fs::read(f).unwrap();
        let name = f.file_name().unwrap().to_string_lossy();
        diffs.extend(differences(&name, &bytes, &settings(Order::Contour), &[3]));
    }
    assert!(diffs.is_empty(), "{diffs:#?}");
}
