//! Labels into the nest's outputs: overlays of the nest DXF and SVG
//! (layer [`super::LABEL_LAYER`]), entities of a sheet's drawing for the
//! cutting pipeline to mark, and the nest's JSON.

use super::{Labels, LABEL_LAYER};
use crate::dxf::{Drawing, Entity, Layer, Place};
use crate::geom::Segment;
use crate::nest::output::Overlay;
use crate::nest::NestJob;

/// One overlay per label, on layer `LABELS`.
pub fn overlays(labels: &Labels) -> Vec<Overlay<'_>> {
    labels
        .labels
        .iter()
        .map(|l| Overlay {
            sheet: l.sheet,
            layer: LABEL_LAYER,
            name: &l.text,
            paths: &l.strokes,
        })
        .collect()
}

/// Adds the labels of sheet `sheet` to its drawing as open polylines on a
/// layer of their own (`LABELS`, or `LABELS_2`… when a part's layer has
/// that name), and returns that layer's name: the caller makes it a
/// marking layer.
pub fn add_to_drawing(d: &mut Drawing, labels: &Labels, sheet: usize) -> String {
    let taken = |n: &str| d.layers.iter().any(|l| l.name.eq_ignore_ascii_case(n));
    let mut name = LABEL_LAYER.to_string();
    let mut k = 1;
    while taken(&name) {
        k += 1;
        name = format!("{LABEL_LAYER}_{k}");
    }
    let layer = d.layers.len() as u32;
    let mut count = 0;
    for l in labels.labels.iter().filter(|l| l.sheet == sheet) {
        for s in l.strokes.iter().filter(|s| s.len() >= 2) {
            let segments: Vec<Segment> = s.windows(2).map(|w| Segment::line(w[0], w[1])).collect();
            for seg in &segments {
                d.extent.union(&seg.bbox());
            }
            d.entities.push(Entity {
                kind: "LWPOLYLINE",
                layer,
                place: Place::Line(0),
                segments,
                closed: false,
                source: None,
                insert: None,
            });
            count += 1;
        }
    }
    *d.counts.entry("LWPOLYLINE".into()).or_default() += count;
    d.layers.push(Layer {
        name: name.clone(),
        color: 1,
        visible: true,
        selected: true,
        entities: count,
    });
    name
}

/// The labels as JSON: `labels[{part, copy, sheet, text, height, centre,
/// angle}]`, `labels_left_out[{part, copy}]` (copies 1-based, as the
/// labels say them).
pub fn to_json(job: &NestJob, labels: &Labels) -> (serde_json::Value, serde_json::Value) {
    let name = |p: usize| job.parts.get(p).map_or("", |p| p.name.as_str());
    (
        labels
            .labels
            .iter()
            .map(|l| {
                serde_json::json!({
                    "part": name(l.part), "copy": l.copy + 1, "sheet": l.sheet + 1,
                    "text": l.text, "height": l.height,
                    "centre": [l.centre.x, l.centre.y], "angle": l.angle,
                })
            })
            .collect(),
        labels
            .left_out
            .iter()
            .map(|&(p, c)| serde_json::json!({"part": name(p), "copy": c + 1}))
            .collect(),
    )
}
