//! kerfcam checks its own cut (issue 20 §9): the program, read back by the
//! backplot, has its kerf swept over the drawn parts. A compensated program
//! passes; one cut on the drawn lines is flagged; the report carries the
//! figures. Over the corpus the flagged files are listed with the reason.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::{fixture, kerf, run};
use kerfcam::contour::ContourKind;
use kerfcam::gcode::{backplot, BackplotMove};
use kerfcam::plan::{self, Cut, CutPlan, Order, Role, Step};
use kerfcam::Output;

/// The program's torch-on moves as a plan: one cut per torch-on run.
fn program_plan(gcode: &str) -> CutPlan {
    let mut cuts: Vec<Cut> = Vec::new();
    let mut open = false;
    for m in backplot(gcode).moves {
        match m.torch() {
            Some(true) => {
                let steps = m.segments().into_iter().map(|segment| Step {
                    segment,
                    role: Role::Contour,
                    contour: None,
                });
                if !open {
                    let first = m.segments()[0].a;
                    cuts.push(Cut {
                        pierce: first,
                        steps: Vec::new(),
                        contours: Vec::new(),
                        part: None,
                        kind: ContourKind::Open,
                        spot: false,
                        small_hole: false,
                        comp: None,
                    });
                    open = true;
                }
                if let Some(c) = cuts.last_mut() {
                    c.steps.extend(steps);
                }
            }
            _ => open = matches!(m, BackplotMove::Line { torch: true, .. }) && open,
        }
    }
    CutPlan {
        cuts,
        ..CutPlan::default()
    }
}

/// The program of `out` swept with a kerf of `width`.
fn verify_program(out: &Output, width: f64) -> plan::Verification {
    let process = kerfcam::process::Process {
        kerf: width,
        ..out.process
    };
    let input = plan::PlanInput {
        file: plan::FileOrder::of(&out.drawing),
        contours: &out.contours,
        kerf: &out.kerf,
        tolerance: 0.001,
        process: &process,
    };
    let plan = program_plan(&out.gcode);
    let one = plan::verify(&input, &plan, kerfcam::par::Threads::ONE);
    // The parts shared among threads: the same answer.
    let three = plan::verify(&input, &plan, kerfcam::par::Threads::new(3));
    assert_eq!(one, three);
    one
}

#[test]
fn a_compensated_program_passes_and_an_uncompensated_one_is_flagged() {
    let file = fixture("seed000-plate-6-holes.dxf");
    let good = run(&file, &kerf(2.0)).unwrap();
    let v = verify_program(&good, 2.0);
    // The program's grid (3 decimals) is the only difference from the plan.
    assert!(v.max_overcut_mm < 0.002, "{v:?}");
    assert!(v.overcut_mm2 < 0.5, "{v:?}");
    assert_eq!(v.parts_not_freed, 0, "{v:?}");
    // The same drawing cut on its lines (a kerf-0 program) on a 2 mm kerf
    // machine: half the kerf taken all round every contour.
    let bare = run(&file, &kerf(0.0)).unwrap();
    let v = verify_program(&bare, 2.0);
    assert!((v.max_overcut_mm - 1.0).abs() < 0.01, "{v:?}");
    // The heat map is the raster the area counts: every cell part
    // material (checked here by the drawing's own outline), at most the
    // deepest overcut deep, all within a kerf of a drawn line.
    assert_eq!(
        v.overcut_cells.len() as f64 * v.cell * v.cell,
        v.overcut_mm2,
        "{v:?}"
    );
    let near_line = |p: kerfcam::geom::Point| {
        bare.contours
            .contours
            .iter()
            .flat_map(|c| c.segments.iter())
            .any(|s| kerfcam::geom::dist_to_segment(p, s) <= 1.0 + v.cell)
    };
    assert!(v
        .overcut_cells
        .iter()
        .all(|&(p, d)| d > 0.0 && d <= v.max_overcut_mm + 1e-9 && near_line(p)));
    assert!(v.attached.is_empty());
    let outline: f64 = bare.contours.contours.iter().map(|c| c.length).sum();
    assert!(
        (v.overcut_mm2 - outline).abs() < 0.1 * outline,
        "{} vs {outline}",
        v.overcut_mm2
    );
    // A program missing its last cut (the outer contour): the part is not freed.
    let cut = good.gcode.rfind("M3 S1").unwrap();
    let end = good.gcode[cut..].find("M5").unwrap() + cut;
    let short = format!("{}{}", &good.gcode[..cut], &good.gcode[end + 2..]);
    let mut missing = good.clone();
    missing.gcode = short;
    let v = verify_program(&missing, 2.0);
    assert_eq!(v.parts_not_freed, 1);
    // Where it stays attached: points of its outline no cut reaches, all
    // round it (the whole outer contour is missing).
    let outer = good
        .contours
        .contours
        .iter()
        .find(|c| c.kind == kerfcam::contour::ContourKind::Outer)
        .unwrap();
    assert!(
        v.attached.len() as f64 >= outer.length / v.cell * 0.9,
        "{}",
        v.attached.len()
    );
    assert!(v.attached.iter().all(|&p| outer
        .segments
        .iter()
        .any(|s| kerfcam::geom::dist_to_segment(p, s) < 1e-6)));
}

