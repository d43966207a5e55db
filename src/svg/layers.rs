//! Layers of an SVG: an Inkscape layer (`<g inkscape:groupmode="layer">`,
//! named by its `inkscape:label`) or, outside layers, the colour an element
//! is drawn in (LightBurn's and most laser software's convention: a colour
//! per operation). A layer holding several colours is split by colour, so
//! cut and engrave lines drawn in one Inkscape layer can still be told
//! apart. Hidden elements go to layers that are off by default.

use std::collections::{BTreeMap, BTreeSet};

use super::style::Paint;
use crate::dxf::{Entity, Layer};

/// An entity read, with what names its layer.
pub struct Raw {
    pub entity: Entity,
    /// The Inkscape layer path ("Cut", "Parts/Holes").
    pub label: Option<String>,
    pub color: Option<Paint>,
    /// display:none or visibility:hidden.
    pub hidden: bool,
    /// Hidden because its Inkscape layer is: the layer keeps its name.
    pub layer_hidden: bool,
}

/// "#ff0000", "gradient", or "0" for nothing drawn.
fn color_name(c: Option<Paint>) -> String {
    match c {
        Some(Paint::Color(rgb)) => format!("#{rgb:06x}"),
        Some(Paint::Server) => "gradient".into(),
        Some(Paint::None) | None => "0".into(),
    }
}

/// The nearest of AutoCAD's first nine colours, for the layer's swatch.
fn aci(c: Option<Paint>) -> i16 {
    let Some(Paint::Color(rgb)) = c else { return 7 };
    let (r, g, b) = (
        (rgb >> 16) as i32,
        ((rgb >> 8) & 0xff) as i32,
        (rgb & 0xff) as i32,
    );
    const TABLE: [(i16, (i32, i32, i32)); 9] = [
        (1, (255, 0, 0)),
        (2, (255, 255, 0)),
        (3, (0, 255, 0)),
        (4, (0, 255, 255)),
        (5, (0, 0, 255)),
        (6, (255, 0, 255)),
        (7, (0, 0, 0)),
        (8, (128, 128, 128)),
        (9, (192, 192, 192)),
    ];
    let d = |(x, y, z): (i32, i32, i32)| (x - r).pow(2) + (y - g).pow(2) + (z - b).pow(2);
    TABLE
        .iter()
        .min_by_key(|(_, c)| d(*c))
        .map_or(7, |(i, _)| *i)
}

/// Names the layers, puts each entity on its own, and returns the layers
/// (in first-met order) with the entities (file order) and, per layer not
/// selected, how many entities it holds.
pub fn assign(
    raw: Vec<Raw>,
    chosen: Option<&[String]>,
) -> (Vec<Layer>, Vec<Entity>, BTreeMap<u32, usize>) {
    let mut colors: BTreeMap<&str, BTreeSet<Option<Paint>>> = BTreeMap::new();
    for r in &raw {
        if let Some(l) = &r.label {
            colors.entry(l).or_default().insert(r.color);
        }
    }
    let names: Vec<String> = raw
        .iter()
        .map(|r| {
            let base = match &r.label {
                Some(l) if colors[l.as_str()].len() > 1 => format!("{l} {}", color_name(r.color)),
                Some(l) => l.clone(),
                None => color_name(r.color),
            };
            if r.hidden && !r.layer_hidden {
                format!("{base} (hidden)")
            } else {
                base
            }
        })
        .collect();
    let mut layers: Vec<Layer> = Vec::new();
    let mut index: BTreeMap<String, u32> = BTreeMap::new();
    let mut entities = Vec::with_capacity(raw.len());
    for (r, name) in raw.into_iter().zip(names) {
        let id = *index.entry(name.clone()).or_insert_with(|| {
            layers.push(Layer {
                name,
                color: aci(r.color),
                visible: false,
                selected: false,
                entities: 0,
            });
            layers.len() as u32 - 1
        });
        let l = &mut layers[id as usize];
        l.visible |= !r.hidden;
        l.entities += 1;
        let mut e = r.entity;
        e.layer = id;
        entities.push(e);
    }
    for l in &mut layers {
        l.selected = match chosen {
            // As DXF layer names: case-insensitive.
            Some(list) => {
                let name = crate::case::lower(&l.name);
                list.iter().any(|n| crate::case::lower(n) == name)
            }
            None => l.visible,
        };
    }
    let mut off = BTreeMap::new();
    entities.retain(|e| {
        let keep = layers[e.layer as usize].selected;
        if !keep {
            *off.entry(e.layer).or_default() += 1;
        }
        keep
    });
    (layers, entities, off)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dxf::Place;

    fn raw(label: Option<&str>, color: u32, hidden: bool, layer_hidden: bool) -> Raw {
        Raw {
            entity: Entity {
                kind: "path",
                layer: 0,
                place: Place::Line(1),
                segments: vec![],
                closed: false,
                source: None,
                insert: None,
            },
            label: label.map(str::to_owned),
            color: Some(Paint::Color(color)),
            hidden,
            layer_hidden,
        }
    }

    #[test]
    fn inkscape_layers_colours_and_hidden_layers() {
        let (layers, ents, off) = assign(
            vec![
                raw(Some("Cut"), 0, false, false),
                raw(None, 0xff0000, false, false),
                raw(Some("Engrave"), 0x0000ff, false, false),
                raw(Some("Engrave"), 0xff0000, false, false),
                raw(Some("Guides"), 0, true, true),
                raw(Some("Cut"), 0, true, false),
            ],
            None,
        );
        let names: Vec<&str> = layers.iter().map(|l| l.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "Cut",
                "#ff0000",
                "Engrave #0000ff",
                "Engrave #ff0000",
                "Guides",
                "Cut (hidden)"
            ]
        );
        assert_eq!(layers[1].color, 1);
        assert!(!layers[4].visible && !layers[4].selected && !layers[5].selected);
        assert_eq!(ents.len(), 4);
        assert_eq!(off.values().sum::<usize>(), 2);
        // Chosen by name, case-insensitive: a hidden layer can be cut.
        let (_, ents, _) = assign(
            vec![raw(Some("Guides"), 0, true, true)],
            Some(&["guides".into()]),
        );
        assert_eq!(ents.len(), 1);
    }
}
