//! A [`Nest`] as geometry: a [`Drawing`] of one sheet (what the cutting
//! pipeline reads: `contour::extract` → kerf → plan → G-code, unchanged),
//! and the nest as a DXF file (every sheet, side by side).
//!
//! Parts are moved by each placement's map (mirror, turn, move); arcs stay
//! arcs: a mirrored arc turns the other way, its bulge negated
//! ([`transform_segments`] does this for every similarity).

use super::{remnant, Nest, NestJob, Placement, Sheets};
use crate::dxf::{Drawing, Entity, Layer, Place, Units};
use crate::geom::{transform_segments, BBox, Segment};
use crate::source::ContourRef;
use crate::warning::Lang;

/// Layer of the sheet outlines in the nest DXF.
pub const SHEET_LAYER: &str = "SHEET";
/// Gap between sheets drawn side by side in the nest DXF, as a fraction of
/// the sheet's width.
pub(super) const SHEET_GAP: f64 = 0.1;

/// The loops (outer first, then holes) of one placed copy.
pub fn placed_loops(job: &NestJob, p: &Placement) -> Vec<Vec<Segment>> {
    let part = &job.parts[p.part];
    let m = p.affine();
    std::iter::once(&part.outer)
        .chain(&part.holes)
        .map(|l| {
            let mut out = Vec::with_capacity(l.len());
            // A rigid map keeps circles circles: the chord is not used.
            transform_segments(l, &m, job.settings.tolerance, &mut out);
            out
        })
        .collect()
}

/// A layer name DXF accepts: the part's name with `<>/\":;?*|=,` and
/// control characters replaced by `_`.
pub fn layer_name(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_control() || "<>/\\\":;?*|=,`".contains(c) {
                '_'
            } else {
                c
            }
        })
        .collect();
    if s.is_empty() {
        "PART".into()
    } else {
        s
    }
}

/// The parts of sheet `sheet` as a drawing in sheet coordinates (lower-left
/// corner at 0, 0), one layer per part, one entity per loop.
pub fn sheet_drawing(job: &NestJob, nest: &Nest, sheet: usize) -> Drawing {
    let mut d = Drawing {
        units: Some(Units::MM),
        units_source: "nest",
        ..Default::default()
    };
    let mut extent = BBox::EMPTY;
    for p in nest.placements.iter().filter(|p| p.sheet == sheet) {
        let name = layer_name(&job.parts[p.part].name);
        let layer = match d.layers.iter().position(|l| l.name == name) {
            Some(i) => i,
            None => {
                d.layers.push(Layer {
                    name,
                    color: 7,
                    visible: true,
                    selected: true,
                    entities: 0,
                });
                d.layers.len() - 1
            }
        };
        for (k, segments) in placed_loops(job, p).into_iter().enumerate() {
            for s in &segments {
                extent.union(&s.bbox());
            }
            d.layers[layer].entities += 1;
            *d.counts.entry("LWPOLYLINE".into()).or_default() += 1;
            d.entities.push(Entity {
                kind: "LWPOLYLINE",
                layer: layer as u32,
                place: Place::Line(0),
                segments,
                closed: true,
                source: Some(ContourRef {
                    part: p.part as u32 + 1,
                    copy: p.copy as u32,
                    contour: k as u32,
                }),
                insert: None,
            });
        }
    }
    d.extent = extent;
    d
}

pub(super) fn polyline(out: &mut String, handle: &mut u32, layer: &str, segs: &[Segment]) {
    // R2000 wants a handle and the subclass markers (ezdxf refuses the
    // entity without AcDbPolyline).
    *handle += 1;
    out.push_str(&format!(
        "0\nLWPOLYLINE\n5\n{handle:X}\n100\nAcDbEntity\n8\n{layer}\n100\nAcDbPolyline\n90\n{}\n70\n1\n",
        segs.len()
    ));
    for s in segs {
        out.push_str(&format!("10\n{}\n20\n{}\n", s.a.x, s.a.y));
        if !s.is_line() {
            out.push_str(&format!("42\n{}\n", s.bulge));
        }
    }
}

