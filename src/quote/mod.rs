//! Cost and time (issue 42 §3): a job's cut plans and a shop's prices
//! ([`CostModel`]) → a [`Quote`]: per copy, per part (its copies summed),
//! per sheet and for the job, the length cut, pierces, machine time,
//! material, cost and price.
//!
//! - Time is the program's estimate ([`crate::Output::est_time_s`], the
//!   report's `est_time_s`), split by copy as [`share`] says: the copies'
//!   times sum to their sheet's; a router's milling and the Z moves of its
//!   profiles (the program's time beyond its plan's) are the sheet's own.
//! - Length cut (`cut_m`) is the length fed with the tool on: contours and
//!   edges cut again (times the depth passes), leads and links; not
//!   markings, not tabs.
//! - Material is each copy's own area (outline less holes) or its share
//!   by area of the sheet used ([`MaterialShare`]; the quote says which),
//!   priced per kg (area × thickness × density) or per m².
//! - What belongs to the sheet and to no copy (the setup, the crop line's
//!   pierce, length and time) is shared equally among its copies.
//! - cost = machine rate × time + pierces × per pierce + metres × per
//!   metre + material − scrap credit + the sheet's share; price = cost ×
//!   (1 + markup / 100).

mod csv;
mod model;
pub mod share;

pub use csv::{cell, to_csv, to_csv_in, Convention};
pub use model::{CostModel, MaterialShare, QuoteError};

use std::collections::BTreeMap;

use serde::Serialize;

use crate::plan::PlanStats;
use crate::text;
use crate::warning::Text;
use crate::Output;

/// One sheet of the job as cut.
#[derive(Clone, Copy, Debug)]
pub struct SheetInput<'a> {
    /// The sheet's pipeline output (its plan, contours, process).
    pub out: &'a Output,
    /// The sheet's used area, mm² (its width × height, or up to the crop
    /// line when a remnant is kept); None for a drawing on no sheet.
    pub used_area_mm2: Option<f64>,
    /// What the sheet cost, when the nest took it from sheets at a cost
    /// (`kerfcam nest --sheet WxH:N:COST`, [`crate::nest::stock`]): then
    /// it is the sheet's material, whole, shared among its copies by area;
    /// None: the model prices the material.
    pub cost: Option<f64>,
}

/// Figures of a copy, a part, a sheet or the job. Money in the model's
/// currency.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Figures {
    /// Length fed with the tool on, m.
    pub cut_m: f64,
    /// Pierces (a copy's own; a sheet's and the job's include the sheet's
    /// own cuts, the crop line's).
    pub pierces: usize,
    /// Estimated machine time, s (a copy's includes its share of the
    /// sheet's own moves).
    pub time_s: f64,
    /// The part's own area (outline less holes), m².
    pub area_m2: f64,
    /// Material charged, m² (the own area or the share of the sheet).
    pub material_m2: f64,
    /// Its mass, kg, when density and thickness are given.
    pub material_kg: Option<f64>,
    /// Material price.
    pub material: f64,
    /// Machine rate × time.
    pub machine: f64,
    /// Pierces × per pierce.
    pub pierce_cost: f64,
    /// Metres × per metre.
    pub cut_cost: f64,
    /// Share of the sheet's setup and own cuts.
    pub sheet_share: f64,
    /// Credit for the skeleton sold as scrap.
    pub scrap_credit: f64,
    /// The sum: machine + pierce + cut + material − scrap + sheet share.
    pub cost: f64,
    /// Cost with the markup.
    pub price: f64,
}

impl Figures {
    fn add(&mut self, o: &Figures) {
        self.cut_m += o.cut_m;
        self.pierces += o.pierces;
        self.time_s += o.time_s;
        self.area_m2 += o.area_m2;
        self.material_m2 += o.material_m2;
        self.material_kg = match (self.material_kg, o.material_kg) {
            (Some(a), Some(b)) => Some(a + b),
            (a, b) => a.or(b),
        };
        self.material += o.material;
        self.machine += o.machine;
        self.pierce_cost += o.pierce_cost;
        self.cut_cost += o.cut_cost;
        self.sheet_share += o.sheet_share;
        self.scrap_credit += o.scrap_credit;
        self.cost += o.cost;
        self.price += o.price;
    }
}

