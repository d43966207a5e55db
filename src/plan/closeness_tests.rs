use crate::plan::Order;
use crate::test_dxf;

/// Rectangles `(x, y, w, h)` as LWPOLYLINEs, mm.
fn drawing(rects: &[(f64, f64, f64, f64)]) -> Vec<u8> {
    let body: String = rects
        .iter()
        .map(|&(x, y, w, h)| test_dxf::rect(x, y, w, h))
        .collect();
    test_dxf::file(&body)
}

fn run(bytes: &[u8], order: Order, verify: bool) -> crate::Output {
    let s = crate::Settings::new(1.5, 0.001, 2000.0)
        .unwrap()
        .with_order(order)
        .unwrap()
        .with_verify(verify);
    crate::run(bytes, &s).unwrap()
}

fn warned(out: &crate::Output) -> Option<String> {
    out.warnings()
        .find(|w| w.code == "parts-closer-than-kerf" && w.text.en.contains("mm²"))
        .map(|w| w.text.en.clone())
}

/// The area in the warning's text ("about 12.3 mm²").
fn area_of(text: &str) -> f64 {
    let at = text.find(" mm²").unwrap();
    let start = text[..at].rfind(' ').unwrap() + 1;
    text[start..at].parse().unwrap()
}

/// The area in `text` against `want` (the bands' area, worked out by hand)
/// within 10 %, and against the sweep's raster within 35 %: the sweep
/// counts cells of w/8 whose centre the disc reaches, a band 0.5 mm thick
/// is 2.7 cells, counted as 2 or 3 (its own figure is ±1 cell a column).
fn check_area(text: &str, want: f64, swept: f64, what: &str) {
    let area = area_of(text);
    assert!(
        (area - want).abs() <= 0.1 * want,
        "{what}: {area} against {want}"
    );
    assert!(
        (area - swept).abs() <= 0.35 * swept,
        "{what}: {area} against the sweep's {swept}"
    );
}

#[test]
fn parts_closer_than_the_kerf_are_warned_in_every_order_with_their_area() {
    // Two plates 1 mm apart along 80 mm, kerf 1.5: each cut takes 0.5 mm
    // of the other along the shared stretch: 2 × 0.5 × 80 mm².
    let bytes = drawing(&[(0.0, 0.0, 80.0, 40.0), (0.0, 41.0, 80.0, 40.0)]);
    for order in [Order::Contour, Order::Chained, Order::Eulerian] {
        let out = run(&bytes, order, false);
        let Some(text) = warned(&out) else {
            panic!("{order:?}: no warning");
        };
        assert!(text.contains("2 part(s) (1, 2)"), "{order:?}: {text}");
        assert!(text.contains("up to 0.50 mm deep"), "{order:?}: {text}");
        let v = run(&bytes, order, true).verification.unwrap();
        check_area(&text, 80.0, v.overcut_mm2, &format!("{order:?}"));
    }
    // The drawing order cuts on the drawn lines: its disc reaches 0.75 mm,
    // short of the neighbour 1 mm away (what it takes from each cut's own
    // part is that order's nature); 0.5 mm apart it takes 0.25 mm along
    // both plates.
    assert!(warned(&run(&bytes, Order::Drawing, false)).is_none());
    let close = drawing(&[(0.0, 0.0, 80.0, 40.0), (0.0, 40.5, 80.0, 40.0)]);
    let text = warned(&run(&close, Order::Drawing, false)).unwrap();
    assert!(text.contains("up to 0.25 mm deep"), "{text}");
    assert!((area_of(&text) - 40.0).abs() < 4.0, "{text}");
}

#[test]
fn glyphs_half_a_millimetre_apart_are_warned_with_the_depth_inside() {
    // The neighbour's kerf path runs 0.25 mm inside the other glyph: the
    // disc reaches 1.0 mm into it, along 20 mm, on both sides of 2 gaps.
    let bytes = drawing(&[
        (0.0, 0.0, 3.0, 20.0),
        (3.5, 0.0, 3.0, 20.0),
        (7.0, 0.0, 3.0, 20.0),
    ]);
    let out = run(&bytes, Order::Contour, false);
    let text = warned(&out).unwrap();
    let v = run(&bytes, Order::Contour, true).verification.unwrap();
    assert!(text.contains("up to 1.00 mm deep"), "{text}");
    check_area(&text, 80.0, v.overcut_mm2, "glyphs");
}

#[test]
fn parts_spaced_for_the_kerf_and_parts_in_holes_are_not_warned() {
    // 3 mm apart; a plate in the hole of a frame with 5 mm all round.
    let bytes = drawing(&[
        (0.0, 0.0, 50.0, 20.0),
        (0.0, 23.0, 50.0, 20.0),
        (100.0, 0.0, 60.0, 60.0),
        (110.0, 10.0, 40.0, 40.0),
        (115.0, 15.0, 30.0, 30.0),
    ]);
    for order in [Order::Contour, Order::Chained, Order::Eulerian] {
        let out = run(&bytes, order, false);
        assert!(warned(&out).is_none(), "{order:?}: {:?}", warned(&out));
    }
    // The plate in the hole 0.5 mm from its edge: the frame loses material.
    let bytes = drawing(&[
        (100.0, 0.0, 60.0, 60.0),
        (110.0, 10.0, 40.0, 40.0),
        (110.5, 15.0, 30.0, 30.0),
    ]);
    let text = warned(&run(&bytes, Order::Contour, false)).unwrap();
    assert!(text.contains("(1, 2)"), "{text}");
}
