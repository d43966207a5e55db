//! Warnings: what a stage skipped, changed or could not do, and where.
//!
//! Geometry stages never fail: they return what they could make plus
//! warnings, so the user sees every entity that was not used and why.
//!
//! Every message exists in English and Brazilian Portuguese. A site writes
//! both side by side with [`text!`](crate::text): the macro takes exactly two
//! format strings, so a message without its translation does not compile, and
//! the two texts stay next to the code that knows what they mean (a catalogue
//! of keys far from the sites drifts). Each warning also has a stable `code`
//! ("units-missing") for scripts, which must never parse the text.

use std::fmt;

use serde::Serialize;

use crate::geom::Point;

/// The languages of the messages.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Lang {
    /// English (the default, and the language of the tests).
    #[default]
    En,
    /// Brazilian Portuguese, in the trade's terms (sangria de corte, perfuração, entrada…).
    PtBr,
}

impl Lang {
    /// Every language, for tests and menus.
    pub const ALL: [Lang; 2] = [Lang::En, Lang::PtBr];

    /// "en" or "pt-BR" (BCP 47).
    pub fn name(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::PtBr => "pt-BR",
        }
    }

    /// "en", "en-US" → English; "pt", "pt-BR", "pt_br" → Portuguese; anything else: None.
    pub fn from_name(name: &str) -> Option<Lang> {
        let n = name.trim().to_ascii_lowercase();
        let base = n.split(['-', '_']).next().unwrap_or("");
        match base {
            "en" => Some(Lang::En),
            "pt" => Some(Lang::PtBr),
            _ => None,
        }
    }
}

/// One message in every language; as JSON `{"en": …, "pt-BR": …}`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Text {
    /// English.
    pub en: String,
    /// Brazilian Portuguese.
    #[serde(rename = "pt-BR")]
    pub pt: String,
}

impl Text {
    /// The two texts (use [`text!`](crate::text) at message sites).
    pub fn new(en: impl Into<String>, pt: impl Into<String>) -> Text {
        Text {
            en: en.into(),
            pt: pt.into(),
        }
    }

    /// The text in `lang`.
    pub fn get(&self, lang: Lang) -> &str {
        match lang {
            Lang::En => &self.en,
            Lang::PtBr => &self.pt,
        }
    }
}

/// English, so `{}` and logs read as before.
impl fmt::Display for Text {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.en)
    }
}

/// A number shown with a decimal comma, for Portuguese texts: `text!("{w} mm"; "{} mm", dec(w))`.
/// Keeps the format's precision (`{:.3}`). Messages only: programs never go through it.
pub fn dec<T: fmt::Display>(v: T) -> Dec<T> {
    Dec(v)
}

/// See [`dec`].
pub struct Dec<T>(T);

impl<T: fmt::Display> fmt::Display for Dec<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = match f.precision() {
            Some(p) => format!("{:.*}", p, self.0),
            None => self.0.to_string(),
        };
        // Not `pad`: it would cut the text to the precision.
        f.write_str(&s.replace('.', ","))
    }
}

/// A message in English and Portuguese, each a `format!` string with its arguments:
/// `text!("{n} lines skipped"; "{n} linhas ignoradas")` or
/// `text!("{} lines skipped", v.len(); "{} linhas ignoradas", v.len())`.
/// (No named arguments: `n = x` would parse as an assignment.)
#[macro_export]
macro_rules! text {
    ($en:literal $(, $ea:expr)* ; $pt:literal $(, $pa:expr)* $(,)?) => {
        $crate::warning::Text::new(format!($en $(, $ea)*), format!($pt $(, $pa)*))
    };
}

/// One message for the user, with the drawing location it is about.
#[derive(Clone, Debug, PartialEq)]
pub struct Warning {
    /// Stable short name of the kind of warning ("units-missing"), for scripts.
    pub code: &'static str,
    /// Human-readable, one line, no trailing period, in every language.
    pub text: Text,
    /// Where in the drawing (mm), when the warning is about one place.
    pub at: Option<Point>,
}

impl Warning {
    /// A warning about the whole drawing.
    pub fn new(code: &'static str, text: Text) -> Self {
        Warning {
            code,
            text,
            at: None,
        }
    }
    /// A warning about one place in the drawing.
    pub fn at(code: &'static str, text: Text, at: Point) -> Self {
        Warning {
            code,
            text,
            at: Some(at),
        }
    }
    /// A warning about one place, when the place is known.
    pub fn maybe_at(code: &'static str, text: Text, at: Option<Point>) -> Self {
        Warning { code, text, at }
    }
    /// The English message.
    pub fn message(&self) -> &str {
        &self.text.en
    }
    /// The message in `lang`.
    pub fn message_in(&self, lang: Lang) -> &str {
        self.text.get(lang)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lang_names() {
        for l in Lang::ALL {
            assert_eq!(Lang::from_name(l.name()), Some(l));
        }
        assert_eq!(Lang::from_name("pt"), Some(Lang::PtBr));
        assert_eq!(Lang::from_name("PT_br"), Some(Lang::PtBr));
        assert_eq!(Lang::from_name("en-GB"), Some(Lang::En));
        assert_eq!(Lang::from_name("de"), None);
    }

    #[test]
    fn text_macro_formats_both() {
        let n = 3;
        let t = text!("{n} holes"; "{} furos", n);
        assert_eq!(t.get(Lang::En), "3 holes");
        assert_eq!(t.get(Lang::PtBr), "3 furos");
        assert_eq!(t.to_string(), "3 holes");
    }

    #[test]
    fn dec_writes_a_decimal_comma_with_the_asked_precision() {
        let (w, side) = (1.5, 12.34567);
        let t = text!("{w} mm, {side:.3}"; "{} mm, {:.3}", dec(w), dec(side));
        assert_eq!(t.en, "1.5 mm, 12.346");
        assert_eq!(t.pt, "1,5 mm, 12,346");
        assert_eq!(format!("{}", dec(-3)), "-3");
    }
}
