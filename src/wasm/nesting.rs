//! Nesting through the JavaScript boundary (issue 16 for issue 18's Sheet
//! mode): a `Nester` gathers parts and a sheet from DXF bytes, nests them
//! with a clock and a progress callback the page passes (no `Instant` in a
//! browser, no threads), and a `NestResult` answers with the placements,
//! the figures, the DXFs and each sheet cut by the ordinary pipeline.
//!
//! ```js
//! const n = new Nester();
//! n.set_cutting(settings);                  // the page's cutting settings, as `new Job` takes them
//! n.add_part(bytes, "bracket.dxf", { quantity: 12, rotations: "90", mirror: false });
//! n.set_sheet_dxf(remnantBytes);            // or { sheet_width, sheet_height } below
//! const r = n.nest({ sheet_width: 1000, sheet_height: 500, spacing: 2.5, margin: 5,
//!                    time_s: 10, seed: 1 },
//!                  () => performance.now() / 1000,
//!                  (p) => { show(p.length, p.utilisation); return !cancelled; });
//! r.json(); r.dxf(); r.remnant_dxf(); const job = r.cut(0, settings); // a Job
//! ```
//!
//! Sheets at a cost (issue 44 item 3): a `cost` on every `sheet_list`
//! size makes the list the stock, and `nest` takes the cheapest
//! combination that holds every copy, as `kerfcam nest --sheet WxH:N:COST`
//! does (`crate::nest::stock`, the same trials: the CLI with one thread).

use serde::{Deserialize, Serialize};
use wasm_bindgen::prelude::*;

use super::nest_result::{NestResult, Priced};
use super::{lang_of, say};
use crate::dxf::Units;
use crate::nest::stock;
use crate::nest::{
    self, NestJob, NestSpec, Part, Progress, Rotations, SheetSize, Sheets, Unplaced,
};
use crate::process::Torches;
use crate::text;
use crate::warning::Lang;
use crate::{Settings, Spec};

/// Per file: how many copies and how they may turn.
#[derive(Deserialize)]
#[serde(default)]
struct WebPart {
    /// Copies of every part in the file…
    quantity: usize,
    /// …or per part, in the file's part order (wins where given).
    quantities: Vec<usize>,
    /// Each part's own choices, in the file's part order (issue 42 §1:
    /// a row per part); what a part does not give is the file's.
    each: Vec<EachPart>,
    /// "none", "180", "90", "free" or a number of steps.
    rotations: String,
    mirror: bool,
    /// The unit the file is read in ("mm", "in", "cm", …), whatever it
    /// says; empty: its own ($INSUNITS, or mm assumed). The page's per-file
    /// unit switch (issue 18 item 1): an inch file is not nested at 1/25.4.
    units: String,
}

/// One part's choices within its file.
#[derive(Default, Deserialize)]
#[serde(default)]
struct EachPart {
    quantity: Option<usize>,
    rotations: Option<String>,
    mirror: Option<bool>,
}

impl Default for WebPart {
    fn default() -> Self {
        WebPart {
            quantity: 1,
            quantities: Vec::new(),
            each: Vec::new(),
            rotations: "90".into(),
            mirror: false,
            units: String::new(),
        }
    }
}