/// The nest's figures and placements as JSON (the CLI's `--json`, the
/// page's nest result): `mode, time_s, placed, evaluations, unplaced[{part,
/// copies, reason (in `lang`), reason_text ({en, pt-BR}: the page's language
/// may change after the nest)}], sheets[{width, height, parts, used_length,
/// utilisation, crop_x}], strip_length, density, spacing, placements[{part,
/// copy, sheet, rotation, mirror, translation, in_hole_of}]`.
pub fn to_json(job: &NestJob, n: &Nest, seconds: f64, lang: Lang) -> serde_json::Value {
    let mode = if matches!(job.sheets, Sheets::Strip { .. }) {
        "strip"
    } else {
        "sheets"
    };
    serde_json::json!({
        "mode": mode,
        "time_s": seconds,
        "placed": n.placements.len(),
        "evaluations": n.evaluations,
        "unplaced": n.unplaced.iter().map(|u| serde_json::json!({"part": u.part, "copies": u.copies, "reason": u.reason.get(lang), "reason_text": u.reason})).collect::<Vec<_>>(),
        "sheets": n.sheets.iter().map(|s| serde_json::json!({
            "width": s.width, "height": s.height, "parts": s.parts,
            "used_length": s.used_length, "utilisation": s.utilisation,
            "crop_x": s.crop_x})).collect::<Vec<_>>(),
        "strip_length": n.strip_length,
        "density": n.density,
        "spacing": job.settings.spacing,
        "placements": n.placements.iter().map(|p| serde_json::json!({
            "part": job.parts[p.part].name, "copy": p.copy, "sheet": p.sheet,
            "rotation": p.rotation, "mirror": p.mirror,
            "translation": [p.translation.x, p.translation.y],
            "in_hole_of": p.in_hole_of.map(|(part, copy)| serde_json::json!({
                "part": job.parts[part].name, "copy": copy})),
            })).collect::<Vec<_>>(),
    })
}

/// Strokes drawn over one sheet of the nest's files (a part's label): open
/// polylines on a layer of their own, named by `name` (escaped where a
/// format needs it: it is data).
#[derive(Clone, Copy, Debug)]
pub struct Overlay<'a> {
    /// Which sheet.
    pub sheet: usize,
    /// Its layer (DXF) or group class (SVG).
    pub layer: &'a str,
    /// What it stands for (a label's text).
    pub name: &'a str,
    /// The polylines, sheet coordinates.
    pub paths: &'a [Vec<crate::geom::Point>],
}

fn open_polyline(out: &mut String, handle: &mut u32, layer: &str, pts: &[crate::geom::Point]) {
    *handle += 1;
    out.push_str(&format!(
        "0\nLWPOLYLINE\n5\n{handle:X}\n100\nAcDbEntity\n8\n{layer}\n100\nAcDbPolyline\n90\n{}\n70\n0\n",
        pts.len()
    ));
    for p in pts {
        out.push_str(&format!("10\n{}\n20\n{}\n", p.x, p.y));
    }
}

/// Layer of the crop line in the nest DXF.
pub const REMNANT_LAYER: &str = "REMNANT";
pub use super::sheet::DEFECT_LAYER;

const DXF_HEAD: &str = "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
const DXF_TAIL: &str = "0\nENDSEC\n0\nEOF\n";

fn line(out: &mut String, handle: &mut u32, layer: &str, s: &Segment) {
    *handle += 1;
    out.push_str(&format!(
        "0\nLINE\n5\n{handle:X}\n100\nAcDbEntity\n8\n{layer}\n100\nAcDbLine\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
        s.a.x, s.a.y, s.b.x, s.b.y
    ));
}

fn closed(pts: &[crate::geom::Point]) -> Vec<Segment> {
    (0..pts.len())
        .map(|i| Segment::line(pts[i], pts[(i + 1) % pts.len()]))
        .collect()
}

fn shifted(segs: &[Segment], dx: f64) -> Vec<Segment> {
    let d = crate::geom::Point::new(dx, 0.0);
    segs.iter()
        .map(|s| Segment {
            a: s.a.add(d),
            b: s.b.add(d),
            bulge: s.bulge,
        })
        .collect()
}

/// The nest as a DXF (R2000, mm): every placed copy as closed LWPOLYLINEs
/// (bulges for arcs) on a layer named after its part, each sheet's outline
/// (the strip's, up to the used length; a remnant's own outline, its no-go
/// zones on `DEFECT`) on layer `SHEET`, the crop line on `REMNANT`. Sheet
/// k is drawn k × 1.1 sheet widths to the right of the first.
pub fn to_dxf(job: &NestJob, nest: &Nest) -> String {
    to_dxf_with(job, nest, &[])
}

