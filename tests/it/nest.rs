//! The nesting engine judged from outside: every nest is checked by code
//! written here (its own arc flattening, segment distances and point in
//! polygon), not by the engine's collision model. A nest is valid when no
//! two parts are closer than the spacing, every part lies inside the sheet
//! less the margin (or the strip), and every copy asked for is placed once.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::sweep::seg_dist;
use common::{fixture, rect_part as rect, rs274_errors, shared};
use kerfcam::contour;
use kerfcam::dxf::{self, ReadOptions};
use kerfcam::geom::{Point, Segment, Tolerance};
use kerfcam::nest::{
    self, instance, output, Nest, NestError, NestJob, NestSettings, Part, Rotations, SheetSize,
    Sheets,
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
    assert_valid_on(job, n, &|_| room, spacing)
}

/// [`assert_valid`] with the room of each sheet: `room(k)` for sheet k.
fn assert_valid_on(
    job: &NestJob,
    n: &Nest,
    room: &dyn Fn(usize) -> (f64, f64, f64, f64),
    spacing: f64,
) {
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
    for (k, (sheet, o)) in outlines.iter().enumerate() {
        let room = room(*sheet);
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
                // Apart: one inside the other is the only way to overlap,
                // and is allowed only inside a hole, the spacing from it.
                if inside(b, a[0]) {
                    assert_in_a_hole(job, n, j, a, spacing - slack);
                }
                if inside(a, b[0]) {
                    assert_in_a_hole(job, n, i, b, spacing - slack);
                }
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

/// `guest` (an outline) lies in a hole of copy `host`, at least `least`
/// from the hole's boundary (then, apart from it and with a point inside,
/// it is wholly inside).
fn assert_in_a_hole(job: &NestJob, n: &Nest, host: usize, guest: &[Point], least: f64) {
    let p = &n.placements[host];
    let hole = job.parts[p.part]
        .holes
        .iter()
        .map(|h| placed_outline(h, p.rotation, p.mirror, p.translation))
        .find(|h| inside(h, guest[0]))
        .unwrap_or_else(|| panic!("a copy lies on copy {host}'s material, in none of its holes"));
    let d = boundary_distance(&hole, guest);
    assert!(
        d >= least,
        "a copy in a hole of copy {host} is {d} from the hole, least {least}"
    );
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
        budget_s: None,
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
        let paths = kerfcam::kerf::offset(&c, settings.kerf(), settings.tolerance());
        let input = kerfcam::plan::PlanInput {
            file: kerfcam::plan::FileOrder::of(&drawing),
            contours: &c,
            kerf: &paths,
            tolerance: settings.tolerance().mm(),
            process: settings.process(),
        };
        let program = kerfcam::gcode::emit(
            &kerfcam::plan::plan(&input, settings.plan()),
            settings.decimals(),
            &settings.job(),
        );
        let errors = rs274_errors(&program, &format!("nest-fixtures-{k}"));
        assert!(errors.is_empty(), "sheet {k}: {errors:?}");
    }
}

#[test]
fn sheets_of_mixed_sizes_fill_in_the_order_given_each_holding_the_rules() {
    // Six plates (about 250 × 130 mm each, 3 mm apart): one 300 × 300
    // sheet holds two; the 700 × 400 sheets after it the rest.
    let parts = fixture_parts("seed000-plate-6-holes.dxf", 6);
    let sizes = [(300.0, 300.0, 1), (700.0, 400.0, 2)];
    let job = NestJob {
        parts,
        sheets: Sheets::Mixed(
            sizes
                .iter()
                .map(|&(width, height, count)| SheetSize {
                    width,
                    height,
                    count,
                })
                .collect(),
        ),
        settings: settings(3.0, 10.0),
    };
    let n = run(&job).unwrap();
    assert!(n.unplaced.is_empty(), "{:?}", n.unplaced);
    assert_eq!(n.placements.len(), 6);
    assert_eq!(n.sheets.len(), 2, "the first sheet and one big one");
    let size = |k: usize| {
        if k == 0 {
            (300.0, 300.0)
        } else {
            (700.0, 400.0)
        }
    };
    for (k, s) in n.sheets.iter().enumerate() {
        assert_eq!((s.width, s.height), size(k), "sheet {k}");
        assert!(s.parts > 0, "sheet {k} is used");
    }
    assert_valid_on(
        &job,
        &n,
        &|k| {
            let (w, h) = size(k);
            (10.0, 10.0, w - 10.0, h - 10.0)
        },
        3.0,
    );
    // The crop line is on the last (large) sheet, within its width.
    let crop = n.sheets[1].crop_x.expect("a remnant kept");
    assert!(crop < 700.0 - 10.0, "{crop}");
    assert!(n.sheets[0].crop_x.is_none());
    // A nest on sheets of one size is the same kind as before (one entry
    // of the list is a Rect).
    assert!(matches!(
        Sheets::rects(vec![SheetSize {
            width: 1.0,
            height: 2.0,
            count: 3
        }]),
        Sheets::Rect { count: 3, .. }
    ));
    // A list with a size that is no size, or a count of 0, is refused.
    for bad in [(0.0, 300.0, 1), (300.0, 300.0, 0)] {
        let mut j = job.clone();
        j.sheets = Sheets::Mixed(vec![
            SheetSize {
                width: 500.0,
                height: 500.0,
                count: 1,
            },
            SheetSize {
                width: bad.0,
                height: bad.1,
                count: bad.2,
            },
        ]);
        assert!(
            matches!(run(&j), Err(NestError::Setting { field: "sheet", .. })),
            "{bad:?}"
        );
    }
}

#[test]
fn free_rotation_lays_a_part_drawn_at_an_odd_angle_flat_and_holds_the_rules() {
    // A 100 × 50 plate drawn turned by 10°: no step of 15° lays it flat,
    // free rotation does (−10°, from its hull's edges).
    let (sn, cs) = 10f64.to_radians().sin_cos();
    let plate: Vec<Point> = [(0.0, 0.0), (100.0, 0.0), (100.0, 50.0), (0.0, 50.0)]
        .iter()
        .map(|&(x, y)| Point::new(cs * x - sn * y, sn * x + cs * y))
        .collect();
    let outer: Vec<Segment> = (0..4)
        .map(|i| Segment::line(plate[i], plate[(i + 1) % 4]))
        .collect();
    let nest_with = |rotations: Rotations| {
        let job = NestJob {
            parts: vec![Part {
                name: "plate".into(),
                outer: outer.clone(),
                holes: Vec::new(),
                quantity: 8,
                rotations,
                mirror: false,
            }],
            sheets: Sheets::Strip { height: 110.0 },
            settings: settings(2.5, 0.0),
        };
        let n = run(&job).unwrap();
        assert_eq!(n.placements.len(), 8);
        assert_valid(&job, &n, (0.0, 0.0, f64::INFINITY, 110.0), 2.5);
        n
    };
    let free = nest_with(Rotations::Free);
    let steps = nest_with(Rotations::Steps(24));
    let (lf, ls) = (free.strip_length.unwrap(), steps.strip_length.unwrap());
    // Flat: eight standing (8 × 52.5 less a spacing) or two rows of four
    // lying (4 × 102.5 less one); tilted 5° at best, each plate's box is
    // 9 mm wider or taller.
    assert!(lf < 418.0, "free rotation: {lf} (24 steps: {ls})");
    assert!(lf < ls - 10.0, "free {lf} against 24 steps {ls}");
    assert!(
        free.placements.iter().all(|p| ((p.rotation + 10.0) / 90.0
            - ((p.rotation + 10.0) / 90.0).round())
        .abs()
            < 1e-9),
        "{:?}",
        free.placements
            .iter()
            .map(|p| p.rotation)
            .collect::<Vec<_>>()
    );
}

#[test]
fn free_rotation_turns_a_copy_to_an_angle_outside_the_set_tried_when_that_packs_tighter() {
    // A 100 × 5 bar and a 4 × 4 square on a strip 60 high. Of the turns
    // tried (15° steps and the bar's own edges) 30° is the shortest that
    // fits (45° is 74 high): 89.1 mm long, the square in a corner. At
    // about 33.6° the bar just fits the height and takes 85.5 mm: only a
    // copy turned to an angle outside the set gets there.
    let bar = rect("bar", 100.0, 5.0, 1);
    let set = Rotations::Free.angles_for(&bar.outer, false);
    let nest_with = |rotations: Rotations| {
        let job = NestJob {
            parts: vec![
                Part {
                    rotations: rotations.clone(),
                    ..bar.clone()
                },
                Part {
                    rotations,
                    ..rect("square", 4.0, 4.0, 1)
                },
            ],
            sheets: Sheets::Strip { height: 60.0 },
            settings: NestSettings {
                max_evaluations: Some(20_000),
                ..settings(0.2, 0.0)
            },
        };
        let n = run(&job).unwrap();
        assert_eq!(n.placements.len(), 2);
        assert_valid(&job, &n, (0.0, 0.0, f64::INFINITY, 60.0), 0.2);
        n
    };
    let free = nest_with(Rotations::Free);
    let fixed = nest_with(Rotations::List(set.clone()));
    let (lf, ls) = (free.strip_length.unwrap(), fixed.strip_length.unwrap());
    let angles: Vec<f64> = free.placements.iter().map(|p| p.rotation).collect();
    let off_set = |a: f64| {
        set.iter()
            .all(|&b| ((a - b + 180.0).rem_euclid(360.0) - 180.0).abs() > 0.05)
    };
    assert!(lf < ls - 2.0, "free {lf} ({angles:?}) against the set {ls}");
    assert!(
        angles.iter().any(|&a| off_set(a)),
        "{angles:?} all in {set:?}"
    );
    // The same seed and budget, the same nest.
    assert_eq!(nest_with(Rotations::Free).placements, free.placements);
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
    // The crop line on REMNANT, the last sheet only, straight across.
    let remnant = d
        .layers
        .iter()
        .position(|l| l.name == "REMNANT")
        .map(|i| i as u32);
    let crops: Vec<_> = d
        .entities
        .iter()
        .filter(|e| Some(e.layer) == remnant)
        .collect();
    assert_eq!(
        crops.len(),
        usize::from(n.sheets.last().unwrap().crop_x.is_some())
    );
    for c in &crops {
        let s = c.segments[0];
        assert!(!c.closed && s.a.x == s.b.x && (s.a.y - s.b.y).abs() == 300.0);
    }
    // 6 copies × (outer + 6 holes), arcs kept as arcs.
    let parts: Vec<_> = d
        .entities
        .iter()
        .filter(|e| e.layer != sheet && Some(e.layer) != remnant)
        .collect();
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
        big.reason.en.contains("larger than the sheet"),
        "{}",
        big.reason
    );
    assert!(n
        .unplaced
        .iter()
        .any(|u| u.part == "none" && u.reason.en.contains("quantity 0")));
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
        n.unplaced[0].copies == 2 && n.unplaced[0].reason.en.contains("no room"),
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
        notes[0]
            .reason
            .en
            .contains("open contour(s) left out: not nestable"),
        "{}",
        notes[0].reason
    );
    // Both copies of the square are nested: the note is of contours, and counts no copy.
    assert_eq!(notes[0].copies, 0);
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
        .all(|w| w[1].evaluations >= w[0].evaluations));
    // The first report comes while the first nest is being placed (8 of
    // its 10 copies); once whole, the nests reported only get shorter.
    assert_eq!((seen[0].evaluations, seen[0].unplaced), (8, 2));
    let whole: Vec<_> = seen.iter().filter(|p| p.unplaced == 0).collect();
    assert_eq!(whole.len(), 2);
    assert!(whole.windows(2).all(|w| w[1].length <= w[0].length));
    assert_eq!(n.placements.len(), 10);
    let len = n.strip_length.unwrap();
    assert!(
        len <= whole[0].length + 1e-9,
        "the nest returned is no worse than the first"
    );
    assert_valid(&job, &n, (0.0, 0.0, len, 120.0), 2.0);
}

