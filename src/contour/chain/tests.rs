//! Chaining tests (split from chain.rs).

use super::*;

fn line_entity(a: (f64, f64), b: (f64, f64)) -> Piece {
    Piece {
        segments: vec![Segment::line(Point::new(a.0, a.1), Point::new(b.0, b.1))],
        closed: false,
        entities: vec![0],
        measure: None,
    }
}

fn pieces(es: Vec<Piece>) -> Pieces {
    let mut p = Pieces::default();
    for e in es {
        p.push(e);
    }
    p
}

#[test]
fn shuffled_reversed_square_chains_into_one_closed_contour() {
    let es = vec![
        line_entity((10.0, 10.0), (10.0, 0.0)),
        line_entity((0.0, 0.0), (10.0, 0.0)),
        line_entity((0.0, 10.0), (0.0005, 0.0)),
        line_entity((0.0, 10.0), (10.0, 10.0)),
    ];
    let mut w = vec![];
    let chains = chain(pieces(es), 1e-3, 1e-3, &mut vec![], &mut w);
    assert_eq!(chains.len(), 1);
    assert!(chains[0].closed);
    assert_eq!(chains[0].segments.len(), 4);
    for pair in chains[0].segments.windows(2) {
        assert_eq!(pair[0].b, pair[1].a);
    }
    assert!(w.is_empty(), "{w:?}");
}

#[test]
fn a_gap_larger_than_the_tolerance_leaves_an_open_chain() {
    let es = vec![
        line_entity((0.0, 0.0), (10.0, 0.0)),
        line_entity((10.01, 0.0), (20.0, 0.0)),
    ];
    let chains = chain(pieces(es), 1e-3, 1e-3, &mut vec![], &mut vec![]);
    assert_eq!(chains.len(), 2);
    assert!(chains.iter().all(|c| !c.closed));
}

#[test]
fn chain_started_mid_way_extends_backwards() {
    let es = vec![
        line_entity((10.0, 0.0), (20.0, 0.0)),
        line_entity((0.0, 0.0), (10.0, 0.0)),
        line_entity((20.0, 0.0), (30.0, 0.0)),
    ];
    let chains = chain(pieces(es), 1e-3, 1e-3, &mut vec![], &mut vec![]);
    assert_eq!(chains.len(), 1);
    assert_eq!(chains[0].segments[0].a, Point::new(0.0, 0.0));
    assert_eq!(chains[0].segments[2].b, Point::new(30.0, 0.0));
}

