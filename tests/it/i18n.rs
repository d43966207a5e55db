//! Messages in English and Brazilian Portuguese: every warning of the corpus
//! and every error kind renders in both, filled (no `{}` left), and the
//! Portuguese is not the English again. Scripts get a stable `code`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use std::collections::BTreeMap;
use std::path::Path;

use common::{fixture, kerf};
use kerfcam::gcode::Post;
use kerfcam::plan::Order;
use kerfcam::report::Report;
use kerfcam::warning::{Lang, Text};
use kerfcam::{Output, Settings};

/// A filled, one-line message.
fn check_filled(m: &str, what: &str) {
    assert!(!m.trim().is_empty(), "{what}: empty message");
    assert!(
        !m.contains("{}") && !m.contains("{:"),
        "{what}: unfilled placeholder in {m:?}"
    );
    assert!(!m.contains('\n'), "{what}: message on several lines: {m:?}");
}

/// Words that may stay the same in both languages: numbers, names in capitals
/// (LINE, $INSUNITS, G2), units, quoted file text.
fn language_neutral(m: &str) -> bool {
    let unquoted: String = m.split('\'').step_by(2).collect();
    unquoted
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| !w.is_empty())
        .all(|w| {
            w.chars().all(|c| c.is_ascii_digit())
                || w.chars().all(|c| !c.is_lowercase())
                || ["mm", "in", "x"].contains(&w)
        })
}

/// A decimal point outside quotes (quoted text is the file's own).
fn decimal_point(m: &str) -> bool {
    let unquoted: Vec<char> = m
        .split('\'')
        .step_by(2)
        .collect::<String>()
        .chars()
        .collect();
    unquoted
        .windows(3)
        .any(|w| w[0].is_ascii_digit() && w[1] == '.' && w[2].is_ascii_digit())
}

/// A decimal comma outside quotes (`12,5`; a list is `12, 5`).
fn decimal_comma(m: &str) -> bool {
    let unquoted: Vec<char> = m
        .split('\'')
        .step_by(2)
        .collect::<String>()
        .chars()
        .collect();
    unquoted
        .windows(3)
        .any(|w| w[0].is_ascii_digit() && w[1] == ',' && w[2].is_ascii_digit())
}

fn check_text(t: &Text, what: &str) {
    check_filled(&t.en, what);
    check_filled(&t.pt, what);
    assert!(
        !decimal_comma(&t.en),
        "{what}: a decimal comma in the English: {:?}",
        t.en
    );
    assert!(
        !decimal_point(&t.pt),
        "{what}: a decimal point in the Portuguese: {:?}",
        t.pt
    );
    assert!(
        t.en != t.pt || language_neutral(&t.en),
        "{what}: the Portuguese is the English: {:?}",
        t.en
    );
}

/// Settings that make each order and lead talk.
fn variants() -> Vec<Settings> {
    let with = |order: Order, cut_open: bool, width: f64| {
        kerf(width)
            .map_plan(|p| {
                p.order = order;
                p.cut_open = cut_open;
            })
            .unwrap()
    };
    // The contour order at 1.5 mm is the shared corpus run's (common::corpus_runs).
    vec![
        with(Order::Chained, true, 6.0),
        with(Order::Eulerian, false, 1.5),
        with(Order::Drawing, true, 1.5),
    ]
}

