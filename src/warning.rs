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
//! ("units-assumed") for scripts, which must never parse the text.

use std::fmt;

use serde::Serialize;

use crate::geom::Point;
use crate::source::ContourRef;

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

/// How much a warning matters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// The program would damage parts or the result is untrustworthy.
    Error,
    /// Something the user must look at.
    Warning,
    /// What was repaired or decided, for the record.
    Info,
}

/// Codes by what they put at risk, most serious first: a file read at the
/// wrong scale or cut short makes every later figure wrong; then parts cut
/// into; then geometry not cut; repairs and notes last. Codes not listed
/// are plain warnings, after the listed ones.
const RANKED: &[(&str, Severity)] = &[
    ("cuts-into-parts", Severity::Error),
    ("verify-overcut", Severity::Error),
    ("verify-not-freed", Severity::Error),
    ("mill-gouge", Severity::Error),
    ("units-assumed", Severity::Warning),
    ("file-truncated", Severity::Warning),
    ("read-stopped", Severity::Warning),
    ("size-implausible", Severity::Warning),
    ("units-contradictory", Severity::Warning),
    ("units-not-length", Severity::Warning),
    ("too-many-segments", Severity::Warning),
    ("parts-closer-than-kerf", Severity::Warning),
    ("parts-share-edges", Severity::Warning),
    ("features-narrower-than-kerf", Severity::Warning),
    ("part-freed-before-holes", Severity::Warning),
    ("kerf-not-compensated", Severity::Warning),
    ("layer-ignored", Severity::Warning),
    ("holes-spotted", Severity::Warning),
    ("no-geometry", Severity::Warning),
    ("self-crossing", Severity::Warning),
    ("self-crossing-empty", Severity::Warning),
    ("self-crossing-repaired", Severity::Warning),
    ("kerf-vanishes", Severity::Warning),
    ("contour-degenerate", Severity::Warning),
    ("healed", Severity::Info),
    ("spline-note", Severity::Info),
    ("origin-moved", Severity::Info),
    ("engrave-v", Severity::Info),
];

/// Place in the ranking of `code` (unlisted warnings after listed
/// warnings, before notes).
fn rank(code: &str) -> (Severity, usize) {
    match RANKED.iter().position(|(c, _)| *c == code) {
        Some(i) => (RANKED[i].1, i),
        None => (Severity::Warning, RANKED.len()),
    }
}

/// What a warning says the program does to the drawn parts, when it is
/// a loss the operator must see before the cut (issue 45 §3): the page
/// lists these first, marks their loops on the preview and says it on
/// the Download button.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Loss {
    /// The cuts take material from parts (the kerf eats into them).
    CutsInto,
    /// Drawn loops left uncut: a part not cut free, a hole left in.
    NotCut,
}

/// The codes that say a loss, and which.
const LOSSES: &[(&str, Loss)] = &[
    ("cuts-into-parts", Loss::CutsInto),
    ("verify-overcut", Loss::CutsInto),
    ("parts-closer-than-kerf", Loss::CutsInto),
    ("parts-share-edges", Loss::CutsInto),
    ("verify-not-freed", Loss::NotCut),
    ("mill-gouge", Loss::CutsInto),
    ("mill-left", Loss::NotCut),
    ("pocket-contours-cross", Loss::NotCut),
    ("features-narrower-than-kerf", Loss::NotCut),
    ("self-crossing", Loss::NotCut),
    ("kerf-vanishes", Loss::NotCut),
    ("hole-splits", Loss::NotCut),
    ("inside-splits", Loss::NotCut),
];

/// Most places kept on a grouped warning.
pub const MAX_PLACES: usize = 5;

/// One message for the user, with the drawing location it is about.
#[derive(Clone, Debug, PartialEq)]
pub struct Warning {
    /// Stable short name of the kind of warning ("units-assumed"), for scripts.
    pub code: &'static str,
    /// Human-readable, one line, no trailing period, in every language.
    pub text: Text,
    /// Where in the drawing (mm), when the warning is about one place.
    pub at: Option<Point>,
    /// How many warnings this one stands for (1 unless [`group`]ed).
    pub count: usize,
    /// The first places of the warnings grouped into this one, mm.
    pub places: Vec<Point>,
    /// What instances of this warning share ("LWPOLYLINE skipped: …"),
    /// and the place that differs ("line 12"), for [`group`].
    pub kind: Option<(Text, Text)>,
    /// The drawn loops it is about, by identity (part, copy, loop): those
    /// a [`Loss`] takes from or leaves uncut, which the page marks.
    pub loops: Vec<ContourRef>,
}