fn square_loop(x0: f64, y0: f64, side: f64) -> Vec<Segment> {
    let c = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)]
        .map(|(x, y)| Point::new(x0 + x, y0 + y));
    (0..4)
        .map(|i| Segment::line(c[i], c[(i + 1) % 4]))
        .collect()
}

/// A 200 × 200 plate with a round hole r = 70 at its centre, and small
/// squares: the squares go in the hole first.
fn ring_job(squares: usize, spacing: f64) -> NestJob {
    let hole =
        kerfcam::geom::arc_pieces(Point::new(100.0, 100.0), 70.0, 0.0, std::f64::consts::TAU);
    let host = Part {
        name: "ring".into(),
        outer: square_loop(0.0, 0.0, 200.0),
        holes: vec![hole],
        quantity: 1,
        rotations: Rotations::Quarter,
        mirror: false,
    };
    let mut small = rect("small", 35.0, 35.0, squares);
    small.rotations = Rotations::Steps(8);
    NestJob {
        parts: vec![host, small],
        sheets: Sheets::Rect {
            width: 600.0,
            height: 300.0,
            count: 1,
        },
        settings: settings(spacing, 5.0),
    }
}

/// Where (100, 100) of a part goes: the ring's hole centre, turned about
/// the part's origin with the plate.
fn ring_centre(n: &Nest) -> Point {
    let p = n.placements.iter().find(|p| p.part == 0).unwrap();
    let (sn, cs) = p.rotation.to_radians().sin_cos();
    Point::new(
        p.translation.x + cs * 100.0 - sn * 100.0,
        p.translation.y + sn * 100.0 + cs * 100.0,
    )
}