/// The nest's settings; a sheet W × H (N of them), a strip, or the sheet
/// given by `set_sheet_dxf`. The rest is a [`NestSpec`]: what is not given
/// takes its defaults, as in `kerfcam nest`.
#[derive(Default, Deserialize)]
#[serde(default)]
struct WebNest {
    sheet_width: Option<f64>,
    sheet_height: Option<f64>,
    sheet_count: Option<usize>,
    /// Sheets of several sizes, filled in this order (issue 16 item 6):
    /// when given, it is the sheets, and `sheet_width`, `sheet_height`
    /// and `sheet_count` (the first size, for the page's own figures) are
    /// not read.
    sheet_list: Option<Vec<WebSheetSize>>,
    /// With costs: the combination nested (sheets of each size), for a
    /// nest made again without a search (`restore`, a team's `search`
    /// that adopts a stopped nest); `nest` finds its own.
    combination: Option<Vec<usize>>,
    /// With `combination`: the combinations nested before it that did not
    /// hold every copy (the report's).
    passed_over: Option<usize>,
    strip_height: Option<f64>,
    spacing: Option<f64>,
    margin: Option<f64>,
    tolerance: Option<f64>,
    time_s: Option<f64>,
    seed: Option<u64>,
    max_evaluations: Option<u64>,
    torches: Option<usize>,
    torch_spacing: Option<f64>,
    torch_park: Option<[f64; 2]>,
}

impl WebNest {
    /// The settings as given, without `None` for an absent page field.
    fn of(settings: &JsValue) -> Result<WebNest, JsError> {
        if settings.is_undefined() || settings.is_null() {
            return Ok(WebNest::default());
        }
        serde_wasm_bindgen::from_value(settings.clone())
            .map_err(|e| err(format!("nest settings: {e}")))
    }
    /// The nest's own settings.
    fn spec(&self) -> NestSpec {
        NestSpec {
            spacing: self.spacing,
            margin: self.margin,
            tolerance: self.tolerance,
            time_s: self.time_s,
            seed: self.seed,
            max_evaluations: self.max_evaluations,
            torches: self.torches,
            torch_spacing: self.torch_spacing,
            torch_park: self.torch_park,
        }
    }
}

/// `count` sheets `width` × `height`, mm: one size of a list, at `cost`
/// a sheet when given (null or absent: none).
#[derive(Deserialize)]
struct WebSheetSize {
    width: f64,
    height: f64,
    count: usize,
    #[serde(default)]
    cost: Option<WebCost>,
}

/// A cost as the page sends it: a number, or text it could not read
/// (refused naming its size, not as a JSON type error).
#[derive(Deserialize)]
#[serde(untagged)]
enum WebCost {
    Number(f64),
    Text(String),
}

/// What a cheapest nest's progress adds: the combination under trial
/// (the nest's sheet numbers refer to its sheets).
#[derive(Clone, PartialEq, Serialize)]
struct WebTrial {
    counts: Vec<usize>,
    passed_over: usize,
}

/// Whether `settings` name the combination of a nest at a cost (read by
/// `restore` and a team's `search`, not by `nest`).
pub(super) fn combination_given(settings: &JsValue) -> bool {
    WebNest::of(settings).is_ok_and(|w| w.combination.is_some())
}

/// What the progress callback hears: the best nest so far.
#[derive(Serialize)]
struct WebProgress {
    evaluations: u64,
    sheets: usize,
    length: f64,
    unplaced: usize,
    elapsed_s: f64,
    /// The best nest's copies when it changed since the last report, 7
    /// numbers each: part index, copy, sheet, rotation, mirror (0/1), x, y.
    placements: Option<Vec<f64>>,
    /// A team's search (nest_team.rs): with the placements, the best nest
    /// as the other workers adopt it and Stop keeps it.
    #[serde(skip_serializing_if = "Option::is_none")]
    best: Option<crate::nest::Best>,
    /// Sheets at a cost: the combination nested now.
    #[serde(skip_serializing_if = "Option::is_none")]
    combination: Option<WebTrial>,
}

/// Seconds from `clock()`; a clock that throws or answers nonsense ends
/// the search (the budget is spent), never the page.
pub(super) fn js_clock(clock: &js_sys::Function) -> f64 {
    clock
        .call0(&JsValue::NULL)
        .ok()
        .and_then(|v| v.as_f64())
        .filter(|t| t.is_finite())
        .unwrap_or(f64::INFINITY)
}

