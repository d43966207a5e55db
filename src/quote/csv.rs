//! The quote as CSV (RFC 4180: comma-separated, `.` decimals, CRLF line
//! ends): a header, a row per part, a row per sheet, the job's row, then
//! the assumptions as `note` rows. Part names come from files, so they are
//! data: every text cell is quoted when it holds a comma, quote or line
//! break, and one that a spreadsheet would run as a formula (starting with
//! `=`, `+`, `-`, `@`, a tab or a carriage return: OWASP's CSV injection
//! advice) is prefixed with `'`.

use super::{Figures, Quote};
use crate::quote::MaterialShare;

const HEADER: &str = "kind,name,quantity,cut_m,pierces,time_s,area_m2,material_m2,material_kg,\
material,machine,pierce_cost,cut_cost,sheet_share,scrap_credit,cost,price,currency";

/// `text` as one CSV cell: defused, then quoted when needed.
pub fn cell(text: &str) -> String {
    let defused = if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{text}")
    } else {
        text.to_string()
    };
    if defused.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", defused.replace('"', "\"\""))
    } else {
        defused
    }
}

fn row(out: &mut String, kind: &str, name: &str, qty: usize, f: &Figures, currency: &str) {
    let kg = f.material_kg.map_or(String::new(), |m| format!("{m:.3}"));
    out.push_str(&format!(
        "{kind},{},{qty},{:.3},{},{:.1},{:.6},{:.6},{kg},{:.2},{:.2},{:.2},{:.2},{:.2},{:.2},{:.2},{:.2},{}\r\n",
        cell(name),
        f.cut_m,
        f.pierces,
        f.time_s,
        f.area_m2,
        f.material_m2,
        f.material,
        f.machine,
        f.pierce_cost,
        f.cut_cost,
        f.sheet_share,
        f.scrap_credit,
        f.cost,
        f.price,
        cell(currency),
    ));
}

/// The quote as CSV text (English headers and notes: a file for other
/// programs).
pub fn to_csv(q: &Quote) -> String {
    let mut out = format!("{HEADER}\r\n");
    let cur = &q.currency;
    for p in &q.parts {
        row(&mut out, "part", &p.name, p.quantity, &p.figures, cur);
    }
    for s in &q.sheets {
        let name = format!("sheet {}", s.sheet);
        row(&mut out, "sheet", &name, s.copies, &s.figures, cur);
    }
    let copies = q.copies.len();
    row(&mut out, "job", "job", copies, &q.job, cur);
    let m = &q.model;
    let material = match q.model.material_share {
        MaterialShare::Area => "material: each part's own area (outline less holes)",
        MaterialShare::Sheet => "material: each part's share by area of the sheet used",
    };
    let price = match (m.material_per_kg, m.material_per_m2) {
        (Some(kg), _) => format!(
            "{kg} {cur}/kg, {} g/cm3, {} mm",
            m.density_g_cm3.unwrap_or(0.0),
            m.thickness_mm.unwrap_or(0.0)
        ),
        (None, Some(m2)) => format!("{m2} {cur}/m2"),
        (None, None) => String::new(),
    };
    let scrap = match m.scrap_per_kg {
        Some(s) => format!("{s} {cur}/kg"),
        None => "none".into(),
    };
    let notes = [
        format!("{material}, at {price}"),
        format!(
            "machine {} {cur}/h, {} {cur}/pierce, {} {cur}/m, setup {} {cur}/sheet, scrap credit {scrap}, markup {} %",
            m.machine_per_hour, m.per_pierce, m.per_metre, m.setup_per_sheet, m.markup_percent
        ),
        "time: the plan's estimate; a part's includes its share of its sheet's crop line; setup and the sheet's own cuts shared equally among the sheet's copies".into(),
    ];
    for n in notes
        .iter()
        .map(String::as_str)
        .chain(q.notes.iter().map(|t| t.en.as_str()))
    {
        out.push_str(&format!("note,{}\r\n", cell(n)));
    }
    out
}
