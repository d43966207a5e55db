//! A setting out of range: what validating a job's settings (src/settings/)
//! and a process's values (src/process/) refuses with.

use std::fmt;

use crate::text;
use crate::warning::{Lang, Text};

/// A setting outside its range.
#[derive(Clone, Debug, PartialEq)]
pub struct SettingsError {
    /// The setting's name.
    pub field: &'static str,
    /// What is wrong, in every language.
    pub reason: Text,
}

impl SettingsError {
    /// The message in every language.
    pub fn text(&self) -> Text {
        let (field, r) = (self.field, &self.reason);
        text!("setting '{field}': {}", r.en; "configuração '{field}': {}", r.pt)
    }
    /// The message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl fmt::Display for SettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text().en)
    }
}

impl std::error::Error for SettingsError {}