/// Tells `f` of a search's progress; false when it said stop. `shown`:
/// the placements sent last (they go out only when the best nest changed:
/// the page redraws the sheet then, not at every report); `team`: with
/// the best nest to adopt.
pub(super) fn tell(
    f: Option<&js_sys::Function>,
    shown: &mut Option<Vec<crate::nest::Placement>>,
    p: Progress,
    team: bool,
) -> bool {
    tell_trial(f, shown, p, team, None)
}

/// [`tell`], with the combination under trial of a cheapest nest (whose
/// best nest goes out too: Stop keeps it).
fn tell_trial(
    f: Option<&js_sys::Function>,
    shown: &mut Option<Vec<crate::nest::Placement>>,
    p: Progress,
    team: bool,
    combination: Option<WebTrial>,
) -> bool {
    let Some(f) = f else {
        return true;
    };
    let changed = shown.as_ref() != Some(&p.best);
    let best = (changed && team).then(|| p.as_best());
    let placements = changed.then(|| {
        let flat = super::nest_json::flat_placements(&p.best);
        *shown = Some(p.best.clone());
        flat
    });
    let value = serde_wasm_bindgen::to_value(&WebProgress {
        evaluations: p.evaluations,
        sheets: p.sheets,
        length: p.length,
        unplaced: p.unplaced,
        elapsed_s: p.elapsed_s,
        placements,
        best,
        combination,
    })
    .unwrap_or(JsValue::NULL);
    // Only an explicit `false` stops; a throwing callback does not.
    f.call1(&JsValue::NULL, &value)
        .map_or(true, |v| v.as_bool() != Some(false))
}

fn err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

impl Nester {
    /// A part file's options and the cutting settings it is read with (in
    /// the unit chosen for it, if any).
    fn part_options(&self, name: &str, options: JsValue) -> Result<(WebPart, Settings), JsError> {
        let o: WebPart = if options.is_undefined() || options.is_null() {
            WebPart::default()
        } else {
            serde_wasm_bindgen::from_value(options)
                .map_err(|e| err(format!("part options: {e}")))?
        };
        let mut cutting = self.cutting()?;
        if !o.units.is_empty() {
            let u = &o.units;
            cutting = cutting.with_units(Units::from_name(u).ok_or_else(|| {
                say(
                    self.lang,
                    text!("{name}: unknown unit '{u}'"; "{name}: unidade '{u}' desconhecida"),
                )
            })?);
        }
        Ok((o, cutting))
    }
}

/// Parts and a sheet, gathered before nesting.
#[wasm_bindgen]
#[derive(Default)]
pub struct Nester {
    pub(super) lang: Lang,
    parts: Vec<Part>,
    pub(super) notes: Vec<Unplaced>,
    sheet: Option<Sheets>,
    /// The page's cutting settings (`set_cutting`); None: the defaults.
    cutting: Option<Settings>,
}

#[wasm_bindgen]
impl Nester {
    /// An empty job; `lang` ("en", "pt-BR") for the errors it throws.
    #[wasm_bindgen(constructor)]
    pub fn new(lang: Option<String>) -> Nester {
        console_error_panic_hook::set_once();
        Nester {
            lang: lang_of(lang.as_deref()),
            ..Nester::default()
        }
    }

    /// The page's cutting settings (the object `new Job` takes): parts and
    /// sheets added after are read in their units, layers, tolerance and
    /// gap, and the spacing defaults to their kerf + 1 mm, as `kerfcam
    /// nest` reads its files. Throws for a setting out of range.
    pub fn set_cutting(&mut self, settings: JsValue) -> Result<(), JsError> {
        self.cutting = Some(super::settings_of(settings)?);
        Ok(())
    }

    /// The cutting settings parts are read with.
    fn cutting(&self) -> Result<Settings, JsError> {
        match &self.cutting {
            Some(s) => Ok(s.clone()),
            None => Spec::default()
                .build()
                .map_err(|e| say(self.lang, e.text())),
        }
    }

