//! Tests of the overlap proxy and the weights ([`super`]).

use super::super::poles::poles;
use super::*;
use crate::nest::collide::{overlaps, Shape};
use crate::nest::shape::Polygon;

fn square(side: f64) -> Polygon {
    Polygon::new(vec![
        Point::new(0.0, 0.0),
        Point::new(side, 0.0),
        Point::new(side, side),
        Point::new(0.0, side),
    ])
}

/// The pair value as the separator uses it: the exact test first.
fn value(a: &Polygon, ta: Point, b: &Polygon, tb: Point) -> f64 {
    let (sa, sb) = (Shape::new(a.moved(ta)), Shape::new(b.moved(tb)));
    if overlaps(&sa, &sb, 1e-9) {
        proxy(&poles(a), ta, &poles(b), tb, 0.01)
    } else {
        0.0
    }
}

#[test]
fn zero_when_clear_or_touching_positive_when_overlapping() {
    let s = square(10.0);
    let o = Point::default();
    assert_eq!(value(&s, o, &s, Point::new(10.0, 0.0)), 0.0);
    assert_eq!(value(&s, o, &s, Point::new(10.0, 10.0)), 0.0);
    assert_eq!(value(&s, o, &s, Point::new(30.0, 3.0)), 0.0);
    assert!(value(&s, o, &s, Point::new(9.99, 0.0)) > 0.0);
    // Overlapping only at a corner no pole reaches: still positive.
    assert!(value(&s, o, &s, Point::new(9.9, 9.9)) > 0.0);
}

#[test]
fn grows_with_the_penetration() {
    let s = square(10.0);
    let l = Polygon::new(
        [
            (0.0, 0.0),
            (20.0, 0.0),
            (20.0, 10.0),
            (10.0, 10.0),
            (10.0, 20.0),
            (0.0, 20.0),
        ]
        .iter()
        .map(|&(x, y)| Point::new(x, y))
        .collect(),
    );
    let o = Point::default();
    // A square slid into a square (or into an L's foot) from the
    // side: the value rises with every half millimetre of the first
    // 4 mm, and is larger still when all in.
    for (b, edge) in [(&s, 10.0), (&l, 20.0)] {
        let at = |x: f64| value(b, o, &s, Point::new(x, 0.0));
        let mut last = 0.0;
        for k in 1..=8 {
            let v = at(edge - k as f64 * 0.5);
            assert!(v > last, "{k}: {v} ≤ {last}");
            last = v;
        }
        assert!(at(edge - 10.0) > last);
    }
}

#[test]
fn the_cut_down_pole_sets_give_the_sum_over_every_pair() {
    // The same sum written plainly, over every pole pair.
    let plain = |a: &[Pole], ta: Point, b: &[Pole], tb: Point, eps: f64| {
        let mut s = 0.0;
        for p in a {
            for q in b {
                let reach = p.r + q.r;
                let dist = p.c.add(ta).dist(q.c.add(tb));
                if dist <= 2.0 * reach {
                    let d = reach - dist;
                    let f = if d >= eps {
                        d
                    } else {
                        eps * eps / (2.0 * eps - d)
                    };
                    s += f * p.r.min(q.r);
                }
            }
        }
        f64::max(s, eps * eps * 1e-3)
    };
    let l = Polygon::new(
        [
            (0.0, 0.0),
            (60.0, 0.0),
            (60.0, 8.0),
            (8.0, 8.0),
            (8.0, 40.0),
            (0.0, 40.0),
        ]
        .iter()
        .map(|&(x, y)| Point::new(x, y))
        .collect(),
    );
    let (pl, ps) = (poles(&l), poles(&square(10.0)));
    assert!(pl.len() > 4);
    let o = Point::default();
    let mut compared = 0;
    for i in -20..=20 {
        for j in -8..=16 {
            let t = Point::new(i as f64 * 3.1, j as f64 * 2.7);
            for (a, b) in [(&pl, &ps), (&ps, &pl), (&pl, &pl)] {
                let (x, y) = (proxy(a, t, b, o, 0.3), plain(a, t, b, o, 0.3));
                assert!((x - y).abs() <= 1e-9 * y.max(1.0), "{t:?}: {x} ≠ {y}");
                compared += 1;
            }
        }
    }
    assert!(compared > 3000);
}

/// The proxy as it was before the pole sets (session 11): poles as
/// an array of structs, the boxes found at every call, one loop a row.
fn before(
    a: &[Pole],
    ta: Point,
    b: &[Pole],
    tb: Point,
    eps: f64,
    limit: f64,
    deep: f64,
) -> (f64, bool) {
    let reach_box = |ps: &[Pole], t: Point| {
        let mut lo = Point::new(f64::INFINITY, f64::INFINITY);
        let mut hi = Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
        let mut r: f64 = 0.0;
        for p in ps {
            let c = p.c.add(t);
            lo = Point::new(lo.x.min(c.x), lo.y.min(c.y));
            hi = Point::new(hi.x.max(c.x), hi.y.max(c.y));
            r = r.max(p.r);
        }
        (lo, hi, r)
    };
    let dt = ta.sub(tb);
    let (alo, ahi, ar) = reach_box(a, dt);
    let (blo, bhi, br) = reach_box(b, Point::default());
    let near: Vec<Pole> = b
        .iter()
        .copied()
        .filter(|q| within(q.c, alo, ahi, 2.0 * (q.r + ar)))
        .collect();
    let (mut s, mut deepest) = (0.0, f64::NEG_INFINITY);
    for p in a {
        let c = p.c.add(dt);
        if !within(c, blo, bhi, 2.0 * (p.r + br)) {
            continue;
        }
        for q in &near {
            let (dx, dy) = (c.x - q.c.x, c.y - q.c.y);
            let reach = p.r + q.r;
            let d2 = dx * dx + dy * dy;
            if d2 > 4.0 * reach * reach {
                continue;
            }
            let d = reach - d2.sqrt();
            deepest = deepest.max(d);
            let f = if d >= eps {
                d
            } else {
                eps * eps / (2.0 * eps - d)
            };
            s += f * p.r.min(q.r);
        }
        if s > limit {
            break;
        }
    }
    (s.max(eps * eps * 1e-3), deepest > deep)
}

