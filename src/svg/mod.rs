//! Stage 1 for SVG: SVG bytes → the same [`Drawing`] the DXF reader makes
//! (issue 41), so contours, kerf, nesting, plans and posts take it unchanged.
//!
//! # Output contract
//! - Coordinates in millimetres, Y up: the root viewport's bottom edge is
//!   y = 0 (SVG's y runs down). A size in physical units (`width`/`height`
//!   in mm, cm, in, pt, pc) is the truth; px, unitless or no size is read at
//!   96 px per inch (CSS, Inkscape ≥ 0.92) with a `units-assumed` warning
//!   giving the size at 96 and at 72 px per inch (Illustrator's legacy).
//!   [`ReadOptions::units`] sets the length of one px instead.
//! - Geometry is only [`Segment`]s: SVG arcs and circles stay true arcs
//!   wherever the transforms keep them circular; ellipses (an `<ellipse>`,
//!   an arc with rx ≠ ry, a circle under a non-uniform scale or a skew) and
//!   Béziers become biarcs within the chord tolerance (the DXF reader's
//!   ELLIPSE and SPLINE code, [`crate::dxf`]). One entity per subpath.
//! - Layers: Inkscape layers (`inkscape:groupmode="layer"`, their labels),
//!   else the stroke colour (a laser file's convention); a layer holding
//!   several colours is split by colour. Hidden elements (`display:none`,
//!   `visibility:hidden`) are read onto layers that are off by default.
//! - What is not geometry (text, images, clip paths, masks, markers,
//!   filters, external references) is counted in `skipped` and said in a
//!   warning naming what to do; nothing is fetched.
//!
//! Written back: [`plan::to_svg`] (the cut plan) and the nest's writer share
//! [`write`]; they need no XML crate and are built without the feature.
//!
//! The XML is read by `roxmltree` (entities of an internal DTD, as
//! Illustrator writes, included), the attribute grammars (path data,
//! transforms, lengths, colours) by `svgtypes`.

pub mod plan;
pub mod write;

// The reader proper: feature "svg" (the page's cutting core is built without it).
#[cfg(feature = "svg")]
mod curves;
#[cfg(feature = "svg")]
mod document;
#[cfg(feature = "svg")]
mod layers;
#[cfg(feature = "svg")]
mod path;
#[cfg(feature = "svg")]
mod shapes;
#[cfg(feature = "svg")]
mod style;
#[cfg(feature = "svg")]
mod transform;
#[cfg(feature = "svg")]
mod walk;

use std::fmt;

use crate::dxf::{Drawing, ReadOptions};
use crate::geom::Segment;
use crate::text;
use crate::warning::{Lang, Text};

/// Largest SVG read, bytes: the XML tree takes several times the file in
/// memory (a browser tab cannot count on a gigabyte for one drawing).
pub const MAX_BYTES: usize = 256 << 20;
/// Deepest element nesting, `<use>` indirections included, followed.
#[cfg(feature = "svg")]
const MAX_DEPTH: usize = 128;
/// Most elements drawn, counting every `<use>` copy: beyond it a file is an
/// expansion bomb (a `<use>` of ten `<use>`s of ten …).
#[cfg(feature = "svg")]
const MAX_ELEMENTS: usize = 1_000_000;
/// Most segments one file may become (the DXF reader's cap, for the same reasons).
#[cfg(feature = "svg")]
const MAX_SEGMENTS: usize = 2_000_000;
/// Largest coordinate magnitude accepted, mm (1000 km): beyond it the number is garbage.
#[cfg(feature = "svg")]
const MAX_COORD_MM: f64 = 1e9;

/// Why an SVG could not be read at all.
#[derive(Clone, Debug, PartialEq)]
pub enum SvgError {
    /// The input is empty.
    Empty,
    /// Larger than [`MAX_BYTES`].
    TooLarge(usize),
    /// gzip-compressed (.svgz).
    Compressed,
    /// Not well-formed XML, with the parser's message (it says the line).
    Xml(String),
    /// XML whose root element is not `<svg>`.
    NotSvg(String),
    /// This build has no SVG reader (the page's cutting core: its worker
    /// runs SVG files with the module that has one).
    NotBuiltIn,
}

