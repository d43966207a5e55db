//! A finished nest in the page: its figures and placements as JSON, its
//! DXFs (the whole nest, one sheet, the remnant) and one sheet cut with the
//! page's settings. Hand edits are `nest_edit.rs`.

use wasm_bindgen::prelude::*;

use super::{say, Job};
use crate::label::{self, LabelOptions, Labels, Naming};
use crate::nest::stock::{self, Stock};
use crate::nest::{self, output, Nest, NestJob};
use crate::process::Torches;
use crate::text;
use crate::warning::Lang;

/// Sheets at a cost: the stock, the combination nested (the whole stock
/// until `nest` finds the cheapest) and the combinations passed over.
#[derive(Clone, Debug)]
pub(super) struct Priced {
    pub stock: Vec<Stock>,
    pub counts: Vec<usize>,
    pub passed_over: usize,
}

impl Priced {
    /// The report's `stock`, `sheet_cost` and `combinations_passed_over`
    /// for `nest` as it stands (a hand edit may leave a sheet empty).
    pub fn add_to(&self, json: &mut serde_json::Value, nest: &Nest) {
        let (used, cost) = stock::used(&self.stock, &self.counts, nest);
        for (key, value) in stock::json_fields(&self.stock, &used, cost, self.passed_over) {
            json[key] = value;
        }
    }
}

/// A finished nest (adjusted by hand through `nest_edit.rs`).
#[wasm_bindgen]
pub struct NestResult {
    pub(super) lang: Lang,
    pub(super) job: NestJob,
    pub(super) nest: Nest,
    pub(super) seconds: f64,
    /// Copies that break the rules after a hand edit (none as nested).
    pub(super) conflicts: Vec<crate::nest::edit::Conflict>,
    /// Where the operator put the crop line (None: after the last part).
    pub(super) crop: Option<Option<f64>>,
    /// Several torches: the setup and the band under torch 1, mm.
    pub(super) torches: Option<(Torches, f64)>,
    /// Labels on the copies (issue 42 §2), and whether the cut scribes
    /// them; None: no labels.
    pub(super) labels: Option<(LabelOptions, bool)>,
    /// Sheets at a cost (issue 44 item 3): the stock and the combination
    /// nested; None: the sheets as given.
    pub(super) priced: Option<Priced>,
}

/// The page's label settings (`set_labels`), wire names.
#[derive(serde::Deserialize)]
#[serde(default)]
struct LabelSpec {
    on: bool,
    naming: String,
    height_max: f64,
    height_min: f64,
    margin: f64,
    mark: bool,
}

impl Default for LabelSpec {
    fn default() -> Self {
        let d = LabelOptions::DEFAULT;
        LabelSpec {
            on: false,
            naming: "name".into(),
            height_max: d.height_max,
            height_min: d.height_min,
            margin: d.margin,
            mark: false,
        }
    }
}

impl NestResult {
    /// A nest as the engine made it, before any hand edit: the files'
    /// `notes` ahead of its unplaced copies, `seconds` its wall time (0 if
    /// the page's clock gave none).
    pub(super) fn fresh(
        lang: Lang,
        job: NestJob,
        mut nest: Nest,
        notes: &[crate::nest::Unplaced],
        seconds: f64,
        torches: Option<(Torches, f64)>,
        priced: Option<Priced>,
    ) -> NestResult {
        nest.unplaced.splice(0..0, notes.iter().cloned());
        NestResult {
            lang,
            job,
            nest,
            seconds: if seconds.is_finite() { seconds } else { 0.0 },
            conflicts: Vec::new(),
            crop: None,
            torches,
            labels: None,
            priced,
        }
    }

