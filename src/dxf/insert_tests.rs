//! Tests of INSERTs: blocks nested, rotated, mirrored, in arrays, after
//! the entities, inserting themselves or missing.

use crate::dxf::tests::{read, HEADER_MM};
use crate::geom::Point;

/// A block "SQ": a 10 × 10 square as 4 lines plus a half-circle arc bump, base (5, 5).
const BLOCKS: &str = "0\nSECTION\n2\nBLOCKS\n\
0\nBLOCK\n2\nSQ\n70\n0\n10\n5\n20\n5\n\
0\nLINE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n\
0\nLINE\n8\n0\n10\n10\n20\n0\n11\n10\n21\n10\n\
0\nLINE\n8\n0\n10\n10\n20\n10\n11\n0\n21\n10\n\
0\nLINE\n8\n0\n10\n0\n20\n10\n11\n0\n21\n0\n\
0\nARC\n8\nMARK\n10\n5\n20\n5\n40\n2\n50\n0\n51\n90\n\
0\nENDBLK\n\
0\nBLOCK\n2\nTWO\n10\n0\n20\n0\n\
0\nINSERT\n2\nSQ\n10\n0\n20\n0\n\
0\nINSERT\n2\nSQ\n10\n20\n20\n0\n\
0\nENDBLK\n\
0\nENDSEC\n";

#[test]
fn nested_rotated_mirrored_inserts_place_block_geometry() {
    let d = read(&format!(
        "{HEADER_MM}{BLOCKS}0\nSECTION\n2\nENTITIES\n\
0\nINSERT\n8\nParts\n2\nTWO\n10\n100\n20\n0\n50\n90\n\
0\nINSERT\n8\nParts\n2\nSQ\n10\n0\n20\n0\n41\n-2\n42\n2\n\
0\nENDSEC\n0\nEOF"
    ));
    assert_eq!(d.counts["INSERT"], 2);
    assert!(d.skipped.is_empty(), "{:?}", d.skipped);
    // TWO holds 2 × SQ (5 entities each); the mirrored SQ adds 5.
    assert_eq!(d.entities.len(), 15);
    // Entities on layer 0 inside a block take the INSERT's layer.
    let parts = d.layers.iter().position(|l| l.name == "Parts").unwrap() as u32;
    assert_eq!(d.entities.iter().filter(|e| e.layer == parts).count(), 12);
    // TWO rotated 90° at (100, 0): SQ's corner (0,0) - base (5,5) = (-5,-5) → rotated (5,-5) → (105, -5).
    let first = &d.entities[0].segments[0];
    assert!(
        first.a.dist(Point::new(105.0, -5.0)) < 1e-9,
        "{:?}",
        first.a
    );
    // The mirrored copy: arc centre (5,5) - base → (0,0) → scaled (-2, 2)·(0,0) = (0,0); radius 4, turning clockwise.
    let arc = d.entities.iter().rev().find(|e| e.kind == "ARC").unwrap();
    let (c, r) = arc.segments[0].arc_center().unwrap();
    assert!(c.dist(Point::new(0.0, 0.0)) < 1e-9 && (r - 4.0).abs() < 1e-9);
    assert!(!arc.segments[0].is_ccw());
}

#[test]
fn self_inserting_blocks_and_missing_blocks_are_reported() {
    let d = read("0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nLOOP\n10\n0\n20\n0\n0\nINSERT\n2\nLOOP\n10\n1\n20\n0\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDBLK\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nINSERT\n2\nLOOP\n0\nINSERT\n2\nNOPE\n0\nENDSEC");
    assert_eq!(d.entities.len(), 1);
    assert!(d
        .warnings
        .iter()
        .any(|w| w.message().contains("inserts itself")));
    assert!(d
        .warnings
        .iter()
        .any(|w| w.message().contains("'NOPE' is not defined")));
}

#[test]
fn insert_arrays_repeat_the_block() {
    let d = read(&format!("{HEADER_MM}{BLOCKS}0\nSECTION\n2\nENTITIES\n0\nINSERT\n2\nSQ\n10\n0\n20\n0\n70\n3\n71\n2\n44\n15\n45\n15\n0\nENDSEC"));
    assert_eq!(d.entities.len(), 30);
}

#[test]
fn attributes_after_an_insert_are_not_counted_as_entities() {
    let d = read(&format!("{HEADER_MM}{BLOCKS}0\nSECTION\n2\nENTITIES\n0\nINSERT\n66\n1\n2\nSQ\n10\n0\n20\n0\n0\nATTRIB\n1\nx\n0\nSEQEND\n0\nENDSEC"));
    assert_eq!(d.counts.len(), 1, "{:?}", d.counts);
}

#[test]
fn blocks_after_the_entities_are_still_expanded() {
    // The streaming pass meets the INSERT before its block: the file is read again, keeping every pair.
    let d = read(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n\
         0\nSECTION\n2\nENTITIES\n0\nINSERT\n2\nB\n10\n5\n20\n0\n0\nENDSEC\n\
         0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nB\n10\n0\n20\n0\n\
         0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDBLK\n0\nENDSEC\n0\nEOF",
    );
    assert_eq!(d.entities.len(), 1);
    assert_eq!(
        d.entities[0].segments[0].a,
        crate::geom::Point::new(5.0, 0.0)
    );
}
