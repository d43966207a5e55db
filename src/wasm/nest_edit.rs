//! A nest adjusted by hand through the JavaScript boundary (issue 18 item
//! 4, paper 001 §6.2): the page draws the parts from their outlines, sends
//! the placements as the operator left them, and hears back which copies
//! break the rules and the figures as they now stand; the crop line may be
//! moved. What is cut and saved afterwards is the edited nest.
//!
//! ```js
//! const parts = JSON.parse(nester.outlines());       // [{name, d}] per part index
//! let s = JSON.parse(result.state());                // figures, placements, conflicts
//! s = JSON.parse(result.edit(JSON.stringify({ placements: [[part, copy, sheet, rot, mirror, x, y], …], crop: 'auto' })));
//! s = JSON.parse(result.snap(3));                    // copy 3 butted left then down
//! if (!s.conflicts.length) result.cut(0, settings);  // cut refuses a nest in conflict
//! ```

use wasm_bindgen::prelude::*;

use super::nest_json::{flat_placements, outlines_json, sheet_shape, PER_COPY};
use super::nest_result::NestResult;
use super::nesting::Nester;
use crate::nest::edit::{Checker, Conflict, Why};
use crate::nest::figures::{crop_range, figures};
use crate::nest::{output, Nest, Placement, Sheets, MAX_QUANTITY};

/// Most copies an edit may hold (a typing error beyond).
const MAX_COPIES: usize = 100_000;
/// Farthest a copy may be put from the sheet's corner, mm.
const FAR: f64 = 1e7;

fn why_json(c: &Conflict) -> serde_json::Value {
    let (why, with) = match c.why {
        Why::Overlap { with } => ("overlap", Some(with)),
        Why::Spacing { with } => ("spacing", Some(with)),
        Why::OffSheet => ("off-sheet", None),
        Why::Margin => ("margin", None),
        Why::NoGo => ("no-go", None),
    };
    serde_json::json!({ "copy": c.copy, "why": why, "with": with })
}

/// A nest edit or nest file refused, in the page's language.
fn bad(lang: crate::warning::Lang, what: crate::warning::Text) -> JsError {
    let t = crate::text!("nest edit: {}", what.en; "ajuste do encaixe: {}", what.pt);
    JsError::new(t.get(lang))
}

impl NestResult {
    /// Hand edits check a copy against the sheet and its neighbours under
    /// one torch; with several torches its copies under the others, and
    /// the band, would not be checked: refused rather than cut wrong.
    fn by_hand(&self) -> Result<(), JsError> {
        match self.torches {
            Some((t, _)) => Err(super::say(
                self.lang,
                crate::text!("a nest for {} torches is not adjusted by hand: nest again to change it", t.count;
                             "um encaixe para {} tochas não é ajustado à mão: encaixe de novo para mudá-lo", t.count),
            )),
            None => Ok(()),
        }
    }
    /// Checks the placements as they stand; figures, hosts and conflicts follow.
    fn recheck(&mut self) {
        let checker = Checker::new(&self.job);
        let (conflicts, host) = checker.check(&self.nest.placements);
        let ids: Vec<(usize, usize)> = self
            .nest
            .placements
            .iter()
            .map(|p| (p.part, p.copy))
            .collect();
        for (p, h) in self.nest.placements.iter_mut().zip(host) {
            p.in_hole_of = h.map(|h| ids[h]);
        }
        let n = self.nest.sheets.len();
        let (sheets, density) = figures(&self.job, &self.nest.placements, n, self.crop);
        self.nest.sheets = sheets;
        self.nest.density = density;
        self.conflicts = conflicts;
    }
}

#[wasm_bindgen]
impl NestResult {
    /// Each part's outline as an SVG path, JSON `[{name, d}]` by part index.
    pub fn outlines(&self) -> String {
        outlines_json(&self.job.parts)
    }

