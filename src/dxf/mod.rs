//! Stage 1: DXF bytes → [`Drawing`].
//!
//! # Output contract
//! - Coordinates are in millimetres, Y up, world X/Y. The unit is the
//!   user's override, else `$INSUNITS`, else assumed by [`units::assume`]
//!   (`$MEASUREMENT = 1` → mm; a drawing under an inch across read as mm →
//!   inches; otherwise mm), always with a `units-assumed` warning that
//!   gives the evidence and the size in both readings.
//! - Geometry is only [`Segment`]s: lines and arcs of at most 180°. Circles
//!   are two half arcs; OCS extrusions (0,0,−1) are applied (mirrored arcs);
//!   SPLINE and ELLIPSE become arcs (biarcs) within the chord tolerance; INSERTs are
//!   expanded (nested blocks, scale, mirror, rotation, arrays).
//! - POINTs are kept as spots. Every model-space entity is counted by type;
//!   those not turned into geometry are counted again in `skipped`, and the
//!   reason is a warning with its line (ASCII) or byte offset (binary).
//! - Text (layer names) is decoded with the file's code page.
//!
//! ASCII and binary DXF from R2.x (AC1003) to 2018 are read; sections may
//! be missing (a file of bare entities is read as an ENTITIES section).

// Shared with the SVG reader (its Béziers and ellipses).
pub(crate) mod biarc;
mod binary;
mod chunks;
mod curves;
mod decimal;
pub(crate) mod ellipse;
mod entities;
mod extent;
mod header;
mod insert;
mod pairs;
mod pass;
mod reader;
mod stream;
mod text;
mod units;
mod walk;

use std::collections::BTreeMap;
use std::fmt;

pub use entities::Entity;
pub use pairs::Place;
#[cfg(feature = "svg")]
pub(crate) use units::size_text;
pub use units::Units;

use crate::geom::{BBox, Point, Segment};
use crate::par::Threads;
use crate::text;
use crate::warning::{dec, Lang, Text, Warning};
use pairs::BadCode;
use pass::parse_in;

/// One layer of the drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct Layer {
    /// Its name, decoded.
    pub name: String,
    /// AutoCAD colour index (a negative colour in the table means "off").
    pub color: i16,
    /// On and not frozen in the file's LAYER table.
    pub visible: bool,
    /// Its geometry is cut (by default the visible layers).
    pub selected: bool,
    /// Geometry entities on it (after block expansion).
    pub entities: usize,
}

/// A POINT entity: a spot to mark, not a contour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spot {
    /// Where, mm.
    pub at: Point,
    /// Its layer.
    pub layer: u32,
    /// Geometry entities read before it (its place in file order among
    /// [`Drawing::entities`], for paper 002's drawing order).
    pub after_entities: usize,
}

/// One copy made by an INSERT (one cell of an array): which block, and
/// the copy it was made inside (a block inserted in a block). A part
/// drawn as a block is named after it (issue 42 §1): entities keep the
/// copy they came from, so two INSERTs of one block stay two parts.
#[derive(Clone, Debug, PartialEq)]
pub struct InsertCopy {
    /// The block's name, decoded (data: escaped where shown).
    pub block: std::sync::Arc<str>,
    /// The copy this one was made inside (an index of [`Drawing::inserts`]).
    pub parent: Option<u32>,
}

/// What the reader found in the file.
#[derive(Clone, Debug, Default)]
pub struct Drawing {
    /// The unit the file's numbers were read in (everything here is in mm).
    pub units: Option<Units>,
    /// Where the unit came from: "$INSUNITS", "assumed" (the file does not
    /// say; a `units-assumed` warning gives the evidence) or "override".
    pub units_source: &'static str,
    /// `$MEASUREMENT` as the file states it (0 imperial, 1 metric).
    pub measurement: Option<i64>,
    /// The box of all geometry, mm (empty when nothing was read).
    pub extent: BBox,
    /// `$ACADVER`, when the file says.
    pub version: Option<String>,
    /// True for a binary DXF.
    pub binary: bool,
    /// True when the file was an SVG ([`crate::svg`]): its units are px or
    /// a CSS length, and the page offers px at 96 and at 72 per inch.
    pub svg: bool,
    /// Geometry entities of the selected layers, in file order.
    pub entities: Vec<Entity>,
    /// POINT entities of the selected layers.
    pub spots: Vec<Spot>,
    /// The copies INSERTs made, that entities name ([`Entity::insert`]).
    pub inserts: Vec<InsertCopy>,
    /// Layers: the LAYER table's, then any others entities name.
    pub layers: Vec<Layer>,
    /// Model-space entities seen, by DXF type.
    pub counts: BTreeMap<String, usize>,
    /// Model-space entities not turned into geometry, by DXF type.
    pub skipped: BTreeMap<String, usize>,
    /// What was skipped or doubtful, and where.
    pub warnings: Vec<Warning>,
}

/// How to read a file.
#[derive(Clone, Debug, PartialEq)]
pub struct ReadOptions {
    /// Largest distance between a curve (spline, ellipse) and the arcs that replace it, mm.
    pub chord: f64,
    /// Units to use whatever the file says.
    pub units: Option<Units>,
    /// Layers to cut (by name); None = the visible ones.
    pub layers: Option<Vec<String>>,
    /// Threads that may read the entities (the drawing is the same with any).
    pub threads: Threads,
}

