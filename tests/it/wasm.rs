//! The pipeline through the wasm API (`Job`), under Node:
//! scripts/test-all.sh's layer 2 (cargo test --target wasm32-unknown-unknown, wasm-bindgen-test-runner). Same fixture answers as the native tests, and a
//! pixel check that the preview draws what it should.
#![cfg(target_arch = "wasm32")]

use kerfcam::wasm::Job;
use serde::Serialize;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

const PLATE: &[u8] = include_bytes!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../shared/fixtures/seed000-plate-6-holes.dxf"
));
const GRID: &[u8] = include_bytes!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../shared/fixtures/seed003-grid-3x2.dxf"
));

#[derive(Serialize)]
struct Web {
    kerf: f64,
    tolerance: f64,
    feed: f64,
}

fn settings(kerf: f64) -> JsValue {
    serde_wasm_bindgen::to_value(&Web {
        kerf,
        tolerance: 0.001,
        feed: 1500.0,
    })
    .unwrap()
}

fn report(job: &Job) -> serde_json::Value {
    serde_json::from_str(&job.report_json()).unwrap()
}

#[wasm_bindgen_test]
fn plate_through_the_job_api_has_one_part_six_holes_and_four_invalid_vertices() {
    let job = Job::new(PLATE, settings(2.0), None).unwrap();
    let r = report(&job);
    assert_eq!(r["plan"]["parts"], 1);
    assert_eq!(r["plan"]["holes"], 6);
    assert_eq!(r["plan"]["open"], 0);
    assert_eq!(r["plan"]["pierces"], 7);
    assert_eq!(r["invalid_vertices"].as_array().unwrap().len(), 4);
    let g = job.gcode();
    assert!(
        g.contains("G21 G90 G17 G40 G91.1") && g.contains("F1500") && g.trim_end().ends_with('%')
    );
    assert_eq!(g.matches("M3 S1").count(), 7);
}

#[wasm_bindgen_test]
fn grid_contours_and_cut_length_match_the_native_answer() {
    let job = Job::new(GRID, settings(0.0), None).unwrap();
    let r = report(&job);
    assert_eq!(r["contours"].as_array().unwrap().len(), 6);
    assert_eq!(r["plan"]["cut_length"], 8400.0);
}

/// A DXF before AutoCAD 2007 in code page `page`, one line on a layer
/// whose name is the raw bytes `name`.
fn code_page_dxf(page: &str, name: &[u8]) -> Vec<u8> {
    let mut d = format!(
        "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$DWGCODEPAGE\n3\n{page}\n0\nENDSEC\n\
         0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n"
    )
    .into_bytes();
    d.extend_from_slice(name);
    d.extend_from_slice(b"\n10\n0\n20\n0\n11\n10\n21\n0\n0\nENDSEC\n0\nEOF\n");
    d
}

#[wasm_bindgen_test]
fn layer_names_decode_with_the_files_code_page_in_wasm() {
    // The page's wasm decodes code pages with the browser's TextDecoder
    // (src/wasm_text.rs); the characters here are the code pages'
    // published mappings (Python's codecs gave the bytes), not kerfcam's.
    for (page, bytes, name) in [
        ("ANSI_932", &b"\x82\xa0\x8a\xbf"[..], "あ漢"),
        ("ANSI_936", b"\xd6\xd0", "中"),
        ("ANSI_949", b"\xc7\xd1\xb1\xdb", "한글"),
        ("ANSI_950", b"\xa4\xa4\xa4\xe5", "中文"),
        ("ANSI_1250", b"Cz\xea\x9c\xe6", "Część"),
        ("DOS850", b"\x81", "ü"),
    ] {
        let job = Job::new(&code_page_dxf(page, bytes), settings(0.0), None).unwrap();
        let r = report(&job);
        let layers: Vec<&str> = r["layers"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|l| l["name"].as_str())
            .collect();
        assert_eq!(layers, [name], "{page}");
    }
    // A code page no decoder knows: read as Windows-1252, with a warning.
    let job = Job::new(&code_page_dxf("ANSI_9999", b"\xe9"), settings(0.0), None).unwrap();
    let r = report(&job);
    assert_eq!(r["layers"][0]["name"], "é");
}

#[wasm_bindgen_test]
fn layer_selection_ignores_case_beyond_ascii_in_wasm() {
    // Case folding of non-ASCII names goes through JavaScript in wasm
    // (src/case.rs): "äRGER" selects the layer "Ärger", "ÖL" does not.
    #[derive(Serialize)]
    struct Pick {
        kerf: f64,
        layers: Vec<String>,
    }
    let dxf = code_page_dxf("ANSI_1252", b"\xc4rger");
    let pick = |name: &str| {
        let s = Pick {
            kerf: 0.0,
            layers: vec![name.to_string()],
        };
        let job = Job::new(&dxf, serde_wasm_bindgen::to_value(&s).unwrap(), None).unwrap();
        report(&job)["contours"].as_array().map_or(0, Vec::len)
    };
    assert_eq!(pick("äRGER"), 1);
    assert_eq!(pick("ÖL"), 0);
}