    /// The nest as it stands: `json()`'s figures and placements, plus
    /// `flat` (7 numbers a copy, part indices), `conflicts` ([{copy, why:
    /// overlap | spacing | off-sheet | margin | no-go, with}]) and
    /// `crop_range` ([from, to] where the last sheet's crop line may go, or
    /// null), `remnant_area` (mm² beyond the crop line, or null),
    /// `sheet_shape` ({path, box}: the sheet drawn) and `margin`.
    pub fn state(&self) -> String {
        let mut j = output::to_json(&self.job, &self.nest, self.seconds, self.lang);
        let last = self.nest.sheets.len().saturating_sub(1);
        j["flat"] = serde_json::json!(flat_placements(&self.nest.placements));
        j["sheet_shape"] = sheet_shape(&self.job.sheets);
        j["margin"] = serde_json::json!(self.job.settings.margin);
        if let Some(p) = &self.priced {
            p.add_to(&mut j, &self.nest);
        }
        j["conflicts"] = self.conflicts.iter().map(why_json).collect();
        if let Some(tn) = self.torch_nest() {
            j["torches"] = crate::nest::torches::to_json(&self.job, &tn, self.seconds, self.lang)
                ["torches"]
                .take();
        }
        if self.labels.is_some() {
            j["labels"] = self.labels_value();
        }
        j["crop_range"] = serde_json::json!(crop_range(&self.job, &self.nest.placements, last));
        let crop = self.nest.sheets.last().and_then(|s| s.crop_x);
        j["remnant_area"] = serde_json::json!(crop.map(|_| {
            crate::nest::remnant::areas(
                &self.job.sheets.sheet(last),
                crop,
                self.job.settings.tolerance,
            )
            .1
        }));
        j.to_string()
    }

    /// Replaces the placements (`{placements: [[part, copy, sheet,
    /// rotation, mirror, x, y], …]}`) and/or the crop line (`crop`: a
    /// number, "auto" after the last part, "none"), checks them and
    /// answers `state()`. Throws (changing nothing) for a part or sheet
    /// that does not exist or numbers that are not numbers.
    pub fn edit(&mut self, json: &str) -> Result<String, JsError> {
        self.by_hand()?;
        let lang = self.lang;
        let v: serde_json::Value = serde_json::from_str(json)
            .map_err(|e| bad(lang, crate::text!("not JSON ({e})"; "não é JSON ({e})")))?;
        let crop = match &v["crop"] {
            serde_json::Value::Null => self.crop,
            serde_json::Value::String(s) if s == "auto" => None,
            serde_json::Value::String(s) if s == "none" => Some(None),
            x => match x.as_f64() {
                Some(x) if x.is_finite() && x.abs() < FAR => Some(Some(x)),
                _ => {
                    return Err(bad(
                        lang,
                        crate::text!("crop is a number, \"auto\" or \"none\""; "crop é um número, \"auto\" ou \"none\""),
                    ))
                }
            },
        };
        if let Some(list) = v.get("placements") {
            let list = list.as_array().ok_or_else(|| {
                bad(
                    lang,
                    crate::text!("placements is a list"; "placements é uma lista"),
                )
            })?;
            if list.len() > MAX_COPIES {
                let n = list.len();
                return Err(bad(
                    lang,
                    crate::text!("{n} copies: at most {MAX_COPIES}"; "{n} cópias: no máximo {MAX_COPIES}"),
                ));
            }
            let (parts, sheets) = (self.job.parts.len(), self.nest.sheets.len());
            let mut ps = Vec::with_capacity(list.len());
            for (i, row) in list.iter().enumerate() {
                let n: Vec<f64> = row
                    .as_array()
                    .map(|r| r.iter().filter_map(|x| x.as_f64()).collect())
                    .unwrap_or_default();
                let ok = n.len() == PER_COPY
                    && n.iter().all(|x| x.is_finite() && x.abs() < FAR)
                    && n[..3].iter().all(|x| x.fract() == 0.0 && *x >= 0.0)
                    && (n[0] as usize) < parts
                    && (n[2] as usize) < sheets;
                if !ok {
                    return Err(bad(
                        lang,
                        crate::text!(
                            "copy {i}: [part < {parts}, copy, sheet < {sheets}, rotation, mirror, x, y] expected";
                            "cópia {i}: esperado [peça < {parts}, cópia, chapa < {sheets}, rotação, espelho, x, y]"
                        ),
                    ));
                }
                ps.push(Placement {
                    part: n[0] as usize,
                    copy: n[1] as usize,
                    sheet: n[2] as usize,
                    rotation: n[3],
                    mirror: n[4] != 0.0,
                    translation: crate::geom::Point::new(n[5], n[6]),
                    in_hole_of: None,
                });
            }
            self.nest.placements = ps;
        }
        self.crop = crop;
        self.recheck();
        Ok(self.state())
    }

