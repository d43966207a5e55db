//! Stage 1: DXF bytes → [`Drawing`].
//!
//! # Output contract
//! - Coordinates are in millimetres (from `$INSUNITS`, else `$MEASUREMENT`,
//!   else mm with a warning; or the user's override), Y up, world X/Y.
//! - Geometry is only [`Segment`]s: lines and arcs of at most 180°. Circles
//!   are two half arcs; OCS extrusions (0,0,−1) are applied (mirrored arcs);
//!   SPLINE and ELLIPSE become lines within the chord tolerance; INSERTs are
//!   expanded (nested blocks, scale, mirror, rotation, arrays).
//! - POINTs are kept as spots. Every model-space entity is counted by type;
//!   those not turned into geometry are counted again in `skipped`, and the
//!   reason is a warning with its line (ASCII) or byte offset (binary).
//! - Text (layer names) is decoded with the file's code page.
//!
//! ASCII and binary DXF from R2.x (AC1003) to 2018 are read; sections may
//! be missing (a file of bare entities is read as an ENTITIES section).

mod binary;
mod curves;
mod entities;
mod pairs;
mod text;
mod units;

use std::collections::{BTreeMap, HashMap};
use std::fmt;

pub use entities::Entity;
pub use pairs::Place;
pub use units::Units;

use crate::geom::{transform_segments, Affine, Point, Segment};
use crate::warning::Warning;
use pairs::{AsciiPairs, BadCode, Pair};
use text::Decoder;

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

/// What the reader found in the file.
#[derive(Clone, Debug, Default)]
pub struct Drawing {
    /// The unit the file's numbers were read in (everything here is in mm).
    pub units: Option<Units>,
    /// Where the unit came from: "$INSUNITS", "$MEASUREMENT", "default" or "override".
    pub units_source: &'static str,
    /// `$ACADVER`, when the file says.
    pub version: Option<String>,
    /// True for a binary DXF.
    pub binary: bool,
    /// Geometry entities of the selected layers, in file order.
    pub entities: Vec<Entity>,
    /// POINT entities of the selected layers.
    pub spots: Vec<Spot>,
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
    /// Largest distance between a curve (spline, ellipse) and the lines that replace it, mm.
    pub chord: f64,
    /// Units to use whatever the file says.
    pub units: Option<Units>,
    /// Layers to cut (by name); None = the visible ones.
    pub layers: Option<Vec<String>>,
}

impl ReadOptions {
    /// Chord 0.01 mm, the file's units, visible layers.
    pub const DEFAULT: ReadOptions = ReadOptions {
        chord: 0.01,
        units: None,
        layers: None,
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

impl fmt::Display for DxfError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DxfError::Empty => write!(f, "the file is empty"),
            DxfError::NotDxf(e) => write!(f, "not a DXF file ({e})"),
            DxfError::Malformed(e) => write!(f, "broken DXF: {e}"),
        }
    }
}

impl std::error::Error for DxfError {}

/// Longest type name kept in the counts (longer ones are garbage).
const MAX_TYPE_LEN: usize = 32;
/// Deepest block nesting followed.
const MAX_BLOCK_DEPTH: usize = 32;
/// Most segments one file may expand to. Two million is far beyond any
/// cutting job (a 3 m × 1.5 m sheet of parts has tens of thousands); beyond
/// it a file is an expansion bomb (INSERT arrays of arrays), and the rest is
/// not read, with a warning.
const MAX_SEGMENTS: usize = 2_000_000;
/// Most copies one INSERT array may make (columns × rows).
const MAX_ARRAY_COPIES: usize = 100_000;
/// Largest coordinate magnitude accepted, mm (1000 km): beyond it the number is garbage.
const MAX_COORD_MM: f64 = 1e9;
/// Sides of a plausible cutting job, mm: a drawing outside this range after
/// unit scaling was most likely saved with the wrong units.
const PLAUSIBLE_SIDE_MM: (f64, f64) = (1.0, 20_000.0);

/// A block definition: its base point and the range of its entity pairs.
struct Block {
    base: Point,
    from: usize,
    to: usize,
}

