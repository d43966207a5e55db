use super::*;
use crate::plan::Order;
use crate::test_dxf::{file, rect};
use crate::Settings;

fn model() -> CostModel {
    CostModel {
        currency: "EUR".into(),
        machine_per_hour: 90.0,
        per_pierce: 0.05,
        per_metre: 0.2,
        material_per_kg: None,
        material_per_m2: Some(40.0),
        density_g_cm3: None,
        thickness_mm: None,
        scrap_per_kg: None,
        setup_per_sheet: 10.0,
        markup_percent: 20.0,
        material_share: MaterialShare::Area,
    }
}

fn cut(dxf: &[u8], order: Order) -> Output {
    let s = Settings::new(1.5, 0.001, 2000.0)
        .unwrap()
        .with_pierce_delay(0.5)
        .unwrap()
        .with_order(order)
        .unwrap();
    crate::run(dxf, &s).unwrap()
}

fn named(p: u32) -> String {
    format!("plate#{p}")
}

fn one(out: &Output, m: &CostModel) -> Quote {
    quote(
        m,
        &[SheetInput {
            out,
            used_area_mm2: None,
            cost: None,
        }],
        &named,
    )
    .unwrap()
}

#[test]
fn a_one_part_quote_is_the_hand_worked_sum() {
    // A 100 × 50 plate with a 20 × 10 hole: 4800 mm² of steel, 2 pierces.
    let out = cut(
        &file(&(rect(0.0, 0.0, 100.0, 50.0) + &rect(40.0, 20.0, 20.0, 10.0))),
        Order::Contour,
    );
    let q = one(&out, &model());
    let time = out.plan.est_time_s(&out.process);
    let st = out.plan.stats();
    let metres = (st.cut_length + st.lead_length) / 1000.0;
    assert_eq!(st.pierces, 2);
    let cost = 90.0 * time / 3600.0 + 2.0 * 0.05 + metres * 0.2 + 4800.0 / 1e6 * 40.0 + 10.0;
    let price = cost * 1.2;
    assert_eq!(q.parts.len(), 1);
    let p = &q.parts[0];
    assert_eq!(
        (p.name.as_str(), p.quantity, p.figures.pierces),
        ("plate#1", 1, 2)
    );
    assert!(
        (p.figures.area_m2 - 0.0048).abs() < 1e-9,
        "{}",
        p.figures.area_m2
    );
    assert!((p.figures.time_s - time).abs() < 1e-9);
    assert!(
        (p.figures.cost - cost).abs() < 1e-9,
        "{} vs {cost}",
        p.figures.cost
    );
    assert!((p.figures.price - price).abs() < 1e-9);
    assert!((q.job.price - price).abs() < 1e-9);
    assert_eq!(q.sheets[0].figures.price, q.job.price);
}

#[test]
fn per_kg_material_is_area_times_thickness_times_density() {
    let out = cut(&file(&rect(0.0, 0.0, 100.0, 100.0)), Order::Contour);
    let m = CostModel {
        material_per_kg: Some(2.0),
        material_per_m2: None,
        density_g_cm3: Some(7.85),
        thickness_mm: Some(3.0),
        ..model()
    };
    let q = one(&out, &m);
    // 10 000 mm² × 3 mm = 30 cm³ × 7.85 g/cm³ = 235.5 g.
    let kg = q.parts[0].figures.material_kg.unwrap();
    assert!((kg - 0.2355).abs() < 1e-12, "{kg}");
    assert!((q.parts[0].figures.material - 0.471).abs() < 1e-12);
}

fn assert_times_sum(out: &Output) {
    let q = one(out, &model());
    let sheet = out.plan.est_time_s(&out.process);
    let sum: f64 = q.copies.iter().map(|c| c.figures.time_s).sum();
    assert!(
        (sum - sheet).abs() < 1e-9 * sheet.max(1.0),
        "copies {sum} s, sheet {sheet} s"
    );
    assert!((q.sheets[0].figures.time_s - sheet).abs() < 1e-12);
    let cost: f64 = q.copies.iter().map(|c| c.figures.cost).sum();
    assert!((cost - q.sheets[0].figures.cost).abs() < 1e-9);
}

