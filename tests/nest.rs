//! The nesting engine judged from outside: every nest is checked by code
//! written here (its own arc flattening, segment distances and point in
//! polygon), not by the engine's collision model. A nest is valid when no
//! two parts are closer than the spacing, every part lies inside the sheet
//! less the margin (or the strip), and every copy asked for is placed once.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::sweep::seg_dist;
use common::{fixture, rs274_errors, shared};
use kerfcam::contour;
use kerfcam::dxf::{self, ReadOptions};
use kerfcam::geom::{Point, Segment, Tolerance};
use kerfcam::nest::{
    self, instance, output, Nest, NestError, NestJob, NestSettings, Part, Rotations, Sheets,
};

/// Chord error of the check's own flattening, mm: distances measured on
/// the flattened outlines are within twice this of the true ones.
const FLAT: f64 = 1e-4;

/// The outline's points after the placement, arcs flattened within FLAT:
/// mirror x → −x, turn, move — written here from the placement's fields.
fn placed_outline(segs: &[Segment], rot_deg: f64, mirror: bool, t: Point) -> Vec<Point> {
    let (s, c) = rot_deg.to_radians().sin_cos();
    let map = |p: Point| {
        let x = if mirror { -p.x } else { p.x };
        Point::new(c * x - s * p.y + t.x, s * x + c * p.y + t.y)
    };
    let mut pts = Vec::new();
    for seg in segs {
        let (a, b) = (map(seg.a), map(seg.b));
        let bulge = if mirror { -seg.bulge } else { seg.bulge };
        pts.push(a);
        if bulge.abs() < 1e-12 {
            continue;
        }
        // Sweep 4·atan(bulge); radius from the chord and the half sweep.
        let sweep = 4.0 * bulge.atan();
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let chord = dx.hypot(dy);
        let r = chord / (2.0 * (sweep / 2.0).sin().abs());
        // The centre is on the chord's normal, left of a→b for a CCW arc
        // under 180° (right for CW), at sqrt(r² − (chord/2)²).
        let h = (r * r - chord * chord / 4.0).max(0.0).sqrt();
        let side = if (sweep > 0.0) == (sweep.abs() < std::f64::consts::PI) {
            1.0
        } else {
            -1.0
        };
        let centre = Point::new(
            (a.x + b.x) / 2.0 - side * dy / chord * h,
            (a.y + b.y) / 2.0 + side * dx / chord * h,
        );
        let start = (a.y - centre.y).atan2(a.x - centre.x);
        let step = 2.0 * (1.0 - FLAT / r).max(-1.0).acos();
        let n = ((sweep.abs() / step).ceil() as usize).max(1);
        for k in 1..n {
            let ang = start + sweep * k as f64 / n as f64;
            pts.push(Point::new(
                centre.x + r * ang.cos(),
                centre.y + r * ang.sin(),
            ));
        }
    }
    pts
}

fn crosses(a: Point, b: Point, c: Point, d: Point) -> bool {
    let o = |p: Point, q: Point, r: Point| (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    let (d1, d2, d3, d4) = (o(a, b, c), o(a, b, d), o(c, d, a), o(c, d, b));
    (d1 > 0.0) != (d2 > 0.0) && (d3 > 0.0) != (d4 > 0.0) && d1 != 0.0 && d2 != 0.0
}

/// Exact distance between two closed polylines' boundaries (0 when they cross).
fn boundary_distance(p: &[Point], q: &[Point]) -> f64 {
    let mut best = f64::INFINITY;
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        for j in 0..q.len() {
            let (c, d) = (q[j], q[(j + 1) % q.len()]);
            if crosses(a, b, c, d) {
                return 0.0;
            }
            best = best
                .min(seg_dist(a, c, d))
                .min(seg_dist(b, c, d))
                .min(seg_dist(c, a, b))
                .min(seg_dist(d, a, b));
        }
    }
    best
}

fn inside(poly: &[Point], p: Point) -> bool {
    let mut c = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            c = !c;
        }
    }
    c
}

