//! Cut charts through the JavaScript boundary (issue 20 §1): the page keeps
//! a library as JSON in the browser and asks the core to read, check and
//! write it — a QtPlasmaC material file or kerfcam JSON in, either out — so
//! the page never parses a chart itself. The entry chosen for a job goes to
//! [`super::Job::new`] as `material` (its JSON) and is applied by
//! [`crate::Settings::with_material`], the CLI's `--material` path.
//!
//! ```js
//! const lib = materials_read(fileText, "pt-BR");   // throws naming entry and field
//! materials_check(JSON.stringify(edited), "en");    // "" or the message
//! materials_cfg(lib);                                // QtPlasmaC material file text
//! new Job(bytes, { material: JSON.stringify(lib.entries[2]) });
//! ```

use wasm_bindgen::prelude::*;

use super::lang_of;
use crate::materials::{Library, MaterialError};

fn err(e: MaterialError, lang: Option<&str>) -> JsError {
    JsError::new(&e.message(lang_of(lang)))
}

/// The starter chart (each entry an example, named "(example)") as JSON.
#[wasm_bindgen]
pub fn materials_starter() -> String {
    Library::starter().to_json()
}

/// A chart file's text (kerfcam JSON or a QtPlasmaC material file) as the
/// library's JSON; a material file is kept inside it, so it exports back
/// byte for byte. Throws the message naming the entry and field.
#[wasm_bindgen]
pub fn materials_read(text: &str, lang: Option<String>) -> Result<String, JsError> {
    Library::from_text(text)
        .map(|l| l.to_json())
        .map_err(|e| err(e, lang.as_deref()))
}

/// "" when the library's JSON is valid, else the message naming the entry
/// and field, in `lang`.
#[wasm_bindgen]
pub fn materials_check(json: &str, lang: Option<String>) -> String {
    match Library::from_json(json) {
        Ok(_) => String::new(),
        Err(e) => e.message(lang_of(lang.as_deref())),
    }
}

/// The library's plasma entries as a QtPlasmaC material file.
#[wasm_bindgen]
pub fn materials_cfg(json: &str, lang: Option<String>) -> Result<String, JsError> {
    Library::from_json(json)
        .map(|l| l.to_material_file())
        .map_err(|e| err(e, lang.as_deref()))
}