#[test]
fn copies_times_sum_to_the_sheets_in_every_order() {
    let parts: String = (0..4)
        .map(|i| {
            rect(i as f64 * 30.0, 0.0, 20.0, 20.0) + &rect(i as f64 * 30.0 + 5.0, 5.0, 5.0, 5.0)
        })
        .collect();
    for order in [Order::Contour, Order::Chained, Order::Eulerian] {
        let out = cut(&file(&parts), order);
        assert_eq!(one(&out, &model()).copies.len(), 4, "{order:?}");
        assert_times_sum(&out);
    }
}

#[test]
fn a_common_line_is_shared_equally_by_the_two_parts() {
    // Two equal squares a kerf apart: the line between them cut once.
    let out = cut(
        &file(&(rect(0.0, 0.0, 50.0, 50.0) + &rect(51.5, 0.0, 50.0, 50.0))),
        Order::Eulerian,
    );
    let shared: f64 = out
        .plan
        .common_line
        .iter()
        .map(|c| c.segment.length())
        .sum();
    assert!(shared > 40.0, "common line {shared} mm");
    assert_times_sum(&out);
    let sp = share::split(&out);
    let cut: Vec<f64> = sp.copies.values().map(|(s, _)| s.cut_length).collect();
    // Mirror images: each has three sides of its own and half the shared one.
    assert!((cut[0] - cut[1]).abs() < 1e-6, "{cut:?}");
    let total = out.plan.stats().cut_length;
    assert!((cut[0] + cut[1] - total).abs() < 1e-9, "{cut:?} of {total}");
    assert!((cut[0] - total / 2.0).abs() < 1e-6);
}

#[test]
fn links_belong_to_the_part_they_lead_into() {
    let parts: String = (0..3)
        .map(|i| rect(i as f64 * 25.0, 0.0, 20.0, 20.0))
        .collect();
    let out = cut(&file(&parts), Order::Chained);
    assert!(out.plan.stats().chains > 0, "not chained");
    let sp = share::split(&out);
    // One pierce for the chain: the first part's; the others' links are theirs.
    let pierces: Vec<usize> = sp.copies.values().map(|(s, _)| s.pierces).collect();
    assert_eq!(pierces.iter().sum::<usize>(), out.plan.pierces());
    assert_eq!(sp.sheet, PlanStats::default());
    let leads: f64 = sp.copies.values().map(|(s, _)| s.lead_length).sum();
    assert!((leads - out.plan.stats().lead_length).abs() < 1e-9);
}

#[test]
fn sheet_share_charges_the_used_sheet_and_credits_the_scrap() {
    let out = cut(
        &file(&(rect(0.0, 0.0, 100.0, 100.0) + &rect(150.0, 0.0, 100.0, 50.0))),
        Order::Contour,
    );
    let m = CostModel {
        material_per_kg: Some(2.0),
        material_per_m2: None,
        density_g_cm3: Some(8.0),
        thickness_mm: Some(1.0),
        scrap_per_kg: Some(0.5),
        material_share: MaterialShare::Sheet,
        ..model()
    };
    let used = 300.0 * 200.0;
    let q = quote(
        &m,
        &[SheetInput {
            out: &out,
            used_area_mm2: Some(used),
            cost: None,
        }],
        &named,
    )
    .unwrap();
    // 60 000 mm² split 2:1; 60 000 mm² × 1 mm × 8 g/cm³ = 0.48 kg.
    let charged: Vec<f64> = q.copies.iter().map(|c| c.figures.material_m2).collect();
    assert!((charged[0] - 0.04).abs() < 1e-12 && (charged[1] - 0.02).abs() < 1e-12);
    assert!((q.job.material - 0.48 * 2.0).abs() < 1e-12);
    // Scrap: 45 000 mm² of skeleton = 0.36 kg at 0.5.
    assert!(
        (q.job.scrap_credit - 0.18).abs() < 1e-12,
        "{}",
        q.job.scrap_credit
    );
    // On no sheet the sheet share is refused, naming the field.
    let e = quote(
        &m,
        &[SheetInput {
            out: &out,
            used_area_mm2: None,
            cost: None,
        }],
        &named,
    )
    .unwrap_err();
    assert_eq!(e.field, "material_share");
}

