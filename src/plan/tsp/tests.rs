//! Properties of [`order`]: each site once, precedence kept, never longer
//! than the nearest-neighbour tour, no panic on odd input, known optima.

use super::*;

use crate::test_rng::Xorshift as Rng;

/// Panics unless `t` visits every visitable site once, before its parent,
/// with a valid candidate, and reports its own length.
fn check(sites: &[Site], origin: Point, t: &Tour) {
    let mut pos = vec![None; sites.len()];
    for (i, &(s, c)) in t.visits.iter().enumerate() {
        assert!(pos[s].is_none(), "site {s} twice");
        pos[s] = Some(i);
        assert!(sites[s].candidates[c].is_finite());
        assert_eq!(t.points[i], sites[s].candidates[c], "visit {i}'s point");
    }
    for (s, site) in sites.iter().enumerate() {
        let visitable = site.candidates.iter().any(|p| p.is_finite());
        assert_eq!(pos[s].is_some(), visitable, "site {s}");
        // Precedence against every visitable ancestor (acyclic inputs only).
        let (mut x, mut steps) = (site.parent, 0);
        while let (Some(u), Some(ps)) = (x, pos[s]) {
            steps += 1;
            if u >= sites.len() || steps > sites.len() {
                break;
            }
            if let Some(pu) = pos[u] {
                assert!(ps < pu, "site {s} after its ancestor {u}");
            }
            x = sites[u].parent;
        }
    }
    let len = path_length(sites, origin, &t.visits);
    assert!((len - t.length).abs() < 1e-6 * (1.0 + len));
    assert!(t.length <= t.nn_length + 1e-9);
}

/// A random nest-like forest: parts with holes with islands, a few
/// candidates each, some coincident, some contours without candidates.
fn random_forest(rng: &mut Rng, n: usize) -> Vec<Site> {
    let mut sites: Vec<Site> = Vec::new();
    while sites.len() < n {
        let c = Point::new(rng.unit() * 1000.0, rng.unit() * 600.0);
        let parent = if sites.is_empty() || rng.unit() < 0.4 {
            None
        } else {
            Some(rng.below(sites.len()))
        };
        let k = rng.below(6);
        let r = 1.0 + rng.unit() * 40.0;
        let candidates = (0..k)
            .map(|j| {
                if rng.unit() < 0.1 {
                    c
                } else {
                    let a = j as f64 + rng.unit();
                    c.add(Point::new(a.cos(), a.sin()).scale(r))
                }
            })
            .collect();
        sites.push(Site { candidates, parent });
    }
    // Parents were drawn among earlier sites: point them the other way
    // round too, so children are not always the later sites.
    let m = sites.len();
    sites.reverse();
    for s in &mut sites {
        s.parent = s.parent.map(|p| m - 1 - p);
    }
    sites
}

#[test]
fn random_forests_keep_every_rule() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for seed in 0..60 {
        let n = 1 + (seed * 7) % 90;
        let sites = random_forest(&mut rng, n);
        let origin = Point::new(rng.unit() * 100.0, -rng.unit() * 100.0);
        let t = order(&sites, origin);
        check(&sites, origin, &t);
    }
}

/// The short schedule of big sheets keeps every rule too, on the random
/// forests and on a row of plates with a hole in the middle each (the
/// 25 MB nest's pattern, whose repaired free tour is longer than the
/// nearest-neighbour one: the polish must bring it back below).
#[test]
fn short_schedule_keeps_every_rule() {
    let short = Effort {
        kicks: 200,
        short: true,
    };
    let mut rng = Rng(0x5eed_5407);
    for seed in 0..30 {
        let n = 1 + (seed * 11) % 120;
        let sites = random_forest(&mut rng, n);
        let origin = Point::new(rng.unit() * 100.0, -rng.unit() * 100.0);
        let t = order_with(&sites, origin, Some(short));
        check(&sites, origin, &t);
    }
    let mut plates = Vec::new();
    for i in 0..400 {
        let (x, y) = ((i % 40) as f64 * 110.0, (i / 40) as f64 * 70.0);
        let corners = [(0.0, 0.0), (100.0, 0.0), (100.0, 60.0), (0.0, 60.0)];
        plates.push(Site {
            candidates: corners
                .iter()
                .map(|&(a, b)| Point::new(x + a, y + b))
                .collect(),
            parent: None,
        });
        plates.push(Site {
            candidates: vec![
                Point::new(x + 35.0, y + 30.0),
                Point::new(x + 15.0, y + 30.0),
            ],
            parent: Some(plates.len() - 1),
        });
    }
    let t = order_with(&plates, Point::default(), Some(short));
    check(&plates, Point::default(), &t);
    let full = order(&plates, Point::default());
    assert!(
        t.length < 0.9 * t.nn_length && t.length < 1.05 * full.length,
        "short {} full {} nn {}",
        t.length,
        full.length,
        t.nn_length
    );
}

