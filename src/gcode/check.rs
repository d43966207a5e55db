//! Checks of a post's fields, and its templates: lines of literal text with
//! typed variables (`{feed}`), never free text from the DXF.

use std::fmt;

use crate::text;
use crate::warning::{dec, Lang, Text};

/// An invalid post, naming the field.
#[derive(Clone, Debug, PartialEq)]
pub struct PostError {
    /// The field (`header[2]`, `decimals`, …).
    pub field: String,
    /// What is wrong, in every language.
    pub reason: Text,
}

impl PostError {
    /// The message in every language.
    pub fn text(&self) -> Text {
        let (field, r) = (&self.field, &self.reason);
        text!("post field '{field}': {}", r.en; "campo '{field}' do pós-processador: {}", r.pt)
    }
    /// The message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl fmt::Display for PostError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text().en)
    }
}

impl std::error::Error for PostError {}

pub(crate) fn err(field: impl Into<String>, reason: Text) -> PostError {
    PostError {
        field: field.into(),
        reason,
    }
}

/// The template variables, all numbers from the job or the plan.
pub const VARS: [&str; 23] = [
    "feed",
    "small_hole_feed",
    "small_hole_speed",
    "pierce_height",
    "cut_height",
    "material",
    "switch_offset",
    "safe_height",
    "probe_feed",
    "probe_distance",
    "kerf",
    "pierce_delay",
    "pierce_delay_ms",
    "est_time_s",
    "cuts",
    "pierces",
    "program",
    "rapid_speed",
    "pass_z",
    "spindle_rpm",
    "tool_number",
    "plunge_feed",
    "retract_height",
];

/// One piece of a template: literal text or a variable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Piece<'a> {
    /// Text as written.
    Text(&'a str),
    /// One of [`VARS`].
    Var(&'a str),
}

/// Splits a template into text and variables; an unknown or unclosed
/// variable is an error naming `field`.
pub fn parse_template<'a>(t: &'a str, field: &str) -> Result<Vec<Piece<'a>>, PostError> {
    let mut out = Vec::new();
    let mut rest = t;
    while let Some(open) = rest.find('{') {
        if open > 0 {
            out.push(Piece::Text(&rest[..open]));
        }
        let after = &rest[open + 1..];
        let close = after.find('}').ok_or_else(|| {
            err(
                field,
                text!("a '{{' is not closed"; "um '{{' não foi fechado"),
            )
        })?;
        let name = &after[..close];
        if !VARS.contains(&name) {
            let known = VARS.join(", ");
            return Err(err(
                field,
                text!("unknown variable {{{name}}} (known: {known})";
                      "variável desconhecida {{{name}}} (conhecidas: {known})"),
            ));
        }
        out.push(Piece::Var(name));
        rest = &after[close + 1..];
    }
    if rest.contains('}') {
        return Err(err(field, text!("a '}}' without '{{'"; "um '}}' sem '{{'")));
    }
    if !rest.is_empty() {
        out.push(Piece::Text(rest));
    }
    Ok(out)
}

/// Free text the user typed into a post: printable ASCII, one line, short.
pub(crate) fn check_text(field: &str, s: &str, max: usize) -> Result<(), PostError> {
    if s.len() > max {
        return Err(err(
            field,
            text!("longer than {max} characters"; "mais longo que {max} caracteres"),
        ));
    }
    if let Some(c) = s.chars().find(|c| !(c.is_ascii_graphic() || *c == ' ')) {
        return Err(err(
            field,
            text!("character {c:?} is not printable ASCII on one line";
                  "o caractere {c:?} não é ASCII imprimível em uma linha"),
        ));
    }
    Ok(())
}

pub(crate) fn check_lines(field: &str, lines: &[String], templates: bool) -> Result<(), PostError> {
    if lines.len() > 64 {
        return Err(err(field, text!("more than 64 lines"; "mais de 64 linhas")));
    }
    for (i, l) in lines.iter().enumerate() {
        let f = format!("{field}[{i}]");
        check_text(&f, l, 200)?;
        if templates {
            parse_template(l, &f)?;
        }
    }
    Ok(())
}

pub(crate) fn check_word(field: &str, w: &str) -> Result<(), PostError> {
    let ok = !w.is_empty()
        && w.len() <= 8
        && w.starts_with(|c: char| c.is_ascii_alphabetic())
        && w.chars().all(|c| c.is_ascii_alphanumeric() || c == '.');
    if ok {
        Ok(())
    } else {
        Err(err(
            field,
            text!("'{w}' is not a word like G1"; "'{w}' não é uma palavra como G1"),
        ))
    }
}

pub(crate) fn check_num(field: &str, v: f64, min: f64, max: f64) -> Result<(), PostError> {
    if v.is_finite() && v >= min && v <= max {
        Ok(())
    } else {
        Err(err(
            field,
            text!("{v} is not between {min} and {max}"; "{} não está entre {} e {}", dec(v), dec(min), dec(max)),
        ))
    }
}

/// Words of a block without separators, upper case ("M30 " → "M30").
pub(crate) fn has_program_end(lines: &[String]) -> bool {
    lines.iter().any(|l| {
        let u = l.to_ascii_uppercase();
        let mut rest = u.as_str();
        while let Some(i) = rest.find('M') {
            let digits: String = rest[i + 1..]
                .chars()
                .skip_while(|c| *c == ' ')
                .take_while(|c| c.is_ascii_digit())
                .collect();
            if let Ok(n) = digits.parse::<u32>() {
                if n == 2 || n == 30 {
                    return true;
                }
            }
            rest = &rest[i + 1..];
        }
        false
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn templates_know_only_typed_variables() {
        assert_eq!(
            parse_template("F{feed}", "h").unwrap(),
            vec![Piece::Text("F"), Piece::Var("feed")]
        );
        let e = parse_template("({layer})", "header[1]").unwrap_err();
        assert_eq!(e.field, "header[1]");
        assert!(parse_template("F{feed", "h").is_err());
        assert!(parse_template("F}", "h").is_err());
    }

    #[test]
    fn program_end_is_found_in_any_spelling() {
        assert!(has_program_end(&["M02".into()]));
        assert!(has_program_end(&["G0 X0 M30".into()]));
        assert!(!has_program_end(&["M25".into(), "M5".into()]));
    }
}
