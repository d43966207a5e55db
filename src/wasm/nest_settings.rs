//! The nest's settings as the page sends them (issue 16, issue 18's Sheet
//! mode): each part file's options and the nest's own settings, read from
//! their JavaScript objects; what is not given takes its defaults, as in
//! `kerfcam nest`.

use serde::Deserialize;
use wasm_bindgen::prelude::*;

use crate::nest::NestSpec;

/// Per file: how many copies and how they may turn.
#[derive(Deserialize)]
#[serde(default)]
pub(super) struct WebPart {
    /// Copies of every part in the file…
    pub(super) quantity: usize,
    /// …or per part, in the file's part order (wins where given).
    pub(super) quantities: Vec<usize>,
    /// Each part's own choices, in the file's part order (issue 42 §1:
    /// a row per part); what a part does not give is the file's.
    pub(super) each: Vec<EachPart>,
    /// "none", "180", "90", "free" or a number of steps.
    pub(super) rotations: String,
    pub(super) mirror: bool,
    /// The unit the file is read in ("mm", "in", "cm", …), whatever it
    /// says; empty: its own ($INSUNITS, or mm assumed). The page's per-file
    /// unit switch (issue 18 item 1): an inch file is not nested at 1/25.4.
    pub(super) units: String,
}

/// One part's choices within its file.
#[derive(Default, Deserialize)]
#[serde(default)]
pub(super) struct EachPart {
    pub(super) quantity: Option<usize>,
    pub(super) rotations: Option<String>,
    pub(super) mirror: Option<bool>,
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
pub(super) struct WebNest {
    pub(super) sheet_width: Option<f64>,
    pub(super) sheet_height: Option<f64>,
    pub(super) sheet_count: Option<usize>,
    /// Sheets of several sizes, filled in this order (issue 16 item 6):
    /// when given, it is the sheets, and `sheet_width`, `sheet_height`
    /// and `sheet_count` (the first size, for the page's own figures) are
    /// not read.
    pub(super) sheet_list: Option<Vec<WebSheetSize>>,
    /// With costs: the combination nested (sheets of each size), for a
    /// nest made again without a search (`restore`, a team's `search`
    /// that adopts a stopped nest); `nest` finds its own.
    pub(super) combination: Option<Vec<usize>>,
    /// With `combination`: the combinations nested before it that did not
    /// hold every copy (the report's).
    pub(super) passed_over: Option<usize>,
    pub(super) strip_height: Option<f64>,
    pub(super) spacing: Option<f64>,
    pub(super) margin: Option<f64>,
    pub(super) tolerance: Option<f64>,
    pub(super) time_s: Option<f64>,
    pub(super) seed: Option<u64>,
    pub(super) max_evaluations: Option<u64>,
    /// The budget of the run a Stop replays (its `time_s`), when the
    /// replay's clock is longer.
    pub(super) budget_s: Option<f64>,
    pub(super) torches: Option<usize>,
    pub(super) torch_spacing: Option<f64>,
    pub(super) torch_park: Option<[f64; 2]>,
}

impl WebNest {
    /// The settings as given, without `None` for an absent page field.
    pub(super) fn of(settings: &JsValue) -> Result<WebNest, JsError> {
        if settings.is_undefined() || settings.is_null() {
            return Ok(WebNest::default());
        }
        serde_wasm_bindgen::from_value(settings.clone())
            .map_err(|e| err(format!("nest settings: {e}")))
    }
    /// The nest's own settings.
    pub(super) fn spec(&self) -> NestSpec {
        NestSpec {
            spacing: self.spacing,
            margin: self.margin,
            tolerance: self.tolerance,
            time_s: self.time_s,
            seed: self.seed,
            max_evaluations: self.max_evaluations,
            budget_s: self.budget_s,
            torches: self.torches,
            torch_spacing: self.torch_spacing,
            torch_park: self.torch_park,
        }
    }
}

/// `count` sheets `width` × `height`, mm: one size of a list, at `cost`
/// a sheet when given (null or absent: none).
#[derive(Deserialize)]
pub(super) struct WebSheetSize {
    pub(super) width: f64,
    pub(super) height: f64,
    pub(super) count: usize,
    #[serde(default)]
    pub(super) cost: Option<WebCost>,
}

/// A cost as the page sends it: a number, or text it could not read
/// (refused naming its size, not as a JSON type error).
#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum WebCost {
    Number(f64),
    Text(String),
}

/// Whether `settings` name the combination of a nest at a cost (read by
/// `restore` and a team's `search`, not by `nest`).
pub(super) fn combination_given(settings: &JsValue) -> bool {
    WebNest::of(settings).is_ok_and(|w| w.combination.is_some())
}

fn err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}