/// True when a point of a grid over `a`'s box is inside `a` and inside
/// `b`, more than 1e-6 from `b`'s boundary.
fn grid_overlap(a: &[Point], b: &[Point]) -> bool {
    let (mut x0, mut y0, mut x1, mut y1) = (
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    );
    for p in a {
        (x0, y0, x1, y1) = (x0.min(p.x), y0.min(p.y), x1.max(p.x), y1.max(p.y));
    }
    let near = |p: Point| (0..b.len()).any(|k| seg_dist(p, b[k], b[(k + 1) % b.len()]) < 1e-6);
    (0..60).any(|i| {
        (0..60).any(|j| {
            let p = Point::new(
                x0 + (x1 - x0) * (i as f64 + 0.5) / 60.0,
                y0 + (y1 - y0) * (j as f64 + 0.5) / 60.0,
            );
            inside(a, p) && inside(b, p) && !near(p)
        })
    })
}

/// The independent check. `room` = (x0, y0, x1, y1) where outlines may lie.
fn assert_valid(job: &NestJob, n: &Nest, room: (f64, f64, f64, f64), spacing: f64) {
    // Counts: each part's copies 0..k once, k = quantity unless listed unplaced.
    for (pi, part) in job.parts.iter().enumerate() {
        let mut copies: Vec<usize> = n
            .placements
            .iter()
            .filter(|p| p.part == pi)
            .map(|p| p.copy)
            .collect();
        copies.sort();
        let missing: usize = n
            .unplaced
            .iter()
            .filter(|u| u.part == part.name)
            .map(|u| u.copies)
            .sum();
        assert_eq!(
            copies.len() + missing.min(part.quantity),
            part.quantity,
            "{}",
            part.name
        );
        assert_eq!(
            copies,
            (0..copies.len()).collect::<Vec<_>>(),
            "{}: copies not 0..k once",
            part.name
        );
    }
    let outlines: Vec<(usize, Vec<Point>)> = n
        .placements
        .iter()
        .map(|p| {
            (
                p.sheet,
                placed_outline(
                    &job.parts[p.part].outer,
                    p.rotation,
                    p.mirror,
                    p.translation,
                ),
            )
        })
        .collect();
    let slack = 2.0 * FLAT + 1e-6;
    for (k, (_, o)) in outlines.iter().enumerate() {
        for q in o {
            assert!(
                q.x >= room.0 - slack
                    && q.y >= room.1 - slack
                    && q.x <= room.2 + slack
                    && q.y <= room.3 + slack,
                "copy {k} leaves the sheet at ({}, {})",
                q.x,
                q.y
            );
        }
    }
    for i in 0..outlines.len() {
        for j in i + 1..outlines.len() {
            let ((si, a), (sj, b)) = (&outlines[i], &outlines[j]);
            if si != sj {
                continue;
            }
            let d = boundary_distance(a, b);
            assert!(
                d >= spacing - slack,
                "copies {i} and {j} are {d} apart, spacing {spacing}"
            );
            if d > slack {
                // Apart: one inside the other is the only way to overlap.
                assert!(
                    !inside(b, a[0]) && !inside(a, b[0]),
                    "copy {i} or {j} lies inside the other"
                );
            } else {
                // Touching (spacing 0): no point of a 60 × 60 grid over one
                // lies inside both, away from the other's boundary.
                assert!(
                    !grid_overlap(a, b) && !grid_overlap(b, a),
                    "copies {i} and {j} overlap"
                );
            }
        }
    }
}

fn fixture_parts(name: &str, quantity: usize) -> Vec<Part> {
    let bytes = std::fs::read(fixture(name)).unwrap();
    let d = dxf::parse(&bytes, &ReadOptions::DEFAULT).unwrap();
    let c = contour::extract(&d, Tolerance::DEFAULT, 0.05);
    nest::parts_from_contours(&c, name, quantity).0
}

fn settings(spacing: f64, margin: f64) -> NestSettings {
    NestSettings {
        spacing,
        margin,
        tolerance: 0.05,
        time_s: 1e9,
        seed: 7,
        max_evaluations: Some(30),
    }
}

fn run(job: &NestJob) -> Result<Nest, NestError> {
    nest::nest(job, &|| 0.0, &mut |_| true)
}