/// The centre of a placed 35 × 35 square.
fn square_mid(p: &nest::Placement) -> Point {
    let (sn, cs) = p.rotation.to_radians().sin_cos();
    Point::new(
        p.translation.x + cs * 17.5 - sn * 17.5,
        p.translation.y + sn * 17.5 + cs * 17.5,
    )
}

#[test]
fn small_parts_go_inside_a_hole_the_spacing_from_it() {
    let job = ring_job(6, 2.5);
    let n = run(&job).unwrap();
    assert!(n.unplaced.is_empty(), "{:?}", n.unplaced);
    let guests: Vec<_> = n
        .placements
        .iter()
        .filter(|p| p.in_hole_of.is_some())
        .collect();
    assert!(guests.len() >= 2, "{} in the hole", guests.len());
    for g in &guests {
        assert_eq!(g.in_hole_of, Some((0, 0)));
        assert_eq!(g.sheet, 0);
    }
    // The independent check finds them inside the hole, ≥ spacing from it.
    assert_valid(&job, &n, (5.0, 5.0, 595.0, 295.0), 2.5);
    // And it would catch a guest too near the hole's edge: move one 3 mm
    // towards it.
    let mut bad = n.clone();
    let k = bad
        .placements
        .iter()
        .position(|p| p.in_hole_of.is_some())
        .unwrap();
    let away = square_mid(&bad.placements[k]).sub(ring_centre(&n));
    let t = &mut bad.placements[k].translation;
    let l = away.x.hypot(away.y).max(1e-9);
    *t = Point::new(t.x + 3.0 * away.x / l, t.y + 3.0 * away.y / l);
    let caught =
        std::panic::catch_unwind(|| assert_valid(&job, &bad, (5.0, 5.0, 595.0, 295.0), 2.5));
    assert!(
        caught.is_err(),
        "the check missed a guest 3 mm nearer the hole's edge"
    );
}