/// Reads an ASCII or binary DXF.
pub fn parse(bytes: &[u8], options: &ReadOptions) -> Result<Drawing, DxfError> {
    if bytes.iter().all(|b| b.is_ascii_whitespace()) {
        return Err(DxfError::Empty);
    }
    let binary = bytes.starts_with(binary::SENTINEL);
    let mut raw = Vec::with_capacity(bytes.len() / 12);
    let (bad, truncated) = if binary {
        collect(binary::BinaryPairs::new(bytes), &mut raw, |it| it.truncated)
    } else {
        collect(AsciiPairs::new(bytes), &mut raw, |it| it.truncated)
    };
    if let Some(e) = &bad {
        if raw.is_empty() {
            return Err(DxfError::NotDxf(e.clone()));
        }
    }
    let mut r = Reader::new(&raw, binary, options);
    r.read_sections();
    let mut d = r.finish();
    if let Some(e) = bad {
        if d.entities.is_empty() && d.counts.is_empty() {
            return Err(DxfError::Malformed(e));
        }
        d.warnings.push(Warning::new(format!(
            "reading stopped at {e}; the rest of the file was ignored"
        )));
    } else if truncated {
        d.warnings.push(Warning::new(
            "the file ends in the middle of a group: it may be truncated",
        ));
    }
    Ok(d)
}

/// Drains a pair iterator; returns the first bad code and whether the input was cut short.
fn collect<'a, I>(
    mut it: I,
    raw: &mut Vec<Pair<'a>>,
    truncated: impl Fn(&I) -> bool,
) -> (Option<BadCode>, bool)
where
    I: Iterator<Item = Result<Pair<'a>, BadCode>>,
{
    for p in it.by_ref() {
        match p {
            Ok(p) => raw.push(p),
            Err(e) => return (Some(e), truncated(&it)),
        }
    }
    (None, truncated(&it))
}

/// Index just past the pairs of the entity starting at `i` (its `0` pair).
fn entity_end(raw: &[Pair], i: usize, to: usize) -> usize {
    raw[i + 1..to]
        .iter()
        .position(|p| p.code == 0)
        .map_or(to, |k| i + 1 + k)
}

struct Reader<'a, 'r, 'o> {
    raw: &'r [Pair<'a>],
    binary: bool,
    options: &'o ReadOptions,
    decoder: Decoder,
    blocks: HashMap<&'a [u8], Block>,
    layer_ids: HashMap<&'a [u8], u32>,
    layer_folded: HashMap<Vec<u8>, u32>,
    entities_range: Option<(usize, usize)>,
    header: HashMap<&'a [u8], usize>,
    scale: f64,
    budget: usize,
    paper_space: usize,
    tilted: usize,
    counts: HashMap<&'a [u8], usize>,
    skipped: HashMap<&'a [u8], usize>,
    in_blocks_skipped: HashMap<&'a [u8], usize>,
    off_layers: BTreeMap<u32, usize>,
    d: Drawing,
}

