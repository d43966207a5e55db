//! Geometry properties over every start vertex and both directions (as
//! cavalier_contours tests its offsets): area, length, orientation, nesting,
//! and the kerf path's distance from the contour.
#![cfg(not(target_arch = "wasm32"))]

use kerfcam::contour::{self, ContourKind};
use kerfcam::dxf::{Drawing, Entity};
use kerfcam::geom::{dist_to_segment, loop_area, path_length, Point, Segment, Tolerance};
use kerfcam::kerf::{self, Join, Kerf};

const PI: f64 = std::f64::consts::PI;

/// A closed loop from (x, y, bulge) vertices.
fn shape(v: &[(f64, f64, f64)]) -> Vec<Segment> {
    (0..v.len())
        .map(|i| {
            let (x, y, b) = v[i];
            let (x2, y2, _) = v[(i + 1) % v.len()];
            Segment {
                a: Point::new(x, y),
                b: Point::new(x2, y2),
                bulge: b,
            }
        })
        .collect()
}

/// Every rotation of the start and both directions of a loop.
fn variants(segs: &[Segment]) -> Vec<Vec<Segment>> {
    let mut out = Vec::new();
    for k in 0..segs.len() {
        let mut r = segs.to_vec();
        r.rotate_left(k);
        out.push(r.iter().rev().map(Segment::reversed).collect());
        out.push(r);
    }
    out
}

/// Each segment as its own LINE/ARC entity (so chaining is exercised), shuffled by a stride.
fn drawing(loops: &[Vec<Segment>]) -> Drawing {
    let mut entities = Vec::new();
    for l in loops {
        let n = l.len();
        // A stride coprime with n visits every segment once, out of order.
        let gcd = |mut a: usize, mut b: usize| {
            while b != 0 {
                (a, b) = (b, a % b);
            }
            a
        };
        let stride = (3..).find(|&k| gcd(k, n) == 1).unwrap_or(1);
        for i in 0..n {
            let s = l[(i * stride + 1) % n];
            let s = if i % 2 == 0 { s.reversed() } else { s };
            entities.push(Entity {
                kind: "LINE",
                layer: 0,
                place: kerfcam::dxf::Place::Line(0),
                segments: vec![s],
                closed: false,
                source: None,
                insert: None,
            });
        }
    }
    Drawing {
        entities,
        ..Drawing::default()
    }
}

fn plate() -> Vec<Segment> {
    // 60 × 40 with a semicircular bump on top (r 10) and a notch (concave corners) at the bottom.
    shape(&[
        (0.0, 0.0, 0.0),
        (25.0, 0.0, 0.0),
        (25.0, 5.0, 0.0),
        (35.0, 5.0, 0.0),
        (35.0, 0.0, 0.0),
        (60.0, 0.0, 0.0),
        (60.0, 40.0, 0.0),
        (40.0, 40.0, 1.0),
        (20.0, 40.0, 0.0),
        (0.0, 40.0, 0.0),
    ])
}

fn slot_hole() -> Vec<Segment> {
    shape(&[
        (15.0, 15.0, 0.0),
        (45.0, 15.0, 1.0),
        (45.0, 25.0, 0.0),
        (15.0, 25.0, 1.0),
    ])
}

fn plate_area() -> f64 {
    60.0 * 40.0 - 50.0 + PI * 50.0
}

#[test]
fn area_length_and_nesting_do_not_depend_on_start_or_direction() {
    let slot_area = 300.0 + PI * 25.0;
    for outer in variants(&plate()) {
        for hole in variants(&slot_hole()).into_iter().step_by(3) {
            let d = drawing(&[outer.clone(), hole.clone()]);
            let cs = contour::extract(&d, Tolerance::DEFAULT, 0.0);
            assert_eq!(cs.contours.len(), 2);
            let o = cs
                .contours
                .iter()
                .find(|c| c.kind == ContourKind::Outer)
                .expect("outer");
            let h = cs
                .contours
                .iter()
                .find(|c| c.kind == ContourKind::Hole)
                .expect("hole");
            assert!((o.area.abs() - plate_area()).abs() < 1e-9, "{}", o.area);
            assert!((h.area.abs() - slot_area).abs() < 1e-9);
            assert!((o.length - path_length(&plate())).abs() < 1e-9);
            assert_eq!(h.depth, 1);
            assert_eq!(h.part, o.part);
        }
    }
}

