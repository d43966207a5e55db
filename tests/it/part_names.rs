//! Part names from the drawing's blocks (issue 42 §1), on corpus files
//! that draw their parts as blocks. Which block drew a part is checked
//! here from the file's own pairs: the block's vertices, placed at its
//! INSERT's point, must hold the part's outline.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, HashSet};

use crate::common::shared;
use kerfcam::nest::{rows, spec};
use kerfcam::Settings;

/// (min x, min y, max x, max y) of a block's coordinates placed at its one
/// INSERT (the corpus files tested insert without scale or rotation: checked).
fn block_boxes(bytes: &[u8]) -> BTreeMap<String, [f64; 4]> {
    let text = String::from_utf8_lossy(bytes).replace('\r', "");
    let lines: Vec<&str> = text.lines().collect();
    let pairs: Vec<(i32, &str)> = lines
        .chunks(2)
        .filter(|c| c.len() == 2)
        .map(|c| (c[0].trim().parse().unwrap_or(-1), c[1].trim()))
        .collect();
    let (mut boxes, mut at) = (BTreeMap::<String, [f64; 4]>::new(), BTreeMap::new());
    let (mut block, mut name_next, mut section) = (None::<String>, false, "");
    let (mut kind, mut insert) = ("", String::new());
    let mut x = None;
    for (i, &(code, value)) in pairs.iter().enumerate() {
        if code == 2 && i > 0 && pairs[i - 1] == (0, "SECTION") {
            section = value;
        }
        if code == 0 {
            kind = value;
            x = None;
            match value {
                "BLOCK" => name_next = true,
                "ENDBLK" => block = None,
                _ => {}
            }
            continue;
        }
        if name_next && code == 2 {
            block = Some(value.to_owned());
            name_next = false;
            continue;
        }
        if section == "ENTITIES" && kind == "INSERT" {
            assert!(![41, 42, 50, 70, 71].contains(&code), "INSERT with group {code}");
            if code == 2 {
                insert = value.to_owned();
                at.insert(insert.clone(), [0.0; 2]);
            }
        }
        let Some(b) = &block else {
            if section == "ENTITIES" && kind == "INSERT" && (code == 10 || code == 20) {
                let p = at.get_mut(&insert).expect("the block name before the point");
                p[usize::from(code == 20)] = value.parse().unwrap();
            }
            continue;
        };
        if code == 10 {
            x = value.parse::<f64>().ok();
        } else if code == 20 {
            if let (Some(px), Ok(py)) = (x, value.parse::<f64>()) {
                let e = boxes.entry(b.clone()).or_insert([f64::MAX, f64::MAX, f64::MIN, f64::MIN]);
                *e = [e[0].min(px), e[1].min(py), e[2].max(px), e[3].max(py)];
            }
        }
    }
    boxes
        .into_iter()
        .filter_map(|(name, b)| {
            let [dx, dy] = *at.get(&name)?;
            Some((name, [b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy]))
        })
        .collect()
}

fn rows_of(rel: &str, stem: &str) -> (Vec<rows::PartRow>, Vec<u8>) {
    let bytes = std::fs::read(shared().join("corpus").join(rel)).unwrap();
    let cutting = Settings::new(1.5, 0.001, 2000.0).unwrap();
    let (parts, contours) = spec::parts_and_contours(&bytes, stem, &cutting).unwrap();
    (rows::file_rows(&parts, &contours, 0.05, 1.25).rows, bytes)
}

#[test]
fn pattern_pieces_drawn_as_blocks_are_named_after_their_blocks() {
    // CLO's export: each pattern piece a block inserted once at 0,0.
    let (rows, bytes) = rows_of("astm-parser/clo-pattern.dxf", "clo-pattern");
    let boxes = block_boxes(&bytes);
    assert_eq!(boxes.len(), 9, "{boxes:?}");
    let names: HashSet<&str> = rows.iter().map(|r| r.name.as_str()).collect();
    assert_eq!(names.len(), rows.len(), "names are unique: {names:?}");
    let mut named = 0;
    for r in &rows {
        let Some(block) = r.name.strip_prefix("clo-pattern/") else {
            assert!(r.name.starts_with("clo-pattern#"), "{}", r.name);
            continue;
        };
        named += 1;
        let b = boxes.get(block).unwrap_or_else(|| panic!("{}: no such block", r.name));
        let e = 0.01;
        assert!(
            r.x >= b[0] - e && r.y >= b[1] - e && r.x + r.width <= b[2] + e && r.y + r.height <= b[3] + e,
            "{} at {:?} lies outside block {block}'s {b:?}",
            r.name,
            (r.x, r.y, r.width, r.height)
        );
    }
    // 11 outlines; the two blocks that each drew two outlines (36_M,
    // 39_M) name neither of theirs.
    assert_eq!((rows.len(), named), (11, 7), "{names:?}");
}

