//! The reader's state: header variables, code page and units, the LAYER
//! table, block definitions, counts; and the final [`Drawing`].
//!
//! HEADER, TABLES and BLOCKS are kept as pairs (`pre`, borrowed slices of
//! the input, usually a small part of a file); the entities of the ENTITIES
//! section stream through [`super::walk`] one at a time and are never kept
//! as pairs. Block definitions are pair ranges of `pre`, walked again for
//! every INSERT.

use std::collections::{BTreeMap, HashMap};

use super::pairs::{Pair, Place};
use super::text::Decoder;
use super::{entities, Drawing, Layer, ReadOptions, MAX_SEGMENTS};
use crate::fx::FxMap;
use crate::geom::{BBox, Point};
use crate::text;
use crate::warning::Warning;

/// Entries of the recent type and layer lists.
const RECENT: usize = 4;

/// A block definition: its base point and the range of its entity pairs in `pre`.
#[derive(Clone)]
pub struct Block {
    pub base: Point,
    pub from: usize,
    pub to: usize,
}

pub struct Reader<'a, 'o> {
    pub binary: bool,
    pub options: &'o ReadOptions,
    pub decoder: Decoder,
    pub blocks: FxMap<&'a [u8], Block>,
    pub layer_ids: FxMap<&'a [u8], u32>,
    pub(super) layer_folded: HashMap<Vec<u8>, u32>,
    /// The raw names that made new layers, in the order they were made
    /// (a chunk's new layers are made again, in this order, when it is
    /// joined: [`super::chunks`]).
    pub(super) made_layers: Vec<&'a [u8]>,
    pub(super) header: HashMap<&'a [u8], usize>,
    pub scale: f64,
    pub budget: usize,
    /// The least budget left over by any entity's request (budget before
    /// it minus its segments): how much smaller a budget would have given
    /// the same reading ([`super::chunks`]).
    pub room: usize,
    pub paper_space: usize,
    pub tilted: usize,
    /// 3-D POLYLINEs not flat: how many, their lowest and highest Z, the first's place.
    pub not_flat: Option<(usize, f64, f64, Place)>,
    pub(super) counts: FxMap<&'a [u8], usize>,
    /// Entities of the last few types met not yet added to `counts`
    /// (files hold runs of one type, or repeat a few: LINEs and CIRCLEs of
    /// parts; a short list searched first saves a hash per entity).
    pub(super) count_runs: Vec<(&'a [u8], usize)>,
    /// The last few layer names looked up and their indices, most recent first.
    last_layers: Vec<(&'a [u8], u32)>,
    pub skipped: FxMap<&'a [u8], usize>,
    pub in_blocks_skipped: FxMap<&'a [u8], usize>,
    pub off_layers: BTreeMap<u32, usize>,
    /// The last map checked for being a similarity (by its bits) and the
    /// answer: every entity of a file is placed by the same few maps.
    pub similar: Option<([u64; 6], bool)>,
    /// The box of the segments of the entities kept so far (the drawing's
    /// extent once all are read).
    pub extent: BBox,
    /// The axis directions the extent's arc boxes use.
    pub axes: super::extent::Axes,
    /// The INSERT copy being walked (None in model space itself): what
    /// the entities read now are stamped with.
    pub insert: Option<u32>,
    pub d: Drawing,
}

#[cfg(test)]
thread_local! {
    /// The segment budget of readers made on this thread (tests make it small).
    pub(super) static TEST_BUDGET: std::cell::Cell<usize> = const { std::cell::Cell::new(MAX_SEGMENTS) };
}

/// [`MAX_SEGMENTS`] (in tests, what this thread's [`TEST_BUDGET`] says).
fn first_budget() -> usize {
    #[cfg(test)]
    return TEST_BUDGET.with(std::cell::Cell::get);
    #[cfg(not(test))]
    MAX_SEGMENTS
}

/// Index just past the pairs of the entity starting at `i` (its `0` pair).
pub fn entity_end(raw: &[Pair], i: usize, to: usize) -> usize {
    raw[i + 1..to]
        .iter()
        .position(|p| p.code == 0)
        .map_or(to, |k| i + 1 + k)
}

impl<'a, 'o> Reader<'a, 'o> {
    pub fn new(binary: bool, options: &'o ReadOptions) -> Self {
        Reader {
            binary,
            options,
            decoder: Decoder::Utf8,
            blocks: FxMap::default(),
            layer_ids: FxMap::default(),
            layer_folded: HashMap::new(),
            made_layers: Vec::new(),
            header: HashMap::new(),
            scale: 1.0,
            budget: first_budget(),
            room: usize::MAX,
            paper_space: 0,
            tilted: 0,
            not_flat: None,
            counts: FxMap::default(),
            count_runs: Vec::new(),
            last_layers: Vec::new(),
            skipped: FxMap::default(),
            in_blocks_skipped: FxMap::default(),
            off_layers: BTreeMap::new(),
            similar: None,
            extent: BBox::EMPTY,
            axes: super::extent::Axes::new(),
            insert: None,
            d: Drawing {
                binary,
                ..Drawing::default()
            },
        }
    }

    /// A reader for a chunk of the ENTITIES section, on another thread:
    /// the context read so far (code page, units, layers, blocks, budget),
    /// nothing counted or kept yet.
    pub fn fork(&self) -> Self {
        Reader {
            binary: self.binary,
            options: self.options,
            decoder: self.decoder,
            blocks: self.blocks.clone(),
            layer_ids: self.layer_ids.clone(),
            layer_folded: self.layer_folded.clone(),
            made_layers: Vec::new(),
            header: HashMap::new(),
            scale: self.scale,
            budget: self.budget,
            d: Drawing {
                binary: self.binary,
                // Counted from zero: the chunk's counts are added when joined.
                layers: (self.d.layers.iter())
                    .map(|l| Layer {
                        entities: 0,
                        ..l.clone()
                    })
                    .collect(),
                ..Drawing::default()
            },
            ..Reader::new(self.binary, self.options)
        }
    }

    pub fn place(&self, at: usize) -> Place {
        if self.binary {
            Place::Byte(at)
        } else {
            Place::Line(at)
        }
    }

    /// Everything the entities need, from the sections read so far (pair
    /// ranges of `pre`): code page, units, layers, blocks.
    pub fn prepare(
        &mut self,
        pre: &[Pair<'a>],
        tables: Option<(usize, usize)>,
        blocks: Option<(usize, usize)>,
    ) {
        self.set_decoder(pre);
        self.set_units(pre);
        if let Some((f, t)) = tables {
            self.read_layers(pre, f, t);
        }
        if let Some((f, t)) = blocks {
            self.read_blocks(pre, f, t);
        }
    }

    /// LAYER records of the TABLES section: name 2, colour 62 (negative = off), flags 70 (1 = frozen).
    fn read_layers(&mut self, pre: &[Pair<'a>], from: usize, to: usize) {
        let mut i = from;
        while i < to {
            if pre[i].code == 0 && pre[i].is("LAYER") {
                let end = entity_end(pre, i, to);
                let body = &pre[i + 1..end];
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
            Some(list) => {
                let name = crate::case::lower(name);
                list.iter().any(|n| crate::case::lower(n) == name)
            }
            None => visible,
        }
    }

    /// Counts one model-space entity of type `kind`.
    pub fn count(&mut self, kind: &'a [u8]) {
        if let Some(run) = self.count_runs.iter_mut().find(|(k, _)| *k == kind) {
            run.1 += 1;
            return;
        }
        if self.count_runs.len() == RECENT {
            let (k, n) = self.count_runs.remove(0);
            *self.counts.entry(k).or_default() += n;
        }
        self.count_runs.push((kind, 1));
    }

    /// The index of a layer, added on first use.
    pub fn layer_id(&mut self, raw_name: &'a [u8]) -> u32 {
        if let Some(&(_, id)) = self.last_layers.iter().find(|(n, _)| *n == raw_name) {
            return id;
        }
        let id = self.find_layer(raw_name);
        if self.last_layers.len() == RECENT {
            self.last_layers.pop();
        }
        self.last_layers.insert(0, (raw_name, id));
        id
    }

    fn find_layer(&mut self, raw_name: &'a [u8]) -> u32 {
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
        self.made_layers.push(raw_name);
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
    fn read_blocks(&mut self, pre: &[Pair<'a>], from: usize, to: usize) {
        let mut i = from;
        while i < to {
            let p = pre[i];
            if !(p.code == 0 && p.is("BLOCK")) {
                i += 1;
                continue;
            }
            let head_end = entity_end(pre, i, to);
            let head = &pre[i + 1..head_end];
            let name = head
                .iter()
                .find(|p| p.code == 2)
                .map(|p| p.trimmed())
                .unwrap_or(b"");
            let base = entities::point(head, 10).unwrap_or_default();
            let end = pre[head_end..to]
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

    pub fn finish(mut self) -> Drawing {
        for (k, n) in std::mem::take(&mut self.count_runs) {
            *self.counts.entry(k).or_default() += n;
        }
        let mut d = std::mem::take(&mut self.d);
        let named = |m: &FxMap<&[u8], usize>| -> BTreeMap<String, usize> {
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
            d.warnings.push(Warning::new(
                "too-many-segments",
                text!("the drawing expands to more than {MAX_SEGMENTS} segments: the rest was not read";
                      "o desenho se expande em mais de {MAX_SEGMENTS} segmentos: o restante não foi lido"),
            ));
        }
        if self.tilted > 0 {
            let n = self.tilted;
            let one = n == 1;
            d.warnings.push(Warning::new(
                "tilted-plane",
                text!("{n} entit{} drawn in a tilted plane (extrusion not along Z): projected onto XY",
                      if one { "y" } else { "ies" };
                      "{n} entidade{} desenhada{} em plano inclinado (extrusão fora do eixo Z): projetada{} em XY",
                      if one { "" } else { "s" }, if one { "" } else { "s" }, if one { "" } else { "s" }),
            ));
        }
        if let Some((n, lo, hi, first)) = self.not_flat {
            // One warning for them all (a mesh-like file holds hundreds).
            let at = super::place_text(first);
            let dec = crate::warning::dec;
            d.warnings.push(Warning::new(
                "polyline-not-flat",
                text!("{n} 3-D POLYLINE(s) not flat (Z {lo:.3} to {hi:.3}), the first at {}: projected onto XY", at.en;
                      "{n} POLYLINE(s) 3D não plana(s) (Z {:.3} a {:.3}), a primeira em {}: projetada(s) em XY",
                      dec(lo), dec(hi), at.pt),
            ));
        }
        if self.paper_space > 0 {
            let n = self.paper_space;
            let one = n == 1;
            d.warnings.push(Warning::new(
                "paper-space",
                text!("{n} paper-space entit{} ignored (only model space is cut)",
                      if one { "y" } else { "ies" };
                      "{n} entidade{} do espaço do papel ignorada{} (só o espaço do modelo é cortado)",
                      if one { "" } else { "s" }, if one { "" } else { "s" }),
            ));
        }
        let other: Vec<String> = d.skipped.iter().map(|(k, n)| format!("{k} ×{n}")).collect();
        if !other.is_empty() {
            let list = other.join(", ");
            d.warnings.push(Warning::new(
                "entities-not-cut",
                text!("entities not cut: {list}"; "entidades não cortadas: {list}"),
            ));
        }
        let in_blocks: Vec<String> = in_blocks_skipped
            .iter()
            .map(|(k, n)| format!("{k} ×{n}"))
            .collect();
        if !in_blocks.is_empty() {
            let list = in_blocks.join(", ");
            d.warnings.push(Warning::new(
                "block-entities-not-cut",
                text!("inside blocks, entities not cut: {list}";
                      "dentro de blocos, entidades não cortadas: {list}"),
            ));
        }
        if !self.off_layers.is_empty() {
            let list: Vec<String> = self
                .off_layers
                .iter()
                .map(|(&l, n)| format!("'{}' ×{n}", d.layers[l as usize].name))
                .collect();
            let list = list.join(", ");
            d.warnings.push(Warning::new(
                "layers-not-selected",
                text!("entities on layers not selected for cutting: {list}";
                      "entidades em camadas não selecionadas para corte: {list}"),
            ));
        }
        if d.entities.is_empty() {
            d.warnings.push(Warning::new(
                "no-geometry",
                text!("no cuttable geometry in model space";
                      "nenhuma geometria cortável no espaço do modelo"),
            ));
        }
        d.extent = self.extent;
        d
    }
}