#[test]
fn larger_nest_improves_on_nearest_neighbour() {
    let mut rng = Rng(99);
    let sites = random_forest(&mut rng, 1500);
    let t = order(&sites, Point::default());
    check(&sites, Point::default(), &t);
    assert!(
        t.length < 0.95 * t.nn_length,
        "{} vs {}",
        t.length,
        t.nn_length
    );
}

#[test]
fn empty_single_and_unvisitable() {
    let t = order(&[], Point::default());
    assert!(t.visits.is_empty() && t.length == 0.0 && t.nn_length == 0.0);
    let one = [Site {
        candidates: vec![Point::new(3.0, 4.0), Point::new(30.0, 40.0)],
        parent: None,
    }];
    let t = order(&one, Point::default());
    assert_eq!(t.visits, vec![(0, 0)]);
    assert!((t.length - 5.0).abs() < 1e-12);
    // A vanished hole (no candidates) between an island and the outer.
    let sites = [
        Site {
            candidates: vec![Point::new(0.0, 100.0)],
            parent: None,
        },
        Site {
            candidates: vec![],
            parent: Some(0),
        },
        Site {
            candidates: vec![Point::new(f64::NAN, 1.0), Point::new(1.0, 200.0)],
            parent: Some(1),
        },
    ];
    let t = order(&sites, Point::default());
    check(&sites, Point::default(), &t);
    assert_eq!(t.visits, vec![(2, 1), (0, 0)]);
}

#[test]
fn bad_parents_do_not_panic() {
    let p = |x: f64| vec![Point::new(x, 0.0)];
    let sites = vec![
        Site {
            candidates: p(1.0),
            parent: Some(1),
        },
        Site {
            candidates: p(2.0),
            parent: Some(2),
        },
        Site {
            candidates: p(3.0),
            parent: Some(0),
        }, // cycle 0 → 1 → 2 → 0
        Site {
            candidates: p(4.0),
            parent: Some(3),
        }, // itself
        Site {
            candidates: p(5.0),
            parent: Some(99),
        }, // out of range
    ];
    let t = order(&sites, Point::new(f64::INFINITY, 0.0));
    assert_eq!(t.visits.len(), 5);
    let mut seen: Vec<usize> = t.visits.iter().map(|v| v.0).collect();
    seen.sort_unstable();
    assert_eq!(seen, vec![0, 1, 2, 3, 4]);
}

#[test]
fn coincident_points_cost_nothing() {
    let sites: Vec<Site> = (0..50)
        .map(|i| Site {
            candidates: vec![Point::new(7.0, 7.0); 3],
            parent: (i % 5 != 0).then(|| i - i % 5),
        })
        .collect();
    let t = order(&sites, Point::new(7.0, 7.0));
    check(&sites, Point::new(7.0, 7.0), &t);
    assert_eq!(t.length, 0.0);
}

#[test]
fn points_on_a_line_in_any_order() {
    let mut rng = Rng(5);
    let mut xs: Vec<f64> = (1..=40).map(f64::from).collect();
    for i in (1..xs.len()).rev() {
        xs.swap(i, rng.below(i + 1));
    }
    // Each site: its point on the line and a decoy far off it.
    let sites: Vec<Site> = xs
        .iter()
        .map(|&x| Site {
            candidates: vec![Point::new(x, 50.0), Point::new(x, 0.0)],
            parent: None,
        })
        .collect();
    let t = order(&sites, Point::default());
    check(&sites, Point::default(), &t);
    assert!((t.length - 40.0).abs() < 1e-9, "{}", t.length);
}

#[test]
fn points_on_a_circle_from_its_centre() {
    let n = 200;
    let r = 100.0;
    let mut rng = Rng(17);
    let mut ks: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        ks.swap(i, rng.below(i + 1));
    }
    let step = std::f64::consts::TAU / n as f64;
    let sites: Vec<Site> = ks
        .iter()
        .map(|&k| Site {
            candidates: vec![Point::new((k as f64 * step).cos(), (k as f64 * step).sin()).scale(r)],
            parent: None,
        })
        .collect();
    let t = order(&sites, Point::default());
    check(&sites, Point::default(), &t);
    let best = r + (n - 1) as f64 * 2.0 * r * (step / 2.0).sin();
    assert!((t.length - best).abs() < 1e-6, "{} vs {best}", t.length);
}

