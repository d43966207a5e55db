//! The quote as CSV, in one of two conventions ([`Convention`]):
//! - RFC 4180 (the CLI's default, and the page's in English): `,` between
//!   cells, `.` decimals, English headers and notes, CRLF line ends;
//! - the Brazilian one (the page in pt-BR, `kerfcam nest --quote-locale
//!   pt-BR`): `;` between cells and `,` decimals — what a spreadsheet set to
//!   Portuguese (Brazil) opens as columns of numbers, since there `,` is the
//!   decimal mark and `;` the list separator — Portuguese headers and notes,
//!   and a UTF-8 byte order mark, without which Excel reads the accents as
//!   Windows-1252.
//!
//! A header, a row per part, a row per sheet, the job's row, then the
//! assumptions as `note` rows. Part names come from files, so they are
//! data: every text cell is quoted when it holds the separator, a quote or
//! a line break, and one that a spreadsheet would run as a formula
//! (starting with `=`, `+`, `-`, `@`, a tab or a carriage return: OWASP's
//! CSV injection advice) is prefixed with `'`.

use super::{Figures, Quote};
use crate::quote::MaterialShare;
use crate::text;
use crate::warning::{Lang, Text};

/// How the cells are written: separator, decimal mark and language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Convention {
    /// RFC 4180: `,` and `.`, English.
    Rfc4180,
    /// Brazil's: `;` and `,`, Portuguese, with a byte order mark.
    PtBr,
}

impl Convention {
    /// The convention of a page or report in `lang`.
    pub fn of(lang: Lang) -> Convention {
        match lang {
            Lang::En => Convention::Rfc4180,
            Lang::PtBr => Convention::PtBr,
        }
    }
    /// The convention named `name` (`en`, `pt-BR`), for `--quote-locale`.
    pub fn from_name(name: &str) -> Option<Convention> {
        match name {
            "en" => Some(Convention::Rfc4180),
            "pt-BR" => Some(Convention::PtBr),
            _ => None,
        }
    }
    fn sep(self) -> char {
        match self {
            Convention::Rfc4180 => ',',
            Convention::PtBr => ';',
        }
    }
    fn lang(self) -> Lang {
        match self {
            Convention::Rfc4180 => Lang::En,
            Convention::PtBr => Lang::PtBr,
        }
    }
    /// `v` with `decimals` decimals and this convention's decimal mark.
    fn num(self, v: f64, decimals: usize) -> String {
        let s = format!("{v:.decimals$}");
        match self {
            Convention::Rfc4180 => s,
            Convention::PtBr => s.replace('.', ","),
        }
    }
}

const HEADER: [&str; 18] = [
    "kind", "name", "quantity", "cut_m", "pierces", "time_s", "area_m2", "material_m2",
    "material_kg", "material", "machine", "pierce_cost", "cut_cost", "sheet_share",
    "scrap_credit", "cost", "price", "currency",
];
/// [`HEADER`] in Portuguese, the page's terms (cost.js).
const HEADER_PT: [&str; 18] = [
    "tipo", "nome", "quantidade", "corte_m", "perfurações", "tempo_s", "área_m2", "material_m2",
    "material_kg", "material", "máquina", "custo_perfurações", "custo_corte", "parte_chapa",
    "crédito_sucata", "custo", "preço", "moeda",
];

/// `text` as one RFC 4180 CSV cell: defused, then quoted when needed.
pub fn cell(text: &str) -> String {
    cell_in(text, ',')
}

/// `text` as one cell between `sep`s.
fn cell_in(text: &str, sep: char) -> String {
    let defused = if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{text}")
    } else {
        text.to_string()
    };
    if defused.contains([sep, '"', '\n', '\r']) {
        format!("\"{}\"", defused.replace('"', "\"\""))
    } else {
        defused
    }
}

/// One row of cells, with the line end.
fn line(out: &mut String, cells: &[String], c: Convention) {
    out.push_str(&cells.join(&c.sep().to_string()));
    out.push_str("\r\n");
}

#[allow(clippy::too_many_arguments)]
fn row(out: &mut String, kind: &str, name: &str, qty: usize, f: &Figures, cur: &str, c: Convention) {
    let n = |v: f64, d: usize| c.num(v, d);
    let sep = c.sep();
    let cells = [
        cell_in(kind, sep),
        cell_in(name, sep),
        qty.to_string(),
        n(f.cut_m, 3),
        f.pierces.to_string(),
        n(f.time_s, 1),
        n(f.area_m2, 6),
        n(f.material_m2, 6),
        f.material_kg.map_or(String::new(), |m| n(m, 3)),
        n(f.material, 2),
        n(f.machine, 2),
        n(f.pierce_cost, 2),
        n(f.cut_cost, 2),
        n(f.sheet_share, 2),
        n(f.scrap_credit, 2),
        n(f.cost, 2),
        n(f.price, 2),
        cell_in(cur, sep),
    ];
    line(out, &cells, c);
}