impl Warning {
    /// A warning about the whole drawing.
    pub fn new(code: &'static str, text: Text) -> Self {
        Warning::maybe_at(code, text, None)
    }
    /// A warning about one place in the drawing.
    pub fn at(code: &'static str, text: Text, at: Point) -> Self {
        Warning::maybe_at(code, text, Some(at))
    }
    /// A warning about one place, when the place is known.
    pub fn maybe_at(code: &'static str, text: Text, at: Option<Point>) -> Self {
        Warning {
            code,
            text,
            at,
            count: 1,
            places: at.into_iter().collect(),
            kind: None,
            loops: Vec::new(),
        }
    }
    /// The same warning about the drawn loops `loops` (sorted, once each).
    pub fn with_loops(mut self, loops: impl IntoIterator<Item = ContourRef>) -> Self {
        self.loops.extend(loops);
        crate::sort::sort_by(&mut self.loops, Ord::cmp);
        self.loops.dedup();
        self
    }
    /// The loss it says, if any ([`LOSSES`]).
    pub fn loss(&self) -> Option<Loss> {
        LOSSES
            .iter()
            .find(|(c, _)| *c == self.code)
            .map(|&(_, l)| l)
    }
    /// The same warning, grouped with others of the same `kind` (the text
    /// they share) and telling them apart by `place` (the text that differs).
    pub fn of_kind(mut self, kind: Text, place: Text) -> Self {
        self.kind = Some((kind, place));
        self
    }
    /// The English message.
    pub fn message(&self) -> &str {
        &self.text.en
    }
    /// The message in `lang`.
    pub fn message_in(&self, lang: Lang) -> &str {
        self.text.get(lang)
    }
    /// How much it matters ([`RANKED`]).
    pub fn severity(&self) -> Severity {
        rank(self.code).0
    }
}

/// Sorts warnings most serious first (stable: stage order within a rank).
pub fn by_severity<'a>(ws: impl Iterator<Item = &'a Warning>) -> Vec<&'a Warning> {
    let mut v: Vec<&Warning> = ws.collect();
    crate::sort::sort_by_key(&mut v, |w| rank(w.code));
    v
}

