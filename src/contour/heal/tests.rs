//! Healing tests (split from heal/mod.rs).

use super::*;
use crate::dxf::{Drawing, Entity, Place};
use crate::geom::arc_pieces;
use std::f64::consts::{PI, TAU};

fn ent(segs: Vec<Segment>, closed: bool) -> Entity {
    Entity {
        kind: "LINE",
        layer: 0,
        place: Place::Line(0),
        segments: segs,
        closed,
        source: None,
        insert: None,
    }
}
fn line(a: (f64, f64), b: (f64, f64)) -> Segment {
    Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1))
}
fn extract(es: Vec<Entity>) -> super::super::Contours {
    super::super::extract(
        &Drawing {
            entities: es,
            ..Drawing::default()
        },
        Tolerance::DEFAULT,
        0.05,
    )
}

#[test]
fn a_line_drawn_twice_in_either_direction_is_kept_once() {
    let c = extract(vec![
        ent(vec![line((0.0, 0.0), (10.0, 0.0))], false),
        ent(vec![line((10.0, 0.0), (0.0, 0.0))], false),
    ]);
    assert_eq!(c.contours.len(), 1);
    assert_eq!(c.healing.duplicates, 1);
    assert_eq!(
        c.healing.locations[0],
        (HealKind::Duplicate, Point::new(5.0, 0.0))
    );
}

#[test]
fn two_squares_sharing_an_edge_each_keep_their_copy_and_close() {
    let sq = |x: f64| {
        vec![
            ent(vec![line((x, 0.0), (x + 10.0, 0.0))], false),
            ent(vec![line((x + 10.0, 0.0), (x + 10.0, 10.0))], false),
            ent(vec![line((x + 10.0, 10.0), (x, 10.0))], false),
            ent(vec![line((x, 10.0), (x, 0.0))], false),
        ]
    };
    let mut es = sq(0.0);
    es.extend(sq(10.0));
    let c = extract(es);
    assert_eq!(c.contours.iter().filter(|c| c.is_closed()).count(), 2);
    assert_eq!(c.healing, Healing::default());
}

#[test]
fn a_square_with_a_doubled_side_closes_once_and_drops_the_copy() {
    let mut es = vec![
        ent(vec![line((0.0, 0.0), (10.0, 0.0))], false),
        ent(vec![line((10.0, 0.0), (10.0, 10.0))], false),
        ent(vec![line((10.0, 10.0), (0.0, 10.0))], false),
        ent(vec![line((0.0, 10.0), (0.0, 0.0))], false),
    ];
    es.push(ent(vec![line((10.0, 10.0), (10.0, 0.0))], false));
    let c = extract(es);
    assert_eq!(c.contours.len(), 1);
    assert!(c.contours[0].is_closed());
    assert_eq!(c.healing.duplicates, 1);
}

#[test]
fn copies_are_found_as_a_set_of_keys_finds_them() {
    // Segments on a small lattice (many drawn twice or more, either
    // way), some repeating "closed edges": each is a copy exactly when
    // its key was met before, as a plain set of keys says.
    let t = 1e-3;
    let mut x = 0x2545_f491_4f6c_dd1du64;
    let mut next = |n: u64| {
        x = crate::test_rng::Xorshift(x).next();
        x % n
    };
    let mut at = || Point::new(next(4) as f64, next(4) as f64 + 1e-4 * next(3) as f64);
    let segs: Vec<Seg> = (0..400)
        .map(|k| Seg {
            s: Segment::line(at(), at()),
            entity: k,
            index: 0,
        })
        .collect();
    let earlier: Vec<_> = (0..5)
        .map(|_| segment_key(&Segment::line(at(), at()), t))
        .collect();
    let mut set: std::collections::HashSet<_> = earlier.iter().copied().collect();
    let want: Vec<u32> = segs
        .iter()
        .filter(|g| set.insert(segment_key(&g.s, t)))
        .map(|g| g.entity)
        .collect();
    let mut healing = Healing::default();
    let got: Vec<u32> = drop_duplicate_segments(segs, t, earlier, &mut healing)
        .iter()
        .map(|g| g.entity)
        .collect();
    assert!(want.len() < 200, "{}", want.len());
    assert_eq!(got, want);
    assert_eq!(healing.duplicates, 400 - want.len());
}

#[test]
fn overlapping_collinear_lines_merge_into_their_union() {
    let c = extract(vec![
        ent(vec![line((0.0, 1.0), (10.0, 1.0))], false),
        ent(vec![line((15.0, 1.0), (6.0, 1.0))], false),
        ent(vec![line((15.0, 1.0), (20.0, 1.0))], false),
    ]);
    assert_eq!(c.healing.overlaps, 1);
    let total: f64 = c.contours.iter().map(|c| c.length).sum();
    assert!((total - 20.0).abs() < 1e-9, "{total}");
}

