use super::*;
use crate::geom::Point;

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<Segment> {
    let p = [
        Point::new(x0, y0),
        Point::new(x1, y0),
        Point::new(x1, y1),
        Point::new(x0, y1),
    ];
    (0..4)
        .map(|i| Segment::line(p[i], p[(i + 1) % 4]))
        .collect()
}

fn rect_contours(w: f64, h: f64) -> Vec<crate::contour::Contour> {
    let bytes = crate::test_dxf::file(&crate::test_dxf::rect(0.0, 0.0, w, h));
    let d = crate::dxf::parse(&bytes, &crate::dxf::ReadOptions::DEFAULT).unwrap();
    crate::contour::extract(&d, crate::geom::Tolerance(0.001), 0.05).contours
}

fn tool(d: f64) -> Tool {
    Tool {
        diameter: d,
        ..Tool::OFF
    }
}

/// The cutting moves' ends and the heights they cut at.
fn cut_points(t: &Toolpath) -> Vec<(Point, f64)> {
    t.moves
        .iter()
        .filter_map(|m| match m {
            MillMove::Cut { seg, z } => Some((seg.b, *z)),
            _ => None,
        })
        .collect()
}

#[test]
fn a_50_by_30_zigzag_at_step_1_never_crosses_the_hole_and_lifts_only_for_it() {
    let pocket = Pocket::new(&rect(0.0, 0.0, 50.0, 30.0), &[], 0.01);
    let free = pocket.inset(0.5);
    let chains = zigzag::chains(&free, 1.0, 0.0, 0.01);
    assert_eq!(chains.len(), 1, "no island: one chain, no lift");
    // 29 mm of tool-centre height at most 1 mm apart: 30 passes.
    let passes = chains[0]
        .windows(2)
        .filter(|w| (w[0].y - w[1].y).abs() < 1e-9 && (w[0].x - w[1].x).abs() > 40.0)
        .count();
    assert_eq!(passes, 30);
    let hole = rect(20.0, 10.0, 30.0, 20.0);
    let pocket = Pocket::new(&rect(0.0, 0.0, 50.0, 30.0), &[&hole], 0.01);
    let free = pocket.inset(0.5);
    let chains = zigzag::chains(&free, 1.0, 0.0, 0.01);
    assert_eq!(chains.len(), 2, "one island: one lift");
    // Planted fault: a zig-zag on the region as drawn runs into the island.
    let drawn = Pocket::new(&rect(0.0, 0.0, 50.0, 30.0), &[&hole], 0.01).inset(0.0);
    let bad = zigzag::chains(&drawn, 1.0, 0.0, 0.01);
    let close = |p: Point| {
        let dx = (20.0 - p.x).max(p.x - 30.0).max(0.0);
        let dy = (10.0 - p.y).max(p.y - 20.0).max(0.0);
        dx.hypot(dy) <= 0.49
    };
    assert!(bad.iter().flatten().any(|&p| close(p)));
    // No move enters the hole grown by the tool radius.
    for ch in &chains {
        for w in ch.windows(2) {
            for k in 0..=100 {
                let p = w[0].add(w[1].sub(w[0]).scale(k as f64 / 100.0));
                // Distance to the island's square, less the tool radius.
                let dx = (20.0 - p.x).max(p.x - 30.0).max(0.0);
                let dy = (10.0 - p.y).max(p.y - 20.0).max(0.0);
                assert!(dx.hypot(dy) > 0.5 - 0.01, "{p:?} in the island");
            }
        }
    }
}

#[test]
fn a_pocket_is_cut_in_n_equal_depths_paper_004_case_3() {
    // H = 64.8, d_max = 15: 5 depths of 12.96, each cleared before the next.
    let passes = Passes {
        depth: 64.8,
        pass_depth: 15.0,
    };
    let contours = rect_contours(40.0, 30.0);
    let g = MillGeometry {
        pockets: contours,
        ..MillGeometry::default()
    };
    let h = Heights {
        retract: 5.0,
        tolerance: 0.001,
    };
    let m = plan(&g, &tool(10.0), passes, h, Point::new(0.0, 0.0));
    let mut depths: Vec<f64> = Vec::new();
    for (_, z) in cut_points(&m.toolpath) {
        if depths.last() != Some(&z) {
            depths.push(z);
        }
    }
    // Entries plunge; every flat cut is at one of the five depths, in order.
    let want: Vec<f64> = (1..=5).map(|k| -12.96 * k as f64).collect();
    assert_eq!(depths.len(), 5, "{depths:?}");
    for (d, w) in depths.iter().zip(&want) {
        assert!((d - w).abs() < 1e-9, "{depths:?}");
    }
    assert_eq!(m.pockets.len(), 1);
    assert_eq!(m.pockets[0].lifts, 0);
}

#[test]
fn a_pocket_narrower_than_the_tool_is_said_and_not_cut() {
    let contours = rect_contours(40.0, 5.0);
    let g = MillGeometry {
        pockets: contours,
        ..MillGeometry::default()
    };
    let passes = Passes {
        depth: 3.0,
        pass_depth: 3.0,
    };
    let h = Heights {
        retract: 5.0,
        tolerance: 0.001,
    };
    let m = plan(&g, &tool(6.0), passes, h, Point::new(0.0, 0.0));
    assert!(m.warnings.iter().any(|w| w.code == "pocket-too-narrow"));
    assert!(cut_points(&m.toolpath).is_empty());
}

#[test]
fn climb_cuts_the_walls_counter_clockwise_and_conventional_the_other_way() {
    // A rectangular pocket cleared contour-parallel: every loop runs the
    // way the milling asks, the wall on the tool's right when climbing
    // with a clockwise spindle (counter-clockwise round an outline).
    let g = MillGeometry {
        pockets: rect_contours(40.0, 30.0),
        ..MillGeometry::default()
    };
    let passes = Passes {
        depth: 3.0,
        pass_depth: 3.0,
    };
    let h = Heights {
        retract: 5.0,
        tolerance: 0.001,
    };
    let turning = |climb: bool| {
        let t = Tool {
            climb,
            pocket: crate::process::PocketStrategy::Offset,
            ..tool(6.0)
        };
        let m = plan(&g, &t, passes, h, Point::new(0.0, 0.0));
        // Twice the signed area swept by the flat cuts at the depth.
        (m.toolpath.moves.iter())
            .filter_map(|mv| match mv {
                MillMove::Cut { seg, z } if *z == -3.0 => Some(seg.a.cross(seg.b)),
                _ => None,
            })
            .sum::<f64>()
    };
    let (climb, conventional) = (turning(true), turning(false));
    assert!(climb > 100.0, "climb: {climb}");
    assert!(conventional < -100.0, "conventional: {conventional}");
}
