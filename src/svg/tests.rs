//! The reader end to end on small hand-written files, with the expected
//! sizes computed by hand.

use super::*;
use crate::dxf::Units;
use crate::geom::{BBox, Point};

fn read(svg: &str) -> Drawing {
    parse(svg.as_bytes(), &ReadOptions::DEFAULT).unwrap()
}

fn size(d: &Drawing) -> (f64, f64) {
    (
        d.extent.max.x - d.extent.min.x,
        d.extent.max.y - d.extent.min.y,
    )
}

fn near(a: f64, b: f64, eps: f64) {
    assert!((a - b).abs() <= eps, "{a} != {b}");
}

fn codes(d: &Drawing) -> Vec<&'static str> {
    d.warnings.iter().map(|w| w.code).collect()
}

#[test]
fn a_rect_10_by_20_mm_on_a_mm_page() {
    let d = read(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50">
        <rect x="5" y="5" width="10" height="20" stroke="black" fill="none"/></svg>"#,
    );
    assert_eq!(d.units, Some(Units::MM));
    assert_eq!(d.units_source, "width/height");
    let (w, h) = size(&d);
    near(w, 10.0, 1e-9);
    near(h, 20.0, 1e-9);
    // y up from the page's bottom edge: the rect's top at y 5 down is 45 up.
    near(d.extent.max.y, 45.0, 1e-9);
    near(d.extent.min.y, 25.0, 1e-9);
    assert_eq!(d.entities.len(), 1);
    assert!(d.entities[0].closed);
    assert!(!codes(&d).contains(&"units-assumed"), "{:?}", d.warnings);
}

