//! Properties of [`simplified`], each checked by code of its own (not the
//! module's): containment by sampled points and an even-odd ray test, no
//! two edges meeting by brute force over every pair, the area within the
//! budget, the box kept.

use super::*;
use crate::geom::{arc_pieces, Segment};
use crate::nest::rng::SplitMix;
use crate::nest::shape::{collision_polygon, room_polygon, signed_area};
use std::f64::consts::PI;

/// A random star-shaped polygon (always simple): `n` angles around the
/// centre, each at a random radius in [inner, 1] × `size`.
fn star(r: &mut SplitMix, n: usize, inner: f64, size: f64) -> Polygon {
    let mut angles: Vec<f64> = (0..n).map(|_| r.unit() * 2.0 * PI).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let pts = angles
        .iter()
        .map(|&a| {
            let rad = size * (inner + (1.0 - inner) * r.unit());
            Point::new(rad * a.cos() + 3.0 * size, rad * a.sin() - size)
        })
        .collect();
    Polygon::new(pts)
}

/// A plate with finger joints on all four sides (boxes.py-like).
fn toothed(teeth: usize, pitch: f64, depth: f64) -> Polygon {
    let side = teeth as f64 * 2.0 * pitch;
    let mut pts = Vec::new();
    // Walk each side of a square counter-clockwise, teeth outwards.
    let corners = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)];
    let outward = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)];
    for k in 0..4 {
        let (x0, y0) = corners[k];
        let (x1, y1) = corners[(k + 1) % 4];
        let (ux, uy) = ((x1 - x0) / side, (y1 - y0) / side);
        let (ox, oy) = outward[k];
        for t in 0..teeth {
            let s0 = t as f64 * 2.0 * pitch;
            let at = |s: f64, o: f64| Point::new(x0 + ux * s + ox * o, y0 + uy * s + oy * o);
            pts.push(at(s0, 0.0));
            pts.push(at(s0 + pitch * 0.5, 0.0));
            pts.push(at(s0 + pitch * 0.5, depth));
            pts.push(at(s0 + pitch * 1.5, depth));
            pts.push(at(s0 + pitch * 1.5, 0.0));
        }
    }
    Polygon::new(pts)
}

/// Even-odd ray test, or within `eps` of an edge.
fn inside_or_on(p: Point, poly: &[Point], eps: f64) -> bool {
    let n = poly.len();
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        // Distance to the edge.
        let ab = b.sub(a);
        let t = (p.sub(a).dot(ab) / ab.dot(ab).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
        if a.add(ab.scale(t)).dist(p) <= eps {
            return true;
        }
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if x > p.x {
                odd = !odd;
            }
        }
    }
    odd
}

