//! Tests of the entity builders (kept apart so entities.rs stays near 400 lines).

use super::*;

fn pairs(src: &[(i32, &'static str)]) -> Vec<Pair<'static>> {
    crate::dxf::pairs::text_pairs(src)
}

#[test]
fn arc_from_0_to_270_degrees_is_split_into_two_pieces() {
    let p = pairs(&[(10, "-50"), (20, "50"), (40, "10"), (50, "0"), (51, "270")]);
    let (segs, closed) = arc(&p).unwrap();
    assert!(!closed);
    assert_eq!(segs.len(), 2);
    assert!((segs[0].a.x + 40.0).abs() < 1e-12 && (segs[0].a.y - 50.0).abs() < 1e-12);
    assert!((segs[1].b.x + 50.0).abs() < 1e-9 && (segs[1].b.y - 40.0).abs() < 1e-9);
    assert!(segs.iter().all(|s| s.is_ccw()));
}

#[test]
fn negative_z_extrusion_mirrors_an_arc_and_reverses_its_turn() {
    let p = pairs(&[
        (10, "10"),
        (20, "0"),
        (40, "5"),
        (50, "0"),
        (51, "90"),
        (230, "-1"),
    ]);
    let (segs, _) = arc(&p).unwrap();
    let (m, tilted) = ocs(&p, 30);
    assert!(!tilted);
    let mut out = vec![];
    crate::geom::transform_segments(&segs, &m, 0.01, &mut out);
    assert!((out[0].a.x + 15.0).abs() < 1e-12, "{:?}", out[0].a);
    assert!(!out[0].is_ccw());
}

#[test]
fn tilted_extrusion_follows_the_arbitrary_axis_algorithm() {
    // N = (1, 0, 0): Ax = Wz × N = (0, 1, 0), Ay = N × Ax = (0, 0, 1): OCS x is world y.
    let p = pairs(&[(210, "1"), (220, "0"), (230, "0"), (30, "7")]);
    let (m, tilted) = ocs(&p, 30);
    assert!(tilted);
    let q = m.apply(Point::new(2.0, 3.0));
    assert!(
        (q.x - 7.0).abs() < 1e-12 && (q.y - 2.0).abs() < 1e-12,
        "{q:?}"
    );
}

#[test]
fn closed_lwpolyline_with_bulge_makes_a_slot() {
    let p = pairs(&[
        (90, "4"),
        (70, "1"),
        (10, "0"),
        (20, "0"),
        (10, "20"),
        (20, "0"),
        (42, "1"),
        (10, "20"),
        (20, "10"),
        (10, "0"),
        (20, "10"),
        (42, "1"),
    ]);
    let (segs, closed) = lwpolyline(&p).unwrap();
    assert!(closed);
    assert_eq!(segs.len(), 4);
    let area = crate::geom::loop_area(&segs);
    let expected = 20.0 * 10.0 + std::f64::consts::PI * 25.0;
    assert!((area - expected).abs() < 1e-9, "{area}");
}

#[test]
fn huge_coordinates_are_rejected_with_a_reason() {
    let p = pairs(&[(10, "1e300"), (20, "0"), (11, "1"), (21, "1")]);
    assert!(line(&p).unwrap_err().en.contains("out of range"));
    let p = pairs(&[(10, "NaN"), (20, "0"), (11, "1"), (21, "1")]);
    assert!(line(&p).is_err());
}

#[test]
fn circle_is_arc_pieces_bit_for_bit() {
    for (x, y, r) in [(25.0, 30.0, 10.0), (-1e6, 3.3, 0.001), (0.1, -7.25, 1234.5)] {
        let text = [x, y, r].map(|v| format!("{v}"));
        let p = [(10, &text[0]), (20, &text[1]), (40, &text[2])]
            .iter()
            .map(|&(code, v)| Pair {
                code,
                value: crate::dxf::pairs::Value::Text(v.as_bytes()),
                at: 1,
            })
            .collect::<Vec<_>>();
        let (segs, closed) = circle(&p).unwrap();
        let want = arc_pieces(Point::new(x, y), r, 0.0, std::f64::consts::TAU);
        assert!(closed);
        let bits = |s: &[Segment]| {
            s.iter()
                .flat_map(|s| [s.a.x, s.a.y, s.b.x, s.b.y, s.bulge])
                .map(f64::to_bits)
                .collect::<Vec<_>>()
        };
        assert_eq!(bits(&segs), bits(&want));
    }
}

#[test]
fn zero_radius_circle_is_rejected() {
    let p = pairs(&[(10, "0"), (20, "0"), (40, "0")]);
    assert!(circle(&p).is_err());
}