#[test]
fn fixture_parts_on_a_sheet_are_valid_and_cut_into_a_program_rs274_accepts() {
    let mut parts = fixture_parts("seed000-plate-6-holes.dxf", 3);
    parts.extend(fixture_parts("seed001-P51703.dxf", 2));
    parts.extend(fixture_parts("seed003-grid-3x2.dxf", 1));
    for p in &mut parts {
        p.mirror = true;
    }
    let asked: usize = parts.iter().map(|p| p.quantity).sum();
    // Six 300×400 grid pieces and five plates are more than one sheet holds.
    let job = NestJob {
        parts,
        sheets: Sheets::Rect {
            width: 1000.0,
            height: 500.0,
            count: 3,
        },
        settings: settings(2.5, 5.0),
    };
    let n = run(&job).unwrap();
    assert!(n.unplaced.is_empty(), "{:?}", n.unplaced);
    assert_eq!(n.placements.len(), asked);
    assert!(n.sheets.len() >= 2);
    assert_valid(&job, &n, (5.0, 5.0, 995.0, 495.0), 2.5);
    // Cut each sheet with the ordinary pipeline.
    let settings = kerfcam::Settings::new(1.5, 0.001, 2000.0).unwrap();
    for (k, used) in n.sheets.iter().enumerate() {
        assert!(used.utilisation > 0.0 && used.utilisation <= 1.0);
        let drawing = output::sheet_drawing(&job, &n, k);
        let c = contour::extract(&drawing, Tolerance::DEFAULT, 0.05);
        let on_sheet: Vec<_> = n.placements.iter().filter(|p| p.sheet == k).collect();
        assert_eq!(
            c.parts,
            on_sheet.len(),
            "each placed copy is one part to cut"
        );
        let holes: usize = on_sheet.iter().map(|p| job.parts[p.part].holes.len()).sum();
        assert_eq!(
            c.contours
                .iter()
                .filter(|x| x.kind == contour::ContourKind::Hole)
                .count(),
            holes
        );
        let paths = kerfcam::kerf::offset(&c, settings.kerf, settings.tolerance);
        let input = kerfcam::plan::PlanInput {
            drawing: &drawing,
            contours: &c,
            kerf: &paths,
            tolerance: settings.tolerance.mm(),
            kerf_width: settings.kerf.width,
        };
        let program = kerfcam::gcode::emit(
            &kerfcam::plan::plan(&input, &settings.plan),
            &settings.gcode,
        );
        let errors = rs274_errors(&program, &format!("nest-fixtures-{k}"));
        assert!(errors.is_empty(), "sheet {k}: {errors:?}");
    }
}

#[test]
fn the_nest_dxf_reads_back_as_the_parts_and_the_sheet() {
    let parts = fixture_parts("seed000-plate-6-holes.dxf", 6);
    let job = NestJob {
        parts,
        sheets: Sheets::Rect {
            width: 500.0,
            height: 300.0,
            count: 3,
        },
        settings: settings(3.0, 10.0),
    };
    let n = run(&job).unwrap();
    assert_eq!(n.placements.len(), 6);
    assert!(
        n.sheets.len() >= 2,
        "six plates (6 × 23 807 mm²) are more than one 480 × 280 sheet holds"
    );
    assert_valid(&job, &n, (10.0, 10.0, 490.0, 290.0), 3.0);
    let text = output::to_dxf(&job, &n);
    let d = dxf::parse(text.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    let sheet = d.layers.iter().position(|l| l.name == "SHEET").unwrap() as u32;
    assert_eq!(
        d.entities.iter().filter(|e| e.layer == sheet).count(),
        n.sheets.len()
    );
    // 6 copies × (outer + 6 holes), arcs kept as arcs.
    let parts: Vec<_> = d.entities.iter().filter(|e| e.layer != sheet).collect();
    assert_eq!(parts.len(), 6 * 7);
    assert!(parts.iter().all(|e| e.closed));
    assert!(parts
        .iter()
        .any(|e| e.segments.iter().any(|s| s.bulge != 0.0)));
}

#[test]
fn an_instance_strip_nest_is_valid_and_deterministic() {
    let text = std::fs::read_to_string(shared().join("nesting").join("fu.json")).unwrap();
    let mut i = instance::read(&text, settings(0.0, 0.0)).unwrap();
    let Sheets::Strip { height } = i.job.sheets else {
        panic!("strip")
    };
    i.job.settings.tolerance = height * 1e-4;
    i.job.settings.max_evaluations = Some(200);
    let a = run(&i.job).unwrap();
    let b = run(&i.job).unwrap();
    assert_eq!(
        a.placements, b.placements,
        "same seed, same evaluations: same nest"
    );
    assert_eq!(a.placements.len(), 12);
    let len = a.strip_length.unwrap();
    assert_valid(&i.job, &a, (0.0, 0.0, len, height), 0.0);
    let area: f64 = i
        .job
        .parts
        .iter()
        .map(|p| p.area() * p.quantity as f64)
        .sum();
    assert!((a.density - area / (height * len)).abs() < 1e-9);
}

fn rect(name: &str, w: f64, h: f64, quantity: usize) -> Part {
    let c = [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)].map(|(x, y)| Point::new(x, y));
    Part {
        name: name.into(),
        outer: (0..4)
            .map(|i| Segment::line(c[i], c[(i + 1) % 4]))
            .collect(),
        holes: vec![],
        quantity,
        rotations: Rotations::Quarter,
        mirror: false,
    }
}

