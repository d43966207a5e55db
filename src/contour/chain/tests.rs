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

#[test]
fn shuffled_reversed_square_chains_into_one_closed_contour() {
    let es = vec![
        line_entity((10.0, 10.0), (10.0, 0.0)),
        line_entity((0.0, 0.0), (10.0, 0.0)),
        line_entity((0.0, 10.0), (0.0005, 0.0)),
        line_entity((0.0, 10.0), (10.0, 10.0)),
    ];
    let mut w = vec![];
    let chains = chain(es, 1e-3, 1e-3, &mut vec![], &mut w);
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
    let chains = chain(es, 1e-3, 1e-3, &mut vec![], &mut vec![]);
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
    let chains = chain(es, 1e-3, 1e-3, &mut vec![], &mut vec![]);
    assert_eq!(chains.len(), 1);
    assert_eq!(chains[0].segments[0].a, Point::new(0.0, 0.0));
    assert_eq!(chains[0].segments[2].b, Point::new(30.0, 0.0));
}

#[test]
fn the_grid_finds_every_end_within_the_tolerance_as_brute_force_does() {
    let mut x = 0x2545_f491_4f6c_dd1du64;
    let mut rnd = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    for t in [1e-3, 0.37, 5.0] {
        let ends: Vec<(Point, u32)> = (0..2000)
            .map(|i| (Point::new(rnd() * 40.0 * t, rnd() * 40.0 * t), i))
            .collect();
        let dense = EndGrid::dense(&ends, t).expect("evenly spread ends: dense");
        assert!(dense.cols > 0);
        let hashed = EndGrid::hashed(&ends, t);
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
    assert!(EndGrid::dense(&ends, t).is_none());
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