    /// Adds every part of a DXF file (an outer outline with its holes);
    /// returns their names as JSON. Open outlines are not nestable and are
    /// reported with the nest. Throws for an unreadable file or options
    /// out of range.
    pub fn add_part(
        &mut self,
        dxf: &[u8],
        name: &str,
        options: JsValue,
    ) -> Result<String, JsError> {
        let (o, cutting) = self.part_options(name, options)?;
        let turns = |name: &str| {
            Rotations::from_name(name).ok_or_else(|| {
                err(format!(
                    "part options: rotations '{name}' is not none, 180, 90, free or a number of steps 1..360"
                ))
            })
        };
        let rotations = turns(&o.rotations)?;
        let stem = name.rsplit_once('.').map_or(name, |(s, _)| s);
        let (mut parts, notes) = nest::read_parts(dxf, stem, o.quantity, &cutting)
            .map_err(|e| err(format!("{name}: {}", e.get(self.lang))))?;
        for (i, p) in parts.iter_mut().enumerate() {
            let each = o.each.get(i);
            p.quantity = each
                .and_then(|e| e.quantity)
                .or(o.quantities.get(i).copied())
                .unwrap_or(o.quantity);
            p.rotations = match each.and_then(|e| e.rotations.as_deref()) {
                Some(r) => turns(r)?,
                None => rotations.clone(),
            };
            p.mirror = each.and_then(|e| e.mirror).unwrap_or(o.mirror);
        }
        let names: Vec<&str> = parts.iter().map(|p| p.name.as_str()).collect();
        let json = serde_json::json!(names).to_string();
        self.parts.extend(parts);
        self.notes.extend(notes);
        Ok(json)
    }

    /// The file's parts as the page lists them before a nest (issue 42
    /// §1), JSON `{rows: [{name, layer, width, height, area, holes,
    /// not_nestable, d}], open, suspect: [text]}`: one row per part in the
    /// order `quantities` follow, `d` its outline and holes as SVG path
    /// data (y up) for the row's picture, `not_nestable` why the nester
    /// cannot place it (null: it can). Options as [`Nester::add_part`]'s
    /// (the units); throws for an unreadable file.
    pub fn part_rows(&self, dxf: &[u8], name: &str, options: JsValue) -> Result<String, JsError> {
        let (_, cutting) = self.part_options(name, options)?;
        let stem = name.rsplit_once('.').map_or(name, |(s, _)| s);
        let (parts, contours) = nest::spec::parts_and_contours(dxf, stem, &cutting)
            .map_err(|e| err(format!("{name}: {}", e.get(self.lang))))?;
        // The nester's test at its default spacing for this kerf (the
        // page's spacing field may differ: the nest then says what it left out).
        let ns = crate::nest::spec::NestSpec::default().settings(cutting.process().kerf);
        let f = nest::rows::file_rows(&parts, &contours, ns.tolerance, ns.spacing / 2.0);
        let lang = self.lang;
        let rows: Vec<_> = f
            .rows
            .iter()
            .zip(&parts)
            .map(|(r, p)| {
                serde_json::json!({
                    "name": r.name, "layer": r.layer, "x": r.x, "y": r.y,
                    "width": r.width, "height": r.height,
                    "area": r.area, "holes": r.holes,
                    "not_nestable": r.not_nestable.as_ref().map(|t| t.get(lang)),
                    "d": super::nest_json::part_path(p),
                })
            })
            .collect();
        let suspect: Vec<&str> = f.suspect.iter().map(|t| t.get(lang)).collect();
        Ok(serde_json::json!({ "rows": rows, "open": f.open, "suspect": suspect }).to_string())
    }

