//! Why nesting could not start ([`NestError`]): said in English and
//! Portuguese, the settings named as the CLI names them.

use std::fmt;

use super::MAX_QUANTITY;

/// Why nesting could not start.
#[derive(Clone, Debug, PartialEq)]
pub enum NestError {
    /// No part has a copy to place.
    NoParts,
    /// A quantity above [`MAX_QUANTITY`].
    TooMany {
        /// The part.
        part: String,
        /// What was asked.
        quantity: usize,
    },
    /// A setting out of range.
    Setting {
        /// Which.
        field: &'static str,
        /// Why, in every language.
        reason: crate::warning::Text,
    },
    /// An instance file that is not the ESICUP JSON format.
    Instance(String),
    /// A sheet drawing (a remnant) with no closed outline to be the sheet.
    NoSheetOutline,
}

impl NestError {
    /// The message in English and Portuguese. Settings and instance files
    /// are named in English (their fields are the CLI's and the format's);
    /// an instance file's fault is said in English (it is the format's).
    pub fn text(&self) -> crate::warning::Text {
        match self {
            NestError::NoParts => crate::text!("no part to nest"; "nenhuma peça para encaixar"),
            NestError::TooMany { part, quantity } => crate::text!(
                "part {part}: quantity {quantity} is above the limit of {MAX_QUANTITY} copies";
                "peça {part}: quantidade {quantity} acima do limite de {MAX_QUANTITY} cópias"),
            NestError::NoSheetOutline => crate::text!(
                "the sheet drawing has no closed outline (outside the DEFECT layer) to be the sheet";
                "o desenho da chapa não tem contorno fechado (fora da camada DEFECT) para ser a chapa"),
            NestError::Setting { field, reason } => crate::warning::Text::new(
                format!("{field}: {}", reason.en),
                format!("{field}: {}", reason.pt),
            ),
            NestError::Instance(_) => {
                let en = self.to_string();
                crate::warning::Text::new(en.clone(), en)
            }
        }
    }
}

impl fmt::Display for NestError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NestError::Instance(why) => write!(f, "not an ESICUP nesting instance: {why}"),
            _ => f.write_str(&self.text().en),
        }
    }
}

impl std::error::Error for NestError {}
