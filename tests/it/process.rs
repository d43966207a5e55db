//! Process technology (issue 20): operations per layer, small holes, the
//! QtPlasmaC and Z posts — each program checked by LinuxCNC's `rs274`.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use std::process::Command;

use common::{out_dir, rs274_errors, rs274_qtplasmac};
use kerfcam::gcode::preset;
use kerfcam::geom::Point;
use kerfcam::origin::ProgramOrigin;
use kerfcam::plan::{Order, Role};
use kerfcam::process::SmallHole;
use kerfcam::{Output, Settings};
use std::f64::consts::PI;

fn lwpoly(layer: &str, pts: &[(f64, f64)]) -> String {
    let mut s = format!("0\nLWPOLYLINE\n8\n{layer}\n90\n{}\n70\n1\n", pts.len());
    for (x, y) in pts {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s
}
fn circle(layer: &str, x: f64, y: f64, r: f64) -> String {
    format!("0\nCIRCLE\n8\n{layer}\n10\n{x}\n20\n{y}\n40\n{r}\n")
}
fn line(layer: &str, a: (f64, f64), b: (f64, f64)) -> String {
    format!(
        "0\nLINE\n8\n{layer}\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
        a.0, a.1, b.0, b.1
    )
}
fn dxf(body: &str) -> Vec<u8> {
    format!("0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n").into_bytes()
}

/// A 200 × 100 plate with a 10 mm hole and a 1 mm hole; a scribed line and
/// a scribed circle round the hole (MARK), a drill spot (SPOT, a 2 mm
/// circle), and a dimension line (DIM).
fn plate() -> Vec<u8> {
    dxf(&[
        lwpoly(
            "CUT",
            &[(0.0, 0.0), (200.0, 0.0), (200.0, 100.0), (0.0, 100.0)],
        ),
        circle("CUT", 50.0, 50.0, 5.0),
        circle("CUT", 150.0, 50.0, 0.5),
        line("MARK", (20.0, 80.0), (80.0, 80.0)),
        circle("MARK", 50.0, 50.0, 20.0),
        circle("SPOT", 120.0, 20.0, 1.0),
        line("DIM", (0.0, -10.0), (200.0, -10.0)),
    ]
    .concat())
}

fn settings(feed: f64) -> Settings {
    Settings::new(1.5, 0.001, feed)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .unwrap()
}

fn with_post(s: Settings, name: &str) -> Settings {
    s.with_post(preset(name).unwrap()).unwrap()
}

fn run(bytes: &[u8], s: &Settings) -> Output {
    kerfcam::run(bytes, s).unwrap()
}

#[test]
fn marks_are_scribed_on_the_line_before_any_cut_with_their_own_codes() {
    let out = run(&plate(), &with_post(settings(2000.0), "qtplasmac"));
    let plan = &out.plan;
    // Marks and spots first, then cuts.
    let first_cut = plan
        .cuts
        .iter()
        .position(|c| !c.spot && !c.is_mark())
        .unwrap();
    assert!(first_cut >= 3, "{first_cut}");
    assert!(plan.cuts[first_cut..]
        .iter()
        .all(|c| !c.is_mark() && c.steps.iter().all(|s| s.role != Role::Mark)));
    let marks: Vec<_> = plan.cuts.iter().filter(|c| c.is_mark()).collect();
    assert_eq!(marks.len(), 2);
    // On the drawn line: the scribed line's ends are the drawn ends, no kerf.
    let scribe = marks.iter().find(|c| c.steps.len() == 1).unwrap();
    let ends = [scribe.pierce, scribe.end()];
    assert!(ends.contains(&Point::new(20.0, 80.0)) && ends.contains(&Point::new(80.0, 80.0)));
    // The scribed circle is no hole of the part: one part, two holes.
    let kinds = |k| out.contours.contours.iter().filter(|c| c.kind == k).count();
    assert_eq!(kinds(kerfcam::contour::ContourKind::Outer), 1);
    assert_eq!(kinds(kerfcam::contour::ContourKind::Hole), 2);
    // The spot layer's circle is spotted at its centre.
    assert!(plan.cuts[..first_cut]
        .iter()
        .any(|c| c.spot && c.pierce.dist(Point::new(120.0, 20.0)) < 1e-9));
    // The DIM layer is reported, not cut.
    assert!(out
        .warnings()
        .any(|w| w.code == "layer-ignored" && w.message().contains("'DIM'")));
    assert!(out.contours.contours.iter().all(|c| &*c.layer != "DIM"));
    // Own codes: scribe M3 $1 before the first torch M3 $0; spot M3 $2.
    let g = &out.gcode;
    let (scribe_at, torch_at) = (g.find("M3 $1 S1").unwrap(), g.find("M3 $0 S1").unwrap());
    assert!(scribe_at < torch_at);
    assert_eq!(g.matches("M3 $1 S1").count(), 2);
    assert_eq!(g.matches("M5 $1").count(), 2);
    assert_eq!(g.matches("M3 $2 S1").count(), 1);
    assert!(g.find("M3 $2 S1").unwrap() < torch_at);
    let errors = rs274_qtplasmac(g, "process-marks-qtplasmac");
    assert!(errors.is_empty(), "{errors:?}");
    // The plain post: marks with the torch codes, on the line, first.
    let plain = run(&plate(), &settings(2000.0));
    let errors = rs274_errors(&plain.gcode, "process-marks-linuxcnc");
    assert!(errors.is_empty(), "{errors:?}");
    assert!(plain.gcode.contains("mark contour"));
    // The report names the marks' moves.
    let json = kerfcam::report::Report::new(&plain).to_json();
    assert!(json.contains("\"mark_length\":"), "{json}");
    // Every layer cut when asked: the MARK circle becomes a hole again.
    let mut ops = kerfcam::process::LayerOps::new();
    ops.by_name = false;
    let all = run(&plate(), &settings(2000.0).with_layer_ops(ops));
    assert!(all.plan.cuts.iter().all(|c| !c.is_mark()));
}

#[test]
fn a_small_hole_is_slow_entered_from_its_centre_overcut_and_height_locked() {
    // 6 mm plate, small holes below 12 mm (2 × thickness) at 60 %.
    let rule = SmallHole {
        diameter: 12.0,
        ..SmallHole::OFF
    };
    let s = settings(1500.0).with_small_hole(rule).unwrap();
    let out = run(&plate(), &s);
    let holes: Vec<_> = out.plan.cuts.iter().filter(|c| c.small_hole).collect();
    assert_eq!(holes.len(), 1);
    let h = holes[0];
    assert_eq!(h.pierce, Point::new(50.0, 50.0));
    // After the lead-in every move stays on the hole's kerf path (radius
    // 5 − 0.75): an overcut along it, no lead-out away from it.
    let r = 5.0 - 0.75;
    let on = |p: Point| (p.dist(Point::new(50.0, 50.0)) - r).abs() < 1e-6;
    assert_eq!(h.steps[0].role, Role::LeadIn);
    assert!(h.steps[1..]
        .iter()
        .all(|s| on(s.segment.a) && on(s.segment.b)));
    let over: f64 = h
        .steps
        .iter()
        .filter(|s| s.role == Role::LeadOut)
        .map(|s| s.segment.length())
        .sum();
    assert!((over - SmallHole::OFF.overcut).abs() < 1e-6, "{over}");
    // The time counts the hole at 900 mm/min, as the program cuts it: the
    // estimate grows by its feed length × (1/900 − 1/1500) minutes.
    let slow: f64 = h.steps.iter().map(|s| s.segment.length()).sum();
    let t = *s.process();
    let full = kerfcam::process::Process {
        small_hole: SmallHole {
            speed_pct: 100.0,
            ..t.small_hole
        },
        ..t
    };
    let extra = out.plan.est_time_s(&t) - out.plan.est_time_s(&full);
    let want = 60.0 * slow * (1.0 / 900.0 - 1.0 / 1500.0);
    assert!((extra - want).abs() < 1e-9, "{extra} vs {want}");
    // The 1 mm hole is below the kerf: spotted, and said.
    assert!(out
        .plan
        .cuts
        .iter()
        .any(|c| c.spot && c.pierce.dist(Point::new(150.0, 50.0)) < 1e-9));
    assert!(out.warnings().any(|w| w.code == "holes-spotted"));
    // Plain LinuxCNC: F900 in the hole, F1500 again after it.
    let g = &out.gcode;
    let pierce = g.find("G0 X50 Y50\n").expect(g);
    assert!(
        g[pierce..].contains("small hole contour 2)\nM3 S1\nF900\nG1 "),
        "{g}"
    );
    let back = g[pierce..].find("F1500\nM5").unwrap();
    assert!(!g[pierce..pierce + back].contains("F1500"));
    assert_eq!(g.matches("F900").count(), 1);
    let errors = rs274_errors(g, "process-small-hole-linuxcnc");
    assert!(errors.is_empty(), "{errors:?}");
    // QtPlasmaC: velocity 60 % and the THC locked (synchronised) in the
    // hole; released after the torch is off.
    let q = run(&plate(), &with_post(s, "qtplasmac")).gcode;
    let at = q.find("G0 X50 Y50\n").expect(&q);
    assert!(
        q[at..].contains("contour 2)\nM3 $0 S1\nM62 P2\nM67 E3 Q60\nG1 "),
        "{q}"
    );
    let end = q[at..].find("M67 E3 Q0\nM5 $0\nM63 P2\n").unwrap();
    assert!(!q[at..at + end].contains("M63"));
    assert_eq!(q.matches("M67 E3 Q60").count(), 1);
    let errors = rs274_qtplasmac(&q, "process-small-hole-qtplasmac");
    assert!(errors.is_empty(), "{errors:?}");
    // Without the rule: no slow hole, the hole entered by an ordinary lead.
    let plain = run(&plate(), &settings(1500.0));
    assert!(plain.plan.cuts.iter().all(|c| !c.small_hole));
    assert!(!plain.gcode.contains("F900"));
}

#[test]
fn the_qtplasmac_post_selects_the_material_and_never_moves_z() {
    let s = with_post(settings(2000.0), "qtplasmac")
        .with_material_number(7)
        .unwrap();
    let g = run(&plate(), &s).gcode;
    let head: Vec<&str> = g.lines().take(8).collect();
    let pos = |w: &str| head.iter().position(|l| *l == w).unwrap_or(usize::MAX);
    assert!(pos("M190 P7") < pos("M66 P3 L3 Q1"), "{head:?}");
    assert!(pos("M66 P3 L3 Q1") < pos("F#<_hal[plasmac.cut-feed-rate]>"));
    // The material's feed rules: no F word of ours anywhere.
    assert!(!g
        .lines()
        .any(|l| l.split(' ').any(|w| w.starts_with("F2000"))));
    assert!(!g.lines().any(|l| l.split(' ').any(|w| w.starts_with('Z'))));
    let tail: Vec<&str> = g.lines().rev().take(3).collect();
    assert_eq!(tail[..2], ["%", "M2"]);
    assert_eq!(tail[2], "M5 $-1");
    let errors = rs274_qtplasmac(&g, "process-qtplasmac");
    assert!(errors.is_empty(), "{errors:?}");
}

#[test]
fn the_z_post_probes_pierces_high_cuts_low_and_retracts() {
    let s = with_post(settings(2000.0), "linuxcnc-z")
        .with_pierce_delay(0.5)
        .unwrap()
        .with_heights(4.0, 1.2)
        .unwrap();
    let out = run(&plate(), &s);
    let g = &out.gcode;
    let pierce =
        "G91\nG38.2 Z-60 F300\nG90\nG10 L20 P0 Z-1.5\nG0 Z4\nM3 S1\nG4 P0.5\nG1 Z1.2 F300\n";
    let pierces = out.plan.pierces() - out.plan.cuts.iter().filter(|c| c.is_mark()).count();
    assert_eq!(g.matches(pierce).count(), pierces, "{g}");
    // The cut's first XY move is back at the cutting feed.
    for (i, _) in g.match_indices(pierce) {
        let next = g[i + pierce.len()..].lines().next().unwrap();
        assert!(
            next.starts_with("G1 ") && next.ends_with(" F2000"),
            "{next}"
        );
    }
    // Every cut, mark and spot ends by retracting.
    assert_eq!(
        g.matches("M5\nG0 Z25\n").count(),
        out.plan.cuts.len(),
        "{g}"
    );
    let errors = rs274_errors(g, "process-z");
    assert!(errors.is_empty(), "{errors:?}");
}

#[test]
fn the_qtplasmac_post_passes_rs274_on_every_fixture() {
    for file in [
        "seed000-plate-6-holes.dxf",
        "seed000-figure1.dxf",
        "seed001-P51703.dxf",
        "seed002-figure4.dxf",
        "seed003-grid-3x2.dxf",
    ] {
        let out = common::run(
            &common::fixture(file),
            &with_post(common::kerf(1.5), "qtplasmac"),
        )
        .unwrap();
        let errors = rs274_qtplasmac(&out.gcode, &format!("process-qtplasmac-{file}"));
        assert!(errors.is_empty(), "{file}: {errors:?}");
    }
}

#[test]
fn the_preview_draws_marks_in_their_own_colour() {
    use kerfcam::preview::{self, View};
    let out = run(&plate(), &settings(2000.0));
    let view = View::fit(&preview::extent(&out.scene()), 600, 300).unwrap();
    let pixmap = preview::render(&out.scene(), &view).unwrap();
    let teal =
        |px: &[u8]| px[0] < 40 && (120..=150).contains(&px[1]) && (100..=135).contains(&px[2]);
    let n = pixmap.data().chunks(4).filter(|p| teal(p)).count();
    assert!(n > 50, "{n} teal pixels");
    // No marks: no teal.
    let mut ops = kerfcam::process::LayerOps::new();
    ops.by_name = false;
    let plain = run(&plate(), &settings(2000.0).with_layer_ops(ops));
    let pixmap = preview::render(&plain.scene(), &view).unwrap();
    assert_eq!(pixmap.data().chunks(4).filter(|p| teal(p)).count(), 0);
}

#[test]
fn the_command_line_takes_layer_operations_and_reports_the_ignored_layer() {
    let file = out_dir().join("process-cli-plate.dxf");
    std::fs::write(&file, plate()).unwrap();
    let run = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_kerfcam"))
            .arg(&file)
            .args(args)
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let (code, json, _) = run(&["--json", "-q", "--verify"]);
    assert_eq!(code, Some(0));
    assert!(
        json.contains("layer-ignored") && json.contains("\"verification\""),
        "{json}"
    );
    let (_, json, _) = run(&[
        "--json",
        "-q",
        "--layer-op",
        "DIM=cut",
        "--layer-op",
        "MARK=ignore",
    ]);
    assert!(
        json.contains("layer 'MARK' is not cut") && !json.contains("'DIM'"),
        "{json}"
    );
    let (_, g, _) = run(&["--small-hole", "12", "--feed", "1500"]);
    assert!(g.contains("F900"), "{g}");
    let (code, _, err) = run(&["--layer-op", "DIM=mill"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("--layer-op"), "{err}");
}

#[test]
fn controller_compensation_starts_on_the_lead_in_line_and_ends_after_the_contour() {
    let part = dxf(&[
        lwpoly("0", &[(0.0, 0.0), (100.0, 0.0), (100.0, 50.0), (0.0, 50.0)]),
        circle("0", 50.0, 25.0, 8.0),
    ]
    .concat());
    let mut plan = kerfcam::plan::PlanOptions::DEFAULT;
    plan.controller_comp = true;
    let s = Settings::new(2.0, 0.001, 2000.0)
        .and_then(|s| s.with_origin(ProgramOrigin::Drawing))
        .and_then(|s| s.with_plan(plan.clone()))
        .unwrap();
    let out = run(&part, &s);
    let lines: Vec<&str> = out.gcode.lines().collect();
    let comps: Vec<usize> = (0..lines.len())
        .filter(|&i| lines[i].starts_with("G41.1") || lines[i].starts_with("G42.1"))
        .collect();
    assert_eq!(comps.len(), 2, "{}", out.gcode);
    for &i in &comps {
        // Tool on the scrap side: left of a clockwise outer and of a
        // counter-clockwise hole; D is the kerf.
        assert_eq!(lines[i], "G41.1 D2");
        // Activated right before the straight lead-in, after the torch.
        assert_eq!(lines[i - 1], "M3 S1");
        assert!(lines[i + 1].starts_with("G1 "), "{}", lines[i + 1]);
        // G40 after the contour, before the torch goes off; nothing
        // compensated in between is left open.
        let off = (i..lines.len()).find(|&k| lines[k] == "G40").unwrap();
        assert_eq!(lines[off + 1], "M5");
        assert!(!lines[i + 1..off].iter().any(|l| l.starts_with("G4")));
    }
    // The drawn contour itself is written (the controller offsets it).
    assert!(out.gcode.contains("G1 X100 Y50\n"));
    assert!(out.gcode.contains("G3 X58 Y25 I8 J0\n") || out.gcode.contains("G3 X42 Y25 I-8 J0\n"));
    let errors = rs274_errors(&out.gcode, "process-controller-comp");
    assert!(errors.is_empty(), "{errors:?}");
    // An arc lead-in cannot take up the offset: written uncompensated, said.
    plan.leads.kind = kerfcam::plan::LeadKind::Arc;
    let arc = run(&part, &s.clone().with_plan(plan.clone()).unwrap());
    assert!(!arc.gcode.contains("G41"));
    assert!(arc.warnings().any(|w| w.code == "comp-no-lead"));
    // Corners the kerf cannot reproduce are still reported.
    let plate = std::fs::read(common::fixture("seed000-plate-6-holes.dxf")).unwrap();
    plan.leads.kind = kerfcam::plan::LeadKind::Perpendicular;
    let ours = run(&plate, &common::kerf(2.0));
    let theirs = run(&plate, &common::kerf(2.0).with_plan(plan.clone()).unwrap());
    assert!(!ours.kerf.invalid_vertices.is_empty());
    assert_eq!(ours.kerf.invalid_vertices, theirs.kerf.invalid_vertices);
    // A controller without compensation codes is refused, by name.
    let grbl = with_post(common::kerf(2.0), "grbl-plasma")
        .with_plan(plan.clone())
        .unwrap();
    let e = kerfcam::run(&plate, &grbl).unwrap_err();
    assert!(e.to_string().contains("GRBL plasma"), "{e}");
    // Only the contour order writes it.
    plan.order = kerfcam::plan::Order::Chained;
    assert_eq!(
        common::kerf(2.0).with_plan(plan).unwrap_err().field,
        "controller_comp"
    );
}

#[test]
fn a_controller_compensated_job_is_verified_on_the_controllers_path() {
    let mut plan = kerfcam::plan::PlanOptions::DEFAULT;
    plan.controller_comp = true;
    let s = common::kerf(2.0).with_verify(true).with_plan(plan).unwrap();
    let out = common::run(&common::fixture("seed000-plate-6-holes.dxf"), &s).unwrap();
    let v = out.verification.unwrap();
    assert_eq!((v.overcut_mm2, v.parts_not_freed), (0.0, 0), "{v:?}");
}

#[test]
fn compared_orders_cut_the_cut_layers_only_as_the_plan_does() {
    // The drawing order cuts the file's entities in its order: the MARK,
    // SPOT and DIM layers are not cut, in the comparison as in the plan.
    let s = settings(2000.0).with_order(Order::Drawing).unwrap();
    let out = run(&plate(), &s);
    let cut = |p: &kerfcam::plan::CutPlan| -> f64 {
        p.cuts
            .iter()
            .filter(|c| !c.is_mark() && !c.spot)
            .flat_map(|c| &c.steps)
            .map(|st| st.segment.length())
            .sum()
    };
    let cmp = kerfcam::compare_orders(&out, &s, &[Order::Drawing]);
    let planned = cut(&out.plan);
    // The plate's outline and its Ø10 and Ø1 holes, on the drawn lines.
    assert!(
        (planned - (600.0 + 2.0 * PI * 5.5)).abs() < 1e-6,
        "{planned}"
    );
    assert!(
        (cmp[0].stats.cut_length - planned).abs() < 1e-6,
        "compared {} mm, planned {planned} mm",
        cmp[0].stats.cut_length
    );
}
