//! A router profile's side chosen on one loop (issue 43 §1): outside,
//! inside or on the line, kept by the loop it was set on (src/plan/choice.rs),
//! never by a contour number. The program is read back from its text alone
//! (`common::program_xy`) and the tool's centre measured against the
//! test's own shapes; a choice that cannot apply is said, nothing moved.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::program_xy::{read, XyMove};
use kerfcam::geom::Point;
use kerfcam::plan::choice::pick_at;
use kerfcam::{LoopKeySpec, Output, SideChoice, Spec};

const R: f64 = 3.0;
const DEPTH: f64 = 6.0;

/// The drawn loops: a plate (x0, y0, x1, y1) with a round hole and a
/// square one, and a round part beside it.
const PLATE: (f64, f64, f64, f64) = (0.0, 0.0, 120.0, 60.0);
const ROUND_HOLE: (f64, f64, f64) = (30.0, 30.0, 10.0);
const SQUARE_HOLE: (f64, f64, f64, f64) = (70.0, 20.0, 95.0, 40.0);
const DISC: (f64, f64, f64) = (160.0, 30.0, 15.0);

fn rect(layer: &str, (x0, y0, x1, y1): (f64, f64, f64, f64)) -> String {
    let mut s = format!("0\nLWPOLYLINE\n8\n{layer}\n90\n4\n70\n1\n");
    for (x, y) in [(x0, y0), (x1, y0), (x1, y1), (x0, y1)] {
        s += &format!("10\n{x}\n20\n{y}\n");
    }
    s
}

fn circle(layer: &str, (x, y, r): (f64, f64, f64)) -> String {
    format!("0\nCIRCLE\n8\n{layer}\n10\n{x}\n20\n{y}\n40\n{r}\n")
}