#[test]
fn px_only_is_read_at_96_per_inch_with_both_sizes_said() {
    let d = read(r#"<svg width="960" height="480"><rect width="96" height="48"/></svg>"#);
    assert_eq!(d.units_source, "assumed");
    let (w, h) = size(&d);
    near(w, 25.4, 1e-9);
    near(h, 12.7, 1e-9);
    let u = d
        .warnings
        .iter()
        .find(|w| w.code == "units-assumed")
        .unwrap();
    assert!(u.text.en.contains("25.4 × 12.7 mm"), "{}", u.text.en);
    assert!(u.text.en.contains("33.9 × 16.9 mm"), "{}", u.text.en);
    // At 72 px per inch when asked.
    let opts = ReadOptions {
        units: Units::from_name("px72"),
        ..ReadOptions::DEFAULT
    };
    let d = parse(
        br#"<svg width="960" height="480"><rect width="72" height="36"/></svg>"#,
        &opts,
    )
    .unwrap();
    let (w, h) = size(&d);
    near(w, 25.4, 1e-9);
    near(h, 12.7, 1e-9);
    assert_eq!(d.units_source, "override");
}

#[test]
fn a_unit_chosen_for_a_mm_file_is_said_not_to_apply() {
    let opts = ReadOptions {
        units: Units::from_name("px72"),
        ..ReadOptions::DEFAULT
    };
    let d = parse(br#"<svg width="10mm" height="10mm" viewBox="0 0 10 10"><rect width="10" height="10"/></svg>"#, &opts).unwrap();
    near(size(&d).0, 10.0, 1e-9);
    assert!(codes(&d).contains(&"units-not-applied"));
}

#[test]
fn a_transform_chain_by_hand() {
    // translate(10,0) rotate(90) scale(2) on the segment (0,0)-(5,0):
    // scale → (10,0); rotate 90 → (0,10); translate → (10,10) user units,
    // 1 unit = 1 mm, page 100 high: y up = 90.
    let d = read(
        r#"<svg width="100mm" height="100mm" viewBox="0 0 100 100">
        <g transform="translate(10,0)"><g transform="rotate(90)"><line x2="5" transform="scale(2)" stroke="red"/></g></g></svg>"#,
    );
    let s = d.entities[0].segments[0];
    assert!(s.a.dist(Point::new(10.0, 100.0)) < 1e-9, "{s:?}");
    assert!(s.b.dist(Point::new(10.0, 90.0)) < 1e-9, "{s:?}");
}

#[test]
fn a_circle_stays_two_or_more_true_arcs_and_skewed_becomes_an_ellipse() {
    let d = read(
        r#"<svg width="100mm" height="100mm" viewBox="0 0 100 100"><circle cx="50" cy="50" r="10"/></svg>"#,
    );
    let segs = &d.entities[0].segments;
    assert!(segs.iter().all(|s| !s.is_line()));
    for s in segs {
        let (c, r) = s.arc_center().unwrap();
        assert!(c.dist(Point::new(50.0, 50.0)) < 1e-9 && (r - 10.0).abs() < 1e-9);
    }
    assert!(d.entities[0].closed);
    // Non-uniform scale: an ellipse 20 × 10 (semi-axes), within 0.01 mm.
    let d = read(
        r#"<svg width="100mm" height="100mm" viewBox="0 0 100 100"><circle cx="25" cy="50" r="10" transform="scale(2,1)"/></svg>"#,
    );
    let bb = d.extent;
    near(bb.max.x - bb.min.x, 40.0, 0.011);
    near(bb.max.y - bb.min.y, 20.0, 0.011);
    for s in all_segments(&d) {
        let m = s.point_at(0.5);
        let t = ((m.x - 50.0) / 20.0).hypot((m.y - 50.0) / 10.0);
        assert!((t - 1.0).abs() * 10.0 < 0.011, "{t}");
    }
}

#[test]
fn inkscape_layers_hidden_layers_and_colours() {
    let d = read(
        r##"<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
          width="100mm" height="100mm" viewBox="0 0 100 100">
        <g inkscape:groupmode="layer" inkscape:label="Cut"><rect width="10" height="10" stroke="#000"/></g>
        <g inkscape:groupmode="layer" inkscape:label="Guides" style="display:none"><rect width="20" height="20"/></g>
        <rect x="50" width="5" height="5" style="stroke:#ff0000;fill:none"/></svg>"##,
    );
    let names: Vec<(&str, bool)> = d
        .layers
        .iter()
        .map(|l| (l.name.as_str(), l.selected))
        .collect();
    assert_eq!(names, [("Cut", true), ("Guides", false), ("#ff0000", true)]);
    assert_eq!(d.entities.len(), 2);
    assert!(codes(&d).contains(&"layers-not-selected"));
}

#[test]
fn use_symbol_and_defs_are_expanded_once_each() {
    let d = read(
        r##"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="100mm" height="100mm" viewBox="0 0 100 100">
        <defs><rect id="r" width="10" height="10"/>
          <symbol id="s" viewBox="0 0 10 10"><rect width="10" height="10"/></symbol></defs>
        <use xlink:href="#r" x="20"/>
        <use href="#s" x="40" width="20" height="20"/></svg>"##,
    );
    assert_eq!(d.entities.len(), 2);
    let bbs: Vec<BBox> = d
        .entities
        .iter()
        .map(|e| {
            let mut b = BBox::EMPTY;
            e.segments.iter().for_each(|s| b.union(&s.bbox()));
            b
        })
        .collect();
    near(bbs[0].min.x, 20.0, 1e-9);
    near(bbs[1].max.x - bbs[1].min.x, 20.0, 1e-9);
}

#[test]
fn use_cycles_external_references_and_text_are_said() {
    let d = read(
        r##"<svg width="10mm" height="10mm" viewBox="0 0 10 10">
        <g id="a"><use href="#b"/><rect width="1" height="1"/></g>
        <g id="b"><use href="#a"/></g>
        <use href="other.svg#x"/><use href="http://example.com/a.svg#y"/><use href="#nothing"/>
        <text>Hello</text><image href="a.png"/></svg>"##,
    );
    let c = codes(&d);
    for code in [
        "use-cycle",
        "external-reference",
        "use-missing",
        "text-not-cut",
        "image-not-cut",
    ] {
        assert!(c.contains(&code), "{code}: {c:?}");
    }
    assert_eq!(d.skipped.get("text"), Some(&1));
    assert!(!d.entities.is_empty());
}

#[test]
fn bad_input_gives_errors_or_warnings() {
    let e = |s: &[u8]| parse(s, &ReadOptions::DEFAULT).unwrap_err();
    assert!(matches!(e(b"<svg><g></svg>"), SvgError::Xml(_)));
    assert!(matches!(e(b"<html/>"), SvgError::NotSvg(_)));
    assert!(matches!(e(b"  "), SvgError::Empty));
    assert!(matches!(e(b"\x1f\x8b\x08\0"), SvgError::Compressed));
    // No size and no viewBox, zero viewBox, huge and non-numbers, a bad command.
    let d = read(
        r#"<svg viewBox="0 0 0 0"><path d="M 0 0 L 1e300 0 M 0 0 L 10 10 Q 5"/><rect width="NaN" height="3"/>
        <path d="M0 0 L 10 0" transform="scale(1e400)"/></svg>"#,
    );
    let c = codes(&d);
    for code in [
        "view-box-unusable",
        "path-error",
        "bad-number",
        "empty-shape",
        "bad-transform",
    ] {
        assert!(c.contains(&code), "{code}: {c:?}");
    }
    assert_eq!(d.entities.len(), 2, "{:?}", d.entities);
}

#[test]
fn deep_nesting_and_use_bombs_stop() {
    let mut s = String::from("<svg>");
    for _ in 0..10_000 {
        s.push_str("<g>");
    }
    s.push_str("<rect width='1' height='1'/>");
    for _ in 0..10_000 {
        s.push_str("</g>");
    }
    s.push_str("</svg>");
    let d = read(&s);
    assert!(codes(&d).contains(&"too-deep"));
    // Ten uses of ten uses … eight levels deep: 10^8 rects.
    let mut s = String::from(r##"<svg><rect id="l0" width="1" height="1"/>"##);
    for k in 1..=8 {
        s.push_str(&format!("<g id='l{k}'>"));
        for _ in 0..10 {
            s.push_str(&format!("<use href='#l{}'/>", k - 1));
        }
        s.push_str("</g>");
    }
    s.push_str("</svg>");
    let d = read(&s);
    assert!(codes(&d).contains(&"too-many-elements"), "{:?}", codes(&d));
}

#[test]
fn illustrator_entities_and_css_classes() {
    let d = read(
        r#"<?xml version="1.0"?>
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [
  <!ENTITY ns_svg "http://www.w3.org/2000/svg">
]>
<svg xmlns="&ns_svg;" viewBox="0 0 72 72"><style>.st0{fill:none;stroke:#0000FF;}</style>
<rect class="st0" width="72" height="36"/></svg>"#,
    );
    assert_eq!(d.layers[0].name, "#0000ff");
    near(size(&d).0, 25.4 * 72.0 / 96.0, 1e-9);
}
