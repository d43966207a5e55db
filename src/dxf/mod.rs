//! Stage 1: DXF bytes → [`Drawing`].
//!
//! # Output contract
//! - Coordinates are in millimetres (scaled from `$INSUNITS`; unset = mm), Y up.
//! - Geometry is only [`Segment`]s: lines and arcs of at most 180°; circles
//!   are two half arcs; OCS extrusion (0,0,-1) is applied (mirrored arcs).
//! - Every model-space entity is counted by type; those not turned into
//!   geometry are counted again in `skipped`, and the reason is a warning.
//! - Only the HEADER and ENTITIES sections are read (paper 000: "only the
//!   ENTITIES section matters for geometry"); BLOCKS, binary DXF, splines and
//!   ellipses are left to the full-fidelity reader and reported as skipped.

mod entities;
mod pairs;
mod units;

use std::collections::BTreeMap;
use std::fmt;

pub use entities::Entity;
pub use units::Units;

use crate::geom::{Point, Segment};
use crate::warning::Warning;
use pairs::{AsciiPairs, BadCode, Pair};

/// What the reader found in the file.
#[derive(Clone, Debug, Default)]
pub struct Drawing {
    /// The unit the file was drawn in (everything here is already in mm).
    pub units: Option<Units>,
    /// Geometry entities, in file order.
    pub entities: Vec<Entity>,
    /// Model-space entities seen, by DXF type.
    pub counts: BTreeMap<String, usize>,
    /// Entities not turned into geometry, by DXF type.
    pub skipped: BTreeMap<String, usize>,
    /// What was skipped or doubtful, and where.
    pub warnings: Vec<Warning>,
}

/// Why a file could not be read at all.
#[derive(Clone, Debug, PartialEq)]
pub enum DxfError {
    /// The input is empty.
    Empty,
    /// A binary DXF (sentinel "AutoCAD Binary DXF"), not read by this version.
    Binary,
    /// The first lines are not group-code/value pairs.
    NotDxf(BadCode),
    /// The structure breaks before any geometry was read.
    Malformed(BadCode),
}

impl fmt::Display for DxfError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DxfError::Empty => write!(f, "the file is empty"),
            DxfError::Binary => write!(
                f,
                "binary DXF is not supported yet: save the drawing as ASCII DXF"
            ),
            DxfError::NotDxf(e) => write!(f, "not a DXF file ({e})"),
            DxfError::Malformed(e) => write!(f, "broken DXF: {e}"),
        }
    }
}

impl std::error::Error for DxfError {}

/// Entity types this reader turns into geometry.
const GEOMETRY: [&str; 5] = ["LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POLYLINE"];

/// Longest type name kept in the counts (longer ones are garbage).
const MAX_TYPE_LEN: usize = 32;

/// Reads an ASCII DXF.
pub fn parse(bytes: &[u8]) -> Result<Drawing, DxfError> {
    if bytes.iter().all(|b| b.is_ascii_whitespace()) {
        return Err(DxfError::Empty);
    }
    if bytes.starts_with(b"AutoCAD Binary DXF") {
        return Err(DxfError::Binary);
    }
    let mut reader = AsciiPairs::new(bytes);
    let mut raw = Vec::new();
    let mut bad = None;
    for p in reader.by_ref() {
        match p {
            Ok(p) => raw.push(p),
            Err(e) => {
                bad = Some(e);
                break;
            }
        }
    }
    if let Some(e) = &bad {
        if raw.is_empty() {
            return Err(DxfError::NotDxf(e.clone()));
        }
    }
    let mut d = Drawing::default();
    let mut insunits = None;
    let mut i = 0;
    let mut saw_section = false;
    while i < raw.len() {
        let p = raw[i];
        if p.code == 0 && p.is("SECTION") {
            saw_section = true;
            let name = raw
                .get(i + 1)
                .filter(|p| p.code == 2)
                .map(|p| p.trimmed())
                .unwrap_or(b"");
            i = (i + 2).min(raw.len());
            let end = section_end(&raw, i);
            match name {
                b"HEADER" => insunits = read_insunits(&raw[i..end]),
                b"ENTITIES" => read_entities(&raw[i..end], &mut d, units_scale(insunits)),
                _ => {}
            }
            i = end + 1;
        } else {
            i += 1;
        }
    }
    if !saw_section {
        // Not a single SECTION: treat the whole file as an entity list.
        read_entities(&raw, &mut d, units_scale(insunits));
    }
    d.units = match insunits {
        None | Some(0) => Some(Units::MM),
        Some(code) => Units::from_insunits(code),
    };
    if let Some(code) = insunits.filter(|&c| c != 0 && Units::from_insunits(c).is_none()) {
        d.warnings.push(Warning::new(format!(
            "$INSUNITS {code} is not a length unit: read as mm"
        )));
        d.units = Some(Units::MM);
    }
    if let Some(e) = bad {
        if d.entities.is_empty() && d.counts.is_empty() {
            return Err(DxfError::Malformed(e));
        }
        d.warnings.push(Warning::new(format!(
            "reading stopped at {e}; the rest of the file was ignored"
        )));
    } else if reader.truncated {
        d.warnings.push(Warning::new(
            "the file ends in the middle of a group: it may be truncated",
        ));
    }
    if d.entities.is_empty() {
        d.warnings.push(Warning::new(
            "no cuttable geometry (LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE) in model space",
        ));
    } else {
        check_size(&mut d);
    }
    Ok(d)
}

