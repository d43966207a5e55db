//! What the drawing names a part (issue 42 §1: a part's name is the
//! file's "plus the block or layer name where the drawing gives one").
//!
//! **Blocks.** Shops' and pattern makers' DXFs often hold each part as a
//! block inserted once (ASTM/AAMA pattern files: a block per piece and
//! size); the name of that block is the part's name in the office. A part
//! is named after the INSERT copy that drew its whole outline, when that
//! copy drew no other part's outline: a block wrapping the whole drawing,
//! or a sheet of several parts, names none of them. An anonymous block
//! (`*U12`, `*X3`: dynamic blocks, hatches, dimensions; DXF reference,
//! BLOCK group 70) gives the name of the named copy it sits in, under the
//! same rule. An SVG's named groups and Inkscape layers are its copies
//! (the SVG reader keeps them in [`Drawing::inserts`]).
//!
//! **Groups.** A part's group is the named layer its whole outline is on
//! (DXF; layer `0` is AutoCAD's unnamed default, a number alone a layer's
//! function in pattern files) or, in an SVG, the
//! innermost named group holding it whole (an SVG's layers are mostly the
//! colours the reader names them by, not the drawing's names). Parts that
//! share a group are told apart by their number
//! ([`crate::nest::parts_from_contours`]).

use std::sync::Arc;

use super::{Contour, ContourKind};
use crate::dxf::{Drawing, InsertCopy};

/// Sets [`Contour::block`] and [`Contour::group`] on the outer contours of
/// `contours`, which were chained from `drawing`'s entities.
pub(super) fn name_parts(contours: &mut [Contour], drawing: &Drawing) {
    if !drawing.svg {
        name_by_layer(contours, drawing);
    }
    let inserts = &drawing.inserts;
    if inserts.is_empty() {
        return;
    }
    // The copy that drew each outline whole, if any.
    let drew: Vec<Option<u32>> = contours
        .iter()
        .map(|c| {
            if c.kind != ContourKind::Outer {
                return None;
            }
            let mut ids = c
                .entities
                .iter()
                .map(|&e| drawing.entities.get(e).and_then(|e| e.insert));
            let first = ids.next()??;
            ids.try_fold(first, |a, b| common(inserts, a, b?))
        })
        .collect();
    // How many outlines each copy drew, nested copies counted in theirs.
    let mut outlines = vec![0u32; inserts.len()];
    for &d in drew.iter().flatten() {
        let mut at = Some(d);
        while let Some(i) = at {
            let Some(slot) = outlines.get_mut(i as usize) else {
                break;
            };
            *slot += 1;
            at = inserts[i as usize].parent;
        }
    }
    let named = |i: u32| -> Option<&Arc<str>> {
        let copy = inserts.get(i as usize)?;
        (!copy.block.starts_with('*') && !copy.block.trim().is_empty()).then_some(&copy.block)
    };
    for (c, d) in contours.iter_mut().zip(drew) {
        let mut at = d;
        while let Some(i) = at.filter(|&i| outlines.get(i as usize) == Some(&1)) {
            if let Some(name) = named(i) {
                c.block = Some(Arc::clone(name));
                break;
            }
            at = inserts[i as usize].parent;
        }
        if drawing.svg {
            let mut at = d;
            while let Some(i) = at {
                if let Some(name) = named(i) {
                    c.group = Some(Arc::clone(name));
                    break;
                }
                at = inserts.get(i as usize).and_then(|c| c.parent);
            }
        }
    }
}

/// A DXF outline's group: the layer all its entities are on, when that
/// layer has a name: not `0`, nor a number alone (ASTM/AAMA pattern files
/// number their layers by function, 1 the boundary, 8 drill holes, 84…;
/// old CAD files number theirs), which names no part.
fn name_by_layer(contours: &mut [Contour], drawing: &Drawing) {
    for c in contours.iter_mut().filter(|c| c.kind == ContourKind::Outer) {
        let mut layers = c.entities.iter().map(|&e| drawing.entities.get(e).map(|e| e.layer));
        let Some(Some(first)) = layers.next() else {
            continue;
        };
        if !layers.all(|l| l == Some(first)) {
            continue;
        }
        let Some(layer) = drawing.layers.get(first as usize) else {
            continue;
        };
        if layer.name.chars().any(char::is_alphabetic) && *c.layer == *layer.name {
            c.group = Some(Arc::clone(&c.layer));
        }
    }
}

/// The deepest copy that is `a` or holds it and is `b` or holds it.
fn common(inserts: &[InsertCopy], a: u32, b: u32) -> Option<u32> {
    if a == b {
        return Some(a);
    }
    let chain = |mut i: u32| {
        let mut v = vec![i];
        while let Some(p) = inserts.get(i as usize).and_then(|c| c.parent) {
            v.push(p);
            i = p;
        }
        v
    };
    let b_chain = chain(b);
    chain(a).into_iter().find(|i| b_chain.contains(i))
}

#[cfg(test)]
mod tests {
    use crate::contour::{extract, ContourKind};
    use crate::geom::Tolerance;

