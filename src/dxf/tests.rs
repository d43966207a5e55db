//! Reader tests built from group-code pairs (as dxf-rs tests its reader).

use super::*;
use crate::geom::loop_area;

pub(super) fn dxf(body: &str) -> Vec<u8> {
    body.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("\n")
        .into_bytes()
}

pub(super) fn read(src: &str) -> Drawing {
    parse(&dxf(src), &ReadOptions::DEFAULT).unwrap()
}

pub(super) const HEADER_MM: &str = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n";

#[test]
fn reads_a_line_in_inches_as_mm() {
    let d = read("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n1\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nCut\n10\n0\n20\n0\n11\n1\n21\n2\n0\nENDSEC\n0\nEOF");
    assert_eq!(d.units.unwrap().name, "in");
    assert_eq!(d.units_source, "$INSUNITS");
    assert_eq!(d.entities.len(), 1);
    assert_eq!(d.layers[d.entities[0].layer as usize].name, "Cut");
    assert_eq!(d.entities[0].segments[0].b, Point::new(25.4, 50.8));
}

#[test]
fn unstated_units_are_assumed_by_evidence_and_always_warned() {
    let line = |header: &str, to: f64| {
        read(&format!("{header}0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n{to}\n21\n1\n0\nENDSEC\n0\nEOF"))
    };
    let assumed = |d: &Drawing| {
        let w: Vec<&Warning> = d
            .warnings
            .iter()
            .filter(|w| w.code == "units-assumed")
            .collect();
        assert_eq!(w.len(), 1, "{:?}", d.warnings);
        w[0].text.en.clone()
    };
    let meas0 = "0\nSECTION\n2\nHEADER\n9\n$MEASUREMENT\n70\n0\n0\nENDSEC\n";
    // A 2 × 1 drawing with $MEASUREMENT 0: inches (a 2 mm part is no cutting job).
    let d = line(meas0, 2.0);
    assert_eq!((d.units.unwrap().name, d.units_source), ("in", "assumed"));
    assert_eq!(d.entities[0].segments[0].b, Point::new(50.8, 25.4));
    assert!(
        assumed(&d).contains("read as inches: 50.8 × 25.4 mm"),
        "{}",
        assumed(&d)
    );
    // 134 wide with $MEASUREMENT 0 (KiCad): mm, and the warning gives both sizes.
    let d = line(meas0, 134.0);
    assert_eq!((d.units.unwrap().name, d.units_source), ("mm", "assumed"));
    assert!(
        assumed(&d).contains("3.40 m × 0.03 m") || assumed(&d).contains("3.40 × 0.03 m"),
        "{}",
        assumed(&d)
    );
    // No header at all: mm, warned.
    let d = line("", 10.0);
    assert_eq!((d.units.unwrap().name, d.units_source), ("mm", "assumed"));
    assumed(&d);
    // $MEASUREMENT 1 keeps even a tiny drawing in mm.
    let d = line(
        "0\nSECTION\n2\nHEADER\n9\n$MEASUREMENT\n70\n1\n0\nENDSEC\n",
        2.0,
    );
    assert_eq!(d.units.unwrap().name, "mm");
    assert!(assumed(&d).contains("$MEASUREMENT = 1"));
    // $INSUNITS 0 (unitless) is no statement either.
    let d = line(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n0\n0\nENDSEC\n",
        2.0,
    );
    assert_eq!((d.units.unwrap().name, d.units_source), ("in", "assumed"));
    // $INSUNITS 1 is the truth, tiny or not, without a word.
    let d = line(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n1\n9\n$MEASUREMENT\n70\n0\n0\nENDSEC\n",
        2.0,
    );
    assert_eq!((d.units.unwrap().name, d.units_source), ("in", "$INSUNITS"));
    assert!(d.warnings.is_empty(), "{:?}", d.warnings);
    // $INSUNITS 4 with $MEASUREMENT 0 is common and says nothing.
    let d = line(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n9\n$MEASUREMENT\n70\n0\n0\nENDSEC\n",
        200.0,
    );
    assert!(d.warnings.is_empty(), "{:?}", d.warnings);
    // The user's unit wins, without a warning.
    let opts = ReadOptions {
        units: Units::from_name("cm"),
        ..ReadOptions::DEFAULT
    };
    let d = parse(
        &dxf("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n10\n21\n0\n0\nENDSEC\n0\nEOF"),
        &opts,
    )
    .unwrap();
    assert_eq!(d.entities[0].segments[0].b, Point::new(100.0, 0.0));
    assert_eq!(d.units_source, "override");
    assert!(d.warnings.is_empty(), "{:?}", d.warnings);
}

