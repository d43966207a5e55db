//! Entities placed in the drawing: segments mapped to mm and checked, an
//! entity or POINT added (with its source), and INSERTs walked through
//! their block definitions, nested and in arrays (DXF reference, INSERT;
//! "Object Coordinate Systems").

use super::pairs::{Pair, Place};
use super::reader::Reader;
use super::{entities, place_text, Entity, InsertCopy, Spot};
use super::{MAX_ARRAY_COPIES, MAX_BLOCK_DEPTH, MAX_COORD_MM, MAX_SEGMENTS};
use crate::geom::{transform_segments, Affine, Point, Segment};
use crate::text;
use crate::warning::{Text, Warning};

impl<'a, 'o> Reader<'a, 'o> {
    /// Maps drawing-unit segments to mm and checks their range.
    pub(super) fn place_segments(
        &mut self,
        segs: Vec<Segment>,
        m: &Affine,
    ) -> Result<Vec<Segment>, Text> {
        if segs.len() > self.budget {
            // Stop expanding altogether: `finish` says so once.
            self.budget = 0;
            return Err(
                text!("the drawing expands to more than {MAX_SEGMENTS} segments";
                             "o desenho se expande em mais de {MAX_SEGMENTS} segmentos"),
            );
        }
        self.room = self.room.min(self.budget - segs.len());
        let key = [m.a, m.b, m.c, m.d, m.e, m.f].map(f64::to_bits);
        let similar = match self.similar {
            Some((k, v)) if k == key => v,
            _ => {
                let v = m.is_similarity(1e-9);
                self.similar = Some((key, v));
                v
            }
        };
        let out = if similar {
            // What `transform_segments` does for a similarity (each segment
            // to one, bulge kept or flipped), done in place: no second
            // vector per entity.
            let mut segs = segs;
            let flip = m.det() < 0.0;
            for s in &mut segs {
                s.a = m.apply(s.a);
                s.b = m.apply(s.b);
                if flip {
                    s.bulge = -s.bulge;
                }
            }
            segs
        } else {
            let mut out = Vec::with_capacity(segs.len());
            transform_segments(&segs, m, self.options.chord, &mut out);
            out
        };
        let ok = out.iter().all(|s| {
            s.is_finite()
                && [s.a.x, s.a.y, s.b.x, s.b.y]
                    .iter()
                    .all(|v| v.abs() <= MAX_COORD_MM)
        });
        if !ok {
            return Err(
                text!("a coordinate is out of range (beyond {MAX_COORD_MM} mm)";
                             "uma coordenada está fora da faixa (além de {MAX_COORD_MM} mm)"),
            );
        }
        self.budget = self.budget.saturating_sub(out.len());
        Ok(out)
    }

    pub(super) fn add_entity(&mut self, e: Entity) {
        let l = &mut self.d.layers[e.layer as usize];
        l.entities += 1;
        if l.selected {
            // The extent grown here, while the segments are in cache: a
            // pass over the finished drawing read every entity and its
            // segments back from memory (~8 % of reading a nest; issue 17).
            // The same unions in the same order as over the entities.
            for s in &e.segments {
                self.extent
                    .union(&super::extent::segment_bbox(s, &self.axes));
            }
            self.d.entities.push(e);
        } else {
            *self.off_layers.entry(e.layer).or_default() += 1;
        }
    }

    pub(super) fn add_spot(&mut self, at: Point, layer: u32) {
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
    pub(super) fn insert(
        &mut self,
        pre: &[Pair<'a>],
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
        let shown = || self.decoder.decode(name);
        let Some(block) = self.blocks.get(name).map(|b| (b.base, b.from, b.to)) else {
            let (p, b) = (place_text(place), shown());
            self.d.warnings.push(Warning::new(
                "block-undefined",
                text!("INSERT at {}: block '{b}' is not defined", p.en;
                      "INSERT em {}: bloco '{b}' não está definido", p.pt),
            ));
            return;
        };
        if stack.contains(&name) || stack.len() >= MAX_BLOCK_DEPTH {
            let (p, b) = (place_text(place), shown());
            self.d.warnings.push(Warning::new(
                "block-recursive",
                text!("INSERT at {}: block '{b}' inserts itself or nests deeper than {MAX_BLOCK_DEPTH}: not expanded", p.en;
                      "INSERT em {}: bloco '{b}' insere a si mesmo ou aninha mais de {MAX_BLOCK_DEPTH} níveis: não expandido", p.pt),
            ));
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
            let (p, b) = (place_text(place), shown());
            self.d.warnings.push(Warning::new(
                "array-too-big",
                text!("INSERT at {} of '{b}' asks for {cols} × {rows} copies: only the first {MAX_ARRAY_COPIES} are made", p.en;
                      "INSERT em {} de '{b}' pede {cols} × {rows} cópias: só as primeiras {MAX_ARRAY_COPIES} são feitas", p.pt),
            ));
            rows = (MAX_ARRAY_COPIES / cols).max(1);
        }
        let cols = cols.min(MAX_ARRAY_COPIES);
        let (dx, dy) = (num(44, 0.0), num(45, 0.0));
        if sx == 0.0 || sy == 0.0 {
            let (p, b) = (place_text(place), shown());
            self.d.warnings.push(Warning::new(
                "insert-zero-scale",
                text!("INSERT at {} of '{b}' has a zero scale: skipped", p.en;
                      "INSERT em {} de '{b}' tem escala zero: ignorado", p.pt),
            ));
            return;
        }
        let (base, from, to) = block;
        let block_name: std::sync::Arc<str> = shown().into();
        let outer = self.insert;
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
                    // Each copy its own: two copies of one block are two parts.
                    self.insert = u32::try_from(self.d.inserts.len()).ok();
                    self.d.inserts.push(InsertCopy {
                        block: block_name.clone(),
                        parent: outer,
                    });
                    self.walk(pre, from, to, &mm, Some(layer), false, stack);
                }
            }
        }
        self.insert = outer;
        stack.pop();
    }
}

#[cfg(test)]
#[path = "insert_tests.rs"]
mod tests;