fn units_scale(insunits: Option<i64>) -> f64 {
    insunits
        .and_then(Units::from_insunits)
        .map_or(1.0, |u| u.to_mm)
}

/// Index of the `0 ENDSEC` that closes the section starting at `from`
/// (or the end of the input, for a file cut short).
fn section_end(raw: &[Pair], from: usize) -> usize {
    raw[from..]
        .iter()
        .position(|p| p.code == 0 && (p.is("ENDSEC") || p.is("EOF")))
        .map_or(raw.len(), |k| from + k)
}

/// `$INSUNITS` group 70 from the HEADER section.
fn read_insunits(header: &[Pair]) -> Option<i64> {
    let at = header
        .iter()
        .position(|p| p.code == 9 && p.is("$INSUNITS"))?;
    header[at + 1..]
        .iter()
        .take_while(|p| p.code != 9)
        .find(|p| p.code == 70)?
        .int()
}

/// Splits an entity list at its `0` pairs and builds each entity.
fn read_entities(raw: &[Pair], d: &mut Drawing, scale: f64) {
    let mut paper_space = 0usize;
    let mut i = 0;
    while i < raw.len() {
        if raw[i].code != 0 {
            i += 1;
            continue;
        }
        let head = raw[i];
        let body_end = raw[i + 1..]
            .iter()
            .position(|p| p.code == 0)
            .map_or(raw.len(), |k| i + 1 + k);
        let body = &raw[i + 1..body_end];
        let kind_text = head.text();
        i = body_end;
        if head.is("ENDSEC") || head.is("EOF") || head.is("SEQEND") {
            continue;
        }
        // VERTEX/SEQEND after a POLYLINE belong to it.
        let mut vertices: Vec<Vec<Pair>> = Vec::new();
        if head.is("POLYLINE") {
            while i < raw.len() && raw[i].code == 0 && raw[i].is("VERTEX") {
                let end = raw[i + 1..]
                    .iter()
                    .position(|p| p.code == 0)
                    .map_or(raw.len(), |k| i + 1 + k);
                vertices.push(raw[i + 1..end].to_vec());
                i = end;
            }
            if i < raw.len() && raw[i].is("SEQEND") {
                i = raw[i + 1..]
                    .iter()
                    .position(|p| p.code == 0)
                    .map_or(raw.len(), |k| i + 1 + k);
            }
        }
        let kind: String = kind_text.chars().take(MAX_TYPE_LEN).collect();
        *d.counts.entry(kind.clone()).or_default() += 1;
        let in_paper_space = body.iter().any(|p| p.code == 67 && p.int() == Some(1));
        if in_paper_space {
            paper_space += 1;
            *d.skipped.entry(kind).or_default() += 1;
            continue;
        }
        let Some(&geometry_kind) = GEOMETRY.iter().find(|g| head.is(g)) else {
            *d.skipped.entry(kind).or_default() += 1;
            continue;
        };
        let built = match geometry_kind {
            "LINE" => entities::line(body, scale),
            "ARC" => entities::arc(body, scale),
            "CIRCLE" => entities::circle(body, scale),
            "LWPOLYLINE" => entities::lwpolyline(body, scale),
            _ => entities::polyline(body, &vertices, scale).map(|(segs, closed, z)| {
                if let Some((lo, hi)) = z.filter(|(lo, hi)| hi - lo > 1e-6) {
                    let msg = format!(
                        "3-D POLYLINE at line {} is not flat (Z {lo:.3} to {hi:.3} mm): projected onto XY",
                        head.line
                    );
                    d.warnings.push(match segs.first() {
                        Some(s) => Warning::at(msg, s.a),
                        None => Warning::new(msg),
                    });
                }
                (segs, closed)
            }),
        };
        match built {
            Ok((segments, closed)) => d.entities.push(Entity {
                kind: geometry_kind,
                layer: body
                    .iter()
                    .find(|p| p.code == 8)
                    .map(Pair::text)
                    .unwrap_or_default(),
                line: head.line,
                segments,
                closed,
            }),
            Err(reason) => {
                *d.skipped.entry(kind).or_default() += 1;
                let at = first_point(body, scale);
                let msg = format!("{geometry_kind} at line {} skipped: {reason}", head.line);
                d.warnings.push(match at {
                    Some(p) => Warning::at(msg, p),
                    None => Warning::new(msg),
                });
            }
        }
    }
    if paper_space > 0 {
        d.warnings.push(Warning::new(format!(
            "{paper_space} paper-space entit{} ignored (only model space is cut)",
            if paper_space == 1 { "y" } else { "ies" }
        )));
    }
    let other: Vec<String> = d
        .skipped
        .iter()
        .filter(|(k, _)| !GEOMETRY.contains(&k.as_str()))
        .map(|(k, n)| format!("{k} ×{n}"))
        .collect();
    if !other.is_empty() {
        d.warnings.push(Warning::new(format!(
            "entity types not cut: {}",
            other.join(", ")
        )));
    }
}

