//! Sheets at a cost (issue 44 item 3): the CLI and the page take the same
//! cheapest combination. The job and the CLI's answer are one file,
//! tests/golden/nest-cost-squares.json: this test runs `kerfcam nest
//! --sheet WxH:N:COST … --json` on its job and compares the answer with
//! the file's `nest`; tests/wasm/nest.test.mjs runs the page's nester on
//! the same job (in one worker, and trial by trial as a team does) and
//! compares with the same `nest`, its quote (`--cost`, the job's
//! `cost_model`) with the page's. `BLESS=1 cargo test
//! --test it nest_cost` rewrites `nest` (look at the diff: a new choice of
//! sheets is a change of behaviour, not of numbers).
#![cfg(not(target_arch = "wasm32"))]

use std::path::PathBuf;

use crate::common;

fn golden() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/golden/nest-cost-squares.json")
}

/// The answer's fields the page must give alike: the choice, its cost,
/// the combinations passed over, the sheets, every placement and the
/// quote at the job's `cost_model` (its material the sheets' cost).
const SAME: [&str; 6] = [
    "stock",
    "sheet_cost",
    "combinations_passed_over",
    "sheets",
    "placements",
    "quote",
];

#[test]
fn the_cli_takes_the_cheapest_combination_the_page_is_checked_against() {
    let path = golden();
    let mut file: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    let job = &file["job"];
    let part = common::out_dir().join(format!("{}.dxf", job["name"].as_str().unwrap()));
    std::fs::write(&part, job["dxf"].as_str().unwrap()).unwrap();
    let mut args = vec![
        "nest".to_string(),
        format!("{}:{}", part.display(), job["quantity"]),
    ];
    for s in job["sheet_list"].as_array().unwrap() {
        args.push("--sheet".into());
        args.push(format!(
            "{}x{}:{}:{}",
            s["width"], s["height"], s["count"], s["cost"]
        ));
    }
    for (flag, key) in [
        ("--margin", "margin"),
        ("--spacing", "spacing"),
        ("--evaluations", "max_evaluations"),
        ("--time", "time_s"),
        ("--seed", "seed"),
    ] {
        args.push(flag.into());
        args.push(job[key].to_string());
    }
    let model = common::out_dir().join("nest-cost-squares-model.json");
    std::fs::write(&model, job["cost_model"].to_string()).unwrap();
    args.push("--cost".into());
    args.push(model.display().to_string());
    args.push("--json".into());
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .args(&args)
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    // What the job is built to show: three cheaper combinations nested
    // first and passed over (see src/nest/stock_tests.rs), four small
    // sheets at 2 taken.
    assert_eq!(j["combinations_passed_over"], 3, "{out}");
    assert_eq!(j["sheet_cost"], 8.0, "{out}");
    assert_eq!(j["placed"], 4, "{out}");
    // The quote's material is the sheets the nest chose, at their cost.
    assert_eq!(j["quote"]["material_share"], "sheet_cost", "{out}");
    assert_eq!(j["quote"]["job"]["material"], 8.0, "{out}");
    let used: Vec<f64> = j["quote"]["sheets"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["material"].as_f64().unwrap())
        .collect();
    assert_eq!(used, [2.0; 4], "{out}");
    let got: serde_json::Map<String, serde_json::Value> = SAME
        .iter()
        .map(|&k| (k.to_string(), j[k].clone()))
        .collect();
    if std::env::var("BLESS").as_deref() == Ok("1") {
        file["nest"] = got.into();
        std::fs::write(&path, serde_json::to_string_pretty(&file).unwrap() + "\n").unwrap();
        return;
    }
    for k in SAME {
        assert_eq!(
            j[k],
            file["nest"][k],
            "{k} differs from {} (BLESS=1 rewrites it)",
            path.display()
        );
    }
}
