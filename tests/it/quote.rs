//! Issue 42 §3: the quote through the command line. A one-part job's
//! price worked out here by hand from the plan (its time estimate, its
//! pierces and metres) and the part's area equals the JSON report's and the
//! CSV's; a nest's copies' times sum to its sheet's; a bad cost model is
//! refused naming the field.
#![cfg(not(target_arch = "wasm32"))]

use std::path::PathBuf;

fn kerfcam(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .args(args)
        .output()
        .expect("kerfcam runs")
}

fn rect(x: f64, y: f64, w: f64, h: f64) -> String {
    let mut e = "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n".to_string();
    for (px, py) in [(x, y), (x + w, y), (x + w, y + h), (x, y + h)] {
        e += &format!("10\n{px}\n20\n{py}\n");
    }
    e
}

/// A 100 × 50 plate with a 20 × 10 hole, in mm: 4800 mm².
fn plate() -> Vec<u8> {
    format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{}{}0\nENDSEC\n0\nEOF\n",
        rect(0.0, 0.0, 100.0, 50.0),
        rect(40.0, 20.0, 20.0, 10.0)
    )
    .into_bytes()
}

const MODEL: &str = r#"{"currency": "EUR", "machine_per_hour": 90, "per_pierce": 0.05,
  "per_metre": 0.2, "material_per_m2": 40, "setup_per_sheet": 10, "markup_percent": 20}"#;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("kerfcam-quote-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The CSV's rows, cells split on commas (the rows read here hold none quoted).
fn rows(csv: &str) -> Vec<Vec<String>> {
    csv.split("\r\n")
        .filter(|r| !r.is_empty())
        .map(|r| r.split(',').map(str::to_string).collect())
        .collect()
}

fn col(header: &[String], name: &str) -> usize {
    header.iter().position(|h| h == name).expect(name)
}

