//! The reader against an independent one: for every corpus file, entity
//! counts per type, units and the extents of the cuttable geometry must
//! match what ezdxf computes (`tests/reference/corpus.json`, made by
//! `tests/reference/ezdxf_reference.py`).
#![cfg(not(target_arch = "wasm32"))]

mod common;

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