/// Distance between two closed segments, 0 when they cross.
fn seg_dist(a: Point, b: Point, c: Point, d: Point) -> f64 {
    let pd = |p: Point, a: Point, b: Point| {
        let ab = b.sub(a);
        let t = (p.sub(a).dot(ab) / ab.dot(ab).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
        a.add(ab.scale(t)).dist(p)
    };
    let side = |p: Point, q: Point, r: Point| (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    let crossing = side(a, b, c).signum() * side(a, b, d).signum() < 0.0
        && side(c, d, a).signum() * side(c, d, b).signum() < 0.0;
    if crossing {
        return 0.0;
    }
    pd(a, c, d)
        .min(pd(b, c, d))
        .min(pd(c, a, b))
        .min(pd(d, a, b))
}

/// No two non-neighbouring edges meet, and neighbours meet only at their
/// shared vertex (no edge folds back on the one before it).
fn assert_simple(poly: &[Point]) {
    let n = poly.len();
    assert!(n >= 3);
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        assert!(a.dist(b) > 0.0, "a zero-length edge at {i}");
        for j in i + 1..n {
            let (c, d) = (poly[j], poly[(j + 1) % n]);
            if j == i + 1 || (i == 0 && j == n - 1) {
                // Neighbours: the far end of each is not on the other.
                let (x, y) = if j == i + 1 { (a, d) } else { (b, c) };
                assert!(
                    seg_dist(x, x, c, d) > 0.0 && seg_dist(y, y, a, b) > 0.0,
                    "edges {i} and {j} fold back"
                );
                continue;
            }
            assert!(
                seg_dist(a, b, c, d) > 0.0,
                "edges {i} and {j} meet: {a:?}-{b:?} {c:?}-{d:?}"
            );
        }
    }
}

fn samples(r: &mut SplitMix, poly: &Polygon, count: usize) -> Vec<Point> {
    let b = poly.bbox;
    let mut out = Vec::new();
    for _ in 0..count * 20 {
        let p = Point::new(
            b.min.x + r.unit() * (b.max.x - b.min.x),
            b.min.y + r.unit() * (b.max.y - b.min.y),
        );
        if inside_or_on(p, &poly.pts, 0.0) {
            out.push(p);
            if out.len() == count {
                break;
            }
        }
    }
    // The boundary too: vertices and edge midpoints.
    let n = poly.pts.len();
    for i in 0..n {
        out.push(poly.pts[i]);
        out.push(poly.pts[i].add(poly.pts[(i + 1) % n]).scale(0.5));
    }
    out
}

/// Every property of a simplification of `orig` on `side` within `excess`.
fn check(r: &mut SplitMix, orig: &Polygon, side: Side, excess: f64) -> Polygon {
    let got = simplified(orig, side, excess);
    assert_simple(&got.pts);
    assert!(signed_area(&got.pts) > 0.0, "counter-clockwise");
    let size = (orig.bbox.max.x - orig.bbox.min.x).max(orig.bbox.max.y - orig.bbox.min.y);
    let eps = 1e-9 * size;
    let (a0, a1) = (orig.area(), got.area());
    let (outer, inner) = match side {
        Side::Grow => {
            assert!(a1 >= a0 - eps * size && a1 <= a0 * (1.0 + excess) + eps * size);
            (&got, orig)
        }
        Side::Shrink => {
            assert!(a1 <= a0 + eps * size && a1 >= a0 * (1.0 - excess) - eps * size);
            (orig, &got)
        }
    };
    for p in samples(r, inner, 200) {
        assert!(
            inside_or_on(p, &outer.pts, eps),
            "{p:?} of the inner polygon outside the outer ({side:?}, {excess})"
        );
    }
    let (b, g) = (orig.bbox, got.bbox);
    assert!(
        g.min.x >= b.min.x - eps
            && g.min.y >= b.min.y - eps
            && g.max.x <= b.max.x + eps
            && g.max.y <= b.max.y + eps,
        "the box grew"
    );
    got
}

#[test]
fn random_stars_grow_and_shrink_within_budget_and_stay_simple() {
    let mut r = SplitMix(44);
    for round in 0..300 {
        let n = 5 + r.below(300);
        let inner = [0.05, 0.5, 0.9, 0.99][round % 4];
        let size = 10.0 + 1000.0 * r.unit();
        let poly = star(&mut r, n, inner, size);
        let excess = [0.0005, 0.001, 0.005, 0.05][r.below(4)];
        for side in [Side::Grow, Side::Shrink] {
            check(&mut r, &poly, side, excess);
        }
    }
}

#[test]
fn a_circles_polygon_loses_most_vertices_for_a_thousandth_of_its_area() {
    let mut r = SplitMix(1);
    let circle = arc_pieces(Point::new(40.0, -7.0), 50.0, 0.0, 2.0 * PI);
    let outline = collision_polygon(&circle, 1.25, 0.05).unwrap();
    // Circumscribed at 0.05 mm already (74 vertices): a quarter goes. A
    // room's chords can only be cut, at twice the area: 70 → 62.
    let grown = check(&mut r, &outline, Side::Grow, EXCESS);
    assert!(
        grown.pts.len() * 4 < outline.pts.len() * 3,
        "{} → {}",
        outline.pts.len(),
        grown.pts.len()
    );
    let room = room_polygon(&circle, 1.25, 0.05).unwrap();
    let shrunk = check(&mut r, &room, Side::Shrink, EXCESS);
    assert!(
        shrunk.pts.len() + 5 < room.pts.len(),
        "{} → {}",
        room.pts.len(),
        shrunk.pts.len()
    );
    // Coarser for a larger budget.
    let coarse = check(&mut r, &outline, Side::Grow, 0.01);
    assert!(coarse.pts.len() * 2 < grown.pts.len());
}

#[test]
fn finger_joints_keep_their_teeth_when_the_budget_is_small() {
    let mut r = SplitMix(2);
    let plate = toothed(10, 6.0, 3.0);
    // The straight vertices between teeth (36, and 3 of the corners) go
    // for nothing; a notch's corner cut is 6 × 3 / 2 = 9 mm², 0.06 % of
    // the 14 400 mm² plate: 0.1 % cuts one corner, no more.
    let got = check(&mut r, &plate, Side::Grow, EXCESS);
    assert!(got.pts.len() + 40 >= plate.pts.len(), "{}", got.pts.len());
    for excess in [0.01, 0.1] {
        check(&mut r, &plate, Side::Grow, excess);
        check(&mut r, &plate, Side::Shrink, excess);
    }
}

#[test]
fn a_concave_arc_of_an_outline_is_cut_from_outside() {
    // A 100 × 100 square with a round bite of r 20 in its top edge.
    let segs = vec![
        Segment::line(Point::new(0.0, 0.0), Point::new(100.0, 0.0)),
        Segment::line(Point::new(100.0, 0.0), Point::new(100.0, 100.0)),
        Segment::line(Point::new(100.0, 100.0), Point::new(70.0, 100.0)),
        Segment {
            a: Point::new(70.0, 100.0),
            b: Point::new(30.0, 100.0),
            bulge: -1.0,
        },
        Segment::line(Point::new(30.0, 100.0), Point::new(0.0, 100.0)),
        Segment::line(Point::new(0.0, 100.0), Point::new(0.0, 0.0)),
    ];
    let poly = collision_polygon(&segs, 0.0, 0.01).unwrap();
    let mut r = SplitMix(3);
    let got = check(&mut r, &poly, Side::Grow, EXCESS);
    assert!(got.pts.len() < poly.pts.len() / 2);
}

#[test]
fn small_and_degenerate_polygons_come_back_unchanged() {
    let tri = Polygon::new(vec![
        Point::new(0.0, 0.0),
        Point::new(1.0, 0.0),
        Point::new(0.0, 1.0),
    ]);
    assert_eq!(simplified(&tri, Side::Grow, 0.5), tri);
    let flat = Polygon::new((0..6).map(|i| Point::new(i as f64, 0.0)).collect());
    assert_eq!(simplified(&flat, Side::Grow, EXCESS), flat);
    let nan = Polygon::new(vec![
        Point::new(0.0, 0.0),
        Point::new(f64::NAN, 0.0),
        Point::new(1.0, 1.0),
        Point::new(0.0, 1.0),
        Point::new(-1.0, 0.5),
    ]);
    assert_eq!(simplified(&nan, Side::Grow, EXCESS).pts.len(), 5);
}

/// What the search nests a part on ([`nesting_polygon`]): a finger-jointed
/// plate of 400 vertices on far fewer, with every point of the drawn
/// outline inside it and at least the spacing's half plus a hundredth of
/// the tolerance from its edges (the margin a flush contact of the exact
/// test may not eat); an outline of few vertices on its collision polygon.
#[test]
fn a_many_vertex_outline_nests_on_fewer_vertices_clear_of_the_part_by_the_margin() {
    let plate = toothed(20, 3.0, 3.0);
    let n = plate.pts.len();
    let outline: Vec<Segment> = (0..n)
        .map(|i| Segment::line(plate.pts[i], plate.pts[(i + 1) % n]))
        .collect();
    let (grow, tol) = (1.25, 0.05);
    let exact = collision_polygon(&outline, grow, tol).unwrap();
    let nested = nesting_polygon(&outline, grow, tol).unwrap();
    assert!(exact.pts.len() > MANY_VERTICES, "{}", exact.pts.len());
    assert!(
        nested.pts.len() * 2 < exact.pts.len(),
        "{} -> {}",
        exact.pts.len(),
        nested.pts.len()
    );
    assert_simple(&nested.pts);
    let m = nested.pts.len();
    for i in 0..n {
        let (a, b) = (plate.pts[i], plate.pts[(i + 1) % n]);
        for p in [a, a.add(b.sub(a).scale(0.5))] {
            assert!(inside_or_on(p, &nested.pts, 0.0), "{p:?} outside");
            let clear = (0..m)
                .map(|k| seg_dist(p, p, nested.pts[k], nested.pts[(k + 1) % m]))
                .fold(f64::INFINITY, f64::min);
            assert!(
                clear >= grow + tol / 100.0 - 1e-9,
                "{p:?} only {clear} mm in"
            );
        }
    }
    // Few vertices: the collision polygon itself.
    let square: Vec<Segment> = [(0.0, 0.0), (50.0, 0.0), (50.0, 50.0), (0.0, 50.0)]
        .iter()
        .zip([(50.0, 0.0), (50.0, 50.0), (0.0, 50.0), (0.0, 0.0)].iter())
        .map(|(&(x0, y0), &(x1, y1))| Segment::line(Point::new(x0, y0), Point::new(x1, y1)))
        .collect();
    assert_eq!(
        nesting_polygon(&square, grow, tol),
        collision_polygon(&square, grow, tol)
    );
}