#[test]
fn the_pole_sets_walked_in_steps_give_the_old_proxy_bit_for_bit() {
    // The separator's nests must not move with this speed-up: same
    // sums, same give-ups, same deep pairs, in one walk or in two.
    let l = Polygon::new(
        [
            (0.0, 0.0),
            (37.0, 0.0),
            (37.0, 6.0),
            (7.0, 6.0),
            (7.0, 29.0),
            (0.0, 29.0),
        ]
        .iter()
        .map(|&(x, y)| Point::new(x, y))
        .collect(),
    );
    // A long bar too: a row of many poles, some of them far from the
    // other set where others are near it (the rows skipped by the box of
    // the poles kept).
    let bar = Polygon::new(
        [(0.0, 0.0), (70.0, 0.0), (70.0, 2.5), (0.0, 2.5)]
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect(),
    );
    let sets = [
        poles(&l),
        poles(&square(10.0)),
        poles(&square(3.3)),
        poles(&bar),
    ];
    assert!(sets[3].len() > 12, "{}", sets[3].len());
    let mut rng = crate::nest::rng::SplitMix(7);
    let mut unit = || rng.unit();
    let (mut deep_seen, mut given_up) = (0, 0);
    let mut near = Near::default();
    for _ in 0..6000 {
        let (ia, ib) = ((unit() * 4.0) as usize, (unit() * 4.0) as usize);
        let (a, b) = (&sets[ia], &sets[ib]);
        let ta = Point::new(unit() * 60.0 - 20.0, unit() * 50.0 - 15.0);
        let tb = Point::new(unit() * 10.0, unit() * 10.0);
        let eps = 0.01 + unit();
        let limit = if unit() < 0.3 {
            f64::INFINITY
        } else {
            unit() * 20.0
        };
        let deep = unit() * 3.0;
        let old = before(a, ta, b, tb, eps, limit, deep);
        let (sa, sb) = (PoleSet::new(a), PoleSet::new(b));
        let probe = (unit() * 4.0) as usize;
        // (One working room for every walk, never cleared: as the
        // separator lends it, pair after pair.)
        let mut w = Walk::new(&sa, ta, &sb, tb, eps, deep, &mut near);
        w.rows(probe, limit);
        w.rows(MAX_POLES, limit);
        assert_eq!(w.value().to_bits(), old.0.to_bits(), "{ta:?} {tb:?}");
        assert_eq!(w.deep(), old.1);
        deep_seen += old.1 as usize;
        given_up += (limit < old.0) as usize;
    }
    assert!(deep_seen > 300 && given_up > 100, "{deep_seen} {given_up}");
}

#[test]
fn a_row_marks_in_blocks_what_the_pairs_mark_one_by_one() {
    // The blocks of four read past `m` (stale poles of an earlier pair,
    // some within reach): never marked. Checked against each pair's test.
    let mut rng = crate::nest::rng::SplitMix(11);
    let mut unit = || rng.unit();
    let mut d2s = [0.0; MAX_POLES];
    let mut marked = 0;
    for _ in 0..3000 {
        let mut near = [[0.0; MAX_POLES]; 3];
        for (xyr, size) in near.iter_mut().zip([40.0, 40.0, 6.0]) {
            for v in xyr.iter_mut() {
                *v = unit() * size;
            }
        }
        let c = Point::new(unit() * 40.0, unit() * 40.0);
        let pr = unit() * 6.0;
        let m = (unit() * (MAX_POLES + 1) as f64) as usize;
        let mark = mark_row(c, pr, (&near[0], &near[1], &near[2]), m, &mut d2s);
        for j in 0..MAX_POLES {
            let (dx, dy) = (c.x - near[0][j], c.y - near[1][j]);
            let d2 = dx * dx + dy * dy;
            let reach = pr + near[2][j];
            let want = j < m && d2 <= 4.0 * reach * reach;
            assert_eq!(mark >> j & 1 == 1, want, "pole {j} of {m}");
            if j < m {
                assert_eq!(d2s[j].to_bits(), d2.to_bits());
            }
            marked += want as usize;
        }
    }
    assert!(marked > 3000, "{marked}");
}

#[test]
fn weights_rise_on_overlapping_pairs_and_decay_on_clear_ones() {
    let mut t = Table::new(3);
    t.set(0, 1, 2.0);
    t.set(1, 2, 1.0);
    t.update_weights();
    assert!((t.weight(0, 1) - HIGH).abs() < 1e-12);
    assert!(t.weight(1, 2) > LOW && t.weight(1, 2) < HIGH);
    assert_eq!(t.weight(0, 2), 1.0);
    assert!(t.colliding(0) && t.colliding(2));
    assert!((t.total() - 3.0).abs() < 1e-12);
    t.set(0, 1, 0.0);
    t.update_weights();
    assert!((t.weight(0, 1) - HIGH * DECAY).abs() < 1e-12);
    assert!(!t.colliding(0));
}