/// The entity's first usable point, to locate a warning.
fn first_point(body: &[Pair], scale: f64) -> Option<Point> {
    let x = body.iter().find(|p| p.code == 10)?.f64()? * scale;
    let y = body.iter().find(|p| p.code == 20)?.f64()? * scale;
    let p = Point::new(x, y);
    (p.is_finite() && x.abs() < 1e9 && y.abs() < 1e9).then_some(p)
}

/// Sides of a plausible cutting job, mm: a drawing outside this range after
/// unit scaling was most likely saved with the wrong units.
const PLAUSIBLE_SIDE_MM: (f64, f64) = (1.0, 20_000.0);

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
            format!("the drawing is {side:.3} mm across (drawn in {unit}): check the drawing's units ($INSUNITS)"),
            bb.min,
        ));
    }
}

/// All segments of a drawing, entity by entity (for tests and tools).
pub fn all_segments(d: &Drawing) -> impl Iterator<Item = &Segment> {
    d.entities.iter().flat_map(|e| e.segments.iter())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dxf(body: &str) -> Vec<u8> {
        body.lines()
            .map(str::trim)
            .collect::<Vec<_>>()
            .join("\n")
            .into_bytes()
    }

    #[test]
    fn reads_a_line_in_inches_as_mm() {
        let src = dxf("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n1\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nCut\n10\n0\n20\n0\n11\n1\n21\n2\n0\nENDSEC\n0\nEOF");
        let d = parse(&src).unwrap();
        assert_eq!(d.units.unwrap().name, "in");
        assert_eq!(d.entities.len(), 1);
        assert_eq!(d.entities[0].layer, "Cut");
        assert_eq!(d.entities[0].segments[0].b, Point::new(25.4, 50.8));
    }

    #[test]
    fn unknown_entities_are_counted_and_skipped() {
        let src = dxf("0\nSECTION\n2\nENTITIES\n0\nTEXT\n1\nhello\n0\nTEXT\n1\nx\n0\nCIRCLE\n10\n0\n20\n0\n40\n5\n0\nENDSEC\n0\nEOF");
        let d = parse(&src).unwrap();
        assert_eq!(d.counts["TEXT"], 2);
        assert_eq!(d.skipped["TEXT"], 2);
        assert_eq!(d.counts["CIRCLE"], 1);
        assert!(d.warnings.iter().any(|w| w.message.contains("TEXT ×2")));
    }

    #[test]
    fn polyline_with_vertices_and_seqend() {
        let src = dxf("0\nSECTION\n2\nENTITIES\n0\nPOLYLINE\n66\n1\n70\n1\n0\nVERTEX\n10\n0\n20\n0\n0\nVERTEX\n10\n10\n20\n0\n0\nVERTEX\n10\n10\n20\n10\n0\nSEQEND\n0\nLINE\n10\n0\n20\n0\n11\n5\n21\n5\n0\nENDSEC\n0\nEOF");
        let d = parse(&src).unwrap();
        assert_eq!(d.entities.len(), 2);
        assert!(d.entities[0].closed);
        assert_eq!(d.entities[0].segments.len(), 3);
        assert_eq!(d.counts.get("VERTEX"), None);
    }

    #[test]
    fn garbage_is_not_a_dxf() {
        assert!(matches!(
            parse(b"\x89PNG\r\n\x1a\n"),
            Err(DxfError::NotDxf(_))
        ));
        assert!(matches!(parse(b"  \n"), Err(DxfError::Empty)));
        assert!(matches!(
            parse(b"AutoCAD Binary DXF\r\n\x1a\0"),
            Err(DxfError::Binary)
        ));
    }

    #[test]
    fn a_broken_tail_keeps_what_was_read_and_warns() {
        let src = dxf("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\nGARBAGE\n0");
        let d = parse(&src).unwrap();
        assert_eq!(d.entities.len(), 1);
        assert!(
            d.warnings.iter().any(|w| w.message.contains("line 15")),
            "{:?}",
            d.warnings
        );
    }

    #[test]
    fn paper_space_entities_are_skipped_and_said_so() {
        let src =
            dxf("0\nSECTION\n2\nENTITIES\n0\nLINE\n67\n1\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC");
        let d = parse(&src).unwrap();
        assert!(d.entities.is_empty());
        assert_eq!(d.skipped["LINE"], 1);
        assert!(d.warnings.iter().any(|w| w.message.contains("paper-space")));
    }
}