/// Sheets at a cost (issue 44): a sheet's cost is its material, whole,
/// shared by its copies' areas.
#[test]
fn sheets_at_a_cost_are_the_material_shared_by_area() {
    let out = cut(
        &file(&(rect(0.0, 0.0, 100.0, 100.0) + &rect(150.0, 0.0, 100.0, 50.0))),
        Order::Contour,
    );
    let small = cut(&file(&rect(0.0, 0.0, 1.0, 1.0)), Order::Contour);
    let m = CostModel {
        material_per_kg: Some(2.0),
        material_per_m2: None,
        density_g_cm3: Some(8.0),
        thickness_mm: Some(1.0),
        ..model()
    };
    let sheet = |out, cost| SheetInput {
        out,
        used_area_mm2: Some(300.0 * 200.0),
        cost: Some(cost),
    };
    let q = quote(&m, &[sheet(&out, 12.0)], &named).unwrap();
    assert_eq!(q.material_share, "sheet_cost");
    let material: Vec<f64> = q.copies.iter().map(|c| c.figures.material).collect();
    assert!(
        (material[0] - 8.0).abs() < 1e-12 && (material[1] - 4.0).abs() < 1e-12,
        "{material:?}"
    );
    assert!((q.job.material - 12.0).abs() < 1e-12);
    // The kg charged are the sheet's, as with the sheet's share.
    assert!((q.job.material_kg.unwrap() - 0.48).abs() < 1e-12);
    assert!(
        q.notes[0].en.contains("(12.00 EUR in all)"),
        "{}",
        q.notes[0].en
    );
    assert!(
        q.notes[0].pt.contains("(12,00 EUR ao todo)"),
        "{}",
        q.notes[0].pt
    );
    assert!(to_csv(&q).contains("material: the cost of each sheet the nest chose"));
    // The same sheet priced by the model instead: the parts' own
    // 15 000 mm², 0.12 kg at 2.
    let by_model = quote(
        &m,
        &[SheetInput {
            cost: None,
            ..sheet(&out, 0.0)
        }],
        &named,
    )
    .unwrap();
    assert!(
        (by_model.job.material - 0.24).abs() < 1e-12,
        "{}",
        by_model.job.material
    );
    assert_ne!(by_model.material_share, "sheet_cost");
    // A second sheet holding one small part: the sheet's whole cost is
    // that part's material.
    let two = quote(&m, &[sheet(&out, 12.0), sheet(&small, 5.0)], &named).unwrap();
    assert!(
        (two.job.material - 17.0).abs() < 1e-12,
        "{}",
        two.job.material
    );
}

#[test]
fn scrap_credit_by_part_area_is_said_not_applied() {
    let out = cut(&file(&rect(0.0, 0.0, 10.0, 10.0)), Order::Contour);
    let m = CostModel {
        scrap_per_kg: Some(0.2),
        density_g_cm3: Some(7.85),
        thickness_mm: Some(2.0),
        ..model()
    };
    let q = one(&out, &m);
    assert_eq!(q.job.scrap_credit, 0.0);
    assert!(
        q.notes[0].en.contains("scrap credit not applied"),
        "{:?}",
        q.notes
    );
}

