//! The reader against an independent one: for every corpus file, entity
//! counts per type, units and the extents of the cuttable geometry must
//! match what ezdxf computes (`tests/reference/corpus.json`, made by
//! `tests/reference/ezdxf_reference.py`).
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use std::collections::BTreeMap;

use kerfcam::dxf::{self, ReadOptions, Units};
use kerfcam::geom::BBox;
use serde_json::Value;

#[test]
fn corpus_counts_units_and_extents_match_ezdxf() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/reference/corpus.json"
    ))
    .unwrap();
    let reference: BTreeMap<String, Value> = serde_json::from_str(&text).unwrap();
    let root = common::shared().join("corpus");
    let mut failures = Vec::new();
    let mut checked = 0;
    for (name, r) in &reference {
        if r.get("error").is_some() {
            continue;
        }
        let bytes = std::fs::read(root.join(name)).unwrap();
        let d = match dxf::parse(&bytes, &ReadOptions::DEFAULT) {
            Ok(d) => d,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        checked += 1;
        let want: BTreeMap<String, usize> = serde_json::from_value(r["counts"].clone()).unwrap();
        if want != d.counts {
            failures.push(format!("{name}: counts {:?} != ezdxf {want:?}", d.counts));
        }
        let ins = r["insunits"].as_i64().unwrap_or(0);
        let scale = match Units::from_insunits(ins) {
            Some(u) => {
                if d.units != Some(u) {
                    failures.push(format!("{name}: units {:?}, $INSUNITS {ins}", d.units));
                }
                u.to_mm
            }
            None => d.units.map_or(1.0, |u| u.to_mm),
        };
        let mut bb = BBox::EMPTY;
        for s in dxf::all_segments(&d) {
            bb.union(&s.bbox());
        }
        match r["bbox"].as_array() {
            Some(b) => {
                let want: Vec<f64> = b.iter().map(|v| v.as_f64().unwrap() * scale).collect();
                let got = bb.to_array();
                let size = (want[2] - want[0]).max(want[3] - want[1]).max(1.0);
                // Curves are lines within 0.01 mm here and flattened by ezdxf too.
                let eps = 1e-6 * size + 0.05;
                if got.iter().zip(&want).any(|(g, w)| (g - w).abs() > eps) {
                    failures.push(format!("{name}: extents {got:?} != ezdxf {want:?}"));
                }
            }
            None => {
                if !bb.is_empty() {
                    failures.push(format!(
                        "{name}: geometry found where ezdxf has none: {:?}",
                        bb.to_array()
                    ));
                }
            }
        }
    }
    assert!(checked >= 50, "only {checked} files checked");
    assert!(
        failures.is_empty(),
        "{} of {checked} files differ:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Chord tolerance for the per-category comparison, mm: small, so the
/// bounds below that follow from it are tight.
const CHORD_MM: f64 = 1e-6;

/// Per awkward category (spline, ellipse, mirrored nested insert, extrusion
/// −Z, binary, code page, no header), total length, extents, the signed area
/// of every closed entity and the layers holding geometry, against ezdxf
/// (`tests/reference/categories.json`, made by
/// `tests/reference/ezdxf_categories.py`; lines, arcs and bulges computed
/// exactly there, splines and ellipses flattened to `flat`, about 1e-8 of
/// the drawing's size).
///
/// Bounds. Lines and arcs are read exactly (up to rounding): everything to
/// 1e-6 relative. A SPLINE or ELLIPSE becomes biarcs within the chord `t`
/// of the curve (Hausdorff distance), so:
/// - extents: each side moves by at most `t` (plus ezdxf's `flat`);
/// - area of a closed curve: the two regions differ only inside the band of
///   half-width `t` around the curve, whose area is at most 2·t·L + π·t²;
/// - length: each fitted arc and the piece of curve between the same end
///   points, closed by their common chord, are convex at this fineness and
///   within `t` of each other, so by Cauchy's formula (perimeter = integral
///   of the width over directions) their perimeters differ by at most 2π·t:
///   |ΔL| ≤ 2π·t per fitted segment (ezdxf's flattening shortens it by less
///   than 2π·flat per piece, and far less in total).
#[test]
fn category_geometry_matches_ezdxf() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/reference");
    let text = std::fs::read_to_string(format!("{dir}/categories.json")).unwrap();
    let reference: BTreeMap<String, Value> = serde_json::from_str(&text).unwrap();
    let corpus = common::shared().join("corpus");
    let options = ReadOptions {
        chord: CHORD_MM,
        ..ReadOptions::DEFAULT
    };
    let mut failures = Vec::new();
    let mut categories = std::collections::BTreeSet::new();
    for (name, r) in &reference {
        let path = match name.strip_prefix("fixtures/") {
            Some(f) => std::path::Path::new(dir).join("fixtures").join(f),
            None => corpus.join(name),
        };
        let d = dxf::parse(&std::fs::read(&path).unwrap(), &options).unwrap();
        categories.insert(r["category"].as_str().unwrap().to_string());
        let mut fail = |what: String| failures.push(format!("{name}: {what}"));
        // Back to drawing units, the reference's.
        let s = d.units.map_or(1.0, |u| u.to_mm);
        if let Some(ins) = r["insunits"].as_i64() {
            if let Some(u) = Units::from_insunits(ins) {
                if d.units != Some(u) {
                    fail(format!("units {:?}, $INSUNITS {ins}", d.units));
                }
            }
        }
        let t = CHORD_MM / s;
        let flat = r["flat"].as_f64().unwrap();
        let curve = |e: &dxf::Entity| matches!(e.kind, "SPLINE" | "ELLIPSE");
        let curve_segments: usize = d
            .entities
            .iter()
            .filter(|e| curve(e))
            .map(|e| e.segments.len())
            .sum();
        let length: f64 = dxf::all_segments(&d).map(|g| g.length()).sum::<f64>() / s;
        let want = r["length"].as_f64().unwrap();
        let bound = 1e-6 * want + curve_segments as f64 * 2.0 * std::f64::consts::PI * (t + flat);
        if (length - want).abs() > bound {
            fail(format!("length {length} != ezdxf {want} (bound {bound:e})"));
        }
        let mut bb = BBox::EMPTY;
        for g in dxf::all_segments(&d) {
            bb.union(&g.bbox());
        }
        let got = bb.to_array().map(|v| v / s);
        let want: Vec<f64> = r["bbox"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let size = (want[2] - want[0]).max(want[3] - want[1]);
        let any_curve = curve_segments > 0;
        let bound = 1e-6 * size + if any_curve { t + flat } else { 0.0 };
        if got.iter().zip(&want).any(|(g, w)| (g - w).abs() > bound) {
            fail(format!(
                "extents {got:?} != ezdxf {want:?} (bound {bound:e})"
            ));
        }
        let mut areas: Vec<(f64, f64)> = d
            .entities
            .iter()
            .filter(|e| e.closed)
            .map(|e| {
                let len: f64 = e.segments.iter().map(|g| g.length()).sum::<f64>() / s;
                let band = if curve(e) {
                    2.0 * (t + flat) * len + std::f64::consts::PI * (t + flat).powi(2)
                } else {
                    0.0
                };
                (kerfcam::geom::loop_area(&e.segments) / (s * s), band)
            })
            .collect();
        areas.sort_by(|a, b| a.0.total_cmp(&b.0));
        let want: Vec<f64> = r["areas"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        if areas.len() != want.len() {
            fail(format!(
                "{} closed entities, ezdxf {}",
                areas.len(),
                want.len()
            ));
        } else {
            for ((a, band), w) in areas.iter().zip(&want) {
                let bound = 1e-6 * w.abs() + 1e-12 * size * size + band;
                if (a - w).abs() > bound {
                    fail(format!("area {a} != ezdxf {w} (bound {bound:e})"));
                }
            }
        }
        let layers: Vec<&str> = d
            .layers
            .iter()
            .filter(|l| l.entities > 0 && l.visible)
            .map(|l| l.name.as_str())
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        // Names trimmed: ezdxf keeps a name's leading blanks (" 1"), kerfcam
        // trims them as it trims every DXF value (CAD programs refuse such names).
        let want: Vec<&str> = r["layers"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap().trim())
            .collect();
        if layers != want {
            fail(format!("layers {layers:?} != ezdxf {want:?}"));
        }
    }
    assert_eq!(categories.len(), 7, "{categories:?}");
    assert!(
        failures.is_empty(),
        "{} differences:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