#[wasm_bindgen_test]
fn missing_settings_take_the_defaults_and_bad_ones_are_refused() {
    assert!(Job::new(PLATE, JsValue::UNDEFINED, None).is_ok());
    assert!(Job::new(PLATE, settings(-1.0), None).is_err());
    assert!(Job::new(b"\x00\x01garbage", settings(1.0), None).is_err());
}

#[wasm_bindgen_test]
fn preview_raster_draws_part_fill_kerf_path_and_invalid_vertices() {
    let job = Job::new(PLATE, settings(2.0), None).unwrap();
    let b = job.bbox();
    let (w, h) = (480u32, 300u32);
    let scale = (w as f64 / (b[2] - b[0])).min(h as f64 / (b[3] - b[1])) * 0.95;
    let px = job
        .render(w, h, (b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0, scale, 1.0)
        .unwrap();
    assert_eq!(px.len(), (w * h * 4) as usize);
    let count = |rgb: [u8; 3]| {
        px.chunks(4)
            .filter(|p| p[..3] == rgb && p[3] == 255)
            .count()
    };
    assert!(count([0xcf, 0xe3, 0xf7]) > 20_000, "part fill");
    assert!(count([0xd6, 0x28, 0x28]) > 100, "kerf path");
    assert!(count([0xb0, 0x00, 0xb0]) > 100, "invalid vertices");
    assert!(count([0x1a, 0x9e, 0x3a]) > 100, "pierce points");
    assert!(job.render(0, 10, 0.0, 0.0, 1.0, 1.0).is_err());
}

#[wasm_bindgen_test]
fn progress_callback_hears_each_stage_in_order() {
    let log = js_sys::Array::new();
    let push = js_sys::Function::new_with_args("name, count", "this.push(name + ':' + count)");
    let on_stage = push.bind0(&log);
    let job = Job::new(PLATE, settings(2.0), Some(on_stage)).unwrap();
    let seen: Vec<String> = log.iter().filter_map(|v| v.as_string()).collect();
    let names: Vec<&str> = seen.iter().map(|s| s.split(':').next().unwrap()).collect();
    assert_eq!(
        names,
        ["reading", "chaining", "offset", "planning", "gcode"]
    );
    assert_eq!(seen[3], "planning:7"); // 7 pierces, as the report says
    assert_eq!(seen[4], format!("gcode:{}", job.gcode().len()));
}

#[derive(Serialize)]
struct WebLang {
    kerf: f64,
    lang: &'static str,
}

#[wasm_bindgen_test]
fn portuguese_messages_same_program() {
    let en = Job::new(PLATE, settings(2.0), None).unwrap();
    let web = WebLang {
        kerf: 2.0,
        lang: "pt-BR",
    };
    let pt = Job::new(PLATE, serde_wasm_bindgen::to_value(&web).unwrap(), None).unwrap();
    let web_en = Web {
        kerf: 2.0,
        tolerance: 0.001,
        feed: 2000.0,
    };
    let en_default_feed =
        Job::new(PLATE, serde_wasm_bindgen::to_value(&web_en).unwrap(), None).unwrap();
    assert_eq!(
        pt.gcode(),
        en_default_feed.gcode(),
        "the program changed with the language"
    );
    let (r_en, r_pt) = (report(&en), report(&pt));
    let w_pt = r_pt["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| w["code"] == "invalid-vertices")
        .expect("invalid-vertices warning");
    assert!(w_pt["message"]
        .as_str()
        .unwrap()
        .contains("canto(s) vivo(s)"));
    let w_en = r_en["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| w["code"] == "invalid-vertices")
        .unwrap();
    assert!(w_en["message"]
        .as_str()
        .unwrap()
        .contains("sharp corner(s)"));
    assert_eq!(w_en["messages"], w_pt["messages"]);
    let bad = r#"{"decimals": 9}"#;
    assert!(kerfcam::wasm::check_post(bad, None).contains("is not between 1 and 6"));
    assert!(kerfcam::wasm::check_post(bad, Some("pt-BR".into())).contains("não está entre 1 e 6"));
}

// ---- Nesting (issue 16): the Nester / NestResult API the Sheet mode uses.

use kerfcam::wasm::Nester;

/// A clock that moves 1 ms each time it is read: the same run every time.
fn tick_clock() -> js_sys::Function {
    js_sys::Function::new_no_args("this.t = (this.t || 0) + 0.001; return this.t;")
        .bind0(&js_sys::Object::new())
}

#[derive(Serialize)]
struct WebNest {
    sheet_width: f64,
    sheet_height: f64,
    sheet_count: usize,
    spacing: f64,
    margin: f64,
    time_s: f64,
    seed: u64,
}

fn sheet(w: f64, h: f64, count: usize, time_s: f64) -> JsValue {
    serde_wasm_bindgen::to_value(&WebNest {
        sheet_width: w,
        sheet_height: h,
        sheet_count: count,
        spacing: 2.5,
        margin: 5.0,
        time_s,
        seed: 3,
    })
    .unwrap()
}

#[derive(Serialize)]
struct WebPart {
    quantity: usize,
    rotations: &'static str,
}

fn qty(quantity: usize) -> JsValue {
    serde_wasm_bindgen::to_value(&WebPart {
        quantity,
        rotations: "90",
    })
    .unwrap()
}

#[wasm_bindgen_test]
fn nest_api_places_parts_reports_progress_and_cuts_a_sheet_with_the_crop_line_last() {
    let mut n = Nester::new(None);
    let names = n.add_part(PLATE, "plate.dxf", qty(3)).unwrap();
    assert_eq!(names, "[\"plate\"]");
    let log = js_sys::Array::new();
    let hear =
        js_sys::Function::new_with_args("p", "this.push(p.length); return true;").bind0(&log);
    let r = n
        .nest(sheet(1000.0, 500.0, 2, 0.2), tick_clock(), Some(hear))
        .unwrap();
    let j: serde_json::Value = serde_json::from_str(&r.json()).unwrap();
    assert_eq!(j["placed"], 3, "{j}");
    assert!(j["unplaced"].as_array().unwrap().is_empty());
    let u = j["sheets"][0]["utilisation"].as_f64().unwrap();
    assert!(u > 0.0 && u <= 1.0);
    // Heard at least the first nest, best-so-far lengths never growing.
    let lengths: Vec<f64> = log.iter().filter_map(|v| v.as_f64()).collect();
    assert!(!lengths.is_empty());
    assert!(
        lengths.windows(2).all(|w| w[1] <= w[0] + 1e-9),
        "{lengths:?}"
    );
    // Sheet 0 cut by the pipeline: 3 plates × 7 contours, then the crop.
    let crop = j["sheets"][0]["crop_x"].as_f64().expect("a remnant kept");
    let job = r.cut(0, settings(1.5)).unwrap();
    let rep = report(&job);
    assert_eq!(rep["plan"]["pierces"], 3 * 7 + 1, "{rep}");
    let g = job.gcode();
    assert_eq!(g.matches("M3 S1").count(), 22);
    // Pierced on the sheet's top edge at the crop line, straight down.
    let lines: Vec<&str> = g.lines().collect();
    let on = lines.iter().rposition(|l| l.starts_with("M3")).unwrap();
    let xy = |l: &str| -> (f64, f64) {
        let v = |c: char| {
            l.split_whitespace()
                .find_map(|w| w.strip_prefix(c).and_then(|n| n.parse::<f64>().ok()))
                .unwrap()
        };
        (v('X'), v('Y'))
    };
    let rapid = lines[..on]
        .iter()
        .rev()
        .find(|l| l.starts_with("G0"))
        .unwrap();
    assert_eq!(xy(rapid), (crop, 500.0), "{rapid}");
    assert_eq!(xy(lines[on + 1]), (crop, 0.0), "{}", lines[on + 1]);
    assert!(lines[on + 2].starts_with("M5"));
    assert!(r.cut(5, settings(1.5)).is_err());
    // The nest DXF, the sheet's DXF (a Job reads it) and the remnant.
    assert!(r.dxf().contains("REMNANT"));
    assert!(kerfcam::wasm::Job::new(r.sheet_dxf(0).as_bytes(), settings(1.5), None).is_ok());
    let rem = r.remnant_dxf();
    assert!(rem.contains("SHEET"));
    // …given back as the sheet of another nest.
    let mut again = Nester::new(None);
    again.add_part(PLATE, "plate.dxf", qty(1)).unwrap();
    assert_eq!(again.set_sheet_dxf(rem.as_bytes()).unwrap(), "[]");
    let r2 = again.nest(JsValue::UNDEFINED, tick_clock(), None).unwrap();
    let j2: serde_json::Value = serde_json::from_str(&r2.json()).unwrap();
    assert_eq!(j2["placed"], 1, "{j2}");
    assert!(j2["placements"][0]["translation"][0].as_f64().unwrap() > crop);
}

/// Sheets of two sizes (the page's `sheet_list`): the first size filled
/// first, each sheet reported and cut at its own size, and a list with a
/// size of 0 sheets refused.
#[wasm_bindgen_test]
fn nest_api_takes_a_list_of_sheet_sizes() {
    let mut n = Nester::new(None);
    n.add_part(PLATE, "plate.dxf", qty(4)).unwrap();
    let list = |sizes: &str| {
        js_sys::JSON::parse(&format!(
            r#"{{"sheet_list": {sizes}, "spacing": 2.5, "margin": 10, "time_s": 0.05, "seed": 1}}"#
        ))
        .unwrap()
    };
    // 450 × 180 holds two 200 × 120 plates, 250 × 150 one.
    let r = n
        .nest(
            list(r#"[{"width": 450, "height": 180, "count": 1}, {"width": 250, "height": 150, "count": 3}]"#),
            tick_clock(),
            None,
        )
        .unwrap();
    let j: serde_json::Value = serde_json::from_str(&r.json()).unwrap();
    assert_eq!(j["placed"], 4, "{j}");
    let sizes: Vec<(f64, f64, u64)> = j["sheets"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            (
                s["width"].as_f64().unwrap(),
                s["height"].as_f64().unwrap(),
                s["parts"].as_u64().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        sizes,
        [(450.0, 180.0, 2), (250.0, 150.0, 1), (250.0, 150.0, 1)],
        "{j}"
    );
    // Sheet 2's program stays on its 250 × 150.
    let g = r.cut(1, settings(1.5)).unwrap().gcode();
    for w in g.split_whitespace() {
        if let Some(x) = w.strip_prefix('X').and_then(|v| v.parse::<f64>().ok()) {
            assert!((-5.0..=255.0).contains(&x), "{w}");
        }
    }
    assert!(n
        .nest(
            list(r#"[{"width": 450, "height": 180, "count": 1}, {"width": 250, "height": 150, "count": 0}]"#),
            tick_clock(),
            None,
        )
        .is_err());
}

/// The largest number in part 0's outline path: its size, whatever the unit.
fn outline_span(n: &Nester) -> f64 {
    let o: serde_json::Value = serde_json::from_str(&n.outlines()).unwrap();
    o[0]["d"]
        .as_str()
        .unwrap()
        .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter_map(|w| w.parse::<f64>().ok())
        .fold(0.0, |m, v| m.max(v.abs()))
}

#[wasm_bindgen_test]
fn nest_api_reads_a_part_file_in_the_unit_chosen_for_it() {
    // The page's per-file unit switch (issue 18): the same file read in
    // inches is 25.4 times the size read as its own (mm); an unknown unit
    // is refused, not read at some scale.
    #[derive(Serialize)]
    struct Units {
        quantity: usize,
        units: &'static str,
    }
    let read = |units| {
        let mut n = Nester::new(None);
        let o = serde_wasm_bindgen::to_value(&Units { quantity: 1, units }).unwrap();
        n.add_part(PLATE, "plate.dxf", o).map(|_| outline_span(&n))
    };
    let own = read("").unwrap();
    let mm = read("mm").unwrap();
    let inch = read("in").unwrap();
    assert!((own - mm).abs() < 1e-9, "{own} {mm}");
    assert!((inch / mm - 25.4).abs() < 1e-9, "{inch} {mm}");
    assert!(read("furlong").is_err());
}

#[wasm_bindgen_test]
fn nest_api_cancel_and_bad_input_are_answers_not_crashes() {
    let mut n = Nester::new(None);
    let names: Vec<String> =
        serde_json::from_str(&n.add_part(GRID, "grid.dxf", qty(4)).unwrap()).unwrap();
    let stop = js_sys::Function::new_with_args("p", "return false;");
    let r = n
        .nest(sheet(1000.0, 500.0, 3, 1e6), tick_clock(), Some(stop))
        .unwrap();
    let j: serde_json::Value = serde_json::from_str(&r.json()).unwrap();
    // Stopped at the first report: the first nest reports every 8 copies
    // (one evaluation each) while it is placed, else once whole.
    let copies = 4 * names.len() as u64;
    let first = if copies > 8 { 8 } else { copies };
    assert_eq!(j["evaluations"], first, "stopped at the first report: {j}");
    let unplaced: u64 = j["unplaced"]
        .as_array()
        .unwrap()
        .iter()
        .map(|u| u["copies"].as_u64().unwrap())
        .sum();
    assert_eq!(
        j["placed"].as_u64().unwrap() + unplaced,
        4 * names.len() as u64,
        "{j}"
    );
    // A clock that throws ends the search, not the page.
    let bad_clock = js_sys::Function::new_no_args("throw new Error('no clock')");
    assert!(n
        .nest(sheet(1000.0, 500.0, 3, 5.0), bad_clock, None)
        .is_ok());
    assert!(Nester::new(None)
        .nest(sheet(1000.0, 500.0, 1, 0.0), tick_clock(), None)
        .is_err());
    assert!(
        n.nest(JsValue::UNDEFINED, tick_clock(), None).is_err(),
        "no sheet given"
    );
    assert!(n
        .nest(sheet(-5.0, 500.0, 1, 0.0), tick_clock(), None)
        .is_err());
    assert!(Nester::new(None)
        .add_part(b"\x00garbage", "x.dxf", qty(1))
        .is_err());
    #[derive(Serialize)]
    struct Rot {
        rotations: &'static str,
    }
    let bad = serde_wasm_bindgen::to_value(&Rot {
        rotations: "sideways",
    })
    .unwrap();
    assert!(Nester::new(None).add_part(PLATE, "p.dxf", bad).is_err());
    assert!(Nester::new(None)
        .set_sheet_dxf(b"0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n")
        .is_err());
}

/// A JsError's message, as the page reads it.
fn message(e: wasm_bindgen::JsError) -> String {
    let v = JsValue::from(e);
    js_sys::Reflect::get(&v, &JsValue::from_str("message"))
        .ok()
        .and_then(|m| m.as_string())
        .unwrap_or_default()
}

#[wasm_bindgen_test]
fn remnant_sheets_and_nest_files_are_refused_in_the_pages_language() {
    // Issue 18: the core's messages about a remnant sheet and a nest file
    // come in Portuguese to a Portuguese page, in English otherwise.
    const EMPTY: &[u8] = b"0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n";
    let pt = message(
        Nester::new(Some("pt-BR".into()))
            .set_sheet_dxf(EMPTY)
            .unwrap_err(),
    );
    assert!(pt.contains("não tem contorno fechado"), "{pt}");
    let en = message(Nester::new(None).set_sheet_dxf(EMPTY).unwrap_err());
    assert!(en.contains("no closed outline"), "{en}");
    // A nest file naming a sheet the nest does not have.
    let mut n = Nester::new(Some("pt-BR".into()));
    n.add_part(PLATE, "plate.dxf", qty(1)).unwrap();
    let bad = r#"{"placements": [[0, 0, 7, 0, 0, 100, 100]]}"#;
    let e = message(
        n.restore(sheet(1000.0, 500.0, 1, 1.0), 1, bad)
            .err()
            .unwrap(),
    );
    assert!(e.starts_with("ajuste do encaixe: cópia 0: esperado"), "{e}");
    let e = message(
        n.restore(sheet(1000.0, 500.0, 1, 1.0), 3, bad)
            .err()
            .unwrap(),
    );
    assert!(e.contains("3 chapas: entre 1 e 1"), "{e}");
}

#[derive(Serialize)]
struct WebProcess {
    kerf: f64,
    layer_ops: Vec<[&'static str; 2]>,
    small_hole_diameter: f64,
    verify: bool,
}

/// Issue 20 through the page's settings: layer operations (a MARK layer
/// scribed first, kind 9 in the moves; a DIM layer reported, or cut when
/// the settings say so), the small-hole rule and the verification.
#[wasm_bindgen_test]
fn layer_operations_small_holes_and_verification_reach_the_job() {
    let dxf = b"0\nSECTION\n2\nENTITIES\n\
0\nCIRCLE\n8\nCUT\n10\n50\n20\n50\n40\n40\n\
0\nCIRCLE\n8\nCUT\n10\n50\n20\n50\n40\n4\n\
0\nLINE\n8\nMARK\n10\n30\n20\n70\n11\n70\n21\n70\n\
0\nLINE\n8\nDIM\n10\n0\n20\n0\n11\n100\n21\n0\n\
0\nENDSEC\n0\nEOF\n";
    let web = |ops: Vec<[&'static str; 2]>| WebProcess {
        kerf: 1.5,
        layer_ops: ops,
        small_hole_diameter: 10.0,
        verify: true,
    };
    let job = Job::new(
        dxf,
        serde_wasm_bindgen::to_value(&web(vec![])).unwrap(),
        None,
    )
    .unwrap();
    let r = report(&job);
    let codes: Vec<&str> = r["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["code"].as_str().unwrap())
        .collect();
    assert!(codes.contains(&"layer-ignored"), "{codes:?}");
    assert_eq!(r["plan"]["small_holes"], 1);
    assert!(r["plan"]["mark_length"].as_f64().unwrap() > 39.9);
    assert_eq!(r["verification"]["parts_not_freed"], 0);
    let moves = job.moves();
    let first_feed = moves
        .chunks(7)
        .map(|m| m[0])
        .find(|k| *k != 0.0 && *k != 6.0 && *k != 7.0)
        .unwrap();
    assert_eq!(first_feed, 9.0, "the mark is the first feed move");
    let cut = Job::new(
        dxf,
        serde_wasm_bindgen::to_value(&web(vec![["DIM", "cut"]])).unwrap(),
        None,
    )
    .unwrap();
    assert!(!cut.report_json().contains("layer-ignored"));
    let bad = Job::new(
        dxf,
        serde_wasm_bindgen::to_value(&web(vec![["DIM", "drill"]])).unwrap(),
        None,
    );
    assert!(bad.is_err());
}

#[derive(Serialize)]
struct WebPasses {
    kerf: f64,
    depth: f64,
    pass_depth: f64,
    post: &'static str,
}

/// Issue 20 §8 through the page's settings: `depth` and `pass_depth` cut a
/// circle in three passes on a post with a Z word; a post without one
/// refuses the job.
#[wasm_bindgen_test]
fn depth_passes_reach_the_program_and_a_post_without_z_refuses() {
    let dxf =
        b"0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n10\n0\nENDSEC\n0\nEOF\n";
    let web = |post| WebPasses {
        kerf: 1.0,
        depth: 10.0,
        pass_depth: 4.0,
        post,
    };
    let job = Job::new(
        dxf,
        serde_wasm_bindgen::to_value(&web("linuxcnc")).unwrap(),
        None,
    )
    .unwrap();
    let g = job.gcode();
    let zs: Vec<&str> = g.lines().filter(|l| l.starts_with("G1 Z-")).collect();
    assert_eq!(zs, ["G1 Z-3.333", "G1 Z-6.667", "G1 Z-10"], "{g}");
    let refused = Job::new(
        dxf,
        serde_wasm_bindgen::to_value(&web("qtplasmac")).unwrap(),
        None,
    );
    assert!(refused.is_err());
}

// ---- A nest adjusted by hand (issue 18 item 4): the NestResult edit API.

#[wasm_bindgen_test]
fn nest_api_live_placements_hand_edits_conflicts_snap_and_the_moved_crop_line() {
    let mut n = Nester::new(None);
    n.add_part(PLATE, "plate.dxf", qty(3)).unwrap();
    let outlines: serde_json::Value = serde_json::from_str(&n.outlines()).unwrap();
    assert_eq!(outlines[0]["name"], "plate");
    let d = outlines[0]["d"].as_str().unwrap();
    assert_eq!(d.matches('M').count(), 7, "outline and six holes: {d}");
    assert!(d.contains('A'), "the round holes stay arcs");
    // Progress carries the best nest's copies, 7 numbers each, when it changed.
    let heard = js_sys::Array::new();
    let hear = js_sys::Function::new_with_args(
        "p",
        "if (p.placements) this.push(p.placements.length); return true;",
    )
    .bind0(&heard);
    let mut r = n
        .nest(sheet(1000.0, 500.0, 1, 0.05), tick_clock(), Some(hear))
        .unwrap();
    let sizes: Vec<f64> = heard.iter().filter_map(|v| v.as_f64()).collect();
    assert!(
        !sizes.is_empty() && sizes.iter().all(|&s| s == 21.0),
        "{sizes:?}"
    );
    let state = |s: &str| -> serde_json::Value { serde_json::from_str(s).unwrap() };
    let s0 = state(&r.state());
    assert_eq!(
        s0["conflicts"].as_array().unwrap().len(),
        0,
        "the nest as found passes the check"
    );
    let flat: Vec<f64> = serde_json::from_value(s0["flat"].clone()).unwrap();
    assert_eq!(flat.len(), 21);
    // Copy 1 dropped onto copy 0: both in conflict, and the nest is not cut.
    let mut moved = flat.clone();
    moved[7 + 5] = flat[5] + 10.0;
    moved[7 + 6] = flat[6];
    moved[7 + 3] = flat[3];
    moved[7 + 4] = flat[4];
    let rows = |f: &[f64]| {
        serde_json::json!({ "placements": f.chunks(7).collect::<Vec<_>>() }).to_string()
    };
    let s1 = state(&r.edit(&rows(&moved)).unwrap());
    let whys: Vec<(u64, String)> = s1["conflicts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["copy"].as_u64().unwrap(),
                c["why"].as_str().unwrap().to_owned(),
            )
        })
        .collect();
    assert!(
        whys.contains(&(0, "overlap".into())) && whys.contains(&(1, "overlap".into())),
        "{whys:?}"
    );
    assert!(
        r.cut(0, settings(1.5)).is_err(),
        "a nest in conflict is not cut"
    );
    // Back where it was: cut again.
    let s2 = state(&r.edit(&rows(&flat)).unwrap());
    assert_eq!(s2["conflicts"].as_array().unwrap().len(), 0);
    assert!(r.cut(0, settings(1.5)).is_ok());
    // Copy 2 taken far right, then snapped: back against its neighbours.
    let mut far = flat.clone();
    far[14 + 5] = 800.0;
    far[14 + 6] = 300.0;
    let s3 = state(&r.edit(&rows(&far)).unwrap());
    let u3 = s3["sheets"][0]["used_length"].as_f64().unwrap();
    let s4 = state(&r.snap(2).unwrap());
    assert_eq!(s4["conflicts"].as_array().unwrap().len(), 0);
    let u4 = s4["sheets"][0]["used_length"].as_f64().unwrap();
    assert!(u4 < u3 - 100.0, "snapped from {u3} to {u4}");
    // The crop line moved right: the remnant and the program's crop cut follow.
    let (lo, hi) = (
        s4["crop_range"][0].as_f64().unwrap(),
        s4["crop_range"][1].as_f64().unwrap(),
    );
    let x = (lo + hi) / 2.0;
    let s5 = state(&r.edit(&format!("{{\"crop\": {x}}}")).unwrap());
    assert_eq!(s5["sheets"][0]["crop_x"].as_f64(), Some(x));
    assert!(s5["sheets"][0]["utilisation"].as_f64() < s4["sheets"][0]["utilisation"].as_f64());
    assert!(
        r.remnant_dxf().contains(&format!("10\n{x}\n")),
        "{}",
        r.remnant_dxf()
    );
    let g = r.cut(0, settings(1.5)).unwrap().gcode();
    assert!(
        g.contains(&format!("X{x:.3}")) || g.contains(&format!("X{}", x)),
        "crop at {x}"
    );
    // Bad edits change nothing.
    assert!(r.edit("{\"placements\": [[9, 0, 0, 0, 0, 1, 1]]}").is_err());
    assert!(r
        .edit("{\"placements\": [[0, 0, 0, 0, 0, 1e400, 1]]}")
        .is_err());
    assert!(r.edit("{\"crop\": \"left\"}").is_err());
    assert!(r.edit("not json").is_err());
    assert!(r.snap(99).is_err());
    assert_eq!(state(&r.state())["flat"], s5["flat"]);
    // A nest file: the same parts and settings, the placements and crop line
    // saved, made again without a search: the same nest, figures and all.
    let saved: Vec<f64> = serde_json::from_value(s5["flat"].clone()).unwrap();
    let file = serde_json::json!({ "placements": saved.chunks(7).collect::<Vec<_>>(), "crop": x })
        .to_string();
    let again = n.restore(sheet(1000.0, 500.0, 1, 0.0), 1, &file).unwrap();
    let s6 = state(&again.state());
    for key in ["flat", "sheets", "conflicts", "remnant_area", "placements"] {
        assert_eq!(s6[key], s5[key], "{key}");
    }
    assert!(
        n.restore(sheet(1000.0, 500.0, 1, 0.0), 2, &file).is_err(),
        "2 sheets of 1"
    );
    assert!(n.restore(sheet(-1.0, 500.0, 1, 0.0), 1, &file).is_err());
    assert!(n
        .restore(
            sheet(1000.0, 500.0, 1, 0.0),
            1,
            "{\"placements\": [[0, 0, 3, 0, 0, 1, 1]]}"
        )
        .is_err());
}

#[derive(Serialize)]
struct WithMaterial {
    kerf: f64,
    feed: f64,
    post: &'static str,
    material: String,
}

#[wasm_bindgen_test]
fn a_material_chosen_in_the_page_sets_the_program_and_bad_ones_name_the_field() {
    use kerfcam::wasm::{materials_cfg, materials_read};
    let file = "[MATERIAL_NUMBER_4]\nNAME = Mild 4mm\nKERF_WIDTH = 1.7\nPIERCE_HEIGHT = 4\n\
PIERCE_DELAY = 0.5\nCUT_HEIGHT = 1.5\nCUT_SPEED = 2700\n";
    let lib: serde_json::Value =
        serde_json::from_str(&materials_read(file, None).unwrap()).unwrap();
    assert_eq!(materials_cfg(&lib.to_string(), None).unwrap(), file);
    let web = |material: String| {
        serde_wasm_bindgen::to_value(&WithMaterial {
            kerf: 1.0,
            feed: 1000.0,
            post: "qtplasmac",
            material,
        })
        .unwrap()
    };
    let job = Job::new(PLATE, web(lib["entries"][0].to_string()), None).unwrap();
    let g = job.gcode();
    assert!(g.contains("M190 P4") && g.contains("kerf 1.7 mm"), "{g}");
    let mut bad = lib["entries"][0].clone();
    bad["feed"] = serde_json::json!(-1);
    assert!(Job::new(PLATE, web(bad.to_string()), None).is_err());
}

#[wasm_bindgen_test]
fn the_contours_preview_comes_once_before_the_plan_fitted_in_the_canvas() {
    // Records what the page's callbacks hear, in order.
    let on_stage =
        js_sys::Function::new_with_args("name", "(globalThis.kerfcamHeard ??= []).push(name)");
    let on_contours = js_sys::Function::new_with_args(
        "rgba, view",
        "globalThis.kerfcamHeard.push(['contours', rgba.length, view[0], view[1], view[2], rgba.some((v, i) => i % 4 < 3 && v < 255)])",
    );
    let job = Job::watched(
        PLATE,
        settings(2.0),
        Some(on_stage),
        Some(vec![300.0, 200.0, 2.0]),
        Some(on_contours),
    )
    .unwrap();
    let log: js_sys::Array = js_sys::Reflect::get(&js_sys::global(), &"kerfcamHeard".into())
        .unwrap()
        .into();
    let heard: Vec<String> = log
        .iter()
        .map(|v| {
            v.as_string()
                .unwrap_or_else(|| js_sys::JSON::stringify(&v).unwrap().into())
        })
        .collect();
    let at = heard
        .iter()
        .position(|h| h.starts_with("[\"contours\""))
        .expect("a contours preview");
    // After chaining, before the kerf and the plan.
    assert_eq!(heard[..at], ["reading", "chaining"]);
    assert_eq!(heard[at + 1..], ["offset", "planning", "gcode"]);
    let v: serde_json::Value = serde_json::from_str(&heard[at]).unwrap();
    // 300 × 200 CSS pixels at ratio 2: 600 × 400 RGBA pixels, something drawn.
    assert_eq!(v[1], 600 * 400 * 4);
    assert_eq!(v[5], true);
    // The view: the contours' extent fitted with a 10 % margin, as the page fits a job.
    let r = report(&job);
    let (cx, cy, scale) = (
        v[2].as_f64().unwrap(),
        v[3].as_f64().unwrap(),
        v[4].as_f64().unwrap(),
    );
    assert!(cx.is_finite() && cy.is_finite() && scale > 0.0);
    let size = &r["size"];
    let (w, h) = (size["w"].as_f64().unwrap(), size["h"].as_f64().unwrap());
    assert!(
        (scale - (300.0 / (w * 1.1)).min(200.0 / (h * 1.1))).abs() < 1e-6 * scale,
        "{scale} for {w} × {h}"
    );
    // Without a canvas size, no preview and no error.
    assert!(Job::watched(
        PLATE,
        settings(2.0),
        None,
        None,
        Some(js_sys::Function::new_no_args("throw 1"))
    )
    .is_ok());
}

#[wasm_bindgen_test]
fn the_page_report_leaves_out_a_long_contour_list_and_says_how_long_it_was() {
    let mut job = Job::new(PLATE, settings(2.0), None).unwrap();
    let full = report(&job);
    let same: serde_json::Value = serde_json::from_str(&job.page_report_json(100)).unwrap();
    assert_eq!(same, full);
    let short: serde_json::Value = serde_json::from_str(&job.page_report_json(3)).unwrap();
    assert_eq!(short["contours_omitted"], 7);
    assert_eq!(short["contours"], serde_json::json!([]));
    assert_eq!(short["plan"], full["plan"]);
    // The job keeps its list.
    assert_eq!(report(&job), full);
    assert_eq!(job.program(), job.gcode().into_bytes());
}

/// Issue 42 §1: a file's parts as rows, and each part's own quantity.
#[wasm_bindgen_test]
fn part_rows_list_each_part_and_each_part_takes_its_own_quantity() {
    let n = Nester::new(None);
    let rows: serde_json::Value =
        serde_json::from_str(&n.part_rows(GRID, "grid.dxf", JsValue::UNDEFINED).unwrap()).unwrap();
    let list = rows["rows"].as_array().unwrap();
    assert_eq!(list.len(), 6, "{rows}");
    for r in list {
        assert!(r["width"].as_f64().unwrap() > 0.0 && r["area"].as_f64().unwrap() > 0.0);
        assert!(r["d"].as_str().unwrap().starts_with('M'));
        assert!(r["not_nestable"].is_null());
    }
    #[derive(Serialize)]
    struct Each {
        quantity: usize,
    }
    #[derive(Serialize)]
    struct Options {
        quantity: usize,
        each: Vec<Each>,
    }
    let options = serde_wasm_bindgen::to_value(&Options {
        quantity: 7,
        each: [1, 0, 2, 0, 0, 0].map(|quantity| Each { quantity }).into(),
    })
    .unwrap();
    let mut n = Nester::new(None);
    n.add_part(GRID, "grid.dxf", options).unwrap();
    let r = n
        .nest(sheet(1000.0, 500.0, 1, 0.2), tick_clock(), None)
        .unwrap();
    let j: serde_json::Value = serde_json::from_str(&r.json()).unwrap();
    assert_eq!(j["placed"], 3, "{j}");
    let names = list.iter().map(|r| r["name"].as_str().unwrap().to_owned());
    let first = names.clone().next().unwrap();
    let third = names.clone().nth(2).unwrap();
    let placed: Vec<&str> = j["placements"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["part"].as_str().unwrap())
        .collect();
    assert_eq!(placed.iter().filter(|p| **p == first).count(), 1, "{placed:?}");
    assert_eq!(placed.iter().filter(|p| **p == third).count(), 2, "{placed:?}");
}