    /// The sheet: an irregular remnant drawn in a DXF (its largest outline;
    /// its holes and closed outlines on layer DEFECT are no-go zones).
    /// Returns what was left out of the drawing as JSON notes.
    pub fn set_sheet_dxf(&mut self, dxf: &[u8]) -> Result<String, JsError> {
        let lang = self.lang;
        let (sheet, notes) = nest::read_sheet(dxf, &self.cutting()?).map_err(|e| say(lang, e))?;
        self.sheet = Some(sheet);
        let notes: Vec<&str> = notes.iter().map(|t| t.get(lang)).collect();
        Ok(serde_json::json!(notes).to_string())
    }

    /// Each part's outline and holes as an SVG path in the part's own
    /// coordinates (y up, arcs kept), JSON `[{name, d}]` in the order of
    /// the part indices that placements and progress name.
    pub fn outlines(&self) -> String {
        super::nest_json::outlines_json(&self.parts)
    }

    /// The sheet given by `set_sheet_dxf` as the page draws it, JSON
    /// `{path, box}` (its outline and no-go zones, y up), or `null`.
    pub fn sheet_shape(&self) -> String {
        self.sheet
            .as_ref()
            .map_or(serde_json::Value::Null, super::nest_json::sheet_shape)
            .to_string()
    }

    /// The torch setup of the settings (None: one torch).
    fn torches(&self, settings: &JsValue) -> Result<Option<Torches>, JsError> {
        WebNest::of(settings)?
            .spec()
            .torches()
            .map_err(|e| say(self.lang, e.text()))
    }

    /// The job these parts and settings make (as `nest` reads them), and
    /// its sheets' costs when every size has one: its sheets
    /// then the `combination` given, else the whole stock (`nest` finds
    /// the cheapest). The costs as `kerfcam nest --sheet WxH:N:COST` takes
    /// them ([`stock::stock_of`]), each checked naming its size.
    pub(super) fn priced_job(
        &self,
        settings: JsValue,
    ) -> Result<(NestJob, Option<Priced>), JsError> {
        let w = WebNest::of(&settings)?;
        let lang = self.lang;
        let list = w.sheet_list.as_deref().unwrap_or_default();
        let mut costs = Vec::with_capacity(list.len());
        for (i, s) in list.iter().enumerate() {
            let n = i + 1;
            costs.push(match &s.cost {
                None => None,
                Some(WebCost::Number(c)) => Some(*c),
                Some(WebCost::Text(t)) => {
                    return Err(say(
                        lang,
                        text!("sheet size {n}: the cost '{t}' is not a number";
                              "tamanho de chapa {n}: o custo '{t}' não é um número"),
                    ))
                }
            });
        }
        let sizes: Vec<SheetSize> = list
            .iter()
            .map(|s| SheetSize {
                width: s.width,
                height: s.height,
                count: s.count,
            })
            .collect();
        let torches = w
            .spec()
            .torches()
            .map_err(|e| say(lang, e.text()))?
            .is_some();
        let stock = stock::stock_of(&sizes, &costs, torches).map_err(|e| {
            let t = e.text();
            say(
                lang,
                text!("sheet costs: {}", t.en; "custos das chapas: {}", t.pt),
            )
        })?;
        if let Some(stock) = &stock {
            for (i, s) in stock.iter().enumerate() {
                let n = i + 1;
                stock::check_cost(s).map_err(|t| {
                    say(
                        lang,
                        text!("sheet size {n}: {}", t.en; "tamanho de chapa {n}: {}", t.pt),
                    )
                })?;
            }
        }
        let sheets = match (w.sheet_width, w.sheet_height, w.strip_height, &self.sheet) {
            _ if !sizes.is_empty() => Sheets::rects(sizes.clone()),
            (Some(width), Some(height), None, _) => Sheets::Rect {
                width,
                height,
                count: w.sheet_count.unwrap_or(1),
            },
            (None, None, Some(height), _) => Sheets::Strip { height },
            (None, None, None, Some(s)) => s.clone(),
            _ => return Err(err(
                "nest settings: give sheet_width and sheet_height, or strip_height, or a sheet DXF",
            )),
        };
        let mut job = NestJob {
            parts: self.parts.clone(),
            sheets,
            settings: w.spec().settings(self.cutting()?.process().kerf),
        };
        let priced = match stock {
            None => None,
            Some(stock) => {
                let counts = match &w.combination {
                    Some(c) => {
                        let fits = c.len() == stock.len()
                            && c.iter().zip(&stock).all(|(&n, s)| n <= s.size.count)
                            && c.iter().any(|&n| n > 0);
                        if !fits {
                            return Err(say(
                                lang,
                                text!("nest settings: the combination {c:?} is not sheets of the stock's sizes";
                                      "configurações do encaixe: a combinação {c:?} não é de chapas dos tamanhos em estoque"),
                            ));
                        }
                        job = stock::with_sheets(&job, &stock, c);
                        c.clone()
                    }
                    None => stock.iter().map(|s| s.size.count).collect(),
                };
                Some(Priced {
                    stock,
                    counts,
                    passed_over: w.passed_over.unwrap_or(0),
                })
            }
        };
        Ok((job, priced))
    }