/// One placed copy.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CopyQuote {
    /// Its part (1-based, the contours' `source.part`).
    pub part: u32,
    /// Which copy (0-based).
    pub copy: u32,
    /// Its sheet (1-based).
    pub sheet: usize,
    /// The part's name.
    pub name: String,
    /// Its figures.
    #[serde(flatten)]
    pub figures: Figures,
}

/// A part: its copies summed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PartQuote {
    /// The part (1-based).
    pub part: u32,
    /// Its name.
    pub name: String,
    /// Copies quoted.
    pub quantity: usize,
    /// Its copies' figures summed.
    #[serde(flatten)]
    pub figures: Figures,
}

/// A sheet's totals.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SheetQuote {
    /// The sheet (1-based).
    pub sheet: usize,
    /// Copies on it.
    pub copies: usize,
    /// The sheet's used area, m², when it is a sheet.
    pub used_m2: Option<f64>,
    /// Its figures: length, pierces and time of its whole plan, money
    /// summed over its copies.
    #[serde(flatten)]
    pub figures: Figures,
}

/// The job's quote.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Quote {
    /// The model's currency label.
    pub currency: String,
    /// Which material share was used ("area" or "sheet"), or
    /// "sheet_cost": every sheet's material is what it cost
    /// ([`SheetInput::cost`]), the model's material price not applied.
    pub material_share: &'static str,
    /// The model it was priced with (the assumptions, shown).
    pub model: CostModel,
    /// Every copy.
    pub copies: Vec<CopyQuote>,
    /// Every part, in part order.
    pub parts: Vec<PartQuote>,
    /// Every sheet, in order.
    pub sheets: Vec<SheetQuote>,
    /// The job's totals.
    pub job: Figures,
    /// What of the model could not be applied, and why.
    pub notes: Vec<Text>,
}

/// Length fed with the tool on, m (see the module doc).
fn cut_m(st: &PlanStats, passes: f64) -> f64 {
    ((st.cut_length + st.repeated_length) * passes + st.lead_length) / 1000.0
}