#[test]
fn a_file_without_eof_is_flagged_truncated_with_where_it_ends() {
    let body = format!("{HEADER_MM}0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n100\n21\n0\n0\nLINE\n10\n0\n20\n0\n11\n0\n21\n100\n");
    let d = read(&body);
    assert_eq!(d.entities.len(), 2);
    let w: Vec<&Warning> = d
        .warnings
        .iter()
        .filter(|w| w.code == "file-truncated")
        .collect();
    assert_eq!(w.len(), 1, "{:?}", d.warnings);
    assert!(w[0].text.en.contains("no EOF marker"), "{}", w[0].text.en);
    assert!(w[0].text.en.contains("line 34"), "{}", w[0].text.en);
    // The same file whole: no warning.
    let d = read(&format!("{body}0\nENDSEC\n0\nEOF\n"));
    assert!(d.warnings.is_empty(), "{:?}", d.warnings);
}

#[test]
fn unknown_entities_are_counted_and_skipped() {
    let d = read(&format!("{HEADER_MM}0\nSECTION\n2\nENTITIES\n0\nTEXT\n1\nhello\n0\nTEXT\n1\nx\n0\nCIRCLE\n10\n0\n20\n0\n40\n5\n0\nENDSEC\n0\nEOF"));
    assert_eq!(d.counts["TEXT"], 2);
    assert_eq!(d.skipped["TEXT"], 2);
    assert_eq!(d.counts["CIRCLE"], 1);
    assert!(d.warnings.iter().any(|w| w.message().contains("TEXT ×2")));
}

#[test]
fn polyline_with_vertices_and_seqend() {
    let d = read(&format!("{HEADER_MM}0\nSECTION\n2\nENTITIES\n0\nPOLYLINE\n66\n1\n70\n1\n0\nVERTEX\n10\n0\n20\n0\n0\nVERTEX\n10\n10\n20\n0\n0\nVERTEX\n10\n10\n20\n10\n0\nSEQEND\n0\nLINE\n10\n0\n20\n0\n11\n5\n21\n5\n0\nENDSEC\n0\nEOF"));
    assert_eq!(d.entities.len(), 2);
    assert!(d.entities[0].closed);
    assert_eq!(d.entities[0].segments.len(), 3);
    assert_eq!(d.counts.get("VERTEX"), None);
}

#[test]
fn garbage_is_not_a_dxf() {
    assert!(matches!(
        parse(b"\x89PNG\r\n\x1a\n", &ReadOptions::DEFAULT),
        Err(DxfError::NotDxf(_))
    ));
    assert!(matches!(
        parse(b"  \n", &ReadOptions::DEFAULT),
        Err(DxfError::Empty)
    ));
}

#[test]
fn a_broken_tail_keeps_what_was_read_and_warns() {
    let d = read("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\nGARBAGE\n0");
    assert_eq!(d.entities.len(), 1);
    assert!(
        d.warnings.iter().any(|w| w.message().contains("line 15")),
        "{:?}",
        d.warnings
    );
}

#[test]
fn paper_space_entities_are_skipped_and_said_so() {
    let d = read("0\nSECTION\n2\nENTITIES\n0\nLINE\n67\n1\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC");
    assert!(d.entities.is_empty());
    assert!(d.counts.is_empty() && d.skipped.is_empty());
    assert!(d
        .warnings
        .iter()
        .any(|w| w.message().contains("1 paper-space entity ignored")));
}

#[test]
fn hidden_and_unselected_layers_are_not_cut_and_reported() {
    let src = format!("{HEADER_MM}0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n0\nLAYER\n2\nCUT\n62\n1\n70\n0\n0\nLAYER\n2\nHIDDEN\n62\n-3\n70\n0\n0\nENDTAB\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\nCUT\n10\n0\n20\n0\n40\n5\n0\nCIRCLE\n8\nHIDDEN\n10\n0\n20\n0\n40\n9\n0\nENDSEC");
    let d = read(&src);
    assert_eq!(d.entities.len(), 1);
    assert_eq!(d.layers.len(), 2);
    assert!(!d.layers[1].visible && !d.layers[1].selected && d.layers[1].entities == 1);
    assert!(d
        .warnings
        .iter()
        .any(|w| w.message().contains("'HIDDEN' ×1")));
    let opts = ReadOptions {
        layers: Some(vec!["HIDDEN".into()]),
        ..ReadOptions::DEFAULT
    };
    let d = parse(&dxf(&src), &opts).unwrap();
    assert_eq!(d.entities.len(), 1);
    assert_eq!(d.layers[d.entities[0].layer as usize].name, "HIDDEN");
}

#[test]
fn layer_names_are_decoded_with_the_code_page() {
    let mut src = dxf("0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$DWGCODEPAGE\n3\nANSI_1250\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nXX\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC");
    let at = src.windows(2).position(|w| w == b"XX").unwrap();
    src.splice(at..at + 2, [0xea, 0x9c, 0xe6]);
    let d = parse(&src, &ReadOptions::DEFAULT).unwrap();
    assert_eq!(d.layers[0].name, "ęść");
}

#[test]
fn points_are_kept_as_spots() {
    let d = read(&format!(
        "{HEADER_MM}0\nSECTION\n2\nENTITIES\n0\nPOINT\n10\n3\n20\n4\n0\nENDSEC"
    ));
    assert_eq!(d.spots.len(), 1);
    assert_eq!(d.spots[0].at, Point::new(3.0, 4.0));
    assert!(d.skipped.is_empty());
}