#[test]
fn overlapping_arcs_on_one_circle_merge_and_zero_length_is_dropped() {
    let o = Point::new(0.0, 0.0);
    let a1 = arc_pieces(o, 5.0, 0.0, PI / 2.0);
    let a2 = arc_pieces(o, 5.0, PI / 4.0, PI / 2.0);
    let c = extract(vec![
        ent(a1, false),
        ent(a2.iter().map(Segment::reversed).collect(), false),
        ent(vec![line((1.0, 1.0), (1.0, 1.0))], false),
    ]);
    assert_eq!((c.healing.overlaps, c.healing.zero_length), (1, 1));
    let total: f64 = c.contours.iter().map(|c| c.length).sum();
    assert!((total - 5.0 * 0.75 * PI).abs() < 1e-9, "{total}");
}

#[test]
fn a_circle_drawn_twice_is_kept_once() {
    let circle = arc_pieces(Point::new(3.0, 3.0), 2.0, 0.0, TAU);
    let c = extract(vec![ent(circle.clone(), true), ent(circle, true)]);
    assert_eq!((c.contours.len(), c.healing.duplicates), (1, 1));
}

#[test]
fn a_gap_below_the_gap_setting_is_closed_and_reported() {
    let c = extract(vec![
        ent(
            vec![
                line((0.0, 0.0), (10.0, 0.0)),
                line((10.0, 0.0), (10.0, 10.0)),
                line((10.0, 10.0), (0.0, 10.0)),
            ],
            false,
        ),
        ent(vec![line((0.0, 10.0), (0.0, 0.02))], false),
    ]);
    assert_eq!(c.contours.len(), 1);
    assert!(c.contours[0].is_closed());
    assert_eq!(c.healing.gaps_closed, 1);
}

#[test]
fn copies_of_closed_entities_are_noted_in_entity_order_among_zero_length_pieces() {
    // Closed squares: the copies are found after every entity is read (by
    // sorting their keys), yet noted where a one-by-one pass noted them:
    // after their entity's zero-length pieces, before later entities'.
    let square = |x: f64, tiny: bool| {
        let mut s = vec![
            line((x, 0.0), (x + 10.0, 0.0)),
            line((x + 10.0, 0.0), (x + 10.0, 10.0)),
            line((x + 10.0, 10.0), (x, 10.0)),
            line((x, 10.0), (x, 0.0)),
        ];
        if tiny {
            // A piece far under the tolerance, at the square's last corner.
            s.insert(3, line((x, 10.0), (x, 10.0 - 1e-6)));
            s[4].a = Point::new(x, 10.0 - 1e-6);
        }
        ent(s, true)
    };
    let c = extract(vec![
        square(0.0, false),
        square(0.0, true),   // a copy with a zero-length piece
        square(20.0, true),  // a zero-length piece
        square(0.0, false),  // a copy
        square(20.0, false), // a copy
        ent(vec![line((40.0, 0.0), (40.0, 1e-6))], false), // zero-length
    ]);
    use HealKind::{Duplicate as D, ZeroLength as Z};
    let kinds: Vec<HealKind> = c.healing.locations.iter().map(|l| l.0).collect();
    assert_eq!(kinds, [Z, D, Z, D, D, Z]);
    assert_eq!(c.healing.locations[2].1, Point::new(20.0, 10.0));
    assert_eq!(c.healing.locations[4].1, Point::new(20.0, 0.0));
    assert_eq!(c.contours.iter().filter(|c| c.is_closed()).count(), 2);
}

#[test]
fn copies_does_not_depend_on_the_hash() {
    // Whether a key is a copy is whether an equal key came before it,
    // whatever the keys' hashes: checked against a set on 100k keys of
    // 30k values (hashes folded to 32 bits), and on keys whose hash is
    // one constant (every key in one run).
    #[derive(PartialEq)]
    struct Collide(u64);
    impl std::hash::Hash for Collide {
        fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
            h.write_u8(7);
        }
    }
    let mut rnd = crate::test_rng::unit(0x51_7cc1_b727_220au64);
    let values: Vec<u64> = (0..100_000).map(|_| (rnd() * 30_000.0) as u64).collect();
    let mut seen = std::collections::HashSet::new();
    let want: Vec<bool> = values.iter().map(|v| !seen.insert(*v)).collect();
    assert_eq!(super::copies(values.len(), |k| values[k]), want);
    let few = &values[..2_000];
    assert_eq!(super::copies(few.len(), |k| Collide(few[k])), want[..2_000]);
}
