//! Trust what you read (issue 13): units never silently 25.4 × off, the
//! program's zero where the user expects it, truncated files flagged,
//! warnings grouped and ranked. Programs are read back by LinuxCNC's own
//! interpreter (`rs274 -g`), not by our code.

use crate::common;

use common::{corpus_files, kerf, rs274_error_lines, rs274_output, shared};
use kerfcam::dxf::Units;
use kerfcam::origin::ProgramOrigin;
use kerfcam::report::Report;
use kerfcam::Settings;

/// Corpus files without `$INSUNITS` whose real size is known (the file's
/// title, its part, or its use) and the size they must read as, mm.
const KNOWN_SIZES: &[(&str, f64, f64)] = &[
    // A dragon cut-out 203 × 412 (the issue: read as inches it was 5.2 × 10.5 m).
    ("dxf2gcode-plasma/DRAAK.dxf", 202.9, 412.0),
    (
        "dxf2gcode-plasma/Ellipsenbögen_Block_gedreht.dxf",
        186.8,
        174.3,
    ),
    ("dxf2gcode-plasma/Linieblock1.dxf", 126.6, 140.0),
    ("visicut/2 HG2 Seite.dxf", 265.5, 167.0),
    // "Fan Grill 80mm": the grille's rings are 77.6 mm across.
    (
        "openbuilds-cam/Fan Grill  80mm - Concentric.dxf",
        77.6,
        77.6,
    ),
    // A NEMA 23 motor's flange is 57 mm square; its mount 52 × 61.
    (
        "openbuilds-cam/Motor NEMA23 - Sliding Mount.dxf",
        52.2,
        61.2,
    ),
];

fn size(r: &serde_json::Value) -> (f64, f64) {
    let s = &r["size"];
    (s["w"].as_f64().unwrap(), s["h"].as_f64().unwrap())
}

fn report(out: &kerfcam::Output) -> serde_json::Value {
    serde_json::from_str(&Report::new(out).to_json()).unwrap()
}

#[test]
fn corpus_files_without_insunits_read_at_their_real_size_with_the_warning() {
    for &(name, w, h) in KNOWN_SIZES {
        let out = common::run(&shared().join("corpus").join(name), &kerf(0.0)).unwrap();
        let r = report(&out);
        let (rw, rh) = size(&r);
        assert!(
            (rw - w).abs() < 0.1 && (rh - h).abs() < 0.1,
            "{name}: {rw} × {rh}, not {w} × {h}"
        );
        assert_eq!(r["units"], "mm", "{name}");
        assert_eq!(r["units_source"], "assumed", "{name}");
        assert_eq!(r["units_assumed"], true, "{name}");
        let first = &r["warnings"][0];
        assert_eq!(
            first["code"], "units-assumed",
            "{name}: the units come first"
        );
        let m = first["message"].as_str().unwrap();
        assert!(m.contains("read as mm"), "{name}: {m}");
    }
}

/// Corpus files without `$INSUNITS` that read as inches: each is 1–3 units
/// across, nothing to cut in mm. Before issue 13 these were read as mm, and
/// DRAAK, Ellipsenbögen, Linieblock1 and 2 HG2 Seite (`$MEASUREMENT = 0`)
/// as inches, 25.4 × too big.
const ASSUMED_INCHES: &[&str] = &[
    "dxf2gcode-plasma/SchlittenBack.dxf",
    "dxf2gcode-plasma/Spline_Problem.dxf",
    "ezdxf/Leica_Disto_S910.dxf",
    "ezdxf/cc_dxflib.dxf",
    "openscad/☠-2D.dxf",
];

#[test]
fn every_corpus_file_says_where_its_unit_came_from() {
    let files = corpus_files();
    assert!(files.len() > 50, "corpus missing: {} files", files.len());
    for path in files {
        let out =
            common::run(&path, &kerf(0.0)).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let r = report(&out);
        let assumed = out.warnings().filter(|w| w.code == "units-assumed").count();
        match r["units_source"].as_str().unwrap() {
            "$INSUNITS" => assert_eq!(assumed, 0, "{}", path.display()),
            "assumed" => {
                assert_eq!(assumed, 1, "{}", path.display());
                let name = path.strip_prefix(shared().join("corpus")).unwrap();
                let inch = ASSUMED_INCHES
                    .iter()
                    .any(|f| name == std::path::Path::new(f));
                assert_eq!(
                    r["units"],
                    if inch { "in" } else { "mm" },
                    "{}",
                    path.display()
                );
            }
            other => panic!("{}: units_source {other}", path.display()),
        }
    }
}