#[test]
fn a_part_larger_than_the_sheet_is_listed_and_the_rest_nested() {
    let mut big = rect("big", 2000.0, 100.0, 2);
    big.rotations = Rotations::None;
    let job = NestJob {
        parts: vec![
            big,
            rect("small", 100.0, 50.0, 5),
            rect("none", 10.0, 10.0, 0),
        ],
        sheets: Sheets::Rect {
            width: 1000.0,
            height: 500.0,
            count: 1,
        },
        settings: settings(2.0, 5.0),
    };
    let n = run(&job).unwrap();
    assert_eq!(n.placements.len(), 5);
    let big = n.unplaced.iter().find(|u| u.part == "big").unwrap();
    assert_eq!(big.copies, 2);
    assert!(
        big.reason.contains("larger than the sheet"),
        "{}",
        big.reason
    );
    assert!(n
        .unplaced
        .iter()
        .any(|u| u.part == "none" && u.reason.contains("quantity 0")));
    assert_valid(&job, &n, (5.0, 5.0, 995.0, 495.0), 2.0);
}

#[test]
fn bad_quantities_spacing_and_sheets_are_said_not_panicked() {
    let job = |parts, spacing: f64, sheets| NestJob {
        parts,
        sheets,
        settings: settings(spacing, 5.0),
    };
    let sheet = Sheets::Rect {
        width: 1000.0,
        height: 500.0,
        count: 1,
    };
    let e = run(&job(
        vec![rect("a", 10.0, 10.0, 10_001)],
        2.0,
        sheet.clone(),
    ))
    .unwrap_err();
    assert!(
        matches!(e, NestError::TooMany { .. }) && e.to_string().contains("10000"),
        "{e}"
    );
    assert_eq!(
        run(&job(vec![rect("a", 10.0, 10.0, 0)], 2.0, sheet.clone())).unwrap_err(),
        NestError::NoParts
    );
    // Spacing larger than the sheet: one copy fits (spacing is between
    // parts), the others are listed with the reason.
    let n = run(&job(vec![rect("a", 10.0, 10.0, 3)], 5000.0, sheet.clone())).unwrap();
    assert_eq!(n.placements.len(), 1);
    assert!(
        n.unplaced[0].copies == 2 && n.unplaced[0].reason.contains("no room"),
        "{:?}",
        n.unplaced
    );
    for bad in [
        Sheets::Rect {
            width: -1.0,
            height: 5.0,
            count: 1,
        },
        Sheets::Rect {
            width: 10.0,
            height: 5.0,
            count: 0,
        },
        Sheets::Strip { height: f64::NAN },
    ] {
        assert!(matches!(
            run(&job(vec![rect("a", 1.0, 1.0, 1)], 0.0, bad)),
            Err(NestError::Setting { .. })
        ));
    }
    assert!(matches!(
        run(&job(vec![rect("a", 1.0, 1.0, 1)], -1.0, sheet)),
        Err(NestError::Setting {
            field: "spacing",
            ..
        })
    ));
}

