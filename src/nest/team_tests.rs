//! A team's nest: deterministic with an evaluation budget, the best of its
//! searches when they never exchange, never worse than one search at the
//! first exchange, and a search that pauses or adopts a nest stays valid.

use super::*;
use crate::geom::{Point, Segment};
use crate::nest::{NestSettings, Part, Rotations, Sheets};

fn poly(pts: &[(f64, f64)], at: (f64, f64)) -> Vec<Segment> {
    let c: Vec<Point> = pts
        .iter()
        .map(|&(x, y)| Point::new(x + at.0, y + at.1))
        .collect();
    (0..c.len())
        .map(|i| Segment::line(c[i], c[(i + 1) % c.len()]))
        .collect()
}

fn rect(w: f64, h: f64) -> Vec<Segment> {
    poly(&[(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)], (0.0, 0.0))
}

/// A strip of L-shapes, rectangles and frames whose holes take the small
/// squares (part-in-part), turned by quarters: a first nest, an order
/// search, then the separation.
fn job(evaluations: u64) -> NestJob {
    let part = |name: &str, outer, holes, quantity| Part {
        name: name.into(),
        outer,
        holes,
        quantity,
        rotations: Rotations::Quarter,
        mirror: false,
    };
    let frame_hole = poly(&[(0.0, 0.0), (26.0, 0.0), (26.0, 26.0), (0.0, 26.0)], (7.0, 7.0));
    NestJob {
        parts: vec![
            part("ell", ell(), Vec::new(), 2),
            part("frame", rect(40.0, 40.0), vec![frame_hole], 2),
            part("square", rect(11.0, 11.0), Vec::new(), 3),
        ],
        sheets: Sheets::Strip { height: 70.0 },
        settings: settings(evaluations),
    }
}

fn ell() -> Vec<Segment> {
    poly(
        &[(0.0, 0.0), (40.0, 0.0), (40.0, 12.0), (12.0, 12.0), (12.0, 30.0), (0.0, 30.0)],
        (0.0, 0.0),
    )
}

fn settings(evaluations: u64) -> NestSettings {
    NestSettings {
        spacing: 1.0,
        margin: 0.0,
        tolerance: 0.01,
        time_s: 1e9,
        seed: 5,
        max_evaluations: Some(evaluations),
        budget_s: None,
    }
}

/// Copies of one L-shape held to one turn: no order to search, the budget
/// goes to the separation at once (the exchanges happen there).
fn ells(evaluations: u64) -> NestJob {
    NestJob {
        parts: vec![Part {
            name: "ell".into(),
            outer: ell(),
            holes: Vec::new(),
            quantity: 9,
            rotations: Rotations::None,
            mirror: false,
        }],
        sheets: Sheets::Strip { height: 70.0 },
        settings: settings(evaluations),
    }
}

fn clock() -> f64 {
    0.0
}

fn quiet(_: Progress) -> bool {
    true
}

/// Σ sheets' used length, and the placements.
fn length(n: &Nest) -> f64 {
    n.sheets.iter().map(|s| s.used_length).sum()
}

/// No two copies' outlines closer than the spacing allows, every one in
/// the strip: checked on the outlines' corners and edges, apart from the
/// engine's collision code.
fn valid(job: &NestJob, n: &Nest) {
    use crate::geom::transform_segments;
    let copies: Vec<Vec<Point>> = n
        .placements
        .iter()
        .map(|p| {
            let mut segs = Vec::new();
            transform_segments(&job.parts[p.part].outer, &p.affine(), 0.01, &mut segs);
            segs.iter().map(|s| s.a).collect()
        })
        .collect();
    let inside = |q: Point, poly: &[Point]| {
        let mut c = false;
        for i in 0..poly.len() {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x) {
                c = !c;
            }
        }
        c
    };
    for (i, a) in copies.iter().enumerate() {
        for q in a {
            assert!(q.y >= -1e-6 && q.y <= 70.0 + 1e-6 && q.x >= -1e-6, "{q:?} off the strip");
        }
        for (j, b) in copies.iter().enumerate() {
            if i == j || n.placements[i].in_hole_of.is_some() || n.placements[j].in_hole_of.is_some() {
                continue;
            }
            // A corner of one strictly inside the other: they overlap.
            let centre = |p: &[Point]| {
                let k = p.len() as f64;
                Point::new(p.iter().map(|q| q.x).sum::<f64>() / k, p.iter().map(|q| q.y).sum::<f64>() / k)
            };
            for q in a.iter().map(|&q| {
                let c = centre(a);
                // Pulled in by a hair: a shared edge is no overlap.
                Point::new(q.x + (c.x - q.x) * 1e-6, q.y + (c.y - q.y) * 1e-6)
            }) {
                assert!(!inside(q, b), "copy {i} has a corner inside copy {j}");
            }
        }
    }
    assert_eq!(n.placements.len(), job.parts.iter().map(|p| p.quantity).sum::<usize>());
}