/// The end points of every feed move rs274 reads in a program (X, Y).
fn feed_points(program: &str, name: &str) -> Vec<(f64, f64)> {
    // Read back by rs274 itself: without it there is nothing to check, and the test fails.
    let text = rs274_output(program, name).expect("rs274 reads the program back");
    assert_eq!(rs274_error_lines(&text), Vec::<String>::new());
    text.lines()
        .filter_map(|l| {
            let args = l.split("STRAIGHT_FEED(").nth(1)?;
            let mut it = args
                .split(',')
                .map(|v| v.trim().trim_end_matches(')').parse::<f64>());
            Some((it.next()?.ok()?, it.next()?.ok()?))
        })
        .collect()
}

/// A 100 × 60 rectangle whose corner is at (-50, -706), drawn with lines,
/// and a square hole: the lowest feed points are the rectangle's corner.
fn plate_far_below_zero(header: &str) -> String {
    let lw = |pts: &[(f64, f64)]| {
        let mut s = format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", pts.len());
        for (x, y) in pts {
            s += &format!("10\n{x}\n20\n{y}\n");
        }
        s
    };
    let outer = lw(&[
        (-50.0, -706.0),
        (50.0, -706.0),
        (50.0, -646.0),
        (-50.0, -646.0),
    ]);
    let hole = lw(&[
        (-10.0, -686.0),
        (10.0, -686.0),
        (10.0, -666.0),
        (-10.0, -666.0),
    ]);
    format!("{header}0\nSECTION\n2\nENTITIES\n{outer}{hole}0\nENDSEC\n0\nEOF\n")
}

fn no_leads(s: Settings) -> Settings {
    let mut plan = s.plan().clone();
    plan.leads.kind = kerfcam::plan::LeadKind::None;
    s.with_plan(plan).unwrap()
}

fn min_xy(points: &[(f64, f64)]) -> (f64, f64) {
    points
        .iter()
        .fold((f64::INFINITY, f64::INFINITY), |(a, b), &(x, y)| {
            (a.min(x), b.min(y))
        })
}

#[test]
fn lower_left_origin_puts_the_parts_corner_at_zero_in_the_program() {
    let dxf = plate_far_below_zero("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n");
    for (name, origin) in [
        ("origin-lower-left", ProgramOrigin::LowerLeft),
        ("origin-auto", ProgramOrigin::Auto),
    ] {
        let s = no_leads(kerf(0.0).with_origin(origin).unwrap());
        let out = kerfcam::run(dxf.as_bytes(), &s).unwrap();
        let (x, y) = min_xy(&feed_points(&out.gcode, name));
        assert!(
            x.abs() < 1e-3 && y.abs() < 1e-3,
            "{name}: lowest feed at ({x}, {y})"
        );
        assert_eq!(out.origin.at, [-50.0, -706.0]);
        assert_eq!(out.origin.auto, origin == ProgramOrigin::Auto);
        assert_eq!(
            out.warnings().any(|w| w.code == "origin-moved"),
            origin == ProgramOrigin::Auto,
            "auto says it moved the zero"
        );
    }
    // The drawing's own zero keeps the drawing's coordinates.
    let s = no_leads(kerf(0.0));
    let out = kerfcam::run(dxf.as_bytes(), &s).unwrap();
    let (x, y) = min_xy(&feed_points(&out.gcode, "origin-drawing"));
    assert!(
        (x + 50.0).abs() < 1e-3 && (y + 706.0).abs() < 1e-3,
        "({x}, {y})"
    );
}

#[test]
fn choosing_inches_scales_the_program_by_exactly_25_4() {
    // No $INSUNITS and 100 units across: read as mm, with the warning.
    let dxf = plate_far_below_zero("");
    let run = |units: Option<Units>, name: &str| {
        let mut s = no_leads(kerf(0.0));
        if let Some(u) = units {
            s = s.with_units(u);
        }
        let out = kerfcam::run(dxf.as_bytes(), &s).unwrap();
        (feed_points(&out.gcode, name), out)
    };
    let (mm, out_mm) = run(None, "units-assumed-mm");
    assert!(out_mm.warnings().any(|w| w.code == "units-assumed"));
    let (inch, out_in) = run(Some(Units::INCH), "units-chosen-in");
    assert!(!out_in.warnings().any(|w| w.code == "units-assumed"));
    assert_eq!(mm.len(), inch.len());
    for ((xm, ym), (xi, yi)) in mm.iter().zip(&inch) {
        // The program is written to 3 decimals: 25.4 × within that.
        assert!(
            (xm * 25.4 - xi).abs() < 2e-3 && (ym * 25.4 - yi).abs() < 2e-3,
            "({xm}, {ym}) → ({xi}, {yi})"
        );
    }
}