/// [`to_dxf`] with `overlays` drawn over their sheets (open LWPOLYLINEs
/// on their layers).
pub fn to_dxf_with(job: &NestJob, nest: &Nest, overlays: &[Overlay]) -> String {
    let mut out = String::from(DXF_HEAD);
    let mut handle = 0x100;
    let mut x = 0.0;
    let mut offsets = Vec::new();
    for (k, s) in nest.sheets.iter().enumerate() {
        offsets.push(x);
        match &job.sheets {
            Sheets::Remnant { outline, no_go } => {
                polyline(&mut out, &mut handle, SHEET_LAYER, &shifted(outline, x));
                for z in no_go {
                    polyline(&mut out, &mut handle, DEFECT_LAYER, &shifted(z, x));
                }
            }
            _ => {
                let (w, h) = (s.width, s.height);
                let c = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)]
                    .map(|(a, b)| crate::geom::Point::new(a + x, b));
                polyline(&mut out, &mut handle, SHEET_LAYER, &closed(&c));
            }
        }
        for l in crop_segments(job, nest, k) {
            line(&mut out, &mut handle, REMNANT_LAYER, &shifted(&[l], x)[0]);
        }
        x += s.width * (1.0 + SHEET_GAP);
    }
    for p in &nest.placements {
        let layer = layer_name(&job.parts[p.part].name);
        let dx = offsets.get(p.sheet).copied().unwrap_or(0.0);
        for l in placed_loops(job, p) {
            polyline(&mut out, &mut handle, &layer, &shifted(&l, dx));
        }
    }
    for o in overlays {
        let dx = offsets.get(o.sheet).copied().unwrap_or(0.0);
        let d = crate::geom::Point::new(dx, 0.0);
        for path in o.paths.iter().filter(|p| p.len() >= 2) {
            let moved: Vec<_> = path.iter().map(|q| q.add(d)).collect();
            open_polyline(&mut out, &mut handle, o.layer, &moved);
        }
    }
    out.push_str(DXF_TAIL);
    out
}

/// The parts of sheet `k` alone as a DXF (sheet coordinates, a layer per
/// part): what the cutting pipeline reads for that sheet.
pub fn sheet_dxf(job: &NestJob, nest: &Nest, k: usize) -> String {
    let mut out = String::from(DXF_HEAD);
    let mut handle = 0x100;
    for p in nest.placements.iter().filter(|p| p.sheet == k) {
        let layer = layer_name(&job.parts[p.part].name);
        for l in placed_loops(job, p) {
            polyline(&mut out, &mut handle, &layer, &l);
        }
    }
    out.push_str(DXF_TAIL);
    out
}

/// The crop line of sheet `k` (empty unless it keeps a remnant), from its
/// upper end on the sheet's edge down.
pub fn crop_segments(job: &NestJob, nest: &Nest, k: usize) -> Vec<Segment> {
    match nest.sheets.get(k).and_then(|s| s.crop_x) {
        Some(x) => remnant::crop_line(&job.sheets.sheet(k), x, job.settings.tolerance),
        None => Vec::new(),
    }
}

/// The remnant kept from the last sheet as a DXF a later nest reads as its
/// sheet (`--sheet-dxf`): its outline on layer `SHEET`, the no-go zones
/// reaching into it on `DEFECT`, in the sheet's coordinates (the remnant
/// stays where it lies on the table). None when no remnant is kept.
pub fn remnant_dxf(job: &NestJob, nest: &Nest) -> Option<String> {
    let x = nest.sheets.last()?.crop_x?;
    let last = job.sheets.sheet(nest.sheets.len() - 1);
    let (outline, zones) = remnant::remnant(&last, x, job.settings.tolerance);
    if outline.len() < 3 {
        return None;
    }
    let mut out = String::from(DXF_HEAD);
    let mut handle = 0x100;
    polyline(&mut out, &mut handle, SHEET_LAYER, &closed(&outline));
    for z in &zones {
        polyline(&mut out, &mut handle, DEFECT_LAYER, &closed(z));
    }
    out.push_str(DXF_TAIL);
    Some(out)
}