#[test]
fn every_corpus_warning_is_in_both_languages() {
    let fixtures = [
        "seed000-figure1.dxf",
        "seed000-plate-6-holes.dxf",
        "seed001-P51703.dxf",
        "seed002-figure4.dxf",
        "seed003-grid-3x2.dxf",
    ]
    .map(fixture);
    assert!(
        common::corpus_runs().len() > 5,
        "no corpus at ../shared/corpus"
    );
    let mut codes: BTreeMap<&'static str, usize> = BTreeMap::new();
    let mut check = |f: &Path, out: &Result<Output, kerfcam::Error>| {
        let Ok(out) = out else {
            return;
        };
        for w in out.warnings() {
            let what = format!("{} [{}]", f.display(), w.code);
            assert!(
                !w.code.is_empty() && w.code.chars().all(|c| c.is_ascii_lowercase() || c == '-'),
                "{what}: code must be kebab-case"
            );
            check_text(&w.text, &what);
            *codes.entry(w.code).or_default() += 1;
        }
        // The report in Portuguese carries the Portuguese message, the code and both texts.
        let report: serde_json::Value =
            serde_json::from_str(&Report::in_lang(out, Lang::PtBr).to_json()).unwrap();
        for (w, r) in out.warnings().zip(report["warnings"].as_array().unwrap()) {
            assert_eq!(r["code"], w.code);
            assert_eq!(r["message"], w.text.pt.as_str());
            assert_eq!(r["messages"]["en"], w.text.en.as_str());
            assert_eq!(r["messages"]["pt-BR"], w.text.pt.as_str());
        }
    };
    // The contour order at 1.5 mm: the corpus's shared run, and the fixtures.
    for r in common::corpus_runs() {
        check(&r.path, &r.out);
    }
    for f in &fixtures {
        check(f, &common::run(f, &common::corpus_settings()));
    }
    // The others, shared with the tests that sweep the corpus in the same
    // settings (the language is the report's: Report::in_lang).
    for settings in variants() {
        for r in common::corpus_runs_with(&settings) {
            check(&r.path, &r.out);
        }
        for f in &fixtures {
            check(f, &common::run(f, &settings));
        }
    }
    eprintln!("warning codes seen: {codes:?}");
    // The corpus is varied enough to reach most kinds; fewer means the runs stopped talking.
    assert!(
        codes.len() >= 10,
        "only {} warning kinds seen: {codes:?}",
        codes.len()
    );
}

#[test]
fn english_stays_the_default() {
    let out = common::run(&fixture("seed000-plate-6-holes.dxf"), &kerf(1.5)).unwrap();
    let report: serde_json::Value = serde_json::from_str(&Report::new(&out).to_json()).unwrap();
    for (w, r) in out.warnings().zip(report["warnings"].as_array().unwrap()) {
        assert_eq!(r["message"], w.message());
    }
    assert_eq!(kerf(1.5).lang(), Lang::En);
}

#[test]
fn synthetic_warnings_are_in_both_languages() {
    // No units, an unknown entity, a paper-space line, an undefined block.
    let dxf = "0\nSECTION\n2\nENTITIES\n\
        0\nLINE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n\
        0\nTEXT\n8\n0\n10\n0\n20\n0\n1\nhi\n\
        0\nLINE\n67\n1\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n\
        0\nINSERT\n8\n0\n2\nNOPE\n10\n0\n20\n0\n\
        0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n-1\n\
        0\nENDSEC\n0\nEOF\n";
    let out = kerfcam::run(dxf.as_bytes(), &kerf(1.5)).unwrap();
    let codes: Vec<&str> = out.warnings().map(|w| w.code).collect();
    for code in [
        "units-assumed",
        "entities-not-cut",
        "paper-space",
        "block-undefined",
        "entity-skipped",
    ] {
        assert!(codes.contains(&code), "{code} not in {codes:?}");
    }
    for w in out.warnings() {
        check_text(&w.text, w.code);
    }
    let units = out.warnings().find(|w| w.code == "units-assumed").unwrap();
    assert!(
        units.message_in(Lang::PtBr).contains("unidades"),
        "{units:?}"
    );
}