/// The quote of `sheets` at `model`'s prices; `name` gives a part's name
/// from its number. Refused when the model is invalid, or when it asks for
/// the sheet's material share of a drawing on no sheet.
pub fn quote(
    model: &CostModel,
    sheets: &[SheetInput],
    name: &dyn Fn(u32) -> String,
) -> Result<Quote, QuoteError> {
    model.validate()?;
    let by_sheet = model.material_share == MaterialShare::Sheet;
    if by_sheet && sheets.iter().any(|s| s.used_area_mm2.is_none()) {
        return Err(QuoteError {
            field: "material_share".into(),
            reason: text!("'sheet' needs a sheet: the drawing is not nested (use 'area', or kerfcam nest)";
                          "'sheet' precisa de uma chapa: o desenho não está encaixado (use 'area', ou kerfcam nest)"),
        });
    }
    // Sheets bought at a cost: each is its material (the nest's sheet
    // cost), shared as the sheet's share shares it.
    let sheet_cost = !sheets.is_empty() && sheets.iter().all(|s| s.cost.is_some());
    let mut notes = Vec::new();
    if sheet_cost {
        let total: f64 = sheets.iter().filter_map(|s| s.cost).sum();
        let (n, cur) = (sheets.len(), &model.currency);
        let total = format!("{total:.2}");
        let total_pt = crate::warning::dec(total.clone());
        notes.push(text!("material: the {n} sheet(s) the nest chose, at the costs given with the sheets ({total} {cur} in all), each sheet's whole cost shared among its copies by area; the cost model's material price is not applied";
                         "material: a(s) {n} chapa(s) escolhida(s) pelo encaixe, aos custos dados com as chapas ({total_pt} {cur} ao todo), o custo inteiro de cada chapa dividido entre suas cópias por área; o preço do material do modelo de custo não é aplicado"));
    }
    if !by_sheet && !sheet_cost && model.scrap_per_kg.is_some() {
        notes.push(text!("scrap credit not applied: material is charged by each part's own area, so the skeleton is not bought";
                         "crédito de sucata não aplicado: o material é cobrado pela área de cada peça, o esqueleto não é comprado"));
    }
    let markup = 1.0 + model.markup_percent / 100.0;
    let mut copies = Vec::new();
    let mut sheet_rows = Vec::new();
    for (k, s) in sheets.iter().enumerate() {
        let t = s.out.process;
        let passes = t.passes.count().max(1) as f64;
        let sp = share::split(s.out);
        let n = sp.copies.len();
        // A router's milling and profiles' Z moves (the program's time
        // beyond its plan's): the sheet's own, shared by its copies.
        let router = (s.out.est_time_s - s.out.plan.est_time_s(&t)).max(0.0);
        let own_time = sp.sheet.est_time_s(&t) + router;
        let own_cost = model.per_pierce * sp.sheet.pierces as f64
            + model.per_metre * cut_m(&sp.sheet, passes)
            + model.setup_per_sheet;
        let parts_area: f64 = sp.copies.values().map(|(_, a)| a.max(0.0)).sum();
        let used = s.used_area_mm2.unwrap_or(0.0);
        // A sheet at a cost is bought whole: shared as the sheet's share.
        let by_sheet = by_sheet || s.cost.is_some();
        let mut sheet = Figures::default();
        for (&(part, copy), (st, area)) in &sp.copies {
            let area = area.max(0.0);
            // The copy's share of its sheet, by area.
            let fraction = if parts_area > 0.0 {
                area / parts_area
            } else {
                1.0 / n as f64
            };
            let charged = if by_sheet { used * fraction } else { area };
            let scrap = match model.scrap_per_kg.filter(|_| by_sheet) {
                Some(p) => model.mass_kg(charged - area).unwrap_or(0.0) * p,
                None => 0.0,
            };
            let mut f = Figures {
                cut_m: cut_m(st, passes),
                pierces: st.pierces,
                time_s: st.est_time_s(&t) + own_time / n as f64,
                area_m2: area / 1e6,
                material_m2: charged / 1e6,
                material_kg: model.mass_kg(charged),
                material: s
                    .cost
                    .map_or_else(|| model.material_cost(charged), |c| c * fraction),
                scrap_credit: scrap,
                sheet_share: own_cost / n as f64,
                ..Figures::default()
            };
            f.machine = model.machine_per_hour * f.time_s / 3600.0;
            f.pierce_cost = model.per_pierce * f.pierces as f64;
            f.cut_cost = model.per_metre * f.cut_m;
            f.cost = f.machine + f.pierce_cost + f.cut_cost + f.material - f.scrap_credit
                + f.sheet_share;
            f.price = f.cost * markup;
            sheet.add(&f);
            copies.push(CopyQuote {
                part,
                copy,
                sheet: k + 1,
                name: name(part),
                figures: f,
            });
        }
        // Money and material are its copies' summed; length, pierces and
        // time its whole plan's (the crop line's too).
        let all = s.out.plan.stats();
        sheet.cut_m = cut_m(&all, passes);
        sheet.pierces = all.pierces;
        sheet.time_s = all.est_time_s(&t) + router;
        if n == 0 {
            // A sheet of no part still costs its setup and its cuts, and
            // what it cost when bought.
            sheet.machine = model.machine_per_hour * sheet.time_s / 3600.0;
            sheet.sheet_share = own_cost;
            sheet.material = s.cost.unwrap_or(0.0);
            sheet.cost = sheet.machine + own_cost + sheet.material;
            sheet.price = sheet.cost * markup;
        }
        sheet_rows.push(SheetQuote {
            sheet: k + 1,
            copies: n,
            used_m2: s.used_area_mm2.map(|a| a / 1e6),
            figures: sheet,
        });
    }
    let mut parts: BTreeMap<u32, PartQuote> = BTreeMap::new();
    for c in &copies {
        let p = parts.entry(c.part).or_insert_with(|| PartQuote {
            part: c.part,
            name: c.name.clone(),
            quantity: 0,
            figures: Figures::default(),
        });
        p.quantity += 1;
        p.figures.add(&c.figures);
    }
    let mut job = Figures::default();
    for s in &sheet_rows {
        job.add(&s.figures);
    }
    Ok(Quote {
        currency: model.currency.clone(),
        material_share: if sheet_cost {
            "sheet_cost"
        } else {
            model.material_share.name()
        },
        model: model.clone(),
        copies,
        parts: parts.into_values().collect(),
        sheets: sheet_rows,
        job,
        notes,
    })
}

#[cfg(test)]
#[path = "quote_tests.rs"]
mod tests;