    /// Nests. `clock()` returns seconds from any fixed start;
    /// `on_progress(p)`, when given, hears `{evaluations, sheets, length,
    /// unplaced, elapsed_s}` after each better nest and now and then, and
    /// stops the search by returning `false` (the best nest so far is
    /// returned). Throws for settings out of range or no part.
    pub fn nest(
        &self,
        settings: JsValue,
        clock: js_sys::Function,
        on_progress: Option<js_sys::Function>,
    ) -> Result<NestResult, JsError> {
        let torches = self.torches(&settings)?;
        let (mut job, mut priced) = self.priced_job(settings)?;
        // A clock that throws or answers nonsense ends the search (the
        // budget is spent), never the page.
        let now = || js_clock(&clock);
        let start = now();
        let mut shown: Option<Vec<crate::nest::Placement>> = None;
        let mut hear = |p: Progress| tell(on_progress.as_ref(), &mut shown, p, false);
        // Several torches (paper 001 §6.5): torch 1's band is nested.
        let (mut n, torches) = match (torches, &mut priced) {
            (Some(t), _) => {
                let tn = nest::torches::nest_torches(&job, &t, &now, &mut hear).map_err(err)?;
                (tn.nest, Some((t, tn.band)))
            }
            // Sheets at a cost: the CLI's trials, each nested as `nest`
            // nests (`kerfcam nest` with one thread).
            (None, Some(p)) => {
                let trial = std::cell::RefCell::new(None::<WebTrial>);
                let mut shown: Option<Vec<crate::nest::Placement>> = None;
                let mut told: Option<WebTrial> = None;
                let c = stock::nest_cheapest_by(
                    &job,
                    &p.stock,
                    &now,
                    &mut |t, go| {
                        *trial.borrow_mut() = Some(WebTrial {
                            counts: t.counts.to_vec(),
                            passed_over: t.passed_over,
                        });
                        nest::nest(t.job, &now, go)
                    },
                    &mut |prog| {
                        let now_trying = trial.borrow().clone();
                        // A new combination is drawn afresh, whatever its placements.
                        if now_trying != told {
                            shown = None;
                            told.clone_from(&now_trying);
                        }
                        tell_trial(on_progress.as_ref(), &mut shown, prog, true, now_trying)
                    },
                )
                .map_err(err)?;
                p.counts = c.counts;
                p.passed_over = c.tried;
                job = c.job;
                (c.nest, None)
            }
            (None, None) => (nest::nest(&job, &now, &mut hear).map_err(err)?, None),
        };
        let seconds = now() - start;
        n.unplaced.splice(0..0, self.notes.iter().cloned());
        Ok(NestResult {
            lang: self.lang,
            job,
            nest: n,
            seconds: if seconds.is_finite() { seconds } else { 0.0 },
            conflicts: Vec::new(),
            crop: None,
            torches,
            labels: None,
            priced,
        })
    }
}
