//! Tests of [`super`]: stretches re-chosen at once as one after another,
//! the short schedule's blocks against one exact pass, on any threads.

use super::super::{Site, Sites};
use super::*;

/// A sheet-like sequence of `n` sites, 1-9 candidates each on a small
/// circle around a random-walk centre, and entries drawn at random (the
/// worst start a re-choice gets).
fn instance(n: usize, seed: u64) -> (Inst, Vec<usize>, Vec<usize>) {
    let mut rnd = crate::test_rng::unit(seed);
    let mut c = Point::new(0.0, 0.0);
    let mut sites = Vec::with_capacity(n);
    for _ in 0..n {
        c = c.add(Point::new(rnd() * 40.0 - 15.0, rnd() * 40.0 - 20.0));
        let k = 1 + (rnd() * 9.0) as usize;
        let r = 2.0 + rnd() * 20.0;
        let candidates = (0..k)
            .map(|j| {
                let a = j as f64 + rnd();
                c.add(Point::new(a.cos(), a.sin()).scale(r))
            })
            .collect();
        sites.push(Site {
            candidates,
            parent: None,
        });
    }
    let inst = Inst::numbered(&Sites::of(&sites), Vec::new());
    let at: Vec<usize> = (0..n)
        .map(|i| ((rnd() * 9.0) as usize) % inst.pts[i].len())
        .collect();
    (inst, (0..n).collect(), at)
}

fn length(inst: &Inst, origin: Point, seq: &[usize], at: &[usize]) -> f64 {
    let mut here = origin;
    seq.iter()
        .map(|&s| {
            let p = inst.pts[s][at[s]];
            let d = dist(here, p);
            here = p;
            d
        })
        .sum()
}

#[test]
fn stretches_at_once_are_what_one_after_another_gives() {
    let (inst, seq, at0) = instance(3_000, 0x5eed_0001);
    let origin = Point::new(-5.0, 3.0);
    // Apart by one fixed position or more; one at each end of the path.
    let stretches = [(0, 40), (42, 42), (44, 700), (900, 1_300), (1_302, 2_999)];
    let layers = Layers::default();
    let mut one = at0.clone();
    for &w in &stretches {
        optimise_stretch(&layers, &mut one, &inst, origin, &seq, w);
    }
    assert!(length(&inst, origin, &seq, &one) < length(&inst, origin, &seq, &at0));
    for t in [1, 2, 3, 8] {
        let mut at = at0.clone();
        optimise_stretches(
            &layers,
            &mut at,
            &inst,
            origin,
            &seq,
            &stretches,
            Threads::new(t),
        );
        assert_eq!(at, one, "{t} threads");
    }
}

#[test]
fn blocks_come_within_a_hair_of_one_exact_pass_on_any_threads() {
    let n = 3 * BLOCK + 500;
    let (inst, seq, at0) = instance(n, 0x5eed_0002);
    let origin = Point::new(0.0, 0.0);
    let layers = Layers::default();
    let mut exact = at0.clone();
    optimise_in(&layers, &mut exact, &inst, origin, &seq);
    let mut blocked = at0.clone();
    optimise_blocks(&layers, &mut blocked, &inst, origin, &seq, 4, Threads::ONE);
    let (e, b) = (
        length(&inst, origin, &seq, &exact),
        length(&inst, origin, &seq, &blocked),
    );
    assert!((b - e).abs() <= 1e-6 * e, "blocked {b} exact {e}");
    // Each border site is the best of its candidates between the
    // entries either side of it (its window was re-chosen last).
    for k in 1..n.div_ceil(BLOCK) {
        let i = k * BLOCK;
        let (prev, next) = (
            inst.pts[seq[i - 1]][blocked[seq[i - 1]]],
            inst.pts[seq[i + 1]][blocked[seq[i + 1]]],
        );
        let cost = |p: Point| dist(prev, p) + dist(p, next);
        let here = cost(inst.pts[seq[i]][blocked[seq[i]]]);
        for &p in inst.pts[seq[i]].iter() {
            assert!(here <= cost(p) + 1e-9, "border {i}");
        }
    }
    for t in [2, 3, 8] {
        let mut at = at0.clone();
        optimise_blocks(&layers, &mut at, &inst, origin, &seq, 4, Threads::new(t));
        assert_eq!(at, blocked, "{t} threads");
    }
}

#[test]
fn short_sequences_and_odd_margins_are_safe() {
    for n in [0, 1, 2, BLOCK - 1, BLOCK, BLOCK + 1, BLOCK + 2] {
        let (inst, seq, at0) = instance(n, 0x5eed_0003 + n as u64);
        for margin in [0, 4, BLOCK] {
            let mut at = at0.clone();
            optimise_blocks(
                &Layers::default(),
                &mut at,
                &inst,
                Point::default(),
                &seq,
                margin,
                Threads::new(2),
            );
            let (before, after) = (
                length(&inst, Point::default(), &seq, &at0),
                length(&inst, Point::default(), &seq, &at),
            );
            assert!(after <= before + 1e-9, "n {n} margin {margin}");
        }
        let mut at = at0.clone();
        optimise_in(&Layers::default(), &mut at, &inst, Point::default(), &seq);
        let (before, after) = (
            length(&inst, Point::default(), &seq, &at0),
            length(&inst, Point::default(), &seq, &at),
        );
        assert!(after <= before + 1e-9, "n {n} one pass");
    }
}
