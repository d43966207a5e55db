//! Contour-parallel pockets cut from the centre outwards or from the walls
//! inwards (issue 43 §2, paper 004 §5.3's R 20 pocket): the loops' order,
//! the tool kept down between loops, and no gouge by the independent
//! checker of `common::mill_sweep` — each program read by rs274.
#![cfg(not(target_arch = "wasm32"))]

use crate::common;

use common::mill_sweep::{samples, sweep, Cell, Grid};
use kerfcam::mill::MillMove;
use kerfcam::Spec;

/// The R 20 pocket's centre (the drawing's zero stays the program's).
const C: (f64, f64) = (30.0, 30.0);

fn circle_dxf() -> Vec<u8> {
    let e = format!("0\nCIRCLE\n8\nPOCKET\n10\n{}\n20\n{}\n40\n20\n", C.0, C.1);
    format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{e}0\nENDSEC\n0\nEOF\n").into_bytes()
}

fn spec(from: &str) -> Spec {
    Spec {
        tool_diameter: Some(2.0),
        stepover: 100.0,
        pocket: "offset".into(),
        pocket_from: from.into(),
        depth: Some(3.0),
        pass_depth: 3.0,
        post: Some("linuxcnc-router".into()),
        layer_ops: vec![["POCKET".into(), "pocket".into()]],
        verify: true,
        ..Spec::default()
    }
}

/// The radii of the loops the flat cuts at `z` run on, in the order cut
/// (a link's end is on the loop it leads to).
fn loop_radii(moves: &[MillMove], z: f64) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    for m in moves {
        if let MillMove::Cut { seg, z: h } = m {
            if *h != z {
                continue;
            }
            let r = ((seg.b.x - C.0).hypot(seg.b.y - C.1) * 1000.0).round() / 1000.0;
            if out.last() != Some(&r) {
                out.push(r);
            }
        }
    }
    out
}

#[test]
fn an_r20_pocket_is_cut_from_the_walls_inwards_or_the_centre_outwards_without_lifting() {
    let g = Grid::new(
        (C.0 - 22.0, C.1 - 22.0),
        (C.0 + 22.0, C.1 + 22.0),
        0.1,
        |x, y| {
            if (x - C.0).hypot(y - C.1) < 20.0 {
                Cell::Pocket
            } else {
                Cell::Keep
            }
        },
        |x, y| 20.0 - (x - C.0).hypot(y - C.1),
    );
    let walls: Vec<f64> = (0..10).map(|k| 19.0 - 2.0 * k as f64).collect();
    let centre: Vec<f64> = walls.iter().rev().copied().collect();
    for (from, want) in [("walls", walls), ("centre", centre)] {
        let out = kerfcam::run(&circle_dxf(), &spec(from).build().unwrap()).unwrap();
        let errors = common::rs274_errors(&out.gcode, &format!("milling-offset-{from}"));
        assert!(errors.is_empty(), "{from}: {errors:?}");
        let m = out.milled.as_ref().unwrap();
        assert_eq!(loop_radii(&m.toolpath.moves, -3.0), want, "{from}");
        // Each link a stepover long, inside the walls: no lift.
        assert_eq!(m.pockets[0].lifts, 0, "{from}");
        let s = sweep(&g, &samples(&out.gcode, 0.05), 1.0, -3.0, 0.02);
        let pct = 100.0 * s.cleared_mm2 / s.reachable_mm2;
        eprintln!(
            "R 20 from the {from}: {} lines, cleared {pct:.2} %, gouge {:.3} mm²",
            out.gcode.lines().count(),
            s.gouge_mm2
        );
        assert_eq!(s.gouge_mm2, 0.0, "{from}: gouge at {:?}", s.gouge_at);
        assert!(pct >= 99.0, "{from}: cleared {pct:.2} %");
        let own = m.swept.as_ref().unwrap();
        assert_eq!((own.gouge_mm2, own.left_mm2), (0.0, 0.0), "{from}: {own:?}");
    }
    // An unknown order is refused by its field.
    assert_eq!(
        spec("middle").build().map(|_| ()).map_err(|e| e.field),
        Err("pocket_from")
    );
}

#[test]
fn from_the_walls_a_pocket_around_an_island_cuts_the_walls_first_and_never_gouges() {
    // common's 60 × 40 pocket round an R 8 island at (30, 20), a 6 mm
    // tool at 40 %: the first loop runs along the walls (3 mm in), the
    // last ones between the island and the walls far from both.
    let mut sp = spec("walls");
    sp.tool_diameter = Some(6.0);
    sp.stepover = 40.0;
    sp.entry = "helix".into();
    let out = kerfcam::run(&common::pocket_island_dxf(false), &sp.build().unwrap()).unwrap();
    let errors = common::rs274_errors(&out.gcode, "milling-offset-walls-island");
    assert!(errors.is_empty(), "{errors:?}");
    let m = out.milled.as_ref().unwrap();
    let first = m.toolpath.moves.iter().find_map(|mv| match mv {
        MillMove::Cut { seg, z } if *z == -3.0 => Some(seg.b),
        _ => None,
    });
    let p = first.unwrap();
    let to_wall = p.x.min(60.0 - p.x).min(p.y).min(40.0 - p.y);
    let to_island = (p.x - 30.0).hypot(p.y - 20.0) - 8.0;
    assert!(
        (to_wall - 3.0).abs() < 1e-6 || (to_island - 3.0).abs() < 1e-6,
        "the first loop is at the tool's radius from a wall: {p:?}"
    );
    let inside = |x: f64, y: f64| (0.0..60.0).contains(&x) && (0.0..40.0).contains(&y);
    let g = Grid::new(
        (-2.0, -2.0),
        (62.0, 42.0),
        0.2,
        |x, y| {
            if inside(x, y) && (x - 30.0).hypot(y - 20.0) > 8.0 {
                Cell::Pocket
            } else {
                Cell::Keep
            }
        },
        |x, y| {
            let wall = x.min(60.0 - x).min(y).min(40.0 - y);
            wall.min((x - 30.0).hypot(y - 20.0) - 8.0)
        },
    );
    let s = sweep(&g, &samples(&out.gcode, 0.1), 3.0, -3.0, 0.05);
    let pct = 100.0 * s.cleared_mm2 / s.reachable_mm2;
    eprintln!(
        "island from the walls: cleared {pct:.2} %, gouge {:.3} mm², lifts {}",
        s.gouge_mm2, m.pockets[0].lifts
    );
    assert_eq!(s.gouge_mm2, 0.0, "gouge at {:?}", s.gouge_at);
    assert!(pct >= 99.0, "cleared {pct:.2} %");
    // Planted fault: the checker sees a wider disc gouge.
    assert!(sweep(&g, &samples(&out.gcode, 0.1), 3.5, -3.0, 0.05).gouge_mm2 > 0.0);
}
