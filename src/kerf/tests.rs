//! Tests of `kerf`.

use super::*;
use crate::test_rng::Xorshift;

fn run(points: &[(f64, f64)]) -> KerfPaths {
    run_repairing(points, true)
}

fn run_repairing(points: &[(f64, f64)], repair: bool) -> KerfPaths {
    let mut body = format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", points.len());
    for (x, y) in points {
        body += &format!("10\n{x}\n20\n{y}\n");
    }
    let dxf = format!("0\nSECTION\n2\nENTITIES\n{body}0\nENDSEC\n0\nEOF\n");
    let s = crate::Settings::new(1.0, 0.001, 1000.0).unwrap();
    let d = crate::dxf::parse(dxf.as_bytes(), s.read()).unwrap();
    let threads = crate::par::Threads::ONE;
    let c = crate::contour::extract_repairing(&d, s.tolerance(), s.gap(), threads, repair);
    offset(&c, s.kerf(), s.tolerance())
}

#[test]
fn a_loop_that_crosses_itself_is_said_where_and_not_cut() {
    // A lopsided bow tie (a symmetric one has no area and is open):
    // y = x and y = 20 − 2x cross at (20/3, 20/3). Left unrepaired.
    let tie = [(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 20.0)];
    // Repaired (the default), its two triangles are cut.
    assert_eq!(run(&tie).paths.len(), 2);
    let k = run_repairing(&tie, false);
    let w: Vec<_> = k
        .warnings
        .iter()
        .filter(|w| w.code == "self-crossing")
        .collect();
    assert_eq!(w.len(), 1, "{:?}", k.warnings);
    let at = w[0].at.unwrap();
    assert!(at.dist(Point::new(20.0 / 3.0, 20.0 / 3.0)) < 1e-9, "{at:?}");
    assert!(
        w[0].message().contains("(1 crossing(s))"),
        "{}",
        w[0].message()
    );
    assert!(k.paths.is_empty());
    // A square does not cross itself: one path, nothing said.
    let k = run(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]);
    assert_eq!(k.paths.len(), 1);
    assert!(!k.warnings.iter().any(|w| w.code == "self-crossing"));
}

/// A random loop of segments, counter-clockwise: a rectangle, a circle of
/// two arcs, a polygon drawn for a circle (short lines), a convex polygon
/// with arcs bulging out, or a star whose edges bulge either way.
fn random_segments(x: &mut Xorshift) -> Vec<Segment> {
    let mut f = || x.unit();
    let (cx, cy) = (f() * 1000.0, f() * 1000.0);
    let kind = (f() * 5.0) as usize;
    let n = match kind {
        0 => 4,
        1 => 2,
        2 => 8 + (f() * 120.0) as usize,
        _ => 3 + (f() * 12.0) as usize,
    };
    let (rx, ry) = (0.2 + f() * 60.0, 0.2 + f() * 60.0);
    let v: Vec<(f64, f64, f64)> = (0..n)
        .map(|i| {
            let a = i as f64 / n as f64 * std::f64::consts::TAU;
            match kind {
                0 => {
                    let (sx, sy) = ([-1.0, 1.0, 1.0, -1.0][i], [-1.0, -1.0, 1.0, 1.0][i]);
                    (cx + sx * rx, cy + sy * ry, 0.0)
                }
                1 => (cx + rx * a.cos(), cy + rx * a.sin(), 1.0),
                2 => (cx + rx * a.cos(), cy + rx * a.sin(), 0.0),
                3 => {
                    let b = if f() < 0.3 { f() * 0.3 } else { 0.0 };
                    (cx + rx * a.cos(), cy + ry * a.sin(), b)
                }
                _ => {
                    let r = 0.3 + f() * 40.0;
                    let b = if f() < 0.4 { f() * 2.0 - 1.0 } else { 0.0 };
                    (cx + r * a.cos(), cy + r * a.sin(), b)
                }
            }
        })
        .collect();
    (0..n)
        .map(|i| {
            let (ax, ay, b) = v[i];
            let (bx, by, _) = v[(i + 1) % n];
            Segment {
                a: Point::new(ax, ay),
                b: Point::new(bx, by),
                bulge: b,
            }
        })
        .collect()
}

#[test]
fn no_invalid_vertices_only_where_the_full_scan_finds_none() {
    let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
    let (mut sure, mut found, mut n) = (0, 0, 0);
    for _ in 0..20000 {
        let segs = random_segments(&mut rng);
        let x = rng.next();
        let kind = if x.is_multiple_of(2) {
            ContourKind::Outer
        } else {
            ContourKind::Hole
        };
        let half = [0.05, 0.25, 0.75, 2.0][(x >> 8) as usize % 4];
        let tol = Tolerance([0.001, 0.01, 1e-6][(x >> 16) as usize % 3]);
        let all = invalid_vertices(&segs, kind, half, tol);
        n += 1;
        found += usize::from(!all.is_empty());
        if bounds::no_invalid_vertices(&segs, kind == ContourKind::Hole, half, tol.mm()) {
            sure += 1;
            assert!(all.is_empty(), "{kind:?} {half} {segs:?}: {all:?}");
        }
    }
    // Not vacuous: the short answer is given often, and the scan finds
    // corners in many of the other loops.
    assert!(sure > n / 4 && found > n / 10, "{sure}, {found} of {n}");
}
