//! Tests of [`super`]: queries against brute force, rings, odd grids.

use super::*;

fn brute(pts: &[Point], q: Point) -> f64 {
    pts.iter().map(|p| dist(*p, q)).fold(f64::MAX, f64::min)
}

#[test]
fn nearest_and_k_nearest_match_brute_force() {
    let mut s = 12345u64;
    let mut rnd = || {
        s = crate::test_rng::Xorshift(s).next();
        (s % 10_000) as f64 / 10.0
    };
    let pts: Vec<Point> = (0..500).map(|_| Point::new(rnd(), rnd() * 0.3)).collect();
    let mut g = Grid::new(&pts, 2.0);
    for i in 0..pts.len() {
        g.insert_nth(i);
    }
    for _ in 0..50 {
        let q = Point::new(rnd() * 1.2 - 100.0, rnd());
        let (_, d) = g.nearest(q, |i| pts[i as usize], |_| true).unwrap();
        assert!((d - brute(&pts, q)).abs() < 1e-12);
        let k = g.k_nearest(q, 5, |i| pts[i as usize], |_| false);
        let mut all: Vec<f64> = pts.iter().map(|p| dist(*p, q)).collect();
        all.sort_by(f64::total_cmp);
        for (j, id) in k.iter().enumerate() {
            assert!((dist(pts[*id as usize], q) - all[j]).abs() < 1e-12);
        }
    }
}

#[test]
fn rings_visit_each_cell_of_the_grid_once_and_nothing_outside() {
    let mut s = 99u64;
    let mut rnd = |n: usize| {
        s = crate::test_rng::Xorshift(s).next();
        (s % n as u64) as usize
    };
    for _ in 0..40 {
        let pts = [
            Point::default(),
            Point::new(1.0 + rnd(300) as f64, rnd(3) as f64),
        ];
        let g = Grid::new(&pts, 1.0 / (1 + rnd(50)) as f64);
        let (cx, cy) = (rnd(g.nx), rnd(g.ny));
        let mut seen = vec![0; g.nx * g.ny];
        for r in 0..=g.reach(cx, cy) + 2 {
            g.ring(cx, cy, r, |c| seen[c] += 1);
        }
        assert!(
            seen.iter().all(|&n| n == 1),
            "{}x{} from ({cx},{cy})",
            g.nx,
            g.ny
        );
    }
}

#[test]
fn k_nearest_on_a_long_thin_grid_with_fewer_items_than_asked() {
    let pts: Vec<Point> = (0..5).map(|i| Point::new(i as f64 * 1000.0, 0.0)).collect();
    let mut g = Grid::new(&pts, 1e-3);
    assert!(g.nx >= 4096 && g.ny == 1, "{}x{}", g.nx, g.ny);
    for i in 0..pts.len() {
        g.insert_nth(i);
    }
    let k = g.k_nearest(Point::new(-50.0, 0.0), 16, |i| pts[i as usize], |_| false);
    assert_eq!(k, vec![0, 1, 2, 3, 4]);
}

#[test]
fn empty_and_coincident() {
    let mut g = Grid::new(&[], 1.0);
    assert!(g
        .nearest(Point::default(), |_| Point::default(), |_| true)
        .is_none());
    let pts = vec![Point::new(3.0, 3.0); 10];
    let mut g = Grid::new(&pts, 1.0);
    for i in 0..pts.len() {
        g.insert_nth(i);
    }
    assert_eq!(
        g.k_nearest(Point::default(), 20, |i| pts[i as usize], |_| false)
            .len(),
        10
    );
    // Dead items go away.
    assert!(g
        .nearest(Point::default(), |i| pts[i as usize], |_| false)
        .is_none());
}