/// The drawing; `extra` first (so that switching its layer off renumbers
/// every other contour).
fn dxf(extra: &str) -> Vec<u8> {
    let e = [
        extra.to_string(),
        rect("PROFILE", PLATE),
        circle("PROFILE", ROUND_HOLE),
        rect("PROFILE", SQUARE_HOLE),
        circle("PROFILE", DISC),
    ]
    .concat();
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

/// A 20 mm square on layer OTHER, drawn before the rest.
fn other() -> String {
    rect("OTHER", (200.0, 0.0, 220.0, 20.0))
}

fn spec(extra: impl FnOnce(&mut Spec)) -> Spec {
    let mut s = Spec {
        tool_diameter: Some(2.0 * R),
        depth: Some(DEPTH),
        pass_depth: 3.0,
        post: Some("grbl-router".into()),
        layer_ops: vec![
            ["PROFILE".into(), "profile".into()],
            ["OTHER".into(), "profile".into()],
        ],
        lead: "arc".into(),
        origin: "drawing".into(),
        ..Spec::default()
    };
    extra(&mut s);
    s
}

/// Signed distance from a rectangle (outside positive).
fn rect_sd(p: (f64, f64), (x0, y0, x1, y1): (f64, f64, f64, f64)) -> f64 {
    let dx = (x0 - p.0).max(p.0 - x1);
    let dy = (y0 - p.1).max(p.1 - y1);
    if dx <= 0.0 && dy <= 0.0 {
        dx.max(dy)
    } else {
        dx.max(0.0).hypot(dy.max(0.0))
    }
}

fn circle_sd(p: (f64, f64), (x, y, r): (f64, f64, f64)) -> f64 {
    (p.0 - x).hypot(p.1 - y) - r
}

/// Each loop's signed distance and the tool centre's asked offset from it
/// (outside positive): the plate as left (outside), the round hole
/// outside, the square hole on the line, the disc inside.
/// A loop: its name, its signed distance, the asked offset.
type Loop = (&'static str, Box<dyn Fn((f64, f64)) -> f64>, f64);

fn loops() -> [Loop; 4] {
    [
        ("plate", Box::new(|p| rect_sd(p, PLATE)), R),
        ("round hole", Box::new(|p| circle_sd(p, ROUND_HOLE)), R),
        ("square hole", Box::new(|p| rect_sd(p, SQUARE_HOLE)), 0.0),
        ("disc", Box::new(|p| circle_sd(p, DISC)), -R),
    ]
}

/// Moves at a depth below the top, going somewhere (the cuts, leads included).
fn cuts(program: &str) -> Vec<XyMove> {
    read(program, 15.0)
        .into_iter()
        .filter(|m| !m.rapid && m.z.0 == m.z.1 && m.z.0 < 0.0 && m.a != m.b)
        .collect()
}

/// Points of the path asked of each loop, every `step` mm (the plate's
/// corners' rounds left out): for the round loops their circle at the
/// offset, for the square hole its drawn edges.
fn asked_points(step: f64) -> Vec<(&'static str, (f64, f64))> {
    let mut out = Vec::new();
    let edges =
        |name: &'static str, (x0, y0, x1, y1): (f64, f64, f64, f64), d: f64, out: &mut Vec<_>| {
            let n = |len: f64| (len / step).ceil() as usize;
            for i in 0..=n(x1 - x0) {
                let x = x0 + (x1 - x0) * i as f64 / n(x1 - x0) as f64;
                out.push((name, (x, y0 - d)));
                out.push((name, (x, y1 + d)));
            }
            for i in 0..=n(y1 - y0) {
                let y = y0 + (y1 - y0) * i as f64 / n(y1 - y0) as f64;
                out.push((name, (x0 - d, y)));
                out.push((name, (x1 + d, y)));
            }
        };
    edges("plate", PLATE, R, &mut out);
    edges("square hole", SQUARE_HOLE, 0.0, &mut out);
    for (name, (x, y, r), d) in [("round hole", ROUND_HOLE, R), ("disc", DISC, -R)] {
        let rr = r + d;
        let n = (std::f64::consts::TAU * rr / step).ceil() as usize;
        for i in 0..n {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            out.push((name, (x + rr * a.cos(), y + rr * a.sin())));
        }
    }
    out
}

/// The tool's centre, read back from the program, is on each loop's
/// asked side at the tool's radius: every point of the asked path is cut
/// (within 0.01 mm of a cutting move), and no cutting move comes nearer
/// its loop, or onto its other side, than that (leads go into the waste,
/// farther off).
fn assert_sides(out: &Output, what: &str) {
    let errors = common::rs274_errors(&out.gcode, &format!("milling-sides-{what}"));
    assert!(errors.is_empty(), "{what}: {errors:?}");
    let moves = cuts(&out.gcode);
    assert!(!moves.is_empty(), "{what}: no cuts");
    for (name, p) in asked_points(1.0) {
        let d = moves
            .iter()
            .map(|m| m.dist(p))
            .fold(f64::INFINITY, f64::min);
        assert!(
            d < 0.01,
            "{what}: {name}'s path at {p:?} not cut ({d:.4} mm off)"
        );
    }
    let loops = loops();
    let mut seen = [0usize; 4];
    for m in &moves {
        for p in m.samples(0.2) {
            if p.0 > 190.0 {
                continue; // the OTHER square, when cut
            }
            // The loop nearest the point is the one its cut is about.
            let (k, sd) = (loops.iter().enumerate())
                .map(|(k, l)| (k, (l.1)(p)))
                .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
                .unwrap();
            let (name, _, asked) = &loops[k];
            seen[k] += 1;
            let ok = if *asked > 0.0 {
                sd >= asked - 0.005
            } else if *asked < 0.0 {
                sd <= asked + 0.005
            } else {
                // On the line; its leads in the hole's waste (inside).
                sd <= 0.005
            };
            assert!(
                ok,
                "{what}: {name} cut at {p:?}, {sd:.4} mm from it (asked {asked})"
            );
        }
    }
    assert!(seen.iter().all(|&n| n > 0), "{what}: {seen:?}");
}

/// The side choice at `at` on the loop through it in `out` (the page's
/// key, as the engine's pickAt gives it).
fn keyed(out: &Output, at: (f64, f64), side: &str) -> SideChoice {
    let (_, pick) = pick_at(&out.contours, Point::new(at.0, at.1), 1.0).unwrap();
    let k = pick.on.unwrap();
    SideChoice {
        at: [pick.at.x, pick.at.y],
        on: Some(LoopKeySpec {
            part: k.source.part,
            copy: k.source.copy,
            contour: k.source.contour,
            area: k.area,
            length: k.length,
            size: k.size,
            layer: k.layer,
        }),
        side: side.into(),
    }
}

fn run(body: &[u8], s: &Spec) -> Output {
    kerfcam::run(body, &s.build().unwrap()).unwrap()
}

fn said<'a>(out: &'a Output, code: &str) -> Vec<&'a kerfcam::warning::Warning> {
    out.warnings().filter(|w| w.code == code).collect()
}

