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
//!
//! The settings as the page sends them are `nest_settings.rs`, the job
//! and stock they make `nest_job.rs`, the progress the page hears
//! `nest_progress.rs`.

use wasm_bindgen::prelude::*;

use super::nest_progress::{js_clock, tell, tell_trial, WebTrial};
use super::nest_result::NestResult;
use super::nest_settings::WebPart;
use super::{lang_of, say};
use crate::dxf::Units;
use crate::nest::stock;
use crate::nest::{self, Part, Progress, Rotations, Sheets, Unplaced};
use crate::text;
use crate::warning::Lang;
use crate::{Settings, Spec};

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
    pub(super) parts: Vec<Part>,
    pub(super) notes: Vec<Unplaced>,
    pub(super) sheet: Option<Sheets>,
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
    pub(super) fn cutting(&self) -> Result<Settings, JsError> {
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
        let (n, torches) = match (torches, &mut priced) {
            (Some(t), _) => {
                let tn = nest::torches::nest_torches(&job, &t, &now, &mut hear)
                    .map_err(|e| say(self.lang, e.text()))?;
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
                .map_err(|e| say(self.lang, e.text()))?;
                p.counts = c.counts;
                p.passed_over = c.tried;
                job = c.job;
                (c.nest, None)
            }
            (None, None) => (
                nest::nest(&job, &now, &mut hear).map_err(|e| say(self.lang, e.text()))?,
                None,
            ),
        };
        let seconds = now() - start;
        Ok(NestResult::fresh(
            self.lang,
            job,
            n,
            &self.notes,
            seconds,
            torches,
            priced,
        ))
    }
}
