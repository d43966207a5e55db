//! The first nest honours the budget and Stop (issue 16): a 200-copy
//! sheet's first nest takes seconds, and neither the time budget nor the
//! page's Stop waited for it. Now it counts one evaluation per copy and
//! asks the budget, the clock and the progress callback between copies;
//! cut short, it is the nest of the copies placed so far — valid (checked
//! by sampling, `common::sampled`, not by the engine's collision code) —
//! and the copies never reached are reported with the reason. Every cut
//! is on evaluation counts or a clock that the test drives, never on
//! wall time.

use crate::common;

use common::sampled::{bounds, nest_faults, Copy};
use common::shared;
use kerfcam::contour;
use kerfcam::dxf::{self, ReadOptions};
use kerfcam::geom::Tolerance;
use kerfcam::nest::{self, output, Nest, NestJob, NestSettings, Part, Sheets};

/// 60 copies of two corpus parts on 1000 × 500 sheets.
fn corpus_job(max_evaluations: Option<u64>, time_s: f64) -> NestJob {
    let mut parts: Vec<Part> = Vec::new();
    for (file, qty) in [("cadquery/1001.dxf", 20), ("cadquery/vslot-2020_1.dxf", 40)] {
        let bytes = std::fs::read(shared().join("corpus").join(file)).unwrap();
        let d = dxf::parse(&bytes, &ReadOptions::DEFAULT).unwrap();
        let c = contour::extract(&d, Tolerance::DEFAULT, 0.05);
        let (p, _) = nest::parts_from_contours(&c, file, qty);
        assert!(!p.is_empty(), "{file}");
        parts.extend(p);
    }
    NestJob {
        parts,
        sheets: Sheets::Rect {
            width: 1000.0,
            height: 500.0,
            count: 10,
        },
        settings: NestSettings {
            spacing: 2.5,
            margin: 10.0,
            tolerance: 0.05,
            time_s,
            seed: 1,
            max_evaluations,
            budget_s: None,
        },
    }
}

fn asked(job: &NestJob) -> usize {
    job.parts.iter().map(|p| p.quantity).sum()
}

/// Every copy inside its sheet's margin and the spacing from the others,
/// by sampling; the copies placed and the copies said left out add up.
fn assert_valid(job: &NestJob, n: &Nest) {
    for k in 0..n.sheets.len() {
        let copies: Vec<Copy> = n
            .placements
            .iter()
            .filter(|p| p.sheet == k)
            .map(|p| Copy::new(&output::placed_loops(job, p)))
            .collect();
        for c in &copies {
            let (x0, y0, x1, y1) = bounds(&c.outer);
            assert!(x0 >= 10.0 - 0.01 && y0 >= 10.0 - 0.01, "{x0} {y0}");
            assert!(x1 <= 990.0 + 0.01 && y1 <= 490.0 + 0.01, "{x1} {y1}");
        }
        let faults = nest_faults(&copies, 2.5, 0.01);
        assert!(faults.is_empty(), "sheet {k}: {faults:?}");
    }
    let left: usize = n.unplaced.iter().map(|u| u.copies).sum();
    assert_eq!(n.placements.len() + left, asked(job));
}

/// Copies left out because the budget or Stop came first.
fn cut_short(n: &Nest) -> usize {
    n.unplaced
        .iter()
        .filter(|u| u.reason.en.contains("before the first nest reached it"))
        .map(|u| u.copies)
        .sum()
}

#[test]
fn an_evaluation_budget_smaller_than_the_copies_cuts_the_first_nest() {
    let job = corpus_job(Some(15), 1e9);
    let n = nest::nest(&job, &|| 0.0, &mut |_| true).unwrap();
    assert_eq!(n.evaluations, 15);
    assert_eq!(n.placements.len(), 15);
    assert_eq!(cut_short(&n), asked(&job) - 15);
    assert_valid(&job, &n);
}

#[test]
fn stop_during_the_first_nest_returns_it_so_far_and_the_replay_is_the_same() {
    let job = corpus_job(None, 1e9);
    let mut heard = Vec::new();
    let stopped = nest::nest(&job, &|| 0.0, &mut |p| {
        heard.push((p.evaluations, p.best.len(), p.unplaced));
        p.evaluations < 16
    })
    .unwrap();
    // Reports every 8 copies during the first nest; Stop at the second.
    assert_eq!(
        heard,
        vec![(8, 8, asked(&job) - 8), (16, 16, asked(&job) - 16)]
    );
    assert_eq!(stopped.evaluations, 16);
    assert_eq!(stopped.placements.len(), 16);
    assert_eq!(cut_short(&stopped), asked(&job) - 16);
    assert_valid(&job, &stopped);
    // The page without a shared flag replays to the count it showed.
    let replay = nest::nest(&corpus_job(Some(16), 1e9), &|| 0.0, &mut |_| true).unwrap();
    assert_eq!(replay.placements, stopped.placements);
}

#[test]
fn the_time_budget_holds_during_the_first_nest() {
    // A clock the test drives: every reading 0.1 s later, a budget of 2 s.
    let t = std::cell::Cell::new(0.0);
    let clock = || {
        t.set(t.get() + 0.1);
        t.get()
    };
    let job = corpus_job(None, 2.0);
    let n = nest::nest(&job, &clock, &mut |_| true).unwrap();
    assert!(
        n.placements.len() < asked(&job) / 2,
        "{}",
        n.placements.len()
    );
    assert!(!n.placements.is_empty());
    assert_eq!(cut_short(&n), asked(&job) - n.placements.len());
    assert_valid(&job, &n);
    // Time 0 asks for the first nest whole, and nothing more.
    let whole = nest::nest(&corpus_job(None, 0.0), &clock, &mut |_| true).unwrap();
    assert_eq!(cut_short(&whole), 0);
    assert_eq!(whole.evaluations as usize, asked(&job));
}