#[test]
fn every_error_kind_is_in_both_languages() {
    let mut errors: Vec<(String, Text)> = Vec::new();
    let mut job_error = |name: &str, bytes: &[u8], settings: &Settings| {
        let e = kerfcam::run(bytes, settings)
            .err()
            .unwrap_or_else(|| panic!("{name}: no error"));
        errors.push((
            name.into(),
            Text::new(e.message(Lang::En), e.message(Lang::PtBr)),
        ));
        assert_eq!(
            e.message(Lang::En),
            e.to_string(),
            "{name}: Display is the English"
        );
    };
    job_error("empty", b"", &kerf(1.5));
    job_error("not dxf", b"hello\nworld\n", &kerf(1.5));
    job_error("malformed", b"0\nSECTION\n2\nENTITIES\nxyz\n", &kerf(1.5));
    let mut push = |name: &str, t: Text| errors.push((name.into(), t));
    push(
        "settings range",
        Settings::new(-1.0, 0.001, 100.0).unwrap_err().text(),
    );
    push(
        "tolerance range",
        Settings::new(1.0, 2.5, 100.0).unwrap_err().text(),
    );
    push("decimals", kerf(1.5).with_decimals(9).unwrap_err().text());
    let bad_posts = [
        r#"{"decimals": 9}"#,
        r#"{"colour": 1}"#,
        r#"{"max_arc_sweep_deg": 270}"#,
        r#"{"header": ["F{layer}"]}"#,
        r#"{"header": ["F{feed"]}"#,
        r#"{"header": ["F}"]}"#,
        r#"{"name": "é"}"#,
        r#"{"rapid": "0G"}"#,
        r#"{"rapid_speed": 0}"#,
        r#"{"footer": ["M5"]}"#,
        r#"{"torch_off": []}"#,
        r#"{"line_numbers": {"start": 1, "step": 0, "width": 0}}"#,
    ];
    for json in bad_posts {
        let e = Post::from_json(json).unwrap_err();
        push(json, e.text());
        assert_eq!(e.message(Lang::PtBr), e.text().pt);
    }
    let post = Post {
        decimals: 9,
        ..Post::default()
    };
    push("with_post", kerf(1.5).with_post(post).unwrap_err().text());
    for (name, t) in &errors {
        check_filled(&t.en, name);
        check_filled(&t.pt, name);
        assert_ne!(t.en, t.pt, "{name}: not translated");
        assert!(
            !decimal_point(&t.pt),
            "{name}: a decimal point in {:?}",
            t.pt
        );
    }
    let malformed = &errors[2].1;
    assert!(malformed.pt.contains("linha"), "{malformed:?}");
}