#[test]
fn an_open_outline_is_not_nestable_and_said_so() {
    // Two lines that do not close, and one closed square.
    let dxf = "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n0\n20\n0\n11\n50\n21\n0\n0\nLINE\n10\n50\n20\n0\n11\n50\n21\n40\n\
0\nLWPOLYLINE\n90\n4\n70\n1\n10\n100\n20\n0\n10\n120\n20\n0\n10\n120\n20\n20\n10\n100\n20\n20\n0\nENDSEC\n0\nEOF\n";
    let d = dxf::parse(dxf.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    let c = contour::extract(&d, Tolerance::DEFAULT, 0.05);
    let (parts, notes) = nest::parts_from_contours(&c, "mixed", 2);
    assert_eq!(parts.len(), 1);
    assert_eq!(notes.len(), 1);
    assert!(
        notes[0].reason.contains("not nestable"),
        "{}",
        notes[0].reason
    );
}

#[test]
fn a_file_that_is_not_an_instance_is_an_error() {
    for text in ["{\"name\": 3}", "not json", "{\"strip_height\": 10, \"items\": [{\"demand\": 1, \"shape\": {\"type\": \"simple_polygon\", \"data\": [[0, 0], [1]]}}]}"] {
        assert!(matches!(instance::read(text, settings(0.0, 0.0)), Err(NestError::Instance(_))), "{text}");
    }
}

#[test]
fn the_check_itself_catches_overlap_spacing_and_the_sheet_edge() {
    let job = NestJob {
        parts: vec![rect("a", 100.0, 50.0, 2)],
        sheets: Sheets::Rect {
            width: 1000.0,
            height: 500.0,
            count: 1,
        },
        settings: settings(2.0, 5.0),
    };
    let good = run(&job).unwrap();
    assert_valid(&job, &good, (5.0, 5.0, 995.0, 495.0), 2.0);
    let moved = |dx: f64, dy: f64| {
        let mut n = good.clone();
        for (k, p) in n.placements.iter_mut().enumerate() {
            p.rotation = 0.0;
            p.translation = Point::new(10.0 + dx * k as f64, 10.0 + dy * k as f64);
        }
        n
    };
    let fails = |n: Nest| {
        std::panic::catch_unwind(|| assert_valid(&job, &n, (5.0, 5.0, 995.0, 495.0), 2.0)).is_err()
    };
    assert!(fails(moved(0.0, 0.0)), "one copy on the other");
    assert!(fails(moved(101.0, 0.0)), "1 mm apart, spacing 2");
    assert!(!fails(moved(102.5, 0.0)), "2.5 mm apart is fine");
    assert!(!fails(moved(0.0, 52.0)), "2 mm apart is fine");
    assert!(fails(moved(0.0, -20.0)), "off the sheet");
    let mut one_missing = good.clone();
    one_missing.placements.pop();
    assert!(fails(one_missing), "a copy missing and not listed");
}

#[test]
fn progress_is_reported_and_a_cancel_returns_the_best_nest_so_far() {
    let job = NestJob {
        parts: vec![rect("a", 100.0, 50.0, 6), rect("b", 70.0, 30.0, 4)],
        sheets: Sheets::Strip { height: 120.0 },
        settings: NestSettings {
            max_evaluations: None,
            ..settings(2.0, 0.0)
        },
    };
    let mut seen = Vec::new();
    // Stop at the third report: without the cancel this would run 1e9 s.
    let n = nest::nest(&job, &|| 0.0, &mut |p| {
        seen.push(p);
        seen.len() < 3
    })
    .unwrap();
    assert_eq!(seen.len(), 3);
    assert!(seen
        .windows(2)
        .all(|w| w[1].length <= w[0].length && w[1].evaluations >= w[0].evaluations));
    assert_eq!(n.placements.len(), 10);
    let len = n.strip_length.unwrap();
    assert!(
        len <= seen[0].length + 1e-9,
        "the nest returned is no worse than the first"
    );
    assert_valid(&job, &n, (0.0, 0.0, len, 120.0), 2.0);
}
