use super::*;
use crate::mill::{plan, Heights, MillGeometry};
use crate::process::{Passes, PocketStrategy, Tool};

const R: f64 = 3.0;
const DEPTH: f64 = 6.0;

/// A 60 × 40 pocket around a round island of R 8 at (30, 20), planned
/// with a 6 mm tool `strategy`, 6 mm deep in 2 passes.
fn milled(strategy: PocketStrategy) -> crate::mill::Milled {
    let entities =
        crate::test_dxf::rect(0.0, 0.0, 60.0, 40.0) + "0\nCIRCLE\n8\n0\n10\n30\n20\n20\n40\n8\n";
    let bytes = crate::test_dxf::file(&entities);
    let d = crate::dxf::parse(&bytes, &crate::dxf::ReadOptions::DEFAULT).unwrap();
    let contours = crate::contour::extract(&d, crate::geom::Tolerance(0.001), 0.05).contours;
    let g = MillGeometry {
        pockets: contours,
        ..MillGeometry::default()
    };
    let tool = Tool {
        diameter: 2.0 * R,
        pocket: strategy,
        ..Tool::OFF
    };
    let passes = Passes {
        depth: DEPTH,
        pass_depth: 3.0,
    };
    let h = Heights {
        retract: 2.0,
        tolerance: 0.01,
    };
    plan(&g, &tool, passes, h, Point::new(0.0, 0.0))
}

fn swept(m: &crate::mill::Milled) -> Swept {
    sweep(&m.toolpath, &m.spans, R, DEPTH, 2.0, 0.01)
}

#[test]
fn a_planned_pocket_sweeps_clean_and_its_corners_are_out_of_reach() {
    for strategy in [PocketStrategy::ZigZag, PocketStrategy::Offset] {
        let m = milled(strategy);
        assert_eq!(m.spans.len(), 1);
        let s = swept(&m);
        assert_eq!(s.gouge_mm2, 0.0, "{strategy:?}: gouge at {:?}", s.gouge_at);
        assert_eq!(s.left_mm2, 0.0, "{strategy:?}: left at {:?}", s.left_at);
        // The four corners a 6 mm disc cannot reach: 4 (r² − πr²/4).
        let corners = 4.0 * R * R * (1.0 - std::f64::consts::FRAC_PI_4);
        assert!(
            (s.unreachable_mm2 - corners).abs() < 1.5,
            "{strategy:?}: {} vs {corners}",
            s.unreachable_mm2
        );
    }
}

#[test]
fn a_move_into_the_island_is_a_gouge_and_a_pass_dropped_leaves_material() {
    // Planted: a cut at full depth from the finishing loop round the
    // island (R 11: its left point at (19, 20)) 1 mm towards the island,
    // and back: the disc takes 1 mm of its wall.
    let mut m = milled(PocketStrategy::ZigZag);
    let i = (m.toolpath.moves.iter())
        .rposition(|mv| matches!(mv, MillMove::Cut { z, .. } if *z == -DEPTH))
        .unwrap();
    let (from, into) = (Point::new(19.0, 20.0), Point::new(20.0, 20.0));
    let planted = [
        MillMove::Cut {
            seg: Segment::line(from, into),
            z: -DEPTH,
        },
        MillMove::Cut {
            seg: Segment::line(into, from),
            z: -DEPTH,
        },
    ];
    m.toolpath.moves.splice(i + 1..i + 1, planted);
    let s = swept(&m);
    assert!(s.gouge_mm2 > 1.0, "{s:?}");
    let at = s.gouge_at.unwrap();
    assert!(at.dist(Point::new(22.0, 20.0)) < 2.0, "said where: {at:?}");
    assert_eq!(s.left_mm2, 0.0);
    // Planted: the last depth's cuts after its first ten dropped.
    let mut m = milled(PocketStrategy::ZigZag);
    let last = (m.toolpath.moves.iter())
        .position(|mv| matches!(mv, MillMove::Cut { z, .. } if *z == -DEPTH))
        .unwrap();
    let mut kept = 0;
    m.toolpath.moves.retain(|mv| match mv {
        MillMove::Cut { z, .. } if *z == -DEPTH => {
            kept += 1;
            kept <= 10
        }
        _ => true,
    });
    assert!(last > 0);
    let s = swept(&m);
    assert!(s.left_mm2 > 500.0, "{s:?}");
    assert_eq!(s.gouge_mm2, 0.0);
    let at = s.left_at.unwrap();
    assert!(
        (0.0..=60.0).contains(&at.x) && (0.0..=40.0).contains(&at.y),
        "{at:?}"
    );
}

#[test]
fn a_swept_piece_marks_its_capsule() {
    // A 40 mm piece at 30° swept by a disc of 2: 2·2·40 + π·4 mm².
    let g = Grid {
        x0: -10.0,
        y0: -10.0,
        cell: 0.05,
        nx: 1200,
        ny: 1000,
    };
    let mut cells = vec![false; g.nx * g.ny];
    let (a, b) = (Point::new(0.0, 0.0), Point::new(40.0 * 0.866_025_4, 20.0));
    stamp(&g, &mut cells, a, b, 2.0);
    let area = cells.iter().filter(|&&c| c).count() as f64 * g.cell * g.cell;
    let want = 4.0 * 40.0 + std::f64::consts::PI * 4.0;
    assert!((area - want).abs() < 0.01 * want, "{area} vs {want}");
    // Every marked cell's centre within 2 of the piece, and the unmarked
    // ones beyond it (to a cell's half diagonal).
    let seg = Segment::line(a, b);
    for j in (0..g.ny).step_by(7) {
        for i in (0..g.nx).step_by(7) {
            let d = crate::geom::dist_to_segment(g.centre(i, j), &seg);
            let c = cells[j * g.nx + i];
            assert!(!c || d <= 2.0 + 1e-9, "{i} {j} marked at {d}");
            assert!(c || d >= 2.0 - 1e-9, "{i} {j} not marked at {d}");
        }
    }
}