#[test]
fn spline_and_ellipse_become_lines_within_the_chord() {
    let d = read(&format!(
        "{HEADER_MM}0\nSECTION\n2\nENTITIES\n\
0\nELLIPSE\n10\n0\n20\n0\n11\n10\n21\n0\n40\n0.5\n41\n0\n42\n6.283185307179586\n\
0\nSPLINE\n70\n8\n71\n1\n72\n4\n73\n2\n40\n0\n40\n0\n40\n1\n40\n1\n10\n0\n20\n0\n10\n3\n20\n4\n\
0\nENDSEC"
    ));
    assert_eq!(d.entities.len(), 2);
    let e = &d.entities[0];
    assert!(e.closed);
    assert!((loop_area(&e.segments) - std::f64::consts::PI * 50.0).abs() < 0.01 * 31.0);
    let s = &d.entities[1];
    let len: f64 = s.segments.iter().map(Segment::length).sum();
    assert!((len - 5.0).abs() < 1e-9);
}

#[test]
fn negative_extrusion_arc_in_a_file_is_mirrored() {
    let d = read(&format!("{HEADER_MM}0\nSECTION\n2\nENTITIES\n0\nARC\n10\n10\n20\n0\n40\n5\n50\n0\n51\n90\n210\n0\n220\n0\n230\n-1\n0\nENDSEC"));
    let s = &d.entities[0].segments[0];
    assert!(s.a.dist(Point::new(-15.0, 0.0)) < 1e-12 && !s.is_ccw());
}

#[test]
fn binary_dxf_reads_like_ascii() {
    let mut v = binary::SENTINEL.to_vec();
    let mut push = |code: i16, val: &[u8]| {
        v.extend_from_slice(&code.to_le_bytes());
        v.extend_from_slice(val);
    };
    push(0, b"SECTION\0");
    push(2, b"ENTITIES\0");
    push(0, b"LINE\0");
    push(8, b"L1\0");
    for (c, x) in [(10, 1.0f64), (20, 2.0), (11, 4.0), (21, 6.0)] {
        push(c, &x.to_le_bytes());
    }
    push(0, b"ENDSEC\0");
    push(0, b"EOF\0");
    // A 3 × 4 drawing without units would be assumed inches: say mm.
    let mm = ReadOptions {
        units: Some(Units::MM),
        ..ReadOptions::DEFAULT
    };
    let d = parse(&v, &mm).unwrap();
    assert!(d.binary);
    assert_eq!(d.entities.len(), 1);
    assert_eq!(d.entities[0].segments[0].b, Point::new(4.0, 6.0));
    assert_eq!(d.entities[0].segments[0].length(), 5.0);
}

#[test]
fn layer_names_differing_only_in_case_are_one_layer() {
    let d = read("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nCut\n10\n0\n20\n0\n11\n1\n21\n0\n0\nLINE\n8\nCUT\n10\n1\n20\n0\n11\n2\n21\n0\n0\nENDSEC");
    assert_eq!(d.layers.len(), 1);
    assert_eq!(
        (d.layers[0].name.as_str(), d.layers[0].entities),
        ("Cut", 2)
    );
    let opts = ReadOptions {
        layers: Some(vec!["cut".into()]),
        ..ReadOptions::DEFAULT
    };
    let src =
        dxf("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nCut\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC");
    assert_eq!(parse(&src, &opts).unwrap().entities.len(), 1);
}

#[test]
fn bare_entities_without_sections_are_read() {
    let d = read("0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n0\nCIRCLE\n10\n0\n20\n0\n40\n1\n0\nEOF");
    assert_eq!(d.entities.len(), 2);
    assert_eq!(d.counts.get("LINE"), Some(&1));
}

#[test]
fn non_flat_3d_polylines_are_projected_with_one_warning_for_all() {
    let poly = |z0: f64, z1: f64| {
        format!(
            "0\nPOLYLINE\n66\n1\n70\n9\n0\nVERTEX\n10\n0\n20\n0\n30\n{z0}\n70\n32\n\
             0\nVERTEX\n10\n10\n20\n0\n30\n{z1}\n70\n32\n0\nVERTEX\n10\n10\n20\n10\n30\n0\n70\n32\n0\nSEQEND\n"
        )
    };
    let d = read(&format!(
        "{HEADER_MM}0\nSECTION\n2\nENTITIES\n{}{}{}0\nENDSEC\n0\nEOF",
        poly(-2.0, 1.0),
        poly(0.0, 0.0),
        poly(0.0, 3.5)
    ));
    assert_eq!(d.entities.len(), 3);
    let w: Vec<_> = d
        .warnings
        .iter()
        .filter(|w| w.code == "polyline-not-flat")
        .collect();
    assert_eq!(w.len(), 1, "{:?}", d.warnings);
    let m = w[0].text.get(crate::warning::Lang::En);
    assert!(
        m.starts_with("2 3-D POLYLINE(s) not flat (Z -2.000 to 3.500), the first at line "),
        "{m}"
    );
}