    /// Copy `i` butted left then down against its neighbours at the
    /// spacing (paper 001's MOVEPECA), the copies in its holes along;
    /// answers `state()`.
    pub fn snap(&mut self, i: usize) -> Result<String, JsError> {
        self.by_hand()?;
        if i >= self.nest.placements.len() {
            return Err(bad(
                self.lang,
                crate::text!("no copy {i}"; "não há cópia {i}"),
            ));
        }
        Checker::new(&self.job).snap(&mut self.nest.placements, i);
        self.recheck();
        Ok(self.state())
    }
}

#[wasm_bindgen]
impl Nester {
    /// A nest saved before (a nest file: its placements as `state().flat`,
    /// its crop line) made again from these parts and `settings` (as
    /// `nest` takes them), without a search: `sheets` sheets, checked as a
    /// hand edit is. Throws for settings out of range, or placements that
    /// name a part or sheet that does not exist.
    pub fn restore(
        &self,
        settings: JsValue,
        sheets: usize,
        edit: &str,
    ) -> Result<NestResult, JsError> {
        let (job, priced) = self.priced_job(settings)?;
        let s = &job.settings;
        let ok = |v: f64| v.is_finite() && v >= 0.0;
        if !(ok(s.spacing) && ok(s.margin) && s.tolerance.is_finite() && s.tolerance > 0.0) {
            return Err(bad(
                self.lang,
                crate::text!("spacing, margin and tolerance are distances ≥ 0"; "espaçamento, margem e tolerância são distâncias ≥ 0"),
            ));
        }
        // Every rectangle's size checked; a list holds the sum of its counts.
        let sizes: Vec<(f64, f64)> = match &job.sheets {
            Sheets::Rect { width, height, .. } => vec![(*width, *height)],
            Sheets::Mixed(v) => v.iter().map(|s| (s.width, s.height)).collect(),
            _ => Vec::new(),
        };
        for (width, height) in sizes {
            if !(width.is_finite() && height.is_finite() && width > 0.0 && height > 0.0) {
                return Err(bad(
                    self.lang,
                    crate::text!("{width} × {height} is not a sheet size"; "{width} × {height} não é um tamanho de chapa"),
                ));
            }
        }
        let count = job.sheets.count().min(MAX_QUANTITY);
        if sheets == 0 || sheets > count {
            return Err(bad(
                self.lang,
                crate::text!("{sheets} sheets: between 1 and {count}"; "{sheets} chapas: entre 1 e {count}"),
            ));
        }
        let (placeholder, _) = figures(&job, &[], sheets, None);
        let mut r = NestResult {
            lang: self.lang,
            job,
            nest: Nest {
                placements: Vec::new(),
                sheets: placeholder,
                unplaced: self.notes.clone(),
                strip_length: None,
                density: 0.0,
                evaluations: 0,
            },
            seconds: 0.0,
            conflicts: Vec::new(),
            crop: None,
            torches: None,
            labels: None,
            priced,
        };
        r.edit(edit)?;
        Ok(r)
    }
}