    /// [`NestResult::labels_json`] as a value (`state()` carries it).
    pub(super) fn labels_value(&self) -> serde_json::Value {
        let labels = self.placed_labels().unwrap_or_default();
        let flat = |s: &Vec<crate::geom::Point>| s.iter().flat_map(|p| [p.x, p.y]).collect::<Vec<f64>>();
        serde_json::json!({
            "labels": labels.labels.iter().map(|l| serde_json::json!({
                "part": l.part, "copy": l.copy, "sheet": l.sheet, "text": l.text,
                "height": l.height, "angle": l.angle,
                "strokes": l.strokes.iter().map(flat).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
            "left_out": labels.left_out.iter().map(|&(part, copy)| serde_json::json!({"part": part, "copy": copy})).collect::<Vec<_>>(),
            "warnings": labels.warnings.iter().map(|w| w.message_in(self.lang).to_owned())
                .chain((self.labels.is_some() && self.torches.is_some()).then(|| {
                    text!("a multi-torch nest is not labelled yet: no labels drawn, scribed or written";
                          "um encaixe com várias tochas ainda não recebe etiquetas: nenhuma desenhada, riscada ou gravada")
                        .get(self.lang)
                        .to_owned()
                }))
                .collect::<Vec<_>>(),
        })
    }
    /// The labels of the nest as it stands (None: labels off, or a
    /// multi-torch nest, not labelled yet).
    fn placed_labels(&self) -> Option<Labels> {
        let (options, _) = self.labels.filter(|_| self.torches.is_none())?;
        Some(label::label_nest(&self.job, &self.nest, &options, self.job.settings.tolerance))
    }
    /// The nest with its torch setup, when it has one.
    pub(super) fn torch_nest(&self) -> Option<nest::torches::TorchNest> {
        self.torches
            .map(|(t, band)| nest::torches::TorchNest::of(&self.job, self.nest.clone(), t, band))
    }
}

#[wasm_bindgen]
impl NestResult {
    /// Figures and placements as JSON (the CLI's `kerfcam nest --json`).
    pub fn json(&self) -> String {
        match self.torch_nest() {
            Some(tn) => nest::torches::to_json(&self.job, &tn, self.seconds, self.lang).to_string(),
            None => {
                let mut j = output::to_json(&self.job, &self.nest, self.seconds, self.lang);
                if let Some(p) = &self.priced {
                    p.add_to(&mut j, &self.nest);
                }
                j.to_string()
            }
        }
    }
    /// Sheets used.
    pub fn sheet_count(&self) -> usize {
        self.nest.sheets.len()
    }
    /// The whole nest as a DXF (parts, sheets on SHEET, crop line on REMNANT).
    pub fn dxf(&self) -> String {
        match self.torch_nest() {
            Some(tn) => nest::torches::to_dxf(&self.job, &tn),
            None => {
                let labels = self.placed_labels();
                let overlays = labels.as_ref().map_or(Vec::new(), label::output::overlays);
                output::to_dxf_with(&self.job, &self.nest, &overlays)
            }
        }
    }
    /// Sets the labels (JSON `{on, naming: "name"|"code", height_max,
    /// height_min, margin, mark}`; a value out of range is refused, naming
    /// its field, and the last good setting kept) and answers them as
    /// `state()` (which carries them) does.
    pub fn set_labels(&mut self, spec: &str) -> Result<String, JsError> {
        let spec: LabelSpec = serde_json::from_str(spec)
            .map_err(|e| JsError::new(&format!("labels: {e}")))?;
        let naming = Naming::from_name(&spec.naming).ok_or_else(|| {
            let n = &spec.naming;
            say(self.lang, text!("label_naming: '{n}' is not name or code"; "label_naming: '{n}' não é name nem code"))
        })?;
        let options = LabelOptions {
            height_max: spec.height_max,
            height_min: spec.height_min,
            margin: spec.margin,
            naming,
        };
        if let Err((field, why)) = options.check() {
            let why = why.get(self.lang).to_owned();
            return Err(say(self.lang, text!("{field}: {why}"; "{field}: {why}")));
        }
        self.labels = spec.on.then_some((options, spec.mark));
        Ok(self.state())
    }
    /// The copies' labels as JSON: `{labels: [{part, copy, sheet, text,
    /// height, angle, strokes: [[x0, y0, x1, y1, …], …]}], left_out:
    /// [{part, copy}], warnings: [text]}` (parts by index, copies 0-based;
    /// empty lists when labels are off).
    pub fn labels_json(&self) -> String {
        self.labels_value().to_string()
    }
    /// The whole nest as an SVG in mm (a layer per sheet, a group per copy;
    /// `kerfcam nest -o NEST.svg`); empty for a multi-torch nest, whose
    /// other torches' copies only the DXF draws.
    pub fn svg(&self) -> String {
        match self.torches {
            Some(_) => String::new(),
            None => {
                let labels = self.placed_labels();
                let overlays = labels.as_ref().map_or(Vec::new(), label::output::overlays);
                nest::svg_out::to_svg_with(&self.job, &self.nest, &overlays)
            }
        }
    }
    /// The parts of sheet `k` alone as a DXF, sheet coordinates.
    pub fn sheet_dxf(&self, k: usize) -> String {
        output::sheet_dxf(&self.job, &self.nest, k)
    }
    /// The remnant kept beyond the last sheet's crop line as a sheet DXF,
    /// or an empty string when none is kept.
    pub fn remnant_dxf(&self) -> String {
        output::remnant_dxf(&self.job, &self.nest).unwrap_or_default()
    }
    /// Sheet `k` cut with the page's cutting settings (as `new Job`
    /// takes them): a `Job` whose plan, preview, report and program are
    /// the sheet's, the crop line cut last.
    pub fn cut(&self, k: usize, settings: JsValue) -> Result<Job, JsError> {
        let n = self.nest.sheets.len();
        if k >= n {
            return Err(say(
                self.lang,
                text!(
                "sheet {k}: the nest has {n} sheet(s)";
                "chapa {k}: o encaixe tem {n} chapa(s)"),
            ));
        }
        // A nest that breaks the rules (a hand edit) is not cut: the
        // program would cut parts into each other.
        if let Some(c) = self.conflicts.first() {
            let (n, copy) = (self.conflicts.len(), c.copy + 1);
            return Err(say(
                self.lang,
                text!(
                "the nest has {n} conflict(s) (copy {copy} first): fix them before cutting";
                "o encaixe tem {n} conflito(s) (cópia {copy} primeiro): corrija antes de cortar"),
            ));
        }
        // The settings are read as the page's Job reads them; the plan is
        // the nest's sheet (crop line last), run once.
        let mut settings = super::settings_of(settings)?;
        // The program drives torch 1 and says so (the nest's setup).
        if let Some((t, _)) = self.torches {
            settings.process.torches = Some(t);
        }
        let scribed = self
            .labels
            .filter(|&(_, mark)| mark)
            .and_then(|_| self.placed_labels());
        let out = crate::nest_cut::cut_sheet_labelled(&self.job, &self.nest, k, &settings, scribed.as_ref())
            .map_err(|e| JsError::new(&e.message(settings.lang)))?;
        let names = self.job.parts.iter().map(|p| p.name.clone()).collect();
        Ok(Job::of(out, settings).with_names(names))
    }

    /// The whole nest quoted at `cost`'s prices (a cost model as JSON):
    /// every sheet cut with the page's cutting settings (as [`Self::cut`]
    /// cuts one), each used up to its crop line; the quote as JSON
    /// (`kerfcam nest --cost … --json`'s `quote`), or as CSV when `csv`.
    pub fn quote(&self, cost: &str, settings: JsValue, csv: bool) -> Result<String, JsError> {
        if self.torches.is_some() {
            return Err(say(
                self.lang,
                text!("a multi-torch nest is not quoted (every torch cuts each copy)";
                      "um encaixe de várias tochas não é orçado (cada tocha corta cada cópia)"),
            ));
        }
        if !self.conflicts.is_empty() {
            let n = self.conflicts.len();
            return Err(say(
                self.lang,
                text!("the nest has {n} conflict(s): fix them before quoting";
                      "o encaixe tem {n} conflito(s): corrija antes de orçar"),
            ));
        }
        let m = super::quote::model(cost, self.lang)?;
        let settings = super::settings_of(settings)?;
        let outs = (0..self.nest.sheets.len())
            .map(|k| crate::nest_cut::cut_sheet(&self.job, &self.nest, k, &settings))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| JsError::new(&e.message(settings.lang)))?;
        // Sheets at a cost: each sheet's cost is its material, as in
        // `kerfcam nest --cost`.
        let costs = self
            .priced
            .as_ref()
            .map(|p| stock::sheet_costs(&p.stock, &p.counts, self.nest.sheets.len()));
        let sheets: Vec<crate::quote::SheetInput> = outs
            .iter()
            .zip(&self.nest.sheets)
            .enumerate()
            .map(|(k, (out, s))| crate::quote::SheetInput {
                out,
                used_area_mm2: Some(s.height * s.crop_x.unwrap_or(s.width)),
                cost: costs.as_ref().and_then(|c| c.get(k).copied()),
            })
            .collect();
        let name = |p: u32| {
            (p as usize)
                .checked_sub(1)
                .and_then(|i| self.job.parts.get(i))
                .map_or(format!("#{p}"), |part| part.name.clone())
        };
        let q = crate::quote::quote(&m, &sheets, &name)
            .map_err(|e| JsError::new(&e.message(self.lang)))?;
        if csv {
            // The page's language's spreadsheet convention (`;` and `,` in pt-BR).
            let c = crate::quote::Convention::of(settings.lang);
            Ok(crate::quote::to_csv_in(&q, c))
        } else {
            serde_json::to_string(&q).map_err(|e| JsError::new(&e.to_string()))
        }
    }
}
