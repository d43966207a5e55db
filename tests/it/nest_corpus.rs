//! A production sheet of real parts (issue 16): 200 copies of parts from
//! ten corpus files (AutoCAD, FreeCAD, SolidWorks, OpenBuilds, ezdxf, …;
//! inch files read as their header says), nested on 3000 × 1500 sheets,
//! every copy placed, counts exact, spacing and margin held — checked by
//! sampling (`common::sampled`), not by the engine's collision code — and
//! the first sheet cut into a program LinuxCNC accepts.
//!
//! Measured on the 2-core machine while other work ran (release): the
//! first nest of the 200 copies took 51 s of CPU before the collision
//! tests were limited to the boxes' overlap, 14 s after.

use crate::common;

use common::sampled::{bounds, nest_faults, Copy};
use common::{rs274_errors, shared};
use kerfcam::contour;
use kerfcam::dxf::{self, ReadOptions};
use kerfcam::geom::Tolerance;
use kerfcam::nest::{self, output, NestJob, NestSettings, Part, Sheets};

const PARTS: [(&str, usize); 10] = [
    ("cadquery/1001.dxf", 20),
    ("cadquery/vslot-2020_1.dxf", 40),
    ("openbuilds-cam/Motor NEMA23 - Sliding Mount.dxf", 4),
    ("dxf2gcode-plasma/SchlittenBack.dxf", 11),
    ("ezdxf/forms.dxf", 2),
    ("maslow-mechanics/ExtraBrackets.DXF", 10),
    ("sofle/sofle_pico_key_plate_v3.5.5.dxf", 3),
    ("dxf2gcode-plasma/1997.DXF", 5),
    ("voron2/Bottom_Panel_350^3_Rev2.DXF", 2),
    ("dxf2gcode-plasma/fc_mounting.dxf", 1),
];

fn parts() -> Vec<Part> {
    let mut parts = Vec::new();
    for (file, qty) in PARTS {
        let bytes = std::fs::read(shared().join("corpus").join(file)).unwrap();
        let d = dxf::parse(&bytes, &ReadOptions::DEFAULT).unwrap();
        let c = contour::extract(&d, Tolerance::DEFAULT, 0.05);
        let (p, _) = nest::parts_from_contours(&c, file, qty);
        assert!(!p.is_empty(), "{file}");
        parts.extend(p);
    }
    parts
}

#[test]
fn two_hundred_corpus_copies_nest_validly_and_cut() {
    let parts = parts();
    let asked: usize = parts.iter().map(|p| p.quantity).sum();
    assert_eq!(asked, 200);
    let job = NestJob {
        parts,
        sheets: Sheets::Rect {
            width: 3000.0,
            height: 1500.0,
            count: 3,
        },
        settings: NestSettings {
            spacing: 2.5,
            margin: 10.0,
            tolerance: 0.05,
            time_s: 1e9,
            seed: 1,
            // The first nest whole (one evaluation per copy placed): what
            // is checked here is validity, not density.
            max_evaluations: Some(200),
            budget_s: None,
        },
    };
    let n = nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
    assert!(n.unplaced.is_empty(), "{:?}", n.unplaced);
    assert_eq!(n.placements.len(), 200);
    for (i, p) in job.parts.iter().enumerate() {
        let copies: Vec<_> = n.placements.iter().filter(|q| q.part == i).collect();
        assert_eq!(copies.len(), p.quantity, "{}", p.name);
        let mut seen: Vec<usize> = copies.iter().map(|q| q.copy).collect();
        seen.sort_unstable();
        assert_eq!(seen, (0..p.quantity).collect::<Vec<_>>(), "{}", p.name);
    }
    for k in 0..n.sheets.len() {
        let copies: Vec<Copy> = n
            .placements
            .iter()
            .filter(|p| p.sheet == k)
            .map(|p| Copy::new(&output::placed_loops(&job, p)))
            .collect();
        for c in &copies {
            let (x0, y0, x1, y1) = bounds(&c.outer);
            assert!(x0 >= 10.0 - 0.01 && y0 >= 10.0 - 0.01, "{x0} {y0}");
            assert!(x1 <= 2990.0 + 0.01 && y1 <= 1490.0 + 0.01, "{x1} {y1}");
        }
        let faults = nest_faults(&copies, 2.5, 0.01);
        assert!(faults.is_empty(), "sheet {k}: {faults:?}");
    }
    // The check itself fails a copy moved onto another.
    let mut moved = n.placements[..2].to_vec();
    moved[1].translation = moved[0].translation;
    let stacked: Vec<Copy> = moved
        .iter()
        .map(|p| Copy::new(&output::placed_loops(&job, p)))
        .collect();
    assert!(!nest_faults(&stacked, 2.5, 0.01).is_empty());
    let settings = kerfcam::Settings::new(1.5, 0.001, 2000.0).unwrap();
    let out = kerfcam::nest_cut::cut_sheet(&job, &n, 0, &settings).unwrap();
    let errors = rs274_errors(&out.gcode, "nest-corpus-200");
    assert!(errors.is_empty(), "{errors:?}");
}

/// The sampled check itself: squares 10 mm across, 1.5 mm apart at a
/// spacing of 2 mm, then one 3 mm into the other, then 2.5 mm apart, and a
/// small square in a ring's hole touching nothing: the first two are
/// faults (too close, overlapping), the others are not.
#[test]
fn the_sampled_check_sees_copies_too_close_and_overlapping() {
    use kerfcam::geom::{Point, Segment};
    let square = |x: f64, y: f64, side: f64| {
        let p = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)].map(|(a, b)| Point::new(x + a, y + b));
        (0..4).map(|i| Segment::line(p[i], p[(i + 1) % 4])).collect::<Vec<_>>()
    };
    let faults = |a: Vec<Vec<Segment>>, b: Vec<Vec<Segment>>| nest_faults(&[Copy::new(&a), Copy::new(&b)], 2.0, 0.01);
    let close = faults(vec![square(0.0, 0.0, 10.0)], vec![square(11.5, 0.0, 10.0)]);
    assert!(close.iter().any(|f| f.contains("1.500 mm apart")), "{close:?}");
    let into = faults(vec![square(0.0, 0.0, 10.0)], vec![square(7.0, 2.0, 10.0)]);
    assert!(into.iter().any(|f| f.contains("overlap")), "{into:?}");
    assert!(faults(vec![square(0.0, 0.0, 10.0)], vec![square(12.5, 0.0, 10.0)]).is_empty());
    let ring = vec![square(0.0, 0.0, 30.0), square(5.0, 5.0, 20.0)];
    assert!(faults(ring, vec![square(10.0, 10.0, 10.0)]).is_empty());
}