/// The cuts of a program as rs274 runs it: the feed end points between
/// each torch on and torch off.
fn rs274_cuts(text: &str) -> Vec<Vec<Point>> {
    let mut cuts = Vec::new();
    let mut cur: Option<Vec<Point>> = None;
    let num = |l: &str| -> Option<(f64, f64)> {
        let args = l.split_once('(')?.1;
        let mut it = args
            .split(',')
            .map(|v| v.trim().trim_end_matches(')').parse::<f64>());
        Some((it.next()?.ok()?, it.next()?.ok()?))
    };
    for l in text.lines() {
        if l.contains("START_SPINDLE") {
            cur = Some(Vec::new());
        } else if l.contains("STOP_SPINDLE") {
            if let Some(c) = cur.take() {
                cuts.push(c);
            }
        } else if let Some(c) = cur.as_mut() {
            if l.contains("STRAIGHT_FEED") || l.contains("ARC_FEED") {
                if let Some((x, y)) = num(l) {
                    c.push(Point::new(x, y));
                }
            }
        }
    }
    cuts
}

#[test]
fn a_part_in_a_hole_is_cut_before_the_hole_and_the_crop_line_last() {
    let job = ring_job(6, 2.5);
    let n = run(&job).unwrap();
    let settings = kerfcam::Settings::new(1.5, 0.001, 2000.0).unwrap();
    let out = kerfcam::nest_cut::cut_sheet(&job, &n, 0, &settings).unwrap();
    let text = common::rs274_output(&out.gcode, "nest-part-in-part").unwrap_or_default();
    if text.is_empty() {
        return; // rs274 missing and KERFCAM_NO_RS274=1: said by rs274_output.
    }
    assert!(common::rs274_error_lines(&text).is_empty(), "{text}");
    let cuts = rs274_cuts(&text);
    assert!(!cuts.is_empty(), "{text}");
    let centre = ring_centre(&n);
    // The hole's cut: most of its points on the circle r = 70 − kerf/2.
    let on_hole = |c: &Vec<Point>| {
        let near = c
            .iter()
            .filter(|p| (p.dist(centre) - 69.25).abs() < 0.3)
            .count();
        near * 10 >= c.len() * 8
    };
    let hole = cuts.iter().position(on_hole).expect("the hole's cut");
    assert!(n.placements.iter().any(|p| p.in_hole_of.is_some()));
    for g in n.placements.iter().filter(|p| p.in_hole_of.is_some()) {
        let mid = square_mid(g);
        let k = cuts
            .iter()
            .position(|c| c.iter().all(|p| p.dist(mid) < 35.0))
            .expect("the guest's cut");
        assert!(
            k < hole,
            "a part in the hole is cut (cut {k}) after the hole (cut {hole})"
        );
    }
    // The crop line: the last cut, pierced on the sheet's top edge, straight down.
    let x = n.sheets[0].crop_x.expect("a remnant is kept");
    let last = cuts.last().unwrap();
    assert!(last.iter().all(|p| (p.x - x).abs() < 1e-3), "{last:?}");
    assert!((last.last().unwrap().y - 0.0).abs() < 1e-3);
    assert!(text
        .lines()
        .rev()
        .find(|l| l.contains("STRAIGHT_TRAVERSE"))
        .is_some_and(|l| l.contains(&format!("{x:.4}, 300.0000"))));
}

fn poly_dxf(loops: &[(&str, Vec<Point>)], circles: &[(Point, f64)]) -> String {
    let mut s = String::from("0\nSECTION\n2\nENTITIES\n");
    for (layer, pts) in loops {
        s += &format!("0\nLWPOLYLINE\n8\n{layer}\n90\n{}\n70\n1\n", pts.len());
        for p in pts {
            s += &format!("10\n{}\n20\n{}\n", p.x, p.y);
        }
    }
    for (c, r) in circles {
        s += &format!("0\nCIRCLE\n8\n0\n10\n{}\n20\n{}\n40\n{r}\n", c.x, c.y);
    }
    s + "0\nENDSEC\n0\nEOF\n"
}