    fn square(x: f64, y: f64, s: f64) -> String {
        format!(
            "0\nLWPOLYLINE\n8\n0\n90\n4\n70\n1\n10\n{x}\n20\n{y}\n10\n{}\n20\n{y}\n10\n{}\n20\n{}\n10\n{x}\n20\n{}\n",
            x + s,
            x + s,
            y + s,
            y + s
        )
    }
    fn line(a: (f64, f64), b: (f64, f64)) -> String {
        format!("0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n", a.0, a.1, b.0, b.1)
    }
    fn block(name: &str, body: &str) -> String {
        format!("0\nBLOCK\n8\n0\n2\n{name}\n70\n0\n10\n0\n20\n0\n{body}0\nENDBLK\n")
    }
    fn insert(name: &str, x: f64, y: f64) -> String {
        format!("0\nINSERT\n8\n0\n2\n{name}\n10\n{x}\n20\n{y}\n")
    }
    /// The block names of the outer outlines, by their box's lower-left x.
    fn names(blocks: &str, entities: &str) -> Vec<(i64, Option<String>)> {
        let dxf = format!(
            "0\nSECTION\n2\nBLOCKS\n{blocks}0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{entities}0\nENDSEC\n0\nEOF\n"
        );
        let d = crate::dxf::parse(dxf.as_bytes(), &crate::dxf::ReadOptions::DEFAULT).unwrap();
        let c = extract(&d, Tolerance::DEFAULT, 0.0);
        let mut v: Vec<_> = (c.contours.iter())
            .filter(|c| c.kind == ContourKind::Outer)
            .map(|c| (c.bbox.min.x.round() as i64, c.block.as_deref().map(str::to_owned)))
            .collect();
        v.sort();
        v
    }

    #[test]
    fn a_part_inserted_as_a_block_carries_its_name_and_each_insert_is_a_part() {
        // FLANGE (a square with a hole) inserted twice, a plate drawn in
        // model space, a bracket drawn as four LINEs in a block.
        let blocks = [
            block("FLANGE", &(square(0.0, 0.0, 50.0) + &square(20.0, 20.0, 10.0))),
            block(
                "Bracket 2",
                &[
                    line((0.0, 0.0), (40.0, 0.0)),
                    line((40.0, 0.0), (40.0, 30.0)),
                    line((40.0, 30.0), (0.0, 30.0)),
                    line((0.0, 30.0), (0.0, 0.0)),
                ]
                .concat(),
            ),
        ]
        .concat();
        let ents = [
            insert("FLANGE", 0.0, 0.0),
            insert("FLANGE", 100.0, 0.0),
            square(200.0, 0.0, 40.0),
            insert("Bracket 2", 300.0, 0.0),
        ]
        .concat();
        let s = |n: &str| Some(n.to_owned());
        assert_eq!(
            names(&blocks, &ents),
            [(0, s("FLANGE")), (100, s("FLANGE")), (200, None), (300, s("Bracket 2"))]
        );
    }

    #[test]
    fn a_block_of_several_parts_names_none_and_an_anonymous_block_gives_its_holders_name() {
        // SHEET holds two squares and an insert of KEY, whose outline is in
        // an anonymous block *U3; a LINE outline half in a block, half not.
        let blocks = [
            block("*U3", &square(0.0, 0.0, 20.0)),
            block("KEY", &insert("*U3", 0.0, 0.0)),
            block(
                "SHEET",
                &[square(0.0, 0.0, 30.0), square(50.0, 0.0, 30.0), insert("KEY", 100.0, 0.0)].concat(),
            ),
            block("HALF", &[line((0.0, 0.0), (40.0, 0.0)), line((40.0, 0.0), (40.0, 30.0))].concat()),
        ]
        .concat();
        let ents = [
            insert("SHEET", 0.0, 0.0),
            insert("HALF", 300.0, 0.0),
            line((340.0, 30.0), (300.0, 30.0)),
            line((300.0, 30.0), (300.0, 0.0)),
        ]
        .concat();
        let s = |n: &str| Some(n.to_owned());
        assert_eq!(names(&blocks, &ents), [(0, None), (50, None), (100, s("KEY")), (300, None)]);
    }

    #[test]
    fn an_outline_wholly_on_a_named_layer_is_in_that_layers_group() {
        let on = |layer: &str, e: String| e.replace("8\n0\n", &format!("8\n{layer}\n"));
        let ents = [
            on("FLANGE", square(0.0, 0.0, 50.0)),
            on("84", square(100.0, 0.0, 40.0)),
            on("KEY", line((200.0, 0.0), (240.0, 0.0))),
            on("KEY", line((240.0, 0.0), (240.0, 30.0))),
            on("KEY", line((240.0, 30.0), (200.0, 0.0))),
            // An outline drawn on two layers is in neither.
            on("A", line((300.0, 0.0), (340.0, 0.0))),
            on("B", line((340.0, 0.0), (340.0, 30.0))),
            on("B", line((340.0, 30.0), (300.0, 0.0))),
        ]
        .concat();
        let dxf = format!("0\nSECTION\n2\nENTITIES\n{ents}0\nENDSEC\n0\nEOF\n");
        let d = crate::dxf::parse(dxf.as_bytes(), &crate::dxf::ReadOptions::DEFAULT).unwrap();
        let c = extract(&d, Tolerance::DEFAULT, 0.0);
        let mut v: Vec<_> = (c.contours.iter())
            .filter(|c| c.kind == ContourKind::Outer)
            .map(|c| (c.bbox.min.x.round() as i64, c.group.as_deref().map(str::to_owned)))
            .collect();
        v.sort();
        let s = |n: &str| Some(n.to_owned());
        assert_eq!(v, [(0, s("FLANGE")), (100, None), (200, s("KEY")), (300, None)]);
    }
}
