//! Issue 39 §6: parts that share edges. A box-joint nest drawn as LINEs,
//! each line between two panels drawn once, so three or four lines meet
//! at the panels' corners: the panels are the faces of the linework, the
//! run says so (`parts-share-edges`, how many, the loss), each shared line
//! is cut once, and `--verify`'s loss on every panel agrees with an
//! independent sweep (`common::sweep::loss_by_part`) within 5 %.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;
use common::kerf;
use common::sweep::loss_by_part;
use kerfcam::contour::ContourKind;
use kerfcam::plan::Order;
use kerfcam::Output;

const KERF: f64 = 1.5;
/// Panels across and up.
const COLS: usize = 3;
const ROWS: usize = 2;
/// A panel's size and its fingers' depth, mm.
const W: f64 = 100.0;
const H: f64 = 60.0;
const DEPTH: f64 = 6.0;

fn line(d: &mut String, a: (f64, f64), b: (f64, f64)) {
    *d += &format!(
        "0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
        a.0, a.1, b.0, b.1
    );
}

/// A finger joint from `a` to `b` as LINEs: the span in `2k + 1` equal
/// steps, every other one `DEPTH` to the left. Returns its length.
fn fingers(d: &mut String, a: (f64, f64), b: (f64, f64), k: usize) -> f64 {
    let n = 2 * k + 1;
    let (dx, dy) = ((b.0 - a.0) / n as f64, (b.1 - a.1) / n as f64);
    let len = (dx * dx + dy * dy).sqrt();
    let (nx, ny) = (-dy / len * DEPTH, dx / len * DEPTH);
    let at = |i: usize, out: bool| {
        let o = if out { 1.0 } else { 0.0 };
        (a.0 + dx * i as f64 + nx * o, a.1 + dy * i as f64 + ny * o)
    };
    for i in 0..n {
        let out = i % 2 == 1;
        line(d, at(i, out), at(i + 1, out));
        if i + 1 < n {
            // The step out to the next finger, or back.
            line(d, at(i + 1, out), at(i + 1, !out));
        }
    }
    n as f64 * len + 2.0 * k as f64 * DEPTH
}

/// The nest: `COLS x ROWS` panels, finger joints between them, the
/// outline's top one LINE across (the panels' corners lie on its inside:
/// T-junctions), one joint an ARC, a round hole in the first panel.
/// Returns the DXF and the length of the shared lines.
fn box_joint_nest() -> (Vec<u8>, f64) {
    let mut d = String::new();
    let mut shared = 0.0;
    for i in 1..COLS {
        for j in 0..ROWS {
            let (x, y0, y1) = (W * i as f64, H * j as f64, H * (j + 1) as f64);
            if (i, j) == (COLS - 1, ROWS - 1) {
                // An arc joint: chord 60, radius 50, bulging right.
                let (cx, cy, r) = (x - 40.0, (y0 + y1) / 2.0, 50.0);
                let half = (30.0_f64).atan2(40.0);
                d += &format!(
                    "0\nARC\n8\n0\n10\n{cx}\n20\n{cy}\n40\n{r}\n50\n{}\n51\n{}\n",
                    -half.to_degrees(),
                    half.to_degrees()
                );
                shared += r * 2.0 * half;
            } else {
                shared += fingers(&mut d, (x, y0), (x, y1), 2);
            }
        }
    }
    for j in 1..ROWS {
        for i in 0..COLS {
            let (y, x0, x1) = (H * j as f64, W * i as f64, W * (i + 1) as f64);
            shared += fingers(&mut d, (x0, y), (x1, y), 3);
        }
    }
    let (w, h) = (W * COLS as f64, H * ROWS as f64);
    for i in 0..COLS {
        line(&mut d, (W * i as f64, 0.0), (W * (i + 1) as f64, 0.0));
    }
    line(&mut d, (w, h), (0.0, h));
    for j in 0..ROWS {
        line(&mut d, (0.0, H * j as f64), (0.0, H * (j + 1) as f64));
        line(&mut d, (w, H * j as f64), (w, H * (j + 1) as f64));
    }
    d += "0\nCIRCLE\n8\n0\n10\n30\n20\n30\n40\n8\n";
    let dxf = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{d}0\nENDSEC\n0\nEOF\n"
    );
    (dxf.into_bytes(), shared)
}

fn run(order: Order) -> Output {
    let (dxf, _) = box_joint_nest();
    let s = kerf(KERF)
        .with_verify(true)
        .map_plan(|p| p.order = order)
        .unwrap();
    kerfcam::run(&dxf, &s).unwrap()
}

#[test]
fn the_panels_of_a_box_joint_nest_are_parts_and_the_warning_names_the_loss() {
    let (_, shared) = box_joint_nest();
    let out = run(Order::Contour);
    let cs = &out.contours.contours;
    let count = |k: ContourKind| cs.iter().filter(|c| c.kind == k).count();
    assert_eq!(
        (count(ContourKind::Outer), count(ContourKind::Hole)),
        (6, 1)
    );
    assert_eq!(count(ContourKind::Open), 0, "{cs:?}");
    // Every panel a face of the grid: 100 x 60 less and plus its fingers.
    for c in cs.iter().filter(|c| c.kind == ContourKind::Outer) {
        assert!((c.area - W * H).abs() < 0.2 * W * H, "{}", c.area);
    }
    assert!((out.contours.shared.length - shared).abs() < 1e-6);
    let w: Vec<_> = out
        .warnings()
        .filter(|w| w.code == "parts-share-edges")
        .collect();
    assert_eq!(w.len(), 1, "{:?}", out.warnings().collect::<Vec<_>>());
    let en = &w[0].text.en;
    assert!(en.starts_with("6 parts share edges"), "{en}");
    assert!(en.contains("half the kerf (0.750 mm)"), "{en}");
    assert!(en.contains(&format!("{shared:.1} mm of them")), "{en}");
    let pt = &w[0].text.pt;
    assert!(pt.contains("6 peças") && pt.contains("0,750 mm"), "{pt}");
    // Nearest-end chaining's warning is gone: the branch points are faces' corners.
    assert!(!out.warnings().any(|w| w.code == "branch-points"));
}