#[test]
fn cli_speaks_portuguese_when_asked_and_writes_the_same_program() {
    let exe = env!("CARGO_BIN_EXE_kerfcam");
    let dir = std::env::temp_dir().join(format!("kerfcam-i18n-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let dxf = dir.join("nounits.dxf");
    std::fs::write(
        &dxf,
        "0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\n0\n10\n0\n20\n0\n40\n10\n0\nENDSEC\n0\nEOF\n",
    )
    .unwrap();
    let run = |lang: &str| {
        let out = std::process::Command::new(exe)
            .arg(&dxf)
            .args(["--lang", lang])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{lang}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        (out.stdout, String::from_utf8(out.stderr).unwrap())
    };
    let (gcode_en, err_en) = run("en");
    let (gcode_pt, err_pt) = run("pt-BR");
    assert_eq!(gcode_en, gcode_pt, "the program changed with the language");
    assert!(
        err_en.contains("warning: units assumed: the file does not state its units"),
        "{err_en}"
    );
    assert!(
        err_pt.contains("aviso: unidades supostas: o arquivo não informa suas unidades"),
        "{err_pt}"
    );
    // An error in Portuguese, and an unknown language refused.
    let bad = std::process::Command::new(exe)
        .arg(&dxf)
        .args(["--lang", "pt-BR", "--kerf", "-1"])
        .output()
        .unwrap();
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("não está entre"));
    let unknown = std::process::Command::new(exe)
        .arg(&dxf)
        .args(["--lang", "fr"])
        .output()
        .unwrap();
    assert!(!unknown.status.success());
    std::fs::remove_dir_all(&dir).ok();
}

/// A rectangle part for the nest's reasons below, not turned.
fn nest_rect(name: &str, w: f64, h: f64, quantity: usize) -> kerfcam::nest::Part {
    kerfcam::nest::Part {
        rotations: kerfcam::nest::Rotations::None,
        ..common::rect_part(name, w, h, quantity)
    }
}

#[test]
fn every_reason_a_copy_is_left_out_is_in_both_languages_and_the_json_speaks_the_one_asked() {
    use kerfcam::nest::{self, output, NestJob, NestSettings, SheetSize, Sheets};
    let settings = |margin: f64, evaluations: u64| NestSettings {
        spacing: 2.5,
        margin,
        tolerance: 0.05,
        time_s: 1e9,
        seed: 1,
        max_evaluations: Some(evaluations),
        budget_s: None,
    };
    let rect = |width, height, count| Sheets::Rect {
        width,
        height,
        count,
    };
    let parts = || {
        vec![
            nest_rect("big", 2000.5, 100.0, 2),
            nest_rect("small", 300.0, 200.0, 12),
            nest_rect("none", 10.0, 10.0, 0),
        ]
    };
    let jobs = [
        // Larger than the sheet (the strip, every size), no room left on
        // it, quantity 0.
        (parts(), rect(1000.0, 500.0, 1), settings(5.0, 200), 3),
        (
            parts(),
            Sheets::Strip { height: 180.5 },
            settings(5.0, 200),
            2,
        ),
        (
            parts(),
            Sheets::Mixed(vec![SheetSize {
                width: 1000.0,
                height: 500.0,
                count: 9,
            }]),
            settings(5.0, 200),
            2,
        ),
        // A remnant with no room inside its margin.
        (
            parts(),
            Sheets::Remnant {
                outline: nest_rect("r", 100.0, 100.0, 1).outer,
                no_go: vec![],
            },
            settings(60.5, 200),
            3,
        ),
        // The budget came before the first nest placed every copy.
        (
            vec![nest_rect("small", 30.0, 20.0, 12)],
            rect(1000.0, 500.0, 1),
            settings(5.0, 4),
            1,
        ),
    ];
    let mut seen = 0;
    for (k, (parts, sheets, settings, reasons)) in jobs.into_iter().enumerate() {
        let job = NestJob {
            parts,
            sheets,
            settings,
        };
        let n = nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
        assert_eq!(n.unplaced.len(), reasons, "job {k}: {:?}", n.unplaced);
        for lang in Lang::ALL {
            let json = output::to_json(&job, &n, 0.0, lang);
            for (u, j) in n.unplaced.iter().zip(json["unplaced"].as_array().unwrap()) {
                assert_eq!(j["reason"], u.reason.get(lang), "job {k}");
            }
        }
        for u in &n.unplaced {
            check_text(&u.reason, &format!("job {k}, {}", u.part));
            seen += 1;
        }
    }
    // Open outlines are not nested, said in both languages too.
    let bytes = std::fs::read(fixture("seed002-figure4.dxf")).unwrap();
    let d = kerfcam::dxf::parse(&bytes, &kerfcam::dxf::ReadOptions::DEFAULT).unwrap();
    let c = kerfcam::contour::extract(&d, kerfcam::geom::Tolerance::DEFAULT, 0.05);
    let (_, notes) = nest::parts_from_contours(&c, "figure4", 1);
    assert!(!notes.is_empty());
    for u in &notes {
        check_text(&u.reason, "open outlines");
    }
    assert_eq!(seen, 11);
}

#[test]
fn every_nest_setting_refused_is_said_in_both_languages() {
    use kerfcam::nest::torches::nest_torches;
    use kerfcam::nest::{self, NestError, NestJob, NestSettings, SheetSize, Sheets};
    use kerfcam::process::Torches;
    let settings = NestSettings {
        spacing: 2.5,
        margin: 5.0,
        tolerance: 0.05,
        time_s: 1e9,
        seed: 1,
        max_evaluations: Some(10),
        budget_s: None,
    };
    let rect = |width, height, count| Sheets::Rect {
        width,
        height,
        count,
    };
    let job = |settings: NestSettings, sheets: Sheets| NestJob {
        parts: vec![nest_rect("a", 100.0, 50.0, 2)],
        sheets,
        settings,
    };
    let sheet = rect(1000.0, 500.0, 1);
    let mut jobs = vec![
        (
            "spacing",
            job(
                NestSettings {
                    spacing: -1.5,
                    ..settings.clone()
                },
                sheet.clone(),
            ),
        ),
        (
            "tolerance",
            job(
                NestSettings {
                    tolerance: 0.0,
                    ..settings.clone()
                },
                sheet.clone(),
            ),
        ),
        ("sheet size", job(settings.clone(), rect(0.0, 500.5, 1))),
        ("sheet count", job(settings.clone(), rect(1000.0, 500.0, 0))),
        (
            "sizes",
            job(
                settings.clone(),
                Sheets::Mixed(vec![SheetSize {
                    width: 1000.0,
                    height: 500.0,
                    count: 0,
                }]),
            ),
        ),
        (
            "strip",
            job(settings.clone(), Sheets::Strip { height: -1.5 }),
        ),
    ];
    let remnant = nest_rect("r", 10.0, 0.0, 1).outer;
    jobs.push((
        "remnant",
        job(
            settings.clone(),
            Sheets::Remnant {
                outline: remnant,
                no_go: vec![],
            },
        ),
    ));
    let mut said: Vec<(String, Text)> = Vec::new();
    for (name, j) in &jobs {
        let e = nest::nest(j, &|| 0.0, &mut |_| true).unwrap_err();
        assert!(matches!(e, NestError::Setting { .. }), "{name}: {e:?}");
        said.push((name.to_string(), e.text()));
    }
    // The torches (Sheet mode's fields): too many for the sheet, closer
    // than the parts, on a list of sizes.
    let torches = |n, d| Torches::new(n, d, None).unwrap().unwrap();
    for (name, j, t) in [
        (
            "torches past the sheet",
            job(settings.clone(), sheet.clone()),
            torches(3, 500.0),
        ),
        (
            "torches too close",
            job(settings.clone(), sheet.clone()),
            torches(2, 2.0),
        ),
        (
            "torches on sizes",
            job(
                settings.clone(),
                Sheets::Mixed(vec![SheetSize {
                    width: 1000.0,
                    height: 500.0,
                    count: 2,
                }]),
            ),
            torches(2, 200.0),
        ),
    ] {
        let e = nest_torches(&j, &t, &|| 0.0, &mut |_| true).unwrap_err();
        said.push((name.into(), e.text()));
    }
    for (name, t) in &said {
        check_text(t, name);
        assert_ne!(t.en, t.pt, "{name}: not translated");
    }
    assert_eq!(said.len(), 10);
    // Display stays the English (the CLI's errors, logs).
    let e = nest::nest(&jobs[0].1, &|| 0.0, &mut |_| true).unwrap_err();
    assert_eq!(e.to_string(), e.text().en);
}

#[test]
fn the_nest_cli_and_the_material_note_speak_the_language_asked() {
    let dir = common::out_dir().join("i18n-nest");
    std::fs::create_dir_all(&dir).unwrap();
    // Named square: the part is "square" in the lines asserted below.
    let square = dir.join("square.dxf");
    std::fs::write(
        &square,
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n\
         0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n0\n20\n0\n10\n60\n20\n0\n10\n60\n20\n60\n10\n0\n20\n60\n\
         0\nENDSEC\n0\nEOF\n",
    )
    .unwrap();
    // The command's standard error in `lang` (it must succeed).
    let stderr_of = |args: &[&str], lang: &str| {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
            .args(args)
            .args(["--lang", lang])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8(o.stderr).unwrap()
    };
    let path = square.to_str().unwrap();
    // One 60 mm square fits a 100 mm sheet (margin 5): the others are left
    // out, and the sheet's cost is reported.
    let nest = |lang: &str, q: usize| {
        let quantity = format!("{path}:{q}");
        let args = ["nest", &quantity, "--sheet", "100x100:1:7.5", "--time", "0"];
        stderr_of(&args, lang)
    };
    // One copy left out is one, not "1 copies".
    assert!(nest("en", 2).contains("not placed: square (1 copy): "));
    assert!(nest("pt-BR", 2).contains("não colocada: square (1 cópia): "));
    let (en, pt) = (nest("en", 3), nest("pt-BR", 3));
    for want in [
        "kerfcam nest: 1 placed on 1 sheet(s), density ",
        "sheets used: 1 x 100x100 at 7.5 = cost 7.5",
        "not placed: square (2 copies): ",
    ] {
        assert!(en.contains(want), "{want:?} in {en}");
    }
    for want in [
        "kerfcam nest: 1 cópia(s) colocada(s) em 1 chapa(s), densidade ",
        "chapas usadas: 1 x 100x100 a 7,5 = custo 7,5",
        "não colocada: square (2 cópias): ",
    ] {
        assert!(pt.contains(want), "{want:?} in {pt}");
    }
    for line in pt.lines() {
        assert!(
            !line.contains(" placed") && !line.contains("sheets used") && !decimal_point(line),
            "English or a decimal point in the pt-BR summary: {line}"
        );
    }
    // The cut-chart entry the CLI takes its kerf from.
    let run = |lang: &str| {
        stderr_of(
            &[path, "--material", "Mild steel 1.5 mm 45 A (example)"],
            lang,
        )
    };
    let (en, pt) = (run("en"), run("pt-BR"));
    assert!(
        en.contains("material: Mild steel 1.5 mm 45 A") && en.contains("(kerf "),
        "{en}"
    );
    assert!(
        pt.contains("(sangria 1,5 mm") && pt.contains("um exemplo: confira"),
        "{pt}"
    );
}