#[test]
fn a_team_with_an_evaluation_budget_gives_the_same_nest_twice() {
    let job = ells(3000);
    let a = nest_team_every(&job, 2, 500, &clock, &mut quiet).unwrap();
    let b = nest_team_every(&job, 2, 500, &clock, &mut quiet).unwrap();
    assert_eq!(a.placements, b.placements);
    assert_eq!(a.evaluations, b.evaluations);
    assert_eq!(a.evaluations, 6000, "each search spends its budget");
    valid(&job, &a);
    // Three searches make another nest from the same seed, as valid.
    let c = nest_team_every(&job, 3, 500, &clock, &mut quiet).unwrap();
    valid(&job, &c);
}

#[test]
fn a_team_that_never_exchanges_gives_the_best_of_its_searches() {
    let job = ells(2500);
    let team = nest_team_every(&job, 2, u64::MAX, &clock, &mut quiet).unwrap();
    let single = |k: usize| {
        let mut j = job.clone();
        j.settings.seed = seed_of(job.settings.seed, k);
        crate::nest::nest(&j, &clock, &mut quiet).unwrap()
    };
    let (s0, s1) = (single(0), single(1));
    assert_eq!(s0.placements, crate::nest::nest(&job, &clock, &mut quiet).unwrap().placements);
    let eps = job.settings.touch();
    let want = if length(&s1) < length(&s0) - eps { &s1 } else { &s0 };
    assert_eq!(team.placements, want.placements);
    assert_ne!(s0.placements, s1.placements, "the two seeds search differently");
}

#[test]
fn a_team_is_never_worse_than_one_search_at_the_first_exchange() {
    let every = 600;
    let budget = 4000;
    let team = nest_team_every(&ells(budget), 2, every, &clock, &mut quiet).unwrap();
    valid(&ells(budget), &team);
    // Each search pauses at its first chance from `every` on; both then
    // hold the better of the two, and the team's best only improves.
    for k in 0..2 {
        let mut j = ells(budget);
        j.settings.seed = seed_of(j.settings.seed, k);
        let mut s = Search::new(&j, j.settings.seed).unwrap();
        s.run(Some(every), &clock, &mut quiet);
        let at_exchange = s.finish();
        assert!(length(&team) <= length(&at_exchange) + 1e-9, "search {k}");
    }
}

#[test]
fn a_search_paused_and_resumed_is_the_same_run() {
    // Paused in the order search (job) and in the separation (ells).
    for job in [job(300), ells(3000)] {
        paused_and_resumed(&job);
    }
}

fn paused_and_resumed(job: &NestJob) {
    let whole = crate::nest::nest(job, &clock, &mut quiet).unwrap();
    let mut s = Search::new(job, job.settings.seed).unwrap();
    let mut until = 0;
    loop {
        until += 37;
        if !s.run(Some(until), &clock, &mut quiet) {
            break;
        }
    }
    let sliced = s.finish();
    assert_eq!(sliced.placements, whole.placements);
    assert_eq!(sliced.evaluations, whole.evaluations);
}

#[test]
fn an_adopted_nest_is_the_same_nest_and_a_bad_one_is_refused() {
    let long = job(400);
    let mut a = Search::new(&long, 1).unwrap();
    a.run(None, &clock, &mut quiet);
    let best = a.best().unwrap();
    // A search still at its first nest takes it whole, holes and all.
    let short = job(6);
    let mut b = Search::new(&short, 2).unwrap();
    b.run(None, &clock, &mut quiet);
    assert!(b.adopt(&best));
    assert_eq!(b.best().unwrap(), best);
    let nb = b.finish();
    assert_eq!(nb.placements, a.finish().placements);
    assert!(nb.placements.iter().any(|p| p.in_hole_of.is_some()));
    // Not better: kept out. Naming a part that does not exist: refused.
    let mut c = Search::new(&long, 3).unwrap();
    c.run(None, &clock, &mut quiet);
    let mut worse = c.best().unwrap();
    worse.length += 1.0;
    assert!(!c.adopt(&worse));
    let mut bad = best.clone();
    bad.length = -1.0;
    bad.copies[0] = 99.0;
    assert!(!c.adopt(&bad));
}

#[test]
fn a_search_in_the_separation_takes_a_better_nest_and_goes_on_from_it() {
    let mut a = Search::new(&ells(2500), 1).unwrap();
    a.run(None, &clock, &mut quiet);
    let best = a.best().unwrap();
    let mut b = Search::new(&ells(3000), 2).unwrap();
    assert!(b.run(Some(100), &clock, &mut quiet), "paused in the separation");
    assert!(best.better_than(&b.best().unwrap(), 1e-5));
    assert!(b.adopt(&best));
    assert_eq!(b.best().unwrap(), best);
    b.run(None, &clock, &mut quiet);
    let after = b.best().unwrap();
    assert!(!best.better_than(&after, 1e-5), "never worse than what it took");
    valid(&ells(3000), &b.finish());
}