impl<'a, 'r, 'o> Reader<'a, 'r, 'o> {
    fn new(raw: &'r [Pair<'a>], binary: bool, options: &'o ReadOptions) -> Self {
        Reader {
            raw,
            binary,
            options,
            decoder: Decoder::Utf8,
            blocks: HashMap::new(),
            layer_ids: HashMap::new(),
            layer_folded: HashMap::new(),
            entities_range: None,
            header: HashMap::new(),
            scale: 1.0,
            budget: MAX_SEGMENTS,
            paper_space: 0,
            tilted: 0,
            counts: HashMap::new(),
            skipped: HashMap::new(),
            in_blocks_skipped: HashMap::new(),
            off_layers: BTreeMap::new(),
            d: Drawing {
                binary,
                ..Drawing::default()
            },
        }
    }

    fn place(&self, at: usize) -> Place {
        if self.binary {
            Place::Byte(at)
        } else {
            Place::Line(at)
        }
    }

    /// Finds the sections; reads HEADER and TABLES at once, notes BLOCKS and
    /// ENTITIES, then walks the model space.
    fn read_sections(&mut self) {
        let n = self.raw.len();
        let mut i = 0;
        let mut saw_section = false;
        let (mut tables, mut blocks) = (None, None);
        while i < n {
            let p = self.raw[i];
            if !(p.code == 0 && p.is("SECTION")) {
                i += 1;
                continue;
            }
            saw_section = true;
            let name = self
                .raw
                .get(i + 1)
                .filter(|p| p.code == 2)
                .map(|p| p.trimmed())
                .unwrap_or(b"");
            let from = (i + 2).min(n);
            let to = self.raw[from..]
                .iter()
                .position(|p| p.code == 0 && (p.is("ENDSEC") || p.is("EOF")))
                .map_or(n, |k| from + k);
            match name {
                b"HEADER" => self.read_header(from, to),
                b"TABLES" => tables = Some((from, to)),
                b"BLOCKS" => blocks = Some((from, to)),
                b"ENTITIES" => self.entities_range = Some((from, to)),
                _ => {}
            }
            i = to + 1;
        }
        if !saw_section {
            self.entities_range = Some((0, n));
        }
        self.set_decoder();
        self.set_units();
        if let Some((f, t)) = tables {
            self.read_layers(f, t);
        }
        if let Some((f, t)) = blocks {
            self.read_blocks(f, t);
        }
        if let Some((f, t)) = self.entities_range {
            let m = Affine::scale(self.scale);
            let mut stack = Vec::new();
            self.walk(f, t, &m, None, true, &mut stack);
        }
    }

    /// `$NAME` → index of its first value pair.
    fn read_header(&mut self, from: usize, to: usize) {
        for i in from..to {
            let p = self.raw[i];
            if p.code == 9 && i + 1 < to {
                self.header.entry(p.trimmed()).or_insert(i + 1);
            }
        }
    }

    fn header_pair(&self, name: &str, code: i32) -> Option<Pair<'a>> {
        let i = *self.header.get(name.as_bytes())?;
        self.raw[i..]
            .iter()
            .take_while(|p| p.code != 9 && p.code != 0)
            .find(|p| p.code == code)
            .copied()
    }

    fn set_decoder(&mut self) {
        let ver = self.header_pair("$ACADVER", 1).map(|p| p.trimmed());
        let cp = self.header_pair("$DWGCODEPAGE", 3).map(|p| p.trimmed());
        self.d.version = ver.map(|v| String::from_utf8_lossy(v).into_owned());
        self.decoder = Decoder::for_file(ver, cp).unwrap_or_else(|| {
            let name = String::from_utf8_lossy(cp.unwrap_or(b"")).into_owned();
            self.d.warnings.push(Warning::new(format!(
                "unknown code page '{name}': names read as Windows-1252"
            )));
            Decoder::for_file(Some(b"AC1015"), Some(b"ANSI_1252")).unwrap_or(Decoder::Utf8)
        });
    }

    fn set_units(&mut self) {
        let ins = self.header_pair("$INSUNITS", 70).and_then(|p| p.int());
        let meas = self.header_pair("$MEASUREMENT", 70).and_then(|p| p.int());
        let from_ins = ins.and_then(Units::from_insunits);
        let (units, source) = if let Some(u) = self.options.units {
            (u, "override")
        } else if let Some(u) = from_ins {
            if (u.to_mm == 25.4 && meas == Some(1))
                || (u.to_mm != 25.4 && u.to_mm < 1000.0 && meas == Some(0))
            {
                self.d.warnings.push(Warning::new(format!(
                    "contradictory units: $INSUNITS says {} but $MEASUREMENT says {}; read as {} (override with the units setting)",
                    u.name,
                    if meas == Some(1) { "metric" } else { "imperial" },
                    u.name
                )));
            }
            (u, "$INSUNITS")
        } else {
            if let Some(code) = ins.filter(|&c| c != 0) {
                self.d.warnings.push(Warning::new(format!(
                    "$INSUNITS {code} is not a length unit"
                )));
            }
            match meas {
                Some(0) => (Units::INCH, "$MEASUREMENT"),
                Some(1) => (Units::MM, "$MEASUREMENT"),
                _ => {
                    self.d.warnings.push(Warning::new(
                        "the file does not say its units: read as mm (override with the units setting)",
                    ));
                    (Units::MM, "default")
                }
            }
        };
        self.d.units = Some(units);
        self.d.units_source = source;
        self.scale = units.to_mm;
    }

    /// LAYER records of the TABLES section: name 2, colour 62 (negative = off), flags 70 (1 = frozen).
    fn read_layers(&mut self, from: usize, to: usize) {
        let raw = self.raw;
        let mut i = from;
        while i < to {
            if raw[i].code == 0 && raw[i].is("LAYER") {
                let end = entity_end(raw, i, to);
                let body = &raw[i + 1..end];
                if let Some(name) = body.iter().find(|p| p.code == 2).map(|p| p.trimmed()) {
                    let color = entities::int(body, 62).unwrap_or(7);
                    let flags = entities::int(body, 70).unwrap_or(0);
                    let visible = color >= 0 && flags & 1 == 0;
                    let id = self.layer_id(name) as usize;
                    let selected = self.layer_selected(&self.d.layers[id].name, visible);
                    let l = &mut self.d.layers[id];
                    l.color = color.clamp(-256, 256) as i16;
                    l.visible = visible;
                    l.selected = selected;
                }
                i = end;
            } else {
                i += 1;
            }
        }
    }

    fn layer_selected(&self, name: &str, visible: bool) -> bool {
        match &self.options.layers {
            // Layer names are case-insensitive in DXF.
            Some(list) => list.iter().any(|n| n.to_lowercase() == name.to_lowercase()),
            None => visible,
        }
    }

    fn layer_id(&mut self, raw_name: &'a [u8]) -> u32 {
        if let Some(&id) = self.layer_ids.get(raw_name) {
            return id;
        }
        // Layer names are case-insensitive: "Cut" and "CUT" are one layer,
        // shown as first met. This slow path runs once per spelling.
        let folded = raw_name.to_ascii_uppercase();
        if let Some(&id) = self.layer_folded.get(&folded) {
            self.layer_ids.insert(raw_name, id);
            return id;
        }
        self.layer_folded.insert(folded, self.d.layers.len() as u32);
        let name = self.decoder.decode(raw_name);
        let id = self.d.layers.len() as u32;
        let selected = self.layer_selected(&name, true);
        self.d.layers.push(Layer {
            name,
            color: 7,
            visible: true,
            selected,
            entities: 0,
        });
        self.layer_ids.insert(raw_name, id);
        id
    }

    /// BLOCK … ENDBLK records: name 2, base point 10/20.
    fn read_blocks(&mut self, from: usize, to: usize) {
        let raw = self.raw;
        let mut i = from;
        while i < to {
            let p = raw[i];
            if !(p.code == 0 && p.is("BLOCK")) {
                i += 1;
                continue;
            }
            let head_end = entity_end(raw, i, to);
            let head = &raw[i + 1..head_end];
            let name = head
                .iter()
                .find(|p| p.code == 2)
                .map(|p| p.trimmed())
                .unwrap_or(b"");
            let base = entities::point(head, 10).unwrap_or_default();
            let end = raw[head_end..to]
                .iter()
                .position(|p| p.code == 0 && p.is("ENDBLK"))
                .map_or(to, |k| head_end + k);
            self.blocks.insert(
                name,
                Block {
                    base,
                    from: head_end,
                    to: end,
                },
            );
            i = end + 1;
        }
    }

    /// Reads the entities in `from..to` through the map `m`. `inherit` is the
    /// layer of the INSERT that placed them (for entities on layer "0").
    fn walk(
        &mut self,
        from: usize,
        to: usize,
        m: &Affine,
        inherit: Option<u32>,
        top: bool,
        stack: &mut Vec<&'a [u8]>,
    ) {
        let raw = self.raw;
        let mut i = from;
        while i < to && self.budget > 0 {
            if raw[i].code != 0 {
                i += 1;
                continue;
            }
            let head = raw[i];
            let body_end = entity_end(raw, i, to);
            let (b0, b1) = (i + 1, body_end);
            i = body_end;
            if head.is("ENDSEC") || head.is("EOF") || head.is("SEQEND") || head.is("ENDBLK") {
                continue;
            }
            // VERTEX/SEQEND after a POLYLINE, ATTRIB/SEQEND after an INSERT, belong to it.
            let mut vertices: Vec<(usize, usize)> = Vec::new();
            if head.is("POLYLINE") || head.is("INSERT") {
                let child = if head.is("POLYLINE") {
                    "VERTEX"
                } else {
                    "ATTRIB"
                };
                while i < to && raw[i].code == 0 && raw[i].is(child) {
                    let end = entity_end(raw, i, to);
                    vertices.push((i + 1, end));
                    i = end;
                }
                if i < to
                    && raw[i].code == 0
                    && raw[i].is("SEQEND")
                    && (head.is("POLYLINE") || !vertices.is_empty())
                {
                    i = entity_end(raw, i, to);
                }
            }
            // Type names stay borrowed bytes until `finish`: no allocation per entity.
            let kind: &'a [u8] = &head.trimmed()[..head.trimmed().len().min(MAX_TYPE_LEN)];
            let body = &raw[b0..b1];
            // Paper space (group 67 = 1) is layout, not model: counted in a warning only.
            if body.iter().any(|p| p.code == 67 && p.int() == Some(1)) {
                self.paper_space += 1;
                continue;
            }
            if top {
                *self.counts.entry(kind).or_default() += 1;
            }
            let layer = match body.iter().find(|p| p.code == 8).map(|p| p.trimmed()) {
                Some(b"0") | None if inherit.is_some() => inherit.unwrap_or(0),
                Some(name) => self.layer_id(name),
                None => self.layer_id(b"0"),
            };
            let place = self.place(head.at);
            let chord = self.options.chord / m.mean_scale().max(1e-300);
            let built = match head.trimmed() {
                b"LINE" => Some(("LINE", entities::line(body))),
                b"ARC" => Some(("ARC", entities::arc(body))),
                b"CIRCLE" => Some(("CIRCLE", entities::circle(body))),
                b"LWPOLYLINE" => Some(("LWPOLYLINE", entities::lwpolyline(body))),
                b"POLYLINE" => {
                    let vs: Vec<&[Pair]> = vertices.iter().map(|&(a, b)| &raw[a..b]).collect();
                    let r = entities::polyline(body, &vs).map(|(segs, closed, z)| {
                        if let Some((lo, hi)) = z.filter(|(lo, hi)| hi - lo > 1e-6) {
                            let msg = format!("3-D POLYLINE at {place} is not flat (Z {lo:.3} to {hi:.3}): projected onto XY");
                            self.d.warnings.push(Warning::new(msg));
                        }
                        (segs, closed)
                    });
                    Some(("POLYLINE", r))
                }
                b"SPLINE" => Some((
                    "SPLINE",
                    curves::spline(body, chord).map(|(segs, closed, note)| {
                        if let Some(n) = note {
                            self.d
                                .warnings
                                .push(Warning::new(format!("SPLINE at {place}: {n}")));
                        }
                        (segs, closed)
                    }),
                )),
                b"ELLIPSE" => Some(("ELLIPSE", curves::ellipse(body, chord))),
                b"POINT" => {
                    if let Ok(p) = entities::point(body, 10) {
                        let at = m.apply(p);
                        if at.is_finite()
                            && at.x.abs() <= MAX_COORD_MM
                            && at.y.abs() <= MAX_COORD_MM
                        {
                            self.add_spot(at, layer);
                        }
                    }
                    continue;
                }
                b"INSERT" => {
                    self.insert(body, m, layer, place, stack);
                    continue;
                }
                _ => None,
            };
            let Some((kind_name, result)) = built else {
                if top {
                    *self.skipped.entry(kind).or_default() += 1;
                } else {
                    *self.in_blocks_skipped.entry(kind).or_default() += 1;
                }
                continue;
            };
            // Entities drawn in their own OCS; LINE, SPLINE, ELLIPSE and 3-D polylines are in world coordinates.
            let flags = entities::int(body, 70).unwrap_or(0);
            let (ocs, tilted) = match kind_name {
                "ARC" | "CIRCLE" => entities::ocs(body, 30),
                "LWPOLYLINE" => entities::ocs(body, 38),
                "POLYLINE" if flags & 8 == 0 => entities::ocs(body, 30),
                _ => (Affine::IDENTITY, false),
            };
            if tilted {
                self.tilted += 1;
            }
            let m = &m.then_after(&ocs);
            match result
                .and_then(|(segs, closed)| self.place_segments(&segs, m).map(|s| (s, closed)))
            {
                Ok((segments, closed)) => {
                    if segments.is_empty() {
                        continue;
                    }
                    self.add_entity(Entity {
                        kind: kind_name,
                        layer,
                        place,
                        segments,
                        closed,
                    });
                }
                Err(reason) => {
                    if top {
                        *self.skipped.entry(kind).or_default() += 1;
                    }
                    let at = entities::point(body, 10)
                        .ok()
                        .map(|p| m.apply(p))
                        .filter(|p| p.is_finite());
                    let msg = format!("{kind_name} at {place} skipped: {reason}");
                    self.d.warnings.push(Warning::maybe_at(msg, at));
                }
            }
        }
    }

    /// Maps drawing-unit segments to mm and checks their range.
    fn place_segments(&mut self, segs: &[Segment], m: &Affine) -> Result<Vec<Segment>, String> {
        if segs.len() > self.budget {
            // Stop expanding altogether: `finish` says so once.
            self.budget = 0;
            return Err(format!(
                "the drawing expands to more than {MAX_SEGMENTS} segments"
            ));
        }
        let mut out = Vec::with_capacity(segs.len());
        transform_segments(segs, m, self.options.chord, &mut out);
        let ok = out.iter().all(|s| {
            s.is_finite()
                && [s.a.x, s.a.y, s.b.x, s.b.y]
                    .iter()
                    .all(|v| v.abs() <= MAX_COORD_MM)
        });
        if !ok {
            return Err(format!(
                "a coordinate is out of range (beyond {MAX_COORD_MM} mm)"
            ));
        }
        self.budget -= out.len();
        Ok(out)
    }

    fn add_entity(&mut self, e: Entity) {
        let l = &mut self.d.layers[e.layer as usize];
        l.entities += 1;
        if l.selected {
            self.d.entities.push(e);
        } else {
            *self.off_layers.entry(e.layer).or_default() += 1;
        }
    }

    fn add_spot(&mut self, at: Point, layer: u32) {
        if self.d.layers[layer as usize].selected {
            self.d.spots.push(Spot {
                at,
                layer,
                after_entities: self.d.entities.len(),
            });
        } else {
            *self.off_layers.entry(layer).or_default() += 1;
        }
    }

    /// INSERT: block name 2, insertion point 10/20 (in the insert's OCS),
    /// scales 41/42, rotation 50 (degrees), columns/rows 70/71 with spacings
    /// 44/45. Each copy maps block point p to
    /// OCS · T(ins) · R(rot) · T(col·dx, row·dy) · S(sx, sy) · T(−base) · p.
    fn insert(
        &mut self,
        body: &[Pair<'a>],
        m: &Affine,
        layer: u32,
        place: Place,
        stack: &mut Vec<&'a [u8]>,
    ) {
        let name = body
            .iter()
            .find(|p| p.code == 2)
            .map(|p| p.trimmed())
            .unwrap_or(b"");
        let shown = self.decoder.decode(name);
        let Some(block) = self.blocks.get(name).map(|b| (b.base, b.from, b.to)) else {
            self.d.warnings.push(Warning::new(format!(
                "INSERT at {place}: block '{shown}' is not defined"
            )));
            return;
        };
        if stack.contains(&name) || stack.len() >= MAX_BLOCK_DEPTH {
            self.d.warnings.push(Warning::new(format!(
                "INSERT at {place}: block '{shown}' inserts itself or nests deeper than {MAX_BLOCK_DEPTH}: not expanded"
            )));
            return;
        }
        let (ocs, tilted) = entities::ocs(body, 30);
        if tilted {
            self.tilted += 1;
        }
        let num = |c: i32, default: f64| {
            entities::num(body, c)
                .filter(|v| v.is_finite())
                .unwrap_or(default)
        };
        let ins = entities::point(body, 10).unwrap_or_default();
        let (sx, sy, rot) = (num(41, 1.0), num(42, 1.0), num(50, 0.0));
        let cols = num(70, 1.0).clamp(1.0, 1e6) as usize;
        let mut rows = num(71, 1.0).clamp(1.0, 1e6) as usize;
        if cols * rows > MAX_ARRAY_COPIES {
            self.d.warnings.push(Warning::new(format!(
                "INSERT at {place} of '{shown}' asks for {cols} × {rows} copies: only the first {MAX_ARRAY_COPIES} are made"
            )));
            rows = (MAX_ARRAY_COPIES / cols).max(1);
        }
        let cols = cols.min(MAX_ARRAY_COPIES);
        let (dx, dy) = (num(44, 0.0), num(45, 0.0));
        if sx == 0.0 || sy == 0.0 {
            self.d.warnings.push(Warning::new(format!(
                "INSERT at {place} of '{shown}' has a zero scale: skipped"
            )));
            return;
        }
        let (base, from, to) = block;
        stack.push(name);
        for r in 0..rows {
            for c in 0..cols {
                if self.budget == 0 {
                    break;
                }
                let local = Affine::translate(ins.x, ins.y)
                    .then_after(&Affine::rotate_deg(rot))
                    .then_after(&Affine::translate(c as f64 * dx, r as f64 * dy))
                    .then_after(&Affine::scale_xy(sx, sy))
                    .then_after(&Affine::translate(-base.x, -base.y));
                let mm = m.then_after(&ocs).then_after(&local);
                if mm.is_finite() {
                    self.walk(from, to, &mm, Some(layer), false, stack);
                }
            }
        }
        stack.pop();
    }

    fn finish(mut self) -> Drawing {
        let mut d = std::mem::take(&mut self.d);
        let named = |m: &HashMap<&[u8], usize>| -> BTreeMap<String, usize> {
            let mut out = BTreeMap::new();
            for (k, n) in m {
                *out.entry(String::from_utf8_lossy(k).into_owned())
                    .or_default() += n;
            }
            out
        };
        d.counts = named(&self.counts);
        d.skipped = named(&self.skipped);
        let in_blocks_skipped = named(&self.in_blocks_skipped);
        if self.budget == 0 {
            d.warnings.push(Warning::new(format!(
                "the drawing expands to more than {MAX_SEGMENTS} segments: the rest was not read"
            )));
        }
        if self.tilted > 0 {
            d.warnings.push(Warning::new(format!(
                "{} entit{} drawn in a tilted plane (extrusion not along Z): projected onto XY",
                self.tilted,
                if self.tilted == 1 { "y" } else { "ies" }
            )));
        }
        if self.paper_space > 0 {
            d.warnings.push(Warning::new(format!(
                "{} paper-space entit{} ignored (only model space is cut)",
                self.paper_space,
                if self.paper_space == 1 { "y" } else { "ies" }
            )));
        }
        let other: Vec<String> = d.skipped.iter().map(|(k, n)| format!("{k} ×{n}")).collect();
        if !other.is_empty() {
            d.warnings.push(Warning::new(format!(
                "entities not cut: {}",
                other.join(", ")
            )));
        }
        let in_blocks: Vec<String> = in_blocks_skipped
            .iter()
            .map(|(k, n)| format!("{k} ×{n}"))
            .collect();
        if !in_blocks.is_empty() {
            d.warnings.push(Warning::new(format!(
                "inside blocks, entities not cut: {}",
                in_blocks.join(", ")
            )));
        }
        if !self.off_layers.is_empty() {
            let list: Vec<String> = self
                .off_layers
                .iter()
                .map(|(&l, n)| format!("'{}' ×{n}", d.layers[l as usize].name))
                .collect();
            d.warnings.push(Warning::new(format!(
                "entities on layers not selected for cutting: {}",
                list.join(", ")
            )));
        }
        if d.entities.is_empty() {
            d.warnings
                .push(Warning::new("no cuttable geometry in model space"));
        } else {
            check_size(&mut d);
        }
        d
    }
}

/// Warns when the scaled drawing is implausibly small or large for a cutting table.
fn check_size(d: &mut Drawing) {
    let mut bb = crate::geom::BBox::EMPTY;
    for s in all_segments(d) {
        bb.union(&s.bbox());
    }
    let side = (bb.max.x - bb.min.x).max(bb.max.y - bb.min.y);
    let unit = d.units.map_or("mm", |u| u.name);
    if side > PLAUSIBLE_SIDE_MM.1 || side < PLAUSIBLE_SIDE_MM.0 {
        d.warnings.push(Warning::at(
            format!(
                "the drawing is {side:.3} mm across (drawn in {unit}): check the drawing's units"
            ),
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