/// Groups identical warnings: the same code and the same text, or the same
/// [`Warning::of_kind`]. A group of several becomes one warning that says
/// how many and where the first are ("599 × LWPOLYLINE skipped: polyline
/// has 1 vertex; first at line 12, line 40, …"), in the place of its first.
pub fn group(ws: Vec<Warning>) -> Vec<Warning> {
    if ws.len() < 2 {
        return ws;
    }
    let key = |w: &Warning| -> (&'static str, String) {
        let t = w.kind.as_ref().map_or(&w.text, |(k, _)| k);
        (w.code, t.en.clone())
    };
    let mut index: std::collections::HashMap<(&'static str, String), usize> =
        std::collections::HashMap::new();
    let mut groups: Vec<Vec<Warning>> = Vec::new();
    for w in ws {
        let k = key(&w);
        match index.get(&k) {
            Some(&i) => groups[i].push(w),
            None => {
                index.insert(k, groups.len());
                groups.push(vec![w]);
            }
        }
    }
    groups.into_iter().map(merge).collect()
}

/// One warning standing for all of `g` (same key).
fn merge(mut g: Vec<Warning>) -> Warning {
    if g.len() == 1 {
        return g.pop().unwrap_or_else(|| Warning::new("", text!(""; "")));
    }
    let n: usize = g.iter().map(|w| w.count).sum();
    let places: Vec<Point> = g
        .iter()
        .flat_map(|w| w.places.iter().copied())
        .take(MAX_PLACES)
        .collect();
    let first = &g[0];
    let text = match &first.kind {
        Some((kind, _)) => {
            let shown: Vec<&Text> = g
                .iter()
                .filter_map(|w| w.kind.as_ref().map(|k| &k.1))
                .take(3)
                .collect();
            let en: Vec<&str> = shown.iter().map(|t| t.en.as_str()).collect();
            let pt: Vec<&str> = shown.iter().map(|t| t.pt.as_str()).collect();
            let more = if n > shown.len() { ", …" } else { "" };
            text!("{n} × {}; first at {}{more}", kind.en, en.join(", ");
                  "{n} × {}; primeiras em {}{more}", kind.pt, pt.join(", "))
        }
        None => text!("{} (×{n})", first.text.en; "{} (×{n})", first.text.pt),
    };
    Warning {
        code: first.code,
        text,
        at: first.at,
        count: n,
        places,
        kind: first.kind.clone(),
        loops: Vec::new(),
    }
    .with_loops(g.iter().flat_map(|w| w.loops.iter().copied()))
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

    #[test]
    fn identical_warnings_are_grouped_with_a_count_and_their_first_places() {
        let skipped = |line: usize| {
            Warning::at(
                "entity-skipped",
                text!("LWPOLYLINE at line {line} skipped: polyline has 1 vertex"; "LWPOLYLINE em linha {line} ignorada: polilinha com 1 vértice"),
                Point::new(line as f64, 0.0),
            )
            .of_kind(
                text!("LWPOLYLINE skipped: polyline has 1 vertex"; "LWPOLYLINE ignorada: polilinha com 1 vértice"),
                text!("line {line}"; "linha {line}"),
            )
        };
        let mut ws: Vec<Warning> = (1..=599).map(skipped).collect();
        ws.insert(1, Warning::new("healed", text!("healed"; "reparado")));
        ws.push(Warning::new("open-contours", text!("open"; "aberto")));
        ws.push(Warning::new("open-contours", text!("open"; "aberto")));
        let g = group(ws);
        assert_eq!(g.len(), 3);
        assert_eq!(g[0].count, 599);
        assert_eq!(
            g[0].text.en,
            "599 × LWPOLYLINE skipped: polyline has 1 vertex; first at line 1, line 2, line 3, …"
        );
        assert!(g[0].text.pt.starts_with("599 × LWPOLYLINE ignorada"));
        assert_eq!(g[0].places.len(), MAX_PLACES);
        assert_eq!(g[0].at, Some(Point::new(1.0, 0.0)));
        assert_eq!((g[1].code, g[1].count), ("healed", 1));
        assert_eq!((g[2].text.en.as_str(), g[2].count), ("open (×2)", 2));
    }

    #[test]
    fn grouped_warnings_keep_every_loop_once_and_losses_are_named() {
        let r = |part, contour| ContourRef {
            part,
            copy: 0,
            contour,
        };
        let w = |part| {
            Warning::new("kerf-vanishes", text!("p{part}"; "p{part}"))
                .of_kind(
                    text!("vanishes"; "some"),
                    text!("part {part}"; "peça {part}"),
                )
                .with_loops([r(part, 1), r(part, 1)])
        };
        let g = group(vec![w(3), w(1), w(3)]);
        assert_eq!(g.len(), 1);
        assert_eq!(g[0].loops, [r(1, 1), r(3, 1)]);
        assert_eq!(g[0].loss(), Some(Loss::NotCut));
        let close = Warning::new("parts-closer-than-kerf", text!("a"; "a"));
        assert_eq!(close.loss(), Some(Loss::CutsInto));
        assert_eq!(Warning::new("units-assumed", text!("a"; "a")).loss(), None);
    }

    #[test]
    fn the_most_serious_come_first_and_repairs_are_notes() {
        let ws = [
            Warning::new("healed", text!("a"; "a")),
            Warning::new("entity-skipped", text!("b"; "b")),
            Warning::new("file-truncated", text!("c"; "c")),
            Warning::new("units-assumed", text!("d"; "d")),
        ];
        let codes: Vec<&str> = by_severity(ws.iter()).iter().map(|w| w.code).collect();
        assert_eq!(
            codes,
            [
                "units-assumed",
                "file-truncated",
                "entity-skipped",
                "healed"
            ]
        );
        assert_eq!(ws[0].severity(), Severity::Info);
        assert_eq!(ws[1].severity(), Severity::Warning);
    }
}