#[test]
fn holes_come_before_their_part_even_when_far() {
    // One part whose hole is at the far end; the outer's entry is near the origin.
    let sites = [
        Site {
            candidates: vec![Point::new(1.0, 0.0), Point::new(100.0, 0.0)],
            parent: None,
        },
        Site {
            candidates: vec![Point::new(90.0, 0.0)],
            parent: Some(0),
        },
    ];
    let t = order(&sites, Point::default());
    check(&sites, Point::default(), &t);
    assert_eq!(t.visits, vec![(1, 0), (0, 1)]);
    assert!((t.length - 100.0).abs() < 1e-12);
}

/// Above [`LARGE`] sites the tour runs on sites renumbered in sheet order
/// ([`spatial`]) and re-chooses entries by stretches: the visits come back
/// in the caller's numbers, every rule kept.
#[test]
fn sheets_above_large_keep_every_rule() {
    let mut rng = Rng(0x0b16_5ee7);
    let sites = random_forest(&mut rng, LARGE + 2_000);
    let origin = Point::new(-10.0, -10.0);
    let effort = Effort {
        kicks: 500,
        short: true,
    };
    let t = order_with(&sites, origin, Some(effort));
    check(&sites, origin, &t);
    assert!(t.length < 0.9 * t.nn_length, "{} {}", t.length, t.nn_length);
}

/// A big sheet of plates with two holes each (benches/pipeline.rs's
/// nest): its construction with precedence is no longer than the relaxed
/// one, so the search starts from it straight away (no relax and
/// repair); every rule kept, and well below the construction.
#[test]
fn plates_with_two_holes_are_searched_with_precedence_from_the_start() {
    let cols = 85;
    let mut sites = Vec::new();
    for i in 0..7_100 {
        let (x, y) = ((i % cols) as f64 * 110.0, (i / cols) as f64 * 70.0);
        let p = |dx: f64, dy: f64| Point::new(x + dx, y + dy);
        let plate = sites.len() + 2;
        sites.push(Site {
            candidates: vec![p(15.0, 30.0), p(35.0, 30.0)],
            parent: Some(plate),
        });
        sites.push(Site {
            candidates: vec![p(60.0, 20.0), p(80.0, 20.0), p(80.0, 40.0), p(60.0, 40.0)],
            parent: Some(plate),
        });
        sites.push(Site {
            candidates: vec![p(0.0, 0.0), p(100.0, 0.0), p(100.0, 60.0), p(0.0, 60.0)],
            parent: None,
        });
    }
    let origin = Point::default();
    let flat = Sites::of(&sites);
    let inst = Inst::numbered(&flat, spatial::order(&flat));
    assert!(inst.active.len() > LARGE);
    let free = inst.relaxed();
    let g = construct::grid(&inst);
    let len = |(seq, at): (Vec<usize>, Vec<usize>)| {
        let mut here = origin;
        seq.iter()
            .map(|&s| {
                let d = dist(here, inst.pts[s][at[s]]);
                here = inst.pts[s][at[s]];
                d
            })
            .sum::<f64>()
    };
    let with_precedence = len(construct::nearest_neighbour(&inst, origin, g.clone()));
    assert!(with_precedence <= len(construct::nearest_neighbour(&free, origin, g)));
    let t = order(&sites, origin);
    check(&sites, origin, &t);
    assert!((t.nn_length - with_precedence).abs() < 1e-6);
    assert!(
        t.length < 0.95 * t.nn_length,
        "{} {}",
        t.length,
        t.nn_length
    );
}

/// The entries of a stretch re-chosen with the entries around it fixed are
/// the best of every combination (brute force over 4^3), the rest unchanged.
#[test]
fn a_stretch_of_entries_is_chosen_exactly() {
    let mut rng = Rng(0x57e7c4);
    for _ in 0..20 {
        let sites: Vec<Site> = (0..7)
            .map(|_| Site {
                candidates: (0..4)
                    .map(|_| Point::new(rng.unit() * 100.0, rng.unit() * 100.0))
                    .collect(),
                parent: None,
            })
            .collect();
        let inst = Inst::new(&sites);
        let seq: Vec<usize> = (0..7).collect();
        let origin = Point::default();
        let at0: Vec<usize> = (0..7).map(|_| rng.below(4)).collect();
        let mut at = at0.clone();
        let layers = cluster::Layers::default();
        cluster::optimise_stretch(&layers, &mut at, &inst, origin, &seq, (2, 4));
        let len = |at: &[usize]| {
            let v: Vec<(usize, usize)> = seq.iter().map(|&s| (s, at[s])).collect();
            path_length(&sites, origin, &v)
        };
        let mut best = f64::INFINITY;
        for k in 0..64 {
            let mut a = at0.clone();
            (a[2], a[3], a[4]) = (k % 4, k / 4 % 4, k / 16);
            best = best.min(len(&a));
        }
        assert!((len(&at) - best).abs() < 1e-9, "{} {best}", len(&at));
        for s in [0, 1, 5, 6] {
            assert_eq!(at[s], at0[s]);
        }
    }
}
