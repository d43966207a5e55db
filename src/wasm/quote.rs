//! The quote in the page (issue 42 §3): the Cost panel's model (JSON)
//! checked field by field, and priced against a drawing's plan or every
//! sheet of a nest ([`crate::quote`]).

use wasm_bindgen::prelude::*;

use super::{lang_of, Job};
use crate::quote::{self, CostModel, SheetInput};

/// Checks a cost model given as JSON: "" when it is valid, else
/// `{"field", "message"}` (the message in `lang`, "en" when absent), for
/// the panel to show at the field.
#[wasm_bindgen]
pub fn check_cost(json: &str, lang: Option<String>) -> String {
    match CostModel::from_json(json) {
        Ok(_) => String::new(),
        Err(e) => serde_json::json!({
            "field": e.field,
            "message": e.message(lang_of(lang.as_deref())),
        })
        .to_string(),
    }
}

/// The model, or the error naming its field in the job's language.
pub(super) fn model(json: &str, lang: crate::warning::Lang) -> Result<CostModel, JsError> {
    CostModel::from_json(json).map_err(|e| JsError::new(&e.message(lang)))
}

impl Job {
    /// The quote of this one drawing (on no sheet), parts named `name#n`.
    fn quote_of(&self, cost: &str, name: &str) -> Result<quote::Quote, JsError> {
        let lang = self.settings.lang;
        let m = model(cost, lang)?;
        let sheet = SheetInput {
            out: &self.out,
            used_area_mm2: None,
            cost: None,
        };
        quote::quote(&m, &[sheet], &|p| format!("{name}#{p}"))
            .map_err(|e| JsError::new(&e.message(lang)))
    }
}

#[wasm_bindgen]
impl Job {
    /// The quote of this job at `cost`'s prices (a cost model as JSON), as
    /// JSON ([`crate::quote::Quote`]); parts named `name#n`. A drawing is
    /// on no sheet: the model's material share must be "area".
    pub fn quote_json(&self, cost: &str, name: &str) -> Result<String, JsError> {
        let q = self.quote_of(cost, name)?;
        serde_json::to_string(&q).map_err(|e| JsError::new(&e.to_string()))
    }

    /// [`Job::quote_json`] as CSV (`kerfcam --quote`'s), in the
    /// spreadsheet convention of `lang` (the page's now; the job's when
    /// absent): `;` and `,` decimals in pt-BR ([`quote::Convention`]).
    pub fn quote_csv(&self, cost: &str, name: &str, lang: Option<String>) -> Result<String, JsError> {
        let lang = lang.map_or(self.settings.lang, |l| lang_of(Some(&l)));
        let c = quote::Convention::of(lang);
        Ok(quote::to_csv_in(&self.quote_of(cost, name)?, c))
    }
}
