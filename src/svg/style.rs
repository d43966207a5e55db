//! The few style properties the reader needs — fill and stroke (a laser
//! file's layers), display and visibility (hidden layers), and what is
//! applied but not cut (clip paths, masks, filters, markers, stroke
//! widths) — from presentation attributes, `<style>` sheets (class, id,
//! type and `*` selectors, as Illustrator's `.st0` and Affinity's write
//! them) and `style` attributes, in that order of precedence (CSS 2.1
//! §6.4.4: presentation attributes lose to every style sheet rule).

use std::str::FromStr;

/// Properties read (the rest are ignored).
const PROPS: &[&str] = &[
    "fill",
    "stroke",
    "display",
    "visibility",
    "stroke-width",
    "clip-path",
    "mask",
    "filter",
    "marker",
    "marker-start",
    "marker-mid",
    "marker-end",
];

/// A paint: none, a colour (0xRRGGBB), or a gradient or pattern (`url(…)`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Paint {
    None,
    Color(u32),
    Server,
}

fn paint(v: &str) -> Option<Paint> {
    let v = v.trim();
    if v == "none" {
        return Some(Paint::None);
    }
    if v.starts_with("url(") {
        return Some(Paint::Server);
    }
    if v == "currentColor" {
        return Some(Paint::Color(0));
    }
    let c = svgtypes::Color::from_str(v).ok()?;
    Some(Paint::Color(
        (c.red as u32) << 16 | (c.green as u32) << 8 | c.blue as u32,
    ))
}

/// One `<style>` rule's selector.
#[derive(Clone, Debug, PartialEq)]
enum Selector {
    Any,
    Type(String),
    Class(String),
    Id(String),
    /// `rect.cls`
    TypeClass(String, String),
}

impl Selector {
    fn parse(s: &str) -> Option<Selector> {
        let s = s.trim();
        if s == "*" {
            return Some(Selector::Any);
        }
        // Descendant, child and attribute selectors are not followed.
        if s.is_empty() || s.contains(|c: char| c.is_whitespace() || "[>+~:".contains(c)) {
            return None;
        }
        if let Some(id) = s.strip_prefix('#') {
            return Some(Selector::Id(id.to_owned()));
        }
        if let Some(class) = s.strip_prefix('.') {
            return Some(Selector::Class(class.to_owned()));
        }
        match s.split_once('.') {
            Some((t, c)) => Some(Selector::TypeClass(t.to_owned(), c.to_owned())),
            None => Some(Selector::Type(s.to_owned())),
        }
    }
    fn specificity(&self) -> u8 {
        match self {
            Selector::Any => 0,
            Selector::Type(_) => 1,
            Selector::Class(_) | Selector::TypeClass(..) => 2,
            Selector::Id(_) => 3,
        }
    }
    fn matches(&self, node: roxmltree::Node) -> bool {
        let has_class = |c: &str| {
            node.attribute("class")
                .is_some_and(|v| v.split_whitespace().any(|x| x == c))
        };
        match self {
            Selector::Any => true,
            Selector::Type(t) => node.tag_name().name() == t,
            Selector::Class(c) => has_class(c),
            Selector::Id(id) => node.attribute("id") == Some(id.as_str()),
            Selector::TypeClass(t, c) => node.tag_name().name() == t && has_class(c),
        }
    }
}

/// A rule's declarations: (property, value) pairs.
type Declarations = Vec<(String, String)>;

/// The document's style sheets, rules in document order.
#[derive(Clone, Debug, Default)]
pub struct Sheet {
    rules: Vec<(Selector, Declarations)>,
}

impl Sheet {
    /// Every `<style>` element's text.
    pub fn of(doc: &roxmltree::Document) -> Sheet {
        let mut s = Sheet::default();
        for n in doc.descendants().filter(|n| n.has_tag_name("style")) {
            let css: String = n.children().filter_map(|c| c.text()).collect();
            s.add(&css);
        }
        s
    }

    fn add(&mut self, css: &str) {
        let css = strip_comments(css);
        let mut rest = css.as_str();
        while let Some(open) = rest.find('{') {
            let Some(close) = rest[open..].find('}').map(|k| open + k) else {
                break;
            };
            let (sel, body) = (&rest[..open], &rest[open + 1..close]);
            rest = &rest[close + 1..];
            // @media, @font-face …: their bodies are skipped whole.
            if sel.trim_start().starts_with('@') {
                if let Some(k) = rest.find('}') {
                    if body.contains('{') {
                        rest = &rest[k + 1..];
                    }
                }
                continue;
            }
            let decls = declarations(body);
            for s in sel.split(',').filter_map(Selector::parse) {
                self.rules.push((s, decls.clone()));
            }
        }
    }

    /// The declarations for `node`, least specific first (later ones win).
    fn for_node(&self, node: roxmltree::Node) -> Vec<(String, String)> {
        let mut hits: Vec<(u8, usize, &Declarations)> = (self.rules.iter().enumerate())
            .filter(|(_, (s, _))| s.matches(node))
            .map(|(i, (s, d))| (s.specificity(), i, d))
            .collect();
        hits.sort_by_key(|&(spec, i, _)| (spec, i));
        hits.into_iter()
            .flat_map(|(_, _, d)| d.iter().cloned())
            .collect()
    }

    /// True when the sheet has no rules.
    pub fn is_empty(&self) -> bool {
        self.rules.is_empty()
    }
}

fn strip_comments(css: &str) -> String {
    let mut out = String::with_capacity(css.len());
    let mut rest = css;
    while let Some(k) = rest.find("/*") {
        out.push_str(&rest[..k]);
        rest = rest[k + 2..]
            .find("*/")
            .map_or("", |e| &rest[k + 2 + e + 2..]);
    }
    out.push_str(rest);
    out
}

