use super::*;
use crate::geom::Segment;
use crate::nest::{output, NestSettings, Part, Rotations, Sheets};

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

fn rect(x: f64, y: f64, w: f64, h: f64) -> Vec<Segment> {
    let c = [p(x, y), p(x + w, y), p(x + w, y + h), p(x, y + h)];
    (0..4).map(|i| Segment::line(c[i], c[(i + 1) % 4])).collect()
}

fn circle(c: Point, r: f64) -> Vec<Segment> {
    vec![
        Segment { a: p(c.x - r, c.y), b: p(c.x + r, c.y), bulge: 1.0 },
        Segment { a: p(c.x + r, c.y), b: p(c.x - r, c.y), bulge: 1.0 },
    ]
}

fn part(name: &str, outer: Vec<Segment>, holes: Vec<Vec<Segment>>, quantity: usize) -> Part {
    Part {
        name: name.into(),
        outer,
        holes,
        quantity,
        rotations: Rotations::Quarter,
        mirror: true,
    }
}

fn placed(part: usize, copy: usize, rotation: f64, mirror: bool, at: Point) -> Placement {
    Placement {
        part,
        copy,
        sheet: 0,
        rotation,
        mirror,
        translation: at,
        in_hole_of: None,
    }
}

/// A plate 120 × 60 with a big hole in its middle and two small ones, in
/// four poses; a 6 × 6 washer too small for any label.
fn job_and_nest() -> (NestJob, Nest) {
    let plate = part(
        "plate",
        rect(0.0, 0.0, 120.0, 60.0),
        vec![circle(p(60.0, 30.0), 18.0), circle(p(12.0, 12.0), 4.0), circle(p(108.0, 48.0), 4.0)],
        4,
    );
    let washer = part("washer", circle(p(0.0, 0.0), 3.0), vec![circle(p(0.0, 0.0), 1.0)], 1);
    let job = NestJob {
        parts: vec![plate, washer],
        sheets: Sheets::Rect { width: 1000.0, height: 1000.0, count: 1 },
        settings: NestSettings::default(),
    };
    let placements = vec![
        placed(0, 0, 0.0, false, p(10.0, 10.0)),
        placed(0, 1, 90.0, false, p(300.0, 10.0)),
        placed(0, 2, 180.0, true, p(500.0, 200.0)),
        placed(0, 3, 270.0, true, p(700.0, 400.0)),
        placed(1, 0, 0.0, false, p(900.0, 900.0)),
    ];
    let nest = Nest {
        placements,
        sheets: Vec::new(),
        unplaced: Vec::new(),
        strip_length: None,
        density: 0.0,
        evaluations: 0,
    };
    (job, nest)
}

#[test]
fn every_label_lies_in_its_copy_clear_of_holes_and_reads_upright() {
    let (job, nest) = job_and_nest();
    let options = LabelOptions::DEFAULT;
    let labels = label_nest(&job, &nest, &options, 0.05);
    assert_eq!(labels.labels.len(), 4);
    for l in &labels.labels {
        let p = nest.placements.iter().find(|p| (p.part, p.copy) == (l.part, l.copy)).unwrap();
        let loops = output::placed_loops(&job, p);
        let c = check::clearance(&loops[0], &loops[1..], &l.strokes);
        assert!(c >= options.margin - check::FINE, "{} clearance {c}", l.text);
        assert!(l.height >= options.height_min && l.height <= options.height_max);
        assert!(l.angle > -90.0 && l.angle <= 90.0 + 1e-6, "{} at {}", l.text, l.angle);
    }
    // The same part in every pose: the same height, turned with it.
    assert!(labels.labels.iter().all(|l| (l.height - labels.labels[0].height).abs() < 1e-9));
    assert_eq!(labels.labels[0].text, "plate#1");
    // Turned with the copy: a quarter turn apart; the copy turned a half
    // turn (and mirrored) reads as the first, not upside down.
    let a: Vec<f64> = labels.labels.iter().map(|l| l.angle).collect();
    assert!(((a[1] - a[0]).rem_euclid(180.0) - 90.0).abs() < 1e-6, "{a:?}");
    assert!((a[2] - a[0]).abs() < 1e-6, "{a:?}");
}

#[test]
fn a_mirrored_copy_reads_unmirrored() {
    let (job, nest) = job_and_nest();
    let labels = label_nest(&job, &nest, &LabelOptions::DEFAULT, 0.05);
    for l in &labels.labels {
        // The first stroke of "P" goes up its left side: from the baseline
        // up, on the left of the box as read (its first point is the box's
        // lower-left corner, at a negative offset along the reading direction).
        let dir = Point::new(l.angle.to_radians().cos(), l.angle.to_radians().sin());
        let up = dir.perp();
        let s = &l.strokes[0];
        let rise = s[1].sub(s[0]).dot(up);
        assert!(rise > 0.0, "{}: the P's stem runs down", l.text);
        assert!(s[0].sub(l.centre).dot(dir) < 0.0, "{}: mirrored", l.text);
    }
}

#[test]
fn a_part_too_small_gets_no_label_and_a_note_naming_it() {
    let (job, nest) = job_and_nest();
    let labels = label_nest(&job, &nest, &LabelOptions::DEFAULT, 0.05);
    assert_eq!(labels.left_out, [(1, 0)]);
    assert_eq!(labels.warnings.len(), 1);
    assert!(labels.warnings[0].message().contains("washer"));
    assert!(!labels.warnings[0].message().contains("plate"));
}

#[test]
fn short_codes_count_parts_by_letters() {
    assert_eq!(code(0), "A");
    assert_eq!(code(25), "Z");
    assert_eq!(code(26), "AA");
    assert_eq!(code(27 * 26), "AAA");
    let (job, nest) = job_and_nest();
    let options = LabelOptions { naming: Naming::Code, ..LabelOptions::DEFAULT };
    let labels = label_nest(&job, &nest, &options, 0.05);
    assert_eq!(labels.labels[3].text, "A4");
    // Short codes are bigger than names in the same part.
    let named = label_nest(&job, &nest, &LabelOptions::DEFAULT, 0.05);
    assert!(labels.labels[0].height > named.labels[0].height);
}

#[test]
fn options_out_of_range_are_refused() {
    let bad = LabelOptions { height_min: 0.0, ..LabelOptions::DEFAULT };
    assert_eq!(bad.check().unwrap_err().0, "label_height_min");
    let bad = LabelOptions { height_max: 2.0, ..LabelOptions::DEFAULT };
    assert_eq!(bad.check().unwrap_err().0, "label_height_max");
    let bad = LabelOptions { margin: f64::NAN, ..LabelOptions::DEFAULT };
    assert_eq!(bad.check().unwrap_err().0, "label_margin");
}