impl ReadOptions {
    /// Chord 0.01 mm, the file's units, visible layers.
    pub const DEFAULT: ReadOptions = ReadOptions {
        chord: 0.01,
        units: None,
        layers: None,
        threads: Threads::ONE,
    };
}

/// Why a file could not be read at all.
#[derive(Clone, Debug, PartialEq)]
pub enum DxfError {
    /// The input is empty.
    Empty,
    /// The first items are not group-code/value pairs.
    NotDxf(BadCode),
    /// The structure breaks before any entity was read.
    Malformed(BadCode),
}

impl DxfError {
    /// The message in every language.
    pub fn text(&self) -> Text {
        match self {
            DxfError::Empty => text!("the file is empty"; "o arquivo está vazio"),
            DxfError::NotDxf(e) => {
                let e = bad_code_text(e);
                text!("not a DXF file ({})", e.en; "não é um arquivo DXF ({})", e.pt)
            }
            DxfError::Malformed(e) => {
                let e = bad_code_text(e);
                text!("broken DXF: {}", e.en; "DXF danificado: {}", e.pt)
            }
        }
    }
    /// The message in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl fmt::Display for DxfError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text().en)
    }
}

/// Where a pair is, in every language ("line 12" / "linha 12").
pub(crate) fn place_text(p: Place) -> Text {
    match p {
        Place::Line(n) => text!("line {n}"; "linha {n}"),
        Place::Byte(n) => text!("byte {n}"; "byte {n}"),
    }
}

/// A bad group code, in every language (the English is BadCode's Display).
fn bad_code_text(e: &BadCode) -> Text {
    let at = place_text(e.place);
    let found = &e.text;
    text!("{}: expected a group code, found '{found}'", at.en;
          "{}: esperado um código de grupo, encontrado '{found}'", at.pt)
}

impl std::error::Error for DxfError {}

/// Longest type name kept in the counts (longer ones are garbage).
const MAX_TYPE_LEN: usize = 32;
/// Deepest block nesting followed.
const MAX_BLOCK_DEPTH: usize = 32;
/// Most segments one file may expand to. Two million is far beyond any
/// cutting job (a 3 m × 1.5 m sheet of parts has tens of thousands); beyond
/// it a file is an expansion bomb (INSERT arrays of arrays), and the rest is
/// not read, with a warning. Measured on a 1e7-vertex LWPOLYLINE (289 MB):
/// reading it whole peaks at 1.3 GB in the reader alone (each later stage
/// holds another 400 MB of segments), past what a browser tab can count on;
/// with this cap the reader peaks at 409 MB and says why it stopped.
const MAX_SEGMENTS: usize = 2_000_000;
/// Most copies one INSERT array may make (columns × rows).
const MAX_ARRAY_COPIES: usize = 100_000;
/// Largest coordinate magnitude accepted, mm (1000 km): beyond it the number is garbage.
const MAX_COORD_MM: f64 = 1e9;
/// Sides of a plausible cutting job, mm: a drawing outside this range after
/// unit scaling was most likely saved with the wrong units.
const PLAUSIBLE_SIDE_MM: (f64, f64) = (1.0, 20_000.0);

/// Reads an ASCII or binary DXF.
pub fn parse(bytes: &[u8], options: &ReadOptions) -> Result<Drawing, DxfError> {
    let mut d = parse_in(bytes, options)?;
    if d.units_source == "assumed" {
        let as_mm = d.extent;
        let side = (as_mm.max.x - as_mm.min.x).max(as_mm.max.y - as_mm.min.y);
        let (unit, evidence) = units::assume(d.measurement, side);
        if unit != Units::MM {
            // Read again in the assumed unit, so curves are fitted within
            // the chord tolerance in mm.
            let again = ReadOptions {
                units: Some(unit),
                ..options.clone()
            };
            let measurement = d.measurement;
            d = parse_in(bytes, &again)?;
            d.units_source = "assumed";
            d.measurement = measurement;
        }
        let w = units::assumed_warning(evidence, d.measurement, &as_mm);
        d.warnings.insert(0, w);
    }
    if !d.entities.is_empty() {
        check_size(&mut d);
    }
    d.warnings = crate::warning::group(std::mem::take(&mut d.warnings));
    Ok(d)
}

/// Warns when the scaled drawing is implausibly small or large for a cutting table.
pub(crate) fn check_size(d: &mut Drawing) {
    let bb = d.extent;
    let side = (bb.max.x - bb.min.x).max(bb.max.y - bb.min.y);
    let unit = d.units.map_or("mm", |u| u.name);
    if side > PLAUSIBLE_SIDE_MM.1 || side < PLAUSIBLE_SIDE_MM.0 {
        d.warnings.push(Warning::at(
            "size-implausible",
            text!("the drawing is {side:.3} mm across (drawn in {unit}): check the drawing's units";
                  "o desenho mede {:.3} mm (desenhado em {unit}): confira as unidades do desenho", dec(side)),
            bb.min,
        ));
    }
}

/// All segments of a drawing, entity by entity (for tests and tools).
pub fn all_segments(d: &Drawing) -> impl Iterator<Item = &Segment> {
    d.entities.iter().flat_map(|e| e.segments.iter())
}

#[cfg(test)]
mod tests;