/// The quote as RFC 4180 CSV text (English headers and notes: a file for
/// other programs; `kerfcam nest --quote`'s default).
pub fn to_csv(q: &Quote) -> String {
    to_csv_in(q, Convention::Rfc4180)
}

/// The quote as CSV text in convention `c`.
pub fn to_csv_in(q: &Quote, c: Convention) -> String {
    let lang = c.lang();
    let sep = c.sep();
    let mut out = String::new();
    if c == Convention::PtBr {
        out.push('\u{feff}');
    }
    let header = match lang {
        Lang::En => HEADER,
        Lang::PtBr => HEADER_PT,
    };
    line(&mut out, &header.map(|h| cell_in(h, sep)), c);
    let cur = &q.currency;
    let word = |t: Text| t.get(lang).to_owned();
    let part = word(text!("part"; "peça"));
    for p in &q.parts {
        row(&mut out, &part, &p.name, p.quantity, &p.figures, cur, c);
    }
    let sheet = word(text!("sheet"; "chapa"));
    for s in &q.sheets {
        let name = format!("{sheet} {}", s.sheet);
        row(&mut out, &sheet, &name, s.copies, &s.figures, cur, c);
    }
    let job = word(text!("job"; "trabalho"));
    row(&mut out, &job, &job, q.copies.len(), &q.job, cur, c);
    let m = &q.model;
    let n = |v: f64| {
        let s = v.to_string();
        if c == Convention::PtBr { s.replace('.', ",") } else { s }
    };
    let material = match q.model.material_share {
        MaterialShare::Area => text!("material: each part's own area (outline less holes)";
                                     "material: a área de cada peça (contorno menos furos)"),
        MaterialShare::Sheet => text!("material: each part's share by area of the sheet used";
                                      "material: a parte de cada peça, por área, da chapa usada"),
    };
    let price = match (m.material_per_kg, m.material_per_m2) {
        (Some(kg), _) => format!(
            "{} {cur}/kg, {} g/cm3, {} mm",
            n(kg),
            n(m.density_g_cm3.unwrap_or(0.0)),
            n(m.thickness_mm.unwrap_or(0.0))
        ),
        (None, Some(m2)) => format!("{} {cur}/m2", n(m2)),
        (None, None) => String::new(),
    };
    let scrap = match m.scrap_per_kg {
        Some(s) => format!("{} {cur}/kg", n(s)),
        None => word(text!("none"; "nenhum")),
    };
    let (hour, pierce, metre, setup, markup) = (
        n(m.machine_per_hour),
        n(m.per_pierce),
        n(m.per_metre),
        n(m.setup_per_sheet),
        n(m.markup_percent),
    );
    // Sheets at a cost: their costs are the material (a note of the quote's
    // says so with their total), the model's price is not applied.
    let material = if q.material_share == "sheet_cost" {
        text!("material: the cost of each sheet the nest chose";
              "material: o custo de cada chapa escolhida pelo encaixe")
    } else {
        text!("{}, at {price}", material.en; "{}, a {price}", material.pt)
    };
    let notes = [
        material,
        text!("machine {hour} {cur}/h, {pierce} {cur}/pierce, {metre} {cur}/m, setup {setup} {cur}/sheet, scrap credit {scrap}, markup {markup} %";
              "máquina {hour} {cur}/h, {pierce} {cur}/perfuração, {metre} {cur}/m, preparação {setup} {cur}/chapa, crédito de sucata {scrap}, margem {markup} %"),
        text!("time: the plan's estimate; a part's includes its share of its sheet's crop line; setup and the sheet's own cuts shared equally among the sheet's copies";
              "tempo: a estimativa do plano; o de uma peça inclui sua parte da linha de recorte da chapa; a preparação e os cortes da própria chapa divididos igualmente entre as cópias da chapa"),
    ];
    let note = word(text!("note"; "nota"));
    for t in notes.iter().chain(&q.notes) {
        line(&mut out, &[cell_in(&note, sep), cell_in(t.get(lang), sep)], c);
    }
    out
}
