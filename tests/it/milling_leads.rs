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
use kerfcam::Spec;

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