#[test]
fn a_block_inserted_several_times_names_each_part_with_its_number() {
    let (rows, _) = rows_of("dxf2gcode-plasma/Linieblock1.dxf", "Linieblock1");
    let names: Vec<&str> = rows.iter().map(|r| r.name.as_str()).collect();
    let unique: HashSet<&&str> = names.iter().collect();
    assert_eq!(unique.len(), names.len(), "{names:?}");
    let of_block = names.iter().filter(|n| n.starts_with("Linieblock1/BLOCK_1#")).count();
    assert_eq!((names.len(), of_block), (7, 6), "{names:?}");
}

/// Each layer's entities' box, read from the file's own pairs (LINE and ARC
/// ends or centres, CIRCLE and ARC centres grown by the radius, polyline
/// vertices): a part named after a layer lies inside that layer's box.
fn layer_boxes(bytes: &[u8]) -> BTreeMap<String, [f64; 4]> {
    let text = String::from_utf8_lossy(bytes).replace('\r', "");
    let lines: Vec<&str> = text.lines().collect();
    let mut boxes = BTreeMap::<String, [f64; 4]>::new();
    let (mut in_entities, mut layer, mut x, mut r) = (false, String::new(), None::<f64>, 0.0);
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut flush = |layer: &str, points: &mut Vec<[f64; 2]>, r: f64| {
        for p in points.drain(..) {
            let e = boxes.entry(layer.to_owned()).or_insert([f64::MAX, f64::MAX, f64::MIN, f64::MIN]);
            *e = [e[0].min(p[0] - r), e[1].min(p[1] - r), e[2].max(p[0] + r), e[3].max(p[1] + r)];
        }
    };
    for c in lines.chunks(2).filter(|c| c.len() == 2) {
        let (code, value) = (c[0].trim().parse::<i32>().unwrap_or(-1), c[1].trim());
        match code {
            0 => {
                flush(&layer, &mut points, r);
                r = 0.0;
                if value == "ENDSEC" {
                    in_entities = false;
                }
            }
            2 if value == "ENTITIES" => in_entities = true,
            8 if in_entities => layer = value.to_owned(),
            10 | 11 if in_entities => x = value.parse().ok(),
            20 | 21 if in_entities => {
                if let (Some(px), Ok(py)) = (x.take(), value.parse::<f64>()) {
                    points.push([px, py]);
                }
            }
            40 if in_entities => r = value.parse().unwrap_or(0.0),
            _ => {}
        }
    }
    boxes
}

#[test]
fn parts_on_several_layers_are_named_after_their_layers() {
    // Pump parts, each kind on its own milling layer ('MILL: 1 Tg: …'),
    // the rest on layer 0.
    let (rows, bytes) = rows_of("dxf2gcode-plasma/pumpenteile.dxf", "pumpenteile");
    let boxes = layer_boxes(&bytes);
    let names: HashSet<&str> = rows.iter().map(|r| r.name.as_str()).collect();
    assert_eq!(names.len(), rows.len(), "names are unique: {names:?}");
    let mut by_layer = BTreeMap::<&str, usize>::new();
    for r in &rows {
        let rest = r.name.strip_prefix("pumpenteile").unwrap();
        let Some(layer) = rest.strip_prefix('/') else {
            assert!(rest.starts_with('#'), "{}", r.name);
            continue;
        };
        let layer = layer.rsplit_once('#').map_or(layer, |(l, _)| l);
        assert_ne!(layer, "0");
        *by_layer.entry(layer).or_default() += 1;
        let b = boxes.get(layer).unwrap_or_else(|| panic!("{}: no such layer", r.name));
        let e = 0.01;
        assert!(
            r.x >= b[0] - e && r.y >= b[1] - e && r.x + r.width <= b[2] + e && r.y + r.height <= b[3] + e,
            "{} at {:?} lies outside layer {layer}'s {b:?}",
            r.name,
            (r.x, r.y, r.width, r.height)
        );
    }
    assert_eq!(by_layer.len(), 3, "{by_layer:?}");
    assert!(by_layer.values().all(|&n| n > 1), "{by_layer:?}");
    // Every part of a file on one named layer: the layer tells none apart.
    let (rows, _) = rows_of("openbuilds-cam/Fan Grill  80mm - Concentric.dxf", "grille");
    assert!(rows.iter().all(|r| r.name.starts_with("grille#")), "{:?}", rows.iter().map(|r| &r.name).collect::<Vec<_>>());
}