#[test]
fn the_grid_finds_every_end_within_the_tolerance_as_brute_force_does() {
    let mut rnd = crate::test_rng::unit(0x2545_f491_4f6c_dd1du64);
    for t in [1e-3, 0.37, 5.0] {
        let ends: Vec<(Point, u32)> = (0..2000)
            .map(|i| (Point::new(rnd() * 40.0 * t, rnd() * 40.0 * t), i))
            .collect();
        let dense =
            EndGrid::dense(&ends, t, crate::par::Threads::ONE).expect("evenly spread ends: dense");
        assert!(dense.cols > 0);
        let hashed = EndGrid::hashed(&ends, t, crate::par::Threads::ONE);
        for grid in [&dense, &hashed] {
            for _ in 0..2000 {
                let p = Point::new(rnd() * 40.0 * t, rnd() * 40.0 * t);
                let mut want: Vec<u32> = ends
                    .iter()
                    .filter(|(q, _)| p.dist(*q) <= t)
                    .map(|e| e.1)
                    .collect();
                let mut got: Vec<u32> = grid
                    .near(p)
                    .filter(|(q, _)| p.dist(*q) <= t)
                    .map(|e| e.1)
                    .collect();
                want.sort_unstable();
                got.sort_unstable();
                assert_eq!(got, want, "t {t} at {p:?}");
            }
            // Exactly t away along an axis, on both sides.
            for &(q, id) in &ends[..200] {
                for (dx, dy) in [(t, 0.0), (-t, 0.0), (0.0, t), (0.0, -t)] {
                    let p = Point::new(q.x + dx, q.y + dy);
                    if p.dist(q) <= t {
                        assert!(grid.near(p).any(|e| e.1 == id), "t {t} at {p:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn the_grid_is_the_same_made_on_any_number_of_threads() {
    // More ends than two ranges' worth, so the box and the buckets are
    // found on ranges: spread (dense), clustered (hashed) and with
    // repeated points (the order within a bucket is the ends' order).
    let mut rnd = crate::test_rng::unit(0x9e37_79b9_7f4a_7c15u64);
    let t = 0.01;
    let spread: Vec<(Point, u32)> = (0..150_000)
        .map(|i| (Point::new(rnd() * 3000.0, rnd() * 1500.0), i))
        .collect();
    let mut clustered: Vec<(Point, u32)> = (0..100_000u32)
        .map(|i| (Point::new((i % 7) as f64 * 0.001, rnd() * 0.5), i))
        .collect();
    clustered.push((Point::new(1e6, 1e6), 100_000));
    for ends in [&spread, &clustered] {
        let one = EndGrid::of(ends.len(), |k| ends[k], t, crate::par::Threads::ONE);
        for n in [2, 3, 8] {
            let many = EndGrid::of(ends.len(), |k| ends[k], t, crate::par::Threads::new(n));
            assert!(many == one, "{n} threads, {} ends", ends.len());
        }
    }
    assert!(EndGrid::dense(&spread, t, crate::par::Threads::ONE).is_some());
    assert!(EndGrid::dense(&clustered, t, crate::par::Threads::ONE).is_none());
}

#[test]
fn clustered_ends_fall_back_to_the_hash_and_are_still_all_found() {
    // 2000 ends within 1 mm at the origin and one 1 km away: dense cells
    // sized to the box would put nearly all ends in one cell.
    let t = 1e-3;
    let mut ends: Vec<(Point, u32)> = (0..2000u32)
        .map(|i| {
            (
                Point::new((i % 50) as f64 * 0.02, (i / 50) as f64 * 0.02),
                i,
            )
        })
        .collect();
    ends.push((Point::new(1e6, 1e6), 2000));
    assert!(EndGrid::dense(&ends, t, crate::par::Threads::ONE).is_none());
    let grid = EndGrid::new(&ends, t);
    assert_eq!(grid.cols, 0);
    for &(q, id) in &ends {
        let p = Point::new(q.x + 0.7 * t, q.y - 0.7 * t);
        let got: Vec<u32> = grid
            .near(p)
            .filter(|(e, _)| p.dist(*e) <= t)
            .map(|e| e.1)
            .collect();
        assert_eq!(got, vec![id]);
    }
}

#[test]
fn open_chains_whose_ends_are_apart_come_back_unchanged_when_chained_again() {
    // What lets `extract` skip its second chaining when nothing was healed:
    // the first leaves no end within t of another chain's end. Short
    // segments on a coarse lattice with jitter: runs, branches, loops.
    let mut rnd = crate::test_rng::unit(0x9e37_79b9_7f4a_7c15u64);
    let t = 0.05;
    let mut at = || {
        let (i, j) = ((rnd() * 12.0).floor(), (rnd() * 12.0).floor());
        (i + rnd() * 0.06, j + rnd() * 0.06)
    };
    let es: Vec<Piece> = (0..600)
        .map(|k| {
            let mut p = line_entity(at(), at());
            p.entities = vec![k];
            p
        })
        .collect();
    let first = chain(pieces(es), t, t, &mut vec![], &mut vec![]);
    let apart =
        |c: &Chain| !c.closed && c.segments[0].a.dist(c.segments[c.segments.len() - 1].b) > t;
    let open: Vec<Chain> = first.into_iter().filter(apart).collect();
    assert!(open.len() > 20 && open.iter().any(|c| c.segments.len() > 2));
    let mut again = Pieces::default();
    for c in &open {
        again.push(Piece {
            segments: c.segments.clone(),
            closed: false,
            entities: c.entities.clone(),
            measure: None,
        });
    }
    let mut w = vec![];
    let second = chain(again, t, t, &mut vec![], &mut w);
    assert!(w.is_empty(), "{w:?}");
    assert_eq!(second.len(), open.len());
    for (a, b) in open.iter().zip(&second) {
        assert_eq!(
            (&a.segments, &a.entities, a.closed),
            (&b.segments, &b.entities, b.closed)
        );
    }
}

#[test]
fn a_chain_grown_both_ways_is_written_end_to_end() {
    // Started from the middle piece, reversed pieces on both sides:
    // every start equals the previous end exactly, ends moved onto the
    // neighbour's far end, entities in chain order.
    let es = vec![
        line_entity((10.0, 0.0), (20.0, 0.0)),
        line_entity((10.0004, 0.0), (0.0, 0.0)),
        line_entity((30.0, 0.0), (20.0003, 0.0)),
        line_entity((-10.0, 0.0), (0.0002, 0.0)),
    ];
    let mut es = es;
    for (k, e) in es.iter_mut().enumerate() {
        e.entities = vec![k];
    }
    let chains = chain(pieces(es), 1e-3, 1e-3, &mut vec![], &mut vec![]);
    assert_eq!(chains.len(), 1);
    let c = &chains[0];
    assert_eq!(c.entities, vec![3, 1, 0, 2]);
    let pts: Vec<(Point, Point)> = c.segments.iter().map(|s| (s.a, s.b)).collect();
    assert_eq!(
        pts,
        vec![
            (Point::new(-10.0, 0.0), Point::new(0.0, 0.0)),
            (Point::new(0.0, 0.0), Point::new(10.0, 0.0)),
            (Point::new(10.0, 0.0), Point::new(20.0, 0.0)),
            (Point::new(20.0, 0.0), Point::new(30.0, 0.0)),
        ]
    );
}