#[test]
fn bad_model_fields_are_refused_by_name() {
    let field = |m: CostModel| m.validate().unwrap_err().field;
    assert_eq!(
        field(CostModel {
            per_pierce: -0.1,
            ..model()
        }),
        "per_pierce"
    );
    assert_eq!(
        field(CostModel {
            machine_per_hour: f64::NAN,
            ..model()
        }),
        "machine_per_hour"
    );
    assert_eq!(
        field(CostModel {
            markup_percent: f64::INFINITY,
            ..model()
        }),
        "markup_percent"
    );
    assert_eq!(
        field(CostModel {
            currency: " ".into(),
            ..model()
        }),
        "currency"
    );
    assert_eq!(
        field(CostModel {
            material_per_kg: Some(1.0),
            ..model()
        }),
        "material_per_m2"
    );
    assert_eq!(
        field(CostModel {
            material_per_kg: Some(1.0),
            material_per_m2: None,
            ..model()
        }),
        "density_g_cm3"
    );
    assert_eq!(
        field(CostModel {
            material_per_m2: None,
            ..model()
        }),
        "material_per_kg"
    );
    assert_eq!(
        field(CostModel {
            thickness_mm: Some(0.0),
            ..model()
        }),
        "thickness_mm"
    );
    assert_eq!(
        field(CostModel {
            scrap_per_kg: Some(-1.0),
            ..model()
        }),
        "scrap_per_kg"
    );
    assert!(model().validate().is_ok());
    // From JSON: a missing field, an unknown one, not JSON at all.
    let json = serde_json::to_string(&model()).unwrap();
    assert_eq!(CostModel::from_json(&json).unwrap(), model());
    let missing = json.replace("\"per_metre\":0.2,", "");
    assert_eq!(
        CostModel::from_json(&missing).unwrap_err().field,
        "per_metre"
    );
    let typo = json.replace("per_metre", "per_meter");
    assert_eq!(CostModel::from_json(&typo).unwrap_err().field, "per_meter");
    assert_eq!(CostModel::from_json("{").unwrap_err().field, "json");
    let neg = json.replace("\"setup_per_sheet\":10.0", "\"setup_per_sheet\":-3");
    let e = CostModel::from_json(&neg).unwrap_err();
    assert_eq!(e.field, "setup_per_sheet");
    assert!(
        e.message(crate::warning::Lang::PtBr).contains("negativo"),
        "{e}"
    );
}