#[test]
fn each_shared_line_is_cut_once_and_the_hole_before_its_panel() {
    let (_, shared) = box_joint_nest();
    for order in [Order::Contour, Order::Chained, Order::Eulerian] {
        let out = run(order);
        let common: f64 = out
            .plan
            .common_line
            .iter()
            .map(|c| c.segment.length())
            .sum();
        assert!(
            (common - shared).abs() < 0.01,
            "{order:?}: {common} vs {shared}"
        );
        let cs = &out.contours.contours;
        let hole = cs.iter().position(|c| c.kind == ContourKind::Hole).unwrap();
        let panel = cs[hole].parent.unwrap();
        let cut_of = |c: usize| out.plan.cuts.iter().position(|k| k.contours.contains(&c));
        assert!(cut_of(hole).unwrap() < cut_of(panel).unwrap(), "{order:?}");
        let v = out.verification.as_ref().unwrap();
        assert_eq!(v.parts_not_freed, 0, "{order:?}: {v:?}");
        // The panels' spacing is `parts-share-edges`'s to say, not the
        // common-line order's "space them by the kerf".
        let closer: Vec<_> = (out.warnings())
            .filter(|w| w.code == "parts-closer-than-kerf")
            .collect();
        assert!(closer.is_empty(), "{order:?}: {closer:?}");
    }
}

#[test]
fn verify_reports_the_loss_on_every_panel_as_an_independent_sweep_does() {
    let out = run(Order::Contour);
    let v = out.verification.clone().unwrap();
    assert_eq!(v.parts.len(), 6, "{:?}", v.parts);
    let sweep = loss_by_part(&out.plan, &out.contours, KERF, 0.05);
    // What the drawing says: half the kerf along each panel's shared edges.
    let along = |part: usize| -> f64 {
        let outer = out
            .contours
            .contours
            .iter()
            .find(|c| c.kind == ContourKind::Outer && c.part == Some(part))
            .unwrap();
        outer
            .segments
            .iter()
            .filter(|s| {
                let m = s.point_at(0.5);
                let (w, h) = (W * COLS as f64, H * ROWS as f64);
                let on_outline = m.x.abs() < 1e-6
                    || m.y.abs() < 1e-6
                    || (m.x - w).abs() < 1e-6
                    || (m.y - h).abs() < 1e-6;
                !on_outline
            })
            .map(|s| s.length())
            .sum()
    };
    for l in &v.parts {
        let s = sweep[l.part];
        println!(
            "part {}: verify {:.3} mm² {:.4} mm, sweep {:.3} mm² {:.4} mm, kerf/2 x shared {:.3} mm²",
            l.part,
            l.overcut_mm2,
            l.max_overcut_mm,
            s.area,
            s.depth,
            KERF / 2.0 * along(l.part)
        );
        let near = |a: f64, b: f64| (a - b).abs() <= 0.05 * b;
        assert!(
            near(l.max_overcut_mm, s.depth),
            "part {}: {l:?} vs {s:?}",
            l.part
        );
        assert!(
            near(l.overcut_mm2, s.area),
            "part {}: {l:?} vs {s:?}",
            l.part
        );
        assert!(near(l.max_overcut_mm, KERF / 2.0), "part {}: {l:?}", l.part);
        let nominal = KERF / 2.0 * along(l.part);
        assert!(
            near(l.overcut_mm2, nominal),
            "part {}: {l:?} vs {nominal}",
            l.part
        );
    }
    let total: f64 = v.parts.iter().map(|l| l.overcut_mm2).sum();
    assert!((total - v.overcut_mm2).abs() < 1e-6, "{total} vs {v:?}");
    // The report carries it, and the warning counts the parts.
    let json = kerfcam::report::Report::new(&out).to_json();
    assert!(json.contains(r#""parts":[{"part":1,"#), "{json}");
    let w = out.warnings().find(|w| w.code == "verify-overcut").unwrap();
    assert!(w.text.en.contains("from 6 part(s)"), "{}", w.text.en);
}

#[test]
fn drawings_without_branch_points_do_not_share_edges() {
    // Closed outlines that touch (each part its own copy of the edge) are
    // parts already: no faces, no warning, the order asked.
    for name in ["seed003-grid-3x2.dxf", "seed000-plate-6-holes.dxf"] {
        let out = common::run(&common::fixture(name), &kerf(KERF)).unwrap();
        assert!(!out.contours.shared.any(), "{name}");
        assert_eq!(out.contours.shared.faces, 0, "{name}");
        assert!(!out.warnings().any(|w| w.code == "parts-share-edges"));
        assert_eq!(out.plan.order, Order::Contour);
    }
}