fn pts(v: &[(f64, f64)]) -> Vec<Point> {
    v.iter().map(|&(x, y)| Point::new(x, y)).collect()
}

fn kerfcam_nest(args: &[&str]) -> (bool, String, String) {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_kerfcam"))
        .arg("nest")
        .args(args)
        .output()
        .unwrap();
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn the_cli_reports_parts_in_holes_writes_the_remnant_and_nests_on_it_again() {
    let dir = common::out_dir();
    let ring = dir.join("nest-ring.dxf");
    let small = dir.join("nest-small.dxf");
    let rem = dir.join("nest-remnant.dxf");
    let ngc = dir.join("nest-ring.ngc");
    let _ = std::fs::remove_file(&rem);
    std::fs::write(
        &ring,
        poly_dxf(
            &[(
                "0",
                pts(&[(0.0, 0.0), (200.0, 0.0), (200.0, 200.0), (0.0, 200.0)]),
            )],
            &[(Point::new(100.0, 100.0), 70.0)],
        ),
    )
    .unwrap();
    std::fs::write(
        &small,
        poly_dxf(
            &[(
                "0",
                pts(&[(0.0, 0.0), (35.0, 0.0), (35.0, 35.0), (0.0, 35.0)]),
            )],
            &[],
        ),
    )
    .unwrap();
    let small_q = format!("{}:6", small.display());
    let (ok, out, err) = kerfcam_nest(&[
        ring.to_str().unwrap(),
        &small_q,
        "--sheet",
        "1000x300",
        "--time",
        "0",
        "--json",
        "--remnant",
        rem.to_str().unwrap(),
        "--gcode",
        ngc.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let guests: Vec<_> = j["placements"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| !p["in_hole_of"].is_null())
        .collect();
    assert!(!guests.is_empty(), "{out}");
    assert_eq!(guests[0]["in_hole_of"]["part"], "nest-ring");
    assert_eq!(guests[0]["in_hole_of"]["copy"], 0);
    let crop = j["sheets"][0]["crop_x"].as_f64().expect("a crop line");
    // Utilisation over the useful area (the sheet left of the crop line).
    let parts_area = 200.0 * 200.0 - std::f64::consts::PI * 4900.0 + 6.0 * 35.0 * 35.0;
    let u = j["sheets"][0]["utilisation"].as_f64().unwrap();
    assert!((u - parts_area / (crop * 300.0)).abs() < 1e-3 * u, "{u}");
    let program = std::fs::read_to_string(&ngc).unwrap();
    assert_eq!(
        rs274_errors(&program, "nest-ring-cli"),
        Vec::<String>::new()
    );
    // The remnant, given back as a sheet: parts go on it and only on it.
    let small_4 = format!("{}:4", small.display());
    let (ok, out, err) = kerfcam_nest(&[
        &small_4,
        "--sheet-dxf",
        rem.to_str().unwrap(),
        "--time",
        "0",
        "--margin",
        "5",
        "--json",
    ]);
    assert!(ok, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["placed"], 4, "{out}");
    for p in j["placements"].as_array().unwrap() {
        let x = p["translation"][0].as_f64().unwrap();
        // Every square turned by a multiple of 90° spans x..x ± 35.
        let r = p["rotation"].as_f64().unwrap();
        let left = if r == 90.0 || r == 180.0 { x - 35.0 } else { x };
        assert!(
            left >= crop + 5.0 - 1e-6,
            "a square at x = {left} is off the remnant (from {crop})"
        );
    }
}

#[test]
fn the_cli_takes_a_list_of_sheet_sizes_and_fills_them_in_order() {
    let dir = common::out_dir();
    let square = dir.join("nest-mixed-square.dxf");
    let ngc = dir.join("nest-mixed.ngc");
    std::fs::write(
        &square,
        poly_dxf(
            &[(
                "0",
                pts(&[(0.0, 0.0), (90.0, 0.0), (90.0, 90.0), (0.0, 90.0)]),
            )],
            &[],
        ),
    )
    .unwrap();
    // A 200 × 100 sheet holds two 90 mm squares (margin 2, spacing 2.5);
    // the five others go on the 400 × 300 sheets after it.
    let q = format!("{}:7", square.display());
    let (ok, out, err) = kerfcam_nest(&[
        &q,
        "--sheet",
        "200x100",
        "--sheet",
        "400x300:2",
        "--margin",
        "2",
        "--spacing",
        "2.5",
        "--time",
        "0",
        "--json",
        "--gcode",
        ngc.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["placed"], 7, "{out}");
    let sheets = j["sheets"].as_array().unwrap();
    assert_eq!(sheets.len(), 2, "{out}");
    assert_eq!(
        (&sheets[0]["width"], &sheets[0]["height"]),
        (&200.0.into(), &100.0.into())
    );
    assert_eq!(
        (&sheets[1]["width"], &sheets[1]["height"]),
        (&400.0.into(), &300.0.into())
    );
    assert_eq!(sheets[0]["parts"], 2, "{out}");
    // Every square lies on its own sheet, inside the margin.
    for p in j["placements"].as_array().unwrap() {
        let k = p["sheet"].as_u64().unwrap() as usize;
        let (w, h) = if k == 0 {
            (200.0, 100.0)
        } else {
            (400.0, 300.0)
        };
        let (x, y) = (
            p["translation"][0].as_f64().unwrap(),
            p["translation"][1].as_f64().unwrap(),
        );
        let r = p["rotation"].as_f64().unwrap().to_radians();
        for (u, v) in [(0.0, 0.0), (90.0, 0.0), (90.0, 90.0), (0.0, 90.0)] {
            let (px, py) = (x + u * r.cos() - v * r.sin(), y + u * r.sin() + v * r.cos());
            assert!(
                px >= 2.0 - 1e-6
                    && py >= 2.0 - 1e-6
                    && px <= w - 2.0 + 1e-6
                    && py <= h - 2.0 + 1e-6,
                "a square's corner at ({px}, {py}) is off sheet {k} ({w} × {h})"
            );
        }
    }
    // Each sheet cut: its program through rs274.
    for (k, path) in [(1, ngc.clone()), (2, dir.join("nest-mixed-2.ngc"))] {
        let program = std::fs::read_to_string(&path).unwrap();
        assert_eq!(
            rs274_errors(&program, &format!("nest-mixed-{k}")),
            Vec::<String>::new()
        );
    }
}

/// Issue 44 item 3, sheets at a cost: five 90 mm squares (92 mm apart at
/// spacing 2, margin 0) hold four to a 200 × 200 sheet (at 7) and one to
/// a 100 × 100 (at 2); b big and s small sheets hold them when
/// 4b + s ≥ 5, cheapest at one of each (9; five small cost 10, two big
/// 14). The report says the sheets used, their cost and the costs given.
#[test]
fn the_cli_takes_the_cheapest_sheets_when_each_size_has_a_cost() {
    let dir = common::out_dir();
    let square = dir.join("nest-cost-square.dxf");
    std::fs::write(
        &square,
        poly_dxf(
            &[(
                "0",
                pts(&[(0.0, 0.0), (90.0, 0.0), (90.0, 90.0), (0.0, 90.0)]),
            )],
            &[],
        ),
    )
    .unwrap();
    let q = format!("{}:5", square.display());
    let run = |big: &str| {
        kerfcam_nest(&[
            &q,
            "--sheet",
            big,
            "--sheet",
            "100x100:5:2",
            "--margin",
            "0",
            "--spacing",
            "2",
            "--evaluations",
            "160",
            "--time",
            "100",
            "--json",
        ])
    };
    let (ok, out, err) = run("200x200:2:7");
    assert!(ok, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["placed"], 5, "{out}");
    assert_eq!(j["sheet_cost"], 9.0, "{out}");
    let stock = j["stock"].as_array().unwrap();
    let row = |k: usize| {
        let s = &stock[k];
        (
            s["width"].as_f64(),
            s["in_stock"].as_u64(),
            s["cost"].as_f64(),
            s["used"].as_u64(),
        )
    };
    assert_eq!(row(0), (Some(200.0), Some(2), Some(7.0), Some(1)));
    assert_eq!(row(1), (Some(100.0), Some(5), Some(2.0), Some(1)));
    assert_eq!(j["sheets"].as_array().unwrap().len(), 2, "{out}");
    // A negative cost, or a cost for one size only: a clear error.
    let (ok, _, err) = run("200x200:2:-7");
    assert!(!ok);
    assert!(
        err.contains("the cost -7 of a 200 × 200 sheet is not a price ≥ 0"),
        "{err}"
    );
    let (ok, _, err) = run("200x200:2");
    assert!(!ok);
    assert!(
        err.contains("give a cost for every sheet size or for none"),
        "{err}"
    );
}

#[test]
fn a_remnant_sheet_keeps_parts_off_its_holes_and_defects() {
    // An L-shaped remnant with a round hole and a defect drawn on DEFECT.
    let l = pts(&[
        (0.0, 0.0),
        (400.0, 0.0),
        (400.0, 150.0),
        (150.0, 150.0),
        (150.0, 300.0),
        (0.0, 300.0),
    ]);
    let defect = pts(&[(200.0, 20.0), (260.0, 20.0), (260.0, 90.0), (200.0, 90.0)]);
    let text = poly_dxf(
        &[("0", l.clone()), ("DEFECT", defect.clone())],
        &[(Point::new(75.0, 75.0), 30.0)],
    );
    let d = dxf::parse(text.as_bytes(), &ReadOptions::DEFAULT).unwrap();
    let c = contour::extract(&d, Tolerance::DEFAULT, 0.05);
    let (sheets, notes) = nest::sheet_from_contours(&c).unwrap();
    assert!(notes.is_empty(), "{notes:?}");
    let Sheets::Remnant { ref no_go, .. } = sheets else {
        panic!("{sheets:?}")
    };
    assert_eq!(no_go.len(), 2);
    let job = NestJob {
        parts: vec![rect("tab", 40.0, 25.0, 14)],
        sheets,
        settings: settings(2.0, 4.0),
    };
    let n = run(&job).unwrap();
    assert!(
        n.placements.len() >= 10,
        "{} placed, {:?}",
        n.placements.len(),
        n.unplaced
    );
    let hole = placed_outline(
        &kerfcam::geom::arc_pieces(Point::new(75.0, 75.0), 30.0, 0.0, std::f64::consts::TAU),
        0.0,
        false,
        Point::new(0.0, 0.0),
    );
    for p in &n.placements {
        let o = placed_outline(&job.parts[0].outer, p.rotation, p.mirror, p.translation);
        assert!(
            inside(&l, o[0]) && boundary_distance(&o, &l) >= 4.0 - 1e-6,
            "{p:?}"
        );
        for z in [&defect, &hole] {
            assert!(!inside(z, o[0]) && !inside(&o, z[0]), "{p:?}");
            assert!(boundary_distance(&o, z) >= 4.0 - 1e-6, "{p:?}");
        }
    }
    assert_valid(&job, &n, (0.0, 0.0, 400.0, 300.0), 2.0);
    // The crop line crosses the L where it stands, and the sheet's
    // utilisation counts neither the hole, the defect nor the remnant.
    let s = &n.sheets[0];
    if let Some(x) = s.crop_x {
        let area = n.placements.len() as f64 * 1000.0;
        let hole_area = std::f64::consts::PI * 900.0;
        let (sheet_area, rem) = nest::remnant::areas(&job.sheets, Some(x), 0.05);
        assert!(sheet_area < 400.0 * 150.0 + 150.0 * 150.0 - 4200.0 - hole_area + 50.0);
        assert!((s.utilisation - area / (sheet_area - rem)).abs() < 1e-9);
    }
}

#[test]
fn on_a_strip_every_copy_of_a_many_vertex_part_is_placed_and_packed() {
    // 12 plates (arcs: ~48 vertices each) on a strip 600 high: when the
    // placer's best candidates were all taken, copies were said to find
    // "no room" on a strip that has no end.
    let job = NestJob {
        parts: fixture_parts("seed000-plate-6-holes.dxf", 12),
        sheets: Sheets::Strip { height: 600.0 },
        settings: NestSettings {
            // The first nest whole (one evaluation per copy placed).
            max_evaluations: Some(12),
            ..settings(0.0, 0.0)
        },
    };
    let n = run(&job).unwrap();
    assert!(n.unplaced.is_empty(), "{:?}", n.unplaced);
    assert_eq!(n.placements.len(), 12);
    assert!(n.density > 0.8, "{}", n.density);
    let len = n.strip_length.unwrap();
    assert_valid(&job, &n, (0.0, 0.0, len, 600.0), 0.0);
}

#[test]
fn a_remnant_with_no_room_inside_its_margin_lists_every_part_with_the_reason() {
    let outline = square_loop(0.0, 0.0, 100.0);
    let job = NestJob {
        parts: vec![rect("tab", 10.0, 10.0, 3)],
        sheets: Sheets::Remnant {
            outline,
            no_go: Vec::new(),
        },
        settings: settings(2.0, 60.0),
    };
    let n = run(&job).unwrap();
    assert!(n.placements.is_empty());
    assert_eq!(n.unplaced.len(), 1);
    assert_eq!(n.unplaced[0].copies, 3);
    assert!(
        n.unplaced[0].reason.en.contains("margin of 60"),
        "{:?}",
        n.unplaced
    );
    // A remnant outline with no area is a setting error, not a panic.
    let flat = NestJob {
        sheets: Sheets::Remnant {
            outline: vec![Segment::line(Point::new(0.0, 0.0), Point::new(10.0, 0.0))],
            no_go: Vec::new(),
        },
        ..job
    };
    assert!(matches!(run(&flat), Err(NestError::Setting { .. })));
}

/// Two plates with parts in their holes on a strip, given the budget of
/// the separation phase too: every part where the independent check wants
/// it, the guests still in their holes the spacing from them.
#[test]
fn plates_with_parts_in_their_holes_stay_valid_through_the_separation() {
    let mut job = ring_job(9, 2.5);
    job.parts[0].quantity = 2;
    job.sheets = Sheets::Strip { height: 260.0 };
    job.settings.margin = 0.0;
    job.settings.max_evaluations = Some(3000);
    let n = run(&job).unwrap();
    let len = n.strip_length.unwrap();
    assert!(n.unplaced.is_empty(), "{:?}", n.unplaced);
    assert_valid(&job, &n, (0.0, 0.0, len, 260.0), 2.5);
    let guests = n
        .placements
        .iter()
        .filter(|p| p.in_hole_of.is_some())
        .count();
    assert!(guests >= 2, "{guests} in holes");
}

/// ESICUP's fu, as the page's Stop runs it: a budget of `time_s`, no
/// evaluation count (the progress callback stops it), collision polygons
/// within a ten-thousandth of its 38-unit strip.
fn fu_without_a_count(time_s: f64) -> NestJob {
    let text = std::fs::read_to_string(shared().join("nesting").join("fu.json")).unwrap();
    let mut job = instance::read(&text, settings(0.0, 0.0)).unwrap().job;
    job.settings.tolerance = 38.0 * 1e-4;
    job.settings.max_evaluations = None;
    job.settings.time_s = time_s;
    job
}

/// The page stops a run by replaying it to the evaluations its progress
/// line last showed: a run stopped at evaluation E, whatever its clock,
/// and a run given E evaluations with a clock that stands still, are the
/// same nest (both phases switch on evaluations, never on the clock).
#[test]
fn a_run_stopped_at_an_evaluation_is_the_run_given_that_many() {
    let mut job = fu_without_a_count(1e9);
    // A clock that runs fast: every reading 1 ms later.
    let t = std::cell::Cell::new(0.0);
    let clock = || {
        t.set(t.get() + 1e-3);
        t.get()
    };
    let mut last = None;
    let stopped = nest::nest(&job, &clock, &mut |p| {
        let go_on = p.evaluations < 6_000;
        last = Some(p);
        go_on
    })
    .unwrap();
    let last = last.unwrap();
    // Past the sequence search (at most 5000 evaluations): in the separation.
    assert!(last.evaluations >= 6_000, "{last:?}");
    assert_eq!(stopped.evaluations, last.evaluations);
    job.settings.max_evaluations = Some(last.evaluations);
    let replay = run(&job).unwrap();
    assert_eq!(replay.placements, stopped.placements);
    assert_eq!(replay.evaluations, last.evaluations);
    let len = replay.strip_length.unwrap();
    assert!((len - last.length).abs() < 1e-9, "{len} vs {last:?}");
}

/// The page's Stop replays a run with 5 s more on the clock, so that the
/// clock never ends the replay before its count: the replay keeps the
/// run's budget (`budget_s`), out of which the sequence search's share
/// is sized, and is the same run. Without it the longer clock would give
/// the sequence search a larger share, and another nest. fu at a budget
/// of 10 ms on a clock that stands still: a share that ends the sequence
/// search early.
#[test]
fn a_replay_with_more_time_keeps_the_runs_budget_and_is_the_same_run() {
    let mut job = fu_without_a_count(0.01);
    let stopped = nest::nest(&job, &|| 0.0, &mut |p| p.evaluations < 6_000).unwrap();
    assert!(stopped.evaluations >= 6_000, "{}", stopped.evaluations);
    job.settings.max_evaluations = Some(stopped.evaluations);
    job.settings.time_s += 5.0;
    let longer = run(&job).unwrap();
    assert_ne!(longer.placements, stopped.placements);
    job.settings.budget_s = Some(0.01);
    let replay = run(&job).unwrap();
    assert_eq!(replay.placements, stopped.placements);
    assert_eq!(replay.evaluations, stopped.evaluations);
}

/// `kerfcam nest --gcode` takes every cutting option of the plain command
/// (one parser, one builder: issue 15 §5), and reads the parts with them.
#[test]
fn the_nest_command_takes_every_cutting_option() {
    let dir = common::out_dir();
    let part = dir.join("nest-options-part.dxf");
    let ngc = dir.join("nest-options.ngc");
    // A 2 × 1 inch plate with no $INSUNITS: read in inches when told.
    std::fs::write(
        &part,
        poly_dxf(
            &[("0", pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]))],
            &[],
        ),
    )
    .unwrap();
    let part_q = format!("{}:2", part.display());
    let (ok, out, err) = kerfcam_nest(&[
        &part_q,
        "--sheet",
        "500x300",
        "--time",
        "0",
        "--json",
        "--units",
        "in",
        "--post",
        "qtplasmac",
        "--lead",
        "arc",
        "--material-number",
        "7",
        "--gcode",
        ngc.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["placed"], 2, "{out}");
    let program = std::fs::read_to_string(&ngc).unwrap();
    // The post and the material number reached the sheet's program.
    assert!(program.contains("M190 P7"), "{program}");
    assert!(program.contains("M3 $0"), "{program}");
    // Read in inches: the plates (turned or not) reach past 25.4 mm
    // along the sheet (read in mm they would end before 7 mm).
    let used = j["sheets"][0]["used_length"].as_f64().unwrap();
    assert!(used > 25.4, "{out}");
    // A bad cutting option is refused by the builder, naming it.
    let (ok, _, err) = kerfcam_nest(&[
        &part_q, "--sheet", "500x300", "--time", "0", "--order", "spiral",
    ]);
    assert!(!ok);
    assert!(err.contains("--order: 'spiral'"), "{err}");
}