#[test]
fn csv_cells_are_escaped_and_defused() {
    assert_eq!(cell("bracket"), "bracket");
    assert_eq!(cell("a,b"), "\"a,b\"");
    assert_eq!(cell("say \"hi\""), "\"say \"\"hi\"\"\"");
    assert_eq!(cell("two\nlines"), "\"two\nlines\"");
    assert_eq!(cell("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
    for evil in ["+1", "-2+3", "@SUM(A1)", "\tx", "\rx"] {
        assert!(
            cell(evil).trim_start_matches('"').starts_with('\''),
            "{evil:?}"
        );
    }
}

#[test]
fn the_csv_has_a_row_per_part_sheet_and_job() {
    let parts = rect(0.0, 0.0, 20.0, 20.0) + &rect(30.0, 0.0, 20.0, 20.0);
    let out = cut(&file(&parts), Order::Contour);
    let q = quote(
        &model(),
        &[SheetInput {
            out: &out,
            used_area_mm2: None,
            cost: None,
        }],
        &|p| format!("=evil,{p}"),
    )
    .unwrap();
    let csv = to_csv(&q);
    let rows: Vec<&str> = csv.split("\r\n").filter(|r| !r.is_empty()).collect();
    assert!(rows[0].starts_with("kind,name,quantity,cut_m"));
    assert_eq!(rows[1].split(',').next(), Some("part"));
    assert!(rows[1].starts_with("part,\"'=evil,1\",1,"), "{}", rows[1]);
    assert!(rows[3].starts_with("sheet,sheet 1,2,"), "{}", rows[3]);
    assert!(rows[4].starts_with("job,job,2,"), "{}", rows[4]);
    assert!(
        rows[4].ends_with(&format!("{:.2},EUR", q.job.price)),
        "{}",
        rows[4]
    );
    assert!(rows[5..].iter().all(|r| r.starts_with("note,")));
}

/// The cells of a CSV text, read by the RFC 4180 grammar with `sep`
/// (written here, apart from the writer).
fn parse_csv(text: &str, sep: char) -> Vec<Vec<String>> {
    let (mut rows, mut row, mut cell) = (Vec::new(), Vec::new(), String::new());
    let (mut quoted, mut chars) = (false, text.chars().peekable());
    while let Some(ch) = chars.next() {
        match (quoted, ch) {
            (true, '"') if chars.peek() == Some(&'"') => {
                chars.next();
                cell.push('"');
            }
            (true, '"') => quoted = false,
            (true, c) => cell.push(c),
            (false, '"') if cell.is_empty() => quoted = true,
            (false, c) if c == sep => row.push(std::mem::take(&mut cell)),
            (false, '\r') => {}
            (false, '\n') => {
                row.push(std::mem::take(&mut cell));
                rows.push(std::mem::take(&mut row));
            }
            (false, c) => cell.push(c),
        }
    }
    rows
}

#[test]
fn the_csv_reads_back_in_both_conventions_names_with_separators_and_quotes_included() {
    let parts = rect(0.0, 0.0, 20.0, 20.0) + &rect(30.0, 0.0, 20.0, 20.0) + &rect(60.0, 0.0, 20.0, 20.0);
    let out = cut(&file(&parts), Order::Contour);
    let names = ["a;b", "c,d", "say \"hi\""];
    let q = quote(
        &model(),
        &[SheetInput {
            out: &out,
            used_area_mm2: None,
            cost: None,
        }],
        &|p| names[p as usize - 1].to_owned(),
    )
    .unwrap();
    let price = |v: f64| format!("{v:.2}");
    // RFC 4180, the CLI's default: unchanged, `,` and `.`.
    assert_eq!(to_csv(&q), to_csv_in(&q, Convention::Rfc4180));
    let en = parse_csv(&to_csv(&q), ',');
    assert_eq!(en[0][..3], ["kind", "name", "quantity"]);
    assert!(en.iter().all(|r| r.len() == 18 || r[0] == "note"), "{en:?}");
    let mut got: Vec<&str> = en[1..4].iter().map(|r| r[1].as_str()).collect();
    got.sort();
    assert_eq!(got, ["a;b", "c,d", "say \"hi\""]);
    let job = en.iter().find(|r| r[0] == "job").unwrap();
    assert_eq!(job[16], price(q.job.price));
    // pt-BR: `;` and `,`, Portuguese, a byte order mark.
    let text = to_csv_in(&q, Convention::PtBr);
    let body = text.strip_prefix('\u{feff}').expect("a byte order mark");
    let pt = parse_csv(body, ';');
    assert_eq!(pt[0][..3], ["tipo", "nome", "quantidade"]);
    assert!(pt.iter().all(|r| r.len() == 18 || r[0] == "nota"), "{pt:?}");
    let mut got: Vec<&str> = pt[1..4].iter().map(|r| r[1].as_str()).collect();
    got.sort();
    assert_eq!(got, ["a;b", "c,d", "say \"hi\""]);
    assert!(pt[1..4].iter().all(|r| r[0] == "peça"));
    let job = pt.iter().find(|r| r[0] == "trabalho").unwrap();
    assert_eq!(job[16], price(q.job.price).replace('.', ","));
    assert_eq!(job[3], format!("{:.3}", q.job.cut_m).replace('.', ","));
    // Every figure reads back as the same number in both.
    let en_job = en.iter().find(|r| r[0] == "job").unwrap();
    for k in 2..17 {
        if en_job[k].is_empty() && job[k].is_empty() {
            continue; // material_kg: priced per m²
        }
        let a: f64 = en_job[k].parse().unwrap();
        let b: f64 = job[k].replace(',', ".").parse().unwrap();
        assert_eq!(a, b, "column {}", en[0][k]);
        assert!(!job[k].contains('.'), "{}", job[k]);
    }
    assert!(pt.iter().filter(|r| r[0] == "nota").all(|r| r.len() == 2));
}