#[test]
fn a_truncated_corpus_file_is_flagged() {
    let path = shared().join("corpus/voron2/Bottom_Panel_350^3_Rev2.DXF");
    let bytes = std::fs::read(&path).unwrap();
    let cut = &bytes[..bytes.len() * 7 / 10];
    let out = kerfcam::run(cut, &kerf(1.5)).unwrap();
    let w: Vec<_> = out
        .warnings()
        .filter(|w| w.code == "file-truncated")
        .collect();
    assert_eq!(
        w.len(),
        1,
        "{:?}",
        out.warnings().map(|w| w.code).collect::<Vec<_>>()
    );
    assert!(w[0].message().contains("line"), "{}", w[0].message());
    // Whole, it is not.
    let out = kerfcam::run(&bytes, &kerf(1.5)).unwrap();
    assert!(!out.warnings().any(|w| w.code == "file-truncated"));
}

#[test]
fn six_hundred_one_vertex_polylines_are_one_grouped_warning() {
    let mut body = String::from("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n50\n20\n50\n40\n20\n");
    for i in 0..600 {
        body += &format!("0\nLWPOLYLINE\n90\n1\n70\n0\n10\n{i}\n20\n0\n");
    }
    body += "0\nENDSEC\n0\nEOF\n";
    let out = kerfcam::run(body.as_bytes(), &kerf(1.5)).unwrap();
    let r = report(&out);
    let skipped: Vec<&serde_json::Value> = r["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == "entity-skipped")
        .collect();
    assert_eq!(skipped.len(), 1, "{skipped:?}");
    assert_eq!(skipped[0]["count"], 600);
    assert_eq!(skipped[0]["places"].as_array().unwrap().len(), 5);
    let m = skipped[0]["message"].as_str().unwrap();
    assert!(m.starts_with("600 × LWPOLYLINE skipped"), "{m}");
    assert!(m.contains("first at line"), "{m}");
}

#[test]
fn repairs_are_notes_after_the_warnings() {
    // Two copies of one line (healed as a duplicate) and an open contour.
    let dxf = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n\
        0\nLINE\n10\n0\n20\n0\n11\n100\n21\n0\n0\nLINE\n10\n0\n20\n0\n11\n100\n21\n0\n0\nENDSEC\n0\nEOF\n";
    let out = kerfcam::run(dxf.as_bytes(), &kerf(1.5)).unwrap();
    let r = report(&out);
    let ws = r["warnings"].as_array().unwrap();
    let healed = ws
        .iter()
        .position(|w| w["code"] == "healed")
        .expect("healed note");
    assert_eq!(ws[healed]["severity"], "info");
    assert!(ws[..healed].iter().all(|w| w["severity"] == "warning"));
    assert!(ws[healed..].iter().all(|w| w["severity"] == "info"));
}

#[test]
fn polygonal_round_holes_are_not_invalid_vertices_but_sharp_corners_are() {
    // A 32-gon hole of radius 10 (each vertex turns 11.25°: a 1.5 mm kerf leaves 0.004 mm there, over the tolerance) and a square hole, in a plate.
    let mut hole = String::from("0\nLWPOLYLINE\n90\n32\n70\n1\n");
    for k in 0..32 {
        let a = k as f64 * std::f64::consts::TAU / 32.0;
        hole += &format!(
            "10\n{}\n20\n{}\n",
            50.0 + 10.0 * a.cos(),
            50.0 + 10.0 * a.sin()
        );
    }
    let square = "0\nLWPOLYLINE\n90\n4\n70\n1\n10\n120\n20\n40\n10\n140\n20\n40\n10\n140\n20\n60\n10\n120\n20\n60\n";
    let outer = "0\nLWPOLYLINE\n90\n4\n70\n1\n10\n0\n20\n0\n10\n200\n20\n0\n10\n200\n20\n100\n10\n0\n20\n100\n";
    let dxf = format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{outer}{hole}{square}0\nENDSEC\n0\nEOF\n");
    let out = kerfcam::run(dxf.as_bytes(), &kerf(1.5)).unwrap();
    let v = &out.kerf.invalid_vertices;
    assert_eq!(v.len(), 4, "{v:?}");
    assert!(
        v.iter().all(|p| p.x >= 119.0),
        "only the square's corners: {v:?}"
    );
}