/// `a: b; c: d` → pairs (property names lower case, `!important` dropped).
fn declarations(body: &str) -> Vec<(String, String)> {
    body.split(';')
        .filter_map(|d| d.split_once(':'))
        .map(|(k, v)| {
            let v = v.trim();
            let v = v.strip_suffix("!important").unwrap_or(v).trim();
            (k.trim().to_ascii_lowercase(), v.to_owned())
        })
        .filter(|(k, _)| PROPS.contains(&k.as_str()))
        .collect()
}

/// The computed properties the reader uses, inherited down the tree.
#[derive(Clone, Debug, PartialEq)]
pub struct Style {
    pub fill: Paint,
    pub stroke: Paint,
    /// `visibility: hidden|collapse` (inherited; a child may say visible).
    pub invisible: bool,
    /// `display: none` here or above (the subtree is not rendered).
    pub display_none: bool,
    /// A stroke width was given (it is not cut).
    pub stroke_width: bool,
    /// `clip-path`, `mask`, `filter` on this element (not inherited).
    pub clip: bool,
    pub mask: bool,
    pub filter: bool,
    /// Markers (inherited).
    pub marker: bool,
}

impl Default for Style {
    /// The initial values: filled black, no stroke, visible.
    fn default() -> Self {
        Style {
            fill: Paint::Color(0),
            stroke: Paint::None,
            invisible: false,
            display_none: false,
            stroke_width: false,
            clip: false,
            mask: false,
            filter: false,
            marker: false,
        }
    }
}

impl Style {
    /// The style of `node` whose parent's is `self`.
    pub fn child(&self, node: roxmltree::Node, sheet: &Sheet) -> Style {
        let mut s = Style {
            clip: false,
            mask: false,
            filter: false,
            ..self.clone()
        };
        for name in PROPS {
            if let Some(v) = node.attribute(*name) {
                s.set(name, v);
            }
        }
        if !sheet.is_empty() {
            for (k, v) in sheet.for_node(node) {
                s.set(&k, &v);
            }
        }
        if let Some(st) = node.attribute("style") {
            for (k, v) in declarations(st) {
                s.set(&k, &v);
            }
        }
        s
    }

    fn set(&mut self, name: &str, v: &str) {
        let v = v.trim();
        if v == "inherit" {
            return;
        }
        let used = |v: &str| !(v.is_empty() || v == "none");
        match name {
            "fill" => self.fill = paint(v).unwrap_or(self.fill),
            "stroke" => self.stroke = paint(v).unwrap_or(self.stroke),
            "display" => self.display_none |= v == "none",
            "visibility" => self.invisible = v == "hidden" || v == "collapse",
            "stroke-width" => {
                self.stroke_width = v
                    .trim_start_matches(['0', '.'])
                    .chars()
                    .any(|c| c.is_ascii_digit())
            }
            "clip-path" => self.clip = used(v),
            "mask" => self.mask = used(v),
            "filter" => self.filter = used(v),
            _ => self.marker |= used(v),
        }
    }

    /// Rendered: neither display:none nor invisible.
    pub fn hidden(&self) -> bool {
        self.display_none || self.invisible
    }

    /// The colour that names a layer: the stroke's, else the fill's.
    pub fn color(&self) -> Option<Paint> {
        match (self.stroke, self.fill) {
            (Paint::None, Paint::None) => None,
            (Paint::None, f) => Some(f),
            (s, _) => Some(s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn style_of(svg: &str, id: &str) -> Style {
        let doc = roxmltree::Document::parse(svg).unwrap();
        let sheet = Sheet::of(&doc);
        let mut s = Style::default();
        let node = doc
            .descendants()
            .find(|n| n.attribute("id") == Some(id))
            .unwrap();
        for a in node.ancestors().collect::<Vec<_>>().into_iter().rev() {
            if a.is_element() {
                s = s.child(a, &sheet);
            }
        }
        s
    }

    #[test]
    fn sheets_beat_attributes_and_style_beats_sheets() {
        let svg = r##"<svg><style>/* x */ .st0{fill:none;stroke:#FF0000} #b{stroke:blue}</style>
            <rect id="a" class="st0" stroke="green"/>
            <rect id="b" class="st0" style="stroke: rgb(0,255,0)"/>
            <g stroke="#00f"><path id="c"/></g></svg>"##;
        let a = style_of(svg, "a");
        assert_eq!((a.fill, a.stroke), (Paint::None, Paint::Color(0xff0000)));
        assert_eq!(style_of(svg, "b").stroke, Paint::Color(0x00ff00));
        let c = style_of(svg, "c");
        assert_eq!(
            (c.fill, c.color()),
            (Paint::Color(0), Some(Paint::Color(0x0000ff)))
        );
    }

    #[test]
    fn display_none_hides_the_subtree_and_visibility_can_be_undone() {
        let svg = r#"<svg><g style="display:none"><path id="a"/></g>
            <g visibility="hidden"><path id="b"/><path id="c" visibility="visible"/></g></svg>"#;
        assert!(style_of(svg, "a").hidden());
        assert!(style_of(svg, "b").hidden());
        assert!(!style_of(svg, "c").hidden());
    }

    #[test]
    fn clip_and_markers_are_noticed() {
        let svg = r#"<svg><g clip-path="url(#c)"><path id="a" marker-end="url(#m)" stroke-width="2"/></g></svg>"#;
        let a = style_of(svg, "a");
        assert!(!a.clip && a.marker && a.stroke_width);
        assert!(style_of(svg, "a").color() == Some(Paint::Color(0)));
    }
}