#[test]
fn each_profile_is_cut_on_the_side_chosen_for_it_at_the_tool_radius() {
    let body = dxf(&other());
    let first = run(&body, &spec(|_| {}));
    let sides = vec![
        keyed(&first, (40.0, 30.0), "outside"),
        keyed(&first, (82.5, 20.0), "on"),
        keyed(&first, (175.0, 30.0), "inside"),
    ];
    let all = run(&body, &spec(|s| s.sides_at = sides.clone()));
    assert!(said(&all, "sides-not-applied").is_empty());
    assert_sides(&all, "all-layers");
    // On the square hole's line an arc from any of its corners would leave
    // its waste (the hole) for the plate: its arcs start mid-edge instead
    // (a corner-only loop's leftover, issue 43), inside the hole; nothing
    // is said.
    assert!(said(&all, "lead-arc-no-room").is_empty());
    let in_hole = (cuts(&all.gcode).into_iter())
        .filter(|m| m.arc.is_some() && m.length() > 9.0 && m.length() < 9.5)
        .filter(|m| m.samples(0.5).iter().all(|p| rect_sd(*p, SQUARE_HOLE) <= 0.005))
        .count();
    // Lead-in and lead-out (R 6, 9.42 mm) on each of the 2 passes.
    assert_eq!(in_hole, 4, "the square hole's lead arcs");
    // OTHER switched off: every contour renumbered; each choice stays on
    // its loop (and the program is the same but for OTHER's square).
    let fewer = run(
        &body,
        &spec(|s| {
            s.sides_at = sides.clone();
            s.layers = Some(vec!["PROFILE".into()]);
        }),
    );
    let before: Vec<_> = (first.contours.contours.iter()).map(|c| c.source).collect();
    let after: Vec<_> = (fewer.contours.contours.iter()).map(|c| c.source).collect();
    assert_ne!(before[1..], after[..], "the contours are renumbered");
    assert!(said(&fewer, "sides-not-applied").is_empty());
    assert_sides(&fewer, "other-off");
    // The same through the CLI's keyless points.
    let cli: Vec<_> = sides
        .iter()
        .map(|c| SideChoice {
            on: None,
            ..c.clone()
        })
        .collect();
    let keyless = run(&body, &spec(|s| s.sides_at = cli));
    assert_eq!(keyless.gcode, all.gcode);
    // Without the choices the holes and the disc go to their waste side:
    // the check sees it (a planted fault: the choices dropped).
    let caught = std::panic::catch_unwind(|| assert_sides(&first, "none"));
    assert!(
        caught.is_err(),
        "the check misses profiles on their default side"
    );
}

#[test]
fn a_side_that_cannot_be_applied_is_said_and_nothing_moves() {
    // An open line on the profile layer, a loop on a pocket layer.
    let extra = "0\nLINE\n8\nPROFILE\n10\n0\n20\n80\n11\n100\n21\n80\n".to_string()
        + &circle("POCKET", (160.0, 90.0, 8.0));
    let body = dxf(&extra);
    let side = |x: f64, y: f64, side: &str| SideChoice {
        at: [x, y],
        on: None,
        side: side.into(),
    };
    let base = spec(|s| {
        s.layer_ops.push(["POCKET".into(), "pocket".into()]);
        s.cut_open = true;
    });
    let plain = run(&body, &base);
    let mut asked = base.clone();
    asked.sides_at = vec![
        side(50.0, 80.0, "inside"),  // the open line
        side(168.0, 90.0, "inside"), // the pocket's loop
        side(300.0, 300.0, "on"),    // nothing there
    ];
    let out = run(&body, &asked);
    let w = said(&out, "sides-not-applied");
    assert_eq!(
        w.len(),
        1,
        "{:?}",
        out.warnings().map(|w| w.code).collect::<Vec<_>>()
    );
    let en = &w[0].text.en;
    assert!(en.starts_with("3 profile side(s)"), "{en}");
    assert!(
        en.contains("(50, 80): an open contour has no inside or outside"),
        "{en}"
    );
    assert!(en.contains("(168, 90): not a router profile"), "{en}");
    assert!(
        en.contains("(300, 300): the loop it was set on is not in the drawing now"),
        "{en}"
    );
    assert!(
        w[0].text.pt.starts_with("3 lado(s) de perfil"),
        "{}",
        w[0].text.pt
    );
    assert_eq!(out.gcode, plain.gcode, "nothing applied elsewhere");
    // No tool (a plasma's kerf): not a router profile.
    let mut plasma = Spec {
        kerf: Some(1.5),
        ..Spec::default()
    };
    plasma.sides_at = vec![side(40.0, 30.0, "outside")];
    let out = kerfcam::run(&dxf(""), &plasma.build().unwrap()).unwrap();
    let w = said(&out, "sides-not-applied");
    assert!(
        w.len() == 1 && w[0].text.en.contains("(40, 30): not a router profile"),
        "{w:?}"
    );
    // An unknown side names its field.
    let mut bad = spec(|_| {});
    bad.sides_at = vec![side(40.0, 30.0, "left")];
    assert_eq!(bad.build().unwrap_err().field, "sides_at");
}