#[test]
fn the_report_carries_the_verification_when_asked() {
    let file = fixture("seed000-plate-6-holes.dxf");
    let mut s = kerf(2.0).with_verify(true);
    let json =
        |s: &kerfcam::Settings| kerfcam::report::Report::new(&run(&file, s).unwrap()).to_json();
    let clean = json(&s);
    assert!(
        clean.contains(
            r#""verification":{"overcut_mm2":0.0,"parts_not_freed":0,"max_overcut_mm":0.0}"#
        ),
        "{clean}"
    );
    s = s.map_plan(|p| p.order = Order::Drawing).unwrap();
    let flagged = json(&s);
    assert!(flagged.contains("verify-overcut"), "{flagged}");
    assert!(!json(&kerf(2.0)).contains("verification"));
}

/// Every fixture with room between its parts is cut clean, every part
/// freed. The 3 × 2 grid's pieces share their edges (paper 003, no room for
/// a kerf): one contour at a time each kerf path runs on the neighbour's
/// edge (a whole kerf into it); the Eulerian order cuts each shared edge
/// once, on the line (half a kerf into each side). Both are flagged.
#[test]
fn every_fixture_program_is_clean() {
    let grid = fixture("seed003-grid-3x2.dxf");
    for (order, depth) in [(Order::Contour, 1.5), (Order::Eulerian, 0.75)] {
        let mut s = kerf(1.5).with_verify(true);
        s = s.map_plan(|p| p.order = order).unwrap();
        let v = run(&grid, &s).unwrap().verification.unwrap();
        assert!((v.max_overcut_mm - depth).abs() < 0.01, "{order:?} {v:?}");
        assert_eq!(v.parts_not_freed, 0, "{order:?} {v:?}");
    }
    for (file, width, order) in [
        ("seed000-plate-6-holes.dxf", 2.0, Order::Contour),
        ("seed000-figure1.dxf", 1.5, Order::Contour),
        ("seed001-P51703.dxf", 3.0, Order::Contour),
        ("seed002-figure4.dxf", 1.5, Order::Contour),
    ] {
        let mut s = kerf(width).with_verify(true);
        s = s.map_plan(|p| p.order = order).unwrap();
        let out = run(&fixture(file), &s).unwrap();
        let v = out.verification.unwrap();
        assert_eq!(v.overcut_mm2, 0.0, "{file}: {v:?}");
        assert_eq!(v.max_overcut_mm, 0.0, "{file}: {v:?}");
        assert_eq!(v.parts_not_freed, 0, "{file}: {v:?}");
    }
}

/// Every corpus file, contour order, 1.5 mm kerf: which the sweep flags,
/// with what the pipeline reported about it (printed; `--nocapture` to
/// read; the issue's closing note lists them by cause).
#[test]
fn the_corpus_is_verified() {
    let mut flagged = 0;
    let mut checked = 0;
    for common::CorpusRun { name, out, .. } in common::corpus_runs() {
        let Ok(out) = out else {
            continue;
        };
        checked += 1;
        let v = out.verification.clone().expect("asked for");
        if v.overcut_mm2 > 0.0 || v.max_overcut_mm > 0.0 || v.parts_not_freed > 0 {
            flagged += 1;
            let mut causes: Vec<&str> = out
                .warnings()
                .map(|w| w.code)
                .filter(|c| !c.starts_with("verify-"))
                .collect();
            causes.dedup();
            println!(
                "{name}: overcut {:.2} mm², up to {:.3} mm, {} part(s) not freed; reported: {causes:?}",
                v.overcut_mm2, v.max_overcut_mm, v.parts_not_freed
            );
            // The report says it too.
            assert!(
                out.warnings().any(|w| w.code.starts_with("verify-")),
                "{name}"
            );
        }
    }
    println!("{flagged} of {checked} corpus files flagged");
    assert!(checked >= 50, "{checked}");
}
