use super::*;
use crate::geom::dist_to_segment;
use crate::plan::Order;
use crate::test_dxf;

/// Closed LWPOLYLINEs through `(x, y)` points, mm.
fn drawing(loops: &[Vec<(f64, f64)>]) -> Vec<u8> {
    let body: String = loops.iter().map(|pts| test_dxf::outline(pts)).collect();
    test_dxf::file(&body)
}

/// A 50 × 30 plate with slots down from its top edge: `(centre x, width, depth)`.
fn plate(slots: &[(f64, f64, f64)]) -> Vec<(f64, f64)> {
    let mut pts = vec![(0.0, 0.0), (50.0, 0.0), (50.0, 30.0)];
    let mut slots = slots.to_vec();
    slots.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (x, w, d) in slots {
        pts.extend([
            (x + w / 2.0, 30.0),
            (x + w / 2.0, 30.0 - d),
            (x - w / 2.0, 30.0 - d),
            (x - w / 2.0, 30.0),
        ]);
    }
    pts.push((0.0, 30.0));
    pts
}

fn run(bytes: &[u8], order: Order) -> crate::Output {
    let s = crate::Settings::new(1.5, 0.001, 2000.0)
        .unwrap()
        .with_order(order)
        .unwrap();
    crate::run(bytes, &s).unwrap()
}

fn warned(out: &crate::Output) -> Option<String> {
    out.warnings()
        .find(|w| w.code == "features-narrower-than-kerf")
        .map(|w| w.text.en.clone())
}

/// The drawing's features, from the contours as read (the checks below
/// hold the figures to what the geometry gives by hand).
fn found(out: &crate::Output) -> Narrow {
    let mut all = Narrow::default();
    for c in &out.contours.contours {
        if c.part.is_some() && c.is_closed() {
            all.add(of_contour(c, 1.5, 0.01, &mut Scratch::default()));
        }
    }
    all
}

#[test]
fn a_slot_narrower_than_the_kerf_is_one_feature_with_its_width_walls_and_area() {
    // 1 mm wide, 10 mm deep: both walls 10 mm, 1 × 10 mm² left.
    let out = run(&drawing(&[plate(&[(25.0, 1.0, 10.0)])]), Order::Contour);
    let n = found(&out);
    assert_eq!((n.features, n.parts.clone()), (1, vec![1]), "{n:?}");
    assert!((n.width - 1.0).abs() < 1e-6, "{n:?}");
    assert!((n.length - 20.0).abs() < 0.2, "{n:?}");
    assert!((n.area - 10.0).abs() < 0.2, "{n:?}");
    let text = warned(&out).unwrap();
    assert!(
        text.starts_with("1 slot(s) or notch(es) of 1 part(s) (1)"),
        "{text}"
    );
    assert!(
        text.contains("down to 1.00 mm wide along 20.0 mm"),
        "{text}"
    );
    // What the warning says is what the kerf stage made: its path stays
    // more than half a kerf from the slot's walls (it never enters), while
    // it runs half a kerf from the plate's long bottom edge.
    let path = &out
        .kerf
        .paths
        .iter()
        .find(|p| p.part == Some(1))
        .unwrap()
        .segments;
    let to_path = |p: Point| {
        path.iter()
            .map(|s| dist_to_segment(p, s))
            .fold(f64::INFINITY, f64::min)
    };
    let (wall, bottom) = (
        to_path(Point::new(24.5, 25.0)),
        to_path(Point::new(10.0, 0.0)),
    );
    assert!(wall > 0.75 + 0.5, "{wall}");
    assert!((bottom - 0.75).abs() < 1e-3, "{bottom}");
}

#[test]
fn a_slot_as_wide_as_the_kerf_or_wider_and_square_corners_are_not_features() {
    for slots in [vec![], vec![(25.0, 2.0, 10.0)], vec![(25.0, 1.5, 10.0)]] {
        let out = run(&drawing(&[plate(&slots)]), Order::Contour);
        assert_eq!(found(&out).features, 0, "{slots:?}");
        assert!(warned(&out).is_none(), "{slots:?}");
    }
    // An L-shaped plate: its inner corner is square.
    let l = vec![
        (0.0, 0.0),
        (40.0, 0.0),
        (40.0, 10.0),
        (10.0, 10.0),
        (10.0, 40.0),
        (0.0, 40.0),
    ];
    assert!(warned(&run(&drawing(&[l]), Order::Contour)).is_none());
}