#[test]
fn kerf_path_stays_exactly_half_the_kerf_from_the_contour() {
    let half = 1.25;
    for outer in variants(&plate()) {
        let d = drawing(&[outer.clone(), slot_hole()]);
        let cs = contour::extract(&d, Tolerance::DEFAULT, 0.0);
        let paths = kerf::offset(
            &cs,
            Kerf {
                width: 2.0 * half,
                join: Join::Round,
                threads: kerfcam::par::Threads::ONE,
            },
            Tolerance::DEFAULT,
        );
        assert_eq!(paths.paths.len(), 2);
        for p in &paths.paths {
            assert!(
                loop_area(&p.segments) > 0.0,
                "kerf paths are counter-clockwise"
            );
            let src = &cs.contours[p.contour].segments;
            for s in &p.segments {
                for t in [0.0, 0.25, 0.5, 0.75] {
                    let q = s.point_at(t);
                    let dist = src
                        .iter()
                        .map(|c| dist_to_segment(q, c))
                        .fold(f64::INFINITY, f64::min);
                    assert!(
                        (dist - half).abs() < 1e-6,
                        "{:?} point at {dist} mm, not {half}",
                        p.kind
                    );
                }
            }
            // Outward for the outer (grows), inward for the hole (shrinks).
            let a0 = cs.contours[p.contour].area.abs();
            let a1 = loop_area(&p.segments);
            match p.kind {
                ContourKind::Outer => assert!(a1 > a0),
                _ => assert!(a1 < a0),
            }
        }
        // The slot hole shrinks exactly: straight sides 2·half closer, ends r − half.
        let hole = paths
            .paths
            .iter()
            .find(|p| p.kind == ContourKind::Hole)
            .unwrap();
        let expected = 30.0 * (10.0 - 2.0 * half) + PI * (5.0 - half).powi(2);
        assert!((loop_area(&hole.segments) - expected).abs() < 1e-6);
        // Concave for a tool outside the part: the notch's two inside corners and
        // the two corners where the bump rises from the top edge.
        let mut v: Vec<(i64, i64)> = paths
            .invalid_vertices
            .iter()
            .map(|p| (p.x.round() as i64, p.y.round() as i64))
            .collect();
        v.sort();
        assert_eq!(v, vec![(20, 40), (25, 5), (35, 5), (40, 40)]);
    }
}

#[test]
fn a_hole_smaller_than_the_kerf_is_reported_and_not_cut() {
    let circle = kerfcam::geom::arc_pieces(Point::new(30.0, 20.0), 0.4, 0.0, 2.0 * PI);
    let d = drawing(&[plate(), circle]);
    let cs = contour::extract(&d, Tolerance::DEFAULT, 0.0);
    let paths = kerf::offset(
        &cs,
        Kerf {
            width: 1.0,
            join: Join::Round,
            threads: kerfcam::par::Threads::ONE,
        },
        Tolerance::DEFAULT,
    );
    assert_eq!(paths.paths.len(), 1);
    assert!(paths
        .warnings
        .iter()
        .any(|w| w.message().contains("vanishes")));
}

#[test]
fn a_hole_with_a_neck_narrower_than_the_kerf_splits_and_is_reported() {
    // Two 10 × 10 squares joined by a 0.5 mm wide neck.
    let dumbbell = shape(&[
        (5.0, 15.0, 0.0),
        (15.0, 15.0, 0.0),
        (15.0, 19.75, 0.0),
        (25.0, 19.75, 0.0),
        (25.0, 15.0, 0.0),
        (35.0, 15.0, 0.0),
        (35.0, 25.0, 0.0),
        (25.0, 25.0, 0.0),
        (25.0, 20.25, 0.0),
        (15.0, 20.25, 0.0),
        (15.0, 25.0, 0.0),
        (5.0, 25.0, 0.0),
    ]);
    let d = drawing(&[plate(), dumbbell]);
    let cs = contour::extract(&d, Tolerance::DEFAULT, 0.0);
    let paths = kerf::offset(
        &cs,
        Kerf {
            width: 2.0,
            join: Join::Round,
            threads: kerfcam::par::Threads::ONE,
        },
        Tolerance::DEFAULT,
    );
    assert_eq!(paths.paths.len(), 1);
    assert!(
        paths
            .warnings
            .iter()
            .any(|w| w.message().contains("splits into 2")),
        "{:?}",
        paths.warnings
    );
}
