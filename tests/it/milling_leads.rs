//! A router's profiles enter and leave each depth pass on tangent arcs in
//! the waste (issue 43 §3): read back from the program's text alone
//! (`common::program_xy`) and swept by the independent checker of
//! `common::mill_sweep`, against the test's own shapes — a plate with a
//! hole the arc fits in and one it does not, beside a neighbour 8 mm away.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::mill_sweep::{samples, sweep, Cell, Grid};
use common::program_xy::{read, XyMove};
use kerfcam::Choice;
use kerfcam::{SideChoice, Spec};

const R: f64 = 3.0;
const DEPTH: f64 = 6.0;
const PLATE: (f64, f64, f64, f64) = (0.0, 0.0, 100.0, 60.0);
const NEIGHBOUR: (f64, f64, f64, f64) = (108.0, 0.0, 150.0, 60.0);
/// Circles (x, y, r): the arc fits in the first, not in the second (the
/// tool's centre path there is 1 mm round).
const HOLES: [(f64, f64, f64); 2] = [(30.0, 30.0, 10.0), (75.0, 30.0, 4.0)];

fn dxf() -> Vec<u8> {
    let rect = |(x0, y0, x1, y1): (f64, f64, f64, f64)| {
        let mut s = "0\nLWPOLYLINE\n8\nPROFILE\n90\n4\n70\n1\n".to_string();
        for (x, y) in [(x0, y0), (x1, y0), (x1, y1), (x0, y1)] {
            s += &format!("10\n{x}\n20\n{y}\n");
        }
        s
    };
    let mut e = rect(PLATE) + &rect(NEIGHBOUR);
    for (x, y, r) in HOLES {
        e += &format!("0\nCIRCLE\n8\nPROFILE\n10\n{x}\n20\n{y}\n40\n{r}\n");
    }
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

fn in_rect(p: (f64, f64), (x0, y0, x1, y1): (f64, f64, f64, f64)) -> bool {
    (x0..=x1).contains(&p.0) && (y0..=y1).contains(&p.1)
}

fn rect_dist(p: (f64, f64), (x0, y0, x1, y1): (f64, f64, f64, f64)) -> f64 {
    let dx = (x0 - p.0).max(p.0 - x1);
    let dy = (y0 - p.1).max(p.1 - y1);
    if dx <= 0.0 && dy <= 0.0 {
        -dx.max(dy)
    } else {
        dx.max(0.0).hypot(dy.max(0.0))
    }
}

/// Distance from `p` to the nearest drawn line.
fn edge_dist(p: (f64, f64)) -> f64 {
    let circles = HOLES.iter().map(|&(x, y, r)| ((p.0 - x).hypot(p.1 - y) - r).abs());
    circles
        .chain([rect_dist(p, PLATE), rect_dist(p, NEIGHBOUR)])
        .fold(f64::INFINITY, f64::min)
}

fn material(x: f64, y: f64) -> Cell {
    let in_hole = HOLES.iter().any(|&(hx, hy, r)| (x - hx).hypot(y - hy) < r);
    if (in_rect((x, y), PLATE) && !in_hole) || in_rect((x, y), NEIGHBOUR) {
        Cell::Keep
    } else {
        Cell::Outside
    }
}

fn spec(extra: impl FnOnce(&mut Spec)) -> Spec {
    let mut s = Spec {
        tool_diameter: Some(2.0 * R),
        depth: Some(DEPTH),
        pass_depth: 3.0,
        post: Some("grbl-router".into()),
        layer_ops: vec![["PROFILE".into(), "profile".into()]],
        lead: "arc".into(),
        verify: true,
        // The plate started on its edge facing the neighbour, where a 6 mm
        // arc would reach into it.
        starts: vec![Choice::Keyed {
            at: [100.0, 30.0],
            on: None,
        }],
        ..Spec::default()
    };
    extra(&mut s);
    s
}

fn unit(v: (f64, f64)) -> (f64, f64) {
    let n = v.0.hypot(v.1);
    (v.0 / n, v.1 / n)
}

/// A move's direction at its start (`end` false) or its end.
fn tangent(m: &XyMove, end: bool) -> (f64, f64) {
    let p = if end { m.b } else { m.a };
    match m.arc {
        Some(((cx, cy), ccw)) => {
            let (rx, ry) = (p.0 - cx, p.1 - cy);
            unit(if ccw { (-ry, rx) } else { (ry, -rx) })
        }
        None => unit((m.b.0 - m.a.0, m.b.1 - m.a.1)),
    }
}

fn flat(m: &XyMove) -> bool {
    !m.rapid && m.z.0 == m.z.1 && m.z.0 < 0.0 && m.a != m.b
}

type Places = Vec<(f64, f64)>;

/// Where the tool goes down into the stock and comes up out of it.
fn plunges_and_lifts(moves: &[XyMove]) -> (Places, Places) {
    let vertical = |m: &&XyMove| m.a == m.b && m.z.0 != m.z.1;
    let down = (moves.iter().filter(vertical))
        .filter(|m| m.z.1 < 0.0 && m.z.1 < m.z.0)
        .map(|m| m.b);
    let up = (moves.iter().filter(vertical))
        .filter(|m| m.z.0 < 0.0 && m.z.1 > m.z.0)
        .map(|m| m.b);
    (down.collect(), up.collect())
}

#[test]
fn router_profiles_enter_and_leave_every_pass_on_tangent_arcs_in_the_waste() {
    let g = Grid::new((-15.0, -15.0), (165.0, 75.0), 0.1, material, |_, _| 0.0);
    // (name, lead radius, profiles the arc has no room for)
    let variants: [(&str, f64, usize); 2] = [("6 mm arcs", 0.0, 2), ("0.5 mm arcs", 0.5, 0)];
    for (name, radius, no_room) in variants {
        let settings = spec(|s| s.lead_radius = radius).build().unwrap();
        let out = kerfcam::run(&dxf(), &settings).unwrap();
        let errors = common::rs274_errors(&out.gcode, &format!("milling-leads-{radius}"));
        assert!(errors.is_empty(), "{name}: {errors:?}");
        let said: Vec<_> = out
            .warnings()
            .filter(|w| w.code == "lead-arc-no-room")
            .collect();
        let moves = read(&out.gcode, 15.0);
        let (down, up) = plunges_and_lifts(&moves);
        // Each of the 4 profiles goes down once a pass, 2 passes; up once
        // a pass with leads (to go across to the lead-in again), once at
        // the end without (the next pass goes down where the last ended).
        assert_eq!((down.len(), up.len()), (8, 8 - no_room), "{name}");
        let on_wall = |pts: &[(f64, f64)]| {
            pts.iter()
                .filter(|p| (edge_dist(**p) - R).abs() < 0.01)
                .count()
        };
        let waste = |pts: &[(f64, f64)]| pts.iter().filter(|p| edge_dist(**p) > R + 0.2).count();
        eprintln!(
            "{name}: down on the wall {} / in the waste {}, up on the wall {} / in the waste {}, warnings {:?}",
            on_wall(&down),
            waste(&down),
            on_wall(&up),
            waste(&up),
            said.iter().map(|w| w.text.en.clone()).collect::<Vec<_>>()
        );
        // Those with room: every pass down and up in the waste; the others
        // on their contour, and said.
        assert_eq!(on_wall(&down), 2 * no_room, "{name}: {down:?}");
        assert_eq!(on_wall(&up), no_room, "{name}: {up:?}");
        assert_eq!(waste(&down), 8 - 2 * no_room, "{name}");
        assert_eq!(waste(&up), 8 - 2 * no_room, "{name}");
        if no_room > 0 {
            assert_eq!(said.len(), 1, "{name}");
            assert!(said[0].text.en.starts_with("2 profile(s)"), "{}", said[0].text.en);
            // Said where: the plate's start facing the neighbour, or the small hole.
            let at = said[0].at.unwrap();
            assert!(edge_dist((at.x, at.y)) < R + 0.01, "{at:?}");
        } else {
            assert!(said.is_empty(), "{name}: {:?}", said[0].text.en);
        }
        // Each entry and exit in the waste is an arc tangent to the cut it
        // joins (the first flat move after going down, the last before up).
        let mut arcs = 0;
        for (i, m) in moves.iter().enumerate() {
            let vertical = m.a == m.b && m.z.0 != m.z.1;
            let stock = (m.z.1 < 0.0 && m.z.1 < m.z.0) || (m.z.0 < 0.0 && m.z.1 > m.z.0);
            if !vertical || !stock || edge_dist(m.b) <= R + 0.2 {
                continue;
            }
            let (lead, joined) = if m.z.1 < m.z.0 {
                (&moves[i + 1], &moves[i + 2])
            } else {
                (&moves[i - 1], &moves[i - 2])
            };
            assert!(lead.arc.is_some() && flat(lead) && flat(joined), "{name}: {lead:?}");
            let (t, u) = if m.z.1 < m.z.0 {
                (tangent(lead, true), tangent(joined, false))
            } else {
                (tangent(joined, true), tangent(lead, false))
            };
            assert!(t.0 * u.0 + t.1 * u.1 > 1.0 - 1e-6, "{name}: {t:?} vs {u:?} at {:?}", lead.b);
            arcs += 1;
        }
        assert_eq!(arcs, 16 - 4 * no_room, "{name}");
        // No gouge: the tool's disc swept along the program's cuts below
        // the top never reaches the plate or the neighbour.
        let s = sweep(&g, &samples(&out.gcode, 0.05), R, -DEPTH, 0.02);
        assert_eq!(s.gouge_mm2, 0.0, "{name}: gouge at {:?}", s.gouge_at);
        // kerfcam's own --verify sweep agrees.
        let v = out.verification.as_ref().unwrap();
        assert_eq!(v.overcut_mm2, 0.0, "{name}: {:?}", v.deepest_at);
        // Planted fault: a disc 0.3 mm wider than the tool reaches the parts.
        let wide = sweep(&g, &samples(&out.gcode, 0.05), R + 0.3, -DEPTH, 0.02);
        assert!(wide.gouge_mm2 > 0.0, "{name}: the checker misses a gouge");
    }
}

/// A plate with a rectangular hole: a loop of corners only.
const SLOT_PLATE: (f64, f64, f64, f64) = (0.0, 0.0, 100.0, 60.0);
const SLOT: (f64, f64, f64, f64) = (30.0, 20.0, 70.0, 40.0);

fn slot_dxf() -> Vec<u8> {
    let rect = |(x0, y0, x1, y1): (f64, f64, f64, f64)| {
        let mut s = "0\nLWPOLYLINE\n8\nPROFILE\n90\n4\n70\n1\n".to_string();
        for (x, y) in [(x0, y0), (x1, y0), (x1, y1), (x0, y1)] {
            s += &format!("10\n{x}\n20\n{y}\n");
        }
        s
    };
    let e = rect(SLOT_PLATE) + &rect(SLOT);
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

fn slot_spec(extra: impl FnOnce(&mut Spec)) -> Spec {
    let mut s = Spec {
        tool_diameter: Some(2.0 * R),
        depth: Some(DEPTH),
        pass_depth: 3.0,
        post: Some("grbl-router".into()),
        layer_ops: vec![["PROFILE".into(), "profile".into()]],
        lead: "arc".into(),
        ..Spec::default()
    };
    extra(&mut s);
    s
}

/// A rectangular hole has no vertex where a tangent arc stays in the
/// waste: each would run across the next wall. Without a start point the
/// arcs start mid-edge (the longest first); a start point the operator set
/// on a corner is kept there, the arcs not cut, and said.
#[test]
fn a_loop_of_corners_only_is_led_in_mid_edge_unless_its_start_was_chosen() {
    let dist = |p: (f64, f64)| rect_dist(p, SLOT_PLATE).min(rect_dist(p, SLOT));
    let material = |x: f64, y: f64| {
        if in_rect((x, y), SLOT_PLATE) && !in_rect((x, y), SLOT) {
            Cell::Keep
        } else {
            Cell::Outside
        }
    };
    let g = Grid::new((-15.0, -15.0), (115.0, 75.0), 0.1, material, |_, _| 0.0);
    for side in ["inside", "on"] {
        let settings = slot_spec(|s| {
            if side == "on" {
                s.sides_at = vec![SideChoice {
                    at: [50.0, 20.0],
                    on: None,
                    side: "on".into(),
                }];
            }
        })
        .build()
        .unwrap();
        let out = kerfcam::run(&slot_dxf(), &settings).unwrap();
        let name = format!("slot {side}");
        let errors = common::rs274_errors(&out.gcode, &format!("milling-leads-slot-{side}"));
        assert!(errors.is_empty(), "{name}: {errors:?}");
        let said: Vec<_> = (out.warnings())
            .filter(|w| w.code == "lead-arc-no-room" || w.code == "sides-not-applied")
            .map(|w| w.text.en.clone())
            .collect();
        assert!(said.is_empty(), "{name}: {said:?}");
        let moves = read(&out.gcode, 15.0);
        let (down, up) = plunges_and_lifts(&moves);
        // 2 profiles × 2 passes, each down and up off the line: in the waste.
        let wall = if side == "on" { 0.0 } else { R };
        let off = |p: &(f64, f64)| dist(*p) > wall + 0.2;
        assert_eq!((down.len(), up.len()), (4, 4), "{name}");
        assert!(down.iter().chain(&up).all(off), "{name}: {down:?} {up:?}");
        // The slot's: mid-edge, inside it, an arc R 6 tangent to a long edge.
        let slot_in: Vec<_> = (moves.iter().enumerate())
            .filter(|(_, m)| m.a == m.b && m.z.1 < 0.0 && m.z.1 < m.z.0 && in_rect(m.b, SLOT))
            .map(|(i, _)| (&moves[i + 1], &moves[i + 2]))
            .collect();
        assert_eq!(slot_in.len(), 2, "{name}");
        for (lead, joined) in slot_in {
            assert!(lead.arc.is_some() && flat(lead) && flat(joined), "{name}: {lead:?}");
            let (t, u) = (tangent(lead, true), tangent(joined, false));
            assert!(t.0 * u.0 + t.1 * u.1 > 1.0 - 1e-6, "{name}: {t:?} vs {u:?}");
            let mid = lead.b;
            assert!((mid.0 - 50.0).abs() < 1e-6, "{name}: mid-edge {mid:?}");
            assert!((lead.length() - 6.0 * std::f64::consts::FRAC_PI_2).abs() < 1e-3, "{name}");
        }
        if side == "inside" {
            let s = sweep(&g, &samples(&out.gcode, 0.05), R, -DEPTH, 0.02);
            assert_eq!(s.gouge_mm2, 0.0, "{name}: gouge at {:?}", s.gouge_at);
        }
    }
    // The operator's start on the slot's corner: kept, the arcs not cut there.
    let settings = slot_spec(|s| {
        s.starts = vec![Choice::Keyed {
            at: [30.0, 20.0],
            on: None,
        }];
    })
    .build()
    .unwrap();
    let out = kerfcam::run(&slot_dxf(), &settings).unwrap();
    let said: Vec<_> = (out.warnings())
        .filter(|w| w.code == "lead-arc-no-room")
        .collect();
    assert_eq!(said.len(), 1);
    assert!(said[0].text.en.starts_with("1 profile(s)"), "{}", said[0].text.en);
    let moves = read(&out.gcode, 15.0);
    let (down, _) = plunges_and_lifts(&moves);
    let corner = (SLOT.0 + R, SLOT.1 + R);
    let at_corner = down.iter().filter(|p| (p.0 - corner.0).hypot(p.1 - corner.1) < 1e-6);
    assert_eq!(at_corner.count(), 2, "down at the chosen corner on both passes: {down:?}");
}

/// The Eulerian order cuts trails over the graph of every path, not one
/// loop each: a router's lead arcs are not cut there. The program is the
/// one without leads — never another lead put in their place — and the
/// warning names the contours and says why.
#[test]
fn the_eulerian_order_says_a_routers_lead_arcs_are_not_cut_and_cuts_nothing_else() {
    let run = |lead: &str| {
        let settings = slot_spec(|s| {
            s.order = "eulerian".into();
            s.lead = lead.into();
        })
        .build()
        .unwrap();
        kerfcam::run(&slot_dxf(), &settings).unwrap()
    };
    let (arc, none) = (run("arc"), run("none"));
    assert_eq!(common::rs274_errors(&arc.gcode, "milling-leads-eulerian"), Vec::<String>::new());
    assert_eq!(arc.gcode, none.gcode, "arcs asked: the program is the one without leads");
    let said: Vec<_> = (arc.warnings())
        .filter(|w| w.code == "router-arcs-not-cut")
        .collect();
    assert_eq!(said.len(), 1, "{:?}", arc.warnings().map(|w| w.code).collect::<Vec<_>>());
    assert!(said[0].text.en.contains("2 cut(s) of the eulerian order"), "{}", said[0].text.en);
    assert_eq!(said[0].loops.len(), 2, "both loops named");
    assert!(said[0].at.is_some());
    // Not the order's own "no lead-in fits" (no lead was tried), and with
    // no leads asked nothing is said.
    assert!(!arc.warnings().any(|w| w.code == "eulerian-pierce-on-path"));
    assert!(!none.warnings().any(|w| w.code == "router-arcs-not-cut"));
}