#[test]
fn a_comb_counts_each_slot_and_notches_shallower_than_a_kerf_are_corners() {
    // Three 1 mm slots 8 mm deep and a 1 mm notch 0.5 mm deep (its
    // walls 0.5 mm long: the corners' rounding, said as invalid vertices).
    let out = run(
        &drawing(&[plate(&[
            (10.0, 1.0, 8.0),
            (20.0, 1.0, 8.0),
            (30.0, 1.0, 8.0),
            (40.0, 1.0, 0.5),
        ])]),
        Order::Contour,
    );
    let n = found(&out);
    assert_eq!(n.features, 3, "{n:?}");
    assert!((n.length - 48.0).abs() < 0.3, "{n:?}");
    // A V notch of 20° narrows below the kerf 4.1 mm from its tip; one of
    // 90° never does.
    let v = |half: f64| {
        let (d, x) = (10.0, 10.0 * half.to_radians().tan());
        vec![
            (0.0, 0.0),
            (50.0, 0.0),
            (50.0, 30.0),
            (25.0 + x, 30.0),
            (25.0, 30.0 - d),
            (25.0 - x, 30.0),
            (0.0, 30.0),
        ]
    };
    assert_eq!(
        found(&run(&drawing(&[v(10.0)]), Order::Contour)).features,
        1
    );
    assert_eq!(
        found(&run(&drawing(&[v(45.0)]), Order::Contour)).features,
        0
    );
}

#[test]
fn a_hole_with_a_narrow_slot_is_a_feature_of_its_part_in_every_order() {
    // A plate with a 10 × 10 hole, a 1 mm slot 6 mm long leaving its side,
    // and a second plate, spaced apart.
    let hole = vec![
        (20.0, 20.0),
        (30.0, 20.0),
        (30.0, 24.5),
        (36.0, 24.5),
        (36.0, 25.5),
        (30.0, 25.5),
        (30.0, 30.0),
        (20.0, 30.0),
    ];
    let outer = vec![(0.0, 0.0), (50.0, 0.0), (50.0, 50.0), (0.0, 50.0)];
    let other = vec![(60.0, 0.0), (80.0, 0.0), (80.0, 20.0), (60.0, 20.0)];
    let bytes = drawing(&[other, outer, hole]);
    for order in [
        Order::Contour,
        Order::Chained,
        Order::Eulerian,
        Order::Drawing,
    ] {
        let out = run(&bytes, order);
        let text = warned(&out).unwrap_or_else(|| panic!("{order:?}: no warning"));
        assert!(
            text.contains("1 slot(s) or notch(es) of 1 part(s)"),
            "{order:?}: {text}"
        );
        assert!(
            text.contains("down to 1.00 mm wide along 12.0 mm"),
            "{order:?}: {text}"
        );
    }
}

#[test]
fn the_controller_s_compensation_is_said_and_no_kerf_no_warning() {
    let n = Narrow {
        parts: vec![2],
        features: 1,
        width: 1.0,
        at: Some(Point::new(1.0, 2.0)),
        length: 20.0,
        area: 10.0,
        loops: Vec::new(),
    };
    let w = n.warning(1.5, true).unwrap();
    assert!(
        w.text.en.contains("controller's compensation"),
        "{}",
        w.text.en
    );
    assert!(
        w.text.pt.contains("compensação do controlador"),
        "{}",
        w.text.pt
    );
    assert_eq!(w.at, Some(Point::new(1.0, 2.0)));
    assert!(Narrow::default().warning(1.5, false).is_none());
    let s = crate::Settings::new(0.0, 0.001, 2000.0).unwrap();
    let out = crate::run(&drawing(&[plate(&[(25.0, 1.0, 10.0)])]), &s).unwrap();
    assert!(warned(&out).is_none());
}

#[test]
fn plain_outlines_are_not_sampled_at_all() {
    // A plate with a round hole and a square hole: no segment has another
    // its scrap-side rays could meet, so nothing is sampled (the 20,000-
    // part nest of benches/pipeline.rs is made of these).
    let mut bytes = String::from_utf8(drawing(&[
        vec![(0.0, 0.0), (100.0, 0.0), (100.0, 60.0), (0.0, 60.0)],
        vec![(60.0, 20.0), (80.0, 20.0), (80.0, 40.0), (60.0, 40.0)],
    ]))
    .unwrap();
    let circle = "0\nCIRCLE\n8\n0\n10\n25\n20\n30\n40\n10\n";
    bytes = bytes.replacen(
        "0\nENDSEC\n0\nEOF",
        &format!("{circle}0\nENDSEC\n0\nEOF"),
        1,
    );
    let out = run(bytes.as_bytes(), Order::Contour);
    let closed: Vec<_> = out
        .contours
        .contours
        .iter()
        .filter(|c| c.is_closed())
        .collect();
    assert_eq!(closed.len(), 3);
    for c in closed {
        let left = (c.area > 0.0) == (c.kind == ContourKind::Hole);
        let mut s = Scratch::default();
        facing_pairs(&c.segments, 1.5, left, 0.01, &mut s);
        assert!(s.pairs.is_empty(), "{:?}: {:?}", c.kind, s.pairs);
    }
    // A round hole 1.2 mm across (narrower than the kerf, not vanished
    // when the kerf is 1.0): its arcs face each other.
    let small = crate::geom::Segment {
        a: Point::new(0.6, 0.0),
        b: Point::new(-0.6, 0.0),
        bulge: 1.0,
    };
    let segs = [
        small,
        crate::geom::Segment {
            a: small.b,
            b: small.a,
            bulge: 1.0,
        },
    ];
    let mut s = Scratch::default();
    facing_pairs(&segs, 1.5, true, 0.01, &mut s);
    assert_eq!(s.pairs, [(0, 0), (0, 1), (1, 0), (1, 1)]);
}