#[test]
fn a_one_part_quote_worked_by_hand_equals_the_json_and_the_csv() {
    let d = dir("one");
    let (dxf, cost, csv) = (d.join("plate.dxf"), d.join("shop.json"), d.join("q.csv"));
    std::fs::write(&dxf, plate()).unwrap();
    std::fs::write(&cost, MODEL).unwrap();
    let args = [
        dxf.to_str().unwrap(),
        "--pierce-delay",
        "0.5",
        "--cost",
        cost.to_str().unwrap(),
    ];
    let o = kerfcam(&[&args[..], &["--quote", csv.to_str().unwrap(), "--json"]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The plan the command made, made again with the same settings.
    let spec = kerfcam::Spec {
        pierce_delay: Some(0.5),
        ..Default::default()
    };
    let out = kerfcam::run(&plate(), &spec.build().unwrap()).unwrap();
    let st = out.plan.stats();
    let time = st.est_time_s(&out.process);
    let metres = (st.cut_length + st.lead_length) / 1000.0;
    assert_eq!(st.pierces, 2);
    let cost = 90.0 * time / 3600.0 + 2.0 * 0.05 + metres * 0.2 + 4800.0 / 1e6 * 40.0 + 10.0;
    let price = cost * 1.2;

    let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let q = &report["quote"];
    assert_eq!(q["currency"], "EUR");
    assert_eq!(q["material_share"], "area");
    let job = &q["job"];
    assert!(
        (job["price"].as_f64().unwrap() - price).abs() < 1e-9,
        "{job} vs {price}"
    );
    assert!((job["time_s"].as_f64().unwrap() - time).abs() < 1e-9);
    assert_eq!(q["parts"][0]["name"], "plate#1");
    assert_eq!(q["parts"][0]["quantity"], 1);

    let text = std::fs::read_to_string(&csv).unwrap();
    let r = rows(&text);
    let h = &r[0];
    let part = r.iter().find(|r| r[0] == "part").unwrap();
    let job = r.iter().find(|r| r[0] == "job").unwrap();
    let num = |row: &Vec<String>, c: &str| row[col(h, c)].parse::<f64>().unwrap();
    assert_eq!(part[col(h, "name")], "plate#1");
    assert_eq!(num(part, "quantity"), 1.0);
    assert_eq!(num(part, "pierces"), 2.0);
    assert!((num(part, "cut_m") - metres).abs() < 5e-4);
    assert!((num(part, "time_s") - time).abs() < 0.05);
    assert!(
        (num(job, "price") - price).abs() < 0.005,
        "{job:?} vs {price}"
    );
    assert_eq!(job[col(h, "currency")], "EUR");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn quote_locale_pt_br_writes_semicolons_and_decimal_commas_with_the_same_figures() {
    let d = dir("locale");
    let (dxf, cost) = (d.join("plate.dxf"), d.join("shop.json"));
    let (en, pt) = (d.join("en.csv"), d.join("pt.csv"));
    std::fs::write(&dxf, plate()).unwrap();
    std::fs::write(&cost, MODEL).unwrap();
    let base = [dxf.to_str().unwrap(), "--cost", cost.to_str().unwrap(), "-o"];
    let ngc = d.join("p.ngc");
    let ngc = ngc.to_str().unwrap();
    let o = kerfcam(&[&base[..], &[ngc, "--quote", en.to_str().unwrap()]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = kerfcam(
        &[&base[..], &[ngc, "--quote", pt.to_str().unwrap(), "--quote-locale", "pt-BR"]].concat(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let en = rows(&std::fs::read_to_string(&en).unwrap());
    let text = std::fs::read_to_string(&pt).unwrap();
    let text = text.strip_prefix('\u{feff}').expect("a byte order mark");
    let pt: Vec<Vec<String>> = text
        .split("\r\n")
        .filter(|r| !r.is_empty())
        .map(|r| r.split(';').map(str::to_string).collect())
        .collect();
    assert_eq!(pt[0][..3], ["tipo", "nome", "quantidade"]);
    let (e, p) = (&en[en.len() - 4], &pt[pt.len() - 4]);
    assert_eq!((e[0].as_str(), p[0].as_str()), ("job", "trabalho"), "{en:?} {pt:?}");
    for k in 2..17 {
        assert!(!p[k].contains('.'), "{p:?}");
        assert_eq!(e[k], p[k].replace(',', "."), "{}", en[0][k]);
    }
    // Not a convention: refused, naming the option.
    let o = kerfcam(&[&base[..], &[ngc, "--quote", "x.csv", "--quote-locale", "de"]].concat());
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--quote-locale"));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_nests_copies_share_its_sheet_time_and_material() {
    let d = dir("nest");
    let (dxf, cost, csv) = (d.join("plate.dxf"), d.join("shop.json"), d.join("q.csv"));
    std::fs::write(&dxf, plate()).unwrap();
    let model = MODEL.replace(
        "\"material_per_m2\": 40",
        "\"material_per_kg\": 1.4, \"density_g_cm3\": 7.85, \"thickness_mm\": 3, \"scrap_per_kg\": 0.15, \"material_share\": \"sheet\"",
    );
    std::fs::write(&cost, model).unwrap();
    let part = format!("{}:3", dxf.display());
    let o = kerfcam(&[
        "nest",
        &part,
        "--sheet",
        "400x300",
        "--time",
        "0",
        "--cost",
        cost.to_str().unwrap(),
        "--quote",
        csv.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let q = &report["quote"];
    let copies = q["copies"].as_array().unwrap();
    assert_eq!(copies.len(), 3);
    let sum = |k: &str| copies.iter().map(|c| c[k].as_f64().unwrap()).sum::<f64>();
    let sheet = &q["sheets"][0];
    let f = |k: &str| sheet[k].as_f64().unwrap();
    assert!(
        (sum("time_s") - f("time_s")).abs() < 1e-9,
        "{} vs {}",
        sum("time_s"),
        f("time_s")
    );
    assert!((sum("material_m2") - f("used_m2")).abs() < 1e-9);
    assert!(sum("scrap_credit") > 0.0);
    // The sheet used: the whole sheet, or up to the crop line.
    let s = &report["sheets"][0];
    let width = s["crop_x"].as_f64().unwrap_or(s["width"].as_f64().unwrap());
    assert!((f("used_m2") - width * s["height"].as_f64().unwrap() / 1e6).abs() < 1e-12);
    let r = rows(&std::fs::read_to_string(&csv).unwrap());
    let h = &r[0];
    let part = r.iter().find(|r| r[0] == "part").unwrap();
    assert_eq!(part[col(h, "quantity")], "3");
    assert_eq!(r.iter().filter(|r| r[0] == "sheet").count(), 1);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_bad_cost_model_is_refused_naming_the_field() {
    let d = dir("bad");
    let (dxf, cost) = (d.join("plate.dxf"), d.join("shop.json"));
    std::fs::write(&dxf, plate()).unwrap();
    std::fs::write(
        &cost,
        MODEL.replace("\"per_pierce\": 0.05", "\"per_pierce\": -1"),
    )
    .unwrap();
    let o = kerfcam(&[dxf.to_str().unwrap(), "--cost", cost.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("'per_pierce'") && err.contains("negative"),
        "{err}"
    );
    let o = kerfcam(&[dxf.to_str().unwrap(), "--quote", "x.csv"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--cost"));
    let _ = std::fs::remove_dir_all(&d);
}