impl SvgError {
    /// The message in every language.
    pub fn text(&self) -> Text {
        match self {
            SvgError::Empty => text!("the file is empty"; "o arquivo está vazio"),
            SvgError::TooLarge(n) => {
                let mb = n >> 20;
                let max = MAX_BYTES >> 20;
                text!("the SVG is {mb} MB, over the {max} MB this reader takes";
                      "o SVG tem {mb} MB, acima dos {max} MB que este leitor aceita")
            }
            SvgError::Compressed => text!(
                "compressed SVG (.svgz): save it as plain SVG (Inkscape: Save As → Plain SVG)";
                "SVG compactado (.svgz): salve-o como SVG simples (Inkscape: Salvar como → SVG simples)"),
            SvgError::Xml(e) => text!("broken SVG (not well-formed XML): {e}";
                                      "SVG danificado (XML malformado): {e}"),
            SvgError::NotBuiltIn => text!(
                "this build of kerfcam reads DXF only (no SVG reader)";
                "esta versão do kerfcam lê só DXF (sem leitor de SVG)"),
            SvgError::NotSvg(root) => text!(
                "not an SVG file: an XML file whose root element is <{root}>";
                "não é um arquivo SVG: um arquivo XML cujo elemento raiz é <{root}>"),
        }
    }
    /// The message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl fmt::Display for SvgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text().en)
    }
}

impl std::error::Error for SvgError {}

/// True when the bytes are XML (an SVG to this reader) rather than DXF: the
/// first character after an optional byte-order mark and white space is
/// `<` (a DXF starts with a group code, a number), or they are gzip (.svgz).
pub fn looks_like_svg(bytes: &[u8]) -> bool {
    if bytes.starts_with(&[0x1f, 0x8b]) {
        return true;
    }
    let b = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    b.iter().find(|c| !c.is_ascii_whitespace()) == Some(&b'<')
}

/// Reads an SVG into a drawing in mm (an error in a build without the
/// feature "svg").
#[cfg(not(feature = "svg"))]
pub fn parse(_bytes: &[u8], _options: &ReadOptions) -> Result<Drawing, SvgError> {
    Err(SvgError::NotBuiltIn)
}

/// Reads an SVG into a drawing in mm.
#[cfg(feature = "svg")]
pub fn parse(bytes: &[u8], options: &ReadOptions) -> Result<Drawing, SvgError> {
    if bytes.starts_with(&[0x1f, 0x8b]) {
        return Err(SvgError::Compressed);
    }
    if bytes.iter().all(|b| b.is_ascii_whitespace()) {
        return Err(SvgError::Empty);
    }
    if bytes.len() > MAX_BYTES {
        return Err(SvgError::TooLarge(bytes.len()));
    }
    let text = String::from_utf8_lossy(bytes);
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let doc = roxmltree::Document::parse_with_options(text, opts)
        .map_err(|e| SvgError::Xml(e.to_string()))?;
    let root = doc.root_element();
    if root.tag_name().name() != "svg" {
        return Err(SvgError::NotSvg(
            root.tag_name().name().chars().take(40).collect(),
        ));
    }
    let mut d = walk::read(&doc, text, options);
    if !d.entities.is_empty() {
        crate::dxf::check_size(&mut d);
    }
    d.warnings = crate::warning::group(std::mem::take(&mut d.warnings));
    Ok(d)
}

/// The page (the root viewport) in mm, where the file gives one or its
/// viewBox implies one: width/height, else the viewBox as px (`px`: the
/// length of a px, None for CSS's 96 per inch). None for a file that does
/// not parse or says neither.
#[cfg(feature = "svg")]
pub fn page_size(bytes: &[u8], px: Option<crate::dxf::Units>) -> Option<(f64, f64)> {
    let text = String::from_utf8_lossy(bytes);
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let doc =
        roxmltree::Document::parse_with_options(text.trim_start_matches('\u{feff}'), opts).ok()?;
    let px_mm = px.map_or(document::PX_MM, |u| u.to_mm);
    document::root(doc.root_element(), px_mm).size_mm
}

/// All segments of a drawing (for tests and tools).
pub fn all_segments(d: &Drawing) -> impl Iterator<Item = &Segment> {
    d.entities.iter().flat_map(|e| e.segments.iter())
}

#[cfg(all(test, feature = "svg"))]
mod tests;
#[cfg(all(test, feature = "svg"))]
mod transform_props;
